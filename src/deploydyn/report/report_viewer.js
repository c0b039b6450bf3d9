// The run report's viewer (src/deploydyn/report/run_report.hpp): reads the JSON block
// #deploydyn-data and fills the page: summary, 3D deployment (three.js), plots, envelope table
// for a time history; the frequency table and the modes animated for a modal folder
// (report/modal_view.hpp); the path, its eigenvalues and the structure at its points for a
// continuation (report/path_view.hpp).
// window.deploydynReport exposes the state the browser test drives (python/tests/test_report.py).
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('deploydyn-data').textContent);
  const report = { ready: false, frame: 0, framesDrawn: 0 };
  window.deploydynReport = report;

  // base64 → typed array; by table, as atob on tens of MB is slow.
  const digits = new Uint8Array(128);
  'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/'.split('').forEach((c, i) => { digits[c.charCodeAt(0)] = i; });
  function decode(base64, Type) {
    let n = base64.length;
    while (n > 0 && base64[n - 1] === '=') --n;
    const bytes = new Uint8Array(Math.floor(n * 3 / 4));
    let j = 0;
    for (let i = 0; i < n; i += 4) {
      const a = digits[base64.charCodeAt(i)], b = digits[base64.charCodeAt(i + 1)];
      const c = i + 2 < n ? digits[base64.charCodeAt(i + 2)] : 0, d = i + 3 < n ? digits[base64.charCodeAt(i + 3)] : 0;
      const v = (a << 18) | (b << 12) | (c << 6) | d;
      bytes[j++] = v >> 16;
      if (j < bytes.length) bytes[j++] = (v >> 8) & 255;
      if (j < bytes.length) bytes[j++] = v & 255;
    }
    return new Type(bytes.buffer);
  }
  function formatNumber(v) {
    if (v === null || v === undefined || Number.isNaN(v)) return '';
    const a = Math.abs(v);
    return a !== 0 && (a >= 1e5 || a < 1e-3) ? v.toExponential(4) : v.toPrecision(6).replace(/\.?0+$/, '');
  }
  function text(id, value) { document.getElementById(id).textContent = value; }

  // --- Summary -------------------------------------------------------------------------------
  function showSummary() {
    const s = data.summary;
    text('title', data.title);
    const message = s.message || '';
    text('status', message.startsWith(s.status) ? message : `${s.status || ''}: ${message}`);
    document.title = `${data.title} — deploydyn report`;
    const rows = [['folder', data.folder]];
    if (s.analysis && s.analysis.type === 'modal') {
      const a = s.analysis;
      rows.push(['analysis', `modal, ${a.modes} modes at t = ${(a.at || []).map(formatNumber).join(', ')} s`]);
    } else if (s.analysis && s.analysis.type === 'continuation') {
      const a = s.analysis;
      rows.push(['analysis', `continuation in ${a.parameter}, μ from ${formatNumber(a.start)} to ${formatNumber(a.end)}`]);
      if (s.path) {
        rows.push(['path', `${s.path.points} points, ended: ${s.path.end}${s.path.end_event ? ' (' + s.path.end_event + ')' : ''}, ${s.path.iterations} iterations, ${s.path.rejected_steps} rejected steps`]);
      }
      for (const e of (s.events || []).slice(0, 20)) rows.push([`event ${e.kind}`, e.description || `μ = ${formatNumber(e.mu)}`]);
    } else if (s.analysis) {
      const a = s.analysis;
      const integrator = a.integrator ? `${a.integrator.type}${a.integrator.rho_inf !== undefined ? ', ρ∞ = ' + a.integrator.rho_inf : ''}` : '';
      rows.push(['analysis', `${a.type}, to ${a.end} s, step ${a.step} s${integrator ? ', ' + integrator : ''}`]);
    }
    if (s.end) rows.push(['end', `${s.end.reason} at t = ${formatNumber(s.end.time_s)} s`]);
    if (s.failure) {  // a path's or a modal run's failure has no time
      rows.push(['failure', `${s.failure.phase}${s.failure.time !== undefined ? ' at t = ' + s.failure.time : ''}: ${s.failure.reason}`]);
    }
    if (s.steps !== undefined) rows.push(['steps', `${s.steps} (${s.newton_iterations} Newton iterations, ${s.rejected_steps} rejected), ${formatNumber(s.wall_time)} s`]);
    rows.push(['model', `${data.nodes} nodes, ${data.members.names.length} members drawn`]);
    const drivers = Object.entries(s.drivers || {}).sort((a, b) => b[1].peak - a[1].peak);
    for (const [name, d] of drivers.slice(0, 4)) {
      rows.push([`driver ${name}`, `peak ${d.quantity} ${formatNumber(d.peak)} ${d.unit} at t = ${formatNumber(d.t_peak)} s`]);
    }
    if (drivers.length > 4) rows.push(['', `… and ${drivers.length - 4} more drivers of smaller peaks (table below)`]);
    if (s.event_counts && Object.keys(s.event_counts).length) {
      rows.push(['events', Object.entries(s.event_counts).map(([k, n]) => `${k} ×${n}`).join(', ')]);
    }
    if (s.output && s.output.note) rows.push(['history', s.output.note]);
    for (const w of s.warnings || []) rows.push(['warning', w]);
    if (data.notes.history) rows.push(['note', data.notes.history]);
    const grid = document.getElementById('summary');
    for (const [key, value] of rows) {
      const k = document.createElement('div'); k.textContent = key;
      const v = document.createElement('div'); v.textContent = value;
      if (key === 'warning' || key === 'failure') v.className = 'warning';
      grid.append(k, v);
    }
  }

  // --- 3D deployment -------------------------------------------------------------------------
  // Colour scales (report/member_colourings.hpp); grey for a member without a value.
  const colourScales = {
    diverging(v, c, out, at) {  // blue (low) – grey (0) – red (high)
      const s = Math.max(-1, Math.min(1, v / c.high));
      const grey = [0.73, 0.73, 0.73], blue = [0.13, 0.4, 0.67], red = [0.7, 0.09, 0.17];
      const end = s < 0 ? blue : red, w = Math.abs(s);
      for (let k = 0; k < 3; ++k) out[at + k] = grey[k] + w * (end[k] - grey[k]);
    },
    sequential(v, c, out, at) {  // blue (low) – yellow – red (high)
      const s = c.high > c.low ? Math.max(0, Math.min(1, (v - c.low) / (c.high - c.low))) : 0.5;
      const stops = [[0.19, 0.21, 0.58], [0.99, 0.75, 0.3], [0.7, 0.09, 0.17]];
      const [a, b, w] = s < 0.5 ? [stops[0], stops[1], 2 * s] : [stops[1], stops[2], 2 * s - 1];
      for (let k = 0; k < 3; ++k) out[at + k] = a[k] + w * (b[k] - a[k]);
    },
    utilization(v, c, out, at) {  // light grey (0) – orange (1, at capacity); red beyond
      if (v > 1) { out[at] = 0.75; out[at + 1] = 0.0; out[at + 2] = 0.0; return; }
      const light = [0.85, 0.85, 0.85], orange = [0.95, 0.55, 0.1], w = Math.max(0, v);
      for (let k = 0; k < 3; ++k) out[at + k] = light[k] + w * (orange[k] - light[k]);
    },
  };
  const legendGradients = {
    diverging: 'linear-gradient(to right, #2166ac, #bbbbbb, #b2182b)',
    sequential: 'linear-gradient(to right, #30358f, #fcbf4d, #b2182b)',
    utilization: 'linear-gradient(to right, #d9d9d9, #f28c1a 85%, #bf0000 85%)',
  };

  // What the 3D view draws, frame by frame: count, initial() (where the deformation scale starts
  // from), at(k) (node positions, x y z per node), label(k), extent (arrays the camera frames),
  // colourings, the first frame shown.
  // A run's or a path's rows: the positions the history or path.csv holds at the chosen rows.
  function rowFrames(anim) {
    const initial = decode(anim.initial, Float32Array), positions = decode(anim.positions, Float32Array);
    const n = initial.length;
    const name = anim.abscissa || 't', unit = anim.unit === undefined ? 's' : anim.unit;
    return {
      count: anim.times.length, times: anim.times, rows: anim.rows, initial: () => initial,
      at: (k) => positions.subarray(k * n, (k + 1) * n),
      label: (k) => `${name} = ${formatNumber(anim.times[k])}${unit ? ' ' + unit : ''}`,
      extent: [positions], colourings: anim.colourings, note: anim.note, first: anim.times.length - 1,
    };
  }
  // A modal folder's chosen mode through one cycle: x_eq + sin(2πk/n) · move.
  const kModePhases = 24;
  function modeFrames(modal) {
    const shapes = modal.shapes.map((s) => s && { equilibrium: decode(s.equilibrium, Float32Array), move: decode(s.move, Float32Array) });
    const n = 3 * data.nodes, out = new Float32Array(n);
    const column = (name) => modal.columns.indexOf(name);
    const extent = [];
    for (const shape of shapes.filter(Boolean)) {
      for (const sign of [-1, 1]) extent.push(shape.equilibrium.map((x, i) => x + sign * shape.move[i]));
    }
    const frames = {
      count: kModePhases, row: shapes.findIndex(Boolean), shapes, extent, colourings: [], note: '',
      first: kModePhases / 4,  // the largest move
      initial: () => shapes[frames.row].equilibrium,
      at(k) {
        const shape = shapes[frames.row], w = Math.sin(2 * Math.PI * k / kModePhases);
        for (let i = 0; i < n; ++i) out[i] = shape.equilibrium[i] + w * shape.move[i];
        return out;
      },
      label() {
        const r = modal.rows[frames.row], f = r[column('frequency')];
        return `mode ${r[column('mode')]} at t = ${formatNumber(r[column('t')])} s: ` +
          (f === null ? `unstable, ω² = ${formatNumber(r[column('omega2')])} rad²/s²` : `f = ${formatNumber(f)} Hz`);
      },
    };
    return frames;
  }

  function showDeployment(frames) {
    const nNodes = data.nodes;
    const members = decode(data.members.nodes, Int32Array);
    const nMembers = members.length / 2;
    const nFrames = frames.count;
    const colourings = frames.colourings.map((c) => ({ ...c, data: decode(c.values, Float32Array) }));
    // With capacities to check against, members are coloured by utilization first.
    let colouring = colourings[0] || null;
    function showLegend() {
      const c = colouring;
      document.getElementById('legend').hidden = !c;
      if (!c) return;
      text('legend-title', c.label);
      document.getElementById('legend-bar').style.background = legendGradients[c.scale];
      const ends = c.scale === 'utilization' ? ['0', '1', '> 1']
        : c.scale === 'diverging' ? [formatNumber(c.low), '0', `+${formatNumber(c.high)}`]
          : [formatNumber(c.low), '', formatNumber(c.high)];
      text('legend-min', ends[0]);
      text('legend-mid', ends[1]);
      text('legend-max', ends[2]);
      text('legend-note', c.scale === 'utilization' ? `${c.note}; largest ${formatNumber(c.largest)}` : c.note);
    }
    showLegend();
    text('animation-note', frames.note || data.notes.animation || '');

    const canvas = document.getElementById('view');
    // Anti-aliased lines cost several samples a pixel: worth it for a few members, not for 10⁵.
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: nMembers <= 5000, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff, 1);
    const scene = new THREE.Scene();
    const geometry = new THREE.BufferGeometry();
    const vertex = new Float32Array(nMembers * 6);
    const colour = new Float32Array(nMembers * 6);
    geometry.setAttribute('position', new THREE.BufferAttribute(vertex, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colour, 3));
    const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
    lines.frustumCulled = false;
    scene.add(lines);

    // The camera frames every node over every frame.
    const box = new THREE.Box3();
    for (const positions of frames.extent) {
      for (let i = 0; i < positions.length; i += 3) box.expandByPoint(new THREE.Vector3(positions[i], positions[i + 1], positions[i + 2]));
    }
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-6);
    const camera = new THREE.PerspectiveCamera(35, 1, size / 1000, size * 100);
    const controls = new THREE.OrbitControls(camera, canvas);
    function resetView() {
      const direction = data.dimension === 2 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(1, -1.4, 0.9).normalize();
      camera.up.set(0, data.dimension === 2 ? 1 : 0, data.dimension === 2 ? 0 : 1);
      camera.position.copy(centre).addScaledVector(direction, 1.6 * size);
      controls.target.copy(centre);
      controls.update();
    }
    resetView();

    let scale = 1;
    function setFrame(k) {
      k = Math.max(0, Math.min(nFrames - 1, k | 0));
      const initial = frames.initial(), positions = frames.at(k);
      for (let m = 0; m < nMembers; ++m) {
        for (let end = 0; end < 2; ++end) {
          const node = members[2 * m + end];
          for (let axis = 0; axis < 3; ++axis) {
            const x0 = initial[3 * node + axis];
            vertex[6 * m + 3 * end + axis] = x0 + scale * (positions[3 * node + axis] - x0);
          }
        }
        const v = colouring ? colouring.data[k * nMembers + m] : NaN;
        if (Number.isFinite(v)) colourScales[colouring.scale](v, colouring, colour, 6 * m);
        else colour[6 * m] = colour[6 * m + 1] = colour[6 * m + 2] = 0.6;
        colour.copyWithin(6 * m + 3, 6 * m, 6 * m + 3);
      }
      geometry.attributes.position.needsUpdate = true;
      geometry.attributes.color.needsUpdate = true;
      report.frame = k;
      document.getElementById('frame').value = k;
      text('time', `${frames.label(k)} (frame ${k + 1} of ${nFrames})`);
      render();
      if (report.onFrame) report.onFrame(k);
    }
    function render() {
      const w = canvas.clientWidth, h = canvas.clientHeight;
      if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
        renderer.setSize(w, h, false);
        camera.aspect = w / Math.max(h, 1);
        camera.updateProjectionMatrix();
      }
      renderer.render(scene, camera);
      report.framesDrawn += 1;
    }
    controls.addEventListener('change', render);
    window.addEventListener('resize', render);
    const slider = document.getElementById('frame');
    slider.max = nFrames - 1;
    slider.addEventListener('input', () => setFrame(+slider.value));
    document.getElementById('scale').addEventListener('change', (e) => {
      scale = Math.max(0, +e.target.value || 0);
      setFrame(report.frame);
    });
    document.getElementById('reset-view').addEventListener('click', () => { resetView(); render(); });
    const colourSelect = document.getElementById('colour-by');
    for (const c of colourings) {
      const option = document.createElement('option');
      option.value = c.name;
      option.textContent = c.label;
      colourSelect.append(option);
    }
    document.getElementById('colour-by-label').hidden = colourings.length < 2;
    report.colourings = colourings.map((c) => c.name);
    report.colourBy = (name) => {
      colouring = colourings.find((c) => c.name === name) || colouring;
      colourSelect.value = colouring ? colouring.name : '';
      showLegend();
      setFrame(report.frame);
    };
    colourSelect.addEventListener('change', (e) => report.colourBy(e.target.value));
    let playing = false, last = 0;
    const play = document.getElementById('play');
    function tick(now) {
      if (!playing) return;
      if (now - last > 50) { last = now; setFrame(report.frame + 1 >= nFrames ? 0 : report.frame + 1); }
      requestAnimationFrame(tick);
    }
    play.addEventListener('click', () => {
      playing = !playing;
      play.textContent = playing ? '❚❚ pause' : '▶ play';
      if (playing) requestAnimationFrame(tick);
    });
    report.setFrame = setFrame;
    // Where each member's midpoint is drawn, in canvas pixels (x right, y down): the browser
    // test looks for the member's colour there.
    report.memberMidpoints = () => {
      const out = [], w = canvas.width, h = canvas.height, p = new THREE.Vector3();
      for (let m = 0; m < nMembers; ++m) {
        p.set((vertex[6 * m] + vertex[6 * m + 3]) / 2, (vertex[6 * m + 1] + vertex[6 * m + 4]) / 2,
              (vertex[6 * m + 2] + vertex[6 * m + 5]) / 2).project(camera);
        out.push([(p.x + 1) / 2 * w, (1 - p.y) / 2 * h]);
      }
      return out;
    };
    report.frameCount = nFrames;
    report.times = frames.times;
    report.frameRows = frames.rows;
    report.setScale = (s) => { scale = s; setFrame(report.frame); };
    setFrame(frames.first);
  }

  // --- Modal folder: the frequency table; a row's mode is animated -----------------------------
  function showModes(frames) {
    const modal = data.modal;
    document.getElementById('modes-section').hidden = false;
    const head = document.querySelector('#modes-table thead'), body = document.querySelector('#modes-table tbody');
    const units = { t: 's', omega2: 'rad²/s²', frequency: 'Hz', dT_C: '°C' };
    const header = document.createElement('tr');
    for (const name of modal.columns) {
      const th = document.createElement('th');
      th.textContent = name === 'dT_C' ? 'ΔT (°C)' : units[name] ? `${name} (${units[name]})` : name;
      header.append(th);
    }
    head.append(header);
    const lines = modal.rows.map((row, r) => {
      const tr = document.createElement('tr');
      for (const v of row) {
        const td = document.createElement('td');
        td.textContent = v === null ? '—' : formatNumber(v);
        td.className = 'numeric';
        tr.append(td);
      }
      if (frames) tr.addEventListener('click', () => report.selectMode(r));
      body.append(tr);
      return tr;
    });
    const column = modal.columns.indexOf('frequency');
    report.frequencies = modal.rows.map((row) => row[column]);
    report.modeRows = modal.rows.length;
    report.selectMode = (r) => {
      if (!frames || !frames.shapes[r]) return false;
      frames.row = r;
      lines.forEach((tr, k) => tr.classList.toggle('chosen', k === r));
      report.modeRow = r;
      report.setFrame(report.frame);
      return true;
    };
    if (frames) report.selectMode(frames.row);
  }

  // --- Continuation folder: the path and its eigenvalues, events marked ----------------------
  // A line plot on `canvas`: series [{x, y, colour, label}], marks [{x, y, symbol}], vertical
  // lines at `verticals`, a ring at `chosen`. Returns the pixel mapping (CSS pixels).
  function linePlot(canvas, { xLabel, yLabel, series, marks = [], verticals = [], chosen = null, zero = false }) {
    const dpr = window.devicePixelRatio || 1;
    canvas.width = canvas.clientWidth * dpr; canvas.height = canvas.clientHeight * dpr;
    const context = canvas.getContext('2d');
    context.setTransform(dpr, 0, 0, dpr, 0, 0);
    const W = canvas.clientWidth, H = canvas.clientHeight, left = 80, right = 12, top = 12, bottom = 36;
    context.clearRect(0, 0, W, H);
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const s of series) {
      for (let i = 0; i < s.x.length; ++i) {
        if (s.x[i] === null || s.y[i] === null) continue;
        x0 = Math.min(x0, s.x[i]); x1 = Math.max(x1, s.x[i]); y0 = Math.min(y0, s.y[i]); y1 = Math.max(y1, s.y[i]);
      }
    }
    if (zero) { y0 = Math.min(y0, 0); y1 = Math.max(y1, 0); }
    if (!(x1 > x0)) { x0 -= 1; x1 += 1; }
    if (!(y1 > y0)) { y0 -= 1; y1 += 1; }
    const padY = 0.04 * (y1 - y0); y0 -= padY; y1 += padY;
    const px = (v) => left + (v - x0) / (x1 - x0) * (W - left - right);
    const py = (v) => top + (y1 - v) / (y1 - y0) * (H - top - bottom);
    context.strokeStyle = '#999'; context.fillStyle = '#333'; context.font = '11px sans-serif';
    context.strokeRect(left, top, W - left - right, H - top - bottom);
    for (let k = 0; k <= 4; ++k) {
      const v = y0 + (y1 - y0) * k / 4, u = x0 + (x1 - x0) * k / 4;
      context.fillText(formatNumber(v), 18, py(v) + 4);  // right of the rotated y label
      context.fillText(formatNumber(u), px(u) - 12, H - 20);
    }
    context.fillText(xLabel, left + (W - left - right) / 2 - 40, H - 4);
    context.save(); context.translate(12, top + (H - top - bottom) / 2 + 40); context.rotate(-Math.PI / 2);
    context.fillText(yLabel, 0, 0); context.restore();
    if (zero && y0 < 0 && y1 > 0) {
      context.strokeStyle = '#bbb'; context.beginPath(); context.moveTo(left, py(0)); context.lineTo(W - right, py(0)); context.stroke();
    }
    context.setLineDash([3, 3]); context.strokeStyle = '#888';
    for (const v of verticals) { context.beginPath(); context.moveTo(px(v), top); context.lineTo(px(v), H - bottom); context.stroke(); }
    context.setLineDash([]);
    series.forEach((s, n) => {
      context.strokeStyle = s.colour; context.lineWidth = 1.5;
      context.beginPath();
      let started = false;
      for (let i = 0; i < s.x.length; ++i) {
        if (s.x[i] === null || s.y[i] === null) { started = false; continue; }
        if (started) context.lineTo(px(s.x[i]), py(s.y[i])); else { context.moveTo(px(s.x[i]), py(s.y[i])); started = true; }
      }
      context.stroke();
      context.fillStyle = s.colour;
      context.fillText(s.label, W - right - 120, top + 14 + 13 * n);
    });
    context.lineWidth = 1;
    for (const m of marks) {
      const x = px(m.x), y = py(m.y);
      context.fillStyle = '#000'; context.font = '14px sans-serif';
      context.fillText(m.symbol, x - 5, y + 5);
    }
    context.font = '11px sans-serif';
    if (chosen) {
      context.strokeStyle = '#e07000'; context.lineWidth = 2;
      context.beginPath(); context.arc(px(chosen.x), py(chosen.y), 6, 0, 2 * Math.PI); context.stroke();
      context.lineWidth = 1;
    }
    return { px, py };
  }

  function showPath(frames) {
    const path = data.path;
    document.getElementById('path-section').hidden = false;
    const labels = { dT_C: 'ΔT (°C)', load_N: 'load (N)', time_s: 'drivers\' time t (s)' };
    const parameterLabel = labels[path.parameter] || path.parameter;
    const symbols = { limit_point: '◆', bifurcation: '▲', singular_constraints: '✕' };
    const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b'];
    const pathCanvas = document.getElementById('path-plot'), eigenCanvas = document.getElementById('eigen-plot');
    let chosenRow = frames ? frames.rows[report.frame] : null;
    let mapping = null;
    function draw() {
      const marks = path.events.map((e) => ({ x: path.displacement_norm[e.row], y: path.value[e.row], symbol: symbols[e.kind] || '●' }));
      const chosen = chosenRow === null ? null : { x: path.displacement_norm[chosenRow], y: path.value[chosenRow] };
      mapping = linePlot(pathCanvas, {
        xLabel: 'displacement norm ‖q − q₀‖ (m)', yLabel: parameterLabel, marks, chosen,
        series: [{ x: path.displacement_norm, y: path.value, colour: '#1f3a5f', label: 'path' }],
      });
      linePlot(eigenCanvas, {
        xLabel: parameterLabel, yLabel: 'lowest eigenvalues (N/m)', zero: true,
        verticals: path.events.map((e) => path.value[e.row]),
        series: path.eigenvalues.map((v, k) => ({ x: path.value, y: v, colour: palette[k % palette.length], label: `λ${k + 1}` })),
        chosen: chosenRow === null || !path.eigenvalues.length ? null : { x: path.value[chosenRow], y: path.eigenvalues[0][chosenRow] },
      });
      report.pathPoints = path.value.map((v, r) => [mapping.px(path.displacement_norm[r]), mapping.py(v)]);
      report.eventMarks = path.events.map((e) => ({ row: e.row, kind: e.kind, at: report.pathPoints[e.row] }));
      report.pathChosenRow = chosenRow;
    }
    text('path-note', path.has_positions ? '' : 'path.csv holds no node positions: the structure is drawn as model.yaml puts it.');
    if (frames) {
      report.onFrame = (k) => { chosenRow = frames.rows[k]; draw(); };
      // The frame nearest to the clicked point of the path.
      pathCanvas.addEventListener('click', (e) => {
        let best = 0, distance = Infinity;
        frames.rows.forEach((row, k) => {
          const [x, y] = report.pathPoints[row];
          const d = (x - e.offsetX) ** 2 + (y - e.offsetY) ** 2;
          if (d < distance) { distance = d; best = k; }
        });
        report.setFrame(best);
      });
    }
    window.addEventListener('resize', draw);
    report.drawPath = draw;
    draw();
  }

  // --- Time histories ------------------------------------------------------------------------
  function showPlots() {
    const p = data.plots;
    const t = decode(p.t, Float64Array);
    const series = new Map();
    const select = document.getElementById('plot-columns');
    p.columns.forEach((name, k) => {
      const option = document.createElement('option');
      option.value = name; option.textContent = name;
      option.selected = p.defaults.includes(name);
      select.append(option);
      series.set(name, () => decode(p.values[k], Float64Array));
    });
    text('plot-note', data.notes.plots || '');
    const canvas = document.getElementById('plot');
    const context = canvas.getContext('2d');
    const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];
    const cache = new Map();
    let range = [t[0], t[t.length - 1]], drag = null;
    function chosen() { return Array.from(select.selectedOptions).map((o) => o.value); }
    function values(name) { if (!cache.has(name)) cache.set(name, series.get(name)()); return cache.get(name); }
    function draw() {
      const dpr = window.devicePixelRatio || 1;
      canvas.width = canvas.clientWidth * dpr; canvas.height = canvas.clientHeight * dpr;
      context.setTransform(dpr, 0, 0, dpr, 0, 0);
      const W = canvas.clientWidth, H = canvas.clientHeight, left = 70, right = 10, top = 10, bottom = 30;
      context.clearRect(0, 0, W, H);
      const names = chosen();
      let lo = Infinity, hi = -Infinity;
      for (const name of names) {
        const v = values(name);
        for (let i = 0; i < t.length; ++i) if (t[i] >= range[0] && t[i] <= range[1] && Number.isFinite(v[i])) { lo = Math.min(lo, v[i]); hi = Math.max(hi, v[i]); }
      }
      if (!(hi > lo)) { lo -= 1; hi += 1; }
      const x = (s) => left + (s - range[0]) / (range[1] - range[0] || 1) * (W - left - right);
      const y = (v) => top + (hi - v) / (hi - lo) * (H - top - bottom);
      context.strokeStyle = '#999'; context.fillStyle = '#333'; context.font = '11px sans-serif';
      context.strokeRect(left, top, W - left - right, H - top - bottom);
      for (let k = 0; k <= 4; ++k) {
        const v = lo + (hi - lo) * k / 4, s = range[0] + (range[1] - range[0]) * k / 4;
        context.fillText(formatNumber(v), 4, y(v) + 4);
        context.fillText(formatNumber(s), x(s) - 10, H - 12);
      }
      context.fillText('t (s)', W - 40, H - 2);
      names.forEach((name, n) => {
        const v = values(name);
        context.strokeStyle = palette[n % palette.length];
        context.beginPath();
        let started = false;
        for (let i = 0; i < t.length; ++i) {
          if (t[i] < range[0] || t[i] > range[1] || !Number.isFinite(v[i])) continue;
          if (started) context.lineTo(x(t[i]), y(v[i])); else { context.moveTo(x(t[i]), y(v[i])); started = true; }
        }
        context.stroke();
        context.fillStyle = palette[n % palette.length];
        context.fillText(name, left + 8, top + 14 + 13 * n);
      });
      if (drag) { context.fillStyle = 'rgba(31,58,95,0.15)'; context.fillRect(Math.min(drag[0], drag[1]), top, Math.abs(drag[1] - drag[0]), H - top - bottom); }
      report.plotted = names;
      report.plotRange = range.slice();
      report.toTime = (px) => range[0] + (px - left) / (W - left - right) * (range[1] - range[0]);
    }
    select.addEventListener('change', draw);
    canvas.addEventListener('mousedown', (e) => { drag = [e.offsetX, e.offsetX]; });
    canvas.addEventListener('mousemove', (e) => { if (drag) { drag[1] = e.offsetX; draw(); } });
    canvas.addEventListener('mouseup', () => {
      if (drag && Math.abs(drag[1] - drag[0]) > 4) {
        const a = report.toTime(Math.min(...drag)), b = report.toTime(Math.max(...drag));
        range = [a, b];
      }
      drag = null; draw();
    });
    canvas.addEventListener('dblclick', () => { range = [t[0], t[t.length - 1]]; draw(); });
    window.addEventListener('resize', draw);
    report.zoom = (a, b) => { range = [a, b]; draw(); };
    draw();
  }

  // --- Envelope table ------------------------------------------------------------------------
  function showTable() {
    const table = data.table;
    text('table-note', data.notes.table || '');
    const head = document.querySelector('#table thead'), body = document.querySelector('#table tbody');
    const row = document.createElement('tr');
    let sortColumn = -1, descending = true, rows = table.rows.slice();
    table.columns.forEach((name, k) => {
      const th = document.createElement('th');
      th.textContent = name;
      th.addEventListener('click', () => {
        descending = sortColumn === k ? !descending : true;
        sortColumn = k;
        rows.sort((a, b) => (typeof a[k] === 'number' ? (a[k] - b[k]) : String(a[k]).localeCompare(String(b[k]))) * (descending ? -1 : 1));
        fill();
      });
      row.append(th);
    });
    head.append(row);
    const filter = document.getElementById('table-filter');
    const shown = 500;
    function fill() {
      const words = filter.value.toLowerCase().split(/\s+/).filter(Boolean);
      const matching = rows.filter((r) => words.every((w) => (r[0] + ' ' + r[1] + ' ' + r[2]).toLowerCase().includes(w)));
      body.replaceChildren();
      for (const r of matching.slice(0, shown)) {
        const tr = document.createElement('tr');
        r.forEach((v) => {
          const td = document.createElement('td');
          td.textContent = typeof v === 'number' ? formatNumber(v) : v;
          if (typeof v === 'number') td.className = 'numeric';
          tr.append(td);
        });
        body.append(tr);
      }
      text('table-count', `${matching.length} rows${matching.length > shown ? `, the first ${shown} shown` : ''}`);
      report.tableRows = Math.min(matching.length, shown);
    }
    filter.addEventListener('input', fill);
    fill();
  }

  showSummary();
  report.kind = data.kind || 'run';
  if (report.kind === 'run') {
    showTable();
    showPlots();
    showDeployment(rowFrames(data.animation));
  } else {
    document.getElementById('plot-section').hidden = true;
    document.getElementById('table-section').hidden = true;
    if (report.kind === 'modal') {
      const frames = modeFrames(data.modal);
      const drawn = frames.row >= 0;
      text('view-title', 'Mode shapes');
      document.getElementById('view-section').hidden = !drawn;
      if (drawn) showDeployment(frames);
      showModes(drawn ? frames : null);
    } else {
      text('view-title', 'The structure along the path');
      const frames = rowFrames(data.animation);
      showDeployment(frames);
      showPath(frames);
    }
  }
  report.ready = true;
})();

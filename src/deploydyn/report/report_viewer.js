// The run report's viewer (src/deploydyn/report/run_report.hpp): reads the JSON block
// #deploydyn-data and fills the page: summary, 3D deployment (three.js), plots, envelope table.
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
    if (s.analysis) {
      const a = s.analysis;
      const integrator = a.integrator ? `${a.integrator.type}${a.integrator.rho_inf !== undefined ? ', ρ∞ = ' + a.integrator.rho_inf : ''}` : '';
      rows.push(['analysis', `${a.type}, to ${a.end} s, step ${a.step} s${integrator ? ', ' + integrator : ''}`]);
    }
    if (s.end) rows.push(['end', `${s.end.reason} at t = ${formatNumber(s.end.time_s)} s`]);
    if (s.failure) rows.push(['failure', `${s.failure.phase} at t = ${s.failure.time}: ${s.failure.reason}`]);
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

  function showDeployment() {
    const anim = data.animation;
    const nNodes = data.nodes;
    const members = decode(data.members.nodes, Int32Array);
    const nMembers = members.length / 2;
    const initial = decode(anim.initial, Float32Array);
    const positions = decode(anim.positions, Float32Array);
    const nFrames = anim.times.length;
    const colourings = anim.colourings.map((c) => ({ ...c, data: decode(c.values, Float32Array) }));
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
    text('animation-note', anim.note || data.notes.animation || '');

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
    for (let i = 0; i < positions.length; i += 3) box.expandByPoint(new THREE.Vector3(positions[i], positions[i + 1], positions[i + 2]));
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
      const base = k * nNodes * 3;
      for (let m = 0; m < nMembers; ++m) {
        for (let end = 0; end < 2; ++end) {
          const node = members[2 * m + end];
          for (let axis = 0; axis < 3; ++axis) {
            const x0 = initial[3 * node + axis];
            vertex[6 * m + 3 * end + axis] = x0 + scale * (positions[base + 3 * node + axis] - x0);
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
      text('time', `t = ${formatNumber(anim.times[k])} s (frame ${k + 1} of ${nFrames})`);
      render();
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
    report.times = anim.times;
    report.setScale = (s) => { scale = s; setFrame(report.frame); };
    setFrame(nFrames - 1);
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
  showTable();
  showPlots();
  showDeployment();
  report.ready = true;
})();

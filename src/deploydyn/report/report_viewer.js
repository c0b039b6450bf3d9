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

  // --- Plot axes -----------------------------------------------------------------------------
  // Round ticks over [lo, hi]: a step of 1, 2 or 5 × 10^n giving about `target` intervals, and
  // its multiples k·step in the range; `cover` widens the range to the multiples around it, so
  // that the first and last ticks bound the data.
  function niceTicks(lo, hi, { target = 6, cover = false } = {}) {
    if (!Number.isFinite(lo) || !Number.isFinite(hi)) { lo = -1; hi = 1; }  // nothing drawn
    if (!(hi > lo)) { lo -= 1; hi += 1; }
    const raw = (hi - lo) / target;
    const n = Math.floor(Math.log10(raw));
    const mantissa = [1, 2, 5, 10].find((m) => m * 10 ** n >= raw * (1 - 1e-9));
    // k·m·10^n, divided rather than multiplied by a negative power: 3 × 0.1 prints 0.3.
    const at = (k) => (n < 0 ? (k * mantissa) / 10 ** -n : k * mantissa * 10 ** n);
    const step = at(1);
    const first = (cover ? Math.floor : Math.ceil)(lo / step - (cover ? -1e-9 : 1e-9));
    const last = (cover ? Math.ceil : Math.floor)(hi / step + (cover ? -1e-9 : 1e-9));
    const ticks = [];
    for (let k = first; k <= last; ++k) ticks.push(at(k));
    const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
    const largest = Math.max(Math.abs(ticks[0]), Math.abs(ticks[ticks.length - 1]));
    const exponential = largest >= 1e6 || step < 1e-4;
    const format = (v) => {
      if (v === 0) return '0';
      if (!exponential) return v.toFixed(digits);
      return v.toExponential(Math.max(0, Math.floor(Math.log10(largest)) - Math.floor(Math.log10(step) + 1e-9)));
    };
    return { lo: cover ? ticks[0] : lo, hi: cover ? ticks[ticks.length - 1] : hi, step, ticks, labels: ticks.map(format) };
  }
  // The frame, round ticks and labels of a plot; `x` and `y` from niceTicks, `at` their pixel
  // mappings. Recorded in report.plotAxes[canvas id] for the browser tests.
  function drawAxes(context, canvas, { box, x, y, px, py, xLabel, yLabel, xUnit, yUnit }) {
    const [left, top, right, bottom] = box;
    context.strokeStyle = '#999'; context.fillStyle = '#333'; context.font = '11px sans-serif';
    context.strokeRect(left, top, right - left, bottom - top);
    context.textAlign = 'right';
    y.ticks.forEach((v, k) => {
      context.fillText(y.labels[k], left - 5, py(v) + 4);
      context.beginPath(); context.moveTo(left - 3, py(v)); context.lineTo(left, py(v)); context.stroke();
    });
    context.textAlign = 'center';
    x.ticks.forEach((v, k) => {
      context.fillText(x.labels[k], px(v), bottom + 14);
      context.beginPath(); context.moveTo(px(v), bottom); context.lineTo(px(v), bottom + 3); context.stroke();
    });
    context.fillText(xLabel, (left + right) / 2, bottom + 28);
    context.save(); context.translate(12, (top + bottom) / 2); context.rotate(-Math.PI / 2);
    context.fillText(yLabel, 0, 0); context.restore();
    context.textAlign = 'start';
    report.plotAxes = report.plotAxes || {};
    report.plotAxes[canvas.id] = {
      x: { label: xLabel, unit: xUnit, lo: x.lo, hi: x.hi, step: x.step, ticks: x.ticks, labels: x.labels },
      y: { label: yLabel, unit: yUnit, lo: y.lo, hi: y.hi, step: y.step, ticks: y.ticks, labels: y.labels },
    };
  }

  // --- Summary -------------------------------------------------------------------------------
  // A time history's events with their times: summary.json's element events (latches, slack
  // cables, …, at most 200 of them) and the verdict's first failure; listed in the summary and
  // marked on the time plots. A path's events are on its own plots.
  function runEvents() {
    const s = data.summary, out = [];
    if (!s.analysis || s.analysis.type === 'modal' || s.analysis.type === 'continuation') return out;
    for (const e of s.events || []) {
      if (Number.isFinite(e.time_s)) out.push({ t: e.time_s, kind: `${e.type}.${e.what}`, label: `${e.type} ${e.element} ${e.what}` });
    }
    const f = s.verdict && !s.verdict.along ? s.verdict.first_failure : null;
    if (f && Number.isFinite(f.time_s)) {
      out.push({ t: f.time_s, kind: 'failure', label: `first failure: ${f.check}${f.member ? ' of ' + f.member : ''}` });
    }
    return out.sort((a, b) => a.t - b.t);
  }
  const kEventsListed = 12;

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
    const events = runEvents();
    for (const e of events.slice(0, kEventsListed)) rows.push([e.kind === 'failure' ? 'failure' : 'event', `${e.label} at t = ${formatNumber(e.t)} s`]);
    if (events.length > kEventsListed) rows.push(['', `… and ${events.length - kEventsListed} more events, marked on the time plots (summary.json lists them)`]);
    report.events = events;
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

  // --- Verdict -------------------------------------------------------------------------------
  // summary.json's verdict (docs/model-format.md): the outcome, the largest utilization of each
  // check, and the members by utilization with the buckling length factor each was checked with
  // (per axis, K_y and K_z, for a 3D beam member whose axes differ).
  function bucklingFactor(m) {
    if (!m.buckling_length_source) return '';
    const [ky, kz] = m.buckling_length_factors || [];
    const k = (ky !== undefined && ky !== null && kz !== undefined && kz !== null && ky !== kz)
      ? `K_y = ${formatNumber(ky)}, K_z = ${formatNumber(kz)}`
      : m.buckling_length_factor !== null && m.buckling_length_factor !== undefined ? `K = ${formatNumber(m.buckling_length_factor)}` : 'K —';
    return `${k} (${m.buckling_length_source})`;
  }
  function fillTable(id, columns, rows) {
    const head = document.querySelector(`#${id} thead`), body = document.querySelector(`#${id} tbody`);
    const tr = document.createElement('tr');
    for (const c of columns) { const th = document.createElement('th'); th.textContent = c; tr.append(th); }
    head.append(tr);
    for (const row of rows) {
      const line = document.createElement('tr');
      row.forEach((v, k) => {
        const td = document.createElement('td');
        td.textContent = typeof v === 'number' ? formatNumber(v) : (v ?? '');
        if (typeof v === 'number') td.className = 'numeric';
        if (columns[k] === 'utilization' && v > 1) td.classList.add('over');  // beyond capacity
        line.append(td);
      });
      body.append(line);
    }
  }
  function showVerdict() {
    const v = data.summary.verdict;
    report.verdictMembers = [];
    if (!v) return;
    document.getElementById('verdict-section').hidden = false;
    const along = v.along ? `${v.along.quantity}${v.along.unit ? ' (' + v.along.unit + ')' : ''}` : 't (s)';
    const outcome = v.along ? (v.deploys ? 'every check passes' : 'a check fails') : (v.deploys ? 'deploys' : 'does not deploy');
    text('verdict-outcome', `${outcome}: ${v.reason}`);
    document.getElementById('verdict-outcome').classList.toggle('fails', !v.deploys);
    const checks = Object.entries(v.checks || {}).map(([name, c]) => [
      name, c.max_utilization ?? null, c.member || '', c.element || '', c.time_s ?? null, c.checked, c.exceeded]);
    fillTable('verdict-checks', ['check', 'utilization', 'member', 'element', along, 'checked', 'exceeded'], checks);
    const notRun = Object.entries(v.checks_not_run || {}).map(([name, why]) => `${name}: ${why}`);
    text('verdict-checks-note', notRun.length ? `not checked: ${notRun.join('; ')}` : '');
    // summary.json lists the members of highest utilization only (its members_note says so).
    const members = Object.entries(v.members || {}).sort((a, b) => b[1].utilization - a[1].utilization);
    const rows = members.map(([name, m]) => {
      const governing = m[m.governing] || {};
      return [name, m.kind, m.governing, m.utilization, governing.time_s ?? null, bucklingFactor(m)];
    });
    fillTable('verdict-members', ['member', 'kind', 'governing check', 'utilization', along, 'buckling length factor'], rows);
    report.verdictMembers = rows;
    text('verdict-members-note', v.members_note || '');
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

  // Members as screen-space wide lines: one instanced quad a member, its width in pixels from
  // its section's depth (report/member_sections.hpp), one draw call whatever the count. The
  // depth cue darkens a member with its distance from the camera across the model's bounding
  // sphere: near members read in front of far ones (3D only).
  const memberVertexShader = `
    attribute vec3 instanceStart;
    attribute vec3 instanceEnd;
    attribute vec3 instanceColour;
    attribute float instanceWidth;
    uniform vec2 resolution;
    uniform vec2 depthRange;
    uniform float depthCue;
    varying vec3 vColour;
    void main() {
      vec4 a = modelViewMatrix * vec4(instanceStart, 1.0);
      vec4 b = modelViewMatrix * vec4(instanceEnd, 1.0);
      vec4 here = position.x < 0.5 ? a : b;
      float far = clamp((-here.z - depthRange.x) / max(depthRange.y - depthRange.x, 1e-9), 0.0, 1.0);
      vColour = instanceColour * (1.0 - depthCue * far);
      vec4 ca = projectionMatrix * a, cb = projectionMatrix * b;
      vec2 along = (cb.xy / cb.w - ca.xy / ca.w) * resolution;
      along = length(along) > 1e-6 ? normalize(along) : vec2(1.0, 0.0);
      vec2 across = vec2(-along.y, along.x);
      vec4 clip = position.x < 0.5 ? ca : cb;
      // Half the width to each side, and half a width beyond each end so that joints close.
      vec2 offset = across * position.y + along * (position.x < 0.5 ? -0.5 : 0.5);
      clip.xy += offset * instanceWidth * 2.0 / resolution * clip.w;  // NDC spans 2 over the resolution
      gl_Position = clip;
    }`;
  const plainFragmentShader = `
    varying vec3 vColour;
    void main() { gl_FragColor = vec4(vColour, 1.0); }`;
  // Node markers as points: a shape (0 dot, 1 square, 2 triangle, 3 open triangle, 4 ring,
  // 5 open diamond) drawn in the point's square.
  const markerVertexShader = `
    attribute float shape;
    attribute float size;
    attribute vec3 colour;
    uniform float pixelRatio;
    varying float vShape;
    varying vec3 vColour;
    void main() {
      vShape = shape;
      vColour = colour;
      gl_PointSize = size * pixelRatio;
      gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
    }`;
  const markerFragmentShader = `
    varying float vShape;
    varying vec3 vColour;
    bool inTriangle(vec2 p, float inset) {  // apex up; p in [0, 1]², y down
      return p.y <= 0.95 - inset && abs(p.x - 0.5) <= (p.y - 0.05 - 1.2 * inset) * 0.55;
    }
    void main() {
      vec2 p = gl_PointCoord;
      float r = length(p - 0.5);
      float d = abs(p.x - 0.5) + abs(p.y - 0.5);
      int s = int(vShape + 0.5);
      bool inside = s == 0 ? r <= 0.5
        : s == 1 ? true
        : s == 2 ? inTriangle(p, 0.0)
        : s == 3 ? inTriangle(p, 0.0) && !inTriangle(p, 0.16)
        : s == 4 ? r <= 0.5 && r >= 0.3
        : d <= 0.5 && d >= 0.36;
      if (!inside) discard;
      gl_FragColor = vec4(vColour, 1.0);
    }`;
  // Marker kinds: shape, size (CSS px), colour, legend text (report/node_markers.hpp).
  const markerKinds = {
    node: { shape: 0, size: 4, colour: [0.25, 0.25, 0.25], legend: 'node' },
    joint: { shape: 4, size: 9, colour: [0.2, 0.2, 0.2], legend: 'joint' },
    roller: { shape: 3, size: 14, colour: [0.1, 0.55, 0.2], legend: 'roller support (some axes held)' },
    fixed: { shape: 2, size: 14, colour: [0.1, 0.55, 0.2], legend: 'fixed support (pinned)' },
    clamped: { shape: 1, size: 12, colour: [0.1, 0.55, 0.2], legend: 'clamped support (rotation held too)' },
    driver: { shape: 5, size: 20, colour: [0.5, 0.1, 0.6], legend: 'driver' },
  };
  function markerSymbol(kind) {  // the legend's picture of a marker, as SVG
    const k = markerKinds[kind], c = `rgb(${k.colour.map((v) => Math.round(255 * v)).join(',')})`;
    const shapes = [
      `<circle cx="7" cy="7" r="2.5" fill="${c}"/>`, `<rect x="2" y="2" width="10" height="10" fill="${c}"/>`,
      `<polygon points="7,1 13,13 1,13" fill="${c}"/>`, `<polygon points="7,2 12.5,12.5 1.5,12.5" fill="none" stroke="${c}" stroke-width="2"/>`,
      `<circle cx="7" cy="7" r="4.5" fill="none" stroke="${c}" stroke-width="2"/>`,
      `<polygon points="7,1 13,7 7,13 1,7" fill="none" stroke="${c}" stroke-width="1.5"/>`];
    return `<svg width="14" height="14" style="vertical-align:middle">${shapes[k.shape]}</svg>`;
  }
  // The markers drawn: one entry a node (its support, joint or plain dot) and one a driver's node.
  // Above kMaxNodeDots nodes the plain dots are left out: they would only grey the picture.
  const kMaxNodeDots = 5000;
  function nodeMarkers(nNodes) {
    const kindOf = new Array(nNodes).fill('node');
    const markers = data.markers || { supports: [], joints: [], drivers: [] };
    for (const node of markers.joints) kindOf[node] = 'joint';
    for (const [node, kind] of markers.supports) kindOf[node] = kind;
    const entries = kindOf.map((kind, node) => ({ node, kind }))
      .filter((e) => e.kind !== 'node' || nNodes <= kMaxNodeDots);
    for (const [node, name] of markers.drivers) entries.push({ node, kind: 'driver', name });
    return entries;
  }

  // A round length (1, 2 or 5 × 10^k m) of about `target` pixels at `pixelsPerMetre`.
  function roundLength(pixelsPerMetre, target) {
    const raw = target / pixelsPerMetre, power = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / power;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * power;
  }

  // The members' mesh: four corners a member, each with both ends, its colour and width
  // (WebGL1 instancing of one quad was 27 times slower in software rendering at 10⁴ members:
  // docs/report.md, "At scale"). update(ends, colours) takes 6 and 3 values a member.
  function wideMembers(nMembers, width, uniforms) {
    const geometry = new THREE.BufferGeometry();
    const corner = new Float32Array(nMembers * 12), cornerWidth = new Float32Array(nMembers * 4);
    const index = new (nMembers * 4 > 65535 ? Uint32Array : Uint16Array)(nMembers * 6);
    const unitQuad = [0, -0.5, 0, 1, -0.5, 0, 1, 0.5, 0, 0, 0.5, 0];
    for (let m = 0; m < nMembers; ++m) {
      corner.set(unitQuad, 12 * m);
      cornerWidth.fill(width[m], 4 * m, 4 * m + 4);
      index.set([0, 1, 2, 0, 2, 3].map((i) => 4 * m + i), 6 * m);
    }
    const cornerEnds = new Float32Array(nMembers * 24), cornerColour = new Float32Array(nMembers * 12);
    geometry.setAttribute('position', new THREE.BufferAttribute(corner, 3));
    geometry.setIndex(new THREE.BufferAttribute(index, 1));
    const ends = new THREE.InterleavedBuffer(cornerEnds, 6);
    geometry.setAttribute('instanceStart', new THREE.InterleavedBufferAttribute(ends, 3, 0));
    geometry.setAttribute('instanceEnd', new THREE.InterleavedBufferAttribute(ends, 3, 3));
    const colourAttribute = new THREE.BufferAttribute(cornerColour, 3);
    geometry.setAttribute('instanceColour', colourAttribute);
    geometry.setAttribute('instanceWidth', new THREE.BufferAttribute(cornerWidth, 1));
    const object = new THREE.Mesh(geometry, new THREE.ShaderMaterial({
      uniforms, vertexShader: memberVertexShader, fragmentShader: plainFragmentShader, side: THREE.DoubleSide,
    }));
    function update(vertex, colour) {
      for (let m = 0; m < nMembers; ++m) {
        for (let c = 0; c < 4; ++c) {
          for (let i = 0; i < 6; ++i) cornerEnds[24 * m + 6 * c + i] = vertex[6 * m + i];
          for (let i = 0; i < 3; ++i) cornerColour[12 * m + 3 * c + i] = colour[3 * m + i];
        }
      }
      ends.needsUpdate = true;
      colourAttribute.needsUpdate = true;
    }
    return { object, update, wide: true };
  }
  // Above kMaxWideMembers members every band would be 1.5–2 px wide anyway: 1-px lines, at half
  // the vertices, with the same depth cue.
  const kMaxWideMembers = 20000;
  const thinVertexShader = `
    attribute vec3 instanceColour;
    uniform vec2 depthRange;
    uniform float depthCue;
    varying vec3 vColour;
    void main() {
      vec4 here = modelViewMatrix * vec4(position, 1.0);
      float far = clamp((-here.z - depthRange.x) / max(depthRange.y - depthRange.x, 1e-9), 0.0, 1.0);
      vColour = instanceColour * (1.0 - depthCue * far);
      gl_Position = projectionMatrix * here;
    }`;
  function thinMembers(nMembers, uniforms) {
    const geometry = new THREE.BufferGeometry();
    const ends = new Float32Array(nMembers * 6), endColour = new Float32Array(nMembers * 6);
    geometry.setAttribute('position', new THREE.BufferAttribute(ends, 3));
    geometry.setAttribute('instanceColour', new THREE.BufferAttribute(endColour, 3));
    const object = new THREE.LineSegments(geometry, new THREE.ShaderMaterial({
      uniforms, vertexShader: thinVertexShader, fragmentShader: plainFragmentShader,
    }));
    function update(vertex, colour) {
      ends.set(vertex);
      for (let m = 0; m < nMembers; ++m) {
        for (let i = 0; i < 3; ++i) endColour[6 * m + i] = endColour[6 * m + 3 + i] = colour[3 * m + i];
      }
      geometry.attributes.position.needsUpdate = true;
      geometry.attributes.instanceColour.needsUpdate = true;
    }
    return { object, update, wide: false };
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
    const overlay = document.getElementById('view-overlay');
    // Anti-aliasing costs several samples a pixel: worth it for a few members, not for 10⁵.
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: nMembers <= 5000, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff, 1);
    const scene = new THREE.Scene();

    // Members: end points (x y z of both ends, 6 a member, updated each frame), colour, width.
    const vertex = new Float32Array(nMembers * 6);
    const colour = new Float32Array(nMembers * 3);
    const width = new Float32Array(nMembers);
    const depths = data.members.depth_m ? decode(data.members.depth_m, Float32Array) : new Float32Array(nMembers);
    const deepest = depths.reduce((a, b) => Math.max(a, b), 0);
    // The deepest section 6 px wide (less when many members share the canvas), the others in
    // proportion to their depth, 1.5 px at least.
    const widest = Math.max(2, Math.min(6, 6 * Math.sqrt(2000 / Math.max(nMembers, 1))));
    for (let m = 0; m < nMembers; ++m) width[m] = deepest > 0 ? Math.max(1.5, widest * depths[m] / deepest) : 2;
    const memberUniforms = {
      resolution: { value: new THREE.Vector2(1, 1) },
      depthRange: { value: new THREE.Vector2(0, 1) },
      depthCue: { value: data.dimension === 3 ? 0.55 : 0 },  // a 2D model keeps its flat view
    };
    const members3d = nMembers <= kMaxWideMembers ? wideMembers(nMembers, width, memberUniforms)
      : thinMembers(nMembers, memberUniforms);
    const lines = members3d.object;
    lines.frustumCulled = false;
    scene.add(lines);

    // Node markers: a point each, drawn over the members.
    const markers = nodeMarkers(nNodes);
    const markerPosition = new Float32Array(markers.length * 3);
    const markerGeometry = new THREE.BufferGeometry();
    markerGeometry.setAttribute('position', new THREE.BufferAttribute(markerPosition, 3));
    markerGeometry.setAttribute('shape', new THREE.Float32BufferAttribute(markers.map((e) => markerKinds[e.kind].shape), 1));
    // Smaller when many: half size at 8000 markers, 0.3 at 22 000 and beyond.
    const markerScale = Math.max(0.3, Math.min(1, Math.sqrt(2000 / Math.max(markers.length, 1))));
    markerGeometry.setAttribute('size', new THREE.Float32BufferAttribute(markers.map((e) => markerScale * markerKinds[e.kind].size), 1));
    markerGeometry.setAttribute('colour', new THREE.Float32BufferAttribute(markers.flatMap((e) => markerKinds[e.kind].colour), 3));
    const markerUniforms = { pixelRatio: { value: renderer.getPixelRatio() } };
    const points = new THREE.Points(markerGeometry, new THREE.ShaderMaterial({
      uniforms: markerUniforms, vertexShader: markerVertexShader, fragmentShader: markerFragmentShader, depthTest: false,
    }));
    points.frustumCulled = false;
    points.renderOrder = 1;
    scene.add(points);
    const present = new Set(markers.map((e) => e.kind));
    document.getElementById('marker-legend').innerHTML = Object.keys(markerKinds).filter((k) => present.has(k))
      .map((k) => `<div>${markerSymbol(k)} ${markerKinds[k].legend}</div>`).join('') +
      '<div class="note">line width: section depth</div>';

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
      const at = (node, axis) => {
        const x0 = initial[3 * node + axis];
        return x0 + scale * (positions[3 * node + axis] - x0);
      };
      for (let m = 0; m < nMembers; ++m) {
        for (let end = 0; end < 2; ++end) {
          const node = members[2 * m + end];
          for (let axis = 0; axis < 3; ++axis) vertex[6 * m + 3 * end + axis] = at(node, axis);
        }
        const v = colouring ? colouring.data[k * nMembers + m] : NaN;
        if (Number.isFinite(v)) colourScales[colouring.scale](v, colouring, colour, 3 * m);
        else colour[3 * m] = colour[3 * m + 1] = colour[3 * m + 2] = 0.6;
      }
      members3d.update(vertex, colour);
      markers.forEach((e, i) => { for (let axis = 0; axis < 3; ++axis) markerPosition[3 * i + axis] = at(e.node, axis); });
      markerGeometry.attributes.position.needsUpdate = true;
      report.frame = k;
      document.getElementById('frame').value = k;
      text('time', `${frames.label(k)} (frame ${k + 1} of ${nFrames})`);
      render();
      if (report.onFrame) report.onFrame(k);
    }

    // The axis triad (bottom left) and the scale bar (bottom right) on the overlay canvas.
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    function drawOverlay(w, h) {
      const dpr = window.devicePixelRatio || 1;
      Object.assign(overlay.style, { left: `${canvas.offsetLeft + canvas.clientLeft}px`, top: `${canvas.offsetTop + canvas.clientTop}px`,
        width: `${w}px`, height: `${h}px` });
      overlay.width = w * dpr; overlay.height = h * dpr;
      const g = overlay.getContext('2d');
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
      g.clearRect(0, 0, w, h);
      g.lineWidth = 2; g.font = 'bold 12px sans-serif'; g.textAlign = 'center'; g.textBaseline = 'middle';
      const origin = [46, h - 46], axes = [];
      const view = camera.matrixWorldInverse;
      ['x', 'y', 'z'].slice(0, data.dimension === 2 ? 2 : 3).forEach((name, i) => {
        const d = new THREE.Vector3(i === 0 ? 1 : 0, i === 1 ? 1 : 0, i === 2 ? 1 : 0).transformDirection(view);
        const tip = [origin[0] + 30 * d.x, origin[1] - 30 * d.y];
        const c = ['#c0392b', '#1e8449', '#1f4e9e'][i];
        g.strokeStyle = c; g.fillStyle = c;
        g.beginPath(); g.moveTo(origin[0], origin[1]); g.lineTo(tip[0], tip[1]); g.stroke();
        const label = [origin[0] + 40 * d.x, origin[1] - 40 * d.y];
        g.fillText(name, label[0], label[1]);
        axes.push({ name, tip, label });
      });
      // Pixels per metre in the plane through the view's centre (the orbit target), square to
      // the view: a perspective view's scale holds at that depth.
      const distance = camera.position.distanceTo(controls.target);
      const pixelsPerMetre = h / 2 / (distance * Math.tan(THREE.Math.degToRad(camera.fov) / 2));
      const length = roundLength(pixelsPerMetre, 100), pixels = length * pixelsPerMetre;
      const x1 = w - 20, x0 = x1 - pixels, y = h - 20;
      g.strokeStyle = '#222'; g.fillStyle = '#222'; g.lineWidth = 2;
      g.beginPath(); g.moveTo(x0, y - 5); g.lineTo(x0, y); g.lineTo(x1, y); g.lineTo(x1, y - 5); g.stroke();
      g.font = '12px sans-serif'; g.textBaseline = 'bottom';
      g.fillText(`${formatNumber(length)} m`, (x0 + x1) / 2, y - 4);
      report.axes = axes;
      report.scaleBar = { length_m: length, pixels, x0, x1, y, pixelsPerMetre };
    }
    function render() {
      const w = canvas.clientWidth, h = canvas.clientHeight;
      if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
        renderer.setSize(w, h, false);
        camera.aspect = w / Math.max(h, 1);
        camera.updateProjectionMatrix();
      }
      camera.updateMatrixWorld();
      memberUniforms.resolution.value.set(canvas.width, canvas.height);
      const distance = camera.position.distanceTo(sphere.center);
      memberUniforms.depthRange.value.set(Math.max(distance - sphere.radius, 0), distance + sphere.radius);
      renderer.render(scene, camera);
      drawOverlay(w, h);
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
    // Where a point is drawn, in canvas pixels (x right, y down), and its distance in front of
    // the camera (m): the browser test looks for members and markers there.
    function project(x, y, z) {
      const p = new THREE.Vector3(x, y, z);
      const depth = -p.clone().applyMatrix4(camera.matrixWorldInverse).z;
      p.project(camera);
      return [(p.x + 1) / 2 * canvas.width, (1 - p.y) / 2 * canvas.height, depth];
    }
    const midpoint = (m) => [0, 1, 2].map((a) => (vertex[6 * m + a] + vertex[6 * m + 3 + a]) / 2);
    report.memberMidpoints = () => Array.from({ length: nMembers }, (_, m) => project(...midpoint(m)).slice(0, 2));
    report.memberDepths = () => Array.from({ length: nMembers }, (_, m) => project(...midpoint(m))[2]);
    report.memberEnds = () => Array.from({ length: nMembers }, (_, m) =>
      [project(vertex[6 * m], vertex[6 * m + 1], vertex[6 * m + 2]).slice(0, 2),
        project(vertex[6 * m + 3], vertex[6 * m + 4], vertex[6 * m + 5]).slice(0, 2)]);
    report.memberWidths = members3d.wide ? Array.from(width) : new Array(nMembers).fill(1);
    report.markers = () => markers.map((e, i) => ({
      node: e.node, kind: e.kind, name: e.name,
      at: project(markerPosition[3 * i], markerPosition[3 * i + 1], markerPosition[3 * i + 2]).slice(0, 2),
    }));
    report.depthCue = memberUniforms.depthCue.value;
    report.camera = camera;
    report.scene = scene;
    report.controls = controls;
    report.render = render;
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
  function linePlot(canvas, { xLabel, yLabel, xUnit, yUnit, series, marks = [], verticals = [], chosen = null, zero = false }) {
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
    const xAxis = niceTicks(x0, x1, { cover: true }), yAxis = niceTicks(y0, y1, { target: 5, cover: true });
    x0 = xAxis.lo; x1 = xAxis.hi; y0 = yAxis.lo; y1 = yAxis.hi;
    const px = (v) => left + (v - x0) / (x1 - x0) * (W - left - right);
    const py = (v) => top + (y1 - v) / (y1 - y0) * (H - top - bottom);
    drawAxes(context, canvas, { box: [left, top, W - right, H - bottom], x: xAxis, y: yAxis, px, py,
                                xLabel, yLabel, xUnit, yUnit });
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
    const labels = { dT_C: ['ΔT', '°C'], load_N: ['load', 'N'], time_s: ['drivers\' time t', 's'] };
    const [parameterName, parameterUnit] = labels[path.parameter] || [path.parameter, ''];
    const parameterLabel = parameterUnit ? `${parameterName} (${parameterUnit})` : parameterName;
    const symbols = { limit_point: '◆', bifurcation: '▲', singular_constraints: '✕' };
    const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b'];
    const pathCanvas = document.getElementById('path-plot'), eigenCanvas = document.getElementById('eigen-plot');
    let chosenRow = frames ? frames.rows[report.frame] : null;
    let mapping = null;
    function draw() {
      const marks = path.events.map((e) => ({ x: path.displacement_norm[e.row], y: path.value[e.row], symbol: symbols[e.kind] || '●' }));
      const chosen = chosenRow === null ? null : { x: path.displacement_norm[chosenRow], y: path.value[chosenRow] };
      mapping = linePlot(pathCanvas, {
        xLabel: 'displacement norm ‖q − q₀‖ (m)', yLabel: parameterLabel, xUnit: 'm', yUnit: parameterUnit, marks, chosen,
        series: [{ x: path.displacement_norm, y: path.value, colour: '#1f3a5f', label: 'path' }],
      });
      linePlot(eigenCanvas, {
        xLabel: parameterLabel, yLabel: 'lowest eigenvalues (N/m)', xUnit: parameterUnit, yUnit: 'N/m', zero: true,
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
    const unitOf = new Map(p.columns.map((name, k) => [name, (p.units || [])[k] || '']));
    p.columns.forEach((name, k) => {
      const option = document.createElement('option');
      option.value = name; option.textContent = unitOf.get(name) ? `${name} (${unitOf.get(name)})` : name;
      option.selected = p.defaults.includes(name);
      select.append(option);
      series.set(name, () => decode(p.values[k], Float64Array));
    });
    text('plot-note', data.notes.plots || '');
    const canvas = document.getElementById('plot');
    const context = canvas.getContext('2d');
    const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];
    const cache = new Map();
    const events = runEvents();
    let range = [t[0], t[t.length - 1]], drag = null;
    function chosen() { return Array.from(select.selectedOptions).map((o) => o.value); }
    function values(name) { if (!cache.has(name)) cache.set(name, series.get(name)()); return cache.get(name); }
    function draw() {
      const dpr = window.devicePixelRatio || 1;
      canvas.width = canvas.clientWidth * dpr; canvas.height = canvas.clientHeight * dpr;
      context.setTransform(dpr, 0, 0, dpr, 0, 0);
      const W = canvas.clientWidth, H = canvas.clientHeight, left = 80, right = 10, top = 10, bottom = 34;
      context.clearRect(0, 0, W, H);
      const names = chosen();
      let lo = Infinity, hi = -Infinity;
      for (const name of names) {
        const v = values(name);
        for (let i = 0; i < t.length; ++i) if (t[i] >= range[0] && t[i] <= range[1] && Number.isFinite(v[i])) { lo = Math.min(lo, v[i]); hi = Math.max(hi, v[i]); }
      }
      if (!(hi > lo)) { lo -= 1; hi += 1; }
      // The time axis keeps the chosen range (zoom) with the round ticks inside it; the value
      // axis widens to the ticks around the data.
      const yAxis = niceTicks(lo, hi, { target: 5, cover: true });
      lo = yAxis.lo; hi = yAxis.hi;
      const x = (s) => left + (s - range[0]) / (range[1] - range[0] || 1) * (W - left - right);
      const y = (v) => top + (hi - v) / (hi - lo) * (H - top - bottom);
      // The y label: the chosen quantities (column prefixes) and their units.
      const distinct = (list) => [...new Set(list)];
      const kinds = distinct(names.map((name) => name.split('.')[0]));
      const units = distinct(names.map((name) => unitOf.get(name) || '?'));
      const quantity = kinds.length > 3 ? `${kinds.slice(0, 3).join(', ')}, …` : kinds.join(', ');
      drawAxes(context, canvas, {
        box: [left, top, W - right, H - bottom], x: niceTicks(range[0], range[1] > range[0] ? range[1] : range[0] + 1),
        y: yAxis, px: x, py: y, xLabel: 't (s)', yLabel: `${quantity || 'value'} (${units.join(', ') || '–'})`,
        xUnit: 's', yUnit: units.join(', '),
      });
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
        context.fillText(unitOf.get(name) ? `${name} (${unitOf.get(name)})` : name, left + 8, top + 14 + 13 * n);
      });
      // The events as vertical lines, labelled where the labels do not overlap.
      const eventColours = { failure: '#c0392b', 'hinge.latched': '#1e8449', 'cable.slack': '#d68910' };
      const lines = [];
      let labelledAt = -Infinity;
      context.save();
      for (const e of events) {
        if (e.t < range[0] || e.t > range[1]) continue;
        const at = x(e.t);
        context.strokeStyle = eventColours[e.kind] || '#777';
        context.setLineDash(e.kind === 'failure' ? [] : [4, 3]);
        context.beginPath(); context.moveTo(at, top); context.lineTo(at, H - bottom); context.stroke();
        const labelled = at - labelledAt >= 14;
        if (labelled) {
          labelledAt = at;
          context.save(); context.translate(at - 3, top + 4); context.rotate(-Math.PI / 2);
          context.fillStyle = context.strokeStyle; context.textAlign = 'right';
          context.fillText(e.label, 0, 0);
          context.restore();
        }
        lines.push({ t: e.t, x: at, label: e.label, kind: e.kind, labelled });
      }
      context.restore();
      report.eventLines = lines;
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
  showVerdict();
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

// The results browser (docs/web.md): draws each view from icpbench's JSON API.
// The view and its choices live in the URL's hash, so a link reproduces what
// is shown. No build step: plain JavaScript and Debian's Chart.js 3.
'use strict';

const FILTERS = ['experiment', 'algorithm', 'problem', 'status'];
const PAGE = 50;
const charts = {};
let options = null;

// --- the state in the hash -------------------------------------------------
function state() { return new URLSearchParams(location.hash.slice(1)); }
// replace: correct the link in place (no new history entry, no redraw).
function setState(changes, replace) {
  const s = state();
  for (const [k, v] of Object.entries(changes)) {
    if (v === '' || v === null || v === undefined) s.delete(k); else s.set(k, v);
  }
  if (replace) history.replaceState(null, '', '#' + s); else location.hash = s.toString();
}
// The API's filter query from the hash: experiment=..&param.w=..
function filterQuery() {
  const s = state(), q = new URLSearchParams();
  for (const f of FILTERS) if (s.get(f)) q.set(f, s.get(f));
  if (s.get('pname') && s.get('pvalue')) q.set('param.' + s.get('pname'), s.get('pvalue'));
  return q;
}

// --- helpers ---------------------------------------------------------------
async function api(path) {
  const res = await fetch(path);
  const body = await res.json();
  if (!res.ok) throw new Error(body.error || res.statusText);
  return body;
}
function showError(e) {
  const p = document.getElementById('error');
  p.textContent = e ? String(e.message || e) : '';
  p.hidden = !e;
}
function fmt(v) {
  if (v === null || v === undefined) return '';
  if (typeof v === 'number') return Number.isInteger(v) ? String(v) : v.toPrecision(4);
  if (typeof v === 'object') return JSON.stringify(v);
  return String(v);
}
// A value in full, as the API gave it: what a CSV holds (±inf as the store writes it).
function full(v) {
  if (typeof v !== 'number') return fmt(v);
  if (isNaN(v)) return '';
  return Number.isFinite(v) ? String(v) : v > 0 ? 'inf' : '-inf';
}
function num(v) { return v === 'inf' ? Infinity : v === '-inf' ? -Infinity : v; }
// Fills table el with a header and rows (arrays of values); onclick(row index).
function fillTable(el, header, rows, onclick, rowClass) {
  el.replaceChildren();
  const head = el.insertRow();
  for (const h of header) { const th = document.createElement('th'); th.textContent = h; head.appendChild(th); }
  rows.forEach((r, i) => {
    const tr = el.insertRow();
    if (onclick) { tr.className = 'clickable'; tr.onclick = () => onclick(i); }
    if (rowClass) tr.classList.add(...rowClass(i).split(' ').filter(Boolean));
    for (const v of r) {
      const td = tr.insertCell();
      td.textContent = fmt(v);
      if (typeof v === 'number') td.className = 'num';
      // The display rounds; the cell keeps the full value for the CSV.
      if (full(v) !== td.textContent) td.dataset.value = full(v);
    }
  });
}
function keyValueTable(el, object) {
  fillTable(el, ['name', 'value'], Object.entries(object));
}
// The table's cells as CSV, downloaded: the full values, not the rounded display.
function downloadCsv(id) {
  const quote = t => /[",\n\r]/.test(t) ? '"' + t.replace(/"/g, '""') + '"' : t;
  const lines = [...document.getElementById(id).rows].map(
    tr => [...tr.cells].map(c => quote(c.dataset.value ?? c.textContent)).join(','));
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([lines.join('\n') + '\n'], {type: 'text/csv'}));
  a.download = id.replace('-table', '') + '.csv';
  a.click();
}
function drawChart(id, config) {
  if (charts[id]) charts[id].destroy();
  config.options = Object.assign({animation: false, maintainAspectRatio: false}, config.options);
  charts[id] = new Chart(document.getElementById(id), config);
}
const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2',
                 '#7f7f7f', '#bcbd22', '#17becf'];
function colour(i, alpha) {
  const c = COLOURS[i % COLOURS.length];
  return alpha ? c + alpha : c;
}
function setOptions(select, values, chosen, blank) {
  select.replaceChildren();
  if (blank !== undefined) select.add(new Option(blank, ''));
  for (const v of values) select.add(new Option(v, v));
  select.value = chosen || '';
}

// --- filters ---------------------------------------------------------------
function drawFilters() {
  const s = state(), box = document.getElementById('filters');
  const lists = {experiment: options.experiments, algorithm: options.algorithms,
                 problem: options.problems, status: ['ok', 'failed', 'timeout', 'skipped']};
  for (const f of FILTERS) {
    const sel = box.querySelector(`[name=${f}]`);
    setOptions(sel, lists[f], s.get(f), 'all');
    sel.onchange = () => setState({[f]: sel.value, offset: ''});
  }
  const pname = box.querySelector('[name=param-name]'), pvalue = box.querySelector('[name=param-value]');
  setOptions(pname, Object.keys(options.parameters), s.get('pname'), 'any');
  setOptions(pvalue, options.parameters[s.get('pname')] || [], s.get('pvalue'), 'any');
  pname.onchange = () => setState({pname: pname.value, pvalue: '', offset: ''});
  pvalue.onchange = () => setState({pvalue: pvalue.value, offset: ''});
}

// --- runs ------------------------------------------------------------------
async function drawRuns() {
  const s = state(), q = filterQuery();
  const summary = await api('/api/summary?' + q);
  const offset = pageOffset(s.get('offset'), summary.total);
  if (String(offset) !== (s.get('offset') || '0')) setState({offset: offset || ''}, true);
  document.getElementById('counts').textContent =
    `${summary.total} runs: ` + ['ok', 'failed', 'timeout', 'skipped']
      .map(k => `${summary.status[k] || 0} ${k}`).join(', ');
  fillTable(document.getElementById('reasons'), ['status', 'reason', 'runs'],
            summary.reasons.map(r => [r.status, r.reason, r.count]));
  q.set('limit', PAGE);
  q.set('offset', offset);
  const runs = await api('/api/runs?' + q);
  // The parameters that differ between the page's runs (all of them are in the key).
  const merged = runs.map(r => Object.assign({}, r.parameters.problem, r.parameters.algorithm));
  const varying = [...new Set(merged.flatMap(Object.keys))]
    .filter(k => new Set(merged.map(m => m[k])).size > 1);
  const params = i => varying.filter(k => k in merged[i]).map(k => `${k}=${merged[i][k]}`).join(' ');
  fillTable(document.getElementById('runs-table'),
            ['id', 'experiment', 'algorithm', 'problem', 'parameters that differ', 'seed', 'status', 'reason',
             'steps', 'mean area (m²)', 'consistency', 'centre rmse (m)', 'time/step (s)', 'key'],
            runs.map((r, i) => [r.id, r.experiment, r.algorithm, r.problem, params(i), r.seed, r.status,
                           r.reason, r.steps, num(r.mean_area), r.consistency_rate, r.centre_rmse,
                           r.time_mean_s, r.key]),
            i => setState({view: 'run', id: runs[i].id, key: runs[i].key, step: ''}),
            i => 'status-' + runs[i].status);
  document.getElementById('page').textContent = pageText(offset, runs.length, summary.total);
  document.getElementById('prev').disabled = offset === 0;
  document.getElementById('next').disabled = offset + runs.length >= summary.total;
  document.getElementById('prev').onclick = () => setState({offset: Math.max(0, offset - PAGE)});
  document.getElementById('next').onclick = () => setState({offset: offset + PAGE});
}

// The link's offset as a whole number; one past the last run (the store or
// the filters changed since the link was made) shows the last page instead.
function pageOffset(text, total) {
  const offset = Math.max(0, Math.floor(Number(text))) || 0;
  return offset < total ? offset : Math.max(0, Math.floor((total - 1) / PAGE) * PAGE);
}
function pageText(offset, shown, total) {
  if (total === 0) return 'no runs';
  if (shown === 0) return `none of ${total} past ${offset}`;  // the store changed between the requests
  return `${offset + 1}–${offset + shown} of ${total}`;
}

// --- comparison ------------------------------------------------------------
async function drawCompare() {
  const s = state();
  const metric = s.get('metric') || 'time_mean_s', group = s.get('group') || 'algorithm';
  const x = s.get('x') || 'none';
  const metrics = ['time_mean_s', 'time_median_s', 'time_p90_s', 'mean_area', 'consistency_rate',
                   'centre_rmse', 'wall_time_s', 'steps', ...options.properties.map(p => 'prop.' + p)];
  const axes = ['algorithm', 'problem', 'experiment',
                ...Object.keys(options.parameters).map(p => 'param.' + p)];
  const sel = id => document.getElementById(id);
  setOptions(sel('metric'), metrics, metric);
  setOptions(sel('group'), axes, group);
  setOptions(sel('x'), ['none', ...axes], x);
  sel('metric').onchange = () => setState({metric: sel('metric').value});
  sel('group').onchange = () => setState({group: sel('group').value});
  sel('x').onchange = () => setState({x: sel('x').value});
  sel('logy').checked = s.get('logy') === '1';
  sel('logy').onchange = () => setState({logy: sel('logy').checked ? '1' : ''});

  const q = filterQuery();
  q.set('metric', metric);
  q.set('group', group);
  q.set('x', x);
  const rows = await api('/api/aggregate?' + q);
  fillTable(sel('compare-table'), [group, x, 'runs', 'mean', 'ci 95% lo', 'ci 95% hi', 'min', 'max'],
            rows.map(r => [r.group, r.x, r.n, num(r.mean), num(r.ci_lo), num(r.ci_hi),
                           num(r.min), num(r.max)]));
  // x values in numeric order when they are numbers.
  const xs = [...new Set(rows.map(r => r.x))];
  if (xs.every(v => v !== null && v !== '' && !isNaN(Number(v)))) xs.sort((a, b) => a - b); else xs.sort();
  const groups = [...new Set(rows.map(r => r.group))];
  const datasets = [];
  groups.forEach((g, i) => {
    const at = v => rows.find(r => r.group === g && r.x === v);
    const pick = f => xs.map(v => { const r = at(v); return r ? num(r[f]) : null; });
    datasets.push({label: String(g), data: pick('mean'), borderColor: colour(i), backgroundColor: colour(i),
                   spanGaps: true});
    datasets.push({label: g + ' ci lo', data: pick('ci_lo'), borderWidth: 0, pointRadius: 0,
                   fill: false, spanGaps: true});
    datasets.push({label: g + ' ci hi', data: pick('ci_hi'), borderWidth: 0, pointRadius: 0,
                   fill: '-1', backgroundColor: colour(i, '33'), spanGaps: true});
  });
  const canvas = sel('compare-chart');
  drawChart('compare-chart', {
    type: xs.length > 1 ? 'line' : 'bar',
    data: {labels: xs.map(v => v === '' ? metric : v), datasets: xs.length > 1 ? datasets :
           datasets.filter((d, i) => i % 3 === 0)},
    options: {scales: {x: {title: {display: true, text: x}},
                       y: {type: s.get('logy') === '1' ? 'logarithmic' : 'linear',
                           title: {display: true, text: metric}}},
              plugins: {legend: {labels: {filter: item => !/ ci (lo|hi)$/.test(item.text)}}}},
  });
  // What the figure shows, for tests and readers of the DOM.
  canvas.dataset.points = rows.length;
  sel('compare-data').textContent = JSON.stringify(rows);

  if (metric === 'consistency_rate') { if (charts['profile-chart']) charts['profile-chart'].destroy(); return; }
  const pq = filterQuery();
  pq.set('metric', metric);
  pq.set('group', group);
  const profile = await api('/api/profile?' + pq);
  const n = profile.instances;
  drawChart('profile-chart', {
    type: 'line',
    data: {datasets: Object.entries(profile.solvers).map(([g, ratios], i) => ({
      label: g, stepped: true, pointRadius: 0, borderColor: colour(i),
      data: ratios.map((t, k) => ({x: t, y: (k + 1) / n}))}))},
    options: {parsing: false, scales: {
      x: {type: 'logarithmic', title: {display: true, text: 'τ (ratio to the best)'}},
      y: {min: 0, max: 1, title: {display: true, text: 'fraction of instances'}}}},
  });
  sel('profile-chart').dataset.instances = n;
}

// --- one run ---------------------------------------------------------------
// The id of the run the link names, or null for none. A link names the run by
// its key too: a retried, forced or merged run has a new id, and the key finds
// it; a key the store lacks is an error, not whichever run has the link's id.
async function linkedRunId(s) {
  const key = s.get('key');
  if (key) {
    const found = await api('/api/runs?key=' + encodeURIComponent(key));
    if (found.length === 0) throw new Error(`The linked run (key ${key}) is not in this store.`);
    const id = String(found[0].id);
    if (id !== s.get('id')) setState({id}, true);  // the link's id is stale: correct it
    return id;
  }
  if (s.get('id')) return s.get('id');
  const first = await api('/api/runs?limit=1&' + filterQuery());
  return first.length ? String(first[0].id) : null;
}
// Empties the run view, so that a run that cannot be shown leaves no other's.
function clearRun(title) {
  document.getElementById('run-title').textContent = title;
  for (const t of ['run-info', 'run-properties', 'steps-table', 'step-values', 'step-properties'])
    document.getElementById(t).replaceChildren();
  for (const c of ['steps-chart', 'corridor-chart', 'estimate-chart'])
    if (charts[c]) { charts[c].destroy(); delete charts[c]; }
  document.getElementById('estimate-note').textContent = '';
}
async function drawRun() {
  const s = state(), input = document.getElementById('run-id');
  input.onchange = () => setState({id: input.value, key: '', step: ''});
  let id, run;
  try {
    id = await linkedRunId(s);
    if (id === null) { input.value = ''; clearRun('No runs (in this store or with these filters).'); return; }
    input.value = id;
    run = await api('/api/runs/' + id);
  } catch (e) {
    input.value = id || '';
    clearRun('');
    throw e;
  }
  document.getElementById('run-title').textContent =
    `${run.algorithm} on ${run.problem} (${run.status}${run.reason ? ': ' + run.reason : ''})`;
  const info = {key: run.key, spec: run.spec_file, seed: run.seed, timeout_s: run.timeout_s,
                wall_time_s: run.wall_time_s, steps: run.steps};
  for (const [k, v] of Object.entries(run.algorithm_params)) info['algorithm ' + k] = v;
  for (const [k, v] of Object.entries(run.problem_params)) info['problem ' + k] = v;
  for (const k of ['mean_area', 'consistency_rate', 'centre_rmse', 'time_mean_s', 'time_median_s',
                   'time_p90_s', 'time_mean_ci_lo_s', 'time_mean_ci_hi_s', 'git_revision',
                   'machine', 'compiler', 'flags', 'date']) info[k] = run[k];
  keyValueTable(document.getElementById('run-info'), info);
  keyValueTable(document.getElementById('run-properties'), run.properties);

  const steps = run.step_rows;
  fillTable(document.getElementById('steps-table'),
            ['step', 'status', 'truth held', 'area (m²)', 'centre error (m)', 'solve time (s)', 'estimate'],
            steps.map(r => [r.step, r.status, r.contained === null ? '' : r.contained ? 'yes' : 'no',
                            num(r.area), r.centre_error, r.solve_time_s, r.estimate]),
            i => setState({step: steps[i].step}),
            i => steps[i].contained === 0 ? 'not-contained' : '');
  drawChart('steps-chart', {
    type: 'line',
    data: {labels: steps.map(r => r.step), datasets: [
      {label: 'area (m²)', data: steps.map(r => num(r.area)), borderColor: colour(0), pointRadius: 0, yAxisID: 'y'},
      {label: 'centre error (m)', data: steps.map(r => r.centre_error), borderColor: colour(2), pointRadius: 0, yAxisID: 'y1'},
      {label: 'truth not held', showLine: false, pointRadius: 4, yAxisID: 'y', backgroundColor: colour(1),
       borderColor: colour(1), data: steps.map(r => r.contained === 0 ? num(r.area) : null)}]},
    options: {scales: {x: {title: {display: true, text: 'step'}},
                       y: {type: 'logarithmic', title: {display: true, text: 'area (m²)'}},
                       y1: {position: 'right', title: {display: true, text: 'centre error (m)'}}}},
  });
  document.getElementById('steps-chart').dataset.steps = steps.length;

  const values = await api('/api/runs/' + id + '/values');
  const vars = [...new Set(values.rows.map(r => r[1]))];
  const datasets = [];
  vars.forEach((v, i) => {
    const rows = values.rows.filter(r => r[1] === v);
    const finite = t => { const n = num(t); return Number.isFinite(n) ? n : null; };
    datasets.push({label: v + ' lo', data: rows.map(r => ({x: r[0], y: finite(r[2])})), borderColor: colour(i), pointRadius: 0, borderWidth: 1});
    datasets.push({label: v + ' hi', data: rows.map(r => ({x: r[0], y: finite(r[3])})), borderColor: colour(i), pointRadius: 0, borderWidth: 1,
                   fill: '-1', backgroundColor: colour(i, '22')});
    datasets.push({label: v + ' truth', data: rows.map(r => ({x: r[0], y: r[4]})), borderColor: '#000', borderDash: [4, 3], pointRadius: 0, borderWidth: 1});
  });
  drawChart('corridor-chart', {type: 'line', data: {datasets},
    options: {parsing: false, scales: {x: {type: 'linear', title: {display: true, text: 'step'}}}}});

  const stepInput = document.getElementById('step');
  stepInput.onchange = () => setState({step: stepInput.value});
  const step = s.get('step') || (steps.length ? steps[0].step : null);
  if (step === null) return;
  stepInput.value = step;
  const detail = await api(`/api/runs/${id}/steps/${step}`);
  fillTable(document.getElementById('step-values'), ['var', 'lo', 'hi', 'truth'],
            detail.values.map(v => [v.var, num(v.lo), num(v.hi), v.truth]));
  keyValueTable(document.getElementById('step-properties'), detail.properties);
  drawEstimate(detail.values);
  await drawRerun(id, step, detail.values);
}

// The step's x-y hull (the estimate's box as the store keeps it) and the truth.
function drawEstimate(values) {
  const v = name => values.find(r => r.var === name);
  const x = v('x'), y = v('y');
  const finite = r => r && [r.lo, r.hi].every(t => Number.isFinite(num(t)));
  if (!finite(x) || !finite(y)) { if (charts['estimate-chart']) charts['estimate-chart'].destroy(); return; }
  const box = [[x.lo, y.lo], [x.hi, y.lo], [x.hi, y.hi], [x.lo, y.hi], [x.lo, y.lo]];
  const datasets = [{label: 'estimate (x-y hull)', data: box.map(([a, b]) => ({x: a, y: b})),
                     showLine: true, fill: true, pointRadius: 0, borderColor: colour(0),
                     backgroundColor: colour(0, '33')}];
  if (x.truth !== null && y.truth !== null)
    datasets.push({label: 'truth', data: [{x: x.truth, y: y.truth}], pointRadius: 5,
                   backgroundColor: '#000'});
  drawChart('estimate-chart', {type: 'scatter', data: {datasets},
    options: {scales: {x: {title: {display: true, text: 'x (m)'}}, y: {title: {display: true, text: 'y (m)'}}}}});
}

// The step's estimate re-run by the server (boxes, accumulator image,
// particles) over the stored hull; the note says whether the re-run
// reproduces the stored step. A run that cannot be re-run keeps the hull.
// One re-run in flight per page: the server keeps computing one whose
// request the page gave up, so quick clicks through steps held both of its
// slots (503). A click meanwhile waits, and only the last one runs.
let rerunInFlight = false, rerunWaiting = null;
async function drawRerun(id, step, values) {
  const note = document.getElementById('estimate-note');
  if (rerunInFlight) {
    rerunWaiting = [id, step, values];
    note.textContent = 're-running the step (after the one in progress)…';
    return;
  }
  rerunInFlight = true;
  try {
    await drawOneRerun(id, step, values);
  } finally {
    rerunInFlight = false;
    if (rerunWaiting) {
      const next = rerunWaiting;
      rerunWaiting = null;
      drawRerun(...next);
    }
  }
}
async function drawOneRerun(id, step, values) {
  const note = document.getElementById('estimate-note'), canvas = document.getElementById('estimate-chart');
  note.textContent = 're-running the step…';
  let e;
  try { e = await api(`/api/runs/${id}/steps/${step}/estimate`); } catch (err) { note.textContent = 'no re-run: ' + err.message; return; }
  if (rerunWaiting) return;  // another step was chosen meanwhile: draw that one
  const d = e.data, rects = [], points = [];
  (d.inner || []).forEach(r => rects.push([r, colour(2)]));
  (d.boundary || []).forEach(r => rects.push([r, colour(3)]));
  const hull = e.x >= 0 ? [e.hull[e.x].lo, e.hull[e.x].hi, e.hull[e.y].lo, e.hull[e.y].hi] : null;
  if (d.box || (hull && !d.inner && hull.every(Number.isFinite))) rects.push([d.box || hull, colour(0)]);  // the set's box
  (d.x && e.kind === 'particles' ? d.x : []).forEach((x, i) => points.push({x, y: d.y[i]}));
  const extent = [...rects.flatMap(([r]) => [{x: r[0], y: r[2]}, {x: r[1], y: r[3]}])];
  if (e.kind === 'accumulator') extent.push({x: d.x[0], y: d.y[0]}, {x: d.x[1], y: d.y[1]});
  const datasets = [{label: e.kind, data: points.concat(extent), pointRadius: c => c.dataIndex < points.length ? 1.5 : 0,
                     backgroundColor: colour(1, '88')}];
  if (e.truth.length > Math.max(e.x, e.y))
    datasets.push({label: 'truth', data: [{x: e.truth[e.x], y: e.truth[e.y]}], pointRadius: 6, pointStyle: 'crossRot',
                   borderColor: '#000', borderWidth: 2});
  const shapes = {id: 'estimate-shapes', beforeDatasetsDraw(chart) {
    const {ctx, scales: {x, y}} = chart;
    ctx.save();
    if (e.kind === 'accumulator') ctx.drawImage(countsImage(d), x.getPixelForValue(d.x[0]), y.getPixelForValue(d.y[1]),
                                                x.getPixelForValue(d.x[1]) - x.getPixelForValue(d.x[0]),
                                                y.getPixelForValue(d.y[0]) - y.getPixelForValue(d.y[1]));
    for (const [r, c] of rects) {
      const px = x.getPixelForValue(r[0]), py = y.getPixelForValue(r[3]);
      ctx.fillStyle = c + '44'; ctx.strokeStyle = c;
      ctx.fillRect(px, py, x.getPixelForValue(r[1]) - px, y.getPixelForValue(r[2]) - py);
      if (rects.length < 500) ctx.strokeRect(px, py, x.getPixelForValue(r[1]) - px, y.getPixelForValue(r[2]) - py);
    }
    ctx.restore();
  }};
  drawChart('estimate-chart', {type: 'scatter', data: {datasets}, plugins: [shapes],
    options: {scales: {x: {title: {display: true, text: 'x (m)'}}, y: {title: {display: true, text: 'y (m)'}}}}});
  canvas.dataset.kind = e.kind;
  canvas.dataset.drawn = rects.length + points.length + (e.kind === 'accumulator' ? d.rows * d.cols : 0);
  note.textContent = `${e.kind}, re-run in ${e.rerun_s.toFixed(2)} s: ` +
    (e.matches_store ? 're-run reproduces the stored step' : 're-run does NOT reproduce the stored step') +
    (d.truncated || d.subsampled || d.downsampled ? ' (thinned for drawing)' : '');
}
// An accumulator's counts as an image, darker for higher counts, cells at or
// above the threshold in colour; image row 0 is the grid's top row (largest y).
function countsImage(d) {
  const img = document.createElement('canvas');
  img.width = d.cols; img.height = d.rows;
  const ctx = img.getContext('2d'), pixels = ctx.createImageData(d.cols, d.rows);
  const max = Math.max(1, ...d.counts.map(r => Math.max(...r)));
  d.counts.forEach((row, r) => row.forEach((n, c) => {
    const i = 4 * ((d.rows - 1 - r) * d.cols + c), shade = 255 - Math.round(200 * n / max);
    pixels.data.set(n >= d.threshold ? [214, 39, 40, 255] : [shade, shade, shade, n > 0 ? 255 : 0], i);
  }));
  ctx.putImageData(pixels, 0, 0);
  return img;
}

// --- figures and claims ----------------------------------------------------
async function drawFigures() {
  const names = await api('/api/figures'), box = document.getElementById('figures');
  box.replaceChildren();
  if (names.length === 0) box.textContent = 'No figures yet: icpbench plot DIR writes them to DIR/figures.';
  for (const n of names) {
    const fig = document.createElement('figure'), url = '/figures/' + n.split('/').map(encodeURIComponent).join('/');
    if (n.endsWith('.pdf')) {
      const a = document.createElement('a'); a.href = url; a.textContent = n; fig.appendChild(a);
    } else {
      const img = document.createElement('img'); img.src = url; img.alt = n; fig.appendChild(img);
      const cap = document.createElement('figcaption'); cap.textContent = n; fig.appendChild(cap);
    }
    box.appendChild(fig);
  }
}
// What a JSON value is, for messages about a file of the wrong shape.
function jsonKind(v) {
  if (v === null) return 'null';
  if (Array.isArray(v)) return 'an array';
  return {object: 'an object', number: 'a number', string: 'a string', boolean: 'a boolean'}[typeof v];
}
const isObject = v => v !== null && typeof v === 'object' && !Array.isArray(v);
// claims.json is an array of objects, one a claim (icpbench paper writes it);
// a file edited by hand or by another tool may be anything, so its shape is checked.
async function drawClaims() {
  const c = await api('/api/claims'), table = document.getElementById('claims-table');
  const text = document.getElementById('claims-file');
  table.replaceChildren();
  if (!c.file) { text.textContent = 'No claims: icpbench paper DIR writes them.'; return; }
  const wrapped = isObject(c.claims) && 'claims' in c.claims;  // {"claims": [...]}
  const list = wrapped ? c.claims.claims : c.claims;
  if (!Array.isArray(list)) {
    text.textContent = '';
    throw new Error(`${c.file} is not a list of claims: ${wrapped ? 'its "claims" holds' : 'it holds'} ` +
                    `${jsonKind(list)}, not an array of objects.`);
  }
  const claims = list.filter(isObject);
  const skipped = list.map((r, i) => isObject(r) ? null : `#${i + 1} (${jsonKind(r)})`).filter(Boolean);
  text.textContent = `From ${c.file}: ${claims.length} claim${claims.length === 1 ? '' : 's'}.` +
    (skipped.length ? ' Skipped the entries that are not objects: ' +
                      skipped.slice(0, 10).join(', ') + (skipped.length > 10 ? ', …' : '.') : '');
  const header = [...new Set(claims.flatMap(Object.keys))];
  fillTable(table, header, claims.map(r => header.map(h => r[h])));
}

// --- the page --------------------------------------------------------------
const VIEWS = {runs: drawRuns, compare: drawCompare, run: drawRun, figures: drawFigures, claims: drawClaims};
async function draw() {
  const view = VIEWS[state().get('view')] ? state().get('view') : 'runs';
  for (const v of Object.keys(VIEWS)) document.getElementById('view-' + v).hidden = v !== view;
  document.getElementById('filters').hidden = view === 'figures' || view === 'claims';
  document.querySelectorAll('nav a').forEach(a => a.classList.toggle('active', a.dataset.view === view));
  try {
    showError(null);
    if (!options) options = await api('/api/options');
    drawFilters();
    await VIEWS[view]();
    document.body.dataset.ready = view;
  } catch (e) {
    showError(e);
    document.body.dataset.ready = 'error';
  }
}
document.querySelectorAll('nav a').forEach(a => a.onclick = e => {
  e.preventDefault();
  setState({view: a.dataset.view});
});
document.querySelectorAll('button.csv').forEach(b => b.onclick = () => downloadCsv(b.dataset.table));
window.addEventListener('hashchange', draw);
draw();

// Sensor control for multi-object estimation (paper 004, Ristic & Vo: Algorithm 1, the 17
// actions (23), the rewards (17), (29), (30), OSPA (24)–(26); Figs 1–3). Every particle,
// reward and OSPA value comes from the fisst package (SensorControlRun, compareSchemes), run
// in two module workers (control.worker.js): one steps the live run, one runs the
// comparison, so that the page never waits on either.
import { chart } from './lib/chart.js';
import { clipTo, cross, dot, haloText, sceneView } from './lib/scene.js';
import { CATEGORICAL, colorbar, colormap } from './lib/colormap.js';
import { $, choice, downloads, fmt, pageReady, pointText, progressBar, slider, timings, toCSV, urlState } from './lib/page.js';

const SCHEMES = ['renyi', 'fisher', 'pent', 'random'];
const SCHEME_LABEL = { renyi: 'Rényi divergence', fisher: 'Fisher information', pent: 'PENT', random: 'random' };
const SCHEME_COLOUR = { renyi: CATEGORICAL[0], fisher: CATEGORICAL[1], pent: CATEGORICAL[2], random: CATEGORICAL[3] };
const [PINK, CYAN, GREEN, RED] = ['#cc79a7', '#0e9bd6', '#009e73', '#d55e00'];
const OBJECT_COLOURS = ['#1f2933', '#0072b2', '#7c3aed', '#0f766e']; // clear of the estimate's vermillion
const AREA = 1000; // the surveillance area A = [0, 1000]² m (Sec. 5.1)
const OSPA_C = 100; // the cut-off c = 100 m (Sec. 5.3)

const url = urlState({ scheme: 'renyi', seed: 1, particles: 750, futureScans: 200, alpha: 0.5, steps: 40, runs: 20 });
const state = url.values;
const timer = timings('control');
timer.badge($('redraw-ms'), { step: 'step (worker)', scene: 'scene', chart: 'OSPA chart', fig3: 'Fig. 3' });

/** The live run as the worker last reported it; `history` is one entry per step. */
const live = { id: 0, k: 0, steps: state.steps, history: [], last: null, particles: [], sensorPath: [], truth: [], measurements: [], scanAt: null, playing: false, busy: false };
const status = (text, error = false) => {
  $('status').textContent = text;
  $('status').className = error ? 'error' : 'muted';
};

// ---------------------------------------------------------------- the workers
const newWorker = () => new Worker(new URL('./control.worker.js', import.meta.url), { type: 'module' });
let stepper = newWorker();
stepper.onmessage = ({ data }) => onStepper(data);
let comparer = null;

const runOptions = () => ({ seed: state.seed, scheme: state.scheme, particles: state.particles, futureScans: state.futureScans, alpha: state.alpha, steps: state.steps });

function restart() {
  Object.assign(live, { id: live.id + 1, k: 0, steps: state.steps, history: [], last: null, particles: [], measurements: [], scanAt: null, busy: true });
  stepper.postMessage({ type: 'start', id: live.id, options: runOptions() });
  stepper.postMessage({ type: 'step', id: live.id }); // the first scan: the particles start on its arcs
  status(`scan 1 of ${state.steps}…`);
  url.save();
}

function requestStep() {
  if (live.busy || live.k >= live.steps) return;
  live.busy = true;
  status(`scan ${live.k + 1} of ${live.steps}…`);
  stepper.postMessage({ type: 'step', id: live.id });
}

let first = true;
function onStepper(data) {
  if (data.id !== undefined && data.id !== live.id) return; // a reply to a run since replaced
  if (data.type === 'error') {
    live.busy = false;
    setPlaying(false);
    status(`${data.name}: ${data.message}`, true);
    if (first) { first = false; pageReady(); }
    return;
  }
  if (data.type === 'started') {
    Object.assign(live, { truth: data.truth, sensorPath: data.sensorPath });
    return;
  }
  if (data.type !== 'step') return;
  const { result } = data;
  timer.record('step', data.ms);
  // Z_k, taken where the sensor stood before this step's move (Alg. 1, line 5).
  Object.assign(live, { k: result.k, last: result, scanAt: result.sensor, measurements: result.measurements, particles: data.particles, sensorPath: data.sensorPath, truth: data.truth, busy: false });
  live.history.push({ k: result.k, ...result.ospa, n: result.estimate.cardinality, probability: mapProbability() });
  drawLive();
  const done = live.k >= live.steps;
  status(done ? `done: ${live.k} scans (restart, or change a setting)` : `scan ${live.k} of ${live.steps}${live.playing ? ': playing' : ''}`);
  if (done) setPlaying(false);
  else if (live.playing) requestStep();
  if (first) { first = false; pageReady(); }
}

function setPlaying(on) {
  live.playing = on;
  $('play').textContent = on ? '❚❚ pause' : '▶ play';
  $('play').setAttribute('aria-pressed', String(on));
}

// ---------------------------------------------------------------- Fig. 1: the scene
/** n̂, the most frequent particle cardinality (22), and Pr{n = n̂}, its share of the particles. */
const mapCardinality = () => live.last?.estimate.cardinality ?? 0;
const mapProbability = () => live.last?.estimate.cardinalityPmf[mapCardinality()] ?? null;

/** The 17 admissible positions (23) around `at`, indexed as the rewards: 0 stay, then 1 + (j − 1)·8 + (ℓ − 1) for j·50 m at ℓ·45°. */
function candidates(at) {
  const out = [[...at]];
  for (let j = 1; j <= 2; j++) for (let l = 1; l <= 8; l++) out.push([at[0] + j * 50 * Math.cos((l * Math.PI) / 4), at[1] + j * 50 * Math.sin((l * Math.PI) / 4)]);
  return out;
}
const rewardMap = colormap('viridis');
const rewardRange = (rewards) => {
  const finite = rewards.filter(Number.isFinite);
  return finite.length ? [Math.min(...finite), Math.max(...finite)] : [0, 1];
};

const view = sceneView($('scene'), {
  width: 600, height: 600, box: { left: 50, top: 10, width: 540, height: 540 }, x: [-120, AREA + 120], y: [-120, AREA + 120], pan: true, zoom: true,
  draw: drawScene,
});
const legend = colorbar($('scene-legend'), { map: 'viridis', label: 'reward of a move', format: (v) => fmt(v, 3) });

function drawScene(ctx, v) {
  const { px, py, box } = v;
  v.axes({ xLabel: 'x (m)', yLabel: 'y (m)', ticks: 6 });
  ctx.save();
  clipTo(ctx, box);
  ctx.fillStyle = '#fbfcfd';
  ctx.fillRect(px(0), py(AREA), px(AREA) - px(0), py(0) - py(AREA));
  ctx.strokeStyle = '#9aa5b1';
  ctx.lineWidth = 1.2;
  ctx.strokeRect(px(0), py(AREA), px(AREA) - px(0), py(0) - py(AREA));
  const n = mapCardinality();
  // Particles: those with n̂ objects coloured by the object's index (self-resolution), the others grey.
  for (const p of live.particles) {
    if (p.length === n) continue;
    for (const x of p) { ctx.fillStyle = 'rgba(154,165,177,0.5)'; ctx.fillRect(px(x[0]) - 1, py(x[1]) - 1, 2, 2); }
  }
  for (const p of live.particles) {
    if (p.length !== n) continue;
    p.forEach((x, i) => { ctx.fillStyle = OBJECT_COLOURS[i % OBJECT_COLOURS.length]; ctx.fillRect(px(x[0]) - 1.25, py(x[1]) - 1.25, 2.5, 2.5); });
  }
  // The range arcs of the last scan, about where it was taken, inside the area.
  if (live.scanAt) {
    ctx.save();
    ctx.beginPath();
    ctx.rect(px(0), py(AREA), px(AREA) - px(0), py(0) - py(AREA));
    ctx.clip();
    ctx.strokeStyle = CYAN;
    ctx.lineWidth = 1.4;
    for (const z of live.measurements) {
      ctx.beginPath();
      ctx.arc(px(live.scanAt[0]), py(live.scanAt[1]), Math.max(z, 0) * (px(1) - px(0)), 0, 2 * Math.PI);
      ctx.stroke();
    }
    ctx.restore();
  }
  // The sensor's path and the diamond where it stands.
  ctx.strokeStyle = PINK;
  ctx.lineWidth = 2;
  ctx.beginPath();
  for (const p of live.sensorPath) ctx.lineTo(px(p[0]), py(p[1]));
  ctx.stroke();
  const here = live.sensorPath.at(-1);
  // The 17 moves from where the scan was taken, coloured by reward; the one taken ringed.
  if (live.last && live.scanAt) {
    const rewards = live.last.rewards;
    const [lo, hi] = rewardRange(rewards);
    candidates(live.scanAt).forEach((c, i) => {
      const r = rewards[i];
      if (!Number.isFinite(r)) {
        ctx.strokeStyle = '#7b8794';
        ctx.lineWidth = 1.5;
        cross(ctx, px(c[0]), py(c[1]), 4);
      } else dot(ctx, px(c[0]), py(c[1]), 5, rewardMap.css(hi > lo ? (r - lo) / (hi - lo) : 1), '#fff', 1);
    });
    const a = live.last.action.position;
    ctx.strokeStyle = RED;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc(px(a[0]), py(a[1]), 8.5, 0, 2 * Math.PI);
    ctx.stroke();
  }
  if (here) {
    const [hx, hy] = [px(here[0]), py(here[1])];
    ctx.beginPath();
    ctx.moveTo(hx, hy - 8); ctx.lineTo(hx + 6, hy); ctx.lineTo(hx, hy + 8); ctx.lineTo(hx - 6, hy); ctx.closePath();
    ctx.fillStyle = PINK;
    ctx.fill();
    ctx.strokeStyle = '#fff';
    ctx.lineWidth = 1.2;
    ctx.stroke();
  }
  // The truth (✱) and the estimate (✕).
  ctx.lineWidth = 2.2;
  for (const t of live.truth) {
    ctx.strokeStyle = GREEN;
    cross(ctx, px(t[0]), py(t[1]), 7, false);
    cross(ctx, px(t[0]), py(t[1]), 5.5, true);
  }
  ctx.strokeStyle = RED;
  for (const e of live.last?.estimate.states ?? []) cross(ctx, px(e[0]), py(e[1]), 6);
  ctx.font = '12px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left';
  if (live.k > 0) haloText(ctx, `k = ${live.k}   Pr{n = ${n}} = ${fmt(mapProbability(), 3)}`, box.left + 8, box.top + 6, '#1f2933');
  else haloText(ctx, 'waiting for the first scan…', box.left + 8, box.top + 6, '#52606d');
  ctx.restore();
}

// ---------------------------------------------------------------- the live OSPA chart (Fig. 2)
const ospaAxis = { label: 'm', range: [0, OSPA_C], format: (v) => fmt(v, 3) };
const kAxis = (steps) => ({ label: 'scan k', integer: true, range: () => [1, Math.max(steps(), 2)], format: String });
const runChart = chart($('run-chart'), {
  height: 230, x: kAxis(() => live.steps), y: ospaAxis,
  series: [
    { label: 'OSPA', colour: '#1f2933', width: 2.5 },
    { label: 'localisation', colour: CATEGORICAL[0], width: 1.6, dash: [6, 4] },
    { label: 'cardinality', colour: CATEGORICAL[1], width: 1.6, dash: [2, 3] },
  ],
  overlay({ ctx, x, y }) { // the last scan's values as dots (a single scan draws no line)
    const h = live.history.at(-1);
    if (!h) return;
    [['distance', '#1f2933'], ['localisation', CATEGORICAL[0]], ['cardinality', CATEGORICAL[1]]].forEach(([part, colour]) => dot(ctx, x(h.k), y(h[part]), 3.5, colour, '#fff', 1));
  },
});

function drawLive() {
  timer.time('scene', () => view.redraw());
  timer.time('chart', () => runChart.update([live.history.map((h) => h.k), live.history.map((h) => h.distance), live.history.map((h) => h.localisation), live.history.map((h) => h.cardinality)]));
  const r = live.last;
  $('k').textContent = `${live.k} of ${live.steps}`;
  $('scan').textContent = `${live.measurements.length}: ${live.measurements.map((z) => `${fmt(z, 4)} m`).join(', ') || 'none'}`;
  $('cardinality').textContent = `${mapCardinality()}, ${fmt(mapProbability(), 3)}`;
  $('estimate').textContent = r.estimate.states.map((e) => pointText(e, 0)).join(' ') || '∅';
  $('ospa').textContent = `${fmt(r.ospa.distance, 4)} m`;
  $('ospa-parts').textContent = `${fmt(r.ospa.localisation, 4)} m, ${fmt(r.ospa.cardinality, 4)} m`;
  const { index, ring, heading, position } = r.action;
  $('action').textContent = `${ring ? `${ring * 50} m at ${heading * 45}°` : 'stay'} to ${pointText(position, 0)}, ${fmt(r.rewards[index], 4)}`;
  const [lo, hi] = rewardRange(r.rewards);
  legend.update({ min: lo, max: hi, label: `reward of a move (${SCHEME_LABEL[state.scheme]})` });
  timer.show();
  $('control-state').textContent = JSON.stringify({ options: runOptions(), k: live.k, step: r, probability: mapProbability(), scanAt: live.scanAt, measurements: live.measurements, sensorPath: live.sensorPath, truth: live.truth, particles: live.particles.length, box: view.box, ...view.domain() }, (_, v) => (v === -Infinity ? '-Infinity' : v)); // JSON has no −∞
}

// ---------------------------------------------------------------- Fig. 3: the comparison
const compare = { stats: null, runs: 0, total: 0, steps: state.steps, running: false };
const bar = progressBar($('compare-progress'), { label: 'comparison progress' });
bar.set(0, 'not started');

/** A Fig. 3 chart of one OSPA part: the mean of each scheme, ± one standard error shaded. */
const fig3Chart = (id, part, label) => chart($(id), {
  height: 260, x: kAxis(() => compare.steps), y: { ...ospaAxis, label: `${label} (m)` },
  series: SCHEMES.map((s) => ({ label: SCHEME_LABEL[s], colour: SCHEME_COLOUR[s], width: s === 'renyi' ? 2.6 : 1.8 })),
  overlay({ ctx, x, y }) {
    if (!compare.stats) return;
    for (const s of SCHEMES) {
      const st = compare.stats[s]?.[part];
      if (!st || st.standardError.some((e) => e === null)) continue;
      ctx.beginPath();
      st.mean.forEach((m, t) => ctx.lineTo(x(t + 1), y(m + st.standardError[t])));
      for (let t = st.mean.length - 1; t >= 0; t--) ctx.lineTo(x(t + 1), y(Math.max(st.mean[t] - st.standardError[t], 0)));
      ctx.closePath();
      ctx.fillStyle = `${SCHEME_COLOUR[s]}1f`;
      ctx.fill();
    }
  },
});
const fig3 = { distance: fig3Chart('fig3a', 'distance', 'mean OSPA'), localisation: fig3Chart('fig3b', 'localisation', 'mean localisation error'), cardinality: fig3Chart('fig3c', 'cardinality', 'mean cardinality error') };

function drawFig3() {
  timer.time('fig3', () => {
    for (const [part, c] of Object.entries(fig3)) {
      const ks = Array.from({ length: compare.steps }, (_, t) => t + 1);
      c.update([ks, ...SCHEMES.map((s) => compare.stats?.[s]?.[part].mean ?? ks.map(() => null))]);
    }
  });
  timer.show();
}

function startCompare() {
  comparer?.terminate();
  comparer = newWorker();
  Object.assign(compare, { stats: null, runs: 0, total: state.runs, steps: state.steps, running: true });
  $('compare').textContent = 'stop';
  $('compare-status').textContent = '';
  bar.set(0, `0 of ${state.runs} runs`);
  comparer.onmessage = ({ data }) => {
    if (data.type === 'progress') bar.set(data.done / data.total, `${Math.floor(data.done)} of ${data.total} runs`);
    else if (data.type === 'compare') {
      Object.assign(compare, { stats: data.stats, runs: data.runs });
      window.fisstFig3 = { runs: data.runs, total: data.total, stats: data.stats }; // for the page test
      bar.set(data.runs / data.total, `${data.runs} of ${data.total} runs`);
      $('compare-status').textContent = `${(data.ms / 1000).toFixed(1)} s`;
      drawFig3();
      if (data.runs === data.total) stopCompare(`done in ${(data.ms / 1000).toFixed(1)} s`);
    } else if (data.type === 'error') stopCompare(`${data.name}: ${data.message}`);
  };
  comparer.postMessage({ type: 'compare', options: { runs: state.runs, steps: state.steps, seed: state.seed, schemes: SCHEMES, particles: state.particles, futureScans: state.futureScans, alpha: state.alpha } });
}

function stopCompare(text = `stopped after ${compare.runs} runs`) {
  comparer?.terminate();
  comparer = null;
  compare.running = false;
  $('compare').textContent = compare.runs ? 'run the comparison again' : 'run the comparison';
  if (compare.runs === compare.total) bar.done(`${compare.runs} of ${compare.total} runs`);
  $('compare-status').textContent = text;
}

// ---------------------------------------------------------------- controls
const onSetting = (key) => (v) => {
  state[key] = v;
  setPlaying(false);
  restart();
};
state.scheme = choice('scheme', SCHEMES, { value: state.scheme, onChange: onSetting('scheme') }).value;
state.seed = slider('seed', { value: state.seed, onInput: onSetting('seed') }).value;
// The package caps one step's work at N·M ≤ 300,000 (SensorControlRun, four objects): the
// slider of M stops there for the N chosen, and an M above it is lowered to it.
const WORK_CAP = 300_000;
const fitScans = () => {
  const max = Math.min(500, Math.floor(WORK_CAP / state.particles / 10) * 10);
  scans.input.max = String(max);
  if (state.futureScans > max) state.futureScans = scans.set(max);
};
state.particles = slider('particles', { value: state.particles, onInput: (v) => { state.particles = v; fitScans(); onSetting('particles')(v); } }).value;
const scans = slider('future-scans', { value: state.futureScans, onInput: onSetting('futureScans') });
state.futureScans = scans.value;
fitScans();
state.alpha = slider('alpha', { value: state.alpha, format: (v) => fmt(v, 2), onInput: onSetting('alpha') }).value;
state.steps = slider('steps', { value: state.steps, onInput: onSetting('steps') }).value;
state.runs = slider('runs', { value: state.runs, onInput: (v) => { state.runs = v; url.save(); } }).value;
$('play').addEventListener('click', () => {
  if (live.k >= live.steps) return restart();
  setPlaying(!live.playing);
  if (live.playing) requestStep();
});
$('step').addEventListener('click', () => { setPlaying(false); requestStep(); });
$('restart').addEventListener('click', () => { setPlaying(false); restart(); });
$('compare').addEventListener('click', () => (compare.running ? stopCompare() : startCompare()));

const runCSV = () => toCSV(['k', 'ospa', 'localisation', 'cardinality', 'n_hat', 'pr_n_hat'], live.history.map((h) => [h.k, h.distance, h.localisation, h.cardinality, h.n, h.probability]));
const sceneCSV = () => toCSV(['what', 'index', 'object', 'x', 'y', 'value'], [
  ...live.particles.flatMap((p, i) => p.map((x, j) => ['particle', i, j, x[0], x[1], p.length])),
  ...live.sensorPath.map((p, i) => ['sensor', i, null, p[0], p[1], null]),
  ...(live.scanAt ? candidates(live.scanAt).map((c, i) => ['move', i, null, c[0], c[1], live.last.rewards[i]]) : []),
  ...live.measurements.map((z, i) => ['range', i, null, null, null, z]),
  ...live.truth.map((t, i) => ['truth', i, null, t[0], t[1], null]),
  ...(live.last?.estimate.states ?? []).map((e, i) => ['estimate', i, null, e[0], e[1], null]),
]);
downloads($('scene-figure'), { name: () => `control-${state.scheme}-k${live.k}`, png: () => view.canvas, csv: sceneCSV });
downloads($('run-figure'), { name: () => `control-${state.scheme}-ospa`, png: () => runChart.canvas(), csv: runCSV });
for (const [id, part] of [['fig3a', 'distance'], ['fig3b', 'localisation'], ['fig3c', 'cardinality']]) {
  downloads($(`${id}-figure`), { name: `control-fig3-${part}`, png: () => fig3[part].canvas(), csv: () => fig3[part].csv() });
}

view.redraw();
drawFig3();
restart();

// The spooky effect made visible (paper 003). Every number comes from the fisst package.
import init, * as fisst from 'fisst';
import { chart, markX } from './lib/chart.js';
import { cross, dot, sceneView } from './lib/scene.js';
import { $, choice, downloads, fmt, pageReady, slider, timings, toCSV, urlState } from './lib/page.js';

await init();

const css = getComputedStyle(document.documentElement);
// The decision codes u1 + 2·u2: nothing, 1 only, 2 only, both (colour-blind-safe colours in style.css).
const COLOURS = ['--none', '--first', '--second', '--both'].map((v) => css.getPropertyValue(v).trim());
const MAP_RES = 200;
const points = (v) => Array.isArray(v) && v.every((p) => Array.isArray(p) && p.length === 2 && p.every(Number.isFinite));
const url = urlState(
  { r1: 0.4, r2: 0.4, r: 0.3, nmax: 40, n: 10, c: 2, p: 2, mode: 'truth', truth: null, estimate: null },
  { check: { truth: (v) => v === null || points(v), estimate: (v) => v === null || points(v) } },
);
const state = url.values;
const timer = timings('spooky');
timer.badge($('redraw-ms'), { maps: 'six decision maps (first load)', fig3: 'Fig. 3 counts' });

// ---------------------------------------------------------------- Fig. 1 and Fig. 2 maps
const ESTIMATORS = ['gospa', 'ospa', 'uospa', 'mam', 'jom', 'map-cardinality'];
const maps = new Map();

function renderMapImage(estimator) {
  const { decisions, resolution } = fisst.mbDecisionMap({ estimator, resolution: MAP_RES });
  const rgb = COLOURS.map((hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16)));
  const image = document.createElement('canvas');
  image.width = resolution;
  image.height = resolution;
  const ctx = image.getContext('2d');
  const data = ctx.createImageData(resolution, resolution);
  for (let row = 0; row < resolution; row++) {
    // decisions: row index grows with r2; the canvas y axis grows downwards.
    const y = resolution - 1 - row;
    for (let col = 0; col < resolution; col++) {
      const k = 4 * (y * resolution + col);
      data.data.set([...rgb[decisions[row * resolution + col]], 255], k);
    }
  }
  ctx.putImageData(data, 0, 0);
  return { image, decisions, resolution };
}

/** A decision map: click or drag on it to set (r1, r2). */
function mapView(estimator) {
  const view = sceneView($(`map-${estimator}`), {
    width: 240, height: 240, box: { left: 48, top: 8, width: 176, height: 188 }, x: [0, 1], y: [0, 1],
    draw(ctx, v) {
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(maps.get(estimator).image, v.box.left, v.box.top, v.box.width, v.box.height);
      v.axes({ xLabel: 'r₁', yLabel: 'r₂', ticks: 4, format: (t) => t.toFixed(2) });
      ctx.strokeStyle = '#111';
      ctx.lineWidth = 2;
      cross(ctx, v.px(state.r1), v.py(state.r2), 7, false);
    },
    drag: {
      hit: () => 'point',
      start: (_, point) => setExistence(point),
      move: (_, { point }) => setExistence(point),
    },
  });
  downloads($(`map-${estimator}`).parentElement, {
    name: `spooky-${estimator}`,
    png: () => view.canvas,
    csv: () => {
      const { decisions, resolution: n } = maps.get(estimator);
      // Cell centres of the grid the package evaluates.
      return toCSV(['r1', 'r2', 'report1', 'report2'], Array.from(decisions, (d, k) => [((k % n) + 0.5) / n, (Math.floor(k / n) + 0.5) / n, d & 1, d >> 1]));
    },
  });
  return view;
}

const describe = (report) => {
  const on = report.map((u, i) => (u ? i + 1 : 0)).filter(Boolean);
  return on.length === 0 ? 'report nothing' : `report ${on.join(' and ')}`;
};

function setExistence([r1, r2]) {
  state.r1 = r1Slider.set(Math.min(Math.max(r1, 0), 1));
  state.r2 = r2Slider.set(Math.min(Math.max(r2, 0), 1));
  updateTwoTargets();
}

function updateTwoTargets() {
  const existence = [state.r1, state.r2];
  for (const metric of ['gospa', 'ospa', 'uospa']) {
    const { report, meanSquareError } = fisst.mbOptimalEstimate({ existence, metric });
    $(`decision-${metric}`).textContent = describe(report);
    $(`mse-${metric}`).textContent = fmt(meanSquareError, 4);
  }
  for (const method of ['mam', 'jom', 'map-cardinality']) {
    $(`decision-${method}`).textContent = describe(fisst.mbAlternativeEstimate({ existence, method }).report);
  }
  for (const v of mapViews) v.redraw();
  url.save();
}

// ---------------------------------------------------------------- Example 5
const STORY = {
  before: { r2: 0.4, text: 'Both potential targets exist with probability 0.4. GOSPA reports neither (each r < 1/2), but the optimal OSPA estimate reports both: {ospa}.' },
  case1: { r2: 0.9, text: 'A measurement from Liverpool raises r₂ to 0.9 and says nothing about Madrid. OSPA now {ospa}: Madrid is dropped although the expected number of targets went up. GOSPA: {gospa}.' },
  case2: { r2: 0.1, text: 'Liverpool is not seen: r₂ falls to 0.1, Madrid unchanged. OSPA now {ospa} — Madrid disappears because of an event hundreds of kilometres away. GOSPA: {gospa}.' },
};

function story(step) {
  setExistence([0.4, STORY[step].r2]);
  $('story').textContent = STORY[step].text
    .replace('{ospa}', $('decision-ospa').textContent)
    .replace('{gospa}', $('decision-gospa').textContent);
}

// ---------------------------------------------------------------- Fig. 3
const SERIES = [
  { key: 'gospa', label: 'GOSPA', colour: '#009e73' },
  { key: 'ospa', label: 'OSPA', colour: '#d55e00' },
  { key: 'uospa', label: 'UOSPA', colour: '#0072b2', dash: [6, 3] },
  { key: 'mapCardinality', label: 'max cardinality', colour: '#cc79a7', dash: [2, 3] },
];
let counts = null;
let fig3 = null;
/** Fig. 3's chart, made on its first draw (after the maps: the first figure comes sooner). */
const makeFig3 = () => chart($('fig3'), {
  height: 280,
  x: { label: 'number of Bernoulli components n', range: () => [0, state.nmax], integer: true, format: String },
  y: { label: 'targets reported', range: () => [0, state.nmax], integer: true, format: String },
  series: SERIES.map((s) => ({ label: s.label, colour: s.colour, dash: s.dash, value: String })),
  overlay: (o) => markX(o, state.n, { colour: '#9aa5b1', dash: [1, 3], width: 1 }),
});

function updateFig3(recompute) {
  nSlider.input.max = String(state.nmax);
  state.n = nSlider.set(Math.min(state.n, state.nmax));
  if (recompute || !counts) counts = timer.time('fig3', () => fisst.mbIdenticalComponentCounts({ existence: state.r, maxComponents: state.nmax }));
  $('fig3-gospa').textContent = counts.gospa[state.n - 1];
  $('fig3-ospa').textContent = counts.ospa[state.n - 1];
  $('fig3-uospa').textContent = counts.uospa[state.n - 1];
  $('fig3-map').textContent = counts.mapCardinality[state.n - 1];
  fig3 ??= makeFig3();
  fig3.update([counts.n, ...SERIES.map((s) => counts[s.key])]);
  timer.show();
  url.save();
}

// ---------------------------------------------------------------- GOSPA playground
const pg = { truth: state.truth ?? [], estimate: state.estimate ?? [] };
const playground = sceneView($('playground'), {
  width: 480, height: 480, box: { left: 0, top: 0, width: 480, height: 480 }, x: [0, 10], y: [0, 10], draw: drawPlayground,
});

function randomScene(seed) {
  // mulberry32, so the scene is the same every time for a seed
  let s = seed >>> 0;
  const rand = () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 2 ** 32;
  };
  pg.truth = Array.from({ length: 5 }, () => [1 + 8 * rand(), 1 + 8 * rand()]);
  pg.estimate = pg.truth.filter(() => rand() > 0.25).map(([a, b]) => [a + (rand() - 0.5) * 1.6, b + (rand() - 0.5) * 1.6]);
  pg.estimate.push([1 + 8 * rand(), 1 + 8 * rand()]);
}

let gospa = null;
function updatePlayground() {
  const { c, p } = state;
  gospa = fisst.gospa(pg.truth, pg.estimate, { c, p });
  const o = fisst.ospa(pg.truth, pg.estimate, { c, p });
  $('gospa-distance').textContent = fmt(gospa.distance, 4);
  $('gospa-localisation').textContent = fmt(gospa.localisation, 4);
  $('gospa-missed').textContent = gospa.missed;
  $('gospa-false').textContent = gospa.falseTargets;
  $('ospa-distance').textContent = `${fmt(o.distance, 4)} (${fmt(o.localisation, 3)}, ${fmt(o.cardinality, 3)})`;
  $('pg-points').textContent = JSON.stringify({ truth: pg.truth, estimate: pg.estimate, c, p });
  [state.truth, state.estimate] = [pg.truth, pg.estimate];
  playground.redraw();
  url.save();
}

function drawPlayground(ctx, { px, py }) {
  const assignedTruth = new Set(gospa.assignment.map(([i]) => i));
  const assignedEstimate = new Set(gospa.assignment.map(([, j]) => j));
  ctx.fillStyle = 'rgba(0, 114, 178, 0.05)'; // cut-off discs around the truth
  for (const [a, b] of pg.truth) {
    ctx.beginPath();
    ctx.arc(px(a), py(b), px(state.c) - px(0), 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.strokeStyle = '#52606d';
  ctx.lineWidth = 1.5;
  for (const [i, j] of gospa.assignment) {
    ctx.beginPath();
    ctx.moveTo(px(pg.truth[i][0]), py(pg.truth[i][1]));
    ctx.lineTo(px(pg.estimate[j][0]), py(pg.estimate[j][1]));
    ctx.stroke();
  }
  pg.truth.forEach(([a, b], i) => {
    dot(ctx, px(a), py(b), 5, '#1f2933');
    if (!assignedTruth.has(i)) {
      ctx.beginPath();
      ctx.arc(px(a), py(b), 10, 0, 2 * Math.PI);
      ctx.strokeStyle = '#d55e00';
      ctx.lineWidth = 2;
      ctx.stroke();
    }
  });
  pg.estimate.forEach(([a, b], j) => {
    ctx.strokeStyle = assignedEstimate.has(j) ? '#0072b2' : '#e69f00';
    ctx.lineWidth = assignedEstimate.has(j) ? 2 : 3;
    cross(ctx, px(a), py(b), 6);
  });
  ctx.fillStyle = '#616e7c';
  ctx.font = '12px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'alphabetic';
  ctx.fillText('● truth  ✕ estimate  ○ missed (vermillion)  ✕ false (orange)  — assigned', 8, 16);
}

// ---------------------------------------------------------------- wiring
const f3 = (digits) => (v) => v.toFixed(digits);
const r1Slider = slider('r1', { value: state.r1, format: f3(3), onInput: (v) => { state.r1 = v; updateTwoTargets(); } });
const r2Slider = slider('r2', { value: state.r2, format: f3(3), onInput: (v) => { state.r2 = v; updateTwoTargets(); } });
[state.r1, state.r2] = [r1Slider.value, r2Slider.value];
for (const step of Object.keys(STORY)) $(`story-${step}`).addEventListener('click', () => story(step));
state.r = slider('fig3-r', { value: state.r, format: f3(2), onInput: (v) => { state.r = v; updateFig3(true); } }).value;
state.nmax = slider('fig3-nmax', { value: state.nmax, onInput: (v) => { state.nmax = v; updateFig3(true); } }).value;
const nSlider = slider('fig3-n', { value: state.n, onInput: (v) => { state.n = v; updateFig3(false); } });
state.c = slider('pg-c', { value: state.c, format: f3(2), onInput: (v) => { state.c = v; updatePlayground(); } }).value;
state.p = slider('pg-p', { value: state.p, format: f3(1), onInput: (v) => { state.p = v; updatePlayground(); } }).value;
state.mode = choice('mode', ['truth', 'estimate'], { value: state.mode, onChange: (m) => { state.mode = m; url.save(); } }).value;
$('pg-random').addEventListener('click', () => {
  randomScene(Date.now() % 100000);
  updatePlayground();
});
$('pg-clear').addEventListener('click', () => {
  pg.truth = [];
  pg.estimate = [];
  updatePlayground();
});
$('playground').addEventListener('click', (event) => {
  const kind = event.shiftKey ? (state.mode === 'truth' ? 'estimate' : 'truth') : state.mode;
  pg[kind].push(playground.toData(event));
  updatePlayground();
});
$('playground').addEventListener('contextmenu', (event) => {
  event.preventDefault();
  const [a, b] = playground.toData(event);
  let best = null;
  for (const kind of ['truth', 'estimate']) {
    pg[kind].forEach(([x, y], i) => {
      const d = Math.hypot(x - a, y - b);
      if (!best || d < best.d) best = { kind, i, d };
    });
  }
  if (best) pg[best.kind].splice(best.i, 1);
  updatePlayground();
});
downloads($('fig3-figure'), { name: 'spooky-fig3', png: () => fig3.canvas(), csv: () => fig3.csv() });
downloads($('playground-figure'), {
  name: 'spooky-gospa',
  png: () => playground.canvas,
  csv: () => toCSV(['kind', 'x', 'y'], [...pg.truth.map((q) => ['truth', ...q]), ...pg.estimate.map((q) => ['estimate', ...q])]),
});

const mapViews = timer.time('maps', () => ESTIMATORS.map((e) => {
  maps.set(e, renderMapImage(e));
  return mapView(e);
}));
updateTwoTargets();
updateFig3(true);
timer.show();
if (state.truth === null) randomScene(7);
updatePlayground();
pageReady();

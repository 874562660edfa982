// Sensor placement by field-of-view count variance (paper 001, Section VII, Figs 9–10).
// Every number comes from the fisst package: the scene, the PHD, the variance map and its
// argmax, and the count pmf of the dragged FoV. This file only says what to compute and draw.
import init, * as fisst from 'fisst';
import { chart, markX } from './lib/chart.js';
import { clipTo, sceneView, starPath } from './lib/scene.js';
import { colorbar, heatImage } from './lib/colormap.js';
import { $, choice, downloads, fmt, msText, pageReady, pointText, slider, timings, toCSV, urlState } from './lib/page.js';

await init();

// FoV centres (and PHD positions): 121 × 121 points on [−3, 3]².
const EXTENT = 3;
const GRID_COUNT = 121;
const GRID = { x: [-EXTENT, EXTENT, GRID_COUNT], y: [-EXTENT, EXTENT, GRID_COUNT] };
// The grid step exactly as the package computes it ((max − min)/(count − 1)): FoV sides that
// are whole multiples of it let the map share corners between neighbouring FoVs (~2.7× faster).
const STEP = (GRID.x[1] - GRID.x[0]) / (GRID.x[2] - 1);
const centre = (i) => GRID.x[0] + i * STEP;
const largest = (values) => values.reduce((a, b) => Math.max(a, b), 0);
const clamp = (v) => Math.min(Math.max(v, -EXTENT), EXTENT);
const LAYERS = { phd: { map: 'viridis', label: 'PHD Σ r<sub>i</sub> N(x; m<sub>i</sub>, P<sub>i</sub>)' }, variance: { map: 'cividis', label: 'Var[|X ∩ S|] of a FoV centred there' } };

// The settings (in the URL); the FoV starts at the grid point nearest (−1, 1), away from the optimum.
const url = urlState(
  { count: 100, seed: 1, side: 1, layer: 'phd', fov: [centre(40), centre(80)] },
  { check: { fov: (f) => Array.isArray(f) && f.length === 2 && f.every((v) => Number.isFinite(v) && Math.abs(v) <= EXTENT) } },
);
const state = url.values;
const result = { scene: null, phd: null, map: null, card: null, images: {} };
const timer = timings('placement');
timer.badge($('redraw-ms'), { phd: 'PHD (last new scene)', map: 'variance map (last new size)', total: 'last update' });

/** The FoV side snapped to a whole number of grid steps, computed as k · STEP like the grid. */
const snap = (side) => Math.min(Math.max(Math.round(side / STEP), 1), 2 * (GRID_COUNT - 1)) * STEP;
const fovSide = () => snap(state.side);
function fovBox([cx, cy]) {
  const h = fovSide() / 2;
  return { min: [cx - h, cy - h], max: [cx + h, cy + h] };
}

// ---------------------------------------------------------------- the scene view
// The heat images' pixels are centred on the grid points: the view spans half a step more.
const HALF = EXTENT + STEP / 2;
const drag = { origin: null };
const view = sceneView($('scene'), {
  width: 520, height: 520, box: { left: 48, top: 10, width: 460, height: 460 }, x: [-HALF, HALF], y: [-HALF, HALF],
  draw: drawScene,
  drag: {
    // A press inside the FoV grabs it where it is; elsewhere it moves the FoV's centre there.
    hit: () => 'fov',
    start(_, [x, y]) {
      const { min, max } = fovBox(state.fov);
      const inside = x >= min[0] && x <= max[0] && y >= min[1] && y <= max[1];
      drag.origin = inside ? [...state.fov] : [x, y];
      moveFov(drag.origin[0], drag.origin[1]);
    },
    move(_, { point, start }) {
      moveFov(drag.origin[0] + point[0] - start[0], drag.origin[1] + point[1] - start[1]);
    },
  },
});
const bar = colorbar($('scene-legend'), { format: (v) => fmt(v, 3) });

function strokeBox(ctx, { min, max }, style, width, dash) {
  ctx.strokeStyle = style;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.strokeRect(view.px(min[0]), view.py(max[1]), view.px(max[0]) - view.px(min[0]), view.py(min[1]) - view.py(max[1]));
  ctx.setLineDash([]);
}

function drawScene(ctx, v) {
  const { px, py, box } = v;
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(result.images[state.layer], box.left, box.top, box.width, box.height);
  v.axes({ xLabel: 'x', yLabel: 'y', ticks: 8 });
  ctx.save();
  clipTo(ctx, box);
  ctx.strokeStyle = '#f59e0b';
  ctx.lineWidth = 1.5;
  for (const c of result.scene) {
    ctx.globalAlpha = 0.35 + 0.65 * c.existence;
    ctx.beginPath();
    ctx.arc(px(c.mean[0]), py(c.mean[1]), 3.5, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
  const [ax, ay] = result.map.argmax;
  strokeBox(ctx, fovBox([ax, ay]), '#ffffff', 2, [6, 4]);
  starPath(ctx, px(ax), py(ay), 9);
  ctx.fillStyle = '#d55e00';
  ctx.fill();
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = 1;
  ctx.stroke();
  strokeBox(ctx, fovBox(state.fov), '#22d3ee', 2.5, []);
  ctx.fillStyle = '#22d3ee';
  ctx.beginPath();
  ctx.arc(px(state.fov[0]), py(state.fov[1]), 3, 0, 2 * Math.PI);
  ctx.fill();
  ctx.restore();
}

// ---------------------------------------------------------------- the pmf bar chart
let pmfMax = 4;
let pmfChart = null;
/** The pmf chart, made on its first draw (after the scene: the first figure comes sooner). */
const makePmfChart = () => chart($('pmf'), {
  height: 220,
  x: { label: 'n objects in your FoV', range: () => [-0.5, pmfMax + 0.5], integer: true, format: String },
  y: { label: 'probability', range: (lo, hi) => [0, Math.max(0.1, Math.ceil(hi * 10) / 10)], format: (v) => fmt(v, 3) },
  series: [{ label: 'P(|X ∩ S| = n)', colour: '#0072b2', fill: '#0072b2', bars: true, width: 0 }],
  overlay: (o) => result.card && markX(o, result.card.mean, { colour: '#d55e00', text: `mean ${fmt(result.card.mean, 3)}` }),
});

function drawPmf() {
  const { pmf, mean, variance } = result.card;
  // Show n up to where the pmf is negligible (and at least to mean + 4 sd).
  let last = 0;
  pmf.forEach((p, n) => { if (p > 1e-4) last = n; });
  const nMax = Math.min(pmf.length - 1, Math.max(last, Math.ceil(mean + 4 * Math.sqrt(variance)), 4));
  const ns = Array.from({ length: nMax + 1 }, (_, n) => n);
  pmfMax = nMax;
  pmfChart ??= makePmfChart();
  pmfChart.update([ns, ns.map((n) => pmf[n])]);
}

// ---------------------------------------------------------------- computations (all fisst)
function computeScene() {
  result.scene = fisst.placementScene({ count: state.count, seed: state.seed, extent: EXTENT }).multiBernoulli;
  const mixture = result.scene.map((c) => ({ weight: c.existence, mean: c.mean, cov: c.cov }));
  result.phd = timer.time('phd', () => fisst.mixtureDensityGrid({ mixture, grid: GRID }));
  result.images.phd = heatImage(result.phd, GRID_COUNT, GRID_COUNT, { map: LAYERS.phd.map });
}

function computeMap() {
  const options = { multiBernoulli: result.scene, fovSize: [fovSide(), fovSide()], grid: GRID };
  result.map = timer.time('map', () => fisst.fovVarianceMap(options));
  result.images.variance = heatImage(result.map.variance, GRID_COUNT, GRID_COUNT, { map: LAYERS.variance.map, vmax: result.map.max });
  const [ax, ay] = result.map.argmax;
  $('map-argmax').textContent = `(${ax.toFixed(2)}, ${ay.toFixed(2)})`;
  $('map-max').textContent = fmt(result.map.max, 6);
  $('map-time').textContent = msText(timer.last.map);
}

function computeFov() {
  result.card = fisst.fovCardinality({ rfs: { multiBernoulli: result.scene }, fov: { box: fovBox(state.fov) } });
  $('fov-center').textContent = pointText(state.fov);
  $('fov-mean').textContent = fmt(result.card.mean, 6);
  $('fov-variance').textContent = fmt(result.card.variance, 6);
  $('fov-empty').textContent = fmt(result.card.pmf[0], 6);
}

function render() {
  const layer = LAYERS[state.layer];
  bar.update({ map: layer.map, label: layer.label, max: state.layer === 'phd' ? largest(result.phd) : result.map.max });
  view.redraw();
  drawPmf();
  $('placement-state').textContent = JSON.stringify({
    scene: { count: state.count, seed: state.seed, extent: EXTENT },
    grid: GRID,
    fovSize: [fovSide(), fovSide()],
    fov: { center: state.fov, box: fovBox(state.fov), mean: result.card.mean, variance: result.card.variance },
    map: { argmax: result.map.argmax, max: result.map.max, ms: timer.last.map },
    layer: state.layer,
    view: { box: view.box, ...view.domain() },
  }, null, 1);
  url.save();
}

/** Recomputes what `what` changed (scene ⊃ map ⊃ fov) and redraws. */
function update(what) {
  timer.time('total', () => {
    if (what === 'scene') computeScene();
    if (what === 'scene' || what === 'map') computeMap();
    if (what !== 'layer') computeFov();
    render();
  });
  timer.show();
}

function moveFov(x, y) {
  state.fov = [clamp(x), clamp(y)];
  update('fov');
}

// ---------------------------------------------------------------- controls
state.count = slider('count', { value: state.count, onInput: (v) => { state.count = v; update('scene'); } }).value;
state.seed = slider('seed', { value: state.seed, onInput: (v) => { state.seed = v; update('scene'); } }).value;
state.side = slider('fov-size', { value: state.side, format: (v) => fmt(snap(v), 3), onInput: (v) => { state.side = v; update('map'); } }).value;
state.layer = choice('layer', Object.keys(LAYERS), { value: state.layer, onChange: (v) => { state.layer = v; update('layer'); } }).value;
$('fov-to-optimum').addEventListener('click', () => moveFov(...result.map.argmax));
downloads($('scene-figure'), {
  name: () => `placement-${state.layer}`,
  png: () => view.canvas,
  csv: () => {
    const values = state.layer === 'phd' ? result.phd : result.map.variance;
    return toCSV(['x', 'y', state.layer], Array.from(values, (v, k) => [centre(k % GRID_COUNT), centre(Math.floor(k / GRID_COUNT)), v]));
  },
});
downloads($('pmf-figure'), { name: 'placement-pmf', png: () => pmfChart.canvas(), csv: () => pmfChart.csv() });

update('scene');
pageReady();

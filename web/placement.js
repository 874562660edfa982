// Sensor placement by field-of-view count variance (paper 001, Section VII, Figs 9–10).
// Every number comes from the fisst package: the scene, the PHD, the variance map and its
// argmax, and the count pmf of the dragged FoV. This file only draws and wires controls.
import init, * as fisst from 'fisst';
import { setupCanvas, scale, drawAxes, ticks, fmt } from './lib/plot.js';

await init();

const $ = (id) => document.getElementById(id);

// FoV centres (and PHD positions): 121 × 121 points on [−3, 3]², as in `grid` below.
const EXTENT = 3;
const GRID_COUNT = 121;
const GRID = { x: [-EXTENT, EXTENT, GRID_COUNT], y: [-EXTENT, EXTENT, GRID_COUNT] };
// The grid step exactly as the package computes it ((max − min)/(count − 1)): FoV sides that
// are whole multiples of it let the map share corners between neighbouring FoVs (~2.7× faster).
const STEP = (GRID.x[1] - GRID.x[0]) / (GRID.x[2] - 1);
const centre = (i) => GRID.x[0] + i * STEP;
const largest = (values) => values.reduce((a, b) => Math.max(a, b), 0);

// ---------------------------------------------------------------- colour maps (display only)
const VIRIDIS = ['#440154', '#482878', '#3e4989', '#31688e', '#26828e', '#1f9e89', '#35b779', '#6ece58', '#b5de2b', '#fde725'];
const INFERNO = ['#000004', '#1b0c41', '#4a0c6b', '#781c6d', '#a52c60', '#cf4446', '#ed6925', '#fb9b06', '#f7d13d', '#fcffa4'];
const rgb = (hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
const PALETTES = { phd: VIRIDIS.map(rgb), variance: INFERNO.map(rgb) };

function colour(palette, t) {
  const u = Math.min(Math.max(t, 0), 1) * (palette.length - 1);
  const k = Math.min(Math.floor(u), palette.length - 2);
  const f = u - k;
  return palette[k].map((c, i) => Math.round(c + f * (palette[k + 1][i] - c)));
}

/** A GRID_COUNT² image of row-major values (y outer, growing upwards) under a palette. */
function heatImage(values, palette, vmax) {
  const n = GRID_COUNT;
  const image = document.createElement('canvas');
  image.width = n;
  image.height = n;
  const ctx = image.getContext('2d');
  const data = ctx.createImageData(n, n);
  for (let j = 0; j < n; j++) {
    const row = n - 1 - j; // canvas rows grow downwards
    for (let i = 0; i < n; i++) {
      const [r, g, b] = colour(palette, vmax > 0 ? values[j * n + i] / vmax : 0);
      const k = 4 * (row * n + i);
      data.data[k] = r;
      data.data[k + 1] = g;
      data.data[k + 2] = b;
      data.data[k + 3] = 255;
    }
  }
  ctx.putImageData(data, 0, 0);
  return image;
}

// ---------------------------------------------------------------- state
const state = {
  count: 100,
  seed: 1,
  fovSide: 1,
  layer: 'phd',
  scene: null, // placementScene(...).multiBernoulli
  phd: null, // Float64Array
  map: null, // fovVarianceMap result
  fov: [0, 0], // centre of the user's FoV
  card: null, // fovCardinality result for the user's FoV
  images: {},
};
const timing = { lastMapMs: null, mapTimes: [], lastPhdMs: null };
window.fisstPlacement = timing;

// ---------------------------------------------------------------- the scene canvas
const VIEW = { width: 600, height: 520, box: { left: 48, top: 10, width: 460, height: 460 } };
// The heat images' pixels are centred on the grid points: the view spans half a step more.
const LO = -EXTENT - STEP / 2;
const HI = EXTENT + STEP / 2;
const { box } = VIEW;
const px = scale(LO, HI, box.left, box.left + box.width);
const py = scale(LO, HI, box.top + box.height, box.top);
const sceneCtx = setupCanvas($('scene'), VIEW.width, VIEW.height);

function fovBox([cx, cy]) {
  const h = state.fovSide / 2;
  return { min: [cx - h, cy - h], max: [cx + h, cy + h] };
}

function strokeBox(ctx, { min, max }, style, width, dash) {
  ctx.save();
  ctx.strokeStyle = style;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.strokeRect(px(min[0]), py(max[1]), px(max[0]) - px(min[0]), py(min[1]) - py(max[1]));
  ctx.restore();
}

function star(ctx, x, y, r) {
  ctx.beginPath();
  for (let k = 0; k < 10; k++) {
    const a = -Math.PI / 2 + (k * Math.PI) / 5;
    const rr = k % 2 === 0 ? r : r * 0.45;
    ctx.lineTo(x + rr * Math.cos(a), y + rr * Math.sin(a));
  }
  ctx.closePath();
}

function drawScene() {
  const ctx = sceneCtx;
  ctx.clearRect(0, 0, VIEW.width, VIEW.height);
  const values = state.layer === 'phd' ? state.phd : state.map.variance;
  const vmax = state.layer === 'phd' ? largest(state.phd) : state.map.max;
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(state.images[state.layer], box.left, box.top, box.width, box.height);
  drawAxes(ctx, box, px, py, {
    xTicks: ticks(-3, 3, 6), yTicks: ticks(-3, 3, 6), xLabel: 'x', yLabel: 'y', fmt: (v) => v.toFixed(0),
  });
  // colour bar
  const bar = { left: box.left + box.width + 16, top: box.top, width: 12, height: box.height };
  const palette = PALETTES[state.layer];
  for (let k = 0; k < bar.height; k++) {
    const [r, g, b] = colour(palette, 1 - k / (bar.height - 1));
    ctx.fillStyle = `rgb(${r},${g},${b})`;
    ctx.fillRect(bar.left, bar.top + k, bar.width, 1);
  }
  ctx.fillStyle = '#52606d';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'top';
  ctx.fillText(fmt(vmax, 3), bar.left + bar.width + 4, bar.top);
  ctx.textBaseline = 'bottom';
  ctx.fillText('0', bar.left + bar.width + 4, bar.top + bar.height);
  ctx.save();
  ctx.translate(bar.left + bar.width + 14, bar.top + bar.height / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = 'center';
  ctx.fillText(state.layer === 'phd' ? 'PHD' : 'Var[|X ∩ S|]', 0, 0);
  ctx.restore();
  // everything else is clipped to the plot box
  ctx.save();
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.clip();
  ctx.strokeStyle = '#f59e0b';
  ctx.lineWidth = 1.5;
  for (const c of state.scene) {
    ctx.globalAlpha = 0.35 + 0.65 * c.existence;
    ctx.beginPath();
    ctx.arc(px(c.mean[0]), py(c.mean[1]), 3.5, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
  const [ax, ay] = state.map.argmax;
  strokeBox(ctx, fovBox([ax, ay]), '#ffffff', 2, [6, 4]);
  star(ctx, px(ax), py(ay), 9);
  ctx.fillStyle = '#dc2626';
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
const PMF = { width: 380, height: 210, box: { left: 48, top: 10, width: 316, height: 150 } };
const pmfCtx = setupCanvas($('pmf'), PMF.width, PMF.height);

function drawPmf() {
  const ctx = pmfCtx;
  const { pmf, mean, variance } = state.card;
  ctx.clearRect(0, 0, PMF.width, PMF.height);
  // Show n up to where the pmf is negligible (and at least to mean + 4 sd).
  let last = 0;
  pmf.forEach((p, n) => { if (p > 1e-4) last = n; });
  const nMax = Math.min(pmf.length - 1, Math.max(last, Math.ceil(mean + 4 * Math.sqrt(variance)), 4));
  const top = Math.max(0.1, Math.ceil(Math.max(...pmf) * 10) / 10);
  const yStep = top <= 0.3 ? 0.05 : top <= 0.6 ? 0.1 : 0.2;
  const b = PMF.box;
  const x = scale(-0.5, nMax + 0.5, b.left, b.left + b.width);
  const y = scale(0, top, b.top + b.height, b.top);
  const step = Math.max(1, Math.ceil(nMax / 10));
  drawAxes(ctx, b, x, y, {
    xTicks: Array.from({ length: Math.floor(nMax / step) + 1 }, (_, k) => k * step),
    yTicks: ticks(0, top, Math.round(top / yStep)), xLabel: 'n objects in your FoV', yLabel: 'probability',
    fmt: (v) => fmt(v, 2),
  });
  const w = Math.max(1, (x(1) - x(0)) * 0.8);
  ctx.fillStyle = '#2563eb';
  for (let n = 0; n <= nMax; n++) {
    ctx.fillRect(x(n) - w / 2, y(pmf[n]), w, y(0) - y(pmf[n]));
  }
  ctx.strokeStyle = '#dc2626';
  ctx.setLineDash([4, 3]);
  ctx.beginPath();
  ctx.moveTo(x(mean), b.top);
  ctx.lineTo(x(mean), b.top + b.height);
  ctx.stroke();
  ctx.setLineDash([]);
}

// ---------------------------------------------------------------- computations (all fisst)
function computeScene() {
  state.scene = fisst.placementScene({ count: state.count, seed: state.seed, extent: EXTENT }).multiBernoulli;
  const mixture = state.scene.map((c) => ({ weight: c.existence, mean: c.mean, cov: c.cov }));
  const t0 = performance.now();
  state.phd = fisst.mixtureDensityGrid({ mixture, grid: GRID });
  timing.lastPhdMs = performance.now() - t0;
  state.images.phd = heatImage(state.phd, PALETTES.phd, largest(state.phd));
}

function computeMap() {
  const options = { multiBernoulli: state.scene, fovSize: [state.fovSide, state.fovSide], grid: GRID };
  const t0 = performance.now();
  state.map = fisst.fovVarianceMap(options);
  const ms = performance.now() - t0;
  timing.lastMapMs = ms;
  timing.mapTimes.push(ms);
  state.images.variance = heatImage(state.map.variance, PALETTES.variance, state.map.max);
  const [ax, ay] = state.map.argmax;
  $('map-argmax').textContent = `(${ax.toFixed(2)}, ${ay.toFixed(2)})`;
  $('map-max').textContent = fmt(state.map.max, 6);
  $('map-time').textContent = `${ms.toFixed(1)} ms`;
}

function computeFov() {
  state.card = fisst.fovCardinality({ rfs: { multiBernoulli: state.scene }, fov: { box: fovBox(state.fov) } });
  const [cx, cy] = state.fov;
  $('fov-center').textContent = `(${cx.toFixed(3)}, ${cy.toFixed(3)})`;
  $('fov-mean').textContent = fmt(state.card.mean, 6);
  $('fov-variance').textContent = fmt(state.card.variance, 6);
  $('fov-empty').textContent = fmt(state.card.pmf[0], 6);
}

function publish() {
  $('placement-state').textContent = JSON.stringify({
    scene: { count: state.count, seed: state.seed, extent: EXTENT },
    grid: GRID,
    fovSize: [state.fovSide, state.fovSide],
    fov: { center: state.fov, box: fovBox(state.fov), mean: state.card.mean, variance: state.card.variance },
    map: { argmax: state.map.argmax, max: state.map.max, ms: timing.lastMapMs },
    layer: state.layer,
    view: { box, domain: [LO, HI] },
  }, null, 1);
}

function render() {
  drawScene();
  drawPmf();
  publish();
}

// ---------------------------------------------------------------- controls
function readControls() {
  state.count = Number($('count').value);
  state.seed = Number($('seed').value);
  // Snap the side to a whole number of grid steps, computed as k · STEP like the grid.
  const k = Math.min(Math.max(Math.round(Number($('fov-size').value) / STEP), 1), 2 * (GRID_COUNT - 1));
  state.fovSide = k * STEP;
  $('count-out').value = state.count;
  $('seed-out').value = state.seed;
  $('fov-size-out').value = fmt(state.fovSide, 3);
}

function onSceneInput() {
  readControls();
  computeScene();
  computeMap();
  computeFov();
  render();
}

function onSizeInput() {
  readControls();
  computeMap();
  computeFov();
  render();
}

function setLayer(layer) {
  state.layer = layer;
  $('layer-phd').setAttribute('aria-pressed', String(layer === 'phd'));
  $('layer-variance').setAttribute('aria-pressed', String(layer === 'variance'));
  render();
}

function moveFov(x, y) {
  const clamp = (v) => Math.min(Math.max(v, -EXTENT), EXTENT);
  state.fov = [clamp(x), clamp(y)];
  computeFov();
  render();
}

// Dragging: pointer events cover mouse, pen and touch. Grabbing inside the FoV keeps the
// grab offset; pressing elsewhere moves the FoV's centre to the pointer.
const drag = { id: null, offset: [0, 0] };
const canvas = $('scene');

function worldPoint(event) {
  // The canvas may be drawn smaller than its layout size on narrow screens (max-width: 100%).
  const rect = canvas.getBoundingClientRect();
  const sx = VIEW.width / rect.width;
  const sy = VIEW.height / rect.height;
  return [px.invert((event.clientX - rect.left) * sx), py.invert((event.clientY - rect.top) * sy)];
}

canvas.addEventListener('pointerdown', (event) => {
  if (drag.id !== null) return;
  const [x, y] = worldPoint(event);
  const { min, max } = fovBox(state.fov);
  const inside = x >= min[0] && x <= max[0] && y >= min[1] && y <= max[1];
  drag.offset = inside ? [state.fov[0] - x, state.fov[1] - y] : [0, 0];
  drag.id = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  canvas.classList.add('dragging');
  event.preventDefault();
  moveFov(x + drag.offset[0], y + drag.offset[1]);
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== drag.id) return;
  const [x, y] = worldPoint(event);
  moveFov(x + drag.offset[0], y + drag.offset[1]);
});
const endDrag = (event) => {
  if (event.pointerId !== drag.id) return;
  drag.id = null;
  canvas.classList.remove('dragging');
  if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
};
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

$('count').addEventListener('input', onSceneInput);
$('seed').addEventListener('input', onSceneInput);
$('fov-size').addEventListener('input', onSizeInput);
$('layer-phd').addEventListener('click', () => setLayer('phd'));
$('layer-variance').addEventListener('click', () => setLayer('variance'));
$('fov-to-optimum').addEventListener('click', () => moveFov(...state.map.argmax));

// The user's FoV starts at the grid point nearest (−1, 1), away from the optimum.
state.fov = [centre(40), centre(80)];
onSceneInput();
document.body.dataset.ready = 'true';

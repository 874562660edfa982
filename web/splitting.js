// Recursive Gaussian splitting along region boundaries and the negative-information filter
// (paper 001, "Split happens!", Section IV, Figs 2–5). Every number comes from the fisst
// package: the split mixture, which components lie in S, the partition masses, the exact
// mass, the split library, the density images and the Fig. 5 filter. This file only builds
// inputs from the controls and says what to draw.
import init, * as fisst from 'fisst';
import { clipTo, drawMixture, ellipsePath, sceneView } from './lib/scene.js';
import { cellCounts, cellGrid, colorbar, heatImage } from './lib/colormap.js';
import { drawHandles, handles, insideRegion, kindOf, labelAnchor, regionPath, reshape, translate, validRegions } from './lib/regions.js';
import { $, choice, downloads, fmt, msText, pageReady, select, slider, timings, toCSV, urlState } from './lib/page.js';

await init();

const css = getComputedStyle(document.documentElement);
const colour = (name) => css.getPropertyValue(name).trim();
const COLOUR = { inside: colour('--split-inside'), outside: colour('--split-outside'), first: colour('--region-first'), other: colour('--region-other'), input: '#111827' };

// ---------------------------------------------------------------- presets
// Components are kept as (weight, mean, principal σs, orientation in degrees); the covariance
// follows from them.
const MIXTURES = {
  one: () => [{ weight: 1, mean: [-0.8, 0.4], sigma: [1.2, 0.5], angle: 35 }],
  three: () => [
    { weight: 0.5, mean: [-1.4, 1.1], sigma: [1.1, 0.45], angle: 20 },
    { weight: 0.3, mean: [1.3, -0.9], sigma: [0.8, 0.6], angle: -40 },
    { weight: 0.2, mean: [0.6, 2.4], sigma: [0.7, 0.3], angle: 75 },
  ],
};

function newRegion(kind, [cx, cy]) {
  if (kind === 'box') return { box: { min: [cx - 1, cy - 0.75], max: [cx + 1, cy + 0.75] } };
  if (kind === 'disc') return { disc: { center: [cx, cy], radius: 0.9 } };
  // An irregular, non-convex pentagon.
  const shape = [[1.2, 0], [0.35, 0.35], [0.3, 1.1], [-1, 0.5], [-0.6, -0.9]];
  return { polygon: shape.map(([x, y]) => [cx + x, cy + y]) };
}

const REGIONS = {
  box: () => [{ box: { min: [-0.5, -1.8], max: [2.5, 1.5] } }],
  several: () => [{ box: { min: [-0.5, -1.8], max: [2.5, 1.5] } }, newRegion('polygon', [-2.3, -1.6]), { disc: { center: [-1.6, 2.1], radius: 1 } }],
};
const MAX_REGIONS = 6;

function covOf({ sigma: [a, b], angle }) {
  const t = (angle * Math.PI) / 180;
  const [c, s] = [Math.cos(t), Math.sin(t)];
  return [[a * a * c * c + b * b * s * s, (a * a - b * b) * c * s], [(a * a - b * b) * c * s, a * a * s * s + b * b * c * c]];
}

// ---------------------------------------------------------------- state (in the URL)
const validComponents = (cs) => Array.isArray(cs) && cs.length > 0 && cs.every((c) => c && c.weight > 0
  && Array.isArray(c.mean) && c.mean.length === 2 && c.mean.every(Number.isFinite)
  && Array.isArray(c.sigma) && c.sigma.length === 2 && c.sigma.every((s) => s > 0) && Number.isFinite(c.angle));
const url = urlState(
  { components: MIXTURES.one(), regions: REGIONS.box(), wmin: -2, R: 3, lambda: -3, spacing: 'equal', layer: 'input', component: 0, region: 0, step: 1, ellipses: false },
  { check: { components: validComponents, regions: (r) => validRegions(r) && r.length <= MAX_REGIONS } },
);
const state = url.values;
state.component = Math.min(Math.max(Math.trunc(state.component), 0), state.components.length - 1);
state.region = Math.min(Math.max(Math.trunc(state.region), 0), state.regions.length - 1);
const result = { split: null, unsplit: null, library: null, options: null };
const timer = timings('splitting');
timer.badge($('redraw-ms'), { split: 'splitForRegions', redraw: 'whole update', fig5: 'Fig. 5 scenario' });
const mixtureOf = () => state.components.map((c) => ({ weight: c.weight, mean: [...c.mean], cov: covOf(c) }));

// ---------------------------------------------------------------- density images (display only)
/** mixtureDensityGrid at a resolution the component count allows (≤ `budget` evaluations). */
function density(mixture, xDomain, yDomain, maxCells, budget = 1e6) {
  const [nx, ny] = cellCounts(xDomain, yDomain, { maxCells, budget, terms: mixture.length });
  const values = mixture.length > 0 ? fisst.mixtureDensityGrid({ mixture, grid: cellGrid(xDomain, yDomain, nx, ny) }) : new Float64Array(nx * ny);
  return { values, nx, ny };
}

const largest = (values) => values.reduce((a, b) => Math.max(a, b), 0);

// ---------------------------------------------------------------- the scene view
const DOMAIN = [-4, 4];
const BOX = { left: 48, top: 10, width: 500, height: 486 };
// Equal units on both axes: the y range follows the box's aspect.
const Y_DOMAIN = [DOMAIN[0] * (BOX.height / BOX.width), DOMAIN[1] * (BOX.height / BOX.width)];
const clampX = (v) => Math.min(Math.max(v, DOMAIN[0]), DOMAIN[1]);
const clampY = (v) => Math.min(Math.max(v, Y_DOMAIN[0]), Y_DOMAIN[1]);
const regionLabel = (k) => `${k === 0 ? 'S' : `region ${k + 1}`} (${kindOf(state.regions[k])})`;
let layer = null; // the density image of the chosen layer
const view = sceneView($('scene'), {
  width: 580, height: 540, box: BOX, x: DOMAIN, y: Y_DOMAIN, draw: drawScene,
  drag: {
    // Targets, topmost first: a component's ✚, a region's handle, a region's interior.
    hit([x, y]) {
      const near = ([wx, wy], r) => Math.hypot(view.px(wx) - view.px(x), view.py(wy) - view.py(y)) <= r;
      for (let k = state.components.length - 1; k >= 0; k--) if (near(state.components[k].mean, 9)) return { type: 'component', index: k };
      for (let k = state.regions.length - 1; k >= 0; k--) {
        const h = handles(state.regions[k]).findIndex((p) => near(p, 7));
        if (h >= 0) return { type: 'handle', index: k, handle: h };
      }
      for (let k = state.regions.length - 1; k >= 0; k--) if (insideRegion(view, state.regions[k], [x, y])) return { type: 'region', index: k };
      return null;
    },
    start(t) {
      if (t.type === 'component') state.component = t.index;
      else state.region = t.index;
      syncControls();
      view.redraw();
    },
    move(t, { point, delta }) {
      const w = [clampX(point[0]), clampY(point[1])];
      if (t.type === 'component') {
        const c = state.components[t.index];
        c.mean = [clampX(c.mean[0] + delta[0]), clampY(c.mean[1] + delta[1])];
      } else if (t.type === 'handle') state.regions[t.index] = reshape(state.regions[t.index], t.handle, w);
      else state.regions[t.index] = translate(state.regions[t.index], delta);
      update();
    },
    end: () => {
      if (state.layer !== 'input') update(); // back to the full resolution
    },
  },
});
const sceneBar = colorbar($('scene-legend'), { map: 'greys', label: 'density (p, p<sub>S</sub>, p<sub>C(S)</sub> on one scale)', format: (v) => fmt(v, 3) });

function drawScene(ctx, v) {
  const { px, py, box } = v;
  const r = result.split;
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(layer, box.left, box.top, box.width, box.height);
  v.axes({ xLabel: 'x', yLabel: 'y', ticks: 8, format: (t) => t.toFixed(0) });
  ctx.save();
  clipTo(ctx, box);
  // Regions: S solid and lightly filled, the others dashed; the selected one thicker.
  state.regions.forEach((region, k) => {
    const path = regionPath(v, region);
    ctx.fillStyle = k === 0 ? 'rgba(4, 120, 87, 0.07)' : 'rgba(124, 58, 237, 0.05)';
    ctx.fill(path, 'evenodd');
    ctx.strokeStyle = k === 0 ? COLOUR.first : COLOUR.other;
    ctx.lineWidth = k === state.region ? 3 : 2;
    ctx.setLineDash(k === 0 ? [] : [7, 4]);
    ctx.stroke(path);
  });
  ctx.setLineDash([]);
  // Split components: 1σ ellipses and means, coloured by the side of S of their mean.
  drawMixture(ctx, px, py, r.mixture, { colourOf: (i) => (r.insideMask[i] ? COLOUR.inside : COLOUR.outside) });
  // Input components: dashed 1σ ellipses and ✚ handles at the means.
  ctx.strokeStyle = COLOUR.input;
  ctx.setLineDash([5, 4]);
  ctx.lineWidth = 1.2;
  ctx.beginPath();
  for (const c of state.components) ellipsePath(ctx, px, py, c.mean, covOf(c));
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.font = '600 11px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  state.components.forEach((c, k) => {
    const [x, y] = [px(c.mean[0]), py(c.mean[1])];
    ctx.beginPath();
    ctx.moveTo(x - 8, y); ctx.lineTo(x + 8, y); ctx.moveTo(x, y - 8); ctx.lineTo(x, y + 8);
    for (const [colour, extra] of [['#ffffff', 2.5], [COLOUR.input, 0]]) {
      ctx.strokeStyle = colour;
      ctx.lineWidth = (k === state.component ? 3 : 2) + extra;
      ctx.stroke();
    }
    ctx.fillStyle = COLOUR.input;
    ctx.fillText(String(k + 1), x + 6, y - 4);
  });
  // Region handles on top; region labels.
  ctx.font = '600 12px system-ui, sans-serif';
  state.regions.forEach((region, k) => {
    const c = k === 0 ? COLOUR.first : COLOUR.other;
    drawHandles(ctx, v, region, c);
    const [lx, ly] = labelAnchor(region);
    ctx.fillStyle = c;
    ctx.fillText(k === 0 ? 'S' : `S${k + 1}`, px(lx) + 6, py(ly) - 6);
  });
  ctx.restore();
}

// ---------------------------------------------------------------- computations (all fisst)
function readOptions() {
  // Rounded to 3 significant digits so the shown value is the value used.
  result.options = {
    minWeight: Number((10 ** state.wmin).toPrecision(3)), components: state.R, lambda: Number((10 ** state.lambda).toPrecision(3)), spacing: state.spacing,
  };
}

function computeLibrary() {
  const { components, lambda, spacing } = result.options;
  const l = (result.library = fisst.splitLibrary({ components, lambda, spacing }));
  const list = (v) => `[${Array.from(v, (x) => fmt(x, 4)).join(', ')}]`;
  $('library').textContent = `Split library (eqs 13–14) for R = ${components}: weights ${list(l.weights)}, means ${list(l.means)}, σ̃ = ${fmt(l.sigma, 5)}, J = ${fmt(l.objective, 4)}`;
}

function computeSplit() {
  const mixture = mixtureOf();
  const r = (result.split = timer.time('split', () => fisst.splitForRegions({ mixture, regions: state.regions, ...result.options })));
  // maxDepth 0: the mean-based partition of the input mixture as it is.
  result.unsplit = fisst.splitForRegions({ mixture, regions: [state.regions[0]], maxDepth: 0 });
  const show = { 'input-count': mixture.length, 'component-count': r.mixture.length, 'inside-count': r.insideMask.filter(Boolean).length, 'split-depth': r.depth, 'split-splits': r.splits, 'split-stop': r.stop ?? 'no' };
  for (const [id, value] of Object.entries(show)) $(id).textContent = String(value);
  $('inside-split').textContent = fmt(r.inside, 6);
  $('outside-split').textContent = fmt(r.outside, 6);
  $('inside-exact').textContent = fmt(r.exactInside, 6);
  $('inside-error').textContent = r.exactInside === null ? '—' : fmt(Math.abs(r.inside - r.exactInside), 3);
  $('inside-unsplit').textContent = fmt(result.unsplit.inside, 6);
  $('split-time').textContent = msText(timer.last.split);
}

/** The chosen density layer; p_S and p_C(S) at a coarser grid while a drag is under way. */
function layerImage() {
  const input = density(mixtureOf(), DOMAIN, Y_DOMAIN, 125);
  const vmax = largest(input.values); // the same scale for p, p_S and p_C(S)
  sceneBar.update({ max: vmax });
  if (state.layer === 'input') return heatImage(input.values, input.nx, input.ny, { map: 'greys', vmax });
  const part = result.split.mixture.filter((_, i) => result.split.insideMask[i] === (state.layer === 'inside'));
  const d = density(part, DOMAIN, Y_DOMAIN, 125, view.dragging === null ? 1.5e6 : 3e5);
  return heatImage(d.values, d.nx, d.ny, { map: 'greys', vmax });
}

function publish() {
  const r = result.split;
  $('split-state').textContent = JSON.stringify({
    mixture: mixtureOf(), regions: state.regions, options: result.options,
    result: {
      count: r.mixture.length, insideCount: r.insideMask.filter(Boolean).length, inside: r.inside, outside: r.outside,
      exactInside: r.exactInside, unsplitInside: result.unsplit.inside, depth: r.depth, splits: r.splits, stop: r.stop, ms: timer.last.split,
    },
    selected: { component: state.component, region: state.region }, layer: state.layer, view: { box: view.box, ...view.domain() },
  }, null, 1);
}

function syncControls() {
  const c = state.components[state.component];
  $('component-selected').textContent = `component ${state.component + 1} (weight ${fmt(c.weight, 3)})`;
  sliders.major.set(c.sigma[0]);
  sliders.minor.set(c.sigma[1]);
  sliders.angle.set(c.angle);
  $('region-selected').textContent = regionLabel(state.region);
  $('region-count').textContent = String(state.regions.length);
  $('remove-region').disabled = state.regions.length <= 1;
  $('region-first').disabled = state.region === 0;
  $('add-region').disabled = state.regions.length >= MAX_REGIONS;
  layers.set(state.layer);
}

/** Recomputes (optionally the library too) and redraws everything of the first panel. */
function update({ library = false } = {}) {
  timer.time('redraw', () => {
    readOptions();
    if (library) computeLibrary();
    computeSplit();
    layer = layerImage();
    view.redraw();
    syncControls();
    publish();
  });
  timer.show();
  url.save();
}

// ---------------------------------------------------------------- controls
const num = (v) => fmt(v, 3);
const option = (key, library) => (v) => { state[key] = v; update({ library }); };
state.wmin = slider('wmin', { value: state.wmin, format: (v) => String(Number((10 ** v).toPrecision(3))), onInput: option('wmin', false) }).value;
state.R = slider('components', { value: state.R, onInput: option('R', true) }).value;
state.lambda = slider('lambda', { value: state.lambda, format: (v) => String(Number((10 ** v).toPrecision(3))), onInput: option('lambda', true) }).value;
state.spacing = select('spacing', { value: state.spacing, onChange: option('spacing', true) }).value;
const edit = (apply) => (v) => { apply(state.components[state.component], v); update(); };
const sliders = {
  major: slider('sigma-major', { format: num, onInput: edit((c, v) => { c.sigma[0] = v; }) }),
  minor: slider('sigma-minor', { format: num, onInput: edit((c, v) => { c.sigma[1] = v; }) }),
  angle: slider('angle', { onInput: edit((c, v) => { c.angle = v; }) }),
};
const layers = choice('layer', ['input', 'inside', 'outside'], { value: state.layer, onChange: (v) => { state.layer = v; update(); } });
const preset = (key, make) => () => { state[key] = make(); state[key === 'components' ? 'component' : 'region'] = 0; update(); };
$('preset-one').addEventListener('click', preset('components', MIXTURES.one));
$('preset-three').addEventListener('click', preset('components', MIXTURES.three));
$('preset-box').addEventListener('click', preset('regions', REGIONS.box));
$('preset-several').addEventListener('click', preset('regions', REGIONS.several));
$('add-region').addEventListener('click', () => {
  if (state.regions.length >= MAX_REGIONS) return;
  // New regions appear left of centre, staggered so they do not cover each other exactly.
  const k = state.regions.length;
  state.regions.push(newRegion($('region-kind').value, [-1.8 + 0.5 * (k % 3), -1.6 + 0.6 * (k % 4)]));
  state.region = state.regions.length - 1;
  update();
});
$('remove-region').addEventListener('click', () => {
  if (state.regions.length <= 1) return;
  state.regions.splice(state.region, 1);
  state.region = Math.min(state.region, state.regions.length - 1);
  update();
});
$('region-first').addEventListener('click', () => {
  state.regions.unshift(...state.regions.splice(state.region, 1));
  state.region = 0;
  update();
});
downloads($('scene-figure'), {
  name: 'splitting',
  png: () => view.canvas,
  csv: () => toCSV(['weight', 'x', 'y', 'cov_xx', 'cov_xy', 'cov_yy', 'mean_in_S'],
    result.split.mixture.map((c, i) => [c.weight, ...c.mean, c.cov[0][0], c.cov[0][1], c.cov[1][1], result.split.insideMask[i]])),
});

// ---------------------------------------------------------------- Fig. 5
const F5X = [-4, 4];
const F5Y = [-2.2, 4.2]; // 8 × 6.4 units on 316 × 252 px: equal units on both axes
const scenario = timer.time('fig5', () => fisst.negativeInformationScenario());
const fig5 = { cache: new Map(), panels: {} };
const fig5Bar = colorbar($('fig5-legend'), { map: 'greys', label: 'density (one scale per scan)', format: (v) => fmt(v, 3) });

/** Per step: density images on one colour scale and the split mixture's inside flags. */
function fig5Images(k) {
  if (fig5.cache.has(k)) return fig5.cache.get(k);
  const s = scenario.steps[k - 1];
  const d = Object.fromEntries(['predicted', 'split', 'posterior'].map((key) => [key, density(s[key], F5X, F5Y, 120)]));
  const vmax = Math.max(largest(d.predicted.values), largest(d.posterior.values));
  const images = Object.fromEntries(Object.entries(d).map(([key, v]) => [key, heatImage(v.values, v.nx, v.ny, { map: 'greys', vmax })]));
  // maxDepth 0 splits nothing: the inside flags of the split mixture as the filter used them.
  const mask = fisst.splitForRegions({ mixture: s.split, regions: [scenario.fov], maxDepth: 0 }).insideMask;
  fig5.cache.set(k, { images, mask, vmax });
  return fig5.cache.get(k);
}

function fig5Panel(key) {
  const panel = sceneView($(`fig5-${key}`), {
    width: 364, height: 300, box: { left: 40, top: 8, width: 316, height: 252 }, x: F5X, y: F5Y,
    draw(ctx, v) {
      const s = scenario.steps[state.step - 1];
      const { images, mask } = fig5Images(state.step);
      ctx.imageSmoothingEnabled = true;
      ctx.drawImage(images[key], v.box.left, v.box.top, v.box.width, v.box.height);
      v.axes({ ticks: 8, format: (t) => t.toFixed(0) });
      ctx.save();
      clipTo(ctx, v.box);
      const fov = regionPath(v, scenario.fov);
      ctx.fillStyle = 'rgba(4, 120, 87, 0.07)';
      ctx.fill(fov);
      ctx.strokeStyle = COLOUR.first;
      ctx.lineWidth = 2;
      ctx.stroke(fov);
      if (key === 'split' || state.ellipses) {
        const colourOf = (i) => (key === 'predicted' ? COLOUR.input : key === 'posterior' || !mask[i] ? COLOUR.outside : COLOUR.inside);
        drawMixture(ctx, v.px, v.py, s[key], { colourOf, dots: false, lineWidth: 1 });
      }
      ctx.font = '600 12px system-ui, sans-serif';
      ctx.fillStyle = COLOUR.first;
      ctx.textAlign = 'left';
      ctx.textBaseline = 'top';
      ctx.fillText('S', v.px(scenario.fov.box.min[0]) + 4, v.py(scenario.fov.box.max[1]) + 3);
      ctx.restore();
    },
  });
  downloads(panel.canvas.parentElement, { name: () => `splitting-fig5-${key}-k${state.step}`, png: () => panel.canvas });
  return panel;
}

function showFig5(k) {
  state.step = k;
  const s = scenario.steps[k - 1];
  const { mask, vmax } = fig5Images(k);
  for (const key of ['predicted', 'split', 'posterior']) (fig5.panels[key] ??= fig5Panel(key)).redraw();
  fig5Bar.update({ max: vmax });
  const show = {
    'fig5-step': s.step, 'fig5-predicted-count': s.predicted.length, 'fig5-split-count': s.split.length, 'fig5-posterior-count': s.posterior.length,
    'fig5-nondetection': fmt(s.nonDetectionProb, 6), 'fig5-predicted-inside': fmt(s.predictedInside, 6), 'fig5-posterior-inside': fmt(s.posteriorInside, 6), 'fig5-depth': s.depth, 'fig5-splits': s.splits,
  };
  for (const [id, value] of Object.entries(show)) $(id).textContent = String(value);
  $('fig5-prev').disabled = k <= 1;
  $('fig5-next').disabled = k >= scenario.steps.length;
  $('fig5-state').textContent = JSON.stringify({
    step: s.step, steps: scenario.steps.length, fov: scenario.fov,
    counts: { predicted: s.predicted.length, split: s.split.length, posterior: s.posterior.length },
    splitInsideCount: mask.filter(Boolean).length, nonDetectionProb: s.nonDetectionProb, predictedInside: s.predictedInside,
    posteriorInside: s.posteriorInside, depth: s.depth, splits: s.splits, scenarioMs: timer.last.fig5,
  }, null, 1);
  url.save();
}

$('fig5-prev').addEventListener('click', () => showFig5(Math.max(1, state.step - 1)));
$('fig5-next').addEventListener('click', () => showFig5(Math.min(scenario.steps.length, state.step + 1)));
$('fig5-ellipses').checked = state.ellipses;
$('fig5-ellipses').addEventListener('change', () => {
  state.ellipses = $('fig5-ellipses').checked;
  showFig5(state.step);
});

// ---------------------------------------------------------------- start
update({ library: true });
showFig5(Math.min(Math.max(Math.trunc(state.step), 1), scenario.steps.length));
pageReady();

// Recursive Gaussian splitting along region boundaries and the negative-information filter
// (paper 001, "Split happens!", Section IV, Figs 2–5). Every number comes from the fisst
// package: the split mixture, which components lie in S, the partition masses, the exact
// mass, the split library, the density images and the Fig. 5 filter. This file only builds
// inputs from the controls, draws and wires events.
import init, * as fisst from 'fisst';
import { setupCanvas, scale, drawAxes, ticks, fmt, ellipsePath } from './lib/plot.js';

await init();

const $ = (id) => document.getElementById(id);
const css = getComputedStyle(document.documentElement);
const COLOUR = {
  inside: css.getPropertyValue('--split-inside').trim(),
  outside: css.getPropertyValue('--split-outside').trim(),
  first: css.getPropertyValue('--region-first').trim(),
  other: css.getPropertyValue('--region-other').trim(),
  input: '#111827',
};

// ---------------------------------------------------------------- density images (display only)
const rgb = (hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
// White to grey: neutral under the many blue and orange ellipses of the first panel.
const PALE = ['#ffffff', '#f0f4f8', '#d9e2ec', '#bcccdc', '#9aa5b1', '#7b8794'].map(rgb);
// White to dark blue-grey: the Fig. 5 densities, where the ellipses are secondary.
const DEEP = ['#ffffff', '#e4ebf2', '#bcccdc', '#829ab1', '#486581', '#243b53'].map(rgb);

function colour(palette, t) {
  const u = Math.min(Math.max(t, 0), 1) * (palette.length - 1);
  const k = Math.min(Math.floor(u), palette.length - 2);
  const f = u - k;
  return palette[k].map((c, i) => Math.round(c + f * (palette[k + 1][i] - c)));
}

/** Cell-centred grid over a domain: `n` cells per axis (the image spans the domain exactly). */
function cellGrid([x0, x1], [y0, y1], nx, ny) {
  const hx = (x1 - x0) / nx;
  const hy = (y1 - y0) / ny;
  return { x: [x0 + hx / 2, x1 - hx / 2, nx], y: [y0 + hy / 2, y1 - hy / 2, ny] };
}

/** An nx × ny image of row-major values (y outer, growing upwards) scaled by vmax. */
function heatImage(values, nx, ny, vmax, palette = PALE) {
  const image = document.createElement('canvas');
  image.width = nx;
  image.height = ny;
  const ctx = image.getContext('2d');
  const data = ctx.createImageData(nx, ny);
  for (let j = 0; j < ny; j++) {
    const row = ny - 1 - j; // canvas rows grow downwards
    for (let i = 0; i < nx; i++) {
      const [r, g, b] = colour(palette, vmax > 0 ? values[j * nx + i] / vmax : 0);
      const k = 4 * (row * nx + i);
      data.data[k] = r;
      data.data[k + 1] = g;
      data.data[k + 2] = b;
      data.data[k + 3] = 255;
    }
  }
  ctx.putImageData(data, 0, 0);
  return image;
}

/** mixtureDensityGrid at a resolution the component count allows (≤ `budget` evaluations). */
function density(mixture, xDomain, yDomain, maxCells, budget = 1e6) {
  const aspect = (yDomain[1] - yDomain[0]) / (xDomain[1] - xDomain[0]);
  const nx = Math.max(24, Math.min(maxCells, Math.floor(Math.sqrt(budget / Math.max(mixture.length, 1) / aspect))));
  const ny = Math.max(1, Math.round(nx * aspect));
  const values = mixture.length > 0
    ? fisst.mixtureDensityGrid({ mixture, grid: cellGrid(xDomain, yDomain, nx, ny) })
    : new Float64Array(nx * ny);
  return { values, nx, ny };
}

const largest = (values) => values.reduce((a, b) => Math.max(a, b), 0);

// ---------------------------------------------------------------- presets
// Components are kept as (weight, mean, principal σs, orientation in degrees); the covariance
// handed to the package is R(θ) diag(σ₁², σ₂²) R(θ)ᵀ.
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
  several: () => [
    { box: { min: [-0.5, -1.8], max: [2.5, 1.5] } },
    newRegion('polygon', [-2.3, -1.6]),
    { disc: { center: [-1.6, 2.1], radius: 1 } },
  ],
};

const kindOf = (region) => Object.keys(region)[0];
const MAX_REGIONS = 6;

function covOf({ sigma: [a, b], angle }) {
  const t = (angle * Math.PI) / 180;
  const c = Math.cos(t);
  const s = Math.sin(t);
  return [
    [a * a * c * c + b * b * s * s, (a * a - b * b) * c * s],
    [(a * a - b * b) * c * s, a * a * s * s + b * b * c * c],
  ];
}

// ---------------------------------------------------------------- state
const state = {
  components: MIXTURES.one(),
  regions: REGIONS.box(),
  options: { minWeight: 0.01, components: 3, lambda: 0.001, spacing: 'equal' },
  component: 0, // the component the σ / orientation sliders edit
  region: 0, // the region "remove" and "make it S" act on
  layer: 'input',
  result: null, // splitForRegions(...)
  unsplit: null, // splitForRegions(... maxDepth: 0): the partition of the input itself
  library: null,
  ms: null,
};
const timing = { splitTimes: [], redrawTimes: [] };
window.fisstSplitting = timing;

const mixtureOf = () => state.components.map((c) => ({ weight: c.weight, mean: [...c.mean], cov: covOf(c) }));

// ---------------------------------------------------------------- the scene canvas
const DOMAIN = [-4, 4];
const VIEW = { width: 580, height: 540, box: { left: 48, top: 10, width: 500, height: 486 } };
const { box } = VIEW;
// Equal units on both axes: the y range follows the box's aspect.
const Y_DOMAIN = [DOMAIN[0] * (box.height / box.width), DOMAIN[1] * (box.height / box.width)];
const px = scale(DOMAIN[0], DOMAIN[1], box.left, box.left + box.width);
const py = scale(Y_DOMAIN[0], Y_DOMAIN[1], box.top + box.height, box.top);
const canvas = $('scene');
const sceneCtx = setupCanvas(canvas, VIEW.width, VIEW.height);

function regionPath(region) {
  const path = new Path2D();
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    path.rect(px(min[0]), py(max[1]), px(max[0]) - px(min[0]), py(min[1]) - py(max[1]));
  } else if (kind === 'disc') {
    const { center, radius } = region.disc;
    path.arc(px(center[0]), py(center[1]), px(radius) - px(0), 0, 2 * Math.PI);
  } else {
    region.polygon.forEach(([x, y], k) => (k === 0 ? path.moveTo(px(x), py(y)) : path.lineTo(px(x), py(y))));
    path.closePath();
  }
  return path;
}

/** The draggable handles of a region, in world coordinates. */
function handles(region) {
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    return [[min[0], min[1]], [max[0], min[1]], [max[0], max[1]], [min[0], max[1]]];
  }
  if (kind === 'disc') {
    const { center, radius } = region.disc;
    return [[center[0] + radius, center[1]]];
  }
  return region.polygon.map((p) => [...p]);
}

function regionLabel(k) {
  return `${k === 0 ? 'S' : `region ${k + 1}`} (${kindOf(state.regions[k])})`;
}

function drawHandle(ctx, x, y, stroke) {
  ctx.fillStyle = '#ffffff';
  ctx.strokeStyle = stroke;
  ctx.lineWidth = 1.5;
  ctx.fillRect(px(x) - 4, py(y) - 4, 8, 8);
  ctx.strokeRect(px(x) - 4, py(y) - 4, 8, 8);
}

function drawScene(image) {
  const ctx = sceneCtx;
  const { result } = state;
  ctx.clearRect(0, 0, VIEW.width, VIEW.height);
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(image, box.left, box.top, box.width, box.height);
  drawAxes(ctx, box, px, py, {
    xTicks: ticks(-4, 4, 8), yTicks: ticks(-3, 3, 6), xLabel: 'x', yLabel: 'y', fmt: (v) => v.toFixed(0),
  });
  ctx.save();
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.clip();
  // Regions: S solid and lightly filled, the others dashed; the selected one thicker.
  state.regions.forEach((region, k) => {
    const path = regionPath(region);
    const c = k === 0 ? COLOUR.first : COLOUR.other;
    ctx.fillStyle = k === 0 ? 'rgba(4, 120, 87, 0.07)' : 'rgba(124, 58, 237, 0.05)';
    ctx.fill(path, 'evenodd');
    ctx.strokeStyle = c;
    ctx.lineWidth = k === state.region ? 3 : 2;
    ctx.setLineDash(k === 0 ? [] : [7, 4]);
    ctx.stroke(path);
  });
  ctx.setLineDash([]);
  // Split components: 1σ ellipses, one path per (side, opacity class) so thousands stay cheap.
  const wmax = result.mixture.reduce((a, c) => Math.max(a, c.weight), 0);
  for (const side of [false, true]) {
    for (const [lo, hi, alpha] of [[0, 0.05, 0.3], [0.05, 0.3, 0.55], [0.3, 1.01, 0.9]]) {
      ctx.beginPath();
      let any = false;
      result.mixture.forEach((c, i) => {
        const t = c.weight / wmax;
        if (result.insideMask[i] !== side || t < lo || t >= hi) return;
        ellipsePath(ctx, px, py, c.mean, c.cov);
        any = true;
      });
      if (!any) continue;
      ctx.globalAlpha = alpha;
      ctx.strokeStyle = side ? COLOUR.inside : COLOUR.outside;
      ctx.lineWidth = 1.2;
      ctx.stroke();
    }
  }
  ctx.globalAlpha = 1;
  // Split component means: small dots.
  for (const side of [false, true]) {
    ctx.fillStyle = side ? COLOUR.inside : COLOUR.outside;
    ctx.beginPath();
    result.mixture.forEach((c, i) => {
      if (result.insideMask[i] !== side) return;
      ctx.moveTo(px(c.mean[0]) + 1.6, py(c.mean[1]));
      ctx.arc(px(c.mean[0]), py(c.mean[1]), 1.6, 0, 2 * Math.PI);
    });
    ctx.fill();
  }
  // Input components: dashed 1σ ellipses and ✚ handles at the means.
  ctx.strokeStyle = COLOUR.input;
  ctx.setLineDash([5, 4]);
  ctx.lineWidth = 1.2;
  ctx.beginPath();
  for (const c of state.components) ellipsePath(ctx, px, py, c.mean, covOf(c));
  ctx.stroke();
  ctx.setLineDash([]);
  state.components.forEach((c, k) => {
    const x = px(c.mean[0]);
    const y = py(c.mean[1]);
    ctx.lineWidth = k === state.component ? 3 : 2;
    ctx.strokeStyle = '#ffffff';
    ctx.beginPath();
    ctx.moveTo(x - 8, y); ctx.lineTo(x + 8, y); ctx.moveTo(x, y - 8); ctx.lineTo(x, y + 8);
    ctx.lineWidth += 2.5;
    ctx.stroke();
    ctx.lineWidth -= 2.5;
    ctx.strokeStyle = COLOUR.input;
    ctx.stroke();
    ctx.font = '600 11px system-ui, sans-serif';
    ctx.fillStyle = COLOUR.input;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'bottom';
    ctx.fillText(String(k + 1), x + 6, y - 4);
  });
  // Region handles on top; region labels.
  state.regions.forEach((region, k) => {
    const c = k === 0 ? COLOUR.first : COLOUR.other;
    for (const [x, y] of handles(region)) drawHandle(ctx, x, y, c);
    const [lx, ly] = handles(region).reduce(([ax, ay], [x, y]) => (y > ay || (y === ay && x < ax) ? [x, y] : [ax, ay]));
    const anchor = kindOf(region) === 'disc'
      ? [region.disc.center[0] - region.disc.radius * 0.7, region.disc.center[1] + region.disc.radius * 0.75]
      : [lx, ly];
    ctx.font = '600 12px system-ui, sans-serif';
    ctx.fillStyle = c;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'bottom';
    ctx.fillText(k === 0 ? 'S' : `S${k + 1}`, px(anchor[0]) + 6, py(anchor[1]) - 6);
  });
  ctx.restore();
}

// ---------------------------------------------------------------- computations (all fisst)
function computeLibrary() {
  const { components, lambda, spacing } = state.options;
  state.library = fisst.splitLibrary({ components, lambda, spacing });
  const l = state.library;
  const list = (v) => `[${Array.from(v, (x) => fmt(x, 4)).join(', ')}]`;
  $('library').textContent = `Split library (eqs 13–14) for R = ${components}: weights ${list(l.weights)}, `
    + `means ${list(l.means)}, σ̃ = ${fmt(l.sigma, 5)}, J = ${fmt(l.objective, 4)}`;
}

function computeSplit() {
  const mixture = mixtureOf();
  const t0 = performance.now();
  state.result = fisst.splitForRegions({ mixture, regions: state.regions, ...state.options });
  state.ms = performance.now() - t0;
  timing.splitTimes.push(state.ms);
  // maxDepth 0: the mean-based partition of the input mixture as it is.
  state.unsplit = fisst.splitForRegions({ mixture, regions: [state.regions[0]], maxDepth: 0 });
  const r = state.result;
  $('input-count').textContent = String(mixture.length);
  $('component-count').textContent = String(r.mixture.length);
  $('inside-count').textContent = String(r.insideMask.filter(Boolean).length);
  $('inside-split').textContent = fmt(r.inside, 6);
  $('outside-split').textContent = fmt(r.outside, 6);
  $('inside-exact').textContent = fmt(r.exactInside, 6);
  $('inside-error').textContent = r.exactInside === null ? '—' : fmt(Math.abs(r.inside - r.exactInside), 3);
  $('inside-unsplit').textContent = fmt(state.unsplit.inside, 6);
  $('split-depth').textContent = String(r.depth);
  $('split-splits').textContent = String(r.splits);
  $('split-stop').textContent = r.stop ?? 'no';
  $('split-time').textContent = `${state.ms.toFixed(1)} ms`;
}

/** The chosen density layer; p_S and p_C(S) at a coarser grid while a drag is under way. */
function layerImage() {
  const input = density(mixtureOf(), DOMAIN, Y_DOMAIN, 125);
  const vmax = largest(input.values); // the same scale for p, p_S and p_C(S)
  if (state.layer === 'input') return heatImage(input.values, input.nx, input.ny, vmax);
  const want = state.layer === 'inside';
  const part = state.result.mixture.filter((_, i) => state.result.insideMask[i] === want);
  const d = density(part, DOMAIN, Y_DOMAIN, 125, drag.id === null ? 1.5e6 : 3e5);
  return heatImage(d.values, d.nx, d.ny, vmax);
}

function publish() {
  const r = state.result;
  $('split-state').textContent = JSON.stringify({
    mixture: mixtureOf(),
    regions: state.regions,
    options: state.options,
    result: {
      count: r.mixture.length,
      insideCount: r.insideMask.filter(Boolean).length,
      inside: r.inside,
      outside: r.outside,
      exactInside: r.exactInside,
      unsplitInside: state.unsplit.inside,
      depth: r.depth,
      splits: r.splits,
      stop: r.stop,
      ms: state.ms,
    },
    selected: { component: state.component, region: state.region },
    layer: state.layer,
    view: { box, x: DOMAIN, y: Y_DOMAIN },
  }, null, 1);
}

function syncControls() {
  const c = state.components[state.component];
  $('component-selected').textContent = `component ${state.component + 1} (weight ${fmt(c.weight, 3)})`;
  $('sigma-major').value = String(c.sigma[0]);
  $('sigma-minor').value = String(c.sigma[1]);
  $('angle').value = String(c.angle);
  $('sigma-major-out').value = fmt(c.sigma[0], 3);
  $('sigma-minor-out').value = fmt(c.sigma[1], 3);
  $('angle-out').value = String(c.angle);
  $('region-selected').textContent = regionLabel(state.region);
  $('region-count').textContent = String(state.regions.length);
  $('remove-region').disabled = state.regions.length <= 1;
  $('region-first').disabled = state.region === 0;
  $('add-region').disabled = state.regions.length >= MAX_REGIONS;
  for (const layer of ['input', 'inside', 'outside']) {
    $(`layer-${layer}`).setAttribute('aria-pressed', String(layer === state.layer));
  }
}

/** Recomputes (optionally the library too) and redraws everything of the first panel. */
function update({ library = false } = {}) {
  const t0 = performance.now();
  if (library) computeLibrary();
  computeSplit();
  drawScene(layerImage());
  syncControls();
  publish();
  timing.redrawTimes.push(performance.now() - t0);
}

// ---------------------------------------------------------------- controls
function readOptions() {
  const wmin = 10 ** Number($('wmin').value);
  const lambda = 10 ** Number($('lambda').value);
  state.options = {
    // Rounded to 3 significant digits so the shown value is the value used.
    minWeight: Number(wmin.toPrecision(3)),
    components: Number($('components').value),
    lambda: Number(lambda.toPrecision(3)),
    spacing: $('spacing').value,
  };
  $('wmin-out').value = String(state.options.minWeight);
  $('components-out').value = String(state.options.components);
  $('lambda-out').value = String(state.options.lambda);
}

for (const id of ['wmin', 'components', 'lambda', 'spacing']) {
  $(id).addEventListener('input', () => {
    readOptions();
    update({ library: id !== 'wmin' });
  });
}

for (const [id, apply] of [
  ['sigma-major', (c, v) => { c.sigma[0] = v; }],
  ['sigma-minor', (c, v) => { c.sigma[1] = v; }],
  ['angle', (c, v) => { c.angle = v; }],
]) {
  $(id).addEventListener('input', () => {
    apply(state.components[state.component], Number($(id).value));
    update();
  });
}

for (const layer of ['input', 'inside', 'outside']) {
  $(`layer-${layer}`).addEventListener('click', () => {
    state.layer = layer;
    update();
  });
}

$('preset-one').addEventListener('click', () => {
  state.components = MIXTURES.one();
  state.component = 0;
  update();
});
$('preset-three').addEventListener('click', () => {
  state.components = MIXTURES.three();
  state.component = 0;
  update();
});
$('preset-box').addEventListener('click', () => {
  state.regions = REGIONS.box();
  state.region = 0;
  update();
});
$('preset-several').addEventListener('click', () => {
  state.regions = REGIONS.several();
  state.region = 0;
  update();
});
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
  const [r] = state.regions.splice(state.region, 1);
  state.regions.unshift(r);
  state.region = 0;
  update();
});

// ---------------------------------------------------------------- dragging
// Pointer events cover mouse, pen and touch. Targets, topmost first: a component's ✚, a
// region's handle, a region's interior (the canvas's own path hit test).
const drag = { id: null, target: null, last: null };
const clampX = (v) => Math.min(Math.max(v, DOMAIN[0]), DOMAIN[1]);
const clampY = (v) => Math.min(Math.max(v, Y_DOMAIN[0]), Y_DOMAIN[1]);

function pointerOf(event) {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

function hitTest([x, y]) {
  const near = ([wx, wy], r) => Math.hypot(px(wx) - x, py(wy) - y) <= r;
  for (let k = state.components.length - 1; k >= 0; k--) {
    if (near(state.components[k].mean, 9)) return { type: 'component', index: k };
  }
  for (let k = state.regions.length - 1; k >= 0; k--) {
    const hs = handles(state.regions[k]);
    for (let h = 0; h < hs.length; h++) if (near(hs[h], 7)) return { type: 'handle', index: k, handle: h };
  }
  const dpr = window.devicePixelRatio || 1;
  for (let k = state.regions.length - 1; k >= 0; k--) {
    // The point is in bitmap pixels; the path is scaled by the context's dpr transform.
    if (sceneCtx.isPointInPath(regionPath(state.regions[k]), x * dpr, y * dpr, 'evenodd')) {
      return { type: 'region', index: k };
    }
  }
  return null;
}

function translate(region, [dx, dy]) {
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    return { box: { min: [min[0] + dx, min[1] + dy], max: [max[0] + dx, max[1] + dy] } };
  }
  if (kind === 'disc') {
    const { center, radius } = region.disc;
    return { disc: { center: [center[0] + dx, center[1] + dy], radius } };
  }
  return { polygon: region.polygon.map(([x, y]) => [x + dx, y + dy]) };
}

/** Moves handle `h` of `region` to the world point `w` (boxes keep a positive size). */
function reshape(region, h, [wx, wy]) {
  const kind = kindOf(region);
  const gap = 0.1;
  if (kind === 'box') {
    const min = [...region.box.min];
    const max = [...region.box.max];
    if (h === 0 || h === 3) min[0] = Math.min(wx, max[0] - gap); else max[0] = Math.max(wx, min[0] + gap);
    if (h === 0 || h === 1) min[1] = Math.min(wy, max[1] - gap); else max[1] = Math.max(wy, min[1] + gap);
    return { box: { min, max } };
  }
  if (kind === 'disc') {
    const { center } = region.disc;
    return { disc: { center, radius: Math.max(Math.hypot(wx - center[0], wy - center[1]), gap) } };
  }
  const polygon = region.polygon.map((p) => [...p]);
  polygon[h] = [wx, wy];
  return { polygon };
}

function applyDrag(w) {
  const t = drag.target;
  const d = [w[0] - drag.last[0], w[1] - drag.last[1]];
  if (t.type === 'component') {
    const c = state.components[t.index];
    c.mean = [clampX(c.mean[0] + d[0]), clampY(c.mean[1] + d[1])];
  } else if (t.type === 'handle') {
    state.regions[t.index] = reshape(state.regions[t.index], t.handle, w);
  } else {
    state.regions[t.index] = translate(state.regions[t.index], d);
  }
  drag.last = w;
}

function worldOf(p) {
  return [clampX(px.invert(p[0])), clampY(py.invert(p[1]))];
}

canvas.addEventListener('pointerdown', (event) => {
  if (drag.id !== null) return;
  const p = pointerOf(event);
  const target = hitTest(p);
  if (!target) return;
  if (target.type === 'component') state.component = target.index;
  else state.region = target.index;
  drag.id = event.pointerId;
  drag.target = target;
  drag.last = worldOf(p);
  canvas.setPointerCapture(event.pointerId);
  canvas.classList.add('dragging');
  event.preventDefault();
  syncControls();
  drawScene(layerImage());
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== drag.id) {
    if (drag.id === null) canvas.classList.toggle('hover', hitTest(pointerOf(event)) !== null);
    return;
  }
  applyDrag(worldOf(pointerOf(event)));
  update();
});
const endDrag = (event) => {
  if (event.pointerId !== drag.id) return;
  drag.id = null;
  drag.target = null;
  canvas.classList.remove('dragging');
  if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
  if (state.layer !== 'input') drawScene(layerImage()); // back to the full resolution
};
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

// ---------------------------------------------------------------- Fig. 5
const FIG5 = { width: 364, height: 300, box: { left: 40, top: 8, width: 316, height: 252 } };
const F5X = [-4, 4];
const F5Y = [-2.2, 4.2]; // 8 × 6.4 units on 316 × 252 px: equal units on both axes
const fx = scale(F5X[0], F5X[1], FIG5.box.left, FIG5.box.left + FIG5.box.width);
const fy = scale(F5Y[0], F5Y[1], FIG5.box.top + FIG5.box.height, FIG5.box.top);
const t5 = performance.now();
const scenario = fisst.negativeInformationScenario();
timing.fig5Ms = performance.now() - t5;
const fig5 = { step: 1, cache: new Map() };

/** Per step: density images on one colour scale and the split mixture's inside flags. */
function fig5Images(k) {
  if (fig5.cache.has(k)) return fig5.cache.get(k);
  const s = scenario.steps[k - 1];
  const d = Object.fromEntries(['predicted', 'split', 'posterior'].map((key) => [key, density(s[key], F5X, F5Y, 120)]));
  const vmax = Math.max(largest(d.predicted.values), largest(d.posterior.values));
  const images = Object.fromEntries(
    Object.entries(d).map(([key, v]) => [key, heatImage(v.values, v.nx, v.ny, vmax, DEEP)]),
  );
  // maxDepth 0 splits nothing: the inside flags of the split mixture as the filter used them.
  const mask = fisst.splitForRegions({ mixture: s.split, regions: [scenario.fov], maxDepth: 0 }).insideMask;
  const out = { images, mask };
  fig5.cache.set(k, out);
  return out;
}

function drawFig5Panel(id, image, mixture, colourOf, ellipses) {
  const ctx = setupCanvas($(id), FIG5.width, FIG5.height);
  const b = FIG5.box;
  ctx.clearRect(0, 0, FIG5.width, FIG5.height);
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(image, b.left, b.top, b.width, b.height);
  drawAxes(ctx, b, fx, fy, {
    xTicks: ticks(-4, 4, 8), yTicks: ticks(-2, 4, 6), xLabel: '', yLabel: '', fmt: (v) => v.toFixed(0),
  });
  ctx.save();
  ctx.beginPath();
  ctx.rect(b.left, b.top, b.width, b.height);
  ctx.clip();
  const { min, max } = scenario.fov.box;
  ctx.fillStyle = 'rgba(4, 120, 87, 0.07)';
  ctx.fillRect(fx(min[0]), fy(max[1]), fx(max[0]) - fx(min[0]), fy(min[1]) - fy(max[1]));
  ctx.strokeStyle = COLOUR.first;
  ctx.lineWidth = 2;
  ctx.strokeRect(fx(min[0]), fy(max[1]), fx(max[0]) - fx(min[0]), fy(min[1]) - fy(max[1]));
  if (ellipses) {
    const wmax = mixture.reduce((a, c) => Math.max(a, c.weight), 0);
    mixture.forEach((c, i) => {
      ctx.beginPath();
      ellipsePath(ctx, fx, fy, c.mean, c.cov);
      ctx.globalAlpha = 0.25 + 0.65 * Math.sqrt(c.weight / wmax);
      ctx.strokeStyle = colourOf(i);
      ctx.lineWidth = 1;
      ctx.stroke();
    });
    ctx.globalAlpha = 1;
  }
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.fillStyle = COLOUR.first;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'top';
  ctx.fillText('S', fx(min[0]) + 4, fy(max[1]) + 3);
  ctx.restore();
}

function showFig5(k) {
  fig5.step = k;
  const s = scenario.steps[k - 1];
  const { images, mask } = fig5Images(k);
  const all = $('fig5-ellipses').checked;
  drawFig5Panel('fig5-predicted', images.predicted, s.predicted, () => COLOUR.input, all);
  drawFig5Panel('fig5-split', images.split, s.split, (i) => (mask[i] ? COLOUR.inside : COLOUR.outside), true);
  drawFig5Panel('fig5-posterior', images.posterior, s.posterior, () => COLOUR.outside, all);
  $('fig5-step').textContent = String(s.step);
  $('fig5-predicted-count').textContent = String(s.predicted.length);
  $('fig5-split-count').textContent = String(s.split.length);
  $('fig5-posterior-count').textContent = String(s.posterior.length);
  $('fig5-nondetection').textContent = fmt(s.nonDetectionProb, 6);
  $('fig5-predicted-inside').textContent = fmt(s.predictedInside, 6);
  $('fig5-posterior-inside').textContent = fmt(s.posteriorInside, 6);
  $('fig5-depth').textContent = String(s.depth);
  $('fig5-splits').textContent = String(s.splits);
  $('fig5-prev').disabled = k <= 1;
  $('fig5-next').disabled = k >= scenario.steps.length;
  $('fig5-state').textContent = JSON.stringify({
    step: s.step,
    steps: scenario.steps.length,
    fov: scenario.fov,
    counts: { predicted: s.predicted.length, split: s.split.length, posterior: s.posterior.length },
    splitInsideCount: mask.filter(Boolean).length,
    nonDetectionProb: s.nonDetectionProb,
    predictedInside: s.predictedInside,
    posteriorInside: s.posteriorInside,
    depth: s.depth,
    splits: s.splits,
    scenarioMs: timing.fig5Ms,
  }, null, 1);
}

$('fig5-prev').addEventListener('click', () => showFig5(Math.max(1, fig5.step - 1)));
$('fig5-next').addEventListener('click', () => showFig5(Math.min(scenario.steps.length, fig5.step + 1)));
$('fig5-ellipses').addEventListener('change', () => showFig5(fig5.step));

// ---------------------------------------------------------------- start
readOptions();
update({ library: true });
showFig5(1);
document.body.dataset.ready = 'true';

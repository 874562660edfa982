// The optimal Bernoulli reporting threshold (paper 000: Theorem III.3, Section IV, Figs 2–3).
// Every Γ, q, a* and expected loss comes from the fisst package (bernoulliThresholdCurve,
// bernoulliEstimate, bernoulliLossCurve, probabilityOutsideBall, mixtureDensityGrid); this
// file only draws, wires the controls and times each redraw.
import init, * as fisst from 'fisst';
import { setupCanvas, scale, drawAxes, ticks, fmt, ellipsePath } from './lib/plot.js';

await init();

const $ = (id) => document.getElementById(id);

// ---------------------------------------------------------------- colours (display only)
const BLUE = '#2563eb';
const RED = '#dc2626';
const GREY = '#7b8794';
const AMBER = '#d97706';
const GREEN = '#047857';
const COMPONENT_COLOURS = ['#7c3aed', '#0891b2', '#c2410c', '#4d7c0f'];

// ---------------------------------------------------------------- state
const SCENES = {
  three: [
    { weight: 0.4, mean: [-2.2, 0.2], cov: [[0.45, 0.18], [0.18, 0.35]] },
    { weight: 0.35, mean: [1.8, -1.2], cov: [[0.4, -0.15], [-0.15, 0.5]] },
    { weight: 0.25, mean: [0.6, 2], cov: [[0.6, 0], [0, 0.25]] },
  ],
  two: [
    { weight: 0.6, mean: [-0.8, -0.3], cov: [[0.12, 0.02], [0.02, 0.12]] },
    { weight: 0.4, mean: [0.8, 0.3], cov: [[0.12, -0.02], [-0.02, 0.12]] },
  ],
  one: [{ weight: 1, mean: [0.5, -0.5], cov: [[1.2, 0.5], [0.5, 0.8]] }],
};
const copyScene = (name) => SCENES[name].map((c) => ({ weight: c.weight, mean: [...c.mean], cov: c.cov.map((r) => [...r]) }));

const state = {
  preset: 'mpe',
  r0: 1,
  cA: 0.9,
  cM: 0.1,
  sigma: 1,
  p: 0.6,
  spread: 1,
  scene: 'three',
  components: copyScene('three'), // covariances before the spread scale
  fig3: null,
  fig2: null,
  view: null,
};

/** The `costs` option of the package for the current preset. */
function costsOption() {
  return state.preset === 'mpe' ? 'mpe' : { mmol: { asset: state.cA, countermeasure: state.cM } };
}

/** The mixture as the package takes it: the components with their covariances scaled. */
function mixture() {
  return state.components.map((c) => ({
    weight: c.weight, mean: [...c.mean], cov: c.cov.map((row) => row.map((v) => v * state.spread)),
  }));
}

/** Γ for a readout: ±∞ say what they mean. */
function gammaText(g) {
  if (g === Infinity) return '∞ (never reports)';
  if (g === -Infinity) return '−∞ (always reports)';
  return fmt(g, 4);
}

const pointText = (a) => `(${a[0].toFixed(3)}, ${a[1].toFixed(3)})`;

// ---------------------------------------------------------------- timing
const HISTORY = 1000;
const timing = {
  last: { fig3: null, fig2: null, view: null, total: null },
  heatMs: null, // the last density heat map (mixtureDensityGrid + image), part of the 2D view's time
  history: { fig3: [], fig2: [], view: [], total: [] },
};
window.fisstThreshold = timing;

function timed(panel, draw) {
  const t0 = performance.now();
  draw();
  const ms = performance.now() - t0;
  timing.last[panel] = ms;
  const h = timing.history[panel];
  h.push(ms);
  if (h.length > HISTORY) h.shift();
  return ms;
}

const msText = (ms) => (ms === null ? '—' : `${ms.toFixed(1)} ms`);

// ---------------------------------------------------------------- small drawing helpers
function polyline(ctx, xs, ys, x, y) {
  ctx.beginPath();
  for (let i = 0; i < xs.length; i++) {
    // ±∞ (and huge values) are drawn off the plot, where the clip hides them.
    const v = Math.min(Math.max(ys[i], -10), 10);
    if (i === 0) ctx.moveTo(x(xs[i]), y(v));
    else ctx.lineTo(x(xs[i]), y(v));
  }
  ctx.stroke();
}

function haloText(ctx, text, px, py, colour) {
  ctx.save();
  ctx.lineJoin = 'round';
  ctx.lineWidth = 3.5;
  ctx.strokeStyle = 'rgba(255,255,255,0.92)';
  ctx.strokeText(text, px, py);
  ctx.fillStyle = colour;
  ctx.fillText(text, px, py);
  ctx.restore();
}

/**
 * Text with subscripts, e.g. `c_M/c_A = 0.25` written as [['c'], ['M', 'sub'], ['/c'],
 * ['A', 'sub'], [' = 0.25']], aligned left or right of `px`, baseline-bottom at `py`.
 */
function subscriptText(ctx, parts, px, py, colour, align = 'left') {
  const base = ctx.font;
  const small = base.replace(/(\d+)px/, (_, n) => `${Math.round(Number(n) * 0.78)}px`);
  const width = (t, sub) => {
    ctx.font = sub ? small : base;
    return ctx.measureText(t).width;
  };
  const total = parts.reduce((w, [t, sub]) => w + width(t, sub), 0);
  let x = align === 'right' ? px - total : px;
  ctx.save();
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  for (const [t, sub] of parts) {
    ctx.font = sub ? small : base;
    haloText(ctx, t, x, py + (sub ? 3 : 0), colour);
    x += ctx.measureText(t).width;
  }
  ctx.restore();
  ctx.font = base;
}

/** The width of `subscriptText`'s parts in the current font. */
function partsWidth(ctx, parts) {
  const base = ctx.font;
  const small = base.replace(/(\d+)px/, (_, n) => `${Math.round(Number(n) * 0.78)}px`);
  let w = 0;
  for (const [t, sub] of parts) {
    ctx.font = sub ? small : base;
    w += ctx.measureText(t).width;
  }
  ctx.font = base;
  return w;
}

const ratioLabel = (k) => [['c'], ['M', 'sub'], ['/c'], ['A', 'sub'], [` = ${k}`]];

function clipTo(ctx, box) {
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.clip();
}

function star(ctx, px, py, r) {
  ctx.beginPath();
  for (let k = 0; k < 10; k++) {
    const a = -Math.PI / 2 + (k * Math.PI) / 5;
    const rr = k % 2 === 0 ? r : r * 0.45;
    ctx.lineTo(px + rr * Math.cos(a), py + rr * Math.sin(a));
  }
  ctx.closePath();
}

// ---------------------------------------------------------------- Fig. 3: Γ against σ
const FIG3 = { width: 640, height: 380, box: { left: 56, top: 12, width: 560, height: 318 } };
const fig3Ctx = setupCanvas($('fig3'), FIG3.width, FIG3.height);
const SIGMA_MAX = 10;
const GAMMA_MAX = 1.2;
// σ from 0.001 (Γ at its σ → 0 value to the eye) to 10 in steps of 0.025.
const SIGMAS = [0.001, ...Array.from({ length: 400 }, (_, k) => 0.025 * (k + 1))];
const R0_FAMILY = [0.1, 1, 3, 5, 10];
const RATIO_FAMILY = [0, 0.25, 0.5, 0.75, 1];

function computeFig3() {
  const costs = costsOption();
  const curve = (radius, c) => fisst.bernoulliThresholdCurve({ sigmas: SIGMAS, radius, costs: c });
  const mmol = state.preset === 'mmol';
  state.fig3 = {
    current: curve(state.r0, costs),
    // The r0 family at the current costs (Fig. 3a; Fig. 3b solid), and for MMOL the c_M/c_A
    // family at the current r0 (Fig. 3b dotted; only the ratio matters).
    r0Family: R0_FAMILY.map((r) => ({ r, gamma: curve(r, costs) })),
    ratioFamily: mmol
      ? RATIO_FAMILY.map((k) => ({ k, gamma: curve(state.r0, { mmol: { asset: 1, countermeasure: k } }) }))
      : [],
    gammaAt1: fisst.bernoulliThresholdCurve({ sigmas: [1], radius: state.r0, costs })[0],
    // σ = r0/1000: q = P(χ²₁ > 10⁶) = 0 in double precision, so this is Γ's floor.
    floor: fisst.bernoulliThresholdCurve({ sigmas: [state.r0 * 1e-3], radius: state.r0, costs })[0],
    qAt1: fisst.probabilityOutsideBall({ density: { mean: [0], cov: 1 }, center: [0], radius: state.r0 }),
  };
}

/** Where to write a curve's label: its right end, or where it leaves the plot at the top. */
function labelAnchor(gamma) {
  let i = gamma.length - 1;
  while (i > 0 && !(gamma[i] <= GAMMA_MAX - 0.02)) i--;
  return i;
}

function drawFig3() {
  computeFig3();
  const ctx = fig3Ctx;
  const { box } = FIG3;
  const f = state.fig3;
  ctx.clearRect(0, 0, FIG3.width, FIG3.height);
  const x = scale(0, SIGMA_MAX, box.left, box.left + box.width);
  const y = scale(0, GAMMA_MAX, box.top + box.height, box.top);
  // Γ > 1: never reported.
  ctx.fillStyle = '#fde2e2';
  ctx.fillRect(box.left, y(GAMMA_MAX), box.width, y(1) - y(GAMMA_MAX));
  ctx.strokeStyle = '#e4e7eb';
  ctx.lineWidth = 1;
  for (const t of ticks(0, GAMMA_MAX, 6)) {
    ctx.beginPath();
    ctx.moveTo(box.left, y(t));
    ctx.lineTo(box.left + box.width, y(t));
    ctx.stroke();
  }
  drawAxes(ctx, box, x, y, {
    xTicks: ticks(0, SIGMA_MAX, 10), yTicks: ticks(0, GAMMA_MAX, 6),
    xLabel: 'σ, standard deviation of the spatial density', yLabel: 'reporting threshold Γ',
    fmt: (v) => (Number.isInteger(v) ? `${v}` : v.toFixed(1)),
  });
  ctx.save();
  clipTo(ctx, box);
  ctx.font = '11px system-ui, sans-serif';
  // the conventional threshold
  ctx.strokeStyle = RED;
  ctx.lineWidth = 1.5;
  ctx.setLineDash([6, 4]);
  ctx.beginPath();
  ctx.moveTo(box.left, y(0.5));
  ctx.lineTo(box.left + box.width, y(0.5));
  ctx.stroke();
  ctx.setLineDash([]);
  // families
  ctx.lineWidth = 1.3;
  ctx.strokeStyle = GREY;
  for (const { gamma } of f.r0Family) polyline(ctx, SIGMAS, gamma, x, y);
  ctx.strokeStyle = AMBER;
  ctx.setLineDash([2, 3]);
  ctx.lineWidth = 1.6;
  for (const { gamma } of f.ratioFamily) polyline(ctx, SIGMAS, gamma, x, y);
  ctx.setLineDash([]);
  // the current settings
  ctx.strokeStyle = BLUE;
  ctx.lineWidth = 3;
  polyline(ctx, SIGMAS, f.current, x, y);
  const marker = f.gammaAt1 <= GAMMA_MAX && f.gammaAt1 >= 0;
  if (marker) {
    ctx.fillStyle = BLUE;
    ctx.beginPath();
    ctx.arc(x(1), y(f.gammaAt1), 5, 0, 2 * Math.PI);
    ctx.fill();
    ctx.strokeStyle = '#fff';
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }
  // Labels in order of priority, each nudged up or down (or dropped) to keep clear of the others.
  const placed = [];
  const place = (left, bottom, w, h) => {
    for (const dy of [0, -12, 12, -24, 24]) {
      const r = { l: left, t: bottom + dy - h, r: left + w, b: bottom + dy };
      if (r.t < box.top || r.b > box.top + box.height) continue;
      if (placed.every((o) => r.l >= o.r || r.r <= o.l || r.t >= o.b || r.b <= o.t)) {
        placed.push(r);
        return dy;
      }
    }
    return null;
  };
  ctx.textBaseline = 'bottom';
  ctx.textAlign = 'left';
  const conventional = 'conventional 0.5';
  const cw = ctx.measureText(conventional).width;
  place(box.left + box.width * 0.55, y(0.5) - 3, cw, 13);
  haloText(ctx, conventional, box.left + box.width * 0.55, y(0.5) - 3, RED);
  if (marker) {
    ctx.font = '600 12px system-ui, sans-serif';
    const t = `Γ = ${gammaText(f.gammaAt1)} at σ = 1`;
    const w = ctx.measureText(t).width;
    const bottom = f.gammaAt1 > 1.05 ? y(f.gammaAt1) + 20 : y(f.gammaAt1) - 6;
    const dy = place(x(1) + 8, bottom, w, 14) ?? 0;
    ctx.textAlign = 'left';
    haloText(ctx, t, x(1) + 8, bottom + dy, BLUE);
  }
  ctx.font = '11px system-ui, sans-serif';
  // The c_M/c_A curves are labelled where they start (Γ → c_M/c_A as σ → 0).
  for (const { k } of f.ratioFamily) {
    const parts = ratioLabel(k);
    const w = partsWidth(ctx, parts);
    const [left, bottom] = k > 0 ? [box.left + 4, y(k) - 2] : [box.left + box.width - 4 - w, y(0) - 3];
    const dy = place(left, bottom, w, 13);
    if (dy !== null) subscriptText(ctx, parts, left, bottom + dy, AMBER);
  }
  // The r0 curves at their right end, or where they leave the plot at the top.
  for (const { r, gamma } of f.r0Family) {
    const i = labelAnchor(gamma);
    const t = `r₀ = ${r}`;
    const w = ctx.measureText(t).width;
    const right = Math.min(x(SIGMAS[i]), box.left + box.width - 4);
    const bottom = Math.max(y(gamma[i]), box.top + 14) - 2;
    const dy = place(right - w, bottom, w, 13);
    ctx.textAlign = 'left';
    if (dy !== null) haloText(ctx, t, right - w, bottom + dy, '#52606d');
  }
  ctx.restore();
  $('gamma').textContent = gammaText(f.gammaAt1);
  $('gamma-floor').textContent = gammaText(f.floor);
  $('q-sigma1').textContent = fmt(f.qAt1, 6);
  const mmol = state.preset === 'mmol';
  $('fig3-legend-ratio').style.display = mmol ? '' : 'none';
  const ratio = state.cM / state.cA;
  $('fig3-family-r0').innerHTML = mmol
    ? `r<sub>0</sub> = 0.1, 1, 3, 5, 10 at c<sub>M</sub>/c<sub>A</sub> = ${fmt(ratio, 3)}`
    : 'r<sub>0</sub> = 0.1, 1, 3, 5, 10';
  $('fig3-family-ratio').innerHTML = `c<sub>M</sub>/c<sub>A</sub> = 0, 0.25, 0.5, 0.75, 1 at r<sub>0</sub> = ${fmt(state.r0, 3)}`;
}

// ---------------------------------------------------------------- Fig. 2: expected loss against p
const FIG2 = { width: 640, height: 340, box: { left: 56, top: 22, width: 560, height: 270 } };
const fig2Ctx = setupCanvas($('fig2'), FIG2.width, FIG2.height);
const PS = Array.from({ length: 1001 }, (_, k) => k / 1000);

function computeFig2() {
  const costs = costsOption();
  const s2 = state.sigma * state.sigma;
  const e = fisst.bernoulliEstimate({
    existence: 0.5, density: { mean: [0], cov: [[s2]] }, radius: state.r0, costs,
  });
  const q = e.missProbability;
  const optimal = fisst.bernoulliLossCurve({ existences: PS, missProbability: q, costs });
  const conventional = fisst.bernoulliLossCurve({ existences: PS, missProbability: q, costs, threshold: 0.5 });
  // Where the optimal rule's expected loss is strictly below the conventional one's.
  const wins = [];
  let gain = 0;
  let gainAt = null;
  for (let k = 0; k < PS.length; k++) {
    const d = conventional.rule[k] - optimal.rule[k];
    if (d > 0) wins.push(k);
    if (d > gain) { gain = d; gainAt = PS[k]; }
  }
  state.fig2 = {
    sigma: state.sigma,
    missProbability: q,
    threshold: e.threshold,
    optimal,
    conventional,
    wins,
    band: wins.length ? [PS[wins[0]], PS[wins.at(-1)]] : null,
    gain,
    gainAt,
  };
}

/** Draws the rule's loss, broken where it switches between ρ_∅ and ρ_{a*}. */
function ruleLine(ctx, curve, x, y) {
  ctx.beginPath();
  let prev = null;
  for (let k = 0; k < PS.length; k++) {
    const branch = curve.rule[k] === curve.empty[k] ? 'empty' : 'singleton';
    if (branch !== prev) ctx.moveTo(x(PS[k]), y(curve.rule[k]));
    else ctx.lineTo(x(PS[k]), y(curve.rule[k]));
    prev = branch;
  }
  ctx.stroke();
}

function drawFig2() {
  computeFig2();
  const ctx = fig2Ctx;
  const { box } = FIG2;
  const f = state.fig2;
  ctx.clearRect(0, 0, FIG2.width, FIG2.height);
  const all = [f.optimal.empty, f.optimal.singleton].flat();
  // A round top and tick step: at most 10 ticks.
  const peak = Math.max(...all, 0.05);
  const yStep = [0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5].find((st) => peak / st <= 10) ?? 10;
  const top = Math.ceil(peak / yStep - 1e-9) * yStep;
  const x = scale(0, 1, box.left, box.left + box.width);
  const y = scale(0, top, box.top + box.height, box.top);
  // the band where the optimal rule wins, shaded grid cell by grid cell (runs of wins)
  ctx.fillStyle = '#bbf7d0';
  const h = (PS[1] - PS[0]) / 2;
  for (let i = 0; i < f.wins.length;) {
    let j = i;
    while (j + 1 < f.wins.length && f.wins[j + 1] === f.wins[j] + 1) j++;
    const a = Math.max(PS[f.wins[i]] - h, 0);
    const b = Math.min(PS[f.wins[j]] + h, 1);
    ctx.fillRect(x(a), box.top, x(b) - x(a), box.height);
    i = j + 1;
  }
  const yTicks = ticks(0, top, Math.round(top / yStep));
  ctx.strokeStyle = '#e4e7eb';
  ctx.lineWidth = 1;
  for (const t of yTicks) {
    ctx.beginPath();
    ctx.moveTo(box.left, y(t));
    ctx.lineTo(box.left + box.width, y(t));
    ctx.stroke();
  }
  drawAxes(ctx, box, x, y, {
    xTicks: ticks(0, 1, 10), yTicks,
    xLabel: 'existence probability p',
    yLabel: state.preset === 'mpe' ? 'probability of error' : 'mean operational loss',
    fmt: (v) => fmt(v, 2),
  });
  ctx.save();
  clipTo(ctx, box);
  ctx.lineWidth = 1.3;
  ctx.strokeStyle = GREY;
  ctx.setLineDash([6, 4]);
  polyline(ctx, PS, f.optimal.empty, x, y);
  ctx.setLineDash([2, 3]);
  polyline(ctx, PS, f.optimal.singleton, x, y);
  ctx.setLineDash([]);
  // optimal solid, conventional dashed on top: where they agree both show
  ctx.lineWidth = 3;
  ctx.strokeStyle = BLUE;
  ruleLine(ctx, f.optimal, x, y);
  ctx.lineWidth = 2;
  ctx.strokeStyle = RED;
  ctx.setLineDash([7, 5]);
  ruleLine(ctx, f.conventional, x, y);
  ctx.setLineDash([]);
  ctx.restore();
  // the two thresholds
  ctx.save();
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'bottom';
  const mark = (p, colour, text, align) => {
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.2;
    ctx.setLineDash([4, 3]);
    ctx.beginPath();
    ctx.moveTo(x(p), box.top);
    ctx.lineTo(x(p), box.top + box.height);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.textAlign = align;
    haloText(ctx, text, x(p) + (align === 'left' ? 3 : -3), box.top - 3, colour);
  };
  const g = f.threshold;
  const gLeft = g < 0.5;
  mark(0.5, RED, 'Γ₂ = 0.5', gLeft ? 'left' : 'right');
  if (g >= 0 && g <= 1) mark(g, BLUE, `Γ₁ = ${gammaText(g)}`, gLeft ? 'right' : 'left');
  else {
    ctx.textAlign = 'right';
    haloText(ctx, `Γ₁ = ${gammaText(g)}: the optimal rule ${g > 1 ? 'never reports' : 'always reports'}`,
      box.left + box.width, box.top - 3, BLUE);
  }
  ctx.restore();
  $('fig2-q').textContent = fmt(f.missProbability, 6);
  $('fig2-gamma').textContent = gammaText(g);
  $('band').textContent = f.band ? `${f.band[0].toFixed(3)} ≤ p ≤ ${f.band[1].toFixed(3)}` : 'nowhere: Γ = 0.5';
  $('gain').textContent = f.band ? `${fmt(f.gain, 4)} at p = ${f.gainAt.toFixed(3)}` : '0';
}

// ---------------------------------------------------------------- the 2D view
const EXTENT = 5;
const GRID_COUNT = 101;
const GRID = { x: [-EXTENT, EXTENT, GRID_COUNT], y: [-EXTENT, EXTENT, GRID_COUNT] };
const STEP = (2 * EXTENT) / (GRID_COUNT - 1);
// The heat image's pixels are centred on the grid points: the view spans half a step more.
const LO = -EXTENT - STEP / 2;
const HI = EXTENT + STEP / 2;
const VIEW = { width: 580, height: 560, box: { left: 44, top: 10, width: 520, height: 520 } };
const { box } = VIEW;
const px = scale(LO, HI, box.left, box.left + box.width);
const py = scale(LO, HI, box.top + box.height, box.top);
const viewCtx = setupCanvas($('view'), VIEW.width, VIEW.height);
const heat = { key: null, image: null, ms: null };

const RAMP = [[255, 255, 255], [224, 236, 252], [176, 206, 245], [111, 160, 230], [56, 108, 200]];
// 256 colours of the ramp, indexed by round(255 · sqrt(density / max)) (display only).
const LUT = Array.from({ length: 256 }, (_, n) => {
  const u = (n / 255) * (RAMP.length - 1);
  const k = Math.min(Math.floor(u), RAMP.length - 2);
  const f = u - k;
  return RAMP[k].map((c, i) => Math.round(c + f * (RAMP[k + 1][i] - c)));
});
const heatCanvas = document.createElement('canvas');
heatCanvas.width = GRID_COUNT;
heatCanvas.height = GRID_COUNT;
const heatCtx = heatCanvas.getContext('2d');
const heatData = heatCtx.createImageData(GRID_COUNT, GRID_COUNT);

/** Paints the GRID_COUNT² density values (row-major, y outer and growing upwards). */
function paintHeat(values) {
  const n = GRID_COUNT;
  let vmax = 0;
  for (const v of values) if (v > vmax) vmax = v;
  const scaleBy = vmax > 0 ? 1 / vmax : 0;
  const out = heatData.data;
  for (let j = 0; j < n; j++) {
    const row = n - 1 - j; // canvas rows grow downwards; y grows upwards
    for (let i = 0; i < n; i++) {
      const [r, g, b] = LUT[Math.round(255 * Math.sqrt(values[j * n + i] * scaleBy))];
      const k = 4 * (row * n + i);
      out[k] = r;
      out[k + 1] = g;
      out[k + 2] = b;
      out[k + 3] = 255;
    }
  }
  heatCtx.putImageData(heatData, 0, 0);
  return heatCanvas;
}

function computeView() {
  const mix = mixture();
  const density = { mixture: mix };
  const costs = costsOption();
  const estimate = fisst.bernoulliEstimate({ existence: state.p, density, radius: state.r0, costs });
  const total = mix.reduce((s, c) => s + c.weight, 0);
  const mean = [0, 1].map((i) => mix.reduce((s, c) => s + c.weight * c.mean[i], 0) / total);
  const qMean = fisst.probabilityOutsideBall({ density, center: mean, radius: state.r0 });
  const key = JSON.stringify(mix);
  if (heat.key !== key) {
    const t0 = performance.now();
    heat.image = paintHeat(fisst.mixtureDensityGrid({ mixture: mix, grid: GRID }));
    heat.ms = performance.now() - t0;
    timing.heatMs = heat.ms;
    heat.key = key;
  }
  state.view = { mixture: mix, estimate, mean, qMean };
}

function drawView() {
  computeView();
  const ctx = viewCtx;
  const v = state.view;
  const e = v.estimate;
  ctx.clearRect(0, 0, VIEW.width, VIEW.height);
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(heat.image, box.left, box.top, box.width, box.height);
  drawAxes(ctx, box, px, py, {
    xTicks: ticks(-4, 4, 4), yTicks: ticks(-4, 4, 4), xLabel: 'x', yLabel: 'y', fmt: (t) => t.toFixed(0),
  });
  ctx.save();
  clipTo(ctx, box);
  const unit = px(1) - px(0);
  // components: 1σ (solid) and 2σ (dashed) ellipses
  v.mixture.forEach((c, i) => {
    const colour = COMPONENT_COLOURS[i % COMPONENT_COLOURS.length];
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.6;
    ctx.beginPath();
    ellipsePath(ctx, px, py, c.mean, c.cov, 1);
    ctx.stroke();
    ctx.setLineDash([5, 4]);
    ctx.lineWidth = 1.2;
    ctx.beginPath();
    ellipsePath(ctx, px, py, c.mean, c.cov, 2);
    ctx.stroke();
    ctx.setLineDash([]);
  });
  // the mixture mean and its ball
  const [mx, my] = [px(v.mean[0]), py(v.mean[1])];
  ctx.strokeStyle = '#323f4b';
  ctx.lineWidth = 1.6;
  ctx.setLineDash([7, 5]);
  ctx.beginPath();
  ctx.arc(mx, my, state.r0 * unit, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  ctx.moveTo(mx - 6, my - 6);
  ctx.lineTo(mx + 6, my + 6);
  ctx.moveTo(mx + 6, my - 6);
  ctx.lineTo(mx - 6, my + 6);
  ctx.stroke();
  // a* and its ball: green when reported, red outline when not
  const [ax, ay] = [px(e.mmuc[0]), py(e.mmuc[1])];
  ctx.fillStyle = e.declare ? 'rgba(16, 185, 129, 0.22)' : 'rgba(148, 163, 184, 0.22)';
  ctx.strokeStyle = e.declare ? GREEN : RED;
  ctx.lineWidth = 2.2;
  ctx.beginPath();
  ctx.arc(ax, ay, state.r0 * unit, 0, 2 * Math.PI);
  ctx.fill();
  ctx.stroke();
  // component handles
  ctx.font = '11px system-ui, sans-serif';
  v.mixture.forEach((c, i) => {
    const colour = COMPONENT_COLOURS[i % COMPONENT_COLOURS.length];
    const [cx, cy] = [px(c.mean[0]), py(c.mean[1])];
    ctx.beginPath();
    ctx.arc(cx, cy, 8, 0, 2 * Math.PI);
    ctx.fillStyle = '#fff';
    ctx.fill();
    ctx.strokeStyle = colour;
    ctx.lineWidth = 3;
    ctx.stroke();
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    haloText(ctx, `w ${c.weight.toFixed(2)}`, cx + 11, cy - 11, colour);
  });
  star(ctx, ax, ay, 9);
  ctx.fillStyle = e.declare ? GREEN : RED;
  ctx.fill();
  ctx.strokeStyle = '#fff';
  ctx.lineWidth = 1.2;
  ctx.stroke();
  // labels
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = 'center';
  // a*'s label under its ball, the mean's above its own (both kept inside the plot)
  const radius = state.r0 * unit;
  const inside = (yy) => Math.min(Math.max(yy, box.top + 4), box.top + box.height - 18);
  haloText(ctx, `a*: q = ${fmt(e.missProbability, 3)}`, ax, inside(ay + radius + 4), e.declare ? GREEN : RED);
  const sameSpot = Math.hypot(ax - mx, ay - my) < 30;
  if (!sameSpot) haloText(ctx, `mean: q = ${fmt(v.qMean, 3)}`, mx, inside(my - radius - 18), '#323f4b');
  ctx.restore();
  drawGauge();
  // readouts
  const g = e.threshold;
  const decision = $('decision');
  decision.textContent = decisionText(e, state.p);
  decision.className = e.declare ? 'report' : 'nothing';
  $('gamma-2d').textContent = gammaText(g);
  $('mmuc').textContent = pointText(e.mmuc);
  $('q-mmuc').textContent = fmt(e.missProbability, 6);
  $('mean').textContent = pointText(v.mean);
  $('q-mean').textContent = fmt(v.qMean, 6);
  $('rho').textContent = `${fmt(e.expectedLossEmpty, 4)}, ${fmt(e.expectedLossSingleton, 4)}`;
}

function decisionText(e, p) {
  return e.declare
    ? `report {a*}: p = ${fmt(p, 3)} > Γ = ${gammaText(e.threshold)}`
    : `report nothing: p = ${fmt(p, 3)} ≤ Γ = ${gammaText(e.threshold)}`;
}

// ---------------------------------------------------------------- the p-against-Γ gauge
const GAUGE = { width: 420, height: 66, box: { left: 12, top: 24, width: 396, height: 14 } };
const gaugeCtx = setupCanvas($('gauge'), GAUGE.width, GAUGE.height);

function drawGauge() {
  const ctx = gaugeCtx;
  const b = GAUGE.box;
  const e = state.view.estimate;
  const x = scale(0, 1, b.left, b.left + b.width);
  ctx.clearRect(0, 0, GAUGE.width, GAUGE.height);
  const g = Math.min(Math.max(e.threshold, 0), 1);
  ctx.fillStyle = '#fecaca';
  ctx.fillRect(b.left, b.top, x(g) - b.left, b.height);
  ctx.fillStyle = '#bbf7d0';
  ctx.fillRect(x(g), b.top, b.left + b.width - x(g), b.height);
  ctx.strokeStyle = '#9aa5b1';
  ctx.lineWidth = 1;
  ctx.strokeRect(b.left, b.top, b.width, b.height);
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'center';
  if (x(g) - b.left > 90) haloText(ctx, 'report nothing', (b.left + x(g)) / 2, b.top + b.height / 2, '#991b1b');
  if (b.left + b.width - x(g) > 70) haloText(ctx, 'report a*', (x(g) + b.left + b.width) / 2, b.top + b.height / 2, '#065f46');
  // 0.5 and Γ
  ctx.textBaseline = 'top';
  ctx.strokeStyle = RED;
  ctx.setLineDash([3, 2]);
  ctx.beginPath();
  ctx.moveTo(x(0.5), b.top - 3);
  ctx.lineTo(x(0.5), b.top + b.height + 3);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.fillStyle = RED;
  ctx.fillText('0.5', x(0.5), b.top + b.height + 5);
  ctx.strokeStyle = BLUE;
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x(g), b.top - 4);
  ctx.lineTo(x(g), b.top + b.height + 4);
  ctx.stroke();
  const gLabelX = Math.min(Math.max(x(g), b.left + 34), b.left + b.width - 34);
  const gLabel = e.threshold > 1 ? 'Γ > 1' : e.threshold < 0 ? 'Γ < 0' : `Γ = ${fmt(e.threshold, 3)}`;
  if (Math.abs(gLabelX - x(0.5)) > 44) {
    ctx.fillStyle = BLUE;
    ctx.fillText(gLabel, gLabelX, b.top + b.height + 5);
  }
  ctx.fillStyle = '#52606d';
  ctx.textAlign = 'left';
  ctx.fillText('0', b.left, b.top + b.height + 5);
  ctx.textAlign = 'right';
  ctx.fillText('1', b.left + b.width, b.top + b.height + 5);
  ctx.textAlign = 'center';
  // p
  const p = x(state.p);
  ctx.fillStyle = '#1f2933';
  ctx.beginPath();
  ctx.moveTo(p, b.top - 1);
  ctx.lineTo(p - 6, b.top - 11);
  ctx.lineTo(p + 6, b.top - 11);
  ctx.closePath();
  ctx.fill();
  ctx.textBaseline = 'bottom';
  ctx.textAlign = state.p > 0.85 ? 'right' : state.p < 0.15 ? 'left' : 'center';
  ctx.fillText(`p = ${fmt(state.p, 3)}`, p + (state.p > 0.85 ? -8 : state.p < 0.15 ? 8 : 0), b.top - 12);
}

// ---------------------------------------------------------------- state for tests and readers
function publish() {
  const v = state.view;
  $('threshold-state').textContent = JSON.stringify({
    preset: state.preset,
    costs: costsOption(),
    r0: state.r0,
    cA: state.cA,
    cM: state.cM,
    fig3: { gammaAt1: state.fig3.gammaAt1, qAt1: state.fig3.qAt1, floor: state.fig3.floor },
    fig2: {
      sigma: state.fig2.sigma, missProbability: state.fig2.missProbability,
      threshold: state.fig2.threshold, band: state.fig2.band, gain: state.fig2.gain,
    },
    view: {
      p: state.p, spread: state.spread, scene: state.scene, mixture: v.mixture,
      estimate: v.estimate, mean: v.mean, qMean: v.qMean,
      box, domain: [LO, HI],
    },
  }, null, 1);
}

// ---------------------------------------------------------------- updates
const DRAW = { fig3: drawFig3, fig2: drawFig2, view: drawView };

/** Redraws the given panels, timing each and the whole update. */
function update(...panels) {
  const t0 = performance.now();
  for (const panel of panels) timed(panel, DRAW[panel]);
  publish();
  const total = performance.now() - t0;
  timing.last.total = total;
  timing.history.total.push(total);
  if (timing.history.total.length > HISTORY) timing.history.total.shift();
  $('redraw-fig3').textContent = msText(timing.last.fig3);
  $('redraw-fig2').textContent = msText(timing.last.fig2);
  $('redraw-view').textContent = msText(timing.last.view);
  $('redraw-total').textContent = msText(total);
}

function costsHtml() {
  const c = (ij) => `c<sub>${ij}</sub>`;
  if (state.preset === 'mpe') {
    return `${c('00')} = 0, ${c('01')} = 1 (missed target), ${c('10')} = 1 (false alarm), ${c('11')} = 0, `
      + 'c = 1 (reported point farther than r<sub>0</sub>): the expected loss is the probability '
      + 'of error (Corollary IV.1).';
  }
  const a = fmt(state.cA, 3);
  const m = fmt(state.cM, 3);
  return `${c('00')} = 0, ${c('01')} = ${c('A')} = ${a} (asset lost), ${c('10')} = ${c('11')} = ${c('M')} = ${m} `
    + `(countermeasure spent), c = ${c('A')} = ${a} (spent farther than r<sub>0</sub>: asset lost too); `
    + `${c('M')}/${c('A')} = ${fmt(state.cM / state.cA, 3)} (Corollary IV.2).`;
}

function readCosts() {
  state.r0 = Number($('r0').value);
  state.cA = Number($('c-a').value);
  state.cM = Number($('c-m').value);
  $('r0-out').value = fmt(state.r0, 3);
  $('c-a-out').value = fmt(state.cA, 3);
  $('c-m-out').value = fmt(state.cM, 3);
  const mmol = state.preset === 'mmol';
  for (const id of ['c-a', 'c-m']) {
    $(id).disabled = !mmol;
    $(`${id}-label`).classList.toggle('disabled', !mmol);
  }
  $('preset-mpe').setAttribute('aria-pressed', String(!mmol));
  $('preset-mmol').setAttribute('aria-pressed', String(mmol));
  $('costs-text').innerHTML = costsHtml();
}

function onCosts() {
  readCosts();
  update('fig3', 'fig2', 'view');
}

function setPreset(preset) {
  state.preset = preset;
  onCosts();
}

function setScene(name) {
  state.scene = name;
  state.components = copyScene(name);
  for (const n of Object.keys(SCENES)) $(`scene-${n}`).setAttribute('aria-pressed', String(n === name));
  update('view');
}

$('preset-mpe').addEventListener('click', () => setPreset('mpe'));
$('preset-mmol').addEventListener('click', () => setPreset('mmol'));
for (const id of ['r0', 'c-a', 'c-m']) $(id).addEventListener('input', onCosts);
$('sigma').addEventListener('input', () => {
  state.sigma = Number($('sigma').value);
  $('sigma-out').value = fmt(state.sigma, 3);
  update('fig2');
});
$('p').addEventListener('input', () => {
  state.p = Number($('p').value);
  $('p-out').value = fmt(state.p, 3);
  update('view');
});
$('spread').addEventListener('input', () => {
  state.spread = Number($('spread').value);
  $('spread-out').value = fmt(state.spread, 3);
  update('view');
});
for (const n of Object.keys(SCENES)) $(`scene-${n}`).addEventListener('click', () => setScene(n));

// ---------------------------------------------------------------- dragging the components
// Pointer events cover mouse, pen and touch. A press within reach of a component's mean grabs
// it (keeping the grab offset).
const canvas = $('view');
const drag = { id: null, index: null, offset: [0, 0] };
const REACH = 26; // px

function worldPoint(event) {
  // The canvas may be drawn smaller than its layout size on narrow screens (max-width: 100%).
  const rect = canvas.getBoundingClientRect();
  const sx = VIEW.width / rect.width;
  const sy = VIEW.height / rect.height;
  return [px.invert((event.clientX - rect.left) * sx), py.invert((event.clientY - rect.top) * sy)];
}

function nearest(event) {
  const rect = canvas.getBoundingClientRect();
  const cx = (event.clientX - rect.left) * (VIEW.width / rect.width);
  const cy = (event.clientY - rect.top) * (VIEW.height / rect.height);
  let best = null;
  let bestD = REACH;
  state.components.forEach((c, i) => {
    const d = Math.hypot(px(c.mean[0]) - cx, py(c.mean[1]) - cy);
    if (d <= bestD) { best = i; bestD = d; }
  });
  return best;
}

function moveComponent(x, y) {
  const clamp = (v) => Math.min(Math.max(v, -EXTENT), EXTENT);
  state.components[drag.index].mean = [clamp(x), clamp(y)];
  update('view');
}

canvas.addEventListener('pointerdown', (event) => {
  if (drag.id !== null) return;
  const i = nearest(event);
  if (i === null) return;
  const [x, y] = worldPoint(event);
  const m = state.components[i].mean;
  drag.index = i;
  drag.offset = [m[0] - x, m[1] - y];
  drag.id = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  canvas.classList.add('dragging');
  event.preventDefault();
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== drag.id) {
    if (drag.id === null) canvas.classList.toggle('over', nearest(event) !== null);
    return;
  }
  const [x, y] = worldPoint(event);
  moveComponent(x + drag.offset[0], y + drag.offset[1]);
});
const endDrag = (event) => {
  if (event.pointerId !== drag.id) return;
  drag.id = null;
  drag.index = null;
  canvas.classList.remove('dragging');
  if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
};
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

// ---------------------------------------------------------------- first draw
readCosts();
update('fig3', 'fig2', 'view');
document.body.dataset.ready = 'true';

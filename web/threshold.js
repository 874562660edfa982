// The optimal Bernoulli reporting threshold (paper 000: Theorem III.3, Section IV, Figs 2–3).
// Every Γ, q, a* and expected loss comes from the fisst package (bernoulliThresholdCurve,
// bernoulliEstimate, bernoulliLossCurve, probabilityOutsideBall, mixtureDensityGrid); this
// file only says what to compute and draw (the drawing, controls and timing are in lib/).
import init, * as fisst from 'fisst';
import { chart, markX } from './lib/chart.js';
import { clipTo, cross, dot, ellipsePath, haloText, labelPlacer, richText, richTextWidth, sceneView, starPath, thresholdGauge } from './lib/scene.js';
import { cellGrid, colorbar, heatImage } from './lib/colormap.js';
import { $, choice, downloads, fmt, nextFrame, pageReady, pointText, slider, timings, toCSV, urlState } from './lib/page.js';

await init();

const [BLUE, RED, GREY, AMBER, GREEN] = ['#0072b2', '#d55e00', '#7b8794', '#e69f00', '#009e73'];
const COMPONENT_COLOURS = ['#7c3aed', '#cc79a7', '#0e7490', '#4d7c0f'];

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
const EXTENT = 5;
const validMeans = (m) => Array.isArray(m) && m.every((p) => Array.isArray(p) && p.length === 2 && p.every((v) => Number.isFinite(v) && Math.abs(v) <= EXTENT));

// Every setting is in the URL; `means` are the dragged component means (null: the scene's).
const url = urlState(
  { preset: 'mpe', r0: 1, cA: 0.9, cM: 0.1, sigma: 1, p: 0.6, spread: 1, scene: 'three', means: null },
  { check: { means: (m) => m === null || validMeans(m) } },
);
const state = url.values;
const sceneMeans = () => SCENES[state.scene].map((c) => [...c.mean]);
if (!SCENES[state.scene] || (state.means && state.means.length !== SCENES[state.scene].length)) {
  state.scene = SCENES[state.scene] ? state.scene : 'three';
  state.means = null;
}
const means = state.means ?? sceneMeans();
const results = { fig3: null, fig2: null, view: null };

const costsOption = () => (state.preset === 'mpe' ? 'mpe' : { mmol: { asset: state.cA, countermeasure: state.cM } });
/** The mixture as the package takes it: the scene's components, dragged and spread. */
const mixture = () => SCENES[state.scene].map((c, i) => ({ weight: c.weight, mean: [...means[i]], cov: c.cov.map((row) => row.map((v) => v * state.spread)) }));
const gammaText = (g) => (g === Infinity ? '∞ (never reports)' : g === -Infinity ? '−∞ (always reports)' : fmt(g, 4));
const gammaValue = (g) => (g >= 10 ? '≥ 10' : g <= -10 ? '≤ −10' : fmt(g, 4));
const timer = timings('threshold');
timer.badge($('redraw-ms'), { fig3: 'Fig. 3', fig2: 'Fig. 2', view: '2D view', total: 'whole update' });

// ---------------------------------------------------------------- Fig. 3: Γ against σ
// σ from 0.001 (Γ at its σ → 0 value to the eye) to 10 in steps of 0.025.
const SIGMAS = [0.001, ...Array.from({ length: 400 }, (_, k) => 0.025 * (k + 1))];
const R0_FAMILY = [0.1, 1, 3, 5, 10];
const RATIO_FAMILY = [0, 0.25, 0.5, 0.75, 1];
const ratioParts = (k) => [['c'], ['M', 1], ['/c'], ['A', 1], [` = ${k}`]];
const clampCurve = (g) => g.map((v) => Math.min(Math.max(v, -10), 10));
let fig3 = null;

function makeFig3(mmol) {
  $('fig3').replaceChildren();
  const family = (label, colour, width, dash, legend = true) => ({ label, colour, width, dash, value: gammaValue, legend });
  return chart($('fig3'), {
    height: 360,
    x: { label: 'σ, standard deviation of the spatial density', range: [0, 10], format: (v) => fmt(v, 3) },
    y: { label: 'reporting threshold Γ', range: [0, 1.2], format: (v) => fmt(v, 2) },
    series: [
      { label: 'Γ &gt; 1: never reported', colour: 'transparent', width: 0, fill: '#fde2e2', fillTo: 1.2, value: () => '' },
      family('conventional 0.5', RED, 1.5, [6, 4], false),
      ...R0_FAMILY.map((r) => family(`r<sub>0</sub> = ${r}`, GREY, 1.3, [])),
      ...(mmol ? RATIO_FAMILY.map((k) => family(`c<sub>M</sub>/c<sub>A</sub> = ${k}`, AMBER, 1.6, [2, 3])) : []),
      family('Γ for your costs and r<sub>0</sub>', BLUE, 3, []),
    ],
    overlay: fig3Labels,
  });
}

function computeFig3() {
  const costs = costsOption();
  const curve = (radius, c) => fisst.bernoulliThresholdCurve({ sigmas: SIGMAS, radius, costs: c });
  const mmol = state.preset === 'mmol';
  results.fig3 = {
    current: curve(state.r0, costs),
    // The r0 family at the current costs (Fig. 3a; Fig. 3b solid), and for MMOL the c_M/c_A
    // family at the current r0 (Fig. 3b dotted; only the ratio matters).
    r0Family: R0_FAMILY.map((r) => ({ r, gamma: curve(r, costs) })),
    ratioFamily: mmol ? RATIO_FAMILY.map((k) => ({ k, gamma: curve(state.r0, { mmol: { asset: 1, countermeasure: k } }) })) : [],
    gammaAt1: fisst.bernoulliThresholdCurve({ sigmas: [1], radius: state.r0, costs })[0],
    // σ = r0/1000: q = P(χ²₁ > 10⁶) = 0 in double precision, so this is Γ's floor.
    floor: fisst.bernoulliThresholdCurve({ sigmas: [state.r0 * 1e-3], radius: state.r0, costs })[0],
    qAt1: fisst.probabilityOutsideBall({ density: { mean: [0], cov: 1 }, center: [0], radius: state.r0 }),
  };
}

/** The labels of Fig. 3: Γ at σ = 1, the families at their ends, each kept clear of the others. */
function fig3Labels({ ctx, x, y, box }) {
  const f = results.fig3;
  const place = labelPlacer(box);
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'bottom';
  ctx.textAlign = 'left';
  place(box.width * 0.55, y(0.5) - 3, ctx.measureText('conventional 0.5').width, 13);
  haloText(ctx, 'conventional 0.5', box.width * 0.55, y(0.5) - 3, RED);
  if (f.gammaAt1 <= 1.2 && f.gammaAt1 >= 0) {
    dot(ctx, x(1), y(f.gammaAt1), 5, BLUE, '#fff', 1.5);
    ctx.font = '600 12px system-ui, sans-serif';
    const t = `Γ = ${gammaText(f.gammaAt1)} at σ = 1`;
    const bottom = f.gammaAt1 > 1.05 ? y(f.gammaAt1) + 20 : y(f.gammaAt1) - 6;
    haloText(ctx, t, x(1) + 8, bottom + (place(x(1) + 8, bottom, ctx.measureText(t).width, 14) ?? 0), BLUE);
    ctx.font = '11px system-ui, sans-serif';
  }
  // The c_M/c_A curves where they start (Γ → c_M/c_A as σ → 0); the r0 curves at their right
  // end, or where they leave the plot at the top.
  for (const { k } of f.ratioFamily) {
    const w = richTextWidth(ctx, ratioParts(k));
    const [left, bottom] = k > 0 ? [4, y(k) - 2] : [box.width - 4 - w, y(0) - 3];
    const dy = place(left, bottom, w, 13);
    if (dy !== null) richText(ctx, ratioParts(k), left, bottom + dy, AMBER);
  }
  for (const { r, gamma } of f.r0Family) {
    let i = gamma.length - 1;
    while (i > 0 && !(gamma[i] <= 1.18)) i--;
    const t = `r₀ = ${r}`;
    const w = ctx.measureText(t).width;
    const right = Math.min(x(SIGMAS[i]), box.width - 4);
    const bottom = Math.max(y(gamma[i]), 14) - 2;
    const dy = place(right - w, bottom, w, 13);
    if (dy !== null) haloText(ctx, t, right - w, bottom + dy, '#52606d');
  }
}

function drawFig3() {
  computeFig3();
  const f = results.fig3;
  const mmol = state.preset === 'mmol';
  if (!fig3 || fig3.mmol !== mmol) fig3 = Object.assign(makeFig3(mmol), { mmol });
  const flat = (v) => SIGMAS.map(() => v);
  fig3.update([SIGMAS, flat(1), flat(0.5), ...f.r0Family.map((c) => clampCurve(c.gamma)),
    ...f.ratioFamily.map((c) => clampCurve(c.gamma)), clampCurve(f.current)]);
  $('gamma').textContent = gammaText(f.gammaAt1);
  $('gamma-floor').textContent = gammaText(f.floor);
  $('q-sigma1').textContent = fmt(f.qAt1, 6);
}

// ---------------------------------------------------------------- Fig. 2: expected loss against p
const PS = Array.from({ length: 1001 }, (_, k) => k / 1000);
let fig2Top = 1;
let fig2 = null;
/** Where a rule's loss switches between ρ_∅ and ρ_{a*}: the line is broken there. */
const switches = (curve) => PS.map((_, k) => k).filter((k) => k > 0 && (curve.rule[k] === curve.empty[k]) !== (curve.rule[k - 1] === curve.empty[k - 1]));
/** Fig. 2's chart (made on its first draw, after Fig. 3: the first figure comes sooner). */
const makeFig2 = () => chart($('fig2'), {
  height: 320,
  x: { label: 'existence probability p', range: [0, 1], format: (v) => fmt(v, 3) },
  y: { label: 'expected loss', range: () => [0, fig2Top], format: (v) => fmt(v, 3) },
  series: [
    { label: 'optimal is strictly better', colour: 'transparent', width: 0, fill: '#bbf7d0', fillTo: 0, value: () => 'yes' },
    { label: 'ρ<sub>∅</sub> (report nothing)', colour: GREY, width: 1.3, dash: [6, 4] },
    { label: 'ρ<sub>{a*}</sub> (report a*)', colour: GREY, width: 1.3, dash: [2, 3] },
    { label: 'optimal: report when p &gt; Γ', colour: BLUE, width: 3, breaks: () => switches(results.fig2.optimal) },
    { label: 'conventional: report when p &gt; 0.5', colour: RED, width: 2, dash: [7, 5], breaks: () => switches(results.fig2.conventional) },
  ],
  overlay(o) {
    if (!results.fig2) return;
    const g = results.fig2.threshold;
    markX(o, 0.5, { colour: RED, text: 'Γ₂ = 0.5', align: g < 0.5 ? 'left' : 'right' });
    if (g >= 0 && g <= 1) markX(o, g, { colour: BLUE, text: `Γ₁ = ${gammaText(g)}`, align: g < 0.5 ? 'right' : 'left' });
    else markX(o, 1, { colour: BLUE, line: false, text: `Γ₁ = ${gammaText(g)}: the optimal rule ${g > 1 ? 'never reports' : 'always reports'}`, align: 'right' });
  },
});

function drawFig2() {
  const costs = costsOption();
  const e = fisst.bernoulliEstimate({ existence: 0.5, density: { mean: [0], cov: [[state.sigma ** 2]] }, radius: state.r0, costs });
  const q = e.missProbability;
  const optimal = fisst.bernoulliLossCurve({ existences: PS, missProbability: q, costs });
  const conventional = fisst.bernoulliLossCurve({ existences: PS, missProbability: q, costs, threshold: 0.5 });
  // Where the optimal rule's expected loss is strictly below the conventional one's.
  const saving = PS.map((_, k) => conventional.rule[k] - optimal.rule[k]);
  const wins = PS.map((_, k) => k).filter((k) => saving[k] > 0);
  const best = saving.reduce((b, d, k) => (d > saving[b] ? k : b), 0);
  const f = (results.fig2 = { sigma: state.sigma, missProbability: q, threshold: e.threshold, optimal, conventional, band: wins.length ? [PS[wins[0]], PS[wins.at(-1)]] : null, gain: Math.max(saving[best], 0), gainAt: saving[best] > 0 ? PS[best] : null });
  // A round top and tick step: at most 10 ticks.
  const peak = Math.max(...optimal.empty, ...optimal.singleton, 0.05);
  const step = [0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5].find((st) => peak / st <= 10) ?? 10;
  fig2Top = Math.ceil(peak / step - 1e-9) * step;
  fig2 ??= makeFig2();
  fig2.update([PS, saving.map((d) => (d > 0 ? fig2Top : null)), optimal.empty, optimal.singleton, optimal.rule, conventional.rule]);
  $('fig2-q').textContent = fmt(q, 6);
  $('fig2-gamma').textContent = gammaText(e.threshold);
  $('band').textContent = f.band ? `${f.band[0].toFixed(3)} ≤ p ≤ ${f.band[1].toFixed(3)}` : 'nowhere: Γ = 0.5';
  $('gain').textContent = f.band ? `${fmt(f.gain, 4)} at p = ${f.gainAt.toFixed(3)}` : '0';
  $('fig2-ylabel').textContent = state.preset === 'mpe' ? 'probability of error' : 'mean operational loss';
}

// ---------------------------------------------------------------- the 2D view
const GRID_COUNT = 101;
const REACH = 26; // px: a press this close to a component's mean grabs it
const heat = { key: null, image: null };
const drag = { index: null, origin: null };
const clamp = (v) => Math.min(Math.max(v, -EXTENT), EXTENT);
const half = EXTENT + EXTENT / (GRID_COUNT - 1); // the heat image's cells are centred on the grid points
const view = sceneView($('view'), {
  width: 580, height: 560, box: { left: 44, top: 10, width: 520, height: 520 }, x: [-half, half], y: [-half, half], pan: true, zoom: true,
  draw: drawScene,
  onView: () => update('view'),
  drag: {
    hit(point) {
      let best = null;
      let bestD = REACH;
      means.forEach((m, i) => {
        const d = Math.hypot(view.px(m[0]) - view.px(point[0]), view.py(m[1]) - view.py(point[1]));
        if (d <= bestD) [best, bestD] = [i, d];
      });
      return best;
    },
    start(i) {
      drag.origin = [...means[i]];
    },
    move(i, { point, start }) {
      means[i] = [clamp(drag.origin[0] + point[0] - start[0]), clamp(drag.origin[1] + point[1] - start[1])];
      state.means = means;
      update('view');
    },
  },
});
const gauge = thresholdGauge($('gauge'), { value: 'p', colours: { threshold: BLUE, conventional: RED }, below: 'report nothing', above: 'report a*' });
const bar = colorbar($('view-legend'), { map: 'blues', scale: 'sqrt', label: 'density s(x), √ scale', format: (v) => fmt(v, 3) });

function computeView() {
  const mix = mixture();
  const density = { mixture: mix };
  const estimate = fisst.bernoulliEstimate({ existence: state.p, density, radius: state.r0, costs: costsOption() });
  const total = mix.reduce((s, c) => s + c.weight, 0);
  const mean = [0, 1].map((i) => mix.reduce((s, c) => s + c.weight * c.mean[i], 0) / total);
  const qMean = fisst.probabilityOutsideBall({ density, center: mean, radius: state.r0 });
  const { x, y } = view.domain();
  const key = JSON.stringify([mix, x, y]);
  if (heat.key !== key) {
    // The density on the visible rectangle (cell centres), recomputed after a drag, pan or zoom.
    const values = fisst.mixtureDensityGrid({ mixture: mix, grid: cellGrid(x, y, GRID_COUNT) });
    const vmax = values.reduce((a, b) => Math.max(a, b), 0);
    heat.image = heatImage(values, GRID_COUNT, GRID_COUNT, { map: 'blues', vmax, scale: 'sqrt' });
    heat.key = key;
    bar.update({ max: vmax });
  }
  results.view = { mixture: mix, estimate, mean, qMean };
}

function drawScene(ctx, v) {
  const { px, py, box } = v;
  const { estimate: e, mean, mixture: mix } = results.view;
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(heat.image, box.left, box.top, box.width, box.height);
  v.axes({ xLabel: 'x', yLabel: 'y', ticks: 5 });
  ctx.save();
  clipTo(ctx, box);
  const radius = state.r0 * (px(1) - px(0));
  mix.forEach((c, i) => { // 1σ (solid) and 2σ (dashed) ellipses
    ctx.strokeStyle = COMPONENT_COLOURS[i];
    for (const [k, w, dash] of [[1, 1.6, []], [2, 1.2, [5, 4]]]) {
      ctx.lineWidth = w;
      ctx.setLineDash(dash);
      ctx.beginPath();
      ellipsePath(ctx, px, py, c.mean, c.cov, k);
      ctx.stroke();
    }
  });
  const [mx, my] = [px(mean[0]), py(mean[1])];
  ctx.strokeStyle = '#323f4b';
  ctx.lineWidth = 1.6;
  ctx.setLineDash([7, 5]);
  ctx.beginPath();
  ctx.arc(mx, my, radius, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.lineWidth = 2.5;
  cross(ctx, mx, my, 6);
  // a* and its ball: green when reported, vermillion when not
  const [ax, ay] = [px(e.mmuc[0]), py(e.mmuc[1])];
  const colour = e.declare ? GREEN : RED;
  ctx.fillStyle = e.declare ? 'rgba(0, 158, 115, 0.2)' : 'rgba(148, 163, 184, 0.22)';
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2.2;
  ctx.beginPath();
  ctx.arc(ax, ay, radius, 0, 2 * Math.PI);
  ctx.fill();
  ctx.stroke();
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  mix.forEach((c, i) => {
    dot(ctx, px(c.mean[0]), py(c.mean[1]), 8, '#fff', COMPONENT_COLOURS[i], 3);
    haloText(ctx, `w ${c.weight.toFixed(2)}`, px(c.mean[0]) + 11, py(c.mean[1]) - 11, COMPONENT_COLOURS[i]);
  });
  starPath(ctx, ax, ay, 9);
  ctx.fillStyle = colour;
  ctx.fill();
  ctx.strokeStyle = '#fff';
  ctx.lineWidth = 1.2;
  ctx.stroke();
  // a*'s label under its ball, the mean's above its own (both kept inside the plot)
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = 'center';
  const inside = (yy) => Math.min(Math.max(yy, box.top + 4), box.top + box.height - 18);
  haloText(ctx, `a*: q = ${fmt(e.missProbability, 3)}`, ax, inside(ay + radius + 4), colour);
  if (Math.hypot(ax - mx, ay - my) >= 30) haloText(ctx, `mean: q = ${fmt(results.view.qMean, 3)}`, mx, inside(my - radius - 18), '#323f4b');
  ctx.restore();
}

function drawView() {
  computeView();
  view.redraw();
  const { estimate: e, mean, qMean } = results.view;
  gauge.update({ value: state.p, threshold: e.threshold });
  $('decision').textContent = `${e.declare ? 'report {a*}' : 'report nothing'}: p = ${fmt(state.p, 3)} ${e.declare ? '>' : '≤'} Γ = ${gammaText(e.threshold)}`;
  $('decision').className = e.declare ? 'report' : 'nothing';
  $('gamma-2d').textContent = gammaText(e.threshold);
  $('mmuc').textContent = pointText(e.mmuc);
  $('q-mmuc').textContent = fmt(e.missProbability, 6);
  $('mean').textContent = pointText(mean);
  $('q-mean').textContent = fmt(qMean, 6);
  $('rho').textContent = `${fmt(e.expectedLossEmpty, 4)}, ${fmt(e.expectedLossSingleton, 4)}`;
}

// ---------------------------------------------------------------- state, updates, controls
function publish() {
  const { fig3: f3, fig2: f2, view: v } = results;
  $('threshold-state').textContent = JSON.stringify({
    preset: state.preset, costs: costsOption(), r0: state.r0, cA: state.cA, cM: state.cM,
    fig3: { gammaAt1: f3.gammaAt1, qAt1: f3.qAt1, floor: f3.floor },
    fig2: { sigma: f2.sigma, missProbability: f2.missProbability, threshold: f2.threshold, band: f2.band, gain: f2.gain },
    view: { p: state.p, spread: state.spread, scene: state.scene, mixture: v.mixture, estimate: v.estimate, mean: v.mean, qMean: v.qMean, box: view.box, ...view.domain() },
  }, null, 1);
}

const DRAW = { fig3: drawFig3, fig2: drawFig2, view: drawView };
/** Redraws the given panels, timing each and the whole update; saves the settings in the URL. */
function update(...panels) {
  timer.time('total', () => {
    for (const panel of panels) timer.time(panel, DRAW[panel]);
    if (results.fig3 && results.fig2) publish();
  });
  timer.show();
  url.save();
}

function showCosts() {
  const mmol = state.preset === 'mmol';
  for (const id of ['c-a', 'c-m']) {
    $(id).disabled = !mmol;
    $(`${id}-label`).classList.toggle('disabled', !mmol);
  }
  for (const el of document.querySelectorAll('#costs-text [data-preset]')) el.hidden = el.dataset.preset !== state.preset;
  for (const [cls, v] of [['c-a', state.cA], ['c-m', state.cM], ['ratio', state.cM / state.cA]]) {
    for (const el of document.querySelectorAll(`#costs-text .${cls}`)) el.textContent = fmt(v, 3);
  }
}

const num = (v) => fmt(v, 3);
const onCosts = (key) => (v) => {
  state[key] = v;
  showCosts();
  update('fig3', 'fig2', 'view');
};
state.preset = choice('preset', ['mpe', 'mmol'], { value: state.preset, onChange: onCosts('preset') }).value;
state.r0 = slider('r0', { value: state.r0, format: num, onInput: onCosts('r0') }).value;
state.cA = slider('c-a', { value: state.cA, format: num, onInput: onCosts('cA') }).value;
state.cM = slider('c-m', { value: state.cM, format: num, onInput: onCosts('cM') }).value;
state.sigma = slider('sigma', { value: state.sigma, format: num, onInput: (v) => { state.sigma = v; update('fig2'); } }).value;
state.p = slider('p', { value: state.p, format: num, onInput: (v) => { state.p = v; update('view'); } }).value;
state.spread = slider('spread', { value: state.spread, format: num, onInput: (v) => { state.spread = v; update('view'); } }).value;
choice('scene', Object.keys(SCENES), {
  value: state.scene,
  onChange(name) {
    state.scene = name;
    state.means = null;
    means.splice(0, means.length, ...sceneMeans());
    update('view');
  },
});
downloads($('fig3-figure'), { name: 'threshold-fig3', png: () => fig3.canvas(), csv: () => fig3.csv() });
downloads($('fig2-figure'), { name: 'threshold-fig2', png: () => fig2.canvas(), csv: () => fig2.csv() });
downloads($('view-figure'), {
  name: 'threshold-2d',
  png: () => view.canvas,
  csv: () => toCSV(['what', 'weight', 'x', 'y', 'cov_xx', 'cov_xy', 'cov_yy', 'q'], [
    ...results.view.mixture.map((c, i) => [`component ${i + 1}`, c.weight, ...c.mean, c.cov[0][0], c.cov[0][1], c.cov[1][1], null]),
    ['a* (MMUC)', null, ...results.view.estimate.mmuc, null, null, null, results.view.estimate.missProbability],
    ['mixture mean', null, ...results.view.mean, null, null, null, results.view.qMean],
  ]),
});

showCosts();
// Fig. 3 first, painted before the other two are computed.
update('fig3');
await nextFrame();
update('fig2', 'view');
pageReady();

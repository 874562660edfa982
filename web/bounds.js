// Error bounds for joint detection and estimation (paper 002: Rezaeian & Vo; Fig. 2 left and
// right, Fig. 3, Corollary 3, (31), (35), (37), Theorem 1, Example 2). Every bound comes from
// the fisst package (jdeBoundNoClutter, gaussianFisherInformation, jdeSequentialBound on this
// thread; jdeExample2, about 10 ms a point, and jdeBound (Theorems 1 and 2) in bounds-worker.js, with the seeded Monte Carlo
// of the detector-estimators (jdeMonteCarlo, also in the worker); jdeExample2Regularity).
import init, * as fisst from 'fisst';
import { chart, markX } from './lib/chart.js';
import { $, downloads, fmt, pageReady, progressBar, slider, timings, urlState } from './lib/page.js';

await init();

const [BLUE, RED, GREEN, PINK, AMBER, SKY, BLACK] = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#000000'];
const FAMILY = [0, 0.25, 0.5, 0.75, 1]; // P̄o of the thin curves of Fig. 2 left
const FAMILY_COLOURS = [RED, AMBER, GREEN, SKY, PINK];
const RIGHT_PO = [0.1, 0.4, 0.7, 1]; // P_o of Fig. 2 right
const RIGHT_COLOURS = [RED, AMBER, GREEN, BLUE];
const grid = (n) => Array.from({ length: n + 1 }, (_, k) => k / n);
const RS = grid(200); // r of Fig. 2 left; the Monte Carlo every 10th
const MC_EVERY = 10;
const QS = grid(20); // q of Fig. 2 right; the Monte Carlo every 2nd
const Q_EVERY = 2;
let rightTop = null; // the top of Fig. 2 right's y axis
const SAMPLES = 20000;

const url = urlState({ vf: 100, vh: 25, e0: 150, e1: 200, po: 0.5, steps: 20, r2: 0.6, e02: 1.2, q: 0.5, lambda: 1 });
const state = url.values;
const timer = timings('bounds');
timer.badge($('redraw-ms'), { left: 'Fig. 2 left', seq: 'Fig. 3', right: 'Fig. 2 right', thm: 'Theorems 1–2', total: 'whole update', worker: 'last worker job' });
const results = { left: null, seq: null, right: null, thm: null, mc: { left: null, seq: null, right: null, thm: null } };

// ---------------------------------------------------------------- the Monte Carlo worker
const worker = new Worker(new URL('./bounds-worker.js', import.meta.url), { type: 'module' });
const bars = Object.fromEntries(['left', 'seq', 'right', 'thm'].map((p) => [p, progressBar($(`${p}-progress`), { label: 'Monte Carlo' })]));
const jobs = { left: 0, seq: 0, right: 0, thm: 0 };
const samplesOf = {};
const sentAt = {};
const KIND = { left: 'fig2left', seq: 'fig3', right: 'example2', thm: 'theorems' };
let nextId = 1;
let ready = false;
/** Sends the panel's Monte Carlo job; the answer to an older one is ignored. */
function simulate(panel, params) {
  jobs[panel] = nextId++;
  samplesOf[panel] = params.samples;
  sentAt[panel] = performance.now();
  results.mc[panel] = null;
  bars[panel].set(0, 'Monte Carlo …');
  worker.postMessage({ id: jobs[panel], kind: KIND[panel], params });
}
worker.onmessage = ({ data }) => {
  const panel = Object.keys(KIND).find((p) => KIND[p] === data.kind);
  if (data.id !== jobs[panel]) return;
  if (data.progress !== undefined) {
    bars[panel].set(data.progress, `Monte Carlo ${Math.round(100 * data.progress)} %`);
    return;
  }
  results.mc[panel] = data.result;
  timer.record('worker', performance.now() - sentAt[panel]);
  bars[panel].done(`Monte Carlo: ${samplesOf[panel].toLocaleString('en')} samples a dot`);
  update(panel);
  if (!ready && Object.values(results.mc).every((m) => m !== null)) {
    ready = true;
    pageReady();
  }
};

// ---------------------------------------------------------------- the linear-Gaussian system
/** z = x + v with σv² chosen so that the posterior variance is σh² (a = 0 when σh² ≥ σf²). */
function system() {
  const vh = Math.min(state.vh, state.vf);
  const [gain, noiseVariance] = vh < state.vf ? [1, (state.vf * vh) / (state.vf - vh)] : [0, 1];
  const info = fisst.gaussianFisherInformation({ priorVariance: state.vf, gain, noiseVariance });
  return { gain, noiseVariance, ...info };
}
const noClutter = (r, P, sys) => fisst.jdeBoundNoClutter({
  existence: r, detectionProbability: P, priorVariance: state.vf, posteriorVariance: sys.posteriorVariance,
  falseAlarmError: state.e0, missError: state.e1,
});
/** The bound with MAP detection on Z = ∅ (Section IV-A): the HPE piece from r_M* = 1/(2 − P̄o) on. */
const mapBound = (b, r, P) => b.mapBound ?? (r >= 1 / (2 - P) ? b.hpe : b.lpe);

/** Monte Carlo dots with ±2 SE bars, for an overlay; `ring` circles some of them in black. */
function drawDots({ ctx, x, y }, points, colour, { filled = true, ring = () => false } = {}) {
  for (const p of points) {
    const [px, py] = [x(p.x), y(p.mse)];
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.3;
    ctx.beginPath();
    ctx.moveTo(px, y(p.mse - 2 * p.se));
    ctx.lineTo(px, y(p.mse + 2 * p.se));
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(px, py, 3.6, 0, 2 * Math.PI);
    ctx.fillStyle = filled ? colour : '#fff';
    ctx.fill();
    ctx.stroke();
    if (ring(p)) {
      ctx.strokeStyle = BLACK;
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(px, py, 7.5, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }
}
const zText = (zs) => (zs.length ? `within ${fmt(Math.max(...zs.map(Math.abs)), 2)} standard errors at all ${zs.length} dots` : 'Monte Carlo running …');

// ---------------------------------------------------------------- Fig. 2 left
const left = chart($('left'), {
  height: 380,
  x: { label: 'probability of existence r', range: [0, 1], format: (v) => fmt(v, 3) },
  y: { label: 'bound on the MSE', range: (lo, hi) => [0, Math.max(hi, 1)], format: (v) => fmt(v, 4) },
  series: [
    ...FAMILY.map((P, i) => ({ label: `P̄<sub>o</sub> = ${P}`, colour: FAMILY_COLOURS[i], width: 1.4 })),
    ...FAMILY.map((P, i) => ({ label: `MAP on ∅, P̄<sub>o</sub> = ${P}`, colour: FAMILY_COLOURS[i], width: 1.2, dash: [5, 4], legend: false })),
    { label: 'your P̄<sub>o</sub>', colour: BLACK, width: 3 },
    { label: 'MAP on ∅, your P̄<sub>o</sub>', colour: BLACK, width: 2, dash: [7, 4] },
    { label: '● Monte Carlo, optimal', colour: 'transparent', width: 0 },
    { label: '○ Monte Carlo, MAP on ∅', colour: 'transparent', width: 0 },
  ],
  overlay(o) {
    const f = results.left;
    if (!f) return;
    markX(o, f.rstar, { colour: '#323f4b', text: `r* = ${fmt(f.rstar, 3)}`, align: f.rstar > 0.8 ? 'right' : 'left' });
    if (Math.abs(f.rmap - f.rstar) > 0.02) { // its label a line lower, clear of r*'s
      markX(o, f.rmap, { colour: '#7b8794', dash: [2, 3] });
      const right = f.rmap > 0.8;
      o.ctx.textAlign = right ? 'right' : 'left';
      o.ctx.fillStyle = '#52606d';
      o.ctx.fillText(`r_M* = ${fmt(f.rmap, 3)}`, o.x(f.rmap) + (right ? -4 : 4), 18);
    }
    const mc = results.mc.left;
    if (!mc) return;
    drawDots(o, mc.map((p) => ({ x: p.r, ...p.map })), BLACK, { filled: false });
    drawDots(o, mc.map((p) => ({ x: p.r, ...p.optimal })), BLACK);
  },
});

function drawLeft() {
  const sys = system();
  const P = state.po;
  const curve = (p) => RS.map((r) => noClutter(r, p, sys));
  const family = FAMILY.map(curve);
  const mine = curve(P);
  const mc = results.mc.left;
  const mcColumn = (key) => RS.map((_, k) => (mc && k % MC_EVERY === 0 ? mc[k / MC_EVERY][key].mse : null));
  results.left = {
    P, rstar: mine[0].existenceThreshold, rmap: 1 / (2 - P), boundAt1: mine.at(-1).bound,
    mc: mc && mc.map((p, i) => {
      const b = mine[i * MC_EVERY];
      return { r: p.r, mse: p.optimal.mse, se: p.optimal.se, bound: b.bound, mapMse: p.map.mse, mapSe: p.map.se, mapBound: mapBound(b, p.r, P) };
    }),
  };
  const zs = results.left.mc ? results.left.mc.flatMap((p) => [p.se > 0 ? (p.mse - p.bound) / p.se : 0, p.mapSe > 0 ? (p.mapMse - p.mapBound) / p.mapSe : 0]) : [];
  results.left.worstZ = zs.length ? Math.max(...zs.map(Math.abs)) : null;
  left.update([RS, ...family.map((c) => c.map((b) => b.bound)), ...family.map((c, i) => c.map((b, k) => mapBound(b, RS[k], FAMILY[i]))),
    mine.map((b) => b.bound), mine.map((b, k) => mapBound(b, RS[k], P)), mcColumn('optimal'), mcColumn('map')]);
  $('rstar').textContent = fmt(results.left.rstar, 4);
  $('rmap').textContent = fmt(results.left.rmap, 4);
  $('bound-r1').textContent = fmt(results.left.boundAt1, 4);
  $('left-z').textContent = zText(zs);
  $('system-text').innerHTML = `As z = ${sys.gain ? 'x + v' : 'v (no information)'} with σ<sub>v</sub>² = ${fmt(sys.noiseVariance, 4)}: `
    + `J<sub>1</sub> = 1/σ<sub>f</sub>² + a²/σ<sub>v</sub>² = ${fmt(sys.information, 5)}, σ<sub>h</sub>² = 1/J<sub>1</sub> = ${fmt(sys.posteriorVariance, 4)}`
    + `. The paper's Fig. 2: σ<sub>f</sub>² = 100, σ<sub>h</sub>² = 25, e<sub>0</sub>² = 150, e<sub>1</sub>² = 200.`;
}

// ---------------------------------------------------------------- Fig. 3
const seq = chart($('seq'), {
  height: 340,
  x: { label: 'number of scans k', integer: true, format: String },
  y: { label: 'bound on the MSE', range: (lo, hi) => [0, hi], format: (v) => fmt(v, 4) },
  series: [
    { label: 'P<sub>k</sub>(Enum) (37)', colour: BLUE, width: 2.5 },
    { label: 'P<sub>k</sub>(IRF) (35)', colour: RED, width: 2, dash: [6, 4] },
    { label: '● Monte Carlo', colour: 'transparent', width: 0 },
  ],
  overlay(o) {
    const mc = results.mc.seq;
    if (mc) drawDots(o, mc.mse.map((mse, k) => ({ x: k + 1, mse, se: mc.se[k] })), BLUE);
  },
});

function drawSeq() {
  const sys = system();
  const opts = { priorInformation: 1 / state.vf, detectedInformation: sys.information, detectionProbability: state.po, steps: state.steps };
  const en = fisst.jdeSequentialBound({ method: 'enumeration', ...opts }).bound;
  const ir = fisst.jdeSequentialBound({ method: 'irf', ...opts }).bound;
  const mc = results.mc.seq;
  const ks = en.map((_, k) => k + 1);
  const zs = mc ? mc.mse.map((m, k) => (mc.se[k] > 0 ? (m - en[k]) / mc.se[k] : 0)) : [];
  results.seq = { ...opts, enumeration: en, irf: ir, mc, worstZ: zs.length ? Math.max(...zs.map(Math.abs)) : null };
  seq.update([ks, en, ir, mc ? mc.mse : ks.map(() => null)]);
  $('seq-j').textContent = `${fmt(opts.priorInformation, 5)}, ${fmt(opts.detectedInformation, 5)}`;
  $('seq-last').textContent = `${fmt(en.at(-1), 4)} / ${fmt(ir.at(-1), 4)}`;
  $('seq-z').textContent = zText(zs);
}

// ---------------------------------------------------------------- Fig. 2 right: Example 2
const REGULARITY = fisst.jdeExample2Regularity(); // r = 1, P_o = 1: 1/J_1 against the posterior mean's MSE
$('right-j1').textContent = fmt(REGULARITY.inverseInformation, 4);
$('right-mmse').textContent = fmt(REGULARITY.posteriorMeanMse, 4);
const right = chart($('right'), {
  height: 380,
  x: { label: 'probability of false alarm q', range: [0, 1], format: (v) => fmt(v, 3) },
  // The (32) curve shoots up where Z'_0 shrinks (its J'_1 → 0): the range follows the rest.
  y: { label: 'MSE: the curve (21) and the Monte Carlo', range: (lo, hi) => [0, rightTop ?? hi], format: (v) => fmt(v, 4) },
  series: [
    ...RIGHT_PO.map((P, i) => ({ label: `P<sub>o</sub> = ${P}`, colour: RIGHT_COLOURS[i], width: 2 })),
    ...RIGHT_PO.map((P, i) => ({ label: `with (20)'s J'<sub>1</sub>, P<sub>o</sub> = ${P}`, colour: RIGHT_COLOURS[i], width: 1.2, dash: [2, 3], legend: false })),
    ...RIGHT_PO.map((P) => ({ label: `● Monte Carlo, P<sub>o</sub> = ${P}`, colour: 'transparent', width: 0, legend: false })),
  ],
  overlay(o) {
    const mc = results.mc.right;
    if (!mc?.points[0]?.paperBound) return;
    o.ctx.font = '11px system-ui, sans-serif';
    o.ctx.textBaseline = 'top';
    results.right.paper.forEach((c, i) => { // where a (32) curve leaves the chart, say so
      const k = c.indexOf(Math.max(...c));
      if (c[k] <= rightTop) return;
      o.ctx.textAlign = QS[k] > 0.7 ? 'right' : 'left';
      o.ctx.fillStyle = RIGHT_COLOURS[i];
      o.ctx.fillText(`↑ (32) reaches ${fmt(c[k], 3)} at q = ${fmt(QS[k], 2)}: its J'₁ → 0 as Z'₀ shrinks`, o.x(QS[k]) + (QS[k] > 0.7 ? -6 : 6), 4 + 14 * i);
    });
    RIGHT_PO.forEach((P, i) => drawDots(o, mc.points.filter((p) => p.P === P).map((p) => ({ x: p.q, ...p })), RIGHT_COLOURS[i], { ring: (p) => p.below }));
  },
});

/** Fig. 2 right from the worker's answer: jdeExample2's curves over q, and the Monte Carlo. */
function drawRight() {
  const mc = results.mc.right;
  if (!mc) {
    results.right = null;
    right.update([QS, ...Array.from({ length: 3 * RIGHT_PO.length }, () => QS.map(() => null))]);
    for (const id of ['right-ve', 'right-below', 'right-mc']) $(id).textContent = '…';
    return;
  }
  const { curves, reference, points } = mc;
  let below = 0;
  for (const p of points) {
    const b = curves[RIGHT_PO.indexOf(p.P)][Math.round(p.q * 20)];
    [p.bound, p.paperBound] = [b.bound, b.paperBound];
    p.below = p.mse + 2 * p.se < Math.min(p.bound, p.paperBound);
    below += p.below;
  }
  const ve = curves[0][0].undetectedVariance;
  rightTop = 1.15 * Math.max(...curves.flat().map((b) => b.bound), ...points.map((p) => p.mse + 2 * p.se));
  results.right = {
    r: state.r2, e0: state.e02, variance: ve, missError: curves[0][0].missError, regularity: REGULARITY, reference, mc: points, below,
    paper: curves.map((c) => c.map((b) => b.paperBound)), curves: curves.map((c) => c.map((b) => b.bound)),
  };
  right.update([QS, ...results.right.paper, ...results.right.curves,
    ...RIGHT_PO.map((P) => QS.map((q, k) => (k % Q_EVERY === 0 ? points.find((p) => p.P === P && p.q === q)?.mse ?? null : null)))]);
  $('right-ve').textContent = `${fmt(ve, 4)}, ${fmt(results.right.missError, 4)}`;
  $('right-below').textContent = `${below} of ${points.length}`;
  $('right-mc').textContent = `${fmt(reference.mse, 4)} ± ${fmt(2 * reference.se, 1)}`;
}

// ---------------------------------------------------------------- Theorems 1 and 2 over r (jdeBound)
// x ~ N(0.5, 4), z = x + v, σv² = 1, P̄o = 0.8, e0² = 6, e1² = 8; model I: a false alarm
// N(1, 25) with probability q; model II: Poisson clutter of rate λ with density N(0, 25).
const THM = { prior: { mean: 0.5, variance: 4 }, observation: { detectionProbability: 0.8, gain: 1, offset: 0, noiseVariance: 1 }, falseAlarmError: 6, missError: 8 };
const THM_RS = grid(20);
let thmTop = null; // the y axis covers the dots too
const thmChart = chart($('thm'), {
  height: 340,
  x: { label: 'probability of existence r', range: [0, 1], format: (v) => fmt(v, 3) },
  y: { label: 'bound on the MSE', range: (lo, hi) => [0, thmTop ?? hi], format: (v) => fmt(v, 4) },
  series: [
    { label: 'model I, Theorem 1 (17)', colour: BLUE, width: 2.5 },
    { label: 'model II, Theorem 2 (23)', colour: RED, width: 2.5 },
    { label: '● Monte Carlo, MAP + posterior mean', colour: 'transparent', width: 0 },
  ],
  overlay(o) {
    const t = results.thm;
    if (!t) return;
    drawDots(o, t.points.map((p) => ({ x: p.r, ...p.mc1 })), BLUE);
    drawDots(o, t.points.map((p) => ({ x: p.r, ...p.mc2 })), RED);
  },
});

function drawThm() {
  const pts = results.mc.thm;
  if (!pts) {
    results.thm = null;
    thmChart.update([THM_RS, THM_RS.map(() => null), THM_RS.map(() => null), THM_RS.map(() => null)]);
    return;
  }
  const z = (mc, b) => (mc.se > 0 ? (mc.mse - b.bound) / Math.hypot(mc.se, b.error) : 0);
  const z1 = pts.map((p) => z(p.mc1, p.model1));
  const z2 = pts.map((p) => z(p.mc2, p.model2));
  thmTop = 1.08 * Math.max(...pts.flatMap((p) => [p.model1.bound, p.model2.bound, p.mc1.mse + 2 * p.mc1.se, p.mc2.mse + 2 * p.mc2.se]));
  results.thm = { q: state.q, lambda: state.lambda, system: THM, points: pts, worstZ1: Math.max(...z1.map(Math.abs)), lowestZ2: Math.min(...z2) };
  thmChart.update([THM_RS, pts.map((p) => p.model1.bound), pts.map((p) => p.model2.bound), THM_RS.map(() => null)]);
  $('thm-z1').textContent = `within ${fmt(results.thm.worstZ1, 2)} standard errors at all ${pts.length} dots`;
  $('thm-z2').textContent = `lowest z = ${fmt(results.thm.lowestZ2, 2)} (never below: z > −4)`;
}

// ---------------------------------------------------------------- state, updates, controls
function publish() {
  $('bounds-state').textContent = JSON.stringify({
    settings: { ...state }, system: system(), left: results.left, seq: results.seq, right: results.right, thm: results.thm,
    mcDone: Object.fromEntries(Object.entries(results.mc).map(([k, v]) => [k, v !== null])),
  }, null, 1);
}

const DRAW = { left: drawLeft, seq: drawSeq, right: drawRight, thm: drawThm };
function update(...panels) {
  timer.time('total', () => {
    for (const panel of panels) timer.time(panel, DRAW[panel]);
    if (results.left && results.seq) publish();
  });
  timer.show();
  url.save();
}

/** Recomputes the bounds of `panels` and starts their Monte Carlo. */
function recompute(...panels) {
  const sys = system();
  if (panels.includes('left')) {
    simulate('left', { rs: RS.filter((_, k) => k % MC_EVERY === 0), detectionProbability: state.po, priorVariance: state.vf, noiseVariance: sys.noiseVariance, gain: sys.gain, falseAlarmError: state.e0, missError: state.e1, samples: SAMPLES, seed: 1 });
  }
  if (panels.includes('seq')) {
    simulate('seq', { priorInformation: 1 / state.vf, detectedInformation: sys.information, detectionProbability: state.po, steps: state.steps, samples: SAMPLES, seed: 2 });
  }
  if (panels.includes('right')) {
    simulate('right', { qs: QS, mcEvery: Q_EVERY, detectionProbabilities: RIGHT_PO, existence: state.r2, falseAlarmError: state.e02, samples: SAMPLES / 2, seed: 3 });
  }
  if (panels.includes('thm')) {
    simulate('thm', { rs: THM_RS, system: THM, falseAlarm: { probability: state.q, mean: 1, variance: 25 }, clutter: { rate: state.lambda, mean: 0, variance: 25 }, samples: SAMPLES, seed: 4 });
  }
  update(...panels);
}

const num = (v) => fmt(v, 3);
const on = (key, ...panels) => (v) => {
  state[key] = v;
  recompute(...panels);
};
state.vf = slider('vf', {
  value: state.vf,
  format: num,
  onInput(v) {
    state.vf = v;
    $('vh').max = String(v);
    state.vh = vhSlider.set(Math.min(state.vh, v));
    recompute('left', 'seq');
  },
}).value;
$('vh').max = String(state.vf); // σh² ≤ σf²: a measurement cannot add uncertainty
const vhSlider = slider('vh', { value: state.vh, format: num, onInput: on('vh', 'left', 'seq') });
state.vh = vhSlider.value;
state.e0 = slider('e0', { value: state.e0, format: num, onInput: on('e0', 'left') }).value;
state.e1 = slider('e1', { value: state.e1, format: num, onInput: on('e1', 'left') }).value;
state.po = slider('po', { value: state.po, format: num, onInput: on('po', 'left', 'seq') }).value;
state.steps = slider('steps', { value: state.steps, format: String, onInput: on('steps', 'seq') }).value;
state.r2 = slider('r2', { value: state.r2, format: num, onInput: on('r2', 'right') }).value;
state.e02 = slider('e02', { value: state.e02, format: num, onInput: on('e02', 'right') }).value;
state.q = slider('thm-q', { value: state.q, format: num, onInput: on('q', 'thm') }).value;
state.lambda = slider('thm-lambda', { value: state.lambda, format: num, onInput: on('lambda', 'thm') }).value;
downloads($('left-figure'), { name: 'bounds-fig2-left', png: () => left.canvas(), csv: () => left.csv() });
downloads($('seq-figure'), { name: 'bounds-fig3', png: () => seq.canvas(), csv: () => seq.csv() });
downloads($('right-figure'), { name: 'bounds-fig2-right', png: () => right.canvas(), csv: () => right.csv() });
downloads($('thm-figure'), { name: 'bounds-theorems', png: () => thmChart.canvas(), csv: () => thmChart.csv() });

recompute('left', 'seq', 'right', 'thm');

// Tracking a person from imprecise reports (paper 001, Section V-C, Figs. 6–8): the airport
// concourse, the reports "near anchor a" (discs), and the GM Bernoulli filter (splitting about
// the discs and the exclusions) beside the Bernoulli particle filter. The scenario and both
// filters run in a module Web Worker (airport-worker.js: airportScenario, GmBernoulliFilter,
// ParticleBernoulliFilter); this file only draws what it posts, step by step.
import { chart, markX } from './lib/chart.js';
import { dot, ellipsePath, haloText, sceneView, starPath } from './lib/scene.js';
import { $, choice, downloads, fmt, pageReady, progressBar, slider, timings, toCSV, urlState } from './lib/page.js';

const [BLUE, RED, GREEN, AMBER, GREY] = ['#0072b2', '#d55e00', '#009e73', '#e69f00', '#7b8794'];
const STEPS = 60;
const PLAY_MS = 350;

const url = urlState({ seed: 7, view: 'both', k: -1, particles: 5000 }, {
  check: {
    seed: (v) => Number.isInteger(v) && v >= 0 && v <= 2 ** 53 - 1,
    k: (v) => Number.isInteger(v) && v >= -1 && v < STEPS,
    particles: (v) => Number.isInteger(v) && v >= 100 && v <= 20_000,
  },
});
const state = url.values;
const timer = timings('airport');
timer.badge($('redraw-ms'), { scene: 'scene', charts: 'charts', gm: 'GM step (worker)', pf: 'PF step (worker)' });
const progress = progressBar($('progress'), { label: 'filters run' });

// ---------------------------------------------------------------- the run (from the worker)
const run = { id: 0, scenario: null, steps: [], done: false, error: null, ms: null };
const worker = new Worker(new URL('./airport-worker.js', import.meta.url), { type: 'module' });
worker.onmessage = ({ data: m }) => {
  if (m.id !== run.id) return;
  if (m.type === 'scenario') {
    run.scenario = m.scenario;
  } else if (m.type === 'step') {
    run.steps[m.k] = m;
    timer.record('gm', m.ms.gm);
    timer.record('pf', m.ms.pf);
    progress.set((m.k + 1) / STEPS, `step ${m.k + 1} of ${STEPS}`);
    if (m.k === 0) {
      redraw();
      pageReady();
    } else if (state.k === -1 || !playing()) redraw();
  } else if (m.type === 'done') {
    run.done = true;
    run.ms = m.ms;
    progress.done(`${STEPS} steps in ${(m.ms / 1000).toFixed(1)} s`);
    document.body.dataset.run = 'done';
    redraw();
  } else if (m.type === 'error') {
    run.error = m.message;
    $('story').textContent = `error: ${m.message}`;
    throw new Error(`airport worker: ${m.message}`);
  }
};

function start() {
  run.id += 1;
  Object.assign(run, { scenario: null, steps: [], done: false, error: null, ms: null });
  delete document.body.dataset.run;
  progress.set(0, 'starting');
  worker.postMessage({ id: run.id, seed: state.seed, steps: STEPS, particles: state.particles });
}

/** The step shown: state.k, or the latest computed step when following (k = −1). */
const shown = () => Math.min(state.k === -1 ? STEPS - 1 : state.k, run.steps.length - 1);

// ---------------------------------------------------------------- derived series (Figs. 7b, 8)
const norm2 = (a, b, i, j) => Math.hypot(a[i] - b[i], a[j] - b[j]);
const rss = (cov, i, j) => Math.sqrt(cov[i][i] + cov[j][j]);
function series() {
  const s = run.scenario;
  const col = (f) => Array.from({ length: STEPS }, (_, k) => (run.steps[k] ? f(run.steps[k], s.truth[k].state) : null));
  return {
    t: s ? s.truth.map((x) => x.t) : Array.from({ length: STEPS }, (_, k) => 15 * (k + 1)),
    existence: { gm: col((m) => m.gm.existence), pf: col((m) => m.pf.existence) },
    position: { gmErr: col((m, x) => norm2(m.gm.mean, x, 0, 1)), pfErr: col((m, x) => norm2(m.pf.mean, x, 0, 1)), gmRss: col((m) => rss(m.gm.cov, 0, 1)), pfRss: col((m) => rss(m.pf.cov, 0, 1)) },
    velocity: { gmErr: col((m, x) => norm2(m.gm.mean, x, 2, 3)), pfErr: col((m, x) => norm2(m.pf.mean, x, 2, 3)), gmRss: col((m) => rss(m.gm.cov, 2, 3)), pfRss: col((m) => rss(m.pf.cov, 2, 3)) },
  };
}

// ---------------------------------------------------------------- the concourse (Figs. 6, 7a)
const view = sceneView($('scene'), {
  width: 1140, height: 186, box: { left: 44, top: 8, width: 1086, height: 140 },
  x: [-5, 305], y: [-5, 35], pan: true, zoom: true,
  draw: drawScene,
  onView: () => publish(),
});

// The close-up: 64 × 32 around the person (same drawing, no pan: it follows the step shown).
const closeup = sceneView($('closeup'), {
  width: 560, height: 300, box: { left: 44, top: 8, width: 508, height: 254 }, x: [0, 64], y: [-1, 31],
  draw: (ctx, v) => {
    const s = run.scenario;
    if (s) {
      const cx = Math.min(Math.max(s.truth[shown()].state[0], 32), 268);
      v.setDomain([cx - 32, cx + 32], [-1, 31]);
    }
    drawScene(ctx, v);
  },
});

function drawScene(ctx, v) {
  const { px, py, box } = v;
  const s = run.scenario;
  v.axes({ xLabel: 'x [dist]', yLabel: 'y', ticks: 6 });
  if (!s) return;
  ctx.save();
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.clip();
  // Exclusions (grey): the four rectangles and everything outside the concourse.
  const c = s.concourse.box;
  const rect = (b) => [px(b.min[0]), py(b.max[1]), px(b.max[0]) - px(b.min[0]), py(b.min[1]) - py(b.max[1])];
  ctx.fillStyle = '#cbd2d9';
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.rect(...rect(c));
  ctx.fill('evenodd');
  for (const e of s.exclusions) if (e.box) ctx.fillRect(...rect(e.box));
  const k = shown();
  const step = run.steps[k];
  const reported = new Set(s.reports[k] ?? []);
  const trueReport = s.trueReports[k];
  // Anchors and their discs ∂A_a; the reports of step k thick (green: the person's, amber: false).
  s.anchors.forEach((a, i) => {
    const r = px(a.radius) - px(0);
    ctx.beginPath();
    ctx.arc(px(a.position[0]), py(a.position[1]), r, 0, 2 * Math.PI);
    const hit = reported.has(i);
    ctx.setLineDash(hit ? [] : [3, 3]);
    ctx.lineWidth = hit ? 2.6 : 1;
    ctx.strokeStyle = hit ? (i === trueReport ? GREEN : AMBER) : '#9aa5b1';
    if (hit) {
      ctx.fillStyle = i === trueReport ? 'rgba(0, 158, 115, 0.12)' : 'rgba(230, 159, 0, 0.14)';
      ctx.fill();
    }
    ctx.stroke();
    dot(ctx, px(a.position[0]), py(a.position[1]), 2.5, '#52606d');
    if (v !== view) { // names in the close-up
      ctx.font = '11px system-ui, sans-serif';
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      haloText(ctx, a.name, px(a.position[0]), py(a.position[1]) + 4, '#52606d');
    }
  });
  ctx.setLineDash([]);
  if (step && state.view !== 'gm') { // the particle cloud
    ctx.fillStyle = 'rgba(213, 94, 0, 0.35)';
    const xy = step.pf.cloud;
    for (let i = 0; i < xy.length; i += 2) ctx.fillRect(px(xy[i]) - 0.8, py(xy[i + 1]) - 0.8, 1.6, 1.6);
  }
  if (step && state.view !== 'pf') { // the GM density: 1σ ellipses, shaded by weight
    const mix = step.gm.mixture;
    const wmax = mix.reduce((a, m) => Math.max(a, m.weight), 0);
    ctx.strokeStyle = BLUE;
    ctx.fillStyle = BLUE;
    ctx.lineWidth = 1;
    for (const m of mix) {
      const t = m.weight / wmax;
      ctx.beginPath();
      ellipsePath(ctx, px, py, m.mean, m.cov, 1);
      ctx.globalAlpha = 0.3 * t;
      ctx.fill();
      ctx.globalAlpha = 0.12 + 0.78 * t;
      ctx.stroke();
    }
    ctx.globalAlpha = 1;
  }
  // The truth and the MMSE estimates up to step k.
  const line = (pts, colour, width, dash = []) => {
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.setLineDash(dash);
    ctx.beginPath();
    pts.forEach(([x, y], i) => (i ? ctx.lineTo(px(x), py(y)) : ctx.moveTo(px(x), py(y))));
    ctx.stroke();
    ctx.setLineDash([]);
  };
  const upTo = run.steps.slice(0, k + 1);
  line(s.truth.slice(0, k + 1).map((x) => x.state), '#1f2933', 1.6);
  if (state.view !== 'pf') line(upTo.map((m) => m.gm.mean), BLUE, 1.8);
  if (state.view !== 'gm') line(upTo.map((m) => m.pf.mean), RED, 1.6, [5, 3]);
  const [tx, ty] = s.truth[k].state;
  starPath(ctx, px(tx), py(ty), 7);
  ctx.fillStyle = '#1f2933';
  ctx.fill();
  if (step && state.view !== 'pf') dot(ctx, px(step.gm.mean[0]), py(step.gm.mean[1]), 4, '#fff', BLUE, 2);
  if (step && state.view !== 'gm') dot(ctx, px(step.pf.mean[0]), py(step.pf.mean[1]), 4, '#fff', RED, 2);
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  if (trueReport === null) haloText(ctx, s.inFov[k] ? 'missed' : 'missed (outside S)', px(tx), py(ty) - 9, '#52606d');
  ctx.restore();
}

// ---------------------------------------------------------------- Fig. 7b and Fig. 8
const X_AXIS = { label: 'time t [s]', range: [0, 15 * STEPS + 5], format: (v) => fmt(v, 4) };
const cursor = (o) => {
  if (!run.scenario || !run.steps.length) return;
  const s = run.scenario;
  // Steps without the person's report (grey ticks at the top) and with false reports (amber, bottom).
  for (let k = 0; k < run.steps.length; k++) {
    const xk = o.x(s.truth[k].t);
    if (s.trueReports[k] === null) { o.ctx.fillStyle = GREY; o.ctx.fillRect(xk - 2, 0, 4, 7); }
    if (s.reports[k].length > (s.trueReports[k] === null ? 0 : 1)) { o.ctx.fillStyle = AMBER; o.ctx.fillRect(xk - 2, o.box.height - 7, 4, 7); }
  }
  const k = shown();
  markX(o, s.truth[k].t, { colour: '#1f2933', text: `k = ${k + 1}`, align: k > STEPS / 2 ? 'right' : 'left' });
};
const pair = (what) => [
  { label: `GM ${what}`, colour: BLUE, width: 2 },
  { label: `PF ${what}`, colour: RED, width: 2, dash: [6, 4] },
];
const existence = chart($('existence'), {
  height: 240, x: X_AXIS, overlay: cursor,
  y: { label: 'existence r<sub>k|k</sub>', range: [0, 1.02], format: (v) => fmt(v, 3) },
  series: pair('r<sub>k|k</sub>'),
});
const errorChart = (id, unit) => chart($(id), {
  height: 240, x: X_AXIS, overlay: cursor,
  y: { label: unit, range: (lo, hi) => [0, Math.max(hi, 1e-3) * 1.05], format: (v) => fmt(v, 3) },
  series: [...pair('MMSE error'), { label: 'GM cov. RSS', colour: BLUE, width: 1.2, dash: [2, 3] }, { label: 'PF cov. RSS', colour: RED, width: 1.2, dash: [1, 3] }],
});
const position = errorChart('position', 'position [dist]');
const velocity = errorChart('velocity', 'velocity [dist/s]');

// ---------------------------------------------------------------- drawing, read-outs, state
let latest = null;
function redraw() {
  if (!run.scenario || !run.steps.length) return;
  timer.time('scene', () => {
    view.redraw();
    closeup.redraw();
  });
  latest = timer.time('charts', () => {
    const d = series();
    existence.update([d.t, d.existence.gm, d.existence.pf]);
    position.update([d.t, d.position.gmErr, d.position.pfErr, d.position.gmRss, d.position.pfRss]);
    velocity.update([d.t, d.velocity.gmErr, d.velocity.pfErr, d.velocity.gmRss, d.velocity.pfRss]);
    return d;
  });
  timer.show();
  story();
  publish();
}

function story() {
  const s = run.scenario;
  const k = shown();
  const m = run.steps[k];
  const name = (a) => s.anchors[a].name;
  const person = s.reports[k].indexOf(s.trueReports[k]); // an anchor may be named twice: once falsely
  const parts = s.reports[k].map((a, i) => `“near ${name(a)}” (${i === person ? 'the person' : 'false report'})`);
  if (s.trueReports[k] === null) parts.push(s.inFov[k] ? 'the person was missed' : 'the person was missed: outside every disc (outside S)');
  $('story').textContent = `Step k = ${k + 1}, t = ${s.truth[k].t} s: ${parts.length ? parts.join('; ') : 'no report'}.`;
  $('k-out').value = String(k + 1);
  stepSlider.set(k);
  const cells = { 'gm-r': m.gm.existence, 'pf-r': m.pf.existence, 'gm-pos': latest.position.gmErr[k], 'pf-pos': latest.position.pfErr[k], 'gm-vel': latest.velocity.gmErr[k], 'pf-vel': latest.velocity.pfErr[k] };
  for (const [id, v] of Object.entries(cells)) $(id).textContent = fmt(v, 4);
  $('gm-n').textContent = `${m.gm.mixture.length} (split ${m.gm.splitComponents})`;
  $('pf-n').textContent = String(m.pf.cloud.length / 2);
}

function publish() {
  if (!run.scenario || !latest) return;
  $('airport-state').textContent = JSON.stringify({
    seed: state.seed, particles: state.particles, view: state.view, k: shown(), computed: run.steps.length, done: run.done,
    existence: latest.existence, position: latest.position, velocity: latest.velocity,
    components: run.steps.map((m) => m.gm.mixture.length), box: view.box, ...view.domain(),
  });
}

// ---------------------------------------------------------------- controls
let timerId = null;
const playing = () => timerId !== null;
function setPlaying(on) {
  clearInterval(timerId);
  timerId = null;
  $('play').textContent = on ? '❚❚ pause' : '▶ play';
  $('play').setAttribute('aria-pressed', String(on));
  if (!on) return;
  if (state.k === -1 || state.k >= STEPS - 1) state.k = 0;
  timerId = setInterval(() => {
    if (state.k + 1 >= run.steps.length) {
      if (run.done) setPlaying(false);
      return;
    }
    goTo(state.k + 1);
  }, PLAY_MS);
  goTo(state.k);
}
function goTo(k) {
  state.k = Math.max(0, Math.min(k, Math.max(run.steps.length - 1, 0)));
  url.save();
  redraw();
}
$('play').addEventListener('click', () => setPlaying(!playing()));
$('back').addEventListener('click', () => { setPlaying(false); goTo(shown() - 1); });
$('step').addEventListener('click', () => { setPlaying(false); goTo(shown() + 1); });
const stepSlider = slider('k', { value: Math.max(state.k, 0), format: (v) => String(v + 1), onInput: (v) => { setPlaying(false); goTo(v); } });
const seedInput = $('seed');
seedInput.value = String(state.seed);
const newSeed = (v) => {
  setPlaying(false);
  state.seed = v;
  state.k = -1;
  seedInput.value = String(v);
  url.save();
  start();
};
seedInput.addEventListener('change', () => {
  const v = Number(seedInput.value);
  if (!(Number.isInteger(v) && v >= 0 && v <= 2 ** 53 - 1)) seedInput.value = String(state.seed);
  else if (v !== state.seed) newSeed(v);
});
$('reseed').addEventListener('click', () => newSeed(Math.floor(Math.random() * 1e6)));
state.view = choice('view', ['both', 'gm', 'pf'], { value: state.view, onChange: (v) => { state.view = v; url.save(); redraw(); } }).value;

downloads($('closeup-figure'), { name: () => `airport-closeup-seed${state.seed}`, png: () => closeup.canvas });
downloads($('scene-figure'), {
  name: () => `airport-scene-seed${state.seed}`,
  png: () => view.canvas,
  csv: () => toCSV(['k', 't', 'x', 'y', 'vx', 'vy', 'reports', 'true_report', 'gm_r', 'gm_x', 'gm_y', 'gm_vx', 'gm_vy', 'pf_r', 'pf_x', 'pf_y', 'pf_vx', 'pf_vy'],
    run.steps.map((m, k) => [k + 1, run.scenario.truth[k].t, ...run.scenario.truth[k].state, run.scenario.reports[k].join(' '), run.scenario.trueReports[k], m.gm.existence, ...m.gm.mean, m.pf.existence, ...m.pf.mean])),
});
for (const [id, c] of [['existence', existence], ['position', position], ['velocity', velocity]]) {
  downloads($(`${id}-figure`), { name: () => `airport-${id}-seed${state.seed}`, png: () => c.canvas(), csv: () => c.csv() });
}
start();

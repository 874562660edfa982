// The spooky effect made visible (paper 003). Every number comes from the fisst package.
import init, * as fisst from 'fisst';
import { setupCanvas, scale, drawAxes, ticks, fmt } from './lib/plot.js';

await init();

const $ = (id) => document.getElementById(id);
const COLORS = ['#e4e7eb', '#60a5fa', '#f59e0b', '#34d399']; // code u1 + 2·u2
const MAP_RES = 200;
const MAP_SIZE = 240;

// ---------------------------------------------------------------- Fig. 1 and Fig. 2 maps
const estimators = ['gospa', 'ospa', 'uospa', 'mam', 'jom', 'map-cardinality'];
const mapImages = new Map();

function renderMapImage(estimator) {
  const { decisions, resolution } = fisst.mbDecisionMap({ estimator, resolution: MAP_RES });
  const image = document.createElement('canvas');
  image.width = resolution;
  image.height = resolution;
  const ctx = image.getContext('2d');
  const data = ctx.createImageData(resolution, resolution);
  for (let row = 0; row < resolution; row++) {
    // decisions: row index grows with r2; the canvas y axis grows downwards.
    const y = resolution - 1 - row;
    for (let col = 0; col < resolution; col++) {
      const hex = COLORS[decisions[row * resolution + col]];
      const k = 4 * (y * resolution + col);
      data.data[k] = parseInt(hex.slice(1, 3), 16);
      data.data[k + 1] = parseInt(hex.slice(3, 5), 16);
      data.data[k + 2] = parseInt(hex.slice(5, 7), 16);
      data.data[k + 3] = 255;
    }
  }
  ctx.putImageData(data, 0, 0);
  return image;
}

const MAP_BOX = { left: 48, top: 8, width: MAP_SIZE - 58, height: MAP_SIZE - 52 };

function drawMap(estimator, r1, r2) {
  const canvas = $(`map-${estimator}`);
  const ctx = setupCanvas(canvas, MAP_SIZE, MAP_SIZE);
  ctx.clearRect(0, 0, MAP_SIZE, MAP_SIZE);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(mapImages.get(estimator), MAP_BOX.left, MAP_BOX.top, MAP_BOX.width, MAP_BOX.height);
  const x = scale(0, 1, MAP_BOX.left, MAP_BOX.left + MAP_BOX.width);
  const y = scale(0, 1, MAP_BOX.top + MAP_BOX.height, MAP_BOX.top);
  drawAxes(ctx, MAP_BOX, x, y, {
    xTicks: ticks(0, 1, 4), yTicks: ticks(0, 1, 4), xLabel: 'r₁', yLabel: 'r₂', fmt: (v) => v.toFixed(2),
  });
  // the current point
  ctx.strokeStyle = '#111';
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x(r1) - 7, y(r2));
  ctx.lineTo(x(r1) + 7, y(r2));
  ctx.moveTo(x(r1), y(r2) - 7);
  ctx.lineTo(x(r1), y(r2) + 7);
  ctx.stroke();
}

function describe(report) {
  const on = report.map((u, i) => (u ? i + 1 : 0)).filter(Boolean);
  if (on.length === 0) return 'report nothing';
  return `report ${on.join(' and ')}`;
}

function updateTwoTargets() {
  const r1 = Number($('r1').value);
  const r2 = Number($('r2').value);
  $('r1-out').value = r1.toFixed(3);
  $('r2-out').value = r2.toFixed(3);
  const existence = [r1, r2];
  for (const metric of ['gospa', 'ospa', 'uospa']) {
    const { report, meanSquareError } = fisst.mbOptimalEstimate({ existence, metric });
    $(`decision-${metric}`).textContent = describe(report);
    $(`mse-${metric}`).textContent = fmt(meanSquareError, 4);
  }
  for (const method of ['mam', 'jom', 'map-cardinality']) {
    $(`decision-${method}`).textContent = describe(fisst.mbAlternativeEstimate({ existence, method }).report);
  }
  for (const e of estimators) drawMap(e, r1, r2);
}

// ---------------------------------------------------------------- Example 5
const STORY = {
  before: { r2: 0.4, text: 'Both potential targets exist with probability 0.4. GOSPA reports neither (each r < 1/2), but the optimal OSPA estimate reports both: {ospa}.' },
  case1: { r2: 0.9, text: 'A measurement from Liverpool raises r₂ to 0.9 and says nothing about Madrid. OSPA now {ospa}: Madrid is dropped although the expected number of targets went up. GOSPA: {gospa}.' },
  case2: { r2: 0.1, text: 'Liverpool is not seen: r₂ falls to 0.1, Madrid unchanged. OSPA now {ospa} — Madrid disappears because of an event hundreds of kilometres away. GOSPA: {gospa}.' },
};

function story(step) {
  const { r2, text } = STORY[step];
  $('r1').value = '0.4';
  $('r2').value = String(r2);
  updateTwoTargets();
  $('story').textContent = text
    .replace('{ospa}', $('decision-ospa').textContent)
    .replace('{gospa}', $('decision-gospa').textContent);
}

// ---------------------------------------------------------------- Fig. 3
const FIG3 = { width: 720, height: 300, box: { left: 56, top: 12, width: 640, height: 240 } };
const SERIES = [
  { key: 'gospa', label: 'GOSPA', color: '#16a34a', dash: [] },
  { key: 'ospa', label: 'OSPA', color: '#dc2626', dash: [] },
  { key: 'uospa', label: 'UOSPA', color: '#2563eb', dash: [6, 3] },
  { key: 'mapCardinality', label: 'max cardinality', color: '#7c3aed', dash: [2, 3] },
];
let fig3Counts = null;

function updateFig3(recompute) {
  const r = Number($('fig3-r').value);
  const nMax = Number($('fig3-nmax').value);
  $('fig3-r-out').value = r.toFixed(2);
  $('fig3-nmax-out').value = nMax;
  const nInput = $('fig3-n');
  nInput.max = String(nMax);
  if (Number(nInput.value) > nMax) nInput.value = String(nMax);
  const n = Number(nInput.value);
  $('fig3-n-out').value = n;
  if (recompute || !fig3Counts) {
    fig3Counts = fisst.mbIdenticalComponentCounts({ existence: r, maxComponents: nMax });
  }
  $('fig3-gospa').textContent = fig3Counts.gospa[n - 1];
  $('fig3-ospa').textContent = fig3Counts.ospa[n - 1];
  $('fig3-uospa').textContent = fig3Counts.uospa[n - 1];
  $('fig3-map').textContent = fig3Counts.mapCardinality[n - 1];

  const ctx = setupCanvas($('fig3'), FIG3.width, FIG3.height);
  ctx.clearRect(0, 0, FIG3.width, FIG3.height);
  const { box } = FIG3;
  const x = scale(0, nMax, box.left, box.left + box.width);
  const y = scale(0, nMax, box.top + box.height, box.top);
  drawAxes(ctx, box, x, y, {
    xTicks: ticks(0, nMax, 5).map(Math.round), yTicks: ticks(0, nMax, 5).map(Math.round),
    xLabel: 'number of Bernoulli components n', yLabel: 'targets reported',
  });
  ctx.save();
  ctx.strokeStyle = '#9aa5b1';
  ctx.setLineDash([1, 3]);
  ctx.beginPath();
  ctx.moveTo(x(n), box.top);
  ctx.lineTo(x(n), box.top + box.height);
  ctx.stroke();
  ctx.restore();
  SERIES.forEach((s, k) => {
    ctx.save();
    ctx.strokeStyle = s.color;
    ctx.fillStyle = s.color;
    ctx.setLineDash(s.dash);
    ctx.lineWidth = 2;
    ctx.beginPath();
    fig3Counts[s.key].forEach((count, i) => {
      const px = x(i + 1);
      const py = y(count);
      if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    });
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillRect(box.left + 12, box.top + 8 + 16 * k, 14, 3);
    ctx.fillText(s.label, box.left + 32, box.top + 13 + 16 * k);
    ctx.restore();
  });
}

// ---------------------------------------------------------------- GOSPA playground
const PG = { size: 480, world: 10 };
const pg = { truth: [], estimate: [], mode: 'truth' };
const toPx = scale(0, PG.world, 0, PG.size);
const toPy = scale(0, PG.world, PG.size, 0);

function setMode(mode) {
  pg.mode = mode;
  $('mode-truth').setAttribute('aria-pressed', String(mode === 'truth'));
  $('mode-estimate').setAttribute('aria-pressed', String(mode === 'estimate'));
}

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
  pg.estimate = pg.truth
    .filter(() => rand() > 0.25)
    .map(([a, b]) => [a + (rand() - 0.5) * 1.6, b + (rand() - 0.5) * 1.6]);
  pg.estimate.push([1 + 8 * rand(), 1 + 8 * rand()]);
}

function updatePlayground() {
  const c = Number($('pg-c').value);
  const p = Number($('pg-p').value);
  $('pg-c-out').value = c.toFixed(2);
  $('pg-p-out').value = p.toFixed(1);
  const g = fisst.gospa(pg.truth, pg.estimate, { c, p });
  const o = fisst.ospa(pg.truth, pg.estimate, { c, p });
  $('gospa-distance').textContent = fmt(g.distance, 4);
  $('gospa-localisation').textContent = fmt(g.localisation, 4);
  $('gospa-missed').textContent = g.missed;
  $('gospa-false').textContent = g.falseTargets;
  $('ospa-distance').textContent = `${fmt(o.distance, 4)} (${fmt(o.localisation, 3)}, ${fmt(o.cardinality, 3)})`;
  $('pg-points').textContent = JSON.stringify({ truth: pg.truth, estimate: pg.estimate, c, p });

  const ctx = setupCanvas($('playground'), PG.size, PG.size);
  ctx.clearRect(0, 0, PG.size, PG.size);
  const assignedTruth = new Set(g.assignment.map(([i]) => i));
  const assignedEstimate = new Set(g.assignment.map(([, j]) => j));
  // cut-off discs around the truth
  ctx.fillStyle = 'rgba(37, 99, 235, 0.05)';
  for (const [a, b] of pg.truth) {
    ctx.beginPath();
    ctx.arc(toPx(a), toPy(b), toPx(c), 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.strokeStyle = '#52606d';
  ctx.lineWidth = 1.5;
  for (const [i, j] of g.assignment) {
    ctx.beginPath();
    ctx.moveTo(toPx(pg.truth[i][0]), toPy(pg.truth[i][1]));
    ctx.lineTo(toPx(pg.estimate[j][0]), toPy(pg.estimate[j][1]));
    ctx.stroke();
  }
  pg.truth.forEach(([a, b], i) => {
    ctx.fillStyle = '#1f2933';
    ctx.beginPath();
    ctx.arc(toPx(a), toPy(b), 5, 0, 2 * Math.PI);
    ctx.fill();
    if (!assignedTruth.has(i)) {
      ctx.strokeStyle = '#dc2626';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(toPx(a), toPy(b), 10, 0, 2 * Math.PI);
      ctx.stroke();
    }
  });
  pg.estimate.forEach(([a, b], j) => {
    ctx.strokeStyle = assignedEstimate.has(j) ? '#2563eb' : '#f59e0b';
    ctx.lineWidth = assignedEstimate.has(j) ? 2 : 3;
    const px = toPx(a);
    const py = toPy(b);
    ctx.beginPath();
    ctx.moveTo(px - 6, py - 6);
    ctx.lineTo(px + 6, py + 6);
    ctx.moveTo(px + 6, py - 6);
    ctx.lineTo(px - 6, py + 6);
    ctx.stroke();
  });
  ctx.fillStyle = '#616e7c';
  ctx.font = '12px system-ui, sans-serif';
  ctx.fillText('● truth  ✕ estimate  ○ missed (red)  ✕ false (orange)  — assigned', 8, 16);
}

function worldPoint(event) {
  const rect = $('playground').getBoundingClientRect();
  return [toPx.invert(event.clientX - rect.left), toPy.invert(event.clientY - rect.top)];
}

// ---------------------------------------------------------------- wiring
$('r1').addEventListener('input', updateTwoTargets);
$('r2').addEventListener('input', updateTwoTargets);
$('story-before').addEventListener('click', () => story('before'));
$('story-case1').addEventListener('click', () => story('case1'));
$('story-case2').addEventListener('click', () => story('case2'));
$('fig3-r').addEventListener('input', () => updateFig3(true));
$('fig3-nmax').addEventListener('input', () => updateFig3(true));
$('fig3-n').addEventListener('input', () => updateFig3(false));
$('mode-truth').addEventListener('click', () => setMode('truth'));
$('mode-estimate').addEventListener('click', () => setMode('estimate'));
$('pg-random').addEventListener('click', () => {
  randomScene(Date.now() % 100000);
  updatePlayground();
});
$('pg-clear').addEventListener('click', () => {
  pg.truth = [];
  pg.estimate = [];
  updatePlayground();
});
$('pg-c').addEventListener('input', updatePlayground);
$('pg-p').addEventListener('input', updatePlayground);
$('playground').addEventListener('click', (event) => {
  const kind = event.shiftKey ? (pg.mode === 'truth' ? 'estimate' : 'truth') : pg.mode;
  pg[kind].push(worldPoint(event));
  updatePlayground();
});
$('playground').addEventListener('contextmenu', (event) => {
  event.preventDefault();
  const [a, b] = worldPoint(event);
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

for (const e of estimators) mapImages.set(e, renderMapImage(e));
updateTwoTargets();
updateFig3(true);
randomScene(7);
updatePlayground();
document.body.dataset.ready = 'true';

// web/threshold.html in headless Chromium: the sliders move Γ's readouts (Fig. 3 and Fig. 2)
// to the values the npm package computes in Node; dragging a mixture component (mouse and
// touch) and moving p move a*, q(a*), q(mean) and the decision to bernoulliEstimate of the
// state the page reports; the redraw times of every panel are printed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { fmt } from '../../../web/lib/page.js';
import { checkDownloads, json, mouseDrag, pixelOf as viewPixel, reopen, text, timeLine, touchDrag, unitsPerPixel as upp, useBrowser } from './harness.mjs';

const browser = useBrowser();
const pageState = (page) => json(page, '#threshold-state');

/** Γ as the page prints it. */
const gammaText = (g) => (g === Infinity ? '∞ (never reports)' : g === -Infinity ? '−∞ (always reports)' : fmt(g, 4));
const pointText = (a) => `(${a[0].toFixed(3)}, ${a[1].toFixed(3)})`;
const mmol = (asset, countermeasure) => ({ mmol: { asset, countermeasure } });

/** The Fig. 3 readouts equal bernoulliThresholdCurve in Node for the page's r0 and costs. */
async function checkFig3(page, s, costs, r0) {
  assert.deepEqual(s.costs, costs);
  assert.equal(s.r0, r0);
  const [gamma] = fisst.bernoulliThresholdCurve({ sigmas: [1], radius: r0, costs });
  const [floor] = fisst.bernoulliThresholdCurve({ sigmas: [r0 * 1e-3], radius: r0, costs });
  assert.equal(s.fig3.gammaAt1, gamma);
  assert.equal(s.fig3.floor, floor);
  assert.equal(await text(page, '#gamma'), gammaText(gamma));
  assert.equal(await text(page, '#gamma-floor'), gammaText(floor));
  const q = fisst.probabilityOutsideBall({ density: { mean: [0], cov: 1 }, center: [0], radius: r0 });
  assert.equal(await text(page, '#q-sigma1'), fmt(q, 6));
  return gamma;
}

/** The Fig. 2 readouts equal bernoulliEstimate and bernoulliLossCurve in Node. */
async function checkFig2(page, s) {
  const { sigma } = s.fig2;
  const e = fisst.bernoulliEstimate({
    existence: 0.5, density: { mean: [0], cov: [[sigma * sigma]] }, radius: s.r0, costs: s.costs,
  });
  assert.equal(s.fig2.missProbability, e.missProbability);
  assert.equal(s.fig2.threshold, e.threshold);
  assert.equal(await text(page, '#fig2-gamma'), gammaText(e.threshold));
  assert.equal(await text(page, '#fig2-q'), fmt(e.missProbability, 6));
  // The band where the optimal rule's loss is strictly below the p > 0.5 rule's, on the grid.
  const ps = Array.from({ length: 1001 }, (_, k) => k / 1000);
  const opt = fisst.bernoulliLossCurve({ existences: ps, missProbability: e.missProbability, costs: s.costs });
  const conv = fisst.bernoulliLossCurve({
    existences: ps, missProbability: e.missProbability, costs: s.costs, threshold: 0.5,
  });
  const wins = ps.filter((_, k) => opt.rule[k] < conv.rule[k]);
  if (wins.length === 0) {
    assert.equal(s.fig2.band, null);
    assert.equal(await text(page, '#band'), 'nowhere: Γ = 0.5');
  } else {
    assert.deepEqual(s.fig2.band, [wins[0], wins.at(-1)]);
    assert.equal(await text(page, '#band'), `${wins[0].toFixed(3)} ≤ p ≤ ${wins.at(-1).toFixed(3)}`);
    // Fig. 2's statement: the band lies between Γ and 0.5 (to the grid step).
    const lo = Math.max(Math.min(e.threshold, 0.5), 0);
    const hi = Math.min(Math.max(e.threshold, 0.5), 1);
    assert.ok(wins[0] >= lo && wins[0] <= lo + 1e-3 + 1e-12, `${wins[0]} vs ${lo}`);
    assert.ok(wins.at(-1) <= hi && wins.at(-1) >= hi - 1e-3 - 1e-12, `${wins.at(-1)} vs ${hi}`);
  }
  return e;
}

/** The 2D view's readouts equal bernoulliEstimate / probabilityOutsideBall of its state. */
async function checkView(page, s) {
  const v = s.view;
  const density = { mixture: v.mixture };
  const e = fisst.bernoulliEstimate({ existence: v.p, density, radius: s.r0, costs: s.costs });
  // The same wasm module in Node and Chromium: bit-identical numbers.
  assert.deepEqual(v.estimate, e);
  const total = v.mixture.reduce((a, c) => a + c.weight, 0);
  for (const i of [0, 1]) {
    const m = v.mixture.reduce((a, c) => a + c.weight * c.mean[i], 0) / total;
    assert.ok(Math.abs(v.mean[i] - m) < 1e-12, `mean ${v.mean} vs ${m}`);
  }
  const qMean = fisst.probabilityOutsideBall({ density, center: v.mean, radius: s.r0 });
  assert.equal(v.qMean, qMean);
  assert.ok(qMean >= e.missProbability - 1e-9, 'a* holds at least as much as the mean');
  const decision = e.declare
    ? `report {a*}: p = ${fmt(v.p, 3)} > Γ = ${gammaText(e.threshold)}`
    : `report nothing: p = ${fmt(v.p, 3)} ≤ Γ = ${gammaText(e.threshold)}`;
  assert.equal(await text(page, '#decision'), decision);
  assert.equal(await page.locator('#decision').getAttribute('class'), e.declare ? 'report' : 'nothing');
  assert.equal(await text(page, '#gamma-2d'), gammaText(e.threshold));
  assert.equal(await text(page, '#mmuc'), pointText(e.mmuc));
  assert.equal(await text(page, '#q-mmuc'), fmt(e.missProbability, 6));
  assert.equal(await text(page, '#mean'), pointText(v.mean));
  assert.equal(await text(page, '#q-mean'), fmt(qMean, 6));
  assert.equal(await text(page, '#rho'), `${fmt(e.expectedLossEmpty, 4)}, ${fmt(e.expectedLossSingleton, 4)}`);
  return e;
}

/** Viewport pixel of a world point of the 2D view. */
const pixelOf = (page, s, point) => viewPixel(page, '#view', s.view, point);
const unitsPerPixel = (s) => upp(s.view);
const near = (a, b, tol = 0.02) => Math.abs(a[0] - b[0]) < tol && Math.abs(a[1] - b[1]) < tol;

test('threshold: r0, c_M and the preset move Γ to the package value (Figs 2 and 3)', async () => {
  const page = await browser.open('threshold.html');
  let s = await pageState(page);
  assert.equal(s.preset, 'mpe');
  // The paper's numbers at σ = 1, r0 = 1: Γ_MPE = 0.5943 (Fig. 2a).
  let g = await checkFig3(page, s, 'mpe', 1);
  assert.equal(await text(page, '#gamma'), '0.5943');
  assert.equal(await text(page, '#gamma-floor'), '0.5');
  await checkFig2(page, s);
  assert.equal(await text(page, '#band'), '0.501 ≤ p ≤ 0.594');
  await checkView(page, s);
  assert.ok(await page.locator('#c-m').isDisabled(), 'c_M is an MMOL cost');

  // r0: a larger tolerance lowers Γ towards 0.5.
  await page.locator('#r0').fill('3');
  s = await pageState(page);
  const g3 = await checkFig3(page, s, 'mpe', 3);
  assert.ok(g3 < g && g3 > 0.5, `${g3}`);
  await checkFig2(page, s);
  await checkView(page, s);

  // The MMOL preset (c_A = 0.9, c_M = 0.1), at r0 = 3 and then the paper's r0 = 1.
  await page.locator('#preset-mmol').click();
  assert.equal(await page.locator('#preset-mmol').getAttribute('aria-pressed'), 'true');
  assert.ok(!(await page.locator('#c-m').isDisabled()));
  s = await pageState(page);
  await checkFig3(page, s, mmol(0.9, 0.1), 3);
  await checkView(page, s);
  await page.locator('#r0').fill('1');
  s = await pageState(page);
  g = await checkFig3(page, s, mmol(0.9, 0.1), 1);
  assert.equal(await text(page, '#gamma'), '0.1628'); // Fig. 2b
  await checkFig2(page, s);
  assert.equal(await text(page, '#band'), '0.163 ≤ p ≤ 0.500');

  // c_M: Γ ≥ c_M/c_A, so a dearer countermeasure raises it.
  await page.locator('#c-m').fill('0.3');
  s = await pageState(page);
  const gm = await checkFig3(page, s, mmol(0.9, 0.3), 1);
  assert.ok(gm > g, `${gm} vs ${g}`);
  assert.equal(await text(page, '#gamma-floor'), fmt(0.3 / 0.9, 4));
  await checkFig2(page, s);
  await checkView(page, s);
  // c_M ≥ c_A: never reported (Γ > 1), even at p = 1.
  await page.locator('#c-a').fill('0.25');
  await page.locator('#p').fill('1');
  s = await pageState(page);
  const never = await checkFig3(page, s, mmol(0.25, 0.3), 1);
  assert.ok(never > 1);
  assert.equal((await checkView(page, s)).declare, false);
  // c_M = 0: always reported (Γ = 0), even at p = 0.01.
  await page.locator('#c-m').fill('0');
  await page.locator('#p').fill('0.01');
  s = await pageState(page);
  assert.equal(await checkFig3(page, s, mmol(0.25, 0), 1), 0);
  assert.equal((await checkView(page, s)).declare, true);
  await checkFig2(page, s);

  // σ of Fig. 2, then back to MPE: the band follows Γ.
  await page.locator('#c-a').fill('0.9');
  await page.locator('#c-m').fill('0.1');
  await page.locator('#sigma').fill('2');
  s = await pageState(page);
  assert.equal(s.fig2.sigma, 2);
  await checkFig2(page, s);
  await browser.screenshot(page, 'threshold-mmol');
  await page.locator('#preset-mpe').click();
  s = await pageState(page);
  await checkFig3(page, s, 'mpe', 1);
  const e2 = await checkFig2(page, s);
  assert.ok(e2.threshold > 0.5943, 'a wider density needs a higher threshold');
  await checkView(page, s);
  await browser.done(page);
});

test('threshold: dragging a component with the mouse moves a*, q(a*) and the decision', async () => {
  const page = await browser.open('threshold.html');
  const s0 = await pageState(page);
  assert.equal(s0.view.scene, 'three');
  const e0 = await checkView(page, s0);
  // The multimodal case: the mixture mean is a poor centre; a* sits on the heaviest mode, and
  // with MPE costs p = 0.6 is not enough to report (Γ > 0.6 > 0.5).
  assert.ok(s0.view.qMean > e0.missProbability + 0.2, `${s0.view.qMean} vs ${e0.missProbability}`);
  assert.ok(near(e0.mmuc, s0.view.mixture[0].mean, 0.05), `${e0.mmuc}`);
  assert.equal(e0.declare, false);
  const k = unitsPerPixel(s0);
  // p = 0.7 is still below Γ.
  await page.locator('#p').fill('0.7');
  const sp = await pageState(page);
  assert.equal(sp.view.p, 0.7);
  assert.equal((await checkView(page, sp)).declare, false);

  // Grab component 1 at its mean and drag it next to component 0: one ball now covers most
  // of both, q(a*) drops, Γ drops below p = 0.7 and the target is reported.
  const m1 = s0.view.mixture[1].mean;
  const [x0, y0] = await pixelOf(page, s0, m1);
  const [x1, y1] = await pixelOf(page, s0, [-1.6, -0.3]);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, { steps: 4 });
  const mid = await pageState(page);
  await checkView(page, mid);
  assert.equal(await page.locator('#view.dragging').count(), 1, 'dragging class while the button is down');
  await page.mouse.move(x1, y1, { steps: 4 });
  await page.mouse.up();
  const s1 = await pageState(page);
  assert.ok(near(s1.view.mixture[1].mean, [-1.6, -0.3], 2 * k), `${s1.view.mixture[1].mean}`);
  assert.deepEqual(s1.view.mixture[0], s0.view.mixture[0]);
  const e1 = await checkView(page, s1);
  assert.ok(e1.missProbability < e0.missProbability - 0.1, `${e1.missProbability}`);
  assert.ok(!near(e1.mmuc, e0.mmuc, 0.1), 'a* moved');
  assert.equal(e1.declare, true);

  // After release the mouse moves nothing.
  await page.mouse.move(x1 + 100, y1 + 100, { steps: 3 });
  assert.deepEqual((await pageState(page)).view.mixture, s1.view.mixture);
  // A press away from every component grabs nothing.
  const [xe, ye] = await pixelOf(page, s1, [4, -4]);
  await mouseDrag(page, [xe, ye], [xe - 50, ye - 50], 2);
  assert.deepEqual((await pageState(page)).view.mixture, s1.view.mixture);

  // p: below Γ nothing is reported.
  await page.locator('#p').fill('0.3');
  let s = await pageState(page);
  assert.equal(s.view.p, 0.3);
  assert.equal((await checkView(page, s)).declare, false);
  // The covariance scale, the MMOL preset and the other scenes.
  await page.locator('#spread').fill('2');
  s = await pageState(page);
  assert.equal(s.view.mixture[0].cov[0][0], 2 * s0.view.mixture[0].cov[0][0]);
  await checkView(page, s);
  await page.locator('#preset-mmol').click();
  await checkView(page, await pageState(page));
  await page.locator('#spread').fill('1');
  await page.locator('#scene-two').click();
  s = await pageState(page);
  assert.equal(s.view.scene, 'two');
  const e2 = await checkView(page, s);
  // Two close modes: a* lies between them, off both means.
  for (const c of s.view.mixture) assert.ok(!near(e2.mmuc, c.mean, 0.3), `${e2.mmuc} vs ${c.mean}`);
  await page.locator('#scene-one').click();
  s = await pageState(page);
  const e3 = await checkView(page, s);
  assert.deepEqual(e3.mmuc, s.view.mixture[0].mean); // Sherman: the mean of a Gaussian
  assert.equal(s.view.qMean, e3.missProbability);
  await page.locator('#scene-three').click();
  await checkView(page, await pageState(page));
  await browser.done(page, 'threshold-drag');
});

test('threshold: a touch drag moves a component too', async () => {
  const page = await browser.open('threshold.html');
  const s0 = await pageState(page);
  const k = unitsPerPixel(s0);
  const m2 = s0.view.mixture[2].mean;
  const [x0, y0] = await pixelOf(page, s0, m2);
  const types = await touchDrag(page, '#view', Array.from({ length: 6 }, (_, i) => [x0 - 24 * i, y0 + 20 * i]));
  assert.ok(types.includes('touch'), `pointer types seen: ${types}`);
  const s1 = await pageState(page);
  const want = [m2[0] - 120 * k, m2[1] - 100 * k];
  assert.ok(near(s1.view.mixture[2].mean, want), `${s1.view.mixture[2].mean} vs ${want}`);
  await checkView(page, s1);
  await browser.done(page);
});

test('threshold: redraw time of every panel', async () => {
  const page = await browser.open('threshold.html');
  // Warm up (the first calls compile and allocate), then clear the history.
  for (const v of ['1.5', '1']) await page.locator('#r0').fill(v);
  await page.evaluate(() => {
    for (const h of Object.values(window.fisstTiming.history)) h.length = 0;
  });
  const sweep = async (id, values) => {
    for (const v of values) await page.locator(id).fill(String(v));
  };
  const grid = (a, b, n) => Array.from({ length: n }, (_, i) => +(a + ((b - a) * i) / (n - 1)).toFixed(2));
  await sweep('#r0', grid(0.1, 4, 20));
  await sweep('#r0', ['1']);
  await sweep('#p', grid(0.05, 0.95, 19));
  await sweep('#sigma', grid(0.1, 4, 20));
  await sweep('#spread', grid(0.5, 3, 11));
  await sweep('#spread', ['1']);
  await page.locator('#preset-mmol').click();
  await sweep('#c-m', grid(0, 1, 21));
  await sweep('#c-a', grid(0.3, 2, 18));
  // A mouse drag of component 0 in 20 steps.
  const s = await pageState(page);
  const [x0, y0] = await pixelOf(page, s, s.view.mixture[0].mean);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + 160, y0 - 60, { steps: 20 });
  await page.mouse.up();
  await checkView(page, await pageState(page));
  const timing = await browser.timing(page);
  const last = timing.last;
  assert.equal(await text(page, '#redraw-view'), `${last.view.toFixed(1)} ms`);
  assert.equal(await text(page, '#redraw-total'), `${last.total.toFixed(1)} ms`);
  const line = timeLine;
  for (const panel of ['fig3', 'fig2', 'view', 'total']) assert.ok(timing.history[panel].length > 10, panel);
  console.log(`redraw (Chromium): ${line('Fig. 3', timing.history.fig3)}; ${line('Fig. 2', timing.history.fig2)}; `
    + `${line('2D view', timing.history.view)}; ${line('whole update', timing.history.total)}`);
  await browser.done(page, 'threshold');
});

test('threshold: the settings and the dragged means are in the URL', async () => {
  const page = await browser.open('threshold.html?preset=mmol&r0=2&cM=0.3&sigma=1.5&p=0.8&spread=1.5&scene=two');
  const s = await pageState(page);
  assert.deepEqual([s.preset, s.r0, s.cM, s.fig2.sigma, s.view.p, s.view.spread, s.view.scene], ['mmol', 2, 0.3, 1.5, 0.8, 1.5, 'two']);
  await checkFig3(page, s, mmol(0.9, 0.3), 2);
  await checkFig2(page, s);
  await checkView(page, s);
  // Drag a component, change p: the reopened URL shows the same view.
  const [x0, y0] = await pixelOf(page, s, s.view.mixture[0].mean);
  await mouseDrag(page, [x0, y0], [x0 - 60, y0 + 40], 3);
  await page.locator('#p').fill('0.35');
  const moved = await pageState(page);
  const again = await reopen(browser, page);
  const s2 = await pageState(again);
  assert.deepEqual(s2.view.mixture, moved.view.mixture);
  assert.deepEqual(s2.view.estimate, moved.view.estimate);
  assert.equal(s2.view.p, 0.35);
  // A malformed URL value falls back to the default without an error.
  const bad = await browser.open('threshold.html?r0=abc&means=[[1,2]]&preset=nope');
  const s3 = await pageState(bad);
  assert.deepEqual([s3.r0, s3.preset, s3.view.scene], [1, 'mpe', 'three']);
  await Promise.all([browser.done(page), browser.done(again, 'threshold-url'), browser.done(bad)]);
});

test('threshold: download buttons give the figures as PNG and CSV', async () => {
  const page = await browser.open('threshold.html');
  await checkDownloads(page, [['#fig3-figure', 402], ['#fig2-figure', 1002], ['#view-figure', 6]], 'threshold');
  await browser.done(page);
});

test('threshold: the 2D view zooms (Ctrl + wheel), pans (drag on empty space) and resets (double-click)', async () => {
  const page = await browser.open('threshold.html');
  const s0 = await pageState(page);
  const width = (v) => v.x[1] - v.x[0];
  // Zoom in about the middle of the view.
  const [cx, cy] = await pixelOf(page, s0, [0, 0]);
  await page.mouse.move(cx, cy);
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -100);
  await page.keyboard.up('Control');
  await page.waitForFunction((w) => {
    const v = JSON.parse(document.getElementById('threshold-state').textContent).view;
    return v.x[1] - v.x[0] < w;
  }, width(s0.view));
  const s1 = await pageState(page);
  assert.ok(width(s1.view) < 0.9 * width(s0.view), `${width(s1.view)}`);
  assert.ok(Math.abs((s1.view.x[0] + s1.view.x[1]) / 2) < 0.05, 'zoomed about the pointer');
  // A component is still dragged in data coordinates.
  const m = s1.view.mixture[0].mean;
  const [x0, y0] = await pixelOf(page, s1, m);
  await mouseDrag(page, [x0, y0], [x0 + 40, y0]);
  const s2 = await pageState(page);
  assert.ok(Math.abs(s2.view.mixture[0].mean[0] - (m[0] + 40 * unitsPerPixel(s1))) < 0.02, `${s2.view.mixture[0].mean}`);
  await checkView(page, s2);
  // Pan: a drag on empty space moves the view, not the mixture.
  const [ex, ey] = await pixelOf(page, s2, [s2.view.x[1] - 0.3, s2.view.y[0] + 0.3]);
  await mouseDrag(page, [ex, ey], [ex - 50, ey - 30]);
  const s3 = await pageState(page);
  assert.deepEqual(s3.view.mixture, s2.view.mixture);
  assert.ok(Math.abs(s3.view.x[0] - (s2.view.x[0] + 50 * unitsPerPixel(s2))) < 0.02, `${s3.view.x}`);
  assert.ok(Math.abs(width(s3.view) - width(s2.view)) < 1e-9);
  // Double-click: back to the initial view.
  await page.mouse.dblclick(ex, ey);
  const s4 = await pageState(page);
  assert.deepEqual([s4.view.x, s4.view.y], [s0.view.x, s0.view.y]);
  await browser.done(page, 'threshold-zoom');
});

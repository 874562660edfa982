// web/bounds.html in headless Chromium: the bounds it draws (Fig. 2 left, Fig. 3, Fig. 2 right)
// are the npm package's values in Node for the settings it reports; the sliders move them; the
// Monte Carlo of the worker attains the Gaussian bounds (Corollary 3, Enumeration) within 4
// standard errors and falls below the curve of Example 2 where NOTES.md says it is no bound;
// the settings are in the URL; the figures download as PNG and CSV.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { fmt } from '../../../web/lib/page.js';
import { checkDownloads, json, reopen, text, timeLine, useBrowser } from './harness.mjs';

const browser = useBrowser();
const pageState = (page) => json(page, '#bounds-state');
/** Waits until every Monte Carlo of the current settings is drawn; returns the state. */
async function settled(page) {
  await page.waitForFunction(() => {
    const s = JSON.parse(document.getElementById('bounds-state').textContent);
    return s.mcDone && Object.values(s.mcDone).every(Boolean);
  }, null, { timeout: 30_000 });
  return pageState(page);
}
const RS = Array.from({ length: 201 }, (_, k) => k / 200);

/** Fig. 2 left: the page's r*, r_M*, bound at r = 1 and Monte Carlo against the package. */
function checkLeft(s) {
  const { vf, e0, e1, po } = s.settings;
  const info = fisst.gaussianFisherInformation({ priorVariance: vf, gain: s.system.gain, noiseVariance: s.system.noiseVariance });
  assert.equal(s.system.posteriorVariance, info.posteriorVariance);
  const opts = (r) => ({ existence: r, detectionProbability: po, priorVariance: vf, posteriorVariance: info.posteriorVariance, falseAlarmError: e0, missError: e1 });
  const at1 = fisst.jdeBoundNoClutter(opts(1));
  assert.equal(s.left.boundAt1, at1.bound);
  assert.equal(s.left.rstar, at1.existenceThreshold);
  assert.equal(s.left.rmap, 1 / (2 - po));
  assert.equal(s.left.mc.length, 21);
  for (const p of s.left.mc) {
    const b = fisst.jdeBoundNoClutter(opts(p.r));
    assert.equal(p.bound, b.bound, `r = ${p.r}`);
    // The optimal detector-estimator attains the bound (and the MAP-on-∅ one its own).
    assert.ok(p.se === 0 ? Math.abs(p.mse - p.bound) < 1e-9 : Math.abs(p.mse - p.bound) < 4 * p.se, `r = ${p.r}: ${p.mse} ± ${p.se} vs ${p.bound}`);
    assert.ok(p.mapSe === 0 ? Math.abs(p.mapMse - p.mapBound) < 1e-9 : Math.abs(p.mapMse - p.mapBound) < 4 * p.mapSe, `MAP r = ${p.r}`);
    assert.ok(p.mapBound >= p.bound - 1e-12);
  }
  return s.left.worstZ;
}

/** Fig. 3: Enum and IRF are the package's; the Monte Carlo attains Enum. */
function checkSeq(s) {
  const { priorInformation, detectedInformation, detectionProbability, steps } = s.seq;
  assert.equal(steps, s.settings.steps);
  assert.equal(detectionProbability, s.settings.po);
  assert.equal(priorInformation, 1 / s.settings.vf);
  assert.equal(detectedInformation, s.system.information);
  const o = { priorInformation, detectedInformation, detectionProbability, steps };
  assert.deepEqual(s.seq.enumeration, fisst.jdeSequentialBound({ method: 'enumeration', ...o }).bound);
  assert.deepEqual(s.seq.irf, fisst.jdeSequentialBound({ method: 'irf', ...o }).bound);
  assert.equal(s.seq.mc.mse.length, steps);
  s.seq.mc.mse.forEach((m, k) => assert.ok(Math.abs(m - s.seq.enumeration[k]) < 4 * s.seq.mc.se[k], `k = ${k + 1}`));
  return s.seq.worstZ;
}

test('bounds: the figures are the package values, the sliders move them, and the Monte Carlo attains the Gaussian bounds', async () => {
  const page = await browser.open('bounds.html');
  let s = await settled(page);
  assert.deepEqual(s.settings, { vf: 100, vh: 25, e0: 150, e1: 200, po: 0.5, steps: 20, r2: 0.6, e02: 1.2, q: 0.5, lambda: 1 });
  // The paper's Fig. 2 left at P̄o = 0.5: σh² = 25, r* = 0.75, bound 62.5 at r = 1.
  assert.equal(s.system.posteriorVariance, 25);
  assert.equal(await text(page, '#rstar'), '0.75');
  assert.equal(await text(page, '#bound-r1'), '62.5');
  const zs = [checkLeft(s), checkSeq(s)];
  assert.equal(await text(page, '#seq-j'), '0.01, 0.04');

  // P̄o moves the thick curve, r*, the dots and Fig. 3.
  await page.locator('#po').fill('0.8');
  s = await settled(page);
  assert.equal(s.settings.po, 0.8);
  assert.equal(await text(page, '#rstar'), fmt(150 / (150 + 100 * 0.2), 4));
  assert.equal(await text(page, '#bound-r1'), fmt(100 - 75 * 0.8, 4));
  zs.push(checkLeft(s), checkSeq(s));
  // σh², e0², e1², σf² and the number of scans.
  for (const [id, v] of [['#vh', '50'], ['#e0', '60'], ['#e1', '300'], ['#vf', '200'], ['#steps', '40']]) {
    await page.locator(id).fill(v);
    s = await settled(page);
    zs.push(checkLeft(s), checkSeq(s));
  }
  assert.equal(s.seq.enumeration.length, 40);
  assert.equal(s.system.posteriorVariance, fisst.gaussianFisherInformation({ priorVariance: 200, gain: 1, noiseVariance: 200 * 50 / 150 }).posteriorVariance);
  // The σh² slider stops at σf² (no information: the bound at r = 1 is σf² whatever P̄o).
  await page.locator('#vh').fill('300');
  s = await settled(page);
  assert.equal(s.settings.vh, 200);
  assert.equal(s.system.gain, 0);
  assert.ok(Math.abs(s.left.boundAt1 - 200) < 1e-9, `${s.left.boundAt1}`);
  zs.push(checkLeft(s), checkSeq(s));
  console.log(`Monte Carlo on the page: worst |z| ${fmt(Math.max(...zs), 3)} over ${zs.length} settings (Fig. 2 left and Fig. 3)`);
  await browser.done(page, 'bounds-sliders');
});

test('bounds: Fig. 2 right is jdeExample2, and the Monte Carlo falls below it where it is no bound', async () => {
  const page = await browser.open('bounds.html');
  let s = await settled(page);
  const check = async (st) => {
    const { r2: r, e02: e0 } = st.settings;
    assert.equal(st.right.r, r);
    for (const [i, P] of [0.1, 0.4, 0.7, 1].entries()) {
      for (const k of [0, 5, 12, 20]) {
        const e = fisst.jdeExample2({ existence: r, detectionProbability: P, falseAlarmProbability: k / 20, falseAlarmError: e0 });
        assert.equal(st.right.paper[i][k], e.paperBound, `P_o = ${P}, q = ${k / 20}`);
        assert.equal(st.right.curves[i][k], e.bound, `P_o = ${P}, q = ${k / 20}`);
      }
    }
    assert.equal(st.right.mc.length, 44);
    for (const p of st.right.mc) assert.equal(p.below, p.mse + 2 * p.se < Math.min(p.bound, p.paperBound));
    assert.equal(await text(page, '#right-below'), `${st.right.below} of 44`);
    return st;
  };
  await check(s);
  // NOTES.md: 1/J_1 = 0.1897, the MMSE 0.0340 at r = 1, P_o = 1; σe² = 0.0341.
  const reg = fisst.jdeExample2Regularity();
  assert.equal(await text(page, '#right-j1'), fmt(reg.inverseInformation, 4));
  assert.equal(fmt(reg.inverseInformation, 4), '0.1897');
  assert.equal(await text(page, '#right-mmse'), fmt(reg.posteriorMeanMse, 4));
  assert.ok(Math.abs(s.right.reference.mse - reg.posteriorMeanMse) < 4 * s.right.reference.se + 1e-4, `${s.right.reference.mse}`);
  assert.ok(Math.abs(s.right.variance - 0.0341) < 1e-4);
  // r = 1: every P_o = 1 dot sits far below its curve (ringed).
  await page.locator('#r2').fill('1');
  s = await check(await settled(page));
  assert.ok(s.right.mc.filter((p) => p.P === 1).every((p) => p.below), 'P_o = 1, r = 1: every dot below the curve');
  await page.locator('#e02').fill('2');
  await check(await settled(page));
  await browser.done(page, 'bounds-right');
});

/** Theorems 1 and 2 over r: the page's curves are jdeBound in Node; the Monte Carlo attains
 * model I within 4 SE and never falls 4 SE below model II. */
function checkThm(s) {
  const { q, lambda } = s.settings;
  assert.equal(s.thm.q, q);
  assert.equal(s.thm.lambda, lambda);
  const { prior, observation, falseAlarmError, missError } = s.thm.system;
  const base = { prior: { gaussian: prior }, observation, falseAlarmError, missError };
  assert.equal(s.thm.points.length, 21);
  for (const [i, p] of s.thm.points.entries()) {
    const one = fisst.jdeBound({ ...base, model: 'I', existence: p.r, falseAlarm: { probability: q, density: { gaussian: { mean: 1, variance: 25 } } } });
    const two = fisst.jdeBound({ ...base, model: 'II', existence: p.r, clutter: { rate: lambda, density: { gaussian: { mean: 0, variance: 25 } } }, samples: 2000, seed: 4 + i });
    assert.equal(p.model1.bound, one.bound, `model I r = ${p.r}`);
    assert.equal(p.model2.bound, two.bound, `model II r = ${p.r}`);
    const z1 = p.mc1.se > 0 ? (p.mc1.mse - one.bound) / Math.hypot(p.mc1.se, one.error) : 0;
    const z2 = p.mc2.se > 0 ? (p.mc2.mse - two.bound) / Math.hypot(p.mc2.se, two.error) : 0;
    assert.ok(Math.abs(z1) < 4, `model I r = ${p.r}: ${p.mc1.mse} ± ${p.mc1.se} vs ${one.bound}`);
    assert.ok(z2 > -4, `model II r = ${p.r}: ${p.mc2.mse} ± ${p.mc2.se} below ${two.bound}`);
  }
  return [s.thm.worstZ1, s.thm.lowestZ2];
}

test('bounds: Theorems 1 and 2 against r are jdeBound, attained by the Monte Carlo for model I and never undercut for model II', async () => {
  const page = await browser.open('bounds.html');
  let s = await settled(page);
  const seen = [checkThm(s)];
  await page.locator('#thm-q').fill('0.9');
  s = await settled(page);
  seen.push(checkThm(s));
  await page.locator('#thm-lambda').fill('2.5');
  s = await settled(page);
  assert.equal(s.settings.lambda, 2.5);
  seen.push(checkThm(s));
  console.log(`Theorems 1–2 on the page: model I worst |z| ${fmt(Math.max(...seen.map((v) => v[0])), 3)}, model II lowest z ${fmt(Math.min(...seen.map((v) => v[1])), 3)} over ${seen.length} settings`);
  await browser.done(page, 'bounds-theorems');
});

test('bounds: the settings are in the URL, and a malformed value falls back to the default', async () => {
  const page = await browser.open('bounds.html?vf=150&vh=30&e0=100&e1=250&po=0.3&steps=12&r2=0.8&e02=0.5');
  const s = await settled(page);
  assert.deepEqual(s.settings, { vf: 150, vh: 30, e0: 100, e1: 250, po: 0.3, steps: 12, r2: 0.8, e02: 0.5, q: 0.5, lambda: 1 });
  checkLeft(s);
  checkSeq(s);
  await page.locator('#po').fill('0.65');
  await settled(page);
  const again = await reopen(browser, page);
  assert.equal((await settled(again)).settings.po, 0.65);
  const bad = await browser.open('bounds.html?po=abc&steps=-4&vf=50&vh=80');
  const s3 = await settled(bad);
  assert.equal(s3.settings.po, 0.5);
  assert.equal(s3.settings.steps, 2); // the sliders clamp
  assert.equal(s3.settings.vh, 50); // σh² ≤ σf²
  await Promise.all([browser.done(page), browser.done(again), browser.done(bad)]);
});

test('bounds: download buttons give the figures as PNG and CSV; redraw times', async () => {
  const page = await browser.open('bounds.html');
  await settled(page);
  await checkDownloads(page, [['#left-figure', 202], ['#seq-figure', 21], ['#right-figure', 22], ['#thm-figure', 22]], 'bounds');
  for (const v of ['0.2', '0.4', '0.6', '0.8', '1']) await page.locator('#po').fill(v);
  for (const v of ['0.2', '0.5', '0.9']) await page.locator('#r2').fill(v);
  await settled(page);
  const t = await browser.timing(page);
  console.log(`redraw (Chromium): ${timeLine('Fig. 2 left', t.history.left)}; ${timeLine('Fig. 3', t.history.seq)}; ${timeLine('Fig. 2 right', t.history.right)}`);
  await browser.done(page, 'bounds-po1');
});

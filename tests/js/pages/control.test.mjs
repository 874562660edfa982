// web/control.html in headless Chromium: the page opens with the first scan drawn (the work
// runs in a module worker), steps the live run to what SensorControlRun gives in Node for the
// same options, keeps its settings in the URL, and a tiny comparison moves the progress bar
// and the three Fig. 3 charts; the step and redraw times are printed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { csvLines, reopen, text, timeLine, useBrowser } from './harness.mjs';

const browser = useBrowser();

/** The state the page publishes (JSON, with −∞ rewards written as '-Infinity'). */
const pageState = async (page) => JSON.parse(await text(page, '#control-state'), (_, v) => (v === '-Infinity' ? -Infinity : v));
const SMALL = 'particles=100&futureScans=20&steps=6';

/** Waits until the live run reports scan k. */
const waitForScan = (page, k) => page.waitForFunction((kk) => JSON.parse(document.getElementById('control-state').textContent).k >= kk, k, { timeout: 60_000 });

/** The same run in Node, stepped k times: the page's worker must give identical numbers. */
function nodeRun(options, k) {
  const run = new fisst.SensorControlRun(options);
  try {
    let last = null;
    for (let i = 0; i < k; i++) last = run.step();
    return { last, sensorPath: run.sensorPath, truth: run.truth, measurements: run.measurements.at(-1), particles: run.particles.weights.length };
  } finally {
    run.free();
  }
}

test('control: opens on scan 1, steps, and equals SensorControlRun in Node', async () => {
  const page = await browser.open(`control.html?${SMALL}`);
  let s = await pageState(page);
  assert.equal(s.k, 1);
  assert.deepEqual(s.options, { seed: 1, scheme: 'renyi', particles: 100, futureScans: 20, alpha: 0.5, steps: 6 });
  assert.equal(s.particles, 100);
  assert.equal(s.step.rewards.length, 17);
  assert.equal(await text(page, '#k'), '1 of 6');
  // Two steps by the button; the page keeps answering meanwhile (the worker does the work).
  await page.locator('#step').click();
  await waitForScan(page, 2);
  await page.locator('#step').click();
  await waitForScan(page, 3);
  s = await pageState(page);
  const node = nodeRun(s.options, 3);
  assert.deepEqual(s.step, node.last);
  assert.deepEqual(s.sensorPath, node.sensorPath);
  assert.deepEqual(s.truth, node.truth);
  assert.deepEqual(s.measurements, node.measurements);
  assert.equal(await text(page, '#ospa'), `${+node.last.ospa.distance.toFixed(4)} m`);
  // Play runs to the end (K = 6), then the button offers a restart.
  await page.locator('#play').click();
  await waitForScan(page, 6);
  await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('done'));
  s = await pageState(page);
  assert.deepEqual(s.step, nodeRun(s.options, 6).last);
  // The downloads: the OSPA chart's six rows, the scene's particles, moves and truth.
  const run = await csvLines(page, '#run-figure');
  assert.equal(run.length, 7);
  assert.deepEqual(run.at(-1).split(',').slice(0, 4).map(Number), [6, s.step.ospa.distance, s.step.ospa.localisation, s.step.ospa.cardinality]);
  const scene = await csvLines(page, '#scene-figure');
  assert.equal(scene.filter((l) => l.startsWith('move,')).length, 17);
  assert.equal(scene.filter((l) => l.startsWith('truth,')).length, 2);
  const png = page.waitForEvent('download');
  await page.locator('#scene-figure [data-download="png"]').click();
  assert.match((await png).suggestedFilename(), /^control-renyi-k6\.png$/);
  const t = await browser.timing(page);
  console.log(`control (Chromium, N = 100, M = 20): ${timeLine('step in the worker', t.history.step)}; ${timeLine('scene', t.history.scene)}`);
  await browser.done(page, 'control-run');
});

test('control: a setting restarts the run and stays in the URL', async () => {
  const page = await browser.open(`control.html?${SMALL}`);
  await page.locator('#scheme-fisher').click();
  await page.locator('#seed').fill('7');
  await page.waitForFunction(() => {
    const s = JSON.parse(document.getElementById('control-state').textContent);
    return s.options.seed === 7 && s.k === 1;
  });
  const s = await pageState(page);
  assert.equal(s.options.scheme, 'fisher');
  assert.equal(await page.locator('#scheme-fisher').getAttribute('aria-pressed'), 'true');
  assert.deepEqual(s.step, nodeRun(s.options, 1).last);
  const again = await reopen(browser, page);
  const s2 = await pageState(again);
  assert.deepEqual(s2.options, s.options);
  assert.deepEqual(s2.step, s.step);
  const bad = await browser.open('control.html?scheme=nope&particles=abc&steps=6');
  const s3 = await pageState(bad);
  assert.deepEqual([s3.options.scheme, s3.options.particles], ['renyi', 750]);
  await Promise.all([browser.done(page), browser.done(again), browser.done(bad)]);
});

test('control: the future-scans slider stops at the package work cap (N·M ≤ 300,000)', async () => {
  // A URL past the cap (2000 × 500 = 10^6) opens at M = 150, and the run starts (no error).
  const page = await browser.open('control.html?particles=2000&futureScans=500&steps=2');
  await page.waitForFunction(() => JSON.parse(document.getElementById('control-state').textContent).k === 1, null, { timeout: 60_000 });
  const s = await pageState(page);
  assert.deepEqual([s.options.particles, s.options.futureScans], [2000, 150]);
  assert.equal(await page.locator('#future-scans').getAttribute('max'), '150');
  assert.doesNotMatch(await text(page, '#status'), /Error/);
  // Fewer particles give the slider its range back.
  await page.locator('#particles').fill('500');
  assert.equal(await page.locator('#future-scans').getAttribute('max'), '500');
  await browser.done(page);
});

test('control: a tiny comparison moves the progress bar and the Fig. 3 charts', async () => {
  const page = await browser.open('control.html?particles=100&futureScans=20&steps=4&runs=2');
  assert.equal(await text(page, '#compare-progress output'), 'not started');
  await page.locator('#compare').click();
  assert.equal(await text(page, '#compare'), 'stop');
  await page.waitForFunction(() => document.querySelector('#compare-progress progress').value > 0, null, { timeout: 60_000 });
  await page.waitForFunction(() => document.getElementById('compare-status').textContent.startsWith('done'), null, { timeout: 120_000 });
  assert.equal(await page.locator('#compare-progress progress').evaluate((el) => el.value), 1);
  // Every chart has a line per scheme: the legend's read-outs are numbers, not dashes.
  const fig3 = await page.evaluate(() => window.fisstFig3);
  for (const part of ['distance', 'localisation', 'cardinality']) {
    for (const scheme of ['renyi', 'fisher', 'pent', 'random']) {
      const st = fig3.stats[scheme][part];
      assert.equal(st.mean.length, 4, `${scheme} ${part}`);
      assert.ok(st.mean.every(Number.isFinite), `${scheme} ${part} ${st.mean}`);
      assert.ok(st.standardError.every((e) => Number.isFinite(e) && e >= 0), `${scheme} ${part} ${st.standardError}`);
    }
  }
  assert.equal(fig3.runs, 2);
  // Run r of the page is compareSchemes({ runs: 1, seed: seed + r }) (control.worker.js):
  // the page's pooled means and standard errors equal those of the two Node calls.
  const options = { runs: 1, steps: 4, schemes: ['renyi', 'fisher', 'pent', 'random'], particles: 100, futureScans: 20, alpha: 0.5 };
  const [a, b] = [1, 2].map((seed) => fisst.compareSchemes({ ...options, seed }));
  a.schemes.forEach((s, i) => {
    for (const part of ['distance', 'localisation', 'cardinality']) {
      s[part].mean.forEach((x, t) => {
        const y = b.schemes[i][part].mean[t];
        const [mean, se] = [(x + y) / 2, Math.abs(x - y) / 2]; // s = |x − y|/√2, se = s/√2
        const got = fig3.stats[s.scheme][part];
        assert.ok(Math.abs(got.mean[t] - mean) <= 1e-9 * Math.max(1, mean), `${s.scheme} ${part} mean[${t}]: ${got.mean[t]} vs ${mean}`);
        assert.ok(Math.abs(got.standardError[t] - se) <= 1e-9 * Math.max(1, se), `${s.scheme} ${part} se[${t}]: ${got.standardError[t]} vs ${se}`);
      });
    }
  });
  // The charts hold the pooled means: their CSVs have a row per scan, a number per scheme.
  for (const [figure, part] of [['#fig3a-figure', 'distance'], ['#fig3b-figure', 'localisation'], ['#fig3c-figure', 'cardinality']]) {
    const lines = await csvLines(page, figure);
    assert.equal(lines.length, 5, figure);
    lines.slice(1).forEach((l, t) => assert.deepEqual(l.split(',').map(Number), [t + 1, ...['renyi', 'fisher', 'pent', 'random'].map((sc) => fig3.stats[sc][part].mean[t])], figure));
  }
  await page.locator('#fig3a').scrollIntoViewIfNeeded();
  await browser.done(page, 'control-compare');
});

test('control: the page keeps answering while the worker runs a paper-size Rényi step', async () => {
  const page = await browser.open('control.html'); // N = 750, M = 200: about 1.7 s a step
  await page.locator('#step').click();
  assert.match(await text(page, '#status'), /^scan 2 of 40…/);
  // While the step runs, frames keep coming and a click is handled at once. The frames are
  // counted while the status still says the step runs (how long a step takes depends on the
  // machine's load: the test needs a few frames of it, not a slow step).
  const { gaps, running } = await page.evaluate(() => new Promise((resolve) => {
    const out = [];
    let last = performance.now();
    const busy = () => /^scan 2 of 40…/.test(document.querySelector('#status').textContent);
    const frame = (t) => {
      if (!busy()) return resolve({ gaps: out, running: false });
      out.push(t - last);
      last = t;
      if (out.length < 20) requestAnimationFrame(frame);
      else resolve({ gaps: out, running: true });
    };
    requestAnimationFrame(frame);
  }));
  assert.ok(gaps.length >= 3, `only ${gaps.length} frames while the step ran`);
  assert.ok(Math.max(...gaps.slice(1)) < 250, `frame gaps ${gaps.map((g) => g.toFixed(0))} ms`);
  if (running) assert.match(await text(page, '#status'), /^scan 2 of 40…/, 'the step was still running');
  await page.locator('details summary').click();
  assert.equal(await page.locator('details').evaluate((el) => el.open), true);
  await waitForScan(page, 2);
  await browser.done(page);
});

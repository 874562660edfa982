// web/airport.html in headless Chromium: the worker's run of both filters equals the npm
// package's GmBernoulliFilter and ParticleBernoulliFilter in Node, step for step (the same
// wasm: identical numbers); back/step/play/pause move the step shown and the figures; the
// density toggle hides the particle cloud; a new seed reruns; the URL keeps the settings.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { json, reopen, text, timeLine, useBrowser } from './harness.mjs';

const browser = useBrowser();
const pageState = (page) => json(page, '#airport-state');
const runDone = (page) => page.waitForSelector('body[data-run="done"]', { timeout: 60_000 });

/** Both filters on airportScenario({ seed }) in Node: existence and position error per step. */
function nodeRun(seed, { particles = 5000, withParticles = true } = {}) {
  const s = fisst.airportScenario({ seed, steps: 60 });
  const gm = new fisst.GmBernoulliFilter(s.config);
  const pf = withParticles ? new fisst.ParticleBernoulliFilter({ ...s.config, particles }) : null;
  const out = { gm: [], pf: [], gmErr: [] };
  try {
    for (let k = 0; k < 60; k++) {
      const reports = s.reports[k].map((a) => ({ disc: { center: s.anchors[a].position, radius: s.anchors[a].radius } }));
      gm.predict();
      gm.update(reports);
      out.gm.push(gm.existence);
      const e = gm.estimate();
      out.gmErr.push(Math.hypot(e.mean[0] - s.truth[k].state[0], e.mean[1] - s.truth[k].state[1]));
      if (pf) {
        pf.predict();
        pf.update(reports);
        out.pf.push(pf.existence);
      }
    }
  } finally {
    gm.free();
    pf?.free();
  }
  return out;
}

/** Pixels of the scene canvas of the particles' hue (vermillion, 25°; amber is 41°, blue 201°). */
const cloudPixels = (page) => page.locator('#scene').evaluate((c) => {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) {
    const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
    const max = Math.max(r, g, b);
    const span = max - Math.min(r, g, b);
    if (d[i + 3] < 128 || span < 40 || max !== r) continue;
    const hue = 60 * ((g - b) / span);
    if (hue > 15 && hue < 33) n++;
  }
  return n;
});

test('airport: the worker runs both filters to the package values; play, step, toggle, seed', async () => {
  const page = await browser.open('airport.html');
  await runDone(page);
  let s = await pageState(page);
  assert.equal(s.seed, 7);
  assert.equal(s.computed, 60);
  assert.equal(s.done, true);
  assert.equal(s.k, 59);
  const node = nodeRun(7);
  assert.deepEqual(s.existence.gm, node.gm);
  assert.deepEqual(s.existence.pf, node.pf);
  assert.deepEqual(s.position.gmErr, node.gmErr);
  // Fig. 7b's statement: the existence stays high and the two filters agree (paper: "similar").
  assert.ok(Math.min(...s.existence.gm.slice(5)) > 0.3, 'GM existence');
  const diff = s.existence.gm.map((r, k) => Math.abs(r - s.existence.pf[k]));
  assert.ok(Math.max(...diff) < 0.35, `GM vs PF existence differ by ${Math.max(...diff)}`);
  assert.ok(s.position.gmRss.every((v) => v > 0) && s.velocity.pfRss.every((v) => v > 0));
  assert.match(await text(page, '#story'), /^Step k = 60, t = 900 s: /);
  assert.equal(await text(page, '#gm-r'), (await text(page, '#gm-r')).trim());

  // Back and step move the step shown, the story and the read-outs.
  await page.click('#back');
  s = await pageState(page);
  assert.equal(s.k, 58);
  assert.match(await text(page, '#story'), /^Step k = 59, t = 885 s: /);
  assert.equal(Number(await text(page, '#gm-r')), Number(node.gm[58].toPrecision(4)));
  await page.click('#step');
  assert.equal((await pageState(page)).k, 59);

  // Play from the end restarts at k = 0 and advances; pause stops.
  await page.click('#play');
  await page.waitForTimeout(1200);
  await page.click('#play');
  const k1 = (await pageState(page)).k;
  assert.ok(k1 >= 1 && k1 < 20, `played to ${k1}`);
  await page.waitForTimeout(600);
  assert.equal((await pageState(page)).k, k1, 'paused');
  assert.equal(await page.locator('#play').getAttribute('aria-pressed'), 'false');

  // The toggle: particles only, GM only (the cloud is gone).
  const both = await cloudPixels(page);
  await page.click('#view-gm');
  const gmOnly = await cloudPixels(page);
  await page.click('#view-pf');
  const pfOnly = await cloudPixels(page);
  assert.ok(both > 50 && pfOnly > 50, `cloud pixels: both ${both}, particles ${pfOnly}`);
  assert.ok(gmOnly < both / 5, `GM only still shows ${gmOnly} cloud pixels (both: ${both})`);
  assert.equal((await pageState(page)).view, 'pf');

  // A new seed reruns both filters.
  await page.fill('#seed', '3');
  await page.locator('#seed').blur(); // the input's change event
  await page.waitForFunction(() => !document.body.dataset.run);
  await runDone(page);
  s = await pageState(page);
  assert.equal(s.seed, 3);
  assert.equal(s.k, 59);
  assert.deepEqual(s.existence.gm, nodeRun(3, { withParticles: false }).gm);
  const t = await browser.timing(page);
  for (const [panel, label] of [['scene', 'scene redraw'], ['charts', 'charts update'], ['gm', 'GM predict+update (worker)'], ['pf', 'PF predict+update (worker, 5000 particles)']]) {
    console.log(timeLine(`airport: ${label}`, t.history[panel]));
  }
  const whole = await page.locator('#progress output').textContent();
  console.log(`airport: whole run ${whole}`);

  // The URL keeps the seed and the view.
  await page.click('#back');
  const again = await reopen(browser, page);
  await runDone(again);
  const s2 = await pageState(again);
  assert.equal(s2.seed, 3);
  assert.equal(s2.view, 'pf');
  assert.equal(s2.k, 58);
  await browser.done(again);
  await page.click('#view-both');
  await browser.done(page, 'airport');
});

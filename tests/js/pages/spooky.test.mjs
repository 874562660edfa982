// web/spooky.html in headless Chromium: its controls move its readouts to the values the npm
// package computes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { pixelOf, reopen, text, useBrowser } from './harness.mjs';

const browser = useBrowser();

function describe(report) {
  const on = report.map((u, i) => (u ? i + 1 : 0)).filter(Boolean);
  return on.length === 0 ? 'report nothing' : `report ${on.join(' and ')}`;
}

test('spooky: sliders move the decisions to the package values', async () => {
  const page = await browser.open('spooky.html');
  for (const [r1, r2] of [[0.4, 0.4], [0.4, 0.9], [0.4, 0.1], [0.7, 0.2], [0.55, 0.05]]) {
    await page.locator('#r1').fill(String(r1));
    await page.locator('#r2').fill(String(r2));
    for (const metric of ['gospa', 'ospa', 'uospa']) {
      const expected = fisst.mbOptimalEstimate({ existence: [r1, r2], metric });
      assert.equal(await text(page, `#decision-${metric}`), describe(expected.report), `${metric} at ${r1},${r2}`);
    }
  }
  // The story buttons walk through Example 5.
  await page.locator('#story-case1').click();
  assert.equal(await text(page, '#decision-ospa'), 'report 2');
  assert.match(await text(page, '#story'), /OSPA now report 2/);
  await page.locator('#story-case2').click();
  assert.equal(await text(page, '#decision-ospa'), 'report nothing');
  // A click on a decision map sets (r1, r2) to the point clicked.
  const map = { box: { left: 48, top: 8, width: 176, height: 188 }, x: [0, 1], y: [0, 1] };
  const [mx, my] = await pixelOf(page, '#map-ospa', map, [0.7, 0.2]);
  await page.mouse.click(mx, my);
  const [r1, r2] = [Number(await page.locator('#r1').inputValue()), Number(await page.locator('#r2').inputValue())];
  assert.ok(Math.abs(r1 - 0.7) < 0.01 && Math.abs(r2 - 0.2) < 0.01, `${r1}, ${r2}`);
  const expected = fisst.mbOptimalEstimate({ existence: [r1, r2], metric: 'ospa' });
  assert.equal(await text(page, '#decision-ospa'), describe(expected.report));
  await browser.done(page);
});

test('spooky: Fig. 3 readout follows eq. (11)', async () => {
  const page = await browser.open('spooky.html');
  await page.locator('#fig3-r').fill('0.2');
  await page.locator('#fig3-nmax').fill('40');
  for (const n of [5, 7, 8, 20]) {
    await page.locator('#fig3-n').fill(String(n));
    const expected = (1 - 0.2) ** n < 0.2 ? n : 0;
    assert.equal(Number(await text(page, '#fig3-ospa')), expected, `n=${n}`);
    assert.equal(Number(await text(page, '#fig3-gospa')), 0);
  }
  await browser.done(page);
});

test('spooky: clicking points updates the GOSPA decomposition', async () => {
  const page = await browser.open('spooky.html');
  await page.locator('#pg-clear').click();
  const canvas = page.locator('#playground');
  const box = await canvas.boundingBox();
  // truth at two places, one estimate near the first, one far away
  await canvas.click({ position: { x: 100, y: 100 } });
  await canvas.click({ position: { x: 300, y: 300 } });
  await canvas.click({ position: { x: 112, y: 100 }, modifiers: ['Shift'] });
  await canvas.click({ position: { x: 420, y: 60 }, modifiers: ['Shift'] });
  assert.ok(box.width > 400);
  const state = JSON.parse(await text(page, '#pg-points'));
  assert.equal(state.truth.length, 2);
  assert.equal(state.estimate.length, 2);
  const g = fisst.gospa(state.truth, state.estimate, { c: state.c, p: state.p });
  assert.equal(Number(await text(page, '#gospa-missed')), g.missed);
  assert.equal(Number(await text(page, '#gospa-false')), g.falseTargets);
  assert.equal(g.missed, 1);
  assert.equal(g.falseTargets, 1);
  assert.ok(Math.abs(Number(await text(page, '#gospa-distance')) - g.distance) < 1e-4);
  // moving the cut-off slider changes the distance
  await page.locator('#pg-c').fill('4');
  const g4 = fisst.gospa(state.truth, state.estimate, { c: 4, p: state.p });
  assert.ok(Math.abs(Number(await text(page, '#gospa-distance')) - g4.distance) < 1e-4);
  assert.deepEqual(page.errors, []);
  await browser.screenshot(page, 'spooky-playground');
  // The points, c and the sliders are in the URL: the reopened page shows the same.
  await page.locator('#r1').fill('0.7');
  const again = await reopen(browser, page);
  assert.deepEqual(JSON.parse(await text(again, '#pg-points')), { ...state, c: 4 });
  assert.equal(await again.locator('#r1').inputValue(), '0.7');
  assert.equal(await text(again, '#gospa-distance'), await text(page, '#gospa-distance'));
  await browser.done(page);
  await browser.done(again);
});

// web/placement.html in headless Chromium: dragging the FoV (mouse and touch) moves its
// readouts to the values the npm package computes for the FoV the page reports, the sliders
// move the variance map's argmax to the package's, and the map recompute time is printed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { fmt } from '../../../web/lib/page.js';
import { json, pixelOf as viewPixel, reopen, text, touchDrag, unitsPerPixel as upp, useBrowser } from './harness.mjs';

const browser = useBrowser();
const pageState = (page) => json(page, '#placement-state');

/** The scene the page reports, rebuilt in Node. */
const sceneOf = (s) => fisst.placementScene(s.scene).multiBernoulli;

/** The page's readouts for its FoV equal fovCardinality of that FoV, computed in Node. */
async function checkFovReadouts(page, s) {
  const [cx, cy] = s.fov.center;
  const h = s.fovSize[0] / 2;
  assert.deepEqual(s.fov.box, { min: [cx - h, cy - h], max: [cx + h, cy + h] });
  const want = fisst.fovCardinality({ rfs: { multiBernoulli: sceneOf(s) }, fov: { box: s.fov.box } });
  // The same wasm module in Node and Chromium: bit-identical numbers.
  assert.equal(s.fov.mean, want.mean);
  assert.equal(s.fov.variance, want.variance);
  assert.equal(await text(page, '#fov-mean'), fmt(want.mean, 6));
  assert.equal(await text(page, '#fov-variance'), fmt(want.variance, 6));
  assert.equal(await text(page, '#fov-empty'), fmt(want.pmf[0], 6));
  assert.equal(await text(page, '#fov-center'), `(${cx.toFixed(3)}, ${cy.toFixed(3)})`);
  return want;
}

/** The page's map readouts equal fovVarianceMap of its scene, FoV size and grid, in Node. */
async function checkMap(page, s) {
  const want = fisst.fovVarianceMap({ multiBernoulli: sceneOf(s), fovSize: s.fovSize, grid: s.grid });
  assert.deepEqual(s.map.argmax, want.argmax);
  assert.equal(s.map.max, want.max);
  const [ax, ay] = want.argmax;
  assert.equal(await text(page, '#map-argmax'), `(${ax.toFixed(2)}, ${ay.toFixed(2)})`);
  assert.equal(await text(page, '#map-max'), fmt(want.max, 6));
  return want;
}

/** Page pixel of a world point, from the view the page reports and the canvas position. */
const pixelOf = (page, s, point) => viewPixel(page, '#scene', s.view, point);
const unitsPerPixel = (s) => upp(s.view);

test('placement: dragging the FoV with the mouse updates its pmf readouts', async () => {
  const page = await browser.open('placement.html');
  const s0 = await pageState(page);
  assert.deepEqual(s0.scene, { count: 100, seed: 1, extent: 3 });
  assert.deepEqual(s0.fovSize, [1, 1]);
  await checkFovReadouts(page, s0);
  await checkMap(page, s0);
  const k = unitsPerPixel(s0);

  // Grab the FoV at its centre and drag it; the readouts follow while the button is down.
  const [x0, y0] = await pixelOf(page, s0, s0.fov.center);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + 120, y0 + 60, { steps: 6 });
  const s1 = await pageState(page);
  assert.ok(Math.abs(s1.fov.center[0] - (s0.fov.center[0] + 120 * k)) < 0.02, `x ${s1.fov.center}`);
  assert.ok(Math.abs(s1.fov.center[1] - (s0.fov.center[1] - 60 * k)) < 0.02, `y ${s1.fov.center}`);
  const w1 = await checkFovReadouts(page, s1);
  assert.notEqual(w1.mean, s0.fov.mean);
  assert.ok(await page.locator('#scene.dragging').count() === 1, 'dragging class while the button is down');

  await page.mouse.move(x0 - 80, y0 - 150, { steps: 5 });
  await page.mouse.up();
  const s2 = await pageState(page);
  assert.ok(Math.abs(s2.fov.center[0] - (s0.fov.center[0] - 80 * k)) < 0.02, `x ${s2.fov.center}`);
  assert.ok(Math.abs(s2.fov.center[1] - (s0.fov.center[1] + 150 * k)) < 0.02, `y ${s2.fov.center}`);
  const w2 = await checkFovReadouts(page, s2);
  assert.notEqual(w2.variance, w1.variance);

  // After the button is released, moving the mouse does nothing.
  await page.mouse.move(x0 + 200, y0 + 200, { steps: 3 });
  assert.deepEqual((await pageState(page)).fov.center, s2.fov.center);

  // Pressing outside the FoV moves its centre there; dragging past the edge clamps to ±3.
  const [xa, ya] = await pixelOf(page, s2, [2, -2]);
  await page.mouse.move(xa, ya);
  await page.mouse.down();
  const s3 = await pageState(page);
  assert.ok(Math.abs(s3.fov.center[0] - 2) < 0.02 && Math.abs(s3.fov.center[1] + 2) < 0.02, `${s3.fov.center}`);
  await page.mouse.move(xa + 400, ya + 400, { steps: 4 });
  await page.mouse.up();
  const s4 = await pageState(page);
  assert.deepEqual(s4.fov.center, [3, -3]);
  await checkFovReadouts(page, s4);

  // "Move my FoV to the optimum": the variance there is the map's maximum.
  await page.locator('#fov-to-optimum').click();
  const s5 = await pageState(page);
  assert.deepEqual(s5.fov.center, s5.map.argmax);
  const w5 = await checkFovReadouts(page, s5);
  assert.ok(Math.abs(w5.variance - s5.map.max) < 1e-12, `${w5.variance} vs ${s5.map.max}`);

  await browser.done(page, 'placement-drag');
});

test('placement: a touch drag moves the FoV too', async () => {
  const page = await browser.open('placement.html');
  const s0 = await pageState(page);
  const k = unitsPerPixel(s0);
  const [x0, y0] = await pixelOf(page, s0, s0.fov.center);
  const types = await touchDrag(page, '#scene', Array.from({ length: 6 }, (_, i) => [x0 - 20 * i, y0 + 12 * i]));
  assert.ok(types.includes('touch'), `pointer types seen: ${types}`);
  const s1 = await pageState(page);
  assert.ok(Math.abs(s1.fov.center[0] - (s0.fov.center[0] - 100 * k)) < 0.02, `x ${s1.fov.center}`);
  assert.ok(Math.abs(s1.fov.center[1] - (s0.fov.center[1] - 60 * k)) < 0.02, `y ${s1.fov.center}`);
  await checkFovReadouts(page, s1);
  await browser.done(page);
});

test('placement: sliders move the map argmax to the package value; map recompute time', async () => {
  const page = await browser.open('placement.html');
  const step = 6 / 120; // the grid step of [−3, 3] with 121 centres, as the package computes it
  const times = [];
  // Seven FoV sides, each a whole number of grid steps (the slider snaps); 100 × 121².
  for (const side of ['0.5', '0.75', '1.25', '1.5', '1.75', '2', '1']) {
    await page.locator('#fov-size').fill(side);
    const s = await pageState(page);
    assert.equal(s.fovSize[0], Math.round(Number(side) / step) * step);
    assert.equal(s.scene.count, 100);
    await checkMap(page, s);
    await checkFovReadouts(page, s);
    const ms = await page.evaluate(() => window.fisstTiming.last.map);
    assert.equal(await text(page, '#map-time'), `${ms.toFixed(1)} ms`);
    times.push(ms);
  }
  // A side between grid steps snaps to the nearest multiple (0.97 → 19 steps).
  await page.locator('#fov-size').fill('0.97');
  let s = await pageState(page);
  assert.equal(s.fovSize[0], 19 * step);
  await checkMap(page, s);
  // The count and seed sliders rebuild the scene (and its PHD heat map).
  const phdTimes = [];
  for (const count of ['100', '99']) {
    await page.locator('#count').fill(count);
    phdTimes.push(await page.evaluate(() => window.fisstTiming.last.phd));
  }
  await page.locator('#count').fill('60');
  s = await pageState(page);
  assert.equal(s.scene.count, 60);
  await checkMap(page, s);
  await checkFovReadouts(page, s);
  await page.locator('#seed').fill('7');
  s = await pageState(page);
  assert.deepEqual(s.scene, { count: 60, seed: 7, extent: 3 });
  const want = await checkMap(page, s);
  await checkFovReadouts(page, s);
  // The variance layer.
  await page.locator('#layer-variance').click();
  assert.equal(await page.locator('#layer-variance').getAttribute('aria-pressed'), 'true');
  assert.equal((await pageState(page)).layer, 'variance');
  assert.ok(want.max > 0);
  assert.deepEqual(page.errors, []);
  await browser.screenshot(page, 'placement-variance');
  const again = await reopen(browser, page);
  const [s1, s2] = [await pageState(again), await pageState(page)];
  for (const st of [s1, s2]) delete st.map.ms;
  assert.deepEqual(s1, s2, 'the URL keeps the scene, FoV and layer');
  await browser.done(again);

  const sorted = [...times].sort((a, b) => a - b);
  const median = sorted[Math.floor(sorted.length / 2)];
  console.log(`map recompute: ${median.toFixed(1)} ms (median of ${times.length}; `
    + `min ${sorted[0].toFixed(1)}, max ${sorted.at(-1).toFixed(1)}; 100 components × 121², Chromium)`);
  console.log(`PHD heat map (mixtureDensityGrid, 100 components × 121²): ${phdTimes.map((t) => t.toFixed(1)).join(', ')} ms`);
  await page.close();
});

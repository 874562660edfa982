// web/splitting.html in headless Chromium: dragging and reshaping the regions, moving a
// component mean and moving the sliders set the split readouts to the values the npm package
// computes in Node for the state the page reports; the Fig. 5 buttons step through
// negativeInformationScenario.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';
import { fmt } from '../../../web/lib/page.js';
import { json, median, mouseDrag, pixelOf as viewPixel, reopen, text, unitsPerPixel as upp, useBrowser } from './harness.mjs';

const browser = useBrowser();
const pageState = (page) => json(page, '#split-state');

/**
 * The page's split readouts equal splitForRegions of the mixture, regions and options the
 * page reports, computed in Node (the same wasm module: bit-identical numbers).
 */
async function checkSplit(page, s) {
  const want = fisst.splitForRegions({ mixture: s.mixture, regions: s.regions, ...s.options });
  const insideCount = want.insideMask.filter(Boolean).length;
  assert.equal(s.result.count, want.mixture.length);
  assert.equal(s.result.insideCount, insideCount);
  assert.equal(s.result.inside, want.inside);
  assert.equal(s.result.outside, want.outside);
  assert.equal(s.result.exactInside, want.exactInside);
  assert.equal(s.result.depth, want.depth);
  assert.equal(s.result.splits, want.splits);
  assert.equal(s.result.stop, want.stop);
  assert.equal(await text(page, '#input-count'), String(s.mixture.length));
  assert.equal(await text(page, '#component-count'), String(want.mixture.length));
  assert.equal(await text(page, '#inside-count'), String(insideCount));
  assert.equal(await text(page, '#inside-split'), fmt(want.inside, 6));
  assert.equal(await text(page, '#outside-split'), fmt(want.outside, 6));
  assert.equal(await text(page, '#inside-exact'), fmt(want.exactInside, 6));
  assert.equal(await text(page, '#inside-error'), fmt(Math.abs(want.inside - want.exactInside), 3));
  assert.equal(await text(page, '#split-depth'), String(want.depth));
  assert.equal(await text(page, '#split-splits'), String(want.splits));
  // The exact mass agrees with fovCardinality's per-component masses of the same mixture.
  const { massInFov } = fisst.fovCardinality({ rfs: { poisson: s.mixture }, fov: s.regions[0] });
  const exact = s.mixture.reduce((acc, c, i) => acc + c.weight * massInFov[i], 0);
  assert.ok(Math.abs(exact - want.exactInside) < 1e-12, `${exact} vs ${want.exactInside}`);
  // Without splitting: the partition of the input mixture itself.
  const unsplit = fisst.splitForRegions({ mixture: s.mixture, regions: [s.regions[0]], maxDepth: 0 });
  assert.equal(s.result.unsplitInside, unsplit.inside);
  assert.equal(await text(page, '#inside-unsplit'), fmt(unsplit.inside, 6));
  return want;
}

/** Page pixel of a world point, from the view the page reports and the canvas position. */
const pixelOf = (page, s, point) => viewPixel(page, '#scene', s.view, point);
/** World units per page pixel (equal on both axes). */
const unitsPerPixel = (s) => upp(s.view);

const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) < tol, `${what}: ${a} vs ${b}`);

test('splitting: dragging and reshaping S, and the sliders, update the split readouts', async () => {
  const page = await browser.open('splitting.html');
  const s0 = await pageState(page);
  assert.equal(s0.mixture.length, 1);
  assert.deepEqual(s0.regions, [{ box: { min: [-0.5, -1.8], max: [2.5, 1.5] } }]);
  assert.deepEqual(s0.options, { minWeight: 0.01, components: 3, lambda: 0.001, spacing: 'equal' });
  const w0 = await checkSplit(page, s0);
  assert.ok(w0.mixture.length > 20, `${w0.mixture.length} components`);
  const k = unitsPerPixel(s0);

  // Grab S inside (away from its handles) and drag it left and down over the mixture.
  const { min, max } = s0.regions[0].box;
  const [x0, y0] = await pixelOf(page, s0, [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2]);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 - 90, y0 + 30, { steps: 4 });
  assert.equal(await page.locator('#scene.dragging').count(), 1, 'dragging class while the button is down');
  const s1 = await pageState(page);
  near(s1.regions[0].box.min[0], min[0] - 90 * k, 0.02, 'min x while dragging');
  near(s1.regions[0].box.min[1], min[1] - 30 * k, 0.02, 'min y while dragging');
  const w1 = await checkSplit(page, s1);
  await page.mouse.move(x0 - 150, y0 + 60, { steps: 4 });
  await page.mouse.up();
  const s2 = await pageState(page);
  const b2 = s2.regions[0].box;
  near(b2.min[0], min[0] - 150 * k, 0.02, 'min x');
  near(b2.max[1], max[1] - 60 * k, 0.02, 'max y');
  // The size is unchanged by a translation.
  near(b2.max[0] - b2.min[0], max[0] - min[0], 1e-9, 'width');
  const w2 = await checkSplit(page, s2);
  assert.notEqual(w2.inside, w0.inside);
  assert.notEqual(w2.exactInside, w0.exactInside);
  assert.notEqual(w2.mixture.length, w0.mixture.length);
  assert.notEqual(w1.exactInside, w2.exactInside);
  // Now S covers most of the mixture: the partition tracks the exact mass to the split's accuracy.
  assert.ok(w2.exactInside > 0.5 && Math.abs(w2.inside - w2.exactInside) < 0.03, `${w2.inside} vs ${w2.exactInside}`);

  // After the button is released, moving the mouse does nothing.
  await page.mouse.move(x0 + 100, y0 + 100, { steps: 3 });
  assert.deepEqual((await pageState(page)).regions, s2.regions);

  // Reshape: drag S's top-right corner handle up and right.
  const [cx, cy] = await pixelOf(page, s2, b2.max);
  await mouseDrag(page, [cx, cy], [cx + 40, cy - 25], 3);
  const s3 = await pageState(page);
  near(s3.regions[0].box.max[0], b2.max[0] + 40 * k, 0.02, 'resized max x');
  near(s3.regions[0].box.max[1], b2.max[1] + 25 * k, 0.02, 'resized max y');
  assert.deepEqual(s3.regions[0].box.min, b2.min);
  await checkSplit(page, s3);

  // w_min slider (log10 scale): 10^−2.5, rounded to 3 digits as shown.
  await page.locator('#wmin').fill('-2.5');
  const s4 = await pageState(page);
  assert.equal(s4.options.minWeight, 0.00316);
  assert.equal(await page.locator('#wmin-out').textContent(), '0.00316');
  const w4 = await checkSplit(page, s4);
  assert.ok(w4.mixture.length > s3.result.count, 'a lower w_min splits more');

  // R slider: a new split library, and its values in the library line.
  await page.locator('#components').fill('5');
  const s5 = await pageState(page);
  assert.equal(s5.options.components, 5);
  await checkSplit(page, s5);
  const lib = fisst.splitLibrary({ components: 5, lambda: s5.options.lambda, spacing: 'equal' });
  const library = await text(page, '#library');
  assert.match(library, /R = 5/);
  assert.ok(library.includes(`σ̃ = ${fmt(lib.sigma, 5)}`), library);
  assert.ok(library.includes(`J = ${fmt(lib.objective, 4)}`), library);

  // λ slider and the free-means library.
  await page.locator('#lambda').fill('-2');
  await page.locator('#spacing').selectOption('free');
  const s6 = await pageState(page);
  assert.deepEqual(s6.options, { minWeight: 0.00316, components: 5, lambda: 0.01, spacing: 'free' });
  await checkSplit(page, s6);

  // The p_S layer.
  await page.locator('#layer-inside').click();
  assert.equal(await page.locator('#layer-inside').getAttribute('aria-pressed'), 'true');
  const s7 = await pageState(page);
  assert.equal(s7.layer, 'inside');
  const times = structuredClone((await browser.timing(page)).history);
  const firstDragRedraws = times.redraw.length;

  // A drag on the p_S layer (its density image is recomputed on every move).
  const b7 = s7.regions[0].box;
  const [x7, y7] = await pixelOf(page, s7, [(b7.min[0] + b7.max[0]) / 2, (b7.min[1] + b7.max[1]) / 2]);
  await mouseDrag(page, [x7, y7], [x7 + 70, y7 - 20], 8);
  const s8 = await pageState(page);
  near(s8.regions[0].box.min[0], b7.min[0] + 70 * k, 0.02, 'min x on the p_S layer');
  await checkSplit(page, s8);

  assert.deepEqual(page.errors, []);
  await browser.screenshot(page, 'splitting');
  const all = (await browser.timing(page)).history;
  const layerDrag = all.redraw.slice(firstDragRedraws);
  console.log(`splitting page (Chromium): splitForRegions ${median(times.split).toFixed(1)} ms, whole `
    + `redraw ${median(times.redraw.slice(1)).toFixed(1)} ms (medians of ${times.redraw.length - 1} `
    + `drags and slider moves on the p layer, ${w0.mixture.length}–${s7.result.count} split components; first load `
    + `${times.redraw[0].toFixed(1)} ms); redraw while dragging on the p_S layer `
    + `${median(layerDrag).toFixed(1)} ms (median of ${layerDrag.length}, ${s8.result.count} components)`);
  // The mixture, the regions, the options and the layer are in the URL.
  const again = await reopen(browser, page);
  const [a, b] = [await pageState(again), await pageState(page)];
  for (const st of [a, b]) delete st.result.ms;
  assert.deepEqual(a, b);
  await browser.done(page);
  await browser.done(again);
});

test('splitting: several regions, a component drag and the choice of S', async () => {
  const page = await browser.open('splitting.html');
  await page.locator('#preset-three').click();
  await page.locator('#preset-several').click();
  let s = await pageState(page);
  assert.equal(s.mixture.length, 3);
  assert.deepEqual(s.regions.map((r) => Object.keys(r)[0]), ['box', 'polygon', 'disc']);
  await checkSplit(page, s);

  // Add a disc region: it is selected; making it S re-partitions the same split mixture
  // (Algorithm 2 does not depend on the order of the regions).
  await page.locator('#region-kind').selectOption('disc');
  await page.locator('#add-region').click();
  s = await pageState(page);
  assert.equal(s.regions.length, 4);
  assert.ok('disc' in s.regions[3]);
  assert.equal(await text(page, '#region-count'), '4');
  const before4 = await checkSplit(page, s);
  await page.locator('#region-first').click();
  s = await pageState(page);
  assert.ok('disc' in s.regions[0]);
  const after4 = await checkSplit(page, s);
  assert.equal(after4.mixture.length, before4.mixture.length);
  assert.notEqual(after4.inside, before4.inside);
  assert.equal(await text(page, '#region-selected'), 'S (disc)');

  // Reshape the disc (S) by its rim handle, then drag component 2's mean.
  const { center, radius } = s.regions[0].disc;
  const k = unitsPerPixel(s);
  const [hx, hy] = await pixelOf(page, s, [center[0] + radius, center[1]]);
  await mouseDrag(page, [hx, hy], [hx + 30, hy], 3);
  s = await pageState(page);
  near(s.regions[0].disc.radius, radius + 30 * k, 0.02, 'radius');
  await checkSplit(page, s);

  const mean = s.mixture[1].mean;
  const [mx, my] = await pixelOf(page, s, mean);
  await mouseDrag(page, [mx, my], [mx - 60, my - 40]);
  const moved = await pageState(page);
  assert.equal(moved.selected.component, 1);
  near(moved.mixture[1].mean[0], mean[0] - 60 * k, 0.02, 'mean x');
  near(moved.mixture[1].mean[1], mean[1] + 40 * k, 0.02, 'mean y');
  assert.deepEqual(moved.mixture[0], s.mixture[0]);
  await checkSplit(page, moved);

  // Its spread and orientation sliders.
  await page.locator('#sigma-major').fill('1.5');
  await page.locator('#angle').fill('-30');
  s = await pageState(page);
  const c = s.mixture[1].cov;
  const t = (-30 * Math.PI) / 180;
  near(c[0][1], (1.5 ** 2 - 0.6 ** 2) * Math.cos(t) * Math.sin(t), 1e-12, 'cov xy');
  await checkSplit(page, s);

  // Remove the selected region (S): the next one becomes S.
  await page.locator('#remove-region').click();
  s = await pageState(page);
  assert.equal(s.regions.length, 3);
  assert.ok('box' in s.regions[0]);
  await checkSplit(page, s);
  await browser.done(page, 'splitting-regions');
});

test('splitting: the Fig. 5 buttons step through negativeInformationScenario', async () => {
  const page = await browser.open('splitting.html');
  const check = async (k) => {
    const want = fisst.negativeInformationScenario({ step: k });
    const s = JSON.parse(await text(page, '#fig5-state'));
    assert.equal(s.step, k);
    assert.equal(await text(page, '#fig5-step'), String(k));
    assert.equal(await text(page, '#fig5-predicted-count'), String(want.predicted.length));
    assert.equal(await text(page, '#fig5-split-count'), String(want.split.length));
    assert.equal(await text(page, '#fig5-posterior-count'), String(want.posterior.length));
    assert.equal(await text(page, '#fig5-nondetection'), fmt(want.nonDetectionProb, 6));
    assert.equal(await text(page, '#fig5-predicted-inside'), fmt(want.predictedInside, 6));
    assert.equal(await text(page, '#fig5-posterior-inside'), fmt(want.posteriorInside, 6));
    assert.equal(await text(page, '#fig5-depth'), String(want.depth));
    assert.equal(await text(page, '#fig5-splits'), String(want.splits));
    assert.equal(s.nonDetectionProb, want.nonDetectionProb);
    assert.equal(s.posteriorInside, want.posteriorInside);
    // The split mixture's components in S are those the update removed.
    assert.equal(s.splitInsideCount + want.posterior.length, want.split.length);
    assert.equal(await page.locator('#fig5-prev').isDisabled(), k === 1);
    assert.equal(await page.locator('#fig5-next').isDisabled(), k === 3);
  };
  await check(1);
  await page.locator('#fig5-next').click();
  await check(2);
  await page.locator('#fig5-next').click();
  await check(3);
  await page.locator('#fig5-prev').click();
  await check(2);
  assert.deepEqual(page.errors, []);
  await page.locator('#fig5-next').click();
  await check(3);
  const again = await reopen(browser, page);
  assert.equal(JSON.parse(await text(again, '#fig5-state')).step, 3, 'the scan is in the URL');
  await browser.done(again);
  await browser.done(page, 'splitting-fig5');
});

// The page-test harness: every test in pages/ opens its page through it.
//
// `const browser = useBrowser()` (at the top of a test file) starts the static server on
// web/ and Debian's /usr/bin/chromium driven by playwright-core (never `npx playwright
// install`) before the file's tests and closes both after them; then
// - `await browser.open('page.html')` opens a page (a query string is fine), waits until it
//   says it is ready (body[data-ready]), collects its console errors, page errors, failed
//   requests and HTTP errors in `page.errors`, and records its load time (first figure drawn,
//   ready: the timing section of web/lib/page.js);
// - `await browser.done(page, 'name')` requires no error, saves a full-page screenshot in
//   tests/browser/screenshots/<name>.png (when a name is given) and closes the page;
// - `browser.timing(page)` is the page's window.fisstTiming (redraw times by panel);
// - after the file, the load times of every page it opened are printed (median of the opens).
// The helpers below (text, json, pixelOf, touchDrag, stats) are what several page tests need.
import { before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdtempSync, mkdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../../scripts/serve.mjs';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const SCREENSHOTS = path.join(ROOT, 'tests/browser/screenshots');

const FLAGS = [
  '--headless=new', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-quic', '--no-first-run',
];

/** Registers the before/after hooks of a test file; returns the browser helpers. */
export function useBrowser() {
  let server;
  let url;
  let context;
  let profile;
  const loads = new Map(); // page file → [{ firstFigure, ready }]
  before(async () => {
    for (const need of ['web/pkg/fisst_wasm.js', 'web/vendor/uplot/uPlot.esm.min.js']) {
      assert.ok(existsSync(path.join(ROOT, need)), `${need} is missing: run \`make web-pkg\``);
    }
    ({ server, url } = await serve({ root: path.join(ROOT, 'web'), port: 0 }));
    profile = mkdtempSync(path.join(tmpdir(), 'fisst-chromium-'));
    context = await chromium.launchPersistentContext(profile, {
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      headless: true,
      args: FLAGS,
      viewport: { width: 1280, height: 900 },
    });
    mkdirSync(SCREENSHOTS, { recursive: true });
  });
  after(async () => {
    for (const [file, times] of loads) {
      const first = stats(times.map((t) => t.firstFigure));
      const ready = stats(times.map((t) => t.ready));
      console.log(`page load (Chromium): ${file} first figure ${first.median.toFixed(0)} ms, ready `
        + `${ready.median.toFixed(0)} ms (medians of ${times.length} opens)`);
    }
    await context?.close();
    server?.close();
    if (profile) rmSync(profile, { recursive: true, force: true });
  });
  return {
    get url() { return url; },
    async open(rel) {
      const page = await context.newPage();
      const errors = [];
      page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
      page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
      page.on('requestfailed', (r) => errors.push(`requestfailed: ${r.url()} ${r.failure()?.errorText}`));
      page.on('response', (r) => { if (r.status() >= 400) errors.push(`HTTP ${r.status()}: ${r.url()}`); });
      await page.goto(new URL(rel, url).href);
      try {
        await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
      } catch (e) {
        throw new Error(`${rel} never got ready: ${errors.join('; ') || e.message}`);
      }
      page.errors = errors;
      const t = await page.evaluate(() => window.fisstTiming ?? null);
      if (t?.page) {
        const file = rel.split('?')[0];
        if (!loads.has(file)) loads.set(file, []);
        loads.get(file).push({ firstFigure: t.firstFigure, ready: t.ready });
      }
      return page;
    },
    timing: (page) => page.evaluate(() => window.fisstTiming),
    async screenshot(page, name) {
      await page.screenshot({ path: path.join(SCREENSHOTS, `${name}.png`), fullPage: true });
    },
    async done(page, name = null) {
      assert.deepEqual(page.errors, []);
      if (name) await this.screenshot(page, name);
      await page.close();
    },
  };
}

/** The lines of the CSV that the CSV button of the figure `figure` (a selector) downloads. */
export async function csvLines(page, figure) {
  const download = page.waitForEvent('download');
  await page.locator(`${figure} [data-download="csv"]`).click();
  const body = await (await download).createReadStream().then((st) => st.toArray());
  return Buffer.concat(body).toString('utf8').trim().split('\n');
}

/**
 * Clicks the CSV and PNG download buttons of each figure `[selector, rows]` and checks the CSV
 * has `rows` lines (header included) and the PNG's file name starts with `prefix`.
 */
export async function checkDownloads(page, figures, prefix) {
  for (const [figure, rows] of figures) {
    assert.equal((await csvLines(page, figure)).length, rows, figure);
    const png = page.waitForEvent('download');
    await page.locator(`${figure} [data-download="png"]`).click();
    assert.match((await png).suggestedFilename(), new RegExp(`^${prefix}-.*\\.png$`), figure);
  }
}

/** The text of the first element matching `sel`. */
export const text = (page, sel) => page.locator(sel).textContent();

/** The JSON a page publishes in the element `sel` (its state, for the tests and readers). */
export const json = async (page, sel) => JSON.parse(await text(page, sel));

/**
 * Viewport pixel of the data point [x, y] of a scene view whose canvas is `sel`, from the
 * view a page publishes (`{ box, x: [x0, x1], y: [y0, y1] }`); scrolled into view first
 * (touches off-screen are dropped).
 */
export async function pixelOf(page, sel, view, [x, y]) {
  await page.locator(sel).scrollIntoViewIfNeeded();
  // The canvas's content box: inside its CSS border.
  const [left, top] = await page.locator(sel).evaluate((el) => {
    const r = el.getBoundingClientRect();
    return [r.x + el.clientLeft, r.y + el.clientTop];
  });
  const { box, x: [x0, x1], y: [y0, y1] } = view;
  return [left + box.left + ((x - x0) / (x1 - x0)) * box.width, top + box.top + ((y1 - y) / (y1 - y0)) * box.height];
}

/** A mouse drag from viewport point `from` to `to` in `steps` moves, then release. */
export async function mouseDrag(page, [x0, y0], [x1, y1], steps = 4) {
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x1, y1, { steps });
  await page.mouse.up();
}

/** Data units per CSS pixel of a published view (along x). */
export const unitsPerPixel = (view) => (view.x[1] - view.x[0]) / view.box.width;

/**
 * A touch drag through the viewport points `path` on the element `sel` (Chromium turns CDP
 * touch input into pointer events of pointerType "touch"); returns the pointer types the
 * element saw, so a test can check that they were touches.
 */
export async function touchDrag(page, sel, path) {
  const cdp = await page.context().newCDPSession(page);
  const touch = (type, p) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: p ? [{ x: p[0], y: p[1], id: 1 }] : [] });
  await page.evaluate((s) => {
    window.pointerTypes = [];
    document.querySelector(s).addEventListener('pointermove', (e) => window.pointerTypes.push(e.pointerType));
  }, sel);
  await touch('touchStart', path[0]);
  for (const p of path.slice(1)) await touch('touchMove', p);
  await touch('touchEnd', null);
  return page.evaluate(() => window.pointerTypes);
}

export { median } from '../../../web/lib/page.js';

/** Count, median and maximum of a list of times. */
export function stats(xs) {
  const sorted = [...xs].sort((a, b) => a - b);
  return { n: xs.length, median: sorted[Math.floor(xs.length / 2)], max: sorted.at(-1) };
}

/** "name 4.5 ms median (max 10.0, n = 61)". */
export function timeLine(name, xs) {
  const { n, median, max } = stats(xs);
  return `${name} ${median.toFixed(1)} ms median (max ${max.toFixed(1)}, n = ${n})`;
}

/**
 * Reopens the page at its current URL (where web/lib/page.js's urlState keeps its settings) and
 * returns the new page: a shared or reloaded link must show the same view.
 */
export async function reopen(browser, page) {
  await page.waitForTimeout(300); // the URL is written 150 ms after the last change
  const href = page.url();
  const rel = href.slice(href.lastIndexOf('/') + 1);
  return browser.open(rel);
}

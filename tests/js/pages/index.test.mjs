// Every demo page listed in web/index.html loads in headless Chromium without a console error
// and leaves a screenshot in tests/browser/screenshots/ (git-ignored); its load time is
// printed by the harness. Each page's interaction tests are in pages/<page>.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { ROOT, useBrowser } from './harness.mjs';

const browser = useBrowser();

const demoPages = () => {
  const html = readFileSync(path.join(ROOT, 'web/index.html'), 'utf8');
  return [...html.matchAll(/href="([a-z0-9-]+\.html)"/g)].map((m) => m[1]);
};

test('index lists the demos and every page loads cleanly', async () => {
  const pages = demoPages();
  assert.ok(pages.includes('spooky.html'));
  await browser.done(await browser.open('index.html'));
  for (const rel of pages) {
    const page = await browser.open(rel);
    await page.waitForTimeout(200);
    assert.deepEqual(page.errors, [], `${rel} has errors`);
    // Each figure has its download buttons; each chart is drawn by uPlot.
    assert.ok(await page.locator('[data-download="png"]').count() >= 1, `${rel}: no download control`);
    await browser.done(page, path.basename(rel, '.html'));
  }
});

/** The part of the npm package a page maps `fisst` to in its import map (`pkg/<part>.js`). */
function pagePart(html) {
  const map = html.match(/<script type="importmap">(.*?)<\/script>/s);
  return map ? JSON.parse(map[1]).imports.fisst.match(/^\.\/pkg\/(\w+)\.js$/)[1] : undefined;
}

/** The modules a page's script imports, transitively and statically (`fisst` through the import map). */
function moduleGraph(entry, part) {
  const seen = new Set();
  const todo = [entry];
  while (todo.length) {
    const file = todo.shift();
    if (seen.has(file)) continue;
    seen.add(file);
    const src = readFileSync(path.join(ROOT, 'web', file), 'utf8');
    for (const [, a, b] of src.matchAll(/^import\s[^;]*?from\s+'([^']+)';|^import\s+'([^']+)';/gm)) {
      const spec = a ?? b;
      todo.push(spec === 'fisst' ? `pkg/${part}.js` : path.posix.normalize(path.posix.join(path.posix.dirname(file), spec)));
    }
  }
  seen.delete(entry);
  return [...seen].sort();
}

test('every page preloads its wasm and modulepreloads its whole module graph (the first figure needs them)', () => {
  for (const rel of demoPages()) {
    const html = readFileSync(path.join(ROOT, 'web', rel), 'utf8');
    const entry = html.match(/<script type="module" src="([^"]+)"/)[1];
    const preloaded = [...html.matchAll(/<link rel="modulepreload" href="([^"]+)">/g)].map((m) => m[1]).sort();
    const part = pagePart(html);
    assert.ok(part, `${rel}: no import map naming the part of fisst the page loads`);
    assert.deepEqual(preloaded, moduleGraph(entry, part), `${rel}: the modulepreload links and the imports differ`);
    // A page loads only its part's wasm module, not the whole package.
    assert.ok(
      html.includes(`<link rel="preload" href="pkg/${part}_bg.wasm" as="fetch" type="application/wasm" crossorigin>`),
      `${rel}: does not preload pkg/${part}_bg.wasm`,
    );
  }
});

test('every page loads five times: its load time (first figure drawn)', async () => {
  for (const rel of demoPages()) {
    for (let k = 0; k < 5; k++) await browser.done(await browser.open(rel));
  }
});

// Every demo page listed in web/index.html loads in headless Chromium without a console error
// and leaves a screenshot in tests/browser/screenshots/ (git-ignored). Each page's interaction
// tests are in pages/<page>.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { startBrowser, ROOT } from '../lib/browser.mjs';

let browser;

before(async () => {
  assert.ok(existsSync(path.join(ROOT, 'web/pkg/fisst_wasm.js')), 'web/pkg is missing: run `make web-pkg`');
  browser = await startBrowser();
});

after(async () => {
  await browser?.close();
});

const demoPages = () => {
  const html = readFileSync(path.join(ROOT, 'web/index.html'), 'utf8');
  return [...html.matchAll(/href="([a-z0-9-]+\.html)"/g)].map((m) => m[1]);
};

test('index lists the demos and every page loads cleanly', async () => {
  const pages = demoPages();
  assert.ok(pages.includes('spooky.html'));
  const index = await browser.open('index.html');
  assert.deepEqual(index.errors, []);
  await index.close();
  for (const rel of pages) {
    const page = await browser.open(rel);
    await page.waitForTimeout(200);
    assert.deepEqual(page.errors, [], `${rel} has errors`);
    await browser.screenshot(page, path.basename(rel, '.html'));
    await page.close();
  }
});


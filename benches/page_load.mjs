// Page-load times of two builds of the demo pages, side by side in one run (issue 11: "no
// slower than before"). Each build's web/ folder (with its pkg/ and vendor/ in place, as
// `make web-pkg` leaves them) is served on its own port; Chromium opens every page of both in
// alternation, `rounds` times, each open in a fresh browser context (a cold HTTP cache: the
// page downloads its wasm every time, as a first visit does).
//
// One rule for both builds, which needs nothing from the pages: an init script hooks the 2D
// canvas drawing calls (fill, stroke, fillRect, fillText, drawImage, putImageData) and
//   first figure = the first such call after the page's wasm module was instantiated
//                  (WebAssembly.instantiate / instantiateStreaming resolved), i.e. the first
//                  figure that can show computed numbers;
//   ready        = the moment body[data-ready="true"] is set (a MutationObserver), which every
//                  page, old and new, does when its figures are drawn.
// Times are ms from navigation start; the table gives medians and the ratio new / old.
//
// node benches/page_load.mjs <oldWebDir> <newWebDir> [rounds=7] [page.html ...]
// e.g. the pages before issue 11 against this tree's:
//   git worktree add --detach /tmp/old a86acf6 && (cd /tmp/old && scripts/build-pkg.sh && cp -r wasm/pkg web/pkg)
//   make web-pkg && node benches/page_load.mjs /tmp/old/web web 9
import { createRequire } from 'node:module';
import path from 'node:path';
import { serve } from '../scripts/serve.mjs';

// playwright-core is installed for the page tests (scripts/npm-deps.sh, in tests/js).
const requireTests = createRequire(new URL('../tests/js/package.json', import.meta.url));
const { chromium } = requireTests('playwright-core');

const [oldDir, newDir, roundsArg, ...only] = process.argv.slice(2);
if (!oldDir || !newDir) {
  console.error('usage: node benches/page_load.mjs <oldWebDir> <newWebDir> [rounds=7] [page.html ...]');
  process.exit(2);
}
const rounds = Number(roundsArg ?? 7);
const pages = only.length ? only : ['threshold.html', 'splitting.html', 'placement.html', 'spooky.html'];

const FLAGS = [
  '--headless=new', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-quic', '--no-first-run',
];

const HOOK = () => {
  window.__load = { wasm: null, firstFigure: null, ready: null };
  new MutationObserver(() => {
    if (window.__load.ready === null && document.body?.dataset.ready === 'true') window.__load.ready = performance.now();
  }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-ready'] });
  const mark = () => {
    if (window.__load.wasm !== null && window.__load.firstFigure === null) window.__load.firstFigure = performance.now();
  };
  for (const name of ['fill', 'stroke', 'fillRect', 'fillText', 'drawImage', 'putImageData']) {
    const original = CanvasRenderingContext2D.prototype[name];
    CanvasRenderingContext2D.prototype[name] = function (...args) {
      mark();
      return original.apply(this, args);
    };
  }
  for (const name of ['instantiate', 'instantiateStreaming']) {
    const original = WebAssembly[name];
    WebAssembly[name] = function (...args) {
      return original.apply(this, args).then((out) => {
        window.__load.wasm ??= performance.now();
        return out;
      });
    };
  }
};

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};

const servers = [];
const builds = [];
for (const [label, dir] of [['old', oldDir], ['new', newDir]]) {
  const { server, url } = await serve({ root: path.resolve(dir), port: 0 });
  servers.push(server);
  builds.push({ label, url });
}
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', headless: true, args: FLAGS });
const results = {}; // page -> label -> [{ firstFigure, ready }]
for (let r = 0; r < rounds; r++) {
  for (const page of pages) {
    // Alternate which build goes first, so neither always meets a warmer machine.
    const order = r % 2 ? [...builds].reverse() : builds;
    for (const { label, url } of order) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
      await context.addInitScript(HOOK);
      const tab = await context.newPage();
      await tab.goto(new URL(page, url).href);
      await tab.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
      const t = await tab.evaluate(() => window.__load);
      (results[page] ??= {})[label] ??= [];
      results[page][label].push(t);
      await context.close();
    }
  }
}
if (process.env.PAGE_LOAD_RAW) console.log(JSON.stringify(results));
await browser.close();
for (const s of servers) s.close();

console.log(`page load (Chromium, cold cache, ${rounds} opens each, alternating): medians in ms`);
console.log('page              first figure old → new (ratio)      ready old → new (ratio)      wasm instantiated old → new');
for (const page of pages) {
  const o = results[page].old;
  const n = results[page].new;
  const f = [median(o.map((x) => x.firstFigure)), median(n.map((x) => x.firstFigure))];
  const d = [median(o.map((x) => x.ready)), median(n.map((x) => x.ready))];
  const w = [median(o.map((x) => x.wasm)), median(n.map((x) => x.wasm))];
  console.log(
    `${page.padEnd(18)}${f[0].toFixed(0).padStart(6)} → ${f[1].toFixed(0).padStart(5)} (${(f[1] / f[0]).toFixed(2)})` +
      `${d[0].toFixed(0).padStart(18)} → ${d[1].toFixed(0).padStart(5)} (${(d[1] / d[0]).toFixed(2)})` +
      `${w[0].toFixed(0).padStart(18)} → ${w[1].toFixed(0).padStart(5)}`,
  );
}

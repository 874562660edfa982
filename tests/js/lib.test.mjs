// The DOM-free parts of web/lib in Node: URL state, regions, colour maps and grids, formats.
// (The rest is exercised in Chromium by the page tests.)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cellCounts, cellGrid, colormap } from '../../web/lib/colormap.js';
import { handles, reshape, translate, validRegions } from '../../web/lib/regions.js';
import { fmt, median, toCSV } from '../../web/lib/page.js';

/** Loads page.js (its urlState) against a fake location/history holding `search`. */
async function urlStateAt(search) {
  const written = [];
  globalThis.location = { pathname: '/page.html', search, hash: '' };
  globalThis.history = { replaceState: (_, __, url) => written.push(url) };
  const { urlState } = await import('../../web/lib/page.js');
  return { urlState, written };
}

test('url state: typed values from the URL, defaults for bad ones, only changes written', async () => {
  const { urlState, written } = await urlStateAt('?r0=2.5&preset=mmol&on=1&means=[[1,2]]&bad=abc&pts={');
  const url = urlState(
    { r0: 1, preset: 'mpe', on: false, means: null, bad: 3, pts: [[0, 0]], n: 7 },
    { check: { means: (m) => m === null || m.length === 1 } },
  );
  assert.deepEqual(url.values, { r0: 2.5, preset: 'mmol', on: true, means: [[1, 2]], bad: 3, pts: [[0, 0]], n: 7 });
  url.values.n = 8;
  url.values.r0 = 1; // back to its default: dropped from the URL
  url.write();
  assert.equal(decodeURIComponent(written.at(-1)), '/page.html?preset=mmol&on=1&means=[[1,2]]&n=8');
  const rejected = urlState({ means: null }, { check: { means: () => false } });
  assert.equal(rejected.values.means, null);
});

test('regions: moves, reshapes and checks', () => {
  const box = { box: { min: [0, 0], max: [2, 1] } };
  assert.deepEqual(translate(box, [1, -1]), { box: { min: [1, -1], max: [3, 0] } });
  assert.deepEqual(handles(box), [[0, 0], [2, 0], [2, 1], [0, 1]]);
  // Dragging a corner past the opposite one keeps a positive size.
  assert.deepEqual(reshape(box, 2, [-5, 3]), { box: { min: [0, 0], max: [0.1, 3] } });
  assert.deepEqual(reshape({ disc: { center: [1, 1], radius: 1 } }, 0, [4, 5]), { disc: { center: [1, 1], radius: 5 } });
  assert.ok(validRegions([box, { disc: { center: [0, 0], radius: 1 } }, { polygon: [[0, 0], [1, 0], [0, 1]] }]));
  for (const bad of [[], [{ box: { min: [1, 0], max: [0, 1] } }], [{ disc: { center: [0, 0], radius: 0 } }], [{ polygon: [[0, 0], [1, 1]] }], [{ box: box.box, disc: {} }]]) {
    assert.equal(validRegions(bad), false, JSON.stringify(bad));
  }
});

test('colour maps: ends of viridis and cividis, lightness of blues falls monotonically', () => {
  assert.deepEqual(colormap('viridis').rgb(0), [0x44, 0x01, 0x54]);
  assert.deepEqual(colormap('viridis').rgb(1), [0xfd, 0xe7, 0x25]);
  assert.deepEqual(colormap('cividis').rgb(0), [0x00, 0x20, 0x51]);
  assert.deepEqual(colormap('viridis').rgb(2), colormap('viridis').rgb(1)); // clamped
  const luma = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;
  for (const name of ['blues', 'greys', 'viridis', 'cividis']) {
    const l = Array.from({ length: 11 }, (_, k) => luma(colormap(name).rgb(k / 10)));
    const up = name === 'viridis' || name === 'cividis';
    for (let k = 1; k < l.length; k++) assert.ok(up ? l[k] > l[k - 1] : l[k] < l[k - 1], `${name} at ${k}`);
  }
  assert.throws(() => colormap('jet'), TypeError);
});

test('grids, formats and CSV', () => {
  // Cells of width 0.5 tiling [0, 2] × [−1, 0]: centres from 0.25.
  assert.deepEqual(cellGrid([0, 2], [-1, 0], 4, 2), { x: [0.25, 1.75, 4], y: [-0.75, -0.25, 2] });
  assert.deepEqual(cellCounts([-4, 4], [-2, 2], { maxCells: 120, budget: 1e6, terms: 100 }), [120, 60]);
  assert.equal(fmt(0.59432, 4), '0.5943');
  assert.equal(fmt(1e-5, 3), '1.00e-5');
  assert.equal(median([3, 1, 2]), 2);
  assert.equal(toCSV(['a', 'b'], [[1, null], ['x,y', 0.1]]), 'a,b\n1,\n"x,y",0.1\n');
});

// Issue 26, point 4: the two first-day mistakes outside the argument checks get typed errors.
test('a freed filter or control run used again throws a TypeError naming its class', async () => {
  const { GmBernoulliFilter, SensorControlRun } = await import('fisst');
  const make = () =>
    new GmBernoulliFilter({
      transition: { F: [[1]], Q: [[0.1]] },
      likelihood: { H: [[1]], R: [[1]] },
      birth: { probability: 0.1, mixture: [{ weight: 1, mean: [0], cov: [[1]] }] },
      detection: { probability: 0.9 },
      clutter: { rate: 1, density: 0.1 },
      existence: 0.5,
      mixture: [{ weight: 1, mean: [0], cov: [[1]] }],
      positionDims: 1,
    });
  const f = make();
  f.free();
  assert.throws(() => f.predict(), { name: 'TypeError', message: /^GmBernoulliFilter was freed/ });
  assert.throws(() => f.existence, { name: 'TypeError', message: /^GmBernoulliFilter was freed/ });
  assert.throws(() => f.free(), { name: 'TypeError', message: /^GmBernoulliFilter was freed/ });
  const run = new SensorControlRun({ scheme: 'random', futureScans: 1 });
  run.free();
  assert.throws(() => run.step(), { name: 'TypeError', message: /^SensorControlRun was freed/ });
});

test('a browser-entry call before init() throws an Error saying to call init() first', async () => {
  const { execFileSync } = await import('node:child_process');
  const { createRequire } = await import('node:module');
  const require = createRequire(import.meta.url);
  const entry = require.resolve('fisst/package.json').replace(/package\.json$/, 'metrics.js');
  const code = `import { gospa } from ${JSON.stringify(entry)};
try { gospa([[0]], [[1]], { c: 2 }); console.log('no error'); }
catch (e) { console.log(e.constructor.name + ': ' + e.message); }`;
  const out = execFileSync(process.execPath, ['--input-type=module', '-e', code], { encoding: 'utf8' });
  assert.match(out, /^Error: fisst\/metrics: call `await init\(\)` first/);
});

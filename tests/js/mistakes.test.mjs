// The mistakes of a user's first day (issue 26, Why, points 1–7, and Checks: "a test per mistake
// asserts the class and the field named in the message"), outside the filters' configuration
// (F, Q, the mixture, H, R and update regions are in mistakes_filters.test.mjs), and ten typical
// mistakes a new user makes across the parts. Each asserts `instanceof` the class the README
// promises (a TypeError for a type or presence problem, a RangeError for a bad value, an Error
// for a call before init()) and the path of the field at fault at the start of the message.
//
// Where today's message blames the wrong field or leaves the field out, the test is written for
// the right message and marked `todo` with what the message does today: node:test reports it
// without failing the run; when the message is fixed, the todo passes and its mark can go.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';
import * as fisst from 'fisst';

const here = path.dirname(fileURLToPath(import.meta.url));
// The browser entry (the exports map's `default`; Node takes `node`, which needs no init).
const browserEntry = pathToFileURL(path.join(path.dirname(createRequire(import.meta.url).resolve('fisst/package.json')), 'fisst_wasm.js')).href;

/** `fn` throws an instance of `Class` whose message matches every regex of `fields`. */
function throwsNaming(fn, Class, ...fields) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof Class, `expected a ${Class.name}, got ${e?.constructor?.name}: ${e?.message}`);
    for (const field of fields) assert.match(e.message, field);
    return true;
  });
}

/** Runs an ES module in a fresh Node process from tests/js (`fisst` resolves there). */
function runChild(code, timeout) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, ['--input-type=module', '-e', code], { cwd: here, timeout });
    let out = '';
    let err = '';
    child.stdout.on('data', (d) => (out += d));
    child.stderr.on('data', (d) => (err += d));
    child.on('close', (status, signal) => resolve({ status, signal, out: out.trim(), err }));
  });
}

const I2 = [[1, 0], [0, 1]];
const g2 = { mean: [0, 0], cov: I2 };
const mb = [{ existence: 0.5, ...g2 }];
const unitBox = { box: { min: [-1, -1], max: [1, 1] } };
const disc = { disc: { center: [0, 0], radius: 1 } };

// --- Why, point 1 (outside the filters): the field that disagrees, and how ---

test('why 1: a 3-D box as the field of view of a 2-D density names options.fov.box', () => {
  throwsNaming(
    () => fisst.fovCardinality({ rfs: { multiBernoulli: mb }, fov: { box: { min: [-1, -1, -1], max: [1, 1, 1] } } }),
    RangeError,
    /^options\.fov\.box\.min has length 3 but options\.rfs\.multiBernoulli\[0\]\.mean has length 2$/,
  );
});

test('why 1: an asymmetric covariance says it is not symmetric, and where', () => {
  const cov = [[1, 0.5], [0, 1]];
  throwsNaming(
    () => fisst.splitForRegions({ mixture: [{ weight: 1, mean: [0, 0], cov }], regions: [unitBox] }),
    RangeError,
    /^options\.mixture\[0\]\.cov\b/,
    /not symmetric|\[0\]\[1\]|\[1\]\[0\]/,
  );
});

test('why 1: an indefinite covariance says it is not positive definite (its smallest eigenvalue)', () => {
  const cov = [[1, 2], [2, 1]]; // eigenvalues 3 and −1
  throwsNaming(
    () => fisst.fovCardinality({ rfs: { poisson: [{ weight: 1, mean: [0, 0], cov }] }, fov: disc }),
    RangeError,
    /^options\.rfs\.poisson\[0\]\.cov\b/,
    /not positive (semi)?definite|eigenvalue/,
  );
});

// --- Why, point 3: options that go together ---

test('why 3: a loss `radius` without `costs` names options.costs as missing', () => {
  const s = fisst.airportScenario({ seed: 1, steps: 1 });
  const filter = new fisst.GmBernoulliFilter(s.config);
  try {
    throwsNaming(() => filter.estimate({ radius: 5 }), TypeError, /^options\.costs\b/);
    throwsNaming(() => filter.estimate({ costs: 'mpe' }), TypeError, /^options\.radius\b/);
  } finally {
    filter.free();
  }
});

// --- Why, point 4: errors outside the promise ---

test('why 4: an object used after free() throws a TypeError naming its class', () => {
  const s = fisst.airportScenario({ seed: 1, steps: 1 });
  const gm = new fisst.GmBernoulliFilter(s.config);
  gm.free();
  throwsNaming(() => gm.predict(), TypeError, /^GmBernoulliFilter was freed/);
  throwsNaming(() => gm.update([]), TypeError, /^GmBernoulliFilter was freed/);
  throwsNaming(() => gm.existence, TypeError, /^GmBernoulliFilter was freed/);
  const pf = new fisst.ParticleBernoulliFilter({ ...s.config, particles: 100, seed: 1 });
  pf.free();
  throwsNaming(() => pf.estimate(), TypeError, /^ParticleBernoulliFilter was freed/);
  const run = new fisst.SensorControlRun({ scheme: 'random', seed: 1, steps: 1, particles: 10, futureScans: 2 });
  run.free();
  throwsNaming(() => run.step(), TypeError, /^SensorControlRun was freed/);
});

test('why 4: an object freed twice throws a TypeError naming its class', () => {
  const s = fisst.airportScenario({ seed: 1, steps: 1 });
  const gm = new fisst.GmBernoulliFilter(s.config);
  gm.free();
  throwsNaming(() => gm.free(), TypeError, /^GmBernoulliFilter was freed/);
  const pf = new fisst.ParticleBernoulliFilter({ ...s.config, particles: 100, seed: 1 });
  pf.free();
  throwsNaming(() => pf.free(), TypeError, /^ParticleBernoulliFilter was freed/);
  const run = new fisst.SensorControlRun({ scheme: 'random', seed: 1, steps: 1, particles: 10, futureScans: 2 });
  run.free();
  throwsNaming(() => run.free(), TypeError, /^SensorControlRun was freed/);
});

test('why 4: a call before init() on the browser entry throws an Error saying to call init() first', async () => {
  // A fresh process: the Node entry (imported above) initialises the same modules.
  const code = `
    const m = await import(${JSON.stringify(browserEntry)});
    for (const f of [() => m.gospa([[0]], [[1]], { c: 2 }), () => new m.GmBernoulliFilter({}), () => m.jdeBoundNoClutter({})]) {
      try { f(); console.log('returned'); } catch (e) { console.log(JSON.stringify([e.constructor.name, e.message])); }
    }`;
  const run = await runChild(code, 30_000);
  assert.equal(run.status, 0, run.err);
  const lines = run.out.split('\n').map((l) => JSON.parse(l));
  assert.equal(lines.length, 3);
  for (const [name, message] of lines) {
    assert.equal(name, 'Error');
    assert.match(message, /^fisst\/\w+: call `await init\(\)` first/);
  }
});

// --- Keys, kinds and values (the contract's promise in the README) ---

test('an unknown key names the options and suggests the close key (aplha → alpha)', () => {
  throwsNaming(() => fisst.gospa([[0]], [[1]], { c: 2, aplha: 1 }), TypeError, /^options has an unknown key "aplha" \(did you mean alpha\?\)/);
});

test('a string where a number belongs is a TypeError naming the field', () => {
  throwsNaming(() => fisst.ospa([[0]], [[1]], { c: '2' }), TypeError, /^options\.c must be a number, got the string "2"/);
  throwsNaming(() => fisst.airportScenario({ seed: '1' }), TypeError, /^options\.seed must be a number/);
});

test('NaN and ±Infinity are RangeErrors naming the field', () => {
  throwsNaming(() => fisst.ospa([[0]], [[1]], { c: NaN }), RangeError, /^options\.c must be a finite number, got NaN/);
  throwsNaming(() => fisst.ospa([[0]], [[1]], { c: Infinity }), RangeError, /^options\.c must be a finite number, got Infinity/);
  throwsNaming(() => fisst.ospa([[0]], [[NaN]], { c: 1 }), RangeError, /^estimate\[0\]\[0\] must be a finite number/);
  throwsNaming(() => fisst.multiBernoulliCardinality([0.5, -Infinity]), RangeError, /^existence\[1\] must be a finite number/);
  throwsNaming(() => fisst.fovCardinality({ rfs: { multiBernoulli: [{ existence: 0.5, mean: [0, NaN], cov: I2 }] }, fov: disc }), RangeError, /^options\.rfs\.multiBernoulli\[0\]\.mean\[1\]/);
});

test('a missing required option is a TypeError naming it', () => {
  throwsNaming(() => fisst.gospa([[0]], [[1]], {}), TypeError, /^options\.c is required/);
  throwsNaming(() => fisst.gospa([[0]], [[1]]), TypeError, /^options must be an object/);
});

// --- Why, point 7: the boundary fuzzer's edges (tests/js/fuzz/known-edges.mjs) ---

const MAX = Number.MAX_VALUE;

test('why 7: gospaSeries with c near the largest double has a finite meanDistance', () => {
  const r = fisst.gospaSeries({ truths: [[[0]], [[0]]], estimates: [[], []], c: MAX, p: 2 });
  assert.ok(Number.isFinite(r.meanDistance), `meanDistance ${r.meanDistance}`);
});

test('why 7: ospaSeries with c = 1e308 has a finite meanDistance and meanCardinality', () => {
  const r = fisst.ospaSeries({ truths: [[[0]], [[0]]], estimates: [[], []], c: 1e308, p: 1 });
  assert.ok(Number.isFinite(r.meanDistance) && Number.isFinite(r.meanCardinality), `${r.meanDistance} ${r.meanCardinality}`);
});

test('why 7: splitForRegions with a box corner at ±1e308 has a finite exactInside', () => {
  const r = fisst.splitForRegions({ mixture: [{ weight: 1, mean: [0, 0], cov: [[1, 0.5], [0.5, 1]] }], regions: [{ box: { min: [-1e308, -1e308], max: [0, 0] } }], maxDepth: 0 });
  assert.ok(Number.isFinite(r.exactInside), `exactInside ${r.exactInside}`);
});

// 10⁶ existence probabilities: a RangeError naming `existence` (a cap), promptly. Each runs in a
// child process with a deadline, started now so that both run side by side.
const LARGE_MS = 5_000; // the bound is 2 s; the machine may be loaded
const million = (fn) => runChild(`
  import * as fisst from 'fisst';
  const t0 = performance.now();
  try { fisst.${fn}(new Float64Array(1e6).fill(0.5)); console.log(JSON.stringify(['returned', '', performance.now() - t0])); }
  catch (e) { console.log(JSON.stringify([e.constructor.name, e.message, performance.now() - t0])); }`, LARGE_MS);
const large = {};
for (const fn of ['multiBernoulliCardinality', 'multiBernoulliLeaveOneOut']) {
  large[fn] = million(fn);
  test(`why 7: ${fn} of 10⁶ existence probabilities is a prompt RangeError naming existence`, async () => {
    const run = await large[fn];
    assert.equal(run.signal, null, `still running after ${LARGE_MS} ms`);
    const [name, message] = JSON.parse(run.out);
    assert.equal(name, 'RangeError', message);
    assert.match(message, /^existence\b/);
  });
}

// Two edges `node fuzz/run.mjs --cases 300000` found (seed 946630), with its shrunk inputs.
const hasNaN = (v) => (typeof v === 'number' ? Number.isNaN(v) : v !== null && typeof v === 'object' && Object.values(v).some(hasNaN));

test('why 7 (fuzz seed 946630): jdeMonteCarlo with a prior variance of 1e308 gives an infinite risk, not NaN', () => {
  const r = fisst.jdeMonteCarlo({ model: 'II', existence: 1, prior: { multivariateGaussian: { mean: [0, 0, 0], cov: [[1e308, 0, 0], [0, 1, 0], [0, 0, 1]] } }, observation: { detectionProbability: 0, gain: [[0, 0, 0]], offset: [0], noiseCov: [[1]] }, falseAlarmError: 0, missError: 0, clutter: { rate: 0, density: { gaussian: { mean: 0, variance: 25 } } }, samples: 200, seed: 1, emptyRule: 'declare' });
  assert.ok(!hasNaN(r), JSON.stringify(r).slice(0, 300));
  assert.equal(r.mse, Infinity);
});

test('why 7 (fuzz seed 946630): a GmBernoulliFilter at -Number.MAX_VALUE split about a FoV has no NaN in its estimate', () => {
  const f = new fisst.GmBernoulliFilter({ existence: 0, mixture: [{ weight: 1, mean: [-MAX, 0, 0, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }], transition: { F: [[1, 0, 0.001, 0], [0, 1, 0, 0.001], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[3.3333333333333334e-19, 0, 5e-16, 0], [0, 3.3333333333333334e-19, 0, 5e-16], [5e-16, 0, 1.0000000000000002e-12, 0], [0, 5e-16, 0, 1.0000000000000002e-12]] }, detection: { probability: 1e-300, fov: { polygon: [[0.1, 0], [-0.04999999999999998, 0.08660254037844388], [-0.5273502691896265, -0.9133974596215564]] } }, splitting: { maxDepth: 2, variancePreserving: true }, reduction: { maxComponents: 7 }, clutter: { rate: 0, density: 0.1 } });
  try {
    f.predict();
    f.update([]);
    const e = f.estimate();
    assert.ok(!hasNaN(e), JSON.stringify(e));
  } finally {
    f.free();
  }
});

test('why 7 (fuzz seed 317566): fovVarianceMap over a grid whose step is 1e308 has finite variances', () => {
  const r = fisst.fovVarianceMap({ multiBernoulli: [{ existence: 5e-324, mean: [0, 0], cov: [[0.001, -1e-323], [-1e-323, 0.001]] }, { existence: 0, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { existence: 0, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { existence: 0, mean: [0, 1e308], cov: [[1, 0], [0, 1]] }], fovSize: [0.01, 0.01], grid: { x: [0, 0, 1], y: [0, 1e308, 2] } });
  assert.ok(!hasNaN(r), JSON.stringify(r));
});

test('why 7 (fuzz seed 198626): costs at the largest double give a loss without NaN', () => {
  const m = Number.MAX_VALUE;
  const r = fisst.multiBernoulliPointEstimate({ components: [{ existence: 0, density: { mean: [0], cov: [[1]] } }], radius: 0.01, costs: { c00: 1e308, c01: 1e308, c10: 1e308, c11: 1e308, c: 1e308 } });
  assert.ok(!hasNaN(r), JSON.stringify(r));
  const curve = fisst.bernoulliLossCurve({ existences: [0], missProbability: 0.5, costs: { c00: m, c01: m, c10: m, c11: m, c: m } });
  assert.ok(!hasNaN(curve), JSON.stringify(curve));
  assert.equal(curve.singleton[0], m);
});

test('why 7 (fuzz seed 198626): jdeMonteCarlo with a clutter rate of 3.5e-323 has a finite risk', () => {
  const r = fisst.jdeMonteCarlo({ model: 'II', existence: 1, prior: { multivariateGaussian: { mean: [0], cov: [[1]] } }, observation: { detectionProbability: 0.006518354876926869, gain: [[0]], noiseCov: [[1]] }, falseAlarmError: 0, missError: 0, clutter: { rate: 3.5e-323, density: { gaussian: { mean: 0, variance: 25 } } }, samples: 200, seed: 1 });
  assert.ok(!hasNaN(r) && Number.isFinite(r.mse), JSON.stringify(r).slice(0, 300));
});

test('why 7 (fuzz seed 602302): jdeMonteCarlo over 2 scans with a prior variance of 5e-324 has a finite risk', () => {
  const r = fisst.jdeMonteCarlo({ model: 'II', existence: 0.001214289776742761, prior: { multivariateGaussian: { mean: [0, 0, 0], cov: [[1, 0, 0], [0, 5e-324, 0], [0, 0, 1]] } }, observation: { detectionProbability: 0.5, gain: [[0, 0, 0], [0, 0, 0], [0, 0, 0]], offset: [0, 0, 0], noiseCov: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }, falseAlarmError: 0, missError: 0, samples: 200, seed: 1, emptyRule: 'declare', scans: 2 });
  assert.ok(!hasNaN(r) && Number.isFinite(r.mse), JSON.stringify(r).slice(0, 300));
});

// The updates and the control step: a joint work cap, checked before any work, a RangeError
// naming the list to shorten with the most it may hold (the four size edges `make fuzz` found;
// specs.mjs largeCases times a case at each cap).
const eye2 = [[1, 0], [0, 1]];
const spreadAt = (i) => (i * 0.6180339887498949) % 1;
const manyComponents = (n) => Array.from({ length: n }, (_, i) => ({ weight: 1 / n, mean: [10 * spreadAt(i), 10 * spreadAt(i + 7919)], cov: eye2 }));
const manyPoints = (n) => Array.from({ length: n }, (_, i) => [10 * spreadAt(2 * i), 10 * spreadAt(2 * i + 1)]);
const filterConfig = (n) => ({ existence: 0.5, mixture: manyComponents(n), transition: { F: eye2, Q: [[0.1, 0], [0, 0.1]] }, detection: { probability: 0.9 }, clutter: { rate: 0.25, density: 0.01 }, likelihood: { H: eye2, R: eye2 } });

test('why 7: gmBernoulliUpdate of 10,000 components by 10,000 measurements is a RangeError naming options.measurements', () => {
  throwsNaming(
    () => fisst.gmBernoulliUpdate({ existence: 0.5, mixture: manyComponents(10_000), detection: { probability: 0.9 }, measurements: manyPoints(10_000), likelihood: { H: eye2, R: eye2 }, clutter: { rate: 0.25, density: 0.01 } }),
    RangeError,
    /^options\.measurements: mixture components \(after splitting\) × measurements × ⌈n²\/16⌉ = 100000000 exceeds MAX_VECTOR_UPDATE_WORK = 2\^18 .*\(at most 26\)$/,
  );
});

test('why 7: a GmBernoulliFilter update past the pairs cap names reports.measurements and leaves the filter as it was', () => {
  const f = new fisst.GmBernoulliFilter(filterConfig(10_000));
  try {
    const before = f.existence;
    throwsNaming(() => f.update({ measurements: manyPoints(27) }), RangeError, /^reports\.measurements: .* = 270000 exceeds MAX_VECTOR_UPDATE_WORK = 2\^18 .*\(at most 26\)$/);
    assert.equal(f.existence, before);
  } finally {
    f.free();
  }
});

test('why 7: a ParticleBernoulliFilter update past 2·10^7 likelihood evaluations names reports', () => {
  const f = new fisst.ParticleBernoulliFilter({ ...filterConfig(1), particles: 200_000, seed: 1 });
  try {
    const disc = { disc: { center: [5, 5], radius: 1 } };
    throwsNaming(() => f.update(Array(51).fill(disc)), RangeError, /^reports: particles × reports × \(1 \+ MCMC moves\) = 20400000 exceeds MAX_UPDATE_EVALUATIONS = 2·10\^7 .*\(at most 50\)$/);
    throwsNaming(() => f.update({ measurements: manyPoints(51) }), RangeError, /^reports\.measurements: particles × measurements × .* = 20400000 exceeds/);
  } finally {
    f.free();
  }
});

test('why 7: a SensorControlRun past N·M·w(n_max) = 300,000 (w = 1 up to four objects, 2^(n_max − 3) past) names options.futureScans', () => {
  throwsNaming(() => new fisst.SensorControlRun({ scheme: 'renyi', seed: 1, particles: 20_000, futureScans: 16 }), RangeError, /^options\.futureScans: .* must be at most 300000, got 320000/);
  throwsNaming(() => new fisst.SensorControlRun({ scheme: 'renyi', seed: 1, particles: 1000, futureScans: 10, maxObjects: 8 }), RangeError, /^options\.futureScans: particles · futureScans · \(maxObjects ≤ 4 \? 1 : 2\^\(maxObjects − 3\)\) must be at most 300000, got 320000$/);
  throwsNaming(() => new fisst.SensorControlRun({ scheme: 'renyi', seed: 1, particles: 1500, futureScans: 51, maxObjects: 5 }), RangeError, /^options\.futureScans: .* must be at most 300000, got 306000$/);
});

test('why 1: gmBernoulliUpdate with more position dimensions than the state names both fields', () => {
  const e4 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
  throwsNaming(
    () => fisst.gmBernoulliUpdate({ existence: 0.5, mixture: [{ weight: 1, mean: [0, 0, 0, 0], cov: e4 }], positionDims: 5, detection: { probability: 0.9 }, reports: [], clutter: { rate: 0.25, density: 0.01 } }),
    RangeError,
    /^options\.positionDims is 5 but options\.mixture\[0\]\.mean has length 4$/,
  );
});

// --- Ten typical first-day mistakes, across the parts ---

test('mistake 1 (metrics): points of different dimensions name the point that disagrees', () => {
  throwsNaming(() => fisst.gospa([[0, 0], [10, 0]], [[1]], { c: 2 }), RangeError, /^estimate\[0\] has length 1, expected 2/);
});

test('mistake 2 (metrics): a series with fewer estimates than truths names both lists', () => {
  throwsNaming(() => fisst.gospaSeries({ truths: [[[0]], [[0]]], estimates: [[[0]]], c: 2 }), RangeError, /^options\.estimates has length 1 but options\.truths has length 2$/);
});

test('mistake 3 (splitting): a Gaussian without a weight in a mixture names the weight', () => {
  throwsNaming(() => fisst.splitForRegions({ mixture: [g2], regions: [unitBox] }), TypeError, /^options\.mixture\[0\]\.weight is required/);
});

test('mistake 4 (splitting): a box with min and max swapped names the box corner', () => {
  throwsNaming(() => fisst.splitForRegions({ mixture: [{ weight: 1, ...g2 }], regions: [{ box: { min: [1, 1], max: [-1, -1] } }] }), RangeError, /^options\.regions\[0\]\.box\.max\[0\]/);
});

test('mistake 5 (fov): the density given without its `rfs` wrapper names the key and the right one', () => {
  throwsNaming(() => fisst.fovCardinality({ multiBernoulli: mb, fov: disc }), TypeError, /^options has an unknown key "multiBernoulli"/, /\brfs\b/);
});

test('mistake 5b (fov): a bare multi-Bernoulli array as `rfs` names the keys and does not offer a string', () => {
  throwsNaming(() => fisst.fovCardinality({ rfs: mb, fov: disc }), TypeError, /^options\.rfs\b/, /multiBernoulli/, /^(?![\s\S]*\ba string\b)/);
});

test('mistake 6 (fov): a detection probability in percent names the field', () => {
  throwsNaming(() => fisst.fovCardinality({ rfs: { multiBernoulli: mb }, fov: disc, detectionProbability: 90 }), RangeError, /^options\.detectionProbability must be a probability in \[0, 1\], got 90/);
});

test('mistake 7 (bernoulli): a bare number as a 2-D covariance names the covariance', () => {
  throwsNaming(() => fisst.bernoulliEstimate({ existence: 0.5, density: { mean: [0, 0], cov: 1 }, radius: 1, costs: 'mpe' }), TypeError, /^options\.density\.cov must be a nested 2×2 array/);
});

test("mistake 8 (bernoulli): the costs preset in capitals ('MPE') names the costs and the choices", () => {
  throwsNaming(() => fisst.bernoulliEstimate({ existence: 0.5, density: g2, radius: 1, costs: 'MPE' }), RangeError, /^options\.costs must be 'mpe'/, /"MPE"/);
});

test('mistake 9 (bounds): a posterior variance above the prior names the posterior variance', () => {
  const jde = { existence: 0.5, detectionProbability: 0.9, priorVariance: 1, posteriorVariance: 2, falseAlarmError: 1, missError: 1 };
  throwsNaming(() => fisst.jdeBoundNoClutter(jde), RangeError, /^options\.posteriorVariance must be ≤ priorVariance/);
});

test("mistake 10 (control): a scheme in capitals ('Renyi') names the scheme and the choices", () => {
  throwsNaming(() => new fisst.SensorControlRun({ scheme: 'Renyi', seed: 1 }), RangeError, /^options\.scheme must be one of 'renyi', 'fisher', 'pent', 'random', got "Renyi"/);
});

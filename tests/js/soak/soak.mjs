// The leak soak: calls every exported function many times in Node, on valid inputs and on
// malformed ones (so the error paths are soaked too), and checks that the wasm memory
// (`memory.buffer.byteLength`), the table of JS values held by wasm (`__wbindgen_externrefs`)
// and the JS heap stop growing after a warm-up.
//
//   node --expose-gc soak/soak.mjs [--calls N]     (make soak: N = 100,000 per function)
//
// Exported `soak({ calls })` is what soak.test.mjs (make test, N = 10,000) runs.
import init, * as fisst from 'fisst';

const g2 = { mean: [0.1, -0.2], cov: [[1, 0.2], [0.2, 0.5]] };
const comp = { weight: 1, ...g2 };
const box = { box: { min: [-1, -1], max: [1, 1] } };
const NCV = { F: [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[0.01, 0, 0.01, 0], [0, 0.01, 0, 0.01], [0.01, 0, 0.02, 0], [0, 0.01, 0, 0.02]] };
/** A small 2D filter config for both classes (50 particles, a fixed seed). */
const FILTER = { existence: 0.7, mixture: [comp], transition: { F: [[1, 0], [0, 1]], Q: [[0.1, 0], [0, 0.1]] }, detection: { probability: 0.9 }, clutter: { rate: 0.25, density: 0.1 }, exclusions: [{ box: { min: [3, 3], max: [4, 4] } }], particles: 50, seed: 3 };

/** Per function (or class, with a driver below): a few cheap valid argument lists and a few
 * malformed ones. */
export const cases = {
  jdeExample2: [[{ existence: 0.6, detectionProbability: 0.5, falseAlarmProbability: 0, falseAlarmError: 1.2 }], [{ existence: 0.6, detectionProbability: 0.5, falseAlarmProbability: 3, falseAlarmError: 1.2 }]],
  jdeBoundNoClutter: [[{ existence: 0.7, detectionProbability: 0.4, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 }], [{ existence: 2, detectionProbability: 0.4, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 }]],
  gaussianFisherInformation: [[{ priorVariance: 4, gain: 2, noiseVariance: 1 }], [{ priorVariance: 4, gain: 2 }]],
  jdeSequentialBound: [[{ method: 'irf', priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: 0.6, steps: 5 }], [{ method: 'crb', priorInformation: 0.01, detectedInformation: 0.04, detectionProbability: 0.6, steps: 5 }]],
  jdeBound: [[{ model: 'I', existence: 0.6, prior: { gaussian: { mean: 0, variance: 4 } }, observation: { detectionProbability: 0.8, noiseVariance: 1 }, falseAlarmError: 6, missError: 9 }], [{ model: 'I', existence: 0.6, prior: { gaussian: { mean: 0, variance: -4 } }, observation: { detectionProbability: 0.8, noiseVariance: 1 }, falseAlarmError: 6, missError: 9 }], [{ model: 'I', existence: 0.6, prior: { multivariateGaussian: g2 }, observation: { detectionProbability: 0.8, gain: [[1, 0.5], [0, 1]], noiseCov: [[1, 0], [0, 2]] }, falseAlarmError: 6, missError: 9 }], [{ model: 'I', existence: 0.6, prior: { multivariateGaussian: g2 }, observation: { detectionProbability: 0.8, gain: [[1, 0.5, 2]], noiseCov: [[1]] }, falseAlarmError: 6, missError: 9 }]],
  gospa: [[[[0, 0], [1, 1]], [[0, 0.5]], { c: 2 }], [[[0]], [[1], [5]], { c: 3, p: 1, alpha: 1 }], [[[0, 0]], [[0, 0]], { c: 2, aplha: 1 }], [[[0, NaN]], [], { c: 1 }]],
  ospa: [[[[0], [5]], [[1]], { c: 10, p: 1 }], [[[0, 0]], 'x', { c: 1 }]],
  uospa: [[[[0], [5]], [[1]], { c: 10 }], [[[0]], [[1]], { c: -1 }]],
  linearAssignment: [[[[4, 1, 3], [2, 0, 5]]], [[[1, 2], [3]]]],
  multiBernoulliCardinality: [[[0.1, 0.5, 0.9]], [[0.5, 2]]],
  multiBernoulliLeaveOneOut: [[[0.1, 0.5, 0.9]], ['0.5']],
  mbOptimalEstimate: [[{ existence: [0.4, 0.4], metric: 'ospa' }], [{ existence: [0.4], metric: 'hausdorff' }]],
  gospaSeries: [[{ truths: [[[0, 0]], []], estimates: [[[0, 1]], [[2, 2]]], c: 2 }], [{ truths: [[[0]]], estimates: [], c: 1 }], [{ truths: [], estimates: [], c: 1, aplha: 2 }]],
  ospaSeries: [[{ truths: [[[0, 0]], [[1, 1], [2, 2]]], estimates: [[[0, 1]], []], c: 3, p: 1 }], [{ truths: [[[0, NaN]]], estimates: [[]], c: 1 }]],
  mbMeanSquareError: [[{ existence: [0.4, 0.9], report: [true, false], metric: 'gospa' }], [{ existence: [0.4], report: [true, true], metric: 'ospa' }]],
  mbAlternativeEstimate: [[{ existence: [0.4, 0.6], method: 'jom' }], [{ existence: [0.4], method: 'map' }]],
  mbDecisionMap: [[{ estimator: 'ospa', resolution: 8 }], [{ estimator: 'ospa', resolution: 0 }]],
  mbIdenticalComponentCounts: [[{ existence: 0.3, maxComponents: 6 }], [{ existence: 0.3 }]],
  fovCardinality: [[{ rfs: { multiBernoulli: [{ existence: 0.6, ...g2 }] }, fov: box }], [{ rfs: { poisson: [comp] }, fov: { circle: 1 } }]],
  fovVarianceMap: [[{ multiBernoulli: [{ existence: 0.6, ...g2 }], fovSize: [1, 1], grid: { x: [-1, 1, 4], y: [-1, 1, 4] } }], [{ multiBernoulli: [], fovSize: [1], grid: {} }]],
  placementScene: [[{ count: 5, seed: 3 }], [{ count: -1 }]],
  mixtureDensityGrid: [[{ mixture: [comp], grid: { x: [-1, 1, 4], y: [-1, 1, 4] } }], [{ mixture: [{ weight: 1, mean: [0, 0], cov: [[1, 2], [3, 4]] }], grid: { x: [0, 1, 2], y: [0, 1, 2] } }]],
  splitLibrary: [[{ components: 4, lambda: 0.001 }], [{ components: 40, lambda: 0.001 }]],
  splitForRegions: [[{ mixture: [comp], regions: [box], maxDepth: 1 }], [{ mixture: [comp], regions: [] }]],
  reduceMixture: [[{ mixture: [comp, { ...comp, mean: [0.2, -0.1] }], mergeDistance: 1 }], [{ mixture: [comp], maxComponents: 0 }]],
  negativeInformationScenario: [[{ step: 1 }], [{ step: 9 }]],
  bernoulliEstimate: [[{ existence: 0.7, density: { mean: [0], cov: 1 }, radius: 1, costs: 'mpe' }], [{ existence: 0.7, density: {}, radius: 1, costs: 'mpe' }]],
  probabilityOutsideBall: [[{ density: { particles: [[0], [1]] }, center: [0], radius: 0.5 }], [{ density: g2, center: [0], radius: 1 }]],
  bernoulliThresholdCurve: [[{ sigmas: [0.5, 1], radius: 1, costs: 'mpe' }], [{ sigmas: [0.5], radius: 1, costs: 'mmse' }]],
  mmucEstimate: [[{ density: { mean: [0, 0], cov: [[1, 0], [0, 1]] }, radius: 0.5 }], [{ density: { mean: [0, 0] }, radius: 0.5 }]],
  multiBernoulliPointEstimate: [[{ components: [{ existence: 0.9, density: { mean: [0], cov: 1 } }], radius: 1, costs: 'mpe' }], [{ components: [{ existence: 2, density: { mean: [0], cov: 1 } }], radius: 1, costs: 'mpe' }]],
  bernoulliLossCurve: [[{ existences: [0.1, 0.9], missProbability: 0.2, costs: 'mpe' }], [{ existences: [0.1], missProbability: 2, costs: 'mpe' }]],
  version: [[]],
  multiObjectLikelihood: [
    [{ likelihoods: [[0.2, 0.01], [0.03, 0.4]], detectionProbability: 0.95, clutterRate: 0.8, clutterDensity: [0.5, 0.5] }],
    [{ likelihoods: [[0.2]], detectionProbability: 0.95, clutterRate: 0.8, clutterDensity: [0.5, 0.5] }],
  ],
  SensorControlRun: [[{ seed: 1, scheme: 'renyi', particles: 10, futureScans: 2, steps: 2 }], [{ scheme: 'best' }]],
  compareSchemes: [[{ runs: 1, steps: 1, seed: 1, schemes: ['pent'], particles: 5, futureScans: 1 }], [{ runs: 0, steps: 1 }]],
  gmBernoulliPredict: [[{ existence: 0.6, mixture: [{ weight: 1, mean: [0, 0, 1, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0.1, 0], [0, 0, 0, 0.1]] }], transition: NCV }], [{ existence: 0.6, mixture: [comp], transition: NCV }]],
  gmBernoulliUpdate: [
    [{ existence: 0.8, mixture: [comp], detection: { probability: 0.9, fov: box }, reports: [{ disc: { center: [0, 0], radius: 1 } }], clutter: { rate: 0.25, density: 0.1 } }],
    [{ existence: 0.8, mixture: [comp], detection: { probability: 0.9 }, measurements: [[0, 0]], likelihood: { H: [[1, 0], [0, 1]], R: [[0.1, 0], [0, 0.1]] }, clutter: { rate: 0.25, density: 0.1 } }],
    [{ existence: 0.8, mixture: [comp], detection: { probability: 0.9 }, reports: [{ disc: { center: [0, 0], radius: -1 } }], clutter: { rate: 0.25, density: 0.1 } }],
  ],
  GmBernoulliFilter: [[FILTER, [{ disc: { center: [0, 0], radius: 1 } }]], [FILTER, []], [FILTER, [{ disc: { center: [0, 0, 0], radius: 1 } }]], [{ ...FILTER, existence: 2 }, []]],
  ParticleBernoulliFilter: [[FILTER, [{ disc: { center: [0, 0], radius: 1 } }]], [FILTER, { measurements: [[0, 0]] }], [{ ...FILTER, particles: 0 }, []]],
  airportScenario: [[{ seed: 1, steps: 5 }], [{ steps: 2001 }]],
};

/** Drivers of classes: `drivers[name](fisst, args)` (construct, call methods, `free()`). */
const driveFilter = (cls) => (fisst, [config, scan]) => {
  const f = new fisst[cls](config);
  try {
    f.predict();
    f.update(scan);
    f.estimate(); // no loss: its MMUC search is bernoulliEstimate's, soaked there
    return f.existence;
  } finally {
    f.free();
  }
};
export const drivers = {
  GmBernoulliFilter: driveFilter('GmBernoulliFilter'),
  ParticleBernoulliFilter: driveFilter('ParticleBernoulliFilter'),
  SensorControlRun: (fisst, args) => {
    const run = new fisst.SensorControlRun(args[0]);
    try {
      while (run.k < run.steps) run.step();
      void run.particles;
      void run.measurements;
    } finally {
      run.free();
    }
  },
};

function call(name, args) {
  try {
    if (drivers[name]) drivers[name](fisst, args);
    else fisst[name](...args);
  } catch (e) {
    if (!(e instanceof TypeError || e instanceof RangeError)) throw e;
  }
}

/** Summed over the package's parts (`init()` resolves to each part's wasm exports). */
function measure(wasm) {
  globalThis.gc?.();
  const parts = Object.values(wasm);
  return {
    wasmBytes: parts.reduce((sum, part) => sum + part.memory.buffer.byteLength, 0),
    externrefs: parts.reduce((sum, part) => sum + (part.__wbindgen_externrefs?.length ?? 0), 0),
    heap: process.memoryUsage().heapUsed,
  };
}

/**
 * Calls each function `calls` times (cycling through its cases) and returns per function the
 * measurements after 20 % of the calls (the warm-up) and at the end.
 */
export async function soak({ calls, only } = {}) {
  const wasm = await init();
  const out = [];
  for (const [name, list] of Object.entries(cases)) {
    if (only && !only.includes(name)) continue;
    const warm = Math.max(1, Math.floor(calls * 0.2));
    for (let i = 0; i < warm; i++) call(name, list[i % list.length]);
    const before = measure(wasm);
    const start = performance.now();
    for (let i = warm; i < calls; i++) call(name, list[i % list.length]);
    const ms = performance.now() - start;
    const after = measure(wasm);
    out.push({ name, calls, before, after, ms });
  }
  return out;
}

/** Whether a soak result grew: any wasm memory or externref growth, or > 4 MiB of JS heap. */
export function grew({ before, after }) {
  return after.wasmBytes > before.wasmBytes || after.externrefs > before.externrefs + 64 || after.heap - before.heap > 4 * 2 ** 20;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const i = process.argv.indexOf('--calls');
  const calls = i >= 0 ? Number(process.argv[i + 1]) : 100_000;
  if (!globalThis.gc) console.log('(run with node --expose-gc for exact heap figures)');
  const results = await soak({ calls });
  let bad = 0;
  console.log(`${'function'.padEnd(30)}${'calls'.padEnd(9)}${'wasm bytes (warm → end)'.padEnd(26)}${'externrefs'.padEnd(13)}${'JS heap MiB'.padEnd(16)}µs/call`);
  for (const r of results) {
    const flag = grew(r);
    if (flag) bad++;
    console.log(
      `${r.name.padEnd(30)}${String(r.calls).padEnd(9)}${`${r.before.wasmBytes} → ${r.after.wasmBytes}`.padEnd(26)}${`${r.before.externrefs} → ${r.after.externrefs}`.padEnd(13)}${`${(r.before.heap / 2 ** 20).toFixed(1)} → ${(r.after.heap / 2 ** 20).toFixed(1)}`.padEnd(16)}${((r.ms * 1000) / (r.calls * 0.8)).toFixed(1)}${flag ? '  GREW' : ''}`,
    );
  }
  console.log(bad ? `${bad} function(s) grew` : 'no growth after warm-up');
  process.exit(bad ? 1 : 0);
}

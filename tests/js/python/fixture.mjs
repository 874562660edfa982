// The npm package's results on a set of inputs from the contract tests, as JSON on stdout:
// python/tests/test_js_parity.py runs this and checks that the Python package returns the same
// numbers (bit for bit) from the same inputs under its own names (snake_case keywords).
//   node tests/js/python/fixture.mjs > out.json
import * as fisst from 'fisst';

// a placement scene as plain data (the arguments are written out as JSON)
const placementSceneFor = (o) => fisst.placementScene(o).multiBernoulli;

const calls = [
  ['gospa', [[[0, 0], [10, 0]], [[0, 1]], { c: 2 }]],
  ['gospa', [[[0, 0], [1, 2], [3, 1]], [[0.5, 0], [3, 1.5]], { c: 2, p: 1, alpha: 2 }]],
  ['gospa', [[[0, 0], [1, 2], [3, 1]], [[0.5, 0], [3, 1.5]], { c: 2, p: 3, alpha: 1 }]],
  ['ospa', [[[0, 0], [1, 1]], [[0, 1]], { c: 2, p: 1 }]],
  ['ospa', [[[0, 0, 0], [1, 1, 1], [4, 0, 2]], [[0, 1, 0], [5, 0, 2]], { c: 3 }]],
  ['uospa', [[[0, 0], [1, 1]], [[0, 1]], { c: 2 }]],
  ['gospaSeries', [{ truths: [[[0, 0]], [], [[1, 1], [2, 2]]], estimates: [[[0, 1]], [[1, 1]], [[2, 2.5]]], c: 2, p: 2 }]],
  ['ospaSeries', [{ truths: [[[0, 0]], [], [[1, 1], [2, 2]]], estimates: [[[0, 1]], [[1, 1]], [[2, 2.5]]], c: 2, p: 1 }]],
  ['linearAssignment', [[[4, 1, 3], [2, 0, 5], [3, 2, 2]]]],
  ['multiBernoulliCardinality', [[0.31180874673401826, 0.6562714661775726, 0.5775291650070283]]],
  ['multiBernoulliLeaveOneOut', [[0.3, 0.7, 0.55]]],
  ['mbOptimalEstimate', [{ existence: [0.4, 0.4], metric: 'ospa' }]],
  ['mbOptimalEstimate', [{ existence: [0.9, 0.2, 0.55, 0.6], metric: 'gospa', c: 2, p: 1 }]],
  ['mbMeanSquareError', [{ existence: [0.4, 0.4], report: [true, false], metric: 'gospa' }]],
  ['mbAlternativeEstimate', [{ existence: [0.4, 0.7, 0.2], method: 'mam' }]],
  ['mbAlternativeEstimate', [{ existence: [0.4, 0.7, 0.2], method: 'map-cardinality' }]],
  ['mbIdenticalComponentCounts', [{ existence: 0.6, maxComponents: 6 }]],
  ['bernoulliLossCurve', [{ existences: [0.1, 0.5, 0.9], missProbability: 0.2, costs: 'mpe' }]],
  ['bernoulliLossCurve', [{ existences: [0.1, 0.5, 0.9], missProbability: 0.3, costs: { mmol: { asset: 2, countermeasure: 1 } } }]],
  ['bernoulliThresholdCurve', [{ sigmas: [0.5, 1, 2, 4], radius: 1, costs: 'mpe' }]],
  ['jdeBoundNoClutter', [{ existence: 0.5, detectionProbability: 0.9, priorVariance: 100, posteriorVariance: 1, falseAlarmError: 100, missError: 100 }]],
  ['gaussianFisherInformation', [{ priorVariance: 4, gain: 2, noiseVariance: 3 }]],
  ['jdeSequentialBound', [{ method: 'enumeration', priorInformation: 0.1, detectedInformation: 1, detectionProbability: 0.8, steps: 5 }]],
  ['jdeSequentialBound', [{ method: 'irf', priorInformation: 0.1, detectedInformation: 1, detectionProbability: 0.8, steps: 5 }]],
  // paper 002's jdeBound (Theorems 1 and 2, (63)–(72)) and jdeMonteCarlo (seeded)
  ['jdeBound', [{ model: 'I', existence: 0.5, prior: { gaussian: { mean: 1, variance: 4 } }, observation: { detectionProbability: 0.9, gain: 2, offset: 0.5, noiseVariance: 1 }, falseAlarm: { probability: 0.2, density: { uniform: { low: -10, high: 10 } } }, falseAlarmError: 150, missError: 200 }]],
  ['jdeBound', [{ model: 'II', existence: 0.7, prior: { gaussian: { mean: 1, variance: 4 } }, observation: { detectionProbability: { table: { x: [-3, 3], probability: [0.3, 0.9] } }, noiseVariance: 1 }, clutter: { rate: 0.5, density: { uniform: { low: -10, high: 10 } } }, falseAlarmError: 10, missError: 20, samples: 500, seed: 3 }]],
  ['jdeBound', [{ model: 'I', existence: 0.6, prior: { multivariateGaussian: { mean: [0, 1], cov: [[2, 0.5], [0.5, 1]] } }, observation: { detectionProbability: 0.8, gain: [[1, 0], [0, 1]], offset: 0, noiseCov: [1, 0, 0, 2] }, falseAlarmError: 50, missError: 60 }]],
  ['jdeMonteCarlo', [{ model: 'II', existence: 0.5, prior: { gaussian: { mean: 0, variance: 1 } }, observation: { detectionProbability: 0.9, noiseVariance: 1 }, clutter: { rate: 1, density: { uniform: { low: -10, high: 10 } } }, falseAlarmError: 1, missError: 1, samples: 300, seed: 5, emptyRule: 'map' }]],
  ['jdeMonteCarlo', [{ model: 'I', existence: 0.8, prior: { multivariateGaussian: { mean: [0, 0], cov: [[1, 0.2], [0.2, 2]] } }, observation: { detectionProbability: 0.7, gain: [[1, 0], [0, 1]], noiseCov: [[1, 0], [0, 1]] }, falseAlarmError: 5, missError: 6, samples: 200, seed: 2, scans: 3 }]],
  ['jdeMonteCarlo', [{ model: 'I', existence: 0.6, prior: 'example2', observation: { detectionProbability: 0.9 }, falseAlarm: { probability: 0.3, density: { uniform: { low: 0, high: 1 } } }, falseAlarmError: 1.2, missError: 1, samples: 200, seed: 9 }]],
  ['probabilityOutsideBall', [{ density: { mean: [0, 0], cov: [[1, 0.3], [0.3, 2]] }, center: [0.5, 0], radius: 1.5 }]],
  ['probabilityOutsideBall', [{ density: { mixture: [{ weight: 0.3, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { weight: 0.7, mean: [2, 1], cov: [[0.5, 0], [0, 0.5]] }] }, center: [1, 0.5], radius: 1 }]],
  ['probabilityOutsideBall', [{ density: { particles: [[0, 0], [1, 1], [3, 0]], weights: [0.2, 0.5, 0.3] }, center: [0.5, 0.5], radius: 1 }]],
  ['reduceMixture', [{ mixture: [{ weight: 0.5, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { weight: 0.3, mean: [0.1, 0], cov: [[1, 0], [0, 1]] }, { weight: 1e-9, mean: [5, 5], cov: [[1, 0], [0, 1]] }, { weight: 0.2, mean: [4, 0], cov: [[2, 0], [0, 1]] }], pruneBelow: 1e-6, mergeDistance: 1, maxComponents: 1 }]],
  ['splitLibrary', [{ components: 4, lambda: 0.001 }]],
  ['splitLibrary', [{ components: 5, lambda: 0.01, spacing: 'free' }]],
  ['splitForRegions', [{ mixture: [{ weight: 0.6, mean: [0, 0], cov: [[1, 0.3], [0.3, 2]] }, { weight: 0.4, mean: [2, 1], cov: [[0.5, 0], [0, 0.5]] }], regions: [{ box: { min: [0.5, -1], max: [3, 2] } }, { disc: { center: [0, 0], radius: 1 } }], gridBound: 3, components: 4 }]],
  ['splitForRegions', [{ mixture: [{ weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1]] }], regions: [{ polygon: [[0, 0], [2, 0], [0, 2]] }], maxComponents: 5 }]],
  ['negativeInformationScenario', []],
  ['negativeInformationScenario', [{ step: 2 }]],
  ['airportScenario', [{ seed: 7, steps: 5 }]],
  ['multiObjectLikelihood', [{ likelihoods: [[0.5, 0.1], [0.2, 0.3]], detectionProbability: 0.9, clutterRate: 1, clutterDensity: [0.1, 0.1] }]],
  ['fovCardinality', [{ rfs: { multiBernoulli: [{ existence: 0.5, mean: [0, 0], cov: [[1, 0.2], [0.2, 0.5]] }, { existence: 0.9, mean: [2, 1], cov: [[0.3, 0], [0, 0.3]] }] }, fov: { box: { min: [-1, -1], max: [2, 1.5] } }, detectionProbability: 0.9 }]],
  ['fovCardinality', [{ rfs: { poisson: [{ weight: 2, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { weight: 0.5, mean: [3, 0], cov: [[0.5, 0], [0, 0.5]] }] }, fov: { disc: { center: [0.5, 0], radius: 1.5 } } }]],
  ['fovCardinality', [{ rfs: { iidCluster: { cardinality: [0.1, 0.3, 0.6], density: [{ weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1]] }] } }, fov: { polygon: [[-1, -1], [2, -1], [0, 2]] } }]],
  ['fovCardinality', [{ rfs: { glmb: [{ weight: 0.4, components: [{ mean: [0, 0], cov: [[1, 0], [0, 1]] }] }, { weight: 0.6, components: [{ mean: [0, 0], cov: [[1, 0], [0, 1]] }, { mean: [1, 1], cov: [[0.5, 0], [0, 0.5]] }] }] }, fov: { union: [{ box: { min: [-1, -1], max: [0, 0] } }, { complement: { disc: { center: [0, 0], radius: 2 } } }] } }]],
  ['fovVarianceMap', [{ multiBernoulli: placementSceneFor({ count: 8, seed: 3 }), fovSize: [1, 1.5], grid: { x: [-3, 3, 7], y: [-2, 2, 5] } }]],
  ['placementScene', [{ count: 5, seed: 9, extent: 2, sigma: [0.2, 0.4] }]],
  ['mixtureDensityGrid', [{ mixture: [{ weight: 0.7, mean: [0, 0], cov: [[1, 0.3], [0.3, 0.8]] }, { weight: 1.2, mean: [1, -1], cov: [[0.5, -0.1], [-0.1, 0.4]] }], grid: { x: [-2, 2, 6], y: [-1, 1, 4] } }]],
  // paper 000's point estimates (bernoulli_estimate, mmuc_estimate, multi_bernoulli_point_estimate)
  ['bernoulliEstimate', [{ existence: 0.7, density: { mixture: [{ weight: 0.5, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { weight: 0.5, mean: [2, 0], cov: [[1, 0], [0, 1]] }] }, radius: 1, costs: 'mpe' }]],
  ['bernoulliEstimate', [{ existence: 0.55, density: { mean: [0], cov: 1 }, radius: 1, costs: 'mpe' }]],
  ['bernoulliEstimate', [{ existence: 0.2, density: { particles: [[0, 0], [1, 1], [3, 0]], weights: [0.2, 0.5, 0.3] }, radius: 1, costs: { mmol: { asset: 0.9, countermeasure: 0.1 } } }]],
  ['mmucEstimate', [{ density: { mixture: [{ weight: 0.3, mean: [0, 0], cov: [[1, 0], [0, 1]] }, { weight: 0.7, mean: [2, 1], cov: [[0.5, 0], [0, 0.5]] }] }, radius: 1 }]],
  ['mmucEstimate', [{ density: { particles: [[0, 0], [0.5, 0.2], [3, 0], [3.2, 0.1]] }, radius: 1 }]],
  ['multiBernoulliPointEstimate', [{ components: [{ existence: 0.9, density: { mean: [0, 0], cov: [[0.2, 0], [0, 0.2]] } }, { existence: 0.55, density: { mean: [5, 5], cov: [[4, 0], [0, 4]] } }, { existence: 0.7, density: { particles: [[9, 9]] } }], radius: 1, costs: { c00: 0, c01: 1, c10: 1, c11: 0, c: 1 } }]],
];

const out = calls.map(([fn, args]) => ({ fn, args, result: fisst[fn](...args) }));
// SensorControlRun: three seeded steps
const run = new fisst.SensorControlRun({ scheme: 'pent', seed: 7, steps: 3, particles: 200, futureScans: 20 });
const steps = [run.step(), run.step(), run.step()];
out.push({ fn: 'SensorControlRun', args: [{ scheme: 'pent', seed: 7, steps: 3, particles: 200, futureScans: 20 }], result: steps });
// GmBernoulliFilter and ParticleBernoulliFilter: predict, update with regions, an empty scan,
// and a vector update; the update infos, existence and mixture after each
const filterConfig = {
  existence: 0.5,
  mixture: [{ weight: 1, mean: [0, 0, 1, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }],
  transition: { F: [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[0.1, 0, 0, 0], [0, 0.1, 0, 0], [0, 0, 0.1, 0], [0, 0, 0, 0.1]] },
  detection: { probability: 0.9, fov: { box: { min: [-5, -5], max: [5, 5] } } },
  clutter: { rate: 1, density: 0.01 },
  likelihood: { H: [[1, 0, 0, 0], [0, 1, 0, 0]], R: [[0.5, 0], [0, 0.5]] },
};
const scans = [[{ disc: { center: [1, 0], radius: 1 } }], [], { measurements: [[2.5, 0.2]] }];
for (const [name, extra] of [['GmBernoulliFilter', {}], ['ParticleBernoulliFilter', { particles: 300, seed: 5 }]]) {
  const f = new fisst[name]({ ...filterConfig, ...extra });
  const trace = [];
  for (const s of scans) {
    f.predict();
    trace.push({ info: f.update(s), existence: f.existence, ...(name === 'GmBernoulliFilter' ? { mixture: f.mixture } : { weights: f.weights }) });
  }
  out.push({ fn: name, args: [{ ...filterConfig, ...extra }], scans, result: trace });
}
const replacer = (_, v) => (v instanceof Float64Array || v instanceof Uint8Array ? Array.from(v) : typeof v === 'number' && !Number.isFinite(v) ? { nonFinite: String(v) } : v);
process.stdout.write(JSON.stringify(out, replacer));

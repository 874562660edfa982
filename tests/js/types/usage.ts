// Compiled with `tsc --noEmit --strict` by types.test.mjs: the package's .d.ts must type the
// contract's names and shapes (a wrong field name or type below would fail the build).
import init, * as fisst from 'fisst';

await init();

const truth: fisst.Point[] = [[0, 0], [10, 0]];
const g: fisst.GospaResult = fisst.gospa(truth, [[0, 1]], { c: 2, p: 2, alpha: 2 });
const distance: number = g.distance;
const missed: number | undefined = g.missed;
const pairs: [number, number][] | undefined = g.assignment;

const o: fisst.OspaResult = fisst.ospa(truth, [new Float64Array([1, 1])], { c: 3 });
const parts: number = o.localisation ** 2 + o.cardinality ** 2;

const pmf: number[] = fisst.multiBernoulliCardinality([0.5, 0.5]);
const best: fisst.MbOptimalEstimateResult = fisst.mbOptimalEstimate({ existence: [0.4, 0.4], metric: 'ospa', c: 1, p: 2 });
const report: boolean[] = best.report;
const mse: number = fisst.mbMeanSquareError({ existence: [0.4, 0.4], report, metric: 'uospa' });

// Every other export, with the shared shapes (Point, Gaussian, WeightedGaussian, Bernoulli,
// Region, MultiObjectDensity) and the generated option and result types.
const box: fisst.Region = { box: { min: [-1, -1], max: [1, 1] } };
const disc: fisst.Region = { disc: { center: new Float64Array([0, 0]), radius: 1 } };
const poly: fisst.Region = { polygon: [[0, 0], [1, 0], [0, 1]] };
const g2: fisst.Gaussian = { mean: [0, 0], cov: [[1, 0], [0, 1]] };
const comp: fisst.WeightedGaussian = { weight: 1, ...g2 };
const mb: fisst.Bernoulli[] = [{ existence: 0.5, ...g2 }];
const rfs: fisst.MultiObjectDensity = { multiBernoulli: mb };
const grid: fisst.Grid = { x: [-1, 1, 5], y: [-1, 1, 5] };

const gs: fisst.GospaSeriesResult = fisst.gospaSeries({ truths: [truth, []], estimates: [[[0, 1]], truth], c: 2 });
const gsMissed: number[] | undefined = gs.missed;
const os: fisst.OspaSeriesResult = fisst.ospaSeries({ truths: [truth], estimates: [truth], c: 2, p: 1 });
const osMean: number = os.meanLocalisation + os.meanCardinality + gs.meanDistance;
const la: fisst.LinearAssignmentResult = fisst.linearAssignment([[1, 2], [3, 4]]);
const u: number = fisst.uospa(truth, truth, { c: 1 }).distance;
const loo: number[][] = fisst.multiBernoulliLeaveOneOut(new Float64Array([0.2, 0.7]));
const alt: boolean[] = fisst.mbAlternativeEstimate({ existence: [0.4, 0.6], method: 'jom', lnC: 0 }).report;
const map: Uint8Array = fisst.mbDecisionMap({ estimator: 'map-cardinality', resolution: 4 }).decisions;
const counts: number[] = fisst.mbIdenticalComponentCounts({ existence: 0.3, maxComponents: 5 }).mapCardinality;
const fc: fisst.FovCardinalityResult = fisst.fovCardinality({ rfs, fov: poly, detectionProbability: 0.9 });
const poisson: number = fisst.fovCardinality({ rfs: { poisson: [comp] }, fov: disc }).mean;
const vmap: Float64Array = fisst.fovVarianceMap({ multiBernoulli: mb, fovSize: [1, 1], grid }).variance;
const scene: fisst.PlacementSceneResult = fisst.placementScene({ count: 3, seed: 2 });
const dens: Float64Array = fisst.mixtureDensityGrid({ mixture: [comp], grid });
const lib: number[] = fisst.splitLibrary({ components: 4, lambda: 0.001, spacing: 'equal' }).weights;
const split: fisst.SplitForRegionsResult = fisst.splitForRegions({ mixture: [comp], regions: [box, disc], gridBound: 3 });
const exact: number | null = split.exactInside;
const reduced: fisst.MixtureComponent[] = fisst.reduceMixture({ mixture: split.mixture, mergeDistance: 1, maxComponents: 3 });
const fig5 = fisst.negativeInformationScenario();
const step = fisst.negativeInformationScenario({ step: 2 });
const est: fisst.BernoulliEstimateResult = fisst.bernoulliEstimate({ existence: 0.7, density: { mixture: [comp] }, radius: 1, costs: 'mpe' });
const at: number[] | null = est.estimate;
const q: number = fisst.probabilityOutsideBall({ density: { particles: [[0, 0], [1, 1]], weights: [1, 2] }, center: [0, 0], radius: 1 });
const gamma: number[] = fisst.bernoulliThresholdCurve({ sigmas: [0.5, 1], radius: 1, costs: { mmol: { asset: 10, countermeasure: 1 } } });
const mmuc: fisst.MmucEstimateResult = fisst.mmucEstimate({ density: { mean: [0], cov: 1 }, radius: 0.5 });
const mbp: number[] = fisst.multiBernoulliPointEstimate({ components: [{ existence: 0.9, density: g2 }], radius: 1, costs: { c00: 0, c01: 1, c10: 1, c11: 0, c: 1 } }).reported;
const loss: number[] = fisst.bernoulliLossCurve({ existences: [0.1, 0.9], missProbability: 0.2, costs: 'mpe' }).rule;
const v: string = fisst.version();

// @ts-expect-error: a misspelt option ('aplha') is not in GospaOptions
fisst.gospa(truth, truth, { c: 1, aplha: 1 });
// @ts-expect-error: a Region has exactly one of box, polygon, disc
const badRegion: fisst.Region = { circle: { center: [0, 0], radius: 1 } };
// @ts-expect-error: 'hausdorff' is not a SetMetricName
fisst.mbOptimalEstimate({ existence: [0.4], metric: 'hausdorff' });
// @ts-expect-error: the cut-off c is required
fisst.gospa(truth, truth, { p: 2 });

export const used = [distance, missed, pairs, parts, pmf, mse, la, u, loo, alt, map, counts, fc, poisson, vmap, scene, dens, lib, exact, reduced, fig5, step, at, q, gamma, mmuc, mbp, loss, v, badRegion];

// Bernoulli filters (issue 12).
const airport: fisst.AirportScenarioResult = fisst.airportScenario({ seed: 1, steps: 3 });
const predicted: fisst.GmBernoulliResult = fisst.gmBernoulliPredict({
  existence: 0.5,
  mixture: airport.config.mixture,
  transition: airport.config.transition,
});
const updated: fisst.GmBernoulliUpdateResult = fisst.gmBernoulliUpdate({
  existence: predicted.existence,
  mixture: predicted.mixture,
  detection: { probability: 0.9, fov: airport.fov },
  reports: [{ disc: { center: [20, 8], radius: 19 } }],
  clutter: { rate: 0.25, density: 0.1 },
});
const delta: number = updated.delta;
const gmFilter = new fisst.GmBernoulliFilter(airport.config);
gmFilter.predict();
gmFilter.update([{ union: [{ disc: { center: [0, 0], radius: 1 } }] }]);
const filterEstimate: fisst.FilterEstimateResult = gmFilter.estimate({ radius: 5, costs: 'mpe' });
const existenceNow: number = gmFilter.existence;
gmFilter.free();
const pfFilter = new fisst.ParticleBernoulliFilter({ ...airport.config, particles: 100 });
pfFilter.update({ measurements: [] });
const cloud: number[][] = pfFilter.particles;
pfFilter.predict();
const info: { delta: number; splitComponents: number } = pfFilter.update([]);
const pfEstimate: fisst.FilterEstimateResult = pfFilter.estimate();
const pfWeights: Float64Array = pfFilter.weights;
const pfSeed: number = pfFilter.seed;
pfFilter.free();
const gmMixture: fisst.MixtureComponent[] = new fisst.GmBernoulliFilter(airport.config).mixture;
const truthNow: [number, number, number, number] = airport.truth[0].state;
const missedSteps: (number | null)[] = airport.trueReports;
export const usedFilters = [delta, filterEstimate, existenceNow, cloud, info, pfEstimate, pfWeights, pfSeed, gmMixture, truthNow, missedSteps];
// @ts-expect-error: a misspelt option ('existance') is not in GmBernoulliPredictOptions
fisst.gmBernoulliPredict({ existance: 0.5, mixture: [], transition: airport.config.transition });
const mol: fisst.MultiObjectLikelihoodResult = fisst.multiObjectLikelihood({
  likelihoods: [[0.2, 0.01]],
  detectionProbability: 0.95,
  clutterRate: 0.8,
  clutterDensity: [1 / 1414, 1 / 1414],
});
const logLik: number = mol.logLikelihood;
const controlRun = new fisst.SensorControlRun({ seed: 1, scheme: 'renyi', particles: 20, futureScans: 4, alpha: 0.5, steps: 2 });
const stepOut: fisst.ControlStep = controlRun.step();
const nextPosition: [number, number] = stepOut.action.position;
const rewards17: number[] = stepOut.rewards;
const ospaNow: number = stepOut.ospa.localisation + stepOut.estimate.cardinality;
const controlParticles: fisst.ControlParticles = controlRun.particles;
const path: [number, number][] = controlRun.sensorPath;
const truth2: [number, number][] = controlRun.truth;
const scans: number[][] = controlRun.measurements;
controlRun.free();
const fig3: fisst.CompareSchemesResult = fisst.compareSchemes({
  runs: 1,
  steps: 1,
  seed: 2,
  schemes: ['pent', 'random'],
  particles: 10,
  futureScans: 2,
  onProgress: (done: number, total: number) => void (done + total),
});
const fig3Mean: number[] = fig3.schemes[0].distance.standardError;
// @ts-expect-error: a misspelt option ('futureScan') is not in SensorControlRunOptions
new fisst.SensorControlRun({ scheme: 'renyi', futureScan: 3 });

// Paper 002: error bounds for joint detection and estimation.
const nc: fisst.JdeBoundNoClutterResult = fisst.jdeBoundNoClutter({ existence: 0.7, detectionProbability: 0.4, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 });
const declares: boolean = nc.declareOnEmpty && nc.existenceThreshold > 0 && nc.mapBound >= nc.bound;
const fi: fisst.GaussianFisherInformationResult = fisst.gaussianFisherInformation({ priorVariance: 100, gain: 1, noiseVariance: 100 / 3 });
const seq: number[] = fisst.jdeSequentialBound({ method: 'enumeration', priorInformation: 1 / fi.information, detectedInformation: fi.information, detectionProbability: 0.5, steps: 10 }).bound;
const tablePrior: fisst.DensityShape = { table: { x: [0, 1, 2], density: [0, 1, 0] } };
const jb: fisst.JdeBoundResult = fisst.jdeBound({
  model: 'I',
  existence: 0.6,
  prior: { gaussian: { mean: 0, variance: 4 } },
  observation: { detectionProbability: { table: { x: [-3, 3], probability: [0.5, 0.9] } }, gain: 1, noiseVariance: 1 },
  falseAlarm: { probability: 0.2, density: { uniform: { low: -10, high: 10 } } },
  falseAlarmError: 6,
  missError: 9,
});
const phase: 'HPE' | 'LPE' = jb.phase;
const termNames: string[] = jb.terms.map((t) => t.name);
const jb2: fisst.JdeBoundResult = fisst.jdeBound({ model: 'II', existence: 0.6, prior: tablePrior, observation: { detectionProbability: 0.9, noiseVariance: 0.5 }, clutter: { rate: 1, density: { mixture: [{ weight: 1, mean: 0, variance: 25 }] } }, falseAlarmError: 6, missError: 9, samples: 500, seed: 1 });
const perN: number[] = jb2.cardinalities.map((c) => c.inverseInformation);
// a state in R^2: a multivariateGaussian prior, gain rows H and noiseCov; per-coordinate bounds
const jbv: fisst.JdeBoundResult = fisst.jdeBound({
  model: 'I',
  existence: 0.6,
  prior: { multivariateGaussian: { mean: [0.5, -1], cov: [[4, 1.2], [1.2, 2]] } },
  observation: { detectionProbability: 0.8, gain: [[1, 0.5]], offset: [0.2], noiseCov: [[1]] },
  falseAlarm: { probability: 0.3, density: { gaussian: { mean: 1, variance: 25 } } },
  falseAlarmError: 6,
  missError: 8,
  dims: 2,
});
const perCoordinate: number[] = (jbv.components ?? []).map((c: fisst.JdeComponentBound) => c.bound);
const coordinatePhases: ('HPE' | 'LPE')[] = (jbv.components ?? []).map((c) => c.phase);
const posteriorCov: number[][] | undefined = jbv.inverseInformationMatrix;
const vectorPrior: fisst.PriorShape = { multivariateGaussian: { mean: new Float64Array([0, 0]), cov: [1, 0, 0, 1] } };
const twoRows: fisst.ObservationShape = { detectionProbability: 0.9, gain: [[1, 0], [0, 1]], noiseCov: [[1, 0], [0, 1]] };
const jbq: fisst.JdeBoundResult = fisst.jdeBound({ model: 'II', existence: 0.6, prior: vectorPrior, observation: twoRows, falseAlarmError: 6, missError: 9, quadratureCardinality: 2 });
// @ts-expect-error: quadratureCardinality is 1 or 2
fisst.jdeBound({ model: 'II', existence: 0.6, prior: vectorPrior, observation: twoRows, falseAlarmError: 6, missError: 9, quadratureCardinality: 3 });
// @ts-expect-error: a multivariateGaussian is a prior, not a false-alarm density
fisst.jdeBound({ model: 'I', existence: 0.6, prior: vectorPrior, observation: twoRows, falseAlarm: { probability: 0.1, density: vectorPrior }, falseAlarmError: 6, missError: 9 });
// @ts-expect-error: a misspelt option ('existance') is not in JdeBoundNoClutterOptions
fisst.jdeBoundNoClutter({ existance: 0.7, detectionProbability: 0.4, priorVariance: 100, posteriorVariance: 25, falseAlarmError: 150, missError: 200 });
const ex2: fisst.JdeExample2Result = fisst.jdeExample2({ existence: 0.6, detectionProbability: 0.5, falseAlarmProbability: 0.3, falseAlarmError: 1.2 });
const ex2Curves: [number, number] = [ex2.bound, ex2.paperBound];
const ex2Reg: fisst.JdeExample2RegularityResult = fisst.jdeExample2Regularity();
const notABound: boolean = ex2Reg.inverseInformation > ex2Reg.posteriorMeanMse;

// Issue 26, point 3: optional where JS takes none, string unions for enumerated strings.
const defaultAirport: fisst.AirportScenarioResult = fisst.airportScenario();
const schemeName: 'renyi' | 'fisher' | 'pent' | 'random' = new fisst.SensorControlRun({ scheme: 'random', futureScans: 1 }).scheme;
const boundTermNames: ('estimation' | 'undetected' | 'missed' | 'falseTarget')[] = jbq.terms.map((t) => t.name);
// @ts-expect-error: FovGaussian (a deprecated alias) was removed; use Gaussian
const removedAlias: fisst.FovGaussian | undefined = undefined;
export { defaultAirport, schemeName, boundTermNames, removedAlias };

// Issue 26, point 3: a field present for the given options is typed present (no `!`), and
// options that go together are typed together.
const gDecomposed: fisst.GospaDecomposedResult = fisst.gospa(truth, [[0, 1]], { c: 2 });
const missedNow: number = fisst.gospa(truth, [[0, 1]], { c: 2, alpha: 2 }).missed;
const pairsNow: [number, number][] = fisst.gospa(truth, [[0, 1]], { c: 2, p: 1 }).assignment;
const gospaAny: fisst.GospaResult = fisst.gospa(truth, [[0, 1]], { c: 2, alpha: 1 });
// @ts-expect-error: with α ≠ 2 the decomposition is absent
const missedAlpha1: number = fisst.gospa(truth, [[0, 1]], { c: 2, alpha: 1 }).missed;
const seriesNow: fisst.GospaSeriesDecomposedResult = fisst.gospaSeries({ truths: [truth], estimates: [truth], c: 2 });
const meanMissedNow: number = seriesNow.meanMissed + seriesNow.localisation[0] + seriesNow.falseTargets[0];
// @ts-expect-error: with α ≠ 2 the series has no decomposition
const seriesMissed: number[] = fisst.gospaSeries({ truths: [truth], estimates: [truth], c: 2, alpha: 0.5 }).missed;
const oneStep: fisst.NegativeInformationStep = fisst.negativeInformationScenario({ step: 1 });
const wholeFig5: fisst.NegativeInformationScenario = fisst.negativeInformationScenario();
// @ts-expect-error: with `step` the result is one step, not the scenario
const notWhole: fisst.NegativeInformationScenario = fisst.negativeInformationScenario({ step: 3 });
const vectorBound: fisst.JdeVectorBoundResult = fisst.jdeBound({
  model: 'I',
  existence: 0.6,
  prior: { multivariateGaussian: { mean: [0, 0], cov: [[1, 0], [0, 1]] } },
  observation: twoRows,
  falseAlarmError: 6,
  missError: 8,
});
const perCoordinateNow: number[] = vectorBound.components.map((c) => c.bound);
const posteriorNow: number[][] = vectorBound.inverseInformationMatrix;
// @ts-expect-error: a scalar prior has no per-coordinate bounds
const scalarComponents: fisst.JdeComponentBound[] = fisst.jdeBound({ model: 'I', existence: 0.6, prior: tablePrior, observation: { detectionProbability: 0.9, noiseVariance: 0.5 }, falseAlarmError: 6, missError: 9 }).components;
const gm2 = new fisst.GmBernoulliFilter(airport.config);
const reportNow: fisst.BernoulliEstimateResult = gm2.estimate({ radius: 5, costs: 'mpe' }).report;
const noReport: null = gm2.estimate().report;
const noReportEmpty: null = gm2.estimate({}).report;
// @ts-expect-error: radius without costs (it throws "options.costs is required with options.radius")
gm2.estimate({ radius: 5 });
// @ts-expect-error: costs without radius
gm2.estimate({ costs: 'mpe' });
gm2.free();
const pf2 = new fisst.ParticleBernoulliFilter({ ...airport.config, particles: 10 });
const pfReport: fisst.BernoulliEstimateResult = pf2.estimate({ radius: 5, costs: { mmol: { asset: 10, countermeasure: 1 } } }).report;
// @ts-expect-error: radius without costs
pf2.estimate({ radius: 5 });
pf2.free();
export { gDecomposed, missedNow, pairsNow, gospaAny, missedAlpha1, meanMissedNow, seriesMissed, oneStep, wholeFig5, notWhole, perCoordinateNow, posteriorNow, scalarComponents, reportNow, noReport, noReportEmpty, pfReport };
// @ts-expect-error: clutter is model II's (it throws a TypeError with model 'I')
fisst.jdeBound({ model: 'I', existence: 0.6, prior: tablePrior, observation: { detectionProbability: 0.9, noiseVariance: 0.5 }, clutter: { rate: 1, density: { uniform: { low: -1, high: 1 } } }, falseAlarmError: 6, missError: 9 });
// @ts-expect-error: falseAlarm is model I's
fisst.jdeBound({ model: 'II', existence: 0.6, prior: tablePrior, observation: { detectionProbability: 0.9, noiseVariance: 0.5 }, falseAlarm: { probability: 0.1, density: { uniform: { low: -1, high: 1 } } }, falseAlarmError: 6, missError: 9 });
const mc: fisst.JdeMonteCarloResult = fisst.jdeMonteCarlo({ model: 'II', existence: 0.6, prior: { gaussian: { mean: 0, variance: 4 } }, observation: { detectionProbability: 0.9, noiseVariance: 1 }, clutter: { rate: 1, density: { uniform: { low: -10, high: 10 } } }, falseAlarmError: 6, missError: 9, samples: 100, seed: 1 });
// @ts-expect-error: falseAlarm is model I's
fisst.jdeMonteCarlo({ model: 'II', existence: 0.6, prior: { gaussian: { mean: 0, variance: 4 } }, observation: { detectionProbability: 0.9, noiseVariance: 1 }, falseAlarm: { probability: 0.1, density: { uniform: { low: -1, high: 1 } } }, falseAlarmError: 6, missError: 9 });
export { mc };

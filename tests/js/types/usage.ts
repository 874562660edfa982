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

// @ts-expect-error: 'hausdorff' is not a SetMetricName
fisst.mbOptimalEstimate({ existence: [0.4], metric: 'hausdorff' });
// @ts-expect-error: the cut-off c is required
fisst.gospa(truth, truth, { p: 2 });

export const used = [distance, missed, pairs, parts, pmf, mse];

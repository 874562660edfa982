// Compiled with usage.ts by types.test.mjs: the parts of the package (`fisst/<part>`) carry
// their own declarations, and the whole package's `init` takes options per part.
import init, * as fisst from 'fisst';
import initMetrics, { gospa, type GospaResult } from 'fisst/metrics';
import { GmBernoulliFilter } from 'fisst/filters';
import { jdeBoundNoClutter } from 'fisst/bounds';

const loaded: fisst.InitOutput = await init({ metrics: { module_or_path: './pkg/metrics_bg.wasm' } });
const memory: WebAssembly.Memory = loaded.control.memory;
// With the DOM types loaded, the platform types are the real ones (not `never`).
type IsNever<T> = [T] extends [never] ? true : false;
const memoryTyped: IsNever<fisst.InitOutput['control']['memory']> = false;
const inputTyped: IsNever<Extract<Parameters<typeof initMetrics>[0], Response>> = false;
await initMetrics();
const partNames: readonly fisst.PartName[] = fisst.parts;

const g: GospaResult = gospa([[0, 0]], [[0, 1]], { c: 2 });
const same: fisst.GospaResult = g;
const filter: typeof GmBernoulliFilter = fisst.GmBernoulliFilter;
const r: number = jdeBoundNoClutter({
  existence: 0.5,
  detectionProbability: 0.9,
  priorVariance: 1,
  posteriorVariance: 0.1,
  falseAlarmError: 1,
  missError: 1,
}).bound;

// @ts-expect-error: `metrcs` names no part
await init({ metrcs: {} });

export { memoryTyped, inputTyped, memory, partNames, same, filter, r };

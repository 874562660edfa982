// The control page's long work, off the main thread (a module worker: it does not see the
// page's import map, so it imports the package by path and initialises it itself).
//
// Messages in (an `id`, when given, is echoed in the replies: the page drops stale ones):
//   { type: 'start', options }   a new SensorControlRun(options) (the previous one is freed)
//   { type: 'step' }             one step of it: Algorithm 1, lines 5–13 (paper 004)
//   { type: 'compare', options } compareSchemes run by run (options.runs of them), so that the
//                                page can draw Fig. 3 as the runs accumulate
// Messages out:
//   { type: 'ready' }
//   { type: 'started', truth, sensorPath }
//   { type: 'step', result, particles (point sets), sensorPath, truth, ms }
//   { type: 'progress', done, total }                      (from compareSchemes' onProgress)
//   { type: 'compare', runs, total, stats, ms }            (the statistics of the runs so far)
//   { type: 'error', during, name, message }
import init, * as fisst from './pkg/control.js';

let run = null;
const ready = init();

/** Sums of one series over the runs: n, Σx and Σx² per time step (to pool chunks exactly). */
const emptySums = (length) => ({ n: 0, sum: new Array(length).fill(0), squares: new Array(length).fill(0) });

/**
 * Adds a chunk's mean and standard error (over its n runs, sample variance) to `sums`:
 * Σx = n·mean, Σx² = (n − 1)·n·se² + n·mean² (se is null or 0 for n = 1).
 */
function addChunk(sums, { mean, standardError }, n) {
  for (let t = 0; t < mean.length; t++) {
    const se = standardError?.[t] ?? 0;
    sums.sum[t] += n * mean[t];
    sums.squares[t] += (n - 1) * n * (Number.isFinite(se) ? se * se : 0) + n * mean[t] * mean[t];
  }
  sums.n += n;
}

/** Mean and standard error (√(s²/n), s² the sample variance; null for one run) of the sums. */
function summary({ n, sum, squares }) {
  const mean = sum.map((s) => s / n);
  const standardError = squares.map((q, t) => {
    if (n < 2) return null;
    const variance = Math.max((q - n * mean[t] * mean[t]) / (n - 1), 0);
    return Math.sqrt(variance / n);
  });
  return { mean, standardError };
}

/** The flat `run.particles` ({ cardinalities, positions }, JS_SHAPES.md) as point sets. */
function pointSets({ cardinalities, positions }) {
  let o = 0;
  return cardinalities.map((n) => Array.from({ length: n }, () => [positions[2 * o], positions[2 * o++ + 1]]));
}

const PARTS = ['distance', 'localisation', 'cardinality'];

async function compare({ runs, seed, ...options }) {
  const total = runs;
  const sums = {};
  const t0 = performance.now();
  for (let r = 0; r < runs; r++) {
    // Run r of the page's comparison is a one-run compareSchemes call with seed + r (every
    // scheme sees the same run seed), pooled here exactly: the page draws the means as the
    // runs come in, and a Node call per run gives the same numbers.
    const out = fisst.compareSchemes({
      ...options,
      runs: 1,
      seed: seed + r,
      onProgress: (done, all) => postMessage({ type: 'progress', done: r + done / all, total }),
    });
    for (const s of out.schemes) {
      sums[s.scheme] ??= Object.fromEntries(PARTS.map((p) => [p, emptySums(s[p].mean.length)]));
      for (const p of PARTS) addChunk(sums[s.scheme][p], s[p], 1);
    }
    const stats = Object.fromEntries(Object.entries(sums).map(([scheme, parts]) => [scheme, Object.fromEntries(PARTS.map((p) => [p, summary(parts[p])]))]));
    postMessage({ type: 'compare', runs: r + 1, total, stats, ms: performance.now() - t0 });
    await new Promise((resolve) => setTimeout(resolve, 0)); // let a new message in
  }
}

onmessage = async ({ data }) => {
  await ready;
  try {
    if (data.type === 'start') {
      run?.free();
      run = null;
      run = new fisst.SensorControlRun(data.options);
      postMessage({ type: 'started', id: data.id, truth: run.truth, sensorPath: run.sensorPath });
    } else if (data.type === 'step') {
      const t0 = performance.now();
      const result = run.step();
      const ms = performance.now() - t0;
      postMessage({ type: 'step', id: data.id, result, particles: pointSets(run.particles), sensorPath: run.sensorPath, truth: run.truth, ms });
    } else if (data.type === 'compare') {
      await compare(data.options);
    }
  } catch (e) {
    postMessage({ type: 'error', id: data.id, during: data.type, name: e?.name ?? 'Error', message: e?.message ?? String(e) });
  }
};

ready.then(() => postMessage({ type: 'ready' }), (e) => postMessage({ type: 'error', during: 'init', name: e.name, message: e.message }));

// The Monte Carlo of web/bounds.html, off the main thread (a module worker): the optimal
// joint detector-estimators of paper 002 simulated by web/bounds-mc.js, one grid point at a
// time. A job is { id, kind, params }; the worker answers { id, kind, progress } after each
// point and { id, kind, result } at the end, and drops a job as soon as a newer one of the
// same kind arrives (a slider drag sends many). Fig. 2 right's curves (jdeExample2, about
// 10 ms a point) are computed here too: a worker does not see the page's import map, so it
// imports the package by path and initialises it itself.
import init, * as fisst from './pkg/bounds.js';
import { example2Prior, mcExample2, mcGaussian, mcSequential } from './bounds-mc.js';

const ready = init();

const latest = {};
const pause = () => new Promise((resolve) => setTimeout(resolve, 0));

const JOBS = {
  /** Fig. 2 left: the optimal and the MAP-on-∅ estimator over r, for one P̄o. */
  * fig2left({ rs, detectionProbability, priorVariance, noiseVariance, gain, falseAlarmError, missError, samples, seed }) {
    for (const [i, r] of rs.entries()) {
      const base = { existence: r, prior: { mean: 0, variance: priorVariance }, gain, noiseVariance, detectionProbability, falseAlarmError, missError, samples };
      yield { r, optimal: mcGaussian({ ...base, seed: seed + 2 * i }), map: mcGaussian({ ...base, rule: 'map', seed: seed + 2 * i + 1 }) };
    }
  },
  /** Fig. 3: the posterior mean after k = 1 … steps scans (r = 1). */
  * fig3(params) {
    yield mcSequential(params);
  },
  /** Theorems 1 and 2 over r: jdeBound (model I with q, model II with λ) and the Monte Carlo. */
  * theorems({ rs, system, falseAlarm, clutter, samples, seed }) {
    const { prior, observation } = system;
    const jb = { prior: { gaussian: prior }, observation, falseAlarmError: system.falseAlarmError, missError: system.missError };
    const mc = { prior, gain: observation.gain, offset: observation.offset, noiseVariance: observation.noiseVariance, detectionProbability: observation.detectionProbability, falseAlarmError: system.falseAlarmError, missError: system.missError, samples };
    for (const [i, r] of rs.entries()) {
      const one = fisst.jdeBound({ ...jb, model: 'I', existence: r, falseAlarm: { probability: falseAlarm.probability, density: { gaussian: { mean: falseAlarm.mean, variance: falseAlarm.variance } } } });
      const two = fisst.jdeBound({ ...jb, model: 'II', existence: r, clutter: { rate: clutter.rate, density: { gaussian: { mean: clutter.mean, variance: clutter.variance } } }, samples: 2000, seed: seed + i });
      yield {
        r, model1: { bound: one.bound, error: one.error, phase: one.phase }, model2: { bound: two.bound, error: two.error, phase: two.phase },
        mc1: mcGaussian({ ...mc, existence: r, falseAlarm, seed: seed + 2 * i }), mc2: mcGaussian({ ...mc, existence: r, clutter, seed: seed + 2 * i + 1 }),
      };
    }
  },
  /** Fig. 2 right: Example 2 over q for each P_o — jdeExample2's curves, then the Monte Carlo. */
  * example2({ qs, mcEvery, detectionProbabilities, existence, falseAlarmError, samples, seed }) {
    for (const P of detectionProbabilities) {
      yield qs.map((q) => fisst.jdeExample2({ existence, detectionProbability: P, falseAlarmProbability: q, falseAlarmError }));
    }
    const missError = falseAlarmError + example2Prior.variance;
    // The reference point of NOTES.md: r = 1, P_o = 1 (the MMSE, 0.0340, against 1/J_1).
    yield mcExample2({ existence: 1, detectionProbability: 1, falseAlarmProbability: 0, falseAlarmError, missError, samples: 4 * samples, seed: seed + 999_999 });
    for (const [j, P] of detectionProbabilities.entries()) {
      for (const [i, q] of qs.entries()) {
        if (i % mcEvery === 0) yield { P, q, ...mcExample2({ existence, detectionProbability: P, falseAlarmProbability: q, falseAlarmError, missError, samples, seed: seed + 1000 * j + i }) };
      }
    }
  },
};

async function run({ id, kind, params }) {
  await ready;
  const out = [];
  const n = params.detectionProbabilities?.length;
  const total = { fig2left: params.rs?.length, theorems: params.rs?.length, fig3: 1, example2: n * (1 + Math.ceil(params.qs?.length / params.mcEvery)) + 1 }[kind];
  for (const point of JOBS[kind](params)) {
    out.push(point);
    postMessage({ id, kind, progress: out.length / total });
    await pause(); // let a newer job in
    if (latest[kind] !== id) return;
  }
  const result = { fig2left: out, theorems: out, fig3: out[0], example2: { curves: out.slice(0, n), reference: out[n], points: out.slice(n + 1) } }[kind];
  postMessage({ id, kind, result });
}

onmessage = (e) => {
  latest[e.data.kind] = e.data.id;
  run(e.data);
};

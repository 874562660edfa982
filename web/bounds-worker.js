// The Monte Carlo of web/bounds.html, off the main thread (a module worker): the optimal
// joint detector-estimators of paper 002 simulated by the package's jdeMonteCarlo (the core's
// seeded bounds::jde_monte_carlo), one grid point at a time. A job is { id, kind, params }; the
// worker answers { id, kind, progress } after each point and { id, kind, result } at the end,
// and drops a job as soon as a newer one of the same kind arrives (a slider drag sends many).
// Fig. 2 right's curves (jdeExample2, about 10 ms a point) are computed here too: a worker does
// not see the page's import map, so it imports the package by path and initialises it itself.
import init, * as fisst from './pkg/bounds.js';

const ready = init();

const latest = {};
const pause = () => new Promise((resolve) => setTimeout(resolve, 0));

/** jdeMonteCarlo's risk as the page draws it: { mse, se, samples, declareOnEmpty }. */
function simulate(options) {
  const { mse, se, samples, declareOnEmpty } = fisst.jdeMonteCarlo(options);
  return { mse, se, samples, declareOnEmpty };
}

const JOBS = {
  /** Fig. 2 left: the optimal and the MAP-on-∅ estimator over r, for one P̄o. */
  * fig2left({ rs, detectionProbability, priorVariance, noiseVariance, gain, falseAlarmError, missError, samples, seed }) {
    for (const [i, r] of rs.entries()) {
      const base = { model: 'I', existence: r, prior: { gaussian: { mean: 0, variance: priorVariance } }, observation: { detectionProbability, gain, noiseVariance }, falseAlarmError, missError, samples };
      yield { r, optimal: simulate({ ...base, seed: seed + 2 * i }), map: simulate({ ...base, emptyRule: 'map', seed: seed + 2 * i + 1 }) };
    }
  },
  /** Fig. 3: the posterior mean after k = 1 … steps scans (r = 1): x ~ N(0, 1/J0), each
   * measurement of information J1 − J0 (none when J1 = J0), x* = 0 when nothing is seen. */
  * fig3({ priorInformation: j0, detectedInformation: j1, detectionProbability, steps, samples, seed }) {
    const dj = j1 - j0;
    const out = fisst.jdeMonteCarlo({
      model: 'I', existence: 1, prior: { gaussian: { mean: 0, variance: 1 / j0 } },
      observation: { detectionProbability, gain: dj > 0 ? 1 : 0, noiseVariance: dj > 0 ? 1 / dj : 1 },
      falseAlarmError: 0, missError: 0, emptyRule: 'declare', scans: steps, samples, seed,
    });
    yield { mse: out.scans.map((s) => s.mse), se: out.scans.map((s) => s.se) };
  },
  /** Theorems 1 and 2 over r: jdeBound (model I with q, model II with λ) and the Monte Carlo. */
  * theorems({ rs, system, falseAlarm, clutter, samples, seed }) {
    const { prior, observation } = system;
    const jb = { prior: { gaussian: prior }, observation, falseAlarmError: system.falseAlarmError, missError: system.missError };
    const one = (r) => ({ ...jb, model: 'I', existence: r, falseAlarm: { probability: falseAlarm.probability, density: { gaussian: { mean: falseAlarm.mean, variance: falseAlarm.variance } } } });
    const two = (r) => ({ ...jb, model: 'II', existence: r, clutter: { rate: clutter.rate, density: { gaussian: { mean: clutter.mean, variance: clutter.variance } } } });
    for (const [i, r] of rs.entries()) {
      const b1 = fisst.jdeBound(one(r));
      const b2 = fisst.jdeBound({ ...two(r), samples: 2000, seed: seed + i });
      yield {
        r, model1: { bound: b1.bound, error: b1.error, phase: b1.phase }, model2: { bound: b2.bound, error: b2.error, phase: b2.phase },
        mc1: simulate({ ...one(r), samples, seed: seed + 2 * i }), mc2: simulate({ ...two(r), samples, seed: seed + 2 * i + 1 }),
      };
    }
  },
  /** Fig. 2 right: Example 2 over q for each P_o — jdeExample2's curves, then the Monte Carlo. */
  * example2({ qs, mcEvery, detectionProbabilities, existence, falseAlarmError, samples, seed }) {
    for (const P of detectionProbabilities) {
      yield qs.map((q) => fisst.jdeExample2({ existence, detectionProbability: P, falseAlarmProbability: q, falseAlarmError }));
    }
    const missError = falseAlarmError + fisst.jdeExample2Regularity().priorVariance;
    const mc = (r, P, q, n, s) => simulate({
      model: 'I', existence: r, prior: 'example2', observation: { detectionProbability: P },
      falseAlarm: { probability: q, density: { uniform: { low: 0, high: 1 } } }, falseAlarmError, missError, samples: n, seed: s,
    });
    // The reference point of NOTES.md: r = 1, P_o = 1 (the MMSE, 0.0340, against 1/J_1).
    yield mc(1, 1, 0, 4 * samples, seed + 999_999);
    for (const [j, P] of detectionProbabilities.entries()) {
      for (const [i, q] of qs.entries()) {
        if (i % mcEvery === 0) yield { P, q, ...mc(existence, P, q, samples, seed + 1000 * j + i) };
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

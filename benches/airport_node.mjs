// Times the npm package's two Bernoulli filter classes on the airport example of `001_…`
// Section V-C in Node: the whole 60-step run of GmBernoulliFilter and of
// ParticleBernoulliFilter (5,000 particles, one MCMC move: the paper's settings) on the
// same reports of airportScenario({ seed, steps: 60 }), after a warm-up run of each.
//   node benches/airport_node.mjs [seed] [reps]   →  median ms per run, GM and PF, and PF/GM
// (build the package first: scripts/build-pkg.sh).
import * as fisst from '../wasm/pkg/node.js';

const seed = Number(process.argv[2] ?? 1);
const reps = Number(process.argv[3] ?? 11);
const steps = 60;
const s = fisst.airportScenario({ seed, steps });
const reports = s.reports.map((scan) =>
  scan.map((a) => ({ disc: { center: s.anchors[a].position, radius: s.anchors[a].radius } })));

function run(make) {
  const f = make();
  try {
    let e;
    for (let k = 0; k < steps; k++) {
      f.predict();
      f.update(reports[k]);
      e = f.estimate();
    }
    return e;
  } finally {
    f.free();
  }
}

function median(f) {
  f(); // warm-up
  const times = [];
  for (let i = 0; i < reps; i++) {
    const t0 = process.hrtime.bigint();
    f();
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(reps / 2)];
}

const gm = median(() => run(() => new fisst.GmBernoulliFilter(s.config)));
const pf = median(() => run(() => new fisst.ParticleBernoulliFilter({
  ...s.config, particles: 5000, mcmcMoves: 1, seed: seed + 1000,
})));
console.log(`airport ${steps} steps, seed ${seed}, Node, median of ${reps}: GM ${gm.toFixed(1)} ms, `
  + `PF 5000 + MCMC ${pf.toFixed(1)} ms, PF/GM ${(pf / gm).toFixed(1)}×`);

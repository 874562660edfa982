// Times the npm package's two Bernoulli filter classes on the airport example of `001_…`
// Section V-C in Node: the whole 60-step run of GmBernoulliFilter and of
// ParticleBernoulliFilter (5,000 particles, one MCMC move: the paper's settings) on the
// same reports of airportScenario({ seed, steps: 60 }), after a warm-up run of each.
//   node benches/airport_node.mjs [seed] [reps]   →  median ms per run, GM and PF, and PF/GM
//   node benches/airport_node.mjs first [firstSeed=1] [lastSeed=10]
//     →  the first run in a fresh process (what a page or a script meets: the module's
//        compilation and the engine's first tier included), each filter in its own process
//        (`node benches/airport_node.mjs once SEED gm|pf` prints one such time)
// (build the package first: scripts/build-pkg.sh).
//
// Measured (stop 40, Node 20, load average 2.9–3.5 from two builds): `first 1 10`: GM 101–234 ms,
// PF 287–400 ms, PF/GM 1.3–3.0× (loading the module and the scenario 25–53 ms before it); the
// same process's later runs of the GM filter take 40–60 ms. The first run is V8's: each wasm
// function is compiled on first call by the baseline compiler (Liftoff) and runs that slower code
// until the optimising tier has caught up (steps 1, 5 and 9 of seed 3 take 9–17 ms once, 0.4 ms
// after). Seed 3's GM, load then run: default 36 + 177 ms; `--no-wasm-lazy-compilation` 69–87 +
// 112–144 ms; with `--no-liftoff` too 1,770–1,816 + 25 ms (everything optimised before the run).
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const mode = process.argv[2];
if (mode === 'first') {
  const [first, last] = [Number(process.argv[3] ?? 1), Number(process.argv[4] ?? 10)];
  const once = (seed, which) => execFileSync(process.execPath,
    [fileURLToPath(import.meta.url), 'once', String(seed), which], { encoding: 'utf8' })
    .trim().split(' ').map(Number);
  const [ratios, loads] = [[], []];
  for (let seed = first; seed <= last; seed++) {
    const [[loadGm, gm], [loadPf, pf]] = [once(seed, 'gm'), once(seed, 'pf')];
    ratios.push(pf / gm);
    loads.push(loadGm, loadPf);
    console.log(`seed ${String(seed).padStart(2)}: first run in a fresh process GM ${gm.toFixed(1)} ms, `
      + `PF ${pf.toFixed(1)} ms, PF/GM ${(pf / gm).toFixed(1)}× (loading the module and the `
      + `scenario before it: ${loadGm.toFixed(0)}, ${loadPf.toFixed(0)} ms)`);
  }
  console.log(`PF/GM of first runs ${Math.min(...ratios).toFixed(1)}–${Math.max(...ratios).toFixed(1)}×; `
    + `loading ${Math.min(...loads).toFixed(0)}–${Math.max(...loads).toFixed(0)} ms`);
  process.exit(0);
}
const t0 = process.hrtime.bigint();
const fisst = await import('../wasm/pkg/node.js');
const seed = Number(process.argv[mode === 'once' ? 3 : 2] ?? 1);
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

const makeGm = () => new fisst.GmBernoulliFilter(s.config);
const makePf = () => new fisst.ParticleBernoulliFilter({
  ...s.config, particles: 5000, mcmcMoves: 1, seed: seed + 1000,
});
if (mode === 'once') {
  // Printed: the module's loading (import, compilation, the scenario) and the first run.
  const t1 = process.hrtime.bigint();
  run(process.argv[4] === 'pf' ? makePf : makeGm);
  const ms = (a, b) => (Number(b - a) / 1e6).toFixed(3);
  console.log(`${ms(t0, t1)} ${ms(t1, process.hrtime.bigint())}`);
  process.exit(0);
}
const gm = median(() => run(makeGm));
const pf = median(() => run(makePf));
console.log(`airport ${steps} steps, seed ${seed}, Node, median of ${reps}: GM ${gm.toFixed(1)} ms, `
  + `PF 5000 + MCMC ${pf.toFixed(1)} ms, PF/GM ${(pf / gm).toFixed(1)}×`);

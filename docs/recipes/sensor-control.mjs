// Sensor control: a range-only sensor moves to where it expects to learn most about an unknown
// number of sources. Ristic & Vo, "Sensor control for multi-object state-space estimation using
// random finite sets" (Algorithm 1, the Rényi-divergence reward (8)–(17), the case study of
// Section 5: area [0, 1000]² m, sources at (300, 600) and (750, 250), p_D = 0.95, clutter λ = 0.8).
import * as fisst from 'fisst';

// One run: `scheme` is 'renyi', 'fisher', 'pent' or 'random'; N multi-object particles
// (`particles`), M future scans per reward (`futureScans`), K steps (`steps`). Small N and M keep
// this fast; the paper uses N = 750 (the default), M = 200 and K = 40. Always pass a seed.
const run = new fisst.SensorControlRun({ scheme: 'renyi', seed: 7, steps: 10, particles: 300, futureScans: 50 });
try {
  while (run.k < run.steps) {
    // One step of Algorithm 1: take the ranges Z_k at `sensor`, update, estimate, score, and
    // choose the next move u_k (`action`: ring j = 0 stay, 1 or 2 for 50 or 100 m; heading ℓ·45°).
    // `estimate` is X̂_k: n̂ (`cardinality`, the MAP count) and n̂ points; `ospa` scores it
    // against the truth (c = 100 m, p = 2); `rewards` holds the 17 actions' rewards (−∞ outside the area).
    const s = run.step();
    const move = `ring ${s.action.ring} heading ${s.action.heading}`;
    console.log(`k=${s.k} at (${s.sensor.map((v) => v.toFixed(0))}) |Z|=${s.measurements.length} ${move} n̂=${s.estimate.cardinality} OSPA=${s.ospa.distance.toFixed(1)}`);
    // k=1 at (0,0) |Z|=3 ring 2 heading 1 n̂=3 OSPA=83.7
    // k=2 at (71,71) |Z|=2 ring 2 heading 1 n̂=3 OSPA=88.0
    // k=3 at (141,141) |Z|=4 ring 2 heading 8 n̂=3 OSPA=100.0
    // k=4 at (241,141) |Z|=4 ring 2 heading 2 n̂=2 OSPA=100.0
    // k=5 at (241,241) |Z|=2 ring 2 heading 2 n̂=2 OSPA=94.4
    // k=6 at (241,341) |Z|=4 ring 2 heading 3 n̂=2 OSPA=65.0
    // k=7 at (171,412) |Z|=5 ring 2 heading 2 n̂=2 OSPA=61.2
    // k=8 at (171,512) |Z|=3 ring 2 heading 1 n̂=2 OSPA=39.0
    // k=9 at (241,583) |Z|=2 ring 1 heading 1 n̂=2 OSPA=32.4
    // k=10 at (277,618) |Z|=2 ring 2 heading 7 n̂=2 OSPA=32.8
  }
  // sensorPath: the start and every location moved to (k + 1 points); truth: the true sources.
  console.log(run.sensorPath.length, JSON.stringify(run.truth)); // 11 [[300,600],[750,250]]
  try { run.step(); } catch (e) { console.log(e.name, e.message); } // RangeError step: the run has done all its 10 steps
} finally {
  run.free(); // like the filters, a run lives in wasm memory: free it when done
}

// Fig. 3 in small: several seeded runs of each scheme, OSPA averaged per step with its standard
// error (`distance`, and its `localisation` and `cardinality` parts, each { mean, standardError }
// per step). runSeeds[r] replays run r with `new SensorControlRun({ seed: runSeeds[r], ... })`.
const cmp = fisst.compareSchemes({ runs: 2, steps: 5, seed: 3, particles: 200, futureScans: 50, schemes: ['renyi', 'random'] });
for (const { scheme, distance } of cmp.schemes) {
  console.log(scheme.padEnd(6), distance.mean.map((d) => d.toFixed(1)).join(' '));
  // renyi  92.7 93.5 81.2 75.4 81.3
  // random 92.7 92.7 100.0 92.4 84.9
}

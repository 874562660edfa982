// Sensor control of paper 004 in Node (the npm package, single-threaded wasm), at the paper's
// size (N = 750, M = 200, 17 actions).
//
//   node benches/control_node.mjs [scheme=renyi] [timedSteps=5]
//     one step after 5 warm-up steps of seed 3: compare with the native criterion bench
//     `cargo bench --bench control` (`control_step/<scheme>`);
//   node benches/control_node.mjs table [firstSeed=1] [lastSeed=10] [steps=12]
//     every step a user waits for (issue 29, goal 2): the first `steps` steps of each seed,
//     each timed on its own (the first seed's run is repeated once untimed as the warm-up), the
//     same table as the native `RAYON_NUM_THREADS=1 target/release/control_table` with the same
//     checksum of rewards and actions (FNV-1a over their bits), so the two runs can be compared
//     row by row.
//
// Measured (h-exp, the kernel's own exp, issue 29): seeds 1–10, steps 1–12, load average
// 1.3–1.9, run alternately with the package before it: worst 255–278 ms, mean 80.2–81.4 ms
// (before: worst 277–339 ms, mean 83.4–101 ms); the same checksums as native
// (e74298192fb1b66d, actions d0cbc2f3b0c64a8c). That module was built without simd128, so the
// exp loop stayed scalar in wasm (natively, two SSE2 lanes, the mean is 45 ms: Node 1.8× one
// native thread). Since then every module is built with simd128 (.cargo/config.toml): the same
// checksums, and at load average 2.4–2.8, alternately with the scalar package of the same
// commit: worst 171–187 ms, mean 54.2–55.2 ms (scalar: worst 272–277 ms, mean 83.1–85.6 ms);
// Node/native of the means 1.2×. Since the kernel's exp takes 2^{i/32} from a table (issue 29,
// 2026-12-05; see `benches/src/bin/control_table.rs`): worst 154.6 ms, mean 44.8 ms (minimum of
// three runs; the package before: 175.9, 51.3), checksums eaacc73d9ac9e257 / d0cbc2f3b0c64a8c.
// With the folded subset sum too (c4b4953, idle, minimum of three): worst 142.9 ms, mean 42.5 ms
// (7dc61c3's package, the same runs: 195.6, 61.5), checksums b4bf0a7f0c9297b2 / d0cbc2f3b0c64a8c.
import * as os from 'node:os';
import * as fisst from '../wasm/pkg/node.js';

function fnv(hash, value) {
  const bytes = new Uint8Array(new Float64Array([value]).buffer);
  for (const b of bytes) {
    hash ^= BigInt(b);
    hash = BigInt.asUintN(64, hash * 0x100000001b3n);
  }
  return hash;
}

function fnvInt(hash, n) {
  const bytes = new Uint8Array(new BigUint64Array([BigInt(n)]).buffer);
  for (const b of bytes) {
    hash ^= BigInt(b);
    hash = BigInt.asUintN(64, hash * 0x100000001b3n);
  }
  return hash;
}

function table(first, last, steps) {
  const options = (seed) => ({ seed, scheme: 'renyi', particles: 750, futureScans: 200, steps: 1000 });
  const warm = new fisst.SensorControlRun(options(first));
  for (let k = 0; k < steps; k++) warm.step();
  warm.free();
  let hash = 0xcbf29ce484222325n;
  let actionsHash = hash;
  const all = [];
  console.log('paper 004, Renyi scheme, N = 750, M = 200: ms per step (Node, wasm, one thread)');
  for (let seed = first; seed <= last; seed++) {
    const run = new fisst.SensorControlRun(options(seed));
    const row = [];
    for (let k = 0; k < steps; k++) {
      const t0 = process.hrtime.bigint();
      const out = run.step();
      row.push(Number(process.hrtime.bigint() - t0) / 1e6);
      for (const r of out.rewards) hash = fnv(hash, r);
      hash = fnvInt(hash, out.action.index);
      actionsHash = fnvInt(actionsHash, out.action.index);
    }
    run.free();
    console.log(`seed ${String(seed).padStart(2)}: ${row.map((ms) => ms.toFixed(1).padStart(6)).join(' ')}`);
    all.push(...row);
  }
  const worst = Math.max(...all);
  const mean = all.reduce((a, b) => a + b, 0) / all.length;
  console.log(`worst ${worst.toFixed(1)} ms, mean ${mean.toFixed(1)} ms over ${all.length} steps; load average ${os.loadavg()[0].toFixed(2)}`);
  console.log(`checksum of rewards and actions: ${hash.toString(16).padStart(16, '0')}; of the actions: ${actionsHash.toString(16).padStart(16, '0')}`);
}

if (process.argv[2] === 'table') {
  const arg = (i, d) => Number(process.argv[i] ?? d);
  table(arg(3, 1), arg(4, 10), arg(5, 12));
} else {
  const scheme = process.argv[2] ?? 'renyi';
  const timed = Number(process.argv[3] ?? 5);
  const run = new fisst.SensorControlRun({ seed: 3, scheme, particles: 750, futureScans: 200, steps: 1000 });
  for (let k = 0; k < 5; k++) run.step();
  const times = [];
  for (let k = 0; k < timed; k++) {
    const t0 = process.hrtime.bigint();
    run.step();
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
  run.free();
  times.sort((a, b) => a - b);
  console.log(`${scheme}: median ${times[Math.floor(times.length / 2)].toFixed(1)} ms per step over ${timed} steps (min ${times[0].toFixed(1)} ms)`);
}

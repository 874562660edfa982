// One sensor-control step of paper 004 in Node (the npm package, single-threaded wasm), at the
// paper's size (N = 750, M = 200, 17 actions), after 5 warm-up steps: compare with the native
// criterion bench `cargo bench --bench control` (`control_step/<scheme>`).
//   node benches/control_node.mjs [scheme=renyi] [timedSteps=5]
import * as fisst from '../wasm/pkg/node.js';

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

// Times the npm package's FoV functions in Node (for pmf_vs_scipy.py and map_vs_numpy.py):
//   node fov_node.mjs pmf <in.json> <reps> <out.json>  →  "median_pb median_fov"
//     multiBernoulliCardinality(r) (the convolution behind the FoV pmf (88)), and
//     fovCardinality end to end with one tight Gaussian per r_S centred in a box FoV
//     (⟨1_S, p⟩ = 1, so its pmf is the same Poisson binomial); writes both pmfs.
//   node fov_node.mjs map <in.json> <reps> <out.json>  →  "median"
//     fovVarianceMap of placementScene({ count, seed, extent }); writes the map.
import { readFileSync, writeFileSync } from 'node:fs';
import * as fisst from '../wasm/pkg/node.js';

const [mode, file, repsText, out] = process.argv.slice(2);
const input = JSON.parse(readFileSync(file, 'utf8'));
const reps = Number(repsText);

function medianTime(f) {
  const times = [];
  let result;
  for (let i = 0; i < reps; i++) {
    const t0 = process.hrtime.bigint();
    result = f();
    times.push(Number(process.hrtime.bigint() - t0) / 1e9);
  }
  times.sort((a, b) => a - b);
  return [times[Math.floor(reps / 2)], result];
}

if (mode === 'pmf') {
  const { r } = input;
  const [tPb, pb] = medianTime(() => fisst.multiBernoulliCardinality(r));
  const multiBernoulli = r.map((existence) => ({ existence, mean: [0, 0], cov: [[1e-4, 0], [0, 1e-4]] }));
  const options = { rfs: { multiBernoulli }, fov: { box: { min: [-1, -1], max: [1, 1] } } };
  const [tFov, fov] = medianTime(() => fisst.fovCardinality(options));
  writeFileSync(out, JSON.stringify({ pmf: Array.from(pb), fovPmf: fov.pmf }));
  console.log(`${tPb} ${tFov}`);
} else if (mode === 'map') {
  const { count, seed, extent, side, grid } = input;
  const { multiBernoulli } = fisst.placementScene({ count, seed, extent });
  const options = { multiBernoulli, fovSize: [side, side], grid: { x: grid, y: grid } };
  const [t, map] = medianTime(() => fisst.fovVarianceMap(options));
  writeFileSync(out, JSON.stringify({ variance: Array.from(map.variance), argmax: map.argmax, max: map.max }));
  console.log(`${t}`);
} else {
  throw new Error('mode must be pmf or map');
}

// How many objects are inside a sensor's field of view (FoV), and where to point the sensor:
// LeGrand & Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture
// random finite set filtering" — FoV cardinality pmfs (Props 1–4, eqs 78–92) and sensor
// placement by the variance of that count (Section VII, Figs 9–10).
import * as fisst from 'fisst';

// A multi-Bernoulli: each component is a potential object that exists with probability r
// (`existence`) and then lies at x ~ N(mean, cov). Covariances in 2D are nested rows.
const multiBernoulli = [
  { existence: 0.9, mean: [0, 0], cov: [[0.1, 0], [0, 0.1]] },
  { existence: 0.6, mean: [1, 0], cov: [[0.2, 0.05], [0.05, 0.2]] },
  { existence: 0.4, mean: [3, 3], cov: [[0.1, 0], [0, 0.1]] },
];
const fov = { box: { min: [-1, -1], max: [1.5, 1] } }; // the FoV S: a box, disc, polygon, union…

// pmf[n] = P(n objects in S); mean and variance of that count; massInFov[i] = ⟨1_S, p_i⟩, the
// probability that component i lies in S if it exists. The key is `rfs` (any MultiObjectDensity).
const c = fisst.fovCardinality({ rfs: { multiBernoulli }, fov });
console.log(c.pmf.map((p) => p.toFixed(4)).join(' ')); // 0.0502 0.4933 0.4565 0.0000
console.log(c.mean.toFixed(4), c.variance.toFixed(4)); // 1.4063 0.3416
console.log(c.massInFov.map((m) => m.toFixed(4)).join(' ')); // 0.9977 0.8473 0.0000

// The same intensity as a Poisson RFS (weights = expected counts): same mean, variance = mean.
const poisson = multiBernoulli.map(({ existence, mean, cov }) => ({ weight: existence, mean, cov }));
const p = fisst.fovCardinality({ rfs: { poisson }, fov });
console.log(p.mean.toFixed(4), p.variance.toFixed(4), p.pmf.length); // 1.4063 1.4063 20

// Placement (Fig. 10): a seeded scene of 100 random components in [−3, 3]², and the variance of
// the count in a 1 × 1 FoV centred at every point of a 121 × 121 grid ([min, max, count] axes).
// The most informative place to look is where that count is most uncertain.
const scene = fisst.placementScene({ count: 100, seed: 1 }); // { multiBernoulli: [...] }
const grid = { x: [-3, 3, 121], y: [-3, 3, 121] };
const map = fisst.fovVarianceMap({ multiBernoulli: scene.multiBernoulli, fovSize: [1, 1], grid });
// variance[j * 121 + i] is the variance with the FoV centred at (x_i, y_j); argmax is the best centre.
console.log(map.variance.length, map.argmax.map((v) => v.toFixed(2)), map.max.toFixed(4)); // 14641 [ '-0.30', '-2.00' ] 2.7430

// The pmf there: its variance is the map's maximum.
const [x, y] = map.argmax;
const best = fisst.fovCardinality({ rfs: scene, fov: { box: { min: [x - 0.5, y - 0.5], max: [x + 0.5, y + 0.5] } } });
console.log(best.mean.toFixed(4), best.variance.toFixed(4)); // 4.6415 2.7430

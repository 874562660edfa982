// GOSPA and OSPA over a small tracking scenario: a truth set and an estimate set at each of four
// time steps. GOSPA (α = 2) is from García-Fernández & Svensson, "Spooky effect in optimal OSPA
// estimation and how GOSPA solves it"; OSPA's localisation and cardinality parts are eqs (24)–(26)
// of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets".
import * as fisst from 'fisst';

// truths[t] and estimates[t] are the sets at step t: arrays of points [x, y] (empty sets allowed).
const truths = [[[0, 0], [10, 0]], [[1, 0], [10, 1]], [[2, 0], [10, 2]], [[3, 0]]];
const estimates = [[[0, 0.5]], [[1, 0.4], [10, 1.3]], [[2.2, 0], [10, 1.8], [20, 20]], [[3, 0.1]]];
const c = 2; // the cut-off c: no point is charged more than c (here a miss or a false target)
const f = (xs) => xs.map((x) => x.toFixed(3)).join(' ');

// GOSPA per step with order p = 2 (the default) and α = 2 (the default), so each step decomposes
// into Σ d² over the assigned pairs (`localisation`, not rooted), missed truths and false targets:
// distance² = localisation + (c²/2)(missed + falseTargets).
const g = fisst.gospaSeries({ truths, estimates, c });
console.log(f(g.distance), '| mean', g.meanDistance.toFixed(3)); // 1.500 0.500 1.442 0.100 | mean 0.886
console.log(g.missed.join(' '), '/', g.falseTargets.join(' ')); // 1 0 0 0 / 0 0 1 0

// OSPA per step (eq. 24), and its parts, which here ARE rooted: distance^p = localisation^p + cardinality^p.
// OSPA is normalised by the larger set size, so it stays in [0, c].
const o = fisst.ospaSeries({ truths, estimates, c });
console.log(f(o.distance)); // 1.458 0.354 1.166 0.100
console.log(f(o.localisation), '/', f(o.cardinality)); // 0.354 0.354 0.163 0.100 / 1.414 0.000 1.155 0.000

// One step with `gospa`: the assignment lists [truthIndex, estimateIndex] pairs; the estimate at
// [20, 20] is farther than c from every truth, so it is left unassigned as a false target.
const one = fisst.gospa(truths[2], estimates[2], { c });
console.log(one.distance.toFixed(4), one.localisation.toFixed(2), one.missed, one.falseTargets); // 1.4422 0.08 0 1
console.log(JSON.stringify(one.assignment)); // [[0,0],[1,1]]
// With α ≠ 2 only the distance exists (the decomposition needs α = 2).
console.log(Object.keys(fisst.gospa(truths[2], estimates[2], { c, alpha: 1 }))); // [ 'distance' ]

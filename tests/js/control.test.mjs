// The JavaScript contract of issue 14 (paper 004, Ristic & Vo, "Sensor control for
// multi-object state-space estimation using random finite sets"): multiObjectLikelihood
// against a brute-force enumeration of the associations θ of eq. (20) written here in plain JS,
// SensorControlRun (Algorithm 1 with the 17 admissible actions (23) and OSPA (24)–(26)) and
// compareSchemes (Fig. 3), at small sizes (the whole file runs in a few seconds).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';

/** mulberry32: a seeded generator in [0, 1), so that the random inputs are reproducible. */
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** ln Σ e^{x_i} (−∞ when every x_i is −∞). */
function logSumExp(xs) {
  const hi = Math.max(...xs);
  if (hi === -Infinity) return -Infinity;
  return hi + Math.log(xs.reduce((s, x) => s + Math.exp(x - hi), 0));
}

/**
 * ln g(Z | X) of eq. (20) by enumerating every association θ: {1 … n} → {0 … m} that is
 * one-to-one on the detected objects (θ(i) = θ(i') > 0 ⇒ i = i'). Multiplied out, (20) is
 *   g = e^{−λ} Σ_θ Π_{θ(i) = 0} (1 − p_D) · Π_{θ(i) = j > 0} p_D g(z_j | x_i) · Π_{j ∉ θ} λ c(z_j),
 * (f_c(Z) = e^{−λ} Π_j λ c(z_j); the division by (1 − p_D) λ c(z) in (20) cancels), which is
 * also defined for p_D = 1 and λ c(z) = 0. Each term is summed in log space, so the oracle
 * neither underflows nor overflows at the scales tested.
 */
function bruteForce({ likelihoods: g, detectionProbability: pD, clutterRate: lambda, clutterDensity: c }) {
  const n = g.length;
  const m = c.length;
  const terms = [];
  const used = new Array(m).fill(false);
  const walk = (i, acc) => {
    if (i === n) {
      let t = acc - lambda;
      for (let j = 0; j < m; j++) if (!used[j]) t += Math.log(lambda * c[j]);
      terms.push(t);
      return;
    }
    walk(i + 1, acc + Math.log(1 - pD)); // object i undetected
    for (let j = 0; j < m; j++) {
      if (used[j]) continue;
      used[j] = true;
      walk(i + 1, acc + Math.log(pD * g[i][j])); // object i gave z_j
      used[j] = false;
    }
  };
  walk(0, 0);
  return logSumExp(terms.map((t) => (Number.isNaN(t) ? -Infinity : t)));
}

/** The number of associations θ enumerated for n objects and m measurements. */
const associations = (n, m) => {
  let total = 0;
  for (let d = 0, ways = 1; d <= Math.min(n, m); d++) {
    // C(n, d) · m! / (m − d)!
    let choose = 1;
    for (let k = 0; k < d; k++) choose = (choose * (n - k)) / (k + 1);
    total += choose * ways;
    ways *= m - d;
  }
  return total;
};

// Tolerance: the package computes (20) exactly to rounding (its dynamic programme is checked
// against its own enumeration in Rust); this JS oracle sums up to 9,276 terms in log space.
// Both agree to a relative 1e-12 in the likelihood, i.e. |Δ ln g| ≤ 1e-12 + 1e-14 |ln g|.
const closeLog = (got, want, what) => {
  assert.ok(!Number.isNaN(got), `${what}: NaN`);
  if (want === -Infinity) return assert.equal(got, -Infinity, what);
  assert.ok(Math.abs(got - want) <= 1e-12 + 1e-14 * Math.abs(want), `${what}: ${got} vs ${want} (Δ ${got - want})`);
};

const likelihood = (o) => fisst.multiObjectLikelihood(o).logLikelihood;

/** Random inputs of n objects and m measurements; `scale` multiplies every g(z | x). */
function randomCase(next, n, m, { scale = 1, zeros = 0 } = {}) {
  const likelihoods = Array.from({ length: n }, () => Array.from({ length: m }, () => (next() < zeros ? 0 : scale * next() ** 3 * 5)));
  return {
    likelihoods,
    detectionProbability: [0.05, 0.5, 0.95, next()][Math.floor(next() * 4)],
    clutterRate: 0.1 + 4 * next(),
    clutterDensity: Array.from({ length: m }, () => 0.01 + next()),
  };
}

test('multiObjectLikelihood is eq. (20): every n ≤ 5, m ≤ 7 against the enumeration of θ', () => {
  const next = rng(14);
  assert.equal(associations(5, 7), 9276);
  let cases = 0;
  for (let n = 0; n <= 5; n++) {
    for (let m = 0; m <= 7; m++) {
      for (let rep = 0; rep < 4; rep++) {
        const o = randomCase(next, n, m, { zeros: rep === 3 ? 0.3 : 0 });
        const got = likelihood(o);
        closeLog(got, bruteForce(o), `n=${n} m=${m} rep=${rep}`);
        cases++;
      }
    }
  }
  assert.equal(cases, 6 * 8 * 4);
});

test('multiObjectLikelihood at tiny and huge scales (underflow of the linear sum)', () => {
  const next = rng(7);
  for (const scale of [1e-150, 1e-300, 1e150, 1e250]) {
    for (const [n, m] of [[1, 1], [3, 4], [5, 7], [5, 2]]) {
      const o = randomCase(next, n, m, { scale });
      closeLog(likelihood(o), bruteForce(o), `scale=${scale} n=${n} m=${m}`);
    }
  }
  // One object, one measurement, every factor a subnormal number: still finite, not −∞.
  const tiny = { likelihoods: [[5e-324]], detectionProbability: 1, clutterRate: 1e-300, clutterDensity: [1e-10] };
  closeLog(likelihood(tiny), bruteForce(tiny), 'subnormal');
  assert.ok(Number.isFinite(likelihood(tiny)));
});

test('multiObjectLikelihood edge cases: n = 0, m = 0, p_D = 1 and 0, zero likelihoods, λ = 0', () => {
  const c = [0.2, 0.5, 0.1];
  const lambda = 0.8;
  const clutterOnly = -lambda + c.reduce((s, v) => s + Math.log(lambda * v), 0);
  // n = 0: f_c(Z) alone; with m = 0 too, e^{−λ}.
  closeLog(likelihood({ likelihoods: [], detectionProbability: 0.9, clutterRate: lambda, clutterDensity: c }), clutterOnly, 'n = 0');
  closeLog(likelihood({ likelihoods: [], detectionProbability: 0.9, clutterRate: lambda, clutterDensity: [] }), -lambda, 'n = m = 0');
  // m = 0: every object missed, e^{−λ} (1 − p_D)^n.
  closeLog(likelihood({ likelihoods: [[], [], []], detectionProbability: 0.9, clutterRate: lambda, clutterDensity: [] }),
    -lambda + 3 * Math.log(0.1), 'm = 0');
  // p_D = 0: the measurements are all clutter, whatever g says.
  closeLog(likelihood({ likelihoods: [[1, 2, 3], [4, 5, 6]], detectionProbability: 0, clutterRate: lambda, clutterDensity: c }), clutterOnly, 'p_D = 0');
  // p_D = 1: every object must be detected; more objects than measurements is impossible.
  const g = [[0.3, 1.2, 0.01], [2, 0.4, 0.7]];
  const full = { likelihoods: g, detectionProbability: 1, clutterRate: lambda, clutterDensity: c };
  closeLog(likelihood(full), bruteForce(full), 'p_D = 1');
  // By hand: θ over the injective maps of 2 objects into 3 measurements, the third one clutter.
  let byHand = 0;
  for (let a = 0; a < 3; a++) for (let b = 0; b < 3; b++) if (a !== b) byHand += g[0][a] * g[1][b] * lambda * c[3 - a - b];
  closeLog(likelihood(full), -lambda + Math.log(byHand), 'p_D = 1 by hand');
  assert.equal(likelihood({ likelihoods: [[1], [1]], detectionProbability: 1, clutterRate: lambda, clutterDensity: [0.5] }), -Infinity);
  assert.equal(likelihood({ likelihoods: [[], []], detectionProbability: 1, clutterRate: lambda, clutterDensity: [] }), -Infinity);
  // A zero likelihood: −∞ when it is the only way to explain Z, never NaN.
  assert.equal(likelihood({ likelihoods: [[0]], detectionProbability: 1, clutterRate: 0, clutterDensity: [0.5] }), -Infinity);
  assert.equal(likelihood({ likelihoods: [[0, 0], [0, 0]], detectionProbability: 1, clutterRate: 1, clutterDensity: [0.5, 0.5] }), -Infinity);
  // … and a plain missing term otherwise.
  const someZero = { likelihoods: [[0, 2], [0.5, 0]], detectionProbability: 0.9, clutterRate: 0.5, clutterDensity: [0.3, 0.6] };
  closeLog(likelihood(someZero), bruteForce(someZero), 'some zero likelihoods');
  // λ = 0: no clutter, so every measurement must come from an object.
  const noClutter = { likelihoods: [[0.3, 1.2], [2, 0.4], [0.5, 0.5]], detectionProbability: 0.7, clutterRate: 0, clutterDensity: [0.5, 0.5] };
  closeLog(likelihood(noClutter), bruteForce(noClutter), 'λ = 0');
  assert.equal(likelihood({ ...noClutter, likelihoods: [[1, 1]] }), -Infinity, 'λ = 0, more measurements than objects');
  // A zero clutter density at a measurement no object explains.
  assert.equal(likelihood({ likelihoods: [[1, 0]], detectionProbability: 0.5, clutterRate: 1, clutterDensity: [1, 0] }), -Infinity);
  // Float64Array rows and densities are the same numbers.
  closeLog(likelihood({ ...someZero, likelihoods: someZero.likelihoods.map((r) => Float64Array.from(r)), clutterDensity: Float64Array.from(someZero.clutterDensity) }),
    likelihood(someZero), 'Float64Array');
  // The result is an object with the one key.
  assert.deepEqual(Object.keys(fisst.multiObjectLikelihood(someZero)), ['logLikelihood']);
});

/** Asserts that `fn` throws a `cls` whose message starts with `path`. */
function throwsAt(fn, cls, path) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof cls, `expected ${cls.name}, got ${e?.constructor?.name}: ${e?.message}`);
    assert.ok(e.message.startsWith(path), `message ${JSON.stringify(e.message)} should start with ${path}`);
    return true;
  });
}

test('multiObjectLikelihood: bad input is a typed error naming the field', () => {
  const ok = { likelihoods: [[0.5, 1]], detectionProbability: 0.9, clutterRate: 0.8, clutterDensity: [0.1, 0.2] };
  const bad = (changes) => () => fisst.multiObjectLikelihood({ ...ok, ...changes });
  throwsAt(bad({ detectionProbability: 1.5 }), RangeError, 'options.detectionProbability');
  throwsAt(bad({ detectionProbability: -0.1 }), RangeError, 'options.detectionProbability');
  throwsAt(bad({ detectionProbability: NaN }), RangeError, 'options.detectionProbability');
  throwsAt(bad({ clutterRate: -1 }), RangeError, 'options.clutterRate');
  throwsAt(bad({ clutterRate: Infinity }), RangeError, 'options.clutterRate');
  throwsAt(bad({ clutterDensity: [0.1, -0.2] }), RangeError, 'options.clutterDensity[1]');
  throwsAt(bad({ clutterDensity: [0.1, NaN] }), RangeError, 'options.clutterDensity[1]');
  throwsAt(bad({ likelihoods: [[0.5, -1]] }), RangeError, 'options.likelihoods[0][1]');
  throwsAt(bad({ likelihoods: [[0.5, Infinity]] }), RangeError, 'options.likelihoods[0][1]');
  throwsAt(bad({ likelihoods: [[0.5, 1], [0.5]] }), RangeError, 'options.likelihoods[1]');
  throwsAt(bad({ likelihoods: [[0.5, 1, 2]] }), RangeError, 'options.likelihoods[0]');
  throwsAt(bad({ likelihoods: [['0.5', 1]] }), TypeError, 'options.likelihoods[0][0]');
  throwsAt(bad({ likelihoods: 'many' }), TypeError, 'options.likelihoods');
  throwsAt(bad({ clutterRate: '0.8' }), TypeError, 'options.clutterRate');
  throwsAt(() => fisst.multiObjectLikelihood({ likelihoods: [], detectionProbability: 0.9, clutterRate: 1 }), TypeError, 'options.clutterDensity');
  throwsAt(() => fisst.multiObjectLikelihood(), TypeError, 'options');
  throwsAt(bad({ extra: 1 }), TypeError, 'options');
  // The caps (the dynamic programme has 2^min(n, m) states): a RangeError before any work.
  const square = (n, m) => ({ likelihoods: Array.from({ length: n }, () => new Array(m).fill(0.5)), detectionProbability: 0.9, clutterRate: 1, clutterDensity: new Array(m).fill(0.1) });
  throwsAt(() => fisst.multiObjectLikelihood(square(13, 13)), RangeError, 'options.likelihoods');
  throwsAt(() => fisst.multiObjectLikelihood(square(65, 1)), RangeError, 'options.likelihoods');
  throwsAt(() => fisst.multiObjectLikelihood(square(1, 1001)), RangeError, 'options.clutterDensity');
  assert.ok(Number.isFinite(likelihood(square(12, 12))), 'min(n, m) = 12 is accepted');
  // The module still works afterwards.
  closeLog(likelihood(ok), bruteForce(ok), 'after the errors');
});

// ------------------------------------------------------------------ SensorControlRun
// Shapes: core/src/control/JS_SHAPES.md (branch issue14).
const SMALL = { particles: 100, futureScans: 20 };
const AREA = 1000; // A = [0, 1000]² m (Sec. 5.1)
const PARTS = ['distance', 'localisation', 'cardinality'];
const waiting = (name) => (typeof fisst[name] === 'function' ? false : `waiting for the ${name} binding (branch issue14)`);

/** OSPA (24)–(26) with c = 100 m, p = 2 by enumerating the permutations (sets of ≤ 8 points). */
function ospaBrute(X, Y, c = 100, p = 2) {
  if (X.length > Y.length) return ospaBrute(Y, X, c, p);
  const [m, n] = [X.length, Y.length];
  if (n === 0) return { distance: 0, localisation: 0, cardinality: 0 };
  let best = Infinity;
  const used = new Array(n).fill(false);
  const walk = (i, acc) => {
    if (i === m) { best = Math.min(best, acc); return; }
    for (let j = 0; j < n; j++) {
      if (used[j]) continue;
      used[j] = true;
      walk(i + 1, acc + Math.min(c, Math.hypot(X[i][0] - Y[j][0], X[i][1] - Y[j][1])) ** p);
      used[j] = false;
    }
  };
  walk(0, 0);
  return { distance: ((best + c ** p * (n - m)) / n) ** (1 / p), localisation: (best / n) ** (1 / p), cardinality: ((c ** p * (n - m)) / n) ** (1 / p) };
}

/** The 17 admissible positions (23) around `at` (N_ρ = 2, N_θ = 8, ρ0 = 50 m): stay, then ring j, heading ℓ. */
function admissible(at) {
  const out = [[...at]];
  for (let j = 1; j <= 2; j++) for (let l = 1; l <= 8; l++) out.push([at[0] + j * 50 * Math.cos((l * Math.PI) / 4), at[1] + j * 50 * Math.sin((l * Math.PI) / 4)]);
  return out;
}
const samePoint = (a, b, tol = 1e-9) => Math.abs(a[0] - b[0]) <= tol && Math.abs(a[1] - b[1]) <= tol;
/** Inside A, to 1e-9 m (cos and sin of ℓ·45° are not exact: (50, −1.2e-14) is on the edge). */
const inside = ([x, y], tol = 1e-9) => x >= -tol && x <= AREA + tol && y >= -tol && y <= AREA + tol;

/** The flat particles of `run.particles` as point sets. */
const unflatten = ({ cardinalities, positions }) => {
  let o = 0;
  return cardinalities.map((n) => Array.from({ length: n }, () => [positions[2 * o], positions[2 * o++ + 1]]));
};

/** Steps a new run k times; returns what it says before and after each step. */
function stepRun(options, k) {
  const run = new fisst.SensorControlRun(options);
  try {
    const before = { sensorPath: run.sensorPath, truth: run.truth, k: run.k, steps: run.steps, seed: run.seed, scheme: run.scheme };
    const out = [];
    for (let i = 0; i < k; i++) {
      const step = run.step();
      out.push({ step, particles: run.particles, sensorPath: run.sensorPath, truth: run.truth, measurements: run.measurements, k: run.k });
    }
    return { before, out };
  } finally {
    run.free();
  }
}

test('SensorControlRun: shapes, the 17 actions (23), −∞ outside A, MAP cardinality (22), OSPA (24)–(26)', { skip: waiting('SensorControlRun') }, () => {
  for (const scheme of ['renyi', 'fisher', 'pent', 'random']) {
    // From the corner (0, 0), the default start: 10 of the 17 moves leave A.
    const { before, out } = stepRun({ seed: 3, scheme, ...SMALL, steps: 5 }, 5);
    assert.deepEqual(before.truth, [[300, 600], [750, 250]]); // the paper's sources (Sec. 5.1)
    assert.deepEqual(before.sensorPath, [[0, 0]]);
    assert.deepEqual([before.k, before.steps, before.seed, before.scheme], [0, 5, 3, scheme]);
    out.forEach(({ step, particles, sensorPath, truth, measurements, k }, i) => {
      const what = `${scheme} k=${i + 1}`;
      assert.deepEqual(Object.keys(step).sort(), ['action', 'estimate', 'k', 'measurements', 'ospa', 'rewards', 'sensor'], what);
      assert.equal(step.k, i + 1, what);
      assert.equal(k, i + 1, what);
      assert.deepEqual(truth, before.truth, what);
      // Z_k was taken at the previous location; the path grows by the move taken.
      assert.equal(sensorPath.length, i + 2, what);
      assert.deepEqual(step.sensor, sensorPath[i], what);
      assert.deepEqual(sensorPath[i + 1], step.action.position, what);
      assert.equal(measurements.length, i + 1, what);
      assert.deepEqual(measurements[i], step.measurements, what);
      assert.ok(step.measurements.every((z) => Number.isFinite(z) && z >= 0), `${what}: ${step.measurements}`);
      // The 17 moves (23) indexed 0 (stay), 1 + (j − 1)·8 + (ℓ − 1); −∞ exactly outside A.
      const moves = admissible(step.sensor);
      const { index, ring, heading, position } = step.action;
      assert.ok(Number.isInteger(index) && index >= 0 && index < 17, what);
      assert.deepEqual([ring, heading], index === 0 ? [0, 0] : [1 + Math.floor((index - 1) / 8), 1 + ((index - 1) % 8)], what);
      assert.ok(samePoint(position, moves[index], 1e-9), `${what}: ${position} vs ${moves[index]}`);
      assert.ok(inside(position), what);
      assert.equal(step.rewards.length, 17, what);
      // (Within 1e-9 m of an edge either is right: the core computes the move in floating
      // point, and a move back along a diagonal lands at −1.4e-14 instead of on the edge.)
      step.rewards.forEach((r, j) => {
        if (inside(moves[j], -1e-9)) assert.ok(Number.isFinite(r), `${what}: reward ${j} = ${r} at ${moves[j]}`);
        else if (!inside(moves[j], 1e-9)) assert.equal(r, -Infinity, `${what}: reward ${j} = ${r} at ${moves[j]}`);
      });
      assert.ok(step.rewards.every((r) => r === -Infinity || Number.isFinite(r)), `${what}: ${step.rewards}`);
      if (scheme === 'random') assert.ok(step.rewards.every((r) => r === -Infinity || r === 0), `${what}: ${step.rewards}`);
      else assert.equal(step.rewards[index], Math.max(...step.rewards), `${what}: a greedy scheme takes the largest reward (6)`);
      // Particles: N point sets inside A with n ≤ n_max = 4, equal weights after resampling.
      assert.equal(particles.weights.length, SMALL.particles, what);
      particles.weights.forEach((w) => assert.ok(Math.abs(w - 1 / SMALL.particles) < 1e-12, what));
      const sets = unflatten(particles);
      assert.equal(particles.positions.length, 2 * particles.cardinalities.reduce((a, b) => a + b, 0), what);
      for (const p of sets) {
        assert.ok(p.length <= 4, what);
        for (const x of p) assert.ok(inside(x), `${what}: particle point ${x}`);
      }
      // (22): the pmf of the particle cardinalities, its argmax n̂, and the states as the
      // object-by-object means of the particles with n̂ objects (Sec. 5.2).
      const pmf = [0, 1, 2, 3, 4].map((n) => sets.filter((p) => p.length === n).length / SMALL.particles);
      const e = step.estimate;
      assert.equal(e.cardinalityPmf.length, 5, what);
      e.cardinalityPmf.forEach((q, n) => assert.ok(Math.abs(q - pmf[n]) < 1e-12, `${what}: pmf ${e.cardinalityPmf} vs ${pmf}`));
      assert.equal(pmf[e.cardinality], Math.max(...pmf), what);
      assert.equal(e.states.length, e.cardinality, what);
      const chosen = sets.filter((p) => p.length === e.cardinality);
      e.states.forEach((s, r) => {
        const mean = [0, 1].map((c) => chosen.reduce((a, p) => a + p[r][c], 0) / chosen.length);
        assert.ok(samePoint(s, mean, 1e-9), `${what}: state ${r} ${s} vs ${mean}`);
      });
      // OSPA of the estimate against the truth (c = 100 m, p = 2), and distance² = localisation² + cardinality².
      const o = ospaBrute(truth, e.states);
      for (const part of PARTS) assert.ok(Math.abs(step.ospa[part] - o[part]) <= 1e-9 * Math.max(1, o[part]), `${what}: ${part} ${step.ospa[part]} vs ${o[part]}`);
      const { distance: d, localisation: l, cardinality: c } = step.ospa;
      assert.ok(Math.abs(d * d - (l * l + c * c)) <= 1e-9 * Math.max(1, d * d), `${what}: ${d}² vs ${l}² + ${c}²`);
      assert.ok(d >= 0 && d <= 100, what);
    });
  }
});

test('SensorControlRun: the same seed gives the same run, another seed another; the paper\'s defaults', { skip: waiting('SensorControlRun') }, () => {
  const a = stepRun({ seed: 11, scheme: 'renyi', ...SMALL, steps: 4 }, 4);
  assert.deepEqual(stepRun({ seed: 11, scheme: 'renyi', ...SMALL, steps: 4 }, 4), a);
  const c = stepRun({ seed: 12, scheme: 'renyi', ...SMALL, steps: 4 }, 4);
  assert.notDeepEqual(a.out.map((s) => s.step.measurements), c.out.map((s) => s.step.measurements));
  // Another start: the path begins there.
  assert.deepEqual(stepRun({ seed: 1, scheme: 'fisher', ...SMALL, steps: 1, start: [500, 500] }, 1).out[0].step.sensor, [500, 500]);
  // N = 750, K = 40 by default; an omitted seed is drawn and can be read back.
  const run = new fisst.SensorControlRun({ scheme: 'random', futureScans: 1 });
  try {
    assert.equal(run.steps, 40);
    assert.ok(Number.isInteger(run.seed));
    run.step();
    assert.equal(run.particles.weights.length, 750);
  } finally {
    run.free();
  }
});

test('SensorControlRun: bad options are typed errors naming the field; a finished run says so', { skip: waiting('SensorControlRun') }, () => {
  const ok = { seed: 1, scheme: 'renyi', ...SMALL, steps: 2 };
  const bad = (changes) => () => new fisst.SensorControlRun({ ...ok, ...changes });
  throwsAt(bad({ scheme: 'greedy' }), RangeError, 'options.scheme');
  throwsAt(bad({ scheme: 3 }), TypeError, 'options.scheme');
  throwsAt(bad({ particles: 0 }), RangeError, 'options.particles');
  throwsAt(bad({ particles: 10.5 }), RangeError, 'options.particles');
  throwsAt(bad({ particles: 20_001 }), RangeError, 'options.particles');
  throwsAt(bad({ futureScans: 0 }), RangeError, 'options.futureScans');
  assert.throws(bad({ particles: 2000, futureScans: 201 }), (e) => e instanceof RangeError && /^options\.(particles|futureScans)/.test(e.message));
  throwsAt(bad({ alpha: 0 }), RangeError, 'options.alpha');
  throwsAt(bad({ alpha: -0.5 }), RangeError, 'options.alpha');
  throwsAt(bad({ alpha: NaN }), RangeError, 'options.alpha');
  throwsAt(bad({ steps: 0 }), RangeError, 'options.steps');
  throwsAt(bad({ seed: -1 }), RangeError, 'options.seed');
  throwsAt(bad({ start: [1200, 0] }), RangeError, 'options.start');
  throwsAt(bad({ maxObjects: 0 }), RangeError, 'options.maxObjects');
  throwsAt(bad({ maxObjects: 9 }), RangeError, 'options.maxObjects');
  throwsAt(bad({ particle: 100 }), TypeError, 'options');
  throwsAt(() => new fisst.SensorControlRun(), TypeError, 'options');
  // α = 1 is the Kullback–Leibler divergence, not an error.
  new fisst.SensorControlRun({ ...ok, alpha: 1 }).free();
  const run = new fisst.SensorControlRun(ok);
  try {
    run.step();
    run.step();
    assert.throws(() => run.step(), (e) => e instanceof RangeError);
    assert.equal(run.k, 2, 'the refused step changed nothing');
    assert.equal(run.sensorPath.length, 3);
  } finally {
    run.free();
  }
});

// ------------------------------------------------------------------ compareSchemes
test('compareSchemes: per scheme, the mean OSPA parts over time with standard errors; onProgress', { skip: waiting('compareSchemes') }, () => {
  const calls = [];
  const schemes = ['renyi', 'random'];
  const out = fisst.compareSchemes({ runs: 3, steps: 4, seed: 5, schemes, ...SMALL, onProgress: (done, total) => calls.push([done, total]) });
  // onProgress after each finished run: done = 1 … runs·schemes.
  assert.deepEqual(calls, [1, 2, 3, 4, 5, 6].map((d) => [d, 6]));
  assert.deepEqual([out.seed, out.runs, out.steps], [5, 3, 4]);
  assert.deepEqual(out.schemes.map((s) => s.scheme), schemes);
  for (const s of out.schemes) {
    for (const part of PARTS) {
      const { mean, standardError } = s[part];
      assert.equal(mean.length, 4, `${s.scheme} ${part}`);
      assert.equal(standardError.length, 4, `${s.scheme} ${part}`);
      assert.ok(mean.every((v) => v >= 0 && v <= 100), `${s.scheme} ${part} ${mean}`);
      assert.ok(standardError.every((v) => v >= 0 && Number.isFinite(v)), `${s.scheme} ${part}`);
    }
    // Per run max(l, c) ≤ d = √(l² + c²) ≤ l + c, so the means keep that order.
    s.distance.mean.forEach((d, t) => {
      const [l, c] = [s.localisation.mean[t], s.cardinality.mean[t]];
      assert.ok(d >= Math.max(l, c) - 1e-9 && d <= l + c + 1e-9, `${s.scheme} t=${t}: ${d} vs ${l}, ${c}`);
    });
  }
  // The same seed gives the same numbers; one run has standard errors 0; all four by default.
  assert.deepEqual(fisst.compareSchemes({ runs: 3, steps: 4, seed: 5, schemes, ...SMALL }), out);
  const one = fisst.compareSchemes({ runs: 1, steps: 2, seed: 5, ...SMALL, futureScans: 5 });
  assert.deepEqual(one.schemes.map((s) => s.scheme), ['renyi', 'fisher', 'pent', 'random']);
  for (const s of one.schemes) for (const part of PARTS) assert.deepEqual(s[part].standardError, [0, 0]);
});

test('compareSchemes: errors name the field; a throwing onProgress stops it', { skip: waiting('compareSchemes') }, () => {
  const ok = { runs: 1, steps: 2, seed: 1, schemes: ['random'], ...SMALL };
  const bad = (changes) => () => fisst.compareSchemes({ ...ok, ...changes });
  throwsAt(bad({ runs: 0 }), RangeError, 'options.runs');
  throwsAt(bad({ runs: 1001 }), RangeError, 'options.runs');
  throwsAt(bad({ steps: 0 }), RangeError, 'options.steps');
  throwsAt(bad({ schemes: ['random', 'bogus'] }), RangeError, 'options.schemes[1]');
  throwsAt(bad({ schemes: 'random' }), TypeError, 'options.schemes');
  throwsAt(bad({ onProgress: 3 }), TypeError, 'options.onProgress');
  throwsAt(bad({ particles: 0 }), RangeError, 'options.particles');
  throwsAt(() => fisst.compareSchemes(), TypeError, 'options');
  assert.throws(bad({ onProgress: () => { throw new Error('stop here'); } }), /stop here/);
  assert.equal(fisst.compareSchemes(ok).schemes.length, 1, 'still usable afterwards');
});

// Run r of compareSchemes uses a seed derived from the master seed (core/src/control/
// comparison.rs, run_seeds); with those seeds returned, its means and standard errors can be
// checked against SensorControlRun runs here.
const probe = waiting('compareSchemes') ? null : fisst.compareSchemes({ runs: 1, steps: 1, schemes: ['random'], particles: 100, futureScans: 1 });
const noSeeds = probe && !Array.isArray(probe.runSeeds) && 'waiting: compareSchemes does not return the seeds of its runs (runSeeds)';
test('compareSchemes: the means and standard errors of SensorControlRun runs with its run seeds', { skip: waiting('compareSchemes') || noSeeds }, () => {
  const out = fisst.compareSchemes({ runs: 3, steps: 3, seed: 9, schemes: ['fisher', 'pent'], ...SMALL });
  assert.equal(out.runSeeds.length, 3);
  for (const s of out.schemes) {
    const runs = out.runSeeds.map((seed) => stepRun({ seed, scheme: s.scheme, ...SMALL, steps: 3 }, 3).out.map((o) => o.step.ospa));
    for (const part of PARTS) {
      for (let t = 0; t < 3; t++) {
        const xs = runs.map((r) => r[t][part]);
        const mean = xs.reduce((a, b) => a + b, 0) / 3;
        const se = Math.sqrt(xs.reduce((a, x) => a + (x - mean) ** 2, 0) / 2 / 3);
        assert.ok(Math.abs(s[part].mean[t] - mean) <= 1e-9 * Math.max(1, mean), `${s.scheme} ${part} mean[${t}]: ${s[part].mean[t]} vs ${mean}`);
        assert.ok(Math.abs(s[part].standardError[t] - se) <= 1e-9 * Math.max(1, se), `${s.scheme} ${part} se[${t}]: ${s[part].standardError[t]} vs ${se}`);
      }
    }
  }
});

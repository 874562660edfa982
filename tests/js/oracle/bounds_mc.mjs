// Seeded Monte Carlo of the joint detector-estimators of paper 002 (Rezaeian & Vo, "Error
// bounds for joint detection and estimation of a single object with random finite set
// observation"), in plain JS: an oracle independent of the `fisst` package (its own generator,
// quadrature, Cholesky and inverse), which tests/js/bounds.test.mjs holds the bounds and the
// package's own Monte Carlo (jdeMonteCarlo, the core's bounds::jde_monte_carlo) to. It was
// web/bounds-mc.js; the page now draws jdeMonteCarlo (issue 25).
// Nothing here touches the DOM. Each function returns the MSE E e²(X, X̂(Z)) (11) and its
// standard error (the sample standard deviation of e² over √samples).
//
// The estimators: MAP detection on Z ≠ ∅ (Lemma 1, (39)–(40)), the posterior mean of x when a
// target is declared, and on Z = ∅ the better of the HPE rule ({x*}) and the LPE rule (∅) of
// (46) — or, with `rule: 'map'`, MAP detection on Z = ∅ too (Section IV-A).

/** A seeded generator: `uniform()` in (0, 1), `normal()` (Box–Muller), `poisson(λ)` (Knuth). */
export function rng(seed) {
  let s = seed >>> 0;
  let spare = null;
  const uniform = () => {
    // mulberry32
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return (((t ^ (t >>> 14)) >>> 0) + 0.5) / 4294967296;
  };
  const normal = () => {
    if (spare !== null) {
      const v = spare;
      spare = null;
      return v;
    }
    const rad = Math.sqrt(-2 * Math.log(uniform()));
    const ang = 2 * Math.PI * uniform();
    spare = rad * Math.sin(ang);
    return rad * Math.cos(ang);
  };
  const poisson = (lambda) => {
    const limit = Math.exp(-lambda);
    let k = 0;
    for (let p = uniform(); p > limit; p *= uniform()) k++;
    return k;
  };
  return { uniform, normal, poisson };
}

/** Running mean and standard error of the squared errors. */
function tally() {
  let n = 0;
  let sum = 0;
  let sum2 = 0;
  return {
    add(e2) { n++; sum += e2; sum2 += e2 * e2; },
    result() {
      const mse = sum / n;
      const variance = Math.max(sum2 / n - mse * mse, 0) * (n / Math.max(n - 1, 1));
      return { mse, se: Math.sqrt(variance / n), samples: n };
    },
  };
}

const gaussPdf = (z, mean, variance) => Math.exp(-((z - mean) ** 2) / (2 * variance)) / Math.sqrt(2 * Math.PI * variance);

/**
 * The linear-Gaussian system of Example 1 with a constant P_o: x ~ N(m, σf²), z = a x + b + v,
 * v ~ N(0, σv²). Model I (falseAlarm: { probability q, mean, variance }: a false observation
 * ψ = N(mean, variance) with probability q when no target exists) or model II (clutter:
 * { rate λ, mean, variance }: Poisson clutter of intensity λ N(mean, variance)); neither gives
 * the no-clutter model Θ_b0 of Corollary 3.
 */
export function mcGaussian({
  existence: r, prior, gain: a = 1, offset: b = 0, noiseVariance, detectionProbability: P,
  falseAlarm = null, clutter = null, falseAlarmError: e0, missError: e1, rule = 'optimal', samples, seed,
}) {
  const g = rng(seed);
  const t = tally();
  const { mean: m, variance: vf } = prior;
  const sf = Math.sqrt(vf);
  const sv = Math.sqrt(noiseVariance);
  const vm = a * a * vf + noiseVariance; // the marginal of z under p_1: N(a m + b, a²σf² + σv²)
  const gainK = (a * vf) / vm; // posterior mean m + K (z − a m − b), variance σh² for every z
  const xhat = (z) => m + gainK * (z - a * m - b);
  const q = falseAlarm ? falseAlarm.probability : 0;
  const lambda = clutter ? clutter.rate : 0;
  // Z = ∅: the HPE rule declares {x*} (x* = m for a constant P_o), the LPE rule ∅ (46). Their
  // expected costs on Z = ∅: (1−r)P(∅|no target)e0² + r(1−P)σf² against r(1−P)e1²
  // (P(∅|no target) = 1 − q in model I, e^{−λ} in model II, where r(1−P) is times e^{−λ} too).
  const emptyNoTarget = clutter ? 1 : 1 - q;
  const hpe = rule === 'map'
    ? r * (1 - P) >= 1 - r // ties declare, as r ≥ r_M*
    : (1 - r) * emptyNoTarget * e0 + r * (1 - P) * vf <= r * (1 - P) * e1; // ties declare, as r ≥ r*
  const cost = (exists, x, declare, estimate) => (exists ? (declare ? (x - estimate) ** 2 : e1) : declare ? e0 : 0);
  for (let k = 0; k < samples; k++) {
    const exists = g.uniform() < r;
    const x = exists ? m + sf * g.normal() : 0;
    const detected = exists && g.uniform() < P;
    if (!clutter) {
      let z = null;
      if (detected) z = a * x + b + sv * g.normal();
      else if (!exists && q > 0 && g.uniform() < q) z = falseAlarm.mean + Math.sqrt(falseAlarm.variance) * g.normal();
      if (z === null) {
        t.add(cost(exists, x, hpe, m));
        continue;
      }
      // MAP (39): declare iff r P̄o ∫p_1(x, z)dx ≥ (1 − r) q ψ(z).
      const declare = q === 0 || r * P * gaussPdf(z, a * m + b, vm) >= (1 - r) * q * gaussPdf(z, falseAlarm.mean, falseAlarm.variance);
      t.add(cost(exists, x, declare, xhat(z)));
      continue;
    }
    const zs = [];
    if (detected) zs.push(a * x + b + sv * g.normal());
    const n = g.poisson(lambda);
    for (let i = 0; i < n; i++) zs.push(clutter.mean + Math.sqrt(clutter.variance) * g.normal());
    if (zs.length === 0) {
      t.add(cost(exists, x, hpe, m));
      continue;
    }
    // β(Z) = Σ_i ∫p_1(x, z_i)dx / v(z_i); MAP (40): declare iff r(1 − P̄o + P̄o β) ≥ 1 − r. The
    // posterior of x given a target: ∝ (1 − P̄o) N(x; m, σf²) + P̄o Σ_i (∫p_1(·, z_i)/v(z_i)) N(x; x̂(z_i), σh²).
    let beta = 0;
    let weighted = 0;
    for (const z of zs) {
      const ratio = gaussPdf(z, a * m + b, vm) / (lambda * gaussPdf(z, clutter.mean, clutter.variance));
      beta += ratio;
      weighted += ratio * xhat(z);
    }
    const declare = r * (1 - P + P * beta) >= 1 - r;
    const estimate = ((1 - P) * m + P * weighted) / (1 - P + P * beta);
    t.add(cost(exists, x, declare, estimate));
  }
  return { ...t.result(), declareOnEmpty: hpe };
}

/**
 * k = 1 … steps scans of an asserted target (r = 1) x ~ N(0, 1/J0), each a measurement of
 * information J1 − J0 with probability P̄o (Section III-E): the posterior mean after m
 * measurements has MSE 1/(J0 + m(J1 − J0)), so the MSE is the Enumeration bound (37).
 */
export function mcSequential({ priorInformation: j0, detectedInformation: j1, detectionProbability: P, steps, samples, seed }) {
  const g = rng(seed);
  const dj = j1 - j0;
  const tallies = Array.from({ length: steps }, tally);
  for (let s = 0; s < samples; s++) {
    const x = g.normal() / Math.sqrt(j0);
    let m = 0;
    let sum = 0;
    for (let k = 0; k < steps; k++) {
      if (g.uniform() < P && dj > 0) { // dj = 0: a measurement carries nothing
        m++;
        sum += x + g.normal() / Math.sqrt(dj);
      }
      tallies[k].add((x - (m > 0 ? (dj * sum) / (j0 + m * dj) : 0)) ** 2);
    }
  }
  const out = tallies.map((t) => t.result());
  return { mse: out.map((o) => o.mse), se: out.map((o) => o.se) };
}

// Example 2 (32): x, z ∈ [0, 1], f(x) = 2x(eˣ − 1), g(z|x) = x e^{xz}/(eˣ − 1), ψ = 1 (model I),
// p_1(x, z) = 2x² e^{xz}. Integrals over x by 24-point Gauss–Legendre on [0, 1].
const GL = (() => {
  const n = 24;
  const nodes = [];
  for (let i = 1; i <= n; i++) {
    let x = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    let dp = 0;
    for (let it = 0; it < 100; it++) {
      let p0 = 1;
      let p1 = x;
      for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k];
      dp = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp;
      x -= dx;
      if (Math.abs(dx) < 1e-16) break;
    }
    nodes.push([(1 + x) / 2, 1 / ((1 - x * x) * dp * dp)]); // weight 2/((1−x²)P'²) halved for [0, 1]
  }
  return nodes;
})();
const integrate01 = (h) => GL.reduce((s, [x, w]) => s + w * h(x), 0);

/** Mean x* and variance σe² of f (Example 2's P_o is constant, so f_d' = f). */
export const example2Prior = (() => {
  const f = (x) => 2 * x * (Math.exp(x) - 1);
  const mean = integrate01((x) => x * f(x));
  return { mean, variance: integrate01((x) => (x - mean) ** 2 * f(x)) };
})();

/** The MAP detector-estimator of Example 2 (model I with ψ = 1 on [0, 1]); P_o constant. */
export function mcExample2({ existence: r, detectionProbability: P, falseAlarmProbability: q, falseAlarmError: e0, missError: e1, samples, seed }) {
  const g = rng(seed);
  const t = tally();
  const { mean: xs, variance: ve } = example2Prior;
  const hpe = (1 - r) * (1 - q) * e0 + r * (1 - P) * ve <= r * (1 - P) * e1;
  const peak = 2 * (Math.E - 1);
  for (let k = 0; k < samples; k++) {
    const exists = g.uniform() < r;
    let x = 0;
    if (exists) {
      do x = g.uniform(); while (g.uniform() * peak > 2 * x * (Math.exp(x) - 1));
    }
    let z = null;
    if (exists && g.uniform() < P) z = Math.log1p(g.uniform() * Math.expm1(x)) / x; // inverse CDF of g(·|x)
    else if (!exists && g.uniform() < q) z = g.uniform();
    if (z === null) {
      t.add(exists ? (hpe ? (x - xs) ** 2 : e1) : hpe ? e0 : 0);
      continue;
    }
    let mass = 0;
    let first = 0;
    for (const [u, w] of GL) {
      const p = w * 2 * u * u * Math.exp(u * z);
      mass += p;
      first += p * u;
    }
    const declare = r * P * mass >= (1 - r) * q; // β_b(z) ≥ (1 − r)/(r P̄o) (19), ψ = 1
    t.add(exists ? (declare ? (x - first / mass) ** 2 : e1) : declare ? e0 : 0);
  }
  return { ...t.result(), declareOnEmpty: hpe };
}

// ------------------------------------------------------------------ a state in R^l (Section V)
const matVec = (A, v) => A.map((row) => row.reduce((s, a, j) => s + a * v[j], 0));
const transpose = (A) => A[0].map((_, j) => A.map((row) => row[j]));
const matMul = (A, B) => A.map((row) => B[0].map((_, j) => row.reduce((s, a, k) => s + a * B[k][j], 0)));
/** The lower Cholesky factor of a symmetric positive definite matrix. */
function cholesky(A) {
  const n = A.length;
  const L = A.map(() => Array(n).fill(0));
  for (let i = 0; i < n; i++) {
    for (let j = 0; j <= i; j++) {
      let s = A[i][j];
      for (let k = 0; k < j; k++) s -= L[i][k] * L[j][k];
      L[i][j] = i === j ? Math.sqrt(s) : s / L[j][j];
    }
  }
  return L;
}
/** The inverse of a small matrix by Gauss–Jordan with partial pivoting. */
function inverse(A) {
  const n = A.length;
  const M = A.map((row, i) => [...row, ...Array.from({ length: n }, (_, j) => (i === j ? 1 : 0))]);
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(M[r][c]) > Math.abs(M[p][c])) p = r;
    [M[c], M[p]] = [M[p], M[c]];
    const d = M[c][c];
    for (let j = 0; j < 2 * n; j++) M[c][j] /= d;
    for (let r = 0; r < n; r++) {
      if (r === c) continue;
      const f = M[r][c];
      for (let j = 0; j < 2 * n; j++) M[r][j] -= f * M[c][j];
    }
  }
  return M.map((row) => row.slice(n));
}
/** N(z; mean, S) for z in R^m, with S⁻¹ and det S given. */
const mvnPdf = (z, mean, Sinv, det) => {
  const d = z.map((v, i) => v - mean[i]);
  const q = d.reduce((s, di, i) => s + di * Sinv[i].reduce((t, a, j) => t + a * d[j], 0), 0);
  return Math.exp(-q / 2) / Math.sqrt((2 * Math.PI) ** z.length * det);
};

/**
 * The optimal joint detector-estimator of a state in R^l (Section V): x ~ N(mean, cov),
 * z = H x + b + v, v ~ N(0, R), constant P_o; model I (falseAlarm: { probability, mean,
 * variance }, one measurement coordinate) or model II (clutter: { rate, mean, variance }, one
 * measurement coordinate), or neither (any H). MAP detection on Z ≠ ∅ (z enters only through
 * the marginal N(z; H x0 + b, H P Hᵀ + R)), the posterior mean x0 + K(z − H x0 − b) with
 * K = P Hᵀ(H P Hᵀ + R)⁻¹ (model II: the mixture over which point is the target's), and on
 * Z = ∅ both rules at once: `hpe` declares {x0}, `lpe` declares ∅. Returns, per rule, the
 * component MSEs E e_i² (e_i(∅, {x'}) = e0/√l, e_i({x}, ∅) = e1/√l) with their standard errors,
 * and the whole-state MSE E e² = Σ_i E e_i² (`total`).
 */
export function mcGaussianVector({
  existence: r, prior, gain: H, offset = null, noiseCov: R, detectionProbability: P,
  falseAlarm = null, clutter = null, falseAlarmError: e0, missError: e1, samples, seed,
}) {
  const g = rng(seed);
  const { mean: x0, cov: Pm } = prior;
  const l = x0.length;
  const m = H.length;
  const b = offset ?? Array(m).fill(0);
  const Lp = cholesky(Pm);
  const Lr = cholesky(R);
  const Ht = transpose(H);
  const S = matMul(matMul(H, Pm), Ht).map((row, i) => row.map((v, j) => v + R[i][j]));
  const Sinv = inverse(S);
  let detS = 1;
  for (const d of cholesky(S).map((row, i) => row[i])) detS *= d * d;
  const K = matMul(matMul(Pm, Ht), Sinv);
  const zMean = matVec(H, x0).map((v, i) => v + b[i]);
  const xhat = (z) => {
    const innov = z.map((v, i) => v - zMean[i]);
    return matVec(K, innov).map((v, i) => v + x0[i]);
  };
  const marginal = (z) => mvnPdf(z, zMean, Sinv, detS);
  const q = falseAlarm ? falseAlarm.probability : 0;
  const lambda = clutter ? clutter.rate : 0;
  if ((q > 0 || lambda > 0) && m !== 1) throw new Error('false observations need one measurement coordinate');
  const rules = ['hpe', 'lpe'];
  const comp = Object.fromEntries(rules.map((k) => [k, Array.from({ length: l }, tally)]));
  const total = Object.fromEntries(rules.map((k) => [k, tally()]));
  const errs = (exists, x, declare, estimate) => Array.from({ length: l }, (_, i) => (exists ? (declare ? (x[i] - estimate[i]) ** 2 : e1 / l) : declare ? e0 / l : 0));
  const add = (rule, e) => {
    for (let i = 0; i < l; i++) comp[rule][i].add(e[i]);
    total[rule].add(e.reduce((s, v) => s + v, 0));
  };
  const addBoth = (e) => { add('hpe', e); add('lpe', e); };
  for (let k = 0; k < samples; k++) {
    const exists = g.uniform() < r;
    const x = exists ? matVec(Lp, Array.from({ length: l }, g.normal)).map((v, i) => v + x0[i]) : null;
    const detected = exists && g.uniform() < P;
    let zTarget = null;
    if (detected) {
      const noise = matVec(Lr, Array.from({ length: m }, g.normal));
      zTarget = matVec(H, x).map((v, i) => v + b[i] + noise[i]);
    }
    const zs = zTarget ? [zTarget] : [];
    if (lambda > 0) {
      const n = g.poisson(lambda);
      for (let i = 0; i < n; i++) zs.push([clutter.mean + Math.sqrt(clutter.variance) * g.normal()]);
    } else if (!exists && q > 0 && g.uniform() < q) zs.push([falseAlarm.mean + Math.sqrt(falseAlarm.variance) * g.normal()]);
    if (zs.length === 0) {
      add('hpe', errs(exists, x, true, x0));
      add('lpe', errs(exists, x, false, x0));
      continue;
    }
    if (lambda === 0) {
      // one point: MAP (39), declare iff r P̄o N(z; H x0 + b, S) ≥ (1 − r) q ψ(z)
      const z = zs[0];
      const declare = q === 0 || r * P * marginal(z) >= (1 - r) * q * gaussPdf(z[0], falseAlarm.mean, falseAlarm.variance);
      addBoth(errs(exists, x, declare, xhat(z)));
      continue;
    }
    // model II: β(Z) = Σ_i N(z_i; H x0 + b, S)/v(z_i); MAP (40); the posterior-mean mixture
    let beta = 0;
    const weighted = Array(l).fill(0);
    for (const z of zs) {
      const ratio = marginal(z) / (lambda * gaussPdf(z[0], clutter.mean, clutter.variance));
      beta += ratio;
      const xz = xhat(z);
      for (let i = 0; i < l; i++) weighted[i] += ratio * xz[i];
    }
    const declare = r * (1 - P + P * beta) >= 1 - r;
    const estimate = x0.map((v, i) => ((1 - P) * v + P * weighted[i]) / (1 - P + P * beta));
    addBoth(errs(exists, x, declare, estimate));
  }
  const out = (t) => t.result();
  return Object.fromEntries(rules.map((k) => [k, { components: comp[k].map(out), total: out(total[k]) }]));
}

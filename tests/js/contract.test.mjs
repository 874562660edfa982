// The JavaScript contract of the npm package `fisst`, in Node: `import * as fisst from 'fisst'`
// with no init call, the names and shapes the issues fix, brute-force oracles written here in
// plain JS, typed errors, and bit-exact parity with the native build.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as fisst from 'fisst';

// ------------------------------------------------------------------ independent JS oracles
function* permutations(n, k) {
  // injective maps {0..k-1} → {0..n-1}
  const used = new Array(n).fill(false);
  const pick = [];
  function* rec() {
    if (pick.length === k) {
      yield pick.slice();
      return;
    }
    for (let j = 0; j < n; j++) {
      if (used[j]) continue;
      used[j] = true;
      pick.push(j);
      yield* rec();
      pick.pop();
      used[j] = false;
    }
  }
  yield* rec();
}

const dist = (a, b) => Math.hypot(...a.map((v, i) => v - b[i]));

/** min over injective maps of Σ min(d, c)^p, smaller set into the larger. */
function cutSum(x, y, c, p) {
  const [s, l] = x.length <= y.length ? [x, y] : [y, x];
  let best = Infinity;
  for (const perm of permutations(l.length, s.length)) {
    let total = 0;
    perm.forEach((j, i) => { total += Math.min(dist(s[i], l[j]), c) ** p; });
    best = Math.min(best, total);
  }
  return s.length === 0 ? 0 : best;
}

function bruteGospa(x, y, c, p, alpha) {
  return (cutSum(x, y, c, p) + (c ** p / alpha) * Math.abs(x.length - y.length)) ** (1 / p);
}

function bruteOspa(x, y, c, p) {
  const n = Math.max(x.length, y.length);
  if (n === 0) return 0;
  return ((cutSum(x, y, c, p) + c ** p * Math.abs(x.length - y.length)) / n) ** (1 / p);
}

function lcg(seed) {
  let s = seed >>> 0;
  return () => ((s = (1664525 * s + 1013904223) >>> 0) / 2 ** 32);
}

function randomSets(rand, maxN, maxM, dim) {
  const pt = () => Array.from({ length: dim }, () => 4 * rand());
  const n = Math.floor(rand() * (maxN + 1));
  const m = Math.floor(rand() * (maxM + 1));
  return [Array.from({ length: n }, pt), Array.from({ length: m }, pt)];
}

const close = (a, b, tol, msg) => assert.ok(Math.abs(a - b) <= tol * (1 + Math.abs(b)), `${msg}: ${a} vs ${b}`);

// ------------------------------------------------------------------ metrics
test('gospa and ospa match brute force on random small sets', () => {
  const rand = lcg(1);
  for (let t = 0; t < 300; t++) {
    const [x, y] = randomSets(rand, 5, 5, 2);
    const c = [0.5, 1.5, 4][t % 3];
    const p = [1, 2, 3][Math.floor(t / 3) % 3];
    for (const alpha of [2, 1, 0.5]) {
      const g = fisst.gospa(x, y, { c, p, alpha });
      close(g.distance, bruteGospa(x, y, c, p, alpha), 1e-12, `gospa ${JSON.stringify({ x, y, c, p, alpha })}`);
    }
    const o = fisst.ospa(x, y, { c, p });
    close(o.distance, bruteOspa(x, y, c, p), 1e-12, 'ospa');
    close(o.distance ** p, o.localisation ** p + o.cardinality ** p, 1e-12, 'ospa parts');
    assert.ok(o.distance <= c * (1 + 1e-15));
  }
});

test('gospa decomposition (alpha = 2) is consistent', () => {
  const rand = lcg(2);
  for (let t = 0; t < 200; t++) {
    const [x, y] = randomSets(rand, 6, 6, 3);
    const c = 1 + 2 * rand();
    const p = 1 + 2 * rand();
    const g = fisst.gospa(x, y, { c, p });
    assert.deepEqual(Object.keys(g).sort(), ['assignment', 'distance', 'falseTargets', 'localisation', 'missed']);
    assert.equal(g.missed, x.length - g.assignment.length);
    assert.equal(g.falseTargets, y.length - g.assignment.length);
    let loc = 0;
    for (const [i, j] of g.assignment) {
      assert.ok(Number.isInteger(i) && Number.isInteger(j));
      const d = dist(x[i], y[j]);
      assert.ok(d < c, 'assigned pairs are closer than c');
      loc += d ** p;
    }
    close(g.localisation, loc, 1e-12, 'localisation');
    close(g.distance ** p, g.localisation + (c ** p / 2) * (g.missed + g.falseTargets), 1e-12, 'decomposition');
  }
});

test('the assignment minimises Σd^p, not Σd (Stone Soup picks the wrong one for p ≠ 1)', () => {
  // Σd is 2 + 2 = 4 both ways here, but Σd² differs: identity 2² + 2² = 8, crossed 0 + ... —
  // check on random sets that fisst's localisation never exceeds the Σd-optimal assignment's.
  const rand = lcg(3);
  let strictly = 0;
  for (let t = 0; t < 500; t++) {
    const n = 2 + Math.floor(rand() * 3);
    const x = Array.from({ length: n }, () => [4 * rand(), 4 * rand()]);
    const y = Array.from({ length: n }, () => [4 * rand(), 4 * rand()]);
    let bestSum = Infinity;
    let atBestSum = Infinity;
    for (const perm of permutations(n, n)) {
      const s = perm.reduce((acc, j, i) => acc + dist(x[i], y[j]), 0);
      const s2 = perm.reduce((acc, j, i) => acc + dist(x[i], y[j]) ** 2, 0);
      if (s < bestSum) { bestSum = s; atBestSum = s2; }
    }
    const g = fisst.gospa(x, y, { c: 100, p: 2 });
    assert.ok(g.localisation <= atBestSum + 1e-9);
    if (g.localisation < atBestSum - 1e-9) strictly++;
  }
  assert.ok(strictly > 0);
});

test('empty sets and the alpha ≠ 2 shape', () => {
  assert.deepEqual(fisst.gospa([], [], { c: 1 }), { distance: 0, localisation: 0, missed: 0, falseTargets: 0, assignment: [] });
  const o = fisst.ospa([], [], { c: 1 });
  assert.equal(o.distance, 0);
  assert.equal(o.localisation, 0);
  assert.equal(o.cardinality, 0);
  const g = fisst.gospa([[0]], [], { c: 2, p: 1, alpha: 1 });
  assert.equal(g.distance, 2);
  assert.equal(g.missed, undefined);
  assert.equal(fisst.ospa([[1, 2]], [], { c: 3 }).distance, 3);
});

// ------------------------------------------------------------------ multi-Bernoulli
function enumeratePmf(r) {
  const pmf = new Array(r.length + 1).fill(0);
  for (let mask = 0; mask < 1 << r.length; mask++) {
    let prob = 1;
    let n = 0;
    r.forEach((ri, i) => {
      if ((mask >> i) & 1) { prob *= ri; n++; } else prob *= 1 - ri;
    });
    pmf[n] += prob;
  }
  return pmf;
}

test('multiBernoulliCardinality is the Poisson-binomial pmf', () => {
  const rand = lcg(4);
  for (let t = 0; t < 50; t++) {
    const r = Array.from({ length: Math.floor(rand() * 11) }, () => rand());
    const pmf = fisst.multiBernoulliCardinality(r);
    assert.ok(Array.isArray(pmf));
    assert.equal(pmf.length, r.length + 1);
    enumeratePmf(r).forEach((v, n) => close(pmf[n], v, 1e-13, `pmf[${n}]`));
  }
  const big = Array.from({ length: 5000 }, (_, i) => (i * 0.6180339887) % 1);
  const pmf = fisst.multiBernoulliCardinality(big);
  assert.ok(pmf.every((v) => v >= 0));
  close(pmf.reduce((a, b) => a + b, 0), 1, 1e-12, 'sum');
});

/** E[d^p] by enumerating outcomes, using the per-outcome errors with far-apart Diracs. */
function bruteMse(r, u, metric, c, p) {
  let total = 0;
  for (let mask = 0; mask < 1 << r.length; mask++) {
    let prob = 1;
    let missed = 0;
    let falseT = 0;
    let detected = 0;
    r.forEach((ri, i) => {
      const e = (mask >> i) & 1;
      prob *= e ? ri : 1 - ri;
      if (e && u[i]) detected++;
      else if (e) missed++;
      else if (u[i]) falseT++;
    });
    const N = detected + missed;
    const k = detected + falseT;
    let err;
    if (metric === 'gospa') err = (c ** p / 2) * (missed + falseT);
    else if (metric === 'uospa') err = c ** p * Math.max(missed, falseT);
    else err = Math.max(N, k) === 0 ? 0 : (c ** p * Math.max(missed, falseT)) / Math.max(N, k);
    total += prob * err;
  }
  return total;
}

test('mbMeanSquareError is Lemma 4 and mbOptimalEstimate is the exhaustive optimum', () => {
  const rand = lcg(5);
  for (let t = 0; t < 60; t++) {
    const n = 1 + Math.floor(rand() * 7);
    const r = Array.from({ length: n }, () => (rand() < 0.15 ? 0.5 : rand()));
    const c = [1, 2][t % 2];
    for (const metric of ['gospa', 'ospa', 'uospa']) {
      let best = Infinity;
      for (let mask = 0; mask < 1 << n; mask++) {
        const report = r.map((_, i) => Boolean((mask >> i) & 1));
        const mse = fisst.mbMeanSquareError({ existence: r, report, metric, c });
        close(mse, bruteMse(r, report, metric, c, 2), 1e-12, `${metric} mse`);
        best = Math.min(best, mse);
      }
      const opt = fisst.mbOptimalEstimate({ existence: r, metric, c });
      assert.deepEqual(Object.keys(opt).sort(), ['meanSquareError', 'report']);
      assert.equal(opt.report.length, n);
      assert.ok(opt.report.every((b) => typeof b === 'boolean'));
      assert.ok(opt.meanSquareError <= best + 1e-12, `${metric} optimum`);
    }
  }
});

test('Example 5 (Madrid and Liverpool) and eq. (11)', () => {
  const est = (r, metric) => fisst.mbOptimalEstimate({ existence: r, metric }).report;
  assert.deepEqual(est([0.4, 0.4], 'ospa'), [true, true]);
  assert.deepEqual(est([0.4, 0.9], 'ospa'), [false, true]);
  assert.deepEqual(est([0.4, 0.1], 'ospa'), [false, false]);
  assert.deepEqual(est([0.4, 0.9], 'gospa'), [false, true]);
  for (const r of [0.1, 0.3, 0.45]) {
    for (let n = 1; n <= 40; n++) {
      const k = est(new Array(n).fill(r), 'ospa').filter(Boolean).length;
      assert.equal(k, (1 - r) ** n < r ? n : 0, `n=${n} r=${r}`);
    }
  }
  const big = Array.from({ length: 1000 }, (_, i) => ((i * 0.7548776662) % 1) * 0.9 + 0.05);
  assert.equal(est(big, 'ospa').length, 1000);
});

// ------------------------------------------------------------------ errors
function throwsNaming(fn, cls, field) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof cls, `expected ${cls.name}, got ${e?.constructor?.name}: ${e?.message}`);
    assert.ok(e.message.includes(field), `message ${JSON.stringify(e.message)} should name ${field}`);
    return true;
  });
}

test('bad input throws a typed error naming the field, and the module survives', () => {
  const pt = [[0, 0]];
  throwsNaming(() => fisst.gospa(pt, pt, { c: 0 }), RangeError, 'c');
  throwsNaming(() => fisst.gospa(pt, pt, { c: -1 }), RangeError, 'c');
  throwsNaming(() => fisst.gospa(pt, pt, { c: NaN }), RangeError, 'c');
  throwsNaming(() => fisst.gospa(pt, pt, { c: Infinity }), RangeError, 'c');
  throwsNaming(() => fisst.gospa(pt, pt, { c: 1, p: 0.9 }), RangeError, 'p');
  throwsNaming(() => fisst.gospa(pt, pt, { c: 1, p: Infinity }), RangeError, 'p');
  throwsNaming(() => fisst.gospa(pt, pt, { c: 1, alpha: 0 }), RangeError, 'alpha');
  throwsNaming(() => fisst.gospa(pt, pt, { c: 1, alpha: 2.01 }), RangeError, 'alpha');
  throwsNaming(() => fisst.gospa([[0, 0], [1]], pt, { c: 1 }), RangeError, 'truth[1]');
  throwsNaming(() => fisst.gospa(pt, [[1, 2, 3]], { c: 1 }), RangeError, 'estimate[0]');
  throwsNaming(() => fisst.gospa([[0, NaN]], pt, { c: 1 }), RangeError, 'truth[0][1]');
  throwsNaming(() => fisst.gospa('points', pt, { c: 1 }), TypeError, 'truth');
  throwsNaming(() => fisst.gospa(pt, [[0, '1']], { c: 1 }), TypeError, 'estimate[0][1]');
  throwsNaming(() => fisst.gospa(pt, pt), TypeError, 'options');
  throwsNaming(() => fisst.gospa(pt, pt, {}), TypeError, 'c');
  throwsNaming(() => fisst.gospa(pt, pt, { c: '2' }), TypeError, 'c');
  throwsNaming(() => fisst.ospa(pt, pt, { c: 1, p: 0 }), RangeError, 'p');
  throwsNaming(() => fisst.multiBernoulliCardinality([0.1, 1.1]), RangeError, 'existence[1]');
  throwsNaming(() => fisst.multiBernoulliCardinality([0.1, NaN]), RangeError, 'existence[1]');
  throwsNaming(() => fisst.multiBernoulliCardinality('0.5'), TypeError, 'existence');
  throwsNaming(() => fisst.mbOptimalEstimate({ existence: [0.5], metric: 'hausdorff' }), RangeError, 'metric');
  throwsNaming(() => fisst.mbOptimalEstimate({ existence: [0.5] }), TypeError, 'metric');
  throwsNaming(() => fisst.mbOptimalEstimate({ existence: [-0.5], metric: 'ospa' }), RangeError, 'existence[0]');
  throwsNaming(() => fisst.mbOptimalEstimate({ existence: [0.5], metric: 'ospa', c: 0 }), RangeError, 'c');
  throwsNaming(() => fisst.mbMeanSquareError({ existence: [0.5], metric: 'ospa', report: [true, true] }), RangeError, 'report');
  throwsNaming(() => fisst.mbMeanSquareError({ existence: [0.5], metric: 'ospa' }), TypeError, 'report');
  // still alive
  assert.equal(fisst.gospa(pt, pt, { c: 1 }).distance, 0);
});

// ------------------------------------------------------------------ parity with native
test('bit-exact parity with the native build (tests/data/parity.json)', () => {
  const fixture = JSON.parse(readFileSync(new URL('../data/parity.json', import.meta.url), 'utf8'));
  assert.ok(fixture.gospa.length > 0);
  for (const { truth, estimate, c, p, alpha, expected } of fixture.gospa) {
    const g = fisst.gospa(truth, estimate, { c, p, alpha });
    assert.equal(g.distance, expected.distance);
    if (alpha === 2) {
      assert.equal(g.localisation, expected.localisation);
      assert.deepEqual(g.assignment, expected.assignment);
    }
  }
  for (const { truth, estimate, c, p, expected } of fixture.ospa) {
    const o = fisst.ospa(truth, estimate, { c, p });
    assert.deepEqual([o.distance, o.localisation, o.cardinality], expected);
  }
  for (const { existence, expected } of fixture.cardinality) {
    assert.deepEqual(fisst.multiBernoulliCardinality(existence), expected);
  }
  for (const { existence, metric, c, p, expected } of fixture.optimal) {
    const e = fisst.mbOptimalEstimate({ existence, metric, c, p });
    assert.deepEqual(e.report, expected.report);
    assert.equal(e.meanSquareError, expected.meanSquareError);
  }
});

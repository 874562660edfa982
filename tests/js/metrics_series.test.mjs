// gospaSeries and ospaSeries (issue 15): whole scenarios in one call, equal to per-step calls,
// the decomposition for α = 2 only, errors naming the step, and size limits that throw a
// RangeError instead of aborting the module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';

function lcg(seed) {
  let s = seed >>> 0;
  return () => (s = (1664525 * s + 1013904223) >>> 0) / 2 ** 32;
}

function scenario(rand, steps, dim = 2) {
  const set = () => Array.from({ length: Math.floor(rand() * 8) }, () => Array.from({ length: dim }, () => 10 * rand()));
  return { truths: Array.from({ length: steps }, set), estimates: Array.from({ length: steps }, set) };
}

test('gospaSeries equals gospa at every step, with its means', () => {
  const rand = lcg(11);
  for (const [p, alpha] of [[2, 2], [1, 2], [3, 2], [2, 1], [1.5, 0.5]]) {
    const { truths, estimates } = scenario(rand, 40);
    const c = 1 + 4 * rand();
    const s = fisst.gospaSeries({ truths, estimates, c, p, alpha });
    assert.equal(s.distance.length, 40);
    let sum = 0;
    truths.forEach((x, t) => {
      const g = fisst.gospa(x, estimates[t], { c, p, alpha });
      assert.equal(s.distance[t], g.distance);
      sum += g.distance;
      if (alpha === 2) {
        assert.equal(s.localisation[t], g.localisation);
        assert.equal(s.missed[t], g.missed);
        assert.equal(s.falseTargets[t], g.falseTargets);
      }
    });
    assert.ok(Math.abs(s.meanDistance - sum / 40) <= 1e-12 * (1 + sum / 40));
    if (alpha === 2) {
      const mm = s.missed.reduce((a, b) => a + b, 0) / 40;
      assert.ok(Math.abs(s.meanMissed - mm) < 1e-12);
      assert.deepEqual(Object.keys(s).sort(), ['distance', 'falseTargets', 'localisation', 'meanDistance', 'meanFalseTargets', 'meanLocalisation', 'meanMissed', 'missed']);
    } else {
      assert.deepEqual(Object.keys(s).sort(), ['distance', 'meanDistance']);
    }
  }
});

test('ospaSeries equals ospa at every step; parts recombine step by step', () => {
  const rand = lcg(12);
  const { truths, estimates } = scenario(rand, 60, 3);
  const s = fisst.ospaSeries({ truths, estimates, c: 4, p: 2 });
  truths.forEach((x, t) => {
    const o = fisst.ospa(x, estimates[t], { c: 4, p: 2 });
    assert.equal(s.distance[t], o.distance);
    assert.equal(s.localisation[t], o.localisation);
    assert.equal(s.cardinality[t], o.cardinality);
  });
  const mean = (a) => a.reduce((x, y) => x + y, 0) / a.length;
  assert.ok(Math.abs(s.meanLocalisation - mean(s.localisation)) < 1e-12);
  assert.ok(Math.abs(s.meanCardinality - mean(s.cardinality)) < 1e-12);
  const empty = fisst.ospaSeries({ truths: [], estimates: [], c: 1 });
  assert.deepEqual(empty, { distance: [], localisation: [], cardinality: [], meanDistance: 0, meanLocalisation: 0, meanCardinality: 0 });
});

test('series errors name the step and the field', () => {
  const bad = (fn, cls, start) =>
    assert.throws(fn, (e) => e instanceof cls && e.message.startsWith(start), start);
  bad(() => fisst.gospaSeries({ truths: [[[0, 0]]], estimates: [], c: 1 }), RangeError, 'options.estimates');
  bad(() => fisst.gospaSeries({ truths: [[[0, 0]], [[0, NaN]]], estimates: [[], []], c: 1 }), RangeError, 'options.truths[1][0][1]');
  bad(() => fisst.ospaSeries({ truths: [[]], estimates: [[[0], [1, 2]]], c: 1 }), RangeError, 'options.estimates[0][1]');
  bad(() => fisst.gospaSeries({ truths: [], estimates: [], c: 0 }), RangeError, 'options.c');
  bad(() => fisst.gospaSeries({ truths: 'x', estimates: [], c: 1 }), TypeError, 'options.truths');
  bad(() => fisst.ospaSeries({ truths: [], estimates: [], c: 1, alpha: 1 }), TypeError, 'options has an unknown key "alpha"');
});

test('a scene whose pairs closer than c would exhaust wasm memory throws a RangeError, and the module lives', () => {
  // 6,000 × 6,000 points all within c of each other: 3.6e7 candidate pairs, past the wasm cap.
  const rand = lcg(13);
  const pts = Array.from({ length: 6000 }, () => [rand(), rand()]);
  assert.throws(() => fisst.gospa(pts, pts, { c: 10 }), (e) => e instanceof RangeError && /closer than c/.test(e.message) && e.message.startsWith('truth'));
  assert.equal(fisst.gospa([[0]], [[1]], { c: 5, p: 1 }).distance, 1);
});

// ---- issue 26 point 7: the fuzzer's edges of the metrics and multi-Bernoulli exports (their
// entries were in fuzz/known-edges.mjs): no silent NaN, and every call bounded by a cap that
// throws a RangeError naming the field.
const rangeError = (start) => (e) => e instanceof RangeError && e.message.startsWith(start);
const halves = (n) => new Float64Array(n).fill(0.5);
// The smaller of wall-clock and CPU time of `f()`, in ms (as the fuzzer's watchdog counts it).
function timed(f) {
  const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
  const [w0, c0] = [performance.now(), cpu()];
  const value = f();
  return { value, ms: Math.min(performance.now() - w0, cpu() - c0) };
}

test('gospaSeries-c-overflow, ospaSeries-c-overflow: means of distances near the largest double are finite', () => {
  const g = fisst.gospaSeries({ truths: [[[0]], [[0]]], estimates: [[], []], c: Number.MAX_VALUE, p: 2 });
  assert.ok(Number.isFinite(g.meanDistance) && g.meanDistance > 1e308);
  assert.equal(g.meanDistance, g.distance[0]);
  const o = fisst.ospaSeries({ truths: [[[0]], [[0]]], estimates: [[], []], c: 1e308, p: 1 });
  assert.deepEqual([o.meanDistance, o.meanCardinality, o.meanLocalisation], [1e308, 1e308, 0]);
});

test('gospaSeries-alpha-subnormal: GOSPA with α = 5e-324 is finite (computed times α)', () => {
  const s = fisst.gospaSeries({ truths: [[[0]]], estimates: [[]], c: 1, alpha: 5e-324 });
  const expected = 1 / Math.sqrt(5e-324);
  assert.ok(Math.abs(s.distance[0] - expected) <= 1e-15 * expected, String(s.distance));
  assert.equal(s.meanDistance, s.distance[0]);
  assert.equal(fisst.gospa([[0]], [], { c: 1, alpha: 5e-324 }).distance, s.distance[0]);
});

test('mbOptimalEstimate-subnormal-c-alpha: tiny c and α give numbers, never NaN', () => {
  assert.equal(fisst.mbOptimalEstimate({ existence: [], metric: 'gospa', c: 5e-324, alpha: 5e-324 }).meanSquareError, 0);
  const e = fisst.mbOptimalEstimate({ existence: [0.3, 0.6], metric: 'gospa', c: 5e-324, alpha: 5e-324 });
  assert.ok(!Number.isNaN(e.meanSquareError));
  assert.equal(fisst.mbMeanSquareError({ existence: [0.3], report: [true], metric: 'gospa', c: 1, alpha: 5e-324 }), Infinity);
});

test('linearAssignment-cost-overflow: costs near ±1e308 give the optimum or ±Infinity, never NaN', () => {
  const a = fisst.linearAssignment([[1e308, 1e308], [1e308, 1e308]]);
  assert.deepEqual([a.pairs.length, a.cost], [2, Infinity]);
  assert.equal(fisst.linearAssignment([[-1e308, 1e308], [1e308, -1e308]]).cost, -Infinity);
  const b = fisst.linearAssignment([[1e308, 5e307], [5e307, 1e308], [1e307, 3e307]]);
  assert.deepEqual(b.pairs, [[0, 1], [2, 0]]);
  assert.equal(b.cost, 5e307 + 1e307);
});

test('multiBernoulliCardinality-1e6, multiBernoulliLeaveOneOut-1e6: capped at 20,000 and 1,000 components', () => {
  assert.throws(() => fisst.multiBernoulliCardinality(halves(1e6)), rangeError('existence has 1000000 components, at most 20000'));
  assert.throws(() => fisst.multiBernoulliLeaveOneOut(halves(1001)), rangeError('existence has 1001 components, at most 1000'));
  const { value: pmf, ms } = timed(() => fisst.multiBernoulliCardinality(halves(20_000)));
  assert.equal(pmf.length, 20_001);
  assert.ok(ms < 2000, `${ms} ms at the cap`);
  const loo = timed(() => fisst.multiBernoulliLeaveOneOut(halves(1000)));
  assert.equal(loo.value.length, 1000);
  assert.ok(loo.ms < 2000, `${loo.ms} ms at the cap`);
});

test('mb estimators at 10^6 components: a RangeError naming options.existence (GOSPA with α = 2 uncapped)', () => {
  const big = halves(1e6);
  const report = Array.from({ length: 1e6 }, (_, i) => i % 2 === 0);
  assert.throws(() => fisst.mbOptimalEstimate({ existence: big, metric: 'ospa' }), rangeError('options.existence has 1000000 components, at most 20000'));
  assert.throws(() => fisst.mbOptimalEstimate({ existence: halves(4001), metric: 'ospa' }), rangeError('options.existence has 4001 components, at most 4000'));
  assert.throws(() => fisst.mbOptimalEstimate({ existence: big, metric: 'uospa' }), rangeError('options.existence'));
  assert.throws(() => fisst.mbMeanSquareError({ existence: big, report, metric: 'ospa' }), rangeError('options.existence'));
  assert.throws(() => fisst.mbAlternativeEstimate({ existence: big, method: 'mam', lnPeak: new Float64Array(1e6), lnC: 0 }), rangeError('options.existence'));
  assert.throws(() => fisst.mbAlternativeEstimate({ existence: big, method: 'map-cardinality' }), rangeError('options.existence'));
  assert.equal(fisst.mbOptimalEstimate({ existence: halves(10), metric: 'gospa' }).report.length, 10);
  const { ms } = timed(() => fisst.mbOptimalEstimate({ existence: halves(4000), metric: 'ospa' }));
  assert.ok(ms < 2000, `${ms} ms at the cap`);
});

test('mbIdenticalComponentCounts-cap: maxComponents up to 300, under 2 s there', () => {
  assert.throws(() => fisst.mbIdenticalComponentCounts({ existence: 0.5, maxComponents: 1000 }), rangeError('options.maxComponents must be an integer in [1, 300], got 1000'));
  const { value, ms } = timed(() => fisst.mbIdenticalComponentCounts({ existence: 0.5, maxComponents: 300 }));
  assert.equal(value.n.length, 300);
  assert.ok(ms < 2000, `${ms} ms at the cap`);
});

test('gospa-1e6-points, ospa-1e6-points, *-1e6-vs-1, *Series-1e6-steps: caps on points, candidate pairs and dense work', () => {
  const line = (n, step) => Array.from({ length: n }, (_, i) => [i * step]);
  const many = line(524_289, 10);
  assert.throws(() => fisst.gospa(many, [], { c: 1 }), rangeError('truth: points in truth and estimate = 524289 exceeds MAX_TOTAL_POINTS'));
  assert.throws(() => fisst.ospa([[0]], many, { c: 1 }), rangeError('estimate: points'));
  assert.throws(() => fisst.uospa(many, [[0]], { c: 1 }), rangeError('truth: points'));
  const steps = Array.from({ length: 131_073 }, () => [[0]]);
  assert.throws(() => fisst.gospaSeries({ truths: steps, estimates: steps, c: 1 }), rangeError('options.truths: points over all steps'));
  assert.throws(() => fisst.ospaSeries({ truths: steps, estimates: steps, c: 1 }), rangeError('options.truths: points over all steps'));
  const million = Array.from({ length: 1e6 }, () => [[0]]);
  const refused = timed(() => assert.throws(() => fisst.gospaSeries({ truths: million, estimates: million, c: 1 }), rangeError('options.truths has 1000000 steps, at most 262144 are supported')));
  assert.ok(refused.ms < 100, `${refused.ms} ms to refuse 10^6 steps`);
  // 8,193 × 8,193 points within c: more candidate pairs than 2^26, refused before any distance.
  const dense = line(8193, 1e-6);
  assert.throws(() => fisst.gospa(dense, dense, { c: 1 }), rangeError('truth × estimate candidate pairs must be at most MAX_CANDIDATE_PAIRS'));
  // 1,100 × 1,100 points within c: more dense assignment work than 2^30.
  const block = line(1100, 1e-6);
  assert.throws(() => fisst.ospa(block, block, { c: 1 }), rangeError('truth × estimate dense assignment work must be at most MAX_DENSE_WORK = 2^30'));
  // At the caps: under 2 s.
  const one = timed(() => fisst.uospa(line(524_287, 0.001), [[0]], { c: 10 }));
  assert.ok(one.ms < 2000, `${one.ms} ms for 524,287 points against one`);
  const series = timed(() => fisst.gospaSeries({ truths: steps.slice(1), estimates: steps.slice(1), c: 1 }));
  assert.equal(series.value.meanDistance, 0);
  assert.ok(series.ms < 2000, `${series.ms} ms for a series at its cap`);
  assert.equal(fisst.gospa([[0]], [[1]], { c: 5, p: 1 }).distance, 1);
});

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

// A user's first-day mistakes with the Bernoulli filters (issue 26 point 1): each throws the
// error class the contract promises, with a message naming the field that disagrees and the
// one it disagrees with, in matrix terms; a covariance error says which property fails. A
// positive semidefinite Q (noise on the velocity only) is accepted by both filters.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as fisst from 'fisst';

const eye = (n, v = 1) => Array.from({ length: n }, (_, i) => Array.from({ length: n }, (_, j) => (i === j ? v : 0)));
const diag = (d) => d.map((v, i) => d.map((_, j) => (i === j ? v : 0)));
const F4 = [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]];
const Q4 = [[0.01 / 3, 0, 0.005, 0], [0, 0.01 / 3, 0, 0.005], [0.005, 0, 0.01, 0], [0, 0.005, 0, 0.01]];
const prior4 = { weight: 1, mean: [0, 0, 1, 0], cov: diag([1, 1, 0.1, 0.1]) };
const H = [[1, 0, 0, 0], [0, 1, 0, 0]];

/** A valid 2-D-position, 4-state configuration, with `over` laid over it. */
const config = (over = {}) => ({
  existence: 0.5,
  mixture: [prior4],
  transition: { F: F4, Q: Q4 },
  detection: { probability: 0.9 },
  clutter: { rate: 0.25, density: 0.01 },
  likelihood: { H, R: eye(2, 0.25) },
  particles: 200,
  seed: 3,
  ...over,
});

const classes = [['GmBernoulliFilter', fisst.GmBernoulliFilter], ['ParticleBernoulliFilter', fisst.ParticleBernoulliFilter]];

/** `fn` throws an instance of `cls` whose message is exactly `message`. */
const throwsExactly = (fn, cls, message) =>
  assert.throws(fn, (e) => {
    assert.ok(e instanceof cls, `${e}`);
    assert.equal(e.message, message);
    return true;
  });

const constructorMistakes = [
  ['a 2×2 F with a 4-D mixture', { transition: { F: eye(2), Q: eye(2, 0.1) }, likelihood: undefined },
    'config.mixture[0].mean has length 4 but config.transition.F is 2×2'],
  ['a 2×2 Q with a 4×4 F', { transition: { F: F4, Q: eye(2, 0.1) } },
    'config.transition.Q is 2×2 but config.transition.F is 4×4'],
  ['an H without F\'s columns', { likelihood: { H: [[1, 0, 0], [0, 1, 0]], R: eye(2) } },
    'config.likelihood.H is 2×3 but config.transition.F is 4×4'],
  ['an R without H\'s rows', { likelihood: { H, R: eye(3) } },
    'config.likelihood.R is 3×3 but config.likelihood.H is 2×4'],
  ['a 2-D birth with a 4×4 F', { birth: { probability: 0.1, mixture: [{ weight: 1, mean: [0, 0], cov: eye(2) }] } },
    'config.birth.mixture[0].mean has length 2 but config.transition.F is 4×4'],
  ['positionDims above the state dimension', { positionDims: 6 },
    'config.positionDims is 6 but config.transition.F is 4×4'],
  ['a 3-D field of view', { detection: { probability: 0.9, fov: { box: { min: [0, 0, 0], max: [1, 1, 1] } } } },
    'config.detection.fov.box.min has length 3 but config.positionDims is 2'],
  ['a 3-D exclusion', { exclusions: [{ disc: { center: [0, 0, 0], radius: 1 } }] },
    'config.exclusions[0].disc.center has length 3 but config.positionDims is 2'],
  ['an asymmetric Q', { transition: { F: F4, Q: [[1, 0.5, 0, 0], [0.4, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] } },
    'config.transition.Q is not symmetric: [0][1] = 0.5 but [1][0] = 0.4'],
  ['an indefinite Q', { transition: { F: F4, Q: diag([0.1, 0.1, 0.1, -0.25]) } },
    'config.transition.Q is not positive semidefinite (smallest eigenvalue -0.25)'],
  ['an indefinite mixture covariance', { mixture: [{ ...prior4, cov: diag([1, 1, 1, -0.25]) }] },
    'config.mixture[0].cov is not positive definite (smallest eigenvalue -0.25)'],
  ['an indefinite R', { likelihood: { H, R: diag([1, -0.25]) } },
    'config.likelihood.R is not positive definite (smallest eigenvalue -0.25)'],
];

for (const [name, cls] of classes) {
  for (const [what, over, message] of constructorMistakes) {
    test(`new ${name} with ${what}: RangeError naming both fields`, () => {
      throwsExactly(() => new cls(config(over)), RangeError, message);
    });
  }

  test(`${name}.update with a 3-D report or a 3-D measurement names the config's field too`, () => {
    const f = new cls(config());
    throwsExactly(() => f.update([{ box: { min: [0, 0, 0], max: [1, 1, 1] } }]), RangeError,
      'reports[0].box.min has length 3 but config.positionDims is 2');
    throwsExactly(() => f.update([{ union: [{ disc: { center: [0, 0, 0], radius: 1 } }] }]), RangeError,
      'reports[0].union[0].disc.center has length 3 but config.positionDims is 2');
    throwsExactly(() => f.update({ measurements: [[1, 2, 3]] }), RangeError,
      'reports.measurements[0] has length 3 but config.likelihood.H is 2×4');
    // the filter is still usable
    f.update([{ disc: { center: [0, 0], radius: 3 } }]);
    f.free();
  });

  test(`${name} accepts a positive semidefinite Q (noise on the velocity only)`, () => {
    const f = new cls(config({ transition: { F: F4, Q: diag([0, 0, 0.01, 0.01]) } }));
    for (let k = 0; k < 4; k++) {
      f.predict();
      f.update([{ disc: { center: [k, 0], radius: 3 } }]);
      f.update({ measurements: [[k, 0.5]] });
    }
    const e = f.estimate();
    assert.ok(e.existence > 0 && e.existence <= 1);
    assert.ok(e.mean.every(Number.isFinite) && e.cov.flat().every(Number.isFinite), JSON.stringify(e));
    f.free();
  });
}

test('gmBernoulliPredict and gmBernoulliUpdate use the same wording', () => {
  throwsExactly(() => fisst.gmBernoulliPredict({ existence: 0.5, mixture: [prior4], transition: { F: eye(2), Q: eye(2) } }),
    RangeError, 'options.mixture[0].mean has length 4 but options.transition.F is 2×2');
  throwsExactly(() => fisst.gmBernoulliPredict({ existence: 0.5, mixture: [prior4], transition: { F: F4, Q: eye(2) } }),
    RangeError, 'options.transition.Q is 2×2 but options.transition.F is 4×4');
  const update = { existence: 0.5, mixture: [prior4], detection: { probability: 0.9 }, clutter: { rate: 0.25, density: 0.01 } };
  throwsExactly(() => fisst.gmBernoulliUpdate({ ...update, reports: [{ disc: { center: [0, 0, 0], radius: 1 } }] }),
    RangeError, 'options.reports[0].disc.center has length 3 but options.positionDims is 2');
  throwsExactly(() => fisst.gmBernoulliUpdate({ ...update, measurements: [[0, 0]], likelihood: { H: [[1, 0, 0]], R: [[1]] } }),
    RangeError, 'options.likelihood.H is 1×3 but options.mixture[0].mean has length 4');
  throwsExactly(() => fisst.gmBernoulliUpdate({ ...update, measurements: [[0, 0]], likelihood: { H, R: eye(3) } }),
    RangeError, 'options.likelihood.R is 3×3 but options.likelihood.H is 2×4');
  const q = fisst.gmBernoulliPredict({ existence: 0.5, mixture: [prior4], transition: { F: F4, Q: diag([0, 0, 0.01, 0.01]) } });
  assert.ok(q.mixture[0].cov.flat().every(Number.isFinite));
});

// Edges the widened boundary fuzzer finds in the current package (issue 26, point 7), as data:
// each entry is the export, a minimal input, what it does today (`found`), what it should do
// (`expected`: "finite result", or "RangeError naming <field>"), and `matches(args, message)`,
// which tells the fuzzer that one of its failures is this edge (`largeLabel`: the fixed case of
// specs.mjs `largeCases` that shows it, for the size edges).
//
// Not a test: fuzz.test.mjs skips the failures these match (its SKIP list names them) so that
// `make test` stays green while the widened generators run; when a fix lands, remove its id
// from SKIP there (and its entry here, or keep it as a regression in regressions.test.mjs).
//   node fuzz/known-edges.mjs   prints, for each entry, whether it still does what `found` says
//                               (the large inputs run in a child process under the watchdog).
import * as fisst from 'fisst';
import { check, findNaN, runLarge, show } from './harness.mjs';
import { largeCases, specs } from './specs.mjs';

const MAX = Number.MAX_VALUE;
const million = () => new Float64Array(1_000_000).fill(0.5);
// Whether any number in `v` has a magnitude of at least `m` (the extremes that overflow).
const anyHuge = (v, m = 1e300) => {
  if (typeof v === 'number') return Math.abs(v) >= m;
  if (v === null || typeof v !== 'object') return false;
  return Object.values(v).some((x) => anyHuge(x, m));
};
const slow = (message) => /took \d+ ms|still running/.test(message);

export const knownEdges = [
  {
    id: 'splitForRegions-huge-corner',
    export: 'splitForRegions',
    // A correlated Gaussian and a box with both coordinates of one corner beyond ~1.3e154 (their
    // product overflows in the exact bivariate normal probability); diagonal covariances and a
    // single huge coordinate are fine. Also with { min: [0, 0], max: [1e308, 1e308] }.
    input: [{ mixture: [{ weight: 1, mean: [0, 0], cov: [[1, 0.5], [0.5, 1]] }], regions: [{ box: { min: [-1e308, -1e308], max: [0, 0] } }], maxDepth: 0 }],
    found: 'NaN at result.exactInside (from |corner| ≈ 1.4e154 on: -1e154 gives 1/3, -1e155 NaN)',
    expected: 'finite result',
    matches: (args, message) => /^NaN at result\.exactInside/.test(message) && anyHuge(args[0]?.regions, 1e150),
  },
  {
    id: 'fovCardinality-huge-corner',
    export: 'fovCardinality',
    // The same exact box probability as splitForRegions-huge-corner: a correlated Gaussian and
    // a FoV box whose corner has both coordinates huge. With a poisson rfs the same FoV is a
    // RangeError that blames the input: "options.rfs.poisson must be finite and >= 0, got NaN".
    input: [{ rfs: { multiBernoulli: [{ existence: 0.5, mean: [0, 0], cov: [[1, 0.5], [0.5, 1]] }] }, fov: { box: { min: [0, 0], max: [1e308, 1e308] } } }],
    found: 'NaN at result.pmf[0], mean, variance, massInFov[0]; poisson: RangeError "options.rfs.poisson must be finite and >= 0, got NaN"',
    expected: 'finite result',
    matches: (args, message) => (/^NaN at result\./.test(message) || /got NaN/.test(message)) && anyHuge(args[0]?.fov, 1e150),
  },
  {
    id: 'mixtureDensityGrid-weight-overflow',
    export: 'mixtureDensityGrid',
    // weight × peak density overflows: 1e308 · 159 (σ² = 1e-3); also weight 1e300 with σ² = 1e-300.
    input: [{ mixture: [{ weight: 1e308, mean: [0, 0], cov: [[0.001, 0], [0, 0.001]] }], grid: { x: [0, 0, 1], y: [0, 0, 1] } }],
    found: 'NaN at result[0] (weight 1e308 with σ² = 1 gives 1.6e307, fine)',
    expected: 'finite result',
    matches: (args, message) => /^NaN at result\[/.test(message) && args[0].mixture.some((c) => Math.abs(c.weight) >= 1e100),
  },
  {
    id: 'mmucEstimate-huge-radius',
    export: 'mmucEstimate',
    // Found through multiBernoulliPointEstimate (the sweep, radius = 1e308); bernoulliEstimate
    // and multiBernoulliPointEstimate give the same NaN estimate and mmuc. Three distinct
    // particles are needed: [[0, 0], [1e308, 0], [0, 0]] and two particles are fine.
    exports: ['mmucEstimate', 'bernoulliEstimate', 'multiBernoulliPointEstimate'],
    input: [{ density: { particles: [[1e-53, 0], [1e308, 0], [0, 0]] }, radius: 1e308 }],
    found: 'center [NaN, NaN] (method "particles-exact"); bernoulliEstimate / multiBernoulliPointEstimate: estimate and mmuc NaN',
    expected: 'finite result',
    matches: (args, message) => /^NaN at result\.(center|estimate|mmuc|estimates|components)/.test(message) && Math.abs(args[0]?.radius) >= 1e100,
  },
  {
    id: 'ParticleBernoulliFilter-mean-overflow',
    export: 'ParticleBernoulliFilter',
    // The prior at the largest double: predicted particles past it make the MMSE mean NaN
    // (fuzz #9 made the same overflow from F a RangeError naming config.transition; from the
    // prior it is not caught). 10 particles give a finite mean; 123 do not.
    input: [{ existence: 0, mixture: [{ weight: 1, mean: [Number.MAX_VALUE, 0], cov: [[1, 0], [0, 1]] }], transition: { F: [[1, 0], [0, 1]], Q: [[1, 0], [0, 1]] }, detection: { probability: 0 }, clutter: { rate: 0, density: 0 }, particles: 123, seed: 0 }, []],
    shown: 'new ParticleBernoulliFilter({ existence: 0, mixture: [{ weight: 1, mean: [Number.MAX_VALUE, 0], cov: I }], transition: { F: I, Q: I }, detection: { probability: 0 }, clutter: { rate: 0, density: 0 }, particles: 123, seed: 0 }); predict(); estimate()',
    found: 'estimate().mean[0] NaN and cov[0][0], cov[0][1] NaN after predict()',
    expected: 'finite result, or RangeError naming config.mixture (or config.transition)',
    matches: (args, message) => /^NaN at result\.e\./.test(message) && anyHuge(args[0]?.mixture, 1e300),
  },
  {
    id: 'GmBernoulliFilter-estimate-cov-overflow',
    export: 'GmBernoulliFilter',
    // Components ±1e308 / Number.MAX_VALUE apart on different axes: the spread term of the MMSE
    // covariance is ∞ on the diagonal (fine) and NaN off it (fuzz #6 fixed the 1e300 case).
    input: [{ existence: 0, mixture: [{ weight: 1 / 3, mean: [0, -1e308, 0, 0], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }, { weight: 2 / 3, mean: [0, 0, 0, Number.MAX_VALUE], cov: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }], transition: { F: [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], Q: [[0.0013333333333333333, 0, 0.002, 0], [0, 0.0013333333333333333, 0, 0.002], [0.002, 0, 0.004, 0], [0, 0.002, 0, 0.004]] }, detection: { probability: 0 }, reduction: { maxComponents: 2 }, clutter: { rate: 0, density: 0.1 } }, []],
    found: 'predict(); update([]); estimate().cov has NaN entries (first at cov[0][1])',
    expected: 'finite result (±Infinity where the spread itself overflows), or RangeError naming config.mixture',
    matches: (args, message) => /^NaN at result\.e\.cov/.test(message) && anyHuge(args[0]?.mixture, 1e300),
  },
  // Found at the size caps by `make fuzz` (specs.mjs largeCases; not in the make-test slice):
  // each call ran past 2.5 s of CPU time and was killed by the watchdog. Inputs: see the label.
  ...[
    ['reduceMixture-runnalls-cap', 'reduceMixture', "reduceMixture: 5000 components to 1 (Runnalls' cap)", 'under 2 s at the 5000-component cap of its own error message (2.4 s of CPU time measured; that cap is not in the .d.ts)'],
    ['reduceMixture-1e6', 'reduceMixture', 'reduceMixture: 10^6 components, maxComponents 10^6 (cap)', 'RangeError naming options.mixture (no documented cap on its length)'],
    ['bernoulliEstimate-mixture-1e4', 'bernoulliEstimate', 'bernoulliEstimate: 10,000-component mixture', 'RangeError naming options.density (or under 2 s)'],
    ['mmucEstimate-1e6-particles', 'mmucEstimate', 'mmucEstimate: 10^6 particles (2D)', 'RangeError naming options.density.particles (or under 2 s)'],
    ['gmBernoulliUpdate-caps', 'gmBernoulliUpdate', 'gmBernoulliUpdate: 10,000 components × 10,000 measurements (caps)', 'under 2 s at the documented caps (or a joint cap naming options.measurements)'],
    ['GmBernoulliFilter-caps', 'GmBernoulliFilter', 'GmBernoulliFilter: 10,000 components, 10,000 measurements', 'under 2 s per call at the documented caps (or a joint cap naming reports)'],
    ['ParticleBernoulliFilter-caps', 'ParticleBernoulliFilter', 'ParticleBernoulliFilter: 200,000 particles, 1000 reports', 'under 2 s per call at the documented caps (or a joint cap naming reports)'],
    ['SensorControlRun-cap', 'SensorControlRun', 'SensorControlRun: 20,000 particles × 50 future scans (10^6 cap), renyi', 'step() under 2 s at the documented cap (or a lower cap naming options.particles)'],
  ].map(([id, name, label, expected]) => ({
    id,
    export: name,
    get input() {
      return largeCases.find((c) => c.label === label).args();
    },
    shown: `specs.mjs largeCases: "${label}"`,
    largeLabel: label,
    found: 'runs past 2.5 s of CPU time (killed by the watchdog)',
    expected,
    matches: () => false,
  })),
];

// ------------------------------------------------------------------ node fuzz/known-edges.mjs
if (import.meta.url === `file://${process.argv[1]}`) {
  for (const edge of knownEdges) {
    const spec = specs.find((s) => s.name === edge.export);
    let message;
    if (edge.largeLabel) {
      const [r] = await runLarge({ labels: [edge.largeLabel] });
      message = r.failure;
    } else {
      message = check(spec, edge.input);
    }
    const shown = edge.shown ?? edge.input.map((a) => show(a)).join(', ');
    const call = /^(new |specs\.mjs)/.test(shown) ? shown : `${edge.export}(${shown})`;
    console.log(`${message ? 'STILL' : 'FIXED'} ${edge.id}: ${call}\n    today: ${message ?? 'passes the checks'}\n    expected: ${edge.expected}`);
  }
  void fisst;
  void findNaN;
}

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
    id: 'gospaSeries-c-overflow',
    export: 'gospaSeries',
    input: [{ truths: [[[0]], [[0]]], estimates: [[], []], c: MAX, p: 2 }],
    found: 'meanDistance NaN; distance [1.27e308, 1.27e308] (the mean over steps of c^p-sized terms overflows)',
    expected: 'finite result',
    matches: (args, message) => /^NaN at result\.mean/.test(message) && anyHuge(args[0]?.c, 1e100),
  },
  {
    id: 'ospaSeries-c-overflow',
    export: 'ospaSeries',
    input: [{ truths: [[[0]], [[0]]], estimates: [[], []], c: 1e308, p: 1 }],
    found: 'meanDistance and meanCardinality NaN; distance [1e308, 1e308] (the sum over steps overflows)',
    expected: 'finite result',
    matches: (args, message) => /^NaN at result\.mean/.test(message) && anyHuge(args[0]?.c, 1e100),
  },
  {
    id: 'gospaSeries-alpha-subnormal',
    export: 'gospaSeries',
    // gospa itself gives distance Infinity here ((c^p / α)^(1/p) overflows); the series' mean NaN.
    input: [{ truths: [[[0]]], estimates: [[]], c: 1, alpha: 5e-324 }],
    found: 'distance [Infinity], meanDistance NaN (gospa([[0]], [], { c: 1, alpha: 5e-324 }) gives Infinity: (c^p / α)^(1/p) overflows)',
    expected: 'finite result, or RangeError naming options.alpha (a lower bound on α)',
    matches: (args, message) => /^NaN at result\./.test(message) && Math.abs(args[0]?.alpha) < 1e-300,
  },
  {
    id: 'linearAssignment-cost-overflow',
    export: 'linearAssignment',
    input: [[[1e308, 1e308], [1e308, 1e308]]],
    found: 'cost NaN, pairs right (the true sum 2e308 overflows; also [[-1e308, -1e308], [-1e308, -1e308]] and [[-1e308, 1e308], [1e308, -1e308]], whose optimum is -2e308 / 0)',
    expected: 'finite result (or ±Infinity where the optimal sum itself overflows; never NaN), or RangeError naming cost',
    matches: (args, message) => /^NaN at result\.cost/.test(message) && anyHuge(args[0], 1e150),
  },
  {
    id: 'mbOptimalEstimate-subnormal-c-alpha',
    export: 'mbOptimalEstimate',
    // c^p / α = 0 / 0 (with c = 1 and α = 5e-324 the meanSquareError is Infinity instead).
    input: [{ existence: [], metric: 'gospa', c: 5e-324, alpha: 5e-324 }],
    found: 'meanSquareError NaN',
    expected: 'finite result, or RangeError naming options.alpha / options.c',
    matches: (args, message) => /^NaN at result\.meanSquareError/.test(message) && Math.abs(args[0]?.alpha) < 1e-300,
  },
  {
    id: 'multiBernoulliCardinality-1e6',
    export: 'multiBernoulliCardinality',
    get input() {
      return [million()];
    },
    shown: '[new Float64Array(1e6).fill(0.5)]',
    largeLabel: 'multiBernoulliCardinality: 10^6 existence probabilities',
    found: 'runs for more than 6 s (O(n²) Poisson-binomial pmf)',
    expected: 'RangeError naming existence',
    matches: (args, message) => slow(message) && args[0]?.length > 20_000,
  },
  {
    id: 'multiBernoulliLeaveOneOut-1e6',
    export: 'multiBernoulliLeaveOneOut',
    get input() {
      return [million()];
    },
    shown: '[new Float64Array(1e6).fill(0.5)]',
    largeLabel: 'multiBernoulliLeaveOneOut: 10^6 existence probabilities',
    found: 'runs for more than 6 s (n² numbers: the n leave-one-out pmfs)',
    expected: 'RangeError naming existence',
    matches: (args, message) => slow(message) && args[0]?.length > 2000,
  },
  // Found at the size caps by `make fuzz` (specs.mjs largeCases; not in the make-test slice):
  // each call ran past 2.5 s of CPU time and was killed by the watchdog. Inputs: see the label.
  ...[
    ['gospa-1e6-points', 'gospa', 'gospa: 10^6 × 10^6 points (1D)', 'RangeError naming truth/estimate (no documented cap on the set sizes)'],
    ['ospa-1e6-points', 'ospa', 'ospa: 10^6 × 10^6 points (1D)', 'RangeError naming truth/estimate (no documented cap on the set sizes)'],
    ['gospaSeries-1e6-steps', 'gospaSeries', 'gospaSeries: 10^6 steps of one point each side', 'RangeError naming options.truths (or under 2 s)'],
    ['ospaSeries-1e6-steps', 'ospaSeries', 'ospaSeries: 10^6 steps of one point each side', 'RangeError naming options.truths (or under 2 s)'],
    ['ospa-1e6-vs-1', 'ospa', 'ospa: 10^6 truth points, one estimate', 'under 2 s (1.5–2.1 s of CPU time measured on a loaded machine: at the bound)'],
    ['uospa-1e6-vs-1', 'uospa', 'uospa: 10^6 truth points, one estimate', 'under 2 s (1.5–2.1 s of CPU time measured on a loaded machine: at the bound)'],
    ['mbOptimalEstimate-ospa-1e6', 'mbOptimalEstimate', 'mbOptimalEstimate (ospa): 10^6 existence probabilities', 'RangeError naming options.existence'],
    ['mbOptimalEstimate-uospa-1e6', 'mbOptimalEstimate', 'mbOptimalEstimate (uospa): 10^6 existence probabilities', 'RangeError naming options.existence'],
    ['mbMeanSquareError-ospa-1e6', 'mbMeanSquareError', 'mbMeanSquareError (ospa): 10^6 components', 'RangeError naming options.existence'],
    ['mbAlternativeEstimate-mam-1e6', 'mbAlternativeEstimate', 'mbAlternativeEstimate (mam): 10^6 components', 'RangeError naming options.existence'],
    ['mbAlternativeEstimate-map-cardinality-1e6', 'mbAlternativeEstimate', 'mbAlternativeEstimate (map-cardinality): 10^6 components', 'RangeError naming options.existence'],
    ['mbIdenticalComponentCounts-cap', 'mbIdenticalComponentCounts', 'mbIdenticalComponentCounts: maxComponents 1000 (cap)', 'under 2 s at the documented cap (or a lower cap naming options.maxComponents)'],
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

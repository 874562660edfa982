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
  // Found at the size caps by `make fuzz` (specs.mjs largeCases; not in the make-test slice):
  // each call ran past 2.5 s of CPU time and was killed by the watchdog. Inputs: see the label.
  ...[
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

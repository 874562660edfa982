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

// The last four size edges (the update caps of gmBernoulliUpdate, GmBernoulliFilter,
// ParticleBernoulliFilter and SensorControlRun's step) became joint work caps in the core
// (MAX_VECTOR_UPDATE_WORK, MAX_UPDATE_EVALUATIONS, control MAX_WORK), each a RangeError naming
// the list to shorten; specs.mjs largeCases holds a case at each cap and one over it.
// The MMUC search's edge (a 3-D mixture with a nearly degenerate component, 2.6 s) is fixed by
// a work budget on the whole search (core MMUC_SEARCH_BUDGET): regressions.test.mjs, fuzz #12.
export const knownEdges = [
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

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
export const knownEdges = [
  // Found by `node fuzz/run.mjs --cases 1000000` (seed 602302): the MMUC search over a
  // two-component 3-D mixture, one component nearly degenerate (variances 1.8e-292 to 8.4e-9),
  // took 2.6 s of CPU. The search's cost per evaluation of q(a) grows with the spread of a
  // component's variances; the component cap (100) does not bound it.
  {
    id: 'mmucEstimate-degenerate-slow',
    export: 'mmucEstimate',
    input: [{ density: { mixture: [{ weight: 1.5943428659959995e-127, mean: new Float64Array([-1.4035815575359678e-285, -4.5651984964795094e-178, -2.9309333900897442e-173]), cov: [[0.001, 0, 0], [0, 0.001, 0], [0, 0, 0.001]] }, { weight: 1, mean: [1.3842930252453666e-130, -1.3556882110795213e-61, -9.471772948376036e-132], cov: [[1.1150655654625976e-11, -5.173865028903137e-271, -2.9191461212067335e-110], [-5.173865028903137e-271, 1.8461991266345536e-292, 1.3789151307041794e-249], [-2.9191461212067335e-110, 1.3789151307041794e-249, 8.405850856824145e-9]] }] }, radius: 0.2503930865808104 }],
    found: 'mmucEstimate() took 2616 ms (CPU 2554 ms; bound 2000 ms)',
    expected: 'under 2 s (a work budget on the MMUC search, or a cap on the variance spread naming the covariance)',
    matches: (args, message) => slow(message) && Array.isArray(args?.[0]?.density?.mixture),
  },
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

// Splitting a Gaussian mixture against regions, so that each component lies (almost) wholly
// inside or outside: LeGrand & Ferrari, "Split Happens! Imprecise and negative information in
// Gaussian mixture random finite set filtering" — the split library (eqs 13–14, Table I),
// recursive splitting (Algs 1–2) and the mean-based partition (eqs 11–12).
import * as fisst from 'fisst';

// The library: the best R-component approximation of N(0, 1) by equal-σ̃ Gaussians, trading the
// L2 error against λσ̃² (13). R = 4, λ = 0.001 is the paper's Table I.
const lib = fisst.splitLibrary({ components: 4, lambda: 0.001 });
console.log(lib.weights.map((w) => w.toFixed(4)).join(' ')); // 0.1077 0.3923 0.3923 0.1077
console.log(lib.means.map((m) => m.toFixed(4)).join(' '), lib.sigma.toFixed(4)); // -1.4224 -0.4741 0.4741 1.4224 0.5816
console.log(lib.variance.toFixed(4)); // 0.9503

// A mixture p(x) = Σ w N(x; m, P) (here one standard Gaussian in 2D) and a field of view S, the
// box [0.5, 10] × [−10, 10]. The exact mass of p inside S is ⟨1_S, p⟩ ≈ P(N(0, 1) ≥ 0.5) = 0.3085.
const mixture = [{ weight: 1, mean: [0, 0], cov: [[1, 0], [0, 1]] }];
const S = { box: { min: [0.5, -10], max: [10, 10] } };

// Without splitting, the mean-based partition puts the whole component outside (its mean is):
const coarse = fisst.splitForRegions({ mixture, regions: [S], maxDepth: 0 });
console.log(coarse.inside, coarse.outside, coarse.exactInside.toFixed(4)); // 0 1 0.3085

// With splitting (R = 3 by default here), components straddling ∂S are split recursively;
// `inside` (weights of the components whose mean is in S) now approximates ⟨1_S, p⟩.
// insideMask[i] says which components of the split mixture are in S; depth and splits count work;
// stop is null when the recursion finished on its own, else the cap that stopped it.
const s = fisst.splitForRegions({ mixture, regions: [S] });
console.log(s.mixture.length, s.inside.toFixed(4), s.outside.toFixed(4)); // 61 0.3071 0.6929
console.log(s.depth, s.splits, s.stop, s.insideMask.filter(Boolean).length); // 7 30 null 30

// A filter then keeps its mixture small: prune light components, merge those within a
// Mahalanobis distance (Vo & Ma), then cap the count (Runnalls). The total weight is preserved.
const r = fisst.reduceMixture({ mixture: s.mixture, pruneBelow: 1e-3, mergeDistance: 2, maxComponents: 5 });
console.log(r.length, r.reduce((a, c) => a + c.weight, 0).toFixed(6)); // 5 1.000000

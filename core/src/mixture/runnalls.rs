//! Runnalls' Kullback–Leibler-based greedy mixture reduction.

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::fns;

/// The components in flat form: weights, means (n each), covariances as packed lower
/// triangles (n(n+1)/2 each, entry (i, j), j ≤ i, at i(i+1)/2 + j), ln det, and the input
/// index of components never merged.
struct Store {
    n: usize,
    tri: usize,
    w: Vec<f64>,
    m: Vec<f64>,
    p: Vec<f64>,
    ln_det: Vec<f64>,
    original: Vec<Option<usize>>,
}

/// ln det of the symmetric matrix whose packed lower triangle is `a`, by an in-place
/// Cholesky factorisation; +∞ when it is not positive definite.
fn ln_det_packed(a: &mut [f64], n: usize) -> f64 {
    let mut prod = 1.0;
    let mut ln_acc = 0.0;
    for j in 0..n {
        let rj = j * (j + 1) / 2;
        let mut d = a[rj + j];
        for k in 0..j {
            d -= a[rj + k] * a[rj + k];
        }
        if !(d > 0.0 && d.is_finite()) {
            return f64::INFINITY;
        }
        let l = fns::sqrt(d);
        a[rj + j] = l;
        let inv = 1.0 / l;
        for i in j + 1..n {
            let ri = i * (i + 1) / 2;
            let mut s = a[ri + j];
            for k in 0..j {
                s -= a[ri + k] * a[rj + k];
            }
            a[ri + j] = s * inv;
        }
        // Π d_j = det; one ln per chunk, avoiding under/overflow.
        prod *= d;
        if !(1e-100..=1e100).contains(&prod) {
            ln_acc += fns::ln(prod);
            prod = 1.0;
        }
    }
    ln_acc + fns::ln(prod)
}

/// ln det of a packed symmetric positive definite matrix: for n ≤ 4 by the division-free
/// Laplace expansion (no square root, no division: about 3× faster than Cholesky, which
/// makes the pair bounds of [`runnalls`] cheap), falling back to [`ln_det_packed`] when the
/// matrix is close to singular (det below 1e-8 of the product of its diagonal, where the
/// expansion would lose digits) or larger.
fn ln_det_small(a: &mut [f64], n: usize) -> f64 {
    let det = match *a {
        [a00] if n == 1 => a00,
        [a00, a10, a11] if n == 2 => a00 * a11 - a10 * a10,
        [a00, a10, a11, a20, a21, a22] if n == 3 => {
            a00 * (a11 * a22 - a21 * a21) - a10 * (a10 * a22 - a21 * a20)
                + a20 * (a10 * a21 - a11 * a20)
        }
        [a00, a10, a11, a20, a21, a22, a30, a31, a32, a33] if n == 4 => {
            // Complementary 2 × 2 minors of rows (0, 1) and rows (2, 3).
            let s0 = a00 * a11 - a10 * a10;
            let s1 = a00 * a21 - a20 * a10;
            let s2 = a00 * a31 - a30 * a10;
            let s3 = a10 * a21 - a20 * a11;
            let s4 = a10 * a31 - a30 * a11;
            let s5 = a20 * a31 - a30 * a21;
            let c5 = a22 * a33 - a32 * a32;
            let c4 = a21 * a33 - a32 * a31;
            let c3 = a21 * a32 - a22 * a31;
            let c2 = a20 * a33 - a32 * a30;
            let c1 = a20 * a32 - a22 * a30;
            let c0 = a20 * a31 - a21 * a30;
            s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0
        }
        _ => return ln_det_packed(a, n),
    };
    let diag: f64 = (0..n).map(|i| a[i * (i + 1) / 2 + i]).product();
    if det > 1e-8 * diag && det.is_finite() {
        fns::ln(det)
    } else {
        ln_det_packed(a, n)
    }
}

impl Store {
    /// Writes the merged packed covariance of a and b into `out` and returns the merged
    /// weight: P_ab = (w_a P_a + w_b P_b)/W + (w_a w_b/W²) d dᵀ, d = m_a − m_b.
    fn merged_cov(&self, a: usize, b: usize, out: &mut [f64], d: &mut [f64]) -> f64 {
        let (n, tri) = (self.n, self.tri);
        let w = self.w[a] + self.w[b];
        let (sa, sb) = if w > 0.0 {
            (self.w[a] / w, self.w[b] / w)
        } else {
            (0.5, 0.5)
        };
        let c = sa * sb;
        let (ma, mb) = (&self.m[a * n..(a + 1) * n], &self.m[b * n..(b + 1) * n]);
        for ((di, x), y) in d.iter_mut().zip(ma).zip(mb) {
            *di = x - y;
        }
        let (pa, pb) = (
            &self.p[a * tri..(a + 1) * tri],
            &self.p[b * tri..(b + 1) * tri],
        );
        let mut k = 0;
        for i in 0..n {
            let ci = c * d[i];
            for dj in &d[..=i] {
                out[k] = sa * pa[k] + sb * pb[k] + ci * dj;
                k += 1;
            }
        }
        w
    }

    /// Runnalls' upper bound on the KL discrepancy of merging a and b:
    ///
    /// ```text
    /// B(a, b) = ½ [ (w_a + w_b) ln det P_ab − w_a ln det P_a − w_b ln det P_b ]
    /// ```
    fn cost(&self, a: usize, b: usize, buf: &mut [f64], d: &mut [f64]) -> f64 {
        let w = self.merged_cov(a, b, buf, d);
        if w == 0.0 {
            return 0.0;
        }
        let c = 0.5
            * (w * ln_det_small(buf, self.n)
                - self.w[a] * self.ln_det[a]
                - self.w[b] * self.ln_det[b]);
        if c.is_nan() { f64::INFINITY } else { c }
    }

    /// Replaces a by the moment-matched merge of a and b.
    fn merge_into(&mut self, a: usize, b: usize, buf: &mut [f64], d: &mut [f64]) {
        let (n, tri) = (self.n, self.tri);
        let w = self.merged_cov(a, b, buf, d);
        let (sa, sb) = if w > 0.0 {
            (self.w[a] / w, self.w[b] / w)
        } else {
            (0.5, 0.5)
        };
        for i in 0..n {
            self.m[a * n + i] = sa * self.m[a * n + i] + sb * self.m[b * n + i];
        }
        self.p[a * tri..(a + 1) * tri].copy_from_slice(&buf[..tri]);
        self.w[a] = w;
        self.ln_det[a] = ln_det_small(buf, n);
        self.original[a] = None;
    }

    /// Component k's covariance as a row-major n × n matrix.
    fn full_cov(&self, k: usize) -> Vec<f64> {
        let (n, tri) = (self.n, self.tri);
        let p = &self.p[k * tri..(k + 1) * tri];
        let mut out = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..=i {
                let x = p[i * (i + 1) / 2 + j];
                out[i * n + j] = x;
                out[j * n + i] = x;
            }
        }
        out
    }
}

const NONE: usize = usize::MAX;
/// Mixtures of up to this many components cache every pair's bound (8 bytes per pair:
/// 67 MB at the limit); larger ones recompute the bounds of a row when it is rescanned.
pub const RUNNALLS_CACHE_LIMIT: usize = 4096;
const MATRIX_LIMIT: usize = RUNNALLS_CACHE_LIMIT;

/// Reduces the mixture to at most `max_components` components by Runnalls' greedy
/// algorithm: repeatedly merge (moment-matched, as in
/// [`merge_components`](super::merge_components)) the pair with the smallest upper bound on
/// the Kullback–Leibler discrepancy
///
/// ```text
/// B(i, j) = ½ [ (w_i + w_j) ln det P_ij − w_i ln det P_i − w_j ln det P_j ]
/// P_ij = (w_i P_i + w_j P_j)/(w_i + w_j) + w_i w_j/(w_i + w_j)² (m_i − m_j)(m_i − m_j)ᵀ
/// ```
///
/// until `max_components` remain. Every merge preserves the weight, mean and covariance of
/// the pair, so the mixture's total weight, mean and covariance are preserved.
///
/// # Cost
/// O(L²) bound evaluations for the first pass, then O(L) per merge (each row keeps its
/// cheapest partner; a row is rescanned only when its partner was merged). The bounds are
/// cached (O(L²) memory) up to [`RUNNALLS_CACHE_LIMIT`] components; beyond it memory is
/// O(L) and a rescan recomputes its row. For n ≤ 4 the determinants come from the
/// division-free Laplace expansion (Cholesky when nearly singular). Measured natively: 1000
/// 4D components to 100 in about 60 ms (`benches/src/bin/splitting_timing.rs`).
/// Ties go to the lowest indices. Surviving components keep the order of the input (a
/// merged pair takes the place of its first member).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `maxComponents` if it is 0;
/// [`Error::NotDefinite`] if a merged covariance fails Cholesky.
///
/// # References
/// A. R. Runnalls, "Kullback-Leibler approach to Gaussian mixture reduction," IEEE Trans.
/// Aerosp. Electron. Syst. 43(3):989–999, 2007, doi:10.1109/TAES.2007.4383588 — eq. (21)
/// (the bound B) and Section IV (the greedy procedure); `001_…` Section V-C uses it after a
/// Vo & Ma merging pass.
pub fn runnalls(mixture: &GaussianMixture, max_components: usize) -> Result<GaussianMixture> {
    if max_components == 0 {
        return Err(Error::parameter("maxComponents", 0.0, "an integer >= 1"));
    }
    let components = mixture.components();
    let total = components.len();
    if total <= max_components {
        return Ok(mixture.clone());
    }
    let n = mixture.dim().unwrap_or(0);
    let tri = n * (n + 1) / 2;
    let mut store = Store {
        n,
        tri,
        w: Vec::with_capacity(total),
        m: Vec::with_capacity(total * n),
        p: Vec::with_capacity(total * tri),
        ln_det: Vec::with_capacity(total),
        original: Vec::with_capacity(total),
    };
    for (i, (w, g)) in components.iter().enumerate() {
        store.w.push(*w);
        store.m.extend(g.mean().iter());
        for r in 0..n {
            for c in 0..=r {
                store.p.push(g.cov()[(r, c)]);
            }
        }
        store.ln_det.push(g.ln_det());
        store.original.push(Some(i));
    }
    let mut buf = vec![0.0; tri];
    let mut d = vec![0.0; n];
    let mut active = vec![true; total];
    // The bound of every active pair, cached when the triangle fits in MATRIX_LIMIT entries.
    let mut cache = (total <= MATRIX_LIMIT).then(|| vec![f64::INFINITY; total * (total - 1) / 2]);
    let tri_index = |i: usize, j: usize| {
        let (i, j) = if i < j { (i, j) } else { (j, i) };
        j * (j - 1) / 2 + i
    };
    // best[i] = (partner, cost), the cheapest active partner of i.
    let mut best: Vec<(usize, f64)> = vec![(NONE, f64::INFINITY); total];
    let better = |cur: (usize, f64), cand: (usize, f64)| cur.0 == NONE || cand.1 < cur.1;
    for j in 1..total {
        for i in 0..j {
            let c = store.cost(i, j, &mut buf, &mut d);
            if let Some(m) = cache.as_mut() {
                m[tri_index(i, j)] = c;
            }
            if better(best[i], (j, c)) {
                best[i] = (j, c);
            }
            if better(best[j], (i, c)) {
                best[j] = (i, c);
            }
        }
    }
    let mut count = total;
    while count > max_components {
        let mut i = NONE;
        for k in 0..total {
            if active[k] && best[k].0 != NONE && (i == NONE || best[k].1 < best[i].1) {
                i = k;
            }
        }
        if i == NONE {
            break;
        }
        let j = best[i].0;
        let (a, b) = if i < j { (i, j) } else { (j, i) };
        store.merge_into(a, b, &mut buf, &mut d);
        active[b] = false;
        count -= 1;
        best[a] = (NONE, f64::INFINITY);
        best[b] = (NONE, f64::INFINITY);
        let mut rescan = Vec::new();
        for k in 0..total {
            if !active[k] || k == a {
                continue;
            }
            let c = store.cost(a, k, &mut buf, &mut d);
            if let Some(m) = cache.as_mut() {
                m[tri_index(a, k)] = c;
            }
            if better(best[a], (k, c)) {
                best[a] = (k, c);
            }
            if best[k].0 == a || best[k].0 == b {
                rescan.push(k);
            } else if better(best[k], (a, c)) {
                best[k] = (a, c);
            }
        }
        for k in rescan {
            let mut bk = (NONE, f64::INFINITY);
            for l in 0..total {
                if !active[l] || l == k {
                    continue;
                }
                let c = match cache.as_ref() {
                    Some(m) => m[tri_index(k, l)],
                    None => store.cost(k, l, &mut buf, &mut d),
                };
                if better(bk, (l, c)) {
                    bk = (l, c);
                }
            }
            best[k] = bk;
        }
    }
    let mut out = Vec::with_capacity(count);
    for k in (0..total).filter(|&k| active[k]) {
        let g = match store.original[k] {
            Some(i) => components[i].1.clone(),
            None => Gaussian::from_slices(
                &store.m[k * n..(k + 1) * n],
                &store.full_cov(k),
                &alloc::format!("mixture[{k}]"),
            )?,
        };
        out.push((store.w[k], g));
    }
    GaussianMixture::new(out, "mixture")
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    #[test]
    fn closed_form_ln_det_matches_cholesky() {
        let mut rng = SmallRng::seed_from_u64(17);
        for n in 1..=6 {
            for trial in 0..200 {
                // A Aᵀ + εI with ε from 1 down to 1e-9: condition numbers up to ~1e10.
                let eps = 10f64.powi(-(trial % 10));
                let a: Vec<f64> = (0..n * n).map(|_| rng.random_range(-1.0..1.0)).collect();
                let mut packed = Vec::new();
                for i in 0..n {
                    for j in 0..=i {
                        let mut s: f64 = (0..n).map(|k| a[i * n + k] * a[j * n + k]).sum();
                        if i == j {
                            s += eps;
                        }
                        packed.push(s);
                    }
                }
                let fast = ln_det_small(&mut packed.clone(), n);
                let slow = ln_det_packed(&mut packed, n);
                assert!(
                    (fast - slow).abs() < 1e-7 * (1.0 + slow.abs()),
                    "n {n} trial {trial}: {fast} vs {slow}"
                );
            }
        }
    }
}

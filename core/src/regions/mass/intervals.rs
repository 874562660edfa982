//! Interval sets (sorted, disjoint, closed intervals; measure is all that matters): union,
//! intersection and complement, the evaluation of a region tree along a line, and the
//! exact n_s = 1 mass of eq. (8) of `001_…` as a sum of Φ differences.

use alloc::vec;
use alloc::vec::Vec;

use super::Quad;
use crate::gaussian::normal;

use super::Shape;

/// A set of intervals (a, b).
pub(super) type Intervals = Vec<(f64, f64)>;

fn merge(mut v: Intervals) -> Intervals {
    v.retain(|&(a, b)| a < b);
    crate::math::sort::sort_by(&mut v, |x, y| x.0.total_cmp(&y.0));
    let mut out: Intervals = Vec::with_capacity(v.len());
    for (a, b) in v {
        match out.last_mut() {
            Some(last) if a <= last.1 => last.1 = last.1.max(b),
            _ => out.push((a, b)),
        }
    }
    out
}

fn intersect(a: &[(f64, f64)], b: &[(f64, f64)]) -> Intervals {
    let (mut i, mut j) = (0, 0);
    let mut out = Vec::new();
    while i < a.len() && j < b.len() {
        let lo = a[i].0.max(b[j].0);
        let hi = a[i].1.min(b[j].1);
        if lo < hi {
            out.push((lo, hi));
        }
        if a[i].1 < b[j].1 {
            i += 1;
        } else {
            j += 1;
        }
    }
    out
}

fn complement(a: &[(f64, f64)], lo: f64, hi: f64) -> Intervals {
    let mut out = Vec::with_capacity(a.len() + 1);
    let mut start = lo;
    for &(x, y) in a {
        if x > start {
            out.push((start, x));
        }
        start = start.max(y);
    }
    if start < hi {
        out.push((start, hi));
    }
    out
}

pub(super) fn combine(
    shape: &Shape,
    lo: f64,
    hi: f64,
    leaf: &mut impl FnMut(&Shape) -> Intervals,
) -> Intervals {
    match shape {
        Shape::Empty => Vec::new(),
        Shape::Full => vec![(lo, hi)],
        Shape::Union(m) => {
            let mut all = Vec::new();
            for s in m {
                all.extend(combine(s, lo, hi, leaf));
            }
            merge(all)
        }
        Shape::Inter(m) => {
            let mut acc = vec![(lo, hi)];
            // Every member is visited (no early exit): the ray method numbers its leaves in
            // visiting order.
            for s in m {
                acc = intersect(&acc, &combine(s, lo, hi, leaf));
            }
            acc
        }
        Shape::Compl(r) => complement(&combine(r, lo, hi, leaf), lo, hi),
        _ => {
            let v = leaf(shape);
            let clipped: Intervals = v.into_iter().map(|(a, b)| (a.max(lo), b.min(hi))).collect();
            merge(clipped)
        }
    }
}

/// n_s = 1: the region is a finite union of intervals, found exactly; the mass is a sum of
/// Φ differences.
pub(super) fn mass_1d(shape: &Shape, m: f64, sigma: f64) -> Quad {
    let set = combine(shape, f64::NEG_INFINITY, f64::INFINITY, &mut |s| match s {
        Shape::Box { min, max } => vec![(min[0], max[0])],
        Shape::Ball { center, radius } => vec![(center[0] - radius, center[0] + radius)],
        _ => Vec::new(),
    });
    let value = crate::math::sum::sum(
        set.iter()
            .map(|&(a, b)| normal::interval((a - m) / sigma, (b - m) / sigma)),
    );
    Quad {
        value,
        error: 2e-16 * (set.len() as f64 + 1.0),
    }
}

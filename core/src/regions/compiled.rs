//! Regions flattened for the splitting test of `001_…` (Algorithms 1–2, eqs. (23)–(26) and
//! (33)–(35)): many regions evaluated at the same collocation points of one component.
//!
//! The test needs, for every region, the inclusion d = 1_S(s) of each mapped grid point s.
//! [`RegionSet`] flattens the regions' trees once per split call (children before parents),
//! so that per component it can
//!
//! 1. decide every node on the ball that holds all the grid points ([`RegionSet::classify`],
//!    with [`Region::ball_relation`] on the primitives and the union / intersection /
//!    complement logic above them), without allocating, and
//! 2. evaluate only the undecided primitives at the points, one tight loop per primitive,
//!    into bit sets (one bit per point), and combine them up the tree by word operations
//!    ([`RegionSet::evaluate`]).
//!
//! The inclusion bits are exactly those of [`Region::contains`] at the same points (the same
//! exact primitive tests; a node decided on the ball agrees with every point in it).

use alloc::vec::Vec;

use core::cmp::Ordering;

use super::predicates::{EPS, ball_side_exact};
use super::{Node, Region};
use crate::math::fns;

/// A flattened node: a primitive (box, polygon, ball) or a combination of earlier nodes.
enum Flat<'a> {
    Primitive(&'a Region),
    Union(Vec<usize>),
    Intersection(Vec<usize>),
    Complement(usize),
}

/// Regions flattened into one arena (children before parents).
pub(crate) struct RegionSet<'a> {
    nodes: Vec<Flat<'a>>,
    roots: Vec<usize>,
}

impl<'a> RegionSet<'a> {
    /// Flattens `regions` (their roots in the given order).
    pub(crate) fn new(regions: &'a [Region]) -> Self {
        let mut set = Self {
            nodes: Vec::new(),
            roots: Vec::with_capacity(regions.len()),
        };
        for r in regions {
            let root = set.push(r);
            set.roots.push(root);
        }
        set
    }

    fn push(&mut self, r: &'a Region) -> usize {
        let flat = match r.node() {
            Node::Box(_) | Node::Polygon(_) | Node::Ball(_) => Flat::Primitive(r),
            Node::Union(m) => Flat::Union(m.iter().map(|x| self.push(x)).collect()),
            Node::Intersection(m) => Flat::Intersection(m.iter().map(|x| self.push(x)).collect()),
            Node::Complement(x) => Flat::Complement(self.push(x)),
        };
        self.nodes.push(flat);
        self.nodes.len() - 1
    }

    /// The root node of each region, in the given order.
    pub(crate) fn roots(&self) -> &[usize] {
        &self.roots
    }

    /// Decides every node on `hull`, a set that holds every point to be evaluated:
    /// `state[i]` is `Some(true)` when the whole hull is inside node i, `Some(false)` when
    /// wholly outside, `None` when undecided. A primitive is decided by
    /// [`Region::ball_relation`] on the hull's ball or by [`Hull::relation`] (its box and its
    /// ellipse); a union is inside when a member is, outside when all are; an intersection
    /// dually.
    pub(crate) fn classify(&self, hull: &Hull<'_>, state: &mut Vec<Option<bool>>) {
        state.clear();
        for node in &self.nodes {
            let s = match node {
                Flat::Primitive(r) => r
                    .ball_relation(hull.center, hull.radius)
                    .or_else(|| hull.relation(r)),
                Flat::Union(m) => combine(m, state, true),
                Flat::Intersection(m) => combine(m, state, false),
                Flat::Complement(x) => state[*x].map(|b| !b),
            };
            state.push(s);
        }
    }

    /// The inclusion bit sets of every node at the `count` points (`points`, flat, `ns`
    /// coordinates each): bit p of `bits[i·words ..]` is 1_{node i}(point p), with
    /// `words = count.div_ceil(64)` and the bits past `count` zero. Decided nodes (`state`
    /// of [`RegionSet::classify`] on a ball holding every point) are filled with their
    /// constant; only the undecided primitives are tested, point by point, by their exact
    /// test.
    ///
    /// `rows` (may be empty) lists runs `[a, b)` of points that lie on one segment, from
    /// point a to point b − 1, up to `tol` per coordinate (the rows of the collocation grid
    /// (20)–(22) of `001_…` along its first axis, with `tol` above the rounding of the
    /// mapping (15)–(17)). For planar balls and boxes a run whose segment lies clearly on
    /// one side of the boundary gets its bits without per-point tests (so only the rows
    /// that cross a boundary are tested point by point): every point of a skipped run is farther from the boundary than any rounding, so its test could only
    /// give the same bit, and the bits are those of the point-by-point test, bit for bit.
    /// The runs must cover the points 0..count.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn evaluate(
        &self,
        points: &[f64],
        ns: usize,
        count: usize,
        rows: &[(usize, usize)],
        tol: f64,
        state: &[Option<bool>],
        bits: &mut Vec<u64>,
    ) {
        let words = count.div_ceil(64);
        bits.clear();
        bits.resize(self.nodes.len() * words, 0);
        let tail = if count.is_multiple_of(64) {
            u64::MAX
        } else {
            (1u64 << (count % 64)) - 1
        };
        let full = |w: usize| if w + 1 == words { tail } else { u64::MAX };
        for (i, node) in self.nodes.iter().enumerate() {
            let (done, rest) = bits.split_at_mut(i * words);
            let out = &mut rest[..words];
            if let Some(b) = state[i] {
                if b {
                    for (w, o) in out.iter_mut().enumerate() {
                        *o = full(w);
                    }
                }
                continue;
            }
            let child = |c: usize| &done[c * words..(c + 1) * words];
            match node {
                Flat::Primitive(r) => {
                    if !(ns == 2 && !rows.is_empty() && run_bits(r, points, rows, tol, out)) {
                        primitive_bits(r, points, ns, count, out);
                    }
                }
                Flat::Union(m) => {
                    for &c in m {
                        for (o, x) in out.iter_mut().zip(child(c)) {
                            *o |= x;
                        }
                    }
                }
                Flat::Intersection(m) => {
                    for (w, o) in out.iter_mut().enumerate() {
                        *o = full(w);
                    }
                    for &c in m {
                        for (o, x) in out.iter_mut().zip(child(c)) {
                            *o &= x;
                        }
                    }
                }
                Flat::Complement(c) => {
                    for (w, (o, x)) in out.iter_mut().zip(child(*c)).enumerate() {
                        *o = !x & full(w);
                    }
                }
            }
        }
    }
}

/// A union (`union`) or intersection of decided / undecided members.
fn combine(members: &[usize], state: &[Option<bool>], union: bool) -> Option<bool> {
    let mut all = true;
    for &m in members {
        match state[m] {
            Some(b) if b == union => return Some(union),
            Some(_) => {}
            None => all = false,
        }
    }
    if all { Some(!union) } else { None }
}

/// The planar ball's exact inclusion test (`Ball::contains`, predicates::ball_side,
/// unrolled for the plane: the same floating-point filter, the same exact fallback).
#[inline]
fn ball_bit(s: &[f64], c: &[f64], radius: f64) -> bool {
    let (dx, dy) = (s[0] - c[0], s[1] - c[1]);
    let r2 = radius * radius;
    let k = 4.0 * (2.0 + 3.0) * EPS;
    let d2 = dx * dx + dy * dy;
    let diff = r2 - d2;
    if fns::abs(diff) > k * (d2 + r2) {
        diff > 0.0
    } else {
        ball_side_exact(s, c, radius) != Ordering::Less
    }
}

/// The planar box's exact inclusion test (`AxisBox::contains`).
#[inline]
fn box_bit(s: &[f64], lo: &[f64], hi: &[f64]) -> bool {
    lo[0] <= s[0] && s[0] <= hi[0] && lo[1] <= s[1] && s[1] <= hi[1]
}

/// The bits of a planar ball or box `r` at the points, run by run (see
/// [`RegionSet::evaluate`]), as [`primitive_bits`] gives them; `false` (nothing written)
/// for another primitive.
///
/// Every point of a run [a, b) lies within 3·`tol` of the segment from point a to point
/// b − 1 (its exact position on the row does, and each computed point, the two ends
/// included, is within `tol` of its exact position). A run is decided without per-point
/// tests when that segment, widened by 4·`tol` and a relative 10⁻⁹ (for a ball), lies
/// inside or outside the region (both are convex, so the segment is inside when its ends
/// are): then every point is farther from the boundary than the rounding of its test, which
/// can only give that bit. The other runs are tested point by point.
fn run_bits(
    r: &Region,
    points: &[f64],
    rows: &[(usize, usize)],
    tol: f64,
    out: &mut [u64],
) -> bool {
    let pt = |p: usize| &points[2 * p..2 * p + 2];
    match r.node() {
        Node::Ball(ball) if ball.dim() == 2 => {
            let c = ball.center();
            let (cx, cy, rho) = (c[0], c[1], ball.radius());
            for &(a, b) in rows {
                let (first, last) = (pt(a), pt(b - 1));
                let (px, py) = (first[0] - cx, first[1] - cy);
                let (qx, qy) = (last[0] - cx, last[1] - cy);
                let margin = 1e-9 * (rho + px.abs() + py.abs() + qx.abs() + qy.abs()) + 4.0 * tol;
                let (dp2, dq2) = (px * px + py * py, qx * qx + qy * qy);
                let inner = rho - margin;
                if inner > 0.0 && dp2.max(dq2) < inner * inner {
                    set_bits(out, a, b);
                    continue;
                }
                // The squared distance from the centre to the segment (t off by a few ulps
                // moves the point along the segment: a second-order change).
                let (ux, uy) = (qx - px, qy - py);
                let uu = ux * ux + uy * uy;
                let t = if uu > 0.0 {
                    (-(px * ux + py * uy) / uu).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let (nx, ny) = (px + t * ux, py + t * uy);
                let outer = rho + margin;
                if nx * nx + ny * ny > outer * outer {
                    continue;
                }
                for p in a..b {
                    out[p / 64] |= u64::from(ball_bit(pt(p), c, rho)) << (p % 64);
                }
            }
            true
        }
        Node::Box(bx) if bx.dim() == 2 => {
            let (lo, hi) = (bx.min(), bx.max());
            let m = 4.0 * tol;
            for &(a, b) in rows {
                let (first, last) = (pt(a), pt(b - 1));
                let (x_min, x_max) = (first[0].min(last[0]), first[0].max(last[0]));
                let (y_min, y_max) = (first[1].min(last[1]), first[1].max(last[1]));
                if lo[0] + m < x_min && x_max < hi[0] - m && lo[1] + m < y_min && y_max < hi[1] - m
                {
                    set_bits(out, a, b);
                } else if x_max + m < lo[0]
                    || x_min - m > hi[0]
                    || y_max + m < lo[1]
                    || y_min - m > hi[1]
                {
                } else {
                    for p in a..b {
                        out[p / 64] |= u64::from(box_bit(pt(p), lo, hi)) << (p % 64);
                    }
                }
            }
            true
        }
        _ => false,
    }
}

/// Sets bits a..b of `out`.
fn set_bits(out: &mut [u64], a: usize, b: usize) {
    let mut p = a;
    while p < b {
        let (w, lo) = (p / 64, p % 64);
        let hi = (b - w * 64).min(64);
        let mask = if hi - lo == 64 {
            u64::MAX
        } else {
            ((1u64 << (hi - lo)) - 1) << lo
        };
        out[w] |= mask;
        p = w * 64 + hi;
    }
}

/// The primitive's exact inclusion test at every point, as bits.
fn primitive_bits(r: &Region, points: &[f64], ns: usize, count: usize, out: &mut [u64]) {
    match r.node() {
        Node::Ball(b) if ns == 2 && b.dim() == 2 => {
            let (c, radius) = (b.center(), b.radius());
            for (p, s) in points.chunks_exact(2).take(count).enumerate() {
                out[p / 64] |= u64::from(ball_bit(s, c, radius)) << (p % 64);
            }
        }
        Node::Box(b) if ns == 2 && b.dim() == 2 => {
            let (lo, hi) = (b.min(), b.max());
            for (p, s) in points.chunks_exact(2).take(count).enumerate() {
                out[p / 64] |= u64::from(box_bit(s, lo, hi)) << (p % 64);
            }
        }
        _ => {
            for (p, s) in points.chunks_exact(ns).take(count).enumerate() {
                out[p / 64] |= u64::from(r.contains(s)) << (p % 64);
            }
        }
    }
}

/// A set known to hold every point of one evaluation (the collocation grid of a component,
/// eqs. (20)–(22): m_s + V_s Λ_s^{1/2} ȳ with ‖ȳ‖ ≤ ζ), described three ways, each with room
/// for the rounding of the mapped points: a ball, a box and an ellipse.
pub(crate) struct Hull<'a> {
    /// m_s.
    pub(crate) center: &'a [f64],
    /// A radius about m_s within which every point lies.
    pub(crate) radius: f64,
    /// Per axis i: every point has |s_i − m_i| ≤ `half_width[i]`.
    pub(crate) half_width: &'a [f64],
    /// V_s (column j the j-th eigenvector, `ns × ns` column-major) and √λ_j: every point
    /// is m_s + Σ_j v_j √λ_j ȳ_j with ‖ȳ‖ ≤ `zeta`, up to `slack` per coordinate.
    pub(crate) vectors: &'a [f64],
    pub(crate) roots: &'a [f64],
    pub(crate) zeta: f64,
    pub(crate) slack: f64,
}

/// Relative margin of the hull tests (far above the rounding of the eigenvectors, the
/// whitening and the distances).
const MARGIN: f64 = 1e-8;

impl Hull<'_> {
    /// `Some(true)` when the primitive `r` certainly holds every point of the hull,
    /// `Some(false)` when it certainly holds none, `None` otherwise. Boxes and balls are
    /// tested against the hull's box (disjoint, or the box inside; for a ball, its nearest
    /// and farthest box points); balls also against the ellipse: with y_c = Λ^{-1/2} Vᵀ
    /// (c − m), every point s = m + V Λ^{1/2} ȳ has ‖s − c‖ ≥ √λ_min (‖y_c‖ − ζ).
    fn relation(&self, r: &Region) -> Option<bool> {
        let n = self.center.len();
        match r.node() {
            Node::Box(b) if b.dim() <= n => {
                let (lo, hi) = (b.min(), b.max());
                let mut inside = true;
                for i in 0..lo.len() {
                    let (m, h) = (self.center[i], self.half_width[i]);
                    if m + h < lo[i] || m - h > hi[i] {
                        return Some(false);
                    }
                    if !(lo[i] <= m - h && m + h <= hi[i]) {
                        inside = false;
                    }
                }
                if inside { Some(true) } else { None }
            }
            Node::Ball(b) if b.dim() == n => {
                let (c, rho) = (b.center(), b.radius());
                let (mut near, mut far) = (0.0, 0.0);
                for ((&ci, &m), &h) in c.iter().zip(self.center).zip(self.half_width) {
                    let (lo, hi) = (m - h, m + h);
                    let gap = if ci < lo {
                        lo - ci
                    } else if ci > hi {
                        ci - hi
                    } else {
                        0.0
                    };
                    near += gap * gap;
                    let reach = (ci - lo).max(hi - ci);
                    far += reach * reach;
                }
                let rho2 = rho * rho;
                if near > rho2 * (1.0 + MARGIN) {
                    return Some(false);
                }
                if far < rho2 * (1.0 - MARGIN) {
                    return Some(true);
                }
                // The ellipse.
                let mut yc2 = 0.0;
                let mut root_min = f64::INFINITY;
                for j in 0..n {
                    let mut dot = 0.0;
                    for ((&v, &ci), &m) in self.vectors[j * n..(j + 1) * n]
                        .iter()
                        .zip(c)
                        .zip(self.center)
                    {
                        dot += v * (ci - m);
                    }
                    let y = dot / self.roots[j];
                    yc2 += y * y;
                    root_min = root_min.min(self.roots[j]);
                }
                let lower = root_min
                    * (fns::sqrt(yc2) * (1.0 - MARGIN) - self.zeta * (1.0 + MARGIN))
                    - self.slack * fns::sqrt(n as f64);
                if lower > rho * (1.0 + MARGIN) {
                    return Some(false);
                }
                None
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    /// The run-by-run bits (planar balls and boxes, rows of a mapped grid) equal the
    /// point-by-point bits, including runs that graze a boundary.
    #[test]
    fn runs_give_the_point_by_point_bits() {
        let regions = vec![
            Region::ball(&[0.3, -0.2], 1.0, "r0").unwrap(),
            Region::axis_box(&[-0.5, -0.75], &[0.25, 2.0], "r1").unwrap(),
            Region::complement(Region::ball(&[1.0, 1.0], 0.5, "r2").unwrap()),
            // A boundary exactly on a row and one exactly through grid points.
            Region::axis_box(&[-1.0, 0.0], &[0.0, 1.0], "r3").unwrap(),
            Region::ball(&[0.0, 0.0], 1.0, "r4").unwrap(),
        ];
        let set = RegionSet::new(&regions);
        for (theta, scale, shift) in [(0.0, 1.0, 0.0), (0.4, 0.7, 0.1), (1.3, 1.9, -0.3)] {
            let (c, s) = (f64::cos(theta), f64::sin(theta));
            let mut points = Vec::new();
            let mut rows = Vec::new();
            for j in 0..15 {
                let a = points.len() / 2;
                for i in 0..15 {
                    let (u, v) = (-1.5 + 3.0 * i as f64 / 14.0, -1.5 + 3.0 * j as f64 / 14.0);
                    if u * u + v * v <= 2.25 * (1.0 + 1e-12) {
                        points.push(shift + scale * (c * u - s * v));
                        points.push(scale * (s * u + c * v));
                    }
                }
                rows.push((a, points.len() / 2));
            }
            let count = points.len() / 2;
            let state = vec![None; 8];
            let (mut by_runs, mut by_points) = (Vec::new(), Vec::new());
            set.evaluate(&points, 2, count, &rows, 1e-12, &state, &mut by_runs);
            set.evaluate(&points, 2, count, &[], 1e-12, &state, &mut by_points);
            assert_eq!(by_runs, by_points);
        }
        let mut out = [0u64; 3];
        set_bits(&mut out, 3, 130);
        let mut want = [0u64; 3];
        for p in 3..130 {
            want[p / 64] |= 1 << (p % 64);
        }
        assert_eq!(out, want);
    }
}

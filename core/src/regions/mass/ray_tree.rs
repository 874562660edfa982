//! Other 2D regions: the ray method in whitened coordinates. With s = m + L z the region
//! maps to polygons, parallelograms and ellipses; along a ray z = ρ(cos θ, sin θ) it is a
//! set of segments whose mass is exact, and the angle integral is adaptive Gauss–Kronrod
//! with breakpoints at every kink (see [`Region::gaussian_mass`](crate::regions::Region::gaussian_mass)).

use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::PI;

use super::{Quad, integrate_smooth_ends};
use crate::math::fns;

use super::intervals::{Intervals, combine};
use super::{MAX_INTERVALS, Shape};

/// Polygons with more edges than this get no self-intersection breakpoints (the adaptive
/// quadrature still resolves the kinks, at a higher cost).
const MAX_INTERSECTION_EDGES: usize = 256;

/// A primitive prepared for rays z = ρ u from the whitened origin.
enum RayLeaf {
    /// Box constraints lo_k ≤ ρ (L u)_k ≤ hi_k (lo, hi relative to the mean).
    Slabs { lo: [f64; 2], hi: [f64; 2] },
    /// Disc |ρ L u − δ| ≤ r with δ = centre − mean.
    Disc { delta: [f64; 2], r: f64 },
    /// Polygon with whitened vertices.
    Poly(Vec<[f64; 2]>),
}

/// The region tree prepared for rays: the 2 × 2 factor L, the leaves in the order
/// `combine` visits them, and the tree itself.
struct RayTree {
    l: [f64; 4],
    leaves: Vec<RayLeaf>,
    tree: Shape,
}

fn whiten(l: &[f64; 4], s: [f64; 2]) -> [f64; 2] {
    let z0 = s[0] / l[0];
    let z1 = (s[1] - l[2] * z0) / l[3];
    [z0, z1]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

impl RayTree {
    fn new(shape: &Shape, m: &[f64], l: &[f64]) -> RayTree {
        let l = [l[0], 0.0, l[2], l[3]];
        let mut leaves = Vec::new();
        // The leaves in the order `combine` visits them (depth first, members in order), so
        // that `segments` can hand them out by a running index.
        fn collect(shape: &Shape, m: &[f64], l: &[f64; 4], leaves: &mut Vec<RayLeaf>) {
            match shape {
                Shape::Box { min, max } => leaves.push(RayLeaf::Slabs {
                    lo: [min[0] - m[0], min[1] - m[1]],
                    hi: [max[0] - m[0], max[1] - m[1]],
                }),
                Shape::Ball { center, radius } => leaves.push(RayLeaf::Disc {
                    delta: [center[0] - m[0], center[1] - m[1]],
                    r: *radius,
                }),
                Shape::Polygon(v) => leaves.push(RayLeaf::Poly(
                    v.iter()
                        .map(|p| whiten(l, [p[0] - m[0], p[1] - m[1]]))
                        .collect(),
                )),
                Shape::Union(ms) | Shape::Inter(ms) => {
                    ms.iter().for_each(|s| collect(s, m, l, leaves))
                }
                Shape::Compl(r) => collect(r, m, l, leaves),
                Shape::Empty | Shape::Full => {}
            }
        }
        collect(shape, m, &l, &mut leaves);
        RayTree {
            l,
            leaves,
            tree: shape.clone(),
        }
    }

    /// The segments of the ray in direction `u` (unit) inside the region.
    fn segments(&self, u: [f64; 2]) -> Intervals {
        let v = [self.l[0] * u[0], self.l[2] * u[0] + self.l[3] * u[1]];
        let mut next = 0usize;
        let leaves = &self.leaves;
        combine(&self.tree, 0.0, f64::INFINITY, &mut |_| {
            let leaf = &leaves[next];
            next += 1;
            leaf_segments(leaf, u, v)
        })
    }

    /// Angles θ of the whitened directions where the integrand has a kink or a √ point:
    /// vertices, corners, directions parallel to box faces, disc tangents, and crossings of
    /// two boundaries (polygon or box edges with each other or with a disc).
    fn breakpoints(&self, shape: &Shape, m: &[f64]) -> Vec<f64> {
        let mut angles = Vec::new();
        let push_dir = |z: [f64; 2], angles: &mut Vec<f64>| {
            if z[0] != 0.0 || z[1] != 0.0 {
                angles.push(libm::atan2(z[1], z[0]));
            }
        };
        // Boundary pieces in s-coordinates relative to the mean, for crossings.
        let mut segments: Vec<([f64; 2], [f64; 2])> = Vec::new();
        let mut circles: Vec<([f64; 2], f64)> = Vec::new();
        for leaf in &self.leaves {
            match leaf {
                RayLeaf::Slabs { lo, hi } => {
                    // Directions parallel to each face pair: (L u)_k = 0.
                    for dir in [[0.0, 1.0], [-self.l[3], self.l[2]]] {
                        push_dir(dir, &mut angles);
                        push_dir([-dir[0], -dir[1]], &mut angles);
                    }
                    let corners = [
                        [lo[0], lo[1]],
                        [hi[0], lo[1]],
                        [hi[0], hi[1]],
                        [lo[0], hi[1]],
                    ];
                    for c in corners {
                        if c[0].is_finite() && c[1].is_finite() {
                            push_dir(whiten(&self.l, c), &mut angles);
                        }
                    }
                    if corners.iter().flatten().all(|x| x.is_finite()) {
                        for i in 0..4 {
                            segments.push((corners[i], corners[(i + 1) % 4]));
                        }
                    }
                }
                RayLeaf::Disc { delta, r } => {
                    let d = fns::sqrt(delta[0] * delta[0] + delta[1] * delta[1]);
                    if d > *r {
                        let beta = libm::asin(r / d);
                        let base = libm::atan2(delta[1], delta[0]);
                        for ang in [base - beta, base + beta] {
                            push_dir(
                                whiten(&self.l, [libm::cos(ang), libm::sin(ang)]),
                                &mut angles,
                            );
                        }
                    }
                    circles.push((*delta, *r));
                }
                RayLeaf::Poly(w) => {
                    for &z in w {
                        push_dir(z, &mut angles);
                    }
                }
            }
        }
        // Polygon edges in s-coordinates relative to the mean.
        fn poly_edges(shape: &Shape, m: &[f64], out: &mut Vec<([f64; 2], [f64; 2])>) {
            match shape {
                Shape::Polygon(v) => {
                    for i in 0..v.len() {
                        let a = v[i];
                        let b = v[(i + 1) % v.len()];
                        out.push(([a[0] - m[0], a[1] - m[1]], [b[0] - m[0], b[1] - m[1]]));
                    }
                }
                Shape::Union(ms) | Shape::Inter(ms) => {
                    ms.iter().for_each(|s| poly_edges(s, m, out))
                }
                Shape::Compl(r) => poly_edges(r, m, out),
                _ => {}
            }
        }
        poly_edges(shape, m, &mut segments);
        if segments.len() <= MAX_INTERSECTION_EDGES {
            for i in 0..segments.len() {
                for j in i + 1..segments.len() {
                    if let Some(p) = segment_crossing(segments[i], segments[j]) {
                        push_dir(whiten(&self.l, p), &mut angles);
                    }
                }
                for &(c, r) in &circles {
                    for p in segment_circle(segments[i], c, r).into_iter().flatten() {
                        push_dir(whiten(&self.l, p), &mut angles);
                    }
                }
            }
        }
        angles
    }
}

fn segment_crossing(s: ([f64; 2], [f64; 2]), t: ([f64; 2], [f64; 2])) -> Option<[f64; 2]> {
    let e = [s.1[0] - s.0[0], s.1[1] - s.0[1]];
    let f = [t.1[0] - t.0[0], t.1[1] - t.0[1]];
    let den = cross(e, f);
    if den == 0.0 {
        return None;
    }
    let d = [t.0[0] - s.0[0], t.0[1] - s.0[1]];
    let a = cross(d, f) / den;
    let b = cross(d, e) / den;
    if (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) {
        Some([s.0[0] + a * e[0], s.0[1] + a * e[1]])
    } else {
        None
    }
}

fn segment_circle(s: ([f64; 2], [f64; 2]), c: [f64; 2], r: f64) -> [Option<[f64; 2]>; 2] {
    let e = [s.1[0] - s.0[0], s.1[1] - s.0[1]];
    let d = [s.0[0] - c[0], s.0[1] - c[1]];
    let a = e[0] * e[0] + e[1] * e[1];
    let b = d[0] * e[0] + d[1] * e[1];
    let cc = d[0] * d[0] + d[1] * d[1] - r * r;
    let disc = b * b - a * cc;
    if a == 0.0 || disc < 0.0 {
        return [None, None];
    }
    let sq = fns::sqrt(disc);
    let point = |t: f64| {
        (0.0..=1.0)
            .contains(&t)
            .then(|| [s.0[0] + t * e[0], s.0[1] + t * e[1]])
    };
    [point((-b - sq) / a), point((-b + sq) / a)]
}

fn leaf_segments(leaf: &RayLeaf, u: [f64; 2], v: [f64; 2]) -> Intervals {
    match leaf {
        RayLeaf::Slabs { lo, hi } => {
            let mut a = 0.0f64;
            let mut b = f64::INFINITY;
            for k in 0..2 {
                if v[k] > 0.0 {
                    a = a.max(lo[k] / v[k]);
                    b = b.min(hi[k] / v[k]);
                } else if v[k] < 0.0 {
                    a = a.max(hi[k] / v[k]);
                    b = b.min(lo[k] / v[k]);
                } else if !(lo[k] <= 0.0 && 0.0 <= hi[k]) {
                    return Vec::new();
                }
            }
            if a < b { vec![(a, b)] } else { Vec::new() }
        }
        RayLeaf::Disc { delta, r } => {
            let qa = v[0] * v[0] + v[1] * v[1];
            let qb = v[0] * delta[0] + v[1] * delta[1];
            let qc = delta[0] * delta[0] + delta[1] * delta[1] - r * r;
            let disc = qb * qb - qa * qc;
            if disc <= 0.0 || qa == 0.0 {
                return Vec::new();
            }
            let sq = fns::sqrt(disc);
            // Stable roots of qa ρ² − 2 qb ρ + qc = 0.
            let q = if qb >= 0.0 { qb + sq } else { qb - sq };
            let (mut r1, mut r2) = (q / qa, if q != 0.0 { qc / q } else { 0.0 });
            if r1 > r2 {
                core::mem::swap(&mut r1, &mut r2);
            }
            let a = r1.max(0.0);
            if a < r2 { vec![(a, r2)] } else { Vec::new() }
        }
        RayLeaf::Poly(w) => {
            let n = w.len();
            let mut hits: Vec<f64> = Vec::new();
            for i in 0..n {
                let a = w[i];
                let b = w[(i + 1) % n];
                let e = [b[0] - a[0], b[1] - a[1]];
                let den = cross(u, e);
                if den == 0.0 {
                    continue;
                }
                let t = cross(a, u) / den;
                if (0.0..1.0).contains(&t) {
                    let rho = cross(a, b) / den;
                    if rho > 0.0 {
                        hits.push(rho);
                    }
                }
            }
            crate::math::sort::sort_f64(&mut hits);
            let mut out = Vec::with_capacity(hits.len() / 2 + 1);
            let mut k = 0;
            if hits.len() % 2 == 1 {
                out.push((0.0, hits[0]));
                k = 1;
            }
            while k + 1 < hits.len() {
                out.push((hits[k], hits[k + 1]));
                k += 2;
            }
            out
        }
    }
}

/// e^{−a²/2} − e^{−b²/2} for 0 ≤ a ≤ b ≤ ∞, accurate for narrow segments.
fn radial_mass(a: f64, b: f64) -> f64 {
    let ea = fns::exp(-0.5 * a * a);
    if b == f64::INFINITY {
        ea
    } else {
        -ea * libm::expm1(-0.5 * (b - a) * (b + a))
    }
}

/// ⟨1_S, N(m, L Lᵀ)⟩ for a 2D region that is not a box:
///
/// ```text
/// (1/2π) ∫₀^{2π} Σ_{segments} ( e^{−ρ₁²/2} − e^{−ρ₂²/2} ) dθ
/// ```
pub(super) fn mass_ray_2d(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
    let rays = RayTree::new(shape, m, l);
    let mut angles = rays.breakpoints(shape, m);
    for a in angles.iter_mut() {
        if *a >= PI {
            *a -= 2.0 * PI;
        }
    }
    angles.retain(|a| a.is_finite());
    crate::math::sort::sort_f64(&mut angles);
    angles.dedup_by(|a, b| *a - *b <= 1e-15);
    let mut points = if angles.is_empty() {
        vec![-PI, -0.5 * PI, 0.0, 0.5 * PI]
    } else {
        angles
    };
    let first = points[0];
    points.push(first + 2.0 * PI);
    // Pieces longer than π/2 are split so that every piece starts with a useful sampling.
    let mut pts = Vec::with_capacity(points.len() * 2);
    for w in points.windows(2) {
        let pieces = libm::ceil((w[1] - w[0]) / (0.5 * PI)).max(1.0) as usize;
        for i in 0..pieces {
            pts.push(w[0] + (w[1] - w[0]) * i as f64 / pieces as f64);
        }
    }
    pts.push(first + 2.0 * PI);
    let f = |theta: f64| {
        let u = [libm::cos(theta), libm::sin(theta)];
        let segs = rays.segments(u);
        crate::math::sum::sum(segs.iter().map(|&(a, b)| radial_mass(a, b))) / (2.0 * PI)
    };
    let q = integrate_smooth_ends(f, &pts, tol, MAX_INTERVALS.max(4 * pts.len()));
    Quad {
        value: q.value,
        error: q.error + 1e-15,
    }
}

//! ⟨1_S, N(m, P)⟩: the probability mass of a Gaussian inside a region.

use alloc::boxed::Box;
use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::PI;

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, normal};
use crate::math::fns;

use super::quadrature::{Quad, integrate_smooth_ends};
use super::{Node, Region, bivariate_normal};

/// The largest region dimension [`Region::gaussian_mass`] serves (n_s ≥ 3 uses nested
/// quadrature whose cost grows exponentially with n_s).
pub const MAX_MASS_DIM: usize = 4;

/// Default absolute tolerance of the quadratures (2D rays and the nested n_s ≥ 3 levels).
const DEFAULT_TOL: f64 = 1e-13;
/// Standardised half-width beyond which the nested quadrature truncates each conditioning
/// variable: 2Φ(−9) ≈ 2.3e-19 of mass is dropped per level.
const Z_MAX: f64 = 9.0;
/// Interval cap of an adaptive quadrature.
const MAX_INTERVALS: usize = 4000;
/// Polygons with more edges than this get no self-intersection breakpoints (the adaptive
/// quadrature still resolves the kinks, at a higher cost).
const MAX_INTERSECTION_EDGES: usize = 256;

/// A probability mass and an estimate of its absolute error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mass {
    /// ⟨1_S, N(m, P)⟩ ∈ [0, 1].
    pub value: f64,
    /// An estimate of |value − exact| (see [`Region::gaussian_mass`] for what backs it).
    pub error: f64,
}

impl Region {
    /// ⟨1_S, N(m, P)⟩ = P(s ∈ S) for x ~ N(m, P), s the first n_s = `self.dim()` components
    /// of x: the integral of eq. (8) of `001_…` (`p_S`), and the quantity ⟨1_S, p⟩ its
    /// Section VI builds every field-of-view pmf from. Only the marginal N(m_s, P_s) of the
    /// first n_s components matters; its Cholesky factor is the leading block of the full one.
    ///
    /// ```text
    /// ⟨1_S, N(m, P)⟩ = ∫_S N(s; m_s, P_s) ds
    /// ```
    ///
    /// # Methods and accuracy
    /// - **n_s = 1**: the region is a finite union of intervals, found exactly; the mass is
    ///   a sum of Φ differences taken in the accurate tail. Error ≈ 1e-16 per interval.
    /// - **a 2D box**: the bivariate normal rectangle probability
    ///   ([`bivariate_normal::rectangle`], Genz's method). Error below 1e-14 (reported as
    ///   1e-14).
    /// - **any other 2D region** (polygon, disc, unions, intersections, complements):
    ///   whiten with the Cholesky factor L (s = m + L z), so z is standard normal and the
    ///   region maps to polygons, parallelograms and ellipses; along the ray z = ρ(cos θ,
    ///   sin θ) the region is a set of segments [ρ₁, ρ₂], whose mass is exact, and
    ///
    ///   ```text
    ///   ⟨1_S, N(m, P)⟩ = (1/2π) ∫₀^{2π} Σ_{segments} ( e^{−ρ₁²/2} − e^{−ρ₂²/2} ) dθ
    ///   ```
    ///
    ///   by adaptive Gauss–Kronrod (7–15) with breakpoints at every vertex direction,
    ///   every direction parallel to a box face, every tangent direction of a disc, and every
    ///   crossing of two boundaries (except two discs'), and a substitution that removes
    ///   the √ behaviour at tangents. The returned error is the sum of the |K₁₅ − G₇|
    ///   estimates (target: `abs_tol`, default 1e-13) — an estimate, not a proof.
    /// - **n_s = 3, 4**: condition on the first whitened component z₁ and integrate the
    ///   (n_s − 1)-dimensional mass of the slice against φ(z₁) by adaptive Gauss–Kronrod over
    ///   |z₁| ≤ 9 (dropping < 2.3e-19), with breakpoints where the slice changes shape; the
    ///   error adds the outer estimate and the largest inner one.
    /// - a **complement** at the top is 1 − the mass of what it complements.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `{what}.mean` if the Gaussian has fewer than n_s
    /// components (`what` is how the caller names the Gaussian, e.g. `rfs.poisson[1]`);
    /// [`Error::Unsupported`] for n_s > [`MAX_MASS_DIM`].
    ///
    /// # Examples
    /// ```
    /// use fisst::gaussian::Gaussian;
    /// use fisst::regions::Region;
    /// // A disc of radius 1 centred on the mean of N(0, I): mass 1 − e^{−1/2}.
    /// let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "p")?;
    /// let disc = Region::ball(&[0.0, 0.0], 1.0, "fov")?;
    /// let m = disc.gaussian_mass(&g, "p")?;
    /// assert!((m.value - (1.0 - (-0.5f64).exp())).abs() < 1e-13);
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn gaussian_mass(&self, gaussian: &Gaussian, what: &str) -> Result<Mass> {
        self.gaussian_mass_with_tolerance(gaussian, what, DEFAULT_TOL)
    }

    /// [`Region::gaussian_mass`] with the absolute tolerance of the adaptive quadratures
    /// (values below 1e-15 are raised to it; a 2D box or a 1D region is exact regardless).
    ///
    /// # Errors
    /// As [`Region::gaussian_mass`].
    pub fn gaussian_mass_with_tolerance(
        &self,
        gaussian: &Gaussian,
        what: &str,
        abs_tol: f64,
    ) -> Result<Mass> {
        let ns = self.dim();
        if gaussian.dim() < ns {
            return Err(Error::dimension(
                alloc::format!("{what}.mean"),
                ns,
                gaussian.dim(),
            ));
        }
        if ns > MAX_MASS_DIM {
            return Err(Error::Unsupported {
                what: alloc::format!("{what}.mean"),
                reason: "Gaussian masses of regions of more than 4 dimensions are not supported",
            });
        }
        let tol = if abs_tol.is_nan() {
            DEFAULT_TOL
        } else {
            abs_tol.max(1e-15)
        };
        let m: Vec<f64> = gaussian.mean().iter().take(ns).copied().collect();
        let chol = gaussian.chol();
        let mut l = vec![0.0; ns * ns];
        for i in 0..ns {
            for j in 0..=i {
                l[i * ns + j] = chol[(i, j)];
            }
        }
        let shape = Shape::from_region(self);
        let q = mass_of(&shape, &m, &l, tol);
        Ok(Mass {
            value: q.value.clamp(0.0, 1.0),
            error: q.error,
        })
    }
}

/// The region as a tree that can be sliced (a slice of a box is a box, of a ball a ball).
#[derive(Clone, Debug)]
enum Shape {
    Empty,
    Full,
    Box { min: Vec<f64>, max: Vec<f64> },
    Ball { center: Vec<f64>, radius: f64 },
    Polygon(Vec<[f64; 2]>),
    Union(Vec<Shape>),
    Inter(Vec<Shape>),
    Compl(Box<Shape>),
}

impl Shape {
    fn from_region(r: &Region) -> Shape {
        match r.node() {
            Node::Box(b) => Shape::Box {
                min: b.min().to_vec(),
                max: b.max().to_vec(),
            },
            Node::Polygon(p) => Shape::Polygon(p.vertices().to_vec()),
            Node::Ball(b) => Shape::Ball {
                center: b.center().to_vec(),
                radius: b.radius(),
            },
            Node::Union(m) => Shape::Union(m.iter().map(Shape::from_region).collect()),
            Node::Intersection(m) => Shape::Inter(m.iter().map(Shape::from_region).collect()),
            Node::Complement(r) => Shape::Compl(Box::new(Shape::from_region(r))),
        }
    }

    /// The slice {s' : (t, s') ∈ S}, one dimension lower. Polygons are 2D and are never
    /// sliced (2D regions go to the ray method).
    fn slice(&self, t: f64) -> Shape {
        match self {
            Shape::Empty => Shape::Empty,
            Shape::Full => Shape::Full,
            Shape::Box { min, max } => {
                if min[0] <= t && t <= max[0] {
                    Shape::Box {
                        min: min[1..].to_vec(),
                        max: max[1..].to_vec(),
                    }
                } else {
                    Shape::Empty
                }
            }
            Shape::Ball { center, radius } => {
                let d = t - center[0];
                let r2 = radius * radius - d * d;
                if r2 > 0.0 {
                    Shape::Ball {
                        center: center[1..].to_vec(),
                        radius: fns::sqrt(r2),
                    }
                } else {
                    Shape::Empty
                }
            }
            Shape::Polygon(_) => Shape::Empty,
            Shape::Union(m) => {
                let parts: Vec<Shape> = m
                    .iter()
                    .map(|s| s.slice(t))
                    .filter(|s| !matches!(s, Shape::Empty))
                    .collect();
                if parts.iter().any(|s| matches!(s, Shape::Full)) {
                    Shape::Full
                } else if parts.is_empty() {
                    Shape::Empty
                } else {
                    Shape::Union(parts)
                }
            }
            Shape::Inter(m) => {
                let parts: Vec<Shape> = m
                    .iter()
                    .map(|s| s.slice(t))
                    .filter(|s| !matches!(s, Shape::Full))
                    .collect();
                if parts.iter().any(|s| matches!(s, Shape::Empty)) {
                    Shape::Empty
                } else if parts.is_empty() {
                    Shape::Full
                } else {
                    Shape::Inter(parts)
                }
            }
            Shape::Compl(r) => match r.slice(t) {
                Shape::Empty => Shape::Full,
                Shape::Full => Shape::Empty,
                s => Shape::Compl(Box::new(s)),
            },
        }
    }

    /// First-coordinate values where the slice changes shape.
    fn first_axis_breaks(&self, out: &mut Vec<f64>) {
        match self {
            Shape::Empty | Shape::Full | Shape::Polygon(_) => {}
            Shape::Box { min, max } => {
                out.push(min[0]);
                out.push(max[0]);
            }
            Shape::Ball { center, radius } => {
                out.push(center[0] - radius);
                out.push(center[0] + radius);
            }
            Shape::Union(m) | Shape::Inter(m) => m.iter().for_each(|s| s.first_axis_breaks(out)),
            Shape::Compl(r) => r.first_axis_breaks(out),
        }
    }
}

/// The mass of `shape` under N(m, L Lᵀ), L lower-triangular row-major n × n.
fn mass_of(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
    let n = m.len();
    match shape {
        Shape::Empty => {
            return Quad {
                value: 0.0,
                error: 0.0,
            };
        }
        Shape::Full => {
            return Quad {
                value: 1.0,
                error: 0.0,
            };
        }
        Shape::Compl(inner) => {
            let q = mass_of(inner, m, l, tol);
            return Quad {
                value: 1.0 - q.value,
                error: q.error,
            };
        }
        _ => {}
    }
    match n {
        1 => mass_1d(shape, m[0], l[0]),
        2 => {
            if let Shape::Box { min, max } = shape {
                mass_box_2d(min, max, m, l)
            } else {
                mass_ray_2d(shape, m, l, tol)
            }
        }
        _ => mass_nested(shape, m, l, tol),
    }
}

// ---------------------------------------------------------------------------------------
// Interval sets (sorted, disjoint, closed intervals; measure is all that matters).

type Intervals = Vec<(f64, f64)>;

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

fn combine(
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

// ---------------------------------------------------------------------------------------
// n_s = 1: exact.

fn mass_1d(shape: &Shape, m: f64, sigma: f64) -> Quad {
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

// ---------------------------------------------------------------------------------------
// A 2D box: the bivariate normal rectangle probability.

fn mass_box_2d(min: &[f64], max: &[f64], m: &[f64], l: &[f64]) -> Quad {
    let s0 = l[0];
    let s1 = fns::sqrt(l[2] * l[2] + l[3] * l[3]);
    let rho = (l[2] / s1).clamp(-1.0, 1.0);
    let value = bivariate_normal::rectangle(
        (min[0] - m[0]) / s0,
        (max[0] - m[0]) / s0,
        (min[1] - m[1]) / s1,
        (max[1] - m[1]) / s1,
        rho,
    );
    Quad {
        value,
        error: 1e-14,
    }
}

// ---------------------------------------------------------------------------------------
// Other 2D regions: the ray method in whitened coordinates.

/// A primitive prepared for rays z = ρ u from the whitened origin.
enum RayLeaf {
    /// Box constraints lo_k ≤ ρ (L u)_k ≤ hi_k (lo, hi relative to the mean).
    Slabs { lo: [f64; 2], hi: [f64; 2] },
    /// Disc |ρ L u − δ| ≤ r with δ = centre − mean.
    Disc { delta: [f64; 2], r: f64 },
    /// Polygon with whitened vertices.
    Poly(Vec<[f64; 2]>),
}

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

fn mass_ray_2d(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
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

// ---------------------------------------------------------------------------------------
// n_s ≥ 3: condition on the first whitened component.

fn mass_nested(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
    let n = m.len();
    let l00 = l[0];
    let mut breaks = Vec::new();
    shape.first_axis_breaks(&mut breaks);
    let mut pts: Vec<f64> = breaks
        .into_iter()
        .map(|t| (t - m[0]) / l00)
        .filter(|z| z.is_finite() && fns::abs(*z) < Z_MAX)
        .collect();
    pts.push(-Z_MAX);
    pts.push(Z_MAX);
    crate::math::sort::sort_f64(&mut pts);
    pts.dedup();
    // Sub-block of L and the column that shifts the conditional mean.
    let k = n - 1;
    let mut sub = vec![0.0; k * k];
    for i in 0..k {
        for j in 0..=i {
            sub[i * k + j] = l[(i + 1) * n + (j + 1)];
        }
    }
    let col: Vec<f64> = (1..n).map(|i| l[i * n]).collect();
    let inner_tol = tol * 0.1;
    let mut worst_inner = 0.0f64;
    let mut cm = vec![0.0; k];
    let q = integrate_smooth_ends(
        |z: f64| {
            let t = m[0] + l00 * z;
            let slice = shape.slice(t);
            for i in 0..k {
                cm[i] = m[i + 1] + col[i] * z;
            }
            let inner = mass_of(&slice, &cm, &sub, inner_tol);
            worst_inner = worst_inner.max(inner.error);
            normal::pdf(z) * inner.value
        },
        &pts,
        tol,
        MAX_INTERVALS,
    );
    Quad {
        value: q.value,
        error: q.error + worst_inner + 3e-19,
    }
}

#[cfg(test)]
mod tests;

//! Algorithms 1 and 2 of `001_…`: recursive splitting of the components that straddle the
//! boundaries of one or several regions.

use alloc::format;
use alloc::rc::Rc;
use alloc::vec::Vec;
use core::cell::OnceCell;

use nalgebra::{DMatrix, DVector};

use super::SplitLibrary;
use super::component::{Eigen, child_covariance, child_means};
use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::fns;
use crate::regions::{Hull, Region, RegionSet};

/// Largest number of collocation points N_g^{n_s} of the full grid (before the ball cut (22)).
pub const MAX_GRID_POINTS: usize = 1 << 20;
/// Largest recursion depth [`SplitOptions::max_depth`] may be set to.
pub const MAX_DEPTH_LIMIT: usize = 64;

/// The knobs of Algorithms 1 and 2 (the split library is passed separately).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct SplitOptions {
    /// n_s: the position states are the first `position_dims` state components (Section III
    /// of `001_…`); every region must have this dimension. Default 2.
    pub position_dims: usize,
    /// w_min: components with weight below it are never split (Algorithm 1); neither are
    /// components of weight 0. The weight is absolute (compare it with the mixture's total
    /// weight). Default 0.01, the value of the Fig. 5 example.
    pub min_weight: f64,
    /// ζ of eqs. (20)–(22): the collocation grid spans [−ζ, ζ] per axis of the whitened
    /// position space and keeps the points with ‖ȳ‖ ≤ ζ, so ζ is a Mahalanobis radius. A
    /// component whose region boundary lies entirely outside that radius is not split (it
    /// keeps up to Φ(−ζ) of its weight on the wrong side: 2.3 % for ζ = 2). Default 2 with
    /// N_g = 15, as in the authors' public Python implementation (`pyest`, `split_for_fov`);
    /// Appendix A's example (plane l = 9 holds the points i₁ = 2 … 14) fits that grid.
    ///
    /// This tail sets a floor on the accuracy of the mean-based partition (11)–(12) that a
    /// smaller w_min does not remove. Measured for N(0, 1) and the half-line x > 0.3 (R = 3,
    /// λ = 0.001, N_g = 41, w_min = 10⁻³ … 10⁻⁵): with ζ = 2 the partition misses the mass
    /// of the split mixture by about 6·10⁻³; with ζ = 3 by 1–3·10⁻⁴, leaving the split
    /// library's own approximation error (about 3·10⁻³ of mass for R = 3, 3·10⁻⁴ for R = 4).
    pub grid_bound: f64,
    /// N_g of eqs. (20)–(22): grid points per axis (≥ 2; odd values put a point on every
    /// principal axis). Default 15.
    pub grid_points: usize,
    /// Cap on the recursion depth (each level splits a component at most once). A
    /// component that still straddles a boundary at this depth is kept unsplit and the
    /// outcome reports [`SplitStop::MaxDepth`]. Default 16; at most [`MAX_DEPTH_LIMIT`].
    pub max_depth: usize,
    /// Cap on the number of components of the result. A split that would exceed it is not
    /// made (its component is kept unsplit) and the outcome reports
    /// [`SplitStop::MaxComponents`]. Default 10 000.
    pub max_components: usize,
}

impl Default for SplitOptions {
    fn default() -> Self {
        Self {
            position_dims: defaults::position_dims(),
            min_weight: defaults::min_weight(),
            grid_bound: defaults::grid_bound(),
            grid_points: defaults::grid_points(),
            max_depth: defaults::max_depth(),
            max_components: defaults::max_components(),
        }
    }
}

/// The defaults of a split request, one function per field (the form serde's
/// `#[serde(default = "…")]` takes): [`SplitOptions::default`] is built from them, and so are
/// the bindings' options that hold the split library's R and λ next to these fields.
pub mod defaults {
    /// n_s = 2 ([`SplitOptions::position_dims`](super::SplitOptions::position_dims)).
    pub const fn position_dims() -> usize {
        2
    }
    /// w_min = 0.01 ([`SplitOptions::min_weight`](super::SplitOptions::min_weight)).
    pub const fn min_weight() -> f64 {
        0.01
    }
    /// ζ = 2 ([`SplitOptions::grid_bound`](super::SplitOptions::grid_bound)).
    pub const fn grid_bound() -> f64 {
        2.0
    }
    /// N_g = 15 ([`SplitOptions::grid_points`](super::SplitOptions::grid_points)).
    pub const fn grid_points() -> usize {
        15
    }
    /// 16 levels ([`SplitOptions::max_depth`](super::SplitOptions::max_depth)).
    pub const fn max_depth() -> usize {
        16
    }
    /// 10 000 components ([`SplitOptions::max_components`](super::SplitOptions::max_components)).
    pub const fn max_components() -> usize {
        10_000
    }
    /// R = 3: the split library's component count of a split request (Fig. 5's R).
    pub const fn components() -> usize {
        3
    }
    /// λ = 0.001 of eq. (13): the split library's weight of a split request (Table I's λ).
    pub const fn lambda() -> f64 {
        0.001
    }
}

/// Which cap stopped the recursion early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "camelCase")
)]
pub enum SplitStop {
    /// A component still straddled a boundary at the depth cap ([`SplitOptions::max_depth`]).
    MaxDepth,
    /// A split would have exceeded the component cap ([`SplitOptions::max_components`]).
    MaxComponents,
}

/// The result of [`split_for_regions`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitOutcome {
    /// The split mixture. Each input component is replaced in place by its descendants, so
    /// the order follows the input.
    pub mixture: GaussianMixture,
    /// The number of recursion levels at which some component was split.
    pub depth: usize,
    /// The number of split operations (each replaces one component by R).
    pub splits: usize,
    /// `None` when the recursion ended by itself (every remaining component is consistently
    /// inside or outside on the grid, or lighter than w_min); otherwise the cap that
    /// stopped it. The mixture is valid either way, only less refined.
    pub stop: Option<SplitStop>,
}

/// The collocation grid of eqs. (20)–(22).
struct Grid {
    /// The points ȳ, flat, `n_s` numbers each.
    points: Vec<f64>,
    ns: usize,
    ng: usize,
    /// ζ.
    zeta: f64,
    /// 64-bit words of a bit set over the points.
    words: usize,
    /// Per plane (j, l) (slot j·N_g + l): the bit set of its points.
    planes: Vec<u64>,
    /// For n_s = 2: the runs [a, b) of points with the same ȳ_2 (the rows along the first
    /// axis, each on one segment of the mapped grid); empty otherwise.
    rows: Vec<(usize, usize)>,
}

impl Grid {
    /// ```text
    /// ȳ_j(l) = −ζ + 2ζ (l − 1)/(N_g − 1)               (21)
    /// G = {(i₁ … i_{n_s}) : ‖ȳ_{i₁…i_{n_s}}‖ ≤ ζ}       (22)
    /// ```
    fn new(ns: usize, ng: usize, zeta: f64) -> Self {
        let axis: Vec<f64> = (0..ng)
            .map(|l| -zeta + 2.0 * zeta * (l as f64 / (ng - 1) as f64))
            .collect();
        // Points on the sphere ‖ȳ‖ = ζ (the axis ends when N_g is odd) belong to G; the
        // relative slack absorbs the rounding of ȳ.
        let r2 = zeta * zeta * (1.0 + 1e-12);
        let mut points = Vec::new();
        let mut index = Vec::new();
        let mut idx = alloc::vec![0usize; ns];
        loop {
            let norm2: f64 = idx.iter().map(|&i| axis[i] * axis[i]).sum();
            if norm2 <= r2 {
                points.extend(idx.iter().map(|&i| axis[i]));
                index.extend_from_slice(&idx);
            }
            // Odometer increment.
            let mut d = 0;
            loop {
                if d == ns {
                    let count = index.len() / ns;
                    let words = count.div_ceil(64);
                    let mut planes = alloc::vec![0u64; ns * ng * words];
                    for (p, idx) in index.chunks_exact(ns).enumerate() {
                        for (j, &l) in idx.iter().enumerate() {
                            planes[(j * ng + l) * words + p / 64] |= 1 << (p % 64);
                        }
                    }
                    let mut rows: Vec<(usize, usize)> = Vec::new();
                    if ns == 2 {
                        for (p, idx) in index.chunks_exact(2).enumerate() {
                            match rows.last_mut() {
                                Some((_, b)) if index[2 * (*b - 1) + 1] == idx[1] => *b = p + 1,
                                _ => rows.push((p, p + 1)),
                            }
                        }
                    }
                    return Self {
                        points,
                        ns,
                        ng,
                        zeta,
                        words,
                        planes,
                        rows,
                    };
                }
                idx[d] += 1;
                if idx[d] < ng {
                    break;
                }
                idx[d] = 0;
                d += 1;
            }
        }
    }

    fn len(&self) -> usize {
        self.points.len() / self.ns
    }
}

/// What a component needs for the split decision: the full-state eigendecomposition and
/// the position block's.
struct CovInfo {
    full: Eigen,
    position: Eigen,
}

/// One component during the recursion. Siblings share their covariance and its
/// decomposition.
struct Item {
    weight: f64,
    mean: DVector<f64>,
    cov: Rc<Shared>,
    /// The input component it descends from (names errors).
    origin: usize,
    /// Whether it is the input component itself (never split): the output then clones the
    /// input Gaussian, factor included, instead of building one.
    original: bool,
    done: bool,
}

struct Shared {
    cov: DMatrix<f64>,
    info: OnceCell<CovInfo>,
    /// The first output Gaussian with this covariance (its siblings reuse the factor).
    gaussian: OnceCell<Gaussian>,
}

impl Shared {
    fn new(cov: DMatrix<f64>) -> Rc<Self> {
        Rc::new(Self {
            cov,
            info: OnceCell::new(),
            gaussian: OnceCell::new(),
        })
    }

    fn info(&self, ns: usize, origin: usize) -> Result<&CovInfo> {
        if let Some(info) = self.info.get() {
            return Ok(info);
        }
        // The name is built only for an error.
        let what = || format!("mixture[{origin}].cov");
        let full = Eigen::named(&self.cov, &what)?;
        let position = if ns == self.cov.nrows() {
            full.clone()
        } else {
            Eigen::named(&self.cov.view((0, 0), (ns, ns)).into_owned(), &what)?
        };
        Ok(self.info.get_or_init(|| CovInfo { full, position }))
    }
}

/// Validates the options against the mixture and regions.
fn validate(
    mixture: &GaussianMixture,
    regions: &[Region],
    library: &SplitLibrary,
    options: &SplitOptions,
) -> Result<()> {
    let ns = options.position_dims;
    if ns == 0 {
        return Err(Error::parameter("positionDims", 0.0, "an integer >= 1"));
    }
    if let Some(n) = mixture.dim()
        && ns > n
    {
        return Err(Error::parameter(
            "positionDims",
            ns as f64,
            "at most the state dimension",
        ));
    }
    for (i, r) in regions.iter().enumerate() {
        if r.dim() != ns {
            return Err(Error::dimension(format!("regions[{i}]"), ns, r.dim()));
        }
    }
    if !(options.min_weight.is_finite() && options.min_weight >= 0.0) {
        return Err(Error::parameter(
            "minWeight",
            options.min_weight,
            "finite and >= 0",
        ));
    }
    if !(options.grid_bound.is_finite() && options.grid_bound > 0.0) {
        return Err(Error::parameter(
            "gridBound",
            options.grid_bound,
            "finite and > 0",
        ));
    }
    let ng = options.grid_points;
    let total = (0..ns).try_fold(1usize, |acc, _| acc.checked_mul(ng));
    if ng < 2 || total.is_none_or(|t| t > MAX_GRID_POINTS) {
        return Err(Error::parameter(
            "gridPoints",
            ng as f64,
            "an integer >= 2 with gridPoints^positionDims <= 2^20",
        ));
    }
    if options.max_depth > MAX_DEPTH_LIMIT {
        return Err(Error::parameter(
            "maxDepth",
            options.max_depth as f64,
            "an integer in [0, 64]",
        ));
    }
    if library.components() < 2 {
        return Err(Error::parameter(
            "components",
            library.components() as f64,
            "an integer >= 2",
        ));
    }
    Ok(())
}

/// Algorithm 1 of `001_…` (`split_for_fov`): [`split_for_regions`] with one region.
///
/// # Errors
/// As [`split_for_regions`].
pub fn split_for_region(
    mixture: &GaussianMixture,
    region: &Region,
    library: &SplitLibrary,
    options: &SplitOptions,
) -> Result<SplitOutcome> {
    split_for_regions(mixture, core::slice::from_ref(region), library, options)
}

/// Algorithm 2 of `001_0f0df91eee9b30d5.txt` (`split_for_multifov`, Algorithm 1 when there is
/// one region): recursively splits every component that straddles a region boundary, so that
/// the mean-based partition [`partition`](super::partition) (11)–(12) becomes accurate.
///
/// For each component ℓ with weight ≥ w_min ([`SplitOptions::min_weight`]):
///
/// 1. **Change of variables** (15)–(19): with P_s = V_s Λ_s V_sᵀ the position block of P
///    (first n_s states) and m_s its mean, y = Λ_s^{−1/2} V_sᵀ (s − m_s) makes the position
///    marginal N(0, I); the region maps to S_y = h(S).
///
///    ```text
///    y = h(s) = Λ_s^{−1/2} V_sᵀ (s − m_s)             (15)–(17)
///    ```
///
/// 2. **Collocation grid** (20)–(22) of N_g points per axis on [−ζ, ζ], kept within the ball
///    ‖ȳ‖ ≤ ζ.
/// 3. **Inclusion** (23), (33): d^{(ι)} = 1_{S_y^{(ι)}}(ȳ) = 1_{S^{(ι)}}(m_s + V_s Λ_s^{1/2} ȳ),
///    decided by the region's own exact test [`Region::contains`] on the mapped-back point
///    (no region is ever transformed, so the test stays exact).
/// 4. **Split or not** (24), (34): no split when, for every region, all grid points agree.
/// 5. **Position direction** (25)–(26), (35): a grid plane y_j = ȳ_j(l) is consistent when, in
///    every region, all its points agree; j* maximises the number of consistent planes.
///    **Tie rule**: among tied j the eigenvector of the largest eigenvalue λ_{s,j} (the
///    paper's rule; eigenvalues are sorted descending, so the first).
/// 6. **Full-state direction** (32): k* = argmax_k |[v_{s,j*}ᵀ 0ᵀ] v_k| over the eigenvectors
///    of the full P (ties again to the largest eigenvalue), and the component is split by
///    [`split_component`](super::split_component) (27)–(31) along v_{k*}.
///
/// The children are examined again at the next level; the recursion ends when no component
/// needs a split. Each level evaluates (34)–(35) as products over all regions, so the result
/// does not depend on the order of `regions` (bit for bit).
///
/// # Caps
/// Nothing can make it run away: each level splits a component at most once, the depth is
/// capped by [`SplitOptions::max_depth`] and the size by [`SplitOptions::max_components`].
/// At a cap the recursion **stops** (the components not yet refined stay as they are) and
/// [`SplitOutcome::stop`] says which cap; it is not an error. With w_min > 0 the recursion
/// ends by itself after at most ln(w_min/w)/ln(max_j w̃_j) levels.
///
/// # Limitations
/// The decision only sees the collocation points: a region (or a part of one) thinner than
/// the grid spacing 2ζ/(N_g − 1) (0.29 σ by default) can fall between the points and go
/// unnoticed, and a boundary farther than ζ from the mean is ignored. The accuracy of the
/// final partition is limited by w_min (see [`partition_accuracy`](super::partition_accuracy)).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `positionDims` (0 or above the state dimension),
/// `minWeight` (negative or not finite), `gridBound` (not finite and > 0), `gridPoints` (< 2
/// or N_g^{n_s} > 2²⁰), `maxDepth` (> 64); [`Error::DimensionMismatch`] naming `regions[i]`
/// for a region whose dimension is not n_s; [`Error::NotDefinite`] naming
/// `mixture[ℓ].cov` if an eigendecomposition or a child's Cholesky factorisation fails.
///
/// # Examples
/// ```
/// use fisst::gaussian::{Gaussian, GaussianMixture};
/// use fisst::regions::Region;
/// use fisst::splitting::{SplitLibrary, SplitOptions, partition, split_for_regions};
/// let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "mixture[0]")?;
/// let p = GaussianMixture::new(vec![(1.0, g)], "mixture")?;
/// let fov = Region::axis_box(&[0.5, -10.0], &[10.0, 10.0], "regions[0]")?;
/// let library = SplitLibrary::for_components(3, 0.001, Default::default())?;
/// let out = split_for_regions(&p, &[fov.clone()], &library, &SplitOptions::default())?;
/// assert!(out.mixture.len() > 1 && out.stop.is_none());
/// // Mean-based partition: close to the exact P(x > 0.5) = 0.3085.
/// let part = partition(&out.mixture, &fov)?;
/// assert!((part.inside_weight - 0.3085).abs() < 0.02);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn split_for_regions(
    mixture: &GaussianMixture,
    regions: &[Region],
    library: &SplitLibrary,
    options: &SplitOptions,
) -> Result<SplitOutcome> {
    validate(mixture, regions, library, options)?;
    let ns = options.position_dims;
    let grid = Grid::new(ns, options.grid_points, options.grid_bound);
    if grid.len() == 0 {
        return Err(Error::parameter(
            "gridPoints",
            options.grid_points as f64,
            "a grid with at least one point within gridBound of the origin (use an odd count)",
        ));
    }
    let r = library.components();
    let mut items: Vec<Item> = mixture
        .components()
        .iter()
        .enumerate()
        .map(|(i, (w, g))| Item {
            weight: *w,
            mean: g.mean().clone(),
            cov: Shared::new(g.cov().clone()),
            origin: i,
            original: true,
            done: false,
        })
        .collect();
    let mut depth = 0;
    let mut splits = 0;
    let mut stop = None;
    let set = RegionSet::new(regions);
    let mut scratch = Scratch::new(&grid);
    loop {
        if items.iter().all(|it| it.done) {
            break;
        }
        let mut count = items.len();
        // Room for every pending item to split (R children each), within the size cap.
        let pending = items.iter().filter(|it| !it.done).count();
        let mut next = Vec::with_capacity(
            (items.len() + pending * (r - 1)).min(options.max_components.max(items.len())),
        );
        let mut split_here = false;
        for mut item in items {
            if item.done {
                next.push(item);
                continue;
            }
            let k = if item.weight < options.min_weight || item.weight == 0.0 || regions.is_empty()
            {
                None
            } else {
                let info = item.cov.info(ns, item.origin)?;
                split_direction(&item.mean, info, &set, &grid, &mut scratch)
            };
            let Some(k) = k else {
                item.done = true;
                next.push(item);
                continue;
            };
            if depth >= options.max_depth {
                stop = Some(SplitStop::MaxDepth);
                item.done = true;
                next.push(item);
                continue;
            }
            if count + (r - 1) > options.max_components {
                stop = Some(SplitStop::MaxComponents);
                item.done = true;
                next.push(item);
                continue;
            }
            let info = item.cov.info(ns, item.origin)?;
            let cov = Shared::new(child_covariance(
                &item.cov.cov,
                &info.full,
                k,
                library.sigma(),
            ));
            for (mean, wt) in child_means(&item.mean, &info.full, k, library)
                .into_iter()
                .zip(library.weights())
            {
                next.push(Item {
                    weight: wt * item.weight,
                    mean,
                    cov: Rc::clone(&cov),
                    origin: item.origin,
                    original: false,
                    done: false,
                });
            }
            count += r - 1;
            splits += 1;
            split_here = true;
        }
        items = next;
        if split_here {
            depth += 1;
        }
    }
    let mut components = Vec::with_capacity(items.len());
    for item in items {
        let g = if item.original {
            mixture.components()[item.origin].1.clone()
        } else {
            let origin = item.origin;
            let what = move || format!("mixture[{origin}]");
            match item.cov.gaussian.get() {
                Some(sibling) => sibling.with_mean(item.mean, &what)?,
                None => {
                    let g = Gaussian::named(item.mean, item.cov.cov.clone(), &what)?;
                    let _ = item.cov.gaussian.set(g.clone());
                    g
                }
            }
        };
        components.push((item.weight, g));
    }
    Ok(SplitOutcome {
        mixture: GaussianMixture::new(components, "mixture")?,
        depth,
        splits,
        stop,
    })
}

/// Buffers reused across components.
struct Scratch {
    /// The grid mapped back to position space, flat.
    mapped: Vec<f64>,
    /// Per flattened region node: decided on the component's ball, or not.
    state: Vec<Option<bool>>,
    /// Per node: the inclusion bits of the grid points.
    bits: Vec<u64>,
    /// Per plane (j, l): consistent in every region so far.
    plane_ok: Vec<bool>,
    /// The ball's radius per axis (the hull's box when n_s > 4).
    reach: Vec<f64>,
}

impl Scratch {
    fn new(grid: &Grid) -> Self {
        Self {
            mapped: alloc::vec![0.0; grid.points.len()],
            state: Vec::new(),
            bits: Vec::new(),
            plane_ok: alloc::vec![true; grid.ns * grid.ng],
            reach: Vec::new(),
        }
    }
}

/// The split decision of one component: `None` if every region includes or excludes the
/// whole grid (24)/(34), otherwise k* of (32) for the direction j* of (26)/(35).
///
/// The inclusions d^{(ι)} of (23)/(33) are bit sets over the grid points
/// ([`RegionSet::evaluate`]); a region is consistent on a plane when its bits on the plane
/// are all 0 or all 1, and on the grid when they are all 0 or all 1 there (the same
/// decisions as testing the points one by one, bit for bit).
fn split_direction(
    mean: &DVector<f64>,
    info: &CovInfo,
    set: &RegionSet<'_>,
    grid: &Grid,
    scratch: &mut Scratch,
) -> Option<usize> {
    let ns = grid.ns;
    let pos = &info.position;
    // Every grid point lies within ζ √λ_max of the mean (‖ȳ‖ ≤ ζ); a region that holds or
    // misses that whole ball agrees on every point, so it changes neither test (24)/(34)
    // nor (25)/(35) and is skipped: the result is the same bit for bit, only faster. The
    // same holds for every node of a region's tree (a union member that misses the ball).
    let lambda_max = pos.values.first().copied().unwrap_or(0.0);
    let scale = mean
        .iter()
        .take(ns)
        .fold(1.0f64, |a, m| a.max(fns::abs(*m)));
    let slack = 1e-12 * scale;
    let reach = grid.zeta * fns::sqrt(lambda_max) * (1.0 + 1e-8) + slack;
    // s = m_s + V_s Λ_s^{1/2} ȳ  (the inverse of (15)), as (V_s Λ_s^{1/2})_{ij} ȳ_j summed
    // in j order.
    let mut a = [0.0f64; 16];
    let small = ns <= 4;
    // √λ_j, on the stack for n_s ≤ 4 (one decision per component and level: no allocation).
    let mut roots_small = [0.0f64; 4];
    let roots_vec: Vec<f64>;
    let roots: &[f64] = if small {
        for (r, &l) in roots_small.iter_mut().zip(&pos.values) {
            *r = fns::sqrt(l);
        }
        &roots_small[..ns]
    } else {
        roots_vec = pos.values.iter().map(|&l| fns::sqrt(l)).collect();
        &roots_vec
    };
    if small {
        for i in 0..ns {
            for j in 0..ns {
                a[i * ns + j] = pos.vectors[(i, j)] * roots[j];
            }
        }
    }
    // The grid's bounding box: |s_i − m_i| ≤ ζ ‖row i of V_s Λ_s^{1/2}‖ (the support of the
    // ellipse along axis i), with the same room for rounding as the ball.
    let mut half_width = [0.0f64; 4];
    if small {
        for (i, h) in half_width.iter_mut().enumerate().take(ns) {
            let row2: f64 = (0..ns).map(|j| a[i * ns + j] * a[i * ns + j]).sum();
            *h = grid.zeta * fns::sqrt(row2) * (1.0 + 1e-8) + slack;
        }
    }
    if !small {
        scratch.reach.clear();
        scratch.reach.resize(ns, reach);
    }
    let hull = Hull {
        center: &mean.as_slice()[..ns],
        radius: reach,
        // Without the box (n_s > 4) every axis gets the ball's radius.
        half_width: if small {
            &half_width[..ns]
        } else {
            &scratch.reach[..]
        },
        vectors: pos.vectors.as_slice(),
        roots,
        zeta: grid.zeta,
        slack,
    };
    set.classify(&hull, &mut scratch.state);
    if set.roots().iter().all(|&r| scratch.state[r].is_some()) {
        return None;
    }
    if ns == 2 {
        // The loop below unrolled for the plane (the same operations in the same order).
        let (m0, m1) = (mean[0], mean[1]);
        let [a00, a01, a10, a11] = [a[0], a[1], a[2], a[3]];
        for (p, out) in grid
            .points
            .chunks_exact(2)
            .zip(scratch.mapped.chunks_exact_mut(2))
        {
            out[0] = m0 + a00 * p[0] + a01 * p[1];
            out[1] = m1 + a10 * p[0] + a11 * p[1];
        }
    } else {
        for (p, out) in grid
            .points
            .chunks_exact(ns)
            .zip(scratch.mapped.chunks_exact_mut(ns))
        {
            for (i, o) in out.iter_mut().enumerate() {
                let mut s = mean[i];
                if small {
                    for j in 0..ns {
                        s += a[i * ns + j] * p[j];
                    }
                } else {
                    for j in 0..ns {
                        s += pos.vectors[(i, j)] * roots[j] * p[j];
                    }
                }
                *o = s;
            }
        }
    }
    let count = grid.len();
    let words = grid.words;
    // Each mapped coordinate m_i + Σ_j a_ij ȳ_j is within a few ulps of |m_i| + Σ_j |a_ij ȳ_j|
    // ≤ |m_i| + √2 ζ √λ_max of its exact value: far below this tolerance.
    let tol = 1e-12 * (scale + 2.0 * reach);
    set.evaluate(
        &scratch.mapped,
        ns,
        count,
        if ns == 2 { &grid.rows } else { &[] },
        tol,
        &scratch.state,
        &mut scratch.bits,
    );
    scratch.plane_ok.iter_mut().for_each(|x| *x = true);
    let full = |w: usize| {
        if w + 1 == words && !count.is_multiple_of(64) {
            (1u64 << (count % 64)) - 1
        } else {
            u64::MAX
        }
    };
    let mut all_consistent = true;
    for &root in set.roots() {
        if scratch.state[root].is_some() {
            continue;
        }
        let d = &scratch.bits[root * words..(root + 1) * words];
        let none = d.iter().all(|&x| x == 0);
        let all = d.iter().enumerate().all(|(w, &x)| x == full(w));
        if !(none || all) {
            all_consistent = false;
        }
        for (slot, ok) in scratch.plane_ok.iter_mut().enumerate() {
            if !*ok {
                continue;
            }
            let m = &grid.planes[slot * words..(slot + 1) * words];
            let (mut any_in, mut all_in) = (false, true);
            for (x, mw) in d.iter().zip(m) {
                let y = x & mw;
                any_in |= y != 0;
                all_in &= y == *mw;
            }
            if any_in && !all_in {
                *ok = false;
            }
        }
    }
    if all_consistent {
        return None;
    }
    // (26): the direction with the most consistent planes; ties to the largest eigenvalue.
    let mut j_star = 0;
    let mut best = 0usize;
    for j in 0..ns {
        let c = scratch.plane_ok[j * grid.ng..(j + 1) * grid.ng]
            .iter()
            .filter(|&&ok| ok)
            .count();
        if j == 0 || c > best {
            best = c;
            j_star = j;
        }
    }
    // (32): the full-state eigenvector best aligned with [v_{s,j*}; 0]; ties to the largest
    // eigenvalue.
    let full = &info.full;
    let n = full.values.len();
    let mut k_star = 0;
    let mut best_dot = -1.0;
    for k in 0..n {
        let dot: f64 = (0..ns)
            .map(|i| pos.vectors[(i, j_star)] * full.vectors[(i, k)])
            .sum();
        let dot = fns::abs(dot);
        if dot > best_dot {
            best_dot = dot;
            k_star = k;
        }
    }
    Some(k_star)
}

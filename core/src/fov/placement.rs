//! Sensor placement (Section VII of `001_…`): the variance of the number of objects in an
//! axis-aligned field of view, over a grid of FoV centres, for a multi-Bernoulli RFS with
//! Gaussian components.

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result, check_probability};
use crate::gaussian::{Gaussian, normal};
use crate::math::fns;
use crate::regions::bivariate_normal;

/// The largest count of grid centres along one axis.
pub const MAX_GRID_AXIS: usize = 4096;
/// The largest number of grid cells (FoV centres) of one map.
pub const MAX_GRID_CELLS: usize = 1 << 22;

/// Standardised distance beyond which the bivariate correction C(h, k) = Φ₂(h, k; ρ) −
/// Φ(h)Φ(k) is dropped: |C| ≤ (|asin ρ|/2π) e^{−max(h², k²)/2} ≤ 5.1e-17 there.
const CORE: f64 = 8.5;
/// A component whose x- or y-marginal mass in the FoV is at most this contributes at most
/// this to the variance of that cell, and is skipped there.
const SKIP: f64 = 1e-17;

/// Centres `min + i·(max − min)/(count − 1)`, i = 0 … count − 1 (`min` alone for count 1).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GridAxis {
    /// The first FoV centre along the axis.
    pub min: f64,
    /// The last FoV centre along the axis.
    pub max: f64,
    /// The number of FoV centres along the axis (≥ 1).
    pub count: usize,
}

impl GridAxis {
    fn step(&self) -> f64 {
        if self.count > 1 {
            (self.max - self.min) / (self.count - 1) as f64
        } else {
            0.0
        }
    }

    /// The i-th centre, `min + i·step` (the last may differ from `max` by rounding).
    pub fn centre(&self, i: usize) -> f64 {
        self.min + i as f64 * self.step()
    }

    fn validate(&self, name: &str) -> Result<()> {
        if !self.min.is_finite() {
            return Err(Error::parameter(
                alloc::format!("{name}[0]"),
                self.min,
                "finite",
            ));
        }
        if !(self.max.is_finite() && self.max >= self.min) {
            return Err(Error::parameter(
                alloc::format!("{name}[1]"),
                self.max,
                "finite and >= the minimum",
            ));
        }
        if self.count == 0 || self.count > MAX_GRID_AXIS {
            return Err(Error::parameter(
                alloc::format!("{name}[2]"),
                self.count as f64,
                "an integer count in [1, 4096]",
            ));
        }
        Ok(())
    }
}

/// The FoV-count variance over a grid of FoV centres.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct VarianceMap {
    /// Var[|X ∩ S(x_i, y_j)|], row-major with y as the outer index: entry `j·nx + i`.
    pub variance: Vec<f64>,
    /// The number of FoV centres along x.
    pub nx: usize,
    /// The number of FoV centres along y.
    pub ny: usize,
    /// The FoV centre (x, y) of the largest variance (the first in row-major order on ties).
    pub argmax: [f64; 2],
    /// The grid indices (i, j) of the largest variance's centre.
    pub argmax_index: [usize; 2],
    /// The largest FoV-count variance over the grid.
    pub max: f64,
}

/// The position marginal of a component, standardised.
#[derive(Clone, Copy, Debug)]
struct Component {
    r: f64,
    mx: f64,
    my: f64,
    sx: f64,
    sy: f64,
    rho: f64,
}

impl Component {
    fn new(r: f64, g: &Gaussian) -> Component {
        let m = g.mean();
        let p = g.cov();
        let sx = fns::sqrt(p[(0, 0)]);
        let sy = fns::sqrt(p[(1, 1)]);
        Component {
            r,
            mx: m[0],
            my: m[1],
            sx,
            sy,
            rho: (p[(0, 1)] / (sx * sy)).clamp(-1.0, 1.0),
        }
    }
}

/// One axis of the corner lattice of a component: standardised corner coordinates `v`,
/// where `v[left[i]]` and `v[right[i]]` are the low and high FoV edges of active centre
/// `first + i`, and the values form uniform runs `(start index, length, first value, step)`.
#[derive(Default)]
struct Lattice {
    v: Vec<f64>,
    left: Vec<usize>,
    right: Vec<usize>,
    runs: Vec<(usize, usize, f64, f64)>,
}

impl Lattice {
    /// Corners `centre ± half` of the centres `first .. last` of `axis`, standardised by
    /// (· − mean)/sd. When the FoV size is a whole number of grid steps (to 4 ulps), high
    /// edges coincide with low edges of later centres and the lattice is shared.
    fn build(&mut self, axis: &GridAxis, half: f64, first: usize, last: usize, mean: f64, sd: f64) {
        self.v.clear();
        self.left.clear();
        self.right.clear();
        self.runs.clear();
        let step = axis.step();
        let n_act = last - first;
        let shift = if step > 0.0 {
            let n = libm::round(2.0 * half / step);
            let exact = fns::abs(n * step - 2.0 * half) <= 4.0 * f64::EPSILON * 2.0 * half;
            (exact && n >= 1.0 && n < (2 * MAX_GRID_AXIS) as f64).then_some(n as usize)
        } else {
            None
        };
        let lo0 = axis.min - half;
        match shift {
            Some(n) => {
                let len = n_act + n;
                for p in 0..len {
                    self.v.push((lo0 + (first + p) as f64 * step - mean) / sd);
                }
                self.left.extend(0..n_act);
                self.right.extend(n..n + n_act);
                self.runs
                    .push((0, len, (lo0 + first as f64 * step - mean) / sd, step / sd));
            }
            None => {
                for (start, edge) in [(0, -half), (n_act, half)] {
                    let base = axis.min + edge;
                    for i in first..last {
                        self.v.push((base + i as f64 * step - mean) / sd);
                    }
                    self.runs.push((
                        start,
                        n_act,
                        (base + first as f64 * step - mean) / sd,
                        step / sd,
                    ));
                }
                self.left.extend(0..n_act);
                self.right.extend(n_act..2 * n_act);
            }
        }
    }
}

/// Reusable buffers of [`component_masses`].
#[derive(Default)]
struct Work {
    px: Vec<f64>,
    py: Vec<f64>,
    hx: Lattice,
    ky: Lattice,
    table: Vec<f64>,
    bk: Vec<f64>,
    phi_h: Vec<f64>,
    phi_k: Vec<f64>,
}

/// Calls `visit(i, j, mass)` with the component's mass in the FoV centred at grid cell
/// (i, j), for every cell where both marginal masses exceed [`SKIP`] (the others have mass
/// ≤ 1e-17).
fn component_masses(
    comp: &Component,
    gx: &GridAxis,
    gy: &GridAxis,
    size: [f64; 2],
    work: &mut Work,
    mut visit: impl FnMut(usize, usize, f64),
) {
    let (hw, hh) = (0.5 * size[0], 0.5 * size[1]);
    // Marginal masses of every centre, and the (contiguous) active ranges.
    let marginal = |axis: &GridAxis, half: f64, mean: f64, sd: f64, out: &mut Vec<f64>| {
        out.clear();
        for i in 0..axis.count {
            let c = axis.centre(i);
            out.push(normal::interval(
                (c - half - mean) / sd,
                (c + half - mean) / sd,
            ));
        }
        let first = out.iter().position(|&p| p > SKIP);
        let last = out.iter().rposition(|&p| p > SKIP);
        match (first, last) {
            (Some(a), Some(b)) => Some((a, b + 1)),
            _ => None,
        }
    };
    let Some((c0, c1)) = marginal(gx, hw, comp.mx, comp.sx, &mut work.px) else {
        return;
    };
    let Some((r0, r1)) = marginal(gy, hh, comp.my, comp.sy, &mut work.py) else {
        return;
    };
    if comp.rho == 0.0 {
        for j in r0..r1 {
            for i in c0..c1 {
                visit(i, j, work.px[i] * work.py[j]);
            }
        }
        return;
    }
    work.hx.build(gx, hw, c0, c1, comp.mx, comp.sx);
    work.ky.build(gy, hh, r0, r1, comp.my, comp.sy);
    let (nh, nk) = (work.hx.v.len(), work.ky.v.len());
    work.table.clear();
    work.table.resize(nh * nk, 0.0);
    correction_table(
        comp.rho,
        &work.hx,
        &work.ky,
        &mut work.table,
        &mut work.bk,
        &mut work.phi_h,
        &mut work.phi_k,
    );
    let t = &work.table;
    for (jj, j) in (r0..r1).enumerate() {
        let (kl, kr) = (work.ky.left[jj], work.ky.right[jj]);
        let py = work.py[j];
        for (ii, i) in (c0..c1).enumerate() {
            let (hl, hr) = (work.hx.left[ii], work.hx.right[ii]);
            let dc = (t[hr * nk + kr] - t[hl * nk + kr]) - (t[hr * nk + kl] - t[hl * nk + kl]);
            visit(i, j, (work.px[i] * py + dc).clamp(0.0, 1.0));
        }
    }
}

/// Fills `table[a·nk + b]` with C(h_a, k_b) = Φ₂(h_a, k_b; ρ) − Φ(h_a)Φ(k_b) for the lattice
/// points with |h|, |k| ≤ [`CORE`] (0 elsewhere).
///
/// For |ρ| < 0.925 this is Genz's Gauss–Legendre sum of the Drezner–Wesolowsky integral
/// (the same nodes as [`bivariate_normal::cdf`]),
/// C = Σ_j a_j exp(−(h² + k² − 2 s_j h k)/(2c_j)), factored as
/// a_j e^{−h²/2c_j} · e^{−k²/2c_j} · e^{s_j h k/c_j}: along a uniform run k = k₀ + q·Δ the
/// last factor is geometric in q, so each table entry costs a few multiplications instead
/// of exponentials. For |ρ| ≥ 0.925, core entries near the diagonal band are one
/// [`bivariate_normal::cdf`] each and the others a closed form (see [`variance_map`]).
#[allow(clippy::too_many_arguments)]
fn correction_table(
    rho: f64,
    hx: &Lattice,
    ky: &Lattice,
    table: &mut [f64],
    bk: &mut Vec<f64>,
    phi_h: &mut Vec<f64>,
    phi_k: &mut Vec<f64>,
) {
    let nk = ky.v.len();
    let core = |x: f64| fns::abs(x) <= CORE;
    if fns::abs(rho) >= 0.925 {
        phi_h.clear();
        phi_h.extend(hx.v.iter().map(|&h| normal::cdf(h)));
        phi_k.clear();
        phi_k.extend(ky.v.iter().map(|&k| normal::cdf(k)));
        // Off the band |h ∓ k| ≤ 8.5·√(2(1 − |ρ|)) the distribution function has a closed
        // form to within Φ(−8.5) ≈ 9.5e-18: for ρ > 0 and h ≤ k, Φ₂ = Φ(h) − P(X ≤ h, Y > k)
        // and that event implies Y − X > k − h, with Y − X ~ N(0, 2(1 − ρ)); for ρ < 0 the
        // same with Y → −Y gives Φ₂ = max(0, Φ(h) + Φ(k) − 1) + (≤ Φ(−|h + k|/√(2(1 + ρ)))).
        let band = CORE * fns::sqrt(2.0 * (1.0 - fns::abs(rho)));
        for (a, &h) in hx.v.iter().enumerate() {
            if !core(h) {
                continue;
            }
            for (b, &k) in ky.v.iter().enumerate() {
                if !core(k) {
                    continue;
                }
                let (ph, pk) = (phi_h[a], phi_k[b]);
                let f = if rho > 0.0 {
                    if fns::abs(h - k) > band {
                        ph.min(pk)
                    } else {
                        bivariate_normal::cdf(h, k, rho)
                    }
                } else if fns::abs(h + k) > band {
                    (ph + pk - 1.0).max(0.0)
                } else {
                    bivariate_normal::cdf(h, k, rho)
                };
                table[a * nk + b] = f - ph * pk;
            }
        }
        return;
    }
    // Nodes θ_j of Genz's rule on [0, asin ρ]: s_j = sin θ_j, c_j = cos² θ_j, weights a_j.
    let (x, w) = bivariate_normal::rule(rho);
    let asr = libm::asin(rho) / 2.0;
    let mut s = [0.0; 20];
    let mut c = [0.0; 20];
    let mut a = [0.0; 20];
    let mut nn = 0;
    for (&xi, &wi) in x.iter().zip(w) {
        for node in [1.0 - xi, 1.0 + xi] {
            let sn = libm::sin(asr * node);
            s[nn] = sn;
            c[nn] = 1.0 - sn * sn;
            a[nn] = wi * asr / (2.0 * core::f64::consts::PI);
            nn += 1;
        }
    }
    // B_j(k) = e^{−k²/2c_j}, node-minor.
    bk.clear();
    bk.resize(nk * nn, 0.0);
    for (b, &k) in ky.v.iter().enumerate() {
        if core(k) {
            for j in 0..nn {
                bk[b * nn + j] = fns::exp(-k * k / (2.0 * c[j]));
            }
        }
    }
    let mut ln_amp = [0.0; 20];
    let mut e = [0.0; 20];
    let mut ratio = [0.0; 20];
    for (ai, &h) in hx.v.iter().enumerate() {
        if !core(h) {
            continue;
        }
        for j in 0..nn {
            ln_amp[j] = fns::ln(fns::abs(a[j])) - h * h / (2.0 * c[j]);
        }
        let row = &mut table[ai * nk..(ai + 1) * nk];
        for &(start, len, k0, dk) in &ky.runs {
            // The core part of the run: k0 + q·dk ∈ [−CORE, CORE].
            let Some(q_lo) = (0..len).find(|&q| core(ky.v[start + q])) else {
                continue;
            };
            let q_hi = (q_lo..len)
                .rposition(|q| core(ky.v[start + q]))
                .map_or(q_lo, |p| q_lo + p + 1);
            // e_j(q) = a_j e^{−h²/2c_j} e^{g_j k_q}, g_j = s_j h / c_j, is geometric in q.
            // Run it from the end where it is largest (its exponent is at most
            // s²h²/2c ≤ 215 in the core: no overflow) towards where it is smallest, so
            // that an underflow to 0 only ever happens to terms that stay negligible.
            let upward = s[0] * h <= 0.0;
            let (q_first, step) = if upward { (q_lo, dk) } else { (q_hi - 1, -dk) };
            let k_first = k0 + q_first as f64 * dk;
            for j in 0..nn {
                let g = s[j] * h / c[j];
                let sign = if a[j] < 0.0 { -1.0 } else { 1.0 };
                e[j] = sign * fns::exp(ln_amp[j] + g * k_first);
                ratio[j] = fns::exp(g * step);
            }
            let out = &mut row[start + q_lo..start + q_hi];
            let bks = &bk[(start + q_lo) * nn..(start + q_hi) * nn];
            match nn {
                6 => run::<6>(out, bks, &mut e, &ratio, upward),
                12 => run::<12>(out, bks, &mut e, &ratio, upward),
                _ => run::<20>(out, bks, &mut e, &ratio, upward),
            }
        }
    }
}

/// `out[q] = Σ_j e_j B_j(q)` with `e_j ← e_j · ratio_j` after each q, visiting q upwards or
/// downwards; N nodes, fixed at compile time so the node loop unrolls.
#[inline]
fn run<const N: usize>(
    out: &mut [f64],
    bks: &[f64],
    e: &mut [f64; 20],
    ratio: &[f64; 20],
    upward: bool,
) {
    let ratio: &[f64; N] = ratio[..N].try_into().unwrap_or(&[0.0; N]);
    let mut ev = [0.0; N];
    ev.copy_from_slice(&e[..N]);
    let mut step = |o: &mut f64, bj: &[f64]| {
        let mut acc = 0.0;
        for j in 0..N {
            acc += ev[j] * bj[j];
            ev[j] *= ratio[j];
        }
        *o = acc;
    };
    if upward {
        for (o, bj) in out.iter_mut().zip(bks.chunks_exact(N)) {
            step(o, bj);
        }
    } else {
        for (o, bj) in out.iter_mut().zip(bks.chunks_exact(N)).rev() {
            step(o, bj);
        }
    }
}

fn check_components(components: &[(f64, Gaussian)]) -> Result<Vec<Component>> {
    components
        .iter()
        .enumerate()
        .map(|(i, (r, g))| {
            check_probability(|| alloc::format!("multi_bernoulli[{i}].existence"), *r)?;
            if g.dim() < 2 {
                return Err(Error::dimension(
                    alloc::format!("multi_bernoulli[{i}].mean"),
                    2,
                    g.dim(),
                ));
            }
            Ok(Component::new(*r, g))
        })
        .collect()
}

fn check_size(fov_size: [f64; 2]) -> Result<()> {
    for (k, &v) in fov_size.iter().enumerate() {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::parameter(
                alloc::format!("fov_size[{k}]"),
                v,
                "finite and > 0",
            ));
        }
    }
    Ok(())
}

/// ⟨1_S, p⟩ of one component for the FoV of size `size` centred at (`cx`, `cy`), by the
/// direct bivariate rectangle ([`bivariate_normal::rectangle`]).
fn direct_mass(comp: &Component, cx: f64, cy: f64, size: [f64; 2]) -> f64 {
    // halves first: cx ± w/2 cannot overflow where cx + w could
    let (hw, hh) = (0.5 * size[0], 0.5 * size[1]);
    bivariate_normal::rectangle(
        (cx - hw - comp.mx) / comp.sx,
        (cx + hw - comp.mx) / comp.sx,
        (cy - hh - comp.my) / comp.sy,
        (cy + hh - comp.my) / comp.sy,
        comp.rho,
    )
}

/// The variance of the number of objects in an axis-aligned `fov_size[0] × fov_size[1]` FoV
/// centred at every point of a grid, and its maximiser: the sensor-placement objective of
/// Section VII of `001_…` (Figs 9–10) for a multi-Bernoulli RFS whose components
/// (r⁽ⁱ⁾, N(m⁽ⁱ⁾, P⁽ⁱ⁾)) have positions in their first two components:
///
/// ```text
/// Var[|X ∩ S|] = Σ_i r_S⁽ⁱ⁾ (1 − r_S⁽ⁱ⁾),   r_S⁽ⁱ⁾ = r⁽ⁱ⁾ ⟨1_S, p⁽ⁱ⁾⟩            (89)
/// ```
///
/// the closed-form variance of the pmf (88) (a Poisson-binomial), which the paper computes
/// through the DFT (90) for every FoV position.
///
/// # How it is fast, and its accuracy
/// ⟨1_S, p⁽ⁱ⁾⟩ for the box [x ± w/2] × [y ± h/2] is P_x P_y + ΔC, the product of the two
/// marginal interval masses (accurate Φ differences) plus the inclusion–exclusion of the
/// correction C(h, k) = Φ₂(h, k; ρ) − Φ(h)Φ(k) at the four standardised corners. Per
/// component:
/// - the corners form a lattice shared by neighbouring centres (when the FoV size is a whole
///   number of grid steps, a high edge is a later centre's low edge);
/// - C is evaluated only where both |h|, |k| ≤ 8.5 — elsewhere |C| ≤ 5.1e-17, a rigorous
///   bound (C is the integral of e^{−(h² + k² − 2hk sin θ)/2cos²θ} ≤ e^{−max(h², k²)/2}
///   over an angle ≤ π/2, divided by 2π);
/// - cells whose x- or y-marginal mass is ≤ 1e-17 are skipped (the component's mass there,
///   and so its variance term, is ≤ 1e-17);
/// - for |ρ| < 0.925, C uses Genz's Gauss–Legendre nodes (the same numbers as
///   [`bivariate_normal::cdf`]) with each exponential factored into row, column and a
///   geometric cross term, so a table entry costs ~3 multiplications per node; for
///   |ρ| ≥ 0.925 each core corner within the band |h ∓ k| ≤ 8.5·√(2(1 − |ρ|)) is one full
///   Genz evaluation, and off the band Φ₂ is Φ(min(h, k)) (ρ > 0) or
///   max(0, Φ(h) + Φ(k) − 1) (ρ < 0) to within Φ(−8.5) ≈ 9.5e-18 (if X ≤ h < k < Y then
///   Y − X ~ N(0, 2(1 − ρ)) exceeds k − h).
///
/// Each mass carries the error of Genz's method (≈1e-15 per corner) plus rounding of the
/// geometric recurrences (≲1e-14) and the dropped terms above (≤ 4 × 5.1e-17): the tests
/// check every mass against [`bivariate_normal::rectangle`] to 1e-13 and the variances to
/// 1e-12. When the FoV size is within 4 ulps of a whole number of steps, corners are moved
/// by that much (an added error ≤ 4ε · size · density).
///
/// # Errors
/// Using the Rust field names: [`Error::InvalidProbability`] naming
/// `multi_bernoulli[i].existence`; [`Error::DimensionMismatch`] naming `multi_bernoulli[i].mean`
/// for a Gaussian of fewer than 2 components; [`Error::InvalidParameter`] naming
/// `fov_size[k]` (must be finite and > 0) or `grid.x[0…2]` / `grid.y[0…2]`;
/// [`Error::Unsupported`] naming `grid` for more than [`MAX_GRID_CELLS`] cells.
///
/// # Examples
/// ```
/// use fisst::fov::{variance_map, GridAxis};
/// use fisst::gaussian::Gaussian;
/// let g = Gaussian::from_slices(&[0.0, 0.0], &[0.04, 0.0, 0.0, 0.04], "p")?;
/// let axis = GridAxis { min: -1.0, max: 1.0, count: 41 };
/// let map = variance_map(&[(1.0, g)], [1.0, 1.0], axis, axis)?;
/// // A certain object is most uncertain to be inside (variance m(1 − m) → 1/4) where the
/// // FoV boundary halves its mass, and nearly certain when the FoV is centred on it.
/// assert!((map.max - 0.25).abs() < 1e-4);
/// let m = 1.0 - 2.0 * fisst::gaussian::normal::cdf(-2.5); // P(|X| ≤ 0.5), σ = 0.2
/// let centred = map.variance[20 * 41 + 20];
/// assert!((centred - m * m * (1.0 - m * m)).abs() < 1e-12);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn variance_map(
    components: &[(f64, Gaussian)],
    fov_size: [f64; 2],
    x: GridAxis,
    y: GridAxis,
) -> Result<VarianceMap> {
    let comps = check_components(components)?;
    check_size(fov_size)?;
    x.validate("grid.x")?;
    y.validate("grid.y")?;
    let cells = x.count * y.count;
    if cells > MAX_GRID_CELLS {
        return Err(Error::Unsupported {
            what: "grid".into(),
            reason: "more than 2^22 FoV centres",
        });
    }
    let mut variance = vec![0.0; cells];
    let mut work = Work::default();
    for comp in &comps {
        let r = comp.r;
        if r == 0.0 {
            continue;
        }
        component_masses(comp, &x, &y, fov_size, &mut work, |i, j, m| {
            // A grid whose step is beyond the f64 range in standard deviations (a centre
            // near ±1e308) breaks the recurrences (∞ − ∞): that cell's mass is then the
            // direct rectangle (exact, finite for every limit).
            let m = if m.is_finite() {
                m
            } else {
                direct_mass(comp, x.centre(i), y.centre(j), fov_size)
            };
            let q = r * m;
            variance[j * x.count + i] += q * (1.0 - q);
        });
    }
    let mut best = 0usize;
    for (k, &v) in variance.iter().enumerate() {
        if v > variance[best] {
            best = k;
        }
    }
    let (bi, bj) = (best % x.count, best / x.count);
    Ok(VarianceMap {
        max: variance[best],
        variance,
        nx: x.count,
        ny: y.count,
        argmax: [x.centre(bi), y.centre(bj)],
        argmax_index: [bi, bj],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    /// A scene like the paper's: means in [−3, 3]², r ∈ [0.35, 1], random orientation and
    /// standard deviations in `sd`.
    fn scene(rng: &mut SmallRng, n: usize, sd: (f64, f64)) -> Vec<(f64, Gaussian)> {
        (0..n)
            .map(|_| {
                let a: f64 = rng.random_range(0.0..std::f64::consts::PI);
                let s1: f64 = rng.random_range(sd.0..sd.1);
                let s2: f64 = rng.random_range(sd.0..sd.1);
                let (c, s) = (a.cos(), a.sin());
                let p = [
                    c * c * s1 * s1 + s * s * s2 * s2,
                    c * s * (s1 * s1 - s2 * s2),
                    c * s * (s1 * s1 - s2 * s2),
                    s * s * s1 * s1 + c * c * s2 * s2,
                ];
                let m = [rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0)];
                (
                    rng.random_range(0.35..1.0),
                    Gaussian::from_slices(&m, &p, "p").unwrap(),
                )
            })
            .collect()
    }

    /// Fuzz seed 317566: a grid of two centres 1e308 apart (a step of 3e309 standard
    /// deviations) gave a NaN variance; the cells the recurrences cannot reach are computed
    /// directly.
    #[test]
    fn a_grid_step_beyond_the_f64_range_gives_finite_variances() {
        let g = |m: [f64; 2], p: [f64; 4]| Gaussian::from_slices(&m, &p, "p").unwrap();
        let comps = [
            (5e-324, g([0.0, 0.0], [0.001, -1e-323, -1e-323, 0.001])),
            (0.5, g([0.0, 0.0], [1.0, 0.0, 0.0, 1.0])),
            (0.0, g([0.0, 1e308], [1.0, 0.0, 0.0, 1.0])),
        ];
        let x = GridAxis {
            min: 0.0,
            max: 0.0,
            count: 1,
        };
        let y = GridAxis {
            min: 0.0,
            max: 1e308,
            count: 2,
        };
        let map = variance_map(&comps, [0.01, 0.01], x, y).unwrap();
        assert!(
            map.variance.iter().all(|v| v.is_finite()),
            "{:?}",
            map.variance
        );
        // the cell at the origin: the unit component's mass in a 0.01 square, ≈ 1.59e-5
        let q = 0.5 * bivariate_normal::rectangle(-0.005, 0.005, -0.005, 0.005, 0.0);
        assert!((map.variance[0] - q * (1.0 - q)).abs() <= 1e-12 * q);
        assert_eq!(map.variance[1], 0.0);
    }

    #[test]
    fn every_mass_matches_the_direct_bivariate_rectangle() {
        let mut rng = SmallRng::seed_from_u64(41);
        let mut worst = 0.0f64;
        // (sd range, FoV size, grid): shared and unshared lattices, tiny and wide components,
        // and a 1-centre axis.
        type Case = ((f64, f64), [f64; 2], GridAxis, GridAxis);
        let cases: [Case; 5] = [
            (
                (0.05, 0.6),
                [1.0, 1.0],
                GridAxis {
                    min: -3.0,
                    max: 3.0,
                    count: 61,
                },
                GridAxis {
                    min: -3.0,
                    max: 3.0,
                    count: 61,
                },
            ),
            (
                (0.05, 0.6),
                [0.73, 1.31],
                GridAxis {
                    min: -3.0,
                    max: 3.0,
                    count: 47,
                },
                GridAxis {
                    min: -2.5,
                    max: 3.5,
                    count: 39,
                },
            ),
            (
                (0.001, 0.02),
                [0.5, 0.25],
                GridAxis {
                    min: -3.0,
                    max: 3.0,
                    count: 121,
                },
                GridAxis {
                    min: -3.0,
                    max: 3.0,
                    count: 121,
                },
            ),
            (
                (1.0, 4.0),
                [2.0, 3.0],
                GridAxis {
                    min: -5.0,
                    max: 5.0,
                    count: 21,
                },
                GridAxis {
                    min: -5.0,
                    max: 5.0,
                    count: 11,
                },
            ),
            (
                (0.1, 1.0),
                [1.0, 0.5],
                GridAxis {
                    min: 0.3,
                    max: 0.3,
                    count: 1,
                },
                GridAxis {
                    min: -4.0,
                    max: 4.0,
                    count: 81,
                },
            ),
        ];
        for (sd, size, gx, gy) in cases {
            let comps = scene(&mut rng, 30, sd);
            let mut work = Work::default();
            for (r, g) in &comps {
                let comp = Component::new(*r, g);
                let mut seen = vec![false; gx.count * gy.count];
                component_masses(&comp, &gx, &gy, size, &mut work, |i, j, m| {
                    seen[j * gx.count + i] = true;
                    let want = direct_mass(&comp, gx.centre(i), gy.centre(j), size);
                    worst = worst.max((m - want).abs());
                    assert!(
                        (m - want).abs() < 1e-13,
                        "{comp:?} at ({i}, {j}): {m} vs {want}"
                    );
                });
                // Skipped cells have negligible mass.
                for j in 0..gy.count {
                    for i in 0..gx.count {
                        if !seen[j * gx.count + i] {
                            let want = direct_mass(&comp, gx.centre(i), gy.centre(j), size);
                            assert!(want <= 1e-17, "skipped mass {want}");
                        }
                    }
                }
            }
        }
        assert!(worst < 1e-13, "worst {worst:e}");
    }

    #[test]
    fn fig10_variance_map_matches_the_pmf_and_finds_the_maximum() {
        let mut rng = SmallRng::seed_from_u64(42);
        let comps = scene(&mut rng, 40, (0.1, 0.8));
        let gx = GridAxis {
            min: -3.0,
            max: 3.0,
            count: 25,
        };
        let gy = GridAxis {
            min: -2.0,
            max: 2.0,
            count: 17,
        };
        let size = [1.0, 0.8];
        let map = variance_map(&comps, size, gx, gy).unwrap();
        assert_eq!(map.variance.len(), 25 * 17);
        let mut best = (f64::NEG_INFINITY, 0, 0);
        for j in 0..gy.count {
            for i in 0..gx.count {
                let (cx, cy) = (gx.centre(i), gy.centre(j));
                // The variance of the full pmf (88) at this FoV, through the region API.
                let fov = crate::regions::Region::axis_box(
                    &[cx - 0.5, cy - 0.4],
                    &[cx + 0.5, cy + 0.4],
                    "fov",
                )
                .unwrap();
                let inside: Vec<f64> = comps
                    .iter()
                    .map(|(r, g)| r * fov.gaussian_mass(g, "p").unwrap().value)
                    .collect();
                let c = super::super::pmf::multi_bernoulli(&inside).unwrap();
                let pmf_var = {
                    let mean: f64 = c.pmf.iter().enumerate().map(|(n, p)| n as f64 * p).sum();
                    c.pmf
                        .iter()
                        .enumerate()
                        .map(|(n, p)| (n as f64 - mean).powi(2) * p)
                        .sum::<f64>()
                };
                let v = map.variance[j * gx.count + i];
                assert!((v - c.variance).abs() < 1e-12, "{v} vs {}", c.variance);
                assert!((v - pmf_var).abs() < 1e-10);
                if v > best.0 {
                    best = (v, i, j);
                }
            }
        }
        assert_eq!(map.argmax_index, [best.1, best.2]);
        assert_eq!(map.max, map.variance[best.2 * gx.count + best.1]);
        assert_eq!(map.argmax, [gx.centre(best.1), gy.centre(best.2)]);
    }

    #[test]
    fn validation_names_the_fields() {
        let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "p").unwrap();
        let ax = GridAxis {
            min: 0.0,
            max: 1.0,
            count: 3,
        };
        let e = variance_map(&[(1.2, g.clone())], [1.0, 1.0], ax, ax).unwrap_err();
        assert_eq!(e.field(), "multi_bernoulli[0].existence");
        let e = variance_map(&[(0.5, g.clone())], [1.0, 0.0], ax, ax).unwrap_err();
        assert_eq!(e.field(), "fov_size[1]");
        let bad = GridAxis {
            min: 1.0,
            max: 0.0,
            count: 3,
        };
        let e = variance_map(&[(0.5, g.clone())], [1.0, 1.0], ax, bad).unwrap_err();
        assert_eq!(e.field(), "grid.y[1]");
        let bad = GridAxis {
            min: 0.0,
            max: 1.0,
            count: 0,
        };
        let e = variance_map(&[(0.5, g.clone())], [1.0, 1.0], bad, ax).unwrap_err();
        assert_eq!(e.field(), "grid.x[2]");
        let g1 = Gaussian::from_slices(&[0.0], &[1.0], "p").unwrap();
        let e = variance_map(&[(0.5, g), (0.5, g1)], [1.0, 1.0], ax, ax).unwrap_err();
        assert_eq!(e.field(), "multi_bernoulli[1].mean");
        let m = variance_map(&[], [1.0, 1.0], ax, ax).unwrap();
        assert_eq!(m.max, 0.0);
        assert_eq!(m.argmax_index, [0, 0]);
    }
}

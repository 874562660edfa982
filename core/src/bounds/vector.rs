//! The vector extensions of paper 002 (Section V, (63)–(72)): a state in R^l, the component
//! metric e_i with e_i(∅, x') = e0/√l and e_i(x, ∅) = e1/√l, so that Σ_i e_i² = e².
//!
//! Each component bound is the scalar one with e0² → e0²/l, e1² → e1²/l, σ_e² → σ_{e,i}² and
//! J'⁻¹ → [J'⁻¹]_ii: the threshold e0²/(e0² + (1 − P̄o)(e1² − l σ_{e,i}²)) of (72) is the scalar
//! r* of these scaled errors. (For model I with false alarms the switch also carries the
//! (1 − q) of (18), which Section V's sentence drops; [`component_bound`] keeps it, since it is
//! where the HPE and LPE bounds of (63) cross.)

use alloc::vec::Vec;
use nalgebra::{DMatrix, DVector};

use crate::bounds::closed::{
    Assembled, Ingredients, NoClutterBound, assemble, check_nonnegative, corollary3, poisson_pmf,
};
use crate::bounds::model::{Density, Density1, Detection, LinearGaussian};
use crate::bounds::theorem::{
    Cardinality, JdeBound, Method, ModelI, Settings, check_common, check_result, theorem1,
};
use crate::bounds::theorem2::{ModelII, theorem2};
use crate::error::{Error, Result};
use crate::math::fns;

/// (63)/(64) for component i: the scalar ingredients `base` (η, w, r, P̄o, e0², e1² of the
/// whole state) with component i's [J'⁻¹]_ii and σ_{e,i}², and the errors divided by l.
pub fn component_bound(
    base: &Ingredients,
    dims: usize,
    inverse_information: f64,
    undetected_variance: f64,
) -> Result<Assembled> {
    if dims == 0 {
        return Err(Error::parameter("dims", 0.0, "≥ 1"));
    }
    let l = dims as f64;
    Ok(assemble(&Ingredients {
        inverse_information,
        undetected_variance,
        false_alarm_error: base.false_alarm_error / l,
        miss_error: base.miss_error / l,
        ..*base
    }))
}

/// (72): Corollary 3 per component, from the diagonal of J_1⁻¹ and the variances σ_{e,i}² of
/// f_d'. Errors name `inverseInformation[i]` etc.
pub fn component_bounds_no_clutter(
    existence: f64,
    mean_detection: f64,
    inverse_information: &[f64],
    undetected_variance: &[f64],
    false_alarm_error: f64,
    miss_error: f64,
) -> Result<Vec<NoClutterBound>> {
    let l = inverse_information.len();
    if l == 0 {
        return Err(Error::dimension("inverseInformation", 1, 0));
    }
    if undetected_variance.len() != l {
        return Err(Error::dimension(
            "undetectedVariance",
            l,
            undetected_variance.len(),
        ));
    }
    let lf = l as f64;
    inverse_information
        .iter()
        .zip(undetected_variance)
        .enumerate()
        .map(|(i, (&j, &s))| {
            corollary3(
                existence,
                mean_detection,
                j,
                s,
                false_alarm_error / lf,
                miss_error / lf,
            )
            .map_err(|e| match e.field() {
                "inverseInformation" | "undetectedVariance" => {
                    e.map_field(|f| alloc::format!("{f}[{i}]"))
                }
                _ => e,
            })
        })
        .collect()
}

/// (70): P̄o [J_1⁻¹]_ii + (1 − P̄o) σ_{e,i}² per component.
pub fn component_corollary1(
    mean_detection: f64,
    inverse_information: &[f64],
    undetected_variance: &[f64],
) -> Vec<f64> {
    inverse_information
        .iter()
        .zip(undetected_variance)
        .map(|(&j, &s)| mean_detection * j + (1.0 - mean_detection) * s)
        .collect()
}

/// J_1 = P⁻¹ + Hᵀ R⁻¹ H, the Fisher information matrix of N(x; x0, P) N(z; Hx, R) (the vector
/// form of Example 1, corrected as NOTES.md says), and its inverse (the posterior covariance).
pub fn gaussian_information_matrix(
    prior_cov: &DMatrix<f64>,
    gain: &DMatrix<f64>,
    noise_cov: &DMatrix<f64>,
) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    let l = prior_cov.nrows();
    if prior_cov.ncols() != l {
        return Err(Error::dimension("priorCovariance", l, prior_cov.ncols()));
    }
    if gain.ncols() != l {
        return Err(Error::dimension("gain", l, gain.ncols()));
    }
    let m = gain.nrows();
    if noise_cov.nrows() != m || noise_cov.ncols() != m {
        return Err(Error::dimension("noiseCovariance", m, noise_cov.nrows()));
    }
    for (what, a) in [
        ("priorCovariance", prior_cov),
        ("noiseCovariance", noise_cov),
    ] {
        for v in a.iter() {
            if !v.is_finite() {
                return Err(Error::parameter(what, *v, "finite"));
            }
        }
    }
    for v in gain.iter() {
        check_finite_gain(*v)?;
    }
    let p_inv = prior_cov
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "priorCovariance".into(),
        })?
        .inverse();
    let r_inv = noise_cov
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "noiseCovariance".into(),
        })?
        .inverse();
    let j = &p_inv + gain.transpose() * r_inv * gain;
    let inv = j
        .clone()
        .cholesky()
        .ok_or_else(|| Error::NotPositiveDefinite {
            what: "gain".into(),
        })?
        .inverse();
    Ok((j, inv))
}

fn check_finite_gain(v: f64) -> Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Error::parameter("gain", v, "finite"))
    }
}

/// The Gaussian prior f = N(x; x0, P) of a state in R^l (Section V).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussianPrior {
    mean: Vec<f64>,
    cov: DMatrix<f64>,
}

impl GaussianPrior {
    /// N(`mean`, `cov`), `cov` the l × l covariance in row-major order (symmetric positive
    /// definite). Errors name `mean[i]` or `cov`.
    pub fn new(mean: &[f64], cov: &[f64]) -> Result<Self> {
        let l = mean.len();
        if l == 0 {
            return Err(Error::dimension("mean", 1, 0));
        }
        for (i, &v) in mean.iter().enumerate() {
            if !v.is_finite() {
                return Err(Error::parameter(alloc::format!("mean[{i}]"), v, "finite"));
            }
        }
        let cov = spd("cov", l, cov)?;
        Ok(GaussianPrior {
            mean: mean.to_vec(),
            cov,
        })
    }

    /// l.
    pub fn dims(&self) -> usize {
        self.mean.len()
    }
}

/// A linear-Gaussian sensor with a constant detection probability: P_o(x) = P_o and
/// g(z|x) = N(z; H x + b, R), z in R^m.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearGaussianSensor {
    detection: f64,
    gain: DMatrix<f64>,
    offset: Vec<f64>,
    noise: DMatrix<f64>,
}

impl LinearGaussianSensor {
    /// P_o = `detection`, H = `gain` (m × `dims`, row-major; m = `gain.len() / dims`),
    /// b = `offset` (length m), R = `noise_cov` (m × m, row-major, symmetric positive
    /// definite). Errors name `detectionProbability`, `gain`, `offset` or `noiseCov`.
    pub fn new(
        detection: f64,
        gain: &[f64],
        dims: usize,
        offset: &[f64],
        noise_cov: &[f64],
    ) -> Result<Self> {
        crate::error::check_probability(|| "detectionProbability".into(), detection)?;
        if dims == 0 || gain.is_empty() || !gain.len().is_multiple_of(dims) {
            return Err(Error::dimension("gain", dims.max(1), gain.len()));
        }
        let m = gain.len() / dims;
        for &v in gain {
            check_finite_gain(v)?;
        }
        if offset.len() != m {
            return Err(Error::dimension("offset", m, offset.len()));
        }
        for (i, &v) in offset.iter().enumerate() {
            if !v.is_finite() {
                return Err(Error::parameter(alloc::format!("offset[{i}]"), v, "finite"));
            }
        }
        let noise = spd("noiseCov", m, noise_cov)?;
        Ok(LinearGaussianSensor {
            detection,
            gain: DMatrix::from_row_slice(m, dims, gain),
            offset: offset.to_vec(),
            noise,
        })
    }

    /// m, the measurement dimension.
    pub fn measurement_dims(&self) -> usize {
        self.gain.nrows()
    }
}

/// A symmetric positive definite n × n matrix from row-major entries.
fn spd(what: &'static str, n: usize, entries: &[f64]) -> Result<DMatrix<f64>> {
    if entries.len() != n * n {
        return Err(Error::dimension(what, n * n, entries.len()));
    }
    let a = DMatrix::from_row_slice(n, n, entries);
    let scale = a.iter().fold(0.0f64, |s, v| s.max(fns::abs(*v)));
    for i in 0..n {
        for j in 0..n {
            let (u, v) = (a[(i, j)], a[(j, i)]);
            if !u.is_finite() {
                return Err(Error::parameter(what, u, "finite"));
            }
            if fns::abs(u - v) > 1e-12 * scale {
                return Err(Error::NotPositiveDefinite { what: what.into() });
            }
        }
    }
    if a.clone().cholesky().is_none() {
        return Err(Error::NotPositiveDefinite { what: what.into() });
    }
    Ok(a)
}

/// The false observations of the vector bounds: model I's (q, ψ) or model II's (λ, c). Their
/// densities live on the measurement space, so they need m = 1 (a gain of one row) when
/// q > 0 or λ > 0.
#[derive(Clone, Copy)]
pub enum VectorMeasurement<'a> {
    /// Model I (13): a false observation with probability q and density ψ.
    I {
        /// q.
        false_alarm_probability: f64,
        /// ψ.
        false_alarm_density: &'a dyn Density,
    },
    /// Model II (22): Poisson clutter of rate λ and density c (v = λ c).
    II {
        /// λ.
        clutter_rate: f64,
        /// c.
        clutter_density: &'a dyn Density,
    },
}

/// The vector problem of Section V: a Gaussian state in R^l, a linear-Gaussian sensor,
/// models I or II, and the component errors e0²/l, e1²/l.
#[derive(Clone, Copy)]
pub struct VectorModel<'a> {
    /// r.
    pub existence: f64,
    /// f = N(x0, P).
    pub prior: &'a GaussianPrior,
    /// P_o, H, b, R.
    pub sensor: &'a LinearGaussianSensor,
    /// Model I or II and its false observations.
    pub measurement: VectorMeasurement<'a>,
    /// e0² (of the whole state; component i uses e0²/l).
    pub false_alarm_error: f64,
    /// e1² (of the whole state; component i uses e1²/l).
    pub miss_error: f64,
}

/// The bound (63)/(64) on the MSE σ_i² of component i.
#[derive(Clone, Debug, PartialEq)]
pub struct ComponentBound {
    /// The bound, its phase (the component's own rule on Z = ∅), threshold (72) and terms.
    pub assembled: Assembled,
    /// [J'_1⁻¹]_ii (63) or Σ_n C_n [J'_{1+n}⁻¹]_ii (64).
    pub inverse_information: f64,
    /// x*_i, the mean of f_d' (the prior mean: P_o is constant).
    pub undetected_mean: f64,
    /// σ_{e,i}² = P_ii.
    pub undetected_variance: f64,
    /// Error estimate of the bound (quadrature, one Monte Carlo standard error).
    pub error: f64,
}

/// The vector bounds: per component (63)/(64), and for the whole state.
#[derive(Clone, Debug, PartialEq)]
pub struct VectorBound {
    /// The bound on σ² = E e²(X, X̂) with the Euclidean metric (σ² = Σ_i σ_i²): the scalar
    /// assembly with S = tr(J'⁻¹) (or Σ C_n tr J'_{1+n}⁻¹) and σ_e² = tr P, one rule on Z = ∅
    /// for all components. It is ≥ Σ_i `components[i].bound` (each component may pick its own
    /// rule). `undetected_mean` is x*_1 (x* is in the components); `cardinalities` carry
    /// tr J'_n⁻¹; `region` is the MAP region of a one-point (scalar) measurement, empty when
    /// m > 1 (then there are no false observations and the region is all of R^m).
    pub total: JdeBound,
    /// One bound per component x_i.
    pub components: Vec<ComponentBound>,
    /// Σ_n C_n J'_{1+n}⁻¹ (J'_1⁻¹ for model I), the l × l matrix whose diagonal enters the
    /// estimation terms, row-major.
    pub inverse_information: Vec<f64>,
}

/// The vector extensions (63)–(65) of Theorems 1 and 2 for a Gaussian prior and a
/// linear-Gaussian sensor with constant P_o.
///
/// **How.** With m = 1 (z = hᵀx + b + v), everything on the measurement side (the MAP regions
/// Z'_0, Z_0^n, w_n, η, μ, C_n) depends on x only through s = hᵀx ~ N(hᵀx0, σ_s² = hᵀPh), so
/// it is the scalar [`theorem1`](super::theorem1) / [`theorem2`](super::theorem2) of the
/// problem in s. Given s, x is Gaussian with the constant covariance P − (Ph)(Ph)ᵀ/σ_s² and
/// p_n(x, Z) = N(x; x0 + a (s − hᵀx0), P − a aᵀσ_s²) p_n^s(s, Z), a = Ph/σ_s², so the Fisher
/// matrix (65) of the detected case is
///
/// ```text
/// J'_n = (1/w_n) (P⁻¹ + κ̄_n h hᵀ),   κ̄_n = w_n J'^s_n − 1/σ_s²,
/// [J'_n⁻¹]_ij = w_n (P_ij − a_i a_j σ_s²) + a_i a_j J'^s_n⁻¹
/// ```
///
/// (Sherman–Morrison; J'^s_n the scalar (20)/(25) of the problem in s). The per-component
/// bound is then [`component_bound`] with these [J'⁻¹]_ii, σ_{e,i}² = P_ii and e0²/l, e1²/l.
/// Each quadrature / Monte Carlo error propagates linearly. With m > 1 (any H, R) the
/// false-observation densities would live on R^m: only q = 0 / λ = 0 is served, where the
/// MAP region is all of R^m, w = 1 and J'_1 = J_1 = P⁻¹ + HᵀR⁻¹H ((72) and its matrix form);
/// the same closed form is used for m = 1 with h = 0.
pub fn vector_bound(m: &VectorModel<'_>, s: &Settings) -> Result<VectorBound> {
    let (prior, sensor) = (m.prior, m.sensor);
    let l = prior.dims();
    if sensor.gain.ncols() != l {
        return Err(Error::dimension("observation.gain", l, sensor.gain.ncols()));
    }
    check_common(m.existence, m.false_alarm_error, m.miss_error, s)?;
    let clutter_free = match m.measurement {
        VectorMeasurement::I {
            false_alarm_probability: q,
            ..
        } => {
            crate::error::check_probability(|| "falseAlarm.probability".into(), q)?;
            q == 0.0
        }
        VectorMeasurement::II {
            clutter_rate: lambda,
            ..
        } => check_nonnegative("clutter.rate", lambda)? == 0.0,
    };
    let p = &prior.cov;
    let scalar = if sensor.measurement_dims() == 1 {
        let h = sensor.gain.row(0).transpose();
        let ph = p * &h;
        let var_s = h.dot(&ph);
        // h is "zero" when hᵀPh is negligible against tr P |h|² (compared with h scaled to
        // max |h_i| = 1, so that neither side underflows), or when σ_s² itself is not a normal
        // number (a subnormal prior variance makes the scalar quadratures crawl: seconds).
        let big = h.amax();
        let hu = if big > 0.0 { &h / big } else { h.clone() };
        let relative = hu.dot(&(p * &hu)) > 1e-12 * p.trace() * hu.dot(&hu);
        (relative && var_s.is_normal()).then_some((h, ph, var_s))
    } else {
        None
    };
    let Some((h, ph, var_s)) = scalar else {
        if !clutter_free {
            return Err(Error::Unsupported {
                what: "observation.gain".into(),
                reason: "false alarms or clutter need a scalar measurement (a gain of one row, not all zero); with m > 1 only q = 0 or λ = 0 is served",
            });
        }
        return closed_form(m);
    };
    let mean_s = h.dot(&DVector::from_column_slice(&prior.mean));
    let sprior = Density1::gaussian(mean_s, var_s).map_err(|e| e.within("prior"))?;
    let sobs = LinearGaussian::new(
        Detection::constant(sensor.detection).map_err(|e| e.within("observation"))?,
        1.0,
        sensor.offset[0],
        sensor.noise[(0, 0)],
    )
    .map_err(|e| e.within("observation"))?;
    let (sb, q, model_ii) = match m.measurement {
        VectorMeasurement::I {
            false_alarm_probability,
            false_alarm_density,
        } => (
            theorem1(
                &ModelI {
                    existence: m.existence,
                    prior: &sprior,
                    observation: &sobs,
                    false_alarm_probability,
                    false_alarm_density,
                    false_alarm_error: m.false_alarm_error,
                    miss_error: m.miss_error,
                },
                s,
            )?,
            false_alarm_probability,
            None,
        ),
        VectorMeasurement::II {
            clutter_rate,
            clutter_density,
        } => (
            theorem2(
                &ModelII {
                    existence: m.existence,
                    prior: &sprior,
                    observation: &sobs,
                    clutter_rate,
                    clutter_density,
                    false_alarm_error: m.false_alarm_error,
                    miss_error: m.miss_error,
                },
                s,
            )?,
            0.0,
            Some(clutter_rate),
        ),
    };
    let a = &ph / var_s;
    // the covariance of x given s, P − a aᵀ σ_s²
    let residual = p - &a * a.transpose() * var_s;
    let outer = &a * a.transpose();
    let mut big_s = DMatrix::zeros(l, l);
    let mut err_resid = 0.0; // Σ C_k w_err_k (multiplies the residual variances)
    let mut err_inv = 0.0; // Σ C_k err_k (multiplies a_i²)
    let mut kept = 0.0;
    let mut big_w = 0.0;
    let mut cards = sb.cardinalities.clone();
    for c in cards.iter_mut() {
        big_s += (&residual * c.w + &outer * c.inverse_information) * c.probability;
        err_resid += c.probability * c.w_error;
        err_inv += c.probability * c.error;
        kept += c.probability;
        big_w += c.probability * c.w;
        c.inverse_information = c.w * residual.trace() + outer.trace() * c.inverse_information;
        c.error = c.w_error * residual.trace() + outer.trace() * c.error;
    }
    let zone = Zone::from_scalar(&sb, q, model_ii, kept, big_w);
    let lf = l as f64;
    let (r, pbar) = (m.existence, sb.mean_detection);
    let component = |i: usize| -> Result<ComponentBound> {
        let (s_i, var_i) = (big_s[(i, i)], p[(i, i)]);
        let (assembled, _) = zone.assemble(
            r,
            pbar,
            s_i,
            var_i,
            m.false_alarm_error / lf,
            m.miss_error / lf,
        );
        let err_s = residual[(i, i)].max(0.0) * err_resid + outer[(i, i)] * err_inv;
        Ok(ComponentBound {
            assembled,
            inverse_information: s_i,
            undetected_mean: prior.mean[i],
            undetected_variance: var_i,
            error: zone.error(
                r,
                pbar,
                err_s,
                var_i,
                m.false_alarm_error / lf,
                m.miss_error / lf,
            ),
        })
    };
    let components = (0..l).map(component).collect::<Result<Vec<_>>>()?;
    let (s_tr, var_tr) = (big_s.trace(), p.trace());
    let err_tr = residual.trace().max(0.0) * err_resid + outer.trace() * err_inv;
    let (assembled, eta) = zone.assemble(r, pbar, s_tr, var_tr, m.false_alarm_error, m.miss_error);
    let error = zone.error(r, pbar, err_tr, var_tr, m.false_alarm_error, m.miss_error);
    let total = check_result(JdeBound {
        assembled,
        mean_detection: pbar,
        undetected_mean: prior.mean[0],
        undetected_variance: var_tr,
        eta,
        region: sb.region.clone(),
        cardinalities: cards,
        error,
        regular: true,
    })?;
    check_vector(VectorBound {
        total,
        components,
        inverse_information: row_major(&big_s),
    })
}

/// [`check_result`] for the components and the matrix too: a NaN anywhere is an error.
fn check_vector(v: VectorBound) -> Result<VectorBound> {
    let nan = v.components.iter().any(|c| {
        let a = &c.assembled;
        [a.bound, a.hpe, a.lpe, c.error, c.inverse_information]
            .iter()
            .any(|x| x.is_nan())
    }) || v.inverse_information.iter().any(|x| x.is_nan());
    if nan {
        return Err(Error::Unsupported {
            what: "prior".into(),
            reason: "the integrals did not converge at this scale (NaN); rescale the problem",
        });
    }
    Ok(v)
}

fn row_major(a: &DMatrix<f64>) -> Vec<f64> {
    let mut v = Vec::with_capacity(a.nrows() * a.ncols());
    for i in 0..a.nrows() {
        for j in 0..a.ncols() {
            v.push(a[(i, j)]);
        }
    }
    v
}

/// The measurement-side ingredients of [`Ingredients`] shared by every component, read back
/// from the scalar theorem exactly as it assembled them.
struct Zone {
    absent_empty: f64,
    /// η: model I's η1, or model II's bracket [η2, η2 + tail] (the smaller bound is taken).
    eta: (f64, f64),
    undetected_empty: f64,
    model_ii: bool,
    detected_mass: f64,
    err_w: f64,
    err_eta: f64,
}

impl Zone {
    /// `q`: model I's false-alarm probability; `lambda`: model II's clutter rate.
    fn from_scalar(b: &JdeBound, q: f64, lambda: Option<f64>, kept: f64, big_w: f64) -> Zone {
        let err_w = b
            .cardinalities
            .iter()
            .map(|c| c.probability * c.w_error)
            .sum();
        match lambda {
            None => Zone {
                absent_empty: 1.0 - q,
                eta: (b.eta, b.eta),
                undetected_empty: 1.0,
                model_ii: false,
                detected_mass: big_w,
                err_w,
                err_eta: 0.0,
            },
            Some(lambda) => {
                let mut eta = 0.0;
                let mut err_eta = 0.0;
                let mut covered = poisson_pmf(lambda, 0);
                for c in &b.cardinalities {
                    let cn = poisson_pmf(lambda, c.n);
                    eta += cn * c.clutter_null;
                    err_eta += cn * c.clutter_null_error;
                    covered += cn;
                }
                let tail = (1.0 - covered).max(0.0);
                let e = fns::exp(-lambda);
                Zone {
                    absent_empty: e,
                    eta: (eta, (eta + tail).min(1.0)),
                    undetected_empty: e,
                    model_ii: true,
                    detected_mass: (big_w + (1.0 - kept).max(0.0)).min(1.0),
                    err_w,
                    err_eta,
                }
            }
        }
    }

    /// No false observations: the MAP region is everything (w = 1, η = 0).
    fn clutter_free() -> Zone {
        Zone {
            absent_empty: 1.0,
            eta: (0.0, 0.0),
            undetected_empty: 1.0,
            model_ii: false,
            detected_mass: 1.0,
            err_w: 0.0,
            err_eta: 0.0,
        }
    }

    #[allow(clippy::too_many_arguments)] // the scalars of one (63)/(64), named as there
    fn ingredients(
        &self,
        r: f64,
        pbar: f64,
        s: f64,
        var: f64,
        e0: f64,
        e1: f64,
        eta: f64,
    ) -> Ingredients {
        Ingredients {
            existence: r,
            mean_detection: pbar,
            undetected_variance: var,
            inverse_information: s,
            detected_mass: self.detected_mass,
            absent_empty: self.absent_empty,
            absent_null: eta,
            undetected_empty: self.undetected_empty,
            undetected_null: if self.model_ii { eta } else { 0.0 },
            false_alarm_error: e0,
            miss_error: e1,
        }
    }

    /// The smaller of the bounds at the two ends of the η bracket (as [`super::theorem2`]).
    fn assemble(&self, r: f64, pbar: f64, s: f64, var: f64, e0: f64, e1: f64) -> (Assembled, f64) {
        let lo = assemble(&self.ingredients(r, pbar, s, var, e0, e1, self.eta.0));
        let hi = assemble(&self.ingredients(r, pbar, s, var, e0, e1, self.eta.1));
        if hi.bound < lo.bound {
            (hi, self.eta.1)
        } else {
            (lo, self.eta.0)
        }
    }

    /// The error propagated as in Theorems 1 and 2 (`err_s`: the error of S).
    fn error(&self, r: f64, pbar: f64, err_s: f64, var: f64, e0: f64, e1: f64) -> f64 {
        fns::abs(r * pbar * (err_s + e1 * self.err_w) + (e0 + var + e1) * self.err_eta)
    }
}

/// m > 1 (or h = 0) without false observations: J'_1 = J_1 = P⁻¹ + HᵀR⁻¹H, w = 1.
fn closed_form(m: &VectorModel<'_>) -> Result<VectorBound> {
    let (prior, sensor) = (m.prior, m.sensor);
    let l = prior.dims();
    let (_, inv) = gaussian_information_matrix(&prior.cov, &sensor.gain, &sensor.noise)
        .map_err(|e| e.within("observation"))?;
    let zone = Zone::clutter_free();
    let lf = l as f64;
    let (r, pbar, p) = (m.existence, sensor.detection, &prior.cov);
    let components = (0..l)
        .map(|i| {
            let (assembled, _) = zone.assemble(
                r,
                pbar,
                inv[(i, i)],
                p[(i, i)],
                m.false_alarm_error / lf,
                m.miss_error / lf,
            );
            ComponentBound {
                assembled,
                inverse_information: inv[(i, i)],
                undetected_mean: prior.mean[i],
                undetected_variance: p[(i, i)],
                error: 0.0,
            }
        })
        .collect();
    let (assembled, _) = zone.assemble(
        r,
        pbar,
        inv.trace(),
        p.trace(),
        m.false_alarm_error,
        m.miss_error,
    );
    let total = check_result(JdeBound {
        assembled,
        mean_detection: pbar,
        undetected_mean: prior.mean[0],
        undetected_variance: p.trace(),
        eta: 0.0,
        region: Vec::new(),
        cardinalities: alloc::vec![Cardinality {
            n: 1,
            probability: 1.0,
            w: 1.0,
            inverse_information: inv.trace(),
            clutter_null: 1.0,
            method: Method::ClosedForm,
            error: 0.0,
            w_error: 0.0,
            clutter_null_error: 0.0,
        }],
        error: 0.0,
        regular: true,
    })?;
    check_vector(VectorBound {
        total,
        components,
        inverse_information: row_major(&inv),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounds::closed::{corollary1, gaussian_no_clutter, no_clutter_ingredients};

    #[test]
    fn one_component_is_the_scalar_bound() {
        for &r in &[0.1, 0.5, 0.9] {
            let v = component_bounds_no_clutter(r, 0.4, &[25.0], &[100.0], 150.0, 200.0).unwrap();
            let s = gaussian_no_clutter(r, 0.4, 100.0, 25.0, 150.0, 200.0).unwrap();
            assert_eq!(v[0], s);
            let base = no_clutter_ingredients(r, 0.4, 25.0, 100.0, 150.0, 200.0);
            let c = component_bound(&base, 1, 25.0, 100.0).unwrap();
            assert!((c.bound - s.bound).abs() < 1e-12);
        }
        assert_eq!(
            component_corollary1(0.3, &[2.0], &[5.0])[0],
            corollary1(0.3, 2.0, 5.0)
        );
        let (j, inv) = gaussian_information_matrix(
            &DMatrix::from_element(1, 1, 4.0),
            &DMatrix::from_element(1, 1, 2.0),
            &DMatrix::from_element(1, 1, 1.0),
        )
        .unwrap();
        let s = crate::bounds::gaussian_fisher_information(4.0, 2.0, 1.0).unwrap();
        assert!((j[(0, 0)] - s.information).abs() < 1e-12);
        assert!((inv[(0, 0)] - s.posterior_variance).abs() < 1e-12);
    }

    #[test]
    fn independent_components_split_the_scalar_error() {
        // Two independent, identically observed components: the thresholds use l σ_{e,i}²,
        // and each HPE line is the scalar one with e0²/2, e1²/2.
        let v =
            component_bounds_no_clutter(0.8, 0.5, &[1.0, 1.0], &[4.0, 4.0], 10.0, 20.0).unwrap();
        let rs = 10.0 / (10.0 + 0.5 * (20.0 - 2.0 * 4.0));
        assert!((v[0].existence_threshold - rs).abs() < 1e-15);
        assert_eq!(v[0], v[1]);
        assert!(component_bounds_no_clutter(0.8, 0.5, &[1.0], &[4.0, 4.0], 1.0, 1.0).is_err());
    }

    fn tight() -> Settings {
        Settings {
            tolerance: 1e-12,
            ..Settings::default()
        }
    }

    #[test]
    fn one_dimension_is_the_scalar_theorem() {
        let psi = Density1::uniform(-10.0, 10.0).unwrap();
        let (x0, var, gain, offset, noise) = (1.0, 4.0, 2.0, 0.5, 1.5);
        let prior = GaussianPrior::new(&[x0], &[var]).unwrap();
        let sensor = LinearGaussianSensor::new(0.8, &[gain], 1, &[offset], &[noise]).unwrap();
        let sprior = Density1::gaussian(x0, var).unwrap();
        let sobs =
            LinearGaussian::new(Detection::constant(0.8).unwrap(), gain, offset, noise).unwrap();
        for &r in &[0.2, 0.6, 0.95] {
            for &q in &[0.0, 0.3] {
                let v = vector_bound(
                    &VectorModel {
                        existence: r,
                        prior: &prior,
                        sensor: &sensor,
                        measurement: VectorMeasurement::I {
                            false_alarm_probability: q,
                            false_alarm_density: &psi,
                        },
                        false_alarm_error: 6.0,
                        miss_error: 9.0,
                    },
                    &tight(),
                )
                .unwrap();
                let b = theorem1(
                    &ModelI {
                        existence: r,
                        prior: &sprior,
                        observation: &sobs,
                        false_alarm_probability: q,
                        false_alarm_density: &psi,
                        false_alarm_error: 6.0,
                        miss_error: 9.0,
                    },
                    &tight(),
                )
                .unwrap();
                let c = &v.components[0].assembled;
                assert!((c.bound - b.assembled.bound).abs() < 1e-10, "{r} {q}");
                assert!((v.total.assembled.bound - b.assembled.bound).abs() < 1e-10);
                assert_eq!(c.phase, b.assembled.phase);
                assert!((c.existence_threshold - b.assembled.existence_threshold).abs() < 1e-10);
            }
        }
        // model II, Monte Carlo for n ≥ 2: with gain 1 the draws are the scalar ones
        let sensor1 = LinearGaussianSensor::new(0.8, &[1.0], 1, &[0.0], &[noise]).unwrap();
        let sobs1 =
            LinearGaussian::new(Detection::constant(0.8).unwrap(), 1.0, 0.0, noise).unwrap();
        let st = Settings {
            samples: 2000,
            seed: 7,
            ..tight()
        };
        for &lambda in &[0.0, 0.8] {
            let v = vector_bound(
                &VectorModel {
                    existence: 0.7,
                    prior: &prior,
                    sensor: &sensor1,
                    measurement: VectorMeasurement::II {
                        clutter_rate: lambda,
                        clutter_density: &psi,
                    },
                    false_alarm_error: 6.0,
                    miss_error: 9.0,
                },
                &st,
            )
            .unwrap();
            let b = theorem2(
                &ModelII {
                    existence: 0.7,
                    prior: &sprior,
                    observation: &sobs1,
                    clutter_rate: lambda,
                    clutter_density: &psi,
                    false_alarm_error: 6.0,
                    miss_error: 9.0,
                },
                &st,
            )
            .unwrap();
            assert!((v.components[0].assembled.bound - b.assembled.bound).abs() < 1e-10);
            assert!((v.components[0].error - b.error).abs() < 1e-10);
            assert!((v.total.eta - b.eta).abs() < 1e-15);
        }
    }

    #[test]
    fn independent_components_are_the_scalar_bounds() {
        // P, H, R diagonal with m = l = 3, no false observations: (72) per component with
        // e²/3, i.e. Corollary 3 of each component's own scalar problem.
        let (var, gain, noise) = ([4.0, 1.0, 9.0], [1.0, 2.0, 0.5], [1.0, 3.0, 2.0]);
        let mut p = [0.0; 9];
        let mut h = [0.0; 9];
        let mut rr = [0.0; 9];
        for i in 0..3 {
            p[4 * i] = var[i];
            h[4 * i] = gain[i];
            rr[4 * i] = noise[i];
        }
        let prior = GaussianPrior::new(&[0.0, 1.0, -2.0], &p).unwrap();
        let sensor = LinearGaussianSensor::new(0.6, &h, 3, &[0.0; 3], &rr).unwrap();
        let psi = Density1::uniform(0.0, 1.0).unwrap();
        for &r in &[0.1, 0.5, 0.9] {
            for model_ii in [false, true] {
                let measurement = if model_ii {
                    VectorMeasurement::II {
                        clutter_rate: 0.0,
                        clutter_density: &psi,
                    }
                } else {
                    VectorMeasurement::I {
                        false_alarm_probability: 0.0,
                        false_alarm_density: &psi,
                    }
                };
                let v = vector_bound(
                    &VectorModel {
                        existence: r,
                        prior: &prior,
                        sensor: &sensor,
                        measurement,
                        false_alarm_error: 30.0,
                        miss_error: 45.0,
                    },
                    &Settings::default(),
                )
                .unwrap();
                let mut sum = 0.0;
                for i in 0..3 {
                    let post =
                        crate::bounds::gaussian_fisher_information(var[i], gain[i], noise[i])
                            .unwrap()
                            .posterior_variance;
                    let c = corollary3(r, 0.6, post, var[i], 10.0, 15.0).unwrap();
                    let got = &v.components[i];
                    assert!((got.assembled.bound - c.bound).abs() < 1e-12, "{r} {i}");
                    assert!(
                        (got.assembled.existence_threshold - c.existence_threshold).abs() < 1e-12
                    );
                    assert!((got.inverse_information - post).abs() < 1e-12);
                    sum += got.assembled.bound;
                }
                assert!(v.total.assembled.bound >= sum - 1e-12);
            }
        }
    }

    #[test]
    fn an_observed_component_with_clutter_is_the_scalar_theorem() {
        // m = 1, h = (1.5, 0, 0), P diagonal: x_1 is the scalar problem (with e²/3), x_2 and
        // x_3 are never observed: [J'⁻¹]_ii = w P_ii per cardinality.
        let prior = GaussianPrior::new(
            &[1.0, 0.0, 2.0],
            &[4.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.5],
        )
        .unwrap();
        let sensor = LinearGaussianSensor::new(0.9, &[1.5, 0.0, 0.0], 3, &[0.0], &[1.0]).unwrap();
        let psi = Density1::uniform(-10.0, 10.0).unwrap();
        let sprior = Density1::gaussian(1.0, 4.0).unwrap();
        let sobs = LinearGaussian::new(Detection::constant(0.9).unwrap(), 1.5, 0.0, 1.0).unwrap();
        for &r in &[0.3, 0.8] {
            let v = vector_bound(
                &VectorModel {
                    existence: r,
                    prior: &prior,
                    sensor: &sensor,
                    measurement: VectorMeasurement::I {
                        false_alarm_probability: 0.5,
                        false_alarm_density: &psi,
                    },
                    false_alarm_error: 6.0,
                    miss_error: 9.0,
                },
                &tight(),
            )
            .unwrap();
            let b = theorem1(
                &ModelI {
                    existence: r,
                    prior: &sprior,
                    observation: &sobs,
                    false_alarm_probability: 0.5,
                    false_alarm_density: &psi,
                    false_alarm_error: 2.0,
                    miss_error: 3.0,
                },
                &tight(),
            )
            .unwrap();
            assert!((v.components[0].assembled.bound - b.assembled.bound).abs() < 1e-10);
            let w = b.cardinalities[0].w;
            assert!((v.components[1].inverse_information - 2.0 * w).abs() < 1e-12);
            assert!((v.components[2].inverse_information - 0.5 * w).abs() < 1e-12);
            // the whole-state matrix: off-diagonal zero here
            assert!(v.inverse_information[1].abs() < 1e-12);
        }
    }

    #[test]
    fn the_reduction_is_the_matrix_information_without_clutter() {
        // m = 1 with a full P: the rank-one reduction must give diag((P⁻¹ + hhᵀ/R)⁻¹).
        let pm = [4.0, 1.5, 0.3, 1.5, 2.0, -0.4, 0.3, -0.4, 1.0];
        let prior = GaussianPrior::new(&[0.0, 1.0, 2.0], &pm).unwrap();
        let sensor = LinearGaussianSensor::new(0.7, &[1.0, 0.5, -2.0], 3, &[0.2], &[0.8]).unwrap();
        let psi = Density1::uniform(-10.0, 10.0).unwrap();
        let v = vector_bound(
            &VectorModel {
                existence: 0.6,
                prior: &prior,
                sensor: &sensor,
                measurement: VectorMeasurement::I {
                    false_alarm_probability: 0.0,
                    false_alarm_density: &psi,
                },
                false_alarm_error: 6.0,
                miss_error: 9.0,
            },
            &tight(),
        )
        .unwrap();
        let (_, inv) = gaussian_information_matrix(
            &DMatrix::from_row_slice(3, 3, &pm),
            &DMatrix::from_row_slice(1, 3, &[1.0, 0.5, -2.0]),
            &DMatrix::from_element(1, 1, 0.8),
        )
        .unwrap();
        for i in 0..3 {
            for j in 0..3 {
                assert!((v.inverse_information[3 * i + j] - inv[(i, j)]).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn a_negligible_gain_is_no_gain() {
        // σ_s² = hᵀPh underflows to a subnormal: without false observations the closed form
        // (h = 0, the prior), with clutter an error naming the gain, both at once.
        let prior = GaussianPrior::new(&[0.0, 0.0], &[6e-208, 0.0, 0.0, 1.5e-223]).unwrap();
        let sensor =
            LinearGaussianSensor::new(0.5, &[-6.4e-59, -6e-107], 2, &[0.0], &[1e150]).unwrap();
        let psi = Density1::gaussian(0.0, 25.0).unwrap();
        let m = |lambda| VectorModel {
            existence: 0.5,
            prior: &prior,
            sensor: &sensor,
            measurement: VectorMeasurement::II {
                clutter_rate: lambda,
                clutter_density: &psi,
            },
            false_alarm_error: 1.0,
            miss_error: 1.0,
        };
        let v = vector_bound(&m(0.0), &Settings::default()).unwrap();
        assert_eq!(v.total.cardinalities[0].method, Method::ClosedForm);
        let e = vector_bound(&m(1e-113), &Settings::default()).unwrap_err();
        assert_eq!(e.field(), "observation.gain");
    }

    #[test]
    fn vector_errors_name_the_field() {
        let psi = Density1::uniform(-10.0, 10.0).unwrap();
        let prior = GaussianPrior::new(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0]).unwrap();
        let two = LinearGaussianSensor::new(
            0.7,
            &[1.0, 0.0, 0.0, 1.0],
            2,
            &[0.0, 0.0],
            &[1.0, 0.0, 0.0, 1.0],
        )
        .unwrap();
        let m = VectorModel {
            existence: 0.5,
            prior: &prior,
            sensor: &two,
            measurement: VectorMeasurement::II {
                clutter_rate: 1.0,
                clutter_density: &psi,
            },
            false_alarm_error: 1.0,
            miss_error: 1.0,
        };
        let e = vector_bound(&m, &Settings::default()).unwrap_err();
        assert_eq!(e.field(), "observation.gain");
        assert_eq!(
            GaussianPrior::new(&[0.0, 0.0], &[1.0, 2.0, 2.0, 1.0])
                .unwrap_err()
                .field(),
            "cov"
        );
        assert_eq!(
            GaussianPrior::new(&[0.0, 0.0], &[1.0, 0.5, 0.0, 1.0])
                .unwrap_err()
                .field(),
            "cov"
        );
        assert_eq!(
            LinearGaussianSensor::new(0.7, &[1.0, 0.0, 1.0], 2, &[0.0], &[1.0])
                .unwrap_err()
                .field(),
            "gain"
        );
        assert_eq!(
            LinearGaussianSensor::new(0.7, &[1.0, 0.0], 2, &[0.0], &[-1.0])
                .unwrap_err()
                .field(),
            "noiseCov"
        );
        let three = LinearGaussianSensor::new(0.7, &[1.0, 0.0, 0.0], 3, &[0.0], &[1.0]).unwrap();
        let e = vector_bound(
            &VectorModel {
                sensor: &three,
                ..m
            },
            &Settings::default(),
        )
        .unwrap_err();
        assert_eq!(e.field(), "observation.gain");
    }
}

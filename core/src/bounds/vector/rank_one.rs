//! The rank-one reduction of paper 002's vector bounds (Section V, (63)–(65)) for a scalar
//! measurement z = hᵀx + b + v (m = 1): the scalar Theorem 1 or 2 of the problem in
//! s = hᵀx, lifted to R^l by Sherman–Morrison (see [`vector_bound`](super::vector_bound)).

use alloc::vec::Vec;
use nalgebra::{DMatrix, DVector};

use super::zone::Zone;
use super::{VectorBound, VectorMeasurement, VectorModel, check_vector, components, row_major};
use crate::bounds::model::{Density1, Detection, LinearGaussian};
use crate::bounds::theorem::{
    Cardinality, JdeBound, ModelI, TheoremOptions, check_result, theorem1,
};
use crate::bounds::theorem2::{ModelII, theorem2};
use crate::error::Result;

/// The projection of the prior on a scalar measurement's gain h.
pub(super) struct Projection {
    h: DVector<f64>,
    /// P h.
    ph: DVector<f64>,
    /// σ_s² = hᵀPh.
    var_s: f64,
}

/// The projection when the sensor measures one scalar and h is not negligible; None
/// otherwise (then the closed form serves, or nothing).
pub(super) fn projection(m: &VectorModel<'_>) -> Option<Projection> {
    if m.sensor.measurement_dims() != 1 {
        return None;
    }
    let p = &m.prior.cov;
    let h = m.sensor.gain.row(0).transpose();
    let ph = p * &h;
    let var_s = h.dot(&ph);
    // h is "zero" when hᵀPh is negligible against tr P |h|² (compared with h scaled to
    // max |h_i| = 1, so that neither side underflows), or when σ_s² itself is not a normal
    // number (a subnormal prior variance makes the scalar quadratures crawl: seconds).
    let big = h.amax();
    let hu = if big > 0.0 { &h / big } else { h.clone() };
    let relative = hu.dot(&(p * &hu)) > 1e-12 * p.trace() * hu.dot(&hu);
    (relative && var_s.is_normal()).then_some(Projection { h, ph, var_s })
}

/// The vector bounds through the scalar theorem of the problem in s.
pub(super) fn bound(
    m: &VectorModel<'_>,
    s: &TheoremOptions,
    proj: &Projection,
) -> Result<VectorBound> {
    let (sb, q, model_ii) = scalar_theorem(m, s, proj)?;
    let lifted = Lifted::new(m, proj, &sb);
    let zone = Zone::from_scalar(m, &sb, q, model_ii, lifted.kept, lifted.big_w);
    let (residual, outer) = (&lifted.residual, &lifted.outer);
    let (err_resid, err_inv) = (lifted.err_resid, lifted.err_inv);
    let big_s = &lifted.big_s;
    let components = components(&zone, m, big_s, |i, var_i| {
        let err_s = residual[(i, i)].max(0.0) * err_resid + outer[(i, i)] * err_inv;
        zone.component_error(err_s, var_i)
    });
    let (s_tr, var_tr) = (big_s.trace(), m.prior.cov.trace());
    let err_tr = residual.trace().max(0.0) * err_resid + outer.trace() * err_inv;
    let (assembled, eta) = zone.whole(s_tr, var_tr);
    let error = zone.whole_error(err_tr, var_tr);
    let total = check_result(JdeBound {
        assembled,
        mean_detection: zone.mean_detection(),
        undetected_mean: m.prior.mean[0],
        undetected_variance: var_tr,
        eta,
        region: sb.region,
        cardinalities: lifted.cards,
        error,
        regular: true,
    })?;
    check_vector(VectorBound {
        total,
        components,
        inverse_information: row_major(big_s),
    })
}

/// Theorem 1 or 2 for s = hᵀx ~ N(hᵀx0, σ_s²) observed as z = s + b + v; with model I's q
/// (0 for model II) and model II's λ (None for model I).
fn scalar_theorem(
    m: &VectorModel<'_>,
    s: &TheoremOptions,
    proj: &Projection,
) -> Result<(JdeBound, f64, Option<f64>)> {
    let sensor = m.sensor;
    let mean_s = proj.h.dot(&DVector::from_column_slice(&m.prior.mean));
    let sprior = Density1::gaussian(mean_s, proj.var_s).map_err(|e| e.within("prior"))?;
    let sobs = LinearGaussian::new(
        Detection::constant(sensor.detection).map_err(|e| e.within("observation"))?,
        1.0,
        sensor.offset[0],
        sensor.noise[(0, 0)],
    )
    .map_err(|e| e.within("observation"))?;
    Ok(match m.measurement {
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
    })
}

/// The scalar series lifted to R^l: [J'_n⁻¹]_ij = w_n (P_ij − a_i a_j σ_s²) + a_i a_j J'^s_n⁻¹
/// summed over n with weights C_n, and the errors that multiply each part.
struct Lifted {
    /// P − a aᵀ σ_s², the covariance of x given s.
    residual: DMatrix<f64>,
    /// a aᵀ, a = Ph/σ_s².
    outer: DMatrix<f64>,
    /// Σ_n C_n J'_n⁻¹.
    big_s: DMatrix<f64>,
    /// Σ_n C_n (error of w_n): multiplies the residual variances.
    err_resid: f64,
    /// Σ_n C_n (error of J'^s_n⁻¹): multiplies a_i².
    err_inv: f64,
    /// Σ_n C_n.
    kept: f64,
    /// Σ_n C_n w_n.
    big_w: f64,
    /// The scalar cardinalities with tr J'_n⁻¹ and its error in place of the scalar ones.
    cards: Vec<Cardinality>,
}

impl Lifted {
    fn new(m: &VectorModel<'_>, proj: &Projection, sb: &JdeBound) -> Lifted {
        let l = m.prior.dims();
        let (p, var_s) = (&m.prior.cov, proj.var_s);
        let a = &proj.ph / var_s;
        let residual = p - &a * a.transpose() * var_s;
        let outer = &a * a.transpose();
        let mut big_s = DMatrix::zeros(l, l);
        let mut err_resid = 0.0;
        let mut err_inv = 0.0;
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
        Lifted {
            residual,
            outer,
            big_s,
            err_resid,
            err_inv,
            kept,
            big_w,
            cards,
        }
    }
}

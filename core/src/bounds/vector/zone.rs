//! The assembly of the vector bounds of paper 002, Section V ((63)/(64) per component and the
//! whole-state bound): the measurement-side ingredients every component shares (η, w, the
//! empty-set probabilities), read back from the scalar Theorem 1 or 2, and the error
//! propagated as there.

use super::VectorModel;
use crate::bounds::closed::{Assembled, Ingredients};
use crate::bounds::theorem::JdeBound;
use crate::bounds::theorem2::EtaBracket;
use crate::math::fns;

/// The measurement-side ingredients of [`Ingredients`] shared by every component, read back
/// from the scalar theorem exactly as it assembled them, with r, P̄o, e0², e1² and l.
pub(super) struct Zone {
    existence: f64,
    mean_detection: f64,
    false_alarm_error: f64,
    miss_error: f64,
    /// l, the state's dimension.
    dims: f64,
    absent_empty: f64,
    /// η: model I's η1 (exact), or model II's bracket [η2, η2 + tail] (the smaller bound is
    /// taken).
    eta: EtaBracket,
    undetected_empty: f64,
    model_ii: bool,
    detected_mass: f64,
    err_w: f64,
}

impl Zone {
    /// `q`: model I's false-alarm probability; `lambda`: model II's clutter rate; `kept`: the
    /// probability the cardinalities of `b` cover; `big_w`: Σ_n C_n w_n over them.
    pub fn from_scalar(
        m: &VectorModel<'_>,
        b: &JdeBound,
        q: f64,
        lambda: Option<f64>,
        kept: f64,
        big_w: f64,
    ) -> Zone {
        let err_w = b
            .cardinalities
            .iter()
            .map(|c| c.probability * c.w_error)
            .sum();
        let zone = Zone::new(m, b.mean_detection, err_w);
        match lambda {
            None => Zone {
                absent_empty: 1.0 - q,
                eta: EtaBracket::exact(b.eta),
                detected_mass: big_w,
                ..zone
            },
            Some(lambda) => {
                let e = fns::exp(-lambda);
                Zone {
                    absent_empty: e,
                    eta: EtaBracket::new(lambda, &b.cardinalities),
                    undetected_empty: e,
                    model_ii: true,
                    detected_mass: (big_w + (1.0 - kept).max(0.0)).min(1.0),
                    ..zone
                }
            }
        }
    }

    /// No false observations: the MAP region is everything (w = 1, η = 0).
    pub fn clutter_free(m: &VectorModel<'_>) -> Zone {
        Zone::new(m, m.sensor.detection, 0.0)
    }

    fn new(m: &VectorModel<'_>, mean_detection: f64, err_w: f64) -> Zone {
        Zone {
            existence: m.existence,
            mean_detection,
            false_alarm_error: m.false_alarm_error,
            miss_error: m.miss_error,
            dims: m.prior.dims() as f64,
            absent_empty: 1.0,
            eta: EtaBracket::exact(0.0),
            undetected_empty: 1.0,
            model_ii: false,
            detected_mass: 1.0,
            err_w,
        }
    }

    /// P̄o.
    pub fn mean_detection(&self) -> f64 {
        self.mean_detection
    }

    fn ingredients(&self, s: f64, var: f64, e0: f64, e1: f64, eta: f64) -> Ingredients {
        Ingredients {
            existence: self.existence,
            mean_detection: self.mean_detection,
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

    /// The smaller of the bounds at the two ends of the η bracket (as
    /// [`theorem2`](crate::bounds::theorem2)), and its η.
    fn assemble(&self, s: f64, var: f64, e0: f64, e1: f64) -> (Assembled, f64) {
        self.eta
            .assemble(|eta| self.ingredients(s, var, e0, e1, eta))
    }

    /// The error propagated as in Theorems 1 and 2 (`err_s`: the error of S).
    fn error(&self, err_s: f64, var: f64, e0: f64, e1: f64) -> f64 {
        let (r, pbar) = (self.existence, self.mean_detection);
        fns::abs(r * pbar * (err_s + e1 * self.err_w) + (e0 + var + e1) * self.eta.error)
    }

    /// (63)/(64) for one component (S = [J'⁻¹]_ii, σ_{e,i}² = `var`): errors e0²/l, e1²/l.
    pub fn component(&self, s: f64, var: f64) -> Assembled {
        let l = self.dims;
        self.assemble(s, var, self.false_alarm_error / l, self.miss_error / l)
            .0
    }

    /// The error of [`Zone::component`] when S has the error `err_s`.
    pub fn component_error(&self, err_s: f64, var: f64) -> f64 {
        let l = self.dims;
        self.error(err_s, var, self.false_alarm_error / l, self.miss_error / l)
    }

    /// The whole-state bound (S = tr J'⁻¹, σ_e² = tr P, errors e0², e1²), and its η.
    pub fn whole(&self, s: f64, var: f64) -> (Assembled, f64) {
        self.assemble(s, var, self.false_alarm_error, self.miss_error)
    }

    /// The error of [`Zone::whole`] when S has the error `err_s`.
    pub fn whole_error(&self, err_s: f64, var: f64) -> f64 {
        self.error(err_s, var, self.false_alarm_error, self.miss_error)
    }
}

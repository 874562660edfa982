//! The application-oriented loss (7) of paper `000_…`: a 2 × 2 cost matrix for the cardinality
//! decision plus a uniform-cost (UC) penalty for reporting a point farther than r0 from the
//! target.

use crate::error::{Error, Result};

/// The five costs of the application-oriented loss, eq. (7) of `000_…` (Narykov, Üney, Ralph,
/// "Optimal Bernoulli point estimation with applications"):
///
/// ```text
///             ⎧ c00                  α = ∅,   φ = ∅      (correct "no target")
/// L(α, φ) =   ⎨ c01                  α = ∅,   φ = {x}    (missed target)
///             ⎪ c10                  α = {a}, φ = ∅      (false alarm)
///             ⎩ c11 + c·1{‖x − a‖ > r0}   α = {a}, φ = {x}  (report, plus a miss of the ball)
/// ```
///
/// All five are finite and nonnegative (the paper takes them in ℝ⁺). Build them with
/// [`Costs::new`], or the presets [`Costs::mpe`] and [`Costs::mmol`] (Table I).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Costs {
    c00: f64,
    c01: f64,
    c10: f64,
    c11: f64,
    c: f64,
}

fn check_cost(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::parameter(what, value, "finite and >= 0"))
    }
}

impl Costs {
    /// The costs `(c00, c01, c10, c11, c)` of eq. (7).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `costs.c00` … `costs.c` for a negative, infinite or
    /// NaN cost.
    pub fn new(c00: f64, c01: f64, c10: f64, c11: f64, c: f64) -> Result<Self> {
        Ok(Self {
            c00: check_cost("costs.c00", c00)?,
            c01: check_cost("costs.c01", c01)?,
            c10: check_cost("costs.c10", c10)?,
            c11: check_cost("costs.c11", c11)?,
            c: check_cost("costs.c", c)?,
        })
    }

    /// The minimum-probability-of-error (MPE) costs of Table I: `(0, 1, 1, 0, 1)`. Every wrong
    /// decision (a miss, a false alarm, or a report outside the ball) costs 1, so the
    /// expected loss is the probability of error (Corollary IV.1).
    pub const fn mpe() -> Self {
        Self {
            c00: 0.0,
            c01: 1.0,
            c10: 1.0,
            c11: 0.0,
            c: 1.0,
        }
    }

    /// The minimum-mean-operational-loss (MMOL) costs of Table I for an asset worth c_A
    /// (`asset`) defended by a countermeasure costing c_M (`countermeasure`):
    ///
    /// ```text
    /// c00 = 0     no target, countermeasure kept
    /// c01 = c_A   target missed: the asset is lost
    /// c10 = c_M   countermeasure spent on nothing
    /// c11 = c_M   countermeasure spent on the target
    /// c   = c_A   spent, but applied farther than r0 from the target: the asset is lost too
    /// ```
    ///
    /// This is Section IV.B's cost-loss model extended with a countermeasure of impact
    /// radius r0; substituting it in Theorem III.3 gives Corollary IV.2, eqs. (19)–(21).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `costs.mmol.asset` or `costs.mmol.countermeasure`
    /// for a negative, infinite or NaN cost.
    pub fn mmol(asset: f64, countermeasure: f64) -> Result<Self> {
        let a = check_cost("costs.mmol.asset", asset)?;
        let m = check_cost("costs.mmol.countermeasure", countermeasure)?;
        Ok(Self {
            c00: 0.0,
            c01: a,
            c10: m,
            c11: m,
            c: a,
        })
    }

    /// c00: nothing reported, nothing there.
    pub const fn c00(&self) -> f64 {
        self.c00
    }

    /// c01: nothing reported, a target there (missed target).
    pub const fn c01(&self) -> f64 {
        self.c01
    }

    /// c10: a point reported, nothing there (false alarm).
    pub const fn c10(&self) -> f64 {
        self.c10
    }

    /// c11: a point reported and a target there.
    pub const fn c11(&self) -> f64 {
        self.c11
    }

    /// c: the extra cost when the reported point is farther than r0 from the target.
    pub const fn c(&self) -> f64 {
        self.c
    }
}

/// The application-oriented loss (7): [`Costs`] and the tolerance radius r0 of the rejection
/// region (9), `B_a = {x : ‖x − a‖ > r0}` (Euclidean distance).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ApplicationLoss {
    costs: Costs,
    radius: f64,
}

impl ApplicationLoss {
    /// The loss with these costs and tolerance radius r0 (`radius`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `radius` unless it is finite and > 0.
    pub fn new(costs: Costs, radius: f64) -> Result<Self> {
        check_radius(radius)?;
        Ok(Self { costs, radius })
    }

    /// The costs.
    pub const fn costs(&self) -> &Costs {
        &self.costs
    }

    /// The tolerance radius r0.
    pub const fn radius(&self) -> f64 {
        self.radius
    }

    /// L(α, φ), eq. (7), for the estimate α (`None` = ∅, `Some(a)` = {a}) and the truth φ
    /// (`None` = ∅, `Some(x)` = {x}). A point x at distance exactly r0 from a is inside the
    /// ball (eq. (9) uses a strict `>`).
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `truth` if `a` and `x` differ in length.
    pub fn loss(&self, estimate: Option<&[f64]>, truth: Option<&[f64]>) -> Result<f64> {
        let c = &self.costs;
        Ok(match (estimate, truth) {
            (None, None) => c.c00,
            (None, Some(_)) => c.c01,
            (Some(_), None) => c.c10,
            (Some(a), Some(x)) => {
                if a.len() != x.len() {
                    return Err(Error::dimension("truth", a.len(), x.len()));
                }
                let d2: f64 = a.iter().zip(x).map(|(ai, xi)| (xi - ai) * (xi - ai)).sum();
                c.c11
                    + if d2 > self.radius * self.radius {
                        c.c
                    } else {
                        0.0
                    }
            }
        })
    }
}

/// Checks r0: finite and > 0.
pub(crate) fn check_radius(radius: f64) -> Result<f64> {
    if radius.is_finite() && radius > 0.0 {
        Ok(radius)
    } else {
        Err(Error::parameter("radius", radius, "finite and > 0"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table1_presets_follow_the_printed_costs() {
        let m = Costs::mpe();
        assert_eq!(
            (m.c00(), m.c01(), m.c10(), m.c11(), m.c()),
            (0.0, 1.0, 1.0, 0.0, 1.0)
        );
        let o = Costs::mmol(0.9, 0.1).unwrap();
        assert_eq!(
            (o.c00(), o.c01(), o.c10(), o.c11(), o.c()),
            (0.0, 0.9, 0.1, 0.1, 0.9)
        );
    }

    #[test]
    fn validation_names_the_field() {
        let e = Costs::new(0.0, -1.0, 1.0, 0.0, 1.0).unwrap_err();
        assert_eq!(e.field(), "costs.c01");
        let e = Costs::new(0.0, 1.0, 1.0, 0.0, f64::NAN).unwrap_err();
        assert_eq!(e.field(), "costs.c");
        let e = Costs::new(0.0, 1.0, f64::INFINITY, 0.0, 1.0).unwrap_err();
        assert_eq!(e.field(), "costs.c10");
        let e = Costs::mmol(0.9, -0.1).unwrap_err();
        assert_eq!(e.field(), "costs.mmol.countermeasure");
        let e = Costs::mmol(f64::NAN, 0.1).unwrap_err();
        assert_eq!(e.field(), "costs.mmol.asset");
        for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = ApplicationLoss::new(Costs::mpe(), r).unwrap_err();
            assert_eq!(e.field(), "radius");
        }
    }

    #[test]
    fn eq7_loss_cases() {
        let l = ApplicationLoss::new(Costs::new(0.5, 2.0, 3.0, 0.25, 7.0).unwrap(), 1.0).unwrap();
        assert_eq!(l.loss(None, None).unwrap(), 0.5);
        assert_eq!(l.loss(None, Some(&[3.0])).unwrap(), 2.0);
        assert_eq!(l.loss(Some(&[3.0]), None).unwrap(), 3.0);
        assert_eq!(l.loss(Some(&[0.0, 0.0]), Some(&[0.0, -1.0])).unwrap(), 0.25);
        assert_eq!(
            l.loss(Some(&[0.0, 0.0]), Some(&[0.0, -1.000_001])).unwrap(),
            7.25
        );
        assert_eq!(
            l.loss(Some(&[0.0]), Some(&[0.0, 1.0])).unwrap_err().field(),
            "truth"
        );
    }
}

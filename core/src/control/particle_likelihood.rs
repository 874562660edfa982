//! The multi-object likelihood (20) of paper `004` for one particle, as the bindings take it:
//! its options with the caps that keep one call fast, and its result. The dynamic programme
//! itself is [`crate::smc::ln_likelihood`].

use alloc::format;
use alloc::string::String;
use alloc::vec::Vec;

use crate::error::{Error, Phrase, Result};

/// The bindings' cap on n, the objects (rows of `likelihoods`).
pub const MAX_OBJECTS: usize = 64;
/// The bindings' cap on m, the measurements (entries of `clutter_density`).
pub const MAX_MEASUREMENTS: usize = 1000;
/// The bindings' cap on min(n, m) (the dynamic programme has 2^min(n, m) states).
pub const MAX_SMALLER: usize = 12;

/// Options of the multi-object likelihood (20) of one particle.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiObjectLikelihoodOptions {
    /// `likelihoods[i][j]` = g(z_j | x_i) ≥ 0, one row of m numbers per object of the
    /// particle (`[]` for n = 0). At most 64 objects, and min(n, m) ≤ 12.
    #[cfg_attr(
        feature = "serde",
        serde(with = "crate::serde_shapes::rows_of_numbers")
    )]
    pub likelihoods: Vec<Vec<f64>>,
    /// The detection probability p_D ∈ [0, 1] of each object.
    pub detection_probability: f64,
    /// The clutter rate λ ≥ 0: the mean number of clutter measurements per scan.
    pub clutter_rate: f64,
    /// The clutter density c(z_j) ≥ 0 at each measurement j (m ≤ 1000), so that
    /// f_c(Z) = e^{−λ} Π_j λ c(z_j).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub clutter_density: Vec<f64>,
}

/// The multi-object likelihood (20) of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004) for one particle.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ParticleLikelihood {
    /// The log-likelihood ln g(Z | X) of (20); −∞ (`-Infinity`) when the likelihood is zero (never NaN).
    pub log_likelihood: f64,
}

impl MultiObjectLikelihoodOptions {
    /// The bindings' caps, before any value is looked at: n ≤ [`MAX_OBJECTS`],
    /// m ≤ [`MAX_MEASUREMENTS`], min(n, m) ≤ [`MAX_SMALLER`].
    ///
    /// # Errors
    /// [`Error::Form`] naming `likelihoods` (n, or min(n, m) > [`MAX_SMALLER`]) or
    /// `clutter_density` (m): `likelihoods: at most 64 objects are supported, got 65`.
    pub fn check_limits(&self) -> Result<()> {
        let n = self.likelihoods.len();
        let m = self.clutter_density.len();
        let cap = |what: &str, said: String| {
            Err(Error::form(what, false, alloc::vec![Phrase::text(said)]))
        };
        if n > MAX_OBJECTS {
            return cap(
                "likelihoods",
                format!(": at most {MAX_OBJECTS} objects are supported, got {n}"),
            );
        }
        if m > MAX_MEASUREMENTS {
            let said = format!(": at most {MAX_MEASUREMENTS} measurements are supported, got {m}");
            return cap("clutter_density", said);
        }
        if n.min(m) > MAX_SMALLER {
            let said = format!(
                ": min(objects, measurements) must be at most {MAX_SMALLER}, got {}",
                n.min(m)
            );
            return cap("likelihoods", said);
        }
        Ok(())
    }

    /// ln g(Z | X) of (20), exactly ([`crate::smc::ln_likelihood`]) after
    /// [`MultiObjectLikelihoodOptions::check_limits`].
    ///
    /// # Errors
    /// The caps', then the values' (`likelihoods[i][j]`, `clutter_density[j]`,
    /// `detection_probability`, `clutter_rate`).
    pub fn evaluate(&self) -> Result<ParticleLikelihood> {
        self.check_limits()?;
        crate::smc::ln_likelihood(
            &self.likelihoods,
            self.detection_probability,
            self.clutter_rate,
            &self.clutter_density,
        )
        .map(|log_likelihood| ParticleLikelihood { log_likelihood })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    fn square(n: usize, m: usize) -> MultiObjectLikelihoodOptions {
        MultiObjectLikelihoodOptions {
            likelihoods: vec![vec![0.5; m]; n],
            detection_probability: 0.9,
            clutter_rate: 1.0,
            clutter_density: vec![0.1; m],
        }
    }

    /// (20) through the options is the core's value; the caps name the field and come before
    /// any check of the values (a bad p_D with too many objects reports the objects).
    #[test]
    fn eq20_options_caps_come_before_the_values() {
        let ok = square(3, 4);
        let want = crate::smc::ln_likelihood(&ok.likelihoods, 0.9, 1.0, &ok.clutter_density);
        assert_eq!(ok.evaluate().unwrap().log_likelihood, want.unwrap());
        assert!(square(12, 12).evaluate().is_ok());
        for (o, e) in [
            (
                square(65, 1),
                "likelihoods: at most 64 objects are supported, got 65",
            ),
            (
                square(1, 1001),
                "clutter_density: at most 1000 measurements are supported, got 1001",
            ),
            (
                square(65, 1001),
                "likelihoods: at most 64 objects are supported, got 65",
            ),
            (
                square(13, 13),
                "likelihoods: min(objects, measurements) must be at most 12, got 13",
            ),
        ] {
            let mut bad = o.clone();
            bad.detection_probability = 2.0;
            for o in [o, bad] {
                assert_eq!(format!("{}", o.evaluate().unwrap_err()), e);
            }
        }
        let mut bad = square(2, 2);
        bad.detection_probability = 2.0;
        assert_eq!(bad.evaluate().unwrap_err().field(), "detection_probability");
        let mut bad = square(2, 2);
        bad.clutter_density[1] = -1.0;
        assert_eq!(bad.evaluate().unwrap_err().field(), "clutter_density[1]");
    }
}

//! The Poisson series of Theorem 2 (23)–(24) of paper 002 over the cardinalities n = k + 1
//! (k clutter points, probability C_k = e^{−λ} λ^k / k!): where it is cut, the sums S and W
//! it feeds into the bound, and the bracket of its η2 tail (see the parent module's docs for
//! why each cut keeps a lower bound).

use crate::bounds::closed::{Assembled, Ingredients, assemble, poisson_pmf};
use crate::bounds::theorem::{Cardinality, TheoremOptions};

/// N, the last clutter count k kept, and Σ_{k ≤ N} C_k: the series stops where its tail is
/// below [`TheoremOptions::series_tolerance`] or at [`TheoremOptions::max_clutter`].
pub(super) fn truncation(lambda: f64, s: &TheoremOptions) -> (usize, f64) {
    let mut last = 0usize;
    let mut kept = poisson_pmf(lambda, 0);
    while 1.0 - kept > s.series_tolerance && last < s.max_clutter {
        last += 1;
        kept += poisson_pmf(lambda, last);
    }
    (last, kept)
}

/// S = Σ_k C_k J'_{k+1}⁻¹ and W = Σ_k C_k w_{k+1} + tail (the tail's w taken as 1), with the
/// errors of each propagated linearly.
pub(super) struct Sums {
    /// The estimation term S = Σ_n C_n J'_{1+n}⁻¹.
    pub s: f64,
    /// The detected mass W = Σ_n C_n w_{n+1} (not yet capped at 1).
    pub w: f64,
    /// The error of S.
    pub err_s: f64,
    /// The error of W.
    pub err_w: f64,
}

impl Sums {
    /// The sums over `cards`, whose probabilities add up to `kept`.
    pub fn new(cards: &[Cardinality], kept: f64) -> Sums {
        let tail = (1.0 - kept).max(0.0);
        let mut sums = Sums {
            s: 0.0,
            w: tail,
            err_s: 0.0,
            err_w: 0.0,
        };
        for c in cards {
            sums.s += c.probability * c.inverse_information;
            sums.w += c.probability * c.w;
            sums.err_s += c.probability * c.error;
            sums.err_w += c.probability * c.w_error;
        }
        sums
    }
}

/// η2 = Σ_{n ≥ 1} C_n null_n (n clutter points alone have probability C_n) over the
/// cardinalities computed, and the bracket [η2, η2 + tail] of what the cut left out; the bound
/// is assembled at both ends and the smaller taken. Model I (and the clutter-free case) has
/// an exact η: a bracket of width 0.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EtaBracket {
    /// η2 over the cardinalities computed.
    pub lo: f64,
    /// η2 with the tail taken as all rejected (≤ 1).
    pub hi: f64,
    /// The error of η2 (from each null_n's).
    pub error: f64,
}

impl EtaBracket {
    /// The bracket of model II with clutter rate λ from the scalar theorem's cardinalities.
    pub fn new(lambda: f64, cards: &[Cardinality]) -> EtaBracket {
        let mut eta = 0.0;
        let mut error = 0.0;
        let mut covered = poisson_pmf(lambda, 0);
        for c in cards {
            let cn = poisson_pmf(lambda, c.n);
            eta += cn * c.clutter_null;
            error += cn * c.clutter_null_error;
            covered += cn;
        }
        let tail = (1.0 - covered).max(0.0);
        EtaBracket {
            lo: eta,
            hi: (eta + tail).min(1.0),
            error,
        }
    }

    /// An η known exactly (model I's η1, or 0 without false observations).
    pub fn exact(eta: f64) -> EtaBracket {
        EtaBracket {
            lo: eta,
            hi: eta,
            error: 0.0,
        }
    }

    /// The smaller of the bounds assembled at the two ends of the bracket, and its η.
    pub fn assemble(&self, ingredients: impl Fn(f64) -> Ingredients) -> (Assembled, f64) {
        let lo = assemble(&ingredients(self.lo));
        let hi = assemble(&ingredients(self.hi));
        if hi.bound < lo.bound {
            (hi, self.hi)
        } else {
            (lo, self.lo)
        }
    }
}

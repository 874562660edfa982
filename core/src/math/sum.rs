//! Compensated summation.

/// Neumaier's improved Kahan–Babuška summation: the error of the sum does not grow with the
/// number of terms (to first order).
///
/// # References
/// A. Neumaier, "Rundungsfehleranalyse einiger Verfahren zur Summation endlicher Summen,"
/// ZAMM 54(1):39–51, 1974.
#[derive(Clone, Copy, Debug, Default)]
pub struct NeumaierSum {
    sum: f64,
    compensation: f64,
}

impl NeumaierSum {
    /// An empty sum.
    pub const fn new() -> Self {
        Self {
            sum: 0.0,
            compensation: 0.0,
        }
    }

    /// Adds `x`.
    #[inline]
    pub fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if super::fns::abs(self.sum) >= super::fns::abs(x) {
            self.compensation += (self.sum - t) + x;
        } else {
            self.compensation += (x - t) + self.sum;
        }
        self.sum = t;
    }

    /// The compensated total; ±∞ when the running sum overflowed (the compensation of an
    /// overflowed sum is ∞ − ∞ = NaN and means nothing).
    #[inline]
    pub fn total(&self) -> f64 {
        if self.sum.is_infinite() {
            self.sum
        } else {
            self.sum + self.compensation
        }
    }
}

impl FromIterator<f64> for NeumaierSum {
    fn from_iter<I: IntoIterator<Item = f64>>(iter: I) -> Self {
        let mut s = Self::new();
        for x in iter {
            s.add(x);
        }
        s
    }
}

/// Σ xᵢ with [`NeumaierSum`].
pub fn sum(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().collect::<NeumaierSum>().total()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz seed 86144: the weights of a mixture split from a weight of f64::MAX summed to
    /// NaN (the overflowed sum's compensation is ∞ − ∞); an overflowed sum is ±∞.
    #[test]
    fn an_overflowing_sum_is_infinite_not_nan() {
        assert_eq!(sum([f64::MAX, f64::MAX]), f64::INFINITY);
        assert_eq!(sum([f64::MAX, f64::MAX, -1.0, 2.0]), f64::INFINITY);
        assert_eq!(sum([-f64::MAX, -f64::MAX]), f64::NEG_INFINITY);
        assert!(sum([f64::INFINITY, f64::NEG_INFINITY]).is_nan());
        assert_eq!(sum([f64::MAX, -f64::MAX, 1.0]), 1.0);
    }

    #[test]
    fn recovers_what_naive_summation_loses() {
        let xs = [1.0, 1e100, 1.0, -1e100];
        assert_eq!(sum(xs), 2.0);
        assert_eq!(xs.iter().sum::<f64>(), 0.0);
    }
}

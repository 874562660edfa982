//! OSPA and GOSPA over whole scenarios: one set pair per time step, per-step values and their
//! means, in one call (in parallel over the steps with the `parallel` feature).

use alloc::string::String;
use alloc::vec::Vec;

use super::{Euclidean, Gospa, GospaDecomposition, Metric, Ospa, OspaDecomposition};
use crate::error::{Error, Result, Shape};
use crate::math::sum::sum;

/// GOSPA over a scenario: the distance at every time step and its mean, with the α = 2
/// decomposition (Prop. 3 of García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation
/// and how GOSPA solves it", paper 003: localisation, missed and false targets) per step and
/// averaged, when it exists.
///
/// (In Rust, built by [`Gospa::series`] / [`Gospa::series_with`], or collected from per-step
/// decompositions: `steps.map(|(x, y)| g.decompose(x, y)).collect::<Result<GospaSeries>>()`.)
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GospaSeries {
    /// The GOSPA distance at each step.
    pub distance: Vec<f64>,
    /// The mean of `distance` over the steps (0 for no steps).
    pub mean_distance: f64,
    /// The localisation cost Σ d^p over the assigned pairs at each step: a sum of p-th powers,
    /// not rooted (as in one step's decomposition ([`GospaDecomposition::localisation`]),
    /// unlike OSPA's rooted part); α = 2 only, like the decomposition itself.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub localisation: Option<Vec<f64>>,
    /// Missed targets (unassigned truths) at each step (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub missed: Option<Vec<usize>>,
    /// False targets (unassigned estimates) at each step (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub false_targets: Option<Vec<usize>>,
    /// The mean of `localisation` (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub mean_localisation: Option<f64>,
    /// The mean of `missed` (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub mean_missed: Option<f64>,
    /// The mean of `false_targets` (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub mean_false_targets: Option<f64>,
}

/// OSPA over a scenario: distance, localisation and cardinality parts at every time step and
/// their means.
///
/// The means are of the rooted per-step values, so `mean_distance^p` is in general not
/// `mean_localisation^p + mean_cardinality^p` (that identity holds step by step).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OspaSeries {
    /// The OSPA distance at each step, eq. (24) of Ristic & Vo, "Sensor control for multi-object
    /// state-space estimation using random finite sets" (paper 004).
    pub distance: Vec<f64>,
    /// The localisation part at each step, eq. (26): rooted and normalised (unlike GOSPA's
    /// `localisation`, a sum of p-th powers).
    pub localisation: Vec<f64>,
    /// The cardinality part at each step, eq. (25).
    pub cardinality: Vec<f64>,
    /// The mean of `distance` (0 for no steps).
    pub mean_distance: f64,
    /// The mean of `localisation` over the steps.
    pub mean_localisation: f64,
    /// The mean of `cardinality` over the steps.
    pub mean_cardinality: f64,
}

/// The mean of `len` nonnegative values (0 for none). When their sum overflows (values near
/// the largest double, from a cut-off c near it) the mean is taken of the values scaled by
/// 2^-64, exactly the same rounding in other units, so that it is finite whenever every value
/// is: +∞ only when a value is. Ordinary values never take that path (the same bits as a plain
/// compensated mean).
fn mean(values: impl IntoIterator<Item = f64> + Clone, len: usize) -> f64 {
    if len == 0 {
        return 0.0;
    }
    let plain = sum(values.clone()) / len as f64;
    if plain.is_finite() {
        return plain;
    }
    const DOWN: f64 = 1.0 / 18_446_744_073_709_551_616.0; // 2^-64
    const UP: f64 = 18_446_744_073_709_551_616.0; // 2^64
    if values.clone().into_iter().any(f64::is_infinite) {
        return f64::INFINITY;
    }
    sum(values.into_iter().map(|v| v * DOWN)) / len as f64 * UP
}

impl GospaSeries {
    fn from_parts(distance: Vec<f64>, parts: Option<(Vec<f64>, Vec<usize>, Vec<usize>)>) -> Self {
        let t = distance.len();
        let mut s = Self {
            mean_distance: mean(distance.iter().copied(), t),
            distance,
            ..Self::default()
        };
        if let Some((localisation, missed, false_targets)) = parts {
            s.mean_localisation = Some(mean(localisation.iter().copied(), t));
            s.mean_missed = Some(mean(missed.iter().map(|&k| k as f64), t));
            s.mean_false_targets = Some(mean(false_targets.iter().map(|&k| k as f64), t));
            s.localisation = Some(localisation);
            s.missed = Some(missed);
            s.false_targets = Some(false_targets);
        }
        s
    }
}

impl FromIterator<GospaDecomposition> for GospaSeries {
    /// The series of per-step α = 2 decompositions, in order.
    fn from_iter<I: IntoIterator<Item = GospaDecomposition>>(iter: I) -> Self {
        let (mut distance, mut localisation, mut missed, mut false_targets) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for d in iter {
            distance.push(d.distance);
            localisation.push(d.localisation);
            missed.push(d.missed);
            false_targets.push(d.false_targets);
        }
        Self::from_parts(distance, Some((localisation, missed, false_targets)))
    }
}

impl OspaSeries {
    fn from_steps(steps: impl IntoIterator<Item = (f64, f64, f64)>) -> Self {
        let (mut distance, mut localisation, mut cardinality) =
            (Vec::new(), Vec::new(), Vec::new());
        for (d, l, c) in steps {
            distance.push(d);
            localisation.push(l);
            cardinality.push(c);
        }
        let t = distance.len();
        Self {
            mean_distance: mean(distance.iter().copied(), t),
            mean_localisation: mean(localisation.iter().copied(), t),
            mean_cardinality: mean(cardinality.iter().copied(), t),
            distance,
            localisation,
            cardinality,
        }
    }
}

impl FromIterator<OspaDecomposition> for OspaSeries {
    /// The series of per-step decompositions, in order.
    fn from_iter<I: IntoIterator<Item = OspaDecomposition>>(iter: I) -> Self {
        Self::from_steps(
            iter.into_iter()
                .map(|d| (d.distance, d.localisation, d.cardinality)),
        )
    }
}

/// Names a per-step field as the series names it: `truth[2][0]` at step 7 becomes
/// `truths[7][2][0]`, `estimate[1]` becomes `estimates[7][1]` (also inside
/// `distance(truth[i], estimate[j])`).
fn at_step(e: Error, t: usize) -> Error {
    e.map_field(|what| {
        let mut out = String::with_capacity(what.len() + 16);
        let mut rest = what;
        while !rest.is_empty() {
            // (no string slicing: its panic brings the string `Debug` code into every wasm
            // module)
            let (word, plural, after) = if let Some(after) = rest.strip_prefix("truth") {
                ("truth", "truths", after)
            } else if let Some(after) = rest.strip_prefix("estimate") {
                ("estimate", "estimates", after)
            } else {
                let mut chars = rest.chars();
                out.extend(chars.next());
                rest = chars.as_str();
                continue;
            };
            rest = after;
            if rest.starts_with('s') {
                out.push_str(word);
            } else {
                out.push_str(plural);
                out.push_str(&alloc::format!("[{t}]"));
            }
        }
        out
    })
}

/// Runs `step` for every `t < steps` (in parallel with the `parallel` feature) and returns
/// the results in order, or the error of the first failing step (the same either way).
fn each_step<R: Send>(steps: usize, step: impl Fn(usize) -> Result<R> + Sync) -> Result<Vec<R>> {
    #[cfg(feature = "parallel")]
    let results: Vec<Result<R>> = {
        use rayon::prelude::*;
        (0..steps).into_par_iter().map(&step).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let results: Vec<Result<R>> = (0..steps).map(&step).collect();
    results
        .into_iter()
        .enumerate()
        .map(|(t, r)| r.map_err(|e| at_step(e, t)))
        .collect()
}

/// Runs `step(truths[t], estimates[t])` for every step with [`each_step`], after checking
/// that the two have as many steps.
fn each_pair<A, B, T, R>(
    truths: &[A],
    estimates: &[B],
    step: impl Fn(&[T], &[T]) -> Result<R> + Sync,
) -> Result<Vec<R>>
where
    A: AsRef<[T]> + Sync,
    B: AsRef<[T]> + Sync,
    T: Sync,
    R: Send,
{
    if truths.len() != estimates.len() {
        return Err(Error::shapes(
            "estimates",
            Shape::Length(estimates.len()),
            "truths",
            Shape::Length(truths.len()),
        ));
    }
    super::check_series_steps(truths.len())?;
    let points = truths
        .iter()
        .map(|x| x.as_ref().len())
        .chain(estimates.iter().map(|y| y.as_ref().len()))
        .fold(0usize, usize::saturating_add);
    if points > super::MAX_SERIES_POINTS {
        return Err(Error::OverBudget {
            what: "truths".into(),
            measure: "points over all steps of truths and estimates",
            work: points,
            limit: "MAX_SERIES_POINTS = 2^18 per series",
            at_most: super::MAX_SERIES_POINTS,
        });
    }
    each_step(truths.len(), |t| {
        step(truths[t].as_ref(), estimates[t].as_ref())
    })
}

impl Gospa {
    /// GOSPA at every step of a scenario under the Euclidean distance: `truths[t]` against
    /// `estimates[t]`, with the α = 2 decomposition when α = 2.
    ///
    /// Each step is exactly [`Gospa::decompose`] (α = 2) or [`Gospa::distance`] (other α),
    /// so the values are identical to per-step calls; the steps run in parallel with the
    /// `parallel` feature, with identical results without it.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] naming `estimates` and `truths` if the two have different
    /// numbers of steps (`estimates has length 1 but truths has length 2`); [`Error::Count`] naming `truths` beyond [`super::MAX_SERIES_STEPS`] steps;
    /// [`Error::OverBudget`] naming `truths` beyond [`super::MAX_SERIES_POINTS`] points over
    /// all steps of both; a step's error with its fields named per step (`truths[t][i]`,
    /// `estimates[t][j]`, `distance(truths[t][i], estimates[t][j])`), the first failing step
    /// in time order.
    ///
    /// # Examples
    /// ```
    /// use fisst::metrics::Gospa;
    /// let g = Gospa::new(2.0, 1.0, 2.0)?;
    /// let truths = vec![vec![[0.0, 0.0]], vec![[0.0, 0.0], [5.0, 5.0]]];
    /// let estimates = vec![vec![[0.5, 0.0]], vec![]];
    /// let s = g.series(&truths, &estimates)?;
    /// // step 0: one pair at 0.5; step 1: two missed targets at c/2 = 1 each
    /// assert_eq!(s.distance, vec![0.5, 2.0]);
    /// assert_eq!(s.mean_distance, 1.25);
    /// assert_eq!((s.missed, s.mean_missed), (Some(vec![0, 2]), Some(1.0)));
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn series<A, B, P>(&self, truths: &[A], estimates: &[B]) -> Result<GospaSeries>
    where
        A: AsRef<[P]> + Sync,
        B: AsRef<[P]> + Sync,
        P: AsRef<[f64]> + Sync,
    {
        self.series_with(truths, estimates, &Euclidean)
    }

    /// [`Gospa::series`] under a user-supplied single-object distance.
    ///
    /// # Errors
    /// As [`Gospa::series`], with the metric's errors.
    pub fn series_with<A, B, T, M>(
        &self,
        truths: &[A],
        estimates: &[B],
        metric: &M,
    ) -> Result<GospaSeries>
    where
        A: AsRef<[T]> + Sync,
        B: AsRef<[T]> + Sync,
        T: Sync,
        M: Metric<T> + Sync + ?Sized,
    {
        if self.alpha() == 2.0 {
            let steps = each_pair(truths, estimates, |x, y| {
                let d = self.decompose_with(x, y, metric)?;
                Ok((d.distance, d.localisation, d.missed, d.false_targets))
            })?;
            let mut parts = (Vec::new(), Vec::new(), Vec::new());
            let mut distance = Vec::with_capacity(steps.len());
            for (d, l, mi, f) in steps {
                distance.push(d);
                parts.0.push(l);
                parts.1.push(mi);
                parts.2.push(f);
            }
            Ok(GospaSeries::from_parts(distance, Some(parts)))
        } else {
            let distance = each_pair(truths, estimates, |x, y| self.distance_with(x, y, metric))?;
            Ok(GospaSeries::from_parts(distance, None))
        }
    }
}

impl Ospa {
    /// OSPA and its parts at every step of a scenario under the Euclidean distance:
    /// `truths[t]` against `estimates[t]`.
    ///
    /// Each step is exactly [`Ospa::decompose`]; parallel over the steps with the `parallel`
    /// feature, with identical results without it.
    ///
    /// # Errors
    /// As [`Gospa::series`].
    ///
    /// # Examples
    /// ```
    /// use fisst::metrics::Ospa;
    /// let o = Ospa::new(10.0, 1.0)?;
    /// let s = o.series(&[vec![[0.0], [5.0]], vec![]], &[vec![[1.0]], vec![]])?;
    /// assert_eq!(s.distance, vec![5.5, 0.0]);
    /// assert_eq!((s.localisation[0], s.cardinality[0]), (0.5, 5.0));
    /// assert_eq!(s.mean_distance, 2.75);
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn series<A, B, P>(&self, truths: &[A], estimates: &[B]) -> Result<OspaSeries>
    where
        A: AsRef<[P]> + Sync,
        B: AsRef<[P]> + Sync,
        P: AsRef<[f64]> + Sync,
    {
        self.series_with(truths, estimates, &Euclidean)
    }

    /// [`Ospa::series`] under a user-supplied single-object distance.
    ///
    /// # Errors
    /// As [`Gospa::series_with`].
    pub fn series_with<A, B, T, M: Metric<T> + Sync + ?Sized>(
        &self,
        truths: &[A],
        estimates: &[B],
        metric: &M,
    ) -> Result<OspaSeries>
    where
        A: AsRef<[T]> + Sync,
        B: AsRef<[T]> + Sync,
        T: Sync,
    {
        let steps = each_pair(truths, estimates, |x, y| {
            let d = self.decompose_with(x, y, metric)?;
            Ok((d.distance, d.localisation, d.cardinality))
        })?;
        Ok(OspaSeries::from_steps(steps))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::FnMetric;
    use alloc::vec;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    type Steps = Vec<Vec<Vec<f64>>>;

    /// A seeded scenario: `steps` steps of 0–12 truths in 2D and their noisy, partly missed,
    /// cluttered estimates.
    fn scenario(seed: u64, steps: usize) -> (Steps, Steps) {
        let mut rng = SmallRng::seed_from_u64(seed);
        let (mut truths, mut estimates) = (vec![], vec![]);
        for _ in 0..steps {
            let n = rng.random_range(0..=12);
            let x: Vec<Vec<f64>> = (0..n)
                .map(|_| vec![rng.random_range(0.0..20.0), rng.random_range(0.0..20.0)])
                .collect();
            let mut y: Vec<Vec<f64>> = vec![];
            for t in &x {
                if rng.random_range(0.0..1.0) < 0.8 {
                    y.push(t.iter().map(|v| v + rng.random_range(-1.0..1.0)).collect());
                }
            }
            for _ in 0..rng.random_range(0..3) {
                y.push(vec![
                    rng.random_range(0.0..20.0),
                    rng.random_range(0.0..20.0),
                ]);
            }
            truths.push(x);
            estimates.push(y);
        }
        (truths, estimates)
    }

    #[test]
    fn gospa_series_is_the_per_step_values_and_their_means() {
        let (truths, estimates) = scenario(1, 120);
        for (c, p) in [(2.0, 1.0), (3.0, 2.0), (1.5, 3.0)] {
            let g = Gospa::new(c, p, 2.0).unwrap();
            let s = g.series(&truths, &estimates).unwrap();
            let per_step: Vec<GospaDecomposition> = truths
                .iter()
                .zip(&estimates)
                .map(|(x, y)| g.decompose(x, y).unwrap())
                .collect();
            let (localisation, missed, false_targets) = (
                s.localisation.clone().unwrap(),
                s.missed.clone().unwrap(),
                s.false_targets.clone().unwrap(),
            );
            for (t, d) in per_step.iter().enumerate() {
                assert_eq!(s.distance[t], d.distance);
                assert_eq!(localisation[t], d.localisation);
                assert_eq!((missed[t], false_targets[t]), (d.missed, d.false_targets));
            }
            let naive = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            assert!((s.mean_distance - naive(&s.distance)).abs() <= 1e-13 * s.mean_distance);
            let missed: Vec<f64> = missed.iter().map(|&k| k as f64).collect();
            assert_eq!(s.mean_missed, Some(naive(&missed)));
            // Collecting the per-step decompositions gives the same series.
            assert_eq!(per_step.into_iter().collect::<GospaSeries>(), s);
            for alpha in [1.0, 0.5] {
                let g = Gospa::new(c, p, alpha).unwrap();
                let s = g.series(&truths, &estimates).unwrap();
                assert!(s.localisation.is_none() && s.mean_false_targets.is_none());
                for t in 0..truths.len() {
                    assert_eq!(
                        s.distance[t],
                        g.distance(&truths[t], &estimates[t]).unwrap()
                    );
                }
            }
        }
    }

    #[test]
    fn ospa_series_is_the_per_step_values_and_their_means() {
        let (truths, estimates) = scenario(2, 80);
        let o = Ospa::new(4.0, 2.0).unwrap();
        let s = o.series(&truths, &estimates).unwrap();
        let per_step: Vec<OspaDecomposition> = truths
            .iter()
            .zip(&estimates)
            .map(|(x, y)| o.decompose(x, y).unwrap())
            .collect();
        for (t, d) in per_step.iter().enumerate() {
            assert_eq!(
                (s.distance[t], s.localisation[t], s.cardinality[t]),
                (d.distance, d.localisation, d.cardinality)
            );
        }
        let mean_loc = s.localisation.iter().sum::<f64>() / 80.0;
        assert!((s.mean_localisation - mean_loc).abs() <= 1e-13 * mean_loc);
        assert_eq!(per_step.into_iter().collect::<OspaSeries>(), s);
        // Slices of slices work as well as vectors of vectors.
        let xs: Vec<&[Vec<f64>]> = truths.iter().map(|v| v.as_slice()).collect();
        assert_eq!(o.series(&xs, &estimates).unwrap(), s);
    }

    #[test]
    fn empty_series_and_empty_steps() {
        let g = Gospa::new(1.0, 2.0, 2.0).unwrap();
        let none: [Vec<[f64; 2]>; 0] = [];
        let s = g.series(&none, &none).unwrap();
        assert_eq!((s.distance.len(), s.mean_distance), (0, 0.0));
        assert_eq!(s.mean_missed, Some(0.0));
        let empty: Vec<Vec<[f64; 2]>> = vec![vec![], vec![]];
        let s = Ospa::new(1.0, 2.0).unwrap().series(&empty, &empty).unwrap();
        assert_eq!(s.distance, vec![0.0, 0.0]);
    }

    #[test]
    fn errors_name_the_step_and_the_first_failing_step_wins() {
        let g = Gospa::new(1.0, 2.0, 2.0).unwrap();
        let (mut truths, mut estimates) = scenario(3, 10);
        let e = g.series(&truths, &estimates[..9]).unwrap_err();
        assert_eq!(e.field(), "estimates");
        assert!(
            alloc::format!("{e}").contains("but truths has length"),
            "{e}"
        );
        truths[7] = vec![vec![0.0, 0.0], vec![f64::NAN, 0.0]];
        estimates[4] = vec![vec![0.0, 0.0], vec![1.0]];
        let e = g.series(&truths, &estimates).unwrap_err();
        assert_eq!(e.field(), "estimates[4][1]");
        estimates[4] = vec![];
        let e = g.series(&truths, &estimates).unwrap_err();
        assert_eq!(e.field(), "truths[7][1][0]");
        let e = Ospa::new(1.0, 2.0)
            .unwrap()
            .series(&truths, &estimates)
            .unwrap_err();
        assert_eq!(e.field(), "truths[7][1][0]");
        let bad = FnMetric(|a: &f64, b: &f64| if a == b { f64::NAN } else { 1.0 });
        let e = g
            .series_with(&[vec![0.0], vec![1.0, 2.0]], &[vec![5.0], vec![2.0]], &bad)
            .unwrap_err();
        assert_eq!(e.field(), "distance(truths[1][1], estimates[1][0])");
    }

    #[test]
    fn def2_and_eq24_means_of_cutoffs_near_the_largest_double_are_finite() {
        // Found by the boundary fuzzer: the sum over steps of c-sized distances overflowed and
        // the means were NaN.
        let truths = vec![vec![vec![0.0]], vec![vec![0.0]]];
        let estimates: Vec<Vec<Vec<f64>>> = vec![vec![], vec![]];
        let g = Gospa::new(f64::MAX, 2.0, 2.0).unwrap();
        let s = g.series(&truths, &estimates).unwrap();
        assert!(s.distance[0].is_finite() && s.distance[0] > 1e308);
        assert_eq!(s.mean_distance, s.distance[0]);
        let o = Ospa::new(1e308, 1.0)
            .unwrap()
            .series(&truths, &estimates)
            .unwrap();
        assert_eq!(o.distance, vec![1e308, 1e308]);
        assert_eq!((o.mean_distance, o.mean_cardinality), (1e308, 1e308));
        assert_eq!(o.mean_localisation, 0.0);
        // Ordinary means are the plain compensated means, bit for bit.
        assert_eq!(mean([0.1, 0.2, 0.4], 3), sum([0.1, 0.2, 0.4]) / 3.0);
        assert_eq!(mean([f64::MAX, f64::INFINITY], 2), f64::INFINITY);
    }

    #[test]
    fn def2_series_with_a_subnormal_alpha_is_finite() {
        // Found by the boundary fuzzer: (c^p / α)^(1/p) overflowed to ∞ and the mean was NaN.
        let g = Gospa::new(1.0, 2.0, 5e-324).unwrap();
        let s = g.series(&[vec![vec![0.0]]], &[vec![]]).unwrap();
        let expected = 1.0 / 5e-324f64.sqrt();
        assert!(
            (s.distance[0] - expected).abs() <= 1e-15 * expected,
            "{:?}",
            s.distance
        );
        assert_eq!(s.mean_distance, s.distance[0]);
        // α Σ d^p next to c^p: one matched pair at 0.5 and one missed point.
        let d = g.distance(&[[0.0], [9.0]], &[[0.5]]).unwrap();
        assert!((d - expected).abs() <= 1e-15 * expected);
        let one = Gospa::new(1.0, 1.0, 1e-320).unwrap();
        assert_eq!(
            one.distance(&[[0.0]], &[[0.5], [7.0]]).unwrap(),
            f64::INFINITY
        );
    }

    #[test]
    fn step_names() {
        let cases = [
            ("truth", "truths[3]"),
            ("truth[2][0]", "truths[3][2][0]"),
            ("estimate[1]", "estimates[3][1]"),
            (
                "distance(truth[0], estimate[4])",
                "distance(truths[3][0], estimates[3][4])",
            ),
            (
                "truth × estimate pairs closer than c",
                "truths[3] × estimates[3] pairs closer than c",
            ),
            ("c", "c"),
        ];
        for (single, series) in cases {
            let e = at_step(Error::parameter(single, 0.0, "x"), 3);
            assert_eq!(e.field(), series);
        }
    }
}

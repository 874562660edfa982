//! Negative information: the non-detection update of a Gaussian mixture inside a field of
//! view, and the reproducible scenario of Fig. 5 of `001_…`.

use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use super::{SplitLibrary, SplitOptions, SplitOutcome, split_for_region};
use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::sum::{NeumaierSum, sum};
use crate::mixture::{ReductionOptions, reduce};
use crate::regions::Region;

/// The posterior of a non-detection (no measurement at all) with detection probability
/// p_D inside the field of view S, by the zeroth-order expansion about the component means:
/// eqs. (57)–(58) of `001_0f0df91eee9b30d5.txt` with an empty measurement set Υ_k and
/// p_D(x; S) = p_D 1_S(x) (51),
///
/// ```text
/// Δ = Σ_ℓ w^{(ℓ)} p_D 1_S(m^{(ℓ)})                                  (58)
/// w^{(ℓ)} ← w^{(ℓ)} (1 − p_D 1_S(m^{(ℓ)})) / (1 − Δ)                 (57)
/// ```
///
/// i.e. the mean-based partition (12) re-weighted and normalised (for p_D = 1 exactly the
/// normalised p_C(S), the density (9)). Components whose weight becomes 0 are dropped. Run
/// [`split_for_region`] first so the partition is accurate. The input weights are taken to
/// sum to 1 (a single-object density); returns the posterior and 1 − Δ, the predicted
/// probability of the non-detection.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `detectionProb`; [`Error::DimensionMismatch`] naming
/// `mixture` if its dimension is below the region's; [`Error::InvalidParameter`] naming
/// `mixture` when the non-detection has probability 0 (every component inside with
/// p_D = 1), so no posterior exists.
pub fn non_detection_update(
    mixture: &GaussianMixture,
    fov: &Region,
    detection_prob: f64,
) -> Result<(GaussianMixture, f64)> {
    if !(0.0..=1.0).contains(&detection_prob) {
        return Err(Error::probability("detectionProb", detection_prob));
    }
    if let Some(n) = mixture.dim()
        && n < fov.dim()
    {
        return Err(Error::dimension("mixture", fov.dim(), n));
    }
    let factors: Vec<f64> = mixture
        .components()
        .iter()
        .map(|(_, g)| {
            if fov.contains(g.mean().as_slice()) {
                1.0 - detection_prob
            } else {
                1.0
            }
        })
        .collect();
    let kept = sum(mixture
        .components()
        .iter()
        .zip(&factors)
        .map(|((w, _), f)| w * f));
    if kept.is_nan() || kept <= 0.0 {
        return Err(Error::parameter(
            "mixture",
            kept,
            "a density with mass outside the field of view (the non-detection has probability 0)",
        ));
    }
    let out = mixture
        .components()
        .iter()
        .zip(&factors)
        .filter(|(_, f)| **f > 0.0)
        .map(|((w, g), f)| (w * f / kept, g.clone()))
        .filter(|(w, _)| *w > 0.0)
        .collect();
    Ok((GaussianMixture::new(out, "mixture")?, kept))
}

/// One time step of [`NegativeInformationScenario::run`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NegativeInformationStep {
    /// The time index k (1, 2, 3 for Fig. 5).
    pub step: usize,
    /// The predicted density p_{k|k−1}: the prediction of the previous posterior.
    pub predicted: GaussianMixture,
    /// The split: Algorithm 1 applied to the prediction.
    pub split: SplitOutcome,
    /// The posterior density p_{k|k}: the non-detection posterior (after the optional reduction).
    pub posterior: GaussianMixture,
    /// The predicted probability 1 − Δ_k of not detecting the object (mean-based).
    pub non_detection_prob: f64,
    /// ⟨1_S, p_{k|k−1}⟩, the exact probability that the object is in the FoV before the
    /// update ([`Region::gaussian_mass`]).
    pub predicted_inside: f64,
    /// ⟨1_S, p_{k|k}⟩, the exact mass the posterior GM still puts inside the FoV (0 for the
    /// true posterior; what the GM approximation leaves).
    pub posterior_inside: f64,
}

/// The negative-information example of Section IV-G and Fig. 5 of `001_…`: an object with
/// an unknown constant velocity crosses the region of interest from left to right past a
/// square field of view, and the sensor reports no detection at each of three time steps
/// (p_D = 1 inside the FoV). Each step predicts the GM with the constant-velocity model,
/// refines it by Algorithm 1 (w_min = 0.01, R = 3, λ = 0.001), and applies the non-detection
/// update [`non_detection_update`] (the mean-based partition (12) and the density (9)).
///
/// The paper gives no numbers for Fig. 5; this scenario fixes them (dimensionless units):
///
/// - state x = (x, y, ẋ, ẏ), n_s = 2 position states;
/// - FoV S = [−1.5, 1.5] × [−1.5, 1.5];
/// - motion: F and Q of eqs. (70)–(71) with T = 1 and ϖ = 0.01;
/// - p_{0|0}: two components with covariance diag(0.5, 0.5, 0.01, 0.0025),
///
///   ```text
///   w      x      y     ẋ     ẏ
///   0.7   −3.0   1.0   1.5   0
///   0.3   −3.3   1.6   1.4   0
///   ```
///
///   so the predicted position mean crosses the upper half of the FoV from left to right
///   (x̄ ≈ −1.6, −0.5, 1.1 at k = 1, 2, 3) while part of the density passes above it.
///
/// # What it shows (and how well)
/// Each update moves the density out of the FoV: the posterior mean is pushed up and away
/// from the FoV relative to the prediction, and the density hugs the FoV's edges. Against
/// the exact Bayes posterior (a 100 000-particle rejection sampler in the tests), the
/// non-detection probabilities 1 − Δ_k agree within 0.02 and the posterior position means
/// within 0.1 at every step. The mean-based partition is only as fine as w_min allows:
/// components lighter than 0.01 are not split further, so the posterior GM keeps 5–16 % of
/// its mass in a thin layer just inside the FoV's edges (the FoV's interior, 0.5 away from
/// the edges, keeps at most 1.2 %, against 9–24 % before the updates); lowering w_min thins
/// that layer at the price of more components (w_min = 0.001: 5–7× as many).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NegativeInformationScenario {
    /// The initial density p_{0|0}, a Gaussian mixture over (x, y, ẋ, ẏ).
    pub initial: GaussianMixture,
    /// The state transition matrix F of eq. (70).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::matrix"))]
    pub transition: DMatrix<f64>,
    /// The process noise covariance Q of eq. (71).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::matrix"))]
    pub process_noise: DMatrix<f64>,
    /// The field of view S.
    pub fov: Region,
    /// The detection probability p_D inside S.
    pub detection_prob: f64,
    /// The number of non-detection updates.
    pub steps: usize,
    /// The split library (R = 3, λ = 0.001, equal spacing).
    pub library: SplitLibrary,
    /// Algorithm 1's options (w_min = 0.01; defaults otherwise).
    pub options: SplitOptions,
    /// Applied to each posterior (the identity by default, as in Fig. 5).
    pub reduction: ReductionOptions,
}

/// F and Q of eqs. (70)–(71) of `001_…` (2D constant velocity, state (x, y, ẋ, ẏ)), period
/// `t`, process-noise intensity `q` (ϖ).
pub fn constant_velocity(t: f64, q: f64) -> (DMatrix<f64>, DMatrix<f64>) {
    #[rustfmt::skip]
    let f = DMatrix::from_row_slice(4, 4, &[
        1.0, 0.0, t, 0.0,
        0.0, 1.0, 0.0, t,
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
    ]);
    let (a, b, c) = (q * t * t * t / 3.0, q * t * t / 2.0, q * t);
    #[rustfmt::skip]
    let qm = DMatrix::from_row_slice(4, 4, &[
        a, 0.0, b, 0.0,
        0.0, a, 0.0, b,
        b, 0.0, c, 0.0,
        0.0, b, 0.0, c,
    ]);
    (f, qm)
}

/// The Kalman prediction of every component: m ← F m, P ← F P Fᵀ + Q (eqs. (48)–(49)).
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `transition` or `processNoise` for matrices that are
/// not n × n; [`Error::NotDefinite`] naming `mixture[i].cov` if a predicted covariance is not
/// positive definite.
pub fn predict(
    mixture: &GaussianMixture,
    transition: &DMatrix<f64>,
    process_noise: &DMatrix<f64>,
) -> Result<GaussianMixture> {
    let Some(n) = mixture.dim() else {
        return Ok(mixture.clone());
    };
    if transition.nrows() != n || transition.ncols() != n {
        return Err(Error::dimension("transition", n, transition.nrows()));
    }
    if process_noise.nrows() != n || process_noise.ncols() != n {
        return Err(Error::dimension("processNoise", n, process_noise.nrows()));
    }
    let mut out = Vec::with_capacity(mixture.len());
    for (i, (w, g)) in mixture.components().iter().enumerate() {
        let m = transition * g.mean();
        let p = transition * g.cov() * transition.transpose() + process_noise;
        let p = (&p + p.transpose()) * 0.5;
        out.push((*w, Gaussian::new(m, p, &alloc::format!("mixture[{i}]"))?));
    }
    GaussianMixture::new(out, "mixture")
}

impl NegativeInformationScenario {
    /// The FoV of [`NegativeInformationScenario::fig5`]: the box `[min, max]` =
    /// [−1.5, 1.5] × [−1.5, 1.5].
    pub const FIG5_FOV: [[f64; 2]; 2] = [[-1.5, -1.5], [1.5, 1.5]];

    /// The scenario of Fig. 5 with the numbers listed on [`NegativeInformationScenario`].
    ///
    /// # Errors
    /// None in practice (the inputs are constants); the constructors it calls return
    /// `Result`.
    pub fn fig5() -> Result<Self> {
        let cov = [0.5, 0.5, 0.01, 0.0025];
        let rows: [(f64, [f64; 4]); 2] =
            [(0.7, [-3.0, 1.0, 1.5, 0.0]), (0.3, [-3.3, 1.6, 1.4, 0.0])];
        let mut comps = Vec::new();
        for (i, (w, m)) in rows.iter().enumerate() {
            let g = Gaussian::new(
                DVector::from_column_slice(m),
                DMatrix::from_diagonal(&DVector::from_column_slice(&cov)),
                &alloc::format!("initial[{i}]"),
            )?;
            comps.push((*w, g));
        }
        let (transition, process_noise) = constant_velocity(1.0, 0.01);
        Ok(Self {
            initial: GaussianMixture::new(comps, "initial")?,
            transition,
            process_noise,
            fov: Region::axis_box(&Self::FIG5_FOV[0], &Self::FIG5_FOV[1], "fov")?,
            detection_prob: 1.0,
            steps: 3,
            library: SplitLibrary::for_components(3, 0.001, super::Spacing::Equal)?,
            options: SplitOptions {
                min_weight: 0.01,
                ..SplitOptions::default()
            },
            reduction: ReductionOptions::default(),
        })
    }

    /// Runs the `steps` predict → split (Algorithm 1) → non-detection update cycles.
    ///
    /// # Errors
    /// Those of [`predict`], [`split_for_region`], [`non_detection_update`],
    /// [`reduce`] and [`Region::gaussian_mass`].
    pub fn run(&self) -> Result<Vec<NegativeInformationStep>> {
        let mut posterior = self.initial.clone();
        let mut out = Vec::with_capacity(self.steps);
        for step in 1..=self.steps {
            let predicted = predict(&posterior, &self.transition, &self.process_noise)?;
            let split = split_for_region(&predicted, &self.fov, &self.library, &self.options)?;
            let (updated, non_detection_prob) =
                non_detection_update(&split.mixture, &self.fov, self.detection_prob)?;
            posterior = reduce(&updated, &self.reduction)?;
            out.push(NegativeInformationStep {
                step,
                predicted_inside: inside_mass(&predicted, &self.fov)?,
                posterior_inside: inside_mass(&posterior, &self.fov)?,
                predicted,
                split,
                posterior: posterior.clone(),
                non_detection_prob,
            });
        }
        Ok(out)
    }
}

/// ⟨1_S, p⟩ of a mixture by [`Region::gaussian_mass`].
pub(crate) fn inside_mass(mixture: &GaussianMixture, region: &Region) -> Result<f64> {
    let mut acc = NeumaierSum::new();
    for (i, (w, g)) in mixture.components().iter().enumerate() {
        acc.add(
            w * region
                .gaussian_mass(g, &alloc::format!("mixture[{i}]"))?
                .value,
        );
    }
    Ok(acc.total())
}

//! Seeded random scenes like the sensor-placement example of Section VII of `001_…` (Figs
//! 9–10): a multi-Bernoulli RFS of Gaussian components with random existence probabilities,
//! means and covariances.
//!
//! The paper states only part of its recipe: "100 MB components, with probabilities of
//! existence randomly chosen between 0.35 and 1. Each MB component has a Gaussian density and
//! randomly chosen mean and covariance", with a 1 × 1 FoV whose optimal centre is
//! (−0.8, −1.25). What is followed and what is chosen here:
//!
//! | quantity | recipe | source |
//! |---|---|---|
//! | number of components | `count` (default 100) | paper |
//! | existence r | uniform in [0.35, 1) | paper |
//! | mean m | uniform in the square [−`extent`, `extent`]² (default `extent` 3) | chosen: the paper does not give its region of interest; ±3 holds its optimum (−0.8, −1.25) and makes a 1 × 1 FoV a sixth of the side, as in Fig. 9 |
//! | covariance P | R(θ) diag(σ₁², σ₂²) R(θ)ᵀ with θ uniform in [0, π) and σ₁, σ₂ independent, uniform in [`sigma[0]`, `sigma[1]`] (default [0.1, 0.5]) | chosen: the paper says only "randomly chosen" |
//!
//! Every component draws six uniforms in the fixed order (r, m_x, m_y, σ₁, σ₂, θ) from one
//! [`SplitMix64`] stream, so the scene of `count = n` is the first n components of any larger
//! scene with the same seed and settings, and the same seed gives bit-identical scenes on
//! every platform (integer arithmetic for the stream; `libm` for sin and cos; no
//! platform-dependent generator).

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::Gaussian;
use crate::math::rng::SplitMix64;

/// The largest number of components of one scene.
pub const MAX_SCENE_COUNT: usize = 10_000;

/// The settings of [`placement_scene`]; [`Default`] is the paper's scene as chosen here.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct SceneOptions {
    /// Number of multi-Bernoulli components (default 100), an integer in [0, 10000]
    /// ([`MAX_SCENE_COUNT`]).
    pub count: usize,
    /// Seed of the SplitMix64 stream, an integer in [0, 2^53 − 1] (default 1: a fixed
    /// default, so the same call always gives the same scene).
    pub seed: u64,
    /// Means uniform in [−extent, extent]², extent finite and > 0 (default 3).
    pub extent: f64,
    /// Principal standard deviations uniform in [min, max], 0 < min ≤ max, finite (default
    /// [0.1, 0.5]). Existence is uniform in [0.35, 1).
    pub sigma: [f64; 2],
}

impl Default for SceneOptions {
    fn default() -> Self {
        SceneOptions {
            count: 100,
            seed: 1,
            extent: 3.0,
            sigma: [0.1, 0.5],
        }
    }
}

/// A seeded multi-Bernoulli scene like Section VII of `001_…`: `(existence, Gaussian)` per
/// component, positions in 2D. See the [module documentation](self) for the recipe, which
/// parts the paper gives and which are chosen.
///
/// # Errors
/// [`Error::OutOfRange`] naming `count` (more than [`MAX_SCENE_COUNT`]);
/// [`Error::InvalidParameter`] naming `extent` (not finite and > 0), `sigma[0]` (not finite and > 0) or
/// `sigma[1]` (not finite and ≥ `sigma[0]`).
///
/// # Examples
/// ```
/// use fisst::fov::{placement_scene, SceneOptions};
/// let scene = placement_scene(&SceneOptions::default())?;
/// assert_eq!(scene.len(), 100);
/// assert!(scene.iter().all(|(r, g)| (0.35..1.0).contains(r) && g.mean()[0].abs() <= 3.0));
/// // A smaller count is a prefix of the same stream.
/// let five = placement_scene(&SceneOptions { count: 5, ..SceneOptions::default() })?;
/// assert_eq!(five[..], scene[..5]);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn placement_scene(options: &SceneOptions) -> Result<Vec<(f64, Gaussian)>> {
    let &SceneOptions {
        count,
        seed,
        extent,
        sigma: [s0, s1],
    } = options;
    Error::check_range("count", count, 0, MAX_SCENE_COUNT)?;
    if !(extent.is_finite() && extent > 0.0) {
        return Err(Error::parameter("extent", extent, "finite and > 0"));
    }
    if !(s0.is_finite() && s0 > 0.0) {
        return Err(Error::parameter("sigma[0]", s0, "finite and > 0"));
    }
    if !(s1.is_finite() && s1 >= s0) {
        return Err(Error::parameter("sigma[1]", s1, "finite and >= sigma[0]"));
    }
    let mut rng = SplitMix64::new(seed);
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let r = 0.35 + 0.65 * rng.uniform();
        let mx = extent * (2.0 * rng.uniform() - 1.0);
        let my = extent * (2.0 * rng.uniform() - 1.0);
        let a = s0 + (s1 - s0) * rng.uniform();
        let b = s0 + (s1 - s0) * rng.uniform();
        let theta = core::f64::consts::PI * rng.uniform();
        let (s, c) = (libm::sin(theta), libm::cos(theta));
        let (a2, b2) = (a * a, b * b);
        let off = c * s * (a2 - b2);
        let cov = [c * c * a2 + s * s * b2, off, off, s * s * a2 + c * c * b2];
        let name = alloc::format!("multi_bernoulli[{i}]");
        out.push((r, Gaussian::from_slices(&[mx, my], &cov, &name)?));
    }
    Ok(out)
}

/// One Bernoulli component of a [`PlacementScene`]: existence, 2D mean and 2 × 2 covariance.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SceneComponent {
    /// The existence probability r ∈ [0.35, 1).
    pub existence: f64,
    /// The mean position `[x, y]`.
    pub mean: [f64; 2],
    /// The position covariance `[[a, b], [b, c]]`, symmetric positive definite.
    pub cov: [[f64; 2]; 2],
}

/// A seeded multi-Bernoulli scene of Section VII of `001_…` (Figs 9–10) as the bindings give it:
/// `multi_bernoulli` is `[{existence, mean, cov}, …]`, ready to pass back as a multi-Bernoulli.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PlacementScene {
    /// The components, one per potential object.
    pub multi_bernoulli: Vec<SceneComponent>,
}

impl SceneOptions {
    /// [`placement_scene`] of these options as a [`PlacementScene`].
    ///
    /// # Errors
    /// Those of [`placement_scene`].
    pub fn scene(&self) -> Result<PlacementScene> {
        let multi_bernoulli = placement_scene(self)?
            .iter()
            .map(|(r, g)| {
                let (m, p) = (g.mean(), g.cov());
                SceneComponent {
                    existence: *r,
                    mean: [m[0], m[1]],
                    cov: [[p[(0, 0)], p[(0, 1)]], [p[(1, 0)], p[(1, 1)]]],
                }
            })
            .collect();
        Ok(PlacementScene { multi_bernoulli })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pinned values of the default scene: the wasm suite checks the same numbers, so the
    /// scene is the same natively and in wasm32.
    const GOLDEN: [(usize, [f64; 6]); 2] = [
        (
            0,
            [
                0.7182650238619825,
                1.4746905435762068,
                2.8260165215207773,
                0.07713190551083224,
                -1.046535880936458e-5,
                0.07713020602897852,
            ],
        ),
        (
            99,
            [
                0.5111431663750448,
                0.693157593170812,
                0.7195304907966535,
                0.06554451512016446,
                0.04699713313188498,
                0.2250281971638252,
            ],
        ),
    ];

    #[test]
    fn fig9_scene_is_placement_scene_as_rows() {
        let o = SceneOptions {
            count: 7,
            ..SceneOptions::default()
        };
        let rows = o.scene().unwrap();
        let raw = placement_scene(&o).unwrap();
        assert_eq!(rows.multi_bernoulli.len(), 7);
        for (c, (r, g)) in rows.multi_bernoulli.iter().zip(&raw) {
            assert_eq!(c.existence, *r);
            assert_eq!(c.mean, [g.mean()[0], g.mean()[1]]);
            assert_eq!(c.cov[0][1], g.cov()[(0, 1)]);
            assert_eq!(c.cov[1][1], g.cov()[(1, 1)]);
        }
        let e = SceneOptions { extent: -1.0, ..o }.scene().unwrap_err();
        assert_eq!(e.field(), "extent");
    }

    #[test]
    fn default_scene_is_pinned() {
        let scene = placement_scene(&SceneOptions::default()).unwrap();
        for (k, want) in GOLDEN {
            let (r, g) = &scene[k];
            let (m, p) = (g.mean(), g.cov());
            let got = [*r, m[0], m[1], p[(0, 0)], p[(0, 1)], p[(1, 1)]];
            assert_eq!(
                got.map(f64::to_bits),
                want.map(f64::to_bits),
                "component {k}"
            );
        }
    }

    #[test]
    fn scenes_follow_the_recipe() {
        let opts = SceneOptions {
            count: 500,
            seed: 9,
            extent: 2.0,
            sigma: [0.2, 0.3],
        };
        let scene = placement_scene(&opts).unwrap();
        assert_eq!(scene.len(), 500);
        for (r, g) in &scene {
            assert!((0.35..1.0).contains(r));
            let m = g.mean();
            assert!(m[0].abs() <= 2.0 && m[1].abs() <= 2.0);
            // The eigenvalues of P are σ₁², σ₂² ∈ [0.04, 0.09].
            let p = g.cov();
            let (tr, det) = (
                p[(0, 0)] + p[(1, 1)],
                p[(0, 0)] * p[(1, 1)] - p[(0, 1)] * p[(1, 0)],
            );
            let disc = libm::sqrt((tr * tr / 4.0 - det).max(0.0));
            let (lo, hi) = (tr / 2.0 - disc, tr / 2.0 + disc);
            assert!(lo >= 0.04 - 1e-12 && hi <= 0.09 + 1e-12, "{lo} {hi}");
        }
        // Different seeds, different scenes; the same seed, the same scene.
        let again = placement_scene(&opts).unwrap();
        assert_eq!(scene, again);
        let other = placement_scene(&SceneOptions { seed: 10, ..opts }).unwrap();
        assert_ne!(scene[0], other[0]);
        // Existence covers [0.35, 1) roughly uniformly.
        let mean_r = scene.iter().map(|(r, _)| r).sum::<f64>() / 500.0;
        assert!((mean_r - 0.675).abs() < 0.03, "{mean_r}");
    }

    #[test]
    fn validation_names_the_fields() {
        let d = SceneOptions::default();
        let field = |o: SceneOptions| -> alloc::string::String {
            placement_scene(&o).unwrap_err().field().into()
        };
        assert_eq!(
            field(SceneOptions {
                count: MAX_SCENE_COUNT + 1,
                ..d
            }),
            "count"
        );
        assert_eq!(field(SceneOptions { extent: 0.0, ..d }), "extent");
        assert_eq!(
            field(SceneOptions {
                extent: f64::NAN,
                ..d
            }),
            "extent"
        );
        assert_eq!(
            field(SceneOptions {
                sigma: [0.0, 1.0],
                ..d
            }),
            "sigma[0]"
        );
        assert_eq!(
            field(SceneOptions {
                sigma: [0.5, 0.4],
                ..d
            }),
            "sigma[1]"
        );
        assert!(
            placement_scene(&SceneOptions { count: 0, ..d })
                .unwrap()
                .is_empty()
        );
    }
}

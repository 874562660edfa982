//! Error bounds for joint detection and estimation of a single object (paper `002`: M.
//! Rezaeian, B.-N. Vo, "Error bounds for joint detection and estimation of a single object
//! with random finite set observation").
//!
//! The state is a Bernoulli RFS X ~ B(r, f); the estimate X̂(Z) is ∅ or {x̂}; the error is the
//! metric e with e(∅, {x'}) = e0, e({x}, ∅) = e1 and e({x}, {x'}) = x − x'. The bounds are
//! on E e²(X, X̂(Z)) for MAP detection on Z ≠ ∅ and any rule on Z = ∅.
//!
//! | item | paper |
//! |---|---|
//! | [`assemble`], [`Ingredients`], [`Terms`] | the HPE/LPE bounds (47)–(48), (57)–(58); (17)/(21), (23)–(24) |
//! | [`corollary1`], [`corollary2`], [`corollary3`] | (27), (28), (29) |
//! | [`gaussian_no_clutter`], [`gaussian_fisher_information`] | (30)–(31), Example 1 (with NOTES.md's erratum) |
//! | [`map_threshold`], [`NoClutterBound::map_bound`] | Section IV-A: MAP detection on Z = ∅ moves r* to r_M* |
//! | [`sequential_bound`] | IRF (35), Enumeration (37) |
//!
//! ```
//! use fisst::bounds::{gaussian_no_clutter, gaussian_fisher_information};
//! // Fig. 2 left: σf² = 100, σh² = 25, e0² = 150, e1² = 200.
//! let b = gaussian_no_clutter(1.0, 0.5, 100.0, 25.0, 150.0, 200.0)?;
//! assert!((b.bound - 62.5).abs() < 1e-12); // 100 − 0.5 (100 − 25)
//! let j = gaussian_fisher_information(100.0, 1.0, 100.0 / 3.0)?;
//! assert!((j.posterior_variance - 25.0).abs() < 1e-12);
//! # Ok::<(), fisst::Error>(())
//! ```

mod closed;

pub use closed::{
    Assembled, GaussianInformation, Ingredients, MAX_STEPS, NoClutterBound, Phase, Sequential,
    Terms, assemble, corollary1, corollary2, corollary3, gaussian_fisher_information,
    gaussian_no_clutter, map_threshold, poisson_pmf, sequential_bound,
};
mod model;
mod theorem;
mod theorem2;

pub use model::{Density, Density1, Detection, GAUSSIAN_SPAN, LinearGaussian, Observation};
pub use theorem::{Cardinality, JdeBound, Method, ModelI, Settings, theorem1};
pub use theorem2::{MAX_CLUTTER_RATE, ModelII, theorem2};
mod example2;
pub use example2::{
    Example2, Example2Observation, Example2Prior, Example2Regularity, UnitUniform, example2,
    example2_regularity,
};

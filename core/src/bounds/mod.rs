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
//! | [`Density`], [`Observation`] (closures with derivatives), [`Density1`], [`Detection`], [`LinearGaussian`] | f, P_o, g, ψ, v of models I (13) and II (22) |
//! | [`theorem1`], [`ModelI`] | Theorem 1 (14)–(21) by quadrature: P̄o, f_d, f_d', σ_e², Z'_0 by root-finding, w_1, η_1, J'_1 (20) |
//! | [`theorem2`], [`ModelII`] | Theorem 2 (22)–(26): n = 1 by quadrature, n = 2 by Monte Carlo or (opt-in, [`Settings::quadrature_cardinality`]) 2D cubature over Z², n ≥ 3 by Monte Carlo; η2 exact (see [`theorem2`]'s module) |
//! | [`component_bound`], [`component_bounds_no_clutter`], [`component_corollary1`], [`gaussian_information_matrix`] | the vector extensions (63)–(72) |
//! | [`vector_bound`], [`VectorModel`], [`GaussianPrior`], [`LinearGaussianSensor`] | (63)–(65) for a Gaussian state in R^l and a linear-Gaussian sensor: per-component and whole-state bounds of Theorems 1 and 2 |
//! | [`example2`], [`example2_regularity`] | Example 2 (32), Fig. 2 right: (32) against (20), and the regularity failure |
//!
//! ## What is a bound, and what is returned
//! - Every term is computed as the paper defines it except where NOTES.md or these docs say
//!   otherwise: J'_n carries the 1/w_n² of (20)/(25) (Example 2's (32) drops it: both are in
//!   [`Example2`]); (23) is read as NOTES.md says; η2 is the exact clutter-rejection
//!   probability, not the product-region formula e^{−λ0} − e^{−λ}.
//! - Truncation: Σ C_n J'⁻¹ is cut where the Poisson tail is below
//!   [`Settings::series_tolerance`] (a valid lower bound: the terms are ≥ 0); Σ C_n w_{n+1} gets
//!   the tail added (w ≤ 1), and the η2 tail is bracketed, so the returned number stays a lower
//!   bound. Monte Carlo and quadrature errors are in [`JdeBound::error`]; the bound is the point
//!   estimate (subtract `error` for a conservative one).
//! - The information inequality needs p_1(·, z) to vanish at the ends of the prior's support;
//!   [`JdeBound::regular`] is false when it does not (uniform priors, tables, Example 2, where
//!   1/J_1 = 0.1897 exceeds the posterior mean's MSE 0.0340): there the estimation term, and so
//!   the "bound", can exceed what an estimator attains.
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
mod vector;
pub use vector::{
    ComponentBound, GaussianPrior, LinearGaussianSensor, VectorBound, VectorMeasurement,
    VectorModel, component_bound, component_bounds_no_clutter, component_corollary1,
    gaussian_information_matrix, vector_bound,
};

//! # fisst — random-finite-set estimation
//!
//! Exact, embeddable implementations of the methods of five papers on random finite sets
//! (RFS): multi-object metrics and optimal multi-Bernoulli estimation (the spooky effect),
//! optimal Bernoulli point estimation, Gaussian splitting for imprecise and negative
//! information, error bounds for joint detection and estimation, and sensor control.
//!
//! ## Quick start
//! ```
//! use fisst::metrics::{Gospa, Ospa};
//! use fisst::estimators::multi_bernoulli::{optimal_estimate, SetMetric};
//!
//! let truth = [[0.0, 0.0], [10.0, 0.0]];
//! let estimate = [[0.5, 0.0], [30.0, 0.0], [40.0, 0.0]];
//! let g = Gospa::new(5.0, 2.0, 2.0)?.decompose(&truth, &estimate)?;
//! assert_eq!((g.missed, g.false_targets), (1, 2));
//! let o = Ospa::new(5.0, 2.0)?.decompose(&truth, &estimate)?;
//! assert!(o.distance <= 5.0);
//!
//! // The optimal OSPA estimate of two far-apart potential targets reports both although
//! // neither is more likely than not to exist: the spooky effect.
//! let best = optimal_estimate(&[0.4, 0.4], SetMetric::Ospa, 1.0, 2.0)?;
//! assert_eq!(best.report, vec![true, true]);
//! # Ok::<(), fisst::Error>(())
//! ```
//!
//! ## Bernoulli filters
//! [`filters`] has the Gaussian-mixture Bernoulli filter for imprecise (region) reports,
//! negative information and vector measurements (Algorithm 3 of `001`), the Bernoulli
//! particle filter it is compared with, and [`sim::airport`] the paper's airport example.
//!
//! ## Features
//! | feature | default | what it does |
//! |---|---|---|
//! | `std` | yes | std support in dependencies. Without it the crate is `#![no_std]` + `alloc` and builds for bare-metal targets such as `thumbv7em-none-eabihf`. |
//! | `parallel` | yes | implies `std`; independent work (metric series over whole scenarios, Monte Carlo comparisons) runs on all cores with rayon. Results are identical with and without it. The wasm bindings leave it off (wasm32 has no threads). |
//! | `serde` | no | `Serialize`/`Deserialize` for the option, model and result types (works without `std`). See [Serialisation](#serialisation). |
//!
//! ## Serialisation
//! With the `serde` feature the option, model and result types (de)serialise under their
//! **Rust field names** (`future_scans`, `position_dims`, …; enum variants under their Rust
//! names, externally tagged). A binding that shows other names (the JavaScript package's
//! camelCase) maps them in its own (de)serialiser; the core does not rename. Vectors are
//! arrays `[x, …]` and matrices row-major arrays of rows `[[…], …]` (module `serde_shapes`).
//!
//! Required fields stay required (a missing one is an error). An omitted optional field takes
//! its default from one place: the type's [`Default`] when every field has one (e.g.
//! [`splitting::SplitOptions`], [`bounds::TheoremOptions`]), else the function the type's own
//! constructor uses (e.g. [`filters::default_reduction`] for a filter configuration's
//! `reduction`). Types with invariants ([`gaussian::Gaussian`], [`regions::Region`],
//! [`filters::GmBernoulli`], …) are written as the arguments of their constructor and read
//! back through it, so a deserialised value is always valid and an invalid one fails with the
//! core's [`Error`] message. A clutter density given as a Rust function is not serialisable.
//!
//! ## Conventions
//! - Every float function comes from `libm` (see [`math::fns`]), so the same inputs give
//!   bit-identical outputs natively, in wasm32 and on a microcontroller.
//! - Data-dependent failures are [`Error`]s naming the offending field; nothing panics on bad
//!   input.
//! - Each formula cites its paper and equation. The papers (`shared/papers/` in the
//!   repository) are: `000` Narykov, Üney, Ralph, optimal Bernoulli point estimation; `001`
//!   LeGrand, Ferrari, "Split happens!"; `002` Rezaeian, Vo, error bounds for joint detection
//!   and estimation; `003` García-Fernández, Svensson, the spooky effect in optimal OSPA
//!   estimation; `004` Ristic, Vo, sensor control for multi-object estimation.
#![no_std]
#![deny(missing_docs)]
#![doc(test(attr(deny(warnings))))]

extern crate alloc;
// Tests may use std whatever the features (the library itself never does without `std`).
#[cfg(any(feature = "std", test))]
extern crate std;

pub mod bernoulli;
pub mod bounds;
pub mod cardinality;
pub mod control;
#[cfg(all(test, feature = "std"))]
mod doc_caps_tests;
pub mod error;
pub mod estimators;
pub mod filters;
pub mod fov;
pub mod gaussian;
pub mod math;
pub mod metrics;
pub mod mixture;
pub mod regions;
#[cfg(feature = "serde")]
pub mod serde_shapes;
#[cfg(all(test, feature = "serde"))]
mod serde_tests;
#[cfg(feature = "serde")]
mod serde_valid;
pub mod sim;
pub mod smc;
pub mod splitting;

pub use error::{Error, Phrase, Result};

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
pub mod error;
pub mod estimators;
pub mod filters;
pub mod fov;
pub mod gaussian;
pub mod math;
pub mod metrics;
pub mod mixture;
pub mod regions;
pub mod sim;
pub mod splitting;

pub use error::{Error, Result};

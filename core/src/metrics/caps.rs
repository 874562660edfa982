//! The caps that bound the time of one OSPA/GOSPA evaluation and of one series (issue 26
//! point 7: no unbounded call): points, steps, candidate pairs and dense assignment work.
//! Each is checked before the work it bounds and fails with an error naming the field.

use crate::error::{Error, Result};

/// The most points, truth and estimate together, of one OSPA/GOSPA evaluation: `2^19 =
/// 524,288` (a bound on its time: half a million points take about a second in Node, most of
/// it reading them). Beyond it the call returns [`Error::OverBudget`] naming the larger set,
/// `truth` or `estimate`.
pub const MAX_TOTAL_POINTS: usize = 1 << 19;

/// The most points, over all steps and both sides, of one series ([`super::Gospa::series`],
/// [`super::Ospa::series`]): `2^18 = 262,144` (every step is a whole evaluation). Beyond it
/// the call returns [`Error::OverBudget`] naming `truths`.
pub const MAX_SERIES_POINTS: usize = 1 << 18;

/// The most steps of one series: `2^18 = 262,144` (each step is an evaluation of its own, and
/// each a set pair to read). Beyond it the call returns [`Error::Count`] naming `truths`
/// ([`check_series_steps`]: the bindings call it before reading the steps).
pub const MAX_SERIES_STEPS: usize = 1 << 18;

/// `Ok` if a series of `steps` steps is within [`MAX_SERIES_STEPS`], else [`Error::Count`]
/// naming `truths`.
///
/// # Errors
/// As above.
pub fn check_series_steps(steps: usize) -> Result<()> {
    Error::check_count("truths", "steps", steps, 0, MAX_SERIES_STEPS)
}

/// The most candidate pairs (pairs in neighbouring grid cells, or all `|X|·|Y|` pairs without
/// a grid) that one evaluation examines: `2^28` on 64-bit targets, `2^26 = 67,108,864` on
/// 32-bit targets (wasm32): twice [`MAX_CLOSE_PAIRS`](super::MAX_CLOSE_PAIRS), so that the scenes that reach that cap
/// still say so, while denser ones fail at once instead of counting billions of pairs.
/// Beyond it the call returns [`Error::InvalidParameter`] naming
/// `truth × estimate candidate pairs` with their count.
#[cfg(target_pointer_width = "64")]
pub const MAX_CANDIDATE_PAIRS: usize = 1 << 28;
/// See the 64-bit documentation: `2^26` on 32-bit targets.
#[cfg(not(target_pointer_width = "64"))]
pub const MAX_CANDIDATE_PAIRS: usize = 1 << 26;

/// The most work of the dense assignments of one evaluation, `Σ min(r, k)²·max(r, k)` over the
/// `r × k` matrices solved densely (the components of the pairs closer than c that are at
/// least half full, or the whole problem when it is small or no grid splits it): `2^30`
/// (about 1,000 × 1,000 points all within c of each other; about a second in Node). Beyond it
/// the call returns [`Error::InvalidParameter`] naming `truth × estimate dense assignment
/// work` with the work.
pub const MAX_DENSE_WORK: u64 = 1 << 30;

/// `min(r, k)² · max(r, k)`, the shortest-augmenting-path cost of an `r × k` assignment.
pub(crate) fn dense_work(r: usize, k: usize) -> u64 {
    let (a, b) = (r.min(k) as u64, r.max(k) as u64);
    a.saturating_mul(a).saturating_mul(b)
}

/// The field of the error beyond [`MAX_DENSE_WORK`].
pub(crate) const WORK_FIELD: &str = "truth × estimate dense assignment work";
/// The field of the error beyond [`MAX_CANDIDATE_PAIRS`].
pub(crate) const CANDIDATES_FIELD: &str = "truth × estimate candidate pairs";

/// `Ok` if `work` is within [`MAX_DENSE_WORK`], else [`Error::InvalidParameter`] naming
/// [`WORK_FIELD`] with the work (exact in an `f64`, whatever the target's `usize`).
pub(crate) fn check_dense_work(work: u64) -> Result<()> {
    if work > MAX_DENSE_WORK {
        return Err(Error::parameter(
            WORK_FIELD,
            work as f64,
            "at most MAX_DENSE_WORK = 2^30 (the sum of min(r, k)^2 max(r, k) over the groups of \
             r × k points mostly within c of each other, about 1,000 × 1,000): lower c or split \
             the sets",
        ));
    }
    Ok(())
}

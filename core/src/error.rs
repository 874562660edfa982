//! The crate's error type.
//!
//! Every data-dependent failure is an [`Error`] whose message names the offending field with
//! the same name the JavaScript bindings use (`c`, `p`, `alpha`, `existence[3]`, `truth[2]`, …),
//! so a Rust user and a JavaScript user read the same sentence.

use alloc::string::String;
use alloc::vec::Vec;
use core::fmt;

use crate::math::decimal::Decimal;

/// What went wrong, and where.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A number outside its documented domain (NaN, infinite, negative, …).
    InvalidParameter {
        /// The field, e.g. `c` or `truth[2][0]`.
        what: String,
        /// The offending value.
        value: f64,
        /// The domain it must lie in, as a phrase: "finite and > 0".
        expected: &'static str,
    },
    /// A probability that is NaN or outside [0, 1].
    InvalidProbability {
        /// The field, e.g. `existence[3]`.
        what: String,
        /// The offending value.
        value: f64,
    },
    /// Two things that must have the same length or dimension do not.
    DimensionMismatch {
        /// The field, e.g. `estimate[4]`.
        what: String,
        /// The length or dimension required.
        expected: usize,
        /// The length or dimension found.
        found: usize,
    },
    /// A matrix that must be symmetric positive definite is not.
    NotPositiveDefinite {
        /// The field, e.g. `components[1].cov`.
        what: String,
    },
    /// A request the method cannot serve with these settings (e.g. the GOSPA decomposition
    /// for α ≠ 2).
    Unsupported {
        /// The field whose value makes the request unsupported.
        what: String,
        /// Why, as a sentence fragment.
        reason: &'static str,
    },
    /// An integer option outside its interval [min, max].
    OutOfRange {
        /// The field, e.g. `samples`.
        what: String,
        /// The offending value.
        value: usize,
        /// The smallest value allowed.
        min: usize,
        /// The largest value allowed.
        max: usize,
    },
    /// A request whose work exceeds a cap (e.g. Theorem 2's Monte Carlo of paper 002:
    /// samples × Σ n at most 10^7).
    OverBudget {
        /// The field to lower, e.g. `samples`.
        what: String,
        /// How the work is counted, e.g. "samples × Σ n".
        measure: &'static str,
        /// The work asked for.
        work: usize,
        /// The cap and what to do, e.g. "10^7 at this clutter rate; pass fewer samples".
        limit: &'static str,
        /// The largest value of `what` within the cap.
        at_most: usize,
    },
    /// A list whose number of entries lies outside [min, max] (a scan of at most 1000 report
    /// regions, a measurement matrix of 1 to 64 rows).
    Count {
        /// The list, e.g. `reports`.
        what: String,
        /// What it holds, plural: "regions", "rows".
        noun: &'static str,
        /// The number of entries found.
        found: usize,
        /// The fewest allowed.
        min: usize,
        /// The most allowed.
        max: usize,
    },
    /// Two fields whose dimensions must agree do not, said in matrix terms: `mixture[0].mean
    /// has length 4 but transition.f is 2×2`.
    ShapeMismatch {
        /// The field that disagrees, e.g. `mixture[0].mean`.
        what: String,
        /// Its shape.
        shape: Shape,
        /// The field it disagrees with, e.g. `transition.f`.
        other: String,
        /// That field's shape.
        other_shape: Shape,
    },
    /// A matrix that must be symmetric is not: entry `[row][col]` differs from `[col][row]`
    /// (beyond a relative tolerance).
    NotSymmetric {
        /// The matrix, e.g. `transition.q`.
        what: String,
        /// The row of the first entry found (the upper triangle, row < col).
        row: usize,
        /// Its column.
        col: usize,
        /// The entry `[row][col]`.
        upper: f64,
        /// The entry `[col][row]`.
        lower: f64,
    },
    /// A symmetric matrix that must be positive definite (or semidefinite) is not.
    NotDefinite {
        /// The matrix, e.g. `mixture[0].cov`.
        what: String,
        /// Its smallest eigenvalue.
        smallest_eigenvalue: f64,
        /// True when positive semidefinite was required (a noise covariance Q).
        semidefinite: bool,
    },
    /// A value in a form that does not fit the other options: a matrix where a 1D prior takes
    /// a number, two alternatives both given, a required alternative missing, rows of the
    /// wrong length. `problem` continues the sentence after the field, naming other fields by
    /// [`Phrase::Path`] and [`Phrase::Name`] so that each binding renders them in its own
    /// names ([`Error::map_paths`], [`Error::map_names`]).
    Form {
        /// The field, e.g. `observation.gain`.
        what: String,
        /// The rest of the sentence, e.g. "must be a number with a 1D prior".
        problem: Vec<Phrase>,
        /// A wrong kind of value (a `TypeError` in the bindings), not a wrong value.
        wrong_kind: bool,
    },
}

/// A piece of an [`Error::Form`]'s sentence.
#[derive(Clone, Debug, PartialEq)]
pub enum Phrase {
    /// Words, as they are.
    Text(String),
    /// Another field's full path (from the same root as the error's field), e.g.
    /// `observation.noise_cov`: mapped with the field by [`Error::map_paths`].
    Path(String),
    /// A field's bare name, e.g. `noise_variance`: mapped by [`Error::map_names`] only.
    Name(String),
}

impl Phrase {
    /// [`Phrase::Text`].
    pub fn text(s: impl Into<String>) -> Self {
        Phrase::Text(s.into())
    }
    /// [`Phrase::Path`].
    pub fn path(s: impl Into<String>) -> Self {
        Phrase::Path(s.into())
    }
    /// [`Phrase::Name`].
    pub fn name(s: impl Into<String>) -> Self {
        Phrase::Name(s.into())
    }
}

/// The shape of a field, as [`Error::ShapeMismatch`] says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A list of this many numbers ("has length 4").
    Length(usize),
    /// A matrix of rows × columns ("is 2×2").
    Matrix(usize, usize),
    /// A count ("is 2", e.g. `position_dims`).
    Value(usize),
}

impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Shape::Length(n) => write!(f, "has length {n}"),
            Shape::Matrix(r, c) => write!(f, "is {r}×{c}"),
            Shape::Value(n) => write!(f, "is {n}"),
        }
    }
}

/// `Result` with [`Error`] as its default error type.
pub type Result<T, E = Error> = core::result::Result<T, E>;

impl Error {
    /// An [`Error::InvalidParameter`].
    pub fn parameter(what: impl Into<String>, value: f64, expected: &'static str) -> Self {
        Error::InvalidParameter {
            what: what.into(),
            value,
            expected,
        }
    }

    /// An [`Error::InvalidProbability`].
    pub fn probability(what: impl Into<String>, value: f64) -> Self {
        Error::InvalidProbability {
            what: what.into(),
            value,
        }
    }

    /// An [`Error::DimensionMismatch`].
    pub fn dimension(what: impl Into<String>, expected: usize, found: usize) -> Self {
        Error::DimensionMismatch {
            what: what.into(),
            expected,
            found,
        }
    }

    /// An [`Error::OutOfRange`]: `value` must lie in [`min`, `max`].
    pub fn range(what: impl Into<String>, value: usize, min: usize, max: usize) -> Self {
        Error::OutOfRange {
            what: what.into(),
            value,
            min,
            max,
        }
    }

    /// `Ok` if `count` items of `per_item` work each (`measure`) stay within `cap`, else an
    /// [`Error::OverBudget`] naming `what` with the work, `limit` (the cap in words) and the
    /// largest count within the cap.
    pub fn check_work(
        what: &str,
        measure: &'static str,
        limit: &'static str,
        per_item: usize,
        count: usize,
        cap: usize,
    ) -> Result<()> {
        let per_item = per_item.max(1);
        let work = per_item.saturating_mul(count);
        if work > cap {
            return Err(Error::OverBudget {
                what: what.into(),
                measure,
                work,
                limit,
                at_most: cap / per_item,
            });
        }
        Ok(())
    }

    /// `Ok` if the list `what` of `found` `noun` has between `min` and `max` entries, else an
    /// [`Error::Count`].
    pub fn check_count(
        what: &str,
        noun: &'static str,
        found: usize,
        min: usize,
        max: usize,
    ) -> Result<()> {
        if found < min || found > max {
            return Err(Error::Count {
                what: what.into(),
                noun,
                found,
                min,
                max,
            });
        }
        Ok(())
    }

    /// `value` if it lies in [`min`, `max`], else an [`Error::OutOfRange`] naming `what`.
    pub fn check_range(what: &str, value: usize, min: usize, max: usize) -> Result<usize> {
        if value < min || value > max {
            return Err(Error::range(what, value, min, max));
        }
        Ok(value)
    }

    /// An [`Error::ShapeMismatch`]: `what` (of `shape`) disagrees with `other` (of
    /// `other_shape`).
    pub fn shapes(
        what: impl Into<String>,
        shape: Shape,
        other: impl Into<String>,
        other_shape: Shape,
    ) -> Self {
        Error::ShapeMismatch {
            what: what.into(),
            shape,
            other: other.into(),
            other_shape,
        }
    }

    /// An [`Error::Form`]: `what` in a form that does not fit, said by `problem`; a type
    /// error when `wrong_kind`.
    pub fn form(what: impl Into<String>, wrong_kind: bool, problem: Vec<Phrase>) -> Self {
        Error::Form {
            what: what.into(),
            problem,
            wrong_kind,
        }
    }

    /// Whether this error is about the kind of a value (a `TypeError` in the bindings: an
    /// [`Error::Form`] with `wrong_kind`) rather than its value.
    pub fn is_wrong_kind(&self) -> bool {
        matches!(
            self,
            Error::Form {
                wrong_kind: true,
                ..
            }
        )
    }

    /// The same error with every field path it names mapped by `rename` (the field and, for
    /// [`Error::ShapeMismatch`], the field it disagrees with; for [`Error::Form`], the
    /// [`Phrase::Path`]s).
    pub fn map_paths(self, mut rename: impl FnMut(&str) -> String) -> Self {
        self.map_paths_with(&mut rename)
    }

    /// [`Error::map_paths`] through one non-generic body (one copy per wasm module, not one
    /// per closure: issue 25, wasm size).
    #[inline(never)]
    fn map_paths_with(mut self, rename: &mut dyn FnMut(&str) -> String) -> Self {
        match &mut self {
            Error::ShapeMismatch { other, .. } => *other = rename(other),
            Error::Form { problem, .. } => {
                for p in problem.iter_mut() {
                    if let Phrase::Path(path) = p {
                        *path = rename(path);
                    }
                }
            }
            _ => {}
        }
        let what = self.field_mut();
        *what = rename(what);
        self
    }

    /// The same error with the bare field names of an [`Error::Form`]'s sentence
    /// ([`Phrase::Name`]) mapped by `rename`: how a binding shows them in its own names
    /// (`noise_variance` → `noiseVariance`). Other errors are unchanged.
    pub fn map_names(mut self, mut rename: impl FnMut(&str) -> String) -> Self {
        if let Error::Form { problem, .. } = &mut self {
            for p in problem.iter_mut() {
                if let Phrase::Name(name) = p {
                    *name = rename(name);
                }
            }
        }
        self
    }

    /// The same error with the path of the field it disagrees with mapped by `rename` (only
    /// [`Error::ShapeMismatch`] names one): for a binding whose two fields are in different
    /// arguments.
    pub fn map_other(mut self, rename: impl FnOnce(&str) -> String) -> Self {
        if let Error::ShapeMismatch { other, .. } = &mut self {
            *other = rename(other);
        }
        self
    }

    /// The field this error's field disagrees with ([`Error::ShapeMismatch`] only).
    pub fn other_field(&self) -> Option<&str> {
        match self {
            Error::ShapeMismatch { other, .. } => Some(other),
            _ => None,
        }
    }

    /// The same error about another field: `rename` maps the field's name (e.g. to say which
    /// time step of a series it is in, or to render a path in a binding's own names).
    pub fn map_field(mut self, rename: impl FnOnce(&str) -> String) -> Self {
        let what = self.field_mut();
        *what = rename(what);
        self
    }

    /// The field this error is about, to rename.
    fn field_mut(&mut self) -> &mut String {
        match self {
            Error::OutOfRange { what, .. }
            | Error::OverBudget { what, .. }
            | Error::Count { what, .. }
            | Error::InvalidParameter { what, .. }
            | Error::InvalidProbability { what, .. }
            | Error::DimensionMismatch { what, .. }
            | Error::NotPositiveDefinite { what }
            | Error::ShapeMismatch { what, .. }
            | Error::NotSymmetric { what, .. }
            | Error::NotDefinite { what, .. }
            | Error::Form { what, .. }
            | Error::Unsupported { what, .. } => what,
        }
    }

    /// The same error about the field `prefix.field` (or `prefix[i]…` when the field starts
    /// with an index): how the bindings give a core error the full path of an argument, e.g.
    /// `c` → `options.c`, `[2].mean` → `options.mixture[2].mean`.
    pub fn within(self, prefix: &str) -> Self {
        if prefix.is_empty() {
            return self;
        }
        self.map_paths(|what| {
            if what.is_empty() {
                prefix.into()
            } else if what.starts_with('[') {
                alloc::format!("{prefix}{what}")
            } else {
                alloc::format!("{prefix}.{what}")
            }
        })
    }

    /// The field this error is about.
    pub fn field(&self) -> &str {
        match self {
            Error::InvalidParameter { what, .. }
            | Error::InvalidProbability { what, .. }
            | Error::DimensionMismatch { what, .. }
            | Error::NotPositiveDefinite { what }
            | Error::Unsupported { what, .. }
            | Error::OutOfRange { what, .. }
            | Error::OverBudget { what, .. }
            | Error::ShapeMismatch { what, .. }
            | Error::NotSymmetric { what, .. }
            | Error::NotDefinite { what, .. }
            | Error::Form { what, .. }
            | Error::Count { what, .. } => what,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidParameter {
                what,
                value,
                expected,
            } => write!(f, "{what} must be {expected}, got {}", Decimal(*value)),
            Error::InvalidProbability { what, value } => {
                write!(
                    f,
                    "{what} must be a probability in [0, 1], got {}",
                    Decimal(*value)
                )
            }
            Error::DimensionMismatch {
                what,
                expected,
                found,
            } => write!(f, "{what} has length {found}, expected {expected}"),
            Error::NotPositiveDefinite { what } => {
                write!(f, "{what} must be symmetric positive definite")
            }
            Error::Unsupported { what, reason } => write!(f, "{what}: {reason}"),
            Error::OutOfRange {
                what,
                value,
                min,
                max,
            } => write!(
                f,
                "{what} must be an integer in [{min}, {max}], got {value}"
            ),
            Error::OverBudget {
                what,
                measure,
                work,
                limit,
                at_most,
            } => write!(
                f,
                "{what}: {measure} = {work} exceeds {limit} (at most {at_most})"
            ),
            // a list with no lower bound only has a cap to say
            Error::Count {
                what,
                noun,
                found,
                min: 0,
                max,
            } => write!(f, "{what} has {found} {noun}, at most {max} are supported"),
            Error::Count {
                what,
                noun,
                found,
                min,
                max,
            } => write!(f, "{what} must have {min} to {max} {noun}, got {found}"),
            Error::ShapeMismatch {
                what,
                shape,
                other,
                other_shape,
            } => write!(f, "{what} {shape} but {other} {other_shape}"),
            Error::NotSymmetric {
                what,
                row,
                col,
                upper,
                lower,
            } => write!(
                f,
                "{what} is not symmetric: [{row}][{col}] = {} but [{col}][{row}] = {}",
                Decimal(*upper),
                Decimal(*lower)
            ),
            Error::NotDefinite {
                what,
                smallest_eigenvalue,
                semidefinite,
            } => {
                let semi = if *semidefinite { "semi" } else { "" };
                write!(
                    f,
                    "{what} is not positive {semi}definite (smallest eigenvalue {})",
                    Decimal(*smallest_eigenvalue)
                )
            }
            Error::Form { what, problem, .. } => {
                // a sentence about a part of the field ("[1] has length …") continues its
                // path, and so does one after a colon
                let joined = match problem.first() {
                    Some(Phrase::Text(t)) => {
                        matches!(t.as_bytes().first(), Some(b'[' | b'.' | b':'))
                    }
                    _ => false,
                };
                f.write_str(what)?;
                if !joined {
                    f.write_str(" ")?;
                }
                for p in problem {
                    match p {
                        Phrase::Text(s) | Phrase::Path(s) | Phrase::Name(s) => f.write_str(s)?,
                    }
                }
                Ok(())
            }
        }
    }
}

impl core::error::Error for Error {}

/// Checks that `value` is a probability in [0, 1] (NaN is rejected).
pub(crate) fn check_probability(what: impl FnOnce() -> String, value: f64) -> Result<f64> {
    if (0.0..=1.0).contains(&value) {
        Ok(value)
    } else {
        Err(Error::probability(what(), value))
    }
}

/// Checks every entry of `values` with [`check_probability`], naming it `name[i]`.
pub(crate) fn check_probabilities(name: &str, values: &[f64]) -> Result<()> {
    for (i, &r) in values.iter().enumerate() {
        check_probability(|| alloc::format!("{name}[{i}]"), r)?;
    }
    Ok(())
}

/// A string in double quotes, escaped as Rust's `{:?}` escapes it wherever that is defined by
/// ASCII alone: `\"`, `\\`, `\n`, `\r`, `\t`, `\0`, and any other control character (C0, DEL,
/// C1) as `\u{1b}`. Other characters are written as they are, where `{:?}` would also escape
/// the unprintable and combining ones by the standard library's Unicode tables (with the
/// character and string `Debug` code, about 6 KB of every wasm module of the npm package;
/// issue 25).
/// The test `quoted_is_debug_for_ascii_and_printable_text` compares the two.
pub struct Quoted<'a>(pub &'a str);

impl fmt::Display for Quoted<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        f.write_char('"')?;
        for c in self.0.chars() {
            match c {
                '"' => f.write_str("\\\"")?,
                '\\' => f.write_str("\\\\")?,
                '\n' => f.write_str("\\n")?,
                '\r' => f.write_str("\\r")?,
                '\t' => f.write_str("\\t")?,
                '\0' => f.write_str("\\0")?,
                '\u{1}'..='\u{1f}' | '\u{7f}'..='\u{9f}' => {
                    let n = c as u32;
                    f.write_str("\\u{")?;
                    if n >= 16 {
                        f.write_char(hex_digit(n >> 4))?;
                    }
                    f.write_char(hex_digit(n & 15))?;
                    f.write_char('}')?;
                }
                c => f.write_char(c)?,
            }
        }
        f.write_char('"')
    }
}

fn hex_digit(d: u32) -> char {
    char::from_digit(d, 16).unwrap_or('0')
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn messages_name_the_field() {
        let e = Error::parameter("c", -1.0, "finite and > 0");
        assert_eq!(e.to_string(), "c must be finite and > 0, got -1");
        assert_eq!(e.field(), "c");
        let e = Error::probability("existence[3]", 1.5);
        assert_eq!(
            e.to_string(),
            "existence[3] must be a probability in [0, 1], got 1.5"
        );
        let e = Error::dimension("estimate[1]", 2, 3);
        assert_eq!(e.to_string(), "estimate[1] has length 3, expected 2");
        let e = Error::range("samples", 5, 100, 1000);
        assert_eq!(
            e.to_string(),
            "samples must be an integer in [100, 1000], got 5"
        );
    }

    #[test]
    fn count_says_the_cap_or_the_interval() {
        let e = Error::check_count("reports", "regions", 1001, 0, 1000).unwrap_err();
        assert_eq!(
            e.to_string(),
            "reports has 1001 regions, at most 1000 are supported"
        );
        let e = Error::check_count("likelihood.h", "rows", 0, 1, 64).unwrap_err();
        assert_eq!(e.to_string(), "likelihood.h must have 1 to 64 rows, got 0");
        assert_eq!(e.within("options").field(), "options.likelihood.h");
        assert!(Error::check_count("reports", "regions", 1000, 0, 1000).is_ok());
    }

    #[test]
    fn within_prefixes_the_field() {
        let e = Error::parameter("c", 0.0, "finite and > 0").within("options");
        assert_eq!(e.to_string(), "options.c must be finite and > 0, got 0");
        let e = Error::dimension("[2].mean", 2, 3).within("options.mixture");
        assert_eq!(e.field(), "options.mixture[2].mean");
        assert_eq!(Error::probability("r", 2.0).within("").field(), "r");
    }

    #[test]
    fn shape_and_covariance_errors_say_what_disagrees() {
        let e = Error::shapes(
            "mixture[0].mean",
            Shape::Length(4),
            "transition.f",
            Shape::Matrix(2, 2),
        )
        .within("config");
        assert_eq!(
            e.to_string(),
            "config.mixture[0].mean has length 4 but config.transition.f is 2×2"
        );
        assert_eq!(e.other_field(), Some("config.transition.f"));
        let e = e.map_other(|o| o.replace("config", "x"));
        assert_eq!(e.other_field(), Some("x.transition.f"));
        let e = Error::NotSymmetric {
            what: "transition.q".into(),
            row: 0,
            col: 1,
            upper: 0.5,
            lower: 0.4,
        };
        assert_eq!(
            e.to_string(),
            "transition.q is not symmetric: [0][1] = 0.5 but [1][0] = 0.4"
        );
        let e = Error::NotDefinite {
            what: "q".into(),
            smallest_eigenvalue: -0.25,
            semidefinite: true,
        };
        assert_eq!(
            e.to_string(),
            "q is not positive semidefinite (smallest eigenvalue -0.25)"
        );
    }

    #[test]
    fn form_names_other_fields_so_bindings_can_rename_them() {
        let e = Error::form(
            "observation.noise_variance",
            true,
            alloc::vec![
                Phrase::text("and "),
                Phrase::path("observation.noise_cov"),
                Phrase::text(" are alternatives (use "),
                Phrase::name("noise_cov"),
                Phrase::text(")"),
            ],
        );
        assert!(e.is_wrong_kind());
        assert_eq!(
            e.to_string(),
            "observation.noise_variance and observation.noise_cov are alternatives (use noise_cov)"
        );
        let upper = |s: &str| s.to_uppercase();
        let e = e
            .within("options")
            .map_paths(upper)
            .map_names(|s| s.replace('_', "-"));
        assert_eq!(
            e.to_string(),
            "OPTIONS.OBSERVATION.NOISE_VARIANCE and OPTIONS.OBSERVATION.NOISE_COV are alternatives (use noise-cov)"
        );
        let e = Error::form("gain[1]", false, alloc::vec![Phrase::text("has length 1")]);
        assert!(!e.is_wrong_kind());
        assert_eq!(e.to_string(), "gain[1] has length 1");
        let e = Error::form("cov", false, alloc::vec![Phrase::text("[1] has length 1")]);
        assert_eq!(e.to_string(), "cov[1] has length 1");
        assert!(!Error::range("samples", 1, 2, 3).is_wrong_kind());
    }

    #[test]
    fn probability_check_rejects_nan_and_out_of_range() {
        assert!(check_probabilities("r", &[0.0, 0.5, 1.0]).is_ok());
        for bad in [f64::NAN, -0.1, 1.0 + 1e-12, f64::INFINITY] {
            let e = check_probabilities("r", &[0.2, bad]).unwrap_err();
            assert_eq!(e.field(), "r[1]");
        }
    }

    #[test]
    fn quoted_is_debug_for_ascii_and_printable_text() {
        // every ASCII character, alone and between others
        for b in 0u8..128 {
            let c = char::from(b);
            for s in [c.to_string(), alloc::format!("a{c}b")] {
                assert_eq!(Quoted(&s).to_string(), alloc::format!("{s:?}"), "{b}");
            }
        }
        // C1 controls, and printable text beyond ASCII
        for s in [
            "\u{80}",
            "x\u{9f}y",
            "détection",
            "日本語 ✓",
            "naïve café",
            "∑ λ ∞",
        ] {
            assert_eq!(Quoted(s).to_string(), alloc::format!("{s:?}"), "{s}");
        }
        // where the two differ: a combining mark, which `{:?}` escapes by its Unicode tables
        assert_eq!(Quoted("e\u{301}").to_string(), "\"e\u{301}\"");
        assert_eq!(alloc::format!("{:?}", "e\u{301}"), "\"e\\u{301}\"");
    }
}

//! A filter's configuration checked as a whole before any field alone (issue 26): the
//! dimensions of F, Q, the mixtures, H, R, n_s and the regions against each other, each
//! error naming the field that disagrees and the one it disagrees with, in matrix terms
//! ([`Error::ShapeMismatch`]: `mixture[0].mean has length 4 but transition.f is 2×2`), for
//! the models of `001_0f0df91eee9b30d5.txt` Section V: the transition (44), the Bernoulli
//! density (39), the measurement model N(z; H x, R) and the regions of (51), (63)–(65).

use alloc::string::String;
use alloc::vec::Vec;

use super::{BernoulliFilterOptions, LinearGaussianLikelihood, LinearGaussianTransition};
use crate::error::{Error, Result, Shape};
use crate::gaussian::GaussianMixture;
use crate::regions::{Node, Region};

/// The dimensions of a filter's configuration as a user gave them (before any field is
/// read), checked against each other by [`ConfigShapes::check`]. A matrix given as rows has
/// the shape (rows, length of its first row).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConfigShapes<'a> {
    /// The shape of the transition matrix F (`transition.f`), rows × columns.
    pub f: (usize, usize),
    /// The shape of the process noise covariance Q (`transition.q`), rows × columns.
    pub q: (usize, usize),
    /// The length of each mean of p_{0|0} (`mixture[i].mean`).
    pub mixture: &'a [usize],
    /// The length of each mean of b(x) (`birth.mixture[i].mean`).
    pub birth: &'a [usize],
    /// H and R (`likelihood.h`, `likelihood.r`), when given.
    pub likelihood: Option<((usize, usize), (usize, usize))>,
    /// The number n_s of position components (`position_dims`).
    pub position_dims: usize,
}

impl ConfigShapes<'_> {
    /// The shape of a matrix given as rows: (rows, length of its first row); `[]` is 0 × 0.
    pub fn of_rows(rows: &[Vec<f64>]) -> (usize, usize) {
        (rows.len(), rows.first().map_or(0, Vec::len))
    }

    /// Checks the dimensions against F's: Q n × n, every mean of length n, H with n columns,
    /// R m × m for an H of m rows, n_s ≤ n. F itself (square, not empty) and each field's
    /// values are left to the field's own check.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] naming the field that disagrees (`transition.q`,
    /// `mixture[i].mean`, `birth.mixture[i].mean`, `likelihood.h`, `likelihood.r`,
    /// `position_dims`) and the one it disagrees with (`transition.f`, or `likelihood.h` for
    /// R).
    pub fn check(&self) -> Result<()> {
        let (n, f) = (self.f.0, Shape::Matrix(self.f.0, self.f.1));
        if self.q != (n, n) {
            return Err(Error::shapes(
                "transition.q",
                Shape::Matrix(self.q.0, self.q.1),
                "transition.f",
                f,
            ));
        }
        check_means(
            self.mixture.iter().copied(),
            "mixture",
            n,
            "transition.f",
            f,
        )?;
        check_means(
            self.birth.iter().copied(),
            "birth.mixture",
            n,
            "transition.f",
            f,
        )?;
        if let Some((h, r)) = self.likelihood {
            if h.1 != n {
                return Err(Error::shapes(
                    "likelihood.h",
                    Shape::Matrix(h.0, h.1),
                    "transition.f",
                    f,
                ));
            }
            if r != (h.0, h.0) {
                return Err(Error::shapes(
                    "likelihood.r",
                    Shape::Matrix(r.0, r.1),
                    "likelihood.h",
                    Shape::Matrix(h.0, h.1),
                ));
            }
        }
        // n_s beyond its own range is its own error (`position_dims must be an integer in …`)
        if self.position_dims > n && self.position_dims <= super::MAX_POSITION_DIMS {
            return Err(Error::shapes(
                "position_dims",
                Shape::Value(self.position_dims),
                "transition.f",
                f,
            ));
        }
        Ok(())
    }
}

/// The mean length of every component of `mixture`.
/// F and Q as a user writes them, unchecked (`transition: { F, Q }` with the paper's
/// capitals): the form a binding reads, so that their shapes are checked against the rest of
/// the configuration before the transition is built (in Rust,
/// [`TransitionRows::check_shapes`], then [`TransitionRows::build`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TransitionRows {
    /// The state transition matrix F, n rows of n numbers (x = F x′ + noise).
    #[cfg_attr(feature = "serde", serde(rename = "F"))]
    pub f: Vec<Vec<f64>>,
    /// The process noise covariance Q, n rows of n numbers, symmetric positive semidefinite.
    #[cfg_attr(feature = "serde", serde(rename = "Q"))]
    pub q: Vec<Vec<f64>>,
}

/// H and R as a user writes them, unchecked (`likelihood: { H, R }`): the linear-Gaussian
/// likelihood N(z; H x, R) of vector measurements before it is built
/// ([`LikelihoodRows::build`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LikelihoodRows {
    /// The measurement matrix H, m rows of n numbers (z = H x + noise).
    #[cfg_attr(feature = "serde", serde(rename = "H"))]
    pub h: Vec<Vec<f64>>,
    /// The measurement noise covariance R, m rows of m numbers, symmetric positive definite.
    #[cfg_attr(feature = "serde", serde(rename = "R"))]
    pub r: Vec<Vec<f64>>,
}

impl TransitionRows {
    /// The transition ([`LinearGaussianTransition::from_rows`]).
    ///
    /// # Errors
    /// As [`LinearGaussianTransition::from_rows`].
    pub fn build(&self) -> Result<LinearGaussianTransition> {
        LinearGaussianTransition::from_rows(&self.f, &self.q)
    }

    /// Checks the shapes of F and Q against the other fields of a configuration as given:
    /// the means of `mixture` and of the birth density `birth`, H and R of `likelihood`,
    /// and n_s = `position_dims` (0: not checked, as [`ConfigShapes::check`]).
    ///
    /// # Errors
    /// As [`ConfigShapes::check`].
    pub fn check_shapes(
        &self,
        mixture: &GaussianMixture,
        birth: &GaussianMixture,
        likelihood: Option<&LikelihoodRows>,
        position_dims: usize,
    ) -> Result<()> {
        let mixture: Vec<usize> = mean_lengths(mixture).collect();
        let birth: Vec<usize> = mean_lengths(birth).collect();
        ConfigShapes {
            f: ConfigShapes::of_rows(&self.f),
            q: ConfigShapes::of_rows(&self.q),
            mixture: &mixture,
            birth: &birth,
            likelihood: likelihood
                .map(|l| (ConfigShapes::of_rows(&l.h), ConfigShapes::of_rows(&l.r))),
            position_dims,
        }
        .check()
    }
}

impl LikelihoodRows {
    /// The likelihood ([`LinearGaussianLikelihood::from_rows`]).
    ///
    /// # Errors
    /// As [`LinearGaussianLikelihood::from_rows`].
    pub fn build(&self) -> Result<LinearGaussianLikelihood> {
        LinearGaussianLikelihood::from_rows(&self.h, &self.r)
    }
}

fn mean_lengths(mixture: &GaussianMixture) -> impl Iterator<Item = usize> + '_ {
    mixture.components().iter().map(|(_, g)| g.dim())
}

/// Checks the whole of a built configuration: as [`ConfigShapes::check`], then every region
/// (field of view, exclusions) against n_s ([`check_region`]).
///
/// # Errors
/// As [`ConfigShapes::check`] and [`check_region`].
pub(crate) fn check_config(config: &BernoulliFilterOptions) -> Result<()> {
    let n = config.transition.dim();
    let mixture: Vec<usize> = mean_lengths(&config.mixture).collect();
    let birth: Vec<usize> = mean_lengths(&config.birth.mixture).collect();
    let likelihood = config.likelihood.as_ref().map(|l| {
        let (h, r) = (l.h(), l.r());
        ((h.nrows(), h.ncols()), (r.nrows(), r.ncols()))
    });
    ConfigShapes {
        f: (n, n),
        q: (n, n),
        mixture: &mixture,
        birth: &birth,
        likelihood,
        position_dims: config.position_dims,
    }
    .check()?;
    let ns = config.position_dims;
    if let Some(fov) = &config.detection.fov {
        check_region(fov, "detection.fov", ns)?;
    }
    for (i, e) in config.exclusions.iter().enumerate() {
        check_region(e, &alloc::format!("exclusions[{i}]"), ns)?;
    }
    Ok(())
}

/// Checks that every mean length in `lengths` (of the mixture at `path`) is `n`, the
/// dimension of `other` (of shape `other_shape`).
///
/// # Errors
/// [`Error::ShapeMismatch`] naming `path[i].mean` and `other`.
pub(crate) fn check_means(
    lengths: impl Iterator<Item = usize>,
    path: &str,
    n: usize,
    other: &str,
    other_shape: Shape,
) -> Result<()> {
    for (i, len) in lengths.enumerate() {
        if len != n {
            return Err(Error::shapes(
                alloc::format!("{path}[{i}].mean"),
                Shape::Length(len),
                other,
                other_shape,
            ));
        }
    }
    Ok(())
}

/// The field of `region` that carries its dimension, as a path below the region
/// (`box.min`, `ball.center`, `polygon[0]`, `union[0].box.min`, …), and that dimension.
pub(crate) fn region_dim_field(region: &Region) -> (String, usize) {
    let below = |name: &str, inner: &Region| {
        let (p, d) = region_dim_field(inner);
        (alloc::format!("{name}.{p}"), d)
    };
    match region.node() {
        Node::Box(_) => ("box.min".into(), region.dim()),
        Node::Ball(_) => ("ball.center".into(), region.dim()),
        Node::Polygon(_) => ("polygon[0]".into(), 2),
        Node::Union(m) | Node::Intersection(m) => {
            let name = match region.node() {
                Node::Union(_) => "union[0]",
                _ => "intersection[0]",
            };
            match m.first() {
                Some(first) => below(name, first),
                None => (name.into(), 0),
            }
        }
        Node::Complement(r) => below("complement", r),
    }
}

/// Checks that the region at `path` has dimension n_s = `position_dims`.
///
/// # Errors
/// [`Error::ShapeMismatch`] naming the region's field that carries its dimension
/// (`reports[0].box.min`, [`region_dim_field`]) and `position_dims`.
pub(crate) fn check_region(region: &Region, path: &str, position_dims: usize) -> Result<()> {
    if region.dim() == position_dims {
        return Ok(());
    }
    let (field, dim) = region_dim_field(region);
    Err(Error::shapes(
        alloc::format!("{path}.{field}"),
        Shape::Length(dim),
        "position_dims",
        Shape::Value(position_dims),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn eq44_q_must_be_f_sized() {
        let s = ConfigShapes {
            f: (4, 4),
            q: (2, 2),
            ..Default::default()
        };
        assert_eq!(
            s.check().unwrap_err().to_string(),
            "transition.q is 2×2 but transition.f is 4×4"
        );
    }

    #[test]
    fn eq39_means_h_r_and_position_dims_against_f() {
        let means = [4];
        let s = ConfigShapes {
            f: (2, 2),
            q: (2, 2),
            mixture: &means,
            ..Default::default()
        };
        assert_eq!(
            s.check().unwrap_err().to_string(),
            "mixture[0].mean has length 4 but transition.f is 2×2"
        );
        let s = ConfigShapes {
            f: (4, 4),
            q: (4, 4),
            birth: &means[..0],
            likelihood: Some(((2, 3), (2, 2))),
            ..Default::default()
        };
        assert_eq!(
            s.check().unwrap_err().to_string(),
            "likelihood.h is 2×3 but transition.f is 4×4"
        );
        let s = ConfigShapes {
            likelihood: Some(((2, 4), (3, 3))),
            ..s
        };
        assert_eq!(
            s.check().unwrap_err().to_string(),
            "likelihood.r is 3×3 but likelihood.h is 2×4"
        );
        let s = ConfigShapes {
            likelihood: None,
            position_dims: 6,
            ..s
        };
        assert_eq!(
            s.check().unwrap_err().to_string(),
            "position_dims is 6 but transition.f is 4×4"
        );
    }

    #[test]
    fn eq63_a_region_names_the_field_that_carries_its_dimension() {
        let b = Region::axis_box(&[0.0; 3], &[1.0; 3], "b").unwrap();
        let e = check_region(&b, "reports[0]", 2).unwrap_err();
        assert_eq!(
            e.to_string(),
            "reports[0].box.min has length 3 but position_dims is 2"
        );
        let d = Region::ball(&[0.0, 0.0], 1.0, "d").unwrap();
        let u = Region::complement(Region::union(alloc::vec![d], "u").unwrap());
        let e = check_region(&u, "detection.fov", 3).unwrap_err();
        assert_eq!(e.field(), "detection.fov.complement.union[0].ball.center");
        assert!(check_region(&u, "detection.fov", 2).is_ok());
    }
}

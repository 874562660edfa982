//! A Gaussian mixture's density over a grid of positions: the PHD heat map of Fig. 9 of
//! `001_…`.

use alloc::vec;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture};

use super::placement::{GridAxis, MAX_GRID_AXIS, MAX_GRID_CELLS};

fn validate(axis: &GridAxis, name: &str) -> Result<()> {
    if !axis.min.is_finite() {
        return Err(Error::parameter(
            alloc::format!("{name}[0]"),
            axis.min,
            "finite",
        ));
    }
    if !(axis.max.is_finite() && axis.max >= axis.min) {
        return Err(Error::parameter(
            alloc::format!("{name}[1]"),
            axis.max,
            "finite and >= the minimum",
        ));
    }
    if axis.count == 0 || axis.count > MAX_GRID_AXIS {
        return Err(Error::parameter(
            alloc::format!("{name}[2]"),
            axis.count as f64,
            "an integer count in [1, 4096]",
        ));
    }
    Ok(())
}

/// The position marginal (first two state components) of every component.
fn position_marginal(mixture: &GaussianMixture) -> Result<GaussianMixture> {
    let mut out = Vec::with_capacity(mixture.len());
    for (j, (w, g)) in mixture.components().iter().enumerate() {
        let what = alloc::format!("mixture[{j}]");
        if g.dim() < 2 {
            return Err(Error::dimension(alloc::format!("{what}.mean"), 2, g.dim()));
        }
        let marginal = if g.dim() == 2 {
            g.clone()
        } else {
            let m = g.mean();
            let p = g.cov();
            Gaussian::new(
                DVector::from_column_slice(&[m[0], m[1]]),
                DMatrix::from_row_slice(2, 2, &[p[(0, 0)], p[(0, 1)], p[(1, 0)], p[(1, 1)]]),
                &what,
            )?
        };
        out.push((*w, marginal));
    }
    GaussianMixture::new(out, "mixture")
}

/// `Ok` if the density's largest possible value, Σ_j w_j N(m_j; m_j, P_j) (every component at
/// its peak), is a finite double: then no grid value and no partial sum overflows (a value
/// past the largest double made the compensated sum ∞ − ∞ = NaN).
fn check_peak(mixture: &GaussianMixture) -> Result<()> {
    let mut total = 0.0;
    for (j, (w, g)) in mixture.components().iter().enumerate() {
        let peak = g.pdf(g.mean().as_slice());
        if !peak.is_finite() {
            return Err(Error::parameter(
                alloc::format!("mixture[{j}].cov"),
                peak,
                "a covariance whose peak density 1/√det(2πP) is finite",
            ));
        }
        total += w * peak;
        if !total.is_finite() {
            return Err(Error::parameter(
                alloc::format!("mixture[{j}].weight"),
                *w,
                "such that the mixture's peak density Σ weight × 1/√det(2πP) is below 1.8e308 \
                 (the largest double)",
            ));
        }
    }
    Ok(())
}

/// Σ_j w_j N(s; m_j, P_j) at every grid position s = (x_i, y_j), row-major with y as the outer
/// index (entry `j·nx + i`), by [`GaussianMixture::pdf`] at each point. For components of
/// more than two dimensions the density is that of the position marginal (the first two
/// state components, as in Section III of `001_…`). With a multi-Bernoulli's weights
/// w_j = r⁽ʲ⁾ this is its PHD (99), the heat map of Fig. 9.
///
/// # Errors
/// Using the Rust field names: [`Error::DimensionMismatch`] naming `mixture[j].mean`
/// for a component of fewer than 2 dimensions; [`Error::InvalidParameter`] naming
/// `grid.x[0…2]` / `grid.y[0…2]` (min finite, max finite and ≥ min, count in [1, 4096]);
/// [`Error::Unsupported`] naming `grid` for more than [`MAX_GRID_CELLS`] positions;
/// [`Error::InvalidParameter`] naming `mixture[j].weight` when Σ_j w_j N(m_j; m_j, P_j), the
/// largest value the density could take, exceeds the largest double (about 1.8e308; the
/// values would overflow), or `mixture[j].cov` for a covariance whose peak density
/// 1/√det(2πP) does.
///
/// # Examples
/// ```
/// use fisst::fov::{mixture_density_grid, GridAxis};
/// use fisst::gaussian::{Gaussian, GaussianMixture};
/// let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "p")?;
/// let phd = GaussianMixture::new(vec![(0.5, g)], "mixture")?;
/// let axis = GridAxis { min: -1.0, max: 1.0, count: 3 };
/// let d = mixture_density_grid(&phd, axis, axis)?;
/// assert!((d[4] - 0.5 / (2.0 * std::f64::consts::PI)).abs() < 1e-16);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn mixture_density_grid(
    mixture: &GaussianMixture,
    x: GridAxis,
    y: GridAxis,
) -> Result<Vec<f64>> {
    let mixture = position_marginal(mixture)?;
    check_peak(&mixture)?;
    validate(&x, "grid.x")?;
    validate(&y, "grid.y")?;
    let cells = x.count * y.count;
    if cells > MAX_GRID_CELLS {
        return Err(Error::Unsupported {
            what: "grid".into(),
            reason: "more than 2^22 positions",
        });
    }
    let mut out = vec![0.0; cells];
    for (j, row) in out.chunks_exact_mut(x.count).enumerate() {
        let yj = y.centre(j);
        for (i, v) in row.iter_mut().enumerate() {
            *v = mixture.pdf(&[x.centre(i), yj]);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_the_components_and_marginalises() {
        // 3D components whose position marginals are a2 and b2.
        let a = Gaussian::from_slices(
            &[1.0, -1.0, 0.5],
            &[0.5, 0.1, 0.0, 0.1, 0.3, 0.1, 0.0, 0.1, 1.0],
            "p",
        )
        .unwrap();
        let a2 = Gaussian::from_slices(&[1.0, -1.0], &[0.5, 0.1, 0.1, 0.3], "p").unwrap();
        let b = Gaussian::from_slices(
            &[0.0, 2.0, 7.0],
            &[1.0, -0.2, 0.3, -0.2, 0.4, 0.0, 0.3, 0.0, 2.0],
            "p",
        )
        .unwrap();
        let b2 = Gaussian::from_slices(&[0.0, 2.0], &[1.0, -0.2, -0.2, 0.4], "p").unwrap();
        let mix = GaussianMixture::new(vec![(0.7, a), (0.4, b)], "mixture").unwrap();
        let gx = GridAxis {
            min: -2.0,
            max: 3.0,
            count: 11,
        };
        let gy = GridAxis {
            min: -3.0,
            max: 4.0,
            count: 8,
        };
        let d = mixture_density_grid(&mix, gx, gy).unwrap();
        assert_eq!(d.len(), 88);
        for j in 0..8 {
            for i in 0..11 {
                let s = [gx.centre(i), gy.centre(j)];
                let want = 0.7 * a2.pdf(&s) + 0.4 * b2.pdf(&s);
                assert!((d[j * 11 + i] - want).abs() <= 1e-15 * want.max(1e-300) + 1e-300);
            }
        }
    }

    /// Issue 26 (point 7): weight × peak density past the largest double gave NaN cells
    /// (the compensated sum's ∞ − ∞); it is an error naming the weight, and a weight just
    /// within the bound gives finite values.
    #[test]
    fn fig9_a_density_past_the_largest_double_is_an_error_not_nan() {
        let ax = GridAxis {
            min: 0.0,
            max: 0.0,
            count: 1,
        };
        let g = Gaussian::from_slices(&[0.0, 0.0], &[0.001, 0.0, 0.0, 0.001], "p").unwrap();
        let mix = GaussianMixture::new(vec![(1e308, g.clone())], "mixture").unwrap();
        let e = mixture_density_grid(&mix, ax, ax).unwrap_err();
        assert_eq!(e.field(), "mixture[0].weight");
        let two = GaussianMixture::new(vec![(1e305, g.clone()), (1e306, g.clone())], "m").unwrap();
        let v = mixture_density_grid(&two, ax, ax).unwrap()[0];
        assert!((v / (1.1e306 * g.pdf(&[0.0, 0.0])) - 1.0).abs() < 1e-15);
        let many = GaussianMixture::new(vec![(1e305, g.clone()); 12], "m").unwrap();
        assert_eq!(
            mixture_density_grid(&many, ax, ax).unwrap_err().field(),
            "mixture[11].weight"
        );
        let sharp = Gaussian::from_slices(&[0.0, 0.0], &[1e-320, 0.0, 0.0, 1e-320], "p").unwrap();
        let mix = GaussianMixture::new(vec![(0.0, sharp)], "mixture").unwrap();
        let e = mixture_density_grid(&mix, ax, ax).unwrap_err();
        assert_eq!(e.field(), "mixture[0].cov");
        let ok = GaussianMixture::new(vec![(1e300, g.clone())], "mixture").unwrap();
        assert!(mixture_density_grid(&ok, ax, ax).unwrap()[0].is_finite());
    }

    #[test]
    fn validation_names_the_fields() {
        let ax = GridAxis {
            min: 0.0,
            max: 1.0,
            count: 3,
        };
        let g1 = Gaussian::from_slices(&[0.0], &[1.0], "p").unwrap();
        let mix = GaussianMixture::new(vec![(1.0, g1)], "mixture").unwrap();
        let e = mixture_density_grid(&mix, ax, ax).unwrap_err();
        assert_eq!(e.field(), "mixture[0].mean");
        let empty = GaussianMixture::default();
        assert_eq!(mixture_density_grid(&empty, ax, ax).unwrap(), vec![0.0; 9]);
        let bad = GridAxis { count: 0, ..ax };
        let e = mixture_density_grid(&empty, bad, ax).unwrap_err();
        assert_eq!(e.field(), "grid.x[2]");
        let bad = GridAxis { max: -1.0, ..ax };
        let e = mixture_density_grid(&empty, ax, bad).unwrap_err();
        assert_eq!(e.field(), "grid.y[1]");
        let big = GridAxis { count: 4096, ..ax };
        let e = mixture_density_grid(&empty, big, big).unwrap_err();
        assert_eq!(e.field(), "grid");
    }
}

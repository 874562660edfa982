//! Smallest enclosing balls and mean shift: the geometry of point sets.
//!
//! - [`smallest_enclosing_ball`]: E. Welzl, "Smallest enclosing disks (balls and ellipsoids)",
//!   in *New Results and New Trends in Computer Science*, LNCS 555, Springer 1991, 359–370,
//!   in the move-to-front form of B. Gärtner, "Fast and robust smallest enclosing balls",
//!   ESA 1999, LNCS 1643, 325–338; with [`circumcentre`], the ball through up to d + 1 points.
//! - [`mean_shift`]: the flat-kernel mean shift of K. Fukunaga & L. D. Hostetler, "The
//!   estimation of the gradient of a density function", *IEEE Trans. Inf. Theory* 21 (1975)
//!   32–40, as analysed by D. Comaniciu & P. Meer, "Mean shift: a robust approach toward
//!   feature space analysis", *IEEE Trans. PAMI* 24 (2002) 603–619.
//!
//! Both serve the MMUC estimate of `000_…` for particle densities
//! ([`SpatialDensity::mmuc`](crate::bernoulli::SpatialDensity::mmuc)); their arithmetic is the
//! one that estimate has always used.

use alloc::vec;
use alloc::vec::Vec;

use super::fns;

/// ‖x − y‖².
fn dist2(x: &[f64], y: &[f64]) -> f64 {
    x.iter().zip(y).map(|(a, b)| (a - b) * (a - b)).sum()
}

/// The centre of the sphere through `pts` that lies in their affine hull, and its squared
/// radius; `None` for affinely dependent points.
pub fn circumcentre(pts: &[&[f64]]) -> Option<(Vec<f64>, f64)> {
    let x0 = pts.first()?;
    let k = pts.len() - 1;
    if k == 0 {
        return Some((x0.to_vec(), 0.0));
    }
    let v: Vec<Vec<f64>> = pts[1..]
        .iter()
        .map(|x| x.iter().zip(x0.iter()).map(|(a, b)| a - b).collect())
        .collect();
    // Solve (2 V Vᵀ) α = (‖v_i‖²) by Gaussian elimination with partial pivoting.
    let mut m: Vec<Vec<f64>> = (0..k)
        .map(|i| {
            let mut row: Vec<f64> = (0..k)
                .map(|j| 2.0 * v[i].iter().zip(&v[j]).map(|(a, b)| a * b).sum::<f64>())
                .collect();
            row.push(v[i].iter().map(|a| a * a).sum());
            row
        })
        .collect();
    let scale = m
        .iter()
        .map(|r| fns::abs(r[0]))
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    for col in 0..k {
        let piv = (col..k).max_by(|&a, &b| fns::abs(m[a][col]).total_cmp(&fns::abs(m[b][col])))?;
        if fns::abs(m[piv][col]) <= 1e-12 * scale {
            return None;
        }
        m.swap(col, piv);
        let (top, rest) = m.split_at_mut(col + 1);
        let pivot_row = &top[col];
        for row in rest.iter_mut() {
            let factor = row[col] / pivot_row[col];
            for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                *x -= factor * p;
            }
        }
    }
    let mut alpha = vec![0.0; k];
    for row in (0..k).rev() {
        let mut s = m[row][k];
        for c in row + 1..k {
            s -= m[row][c] * alpha[c];
        }
        alpha[row] = s / m[row][row];
    }
    let mut o = x0.to_vec();
    for (a, vi) in alpha.iter().zip(&v) {
        for (oj, vij) in o.iter_mut().zip(vi) {
            *oj += a * vij;
        }
    }
    let r2 = dist2(&o, x0);
    Some((o, r2))
}

/// The smallest ball enclosing `pts` (Welzl 1991, in Gärtner's move-to-front form, recursion
/// depth ≤ d + 1): its centre and squared radius; `None` for no points. A point counts as
/// inside when its squared distance is within a relative 10⁻¹² of the squared radius.
///
/// ```
/// use fisst::math::geometry::smallest_enclosing_ball;
/// let pts: [&[f64]; 3] = [&[0.0, 0.0], &[2.0, 0.0], &[1.0, 0.5]];
/// let (c, r2) = smallest_enclosing_ball(&pts).unwrap();
/// assert!((c[0] - 1.0).abs() < 1e-15 && c[1].abs() < 1e-15 && (r2 - 1.0).abs() < 1e-15);
/// ```
pub fn smallest_enclosing_ball(pts: &[&[f64]]) -> Option<(Vec<f64>, f64)> {
    let first = pts.first()?;
    let d = first.len();
    let mut list: Vec<&[f64]> = pts.to_vec();
    let mut boundary: Vec<&[f64]> = Vec::with_capacity(d + 1);
    let n = list.len();
    Some(move_to_front(&mut list, n, &mut boundary, d))
}

fn move_to_front<'a>(
    list: &mut Vec<&'a [f64]>,
    end: usize,
    boundary: &mut Vec<&'a [f64]>,
    d: usize,
) -> (Vec<f64>, f64) {
    let mut ball = match circumcentre(boundary) {
        Some(b) => b,
        None if boundary.is_empty() => (vec![0.0; d], -1.0),
        // Dependent boundary points (from rounding): fall back to the first one's ball.
        None => (boundary[0].to_vec(), 0.0),
    };
    if boundary.len() == d + 1 {
        return ball;
    }
    let mut i = 0;
    while i < end {
        let pt = list[i];
        if ball.1 < 0.0 || dist2(pt, &ball.0) > ball.1 * (1.0 + 1e-12) {
            boundary.push(pt);
            ball = move_to_front(list, i, boundary, d);
            boundary.pop();
            let moved = list.remove(i);
            list.insert(0, moved);
        }
        i += 1;
    }
    ball
}

/// Flat-kernel mean shift (Fukunaga & Hostetler 1975; Comaniciu & Meer 2002) from `start`:
/// move the centre c to the `weights`-weighted mean of the `points` within the closed ball of
/// radius `radius` about it, until a move is at most 10⁻¹² `radius` long, the ball holds no
/// weight, or `max_iter` moves. Returns the last centre. With the flat kernel the centre climbs
/// to a local maximum of the weight within the ball (Comaniciu & Meer 2002, Theorem 1 with the
/// uniform kernel, whose shadow is the Epanechnikov kernel).
///
/// ```
/// use fisst::math::geometry::mean_shift;
/// let pts: [&[f64]; 3] = [&[0.0], &[1.0], &[2.0]];
/// let c = mean_shift(&pts, &[1.0, 1.0, 1.0], &[0.2], 1.5, 30);
/// assert_eq!(c, vec![1.0]);
/// ```
pub fn mean_shift(
    points: &[&[f64]],
    weights: &[f64],
    start: &[f64],
    radius: f64,
    max_iter: usize,
) -> Vec<f64> {
    let r2 = radius * radius;
    let mut c = start.to_vec();
    for _ in 0..max_iter {
        let mut acc = vec![0.0; start.len()];
        let mut w = 0.0;
        for (x, wi) in points.iter().zip(weights) {
            if dist2(x, &c) <= r2 {
                w += wi;
                for (a, xk) in acc.iter_mut().zip(x.iter()) {
                    *a += wi * xk;
                }
            }
        }
        if w <= 0.0 {
            break;
        }
        let next: Vec<f64> = acc.iter().map(|a| a / w).collect();
        let moved = dist2(&next, &c);
        c = next;
        if moved <= 1e-24 * r2 {
            break;
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::{seeded, uniform};

    fn ball(pts: &[&[f64]]) -> (Vec<f64>, f64) {
        smallest_enclosing_ball(pts).unwrap()
    }

    #[test]
    fn ball_of_two_points_is_their_diameter() {
        let (c, r2) = ball(&[&[1.0, 2.0, 3.0], &[3.0, 2.0, -1.0]]);
        assert_eq!(c, vec![2.0, 2.0, 1.0]);
        assert!((r2 - 5.0).abs() < 1e-14, "{r2}");
        assert!(smallest_enclosing_ball(&[]).is_none());
        assert_eq!(ball(&[&[4.0]]), (vec![4.0], 0.0));
    }

    #[test]
    fn ball_of_an_equilateral_triangle_is_its_circumcircle() {
        let h = fns::sqrt(3.0) / 2.0;
        let pts: [&[f64]; 3] = [&[0.0, 0.0], &[1.0, 0.0], &[0.5, h]];
        let (c, r2) = ball(&pts);
        // Centre at the centroid (½, √3/6), radius 1/√3.
        assert!(
            (c[0] - 0.5).abs() < 1e-15 && (c[1] - h / 3.0).abs() < 1e-15,
            "{c:?}"
        );
        assert!((r2 - 1.0 / 3.0).abs() < 1e-15, "{r2}");
        // An obtuse triangle's ball is the circle on its longest side instead.
        let (c, r2) = ball(&[&[0.0, 0.0], &[4.0, 0.0], &[2.0, 0.5]]);
        assert!((c[0] - 2.0).abs() < 1e-15 && c[1].abs() < 1e-15 && (r2 - 4.0).abs() < 1e-14);
    }

    #[test]
    fn ball_of_random_points_holds_them_all_with_some_on_its_boundary() {
        let mut rng = seeded(5);
        for d in 1..=4 {
            let raw: Vec<Vec<f64>> = (0..200)
                .map(|_| (0..d).map(|_| 2.0 * uniform(&mut rng) - 1.0).collect())
                .collect();
            let pts: Vec<&[f64]> = raw.iter().map(|p| p.as_slice()).collect();
            let (c, r2) = ball(&pts);
            let d2: Vec<f64> = pts.iter().map(|p| dist2(p, &c)).collect();
            assert!(d2.iter().all(|&x| x <= r2 * (1.0 + 1e-9)), "d = {d}");
            let on = d2.iter().filter(|&&x| x >= r2 * (1.0 - 1e-9)).count();
            // At least two points span the ball (the minimal ball has 2 ≤ k ≤ d + 1 of them).
            assert!((2..=d + 1).contains(&on), "d = {d}: {on} on the boundary");
            // No bigger than the ball about the cube [−1, 1]^d.
            assert!(r2 > 0.0 && r2 <= d as f64, "d = {d}: r² = {r2}");
        }
    }

    #[test]
    fn mean_shift_climbs_to_the_mode_of_a_symmetric_set() {
        // A symmetric cluster about (1, −2): the centre of a grid, plus far-away outliers.
        let mut raw: Vec<Vec<f64>> = Vec::new();
        for i in -3..=3 {
            for j in -3..=3 {
                raw.push(vec![1.0 + 0.1 * i as f64, -2.0 + 0.1 * j as f64]);
            }
        }
        raw.push(vec![10.0, 10.0]);
        raw.push(vec![-10.0, 5.0]);
        let pts: Vec<&[f64]> = raw.iter().map(|p| p.as_slice()).collect();
        let w = vec![1.0; pts.len()];
        let c = mean_shift(&pts, &w, &[1.25, -1.8], 1.0, 100);
        assert!(
            (c[0] - 1.0).abs() < 1e-12 && (c[1] + 2.0).abs() < 1e-12,
            "{c:?}"
        );
        // No weight within the ball: the start is returned.
        assert_eq!(
            mean_shift(&pts, &w, &[50.0, 50.0], 1.0, 100),
            vec![50.0, 50.0]
        );
    }
}

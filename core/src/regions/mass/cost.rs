//! A cost model of [`Region::gaussian_mass`]: the native time one Gaussian mass in a region
//! takes, so that callers (the bindings' work budgets, the field-of-view pmfs of Section VI
//! of `001_…`) can refuse work that would take too long before doing it.

use super::{Node, Region};

impl Region {
    /// An estimate of the native cost of one [`Region::gaussian_mass`] in this region, in
    /// microseconds, by the method the mass uses (see there):
    ///
    /// - a box of at most 2 dimensions (the bivariate rectangle) or a 1D ball (intervals):
    ///   1 µs;
    /// - a polygon (the ray method): 150 + 10 µs per vertex;
    /// - a ball of n ≥ 2 dimensions: 150 · 150^(n − 2) µs; a box of n ≥ 3 dimensions:
    ///   150^(n − 2) µs (each nested quadrature level multiplies by about 150);
    /// - a union or intersection: the sum of its members, at least 150 µs (the ray method);
    /// - a complement: the cost of what it complements.
    ///
    /// Calibrated by timing native release builds: a 2D box ~1 µs, a 2D disc or a small
    /// polygon ~150–200 µs, a 3D box ~100 µs, a 3D ball ~20 ms; each extra dimension
    /// multiplies by ~150.
    ///
    /// # Examples
    /// ```
    /// use fisst::regions::Region;
    /// let disc = Region::ball(&[0.0, 0.0], 1.0, "fov")?;
    /// assert_eq!(disc.mass_cost_us(), 150.0);
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn mass_cost_us(&self) -> f64 {
        // 150^(dim − 2) by products (`powi` is std-only; exact while 150^k < 2^53, k ≤ 7)
        let nested = |dim: usize| (2..dim).fold(1.0, |a: f64, _| a * 150.0);
        match self.node() {
            Node::Box(b) if b.dim() <= 2 => 1.0,
            Node::Box(b) => nested(b.dim()),
            Node::Polygon(v) => 150.0 + 10.0 * v.vertices().len() as f64,
            Node::Ball(d) if d.dim() <= 1 => 1.0,
            Node::Ball(d) => 150.0 * nested(d.dim()),
            Node::Union(m) | Node::Intersection(m) => {
                m.iter().map(Region::mass_cost_us).sum::<f64>().max(150.0)
            }
            Node::Complement(r) => r.mass_cost_us(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    #[test]
    fn eq8_mass_cost_follows_the_method_of_each_region() {
        let b2 = Region::axis_box(&[0.0, 0.0], &[1.0, 1.0], "b").unwrap();
        let b3 = Region::axis_box(&[0.0; 3], &[1.0; 3], "b").unwrap();
        let d1 = Region::ball(&[0.0], 1.0, "d").unwrap();
        let d3 = Region::ball(&[0.0; 3], 1.0, "d").unwrap();
        let tri = Region::polygon(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], "p").unwrap();
        assert_eq!(b2.mass_cost_us(), 1.0);
        assert_eq!(b3.mass_cost_us(), 150.0);
        assert_eq!(d1.mass_cost_us(), 1.0);
        assert_eq!(d3.mass_cost_us(), 22_500.0);
        assert_eq!(tri.mass_cost_us(), 180.0);
        let u = Region::union(vec![b2.clone(), b2.clone()], "u").unwrap();
        assert_eq!(u.mass_cost_us(), 150.0);
        let u = Region::union(vec![tri.clone(), b2.clone()], "u").unwrap();
        assert_eq!(u.mass_cost_us(), 181.0);
        let i = Region::intersection(vec![tri.clone(), tri], "i").unwrap();
        assert_eq!(i.mass_cost_us(), 360.0);
        assert_eq!(Region::complement(d3).mass_cost_us(), 22_500.0);
    }
}

//! Multi-object particles (11) of paper `004`: each particle a finite set of planar object
//! states, with a weight; initialisation from the first scan along the range arcs (Sec. 5.2);
//! the MAP cardinality (22) and the per-cardinality mean estimate.

use alloc::vec;
use alloc::vec::Vec;

use rand::Rng;

use crate::gaussian::normal;
use crate::math::fns::{cos, sin};
use crate::math::linear_assignment;
use crate::math::rng::{index, uniform};

/// A planar object state [x, y] (the case study's single-object state space, Sec. 5.1).
pub type State = [f64; 2];

/// The axis-aligned surveillance area 𝒜 = [lo₀, hi₀] × [lo₁, hi₁].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Area {
    /// The lower corner [x, y] of the rectangular area.
    pub lo: State,
    /// The upper corner [x, y] of the rectangular area.
    pub hi: State,
}

impl Area {
    /// Whether `p` lies in the area (boundary included).
    pub fn contains(&self, p: State) -> bool {
        p[0] >= self.lo[0] && p[0] <= self.hi[0] && p[1] >= self.lo[1] && p[1] <= self.hi[1]
    }

    /// `p` moved onto the boundary of the area where it lies outside by at most `tol` in a
    /// coordinate (rounding of a move that ends on an edge); otherwise `p` unchanged.
    pub fn snap_to_edge(&self, p: State, tol: f64) -> State {
        let mut q = p;
        for ((x, lo), hi) in q.iter_mut().zip(self.lo).zip(self.hi) {
            if *x < lo && lo - *x <= tol {
                *x = lo;
            } else if *x > hi && *x - hi <= tol {
                *x = hi;
            }
        }
        q
    }

    /// A uniform draw from the area.
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> State {
        [
            self.lo[0] + (self.hi[0] - self.lo[0]) * uniform(rng),
            self.lo[1] + (self.hi[1] - self.lo[1]) * uniform(rng),
        ]
    }

    /// `p` moved to the nearest point of the area.
    pub fn clamp(&self, p: State) -> State {
        [
            crate::math::fns::clamp(p[0], self.lo[0], self.hi[0]),
            crate::math::fns::clamp(p[1], self.lo[1], self.hi[1]),
        ]
    }
}

/// The particle approximation (11) f(X) ≈ Σ_i w_i δ_{X_i}(X) of a multi-object density.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiObjectParticles {
    /// The particles' object sets X_i, each of at most `max_objects` states.
    pub sets: Vec<Vec<State>>,
    /// The particle weights w_i (normalised).
    pub weights: Vec<f64>,
    /// The largest number n_max of objects in a particle.
    pub max_objects: usize,
}

/// The point estimate of Sec. 5.2 of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004): the MAP cardinality (22) and the mean of the particles
/// with that cardinality.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SetEstimate {
    /// The estimated number of objects n̂ = argmax_n Σ_i w_i Δ[n, n_i] (22) (ties: the smaller
    /// n).
    pub cardinality: usize,
    /// The n̂ estimated object states [x, y]: the mean of the particles with n̂ objects.
    pub states: Vec<State>,
    /// The cardinality pmf: the total particle weight of each cardinality 0 … n_max.
    pub cardinality_pmf: Vec<f64>,
}

impl MultiObjectParticles {
    /// Initialisation from the first scan (Sec. 5.2): particle i draws a cardinality
    /// uniformly in 0 … n_max and a random subset of min(n, m) of the ranges `ranges` measured
    /// from `sensor`; each object of the subset is placed on its range arc (radius z + spread(z)·ε,
    /// angle uniform, redrawn until inside `area`, up to 64 times, then uniform in the area),
    /// the other objects uniformly in the area. Weights are equal.
    pub fn from_ranges<R: Rng + ?Sized>(
        count: usize,
        max_objects: usize,
        area: &Area,
        sensor: State,
        ranges: &[f64],
        spread: impl Fn(f64) -> f64,
        rng: &mut R,
    ) -> Self {
        let mut sets = Vec::with_capacity(count);
        let mut order: Vec<usize> = (0..ranges.len()).collect();
        for _ in 0..count {
            let n = index(rng, max_objects + 1);
            let on_arcs = n.min(ranges.len());
            // Partial Fisher–Yates: the first `on_arcs` entries are a uniform subset.
            for a in 0..on_arcs {
                let b = a + index(rng, order.len() - a);
                order.swap(a, b);
            }
            let mut set = Vec::with_capacity(n);
            for &j in &order[..on_arcs] {
                let z = ranges[j];
                let mut placed = None;
                for _ in 0..64 {
                    let r = z + spread(z) * normal::sample(rng);
                    let phi = core::f64::consts::TAU * uniform(rng);
                    let p = [sensor[0] + r * cos(phi), sensor[1] + r * sin(phi)];
                    if r >= 0.0 && area.contains(p) {
                        placed = Some(p);
                        break;
                    }
                }
                set.push(placed.unwrap_or_else(|| area.sample(rng)));
            }
            while set.len() < n {
                set.push(area.sample(rng));
            }
            sets.push(set);
        }
        let weights = vec![1.0 / count.max(1) as f64; count];
        Self {
            sets,
            weights,
            max_objects,
        }
    }

    /// The number of particles N.
    pub fn len(&self) -> usize {
        self.sets.len()
    }

    /// Whether there are no particles.
    pub fn is_empty(&self) -> bool {
        self.sets.is_empty()
    }

    /// The weight of each cardinality 0 … n_max.
    pub fn cardinality_pmf(&self) -> Vec<f64> {
        let mut pmf = vec![0.0; self.max_objects + 1];
        for (s, &w) in self.sets.iter().zip(&self.weights) {
            if let Some(p) = pmf.get_mut(s.len()) {
                *p += w;
            }
        }
        pmf
    }

    /// The estimate of Sec. 5.2: n̂ by (22), then the weighted mean of the particles with n̂
    /// objects, each particle's objects first put in the order that best matches the first
    /// such particle (a linear assignment on squared distances). The paper relies on the
    /// "self-resolving" of the permutation symmetry by resampling; the alignment makes that
    /// explicit and leaves the set, hence the density, unchanged.
    pub fn estimate(&mut self) -> SetEstimate {
        let pmf = self.cardinality_pmf();
        let mut n_hat = 0;
        for (n, &p) in pmf.iter().enumerate() {
            if p > pmf[n_hat] {
                n_hat = n;
            }
        }
        self.align(n_hat);
        let mut states = vec![[0.0, 0.0]; n_hat];
        let mut total = 0.0;
        for (s, &w) in self.sets.iter().zip(&self.weights) {
            if s.len() == n_hat {
                total += w;
                for (acc, x) in states.iter_mut().zip(s) {
                    acc[0] += w * x[0];
                    acc[1] += w * x[1];
                }
            }
        }
        if total > 0.0 {
            for acc in &mut states {
                acc[0] /= total;
                acc[1] /= total;
            }
        }
        SetEstimate {
            cardinality: n_hat,
            states,
            cardinality_pmf: pmf,
        }
    }

    /// Permutes the objects of every particle with `n` objects to best match the first one.
    pub fn align(&mut self, n: usize) {
        if n < 2 {
            return;
        }
        let Some(first) = self.sets.iter().position(|s| s.len() == n) else {
            return;
        };
        let reference = self.sets[first].clone();
        let mut cost = vec![0.0; n * n];
        for set in self.sets.iter_mut().filter(|s| s.len() == n) {
            for (a, r) in reference.iter().enumerate() {
                for (b, x) in set.iter().enumerate() {
                    cost[a * n + b] = (r[0] - x[0]) * (r[0] - x[0]) + (r[1] - x[1]) * (r[1] - x[1]);
                }
            }
            if let Ok(assignment) = linear_assignment(&cost, n, n) {
                let old = set.clone();
                for (a, b) in assignment.pairs {
                    set[a] = old[b];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::seeded;

    const AREA: Area = Area {
        lo: [0.0, 0.0],
        hi: [1000.0, 1000.0],
    };

    #[test]
    fn alg1_initialisation_puts_objects_on_the_arcs() {
        let mut rng = seeded(1);
        let p = MultiObjectParticles::from_ranges(
            3000,
            4,
            &AREA,
            [0.0, 0.0],
            &[500.0, 800.0],
            |_| 1e-9,
            &mut rng,
        );
        assert_eq!(p.len(), 3000);
        let pmf = p.cardinality_pmf();
        for q in &pmf {
            assert!((q - 0.2).abs() < 0.03, "{pmf:?}");
        }
        for s in &p.sets {
            assert!(s.len() <= 4);
            for x in s {
                assert!(AREA.contains(*x));
            }
            // Cardinality 2: one object on each arc.
            if s.len() == 2 {
                let mut r: Vec<f64> = s.iter().map(|x| libm::hypot(x[0], x[1])).collect();
                r.sort_by(f64::total_cmp);
                assert!((r[0] - 500.0).abs() < 1e-6 && (r[1] - 800.0).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn eq22_estimate_aligns_permuted_particles() {
        let sets = vec![
            vec![[0.0, 0.0], [100.0, 0.0]],
            vec![[101.0, 0.0], [1.0, 0.0]],
            vec![[5.0, 5.0]],
        ];
        let mut p = MultiObjectParticles {
            sets,
            weights: vec![0.4, 0.4, 0.2],
            max_objects: 3,
        };
        let e = p.estimate();
        assert_eq!(e.cardinality, 2);
        assert_eq!(e.states, vec![[0.5, 0.0], [100.5, 0.0]]);
        assert!((e.cardinality_pmf[1] - 0.2).abs() < 1e-15);
    }
}

//! The admissible sensor actions (23) of paper `004`: stay, or move j·ρ₀ along heading
//! ℓ·θ₀ (θ₀ = 2π/N_θ), j = 1 … N_ρ, ℓ = 1 … N_θ; N_ρ = 2, N_θ = 8, ρ₀ = 50 m give 17 options.
//! An action outside the area gets the reward −∞.

use alloc::vec::Vec;

use crate::math::fns::{cos, sin};
use crate::smc::{Area, State};

/// One sensor action u of (23) of Ristic & Vo, "Sensor control for multi-object state-space
/// estimation using random finite sets" (paper 004): stay, or move j·ρ₀ along heading ℓ·θ₀.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Action {
    /// The action's index: 0 for stay, else 1 + (ring − 1)·N_θ + (heading − 1) (0 … 16 in the
    /// paper's grid).
    pub index: usize,
    /// The ring j of the move: 0 (stay) … N_ρ; the move is j·ρ₀ (ρ₀ = 50 m).
    pub ring: usize,
    /// The heading ℓ: 0 for stay, else 1 … N_θ (angle ℓ·θ₀ = ℓ·45° counter-clockwise from +x).
    pub heading: usize,
    /// The sensor's next location [x, y], in m.
    pub position: State,
    /// Whether `position` lies in the area (admissible; not serialised).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub inside: bool,
}

/// The grid of (23).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct ActionGrid {
    /// The number N_ρ of rings of move lengths (2).
    pub rings: usize,
    /// The number N_θ of headings (8).
    pub headings: usize,
    /// The move length ρ₀ of one ring, in m (50 m).
    pub step: f64,
}

impl Default for ActionGrid {
    fn default() -> Self {
        Self {
            rings: 2,
            headings: 8,
            step: 50.0,
        }
    }
}

impl ActionGrid {
    /// The 1 + N_ρ N_θ actions from `from`, stay first, then ring by ring, heading by heading.
    pub fn actions(&self, from: State, area: &Area) -> Vec<Action> {
        let mut out = Vec::with_capacity(1 + self.rings * self.headings);
        out.push(Action {
            index: 0,
            ring: 0,
            heading: 0,
            position: from,
            inside: area.contains(from),
        });
        let theta0 = core::f64::consts::TAU / self.headings as f64;
        for j in 1..=self.rings {
            for l in 1..=self.headings {
                let a = l as f64 * theta0;
                let r = j as f64 * self.step;
                // Snap the rounding of cos/sin at multiples of 90° to exact zeros, so a move
                // along an edge of the area stays on it.
                let snap = |v: f64| if v.abs() < 1e-12 { 0.0 } else { v };
                let p = [from[0] + r * snap(cos(a)), from[1] + r * snap(sin(a))];
                // A move back along a diagonal to an edge or corner lands a rounding error
                // outside it (x = −1.4e-14 for the corner): within 1e-9 of the step, on it.
                let p = area.snap_to_edge(p, 1e-9 * self.step);
                out.push(Action {
                    index: out.len(),
                    ring: j,
                    heading: l,
                    position: p,
                    inside: area.contains(p),
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq23_seventeen_actions_with_corner_exclusions() {
        let area = Area {
            lo: [0.0, 0.0],
            hi: [1000.0, 1000.0],
        };
        let acts = ActionGrid::default().actions([500.0, 500.0], &area);
        assert_eq!(acts.len(), 17);
        assert!(acts.iter().all(|a| a.inside));
        assert_eq!(acts[0].position, [500.0, 500.0]);
        // Heading 2 = 90°, ring 2: 100 m north.
        let a = acts[1 + 8 + 1];
        assert_eq!((a.ring, a.heading), (2, 2));
        assert!((a.position[0] - 500.0).abs() < 1e-9 && (a.position[1] - 600.0).abs() < 1e-9);
        // From the corner: stay, and headings 1 (45°), 2 (90°, along an edge) and 8 (360°,
        // along the other edge) in both rings.
        let acts = ActionGrid::default().actions([0.0, 0.0], &area);
        let inside: Vec<usize> = acts.iter().filter(|a| a.inside).map(|a| a.index).collect();
        assert_eq!(inside, [0, 1, 2, 8, 9, 10, 16]);
    }

    #[test]
    fn eq23_diagonal_move_back_to_the_corner_is_inside() {
        // Found by the page's Node tests: from (70.71…, 70.71…) the 100 m move at 225° ends
        // at x = −1.4e-14 by rounding, and was excluded.
        let area = Area {
            lo: [0.0, 0.0],
            hi: [1000.0, 1000.0],
        };
        let h = 100.0 * core::f64::consts::FRAC_1_SQRT_2;
        let acts = ActionGrid::default().actions([h, h], &area);
        let a = acts[1 + 8 + 4];
        assert_eq!((a.ring, a.heading), (2, 5));
        assert!(a.inside, "{:?}", a.position);
        assert!(a.position[0].abs() < 1e-12 && a.position[1].abs() < 1e-12);
        // A real step outside stays outside.
        let acts = ActionGrid::default().actions([10.0, 10.0], &area);
        assert!(!acts[1 + 8 + 4].inside);
    }
}

//! A polygon in the plane (convex or not).

use alloc::vec::Vec;
use core::cmp::Ordering;

use crate::error::{Error, Result};

use super::predicates::orient2d;

/// The most vertices of one [`Polygon`]: its inclusion test and masses cost time linear in
/// them, and a polygon given by a user (a report, a field of view) is bounded here.
pub const MAX_VERTICES: usize = 1_000;

/// A closed polygon in the first two position components, given by its vertices in order
/// (the edge from the last vertex back to the first closes it).
///
/// - **Orientation**: either; counter-clockwise and clockwise lists give the same region.
/// - **Non-convex** polygons are fine.
/// - **Self-intersecting** polygons use the *even–odd* rule: a point is inside when a ray
///   from it crosses the boundary an odd number of times (a pentagram's centre is outside).
///   For a simple polygon this is the usual interior.
/// - **Boundary**: the region is closed; every point on an edge is inside.
/// - Repeated consecutive vertices (zero-length edges) are allowed and ignored.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    vertices: Vec<[f64; 2]>,
}

impl Polygon {
    /// The polygon with these vertices. `what` names it in errors: `{what}[i]` for vertex i.
    ///
    /// # Errors
    /// [`Error::Count`] naming `what` for more than [`MAX_VERTICES`] vertices;
    /// [`Error::InvalidParameter`] for fewer than 3 vertices, a non-finite coordinate, or
    /// vertices that all lie on one line (zero area; decided exactly).
    pub fn new(vertices: &[[f64; 2]], what: &str) -> Result<Self> {
        Error::check_count(what, "vertices", vertices.len(), 0, MAX_VERTICES)?;
        if vertices.len() < 3 {
            return Err(Error::parameter(
                what,
                vertices.len() as f64,
                "a list of at least 3 vertices",
            ));
        }
        for (i, v) in vertices.iter().enumerate() {
            for (k, &c) in v.iter().enumerate() {
                if !c.is_finite() {
                    return Err(Error::parameter(
                        alloc::format!("{what}[{i}][{k}]"),
                        c,
                        "finite",
                    ));
                }
            }
        }
        let v0 = vertices[0];
        let degenerate = match vertices.iter().find(|v| **v != v0) {
            None => true,
            Some(&v1) => vertices
                .iter()
                .all(|&v| orient2d(v0, v1, v) == Ordering::Equal),
        };
        if degenerate {
            return Err(Error::parameter(
                what,
                0.0,
                "a polygon of nonzero area (not all vertices on one line)",
            ));
        }
        Ok(Self {
            vertices: vertices.to_vec(),
        })
    }

    /// The vertices, in the order given.
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// The dimension: 2.
    pub fn dim(&self) -> usize {
        2
    }

    /// True when `(s[0], s[1])` is inside (even–odd rule) or on an edge. Exact (robust
    /// orientation predicate, no rounding misclassifies a point); `O(vertices)`.
    ///
    /// # Panics
    /// If `s.len() < 2`.
    pub fn contains(&self, s: &[f64]) -> bool {
        let p = [s[0], s[1]];
        let n = self.vertices.len();
        let mut inside = false;
        for i in 0..n {
            let a = self.vertices[i];
            let b = self.vertices[(i + 1) % n];
            let a_above = a[1] > p[1];
            let b_above = b[1] > p[1];
            let on_line_bbox = p[0] >= a[0].min(b[0])
                && p[0] <= a[0].max(b[0])
                && p[1] >= a[1].min(b[1])
                && p[1] <= a[1].max(b[1]);
            if a_above == b_above && !on_line_bbox {
                continue;
            }
            let o = orient2d(a, b, p);
            if o == Ordering::Equal && on_line_bbox {
                return true;
            }
            if a_above != b_above {
                // The edge crosses the horizontal line through p; the crossing is to the
                // right of p when p is left of the upward-directed edge.
                let right = if b_above {
                    o == Ordering::Greater
                } else {
                    o == Ordering::Less
                };
                if right {
                    inside = !inside;
                }
            }
        }
        inside
    }
}

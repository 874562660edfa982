//! The vector bounds of paper 002 without false observations (q = 0 or λ = 0) for any
//! linear-Gaussian sensor (m ≥ 1, or m = 1 with h = 0): the MAP region is all of R^m, w = 1
//! and J'_1 = J_1 = P⁻¹ + HᵀR⁻¹H, so (63) per component is Corollary 3 with [J_1⁻¹]_ii (72).

use alloc::vec::Vec;

use super::zone::Zone;
use super::{VectorBound, VectorModel, check_vector, components, row_major};
use crate::bounds::theorem::{Cardinality, JdeBound, Method, check_result};
use crate::error::Result;

use super::components::gaussian_information_matrix;

/// m > 1 (or h = 0) without false observations: J'_1 = J_1 = P⁻¹ + HᵀR⁻¹H, w = 1.
pub(super) fn bound(m: &VectorModel<'_>) -> Result<VectorBound> {
    let (prior, sensor) = (m.prior, m.sensor);
    let (_, inv) = gaussian_information_matrix(&prior.cov, &sensor.gain, &sensor.noise)
        .map_err(|e| e.within("observation"))?;
    let zone = Zone::clutter_free(m);
    let components = components(&zone, m, &inv, |_, _| 0.0);
    let (assembled, _) = zone.whole(inv.trace(), prior.cov.trace());
    let total = check_result(JdeBound {
        assembled,
        mean_detection: sensor.detection,
        undetected_mean: prior.mean[0],
        undetected_variance: prior.cov.trace(),
        eta: 0.0,
        region: Vec::new(),
        cardinalities: alloc::vec![Cardinality {
            n: 1,
            probability: 1.0,
            w: 1.0,
            inverse_information: inv.trace(),
            clutter_null: 1.0,
            method: Method::ClosedForm,
            error: 0.0,
            w_error: 0.0,
            clutter_null_error: 0.0,
        }],
        error: 0.0,
        regular: true,
    })?;
    check_vector(VectorBound {
        total,
        components,
        inverse_information: row_major(&inv),
    })
}

//! Whether the tolerance band of a four-bar crosses a change of Grashof
//! type. s + l − p − q (shortest plus longest less the other two) is
//! negative where some link turns fully, positive for a triple rocker; a
//! design of the band changes type where it changes sign. Its gradient is
//! ±1 in every length, so its worst-case change Σ tᵢ is exact, whatever
//! the order of the lengths within the band.
//!
//! The limit margin of a cycle ([`limit_margin`](super::limit_margin))
//! sees the same thing from the poses: a crank that stops turning meets a
//! limit position.

use super::{Spread, Tolerances, distance};
use crate::closed_form::FourBar;
use nalgebra::SVector;

/// The margin of a four-bar to a change of Grashof type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GrashofMargin {
    /// s + l − p − q.
    pub sum: f64,
    /// Its gradient by (l1, l2, l3, l4).
    pub gradient: SVector<f64, 4>,
    /// Its spread under the tolerances.
    pub spread: Spread,
    /// |s + l − p − q| / Σ |∂/∂lᵢ| tᵢ: how many times the worst-case
    /// change the margin is.
    pub distance: f64,
}

impl GrashofMargin {
    /// Whether some designs of the band are of another Grashof type:
    /// distance < 1.
    pub fn crosses(&self) -> bool {
        self.distance < 1.0
    }
}

/// The margin of `bar` to a change of Grashof type under `tolerances` on
/// (l1, l2, l3, l4), the order of [`crate::mechanisms::FourBar`]'s
/// parameters.
pub fn grashof_margin(bar: &FourBar, tolerances: &Tolerances<4>) -> GrashofMargin {
    let lengths = [bar.l1, bar.l2, bar.l3, bar.l4];
    let mut order = [0, 1, 2, 3];
    order.sort_by(|&i, &j| lengths[i].total_cmp(&lengths[j]));
    let mut gradient = SVector::<f64, 4>::repeat(-1.0);
    gradient[order[0]] = 1.0;
    gradient[order[3]] = 1.0;
    let sum = gradient.dot(&SVector::from(lengths));
    let spread = tolerances.spread(&gradient);
    GrashofMargin {
        sum,
        gradient,
        spread,
        distance: distance(sum.abs(), &spread),
    }
}

//! A crank-and-slotted-lever quick return, its lever driving a ram through
//! a connecting rod.

/// A crank-and-slotted-lever quick return: the crank OA (r, θ the driver,
/// O at the origin) carries a block sliding along the slotted lever, which
/// turns about C = (0, −d) (its angle φ3, the block at s from C); the
/// lever's tip P (at `lever` from C) drives the ram R, on a horizontal line
/// at the height y_r, through the rod PR (`rod`, its angle φ4). The
/// return stroke takes the crank through 2·acos(r/d), the working stroke
/// through the rest. The compiled twin of `mechanisms/quick_return.toml`.
#[linkage::linkage(
    u = [phi3, s, phi4, x_r],
    v = [theta],
    points = [
        A = (r * theta.cos(), r * theta.sin()),
        P = (lever * phi3.cos(), -d + lever * phi3.sin()),
        R = (x_r, y_r),
    ],
    closure = [
        r * theta.cos() - s * phi3.cos(),
        r * theta.sin() + d - s * phi3.sin(),
        P.x + rod * phi4.cos() - x_r,
        P.y + rod * phi4.sin() - y_r,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuickReturn {
    pub r: f64,
    pub d: f64,
    pub lever: f64,
    pub rod: f64,
    pub y_r: f64,
}

/// The fixed centres 240 apart and the crank 120 (a time ratio of 2), the
/// lever 450, the rod 135, the ram's line 180 above O (mm).
pub const QUICK_RETURN: QuickReturn = QuickReturn {
    r: 120.0,
    d: 240.0,
    lever: 450.0,
    rod: 135.0,
    y_r: 180.0,
};

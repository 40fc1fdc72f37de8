//! A four-bar for motion generation: its coupler a body carrying the point
//! P, the ground pivots anywhere.

/// A four-bar whose coupler is a body carrying the point P (its position is
/// u's x_p, y_p, its angle θ3) with the moving pivots B and C at (bx, by)
/// and (cx, cy) in its frame; the ground pivots A and D anywhere. Its
/// dyads: the crank (A; B; l2), driven, and the rocker (D; C; l4).
#[linkage::linkage(
    u = [x_p, y_p, theta3, theta4],
    v = [theta2],
    points = [P = (x_p, y_p)],
    closure = [
        xa + l2 * theta2.cos() - (x_p + bx * theta3.cos() - by * theta3.sin()),
        ya + l2 * theta2.sin() - (y_p + bx * theta3.sin() + by * theta3.cos()),
        xd + l4 * theta4.cos() - (x_p + cx * theta3.cos() - cy * theta3.sin()),
        yd + l4 * theta4.sin() - (y_p + cx * theta3.sin() + cy * theta3.cos()),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coupler {
    pub xa: f64,
    pub ya: f64,
    pub xd: f64,
    pub yd: f64,
    pub l2: f64,
    pub l4: f64,
    pub bx: f64,
    pub by: f64,
    pub cx: f64,
    pub cy: f64,
}

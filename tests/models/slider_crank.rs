//! An offset slider-crank, its slider position a prismatic coordinate.

/// An offset slider-crank: crank r, rod l, slider at height e; the slider
/// position s is a prismatic coordinate.
#[linkage::linkage(
    u = [theta3, s],
    v = [theta2],
    points = [
        B = (r * theta2.cos(), r * theta2.sin()),
        P = (s, e),
        G3 = (B.x + 0.5 * l * theta3.cos(), B.y + 0.5 * l * theta3.sin()),
    ],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct SliderCrank {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}

/// The one the tests use.
pub const SLIDER_CRANK: SliderCrank = SliderCrank {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};

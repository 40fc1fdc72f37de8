//! The offset slider-crank driven by its slider.

/// The offset slider-crank driven by its slider: the crank angle is now a
/// dependent coordinate, and the two dead centres (crank and rod in line)
/// are limit positions of the slider.
#[linkage::linkage(
    u = [theta2, theta3],
    v = [s],
    points = [B = (r * theta2.cos(), r * theta2.sin())],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Debug)]
pub struct SliderDriven {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}

/// The one the tests use.
pub const SLIDER_DRIVEN: SliderDriven = SliderDriven {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};

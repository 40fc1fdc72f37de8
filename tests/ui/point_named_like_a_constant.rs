use linkage::prelude::*;

// A point named like a generated constant gets no index constant, so the
// name is declared once, by the constant: the attribute's mistake is the
// only error, and `SENSITIVITY_TRIG_U` keeps its type.
#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2],
    points = [SENSITIVITY_TRIG_U = (l2 * theta2.cos(), l2 * theta2.sin())],
    closure = [
        l2 * theta2.cos() + l3 * thta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

fn main() {
    let _: [bool; 2] = FourBar::SENSITIVITY_TRIG_U;
    let _: [&'static str; 1] = FourBar::POINT_NAMES;
}

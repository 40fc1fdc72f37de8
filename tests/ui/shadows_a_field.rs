use linkage::prelude::*;

#[linkage::linkage(
    u = [theta3, l4],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 - l1,
        l2 * theta2.sin() + l3 * theta3.sin(),
    ],
)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

fn main() {
    // The struct stays usable: only the attribute's own mistakes are reported.
    let bar = FourBar { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0 };
    let _ = bar.solve_position(&vector![1.2, -0.9], &vector![0.3], &Options::default());
}

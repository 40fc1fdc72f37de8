use linkage::prelude::*;

// Every mistake `params` can hold, reported together: a misspelt field, a
// field the equations do not use, a coordinate, a point, a field that is
// not `f64`, and a name listed twice.
#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2],
    points = [B = (l2 * theta2.cos(), l2 * theta2.sin())],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
    params = [l22, mass, theta3, B, label, l3, l3],
)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub mass: f64,
    pub label: u32,
}

fn main() {
    // The struct stays usable: only the attribute's own mistakes are reported.
    let bar = FourBar { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0, mass: 1.0, label: 0 };
    let _ = bar.solve_position(&vector![1.2, -0.9], &vector![0.3], &Options::default());
}

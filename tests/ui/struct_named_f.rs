use linkage::prelude::*;

// A struct named like a dimension the fallback leaves generic: the
// attribute's mistake is the only error. `v` is not a list, so the
// fallback is generic in f (and in n = m + f), and its generic parameter
// for f must not take the name `F` (`impl<const F: usize> Linkage<2, F>
// for F` would not name the struct).
#[linkage::linkage(
    u = [theta3, theta4],
    v = theta2,
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
pub struct F {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

fn main() {
    let bar = F { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0 };
    let _ = bar.solve_position(&vector![1.2, -0.9], &vector![0.3], &Options::default());
    let _: SMatrix<f64, 2, 3> = bar.psi_q(&vector![1.2, -0.9], &vector![0.3]);
}

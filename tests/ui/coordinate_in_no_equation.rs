use linkage::prelude::*;

#[linkage::linkage(
    u = [theta3, theta4, theta5],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        theta3 - theta4 + theta5 - theta5,
    ],
)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

fn main() {}

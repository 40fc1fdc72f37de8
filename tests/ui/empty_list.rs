use linkage::prelude::*;

#[linkage::linkage(
    u = [],
    v = [theta2],
    closure = [],
)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

fn main() {
    let _bar = FourBar { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0 };
}

//! The chain of 1 four-bar loop (`super::chain_text(1)`), compiled; m = 2. One
//! loop keys no crank to a rocker: it has no `delta`.

#[linkage::linkage(
    u = [
        a1, b1,
    ],
    v = [t],
    points = [
        P1 = (0.0 * l1 + l2 * t.cos() + e * (a1 + beta).cos(), l2 * t.sin() + e * (a1 + beta).sin()),
    ],
    closure = [
        l2 * t.cos() + l3 * a1.cos() + l4 * b1.cos() - l1,
        l2 * t.sin() + l3 * a1.sin() + l4 * b1.sin(),
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct Chain {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub e: f64,
    pub beta: f64,
}

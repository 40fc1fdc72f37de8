//! The chain of 4 four-bar loops (`super::chain_text(4)`), compiled; m = 8.

#[linkage::linkage(
    u = [
        a1, b1, a2, b2, a3, b3, a4, b4,
    ],
    v = [t],
    points = [
        P1 = (0.0 * l1 + l2 * t.cos() + e * (a1 + beta).cos(), l2 * t.sin() + e * (a1 + beta).sin()),
        P2 = (1.0 * l1 + l2 * (b1 + delta).cos() + e * (a2 + beta).cos(), l2 * (b1 + delta).sin() + e * (a2 + beta).sin()),
        P3 = (2.0 * l1 + l2 * (b2 + delta).cos() + e * (a3 + beta).cos(), l2 * (b2 + delta).sin() + e * (a3 + beta).sin()),
        P4 = (3.0 * l1 + l2 * (b3 + delta).cos() + e * (a4 + beta).cos(), l2 * (b3 + delta).sin() + e * (a4 + beta).sin()),
    ],
    closure = [
        l2 * t.cos() + l3 * a1.cos() + l4 * b1.cos() - l1,
        l2 * t.sin() + l3 * a1.sin() + l4 * b1.sin(),
        l2 * (b1 + delta).cos() + l3 * a2.cos() + l4 * b2.cos() - l1,
        l2 * (b1 + delta).sin() + l3 * a2.sin() + l4 * b2.sin(),
        l2 * (b2 + delta).cos() + l3 * a3.cos() + l4 * b3.cos() - l1,
        l2 * (b2 + delta).sin() + l3 * a3.sin() + l4 * b3.sin(),
        l2 * (b3 + delta).cos() + l3 * a4.cos() + l4 * b4.cos() - l1,
        l2 * (b3 + delta).sin() + l3 * a4.sin() + l4 * b4.sin(),
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
    pub delta: f64,
}

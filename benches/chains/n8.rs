//! The chain of 8 four-bar loops (`super::chain_text(8)`), compiled; m = 16.

#[linkage::linkage(
    u = [
        a1, b1, a2, b2, a3, b3, a4, b4,
        a5, b5, a6, b6, a7, b7, a8, b8,
    ],
    v = [t],
    points = [
        P1 = (0.0 * l1 + l2 * t.cos() + e * (a1 + beta).cos(), l2 * t.sin() + e * (a1 + beta).sin()),
        P2 = (1.0 * l1 + l2 * (b1 + delta).cos() + e * (a2 + beta).cos(), l2 * (b1 + delta).sin() + e * (a2 + beta).sin()),
        P3 = (2.0 * l1 + l2 * (b2 + delta).cos() + e * (a3 + beta).cos(), l2 * (b2 + delta).sin() + e * (a3 + beta).sin()),
        P4 = (3.0 * l1 + l2 * (b3 + delta).cos() + e * (a4 + beta).cos(), l2 * (b3 + delta).sin() + e * (a4 + beta).sin()),
        P5 = (4.0 * l1 + l2 * (b4 + delta).cos() + e * (a5 + beta).cos(), l2 * (b4 + delta).sin() + e * (a5 + beta).sin()),
        P6 = (5.0 * l1 + l2 * (b5 + delta).cos() + e * (a6 + beta).cos(), l2 * (b5 + delta).sin() + e * (a6 + beta).sin()),
        P7 = (6.0 * l1 + l2 * (b6 + delta).cos() + e * (a7 + beta).cos(), l2 * (b6 + delta).sin() + e * (a7 + beta).sin()),
        P8 = (7.0 * l1 + l2 * (b7 + delta).cos() + e * (a8 + beta).cos(), l2 * (b7 + delta).sin() + e * (a8 + beta).sin()),
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
        l2 * (b4 + delta).cos() + l3 * a5.cos() + l4 * b5.cos() - l1,
        l2 * (b4 + delta).sin() + l3 * a5.sin() + l4 * b5.sin(),
        l2 * (b5 + delta).cos() + l3 * a6.cos() + l4 * b6.cos() - l1,
        l2 * (b5 + delta).sin() + l3 * a6.sin() + l4 * b6.sin(),
        l2 * (b6 + delta).cos() + l3 * a7.cos() + l4 * b7.cos() - l1,
        l2 * (b6 + delta).sin() + l3 * a7.sin() + l4 * b7.sin(),
        l2 * (b7 + delta).cos() + l3 * a8.cos() + l4 * b8.cos() - l1,
        l2 * (b7 + delta).sin() + l3 * a8.sin() + l4 * b8.sin(),
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

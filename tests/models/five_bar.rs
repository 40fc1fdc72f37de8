//! A five-bar with two cranks driven independently (f = 2).

/// A five-bar with two cranks driven independently (f = 2): A at the
/// origin, E at (l1, 0), cranks AB and ED, coupler links BC and DC.
#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2, theta5],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        D = (l1 + l5 * theta5.cos(), l5 * theta5.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
    ],
    closure = [
        B.x + l3 * theta3.cos() - D.x - l4 * theta4.cos(),
        B.y + l3 * theta3.sin() - D.y - l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Debug)]
pub struct FiveBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub l5: f64,
}

/// The one the tests use.
pub const FIVE_BAR: FiveBar = FiveBar {
    l1: 40.0,
    l2: 15.0,
    l3: 50.0,
    l4: 50.0,
    l5: 15.0,
};

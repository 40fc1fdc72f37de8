// `v` written without its brackets: that mistake is the only error, and
// every generated item keeps the type it has without it.

#[linkage::linkage(
    u = [theta3, theta4],
    v = theta2,
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Default)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

include!("every_item/uses.rs");

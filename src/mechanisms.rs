//! Ready mechanisms: the four-bar of the Maple worksheet, with and without
//! its named points. The examples, tests and benchmarks use these; a user
//! can too, without writing the attribute. (The closed-form four-bar is
//! [`crate::closed_form::FourBar`].)

/// The four-bar of the Maple worksheet: ground A–D of length l1, crank AB
/// (l2, angle θ2), coupler BC (l3, θ3), rocker CD (l4, θ4 the angle of
/// C→D); the points B and C, and the link midpoints G2, G3, G4 the
/// worksheet draws its arrows from.
#[crate::linkage(
    u = [theta3, theta4],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        G2 = (0.5 * B.x, 0.5 * B.y),
        G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
        G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

impl FourBar {
    /// The worksheet's lengths: l = (80, 20, 50, 70) mm.
    pub const WORKSHEET: FourBar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
}

/// The same four-bar without named points: its closure equations alone,
/// the least work per pose (sweeps of many designs, benchmarks).
#[crate::linkage(
    u = [theta3, theta4],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BareFourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

impl BareFourBar {
    /// The worksheet's lengths: l = (80, 20, 50, 70) mm.
    pub const WORKSHEET: BareFourBar = BareFourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
}

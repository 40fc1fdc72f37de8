//! A Stephenson III six-bar: its driven crank in no four-bar loop, so both
//! loops must be closed together (up to six assemblies).

/// A Stephenson III six-bar: the crank AB (A at the origin, l2, θ2 the
/// driver) carries the ternary link BCE (C at l3 along its angle θ3, E at
/// (ex, ey) in its frame); the ternary link DFG turns about the ground
/// pivot D = (dx, dy) (F at l4 along its angle θ4, G at (gx, gy) in its
/// frame); the binary links CF (l5, θ5) and EG (l6, θ6) join them. The two
/// loops A-B-C-F-D and A-B-E-G-D share θ3 and θ4: Ψ_u is one block of
/// four, whose assemblies are the real roots of a polynomial of degree
/// six.
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        E = (
            B.x + ex * theta3.cos() - ey * theta3.sin(),
            B.y + ex * theta3.sin() + ey * theta3.cos()
        ),
        F = (dx + l4 * theta4.cos(), dy + l4 * theta4.sin()),
        G = (
            dx + gx * theta4.cos() - gy * theta4.sin(),
            dy + gx * theta4.sin() + gy * theta4.cos()
        ),
    ],
    closure = [
        C.x + l5 * theta5.cos() - F.x,
        C.y + l5 * theta5.sin() - F.y,
        E.x + l6 * theta6.cos() - G.x,
        E.y + l6 * theta6.sin() - G.y,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StephensonThree {
    pub l2: f64,
    pub l3: f64,
    pub ex: f64,
    pub ey: f64,
    pub dx: f64,
    pub dy: f64,
    pub l4: f64,
    pub gx: f64,
    pub gy: f64,
    pub l5: f64,
    pub l6: f64,
}

/// Dimensions with six real assemblies at θ2 = atan2(4, 3)
/// (benches/reference/assembly_modes.py).
pub const STEPHENSON_THREE: StephensonThree = StephensonThree {
    l2: 10.0,
    l3: 60.0,
    ex: -7.0,
    ey: 30.0,
    dx: 49.0,
    dy: -16.0,
    l4: 65.0,
    gx: 20.0,
    gy: 29.0,
    l5: 73.0,
    l6: 55.0,
};

//! A Watt six-bar whose second loop hangs from the rocker.

/// A Watt six-bar: the four-bar A-B-C-D, and a second loop from E, rigid
/// with the rocker CD (|DE| = le at the angle θ4 + β), through F to the
/// ground pivot G.
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        l1 + le * (theta4 + beta).cos() + l5 * theta5.cos() + l6 * theta6.cos() - gx,
        le * (theta4 + beta).sin() + l5 * theta5.sin() + l6 * theta6.sin() - gy,
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct WattSixBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub le: f64,
    pub beta: f64,
    pub l5: f64,
    pub l6: f64,
    pub gx: f64,
    pub gy: f64,
}

/// The one the assembly tests use: the worksheet's four-bar, E 40 from D
/// at 0.5 rad from the rocker, links 60 and 50 to G = (100, 60); four
/// assemblies at θ2 = 20°.
pub const WATT_SIX_BAR: WattSixBar = WattSixBar {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
    le: 40.0,
    beta: 0.5,
    l5: 60.0,
    l6: 50.0,
    gx: 100.0,
    gy: 60.0,
};

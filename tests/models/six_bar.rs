//! A two-loop six-bar (m = 4): the Maple worksheet's four-bar with a dyad.

use std::f64::consts::PI;

/// A two-loop six-bar (m = 4): the worksheet's four-bar, with a dyad EF–FG
/// attached at the coupler point E (distance e from B, at angle beta to BC)
/// and the ground pivot G = (gx, gy).
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        E = (B.x + e * (theta3 + beta).cos(), B.y + e * (theta3 + beta).sin()),
        F = (E.x + l5 * theta5.cos(), E.y + l5 * theta5.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
        E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
    ],
)]
#[derive(Clone, Debug)]
pub struct SixBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub e: f64,
    pub beta: f64,
    pub l5: f64,
    pub l6: f64,
    pub gx: f64,
    pub gy: f64,
}

/// The one the tests use.
pub const SIX_BAR: SixBar = SixBar {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
    e: 40.0,
    beta: PI / 6.0,
    l5: 60.0,
    l6: 50.0,
    gx: 20.0,
    gy: 90.0,
};

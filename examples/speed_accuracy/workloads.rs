//! The benchmark workloads: the worksheet's four-bar, the slider-crank and
//! the six-bar on the dense grid θ2 = (TAU·k)/N, N = 1 008 000 samples per
//! revolution, with their 50-digit references (every 280th sample).
#![allow(dead_code)]

use linkage::prelude::*;

/// Samples per revolution of the dense sweep.
pub const N: usize = 1_008_000;
/// The reference is given at every STRIDE-th sample.
pub const STRIDE: usize = 280;

/// ω2 = 400 rpm
pub const OMEGA2: f64 = 400.0 * std::f64::consts::TAU / 60.0;

/// θ2 of sample k, computed as the reference script computes it.
pub fn theta2(k: usize) -> f64 {
    (std::f64::consts::TAU * k as f64) / N as f64
}

// The mechanisms are written here, as a user writes a mechanism in their own
// crate, so that the generated code is compiled where it is used; the
// four-bar is `linkage::mechanisms::BareFourBar`'s equations.
#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

pub const FOUR_BAR: FourBar = FourBar {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
};

#[linkage::linkage(
    u = [theta3, s],
    v = [theta2],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct SliderCrank {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}

pub const SLIDER_CRANK: SliderCrank = SliderCrank {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};

#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        E = (B.x + e * (theta3 + beta).cos(), B.y + e * (theta3 + beta).sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
        E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
    ],
)]
#[derive(Clone, Copy, Debug)]
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

pub const SIX_BAR: SixBar = SixBar {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
    e: 40.0,
    beta: std::f64::consts::PI / 6.0,
    l5: 60.0,
    l6: 50.0,
    gx: 20.0,
    gy: 90.0,
};

/// One reference sample: k, positions, first and second derivatives.
pub type Row<const M: usize> = (usize, [f64; M], [f64; M], [f64; M]);

/// A reference: for each reference sample k, the positions, first and
/// second derivatives (velocities at the workload's speed, or analogs).
pub struct Reference<const M: usize> {
    pub rows: Vec<Row<M>>,
}

impl<const M: usize> Reference<M> {
    pub fn parse(text: &str) -> Reference<M> {
        let rows = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with('k'))
            .map(|l| {
                let v: Vec<f64> = l.split(',').map(|x| x.parse().expect("a number")).collect();
                let k = v[0] as usize;
                let pick = |offset: usize| std::array::from_fn(|i| v[2 + offset + i]);
                // The four-bar's file interleaves (θ3, θ4, ω3, ω4, α3, α4); the
                // others list positions, then first, then second derivatives.
                (k, pick(0), pick(M), pick(2 * M))
            })
            .collect();
        Reference { rows }
    }
}

/// The worst normwise relative error of each kind (positions, velocities,
/// accelerations): for each coordinate, max |x − ref| over the reference
/// samples divided by max |ref|, then the worst coordinate.
pub fn errors<const M: usize>(
    reference: &Reference<M>,
    ours: &[([f64; M], [f64; M], [f64; M])],
) -> [f64; 3] {
    assert_eq!(reference.rows.len(), ours.len());
    let mut out = [0.0_f64; 3];
    for (kind, worst) in out.iter_mut().enumerate() {
        for i in 0..M {
            let (mut diff, mut size) = (0.0_f64, 0.0_f64);
            for (row, x) in reference.rows.iter().zip(ours) {
                let (r, o) = match kind {
                    0 => (row.1[i], x.0[i]),
                    1 => (row.2[i], x.1[i]),
                    _ => (row.3[i], x.2[i]),
                };
                let d = if kind == 0 && reference_is_angle(i) {
                    let d = (o - r).rem_euclid(std::f64::consts::TAU);
                    d.min(std::f64::consts::TAU - d)
                } else {
                    (o - r).abs()
                };
                diff = diff.max(d);
                size = size.max(r.abs());
            }
            *worst = worst.max(diff / size.max(f64::MIN_POSITIVE));
        }
    }
    out
}

/// All the workloads' coordinates are angles except the slider's s, which
/// never wraps: wrapping is harmless for it.
fn reference_is_angle(_i: usize) -> bool {
    true
}

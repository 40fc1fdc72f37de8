//! Grid arithmetic: ulps, the grid values of line and rocking drives, drives
//! whose grid lands on a given value to the bit, and the singular values a
//! drive passes.

use std::f64::consts::TAU;

/// x moved by `n` ulps (n < 0: down), through zero and the subnormals.
fn ulps(x: f64, n: i64) -> f64 {
    // The bits of an f64 ordered as integers: negative numbers mirrored.
    let ordered = |x: f64| {
        let b = x.to_bits() as i64;
        if b < 0 { i64::MIN - b } else { b }
    };
    let o = ordered(x) + n;
    let b = if o < 0 { i64::MIN - o } else { o };
    f64::from_bits(b as u64)
}

/// The k-th grid value of `Drive::Line { from, to, steps }`, as its
/// documentation gives it.
pub(crate) fn line_grid(from: f64, to: f64, steps: usize, k: usize) -> f64 {
    from + (to - from) / steps as f64 * k as f64
}

/// A line drive of `steps` steps of about `h` (negative: backwards) whose
/// k-th grid value is `target` to the bit, found by moving `from` and `to`
/// a few ulps; the nearest one tried if none is.
pub(crate) fn line_through(target: f64, k: usize, steps: usize, h: f64) -> (f64, f64) {
    let from0 = target - h * k as f64;
    let to0 = from0 + h * steps as f64;
    let mut best = (from0, to0, f64::INFINITY);
    for df in -24..=24 {
        for dt in -24..=24 {
            let (from, to) = (ulps(from0, df), ulps(to0, dt));
            let miss = (line_grid(from, to, steps, k) - target).abs();
            if miss == 0.0 {
                return (from, to);
            }
            if miss < best.2 {
                best = (from, to, miss);
            }
        }
    }
    (best.0, best.1)
}

/// A rocking drive's start such that `from + step·k` is `target` to the bit.
pub(crate) fn rocking_through(target: f64, k: usize, step: f64) -> f64 {
    let mut from = target - step * k as f64;
    for _ in 0..400 {
        let g = from + step * k as f64;
        if g == target {
            return from;
        }
        from = ulps(from, if g < target { 1 } else { -1 });
    }
    from
}

/// |grid − v| in ulps of max(1, |v|).
pub(crate) fn miss(grid: f64, v: f64) -> f64 {
    (grid - v).abs() / unit(v)
}

/// |a − b| for angles, wrapped to [0, π].
pub(crate) fn angle_error(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// The offsets, in ulps, of the grid value from the singular pose.
pub(crate) const OFFSETS: [i64; 5] = [0, 1, -1, 3, -3];

/// The ulp of max(1, |v|).
fn unit(v: f64) -> f64 {
    let a = v.abs().max(1.0);
    ulps(a, 1) - a
}

/// `n` ulps (of max(1, |v|)) from v.
pub(crate) fn off(v: f64, n: i64) -> f64 {
    v + n as f64 * unit(v)
}

/// Singular driver values in the open interval between `from` and `to`, in
/// the order a drive from `from` meets them, of a pattern repeating every
/// 2π.
pub(crate) fn passed_between(from: f64, to: f64, singular: &[f64]) -> Vec<f64> {
    let (lo, hi) = (from.min(to), from.max(to));
    let mut found: Vec<f64> = singular
        .iter()
        .flat_map(|&s| (-3..=3).map(move |m| s + m as f64 * TAU))
        .filter(|&s| s > lo && s < hi)
        .collect();
    found.sort_by(f64::total_cmp);
    if to < from {
        found.reverse();
    }
    found
}

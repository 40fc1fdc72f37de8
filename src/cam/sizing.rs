//! The smallest cam that keeps the pressure angle within a limit: for each
//! candidate size the follower's placement that best balances the strokes
//! (a coarse scan refined by Brent's method), the size bracketed and then
//! bisected (the crate's one bisection, in [`crate::numerics`]).

use super::{Cam, CamError, Follower, Program, Rotation, pressure_limit, setting};
use crate::numerics;
use std::f64::consts::PI;

/// The worst excess of a candidate cam's pressure angle over `limit`;
/// +∞ for a candidate that is no cam (degenerate somewhere): infeasible.
fn candidate_excess(cam: Option<Cam>, limit: f64) -> f64 {
    cam.and_then(|c| c.pressure_excess(limit).ok())
        .filter(|e| !e.is_nan())
        .unwrap_or(f64::INFINITY)
}

/// The x in `xs` where f is least (the first of equals), then Brent's
/// minimum between its neighbours: (x, f(x)).
fn coarse_then_brent(f: &mut impl FnMut(f64) -> f64, xs: &[f64], tolerance: f64) -> (f64, f64) {
    let ys: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
    let k = (0..xs.len())
        .min_by(|&p, &q| ys[p].total_cmp(&ys[q]))
        .unwrap_or(0);
    let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(xs.len() - 1)]);
    let mut g = |x: f64| Ok::<f64, std::convert::Infallible>(f(x));
    let (x, fx) = match numerics::minimize(&mut g, lo, hi, tolerance) {
        Ok(found) => found,
        Err(never) => match never {},
    };
    if fx <= ys[k] { (x, fx) } else { (xs[k], ys[k]) }
}

/// The smallest rocker cam whose pressure angle stays within ±`limit` (rad,
/// in (0, π/2)) over the turn, for a given program, arm (positive and
/// finite), pivot direction and rotation: the base radius by bisection, and
/// for each candidate base radius the initial arm angle (with the centre
/// distance it implies by the law of cosines, r0² = a² + l² − 2al·cos ψ0)
/// that best balances the rise's and the return's extremes. Base radii up
/// to 100 arms are tried.
pub fn smallest_rocker(
    program: &Program,
    arm: f64,
    pivot_angle: f64,
    rotation: Rotation,
    limit: f64,
) -> Result<Cam, CamError> {
    setting("the rocker's arm", "positive and finite", arm, arm > 0.0)?;
    setting("the rocker's pivot angle", "finite", pivot_angle, true)?;
    let limit = pressure_limit(limit)?;
    let make = |r0: f64, psi0: f64| -> Option<Cam> {
        let disc = r0 * r0 - arm * arm * psi0.sin().powi(2);
        if disc < 0.0 {
            return None;
        }
        let a = arm * psi0.cos() + disc.sqrt();
        let clear_of_the_centre = a > arm * 1e-6; // false for NaN too
        if !clear_of_the_centre {
            return None;
        }
        let follower = Follower::Rocker {
            arm,
            centre_distance: a,
            initial_angle: psi0,
            pivot_angle,
        };
        Cam::new(program.clone(), follower, rotation).ok()
    };
    // For a base radius: the best initial angle, and its excess.
    let best = |r0: f64| -> (f64, f64) {
        let upper = (r0 / arm).clamp(-1.0, 1.0).asin().min(PI / 2.0 - 1e-9);
        let n = 24;
        let xs: Vec<f64> = (0..=n)
            .map(|i| 1e-3 + (upper - 2e-3) * i as f64 / n as f64)
            .collect();
        coarse_then_brent(
            &mut |psi0| candidate_excess(make(r0, psi0), limit),
            &xs,
            1e-12,
        )
    };
    let (lo, hi) = numerics::bracket_feasible(
        &mut |r0| best(r0).1 <= 0.0,
        arm * 0.05,
        arm * 0.5,
        100.0 * arm,
    )
    .ok_or(CamError::NoSize {
        limit: 100.0 * arm,
        angle: limit.to_degrees(),
    })?;
    let r0 = numerics::bisect(&mut |r0| best(r0).1 <= 0.0, lo, hi);
    let (psi0, _) = best(r0);
    make(r0, psi0).ok_or(CamError::NoSize {
        limit: r0,
        angle: limit.to_degrees(),
    })
}

/// The smallest translating cam (base radius, with the offset that best
/// balances the strokes) whose pressure angle stays within ±`limit` (rad,
/// in (0, π/2)), for a finite axis angle. Base radii up to 10⁴ lifts are
/// tried.
pub fn smallest_translating(
    program: &Program,
    axis_angle: f64,
    rotation: Rotation,
    limit: f64,
) -> Result<Cam, CamError> {
    setting("the follower's axis angle", "finite", axis_angle, true)?;
    let limit = pressure_limit(limit)?;
    let make = |base: f64, offset: f64| {
        let follower = Follower::Translating {
            offset,
            base,
            axis_angle,
        };
        Cam::new(program.clone(), follower, rotation).ok()
    };
    let best = |base: f64| -> (f64, f64) {
        let n = 24;
        let xs: Vec<f64> = (0..=n)
            .map(|i| -0.95 * base + 1.9 * base * i as f64 / n as f64)
            .collect();
        coarse_then_brent(
            &mut |e| candidate_excess(make(base, e), limit),
            &xs,
            1e-13 * base,
        )
    };
    let lift = program.lift();
    let feasible = |b: f64| b > 0.0 && best(b).1 <= 0.0;
    let (lo, hi) = numerics::bracket_feasible(&mut |b| feasible(b), 0.0, lift, 1e4 * lift).ok_or(
        CamError::NoSize {
            limit: 1e4 * lift,
            angle: limit.to_degrees(),
        },
    )?;
    let base = numerics::bisect(&mut |b| feasible(b), lo, hi);
    let (offset, _) = best(base);
    make(base, offset).ok_or(CamError::NoSize {
        limit: base,
        angle: limit.to_degrees(),
    })
}

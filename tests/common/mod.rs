//! Mechanisms and helpers shared by the integration tests.
#![allow(dead_code)]

pub mod sensitivity;
pub mod twins;

#[allow(unused_imports)] // not every test binary uses it
pub use linkage::mechanisms::FourBar;
use linkage::num_dual::{Dual2_64, Dual64};
use linkage::prelude::*;
use std::f64::consts::TAU;

/// ω2 = 400 rpm
pub const OMEGA2: f64 = 400.0 * TAU / 60.0;

/// |a − b| / max(|b|, floor)
pub fn rel(a: f64, b: f64, floor: f64) -> f64 {
    (a - b).abs() / b.abs().max(floor)
}

/// ‖a − b‖∞ / max(‖b‖∞, floor)
pub fn rel_norm(a: &[f64], b: &[f64], floor: f64) -> f64 {
    assert_eq!(a.len(), b.len());
    let diff = a
        .iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    let size = b.iter().fold(0.0_f64, |m, y| m.max(y.abs()));
    diff / size.max(floor)
}

/// Solves a sequence of driver values by continuation: each pose starts
/// Newton from the previous one.
pub fn continuation<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u0: SVector<f64, M>,
    drivers: &[SVector<f64, F>],
) -> Vec<SVector<f64, M>> {
    let mut u = u0;
    drivers
        .iter()
        .map(|v| {
            u = model
                .solve_position(&u, v, &Options::default())
                .unwrap_or_else(|e| panic!("no position at v = {v:?}: {e}"))
                .u;
            u
        })
        .collect()
}

/// The Jacobian Ψ_q of `psi_generic` by forward-mode automatic
/// differentiation (one dual-number evaluation per column of q = [u; v]).
pub fn psi_q_by_dual<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> Vec<Vec<f64>> {
    let mut columns = Vec::new();
    for k in 0..M + F {
        let ud = SVector::<Dual64, M>::from_fn(|i, _| {
            let d = Dual64::from(u[i]);
            if i == k { d.derivative() } else { d }
        });
        let vd = SVector::<Dual64, F>::from_fn(|i, _| {
            let d = Dual64::from(v[i]);
            if M + i == k { d.derivative() } else { d }
        });
        columns.push(model.psi_generic(&ud, &vd).iter().map(|x| x.eps).collect());
    }
    columns
}

/// γ = d²/ds² Ψ(u + s·u̇, v + s·v̇) at s = 0, by a second-order dual number.
pub fn gamma_by_dual<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
) -> SVector<f64, M> {
    let ud = SVector::<Dual2_64, M>::from_fn(|i, _| Dual2_64::new(u[i], udot[i], 0.0));
    let vd = SVector::<Dual2_64, F>::from_fn(|i, _| Dual2_64::new(v[i], vdot[i], 0.0));
    model.psi_generic(&ud, &vd).map(|x| x.v2)
}

/// Point velocities and accelerations by a second-order dual number along
/// the path q(s) = q + s·q̇ + s²/2·q̈: its first derivative is P_q q̇, its
/// second P_q q̈ + (P_q q̇)_q q̇.
#[allow(clippy::too_many_arguments)]
pub fn points_by_dual<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
    uddot: &SVector<f64, M>,
    vddot: &SVector<f64, F>,
) -> Vec<[f64; 6]> {
    let ud = SVector::<Dual2_64, M>::from_fn(|i, _| Dual2_64::new(u[i], udot[i], uddot[i]));
    let vd = SVector::<Dual2_64, F>::from_fn(|i, _| Dual2_64::new(v[i], vdot[i], vddot[i]));
    model
        .point_positions_generic(&ud, &vd)
        .as_ref()
        .iter()
        .map(|p| [p.x.re, p.y.re, p.x.v1, p.y.v1, p.x.v2, p.y.v2])
        .collect()
}

/// The residual of the velocity equation, ‖Ψ_u u̇ + Ψ_v v̇‖∞, relative to
/// the size of its terms.
pub fn velocity_residual<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
) -> f64 {
    let a = model.psi_u(u, v) * udot;
    let b = model.psi_v(u, v) * vdot;
    let scale = a.amax().max(b.amax()).max(f64::MIN_POSITIVE);
    (a + b).amax() / scale
}

/// Every invariant of one pose: Ψ = 0 after Newton, the velocity equation,
/// methods A = B = fused, the generated Jacobian and γ against num-dual, and
/// the point kinematics against num-dual. Returns the worst relative figure
/// of each.
pub fn check_invariants<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u_guess: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
) -> (SVector<f64, M>, [f64; 6]) {
    let options = Options::default();
    let a = model
        .analyze(u_guess, v, vdot, vddot, &options)
        .unwrap_or_else(|e| panic!("analysis failed at v = {v:?}: {e}"));
    let u = a.u;
    // Ψ = 0, relative to the size of the mechanism (its Jacobian).
    let psi = model.psi(&u, v).amax();
    let size = model.psi_u(&u, v).amax().max(model.psi_v(&u, v).amax());
    let psi_rel = psi / size;
    let vel = velocity_residual(model, &u, v, &a.udot, vdot);

    let acc = |method| {
        model
            .acceleration(&u, v, &a.udot, vdot, vddot, &Options { method, ..options })
            .unwrap()
    };
    let (acc_a, acc_b, acc_f) = (
        acc(AccelerationMethod::A),
        acc(AccelerationMethod::B),
        acc(AccelerationMethod::Fused),
    );
    let methods = rel_norm(acc_a.as_slice(), acc_b.as_slice(), 1e-300).max(rel_norm(
        acc_f.as_slice(),
        acc_b.as_slice(),
        1e-300,
    ));

    // Generated Ψ_q against num-dual, column by column.
    let columns = psi_q_by_dual(model, &u, v);
    let (pu, pv) = (model.psi_u(&u, v), model.psi_v(&u, v));
    let mut generated = Vec::new();
    let mut dual = Vec::new();
    for (k, col) in columns.iter().enumerate() {
        for i in 0..M {
            generated.push(if k < M { pu[(i, k)] } else { pv[(i, k - M)] });
            dual.push(col[i]);
        }
    }
    let jac = rel_norm(&generated, &dual, 1e-300);
    let g = model.gamma(&u, v, &a.udot, vdot);
    let gd = gamma_by_dual(model, &u, v, &a.udot, vdot);
    let gamma = rel_norm(g.as_slice(), gd.as_slice(), 1e-300);

    // Points against num-dual, relative to the largest point position,
    // velocity and acceleration of the pose (a point may be at rest).
    let by_dual = points_by_dual(model, &u, v, &a.udot, vdot, &a.uddot, vddot);
    let largest = |p: &L::Points| {
        p.as_ref()
            .iter()
            .map(|x| x.amax())
            .fold(f64::MIN_POSITIVE, f64::max)
    };
    let floors = [
        largest(&a.points),
        largest(&a.point_velocities),
        largest(&a.point_accelerations),
    ];
    let mut points = 0.0_f64;
    for (k, d) in by_dual.iter().enumerate() {
        let p = a.points.as_ref()[k];
        let pv = a.point_velocities.as_ref()[k];
        let pa = a.point_accelerations.as_ref()[k];
        points = points
            .max(rel_norm(p.as_slice(), &d[0..2], floors[0]))
            .max(rel_norm(pv.as_slice(), &d[2..4], floors[1]))
            .max(rel_norm(pa.as_slice(), &d[4..6], floors[2]));
    }
    (u, [psi_rel, vel, methods, jac, gamma, points])
}

/// The branch-continuity check on two consecutive poses of a sweep that no
/// limit position separates: whether their velocity ratios jump farther
/// than the step and the second-order analogs allow, |Δu′| > 3·max‖u″‖·|Δv|
/// plus rounding (1e-9, and ε·κ² near a singular pose, κ = 1/rcond, relative
/// to u′). On a smooth branch — through a branch point too — u′ changes by
/// about u″·Δv; a pose on another branch crossing this one jumps by the
/// difference of their tangents. The ends' u″ bound the change only where
/// the step is fine against the scale on which u′ varies: a step with
/// max‖u″‖·|Δv| > 0.1·max‖u′‖ is not judged. Returns (jump, allowed) where
/// it jumps.
pub fn ratio_jump<const M: usize, const F: usize>(
    a: &SweepPose<M, F>,
    b: &SweepPose<M, F>,
) -> Option<(f64, f64)> {
    let jump = (b.udot - a.udot).amax();
    let size = a.udot.amax().max(b.udot.amax());
    let step = (b.v - a.v)
        .iter()
        .fold(0.0, |length: f64, x| length.hypot(*x));
    let change = a.uddot.amax().max(b.uddot.amax()) * step;
    let judged = change <= 0.1 * size; // false for NaN (0·∞) too
    if !judged {
        return None;
    }
    let rounding = 1e-9 + 8.0 * f64::EPSILON / (a.rcond * b.rcond);
    let allowed = 3.0 * change + rounding * size;
    let continuous = jump <= allowed; // false for NaN too
    (!continuous).then_some((jump, allowed))
}

/// The branch-continuity check on two consecutive poses of a sweep of
/// `model` (f = 1), no limit position between them: [`ratio_jump`], and,
/// where it flags a jump, a tie-breaker — between coarse grid poses the
/// branch may turn sharply, past a near-singular pose, where the ends' u″
/// say nothing of the u″ between. A sweep 64 times finer from one pose to
/// the other must then arrive at the second pose (to 1e-9), complete, every
/// one of its own pairs passing [`ratio_jump`]; if it does, the turn is the
/// branch's own. Returns (jump, allowed) of a true jump.
pub fn branch_jump<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    a: &SweepPose<M, 1>,
    b: &SweepPose<M, 1>,
) -> Option<(f64, f64)> {
    let flagged = ratio_jump(a, b)?;
    let drive = Drive::Line {
        from: a.v,
        to: b.v,
        steps: 64,
    };
    let finer = model.sweep(&a.u, &drive, &SweepOptions::default());
    let continuous = finer.is_ok_and(|s| {
        let arrives = s.poses.last().is_some_and(|last| {
            last.v == b.v && (last.u - b.u).amax() <= 1e-9 * (1.0 + b.u.amax())
        });
        s.complete
            && arrives
            && s.poses
                .windows(2)
                .all(|w| ratio_jump(&w[0], &w[1]).is_none())
    });
    (!continuous).then_some(flagged)
}

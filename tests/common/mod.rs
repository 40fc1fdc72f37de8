//! Mechanisms and helpers shared by the integration tests.
#![allow(dead_code)]

pub mod sensitivity;

#[allow(unused_imports)] // not every test binary uses it
pub use linkage::mechanisms::FourBar;
use linkage::num_dual::{Dual2_64, Dual64};
use linkage::prelude::*;
use std::f64::consts::{PI, TAU};

/// ω2 = 400 rpm
pub const OMEGA2: f64 = 400.0 * TAU / 60.0;

/// An offset slider-crank: crank r, rod l, slider at height e; the slider
/// position s is a prismatic coordinate.
#[linkage::linkage(
    u = [theta3, s],
    v = [theta2],
    points = [
        B = (r * theta2.cos(), r * theta2.sin()),
        P = (s, e),
        G3 = (B.x + 0.5 * l * theta3.cos(), B.y + 0.5 * l * theta3.sin()),
    ],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Debug)]
pub struct SliderCrank {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}

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

/// A boom pivoted at the origin, raised by a hydraulic cylinder from the
/// ground pivot A = (ax, ay) to the boom point at distance b: driven by the
/// actuator length L, so Ψ_u depends on v and Ψ_v on u (the mixed blocks of
/// method B are non-zero).
#[linkage::linkage(
    u = [theta, phi],
    v = [length],
    points = [
        K = (b * theta.cos(), b * theta.sin()),
        T = (lb * theta.cos(), lb * theta.sin()),
    ],
    closure = [
        ax + length * phi.cos() - b * theta.cos(),
        ay + length * phi.sin() - b * theta.sin(),
    ],
)]
#[derive(Clone, Debug)]
pub struct Boom {
    pub ax: f64,
    pub ay: f64,
    pub b: f64,
    /// The boom's length, to its tip T.
    pub lb: f64,
}

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

/// The offset slider-crank driven by its slider: the crank angle is now a
/// dependent coordinate, and the two dead centres (crank and rod in line)
/// are limit positions of the slider.
#[linkage::linkage(
    u = [theta2, theta3],
    v = [s],
    points = [B = (r * theta2.cos(), r * theta2.sin())],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Debug)]
pub struct SliderDriven {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}

pub const SLIDER_DRIVEN: SliderDriven = SliderDriven {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};

pub const SLIDER_CRANK: SliderCrank = SliderCrank {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};

pub const FIVE_BAR: FiveBar = FiveBar {
    l1: 40.0,
    l2: 15.0,
    l3: 50.0,
    l4: 50.0,
    l5: 15.0,
};

pub const BOOM: Boom = Boom {
    ax: 0.4,
    ay: -0.3,
    b: 1.0,
    lb: 2.5,
};

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

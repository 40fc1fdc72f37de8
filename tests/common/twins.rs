//! A run-time mechanism against its compiled twin: every kernel at a pose
//! in motion, entry by entry to the bit (on dual numbers, where the
//! run-time mechanism evaluates its formulas rather than the generated
//! code, to rounding).

use linkage::mechanism::Fixed;
use linkage::prelude::*;

pub fn same<const R: usize, const C: usize>(
    what: &str,
    a: &SMatrix<f64, R, C>,
    b: &SMatrix<f64, R, C>,
) {
    for (x, y) in a.iter().zip(b.iter()) {
        assert!(
            x.to_bits() == y.to_bits(),
            "{what}: compiled {a} run-time {b}"
        );
    }
}

pub fn same_points(what: &str, a: &[Vector2<f64>], b: &[Vector2<f64>]) {
    assert_eq!(a.len(), b.len(), "{what}: the number of points");
    for (p, q) in a.iter().zip(b) {
        same(what, p, q);
    }
}

/// Every kernel of the two at one pose in motion.
#[allow(clippy::too_many_arguments)]
pub fn every_kernel<L, const M: usize, const F: usize>(
    compiled: &L,
    twin: &Fixed<M, F>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
    uddot: &SVector<f64, M>,
    vddot: &SVector<f64, F>,
) where
    L: Linkage<M, F>,
{
    same("psi", &compiled.psi(u, v), &twin.psi(u, v));
    same("psi_u", &compiled.psi_u(u, v), &twin.psi_u(u, v));
    same("psi_v", &compiled.psi_v(u, v), &twin.psi_v(u, v));
    let (a, b) = (compiled.psi_and_psi_u(u, v), twin.psi_and_psi_u(u, v));
    same("psi_and_psi_u.0", &a.0, &b.0);
    same("psi_and_psi_u.1", &a.1, &b.1);
    same(
        "psi_u_udot_u",
        &compiled.psi_u_udot_u(u, v, udot),
        &twin.psi_u_udot_u(u, v, udot),
    );
    same(
        "psi_u_udot_v",
        &compiled.psi_u_udot_v(u, v, udot),
        &twin.psi_u_udot_v(u, v, udot),
    );
    same(
        "psi_v_vdot_u",
        &compiled.psi_v_vdot_u(u, v, vdot),
        &twin.psi_v_vdot_u(u, v, vdot),
    );
    same(
        "psi_v_vdot_v",
        &compiled.psi_v_vdot_v(u, v, vdot),
        &twin.psi_v_vdot_v(u, v, vdot),
    );
    same(
        "psi_u_dot",
        &compiled.psi_u_dot(u, v, udot, vdot),
        &twin.psi_u_dot(u, v, udot, vdot),
    );
    same(
        "psi_v_dot",
        &compiled.psi_v_dot(u, v, udot, vdot),
        &twin.psi_v_dot(u, v, udot, vdot),
    );
    same(
        "gamma",
        &compiled.gamma(u, v, udot, vdot),
        &twin.gamma(u, v, udot, vdot),
    );
    same_points(
        "points",
        compiled.point_positions(u, v).as_ref(),
        twin.point_positions(u, v).as_ref(),
    );
    same_points(
        "point velocities",
        compiled.point_velocities(u, v, udot, vdot).as_ref(),
        twin.point_velocities(u, v, udot, vdot).as_ref(),
    );
    same_points(
        "point accelerations",
        compiled
            .point_accelerations(u, v, udot, vdot, uddot, vddot)
            .as_ref(),
        twin.point_accelerations(u, v, udot, vdot, uddot, vddot)
            .as_ref(),
    );
    assert_eq!(compiled.trig_u(), twin.trig_u());
    assert_eq!(compiled.trig_v(), twin.trig_v());
    let trig_u: [(f64, f64); M] = std::array::from_fn(|k| u[k].sin_cos());
    let trig_v: [(f64, f64); F] = std::array::from_fn(|k| v[k].sin_cos());
    for (a, b) in [
        (
            compiled.kinematics(u, v, vdot, vddot),
            twin.kinematics(u, v, vdot, vddot),
        ),
        (
            compiled.kinematics_with_trig(u, v, &trig_u, &trig_v, vdot, vddot),
            twin.kinematics_with_trig(u, v, &trig_u, &trig_v, vdot, vddot),
        ),
    ] {
        same("kinematics.psi", &a.psi, &b.psi);
        same("kinematics.psi_u", &a.psi_u, &b.psi_u);
        same("kinematics.psi_v", &a.psi_v, &b.psi_v);
        same("kinematics.inverse", &a.inverse, &b.inverse);
        same("kinematics.udot", &a.udot, &b.udot);
        same("kinematics.uddot", &a.uddot, &b.uddot);
        assert_eq!(a.rcond.to_bits(), b.rcond.to_bits());
        assert_eq!(a.det.to_bits(), b.det.to_bits());
    }
    // On dual numbers the run-time mechanism evaluates its formulas, not
    // the generated code: the same values to rounding.
    let (ud, vd) = (u.map(num_dual::Dual64::from), v.map(num_dual::Dual64::from));
    let (a, b) = (compiled.psi_generic(&ud, &vd), twin.psi_generic(&ud, &vd));
    let scale = compiled.psi_u(u, v).abs().max().max(1.0) * (1.0 + u.abs().max());
    for (x, y) in a.iter().zip(b.iter()) {
        assert!((x.re - y.re).abs() <= 1e-13 * scale, "psi_generic: {a} {b}");
    }
}

/// Two sweeps, pose by pose, to the bit.
pub fn same_sweep<const M: usize, const F: usize>(a: &Sweep<M, F>, b: &Sweep<M, F>) {
    assert_eq!(a.poses.len(), b.poses.len(), "the number of poses");
    for (p, q) in a.poses.iter().zip(&b.poses) {
        same("pose.v", &p.v, &q.v);
        same("pose.u", &p.u, &q.u);
        same("pose.udot", &p.udot, &q.udot);
        same("pose.uddot", &p.uddot, &q.uddot);
    }
    assert_eq!(a.events.len(), b.events.len(), "the singular poses");
    for (e, g) in a.events.iter().zip(&b.events) {
        same("event.v", &e.v, &g.v);
        same("event.u", &e.u, &g.u);
    }
    assert_eq!(a.complete, b.complete);
}

/// Poses in motion spread over [−4, 4) in every coordinate and rate,
/// the same on every run (a linear congruential sequence).
pub fn motions<const M: usize, const F: usize>(count: usize) -> Vec<[Vec<f64>; 6]> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) * 8.0 - 4.0
    };
    (0..count)
        .map(|_| [M, F, M, F, M, F].map(|n| (0..n).map(|_| next()).collect()))
        .collect()
}

//! A run-time mechanism against its compiled twin: every kernel at a pose
//! in motion, entry by entry to the bit (on dual numbers, where the
//! run-time mechanism evaluates its formulas rather than the generated
//! code, to rounding).

use linkage::mechanism::Fixed;
use linkage::prelude::*;
use linkage::{PositionSensitivity, PositionTerms, SensitivityKernel, SensitivityTerms};

/// The inside of the attribute `#[linkage::linkage(...)]` (or
/// `#[crate::linkage(...)]`) on `struct name` in `source`.
pub fn attribute<'s>(source: &'s str, name: &str) -> &'s str {
    let item = source
        .find(&format!("pub struct {name} "))
        .unwrap_or_else(|| panic!("no struct {name}"));
    let open = ["#[linkage::linkage(", "#[crate::linkage("]
        .iter()
        .filter_map(|a| source[..item].rfind(a).map(|k| k + a.len()))
        .max()
        .unwrap_or_else(|| panic!("no attribute on {name}"));
    // The parenthesis that closes the one opened.
    let mut depth = 1;
    for (k, c) in source[open..].char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return &source[open..open + k];
                }
            }
            _ => {}
        }
    }
    panic!("the attribute on {name} does not close")
}

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
    // The three levels in one pass, on the sines and cosines given.
    let trig_u: [(f64, f64); M] = u.map(f64::sin_cos).into();
    let trig_v: [(f64, f64); F] = v.map(f64::sin_cos).into();
    let [p, pv, pa] = twin.point_motion_with_trig(u, v, udot, vdot, uddot, vddot, &trig_u, &trig_v);
    same_points(
        "points in one pass",
        compiled.point_positions(u, v).as_ref(),
        p.as_ref(),
    );
    same_points(
        "point velocities in one pass",
        compiled.point_velocities(u, v, udot, vdot).as_ref(),
        pv.as_ref(),
    );
    same_points(
        "point accelerations in one pass",
        compiled
            .point_accelerations(u, v, udot, vdot, uddot, vddot)
            .as_ref(),
        pa.as_ref(),
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
        same(
            "kinematics.inverse",
            &a.factors.inverse(),
            &b.factors.inverse(),
        );
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

/// Point columns (one set of points per coordinate or parameter), to the
/// bit.
fn same_columns<A: AsRef<[Vector2<f64>]>, B: AsRef<[Vector2<f64>]>>(what: &str, a: &[A], b: &[B]) {
    assert_eq!(a.len(), b.len(), "{what}: the number of columns");
    for (p, q) in a.iter().zip(b) {
        same_points(what, p.as_ref(), q.as_ref());
    }
}

/// Every term of the sensitivities, to the bit.
fn same_terms<const M: usize, const K: usize, A, B>(
    a: &SensitivityTerms<M, K, A>,
    b: &SensitivityTerms<M, K, B>,
) where
    A: AsRef<[Vector2<f64>]>,
    B: AsRef<[Vector2<f64>]>,
{
    same("terms.psi_u", &a.psi_u, &b.psi_u);
    same("terms.psi_p", &a.psi_p, &b.psi_p);
    same("terms.psi_u_dot", &a.psi_u_dot, &b.psi_u_dot);
    same("terms.psi_p_dot", &a.psi_p_dot, &b.psi_p_dot);
    same("terms.psi_u_ddot", &a.psi_u_ddot, &b.psi_u_ddot);
    same("terms.psi_p_ddot", &a.psi_p_ddot, &b.psi_p_ddot);
    same_columns("terms.points_u", &a.points_u, &b.points_u);
    same_columns("terms.points_p", &a.points_p, &b.points_p);
    same_columns(
        "terms.point_velocities_u",
        &a.point_velocities_u,
        &b.point_velocities_u,
    );
    same_columns(
        "terms.point_velocities_p",
        &a.point_velocities_p,
        &b.point_velocities_p,
    );
    same_columns(
        "terms.point_accelerations_u",
        &a.point_accelerations_u,
        &b.point_accelerations_u,
    );
    same_columns(
        "terms.point_accelerations_p",
        &a.point_accelerations_p,
        &b.point_accelerations_p,
    );
}

/// The terms of the positions' sensitivities, to the bit.
fn same_position_terms<const M: usize, const K: usize, A, B>(
    a: &PositionTerms<M, K, A>,
    b: &PositionTerms<M, K, B>,
) where
    A: AsRef<[Vector2<f64>]>,
    B: AsRef<[Vector2<f64>]>,
{
    same("position terms.psi_u", &a.psi_u, &b.psi_u);
    same("position terms.psi_p", &a.psi_p, &b.psi_p);
    same_columns("position terms.points_u", &a.points_u, &b.points_u);
    same_columns("position terms.points_p", &a.points_p, &b.points_p);
}

/// The sensitivities of the positions alone are the whole sensitivities'
/// (or the same error): u_p and rcond to the bit, dP/dp to the number
/// (the whole sum adds a coordinate's zero term, and 0 + −0 is +0).
pub fn same_positions<const M: usize, const K: usize, A, B>(
    whole: &Result<Sensitivity<M, K, A>, Error>,
    positions: &Result<PositionSensitivity<M, K, B>, Error>,
) where
    A: AsRef<[Vector2<f64>]>,
    B: AsRef<[Vector2<f64>]>,
{
    match (whole, positions) {
        (Ok(a), Ok(b)) => {
            same("positions.u", &a.u, &b.u);
            assert_eq!(a.rcond.to_bits(), b.rcond.to_bits(), "positions.rcond");
            for (p, q) in a.points.iter().zip(&b.points) {
                assert_eq!(p.as_ref(), q.as_ref(), "positions.points");
            }
        }
        (Err(a), Err(b)) => assert_eq!(format!("{a:?}"), format!("{b:?}")),
        (a, b) => panic!(
            "one failed: {:?} and {:?}",
            a.as_ref().err(),
            b.as_ref().err()
        ),
    }
}

/// The same sensitivities (or the same error), to the bit.
pub fn same_sensitivity<const M: usize, const K: usize, A, B>(
    a: &Result<Sensitivity<M, K, A>, Error>,
    b: &Result<Sensitivity<M, K, B>, Error>,
) where
    A: AsRef<[Vector2<f64>]>,
    B: AsRef<[Vector2<f64>]>,
{
    match (a, b) {
        (Ok(a), Ok(b)) => {
            same("sensitivity.u", &a.u, &b.u);
            same("sensitivity.udot", &a.udot, &b.udot);
            same("sensitivity.uddot", &a.uddot, &b.uddot);
            same_columns("sensitivity.points", &a.points, &b.points);
            same_columns(
                "sensitivity.point_velocities",
                &a.point_velocities,
                &b.point_velocities,
            );
            same_columns(
                "sensitivity.point_accelerations",
                &a.point_accelerations,
                &b.point_accelerations,
            );
            assert_eq!(a.rcond.to_bits(), b.rcond.to_bits(), "sensitivity.rcond");
        }
        (Err(a), Err(b)) => assert_eq!(format!("{a:?}"), format!("{b:?}")),
        _ => panic!(
            "compiled {} run-time {}",
            a.as_ref().map_or_else(|e| e.to_string(), |_| "Ok".into()),
            b.as_ref().map_or_else(|e| e.to_string(), |_| "Ok".into())
        ),
    }
}

/// Every kernel of the sensitivities of the two at one pose in motion,
/// their parameters, and the sensitivities solved from them.
pub fn every_sensitivity_kernel<L, const M: usize, const F: usize, const K: usize>(
    compiled: &L,
    twin: &Fixed<M, F, 32, K>,
    motion: &Motion<M, F>,
) where
    L: Sensitivities<M, F, K>,
{
    assert_eq!(compiled.param_names(), twin.param_names());
    same("params", &compiled.params(), &twin.params());
    let Motion {
        u,
        v,
        udot,
        vdot,
        uddot,
        vddot,
    } = motion;
    same_terms(
        &compiled.sensitivity_terms(u, v, udot, vdot, uddot, vddot),
        &twin.sensitivity_terms(u, v, udot, vdot, uddot, vddot),
    );
    assert_eq!(compiled.sensitivity_trig_u(), twin.sensitivity_trig_u());
    assert_eq!(compiled.sensitivity_trig_v(), twin.sensitivity_trig_v());
    // Sines and cosines other than the coordinates' own: the kernel must
    // read what it is given.
    let trig_u: [(f64, f64); M] = std::array::from_fn(|k| (u[k] + 0.25).sin_cos());
    let trig_v: [(f64, f64); F] = std::array::from_fn(|k| (v[k] - 0.5).sin_cos());
    same_terms(
        &compiled.sensitivity_terms_with_trig(u, v, &trig_u, &trig_v, udot, vdot, uddot, vddot),
        &twin.sensitivity_terms_with_trig(u, v, &trig_u, &trig_v, udot, vdot, uddot, vddot),
    );
    // The positions' terms: the compiled mechanism's read from its whole
    // terms, the run-time mechanism's from a kernel of their own, which
    // reads the sines and cosines of no coordinate the whole terms do not.
    let (a, b) = (
        compiled.position_terms_with_trig(u, v, &trig_u, &trig_v),
        twin.position_terms_with_trig(u, v, &trig_u, &trig_v),
    );
    same_position_terms(&a, &b);
    let within = |part: &[bool], whole: &[bool]| part.iter().zip(whole).all(|(p, w)| !p | w);
    assert!(within(&twin.position_trig_u(), &twin.sensitivity_trig_u()));
    assert!(within(&twin.position_trig_v(), &twin.sensitivity_trig_v()));
    same("psi_p", &compiled.psi_p(u, v), &twin.psi_p(u, v));
    let options = Options::default();
    same_sensitivity(
        &compiled.sensitivities(motion, &options),
        &twin.sensitivities(motion, &options),
    );
    // On dual numbers, by the first parameter: to rounding.
    let seed = |k: usize, x: f64| num_dual::Dual64::new(x, if k == 0 { 1.0 } else { 0.0 });
    let params = SVector::<_, K>::from_fn(|k, _| seed(k, compiled.params()[k]));
    let (ud, vd) = (u.map(num_dual::Dual64::from), v.map(num_dual::Dual64::from));
    let a = compiled.psi_generic_params(&params, &ud, &vd);
    let b = twin.psi_generic_params(&params, &ud, &vd);
    let psi_p = compiled.psi_p(u, v);
    let scale = (compiled.psi_u(u, v).abs().max() + psi_p.abs().max()).max(1.0)
        * (1.0 + u.abs().max() + compiled.params().abs().max());
    for (i, (x, y)) in a.iter().zip(b.iter()).enumerate() {
        assert!(
            (x.re - y.re).abs() <= 1e-13 * scale,
            "psi_generic_params: {a} {b}"
        );
        assert!(
            (x.eps - y.eps).abs() <= 1e-13 * scale,
            "psi_generic_params: {a} {b}"
        );
        if K > 0 {
            assert!(
                (y.eps - psi_p[(i, 0)]).abs() <= 1e-13 * scale,
                "the dual part is Ψ_p's column"
            );
        }
    }
    let a = compiled.point_positions_generic_params(&params, &ud, &vd);
    let b = twin.point_positions_generic_params(&params, &ud, &vd);
    assert_eq!(a.as_ref().len(), b.as_ref().len());
    for (p, q) in a.as_ref().iter().zip(b.as_ref()) {
        for (x, y) in p.iter().zip(q.iter()) {
            assert!(
                (x.re - y.re).abs() <= 1e-13 * scale,
                "points on duals: {p} {q}"
            );
            assert!(
                (x.eps - y.eps).abs() <= 1e-13 * scale,
                "points on duals: {p} {q}"
            );
        }
    }
}

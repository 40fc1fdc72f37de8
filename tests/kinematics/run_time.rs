//! Run-time mechanisms against their compiled twins: the same attribute
//! text, compiled by the macro and read at run time into tapes, gives the
//! same numbers to the bit — every kernel at random poses and rates, and
//! the analyses (a pose, a sweep with its singular poses) built on them.

use crate::models::{BOOM, FIVE_BAR, SIX_BAR, SLIDER_CRANK, STEPHENSON_THREE, WATT_SIX_BAR};
use linkage::mechanism::{Fixed, Mechanism};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use proptest::prelude::*;

/// The text inside `#[...linkage(` … `)]` of the struct `name` in `source`.
fn attribute_of(source: &str, name: &str) -> String {
    let at = source
        .find(&format!("pub struct {name} "))
        .unwrap_or_else(|| panic!("no struct {name}"));
    let start = source[..at].rfind("linkage(").expect("an attribute") + "linkage(".len();
    let mut depth = 0;
    for (k, c) in source[start..at].char_indices() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' if depth == 0 => return source[start..start + k].to_owned(),
            ')' | ']' | '}' => depth -= 1,
            _ => {}
        }
    }
    panic!("the attribute of {name} does not end")
}

/// The twin of a compiled mechanism: its attribute read at run time, with
/// the compiled mechanism's parameter values.
fn twin<L, const M: usize, const F: usize, const K: usize>(
    compiled: &L,
    source: &str,
    name: &str,
) -> Fixed<M, F>
where
    L: Sensitivities<M, F, K>,
{
    let values = compiled.params();
    let parameters: Vec<(&str, f64)> = (compiled.param_names().iter().copied())
        .zip(values.iter().copied())
        .collect();
    let mechanism = Mechanism::from_text(name, &attribute_of(source, name), &parameters)
        .unwrap_or_else(|e| panic!("{name} reads at run time: {e}"));
    mechanism.fixed::<M, F>().expect("the compiled sizes")
}

fn same<const R: usize, const C: usize>(
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

fn same_points(what: &str, a: &[Vector2<f64>], b: &[Vector2<f64>]) {
    assert_eq!(a.len(), b.len(), "{what}: the number of points");
    for (p, q) in a.iter().zip(b) {
        same(what, p, q);
    }
}

/// Every kernel of the two at one pose in motion.
#[allow(clippy::too_many_arguments)]
fn every_kernel<L, const M: usize, const F: usize>(
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

/// u, v, u̇, v̇, ü, v̈ as lists.
type Motion6 = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

/// A pose in motion: every coordinate and rate in [−4, 4).
fn motion<const M: usize, const F: usize>() -> impl Strategy<Value = Motion6> {
    let numbers = |n: usize| proptest::collection::vec(-4.0..4.0f64, n);
    (
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
    )
}

macro_rules! twins {
    ($($test:ident: $model:expr, $name:literal, $source:literal, $m:literal, $f:literal, $k:literal;)*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig { cases: 200, failure_persistence: None, ..ProptestConfig::default() })]
            #[test]
            fn $test((u, v, udot, vdot, uddot, vddot) in motion::<$m, $f>()) {
                let compiled = $model;
                let twin = twin::<_, $m, $f, $k>(&compiled, include_str!($source), $name);
                let vector = |x: &[f64]| SVector::<f64, $m>::from_column_slice(x);
                let driver = |x: &[f64]| SVector::<f64, $f>::from_column_slice(x);
                every_kernel(
                    &compiled, &twin,
                    &vector(&u), &driver(&v), &vector(&udot), &driver(&vdot), &vector(&uddot), &driver(&vddot),
                );
            }
        }
    )*};
}

twins! {
    the_worksheets_four_bar: FourBar::WORKSHEET, "FourBar", "../../src/mechanisms.rs", 2, 1, 4;
    the_slider_crank: SLIDER_CRANK, "SliderCrank", "../models/slider_crank.rs", 2, 1, 3;
    the_five_bar: FIVE_BAR, "FiveBar", "../models/five_bar.rs", 2, 2, 5;
    the_boom: BOOM, "Boom", "../models/boom.rs", 2, 1, 4;
    the_six_bar: SIX_BAR, "SixBar", "../models/six_bar.rs", 4, 1, 10;
    the_watt_six_bar: WATT_SIX_BAR, "WattSixBar", "../models/watt_six_bar.rs", 4, 1, 10;
    the_stephenson_three: STEPHENSON_THREE, "StephensonThree", "../models/stephenson_three.rs", 4, 1, 11;
}

/// The analyses on the two: a pose analysed, and a sweep through the
/// worksheet's whole turn, pose by pose the same to the bit.
#[test]
fn a_sweep_of_the_twin_is_the_compiled_sweep() {
    let compiled = FourBar::WORKSHEET;
    let twin = twin::<_, 2, 1, 4>(
        &compiled,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    let options = Options::default();
    let (u0, v0) = (vector![1.2, -0.9], vector![0.35]);
    let a = compiled
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    let b = twin
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    same("analysis.u", &a.u, &b.u);
    same("analysis.uddot", &a.uddot, &b.uddot);
    same_points("analysis.points", a.points.as_ref(), b.points.as_ref());
    let drive = Drive::Line {
        from: vector![0.35],
        to: vector![0.35 + std::f64::consts::TAU],
        steps: 720,
    };
    let sweep_options = SweepOptions::default();
    let a = compiled.sweep(&u0, &drive, &sweep_options).unwrap();
    let b = twin.sweep(&u0, &drive, &sweep_options).unwrap();
    assert_eq!(a.poses.len(), b.poses.len());
    for (p, q) in a.poses.iter().zip(&b.poses) {
        same("pose.v", &p.v, &q.v);
        same("pose.u", &p.u, &q.u);
        same("pose.udot", &p.udot, &q.udot);
        same("pose.uddot", &p.uddot, &q.uddot);
    }
    assert_eq!(a.events.len(), b.events.len());
    assert_eq!(a.complete, b.complete);
}

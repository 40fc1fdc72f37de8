//! Bad input gets a typed error, never a panic and never a NaN inside `Ok`.

use crate::common::{FourBar, OMEGA2};
use linkage::prelude::*;
use std::f64::consts::PI;

fn guess() -> SVector<f64, 2> {
    vector![70f64.to_radians(), -50f64.to_radians()]
}

#[test]
fn non_finite_inputs_are_named() {
    let o = Options::default();
    let v = vector![0.3];
    let err = FourBar::WORKSHEET
        .solve_position(&vector![f64::NAN, 0.0], &v, &o)
        .unwrap_err();
    assert!(
        matches!(err, Error::NonFiniteInput { argument: "u0", index: 0, value } if value.is_nan()),
        "{err}"
    );
    let err = FourBar::WORKSHEET
        .solve_position(&guess(), &vector![f64::INFINITY], &o)
        .unwrap_err();
    assert_eq!(
        err,
        Error::NonFiniteInput {
            argument: "v",
            index: 0,
            value: f64::INFINITY
        }
    );
    let err = FourBar::WORKSHEET
        .velocity(&guess(), &v, &vector![f64::NEG_INFINITY], &o)
        .unwrap_err();
    assert!(
        matches!(
            err,
            Error::NonFiniteInput {
                argument: "vdot",
                ..
            }
        ),
        "{err}"
    );
    let err = FourBar::WORKSHEET
        .analyze(&guess(), &v, &vector![OMEGA2], &vector![f64::NAN], &o)
        .unwrap_err();
    assert!(
        matches!(
            err,
            Error::NonFiniteInput {
                argument: "vddot",
                ..
            }
        ),
        "{err}"
    );
    assert_eq!(err.to_string(), "non-finite input: vddot[0] = NaN");
}

#[test]
fn non_finite_parameters_are_reported() {
    let bar = FourBar {
        l1: f64::NAN,
        ..FourBar::WORKSHEET
    };
    let err = bar
        .solve_position(&guess(), &vector![0.3], &Options::default())
        .unwrap_err();
    assert_eq!(
        err,
        Error::NonFiniteValue {
            stage: Stage::Position,
            quantity: "Ψ"
        }
    );
}

/// The change-point four-bar (l2 = 40: s + l = p + q) at θ2 = 180°: all four
/// joints collinear, det Ψ_u = 0.
#[test]
fn singular_pose_is_detected_with_its_conditioning() {
    let bar = FourBar {
        l2: 40.0,
        ..FourBar::WORKSHEET
    };
    let (u, v) = (vector![0.0, 0.0], vector![PI]);
    assert!(
        bar.psi(&u, &v).amax() < 1e-12,
        "the collinear pose is assembled"
    );
    let err = bar
        .velocity(&u, &v, &vector![1.0], &Options::default())
        .unwrap_err();
    match err {
        Error::Singular {
            stage,
            rcond,
            min_rcond,
        } => {
            assert_eq!(stage, Stage::Velocity);
            assert_eq!(rcond, 0.0);
            assert_eq!(min_rcond, Options::default().min_rcond(Stage::Velocity));
        }
        other => panic!("{other}"),
    }
    // Close to it, the conditioning figure says how close.
    let near = vector![1e-12, -1e-12];
    let err = bar
        .velocity(&near, &v, &vector![1.0], &Options::default())
        .unwrap_err();
    assert!(
        matches!(err, Error::Singular { rcond, min_rcond, .. } if rcond > 0.0 && rcond < min_rcond),
        "{err}"
    );
    assert!(err.to_string().contains("reciprocal condition number"));
    // With the check switched off, the caller gets the (inaccurate) answer.
    let lenient = Options {
        accuracy: f64::INFINITY,
        ..Options::default()
    };
    assert!(bar.velocity(&near, &v, &vector![1.0], &lenient).is_ok());
}

/// The non-Grashof four-bar (l2 = 45) cannot be assembled at θ2 = 180°:
/// Newton fails with a typed error, not a wrong pose.
#[test]
fn unassemblable_pose_is_an_error() {
    let bar = FourBar {
        l2: 45.0,
        ..FourBar::WORKSHEET
    };
    let result = bar.solve_position(&vector![0.1, -0.1], &vector![PI], &Options::default());
    match result {
        Err(Error::NotConverged {
            iterations,
            residual,
            ..
        }) => {
            assert_eq!(iterations, Options::default().max_iterations);
            assert!(residual > 1.0, "the residual stays large: {residual}");
        }
        Err(Error::Singular {
            stage: Stage::Position,
            ..
        }) => {}
        other => panic!("expected an error, got {other:?}"),
    }
}

/// Damped Newton tells "cannot be assembled" from "did not converge": at
/// θ2 = 180° the non-Grashof four-bar's B–D distance is 125 > l3 + l4 = 120,
/// so the closest pose, coupler and rocker stretched along BD, misses by 5.
#[test]
fn damped_newton_reports_cannot_assemble_with_the_gap() {
    let bar = FourBar {
        l2: 45.0,
        ..FourBar::WORKSHEET
    };
    for guess in [vector![0.1, -0.1], vector![2.0, 1.0], vector![-1.0, 2.5]] {
        let err = bar
            .solve_position(&guess, &vector![PI], &Options::damped())
            .unwrap_err();
        match err {
            Error::CannotAssemble {
                residual,
                ref closest,
                gradient,
            } => {
                assert!((residual - 5.0).abs() < 1e-9, "residual {residual}");
                assert!(gradient < 1e-6);
                // Both links point from B to D: θ3 = θ4 = 0 (mod 2π).
                for angle in closest {
                    assert!(angle.sin().abs() < 1e-6 && angle.cos() > 0.0, "{closest:?}");
                }
                assert!(err.to_string().contains("cannot be assembled"), "{err}");
            }
            other => panic!("from {guess:?}: {other}"),
        }
    }
    // Where it can be assembled, damped Newton finds the same pose as Newton.
    let v = vector![20f64.to_radians()];
    let plain = FourBar::WORKSHEET
        .solve_position(&guess(), &v, &Options::default())
        .unwrap();
    let damped = FourBar::WORKSHEET
        .solve_position(&guess(), &v, &Options::damped())
        .unwrap();
    assert!((plain.u - damped.u).amax() < 1e-14);
}

/// From a poor guess plain Newton may wander; damped Newton converges.
#[test]
fn damped_newton_converges_from_poor_guesses() {
    let v = vector![20f64.to_radians()];
    let mut damped_ok = 0;
    for k in 0..36 {
        let a = f64::from(k) * 10f64.to_radians();
        let start = vector![a, -a];
        if let Ok(p) = FourBar::WORKSHEET.solve_position(&start, &v, &Options::damped()) {
            // Either assembly mode is a valid answer; it must satisfy Ψ = 0.
            assert!(FourBar::WORKSHEET.psi(&p.u, &v).amax() < 1e-12);
            damped_ok += 1;
        }
    }
    assert_eq!(
        damped_ok, 36,
        "damped Newton converged from {damped_ok} of 36 guesses"
    );
}

/// Whatever the inputs, an `Ok` holds finite numbers that satisfy the
/// equations; an `Err` is typed.
#[test]
fn no_nan_inside_ok_on_hostile_inputs() {
    let values = [
        0.0,
        -0.0,
        1e-300,
        5e-324,
        1.0,
        -1.0,
        3.0,
        1e8,
        -1e15,
        1e300,
        f64::MAX,
        f64::MIN_POSITIVE,
    ];
    let o = Options::default();
    let mut oks = 0;
    let mut errs = 0;
    for &a in &values {
        for &b in &values {
            for &t in &values {
                match FourBar::WORKSHEET.analyze(
                    &vector![a, b],
                    &vector![t],
                    &vector![OMEGA2],
                    &vector![1.0],
                    &o,
                ) {
                    Ok(r) => {
                        oks += 1;
                        let all =
                            r.u.iter()
                                .chain(&r.udot)
                                .chain(&r.uddot)
                                .chain(r.points.iter().flat_map(|p| p.iter()));
                        assert!(all.copied().all(f64::is_finite), "{r:?}");
                        assert!(FourBar::WORKSHEET.psi(&r.u, &vector![t]).amax() <= o.residual_tol);
                    }
                    Err(_) => errs += 1,
                }
            }
        }
    }
    assert!(oks > 0 && errs > 0, "{oks} ok, {errs} errors");
}

#[test]
fn newton_reports_iterations_and_residual() {
    let p = FourBar::WORKSHEET
        .solve_position(&guess(), &vector![20f64.to_radians()], &Options::default())
        .unwrap();
    assert!(p.iterations >= 3 && p.iterations <= 5, "{}", p.iterations);
    assert!(p.residual < 1e-13);
    // A cap of one step is not enough from (70°, −50°).
    let err = FourBar::WORKSHEET
        .solve_position(
            &guess(),
            &vector![20f64.to_radians()],
            &Options {
                max_iterations: 1,
                ..Options::default()
            },
        )
        .unwrap_err();
    match err {
        Error::NotConverged {
            iterations: 1,
            residual,
            step,
        } => {
            assert!(residual > 1e-4 && step > 1e-3, "{residual} {step}");
        }
        other => panic!("{other}"),
    }
}

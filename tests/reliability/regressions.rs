//! Failures the long campaigns found, kept as fixed cases.

use crate::common::FourBar;
use crate::harness::{Truth, four_bar_truth};
use linkage::prelude::*;

/// Failures the long campaigns found, kept as fixed cases.
#[test]
fn regressions() {
    // All links 1, θ₂ = 187°: the pivots B and D are 1.9963 apart, just
    // inside the dyad's reach of 2. From θ₃ = θ₄ = 0 the iterates stay
    // symmetric and stall at the stretched dyad, a saddle of ½‖Ψ‖² with
    // ‖Ψ‖∞ = 3.7e-3; it was once reported as CannotAssemble.
    let bar = FourBar {
        l1: 1.0,
        l2: 1.0,
        l3: 1.0,
        l4: 1.0,
    };
    let options = Options {
        damped: true,
        ..Options::default()
    };
    let theta2 = -9.303165937741154;
    let pose = bar
        .solve_position(&vector![-1e-300, -1e-300], &vector![theta2], &options)
        .expect("the four-bar assembles");
    assert!(pose.residual <= options.residual_tol);
    assert!(matches!(
        four_bar_truth([1.0; 4], theta2),
        Truth::Assembles { .. }
    ));
}

/// A frame of 3e23 with a crank of 1.27 driven at θ̇₂ = −1e-300: the true
/// u̇ is about 1e-323, a subnormal number with no relative precision left.
/// It was once returned as `Ok` with u̇ = 0; now it is an `Underflow`.
/// A drive whose step is so long that its Euclidean norm overflowed in
/// the computing (|step|² > f64::MAX) made the sweep's rate 0: every pose
/// reported v̇ = 0 and u̇ = 0 for a moving driver. The step's length is now
/// taken at scale.
#[test]
fn huge_steps_keep_their_speed() {
    let from = 20f64.to_radians();
    let [t3, t4] = FourBar::WORKSHEET
        .closed_form()
        .position(from, 1.0)
        .unwrap();
    for step in [1e160, -1e200] {
        // One pose only (the first step cannot be taken): the start, at the
        // sweep's speed.
        let summary = FourBar::WORKSHEET.sweep_each(
            &vector![t3, t4],
            &Drive::Rocking {
                from: vector![from],
                step: vector![step],
                max_steps: 1,
            },
            &SweepOptions::default(),
            |pose| {
                assert_eq!(pose.vdot[0], step.signum(), "v̇ at speed 1");
                assert!(pose.udot.amax() > 0.1, "u̇ = {:?}", pose.udot);
            },
        );
        assert!(summary.is_err() || summary.unwrap().poses >= 1);
    }
}

#[test]
fn subnormal_velocities_are_underflow() {
    let (l1, l2, theta2): (f64, f64, f64) =
        (2.9847149370108802e23, 1.2736528197825383, 9.527996370732259);
    let b = Vector2::new(l2 * theta2.cos(), l2 * theta2.sin());
    let c = Vector2::new(2.9748600056257435, 0.2004409639425302) * l1;
    let d = Vector2::new(l1, 0.0);
    let bar = FourBar {
        l1,
        l2,
        l3: (c - b).norm(),
        l4: (d - c).norm(),
    };
    let guess = vector![(c - b).y.atan2((c - b).x), (d - c).y.atan2((d - c).x)];
    let options = Options::default();
    let result = bar.analyze(
        &guess,
        &vector![theta2],
        &vector![-1e-300],
        &vector![0.0],
        &options,
    );
    assert!(matches!(result, Err(Error::Underflow { .. })), "{result:?}");
    // The same mechanism at an ordinary speed is fine.
    let a = bar
        .analyze(
            &guess,
            &vector![theta2],
            &vector![-1.0],
            &vector![0.0],
            &options,
        )
        .expect("an ordinary speed");
    assert!(a.udot.amax() > 0.0);
}

/// A rhombus of unit links (all equal) at θ̇₂ = 88.75, θ̈₂ = 2.2e-308: γ's
/// terms, of size θ̇₂², cancel, and ü is tiny; that is no underflow (the
/// error is relative to the terms), and methods A and B must agree. Once
/// one said `Underflow` while the other said `Ok`.
#[test]
fn cancellation_is_not_underflow() {
    let unit = FourBar {
        l1: 1.0,
        l2: 1.0,
        l3: 1.0,
        l4: 1.0,
    };
    let damped = Options {
        damped: true,
        ..Options::default()
    };
    methods_agree_with_the_analysis(
        &unit,
        &damped,
        [5.66924140171174, -1.3335562559465945],
        [
            -6.793924208014447,
            88.75085585176765,
            2.2250738585072014e-308,
        ],
    );
    // Rhombi of 26.4 at θ̇₂ = 20.6 and θ̈₂ = 5e-324: ü is subnormal, but the
    // terms it is made of are not; methods A and B cancel γ exactly and
    // once said `Underflow` where the fused γ said `Ok`.
    let side = 26.382266724994903;
    let rhombus = FourBar {
        l1: side,
        l2: side,
        l3: side,
        l4: side,
    };
    methods_agree_with_the_analysis(
        &rhombus,
        &Options::default(),
        [4.218873701362285, 2.2040557835185792],
        [-0.9480644196028856, 20.609772770627007, 5e-324],
    );
}

/// `analyze` from `guess` at (θ2, θ̇2, θ̈2) = `drive`, then ü by methods A
/// and B at its pose: no error, and equal to the analysis' ü within 1e-13
/// of θ̇2².
fn methods_agree_with_the_analysis(
    bar: &FourBar,
    options: &Options,
    guess: [f64; 2],
    drive: [f64; 3],
) {
    let (v, vdot, vddot) = (vector![drive[0]], vector![drive[1]], vector![drive[2]]);
    let a = bar
        .analyze(&vector![guess[0], guess[1]], &v, &vdot, &vddot, options)
        .expect("the rhombus assembles");
    for method in [AccelerationMethod::A, AccelerationMethod::B] {
        let with = Options { method, ..*options };
        let uddot = bar
            .acceleration(&a.u, &v, &a.udot, &vdot, &vddot, &with)
            .expect("no underflow");
        assert!((uddot - a.uddot).amax() <= 1e-13 * vdot[0] * vdot[0]);
    }
}

/// The worksheet's crank-rocker turned through 10⁴ rad in two steps: with
/// at most 0.1 rad per sub-step that needs 5·10⁴ sub-steps a step. Once a
/// drive of 1e300 rad sub-stepped forever; now the budget stops it.
#[test]
fn endless_drives_hit_the_substep_limit() {
    let options = SweepOptions {
        max_substeps: 1000,
        ..SweepOptions::default()
    };
    let guess = vector![0.3, 1.5];
    let far = Drive::Line {
        from: vector![0.0],
        to: vector![1e4],
        steps: 2,
    };
    let result = FourBar::WORKSHEET.sweep(&guess, &far, &options);
    assert!(
        matches!(
            result,
            Err(Error::SubstepLimit {
                step: 1,
                limit: 1000
            })
        ),
        "{:?}",
        result.map(|s| s.poses.len())
    );
    // One turn in 36 steps stays well within the same budget.
    let turn = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: 36,
    };
    let sweep = FourBar::WORKSHEET
        .sweep(&guess, &turn, &options)
        .expect("one turn");
    assert!(sweep.complete && sweep.poses.len() == 37);
}

/// Angles do not care about units: a mechanism scaled by k (and its
/// residual tolerance with it) has the same angles, angular velocities and
/// angular accelerations, whatever k. The
/// runtime must give them (or say `Underflow`, never a wrong `Ok`) for k
/// from 1e-250 to 1e250, at speeds from 1e-40 to 1e3, on the fused and the
/// separate paths and from the stretched-dyad saddle. A review found each
/// of these broken once: a tiny mechanism's γ underflowed inside `Ok`, the
/// fused kernel returned ü = 0, and the merit ½‖Ψ‖² underflowed so that a
/// saddle looked like a minimum.
#[test]
fn angles_are_scale_invariant() {
    let base = [1.0, 1.0, 1.0, 1.0];
    let theta2 = -9.303165937741154;
    let near = vector![0.9, -0.8];
    let saddle = vector![-1e-300, -1e-300];
    for k in [1e-250, 1e-170, 1e-60, 1.0, 1e60, 1e170, 1e250] {
        let bar = |l: [f64; 4]| FourBar {
            l1: l[0] * k,
            l2: l[1] * k,
            l3: l[2] * k,
            l4: l[3] * k,
        };
        let (unit, scaled) = (bar(base.map(|x| x / k)), bar(base));
        for omega in [1e-40, 1e-3, 1.0, 1e3] {
            for method in [
                AccelerationMethod::Fused,
                AccelerationMethod::A,
                AccelerationMethod::B,
            ] {
                for guess in [near, saddle] {
                    let options = Options {
                        damped: true,
                        method,
                        ..Options::default()
                    };
                    let (v, vdot, vddot) = (vector![theta2], vector![omega], vector![0.5 * omega]);
                    let truth = unit
                        .analyze(&guess, &v, &vdot, &vddot, &options)
                        .expect("the unit rhombus");
                    // The residual tolerance is in the mechanism's units.
                    let options = Options {
                        residual_tol: options.residual_tol * k,
                        ..options
                    };
                    match scaled.analyze(&guess, &v, &vdot, &vddot, &options) {
                        Ok(a) => {
                            // To rounding of the terms each is made of:
                            // angles of size 1, rates of ω, accelerations
                            // of ω² + θ̈₂.
                            let close = |x: &SVector<f64, 2>, y: &SVector<f64, 2>, size: f64| {
                                (x - y).amax() <= 1e-12 * size
                            };
                            assert!(
                                close(&a.u, &truth.u, 1.0)
                                    && close(&a.udot, &truth.udot, omega)
                                    && close(&a.uddot, &truth.uddot, omega * omega + vddot[0]),
                                "k = {k:e}, ω = {omega:e}, {method:?}: {:?} against {:?}",
                                (a.u, a.udot, a.uddot),
                                (truth.u, truth.udot, truth.uddot)
                            );
                        }
                        Err(Error::Underflow { .. }) => {}
                        Err(e) => panic!("k = {k:e}, ω = {omega:e}, {method:?}: {e}"),
                    }
                }
            }
        }
    }
}

/// Velocities below the normal range (1e-309) with an ordinary v̈: ü is
/// Ψ_u⁻¹Ψ_v v̈ to full precision, the vanishing γ notwithstanding. Once the
/// scaling of the velocities divided by zero here.
#[test]
fn subnormal_velocities_with_an_ordinary_acceleration() {
    let options = Options::default();
    let v = vector![20f64.to_radians()];
    let pose = FourBar::WORKSHEET
        .solve_position(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &v,
            &options,
        )
        .expect("the worksheet's pose");
    let rest = FourBar::WORKSHEET
        .acceleration(
            &pose.u,
            &v,
            &vector![0.0, 0.0],
            &vector![0.0],
            &vector![1.0],
            &options,
        )
        .expect("at rest");
    for method in [
        AccelerationMethod::A,
        AccelerationMethod::B,
        AccelerationMethod::Fused,
    ] {
        let with = Options { method, ..options };
        let udot = vector![1e-309, -2e-309];
        let uddot = FourBar::WORKSHEET
            .acceleration(&pose.u, &v, &udot, &vector![1e-309], &vector![1.0], &with)
            .expect("γ ≈ 1e-618 is nothing beside Ψ_v v̈");
        assert!((uddot - rest).amax() <= 1e-15 * rest.amax(), "{method:?}");
    }
}

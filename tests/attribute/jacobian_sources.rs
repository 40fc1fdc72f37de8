//! The alternative sources of derivatives — num-dual on `psi_generic` and
//! central finite differences — give the worksheet's answers to their own
//! accuracy, through the same runtime.

use crate::common::{FourBar, OMEGA2, rel_norm};
use linkage::prelude::*;

fn analyze(jacobian: JacobianSource) -> Analysis<2, 1, [Vector2<f64>; 5]> {
    FourBar::WORKSHEET
        .analyze(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &vector![20f64.to_radians()],
            &vector![OMEGA2],
            &vector![37.0],
            &Options {
                jacobian,
                ..Options::default()
            },
        )
        .unwrap()
}

#[test]
fn dual_numbers_agree_to_rounding_and_finite_differences_to_their_truncation() {
    let exact = analyze(JacobianSource::Generated);
    for (source, position, velocity, acceleration) in [
        (JacobianSource::Dual, 1e-15, 1e-15, 1e-15),
        (JacobianSource::FiniteDifference, 1e-15, 1e-10, 1e-7),
    ] {
        let a = analyze(source);
        let e = [
            rel_norm(a.u.as_slice(), exact.u.as_slice(), 0.0),
            rel_norm(a.udot.as_slice(), exact.udot.as_slice(), 0.0),
            rel_norm(a.uddot.as_slice(), exact.uddot.as_slice(), 0.0),
        ];
        eprintln!(
            "{source:?}: relative errors of u, u̇, ü: {:.1e}, {:.1e}, {:.1e}",
            e[0], e[1], e[2]
        );
        assert!(
            e[0] <= position && e[1] <= velocity && e[2] <= acceleration,
            "{source:?}: {e:?}"
        );
    }
}

#[test]
fn every_source_solves_newton_to_full_precision() {
    // Newton converges to the root whatever the Jacobian's accuracy: only
    // the rate changes.
    for source in [
        JacobianSource::Generated,
        JacobianSource::Dual,
        JacobianSource::FiniteDifference,
    ] {
        for damped in [false, true] {
            let p = FourBar::WORKSHEET
                .solve_position(
                    &vector![70f64.to_radians(), -50f64.to_radians()],
                    &vector![20f64.to_radians()],
                    &Options {
                        jacobian: source,
                        damped,
                        ..Options::default()
                    },
                )
                .unwrap();
            assert!(
                p.residual < 1e-13,
                "{source:?}, damped {damped}: {}",
                p.residual
            );
        }
    }
}

/// `analyze`'s lean path (every Newton evaluation the fused kernel, the
/// iterates' sines and cosines carried) against the general one (method B:
/// Newton on Ψ and Ψ_u, then the separate solves): the same pose, velocities
/// and accelerations to rounding at every degree of the cycle from a guess
/// 0.2 rad off, and the reported residual is `psi`'s at the returned pose,
/// to the bit.
#[test]
fn the_lean_analysis_agrees_with_the_separate_solves() {
    let bar = FourBar::WORKSHEET;
    let closed = bar.closed_form();
    let general = Options {
        method: AccelerationMethod::B,
        ..Options::default()
    };
    let (vdot, vddot) = (vector![OMEGA2], vector![37.0]);
    for degree in 0..360 {
        let v = vector![f64::from(degree).to_radians()];
        let exact = closed.position(v[0], 1.0).expect("a crank-rocker");
        let guess = vector![exact[0] + 0.2, exact[1] - 0.2];
        let lean = bar
            .analyze(&guess, &v, &vdot, &vddot, &Options::default())
            .unwrap();
        let separate = bar.analyze(&guess, &v, &vdot, &vddot, &general).unwrap();
        assert_eq!(lean.residual, bar.psi(&lean.u, &v).amax(), "θ2 = {degree}°");
        for (name, a, b, tol) in [
            // Newton ends within rounding of the root either way: a few
            // ulps apart.
            ("u", lean.u, separate.u, 4.0 * f64::EPSILON),
            ("u̇", lean.udot, separate.udot, 1e-14),
            ("ü", lean.uddot, separate.uddot, 1e-13),
        ] {
            let error = rel_norm(a.as_slice(), b.as_slice(), 1.0);
            assert!(error <= tol, "θ2 = {degree}°, {name}: {error:e}");
        }
    }
}

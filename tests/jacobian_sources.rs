//! The alternative sources of derivatives — num-dual on `psi_generic` and
//! central finite differences — give the worksheet's answers to their own
//! accuracy, through the same runtime.

mod common;

use common::{FourBar, OMEGA2, rel_norm};
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

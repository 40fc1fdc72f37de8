//! Bad settings, bad machines and a bad synthesis are typed errors.

use crate::machine::{COURSE_PROJECT, Data, Shaper, machine, synthesize};
use linkage::error::{NameKind, UnknownName};
use linkage::machine::{Machine, MachineError, Motor, flywheel};
use linkage::prelude::*;
use std::f64::consts::TAU;

/// Settings out of their range are typed errors: δ of 2 or more (ω_min
/// would not be positive), a motor with NaN numbers, a grid of usize::MAX
/// poses (it once meant a sweep of that many steps), a load direction of
/// zero, a load that returns NaN.
#[test]
fn bad_settings_of_a_machine_are_typed_errors() {
    use linkage::machine::{Body, Load, MachineError as E};
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = machine(&shaper, &COURSE_PROJECT).unwrap();
    let omega = TAU * COURSE_PROJECT.n1;
    for delta in [2.0, 3.0, 0.0, -0.1, f64::NAN] {
        assert!(
            matches!(m.energy_method(omega, delta), Err(E::BadSetting { .. })),
            "δ = {delta}"
        );
    }
    let e = m.energy_method(omega, COURSE_PROJECT.delta).unwrap();
    for motor in [
        Motor::Constant { moment: f64::NAN },
        Motor::Linear {
            moment: 1.0,
            speed: 0.0,
            slope: 1.0,
        },
        Motor::Linear {
            moment: 1.0,
            speed: omega,
            slope: f64::INFINITY,
        },
    ] {
        assert!(
            matches!(
                m.steady_motion(e.flywheel, motor, omega, 100),
                Err(E::BadSetting { .. })
            ),
            "{motor:?}"
        );
    }
    let build = |load: Load| {
        Machine::new(shaper, shaper.guess())
            .body(Body::new("ram").mass(1.0).at("S5"))
            .load(load)
            .build()
            .err()
    };
    assert!(matches!(
        Machine::new(shaper, shaper.guess())
            .grid(usize::MAX)
            .build()
            .err(),
        Some(E::BadSetting { .. })
    ));
    assert!(matches!(
        build(Load::friction("f", "F", nalgebra::Vector2::zeros(), 1.0)),
        Some(E::BadSetting { .. })
    ));
    assert!(matches!(
        build(Load::gravity("g", nalgebra::Vector2::new(0.0, f64::NAN))),
        Some(E::BadSetting { .. })
    ));
    assert!(matches!(
        build(Load::force("nan", "K", |_| nalgebra::Vector2::new(
            f64::NAN,
            0.0
        ))),
        Some(E::NonFiniteLoad { .. })
    ));
    assert!(matches!(
        flywheel::from_md2(-1.0),
        Err(E::BadSetting { .. })
    ));
    assert!(matches!(
        flywheel::on_motor_shaft(1.0, 0.0, 0.1, 0.1),
        Err(E::BadSetting { .. })
    ));
    assert!(matches!(
        flywheel::Rim::course_rule(f64::NAN),
        Err(E::BadSetting { .. })
    ));
}

/// A time ratio of 1 or less would mirror the machine (K_V = 0.8 gave a
/// swing of −20°): the synthesis says so instead.
#[test]
fn the_synthesis_rejects_a_time_ratio_of_one_or_less() {
    for k_v in [0.8, 1.0, f64::NAN, f64::INFINITY] {
        let data = Data {
            k_v,
            ..COURSE_PROJECT
        };
        let err = synthesize(&data).err();
        assert!(
            matches!(
                err,
                Some(MachineError::BadSetting {
                    what: "the time ratio K_V",
                    ..
                })
            ),
            "K_V = {k_v}: {err:?}"
        );
        eprintln!("K_V = {k_v}: {}", err.unwrap());
    }
    assert!(
        synthesize(&Data {
            stroke: 0.0,
            ..COURSE_PROJECT
        })
        .is_err()
    );
}

#[test]
fn bad_machines_are_typed_errors() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let err = Machine::new(shaper, shaper.guess())
        .body(linkage::machine::Body::new("ram").mass(1.0).at("Q"))
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(err, linkage::machine::MachineError::UnknownName(UnknownName { kind: NameKind::Point, ref name, .. }) if name == "Q"),
        "{err}"
    );
    let err = Machine::new(shaper, shaper.guess())
        .body(
            linkage::machine::Body::new("rocker")
                .inertia(1.0)
                .angle("psi"),
        )
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(
            err,
            linkage::machine::MachineError::UnknownName(UnknownName {
                kind: NameKind::Coordinate,
                ..
            })
        ),
        "{err}"
    );
    assert!(linkage::machine::Table::new(vec![(0.0, 1.0), (0.0, 2.0)]).is_err());
    let err = Machine::new(shaper, shaper.guess())
        .body(linkage::machine::Body::new("ram").mass(-1.0).at("S5"))
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(err, linkage::machine::MachineError::BadSetting { .. }),
        "{err}"
    );
    // A crank as long as the pivot distance: A passes through C, where the
    // rocker's angle is undefined.
    let broken = Shaper {
        l_oa: -shaper.y_c,
        ..shaper
    };
    let err = Machine::new(broken, broken.guess()).build().err().unwrap();
    assert!(
        matches!(
            err,
            linkage::machine::MachineError::Incomplete { .. }
                | linkage::machine::MachineError::Kinematics(_)
        ),
        "{err}"
    );
}

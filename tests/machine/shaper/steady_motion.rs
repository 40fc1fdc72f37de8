//! The flywheel and the machine's motion with other inputs: the method's
//! invariants, the real (steady) motion and its extremes, and the work of a
//! force that jumps over any angle.

use crate::machine::{COURSE_PROJECT, Data, machine, synthesize};
use linkage::machine::{MachineError, Motor};
use std::f64::consts::TAU;

#[test]
fn other_inputs_keep_the_methods_invariants() {
    let data = Data {
        k_v: 1.4,
        stroke: 0.4,
        m5: 80.0,
        ..COURSE_PROJECT
    };
    let shaper = synthesize(&data).unwrap();
    let m = machine(&shaper, &data).unwrap();
    // The stroke is H and the time ratio K_V: the ram's extremes at the
    // dead positions φ = 0 and π + β.
    let dead = std::f64::consts::PI + shaper.beta();
    let (x0, x1) = (
        m.analysis(0.0).unwrap().u[2],
        m.analysis(dead).unwrap().u[2],
    );
    assert!((x1 - x0 - data.stroke).abs() < 1e-13);
    assert!((dead / (TAU - dead) - data.k_v).abs() < 1e-13);
    // Energy balance over a cycle: M_D·2π = −A(2π) = the cutting diagram's
    // area + friction over both strokes (gravity does no work over a cycle).
    let area = linkage::machine::Table::new(
        data.cutting
            .iter()
            .map(|&(s, f)| (s * data.stroke, f))
            .collect(),
    )
    .unwrap()
    .area();
    let resistances = area + data.friction * 2.0 * data.stroke;
    assert!(
        (m.mean_driving_moment() * TAU - resistances).abs() <= 1e-11 * resistances,
        "{} vs {resistances}",
        m.mean_driving_moment() * TAU
    );
    // The energy method keeps ω within ω_m(1 ± δ/2), reached at the extremes
    // of ΔT_I.
    let omega = TAU * data.n1;
    let e = m.energy_method(omega, data.delta).unwrap();
    let (lo, hi) = e.omega_extremes();
    for (phi, expected) in [lo, hi] {
        assert!((e.omega(phi).unwrap() - expected).abs() <= 1e-12 * omega);
    }
    assert!((lo.1 - omega * (1.0 - data.delta / 2.0)).abs() < 1e-12);
    for k in 0..720 {
        let w = e.omega(k as f64 * TAU / 720.0).unwrap();
        assert!(w >= lo.1 - 1e-12 && w <= hi.1 + 1e-12);
    }
    // The real motion with that flywheel fluctuates by about δ.
    let real = m
        .steady_motion(
            e.flywheel,
            Motor::Constant {
                moment: e.driving_moment,
            },
            omega,
            4000,
        )
        .unwrap();
    assert!(
        (real.delta - data.delta).abs() < 0.2 * data.delta,
        "{}",
        real.delta
    );
}

#[test]
fn the_real_motion_is_periodic_and_conserves_energy() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = machine(&shaper, &COURSE_PROJECT).unwrap();
    let omega = TAU * COURSE_PROJECT.n1;
    let e = m.energy_method(omega, COURSE_PROJECT.delta).unwrap();
    let real = m
        .steady_motion(
            e.flywheel,
            Motor::Constant {
                moment: e.driving_moment,
            },
            omega,
            4000,
        )
        .unwrap();
    // With the mean driving moment, T(φ) = T(0) + A(φ) + M_D·φ exactly:
    // the integrator against the energy integral.
    let j = |phi: f64| e.flywheel + m.reduced(phi).unwrap().inertia;
    let t0 = 0.5 * j(0.0) * real.omega[0] * real.omega[0];
    let mut worst: f64 = 0.0;
    for (k, (&phi, &w)) in real.phi.iter().zip(&real.omega).enumerate().step_by(97) {
        let exact = (2.0 * (t0 + m.work(phi).unwrap() + e.driving_moment * phi) / j(phi)).sqrt();
        worst = worst.max((w - exact).abs() / exact);
        let _ = k;
    }
    assert!(worst < 1e-10, "RK4 against the energy integral: {worst:e}");
    assert!((real.omega[real.omega.len() - 1] - real.omega[0]).abs() < 1e-10);
    assert!((0.5 * (real.omega_min.1 + real.omega_max.1) - omega).abs() < 1e-9);
    // The energy method's estimate against the achieved fluctuation.
    assert!(
        real.delta < COURSE_PROJECT.delta && real.delta > 0.9 * COURSE_PROJECT.delta,
        "{}",
        real.delta
    );
    // A motor with a falling characteristic settles on a periodic motion
    // too, found by shooting: ω(2π) = ω(0), and energy balances.
    let motor = Motor::Linear {
        moment: e.driving_moment,
        speed: omega,
        slope: 50.0,
    };
    let settled = m.steady_motion(e.flywheel, motor, omega, 4000).unwrap();
    let n = settled.omega.len();
    assert!((settled.omega[n - 1] - settled.omega[0]).abs() < 1e-9);
    assert!(settled.delta < COURSE_PROJECT.delta);
}

/// The real motion's extremes of ω are located between the nodes (ε = 0
/// there), not read off the grid: they bound every node, and agree between
/// a coarse and a fine grid far better than the grid's spacing would allow.
#[test]
fn the_real_motion_locates_its_extremes() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = machine(&shaper, &COURSE_PROJECT).unwrap();
    let omega = TAU * COURSE_PROJECT.n1;
    let e = m.energy_method(omega, COURSE_PROJECT.delta).unwrap();
    let motor = Motor::Constant {
        moment: e.driving_moment,
    };
    let coarse = m.steady_motion(e.flywheel, motor, omega, 500).unwrap();
    let fine = m.steady_motion(e.flywheel, motor, omega, 8000).unwrap();
    for run in [&coarse, &fine] {
        assert!(
            run.omega
                .iter()
                .all(|&w| w >= run.omega_min.1 && w <= run.omega_max.1)
        );
    }
    let spacing = TAU / 500.0;
    for (a, b) in [
        (coarse.omega_min, fine.omega_min),
        (coarse.omega_max, fine.omega_max),
    ] {
        assert!((a.0 - b.0).abs() < 1e-3 * spacing, "φ {} vs {}", a.0, b.0);
        assert!((a.1 - b.1).abs() < 1e-9 * omega, "ω {} vs {}", a.1, b.1);
    }
    assert!(matches!(
        m.steady_motion(e.flywheel, motor, omega, 5),
        Err(MachineError::BadSetting { .. })
    ));
}

/// A cutting force that starts and stops at full value: a table that
/// jumps. The work integral splits at the jumps (they are kinks), so the
/// energy balance holds exactly; and the work over several cycles, or
/// backwards, is whole cycles of A(2π) plus the rest, as the pose repeats.
#[test]
fn a_force_that_jumps_and_work_over_any_angle() {
    let force = 9000.0;
    let data = Data {
        cutting: [
            (0.0, 0.0),
            (0.05, 0.0),
            (0.05, force),
            (0.5, force),
            (0.95, force),
            (0.95, 0.0),
            (1.0, 0.0),
        ],
        ..COURSE_PROJECT
    };
    let shaper = synthesize(&data).unwrap();
    let m = machine(&shaper, &data).unwrap();
    let resistances = force * 0.9 * data.stroke + data.friction * 2.0 * data.stroke;
    assert!(
        (m.mean_driving_moment() * TAU - resistances).abs() <= 1e-11 * resistances,
        "{} vs {resistances}",
        m.mean_driving_moment() * TAU
    );
    let a = |phi: f64| m.work(phi).unwrap();
    let cycle = m.cycle_work();
    for phi in [0.3, 2.0, 5.9] {
        for n in [-2.0, -1.0, 1.0, 3.0] {
            let expected = a(phi) + n * cycle;
            let got = a(phi + n * TAU);
            assert!(
                (got - expected).abs() <= 1e-9 * cycle.abs(),
                "A({phi} + {n}·2π) = {got}, expected {expected}"
            );
        }
    }
    assert!(matches!(
        m.work(f64::NAN),
        Err(MachineError::BadSetting { .. })
    ));
}

//! The shaping machine of the course project (seed 002), first half:
//! synthesis, kinematics, reduced dynamics, work, the flywheel by the energy
//! method, ω1 and ε1 — against the 50-digit reference
//! (tests/data/shaper_cam_reference.csv), and, with other inputs, against
//! the invariants of the method.

#[path = "../examples/shaper/machine.rs"]
mod machine;

use linkage::error::{NameKind, UnknownName};
use linkage::machine::{Machine, MachineError, Motor, flywheel};
use linkage::prelude::*;
use machine::{Data, SEED, Shaper, machine, synthesize};
use std::collections::HashMap;
use std::f64::consts::TAU;

/// key → (exact value, the seed's printed text).
fn reference() -> HashMap<String, (f64, Option<String>)> {
    include_str!("data/shaper_cam_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("key,"))
        .map(|l| {
            let cols: Vec<&str> = l.split(',').collect();
            let value = cols[1].parse().unwrap_or(f64::NAN);
            let seed = (!cols[2].is_empty()).then(|| cols[2].to_string());
            (cols[0].to_string(), (value, seed))
        })
        .collect()
}

/// Everything the first half of the course project computes, by linkage.
fn ours(data: &Data) -> HashMap<&'static str, f64> {
    let shaper = synthesize(data).unwrap();
    let m = machine(&shaper, data).expect("the shaper runs its cycle");
    let f = shaper.seed_position();
    let omega = TAU * data.n1;
    let mut out = HashMap::new();
    let mut put = |k: &'static str, v: f64| {
        out.insert(k, v);
    };
    put("shaper.omega1cp", omega);
    put("shaper.l_f", data.l_s5.hypot(data.l_p));
    put(
        "shaper.fi_r_deg",
        (data.l_p / data.l_s5).atan().to_degrees(),
    );
    put("shaper.beta", shaper.beta());
    put("shaper.beta_deg", shaper.beta().to_degrees());
    put("shaper.l_CD", shaper.l_cd);
    put("shaper.l_OA", shaper.l_oa);
    put("shaper.y_C", shaper.y_c);
    put("shaper.y_F", shaper.y_f);
    put("shaper.phi0_deg", shaper.phi0.to_degrees());
    put("shaper.f_deg", f.to_degrees());
    put("shaper.f", f);
    put("shaper.phi1_f_deg", (shaper.phi0 - f).to_degrees());
    let a = m.analysis(f).unwrap();
    let point = |name| Shaper::point_index(name).unwrap();
    let (pa, pd, ps3) = (point("A"), point("D"), point("S3"));
    put("shaper.x_A", a.points[pa].x);
    put("shaper.y_A", a.points[pa].y);
    put("shaper.phi3_deg", a.u[0].to_degrees());
    put("shaper.x_D", a.points[pd].x);
    put("shaper.y_D", a.points[pd].y);
    put("shaper.x_S3", a.points[ps3].x);
    put("shaper.y_S3", a.points[ps3].y);
    // The analogs: velocities and accelerations at φ̇ = 1, φ̈ = 0.
    put("shaper.v_qDx", a.point_velocities[pd].x);
    put("shaper.v_qS3x", a.point_velocities[ps3].x);
    put("shaper.v_qS3y", a.point_velocities[ps3].y);
    put("shaper.omega_q3", a.udot[0]);
    put("shaper.a_qDx", a.point_accelerations[pd].x);
    put("shaper.a_qS3x", a.point_accelerations[ps3].x);
    put("shaper.a_qS3y", a.point_accelerations[ps3].y);
    put("shaper.eps_q3", a.uddot[0]);
    let r = m.reduced(f).unwrap();
    // Bodies: rocker 3, ram 5; [I ω_q², m v_q², 2I ω_q ε_q, 2m v_q·a_q].
    put("shaper.J_PR3j", r.bodies[0][0]);
    put("shaper.J_PR3m", r.bodies[0][1]);
    put("shaper.J_PR5m", r.bodies[1][1]);
    put("shaper.J_PRII", r.inertia);
    put("shaper.dJ_PR3j", r.bodies[0][2]);
    put("shaper.dJ_PR3m", r.bodies[0][3]);
    put("shaper.dJ_PR5m", r.bodies[1][3]);
    put("shaper.dJ_PRII", r.inertia_derivative);
    let start = m.analysis(0.0).unwrap();
    let s_d = a.points[pd].x - start.points[pd].x;
    put("shaper.s_D_f", s_d);
    put("shaper.s_D_f_over_H", s_d / data.stroke);
    let pose = m.pose(f).unwrap();
    let cutting = m
        .applied(&pose)
        .unwrap()
        .into_iter()
        .find_map(|(load, applied)| match applied {
            linkage::machine::Applied::Force { force, .. } if load == 0 => Some(force.x),
            _ => None,
        })
        .unwrap();
    put("shaper.F_Cx_f", cutting);
    // Loads: cutting, friction, gravity.
    put("shaper.M_PRFC", r.loads[0]);
    put("shaper.M_PRFtr", r.loads[1]);
    put("shaper.M_PRG3", r.loads[2]);
    put("shaper.M_PRCsum_f", r.moment);
    put("shaper.A_C_f", m.work(f).unwrap());
    put("shaper.A_C_2pi", m.cycle_work());
    let cutting_table: f64 = data
        .cutting
        .windows(2)
        .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0) * data.stroke)
        .sum();
    put("shaper.cutting_work_per_cycle", cutting_table);
    let md = m.mean_driving_moment();
    put("shaper.M_PRDsr", md);
    put("shaper.A_D_f", md * f);
    put("shaper.A_Sigma_f", m.work(f).unwrap() + md * f);
    put("shaper.T_II_f", 0.5 * r.inertia * omega * omega);
    let e = m.energy_method(omega, data.delta).unwrap();
    put("shaper.dT_I_f", e.delta_t(f).unwrap());
    put("shaper.phi_min", e.minimum.0);
    put("shaper.dT_Imin", e.minimum.1);
    put("shaper.phi_max", e.maximum.0);
    put("shaper.dT_Imax", e.maximum.1);
    put("shaper.dT_Inb", e.maximum.1 - e.minimum.1);
    put("shaper.J_PRI", e.flywheel);
    let ratio = data.n_motor / data.n1;
    put("shaper.u_motor_to_crank", ratio);
    let j_m = flywheel::on_motor_shaft(
        e.flywheel,
        ratio,
        flywheel::from_md2(data.md2_motor).unwrap(),
        flywheel::from_md2(data.md2_gears).unwrap(),
    )
    .unwrap();
    put("shaper.J_m", j_m);
    put("shaper.omega1_f", e.omega(f).unwrap());
    put("shaper.eps1_f", e.epsilon(f).unwrap());
    put("shaper.omega_n", e.omega(0.0).unwrap());
    put("shaper.eps_n", e.epsilon(0.0).unwrap());
    let (w_min, w_max) = e.omega_extremes();
    put("shaper.omega1_min", w_min.1);
    put("shaper.omega1_max", w_max.1);
    let (eps_min, eps_max) = e.epsilon_extremes().unwrap();
    put("shaper.phi_min2", eps_min.0);
    put("shaper.eps1_min", eps_min.1);
    put(
        "shaper.eps1_at_phi_min_literal",
        e.epsilon(e.minimum.0).unwrap(),
    );
    put("shaper.phi_max2", eps_max.0);
    put("shaper.eps1_max", eps_max.1);
    let rim = flywheel::Rim::course_rule(j_m).unwrap();
    put("shaper.D2", rim.outer);
    put("shaper.D1", rim.inner);
    put("shaper.b", rim.width);
    put("shaper.m1", rim.mass);
    out
}

/// The force analysis at f: accelerations, inertia loads, the right-hand
/// side, the 18 unknowns, magnitudes and directions.
fn ours_kinetostatics(data: &Data) -> HashMap<String, f64> {
    let shaper = synthesize(data).unwrap();
    let m = machine(&shaper, data).unwrap();
    let f = shaper.seed_position();
    let omega = TAU * data.n1;
    let e = m.energy_method(omega, data.delta).unwrap();
    let statics = machine::kinetostatics(&m, e.flywheel).unwrap();
    let (w, eps) = (e.omega(f).unwrap(), e.epsilon(f).unwrap());
    let sol = statics.solve(f, w, eps).unwrap();
    let a = m.analysis(f).unwrap();
    let point = |name| Shaper::point_index(name).unwrap();
    let acc = |p: usize| a.point_accelerations[p] * (w * w) + a.point_velocities[p] * eps;
    let rocker = a.uddot[0] * w * w + a.udot[0] * eps;
    let mut out = HashMap::new();
    let mut put = |k: &str, v: f64| {
        out.insert(format!("shaper.{k}"), v);
    };
    put("a_S3x", acc(point("S3")).x);
    put("a_S3y", acc(point("S3")).y);
    put("a_Dx", acc(point("D")).x);
    put("eps3", rocker);
    put("M_Phi1", e.flywheel * eps);
    put("Phi3x", -data.m3 * acc(point("S3")).x);
    put("Phi3y", -data.m3 * acc(point("S3")).y);
    put("M_Phi3", -data.i3s * rocker);
    put("Phi5x", -data.m5 * acc(point("D")).x);
    put("G3", data.m3 * data.g);
    put("G5", data.m5 * data.g);
    put("A4_cos_phi3", a.u[0].cos());
    for k in 0..18 {
        put(&format!("B{k}"), sol.rhs[k]);
    }
    put("check.det_A", sol.matrix.determinant());
    let names = ["F10", "F12", "F30", "F34", "F23", "F45", "F50"];
    for (k, n) in names.iter().enumerate() {
        put(&format!("reactions.{n}x"), sol.unknowns[k]);
        put(&format!("reactions.{n}y"), sol.unknowns[7 + k]);
    }
    for (k, n) in ["M23", "M45", "M50", "M1"].iter().enumerate() {
        put(&format!("reactions.{n}"), sol.unknowns[14 + k]);
    }
    for joint in &sol.joints {
        put(&format!("reactions.F{}", joint.name), joint.magnitude());
        put(
            &format!("reactions.phi{}_deg", joint.name),
            joint.angle_degrees(),
        );
    }
    put(
        "check.M1_plus_MPRDsr",
        sol.driving_moment + e.driving_moment,
    );
    out
}

#[test]
fn the_reaction_table_matches_the_50_digit_reference() {
    let reference = reference();
    let ours = ours_kinetostatics(&SEED);
    // Components that vanish exactly (forces normal to a guide): to the
    // rounding of the 18×18 solve, relative to the largest reaction.
    let scale = 1600.0;
    let mut printed_checked = 0;
    for (key, value) in &ours {
        let (exact, seed) = reference
            .get(key)
            .unwrap_or_else(|| panic!("{key} not in the reference"));
        let error = if *exact == 0.0 || key.starts_with("shaper.check.M1") {
            value.abs() / scale
        } else {
            (value - exact).abs() / exact.abs()
        };
        assert!(
            error <= 1e-9,
            "{key}: ours {value}, exact {exact}, {error:e}"
        );
        if let Some(text) = seed {
            let (printed, half) = printed(text);
            printed_checked += 1;
            let explained = [
                "shaper.M_Phi1",
                "shaper.B10",
                "shaper.Phi5x",
                "shaper.reactions.F30y",
                "shaper.reactions.F30",
                "shaper.reactions.M1",
            ];
            if explained.contains(&key.as_str()) {
                let relative = (value - printed).abs() / printed.abs();
                assert!(
                    (value - printed).abs() > half && relative < 2e-3,
                    "{key}: the quadrature's offset expected, {relative:e}"
                );
            } else {
                assert!(
                    (value - printed).abs() <= half * (1.0 + 1e-9) + 1e-12,
                    "{key}: ours {value}, printed {text}"
                );
            }
        }
    }
    assert!(
        ours.len() >= 60 && printed_checked >= 40,
        "{} / {printed_checked}",
        ours.len()
    );
}

#[test]
fn the_balancing_moment_three_ways_over_a_cycle() {
    let shaper = synthesize(&SEED).unwrap();
    let m = machine(&shaper, &SEED).unwrap();
    let omega = TAU * SEED.n1;
    let e = m.energy_method(omega, SEED.delta).unwrap();
    let statics = machine::kinetostatics(&m, e.flywheel).unwrap();
    let (mut against_power, mut against_dynamics) = (0.0_f64, 0.0_f64);
    for k in 0..360 {
        let phi = k as f64 * TAU / 360.0;
        let (w, eps) = (e.omega(phi).unwrap(), e.epsilon(phi).unwrap());
        let solved = statics.solve(phi, w, eps).unwrap().driving_moment;
        let power = statics.power_balance(phi, w, eps).unwrap();
        against_power = against_power.max(((solved - power) / power).abs());
        // ε1 from the equation of motion with the flywheel: the balancing
        // moment is the constant −M_PRDsr at every pose.
        against_dynamics =
            against_dynamics.max(((solved + e.driving_moment) / e.driving_moment).abs());
    }
    assert!(against_power <= 1e-9, "{against_power:e}");
    assert!(against_dynamics <= 1e-9, "{against_dynamics:e}");
    // At any other motion the power balance still holds, but the moment is
    // no longer the mean one.
    let solved = statics.solve(1.0, 5.0, 2.0).unwrap().driving_moment;
    let power = statics.power_balance(1.0, 5.0, 2.0).unwrap();
    assert!(((solved - power) / power).abs() <= 1e-12);
    assert!((solved + e.driving_moment).abs() > 1.0);
}

/// Where the reference value's location is only defined to the optimiser's
/// tolerance (an extremum's abscissa), a looser comparison.
fn tolerance(key: &str) -> f64 {
    match key {
        "shaper.phi_min" | "shaper.phi_max" | "shaper.phi_min2" | "shaper.phi_max2" => 1e-7,
        _ => 1e-9,
    }
}

#[test]
fn every_first_half_value_matches_the_50_digit_reference() {
    let reference = reference();
    let ours = ours(&SEED);
    assert!(ours.len() >= 74, "{} values", ours.len());
    let mut worst = ("", 0.0_f64);
    for (key, value) in &ours {
        let (exact, _) = reference
            .get(*key)
            .unwrap_or_else(|| panic!("{key} not in the reference"));
        let error = (value - exact).abs() / exact.abs().max(1e-300);
        let error = if *exact == 0.0 { value.abs() } else { error };
        assert!(
            error <= tolerance(key),
            "{key}: ours {value}, exact {exact}, relative {error:e}"
        );
        if tolerance(key) == 1e-9 && error > worst.1 {
            worst = (key, error);
        }
    }
    eprintln!("worst relative difference: {} {:e}", worst.0, worst.1);
}

/// The printed digits of a seed value: "102.041" → (102.041, 0.0005).
fn printed(text: &str) -> (f64, f64) {
    let text = text.trim();
    let (mantissa, exponent) = match text.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    let value: f64 = text.parse().unwrap();
    (value, 0.5 * 10f64.powi(exponent - decimals))
}

/// Where the seed's printed number is not the exact value, the reason (see
/// tests/data/README.md): Mathcad integrated the moment with a quadrature
/// off by 1.7e-4 relative, and everything downstream inherits it; ε1 at
/// φ = 0 inherits it through ω1; the rim's mass through D2⁵ ∝ J_m.
const QUADRATURE_CHAIN: [&str; 13] = [
    "shaper.A_C_f",
    "shaper.A_C_2pi",
    "shaper.M_PRDsr",
    "shaper.A_D_f",
    "shaper.A_Sigma_f",
    "shaper.dT_I_f",
    "shaper.dT_Imin",
    "shaper.dT_Imax",
    "shaper.J_PRI",
    "shaper.eps_n",
    "shaper.eps1_min",
    "shaper.eps1_max",
    "shaper.m1",
];

#[test]
fn the_seeds_printed_numbers_agree_to_their_digits_or_by_the_known_quadrature_error() {
    let reference = reference();
    let ours = ours(&SEED);
    let mut checked = 0;
    for (key, value) in &ours {
        let Some((_, Some(text))) = reference.get(*key) else {
            continue;
        };
        let (seed, half) = printed(text);
        checked += 1;
        if QUADRATURE_CHAIN.contains(key) {
            let relative = (value - seed).abs() / seed.abs();
            assert!(
                (value - seed).abs() > half && relative < 2e-3,
                "{key}: ours {value}, printed {text}: expected the known quadrature offset, got {relative:e}"
            );
        } else {
            assert!(
                (value - seed).abs() <= half * (1.0 + 1e-9),
                "{key}: ours {value}, printed {text} (±{half})"
            );
        }
    }
    assert!(checked >= 60, "{checked} printed values checked");
}

#[test]
fn the_seeds_closed_form_is_what_newton_finds() {
    let shaper = synthesize(&SEED).unwrap();
    let m = machine(&shaper, &SEED).unwrap();
    for k in 0..360 {
        let phi = (k as f64).to_radians();
        let a = m.analysis(phi).unwrap();
        let closed = shaper.closed_form_phi3(phi);
        assert!(
            (a.u[0] - closed).abs() < 1e-13,
            "φ = {k}°: {} vs {closed}",
            a.u[0]
        );
        assert!((a.u[2] - shaper.l_cd * closed.cos()).abs() < 1e-13);
    }
    // φ = 0 and π + β are the dead positions: the ram at rest, at x = ∓H/2.
    for (phi, x) in [(0.0, -0.25), (std::f64::consts::PI + shaper.beta(), 0.25)] {
        let a = m.analysis(phi).unwrap();
        assert!(a.udot[2].abs() < 1e-13 && (a.u[2] - x).abs() < 1e-13);
    }
}

#[test]
fn other_inputs_keep_the_methods_invariants() {
    let data = Data {
        k_v: 1.4,
        stroke: 0.4,
        m5: 80.0,
        ..SEED
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
    let shaper = synthesize(&SEED).unwrap();
    let m = machine(&shaper, &SEED).unwrap();
    let omega = TAU * SEED.n1;
    let e = m.energy_method(omega, SEED.delta).unwrap();
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
        real.delta < SEED.delta && real.delta > 0.9 * SEED.delta,
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
    assert!(settled.delta < SEED.delta);
}

/// The real motion's extremes of ω are located between the nodes (ε = 0
/// there), not read off the grid: they bound every node, and agree between
/// a coarse and a fine grid far better than the grid's spacing would allow.
#[test]
fn the_real_motion_locates_its_extremes() {
    let shaper = synthesize(&SEED).unwrap();
    let m = machine(&shaper, &SEED).unwrap();
    let omega = TAU * SEED.n1;
    let e = m.energy_method(omega, SEED.delta).unwrap();
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
        ..SEED
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

/// Settings out of their range are typed errors: δ of 2 or more (ω_min
/// would not be positive), a motor with NaN numbers, a grid of usize::MAX
/// poses (it once meant a sweep of that many steps), a load direction of
/// zero, a load that returns NaN.
#[test]
fn bad_settings_of_a_machine_are_typed_errors() {
    use linkage::machine::{Body, Load, MachineError as E};
    let shaper = synthesize(&SEED).unwrap();
    let m = machine(&shaper, &SEED).unwrap();
    let omega = TAU * SEED.n1;
    for delta in [2.0, 3.0, 0.0, -0.1, f64::NAN] {
        assert!(
            matches!(m.energy_method(omega, delta), Err(E::BadSetting { .. })),
            "δ = {delta}"
        );
    }
    let e = m.energy_method(omega, SEED.delta).unwrap();
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
        let data = Data { k_v, ..SEED };
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
            ..SEED
        })
        .is_err()
    );
}

#[test]
fn bad_machines_are_typed_errors() {
    let shaper = synthesize(&SEED).unwrap();
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

//! The first half of the course project — synthesis, kinematics, reduced
//! dynamics, work, the flywheel by the energy method, ω1 and ε1 — against
//! the 50-digit reference and the course project's printed numbers, and the course project's
//! closed form against Newton.

use super::reference::{printed, reference};
use crate::machine::{COURSE_PROJECT, Data, machine, synthesize};
use linkage::machine::flywheel;
use linkage::prelude::*;
use std::collections::HashMap;
use std::f64::consts::TAU;

/// Everything the first half of the course project computes, by linkage.
fn ours(data: &Data) -> HashMap<&'static str, f64> {
    let shaper = synthesize(data).unwrap();
    let m = machine(&shaper, data).expect("the shaper runs its cycle");
    let f = shaper.analysed_position();
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
    let point = |name| m.model().point_index(name).unwrap();
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
    let ours = ours(&COURSE_PROJECT);
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

/// Where the course project's printed number is not the exact value, the reason (see
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
fn the_course_projects_printed_numbers_agree_to_their_digits_or_by_the_known_quadrature_error() {
    let reference = reference();
    let ours = ours(&COURSE_PROJECT);
    let mut checked = 0;
    for (key, value) in &ours {
        let Some((_, Some(text))) = reference.get(*key) else {
            continue;
        };
        let (printed_value, half) = printed(text);
        checked += 1;
        if QUADRATURE_CHAIN.contains(key) {
            let relative = (value - printed_value).abs() / printed_value.abs();
            assert!(
                (value - printed_value).abs() > half && relative < 2e-3,
                "{key}: ours {value}, printed {text}: expected the known quadrature offset, got {relative:e}"
            );
        } else {
            assert!(
                (value - printed_value).abs() <= half * (1.0 + 1e-9),
                "{key}: ours {value}, printed {text} (±{half})"
            );
        }
    }
    assert!(checked >= 60, "{checked} printed values checked");
}

#[test]
fn the_course_projects_closed_form_is_what_newton_finds() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = machine(&shaper, &COURSE_PROJECT).unwrap();
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

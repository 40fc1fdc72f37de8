//! The force analysis at the course project's position against the 50-digit
//! reference, and the balancing moment three ways over a cycle.

use super::reference::{printed, reference};
use crate::machine::{self, COURSE_PROJECT, Data, machine, synthesize};
use linkage::prelude::*;
use std::collections::HashMap;
use std::f64::consts::TAU;

/// The force analysis at f: accelerations, inertia loads, the right-hand
/// side, the 18 unknowns, magnitudes and directions.
fn ours_kinetostatics(data: &Data) -> HashMap<String, f64> {
    let shaper = synthesize(data).unwrap();
    let m = machine(&shaper, data).unwrap();
    let f = shaper.analysed_position();
    let omega = TAU * data.n1;
    let e = m.energy_method(omega, data.delta).unwrap();
    let statics = machine::kinetostatics(&m, e.flywheel).unwrap();
    let (w, eps) = (e.omega(f).unwrap(), e.epsilon(f).unwrap());
    let sol = statics.solve(f, w, eps).unwrap();
    let a = m.analysis(f).unwrap();
    let point = |name| m.model().point_index(name).unwrap();
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
    let ours = ours_kinetostatics(&COURSE_PROJECT);
    // Components that vanish exactly (forces normal to a guide): to the
    // rounding of the 18×18 solve, relative to the largest reaction.
    let scale = 1600.0;
    let mut printed_checked = 0;
    for (key, value) in &ours {
        let (exact, printed_text) = reference
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
        if let Some(text) = printed_text {
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
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = machine(&shaper, &COURSE_PROJECT).unwrap();
    let omega = TAU * COURSE_PROJECT.n1;
    let e = m.energy_method(omega, COURSE_PROJECT.delta).unwrap();
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

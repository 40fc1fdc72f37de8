//! The dynamics differentiated by the design (`Machine::design`): the
//! exact derivatives of J(φ), M(φ), A(φ) and the flywheel J_I of the
//! energy method by the mechanism's dimensions and the bodies' masses and
//! inertias, against central differences of the machine rebuilt with each
//! one moved.

use crate::machine::{COURSE_PROJECT, Data, Shaper, machine, synthesize};
use linkage::machine::MachineError;
use std::f64::consts::TAU;

/// The design moved by `h` in the named dimension or mass.
fn moved(shaper: &Shaper, data: &Data, name: &str, h: f64) -> (Shaper, Data) {
    let (mut s, mut d) = (*shaper, *data);
    match name {
        "l_oa" => s.l_oa += h,
        "l_cd" => s.l_cd += h,
        "y_c" => s.y_c += h,
        "phi0" => s.phi0 += h,
        "lambda_s3" => s.lambda_s3 += h,
        "mass of rocker 3" => d.m3 += h,
        "inertia of rocker 3" => d.i3s += h,
        "mass of ram 5" => d.m5 += h,
        _ => unreachable!("{name}"),
    }
    (s, d)
}

/// J, M at φ₁ and φ₂, the work from φ₁ to φ₂, A(2π) and J_I of a design.
/// (Not A(φ₁) itself: the ram's dead position, where friction kinks, sits
/// at φ = 0 for the nominal design and moves to either side of it with the
/// design, so A(φ₁) from 0 is only once differentiable there and central
/// differences of it err by O(h); the work between two poses clear of it
/// and over a whole cycle are smooth.)
fn quantities(shaper: &Shaper, data: &Data, phis: [f64; 2]) -> Vec<f64> {
    let m = machine(shaper, data).unwrap();
    let e = m.energy_method(TAU * data.n1, data.delta).unwrap();
    let mut out = Vec::new();
    for phi in phis {
        let r = m.reduced(phi).unwrap();
        out.extend([r.inertia, r.moment]);
    }
    let between = m.work(phis[1]).unwrap() - m.work(phis[0]).unwrap();
    out.extend([between, m.cycle_work(), e.flywheel]);
    out
}

#[test]
fn the_flywheel_and_the_reduced_dynamics_differentiate_as_differences_say() {
    let data = COURSE_PROJECT;
    let shaper = synthesize(&data).unwrap();
    let m = machine(&shaper, &data).unwrap();
    let e = m.energy_method(TAU * data.n1, data.delta).unwrap();
    let design = m.design().unwrap();
    let names = design.names();
    assert_eq!(names.len(), 8 + 2 * 5);
    // A pose on the working stroke (the cutting force on its slope) and one
    // on the return.
    let phis = [1.7, 4.9];
    let exact: Vec<Vec<f64>> = {
        let (a, b) = (
            design.reduced(phis[0]).unwrap(),
            design.reduced(phis[1]).unwrap(),
        );
        let (w0, w1) = (design.work(phis[0]).unwrap(), design.work(phis[1]).unwrap());
        let cycle = design.work(TAU).unwrap();
        let flywheel = design.flywheel(&e).unwrap();
        (0..names.len())
            .map(|i| {
                vec![
                    a.inertia[i],
                    a.moment[i],
                    b.inertia[i],
                    b.moment[i],
                    w1[i] - w0[i],
                    cycle[i],
                    flywheel[i],
                ]
            })
            .collect()
    };
    let nominal = quantities(&shaper, &data, phis);
    for name in [
        "l_oa",
        "l_cd",
        "y_c",
        "phi0",
        "lambda_s3",
        "mass of rocker 3",
        "inertia of rocker 3",
        "mass of ram 5",
    ] {
        let i = names.iter().position(|n| n == name).unwrap();
        let h = 1e-5;
        let (s1, d1) = moved(&shaper, &data, name, h);
        let (s0, d0) = moved(&shaper, &data, name, -h);
        let (up, down) = (quantities(&s1, &d1, phis), quantities(&s0, &d0, phis));
        for (k, what) in [
            "J(φ₁)",
            "M(φ₁)",
            "J(φ₂)",
            "M(φ₂)",
            "A(φ₂) − A(φ₁)",
            "A(2π)",
            "J_I",
        ]
        .iter()
        .enumerate()
        {
            let difference = (up[k] - down[k]) / (2.0 * h);
            // Central differences: truncation ≈ h²·f‴, rounding ≈ ε·|f|/h
            // (the quantities are computed to ≈ 1e-13 of their size).
            // Measured: a median of 2e-11 of the scale, the worst 1.2e-7
            // (J and J_I by l_OA: truncation, at h = 1e-5), whence 1e-6.
            let scale = nominal[k].abs().max(1.0);
            let error = (exact[i][k] - difference).abs();
            assert!(
                error <= 1e-6 * scale,
                "∂{what}/∂{name}: exact {} vs differences {difference} ({error:e})",
                exact[i][k]
            );
        }
    }
    // The massless bodies' masses and inertias: J would grow by ω² of the
    // crank (turning at unit speed) and by nothing for a body without a
    // centre of mass (the crank, the blocks) or an angle (the ram, the
    // blocks); M does not change with any of them (no weight).
    let r = design.reduced(phis[0]).unwrap();
    for (i, name) in names.iter().enumerate() {
        let expected = match name.as_str() {
            "inertia of crank 1" => Some(1.0),
            "mass of crank 1" | "inertia of ram 5" | "mass of block 2" | "inertia of block 2"
            | "mass of block 4" | "inertia of block 4" => Some(0.0),
            _ => None,
        };
        if let Some(expected) = expected {
            assert!(
                (r.inertia[i] - expected).abs() < 1e-15 && r.moment[i] == 0.0,
                "{name}: ∂J {} ∂M {}",
                r.inertia[i],
                r.moment[i]
            );
        }
    }
}

#[test]
fn a_load_given_as_a_function_is_not_differentiated() {
    use linkage::machine::{Body, Load, Machine};
    use linkage::prelude::*;
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let m = Machine::new(shaper, shaper.guess())
        .body(Body::new("ram 5").mass(65.0).at("S5"))
        .load(Load::force("push", "F", |_| vector![-100.0, 0.0]))
        .build()
        .unwrap();
    match m.design() {
        Err(MachineError::NotDifferentiable { what, .. }) => assert_eq!(what, "the load `push`"),
        other => panic!("{:?}", other.map(|d| d.names().to_vec())),
    }
}

/// The flywheel minimised over l_OC, y_F and the rocker's mass
/// distribution (examples/shaper/redesign.rs): the optimum satisfies the
/// optimality conditions with its exact gradient, is confirmed by J_PRI on
/// either side of it, and its flywheel keeps the true periodic motion
/// within the required fluctuation.
#[test]
fn the_flywheel_optimum_is_a_minimum_and_keeps_the_true_motion_within_delta() {
    use crate::redesign::{bounds, course_variables, flywheel_value, minimise, true_fluctuation};
    let data = COURSE_PROJECT;
    let course = course_variables(&data).unwrap();
    let (lower, upper) = bounds(&course);
    let j_course = flywheel_value(&data, &course).unwrap();
    let best = minimise(&data).unwrap();
    assert!(
        best.flywheel < 0.95 * j_course,
        "{} vs {j_course}",
        best.flywheel
    );
    // l_OC: no effect (its gradient at rounding level: the swing and the
    // stroke are kept, and with them the ram's and the rocker's motion);
    // y_F none at all (the guide height enters neither J nor M: exactly 0,
    // a fact of the mechanism, not of the optimiser); λ_S3 interior,
    // stationary; I_S3 on its lower bound, J_PRI growing with it.
    let scale = best.flywheel;
    assert!(
        best.gradient[0].abs() <= 1e-9 * scale,
        "{}",
        best.gradient[0]
    );
    assert_eq!(best.gradient[1], 0.0);
    assert!(best.x[2] > lower[2] && best.x[2] < upper[2]);
    assert!(
        best.gradient[2].abs() <= 1e-6 * scale,
        "{}",
        best.gradient[2]
    );
    assert!(best.x[3] == lower[3] && best.gradient[3] > 0.0);
    // J_PRI itself on either side of the stationary λ_S3.
    for h in [-0.02, 0.02] {
        let mut x = best.x.clone();
        x[2] += h;
        let j = flywheel_value(&data, &x).unwrap();
        assert!(j > best.flywheel, "λ_S3 {}: {j} ≤ {}", x[2], best.flywheel);
    }
    // The true periodic motion with the optimum's flywheel: δ within the
    // target, as with the course project's (the energy method's estimate
    // errs on the safe side by a few per cent in both).
    let delta = true_fluctuation(&data, &best.x, best.flywheel).unwrap();
    assert!(delta <= data.delta && delta > 0.9 * data.delta, "{delta}");
}

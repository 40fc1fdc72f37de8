//! The two acceleration methods of the worksheet differ by zero, and the
//! generated derivatives are those of automatic differentiation.

use crate::common::{FourBar, OMEGA2, gamma_by_dual, rel_norm};
use linkage::num_dual::{DualSVec64, jacobian};
use linkage::prelude::*;

/// The poses of a sweep of n crank angles over a revolution, by continuation.
fn revolution(n: usize) -> Vec<(f64, SVector<f64, 2>)> {
    let drivers: Vec<SVector<f64, 1>> = (0..n)
        .map(|k| vector![std::f64::consts::TAU * k as f64 / n as f64])
        .collect();
    let poses = crate::common::continuation(
        &FourBar::WORKSHEET,
        vector![78f64.to_radians(), -44f64.to_radians()],
        &drivers,
    );
    drivers.iter().map(|v| v[0]).zip(poses).collect()
}

/// ü by a given method at a pose.
fn uddot(
    u: &SVector<f64, 2>,
    theta2: f64,
    alpha2: f64,
    method: AccelerationMethod,
) -> SVector<f64, 2> {
    let v = vector![theta2];
    let vdot = vector![OMEGA2];
    let options = Options {
        method,
        ..Options::default()
    };
    let vel = FourBar::WORKSHEET.velocity(u, &v, &vdot, &options).unwrap();
    FourBar::WORKSHEET
        .acceleration(u, &v, &vel.udot, &vdot, &vector![alpha2], &options)
        .unwrap()
}

#[test]
fn methods_a_and_b_differ_by_zero_at_3600_crank_angles() {
    let mut worst: f64 = 0.0;
    let mut exactly_equal = 0;
    for (theta2, u) in revolution(3600) {
        for alpha2 in [0.0, 123.0, -2500.0] {
            let a = uddot(&u, theta2, alpha2, AccelerationMethod::A);
            let b = uddot(&u, theta2, alpha2, AccelerationMethod::B);
            let fused = uddot(&u, theta2, alpha2, AccelerationMethod::Fused);
            let r = rel_norm(a.as_slice(), b.as_slice(), 0.0).max(rel_norm(
                fused.as_slice(),
                b.as_slice(),
                0.0,
            ));
            assert!(
                r <= 1e-12,
                "θ2 = {theta2}, α2 = {alpha2}: A {a:?}, B {b:?}, fused {fused:?}"
            );
            worst = worst.max(r);
            exactly_equal += usize::from(a == b);
        }
    }
    eprintln!(
        "worst |ü − ü_B|/|ü_B| = {worst:.2e}; A and B bit-identical in {exactly_equal} of 10800 cases"
    );
    // For the four-bar Ψ̇_u = ([Ψ_u]u̇)_u and Ψ̇_v v̇ = ([Ψ_v]v̇)_v v̇ entry
    // by entry (the mixed blocks vanish), so the generated code of the two
    // methods computes the same numbers in the same order: the difference is
    // exactly zero, not merely small.
    assert_eq!(exactly_equal, 10800);
}

/// The macro proves A = B symbolically: both γ expand to the same
/// polynomial in the velocities (the worksheet's `differenza := 0`).
#[test]
fn methods_agree_symbolically() {
    assert_eq!(FourBar::SYMBOLIC.methods_agree, Some(true));
    assert_eq!(
        FourBar::SYMBOLIC.get("psi_u_dot").unwrap().entries(),
        FourBar::SYMBOLIC.get("psi_u_udot_u").unwrap().entries(),
        "for the four-bar Ψ̇_u and ([Ψ_u]u̇)_u are the same matrix, as in the worksheet"
    );
}

#[test]
fn psi_q_is_the_jacobian_of_psi_generic() {
    let mut worst: f64 = 0.0;
    for (theta2, u) in revolution(360) {
        let q = vector![u[0], u[1], theta2];
        let (psi, jac) = jacobian(
            |q: SVector<DualSVec64<3>, 3>| {
                FourBar::WORKSHEET.psi_generic(&vector![q[0], q[1]], &vector![q[2]])
            },
            &q,
        );
        let generated = FourBar::WORKSHEET.psi_q(&u, &vector![theta2]);
        let r = rel_norm(generated.as_slice(), jac.as_slice(), 0.0);
        assert!(r <= 1e-13, "θ2 = {theta2}: {generated} vs {jac}");
        assert!(
            rel_norm(
                FourBar::WORKSHEET.psi(&u, &vector![theta2]).as_slice(),
                psi.as_slice(),
                1.0
            ) <= 1e-13
        );
        worst = worst.max(r);
    }
    eprintln!("worst relative difference of Ψ_q: {worst:.2e}");
}

#[test]
fn gamma_is_the_second_derivative_of_psi_generic() {
    let mut worst: f64 = 0.0;
    for (theta2, u) in revolution(360) {
        let v = vector![theta2];
        let vdot = vector![OMEGA2];
        let udot = FourBar::WORKSHEET
            .velocity(&u, &v, &vdot, &Options::default())
            .unwrap()
            .udot;
        let g = FourBar::WORKSHEET.gamma(&u, &v, &udot, &vdot);
        let d = gamma_by_dual(&FourBar::WORKSHEET, &u, &v, &udot, &vdot);
        let r = rel_norm(g.as_slice(), d.as_slice(), 0.0);
        assert!(r <= 1e-13, "θ2 = {theta2}: {g} vs {d}");
        worst = worst.max(r);
    }
    eprintln!("worst relative difference of γ: {worst:.2e}");
}

/// The fused kernel computes the same Ψ, Ψ_u, Ψ_v as the separate
/// functions, to the bit, and the same velocities and accelerations to
/// rounding.
#[test]
fn the_fused_kernel_equals_the_separate_functions() {
    for (theta2, u) in revolution(360) {
        let (v, vdot, vddot) = (vector![theta2], vector![OMEGA2], vector![37.0]);
        let k = FourBar::WORKSHEET.kinematics(&u, &v, &vdot, &vddot);
        assert_eq!(k.psi, FourBar::WORKSHEET.psi(&u, &v));
        assert_eq!(k.psi_u, FourBar::WORKSHEET.psi_u(&u, &v));
        assert_eq!(k.psi_v, FourBar::WORKSHEET.psi_v(&u, &v));
        let options = Options {
            method: AccelerationMethod::B,
            ..Options::default()
        };
        let vel = FourBar::WORKSHEET
            .velocity(&u, &v, &vdot, &options)
            .unwrap();
        let acc = FourBar::WORKSHEET
            .acceleration(&u, &v, &vel.udot, &vdot, &vddot, &options)
            .unwrap();
        assert!(rel_norm(k.udot.as_slice(), vel.udot.as_slice(), 0.0) <= 1e-15);
        assert!(
            rel_norm(k.uddot.as_slice(), acc.as_slice(), 0.0) <= 1e-14,
            "{} vs {}",
            k.uddot,
            acc
        );
        assert_eq!(k.rcond, vel.rcond);
    }
}

/// Given the exact sines and cosines, the kernel that takes them equals the
/// one that computes them, to the bit; given perturbed ones, it uses them
/// (so a sweep that carries them really saves the calls).
#[test]
fn the_kernel_with_given_trig_equals_the_fused_kernel() {
    for (theta2, u) in revolution(360) {
        let (v, vdot, vddot) = (vector![theta2], vector![OMEGA2], vector![37.0]);
        let trig_u = [u[0].sin_cos(), u[1].sin_cos()];
        let trig_v = [theta2.sin_cos()];
        let k = FourBar::WORKSHEET.kinematics(&u, &v, &vdot, &vddot);
        let t = FourBar::WORKSHEET.kinematics_with_trig(&u, &v, &trig_u, &trig_v, &vdot, &vddot);
        assert_eq!(k, t, "θ2 = {theta2}");
        let shifted = (theta2 + 1e-3).sin_cos();
        let moved =
            FourBar::WORKSHEET.kinematics_with_trig(&u, &v, &trig_u, &[shifted], &vdot, &vddot);
        let expected = FourBar::WORKSHEET.kinematics(&u, &vector![theta2 + 1e-3], &vdot, &vddot);
        assert_eq!(moved.psi, expected.psi);
    }
}

//! Every supported function, in method and free-function form, with the
//! named constants: the two spellings generate the same numbers, and the
//! generated derivatives (and the dual-number code) are right for each
//! function.

use crate::common::{gamma_by_dual, psi_q_by_dual, rel_norm};
use linkage::num_dual::Dual2_64;
use linkage::prelude::*;

#[linkage::linkage(
    u = [a, b],
    v = [t],
    points = [
        P = (a.hypot(b) + (l2 + t * t).powf(0.5), (t - a).abs() * E),
        Q = (P.x.exp() * 0.01, -P.y + 2 * l1),
    ],
    closure = [
        a.sin() * l1 + b.cos().powi(2) - (a * a + l2).sqrt() + b.atan2(l2 + t.exp()) + (t * 0.5).tanh() - PI / 4.0,
        a.tan() + b.sinh() * 0.1 + (l1 + a.cosh()).ln() + (l2 + b * b).powf(1.5) * 0.01 - a.hypot(b)
            + (t - a).abs() + (0.3 * b).asin() + (0.2 * a).acos() + (0.5 * t).atan() - 2 / l1.powi(-1),
    ],
)]
pub struct Methods {
    pub l1: f64,
    pub l2: f64,
}

#[linkage::linkage(
    u = [a, b],
    v = [t],
    points = [
        P = (hypot(a, b) + powf(l2 + t * t, 0.5), abs(t - a) * std::f64::consts::E),
        Q = (f64::exp(P.x) * 0.01, -P.y + 2.0 * l1),
    ],
    closure = [
        sin(a) * l1 + powi(f64::cos(b), 2) - sqrt(a * a + l2) + atan2(b, l2 + exp(t)) + tanh(t * 0.5)
            - core::f64::consts::FRAC_PI_4,
        tan(a) + sinh(b) * 0.1 + ln(l1 + cosh(a)) + f64::powf(l2 + b * b, 1.5) * 0.01 - f64::hypot(a, b)
            + abs(t - a) + asin(0.3 * b) + acos(0.2 * a) + atan(0.5 * t) - 2.0 * l1,
    ],
)]
pub struct Functions {
    pub l1: f64,
    pub l2: f64,
}

fn samples() -> impl Iterator<
    Item = (
        SVector<f64, 2>,
        SVector<f64, 1>,
        SVector<f64, 2>,
        SVector<f64, 1>,
    ),
> {
    (0..50).map(|k| {
        let s = k as f64 / 50.0;
        (
            vector![-0.9 + 1.7 * s, 0.8 - 1.5 * s],
            vector![1.3 - 2.1 * s],
            vector![0.7 - s, 0.2 + s],
            vector![-1.1 + 0.4 * s],
        )
    })
}

#[test]
fn method_and_function_forms_generate_the_same_numbers() {
    let (m, f) = (Methods { l1: 1.3, l2: 0.7 }, Functions { l1: 1.3, l2: 0.7 });
    for (u, v, udot, vdot) in samples() {
        assert_eq!(m.psi(&u, &v), f.psi(&u, &v));
        assert_eq!(m.psi_q(&u, &v), f.psi_q(&u, &v));
        assert_eq!(m.gamma(&u, &v, &udot, &vdot), f.gamma(&u, &v, &udot, &vdot));
        assert_eq!(m.point_positions(&u, &v), f.point_positions(&u, &v));
    }
    // The formulas read the same, but for the constant's spelling.
    assert_eq!(
        Methods::SYMBOLIC.get("psi_q").unwrap().entries(),
        Functions::SYMBOLIC.get("psi_q").unwrap().entries()
    );
    let psi = Functions::SYMBOLIC.get("psi").unwrap();
    assert!(psi.entries()[0].ends_with("- π/4"), "{}", psi.entries()[0]);
}

#[test]
fn every_function_differentiates_right() {
    let model = Functions { l1: 1.3, l2: 0.7 };
    for (u, v, udot, vdot) in samples() {
        // Ψ on f64 through the dual-number code equals the f64 code.
        let generic = model.psi_generic(&u, &v);
        assert!(rel_norm(generic.as_slice(), model.psi(&u, &v).as_slice(), 1.0) < 1e-15);
        // Ψ_q and γ against num-dual.
        let columns = psi_q_by_dual(&model, &u, &v);
        let jac = model.psi_q(&u, &v);
        for (k, col) in columns.iter().enumerate() {
            let ours = [jac[(0, k)], jac[(1, k)]];
            assert!(
                rel_norm(&ours, col, 1.0) < 1e-14,
                "column {k}: {ours:?} vs {col:?}"
            );
        }
        let g = model.gamma(&u, &v, &udot, &vdot);
        let d = gamma_by_dual(&model, &u, &v, &udot, &vdot);
        assert!(
            rel_norm(g.as_slice(), d.as_slice(), 1.0) < 1e-13,
            "{g} vs {d}"
        );
        // Both acceleration methods.
        let a = model.gamma_by(AccelerationMethod::A, &u, &v, &udot, &vdot);
        let b = model.gamma_by(AccelerationMethod::B, &u, &v, &udot, &vdot);
        assert!(rel_norm(a.as_slice(), b.as_slice(), 1.0) < 1e-13);
        assert!(rel_norm(a.as_slice(), g.as_slice(), 1.0) < 1e-13);
        // Points: velocities and accelerations against num-dual.
        let uddot = vector![0.3, -0.2];
        let vddot = vector![0.5];
        let pv = model.point_velocities(&u, &v, &udot, &vdot);
        let pa = model.point_accelerations(&u, &v, &udot, &vdot, &uddot, &vddot);
        let ud = SVector::<Dual2_64, 2>::from_fn(|i, _| Dual2_64::new(u[i], udot[i], uddot[i]));
        let vd = SVector::<Dual2_64, 1>::from_fn(|i, _| Dual2_64::new(v[i], vdot[i], vddot[i]));
        let dual = model.point_positions_generic(&ud, &vd);
        for k in 0..2 {
            let d = &dual[k];
            assert!(rel_norm(pv[k].as_slice(), &[d.x.v1, d.y.v1], 1.0) < 1e-14);
            assert!(rel_norm(pa[k].as_slice(), &[d.x.v2, d.y.v2], 1.0) < 1e-13);
        }
    }
}

// Every item `#[linkage::linkage]` generates for the four-bar `FourBar`
// (u = [theta3, theta4], v = [theta2], points B and C, the parameters
// l1, l2, l3, l4), used as a user's code uses it and with the types it has
// when the attribute has no mistake: `no_mistake.rs` compiles and runs
// this, and each test of a mistake includes it, where only the mistake may
// be reported.

use linkage::SensitivityTerms;
use linkage::num_dual::Dual64;
use linkage::prelude::*;
use linkage::tolerance::{Tolerance, Tolerances};

/// The trait impls, at the four-bar's dimensions.
fn through_the_traits<L: Sensitivities<2, 1, 4>>(model: &L) -> usize {
    let names: ([&str; 2], [&str; 1], [&str; 4]) =
        (model.u_names(), model.v_names(), model.param_names());
    let _: &[&str] = model.point_names();
    let _: SVector<f64, 4> = model.params();
    names.0.len() + names.1.len() + names.2.len() + model.point_index("C").unwrap_or(0)
}

/// Results used as they come, with no type written to fix their sizes
/// (in a function of its own: rustc reports no ambiguity in a function
/// that has other errors).
fn as_they_come(bar: &FourBar) -> bool {
    let (u, v, vdot, vddot) = (vector![1.2, -0.9], vector![0.3], vector![1.0], vector![0.0]);
    let options = Options::default();
    let Ok(analysis) = bar.analyze(&u, &v, &vdot, &vddot, &options) else {
        return false;
    };
    let largest = bar
        .sensitivities_of(&analysis, &options)
        .map(|s| s.u.amax());
    let columns = bar.psi_p(&u, &v).ncols() + FourBar::PARAM_NAMES.len();
    largest.is_ok() && columns == 8
}

fn main() {
    let mut bar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
        ..Default::default()
    };
    let (u, v) = (vector![1.2, -0.9], vector![0.3]);
    let (udot, vdot, uddot, vddot) = (
        vector![0.1, 0.2],
        vector![1.0],
        vector![0.0, 0.1],
        vector![0.0],
    );
    let options = Options::default();

    // The constants.
    let _: [&'static str; 2] = FourBar::U_NAMES;
    let _: [&'static str; 1] = FourBar::V_NAMES;
    let _: [&'static str; 2] = FourBar::POINT_NAMES;
    let _: [&'static str; 4] = FourBar::PARAM_NAMES;
    let _: [usize; 2] = [FourBar::B, FourBar::C];
    let _: ([bool; 2], [bool; 1]) = (FourBar::TRIG_U, FourBar::TRIG_V);
    let _: SymbolicTable = FourBar::SYMBOLIC;
    let tolerances: Tolerances<4> =
        Tolerances::by_name(&FourBar::PARAM_NAMES, &[("l3", Tolerance::Band(0.1))]).unwrap();

    // The inherent functions.
    let _: SVector<f64, 2> = bar.psi(&u, &v);
    let _: SMatrix<f64, 2, 3> = bar.psi_q(&u, &v);
    let _: SMatrix<f64, 2, 2> = bar.psi_u(&u, &v);
    let _: SVector<f64, 2> = bar.psi_v(&u, &v);
    let _: (SVector<f64, 2>, SMatrix<f64, 2, 2>) = bar.psi_and_psi_u(&u, &v);
    let _: SMatrix<f64, 2, 2> = bar.psi_u_udot_u(&u, &v, &udot);
    let _: SVector<f64, 2> = bar.psi_u_udot_v(&u, &v, &udot);
    let _: SMatrix<f64, 2, 2> = bar.psi_v_vdot_u(&u, &v, &vdot);
    let _: SVector<f64, 2> = bar.psi_v_vdot_v(&u, &v, &vdot);
    let _: SMatrix<f64, 2, 2> = bar.psi_u_dot(&u, &v, &udot, &vdot);
    let _: SVector<f64, 2> = bar.psi_v_dot(&u, &v, &udot, &vdot);
    let _: SVector<f64, 2> = bar.gamma(&u, &v, &udot, &vdot);
    let _: [Vector2<f64>; 2] = bar.point_positions(&u, &v);
    let _: [Vector2<f64>; 2] = bar.point_velocities(&u, &v, &udot, &vdot);
    let _: [Vector2<f64>; 2] = bar.point_accelerations(&u, &v, &udot, &vdot, &uddot, &vddot);
    let _: Kinematics<2, 1> = bar.kinematics(&u, &v, &vdot, &vddot);
    let trig_u = [u[0].sin_cos(), u[1].sin_cos()];
    let trig_v = [v[0].sin_cos()];
    let _: Kinematics<2, 1> = bar.kinematics_with_trig(&u, &v, &trig_u, &trig_v, &vdot, &vddot);
    let (u_dual, v_dual) = (u.map(Dual64::from), v.map(Dual64::from));
    let _: SVector<Dual64, 2> = bar.psi_generic(&u_dual, &v_dual);
    let _: [Vector2<Dual64>; 2] = bar.point_positions_generic(&u_dual, &v_dual);
    let _: SMatrix<f64, 2, 4> = bar.psi_p(&u, &v);
    let terms = bar.sensitivity_terms(&u, &v, &udot, &vdot, &uddot, &vddot);
    let _: SensitivityTerms<2, 4, [Vector2<f64>; 2]> = terms;
    let p_dual = SVector::<Dual64, 4>::from_element(Dual64::from(1.0));
    let _: SVector<Dual64, 2> = bar.psi_generic_params(&p_dual, &u_dual, &v_dual);
    let _: [Vector2<Dual64>; 2] = bar.point_positions_generic_params(&p_dual, &u_dual, &v_dual);

    // Not entry points but the hidden kernel's items, which the runtime's
    // sweeps and analyses call (`#[doc(hidden)]`): the error path provides
    // them too, so that they are checked here with the others.
    let _: ([bool; 2], [bool; 1]) = (FourBar::SENSITIVITY_TRIG_U, FourBar::SENSITIVITY_TRIG_V);
    let _: SensitivityTerms<2, 4, [Vector2<f64>; 2]> =
        bar.sensitivity_terms_with_trig(&u, &v, &trig_u, &trig_v, &udot, &vdot, &uddot, &vddot);

    // The traits' functions, called as methods.
    let position: Position<2> = bar.solve_position(&u, &v, &options).unwrap();
    let _: Velocity<2, 1> = bar.velocity(&position.u, &v, &vdot, &options).unwrap();
    let _: SVector<f64, 2> = bar
        .acceleration(&position.u, &v, &udot, &vdot, &vddot, &options)
        .unwrap();
    let analysis = bar.analyze(&u, &v, &vdot, &vddot, &options).unwrap();
    let c: Vector2<f64> = analysis.points[FourBar::C];
    let motion = Motion::of_analysis(&analysis);
    let _: Sensitivity<2, 4, [Vector2<f64>; 2]> = bar.sensitivities(&motion, &options).unwrap();
    let sensitivity = bar
        .sensitivities_of(&analysis, &options)
        .unwrap();
    let _: Sensitivity<2, 4, [Vector2<f64>; 2]> = sensitivity;
    let spread = tolerances.spread(&sensitivity.u.row(0).transpose());
    assert!(as_they_come(&bar));
    let params: SVector<f64, 4> = bar.params();
    bar.set_params(&params);
    assert!(through_the_traits(&bar) == 8 && c.norm() > 0.0 && spread.rss >= 0.0);
}

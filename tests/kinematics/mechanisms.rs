//! The invariants on five more mechanisms: a slider-crank (a prismatic
//! coordinate), a five-bar with two drivers (f = 2), a boom driven by an
//! actuator length (non-zero mixed blocks of method B), a two-loop six-bar
//! (m = 4), and the path-generation four-bar of `linkage::mechanisms` with
//! its pivots and coupler point off the axes. At every pose of a sweep:
//! Ψ = 0 after Newton,
//! Ψ_u u̇ + Ψ_v v̇ = 0, method A = method B = fused, and the generated
//! Ψ_q, γ and point kinematics equal num-dual's derivatives of the generic
//! closure equations.

use crate::common::check_invariants;
use crate::models::{BOOM, Boom, FIVE_BAR, SIX_BAR, SLIDER_CRANK, SixBar};
use linkage::closed_form::{self, Grashof};
use linkage::mechanisms::{BareFourBar, CouplerFourBar, FourBar};
use linkage::prelude::*;
use std::f64::consts::TAU;

const NAMES: [&str; 6] = [
    "Ψ",
    "Ψ_u u̇ + Ψ_v v̇",
    "A vs B vs fused",
    "Ψ_q vs num-dual",
    "γ vs num-dual",
    "points vs num-dual",
];
const TOLERANCES: [f64; 6] = [1e-14, 1e-13, 1e-12, 1e-13, 1e-13, 1e-13];

/// Runs the invariants along a path of driver values by continuation.
fn sweep<L: Linkage<M, F>, const M: usize, const F: usize>(
    name: &str,
    model: &L,
    mut u: SVector<f64, M>,
    path: impl Iterator<Item = (SVector<f64, F>, SVector<f64, F>, SVector<f64, F>)>,
) {
    let mut worst = [0.0_f64; 6];
    let mut poses = 0;
    for (v, vdot, vddot) in path {
        let (solved, figures) = check_invariants(model, &u, &v, &vdot, &vddot);
        u = solved;
        for (k, f) in figures.iter().enumerate() {
            assert!(
                *f <= TOLERANCES[k],
                "{name} at v = {v:?}: {} off by {f:.2e}",
                NAMES[k]
            );
            worst[k] = worst[k].max(*f);
        }
        poses += 1;
    }
    eprintln!(
        "{name}: {poses} poses, worst {:?}",
        NAMES.iter().zip(worst).collect::<Vec<_>>()
    );
}

#[test]
fn slider_crank() {
    let n = 720;
    let path = (0..n).map(|k| {
        let t = TAU * k as f64 / n as f64;
        (vector![t], vector![150.0], vector![-30.0])
    });
    sweep("slider-crank", &SLIDER_CRANK, vector![0.0, 0.25], path);
}

#[test]
fn five_bar_with_two_drivers() {
    let n = 720;
    // Both cranks turn, at different speeds and with accelerations.
    let path = (0..n).map(|k| {
        let t = TAU * k as f64 / n as f64;
        (
            vector![t, 2.0 * t + 1.0],
            vector![10.0, -7.0],
            vector![3.0, 40.0],
        )
    });
    sweep("five-bar", &FIVE_BAR, vector![1.2, 2.0], path);
}

#[test]
fn boom_driven_by_its_actuator_length() {
    let n = 500;
    let path = (0..n).map(|k| {
        let length = 0.9 + 0.5 * k as f64 / n as f64;
        (vector![length], vector![0.05], vector![-0.02])
    });
    sweep("boom", &BOOM, vector![0.3, 1.2], path);
}

/// The boom's mixed blocks are structurally non-zero, and at a pose they
/// matter: method B without them would be wrong.
#[test]
fn boom_mixed_blocks_are_nonzero_and_needed() {
    let table = Boom::SYMBOLIC;
    for key in ["psi_u_udot_v", "psi_v_vdot_u"] {
        let m = table.get(key).unwrap();
        assert!(!m.nonzero.is_empty(), "{key} is zero: {m}");
    }
    assert_eq!(table.methods_agree, Some(true));
    let v = vector![1.1];
    let u = BOOM
        .solve_position(&vector![0.3, 1.2], &v, &Options::default())
        .unwrap()
        .u;
    let vdot = vector![0.05];
    let udot = BOOM
        .velocity(&u, &v, &vdot, &Options::default())
        .unwrap()
        .udot;
    let mixed = BOOM.psi_u_udot_v(&u, &v, &udot) * vdot + BOOM.psi_v_vdot_u(&u, &v, &vdot) * udot;
    let gamma = BOOM.gamma(&u, &v, &udot, &vdot);
    assert!(
        mixed.amax() > 0.1 * gamma.amax(),
        "mixed {mixed:?}, γ {gamma:?}"
    );
}

#[test]
fn six_bar_with_two_loops() {
    let n = 720;
    let path = (0..n).map(|k| {
        let t = TAU * k as f64 / n as f64;
        (vector![t], vector![41.9], vector![5.0])
    });
    let guess = SVector::<f64, 4>::from([78f64.to_radians(), -44f64.to_radians(), 0.3, -0.5]);
    sweep("six-bar", &SIX_BAR, guess, path);
    assert_eq!(SixBar::SYMBOLIC.methods_agree, Some(true));
}

#[test]
fn coupler_four_bar_with_its_ground_and_coupler_point_off_the_axes() {
    // Ground from (3, −2) to (70, 35), 76.5 long: still a crank-rocker.
    let bar = CouplerFourBar {
        xa: 3.0,
        ya: -2.0,
        xd: 70.0,
        yd: 35.0,
        px: 30.0,
        py: 15.0,
        ..CouplerFourBar::WORKSHEET
    };
    let n = 720;
    let path = (0..n).map(|k| {
        let t = TAU * k as f64 / n as f64;
        (vector![t], vector![41.9], vector![5.0])
    });
    sweep("coupler four-bar", &bar, vector![1.8, -0.3], path);
}

/// `CouplerFourBar::WORKSHEET` is the worksheet's four-bar, P its G3; P
/// lies px along B→C and py to its left.
#[test]
fn coupler_four_bar_frame() {
    let worksheet = FourBar::WORKSHEET;
    let moved = CouplerFourBar {
        py: 10.0,
        ..CouplerFourBar::WORKSHEET
    };
    let options = Options::default();
    for k in 0..12 {
        let v = vector![TAU * k as f64 / 12.0];
        let u = worksheet
            .solve_position(&vector![1.3, -0.8], &v, &options)
            .unwrap()
            .u;
        let ours = CouplerFourBar::WORKSHEET.point_positions(&u, &v);
        let theirs = worksheet.point_positions(&u, &v);
        assert!((ours[CouplerFourBar::P] - theirs[FourBar::G3]).norm() < 1e-12);
        assert!((ours[CouplerFourBar::B] - theirs[FourBar::B]).norm() < 1e-12);
        assert!((ours[CouplerFourBar::C] - theirs[FourBar::C]).norm() < 1e-12);
        let (b, c, p) = (
            ours[CouplerFourBar::B],
            ours[CouplerFourBar::C],
            moved.point_positions(&u, &v)[CouplerFourBar::P],
        );
        let along = (c - b).normalize();
        let left = vector![-along.y, along.x];
        assert!(
            (p - b - 25.0 * along - 10.0 * left).norm() < 1e-12,
            "at {k}"
        );
        assert!(CouplerFourBar::WORKSHEET.psi(&u, &v).norm() < 1e-12);
    }
}

/// Link lengths (l1, l2, l3, l4) of each Grashof class, the ground l1
/// first.
const CLASSES: [([f64; 4], Grashof); 6] = [
    ([80.0, 20.0, 50.0, 70.0], Grashof::CrankRocker),
    ([20.0, 80.0, 50.0, 70.0], Grashof::DoubleCrank),
    ([80.0, 50.0, 20.0, 70.0], Grashof::GrashofDoubleRocker),
    ([80.0, 70.0, 50.0, 20.0], Grashof::RockerCrank),
    ([80.0, 55.0, 60.0, 70.0], Grashof::TripleRocker),
    ([80.0, 30.0, 50.0, 60.0], Grashof::ChangePoint),
];

fn reference([l1, l2, l3, l4]: [f64; 4]) -> Grashof {
    closed_form::FourBar { l1, l2, l3, l4 }.grashof()
}

/// The ready four-bars' Grashof type is the closed form's, for each class.
#[test]
fn four_bar_and_bare_four_bar_grashof_is_the_closed_forms() {
    for (lengths, class) in CLASSES {
        let [l1, l2, l3, l4] = lengths;
        assert_eq!(reference(lengths), class, "{lengths:?}");
        let named = FourBar { l1, l2, l3, l4 };
        let bare = BareFourBar { l1, l2, l3, l4 };
        assert_eq!(named.grashof(), reference(lengths), "FourBar {lengths:?}");
        assert_eq!(
            bare.grashof(),
            reference(lengths),
            "BareFourBar {lengths:?}"
        );
    }
}

/// `CouplerFourBar`'s ground is |AD| wherever its pivots are: A moved off
/// the origin and D off A's horizontal, at a distance l1 along (4, 3)/5 or
/// (−3, 4)/5 (exact in binary, so that the change point stays one). Read
/// as xd − xa alone, the change point would be a crank-rocker.
#[test]
fn coupler_four_bar_grashof_takes_its_ground_from_the_pivots() {
    let (xa, ya) = (3.0, -2.0);
    for (along, across) in [(4.0, 3.0), (-3.0, 4.0)] {
        for (lengths, class) in CLASSES {
            let [l1, l2, l3, l4] = lengths;
            let bar = CouplerFourBar {
                xa,
                ya,
                xd: xa + l1 * along / 5.0,
                yd: ya + l1 * across / 5.0,
                l2,
                l3,
                l4,
                ..CouplerFourBar::WORKSHEET
            };
            assert_eq!(bar.closed_form().l1, l1, "{lengths:?}");
            assert_eq!(bar.grashof(), reference(lengths), "{lengths:?}");
            assert_eq!(bar.grashof(), class, "{lengths:?}");
        }
    }
    let [l1, l2, l3, l4] = CLASSES[5].0;
    let x_only = closed_form::FourBar {
        l1: l1 * 4.0 / 5.0,
        l2,
        l3,
        l4,
    };
    assert_eq!(x_only.grashof(), Grashof::CrankRocker);
}

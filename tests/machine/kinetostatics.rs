//! The force analysis on a four-bar with masses and a load, against a
//! free-body solution derived by hand; the power balance; and tables that
//! cannot be solved, with the errors that say why.

use crate::common::FourBar;
use linkage::error::{NameKind, UnknownName};
use linkage::machine::kinetostatics::{Kinetostatics, KinetostaticsError};
use linkage::machine::{Body, Load, Machine};
use linkage::prelude::*;

/// The worksheet's four-bar in metres, with a heavy coupler and rocker and
/// a load on the coupler's midpoint.
const BAR: FourBar = FourBar {
    l1: 0.08,
    l2: 0.02,
    l3: 0.05,
    l4: 0.07,
};
const M3: f64 = 1.5;
const I3: f64 = 4e-4;
const M4: f64 = 2.0;
const I4: f64 = 9e-4;
const G: f64 = 9.81;
const P: Vector2<f64> = Vector2::new(30.0, -120.0);

fn machine() -> Machine<FourBar, 2> {
    let start = BAR.closed_form().position(0.0, 1.0).unwrap();
    Machine::new(BAR, vector![start[0], start[1]])
        .body(Body::new("crank").angle("theta2"))
        .body(
            Body::new("coupler")
                .mass(M3)
                .inertia(I3)
                .at("G3")
                .angle("theta3"),
        )
        .body(
            Body::new("rocker")
                .mass(M4)
                .inertia(I4)
                .at("G4")
                .angle("theta4"),
        )
        .load(Load::force("P", "G3", |_| P))
        .load(Load::gravity("gravity", vector![0.0, -G]))
        .build()
        .unwrap()
}

fn statics(m: &Machine<FourBar, 2>) -> Kinetostatics<'_, FourBar, 2> {
    Kinetostatics::new(m)
        .ground_point("A", [0.0, 0.0])
        .ground_point("D", [BAR.l1, 0.0])
        .body("crank")
        .body("coupler")
        .body("rocker")
        .revolute("A", "crank", "ground", "A")
        .revolute("B", "crank", "coupler", "B")
        .revolute("C", "coupler", "rocker", "C")
        .revolute("D", "rocker", "ground", "D")
        .load_on("P", "coupler")
        .driver("crank", 1.0)
        .build()
        .unwrap()
}

/// z = a × b
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The free-body solution: the rocker's moments about D and the coupler's
/// about B give F_23 (on the coupler from the rocker, at C); the rest
/// follows from the force balances; the massless crank's moment about A
/// gives the balancing moment ([`hand_moment`]). Returns F_10, F_12, F_23,
/// F_30.
fn by_hand(m: &Machine<FourBar, 2>, phi: f64, omega: f64, epsilon: f64) -> [Vector2<f64>; 4] {
    let a = m.analysis(phi).unwrap();
    let point = |name| a.points[m.model().point_index(name).unwrap()];
    let acc = |name| {
        let k = m.model().point_index(name).unwrap();
        a.point_accelerations[k] * (omega * omega) + a.point_velocities[k] * epsilon
    };
    let (b, c, g3, g4) = (point("B"), point("C"), point("G3"), point("G4"));
    let d = Vector2::new(BAR.l1, 0.0);
    let alpha3 = a.uddot[0] * omega * omega + a.udot[0] * epsilon;
    let alpha4 = a.uddot[1] * omega * omega + a.udot[1] * epsilon;
    let weight = |m: f64| Vector2::new(0.0, -m * G);
    // The coupler's and the rocker's loads at their centres, with the
    // d'Alembert forces.
    let q3 = P + weight(M3) - acc("G3") * M3;
    let q4 = weight(M4) - acc("G4") * M4;
    // Rocker about D: (C − D) × (−F23) + (G4 − D) × Q4 − I4 α4 = 0.
    // Coupler about B: (C − B) × F23 + (G3 − B) × Q3 − I3 α3 = 0.
    let c4 = cross(g4 - d, q4) - I4 * alpha4;
    let c3 = cross(g3 - b, q3) - I3 * alpha3;
    let (rd, rb) = (c - d, c - b);
    let det = -rd.y * rb.x + rd.x * rb.y;
    let f23 = Vector2::new(
        (c4 * rb.x - rd.x * (-c3)) / det,
        (-rd.y * (-c3) + rb.y * c4) / det,
    );
    let f21 = -(f23 + q3);
    let f30 = f23 - q4;
    let f12 = -f21;
    let f10 = -f12;
    [f10, f12, f23, f30]
}

/// The massless crank's moments about A: (B − A) × F12 + M_b = 0.
fn hand_moment(m: &Machine<FourBar, 2>, phi: f64, omega: f64, epsilon: f64) -> f64 {
    let [_, f12, _, _] = by_hand(m, phi, omega, epsilon);
    let a = m.analysis(phi).unwrap();
    let b = a.points[FourBar::B];
    -cross(b, f12)
}

#[test]
fn reactions_equal_the_free_body_solution() {
    let m = machine();
    let s = statics(&m);
    let mut worst: f64 = 0.0;
    for k in 0..72 {
        let phi = k as f64 * std::f64::consts::TAU / 72.0;
        for (omega, epsilon) in [(0.0, 0.0), (41.9, 0.0), (41.9, -300.0)] {
            let solved = s.solve(phi, omega, epsilon).unwrap();
            let hand = by_hand(&m, phi, omega, epsilon);
            let scale = hand.iter().map(|v| v.norm()).fold(0.0, f64::max);
            for (joint, expected) in solved.joints.iter().zip(hand) {
                worst = worst.max((joint.force - expected).norm() / scale);
            }
            let moment = hand_moment(&m, phi, omega, epsilon);
            assert!(
                (solved.driving_moment - moment).abs() <= 1e-10 * moment.abs().max(1e-3),
                "φ = {phi}: {} vs {moment}",
                solved.driving_moment
            );
            // And the power balance.
            if omega != 0.0 {
                let power = s.power_balance(phi, omega, epsilon).unwrap();
                assert!((power - moment).abs() <= 1e-9 * moment.abs().max(1e-3));
            }
        }
    }
    assert!(worst < 1e-12, "worst relative difference {worst:e}");
    // At rest the rocker and coupler carry their weights and the load only.
    let at_rest = s.solve(0.3, 0.0, 0.0).unwrap();
    let total: Vector2<f64> = at_rest.joints[0].force + at_rest.joints[3].force;
    let expected = -(P + Vector2::new(0.0, -(M3 + M4) * G));
    assert!(
        (total - expected).norm() < 1e-10,
        "{total:?} vs {expected:?}"
    );
}

#[test]
fn a_redundant_or_loose_table_says_which_joints() {
    let m = machine();
    // One joint too many: statically indeterminate by count.
    let err = Kinetostatics::new(&m)
        .ground_point("A", [0.0, 0.0])
        .ground_point("D", [BAR.l1, 0.0])
        .body("crank")
        .body("coupler")
        .body("rocker")
        .revolute("A", "crank", "ground", "A")
        .revolute("B", "crank", "coupler", "B")
        .revolute("C", "coupler", "rocker", "C")
        .revolute("D", "rocker", "ground", "D")
        .revolute("C'", "coupler", "ground", "C")
        .load_on("P", "coupler")
        .driver("crank", 1.0)
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(
            err,
            KinetostaticsError::NotSquare {
                unknowns: 11,
                equations: 9,
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("statically indeterminate"));
    // Square, but the crank is pinned twice and the rocker swings free.
    let err = Kinetostatics::new(&m)
        .ground_point("A", [0.0, 0.0])
        .ground_point("E", [0.01, -0.01])
        .body("crank")
        .body("coupler")
        .body("rocker")
        .revolute("A", "crank", "ground", "A")
        .revolute("E", "crank", "ground", "E")
        .revolute("B", "crank", "coupler", "B")
        .revolute("C", "coupler", "rocker", "C")
        .load_on("P", "coupler")
        .driver("crank", 1.0)
        .build()
        .err()
        .unwrap();
    match &err {
        KinetostaticsError::Indeterminate { joints, .. } => {
            assert!(
                joints.contains(&"A".to_string()) && joints.contains(&"E".to_string()),
                "{joints:?}"
            );
        }
        other => panic!("{other}"),
    }
    // Names that do not exist.
    let err = Kinetostatics::new(&m)
        .body("crank")
        .revolute("A", "crank", "ground", "Z")
        .driver("crank", 1.0)
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(
            err,
            KinetostaticsError::UnknownName(UnknownName {
                kind: NameKind::Point,
                ..
            })
        ),
        "{err}"
    );
    let err = Kinetostatics::new(&m)
        .ground_point("A", [0.0, 0.0])
        .body("crank")
        .revolute("A", "crank", "frame", "A")
        .driver("crank", 1.0)
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(
            err,
            KinetostaticsError::UnknownName(UnknownName {
                kind: NameKind::Body,
                ..
            })
        ),
        "{err}"
    );
    let err = Kinetostatics::new(&m)
        .ground_point("A", [0.0, 0.0])
        .body("crank")
        .revolute("A", "crank", "ground", "A")
        .driver("crank", 1.0)
        .build()
        .err()
        .unwrap();
    assert!(
        matches!(err, KinetostaticsError::UnassignedLoad { .. }),
        "{err}"
    );
}

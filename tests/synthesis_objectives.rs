//! Synthesis objectives beyond targets: the designer's own terms (on dual
//! numbers, their exact gradient with them) and a closed target curve.

use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use linkage::synthesis::{Problem, Range, Requirements, Search, SynthesisError, synthesize};

/// The worksheet's four-bar scaled to a ground link of 1.
const UNIT: FourBar = FourBar {
    l1: 1.0,
    l2: 0.25,
    l3: 0.625,
    l4: 0.875,
};

/// Function generation only fixes a four-bar's shape (the angles do not
/// change when every length is scaled): with the ground link free too, a
/// term l1 − 2 = 0 picks the one design of ground link 2 — the three
/// precision points' design doubled, to rounding.
#[test]
fn a_designers_term_picks_the_scale_function_generation_leaves_free() {
    let thetas = [30f64, 60.0, 90.0].map(f64::to_radians);
    let zero = vector![0.0];
    let mut u = vector![1.3, -0.8];
    let targets: Vec<(f64, f64)> = thetas
        .iter()
        .map(|&t| {
            let a = UNIT
                .analyze(&u, &vector![t], &zero, &zero, &Options::default())
                .unwrap();
            u = a.u;
            (t, a.u[1])
        })
        .collect();
    let start = FourBar {
        l1: 1.5,
        l2: 0.6,
        l3: 1.4,
        l4: 1.6,
    };
    let problem = Problem::function(start, "theta4", &targets)
        .unwrap()
        .free("l1", 1.0, 3.0)
        .unwrap()
        .free("l2", 0.2, 1.0)
        .unwrap()
        .free("l3", 0.6, 2.4)
        .unwrap()
        .free("l4", 0.6, 2.4)
        .unwrap()
        .term("ground link of 2", |p| p[0] - 2.0)
        .guess(vector![1.3, -0.8])
        .precision_points();
    assert_eq!((problem.residuals(), problem.unknowns()), (4, 4));
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Between),
        &Search {
            starts: 12,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(!found.designs.is_empty(), "{found:?}");
    for design in &found.designs {
        let m = &design.model;
        assert_eq!(design.errors.len(), 3, "one error per target, not per term");
        let error = [m.l1 - 2.0, m.l2 - 0.5, m.l3 - 1.25, m.l4 - 1.75]
            .iter()
            .fold(0.0f64, |e, x| e.max(x.abs()));
        assert!(error < 1e-12, "{m:?}: {error:e}");
    }
}

/// The worksheet's coupler curve (G3 over a turn, 720 poses) as a closed
/// polyline: the curve problem samples it evenly and finds the worksheet's
/// links again, to the polyline's own deviation from the curve.
#[test]
fn a_closed_target_curve_is_fitted_by_least_squares() {
    let sweep = FourBar::WORKSHEET
        .sweep(
            &vector![0.4, -1.0],
            &Drive::Line {
                from: vector![0.0],
                to: vector![std::f64::consts::TAU],
                steps: 720,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    let g3 = FourBar::point_index("G3").unwrap();
    let curve: Vec<Vector2<f64>> = sweep.poses[..720]
        .iter()
        .map(|pose| {
            FourBar::WORKSHEET
                .point_positions(&pose.u, &pose.v)
                .as_ref()[g3]
        })
        .collect();
    let start = FourBar {
        l2: 24.0,
        l3: 45.0,
        l4: 75.0,
        ..FourBar::WORKSHEET
    };
    let problem = Problem::curve(start, "G3", &curve, 24)
        .unwrap()
        .free("l2", 10.0, 30.0)
        .unwrap()
        .free("l3", 30.0, 70.0)
        .unwrap()
        .free("l4", 50.0, 90.0)
        .unwrap()
        .guess(vector![1.3, -0.8]);
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Revolution),
        &Search {
            starts: 8,
            ..Search::default()
        },
    )
    .unwrap();
    let best = found.best().unwrap();
    let m = &best.model;
    // Samples on chords 0.3 mm long lie within ≈ 1e-3 mm of the curve.
    let error = [m.l2 - 20.0, m.l3 - 50.0, m.l4 - 70.0]
        .iter()
        .fold(0.0f64, |e, x| e.max(x.abs()));
    assert!(
        error < 1e-2 && best.rms_error < 1e-3,
        "{m:?}: {error:e}, rms {:e}",
        best.rms_error
    );
    let two = [curve[0], curve[1]];
    for (bad, samples) in [(&two[..], 24), (&curve[..], 2), (&[curve[0]; 5][..], 24)] {
        assert!(matches!(
            Problem::curve(FourBar::WORKSHEET, "G3", bad, samples),
            Err(SynthesisError::Curve(_))
        ));
    }
}

//! Synthesis objectives beyond targets: the designer's own terms (on dual
//! numbers, their exact gradient with them), a closed target curve, and a
//! function fitted over a range by least squares.

use crate::Freed;
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
        .freed(&[
            ("l1", 1.0, 3.0),
            ("l2", 0.2, 1.0),
            ("l3", 0.6, 2.4),
            ("l4", 0.6, 2.4),
        ])
        .term("ground link of 2", |p| p[0] - 2.0)
        .guess(vector![1.3, -0.8])
        .precision_points();
    assert_eq!((problem.residuals(), problem.unknowns()), (4, 4));
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Targets),
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
    let g3 = FourBar::G3;
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
        .freed(&[("l2", 10.0, 30.0), ("l3", 30.0, 70.0), ("l4", 50.0, 90.0)])
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
    // Samples on chords 0.3 mm long lie within ≈ 1e-3 mm of the curve;
    // the fit, measured, is within 1.3e-4 of the links, 2.5e-5 rms.
    let error = [m.l2 - 20.0, m.l3 - 50.0, m.l4 - 70.0]
        .iter()
        .fold(0.0f64, |e, x| e.max(x.abs()));
    assert!(
        error < 1e-3 && best.rms_error < 1e-4,
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

/// θ4 of the four-bar `model` at the crank angle `theta2`, on the branch
/// of the pose `u` it has at the crank angle `v` (closed form).
fn theta4(model: &FourBar, (v, u): (f64, &SVector<f64, 2>), theta2: f64) -> f64 {
    let bar = model.closed_form();
    let sigma = bar.branch(v, u[0]);
    bar.position(theta2, sigma)
        .expect("assembles over the range")[1]
}

/// A function the worksheet's four-bar generates exactly (its own θ4 over
/// 0.2 ≤ θ2 ≤ 1.4), fitted over the range by least squares from another
/// design: the worksheet's links again, and no error.
#[test]
fn a_function_over_a_range_that_a_design_generates_exactly_gives_that_design() {
    let worksheet = FourBar::WORKSHEET;
    let (v0, u0) = (0.2, vector![1.2, -0.9]);
    let u0 = worksheet
        .solve_position(&u0, &vector![v0], &Options::default())
        .unwrap()
        .u;
    let problem = Problem::function_over(
        FourBar {
            l2: 25.0,
            l3: 45.0,
            l4: 65.0,
            ..worksheet
        },
        "theta4",
        (0.2, 1.4),
        13,
        |v| theta4(&worksheet, (v0, &u0), v),
    )
    .unwrap()
    .freed(&[("l2", 10.0, 30.0), ("l3", 30.0, 70.0), ("l4", 50.0, 90.0)])
    .guess(vector![1.3, -0.8]);
    assert_eq!((problem.residuals(), problem.unknowns()), (13, 3));
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Task),
        &Search::default(),
    )
    .unwrap();
    let best = found.best().unwrap();
    let m = &best.model;
    let error = [m.l2 - 20.0, m.l3 - 50.0, m.l4 - 70.0]
        .iter()
        .fold(0.0f64, |e, x| e.max(x.abs()));
    // (Measured: 1.3e-12 and 1.9e-15.)
    assert!(error < 1e-11, "{m:?}: {error:e}");
    assert!(best.rms_error < 1e-14, "{best:?}");
}

/// Freudenstein's y = log10 x (1 ≤ x ≤ 10; the crank from 0° to 60°, the
/// rocker's angle φ from 90° to 180°) fitted over the whole range by least
/// squares at 31 drivers: its sum of squares there is well below that of
/// the three Chebyshev precision points' design, and the error the search
/// reports is the one the closed form gives at the samples.
#[test]
fn a_function_fitted_over_its_range_beats_three_precision_points_there() {
    use std::f64::consts::PI;
    let crank = |x: f64| (60.0 * (x - 1.0) / 9.0).to_radians();
    let wanted = |theta: f64| {
        let x = 1.0 + 9.0 * theta / 60f64.to_radians();
        (90.0 + 90.0 * x.log10()).to_radians() - PI
    };
    let start = FourBar {
        l1: 1.0,
        l2: 1.0,
        l3: 2.0,
        l4: 2.0,
    };
    let free = |problem: Problem<FourBar, 2, 4>| {
        problem
            .freed(&[("l2", 0.1, 5.0), ("l3", 0.1, 5.0), ("l4", 0.1, 5.0)])
            .guess(vector![1.0, wanted(0.0)])
    };
    let range = (0.0, 60f64.to_radians());
    let samples = 31;
    let fitted = free(Problem::function_over(start, "theta4", range, samples, wanted).unwrap());
    let chebyshev: Vec<(f64, f64)> = [1.0, 2.0, 3.0]
        .map(|j: f64| crank(5.5 - 4.5 * (PI * (2.0 * j - 1.0) / 6.0).cos()))
        .iter()
        .map(|&t| (t, wanted(t)))
        .collect();
    let exact = free(Problem::function(start, "theta4", &chebyshev).unwrap())
        .driver_range(range.0, range.1)
        .unwrap()
        .precision_points();
    // (The fits are compared, not their transmission: the fitted design's
    // falls to 11° at θ2 = 0, below the default 40°.)
    let mut requirements = Requirements::new(Range::Task);
    requirements.min_transmission = 0.0;
    let search = Search::default();
    let fitted = synthesize(&fitted, &requirements, &search).unwrap();
    let exact = synthesize(&exact, &requirements, &search).unwrap();
    let squares = |design: &linkage::synthesis::Candidate<FourBar, 2>| -> f64 {
        (0..samples)
            .map(|k| {
                let theta = range.1 * k as f64 / (samples - 1) as f64;
                let at = theta4(&design.model, (design.drivers[0], &design.poses[0]), theta);
                let miss = at - wanted(theta);
                let miss = miss - 2.0 * PI * (miss / (2.0 * PI)).round();
                miss * miss
            })
            .sum()
    };
    let (fitted, exact) = (fitted.best().unwrap(), exact.best().unwrap());
    let (ours, theirs) = (squares(fitted), squares(exact));
    assert!(
        ours < 0.9 * theirs,
        "a fit no better than three points: {ours:e}, {theirs:e}"
    );
    let rms = (ours / samples as f64).sqrt();
    assert!(
        (rms - fitted.rms_error).abs() <= 1e-12 * rms,
        "the search's error {} against the closed form's {rms}",
        fitted.rms_error
    );
}

#[test]
fn a_function_range_that_cannot_be_sampled_is_a_typed_error() {
    let range = |from: f64, to: f64, samples: usize, value: f64| {
        Problem::function_over(FourBar::WORKSHEET, "theta4", (from, to), samples, |_| value)
            .map(|_| ())
    };
    assert!(matches!(
        range(0.0, 1.0, 1, 0.0),
        Err(SynthesisError::FunctionRange(_))
    ));
    assert!(matches!(
        range(1.0, 1.0, 5, 0.0),
        Err(SynthesisError::FunctionRange(_))
    ));
    assert!(matches!(
        range(0.0, f64::NAN, 5, 0.0),
        Err(SynthesisError::FunctionRange(_))
    ));
    assert!(matches!(
        range(0.0, 1.0, 5, f64::INFINITY),
        Err(SynthesisError::NonFiniteTarget)
    ));
    assert!(matches!(
        Problem::function_over(FourBar::WORKSHEET, "theta9", (0.0, 1.0), 5, |_| 0.0).map(|_| ()),
        Err(SynthesisError::UnknownName(_))
    ));
    assert!(range(0.0, 1.0, 2, -0.9).is_ok());
}

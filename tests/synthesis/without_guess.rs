//! Synthesis without a guess of the first pose: each start assembles its
//! design with the assembly search (`linkage::assembly`) and follows the
//! first mode that reaches every target; the same designs as with the
//! worksheet's guess.

use crate::{AWAY, Freed, WIDE, rocker, transmission, worksheet_targets};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use linkage::synthesis::{Problem, Range, Requirements, Search, Timing, synthesize};
use std::f64::consts::PI;

#[test]
fn freudensteins_three_precision_points_need_no_guess() {
    let design = [1.0, 0.25, 0.625, 0.875];
    let thetas = [30f64, 60.0, 90.0].map(f64::to_radians);
    // θ4, the direction C→D, at each crank angle: Freudenstein's φ − π.
    let targets: Vec<(f64, f64)> = thetas
        .iter()
        .map(|&t| (t, rocker(design, t) - PI))
        .collect();
    let start = FourBar {
        l1: 1.0,
        l2: 0.3,
        l3: 0.7,
        l4: 0.8,
    };
    let problem = Problem::function(start, "theta4", &targets)
        .unwrap()
        .freed(&[("l2", 0.1, 0.5), ("l3", 0.3, 1.2), ("l4", 0.3, 1.2)])
        .precision_points();
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Targets),
        &Search {
            starts: 16,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(!found.designs.is_empty(), "{found:?}");
    for d in &found.designs {
        let m = &d.model;
        let error = (m.l2 - design[1])
            .abs()
            .max((m.l3 - design[2]).abs())
            .max((m.l4 - design[3]).abs());
        assert!(error < 1e-12, "{m:?}: {error:e}");
        // On the branch the targets were taken from (θ3 > 0 there).
        assert!(d.poses[0][0] > 0.0, "{:?}", d.poses[0]);
    }
}

#[test]
fn path_generation_through_five_points_needs_no_guess() {
    let (targets, _) = worksheet_targets();
    let [(a, b), (c, d), (e, f)] = WIDE;
    let problem = Problem::path(AWAY, "G3", &targets, Timing::Free)
        .unwrap()
        .freed(&[("l2", a, b), ("l3", c, d), ("l4", e, f)]);
    let found = synthesize(
        &problem,
        &transmission(30.0),
        &Search {
            starts: 24,
            ..Search::default()
        },
    )
    .unwrap();
    let best = found.designs.first().unwrap_or_else(|| panic!("{found:?}"));
    assert!(best.rms_error < 1e-9, "{best:?}");
    let m = &best.model;
    assert!(
        (m.l2 - 20.0).abs() < 1e-8 && (m.l3 - 50.0).abs() < 1e-8 && (m.l4 - 70.0).abs() < 1e-8,
        "{m:?}"
    );
    // Without a guess no start failed for want of an assembly.
    assert!(found.failed_starts < found.starts, "{found:?}");
}

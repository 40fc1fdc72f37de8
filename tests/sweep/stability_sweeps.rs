//! Tracked sweeps over full cycles: every Grashof class of four-bar, the
//! slider-crank driven through its dead centres, and the six-bar. Never a
//! silent branch flip (every pose checked against the closed form on the
//! branch it must be on), every singular pose located and classified.

use crate::common::FourBar;
use crate::models::{SIX_BAR, SLIDER_CRANK, SLIDER_DRIVEN, SixBar, SliderDriven};
use linkage::closed_form::{self, Grashof, circle_intersection};
use linkage::prelude::*;
use std::f64::consts::{PI, TAU};

const STEPS: usize = 10_000;

/// |a − b| for angles, wrapped to [0, π].
fn angle_error(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// The branch sign each pose must be on: `start`, flipped at every event
/// that changes branch (limit positions, and the crossing of a branch point
/// when `flips_at_branch_points`).
fn expected_branch<const M: usize>(
    sweep: &Sweep<M, 1>,
    start: f64,
    k: usize,
    flips_at_branch_points: bool,
) -> f64 {
    let flips = sweep
        .events
        .iter()
        .filter(|e| e.after <= k && (e.kind == EventKind::LimitPosition || flips_at_branch_points))
        .count();
    if flips % 2 == 0 { start } else { -start }
}

/// The agreement to expect with the closed form at driver value `v`: 1e-9,
/// except within 1e-6 of a limit position, where the pose is determined only
/// to about √ε by either method (the two branches merge: a fold).
fn tolerance<const M: usize>(sweep: &Sweep<M, 1>, v: f64) -> f64 {
    let near_fold = sweep
        .events
        .iter()
        .any(|e| e.kind == EventKind::LimitPosition && (e.v[0] - v).abs() < 1e-6);
    if near_fold { 1e-7 } else { 1e-9 }
}

/// Every pose of a four-bar sweep against the closed form; returns the worst
/// angle error.
fn check_fourbar(
    bar: &FourBar,
    sweep: &Sweep<2, 1>,
    start_branch: f64,
    flips_at_branch_points: bool,
) -> f64 {
    let cf = bar.closed_form();
    let mut worst: f64 = 0.0;
    for (k, p) in sweep.poses.iter().enumerate() {
        let sigma = expected_branch(sweep, start_branch, k, flips_at_branch_points);
        let exact = cf
            .position(p.v[0], sigma)
            .expect("the closed form assembles");
        let e = angle_error(p.u[0], exact[0]).max(angle_error(p.u[1], exact[1]));
        assert!(
            e < tolerance(sweep, p.v[0]),
            "pose {k} at θ2 = {}: sweep {:?}, closed form {exact:?} on branch {sigma}",
            p.v[0],
            p.u.as_slice()
        );
        worst = worst.max(e);
    }
    worst
}

fn full_turn(steps: usize) -> Drive<1> {
    Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps,
    }
}

fn start_pose(bar: &FourBar, theta2: f64, sigma: f64) -> SVector<f64, 2> {
    let [a, b] = bar.closed_form().position(theta2, sigma).unwrap();
    vector![a, b]
}

#[test]
fn crank_rocker_full_cycle_never_flips() {
    assert_eq!(
        FourBar::WORKSHEET.closed_form().grashof(),
        Grashof::CrankRocker
    );
    for sigma in [1.0, -1.0] {
        let sweep = FourBar::WORKSHEET
            .sweep(
                &start_pose(&FourBar::WORKSHEET, 0.0, sigma),
                &full_turn(STEPS),
                &SweepOptions::default(),
            )
            .unwrap();
        assert!(sweep.complete);
        assert_eq!(sweep.poses.len(), STEPS + 1);
        assert!(sweep.events.is_empty(), "{:?}", sweep.events);
        let worst = check_fourbar(&FourBar::WORKSHEET, &sweep, sigma, false);
        eprintln!("crank-rocker, branch {sigma}: worst angle error {worst:.1e}");
        // After a full turn the mechanism is back where it started.
        let (first, last) = (sweep.poses[0].u, sweep.poses[STEPS].u);
        assert!((0..2).all(|i| angle_error(first[i], last[i]) < 1e-12));
    }
}

#[test]
fn double_crank_full_cycle_never_flips() {
    let bar = FourBar {
        l1: 20.0,
        l2: 60.0,
        l3: 50.0,
        l4: 70.0,
    };
    assert_eq!(bar.closed_form().grashof(), Grashof::DoubleCrank);
    let sweep = bar
        .sweep(
            &start_pose(&bar, 0.0, 1.0),
            &full_turn(STEPS),
            &SweepOptions::default(),
        )
        .unwrap();
    assert!(sweep.complete && sweep.events.is_empty());
    assert_eq!(sweep.poses.len(), STEPS + 1);
    let worst = check_fourbar(&bar, &sweep, 1.0, false);
    eprintln!("double crank: worst angle error {worst:.1e}");
    // The rocker turns fully too: θ4 advances by 2π over the cycle.
    let turn = sweep.poses[STEPS].u[1] - sweep.poses[0].u[1];
    assert!((turn.abs() - TAU).abs() < 1e-9, "θ4 turned by {turn}");
}

#[test]
fn triple_rocker_rocks_between_its_limit_positions() {
    let bar = FourBar {
        l2: 45.0,
        ..FourBar::WORKSHEET
    };
    let cf = bar.closed_form();
    assert_eq!(cf.grashof(), Grashof::TripleRocker);
    // The law of cosines: BD = l3 + l4.
    let limit = cf.collinear_crank_angles()[0];
    for (step, sigma) in [(4.0 * limit / STEPS as f64, 1.0), (limit / 3333.3, -1.0)] {
        let sweep = bar
            .sweep(
                &start_pose(&bar, 0.0, sigma),
                &Drive::Rocking {
                    from: vector![0.0],
                    step: vector![step],
                    max_steps: 2 * STEPS,
                },
                &SweepOptions::default(),
            )
            .unwrap();
        assert!(sweep.complete, "the rocking cycle closes");
        assert_eq!(sweep.events.len(), 2, "{:?}", sweep.events);
        for (e, expected) in sweep.events.iter().zip([limit, -limit]) {
            assert_eq!(e.kind, EventKind::LimitPosition);
            assert!(
                (e.v[0] - expected).abs() <= 1e-12,
                "limit at {} vs {expected}",
                e.v[0]
            );
            assert!(
                e.rank_measure > 1e-3,
                "a limit, not a branch point: {}",
                e.rank_measure
            );
        }
        let worst = check_fourbar(&bar, &sweep, sigma, false);
        eprintln!(
            "triple rocker, step {step:.2e}: {} poses, limits off the law of cosines by {:.1e} and {:.1e} rad, worst angle error {worst:.1e}",
            sweep.poses.len(),
            (sweep.events[0].v[0] - limit).abs(),
            (sweep.events[1].v[0] + limit).abs(),
        );
        // Back at the start on the starting branch.
        let (first, last) = (sweep.poses[0], *sweep.poses.last().unwrap());
        assert_eq!(last.v, first.v);
        assert!((0..2).all(|i| angle_error(first.u[i], last.u[i]) < 1e-9));
    }
}

#[test]
fn change_point_branch_point_is_found_and_crossed() {
    let bar = FourBar {
        l2: 40.0,
        ..FourBar::WORKSHEET
    };
    let cf = bar.closed_form();
    assert_eq!(cf.grashof(), Grashof::ChangePoint);
    // The collinear pose at θ2 = π is on the grid (step 5000 of 10 000) and,
    // with an odd number of steps, between grid values.
    for steps in [STEPS, STEPS + 1] {
        let sweep = bar
            .sweep(
                &start_pose(&bar, 0.0, 1.0),
                &full_turn(steps),
                &SweepOptions::default(),
            )
            .unwrap();
        assert!(sweep.complete);
        assert_eq!(sweep.events.len(), 1, "{:?}", sweep.events);
        let e = sweep.events[0];
        assert_eq!(e.kind, EventKind::BranchPoint);
        assert!((e.v[0] - PI).abs() <= 1e-12, "branch point at {}", e.v[0]);
        assert!(
            e.rank_measure < 1e-6,
            "[Ψ_u Ψ_v] loses rank: {}",
            e.rank_measure
        );
        // Through the crossing the sweep follows the smooth branch, which
        // changes assembly mode: the closed form's branch sign flips there.
        let worst = check_fourbar(&bar, &sweep, 1.0, true);
        eprintln!(
            "change point, {steps} steps: branch point at {:.15} rad (π = {:.15}), {} poses, worst angle error {worst:.1e}",
            e.v[0],
            PI,
            sweep.poses.len()
        );
    }
}

/// The crank-driven slider-crank has no singular pose: det Ψ_u = l cos θ3.
#[test]
fn crank_driven_slider_crank_sweeps_cleanly() {
    let sweep = SLIDER_CRANK
        .sweep(
            &vector![0.0, 0.25],
            &full_turn(STEPS),
            &SweepOptions::default(),
        )
        .unwrap();
    assert!(sweep.complete && sweep.events.is_empty());
    for p in &sweep.poses {
        let (r, l, e) = (SLIDER_CRANK.r, SLIDER_CRANK.l, SLIDER_CRANK.e);
        let theta2 = p.v[0];
        let theta3 = ((e - r * theta2.sin()) / l).asin();
        let s = r * theta2.cos() + l * theta3.cos();
        assert!(
            angle_error(p.u[0], theta3) < 1e-12 && (p.u[1] - s).abs() < 1e-14,
            "{p:?}"
        );
    }
}

/// Driven by its slider, the slider-crank meets its dead centres as limit
/// positions of the slider, at s = √((l ± r)² − e²); the sweep reverses the
/// slider there and the crank turns on through them.
#[test]
fn slider_driven_through_its_dead_centres() {
    let SliderDriven { r, l, e } = SLIDER_DRIVEN;
    let s_max = ((l + r).powi(2) - e * e).sqrt();
    let s_min = ((l - r).powi(2) - e * e).sqrt();
    let s0 = 0.2;
    let step = 2.0 * (s_max - s_min) / STEPS as f64;
    let closed = |s: f64, sigma: f64| {
        let b = circle_intersection(Vector2::zeros(), r, Vector2::new(s, e), l, sigma).unwrap();
        let bp = Vector2::new(s, e) - b;
        [b.y.atan2(b.x), bp.y.atan2(bp.x)]
    };
    let start = closed(s0, 1.0);
    let sweep = SLIDER_DRIVEN
        .sweep(
            &vector![start[0], start[1]],
            &Drive::Rocking {
                from: vector![s0],
                step: vector![step],
                max_steps: 2 * STEPS,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    assert!(sweep.complete);
    assert_eq!(sweep.events.len(), 2, "{:?}", sweep.events);
    for (event, expected) in sweep.events.iter().zip([s_max, s_min]) {
        assert_eq!(event.kind, EventKind::LimitPosition);
        assert!(
            (event.v[0] - expected).abs() <= 1e-12 * expected.max(1.0),
            "dead centre at {} vs {expected}",
            event.v[0]
        );
    }
    let mut worst: f64 = 0.0;
    for (k, p) in sweep.poses.iter().enumerate() {
        let sigma = expected_branch(&sweep, 1.0, k, false);
        let exact = closed(p.v[0], sigma);
        let err = angle_error(p.u[0], exact[0]).max(angle_error(p.u[1], exact[1]));
        assert!(
            err < tolerance(&sweep, p.v[0]),
            "pose {k} at s = {}: {:?} vs {exact:?}",
            p.v[0],
            p.u.as_slice()
        );
        worst = worst.max(err);
    }
    // Over the cycle the crank made one full turn.
    let turn = sweep.poses.last().unwrap().u[0] - sweep.poses[0].u[0];
    assert!(
        (turn.abs() - TAU).abs() < 1e-9,
        "the crank turned by {turn}"
    );
    eprintln!(
        "slider-driven: dead centres off by {:.1e} and {:.1e} m, worst angle error {worst:.1e}",
        (sweep.events[0].v[0] - s_max).abs(),
        (sweep.events[1].v[0] - s_min).abs()
    );
}

/// The six-bar over a full turn, against its closed form (the four-bar,
/// then the dyad by circle intersection).
#[test]
fn six_bar_full_cycle_never_flips() {
    let SixBar {
        l1,
        l2,
        l3,
        l4,
        e,
        beta,
        l5,
        l6,
        gx,
        gy,
    } = SIX_BAR;
    let four = closed_form::FourBar { l1, l2, l3, l4 };
    let closed = |theta2: f64, sigma2: f64| {
        let [t3, t4] = four.position(theta2, 1.0).unwrap();
        let b = four.b(theta2);
        let point_e = b + Vector2::new((t3 + beta).cos(), (t3 + beta).sin()) * e;
        let g = Vector2::new(gx, gy);
        let f = circle_intersection(point_e, l5, g, l6, sigma2).unwrap();
        let (ef, gf) = (f - point_e, f - g);
        [t3, t4, ef.y.atan2(ef.x), gf.y.atan2(gf.x)]
    };
    for sigma2 in [1.0, -1.0] {
        let start = closed(0.0, sigma2);
        let sweep = SIX_BAR
            .sweep(
                &SVector::<f64, 4>::from(start),
                &full_turn(STEPS),
                &SweepOptions::default(),
            )
            .unwrap();
        assert!(
            sweep.complete && sweep.events.is_empty(),
            "{:?}",
            sweep.events
        );
        let mut worst: f64 = 0.0;
        for p in &sweep.poses {
            let exact = closed(p.v[0], sigma2);
            for (ours, theirs) in p.u.iter().zip(exact) {
                worst = worst.max(angle_error(*ours, theirs));
            }
        }
        assert!(
            worst < 1e-9,
            "six-bar branch {sigma2}: worst angle error {worst:e}"
        );
        eprintln!("six-bar, dyad branch {sigma2}: worst angle error {worst:.1e}");
    }
}

/// f = 2: the five-bar's two cranks driven along a straight line of driver
/// space (both turning, at different rates), against its closed form.
#[test]
fn five_bar_along_a_path_of_both_drivers() {
    let bar = crate::models::FIVE_BAR;
    let closed = |t2: f64, t5: f64| {
        let b = Vector2::new(bar.l2 * t2.cos(), bar.l2 * t2.sin());
        let d = Vector2::new(bar.l1 + bar.l5 * t5.cos(), bar.l5 * t5.sin());
        let c = circle_intersection(b, bar.l3, d, bar.l4, 1.0).unwrap();
        let (bc, dc) = (c - b, c - d);
        [bc.y.atan2(bc.x), dc.y.atan2(dc.x)]
    };
    let start = closed(0.0, 1.0);
    let sweep = bar
        .sweep(
            &vector![start[0], start[1]],
            &Drive::Line {
                from: vector![0.0, 1.0],
                to: vector![TAU, 1.0 + 2.0 * TAU],
                steps: STEPS,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    assert!(
        sweep.complete && sweep.events.is_empty(),
        "{:?}",
        sweep.events
    );
    assert_eq!(sweep.poses.len(), STEPS + 1);
    let mut worst: f64 = 0.0;
    for p in &sweep.poses {
        let exact = closed(p.v[0], p.v[1]);
        worst = worst.max(angle_error(p.u[0], exact[0]).max(angle_error(p.u[1], exact[1])));
        // The drivers move along the line at the sweep's speed.
        assert!((p.vdot.norm() - 1.0).abs() < 1e-12);
    }
    assert!(worst < 1e-9, "five-bar: worst angle error {worst:e}");
    eprintln!("five-bar along a path: worst angle error {worst:.1e}");
}

/// The sweep's velocities and accelerations are those of `analyze` for the
/// driver at the sweep's speed: ω2 = 400 rpm over the worksheet's cycle.
#[test]
fn sweep_kinematics_match_analyze() {
    let omega2 = crate::common::OMEGA2;
    let options = SweepOptions {
        speed: omega2,
        ..SweepOptions::default()
    };
    let sweep = FourBar::WORKSHEET
        .sweep(
            &start_pose(&FourBar::WORKSHEET, 0.0, 1.0),
            &full_turn(360),
            &options,
        )
        .unwrap();
    for p in &sweep.poses {
        let a = FourBar::WORKSHEET
            .analyze(
                &p.u,
                &p.v,
                &vector![omega2],
                &vector![0.0],
                &Options::default(),
            )
            .unwrap();
        assert_eq!(p.vdot, vector![omega2]);
        assert!((p.u - a.u).amax() < 1e-14);
        assert!(
            (p.udot - a.udot).amax() <= 1e-12 * a.udot.amax(),
            "{:?} vs {:?}",
            p.udot,
            a.udot
        );
        assert!(
            (p.uddot - a.uddot).amax() <= 1e-12 * a.uddot.amax(),
            "{:?} vs {:?}",
            p.uddot,
            a.uddot
        );
    }
}

//! Synthesis against closed forms and its own certificate: Freudenstein's
//! three-precision-point function generation, path generation through
//! points of a known coupler curve, and the typed errors of bad problems.

#[path = "../models/mod.rs"]
mod models;
/// The path tasks of the side-by-side with pylinkage (their bounds).
#[allow(dead_code)]
#[path = "../../examples/synthesis/tasks.rs"]
mod tasks;

/// Burmester's four- and five-position motion generation against a
/// 50-digit reference.
mod burmester;
/// The designer's terms, curves and functions over a range.
mod objectives;
/// Synthesis without a guess of the first pose.
mod without_guess;
use crate::models::Coupler;
use linkage::closed_form::{self, Grashof};
use linkage::mechanisms::{CouplerFourBar, FourBar};
use linkage::nalgebra::{Matrix3, Vector3};
use linkage::prelude::*;
use linkage::synthesis::{
    Defect, Problem, Range, Requirements, Search, SynthesisError, Timing, Transmission, certify,
    synthesize, synthesize_cancellable,
};
use std::f64::consts::{PI, TAU};

/// The rocker's angle at D (from the ground line, Freudenstein's φ) of the
/// four-bar `l` at the crank angle θ on the branch with θ3 > 0.
fn rocker(l: [f64; 4], theta: f64) -> f64 {
    let bar = closed_form::FourBar {
        l1: l[0],
        l2: l[1],
        l3: l[2],
        l4: l[3],
    };
    let [_, theta4] = [1.0, -1.0]
        .into_iter()
        .filter_map(|s| bar.position(theta, s))
        .find(|a| a[0] > 0.0)
        .expect("assembles");
    theta4 + PI
}

#[test]
fn freudenstein_three_precision_points_are_reproduced() {
    // Precision points from the worksheet's four-bar scaled to l1 = 1.
    let design = [1.0, 0.25, 0.625, 0.875];
    let thetas = [30f64, 60.0, 90.0].map(f64::to_radians);
    let phis = thetas.map(|t| rocker(design, t));
    // Freudenstein: K1 cos φ − K2 cos θ + K3 = cos(θ − φ), K1 = d/a,
    // K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac): linear in K.
    let a = Matrix3::from_fn(|i, j| [phis[i].cos(), -thetas[i].cos(), 1.0][j]);
    let rhs = Vector3::from_fn(|i, _| (thetas[i] - phis[i]).cos());
    let k = a.lu().solve(&rhs).expect("three distinct points");
    let d = 1.0_f64;
    let (l2, l4) = (d / k[0], d / k[1]);
    let l3 = (l2 * l2 + l4 * l4 + d * d - 2.0 * l2 * l4 * k[2]).sqrt();

    let start = FourBar {
        l1: 1.0,
        l2: 0.3,
        l3: 0.7,
        l4: 0.8,
    };
    // Our θ4 is the direction C→D: φ − π.
    let targets: Vec<(f64, f64)> = thetas
        .iter()
        .zip(&phis)
        .map(|(t, p)| (*t, p - PI))
        .collect();
    let problem = Problem::function(start, "theta4", &targets)
        .unwrap()
        .freed(&[("l2", 0.1, 0.5), ("l3", 0.3, 1.2), ("l4", 0.3, 1.2)])
        .guess(vector![1.3, -0.8])
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
    for design in &found.designs {
        let m = &design.model;
        let error = (m.l2 - l2)
            .abs()
            .max((m.l3 - l3).abs())
            .max((m.l4 - l4).abs());
        assert!(
            error < 1e-12,
            "{m:?} against the closed form ({l2}, {l3}, {l4}): {error:e}"
        );
    }
    // And the closed form is the design they came from.
    assert!((l2 - 0.25).abs() < 1e-13 && (l3 - 0.625).abs() < 1e-13 && (l4 - 0.875).abs() < 1e-13);
}

/// Freudenstein's problem on the worksheet's four-bar read at run time
/// from its equations: the closed form's design, to 1e-12.
#[test]
fn a_mechanism_read_at_run_time_is_synthesized_as_the_compiled_one() {
    let design = [1.0, 0.25, 0.625, 0.875];
    let thetas = [30f64, 60.0, 90.0].map(f64::to_radians);
    let targets: Vec<(f64, f64)> = thetas
        .iter()
        .map(|&t| (t, rocker(design, t) - PI))
        .collect();
    let text = "u = [theta3, theta4], v = [theta2],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
            l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        ]";
    let start = [("l1", 1.0), ("l2", 0.3), ("l3", 0.7), ("l4", 0.8)];
    let run_time = linkage::mechanism::Mechanism::from_text("Bar", text, &start)
        .unwrap()
        .sensitive::<2, 1, 4>()
        .unwrap();
    let problem = Problem::function(run_time, "theta4", &targets)
        .unwrap()
        .freed(&[("l2", 0.1, 0.5), ("l3", 0.3, 1.2), ("l4", 0.3, 1.2)])
        .guess(vector![1.3, -0.8])
        .precision_points();
    let search = Search {
        starts: 16,
        ..Search::default()
    };
    // Observed: every start reported once, and the same designs.
    let ended = std::sync::atomic::AtomicUsize::new(0);
    let found = linkage::synthesis::synthesize_observed(
        &problem,
        &Requirements::new(Range::Targets),
        &search,
        &|| {
            ended.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        },
    )
    .unwrap();
    assert_eq!(ended.into_inner(), search.starts);
    let again = synthesize(&problem, &Requirements::new(Range::Targets), &search).unwrap();
    let designs =
        |s: &linkage::synthesis::Synthesis<linkage::mechanism::Fixed<2, 1, 32, 4>, 2>| -> Vec<_> {
            (s.designs.iter())
                .map(|c| (c.model.params(), c.rms_error.to_bits()))
                .collect()
        };
    assert_eq!(designs(&found), designs(&again));
    assert!(!found.designs.is_empty(), "{found:?}");
    for candidate in &found.designs {
        let l = candidate.model.params();
        assert_eq!(l[0], 1.0, "l1 is not free");
        let error = (l - vector![1.0, 0.25, 0.625, 0.875]).amax();
        assert!(error < 1e-12, "{l} against the closed form: {error:e}");
        assert!(candidate.certificate.is_some(), "certified");
    }
}

#[test]
fn bad_problems_are_typed_errors() {
    let bar = FourBar::WORKSHEET;
    let four = [(0.1, -0.8), (0.3, -0.85), (0.5, -0.9), (0.7, -0.95)];
    let over = Problem::function(bar, "theta4", &four)
        .unwrap()
        .freed(&[("l2", 10.0, 30.0), ("l3", 30.0, 70.0), ("l4", 50.0, 90.0)])
        .guess(vector![1.3, -0.8])
        .precision_points();
    // Four arbitrary precision points, three unknowns: no design meets
    // them, and the error names the closest candidate and why.
    let found = synthesize(
        &over,
        &Requirements::new(Range::Targets),
        &Search {
            starts: 8,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(found.designs.is_empty());
    match found.best() {
        Err(SynthesisError::NoDesign {
            closest: Some(closest),
            ..
        }) => assert!(matches!(closest.defect, Defect::Misses { .. })),
        Err(SynthesisError::Unreachable { .. }) => {}
        other => panic!("{other:?}"),
    }
    // A driver range: empty, or not holding a prescribed driver; asked of
    // a problem that states none.
    let three = || Problem::function(bar, "theta4", &four[..3]).unwrap();
    assert_eq!(
        three().driver_range(0.4, 0.4).unwrap_err(),
        SynthesisError::EmptyRange { from: 0.4, to: 0.4 }
    );
    assert!(matches!(
        three().driver_range(0.0, f64::NAN),
        Err(SynthesisError::EmptyRange { .. })
    ));
    assert_eq!(
        three().driver_range(0.2, 1.0).unwrap_err(),
        SynthesisError::OutsideRange {
            target: 0,
            driver: 0.1,
            from: 0.2,
            to: 1.0
        }
    );
    assert!(three().driver_range(0.6, 0.0).is_ok());
    let free = three().free("l2", 10.0, 30.0).unwrap();
    assert!(matches!(
        synthesize(&free, &Requirements::new(Range::Task), &Search::default()),
        Err(SynthesisError::NoRange)
    ));
    let problem = || Problem::function(bar, "theta4", &four[..3]).unwrap();
    assert!(matches!(
        problem().free("l2", 30.0, 10.0),
        Err(SynthesisError::EmptyBounds { .. })
    ));
    assert!(matches!(
        problem().free("l2", 10.0, f64::INFINITY),
        Err(SynthesisError::EmptyBounds { .. })
    ));
    assert!(matches!(
        problem().free("l9", 1.0, 2.0),
        Err(SynthesisError::UnknownName(_))
    ));
    assert!(matches!(
        Problem::function(bar, "theta9", &four),
        Err(SynthesisError::UnknownName(_))
    ));
    assert!(matches!(
        Problem::path(bar, "Z", &[vector![1.0, 2.0]], Timing::Free),
        Err(SynthesisError::UnknownName(_))
    ));
    assert!(matches!(
        Problem::function(bar, "theta4", &[]),
        Err(SynthesisError::NoTargets)
    ));
    assert!(matches!(
        Problem::path(bar, "C", &[vector![1.0, f64::NAN]], Timing::Free),
        Err(SynthesisError::NonFiniteTarget)
    ));
    assert!(matches!(
        Problem::path(
            bar,
            "C",
            &[vector![1.0, 2.0]],
            Timing::Prescribed(vec![0.1, 0.2])
        ),
        Err(SynthesisError::Timing {
            targets: 1,
            drivers: 2
        })
    ));
    assert!(matches!(
        synthesize(
            &problem(),
            &Requirements::new(Range::Targets),
            &Search::default()
        ),
        Err(SynthesisError::NothingFree)
    ));
}

/// Five points of the worksheet's coupler curve of G3, at θ2 = 10°, 82°, …
fn worksheet_targets() -> (Vec<Vector2<f64>>, Vec<f64>) {
    let bar = FourBar::WORKSHEET;
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![2.0 * PI],
        steps: 360,
    };
    let sweep = bar
        .sweep(&vector![1.3, -0.8], &drive, &SweepOptions::default())
        .unwrap();
    let picks: Vec<usize> = (0..5).map(|i| 10 + 72 * i).collect();
    let targets = picks
        .iter()
        .map(|&k| bar.point_positions(&sweep.poses[k].u, &sweep.poses[k].v)[FourBar::G3])
        .collect();
    (
        targets,
        picks.iter().map(|&k| sweep.poses[k].v[0]).collect(),
    )
}

/// Path generation for G3 of a four-bar with l1 = 80, l2, l3, l4 free
/// within `bounds`, timing free, from the worksheet's branch.
fn g3_path(
    start: FourBar,
    targets: &[Vector2<f64>],
    bounds: [(f64, f64); 3],
) -> Problem<FourBar, 2, 4> {
    let [(a, b), (c, d), (e, f)] = bounds;
    Problem::path(start, "G3", targets, Timing::Free)
        .unwrap()
        .freed(&[("l2", a, b), ("l3", c, d), ("l4", e, f)])
        .guess(vector![1.3, -0.8])
}

/// The path problems' start: the worksheet's four-bar with its links
/// changed.
const AWAY: FourBar = FourBar {
    l2: 25.0,
    l3: 45.0,
    l4: 65.0,
    ..FourBar::WORKSHEET
};

/// The wide bounds of the path problems.
const WIDE: [(f64, f64); 3] = [(10.0, 30.0), (30.0, 70.0), (50.0, 90.0)];

/// The transmission angle as a designer writes it: its cosine, from the
/// directions C→B (θ3 + π) and C→D (θ4).
fn transmission(min_degrees: f64) -> Requirements<'static, FourBar, 2> {
    let mut requirements = Requirements::new(Range::Revolution);
    requirements.min_transmission = min_degrees.to_radians();
    requirements.transmission =
        Transmission::Cosine(Box::new(|_: &FourBar, pose: &SweepPose<2, 1>| {
            -(pose.u[1] - pose.u[0]).cos()
        }));
    requirements
}

#[test]
fn path_generation_finds_the_coupler_curve_through_five_points_and_certifies_it() {
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, WIDE);
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
    // Every design returned runs the whole turn through the targets in order.
    for design in &found.designs {
        let drivers = &design.drivers;
        let forward: f64 = (0..5)
            .map(|i| (drivers[(i + 1) % 5] - drivers[i]).rem_euclid(2.0 * PI))
            .sum();
        let backward: f64 = (0..5)
            .map(|i| (drivers[i] - drivers[(i + 1) % 5]).rem_euclid(2.0 * PI))
            .sum();
        assert!(
            (forward - 2.0 * PI).abs() < 1e-9 || (backward - 2.0 * PI).abs() < 1e-9,
            "{drivers:?}"
        );
    }
}

/// pylinkage's README task (its coupler point through (0, 0), (1, 1), (2,
/// 1), (3, 0), every dimension of the four-bar free within the box of the
/// side-by-side with pylinkage, timing free, certified over a turn with
/// the default 40° of transmission): a search that starts from designs
/// whose crank turns certifies its first design within 16 starts for each
/// of five random states. (Starting from the first draw that could be
/// followed, rockers included, took two to five rounds of 8 starts.)
#[test]
fn the_readme_task_of_pylinkage_certifies_a_design_within_sixteen_starts() {
    let targets = [
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(2.0, 1.0),
        Vector2::new(3.0, 0.0),
    ];
    let problem = tasks::path_problem(&targets).unwrap();
    for random_state in 1..=5 {
        let found = synthesize(
            &problem,
            &Requirements::new(Range::Revolution),
            &Search {
                starts: 128,
                random_state,
                enough: Some(1),
                ..Search::default()
            },
        )
        .unwrap();
        let design = found.best().unwrap_or_else(|e| panic!("{e}"));
        assert!(design.largest_error().1 < 1e-12, "{design:?}");
        assert!(
            found.starts <= 16,
            "random state {random_state}: {} starts",
            found.starts
        );
    }
}

/// A search asked for enough designs takes its starts in order and ends
/// with the start that certifies them: what it returns is exactly what the
/// whole search found from those starts, whatever the number of threads.
#[test]
fn a_search_stops_at_the_start_that_certifies_enough_designs() {
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, WIDE);
    let search = Search {
        starts: 48,
        ..Search::default()
    };
    let whole = synthesize(&problem, &transmission(30.0), &search).unwrap();
    let mut starts = whole.designs.iter().map(|d| d.start).collect::<Vec<_>>();
    starts.sort();
    assert!(!starts.is_empty(), "{starts:?}");
    let every = starts.len();
    for (enough, threads) in [(1, 1), (1, 2), (1, 3), (every, 2)] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let early = pool
            .install(|| {
                synthesize(
                    &problem,
                    &transmission(30.0),
                    &Search {
                        enough: Some(enough),
                        ..search
                    },
                )
            })
            .unwrap();
        // The start of the enough-th design is the last one run.
        let last = starts[enough - 1];
        assert_eq!(
            early.starts,
            last + 1,
            "{enough} designs, {threads} threads"
        );
        assert_eq!(early.designs.len(), enough);
        for design in &early.designs {
            assert!(design.start <= last);
            assert!(
                whole.designs.iter().any(|d| d == design),
                "{design:?} is not among the whole search's designs"
            );
        }
        let refused = whole.refused.iter().filter(|r| r.0.start <= last);
        assert_eq!(early.refused, refused.cloned().collect::<Vec<_>>());
        let seen = early.designs.len() + early.refused.len() + early.failed_starts;
        assert!(seen <= early.starts);
    }
}

/// A search split into shards of consecutive starts (the same random
/// state, `first` set, duplicates kept) gives, shard after shard, the
/// designs of the whole search run at once, candidate for candidate.
#[test]
fn shards_of_a_search_put_together_are_the_whole_search() {
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, WIDE);
    let whole = Search {
        starts: 24,
        random_state: 7,
        distinct: false,
        ..Search::default()
    };
    let all = synthesize(&problem, &transmission(30.0), &whole).unwrap();
    let mut designs = Vec::new();
    let (mut refused, mut failed) = (0, 0);
    for (first, starts) in [(0, 5), (5, 11), (16, 8)] {
        let shard = Search {
            first,
            starts,
            ..whole
        };
        let part = synthesize(&problem, &transmission(30.0), &shard).unwrap();
        assert!(
            part.designs
                .iter()
                .all(|d| (first..first + starts).contains(&d.start))
        );
        designs.extend(part.designs);
        refused += part.refused.len();
        failed += part.failed_starts;
    }
    designs.sort_by_key(|d| d.start);
    let mut whole_designs = all.designs.clone();
    whole_designs.sort_by_key(|d| d.start);
    assert!(whole_designs.len() > 1, "{}", whole_designs.len());
    assert_eq!(designs, whole_designs);
    assert_eq!((refused, failed), (all.refused.len(), all.failed_starts));
    // Duplicates kept: the distinct search returns fewer or as many.
    let distinct = synthesize(
        &problem,
        &transmission(30.0),
        &Search {
            distinct: true,
            ..whole
        },
    )
    .unwrap();
    assert!(distinct.designs.len() <= all.designs.len());
    assert!(distinct.designs.iter().all(|d| all.designs.contains(d)));
}

/// Pieces of a distinct search absorbed one after the other
/// (`Synthesis::absorb`) are the whole distinct search, row for row: a
/// design found again in a later piece dropped as the whole search drops
/// it.
#[test]
fn pieces_absorbed_in_order_are_the_whole_distinct_search() {
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, WIDE);
    let whole = Search {
        starts: 24,
        random_state: 7,
        ..Search::default()
    };
    let all = synthesize(&problem, &transmission(30.0), &whole).unwrap();
    let mut pieces = None::<linkage::synthesis::Synthesis<_, 2>>;
    let mut found_in_pieces = 0;
    for (first, starts) in [(0, 5), (5, 11), (16, 8)] {
        let piece = Search {
            first,
            starts,
            ..whole
        };
        let part = synthesize(&problem, &transmission(30.0), &piece).unwrap();
        found_in_pieces += part.designs.len();
        match pieces.as_mut() {
            None => pieces = Some(part),
            Some(found) => found.absorb(&problem, part),
        }
    }
    let pieces = pieces.unwrap();
    // A design found in more than one piece, kept once.
    assert!(found_in_pieces > all.designs.len(), "{found_in_pieces}");
    assert_eq!(pieces, all);
}

/// A search told to stop ends with `Cancelled` once the starts under way
/// are done, and starts no more.
#[test]
fn a_cancelled_search_stops_between_starts() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, WIDE);
    let search = Search {
        starts: 64,
        ..Search::default()
    };
    let ended = AtomicUsize::new(0);
    let stopped = synthesize_cancellable(
        &problem,
        &transmission(30.0),
        &search,
        &|| {
            ended.fetch_add(1, Ordering::Relaxed);
        },
        &|| ended.load(Ordering::Relaxed) >= 3,
    );
    assert_eq!(stopped, Err(SynthesisError::Cancelled));
    // The starts under way when the flag rose finish; no other begins.
    let ran = ended.load(Ordering::Relaxed);
    assert!(
        (3..3 + rayon::current_num_threads()).contains(&ran),
        "{ran} starts ran"
    );
    let never = synthesize_cancellable(&problem, &transmission(30.0), &search, &|| {}, &|| true);
    assert_eq!(never, Err(SynthesisError::Cancelled));
}

/// The requirement that a design be of one Grashof type (the designer's
/// check, here by the closed form's classification).
fn grashof(wanted: Grashof) -> Requirements<'static, FourBar, 2> {
    let mut requirements = Requirements::new(Range::Revolution);
    requirements.check = Some(Box::new(move |m: &FourBar| {
        let found = m.closed_form().grashof();
        if found == wanted {
            Ok(())
        } else {
            Err(format!("a {found:?}, not a {wanted:?}"))
        }
    }));
    requirements
}

/// A Grashof type asked for is kept: near the worksheet's design (a
/// crank-rocker), asking for crank-rockers certifies it, asking for
/// double cranks refuses every candidate that meets the targets with the
/// designer's reason.
#[test]
fn a_requested_grashof_type_is_certified_and_another_refused() {
    let (targets, _) = worksheet_targets();
    let near = [(19.0, 21.0), (49.0, 51.0), (69.0, 71.0)];
    let problem = g3_path(AWAY, &targets, near);
    let search = Search {
        starts: 8,
        ..Search::default()
    };
    let found = synthesize(&problem, &grashof(Grashof::CrankRocker), &search).unwrap();
    assert!(!found.designs.is_empty(), "{found:?}");
    let refused = synthesize(&problem, &grashof(Grashof::DoubleCrank), &search).unwrap();
    assert!(refused.designs.is_empty(), "{:?}", refused.designs);
    // Those that meet the targets are refused by the check (before any
    // sweep); the others for missing them.
    let mut checked = 0;
    for (_, defect) in &refused.refused {
        match defect {
            Defect::Check(why) => {
                assert_eq!(why, "a CrankRocker, not a DoubleCrank");
                checked += 1;
            }
            _ => assert!(matches!(defect, Defect::Misses { .. }), "{defect:?}"),
        }
    }
    assert!(
        checked >= found.designs.len(),
        "{checked} refused by the check"
    );
}

#[test]
fn a_design_that_fails_its_requirements_is_refused_with_the_reason() {
    // The worksheet's four-bar has a smallest transmission angle of 57°:
    // asking 80° refuses it, and says where the angle falls short.
    let (targets, _) = worksheet_targets();
    let problem = g3_path(AWAY, &targets, [(19.0, 21.0), (49.0, 51.0), (69.0, 71.0)]);
    let found = synthesize(
        &problem,
        &transmission(80.0),
        &Search {
            starts: 8,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(found.designs.is_empty(), "{:?}", found.designs);
    // The starts that converge to the worksheet's design are refused for
    // the transmission angle, on the first leg where it falls short, with
    // the angle there (cos μ = (l3² + l4² − BD²)/(2 l3 l4), BD the
    // diagonal); those that converge elsewhere (targets out of order) for
    // that.
    let mu = |theta2: f64| {
        let bd2 = 80f64.powi(2) + 20f64.powi(2) - 2.0 * 80.0 * 20.0 * theta2.cos();
        ((50f64.powi(2) + 70f64.powi(2) - bd2) / (2.0 * 50.0 * 70.0)).acos()
    };
    let mut seen = 0;
    for (candidate, defect) in &found.refused {
        match defect {
            Defect::Transmission { v, angle } if candidate.rms_error < 1e-9 => {
                assert!(
                    (angle - mu(*v)).abs() < 1e-9,
                    "{angle} against {}: {defect:?}",
                    mu(*v)
                );
                assert!(*angle < 80f64.to_radians());
                seen += 1;
            }
            Defect::Order { .. } => {}
            other => panic!("{other:?} for {:?}", candidate.model),
        }
    }
    assert!(seen > 0, "{:?}", found.refused);
}

/// An independent check of a returned design: a dense sweep of one whole
/// turn from its first target, which must run without a singular pose and
/// pass every target at its driver, in the targets' order.
fn runs_through_its_targets(
    design: &linkage::synthesis::Candidate<FourBar, 2>,
    targets: &[Vector2<f64>],
) {
    let drivers = &design.drivers;
    let direction = if (drivers[1] - drivers[0]).rem_euclid(2.0 * PI) < PI {
        1.0
    } else {
        -1.0
    };
    let drive = Drive::Line {
        from: vector![drivers[0]],
        to: vector![drivers[0] + direction * 2.0 * PI],
        steps: 3600,
    };
    let sweep = design
        .model
        .sweep(&design.poses[0], &drive, &SweepOptions::default())
        .unwrap();
    assert!(
        sweep.complete && sweep.events.is_empty(),
        "{:?}",
        sweep.events
    );
    let mut passed = Vec::new();
    for (i, target) in targets.iter().enumerate() {
        // The turn's driver at the target, and the pose the sweep has there.
        let along = (direction * (drivers[i] - drivers[0])).rem_euclid(2.0 * PI);
        let v = drivers[0] + direction * along;
        let near = sweep
            .poses
            .iter()
            .min_by(|a, b| (a.v[0] - v).abs().total_cmp(&(b.v[0] - v).abs()))
            .unwrap();
        let pose = design
            .model
            .solve_position(&near.u, &vector![v], &Options::default())
            .unwrap();
        let point = design.model.point_positions(&pose.u, &vector![v])[FourBar::G3];
        assert!(
            (point - target).norm() < 1e-6 + 2.0 * design.errors[i],
            "target {i}"
        );
        passed.push(along);
    }
    assert!(
        passed.windows(2).all(|w| w[1] > w[0]),
        "out of order: {passed:?}"
    );
}

/// `cases` cases from a fixed stream of random numbers (another with
/// `PROPTEST_RNG_SEED=n`), no failure files.
fn fixed_stream(cases: u32) -> proptest::prelude::ProptestConfig {
    let mut config = proptest::prelude::ProptestConfig::with_cases(cases);
    config.failure_persistence = None;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = proptest::test_runner::RngSeed::Fixed(0x7379_6e74_6865_7369);
    }
    config
}

proptest::proptest! {
    #![proptest_config(fixed_stream(6))]
    #[test]
    fn every_returned_design_runs_through_its_targets(
        // Crank-rockers: s + l = l2 + 80 ≤ 100 < l3 + l4, the crank shortest.
        l2 in 15.0..20.0f64, l3 in 45.0..60.0f64, l4 in 60.0..80.0f64,
        phase in 0.0..6.0f64, jitter in proptest::collection::vec(-1.0..1.0f64, 10),
    ) {
        // Targets near a coupler curve of a random crank-rocker (jittered
        // by up to 1 mm, so not always exactly reachable).
        let source = FourBar { l2, l3, l4, ..FourBar::WORKSHEET };
        let drive = Drive::Line { from: vector![0.0], to: vector![2.0 * PI], steps: 720 };
        let sweep = source.sweep(&vector![1.3, -0.8], &drive, &SweepOptions::default()).unwrap();
        proptest::prop_assert!(sweep.complete && sweep.poses.len() == 721);
        let targets: Vec<Vector2<f64>> = (0..5)
            .map(|i| {
                let k = ((phase / (2.0 * PI) * 720.0) as usize + 144 * i) % 720;
                let p = source.point_positions(&sweep.poses[k].u, &sweep.poses[k].v)[FourBar::G3];
                p + vector![jitter[2 * i], jitter[2 * i + 1]]
            })
            .collect();
        let problem = g3_path(FourBar::WORKSHEET, &targets, WIDE);
        let found = synthesize(&problem, &transmission(20.0), &Search { starts: 12, ..Search::default() }).unwrap();
        // Targets within a millimetre of a crank-rocker's curve: a design is found.
        proptest::prop_assert!(!found.designs.is_empty(), "{:?}", found.refused);
        for design in &found.designs {
            runs_through_its_targets(design, &targets);
        }
    }
}

/// The centre of the circle through three points.
fn circumcentre(p: [Vector2<f64>; 3]) -> Vector2<f64> {
    let (a, b, c) = (p[0], p[1], p[2]);
    let d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    let (a2, b2, c2) = (a.norm_squared(), b.norm_squared(), c.norm_squared());
    vector![
        (a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
        (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d
    ]
}

#[test]
fn three_position_motion_generation_is_reproduced() {
    // Three poses of a crank-rocker's coupler (crank 20 at A = (0, 0),
    // rocker 70 at D = (80, 0), coupler pivots 50 apart, P off the line).
    let known = Coupler {
        xa: 0.0,
        ya: 0.0,
        xd: 80.0,
        yd: 0.0,
        l2: 20.0,
        l4: 70.0,
        bx: -25.0,
        by: -10.0,
        cx: 25.0,
        cy: -10.0,
    };
    let drive = Drive::Line {
        from: vector![0.2],
        to: vector![4.2],
        steps: 400,
    };
    let sweep = known
        .sweep(
            &vector![30.0, 60.0, 0.3, -1.2],
            &drive,
            &SweepOptions::default(),
        )
        .unwrap();
    let poses: Vec<(Vector2<f64>, f64)> = [0, 200, 400]
        .iter()
        .map(|&k| {
            (
                vector![sweep.poses[k].u[0], sweep.poses[k].u[1]],
                sweep.poses[k].u[2],
            )
        })
        .collect();
    // The closed form: with the moving pivots chosen, each fixed pivot is
    // the centre of the circle through its moving pivot's three positions.
    let rotate = |angle: f64, x: f64, y: f64| {
        vector![
            x * angle.cos() - y * angle.sin(),
            x * angle.sin() + y * angle.cos()
        ]
    };
    let b = poses
        .iter()
        .map(|(p, t)| p + rotate(*t, known.bx, known.by))
        .collect::<Vec<_>>();
    let c = poses
        .iter()
        .map(|(p, t)| p + rotate(*t, known.cx, known.cy))
        .collect::<Vec<_>>();
    let (a, d) = (
        circumcentre([b[0], b[1], b[2]]),
        circumcentre([c[0], c[1], c[2]]),
    );
    let (l2, l4) = ((b[0] - a).norm(), (c[0] - d).norm());
    // (The poses close only to Newton's tolerance: the known design is
    // recovered to that, the closed form from these poses to rounding.)
    assert!(
        (a.norm() + (d - vector![80.0, 0.0]).norm()) < 1e-7
            && (l2 - 20.0).abs() < 1e-7
            && (l4 - 70.0).abs() < 1e-7,
        "{a} {d} {l2} {l4}"
    );

    let start = Coupler {
        xa: 5.0,
        ya: 5.0,
        xd: 70.0,
        yd: -5.0,
        l2: 25.0,
        l4: 60.0,
        ..known
    };
    let problem = Problem::motion(start, "P", "theta3", &poses, Timing::Free)
        .unwrap()
        .freed(&[
            ("xa", -20.0, 20.0),
            ("ya", -20.0, 20.0),
            ("xd", 60.0, 100.0),
            ("yd", -20.0, 20.0),
            ("l2", 10.0, 30.0),
            ("l4", 50.0, 90.0),
        ])
        .guess(vector![poses[0].0.x, poses[0].0.y, poses[0].1, -1.2])
        .precision_points();
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Targets),
        &Search {
            starts: 24,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(!found.designs.is_empty(), "{:?}", found.refused);
    for design in &found.designs {
        let m = &design.model;
        let error = [
            m.xa - a.x,
            m.ya - a.y,
            m.xd - d.x,
            m.yd - d.y,
            m.l2 - l2,
            m.l4 - l4,
        ]
        .iter()
        .fold(0.0f64, |e, x| e.max(x.abs()));
        assert!(error < 1e-12 * 80.0, "{m:?}: {error:e}");
    }
}

#[test]
fn a_target_out_of_reach_is_a_typed_error() {
    // G3 of a four-bar with l1 = 80 and links within these bounds stays
    // within 60 mm of the crank pivot: a precision point 500 mm away is out
    // of reach.
    let targets = [vector![20.0, 30.0], vector![500.0, 0.0]];
    let problem = g3_path(FourBar::WORKSHEET, &targets, WIDE).precision_points();
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Revolution),
        &Search {
            starts: 8,
            ..Search::default()
        },
    )
    .unwrap();
    assert!(found.designs.is_empty());
    let best = found.best();
    assert!(
        matches!(best, Err(SynthesisError::Unreachable { target: 1, error }) if error > 400.0),
        "{best:?}"
    );
}

/// The poses of `bar` at the crank angles `degrees` (in the order given),
/// followed by continuation from `guess` at the first along increasing
/// angles; the drivers as given.
fn poses_along(bar: FourBar, guess: SVector<f64, 2>, degrees: &[f64]) -> Vec<SVector<f64, 2>> {
    let mut at = degrees[0];
    let mut u = bar
        .solve_position(&guess, &vector![at.to_radians()], &Options::default())
        .unwrap()
        .u;
    let mut out = vec![u];
    for &d in &degrees[1..] {
        // The same pose whole turns apart: follow to the angle within one
        // turn ahead of the last.
        let ahead = at + (d - at).rem_euclid(360.0);
        let drive = Drive::Line {
            from: vector![at.to_radians()],
            to: vector![ahead.to_radians()],
            steps: ((ahead - at) as usize).max(1),
        };
        let sweep = bar.sweep(&u, &drive, &SweepOptions::default()).unwrap();
        assert!(sweep.complete, "{bar:?} from {at}° to {ahead}°");
        u = sweep.poses.last().unwrap().u;
        at = ahead;
        out.push(u);
    }
    out
}

#[test]
fn a_revolution_is_swept_whole_whatever_turn_each_drivers_value_is_in() {
    // Non-Grashof (20 + 80 > 40 + 55): the crank cannot pass 134°…226°.
    // Targets at 250°, 300°, 0°, 60°, 120° in one assembly: the turn's last
    // leg, from 120° (480°) on to 250° (610°), crosses that gap. With the
    // last driver written a turn on (840° for 480°, as a solver's free
    // driver may drift), a leg started from the target's own driver would
    // run back from 840° to 610° through the targets' side and never meet
    // the gap.
    let bar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 40.0,
        l4: 55.0,
    };
    let degrees = [250.0, 300.0, 360.0, 420.0, 480.0];
    let poses = poses_along(bar, vector![1.0, -1.0], &degrees);
    let drivers: Vec<f64> = [250.0, 300.0, 360.0, 420.0, 840.0]
        .iter()
        .map(|d: &f64| d.to_radians())
        .collect();
    // (Only the sweep through the gap is asked: the non-Grashof bar's
    // transmission angle falls below the default 40° on the way.)
    let mut requirements = Requirements::new(Range::Revolution);
    requirements.min_transmission = 0.0;
    let verdict = certify(
        &bar,
        &poses,
        &drivers,
        None,
        &requirements,
        &SweepOptions::default(),
    );
    assert!(
        matches!(
            verdict,
            Err(Defect::Singular { .. } | Defect::Incomplete { .. } | Defect::Stops { .. })
        ),
        "{verdict:?}"
    );
    // A crank-rocker with the same drivers, whole turns apart, runs the
    // turn and is certified.
    let worksheet = FourBar::WORKSHEET;
    let poses = poses_along(worksheet, vector![1.3, -0.8], &degrees);
    let certificate = certify(
        &worksheet,
        &poses,
        &drivers,
        None,
        &Requirements::new(Range::Revolution),
        &SweepOptions::default(),
    )
    .unwrap();
    // The turn swept, from the first target on, and the worksheet's
    // smallest transmission angle: 57.1° (cos μ = 3800/7000 at θ2 = 0).
    assert_eq!(certificate.from, drivers[0]);
    assert!((certificate.to - drivers[0] - TAU).abs() < 1e-12);
    let smallest = (3800.0f64 / 7000.0).acos();
    assert!(
        (certificate.transmission - smallest).abs() < 1e-3,
        "{certificate:?}"
    );
    assert!(certificate.transmission >= smallest - 1e-12);
}

#[test]
fn a_problems_jacobian_is_its_residuals_derivative() {
    // G3 through five points of the worksheet's curve, timing free: at the
    // worksheet's design and drivers every residual vanishes, and each
    // column of the Jacobian is the central difference of the residuals.
    let (targets, drivers) = worksheet_targets();
    let problem = g3_path(FourBar::WORKSHEET, &targets, WIDE);
    let bar = FourBar::WORKSHEET;
    let poses: Vec<SVector<f64, 2>> = drivers
        .iter()
        .map(|v| {
            bar.solve_position(&vector![1.3, -0.8], &vector![*v], &Options::default())
                .unwrap()
                .u
        })
        .collect();
    let mut x = vec![20.0, 50.0, 70.0];
    x.extend(&drivers);
    let options = Options::default();
    let (residuals, jacobian, found) = problem.evaluate(&x, &poses, &options).unwrap();
    assert!(residuals.amax() < 1e-12, "{residuals}");
    assert_eq!((jacobian.nrows(), jacobian.ncols()), (10, 8));
    for (a, b) in found.iter().zip(&poses) {
        assert!((a - b).amax() < 1e-12);
    }
    for j in 0..x.len() {
        let h = 1e-6 * x[j].abs().max(1.0);
        let at = |step: f64| {
            let mut y = x.clone();
            y[j] += step;
            problem.evaluate(&y, &poses, &options).unwrap().0
        };
        let difference = (at(h) - at(-h)) / (2.0 * h);
        let column = jacobian.column(j);
        assert!(
            // (Measured: 2.3e-10 of the column's size.)
            (&difference - column).amax() < 1e-8 * column.amax().max(1.0),
            "column {j}: {column} against {difference}"
        );
    }
    // Unknowns or poses of the wrong length.
    assert!(problem.evaluate(&x[1..], &poses, &options).is_none());
    assert!(problem.evaluate(&x, &poses[1..], &options).is_none());
}

/// Freudenstein's three Chebyshev points of y = log10 x on 1 ≤ x ≤ 10,
/// the crank over 45°…105° and θ4 (the direction C→D) as the output,
/// written from scratch (not one of the examples' tasks): the points lie
/// at 49.02°, 75° and 100.98°, inside the task's range. The four-bar
/// `scale` times the size: the ground `scale`, the links free within
/// [0.1, 5]·`scale`; its closed form's lengths beside it.
fn log10_task(scale: f64) -> (Problem<FourBar, 2, 4>, [f64; 3]) {
    let phi: [f64; 3] = [0.8555470979371927, 1.3089969389957472, 1.7624467800543016];
    let psi: [f64; 3] = [2.5031314937856872, 3.2750514376378943, 3.849787933013452];
    // cos(φ − θ4) = K1 cos φ + K2 cos θ4 + K3, K1 = l1/l4, K2 = l1/l2,
    // K3 = (l3² − l1² − l2² − l4²)/(2 l2 l4): linear in K.
    let a = Matrix3::from_fn(|i, j| [phi[i].cos(), psi[i].cos(), 1.0][j]);
    let rhs = Vector3::from_fn(|i, _| (phi[i] - psi[i]).cos());
    let k = a.lu().solve(&rhs).unwrap();
    let (l1, l4, l2) = (scale, scale / k[0], scale / k[1]);
    let l3 = (2.0 * l2 * l4 * k[2] + l1 * l1 + l2 * l2 + l4 * l4).sqrt();
    let start = FourBar {
        l1: scale,
        l2: scale,
        l3: 2.0 * scale,
        l4: 2.0 * scale,
    };
    let targets: Vec<(f64, f64)> = phi.iter().zip(psi).map(|(&p, q)| (p, q)).collect();
    let problem = Problem::function(start, "theta4", &targets)
        .unwrap()
        .freed(&[
            ("l2", 0.1 * scale, 5.0 * scale),
            ("l3", 0.1 * scale, 5.0 * scale),
            ("l4", 0.1 * scale, 5.0 * scale),
        ])
        .guess(vector![-1.09, 2.5])
        .driver_range(45f64.to_radians(), 105f64.to_radians())
        .unwrap()
        .precision_points();
    (problem, [l2, l3, l4])
}

/// The designer's transmission angle of the task above: acos(−cos(θ3 − θ4)).
fn transmission_of(min_degrees: f64, range: Range) -> Requirements<'static, FourBar, 2> {
    let mut requirements = Requirements::new(range);
    requirements.min_transmission = min_degrees.to_radians();
    requirements.transmission =
        Transmission::Cosine(Box::new(|_: &FourBar, pose: &SweepPose<2, 1>| {
            -(pose.u[0] - pose.u[1]).cos()
        }));
    requirements.grashof = Some(FourBar::grashof);
    requirements
}

/// The certificate covers the task's range, not only the precision
/// points' span: the design whose transmission angle is 25.83° at the
/// first point falls to 23.46° at the range's start, 45°, and a 25°
/// requirement refuses it there (it was certified when only the points'
/// span was swept). Over the points' span alone it passes, and its
/// certificate says what it swept. The refusal names the closest
/// candidate and why.
#[test]
fn a_certificate_covers_the_tasks_whole_range() {
    let (problem, closed) = log10_task(1.0);
    let search = Search {
        starts: 8,
        ..Search::default()
    };
    let over_points =
        synthesize(&problem, &transmission_of(25.0, Range::Targets), &search).unwrap();
    let design = over_points.best().unwrap();
    assert!((design.model.l3 - closed[1]).abs() < 1e-12, "{design:?}");
    let certificate = design.certificate.expect("a returned design is certified");
    assert_eq!(certificate.from, 0.8555470979371927);
    assert_eq!(certificate.to, 1.7624467800543016);
    // Closed form at 49.02°: 25.8275°.
    assert!((certificate.transmission.to_degrees() - 25.8275).abs() < 1e-3);
    assert_eq!(certificate.transmission_at, certificate.from);
    assert_eq!(certificate.grashof, Some(design.model.grashof()));

    let over_task = synthesize(&problem, &transmission_of(25.0, Range::Task), &search).unwrap();
    assert!(over_task.designs.is_empty(), "{:?}", over_task.designs);
    let refused = over_task
        .refused
        .iter()
        .find(|(c, _)| (c.model.l3 - closed[1]).abs() < 1e-12)
        .expect("the closed form's design, refused");
    match refused.1 {
        Defect::Transmission { v, angle } => {
            assert!((v - 45f64.to_radians()).abs() < 1e-12, "{v}");
            // Closed form at 45°: 23.4579°.
            assert!((angle.to_degrees() - 23.4579).abs() < 1e-3, "{angle}");
        }
        ref other => panic!("{other:?}"),
    }
    match over_task.best() {
        Err(
            e @ SynthesisError::NoDesign {
                closest: Some(_), ..
            },
        ) => {
            let SynthesisError::NoDesign {
                closest: Some(closest),
                ..
            } = &e
            else {
                unreachable!()
            };
            let least = over_task
                .refused
                .iter()
                .map(|(c, _)| c.rms_error)
                .fold(f64::INFINITY, f64::min);
            assert_eq!(closest.rms_error, least);
            assert!(
                e.to_string().contains("transmission angle falls to 23.46°"),
                "{e}"
            );
        }
        other => panic!("{other:?}"),
    }
    // With the range's start at 48°: 25.3°, certified over the task.
    let narrower = log10_task(1.0)
        .0
        .driver_range(48f64.to_radians(), 105f64.to_radians());
    let found = synthesize(
        &narrower.unwrap(),
        &transmission_of(25.0, Range::Task),
        &search,
    )
    .unwrap();
    let certificate = found.best().unwrap().certificate.unwrap();
    assert_eq!(
        (certificate.from, certificate.to),
        (48f64.to_radians(), 105f64.to_radians())
    );
}

/// The same task at three sizes: the solver stops at rounding whatever the
/// units (its tests are relative), and the precision points are accepted at
/// each. (Before, its gradient test was absolute below a residual of 1 and
/// stopped at residuals of 1e-13 rad, the lengths 1.9e-12 from the closed
/// form.)
#[test]
fn precision_points_reach_rounding_at_every_scale() {
    for scale in [1e-3, 1.0, 1e3] {
        let (problem, closed) = log10_task(scale);
        let found = synthesize(
            &problem,
            &transmission_of(20.0, Range::Task),
            &Search {
                starts: 8,
                ..Search::default()
            },
        )
        .unwrap();
        let design = found.best().unwrap();
        let m = &design.model;
        let off = [m.l2 - closed[0], m.l3 - closed[1], m.l4 - closed[2]]
            .iter()
            .fold(0.0f64, |e, x| e.max(x.abs()))
            / scale;
        assert!(off < 1e-14, "scale {scale}: {off:e} from the closed form");
        assert!(design.rms_error < 1e-15, "scale {scale}: {design:?}");
    }
    // A path's misses are lengths: the worksheet's G3 through five timed
    // points (ten equations, three unknowns: consistent, so precision
    // points), at each size. (The targets are the sweep's points, closed to
    // Newton's tolerance: the worksheet's lengths meet them to 1e-12, and
    // the designs found at the three sizes agree with each other to
    // rounding.)
    let (targets, drivers) = worksheet_targets();
    let mut found_lengths = Vec::new();
    for scale in [1e-3, 1.0, 1e3] {
        let bar = FourBar {
            l1: 80.0 * scale,
            l2: 25.0 * scale,
            l3: 45.0 * scale,
            l4: 65.0 * scale,
        };
        let scaled: Vec<Vector2<f64>> = targets.iter().map(|t| t * scale).collect();
        let problem = Problem::path(bar, "G3", &scaled, Timing::Prescribed(drivers.clone()))
            .unwrap()
            .freed(&[
                ("l2", 10.0 * scale, 30.0 * scale),
                ("l3", 30.0 * scale, 70.0 * scale),
                ("l4", 50.0 * scale, 90.0 * scale),
            ])
            .guess(vector![1.3, -0.8])
            .precision_points();
        assert_eq!((problem.residuals(), problem.unknowns()), (10, 3));
        let found = synthesize(
            &problem,
            &Requirements::new(Range::Revolution),
            &Search {
                starts: 8,
                ..Search::default()
            },
        )
        .unwrap();
        let design = found.best().unwrap();
        let m = &design.model;
        let off = [
            m.l2 - 20.0 * scale,
            m.l3 - 50.0 * scale,
            m.l4 - 70.0 * scale,
        ]
        .iter()
        .fold(0.0f64, |e, x| e.max(x.abs()))
            / scale;
        assert!(off < 1e-12, "scale {scale}: {off:e}");
        assert!(
            design.largest_error().1 < 1e-13 * scale,
            "scale {scale}: {design:?}"
        );
        found_lengths.push([m.l2 / scale, m.l3 / scale, m.l4 / scale]);
    }
    for lengths in &found_lengths {
        for (a, b) in lengths.iter().zip(&found_lengths[1]) {
            assert!((a / b - 1.0).abs() < 1e-14, "{found_lengths:?}");
        }
    }
}

/// By default a four-bar must keep a transmission angle of 40°: a
/// crank-rocker whose angle falls to 29.7° (l = 100, 45, 70, 80: at
/// θ2 = 180°, cos μ = (70² + 80² − 145²)/(2·70·80)) is refused there, and
/// certified when no limit is asked, its certificate reporting that angle,
/// where, and its Grashof type.
#[test]
fn by_default_a_near_dead_design_is_refused() {
    let bar = FourBar {
        l1: 100.0,
        l2: 45.0,
        l3: 70.0,
        l4: 80.0,
    };
    let degrees = [30.0, 120.0, 210.0, 300.0];
    let poses = poses_along(bar, vector![1.0, -1.5], &degrees);
    let drivers: Vec<f64> = degrees.iter().map(|d: &f64| d.to_radians()).collect();
    let worst = ((70.0f64 * 70.0 + 80.0 * 80.0 - 145.0 * 145.0) / (2.0 * 70.0 * 80.0))
        .abs()
        .acos();
    let options = SweepOptions::default();
    match certify(
        &bar,
        &poses,
        &drivers,
        None,
        &Requirements::new(Range::Revolution),
        &options,
    ) {
        Err(Defect::Transmission { v, angle }) => {
            assert!(
                (angle - worst).abs() < 1e-3 && angle >= worst - 1e-12,
                "{angle}"
            );
            assert!((v - PI).abs() < 0.02, "{v}");
        }
        other => panic!("{other:?}"),
    }
    let mut none = Requirements::new(Range::Revolution);
    none.min_transmission = 0.0;
    none.grashof = Some(FourBar::grashof);
    let certificate = certify(&bar, &poses, &drivers, None, &none, &options).unwrap();
    assert!((certificate.transmission - worst).abs() < 1e-3);
    assert!((certificate.transmission_at - PI).abs() < 0.02);
    assert_eq!(certificate.grashof, Some(Grashof::CrankRocker));
}

/// Nine points of the worksheet's coupler curve with the crank's rotations
/// between them prescribed and its start free (relative timing: nine
/// dimensions and one offset, eighteen equations): consistent, so met as
/// precision points, and the offset found.
#[test]
fn relative_timing_meets_a_consistent_over_determined_set() {
    let bar = CouplerFourBar::WORKSHEET;
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 360,
    };
    let sweep = bar
        .sweep(&vector![1.3, -0.8], &drive, &SweepOptions::default())
        .unwrap();
    let picks: Vec<usize> = (0..9).map(|i| 15 + 40 * i).collect();
    let targets: Vec<Vector2<f64>> = picks
        .iter()
        .map(|&k| bar.point_positions(&sweep.poses[k].u, &sweep.poses[k].v)[CouplerFourBar::P])
        .collect();
    let offset = sweep.poses[picks[0]].v[0];
    let relative: Vec<f64> = picks
        .iter()
        .map(|&k| sweep.poses[k].v[0] - offset)
        .collect();
    let start = CouplerFourBar {
        xa: 3.0,
        ya: -2.0,
        xd: 76.0,
        yd: 4.0,
        l2: 22.0,
        l3: 47.0,
        l4: 66.0,
        px: 20.0,
        py: 5.0,
    };
    let problem = Problem::path(start, "P", &targets, Timing::Relative(relative.clone()))
        .unwrap()
        .freed(&[
            ("xa", -10.0, 10.0),
            ("ya", -10.0, 10.0),
            ("xd", 70.0, 90.0),
            ("yd", -10.0, 10.0),
            ("l2", 15.0, 25.0),
            ("l3", 40.0, 60.0),
            ("l4", 60.0, 80.0),
            ("px", 15.0, 35.0),
            ("py", -10.0, 10.0),
        ])
        .guess(vector![1.3, -0.8])
        .precision_points();
    assert_eq!((problem.residuals(), problem.unknowns()), (18, 10));
    let found = synthesize(
        &problem,
        &Requirements::new(Range::Revolution),
        &Search {
            starts: 16,
            enough: Some(1),
            within: Some(1e-9),
            ..Search::default()
        },
    )
    .unwrap();
    let design = found.best().unwrap();
    assert!(design.largest_error().1 < 1e-11, "{design:?}");
    for (d, r) in design.drivers.iter().zip(&relative) {
        let gap = d - r - design.drivers[0];
        assert!(gap.abs() < 1e-12, "{gap}");
    }
    // Every start drew a design that runs through the prescribed drivers.
    assert_eq!(found.failed_starts, 0, "{found:?}");
}

/// `within`: a search asked for one design under a tolerance its
/// least-squares designs cannot reach runs every start; without it, it
/// stops at the first start that certifies one.
#[test]
fn a_search_for_designs_within_a_tolerance_counts_only_those() {
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
    let problem = Problem::function_over(start, "theta4", (0.0, 60f64.to_radians()), 11, wanted)
        .unwrap()
        .freed(&[("l2", 0.1, 5.0), ("l3", 0.1, 5.0), ("l4", 0.1, 5.0)])
        .guess(vector![1.0, wanted(0.0)]);
    let mut requirements = Requirements::new(Range::Task);
    requirements.min_transmission = 0.0;
    let search = |within| Search {
        starts: 24,
        enough: Some(1),
        within,
        ..Search::default()
    };
    let any = synthesize(&problem, &requirements, &search(None)).unwrap();
    assert_eq!(any.starts, any.designs[0].start + 1);
    assert!(any.starts < 24);
    let best = any.best().unwrap().largest_error().1;
    assert!(best > 1e-3, "{best}");
    let under = synthesize(&problem, &requirements, &search(Some(1e-6))).unwrap();
    assert_eq!(under.starts, 24);
}

proptest::proptest! {
    #![proptest_config(fixed_stream(6))]
    /// Random crank-rockers at random sizes from 1e-3 to 1e3: three
    /// precision points of their rocker's angle give them back to
    /// rounding, the solver's stopping and the acceptance alike free of
    /// the units.
    #[test]
    fn random_precision_points_are_met_to_rounding_at_any_size(
        // Crank-rockers: l2 + 1 < 1.2 ≤ l3 + l4, the crank shortest.
        l2 in 0.15..0.19f64, l3 in 0.5..0.6f64, l4 in 0.7..0.8f64,
        first in 0.0..6.0f64, exponent in -3.0..3.0f64,
    ) {
        let scale = 10f64.powf(exponent);
        let bar = closed_form::FourBar { l1: scale, l2: l2 * scale, l3: l3 * scale, l4: l4 * scale };
        let thetas = [first, first + 0.6, first + 1.2];
        let targets: Vec<(f64, f64)> = thetas
            .iter()
            .map(|&t| (t, bar.position(t, 1.0).unwrap()[1]))
            .collect();
        let [t3, t4] = bar.position(thetas[0], 1.0).unwrap();
        let start = FourBar { l1: scale, l2: 0.17 * scale, l3: 0.5 * scale, l4: 0.7 * scale };
        let problem = Problem::function(start, "theta4", &targets)
            .unwrap()
            .freed(&[
                ("l2", 0.1 * scale, 0.25 * scale),
                ("l3", 0.3 * scale, 0.9 * scale),
                ("l4", 0.4 * scale, 1.0 * scale),
            ])
            .guess(vector![t3, t4])
            .precision_points();
        let mut requirements = Requirements::new(Range::Targets);
        requirements.min_transmission = 0.0;
        let found = synthesize(&problem, &requirements, &Search { starts: 8, ..Search::default() })
            .unwrap();
        let design = found.best().unwrap();
        let m = &design.model;
        let off = [m.l2 - bar.l2, m.l3 - bar.l3, m.l4 - bar.l4]
            .iter()
            .fold(0.0f64, |e, x| e.max(x.abs()))
            / scale;
        proptest::prop_assert!(off < 1e-12, "scale {scale:e}: {off:e} from the design, {design:?}");
        proptest::prop_assert!(design.rms_error < 1e-14, "{design:?}");
    }
}

/// Frees several parameters at once: the tests' builder chains.
pub(crate) trait Freed {
    /// Each (name, lower, upper) of `bounds` freed, in order.
    fn freed(self, bounds: &[(&str, f64, f64)]) -> Self;
}

impl<L: Sensitivities<M, 1, K>, const M: usize, const K: usize> Freed for Problem<L, M, K> {
    fn freed(self, bounds: &[(&str, f64, f64)]) -> Self {
        bounds.iter().fold(self, |problem, &(name, lower, upper)| {
            problem.free(name, lower, upper).unwrap()
        })
    }
}

//! Four-bar sweeps of every Grashof class, checked pose by pose against the
//! closed form, event by event against the law of cosines.

use crate::common::{self, FourBar};
use crate::harness::{Tally, Truth, four_bar_truth, runner};
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

/// What the four-bar sweeps found.
#[derive(Default)]
struct SweepTally {
    cases: usize,
    ok: usize,
    poses: usize,
    events: BTreeMap<&'static str, usize>,
    errors: BTreeMap<&'static str, usize>,
}

/// Four-bars of every Grashof class, the change points, parallelograms,
/// kites and deltoids among them, swept over random spans in random numbers
/// of steps from a random start on a random branch. Every pose is checked
/// against the closed form on the branch it must be on (the start's, flipped
/// at each branch point reported and at nothing else), every event against
/// the law of cosines (|BD| = l3 + l4 or |l3 − l4| there), every pair of
/// consecutive poses by the branch-continuity check, and a sweep that
/// reports the line complete must not have passed a driver value where the
/// mechanism cannot be assembled.
#[test]
fn four_bar_sweeps_never_lie() {
    let start = Instant::now();
    let tally = RefCell::new(SweepTally::default());
    let world = (
        0..6usize,
        [
            10.0f64..100.0,
            10.0f64..100.0,
            10.0f64..100.0,
            10.0f64..100.0,
        ],
        -3.0f64..3.0,
        any::<bool>(),
        -PI..PI,
        -4.0 * PI..4.0 * PI,
        1..1500usize,
    );
    runner()
        .run(
            &world,
            |(mode, [a, b, c, d], exponent, positive, from, span, steps)| {
                // Mode 0: any four lengths; 1, 2: change points (l1 + l2 =
                // l3 + l4, collinear at θ2 = π; l3 − l4 = l1 − l2, at 0);
                // 3: a parallelogram; 4: a kite (l1 = l2, l3 = l4); 5: a
                // deltoid (l2 = l3, l4 = l1).
                let scale = 10f64.powf(exponent);
                let (l1, l2, l3) = (a * scale, b * scale, c * scale);
                let l = match mode {
                    1 => {
                        let (l2, l1) = (l2.min(l1), l2.max(l1));
                        [l1, l2, (l1 + l2) * 0.4, (l1 + l2) * 0.6]
                    }
                    2 => [l1 + l2, l2, l3 + l1, l3],
                    3 => [l1, l2, l1, l2],
                    4 => [l1, l1, l3, l3],
                    5 => [l1, l2, l2, l1],
                    _ => [l1, l2, l3, d * scale],
                };
                let sigma = if positive { 1.0 } else { -1.0 };
                let closed = linkage::closed_form::FourBar {
                    l1: l[0],
                    l2: l[1],
                    l3: l[2],
                    l4: l[3],
                };
                // A start clear of every singular pose.
                if !matches!(four_bar_truth(l, from), Truth::Assembles { clear: true }) {
                    return Ok(());
                }
                let Some(u0) = closed.position(from, sigma) else {
                    return Ok(());
                };
                let bar = FourBar {
                    l1: l[0],
                    l2: l[1],
                    l3: l[2],
                    l4: l[3],
                };
                let to = from + span;
                let drive = Drive::Line {
                    from: vector![from],
                    to: vector![to],
                    steps,
                };
                let mut t = tally.borrow_mut();
                t.cases += 1;
                let sweep = match catch_unwind(AssertUnwindSafe(|| {
                    bar.sweep(&vector![u0[0], u0[1]], &drive, &SweepOptions::default())
                })) {
                    Err(_) => return Err(TestCaseError::fail("panicked")),
                    Ok(Err(e)) => {
                        let mut errors = Tally::default();
                        errors.error(&e);
                        for (kind, n) in errors.errors {
                            *t.errors.entry(kind).or_default() += n;
                        }
                        return Ok(());
                    }
                    Ok(Ok(sweep)) => sweep,
                };
                t.ok += 1;
                t.poses += sweep.poses.len();
                // Events where the law of cosines puts them.
                let bd = |theta2: f64| (l[0] - l[1] * theta2.cos()).hypot(l[1] * theta2.sin());
                for e in &sweep.events {
                    *t.events
                        .entry(match e.kind {
                            EventKind::BranchPoint => "branch points",
                            EventKind::LimitPosition => "limit positions",
                        })
                        .or_default() += 1;
                    let at = bd(e.v[0]);
                    let off = (at - (l[2] + l[3]))
                        .abs()
                        .min((at - (l[2] - l[3]).abs()).abs());
                    prop_assert!(
                        off <= 1e-9 * (l[2] + l[3]),
                        "{:?} at θ2 = {} where |BD| = {at}, l3 ± l4 = {}, {}",
                        e.kind,
                        e.v[0],
                        l[2] + l[3],
                        (l[2] - l[3]).abs()
                    );
                }
                // Every pose on its branch, continuous with the last.
                for (k, p) in sweep.poses.iter().enumerate() {
                    let flips = sweep
                        .events
                        .iter()
                        .filter(|e| e.after <= k && e.kind == EventKind::BranchPoint)
                        .count();
                    let side = if flips % 2 == 0 { sigma } else { -sigma };
                    let exact = closed.position(p.v[0], side);
                    let near_limit = sweep.events.iter().any(|e| {
                        e.kind == EventKind::LimitPosition && (e.v[0] - p.v[0]).abs() < 1e-6
                    });
                    let tolerance = if near_limit { 1e-7 } else { 1e-9 };
                    let error = exact.map_or(f64::INFINITY, |x| {
                        let wrap = |d: f64| {
                            let d = d.rem_euclid(2.0 * PI);
                            d.min(2.0 * PI - d)
                        };
                        wrap(p.u[0] - x[0]).max(wrap(p.u[1] - x[1]))
                    });
                    prop_assert!(
                        error <= tolerance,
                        "pose {k} at θ2 = {}: {:?}, closed form {exact:?} on branch {side}",
                        p.v[0],
                        p.u.as_slice()
                    );
                }
                for pair in sweep.poses.windows(2) {
                    let jump = common::branch_jump(&bar, &pair[0], &pair[1]);
                    prop_assert!(
                        jump.is_none(),
                        "velocity ratios jump: {jump:?} at θ2 = {}",
                        pair[1].v[0]
                    );
                }
                // A complete line passed no driver value where the
                // mechanism cannot be assembled.
                if sweep.complete {
                    let cannot = (0..=steps).any(|k| {
                        let theta2 = from + (to - from) / steps as f64 * k as f64;
                        four_bar_truth(l, theta2) == Truth::Cannot
                    });
                    prop_assert!(!cannot, "complete through a pose that cannot be assembled");
                }
                Ok(())
            },
        )
        .unwrap();
    let t = tally.into_inner();
    eprintln!(
        "four-bar sweeps: {} cases in {:.1} s, {} Ok ({} poses), events {:?}, errors {:?}; panics 0, wrong Ok 0, branch jumps 0",
        t.cases,
        start.elapsed().as_secs_f64(),
        t.ok,
        t.poses,
        t.events,
        t.errors
    );
    assert!(t.events.contains_key("branch points") && t.events.contains_key("limit positions"));
}

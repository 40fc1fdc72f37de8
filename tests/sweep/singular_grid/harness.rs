//! The campaign's harness: runs, their tally, the check of one run, the step
//! counts, full turns through singular poses, the campaign on two threads,
//! and its report.

use super::grids::{OFFSETS, angle_error, line_grid, line_through, miss, off, passed_between};
use crate::common;
use linkage::prelude::*;
use std::f64::consts::TAU;
use std::time::{Duration, Instant};

/// The location promised for a singular pose, relative to max(1, |v|).
const LOCATED_TO: f64 = 1e-12;

/// What the campaign found, per scenario.
#[derive(Clone, Debug, Default)]
pub(crate) struct Tally {
    runs: usize,
    /// Runs whose grid aims at a singular pose.
    aimed: usize,
    /// Runs with a grid pose on the singular pose to the bit.
    on: usize,
    /// Runs with a grid pose 1 to 4 ulps from it (ulps of max(1, |v|)).
    within_ulps: usize,
    poses: usize,
    events_expected: usize,
    events_found: usize,
    worst_location: f64,
    /// Consecutive poses whose velocity ratios jump.
    branch_jumps: usize,
    /// Poses off the closed form's branch, missing, extra, misplaced or
    /// misclassified events, a wrong `complete`.
    wrong_ok: usize,
    errors: usize,
    /// Runs over the time limit.
    hangs: usize,
    slowest: Duration,
    first_failure: Option<String>,
}

impl Tally {
    pub(crate) fn add(&mut self, other: &Tally) {
        self.runs += other.runs;
        self.aimed += other.aimed;
        self.on += other.on;
        self.within_ulps += other.within_ulps;
        self.poses += other.poses;
        self.events_expected += other.events_expected;
        self.events_found += other.events_found;
        self.worst_location = self.worst_location.max(other.worst_location);
        self.branch_jumps += other.branch_jumps;
        self.wrong_ok += other.wrong_ok;
        self.errors += other.errors;
        self.hangs += other.hangs;
        self.slowest = self.slowest.max(other.slowest);
        if self.first_failure.is_none() {
            self.first_failure.clone_from(&other.first_failure);
        }
    }

    fn fail(&mut self, what: String) {
        if self.first_failure.is_none() {
            self.first_failure = Some(what);
        }
    }

    fn clean(&self) -> bool {
        self.branch_jumps == 0
            && self.wrong_ok == 0
            && self.errors == 0
            && self.hangs == 0
            && self.events_found == self.events_expected
            && self.on + self.within_ulps == self.aimed
    }
}

/// One run: a drive, where it starts, and what it must meet.
pub(crate) struct Run<const M: usize> {
    pub(crate) label: String,
    pub(crate) start: SVector<f64, M>,
    pub(crate) drive: Drive<1>,
    /// The singular poses passed, in order: kind and driver value.
    pub(crate) expected: Vec<(EventKind, f64)>,
    pub(crate) complete: bool,
    /// How far the nearest grid pose is from the singular pose it aims at,
    /// in ulps of max(1, |v|); None for a grid that does not aim at one.
    pub(crate) miss: Option<f64>,
}

/// The mechanism's exact pose at driver value v on the branch reached after
/// `events` singular poses.
type Truth<'a, const M: usize> = &'a (dyn Fn(f64, usize) -> Option<[f64; M]> + Sync);

/// A run swept and checked.
fn check<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    run: &Run<M>,
    truth: Truth<'_, M>,
    angles: [bool; M],
    tally: &mut Tally,
) {
    tally.runs += 1;
    if let Some(miss) = run.miss {
        tally.aimed += 1;
        tally.on += usize::from(miss == 0.0);
        tally.within_ulps += usize::from(miss > 0.0 && miss <= 4.0);
    }
    tally.events_expected += run.expected.len();
    let began = Instant::now();
    let result = model.sweep(&run.start, &run.drive, &SweepOptions::default());
    let took = began.elapsed();
    tally.slowest = tally.slowest.max(took);
    if took > Duration::from_secs(20) {
        tally.hangs += 1;
        tally.fail(format!("{}: {took:?}", run.label));
    }
    let sweep = match result {
        Ok(s) => s,
        Err(e) => {
            tally.errors += 1;
            tally.fail(format!("{}: {e}", run.label));
            return;
        }
    };
    tally.poses += sweep.poses.len();
    // The events: in order, of the right kind, located.
    let mut events_right = sweep.events.len() == run.expected.len();
    for (found, &(kind, at)) in sweep.events.iter().zip(&run.expected) {
        let error = (found.v[0] - at).abs() / at.abs().max(1.0);
        if found.kind == kind && error <= LOCATED_TO {
            tally.events_found += 1;
            tally.worst_location = tally.worst_location.max(error);
        } else {
            events_right = false;
        }
    }
    if !events_right || sweep.complete != run.complete {
        tally.wrong_ok += 1;
        let found: Vec<_> = sweep.events.iter().map(|e| (e.kind, e.v[0])).collect();
        tally.fail(format!(
            "{}: events {found:?} (complete: {}), expected {:?} (complete: {})",
            run.label, sweep.complete, run.expected, run.complete
        ));
    }
    // Every pose on its branch.
    let passed = |k: usize| sweep.events.iter().filter(|e| e.after <= k).count();
    for (k, p) in sweep.poses.iter().enumerate() {
        let Some(exact) = truth(p.v[0], passed(k)) else {
            tally.wrong_ok += 1;
            tally.fail(format!(
                "{}: pose {k} at {} cannot exist",
                run.label, p.v[0]
            ));
            continue;
        };
        let near_limit = sweep
            .events
            .iter()
            .any(|e| e.kind == EventKind::LimitPosition && (e.v[0] - p.v[0]).abs() < 1e-6);
        let tolerance = if near_limit { 1e-7 } else { 1e-9 };
        let error = (0..M)
            .map(|i| {
                if angles[i] {
                    angle_error(p.u[i], exact[i])
                } else {
                    (p.u[i] - exact[i]).abs() / exact[i].abs().max(1.0)
                }
            })
            .fold(0.0, f64::max);
        let on_branch = error <= tolerance; // false for NaN too
        if !on_branch {
            tally.wrong_ok += 1;
            tally.fail(format!(
                "{}: pose {k} at v = {} is {:?}, the closed form {exact:?} (error {error:e})",
                run.label,
                p.v[0],
                p.u.as_slice()
            ));
        }
    }
    // The branch-continuity check on every pair of consecutive poses that no
    // limit position separates.
    for (k, pair) in sweep.poses.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let reversed = sweep
            .events
            .iter()
            .any(|e| e.kind == EventKind::LimitPosition && e.after == k + 1);
        if reversed {
            continue;
        }
        if let Some((jump, allowed)) = common::branch_jump(model, a, b) {
            tally.branch_jumps += 1;
            tally.fail(format!(
                "{}: velocity ratios jump by {jump:e} (allowed {allowed:e}) between v = {} and {}",
                run.label, a.v[0], b.v[0]
            ));
        }
    }
}

/// The step counts of the campaign.
pub(crate) fn step_counts() -> Vec<usize> {
    let setting = std::env::var("LINKAGE_GRID").unwrap_or_default();
    // A comma-separated list reruns those step counts alone.
    let listed: Vec<usize> = setting.split(',').filter_map(|s| s.parse().ok()).collect();
    if !listed.is_empty() {
        return listed;
    }
    let full = setting == "full";
    let stride = if full { 1 } else { 331 };
    // The counts first reported (they put a grid pose on the f64 nearest
    // π for the change point l = 80/40/50/70) always.
    let mut counts: Vec<usize> = (50..=5000).step_by(stride).collect();
    counts.extend([490, 674, 698, 704, 726, 758, 760]);
    counts.sort_unstable();
    counts.dedup();
    counts
}

/// Full turns of the crank, each with the grid through `singular[0]` at
/// index k, for every step count, direction and offset.
pub(crate) fn full_turns<const M: usize>(
    singular: &[f64],
    start: &(dyn Fn(f64) -> Option<[f64; M]> + Sync),
    counts: &[usize],
    label: &str,
) -> Vec<Run<M>> {
    let mut runs = Vec::new();
    for &steps in counts {
        for direction in [1.0, -1.0] {
            let offset = OFFSETS[steps % OFFSETS.len()];
            let target = off(singular[0], offset);
            // The singular pose a third of the way, give or take, and never
            // near either end.
            let k = steps / 3 + steps % 7;
            let (from, to) = line_through(target, k, steps, direction * TAU / steps as f64);
            let expected = passed_between(from, to, singular)
                .into_iter()
                .map(|v| (EventKind::BranchPoint, v))
                .collect();
            let Some(u0) = start(from) else {
                panic!("{label}: the start {from} does not assemble");
            };
            runs.push(Run {
                label: format!(
                    "{label}, {steps} steps, direction {direction}, offset {offset} ulps"
                ),
                start: SVector::from(u0),
                drive: Drive::Line {
                    from: vector![from],
                    to: vector![to],
                    steps,
                },
                expected,
                complete: true,
                miss: Some(miss(line_grid(from, to, steps, k), singular[0])),
            });
        }
    }
    runs
}

/// Runs the campaign of one scenario on two threads.
pub(crate) fn campaign<L: Linkage<M, 1> + Sync, const M: usize>(
    model: &L,
    runs: &[Run<M>],
    truth: Truth<'_, M>,
    angles: [bool; M],
) -> Tally {
    let halves = runs.split_at(runs.len() / 2);
    let tallies: Vec<Tally> = std::thread::scope(|scope| {
        [halves.0, halves.1]
            .map(|part| {
                scope.spawn(move || {
                    let mut tally = Tally::default();
                    for run in part {
                        check(model, run, truth, angles, &mut tally);
                    }
                    tally
                })
            })
            .map(|h| h.join().expect("a campaign thread panicked"))
            .to_vec()
    });
    let mut all = Tally::default();
    for t in &tallies {
        all.add(t);
    }
    all
}

pub(crate) fn report(name: &str, tally: &Tally, began: Instant) {
    eprintln!(
        "| {name} | {} | {} | {} | {} | {} | {} | {:.1e} | {} | {} | {} | {} | {:.1} s |",
        tally.runs,
        tally.on,
        tally.within_ulps,
        tally.poses,
        tally.events_expected,
        tally.events_found,
        tally.worst_location,
        tally.branch_jumps,
        tally.wrong_ok,
        tally.errors,
        tally.hangs,
        began.elapsed().as_secs_f64()
    );
    assert!(
        tally.clean(),
        "{name}: {tally:?}\nfirst failure: {}",
        tally.first_failure.as_deref().unwrap_or("-")
    );
}

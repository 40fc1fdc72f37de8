//! Many starts in parallel: each a random design within the bounds (and a
//! random phase of the free drivers), assembled at the first target's
//! driver (from the problem's guess, or by the assembly search without
//! one) and followed by continuation to the poses at every target, solved by Levenberg–Marquardt on the exact
//! Jacobian, then certified; the certified designs kept once each and
//! ranked by their error at the targets.

use super::SynthesisError;
use super::certify::{Certificate, Defect, Range, Requirements, certify};
use super::continuation;
use super::problem::{Problem, Timing, extent};
use super::residuals::{Poses, branch, evaluate};
use crate::assembly;
use crate::batch;
use crate::least_squares::{Evaluation, Stopping, minimize};
use crate::random::SplitMix64;
use crate::runtime::{Error, Options, Sensitivities, SweepOptions};
use nalgebra::{DVector, SVector};
use std::f64::consts::TAU;

/// How to search.
///
/// [`Search::default`]: 64 starts from random state 1; Levenberg–Marquardt
/// with [`Stopping::default`]; the solves and sweeps of
/// [`SweepOptions::default`]; every start solved (`enough: None`) and any
/// certified design kept (`within: None`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Search {
    /// Random starts, solved in parallel.
    pub starts: usize,
    /// The state the random numbers of the starts begin from: each start
    /// is a function of it and the start's index alone (the same state,
    /// the same starts).
    pub random_state: u64,
    /// When each start's Levenberg–Marquardt stops.
    pub stopping: Stopping,
    /// The solves of the poses and the sweeps of the certificate.
    pub options: SweepOptions,
    /// Stop once this many distinct designs are certified (counting only
    /// those within [`Search::within`]): the search returns what the
    /// starts from the first to the one that certifies the last of them
    /// found, and no more (the threads take the starts in turn; a later
    /// start that ran meanwhile is dropped). `None`: every start. Either
    /// way the result depends only on the random state, not on the
    /// machine's cores.
    pub enough: Option<usize>,
    /// A design counts towards [`Search::enough`] only if it misses no
    /// target by more than this (in the targets' units): "designs under a
    /// tolerance". `None`: any certified design counts.
    pub within: Option<f64>,
    /// The index of the first start: the search runs the starts `first`
    /// to `first + starts - 1`. A larger search split into shards of
    /// consecutive starts (the same random state) runs the same starts,
    /// each of which depends on its index alone.
    pub first: usize,
    /// Whether a design found again from a later start (the same free
    /// parameters and drivers, to 1e-6 of their ranges) is dropped. A
    /// shard keeps them (`false`): the shards' designs, put together in
    /// the order of their starts, are then those of the whole search run
    /// at once with `distinct: false`, row for row.
    pub distinct: bool,
}

impl Search {
    /// Random designs a start draws, one after the other from its stream,
    /// until one assembles at every target's driver and can be followed
    /// through them (with prescribed timing most random designs cannot:
    /// their driver does not reach every target's angle); a start none of
    /// whose draws can is a failed start. With free timing over a
    /// revolution, the first whose driver turns one is taken, a rocker only
    /// if none does.
    pub const DRAWS: usize = 32;
}

impl Default for Search {
    fn default() -> Search {
        Search {
            starts: 64,
            random_state: 1,
            stopping: Stopping::default(),
            options: SweepOptions::default(),
            enough: None,
            within: None,
            first: 0,
            distinct: true,
        }
    }
}

/// A design the search found.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate<L, const M: usize> {
    pub model: L,
    /// The driver at each target.
    pub drivers: Vec<f64>,
    /// The pose at each target.
    pub poses: Vec<SVector<f64, M>>,
    /// The miss at each target: the distance from the target (a path's
    /// point), the difference of values (a function), or the norm of the
    /// position's and the weighted angle's misses (a motion).
    pub errors: Vec<f64>,
    /// The root mean square of the misses over the targets, √(Σ eᵢ²/n)
    /// (the designer's own terms not included).
    pub rms_error: f64,
    /// Evaluations of residuals and Jacobian the solver took.
    pub evaluations: usize,
    /// The start it came from.
    pub start: usize,
    /// What its certificate found (a returned design), `None` for a
    /// refused candidate.
    pub certificate: Option<Certificate>,
}

impl<L, const M: usize> Candidate<L, M> {
    /// The target missed most, and by how much.
    pub fn largest_error(&self) -> (usize, f64) {
        self.errors
            .iter()
            .copied()
            .enumerate()
            .fold(
                (0, 0.0),
                |most, (i, e)| if e > most.1 { (i, e) } else { most },
            )
    }
}

/// The refused candidate closest to the targets, and why it was refused.
#[derive(Clone, Debug, PartialEq)]
pub struct Closest {
    /// Its root-mean-square miss ([`Candidate::rms_error`]).
    pub rms_error: f64,
    /// The target it missed most, and by how much.
    pub largest_error: (usize, f64),
    pub defect: Defect,
}

impl std::fmt::Display for Closest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (target, error) = self.largest_error;
        write!(
            f,
            "the closest candidate (RMS miss {:e}, target {target} missed by {error:e}) was refused: {}",
            self.rms_error, self.defect
        )
    }
}

impl<L, const M: usize> Synthesis<L, M> {
    /// The refused candidate closest to the targets (the smallest
    /// [`Candidate::rms_error`]), and why it was refused.
    pub fn closest_refused(&self) -> Option<Closest> {
        self.refused
            .iter()
            .min_by(|a, b| a.0.rms_error.total_cmp(&b.0.rms_error))
            .map(|(candidate, defect)| Closest {
                rms_error: candidate.rms_error,
                largest_error: candidate.largest_error(),
                defect: defect.clone(),
            })
    }

    /// The best certified design, or why there is none: a target that
    /// every candidate missed (out of reach), or the refusals (the closest
    /// one's reason) and failed starts.
    pub fn best(&self) -> Result<&Candidate<L, M>, SynthesisError> {
        if let Some(best) = self.designs.first() {
            return Ok(best);
        }
        let misses: Vec<(usize, f64)> = self
            .refused
            .iter()
            .filter_map(|(_, defect)| match defect {
                Defect::Misses { target, error } => Some((*target, *error)),
                _ => None,
            })
            .collect();
        if !misses.is_empty() && misses.len() == self.refused.len() {
            let target = misses[0].0;
            if misses.iter().all(|m| m.0 == target) {
                let error = misses.iter().map(|m| m.1).fold(f64::INFINITY, f64::min);
                return Err(SynthesisError::Unreachable { target, error });
            }
        }
        Err(SynthesisError::NoDesign {
            refused: self.refused.len(),
            failed_starts: self.failed_starts,
            closest: self.closest_refused(),
        })
    }
}

/// What the search gives: the certified designs, distinct, best first; the
/// candidates refused, with their defect; the starts that could not be
/// assembled at all.
#[derive(Clone, Debug, PartialEq)]
pub struct Synthesis<L, const M: usize> {
    pub designs: Vec<Candidate<L, M>>,
    pub refused: Vec<(Candidate<L, M>, Defect)>,
    pub failed_starts: usize,
    /// The starts run: all of them, or fewer when [`Search::enough`]
    /// designs were certified sooner.
    pub starts: usize,
}

impl<L, const M: usize> Synthesis<L, M> {
    /// Puts a later piece of the same search after this one (the starts
    /// that follow, as [`Search::first`] splits a search): its designs
    /// after these, a design found again dropped by the rule of
    /// [`Search::distinct`], its refused candidates, failed starts and
    /// starts added. Pieces absorbed in the order of their starts give
    /// the designs of the whole search run at once, row for row.
    pub fn absorb<const K: usize>(&mut self, problem: &Problem<L, M, K>, later: Synthesis<L, M>)
    where
        L: Sensitivities<M, 1, K>,
    {
        for candidate in later.designs {
            if !(self.designs.iter()).any(|d| same_design(problem, d, &candidate)) {
                self.designs.push(candidate);
            }
        }
        self.designs
            .sort_by(|a, b| a.rms_error.total_cmp(&b.rms_error));
        self.refused.extend(later.refused);
        self.failed_starts += later.failed_starts;
        self.starts += later.starts;
    }
}

/// Solves `problem` from `search.starts` random starts in parallel and
/// certifies every result against `requirements` (or from as many of them,
/// in order, as it takes to certify [`Search::enough`] designs).
pub fn synthesize<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    requirements: &Requirements<'_, L, M>,
    search: &Search,
) -> Result<Synthesis<L, M>, SynthesisError>
where
    L: Sensitivities<M, 1, K> + Clone + Sync + Send,
{
    synthesize_observed(problem, requirements, search, &|| {})
}

/// [`synthesize`], calling `on_start` as each start ends (solved and
/// judged, or failed), from whichever thread ran it: for a progress bar.
pub fn synthesize_observed<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    requirements: &Requirements<'_, L, M>,
    search: &Search,
    on_start: &(dyn Fn() + Sync),
) -> Result<Synthesis<L, M>, SynthesisError>
where
    L: Sensitivities<M, 1, K> + Clone + Sync + Send,
{
    synthesize_cancellable(problem, requirements, search, on_start, &|| false)
}

/// [`synthesize_observed`], stopped once `cancelled` says so: each start
/// asks before it begins and between its draws and its solver's trials, and
/// a search asked to stop ends with [`SynthesisError::Cancelled`] as soon
/// as the starts under way have noticed (an interrupted caller — Ctrl-C in
/// Python — need not wait for the rest). Once `cancelled` has said so it
/// must keep saying so: a start it stopped has no outcome.
pub fn synthesize_cancellable<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    requirements: &Requirements<'_, L, M>,
    search: &Search,
    on_start: &(dyn Fn() + Sync),
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Result<Synthesis<L, M>, SynthesisError>
where
    L: Sensitivities<M, 1, K> + Clone + Sync + Send,
{
    problem.check()?;
    if search.first.checked_add(search.starts).is_none() {
        return Err(SynthesisError::Options(Error::InvalidInput {
            argument: "first",
            value: search.first as f64,
            why: "the starts from `first` on run past the largest index a start can have",
        }));
    }
    search
        .options
        .options
        .check()
        .map_err(SynthesisError::Options)?;
    if requirements.range == Range::Task && problem.range.is_none() {
        return Err(SynthesisError::NoRange);
    }
    let mut synthesis = Synthesis {
        designs: Vec::new(),
        refused: Vec::new(),
        failed_starts: 0,
        starts: 0,
    };
    // Each start solved and certified, on the pool's threads, and taken
    // in the starts' order until enough designs count.
    let run = |k: usize, wanted: &dyn Fn() -> bool| {
        // A start no longer wanted (or the search cancelled) ends early:
        // its outcome is dropped.
        let stop = || cancelled() || !wanted();
        if stop() {
            return None;
        }
        let start = search.first + k;
        let solved = solve(problem, search, requirements.steps_per_radian, start, &stop);
        if stop() {
            return None;
        }
        let outcome = solved.map(|mut candidate| {
            let verdict = verdict(problem, &candidate, requirements, &search.options);
            candidate.certificate = verdict.as_ref().ok().copied();
            (candidate, verdict.map(|_| ()))
        });
        on_start();
        outcome
    };
    let mut counted = 0;
    let starts = if search.enough == Some(0) {
        0
    } else {
        search.starts
    };
    batch::in_order_until(starts, run, |outcome| {
        synthesis.starts += 1;
        match outcome {
            None => synthesis.failed_starts += 1,
            Some((candidate, Ok(()))) => {
                if !(search.distinct
                    && (synthesis.designs.iter()).any(|d| same_design(problem, d, &candidate)))
                {
                    let within = (search.within).is_none_or(|w| candidate.largest_error().1 <= w);
                    counted += usize::from(within);
                    synthesis.designs.push(candidate);
                }
            }
            Some((candidate, Err(defect))) => synthesis.refused.push((candidate, defect)),
        }
        // (Cancelled, the search returns no outcome: nothing later is needed.)
        search.enough.is_some_and(|enough| counted >= enough) || cancelled()
    });
    if cancelled() {
        return Err(SynthesisError::Cancelled);
    }
    synthesis
        .designs
        .sort_by(|a, b| a.rms_error.total_cmp(&b.rms_error));
    Ok(synthesis)
}

/// A draw of `stream`: the free parameters uniform within their bounds;
/// free drivers evenly spread from a random phase over a revolution, or
/// over the task's range; a relative timing's offset uniform over a
/// revolution, or over the offsets that keep every driver in the range.
fn start_point<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    stream: &mut SplitMix64,
) -> DVector<f64>
where
    L: Sensitivities<M, 1, K>,
{
    let mut x: Vec<f64> = problem
        .free
        .iter()
        .map(|f| f.lower + (f.upper - f.lower) * stream.uniform())
        .collect();
    let phase = stream.uniform();
    let n = problem.targets.len();
    let (lower, upper) = driver_bounds(problem);
    match (&problem.timing, problem.range) {
        (Timing::Prescribed(_), _) => {}
        (Timing::Relative(_), None) => x.push(TAU * phase),
        (Timing::Relative(_), Some(_)) => x.push(lower + (upper - lower) * phase),
        (Timing::Free, None) => {
            x.extend((0..n).map(|i| TAU * phase + TAU * i as f64 / n as f64));
        }
        (Timing::Free, Some((from, to))) => {
            // Evenly in the range's direction, in the targets' order.
            x.extend((0..n).map(|i| from + (to - from) * (i as f64 + 0.5) / n as f64));
        }
    }
    DVector::from_vec(x)
}

/// The bounds of the driver unknowns: the task's range for free drivers;
/// for a relative timing's offset, those that keep every driver in it;
/// none without a range.
fn driver_bounds<L, const M: usize, const K: usize>(problem: &Problem<L, M, K>) -> (f64, f64)
where
    L: Sensitivities<M, 1, K>,
{
    let Some((from, to)) = problem.range else {
        return (f64::NEG_INFINITY, f64::INFINITY);
    };
    let (low, high) = (from.min(to), from.max(to));
    match &problem.timing {
        Timing::Relative(drivers) => {
            let (least, most) = extent(drivers);
            (low - least, high - most)
        }
        _ => (low, high),
    }
}

/// The unknowns' bounds: the free parameters', then the drivers'
/// ([`driver_bounds`]).
fn bounds<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
) -> (DVector<f64>, DVector<f64>)
where
    L: Sensitivities<M, 1, K>,
{
    let n = problem.unknowns();
    let (low, high) = driver_bounds(problem);
    let lower = DVector::from_fn(n, |i, _| problem.free.get(i).map_or(low, |f| f.lower));
    let upper = DVector::from_fn(n, |i, _| problem.free.get(i).map_or(high, |f| f.upper));
    (lower, upper)
}

/// The poses of `model` to begin from at the driver `v`: the one Newton
/// reaches from the problem's guess, or, without a guess, its assembly
/// modes there ([`assembly::modes`]) in their order turned by the start's
/// index (start k first tries mode k mod n). None if it cannot be
/// assembled at `v`.
fn assemblies<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    model: &L,
    v: f64,
    start: usize,
    options: &SweepOptions,
) -> Vec<SVector<f64, M>>
where
    L: Sensitivities<M, 1, K>,
{
    let v = SVector::from([v]);
    match &problem.guess {
        Some(guess) => model
            .solve_position(guess, &v, &options.options)
            .ok()
            .map(|s| s.u)
            .into_iter()
            .collect(),
        None => match assembly::modes(model, &v, &assembly::Search::default()) {
            Ok(found) => {
                let n = found.modes.len();
                (0..n).map(|k| found.modes[(start + k) % n].u).collect()
            }
            Err(_) => Vec::new(),
        },
    }
}

/// The poses at the targets for the unknowns `x`: the first solved from
/// the problem's guess, or from the design's assemblies without one
/// ([`assemblies`]: the first that reaches every target), each next one
/// followed from it by continuation (so that all lie on one branch);
/// `None` if the start cannot be assembled or followed. `first` holds the
/// design's assemblies at the first target's driver
/// ([`assemblies_at_first`]). `on_arc`, over a
/// revolution ([`Problem::over_a_revolution`]): a start that cannot be
/// followed through drivers spread over a whole revolution (its driver
/// cannot turn one: a rocker) has them spread over the arc it can reach
/// instead, and `x`'s drivers are moved there.
fn first_poses<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x: &mut DVector<f64>,
    start: usize,
    steps_per_radian: f64,
    options: &SweepOptions,
    first: Vec<SVector<f64, M>>,
    on_arc: bool,
) -> Option<Poses<M>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let model = problem.model_at(x.as_slice());
    let n = problem.targets.len();
    let mut drivers: Vec<f64> = (0..n).map(|i| problem.driver(x.as_slice(), i)).collect();
    let mut u = first.into_iter().find_map(|first| {
        continuation::through(&model, first, &drivers, steps_per_radian, options)
    });
    if on_arc && u.is_none() && problem.over_a_revolution() {
        // The arc the driver reaches from the first target's driver (or,
        // if it does not assemble there, from the first of eight around
        // the turn where it does), the drivers spread over it.
        let (v0, u0) = (0..8).find_map(|k| {
            let v = drivers[0] + TAU * k as f64 / 8.0;
            let at = assemblies(problem, &model, v, start, options);
            at.first().map(|u| (v, *u))
        })?;
        let reach = |to: f64| {
            let followed =
                continuation::follow(&model, &u0, (v0, to), steps_per_radian, options, |_| {})
                    .ok()?;
            Some((followed.v, followed.summary.complete))
        };
        let (high, whole) = reach(v0 + TAU)?;
        let (low, high) = if whole {
            (v0, v0 + TAU)
        } else {
            (reach(v0 - TAU)?.0, high)
        };
        for (i, d) in drivers.iter_mut().enumerate() {
            *d = low + (high - low) * (i as f64 + 0.5) / n as f64;
        }
        let arc: Vec<f64> = std::iter::once(v0).chain(drivers.iter().copied()).collect();
        u = Some(continuation::through(&model, u0, &arc, steps_per_radian, options)?.split_off(1));
        for (i, d) in drivers.iter().enumerate() {
            x[problem.free.len() + i] = *d;
        }
    }
    let u = u?;
    let branch = u
        .iter()
        .zip(&drivers)
        .map(|(u, v)| branch(&model, u, *v))
        .collect();
    Some(Poses { u, branch })
}

/// The draw a start begins from, and its evaluation: of [`Search::DRAWS`]
/// draws of `stream`, the first that can be assembled, followed through
/// the targets' drivers as drawn and evaluated there; `None` if none can.
/// Over a revolution ([`Problem::over_a_revolution`]), a draw whose driver
/// cannot turn one (a rocker) comes only after every draw that can: such
/// a start is rarely certified (on pylinkage's README task, 2 % of the
/// starts from rockers against 12 % of the others), so the rockers are
/// followed over the arc they reach ([`first_poses`]) only if none of the
/// draws turns.
fn first_draw<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    search: &Search,
    steps_per_radian: f64,
    start: usize,
    stream: &mut SplitMix64,
    stop: &dyn Fn() -> bool,
) -> Option<(DVector<f64>, Evaluation<Poses<M>>)>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let options = &search.options;
    let followed = |x: &DVector<f64>, first: Vec<SVector<f64, M>>, on_arc: bool| {
        let mut x = x.clone();
        let poses = first_poses(
            problem,
            &mut x,
            start,
            steps_per_radian,
            options,
            first,
            on_arc,
        )?;
        let first = evaluate(problem, &x, &poses, &options.options)?;
        Some((x, first))
    };
    let at_first = |x: &DVector<f64>| assemblies_at_first(problem, x, start, options);
    if !problem.over_a_revolution() {
        return (0..Search::DRAWS).take_while(|_| !stop()).find_map(|_| {
            let x = start_point(problem, stream);
            followed(&x, at_first(&x), false)
        });
    }
    // Whether a draw turns is first asked of a few Newton solves around
    // the turn ([`assembles_around`]), then of the follow through the
    // targets. On the path tasks of docs/performance.md about as many
    // designs as when every draw was followed, 15–35 % sooner.
    let mut rockers = Vec::new();
    for _ in 0..Search::DRAWS {
        if stop() {
            return None;
        }
        let x = start_point(problem, stream);
        let turns = assembles_around(problem, &x, at_first(&x), options);
        if let Some(drawn) = turns.and_then(|first| followed(&x, first, false)) {
            return Some(drawn);
        }
        rockers.push(x);
    }
    // (A draw screened out by a Newton solve that failed where it
    // assembles is followed whole here, before any arc is tried.)
    rockers
        .iter()
        .take_while(|_| !stop())
        .find_map(|x| followed(x, at_first(x), true))
}

/// The assemblies of the design `x` at its first target's driver
/// ([`assemblies`]).
fn assemblies_at_first<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x: &DVector<f64>,
    start: usize,
    options: &SweepOptions,
) -> Vec<SVector<f64, M>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let model = problem.model_at(x.as_slice());
    assemblies(
        problem,
        &model,
        problem.driver(x.as_slice(), 0),
        start,
        options,
    )
}

/// Driver angles around a turn at which [`assembles_around`] solves.
const AROUND: usize = 16;

/// `first`, the design `x`'s assemblies at its first target's driver, if
/// one of them assembles at [`AROUND`] drivers evenly around a turn from
/// there, each solved by Newton (at most 16 iterations) from the pose
/// before it: a driver that cannot turn a revolution (a rocker) usually
/// fails where it does not assemble, at a small part of the cost of
/// following it there. A screen, not a verdict: a draw that passes is
/// still followed, and a dead range narrower than the spacing of the
/// drivers is caught by that follow.
fn assembles_around<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x: &DVector<f64>,
    first: Vec<SVector<f64, M>>,
    options: &SweepOptions,
) -> Option<Vec<SVector<f64, M>>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let model = problem.model_at(x.as_slice());
    let v0 = problem.driver(x.as_slice(), 0);
    let newton = Options {
        max_iterations: options.options.max_iterations.min(16),
        ..options.options
    };
    let around = |&u: &SVector<f64, M>| {
        let mut u = u;
        (1..AROUND).all(|j| {
            let v = SVector::from([v0 + TAU * j as f64 / AROUND as f64]);
            match model.solve_position(&u, &v, &newton) {
                Ok(solved) => {
                    u = solved.u;
                    true
                }
                Err(_) => false,
            }
        })
    };
    first.iter().any(around).then_some(first)
}

/// One start solved from its draw ([`first_draw`]); `None` if none of its
/// draws can be followed through the targets.
fn solve<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    search: &Search,
    steps_per_radian: f64,
    start: usize,
    stop: &dyn Fn() -> bool,
) -> Option<Candidate<L, M>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let options: &Options = &search.options.options;
    let mut stream = SplitMix64::of_sample(search.random_state, start as u64);
    let (x0, first) = first_draw(problem, search, steps_per_radian, start, &mut stream, stop)?;
    let (lower, upper) = bounds(problem);
    // (Stopped, every trial is one that cannot be evaluated: the solver
    // gives up after `Stopping::unevaluable` of them.)
    let found = minimize(first, x0, &lower, &upper, &search.stopping, |x, from| {
        (!stop())
            .then(|| evaluate(problem, x, from, options))
            .flatten()
    });
    let rows = problem.task.rows();
    // Each target's miss (the designer's terms follow the targets' rows).
    let errors: Vec<f64> = found.residuals.as_slice()[..problem.target_residuals()]
        .chunks(rows)
        .map(|r| r.iter().map(|x| x * x).sum::<f64>().sqrt())
        .collect();
    let rms_error = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
    let x = found.x.as_slice();
    let mut drivers: Vec<f64> = (0..problem.targets.len())
        .map(|i| problem.driver(x, i))
        .collect();
    if problem.over_a_revolution() {
        one_way(&mut drivers);
    }
    Some(Candidate {
        model: problem.model_at(x),
        drivers,
        poses: found.state.u,
        errors,
        rms_error,
        evaluations: found.evaluations,
        start,
        certificate: None,
    })
}

/// Free drivers are angles whose whole turns the solver leaves wherever
/// its steps took them (a driver a turn away gives the same pose). If they
/// do not visit the targets in order turning one way, less than a turn
/// from each to the next, each is moved by whole turns onto the shortest
/// route that does: the route the certificate then follows.
fn one_way(drivers: &mut [f64]) {
    let gaps = || drivers.windows(2).map(|w| w[1] - w[0]);
    let within = gaps().all(|g| g != 0.0 && g.abs() < TAU);
    if within && (gaps().all(|g| g > 0.0) || gaps().all(|g| g < 0.0)) {
        return;
    }
    let travel = |sign: f64| -> f64 {
        drivers
            .windows(2)
            .map(|w| (sign * (w[1] - w[0])).rem_euclid(TAU))
            .sum()
    };
    let sign = if travel(1.0) <= travel(-1.0) {
        1.0
    } else {
        -1.0
    };
    for i in 1..drivers.len() {
        let gap = (sign * (drivers[i] - drivers[i - 1])).rem_euclid(TAU);
        drivers[i] = drivers[i - 1] + sign * gap;
    }
}

/// How far a precision point may be missed, relative to the targets'
/// size ([`Problem::precision_points`]).
pub(crate) const PRECISION: f64 = 1e-10;

/// Whether a candidate is returned: met (for precision points) and
/// certified.
fn verdict<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    candidate: &Candidate<L, M>,
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
) -> Result<Certificate, Defect>
where
    L: Sensitivities<M, 1, K>,
{
    let (target, error) = candidate.largest_error();
    // (A NaN miss is no meeting either.)
    let met = error <= PRECISION * problem.target_scale();
    // A miss that is not finite is no design, whether the targets must be
    // met or come as near as they can (targets so large that the misses
    // overflow).
    if (problem.exact && !met) || !error.is_finite() || !candidate.rms_error.is_finite() {
        return Err(Defect::Misses { target, error });
    }
    certify(
        &candidate.model,
        &candidate.poses,
        &candidate.drivers,
        problem.range,
        requirements,
        options,
    )
}

/// Two candidates are the same design if their free parameters agree to
/// 1e-6 of their bounds' widths and their drivers to 1e-6 (an angle's up
/// to whole turns).
fn same_design<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    a: &Candidate<L, M>,
    b: &Candidate<L, M>,
) -> bool
where
    L: Sensitivities<M, 1, K>,
{
    let (pa, pb) = (a.model.params(), b.model.params());
    let params = problem
        .free
        .iter()
        .all(|f| (pa[f.index] - pb[f.index]).abs() <= 1e-6 * (f.upper - f.lower));
    let drivers = a
        .drivers
        .iter()
        .zip(&b.drivers)
        .all(|(x, y)| continuation::same_driver(&a.model, *x, *y, 1e-6));
    params && drivers
}

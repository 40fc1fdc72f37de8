//! Many starts in parallel: each a random design within the bounds (and a
//! random phase of the free drivers), followed by continuation to the
//! poses at every target, solved by Levenberg–Marquardt on the exact
//! Jacobian, then certified; the certified designs kept once each and
//! ranked by their error at the targets.

use super::SynthesisError;
use super::certify::{Defect, Requirements, certify};
use super::least_squares::{Stopping, minimize};
use super::problem::Problem;
use super::residuals::{Poses, branch, evaluate};
use crate::batch;
use crate::random::SplitMix64;
use linkage_runtime::{Drive, Options, Sensitivities, SweepOptions};
use nalgebra::{DVector, SVector};
use std::f64::consts::TAU;

/// How to search.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Search {
    /// Random starts, solved in parallel.
    pub starts: usize,
    /// The random stream the starts are drawn from (each start a function
    /// of it and its index).
    pub stream: u64,
    pub stopping: Stopping,
    /// The solves of the poses and the sweeps of the certificate.
    pub options: SweepOptions,
    /// Stop once this many distinct designs are certified: the starts then
    /// run in rounds of [`Search::ROUND`] (in parallel within a round), and
    /// the search ends with the round that reaches them. `None`: every
    /// start. Either way the result depends only on the stream, not on
    /// the machine's cores.
    pub enough: Option<usize>,
}

impl Search {
    /// Starts per round when the search may stop early.
    pub const ROUND: usize = 8;
}

impl Default for Search {
    fn default() -> Search {
        Search {
            starts: 64,
            stream: 1,
            stopping: Stopping::default(),
            options: SweepOptions::default(),
            enough: None,
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
    /// The miss at each target (the norm of its residuals), and the root
    /// mean square of all residuals.
    pub errors: Vec<f64>,
    pub rms_error: f64,
    /// Evaluations of residuals and Jacobian the solver took.
    pub evaluations: usize,
    /// The start it came from.
    pub start: usize,
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

impl<L, const M: usize> Synthesis<L, M> {
    /// The best certified design, or why there is none: a target that
    /// every candidate missed (out of reach), or the refusals and failed
    /// starts.
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
            first_defect: self.refused.first().map(|(_, d)| d.clone()),
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

/// Solves `problem` from `search.starts` random starts in parallel and
/// certifies every result against `requirements` (or from as many rounds
/// of them as it takes to certify [`Search::enough`] designs).
pub fn synthesize<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    requirements: &Requirements<'_, L, M>,
    search: &Search,
) -> Result<Synthesis<L, M>, SynthesisError>
where
    L: Sensitivities<M, 1, K> + Clone + Sync + Send,
{
    problem.check()?;
    search.options.options.check()?;
    let round = match search.enough {
        Some(_) => Search::ROUND,
        None => search.starts.max(1),
    };
    let mut synthesis = Synthesis {
        designs: Vec::new(),
        refused: Vec::new(),
        failed_starts: 0,
        starts: 0,
    };
    while synthesis.starts < search.starts
        && search
            .enough
            .is_none_or(|enough| synthesis.designs.len() < enough)
    {
        let starts: Vec<usize> =
            (synthesis.starts..search.starts.min(synthesis.starts + round)).collect();
        // Solved and certified in parallel; kept in the starts' order.
        let outcomes = batch::map(&starts, |&start| {
            let x0 = start_point(problem, search.stream, start);
            let candidate = solve(problem, x0, search, start)?;
            let verdict = verdict(problem, &candidate, requirements, &search.options);
            Some((candidate, verdict))
        });
        synthesis.starts += starts.len();
        for outcome in outcomes {
            match outcome {
                None => synthesis.failed_starts += 1,
                Some((candidate, Ok(()))) => {
                    if !synthesis
                        .designs
                        .iter()
                        .any(|d| same_design(problem, d, &candidate))
                    {
                        synthesis.designs.push(candidate);
                    }
                }
                Some((candidate, Err(defect))) => synthesis.refused.push((candidate, defect)),
            }
        }
    }
    synthesis
        .designs
        .sort_by(|a, b| a.rms_error.total_cmp(&b.rms_error));
    Ok(synthesis)
}

/// Start `start`: the free parameters uniform within their bounds, the
/// free drivers evenly spread from a random phase.
fn start_point<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    stream: u64,
    start: usize,
) -> DVector<f64>
where
    L: Sensitivities<M, 1, K>,
{
    let mut stream = SplitMix64::of_sample(stream, start as u64);
    let mut x: Vec<f64> = problem
        .free
        .iter()
        .map(|f| f.lower + (f.upper - f.lower) * stream.uniform())
        .collect();
    let phase = TAU * stream.uniform();
    let n = problem.free_drivers();
    x.extend((0..n).map(|i| phase + TAU * i as f64 / n as f64));
    DVector::from_vec(x)
}

/// The unknowns' bounds: the free parameters', and none on the drivers.
fn bounds<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
) -> (DVector<f64>, DVector<f64>)
where
    L: Sensitivities<M, 1, K>,
{
    let n = problem.unknowns();
    let lower = DVector::from_fn(n, |i, _| {
        problem.free.get(i).map_or(f64::NEG_INFINITY, |f| f.lower)
    });
    let upper = DVector::from_fn(n, |i, _| {
        problem.free.get(i).map_or(f64::INFINITY, |f| f.upper)
    });
    (lower, upper)
}

/// The poses at the targets for the unknowns `x`: the first solved from
/// the problem's guess, each next one followed from it by continuation
/// (so that all lie on one branch); `None` if the start cannot be
/// assembled or followed. With free timing, a start that cannot be
/// followed through drivers spread over a whole revolution (its driver
/// cannot turn one: a rocker) has them spread over the arc it can reach
/// instead, and `x`'s drivers are moved there.
fn first_poses<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x: &mut DVector<f64>,
    options: &SweepOptions,
) -> Option<Poses<M>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let model = problem.model_at(x.as_slice());
    let n = problem.targets.len();
    let mut drivers: Vec<f64> = (0..n).map(|i| problem.driver(x.as_slice(), i)).collect();
    let first = model
        .solve_position(
            &problem.guess,
            &SVector::from([drivers[0]]),
            &options.options,
        )
        .ok()
        .map(|s| s.u);
    let mut u = first.and_then(|first| follow(&model, first, &drivers, options));
    if u.is_none() && problem.drivers.is_none() {
        // The arc the driver reaches from the first target's driver (or,
        // if it does not assemble there, from the first of eight around
        // the turn where it does), the drivers spread over it.
        let (v0, u0) = (0..8).find_map(|k| {
            let v = drivers[0] + TAU * k as f64 / 8.0;
            let at = model.solve_position(&problem.guess, &SVector::from([v]), &options.options);
            at.ok().map(|s| (v, s.u))
        })?;
        let reach = |to: f64| {
            let drive = Drive::Line {
                from: SVector::from([v0]),
                to: SVector::from([to]),
                steps: ((to - v0).abs() * 30.0).ceil() as usize,
            };
            let mut last = v0;
            let summary = model
                .sweep_each(&u0, &drive, options, |pose| last = pose.v[0])
                .ok()?;
            Some((last, summary.complete))
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
        u = Some(follow(&model, u0, &arc, options)?.split_off(1));
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

/// The poses at `drivers` followed by continuation from `first` at the
/// first of them; `None` if a sweep stops.
fn follow<L, const M: usize, const K: usize>(
    model: &L,
    first: SVector<f64, M>,
    drivers: &[f64],
    options: &SweepOptions,
) -> Option<Vec<SVector<f64, M>>>
where
    L: Sensitivities<M, 1, K>,
{
    let mut u = vec![first];
    for pair in drivers.windows(2) {
        let drive = Drive::Line {
            from: SVector::from([pair[0]]),
            to: SVector::from([pair[1]]),
            steps: ((pair[1] - pair[0]).abs() * 30.0).ceil().max(2.0) as usize,
        };
        let mut last = None;
        let summary = model
            .sweep_each(u.last()?, &drive, options, |pose| last = Some(pose.u))
            .ok()?;
        if !summary.complete {
            return None;
        }
        u.push(last?);
    }
    Some(u)
}

/// One start solved: its candidate, or `None` if it cannot be assembled.
fn solve<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x0: DVector<f64>,
    search: &Search,
    start: usize,
) -> Option<Candidate<L, M>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let options: &Options = &search.options.options;
    let mut x0 = x0;
    let poses = first_poses(problem, &mut x0, &search.options)?;
    let first = evaluate(problem, &x0, &poses, options)?;
    let (lower, upper) = bounds(problem);
    let found = minimize(first, x0, &lower, &upper, &search.stopping, |x, from| {
        evaluate(problem, x, from, options)
    });
    let rows = problem.task.rows();
    // Each target's miss (the designer's terms follow the targets' rows).
    let errors = found.residuals.as_slice()[..problem.target_residuals()]
        .chunks(rows)
        .map(|r| r.iter().map(|x| x * x).sum::<f64>().sqrt())
        .collect();
    let rms_error = (found.residuals.norm_squared() / found.residuals.len() as f64).sqrt();
    let x = found.x.as_slice();
    let mut drivers: Vec<f64> = (0..problem.targets.len())
        .map(|i| problem.driver(x, i))
        .collect();
    if problem.drivers.is_none() {
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

/// Whether a candidate is returned: met (for precision points) and
/// certified.
fn verdict<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    candidate: &Candidate<L, M>,
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
) -> Result<(), Defect>
where
    L: Sensitivities<M, 1, K>,
{
    if problem.exact {
        let scale = problem
            .targets
            .iter()
            .flat_map(|t| t.iter().map(|x| x.abs()))
            .fold(1.0, f64::max);
        let (target, error) = candidate.largest_error();
        if error > 1e-9 * scale {
            return Err(Defect::Misses { target, error });
        }
    }
    certify(
        &candidate.model,
        &candidate.poses,
        &candidate.drivers,
        requirements,
        options,
    )
}

/// Two candidates are the same design if their free parameters agree to
/// 1e-6 of their bounds' widths and their drivers to 1e-6 (modulo a turn).
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
    let drivers = a.drivers.iter().zip(&b.drivers).all(|(x, y)| {
        let d = x - y;
        (d - TAU * (d / TAU).round()).abs() <= 1e-6
    });
    params && drivers
}

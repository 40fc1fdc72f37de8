//! Many independent analyses at once, in parallel on rayon's thread pool
//! (with the `parallel` feature, on by default; without it, one after the
//! other, with the same results).
//!
//! Optimising a design means analysing thousands of parameter sets; each is
//! independent of the others, so they spread over the cores with nothing
//! shared but the read-only jobs. The results come back in the jobs' order,
//! one `Result` per job: a design that cannot be assembled is an `Err` in
//! its slot and does not stop the others.
//!
//! The work runs on the current rayon pool: the global one (sized by
//! `RAYON_NUM_THREADS`, by default one thread per core), or one of your own
//! through `rayon::ThreadPool::install` (add `rayon` to your own
//! dependencies for that).
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::batch::{self, SweepJob};
//!
//! #[linkage::linkage(
//!     u = [theta3, theta4],
//!     v = [theta2],
//!     closure = [
//!         l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
//!         l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
//!     ],
//! )]
//! #[derive(Clone, Copy, Debug)]
//! pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }
//!
//! // Crank-rockers with couplers from 45 to 55: the largest angular
//! // acceleration of the rocker over a revolution at ω2 = 10 rad/s.
//! let jobs: Vec<SweepJob<FourBar, 2, 1>> = (0..11)
//!     .map(|k| SweepJob {
//!         model: FourBar { l1: 80.0, l2: 20.0, l3: 45.0 + k as f64, l4: 70.0 },
//!         u0: vector![1.2, -0.8],
//!         drive: Drive::Line { from: vector![0.0], to: vector![std::f64::consts::TAU], steps: 3600 },
//!     })
//!     .collect();
//! let options = SweepOptions { speed: 10.0, ..SweepOptions::default() };
//! let peaks = batch::sweeps(&jobs, &options, |_| 0.0_f64, |peak, pose| {
//!     *peak = peak.max(pose.uddot[1].abs());
//! });
//! for result in &peaks {
//!     let swept = result.as_ref().expect("every design assembles");
//!     assert!(swept.summary.complete && swept.value > 0.0);
//! }
//! ```

pub use crate::runtime::AnalysisJob;
use crate::runtime::{
    Analysis, Drive, Error, Linkage, Options, Sensitivities, Sensitivity, SweepOptions, SweepPose,
    SweepSummary, analyze_together,
};
use nalgebra::SVector;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// The jobs, on rayon's pool.
#[cfg(feature = "parallel")]
fn each<T: Sync>(jobs: &[T]) -> rayon::slice::Iter<'_, T> {
    jobs.par_iter()
}

/// The jobs, one after the other (without the `parallel` feature).
#[cfg(not(feature = "parallel"))]
fn each<T>(jobs: &[T]) -> std::slice::Iter<'_, T> {
    jobs.iter()
}

/// How many analyses run side by side on one thread (see [`analyses`]).
const SIDE_BY_SIDE: usize = 64;

/// `f` of every run of at most [`SIDE_BY_SIDE`] jobs and its slots of
/// `out` (one per job), on rayon's pool.
#[cfg(feature = "parallel")]
fn side_by_side<T: Sync, R: Send>(jobs: &[T], out: &mut [R], f: impl Fn(&[T], &mut [R]) + Sync) {
    (jobs.par_chunks(SIDE_BY_SIDE))
        .zip(out.par_chunks_mut(SIDE_BY_SIDE))
        .for_each(|(jobs, out)| f(jobs, out));
}

/// `f` of every run of at most [`SIDE_BY_SIDE`] jobs and its slots of
/// `out` (one per job), one after the other (without the `parallel`
/// feature).
#[cfg(not(feature = "parallel"))]
fn side_by_side<T, R>(jobs: &[T], out: &mut [R], f: impl Fn(&[T], &mut [R])) {
    (jobs.chunks(SIDE_BY_SIDE))
        .zip(out.chunks_mut(SIDE_BY_SIDE))
        .for_each(|(jobs, out)| f(jobs, out));
}

/// Every job's [`Linkage::analyze`], analysed side by side
/// ([`analyze_together`]) in runs of [`SIDE_BY_SIDE`], each result written
/// once, in its place.
#[allow(clippy::type_complexity)]
fn analyses_side_by_side<L, const M: usize, const F: usize>(
    jobs: &[AnalysisJob<L, M, F>],
    options: &Options,
) -> Vec<Result<Analysis<M, F, L::Points>, Error>>
where
    L: Linkage<M, F> + Sync,
    L::Points: Send,
{
    // Each slot is written over by `analyze_together`.
    let mut results: Vec<_> = (jobs.iter())
        .map(|_| {
            Err(Error::NotConverged {
                iterations: 0,
                residual: f64::NAN,
                step: f64::NAN,
            })
        })
        .collect();
    side_by_side(jobs, &mut results, |jobs, out| {
        analyze_together(jobs, options, out)
    });
    results
}

/// Runs `f` on every job in parallel, the results in the jobs' order: the
/// general form of the functions below, for work of your own on many
/// designs (a Monte Carlo sample each, an objective per candidate).
pub fn map<T, R, G>(jobs: &[T], f: G) -> Vec<R>
where
    T: Sync,
    R: Send,
    G: Fn(&T) -> R + Send + Sync,
{
    each(jobs).map(f).collect()
}

/// `f` of the indices 0, 1, 2, … below `count`, taken in turn by the
/// pool's threads, each result handed to `consume` in index order, until
/// `consume` says it has had enough (returns `true`): no result after that
/// one is handed on. What `consume` is given depends only on `f` and on
/// `consume` itself, not on the threads: an index after the last one
/// handed on may have started, and its result is dropped. `f` is also
/// given a probe that turns false once its index is no longer wanted, so
/// that such a job may end early with anything. A search that stops at its
/// first success runs this way.
pub(crate) fn in_order_until<R, G, Consume>(count: usize, f: G, consume: Consume)
where
    R: Send,
    G: Fn(usize, &dyn Fn() -> bool) -> R + Send + Sync,
    Consume: FnMut(R) -> bool + Send,
{
    #[cfg(feature = "parallel")]
    in_order::in_order_until(count, f, consume);
    #[cfg(not(feature = "parallel"))]
    {
        let mut consume = consume;
        for index in 0..count {
            if consume(f(index, &|| true)) {
                break;
            }
        }
    }
}

#[cfg(feature = "parallel")]
mod in_order;

/// One sweep of a batch: a model (a parameter set), the guess of its
/// starting pose and its drive.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepJob<L, const M: usize, const F: usize> {
    pub model: L,
    pub u0: SVector<f64, M>,
    pub drive: Drive<F>,
}

/// The outcome of one sweep of a batch: what `on_pose` made of its poses,
/// and the sweep's summary (its events, whether it went the whole way).
#[derive(Clone, Debug, PartialEq)]
pub struct Swept<A, const M: usize, const F: usize> {
    pub value: A,
    pub summary: SweepSummary<M, F>,
}

/// Runs every job's sweep ([`Linkage::sweep_each`]) in parallel. Each sweep
/// starts from `init(job index)` and folds its poses into it with
/// `on_pose`, in order; the poses themselves are not kept, so a batch of
/// millions of poses runs in the memory of its accumulators.
///
/// Each result equals, to the bit, what the same sweep gives alone: the jobs
/// share nothing.
pub fn sweeps<L, A, I, P, const M: usize, const F: usize>(
    jobs: &[SweepJob<L, M, F>],
    options: &SweepOptions,
    init: I,
    on_pose: P,
) -> Vec<Result<Swept<A, M, F>, Error>>
where
    L: Linkage<M, F> + Sync,
    A: Send,
    I: Fn(usize) -> A + Sync,
    P: Fn(&mut A, &SweepPose<M, F>) + Sync,
{
    each(jobs)
        .enumerate()
        .map(|(k, job)| {
            let mut value = init(k);
            let summary = job.model.sweep_each(&job.u0, &job.drive, options, |pose| {
                on_pose(&mut value, pose)
            })?;
            Ok(Swept { value, summary })
        })
        .collect()
}

/// Runs every job's [`Linkage::analyze`] in parallel (see the module
/// documentation). For a run-time mechanism ([`crate::mechanism`]), runs
/// of jobs are analysed side by side on each thread: their Newton
/// iterations ask for their evaluations together, which it makes on its
/// tapes' lanes, several poses or designs of one mechanism per pass. Each
/// result equals, to the bit, what the job's `analyze` gives alone.
#[allow(clippy::type_complexity)]
pub fn analyses<L, const M: usize, const F: usize>(
    jobs: &[AnalysisJob<L, M, F>],
    options: &Options,
) -> Vec<Result<Analysis<M, F, L::Points>, Error>>
where
    L: Linkage<M, F> + Sync,
    L::Points: Send,
{
    if L::evaluates_together() {
        return analyses_side_by_side(jobs, options);
    }
    each(jobs).map(|job| analyze(job, options)).collect()
}

/// One job's analysis, alone.
fn analyze<L: Linkage<M, F>, const M: usize, const F: usize>(
    job: &AnalysisJob<L, M, F>,
    options: &Options,
) -> Result<Analysis<M, F, L::Points>, Error> {
    (job.model).analyze(&job.u_guess, &job.v, &job.vdot, &job.vddot, options)
}

/// [`sweeps`] with the sensitivities of every pose to the parameters
/// ([`Sensitivities::sweep_sensitivities_each`]): `on_pose` gets each pose
/// with its sensitivities, or the reason they are refused there (next to a
/// singular pose).
#[allow(clippy::type_complexity)]
pub fn sweeps_with_sensitivities<L, A, I, P, const M: usize, const F: usize, const K: usize>(
    jobs: &[SweepJob<L, M, F>],
    options: &SweepOptions,
    init: I,
    on_pose: P,
) -> Vec<Result<Swept<A, M, F>, Error>>
where
    L: Sensitivities<M, F, K> + Sync,
    A: Send,
    I: Fn(usize) -> A + Sync,
    P: Fn(&mut A, &SweepPose<M, F>, Result<Sensitivity<M, K, L::Points>, Error>) + Sync,
{
    each(jobs)
        .enumerate()
        .map(|(k, job)| {
            let mut value = init(k);
            let summary = job.model.sweep_sensitivities_each(
                &job.u0,
                &job.drive,
                options,
                |pose, sensitivity| on_pose(&mut value, pose, sensitivity),
            )?;
            Ok(Swept { value, summary })
        })
        .collect()
}

/// Runs every job's [`Linkage::analyze`] and then
/// [`Sensitivities::sensitivities`] at the pose found, in parallel.
#[allow(clippy::type_complexity)]
pub fn analyses_with_sensitivities<L, const M: usize, const F: usize, const K: usize>(
    jobs: &[AnalysisJob<L, M, F>],
    options: &Options,
) -> Vec<Result<(Analysis<M, F, L::Points>, Sensitivity<M, K, L::Points>), Error>>
where
    L: Sensitivities<M, F, K> + Sync,
    L::Points: Send,
{
    let with_sensitivities = |job: &AnalysisJob<L, M, F>, analysis| {
        let analysis = analysis?;
        let sensitivity = job.model.sensitivities_of(&analysis, options)?;
        Ok((analysis, sensitivity))
    };
    if L::evaluates_together() {
        let analyses = analyses_side_by_side(jobs, options);
        return (each(jobs).zip(analyses))
            .map(|(job, analysis)| with_sensitivities(job, analysis))
            .collect();
    }
    each(jobs)
        .map(|job| with_sensitivities(job, analyze(job, options)))
        .collect()
}

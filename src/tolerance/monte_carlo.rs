//! The Monte Carlo check of the linear estimate: designs drawn within the
//! tolerances, analysed in parallel through [`batch`](crate::batch).

use super::output::{Resolved, TolerancePose};
use super::{Design, Output, Statistics, ToleranceError, Tolerances};
use crate::batch;
use crate::runtime::{Drive, Error, Event, Motion, Sensitivities, SweepOptions};
use nalgebra::SVector;

/// A Monte Carlo run: how many samples, and the state their random numbers
/// begin from (the same state, the same samples).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MonteCarlo {
    pub samples: usize,
    pub random_state: u64,
}

impl MonteCarlo {
    /// Sample `index` of the run: `model` with its parameters moved by
    /// [`Tolerances::deviation`].
    pub fn sample<L, const M: usize, const F: usize, const K: usize>(
        &self,
        model: &L,
        tolerances: &Tolerances<K>,
        index: usize,
    ) -> L
    where
        L: Sensitivities<M, F, K> + Clone,
    {
        let mut sample = model.clone();
        sample.set_params(&(model.params() + tolerances.deviation(self.random_state, index)));
        sample
    }
}

/// Runs `evaluate` on every sample of the run, in parallel; the results
/// come in the samples' order. The general form, for a quantity of your
/// own (the stroke: a sweep and [`locate`](crate::watch::locate) per
/// sample).
pub fn monte_carlo<L, T, G, const M: usize, const F: usize, const K: usize>(
    model: &L,
    tolerances: &Tolerances<K>,
    run: &MonteCarlo,
    evaluate: G,
) -> Result<Vec<T>, ToleranceError>
where
    L: Sensitivities<M, F, K> + Clone + Sync,
    T: Send,
    G: Fn(&L) -> T + Send + Sync,
{
    if run.samples == 0 {
        return Err(ToleranceError::NoSamples);
    }
    let indices: Vec<usize> = (0..run.samples).collect();
    Ok(batch::map(&indices, |&i| {
        evaluate(&run.sample(model, tolerances, i))
    }))
}

/// Why a sample was left out of a cycle's statistics.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Failure<const M: usize, const F: usize> {
    /// It cannot be assembled, or its sweep failed.
    Kinematics(Error),
    /// It does not follow the drive as the nominal design does: a limit
    /// position ends it, or it meets singular poses the nominal does not
    /// (the first such event).
    Singular(Option<Event<M, F>>),
    /// Its extremes cannot be located ([`monte_carlo_range`](super::monte_carlo_range)).
    Extremes(ToleranceError),
}

/// The Monte Carlo statistics of every output at every step of the drive.
#[derive(Clone, Debug, PartialEq)]
pub struct CycleSamples<const M: usize, const F: usize> {
    /// The outputs' names.
    pub names: Vec<String>,
    /// The nominal design's driver at each step (`None` at a step it has
    /// no pose for).
    pub v: Vec<Option<SVector<f64, F>>>,
    /// `statistics[o][k]`: output `o` at step `k`, over the samples that
    /// pass (non-finite values left out).
    pub statistics: Vec<Vec<Statistics>>,
    /// The samples drawn.
    pub samples: usize,
    /// The samples left out, by index, and why.
    pub failures: Vec<(usize, Failure<M, F>)>,
}

impl<const M: usize, const F: usize> Failure<M, F> {
    /// Whether the sample cannot run the cycle: it cannot be assembled, or
    /// its drive ends at a limit position or a singular pose the nominal
    /// design does not meet (not: it runs the cycle, and only its extremes
    /// could not be located).
    pub fn cannot_run(&self) -> bool {
        matches!(self, Failure::Kinematics(_) | Failure::Singular(_))
    }
}

impl<const M: usize, const F: usize> CycleSamples<M, F> {
    /// The fraction of the samples left out: those that cannot be
    /// assembled, or do not run the cycle as the nominal design does.
    pub fn failed_fraction(&self) -> f64 {
        failed_fraction(&self.failures, self.samples)
    }

    /// The fraction of the samples that cannot run the cycle
    /// ([`Failure::cannot_run`]).
    pub fn cannot_run_fraction(&self) -> f64 {
        cannot_run_fraction(&self.failures, self.samples)
    }
}

/// The fraction of `samples` that `failures` lists.
pub(super) fn failed_fraction<T>(failures: &[T], samples: usize) -> f64 {
    failures.len() as f64 / samples as f64
}

/// The fraction of `samples` that `failures` lists as unable to run the
/// cycle.
pub(super) fn cannot_run_fraction<const M: usize, const F: usize>(
    failures: &[(usize, Failure<M, F>)],
    samples: usize,
) -> f64 {
    failures.iter().filter(|(_, why)| why.cannot_run()).count() as f64 / samples as f64
}

/// The samples analysed together (their values held before they are
/// folded, in order, into the statistics).
const CHUNK: usize = 1024;

/// Sweeps every sample of the run along the nominal design's drive and
/// gathers each output's statistics at each step, to set beside
/// [`cycle`](super::cycle)'s linear estimate. A path's deviation is
/// measured from the nominal point at the same step. The result is the
/// same on any number of threads.
pub fn monte_carlo_cycle<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    outputs: &[Output<'_, M, F, K>],
    tolerances: &Tolerances<K>,
    run: &MonteCarlo,
) -> Result<CycleSamples<M, F>, ToleranceError>
where
    L: Sensitivities<M, F, K> + Clone + Sync,
{
    monte_carlo_cycle_observed(model, u0, drive, options, outputs, tolerances, run, &|| {})
}

/// [`monte_carlo_cycle`], calling `on_sample` as each sample's sweep ends
/// (or fails), from whichever thread ran it: for a progress bar.
#[allow(clippy::too_many_arguments)]
pub fn monte_carlo_cycle_observed<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    outputs: &[Output<'_, M, F, K>],
    tolerances: &Tolerances<K>,
    run: &MonteCarlo,
    on_sample: &(dyn Fn() + Sync),
) -> Result<CycleSamples<M, F>, ToleranceError>
where
    L: Sensitivities<M, F, K> + Clone + Sync,
{
    if run.samples == 0 {
        return Err(ToleranceError::NoSamples);
    }
    let resolved = outputs
        .iter()
        .map(|o| o.resolve(model))
        .collect::<Result<Vec<_>, _>>()?;
    let sweep = model
        .sweep(u0, drive, options)
        .map_err(|error| ToleranceError::Kinematics {
            design: Design::Nominal,
            error,
        })?;
    let steps = sweep.poses.iter().map(|p| p.step + 1).max().unwrap_or(0);
    let mut nominal: Vec<Option<TolerancePose<M, F, K>>> = vec![None; steps];
    for pose in &sweep.poses {
        nominal[pose.step] = Some(TolerancePose::plain(model, &Motion::of_sweep_pose(pose)));
    }
    let mut statistics = vec![vec![Statistics::default(); steps]; outputs.len()];
    let mut failures = Vec::new();
    let indices: Vec<usize> = (0..run.samples).collect();
    for chunk in indices.chunks(CHUNK) {
        let values = batch::map(chunk, |&i| {
            let sample = run.sample(model, tolerances, i);
            let values = sample_values(
                &sample,
                u0,
                drive,
                options,
                &resolved,
                &nominal,
                sweep.events.len(),
            );
            on_sample();
            values
        });
        for (&i, values) in chunk.iter().zip(values) {
            match values {
                Ok(values) => {
                    for (k, at_step) in values.chunks(outputs.len()).enumerate() {
                        for (o, &y) in at_step.iter().enumerate() {
                            if y.is_finite() {
                                statistics[o][k].push(y);
                            }
                        }
                    }
                }
                Err(why) => failures.push((i, why)),
            }
        }
    }
    Ok(CycleSamples {
        names: outputs.iter().map(|o| o.name().to_owned()).collect(),
        v: nominal
            .iter()
            .map(|p| p.as_ref().map(|p| p.v.map(|x| x.re)))
            .collect(),
        statistics,
        samples: run.samples,
        failures,
    })
}

/// One sample's outputs at every step (`outputs` values per step, NaN
/// where it or the nominal has no pose), or why it is left out.
fn sample_values<L, const M: usize, const F: usize, const K: usize>(
    sample: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    outputs: &[Resolved<'_, M, F, K>],
    nominal: &[Option<TolerancePose<M, F, K>>],
    nominal_events: usize,
) -> Result<Vec<f64>, Failure<M, F>>
where
    L: Sensitivities<M, F, K>,
{
    let mut values = vec![f64::NAN; nominal.len() * outputs.len()];
    let mut at: Option<TolerancePose<M, F, K>> = None;
    let summary = sample
        .sweep_each(u0, drive, options, |pose| {
            let Some(Some(reference)) = nominal.get(pose.step) else {
                return;
            };
            // One pose's memory for the whole sweep.
            let motion = Motion::of_sweep_pose(pose);
            let at = match &mut at {
                Some(at) => {
                    at.set_plain(sample, &motion);
                    at
                }
                None => at.insert(TolerancePose::plain(sample, &motion)),
            };
            for (o, output) in outputs.iter().enumerate() {
                values[pose.step * outputs.len() + o] = output.at(at, reference).re;
            }
        })
        .map_err(Failure::Kinematics)?;
    if !summary.complete || summary.events.len() != nominal_events {
        return Err(Failure::Singular(summary.events.into_iter().next()));
    }
    Ok(values)
}

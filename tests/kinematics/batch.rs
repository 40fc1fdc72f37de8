//! Batches: the same results as one job at a time, to the bit, in the jobs'
//! order, on any number of threads; a job that fails fails alone.

use crate::common::{FourBar, OMEGA2};
use linkage::batch::{self, AnalysisJob, SweepJob};
use linkage::prelude::*;
use std::f64::consts::TAU;

/// Four-bars with couplers of 40 … 59, and one (index 7) whose crank is
/// longer than the others together: it cannot be assembled anywhere.
fn designs() -> Vec<FourBar> {
    (0..20)
        .map(|k| {
            let mut bar = FourBar {
                l3: 40.0 + k as f64,
                ..FourBar::WORKSHEET
            };
            if k == 7 {
                bar.l2 = 500.0;
            }
            bar
        })
        .collect()
}

fn jobs() -> Vec<SweepJob<FourBar, 2, 1>> {
    designs()
        .into_iter()
        .map(|model| SweepJob {
            model,
            u0: vector![1.2, -0.8],
            drive: Drive::Line {
                from: vector![0.0],
                to: vector![TAU],
                steps: 720,
            },
        })
        .collect()
}

/// Per sweep: the number of poses, the largest |α4| and a checksum of every
/// coordinate, velocity and acceleration.
type Fold = (usize, f64, f64);

fn fold(acc: &mut Fold, pose: &SweepPose<2, 1>) {
    acc.0 += 1;
    acc.1 = acc.1.max(pose.uddot[1].abs());
    acc.2 += pose.u.sum() + pose.udot.sum() + pose.uddot.sum();
}

fn sweep_options() -> SweepOptions {
    SweepOptions {
        speed: OMEGA2,
        ..SweepOptions::default()
    }
}

#[test]
fn batch_sweeps_equal_single_sweeps_on_any_number_of_threads() {
    let jobs = jobs();
    let options = sweep_options();
    let alone: Vec<Result<Fold, Error>> = jobs
        .iter()
        .map(|job| {
            let mut acc = (0, 0.0, 0.0);
            job.model
                .sweep_each(&job.u0, &job.drive, &options, |p| fold(&mut acc, p))
                .map(|_| acc)
        })
        .collect();
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let batch = pool.install(|| batch::sweeps(&jobs, &options, |_| (0, 0.0, 0.0), fold));
        assert_eq!(batch.len(), jobs.len());
        for (k, (b, a)) in batch.iter().zip(&alone).enumerate() {
            match (b, a) {
                (Ok(b), Ok(a)) => {
                    // To the bit, and in order.
                    assert_eq!(b.value, *a, "job {k} on {threads} threads");
                    assert!(b.summary.complete && b.summary.poses == 721);
                }
                (Err(b), Err(a)) => assert_eq!(b, a),
                _ => panic!("job {k}: batch {b:?}, alone {a:?}"),
            }
        }
    }
}

#[test]
fn a_design_that_cannot_be_assembled_fails_alone() {
    // Damped Newton tells "no solution" from "not converged".
    let mut options = sweep_options();
    options.options.damped = true;
    let batch = batch::sweeps(&jobs(), &options, |_| (0, 0.0, 0.0), fold);
    for (k, result) in batch.iter().enumerate() {
        if k == 7 {
            assert!(
                matches!(result, Err(Error::CannotAssemble { .. })),
                "{result:?}"
            );
        } else {
            let swept = result.as_ref().expect("the others assemble");
            assert!(swept.value.1 > 0.0);
        }
    }
}

#[test]
fn init_receives_the_job_index() {
    let batch = batch::sweeps(&jobs(), &sweep_options(), |k| vec![k], |_, _| {});
    assert_eq!(batch.len(), jobs().len());
    for (k, result) in batch.iter().enumerate() {
        match result {
            Ok(swept) => assert_eq!(swept.value, vec![k]),
            // The one design that cannot be assembled (undamped Newton
            // does not converge there).
            Err(e) => assert_eq!(k, 7, "{e:?}"),
        }
    }
}

#[test]
fn batch_analyses_equal_single_analyses() {
    let jobs: Vec<AnalysisJob<FourBar, 2, 1>> = designs()
        .into_iter()
        .enumerate()
        .map(|(k, model)| AnalysisJob {
            model,
            u_guess: vector![1.2, -0.8],
            v: vector![(10.0 * k as f64).to_radians()],
            vdot: vector![OMEGA2],
            vddot: vector![5.0],
        })
        .collect();
    let options = Options::default();
    let batch = batch::analyses(&jobs, &options);
    for (job, result) in jobs.iter().zip(&batch) {
        let alone = job
            .model
            .analyze(&job.u_guess, &job.v, &job.vdot, &job.vddot, &options);
        assert_eq!(result, &alone);
    }
    assert!(batch[7].is_err() && batch[0].is_ok());
}

/// Sensitivities in a batch: each job's equal, to the bit, what the same
/// design gives alone; the design that cannot be assembled fails alone.
#[test]
fn batch_sensitivities_equal_single_ones() {
    let designs = designs();
    let sweeps = batch::sweeps_with_sensitivities(
        &jobs(),
        &sweep_options(),
        |_| (0usize, 0.0f64),
        |acc, _pose, s| {
            if let Ok(s) = s {
                acc.0 += 1;
                acc.1 += s.u.sum() + s.udot.sum() + s.uddot.sum();
            }
        },
    );
    for (k, (result, model)) in sweeps.iter().zip(&designs).enumerate() {
        if k == 7 {
            assert!(result.is_err());
            continue;
        }
        let job = &jobs()[k];
        let mut alone = (0usize, 0.0f64);
        model
            .sweep_sensitivities_each(&job.u0, &job.drive, &sweep_options(), |_, s| {
                if let Ok(s) = s {
                    alone.0 += 1;
                    alone.1 += s.u.sum() + s.udot.sum() + s.uddot.sum();
                }
            })
            .unwrap();
        let value = &result.as_ref().unwrap().value;
        assert!(
            value.0 > 700,
            "design {k}: {} poses with sensitivities",
            value.0
        );
        assert_eq!(value.0, alone.0);
        assert_eq!(value.1.to_bits(), alone.1.to_bits());
    }
    let jobs: Vec<AnalysisJob<FourBar, 2, 1>> = designs
        .iter()
        .map(|&model| AnalysisJob {
            model,
            u_guess: vector![1.2, -0.8],
            v: vector![0.4],
            vdot: vector![OMEGA2],
            vddot: vector![1.0],
        })
        .collect();
    let options = Options::damped();
    for (k, result) in batch::analyses_with_sensitivities(&jobs, &options)
        .into_iter()
        .enumerate()
    {
        if k == 7 {
            assert!(result.is_err());
            continue;
        }
        let (analysis, s) = result.unwrap();
        let job = &jobs[k];
        let motion = Motion::of_analysis(&analysis);
        assert_eq!(s, job.model.sensitivities(&motion, &options).unwrap());
    }
}

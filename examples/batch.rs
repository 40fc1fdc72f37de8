//! A design study as a batch: 2 000 four-bar crank-rockers (coupler and
//! rocker lengths on a grid), each swept over a revolution of the crank in
//! 3 600 steps at ω2 = 400 rpm, each reduced to its smallest transmission
//! angle and the largest angular acceleration of its rocker. Timed on one
//! thread and on every core, and written to `out/batch/batch.csv`.
//!
//!     cargo run --release --example batch

use linkage::batch::{self, SweepJob};
use linkage::mechanisms::BareFourBar;
use linkage::prelude::*;
use std::f64::consts::TAU;

#[path = "support/output.rs"]
mod output;
use std::time::Instant;

const STEPS: usize = 3600;
const OMEGA2: f64 = 400.0 * TAU / 60.0;

/// The smallest transmission angle (deg) and the largest |α4| (rad/s²).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Merit {
    min_transmission: f64,
    max_alpha4: f64,
}

impl Merit {
    /// Before the first pose.
    fn new() -> Merit {
        Merit {
            min_transmission: 180.0,
            max_alpha4: 0.0,
        }
    }

    /// Folds one pose in: the transmission angle between coupler and
    /// rocker, and the rocker's angular acceleration.
    fn add(&mut self, pose: &SweepPose<2, 1>) {
        let mu = (pose.u[0] - pose.u[1]).sin().abs().asin().to_degrees();
        self.min_transmission = self.min_transmission.min(mu);
        self.max_alpha4 = self.max_alpha4.max(pose.uddot[1].abs());
    }
}

fn jobs() -> Vec<SweepJob<BareFourBar, 2, 1>> {
    let mut jobs = Vec::new();
    for i in 0..40 {
        for j in 0..50 {
            let model = BareFourBar {
                l1: 80.0,
                l2: 20.0,
                l3: 45.0 + 0.5 * i as f64,
                l4: 55.0 + 0.5 * j as f64,
            };
            // The open branch at θ2 = 0, from the closed form.
            let start = model
                .closed_form()
                .position(0.0, 1.0)
                .expect("a crank-rocker assembles at θ2 = 0");
            jobs.push(SweepJob {
                model,
                u0: vector![start[0], start[1]],
                drive: Drive::Line {
                    from: vector![0.0],
                    to: vector![TAU],
                    steps: STEPS,
                },
            });
        }
    }
    jobs
}

fn run(jobs: &[SweepJob<BareFourBar, 2, 1>], options: &SweepOptions) -> Vec<Merit> {
    batch::sweeps(
        jobs,
        options,
        |_| Merit::new(),
        |merit, pose| merit.add(pose),
    )
    .into_iter()
    .map(|r| r.expect("every design sweeps").value)
    .collect()
}

/// The median of `repeats` timings of the batch on `threads` threads, in
/// seconds, and the results.
fn time(
    jobs: &[SweepJob<BareFourBar, 2, 1>],
    options: &SweepOptions,
    threads: usize,
    repeats: usize,
) -> (f64, Vec<Merit>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let mut results = Vec::new();
    let mut times: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            results = pool.install(|| run(jobs, options));
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    (times[repeats / 2], results)
}

/// The same jobs as a plain loop of `sweep_each` calls on this thread,
/// with the same work per pose, without the batch: the cost the batch
/// machinery is measured against (median of `repeats`, seconds), and the
/// results.
fn time_plain_loop(
    jobs: &[SweepJob<BareFourBar, 2, 1>],
    options: &SweepOptions,
    repeats: usize,
) -> (f64, Vec<Merit>) {
    let mut results = Vec::new();
    let mut times: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let mut merits = Vec::with_capacity(jobs.len());
            for job in jobs {
                let mut merit = Merit::new();
                job.model
                    .sweep_each(&job.u0, &job.drive, options, |pose| merit.add(pose))
                    .expect("every design sweeps");
                merits.push(merit);
            }
            let elapsed = start.elapsed().as_secs_f64();
            results = merits;
            elapsed
        })
        .collect();
    times.sort_by(f64::total_cmp);
    (times[repeats / 2], results)
}

fn main() -> std::io::Result<()> {
    let jobs = jobs();
    let options = SweepOptions {
        speed: OMEGA2,
        ..SweepOptions::default()
    };
    let poses = jobs.len() * (STEPS + 1);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (one, serial) = time(&jobs, &options, 1, 5);
    let (all, parallel) = time(&jobs, &options, cores, 5);
    let (plain, looped) = time_plain_loop(&jobs, &options, 5);
    assert_eq!(serial, looped, "the batch gives what the plain loop gives");
    assert_eq!(
        serial, parallel,
        "the same results on any number of threads"
    );
    let best = serial
        .iter()
        .zip(&jobs)
        .max_by(|a, b| a.0.min_transmission.total_cmp(&b.0.min_transmission))
        .expect("designs");
    println!(
        "{} designs × {} poses = {poses} poses",
        jobs.len(),
        STEPS + 1
    );
    println!("| threads | seconds | ns / pose | speed-up |");
    println!("|---:|---:|---:|---:|");
    for (threads, seconds) in [(1, one), (cores, all)] {
        println!(
            "| {threads} | {seconds:.3} | {:.1} | {:.2}× |",
            seconds * 1e9 / poses as f64,
            one / seconds
        );
    }
    println!(
        "| plain loop of sweep_each, 1 | {plain:.3} | {:.1} | {:.2}× |",
        plain * 1e9 / poses as f64,
        one / plain
    );
    println!(
        "\nbest transmission: l3 = {}, l4 = {}: μ_min = {:.2}°, max |α4| = {:.0} rad/s²",
        best.1.model.l3, best.1.model.l4, best.0.min_transmission, best.0.max_alpha4
    );
    let path = output::folder("batch")?.join("batch.csv");
    std::fs::write(
        &path,
        format!(
            "# Written by `cargo run --release --example batch`: {} four-bar designs, {} poses each, median of 5 runs.\n\
             threads,seconds,ns_per_pose,speedup\n1,{one:.4},{:.2},1.00\n{cores},{all:.4},{:.2},{:.2}\nplain loop,{plain:.4},{:.2},{:.2}\n",
            jobs.len(),
            STEPS + 1,
            one * 1e9 / poses as f64,
            all * 1e9 / poses as f64,
            one / all,
            plain * 1e9 / poses as f64,
            one / plain
        ),
    )?;
    println!("wrote {}", path.display());
    Ok(())
}

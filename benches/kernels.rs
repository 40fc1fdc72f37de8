//! Criterion benchmarks of the generated code and the runtime, for the
//! three benchmark mechanisms (the worksheet's four-bar, the offset slider-crank,
//! the two-loop six-bar): Ψ, Ψ_u and γ evaluations, one Newton step, the
//! fused kernel, a whole analysis, and a sweep over a revolution.
//!
//!     cargo bench --bench kernels            # all
//!     cargo bench --bench kernels -- four-bar  # one mechanism
//!
//! The sweep reports its time per pose (criterion's throughput in
//! elements). The speed-versus-accuracy comparison with the other methods
//! and the peers is the `speed_accuracy` example.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use linkage::prelude::*;
use std::hint::black_box;
use std::time::Duration;

#[path = "../examples/speed_accuracy/workloads.rs"]
mod workloads;
use workloads::{FOUR_BAR, SIX_BAR, SLIDER_CRANK};

/// Poses of the benchmarked sweep: one revolution of the crank.
const SWEEP_STEPS: usize = 10_000;

/// A converged pose at θ2 = 20° (from a sweep, so on the benchmarks'
/// branch) with its velocities.
fn pose<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    u0: SVector<f64, M>,
) -> (SVector<f64, M>, SVector<f64, 1>, SVector<f64, M>) {
    let v = vector![20f64.to_radians()];
    let drive = Drive::Line {
        from: vector![0.0],
        to: v,
        steps: 200,
    };
    let sweep = model
        .sweep(&u0, &drive, &SweepOptions::default())
        .expect("the benchmark mechanisms sweep");
    let last = sweep.poses.last().expect("poses");
    (last.u, v, last.udot)
}

/// The benchmarks of one mechanism; `u0` starts the sweeps near θ2 = 0,
/// `cold` is the rough guess of the cold analysis at θ2 = 20°.
fn mechanism<L: Linkage<M, 1>, const M: usize>(
    c: &mut Criterion,
    name: &str,
    model: &L,
    u0: SVector<f64, M>,
    cold: SVector<f64, M>,
) {
    let (u, v, udot) = pose(model, u0);
    let vdot = vector![1.0];
    let vddot = vector![0.0];
    let options = Options::default();
    let mut group = c.benchmark_group(name);
    group.bench_function("psi", |b| {
        b.iter(|| model.psi(black_box(&u), black_box(&v)))
    });
    group.bench_function("psi_u", |b| {
        b.iter(|| model.psi_u(black_box(&u), black_box(&v)))
    });
    group.bench_function("gamma", |b| {
        b.iter(|| model.gamma(black_box(&u), black_box(&v), black_box(&udot), &vdot))
    });
    // One Newton–Raphson step from a guess 10⁻³ off: Ψ and Ψ_u in one
    // pass, the inverse (closed form for m ≤ 3), the update.
    let guess = u.add_scalar(1e-3);
    group.bench_function("newton_step", |b| {
        b.iter(|| {
            let (psi, psi_u) = model.psi_and_psi_u(black_box(&guess), black_box(&v));
            let inverse = linkage::invert(&psi_u);
            guess - inverse.inverse * psi
        })
    });
    group.bench_function("kinematics (fused kernel)", |b| {
        b.iter(|| model.kinematics(black_box(&u), black_box(&v), &vdot, &vddot))
    });
    // The whole analysis of one pose, warm (from the converged pose: one
    // Newton step confirms it) and cold (from a rough guess).
    group.bench_function("analyze warm", |b| {
        b.iter(|| {
            model
                .analyze(black_box(&u), black_box(&v), &vdot, &vddot, &options)
                .expect("regular pose")
        })
    });
    group.bench_function("analyze cold", |b| {
        b.iter(|| {
            model
                .analyze(black_box(&cold), black_box(&v), &vdot, &vddot, &options)
                .expect("regular pose")
        })
    });
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: SWEEP_STEPS,
    };
    let sweep_options = SweepOptions::default();
    group.throughput(Throughput::Elements(SWEEP_STEPS as u64 + 1));
    group.bench_function(BenchmarkId::new("sweep", SWEEP_STEPS), |b| {
        b.iter(|| {
            let mut checksum = 0.0;
            model
                .sweep_each(black_box(&u0), &drive, &sweep_options, |p| {
                    checksum += p.uddot[0]
                })
                .expect("the revolution sweeps");
            checksum
        })
    });
    // The dense grid of the speed table (workloads::N samples per
    // revolution), over a tenth of a revolution: one fused evaluation per
    // pose.
    let dense = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU / 10.0],
        steps: workloads::N / 10,
    };
    group.throughput(Throughput::Elements(workloads::N as u64 / 10 + 1));
    group.bench_function("sweep dense", |b| {
        b.iter(|| {
            let mut checksum = 0.0;
            model
                .sweep_each(black_box(&u0), &dense, &sweep_options, |p| {
                    checksum += p.uddot[0]
                })
                .expect("the dense sweep runs");
            checksum
        })
    });
    group.finish();
}

fn benches(c: &mut Criterion) {
    let four_bar = linkage::closed_form::FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    }
    .position(0.0, 1.0)
    .expect("assembles");
    // The cold guess is the README's (θ3, θ4) = (70°, −50°).
    mechanism(
        c,
        "four-bar",
        &FOUR_BAR,
        vector![four_bar[0], four_bar[1]],
        vector![70f64.to_radians(), -50f64.to_radians()],
    );
    // Near the starts of the reference data (tests/data/bench_*.csv, k = 0).
    mechanism(
        c,
        "slider-crank",
        &SLIDER_CRANK,
        vector![0.050_020_857, 0.249_749_844],
        vector![0.0, 0.25],
    );
    mechanism(
        c,
        "six-bar",
        &SIX_BAR,
        vector![1.369_438_4, -0.775_193_4, 2.237_243_8, -3.043_485_2],
        vector![1.2, -0.7, 2.1, -3.0],
    );
}

criterion_group! {
    name = kernels;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30);
    targets = benches
}
criterion_main!(kernels);

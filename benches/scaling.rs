//! How the cost grows with the size of the mechanism: compiled chains of
//! N = 1, 2, 4, 8, 16 and 32 four-bar loops (m = 2N, `benches/chains/`),
//! each at the pose θ2 = 20°: the fused kernel, `analyze` warm, the
//! sensitivities to the seven parameters at that analysis, and a sweep
//! over a revolution in 10 000 steps (its time per pose as criterion's
//! throughput in elements). Linear cost doubles the time with N.
//!
//!     cargo bench --bench scaling
//!     cargo bench --bench scaling -- "N = 32"

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use linkage::prelude::*;
use std::hint::black_box;

#[path = "chains/mod.rs"]
mod chains;
#[path = "chains/n1.rs"]
mod n1;
#[path = "chains/n16.rs"]
mod n16;
#[path = "chains/n2.rs"]
mod n2;
#[path = "chains/n32.rs"]
mod n32;
#[path = "chains/n4.rs"]
mod n4;
#[path = "chains/n8.rs"]
mod n8;

/// Poses of the benchmarked sweeps: one revolution of the crank.
const SWEEP_STEPS: usize = 10_000;

/// The rows of one chain.
fn rows<L: Sensitivities<M, 1, K>, const M: usize, const K: usize>(
    c: &mut Criterion,
    n: usize,
    model: &L,
) {
    let u0 = chains::chain_pose::<M>(0.0);
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: SWEEP_STEPS,
    };
    let sweep_options = SweepOptions::default();
    let v = vector![20f64.to_radians()];
    let u = chains::chain_pose::<M>(v[0]);
    let (vdot, vddot) = (vector![1.0], vector![0.0]);
    let options = Options::default();
    let analysis = model
        .analyze(&u, &v, &vdot, &vddot, &options)
        .expect("the chain assembles at 20°");
    let mut group = c.benchmark_group(format!("chain N = {n}"));
    if n >= 16 {
        group.sample_size(20);
    }
    group.bench_function(BenchmarkId::new("kinematics", M), |b| {
        b.iter(|| model.kinematics(black_box(&analysis.u), black_box(&v), &vdot, &vddot))
    });
    group.bench_function(BenchmarkId::new("analyze warm", M), |b| {
        b.iter(|| {
            model
                .analyze(
                    black_box(&analysis.u),
                    black_box(&v),
                    &vdot,
                    &vddot,
                    &options,
                )
                .expect("regular pose")
        })
    });
    group.bench_function(BenchmarkId::new("sensitivities_of", M), |b| {
        b.iter(|| {
            model
                .sensitivities_of(black_box(&analysis), &options)
                .expect("regular pose")
        })
    });
    group.throughput(Throughput::Elements(SWEEP_STEPS as u64 + 1));
    group.bench_function(BenchmarkId::new("sweep 10000", M), |b| {
        b.iter(|| {
            model
                .sweep(black_box(&u0), &drive, &sweep_options)
                .expect("the revolution sweeps")
        })
    });
    group.finish();
}

fn scaling(c: &mut Criterion) {
    for (n, source) in [
        (1, include_str!("chains/n1.rs")),
        (2, include_str!("chains/n2.rs")),
        (4, include_str!("chains/n4.rs")),
        (8, include_str!("chains/n8.rs")),
        (16, include_str!("chains/n16.rs")),
        (32, include_str!("chains/n32.rs")),
    ] {
        chains::check_compiled(source, n);
    }
    rows::<_, 2, 6>(c, 1, &chain!(n1));
    rows::<_, 4, 7>(c, 2, &chain!(n2));
    rows::<_, 8, 7>(c, 4, &chain!(n4));
    rows::<_, 16, 7>(c, 8, &chain!(n8));
    rows::<_, 32, 7>(c, 16, &chain!(n16));
    rows::<_, 64, 7>(c, 32, &chain!(n32));
}

criterion_group!(benches, scaling);
criterion_main!(benches);

//! Criterion benchmarks of run-time mechanisms against compiled ones: each
//! benchmark mechanism (the worksheet's four-bar, the offset slider-crank,
//! the two-loop six-bar, and a chain of 32 four-bar loops) compiled by the
//! attribute and read at run time from the same attribute text with the
//! same parameter values ([`linkage::mechanism::Mechanism::from_text`],
//! seen at its sizes with `fixed`), side by side in one group, compiled
//! then run-time for each row: Ψ and Ψ_u in one pass, the fused kernel, a
//! whole analysis at one pose (warm), and a sweep over a revolution (its
//! time per pose as criterion's throughput in elements). Then the time
//! from text to a ready mechanism (read, lowered, differentiated, every
//! tape built) for the four-bar and chains of N = 1 … 32 loops, and its
//! two stages apart (`text::build`, `Tapes::build`).
//!
//!     cargo bench --bench run_time               # all
//!     cargo bench --bench run_time -- four-bar   # one mechanism
//!     cargo bench --bench run_time -- from_text  # text to a ready mechanism

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use linkage::mechanism::{Fixed, Mechanism};
use linkage::prelude::*;
use linkage_symbolic::plan::Kernel;
use linkage_symbolic::tape::{self, Tapes};
use linkage_symbolic::text::{self, Equations, Parameter};
use std::hint::black_box;
use std::time::Duration;

#[path = "../examples/speed_accuracy/workloads.rs"]
mod workloads;
use workloads::{FOUR_BAR, SIX_BAR, SLIDER_CRANK};

#[path = "chains/mod.rs"]
mod chains;
#[path = "chains/n32.rs"]
mod n32;
use chains::{attribute_of, chain_pose, chain_text};

/// Poses of the benchmarked sweeps: one revolution of the crank.
const SWEEP_STEPS: usize = 10_000;

/// A compiled mechanism's attribute text read at run time, with the
/// compiled mechanism's parameter values.
fn read<L, const M: usize, const K: usize>(compiled: &L, source: &str, name: &str) -> Mechanism
where
    L: Sensitivities<M, 1, K>,
{
    let values = compiled.params();
    let parameters: Vec<(&str, f64)> = (compiled.param_names().iter().copied())
        .zip(values.iter().copied())
        .collect();
    Mechanism::from_text(name, &attribute_of(source, name), &parameters)
        .unwrap_or_else(|e| panic!("{name} reads at run time: {e}"))
}

/// The run-time twin of a compiled mechanism ([`read`]), seen with room
/// for `P` named points (as many as it has: an analysis copies them).
fn twin<L, const M: usize, const K: usize, const P: usize>(
    compiled: &L,
    source: &str,
    name: &str,
) -> Fixed<M, 1, P>
where
    L: Sensitivities<M, 1, K>,
{
    read(compiled, source, name)
        .fixed_with::<M, 1, P>()
        .expect("the compiled sizes")
}

/// A converged pose at θ2 = 20° (from a sweep, so on the benchmarks'
/// branch).
fn pose<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    u0: &SVector<f64, M>,
) -> (SVector<f64, M>, SVector<f64, 1>) {
    let v = vector![20f64.to_radians()];
    let drive = Drive::Line {
        from: vector![0.0],
        to: v,
        steps: 200,
    };
    let sweep = model
        .sweep(u0, &drive, &SweepOptions::default())
        .expect("the benchmark mechanisms sweep");
    (sweep.poses.last().expect("poses").u, v)
}

/// The revolution every sweep follows.
fn revolution() -> Drive<1> {
    Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: SWEEP_STEPS,
    }
}

/// The two follow the same poses, to the bit (a run-time twin runs the
/// compiled code's operations): the benchmark compares equal work.
fn same_sweep<A: Linkage<M, 1>, B: Linkage<M, 1>, const M: usize>(
    name: &str,
    compiled: &A,
    run_time: &B,
    u0: &SVector<f64, M>,
) {
    let options = SweepOptions::default();
    let a = compiled.sweep(u0, &revolution(), &options).expect("sweeps");
    let b = run_time.sweep(u0, &revolution(), &options).expect("sweeps");
    assert!(
        a.complete && b.complete,
        "{name}: the revolution is followed"
    );
    assert_eq!(a.poses.len(), b.poses.len(), "{name}: the poses");
    for (p, q) in a.poses.iter().zip(&b.poses) {
        assert!(
            p.u.iter()
                .zip(q.u.iter())
                .all(|(x, y)| x.to_bits() == y.to_bits()),
            "{name}: the twin's sweep differs at step {}",
            p.step
        );
    }
}

/// Which rows a mechanism is measured on.
#[derive(Clone, Copy, PartialEq)]
enum Rows {
    /// Every row.
    All,
    /// The analysis and the sweep.
    Analyses,
}

/// The benchmarks of one mechanism, compiled and run-time side by side;
/// `u0` starts the sweeps at θ2 = 0.
fn side_by_side<A: Linkage<M, 1>, B: Linkage<M, 1>, const M: usize>(
    c: &mut Criterion,
    name: &str,
    compiled: &A,
    run_time: &B,
    u0: SVector<f64, M>,
    rows: Rows,
) {
    let (u, v) = pose(compiled, &u0);
    let vdot = vector![1.0];
    let vddot = vector![0.0];
    let options = Options::default();
    let mut group = c.benchmark_group(name);
    if rows == Rows::Analyses {
        group.sample_size(10);
    }
    macro_rules! both {
        ($row:expr, |$model:ident| $body:expr) => {
            group.bench_function(BenchmarkId::new($row, "compiled"), |b| {
                let $model = compiled;
                b.iter(|| $body)
            });
            group.bench_function(BenchmarkId::new($row, "run-time"), |b| {
                let $model = run_time;
                b.iter(|| $body)
            });
        };
    }
    if rows == Rows::All {
        both!("psi_and_psi_u", |model| model
            .psi_and_psi_u(black_box(&u), black_box(&v)));
        both!("kinematics", |model| model.kinematics(
            black_box(&u),
            black_box(&v),
            &vdot,
            &vddot
        ));
    }
    // From the converged pose: one evaluation confirms it.
    both!("analyze warm", |model| model
        .analyze(black_box(&u), black_box(&v), &vdot, &vddot, &options)
        .expect("regular pose"));
    let drive = revolution();
    let sweep_options = SweepOptions::default();
    group.throughput(Throughput::Elements(SWEEP_STEPS as u64 + 1));
    // Checked once, where the sweeps are measured (not when a filter
    // leaves them out).
    let mut checked = false;
    group.bench_function(BenchmarkId::new("sweep 10000", "compiled"), |b| {
        if !checked {
            same_sweep(name, compiled, run_time, &u0);
            checked = true;
        }
        b.iter(|| {
            compiled
                .sweep(black_box(&u0), &drive, &sweep_options)
                .expect("the revolution sweeps")
        })
    });
    group.bench_function(BenchmarkId::new("sweep 10000", "run-time"), |b| {
        b.iter(|| {
            run_time
                .sweep(black_box(&u0), &drive, &sweep_options)
                .expect("the revolution sweeps")
        })
    });
    group.finish();
}

fn mechanisms(c: &mut Criterion) {
    let source = include_str!("../examples/speed_accuracy/workloads.rs");
    let four_bar = linkage::closed_form::FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    }
    .position(0.0, 1.0)
    .expect("assembles");
    side_by_side(
        c,
        "four-bar",
        &FOUR_BAR,
        &twin::<_, 2, 4, 0>(&FOUR_BAR, source, "FourBar"),
        vector![four_bar[0], four_bar[1]],
        Rows::All,
    );
    // The starts of kernels.rs (near the reference data's, k = 0).
    side_by_side(
        c,
        "slider-crank",
        &SLIDER_CRANK,
        &twin::<_, 2, 3, 0>(&SLIDER_CRANK, source, "SliderCrank"),
        vector![0.050_020_857, 0.249_749_844],
        Rows::All,
    );
    side_by_side(
        c,
        "six-bar",
        &SIX_BAR,
        &twin::<_, 4, 10, 2>(&SIX_BAR, source, "SixBar"),
        vector![1.369_438_4, -0.775_193_4, 2.237_243_8, -3.043_485_2],
        Rows::All,
    );
    let attribute = chains::check_compiled(include_str!("chains/n32.rs"), 32);
    let run_time = Mechanism::from_text("Chain", &attribute, &chains::PARAMETERS)
        .expect("the chain reads at run time")
        .fixed::<64, 1>()
        .expect("m = 64, f = 1");
    side_by_side(
        c,
        "chain N = 32",
        &chain!(n32),
        &run_time,
        chain_pose::<64>(0.0),
        Rows::Analyses,
    );
}

/// Poses of the batch of poses, designs of the batch of designs.
const BATCH_POSES: usize = 10_000;
const BATCH_DESIGNS: usize = 1_000;

/// Batches of analyses ([`linkage::batch::analyses`]) of the four-bar, on
/// one thread, compiled and run-time (whose Newton iterations run side by
/// side on the tapes' lanes): 10⁴ poses of one design round the turn, each
/// from the pose 0.02 rad ahead (as a batch seeded by a coarser one), and
/// 10³ designs (couplers of 45 … 55) at θ2 = 20° from the worksheet
/// design's pose; the time per analysis as throughput.
fn batches(c: &mut Criterion) {
    use linkage::batch::{self, AnalysisJob};
    let source = include_str!("../examples/speed_accuracy/workloads.rs");
    let mechanism = read(&FOUR_BAR, source, "FourBar");
    // Room for as many points as it has, none.
    let run_time = mechanism.fixed_with::<2, 1, 0>().expect("m = 2, f = 1");
    let start = linkage::closed_form::FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    }
    .position(0.0, 1.0)
    .expect("assembles");
    let turn = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: BATCH_POSES,
    };
    let sweep = FOUR_BAR
        .sweep(
            &vector![start[0], start[1]],
            &turn,
            &SweepOptions::default(),
        )
        .expect("the revolution sweeps");
    let poses = |k: usize| {
        let ahead = &sweep.poses[(k + BATCH_POSES / 314) % BATCH_POSES];
        (ahead.u, sweep.poses[k].v)
    };
    let (u20, v20) = pose(&FOUR_BAR, &vector![start[0], start[1]]);
    let couplers = |k: usize| 45.0 + 10.0 * k as f64 / BATCH_DESIGNS as f64;
    fn job<L>(model: L, (u_guess, v): (SVector<f64, 2>, SVector<f64, 1>)) -> AnalysisJob<L, 2, 1> {
        AnalysisJob {
            model,
            u_guess,
            v,
            vdot: vector![1.0],
            vddot: vector![0.0],
        }
    }
    let compiled_poses: Vec<_> = (0..BATCH_POSES).map(|k| job(FOUR_BAR, poses(k))).collect();
    let run_time_poses: Vec<_> = (0..BATCH_POSES)
        .map(|k| job(run_time.clone(), poses(k)))
        .collect();
    let compiled_designs: Vec<_> = (0..BATCH_DESIGNS)
        .map(|k| {
            let mut design = FOUR_BAR;
            design.l3 = couplers(k);
            job(design, (u20, v20))
        })
        .collect();
    let run_time_designs: Vec<_> = (0..BATCH_DESIGNS)
        .map(|k| {
            let mut design = mechanism.clone();
            design.set_parameter("l3", couplers(k)).expect("l3");
            job(
                design.fixed_with::<2, 1, 0>().expect("m = 2, f = 1"),
                (u20, v20),
            )
        })
        .collect();
    let options = Options::default();
    // The same analyses, to the bit.
    let agree = |a: Vec<Result<Analysis<2, 1, _>, _>>, b: Vec<Result<Analysis<2, 1, _>, _>>| {
        for (a, b) in a.iter().zip(&b) {
            let (a, b) = (
                a.as_ref().expect("assembles"),
                b.as_ref().expect("assembles"),
            );
            assert_eq!((a.u, a.uddot), (b.u, b.uddot), "the twins' batches agree");
        }
    };
    agree(
        batch::analyses(&compiled_poses, &options),
        batch::analyses(&run_time_poses, &options),
    );
    agree(
        batch::analyses(&compiled_designs, &options),
        batch::analyses(&run_time_designs, &options),
    );
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a pool of one thread");
    let mut group = c.benchmark_group("four-bar batch");
    group.sample_size(10);
    group.throughput(Throughput::Elements(BATCH_POSES as u64));
    group.bench_function(BenchmarkId::new("poses 10000", "compiled"), |b| {
        b.iter(|| one_thread.install(|| batch::analyses(black_box(&compiled_poses), &options)))
    });
    group.bench_function(BenchmarkId::new("poses 10000", "run-time"), |b| {
        b.iter(|| one_thread.install(|| batch::analyses(black_box(&run_time_poses), &options)))
    });
    group.throughput(Throughput::Elements(BATCH_DESIGNS as u64));
    group.bench_function(BenchmarkId::new("designs 1000", "compiled"), |b| {
        b.iter(|| one_thread.install(|| batch::analyses(black_box(&compiled_designs), &options)))
    });
    group.bench_function(BenchmarkId::new("designs 1000", "run-time"), |b| {
        b.iter(|| one_thread.install(|| batch::analyses(black_box(&run_time_designs), &options)))
    });
    group.finish();
}

/// From text to a ready mechanism: the four-bar (the attribute of
/// `linkage::mechanisms::FourBar`, points and all) and chains of N loops.
fn from_text(c: &mut Criterion) {
    let four_bar = attribute_of(include_str!("../src/mechanisms.rs"), "FourBar");
    let four_bar_parameters = [("l1", 80.0), ("l2", 20.0), ("l3", 50.0), ("l4", 70.0)];
    let texts: Vec<(usize, String)> = [1, 2, 4, 8, 16, 32]
        .into_iter()
        .map(|n| (n, chain_text(n)))
        .collect();
    let mut group = c.benchmark_group("from_text");
    group.sampling_mode(criterion::SamplingMode::Flat);
    group.bench_function("four-bar (worksheet)", |b| {
        b.iter(|| {
            Mechanism::from_text("FourBar", black_box(&four_bar), &four_bar_parameters)
                .expect("reads")
        })
    });
    for (n, text) in &texts {
        if *n >= 8 {
            group.sample_size(10);
        }
        group.bench_function(BenchmarkId::new("chain", n), |b| {
            b.iter(|| {
                Mechanism::from_text("Chain", black_box(text), &chains::PARAMETERS).expect("reads")
            })
        });
    }
    group.finish();

    // The two stages apart: read, lowered and differentiated
    // (`text::build`), then every kernel's tape (`Tapes::build`).
    let mut group = c.benchmark_group("from_text stages");
    group.sampling_mode(criterion::SamplingMode::Flat);
    let names = |list: &[(&'static str, f64)]| -> Vec<Parameter<'static>> {
        list.iter().map(|(n, _)| Parameter::new(n)).collect()
    };
    let cases = [
        (
            "four-bar (worksheet)",
            four_bar.clone(),
            names(&four_bar_parameters),
        ),
        ("chain 32", texts[5].1.clone(), names(&chains::PARAMETERS)),
    ];
    for (what, text, parameters) in &cases {
        if what.starts_with("chain") {
            group.sample_size(10);
        }
        group.bench_function(BenchmarkId::new("text::build", what), |b| {
            b.iter(|| text::build("M", Equations::new(black_box(text)), parameters).is_ok())
        });
        let built = text::build("M", Equations::new(text), parameters)
            .unwrap_or_else(|_| panic!("{what} builds"));
        group.bench_function(BenchmarkId::new("Tapes::build", what), |b| {
            b.iter(|| Tapes::build(black_box(&built.derivatives)).is_ok())
        });
    }
    group.finish();

    // `Tapes::build` kernel by kernel (`tape::compile`), with each tape's
    // length: where the second stage spends its time.
    let mut group = c.benchmark_group("from_text kernels");
    group.sampling_mode(criterion::SamplingMode::Flat);
    group.warm_up_time(Duration::from_millis(200));
    group.measurement_time(Duration::from_millis(500));
    group.sample_size(10);
    for (what, text, parameters) in &cases {
        let built = text::build("M", Equations::new(text), parameters)
            .unwrap_or_else(|_| panic!("{what} builds"));
        for kernel in Kernel::every() {
            let ops = tape::compile(&built.derivatives, kernel)
                .map(|t| t.len())
                .unwrap_or(0);
            let id = format!("{what}/{} ({ops} ops)", kernel.name());
            group.bench_function(id, |b| {
                b.iter(|| tape::compile(black_box(&built.derivatives), kernel).is_ok())
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = run_time;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30);
    targets = mechanisms, batches, from_text
}
criterion_main!(run_time);

//! Speed against accuracy: every method over a full revolution of the dense
//! sweep (N = 1 008 000 samples; positions, velocities and accelerations),
//! timed per sample, its errors measured against the 50-digit reference.
//!
//! ```sh
//! cargo run --release --example speed_accuracy             # measure ours, then chart
//! cargo run --release --example speed_accuracy -- --chart  # chart the CSVs only
//! ```
//!
//! It reads the peers' results (`benches/results/peers.csv`, written by
//! `benches/peers/run.sh`), prints the table and writes `ours.csv` and
//! `speed_accuracy.svg` to `out/speed_accuracy/`; `--chart` draws the
//! committed `benches/results/ours.csv` without measuring.

#[path = "../support/output.rs"]
mod output;
mod workloads;

use linkage::closed_form;
use linkage::draw::chart::{Chart, Colour, Dash, Marker, Panel};
use linkage::prelude::*;
use std::path::Path;
use std::time::Instant;
use workloads::{FOUR_BAR, N, OMEGA2, Reference, SIX_BAR, SLIDER_CRANK, STRIDE, errors, theta2};

/// One measured method on one workload.
#[derive(Clone, Debug)]
struct Result {
    workload: String,
    method: String,
    /// Median nanoseconds per sample.
    ns: f64,
    /// Worst relative errors of positions, velocities, accelerations.
    errors: [f64; 3],
    samples: usize,
}

/// Times `run` (which processes `samples` samples and returns a checksum):
/// the median of `repeats` runs, in ns per sample.
fn time(samples: usize, repeats: usize, mut run: impl FnMut() -> f64) -> f64 {
    let mut times: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            std::hint::black_box(run());
            start.elapsed().as_secs_f64() * 1e9 / samples as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

type Sample<const M: usize> = ([f64; M], [f64; M], [f64; M]);

fn sample<const M: usize>(
    u: &SVector<f64, M>,
    udot: &SVector<f64, M>,
    uddot: &SVector<f64, M>,
) -> Sample<M> {
    (
        std::array::from_fn(|i| u[i]),
        std::array::from_fn(|i| udot[i]),
        std::array::from_fn(|i| uddot[i]),
    )
}

/// The library's sweep over the revolution: the generated code through the
/// public API, or with another source of derivatives.
#[allow(clippy::too_many_arguments)]
fn sweep_method<L: Linkage<M, 1>, const M: usize>(
    workload: &str,
    method: &str,
    model: &L,
    u0: SVector<f64, M>,
    speed: f64,
    jacobian: JacobianSource,
    reference: &Reference<M>,
    repeats: usize,
) -> Result {
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: N,
    };
    let options = SweepOptions {
        speed,
        options: Options {
            jacobian,
            ..Options::default()
        },
        ..SweepOptions::default()
    };
    let mut at_reference = Vec::new();
    let summary = model
        .sweep_each(&u0, &drive, &options, |p| {
            if p.step % STRIDE == 0 && p.step < N {
                at_reference.push(sample(&p.u, &p.udot, &p.uddot));
            }
        })
        .expect("the sweep runs");
    assert!(
        summary.complete && summary.poses == N + 1,
        "{workload} {method}: {summary:?}"
    );
    let ns = time(N + 1, repeats, || {
        let mut checksum = 0.0;
        model
            .sweep_each(&u0, &drive, &options, |p| checksum += p.uddot[0])
            .expect("the sweep runs");
        checksum
    });
    Result {
        workload: workload.into(),
        method: method.into(),
        ns,
        errors: errors(reference, &at_reference),
        samples: N + 1,
    }
}

/// `analyze` at every sample, Newton warm-started from the previous pose
/// (no predictor), stopping when the step falls below `step_tol`.
fn tolerance_method(
    step_tol: f64,
    label: &str,
    reference: &Reference<2>,
    u0: SVector<f64, 2>,
) -> Result {
    let options = Options {
        step_tol,
        residual_tol: 1e-3,
        ..Options::default()
    };
    let run = |record: &mut Vec<Sample<2>>| {
        let mut u = u0;
        let mut checksum = 0.0;
        for k in 0..N {
            let a = FOUR_BAR
                .analyze(
                    &u,
                    &vector![theta2(k)],
                    &vector![OMEGA2],
                    &vector![0.0],
                    &options,
                )
                .expect("analysis");
            u = a.u;
            checksum += a.uddot[0];
            if k % STRIDE == 0 {
                record.push(sample(&a.u, &a.udot, &a.uddot));
            }
        }
        checksum
    };
    let mut at_reference = Vec::new();
    run(&mut at_reference);
    let ns = time(N, 3, || run(&mut Vec::with_capacity(N / STRIDE + 1)));
    Result {
        workload: "four-bar".into(),
        method: format!("Newton per sample, step tol {label}"),
        ns,
        errors: errors(reference, &at_reference),
        samples: N,
    }
}

/// The closed form over the dense revolution as a careful hand-writer
/// would sweep it: sin θ2 and cos θ2 carried from an anchor by the
/// angle-addition formulas (|δ| ≤ 2⁻¹⁰, the series to δ⁵; re-anchored by
/// `sin_cos` beyond), [`closed_form::FourBar::directions_from_crank`] for
/// the rest, and θ3, θ4 followed from an anchor direction by the small
/// angle between the two (the series of atan; re-anchored by `atan2`
/// beyond 2⁻¹⁰). Per sample a hypot, a square root, five divisions and,
/// but at the anchors, no sine, cosine or arctangent.
fn closed_form_sweep(cf: &closed_form::FourBar, mut on_sample: impl FnMut(usize, &Sample<2>)) {
    const RANGE: f64 = 1.0 / 1024.0;
    let (mut anchor2, mut trig2) = (f64::NAN, (0.0_f64, 1.0_f64));
    // Per output angle: the anchor angle and its direction.
    let mut anchors = [(f64::NAN, nalgebra::Vector2::new(1.0, 0.0)); 2];
    for k in 0..=N {
        let t = theta2(k);
        let mut d = t - anchor2;
        let near = d.abs() <= RANGE; // false before the first anchor (NaN)
        if !near {
            anchor2 = t;
            trig2 = t.sin_cos();
            d = 0.0;
        }
        let d2 = d * d;
        let sin_d = d + d * d2 * (-1.0 / 6.0 + d2 / 120.0);
        let cos_d_minus_1 = d2 * (-0.5 + d2 / 24.0);
        let (s, c) = trig2;
        let crank = (
            s + (s * cos_d_minus_1 + c * sin_d),
            c + (c * cos_d_minus_1 - s * sin_d),
        );
        let state = cf
            .directions_from_crank(crank, OMEGA2, 0.0, 1.0)
            .expect("assembled");
        let directions = [state.coupler, state.rocker];
        let angles = std::array::from_fn(|i| {
            let (e, (angle, a)) = (directions[i], anchors[i]);
            // tan of the angle from the anchor's direction to e (NaN before
            // the first anchor)
            let x = (a.x * e.y - a.y * e.x) / (a.x * e.x + a.y * e.y);
            if x.abs() <= RANGE {
                let x2 = x * x;
                angle + (x + x * x2 * (-1.0 / 3.0 + x2 * (1.0 / 5.0)))
            } else {
                let angle = e.y.atan2(e.x);
                anchors[i] = (angle, e);
                angle
            }
        });
        on_sample(k, &(angles, state.velocities, state.accelerations));
    }
}

fn measure() -> Vec<Result> {
    let mut results = Vec::new();
    let fourbar_ref = Reference::<2>::parse(include_str!("../../tests/data/bench_fourbar.csv"));
    let cf = closed_form::FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
    let start = cf.position(0.0, 1.0).expect("assembled");
    let u0 = vector![start[0], start[1]];
    for (method, jacobian, repeats) in [
        ("generated (sweep API)", JacobianSource::Generated, 7),
        ("num-dual Jacobians (sweep API)", JacobianSource::Dual, 3),
        (
            "finite differences (sweep API)",
            JacobianSource::FiniteDifference,
            3,
        ),
    ] {
        results.push(sweep_method(
            "four-bar",
            method,
            &FOUR_BAR,
            u0,
            OMEGA2,
            jacobian,
            &fourbar_ref,
            repeats,
        ));
        eprintln!("measured four-bar: {method}");
    }
    // The hand-written closed form, sample by sample: one sin_cos, the
    // circle intersection, two atan2.
    let closed = |k: usize| cf.state(theta2(k), OMEGA2, 0.0, 1.0).expect("assembled");
    let at_reference: Vec<Sample<2>> = (0..N)
        .step_by(STRIDE)
        .map(|k| {
            let s = closed(k);
            (s.angles, s.velocities, s.accelerations)
        })
        .collect();
    let ns = time(N + 1, 7, || {
        (0..=N)
            .map(|k| closed(std::hint::black_box(k)).accelerations[0])
            .sum()
    });
    results.push(Result {
        workload: "four-bar".into(),
        method: "closed form per sample (hand-written)".into(),
        ns,
        errors: errors(&fourbar_ref, &at_reference),
        samples: N + 1,
    });
    // The best hand-written sweep: the same closed form with the sines and
    // cosines carried along the revolution.
    let mut at_reference = Vec::new();
    closed_form_sweep(&cf, |k, s| {
        if k % STRIDE == 0 && k < N {
            at_reference.push(*s);
        }
    });
    let ns = time(N + 1, 7, || {
        let mut checksum = 0.0;
        closed_form_sweep(&cf, |_, s| checksum += s.2[0]);
        checksum
    });
    results.push(Result {
        workload: "four-bar".into(),
        method: "closed form, sweep with trig carried (hand-written)".into(),
        ns,
        errors: errors(&fourbar_ref, &at_reference),
        samples: N + 1,
    });
    eprintln!("measured four-bar: closed form");
    for (tol, label) in [
        (1e-4, "1e-4"),
        (1e-6, "1e-6"),
        (1e-8, "1e-8"),
        (1e-10, "1e-10"),
        (1e-12, "1e-12"),
        (1e-14, "1e-14"),
        (0.0, "0 (to convergence)"),
    ] {
        results.push(tolerance_method(tol, label, &fourbar_ref, u0));
        eprintln!("measured four-bar: tolerance {label}");
    }

    let slider_ref = Reference::<2>::parse(include_str!("../../tests/data/bench_slider_crank.csv"));
    let r = slider_ref.rows[0];
    let slider_u0 = vector![r.1[0], r.1[1]];
    for (method, jacobian, repeats) in [
        ("generated (sweep API)", JacobianSource::Generated, 5),
        ("num-dual Jacobians (sweep API)", JacobianSource::Dual, 3),
        (
            "finite differences (sweep API)",
            JacobianSource::FiniteDifference,
            3,
        ),
    ] {
        results.push(sweep_method(
            "slider-crank",
            method,
            &SLIDER_CRANK,
            slider_u0,
            1.0,
            jacobian,
            &slider_ref,
            repeats,
        ));
        eprintln!("measured slider-crank: {method}");
    }
    let six_ref = Reference::<4>::parse(include_str!("../../tests/data/bench_six_bar.csv"));
    let r = six_ref.rows[0];
    let six_u0 = SVector::<f64, 4>::from(r.1);
    for (method, jacobian, repeats) in [
        ("generated (sweep API)", JacobianSource::Generated, 5),
        ("num-dual Jacobians (sweep API)", JacobianSource::Dual, 3),
        (
            "finite differences (sweep API)",
            JacobianSource::FiniteDifference,
            3,
        ),
    ] {
        results.push(sweep_method(
            "six-bar", method, &SIX_BAR, six_u0, 1.0, jacobian, &six_ref, repeats,
        ));
        eprintln!("measured six-bar: {method}");
    }
    results
}

fn write_csv(path: &Path, results: &[Result]) -> std::io::Result<()> {
    let mut text = String::from(
        "# Measured by `cargo run --release --example speed_accuracy`: median ns per sample over a revolution of the\n\
         # dense sweep (positions, velocities, accelerations), worst relative errors against tests/data/bench_*.csv.\n\
         workload,method,ns_per_sample,error_positions,error_velocities,error_accelerations,samples\n",
    );
    for r in results {
        text.push_str(&format!(
            "{},{},{:.2},{:.3e},{:.3e},{:.3e},{}\n",
            r.workload, r.method, r.ns, r.errors[0], r.errors[1], r.errors[2], r.samples
        ));
    }
    std::fs::create_dir_all(path.parent().expect("a folder"))?;
    std::fs::write(path, text)
}

fn read_csv(path: &Path) -> Vec<Result> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Vec::new();
    };
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("workload"))
        .filter_map(|l| {
            // workload, method, then five numbers; a method's name may
            // hold commas ("Newton per sample, step tol 1e-4").
            let (workload, rest) = l.split_once(',')?;
            let f: Vec<&str> = rest.rsplitn(6, ',').collect();
            if f.len() < 6 {
                return None;
            }
            Some(Result {
                workload: workload.into(),
                method: f[5].into(),
                ns: f[4].parse().ok()?,
                errors: [f[3].parse().ok()?, f[2].parse().ok()?, f[1].parse().ok()?],
                samples: f[0].parse().ok()?,
            })
        })
        .collect()
}

fn print_table(results: &[Result]) {
    println!(
        "| workload | method | ns / sample | vs closed form | positions | velocities | accelerations | samples |\n\
         |---|---|---:|---:|---:|---:|---:|---:|"
    );
    let floor = results
        .iter()
        .find(|r| r.workload == "four-bar" && r.method.starts_with("closed form"))
        .map(|r| r.ns);
    for r in results {
        let ratio = match (floor, r.workload.as_str()) {
            (Some(f), "four-bar") => format!("{:.2}×", r.ns / f),
            _ => "—".to_owned(),
        };
        println!(
            "| {} | {} | {:.1} | {} | {:.1e} | {:.1e} | {:.1e} | {} |",
            r.workload, r.method, r.ns, ratio, r.errors[0], r.errors[1], r.errors[2], r.samples
        );
    }
}

/// The chart: ns per sample against the worst relative error, for the
/// four-bar, one panel per kind of quantity. Every method an open marker
/// of its own shape and colour, so that markers on one another both show.
fn chart(results: &[Result], path: &Path) -> std::result::Result<(), Box<dyn std::error::Error>> {
    let four: Vec<&Result> = results
        .iter()
        .filter(|r| r.workload == "four-bar")
        .collect();
    let methods: Vec<&Result> = four
        .iter()
        .copied()
        .filter(|r| !r.method.starts_with("Newton per sample"))
        .collect();
    let x_min = four.iter().map(|r| r.ns).fold(f64::INFINITY, f64::min) / 2.0;
    let x_max = four.iter().map(|r| r.ns).fold(0.0, f64::max) * 2.0;
    let mut chart = Chart::new(
        "The worksheet's four-bar over a revolution (1 008 000 samples): time per sample against worst relative error",
        "ns per sample",
    )
    .note("exact results are drawn at 10⁻¹⁷")
    .columns(3)
    .size(1200, 430)
    .shared_legend();
    for (kind, title) in ["positions", "velocities", "accelerations"]
        .iter()
        .enumerate()
    {
        // Newton's tolerance as a curve.
        let curve: Vec<(f64, f64)> = four
            .iter()
            .filter(|r| r.method.starts_with("Newton per sample"))
            .map(|r| (r.ns, r.errors[kind].max(1e-17)))
            .collect();
        let mut panel = Panel::new("worst relative error")
            .caption(title)
            .x_log()
            .y_log()
            .x_range(x_min, x_max)
            .y_range(1e-17, 1e-2)
            .line_and_points(
                "Newton per sample, tolerance swept (10⁻⁴ … to convergence)",
                curve,
            )
            .colour(Colour::GREY)
            .dash(Dash::Solid)
            .marker(Marker::Circle)
            .width(0.8);
        for r in &methods {
            panel = panel
                .points(&r.method, vec![(r.ns, r.errors[kind].max(1e-17))])
                .open();
        }
        chart = chart.panel(panel);
    }
    std::fs::write(path, chart.render()?)?;
    Ok(())
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let folder = output::folder("speed_accuracy")?;
    // `--chart`: the chart of the committed measurements, without measuring.
    let chart_only = std::env::args().any(|a| a == "--chart");
    let ours_path = if chart_only {
        root.join("benches/results/ours.csv")
    } else {
        folder.join("ours.csv")
    };
    let ours = if chart_only {
        read_csv(&ours_path)
    } else {
        let measured = measure();
        write_csv(&ours_path, &measured)?;
        measured
    };
    let peers = read_csv(&root.join("benches/results/peers.csv"));
    let mut all = ours;
    all.extend(peers);
    print_table(&all);
    let figure = folder.join("speed_accuracy.svg");
    chart(&all, &figure)?;
    if chart_only {
        println!("\nread {}, wrote {}", ours_path.display(), figure.display());
    } else {
        println!("\nwrote {} and {}", ours_path.display(), figure.display());
    }
    Ok(())
}

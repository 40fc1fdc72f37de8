//! Where the linear tolerance theory fails, and says so: an offset
//! slider-crank (r = 40, e = 20, ±0.1 on r, l, e) whose rod approaches
//! r + e, against closed forms. Its measure of a pose is cos²θ3, smallest
//! at θ2 = −90°, where it is 1 − ((r + e)/l)²; a design of the band runs
//! the cycle exactly while l ≥ r + e. Its stroke is
//! √((l + r)² − e²) − √((l − r)² − e²).

use linkage::mechanisms::{FourBar, OffsetSliderCrank};
use linkage::num_dual::{DualNum, DualSVec64};
use linkage::prelude::*;
use linkage::tolerance::{
    self, Design, Failure, MonteCarlo, Output, Tolerance, ToleranceError, Tolerances, gradient,
};
use linkage::watch::Of;
use std::f64::consts::{FRAC_PI_2, TAU};

const R: f64 = 40.0;
const E: f64 = 20.0;

fn crank(l: f64) -> OffsetSliderCrank {
    OffsetSliderCrank { r: R, l, e: E }
}

fn tolerances() -> Tolerances<3> {
    Tolerances::new([Tolerance::Band(0.1); 3]).unwrap()
}

/// A turn of the crank from θ2 = 1 (no extreme and no worst pose on the
/// grid), and the pose there.
fn cycle_of(crank: &OffsetSliderCrank) -> (SVector<f64, 2>, Drive<1>) {
    let start = 1.0_f64;
    let theta3 = ((crank.e - crank.r * start.sin()) / crank.l).asin();
    let s = crank.r * start.cos() + crank.l * theta3.cos();
    let drive = Drive::Line {
        from: vector![start],
        to: vector![start + TAU],
        steps: 72,
    };
    (vector![theta3, s], drive)
}

/// The closed form of the smallest measure 1 − ((r + e)/l)² on dual
/// parameters (r, l, e).
fn smallest_measure(l: f64) -> DualSVec64<3> {
    let [r, l, e] = dual([R, l, E]);
    -((r + e) / l).powi(2) + 1.0
}

fn stroke(l: f64) -> DualSVec64<3> {
    let [r, l, e] = dual([R, l, E]);
    ((l + r).powi(2) - e * e).sqrt() - ((l - r).powi(2) - e * e).sqrt()
}

fn dual(p: [f64; 3]) -> [DualSVec64<3>; 3] {
    std::array::from_fn(|i| tolerance::with_gradient(p[i], SVector::ith(i, 1.0)))
}

#[test]
fn the_distance_to_the_limit_position_is_its_closed_form() {
    for (l, flagged) in [(60.05, true), (60.2, true), (120.0, false)] {
        let crank = crank(l);
        let (u0, drive) = cycle_of(&crank);
        let outputs = [Output::coordinate("s", Of::Position)];
        let cycle = tolerance::cycle(
            &crank,
            &u0,
            &drive,
            &SweepOptions::default(),
            &outputs,
            &tolerances(),
        )
        .unwrap();
        let margin = cycle.limit.expect("a cycle with poses");
        let exact = smallest_measure(l);
        let worst = tolerances().spread(&gradient(&exact)).worst_case;
        // Found between the grid's poses, at θ2 = −90° (to the golden
        // section's 1e-12 in the step's fraction, so q to rounding).
        assert!(
            (margin.v[0] - (TAU - FRAC_PI_2)).abs() < 1e-6,
            "l = {l}: at θ2 = {}",
            margin.v[0]
        );
        assert!(
            (margin.measure - exact.re).abs() < 1e-12,
            "l = {l}: q {} against {}",
            margin.measure,
            exact.re
        );
        assert!(
            (margin.gradient - gradient(&exact)).amax() < 1e-9 * gradient(&exact).amax(),
            "l = {l}: {} against {}",
            margin.gradient.transpose(),
            gradient(&exact).transpose()
        );
        assert!((margin.distance / (exact.re / worst) - 1.0).abs() < 1e-8);
        assert_eq!(margin.reaches_limit(), flagged, "l = {l}: {margin:?}");
        // The measure is linear across the fold (l = r + e): the distance
        // is the rod's excess over r + e in units of the worst-case change
        // of l − r − e (0.3), to first order in 1/l.
        let excess = (l - R - E) / 0.3;
        assert!(
            l > 61.0 || (margin.distance / excess - 1.0).abs() < 0.01 * (1.0 + l / 60.0),
            "l = {l}: distance {} against {excess}",
            margin.distance
        );
        println!("l = {l}: distance {:.4}", margin.distance);
    }
}

#[test]
fn the_fraction_of_designs_that_do_not_run_the_cycle_is_reported() {
    // Exactly those whose rod is shorter than crank plus offset fail; a
    // design just longer passes so close to the fold that its sweep may
    // still drop poses and be left out too. So every design that must
    // fail fails, and a few more at most.
    let run = MonteCarlo {
        samples: 600,
        random_state: 9,
    };
    let output = Output::coordinate("s", Of::Position);
    for (l, expected) in [(60.05, 0.3177), (60.2, 0.0208), (120.0, 0.0)] {
        let crank = crank(l);
        let (u0, drive) = cycle_of(&crank);
        let options = SweepOptions::default();
        let sampled = tolerance::monte_carlo_range(
            &crank,
            &u0,
            &drive,
            &options,
            &output,
            &tolerances(),
            &run,
        )
        .unwrap();
        let must_fail: Vec<usize> = (0..run.samples)
            .filter(|&i| {
                let d = tolerances().deviation(run.random_state, i);
                l + d[1] < R + d[0] + E + d[2]
            })
            .collect();
        let failed: Vec<usize> = sampled.failures.iter().map(|f| f.0).collect();
        assert!(
            must_fail.iter().all(|i| failed.contains(i)),
            "l = {l}: {failed:?}"
        );
        // Those that must fail cannot be assembled over the cycle; a few
        // more pass so close to the fold (within 0.02 of the band's 0.3)
        // that their sweep cannot be followed past it.
        let mut closest: f64 = 0.0;
        for (i, why) in &sampled.failures {
            let d = tolerances().deviation(run.random_state, *i);
            let excess = l + d[1] - R - d[0] - E - d[2];
            if must_fail.contains(i) {
                assert!(
                    matches!(why, Failure::Kinematics(_) | Failure::Singular(_)),
                    "{why:?}"
                );
            } else {
                assert!(
                    (0.0..0.02).contains(&excess),
                    "sample {i}: {excess}, {why:?}"
                );
                closest = closest.max(excess);
            }
        }
        // The binomial error of 600 samples is ≤ 0.019.
        let fraction = sampled.failed_fraction();
        assert!((fraction - expected).abs() < 0.06, "l = {l}: {fraction}");
        // The linear estimate of that fraction, from the margin.
        let cycle = tolerance::cycle(&crank, &u0, &drive, &options, &[], &tolerances()).unwrap();
        let estimate = cycle.limit.unwrap().failing_fraction();
        assert!(
            (estimate - expected).abs() < 0.02,
            "l = {l}: estimate {estimate} against {expected}"
        );
        let range = tolerance::range(&crank, &u0, &drive, &options, &output, &tolerances());
        let range = range.unwrap();
        println!(
            "l = {l}: failed {fraction:.4} (estimate {estimate:.4}; {} must, the others within {closest:.4} of the fold); σ Monte Carlo / linear {:.3}; max − nominal {:.3} against worst case {:.3}",
            must_fail.len(),
            sampled.statistics.std() / range.spread.sigma,
            sampled.statistics.max - range.value.re,
            range.spread.worst_case,
        );
    }
}

#[test]
fn the_strokes_spread_is_one_call_and_its_closed_form() {
    for l in [60.05, 60.2, 120.0] {
        let crank = crank(l);
        let (u0, drive) = cycle_of(&crank);
        let range = tolerance::range(
            &crank,
            &u0,
            &drive,
            &SweepOptions::default(),
            &Output::coordinate("s", Of::Position),
            &tolerances(),
        )
        .unwrap();
        let exact = stroke(l);
        let error = (range.value.re - exact.re)
            .abs()
            .max((range.gradient() - gradient(&exact)).amax());
        let scale = exact.re.max(gradient(&exact).amax());
        assert!(
            error <= 1e-12 * scale,
            "l = {l}: {} {} against {} {}",
            range.value.re,
            range.gradient().transpose(),
            exact.re,
            gradient(&exact).transpose()
        );
        let spread = tolerances().spread(&gradient(&exact));
        assert!((range.spread.worst_case - spread.worst_case).abs() < 1e-12 * scale);
        assert!((range.spread.sigma - spread.sigma).abs() < 1e-12 * scale);
    }
}

#[test]
fn the_grashof_margin_of_a_four_bar() {
    let tolerances = Tolerances::new([
        Tolerance::Band(0.15),
        Tolerance::Band(0.1),
        Tolerance::Band(0.15),
        Tolerance::Band(0.15),
    ])
    .unwrap();
    // The worksheet's: s + l − p − q = 20 + 80 − 50 − 70 = −20, far.
    let far = tolerance::grashof_margin(&FourBar::WORKSHEET.closed_form(), &tolerances);
    assert_eq!(far.sum, -20.0);
    assert_eq!(far.gradient, vector![1.0, 1.0, -1.0, -1.0]);
    assert!((far.distance - 20.0 / 0.55).abs() < 1e-12);
    assert!(!far.crosses());
    // A 30.3 mm coupler: 20 + 80 − 30.3 − 70 = −0.3 against 0.55.
    let near = FourBar {
        l3: 30.3,
        ..FourBar::WORKSHEET
    };
    let near = tolerance::grashof_margin(&near.closed_form(), &tolerances);
    assert!((near.sum + 0.3).abs() < 1e-12);
    assert!((near.distance - 0.3 / 0.55).abs() < 1e-12);
    assert!(near.crosses());
}

#[test]
fn kinematic_errors_say_which_design() {
    // l = 10 cannot be assembled at all: the nominal design's error says so.
    let crank = crank(10.0);
    let (_, drive) = cycle_of(&crank);
    let run = MonteCarlo {
        samples: 4,
        random_state: 1,
    };
    let output = Output::coordinate("s", Of::Position);
    let options = SweepOptions::default();
    let u0 = vector![0.0, 30.0];
    let nominal =
        tolerance::monte_carlo_range(&crank, &u0, &drive, &options, &output, &tolerances(), &run);
    let Err(
        error @ ToleranceError::Kinematics {
            design: Design::Nominal,
            ..
        },
    ) = nominal
    else {
        panic!("{nominal:?}");
    };
    assert!(
        error.to_string().starts_with("the nominal design: "),
        "{error}"
    );
    // Called on a design by itself, the error names no design it cannot
    // know; in a Monte Carlo closure, in_sample names the sample.
    let given = tolerance::range(&crank, &u0, &drive, &options, &output, &tolerances());
    let Err(given) = given else {
        panic!("{given:?}");
    };
    assert!(
        matches!(
            given,
            ToleranceError::Kinematics {
                design: Design::Given,
                ..
            }
        ),
        "{given:?}"
    );
    assert!(given.to_string().starts_with("the design: "), "{given}");
    let sample = given.in_sample(17);
    assert!(
        sample.to_string().starts_with("Monte Carlo sample 17: "),
        "{sample}"
    );
}

#[test]
fn a_four_bar_near_the_grashof_limit_is_flagged_by_its_cycle() {
    // The worksheet's four-bar under ISO 2768-f runs far from any limit;
    // with a 30.3 mm coupler, 0.3 mm inside the Grashof limit, the band
    // reaches a limit position (about 3 % of its designs lock up).
    let tolerances = Tolerances::new([
        Tolerance::Band(0.15),
        Tolerance::Band(0.1),
        Tolerance::Band(0.15),
        Tolerance::Band(0.15),
    ])
    .unwrap();
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 24,
    };
    let options = SweepOptions::default();
    let far = tolerance::cycle(
        &FourBar::WORKSHEET,
        &vector![1.3, -0.8],
        &drive,
        &options,
        &[],
        &tolerances,
    )
    .unwrap()
    .limit
    .unwrap();
    let near_bar = FourBar {
        l3: 30.3,
        ..FourBar::WORKSHEET
    };
    let near = tolerance::cycle(
        &near_bar,
        &vector![1.68, -0.445],
        &drive,
        &options,
        &[],
        &tolerances,
    )
    .unwrap()
    .limit
    .unwrap();
    println!("worksheet: {far:?}\nnear: {near:?}");
    assert!(!far.reaches_limit() && far.distance > 10.0, "{far:?}");
    assert!(near.reaches_limit(), "{near:?}");
    // The measure of a four-bar is sin²μ, μ = θ4 − θ3 the transmission angle.
    let mu = near.u[1] - near.u[0];
    assert!((near.measure - mu.sin().powi(2)).abs() < 1e-14);
    assert!((near.failing_fraction() - 0.03).abs() < 0.02, "{near:?}");
}

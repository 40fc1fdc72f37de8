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

/// P(Σ xᵢ > c) for independent xᵢ uniform on [−aᵢ, aᵢ]: exactly, by the
/// distribution of a sum of uniforms on [0, wᵢ] (wᵢ = 2aᵢ),
/// F(x) = Σ_S (−1)^|S| (x − Σ_{i∈S} wᵢ)₊ⁿ / (n! Π wᵢ) over the subsets S.
fn uniform_sum_tail(a: &[f64], c: f64) -> f64 {
    let n = a.len();
    let w: Vec<f64> = a.iter().map(|a| 2.0 * a).collect();
    let x = c + a.iter().sum::<f64>();
    if x >= w.iter().sum::<f64>() {
        return 0.0;
    }
    let mut cdf = 0.0;
    for subset in 0..1usize << n {
        let shift: f64 = (0..n).filter(|i| subset >> i & 1 == 1).map(|i| w[i]).sum();
        let sign = if subset.count_ones() % 2 == 0 {
            1.0
        } else {
            -1.0
        };
        cdf += sign * (x - shift).max(0.0).powi(n as i32);
    }
    let factorial: f64 = (1..=n).map(|k| k as f64).product();
    1.0 - cdf / (factorial * w.iter().product::<f64>())
}

/// The probability that a design of the band has l < r + e: the
/// deviations δr + δe − δl exceed l − r − e.
fn must_fail_probability(l: f64) -> f64 {
    uniform_sum_tail(&[0.1; 3], l - R - E)
}

/// Three standard deviations of a fraction p of n samples.
fn three_sigma(p: f64, n: usize) -> f64 {
    3.0 * (p * (1.0 - p) / n as f64).sqrt()
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
        // Found between the grid's poses, at θ2 = −90° (to Brent's √ε in
        // the step's fraction, so q to rounding: its minimum is flat).
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
        // is the rod's excess x = l − r − e in units of the worst-case
        // change of l − r − e (0.3), times 1 + 5t/6 − t²/(18 + 12t) with
        // t = x/(r + e) (q = 1 − ((r + e)/l)² and its gradient expanded):
        // first order in t at the fold, 1.8 times at l = 120.
        let t = (l - R - E) / (R + E);
        let excess = (l - R - E) / 0.3;
        let factor = 1.0 + 5.0 * t / 6.0 - t * t / (18.0 + 12.0 * t);
        assert!(
            (margin.distance / (excess * factor) - 1.0).abs() < 1e-8,
            "l = {l}: distance {} against {excess} × {factor}",
            margin.distance
        );
        // The same margin from any sweep, its u_p computed pose by pose.
        let sweep = crank.sweep(&u0, &drive, &SweepOptions::default()).unwrap();
        let again = tolerance::limit_margin(
            &crank,
            &sweep,
            &tolerances(),
            &SweepOptions::default().options,
        )
        .unwrap();
        assert!((again.v[0] - margin.v[0]).abs() < 1e-6, "{again:?}");
        assert!((again.measure - exact.re).abs() < 1e-12, "{again:?}");
        assert!(
            (again.distance / margin.distance - 1.0).abs() < 1e-8,
            "{again:?}"
        );
        println!("l = {l}: distance {:.4}", margin.distance);
    }
}

#[test]
fn the_measure_of_a_slider_crank_pose_is_cos_squared_of_its_rod_angle() {
    let crank = crank(60.2);
    for theta2 in [0.0, 1.0, -FRAC_PI_2, 2.5] {
        let theta3 = ((E - R * f64::sin(theta2)) / crank.l).asin();
        let s = R * theta2.cos() + crank.l * theta3.cos();
        let q = tolerance::limit_measure(&crank, &vector![theta3, s], &vector![theta2]);
        assert!(
            (q - theta3.cos().powi(2)).abs() < 1e-14,
            "θ2 = {theta2}: {q} against {}",
            theta3.cos().powi(2)
        );
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
    let n = run.samples;
    let output = Output::coordinate("s", Of::Position);
    // The sum of three uniforms' tail by hand: 1 − F(1.75) of the
    // Irwin–Hall distribution on [0, 3] at l = 60.05, (0.5)³/6 at 60.2.
    assert!((must_fail_probability(60.05) - 61.0 / 192.0).abs() < 1e-12);
    assert!((must_fail_probability(60.2) - 1.0 / 48.0).abs() < 1e-12);
    assert_eq!(must_fail_probability(120.0), 0.0);
    // l, the linear estimate's allowed error against the exact fraction
    // (the normal tail against the sum of three uniforms: 0.0093 and
    // 0.0017 here) and the guide's estimate, and the guide's failed
    // fraction and σ ratio of the stroke (Monte Carlo over linear) at this
    // random state.
    for (l, estimate_error, estimate_guide, failed_guide, ratio_guide) in [
        (60.05, 0.012, 0.3084, 0.373, 0.45),
        (60.2, 0.003, 0.0225, 0.040, 0.95),
        (120.0, 1e-12, 0.0, 0.0, 1.00),
    ] {
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
        let must_fail: Vec<usize> = (0..n)
            .filter(|&i| {
                let d = tolerances().deviation(run.random_state, i);
                l + d[1] < R + d[0] + E + d[2]
            })
            .collect();
        // The share that must fail is the exact probability, to the
        // samples' binomial error.
        let exact = must_fail_probability(l);
        let must_share = must_fail.len() as f64 / n as f64;
        assert!(
            (must_share - exact).abs() <= three_sigma(exact, n),
            "l = {l}: {must_share} against {exact}"
        );
        // Those that must fail cannot be assembled over the cycle; a few
        // more pass so close to the fold (within 0.02 of the band's 0.3)
        // that their extremes are not located: the sweep is not followed
        // past it.
        let failed: Vec<usize> = sampled.failures.iter().map(|f| f.0).collect();
        assert!(
            must_fail.iter().all(|i| failed.contains(i)),
            "l = {l}: {failed:?}"
        );
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
                    (0.0..0.02).contains(&excess) && matches!(why, Failure::Extremes(_)),
                    "sample {i}: {excess}, {why:?}"
                );
                closest = closest.max(excess);
            }
        }
        // The others are at most those within 0.02 of the fold, to their
        // binomial error.
        let extra = (failed.len() - must_fail.len()) as f64 / n as f64;
        let near = must_fail_probability(l - 0.02) - exact;
        assert!(
            extra <= near + three_sigma(near, n),
            "l = {l}: {extra} extra, {near} within 0.02"
        );
        let fraction = sampled.failed_fraction();
        assert_eq!(fraction, failed.len() as f64 / n as f64);
        // Those that cannot run the cycle are exactly those that must fail.
        assert_eq!(sampled.cannot_run_fraction(), must_share);
        assert!(
            (sampled.failures.iter()).all(|(i, why)| why.cannot_run() == must_fail.contains(i))
        );
        assert!(
            (fraction - failed_guide).abs() <= three_sigma(failed_guide, n),
            "l = {l}: {fraction} against the guide's {failed_guide}"
        );
        // The linear estimate of that fraction, from the margin: q taken
        // as normal.
        let cycle = tolerance::cycle(&crank, &u0, &drive, &options, &[], &tolerances()).unwrap();
        let estimate = cycle.limit.unwrap().failing_fraction();
        assert!(
            (estimate - exact).abs() < estimate_error && (estimate - estimate_guide).abs() < 1e-4,
            "l = {l}: estimate {estimate} against {exact}"
        );
        // The stroke's σ: far from the fold (l = 120) the linear one, to
        // the sampling error of a standard deviation, 1/√(2n); close to
        // it, the guide's, to the same error.
        let range = tolerance::range(&crank, &u0, &drive, &options, &output, &tolerances());
        let range = range.unwrap();
        let passed = sampled.statistics.count as f64;
        let ratio = sampled.statistics.std() / range.spread.sigma;
        assert!(
            (ratio - ratio_guide).abs() <= 3.0 / (2.0 * passed).sqrt(),
            "l = {l}: σ ratio {ratio} against {ratio_guide}"
        );
        println!(
            "l = {l}: failed {fraction:.4} (estimate {estimate:.4}, exact {exact:.4}; {} must, the others within {closest:.4} of the fold); σ Monte Carlo / linear {ratio:.3}; max − nominal {:.3} against worst case {:.3}",
            must_fail.len(),
            sampled.statistics.max - range.value.re,
            range.spread.worst_case,
        );
    }
}

/// The same run through the statistics of the whole cycle: exactly the
/// designs that must fail are left out. Those just past the fold that
/// [`tolerance::monte_carlo_range`] leaves out run the cycle; only their
/// extremes are not located.
#[test]
fn the_cycles_statistics_leave_out_the_designs_that_must_fail() {
    let run = MonteCarlo {
        samples: 600,
        random_state: 9,
    };
    let l = 60.2;
    let crank = crank(l);
    let (u0, drive) = cycle_of(&crank);
    let outputs = [Output::coordinate("s", Of::Position)];
    let sampled = tolerance::monte_carlo_cycle(
        &crank,
        &u0,
        &drive,
        &SweepOptions::default(),
        &outputs,
        &tolerances(),
        &run,
    )
    .unwrap();
    let excess = |i: usize| {
        let d = tolerances().deviation(run.random_state, i);
        l + d[1] - R - d[0] - E - d[2]
    };
    let failed: Vec<usize> = sampled.failures.iter().map(|f| f.0).collect();
    let must: Vec<usize> = (0..run.samples).filter(|&i| excess(i) < 0.0).collect();
    assert_eq!(failed, must);
    assert_eq!(sampled.failed_fraction(), 15.0 / 600.0);
    // Each of them cannot run the cycle.
    assert_eq!(sampled.cannot_run_fraction(), 15.0 / 600.0);
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
    // Its source is the kinematic error itself.
    let source = std::error::Error::source(&given).expect("the kinematic error");
    assert!(given.to_string().ends_with(&source.to_string()), "{given}");
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
    // Both worst at θ2 = 180°, where the crank pin is l1 + l2 from the
    // rocker's pivot: cos μ = (l3² + l4² − (l1 + l2)²) / (2 l3 l4), q = sin²μ.
    for (bar, margin, flagged) in [(FourBar::WORKSHEET, far, false), (near_bar, near, true)] {
        let [l1, l2, l3, l4] = std::array::from_fn(|i| {
            let l = [bar.l1, bar.l2, bar.l3, bar.l4];
            tolerance::with_gradient(l[i], SVector::<f64, 4>::ith(i, 1.0))
        });
        let d = l1 + l2;
        let cos_mu = (l3 * l3 + l4 * l4 - d * d) / (l3 * l4 * 2.0);
        let q = -cos_mu * cos_mu + 1.0;
        let spread = tolerances.spread(&gradient(&q));
        assert!(
            (margin.v[0] - std::f64::consts::PI).abs() < 1e-6,
            "{margin:?}"
        );
        assert!((margin.measure - q.re).abs() < 1e-14, "{margin:?}");
        assert!(
            (margin.gradient - gradient(&q)).amax() < 1e-12,
            "{margin:?} against {q:?}"
        );
        assert!((margin.distance / (q.re / spread.worst_case) - 1.0).abs() < 1e-10);
        assert_eq!(margin.reaches_limit(), flagged, "{margin:?}");
    }
    // The measure of a four-bar is sin²μ, μ = θ4 − θ3 the transmission angle.
    let mu = near.u[1] - near.u[0];
    assert!((near.measure - mu.sin().powi(2)).abs() < 1e-14);
    // The designs that lock are exactly the non-Grashof ones,
    // l1 + l2 − l3 − l4 > 0: δl1 + δl2 − δl3 − δl4 > 0.3, 3.01 %. The
    // linear estimate takes q as normal: 2.96 %.
    let locking = uniform_sum_tail(&[0.15, 0.1, 0.15, 0.15], 0.3);
    assert!((locking - 0.030_09).abs() < 1e-5, "{locking}");
    assert!(
        (near.failing_fraction() - locking).abs() < 0.001,
        "{} against {locking}",
        near.failing_fraction()
    );
}

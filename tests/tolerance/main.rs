//! Tolerance analysis against numbers computed elsewhere: the spreads'
//! formulas by hand, the shaper's stroke, dead positions and time ratio
//! against their closed forms differentiated by num-dual (the envelope
//! theorem and the implicit place of an extremum or a zero), and the
//! linear σ against Monte Carlo runs.

#[path = "../models/mod.rs"]
mod models;

#[path = "../../examples/shaper/machine.rs"]
mod machine;

use linkage::mechanisms::FourBar;
use linkage::num_dual::{DualNum, DualSVec64};
use linkage::prelude::*;
use linkage::tolerance::{
    self, MonteCarlo, Output, Tolerance, ToleranceError, Tolerances, gradient,
};
use linkage::watch::{Axis, FoundKind, Of, Watch, locate};
use machine::{COURSE_PROJECT, Shaper, synthesize};
use std::f64::consts::{PI, TAU};

#[test]
fn spreads_follow_their_formulas() {
    let tolerances = Tolerances::new([
        Tolerance::Band(0.3),
        Tolerance::Normal(0.1),
        Tolerance::EXACT,
    ])
    .unwrap();
    let g = vector![2.0, -5.0, 7.0];
    let spread = tolerances.spread(&g);
    // Worst case: 2·0.3 + 5·0.3 (3σ); RSS: √(0.6² + 1.5²); σ: √((2·0.3/√3)² + (5·0.1)²).
    assert!((spread.worst_case - 2.1).abs() < 1e-15);
    assert!((spread.rss - (0.36f64 + 2.25).sqrt()).abs() < 1e-15);
    assert!((spread.sigma - (0.12f64 + 0.25).sqrt()).abs() < 1e-15);
    assert!((tolerances.contributions(&g) - vector![0.6, 1.5, 0.0]).amax() < 1e-15);
}

#[test]
fn bad_tolerances_are_errors() {
    for bad in [-0.1, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Tolerances::new([Tolerance::Band(0.1), Tolerance::Normal(bad)]),
            Err(ToleranceError::BadTolerance { parameter: 1, .. })
        ));
    }
    let unknown = Tolerances::by_name(&FourBar::PARAM_NAMES, &[("l5", Tolerance::Band(0.1))]);
    let Err(ToleranceError::UnknownName(name)) = unknown else {
        panic!("{unknown:?}");
    };
    assert_eq!(
        (name.name.as_str(), name.known.as_str()),
        ("l5", "l1, l2, l3, l4")
    );
    let named =
        Tolerances::by_name(&FourBar::PARAM_NAMES, &[("l3", Tolerance::Band(0.2))]).unwrap();
    assert_eq!(named.get(2), Tolerance::Band(0.2));
    assert_eq!(named.get(0), Tolerance::EXACT);
}

/// The shaper's dead positions in closed form, on dual parameters
/// (l_oa, l_cd, y_c, y_f, φ0, …): the ram's x there and the driver φ.
/// With β/2 = asin(l_OA/l_OC), the rocker leans by ±β/2 and the crank is
/// ⟂ to it: at the left dead position the crank's angle φ0 − φ is π + β/2,
/// at the right one −β/2.
fn dead_positions(p: &[DualSVec64<8>; 8]) -> [(DualSVec64<8>, DualSVec64<8>); 2] {
    let [l_oa, l_cd, y_c, _, phi0, ..] = *p;
    let half = (l_oa / -y_c).asin();
    let x = l_cd * (l_oa / -y_c);
    [(-x, phi0 - half - PI), (x, phi0 + half)]
}

fn dual_params(shaper: &Shaper) -> [DualSVec64<8>; 8] {
    let p = shaper.params();
    std::array::from_fn(|i| {
        let mut unit = SVector::<f64, 8>::zeros();
        unit[i] = 1.0;
        tolerance::with_gradient(p[i], unit)
    })
}

fn assert_close<const K: usize>(what: &str, ours: &DualSVec64<K>, theirs: &DualSVec64<K>) {
    let scale = theirs.re.abs().max(gradient(theirs).amax()).max(1.0);
    let error = (ours.re - theirs.re)
        .abs()
        .max((gradient(ours) - gradient(theirs)).amax());
    assert!(
        error <= 1e-12 * scale,
        "{what}: ours {} {}, closed form {} {} (error {error:e})",
        ours.re,
        gradient(ours).transpose(),
        theirs.re,
        gradient(theirs).transpose()
    );
}

fn shaper_sweep(shaper: &Shaper) -> Sweep<3, 1> {
    let drive = Drive::Line {
        from: vector![-0.3],
        to: vector![TAU - 0.3],
        steps: 72,
    };
    shaper
        .sweep(&shaper.guess(), &drive, &SweepOptions::default())
        .unwrap()
}

#[test]
fn the_shapers_stroke_and_time_ratio_move_as_their_closed_forms() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let sweep = shaper_sweep(&shaper);
    let found = tolerance::extremes(
        &shaper,
        &sweep,
        &Output::coordinate("x_d", Of::Position),
        &Options::default(),
    )
    .unwrap();
    assert_eq!(found.len(), 2);
    let [left, right] = dead_positions(&dual_params(&shaper));
    let (min, max) = match found[0].kind {
        FoundKind::Minimum => (&found[0], &found[1]),
        _ => (&found[1], &found[0]),
    };
    assert_eq!(
        (min.kind, max.kind),
        (FoundKind::Minimum, FoundKind::Maximum)
    );
    // The envelope theorem: the extreme values move by their partial derivatives.
    assert_close("x_D at the left dead position", &min.value, &left.0);
    assert_close("x_D at the right dead position", &max.value, &right.0);
    // Their places, by implicit differentiation of ẋ_D = 0.
    assert_close("φ at the left dead position", &min.v.unwrap(), &left.1);
    assert_close("φ at the right dead position", &max.v.unwrap(), &right.1);
    // So the stroke and the time ratio, derived from them.
    assert_close("the stroke", &(max.value - min.value), &(right.0 - left.0));
    let ratio = |a: DualSVec64<8>| a / (-a + TAU);
    assert_close(
        "the time ratio",
        &ratio(max.v.unwrap() - min.v.unwrap()),
        &ratio(right.1 - left.1),
    );
    assert!((ratio(right.1 - left.1).re - COURSE_PROJECT.k_v).abs() < 1e-14);
}

#[test]
fn zeros_move_as_the_closed_form_says() {
    // The dead positions again, as the zeros of the ram's velocity.
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let sweep = shaper_sweep(&shaper);
    let options = Options::default();
    let velocity = Output::coordinate("x_d", Of::Velocity);
    let zeros = locate(
        &shaper,
        &sweep,
        &[Watch::coordinate("x_d", Of::Velocity).zeros()],
        &options,
    )
    .unwrap();
    assert_eq!(zeros.len(), 2);
    let [left, right] = dead_positions(&dual_params(&shaper));
    for (found, (_, place)) in zeros.iter().zip([left, right]) {
        let at = tolerance::at_found(&shaper, &sweep, found, &velocity, &options).unwrap();
        assert!(matches!(at.kind, FoundKind::Zero { .. }));
        assert_close("the place of a zero of ẋ_D", &at.v.unwrap(), &place);
        assert_eq!(gradient(&at.value), SVector::<f64, 8>::zeros());
    }
}

#[test]
fn extremes_of_a_path_or_function_are_refused_with_a_reason() {
    let bar = FourBar::WORKSHEET;
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 36,
    };
    let sweep = bar
        .sweep(&vector![1.3, -0.8], &drive, &SweepOptions::default())
        .unwrap();
    let result = tolerance::extremes(&bar, &sweep, &Output::path("G3"), &Options::default());
    assert!(
        matches!(result, Err(ToleranceError::Unsupported { .. })),
        "{result:?}"
    );
    let unknown = tolerance::extremes(
        &bar,
        &sweep,
        &Output::coordinate("theta5", Of::Position),
        &Options::default(),
    );
    assert!(
        matches!(unknown, Err(ToleranceError::Watch(_))),
        "{unknown:?}"
    );
}

/// The worksheet's four-bar over a cycle of 24 steps at 400 rpm, under
/// ISO 2768-f.
fn four_bar_case() -> (
    FourBar,
    SVector<f64, 2>,
    Drive<1>,
    SweepOptions,
    Tolerances<4>,
) {
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
    let options = SweepOptions {
        speed: 400.0 * TAU / 60.0,
        ..SweepOptions::default()
    };
    (
        FourBar::WORKSHEET,
        vector![1.3, -0.8],
        drive,
        options,
        tolerances,
    )
}

fn four_bar_outputs() -> Vec<Output<'static, 2, 1, 4>> {
    vec![
        Output::coordinate("theta4", Of::Position),
        Output::coordinate("theta4", Of::Acceleration),
        Output::path("G3"),
        Output::point("G3", Axis::Y, Of::Velocity),
        Output::function("transmission angle", |p| {
            p.u[1] - p.u[0] + DualSVec64::from_re(PI)
        }),
    ]
}

#[test]
fn monte_carlo_confirms_the_linear_spreads_of_the_worksheets_four_bar() {
    let (bar, u0, drive, options, tolerances) = four_bar_case();
    let outputs = four_bar_outputs();
    let run = MonteCarlo {
        samples: 4000,
        random_state: 11,
    };
    let cycle = tolerance::cycle(&bar, &u0, &drive, &options, &outputs, &tolerances).unwrap();
    // Observed: every sample reported once.
    let ended = std::sync::atomic::AtomicUsize::new(0);
    let samples = tolerance::monte_carlo_cycle_observed(
        &bar,
        &u0,
        &drive,
        &options,
        &outputs,
        &tolerances,
        &run,
        &|| {
            ended.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        },
    )
    .unwrap();
    assert_eq!(ended.into_inner(), run.samples);
    assert!(samples.failures.is_empty());
    assert_eq!(
        samples.names,
        cycle
            .bands
            .iter()
            .map(|b| b.name.clone())
            .collect::<Vec<_>>()
    );
    for (o, band) in cycle.bands.iter().enumerate() {
        for k in 0..band.v.len() {
            let spread = band.spread[k].expect("no singular pose on the worksheet's cycle");
            let mc = &samples.statistics[o][k];
            assert_eq!(mc.count, run.samples);
            // σ of a sample of 4000 is good to ≈ 1/√8000 ≈ 1.1 %.
            assert!(
                (mc.std() / spread.sigma - 1.0).abs() < 0.05,
                "{} at step {k}: Monte Carlo σ {} against linear {}",
                band.name,
                mc.std(),
                spread.sigma
            );
            // Every design within the worst case (to the response's curvature).
            let reach = (mc.max - band.value[k]).max(band.value[k] - mc.min);
            assert!(
                reach <= 1.02 * spread.worst_case,
                "{} at step {k}",
                band.name
            );
            assert!(
                (mc.mean - band.value[k]).abs() < 0.1 * spread.sigma,
                "{}",
                band.name
            );
        }
    }
}

#[test]
fn monte_carlo_is_the_same_on_any_number_of_threads() {
    let (bar, u0, drive, options, tolerances) = four_bar_case();
    let outputs = four_bar_outputs();
    let run = MonteCarlo {
        samples: 1500,
        random_state: 3,
    };
    let on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                tolerance::monte_carlo_cycle(
                    &bar,
                    &u0,
                    &drive,
                    &options,
                    &outputs,
                    &tolerances,
                    &run,
                )
                .unwrap()
            })
    };
    assert_eq!(on(1), on(2));
    // A sample is drawn again by itself, to the bit.
    let again = run.sample(&bar, &tolerances, 7);
    assert_eq!(again.params(), bar.params() + tolerances.deviation(3, 7));
}

#[test]
fn near_the_grashof_limit_some_designs_lock_up_and_are_reported() {
    // Coupler 30.3 mm: s + l = 100 against p + q = 100.3; ±0.15 mm on
    // every length turns some designs of the band into non-Grashof ones,
    // which cannot pass θ2 = 180°.
    let (bar, _, drive, options, tolerances) = four_bar_case();
    let bar = FourBar { l3: 30.3, ..bar };
    let u0 = vector![1.68, -0.445];
    let outputs = [Output::coordinate("theta4", Of::Position)];
    let run = MonteCarlo {
        samples: 2000,
        random_state: 5,
    };
    let samples =
        tolerance::monte_carlo_cycle(&bar, &u0, &drive, &options, &outputs, &tolerances, &run)
            .unwrap();
    // Exactly the non-Grashof designs lock up: those whose deviations
    // make l1 + l2 exceed l3 + l4 (a sum of four uniform deviations beyond
    // 0.3 mm, about 3 % of them).
    let non_grashof: Vec<usize> = (0..run.samples)
        .filter(|&i| {
            let d = tolerances.deviation(run.random_state, i);
            d[0] + d[1] - d[2] - d[3] > 0.3
        })
        .collect();
    let failed: Vec<usize> = samples.failures.iter().map(|f| f.0).collect();
    assert!(
        (20..120).contains(&failed.len()),
        "{} of 2000 lock up",
        failed.len()
    );
    assert_eq!(failed, non_grashof);
}

#[test]
fn monte_carlo_needs_samples_and_known_names() {
    let (bar, u0, drive, options, tolerances) = four_bar_case();
    let none = MonteCarlo {
        samples: 0,
        random_state: 0,
    };
    let outputs = four_bar_outputs();
    assert!(matches!(
        tolerance::monte_carlo_cycle(&bar, &u0, &drive, &options, &outputs, &tolerances, &none),
        Err(ToleranceError::NoSamples)
    ));
    let unknown = [Output::point("G7", Axis::X, Of::Position)];
    let result = tolerance::cycle(&bar, &u0, &drive, &options, &unknown, &tolerances);
    let Err(ToleranceError::UnknownName(name)) = result else {
        panic!("{result:?}");
    };
    assert_eq!(name.name, "G7");
}

/// Where the linear theory fails, and says so (in this binary, not one of
/// its own: each test binary links the whole library).
mod limits;

/// A mechanism read at run time, the Maple worksheet's four-bar from its
/// file, has the compiled four-bar's tolerance bands over a whole turn, to
/// the bit, and the same Monte Carlo run, sample by sample.
#[test]
fn a_mechanism_read_at_run_time_has_the_compiled_bands() {
    let file = linkage::file::MechanismFile::parse(include_str!("../../mechanisms/four_bar.toml"))
        .expect("the library's four-bar reads");
    let run_time = file.mechanism().unwrap().sensitive::<2, 1, 4>().unwrap();
    let compiled = FourBar::WORKSHEET;
    let tolerances = Tolerances::new([
        Tolerance::Band(0.05),
        Tolerance::Normal(0.02),
        Tolerance::Band(0.05),
        Tolerance::EXACT,
    ])
    .unwrap();
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 90,
    };
    let outputs = [
        Output::coordinate("theta4", Of::Position),
        Output::point("C", Axis::Y, Of::Acceleration),
        Output::path("C"),
    ];
    let u0 = vector![1.2, -1.0];
    let options = SweepOptions::default();
    let a = tolerance::cycle(&compiled, &u0, &drive, &options, &outputs, &tolerances).unwrap();
    let b = tolerance::cycle(&run_time, &u0, &drive, &options, &outputs, &tolerances).unwrap();
    assert_eq!(a.bands.len(), b.bands.len());
    for (x, y) in a.bands.iter().zip(&b.bands) {
        assert_eq!(x.name, y.name);
        let bits = |g: &Option<SVector<f64, 4>>| g.map(|g| g.map(f64::to_bits));
        assert_eq!(
            x.gradient.iter().map(bits).collect::<Vec<_>>(),
            y.gradient.iter().map(bits).collect::<Vec<_>>(),
            "{}",
            x.name
        );
        assert_eq!(
            x.value.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            y.value.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
    }
    let run = MonteCarlo {
        samples: 64,
        random_state: 7,
    };
    let a = tolerance::monte_carlo_cycle(
        &compiled,
        &u0,
        &drive,
        &options,
        &outputs,
        &tolerances,
        &run,
    )
    .unwrap();
    let b = tolerance::monte_carlo_cycle(
        &run_time,
        &u0,
        &drive,
        &options,
        &outputs,
        &tolerances,
        &run,
    )
    .unwrap();
    assert_eq!(a.failures.len(), b.failures.len());
    for (x, y) in a
        .statistics
        .iter()
        .flatten()
        .zip(b.statistics.iter().flatten())
    {
        assert_eq!(x.count, y.count);
        assert_eq!(
            (x.mean.to_bits(), x.min.to_bits(), x.max.to_bits()),
            (y.mean.to_bits(), y.min.to_bits(), y.max.to_bits())
        );
    }
}

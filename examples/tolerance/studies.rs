//! The example's computations: a four-bar's outputs over the cycle and its
//! located extremes, and the shaper's stroke and time ratio, each linear
//! and by Monte Carlo.

use crate::machine::{COURSE_PROJECT, Shaper, synthesize};
use linkage::mechanisms::FourBar;
use linkage::num_dual::DualSVec64;
use linkage::prelude::*;
use linkage::tolerance::{
    self, Cycle, CycleSamples, MonteCarlo, Output, Spread, Statistics, Tolerance, Tolerances,
    gradient,
};
use linkage::watch::{Axis, FoundKind, Of, Watch, locate};
use std::f64::consts::{PI, TAU};

/// The Monte Carlo run of every study.
pub const RUN: MonteCarlo = MonteCarlo {
    samples: 100_000,
    random_state: 2026,
};

/// The crank's speed: 400 rpm, as in the worksheet.
const OMEGA2: f64 = 400.0 * TAU / 60.0;

/// The cycle's steps (3°).
const STEPS: usize = 120;

/// One four-bar's study.
pub struct CycleStudy {
    pub name: String,
    pub model: FourBar,
    pub tolerances: Tolerances<4>,
    /// The pose at θ2 = 0 the sweeps start from.
    pub start: SVector<f64, 2>,
    pub cycle: Cycle<2, 1, 4>,
    pub samples: CycleSamples<2, 1>,
    pub located: Vec<Located>,
}

impl CycleStudy {
    /// The dimension that adds most to output `o`'s worst case over the
    /// cycle.
    pub fn most_important(&self, o: usize) -> &'static str {
        most(&self.cycle.bands[o].contributions(&self.tolerances))
    }
}

/// A located quantity: linear against Monte Carlo.
pub struct Located {
    pub name: &'static str,
    pub nominal: f64,
    pub spread: Spread,
    /// What each dimension adds to the worst case.
    pub contributions: Vec<(&'static str, f64)>,
    pub most_important: &'static str,
    pub monte_carlo: Statistics,
}

/// The shaper's study.
pub struct ShaperStudy {
    pub name: String,
    pub located: Vec<Located>,
}

fn most<const K: usize>(contributions: &SVector<f64, K>) -> &'static str {
    FourBar::PARAM_NAMES
        .get(contributions.argmax().0)
        .copied()
        .unwrap_or("?")
}

/// How an output is printed: its unit and the factor from radians or mm.
pub fn unit(name: &str) -> (&'static str, f64) {
    match name {
        "theta4" | "transmission angle" => ("°", 180.0 / PI),
        "velocity of theta4" => ("rad/s", 1.0),
        "velocity of G3.x" | "velocity of G3.y" => ("mm/s", 1.0),
        "acceleration of theta4" => ("rad/s²", 1.0),
        _ => ("mm", 1.0),
    }
}

/// The worksheet's four-bar with the coupler `l3`, under ISO 2768-f.
pub fn four_bar(name: &str, l3: f64) -> Result<CycleStudy, Box<dyn std::error::Error>> {
    let model = FourBar {
        l3,
        ..FourBar::WORKSHEET
    };
    // ISO 2768-f: ±0.1 mm over 6–30 mm, ±0.15 mm over 30–120 mm.
    let band = |l: f64| Tolerance::Band(if l <= 30.0 { 0.1 } else { 0.15 });
    let tolerances = Tolerances::new([model.l1, model.l2, model.l3, model.l4].map(band))?;
    let u0 = start(&model)?;
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: STEPS,
    };
    let options = SweepOptions {
        speed: OMEGA2,
        ..SweepOptions::default()
    };
    let outputs = outputs();
    let cycle = tolerance::cycle(&model, &u0, &drive, &options, &outputs, &tolerances)?;
    let samples =
        tolerance::monte_carlo_cycle(&model, &u0, &drive, &options, &outputs, &tolerances, &RUN)?;
    let located = swing_and_ratio(&model, &u0, &tolerances)?;
    Ok(CycleStudy {
        name: name.into(),
        model,
        tolerances,
        start: u0,
        cycle,
        samples,
        located,
    })
}

/// The outputs followed over the four-bar's cycle.
fn outputs() -> Vec<Output<'static, 2, 1, 4>> {
    vec![
        Output::coordinate("theta4", Of::Position),
        Output::coordinate("theta4", Of::Velocity),
        Output::coordinate("theta4", Of::Acceleration),
        // The angle at C between the coupler C→B and the rocker C→D.
        Output::function("transmission angle", |p| {
            p.u[1] - p.u[0] + DualSVec64::from_re(PI)
        }),
        Output::path("G3"),
        // For drawing the band: the coupler curve and its direction.
        Output::point("G3", Axis::X, Of::Position),
        Output::point("G3", Axis::Y, Of::Position),
        Output::point("G3", Axis::X, Of::Velocity),
        Output::point("G3", Axis::Y, Of::Velocity),
    ]
}

/// The pose at θ2 = 0 on the worksheet's branch (θ3 > 0).
fn start(model: &FourBar) -> Result<SVector<f64, 2>, Box<dyn std::error::Error>> {
    let closed = model.closed_form();
    [1.0, -1.0]
        .into_iter()
        .filter_map(|sigma| closed.position(0.0, sigma))
        .find(|[theta3, _]| *theta3 > 0.0)
        .map(|[theta3, theta4]| vector![theta3, theta4])
        .ok_or_else(|| "the four-bar does not assemble at θ2 = 0".into())
}

/// The rocker's swing (largest minus smallest θ4) and the time ratio (the
/// crank's turn from the smallest θ4 to the largest, over the rest).
fn swing_and_ratio(
    model: &FourBar,
    u0: &SVector<f64, 2>,
    tolerances: &Tolerances<4>,
) -> Result<Vec<Located>, Box<dyn std::error::Error>> {
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 72,
    };
    let (swing, ratio, samples) = range_and_ratio(model, u0, &drive, "theta4", tolerances)?;
    Ok(vec![
        located(
            "rocker swing θ4,max − θ4,min [°]",
            swing * (180.0 / PI),
            tolerances,
            &FourBar::PARAM_NAMES,
            samples.iter().map(|s| s.0.to_degrees()),
        ),
        located(
            "time ratio (crank turn while θ4 rises / falls)",
            ratio,
            tolerances,
            &FourBar::PARAM_NAMES,
            samples.iter().map(|s| s.1),
        ),
    ])
}

/// The range (largest minus smallest) of the coordinate `name` along
/// `drive` and the time ratio (the driver's turn from its smallest to its
/// largest, over the rest): linear, with their gradients (the envelope
/// theorem at the located extremes), and by Monte Carlo (a sweep and the
/// extremes located again per sample; samples without both left out).
#[allow(clippy::type_complexity)]
fn range_and_ratio<L, const M: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<1>,
    name: &str,
    tolerances: &Tolerances<K>,
) -> Result<(DualSVec64<K>, DualSVec64<K>, Vec<(f64, f64)>), Box<dyn std::error::Error>>
where
    L: Sensitivities<M, 1, K> + Clone + Sync + Send,
{
    let options = SweepOptions::default();
    let sweep = model.sweep(u0, drive, &options)?;
    let output = Output::coordinate(name, Of::Position);
    let found = tolerance::extremes(model, &sweep, &output, &options.options)?;
    let (low, high) = extremes_pair(&found.iter().map(|f| (f.kind, f)).collect::<Vec<_>>())
        .ok_or_else(|| format!("{name} has no maximum and minimum"))?;
    let place = |l: &tolerance::Located<K>| l.v.expect("a coordinate's extreme has a known place");
    let range = high.value - low.value;
    let ratio = time_ratio(place(low), place(high));
    let samples = tolerance::monte_carlo(model, tolerances, &RUN, |sample: &L| {
        let sweep = sample.sweep(u0, drive, &options).ok()?;
        let watch = [Watch::coordinate(name, Of::Position).extrema()];
        let found = locate(sample, &sweep, &watch, &options.options).ok()?;
        let pairs: Vec<_> = found.iter().map(|f| (f.kind, (f.value, f.v[0]))).collect();
        let (low, high) = extremes_pair(&pairs)?;
        let ratio = time_ratio(DualSVec64::<1>::from_re(low.1), DualSVec64::from_re(high.1));
        Some((high.0 - low.0, ratio.re))
    })?;
    Ok((range, ratio, samples.into_iter().flatten().collect()))
}

/// The smallest and the largest of located extrema (by kind).
fn extremes_pair<T: Copy>(found: &[(FoundKind, T)]) -> Option<(T, T)> {
    let low = found.iter().find(|f| f.0 == FoundKind::Minimum)?.1;
    let high = found.iter().find(|f| f.0 == FoundKind::Maximum)?.1;
    Some((low, high))
}

/// The crank's turn from `low` to `high` over the turn back.
fn time_ratio<const K: usize>(low: DualSVec64<K>, high: DualSVec64<K>) -> DualSVec64<K> {
    let mut turn = high - low;
    if turn.re < 0.0 {
        turn += TAU;
    }
    turn / (-turn + TAU)
}

/// A located quantity with its linear spread and its Monte Carlo samples.
fn located<const K: usize>(
    name: &'static str,
    value: DualSVec64<K>,
    tolerances: &Tolerances<K>,
    names: &[&'static str; K],
    samples: impl Iterator<Item = f64>,
) -> Located {
    let g = gradient(&value);
    let contributions = tolerances.contributions(&g);
    Located {
        name,
        nominal: value.re,
        spread: tolerances.spread(&g),
        contributions: names
            .iter()
            .copied()
            .zip(contributions.iter().copied())
            .collect(),
        most_important: names[contributions.argmax().0],
        monte_carlo: Statistics::of(samples),
    }
}

/// The shaper's stroke and time ratio under tolerances on its lengths.
pub fn shaper() -> Result<ShaperStudy, Box<dyn std::error::Error>> {
    let model = synthesize(&COURSE_PROJECT)?;
    let tolerances = Tolerances::by_name(
        &Shaper::PARAM_NAMES,
        &[
            ("l_oa", Tolerance::Band(1e-4)),
            ("l_cd", Tolerance::Band(2e-4)),
            ("y_c", Tolerance::Band(1e-4)),
            ("y_f", Tolerance::Band(2e-4)),
        ],
    )?;
    // From just before the left dead position (φ = 0) round to it.
    let drive = Drive::Line {
        from: vector![-0.3],
        to: vector![TAU - 0.3],
        steps: 72,
    };
    let (stroke, ratio, samples) =
        range_and_ratio(&model, &model.guess(), &drive, "x_d", &tolerances)?;
    Ok(ShaperStudy {
        name: "the shaper of the course project".into(),
        located: vec![
            located(
                "stroke H [m]",
                stroke,
                &tolerances,
                &Shaper::PARAM_NAMES,
                samples.iter().map(|s| s.0),
            ),
            located(
                "time ratio K_V",
                ratio,
                &tolerances,
                &Shaper::PARAM_NAMES,
                samples.iter().map(|s| s.1),
            ),
        ],
    })
}

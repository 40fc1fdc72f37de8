//! The example's pictures, drawn with the library's `Chart`: the coupler
//! curve with its tolerance band, which dimension matters most, and the
//! linear σ against the Monte Carlo σ over the cycle.

use crate::studies::{CycleStudy, RUN, ShaperStudy};
use linkage::draw::chart::look::COLOURS;
use linkage::draw::chart::{Chart, Colour, Dash, DiagramError, Marker, Panel};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use linkage::tolerance::Band;

/// The deviations in the band picture are drawn this many times larger.
const MAGNIFY: f64 = 8.0;

/// The Monte Carlo designs drawn as curves in the band picture.
const CURVES: usize = 40;

const WORST: Colour = COLOURS[4];
const RSS: Colour = COLOURS[1];
const SAMPLE: Colour = COLOURS[0];

fn band<'s>(study: &'s CycleStudy, name: &str) -> &'s Band<1, 4> {
    study
        .cycle
        .band(name)
        .unwrap_or_else(|| panic!("the study follows `{name}`"))
}

/// The coupler curve of G3 with its band, normal to the curve: the linear
/// worst case and RSS, the Monte Carlo extremes of 100 000 designs, and
/// some of those designs' curves, every deviation magnified.
pub fn coupler_band(study: &CycleStudy) -> Result<String, DiagramError> {
    let (x, y) = (band(study, "G3.x"), band(study, "G3.y"));
    let (vx, vy) = (
        band(study, "velocity of G3.x"),
        band(study, "velocity of G3.y"),
    );
    let path = band(study, "path of G3");
    let o = study
        .cycle
        .bands
        .iter()
        .position(|b| b.name == "path of G3")
        .expect("the path is followed");
    let statistics = &study.samples.statistics[o];
    let normal: Vec<(f64, f64)> = (0..x.value.len())
        .map(|k| {
            let (a, b) = (vx.value[k], vy.value[k]);
            let n = a.hypot(b);
            (-b / n, a / n)
        })
        .collect();
    let offset = |k: usize, d: f64| {
        (
            x.value[k] + MAGNIFY * d * normal[k].0,
            y.value[k] + MAGNIFY * d * normal[k].1,
        )
    };
    let ring = |d: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        let n = x.value.len();
        let mut outline: Vec<(f64, f64)> = (0..n).map(|k| offset(k, d(k))).collect();
        outline.extend((0..n).rev().map(|k| offset(k, -d(k))));
        outline
    };
    let spread = |k: usize| path.spread[k].unwrap_or_default();
    // A few Monte Carlo designs' curves, their deviations magnified alike.
    let curves: Vec<Vec<(f64, f64)>> = (0..CURVES)
        .filter_map(|i| {
            let sample = RUN.sample(&study.model, &study.tolerances, i);
            let mut curve = Vec::new();
            let drive = Drive::Line {
                from: vector![0.0],
                to: vector![std::f64::consts::TAU],
                steps: x.value.len() - 1,
            };
            let g3 = FourBar::G3;
            let summary = sample
                .sweep_each(&study.start, &drive, &SweepOptions::default(), |p| {
                    let g3 = sample.point_positions(&p.u, &p.v).as_ref()[g3];
                    let k = p.step;
                    let (dx, dy) = (g3.x - x.value[k], g3.y - y.value[k]);
                    curve.push((x.value[k] + MAGNIFY * dx, y.value[k] + MAGNIFY * dy));
                })
                .ok()?;
            summary.complete.then_some(curve)
        })
        .collect();
    let extreme = |side: f64| -> Vec<(f64, f64)> {
        (0..x.value.len())
            .filter(|&k| statistics[k].count > 0)
            .map(|k| {
                let s = &statistics[k];
                offset(k, if side > 0.0 { s.max } else { s.min })
            })
            .collect()
    };
    let extremes_name = format!("the Monte Carlo extremes of {} designs", RUN.samples);
    let panel = Panel::new("y [mm]")
        .x_label("x [mm]")
        .equal_scales()
        .fill(
            "linear worst case Σ|∂n/∂l_i| t_i",
            ring(&|k| spread(k).worst_case),
        )
        .colour(WORST)
        .fill("linear RSS √Σ(∂n/∂l_i t_i)²", ring(&|k| spread(k).rss))
        .colour(RSS)
        .lines(
            &format!("{} of the Monte Carlo designs", curves.len()),
            curves,
        )
        .colour(SAMPLE)
        .dash(Dash::Solid)
        .faint()
        .lines(&extremes_name, vec![extreme(1.0), extreme(-1.0)])
        .colour(Colour::BLACK)
        .dash(Dash::Dashed)
        .width(0.8)
        .line(
            "nominal",
            (0..x.value.len())
                .map(|k| (x.value[k], y.value[k]))
                .collect(),
        )
        .colour(Colour::BLACK)
        .dash(Dash::Solid)
        .width(1.4);
    Chart::new(
        &format!(
            "{}: the coupler curve of G_3 and its tolerance band (ISO 2768-f), deviations ×{MAGNIFY}",
            study.name
        ),
        "",
    )
    .size(760, 660)
    .panel(panel)
    .render()
}

/// A parameter's name as the example's text writes it (`l_OA`).
fn shown(name: &str) -> String {
    match name.split_once('_') {
        Some((letter, index)) => format!("{letter}_{}", index.to_uppercase()),
        None => name.to_string(),
    }
}

/// The contributions of `names`, in their order (0 for a name not among
/// them).
fn in_order<'a>(contributions: &[(&str, f64)], names: &[&'a str]) -> Vec<(&'a str, f64)> {
    names
        .iter()
        .map(|n| {
            let value = contributions
                .iter()
                .find(|c| c.0 == *n)
                .map_or(0.0, |c| c.1);
            (*n, value)
        })
        .collect()
}

/// Which dimension matters most: each dimension's share of the worst case
/// of each quantity, one panel per mechanism, a group of bars per quantity.
pub fn importance(four_bar: &CycleStudy, shaper: &ShaperStudy) -> Result<String, DiagramError> {
    let share = |contributions: &[(&str, f64)]| -> Vec<f64> {
        let total: f64 = contributions.iter().map(|c| c.1).sum();
        contributions
            .iter()
            .map(|c| {
                if total > 0.0 {
                    100.0 * c.1 / total
                } else {
                    0.0
                }
            })
            .collect()
    };
    let names: Vec<String> = FourBar::PARAM_NAMES.iter().map(|n| shown(n)).collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let mut four = Panel::bars("share of the worst case [%]", &names)
        .caption("the Maple worksheet's four-bar")
        .y_range(0.0, 100.0);
    for name in ["path of G3", "theta4", "transmission angle"] {
        let b = band(four_bar, name);
        let c = b.contributions(&four_bar.tolerances);
        let shown_name = match name {
            "theta4" => "θ_4 at its worst",
            "path of G3" => "path of G_3 at its worst",
            _ => "transmission angle at its worst",
        };
        let pairs: Vec<(&str, f64)> = FourBar::PARAM_NAMES
            .iter()
            .copied()
            .zip(c.iter().copied())
            .collect();
        four = four.group(shown_name, &share(&pairs));
    }
    for located in &four_bar.located {
        let pairs = in_order(&located.contributions, &FourBar::PARAM_NAMES);
        four = four.group(located.name, &share(&pairs));
    }
    const SHAPER: [&str; 4] = ["l_oa", "l_cd", "y_c", "y_f"];
    let shaper_names: Vec<String> = SHAPER.iter().map(|n| shown(n)).collect();
    let shaper_names: Vec<&str> = shaper_names.iter().map(String::as_str).collect();
    let mut machine = Panel::bars("share of the worst case [%]", &shaper_names)
        .caption("the Mathcad course project's shaper")
        .y_range(0.0, 100.0);
    for located in &shaper.located {
        let kept = in_order(&located.contributions, &SHAPER);
        machine = machine.group(located.name, &share(&kept));
    }
    Chart::new(
        "Which dimension matters most: each one's share of the linear worst case Σ|∂y/∂p_i| t_i",
        "",
    )
    .note("four-bar: ISO 2768-f on l_1…l_4; shaper: ±0.1 mm on l_OA and l_OC (y_C), ±0.2 mm on l_CD and the guide height y_F")
    .size(900, 420)
    .columns(1)
    .panel(four)
    .panel(machine)
    .render()
}

/// σ of the rocker's angle and acceleration over the cycle, linear against
/// Monte Carlo, for the worksheet's four-bar and for the one near the
/// Grashof limit.
pub fn linear_vs_monte_carlo(
    worksheet: &CycleStudy,
    near_limit: &CycleStudy,
) -> Result<String, DiagramError> {
    let quantities = [
        ("theta4", "σ of θ_4 [°]", 180.0 / std::f64::consts::PI),
        ("acceleration of theta4", "σ of α_4 [rad/s²]", 1.0),
    ];
    let mut chart = Chart::new(
        &format!(
            "Standard deviations over the cycle: linear (exact sensitivities) against {} Monte Carlo designs",
            RUN.samples
        ),
        "crank angle θ_2 [°]",
    )
    .note("ISO 2768-f on l_1…l_4, 400 rpm; the Monte Carlo σ over the designs that run the whole cycle (those that lock up are left out)")
    .columns(2)
    .size(1000, 400);
    for &(name, label, scale) in &quantities {
        for study in [worksheet, near_limit] {
            chart = chart.panel(sigma_panel(study, name, label, scale));
        }
    }
    chart.render()
}

/// One output's linear and Monte Carlo σ against the crank angle.
fn sigma_panel(study: &CycleStudy, name: &str, label: &str, scale: f64) -> Panel {
    let b = band(study, name);
    let o = study
        .cycle
        .bands
        .iter()
        .position(|c| c.name == name)
        .expect("the output is followed");
    let deg = 180.0 / std::f64::consts::PI;
    let linear: Vec<(f64, f64)> = (0..b.v.len())
        .filter_map(|k| Some((b.v[k][0] * deg, b.spread[k]?.sigma * scale)))
        .collect();
    let statistics = &study.samples.statistics[o];
    let sampled: Vec<(f64, f64)> = (0..b.v.len())
        .filter(|&k| statistics[k].count > 1)
        .map(|k| (b.v[k][0] * deg, statistics[k].std() * scale))
        .collect();
    let values = || linear.iter().chain(&sampled).map(|p| p.1);
    let top = values().fold(0.0, f64::max);
    let bottom = values().fold(f64::INFINITY, f64::min);
    let failed = study.samples.failures.len();
    let panel = Panel::new(label)
        .caption(&format!(
            "{} ({failed} of {} designs lock up)",
            study.name, study.samples.samples
        ))
        .x_range(0.0, 360.0)
        .line("linear σ", linear)
        .colour(RSS)
        .dash(Dash::Solid)
        .points("Monte Carlo σ", sampled)
        .colour(SAMPLE)
        .marker(Marker::Circle)
        .open();
    // A log axis where σ spans a decade or more, else a linear one from
    // zero (whose ticks can be read).
    if top / bottom > 10.0 {
        panel.y_log()
    } else {
        panel.y_range(0.0, top * 1.15)
    }
}

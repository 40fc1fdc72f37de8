//! The example's pictures, as SVG: the coupler curve with its tolerance
//! band, which dimension matters most, and the linear σ against the Monte
//! Carlo σ over the cycle.

use crate::studies::{CycleStudy, RUN, ShaperStudy};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use linkage::tolerance::Band;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use crate::page::{Area, Drawn, page};

/// The deviations in the band picture are drawn this many times larger.
const MAGNIFY: f64 = 8.0;

/// The Monte Carlo designs drawn as curves in the band picture.
const CURVES: usize = 40;

const WORST: RGBColor = RGBColor(250, 205, 140);
const RSS: RGBColor = RGBColor(230, 140, 20);
const NOMINAL: RGBColor = RGBColor(20, 20, 20);
const SAMPLE: RGBColor = RGBColor(40, 110, 200);

fn band<'s>(study: &'s CycleStudy, name: &str) -> &'s Band<1, 4> {
    study
        .cycle
        .band(name)
        .unwrap_or_else(|| panic!("the study follows `{name}`"))
}

/// The coupler curve of G3 with its band, normal to the curve: the linear
/// worst case and RSS, the Monte Carlo extremes of 100 000 designs, and
/// some of those designs' curves, every deviation magnified.
pub fn coupler_band(study: &CycleStudy) -> Result<String, Box<dyn std::error::Error>> {
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
            let g3 = FourBar::point_index("G3")?;
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
    let (xs, ys): (Vec<f64>, Vec<f64>) = ring(&|k| spread(k).worst_case).into_iter().unzip();
    let (x0, x1) = bounds(&xs);
    let (y0, y1) = bounds(&ys);
    // Equal scales on both axes: the plot area is about 826 × 626 px.
    let (width, height) = (826.0, 626.0);
    let scale = ((x1 - x0) / width).max((y1 - y0) / height) * 1.1;
    let (xm, ym) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (x0, x1) = (xm - 0.5 * scale * width, xm + 0.5 * scale * width);
    let (y0, y1) = (ym - 0.5 * scale * height, ym + 0.5 * scale * height);
    page((900, 760), |root| {
        let (top, body) = root.split_vertically(70);
        top.draw(&Text::new(
            format!(
                "{}: the coupler curve of G3 and its tolerance band (ISO 2768-f), deviations ×{MAGNIFY}",
                study.name
            ),
            (14, 10),
            ("sans-serif", 17).into_font(),
        ))?;
        let mut chart = ChartBuilder::on(&body)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .bold_line_style(BLACK.mix(0.08))
            .x_desc("x [mm]")
            .y_desc("y [mm]")
            .draw()?;
        chart
            .draw_series(std::iter::once(Polygon::new(
                ring(&|k| spread(k).worst_case),
                WORST.filled(),
            )))?
            .label("linear worst case Σ|∂n/∂lᵢ| tᵢ")
            .legend(|(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], WORST.filled()));
        chart
            .draw_series(std::iter::once(Polygon::new(
                ring(&|k| spread(k).rss),
                RSS.mix(0.55).filled(),
            )))?
            .label("linear RSS √Σ(∂n/∂lᵢ tᵢ)²")
            .legend(|(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], RSS.mix(0.55).filled()));
        for (i, curve) in curves.iter().enumerate() {
            let series = chart.draw_series(LineSeries::new(curve.clone(), SAMPLE.mix(0.35)))?;
            if i == 0 {
                series
                    .label(format!("{} of the Monte Carlo designs", curves.len()))
                    .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], SAMPLE.mix(0.6)));
            }
        }
        for (side, label) in [(1.0, true), (-1.0, false)] {
            let edge: Vec<(f64, f64)> = (0..x.value.len())
                .filter(|&k| statistics[k].count > 0)
                .map(|k| {
                    let s = &statistics[k];
                    offset(k, if side > 0.0 { s.max } else { s.min })
                })
                .collect();
            let series =
                chart.draw_series(DashedLineSeries::new(edge, 6, 4, BLACK.stroke_width(1)))?;
            if label {
                series
                    .label(format!(
                        "dashed: the Monte Carlo extremes of {} designs",
                        RUN.samples
                    ))
                    .legend(|(x, y)| PathElement::new([(x, y), (x + 6, y)], BLACK));
            }
        }
        chart
            .draw_series(LineSeries::new(
                (0..x.value.len()).map(|k| (x.value[k], y.value[k])),
                NOMINAL.stroke_width(2),
            ))?
            .label("nominal")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], NOMINAL.stroke_width(2)));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.3))
            .label_font(("sans-serif", 13))
            .draw()?;
        Ok(())
    })
}

fn bounds(values: &[f64]) -> (f64, f64) {
    values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        })
}

/// Which dimension matters most: each dimension's share of the worst case,
/// one panel per quantity.
pub fn importance(
    four_bar: &CycleStudy,
    shaper: &ShaperStudy,
) -> Result<String, Box<dyn std::error::Error>> {
    let mut panels: Vec<(String, Vec<(&'static str, f64)>)> = Vec::new();
    for name in ["path of G3", "theta4", "transmission angle"] {
        let b = band(four_bar, name);
        let c = b.contributions(&four_bar.tolerances);
        let shown = if name == "theta4" { "θ4" } else { name };
        panels.push((
            format!("four-bar: {shown} (at its worst over the cycle)"),
            FourBar::PARAM_NAMES
                .iter()
                .copied()
                .zip(c.iter().copied())
                .collect(),
        ));
    }
    for located in four_bar.located.iter().chain(&shaper.located) {
        let owner = if four_bar.located.iter().any(|l| std::ptr::eq(l, located)) {
            "four-bar"
        } else {
            "shaper"
        };
        let shown: Vec<_> = located
            .contributions
            .iter()
            .copied()
            .filter(|(name, _)| {
                owner == "four-bar" || ["l_oa", "l_cd", "y_c", "y_f"].contains(name)
            })
            .collect();
        panels.push((format!("{owner}: {}", located.name), shown));
    }
    let columns = 4;
    let rows = panels.len().div_ceil(columns);
    page((1200, 90 + 260 * rows as u32), |root| {
        let (top, body) = root.split_vertically(60);
        top.draw(&Text::new(
            "Which dimension matters most: each one's share of the linear worst case Σ|∂y/∂pᵢ| tᵢ, %",
            (14, 10),
            ("sans-serif", 17).into_font(),
        ))?;
        top.draw(&Text::new(
            "four-bar: ISO 2768-f on l1…l4; shaper: ±0.1 mm on l_OA and l_OC (y_c), ±0.2 mm on l_CD and the guide height y_F",
            (14, 36),
            ("sans-serif", 13).into_font(),
        ))?;
        let areas = body.split_evenly((rows, columns));
        for (area, (title, bars)) in areas.iter().zip(&panels) {
            let total: f64 = bars.iter().map(|b| b.1).sum();
            let mut chart = ChartBuilder::on(area)
                .caption(title, ("sans-serif", 13))
                .margin(10)
                .x_label_area_size(28)
                .y_label_area_size(40)
                .build_cartesian_2d((0..bars.len() - 1).into_segmented(), 0.0..100.0)?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .bold_line_style(BLACK.mix(0.08))
                .disable_x_mesh()
                .x_label_formatter(&|x| match x {
                    SegmentValue::CenterOf(i) => {
                        bars.get(*i).map(|b| b.0.to_owned()).unwrap_or_default()
                    }
                    _ => String::new(),
                })
                .y_labels(6)
                .draw()?;
            chart.draw_series(bars.iter().enumerate().map(|(i, b)| {
                let share = if total > 0.0 {
                    100.0 * b.1 / total
                } else {
                    0.0
                };
                let mut bar = Rectangle::new(
                    [
                        (SegmentValue::Exact(i), 0.0),
                        (SegmentValue::Exact(i + 1), share),
                    ],
                    RSS.filled(),
                );
                bar.set_margin(0, 0, 8, 8);
                bar
            }))?;
        }
        Ok(())
    })
}

/// σ of the rocker's angle and acceleration over the cycle, linear against
/// Monte Carlo, for the worksheet's four-bar and for the one near the
/// Grashof limit.
pub fn linear_vs_monte_carlo(
    worksheet: &CycleStudy,
    near_limit: &CycleStudy,
) -> Result<String, Box<dyn std::error::Error>> {
    page((1200, 860), |root| {
        let (top, body) = root.split_vertically(60);
        top.draw(&Text::new(
            format!(
                "Standard deviations over the cycle: linear (exact sensitivities) against {} Monte Carlo designs",
                RUN.samples
            ),
            (14, 10),
            ("sans-serif", 17).into_font(),
        ))?;
        top.draw(&Text::new(
            "ISO 2768-f on l1…l4, 400 rpm; the Monte Carlo σ over the designs that run the whole cycle (those that lock up are left out)",
            (14, 36),
            ("sans-serif", 13).into_font(),
        ))?;
        let panels = body.split_evenly((2, 2));
        let quantities = [
            ("theta4", "σ of θ4 [°]", 180.0 / std::f64::consts::PI),
            ("acceleration of theta4", "σ of α4 [rad/s²]", 1.0),
        ];
        let cells = quantities
            .iter()
            .flat_map(|q| [(q, worksheet), (q, near_limit)]);
        for (area, (&(name, label, scale), study)) in panels.iter().zip(cells) {
            sigma_panel(area, study, name, label, scale)?;
        }
        Ok(())
    })
}

/// One output's linear and Monte Carlo σ against the crank angle.
fn sigma_panel(area: &Area<'_>, study: &CycleStudy, name: &str, label: &str, scale: f64) -> Drawn {
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
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(
            format!(
                "{} ({failed} of {} designs lock up)",
                study.name, study.samples.samples
            ),
            ("sans-serif", 14),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64);
    // A log axis where σ spans a decade or more, else a linear one (whose
    // ticks can be read).
    if top / bottom > 10.0 {
        let chart =
            builder.build_cartesian_2d(0.0..360.0, (bottom * 0.7..top * 1.6).log_scale())?;
        sigma_series(chart, label, linear, sampled)
    } else {
        let chart = builder.build_cartesian_2d(0.0..360.0, 0.0..top * 1.25)?;
        sigma_series(chart, label, linear, sampled)
    }
}

/// The linear σ as a line and the Monte Carlo σ as circles, on `chart`.
fn sigma_series<'a, Y>(
    mut chart: ChartContext<'a, SVGBackend<'a>, Cartesian2d<RangedCoordf64, Y>>,
    label: &str,
    linear: Vec<(f64, f64)>,
    sampled: Vec<(f64, f64)>,
) -> Drawn
where
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("crank angle θ2 [°]")
        .y_desc(label)
        .x_labels(9)
        .y_labels(8)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_label_formatter(&|y| format!("{y:.2}"))
        .draw()?;
    chart
        .draw_series(LineSeries::new(linear, RSS.stroke_width(2)))?
        .label("linear σ")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], RSS.stroke_width(2)));
    chart
        .draw_series(PointSeries::of_element(
            sampled,
            3,
            SAMPLE.stroke_width(1),
            &|c, s, st| Circle::new(c, s, st),
        ))?
        .label("Monte Carlo σ")
        .legend(|(x, y)| Circle::new((x + 10, y), 3, SAMPLE.stroke_width(1)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .label_font(("sans-serif", 13))
        .draw()?;
    Ok(())
}

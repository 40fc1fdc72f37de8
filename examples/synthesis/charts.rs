//! The example's pictures, as SVG: the targets on the worksheet's coupler
//! curve, the designs drawn at several poses with their coupler curves
//! through the targets, and the convergence of each method (error against
//! wall time).

use crate::Series;
use crate::results::{Design, Method};
use linkage::mechanisms::CouplerFourBar;
use linkage::prelude::*;
use plotters::prelude::*;
use std::f64::consts::TAU;

use crate::page::{Area, Drawn, page};

const OURS: Colour = COLOURS[0];
const PSO: Colour = COLOURS[1];
const DE: Colour = COLOURS[2];
const BURMESTER: Colour = COLOURS[3];
const TARGET: RGBColor = RGBColor(200, 30, 30);
const LINK: RGBColor = RGBColor(40, 40, 40);

/// A title line and a smaller note under it.
fn heading(area: &Area<'_>, title: &str, note: &str) -> Drawn {
    area.draw(&Text::new(
        title.to_owned(),
        (14, 10),
        ("sans-serif", 17).into_font(),
    ))?;
    area.draw(&Text::new(
        note.to_owned(),
        (14, 36),
        ("sans-serif", 13).into_font(),
    ))?;
    Ok(())
}

/// Ranges holding `points` with equal scales on both axes, for a plot area
/// of `width` × `height` pixels, with a margin of 8 %.
fn equal_ranges(
    points: impl Iterator<Item = (f64, f64)>,
    (width, height): (f64, f64),
) -> ((f64, f64), (f64, f64)) {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for (x, y) in points {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    let scale = ((x1 - x0) / width).max((y1 - y0) / height) * 1.16;
    let (xm, ym) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    (
        (xm - 0.5 * scale * width, xm + 0.5 * scale * width),
        (ym - 0.5 * scale * height, ym + 0.5 * scale * height),
    )
}

/// The joints A, B, C, D and P of `model` at the pose `u`, θ2 = `v`.
fn joints(model: &CouplerFourBar, u: &SVector<f64, 2>, v: f64) -> [(f64, f64); 5] {
    let p = model.point_positions(u, &vector![v]);
    let at = |q: Vector2<f64>| (q.x, q.y);
    [
        (model.xa, model.ya),
        at(p[CouplerFourBar::B]),
        at(p[CouplerFourBar::C]),
        (model.xd, model.yd),
        at(p[CouplerFourBar::P]),
    ]
}

/// The poses of a turn from `u` at θ2 = `v` at `count` evenly spaced
/// crank angles.
fn poses(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
    count: usize,
) -> Vec<[(f64, f64); 5]> {
    let drive = Drive::Line {
        from: vector![v],
        to: vector![v + TAU],
        steps: 360,
    };
    let Ok(sweep) = model.sweep(u, &drive, &SweepOptions::default()) else {
        return Vec::new();
    };
    let every = (sweep.poses.len() / count).max(1);
    sweep
        .poses
        .iter()
        .step_by(every)
        .take(count)
        .map(|p| joints(model, &p.u, p.v[0]))
        .collect()
}

/// What a mechanism panel shows: a design at its pose `u`, θ2 = `v`, its
/// coupler curve, the targets, and how many poses of its turn.
struct Panel<'a> {
    model: &'a CouplerFourBar,
    u: &'a SVector<f64, 2>,
    v: f64,
    curve: &'a [(f64, f64)],
    targets: &'a [Vector2<f64>],
    shown: usize,
    colour: RGBColor,
}

/// One mechanism panel: the coupler curve, the targets numbered, and the
/// mechanism at `shown` poses (the first dark, the others light).
fn mechanism_panel(area: &Area<'_>, caption: &str, panel: Panel<'_>) -> Drawn {
    let Panel {
        model,
        u,
        v,
        curve,
        targets,
        shown,
        colour,
    } = panel;
    let drawn = poses(model, u, v, shown);
    let (w, h) = area.dim_in_pixel();
    let plot = (f64::from(w) - 80.0, f64::from(h) - 80.0);
    let (xs, ys) = equal_ranges(
        curve
            .iter()
            .copied()
            .chain(targets.iter().map(|t| (t.x, t.y)))
            .chain(drawn.iter().flatten().copied()),
        plot,
    );
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 14))
        .margin(10)
        .x_label_area_size(32)
        .y_label_area_size(42)
        .build_cartesian_2d(xs.0..xs.1, ys.0..ys.1)?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("x [mm]")
        .y_desc("y [mm]")
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_label_formatter(&|y| format!("{y:.0}"))
        .draw()?;
    for (i, pose) in drawn.iter().enumerate().rev() {
        let [a, b, c, d, p] = *pose;
        let style = if i == 0 {
            LINK.stroke_width(2)
        } else {
            LINK.mix(0.22).stroke_width(1)
        };
        chart.draw_series(std::iter::once(PathElement::new(vec![a, b, c, d], style)))?;
        chart.draw_series(std::iter::once(Polygon::new(
            vec![b, c, p],
            if i == 0 {
                colour.mix(0.25)
            } else {
                colour.mix(0.06)
            },
        )))?;
        chart.draw_series(std::iter::once(PathElement::new(vec![b, p, c], style)))?;
        if i == 0 {
            chart.draw_series(DashedLineSeries::new(
                vec![a, d],
                4,
                4,
                LINK.mix(0.5).stroke_width(1),
            ))?;
            for pivot in [a, d] {
                chart.draw_series(std::iter::once(TriangleMarker::new(
                    pivot,
                    7,
                    LINK.filled(),
                )))?;
            }
            chart.draw_series([b, c, p].map(|q| Circle::new(q, 3, LINK.filled())))?;
        }
    }
    chart.draw_series(LineSeries::new(curve.to_vec(), colour.stroke_width(2)))?;
    chart.draw_series(
        targets
            .iter()
            .map(|t| Cross::new((t.x, t.y), 5, TARGET.stroke_width(2))),
    )?;
    chart.draw_series(targets.iter().enumerate().map(|(i, t)| {
        EmptyElement::at((t.x, t.y))
            + Text::new(
                format!("{i}"),
                (6, -16),
                ("sans-serif", 12).into_font().color(&TARGET),
            )
    }))?;
    Ok(())
}

/// The worksheet's four-bar at θ2 = 0 with its coupler curve of G3 and the
/// targets taken on it, one panel per target count.
pub fn targets(sets: &[Vec<Vector2<f64>>]) -> Result<String, Box<dyn std::error::Error>> {
    let model = CouplerFourBar::WORKSHEET;
    let u = vector![1.3, -0.8];
    let curve: Vec<(f64, f64)> = poses(&model, &u, 0.0, 361).iter().map(|j| j[4]).collect();
    page((1100, 560), |root| {
        let (top, body) = root.split_vertically(64);
        heading(
            &top,
            "The targets: points of the Maple worksheet's coupler curve of G3 at evenly spaced crank angles",
            "The worksheet's four-bar (l = 80, 20, 50, 70 mm; G3 the coupler's midpoint) at θ2 = 0, where it meets target 0; target k at θ2 = 360°·k/n",
        )?;
        let panels = body.split_evenly((1, sets.len()));
        for (area, set) in panels.iter().zip(sets) {
            mechanism_panel(
                area,
                &format!("{} targets", set.len()),
                Panel {
                    model: &model,
                    u: &u,
                    v: 0.0,
                    curve: &curve,
                    targets: set,
                    shown: 1,
                    colour: RGBColor(120, 120, 120),
                },
            )?;
        }
        Ok(())
    })
}

/// The best design of each tool on each path task, drawn at several poses
/// with its coupler curve through the targets.
pub fn designs(
    methods: &[Method],
    sets: &[Vec<Vector2<f64>>],
) -> Result<String, Box<dyn std::error::Error>> {
    let tools: Vec<&str> = ["linkage", "pylinkage"]
        .into_iter()
        .filter(|tool| methods.iter().any(|m| m.tool == *tool))
        .collect();
    let rows = sets.len();
    page((560 * tools.len() as u32, 90 + 500 * rows as u32), |root| {
        let (top, body) = root.split_vertically(64);
        heading(
            &top,
            "The best design of each tool, at several poses, with its coupler curve through the targets (×)",
            "Error: the largest distance of a target from the design's swept curve; verdict: linkage's certificate over a whole turn",
        )?;
        let panels = body.split_evenly((rows, tools.len()));
        let mut k = 0;
        for set in sets {
            let task = format!("path{}", set.len());
            for tool in &tools {
                let best: Option<(&Method, &Design)> = methods
                    .iter()
                    .filter(|m| m.tool == *tool && m.task == task)
                    .filter_map(|m| Some((m, m.best()?)))
                    .min_by(|a, b| a.1.judged.error().total_cmp(&b.1.judged.error()));
                let area = &panels[k];
                k += 1;
                let Some((method, design)) = best else {
                    area.draw(&Text::new(
                        format!("{tool}: no design through {} points", set.len()),
                        (30, 40),
                        ("sans-serif", 15).into_font(),
                    ))?;
                    continue;
                };
                let Some((model, u, v)) = &design.drawn else {
                    continue;
                };
                let curve: Vec<(f64, f64)> =
                    design.judged.curve.iter().map(|p| (p.x, p.y)).collect();
                let colour = colour_of(&format!("{tool}: {}", method.name));
                mechanism_panel(
                    area,
                    &format!(
                        "{tool}: {}, {} points — error {:.1e} mm, {}",
                        method.name,
                        set.len(),
                        design.judged.error(),
                        design.judged.verdict.describe()
                    ),
                    Panel {
                        model,
                        u,
                        v: *v,
                        curve: &curve,
                        targets: set,
                        shown: 5,
                        colour,
                    },
                )?;
            }
        }
        Ok(())
    })
}

fn colour_of(label: &str) -> Colour {
    if label.starts_with("linkage") {
        OURS
    } else if label.contains("PSO") {
        PSO
    } else if label.contains("differential") {
        DE
    } else {
        BURMESTER
    }
}

/// Error against wall time, one panel per path task: our runs with growing
/// budgets, pylinkage's optimisers' best design so far in each run, its
/// Burmester runs.
pub fn convergence(series: &[Series]) -> Result<String, DiagramError> {
    let tasks: Vec<&str> = {
        let mut t: Vec<&str> = series.iter().map(|s| s.task.as_str()).collect();
        t.dedup();
        t
    };
    let all = || series.iter().flat_map(|s| &s.points).filter(|p| p.1 > 0.0);
    let t0 = all().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let t1 = all().map(|p| p.0).fold(0.0, f64::max);
    let e0 = all().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let e1 = all().map(|p| p.1).fold(0.0, f64::max);
    let (t0, t1) = (
        10f64.powf(t0.log10().floor()),
        10f64.powf(t1.log10().ceil()),
    );
    let (e0, e1) = (
        10f64.powf(e0.log10().floor()),
        10f64.powf(e1.log10().ceil() + 1.0),
    );
    let mut chart = Chart::new(
        "Convergence: the error of the best design so far against wall time",
        "wall time [s]",
    )
    .note("linkage: one run per budget of random starts (each a separate run, timed whole); pylinkage: each optimiser run's best design so far; error judged the same way for both")
    .columns(tasks.len())
    .size(1000, 460)
    .shared_legend();
    for task in &tasks {
        let mut panel = Panel::new("largest distance of a target from the curve [mm]")
            .caption(&format!("{} targets", &task[4..]))
            .x_log()
            .y_log()
            .x_range(t0, t1)
            .y_range(e0, e1);
        // Methods without a design: a note, not a legend entry.
        let notes = series
            .iter()
            .filter(|s| s.task == *task && s.points.is_empty());
        for (i, s) in notes.enumerate() {
            let y = (e0.log10() + (0.55 - 0.07 * i as f64) * (e1.log10() - e0.log10())).exp10();
            panel = panel.note((t0 * 1.5, y), &format!("{}: no design", s.label));
        }
        // The runs of one method under one name (a line each, one entry).
        let mut keys: Vec<(String, bool)> = Vec::new();
        for s in series
            .iter()
            .filter(|s| s.task == *task && !s.points.is_empty())
        {
            let key = s.label.split(", run").next().unwrap_or(&s.label).to_owned();
            if !keys.iter().any(|k| k.0 == key) {
                keys.push((key, s.line));
            }
        }
        for (key, line) in keys {
            let runs: Vec<Vec<(f64, f64)>> = series
                .iter()
                .filter(|s| s.task == *task && s.label.split(", run").next() == Some(key.as_str()))
                .map(|s| s.points.iter().copied().filter(|p| p.1 > 0.0).collect())
                .collect();
            let colour = colour_of(&key);
            panel = if !line {
                let points = runs.into_iter().flatten().collect();
                let shaped = panel
                    .points(&key, points)
                    .colour(colour)
                    .marker(Marker::Triangle);
                if key.contains("max_solutions 1)") {
                    shaped
                } else {
                    shaped.open()
                }
            } else if key.starts_with("linkage") {
                let points = runs.into_iter().flatten().collect();
                panel
                    .line_and_points(&key, points)
                    .colour(colour)
                    .dash(Dash::Solid)
                    .marker(Marker::Circle)
                    .width(1.4)
            } else {
                let dash = if key.contains("PSO") {
                    Dash::Solid
                } else {
                    Dash::Dashed
                };
                panel.lines(&key, runs).colour(colour).dash(dash).width(0.7)
            };
        }
        chart = chart.panel(panel);
    }
    chart.render()
}

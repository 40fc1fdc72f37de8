//! The example's pictures, drawn with the library: the targets on the
//! worksheet's coupler curve and the designs at several poses with their
//! coupler curves through the targets (scenes on a sheet), and the
//! convergence of each method (a chart of error against wall time).

use crate::Series;
use crate::results::{Design, Method};
use linkage::draw::chart::look::COLOURS;
use linkage::draw::chart::{Chart, Colour, Dash, DiagramError, Marker, Panel};
use linkage::draw::scene::{Curve, Frame, MarkerShape, Markers, Scene, SceneError, Sheet};
use linkage::mechanisms::CouplerFourBar;
use linkage::prelude::*;
use std::f64::consts::TAU;

const OURS: Colour = COLOURS[0];
const PSO: Colour = COLOURS[1];
const DE: Colour = COLOURS[2];
const BURMESTER: Colour = COLOURS[3];

/// The width of one scene on a sheet of two side by side (the widest at
/// which a sheet of two still prints its text at 7 pt or more).
const SCENE_WIDTH: f64 = 400.0;

/// The poses of a turn from `u` at θ2 = `v` at `count` evenly spaced
/// crank angles (the first at `v`).
fn turn(model: &CouplerFourBar, u: &SVector<f64, 2>, v: f64, count: usize) -> Vec<Frame> {
    let drive = Drive::Line {
        from: vector![v],
        to: vector![v + TAU],
        steps: 360,
    };
    let Ok(sweep) = model.sweep(u, &drive, &SweepOptions::default()) else {
        return Vec::new();
    };
    let every = (sweep.poses.len() / count.max(1)).max(1);
    sweep
        .poses
        .iter()
        .step_by(every)
        .take(count)
        .map(|p| Frame::positions(model, &p.u, &p.v))
        .collect()
}

/// A design at its pose `u`, θ2 = `v`, faint at `shown − 1` more poses of
/// its turn, with its coupler curve and the targets numbered from 0.
#[allow(clippy::too_many_arguments)]
fn design_scene(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
    curve: &[Vector2<f64>],
    targets: &[Vector2<f64>],
    shown: usize,
    colour: Colour,
    title: &str,
) -> Result<String, SceneError> {
    let frames = turn(model, u, v, shown);
    let frame = frames
        .first()
        .cloned()
        .unwrap_or_else(|| Frame::positions(model, u, &vector![v]));
    Scene::new()
        .ground("A", [model.xa, model.ya])
        .ground("D", [model.xd, model.yd])
        .link(["A", "B"])
        .plate(["B", "C", "P"])
        .link(["C", "D"])
        .ghosts(frames.get(1..).unwrap_or(&[]))
        .curve(Curve::new("coupler curve of P", curve.iter().copied()).colour(&colour.to_string()))
        .markers(
            Markers::new("targets", targets.iter().copied())
                .shape(MarkerShape::Cross)
                .colour("#C62828")
                .numbered_from(0),
        )
        .title(title)
        .width(SCENE_WIDTH)
        .render(&frame, &[])
}

/// The worksheet's four-bar at θ2 = 0 with its coupler curve of G3 and the
/// targets taken on it, one picture per target count.
pub fn targets(sets: &[Vec<Vector2<f64>>]) -> Result<String, SceneError> {
    let model = CouplerFourBar::WORKSHEET;
    let u = vector![1.3, -0.8];
    let curve: Vec<Vector2<f64>> = turn(&model, &u, 0.0, 361)
        .iter()
        .filter_map(|f| f.position("P"))
        .collect();
    let mut sheet = Sheet::new(
        "The targets: points of the Maple worksheet's coupler curve of G3 at evenly spaced crank angles",
    )
    .subtitle("The worksheet's four-bar (l = 80, 20, 50, 70 mm; G3 the coupler's midpoint, here P) at θ2 = 0, where it meets target 0; target k at θ2 = 360°·k/n")
    .columns(sets.len().max(1));
    for set in sets {
        sheet = sheet.picture(design_scene(
            &model,
            &u,
            0.0,
            &curve,
            set,
            1,
            Colour::GREY,
            &format!("{} targets", set.len()),
        )?);
    }
    sheet.render()
}

/// The best design of each tool on each path task, drawn at several poses
/// with its coupler curve through the targets.
pub fn designs(methods: &[Method], sets: &[Vec<Vector2<f64>>]) -> Result<String, SceneError> {
    let tools: Vec<&str> = ["linkage", "pylinkage"]
        .into_iter()
        .filter(|tool| methods.iter().any(|m| m.tool == *tool))
        .collect();
    let mut sheet = Sheet::new(
        "The best design of each tool, at several poses (faint), with its coupler curve through the targets (×)",
    )
    .subtitle("Error: the largest distance of a target from the design's swept curve; verdict: linkage's certificate over a whole turn")
    .columns(tools.len().max(1));
    for set in sets {
        let task = format!("path{}", set.len());
        for tool in &tools {
            let best: Option<(&Method, &Design)> = methods
                .iter()
                .filter(|m| m.tool == *tool && m.task == task)
                .filter_map(|m| Some((m, m.best()?)))
                .min_by(|a, b| a.1.judged.error().total_cmp(&b.1.judged.error()));
            let Some((method, design)) = best else {
                continue;
            };
            let Some((model, u, v)) = &design.drawn else {
                continue;
            };
            let title = format!(
                "{tool}: {}, {} points — error {:.1e} mm, {}",
                method.name,
                set.len(),
                design.judged.error(),
                design.judged.verdict.describe()
            );
            let colour = colour_of(&format!("{tool}: {}", method.name));
            sheet = sheet.picture(design_scene(
                model,
                u,
                *v,
                &design.judged.curve,
                set,
                5,
                colour,
                &title,
            )?);
        }
    }
    sheet.render()
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
        let missing: Vec<String> = series
            .iter()
            .filter(|s| s.task == *task && s.points.is_empty())
            .map(|s| s.label.replace('_', "\\_"))
            .collect();
        if !missing.is_empty() {
            let y = 10f64.powf(e0.log10() + 0.62 * (e1.log10() - e0.log10()));
            panel = panel.note((t0 * 1.5, y), &missing.join("; "));
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
            let name = key.replace('_', "\\_");
            panel = if !line {
                let points = runs.into_iter().flatten().collect();
                let shaped = panel
                    .points(&name, points)
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
                    .line_and_points(&name, points)
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
                panel
                    .lines(&name, runs)
                    .colour(colour)
                    .dash(dash)
                    .width(0.7)
            };
        }
        chart = chart.panel(panel);
    }
    chart.render()
}

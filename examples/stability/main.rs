//! Where each method breaks: approaching a limit position (non-Grashof
//! four-bar) and a branch point (change-point four-bar), the errors of the
//! library, of the same code without its conditioning check, of num-dual
//! and finite-difference Jacobians and of the closed form, against the
//! 50-digit reference; Newton's iterations; and methods A and B against the
//! condition number of Ψ_u (actuator-driven boom).
//!
//! Run with `cargo run --release --example stability`; it prints the tables
//! and writes the charts to `out/stability/` (`stability_limit.svg`,
//! `stability_branch.svg`, `stability_iterations.svg`,
//! `stability_methods.svg`).

#[path = "../support/output.rs"]
mod output;
mod study;

use plotters::prelude::*;
use std::path::Path;
use study::{Case, Method, Row};

/// The smallest value shown on a log axis (exact zeros are drawn here).
const FLOOR: f64 = 1e-17;

fn color(method: Method) -> RGBColor {
    match method {
        Method::Generated => RGBColor(20, 20, 20),
        Method::Unguarded => RGBColor(200, 40, 40),
        Method::Dual => RGBColor(40, 110, 200),
        Method::FiniteDifference => RGBColor(230, 140, 20),
        Method::ClosedForm => RGBColor(40, 150, 70),
    }
}

fn print_table(case: Case, rows: &[Row]) {
    println!("\n{}", case.name());
    println!(
        "{:>9} {:>9}  {:<34} {:>4} {:>9} {:>9} {:>9}  outcome",
        "δ [rad]", "κ(Ψ_u)", "method", "it", "θ err", "ω err", "α err"
    );
    for r in rows {
        let outcome = match (
            &r.error,
            r.position.max(r.velocity).max(r.acceleration) <= 1e-6,
        ) {
            (Some(e), _) => format!("typed error: {}", e.split(':').next().unwrap_or(e)),
            (None, true) => "ok".to_owned(),
            (None, false) => "ok, but off by more than 1e-6".to_owned(),
        };
        println!(
            "{:9.2e} {:9.2e}  {:<34} {:>4} {:9.1e} {:9.1e} {:9.1e}  {outcome}",
            r.delta,
            r.condition,
            r.method.name(),
            r.iterations.map_or("—".to_owned(), |i| i.to_string()),
            r.position,
            r.velocity,
            r.acceleration
        );
    }
}

/// Error against δ for every method, in three panels: θ, ω, α.
fn error_chart(case: Case, rows: &[Row], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1200, 460)).into_drawing_area();
    root.fill(&WHITE)?;
    let title = format!(
        "Approaching the {}: error against the 50-digit reference",
        case.name()
    );
    let (top, body) = root.split_vertically(36);
    top.draw(&Text::new(title, (14, 10), ("sans-serif", 18).into_font()))?;
    let panels = body.split_evenly((1, 3));
    type Quantity = (&'static str, fn(&Row) -> f64);
    let quantities: [Quantity; 3] = [
        ("positions θ3, θ4: absolute error [rad]", |r| r.position),
        ("velocity analogs ω: relative error", |r| r.velocity),
        ("acceleration analogs α: relative error", |r| {
            r.acceleration
        }),
    ];
    for (panel, (label, value)) in panels.iter().zip(quantities) {
        let mut chart = ChartBuilder::on(panel)
            .caption(label, ("sans-serif", 14))
            .margin(8)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((1e-13f64..0.2f64).log_scale(), (FLOOR..1e9f64).log_scale())?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .bold_line_style(BLACK.mix(0.1))
            .x_desc("δ: distance to the singular pose [rad]")
            .x_labels(7)
            .y_labels(7)
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()?;
        // The accuracy the library promises.
        chart.draw_series(LineSeries::new(
            [(1e-13, 1e-6), (0.2, 1e-6)],
            BLACK.mix(0.35).stroke_width(1),
        ))?;
        for method in Method::ALL {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.method == method && r.error.is_none())
                .map(|r| (r.delta, value(r).clamp(FLOOR, 1e9)))
                .filter(|p| p.1.is_finite())
                .collect();
            let c = color(method);
            let width = if method == Method::Generated { 3 } else { 1 };
            chart
                .draw_series(LineSeries::new(points.clone(), c.stroke_width(width)))?
                .label(method.name())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                });
            if method == Method::Generated {
                chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, c.filled())))?;
                // Where the library answers with a typed error instead.
                let refused: Vec<f64> = rows
                    .iter()
                    .filter(|r| r.method == method && r.error.is_some())
                    .map(|r| r.delta)
                    .collect();
                if let Some(edge) = refused.iter().copied().reduce(f64::max) {
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [(1e-13, FLOOR), (edge, 1e9)],
                        BLACK.mix(0.06).filled(),
                    )))?;
                }
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.3))
            .label_font(("sans-serif", 11))
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// Newton iterations against δ, both singular poses.
fn iterations_chart(
    limit: &[Row],
    branch: &[Row],
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (900, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((1, 2));
    for (panel, (rows, case)) in panels
        .iter()
        .zip([(limit, Case::Limit), (branch, Case::Branch)])
    {
        let mut chart = ChartBuilder::on(panel)
            .caption(
                format!("Newton iterations, {}", case.name()),
                ("sans-serif", 14),
            )
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(40)
            .build_cartesian_2d((1e-13f64..0.2f64).log_scale(), 0f64..32f64)?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .bold_line_style(BLACK.mix(0.1))
            .x_desc("δ [rad]")
            .y_desc("iterations")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0}"))
            .draw()?;
        for method in [
            Method::Unguarded,
            Method::Dual,
            Method::FiniteDifference,
            Method::Generated,
        ] {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.method == method)
                .filter_map(|r| r.iterations.map(|i| (r.delta, i as f64)))
                .collect();
            let c = color(method);
            chart
                .draw_series(LineSeries::new(points.clone(), c.stroke_width(2)))?
                .label(method.name())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                });
            chart.draw_series(points.iter().map(|&p| Circle::new(p, 2, c.filled())))?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.3))
            .label_font(("sans-serif", 11))
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// Methods A and B against the condition number of Ψ_u.
fn methods_chart(
    rows: &[study::MethodsRow],
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (760, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Actuator-driven boom near full extension: acceleration analogs by method A and B",
            ("sans-serif", 15),
        )
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d((5f64..2e7f64).log_scale(), (FLOOR..1e-2f64).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .bold_line_style(BLACK.mix(0.1))
        .x_desc("κ, condition number of Ψ_u")
        .y_desc("relative error / difference")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()?;
    type Series = (&'static str, RGBColor, u32, fn(&study::MethodsRow) -> f64);
    let series: [Series; 4] = [
        (
            "method A against the reference",
            RGBColor(200, 40, 40),
            6,
            |r| r.error_a,
        ),
        (
            "method B against the reference",
            RGBColor(40, 110, 200),
            2,
            |r| r.error_b,
        ),
        ("|A − B|", RGBColor(20, 20, 20), 2, |r| r.a_minus_b),
        ("|fused − B|", RGBColor(40, 150, 70), 2, |r| {
            r.fused_minus_b
        }),
    ];
    for (label, c, width, value) in series {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .map(|r| (r.condition, value(r).max(FLOOR)))
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), c.stroke_width(width)))?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2)));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 2, c.filled())))?;
    }
    let slope: Vec<(f64, f64)> = (0..=60)
        .map(|i| {
            let k = 5.0 * 10f64.powf(f64::from(i) / 10.0);
            (k, f64::EPSILON * k * k)
        })
        .collect();
    chart
        .draw_series(LineSeries::new(slope, BLACK.mix(0.35)))?
        .label("ε·κ²")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK.mix(0.35)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .draw()?;
    root.present()?;
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let figures = output::folder("stability")?;
    let limit = study::run(Case::Limit);
    let branch = study::run(Case::Branch);
    print_table(Case::Limit, &limit);
    print_table(Case::Branch, &branch);
    error_chart(Case::Limit, &limit, &figures.join("stability_limit.svg"))?;
    error_chart(Case::Branch, &branch, &figures.join("stability_branch.svg"))?;
    iterations_chart(&limit, &branch, &figures.join("stability_iterations.svg"))?;
    let methods = study::methods_near_limit();
    println!("\nboom near full extension: methods A and B");
    println!(
        "{:>9} {:>9} {:>9} {:>9} {:>9}",
        "δ [m]", "κ(Ψ_u)", "A err", "B err", "|A−B|"
    );
    for r in &methods {
        println!(
            "{:9.2e} {:9.2e} {:9.1e} {:9.1e} {:9.1e}",
            r.delta, r.condition, r.error_a, r.error_b, r.a_minus_b
        );
    }
    methods_chart(&methods, &figures.join("stability_methods.svg"))?;
    for name in [
        "stability_limit",
        "stability_branch",
        "stability_iterations",
        "stability_methods",
    ] {
        println!("wrote {}", figures.join(format!("{name}.svg")).display());
    }
    Ok(())
}

//! The stability study's charts, as SVG: errors against δ near a limit
//! position and a branch point, Newton's iterations, and methods A and B
//! against the condition number of Ψᵤ. Each picture has one legend, above
//! its panels, whose swatches are drawn in the styles of the curves they
//! name (`tests/draw/diagrams.rs` checks that).
//!
//! Shared by `cargo run --release --example stability` and
//! `tests/draw/diagrams.rs`.

use crate::study::{Case, Method, MethodsRow, Row};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::page::{Area, Drawn, page};

/// The smallest value shown on a log axis (exact zeros are drawn here).
pub const FLOOR: f64 = 1e-17;

/// The accuracy the library promises by default (`Options::accuracy`).
const ACCURACY: f64 = 1e-6;

pub fn color(method: Method) -> RGBColor {
    match method {
        Method::Generated => RGBColor(20, 20, 20),
        Method::Unguarded => RGBColor(200, 40, 40),
        Method::Dual => RGBColor(40, 110, 200),
        Method::FiniteDifference => RGBColor(230, 140, 20),
        Method::ClosedForm => RGBColor(40, 150, 70),
    }
}

/// How a method's curve is drawn in the error charts: the library's own
/// thicker, with its points marked.
fn error_style(method: Method) -> (ShapeStyle, bool) {
    let width = if method == Method::Generated { 3 } else { 1 };
    (
        color(method).stroke_width(width),
        method == Method::Generated,
    )
}

/// The shading of the δ where the library refuses to answer.
fn refused_style() -> ShapeStyle {
    BLACK.mix(0.06).filled()
}

/// The line of the accuracy target.
fn accuracy_style() -> ShapeStyle {
    BLACK.mix(0.35).stroke_width(1)
}

/// What a legend entry shows before its name.
#[derive(Clone, Copy)]
enum Swatch {
    /// A curve's style, with a point marked on it or not.
    Line(ShapeStyle, bool),
    /// A shaded region's fill.
    Band(ShapeStyle),
}

/// A legend across `area`, entries left to right from `(x, y)` (the first
/// row's middle), on as many rows as they need.
fn legend(area: &Area<'_>, entries: &[(String, Swatch)], (x, y): (i32, i32)) -> Drawn {
    const SWATCH: i32 = 26;
    let right = area.dim_in_pixel().0 as i32 - 12;
    let font = ("sans-serif", 14)
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    let (mut at, mut line) = (x, y);
    for (name, swatch) in entries {
        // A rough width: SVG text cannot be measured here.
        let width = SWATCH + 6 + (name.chars().count() as f64 * 6.4).ceil() as i32 + 22;
        if at + width > right && at > x {
            (at, line) = (x, line + 20);
        }
        match *swatch {
            Swatch::Line(style, marked) => {
                area.draw(&PathElement::new(
                    vec![(at, line), (at + SWATCH, line)],
                    style,
                ))?;
                if marked {
                    area.draw(&Circle::new(
                        (at + SWATCH / 2, line),
                        3,
                        style.color.filled(),
                    ))?;
                }
            }
            Swatch::Band(style) => {
                area.draw(&Rectangle::new(
                    [(at, line - 7), (at + SWATCH, line + 7)],
                    style,
                ))?;
                area.draw(&Rectangle::new(
                    [(at, line - 7), (at + SWATCH, line + 7)],
                    BLACK.mix(0.25),
                ))?;
            }
        }
        area.draw(&Text::new(
            name.clone(),
            (at + SWATCH + 6, line),
            font.clone(),
        ))?;
        at += width;
    }
    Ok(())
}

/// Error against δ for every method, in three panels: θ, ω, α; one legend,
/// which says what the shading and the horizontal line are.
pub fn error_chart(case: Case, rows: &[Row]) -> Result<String, Box<dyn std::error::Error>> {
    page((1200, 520), |root| {
        let (top, body) = root.split_vertically(84);
        let title = format!(
            "Approaching the {}: error against the 50-digit reference",
            case.name()
        );
        top.draw(&Text::new(title, (14, 10), ("sans-serif", 18).into_font()))?;
        let mut entries: Vec<(String, Swatch)> = Method::ALL
            .into_iter()
            .map(|m| {
                let (style, marked) = error_style(m);
                (m.name().to_owned(), Swatch::Line(style, marked))
            })
            .collect();
        entries.push((
            "accuracy target, Options::accuracy = 1e-6".to_owned(),
            Swatch::Line(accuracy_style(), false),
        ));
        entries.push((
            "shaded: the library returns Error::Singular instead of a result".to_owned(),
            Swatch::Band(refused_style()),
        ));
        legend(&top, &entries, (20, 46))?;
        // Where the library answers with Error::Singular instead.
        let refused = rows
            .iter()
            .filter(|r| r.method == Method::Generated && r.singular)
            .map(|r| r.delta)
            .reduce(f64::max);
        let panels = body.split_evenly((1, 3));
        type Quantity = (&'static str, fn(&Row) -> f64);
        let quantities: [Quantity; 3] = [
            ("positions θ₃, θ₄: absolute error [rad]", |r| {
                r.position
            }),
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
            if let Some(edge) = refused {
                chart.draw_series(std::iter::once(Rectangle::new(
                    [(1e-13, FLOOR), (edge, 1e9)],
                    refused_style(),
                )))?;
            }
            chart.draw_series(LineSeries::new(
                [(1e-13, ACCURACY), (0.2, ACCURACY)],
                accuracy_style(),
            ))?;
            for method in Method::ALL {
                let points: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| r.method == method && r.error.is_none())
                    .map(|r| (r.delta, value(r).clamp(FLOOR, 1e9)))
                    .filter(|p| p.1.is_finite())
                    .collect();
                let (style, marked) = error_style(method);
                chart.draw_series(LineSeries::new(points.clone(), style))?;
                if marked {
                    chart.draw_series(
                        points
                            .iter()
                            .map(|&p| Circle::new(p, 3, style.color.filled())),
                    )?;
                }
            }
        }
        Ok(())
    })
}

/// Newton iterations against δ, both singular poses; one legend.
pub fn iterations_chart(
    limit: &[Row],
    branch: &[Row],
) -> Result<String, Box<dyn std::error::Error>> {
    const METHODS: [Method; 4] = [
        Method::Unguarded,
        Method::Dual,
        Method::FiniteDifference,
        Method::Generated,
    ];
    let style = |method| color(method).stroke_width(2);
    page((900, 460), |root| {
        let (top, body) = root.split_vertically(40);
        let entries: Vec<(String, Swatch)> = METHODS
            .into_iter()
            .map(|m| (m.name().to_owned(), Swatch::Line(style(m), true)))
            .collect();
        legend(&top, &entries, (20, 20))?;
        let panels = body.split_evenly((1, 2));
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
            for method in METHODS {
                let points: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| r.method == method)
                    .filter_map(|r| r.iterations.map(|i| (r.delta, i as f64)))
                    .collect();
                let style = style(method);
                chart.draw_series(LineSeries::new(points.clone(), style))?;
                chart.draw_series(
                    points
                        .iter()
                        .map(|&p| Circle::new(p, 2, style.color.filled())),
                )?;
            }
        }
        Ok(())
    })
}

/// Methods A and B against the condition number of Ψᵤ.
pub fn methods_chart(rows: &[MethodsRow]) -> Result<String, Box<dyn std::error::Error>> {
    type Series = (&'static str, ShapeStyle, fn(&MethodsRow) -> f64);
    let series: [Series; 4] = [
        (
            "method A against the reference",
            RGBColor(200, 40, 40).stroke_width(6),
            |r| r.error_a,
        ),
        (
            "method B against the reference",
            RGBColor(40, 110, 200).stroke_width(2),
            |r| r.error_b,
        ),
        ("|A − B|", RGBColor(20, 20, 20).stroke_width(2), |r| {
            r.a_minus_b
        }),
        (
            "|fused − B|",
            RGBColor(40, 150, 70).stroke_width(2),
            |r| r.fused_minus_b,
        ),
    ];
    let slope_style = BLACK.mix(0.35).stroke_width(1);
    page((760, 540), |root| {
        let (top, body) = root.split_vertically(84);
        top.draw(&Text::new(
            "Actuator-driven boom near full extension: acceleration analogs by method A and B",
            (14, 10),
            ("sans-serif", 15).into_font(),
        ))?;
        let mut entries: Vec<(String, Swatch)> = series
            .iter()
            .map(|(name, style, _)| (name.to_string(), Swatch::Line(*style, true)))
            .collect();
        entries.push(("ε·κ²".to_owned(), Swatch::Line(slope_style, false)));
        legend(&top, &entries, (20, 44))?;
        let mut chart = ChartBuilder::on(&body)
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(56)
            .build_cartesian_2d((5f64..2e7f64).log_scale(), (FLOOR..1e-2f64).log_scale())?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .bold_line_style(BLACK.mix(0.1))
            .x_desc("κ, condition number of Ψᵤ")
            .y_desc("relative error / difference")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()?;
        for (_, style, value) in series {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .map(|r| (r.condition, value(r).max(FLOOR)))
                .collect();
            chart.draw_series(LineSeries::new(points.clone(), style))?;
            chart.draw_series(
                points
                    .iter()
                    .map(|&p| Circle::new(p, 2, style.color.filled())),
            )?;
        }
        let slope: Vec<(f64, f64)> = (0..=60)
            .map(|i| {
                let k = 5.0 * 10f64.powf(f64::from(i) / 10.0);
                (k, f64::EPSILON * k * k)
            })
            .collect();
        chart.draw_series(LineSeries::new(slope, slope_style))?;
        Ok(())
    })
}

//! The stability study's charts, drawn with the library's `Chart`: errors
//! against δ near a limit position and a branch point, Newton's
//! iterations, and methods A and B against the condition number of Ψᵤ.
//! Each picture has one legend, above its panels, whose swatches are drawn
//! in the looks of the curves they name (`tests/draw/diagrams.rs` checks
//! that).
//!
//! Shared by `cargo run --release --example stability` and
//! `tests/draw/diagrams.rs`.

use crate::study::{Case, Method, MethodsRow, Row};
use linkage::draw::chart::{Chart, Colour, Dash, DiagramError, Marker, Panel};

/// The smallest value shown on a log axis (exact zeros are drawn here).
pub const FLOOR: f64 = 1e-17;

/// The largest error drawn: larger ones are drawn at it (and a note says
/// so), flat along the top.
const CEILING: f64 = 1e8;

/// The accuracy the library promises by default (`Options::accuracy`).
const ACCURACY: f64 = 1e-6;

/// Each method's colour and dashes, the same in every chart.
pub fn look(method: Method) -> (Colour, Dash) {
    use linkage::draw::chart::look::COLOURS;
    match method {
        Method::Generated => (Colour::BLACK, Dash::Solid),
        Method::Unguarded => (COLOURS[1], Dash::Solid),
        Method::Dual => (COLOURS[0], Dash::Dashed),
        Method::FiniteDifference => (COLOURS[4], Dash::DashDot),
        Method::ClosedForm => (COLOURS[2], Dash::Dotted),
    }
}

/// A method's curve: the library's own thicker, with its points marked.
fn curve(panel: Panel, method: Method, points: Vec<(f64, f64)>) -> Panel {
    let (colour, dash) = look(method);
    if method == Method::Generated {
        panel
            .line_and_points(method.name(), points)
            .colour(colour)
            .dash(dash)
            .marker(Marker::Circle)
            .width(1.6)
    } else {
        panel.line(method.name(), points).colour(colour).dash(dash)
    }
}

/// Error against δ for every method, in three panels: θ, ω, α; one legend,
/// which says what the shading and the horizontal line are.
pub fn error_chart(case: Case, rows: &[Row]) -> Result<String, DiagramError> {
    // Where the library answers with Error::Singular instead.
    let refused = rows
        .iter()
        .filter(|r| r.method == Method::Generated && r.singular)
        .map(|r| r.delta)
        .reduce(f64::max);
    type Quantity = (&'static str, fn(&Row) -> f64);
    let quantities: [Quantity; 3] = [
        ("positions θ_3, θ_4: absolute error [rad]", |r| r.position),
        ("velocity analogs ω: relative error", |r| r.velocity),
        ("acceleration analogs α: relative error", |r| {
            r.acceleration
        }),
    ];
    let mut chart = Chart::new(
        &format!(
            "Approaching the {}: error against the 50-digit reference",
            case.name()
        ),
        "δ: distance to the singular pose [rad]",
    )
    .note("errors above 10⁸ are drawn at 10⁸, flat along the top; exact zeros at 10⁻¹⁷")
    .columns(3)
    .size(1200, 470)
    .shared_legend();
    for (label, value) in quantities {
        let mut panel = Panel::new("")
            .caption(label)
            .x_log()
            .y_log()
            .x_range(1e-13, 0.2)
            .y_range(FLOOR, 1e9);
        if let Some(edge) = refused {
            panel = panel.shade(
                "shaded: the library returns Error::Singular instead of a result",
                1e-13,
                edge,
            );
        }
        panel = panel.levels("accuracy target, Options::accuracy = 1e-6", &[ACCURACY]);
        for method in Method::ALL {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.method == method && r.error.is_none())
                .map(|r| (r.delta, value(r).clamp(FLOOR, CEILING)))
                .filter(|p| p.1.is_finite())
                .collect();
            panel = curve(panel, method, points);
        }
        chart = chart.panel(panel);
    }
    chart.render()
}

/// Newton iterations against δ, both singular poses; one legend.
pub fn iterations_chart(limit: &[Row], branch: &[Row]) -> Result<String, DiagramError> {
    const METHODS: [Method; 4] = [
        Method::Unguarded,
        Method::Dual,
        Method::FiniteDifference,
        Method::Generated,
    ];
    let mut chart = Chart::new(
        "Newton's iterations to converge against the distance to the singular pose",
        "δ [rad]",
    )
    .columns(2)
    .size(900, 420)
    .shared_legend();
    for (rows, case) in [(limit, Case::Limit), (branch, Case::Branch)] {
        let mut panel = Panel::new("iterations")
            .caption(&format!("at the {}", case.name()))
            .x_log()
            .x_range(1e-13, 0.2)
            .y_range(0.0, 32.0);
        for method in METHODS {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.method == method)
                .filter_map(|r| r.iterations.map(|i| (r.delta, i as f64)))
                .collect();
            let (colour, dash) = look(method);
            panel = panel
                .line_and_points(method.name(), points)
                .colour(colour)
                .dash(dash);
        }
        chart = chart.panel(panel);
    }
    chart.render()
}

/// Methods A and B against the condition number of Ψᵤ.
pub fn methods_chart(rows: &[MethodsRow]) -> Result<String, DiagramError> {
    use linkage::draw::chart::look::COLOURS;
    type Series = (&'static str, Colour, Dash, f64, fn(&MethodsRow) -> f64);
    let series: [Series; 4] = [
        (
            "method A against the reference",
            COLOURS[1],
            Dash::Solid,
            2.6,
            |r| r.error_a,
        ),
        (
            "method B against the reference",
            COLOURS[0],
            Dash::Dashed,
            1.1,
            |r| r.error_b,
        ),
        ("|A − B|", Colour::BLACK, Dash::Solid, 1.1, |r| {
            r.a_minus_b
        }),
        ("|fused − B|", COLOURS[2], Dash::DashDot, 1.1, |r| {
            r.fused_minus_b
        }),
    ];
    let mut panel = Panel::new("relative error / difference")
        .x_log()
        .y_log()
        .x_range(5.0, 2e7)
        .y_range(FLOOR, 1e-2);
    for (name, colour, dash, width, value) in series {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .map(|r| (r.condition, value(r).max(FLOOR)))
            .collect();
        panel = panel
            .line_and_points(name, points)
            .colour(colour)
            .dash(dash)
            .width(width);
    }
    let slope: Vec<(f64, f64)> = (0..=60)
        .map(|i| {
            let k = 5.0 * 10f64.powf(f64::from(i) / 10.0);
            (k, f64::EPSILON * k * k)
        })
        .collect();
    panel = panel
        .line("ε·κ²", slope)
        .colour(Colour::GREY)
        .dash(Dash::Dotted);
    Chart::new(
        "Actuator-driven boom near full extension: acceleration analogs by method A and B",
        "κ, condition number of Ψ_u",
    )
    .note("exact zeros are drawn at 10⁻¹⁷")
    .size(760, 460)
    .shared_legend()
    .panel(panel)
    .render()
}

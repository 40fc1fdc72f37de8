//! The legend under the drawing: an entry per kind of arrow (with its
//! scale), per traced path, per named curve, per named set of markers and
//! for named ghost poses, each with a swatch drawn exactly as what it
//! describes, then a scale bar.
//!
//! Each entry is a group `class="legend-entry"` whose `data-for` names what
//! it describes: the class of the arrows (`velocity`, `acceleration`) or
//! the id of the traced path (`trace-A`), the curve (`curve-0`), the set
//! of markers (`markers-0`) or `ghosts`.

use super::Scene;
use super::arrow_kind::Kind;
use super::arrows::Arrow;
use super::layout::{Layout, number};
use super::markers::marker_symbol;
use super::style;
use crate::draw::svg::{Writer, fmt, nice_below, scale_bar};
use linkage_symbolic::names::textbook;
use nalgebra::Vector2;

/// The swatch's length.
const SWATCH: f64 = 34.0;

impl Scene {
    pub(super) fn draw_legend(&self, w: &mut Writer, layout: &Layout, traced: bool) {
        let x = style::MARGIN;
        let mut y = layout.legend_top;
        let (l, t) = (&self.length_unit, &self.time_unit);
        w.open("g", &[("id", "legend"), ("class", "legend")]);
        for (kind, shown, scale, unit) in [
            (
                Kind::Velocity,
                !self.velocity_arrows.is_empty(),
                layout.velocity_scale,
                format!("{l}/{t}"),
            ),
            (
                Kind::Acceleration,
                !self.acceleration_arrows.is_empty(),
                layout.acceleration_scale,
                format!("{l}/{t}²"),
            ),
        ] {
            if !shown {
                continue;
            }
            w.open("g", &[("class", "legend-entry"), ("data-for", kind.name())]);
            let arrow = Arrow::new(Vector2::new(x, y - 4.0), Vector2::new(x + SWATCH, y - 4.0));
            w.element(
                "line",
                &[
                    ("class", "swatch"),
                    ("x1", &fmt(arrow.base.x)),
                    ("y1", &fmt(arrow.base.y)),
                    ("x2", &fmt(arrow.neck.x)),
                    ("y2", &fmt(arrow.neck.y)),
                    ("stroke", kind.colour()),
                    ("stroke-width", &fmt(style::ARROW_WIDTH)),
                ],
            );
            w.element(
                "polygon",
                &[("points", &arrow.head()), ("fill", kind.colour())],
            );
            legend_text(
                w,
                x + SWATCH + 10.0,
                y,
                &format!(
                    "{}, scale {}: 1 {l} drawn = {} {unit}",
                    kind.name(),
                    number(scale),
                    number(1.0 / scale)
                ),
            );
            w.close("g");
            y += style::LEGEND_LINE;
        }
        for (k, name) in self.traces.iter().enumerate().filter(|_| traced) {
            let look = style::trace(k);
            w.open(
                "g",
                &[
                    ("class", "legend-entry"),
                    ("data-for", &format!("trace-{name}")),
                ],
            );
            let width = fmt(style::TRACE_WIDTH);
            line_swatch(
                w,
                x,
                y,
                &[
                    ("stroke", look.colour),
                    ("stroke-width", &width),
                    ("stroke-dasharray", look.dashes),
                ],
            );
            legend_text(
                w,
                x + SWATCH + 10.0,
                y,
                &format!("path of {} over the cycle", textbook(name)),
            );
            w.close("g");
            y += style::LEGEND_LINE;
        }
        for (k, curve) in self.curves.iter().enumerate() {
            if curve.name().is_empty() {
                continue;
            }
            let look = curve.look(k);
            w.open(
                "g",
                &[
                    ("class", "legend-entry"),
                    ("data-for", &format!("curve-{k}")),
                ],
            );
            let width = fmt(style::CURVE_WIDTH);
            let mut stroke = vec![
                ("stroke", look.colour.as_str()),
                ("stroke-width", width.as_str()),
            ];
            if !look.dashes.is_empty() {
                stroke.push(("stroke-dasharray", look.dashes.as_str()));
            }
            line_swatch(w, x, y, &stroke);
            legend_text(w, x + SWATCH + 10.0, y, curve.name());
            w.close("g");
            y += style::LEGEND_LINE;
        }
        for (k, set) in self.markers.iter().enumerate() {
            if set.name().is_empty() {
                continue;
            }
            w.open(
                "g",
                &[
                    ("class", "legend-entry"),
                    ("data-for", &format!("markers-{k}")),
                ],
            );
            marker_symbol(w, Vector2::new(x + SWATCH / 2.0, y - 4.0), &set.look(k));
            legend_text(w, x + SWATCH + 10.0, y, set.name());
            w.close("g");
            y += style::LEGEND_LINE;
        }
        if self.ghosts_in_legend() {
            // A faint bar, as the ghosts' bars are drawn.
            w.open("g", &[("class", "legend-entry"), ("data-for", "ghosts")]);
            let width = fmt(style::GHOST_BAR_WIDTH);
            line_swatch(
                w,
                x,
                y,
                &[
                    ("stroke", style::GHOST),
                    ("stroke-width", &width),
                    ("stroke-linecap", "round"),
                ],
            );
            legend_text(w, x + SWATCH + 10.0, y, &self.ghost_name);
            w.close("g");
            y += style::LEGEND_LINE;
        }
        // A bar of a round length.
        let length = nice_below(120.0 / layout.scale);
        let pixels = length * layout.scale;
        scale_bar(w, x, y - 4.0, pixels);
        legend_text(w, x + pixels + 10.0, y, &format!("{} {l}", number(length)));
        w.close("g");
    }
}

/// An entry's swatch that is a line, from `x` for the swatch's length at
/// the height of the entry's text at `y`, drawn with `stroke` (colour,
/// width, dashes).
fn line_swatch(w: &mut Writer, x: f64, y: f64, stroke: &[(&str, &str)]) {
    let (x1, x2, level) = (fmt(x), fmt(x + SWATCH), fmt(y - 4.0));
    let mut attributes = vec![
        ("class", "swatch"),
        ("x1", x1.as_str()),
        ("y1", level.as_str()),
        ("x2", x2.as_str()),
        ("y2", level.as_str()),
    ];
    attributes.extend_from_slice(stroke);
    w.element("line", &attributes);
}

fn legend_text(w: &mut Writer, x: f64, y: f64, text: &str) {
    w.open(
        "text",
        &[
            ("x", &fmt(x)),
            ("y", &fmt(y)),
            ("font-family", style::FONT),
            ("font-size", "13"),
            ("fill", style::INK),
        ],
    );
    w.text(text);
    w.close("text");
}

//! The marks a chart draws at a point: markers of each shape, and arrows.

use super::look::{Look, Marker, points};
use crate::draw::svg::{Writer, fmt};

/// A marker of `shape` at `at`, in `look`'s colour, filled or `open`, at
/// `px` pixels a printed point.
pub(crate) fn marker(
    w: &mut Writer,
    shape: Marker,
    open: bool,
    look: &Look,
    (x, y): (f64, f64),
    px: f64,
) {
    let r = points::MARKER * px;
    let colour = look.colour.to_string();
    let stroke_width = fmt(0.8 * points::THIN * px * if open { 1.6 } else { 1.0 });
    let fill = if open { "#FFFFFF" } else { colour.as_str() };
    let opacity = fmt(look.opacity);
    let path = |points: &[(f64, f64)]| {
        let mut d = String::new();
        for (i, (px_, py)) in points.iter().enumerate() {
            d.push(if i == 0 { 'M' } else { 'L' });
            d.push_str(&format!("{} {} ", fmt(x + px_ * r), fmt(y + py * r)));
        }
        d.push('Z');
        d
    };
    let outline: Option<String> = match shape {
        Marker::Circle => None,
        Marker::Square => Some(path(&[
            (-0.85, -0.85),
            (0.85, -0.85),
            (0.85, 0.85),
            (-0.85, 0.85),
        ])),
        Marker::Triangle => Some(path(&[(0.0, -1.2), (1.1, 0.75), (-1.1, 0.75)])),
        Marker::TriangleDown => Some(path(&[(0.0, 1.2), (1.1, -0.75), (-1.1, -0.75)])),
        Marker::Diamond => Some(path(&[(0.0, -1.25), (1.0, 0.0), (0.0, 1.25), (-1.0, 0.0)])),
        Marker::Cross | Marker::Plus => {
            let (a, b) = if shape == Marker::Cross {
                (0.95, 0.95)
            } else {
                (1.25, 0.0)
            };
            let d = format!(
                "M{} {} L{} {} M{} {} L{} {}",
                fmt(x - a * r),
                fmt(y - b * r),
                fmt(x + a * r),
                fmt(y + b * r),
                fmt(x - b * r),
                fmt(y + a * r),
                fmt(x + b * r),
                fmt(y - a * r)
            );
            w.element(
                "path",
                &[
                    ("d", &d),
                    ("fill", "none"),
                    ("stroke", &colour),
                    ("stroke-width", &fmt(1.5 * points::THIN * px)),
                    ("opacity", &opacity),
                    ("class", "marker"),
                ],
            );
            return;
        }
    };
    match outline {
        None => w.element(
            "circle",
            &[
                ("cx", &fmt(x)),
                ("cy", &fmt(y)),
                ("r", &fmt(r)),
                ("fill", fill),
                ("stroke", &colour),
                ("stroke-width", &stroke_width),
                ("opacity", &opacity),
                ("class", "marker"),
            ],
        ),
        Some(d) => w.element(
            "path",
            &[
                ("d", &d),
                ("fill", fill),
                ("stroke", &colour),
                ("stroke-width", &stroke_width),
                ("stroke-linejoin", "round"),
                ("opacity", &opacity),
                ("class", "marker"),
            ],
        ),
    }
}

/// An arrow from `from` to `to` (in pixels) in `look`, its head a filled
/// triangle, at `px` pixels a printed point.
pub(crate) fn arrow(w: &mut Writer, look: &Look, from: (f64, f64), to: (f64, f64), px: f64) {
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let length = dx.hypot(dy);
    let colour = look.colour.to_string();
    if length < 1e-9 {
        return;
    }
    let (ux, uy) = (dx / length, dy / length);
    let head = (5.0 * px).min(0.5 * length);
    let half = 0.45 * head;
    let base = (to.0 - ux * head, to.1 - uy * head);
    w.element(
        "line",
        &[
            ("x1", &fmt(from.0)),
            ("y1", &fmt(from.1)),
            ("x2", &fmt(base.0)),
            ("y2", &fmt(base.1)),
            ("stroke", &colour),
            ("stroke-width", &fmt(look.width * px)),
            ("opacity", &fmt(look.opacity)),
        ],
    );
    let d = format!(
        "M{} {} L{} {} L{} {} Z",
        fmt(to.0),
        fmt(to.1),
        fmt(base.0 - uy * half),
        fmt(base.1 + ux * half),
        fmt(base.0 + uy * half),
        fmt(base.1 - ux * half)
    );
    w.element(
        "path",
        &[
            ("d", &d),
            ("fill", &colour),
            ("opacity", &fmt(look.opacity)),
        ],
    );
}

//! One panel drawn in its cell of the page, as laid out (`layout.rs`): its
//! grid, what it shows (clipped to the axes), its ticks and labels, and its
//! legend.

use super::layout::{Cell, Frame, caption_lines};
use super::legend::{Legend, entries, stroke};
use super::look::{AXIS, BAR_OPACITY, Colour, Dash, FONT, Look, SHADE, level_look, points};
use super::marks::{arrow, marker};
use super::panel::{Panel, Scale, Series, Shape};
use super::text;
use crate::draw::svg::{Writer, fmt};

fn line(w: &mut Writer, a: (f64, f64), b: (f64, f64), attributes: &[(&str, &str)]) {
    let mut all = vec![
        ("x1", fmt(a.0)),
        ("y1", fmt(a.1)),
        ("x2", fmt(b.0)),
        ("y2", fmt(b.1)),
    ];
    all.extend(attributes.iter().map(|(k, v)| (*k, v.to_string())));
    let refs: Vec<(&str, &str)> = all.iter().map(|(k, v)| (*k, v.as_str())).collect();
    w.element("line", &refs);
}

fn polyline(w: &mut Writer, points: &[(f64, f64)], look: &Look, px: f64, closed: bool) {
    let text: Vec<String> = points
        .iter()
        .map(|p| format!("{},{}", fmt(p.0), fmt(p.1)))
        .collect();
    let mut attributes = vec![("points", text.join(" "))];
    attributes.extend(stroke(look, px));
    attributes.push(("stroke-linejoin", "round".into()));
    let refs: Vec<(&str, &str)> = attributes.iter().map(|(k, v)| (*k, v.as_str())).collect();
    w.element(if closed { "polygon" } else { "polyline" }, &refs);
}

fn write_text(
    w: &mut Writer,
    (x, y): (f64, f64),
    content: &str,
    size: f64,
    anchor: &str,
    extra: &[(&str, &str)],
) {
    let (x, y, font_size) = (fmt(x), fmt(y), fmt(size));
    let mut attributes = vec![
        ("x", x.as_str()),
        ("y", y.as_str()),
        ("font-family", FONT),
        ("font-size", font_size.as_str()),
        ("text-anchor", anchor),
    ];
    attributes.extend_from_slice(extra);
    w.text_runs(&attributes, &text::runs(content, size));
}

/// Draws `panel` in `cell`, each series in its look.
pub(crate) fn draw(w: &mut Writer, panel: &Panel, cell: &Cell, look: &dyn Fn(&Series) -> Look) {
    let px = cell.px;
    let frame = Frame::lay_out(panel, cell, look);
    let [l, t, r, b] = frame.plot;
    let tick_font = points::TICK * px;
    let label_font = points::LABEL * px;
    let tick = points::TICK_LENGTH * px;
    let grid_width = fmt(points::GRID * px);
    let bars = !panel.categories.is_empty();
    // The grid, under everything.
    for (v, _) in &frame.y.ticks {
        let y = frame.y.place(*v, b, t);
        line(
            w,
            (l, y),
            (r, y),
            &[("stroke", "#E4E4E4"), ("stroke-width", &grid_width)],
        );
    }
    if !bars {
        for (v, _) in &frame.x.ticks {
            let x = frame.x.place(*v, l, r);
            line(
                w,
                (x, t),
                (x, b),
                &[("stroke", "#E4E4E4"), ("stroke-width", &grid_width)],
            );
        }
    }
    w.open("g", &[("clip-path", &format!("url(#{})", cell.clip))]);
    for (_, from, to) in &panel.shades {
        let (x0, x1) = (frame.x.place(*from, l, r), frame.x.place(*to, l, r));
        w.element(
            "rect",
            &[
                ("x", &fmt(x0.min(x1))),
                ("y", &fmt(t)),
                ("width", &fmt((x1 - x0).abs())),
                ("height", &fmt(b - t)),
                ("fill", &SHADE.0.to_string()),
                ("opacity", &fmt(SHADE.1)),
            ],
        );
    }
    for series in &panel.series {
        if let Shape::Fill(outline) = &series.shape {
            let look = look(series);
            let page: Vec<(f64, f64)> = outline.iter().map(|&p| frame.to_page(p)).collect();
            let text: Vec<String> = page
                .iter()
                .map(|p| format!("{},{}", fmt(p.0), fmt(p.1)))
                .collect();
            w.element(
                "polygon",
                &[
                    ("points", &text.join(" ")),
                    ("fill", &look.colour.to_string()),
                    ("opacity", &fmt(look.opacity)),
                    ("stroke", "none"),
                ],
            );
        }
    }
    if frame.y.scale == Scale::Linear && frame.y.range.0 < 0.0 && frame.y.range.1 > 0.0 {
        let y = frame.y.place(0.0, b, t);
        line(
            w,
            (l, y),
            (r, y),
            &[
                ("stroke", "#8C8C8C"),
                ("stroke-width", &fmt(points::THIN * px)),
            ],
        );
    }
    let n = panel.groups.len().max(1) as f64;
    for (g, (_, values)) in panel.groups.iter().enumerate() {
        let colour = super::look::COLOURS[g % super::look::COLOURS.len()].to_string();
        let bar = 0.8 / n;
        for (i, v) in values.iter().enumerate() {
            let x0 = i as f64 - 0.4 + g as f64 * bar;
            let (a, top) = (frame.to_page((x0, 0.0)), frame.to_page((x0 + bar, *v)));
            let (y0, y1) = (a.1.min(top.1), a.1.max(top.1));
            w.element(
                "rect",
                &[
                    ("x", &fmt(a.0)),
                    ("y", &fmt(y0)),
                    ("width", &fmt(top.0 - a.0 - 0.6 * px)),
                    ("height", &fmt(y1 - y0)),
                    ("fill", &colour),
                    ("opacity", &fmt(BAR_OPACITY)),
                ],
            );
        }
    }
    for (k, (_, ys)) in panel.levels.iter().enumerate() {
        for y in ys {
            let y = frame.y.place(*y, b, t);
            polyline(w, &[(l, y), (r, y)], &level_look(k), px, false);
        }
    }
    let mark_look = Look {
        colour: Colour::GREY,
        dash: Some(Dash::Dashed),
        marker: None,
        width: points::THIN,
        opacity: 1.0,
    };
    for (x, _) in &panel.marks {
        let x = frame.x.place(*x, l, r);
        polyline(w, &[(x, t), (x, b)], &mark_look, px, false);
    }
    for series in &panel.series {
        let look = look(series);
        match &series.shape {
            Shape::Fill(_) => {}
            Shape::Lines(lines) => {
                for points in lines {
                    let page: Vec<(f64, f64)> = points.iter().map(|&p| frame.to_page(p)).collect();
                    polyline(w, &page, &look, px, false);
                }
            }
            Shape::LineAndPoints(points) | Shape::Points(points) => {
                let page: Vec<(f64, f64)> = points.iter().map(|&p| frame.to_page(p)).collect();
                if look.dash.is_some() {
                    polyline(w, &page, &look, px, false);
                }
                if let Some((shape, open)) = look.marker {
                    for &p in &page {
                        marker(w, shape, open, &look, p, px);
                    }
                }
            }
            Shape::Arrow([from, to]) => {
                let (a, z) = (frame.to_page(*from), frame.to_page(*to));
                arrow(w, &look, a, z, px);
            }
        }
    }
    w.close("g");
    // Texts over everything drawn.
    for (k, (x, label)) in panel.marks.iter().enumerate() {
        if label.is_empty() {
            continue;
        }
        let xp = frame.x.place(*x, l, r);
        let right_half = xp > 0.5 * (l + r);
        let (anchor, nudge) = if right_half {
            ("end", -2.0 * px)
        } else {
            ("start", 2.0 * px)
        };
        let y = t + tick_font * (1.1 + 1.1 * (k % 2) as f64);
        write_text(
            w,
            (xp + nudge, y),
            label,
            tick_font,
            anchor,
            &[("fill", "#555555")],
        );
    }
    for ((x, y), note) in &panel.notes {
        // Wrapped to the room right of where it starts.
        let p = frame.to_page((*x, *y));
        let room = (r - p.0 - 2.0 * px).max(4.0 * tick_font);
        for (k, line) in text::wrap(note, tick_font, room).iter().enumerate() {
            let at = (p.0, p.1 + 1.25 * tick_font * k as f64);
            write_text(
                w,
                at,
                line,
                tick_font,
                "start",
                &[("fill", "#333333"), ("class", "note")],
            );
        }
    }
    // The axes, their ticks and labels.
    let axis_width = fmt(points::AXIS * px);
    let axis = [
        ("stroke", AXIS),
        ("opacity", "1"),
        ("stroke-width", axis_width.as_str()),
    ];
    line(w, (l, t), (l, b), &axis);
    line(w, (l, b), (r, b), &axis);
    for (v, label) in &frame.y.ticks {
        let y = frame.y.place(*v, b, t);
        line(w, (l - tick, y), (l, y), &axis);
        if !label.is_empty() {
            write_text(
                w,
                (l - tick - 0.3 * tick_font, y + 0.35 * tick_font),
                label,
                tick_font,
                "end",
                &[],
            );
        }
    }
    for (v, label) in &frame.x.ticks {
        let x = frame.x.place(*v, l, r);
        line(w, (x, b), (x, b + tick), &axis);
        if !label.is_empty() {
            write_text(
                w,
                (x, b + tick + 1.05 * tick_font),
                label,
                tick_font,
                "middle",
                &[],
            );
        }
    }
    if let Some(x_label) = cell.x_label {
        let y = b + tick + 1.5 * tick_font + 1.2 * label_font;
        write_text(w, (0.5 * (l + r), y), x_label, label_font, "middle", &[]);
    }
    if !panel.y_label.is_empty() {
        let x = cell.area[0] + 1.0 * label_font;
        let y = 0.5 * (t + b);
        let rotate = format!("rotate(-90 {} {})", fmt(x), fmt(y));
        write_text(
            w,
            (x, y),
            &panel.y_label,
            label_font,
            "middle",
            &[("transform", &rotate)],
        );
    }
    let size = points::CAPTION * px;
    for (k, line) in caption_lines(panel, cell).iter().enumerate() {
        let y = cell.area[1] + (1.2 + 1.3 * k as f64) * size;
        let middle = cell.area[0] + 0.5 * cell.area[2];
        write_text(w, (middle, y), line, size, "middle", &[]);
    }
    if let Some(place) = frame.legend_at {
        let entries = entries(panel, look);
        let legend = Legend {
            entries: &entries,
            px,
        };
        let (bw, bh) = legend.box_size();
        w.element(
            "rect",
            &[
                ("x", &fmt(place.0)),
                ("y", &fmt(place.1)),
                ("width", &fmt(bw)),
                ("height", &fmt(bh)),
                ("fill", "#FFFFFF"),
                ("fill-opacity", "0.88"),
                ("stroke", "none"),
            ],
        );
        legend.draw_boxed(w, place);
    }
}

/// The clipping rectangle of `panel` in `cell`, for the page's `<defs>`.
pub(crate) fn clip(w: &mut Writer, panel: &Panel, cell: &Cell, look: &dyn Fn(&Series) -> Look) {
    let [l, t, r, b] = Frame::lay_out(panel, cell, look).plot;
    w.open("clipPath", &[("id", &cell.clip)]);
    w.element(
        "rect",
        &[
            ("x", &fmt(l)),
            ("y", &fmt(t)),
            ("width", &fmt(r - l)),
            ("height", &fmt(b - t)),
        ],
    );
    w.close("clipPath");
}

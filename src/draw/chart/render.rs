//! One panel drawn in its cell of the page: its axes laid out from the
//! data, its grid, what it shows (clipped to the axes), its ticks and
//! labels, and its legend where it covers the least.

use super::axis::{Axis, range_of};
use super::legend::{Entry, Legend, Swatch, ink, stroke};
use super::look::{Colour, Dash, FONT, Look, points};
use super::marks::{arrow, marker};
use super::panel::{Panel, Scale, Series, Shape};
use super::text;
use crate::draw::svg::{Writer, fmt};

/// What a panel needs from its chart.
pub(crate) struct Cell<'a> {
    /// Left, top, width, height, in pixels.
    pub(crate) area: [f64; 4],
    /// Pixels a printed point.
    pub(crate) px: f64,
    /// The abscissa's label, if this panel shows one.
    pub(crate) x_label: Option<&'a str>,
    /// Whether the panel draws its own legend.
    pub(crate) legend: bool,
    /// The id of its clipping rectangle (unique in the page).
    pub(crate) clip: String,
    /// Where its axes start at the least (so that the panels of a column
    /// line up), in pixels.
    pub(crate) least_left: f64,
    /// The lines of caption its row has room for (so that the panels of a
    /// row line up).
    pub(crate) caption_lines: usize,
}

/// The look of reference levels: dark grey, the `k`th in its own dashes.
pub(crate) fn level_look(k: usize) -> Look {
    const DASHES: [Dash; 3] = [Dash::Dashed, Dash::Dotted, Dash::DashDot];
    Look {
        colour: Colour(70, 70, 70),
        dash: Some(DASHES[k % DASHES.len()]),
        marker: None,
        width: 0.9,
        opacity: 1.0,
    }
}

/// The colour of the axes and their ticks (not black, which a series may
/// have).
pub(crate) const AXIS: &str = "#262626";

/// The shading of a range of the abscissa.
pub(crate) const SHADE: (Colour, f64) = (Colour(0, 0, 0), 0.08);

/// The fill of bars: a group's colour, nearly opaque.
pub(crate) const BAR_OPACITY: f64 = 0.85;

/// The legend entries of `panel`, each series in its look (`look`).
pub(crate) fn entries(panel: &Panel, look: &dyn Fn(&Series) -> Look) -> Vec<Entry> {
    let mut entries: Vec<Entry> = Vec::new();
    for series in panel
        .series
        .iter()
        .filter(|s| s.listed && !s.name.is_empty())
    {
        if entries.iter().any(|e| e.name == series.name) {
            continue;
        }
        let l = look(series);
        let swatch = match series.shape {
            Shape::Fill(_) => Swatch::Fill {
                colour: l.colour,
                opacity: l.opacity,
            },
            _ => Swatch::Series(l),
        };
        entries.push(Entry {
            name: series.name.clone(),
            swatch,
        });
    }
    for (k, (label, _)) in panel.levels.iter().enumerate() {
        entries.push(Entry {
            name: label.clone(),
            swatch: Swatch::Series(level_look(k)),
        });
    }
    for (label, _, _) in &panel.shades {
        if !entries.iter().any(|e| &e.name == label) {
            entries.push(Entry {
                name: label.clone(),
                swatch: Swatch::Fill {
                    colour: SHADE.0,
                    opacity: SHADE.1,
                },
            });
        }
    }
    if panel.groups.len() > 1 {
        for (g, (name, _)) in panel.groups.iter().enumerate() {
            entries.push(Entry {
                name: name.clone(),
                swatch: Swatch::Fill {
                    colour: super::look::COLOURS[g % super::look::COLOURS.len()],
                    opacity: BAR_OPACITY,
                },
            });
        }
    }
    entries
}

/// The panel's axes' ranges from its data (or as given).
fn ranges(panel: &Panel) -> [(f64, f64); 2] {
    let bars = !panel.categories.is_empty();
    let xs = || {
        panel
            .series
            .iter()
            .flat_map(|s| s.points().map(|p| p.0))
            .chain(panel.marks.iter().map(|m| m.0))
            .chain(panel.shades.iter().flat_map(|s| [s.1, s.2]))
    };
    let ys = || {
        panel
            .series
            .iter()
            .flat_map(|s| s.points().map(|p| p.1))
            .chain(panel.levels.iter().flat_map(|l| l.1.iter().copied()))
            .chain(panel.groups.iter().flat_map(|g| g.1.iter().copied()))
    };
    let only_curves = panel
        .series
        .iter()
        .all(|s| matches!(s.shape, Shape::Lines(_) | Shape::Fill(_)));
    let x_margin = if panel.equal_scales {
        0.06
    } else if only_curves {
        0.0
    } else {
        0.04
    };
    let x = panel.ranges[0].unwrap_or_else(|| {
        if bars {
            (-0.6, panel.categories.len() as f64 - 0.4)
        } else {
            range_of(xs(), panel.scales[0], x_margin)
        }
    });
    let y = panel.ranges[1].unwrap_or_else(|| {
        if bars {
            let (lo, hi) = range_of(ys().chain([0.0]), Scale::Linear, 0.0);
            (lo.min(0.0), hi + 0.08 * (hi - lo))
        } else {
            range_of(ys(), panel.scales[1], 0.08)
        }
    });
    [x, y]
}

/// `range` widened about its middle by `factor` (on its scale).
fn widen((lo, hi): (f64, f64), scale: Scale, factor: f64) -> (f64, f64) {
    match scale {
        Scale::Linear => {
            let (m, h) = (0.5 * (lo + hi), 0.5 * (hi - lo) * factor);
            (m - h, m + h)
        }
        Scale::Log => {
            let (a, b) = (lo.log10(), hi.log10());
            let (m, h) = (0.5 * (a + b), 0.5 * (b - a) * factor);
            (10f64.powf(m - h), 10f64.powf(m + h))
        }
    }
}

/// `ranges` with one scale for both axes in the rectangle `plot`: the
/// axis with the more pixels a unit is widened.
fn equal(mut ranges: [(f64, f64); 2], scales: [Scale; 2], plot: [f64; 4]) -> [(f64, f64); 2] {
    let span = |r: (f64, f64), s: Scale| match s {
        Scale::Linear => r.1 - r.0,
        Scale::Log => r.1.log10() - r.0.log10(),
    };
    let per_x = (plot[2] - plot[0]) / span(ranges[0], scales[0]);
    let per_y = (plot[3] - plot[1]) / span(ranges[1], scales[1]);
    if per_x > per_y {
        ranges[0] = widen(ranges[0], scales[0], per_x / per_y);
    } else {
        ranges[1] = widen(ranges[1], scales[1], per_y / per_x);
    }
    ranges
}

/// The plotting rectangle and the axes of `panel` in `cell`.
struct Frame {
    /// Left, top, right, bottom of the axes, in pixels.
    plot: [f64; 4],
    x: Axis,
    y: Axis,
    /// The top left corner of the panel's legend box, if it has one.
    legend_at: Option<(f64, f64)>,
    /// Pixels a printed point.
    px: f64,
}

impl Frame {
    /// The panel's axes, and where its legend goes: where it covers the
    /// least of what is drawn; if that is not nothing, the ordinate is
    /// extended upwards to make room for it at the top.
    fn lay_out(panel: &Panel, cell: &Cell, look: &dyn Fn(&Series) -> Look) -> Frame {
        let ranges = ranges(panel);
        let mut frame = Frame::axes(panel, cell, ranges);
        let entries = entries(panel, look);
        if !cell.legend || entries.len() < 2 {
            return frame;
        }
        let legend = Legend {
            entries: &entries,
            px: cell.px,
        };
        let (place, covered) = frame.legend_place(&legend, &ink_of(panel, &frame, look));
        frame.legend_at = Some(place);
        if covered <= 0.5 * cell.px || panel.ranges[1].is_some() {
            return frame;
        }
        let [_, t, _, b] = frame.plot;
        let (_, bh) = legend.box_size();
        let room = (bh + 8.0 * cell.px) / (b - t);
        if room >= 0.7 {
            return frame;
        }
        let mut ranges = ranges;
        let (lo, hi) = ranges[1];
        ranges[1] = match panel.scales[1] {
            Scale::Linear => (lo, hi + (hi - lo) * room / (1.0 - room)),
            Scale::Log => {
                let (a, z) = (lo.log10(), hi.log10());
                (lo, 10f64.powf(z + (z - a) * room / (1.0 - room)))
            }
        };
        let mut frame = Frame::axes(panel, cell, ranges);
        let (place, _) = frame.legend_place(&legend, &ink_of(panel, &frame, look));
        frame.legend_at = Some(place);
        frame
    }

    /// Where `legend`'s box covers the least of `drawn`: a corner, else
    /// somewhere up a side; and how much it covers, in pixels.
    fn legend_place(&self, legend: &Legend, drawn: &[Vec<(f64, f64)>]) -> ((f64, f64), f64) {
        let [l, t, r, b] = self.plot;
        let (bw, bh) = legend.box_size();
        let inset = 4.0 * legend.px;
        let (left, right) = (l + inset, r - bw - inset);
        let (top, bottom) = (t + inset, b - bh - inset);
        let corners = [(right, top), (left, top), (right, bottom), (left, bottom)];
        let sides = (1..8).map(|k| top + k as f64 * (bottom - top) / 8.0);
        corners
            .into_iter()
            .chain(sides.flat_map(|y| [(right, y), (left, y)]))
            .map(|(x, y)| {
                let area = [x - inset, y - inset, x + bw + inset, y + bh + inset];
                ((x, y), ink(drawn, area))
            })
            .fold(None, |best: Option<((f64, f64), f64)>, c| match best {
                Some(b) if b.1 <= c.1 => Some(b),
                _ => Some(c),
            })
            .unwrap_or(((right, top), 0.0))
    }

    fn axes(panel: &Panel, cell: &Cell, ranges: [(f64, f64); 2]) -> Frame {
        let px = cell.px;
        let [left, top, width, height] = cell.area;
        let tick_font = points::TICK * px;
        let label_font = points::LABEL * px;
        let tick = points::TICK_LENGTH * px;
        let top_margin = match cell.caption_lines {
            0 => 0.8 * tick_font,
            lines => (0.7 + 1.3 * lines as f64) * points::CAPTION * px,
        };
        let bottom_margin = tick
            + 1.5 * tick_font
            + if cell.x_label.is_some() {
                1.7 * label_font
            } else {
                0.3 * tick_font
            };
        let plot_top = top + top_margin;
        let plot_bottom = top + height - bottom_margin;
        let bars = !panel.categories.is_empty();
        let mut ranges = ranges;
        let mut plot = [left, plot_top, left + width, plot_bottom];
        let (mut x, mut y) = (
            Axis::new(panel.scales[0], ranges[0], 2),
            Axis::new(panel.scales[1], ranges[1], 2),
        );
        for _ in 0..2 {
            let y_room = ((plot_bottom - plot_top) / (2.6 * tick_font)).floor() as usize;
            y = Axis::new(panel.scales[1], ranges[1], y_room.clamp(2, 10));
            let y_label_width = if panel.y_label.is_empty() {
                0.0
            } else {
                1.6 * label_font
            };
            let plot_left =
                (left + y_label_width + y.widest_label(tick_font) + tick + 0.5 * tick_font)
                    .max(cell.least_left);
            let provisional = Axis::new(panel.scales[0], ranges[0], 6);
            let right_margin = (0.5 * provisional.widest_label(tick_font)).max(5.0 * px);
            let plot_right = left + width - right_margin;
            plot = [plot_left, plot_top, plot_right, plot_bottom];
            let widest = provisional.widest_label(tick_font).max(tick_font);
            let x_room = ((plot_right - plot_left) / (widest + 1.2 * tick_font)).round() as usize;
            x = if bars {
                let ticks = panel
                    .categories
                    .iter()
                    .enumerate()
                    .map(|(i, c)| (i as f64, c.clone()))
                    .collect();
                Axis {
                    scale: Scale::Linear,
                    range: ranges[0],
                    ticks,
                }
            } else {
                Axis::new(panel.scales[0], ranges[0], x_room.clamp(2, 10))
            };
            if !panel.equal_scales {
                break;
            }
            ranges = equal(ranges, panel.scales, plot);
        }
        if panel.equal_scales {
            // The last pass's tick labels may have moved the axes: the
            // ranges fitted to where they are, the ticks with them.
            ranges = equal(ranges, panel.scales, plot);
            let rooms = (x.ticks.len().max(2), y.ticks.len().max(2));
            x = Axis::new(panel.scales[0], ranges[0], rooms.0);
            y = Axis::new(panel.scales[1], ranges[1], rooms.1);
        }
        Frame {
            plot,
            x,
            y,
            legend_at: None,
            px: cell.px,
        }
    }

    fn to_page(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let [l, t, r, b] = self.plot;
        (self.x.place(x, l, r), self.y.place(y, b, t))
    }
}

/// What a legend must not cover: the panel's curves, points, bars, levels
/// and marks, as polylines in pixels.
fn ink_of(panel: &Panel, frame: &Frame, look: &dyn Fn(&Series) -> Look) -> Vec<Vec<(f64, f64)>> {
    let [l, t, r, b] = frame.plot;
    let mut drawn: Vec<Vec<(f64, f64)>> = Vec::new();
    let n = panel.groups.len().max(1) as f64;
    for (g, (_, values)) in panel.groups.iter().enumerate() {
        for (i, v) in values.iter().enumerate() {
            let x0 = i as f64 - 0.4 + g as f64 * 0.8 / n;
            let (a, z) = (frame.to_page((x0, 0.0)), frame.to_page((x0 + 0.8 / n, *v)));
            drawn.push(vec![(a.0, a.1), (a.0, z.1), (z.0, z.1), (z.0, a.1)]);
        }
    }
    for (_, ys) in &panel.levels {
        for y in ys {
            let y = frame.y.place(*y, b, t);
            drawn.push(vec![(l, y), (r, y)]);
        }
    }
    for (x, _) in &panel.marks {
        let x = frame.x.place(*x, l, r);
        drawn.push(vec![(x, t), (x, b)]);
    }
    for ((x, y), note) in &panel.notes {
        let p = frame.to_page((*x, *y));
        let size = points::TICK * frame.px;
        drawn.push(vec![p, (p.0 + text::width(note, size), p.1)]);
    }
    for series in &panel.series {
        let page = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
            points.iter().map(|&p| frame.to_page(p)).collect()
        };
        match &series.shape {
            Shape::Fill(_) => {}
            Shape::Lines(lines) => drawn.extend(lines.iter().map(|p| page(p))),
            Shape::LineAndPoints(p) | Shape::Points(p) => {
                let points = page(p);
                if look(series).dash.is_some() {
                    drawn.push(points.clone());
                }
                // A marker as a short cross, so that it counts.
                for (x, y) in points {
                    drawn.push(vec![(x - 3.0, y), (x + 3.0, y)]);
                    drawn.push(vec![(x, y - 3.0), (x, y + 3.0)]);
                }
            }
            Shape::Arrow(ends) => drawn.push(page(ends)),
        }
    }
    drawn
}

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
    let (x, y, size) = (fmt(x), fmt(y), fmt(size));
    let mut attributes = vec![
        ("x", x.as_str()),
        ("y", y.as_str()),
        ("font-family", FONT),
        ("font-size", size.as_str()),
        ("text-anchor", anchor),
    ];
    attributes.extend_from_slice(extra);
    let parsed: f64 = attributes[3].1.parse().unwrap_or(10.0);
    w.text_runs(&attributes, &text::runs(content, parsed));
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
        let p = frame.to_page((*x, *y));
        write_text(
            w,
            p,
            note,
            tick_font,
            "start",
            &[("fill", "#333333"), ("class", "note")],
        );
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

/// The caption of `panel` in lines that fit in `cell`.
pub(crate) fn caption_lines(panel: &Panel, cell: &Cell) -> Vec<String> {
    let size = points::CAPTION * cell.px;
    panel.caption.as_ref().map_or(Vec::new(), |caption| {
        text::wrap(caption, size, cell.area[2] - 2.0 * size)
    })
}

/// Where the axes of `panel` in `cell` start, in pixels.
pub(crate) fn plot_left(panel: &Panel, cell: &Cell, look: &dyn Fn(&Series) -> Look) -> f64 {
    Frame::lay_out(panel, cell, look).plot[0]
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

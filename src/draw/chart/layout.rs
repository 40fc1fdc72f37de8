//! A panel's layout in its cell: the axes' ranges from the data (with
//! one scale for both where asked), the plotting rectangle and the ticks
//! its labels leave room for, and where its legend covers the least.

use super::axis::{Axis, range_of};
use super::legend::{Legend, entries, ink};
use super::look::{Look, points};
use super::panel::{Panel, Scale, Series, Shape};
use super::text;

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
pub(crate) struct Frame {
    /// Left, top, right, bottom of the axes, in pixels.
    pub(crate) plot: [f64; 4],
    pub(crate) x: Axis,
    pub(crate) y: Axis,
    /// The top left corner of the panel's legend box, if it has one.
    pub(crate) legend_at: Option<(f64, f64)>,
    /// Pixels a printed point.
    px: f64,
}

impl Frame {
    /// The panel's axes, and where its legend goes: where it covers the
    /// least of what is drawn; if that is not nothing, the ordinate is
    /// extended upwards to make room for it at the top.
    pub(crate) fn lay_out(panel: &Panel, cell: &Cell, look: &dyn Fn(&Series) -> Look) -> Frame {
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

    pub(crate) fn to_page(&self, (x, y): (f64, f64)) -> (f64, f64) {
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
        // Its box, wrapped as it is drawn.
        let p = frame.to_page((*x, *y));
        let size = points::TICK * frame.px;
        let room = (r - p.0 - 2.0 * frame.px).max(4.0 * size);
        let lines = text::wrap(note, size, room);
        let wide = lines
            .iter()
            .map(|l| text::width(l, size))
            .fold(0.0, f64::max);
        let low = p.1 + 1.25 * size * (lines.len() as f64 - 1.0);
        drawn.push(vec![
            (p.0, p.1 - size),
            (p.0 + wide, p.1 - size),
            (p.0 + wide, low),
            (p.0, low),
            (p.0, p.1 - size),
        ]);
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

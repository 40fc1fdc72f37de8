//! Legends: each entry the swatch of what it names, drawn in the same look
//! (colour, dashes, width, marker), and its name; laid out in rows under a
//! title or boxed in a panel's emptiest corner.

use super::look::{BAR_OPACITY, SHADE, level_look};
use super::look::{Colour, FONT, Look, points};
use super::marks::marker;
use super::panel::{Panel, Series, Shape};
use super::text;
use crate::draw::svg::{Writer, fmt};

/// What an entry draws before its name.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Swatch {
    /// A line (and a marker on it, if the look has one), or a marker alone
    /// if the look has no line.
    Series(Look),
    /// A filled rectangle.
    Fill { colour: Colour, opacity: f64 },
}

/// One entry: its swatch and its name.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Entry {
    pub(crate) name: String,
    pub(crate) swatch: Swatch,
}

/// A legend, at a scale of `px` pixels a printed point.
pub(crate) struct Legend<'a> {
    pub(crate) entries: &'a [Entry],
    pub(crate) px: f64,
}

impl Legend<'_> {
    fn font(&self) -> f64 {
        points::LEGEND * self.px
    }

    fn swatch_length(&self) -> f64 {
        18.0 * self.px
    }

    fn gap(&self) -> f64 {
        4.0 * self.px
    }

    /// The height of a line of entries.
    pub(crate) fn line_height(&self) -> f64 {
        1.5 * self.font()
    }

    fn entry_width(&self, entry: &Entry) -> f64 {
        self.swatch_length() + self.gap() + text::width(&entry.name, self.font())
    }

    /// The entries laid out in rows at most `width` wide: the rows, each
    /// its entries' indices and their x offsets.
    pub(crate) fn rows(&self, width: f64) -> Vec<Vec<(usize, f64)>> {
        let space = 12.0 * self.px;
        let mut rows: Vec<Vec<(usize, f64)>> = Vec::new();
        let mut x = 0.0;
        for (i, entry) in self.entries.iter().enumerate() {
            let w = self.entry_width(entry);
            match rows.last_mut() {
                Some(row) if x + w <= width => row.push((i, x)),
                _ => {
                    rows.push(vec![(i, 0.0)]);
                    x = 0.0;
                }
            }
            x += w + space;
        }
        rows
    }

    /// The entries in rows from (`x`, `y`) (the first line's middle), at
    /// most `width` wide; the height they take.
    pub(crate) fn draw_rows(&self, w: &mut Writer, (x, y): (f64, f64), width: f64) -> f64 {
        let rows = self.rows(width);
        for (r, row) in rows.iter().enumerate() {
            let line = y + r as f64 * self.line_height();
            for &(i, dx) in row {
                self.entry(w, &self.entries[i], (x + dx, line));
            }
        }
        rows.len() as f64 * self.line_height()
    }

    /// The size of the boxed legend (one entry a line).
    pub(crate) fn box_size(&self) -> (f64, f64) {
        let widest = self
            .entries
            .iter()
            .map(|e| self.entry_width(e))
            .fold(0.0, f64::max);
        let margin = self.gap();
        (
            widest + 2.0 * margin,
            self.line_height() * self.entries.len() as f64 + margin,
        )
    }

    /// The legend in a white box, its top left corner at `corner`.
    pub(crate) fn draw_boxed(&self, w: &mut Writer, (x, y): (f64, f64)) {
        let (bw, bh) = self.box_size();
        w.element(
            "rect",
            &[
                ("x", &fmt(x)),
                ("y", &fmt(y)),
                ("width", &fmt(bw)),
                ("height", &fmt(bh)),
                ("fill", "none"),
                ("stroke", "#BBBBBB"),
                ("stroke-width", &fmt(points::GRID * self.px)),
                ("class", "legend-box"),
            ],
        );
        for (i, entry) in self.entries.iter().enumerate() {
            let line = y + self.gap() / 2.0 + self.line_height() * (i as f64 + 0.5);
            self.entry(w, entry, (x + self.gap(), line));
        }
    }

    /// One entry, its swatch from `x` on the line `y`.
    fn entry(&self, w: &mut Writer, entry: &Entry, (x, y): (f64, f64)) {
        let length = self.swatch_length();
        match &entry.swatch {
            Swatch::Series(look) => {
                if look.dash.is_some() {
                    let mut attributes = vec![
                        ("x1", fmt(x)),
                        ("y1", fmt(y)),
                        ("x2", fmt(x + length)),
                        ("y2", fmt(y)),
                    ];
                    attributes.extend(stroke(look, self.px));
                    let refs: Vec<(&str, &str)> =
                        attributes.iter().map(|(k, v)| (*k, v.as_str())).collect();
                    w.element("line", &refs);
                }
                if let Some((shape, open)) = look.marker {
                    marker(w, shape, open, look, (x + length / 2.0, y), self.px);
                }
            }
            Swatch::Fill { colour, opacity } => {
                let h = 0.9 * self.font();
                w.element(
                    "rect",
                    &[
                        ("x", &fmt(x)),
                        ("y", &fmt(y - h / 2.0)),
                        ("width", &fmt(length)),
                        ("height", &fmt(h)),
                        ("fill", &colour.to_string()),
                        ("opacity", &fmt(*opacity)),
                    ],
                );
            }
        }
        let runs = text::runs(&entry.name, self.font());
        w.text_runs(
            &[
                ("x", &fmt(x + length + self.gap())),
                ("y", &fmt(y + 0.35 * self.font())),
                ("font-family", FONT),
                ("font-size", &fmt(self.font())),
                ("text-anchor", "start"),
                ("fill", "#000000"),
            ],
            &runs,
        );
    }
}

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

/// A line's stroke attributes in `look`, at `px` pixels a point.
pub(crate) fn stroke(look: &Look, px: f64) -> Vec<(&'static str, String)> {
    let mut attributes = vec![
        ("fill", "none".to_string()),
        ("stroke", look.colour.to_string()),
        ("stroke-width", fmt(look.width * px)),
        ("opacity", fmt(look.opacity)),
    ];
    if let Some(pattern) = look.dash.and_then(|d| d.pattern()) {
        let scaled: Vec<String> = pattern.iter().map(|p| fmt(p * px)).collect();
        attributes.push(("stroke-dasharray", scaled.join(" ")));
    }
    attributes
}

/// How much of `lines` (polylines, in pixels) lies within `area`
/// ([left, top, right, bottom]): the length inside it, in pixels.
pub(crate) fn ink(lines: &[Vec<(f64, f64)>], area: [f64; 4]) -> f64 {
    lines
        .iter()
        .flat_map(|line| line.windows(2))
        .map(|pair| clipped_length(pair[0], pair[1], area))
        .sum()
}

/// The length of the segment from `a` to `b` within `area` (Liang–Barsky).
fn clipped_length(a: (f64, f64), b: (f64, f64), [x0, y0, x1, y1]: [f64; 4]) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut enter, mut leave) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return 0.0;
            }
        } else if p < 0.0 {
            enter = enter.max(q / p);
        } else {
            leave = leave.min(q / p);
        }
    }
    if leave > enter {
        (leave - enter) * dx.hypot(dy)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ink_is_the_length_inside() {
        let lines = vec![vec![(0.0, 5.0), (20.0, 5.0)]];
        assert_eq!(ink(&lines, [5.0, 0.0, 10.0, 10.0]), 5.0);
        assert_eq!(ink(&lines, [5.0, 6.0, 10.0, 10.0]), 0.0);
    }
}

//! Charts fit to print: panels of curves, points, bands and bars in a
//! grid, as self-contained SVG, in one style — the motion diagrams, the
//! hodographs and every chart of the examples are drawn with it.
//!
//! A chart is laid out for print: its sizes are set in points at a 16 cm
//! column (no text under 8 pt there, subscripts at three quarters), so a
//! wider picture has larger text rather than smaller; coordinates are
//! written to a hundredth of a pixel. Series are told apart by colour
//! (Okabe and Ito's set, which colour-blind readers tell apart) and by
//! dashes or marker shapes as well, so the chart reads in grey too; a
//! series keeps its look in every panel of a chart (its look follows its
//! name). In every title, label and name `_` starts a subscript (`J_II`).
//!
//! ```
//! use linkage::draw::chart::{Chart, Panel};
//!
//! let wave: Vec<(f64, f64)> = (0..=36).map(|i| (10.0 * i as f64, (i as f64 / 6.0).sin())).collect();
//! let svg = Chart::new("A wave", "φ [°]")
//!     .panel(
//!         Panel::new("y [mm]")
//!             .line("y(φ)", wave.clone())
//!             .points("measured", wave.iter().step_by(4).copied().collect())
//!             .levels("limits", &[-0.9, 0.9]),
//!     )
//!     .render()?;
//! assert!(svg.starts_with("<svg"));
//! # Ok::<(), linkage::draw::chart::DiagramError>(())
//! ```
//!
//! The area's files: the chart (here: the page, its title and shared
//! legend, the grid of panels), a panel as a builder (`panel.rs`), its
//! layout (`layout.rs`) and drawing (`render.rs`), the axes (`axis.rs`), the legends (`legend.rs`),
//! markers and arrows (`marks.rs`), the looks and printed sizes
//! (`look.rs`), the words and numbers (`text.rs`), and the checks
//! (`error.rs`).

mod axis;
mod error;
mod layout;
mod legend;
pub mod look;
mod marks;
mod panel;
mod render;
mod text;

pub use error::DiagramError;
pub use look::{Colour, Dash, Marker};
pub use panel::{Panel, Scale};

pub(crate) use error::{MAX_PIXELS, check_plottable, grid, height, plottable, width, within};

use crate::draw::svg::{Writer, fmt};
use layout::Cell;
use legend::{Entry, Legend};
use look::{FONT, Look, points};
use panel::{Series, Shape};

/// Where a chart's legends go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Legends {
    /// In each panel, where it covers the least; once under the title when
    /// every panel would show the same one.
    Auto,
    /// Every entry of every panel, once, under the title.
    Shared,
}

/// Panels in a grid under a title: the charts of a machine's reduced
/// dynamics, a study's errors against a distance, and the like. See the
/// [module docs](self).
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    title: String,
    note: Option<String>,
    x_label: String,
    panels: Vec<Panel>,
    columns: usize,
    width: u32,
    panel_height: u32,
    legends: Legends,
}

impl Chart {
    /// A chart titled `title` whose panels share the abscissa `x_label`
    /// (drawn under the bottom panel of each column; a panel may have its
    /// own, [`Panel::x_label`]).
    pub fn new(title: &str, x_label: &str) -> Chart {
        Chart {
            title: title.into(),
            note: None,
            x_label: x_label.into(),
            panels: Vec::new(),
            columns: 1,
            width: 900,
            panel_height: 300,
            legends: Legends::Auto,
        }
    }

    pub fn panel(mut self, panel: Panel) -> Chart {
        self.panels.push(panel);
        self
    }

    /// A line under the title: what the chart shows, how it was made.
    pub fn note(mut self, note: &str) -> Chart {
        self.note = Some(note.into());
        self
    }

    /// Panels per row (default 1; 1 to 20, checked when it is drawn).
    pub fn columns(mut self, columns: usize) -> Chart {
        self.columns = columns;
        self
    }

    /// The picture's width (200 to 20 000), and each panel's height (120 to
    /// 20 000), in pixels; checked when it is drawn. The text keeps its
    /// printed size: a wider picture has larger text in pixels.
    pub fn size(mut self, width: u32, panel_height: u32) -> Chart {
        self.width = width;
        self.panel_height = panel_height;
        self
    }

    /// One legend under the title with every entry of every panel, instead
    /// of one in each panel.
    pub fn shared_legend(mut self) -> Chart {
        self.legends = Legends::Shared;
        self
    }

    /// Each series' place among the chart's names: its colour, marker and
    /// dashes follow it.
    fn order(&self) -> Vec<&str> {
        let mut names: Vec<&str> = Vec::new();
        for series in self.panels.iter().flat_map(|p| &p.series) {
            if !names.contains(&series.name.as_str()) {
                names.push(&series.name);
            }
        }
        names
    }

    /// How `series` is drawn: what was chosen, the rest from its name's
    /// place `k` in the chart.
    fn look(series: &Series, k: usize) -> Look {
        let chosen = series.chosen;
        let colour = chosen
            .colour
            .unwrap_or(look::COLOURS[k % look::COLOURS.len()]);
        let dash = chosen.dash.unwrap_or(look::DASHES[k % look::DASHES.len()]);
        // Past the seventh name, each colour comes again with another
        // marker (and dashes), so that no two names look alike.
        let n = look::MARKERS.len();
        let shape = chosen.marker.unwrap_or(look::MARKERS[(k + k / n) % n]);
        let (dash, marker, opacity) = match series.shape {
            Shape::Lines(_) => (Some(dash), None, 1.0),
            Shape::LineAndPoints(_) => (Some(dash), Some((shape, chosen.open)), 1.0),
            Shape::Points(_) => (None, Some((shape, chosen.open)), 1.0),
            Shape::Fill(_) => (None, None, 0.3),
            Shape::Arrow(_) => (Some(look::Dash::Solid), None, 1.0),
        };
        Look {
            colour,
            dash,
            marker,
            width: chosen.width.unwrap_or(points::LINE),
            opacity: chosen.opacity.unwrap_or(opacity),
        }
    }

    fn check(&self) -> Result<(), DiagramError> {
        for panel in &self.panels {
            for series in &panel.series {
                let values = series.points().flat_map(|p| [p.0, p.1]);
                check_plottable("point", &series.name, values, 2)?;
                for (axis, scale) in panel.scales.iter().enumerate() {
                    if *scale == Scale::Log {
                        let at = series.points().position(|p| [p.0, p.1][axis] <= 0.0);
                        if let Some(pose) = at {
                            return Err(DiagramError::NotPositive {
                                what: "point",
                                name: series.name.clone(),
                                pose,
                            });
                        }
                    }
                }
            }
            for (x, label) in &panel.marks {
                check_plottable("mark", label, [*x], 1)?;
            }
            for (label, ys) in &panel.levels {
                check_plottable("level", label, ys.iter().copied(), 1)?;
            }
            for (label, from, to) in &panel.shades {
                check_plottable("shaded range", label, [*from, *to], 2)?;
            }
            for ((x, y), note) in &panel.notes {
                check_plottable("note", note, [*x, *y], 2)?;
            }
            for (name, values) in &panel.groups {
                check_plottable("bar", name, values.iter().copied(), 1)?;
            }
            for (axis, range) in panel.ranges.iter().enumerate() {
                if let Some((lo, hi)) = range {
                    let log = panel.scales[axis] == Scale::Log;
                    if !(plottable(*lo) && plottable(*hi) && lo < hi && (!log || *lo > 0.0)) {
                        return Err(DiagramError::BadSetting {
                            what: "an axis's range",
                            must: "finite, increasing (and positive on a log axis)",
                            value: *lo,
                        });
                    }
                }
            }
        }
        Ok(())
    }

    /// The chart as SVG.
    pub fn render(&self) -> Result<String, DiagramError> {
        self.check()?;
        let width = f64::from(width(self.width)?);
        let each = height(self.panel_height, 120)?;
        let (_, rows_height) = grid(self.columns, self.panels.len(), each)?;
        let px = width / points::COLUMN;
        let names = self.order();
        let look = |series: &Series| {
            let k = names.iter().position(|n| *n == series.name).unwrap_or(0);
            Chart::look(series, k)
        };
        let shared = self.shared_entries(&look);
        let margin = 6.0 * px;
        let title_font = points::TITLE * px;
        let note_font = points::NOTE * px;
        let line_width = width - 2.0 * margin;
        let title_lines = text::wrap(&self.title, title_font, line_width);
        let note_lines = self
            .note
            .as_deref()
            .map_or(Vec::new(), |n| text::wrap(n, note_font, line_width));
        let mut head = margin + 0.2 * title_font;
        let mut heading: Vec<(f64, &str, f64, &str)> = Vec::new();
        for line in title_lines.iter().filter(|l| !l.is_empty()) {
            head += 1.25 * title_font;
            heading.push((head, line, title_font, "title"));
        }
        for line in &note_lines {
            head += 1.4 * note_font;
            heading.push((head, line, note_font, "note"));
        }
        let legend_y = head + 1.6 * points::LEGEND * px;
        let legend_height = shared.as_ref().map_or(0.0, |entries| {
            let legend = Legend { entries, px };
            legend.rows(line_width).len() as f64 * legend.line_height()
        });
        head += 0.6 * title_font + legend_height;
        if legend_height > 0.0 {
            head += 0.4 * title_font;
        }
        let across = self.columns > 1 && !self.x_label.is_empty();
        let foot = if across {
            2.0 * points::LABEL * px
        } else {
            0.0
        };
        let height = head + f64::from(rows_height) + foot + margin;
        let cell_width = (width - margin) / self.columns as f64;
        let mut cells: Vec<Cell> = (0..self.panels.len())
            .map(|i| {
                let (row, column) = (i / self.columns, i % self.columns);
                let below = i + self.columns < self.panels.len();
                let panel = &self.panels[i];
                // The chart's abscissa label goes under the bottom panel
                // of a single column; across the page under several.
                let x_label = match &panel.x_label {
                    Some(own) => Some(own.as_str()),
                    None if !below && !self.x_label.is_empty() && self.columns == 1 => {
                        Some(self.x_label.as_str())
                    }
                    None => None,
                };
                Cell {
                    area: [
                        margin / 2.0 + column as f64 * cell_width,
                        head + row as f64 * f64::from(each),
                        cell_width,
                        f64::from(each),
                    ],
                    px,
                    x_label,
                    legend: shared.is_none(),
                    clip: format!("clip-{:08x}-{i}", fingerprint(&self.title)),
                    least_left: 0.0,
                    caption_lines: 0,
                }
            })
            .collect();
        // The panels of a row start their axes at one height.
        let captions: Vec<usize> = self
            .panels
            .iter()
            .zip(&cells)
            .map(|(panel, cell)| layout::caption_lines(panel, cell).len())
            .collect();
        for (i, cell) in cells.iter_mut().enumerate() {
            let row = i / self.columns * self.columns;
            let end = (row + self.columns).min(captions.len());
            cell.caption_lines = captions[row..end].iter().copied().max().unwrap_or(0);
        }
        // The panels of a column start their axes at one abscissa.
        let lefts: Vec<f64> = self
            .panels
            .iter()
            .zip(&cells)
            .map(|(panel, cell)| layout::plot_left(panel, cell, &look) - cell.area[0])
            .collect();
        for (i, cell) in cells.iter_mut().enumerate() {
            let column = (i % self.columns..lefts.len()).step_by(self.columns);
            let most = column.map(|k| lefts[k]).fold(0.0, f64::max);
            cell.least_left = cell.area[0] + most;
        }
        let mut w = Writer::svg(width, height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "#FFFFFF")],
        );
        w.open("defs", &[]);
        for (panel, cell) in self.panels.iter().zip(&cells) {
            render::clip(&mut w, panel, cell, &look);
        }
        w.close("defs");
        for (y, line, size, class) in heading {
            let fill = if class == "note" {
                "#333333"
            } else {
                "#000000"
            };
            w.text_runs(
                &[
                    ("x", &fmt(margin)),
                    ("y", &fmt(y)),
                    ("font-family", FONT),
                    ("font-size", &fmt(size)),
                    ("fill", fill),
                    ("class", class),
                ],
                &text::runs(line, size),
            );
        }
        if let Some(entries) = &shared {
            Legend { entries, px }.draw_rows(&mut w, (margin, legend_y), width - 2.0 * margin);
        }
        for (panel, cell) in self.panels.iter().zip(&cells) {
            render::draw(&mut w, panel, cell, &look);
        }
        if across {
            let size = points::LABEL * px;
            w.text_runs(
                &[
                    ("x", &fmt(width / 2.0)),
                    ("y", &fmt(height - margin - 0.5 * size)),
                    ("font-family", FONT),
                    ("font-size", &fmt(size)),
                    ("text-anchor", "middle"),
                ],
                &text::runs(&self.x_label, size),
            );
        }
        Ok(w.finish())
    }

    /// The legend drawn once under the title, if there is one: every entry
    /// of every panel when asked for, or the one legend every panel would
    /// show (of more than one entry, in more than one panel).
    fn shared_entries(&self, look: &dyn Fn(&Series) -> Look) -> Option<Vec<Entry>> {
        let each: Vec<Vec<Entry>> = self
            .panels
            .iter()
            .map(|p| legend::entries(p, look))
            .collect();
        match self.legends {
            Legends::Shared => {
                let mut all: Vec<Entry> = Vec::new();
                for entry in each.into_iter().flatten() {
                    if !all.iter().any(|e| e.name == entry.name) {
                        all.push(entry);
                    }
                }
                Some(all)
            }
            Legends::Auto => {
                let first = each.first()?;
                let same = each.iter().all(|e| e == first);
                (self.panels.len() > 1 && first.len() > 1 && same).then(|| first.clone())
            }
        }
    }
}

/// A short hash of `text` (FNV-1a), to keep the ids of two charts in one
/// page apart.
fn fingerprint(text: &str) -> u32 {
    text.bytes().fold(0x811c_9dc5_u32, |h, b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

//! Charts: panels of curves over one abscissa, with marks and reference
//! levels, in a grid.

use super::plot::*;
use super::{DiagramError, PALETTE};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// One curve of a [`Chart`] panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub dashed: bool,
}

/// One panel of a [`Chart`]: curves against a common abscissa, with
/// vertical marks and horizontal reference levels.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub y_label: String,
    pub series: Vec<Series>,
    pub marks: Vec<(f64, String)>,
    /// Reference levels: a label and the ordinates it is drawn at.
    pub levels: Vec<(String, Vec<f64>)>,
}

impl Panel {
    pub fn new(y_label: &str) -> Panel {
        Panel {
            y_label: y_label.into(),
            series: Vec::new(),
            marks: Vec::new(),
            levels: Vec::new(),
        }
    }

    /// A solid curve.
    pub fn line(mut self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.series.push(Series {
            name: name.into(),
            points,
            dashed: false,
        });
        self
    }

    /// A dashed curve.
    pub fn dashed(mut self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.series.push(Series {
            name: name.into(),
            points,
            dashed: true,
        });
        self
    }

    /// A vertical dashed mark at x, labelled.
    pub fn mark(mut self, x: f64, label: &str) -> Panel {
        self.marks.push((x, label.into()));
        self
    }

    /// Horizontal reference lines at each of `ys` across the panel — one
    /// limit or target (±35°, say) — in one style, with one legend entry.
    pub fn levels(mut self, label: &str, ys: &[f64]) -> Panel {
        self.levels.push((label.into(), ys.to_vec()));
        self
    }

    /// The panel's legend: each curve, then each level, with the style it
    /// is drawn in.
    fn legend(&self) -> Legend {
        let curves = self
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| (s.name.clone(), curve_style(i, s)));
        let levels = self
            .levels
            .iter()
            .map(|(label, _)| (label.clone(), level_style()));
        Legend(curves.chain(levels).collect())
    }
}

/// The style of the `i`th curve of a panel: its colour, dashed or solid.
fn curve_style(i: usize, series: &Series) -> ShapeStyle {
    stroke(PALETTE[i % PALETTE.len()], 2, series.dashed)
}

fn level_style() -> ShapeStyle {
    stroke(LEVEL, 2, true)
}

/// Panels of curves over one abscissa, as SVG, laid out in a grid: the
/// charts of a machine's reduced dynamics and the like. A panel of more
/// than one curve or level has its legend, in the corner its curves leave
/// emptiest; when every panel would show the same legend, it is shown once,
/// under the title. In labels and names `_` starts a subscript (`J_II`).
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    title: String,
    x_label: String,
    panels: Vec<Panel>,
    columns: usize,
    width: u32,
    panel_height: u32,
}

impl Chart {
    pub fn new(title: &str, x_label: &str) -> Chart {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            panels: Vec::new(),
            columns: 1,
            width: 900,
            panel_height: 240,
        }
    }

    pub fn panel(mut self, panel: Panel) -> Chart {
        self.panels.push(panel);
        self
    }

    /// Panels per row (default 1; 1 to 20, checked when it is drawn).
    pub fn columns(mut self, columns: usize) -> Chart {
        self.columns = columns;
        self
    }

    /// The picture's width (200 to 20 000), and each panel's height (120 to
    /// 20 000), in pixels; checked when it is drawn.
    pub fn size(mut self, width: u32, panel_height: u32) -> Chart {
        self.width = width;
        self.panel_height = panel_height;
        self
    }

    /// The chart as SVG.
    pub fn render(&self) -> Result<String, DiagramError> {
        for panel in &self.panels {
            for series in &panel.series {
                let coordinates = series.points.iter().flat_map(|p| [p.0, p.1]);
                check_plottable("point", &series.name, coordinates, 2)?;
            }
            for (x, label) in &panel.marks {
                check_plottable("mark", label, [*x], 1)?;
            }
            for (label, ys) in &panel.levels {
                check_plottable("level", label, ys.iter().copied(), 1)?;
            }
        }
        let each = height(self.panel_height, 120)?;
        let (rows, rows_height) = grid(self.columns, self.panels.len(), each)?;
        let title_height = if self.shared_legend().is_some() {
            66
        } else {
            40
        };
        let height = title_height + rows_height + 10;
        page((width(self.width)?, height), |root| {
            self.draw(root, title_height, rows)
        })
    }

    /// The legend every panel would show, if there are several panels and
    /// they all show the same one.
    fn shared_legend(&self) -> Option<Legend> {
        let first = self.panels.first()?.legend();
        let same = self.panels.iter().all(|p| p.legend().0 == first.0);
        (self.panels.len() > 1 && first.0.len() > 1 && same).then_some(first)
    }

    fn draw(
        &self,
        root: &Page<'_>,
        title_height: u32,
        rows: usize,
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (top, body) = root.split_vertically(title_height);
        top.draw(&title_text(self.title.clone(), 11))?;
        let shared = self.shared_legend();
        if let Some(legend) = &shared {
            legend.row(&top, 20, 50)?;
        }
        let areas = body.split_evenly((rows, self.columns));
        for (panel, area) in self.panels.iter().zip(areas.iter()) {
            let points = || panel.series.iter().flat_map(|s| s.points.iter());
            let levels = || panel.levels.iter().flat_map(|(_, ys)| ys.iter().copied());
            let x_range = span(points().map(|p| p.0));
            let y_range = pad(span(points().map(|p| p.1).chain(levels())));
            let mut chart = ChartBuilder::on(area)
                .margin_left(8)
                .margin_right(16)
                .margin_top(12)
                .x_label_area_size(38)
                .y_label_area_size(70)
                .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .bold_line_style(BLACK.mix(0.08))
                .axis_desc_style(("sans-serif", 13))
                .label_style(("sans-serif", 12))
                .y_desc(panel.y_label.clone())
                .x_desc(self.x_label.clone())
                .y_label_formatter(&|y| trim(*y))
                .x_label_formatter(&|x| trim(*x))
                .draw()?;
            if y_range.0 < 0.0 && y_range.1 > 0.0 {
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(x_range.0, 0.0), (x_range.1, 0.0)],
                    BLACK.mix(0.35).stroke_width(1),
                )))?;
            }
            for (x, label) in &panel.marks {
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(*x, y_range.0), (*x, y_range.1)],
                    stroke(MARK, 1, true),
                )))?;
                let right_half = *x > 0.5 * (x_range.0 + x_range.1);
                let (h, nudge) = if right_half {
                    (HPos::Right, -0.006)
                } else {
                    (HPos::Left, 0.006)
                };
                chart.draw_series(std::iter::once(Text::new(
                    label.clone(),
                    (*x + nudge * (x_range.1 - x_range.0), y_range.1),
                    ("sans-serif", 12)
                        .into_font()
                        .color(&RGBColor(90, 90, 90))
                        .pos(Pos::new(h, VPos::Top)),
                )))?;
            }
            // The styles drawn are the legend's: one source for both.
            let legend = panel.legend();
            let (curve_styles, level_styles) = legend.0.split_at(panel.series.len());
            for ((_, ys), (_, style)) in panel.levels.iter().zip(level_styles) {
                chart
                    .draw_series(ys.iter().map(|&y| {
                        PathElement::new(vec![(x_range.0, y), (x_range.1, y)], *style)
                    }))?;
            }
            for (series, (_, style)) in panel.series.iter().zip(curve_styles) {
                chart.draw_series(LineSeries::new(series.points.iter().copied(), *style))?;
            }
            if legend.0.len() > 1 && shared.is_none() {
                // Where it covers the least of the curves, levels and
                // marks: a corner, else somewhere up a side.
                let plot = chart.plotting_area().strip_coord_spec();
                let (w, h) = plot.dim_in_pixel();
                let (w, h) = (f64::from(w), f64::from(h));
                let pixel = |(x, y): (f64, f64)| {
                    (
                        (x - x_range.0) / (x_range.1 - x_range.0) * w,
                        (y_range.1 - y) / (y_range.1 - y_range.0) * h,
                    )
                };
                let mut lines: Vec<Vec<(f64, f64)>> = panel
                    .series
                    .iter()
                    .map(|s| s.points.iter().map(|&p| pixel(p)).collect())
                    .collect();
                lines.extend(levels().map(|y| vec![pixel((x_range.0, y)), pixel((x_range.1, y))]));
                lines.extend(
                    panel
                        .marks
                        .iter()
                        .map(|(x, _)| vec![pixel((*x, y_range.0)), pixel((*x, y_range.1))]),
                );
                let (bw, bh) = legend.box_size();
                let (left, right) = (8, w as i32 - bw - 8);
                let (top, bottom) = (8, h as i32 - bh - 8);
                let middles = (1..8).map(|k| top + k * (bottom - top) / 8);
                let corners = [(left, top), (right, top), (left, bottom), (right, bottom)];
                let sides = middles.flat_map(|y| [(left, y), (right, y)]);
                let place = corners
                    .into_iter()
                    .chain(sides)
                    .map(|(x, y)| {
                        let area = [x - 4, y - 4, x + bw + 4, y + bh + 4].map(f64::from);
                        ((x, y), ink(&lines, area))
                    })
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .map_or((right, bottom), |(at, _)| at);
                legend.boxed(&plot, place)?;
            }
        }
        Ok(())
    }
}

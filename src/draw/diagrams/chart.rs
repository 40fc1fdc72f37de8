//! Charts: panels of curves over one abscissa, with marks, in a grid.

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
/// vertical marks.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub y_label: String,
    pub series: Vec<Series>,
    pub marks: Vec<(f64, String)>,
}

impl Panel {
    pub fn new(y_label: &str) -> Panel {
        Panel {
            y_label: y_label.into(),
            series: Vec::new(),
            marks: Vec::new(),
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
}

/// Panels of curves over one abscissa, as SVG, laid out in a grid: the
/// charts of a machine's reduced dynamics and the like.
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
        }
        let each = height(self.panel_height, 120)?;
        let (rows, rows_height) = grid(self.columns, self.panels.len(), each)?;
        let title_height = 40;
        let height = title_height + rows_height + 10;
        page((width(self.width)?, height), |root| {
            self.draw(root, title_height, rows)
        })
    }

    fn draw(
        &self,
        root: &Page<'_>,
        title_height: u32,
        rows: usize,
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (top, body) = root.split_vertically(title_height);
        top.draw(&title_text(self.title.clone(), 11))?;
        let areas = body.split_evenly((rows, self.columns));
        for (panel, area) in self.panels.iter().zip(areas.iter()) {
            let points = || panel.series.iter().flat_map(|s| s.points.iter());
            let x_range = span(points().map(|p| p.0));
            let y_range = pad(span(points().map(|p| p.1)));
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
                chart.draw_series(
                    dashed(*x, y_range, 14)
                        .into_iter()
                        .map(|d| PathElement::new(d, RGBColor(120, 120, 120).stroke_width(1))),
                )?;
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
            for (i, series) in panel.series.iter().enumerate() {
                let colour = PALETTE[i % PALETTE.len()];
                let style = colour.stroke_width(2);
                let drawn = if series.dashed {
                    // Dashes: every other piece of the polyline.
                    let pieces: Vec<Vec<(f64, f64)>> = series
                        .points
                        .chunks(4)
                        .step_by(2)
                        .map(|c| c.to_vec())
                        .filter(|c| c.len() > 1)
                        .collect();
                    chart.draw_series(pieces.into_iter().map(|p| PathElement::new(p, style)))?
                } else {
                    chart.draw_series(LineSeries::new(series.points.iter().copied(), style))?
                };
                if panel.series.len() > 1 {
                    drawn.label(series.name.clone()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2))
                    });
                }
            }
            if panel.series.len() > 1 {
                // The corner the curves leave emptiest.
                let corners = [
                    (SeriesLabelPosition::UpperLeft, (0.0, 0.7)),
                    (SeriesLabelPosition::UpperRight, (0.65, 0.7)),
                    (SeriesLabelPosition::LowerLeft, (0.0, 0.0)),
                    (SeriesLabelPosition::LowerRight, (0.65, 0.0)),
                ];
                let crowding = |(x0, y0): (f64, f64)| {
                    points()
                        .filter(|p| {
                            let fx = (p.0 - x_range.0) / (x_range.1 - x_range.0);
                            let fy = (p.1 - y_range.0) / (y_range.1 - y_range.0);
                            fx >= x0 && fx <= x0 + 0.35 && fy >= y0 && fy <= y0 + 0.3
                        })
                        .count()
                };
                let corner = corners
                    .into_iter()
                    .min_by_key(|(_, at)| crowding(*at))
                    .map_or(SeriesLabelPosition::LowerRight, |(c, _)| c);
                chart
                    .configure_series_labels()
                    .position(corner)
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK.mix(0.25))
                    .label_font(("serif", 13))
                    .draw()?;
            }
        }
        Ok(())
    }
}

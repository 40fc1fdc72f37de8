//! Motion diagrams: every coordinate, its velocity and its acceleration
//! against the driver over a sweep, as SVG (plotters' SVG backend, no
//! system libraries), with the sweep's singular poses marked.
//!
//! Rows: positions, velocities, accelerations. Columns: angles and lengths
//! (each with its units), as the mechanism has them. A coordinate is taken
//! for an angle when the closure equations take its sine or cosine
//! ([`Linkage::TRIG_U`]); [`Diagrams::kind`] overrides that. Angles are
//! drawn in degrees, their rates in rad/s and rad/s².
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::diagrams::Diagrams;
//!
//! #[linkage::linkage(
//!     u = [theta3, s],
//!     v = [theta2],
//!     closure = [
//!         r * theta2.cos() + l * theta3.cos() - s,
//!         r * theta2.sin() + l * theta3.sin() - e,
//!     ],
//! )]
//! #[derive(Clone, Debug)]
//! pub struct SliderCrank { pub r: f64, pub l: f64, pub e: f64 }
//!
//! let crank = SliderCrank { r: 50.0, l: 200.0, e: 10.0 };
//! let drive = Drive::Line { from: vector![0.0], to: vector![std::f64::consts::TAU], steps: 360 };
//! let options = SweepOptions { speed: 10.0, ..SweepOptions::default() };
//! let sweep = crank.sweep(&vector![-0.05, 250.0], &drive, &options)?;
//! let svg = Diagrams::new().title("An offset slider-crank").render(&crank, &sweep)?;
//! assert!(svg.contains("<svg"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::svg::pretty_name;
use linkage_runtime::{EventKind, Linkage, Sweep};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Whether a coordinate is an angle (radians) or a length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Angle,
    Length,
}

/// What went wrong drawing the diagrams.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum DiagramError {
    /// A size or a number of columns is out of its range.
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The sweep has fewer than two poses.
    TooFewPoses { poses: usize },
    /// A value to plot is NaN, infinite, or beyond ±1e300 (where the
    /// axes' arithmetic would overflow).
    NonFinite {
        what: &'static str,
        name: String,
        pose: usize,
    },
    /// plotters could not draw.
    Drawing(String),
}

impl std::fmt::Display for DiagramError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::BadSetting { what, must, value } => {
                write!(f, "{what} must be {must}, got {value}")
            }
            Self::TooFewPoses { poses } => write!(
                f,
                "motion diagrams need a sweep of at least two poses, got {poses}"
            ),
            Self::NonFinite { name, pose, what } => write!(
                f,
                "the {what} of `{name}` at pose {pose} is not finite, or beyond ±1e300"
            ),
            Self::Drawing(inner) => write!(f, "drawing failed: {inner}"),
        }
    }
}

impl std::error::Error for DiagramError {}

/// How to draw the motion diagrams of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagrams {
    title: Option<String>,
    length_unit: String,
    time_unit: String,
    width: u32,
    row_height: u32,
    kinds: Vec<(String, Kind)>,
}

impl Default for Diagrams {
    fn default() -> Self {
        Diagrams::new()
    }
}

/// One curve: a coordinate's values, in display units.
struct Curve {
    name: String,
    kind: Kind,
    /// [position, velocity, acceleration] at each pose.
    values: Vec<[f64; 3]>,
}

const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 96, 172),
    RGBColor(200, 64, 40),
    RGBColor(46, 125, 50),
    RGBColor(142, 68, 173),
    RGBColor(224, 130, 20),
    RGBColor(0, 131, 143),
];

impl Diagrams {
    /// Units mm and s, 900 pixels wide, 230 per row.
    pub fn new() -> Diagrams {
        Diagrams {
            title: None,
            length_unit: "mm".into(),
            time_unit: "s".into(),
            width: 900,
            row_height: 230,
            kinds: Vec::new(),
        }
    }

    pub fn title(mut self, title: &str) -> Diagrams {
        self.title = Some(title.into());
        self
    }

    /// The units of the model's lengths and of time.
    pub fn units(mut self, length: &str, time: &str) -> Diagrams {
        self.length_unit = length.into();
        self.time_unit = time.into();
        self
    }

    /// Draw the coordinate `name` (of u or v) as `kind`.
    pub fn kind(mut self, name: &str, kind: Kind) -> Diagrams {
        self.kinds.push((name.into(), kind));
        self
    }

    /// The picture's size: `width` pixels (200 to 20 000), `row_height`
    /// per row (120 to 20 000); checked when it is drawn.
    pub fn size(mut self, width: u32, row_height: u32) -> Diagrams {
        self.width = width;
        self.row_height = row_height;
        self
    }

    fn kind_of(&self, name: &str, trig: bool) -> Kind {
        self.kinds
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map_or(if trig { Kind::Angle } else { Kind::Length }, |(_, k)| *k)
    }

    /// The diagrams of `sweep` (a sweep of `model`) as SVG.
    pub fn render<L: Linkage<M, F>, const M: usize, const F: usize>(
        &self,
        _model: &L,
        sweep: &Sweep<M, F>,
    ) -> Result<String, DiagramError> {
        let poses = &sweep.poses;
        if poses.len() < 2 {
            return Err(DiagramError::TooFewPoses { poses: poses.len() });
        }
        // The abscissa: the driver for f = 1, else the pose's step.
        let driver_kind = if F == 1 {
            Some(self.kind_of(L::V_NAMES[0], L::TRIG_V[0]))
        } else {
            None
        };
        let abscissa = |v: f64| match driver_kind {
            Some(Kind::Angle) => v.to_degrees(),
            _ => v,
        };
        let xs: Vec<f64> = poses
            .iter()
            .map(|p| {
                if F == 1 {
                    abscissa(p.v[0])
                } else {
                    p.step as f64
                }
            })
            .collect();
        check_plottable("driver", L::V_NAMES[0], xs.iter().copied(), 1)?;
        let x_desc = match driver_kind {
            Some(Kind::Angle) => format!("{} [°]", pretty_name(L::V_NAMES[0])),
            Some(Kind::Length) => format!("{} [{}]", pretty_name(L::V_NAMES[0]), self.length_unit),
            None => "pose".to_string(),
        };
        let mut curves = Vec::new();
        for k in 0..M {
            let name = L::U_NAMES[k];
            let kind = self.kind_of(name, L::TRIG_U[k]);
            let mut values = Vec::with_capacity(poses.len());
            for (i, p) in poses.iter().enumerate() {
                let position = if kind == Kind::Angle {
                    p.u[k].to_degrees()
                } else {
                    p.u[k]
                };
                for (what, x) in [
                    ("position", position),
                    ("velocity", p.udot[k]),
                    ("acceleration", p.uddot[k]),
                ] {
                    if !plottable(x) {
                        return Err(DiagramError::NonFinite {
                            what,
                            name: name.into(),
                            pose: i,
                        });
                    }
                }
                values.push([position, p.udot[k], p.uddot[k]]);
            }
            curves.push(Curve {
                name: pretty_name(name),
                kind,
                values,
            });
        }
        let events: Vec<(f64, &'static str)> = if F == 1 {
            sweep
                .events
                .iter()
                .map(|e| {
                    (
                        abscissa(e.v[0]),
                        match e.kind {
                            EventKind::LimitPosition => "limit position",
                            EventKind::BranchPoint => "branch point",
                        },
                    )
                })
                .collect()
        } else {
            Vec::new()
        };
        let columns: Vec<Kind> = [Kind::Angle, Kind::Length]
            .into_iter()
            .filter(|k| curves.iter().any(|c| c.kind == *k))
            .collect();
        let title_height = 36;
        let (_, rows_height) = grid(1, 3, height(self.row_height, 120)?)?;
        let height = title_height + rows_height + 10;
        page((width(self.width)?, height), |root| {
            self.draw(root, title_height, &columns, &curves, &xs, &x_desc, &events)
        })
    }

    #[allow(clippy::too_many_arguments)]
    fn draw(
        &self,
        root: &Page<'_>,
        title_height: u32,
        columns: &[Kind],
        curves: &[Curve],
        xs: &[f64],
        x_desc: &str,
        events: &[(f64, &'static str)],
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (top, body) = root.split_vertically(title_height);
        if let Some(title) = &self.title {
            top.draw(&title_text(title.clone(), 10))?;
        }
        // One legend for every panel, at the top right.
        let mut x = self.width as i32 - 16 - 70 * curves.len() as i32;
        for (i, curve) in curves.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            let y = (title_height as i32 / 2).max(12);
            top.draw(&PathElement::new(
                vec![(x, y), (x + 24, y)],
                colour.stroke_width(3),
            ))?;
            top.draw(&Text::new(
                curve.name.clone(),
                (x + 30, y - 9),
                ("serif", 17).into_font().color(&BLACK),
            ))?;
            x += 70;
        }
        let panels = body.split_evenly((3, columns.len()));
        let (l, t) = (&self.length_unit, &self.time_unit);
        let x_range = span(xs.iter().copied());
        for row in 0..3 {
            for (col, kind) in columns.iter().enumerate() {
                let panel = &panels[row * columns.len() + col];
                let mine: Vec<&Curve> = curves.iter().filter(|c| c.kind == *kind).collect();
                let y_desc = match (kind, row) {
                    (Kind::Angle, 0) => "angle [°]".to_string(),
                    (Kind::Angle, 1) => "angular velocity [rad/s]".to_string(),
                    (Kind::Angle, _) => "angular acceleration [rad/s²]".to_string(),
                    (Kind::Length, 0) => format!("position [{l}]"),
                    (Kind::Length, 1) => format!("velocity [{l}/{t}]"),
                    (Kind::Length, _) => format!("acceleration [{l}/{t}²]"),
                };
                let y_range = pad(span(
                    mine.iter()
                        .flat_map(|c| c.values.iter().map(move |v| v[row])),
                ));
                let mut chart = ChartBuilder::on(panel)
                    .margin_left(8)
                    .margin_right(16)
                    .margin_top(10)
                    .x_label_area_size(if row == 2 { 40 } else { 22 })
                    .y_label_area_size(74)
                    .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
                let mut mesh = chart.configure_mesh();
                mesh.light_line_style(WHITE)
                    .bold_line_style(BLACK.mix(0.08))
                    .axis_desc_style(("sans-serif", 13))
                    .label_style(("sans-serif", 12))
                    .y_desc(y_desc)
                    .y_label_formatter(&|y| trim(*y))
                    .x_label_formatter(&|x| trim(*x));
                if row == 2 {
                    mesh.x_desc(x_desc);
                }
                mesh.draw()?;
                // Zero, where it is in range.
                if y_range.0 < 0.0 && y_range.1 > 0.0 {
                    chart.draw_series(std::iter::once(PathElement::new(
                        vec![(x_range.0, 0.0), (x_range.1, 0.0)],
                        BLACK.mix(0.35).stroke_width(1),
                    )))?;
                }
                for &(x, what) in events {
                    let dashes = dashed(x, y_range, 14);
                    chart.draw_series(
                        dashes
                            .into_iter()
                            .map(|d| PathElement::new(d, RGBColor(120, 120, 120).stroke_width(1))),
                    )?;
                    if row == 0 {
                        // Written towards the middle, so as not to leave the
                        // panel at its edges.
                        let right_half = x > 0.5 * (x_range.0 + x_range.1);
                        let (h, nudge) = if right_half {
                            (HPos::Right, -0.006)
                        } else {
                            (HPos::Left, 0.006)
                        };
                        let style = ("sans-serif", 13)
                            .into_font()
                            .color(&RGBColor(90, 90, 90))
                            .pos(Pos::new(h, VPos::Top));
                        chart.draw_series(std::iter::once(Text::new(
                            what,
                            (x + nudge * (x_range.1 - x_range.0), y_range.1),
                            style,
                        )))?;
                    }
                }
                for curve in &mine {
                    let index = curves
                        .iter()
                        .position(|c| c.name == curve.name)
                        .unwrap_or(0);
                    let colour = PALETTE[index % PALETTE.len()];
                    chart.draw_series(LineSeries::new(
                        xs.iter().zip(&curve.values).map(|(&x, v)| (x, v[row])),
                        colour.stroke_width(2),
                    ))?;
                }
            }
        }
        Ok(())
    }
}

/// Vertical dashes at x over the y range.
fn dashed(x: f64, y: (f64, f64), pieces: usize) -> Vec<Vec<(f64, f64)>> {
    let step = (y.1 - y.0) / (2 * pieces) as f64;
    (0..pieces)
        .map(|i| {
            let a = y.0 + 2.0 * i as f64 * step;
            vec![(x, a), (x, a + step)]
        })
        .collect()
}

fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (0.0, 1.0);
    }
    // At least a millionth of the values' size wide (1 for values all
    // zero), so that the axis has ticks to draw.
    let least = (1e-6 * lo.abs().max(hi.abs())).max(f64::MIN_POSITIVE);
    if hi - lo >= least {
        (lo, hi)
    } else {
        let middle = 0.5 * lo + 0.5 * hi;
        let half = if middle == 0.0 { 1.0 } else { least };
        (middle - half, middle + half)
    }
}

/// The range widened by 8 % each way.
fn pad((lo, hi): (f64, f64)) -> (f64, f64) {
    let d = 0.08 * (hi - lo);
    (lo - d, hi + d)
}

/// A tick label without trailing zeros.
fn trim(x: f64) -> String {
    if x != 0.0 && (x.abs() >= 1e5 || x.abs() < 1e-3) {
        return format!("{x:.1e}");
    }
    let text = format!("{x:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

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

/// A hodograph's name, its points, and the vector marked with its label.
type HodographPanel = (String, Vec<(f64, f64)>, Option<(f64, f64, String)>);

/// Hodographs: the tips of force vectors over a cycle drawn from a common
/// origin, one panel per force, each panel with equal scales on both axes
/// (so directions and magnitudes read true) — the polar diagrams of joint
/// reactions.
#[derive(Clone, Debug, PartialEq)]
pub struct Hodographs {
    title: String,
    unit: String,
    panels: Vec<HodographPanel>,
    columns: usize,
    size: u32,
}

impl Hodographs {
    /// Forces in `unit` (e.g. "N").
    pub fn new(title: &str, unit: &str) -> Hodographs {
        Hodographs {
            title: title.into(),
            unit: unit.into(),
            panels: Vec::new(),
            columns: 2,
            size: 420,
        }
    }

    /// A force's components over the cycle, and optionally one vector
    /// marked (drawn as an arrow from the origin) with its label.
    pub fn panel(
        mut self,
        name: &str,
        points: Vec<(f64, f64)>,
        mark: Option<(f64, f64, &str)>,
    ) -> Hodographs {
        self.panels.push((
            name.into(),
            points,
            mark.map(|(x, y, l)| (x, y, l.to_string())),
        ));
        self
    }

    /// Panels per row (default 2; 1 to 20) and each panel's side in pixels
    /// (160 to 20 000, the whole picture too); checked when it is drawn.
    pub fn layout(mut self, columns: usize, size: u32) -> Hodographs {
        self.columns = columns;
        self.size = size;
        self
    }

    pub fn render(&self) -> Result<String, DiagramError> {
        for (name, points, mark) in &self.panels {
            check_plottable("force", name, points.iter().flat_map(|p| [p.0, p.1]), 2)?;
            if let Some((x, y, label)) = mark {
                check_plottable("marked force", label, [*x, *y], 2)?;
            }
        }
        let side = height(self.size, 160)?;
        let (rows, rows_height) = grid(self.columns, self.panels.len(), side)?;
        let total_width = within(
            "the picture's width",
            "at most 20 000 pixels (columns × their side)",
            self.columns as u64 * u64::from(side),
            0..=MAX_PIXELS.into(),
        )?;
        let title_height = 40;
        page((total_width, title_height + rows_height), |root| {
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
        let unit = &self.unit;
        for ((name, points, mark), area) in self.panels.iter().zip(areas.iter()) {
            // A square window about the origin holding every tip.
            let mut reach = points
                .iter()
                .fold(0.0_f64, |r, p| r.max(p.0.abs()).max(p.1.abs()));
            if let Some((x, y, _)) = mark {
                reach = reach.max(x.abs()).max(y.abs());
            }
            let reach = reach.max(f64::MIN_POSITIVE) * 1.12;
            let mut chart = ChartBuilder::on(area)
                .caption(name.clone(), ("serif", 16))
                .margin(10)
                .x_label_area_size(34)
                .y_label_area_size(58)
                .build_cartesian_2d(-reach..reach, -reach..reach)?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .bold_line_style(BLACK.mix(0.08))
                .axis_desc_style(("sans-serif", 12))
                .label_style(("sans-serif", 11))
                .x_desc(format!("Fx [{unit}]"))
                .y_desc(format!("Fy [{unit}]"))
                .x_label_formatter(&|x| trim(*x))
                .y_label_formatter(&|y| trim(*y))
                .draw()?;
            let axis = BLACK.mix(0.35).stroke_width(1);
            chart.draw_series([
                PathElement::new(vec![(-reach, 0.0), (reach, 0.0)], axis),
                PathElement::new(vec![(0.0, -reach), (0.0, reach)], axis),
            ])?;
            let mut closed = points.clone();
            if let Some(first) = points.first() {
                closed.push(*first);
            }
            chart.draw_series(LineSeries::new(closed, PALETTE[0].stroke_width(2)))?;
            if let Some((x, y, label)) = mark {
                let red = PALETTE[1];
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(0.0, 0.0), (*x, *y)],
                    red.stroke_width(2),
                )))?;
                chart.draw_series(std::iter::once(Circle::new((*x, *y), 4, red.filled())))?;
                chart.draw_series(std::iter::once(Text::new(
                    label.clone(),
                    (*x, *y),
                    ("sans-serif", 12).into_font().color(&red),
                )))?;
            }
        }
        Ok(())
    }
}
/// Whether a value can be plotted: finite and within ±1e300, so that an
/// axis's span and its padding cannot overflow.
fn plottable(x: f64) -> bool {
    x.abs() <= 1e300 // false for NaN too
}

/// The first of `values` that cannot be plotted, as an error.
fn check_plottable(
    what: &'static str,
    name: &str,
    values: impl IntoIterator<Item = f64>,
    per_pose: usize,
) -> Result<(), DiagramError> {
    match values.into_iter().position(|x| !plottable(x)) {
        Some(i) => Err(DiagramError::NonFinite {
            what,
            name: name.into(),
            pose: i / per_pose.max(1),
        }),
        None => Ok(()),
    }
}

/// The largest side of a picture, in pixels.
const MAX_PIXELS: u32 = 20_000;

/// A size or a count, checked: in `range`.
fn within(
    what: &'static str,
    must: &'static str,
    value: u64,
    range: std::ops::RangeInclusive<u64>,
) -> Result<u32, DiagramError> {
    if range.contains(&value) {
        Ok(value as u32)
    } else {
        Err(DiagramError::BadSetting {
            what,
            must,
            value: value as f64,
        })
    }
}

/// A picture's width, checked: 200 to 20 000 pixels.
fn width(value: u32) -> Result<u32, DiagramError> {
    within(
        "the width",
        "from 200 to 20 000 pixels",
        value.into(),
        200..=MAX_PIXELS.into(),
    )
}

/// A panel's or a row's height, checked: `least` to 20 000 pixels.
fn height(value: u32, least: u32) -> Result<u32, DiagramError> {
    within(
        "a panel's height",
        "from 120 (160 for hodographs) to 20 000 pixels",
        value.into(),
        least.into()..=MAX_PIXELS.into(),
    )
}

/// Panels per row, and the rows they make of `panels`, checked: 1 to 20
/// columns, the whole picture at most 20 000 pixels high for `each` pixels
/// a row.
fn grid(columns: usize, panels: usize, each: u32) -> Result<(usize, u32), DiagramError> {
    let columns = within(
        "the number of columns",
        "from 1 to 20",
        columns as u64,
        1..=20,
    )? as usize;
    let rows = panels.div_ceil(columns).max(1);
    let tall = within(
        "the picture's height",
        "at most 20 000 pixels (rows × their height)",
        rows as u64 * u64::from(each),
        0..=MAX_PIXELS.into(),
    )?;
    Ok((rows, tall))
}

/// The drawing area of an SVG page.
type Page<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

/// An SVG page of `size`, white, on which `draw` draws; plotters' errors
/// become [`DiagramError::Drawing`].
fn page(
    size: (u32, u32),
    draw: impl FnOnce(&Page<'_>) -> Result<(), Box<dyn std::error::Error>>,
) -> Result<String, DiagramError> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        let drawing = |e: &dyn std::fmt::Display| DiagramError::Drawing(e.to_string());
        root.fill(&WHITE).map_err(|e| drawing(&e))?;
        draw(&root).map_err(|e| drawing(&e))?;
        root.present().map_err(|e| drawing(&e))?;
    }
    Ok(out)
}

/// A page's title, at the left of its band, `y` pixels down.
fn title_text(title: String, y: i32) -> Text<'static, (i32, i32), String> {
    Text::new(title, (16, y), ("serif", 19).into_font().color(&BLACK))
}

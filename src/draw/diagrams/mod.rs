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
//! use linkage::draw::diagrams::Diagrams;
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
//!
//! The area's files: the motion diagrams of a sweep (here), [`Chart`]s of
//! panels (`chart.rs`), [`Hodographs`] (`hodographs.rs`), and what they
//! share (`plot.rs`: the checks of sizes and values, the page, the axes'
//! ranges and ticks).

mod chart;
mod hodographs;
mod plot;

pub use chart::{Chart, Panel, Series};
pub use hodographs::Hodographs;

use linkage_runtime::{EventKind, Linkage, Sweep};
use linkage_symbolic::names::textbook;
use plot::*;
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

crate::error::error_impls! {
    DiagramError {
        Self::BadSetting { what, must, value } => ("{what} must be {must}, got {value}"),
        Self::TooFewPoses { poses } => ("motion diagrams need a sweep of at least two poses, got {poses}"),
        Self::NonFinite { name, pose, what } => ("the {what} of `{name}` at pose {pose} is not finite, or beyond ±1e300"),
        Self::Drawing(inner) => ("drawing failed: {inner}"),
    }
    wraps {  }
}

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

pub(super) const PALETTE: [RGBColor; 6] = [
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
            Some(Kind::Angle) => format!("{} [°]", textbook(L::V_NAMES[0])),
            Some(Kind::Length) => format!("{} [{}]", textbook(L::V_NAMES[0]), self.length_unit),
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
                name: textbook(name),
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

//! Motion diagrams: every coordinate, its velocity and its acceleration
//! against the driver over a sweep, as SVG drawn with the library's
//! [`Chart`], with the sweep's singular poses marked.
//!
//! Rows: positions, velocities, accelerations. Columns: angles and lengths
//! (each with its units), as the mechanism has them. A coordinate is taken
//! for an angle when the closure equations take its sine or cosine
//! ([`Kernels::trig_u`](crate::Kernels::trig_u)); [`Diagrams::kind`] overrides that. Angles are
//! drawn in degrees, their rates in rad/s and rad/s². A sweep of one
//! revolution of an angular driver back to the pose it started from is a
//! period of the motion: it is drawn over 0…360° whatever angle it started
//! at.
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
//! In every title, label and name `_` starts a subscript: `J_II`, `ω_1`
//! are drawn J with II below the line, ω₁. Every legend's swatch is drawn
//! in the look of its curve.
//!
//! The area's files: the motion diagrams of a sweep (here) and the
//! [`Hodographs`] (`hodographs.rs`), both drawn as [`Chart`]s
//! ([`crate::draw::chart`], re-exported here).

mod hodographs;

pub use crate::draw::chart::{Chart, DiagramError, Panel};
pub use hodographs::Hodographs;

use crate::draw::chart::{check_plottable, height, plottable};
use crate::runtime::{EventKind, Linkage, Sweep};
use linkage_symbolic::names::textbook;

/// Whether a coordinate is an angle (radians) or a length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Angle,
    Length,
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

impl Diagrams {
    /// Units mm and s, 900 pixels wide, 260 per row.
    pub fn new() -> Diagrams {
        Diagrams {
            title: None,
            length_unit: "mm".into(),
            time_unit: "s".into(),
            width: 900,
            row_height: 260,
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
        model: &L,
        sweep: &Sweep<M, F>,
    ) -> Result<String, DiagramError> {
        let poses = &sweep.poses;
        if poses.len() < 2 {
            return Err(DiagramError::TooFewPoses { poses: poses.len() });
        }
        // The abscissa: the driver for f = 1, else the pose's step.
        let driver_kind = if F == 1 {
            Some(self.kind_of(model.v_names()[0], model.trig_v()[0]))
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
        check_plottable("driver", model.v_names()[0], xs.iter().copied(), 1)?;
        let x_desc = match driver_kind {
            Some(Kind::Angle) => format!("{} [°]", textbook(model.v_names()[0])),
            Some(Kind::Length) => {
                format!("{} [{}]", textbook(model.v_names()[0]), self.length_unit)
            }
            None => "pose".to_string(),
        };
        let mut curves = Vec::new();
        for k in 0..M {
            let name = model.u_names()[k];
            let kind = self.kind_of(name, model.trig_u()[k]);
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
        let (xs, curves, events) = if driver_kind == Some(Kind::Angle) {
            one_period(xs, curves, events)
        } else {
            (xs, curves, events)
        };
        let columns: Vec<Kind> = [Kind::Angle, Kind::Length]
            .into_iter()
            .filter(|k| curves.iter().any(|c| c.kind == *k))
            .collect();
        let each = height(self.row_height, 120)?;
        let (l, t) = (&self.length_unit, &self.time_unit);
        let mut chart = Chart::new(self.title.as_deref().unwrap_or(""), &x_desc)
            .columns(columns.len())
            .size(self.width, each)
            .shared_legend();
        for row in 0..3 {
            for kind in &columns {
                let y_desc = match (kind, row) {
                    (Kind::Angle, 0) => "angle [°]".to_string(),
                    (Kind::Angle, 1) => "angular velocity [rad/s]".to_string(),
                    (Kind::Angle, _) => "angular acceleration [rad/s²]".to_string(),
                    (Kind::Length, 0) => format!("position [{l}]"),
                    (Kind::Length, 1) => format!("velocity [{l}/{t}]"),
                    (Kind::Length, _) => format!("acceleration [{l}/{t}²]"),
                };
                let mut panel = Panel::new(&y_desc);
                for &(x, what) in &events {
                    panel = panel.mark(x, if row == 0 { what } else { "" });
                }
                for curve in curves.iter().filter(|c| c.kind == *kind) {
                    let points = xs.iter().zip(&curve.values).map(|(&x, v)| (x, v[row]));
                    panel = panel.line(&curve.name, points.collect());
                }
                chart = chart.panel(panel);
            }
        }
        chart.render()
    }
}

/// The abscissae, curves and events of a sweep of an angular driver (in
/// degrees), as one period over 0…360° when the sweep is one: one
/// revolution of the driver back to the pose it started from. The poses
/// past the driver's wrap-around (360°, or 0° turning back) are moved to
/// their place in 0…360° (their angles less what they gained over the
/// revolution, so that each curve runs on through the start), and the
/// curves are closed at 0° and 360° by interpolation. Any other sweep is
/// returned as it is.
fn one_period(
    xs: Vec<f64>,
    curves: Vec<Curve>,
    events: Vec<(f64, &'static str)>,
) -> (Vec<f64>, Vec<Curve>, Vec<(f64, &'static str)>) {
    let n = xs.len();
    let revolution = n >= 3 && ((xs[n - 1] - xs[0]).abs() - 360.0).abs() < 1e-6;
    // What each coordinate gains over the revolution: whole turns for an
    // angle, nothing for a length.
    let gains: Vec<f64> = curves
        .iter()
        .map(|c| c.values[n - 1][0] - c.values[0][0])
        .collect();
    let periodic = curves.iter().zip(&gains).all(|(c, &gain)| match c.kind {
        Kind::Angle => (gain - 360.0 * (gain / 360.0).round()).abs() < 1e-4,
        Kind::Length => {
            let size = c.values.iter().fold(1.0_f64, |m, v| m.max(v[0].abs()));
            gain.abs() < 1e-6 * size
        }
    });
    if !(revolution && periodic) {
        return (xs, curves, events);
    }
    // The driver within [0, 360), and the turn it is in.
    let wrap = |x: f64| {
        let w = x.rem_euclid(360.0);
        if 360.0 - w < 1e-9 { 0.0 } else { w }
    };
    let turn = |x: f64| ((x - wrap(x)) / 360.0).round();
    let first_turn = turn(xs[0]);
    let direction = (xs[n - 1] - xs[0]).signum();
    // The last pose is the first again.
    let mut order: Vec<usize> = (0..n - 1).collect();
    order.sort_by(|&a, &b| wrap(xs[a]).total_cmp(&wrap(xs[b])));
    let (low, high) = (order[0], order[n - 2]);
    let (x_low, x_high) = (wrap(xs[low]), wrap(xs[high]));
    // Where 0° (and 360°) falls between the last pose and the first.
    let t = (360.0 - x_high) / (x_low + 360.0 - x_high);
    let mut wrapped = Vec::with_capacity(n + 1);
    if x_low > 0.0 {
        wrapped.push(0.0);
    }
    wrapped.extend(order.iter().map(|&k| wrap(xs[k])));
    wrapped.push(360.0);
    let curves = curves
        .into_iter()
        .zip(gains)
        .map(|(curve, gain)| {
            let gain = if curve.kind == Kind::Angle { gain } else { 0.0 };
            let value = |k: usize| {
                let mut v = curve.values[k];
                if turn(xs[k]) != first_turn {
                    v[0] -= gain;
                }
                v
            };
            // What it gains from 0° to 360° (the sweep may turn backwards).
            let per_turn = gain * direction;
            let (a, mut b) = (value(high), value(low));
            b[0] += per_turn;
            let at_360: [f64; 3] = std::array::from_fn(|i| a[i] + t * (b[i] - a[i]));
            let mut values = Vec::with_capacity(n + 1);
            if x_low > 0.0 {
                values.push([at_360[0] - per_turn, at_360[1], at_360[2]]);
            }
            values.extend(order.iter().map(|&k| value(k)));
            values.push(at_360);
            Curve { values, ..curve }
        })
        .collect();
    let mut events: Vec<(f64, &'static str)> = events
        .into_iter()
        .map(|(x, what)| (wrap(x), what))
        .collect();
    events.sort_by(|a, b| a.0.total_cmp(&b.0));
    events.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-9 && a.1 == b.1);
    (wrapped, curves, events)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A revolution of the driver from `start`° in steps of `step`° (down
    /// if negative): an angle gaining a turn, and a length.
    fn revolution(start: f64, step: f64) -> (Vec<f64>, Vec<Curve>) {
        let n = (360.0 / step.abs()).round() as usize;
        let xs: Vec<f64> = (0..=n).map(|i| start + step * i as f64).collect();
        let angle = |x: f64| x + 30.0;
        let length = |x: f64| x.to_radians().sin();
        let curve = |name: &str, kind, f: &dyn Fn(f64) -> f64| Curve {
            name: name.into(),
            kind,
            values: xs.iter().map(|&x| [f(x), 1.0, 0.0]).collect(),
        };
        let curves = vec![
            curve("angle", Kind::Angle, &angle),
            curve("length", Kind::Length, &length),
        ];
        (xs, curves)
    }

    fn check_one_period(start: f64, step: f64) {
        let (xs, curves) = revolution(start, step);
        let events = vec![(start + 100.0 * step.signum(), "limit position")];
        let (xs, curves, events) = one_period(xs, curves, events);
        assert_eq!((xs[0], xs[xs.len() - 1]), (0.0, 360.0));
        assert!(xs.windows(2).all(|w| w[0] < w[1]), "{xs:?}");
        // The angle runs on through the old start (by whole turns the same
        // at every pose); the length repeats.
        let turns = curves[0].values[0][0] - 30.0;
        assert!((turns / 360.0 - (turns / 360.0).round()).abs() < 1e-12);
        for (k, &x) in xs.iter().enumerate() {
            let [angle, rate, _] = curves[0].values[k];
            assert!((angle - (x + 30.0 + turns)).abs() < 1e-9, "at {x}: {angle}");
            assert_eq!(rate, 1.0);
            let length = curves[1].values[k][0];
            assert!(
                (length - x.to_radians().sin()).abs() < 2e-3,
                "at {x}: {length}"
            );
        }
        let event = (start + 100.0 * step.signum()).rem_euclid(360.0);
        assert!((events[0].0 - event).abs() < 1e-9);
    }

    #[test]
    fn a_revolution_is_drawn_over_0_to_360_degrees() {
        check_one_period(20.0, 1.0);
        check_one_period(20.5, 1.0);
        check_one_period(-170.0, 2.0);
        check_one_period(20.0, -1.0);
        check_one_period(0.0, 1.0);
    }

    #[test]
    fn other_sweeps_are_drawn_as_they_are() {
        // Half a revolution.
        let (xs, curves) = revolution(20.0, 1.0);
        let half = xs[..=180].to_vec();
        let cut: Vec<Curve> = curves
            .into_iter()
            .map(|c| Curve {
                values: c.values[..=180].to_vec(),
                ..c
            })
            .collect();
        let (same, _, _) = one_period(half.clone(), cut, Vec::new());
        assert_eq!(same, half);
        // A revolution that does not come back to its pose.
        let (xs, mut curves) = revolution(20.0, 1.0);
        curves[1].values[360][0] += 0.5;
        let (same, _, _) = one_period(xs.clone(), curves, Vec::new());
        assert_eq!(same, xs);
    }
}

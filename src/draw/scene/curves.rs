//! Curves given as points of the mechanism's plane — a second design's
//! coupler curve, a target path, a desired trajectory — drawn as
//! polylines, open or closed, each named in the legend, in colours and
//! dash patterns no traced path has.

use super::colour::check_colour;
use super::style;
use super::{Scene, SceneError};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;
use std::fmt::Write as _;

/// A polyline in the mechanism's plane (in the model's length unit),
/// with a name for the legend.
///
/// Unless given, its colour and dash pattern are chosen per curve in
/// turn, told apart from the traced paths' (the first curve solid); it
/// is open unless closed.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    name: String,
    points: Vec<Vector2<f64>>,
    closed: bool,
    colour: Option<String>,
    dashes: Option<Vec<f64>>,
}

/// A curve's stroke, its choices made.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct CurveLook {
    pub(super) colour: String,
    /// An SVG `stroke-dasharray`, empty for a solid line.
    pub(super) dashes: String,
}

impl Curve {
    /// A curve named `name` (its legend entry; an empty name has none)
    /// through `points`: `[x, y]` arrays or `Vector2`s, at least two.
    pub fn new<P: Into<Vector2<f64>>>(name: &str, points: impl IntoIterator<Item = P>) -> Curve {
        Curve {
            name: name.into(),
            points: points.into_iter().map(Into::into).collect(),
            closed: false,
            colour: None,
            dashes: None,
        }
    }

    /// Whether the last point joins the first (a closed coupler curve).
    pub fn closed(mut self, closed: bool) -> Curve {
        self.closed = closed;
        self
    }

    /// The curve's colour, as SVG writes colours (`#0072b2`, `teal`,
    /// `rgb(…)`).
    pub fn colour(mut self, colour: &str) -> Curve {
        self.colour = Some(colour.into());
        self
    }

    /// The dash pattern: lengths in pixels of dash, gap, dash, …, each
    /// positive; none for a solid line.
    pub fn dashes(mut self, pattern: &[f64]) -> Curve {
        self.dashes = Some(pattern.to_vec());
        self
    }

    /// The first mistake in the curve, if any.
    pub(super) fn check(&self) -> Result<(), SceneError> {
        if self.points.len() < 2 {
            return Err(SceneError::TooFewPoints {
                what: "curve",
                name: self.name.clone(),
                points: self.points.len(),
                least: 2,
            });
        }
        if let Some(index) = self
            .points
            .iter()
            .position(|p| !(p.x.is_finite() && p.y.is_finite()))
        {
            return Err(SceneError::NonFinitePoint {
                what: "curve",
                name: self.name.clone(),
                index,
            });
        }
        for &length in self.dashes.iter().flatten() {
            super::positive("a curve's dash length", length)?;
        }
        if let Some(colour) = &self.colour {
            check_colour("a curve", colour)?;
        }
        Ok(())
    }

    pub(super) fn name(&self) -> &str {
        &self.name
    }

    /// The curve's points, in the model's plane.
    pub(super) fn points(&self) -> &[Vector2<f64>] {
        &self.points
    }

    /// The look of the curve, the `k`-th curve of its scene.
    pub(super) fn look(&self, k: usize) -> CurveLook {
        let chosen = style::curve(k);
        CurveLook {
            colour: self.colour.clone().unwrap_or_else(|| chosen.colour.into()),
            dashes: match &self.dashes {
                Some(pattern) => pattern
                    .iter()
                    .map(|&l| fmt(l))
                    .collect::<Vec<_>>()
                    .join(" "),
                None => chosen.dashes.into(),
            },
        }
    }

    /// The stretches of the curve on the screen, given its points there:
    /// the closing one too for a closed curve.
    pub(super) fn segments(&self, at: &[Vector2<f64>]) -> Vec<(Vector2<f64>, Vector2<f64>)> {
        let mut segments: Vec<_> = at.windows(2).map(|pair| (pair[0], pair[1])).collect();
        if let (true, Some(first), Some(last)) = (self.closed, at.first(), at.last()) {
            segments.push((*last, *first));
        }
        segments
    }
}

impl Scene {
    /// A curve through points of the plane (see [`Curve`]), drawn with
    /// the traced paths, in the legend under its name.
    pub fn curve(mut self, curve: Curve) -> Scene {
        self.curves.push(curve);
        self
    }

    /// Every curve through its screen points (`at`, one list per curve).
    pub(super) fn draw_curves(&self, w: &mut Writer, at: &[Vec<Vector2<f64>>]) {
        for (k, (curve, points)) in self.curves.iter().zip(at).enumerate() {
            let mut d = String::new();
            for (i, p) in points.iter().enumerate() {
                let command = if i == 0 { "M" } else { "L" };
                let _ = write!(d, "{command}{} {} ", fmt(p.x), fmt(p.y));
            }
            if curve.closed {
                d.push('Z');
            }
            let look = curve.look(k);
            let mut attributes = vec![
                ("class", "curve"),
                ("data-name", curve.name.as_str()),
                ("d", d.trim_end()),
                ("fill", "none"),
                ("stroke", look.colour.as_str()),
                ("stroke-linejoin", "round"),
            ];
            let id = format!("curve-{k}");
            let width = fmt(style::CURVE_WIDTH);
            attributes.insert(0, ("id", &id));
            attributes.push(("stroke-width", &width));
            if !look.dashes.is_empty() {
                attributes.push(("stroke-dasharray", &look.dashes));
            }
            w.element("path", &attributes);
        }
    }
}

//! Markers: fixed points of the mechanism's plane — the targets of a
//! synthesis, precision points — each set drawn in one shape and colour,
//! named in the legend, each marker labelled if asked ("1", "2", …).

use super::colour::check_colour;
use super::style;
use super::{Scene, SceneError};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;

/// The shape of a marker.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MarkerShape {
    /// A diagonal cross, ×.
    Cross,
    Circle,
    Square,
    /// A triangle pointing up.
    Triangle,
    /// A square standing on a corner.
    Diamond,
}

impl MarkerShape {
    /// The shapes given to sets of markers in turn, when none is given.
    const IN_TURN: [MarkerShape; 5] = [
        MarkerShape::Cross,
        MarkerShape::Circle,
        MarkerShape::Square,
        MarkerShape::Triangle,
        MarkerShape::Diamond,
    ];

    /// The outline of the shape of half size `s`, centred on the origin,
    /// as SVG path data.
    fn path(self, s: f64) -> String {
        let f = |x: f64| fmt(x * s);
        match self {
            MarkerShape::Cross => format!(
                "M{} {} L{} {} M{} {} L{} {}",
                f(-1.0),
                f(-1.0),
                f(1.0),
                f(1.0),
                f(-1.0),
                f(1.0),
                f(1.0),
                f(-1.0)
            ),
            MarkerShape::Circle => format!(
                "M{} 0 A{r} {r} 0 1 0 {} 0 A{r} {r} 0 1 0 {} 0 Z",
                f(-1.0),
                f(1.0),
                f(-1.0),
                r = f(1.0)
            ),
            MarkerShape::Square => format!(
                "M{} {} H{} V{} H{} Z",
                f(-0.9),
                f(-0.9),
                f(0.9),
                f(0.9),
                f(-0.9)
            ),
            // The centroid on the point.
            MarkerShape::Triangle => format!(
                "M0 {} L{} {} L{} {} Z",
                f(-1.2),
                f(1.04),
                f(0.6),
                f(-1.04),
                f(0.6)
            ),
            MarkerShape::Diamond => format!(
                "M0 {} L{} 0 L0 {} L{} 0 Z",
                f(-1.25),
                f(1.25),
                f(1.25),
                f(-1.25)
            ),
        }
    }
}

/// What each marker of a set is labelled with.
#[derive(Clone, Debug, PartialEq)]
enum Labelling {
    None,
    /// Counted up from this number.
    Numbered(usize),
    /// One text per marker (an empty one leaves its marker unlabelled).
    Given(Vec<String>),
}

/// A set of markers at fixed points of the mechanism's plane (in the
/// model's length unit), such as the targets of a synthesis: one shape
/// and one colour for the set, and an entry in the legend with its name.
///
/// Unless given, the shape and the colour are chosen per set in turn
/// (the first set crosses, then circles, squares, triangles, diamonds),
/// and the markers are open (not filled) and unlabelled.
#[derive(Clone, Debug, PartialEq)]
pub struct Markers {
    name: String,
    points: Vec<Vector2<f64>>,
    labelling: Labelling,
    shape: Option<MarkerShape>,
    filled: bool,
    colour: Option<String>,
    size: f64,
}

/// A set's look, its choices made.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct MarkerLook {
    shape: MarkerShape,
    filled: bool,
    pub(super) colour: String,
    /// Half the marker's size, in pixels.
    pub(super) size: f64,
}

impl Markers {
    /// A set named `name` (its legend entry; an empty name has none) of
    /// markers at `points`: `[x, y]` arrays or `Vector2`s.
    pub fn new<P: Into<Vector2<f64>>>(name: &str, points: impl IntoIterator<Item = P>) -> Markers {
        Markers {
            name: name.into(),
            points: points.into_iter().map(Into::into).collect(),
            labelling: Labelling::None,
            shape: None,
            filled: false,
            colour: None,
            size: style::MARKER_SIZE,
        }
    }

    /// The markers' shape.
    pub fn shape(mut self, shape: MarkerShape) -> Markers {
        self.shape = Some(shape);
        self
    }

    /// Whether the markers are filled with their colour (default: open,
    /// so that a curve through a marker shows inside it). A cross is
    /// drawn alike either way.
    pub fn filled(mut self, filled: bool) -> Markers {
        self.filled = filled;
        self
    }

    /// The markers' colour, as SVG writes colours (`#d55e00`, `teal`,
    /// `rgb(…)`).
    pub fn colour(mut self, colour: &str) -> Markers {
        self.colour = Some(colour.into());
        self
    }

    /// Half a marker's size in pixels, 2 to 40 (default 5.5).
    pub fn size(mut self, pixels: f64) -> Markers {
        self.size = pixels;
        self
    }

    /// Each marker labelled with its number, from 1.
    pub fn numbered(self) -> Markers {
        self.numbered_from(1)
    }

    /// Each marker labelled with its number, from `first`.
    pub fn numbered_from(mut self, first: usize) -> Markers {
        self.labelling = Labelling::Numbered(first);
        self
    }

    /// Each marker labelled with its text, one per marker (an empty text
    /// leaves its marker unlabelled).
    pub fn labels<S: Into<String>>(mut self, labels: impl IntoIterator<Item = S>) -> Markers {
        self.labelling = Labelling::Given(labels.into_iter().map(Into::into).collect());
        self
    }

    /// The first mistake in the set, if any.
    pub(super) fn check(&self) -> Result<(), SceneError> {
        if self.points.is_empty() {
            return Err(SceneError::TooFewPoints {
                what: "set of markers",
                name: self.name.clone(),
                points: 0,
                least: 1,
            });
        }
        if let Some(index) = self
            .points
            .iter()
            .position(|p| !(p.x.is_finite() && p.y.is_finite()))
        {
            return Err(SceneError::NonFinitePoint {
                what: "set of markers",
                name: self.name.clone(),
                index,
            });
        }
        if let Labelling::Given(labels) = &self.labelling {
            if labels.len() != self.points.len() {
                return Err(SceneError::LabelCount {
                    name: self.name.clone(),
                    markers: self.points.len(),
                    labels: labels.len(),
                });
            }
        }
        if !(2.0..=40.0).contains(&self.size) {
            return Err(SceneError::BadSetting {
                what: "a marker's size",
                must: "from 2 to 40 pixels",
                value: self.size,
            });
        }
        if let Some(colour) = &self.colour {
            check_colour("a set of markers", colour)?;
        }
        Ok(())
    }

    pub(super) fn name(&self) -> &str {
        &self.name
    }

    /// The markers' points, in the model's plane.
    pub(super) fn points(&self) -> &[Vector2<f64>] {
        &self.points
    }

    /// The label of the `i`-th marker, if it has one.
    pub(super) fn label(&self, i: usize) -> Option<String> {
        match &self.labelling {
            Labelling::None => None,
            Labelling::Numbered(first) => Some((first + i).to_string()),
            Labelling::Given(labels) => labels.get(i).filter(|l| !l.is_empty()).cloned(),
        }
    }

    /// The look of the set, the `k`-th set of its scene.
    pub(super) fn look(&self, k: usize) -> MarkerLook {
        MarkerLook {
            shape: self
                .shape
                .unwrap_or(MarkerShape::IN_TURN[k % MarkerShape::IN_TURN.len()]),
            filled: self.filled,
            colour: self
                .colour
                .clone()
                .unwrap_or_else(|| style::marker_colour(k).into()),
            size: self.size,
        }
    }
}

impl Scene {
    /// A set of markers at fixed points of the plane (see [`Markers`]),
    /// drawn above the mechanism, in the legend under its name.
    pub fn markers(mut self, markers: Markers) -> Scene {
        self.markers.push(markers);
        self
    }

    /// Every set of markers at its screen points (`at`, one list per set).
    pub(super) fn draw_markers(&self, w: &mut Writer, at: &[Vec<Vector2<f64>>]) {
        for (k, (set, points)) in self.markers.iter().zip(at).enumerate() {
            let look = set.look(k);
            w.open(
                "g",
                &[
                    ("id", &format!("markers-{k}")),
                    ("class", "markers"),
                    ("data-name", &set.name),
                ],
            );
            for p in points {
                marker_symbol(w, *p, &look);
            }
            w.close("g");
        }
    }
}

/// One marker centred on `at`, over a white outline that keeps it visible
/// on a bar or a curve.
pub(super) fn marker_symbol(w: &mut Writer, at: Vector2<f64>, look: &MarkerLook) {
    let d = look.shape.path(look.size);
    let width = if look.shape == MarkerShape::Cross {
        2.2
    } else {
        1.8
    };
    let fill = if look.filled && look.shape != MarkerShape::Cross {
        look.colour.as_str()
    } else {
        "none"
    };
    w.open(
        "g",
        &[
            ("class", "marker"),
            (
                "transform",
                &format!("translate({} {})", fmt(at.x), fmt(at.y)),
            ),
        ],
    );
    w.element(
        "path",
        &[
            ("class", "halo"),
            ("d", &d),
            ("fill", "none"),
            ("stroke", style::HALO),
            ("stroke-width", &fmt(width + 2.4)),
            ("stroke-linejoin", "round"),
        ],
    );
    w.element(
        "path",
        &[
            ("d", &d),
            ("fill", fill),
            ("stroke", &look.colour),
            ("stroke-width", &fmt(width)),
            ("stroke-linejoin", "round"),
            ("stroke-linecap", "round"),
        ],
    );
    w.close("g");
}

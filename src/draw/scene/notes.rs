//! Notes: free text at a point of the mechanism's plane.

use super::geometry::Rect;
use super::style;
use super::{Scene, SceneError, finite};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;

/// A text centred on a point of the plane.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Note {
    at: Vector2<f64>,
    text: String,
}

/// Where a note's baseline lies below its box's centre, in em.
const BASELINE: f64 = 0.3;

impl Note {
    pub(super) fn check(&self) -> Result<(), SceneError> {
        finite(self.at, "position", &self.text)
    }

    /// Its point, in the model's plane.
    pub(super) fn at(&self) -> Vector2<f64> {
        self.at
    }

    /// The box the text covers when centred on `centre` on the screen.
    pub(super) fn extent(&self, centre: Vector2<f64>) -> Rect {
        let half = Vector2::new(
            super::heading::text_width(&self.text, style::NOTE_SIZE) / 2.0,
            0.5 * style::NOTE_SIZE,
        );
        Rect::centred(centre, half)
    }
}

impl Scene {
    /// A text centred on the point `at` of the plane (in the model's
    /// length unit): a remark on the drawing, such as "dead centre".
    pub fn note(mut self, at: [f64; 2], text: &str) -> Scene {
        self.notes.push(Note {
            at: Vector2::new(at[0], at[1]),
            text: text.into(),
        });
        self
    }

    /// Every note, centred on its screen point (`at`, one per note).
    pub(super) fn draw_notes(&self, w: &mut Writer, at: &[Vector2<f64>]) {
        for (note, p) in self.notes.iter().zip(at) {
            w.open(
                "text",
                &[
                    ("class", "note"),
                    ("x", &fmt(p.x)),
                    ("y", &fmt(p.y + BASELINE * style::NOTE_SIZE)),
                    ("text-anchor", "middle"),
                    ("font-family", style::FONT),
                    ("font-size", &fmt(style::NOTE_SIZE)),
                    ("fill", style::INK),
                    ("stroke", "white"),
                    ("stroke-width", "3"),
                    ("stroke-linejoin", "round"),
                    ("paint-order", "stroke"),
                ],
            );
            w.text(&note.text);
            w.close("text");
        }
    }
}

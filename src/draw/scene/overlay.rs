//! What a scene draws in the plane besides the pose and its paths — ghost
//! poses, curves, markers, notes — checked, and placed on the screen.

use super::layout::{Layout, Placed};
use super::{Scene, SceneError};
use nalgebra::Vector2;

/// The ghost poses, curves, markers and notes on the screen.
pub(super) struct Overlay {
    pub(super) ghosts: Vec<Placed>,
    /// Each curve's points.
    pub(super) curves: Vec<Vec<Vector2<f64>>>,
    /// Each set's markers.
    pub(super) markers: Vec<Vec<Vector2<f64>>>,
    /// Each note's point.
    pub(super) notes: Vec<Vector2<f64>>,
}

impl Scene {
    /// The first mistake in the markers, the curves or the notes, in the
    /// order they were given, if any. (The ghost poses are checked where
    /// they are placed, as the pose is.)
    pub(super) fn check_overlay(&self) -> Result<(), SceneError> {
        for set in &self.markers {
            set.check()?;
        }
        for curve in &self.curves {
            curve.check()?;
        }
        for note in &self.notes {
            note.check()?;
        }
        Ok(())
    }

    /// Every fixed point of the plane the overlay draws: the markers, the
    /// curves' points, the notes' points.
    pub(super) fn overlay_points(&self) -> impl Iterator<Item = Vector2<f64>> + '_ {
        let markers = self.markers.iter().flat_map(|set| set.points());
        let curves = self.curves.iter().flat_map(|curve| curve.points());
        markers
            .chain(curves)
            .copied()
            .chain(self.notes.iter().map(|note| note.at()))
    }

    /// The overlay on the screen.
    pub(super) fn overlay(&self, layout: &Layout) -> Result<Overlay, SceneError> {
        let screen = |points: &[Vector2<f64>]| points.iter().map(|p| layout.screen(*p)).collect();
        Ok(Overlay {
            ghosts: self.place_ghosts(layout)?,
            curves: self.curves.iter().map(|c| screen(c.points())).collect(),
            markers: self.markers.iter().map(|m| screen(m.points())).collect(),
            notes: self
                .notes
                .iter()
                .map(|note| layout.screen(note.at()))
                .collect(),
        })
    }
}

//! Where a scene puts the model on its picture: the map from model
//! coordinates to the picture's pixels that [`Scene::render`] uses, for a
//! program that draws over the picture or reads a click on it as a point
//! of the model (the page's target points).

use super::{Frame, Scene, SceneError};
use nalgebra::Vector2;

/// The map between model coordinates (y up) and the pixels of a rendered
/// picture (y down, from its top left corner): one scale for both axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Pixels per model unit.
    pub scale: f64,
    /// The model point drawn at the picture's left edge (x) and at the
    /// drawing's top (y).
    pub origin: Vector2<f64>,
    /// The drawing's top, in pixels from the picture's top.
    pub top: f64,
    /// The picture's size in pixels.
    pub width: f64,
    pub height: f64,
}

impl Placement {
    /// The pixel where the model point `p` is drawn.
    pub fn screen(&self, p: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(
            p.x * self.scale - self.origin.x * self.scale,
            self.top + (self.origin.y * self.scale - p.y * self.scale),
        )
    }

    /// The model point drawn at the pixel `s`.
    pub fn model(&self, s: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(
            self.origin.x + s.x / self.scale,
            self.origin.y - (s.y - self.top) / self.scale,
        )
    }
}

impl Scene {
    /// Where [`Scene::render`] of `frame` with the paths over `cycle`
    /// puts the model: the same map, found the same way, without drawing.
    pub fn placement(&self, frame: &Frame, cycle: &[Frame]) -> Result<Placement, SceneError> {
        let layout = self.layout(
            std::slice::from_ref(frame),
            cycle,
            self.title.as_deref(),
            self.subtitle.as_deref(),
        )?;
        Ok(Placement {
            scale: layout.scale,
            origin: layout.origin,
            top: layout.top,
            width: layout.width,
            height: layout.height,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanisms::FourBar;
    use crate::prelude::*;

    /// The placement is the render's: the ground pivot D drawn where the
    /// placement says (the render's ground symbol hangs from it), and a
    /// pixel read back as the model point drawn there.
    #[test]
    fn the_placement_is_where_the_render_draws() {
        let bar = FourBar::WORKSHEET;
        let u = bar
            .assemble(&vector![0.7], &crate::assembly::Pick::Index(0))
            .unwrap()
            .u;
        let frame = Frame::positions(&bar, &u, &vector![0.7]);
        let scene = Scene::new()
            .ground("A", [0.0, 0.0])
            .link(["A", "B"])
            .width(500.0);
        let placed = scene.placement(&frame, &[]).unwrap();
        let svg = scene.render(&frame, &[]).unwrap();
        let b = placed.screen(frame.position("B").unwrap());
        let attribute = |name: &str| -> f64 {
            let line = svg.lines().find(|l| l.contains("link-A-B")).unwrap();
            let from = line.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            line[from..].split('"').next().unwrap().parse().unwrap()
        };
        // The picture's numbers carry two decimals.
        assert!((attribute("x2") - b.x).abs() <= 0.005, "{svg}");
        assert!((attribute("y2") - b.y).abs() <= 0.005, "{svg}");
        assert!(
            svg.contains(&format!("width=\"{}\"", placed.width)),
            "{svg}"
        );
        let back = placed.model(b);
        assert!((back - frame.position("B").unwrap()).norm() < 1e-12);
    }
}

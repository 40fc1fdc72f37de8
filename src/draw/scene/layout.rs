//! The layout of a scene: the scale fitted to everything drawn, the
//! arrows' scales, and the screen positions of the points.

use super::arrow_kind::Kind;
use super::heading::Heading;
use super::style;
use super::{Frame, Scene, SceneError, finite, resolve};
use crate::draw::svg::{Writer, nice_below};
use nalgebra::Vector2;

impl Scene {
    /// The scale of the drawing and the arrows, fitted to every frame.
    pub(super) fn layout(
        &self,
        frames: &[Frame],
        cycle: &[Frame],
        title: Option<&str>,
        subtitle: Option<&str>,
    ) -> Result<Layout, SceneError> {
        if !(200.0..=20_000.0).contains(&self.width) {
            return Err(SceneError::BadSetting {
                what: "the width",
                must: "from 200 to 20 000 pixels",
                value: self.width,
            });
        }
        for slider in &self.sliders {
            if !slider.angle.is_finite() {
                return Err(SceneError::BadSetting {
                    what: "a slider's angle",
                    must: "finite",
                    value: slider.angle,
                });
            }
        }
        for scale in [self.velocity_scale, self.acceleration_scale]
            .into_iter()
            .flatten()
        {
            // Its reciprocal is in the legend.
            if !(scale > 0.0 && scale.is_finite() && (1.0 / scale).is_finite()) {
                return Err(SceneError::BadSetting {
                    what: "an arrow scale",
                    must: "positive, finite and with a finite reciprocal",
                    value: scale,
                });
            }
        }
        self.check_overlay()?;
        let lookup = |frame: &Frame, name: &str| -> Result<Vector2<f64>, SceneError> {
            resolve(frame, name, &self.ground)
        };
        // The mechanism (arrows excluded) as drawn, its ghost poses too.
        let mut bounds = Bounds::default();
        for frame in frames.iter().chain(&self.ghosts) {
            for name in self.names() {
                bounds.add(lookup(frame, name)?);
            }
            for (name, _) in &self.ground {
                bounds.add(lookup(frame, name)?);
            }
        }
        // Of the rest of the cycle, what is drawn: the traces, the sliders'
        // strokes.
        for frame in cycle {
            for name in self
                .traces
                .iter()
                .chain(self.sliders.iter().map(|s| &s.point))
            {
                bounds.add(lookup(frame, name)?);
            }
        }
        // The markers, the curves, the notes.
        for p in self.overlay_points() {
            bounds.add(p);
        }
        if bounds.is_empty() {
            for frame in frames {
                for p in &frame.positions {
                    bounds.add(*p);
                }
            }
        }
        let velocity_scale = self
            .velocity_scale
            .map_or_else(|| self.automatic_scale(Kind::Velocity, frames, cycle), Ok)?;
        let acceleration_scale = self.acceleration_scale.map_or_else(
            || self.automatic_scale(Kind::Acceleration, frames, cycle),
            Ok,
        )?;
        // Everything drawn: the arrows' tips too.
        for frame in frames {
            for (names, vectors, scale) in [
                (&self.velocity_arrows, &frame.velocities, velocity_scale),
                (
                    &self.acceleration_arrows,
                    &frame.accelerations,
                    acceleration_scale,
                ),
            ] {
                if let Some(vectors) = vectors {
                    for name in names {
                        let k = frame.point(name)?;
                        let tip = frame.positions[k] + vectors[k] * scale;
                        finite(tip, "arrow's tip", name)?;
                        bounds.add(tip);
                    }
                }
            }
        }
        // A mechanism so large that its extent overflows cannot be drawn.
        let spread = bounds.extent();
        if !spread.is_finite() {
            return Err(SceneError::BadSetting {
                what: "the extent of the drawing",
                must: "finite (its coordinates overflow)",
                value: spread,
            });
        }
        let legend_lines = usize::from(!self.velocity_arrows.is_empty())
            + usize::from(!self.acceleration_arrows.is_empty())
            + if cycle.is_empty() {
                0
            } else {
                self.traces.len()
            }
            + self.curves.iter().filter(|c| !c.name().is_empty()).count()
            + self.markers.iter().filter(|m| !m.name().is_empty()).count()
            + usize::from(self.ghosts_in_legend())
            + 1;
        Ok(Layout::fit(
            &bounds,
            self.width,
            Heading::new(title, subtitle, self.width),
            legend_lines,
            velocity_scale,
            acceleration_scale,
        ))
    }

    /// Screen positions of every frame point and ground pivot.
    pub(super) fn place(&self, layout: &Layout, frame: &Frame) -> Result<Placed, SceneError> {
        let mut placed = Placed::default();
        for (name, _) in &self.ground {
            let at = resolve(frame, name, &self.ground)?;
            placed.insert(name, layout.screen(at));
        }
        for name in self.names() {
            let at = resolve(frame, name, &self.ground)?;
            placed.insert(name, layout.screen(at));
        }
        placed.centre = placed
            .points
            .iter()
            .fold(Vector2::zeros(), |s, (_, p)| s + p)
            / placed.points.len().max(1) as f64;
        Ok(placed)
    }

    /// The scale of the arrows of `kind` when none is given: the longest
    /// such arrow over the frames and the cycle drawn as long as
    /// `style::ARROW_FRACTION` of the mechanism's extent over them, the
    /// scale rounded down to 1, 2 or 5 × 10ᵏ. A still and an animation
    /// of one motion so get the same scales. (The cycle's frames count
    /// where they can be drawn: one without the vectors, or with a point
    /// not finite, is passed over.)
    fn automatic_scale(
        &self,
        kind: Kind,
        frames: &[Frame],
        cycle: &[Frame],
    ) -> Result<f64, SceneError> {
        let names = match kind {
            Kind::Velocity => &self.velocity_arrows,
            Kind::Acceleration => &self.acceleration_arrows,
        };
        let mut longest: f64 = 0.0;
        let mut extent = Bounds::default();
        for frame in frames {
            for name in names {
                let k = frame.point(name)?;
                let vector = kind.vectors(frame)?[k];
                finite(vector, kind.plural(), name)?;
                longest = longest.max(vector.norm());
            }
        }
        for frame in cycle {
            let Ok(vectors) = kind.vectors(frame) else {
                continue;
            };
            for name in names {
                if let Some(vector) = frame.index(name).and_then(|k| vectors.get(k)) {
                    if vector.x.is_finite() && vector.y.is_finite() {
                        longest = longest.max(vector.norm());
                    }
                }
            }
        }
        for frame in frames.iter().chain(cycle) {
            for name in self.names().chain(self.ground.iter().map(|(n, _)| n)) {
                if let Ok(p) = resolve(frame, name, &self.ground) {
                    extent.add(p);
                }
            }
        }
        if extent.is_empty() {
            for frame in frames {
                for p in &frame.positions {
                    extent.add(*p);
                }
            }
        }
        let extent = extent.extent().max(f64::MIN_POSITIVE);
        Ok(if longest > 0.0 {
            nice_below(style::ARROW_FRACTION * extent / longest)
        } else {
            1.0
        })
    }
}

/// Frames with their points in screen coordinates.
#[derive(Default)]
pub(super) struct Placed {
    pub(super) points: Vec<(String, Vector2<f64>)>,
    pub(super) centre: Vector2<f64>,
}

impl Placed {
    pub(super) fn insert(&mut self, name: &str, at: Vector2<f64>) {
        if !self.points.iter().any(|(n, _)| n == name) {
            self.points.push((name.to_string(), at));
        }
    }

    pub(super) fn get(&self, name: &str) -> Vector2<f64> {
        self.points
            .iter()
            .find(|(n, _)| n == name)
            .map_or(Vector2::zeros(), |(_, p)| *p)
    }
}

/// A scale or a length as a reader would write it: 0.02, 0.0005, 2000;
/// very small or very large ones as 3e-12 or 4.5e15.
pub(super) fn number(x: f64) -> String {
    if x != 0.0 && !(1e-6..1e9).contains(&x.abs()) {
        return format!("{x:e}");
    }
    let text = format!("{x:.10}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    text.to_string()
}

/// The model-space box of everything drawn.
#[derive(Default)]
struct Bounds {
    min: Option<Vector2<f64>>,
    max: Option<Vector2<f64>>,
}

impl Bounds {
    fn add(&mut self, p: Vector2<f64>) {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return;
        }
        self.min = Some(self.min.map_or(p, |m| m.inf(&p)));
        self.max = Some(self.max.map_or(p, |m| m.sup(&p)));
    }

    fn is_empty(&self) -> bool {
        self.min.is_none()
    }

    fn extent(&self) -> f64 {
        match (self.min, self.max) {
            (Some(a), Some(b)) => (b - a).amax(),
            _ => 0.0,
        }
    }
}

/// The map from model coordinates (y up) to the picture's (y down), one
/// scale for both axes, and the arrows' scales.
pub(super) struct Layout {
    pub(super) scale: f64,
    pub(super) origin: Vector2<f64>,
    pub(super) top: f64,
    pub(super) width: f64,
    pub(super) height: f64,
    pub(super) legend_top: f64,
    pub(super) heading: Heading,
    pub(super) velocity_scale: f64,
    pub(super) acceleration_scale: f64,
}

impl Layout {
    fn fit(
        bounds: &Bounds,
        width: f64,
        heading: Heading,
        legend_lines: usize,
        velocity_scale: f64,
        acceleration_scale: f64,
    ) -> Layout {
        let (min, max) = match (bounds.min, bounds.max) {
            (Some(a), Some(b)) => (a, b),
            _ => (Vector2::zeros(), Vector2::new(1.0, 1.0)),
        };
        let size = (max - min).sup(&Vector2::new(1e-12, 1e-12));
        let inner = width - 2.0 * style::MARGIN;
        // Not taller than wide by more than 1.4: a tall mechanism is drawn
        // smaller.
        let scale = (inner / size.x).min(1.4 * inner / size.y);
        // Under the heading's last line as under a title of one line.
        let top = heading.bottom().map_or(style::MARGIN, |b| b + 42.0);
        let drawing = size.y * scale;
        // Room under the drawing for the ground symbols, then the legend.
        let legend_top = top + drawing + style::GROUND_HEIGHT + 50.0;
        let height = legend_top + legend_lines as f64 * style::LEGEND_LINE + 10.0;
        // Centred horizontally.
        let left = (width - size.x * scale) / 2.0;
        Layout {
            scale,
            origin: Vector2::new(min.x - left / scale, max.y),
            top,
            width,
            height,
            legend_top,
            heading,
            velocity_scale,
            acceleration_scale,
        }
    }

    /// Model → screen (scaled before the difference, so that coordinates
    /// near the ends of the range of f64 do not overflow on the way).
    pub(super) fn screen(&self, p: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(
            p.x * self.scale - self.origin.x * self.scale,
            self.top + (self.origin.y * self.scale - p.y * self.scale),
        )
    }

    /// The document, its background and its heading, if any.
    pub(super) fn open(&self) -> Writer {
        let mut w = Writer::svg(self.width, self.height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "white")],
        );
        self.heading.draw(&mut w, self.width);
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_as_a_reader_writes_them() {
        assert_eq!(number(0.0005), "0.0005");
        assert_eq!(number(2000.0), "2000");
        assert_eq!(number(3e-12), "3e-12");
        assert_eq!(number(4.5e15), "4.5e15");
    }
}

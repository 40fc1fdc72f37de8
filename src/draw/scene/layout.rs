//! The layout of a scene: the scale fitted to everything drawn, the
//! screen positions of the points, and where the labels go (clear of the
//! bars, arrows, symbols and one another).

use super::animation::Motion;
use super::symbols::style;
use super::{Frame, Scene, SceneError, Shape, Slideway, finite, resolve, unknown};
use crate::draw::svg::{Writer, fmt};
use linkage_symbolic::names::textbook;
use nalgebra::Vector2;

impl Scene {
    /// The scale of the drawing and the arrows, fitted to every frame.
    pub(super) fn layout(&self, frames: &[Frame], cycle: &[Frame]) -> Result<Layout, SceneError> {
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
        let lookup = |frame: &Frame, name: &str| -> Result<Vector2<f64>, SceneError> {
            resolve(frame, name, &self.ground)
        };
        // The mechanism's extent (arrows excluded) sets the automatic scales.
        let mut bounds = Bounds::default();
        for frame in frames {
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
        if bounds.is_empty() {
            for frame in frames {
                for p in &frame.positions {
                    bounds.add(*p);
                }
            }
        }
        let extent = bounds.extent().max(f64::MIN_POSITIVE);
        let longest = |kinds: &[String], pick: fn(&Frame) -> Option<&Vec<Vector2<f64>>>, what| {
            let mut longest: f64 = 0.0;
            for frame in frames {
                for name in kinds {
                    let vectors = pick(frame).ok_or(SceneError::MissingKinematics { what })?;
                    let k = frame.index(name).ok_or_else(|| unknown(frame, name))?;
                    let vector = vectors[k];
                    finite(vector, what, name)?;
                    longest = longest.max(vector.norm());
                }
            }
            Ok::<f64, SceneError>(longest)
        };
        let auto = |given: Option<f64>, longest: f64| {
            given.unwrap_or_else(|| {
                if longest > 0.0 {
                    nice_below(style::ARROW_FRACTION * extent / longest)
                } else {
                    1.0
                }
            })
        };
        let velocity_scale = auto(
            self.velocity_scale,
            longest(
                &self.velocity_arrows,
                |f| f.velocities.as_ref(),
                "velocities",
            )?,
        );
        let acceleration_scale = auto(
            self.acceleration_scale,
            longest(
                &self.acceleration_arrows,
                |f| f.accelerations.as_ref(),
                "accelerations",
            )?,
        );
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
                        let k = frame.index(name).ok_or_else(|| unknown(frame, name))?;
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
            + 1;
        Ok(Layout::fit(
            &bounds,
            self.width,
            self.title.is_some(),
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

    /// Names beside the points, each where it is farthest from the bars,
    /// arrows, points and the labels already placed (chosen on the first
    /// frame; an animated label keeps its offset from its point).
    pub(super) fn draw_labels(
        &self,
        w: &mut Writer,
        at: &Placed,
        motion: Option<&Motion>,
        obstacles: &[(Vector2<f64>, Vector2<f64>)],
    ) {
        let mut taken: Vec<Vector2<f64>> = Vec::new();
        for (name, p) in &at.points {
            let mut best = (f64::NEG_INFINITY, Vector2::new(12.0, -12.0));
            for radius in [14.0, 20.0] {
                for k in 0..16 {
                    // From the upper right, counter-clockwise on the screen.
                    let angle =
                        std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::TAU / 16.0;
                    let offset = Vector2::new(angle.cos(), -angle.sin()) * radius;
                    let c = p + offset;
                    let mut clearance = f64::INFINITY;
                    for (a, b) in obstacles {
                        clearance = clearance.min(segment_distance(c, *a, *b) - 8.0);
                    }
                    for (_, q) in &at.points {
                        clearance = clearance.min((c - q).norm() - 9.0);
                    }
                    for q in &taken {
                        clearance = clearance.min((c - q).norm() - 16.0);
                    }
                    // Near is better, once clear.
                    let score = clearance.min(6.0) - 0.05 * radius;
                    if score > best.0 {
                        best = (score, offset);
                    }
                }
            }
            let offset = best.1;
            taken.push(p + offset);
            // Centred on the spot: anchored in the middle, baseline 5 px
            // below the centre.
            let spot = |q: Vector2<f64>| q + offset + Vector2::new(0.0, 5.0);
            let q = spot(*p);
            w.open(
                "text",
                &[
                    ("class", "label"),
                    ("x", &fmt(q.x)),
                    ("y", &fmt(q.y)),
                    ("text-anchor", "middle"),
                    ("font-family", style::FONT),
                    ("font-style", "italic"),
                    ("font-size", "15"),
                    ("fill", style::INK),
                ],
            );
            if let Some(m) = motion {
                m.animate(w, "x", |f| fmt(spot(f.get(name)).x));
                m.animate(w, "y", |f| fmt(spot(f.get(name)).y));
            }
            w.text(&textbook(name));
            w.close("text");
        }
    }

    /// The segments a label should keep clear of: bars, plate edges,
    /// arrows, ground symbols and slider blocks, on the screen.
    pub(super) fn obstacles(
        &self,
        layout: &Layout,
        frame: &Frame,
        at: &Placed,
    ) -> Vec<(Vector2<f64>, Vector2<f64>)> {
        let mut out = Vec::new();
        for body in &self.shapes {
            match body {
                Shape::Bar([a, b]) => out.push((at.get(a), at.get(b))),
                Shape::Plate(corners) => {
                    for (i, a) in corners.iter().enumerate() {
                        let b = &corners[(i + 1) % corners.len()];
                        out.push((at.get(a), at.get(b)));
                    }
                }
            }
        }
        for (name, _) in &self.ground {
            let p = at.get(name);
            out.push((p, p + Vector2::new(0.0, style::GROUND_HEIGHT + 6.0)));
        }
        for slider in &self.sliders {
            // The block's outline (30 × 18 px).
            let p = at.get(&slider.point);
            let along = match &slider.guide {
                Slideway::Link([a, b]) => (at.get(b) - at.get(a))
                    .try_normalize(1e-12)
                    .unwrap_or(Vector2::x()),
                _ => Vector2::new(slider.angle.cos(), -slider.angle.sin()),
            };
            let across = Vector2::new(-along.y, along.x);
            let corners = [(-15.0, -9.0), (15.0, -9.0), (15.0, 9.0), (-15.0, 9.0)]
                .map(|(a, c)| p + along * a + across * c);
            for i in 0..4 {
                out.push((corners[i], corners[(i + 1) % 4]));
            }
        }
        for (names, vectors, scale) in [
            (
                &self.velocity_arrows,
                &frame.velocities,
                layout.velocity_scale,
            ),
            (
                &self.acceleration_arrows,
                &frame.accelerations,
                layout.acceleration_scale,
            ),
        ] {
            if let Some(vectors) = vectors {
                for name in names {
                    if let Some(k) = frame.index(name) {
                        let base = frame.positions[k];
                        out.push((
                            layout.screen(base),
                            layout.screen(base + vectors[k] * scale),
                        ));
                    }
                }
            }
        }
        out
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

/// The largest 1, 2 or 5 × 10ᵏ not above x.
pub(super) fn nice_below(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let decade = 10f64.powf(x.log10().floor());
    let mantissa = x / decade;
    let nice = if mantissa >= 5.0 {
        5.0
    } else if mantissa >= 2.0 {
        2.0
    } else {
        1.0
    };
    nice * decade
}

/// The distance from c to the segment ab.
fn segment_distance(c: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let ab = b - a;
    let t = if ab.norm_squared() > 0.0 {
        ((c - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - c).norm()
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
    pub(super) velocity_scale: f64,
    pub(super) acceleration_scale: f64,
}

impl Layout {
    fn fit(
        bounds: &Bounds,
        width: f64,
        titled: bool,
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
        let top = style::MARGIN + if titled { 34.0 } else { 0.0 };
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

    pub(super) fn open(&self, scene: &Scene) -> Writer {
        let mut w = Writer::svg(self.width, self.height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "white")],
        );
        if let Some(title) = &scene.title {
            w.open(
                "text",
                &[
                    ("x", &fmt(self.width / 2.0)),
                    ("y", &fmt(style::MARGIN - 8.0)),
                    ("text-anchor", "middle"),
                    ("font-family", style::FONT),
                    ("font-size", "17"),
                    ("fill", style::INK),
                ],
            );
            w.text(title);
            w.close("text");
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_numbers() {
        assert_eq!(nice_below(0.0234), 0.02);
        assert_eq!(nice_below(0.00071), 0.0005);
        assert_eq!(nice_below(3.0), 2.0);
        assert_eq!(nice_below(1.0), 1.0);
        assert_eq!(number(0.0005), "0.0005");
        assert_eq!(number(2000.0), "2000");
        assert_eq!(number(3e-12), "3e-12");
        assert_eq!(number(4.5e15), "4.5e15");
    }
}

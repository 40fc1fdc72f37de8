//! Pictures of a mechanism: a pose drawn with its velocity and acceleration
//! arrows, the paths its points trace, and an animation of a whole cycle, as
//! self-contained SVG (no fonts or system libraries needed to write them).
//!
//! A [`Scene`] says no more than a picture needs — which points are ground
//! pivots, which pairs (or polygons) of points are links, which points ride
//! on sliders, which get arrows and at what scales, which paths to trace.
//! Everything else comes from the generated point kinematics, through a
//! [`Frame`] per pose:
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::scene::{Frame, Scene};
//!
//! #[linkage::linkage(
//!     u = [theta3, theta4],
//!     v = [theta2],
//!     points = [
//!         B = (l2 * theta2.cos(), l2 * theta2.sin()),
//!         C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
//!     ],
//!     closure = [
//!         l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
//!         l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
//!     ],
//! )]
//! #[derive(Clone, Debug)]
//! pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }
//!
//! let bar = FourBar { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0 };
//! let pose = bar.analyze(
//!     &vector![1.2, -0.9], &vector![0.35], &vector![41.9], &vector![0.0],
//!     &Options::default(),
//! )?;
//! let scene = Scene::new()
//!     .ground("A", [0.0, 0.0])
//!     .ground("D", [80.0, 0.0])
//!     .link(["A", "B"])
//!     .link(["B", "C"])
//!     .link(["C", "D"])
//!     .velocities(["B", "C"]);
//! let svg = scene.render(&Frame::from_analysis::<FourBar, 2, 1>(&pose), &[])?;
//! assert!(svg.starts_with("<svg"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Drawing conventions: x to the right and y up, one scale for both axes,
//! fitted to the picture; ground pivots hatched; links as bars, joints as
//! open circles, other points as dots; velocities green and accelerations
//! red (as in the Maple worksheet), each with its scale in the legend.

use crate::svg::{Writer, fmt, pretty_name};
use linkage_runtime::{Analysis, Linkage, SweepPose};
use nalgebra::{SVector, Vector2};
use std::fmt::Write as _;

/// What went wrong drawing a scene.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
    /// The scene names a point that neither the frame nor the scene's
    /// ground pivots define.
    UnknownPoint { name: String, known: String },
    /// Arrows were asked for, but the frame has no velocities or
    /// accelerations.
    MissingKinematics { what: &'static str },
    /// A coordinate to draw is NaN or infinite.
    NonFinite { what: &'static str, name: String },
    /// An animation needs at least two frames.
    TooFewFrames { frames: usize },
    /// A number given is out of its range: a scale or a size zero,
    /// negative or not finite, an angle not finite.
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::UnknownPoint { known, name } => write!(
                f,
                "the scene names the point `{name}`, which is not among the frame's points ({known})"
            ),
            Self::MissingKinematics { what } => write!(
                f,
                "the scene draws {what} arrows but the frame has no {what}"
            ),
            Self::NonFinite { name, what } => write!(f, "the {what} of `{name}` is not finite"),
            Self::TooFewFrames { frames } => {
                write!(f, "an animation needs at least two frames, got {frames}")
            }
            Self::BadSetting { value, what, must } => {
                write!(f, "{what} must be {must}, got {value}")
            }
        }
    }
}

impl std::error::Error for SceneError {}

/// The named points of one pose: positions, and, where known, velocities
/// and accelerations (in the model's length and time units).
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub names: Vec<String>,
    pub positions: Vec<Vector2<f64>>,
    pub velocities: Option<Vec<Vector2<f64>>>,
    pub accelerations: Option<Vec<Vector2<f64>>>,
}

impl Frame {
    /// The points of a whole analysis ([`Linkage::analyze`]).
    pub fn from_analysis<L: Linkage<M, F>, const M: usize, const F: usize>(
        analysis: &Analysis<M, F, L::Points>,
    ) -> Frame {
        Frame {
            names: L::POINT_NAMES.iter().map(|s| s.to_string()).collect(),
            positions: analysis.points.as_ref().to_vec(),
            velocities: Some(analysis.point_velocities.as_ref().to_vec()),
            accelerations: Some(analysis.point_accelerations.as_ref().to_vec()),
        }
    }

    /// The points of a pose of a sweep (driven at the sweep's constant
    /// speed: v̈ = 0).
    pub fn from_sweep_pose<L: Linkage<M, F>, const M: usize, const F: usize>(
        model: &L,
        pose: &SweepPose<M, F>,
    ) -> Frame {
        Frame::at(
            model,
            &pose.u,
            &pose.v,
            &pose.udot,
            &pose.vdot,
            &pose.uddot,
            &SVector::zeros(),
        )
    }

    /// The points at a state (u, v, u̇, v̇, ü, v̈).
    pub fn at<L: Linkage<M, F>, const M: usize, const F: usize>(
        model: &L,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
    ) -> Frame {
        Frame {
            names: L::POINT_NAMES.iter().map(|s| s.to_string()).collect(),
            positions: model.point_positions(u, v).as_ref().to_vec(),
            velocities: Some(model.point_velocities(u, v, udot, vdot).as_ref().to_vec()),
            accelerations: Some(
                model
                    .point_accelerations(u, v, udot, vdot, uddot, vddot)
                    .as_ref()
                    .to_vec(),
            ),
        }
    }

    /// Positions only (no arrows can be drawn from it).
    pub fn positions<L: Linkage<M, F>, const M: usize, const F: usize>(
        model: &L,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> Frame {
        Frame {
            names: L::POINT_NAMES.iter().map(|s| s.to_string()).collect(),
            positions: model.point_positions(u, v).as_ref().to_vec(),
            velocities: None,
            accelerations: None,
        }
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }
}

/// A body of the mechanism: a bar between two points or a plate over three
/// or more.
#[derive(Clone, Debug, PartialEq)]
enum Body {
    Bar([String; 2]),
    Plate(Vec<String>),
}

/// A slider: the block at `point`, moving along a guide at `angle` (rad)
/// through it.
#[derive(Clone, Debug, PartialEq)]
struct Slider {
    point: String,
    angle: f64,
    guide: Guide,
}

/// What a slider block slides on.
#[derive(Clone, Debug, PartialEq)]
enum Guide {
    /// A fixed straight guide at the slider's angle, drawn hatched.
    Ground,
    /// A link: the block turns with the line from the first point to the
    /// second (the link itself is drawn as a body).
    Link([String; 2]),
    /// A slot in a moving body at a fixed angle, drawn with that body.
    Slot,
}

/// What a picture of the mechanism shows (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    ground: Vec<(String, Vector2<f64>)>,
    bodies: Vec<Body>,
    sliders: Vec<Slider>,
    velocity_arrows: Vec<String>,
    acceleration_arrows: Vec<String>,
    velocity_scale: Option<f64>,
    acceleration_scale: Option<f64>,
    traces: Vec<String>,
    labels: bool,
    title: Option<String>,
    length_unit: String,
    time_unit: String,
    width: f64,
}

impl Default for Scene {
    fn default() -> Self {
        Scene::new()
    }
}

/// Colours and sizes (screen pixels) of the drawing.
mod style {
    pub const INK: &str = "#1b1b1b";
    pub const BAR: &str = "#3a4a5c";
    pub const PLATE_FILL: &str = "#dbe4ee";
    pub const VELOCITY: &str = "#2e7d32";
    pub const ACCELERATION: &str = "#c62828";
    pub const TRACE: &str = "#7b8794";
    pub const BAR_WIDTH: f64 = 5.0;
    pub const JOINT_RADIUS: f64 = 4.5;
    pub const DOT_RADIUS: f64 = 3.2;
    pub const ARROW_WIDTH: f64 = 2.2;
    pub const HEAD_LENGTH: f64 = 11.0;
    pub const HEAD_HALF_WIDTH: f64 = 4.2;
    pub const GROUND_HEIGHT: f64 = 14.0;
    pub const GROUND_HALF_WIDTH: f64 = 11.0;
    pub const MARGIN: f64 = 46.0;
    pub const LEGEND_LINE: f64 = 18.0;
    pub const FONT: &str = "DejaVu Serif, Georgia, 'Times New Roman', serif";
    /// The longest arrow of each kind, when its scale is chosen
    /// automatically, as a fraction of the mechanism's extent.
    pub const ARROW_FRACTION: f64 = 0.3;
}

impl Scene {
    /// An empty scene, 720 pixels wide, labelled, units mm and s.
    pub fn new() -> Scene {
        Scene {
            ground: Vec::new(),
            bodies: Vec::new(),
            sliders: Vec::new(),
            velocity_arrows: Vec::new(),
            acceleration_arrows: Vec::new(),
            velocity_scale: None,
            acceleration_scale: None,
            traces: Vec::new(),
            labels: true,
            title: None,
            length_unit: "mm".into(),
            time_unit: "s".into(),
            width: 720.0,
        }
    }

    /// A ground pivot named `name` at a fixed position (drawn hatched); a
    /// name the frame also defines is drawn where the frame puts it.
    pub fn ground(mut self, name: &str, at: [f64; 2]) -> Scene {
        self.ground.push((name.into(), Vector2::new(at[0], at[1])));
        self
    }

    /// A binary link between two points (frame points or ground pivots).
    pub fn link(mut self, ends: [&str; 2]) -> Scene {
        self.bodies.push(Body::Bar(ends.map(String::from)));
        self
    }

    /// A ternary (or larger) link: the polygon through its joints.
    pub fn plate<const N: usize>(mut self, corners: [&str; N]) -> Scene {
        self.bodies
            .push(Body::Plate(corners.iter().map(|s| s.to_string()).collect()));
        self
    }

    /// A slider block at `point` on a straight guide at `angle` (rad, from
    /// the x axis) through it.
    pub fn slider(mut self, point: &str, angle: f64) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle,
            guide: Guide::Ground,
        });
        self
    }

    /// A slider block at `point` sliding along the link through `line`
    /// (its two points): the block turns with the link.
    pub fn slider_on(mut self, point: &str, line: [&str; 2]) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle: 0.0,
            guide: Guide::Link(line.map(String::from)),
        });
        self
    }

    /// A slider block at `point` in a slot at a fixed `angle` (rad) of a
    /// translating body, such as a ram: no ground guide is drawn.
    pub fn block(mut self, point: &str, angle: f64) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle,
            guide: Guide::Slot,
        });
        self
    }

    /// Velocity arrows at these points.
    pub fn velocities<const N: usize>(mut self, points: [&str; N]) -> Scene {
        self.velocity_arrows
            .extend(points.iter().map(|s| s.to_string()));
        self
    }

    /// Acceleration arrows at these points.
    pub fn accelerations<const N: usize>(mut self, points: [&str; N]) -> Scene {
        self.acceleration_arrows
            .extend(points.iter().map(|s| s.to_string()));
        self
    }

    /// Drawn length per unit of velocity (the worksheet's 0.02: an arrow of
    /// 0.02 mm per mm/s). Chosen automatically if not set.
    pub fn velocity_scale(mut self, scale: f64) -> Scene {
        self.velocity_scale = Some(scale);
        self
    }

    /// Drawn length per unit of acceleration (the worksheet's 0.0005).
    pub fn acceleration_scale(mut self, scale: f64) -> Scene {
        self.acceleration_scale = Some(scale);
        self
    }

    /// The path of these points over the cycle given to
    /// [`Scene::render`] (a coupler curve).
    pub fn trace<const N: usize>(mut self, points: [&str; N]) -> Scene {
        self.traces.extend(points.iter().map(|s| s.to_string()));
        self
    }

    /// Whether to write the points' names beside them (default yes).
    pub fn labels(mut self, on: bool) -> Scene {
        self.labels = on;
        self
    }

    /// A title above the drawing.
    pub fn title(mut self, title: &str) -> Scene {
        self.title = Some(title.into());
        self
    }

    /// The units of the model's lengths and times, for the legend.
    pub fn units(mut self, length: &str, time: &str) -> Scene {
        self.length_unit = length.into();
        self.time_unit = time.into();
        self
    }

    /// The picture's width in pixels, 200 to 20 000 (the height follows
    /// the mechanism).
    pub fn width(mut self, pixels: f64) -> Scene {
        self.width = pixels;
        self
    }

    /// The pose `frame` as SVG, with the traced paths over `cycle` (frames
    /// of the whole motion; may be empty).
    pub fn render(&self, frame: &Frame, cycle: &[Frame]) -> Result<String, SceneError> {
        let layout = self.layout(std::slice::from_ref(frame), cycle)?;
        let mut w = layout.open(self);
        self.draw_traces(&mut w, &layout, cycle)?;
        self.draw_guides(&mut w, &layout, std::slice::from_ref(frame), cycle)?;
        for (name, _) in &self.ground {
            let at = resolve(frame, name, &self.ground)?;
            ground_symbol(&mut w, layout.screen(at));
        }
        let placed = self.place(&layout, frame)?;
        self.draw_bodies(&mut w, &placed, None);
        self.draw_sliders(&mut w, &placed, None);
        self.draw_points(&mut w, &placed, None);
        self.draw_arrows(&mut w, &layout, frame, None)?;
        if self.labels {
            let obstacles = self.obstacles(&layout, frame, &placed);
            self.draw_labels(&mut w, &placed, None, &obstacles);
        }
        self.draw_legend(&mut w, &layout, !cycle.is_empty());
        Ok(w.finish())
    }

    /// An animation of `cycle` (its frames at equal time steps, looping
    /// over `seconds`), as SVG with SMIL animations: self-contained, played
    /// by any browser.
    pub fn animate(&self, cycle: &[Frame], seconds: f64) -> Result<String, SceneError> {
        if cycle.len() < 2 {
            return Err(SceneError::TooFewFrames {
                frames: cycle.len(),
            });
        }
        positive("the animation's duration", seconds)?;
        let layout = self.layout(cycle, cycle)?;
        let mut w = layout.open(self);
        self.draw_traces(&mut w, &layout, cycle)?;
        self.draw_guides(&mut w, &layout, cycle, cycle)?;
        for (name, _) in &self.ground {
            let at = resolve(&cycle[0], name, &self.ground)?;
            ground_symbol(&mut w, layout.screen(at));
        }
        let frames: Vec<Placed> = cycle
            .iter()
            .map(|f| self.place(&layout, f))
            .collect::<Result<_, _>>()?;
        let motion = Motion {
            frames: &frames,
            seconds,
        };
        self.draw_bodies(&mut w, &frames[0], Some(&motion));
        self.draw_sliders(&mut w, &frames[0], Some(&motion));
        self.draw_points(&mut w, &frames[0], Some(&motion));
        self.draw_arrows(&mut w, &layout, &cycle[0], Some((cycle, seconds)))?;
        if self.labels {
            let obstacles = self.obstacles(&layout, &cycle[0], &frames[0]);
            self.draw_labels(&mut w, &frames[0], Some(&motion), &obstacles);
        }
        self.draw_legend(&mut w, &layout, true);
        Ok(w.finish())
    }

    /// Every point the scene names, checked against the frame.
    fn names(&self) -> impl Iterator<Item = &String> {
        let bodies = self.bodies.iter().flat_map(|b| match b {
            Body::Bar(ends) => ends.as_slice(),
            Body::Plate(corners) => corners.as_slice(),
        });
        let guides = self.sliders.iter().flat_map(|s| match &s.guide {
            Guide::Link(line) => line.as_slice(),
            _ => &[],
        });
        bodies
            .chain(self.sliders.iter().map(|s| &s.point))
            .chain(guides)
            .chain(&self.velocity_arrows)
            .chain(&self.acceleration_arrows)
            .chain(&self.traces)
    }

    /// The scale of the drawing and the arrows, fitted to every frame.
    fn layout(&self, frames: &[Frame], cycle: &[Frame]) -> Result<Layout, SceneError> {
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
    fn place(&self, layout: &Layout, frame: &Frame) -> Result<Placed, SceneError> {
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

    fn draw_traces(
        &self,
        w: &mut Writer,
        layout: &Layout,
        cycle: &[Frame],
    ) -> Result<(), SceneError> {
        if cycle.is_empty() {
            return Ok(());
        }
        for name in &self.traces {
            let mut d = String::new();
            for (i, frame) in cycle.iter().enumerate() {
                let p = layout.screen(resolve(frame, name, &self.ground)?);
                let _ = write!(
                    d,
                    "{}{} {} ",
                    if i == 0 { "M" } else { "L" },
                    fmt(p.x),
                    fmt(p.y)
                );
            }
            w.element(
                "path",
                &[
                    ("id", &format!("trace-{name}")),
                    ("class", "trace"),
                    ("d", d.trim_end()),
                    ("fill", "none"),
                    ("stroke", style::TRACE),
                    ("stroke-width", "1.2"),
                    ("stroke-dasharray", "5 3"),
                ],
            );
        }
        Ok(())
    }

    /// Each slider's guide, long enough for its whole stroke, hatched on
    /// one side.
    fn draw_guides(
        &self,
        w: &mut Writer,
        layout: &Layout,
        frames: &[Frame],
        cycle: &[Frame],
    ) -> Result<(), SceneError> {
        for slider in self.sliders.iter().filter(|s| s.guide == Guide::Ground) {
            let dir = Vector2::new(slider.angle.cos(), slider.angle.sin());
            let mut range = (f64::INFINITY, f64::NEG_INFINITY);
            let mut origin = None;
            for frame in frames.iter().chain(cycle) {
                let p = resolve(frame, &slider.point, &self.ground)?;
                let o = *origin.get_or_insert(p);
                let s = (p - o).dot(&dir);
                range = (range.0.min(s), range.1.max(s));
            }
            let Some(o) = origin else { continue };
            let pad = 26.0 / layout.scale;
            let a = layout.screen(o + dir * (range.0 - pad));
            let b = layout.screen(o + dir * (range.1 + pad));
            guide_symbol(w, a, b, &slider.point);
        }
        Ok(())
    }

    fn draw_bodies(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        for (i, body) in self.bodies.iter().enumerate() {
            match body {
                Body::Bar([a, b]) => {
                    let (p, q) = (at.get(a), at.get(b));
                    let id = format!("link-{a}-{b}");
                    w.open(
                        "line",
                        &[
                            ("id", &id),
                            ("class", "link"),
                            ("x1", &fmt(p.x)),
                            ("y1", &fmt(p.y)),
                            ("x2", &fmt(q.x)),
                            ("y2", &fmt(q.y)),
                            ("stroke", style::BAR),
                            ("stroke-width", &fmt(style::BAR_WIDTH)),
                            ("stroke-linecap", "round"),
                        ],
                    );
                    if let Some(m) = motion {
                        m.animate(w, "x1", |f| fmt(f.get(a).x));
                        m.animate(w, "y1", |f| fmt(f.get(a).y));
                        m.animate(w, "x2", |f| fmt(f.get(b).x));
                        m.animate(w, "y2", |f| fmt(f.get(b).y));
                    }
                    w.close("line");
                }
                Body::Plate(corners) => {
                    let points = |f: &Placed| {
                        corners
                            .iter()
                            .map(|c| {
                                let p = f.get(c);
                                format!("{},{}", fmt(p.x), fmt(p.y))
                            })
                            .collect::<Vec<_>>()
                            .join(" ")
                    };
                    w.open(
                        "polygon",
                        &[
                            ("id", &format!("plate-{i}")),
                            ("class", "link"),
                            ("points", &points(at)),
                            ("fill", style::PLATE_FILL),
                            ("stroke", style::BAR),
                            ("stroke-width", "3"),
                            ("stroke-linejoin", "round"),
                        ],
                    );
                    if let Some(m) = motion {
                        m.animate(w, "points", points);
                    }
                    w.close("polygon");
                }
            }
        }
    }

    fn draw_sliders(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        for slider in &self.sliders {
            let p = at.get(&slider.point);
            let translate = |p: Vector2<f64>| format!("{} {}", fmt(p.x), fmt(p.y));
            w.open(
                "g",
                &[
                    ("id", &format!("slider-{}", slider.point)),
                    ("class", "slider"),
                    ("transform", &format!("translate({})", translate(p))),
                ],
            );
            if let Some(m) = motion {
                let values: Vec<String> = m
                    .frames
                    .iter()
                    .map(|f| translate(f.get(&slider.point)))
                    .collect();
                w.element(
                    "animateTransform",
                    &[
                        ("attributeName", "transform"),
                        ("type", "translate"),
                        ("dur", &format!("{}s", fmt(m.seconds))),
                        ("repeatCount", "indefinite"),
                        ("calcMode", "linear"),
                        ("values", &values.join(";")),
                    ],
                );
            }
            // The block's angle on the screen (y points down there).
            let degrees = |f: &Placed| match &slider.guide {
                Guide::Link([a, b]) => {
                    let d = f.get(b) - f.get(a);
                    d.y.atan2(d.x).to_degrees()
                }
                _ => -slider.angle.rem_euclid(std::f64::consts::TAU).to_degrees(),
            };
            w.open(
                "g",
                &[("transform", &format!("rotate({})", fmt(degrees(at))))],
            );
            if let (Some(m), Guide::Link(_)) = (motion, &slider.guide) {
                // Unwrapped, so that the block does not spin round at ±180°.
                let mut previous: Option<f64> = None;
                let values: Vec<String> = m
                    .frames
                    .iter()
                    .map(|f| {
                        let mut a = degrees(f);
                        if let Some(p) = previous {
                            a += 360.0 * ((p - a) / 360.0).round();
                        }
                        previous = Some(a);
                        fmt(a)
                    })
                    .collect();
                w.element(
                    "animateTransform",
                    &[
                        ("attributeName", "transform"),
                        ("type", "rotate"),
                        ("dur", &format!("{}s", fmt(m.seconds))),
                        ("repeatCount", "indefinite"),
                        ("calcMode", "linear"),
                        ("values", &values.join(";")),
                    ],
                );
            }
            w.element(
                "rect",
                &[
                    ("x", "-15"),
                    ("y", "-9"),
                    ("width", "30"),
                    ("height", "18"),
                    ("rx", "2"),
                    ("fill", style::PLATE_FILL),
                    ("stroke", style::BAR),
                    ("stroke-width", "2.2"),
                ],
            );
            w.close("g");
            w.close("g");
        }
    }

    /// Joints (ends of links, pivots, sliders) as open circles; other
    /// points as dots.
    fn draw_points(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        let joints: Vec<&String> = self
            .bodies
            .iter()
            .flat_map(|b| match b {
                Body::Bar(ends) => ends.as_slice(),
                Body::Plate(corners) => corners.as_slice(),
            })
            .chain(self.ground.iter().map(|(n, _)| n))
            .chain(self.sliders.iter().map(|s| &s.point))
            .collect();
        for (name, p) in &at.points {
            let joint = joints.contains(&name);
            w.open(
                "circle",
                &[
                    ("id", &format!("point-{name}")),
                    ("class", if joint { "joint" } else { "point" }),
                    ("cx", &fmt(p.x)),
                    ("cy", &fmt(p.y)),
                    (
                        "r",
                        &fmt(if joint {
                            style::JOINT_RADIUS
                        } else {
                            style::DOT_RADIUS
                        }),
                    ),
                    ("fill", if joint { "white" } else { style::INK }),
                    ("stroke", style::INK),
                    ("stroke-width", if joint { "1.8" } else { "0" }),
                ],
            );
            if let Some(m) = motion {
                m.animate(w, "cx", |f| fmt(f.get(name).x));
                m.animate(w, "cy", |f| fmt(f.get(name).y));
            }
            w.close("circle");
        }
    }

    fn draw_arrows(
        &self,
        w: &mut Writer,
        layout: &Layout,
        frame: &Frame,
        motion: Option<(&[Frame], f64)>,
    ) -> Result<(), SceneError> {
        for (kind, names, colour, scale) in [
            (
                "velocity",
                &self.velocity_arrows,
                style::VELOCITY,
                layout.velocity_scale,
            ),
            (
                "acceleration",
                &self.acceleration_arrows,
                style::ACCELERATION,
                layout.acceleration_scale,
            ),
        ] {
            for name in names {
                let geometry = |f: &Frame| -> Result<Arrow, SceneError> {
                    let k = f.index(name).ok_or_else(|| unknown(f, name))?;
                    let vectors = if kind == "velocity" {
                        f.velocities.as_ref()
                    } else {
                        f.accelerations.as_ref()
                    };
                    let vector = vectors.ok_or(SceneError::MissingKinematics {
                        what: if kind == "velocity" {
                            "velocities"
                        } else {
                            "accelerations"
                        },
                    })?[k];
                    let base = f.positions[k];
                    Ok(Arrow::new(
                        layout.screen(base),
                        layout.screen(base + vector * scale),
                    ))
                };
                let arrow = geometry(frame)?;
                w.open(
                    "g",
                    &[
                        ("id", &format!("{kind}-{name}")),
                        ("class", &format!("arrow {kind}")),
                        ("fill", colour),
                        ("stroke", colour),
                    ],
                );
                w.open(
                    "line",
                    &[
                        ("x1", &fmt(arrow.base.x)),
                        ("y1", &fmt(arrow.base.y)),
                        ("x2", &fmt(arrow.neck.x)),
                        ("y2", &fmt(arrow.neck.y)),
                        ("stroke-width", &fmt(style::ARROW_WIDTH)),
                        ("stroke-linecap", "round"),
                    ],
                );
                let arrows: Vec<Arrow> = match motion {
                    Some((cycle, _)) => cycle.iter().map(&geometry).collect::<Result<_, _>>()?,
                    None => Vec::new(),
                };
                if let Some((_, seconds)) = motion {
                    let values = |f: &dyn Fn(&Arrow) -> String| {
                        arrows.iter().map(f).collect::<Vec<_>>().join(";")
                    };
                    animate_values(w, "x1", &values(&|a| fmt(a.base.x)), seconds);
                    animate_values(w, "y1", &values(&|a| fmt(a.base.y)), seconds);
                    animate_values(w, "x2", &values(&|a| fmt(a.neck.x)), seconds);
                    animate_values(w, "y2", &values(&|a| fmt(a.neck.y)), seconds);
                }
                w.close("line");
                w.open(
                    "polygon",
                    &[
                        ("points", &arrow.head()),
                        ("stroke-width", "0.8"),
                        ("stroke-linejoin", "round"),
                    ],
                );
                if let Some((_, seconds)) = motion {
                    let values: Vec<String> = arrows.iter().map(Arrow::head).collect();
                    animate_values(w, "points", &values.join(";"), seconds);
                }
                w.close("polygon");
                w.close("g");
            }
        }
        Ok(())
    }

    /// Names beside the points, each where it is farthest from the bars,
    /// arrows, points and the labels already placed (chosen on the first
    /// frame; an animated label keeps its offset from its point).
    fn draw_labels(
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
            w.text(&pretty_name(name));
            w.close("text");
        }
    }

    /// The segments a label should keep clear of: bars, plate edges,
    /// arrows, ground symbols and slider blocks, on the screen.
    fn obstacles(
        &self,
        layout: &Layout,
        frame: &Frame,
        at: &Placed,
    ) -> Vec<(Vector2<f64>, Vector2<f64>)> {
        let mut out = Vec::new();
        for body in &self.bodies {
            match body {
                Body::Bar([a, b]) => out.push((at.get(a), at.get(b))),
                Body::Plate(corners) => {
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
                Guide::Link([a, b]) => (at.get(b) - at.get(a))
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

    fn draw_legend(&self, w: &mut Writer, layout: &Layout, traced: bool) {
        let mut y = layout.legend_top;
        let x = style::MARGIN;
        let (l, t) = (&self.length_unit, &self.time_unit);
        let mut line = |w: &mut Writer, colour: &str, text: String| {
            let arrow = Arrow::new(Vector2::new(x, y - 4.0), Vector2::new(x + 34.0, y - 4.0));
            w.element(
                "line",
                &[
                    ("x1", &fmt(arrow.base.x)),
                    ("y1", &fmt(arrow.base.y)),
                    ("x2", &fmt(arrow.neck.x)),
                    ("y2", &fmt(arrow.neck.y)),
                    ("stroke", colour),
                    ("stroke-width", &fmt(style::ARROW_WIDTH)),
                ],
            );
            w.element("polygon", &[("points", &arrow.head()), ("fill", colour)]);
            legend_text(w, x + 44.0, y, &text);
            y += style::LEGEND_LINE;
        };
        w.open("g", &[("id", "legend"), ("class", "legend")]);
        if !self.velocity_arrows.is_empty() {
            let s = layout.velocity_scale;
            line(
                w,
                style::VELOCITY,
                format!(
                    "velocity, scale {}: 1 {l} drawn = {} {l}/{t}",
                    number(s),
                    number(1.0 / s)
                ),
            );
        }
        if !self.acceleration_arrows.is_empty() {
            let s = layout.acceleration_scale;
            line(
                w,
                style::ACCELERATION,
                format!(
                    "acceleration, scale {}: 1 {l} drawn = {} {l}/{t}²",
                    number(s),
                    number(1.0 / s)
                ),
            );
        }
        for name in self.traces.iter().filter(|_| traced) {
            w.element(
                "line",
                &[
                    ("x1", &fmt(x)),
                    ("y1", &fmt(y - 4.0)),
                    ("x2", &fmt(x + 34.0)),
                    ("y2", &fmt(y - 4.0)),
                    ("stroke", style::TRACE),
                    ("stroke-width", "1.2"),
                    ("stroke-dasharray", "5 3"),
                ],
            );
            legend_text(
                w,
                x + 44.0,
                y,
                &format!("path of {} over the cycle", pretty_name(name)),
            );
            y += style::LEGEND_LINE;
        }
        // A bar of a round length.
        let length = nice_below(120.0 / layout.scale);
        let pixels = length * layout.scale;
        let bar_y = y - 4.0;
        w.element(
            "path",
            &[
                ("id", "scale-bar"),
                (
                    "d",
                    &format!(
                        "M{} {} v-4 v8 v-4 h{} v-4 v8",
                        fmt(x),
                        fmt(bar_y),
                        fmt(pixels)
                    ),
                ),
                ("fill", "none"),
                ("stroke", style::INK),
                ("stroke-width", "1.4"),
            ],
        );
        legend_text(w, x + pixels + 10.0, y, &format!("{} {l}", number(length)));
        w.close("g");
    }
}

/// Frames with their points in screen coordinates.
#[derive(Default)]
struct Placed {
    points: Vec<(String, Vector2<f64>)>,
    centre: Vector2<f64>,
}

impl Placed {
    fn insert(&mut self, name: &str, at: Vector2<f64>) {
        if !self.points.iter().any(|(n, _)| n == name) {
            self.points.push((name.to_string(), at));
        }
    }

    fn get(&self, name: &str) -> Vector2<f64> {
        self.points
            .iter()
            .find(|(n, _)| n == name)
            .map_or(Vector2::zeros(), |(_, p)| *p)
    }
}

/// The frames of an animation and its period.
struct Motion<'a> {
    frames: &'a [Placed],
    seconds: f64,
}

impl Motion<'_> {
    /// An `<animate>` of `attribute` through the frames' values.
    fn animate(&self, w: &mut Writer, attribute: &str, value: impl Fn(&Placed) -> String) {
        let values: Vec<String> = self.frames.iter().map(value).collect();
        animate_values(w, attribute, &values.join(";"), self.seconds);
    }
}

fn animate_values(w: &mut Writer, attribute: &str, values: &str, seconds: f64) {
    w.element(
        "animate",
        &[
            ("attributeName", attribute),
            ("dur", &format!("{}s", fmt(seconds))),
            ("repeatCount", "indefinite"),
            ("calcMode", "linear"),
            ("values", values),
        ],
    );
}

/// An arrow in screen coordinates: from `base` to `tip`, the shaft ending
/// where the head begins.
struct Arrow {
    base: Vector2<f64>,
    neck: Vector2<f64>,
    tip: Vector2<f64>,
    side: Vector2<f64>,
}

impl Arrow {
    fn new(base: Vector2<f64>, tip: Vector2<f64>) -> Arrow {
        let along = tip - base;
        let length = along.norm();
        let dir = if length > 0.0 {
            along / length
        } else {
            Vector2::new(1.0, 0.0)
        };
        // Short arrows get a smaller head, never longer than the arrow.
        let head = style::HEAD_LENGTH.min(0.6 * length);
        let half = style::HEAD_HALF_WIDTH * head / style::HEAD_LENGTH;
        Arrow {
            base,
            neck: tip - dir * head,
            tip,
            side: Vector2::new(-dir.y, dir.x) * half,
        }
    }

    /// The head's triangle, its apex (the arrow's tip) first.
    fn head(&self) -> String {
        let (a, b) = (self.neck + self.side, self.neck - self.side);
        format!(
            "{},{} {},{} {},{}",
            fmt(self.tip.x),
            fmt(self.tip.y),
            fmt(a.x),
            fmt(a.y),
            fmt(b.x),
            fmt(b.y)
        )
    }
}

/// A fixed pivot: a triangle under the joint on a hatched base.
fn ground_symbol(w: &mut Writer, at: Vector2<f64>) {
    let (h, b) = (style::GROUND_HEIGHT, style::GROUND_HALF_WIDTH);
    let base_y = at.y + h;
    let mut d = format!(
        "M{} {} L{} {} L{} {} Z",
        fmt(at.x),
        fmt(at.y),
        fmt(at.x - b),
        fmt(base_y),
        fmt(at.x + b),
        fmt(base_y)
    );
    let mut hatch = format!(
        "M{} {} H{}",
        fmt(at.x - b - 5.0),
        fmt(base_y),
        fmt(at.x + b + 5.0)
    );
    let mut x = at.x - b - 5.0;
    while x < at.x + b + 5.0 {
        let _ = write!(hatch, " M{} {} l-6 7", fmt(x + 6.0), fmt(base_y));
        x += 5.0;
    }
    d.push(' ');
    w.element(
        "path",
        &[
            ("class", "ground"),
            ("d", d.trim_end()),
            ("fill", style::PLATE_FILL),
            ("stroke", style::INK),
            ("stroke-width", "1.4"),
            ("stroke-linejoin", "round"),
        ],
    );
    w.element(
        "path",
        &[
            ("class", "ground"),
            ("d", &hatch),
            ("fill", "none"),
            ("stroke", style::INK),
            ("stroke-width", "1.1"),
        ],
    );
}

/// A straight guide from `a` to `b`, hatched on its lower side.
fn guide_symbol(w: &mut Writer, a: Vector2<f64>, b: Vector2<f64>, point: &str) {
    let along = b - a;
    let length = along.norm().max(1e-9);
    let dir = along / length;
    // The side away from the block: below on the screen for a level guide.
    let mut normal = Vector2::new(-dir.y, dir.x);
    if normal.y < 0.0 {
        normal = -normal;
    }
    let offset = normal * 10.0;
    let (a, b) = (a + offset, b + offset);
    let mut hatch = format!("M{} {} L{} {}", fmt(a.x), fmt(a.y), fmt(b.x), fmt(b.y));
    let mut s = 4.0;
    while s < length {
        let p = a + dir * s;
        let q = p + normal * 7.0 - dir * 6.0;
        let _ = write!(
            hatch,
            " M{} {} L{} {}",
            fmt(p.x),
            fmt(p.y),
            fmt(q.x),
            fmt(q.y)
        );
        s += 6.0;
    }
    w.element(
        "path",
        &[
            ("id", &format!("guide-{point}")),
            ("class", "guide"),
            ("d", &hatch),
            ("fill", "none"),
            ("stroke", style::INK),
            ("stroke-width", "1.2"),
        ],
    );
}

fn legend_text(w: &mut Writer, x: f64, y: f64, text: &str) {
    w.open(
        "text",
        &[
            ("x", &fmt(x)),
            ("y", &fmt(y)),
            ("font-family", style::FONT),
            ("font-size", "13"),
            ("fill", style::INK),
        ],
    );
    w.text(text);
    w.close("text");
}

/// The largest 1, 2 or 5 × 10ᵏ not above x.
fn nice_below(x: f64) -> f64 {
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
fn number(x: f64) -> String {
    if x != 0.0 && !(1e-6..1e9).contains(&x.abs()) {
        return format!("{x:e}");
    }
    let text = format!("{x:.10}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    text.to_string()
}

fn positive(what: &'static str, value: f64) -> Result<(), SceneError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(SceneError::BadSetting {
            what,
            must: "positive and finite",
            value,
        })
    }
}

fn finite(p: Vector2<f64>, what: &'static str, name: &str) -> Result<(), SceneError> {
    if p.x.is_finite() && p.y.is_finite() {
        Ok(())
    } else {
        Err(SceneError::NonFinite {
            what,
            name: name.into(),
        })
    }
}

fn unknown(frame: &Frame, name: &str) -> SceneError {
    SceneError::UnknownPoint {
        name: name.into(),
        known: frame.names.join(", "),
    }
}

/// A name's position: the frame's point, else the scene's ground pivot.
fn resolve(
    frame: &Frame,
    name: &str,
    ground: &[(String, Vector2<f64>)],
) -> Result<Vector2<f64>, SceneError> {
    let at = match frame.index(name) {
        Some(k) => frame.positions[k],
        None => ground
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| *p)
            .ok_or_else(|| unknown(frame, name))?,
    };
    finite(at, "position", name)?;
    Ok(at)
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
struct Layout {
    scale: f64,
    origin: Vector2<f64>,
    top: f64,
    width: f64,
    height: f64,
    legend_top: f64,
    velocity_scale: f64,
    acceleration_scale: f64,
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
    fn screen(&self, p: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(
            p.x * self.scale - self.origin.x * self.scale,
            self.top + (self.origin.y * self.scale - p.y * self.scale),
        )
    }

    fn open(&self, scene: &Scene) -> Writer {
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

    #[test]
    fn arrows_end_at_their_tips() {
        let a = Arrow::new(Vector2::new(0.0, 0.0), Vector2::new(100.0, 0.0));
        assert_eq!(a.tip, Vector2::new(100.0, 0.0));
        assert!(a.neck.x < 100.0 && a.neck.x > 80.0);
        assert!(a.head().starts_with("100,0 "));
    }
}

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
//! use linkage::draw::scene::{Frame, Scene};
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
//! let svg = scene.render(&Frame::from_analysis(&bar, &pose), &[])?;
//! assert!(svg.starts_with("<svg"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Drawing conventions: x to the right and y up, one scale for both axes,
//! fitted to the picture; ground pivots hatched; links as bars, joints as
//! open circles, other points as dots; velocities green and accelerations
//! red (as in the Maple worksheet), each with its scale in the legend,
//! drawn above the links with a white outline, arrows that would lie on
//! one another moved apart sideways; each traced path in its own colour
//! and dash pattern; labels where they overlap nothing drawn.
//!
//! Besides the pose, a scene draws what a design is judged against, in
//! the mechanism's plane: [`Markers`] at fixed points (a synthesis's
//! targets, numbered), [`Curve`]s through given points (a second design's
//! coupler curve, a desired path), other poses of the mechanism drawn
//! faint behind it ([`Scene::ghosts`]), and notes ([`Scene::note`]); a
//! [`Sheet`] sets several pictures side by side under one title:
//!
//! ```
//! use linkage::draw::scene::{Curve, Frame, Markers, Scene, Sheet};
//! use linkage::mechanisms::CouplerFourBar;
//! use linkage::prelude::*;
//! use std::f64::consts::TAU;
//!
//! let design = CouplerFourBar::WORKSHEET;
//! let drive = Drive::Line { from: vector![0.0], to: vector![TAU], steps: 60 };
//! let sweep = design.sweep(&vector![1.3, -0.8], &drive, &SweepOptions::default())?;
//! let turn: Vec<Frame> = sweep.poses.iter().map(|p| Frame::from_sweep_pose(&design, p)).collect();
//! let targets = [[25.0, 12.0], [10.0, 35.0], [-5.0, 20.0]];
//! let scene = Scene::new()
//!     .ground("A", [0.0, 0.0])
//!     .ground("D", [80.0, 0.0])
//!     .link(["A", "B"])
//!     .plate(["B", "C", "P"])
//!     .link(["C", "D"])
//!     .trace(["P"])
//!     .markers(Markers::new("targets", targets).numbered())
//!     .curve(Curve::new("desired path", [[-10.0, 10.0], [30.0, 40.0]]))
//!     .ghosts(&[turn[15].clone(), turn[30].clone()])
//!     .note([40.0, -10.0], "ground link")
//!     .title("The worksheet's four-bar")
//!     .subtitle("its coupler's midpoint against three targets")
//!     .width(400.0);
//! let picture = scene.render(&turn[0], &turn)?;
//! let sheet = Sheet::new("Two poses")
//!     .picture(picture)
//!     .picture(scene.render(&turn[45], &turn)?)
//!     .render()?;
//! assert_eq!(sheet.matches("<svg").count(), 3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The area's files: the description (here: [`Scene`], [`Frame`], the
//! checks), the layout (`layout.rs`: the scale, the arrows' scales, the
//! screen positions; `heading.rs`: the title and subtitle), the look
//! (`style.rs`, `colour.rs`), the drawing symbols (`symbols.rs`: traces,
//! guides, links, sliders, points, ground), the arrows (`arrows.rs`), what
//! is drawn in the plane besides the pose (`overlay.rs`: `markers.rs`,
//! `curves.rs`, `ghosts.rs`, `notes.rs`), the labels (`labels.rs`, on
//! `geometry.rs`), the legend (`legend.rs`), the animation
//! (`animation.rs`) and the sheet of pictures (`sheet.rs`).

mod animation;
mod arrow_kind;
mod arrows;
mod colour;
mod curves;
mod geometry;
mod ghosts;
mod heading;
mod labels;
mod layout;
mod legend;
mod markers;
mod motion;
mod notes;
mod overlay;
mod placement;
mod sheet;
mod style;
mod symbols;

pub use curves::Curve;
pub use markers::{MarkerShape, Markers};
pub use placement::Placement;
pub use sheet::Sheet;

use crate::error::{NameKind, UnknownName};
use crate::ground::Ground;
use crate::runtime::{Analysis, Linkage, SweepPose};
use nalgebra::{SVector, Vector2};
use symbols::{ground_symbol, guide_symbol};

/// What went wrong drawing a scene.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
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
    /// The scene names a point that neither the frame nor the scene's
    /// ground pivots define.
    UnknownName(UnknownName),
    /// A point of a set of markers or of a curve (`what`), named `name`,
    /// is NaN or infinite: the point at `index` (counted from 0) of those
    /// given.
    NonFinitePoint {
        what: &'static str,
        name: String,
        index: usize,
    },
    /// A set of markers without markers, or a curve of fewer than two
    /// points.
    TooFewPoints {
        what: &'static str,
        name: String,
        points: usize,
        least: usize,
    },
    /// A set of markers given a number of labels other than its number
    /// of markers.
    LabelCount {
        name: String,
        markers: usize,
        labels: usize,
    },
    /// A colour given is not one SVG understands.
    BadColour { what: &'static str, colour: String },
    /// A sheet was asked for without pictures.
    EmptySheet,
    /// The picture at `index` (counted from 0) of a sheet is not an SVG
    /// document with its width and height in pixels.
    NotAPicture { index: usize },
    /// Text of `font` px on a sheet `width` px wide would print at
    /// `printed` pt with the sheet printed 16 cm wide, smaller than `least`
    /// (7 pt, 5.5 pt for subscripts and superscripts): in the picture at
    /// `picture` (counted from 0), or in the sheet's own heading if `None`.
    TextTooSmall {
        picture: Option<usize>,
        font: f64,
        width: f64,
        printed: f64,
        least: f64,
    },
}

crate::error::error_impls! {
    SceneError {
        Self::MissingKinematics { what } => ("the scene draws {what} arrows but the frame has no {what}"),
        Self::NonFinite { name, what } => ("the {what} of `{name}` is not finite"),
        Self::TooFewFrames { frames } => ("an animation needs at least two frames, got {frames}"),
        Self::BadSetting { value, what, must } => ("{what} must be {must}, got {value}"),
        Self::UnknownName(inner) => ("{inner}"),
        Self::NonFinitePoint { what, name, index } => ("point {index} (from 0) of the {what} `{name}` is not finite"),
        Self::TooFewPoints { what, name, points, least } => ("the {what} `{name}` has {points} points, fewer than {least}"),
        Self::LabelCount { name, markers, labels } => ("the set of markers `{name}` has {markers} markers but {labels} labels"),
        Self::BadColour { what, colour } => ("the colour of {what} must be one SVG understands (#rrggbb, a name, rgb(…)), got `{colour}`"),
        Self::EmptySheet => ("a sheet needs at least one picture"),
        Self::NotAPicture { index } => ("picture {index} (from 0) of the sheet is not an SVG document with its width and height in pixels"),
        Self::TextTooSmall { picture, font, width, printed, least } => ("{} has text of {font} px, which on a sheet {width} px wide printed 16 cm wide is {printed:.1} pt, below {least} pt: draw the pictures narrower", match picture { Some(k) => format!("picture {k} (from 0)"), None => "the sheet's heading".to_string() }),
    }
    wraps { UnknownName(UnknownName) }
}

/// The named points of one pose: positions, and, where known, velocities
/// and accelerations (in the model's length and time units).
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The points' names, in the model's order.
    pub names: Vec<String>,
    /// Each point's position.
    pub positions: Vec<Vector2<f64>>,
    /// Each point's velocity, if known.
    pub velocities: Option<Vec<Vector2<f64>>>,
    /// Each point's acceleration, if known.
    pub accelerations: Option<Vec<Vector2<f64>>>,
}

impl Frame {
    /// The position of the point `name`, if the frame has it.
    pub fn position(&self, name: &str) -> Option<Vector2<f64>> {
        let k = self.names.iter().position(|n| n == name)?;
        self.positions.get(k).copied()
    }

    /// The points of a whole analysis ([`Linkage::analyze`]) of `model`
    /// (which names the points).
    pub fn from_analysis<L: Linkage<M, F>, const M: usize, const F: usize>(
        model: &L,
        analysis: &Analysis<M, F, L::Points>,
    ) -> Frame {
        Frame {
            names: model.point_names().iter().map(|s| s.to_string()).collect(),
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
            names: model.point_names().iter().map(|s| s.to_string()).collect(),
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
            names: model.point_names().iter().map(|s| s.to_string()).collect(),
            positions: model.point_positions(u, v).as_ref().to_vec(),
            velocities: None,
            accelerations: None,
        }
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// The index of the point `name`, which the scene names.
    fn point(&self, name: &str) -> Result<usize, UnknownName> {
        self.index(name).ok_or_else(|| self.unknown(name))
    }

    /// The error of the scene naming `name`, which is none of the frame's
    /// points: built only once a lookup has failed.
    fn unknown(&self, name: &str) -> UnknownName {
        let names = self.names.iter().map(String::as_str);
        UnknownName::new(NameKind::Point, "scene", name, names)
    }
}

/// A body of the mechanism: a bar between two points or a plate over three
/// or more.
#[derive(Clone, Debug, PartialEq)]
enum Shape {
    Bar([String; 2]),
    Plate(Vec<String>),
}

/// A slider: the block at `point`, moving along a guide at `angle` (rad)
/// through it.
#[derive(Clone, Debug, PartialEq)]
struct Slider {
    point: String,
    angle: f64,
    guide: Slideway,
}

/// What a slider block slides on.
#[derive(Clone, Debug, PartialEq)]
enum Slideway {
    /// A fixed straight guide at the slider's angle, drawn hatched.
    Ground,
    /// A link: the block turns with the line from the first point to the
    /// second (the link itself is drawn as a body).
    Link([String; 2]),
    /// A slot in a moving body at a fixed angle, drawn with that body.
    Slot,
}

/// What a picture of a mechanism shows (see the [module](self)): built
/// up by its methods, then drawn from a [`Frame`] by [`Scene::render`] or
/// through a cycle of frames by [`Scene::animate`].
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    ground: Vec<(String, Vector2<f64>)>,
    shapes: Vec<Shape>,
    sliders: Vec<Slider>,
    velocity_arrows: Vec<String>,
    acceleration_arrows: Vec<String>,
    velocity_scale: Option<f64>,
    acceleration_scale: Option<f64>,
    traces: Vec<String>,
    markers: Vec<Markers>,
    curves: Vec<Curve>,
    ghosts: Vec<Frame>,
    /// The ghosts' legend entry (none if empty).
    ghost_name: String,
    notes: Vec<notes::Note>,
    labels: bool,
    title: Option<String>,
    subtitle: Option<String>,
    animation_title: Option<String>,
    length_unit: String,
    time_unit: String,
    width: f64,
}

impl Default for Scene {
    fn default() -> Self {
        Scene::new()
    }
}

impl Scene {
    /// An empty scene, 720 pixels wide, labelled, units mm and s.
    pub fn new() -> Scene {
        Scene {
            ground: Vec::new(),
            shapes: Vec::new(),
            sliders: Vec::new(),
            velocity_arrows: Vec::new(),
            acceleration_arrows: Vec::new(),
            velocity_scale: None,
            acceleration_scale: None,
            traces: Vec::new(),
            markers: Vec::new(),
            curves: Vec::new(),
            ghosts: Vec::new(),
            ghost_name: String::new(),
            notes: Vec::new(),
            labels: true,
            title: None,
            subtitle: None,
            animation_title: None,
            length_unit: "mm".into(),
            time_unit: "s".into(),
            width: 720.0,
        }
    }

    /// A ground pivot named `name` at a fixed position (drawn hatched); a
    /// name the frame also defines is drawn where the frame puts it, and
    /// a pivot named again is moved.
    pub fn ground(mut self, name: &str, at: [f64; 2]) -> Scene {
        let at = Vector2::new(at[0], at[1]);
        match self.ground.iter_mut().find(|(n, _)| n == name) {
            Some((_, was)) => *was = at,
            None => self.ground.push((name.into(), at)),
        }
        self
    }

    /// Every point of `ground` as a ground pivot (as [`Scene::ground`]
    /// each): the same description a force analysis takes.
    pub fn with_ground(mut self, ground: &Ground) -> Scene {
        for (name, at) in ground.points() {
            self = self.ground(name, [at.x, at.y]);
        }
        self
    }

    /// A binary link between two points (frame points or ground pivots).
    pub fn link(mut self, ends: [&str; 2]) -> Scene {
        self.shapes.push(Shape::Bar(ends.map(String::from)));
        self
    }

    /// A ternary (or larger) link: the polygon through its joints (an
    /// array of names, or any list of them, such as one read at run time).
    pub fn plate<I>(mut self, corners: I) -> Scene
    where
        I: IntoIterator,
        I::Item: AsRef<str>,
    {
        self.shapes.push(Shape::Plate(owned(corners)));
        self
    }

    /// A slider block at `point` on a straight guide at `angle` (rad, from
    /// the x axis) through it.
    pub fn slider(mut self, point: &str, angle: f64) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle,
            guide: Slideway::Ground,
        });
        self
    }

    /// A slider block at `point` sliding along the link through `line`
    /// (its two points): the block turns with the link.
    pub fn slider_on(mut self, point: &str, line: [&str; 2]) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle: 0.0,
            guide: Slideway::Link(line.map(String::from)),
        });
        self
    }

    /// A slider block at `point` in a slot at a fixed `angle` (rad) of a
    /// translating body, such as a ram: no ground guide is drawn.
    pub fn block(mut self, point: &str, angle: f64) -> Scene {
        self.sliders.push(Slider {
            point: point.into(),
            angle,
            guide: Slideway::Slot,
        });
        self
    }

    /// Velocity arrows at these points (each drawn once, however often named).
    pub fn velocities<I>(mut self, points: I) -> Scene
    where
        I: IntoIterator,
        I::Item: AsRef<str>,
    {
        add_new(&mut self.velocity_arrows, points);
        self
    }

    /// Acceleration arrows at these points (each drawn once, however often named).
    pub fn accelerations<I>(mut self, points: I) -> Scene
    where
        I: IntoIterator,
        I::Item: AsRef<str>,
    {
        add_new(&mut self.acceleration_arrows, points);
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
    pub fn trace<I>(mut self, points: I) -> Scene
    where
        I: IntoIterator,
        I::Item: AsRef<str>,
    {
        self.traces.extend(owned(points));
        self
    }

    /// Whether to write the points' names beside them (default yes).
    pub fn labels(mut self, on: bool) -> Scene {
        self.labels = on;
        self
    }

    /// A title above the still picture ([`Scene::render`]): it may name
    /// the pose. An animation does not carry it (see
    /// [`Scene::animation_title`]).
    pub fn title(mut self, title: &str) -> Scene {
        self.title = Some(title.into());
        self
    }

    /// A line under the still picture's title ([`Scene::title`]), in
    /// smaller type: what the reader should look at, the design's
    /// numbers. (Each of the two is wrapped to the picture's width.)
    pub fn subtitle(mut self, subtitle: &str) -> Scene {
        self.subtitle = Some(subtitle.into());
        self
    }

    /// A title above the animation ([`Scene::animate`]), which shows a
    /// whole cycle (so it should not name a pose); none if not set.
    pub fn animation_title(mut self, title: &str) -> Scene {
        self.animation_title = Some(title.into());
        self
    }

    /// The units of the model's lengths and times, for the legend.
    pub fn units(mut self, length: &str, time: &str) -> Scene {
        self.length_unit = length.into();
        self.time_unit = time.into();
        self
    }

    /// The picture's width in pixels, 200 to 20 000 (the height follows
    /// the mechanism). Its smallest text is 13 px, so on a [`Sheet`]
    /// printed 16 cm wide two pictures side by side keep it at 7 pt up to
    /// 409 px each.
    pub fn width(mut self, pixels: f64) -> Scene {
        self.width = pixels;
        self
    }

    /// The pose `frame` as SVG, with the traced paths over `cycle` (frames
    /// of the whole motion; may be empty). Automatic arrow scales are
    /// chosen over the frame and the cycle, as [`Scene::animate`] chooses
    /// them over the cycle: a still of a pose of the cycle and the
    /// animation share their scales.
    pub fn render(&self, frame: &Frame, cycle: &[Frame]) -> Result<String, SceneError> {
        let frames = std::slice::from_ref(frame);
        let layout = self.layout(
            frames,
            cycle,
            self.title.as_deref(),
            self.subtitle.as_deref(),
        )?;
        let mut w = layout.open();
        let overlay = self.overlay(&layout)?;
        self.draw_ghosts(&mut w, &overlay.ghosts);
        let traces = self.trace_paths(&layout, cycle)?;
        self.draw_traces(&mut w, &traces);
        self.draw_curves(&mut w, &overlay.curves);
        let guides = self.guides(&layout, frames, cycle)?;
        for guide in &guides {
            guide_symbol(&mut w, guide);
        }
        for (name, _) in &self.ground {
            let at = resolve(frame, name, &self.ground)?;
            ground_symbol(&mut w, layout.screen(at));
        }
        let placed = self.place(&layout, frame)?;
        self.draw_links(&mut w, &placed, None);
        self.draw_sliders(&mut w, &placed, None);
        self.draw_points(&mut w, &placed, None);
        self.draw_markers(&mut w, &overlay.markers);
        self.draw_arrows(&mut w, &layout, frame, None)?;
        self.draw_notes(&mut w, &overlay.notes);
        if self.labels {
            let arrows = self.arrows(&layout, frame)?;
            let obstacles = self.obstacles(&layout, &placed, &arrows, &guides, &traces, &overlay);
            self.draw_labels(&mut w, &placed, None, &obstacles, &overlay);
        }
        self.draw_legend(&mut w, &layout, !cycle.is_empty());
        Ok(w.finish())
    }

    /// Every point the scene names, checked against the frame.
    pub(super) fn names(&self) -> impl Iterator<Item = &String> {
        let bodies = self.shapes.iter().flat_map(|b| match b {
            Shape::Bar(ends) => ends.as_slice(),
            Shape::Plate(corners) => corners.as_slice(),
        });
        let guides = self.sliders.iter().flat_map(|s| match &s.guide {
            Slideway::Link(line) => line.as_slice(),
            _ => &[],
        });
        bodies
            .chain(self.sliders.iter().map(|s| &s.point))
            .chain(guides)
            .chain(&self.velocity_arrows)
            .chain(&self.acceleration_arrows)
            .chain(&self.traces)
    }
}

/// Names given as any list of strings, owned.
/// The names not yet in `list`, added to it in order (a point's arrow
/// asked for twice is drawn once).
fn add_new<I>(list: &mut Vec<String>, names: I)
where
    I: IntoIterator,
    I::Item: AsRef<str>,
{
    for name in names {
        if !list.iter().any(|n| n == name.as_ref()) {
            list.push(name.as_ref().to_owned());
        }
    }
}

fn owned<I>(names: I) -> Vec<String>
where
    I: IntoIterator,
    I::Item: AsRef<str>,
{
    names.into_iter().map(|s| s.as_ref().to_owned()).collect()
}

pub(super) fn positive(what: &'static str, value: f64) -> Result<(), SceneError> {
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

pub(super) fn finite(p: Vector2<f64>, what: &'static str, name: &str) -> Result<(), SceneError> {
    if p.x.is_finite() && p.y.is_finite() {
        Ok(())
    } else {
        Err(SceneError::NonFinite {
            what,
            name: name.into(),
        })
    }
}

/// A name's position: the frame's point, else the scene's ground pivot.
pub(super) fn resolve(
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
            .ok_or_else(|| frame.unknown(name))?,
    };
    finite(at, "position", name)?;
    Ok(at)
}

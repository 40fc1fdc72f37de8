//! Closure equations from a checked topology.
//!
//! The links are visited from the frame along a spanning tree of joints.
//! Each link gets a frame: an origin (one of its joints, whose position the
//! link it was reached from gives) and an angle — the coordinate
//! `theta_<link>`, the angle of the line from its origin to a reference
//! joint; or, for a link that slides on a prismatic joint, its guide's
//! angle plus the slide's. Each of the link's other joints is placed from
//! its origin by a length and an angle read from the drawing (`l_<o>_<j>`,
//! `a_<o>_<j>`), or given. A slider or slot runs along a line of its guide
//! at `gamma_<joint>` from the guide's frame and `h_<joint>` from its
//! origin, and the travel along it, `s_<joint>`, is a coordinate. Every
//! joint the tree does not cross closes a loop: the joint's position
//! reached through each of its links is one (two equations), and a
//! prismatic joint's links turn together (one more). The count of
//! equations is then Grübler–Kutzbach's.

use super::check::Checked;
use super::model::{Driven, JointKind};
use std::collections::VecDeque;

/// A value and the comment that says what it is.
#[derive(Clone, Debug)]
pub(super) struct Value {
    pub name: String,
    pub value: f64,
    pub what: String,
}

/// The generated mechanism: its coordinates, equations and parameters,
/// the drawn pose, and what a picture draws.
#[derive(Clone, Debug, Default)]
pub(super) struct Generated {
    /// Dependent coordinates and their drawn values.
    pub u: Vec<Value>,
    /// Driving coordinates and their drawn values, with the topology's
    /// driver index.
    pub v: Vec<(Value, usize)>,
    /// `name = (x, y)` of each point, in order.
    pub points: Vec<(String, String, String)>,
    pub closure: Vec<String>,
    /// The joint each closure equation closes a loop at.
    pub closes_at: Vec<String>,
    pub parameters: Vec<Value>,
    /// The frame's pivots.
    pub ground: Vec<(String, [f64; 2])>,
    /// Binary links and plates, by their points' names.
    pub bodies: Vec<Vec<String>>,
    /// Blocks on the frame: (point, angle).
    pub ground_sliders: Vec<(String, f64)>,
    /// Blocks on a moving link: (point, two points of the link along its
    /// line).
    pub along_sliders: Vec<(String, [String; 2])>,
}

/// How a link's frame turns.
#[derive(Clone, Debug)]
struct Frame {
    /// The origin joint.
    origin: usize,
    /// The angle's text ("" for the frame: zero).
    angle: String,
    /// Its drawn value.
    drawn: f64,
    /// The joint whose direction from the origin the angle is (a free
    /// frame's), placed with no angle of its own.
    reference: Option<usize>,
}

struct Generator<'c, 't> {
    checked: &'c Checked<'t>,
    out: Generated,
    frames: Vec<Option<Frame>>,
    /// The link that defined each joint's point (the frame for its pivots,
    /// which are parameters rather than points).
    placer: Vec<Option<usize>>,
    /// The tree joint through which each link was reached.
    entered: Vec<Option<usize>>,
    /// When each link was reached (`usize::MAX`: not yet): of a slider's
    /// two links, the first reached is its guide.
    reached: Vec<usize>,
}

/// The closure equations of a checked topology.
pub(super) fn generate(checked: &Checked<'_>) -> Generated {
    let n = checked.links.len();
    let mut generator = Generator {
        checked,
        out: Generated::default(),
        frames: vec![None; n],
        placer: vec![None; checked.topology.joints.len()],
        entered: vec![None; n],
        reached: vec![usize::MAX; n],
    };
    generator.visit();
    generator.close();
    generator.draw();
    generator.out
}

/// `x` as Rust writes an f64 that reads back to itself.
pub(super) fn number(x: f64) -> String {
    let text = format!("{x:?}");
    if text.contains('.') || text.contains('e') || text.contains("inf") || text.contains("NaN") {
        text
    } else {
        format!("{text}.0")
    }
}

impl Generator<'_, '_> {
    fn name(&self, joint: usize) -> &str {
        self.checked.joint_name(joint)
    }

    /// The drawn or given distance between two joints of one link.
    fn length(&self, a: usize, b: usize) -> f64 {
        let (na, nb) = (self.name(a), self.name(b));
        let given = self
            .checked
            .topology
            .lengths
            .iter()
            .find(|(x, y, _)| (x == na && y == nb) || (x == nb && y == na));
        if let Some((_, _, l)) = given {
            return *l;
        }
        let (pa, pb) = (self.checked.at(a), self.checked.at(b));
        (pb[0] - pa[0]).hypot(pb[1] - pa[1])
    }

    fn drawn_angle(&self, a: usize, b: usize) -> f64 {
        let (pa, pb) = (self.checked.at(a), self.checked.at(b));
        (pb[1] - pa[1]).atan2(pb[0] - pa[0])
    }

    fn parameter(&mut self, name: String, value: f64, what: String) -> String {
        self.out.parameters.push(Value {
            name: name.clone(),
            value,
            what,
        });
        name
    }

    /// The text of a placed joint's position: its point, or for a pivot of
    /// the frame its parameters.
    fn position_of(&mut self, joint: usize) -> (String, String) {
        let name = self.name(joint).to_owned();
        if self.placer[joint] != Some(self.checked.ground) {
            return (format!("{name}.x"), format!("{name}.y"));
        }
        let [x, y] = self.checked.at(joint);
        let px = format!("x_{name}");
        let py = format!("y_{name}");
        if !self.out.parameters.iter().any(|p| p.name == px) {
            self.parameter(px.clone(), x, format!("{name}, a pivot of the frame: x"));
            self.parameter(py.clone(), y, format!("{name}, a pivot of the frame: y"));
            self.out.ground.push((name, [x, y]));
        }
        (px, py)
    }

    /// `angle + offset` as text, either part possibly absent.
    fn sum(angle: &str, offset: Option<&str>) -> String {
        match (angle.is_empty(), offset) {
            (true, None) => "0.0".to_owned(),
            (true, Some(o)) => o.to_owned(),
            (false, None) => angle.to_owned(),
            (false, Some(o)) => format!("({angle} + {o})"),
        }
    }

    /// The vector from `link`'s origin to `joint` in its frame, as text
    /// (x, y), or `None` where they coincide.
    fn relative(
        &mut self,
        link: usize,
        joint: usize,
        reference: Option<usize>,
    ) -> Option<(String, String)> {
        let frame = self.frames[link].clone().expect("a visited link");
        let o = frame.origin;
        if joint == o
            || (!self.given(o, joint)
                && self
                    .checked
                    .coincide(self.checked.at(o), self.checked.at(joint)))
        {
            return None;
        }
        let (on, jn) = (self.name(o).to_owned(), self.name(joint).to_owned());
        let l = self.parameter(
            format!("l_{on}_{jn}"),
            self.length(o, joint),
            format!("{on}–{jn} on link `{}`", self.checked.link_name(link)),
        );
        let offset = if Some(joint) == reference {
            None
        } else {
            let a = self.drawn_angle(o, joint) - frame.drawn;
            let a = (a.sin()).atan2(a.cos());
            Some(self.parameter(
                format!("a_{on}_{jn}"),
                a,
                format!(
                    "the angle of {on}→{jn} from the frame of link `{}`",
                    self.checked.link_name(link)
                ),
            ))
        };
        let angle = Self::sum(&frame.angle, offset.as_deref());
        Some((
            format!("{l} * {angle}.cos()"),
            format!("{l} * {angle}.sin()"),
        ))
    }

    fn given(&self, a: usize, b: usize) -> bool {
        let (na, nb) = (self.name(a), self.name(b));
        (self.checked.topology.lengths.iter())
            .any(|(x, y, _)| (x == na && y == nb) || (x == nb && y == na))
    }

    /// `base + rel` (or `base - rel`) as text.
    fn offset(
        base: &(String, String),
        rel: &Option<(String, String)>,
        minus: bool,
    ) -> (String, String) {
        match rel {
            None => base.clone(),
            Some((x, y)) => {
                let op = if minus { "-" } else { "+" };
                (
                    format!("{} {op} {x}", base.0),
                    format!("{} {op} {y}", base.1),
                )
            }
        }
    }

    /// The point at travel `s_<joint>` along the line of `joint` on the
    /// guide `link`: its text, and the travel's drawn value.
    fn line_point(&mut self, link: usize, joint: usize) -> ((String, String), f64) {
        let frame = self.frames[link].clone().expect("a visited guide");
        let jn = self.name(joint).to_owned();
        let world = match self.checked.kind(joint) {
            JointKind::Prismatic { angle } | JointKind::PinInSlot { angle } => angle,
            JointKind::Revolute => 0.0,
        };
        let gamma_value = {
            let a = world - frame.drawn;
            a.sin().atan2(a.cos())
        };
        let (origin, from) = if link == self.checked.ground {
            ((String::new(), String::new()), [0.0, 0.0])
        } else {
            let (x, y) = self.position_of(frame.origin);
            (
                (format!("{x} + "), format!("{y} + ")),
                self.checked.at(frame.origin),
            )
        };
        let at = self.checked.at(joint);
        let (dx, dy) = (at[0] - from[0], at[1] - from[1]);
        let (t, nrm) = ((world.cos(), world.sin()), (-world.sin(), world.cos()));
        let travel = dx * t.0 + dy * t.1;
        let offset = dx * nrm.0 + dy * nrm.1;
        let link_name = self.checked.link_name(link).to_owned();
        let gamma = self.parameter(
            format!("gamma_{jn}"),
            gamma_value,
            format!("the line of `{jn}` on link `{link_name}`, from its frame"),
        );
        let h = self.parameter(
            format!("h_{jn}"),
            offset,
            format!("the offset of the line of `{jn}` from the origin of link `{link_name}`"),
        );
        let angle = Self::sum(&frame.angle, Some(&gamma));
        let s = format!("s_{jn}");
        let x = format!("{}{s} * {angle}.cos() - {h} * {angle}.sin()", origin.0);
        let y = format!("{}{s} * {angle}.sin() + {h} * {angle}.cos()", origin.1);
        ((x, y), travel)
    }

    fn define(&mut self, link: usize, joint: usize, (x, y): (String, String)) {
        let name = self.name(joint).to_owned();
        self.out.points.push((name, x, y));
        self.placer[joint] = Some(link);
    }

    /// A coordinate: driven if a driver names it, dependent otherwise.
    fn coordinate(&mut self, value: Value, driver: Option<usize>) {
        match driver {
            Some(d) => self.out.v.push((value, d)),
            None => self.out.u.push(value),
        }
    }

    /// The travel `s_<joint>` along a slider or slot, drawn at `travel`: a
    /// coordinate, driven if a driver names it.
    fn slide(&mut self, joint: usize, travel: f64) {
        let value = Value {
            name: format!("s_{}", self.name(joint)),
            value: travel,
            what: format!("the travel along `{}`", self.name(joint)),
        };
        let driver = self.slide_driver(joint);
        self.coordinate(value, driver);
    }

    /// The driver of the angle of `link`, if any: (from, to, index).
    fn angle_driver(&self, link: usize) -> Option<(usize, usize, usize)> {
        let joints = &self.checked.links[link];
        (self.checked.topology.drivers.iter().enumerate()).find_map(|(d, driver)| {
            match &driver.driven {
                Driven::Angle { from, to } => {
                    let (a, b) = (self.checked.joint(from)?, self.checked.joint(to)?);
                    (joints.contains(&a) && joints.contains(&b)).then_some((a, b, d))
                }
                Driven::Slide { .. } => None,
            }
        })
    }

    fn slide_driver(&self, joint: usize) -> Option<usize> {
        let name = self.name(joint);
        (self.checked.topology.drivers.iter())
            .position(|d| matches!(&d.driven, Driven::Slide { joint } if joint == name))
    }

    /// Whether `link` places the point of `joint`: any link of a pin (the
    /// first to come), the frame its pivots; of a slider the link reached
    /// second (the block: the two slide on each other and turn together,
    /// so either may be the guide); of a slot its pin's link (the second
    /// listed).
    fn places(&self, link: usize, joint: usize) -> bool {
        let on = &self.checked.joint_links[joint];
        match self.checked.kind(joint) {
            JointKind::Revolute => {
                !on.contains(&self.checked.ground) || link == self.checked.ground
            }
            JointKind::Prismatic { .. } => {
                let other = if on[0] == link { on[1] } else { on[0] };
                self.reached[other] < self.reached[link]
            }
            JointKind::PinInSlot { .. } => on[1] == link,
        }
    }

    /// A slider's guide: of its two links, the first reached.
    fn guide(&self, joint: usize) -> (usize, usize) {
        let on = &self.checked.joint_links[joint];
        match self.checked.kind(joint) {
            JointKind::Prismatic { .. } if self.reached[on[1]] < self.reached[on[0]] => {
                (on[1], on[0])
            }
            _ => (on[0], on[1]),
        }
    }

    /// The spanning tree from the frame, breadth first: each link reached
    /// through one joint from a link already placed, pins before slides.
    fn visit(&mut self) {
        let ground = self.checked.ground;
        self.frames[ground] = Some(Frame {
            origin: usize::MAX,
            angle: String::new(),
            drawn: 0.0,
            reference: None,
        });
        let mut queue = VecDeque::from([ground]);
        let mut order = 0;
        self.reached[ground] = order;
        for &j in &self.checked.links[ground].clone() {
            if self.places(ground, j) {
                self.placer[j] = Some(ground);
            }
        }
        while let Some(k) = queue.pop_front() {
            self.place_points(k);
            for pass in [true, false] {
                for &j in &self.checked.links[k].clone() {
                    if (self.checked.kind(j) == JointKind::Revolute) != pass {
                        continue;
                    }
                    for &l in &self.checked.joint_links[j].clone() {
                        if self.reached[l] != usize::MAX {
                            continue;
                        }
                        order += 1;
                        self.reached[l] = order;
                        self.enter(k, l, j);
                        queue.push_back(l);
                    }
                }
            }
        }
    }

    /// The points of link `k` not yet placed, from its frame.
    fn place_points(&mut self, k: usize) {
        if k == self.checked.ground {
            return;
        }
        let frame = self.frames[k].clone().expect("visited");
        let (origin, reference) = (frame.origin, frame.reference);
        for &j in &self.checked.links[k].clone() {
            if self.placer[j].is_some() || !self.places(k, j) {
                continue;
            }
            let base = self.position_of(origin);
            let rel = self.relative(k, j, reference);
            let position = Self::offset(&base, &rel, false);
            self.define(k, j, position);
        }
    }

    /// Link `l` reached from link `k` through joint `j`: its frame, and
    /// its origin's point where the link through which it was reached does
    /// not give it.
    fn enter(&mut self, k: usize, l: usize, j: usize) {
        self.entered[l] = Some(j);
        let name = self.checked.link_name(l).to_owned();
        let joints = self.checked.links[l].clone();
        match self.checked.kind(j) {
            JointKind::Prismatic { .. } => {
                // The link slides on k without turning (k its guide, as the
                // two turn together either way); its origin is the joint.
                let guide = self.frames[k].clone().expect("visited");
                let (point, travel) = self.line_point(k, j);
                let world = self.slide_angle(j);
                let gamma = format!("gamma_{}", self.name(j));
                self.frames[l] = Some(Frame {
                    origin: j,
                    angle: Self::sum(&guide.angle, Some(&gamma)),
                    drawn: world,
                    reference: None,
                });
                self.define(l, j, point);
                self.slide(j, travel);
            }
            JointKind::PinInSlot { .. } if self.places(l, j) => {
                // The pin's link, reached from the slot: its origin the pin.
                let (point, travel) = self.line_point(k, j);
                self.define(l, j, point);
                self.slide(j, travel);
                self.free_frame(l, j, &name, &joints);
            }
            JointKind::PinInSlot { .. } => {
                // The slot's link, reached from its pin: an origin of its
                // own, found back from the pin along the slot.
                let Some(&origin) = joints.iter().find(|&&o| o != j && self.places(l, o)) else {
                    return;
                };
                self.free_frame(l, origin, &name, &joints);
                // The line through the origin: the pin at travel s from it.
                let ((x, y), travel) = self.line_point_relative(l, j);
                let pin = self.position_of(j);
                self.define(
                    l,
                    origin,
                    (format!("{} - ({x})", pin.0), format!("{} - ({y})", pin.1)),
                );
                self.slide(j, travel);
            }
            JointKind::Revolute => {
                let driven = self.angle_driver(l);
                let origin = match driven {
                    Some((a, _, _)) => a,
                    None => j,
                };
                self.free_frame(l, origin, &name, &joints);
                if origin != j {
                    // The driven line's origin, back from the joint entered.
                    let reference = self.frames[l].as_ref().and_then(|f| f.reference);
                    let rel = self.relative(l, j, reference);
                    let base = self.position_of(j);
                    let position = Self::offset(&base, &rel, true);
                    self.define(l, origin, position);
                }
            }
        }
    }

    /// The world angle of a slider's or slot's line, as drawn.
    fn slide_angle(&self, joint: usize) -> f64 {
        match self.checked.kind(joint) {
            JointKind::Prismatic { angle } | JointKind::PinInSlot { angle } => angle,
            JointKind::Revolute => 0.0,
        }
    }

    /// A turning frame for link `l` at `origin`: its angle the coordinate
    /// `theta_<l>`, of the line to the driver's joint, or to the first
    /// joint drawn apart from the origin.
    fn free_frame(&mut self, l: usize, origin: usize, name: &str, joints: &[usize]) {
        let driven = self.angle_driver(l);
        let reference = match driven {
            Some((a, b, _)) if a == origin => Some(b),
            _ => joints.iter().copied().find(|&o| {
                o != origin
                    && self.places(l, o)
                    && !self
                        .checked
                        .coincide(self.checked.at(origin), self.checked.at(o))
            }),
        };
        let drawn = match reference {
            Some(r) => self.drawn_angle(origin, r),
            None => joints
                .iter()
                .find(|&&o| self.checked.kind(o) != JointKind::Revolute)
                .map_or(0.0, |&o| self.slide_angle(o)),
        };
        let theta = format!("theta_{name}");
        self.frames[l] = Some(Frame {
            origin,
            angle: theta.clone(),
            drawn,
            reference,
        });
        let value = Value {
            name: theta,
            value: drawn,
            what: match reference {
                Some(r) => format!("the angle of {}→{}", self.name(origin), self.name(r)),
                None => format!("the angle of link `{name}`"),
            },
        };
        self.coordinate(value, driven.map(|(_, _, d)| d));
    }

    /// The vector from the origin of link `l` to the point at travel
    /// `s_<joint>` on its line, and the drawn travel.
    fn line_point_relative(&mut self, l: usize, joint: usize) -> ((String, String), f64) {
        let ((x, y), travel) = self.line_point(l, joint);
        let frame = self.frames[l].clone().expect("visited");
        let (ox, oy) = self.position_of(frame.origin);
        let strip = |text: String, base: &str| {
            text.strip_prefix(&format!("{base} + "))
                .map_or(text.clone(), str::to_owned)
        };
        ((strip(x, &ox), strip(y, &oy)), travel)
    }

    /// A closure equation, of the loop closed at `joint`.
    fn equation(&mut self, joint: usize, text: String) {
        self.out.closure.push(text);
        self.out.closes_at.push(self.name(joint).to_owned());
    }

    /// One loop per joint the tree did not cross, for each link beyond the
    /// one that placed it.
    fn close(&mut self) {
        for j in 0..self.checked.topology.joints.len() {
            let on = self.checked.joint_links[j].clone();
            match self.checked.kind(j) {
                JointKind::Revolute => {
                    let placer = self.placer[j];
                    for &l in &on {
                        if Some(l) == placer || self.entered[l] == Some(j) {
                            continue;
                        }
                        let here = self.position_of(j);
                        let through = self.through(l, j);
                        self.equation(j, format!("{} - ({})", here.0, through.0));
                        self.equation(j, format!("{} - ({})", here.1, through.1));
                    }
                }
                JointKind::Prismatic { .. } | JointKind::PinInSlot { .. } => {
                    let (guide, block) = self.guide(j);
                    if self.entered[guide] == Some(j) || self.entered[block] == Some(j) {
                        continue;
                    }
                    let (point, travel) = self.line_point(guide, j);
                    // The block's (or pin's) point, through its own frame
                    // where another link placed the joint's point.
                    let here = if self.placer[j] == Some(block) {
                        self.position_of(j)
                    } else {
                        self.through(block, j)
                    };
                    self.equation(j, format!("{} - ({})", here.0, point.0));
                    self.equation(j, format!("{} - ({})", here.1, point.1));
                    self.slide(j, travel);
                    if matches!(self.checked.kind(j), JointKind::Prismatic { .. }) {
                        let (g, b) = (
                            self.frames[guide].clone().expect("visited"),
                            self.frames[block].clone().expect("visited"),
                        );
                        let c = self.parameter(
                            format!("c_{}", self.name(j)),
                            {
                                let a = b.drawn - g.drawn;
                                a.sin().atan2(a.cos())
                            },
                            format!("the fixed angle between the links of `{}`", self.name(j)),
                        );
                        let gb = Self::sum(&b.angle, None);
                        let gg = Self::sum(&g.angle, Some(&c));
                        self.equation(j, format!("{gb} - {gg}"));
                    }
                }
            }
        }
    }

    /// The position of joint `j` reached through link `l`'s frame, as text.
    fn through(&mut self, l: usize, j: usize) -> (String, String) {
        let frame = self.frames[l].clone().expect("visited");
        let base = self.position_of(frame.origin);
        let rel = self.relative(l, j, frame.reference);
        Self::offset(&base, &rel, false)
    }

    /// What a picture draws: the frame's pivots, each moving link by its
    /// points, blocks on the frame.
    fn draw(&mut self) {
        let ground = self.checked.ground;
        for (l, joints) in self.checked.links.iter().enumerate() {
            if l == ground {
                continue;
            }
            // Its pins first, then what slides on it; one name a place.
            let mut body: Vec<usize> = Vec::new();
            let pins_first = (joints.iter().copied())
                .filter(|&j| self.checked.kind(j) == JointKind::Revolute)
                .chain(
                    joints
                        .iter()
                        .copied()
                        .filter(|&j| self.checked.kind(j) != JointKind::Revolute),
                );
            for j in pins_first {
                // A slider's or a slot's point lies on its guide's line too.
                let apart = body.iter().all(|&b| {
                    !self
                        .checked
                        .coincide(self.checked.at(b), self.checked.at(j))
                });
                if self.placer[j].is_some() && apart {
                    body.push(j);
                }
            }
            let body: Vec<String> = body.iter().map(|&j| self.name(j).to_owned()).collect();
            if body.len() >= 2 {
                self.out.bodies.push(body);
            }
        }
        for j in 0..self.checked.topology.joints.len() {
            if self.checked.kind(j) == JointKind::Revolute {
                continue;
            }
            let (guide, block) = self.guide(j);
            // The block drawn at the block's pin where one is drawn there.
            let at = self.checked.at(j);
            let pin = (self.checked.links[block].iter().copied()).find(|&p| {
                p != j
                    && self.checked.kind(p) == JointKind::Revolute
                    && self.placer[p].is_some()
                    && self.checked.coincide(self.checked.at(p), at)
            });
            let point = self.name(pin.unwrap_or(j)).to_owned();
            if guide == ground {
                self.out.ground_sliders.push((point, self.slide_angle(j)));
                continue;
            }
            // On a moving guide: along two of its points on the line.
            let line = self.slide_angle(j);
            let on_line = |a: usize, b: usize| {
                let d = self.drawn_angle(a, b) - line;
                d.sin().abs() < 1e-9
                    && !self
                        .checked
                        .coincide(self.checked.at(a), self.checked.at(b))
            };
            let points: Vec<usize> = (self.checked.links[guide].iter().copied())
                .filter(|&p| {
                    p != j
                        && self.placer[p].is_some()
                        && self.checked.kind(p) == JointKind::Revolute
                })
                .collect();
            let pair = points.iter().enumerate().find_map(|(k, &a)| {
                points[k + 1..]
                    .iter()
                    .find(|&&b| on_line(a, b))
                    .map(|&b| [a, b])
            });
            if let Some([a, b]) = pair {
                let names = [self.name(a).to_owned(), self.name(b).to_owned()];
                self.out.along_sliders.push((point, names));
            }
        }
    }
}

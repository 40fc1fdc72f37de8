//! A mechanism as an engineer draws it: joints at drawn positions, links
//! listing the joints they carry, and what drives it.

/// What a joint lets the links it joins do.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum JointKind {
    /// A pin: every link it joins turns about it. On one link only, it is
    /// a named point of that link (a coupler point).
    Revolute,
    /// A slider: its two links slide on each other along the line through
    /// the joint at `angle` (from the x axis, in radians, as drawn), and
    /// turn together.
    Prismatic { angle: f64 },
    /// A pin in a slot: the pin, on one of its two links, runs in a
    /// straight slot of the other (the joint's guide), through the joint at
    /// `angle` (as drawn), and turns in it.
    PinInSlot { angle: f64 },
}

/// A joint, where it is drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// Its name: an identifier of the equations (it names the joint's point).
    pub name: String,
    pub kind: JointKind,
    /// Where it is drawn, in the topology's length unit.
    pub at: [f64; 2],
    /// A slider's or a slot's guide: the link that carries the line (the
    /// first of its two links in the topology's order when not said).
    pub guide: Option<String>,
}

/// A rigid link and the joints it carries, in order (a binary link's two,
/// a plate's three or more). The ground link is the frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// Its name: an identifier of the equations (it names the link's angle,
    /// `theta_<name>`).
    pub name: String,
    pub joints: Vec<String>,
}

/// What a driver moves.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Driven {
    /// The angle of the line from joint `from` to joint `to`, both on one
    /// link, from the x axis (a crank's angle, when `from` is its ground
    /// pivot).
    Angle { from: String, to: String },
    /// The travel along a prismatic joint or a slot (a linear actuator).
    Slide { joint: String },
}

/// A driver: what it moves and over which range; ranges and rates in the
/// engine's units (radians, lengths in the topology's unit, per second).
#[derive(Clone, Debug, PartialEq)]
pub struct Driver {
    pub driven: Driven,
    /// The sweep's range; an angle's is a turn from the drawn angle when
    /// not given. A slide must give it.
    pub range: Option<[f64; 2]>,
    /// The sweep's steps (as a mechanism file's `steps`), 360 when not given.
    pub steps: Option<usize>,
    /// The rate v̇ (1 when not given).
    pub rate: Option<f64>,
    /// The pose one analysis takes; the drawn value when not given.
    pub at: Option<f64>,
}

/// A mechanism given by its joints and links: see the [module](super).
#[derive(Clone, Debug, PartialEq)]
pub struct Topology {
    /// The mechanism's name: an identifier (a Rust type's name).
    pub name: String,
    /// Free text for pictures and tables.
    pub title: Option<String>,
    /// The unit of lengths: `m`, `mm`, `cm`, `in` or `ft`.
    pub length_unit: String,
    pub joints: Vec<Joint>,
    pub links: Vec<Link>,
    /// The name of the link that is the frame (`ground` unless said).
    pub ground: String,
    pub drivers: Vec<Driver>,
    /// Lengths given rather than read from the drawing: (joint, joint,
    /// length) on the link that carries both. The drawing is then a sketch
    /// that picks the assembly, and need not close.
    pub lengths: Vec<(String, String, f64)>,
    /// Points whose paths a picture traces.
    pub trace: Vec<String>,
}

impl Topology {
    /// An empty topology named `name`, lengths in metres, the frame
    /// `ground`.
    pub fn new(name: &str) -> Topology {
        Topology {
            name: name.to_owned(),
            title: None,
            length_unit: "m".to_owned(),
            joints: Vec::new(),
            links: Vec::new(),
            ground: "ground".to_owned(),
            drivers: Vec::new(),
            lengths: Vec::new(),
            trace: Vec::new(),
        }
    }

    /// With this title.
    pub fn title(mut self, title: &str) -> Topology {
        self.title = Some(title.to_owned());
        self
    }

    /// With lengths in this unit (`m`, `mm`, `cm`, `in`, `ft`).
    pub fn length_unit(mut self, unit: &str) -> Topology {
        self.length_unit = unit.to_owned();
        self
    }

    /// With a pin (or a named point, on one link) drawn at `at`.
    pub fn revolute(self, name: &str, at: [f64; 2]) -> Topology {
        self.joint(name, JointKind::Revolute, at)
    }

    /// With a slider drawn at `at`, sliding along `angle` (radians).
    pub fn prismatic(self, name: &str, at: [f64; 2], angle: f64) -> Topology {
        self.joint(name, JointKind::Prismatic { angle }, at)
    }

    /// With a pin in a slot drawn at `at`, the slot along `angle`
    /// (radians).
    pub fn pin_in_slot(self, name: &str, at: [f64; 2], angle: f64) -> Topology {
        self.joint(name, JointKind::PinInSlot { angle }, at)
    }

    /// With a joint of any kind.
    pub fn joint(mut self, name: &str, kind: JointKind, at: [f64; 2]) -> Topology {
        self.joints.push(Joint {
            name: name.to_owned(),
            kind,
            at,
            guide: None,
        });
        self
    }

    /// With the slider or slot `joint`'s line on `link`.
    pub fn guide(mut self, joint: &str, link: &str) -> Topology {
        if let Some(j) = self.joints.iter_mut().find(|j| j.name == joint) {
            j.guide = Some(link.to_owned());
        }
        self
    }

    /// With a link carrying these joints.
    pub fn link(mut self, name: &str, joints: &[&str]) -> Topology {
        self.links.push(Link {
            name: name.to_owned(),
            joints: joints.iter().map(|j| (*j).to_owned()).collect(),
        });
        self
    }

    /// With the frame called `name` rather than `ground`.
    pub fn ground(mut self, name: &str) -> Topology {
        self.ground = name.to_owned();
        self
    }

    /// Driven by the angle of the line `from` → `to`, over a turn from its
    /// drawn value.
    pub fn drive_angle(self, from: &str, to: &str) -> Topology {
        self.drive(Driver {
            driven: Driven::Angle {
                from: from.to_owned(),
                to: to.to_owned(),
            },
            range: None,
            steps: None,
            rate: None,
            at: None,
        })
    }

    /// Driven by the travel along the slider or slot `joint`, over
    /// `range`.
    pub fn drive_slide(self, joint: &str, range: [f64; 2]) -> Topology {
        self.drive(Driver {
            driven: Driven::Slide {
                joint: joint.to_owned(),
            },
            range: Some(range),
            steps: None,
            rate: None,
            at: None,
        })
    }

    /// With a driver.
    pub fn drive(mut self, driver: Driver) -> Topology {
        self.drivers.push(driver);
        self
    }

    /// With the distance between joints `a` and `b` (on one link) given,
    /// not read from the drawing.
    pub fn length(mut self, a: &str, b: &str, length: f64) -> Topology {
        self.lengths.push((a.to_owned(), b.to_owned(), length));
        self
    }

    /// Tracing the path of `point`.
    pub fn trace(mut self, point: &str) -> Topology {
        self.trace.push(point.to_owned());
        self
    }
}

//! What can be wrong with a topology, each mistake naming its culprit.

use std::fmt;

/// A mistake in a topology: a name, a joint or link, a loop or a driver
/// that cannot be.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum TopologyError {
    /// A name the equations cannot use (the reason given).
    BadName { name: String, why: String },
    /// Two joints, two links, or a joint and a link with one name.
    DuplicateName { name: String },
    /// A generated name (`theta_<link>`, `l_<a>_<b>`, …) that is also a
    /// joint's or a link's name.
    NameClash { name: String },
    /// No link of the frame's name.
    NoGround { ground: String },
    /// A link lists a joint that is not defined.
    UnknownJoint { link: String, joint: String },
    /// A link lists a joint twice.
    JointTwice { link: String, joint: String },
    /// A joint that no link lists.
    JointOnNoLink { joint: String },
    /// A link that lists no joint.
    EmptyLink { link: String },
    /// A slider's or a slot's guide that is not one of its links.
    BadGuide { joint: String, link: String },
    /// A slider or a slot not on exactly two links.
    SliderLinks { joint: String, links: usize },
    /// A position or an angle that is not a finite number.
    NotFinite { what: String },
    /// Links that no chain of joints connects to the frame.
    Disconnected { links: Vec<String> },
    /// Two joints of one link drawn at one place, where the link's angle
    /// or length needs them apart.
    CoincidentPins { link: String, joints: [String; 2] },
    /// A link that only one joint holds and nothing drives: it turns
    /// freely.
    Dangling { link: String, joint: String },
    /// Two links joined by two pins are one rigid body.
    RigidPair {
        links: [String; 2],
        joints: [String; 2],
    },
    /// The degrees of freedom (Grübler–Kutzbach) and the drivers disagree.
    Mobility {
        mobility: i64,
        drivers: usize,
        links: usize,
        full_joints: usize,
        half_joints: usize,
    },
    /// A loop of links that cannot move at all: over-constrained.
    RigidLoop { links: Vec<String> },
    /// A driver names a joint that is not defined.
    UnknownDriverJoint { joint: String },
    /// An angle driver whose two joints no moving link carries.
    DriverNotOnOneLink { from: String, to: String },
    /// An angle driver on a link that slides without turning.
    DrivenLinkLocked { link: String, joint: String },
    /// A slide driver on a joint that is not a slider or a slot.
    NotASlide { joint: String },
    /// A slide driver without its range.
    SlideWithoutRange { joint: String },
    /// Two drivers of one motion.
    DrivenTwice { what: String },
    /// A length given between joints no link carries together, or not
    /// positive.
    BadLength {
        from: String,
        to: String,
        why: String,
    },
    /// A driver's range of zero length, or its steps out of range.
    BadDrive { why: String },
    /// No driver, and no degree of freedom: a structure, not a mechanism.
    NoDriver,
    /// Every coordinate driven: nothing is left to solve for.
    NothingDepends,
    /// A point to trace that is no joint.
    UnknownTrace { name: String },
    /// A point traced twice.
    TracedTwice { name: String },
    /// The length unit is none of `m`, `mm`, `cm`, `in`, `ft`.
    BadUnit { unit: String },
    /// The generated mechanism file did not read: a fault of this
    /// library, reported rather than hidden.
    Generated { why: String },
}

impl fmt::Display for TopologyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use TopologyError::*;
        match self {
            BadName { why, .. } => write!(f, "{why}"),
            DuplicateName { name } => write!(
                f,
                "`{name}` names two things: each joint and link needs its own name"
            ),
            NameClash { name } => write!(
                f,
                "`{name}` is a joint's or a link's name and also a name the equations generate: rename it"
            ),
            NoGround { ground } => write!(
                f,
                "no link is named `{ground}`, the frame: list the fixed pivots on a link of that name"
            ),
            UnknownJoint { link, joint } => {
                write!(f, "link `{link}` lists `{joint}`, which is no joint")
            }
            JointTwice { link, joint } => write!(f, "link `{link}` lists `{joint}` twice"),
            JointOnNoLink { joint } => write!(
                f,
                "joint `{joint}` is on no link: list it on the links it joins"
            ),
            EmptyLink { link } => write!(f, "link `{link}` carries no joint"),
            BadGuide { joint, link } => write!(
                f,
                "the guide of `{joint}` is `{link}`, which is not one of the links it joins"
            ),
            SliderLinks { joint, links } => write!(
                f,
                "slider `{joint}` is on {links} link(s): a slider or a slot joins exactly two links, its guide listed first"
            ),
            NotFinite { what } => write!(f, "{what} is not a finite number"),
            Disconnected { links } => write!(
                f,
                "no chain of joints connects {} to the frame",
                quoted(links)
            ),
            CoincidentPins { link, joints } => write!(
                f,
                "joints `{}` and `{}` of link `{link}` are drawn at one place: the link's length or angle needs them apart",
                joints[0], joints[1]
            ),
            Dangling { link, joint } => write!(
                f,
                "link `{link}` is held by joint `{joint}` alone and nothing drives it: it turns freely"
            ),
            RigidPair { links, joints } => write!(
                f,
                "links `{}` and `{}` are joined by two pins, `{}` and `{}`: they are one rigid body — make them one link",
                links[0], links[1], joints[0], joints[1]
            ),
            Mobility {
                mobility,
                drivers,
                links,
                full_joints,
                half_joints,
            } => write!(
                f,
                "the mechanism has {mobility} degree(s) of freedom (Grübler–Kutzbach: 3·({links} − 1) − 2·{full_joints} − {half_joints} = {mobility}) and {drivers} driver(s): {}",
                if *mobility > *drivers as i64 {
                    format!(
                        "drive {} more motion(s), or join the free links",
                        *mobility - *drivers as i64
                    )
                } else if *mobility < 0 {
                    "it is over-constrained: remove a joint or a link from a loop that cannot move"
                        .to_owned()
                } else {
                    format!(
                        "{} driver(s) too many for its motion",
                        *drivers as i64 - *mobility
                    )
                }
            ),
            RigidLoop { links } => write!(
                f,
                "the loop of links {} cannot move (a truss): the mechanism is over-constrained there",
                quoted(links)
            ),
            UnknownDriverJoint { joint } => {
                write!(f, "a driver names `{joint}`, which is no joint")
            }
            DriverNotOnOneLink { from, to } => write!(
                f,
                "the driver of the angle `{from}` → `{to}` needs both joints on one moving link"
            ),
            DrivenLinkLocked { link, joint } => write!(
                f,
                "link `{link}` slides on slider `{joint}` without turning: its angle cannot be driven"
            ),
            NotASlide { joint } => write!(
                f,
                "joint `{joint}` is not a slider or a slot: only a slide can be driven along"
            ),
            SlideWithoutRange { joint } => {
                write!(f, "the slide along `{joint}` is driven without a range")
            }
            DrivenTwice { what } => write!(f, "{what} is driven twice"),
            BadLength { from, to, why } => write!(f, "the length `{from}`–`{to}`: {why}"),
            BadUnit { unit } => write!(f, "`{unit}` is not a length unit: m, mm, cm, in or ft"),
            BadDrive { why } => write!(f, "a driver: {why}"),
            NoDriver => f.write_str(
                "nothing drives it, and it cannot move (0 degrees of freedom): a structure, not a mechanism",
            ),
            NothingDepends => f.write_str(
                "every coordinate is driven: nothing is left to solve for (drive fewer, or join more links)",
            ),
            TracedTwice { name } => write!(f, "`{name}` is traced twice"),
            UnknownTrace { name } => write!(f, "`{name}` is traced but is no joint"),
            Generated { why } => write!(
                f,
                "the generated mechanism file does not read (a fault of linkage): {why}"
            ),
        }
    }
}

impl std::error::Error for TopologyError {}

/// Every mistake of a topology, in the order found.
#[derive(Clone, Debug, PartialEq)]
pub struct TopologyErrors {
    pub errors: Vec<TopologyError>,
}

impl fmt::Display for TopologyErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, error) in self.errors.iter().enumerate() {
            if k > 0 {
                writeln!(f)?;
            }
            write!(f, "{error}")?;
        }
        Ok(())
    }
}

impl std::error::Error for TopologyErrors {}

impl From<TopologyError> for TopologyErrors {
    fn from(error: TopologyError) -> TopologyErrors {
        TopologyErrors {
            errors: vec![error],
        }
    }
}

/// `a`, `b` and `c`.
fn quoted(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    match quoted.len() {
        0 => String::new(),
        1 => quoted[0].clone(),
        n => format!("{} and {}", quoted[..n - 1].join(", "), quoted[n - 1]),
    }
}

//! pyslvs's mechanism expressions, read into a topology and written back.
//!
//! pyslvs (Yuan Chang's Python kernel of Pyslvs-UI) writes a mechanism as
//! `M[J[R, color[Green], P[0.0, 0.0], L[ground, L1]], J[RP, A[30.0], …], …]`:
//! one `J[…]` per joint, numbered from 0 in order, each with its type (`R`
//! a pin, `P` a slider, `RP` a pin in a slot), for `P` and `RP` the slot's
//! angle `A[deg]` (from the x axis, as drawn), its colour, its drawn
//! position `P[x, y]` and the links it joins `L[…]`, the frame named
//! `ground`. Of a slider's links the first carries the slot, the others
//! the pin. Its inputs are pairs of joints (base, drive): the angle of
//! the line base → drive, from the x axis.
//!
//! Read here, joint i is `J<i>`, lengths are millimetres (as Pyslvs-UI
//! draws them). A pin in a slot on more than one pin link
//! is the slot on the first (`J<i>`) and a pin `J<i>_pin` joining the
//! pin's links; a slider whose block is more than one link, or an input
//! whose two joints no moving link carries, is not representable and is
//! refused with the reason.

use super::model::{JointKind, Topology};
use std::fmt;

/// Why an expression was not read.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PyslvsError {
    /// The text is not an expression: the byte where it goes wrong.
    Syntax { at: usize, why: String },
    /// The expression is well formed, but not a mechanism linkage can
    /// take as it is (the reason given).
    Unrepresentable { why: String },
}

impl fmt::Display for PyslvsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PyslvsError::Syntax { at, why } => write!(f, "at byte {at}: {why}"),
            PyslvsError::Unrepresentable { why } => f.write_str(why),
        }
    }
}

impl std::error::Error for PyslvsError {}

/// A joint as the expression writes it.
#[derive(Clone, Debug, PartialEq)]
pub struct PyslvsJoint {
    /// `R`, `P` or `RP`.
    pub kind: String,
    /// The slot's angle in degrees (`P`, `RP`).
    pub angle: Option<f64>,
    /// The colour as written (a name or `(r, g, b)`).
    pub color: Option<String>,
    pub at: [f64; 2],
    pub links: Vec<String>,
}

/// Reads an expression's joints.
pub fn parse_expression(text: &str) -> Result<Vec<PyslvsJoint>, PyslvsError> {
    let mut p = Parser { text, at: 0 };
    p.skip();
    p.expect("M")?;
    p.expect("[")?;
    let mut joints = Vec::new();
    loop {
        p.skip();
        if p.eat("]") {
            break;
        }
        joints.push(p.joint()?);
        p.skip();
        if p.eat(",") {
            continue;
        }
        p.expect("]")?;
        break;
    }
    p.skip();
    if p.at < text.len() {
        return Err(p.error("text after the expression's closing `]`"));
    }
    Ok(joints)
}

struct Parser<'t> {
    text: &'t str,
    at: usize,
}

impl<'t> Parser<'t> {
    fn rest(&self) -> &'t str {
        &self.text[self.at..]
    }

    fn error(&self, why: &str) -> PyslvsError {
        PyslvsError::Syntax {
            at: self.at,
            why: why.to_owned(),
        }
    }

    /// Spaces, `# …` to the end of the line and `#[ … #]`.
    fn skip(&mut self) {
        loop {
            let rest = self.rest();
            let trimmed = rest.trim_start();
            self.at += rest.len() - trimmed.len();
            if let Some(block) = trimmed.strip_prefix("#[") {
                let end = block.find("#]").map_or(block.len(), |k| k + 2);
                self.at += 2 + end;
            } else if trimmed.starts_with('#') {
                let end = trimmed.find('\n').unwrap_or(trimmed.len());
                self.at += end;
            } else {
                return;
            }
        }
    }

    fn eat(&mut self, token: &str) -> bool {
        self.skip();
        if self.rest().starts_with(token) {
            self.at += token.len();
            true
        } else {
            false
        }
    }

    fn expect(&mut self, token: &str) -> Result<(), PyslvsError> {
        if self.eat(token) {
            Ok(())
        } else {
            Err(self.error(&format!("expected `{token}`")))
        }
    }

    fn name(&mut self) -> Result<String, PyslvsError> {
        self.skip();
        let rest = self.rest();
        let len = rest
            .char_indices()
            .find(|&(k, c)| !(c == '_' || c.is_ascii_alphabetic() || (k > 0 && c.is_ascii_digit())))
            .map_or(rest.len(), |(k, _)| k);
        if len == 0 {
            return Err(self.error("expected a name"));
        }
        self.at += len;
        Ok(rest[..len].to_owned())
    }

    fn number(&mut self) -> Result<f64, PyslvsError> {
        self.skip();
        let rest = self.rest();
        let len = rest
            .char_indices()
            .find(|&(k, c)| {
                !(c.is_ascii_digit()
                    || c == '.'
                    || c == 'e'
                    || c == 'E'
                    || ((c == '-' || c == '+')
                        && (k == 0 || matches!(rest.as_bytes()[k - 1], b'e' | b'E'))))
            })
            .map_or(rest.len(), |(k, _)| k);
        let value: f64 = rest[..len]
            .parse()
            .map_err(|_| self.error("expected a number"))?;
        if !value.is_finite() {
            return Err(self.error("a number that is not finite"));
        }
        self.at += len;
        Ok(value)
    }

    /// `J[type, A[deg]?, color[…]?, P[x, y], L[names]]`.
    fn joint(&mut self) -> Result<PyslvsJoint, PyslvsError> {
        self.expect("J")?;
        self.expect("[")?;
        let kind = self.name()?;
        if !matches!(kind.as_str(), "R" | "P" | "RP") {
            return Err(self.error(&format!("`{kind}` is no joint type: R, P or RP")));
        }
        let mut joint = PyslvsJoint {
            kind,
            angle: None,
            color: None,
            at: [0.0; 2],
            links: Vec::new(),
        };
        let mut position = false;
        while self.eat(",") {
            self.skip();
            let field = self.rest();
            if field.starts_with("A[") {
                self.expect("A")?;
                self.expect("[")?;
                joint.angle = Some(self.number()?);
                self.expect("]")?;
            } else if field.starts_with("color[") {
                self.at += "color[".len();
                let close = self
                    .rest()
                    .find(']')
                    .ok_or_else(|| self.error("a colour without its `]`"))?;
                joint.color = Some(self.rest()[..close].trim().to_owned());
                self.at += close + 1;
            } else if field.starts_with("P[") {
                self.expect("P")?;
                self.expect("[")?;
                let x = self.number()?;
                self.expect(",")?;
                let y = self.number()?;
                self.expect("]")?;
                joint.at = [x, y];
                position = true;
            } else if field.starts_with("L[") {
                self.expect("L")?;
                self.expect("[")?;
                while !self.eat("]") {
                    joint.links.push(self.name()?);
                    if !self.eat(",") {
                        self.expect("]")?;
                        break;
                    }
                }
            } else {
                return Err(self.error("expected `A[…]`, `color[…]`, `P[x, y]` or `L[…]`"));
            }
        }
        self.expect("]")?;
        if !position {
            return Err(self.error("a joint without its position `P[x, y]`"));
        }
        if joint.kind != "R" && joint.angle.is_none() {
            return Err(self.error("a slider without its angle `A[deg]`"));
        }
        Ok(joint)
    }
}

/// The topology of an expression driven by `inputs` (pairs of joint
/// numbers, the angle of base → drive), named `name`.
pub fn from_pyslvs(
    name: &str,
    expression: &str,
    inputs: &[(usize, usize)],
) -> Result<Topology, PyslvsError> {
    let joints = parse_expression(expression)?;
    let unrepresentable = |why: String| PyslvsError::Unrepresentable { why };
    // pyslvs draws in millimetres.
    let mut topology = Topology::new(name).length_unit("mm");
    // The links in order of first mention, the frame as `ground`.
    let mut links: Vec<(String, Vec<String>)> = Vec::new();
    let mut carry = |link: &str, joint: String| match links.iter_mut().find(|(n, _)| n == link) {
        Some((_, joints)) => joints.push(joint),
        None => links.push((link.to_owned(), vec![joint])),
    };
    for (i, joint) in joints.iter().enumerate() {
        let name = format!("J{i}");
        let angle = joint.angle.unwrap_or(0.0).to_radians();
        match (joint.kind.as_str(), &joint.links[..]) {
            ("R", on) => {
                topology = topology.revolute(&name, joint.at);
                for link in on {
                    carry(link, name.clone());
                }
            }
            (_, [] | [_]) => {
                return Err(unrepresentable(format!(
                    "joint {i} is a slider on {} link(s): a slider joins a slot's link and a pin's",
                    joint.links.len()
                )));
            }
            ("P", [slot, block]) => {
                topology = topology
                    .prismatic(&name, joint.at, angle)
                    .guide(&name, slot);
                carry(slot, name.clone());
                carry(block, name);
            }
            ("P", _) => {
                return Err(unrepresentable(format!(
                    "joint {i} is a slider whose block is {} links: linkage takes a block of one link",
                    joint.links.len() - 1
                )));
            }
            (_, [slot, pins @ ..]) => {
                topology = topology
                    .pin_in_slot(&name, joint.at, angle)
                    .guide(&name, slot);
                carry(slot, name.clone());
                carry(&pins[0], name.clone());
                if pins.len() > 1 {
                    let pin = format!("{name}_pin");
                    topology = topology.revolute(&pin, joint.at);
                    for link in pins {
                        carry(link, pin.clone());
                    }
                }
            }
        }
    }
    if !links.iter().any(|(n, _)| n == "ground") {
        return Err(unrepresentable(
            "no joint is on `ground`, the frame".to_owned(),
        ));
    }
    for (link, joints) in &links {
        let joints: Vec<&str> = joints.iter().map(String::as_str).collect();
        topology = topology.link(link, &joints);
    }
    for &(base, drive) in inputs {
        if base >= joints.len() || drive >= joints.len() {
            return Err(unrepresentable(format!(
                "the input ({base}, {drive}) names a joint the expression does not have ({} joints)",
                joints.len()
            )));
        }
        if base == drive {
            return Err(unrepresentable(format!(
                "the input ({base}, {drive}) drives nothing: its base and its drive are one joint"
            )));
        }
        topology = topology.drive_angle(&format!("J{base}"), &format!("J{drive}"));
    }
    Ok(topology)
}

/// The expression of a topology whose joints pyslvs can write (pins,
/// sliders and pins in slots on two links), and its inputs: joints
/// numbered in order (the `_pin` half of a pin in a slot merged back into
/// its slot), colours as read or `Green`.
pub fn to_pyslvs(topology: &Topology) -> Result<(String, Vec<(usize, usize)>), PyslvsError> {
    let unrepresentable = |why: String| PyslvsError::Unrepresentable { why };
    let on = |joint: &str| -> Vec<String> {
        (topology.links.iter())
            .filter(|l| l.joints.iter().any(|j| j == joint))
            .map(|l| {
                if l.name == topology.ground {
                    "ground".to_owned()
                } else {
                    l.name.clone()
                }
            })
            .collect()
    };
    let written: Vec<&super::model::Joint> = (topology.joints.iter())
        .filter(|j| {
            !(j.name.ends_with("_pin")
                && topology
                    .joints
                    .iter()
                    .any(|s| s.name == j.name[..j.name.len() - 4]))
        })
        .collect();
    let mut parts = Vec::new();
    for joint in &written {
        let mut links = on(&joint.name);
        if let Some(guide) = &joint.guide {
            let guide = if *guide == topology.ground {
                "ground"
            } else {
                guide.as_str()
            };
            if let Some(k) = links.iter().position(|l| l == guide) {
                links[..=k].rotate_right(1);
            }
        }
        let (kind, angle) = match joint.kind {
            JointKind::Revolute => ("R", None),
            JointKind::Prismatic { angle } => ("P", Some(angle)),
            JointKind::PinInSlot { angle } => {
                // The pin's other links, from its `_pin` half.
                for extra in on(&format!("{}_pin", joint.name)) {
                    if !links.contains(&extra) {
                        links.push(extra);
                    }
                }
                ("RP", Some(angle))
            }
        };
        let angle = angle.map_or(String::new(), |a| format!("A[{}], ", degrees(a)));
        parts.push(format!(
            "J[{kind}, {angle}color[Green], P[{}, {}], L[{}]]",
            super::generate::number(joint.at[0]),
            super::generate::number(joint.at[1]),
            links.join(", ")
        ));
    }
    let index = |name: &str| written.iter().position(|j| j.name == name);
    let mut inputs = Vec::new();
    for driver in &topology.drivers {
        match &driver.driven {
            super::model::Driven::Angle { from, to } => match (index(from), index(to)) {
                (Some(a), Some(b)) => inputs.push((a, b)),
                _ => {
                    return Err(unrepresentable(format!(
                        "the driver {from} → {to} names a joint that is not written"
                    )));
                }
            },
            super::model::Driven::Slide { joint } => {
                return Err(unrepresentable(format!(
                    "pyslvs's inputs are angles: the slide along `{joint}` is not one"
                )));
            }
        }
    }
    Ok((format!("M[{}]", parts.join(", ")), inputs))
}

/// An angle in degrees, in the fewest decimals that read back to the same
/// radians (`30.0`, not `29.999999999999996`).
fn degrees(radians: f64) -> String {
    let degrees = radians.to_degrees();
    (1..=17)
        .map(|decimals| format!("{degrees:.decimals$}"))
        .find(|text| text.parse::<f64>().is_ok_and(|d| d.to_radians() == radians))
        .unwrap_or_else(|| super::generate::number(degrees))
}

//! A topology written as a topology file ([`crate::file::TopologyFile`]):
//! what an importer hands to a user to keep. Numbers are written so that
//! they read back to the same f64 (angles in radians, as bare numbers,
//! with their degrees in a comment).

use super::generate::number;
use super::model::{Driven, JointKind, Topology};
use std::fmt::Write;

/// The topology file of `topology`.
pub(super) fn topology_file(topology: &Topology) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "name = {}", quote(&topology.name));
    if let Some(title) = &topology.title {
        let _ = writeln!(out, "title = {}", quote(title));
    }
    let _ = writeln!(out, "length_unit = {}", quote(&topology.length_unit));
    if topology.ground != "ground" {
        let _ = writeln!(out, "ground = {}", quote(&topology.ground));
    }
    if !topology.trace.is_empty() {
        let _ = writeln!(out, "trace = {}", list(&topology.trace));
    }
    out.push_str("\n[joints]\n");
    for joint in &topology.joints {
        let at = format!("[{}, {}]", number(joint.at[0]), number(joint.at[1]));
        let line = match joint.kind {
            JointKind::Revolute => at,
            JointKind::Prismatic { angle } | JointKind::PinInSlot { angle } => {
                let key = if matches!(joint.kind, JointKind::Prismatic { .. }) {
                    "slider"
                } else {
                    "slot"
                };
                let guide = (joint.guide.as_ref())
                    .map_or(String::new(), |g| format!(", guide = {}", quote(g)));
                format!(
                    "{{ at = {at}, {key} = {}{guide} }}   # {}°",
                    number(angle),
                    angle.to_degrees()
                )
            }
        };
        let _ = writeln!(out, "{} = {line}", joint.name);
    }
    out.push_str("\n[links]\n");
    for link in &topology.links {
        let _ = writeln!(out, "{} = {}", link.name, list(&link.joints));
    }
    for driver in &topology.drivers {
        out.push_str("\n[[drive]]\n");
        match &driver.driven {
            Driven::Angle { from, to } => {
                let _ = writeln!(out, "angle = {}", list(&[from.clone(), to.clone()]));
            }
            Driven::Slide { joint } => {
                let _ = writeln!(out, "slide = {}", quote(joint));
            }
        }
        if let Some([from, to]) = driver.range {
            let _ = writeln!(out, "from = {}\nto = {}", number(from), number(to));
        }
        if let Some(steps) = driver.steps {
            let _ = writeln!(out, "steps = {steps}");
        }
        if let Some(rate) = driver.rate {
            let _ = writeln!(out, "rate = {}", number(rate));
        }
        if let Some(at) = driver.at {
            let _ = writeln!(out, "at = {}", number(at));
        }
    }
    if !topology.lengths.is_empty() {
        out.push_str("\n[lengths]\n");
        for (a, b, length) in &topology.lengths {
            let _ = writeln!(out, "{a}-{b} = {}", number(*length));
        }
    }
    out
}

fn list(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| quote(n)).collect();
    format!("[{}]", quoted.join(", "))
}

/// A TOML basic string.
pub(super) fn quote(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

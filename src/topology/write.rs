//! The generated mechanism written as a mechanism file: what a user keeps,
//! and what the file reader then reads like any other.

use super::check::Checked;
use super::generate::{Generated, number};
use super::save::quote;
use std::f64::consts::TAU;
use std::fmt::Write;

/// The mechanism file of a generated topology.
pub(super) fn mechanism_file(checked: &Checked<'_>, generated: &Generated) -> String {
    let topology = checked.topology;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Generated from a topology of {} joints and {} links: each link's angle\n# (theta_<link>) or a slider's travel (s_<joint>) a coordinate, lengths\n# (l_<a>_<b>) and angles (a_<a>_<b>) read from the drawing.",
        topology.joints.len(),
        topology.links.len()
    );
    let _ = writeln!(out, "name = {}", quote(&topology.name));
    if let Some(title) = &topology.title {
        let _ = writeln!(out, "title = {}", quote(title));
    }
    let _ = writeln!(out, "length_unit = {}", quote(&topology.length_unit));
    out.push_str("equations = '''\n");
    let names = |values: &mut dyn Iterator<Item = &str>| values.collect::<Vec<_>>().join(", ");
    let _ = writeln!(
        out,
        "u = [{}],",
        names(&mut generated.u.iter().map(|v| v.name.as_str()))
    );
    let _ = writeln!(
        out,
        "v = [{}],",
        names(&mut generated.v.iter().map(|(v, _)| v.name.as_str()))
    );
    if !generated.points.is_empty() {
        out.push_str("points = [\n");
        for (name, x, y) in &generated.points {
            let _ = writeln!(out, "    {name} = ({x}, {y}),");
        }
        out.push_str("],\n");
    }
    out.push_str("closure = [\n");
    for equation in &generated.closure {
        let _ = writeln!(out, "    {equation},");
    }
    out.push_str("],\n'''\n\n[parameters]\n");
    for p in &generated.parameters {
        let _ = writeln!(out, "{} = {}   # {}", p.name, number(p.value), p.what);
    }
    for (value, d) in &generated.v {
        let driver = &topology.drivers[*d];
        let angle = value.name.starts_with("theta_");
        let [from, to] = driver.range.unwrap_or(if angle {
            [value.value, value.value + TAU]
        } else {
            [value.value, value.value]
        });
        let _ = writeln!(out, "\n[drive.{}]   # {}", value.name, value.what);
        let _ = writeln!(out, "from = {}", number(from));
        let _ = writeln!(out, "to = {}", number(to));
        let _ = writeln!(out, "steps = {}", driver.steps.unwrap_or(360));
        let _ = writeln!(out, "rate = {}", number(driver.rate.unwrap_or(1.0)));
        let _ = writeln!(out, "at = {}", number(driver.at.unwrap_or(value.value)));
    }
    if !generated.u.is_empty() {
        out.push_str("\n[assembly]\n# The drawn assembly.\nnear = { ");
        let sketch: Vec<String> = (generated.u.iter())
            .map(|v| format!("{} = {}", v.name, number(v.value)))
            .collect();
        out.push_str(&sketch.join(", "));
        out.push_str(" }\n");
    }
    out.push_str("\n[drawing]\nground = { ");
    let pivots: Vec<String> = (generated.ground.iter())
        .map(|(n, [x, y])| format!("{n} = [{}, {}]", number(*x), number(*y)))
        .collect();
    out.push_str(&pivots.join(", "));
    out.push_str(" }\n");
    let list = |names: &[String]| {
        let quoted: Vec<String> = names.iter().map(|n| quote(n)).collect();
        format!("[{}]", quoted.join(", "))
    };
    let links: Vec<String> = (generated.bodies.iter())
        .filter(|b| b.len() == 2)
        .map(|b| list(b))
        .collect();
    let plates: Vec<String> = (generated.bodies.iter())
        .filter(|b| b.len() > 2)
        .map(|b| list(b))
        .collect();
    let _ = writeln!(out, "links = [{}]", links.join(", "));
    if !plates.is_empty() {
        let _ = writeln!(out, "plates = [{}]", plates.join(", "));
    }
    let mut sliders: Vec<String> = (generated.ground_sliders.iter())
        .map(|(point, angle)| format!("{{ point = {}, angle = {} }}", quote(point), number(*angle)))
        .collect();
    sliders.extend(
        (generated.along_sliders.iter()).map(|(point, along)| {
            format!("{{ point = {}, along = {} }}", quote(point), list(along))
        }),
    );
    if !sliders.is_empty() {
        let _ = writeln!(out, "sliders = [{}]", sliders.join(", "));
    }
    if !topology.trace.is_empty() {
        let _ = writeln!(out, "trace = {}", list(&topology.trace));
    }
    out
}

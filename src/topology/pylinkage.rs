//! pylinkage's mechanisms, read into a topology and written back.
//!
//! pylinkage (Hugo Farajallah's Python package) writes a mechanism as JSON
//! (`pylinkage.mechanism.mechanism_to_dict`, 1.x):
//!
//! ```json
//! {"name": "Four-Bar",
//!  "joints": [{"id": "O1", "type": "ground", "position": [0, 0]}, …],
//!  "links": [{"id": "ground", "type": "ground", "joints": ["O1", "O2"]},
//!            {"id": "crank", "type": "driver", "joints": ["O1", "A"],
//!             "angular_velocity": 0.31, "initial_angle": 0.0,
//!             "motor_joint": "O1"}, …],
//!  "ground": "ground"}
//! ```
//!
//! Joints are `ground`, `revolute`, `prismatic` (a pin running on a fixed
//! line through `line_point` along `axis`) and `tracker` (a point at
//! `distance` and `angle` from the line of two reference joints); links
//! `ground`, `driver` (turned about its `motor_joint` from
//! `initial_angle` by `angular_velocity` a step), `arc_driver` (the same
//! between `arc_start` and `arc_end`) and `link`. Lengths are those of the
//! positions, as pylinkage reads them.
//!
//! Read here, names become identifiers (`crank.tip` → `crank_tip`), a
//! prismatic joint is a pin in a slot of the frame, a tracker a point of the
//! link that carries both its references; a step of the drive is a
//! second. A tracker whose references no link carries together is refused
//! with the reason.

use super::model::{Driven, Driver, JointKind, Topology};
use serde_json::Value;
use std::f64::consts::TAU;
use std::fmt;

/// Why pylinkage's JSON was not read.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PylinkageError {
    /// Not JSON, or not pylinkage's shape: where, and what.
    Malformed { why: String },
    /// Well formed, but not a mechanism linkage can take as it is.
    Unrepresentable { why: String },
}

impl fmt::Display for PylinkageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PylinkageError::Malformed { why } | PylinkageError::Unrepresentable { why } => {
                f.write_str(why)
            }
        }
    }
}

impl std::error::Error for PylinkageError {}

fn malformed(why: impl Into<String>) -> PylinkageError {
    PylinkageError::Malformed { why: why.into() }
}

/// An identifier for a pylinkage id: letters, digits and `_`, the rest
/// `_`, a letter first; made unique against `taken`.
pub fn identifier(id: &str, taken: &[String]) -> String {
    let mut name: String = id
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let name_trimmed = name.trim_matches('_').to_owned();
    name = if name_trimmed.is_empty() {
        "J".to_owned()
    } else {
        name_trimmed
    };
    if name.starts_with(|c: char| c.is_ascii_digit()) {
        name.insert(0, 'J');
    }
    if crate::file::not_an_identifier(&name).is_some() {
        name.push('_');
    }
    let mut unique = name.clone();
    let mut k = 2;
    while taken.contains(&unique) {
        unique = format!("{name}_{k}");
        k += 1;
    }
    unique
}

fn field<'v>(value: &'v Value, key: &str, what: &str) -> Result<&'v Value, PylinkageError> {
    value
        .get(key)
        .ok_or_else(|| malformed(format!("{what} has no `{key}`")))
}

fn text<'v>(value: &'v Value, key: &str, what: &str) -> Result<&'v str, PylinkageError> {
    field(value, key, what)?
        .as_str()
        .ok_or_else(|| malformed(format!("`{key}` of {what} is not a string")))
}

fn number(value: &Value, key: &str, what: &str) -> Result<f64, PylinkageError> {
    let x = field(value, key, what)?
        .as_f64()
        .ok_or_else(|| malformed(format!("`{key}` of {what} is not a number")))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(malformed(format!("`{key}` of {what} is not finite")))
    }
}

fn pair(value: &Value, key: &str, what: &str) -> Result<[f64; 2], PylinkageError> {
    let bad = || malformed(format!("`{key}` of {what} is not a pair of numbers"));
    let array = field(value, key, what)?.as_array().ok_or_else(bad)?;
    match &array[..] {
        [x, y] => {
            let (x, y) = (x.as_f64().ok_or_else(bad)?, y.as_f64().ok_or_else(bad)?);
            if x.is_finite() && y.is_finite() {
                Ok([x, y])
            } else {
                Err(bad())
            }
        }
        _ => Err(bad()),
    }
}

/// The topology of pylinkage's JSON (`mechanism_to_dict`), with the names
/// given to its ids.
pub fn from_pylinkage(json: &str) -> Result<(Topology, Vec<(String, String)>), PylinkageError> {
    let root: Value = serde_json::from_str(json).map_err(|e| {
        malformed(format!(
            "not JSON: {e} (line {}, column {})",
            e.line(),
            e.column()
        ))
    })?;
    let title = root
        .get("name")
        .and_then(Value::as_str)
        .unwrap_or("Mechanism");
    let name = identifier(&title.replace(['-', ' '], ""), &[]);
    let mut topology = Topology::new(&name).title(title);
    let joints = field(&root, "joints", "the mechanism")?
        .as_array()
        .ok_or_else(|| malformed("`joints` is not a list"))?;
    let links = field(&root, "links", "the mechanism")?
        .as_array()
        .ok_or_else(|| malformed("`links` is not a list"))?;
    // Names for the ids, joints then links.
    let mut names: Vec<(String, String)> = Vec::new();
    let mut taken: Vec<String> = Vec::new();
    let mut name_of = |id: &str, names: &mut Vec<(String, String)>| {
        let n = identifier(id, &taken);
        taken.push(n.clone());
        names.push((id.to_owned(), n.clone()));
        n
    };
    for joint in joints {
        let id = text(joint, "id", "a joint")?;
        name_of(id, &mut names);
    }
    let joint_name = |id: &str, names: &[(String, String)]| {
        (names.iter())
            .find(|(i, _)| i == id)
            .map(|(_, n)| n.clone())
            .ok_or_else(|| malformed(format!("a link lists `{id}`, which is no joint")))
    };
    let ground_id = root.get("ground").and_then(Value::as_str);
    let mut ground_joints: Vec<String> = Vec::new();
    let mut trackers: Vec<(String, String, String)> = Vec::new();
    for joint in joints {
        let id = text(joint, "id", "a joint")?;
        let what = format!("joint `{id}`");
        let name = joint_name(id, &names)?;
        let at = pair(joint, "position", &what)?;
        match text(joint, "type", &what)? {
            "ground" => {
                topology = topology.revolute(&name, at);
                ground_joints.push(name);
            }
            "revolute" => topology = topology.revolute(&name, at),
            "prismatic" => {
                let axis = pair(joint, "axis", &what)?;
                let through = pair(joint, "line_point", &what)?;
                let off = (at[0] - through[0]) * axis[1] - (at[1] - through[1]) * axis[0];
                let norm = axis[0].hypot(axis[1]);
                if norm == 0.0 {
                    return Err(malformed(format!("the axis of {what} has no length")));
                }
                if (off / norm).abs() > 1e-9 * (1.0 + at[0].abs().max(at[1].abs())) {
                    return Err(PylinkageError::Unrepresentable {
                        why: format!("{what} is drawn {:.3e} off its line", off / norm),
                    });
                }
                topology = topology.pin_in_slot(&name, at, axis[1].atan2(axis[0]));
                ground_joints.push(name.clone());
                topology = topology.guide(&name, "ground");
            }
            "tracker" => {
                let a = joint_name(text(joint, "ref_joint1_id", &what)?, &names)?;
                let b = joint_name(text(joint, "ref_joint2_id", &what)?, &names)?;
                topology = topology.revolute(&name, at);
                trackers.push((name, a, b));
            }
            other => {
                return Err(PylinkageError::Unrepresentable {
                    why: format!("{what} is of type `{other}`, which linkage does not read"),
                });
            }
        }
    }
    let mut ground_link = None;
    let mut link_joints: Vec<(String, Vec<String>)> = Vec::new();
    for link in links {
        let id = text(link, "id", "a link")?;
        let what = format!("link `{id}`");
        let kind = text(link, "type", &what)?;
        let members = field(link, "joints", &what)?
            .as_array()
            .ok_or_else(|| malformed(format!("`joints` of {what} is not a list")))?;
        let mut on = Vec::new();
        for member in members {
            let member = member
                .as_str()
                .ok_or_else(|| malformed(format!("a joint of {what} is not a string")))?;
            on.push(joint_name(member, &names)?);
        }
        if kind == "ground" || Some(id) == ground_id {
            ground_link = Some(link_joints.len());
            link_joints.push(("ground".to_owned(), on));
            continue;
        }
        let name = identifier(id, &taken);
        taken.push(name.clone());
        match kind {
            "driver" | "arc_driver" => {
                let motor = joint_name(text(link, "motor_joint", &what)?, &names)?;
                let Some(tip) = on.iter().find(|j| **j != motor).cloned() else {
                    return Err(malformed(format!("{what} drives no joint but its motor")));
                };
                let start = number(link, "initial_angle", &what)?;
                let rate = number(link, "angular_velocity", &what)?;
                let range = if kind == "arc_driver" {
                    [
                        number(link, "arc_start", &what)?,
                        number(link, "arc_end", &what)?,
                    ]
                } else {
                    [start, start + TAU.copysign(rate)]
                };
                let steps = if rate == 0.0 {
                    360
                } else {
                    ((range[1] - range[0]).abs() / rate.abs())
                        .round()
                        .clamp(1.0, crate::file::MOST_STEPS as f64) as usize
                };
                topology = topology.drive(Driver {
                    driven: Driven::Angle {
                        from: motor,
                        to: tip,
                    },
                    range: Some(range),
                    steps: Some(steps),
                    rate: Some(rate),
                    at: Some(start),
                });
            }
            "link" => {}
            other => {
                return Err(PylinkageError::Unrepresentable {
                    why: format!("{what} is of type `{other}`, which linkage does not read"),
                });
            }
        }
        link_joints.push((name, on));
    }
    // The frame carries the ground joints and the lines of the prismatic
    // ones; a tracker is a point of the link of both its references.
    match ground_link {
        Some(g) => {
            for joint in &ground_joints {
                if !link_joints[g].1.contains(joint) {
                    link_joints[g].1.push(joint.clone());
                }
            }
        }
        None => link_joints.insert(0, ("ground".to_owned(), ground_joints)),
    }
    for (tracker, a, b) in trackers {
        let Some(link) = (link_joints.iter_mut())
            .find(|(n, on)| n != "ground" && on.contains(&a) && on.contains(&b))
        else {
            return Err(PylinkageError::Unrepresentable {
                why: format!(
                    "the tracker `{tracker}` follows `{a}` and `{b}`, which no link carries together: it is on no rigid body"
                ),
            });
        };
        link.1.push(tracker);
    }
    merge_triangles(&mut link_joints);
    for (name, on) in &link_joints {
        let on: Vec<&str> = on.iter().map(String::as_str).collect();
        topology = topology.link(name, &on);
    }
    Ok((topology, names))
}

/// Three moving links of two joints each, pinned pairwise at three joints,
/// are one rigid plate (pylinkage writes a point fixed to a link, its
/// `FixedDyad`, so): each such triangle becomes one link of the three
/// joints, named after the first. (Kept apart, a plate drawn flat — its
/// point on the line of the other two — would be a dead centre at every
/// pose.)
fn merge_triangles(links: &mut Vec<(String, Vec<String>)>) {
    loop {
        let binary: Vec<usize> = (0..links.len())
            .filter(|&k| links[k].0 != "ground" && links[k].1.len() == 2)
            .collect();
        let shares =
            |a: usize, b: usize| links[a].1.iter().find(|j| links[b].1.contains(j)).cloned();
        let mut found = None;
        'search: for (i, &a) in binary.iter().enumerate() {
            for (j, &b) in binary.iter().enumerate().skip(i + 1) {
                let Some(ab) = shares(a, b) else { continue };
                for &c in &binary[j + 1..] {
                    if let (Some(bc), Some(ca)) = (shares(b, c), shares(c, a))
                        && ab != bc
                        && bc != ca
                        && ca != ab
                    {
                        found = Some((a, b, c, [ca, ab, bc]));
                        break 'search;
                    }
                }
            }
        }
        let Some((a, b, c, joints)) = found else {
            return;
        };
        links[a].1 = joints.to_vec();
        for k in [c, b] {
            links.remove(k);
        }
    }
}

/// pylinkage's JSON of a topology whose joints it can write: pins (on the
/// frame: `ground`), pins in slots of the frame (`prismatic`), one angle
/// driver per driven link (`driver`, its range a turn; an `arc_driver`
/// otherwise). `ids` gives the ids to write for names (from
/// [`from_pylinkage`]); a name without one is written as it is.
pub fn to_pylinkage(
    topology: &Topology,
    ids: &[(String, String)],
) -> Result<String, PylinkageError> {
    let unrepresentable = |why: String| PylinkageError::Unrepresentable { why };
    let id = |name: &str| {
        (ids.iter())
            .find(|(_, n)| n == name)
            .map_or(name.to_owned(), |(i, _)| i.clone())
    };
    let ground = (topology.links.iter())
        .find(|l| l.name == topology.ground)
        .ok_or_else(|| unrepresentable(format!("no link is named `{}`", topology.ground)))?;
    let mut joints = Vec::new();
    for joint in &topology.joints {
        let on_ground = ground.joints.contains(&joint.name);
        let mut entry =
            serde_json::json!({"id": id(&joint.name), "position": [joint.at[0], joint.at[1]]});
        match joint.kind {
            JointKind::Revolute => {
                entry["type"] = (if on_ground { "ground" } else { "revolute" }).into();
            }
            JointKind::PinInSlot { angle } if on_ground => {
                entry["type"] = "prismatic".into();
                entry["axis"] = serde_json::json!([angle.cos(), angle.sin()]);
                entry["line_point"] = serde_json::json!([joint.at[0], joint.at[1]]);
                entry["slide_distance"] = 0.0.into();
            }
            _ => {
                return Err(unrepresentable(format!(
                    "joint `{}` slides on a moving link: pylinkage's joints slide on the frame",
                    joint.name
                )));
            }
        }
        joints.push(entry);
    }
    let mut links = vec![serde_json::json!({
        "id": "ground", "type": "ground",
        "joints": ground.joints.iter().filter(|j| {
            topology.joints.iter().any(|t| t.name == **j && t.kind == JointKind::Revolute)
        }).map(|j| id(j)).collect::<Vec<_>>(),
    })];
    for link in topology.links.iter().filter(|l| l.name != topology.ground) {
        let members: Vec<String> = link.joints.iter().map(|j| id(j)).collect();
        let mut entry =
            serde_json::json!({"id": id(&link.name), "type": "link", "joints": members});
        let driver = topology.drivers.iter().find(|d| match &d.driven {
            Driven::Angle { from, to } => link.joints.contains(from) && link.joints.contains(to),
            Driven::Slide { .. } => false,
        });
        if let Some(driver) = driver {
            let Driven::Angle { from, .. } = &driver.driven else {
                unreachable!()
            };
            let range = driver.range.unwrap_or([0.0, TAU]);
            let start = driver.at.unwrap_or(range[0]);
            let rate = driver.rate.unwrap_or(1.0);
            let turn = ((range[1] - range[0]).abs() - TAU).abs() < 1e-12;
            entry["type"] = (if turn { "driver" } else { "arc_driver" }).into();
            entry["angular_velocity"] = rate.into();
            entry["initial_angle"] = start.into();
            entry["motor_joint"] = id(from).into();
            if !turn {
                entry["arc_start"] = range[0].into();
                entry["arc_end"] = range[1].into();
            }
        }
        links.push(entry);
    }
    if let Some(d) = topology
        .drivers
        .iter()
        .find(|d| matches!(d.driven, Driven::Slide { .. }))
    {
        return Err(unrepresentable(format!(
            "{:?}: pylinkage's drivers turn",
            d.driven
        )));
    }
    let root = serde_json::json!({
        "name": topology.title.clone().unwrap_or_else(|| topology.name.clone()),
        "joints": joints,
        "links": links,
        "ground": "ground",
    });
    serde_json::to_string_pretty(&root).map_err(|e| unrepresentable(e.to_string()))
}

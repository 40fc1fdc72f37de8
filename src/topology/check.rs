//! A topology checked and indexed: names, the links' joints, sliders on two
//! links, connection to the frame, drivers and mobility. Mistakes that
//! make later checks meaningless (an unknown joint, say) stop there, so
//! that each mistake is reported once, without follow-ons.

use super::error::{TopologyError, TopologyErrors};
use super::model::{Driven, JointKind, Topology};
use crate::file::units;
use std::collections::{BTreeSet, HashMap};

/// The longest name of a joint or a link (the generated names join two).
const LONGEST_NAME: usize = 100;

/// A topology whose names resolve: joints and links by index.
#[derive(Debug)]
pub(super) struct Checked<'t> {
    pub topology: &'t Topology,
    /// Each link's joints, by index.
    pub links: Vec<Vec<usize>>,
    /// The links that list each joint, in the topology's order.
    pub joint_links: Vec<Vec<usize>>,
    pub ground: usize,
    /// The size of the drawing (its largest extent), for tolerances.
    pub size: f64,
}

impl<'t> Checked<'t> {
    pub fn joint(&self, name: &str) -> Option<usize> {
        self.topology.joints.iter().position(|j| j.name == name)
    }

    /// What kind of joint `joint` is.
    pub fn kind(&self, joint: usize) -> JointKind {
        self.topology.joints[joint].kind
    }

    pub fn at(&self, joint: usize) -> [f64; 2] {
        self.topology.joints[joint].at
    }

    pub fn joint_name(&self, joint: usize) -> &str {
        &self.topology.joints[joint].name
    }

    pub fn link_name(&self, link: usize) -> &str {
        &self.topology.links[link].name
    }

    /// Whether two drawn positions are one place, at the drawing's scale.
    pub fn coincide(&self, a: [f64; 2], b: [f64; 2]) -> bool {
        (a[0] - b[0]).hypot(a[1] - b[1]) <= 1e-9 * self.size
    }
}

/// Checks `topology`: every mistake found, or the indexed topology.
pub(super) fn check(topology: &Topology) -> Result<Checked<'_>, TopologyErrors> {
    let mut errors = Vec::new();
    names(topology, &mut errors);
    if units::lookup(&topology.length_unit).is_none_or(|u| u.kind != units::Kind::Length) {
        errors.push(TopologyError::BadUnit {
            unit: topology.length_unit.clone(),
        });
    }
    for joint in &topology.joints {
        let angle = match joint.kind {
            JointKind::Revolute => 0.0,
            JointKind::Prismatic { angle } | JointKind::PinInSlot { angle } => angle,
        };
        if !(joint.at[0].is_finite() && joint.at[1].is_finite() && angle.is_finite()) {
            errors.push(TopologyError::NotFinite {
                what: format!("the position or angle of joint `{}`", joint.name),
            });
        }
    }
    let index: HashMap<&str, usize> = (topology.joints.iter().enumerate())
        .map(|(k, j)| (j.name.as_str(), k))
        .collect();
    let mut links = Vec::new();
    for link in &topology.links {
        let mut joints = Vec::new();
        if link.joints.is_empty() {
            errors.push(TopologyError::EmptyLink {
                link: link.name.clone(),
            });
        }
        for name in &link.joints {
            match index.get(name.as_str()) {
                None => errors.push(TopologyError::UnknownJoint {
                    link: link.name.clone(),
                    joint: name.clone(),
                }),
                Some(&j) if joints.contains(&j) => errors.push(TopologyError::JointTwice {
                    link: link.name.clone(),
                    joint: name.clone(),
                }),
                Some(&j) => joints.push(j),
            }
        }
        links.push(joints);
    }
    let ground = topology
        .links
        .iter()
        .position(|l| l.name == topology.ground);
    if ground.is_none() {
        errors.push(TopologyError::NoGround {
            ground: topology.ground.clone(),
        });
    }
    let mut joint_links = vec![Vec::new(); topology.joints.len()];
    for (l, joints) in links.iter().enumerate() {
        for &j in joints {
            joint_links[j].push(l);
        }
    }
    for (j, on) in joint_links.iter_mut().enumerate() {
        let joint = &topology.joints[j];
        // The guide first.
        if let Some(guide) = &joint.guide {
            match on.iter().position(|&l| topology.links[l].name == *guide) {
                Some(k) => on[..=k].rotate_right(1),
                None => errors.push(TopologyError::BadGuide {
                    joint: joint.name.clone(),
                    link: guide.clone(),
                }),
            }
        }
        if on.is_empty() {
            errors.push(TopologyError::JointOnNoLink {
                joint: joint.name.clone(),
            });
        } else if joint.kind != JointKind::Revolute && on.len() != 2 {
            errors.push(TopologyError::SliderLinks {
                joint: joint.name.clone(),
                links: on.len(),
            });
        }
    }
    if !errors.is_empty() {
        return Err(TopologyErrors { errors });
    }
    let extent = |k: usize| {
        let values = topology.joints.iter().map(|j| j.at[k]);
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
        hi - lo
    };
    let size = extent(0).max(extent(1)).max(f64::MIN_POSITIVE);
    let checked = Checked {
        topology,
        links,
        joint_links,
        ground: ground.unwrap_or(0),
        size,
    };
    connected(&checked, &mut errors);
    rigid_pairs(&checked, &mut errors);
    coincident_pins(&checked, &mut errors);
    drivers(&checked, &mut errors);
    lengths(&checked, &mut errors);
    for (k, name) in topology.trace.iter().enumerate() {
        if checked.joint(name).is_none() {
            errors.push(TopologyError::UnknownTrace { name: name.clone() });
        } else if topology.trace[..k].contains(name) {
            errors.push(TopologyError::TracedTwice { name: name.clone() });
        }
    }
    if errors.is_empty() {
        mobility(&checked, &mut errors);
    }
    if errors.is_empty() {
        Ok(checked)
    } else {
        Err(TopologyErrors { errors })
    }
}

/// Every name an identifier, each given once.
fn names(topology: &Topology, errors: &mut Vec<TopologyError>) {
    let mut seen = BTreeSet::new();
    let joints = topology.joints.iter().map(|j| &j.name);
    let links = topology.links.iter().map(|l| &l.name);
    for name in joints.chain(links) {
        if let Some(why) = crate::file::not_an_identifier(name) {
            errors.push(TopologyError::BadName {
                name: name.clone(),
                why,
            });
        } else if name.len() > LONGEST_NAME {
            errors.push(TopologyError::BadName {
                name: name.clone(),
                why: format!("a name of {} characters: a joint's or a link's name has at most {LONGEST_NAME}", name.len()),
            });
        } else if !seen.insert(name.as_str()) {
            errors.push(TopologyError::DuplicateName { name: name.clone() });
        }
    }
    if let Some(why) = crate::file::not_an_identifier(&topology.name) {
        errors.push(TopologyError::BadName {
            name: topology.name.clone(),
            why,
        });
    }
}

/// Every link reached from the frame through joints.
fn connected(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    let n = checked.links.len();
    let mut reached = vec![false; n];
    let mut stack = vec![checked.ground];
    reached[checked.ground] = true;
    while let Some(l) = stack.pop() {
        for &j in &checked.links[l] {
            for &other in &checked.joint_links[j] {
                if !reached[other] {
                    reached[other] = true;
                    stack.push(other);
                }
            }
        }
    }
    let lost: Vec<String> = (0..n)
        .filter(|&l| !reached[l])
        .map(|l| checked.link_name(l).to_owned())
        .collect();
    if !lost.is_empty() {
        errors.push(TopologyError::Disconnected { links: lost });
    }
}

/// No two links joined by two pins.
fn rigid_pairs(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    let mut shared: HashMap<(usize, usize), usize> = HashMap::new();
    for (j, on) in checked.joint_links.iter().enumerate() {
        if checked.kind(j) != JointKind::Revolute {
            continue;
        }
        for (a, &la) in on.iter().enumerate() {
            for &lb in &on[a + 1..] {
                if let Some(&first) = shared.get(&(la, lb)) {
                    errors.push(TopologyError::RigidPair {
                        links: [
                            checked.link_name(la).to_owned(),
                            checked.link_name(lb).to_owned(),
                        ],
                        joints: [
                            checked.joint_name(first).to_owned(),
                            checked.joint_name(j).to_owned(),
                        ],
                    });
                } else {
                    shared.insert((la, lb), j);
                }
            }
        }
    }
}

/// No two pins of a moving link drawn at one place (its length or angle
/// would be undefined: they are one joint), no link held by one pin alone
/// and not driven.
fn coincident_pins(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    for (l, joints) in checked.links.iter().enumerate() {
        if l == checked.ground {
            continue;
        }
        let pins: Vec<usize> = (joints.iter().copied())
            .filter(|&j| checked.kind(j) == JointKind::Revolute)
            .collect();
        // A turning link needs two of its joints apart for its angle.
        let slides = joints
            .iter()
            .any(|&j| matches!(checked.kind(j), JointKind::Prismatic { .. }));
        if let [first, second, ..] = joints[..]
            && !slides
            && joints
                .iter()
                .all(|&j| checked.coincide(checked.at(j), checked.at(first)))
        {
            errors.push(TopologyError::CoincidentPins {
                link: checked.link_name(l).to_owned(),
                joints: [
                    checked.joint_name(first).to_owned(),
                    checked.joint_name(second).to_owned(),
                ],
            });
            continue;
        }
        'pairs: for (a, &ja) in pins.iter().enumerate() {
            for &jb in &pins[a + 1..] {
                if checked.coincide(checked.at(ja), checked.at(jb)) {
                    errors.push(TopologyError::CoincidentPins {
                        link: checked.link_name(l).to_owned(),
                        joints: [
                            checked.joint_name(ja).to_owned(),
                            checked.joint_name(jb).to_owned(),
                        ],
                    });
                    break 'pairs;
                }
            }
        }
        let driven = (checked.topology.drivers.iter()).any(|d| match &d.driven {
            Driven::Angle { from, to } => [from, to]
                .iter()
                .all(|n| checked.joint(n).is_some_and(|j| joints.contains(&j))),
            Driven::Slide { .. } => false,
        });
        if let [only] = joints[..]
            && checked.kind(only) == JointKind::Revolute
            && checked.joint_links[only].len() > 1
            && !driven
        {
            errors.push(TopologyError::Dangling {
                link: checked.link_name(l).to_owned(),
                joint: checked.joint_name(only).to_owned(),
            });
        }
    }
}

/// Drivers that name joints, each motion once.
fn drivers(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    let mut driven = BTreeSet::new();
    for driver in &checked.topology.drivers {
        match &driver.driven {
            Driven::Angle { from, to } => {
                let (Some(a), Some(b)) = (checked.joint(from), checked.joint(to)) else {
                    for name in [from, to] {
                        if checked.joint(name).is_none() {
                            errors.push(TopologyError::UnknownDriverJoint {
                                joint: name.clone(),
                            });
                        }
                    }
                    continue;
                };
                let link = (0..checked.links.len()).find(|&l| {
                    l != checked.ground
                        && checked.links[l].contains(&a)
                        && checked.links[l].contains(&b)
                });
                let locked = unturning(checked);
                match link {
                    None => errors.push(TopologyError::DriverNotOnOneLink {
                        from: from.clone(),
                        to: to.clone(),
                    }),
                    Some(l) if locked[l] => {
                        let slider = (checked.links[l].iter())
                            .find(|&&j| matches!(checked.kind(j), JointKind::Prismatic { .. }))
                            .map_or(String::new(), |&j| checked.joint_name(j).to_owned());
                        errors.push(TopologyError::DrivenLinkLocked {
                            link: checked.link_name(l).to_owned(),
                            joint: slider,
                        })
                    }
                    Some(l)
                        if !driven
                            .insert(format!("the angle of link `{}`", checked.link_name(l))) =>
                    {
                        errors.push(TopologyError::DrivenTwice {
                            what: format!("the angle of link `{}`", checked.link_name(l)),
                        })
                    }
                    Some(_) => {}
                }
            }
            Driven::Slide { joint } => match checked.joint(joint) {
                None => errors.push(TopologyError::UnknownDriverJoint {
                    joint: joint.clone(),
                }),
                Some(j) if checked.kind(j) == JointKind::Revolute => {
                    errors.push(TopologyError::NotASlide {
                        joint: joint.clone(),
                    })
                }
                Some(_) if driver.range.is_none() => {
                    errors.push(TopologyError::SlideWithoutRange {
                        joint: joint.clone(),
                    })
                }
                Some(_) if !driven.insert(format!("the slide along `{joint}`")) => {
                    errors.push(TopologyError::DrivenTwice {
                        what: format!("the slide along `{joint}`"),
                    })
                }
                Some(_) => {}
            },
        }
        let values = [
            driver.range.map(|r| r[0]),
            driver.range.map(|r| r[1]),
            driver.rate,
            driver.at,
        ];
        if values.iter().flatten().any(|x| !x.is_finite()) {
            errors.push(TopologyError::NotFinite {
                what: "a driver's range, rate or pose".to_owned(),
            });
        } else if driver.range.is_some_and(|[from, to]| from == to) {
            errors.push(TopologyError::BadDrive {
                why: "its range is of zero length (`from` = `to`, to rounding)".to_owned(),
            });
        }
        if let Some(steps) = driver.steps
            && !(1..=crate::file::MOST_STEPS).contains(&steps)
        {
            errors.push(TopologyError::BadDrive {
                why: format!(
                    "{steps} steps: a sweep takes 1 to {}",
                    crate::file::MOST_STEPS
                ),
            });
        }
    }
}

/// The links that cannot turn: slid on the frame along sliders, or on
/// links that cannot turn.
fn unturning(checked: &Checked<'_>) -> Vec<bool> {
    let mut locked = vec![false; checked.links.len()];
    locked[checked.ground] = true;
    let mut changed = true;
    while changed {
        changed = false;
        for (j, on) in checked.joint_links.iter().enumerate() {
            if matches!(checked.kind(j), JointKind::Prismatic { .. })
                && let [a, b] = on[..]
                && locked[a] != locked[b]
            {
                locked[a] = true;
                locked[b] = true;
                changed = true;
            }
        }
    }
    locked
}

/// Given lengths between two joints of one link, positive.
fn lengths(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    for (a, b, length) in &checked.topology.lengths {
        let bad = |why: &str| TopologyError::BadLength {
            from: a.clone(),
            to: b.clone(),
            why: why.to_owned(),
        };
        let (Some(ja), Some(jb)) = (checked.joint(a), checked.joint(b)) else {
            errors.push(bad("names a joint that is not defined"));
            continue;
        };
        if !(length.is_finite() && *length > 0.0) {
            errors.push(bad("must be a positive finite number"));
        } else if !(checked.links.iter()).any(|l| l.contains(&ja) && l.contains(&jb)) {
            errors.push(bad("no link carries both joints"));
        }
    }
}

/// Grübler–Kutzbach: 3(n − 1) − 2 j₁ − j₂, a pin on k links counting as
/// k − 1 pins, against the drivers; a loop of three links joined by pins
/// (a triangle) named as rigid.
fn mobility(checked: &Checked<'_>, errors: &mut Vec<TopologyError>) {
    let mut full = 0;
    let mut half = 0;
    for (j, on) in checked.joint_links.iter().enumerate() {
        match checked.kind(j) {
            JointKind::Revolute => full += on.len().saturating_sub(1),
            JointKind::Prismatic { .. } => full += 1,
            JointKind::PinInSlot { .. } => half += 1,
        }
    }
    let n = checked.links.len();
    let mobility = 3 * (n as i64 - 1) - 2 * full as i64 - half as i64;
    let drivers = checked.topology.drivers.len();
    if mobility == 0 && drivers == 0 {
        errors.push(TopologyError::NoDriver);
        return;
    }
    // A part that cannot move makes the equations singular whatever the
    // count (another part then moves freely): looked for always where
    // the search is small, and wherever the count says over-constrained.
    let small = n <= 16;
    // (The whole mechanism over-constrained is the count's to say.)
    if (mobility < drivers as i64 || small)
        && let Some(links) = over_constrained(checked)
        && links.len() < n
    {
        errors.push(TopologyError::RigidLoop { links });
        return;
    }
    if mobility != drivers as i64 {
        errors.push(TopologyError::Mobility {
            mobility,
            drivers,
            links: n,
            full_joints: full,
            half_joints: half,
        });
    }
}

/// The smallest set of links (up to eight) that the joints among them
/// leave with fewer than no degrees of freedom of their own: where an
/// over-constrained mechanism cannot move.
fn over_constrained(checked: &Checked<'_>) -> Option<Vec<String>> {
    let n = checked.links.len();
    let largest = n.min(8);
    for size in 2..=largest {
        let mut chosen: Vec<usize> = (0..size).collect();
        loop {
            if sub_mobility(checked, &chosen) < 0 {
                return Some(
                    chosen
                        .iter()
                        .map(|&l| checked.link_name(l).to_owned())
                        .collect(),
                );
            }
            // The next combination of `size` links out of n.
            let Some(k) = (0..size).rev().find(|&k| chosen[k] < n - size + k) else {
                break;
            };
            chosen[k] += 1;
            for i in k + 1..size {
                chosen[i] = chosen[i - 1] + 1;
            }
        }
    }
    None
}

/// Grübler–Kutzbach of the links `chosen` and the joints among them.
fn sub_mobility(checked: &Checked<'_>, chosen: &[usize]) -> i64 {
    let mut constraints = 0;
    for (j, on) in checked.joint_links.iter().enumerate() {
        let inside = on.iter().filter(|l| chosen.contains(l)).count();
        if inside < 2 {
            continue;
        }
        constraints += match checked.kind(j) {
            JointKind::Revolute => 2 * (inside as i64 - 1),
            JointKind::Prismatic { .. } => 2,
            JointKind::PinInSlot { .. } => 1,
        };
    }
    // A driver inside fixes one more freedom.
    let driven = (checked.topology.drivers.iter())
        .filter(|d| match &d.driven {
            Driven::Angle { from, to } => {
                let (Some(a), Some(b)) = (checked.joint(from), checked.joint(to)) else {
                    return false;
                };
                chosen.iter().any(|&l| {
                    l != checked.ground
                        && checked.links[l].contains(&a)
                        && checked.links[l].contains(&b)
                }) && chosen.contains(&checked.ground)
            }
            Driven::Slide { joint } => checked
                .joint(joint)
                .is_some_and(|j| checked.joint_links[j].iter().all(|l| chosen.contains(l))),
        })
        .count() as i64;
    3 * (chosen.len() as i64 - 1) - constraints - driven
}

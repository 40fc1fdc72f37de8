//! Topology files: a mechanism as joints and links, read into a
//! [`Topology`] with every name's place kept, so that a mistake of the
//! topology (a joint on no link, the wrong mobility) is located at its
//! culprit in the file.
//!
//! ```toml
//! name = "FourBar"
//! length_unit = "mm"
//!
//! [joints]                 # where each joint is drawn
//! A = [0, 0]               # a pin
//! B = [18.8, 6.8]
//! C = [35.4, 54.0]
//! D = ["80 mm", 0]
//! # S = { at = [4, 0.5], slider = "0 deg" }   a slider along 0°
//! # Q = { at = [1, 2], slot = "30 deg", guide = "lever" }
//! #                                  a pin in a slot of `lever` along 30°
//!
//! [links]                  # each link's joints; `ground` is the frame
//! ground = ["A", "D"]
//! crank = ["A", "B"]
//! coupler = ["B", "C"]
//! rocker = ["D", "C"]
//!
//! [[drive]]                # the angle of A→B over a turn from as drawn
//! angle = ["A", "B"]
//! rate = "400 rpm"
//! at = "20 deg"
//!
//! [lengths]                # optional: lengths given, the drawing a sketch
//! A-B = 20
//! B-C = 50
//! D-C = 70
//! ```
//!
//! | key | what | |
//! |---|---|---|
//! | `name`, `title`, `length_unit` | as in a mechanism file | `name` required |
//! | `ground` | the name of the frame's link (`ground` unless said) | optional |
//! | `[joints]` | `<name> = [x, y]` for a pin (or a point, on one link); `{ at = [x, y], slider = angle }` for a slider, `{ at = [x, y], slot = angle }` for a pin in a slot; `guide = "link"` names the link that carries the line (by default the first of the joint's two links in `[links]`) | required |
//! | `[links]` | `<name> = ["A", "B", …]`: the joints each link carries | required |
//! | `[[drive]]` | one per driver: `angle = ["A", "B"]` (the angle of the line A→B of one link) or `slide = "S"` (the travel along a slider or slot); `from`, `to` (an angle's default: a turn from its drawn value; a slide's required), `steps`, `rate`, `at` as in a mechanism file | required |
//! | `[lengths]` | `A-B = length`: the distance of two joints of one link, given rather than drawn | optional |
//! | `trace` | points whose paths a picture traces | optional |

use super::error::{FileError, FileErrors};
use super::quantity::Accept;
use super::reader::{Reader, Table, Value};
use super::units::{self, Kind, Unit};
use super::{MechanismFile, syntax};
use crate::topology::{Driven, Driver, JointKind, Topology, TopologyError};
use std::collections::HashMap;
use std::ops::Range;
use toml::de::DeValue;

/// A topology file, read: the topology and where each of its names is
/// written.
#[derive(Clone, Debug)]
pub struct TopologyFile {
    pub topology: Topology,
    /// Where each joint's and link's name is written.
    places: HashMap<String, Range<usize>>,
    /// Where each driver is written, in order.
    driver_places: Vec<Range<usize>>,
    /// Where the `[links]` table is, and the file's start.
    links_place: Range<usize>,
    /// Where each traced name is written.
    trace_places: Vec<(String, Range<usize>)>,
}

/// Whether `text` is a topology file rather than a mechanism file: it has
/// `[joints]` and no `equations`.
pub fn is_topology(text: &str) -> bool {
    let (document, _) = toml::de::DeTable::parse_recoverable(text);
    let has = |key: &str| {
        document
            .get_ref()
            .iter()
            .any(|(k, _)| k.get_ref().as_ref() == key)
    };
    has("joints") && !has("equations")
}

impl TopologyFile {
    /// Reads a topology file's text, every mistake located; the topology
    /// itself is checked too (a joint on no link, the mobility, …).
    pub fn parse(text: &str) -> Result<TopologyFile, FileErrors> {
        let mut reader = Reader::new(text);
        let file = syntax::document(&mut reader).and_then(|root| {
            let root = Table::new(root.get_ref(), "", 0..0);
            reader.topology(root)
        });
        match file {
            Some(file) if !reader.failed() => match file.topology.check() {
                Ok(()) => Ok(file),
                Err(errors) => Err(FileErrors {
                    errors: errors.errors.iter().map(|e| file.locate(text, e)).collect(),
                }),
            },
            _ => Err(FileErrors {
                errors: reader.into_errors(),
            }),
        }
    }

    /// The mechanism file its topology generates ([`Topology::mechanism_text`]),
    /// and that text.
    pub fn mechanism_file(&self) -> Result<(MechanismFile, String), FileErrors> {
        let text = self
            .topology
            .mechanism_text()
            .map_err(|errors| FileErrors {
                errors: errors.errors.iter().map(|e| self.locate("", e)).collect(),
            })?;
        let file = MechanismFile::parse(&text)?;
        Ok((file, text))
    }

    /// A topology mistake at the place of its culprit.
    fn locate(&self, text: &str, error: &TopologyError) -> FileError {
        use TopologyError::*;
        let name = match error {
            BadName { name, .. } | DuplicateName { name } | NameClash { name } => Some(name),
            UnknownJoint { link, .. } | JointTwice { link, .. } | EmptyLink { link } => Some(link),
            JointOnNoLink { joint } | SliderLinks { joint, .. } | BadGuide { joint, .. } => {
                Some(joint)
            }
            Disconnected { links } | RigidLoop { links } => links.first(),
            CoincidentPins { joints, .. } => joints.get(1),
            Dangling { link, .. } => Some(link),
            RigidPair { links, .. } => links.get(1),
            _ => None,
        };
        let driver = match error {
            UnknownDriverJoint { .. }
            | DriverNotOnOneLink { .. }
            | DrivenLinkLocked { .. }
            | NotASlide { .. }
            | SlideWithoutRange { .. }
            | BadDrive { .. }
            | Mobility { .. } => self.driver_places.first(),
            DrivenTwice { .. } => self.driver_places.last(),
            _ => None,
        };
        let traced = match error {
            UnknownTrace { name } => self
                .trace_places
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, r)| r),
            TracedTwice { name } => (self.trace_places.iter())
                .filter(|(n, _)| n == name)
                .nth(1)
                .map(|(_, r)| r),
            _ => None,
        };
        let at = (name.and_then(|n| self.places.get(n)))
            .or(driver)
            .or(traced)
            .cloned()
            .unwrap_or_else(|| self.links_place.clone());
        FileError::new(text, at, error.to_string())
    }
}

impl Reader<'_> {
    /// The document's keys, into a topology file.
    fn topology(&mut self, mut root: Table<'_, '_>) -> Option<TopologyFile> {
        let name = root.require(
            self,
            "name",
            "the mechanism's name, such as name = \"FourBar\"",
        );
        let title = root.take("title");
        let length = root.take("length_unit");
        let ground = root.take("ground");
        let joints = root.require(
            self,
            "joints",
            "a [joints] table: where each joint is drawn",
        );
        let links = root.require(
            self,
            "links",
            "a [links] table: the joints each link carries",
        );
        let drive = root.require(
            self,
            "drive",
            "a [[drive]] for each driver: `angle = [\"A\", \"B\"]` or `slide = \"S\"`",
        );
        let lengths = root.take("lengths");
        let trace = root.take("trace");
        root.finish(self);
        let unit = match length {
            Some(v) => {
                let text = self.string("length_unit", v)?;
                match units::lookup(text) {
                    Some(u) if u.kind == Kind::Length => Some(u),
                    _ => {
                        self.error(
                            v.span(),
                            format!(
                                "`length_unit` must be a unit of length ({}), not `{text}`",
                                units::of_kind(Kind::Length)
                            ),
                        );
                        None
                    }
                }
            }
            None => units::lookup("m"),
        };
        let unit = unit?;
        let name = name.and_then(|v| {
            let text = self.string("name", v)?;
            self.identifier(text, v.span()).map(|n| n.text)
        });
        let mut topology =
            Topology::new(name.as_deref().unwrap_or("Mechanism")).length_unit(unit.name);
        if let Some(title) = title.and_then(|v| self.string("title", v)) {
            topology.title = Some(title.to_owned());
        }
        if let Some(g) = ground.and_then(|v| self.string("ground", v)) {
            topology.ground = g.to_owned();
        }
        let mut places = HashMap::new();
        if let Some(value) = joints {
            self.joints(value, unit, &mut topology, &mut places);
        }
        let links_place = links.map_or(0..0, |v| v.span());
        if let Some(value) = links {
            self.links(value, &mut topology, &mut places);
        }
        let mut driver_places = Vec::new();
        if let Some(value) = drive {
            self.drivers(value, unit, &mut topology, &mut driver_places);
        }
        if let Some(value) = lengths {
            self.given_lengths(value, unit, &mut topology);
        }
        let mut trace_places = Vec::new();
        if let Some(value) = trace
            && let Some(names) = self.names("trace", value)
        {
            topology.trace = names.iter().map(|(n, _)| n.clone()).collect();
            trace_places = names;
        }
        name?;
        Some(TopologyFile {
            topology,
            places,
            driver_places,
            links_place,
            trace_places,
        })
    }

    /// `[joints]`: `A = [x, y]` or `S = { at = [x, y], slider = angle }`.
    fn joints(
        &mut self,
        value: &Value<'_>,
        unit: Unit,
        topology: &mut Topology,
        places: &mut HashMap<String, Range<usize>>,
    ) {
        let mut guides: Vec<(String, String)> = Vec::new();
        let Some(table) = self.table("joints", "a table of joints: `A = [x, y]`", value) else {
            return;
        };
        for (key, span, value) in table.all() {
            let place = table.place(key);
            let Some(name) = self.identifier(key, span.clone()) else {
                continue;
            };
            let (at, kind) = match value.get_ref() {
                DeValue::Table(_) => {
                    let Some(mut t) = self.table(&place, "a joint", value) else {
                        continue;
                    };
                    let at = t.require(self, "at", "where the joint is drawn: `at = [x, y]`");
                    let slider = t.take("slider");
                    let slot = t.take("slot");
                    let guide = t.take("guide");
                    t.finish(self);
                    if let Some(v) = guide
                        && let Some(g) = self.string(&format!("{place}.guide"), v)
                    {
                        guides.push((name.text.clone(), g.to_owned()));
                    }
                    let angle = |reader: &mut Self, key: &str, v: &Value<'_>| {
                        reader
                            .quantity(&format!("{place}.{key}"), v, Accept::ANGLE, unit)
                            .map(|q| q.value)
                    };
                    let kind = match (slider, slot) {
                        (Some(_), Some(s)) => {
                            self.error(
                                s.span(),
                                format!("`{place}` is a slider or a slot, not both"),
                            );
                            None
                        }
                        (Some(v), None) => {
                            angle(self, "slider", v).map(|angle| JointKind::Prismatic { angle })
                        }
                        (None, Some(v)) => {
                            angle(self, "slot", v).map(|angle| JointKind::PinInSlot { angle })
                        }
                        (None, None) => Some(JointKind::Revolute),
                    };
                    (
                        at.and_then(|v| {
                            self.position(&format!("{place}.at"), v, unit)
                                .map(|[x, y]| [x.value, y.value])
                        }),
                        kind,
                    )
                }
                _ => (
                    self.position(&place, value, unit)
                        .map(|[x, y]| [x.value, y.value]),
                    Some(JointKind::Revolute),
                ),
            };
            if let (Some(at), Some(kind)) = (at, kind) {
                places.insert(name.text.clone(), span);
                let guide = (guides.iter())
                    .find(|(j, _)| *j == name.text)
                    .map(|(_, g)| g.clone());
                topology.joints.push(crate::topology::Joint {
                    name: name.text,
                    kind,
                    at,
                    guide,
                });
            }
        }
    }

    /// `[links]`: `crank = ["A", "B"]`.
    fn links(
        &mut self,
        value: &Value<'_>,
        topology: &mut Topology,
        places: &mut HashMap<String, Range<usize>>,
    ) {
        let Some(table) = self.table("links", "a table of links: `crank = [\"A\", \"B\"]`", value)
        else {
            return;
        };
        for (key, span, value) in table.all() {
            let Some(name) = self.identifier(key, span.clone()) else {
                continue;
            };
            let Some(joints) = self.names(&table.place(key), value) else {
                continue;
            };
            places.entry(name.text.clone()).or_insert(span);
            topology.links.push(crate::topology::Link {
                name: name.text,
                joints: joints.into_iter().map(|(n, _)| n).collect(),
            });
        }
    }

    /// `[[drive]]`: one table per driver.
    fn drivers(
        &mut self,
        value: &Value<'_>,
        unit: Unit,
        topology: &mut Topology,
        places: &mut Vec<Range<usize>>,
    ) {
        let Some(array) = self.array("drive", "an array of [[drive]] tables", value) else {
            return;
        };
        for (k, item) in array.iter().enumerate() {
            let place = format!("drive[{k}]");
            let Some(mut t) = self.table(
                &place,
                "a driver: `angle = [\"A\", \"B\"]` or `slide = \"S\"`",
                item,
            ) else {
                continue;
            };
            let angle = t.take("angle");
            let slide = t.take("slide");
            let from = t.take("from");
            let to = t.take("to");
            let steps = t.take("steps");
            let rate = t.take("rate");
            let at = t.take("at");
            let span = t.span();
            t.finish(self);
            let driven = match (angle, slide) {
                (Some(v), None) => self.names(&format!("{place}.angle"), v).and_then(|names| match &names[..] {
                    [(a, _), (b, _)] => Some(Driven::Angle { from: a.clone(), to: b.clone() }),
                    _ => {
                        self.error(v.span(), format!("`{place}.angle` must name two joints: [\"A\", \"B\"], the line A→B"));
                        None
                    }
                }),
                (None, Some(v)) => self.string(&format!("{place}.slide"), v).map(|j| Driven::Slide { joint: j.to_owned() }),
                (Some(_), Some(v)) => {
                    self.error(v.span(), format!("`{place}` drives an angle or a slide, not both"));
                    None
                }
                (None, None) => {
                    self.error(span.clone(), format!("`{place}` says neither `angle = [\"A\", \"B\"]` nor `slide = \"S\"`"));
                    None
                }
            };
            let accept = match driven {
                Some(Driven::Slide { .. }) => Accept::LENGTH,
                _ => Accept::ANGLE,
            };
            let quantity = |reader: &mut Self, key: &str, v: Option<&Value<'_>>, accept| {
                v.map(|v| {
                    reader
                        .quantity(&format!("{place}.{key}"), v, accept, unit)
                        .map(|q| q.value)
                })
            };
            let from = quantity(self, "from", from, accept);
            let to = quantity(self, "to", to, accept);
            let at = quantity(self, "at", at, accept);
            let rate = quantity(self, "rate", rate, Accept::RATE);
            let steps = steps
                .map(|v| self.count(&format!("{place}.steps"), v, 1, super::MOST_STEPS as u64));
            let range = match (from, to) {
                (Some(Some(f)), Some(Some(t))) => Some([f, t]),
                (None, None) => None,
                (Some(None), _) | (_, Some(None)) => None,
                (Some(_), None) | (None, Some(_)) => {
                    self.error(
                        span.clone(),
                        format!(
                            "`{place}` gives one end of its range: give `from` and `to`, or neither"
                        ),
                    );
                    None
                }
            };
            if let Some(driven) = driven {
                places.push(span);
                topology.drivers.push(Driver {
                    driven,
                    range,
                    steps: steps.flatten(),
                    rate: rate.flatten(),
                    at: at.flatten(),
                });
            }
        }
    }

    /// `[lengths]`: `A-B = 20`.
    fn given_lengths(&mut self, value: &Value<'_>, unit: Unit, topology: &mut Topology) {
        let Some(table) = self.table("lengths", "a table of lengths: `A-B = 20`", value) else {
            return;
        };
        for (key, span, value) in table.all() {
            let Some((a, b)) = key.split_once('-') else {
                self.error(span, format!("`{key}` must name two joints: `A-B`"));
                continue;
            };
            if let Some(q) = self.quantity(&table.place(key), value, Accept::LENGTH, unit) {
                topology.lengths.push((a.to_owned(), b.to_owned(), q.value));
            }
        }
    }
}

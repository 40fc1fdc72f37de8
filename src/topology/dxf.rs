//! A topology's pose and its links for CAD, as DXF (release 12, ASCII,
//! which every CAD program and laser cutter reads): each link an outline
//! around its joints (a bar's two ends rounded, a plate the rounded hull
//! of its joints) with a hole at every pin through it, one layer per link,
//! the drawing's units in the header; the paths of points as polylines;
//! and a cut sheet with every moving link laid flat and labelled. A pin
//! running in a slot of a moving link has its slot cut, a hole's width
//! wide and as long as the pin travels over a cycle; a slider's guide is
//! the link itself.
//!
//! Coordinates are written as Rust writes an f64 (the shortest text that
//! reads back to it): a reader gets the pose's numbers exactly.

use super::model::{JointKind, Topology};
use std::fmt::Write;

/// The positions of a topology's joints at each pose of a cycle.
pub type Cycle<'a> = &'a [Vec<(String, [f64; 2])>];

/// The sizes of the parts drawn: a link's width (its outline lies
/// `width / 2` around its pins) and the pins' holes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DxfOptions {
    pub width: f64,
    pub hole_diameter: f64,
}

impl DxfOptions {
    /// For a mechanism of this size: links a twentieth of it wide, holes
    /// two fifths of a link's width.
    pub fn for_size(size: f64) -> DxfOptions {
        let width = size / 20.0;
        DxfOptions {
            width,
            hole_diameter: 0.4 * width,
        }
    }
}

/// DXF's code for a length unit ($INSUNITS).
fn insunits(unit: &str) -> u8 {
    match unit {
        "in" => 1,
        "ft" => 2,
        "mm" => 4,
        "cm" => 5,
        "m" => 6,
        _ => 0,
    }
}

/// The positions of a topology's joints at a pose, by name.
pub type Positions<'a> = &'a [(String, [f64; 2])];

fn at(positions: Positions<'_>, name: &str) -> Option<[f64; 2]> {
    positions.iter().find(|(n, _)| n == name).map(|(_, p)| *p)
}

/// A DXF document being written: layers, then entities.
struct Document {
    layers: Vec<String>,
    entities: String,
}

fn number(x: f64) -> String {
    super::generate::number(if x == 0.0 { 0.0 } else { x })
}

impl Document {
    fn new() -> Document {
        Document {
            layers: Vec::new(),
            entities: String::new(),
        }
    }

    fn layer(&mut self, name: &str) {
        if !self.layers.iter().any(|l| l == name) {
            self.layers.push(name.to_owned());
        }
    }

    fn circle(&mut self, layer: &str, centre: [f64; 2], radius: f64) {
        self.layer(layer);
        let _ = write!(
            self.entities,
            "0\nCIRCLE\n8\n{layer}\n10\n{}\n20\n{}\n30\n0.0\n40\n{}\n",
            number(centre[0]),
            number(centre[1]),
            number(radius)
        );
    }

    /// A polyline through `(point, bulge)` vertices (bulge: the tangent of
    /// a quarter of the arc's angle to the next vertex, 0 for a line).
    fn polyline(&mut self, layer: &str, vertices: &[([f64; 2], f64)], closed: bool) {
        self.layer(layer);
        let _ = write!(
            self.entities,
            "0\nPOLYLINE\n8\n{layer}\n66\n1\n10\n0.0\n20\n0.0\n30\n0.0\n70\n{}\n",
            u8::from(closed)
        );
        for (p, bulge) in vertices {
            let _ = write!(
                self.entities,
                "0\nVERTEX\n8\n{layer}\n10\n{}\n20\n{}\n30\n0.0\n",
                number(p[0]),
                number(p[1])
            );
            if *bulge != 0.0 {
                let _ = write!(self.entities, "42\n{}\n", number(*bulge));
            }
        }
        let _ = write!(self.entities, "0\nSEQEND\n8\n{layer}\n");
    }

    fn text(&mut self, layer: &str, at: [f64; 2], height: f64, text: &str) {
        self.layer(layer);
        let _ = write!(
            self.entities,
            "0\nTEXT\n8\n{layer}\n10\n{}\n20\n{}\n30\n0.0\n40\n{}\n1\n{text}\n",
            number(at[0]),
            number(at[1]),
            number(height)
        );
    }

    /// The whole file, in `unit`.
    fn finish(self, unit: &str) -> String {
        let mut out = String::new();
        let _ = write!(
            out,
            "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n{}\n0\nENDSEC\n",
            insunits(unit)
        );
        out.push_str("0\nSECTION\n2\nTABLES\n");
        out.push_str("0\nTABLE\n2\nLTYPE\n70\n1\n0\nLTYPE\n2\nCONTINUOUS\n70\n0\n3\nSolid line\n72\n65\n73\n0\n40\n0.0\n0\nENDTAB\n");
        let _ = write!(out, "0\nTABLE\n2\nLAYER\n70\n{}\n", self.layers.len() + 1);
        out.push_str("0\nLAYER\n2\n0\n70\n0\n62\n7\n6\nCONTINUOUS\n");
        for (k, layer) in self.layers.iter().enumerate() {
            // A colour each, from AutoCAD's first seven.
            let _ = write!(
                out,
                "0\nLAYER\n2\n{layer}\n70\n0\n62\n{}\n6\nCONTINUOUS\n",
                1 + k % 7
            );
        }
        out.push_str("0\nENDTAB\n");
        out.push_str("0\nTABLE\n2\nSTYLE\n70\n1\n0\nSTYLE\n2\nSTANDARD\n70\n0\n40\n0.0\n41\n1.0\n50\n0.0\n71\n0\n42\n2.5\n3\ntxt\n4\n\n0\nENDTAB\n");
        out.push_str("0\nENDSEC\n0\nSECTION\n2\nENTITIES\n");
        out.push_str(&self.entities);
        out.push_str("0\nENDSEC\n0\nEOF\n");
        out
    }
}

/// The convex hull of `points`, counter-clockwise, without collinear
/// points (Andrew's monotone chain).
fn hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    sorted.dedup();
    if sorted.len() < 3 {
        return sorted;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut lower: Vec<[f64; 2]> = Vec::new();
    for &p in &sorted {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<[f64; 2]> = Vec::new();
    for &p in sorted.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// The outline `radius` around the hull of `pins`: straight sides offset
/// outwards, joined by arcs about the hull's corners (a bar's rounded
/// ends), as polyline vertices with bulges.
fn outline(pins: &[[f64; 2]], radius: f64) -> Vec<([f64; 2], f64)> {
    let corners = hull(pins);
    match corners[..] {
        [] => Vec::new(),
        [c] => vec![([c[0] - radius, c[1]], 1.0), ([c[0] + radius, c[1]], 1.0)],
        _ => {
            let k = corners.len();
            let normal = |i: usize| {
                let (a, b) = (corners[i], corners[(i + 1) % k]);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let length = dx.hypot(dy);
                [dy / length, -dx / length]
            };
            let mut vertices = Vec::new();
            for (i, &c) in corners.iter().enumerate() {
                let (before, after) = (normal((i + k - 1) % k), normal(i));
                // The exterior angle of a convex corner, in (0, π].
                let mut turn = (before[0] * after[1] - before[1] * after[0])
                    .atan2(before[0] * after[0] + before[1] * after[1]);
                if turn <= 0.0 {
                    turn += 2.0 * std::f64::consts::PI;
                }
                vertices.push((
                    [c[0] + radius * before[0], c[1] + radius * before[1]],
                    (turn / 4.0).tan(),
                ));
                vertices.push(([c[0] + radius * after[0], c[1] + radius * after[1]], 0.0));
            }
            vertices
        }
    }
}

/// The joints of a link whose positions are known, one a place, and
/// whether each is a pin through it (a hole): a pin joining it to another
/// link, or a pin in a slot on its pin's side. A point of it alone (a
/// coupler point) shapes its outline without a hole; a slider's line and a
/// slot are no holes.
fn pins_of(
    topology: &Topology,
    link: usize,
    positions: Positions<'_>,
) -> Vec<(String, [f64; 2], bool)> {
    let this = &topology.links[link].name;
    let mut pins: Vec<(String, [f64; 2], bool)> = Vec::new();
    for name in &topology.links[link].joints {
        let Some(p) = at(positions, name) else {
            continue;
        };
        let Some(joint) = topology.joints.iter().find(|j| j.name == *name) else {
            continue;
        };
        let links = topology
            .links
            .iter()
            .filter(|l| l.joints.contains(name))
            .count();
        let hole = match joint.kind {
            JointKind::Revolute => links > 1,
            JointKind::PinInSlot { .. } => joint.guide.as_deref().is_some_and(|g| g != this),
            JointKind::Prismatic { .. } => false,
        };
        match pins
            .iter_mut()
            .find(|(_, q, _)| (q[0] - p[0]).hypot(q[1] - p[1]) < 1e-12)
        {
            Some(same) => same.2 |= hole,
            None => pins.push((name.clone(), p, hole)),
        }
    }
    pins
}

impl Topology {
    /// The pose whose joints are at `positions` as DXF: each moving link
    /// an outline on its own layer with a hole at each pin and a slot for
    /// each pin that runs in it (as long as the pin travels over `cycle`,
    /// the joints' positions at each pose of a cycle), the frame's pivots
    /// as holes on the layer of the frame, and the path over `cycle` of
    /// each traced point as a polyline on a layer `path_<name>`.
    pub fn pose_dxf(
        &self,
        positions: Positions<'_>,
        cycle: Cycle<'_>,
        options: &DxfOptions,
    ) -> String {
        let mut document = Document::new();
        let radius = options.width / 2.0;
        let slots = self.slots(positions, cycle);
        for (l, link) in self.links.iter().enumerate() {
            let pins = pins_of(self, l, positions);
            let ends = slots
                .iter()
                .filter(|(g, _)| *g == link.name)
                .flat_map(|(_, e)| e.iter().copied());
            if link.name != self.ground {
                let places: Vec<[f64; 2]> = pins.iter().map(|(_, p, _)| *p).chain(ends).collect();
                document.polyline(&link.name, &outline(&places, radius), true);
            }
            for (_, p, hole) in &pins {
                if *hole {
                    document.circle(&link.name, *p, options.hole_diameter / 2.0);
                }
            }
        }
        for (link, ends) in &slots {
            document.polyline(link, &outline(ends, options.hole_diameter / 2.0), true);
        }
        for name in &self.trace {
            let path: Vec<([f64; 2], f64)> = cycle
                .iter()
                .filter_map(|pose| at(pose, name))
                .map(|p| (p, 0.0))
                .collect();
            if path.len() > 1 {
                document.polyline(&format!("path_{name}"), &path, false);
            }
        }
        document.finish(&self.length_unit)
    }

    /// The slots of moving links, in the coordinates of the pose at
    /// `positions`: for each pin in a slot of a moving link, the two ends
    /// (one where the pin does not travel) of its travel along the slot's
    /// line over `cycle`, the guide link's name first.
    fn slots(&self, positions: Positions<'_>, cycle: Cycle<'_>) -> Vec<(String, Vec<[f64; 2]>)> {
        let mut slots = Vec::new();
        for joint in &self.joints {
            let (JointKind::PinInSlot { angle }, Some(guide)) = (joint.kind, &joint.guide) else {
                continue;
            };
            let Some(link) = self
                .links
                .iter()
                .find(|l| l.name == *guide && l.name != self.ground)
            else {
                continue;
            };
            // The guide's frame: two of its other joints, apart as drawn.
            let drawn = |name: &str| self.joints.iter().find(|j| j.name == name).map(|j| j.at);
            let others: Vec<&String> = link.joints.iter().filter(|n| **n != joint.name).collect();
            let frame = others.iter().enumerate().find_map(|(k, a)| {
                others[k + 1..].iter().find_map(|b| {
                    let (pa, pb) = (drawn(a)?, drawn(b)?);
                    ((pb[0] - pa[0]).hypot(pb[1] - pa[1]) > 1e-9)
                        .then(|| ((*a).clone(), (*b).clone(), pa, pb))
                })
            });
            let Some((a, b, pa, pb)) = frame else {
                continue;
            };
            // The slot's direction in the guide's frame, as drawn.
            let along = angle - (pb[1] - pa[1]).atan2(pb[0] - pa[0]);
            let (dir, normal) = ([along.cos(), along.sin()], [-along.sin(), along.cos()]);
            let local = |pose: Positions<'_>| -> Option<([f64; 2], f64, [f64; 2])> {
                let (o, r, pin) = (at(pose, &a)?, at(pose, &b)?, at(pose, &joint.name)?);
                let turn = (r[1] - o[1]).atan2(r[0] - o[0]);
                let (s, c) = turn.sin_cos();
                let d = [pin[0] - o[0], pin[1] - o[1]];
                Some((o, turn, [c * d[0] + s * d[1], -s * d[0] + c * d[1]]))
            };
            let travels: Vec<f64> = (cycle.iter())
                .filter_map(|pose| local(pose))
                .map(|(_, _, p)| p[0] * dir[0] + p[1] * dir[1])
                .collect();
            let Some((origin, turn, here)) = local(positions) else {
                continue;
            };
            let offset = here[0] * normal[0] + here[1] * normal[1];
            let here_travel = here[0] * dir[0] + here[1] * dir[1];
            let least = travels.iter().copied().fold(here_travel, f64::min);
            let most = travels.iter().copied().fold(here_travel, f64::max);
            let (s, c) = turn.sin_cos();
            let world = |t: f64| {
                let l = [
                    t * dir[0] + offset * normal[0],
                    t * dir[1] + offset * normal[1],
                ];
                [
                    origin[0] + c * l[0] - s * l[1],
                    origin[1] + s * l[0] + c * l[1],
                ]
            };
            slots.push((link.name.clone(), vec![world(least), world(most)]));
        }
        slots
    }

    /// Every moving link of the pose at `positions` laid flat for cutting:
    /// turned so that its two farthest pins lie along x, side by side with
    /// a link's width between them, each labelled with its name (layer
    /// `labels`), its outline and holes on its own layer.
    pub fn cut_sheet_dxf(
        &self,
        positions: Positions<'_>,
        cycle: Cycle<'_>,
        options: &DxfOptions,
    ) -> String {
        let mut document = Document::new();
        let radius = options.width / 2.0;
        let slots = self.slots(positions, cycle);
        let mut x = 0.0;
        for (l, link) in self.links.iter().enumerate() {
            if link.name == self.ground {
                continue;
            }
            let pins = pins_of(self, l, positions);
            let Some(&(_, first, _)) = pins.first() else {
                continue;
            };
            // Along the line of its two farthest pins.
            let mut angle = 0.0;
            let mut far = 0.0;
            for (a, (_, p, _)) in pins.iter().enumerate() {
                for (_, q, _) in &pins[a + 1..] {
                    let d = (q[0] - p[0]).hypot(q[1] - p[1]);
                    if d > far {
                        far = d;
                        angle = (q[1] - p[1]).atan2(q[0] - p[0]);
                    }
                }
            }
            let (s, c) = (-angle).sin_cos();
            let turn = |p: [f64; 2]| {
                let (dx, dy) = (p[0] - first[0], p[1] - first[1]);
                [c * dx - s * dy, s * dx + c * dy]
            };
            let slot_ends: Vec<Vec<[f64; 2]>> = (slots.iter())
                .filter(|(g, _)| *g == link.name)
                .map(|(_, ends)| ends.iter().map(|p| turn(*p)).collect())
                .collect();
            let turned: Vec<[f64; 2]> = (pins.iter())
                .map(|(_, p, _)| turn(*p))
                .chain(slot_ends.iter().flatten().copied())
                .collect();
            let min_x = turned.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
            let max_x = turned
                .iter()
                .map(|p| p[0])
                .fold(f64::NEG_INFINITY, f64::max);
            let min_y = turned.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
            let shift = [x - min_x + radius, -min_y + radius];
            let placed: Vec<[f64; 2]> = turned
                .iter()
                .map(|p| [p[0] + shift[0], p[1] + shift[1]])
                .collect();
            document.polyline(&link.name, &outline(&placed, radius), true);
            for (p, (_, _, hole)) in placed.iter().zip(&pins) {
                if *hole {
                    document.circle(&link.name, *p, options.hole_diameter / 2.0);
                }
            }
            for ends in &slot_ends {
                let laid: Vec<[f64; 2]> = ends
                    .iter()
                    .map(|p| [p[0] + shift[0], p[1] + shift[1]])
                    .collect();
                document.polyline(
                    &link.name,
                    &outline(&laid, options.hole_diameter / 2.0),
                    true,
                );
            }
            document.text(
                "labels",
                [x, -1.5 * options.width],
                0.6 * options.width,
                &link.name,
            );
            x += (max_x - min_x) + 2.0 * radius + options.width;
        }
        document.finish(&self.length_unit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn a_bars_outline_is_rounded_at_both_ends() {
        let o = outline(&[[0.0, 0.0], [10.0, 0.0]], 1.0);
        assert_eq!(o.len(), 4);
        // Half turns at each end, straight sides between.
        assert!((o[0].1 - 1.0).abs() < 1e-15 && o[1].1 == 0.0);
        assert!((o[2].1 - 1.0).abs() < 1e-15 && o[3].1 == 0.0);
        for (p, _) in &o {
            let d = p[1].abs();
            assert!((d - 1.0).abs() < 1e-15, "{p:?}");
        }
    }

    #[test]
    fn a_plates_outline_turns_once_around_its_hull() {
        let pins = [[0.0, 0.0], [4.0, 0.0], [2.0, 3.0], [2.0, 1.0]];
        let o = outline(&pins, 0.5);
        assert_eq!(o.len(), 6, "the inner pin is not on the hull");
        let total: f64 = o.iter().map(|(_, b)| 4.0 * b.atan()).sum();
        assert!((total - 2.0 * PI).abs() < 1e-12);
    }

    #[test]
    fn collinear_pins_make_a_bar() {
        assert_eq!(
            hull(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
            [[0.0, 0.0], [2.0, 2.0]]
        );
    }
}

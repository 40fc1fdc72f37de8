//! The drawing symbols of a scene: traced paths, guides, links and
//! plates, slider blocks, joints and points, ground pivots. (Arrows are in
//! `arrows.rs`, labels in `labels.rs`, the legend in `legend.rs`.)

use super::geometry::{Capsule, Rect};
use super::layout::{Layout, Placed};
use super::motion::Motion;
use super::style;
use super::{Frame, Scene, SceneError, Shape, Slider, Slideway, resolve};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;
use std::fmt::Write as _;

/// A straight guide on the screen: the path of its block's centre from
/// `a` to `b`, hatched on the side `normal` points to.
pub(super) struct Guide {
    point: String,
    a: Vector2<f64>,
    b: Vector2<f64>,
    normal: Vector2<f64>,
}

impl Guide {
    fn new(point: &str, a: Vector2<f64>, b: Vector2<f64>) -> Guide {
        let dir = (b - a).try_normalize(1e-12).unwrap_or(Vector2::x());
        // The side away from the block: below on the screen for a level
        // guide.
        let mut normal = Vector2::new(-dir.y, dir.x);
        if normal.y < 0.0 {
            normal = -normal;
        }
        Guide {
            point: point.into(),
            a,
            b,
            normal,
        }
    }

    /// The band the guide's line and hatching cover.
    pub(super) fn hatched_band(&self) -> Capsule {
        let middle = self.normal * (style::GUIDE_OFFSET + style::GUIDE_HATCH / 2.0);
        Capsule {
            a: self.a + middle,
            b: self.b + middle,
            radius: style::GUIDE_HATCH / 2.0 + 1.5,
        }
    }
}

impl Scene {
    /// Each traced point's path over the cycle, on the screen.
    pub(super) fn trace_paths(
        &self,
        layout: &Layout,
        cycle: &[Frame],
    ) -> Result<Vec<Vec<Vector2<f64>>>, SceneError> {
        if cycle.is_empty() {
            return Ok(Vec::new());
        }
        self.traces
            .iter()
            .map(|name| {
                cycle
                    .iter()
                    .map(|frame| Ok(layout.screen(resolve(frame, name, &self.ground)?)))
                    .collect()
            })
            .collect()
    }

    /// The traced paths, each in its own style (`style::trace`).
    pub(super) fn draw_traces(&self, w: &mut Writer, paths: &[Vec<Vector2<f64>>]) {
        for (k, (name, path)) in self.traces.iter().zip(paths).enumerate() {
            let mut d = String::new();
            for (i, p) in path.iter().enumerate() {
                let _ = write!(
                    d,
                    "{}{} {} ",
                    if i == 0 { "M" } else { "L" },
                    fmt(p.x),
                    fmt(p.y)
                );
            }
            let look = style::trace(k);
            w.element(
                "path",
                &[
                    ("id", &format!("trace-{name}")),
                    ("class", "trace"),
                    ("d", d.trim_end()),
                    ("fill", "none"),
                    ("stroke", look.colour),
                    ("stroke-width", &fmt(style::TRACE_WIDTH)),
                    ("stroke-dasharray", look.dashes),
                ],
            );
        }
    }

    /// Each slider's guide, long enough for its whole stroke.
    pub(super) fn guides(
        &self,
        layout: &Layout,
        frames: &[Frame],
        cycle: &[Frame],
    ) -> Result<Vec<Guide>, SceneError> {
        let mut guides = Vec::new();
        for slider in self.sliders.iter().filter(|s| s.guide == Slideway::Ground) {
            let dir = Vector2::new(slider.angle.cos(), slider.angle.sin());
            let mut range = (f64::INFINITY, f64::NEG_INFINITY);
            let mut origin = None;
            for frame in frames.iter().chain(cycle) {
                let p = resolve(frame, &slider.point, &self.ground)?;
                let o = *origin.get_or_insert(p);
                let s = (p - o).dot(&dir);
                range = (range.0.min(s), range.1.max(s));
            }
            let Some(o) = origin else { continue };
            let pad = 26.0 / layout.scale;
            let a = layout.screen(o + dir * (range.0 - pad));
            let b = layout.screen(o + dir * (range.1 + pad));
            guides.push(Guide::new(&slider.point, a, b));
        }
        Ok(guides)
    }

    pub(super) fn draw_links(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        for (i, body) in self.shapes.iter().enumerate() {
            match body {
                Shape::Bar([a, b]) => {
                    let (p, q) = (at.get(a), at.get(b));
                    let id = format!("link-{a}-{b}");
                    w.open(
                        "line",
                        &[
                            ("id", &id),
                            ("class", "link"),
                            ("x1", &fmt(p.x)),
                            ("y1", &fmt(p.y)),
                            ("x2", &fmt(q.x)),
                            ("y2", &fmt(q.y)),
                            ("stroke", style::BAR),
                            ("stroke-width", &fmt(style::BAR_WIDTH)),
                            ("stroke-linecap", "round"),
                        ],
                    );
                    if let Some(m) = motion {
                        m.animate(w, "x1", |f| fmt(f.get(a).x));
                        m.animate(w, "y1", |f| fmt(f.get(a).y));
                        m.animate(w, "x2", |f| fmt(f.get(b).x));
                        m.animate(w, "y2", |f| fmt(f.get(b).y));
                    }
                    w.close("line");
                }
                Shape::Plate(corners) => {
                    let points = |f: &Placed| {
                        corners
                            .iter()
                            .map(|c| {
                                let p = f.get(c);
                                format!("{},{}", fmt(p.x), fmt(p.y))
                            })
                            .collect::<Vec<_>>()
                            .join(" ")
                    };
                    w.open(
                        "polygon",
                        &[
                            ("id", &format!("plate-{i}")),
                            ("class", "link"),
                            ("points", &points(at)),
                            ("fill", style::PLATE_FILL),
                            ("stroke", style::BAR),
                            ("stroke-width", "3"),
                            ("stroke-linejoin", "round"),
                        ],
                    );
                    if let Some(m) = motion {
                        m.animate(w, "points", points);
                    }
                    w.close("polygon");
                }
            }
        }
    }

    pub(super) fn draw_sliders(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        for slider in &self.sliders {
            let p = at.get(&slider.point);
            let translate = |p: Vector2<f64>| format!("{} {}", fmt(p.x), fmt(p.y));
            w.open(
                "g",
                &[
                    ("id", &format!("slider-{}", slider.point)),
                    ("class", "slider"),
                    ("transform", &format!("translate({})", translate(p))),
                ],
            );
            if let Some(m) = motion {
                let values: Vec<String> = m
                    .frames
                    .iter()
                    .map(|f| translate(f.get(&slider.point)))
                    .collect();
                w.element(
                    "animateTransform",
                    &[
                        ("attributeName", "transform"),
                        ("type", "translate"),
                        ("dur", &format!("{}s", fmt(m.seconds))),
                        ("repeatCount", "indefinite"),
                        ("calcMode", "linear"),
                        ("values", &values.join(";")),
                    ],
                );
            }
            let degrees = |f: &Placed| block_degrees(slider, f);
            w.open(
                "g",
                &[("transform", &format!("rotate({})", fmt(degrees(at))))],
            );
            if let (Some(m), Slideway::Link(_)) = (motion, &slider.guide) {
                // Unwrapped, so that the block does not spin round at ±180°.
                let mut previous: Option<f64> = None;
                let values: Vec<String> = m
                    .frames
                    .iter()
                    .map(|f| {
                        let mut a = degrees(f);
                        if let Some(p) = previous {
                            a += 360.0 * ((p - a) / 360.0).round();
                        }
                        previous = Some(a);
                        fmt(a)
                    })
                    .collect();
                w.element(
                    "animateTransform",
                    &[
                        ("attributeName", "transform"),
                        ("type", "rotate"),
                        ("dur", &format!("{}s", fmt(m.seconds))),
                        ("repeatCount", "indefinite"),
                        ("calcMode", "linear"),
                        ("values", &values.join(";")),
                    ],
                );
            }
            let (half_length, half_height) = style::BLOCK_HALF;
            w.element(
                "rect",
                &[
                    ("x", &fmt(-half_length)),
                    ("y", &fmt(-half_height)),
                    ("width", &fmt(2.0 * half_length)),
                    ("height", &fmt(2.0 * half_height)),
                    ("rx", "2"),
                    ("fill", style::PLATE_FILL),
                    ("stroke", style::BAR),
                    ("stroke-width", "2.2"),
                ],
            );
            w.close("g");
            w.close("g");
        }
    }

    /// Joints (ends of links, pivots, sliders) as open circles; other
    /// points as dots.
    pub(super) fn draw_points(&self, w: &mut Writer, at: &Placed, motion: Option<&Motion>) {
        let joints: Vec<&String> = self
            .shapes
            .iter()
            .flat_map(|b| match b {
                Shape::Bar(ends) => ends.as_slice(),
                Shape::Plate(corners) => corners.as_slice(),
            })
            .chain(self.ground.iter().map(|(n, _)| n))
            .chain(self.sliders.iter().map(|s| &s.point))
            .collect();
        for (name, p) in &at.points {
            let joint = joints.contains(&name);
            w.open(
                "circle",
                &[
                    ("id", &format!("point-{name}")),
                    ("class", if joint { "joint" } else { "point" }),
                    ("cx", &fmt(p.x)),
                    ("cy", &fmt(p.y)),
                    (
                        "r",
                        &fmt(if joint {
                            style::JOINT_RADIUS
                        } else {
                            style::DOT_RADIUS
                        }),
                    ),
                    ("fill", if joint { "white" } else { style::INK }),
                    ("stroke", style::INK),
                    ("stroke-width", if joint { "1.8" } else { "0" }),
                ],
            );
            if let Some(m) = motion {
                m.animate(w, "cx", |f| fmt(f.get(name).x));
                m.animate(w, "cy", |f| fmt(f.get(name).y));
            }
            w.close("circle");
        }
    }
}

/// A slider block's angle on the screen, in degrees (y points down
/// there): its guide's, or that of the link it slides on.
pub(super) fn block_degrees(slider: &Slider, at: &Placed) -> f64 {
    match &slider.guide {
        Slideway::Link([a, b]) => {
            let d = at.get(b) - at.get(a);
            d.y.atan2(d.x).to_degrees()
        }
        _ => -slider.angle.rem_euclid(std::f64::consts::TAU).to_degrees(),
    }
}

/// A fixed pivot: a triangle under the joint on a hatched base.
pub(super) fn ground_symbol(w: &mut Writer, at: Vector2<f64>) {
    let (h, b) = (style::GROUND_HEIGHT, style::GROUND_HALF_WIDTH);
    let base_y = at.y + h;
    let mut d = format!(
        "M{} {} L{} {} L{} {} Z",
        fmt(at.x),
        fmt(at.y),
        fmt(at.x - b),
        fmt(base_y),
        fmt(at.x + b),
        fmt(base_y)
    );
    let mut hatch = format!(
        "M{} {} H{}",
        fmt(at.x - b - 5.0),
        fmt(base_y),
        fmt(at.x + b + 5.0)
    );
    // Strokes down to the left, every 5 px, within the base line's ends.
    let mut x = at.x - b + 1.0;
    while x <= at.x + b + 5.0 {
        let _ = write!(hatch, " M{} {} l-6 7", fmt(x), fmt(base_y));
        x += 5.0;
    }
    d.push(' ');
    w.element(
        "path",
        &[
            ("class", "ground"),
            ("d", d.trim_end()),
            ("fill", style::PLATE_FILL),
            ("stroke", style::INK),
            ("stroke-width", "1.4"),
            ("stroke-linejoin", "round"),
        ],
    );
    w.element(
        "path",
        &[
            ("class", "ground"),
            ("d", &hatch),
            ("fill", "none"),
            ("stroke", style::INK),
            ("stroke-width", "1.1"),
        ],
    );
}

/// The box a ground symbol at `at` covers (its triangle and hatching).
pub(super) fn ground_extent(at: Vector2<f64>) -> Rect {
    let (h, b) = (style::GROUND_HEIGHT, style::GROUND_HALF_WIDTH);
    Rect {
        min: Vector2::new(at.x - b - 6.0, at.y + 2.0),
        max: Vector2::new(at.x + b + 6.0, at.y + h + 8.0),
    }
}

/// A straight guide: its line, hatched on the side away from the block.
pub(super) fn guide_symbol(w: &mut Writer, guide: &Guide) {
    let along = guide.b - guide.a;
    let length = along.norm().max(1e-9);
    let dir = along / length;
    let normal = guide.normal;
    let offset = normal * style::GUIDE_OFFSET;
    let (a, b) = (guide.a + offset, guide.b + offset);
    let mut hatch = format!("M{} {} L{} {}", fmt(a.x), fmt(a.y), fmt(b.x), fmt(b.y));
    let mut s = 4.0;
    while s < length {
        let p = a + dir * s;
        let q = p + normal * style::GUIDE_HATCH - dir * 6.0;
        let _ = write!(
            hatch,
            " M{} {} L{} {}",
            fmt(p.x),
            fmt(p.y),
            fmt(q.x),
            fmt(q.y)
        );
        s += 6.0;
    }
    w.element(
        "path",
        &[
            ("id", &format!("guide-{}", guide.point)),
            ("class", "guide"),
            ("d", &hatch),
            ("fill", "none"),
            ("stroke", style::INK),
            ("stroke-width", "1.2"),
        ],
    );
}

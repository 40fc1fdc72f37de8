//! The drawing symbols of a scene: traces, guides, links and plates,
//! slider blocks, joints and points, velocity and acceleration arrows,
//! ground pivots, and the legend.
//!
//! Over 600 lines, as one idea: every element a scene draws, each a short
//! function that writes its SVG in the scene's style (the `style` module);
//! split further, the pieces would only share that style and the `Arrow`.

use super::animation::{Motion, animate_values};
use super::layout::{Layout, Placed, nice_below, number};
use super::{Frame, Scene, SceneError, Shape, Slideway, resolve, unknown};
use crate::draw::svg::{Writer, fmt};
use linkage_symbolic::names::textbook;
use nalgebra::Vector2;
use std::fmt::Write as _;

pub(super) mod style {
    pub const INK: &str = "#1b1b1b";
    pub const BAR: &str = "#3a4a5c";
    pub const PLATE_FILL: &str = "#dbe4ee";
    pub const VELOCITY: &str = "#2e7d32";
    pub const ACCELERATION: &str = "#c62828";
    pub const TRACE: &str = "#7b8794";
    pub const BAR_WIDTH: f64 = 5.0;
    pub const JOINT_RADIUS: f64 = 4.5;
    pub const DOT_RADIUS: f64 = 3.2;
    pub const ARROW_WIDTH: f64 = 2.2;
    pub const HEAD_LENGTH: f64 = 11.0;
    pub const HEAD_HALF_WIDTH: f64 = 4.2;
    pub const GROUND_HEIGHT: f64 = 14.0;
    pub const GROUND_HALF_WIDTH: f64 = 11.0;
    pub const MARGIN: f64 = 46.0;
    pub const LEGEND_LINE: f64 = 18.0;
    pub const FONT: &str = "DejaVu Serif, Georgia, 'Times New Roman', serif";
    /// The longest arrow of each kind, when its scale is chosen
    /// automatically, as a fraction of the mechanism's extent.
    pub const ARROW_FRACTION: f64 = 0.3;
}

impl Scene {
    pub(super) fn draw_traces(
        &self,
        w: &mut Writer,
        layout: &Layout,
        cycle: &[Frame],
    ) -> Result<(), SceneError> {
        if cycle.is_empty() {
            return Ok(());
        }
        for name in &self.traces {
            let mut d = String::new();
            for (i, frame) in cycle.iter().enumerate() {
                let p = layout.screen(resolve(frame, name, &self.ground)?);
                let _ = write!(
                    d,
                    "{}{} {} ",
                    if i == 0 { "M" } else { "L" },
                    fmt(p.x),
                    fmt(p.y)
                );
            }
            w.element(
                "path",
                &[
                    ("id", &format!("trace-{name}")),
                    ("class", "trace"),
                    ("d", d.trim_end()),
                    ("fill", "none"),
                    ("stroke", style::TRACE),
                    ("stroke-width", "1.2"),
                    ("stroke-dasharray", "5 3"),
                ],
            );
        }
        Ok(())
    }

    /// Each slider's guide, long enough for its whole stroke, hatched on
    /// one side.
    pub(super) fn draw_guides(
        &self,
        w: &mut Writer,
        layout: &Layout,
        frames: &[Frame],
        cycle: &[Frame],
    ) -> Result<(), SceneError> {
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
            guide_symbol(w, a, b, &slider.point);
        }
        Ok(())
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
            // The block's angle on the screen (y points down there).
            let degrees = |f: &Placed| match &slider.guide {
                Slideway::Link([a, b]) => {
                    let d = f.get(b) - f.get(a);
                    d.y.atan2(d.x).to_degrees()
                }
                _ => -slider.angle.rem_euclid(std::f64::consts::TAU).to_degrees(),
            };
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
            w.element(
                "rect",
                &[
                    ("x", "-15"),
                    ("y", "-9"),
                    ("width", "30"),
                    ("height", "18"),
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

    pub(super) fn draw_arrows(
        &self,
        w: &mut Writer,
        layout: &Layout,
        frame: &Frame,
        motion: Option<(&[Frame], f64)>,
    ) -> Result<(), SceneError> {
        for (kind, names, colour, scale) in [
            (
                "velocity",
                &self.velocity_arrows,
                style::VELOCITY,
                layout.velocity_scale,
            ),
            (
                "acceleration",
                &self.acceleration_arrows,
                style::ACCELERATION,
                layout.acceleration_scale,
            ),
        ] {
            for name in names {
                let geometry = |f: &Frame| -> Result<Arrow, SceneError> {
                    let k = f.index(name).ok_or_else(|| unknown(f, name))?;
                    let vectors = if kind == "velocity" {
                        f.velocities.as_ref()
                    } else {
                        f.accelerations.as_ref()
                    };
                    let vector = vectors.ok_or(SceneError::MissingKinematics {
                        what: if kind == "velocity" {
                            "velocities"
                        } else {
                            "accelerations"
                        },
                    })?[k];
                    let base = f.positions[k];
                    Ok(Arrow::new(
                        layout.screen(base),
                        layout.screen(base + vector * scale),
                    ))
                };
                let arrow = geometry(frame)?;
                w.open(
                    "g",
                    &[
                        ("id", &format!("{kind}-{name}")),
                        ("class", &format!("arrow {kind}")),
                        ("fill", colour),
                        ("stroke", colour),
                    ],
                );
                w.open(
                    "line",
                    &[
                        ("x1", &fmt(arrow.base.x)),
                        ("y1", &fmt(arrow.base.y)),
                        ("x2", &fmt(arrow.neck.x)),
                        ("y2", &fmt(arrow.neck.y)),
                        ("stroke-width", &fmt(style::ARROW_WIDTH)),
                        ("stroke-linecap", "round"),
                    ],
                );
                let arrows: Vec<Arrow> = match motion {
                    Some((cycle, _)) => cycle.iter().map(&geometry).collect::<Result<_, _>>()?,
                    None => Vec::new(),
                };
                if let Some((_, seconds)) = motion {
                    let values = |f: &dyn Fn(&Arrow) -> String| {
                        arrows.iter().map(f).collect::<Vec<_>>().join(";")
                    };
                    animate_values(w, "x1", &values(&|a| fmt(a.base.x)), seconds);
                    animate_values(w, "y1", &values(&|a| fmt(a.base.y)), seconds);
                    animate_values(w, "x2", &values(&|a| fmt(a.neck.x)), seconds);
                    animate_values(w, "y2", &values(&|a| fmt(a.neck.y)), seconds);
                }
                w.close("line");
                w.open(
                    "polygon",
                    &[
                        ("points", &arrow.head()),
                        ("stroke-width", "0.8"),
                        ("stroke-linejoin", "round"),
                    ],
                );
                if let Some((_, seconds)) = motion {
                    let values: Vec<String> = arrows.iter().map(Arrow::head).collect();
                    animate_values(w, "points", &values.join(";"), seconds);
                }
                w.close("polygon");
                w.close("g");
            }
        }
        Ok(())
    }

    pub(super) fn draw_legend(&self, w: &mut Writer, layout: &Layout, traced: bool) {
        let mut y = layout.legend_top;
        let x = style::MARGIN;
        let (l, t) = (&self.length_unit, &self.time_unit);
        let mut line = |w: &mut Writer, colour: &str, text: String| {
            let arrow = Arrow::new(Vector2::new(x, y - 4.0), Vector2::new(x + 34.0, y - 4.0));
            w.element(
                "line",
                &[
                    ("x1", &fmt(arrow.base.x)),
                    ("y1", &fmt(arrow.base.y)),
                    ("x2", &fmt(arrow.neck.x)),
                    ("y2", &fmt(arrow.neck.y)),
                    ("stroke", colour),
                    ("stroke-width", &fmt(style::ARROW_WIDTH)),
                ],
            );
            w.element("polygon", &[("points", &arrow.head()), ("fill", colour)]);
            legend_text(w, x + 44.0, y, &text);
            y += style::LEGEND_LINE;
        };
        w.open("g", &[("id", "legend"), ("class", "legend")]);
        if !self.velocity_arrows.is_empty() {
            let s = layout.velocity_scale;
            line(
                w,
                style::VELOCITY,
                format!(
                    "velocity, scale {}: 1 {l} drawn = {} {l}/{t}",
                    number(s),
                    number(1.0 / s)
                ),
            );
        }
        if !self.acceleration_arrows.is_empty() {
            let s = layout.acceleration_scale;
            line(
                w,
                style::ACCELERATION,
                format!(
                    "acceleration, scale {}: 1 {l} drawn = {} {l}/{t}²",
                    number(s),
                    number(1.0 / s)
                ),
            );
        }
        for name in self.traces.iter().filter(|_| traced) {
            w.element(
                "line",
                &[
                    ("x1", &fmt(x)),
                    ("y1", &fmt(y - 4.0)),
                    ("x2", &fmt(x + 34.0)),
                    ("y2", &fmt(y - 4.0)),
                    ("stroke", style::TRACE),
                    ("stroke-width", "1.2"),
                    ("stroke-dasharray", "5 3"),
                ],
            );
            legend_text(
                w,
                x + 44.0,
                y,
                &format!("path of {} over the cycle", textbook(name)),
            );
            y += style::LEGEND_LINE;
        }
        // A bar of a round length.
        let length = nice_below(120.0 / layout.scale);
        let pixels = length * layout.scale;
        let bar_y = y - 4.0;
        w.element(
            "path",
            &[
                ("id", "scale-bar"),
                (
                    "d",
                    &format!(
                        "M{} {} v-4 v8 v-4 h{} v-4 v8",
                        fmt(x),
                        fmt(bar_y),
                        fmt(pixels)
                    ),
                ),
                ("fill", "none"),
                ("stroke", style::INK),
                ("stroke-width", "1.4"),
            ],
        );
        legend_text(w, x + pixels + 10.0, y, &format!("{} {l}", number(length)));
        w.close("g");
    }
}

/// An arrow in screen coordinates: from `base` to `tip`, the shaft ending
/// where the head begins.
struct Arrow {
    base: Vector2<f64>,
    neck: Vector2<f64>,
    tip: Vector2<f64>,
    side: Vector2<f64>,
}

impl Arrow {
    fn new(base: Vector2<f64>, tip: Vector2<f64>) -> Arrow {
        let along = tip - base;
        let length = along.norm();
        let dir = if length > 0.0 {
            along / length
        } else {
            Vector2::new(1.0, 0.0)
        };
        // Short arrows get a smaller head, never longer than the arrow.
        let head = style::HEAD_LENGTH.min(0.6 * length);
        let half = style::HEAD_HALF_WIDTH * head / style::HEAD_LENGTH;
        Arrow {
            base,
            neck: tip - dir * head,
            tip,
            side: Vector2::new(-dir.y, dir.x) * half,
        }
    }

    /// The head's triangle, its apex (the arrow's tip) first.
    fn head(&self) -> String {
        let (a, b) = (self.neck + self.side, self.neck - self.side);
        format!(
            "{},{} {},{} {},{}",
            fmt(self.tip.x),
            fmt(self.tip.y),
            fmt(a.x),
            fmt(a.y),
            fmt(b.x),
            fmt(b.y)
        )
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
    let mut x = at.x - b - 5.0;
    while x < at.x + b + 5.0 {
        let _ = write!(hatch, " M{} {} l-6 7", fmt(x + 6.0), fmt(base_y));
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

/// A straight guide from `a` to `b`, hatched on its lower side.
pub(super) fn guide_symbol(w: &mut Writer, a: Vector2<f64>, b: Vector2<f64>, point: &str) {
    let along = b - a;
    let length = along.norm().max(1e-9);
    let dir = along / length;
    // The side away from the block: below on the screen for a level guide.
    let mut normal = Vector2::new(-dir.y, dir.x);
    if normal.y < 0.0 {
        normal = -normal;
    }
    let offset = normal * 10.0;
    let (a, b) = (a + offset, b + offset);
    let mut hatch = format!("M{} {} L{} {}", fmt(a.x), fmt(a.y), fmt(b.x), fmt(b.y));
    let mut s = 4.0;
    while s < length {
        let p = a + dir * s;
        let q = p + normal * 7.0 - dir * 6.0;
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
            ("id", &format!("guide-{point}")),
            ("class", "guide"),
            ("d", &hatch),
            ("fill", "none"),
            ("stroke", style::INK),
            ("stroke-width", "1.2"),
        ],
    );
}

pub(super) fn legend_text(w: &mut Writer, x: f64, y: f64, text: &str) {
    w.open(
        "text",
        &[
            ("x", &fmt(x)),
            ("y", &fmt(y)),
            ("font-family", style::FONT),
            ("font-size", "13"),
            ("fill", style::INK),
        ],
    );
    w.text(text);
    w.close("text");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrows_end_at_their_tips() {
        let a = Arrow::new(Vector2::new(0.0, 0.0), Vector2::new(100.0, 0.0));
        assert_eq!(a.tip, Vector2::new(100.0, 0.0));
        assert!(a.neck.x < 100.0 && a.neck.x > 80.0);
        assert!(a.head().starts_with("100,0 "));
    }
}

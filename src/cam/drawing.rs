//! The cam drawn at one angle: its profile, base circle and pitch curve,
//! the roller and the follower in their true position, and the pressure
//! angle at the contact.

use super::{Cam, CamError, Follower, ProfilePoint, perp, rotate};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;

const INK: &str = "#1b1b1b";
const CAM_FILL: &str = "#dbe4ee";
const FOLLOWER: &str = "#3a4a5c";
const PITCH: &str = "#7b8794";
const NORMAL: &str = "#c62828";
const MOTION: &str = "#2e7d32";

/// A length in metres as a reader wants it: in millimetres where that is
/// ordinary, else in metres in scientific notation.
fn metres(x: f64) -> String {
    let mm = 1000.0 * x;
    if mm.abs() < 1e7 {
        format!("{mm:.1} mm")
    } else {
        format!("{x:.4e} m")
    }
}

impl Cam {
    /// An SVG drawing of the cam turned to `phi`, with a roller of radius
    /// `roller`, `width` pixels wide (200 to 10⁵). The profile must not
    /// undercut.
    pub fn drawing(
        &self,
        roller: f64,
        phi: f64,
        title: &str,
        width: f64,
    ) -> Result<String, CamError> {
        if !(200.0..=1e5).contains(&width) {
            return Err(CamError::BadSetting {
                what: "the drawing's width",
                must: "from 200 to 10⁵ pixels",
                value: width,
            });
        }
        let profile = self.profile(roller, 720)?;
        let pitch = self.pitch(phi)?;
        let theta = self.pressure_angle(phi)?.to_degrees();
        let turn = self.rotation.sign() * phi;
        // The absolute frame: the cam turned by σφ.
        let at = |v: Vector2<f64>| rotate(v, turn);
        let k = at(pitch.k);
        let (pivot, arm_end) = match self.follower {
            Follower::Rocker {
                centre_distance,
                pivot_angle,
                ..
            } => {
                let g = Vector2::new(pivot_angle.cos(), pivot_angle.sin()) * centre_distance;
                (Some(g), g)
            }
            Follower::Translating { .. } => (None, k + at(pitch.motion) * (2.5 * roller)),
        };
        // The picture's extent: the profile, the pivot, the roller.
        let mut lo = Vector2::new(f64::INFINITY, f64::INFINITY);
        let mut hi = -lo;
        let mut grow = |p: Vector2<f64>| {
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        };
        for p in &profile {
            grow(at(p.pitch));
            grow(at(p.profile));
        }
        grow(arm_end);
        grow(k + Vector2::new(roller, roller));
        grow(k - Vector2::new(roller, roller));
        grow(Vector2::zeros());
        let margin = 40.0;
        let scale = (width - 2.0 * margin) / (hi.x - lo.x).max(hi.y - lo.y);
        let height = (hi.y - lo.y) * scale + 2.0 * margin + 70.0;
        let top = 40.0;
        let screen = |p: Vector2<f64>| {
            Vector2::new(
                margin
                    + (p.x - lo.x) * scale
                    + 0.5 * (width - 2.0 * margin - (hi.x - lo.x) * scale),
                top + (hi.y - p.y) * scale,
            )
        };
        let path = |points: &mut dyn Iterator<Item = Vector2<f64>>| {
            let mut d = String::new();
            for (i, p) in points.enumerate() {
                let s = screen(p);
                d.push_str(&format!(
                    "{}{} {} ",
                    if i == 0 { "M" } else { "L" },
                    fmt(s.x),
                    fmt(s.y)
                ));
            }
            d.push('Z');
            d
        };
        let mut w = Writer::svg(width, height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "white")],
        );
        w.open(
            "text",
            &[
                ("x", &fmt(width / 2.0)),
                ("y", "26"),
                ("text-anchor", "middle"),
                ("font-family", "DejaVu Serif, Georgia, serif"),
                ("font-size", "17"),
                ("fill", INK),
            ],
        );
        w.text(title);
        w.close("text");
        // The cam.
        w.element(
            "path",
            &[
                ("id", "profile"),
                (
                    "d",
                    &path(&mut profile.iter().map(|p: &ProfilePoint| at(p.profile))),
                ),
                ("fill", CAM_FILL),
                ("stroke", INK),
                ("stroke-width", "1.8"),
            ],
        );
        let r0 = self.base_radius();
        let o = screen(Vector2::zeros());
        for (id, radius, dash) in [
            ("base-circle", r0 - roller, "6 4"),
            ("pitch-base-circle", r0, "2 4"),
        ] {
            w.element(
                "circle",
                &[
                    ("id", id),
                    ("cx", &fmt(o.x)),
                    ("cy", &fmt(o.y)),
                    ("r", &fmt(radius * scale)),
                    ("fill", "none"),
                    ("stroke", PITCH),
                    ("stroke-width", "1"),
                    ("stroke-dasharray", dash),
                ],
            );
        }
        w.element(
            "path",
            &[
                ("id", "pitch-curve"),
                ("d", &path(&mut profile.iter().map(|p| at(p.pitch)))),
                ("fill", "none"),
                ("stroke", PITCH),
                ("stroke-width", "1.2"),
                ("stroke-dasharray", "5 3"),
            ],
        );
        // The follower.
        let ks = screen(k);
        let end = screen(arm_end);
        w.element(
            "line",
            &[
                ("id", "follower"),
                ("x1", &fmt(ks.x)),
                ("y1", &fmt(ks.y)),
                ("x2", &fmt(end.x)),
                ("y2", &fmt(end.y)),
                ("stroke", FOLLOWER),
                ("stroke-width", "6"),
                ("stroke-linecap", "round"),
            ],
        );
        w.element(
            "circle",
            &[
                ("id", "roller"),
                ("cx", &fmt(ks.x)),
                ("cy", &fmt(ks.y)),
                ("r", &fmt(roller * scale)),
                ("fill", "white"),
                ("stroke", FOLLOWER),
                ("stroke-width", "2.2"),
            ],
        );
        // The pressure angle: the common normal and the direction of
        // motion at K.
        let mut normal = perp(pitch.dk).normalize();
        if normal.dot(&pitch.k) < 0.0 {
            normal = -normal;
        }
        let length = 0.45 * r0;
        for (id, dir, colour) in [
            ("normal", at(normal), NORMAL),
            ("motion", at(pitch.motion), MOTION),
        ] {
            let (a, b) = (screen(k - dir * (0.3 * length)), screen(k + dir * length));
            w.element(
                "line",
                &[
                    ("id", id),
                    ("x1", &fmt(a.x)),
                    ("y1", &fmt(a.y)),
                    ("x2", &fmt(b.x)),
                    ("y2", &fmt(b.y)),
                    ("stroke", colour),
                    ("stroke-width", "1.6"),
                ],
            );
        }
        // Pivots.
        for p in std::iter::once(Vector2::zeros()).chain(pivot) {
            let s = screen(p);
            w.element(
                "circle",
                &[
                    ("cx", &fmt(s.x)),
                    ("cy", &fmt(s.y)),
                    ("r", "4.5"),
                    ("fill", "white"),
                    ("stroke", INK),
                    ("stroke-width", "1.8"),
                ],
            );
        }
        // The legend.
        let lines = [
            (
                PITCH,
                format!(
                    "base circle r0 − r = {}, pitch curve (dashed)",
                    metres(r0 - roller)
                ),
            ),
            (NORMAL, "common normal at the contact".to_string()),
            (
                MOTION,
                format!("the roller centre's motion: pressure angle {theta:.2}°"),
            ),
        ];
        for (i, (colour, text)) in lines.iter().enumerate() {
            let y = height - 60.0 + 18.0 * i as f64;
            w.element(
                "line",
                &[
                    ("x1", "40"),
                    ("y1", &fmt(y - 4.0)),
                    ("x2", "70"),
                    ("y2", &fmt(y - 4.0)),
                    ("stroke", colour),
                    ("stroke-width", "2"),
                ],
            );
            w.open(
                "text",
                &[
                    ("x", "80"),
                    ("y", &fmt(y)),
                    ("font-family", "DejaVu Serif, Georgia, serif"),
                    ("font-size", "13"),
                    ("fill", INK),
                ],
            );
            w.text(text);
            w.close("text");
        }
        Ok(w.finish())
    }
}

//! The cam drawn at one angle: its profile, base circle and pitch curve,
//! the roller and the follower in their true position, and the pressure
//! angle at the contact. The cam, its centre O, the roller, the arm and the
//! pivot are labelled where they are drawn; the circles, the pitch curve
//! and the two lines at the contact are named in a legend whose swatches
//! are drawn with their own strokes; a scale bar gives the scale.

mod labels;

use super::{Cam, CamError, Follower, ProfilePoint, perp, rotate};
use crate::draw::palette::FONT;
use crate::draw::palette::{
    ACCELERATION as NORMAL, BAR as FOLLOWER, INK, PLATE_FILL as CAM_FILL, VELOCITY as MOTION,
};
use crate::draw::svg::{Writer, fmt, nice_below, scale_bar};
use labels::Labels;
use nalgebra::Vector2;

const PITCH: &str = "#7b8794";

/// How a line of the legend is drawn, in the picture and in its swatch
/// alike.
#[derive(Clone, Copy)]
struct Stroke {
    colour: &'static str,
    width: f64,
    dash: Option<&'static str>,
}

const BASE_CIRCLE: Stroke = Stroke {
    colour: PITCH,
    width: 1.0,
    dash: Some("6 4"),
};
const PITCH_BASE_CIRCLE: Stroke = Stroke {
    colour: PITCH,
    width: 1.0,
    dash: Some("2 4"),
};
/// Dash-dot, as a centre line: the path of the roller's centre.
const PITCH_CURVE: Stroke = Stroke {
    colour: PITCH,
    width: 1.3,
    dash: Some("12 4 2 4"),
};
const NORMAL_LINE: Stroke = Stroke {
    colour: NORMAL,
    width: 1.6,
    dash: None,
};
const MOTION_LINE: Stroke = Stroke {
    colour: MOTION,
    width: 1.6,
    dash: None,
};

impl Stroke {
    /// Writes the element `name` with its `geometry`, unfilled, in this
    /// stroke.
    fn draw(self, w: &mut Writer, name: &str, geometry: &[(&str, &str)]) {
        let width = fmt(self.width);
        let mut attributes: Vec<(&str, &str)> = geometry.to_vec();
        attributes.extend([
            ("fill", "none"),
            ("stroke", self.colour),
            ("stroke-width", &width),
        ]);
        if let Some(dash) = self.dash {
            attributes.push(("stroke-dasharray", dash));
        }
        w.element(name, &attributes);
    }
}

/// A line of the legend's text at (`x`, `y`), its baseline.
fn legend_text(w: &mut Writer, x: f64, y: f64, id: Option<&str>, text: &str) {
    let (x, y) = (fmt(x), fmt(y));
    let mut attributes = vec![
        ("x", x.as_str()),
        ("y", y.as_str()),
        ("font-family", FONT),
        ("font-size", "13"),
        ("fill", INK),
    ];
    attributes.extend(id.map(|id| ("id", id)));
    w.open("text", &attributes);
    w.text(text);
    w.close("text");
}

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

/// A length in metres as the scale bar reads it ("50 mm"), with as many
/// decimals as a length under a millimetre needs.
fn millimetres(length: f64) -> String {
    let mm_decade = length.log10().floor() + 3.0;
    if (-3.0..7.0).contains(&mm_decade) {
        format!("{:.*} mm", (-mm_decade).max(0.0) as usize, 1000.0 * length)
    } else {
        format!("{length:e} m")
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
        let top = 40.0;
        // The legend below the picture: five lines and the scale bar.
        let row = 18.0;
        let legend_top = top + (hi.y - lo.y) * scale + margin;
        let height = legend_top + 6.0 * row + 10.0;
        let screen = |p: Vector2<f64>| {
            Vector2::new(
                margin
                    + (p.x - lo.x) * scale
                    + 0.5 * (width - 2.0 * margin - (hi.x - lo.x) * scale),
                top + (hi.y - p.y) * scale,
            )
        };
        let path = |points: &[Vector2<f64>]| {
            let mut d = String::new();
            for (i, s) in points.iter().enumerate() {
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
        // Labels go below the title and above the legend.
        let mut labels = Labels::new(
            Vector2::new(4.0, 34.0),
            Vector2::new(width - 4.0, legend_top - 6.0),
        );
        let mut w = Writer::svg(width, height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "white")],
        );
        w.open(
            "text",
            &[
                ("id", "title"),
                ("x", &fmt(width / 2.0)),
                ("y", "26"),
                ("text-anchor", "middle"),
                ("font-family", FONT),
                ("font-size", "17"),
                ("fill", INK),
            ],
        );
        w.text(title);
        w.close("text");
        // The cam.
        let outline: Vec<_> = profile
            .iter()
            .map(|p: &ProfilePoint| screen(at(p.profile)))
            .collect();
        w.element(
            "path",
            &[
                ("id", "profile"),
                ("d", &path(&outline)),
                ("fill", CAM_FILL),
                ("stroke", INK),
                ("stroke-width", "1.8"),
            ],
        );
        labels.avoid_polyline(&outline, true, 1.8);
        let r0 = self.base_radius();
        let o = screen(Vector2::zeros());
        for (id, radius, stroke) in [
            ("base-circle", r0 - roller, BASE_CIRCLE),
            ("pitch-base-circle", r0, PITCH_BASE_CIRCLE),
        ] {
            stroke.draw(
                &mut w,
                "circle",
                &[
                    ("id", id),
                    ("cx", &fmt(o.x)),
                    ("cy", &fmt(o.y)),
                    ("r", &fmt(radius * scale)),
                ],
            );
            labels.avoid_circle(o, radius * scale, stroke.width);
        }
        let pitch_curve: Vec<_> = profile.iter().map(|p| screen(at(p.pitch))).collect();
        PITCH_CURVE.draw(
            &mut w,
            "path",
            &[("id", "pitch-curve"), ("d", &path(&pitch_curve))],
        );
        labels.avoid_polyline(&pitch_curve, true, PITCH_CURVE.width);
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
        labels.avoid_polyline(&[ks, end], false, 6.0);
        let roller_px = roller * scale;
        w.element(
            "circle",
            &[
                ("id", "roller"),
                ("cx", &fmt(ks.x)),
                ("cy", &fmt(ks.y)),
                ("r", &fmt(roller_px)),
                ("fill", "white"),
                ("stroke", FOLLOWER),
                ("stroke-width", "2.2"),
            ],
        );
        labels.avoid_circle(ks, roller_px, 2.2);
        // The pressure angle: the common normal and the direction of
        // motion at K.
        let mut normal = perp(pitch.dk).normalize();
        if normal.dot(&pitch.k) < 0.0 {
            normal = -normal;
        }
        let length = 0.45 * r0;
        for (id, dir, stroke) in [
            ("normal", at(normal), NORMAL_LINE),
            ("motion", at(pitch.motion), MOTION_LINE),
        ] {
            let (a, b) = (screen(k - dir * (0.3 * length)), screen(k + dir * length));
            stroke.draw(
                &mut w,
                "line",
                &[
                    ("id", id),
                    ("x1", &fmt(a.x)),
                    ("y1", &fmt(a.y)),
                    ("x2", &fmt(b.x)),
                    ("y2", &fmt(b.y)),
                ],
            );
            labels.avoid_polyline(&[a, b], false, stroke.width);
        }
        // The cam's centre and the rocker's pivot.
        let dot = 4.5;
        let centres: Vec<_> = std::iter::once(("centre", o))
            .chain(pivot.map(|g| ("pivot", screen(g))))
            .collect();
        for &(id, s) in &centres {
            w.element(
                "circle",
                &[
                    ("id", id),
                    ("cx", &fmt(s.x)),
                    ("cy", &fmt(s.y)),
                    ("r", &fmt(dot)),
                    ("fill", "white"),
                    ("stroke", INK),
                    ("stroke-width", "1.8"),
                ],
            );
            labels.avoid_circle(s, dot, 1.8);
        }
        // The labels, once everything they keep clear of is drawn.
        for (id, s) in centres {
            let name = if id == "centre" { "O" } else { "pivot" };
            labels.place(&mut w, id, name, s, dot + 0.9);
        }
        labels.place(&mut w, "profile", "cam", o, 0.35 * (r0 - roller) * scale);
        labels.place(&mut w, "roller", "roller", ks, roller_px + 1.1);
        // The arm between the roller's rim and its far end.
        let rim = ks + (end - ks).normalize() * roller_px;
        let arm_name = if pivot.is_some() { "arm" } else { "follower" };
        labels.place(&mut w, "follower", arm_name, (rim + end) * 0.5, 3.0);
        // The legend.
        w.open("g", &[("id", "legend")]);
        let lines = [
            (
                BASE_CIRCLE,
                format!(
                    "base circle r0 − r = {}, roller r = {}",
                    metres(r0 - roller),
                    metres(roller)
                ),
            ),
            (
                PITCH_BASE_CIRCLE,
                format!("the pitch curve's base circle r0 = {}", metres(r0)),
            ),
            (
                PITCH_CURVE,
                "pitch curve (the roller centre's path)".to_string(),
            ),
            (NORMAL_LINE, "common normal at the contact".to_string()),
            (
                MOTION_LINE,
                format!("the roller centre's motion: pressure angle {theta:.2}°"),
            ),
        ];
        let swatch = (40.0, 76.0);
        for (i, (stroke, text)) in lines.iter().enumerate() {
            let y = legend_top + 13.0 + row * i as f64;
            stroke.draw(
                &mut w,
                "line",
                &[
                    ("class", "swatch"),
                    ("x1", &fmt(swatch.0)),
                    ("y1", &fmt(y - 4.0)),
                    ("x2", &fmt(swatch.1)),
                    ("y2", &fmt(y - 4.0)),
                ],
            );
            legend_text(&mut w, swatch.1 + 10.0, y, None, text);
        }
        // A scale bar of a round length, about 120 px long at most.
        let bar = nice_below(120.0 / scale);
        let bar_px = bar * scale;
        if bar_px.is_finite() && bar_px > 0.0 {
            let y = legend_top + 13.0 + row * lines.len() as f64;
            scale_bar(&mut w, swatch.0, y - 4.0, bar_px);
            legend_text(
                &mut w,
                swatch.0 + bar_px + 10.0,
                y,
                Some("scale-label"),
                &millimetres(bar),
            );
        }
        w.close("g");
        Ok(w.finish())
    }
}

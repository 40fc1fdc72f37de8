//! Velocity and acceleration arrows: where each goes on the screen, and
//! how they are drawn so that every one stays readable.
//!
//! Three rules, as a textbook figure follows them:
//! - arrows are drawn above the links, each with a thin white outline (a
//!   halo), so that an arrow along a bar or across another arrow shows;
//! - arrows that would lie on one another (nearly parallel, overlapping
//!   along their length, closer than a shaft's width apart) are moved apart
//!   sideways, symmetrically, by a few pixels — within the joint's circle
//!   for two arrows of one point;
//! - the longer arrows are drawn first and every head after every shaft,
//!   so that no head and no short arrow is hidden under a long shaft.

use super::arrow_kind::Kind;
use super::geometry::{Capsule, cross};
use super::layout::Layout;
use super::motion::animate_values;
use super::style;
use super::{Frame, Scene, SceneError};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;

/// An arrow in screen coordinates: from `base` to `tip`, the shaft ending
/// where the head begins.
#[derive(Clone, Copy, Debug)]
pub(super) struct Arrow {
    pub(super) base: Vector2<f64>,
    pub(super) neck: Vector2<f64>,
    pub(super) tip: Vector2<f64>,
    side: Vector2<f64>,
}

impl Arrow {
    pub(super) fn new(base: Vector2<f64>, tip: Vector2<f64>) -> Arrow {
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

    fn length(&self) -> f64 {
        (self.tip - self.base).norm()
    }

    /// Where the shaft's halo starts: clear of the joint's circle at the
    /// base, so that the outline does not cut the circle.
    fn halo_start(&self) -> Vector2<f64> {
        let shaft = self.neck - self.base;
        let clear = style::JOINT_RADIUS + 2.0;
        let length = shaft.norm();
        if length > clear {
            self.base + shaft * (clear / length)
        } else {
            self.neck
        }
    }

    /// The head's triangle, its apex (the arrow's tip) first.
    pub(super) fn head(&self) -> String {
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

    /// The ground the arrow covers, outline included: its shaft and its
    /// head.
    pub(super) fn outline(&self) -> [Capsule; 2] {
        [
            Capsule {
                a: self.base,
                b: self.neck,
                radius: style::ARROW_WIDTH / 2.0 + style::HALO_WIDTH,
            },
            Capsule {
                a: self.neck,
                b: self.tip,
                radius: self.side.norm(),
            },
        ]
    }
}

/// One arrow of a scene: its kind, its point, where it is drawn.
pub(super) struct PointArrow {
    pub(super) kind: Kind,
    pub(super) name: String,
    pub(super) arrow: Arrow,
}

impl PointArrow {
    fn id(&self) -> String {
        format!("{}-{}", self.kind.name(), self.name)
    }
}

/// The centre-to-centre distance of two arrows side by side.
const GAP: f64 = 6.0;
/// The most an arrow is moved sideways.
const MOST_SHIFT: f64 = 8.0;
/// Arrows closer to parallel than this (the sine of the angle between
/// them, about 11°) can lie on one another.
const PARALLEL: f64 = 0.2;
/// Arrows overlapping along their length by less than this (such as two
/// arrows from one point in opposite directions) do not.
const LEAST_OVERLAP: f64 = 4.0;

impl Scene {
    /// The frame's arrows on the screen, in the scene's order, moved apart
    /// where they would lie on one another.
    pub(super) fn arrows(
        &self,
        layout: &Layout,
        frame: &Frame,
    ) -> Result<Vec<PointArrow>, SceneError> {
        let mut found = Vec::new();
        for (kind, names, scale) in [
            (Kind::Velocity, &self.velocity_arrows, layout.velocity_scale),
            (
                Kind::Acceleration,
                &self.acceleration_arrows,
                layout.acceleration_scale,
            ),
        ] {
            for name in names {
                let k = frame.point(name)?;
                let vector = kind.vectors(frame)?[k];
                let base = frame.positions[k];
                found.push((
                    kind,
                    name,
                    layout.screen(base),
                    layout.screen(base + vector * scale),
                ));
            }
        }
        let segments: Vec<_> = found.iter().map(|(_, _, a, b)| (*a, *b)).collect();
        let shifts = shifts_apart(&segments);
        Ok(found
            .into_iter()
            .zip(shifts)
            .map(|((kind, name, base, tip), shift)| PointArrow {
                kind,
                name: name.clone(),
                arrow: Arrow::new(base + shift, tip + shift),
            })
            .collect())
    }

    /// The arrows of `frame`; animated through `motion`'s frames and period
    /// if given.
    pub(super) fn draw_arrows(
        &self,
        w: &mut Writer,
        layout: &Layout,
        frame: &Frame,
        motion: Option<(&[Frame], f64)>,
    ) -> Result<(), SceneError> {
        let arrows = self.arrows(layout, frame)?;
        // Each arrow through the cycle, in the same order.
        let tracks: Vec<Vec<Arrow>> = match motion {
            Some((cycle, _)) => {
                let mut tracks = vec![Vec::with_capacity(cycle.len()); arrows.len()];
                for f in cycle {
                    for (track, a) in tracks.iter_mut().zip(self.arrows(layout, f)?) {
                        track.push(a.arrow);
                    }
                }
                tracks
            }
            None => Vec::new(),
        };
        let seconds = motion.map(|(_, s)| s);
        let mut order: Vec<usize> = (0..arrows.len()).collect();
        order.sort_by(|&i, &j| {
            arrows[j]
                .arrow
                .length()
                .total_cmp(&arrows[i].arrow.length())
        });
        w.open("g", &[("id", "arrows"), ("class", "arrows")]);
        for &i in &order {
            let a = &arrows[i];
            let colour = a.kind.colour();
            w.open(
                "g",
                &[
                    ("id", &a.id()),
                    ("class", &format!("arrow {}", a.kind.name())),
                    ("fill", colour),
                    ("stroke", colour),
                ],
            );
            let halo_width = style::ARROW_WIDTH + 2.0 * style::HALO_WIDTH;
            let track = tracks.get(i).map(Vec::as_slice);
            line(
                w,
                &[
                    ("class", "halo"),
                    ("stroke", style::HALO),
                    ("stroke-width", &fmt(halo_width)),
                    ("stroke-linecap", "round"),
                ],
                |a| (a.halo_start(), a.neck),
                &a.arrow,
                track.zip(seconds),
            );
            line(
                w,
                &[
                    ("class", "shaft"),
                    ("stroke-width", &fmt(style::ARROW_WIDTH)),
                    ("stroke-linecap", "round"),
                ],
                |a| (a.base, a.neck),
                &a.arrow,
                track.zip(seconds),
            );
            w.close("g");
        }
        // Every head above every shaft.
        for &i in &order {
            let a = &arrows[i];
            let colour = a.kind.colour();
            w.open(
                "g",
                &[
                    ("id", &format!("{}-head", a.id())),
                    ("class", &format!("arrow-head {}", a.kind.name())),
                    ("fill", colour),
                    ("stroke", colour),
                ],
            );
            let track = tracks.get(i).map(Vec::as_slice);
            head(
                w,
                &[
                    ("class", "halo"),
                    ("fill", style::HALO),
                    ("stroke", style::HALO),
                    ("stroke-width", &fmt(2.0 * style::HALO_WIDTH)),
                    ("stroke-linejoin", "round"),
                ],
                &a.arrow,
                track.zip(seconds),
            );
            head(
                w,
                &[
                    ("class", "head"),
                    ("stroke-width", "0.8"),
                    ("stroke-linejoin", "round"),
                ],
                &a.arrow,
                track.zip(seconds),
            );
            w.close("g");
        }
        w.close("g");
        Ok(())
    }
}

/// A `<line>` from `ends(arrow)`, animated through the track if given.
fn line(
    w: &mut Writer,
    attributes: &[(&str, &str)],
    ends: impl Fn(&Arrow) -> (Vector2<f64>, Vector2<f64>),
    arrow: &Arrow,
    motion: Option<(&[Arrow], f64)>,
) {
    let (p, q) = ends(arrow);
    let (x1, y1, x2, y2) = (fmt(p.x), fmt(p.y), fmt(q.x), fmt(q.y));
    let mut all = vec![("x1", &*x1), ("y1", &*y1), ("x2", &*x2), ("y2", &*y2)];
    all.extend_from_slice(attributes);
    w.open("line", &all);
    if let Some((track, seconds)) = motion {
        let values = |coordinate: &dyn Fn((Vector2<f64>, Vector2<f64>)) -> f64| {
            track
                .iter()
                .map(|a| fmt(coordinate(ends(a))))
                .collect::<Vec<_>>()
                .join(";")
        };
        animate_values(w, "x1", &values(&|(p, _)| p.x), seconds);
        animate_values(w, "y1", &values(&|(p, _)| p.y), seconds);
        animate_values(w, "x2", &values(&|(_, q)| q.x), seconds);
        animate_values(w, "y2", &values(&|(_, q)| q.y), seconds);
    }
    w.close("line");
}

/// The arrow's head as a `<polygon>`, animated through the track if given.
fn head(
    w: &mut Writer,
    attributes: &[(&str, &str)],
    arrow: &Arrow,
    motion: Option<(&[Arrow], f64)>,
) {
    let points = arrow.head();
    let mut all = vec![("points", &*points)];
    all.extend_from_slice(attributes);
    w.open("polygon", &all);
    if let Some((track, seconds)) = motion {
        let values: Vec<String> = track.iter().map(Arrow::head).collect();
        animate_values(w, "points", &values.join(";"), seconds);
    }
    w.close("polygon");
}

/// Sideways shifts that keep arrows (screen segments from base to tip)
/// from lying on one another: each pair that would is pushed apart, half
/// each way, until none is (or a few rounds have passed).
fn shifts_apart(segments: &[(Vector2<f64>, Vector2<f64>)]) -> Vec<Vector2<f64>> {
    let mut shifts = vec![Vector2::zeros(); segments.len()];
    for _round in 0..8 {
        let mut moved = false;
        for i in 0..segments.len() {
            for j in i + 1..segments.len() {
                let at = |k: usize| (segments[k].0 + shifts[k], segments[k].1 + shifts[k]);
                if let Some(push) = push_apart(at(i), at(j)) {
                    shifts[i] -= push / 2.0;
                    shifts[j] += push / 2.0;
                    moved = true;
                }
            }
        }
        if !moved {
            break;
        }
    }
    for shift in &mut shifts {
        let length = shift.norm();
        if !length.is_finite() {
            *shift = Vector2::zeros();
        } else if length > MOST_SHIFT {
            *shift *= MOST_SHIFT / length;
        }
    }
    shifts
}

/// How far to move the second segment (the first the other way) so that
/// the two no longer lie on one another, if they do: nearly parallel,
/// overlapping along their length, less than [`GAP`] apart over the
/// overlap and not crossing there (a crossing stays readable with the
/// arrows' halos).
fn push_apart(
    first: (Vector2<f64>, Vector2<f64>),
    second: (Vector2<f64>, Vector2<f64>),
) -> Option<Vector2<f64>> {
    let (la, lb) = ((first.1 - first.0).norm(), (second.1 - second.0).norm());
    if !(la > 1e-9 && lb > 1e-9 && la.is_finite() && lb.is_finite()) {
        return None;
    }
    if lb > la {
        return push_apart(second, first).map(|push| -push);
    }
    // Measured along the longer, first segment.
    let u = (first.1 - first.0) / la;
    let v = (second.1 - second.0) / lb;
    if cross(u, v).abs() > PARALLEL {
        return None;
    }
    let normal = Vector2::new(-u.y, u.x);
    let along = |p: Vector2<f64>| (p - first.0).dot(&u);
    let (s0, s1) = (along(second.0), along(second.1));
    let (lo, hi) = (s0.min(s1).max(0.0), s0.max(s1).min(la));
    if hi - lo < LEAST_OVERLAP {
        return None;
    }
    // The second's distance from the first's line at both ends of the
    // overlap.
    let off = |s: f64| {
        let t = (s - s0) / (s1 - s0);
        (second.0 + (second.1 - second.0) * t - first.0).dot(&normal)
    };
    let (e_lo, e_hi) = (off(lo), off(hi));
    if e_lo * e_hi < 0.0 && e_lo.abs().min(e_hi.abs()) > 1.0 {
        return None;
    }
    let nearest = e_lo.abs().min(e_hi.abs());
    if nearest >= GAP {
        return None;
    }
    let side = if (e_lo + e_hi).abs() > 1e-9 {
        (e_lo + e_hi).signum()
    } else {
        1.0
    };
    Some(normal * side * (GAP - nearest))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vector2<f64> {
        Vector2::new(x, y)
    }

    #[test]
    fn arrows_end_at_their_tips() {
        let a = Arrow::new(v(0.0, 0.0), v(100.0, 0.0));
        assert_eq!(a.tip, v(100.0, 0.0));
        assert!(a.neck.x < 100.0 && a.neck.x > 80.0);
        assert!(a.head().starts_with("100,0 "));
    }

    #[test]
    fn collinear_arrows_of_one_point_are_moved_apart_symmetrically() {
        let shifts = shifts_apart(&[(v(0.0, 0.0), v(-100.0, 0.0)), (v(0.0, 0.0), v(-30.0, 0.0))]);
        assert!((shifts[0] + shifts[1]).norm() < 1e-12, "{shifts:?}");
        assert!(((shifts[1] - shifts[0]).norm() - GAP).abs() < 1e-12);
        assert!(shifts[0].x.abs() < 1e-12, "sideways only");
    }

    #[test]
    fn arrows_that_do_not_lie_on_one_another_stay() {
        for pair in [
            // Opposite ways from one point.
            [(v(0.0, 0.0), v(-100.0, 0.0)), (v(0.0, 0.0), v(30.0, 0.0))],
            // At right angles.
            [(v(0.0, 0.0), v(100.0, 0.0)), (v(0.0, 0.0), v(0.0, 30.0))],
            // Parallel, far enough apart.
            [(v(0.0, 0.0), v(100.0, 0.0)), (v(0.0, 9.0), v(100.0, 9.0))],
            // Crossing at a small angle.
            [(v(0.0, -2.0), v(100.0, 2.0)), (v(0.0, 2.0), v(100.0, -2.0))],
        ] {
            assert!(shifts_apart(&pair).iter().all(|s| s.norm() == 0.0));
        }
    }
}

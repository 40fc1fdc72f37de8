//! Plane geometry on the screen for placing things clear of one another:
//! segments, capsules (a segment thickened to a stroke), boxes, polygons,
//! and the distances between them.

use nalgebra::Vector2;

/// A stroke: the points within `radius` of the segment from `a` to `b` (a
/// disc when `a == b`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Capsule {
    pub(super) a: Vector2<f64>,
    pub(super) b: Vector2<f64>,
    pub(super) radius: f64,
}

/// An axis-aligned box.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rect {
    pub(super) min: Vector2<f64>,
    pub(super) max: Vector2<f64>,
}

impl Rect {
    pub(super) fn centred(centre: Vector2<f64>, half: Vector2<f64>) -> Rect {
        Rect {
            min: centre - half,
            max: centre + half,
        }
    }

    fn centre(&self) -> Vector2<f64> {
        (self.min + self.max) / 2.0
    }

    fn half(&self) -> Vector2<f64> {
        (self.max - self.min) / 2.0
    }

    fn contains(&self, p: Vector2<f64>) -> bool {
        (self.min.x..=self.max.x).contains(&p.x) && (self.min.y..=self.max.y).contains(&p.y)
    }

    fn corners(&self) -> [Vector2<f64>; 4] {
        [
            self.min,
            Vector2::new(self.max.x, self.min.y),
            self.max,
            Vector2::new(self.min.x, self.max.y),
        ]
    }

    /// The gap between two boxes; negative when they overlap (by how far
    /// the smaller overlap reaches).
    pub(super) fn gap_to_rect(&self, other: &Rect) -> f64 {
        let d = (other.centre() - self.centre()).abs() - self.half() - other.half();
        if d.x > 0.0 || d.y > 0.0 {
            d.sup(&Vector2::zeros()).norm()
        } else {
            d.x.max(d.y)
        }
    }

    /// The distance from the box to the point `p` (zero inside).
    pub(super) fn distance_to(&self, p: Vector2<f64>) -> f64 {
        point_to_rect(p, self)
    }

    /// The gap between the box and a stroke; negative when they overlap.
    pub(super) fn gap_to_capsule(&self, c: &Capsule) -> f64 {
        segment_to_rect(c.a, c.b, self) - c.radius
    }

    /// How far the box is inside `outer`: negative when it sticks out.
    pub(super) fn inset_in(&self, outer: &Rect) -> f64 {
        let d = [
            self.min.x - outer.min.x,
            self.min.y - outer.min.y,
            outer.max.x - self.max.x,
            outer.max.y - self.max.y,
        ];
        d.into_iter().fold(f64::INFINITY, f64::min)
    }

    /// The gap between the box and a filled polygon; negative when they
    /// overlap.
    pub(super) fn gap_to_polygon(&self, corners: &[Vector2<f64>]) -> f64 {
        if corners.len() < 3 {
            return f64::INFINITY;
        }
        let edges = || {
            corners
                .iter()
                .zip(corners.iter().cycle().skip(1))
                .map(|(a, b)| (*a, *b))
        };
        let gap = edges()
            .map(|(a, b)| segment_to_rect(a, b, self))
            .fold(f64::INFINITY, f64::min);
        if self.corners().iter().any(|p| inside_polygon(*p, corners))
            || corners.iter().any(|p| self.contains(*p))
        {
            -gap.max(1.0)
        } else {
            gap
        }
    }
}

/// The distance from `c` to the segment from `a` to `b`.
pub(super) fn point_to_segment(c: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let ab = b - a;
    let t = if ab.norm_squared() > 0.0 {
        ((c - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - c).norm()
}

/// The distance between a segment and a box: zero or less when the segment
/// enters the box (less the deeper it runs through it).
fn segment_to_rect(a: Vector2<f64>, b: Vector2<f64>, r: &Rect) -> f64 {
    if crosses_rect(a, b, r) {
        // A depth: how far the segment passes inside the box's inscribed
        // disc's reach.
        return point_to_segment(r.centre(), a, b) - r.half().norm();
    }
    let corners = r.corners();
    let mut d = point_to_rect(a, r).min(point_to_rect(b, r));
    for p in corners {
        d = d.min(point_to_segment(p, a, b));
    }
    d
}

fn point_to_rect(p: Vector2<f64>, r: &Rect) -> f64 {
    let d = (p - r.centre()).abs() - r.half();
    d.sup(&Vector2::zeros()).norm()
}

/// Whether the segment has a point in the box (Liang–Barsky clipping).
fn crosses_rect(a: Vector2<f64>, b: Vector2<f64>, r: &Rect) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - r.min.x),
        (d.x, r.max.x - a.x),
        (-d.y, a.y - r.min.y),
        (d.y, r.max.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    t0 <= t1
}

/// Whether `p` is inside the polygon (even–odd rule).
fn inside_polygon(p: Vector2<f64>, corners: &[Vector2<f64>]) -> bool {
    let mut inside = false;
    for (a, b) in corners.iter().zip(corners.iter().cycle().skip(1)) {
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// The 2-D cross product (z of the 3-D one).
pub(super) fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vector2<f64> {
        Vector2::new(x, y)
    }

    #[test]
    fn gaps() {
        let r = Rect::centred(v(0.0, 0.0), v(10.0, 5.0));
        // A stroke passing 3 px above, 1 px thick.
        let above = Capsule {
            a: v(-20.0, -8.0),
            b: v(20.0, -8.0),
            radius: 1.0,
        };
        assert!((r.gap_to_capsule(&above) - 2.0).abs() < 1e-12);
        let through = Capsule {
            a: v(-20.0, 0.0),
            b: v(20.0, 0.0),
            radius: 1.0,
        };
        assert!(r.gap_to_capsule(&through) < 0.0);
        let other = Rect::centred(v(25.0, 0.0), v(10.0, 5.0));
        assert!((r.gap_to_rect(&other) - 5.0).abs() < 1e-12);
        let overlapping = Rect::centred(v(15.0, 0.0), v(10.0, 5.0));
        assert!(r.gap_to_rect(&overlapping) < 0.0);
        let triangle = [v(-30.0, -30.0), v(30.0, -30.0), v(0.0, 30.0)];
        assert!(r.gap_to_polygon(&triangle) < 0.0);
        let far = [v(100.0, 0.0), v(110.0, 0.0), v(105.0, 10.0)];
        assert!((r.gap_to_polygon(&far) - 90.0).abs() < 1e-12);
        let frame = Rect::centred(v(0.0, 0.0), v(100.0, 100.0));
        assert!((r.inset_in(&frame) - 90.0).abs() < 1e-12);
    }
}

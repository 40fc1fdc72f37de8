//! Short labels ("O", "roller", "pivot") written beside what they name, on
//! the side clearest of every line drawn.
//!
//! Everything drawn is registered as points a few pixels apart with half
//! its stroke's width; a label is tried in sixteen directions around its
//! feature and goes where its box keeps the most room from those points
//! (any room over [`GAP`] − 1 px counting as clear), the first such
//! direction winning a tie. A label placed is avoided by the ones after it.

use super::{FONT, INK};
use crate::draw::svg::{Writer, fmt};
use nalgebra::Vector2;
use std::f64::consts::PI;

type Point = Vector2<f64>;

const FONT_SIZE: f64 = 13.0;
/// A generous width of one character of the font, as a fraction of its size.
const CHAR_WIDTH: f64 = 0.62;
/// The gap between a label and what it names, px; a label with this much
/// room from every other line counts as clear.
const GAP: f64 = 6.0;
/// The spacing of the points that stand for a line, px.
const STEP: f64 = 3.0;
/// About the most points that stand for one line (wider spaced on huge
/// drawings).
const MOST_POINTS: f64 = 4000.0;

/// A line drawn: points along it and half its stroke's width.
struct Obstacle {
    points: Vec<Point>,
    half_width: f64,
}

/// A label's box on the screen.
#[derive(Clone, Copy)]
struct Rect {
    min: Point,
    max: Point,
}

impl Rect {
    fn distance(&self, p: Point) -> f64 {
        let dx = (self.min.x - p.x).max(p.x - self.max.x).max(0.0);
        let dy = (self.min.y - p.y).max(p.y - self.max.y).max(0.0);
        dx.hypot(dy)
    }

    fn inside(&self, outer: &Rect) -> bool {
        self.min.x >= outer.min.x
            && self.min.y >= outer.min.y
            && self.max.x <= outer.max.x
            && self.max.y <= outer.max.y
    }

    fn outline(&self) -> [Point; 4] {
        [
            self.min,
            Point::new(self.max.x, self.min.y),
            self.max,
            Point::new(self.min.x, self.max.y),
        ]
    }
}

/// The labels of one drawing and what they keep clear of.
pub(super) struct Labels {
    obstacles: Vec<Obstacle>,
    /// Where labels may go (below the title, above the legend), px.
    area: Rect,
}

impl Labels {
    /// Labels kept within the box from `min` to `max` (screen pixels).
    pub(super) fn new(min: Point, max: Point) -> Labels {
        Labels {
            obstacles: Vec::new(),
            area: Rect { min, max },
        }
    }

    /// A polyline drawn with a stroke `width` px wide (its last point
    /// joined to its first if `closed`).
    pub(super) fn avoid_polyline(&mut self, points: &[Point], closed: bool, width: f64) {
        let joins = points.len().saturating_sub(1) + usize::from(closed && points.len() > 2);
        let ends = |i: usize| (points[i], points[(i + 1) % points.len()]);
        let length: f64 = (0..joins).map(|i| (ends(i).1 - ends(i).0).norm()).sum();
        let step = STEP.max(length / MOST_POINTS);
        let mut dense = Vec::new();
        for i in 0..joins {
            let (a, b) = ends(i);
            let pieces = ((b - a).norm() / step).ceil();
            let pieces = if pieces.is_finite() {
                pieces.clamp(1.0, MOST_POINTS) as usize
            } else {
                1
            };
            dense.extend((0..pieces).map(|j| a + (b - a) * (j as f64 / pieces as f64)));
        }
        dense.extend(points.last());
        self.obstacles.push(Obstacle {
            points: dense,
            half_width: 0.5 * width,
        });
    }

    /// A circle drawn with a stroke `width` px wide.
    pub(super) fn avoid_circle(&mut self, centre: Point, radius: f64, width: f64) {
        let pieces = (2.0 * PI * radius.abs() / STEP).ceil();
        let pieces = if pieces.is_finite() {
            pieces.clamp(12.0, MOST_POINTS) as usize
        } else {
            12
        };
        let points: Vec<Point> = (0..pieces)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / pieces as f64;
                centre + Point::new(a.cos(), a.sin()) * radius
            })
            .collect();
        self.avoid_polyline(&points, true, width);
    }

    /// Writes `text` beside a feature that reaches `reach` px about `at`,
    /// as `<text id="label-{of}">`, `of` being the id of what it names;
    /// nothing if the label fits nowhere in the area.
    pub(super) fn place(&mut self, w: &mut Writer, of: &str, text: &str, at: Point, reach: f64) {
        let size = Point::new(
            CHAR_WIDTH * FONT_SIZE * text.chars().count() as f64,
            FONT_SIZE,
        );
        let mut best: Option<(f64, Rect)> = None;
        // Up-right first, then clockwise on the screen (y down).
        for i in 0..16 {
            let angle = -0.25 * PI + i as f64 * PI / 8.0;
            let dir = Point::new(angle.cos(), angle.sin());
            // The box's nearest side to `at` touches the point `reach + GAP`
            // out, the box lying beyond it.
            let touch = at + dir * (reach + GAP);
            let centre = touch + dir.component_mul(&size) * 0.5;
            let rect = Rect {
                min: centre - size * 0.5,
                max: centre + size * 0.5,
            };
            if !rect.inside(&self.area) {
                continue;
            }
            let room = self.room(&rect).min(GAP - 1.0);
            if best.is_none_or(|(most, _)| room > most) {
                best = Some((room, rect));
            }
        }
        let Some((_, rect)) = best else { return };
        let id = format!("label-{of}");
        w.open(
            "text",
            &[
                ("id", &id),
                ("x", &fmt(rect.min.x)),
                ("y", &fmt(rect.max.y - 0.22 * FONT_SIZE)),
                ("font-family", FONT),
                ("font-size", &fmt(FONT_SIZE)),
                ("fill", INK),
            ],
        );
        w.text(text);
        w.close("text");
        self.avoid_polyline(&rect.outline(), true, 0.0);
    }

    /// The least room between a box and any line drawn, px.
    fn room(&self, rect: &Rect) -> f64 {
        self.obstacles
            .iter()
            .flat_map(|o| o.points.iter().map(|&p| rect.distance(p) - o.half_width))
            .fold(f64::INFINITY, f64::min)
    }
}

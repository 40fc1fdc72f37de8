//! The points' names and the markers' labels: each beside its point, at
//! the nearest spot where its box keeps clear of everything drawn — bars
//! and plates, slider blocks, ground symbols and hatched guides, arrows,
//! traced paths and curves, the joints of ghost poses, markers, notes,
//! the points, the labels already placed — and inside the drawing's area
//! (not on the heading or the legend), nearer its own point than any
//! other, so that it names the right one. Where no spot near the point is
//! clear, the one that overlaps least.

use super::arrows::PointArrow;
use super::geometry::{Capsule, Rect, point_to_segment};
use super::layout::{Layout, Placed};
use super::motion::Motion;
use super::overlay::Overlay;
use super::style;
use super::symbols::{Guide, ground_extent};
use super::{Scene, Shape, Slideway};
use crate::draw::svg::{Writer, fmt};
use linkage_symbolic::names::textbook;
use nalgebra::Vector2;

/// What labels keep clear of, on the screen.
pub(super) struct Obstacles {
    strokes: Vec<Capsule>,
    boxes: Vec<Rect>,
    polygons: Vec<Vec<Vector2<f64>>>,
    /// Where labels may go.
    area: Rect,
}

/// How clear a label wants to be; beyond, a nearer spot is better.
const ENOUGH: f64 = 4.0;
/// How much a pixel farther from the point costs, against clearance.
const FARTHER: f64 = 0.06;
/// The gaps tried between a point's circle and its label's box.
const GAPS: [f64; 7] = [3.0, 6.0, 10.0, 15.0, 21.0, 29.0, 40.0];
/// The directions tried from a point, starting at the upper right.
const DIRECTIONS: usize = 16;
/// How much nearer its own point than any other a label should be.
const NEARER: f64 = 3.0;

/// Where the text's baseline lies below its box's centre, in em.
const BASELINE: f64 = 0.25;

/// Half a label's box (`style::FONT`, `size` px): the text's width by the
/// font's usual advances, on the wide side (capitals about 0.75 em, digits
/// 0.64 em, subscript digits 0.42 em, the rest 0.6 em), from the cap
/// height (0.72 em above the baseline) to below the subscripts (0.22 em).
fn label_half_size(text: &str, size: f64) -> Vector2<f64> {
    let ems: f64 = text
        .chars()
        .map(|c| match c {
            'A'..='Z' => 0.75,
            '0'..='9' => 0.64,
            '\u{2080}'..='\u{2089}' => 0.42,
            _ => 0.6,
        })
        .sum();
    Vector2::new(ems * size / 2.0, 0.47 * size)
}

impl Obstacles {
    /// Only the obstacles that come nearer `p` than `reach` (plus
    /// [`ENOUGH`]): all that matter to a label within `reach` of `p`.
    fn near(&self, p: Vector2<f64>, reach: f64) -> Obstacles {
        let within = reach + ENOUGH;
        Obstacles {
            strokes: self
                .strokes
                .iter()
                .filter(|c| point_to_segment(p, c.a, c.b) - c.radius < within)
                .copied()
                .collect(),
            boxes: self
                .boxes
                .iter()
                .filter(|b| b.distance_to(p) < within)
                .copied()
                .collect(),
            polygons: self.polygons.clone(),
            area: self.area,
        }
    }

    /// How clear the box is of every obstacle (negative: it overlaps),
    /// or some value not above `floor` once it is known to be no more.
    fn clearance(&self, r: &Rect, floor: f64) -> f64 {
        let mut clear = r.inset_in(&self.area);
        let gaps = self
            .strokes
            .iter()
            .map(|c| r.gap_to_capsule(c))
            .chain(self.boxes.iter().map(|b| r.gap_to_rect(b)))
            .chain(self.polygons.iter().map(|p| r.gap_to_polygon(p)));
        for gap in gaps {
            if clear <= floor {
                break;
            }
            clear = clear.min(gap);
        }
        clear
    }
}

impl Scene {
    /// Everything drawn that a label should keep clear of, on the screen.
    pub(super) fn obstacles(
        &self,
        layout: &Layout,
        at: &Placed,
        arrows: &[PointArrow],
        guides: &[Guide],
        traces: &[Vec<Vector2<f64>>],
        overlay: &Overlay,
    ) -> Obstacles {
        let mut strokes = Vec::new();
        let mut polygons = Vec::new();
        let stroke = |a, b, radius| Capsule { a, b, radius };
        for body in &self.shapes {
            match body {
                Shape::Bar([a, b]) => {
                    strokes.push(stroke(at.get(a), at.get(b), style::BAR_WIDTH / 2.0 + 0.5));
                }
                Shape::Plate(corners) => {
                    let corners: Vec<_> = corners.iter().map(|c| at.get(c)).collect();
                    for (a, b) in corners.iter().zip(corners.iter().cycle().skip(1)) {
                        strokes.push(stroke(*a, *b, 2.0));
                    }
                    polygons.push(corners);
                }
            }
        }
        for slider in &self.sliders {
            // The block's outline (a stadium round its rectangle).
            let p = at.get(&slider.point);
            let along = match &slider.guide {
                Slideway::Link([a, b]) => (at.get(b) - at.get(a))
                    .try_normalize(1e-12)
                    .unwrap_or(Vector2::x()),
                _ => Vector2::new(slider.angle.cos(), -slider.angle.sin()),
            };
            let (half_length, half_height) = style::BLOCK_HALF;
            strokes.push(stroke(
                p - along * half_length,
                p + along * half_length,
                half_height + 1.5,
            ));
        }
        for guide in guides {
            strokes.push(guide.hatched_band());
        }
        for a in arrows {
            strokes.extend(a.arrow.outline());
        }
        for path in traces {
            for pair in path.windows(2) {
                strokes.push(stroke(pair[0], pair[1], style::TRACE_WIDTH / 2.0 + 0.5));
            }
        }
        for (curve, points) in self.curves.iter().zip(&overlay.curves) {
            for (a, b) in curve.segments(points) {
                strokes.push(stroke(a, b, style::CURVE_WIDTH / 2.0 + 0.5));
            }
        }
        // Of the ghost poses, only the joints: a label's white outline
        // reads well over their faint bars, and keeping clear of those
        // too would push labels far from their points.
        for ghost in &overlay.ghosts {
            for (_, p) in &ghost.points {
                strokes.push(stroke(*p, *p, style::GHOST_JOINT_RADIUS + 1.0));
            }
        }
        for (k, (set, points)) in self.markers.iter().zip(&overlay.markers).enumerate() {
            let radius = marker_radius(set.look(k).size);
            strokes.extend(points.iter().map(|p| stroke(*p, *p, radius)));
        }
        for (_, p) in &at.points {
            strokes.push(stroke(*p, *p, style::JOINT_RADIUS + 1.0));
        }
        let mut boxes: Vec<Rect> = self
            .ground
            .iter()
            .map(|(name, _)| ground_extent(at.get(name)))
            .collect();
        boxes.extend(
            self.notes
                .iter()
                .zip(&overlay.notes)
                .map(|(note, p)| note.extent(*p)),
        );
        let top = layout.heading.bottom().map_or(4.0, |b| b + 8.0);
        Obstacles {
            strokes,
            boxes,
            polygons,
            area: Rect {
                min: Vector2::new(4.0, top),
                max: Vector2::new(layout.width - 4.0, layout.legend_top - style::LEGEND_LINE),
            },
        }
    }

    /// Names beside the points (placed on the first frame; an animated
    /// label keeps its offset from its point), then the markers' labels
    /// beside their markers, each in its set's colour.
    pub(super) fn draw_labels(
        &self,
        w: &mut Writer,
        at: &Placed,
        motion: Option<&Motion>,
        obstacles: &Obstacles,
        overlay: &Overlay,
    ) {
        let mut taken: Vec<Rect> = Vec::new();
        // Every point a label might be taken to name.
        let anchors: Vec<Vector2<f64>> = at
            .points
            .iter()
            .map(|(_, p)| *p)
            .chain(overlay.markers.iter().flatten().copied())
            .collect();
        for (name, p) in &at.points {
            let text = textbook(name);
            let half = label_half_size(&text, style::LABEL_SIZE);
            let offset = best_offset(*p, style::JOINT_RADIUS, half, &anchors, obstacles, &taken);
            taken.push(Rect::centred(p + offset, half));
            let spot =
                |q: Vector2<f64>| q + offset + Vector2::new(0.0, BASELINE * style::LABEL_SIZE);
            let q = spot(*p);
            w.open(
                "text",
                &[
                    ("class", "label"),
                    ("x", &fmt(q.x)),
                    ("y", &fmt(q.y)),
                    ("text-anchor", "middle"),
                    ("font-family", style::FONT),
                    ("font-style", "italic"),
                    ("font-size", &fmt(style::LABEL_SIZE)),
                    ("fill", style::INK),
                    // A white outline under the letters, for where they
                    // touch a line.
                    ("stroke", "white"),
                    ("stroke-width", "3"),
                    ("stroke-linejoin", "round"),
                    ("paint-order", "stroke"),
                ],
            );
            if let Some(m) = motion {
                m.animate(w, "x", |f| fmt(spot(f.get(name)).x));
                m.animate(w, "y", |f| fmt(spot(f.get(name)).y));
            }
            w.text(&text);
            w.close("text");
        }
        for (k, (set, points)) in self.markers.iter().zip(&overlay.markers).enumerate() {
            let look = set.look(k);
            for (i, p) in points.iter().enumerate() {
                let Some(text) = set.label(i) else { continue };
                let half = label_half_size(&text, style::NOTE_SIZE);
                let radius = marker_radius(look.size);
                let offset = best_offset(*p, radius, half, &anchors, obstacles, &taken);
                taken.push(Rect::centred(p + offset, half));
                let q = p + offset + Vector2::new(0.0, BASELINE * style::NOTE_SIZE);
                w.open(
                    "text",
                    &[
                        ("class", "marker-label"),
                        ("data-set", &k.to_string()),
                        ("x", &fmt(q.x)),
                        ("y", &fmt(q.y)),
                        ("text-anchor", "middle"),
                        ("font-family", style::FONT),
                        ("font-size", &fmt(style::NOTE_SIZE)),
                        ("fill", &look.colour),
                        ("stroke", "white"),
                        ("stroke-width", "3"),
                        ("stroke-linejoin", "round"),
                        ("paint-order", "stroke"),
                    ],
                );
                w.text(&text);
                w.close("text");
            }
        }
    }
}

/// How far from its centre a marker of half size `size` reaches (a
/// diamond's corners, a cross's arms, with the outline).
fn marker_radius(size: f64) -> f64 {
    1.25 * size + 1.5
}

/// The offset from the point `p` (drawn `radius` round) of the centre of
/// its label's box (of half size `half`): the nearest spot clear of the
/// obstacles and the labels `taken`, and nearer `p` than the other
/// `points`; else the clearest.
fn best_offset(
    p: Vector2<f64>,
    radius: f64,
    half: Vector2<f64>,
    points: &[Vector2<f64>],
    obstacles: &Obstacles,
    taken: &[Rect],
) -> Vector2<f64> {
    // Every box tried lies within `reach` of `p`: what lies farther
    // cannot make a difference.
    let reach = radius + GAPS[GAPS.len() - 1] + 2.0 * half.norm();
    let obstacles = obstacles.near(p, reach);
    // Points drawn on top of `p` cannot be told apart from it anyway.
    let others: Vec<Vector2<f64>> = points
        .iter()
        .copied()
        .filter(|q| (2.0..2.0 * reach + NEARER + ENOUGH).contains(&(q - p).norm()))
        .collect();
    let mut best = (f64::NEG_INFINITY, Vector2::new(half.x + 6.0, -half.y - 6.0));
    for gap in GAPS {
        // No spot this far out can beat one already found.
        if best.0 >= ENOUGH - FARTHER * gap {
            break;
        }
        for k in 0..DIRECTIONS {
            // From the upper right, counter-clockwise on the screen.
            let angle =
                std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::TAU / DIRECTIONS as f64;
            let dir = Vector2::new(angle.cos(), -angle.sin());
            // From the box's centre to its edge along `dir`.
            let to_edge = (half.x / dir.x.abs()).min(half.y / dir.y.abs());
            let offset = dir * (radius + gap + to_edge);
            let r = Rect::centred(p + offset, half);
            // Less clear than this, the spot cannot beat the best.
            let floor = best.0 + FARTHER * gap;
            let mut clear = obstacles.clearance(&r, floor);
            for t in taken {
                clear = clear.min(r.gap_to_rect(t) - 2.0);
            }
            let own = r.distance_to(p);
            for q in &others {
                clear = clear.min(r.distance_to(*q) - own - NEARER);
            }
            let score = clear.min(ENOUGH) - FARTHER * gap;
            if score > best.0 {
                best = (score, offset);
            }
        }
    }
    best.1
}

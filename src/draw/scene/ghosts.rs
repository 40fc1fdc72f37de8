//! Ghost poses: other poses of the same mechanism drawn faint behind the
//! main one — its bars, plates, slider blocks and joints in light grey,
//! without labels, arrows or ground symbols — so that a still shows how
//! the mechanism moves.

use super::layout::{Layout, Placed};
use super::style;
use super::symbols::block_degrees;
use super::{Frame, Scene, SceneError, Shape};
use crate::draw::svg::{Writer, fmt};

impl Scene {
    /// Other poses of the mechanism (frames of the same model), drawn
    /// faint behind the pose given to [`Scene::render`] (and behind the
    /// animation); may be called again to add more.
    pub fn ghosts(mut self, frames: &[Frame]) -> Scene {
        self.ghosts.extend_from_slice(frames);
        self
    }

    /// What the ghost poses are, said in the legend beside a faint bar
    /// (no entry if empty, or if there is no ghost).
    pub fn ghost_name(mut self, name: &str) -> Scene {
        self.ghost_name = name.to_owned();
        self
    }

    /// Whether the legend has an entry for the ghosts.
    pub(super) fn ghosts_in_legend(&self) -> bool {
        !(self.ghosts.is_empty() || self.ghost_name.is_empty())
    }

    /// The ghost poses' points on the screen.
    pub(super) fn place_ghosts(&self, layout: &Layout) -> Result<Vec<Placed>, SceneError> {
        self.ghosts
            .iter()
            .map(|frame| self.place(layout, frame))
            .collect()
    }

    /// The ghost poses, each a group `class="ghost"`, all in the group
    /// `#ghosts`.
    pub(super) fn draw_ghosts(&self, w: &mut Writer, ghosts: &[Placed]) {
        if ghosts.is_empty() {
            return;
        }
        w.open("g", &[("id", "ghosts"), ("class", "ghosts")]);
        for (k, at) in ghosts.iter().enumerate() {
            w.open("g", &[("class", "ghost"), ("data-pose", &k.to_string())]);
            for body in &self.shapes {
                match body {
                    Shape::Bar([a, b]) => {
                        let (p, q) = (at.get(a), at.get(b));
                        w.element(
                            "line",
                            &[
                                ("class", "ghost-link"),
                                ("x1", &fmt(p.x)),
                                ("y1", &fmt(p.y)),
                                ("x2", &fmt(q.x)),
                                ("y2", &fmt(q.y)),
                                ("stroke", style::GHOST),
                                ("stroke-width", &fmt(style::GHOST_BAR_WIDTH)),
                                ("stroke-linecap", "round"),
                            ],
                        );
                    }
                    Shape::Plate(corners) => {
                        let points: Vec<String> = corners
                            .iter()
                            .map(|c| {
                                let p = at.get(c);
                                format!("{},{}", fmt(p.x), fmt(p.y))
                            })
                            .collect();
                        w.element(
                            "polygon",
                            &[
                                ("class", "ghost-link"),
                                ("points", &points.join(" ")),
                                ("fill", style::GHOST_FILL),
                                ("stroke", style::GHOST),
                                ("stroke-width", "1.6"),
                                ("stroke-linejoin", "round"),
                            ],
                        );
                    }
                }
            }
            for slider in &self.sliders {
                let p = at.get(&slider.point);
                let (half_length, half_height) = style::BLOCK_HALF;
                w.element(
                    "rect",
                    &[
                        ("class", "ghost-slider"),
                        ("x", &fmt(-half_length)),
                        ("y", &fmt(-half_height)),
                        ("width", &fmt(2.0 * half_length)),
                        ("height", &fmt(2.0 * half_height)),
                        ("rx", "2"),
                        (
                            "transform",
                            &format!(
                                "translate({} {}) rotate({})",
                                fmt(p.x),
                                fmt(p.y),
                                fmt(block_degrees(slider, at))
                            ),
                        ),
                        ("fill", style::GHOST_FILL),
                        ("stroke", style::GHOST),
                        ("stroke-width", "1.4"),
                    ],
                );
            }
            for (_, p) in &at.points {
                w.element(
                    "circle",
                    &[
                        ("class", "ghost-joint"),
                        ("cx", &fmt(p.x)),
                        ("cy", &fmt(p.y)),
                        ("r", &fmt(style::GHOST_JOINT_RADIUS)),
                        ("fill", "white"),
                        ("stroke", style::GHOST),
                        ("stroke-width", "1.2"),
                    ],
                );
            }
            w.close("g");
        }
        w.close("g");
    }
}

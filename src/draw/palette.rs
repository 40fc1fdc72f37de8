//! The colours every picture shares — a scene, the cam's drawing — so that
//! a link, a velocity or an acceleration looks the same in each.

/// Text, outlines, the scale bar.
pub const INK: &str = "#1b1b1b";
/// Links (bars) and the follower's arm.
pub const BAR: &str = "#3a4a5c";
/// Plates, slider blocks, the cam's body.
pub const PLATE_FILL: &str = "#dbe4ee";
/// Velocities, and the cam's roller-centre motion.
pub const VELOCITY: &str = "#2e7d32";
/// Accelerations, and the cam's common normal.
pub const ACCELERATION: &str = "#c62828";
/// The font of every picture's text: one family for scenes, charts and
/// drawings.
pub const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

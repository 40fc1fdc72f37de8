//! The look of a scene: colours, stroke widths, sizes, the font (every
//! picture's), and the styles of the traced paths, shared by the drawing
//! and its legend.

pub use crate::draw::palette::{ACCELERATION, BAR, FONT, INK, PLATE_FILL, VELOCITY};
/// The outline that keeps an arrow visible over a bar or another arrow.
pub const HALO: &str = "white";
pub const BAR_WIDTH: f64 = 5.0;
pub const JOINT_RADIUS: f64 = 4.5;
pub const DOT_RADIUS: f64 = 3.2;
pub const ARROW_WIDTH: f64 = 2.2;
/// The width of the outline on each side of an arrow.
pub const HALO_WIDTH: f64 = 1.6;
pub const HEAD_LENGTH: f64 = 11.0;
pub const HEAD_HALF_WIDTH: f64 = 4.2;
pub const GROUND_HEIGHT: f64 = 14.0;
pub const GROUND_HALF_WIDTH: f64 = 11.0;
/// A slider block's half length and half height.
pub const BLOCK_HALF: (f64, f64) = (15.0, 9.0);
/// How far a straight guide's line lies from the path of its block's
/// centre, and how deep its hatching reaches beyond.
pub const GUIDE_OFFSET: f64 = 10.0;
pub const GUIDE_HATCH: f64 = 7.0;
pub const MARGIN: f64 = 46.0;
pub const LEGEND_LINE: f64 = 18.0;
pub const LABEL_SIZE: f64 = 15.0;
pub const TRACE_WIDTH: f64 = 1.4;
/// The longest arrow of each kind, when its scale is chosen
/// automatically, as a fraction of the mechanism's extent.
pub const ARROW_FRACTION: f64 = 0.3;

/// The stroke of a traced path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceStyle {
    pub colour: &'static str,
    pub dashes: &'static str,
}

/// The style of the `k`-th traced path: colours and dash patterns both
/// cycle (4 and 5 of them), so that twenty paths are told apart by either,
/// and the first few by both.
pub fn trace(k: usize) -> TraceStyle {
    const COLOURS: [&str; 4] = ["#5d6d7e", "#7b3fa0", "#b35c00", "#00838f"];
    const DASHES: [&str; 5] = ["6 3", "1.5 2.5", "10 3 2 3", "3 3", "12 4"];
    TraceStyle {
        colour: COLOURS[k % COLOURS.len()],
        dashes: DASHES[k % DASHES.len()],
    }
}

/// The width of a given curve ([`super::Curve`]): a little heavier than a
/// traced path, as a given line is what the picture is about.
pub const CURVE_WIDTH: f64 = 2.0;

/// The stroke of a given curve, chosen when none is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveStyle {
    pub colour: &'static str,
    pub dashes: &'static str,
}

/// The style of the `k`-th given curve: colours none of the traced paths,
/// arrows or bars use, the first curve solid (no traced path is) and the
/// others in dash patterns no traced path has.
pub fn curve(k: usize) -> CurveStyle {
    const COLOURS: [&str; 4] = ["#0072b2", "#e69f00", "#009e73", "#8c564b"];
    const DASHES: [&str; 3] = ["", "8 2 2 2", "2 2"];
    CurveStyle {
        colour: COLOURS[k % COLOURS.len()],
        dashes: DASHES[k % DASHES.len()],
    }
}

/// The colour of the `k`-th set of markers, chosen when none is given:
/// none a curve, a traced path, an arrow or a bar has, one for each of
/// the five shapes the sets take in turn.
pub fn marker_colour(k: usize) -> &'static str {
    const COLOURS: [&str; 5] = ["#d55e00", "#1b1b1b", "#cc79a7", "#56b4e9", "#882255"];
    COLOURS[k % COLOURS.len()]
}

/// Half the size of a marker, when none is given.
pub const MARKER_SIZE: f64 = 5.5;
/// The font size of markers' labels and of notes.
pub const NOTE_SIZE: f64 = 13.0;

/// A pose drawn faint behind the main one: its bars, plate outlines and
/// joints.
pub const GHOST: &str = "#c4ccd6";
/// A faint pose's plates.
pub const GHOST_FILL: &str = "#f4f6f9";
pub const GHOST_BAR_WIDTH: f64 = 3.0;
pub const GHOST_JOINT_RADIUS: f64 = 2.6;

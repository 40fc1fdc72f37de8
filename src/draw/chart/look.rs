//! How a chart's series look: colours a colour-blind reader tells apart
//! (Okabe and Ito's), marker shapes and dash patterns, each series
//! distinct by two of them, so that a figure printed in grey still reads;
//! and the printed sizes of everything, in points at a 16 cm column.

use core::fmt;

/// A colour (sRGB).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Colour(pub u8, pub u8, pub u8);

impl fmt::Display for Colour {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{:02X}{:02X}{:02X}", self.0, self.1, self.2)
    }
}

impl Colour {
    pub const BLACK: Colour = Colour(0, 0, 0);
    pub const GREY: Colour = Colour(120, 120, 120);
}

/// The colours of series in order: Okabe and Ito's set, which readers
/// with any common colour-vision deficiency tell apart.
pub const COLOURS: [Colour; 7] = [
    Colour(0, 114, 178),   // blue
    Colour(213, 94, 0),    // vermilion
    Colour(0, 158, 115),   // bluish green
    Colour(204, 121, 167), // reddish purple
    Colour(230, 159, 0),   // orange
    Colour(86, 180, 233),  // sky blue
    Colour(0, 0, 0),       // black
];

/// The shape of a point series' markers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    Circle,
    Square,
    Triangle,
    Diamond,
    TriangleDown,
    Cross,
    Plus,
}

/// The markers of point series in order.
pub const MARKERS: [Marker; 7] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
    Marker::TriangleDown,
    Marker::Cross,
    Marker::Plus,
];

/// A line's pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dash {
    Solid,
    Dashed,
    Dotted,
    DashDot,
    LongDash,
}

impl Dash {
    /// The SVG `stroke-dasharray`, in points, for a line `width` points
    /// wide (`None`: solid).
    pub(crate) fn pattern(self) -> Option<[f64; 4]> {
        match self {
            Dash::Solid => None,
            Dash::Dashed => Some([4.0, 2.2, 4.0, 2.2]),
            Dash::Dotted => Some([1.0, 1.6, 1.0, 1.6]),
            Dash::DashDot => Some([5.0, 1.8, 1.2, 1.8]),
            Dash::LongDash => Some([8.0, 2.5, 8.0, 2.5]),
        }
    }
}

/// The dashes of line series in order.
pub const DASHES: [Dash; 5] = [
    Dash::Solid,
    Dash::Dashed,
    Dash::DashDot,
    Dash::Dotted,
    Dash::LongDash,
];

/// The printed sizes, in points when the figure is printed 16 cm wide:
/// no text smaller than [`points::TICK`] (subscripts, three quarters of their
/// text), lines no thinner than a hairline that a printer keeps.
pub mod points {
    /// The width of the column a figure is printed at, in points (16 cm).
    pub const COLUMN: f64 = 16.0 / 2.54 * 72.0;
    pub const TITLE: f64 = 10.0;
    pub const NOTE: f64 = 8.0;
    pub const CAPTION: f64 = 9.0;
    pub const LABEL: f64 = 8.5;
    pub const TICK: f64 = 8.0;
    pub const LEGEND: f64 = 8.0;
    pub const LINE: f64 = 1.1;
    pub const THIN: f64 = 0.6;
    pub const GRID: f64 = 0.4;
    pub const AXIS: f64 = 0.7;
    pub const MARKER: f64 = 2.4;
    pub const TICK_LENGTH: f64 = 2.5;
}

/// The font of every picture's text.
pub use crate::draw::palette::FONT;

/// How one series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Look {
    pub colour: Colour,
    /// The line's pattern, if the series is drawn as a line.
    pub dash: Option<Dash>,
    /// The markers' shape, if the series has markers; and whether they are
    /// open (outlined) rather than filled.
    pub marker: Option<(Marker, bool)>,
    /// The line's width, in points.
    pub width: f64,
    /// 1 opaque … 0 invisible.
    pub opacity: f64,
}

/// The look of reference levels: dark grey, the `k`th in its own dashes.
pub(crate) fn level_look(k: usize) -> Look {
    const DASHES: [Dash; 3] = [Dash::Dashed, Dash::Dotted, Dash::DashDot];
    Look {
        colour: Colour(70, 70, 70),
        dash: Some(DASHES[k % DASHES.len()]),
        marker: None,
        width: 0.9,
        opacity: 1.0,
    }
}

/// The colour of the axes and their ticks (not black, which a series may
/// have).
pub(crate) const AXIS: &str = "#262626";

/// The shading of a range of the abscissa.
pub(crate) const SHADE: (Colour, f64) = (Colour(0, 0, 0), 0.08);

/// The fill of bars: a group's colour, nearly opaque.
pub(crate) const BAR_OPACITY: f64 = 0.85;

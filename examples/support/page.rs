//! An SVG page for the examples' own charts (plotters, SVG backend): the
//! area they draw on and the page as a string.

use plotters::coord::Shift;
use plotters::prelude::*;

/// A drawing area of the page.
pub type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// What drawing gives.
pub type Drawn = Result<(), Box<dyn std::error::Error>>;

/// `draw` on an SVG page of `size`, white; the page as a string.
pub fn page(
    size: (u32, u32),
    draw: impl FnOnce(&Area<'_>) -> Drawn,
) -> Result<String, Box<dyn std::error::Error>> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root)?;
        root.present()?;
    }
    Ok(svg)
}

//! What the diagrams, charts and hodographs share: the checks of sizes,
//! counts and values, the SVG page, and the axes' ranges and tick labels.

use super::DiagramError;
use plotters::prelude::*;

/// Vertical dashes at x over the y range.
pub(super) fn dashed(x: f64, y: (f64, f64), pieces: usize) -> Vec<Vec<(f64, f64)>> {
    let step = (y.1 - y.0) / (2 * pieces) as f64;
    (0..pieces)
        .map(|i| {
            let a = y.0 + 2.0 * i as f64 * step;
            vec![(x, a), (x, a + step)]
        })
        .collect()
}

pub(super) fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (0.0, 1.0);
    }
    // At least a millionth of the values' size wide (1 for values all
    // zero), so that the axis has ticks to draw.
    let least = (1e-6 * lo.abs().max(hi.abs())).max(f64::MIN_POSITIVE);
    if hi - lo >= least {
        (lo, hi)
    } else {
        let middle = 0.5 * lo + 0.5 * hi;
        let half = if middle == 0.0 { 1.0 } else { least };
        (middle - half, middle + half)
    }
}

/// The range widened by 8 % each way.
pub(super) fn pad((lo, hi): (f64, f64)) -> (f64, f64) {
    let d = 0.08 * (hi - lo);
    (lo - d, hi + d)
}

/// A tick label without trailing zeros.
pub(super) fn trim(x: f64) -> String {
    if x != 0.0 && (x.abs() >= 1e5 || x.abs() < 1e-3) {
        return format!("{x:.1e}");
    }
    let text = format!("{x:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

/// Whether a value can be plotted: finite and within ±1e300, so that an
/// axis's span and its padding cannot overflow.
pub(super) fn plottable(x: f64) -> bool {
    x.abs() <= 1e300 // false for NaN too
}

/// The first of `values` that cannot be plotted, as an error.
pub(super) fn check_plottable(
    what: &'static str,
    name: &str,
    values: impl IntoIterator<Item = f64>,
    per_pose: usize,
) -> Result<(), DiagramError> {
    match values.into_iter().position(|x| !plottable(x)) {
        Some(i) => Err(DiagramError::NonFinite {
            what,
            name: name.into(),
            pose: i / per_pose.max(1),
        }),
        None => Ok(()),
    }
}

/// The largest side of a picture, in pixels.
pub(super) const MAX_PIXELS: u32 = 20_000;

/// A size or a count, checked: in `range`.
pub(super) fn within(
    what: &'static str,
    must: &'static str,
    value: u64,
    range: std::ops::RangeInclusive<u64>,
) -> Result<u32, DiagramError> {
    if range.contains(&value) {
        Ok(value as u32)
    } else {
        Err(DiagramError::BadSetting {
            what,
            must,
            value: value as f64,
        })
    }
}

/// A picture's width, checked: 200 to 20 000 pixels.
pub(super) fn width(value: u32) -> Result<u32, DiagramError> {
    within(
        "the width",
        "from 200 to 20 000 pixels",
        value.into(),
        200..=MAX_PIXELS.into(),
    )
}

/// A panel's or a row's height, checked: `least` to 20 000 pixels.
pub(super) fn height(value: u32, least: u32) -> Result<u32, DiagramError> {
    within(
        "a panel's height",
        "from 120 (160 for hodographs) to 20 000 pixels",
        value.into(),
        least.into()..=MAX_PIXELS.into(),
    )
}

/// Panels per row, and the rows they make of `panels`, checked: 1 to 20
/// columns, the whole picture at most 20 000 pixels high for `each` pixels
/// a row.
pub(super) fn grid(columns: usize, panels: usize, each: u32) -> Result<(usize, u32), DiagramError> {
    let columns = within(
        "the number of columns",
        "from 1 to 20",
        columns as u64,
        1..=20,
    )? as usize;
    let rows = panels.div_ceil(columns).max(1);
    let tall = within(
        "the picture's height",
        "at most 20 000 pixels (rows × their height)",
        rows as u64 * u64::from(each),
        0..=MAX_PIXELS.into(),
    )?;
    Ok((rows, tall))
}

/// The drawing area of an SVG page.
pub(super) type Page<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

/// An SVG page of `size`, white, on which `draw` draws; plotters' errors
/// become [`DiagramError::Drawing`].
pub(super) fn page(
    size: (u32, u32),
    draw: impl FnOnce(&Page<'_>) -> Result<(), Box<dyn std::error::Error>>,
) -> Result<String, DiagramError> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        let drawing = |e: &dyn std::fmt::Display| DiagramError::Drawing(e.to_string());
        root.fill(&WHITE).map_err(|e| drawing(&e))?;
        draw(&root).map_err(|e| drawing(&e))?;
        root.present().map_err(|e| drawing(&e))?;
    }
    Ok(out)
}

/// A page's title, at the left of its band, `y` pixels down.
pub(super) fn title_text(title: String, y: i32) -> Text<'static, (i32, i32), String> {
    Text::new(title, (16, y), ("serif", 19).into_font().color(&BLACK))
}

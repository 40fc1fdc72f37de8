//! What the diagrams, charts and hodographs share: the checks of sizes,
//! counts and values, the SVG page (with its dashed lines and subscripts),
//! the legends, and the axes' ranges and tick labels.

use super::DiagramError;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The dash pattern of every dashed line (SVG `stroke-dasharray`).
pub(super) const DASHES: &str = "7 4";

/// plotters' SVG has no dashed strokes: a dashed line is drawn with this
/// opacity, which [`page`] turns into `opacity="1"` and [`DASHES`].
const DASHED_OPACITY: f64 = 0.9961;

/// The grey of the vertical marks.
pub(super) const MARK: RGBColor = RGBColor(120, 120, 120);

/// The colour of horizontal reference levels (a limit, a target).
pub(super) const LEVEL: RGBColor = RGBColor(70, 70, 70);

/// A line's style: `colour`, `width` pixels wide, dashed or solid. The
/// curve and its legend swatch take the same style from here.
pub(super) fn stroke(colour: RGBColor, width: u32, dashed: bool) -> ShapeStyle {
    let colour = if dashed {
        colour.mix(DASHED_OPACITY)
    } else {
        colour.to_rgba()
    };
    colour.stroke_width(width)
}

/// How much of `lines` (polylines, in pixels) lies within `area`
/// ([left, top, right, bottom]): the length inside it, in pixels.
pub(super) fn ink(lines: &[Vec<(f64, f64)>], area: [f64; 4]) -> f64 {
    lines
        .iter()
        .flat_map(|line| line.windows(2))
        .map(|pair| clipped_length(pair[0], pair[1], area))
        .sum()
}

/// The length of the segment from `a` to `b` within `area` (Liang–Barsky).
fn clipped_length(a: (f64, f64), b: (f64, f64), [x0, y0, x1, y1]: [f64; 4]) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut enter, mut leave) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return 0.0;
            }
        } else if p < 0.0 {
            enter = enter.max(q / p);
        } else {
            leave = leave.min(q / p);
        }
    }
    if leave > enter {
        (leave - enter) * dx.hypot(dy)
    } else {
        0.0
    }
}

/// A legend: each entry the style its curve is drawn in (the swatch) and
/// the curve's name.
pub(super) struct Legend(pub Vec<(String, ShapeStyle)>);

impl Legend {
    /// The swatch's length, the gap after it, and the space between
    /// entries of a row, in pixels.
    const SWATCH: i32 = 26;
    const GAP: i32 = 6;
    const SPACE: i32 = 18;
    /// The names' font, in plotters' size (the SVG's is 1.24 times less).
    const FONT: f64 = 15.0;
    /// A line of the boxed legend, and the box's margin.
    const LINE: i32 = 17;
    const MARGIN: i32 = 7;

    /// A rough width of a name: plotters' SVG cannot measure text.
    fn name_width(name: &str) -> i32 {
        let letters = name.chars().filter(|&c| c != '_').count();
        (letters as f64 * 0.5 * Self::FONT / 1.24).ceil() as i32
    }

    fn entry_width(name: &str) -> i32 {
        Self::SWATCH + Self::GAP + Self::name_width(name)
    }

    fn entry(
        area: &Page<'_>,
        (name, style): &(String, ShapeStyle),
        (x, y): (i32, i32),
    ) -> Result<(), Box<dyn std::error::Error>> {
        area.draw(&PathElement::new(
            vec![(x, y), (x + Self::SWATCH, y)],
            *style,
        ))?;
        let font = ("serif", Self::FONT)
            .into_font()
            .color(&BLACK)
            .pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(
            name.clone(),
            (x + Self::SWATCH + Self::GAP, y),
            font,
        ))?;
        Ok(())
    }

    /// The width of the legend in one row.
    pub(super) fn row_width(&self) -> i32 {
        let names: i32 = self.0.iter().map(|(n, _)| Self::entry_width(n)).sum();
        names + Self::SPACE * (self.0.len() as i32 - 1).max(0)
    }

    /// The legend in one row from `x`, its swatches on the line `y`.
    pub(super) fn row(
        &self,
        area: &Page<'_>,
        mut x: i32,
        y: i32,
    ) -> Result<(), Box<dyn std::error::Error>> {
        for entry in &self.0 {
            Self::entry(area, entry, (x, y))?;
            x += Self::entry_width(&entry.0) + Self::SPACE;
        }
        Ok(())
    }

    /// The size of the boxed legend (one entry a line).
    pub(super) fn box_size(&self) -> (i32, i32) {
        let widest = self.0.iter().map(|(n, _)| Self::entry_width(n)).max();
        (
            widest.unwrap_or(0) + 2 * Self::MARGIN,
            Self::LINE * self.0.len() as i32 + 2 * Self::MARGIN - 4,
        )
    }

    /// The legend in a box, one entry a line, its top left corner at
    /// `corner`.
    pub(super) fn boxed(
        &self,
        area: &Page<'_>,
        corner: (i32, i32),
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (w, h) = self.box_size();
        let (x, y) = corner;
        area.draw(&Rectangle::new(
            [(x, y), (x + w, y + h)],
            WHITE.mix(0.85).filled(),
        ))?;
        area.draw(&Rectangle::new([(x, y), (x + w, y + h)], BLACK.mix(0.25)))?;
        for (i, entry) in self.0.iter().enumerate() {
            let line = y + Self::MARGIN + Self::LINE / 2 - 2 + Self::LINE * i as i32;
            Self::entry(area, entry, (x + Self::MARGIN, line))?;
        }
        Ok(())
    }
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
    Ok(subscripts(&out.replace(
        &format!("opacity=\"{DASHED_OPACITY}\""),
        &format!("opacity=\"1\" stroke-dasharray=\"{DASHES}\""),
    )))
}

/// Every `<text>` of `svg` with its subscripts drawn (see [`subscripted`]).
fn subscripts(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(at) = rest.find("<text ") {
        let (before, text) = rest.split_at(at);
        out.push_str(before);
        let (Some(open), Some(close)) = (text.find('>'), text.find("</text>")) else {
            rest = text;
            break;
        };
        let tag = &text[..=open];
        let size = tag
            .split("font-size=\"")
            .nth(1)
            .and_then(|s| s.split('"').next())
            .and_then(|s| s.parse().ok())
            .unwrap_or(12.0);
        out.push_str(tag);
        out.push_str(&subscripted(&text[open + 1..close], size));
        rest = &text[close..];
    }
    out.push_str(rest);
    out
}

/// `text` (of a font of `size` pixels) with its subscripts drawn: `_`
/// starts one, which runs to the next space, bracket, operator or `_` —
/// "J_II(φ)", "dJ_II/dφ", "ω_1". Digits and the letters that Unicode has
/// subscripts of become those (ω₁), as in the scenes' G₂; any other, a
/// smaller `tspan` lowered by `dy` (which every SVG viewer draws).
pub(super) fn subscripted(text: &str, size: f64) -> String {
    let mut parts = text.split('_');
    let mut out = String::from(parts.next().unwrap_or(""));
    let drop = 0.3 * size;
    let mut lowered = false;
    for part in parts {
        let end = part
            .find(|c: char| c.is_whitespace() || "()[]{}/,;:=+−-·*^'&<>\"".contains(c))
            .unwrap_or(part.len());
        let (low, mut after) = part.split_at(end);
        let unicode: Option<String> = low.chars().map(unicode_subscript).collect();
        let literal;
        if low.is_empty() {
            // Not a subscript: the text's own `_`.
            literal = format!("_{part}");
            after = &literal;
        } else if let (false, Some(unicode)) = (lowered, unicode) {
            out.push_str(&unicode);
        } else {
            let dy = if lowered {
                String::new()
            } else {
                format!(" dy=\"{drop:.2}\"")
            };
            let small = 0.75 * size;
            out.push_str(&format!(
                "<tspan{dy} font-size=\"{small:.2}\">{low}</tspan>"
            ));
            lowered = true;
        }
        if lowered && !after.is_empty() {
            // Spaces opening a tspan are dropped by some viewers (librsvg):
            // they go between the tspans.
            let rest = after.trim_start();
            out.push_str(&after[..after.len() - rest.len()]);
            if !rest.is_empty() {
                out.push_str(&format!("<tspan dy=\"-{drop:.2}\">{rest}</tspan>"));
                lowered = false;
            }
        } else {
            out.push_str(after);
        }
    }
    out
}

/// The Unicode subscript of `c`, if there is one (and fonts have it).
fn unicode_subscript(c: char) -> Option<char> {
    const FROM: &str = "0123456789aehijklmnoprstuvx";
    const TO: &str = "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ";
    FROM.chars()
        .position(|f| f == c)
        .and_then(|i| TO.chars().nth(i))
}

/// A page's title, at the left of its band, `y` pixels down.
pub(super) fn title_text(title: String, y: i32) -> Text<'static, (i32, i32), String> {
    Text::new(title, (16, y), ("serif", 19).into_font().color(&BLACK))
}

//! A sheet: several pictures side by side in a grid under one title, as
//! one SVG document (the rules it keeps are on [`Sheet`]).

use super::SceneError;
use super::heading::Heading;
use crate::draw::svg::{Writer, fmt};

/// The white border round the grid, and between its cells.
const BORDER: f64 = 8.0;
/// How far under the heading's last baseline the grid starts.
const UNDER_HEADING: f64 = 14.0;
/// How many points the sheet's width prints at: 16 cm.
const PRINTED_POINTS: f64 = 16.0 / 2.54 * 72.0;
/// The smallest text the sheet prints, in points.
const LEAST_POINTS: f64 = 7.0;
/// The smallest subscript or superscript (a `tspan` of its own size).
const LEAST_SCRIPT_POINTS: f64 = 5.5;

/// Several pictures — scenes, and any other SVG the library writes — side
/// by side in a grid under one title, as one SVG document.
///
/// Each picture is nested whole as an `<svg>` element at its own size,
/// with its own `viewBox`: nothing in it is scaled, so its text keeps the
/// size it was drawn at. A column is as wide as its widest picture and a
/// row as tall as its tallest; a picture narrower than its column is
/// centred in it. The ids of each picture are prefixed (`p0-`, `p1-`, …)
/// so that the sheet's stay unique.
///
/// The sheet is meant to be printed at most 16 cm wide, so it keeps every
/// text at 7 pt or more there: a text of `f` px on a sheet `W` px wide
/// prints at `f` × 453.5 / `W` pt (subscripts and superscripts, set in
/// `tspan`s of their own size, at 5.5 pt or more). [`Sheet::render`]
/// refuses a sheet that would print smaller
/// ([`SceneError::TextTooSmall`]): draw its pictures
/// narrower (a scene of [`Scene::width`] 400 has 13-px text, so two of
/// them side by side print at 7.2 pt).
///
/// [`Scene::width`]: super::Scene::width
///
/// ```
/// use linkage::draw::scene::Sheet;
///
/// let picture = |colour: &str| {
///     format!(
///         r#"<svg xmlns="http://www.w3.org/2000/svg" width="300" height="200" viewBox="0 0 300 200"><rect width="300" height="200" fill="{colour}"/></svg>"#
///     )
/// };
/// let sheet = Sheet::new("Four designs")
///     .columns(2)
///     .picture(picture("teal"))
///     .picture(picture("navy"))
///     .picture(picture("olive"))
///     .picture(picture("maroon"))
///     .render()?;
/// assert_eq!(sheet.matches("<svg").count(), 5);
/// # Ok::<(), linkage::draw::scene::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    title: String,
    subtitle: Option<String>,
    columns: usize,
    pictures: Vec<String>,
}

/// A picture taken apart for nesting.
struct Nested {
    width: f64,
    height: f64,
    view_box: String,
    /// The root's other attributes (its namespaces among them), ids
    /// prefixed.
    attributes: Vec<(String, String)>,
    /// Everything inside the root, ids prefixed.
    body: String,
    fonts: Fonts,
}

/// The smallest font sizes a picture sets, in px: of its text, and of its
/// subscripts and superscripts (`tspan`s of their own size).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Fonts {
    text: Option<f64>,
    script: Option<f64>,
}

impl Sheet {
    /// An empty sheet titled `title` (an empty title: none), two pictures
    /// to a row.
    pub fn new(title: &str) -> Sheet {
        Sheet {
            title: title.into(),
            subtitle: None,
            columns: 2,
            pictures: Vec::new(),
        }
    }

    /// A line under the title, in smaller type.
    pub fn subtitle(mut self, subtitle: &str) -> Sheet {
        self.subtitle = Some(subtitle.into());
        self
    }

    /// How many pictures to a row (at least 1; default 2).
    pub fn columns(mut self, columns: usize) -> Sheet {
        self.columns = columns;
        self
    }

    /// The next picture, in rows from the top left: an SVG document such
    /// as [`Scene::render`](super::Scene::render) writes.
    pub fn picture(mut self, svg: impl Into<String>) -> Sheet {
        self.pictures.push(svg.into());
        self
    }

    /// The sheet as one SVG document; an error for no pictures, no
    /// columns, a picture that is not an SVG document sized in pixels,
    /// or text that would print below 7 pt with the sheet 16 cm wide.
    pub fn render(&self) -> Result<String, SceneError> {
        if self.columns == 0 {
            return Err(SceneError::BadSetting {
                what: "the number of a sheet's columns",
                must: "at least 1",
                value: 0.0,
            });
        }
        if self.pictures.is_empty() {
            return Err(SceneError::EmptySheet);
        }
        let nested: Vec<Nested> = self
            .pictures
            .iter()
            .enumerate()
            .map(|(index, svg)| nest(svg, index))
            .collect::<Result<_, _>>()?;
        let columns = self.columns.min(nested.len());
        let rows = nested.len().div_ceil(columns);
        let mut column_widths = vec![0.0f64; columns];
        let mut row_heights = vec![0.0f64; rows];
        for (k, picture) in nested.iter().enumerate() {
            let (row, column) = (k / columns, k % columns);
            column_widths[column] = column_widths[column].max(picture.width);
            row_heights[row] = row_heights[row].max(picture.height);
        }
        let width = column_widths.iter().sum::<f64>() + BORDER * (columns + 1) as f64;
        let heading = Heading::new(Some(&self.title), self.subtitle.as_deref(), width);
        // The text of each picture, then of the heading, printed.
        let fonts = nested
            .iter()
            .enumerate()
            .flat_map(|(k, picture)| {
                [
                    picture.fonts.text.map(|font| (Some(k), font, LEAST_POINTS)),
                    picture
                        .fonts
                        .script
                        .map(|font| (Some(k), font, LEAST_SCRIPT_POINTS)),
                ]
            })
            .flatten()
            .chain(
                heading
                    .smallest_font()
                    .map(|font| (None, font, LEAST_POINTS)),
            );
        for (picture, font, least) in fonts {
            let printed = font * PRINTED_POINTS / width;
            if printed < least {
                return Err(SceneError::TextTooSmall {
                    picture,
                    font,
                    width,
                    printed,
                    least,
                });
            }
        }
        let top = heading.bottom().map_or(BORDER, |b| b + UNDER_HEADING);
        let height = top + row_heights.iter().sum::<f64>() + BORDER * rows as f64;
        let mut w = Writer::svg(width, height);
        w.element(
            "rect",
            &[("width", "100%"), ("height", "100%"), ("fill", "white")],
        );
        heading.draw(&mut w, width);
        for (k, picture) in nested.iter().enumerate() {
            let (row, column) = (k / columns, k % columns);
            let left = BORDER * (column + 1) as f64 + column_widths[..column].iter().sum::<f64>();
            let x = left + (column_widths[column] - picture.width) / 2.0;
            let y = top + BORDER * row as f64 + row_heights[..row].iter().sum::<f64>();
            let index = k.to_string();
            let (x, y) = (fmt(x), fmt(y));
            let (picture_width, picture_height) = (fmt(picture.width), fmt(picture.height));
            let mut attributes: Vec<(&str, &str)> = vec![
                ("class", "sheet-picture"),
                ("data-picture", &index),
                ("x", &x),
                ("y", &y),
                ("width", &picture_width),
                ("height", &picture_height),
                ("viewBox", &picture.view_box),
            ];
            attributes.extend(
                picture
                    .attributes
                    .iter()
                    .map(|(key, value)| (key.as_str(), value.as_str())),
            );
            w.open("svg", &attributes);
            w.verbatim(&picture.body);
            w.close("svg");
        }
        Ok(w.finish())
    }
}

/// The picture at `index` taken apart for nesting: its size and view
/// box, its root's other attributes and its body, ids prefixed.
fn nest(svg: &str, index: usize) -> Result<Nested, SceneError> {
    let not_a_picture = SceneError::NotAPicture { index };
    let start = svg
        .match_indices("<svg")
        .map(|(at, _)| at)
        .find(|&at| {
            svg[at + 4..]
                .chars()
                .next()
                .is_some_and(|c| c.is_whitespace() || c == '>')
        })
        .ok_or_else(|| not_a_picture.clone())?;
    let open_end = start
        + svg[start..]
            .find('>')
            .ok_or_else(|| not_a_picture.clone())?;
    let close = svg.rfind("</svg>").ok_or_else(|| not_a_picture.clone())?;
    if close <= open_end || svg[..open_end].ends_with('/') {
        return Err(not_a_picture);
    }
    let attributes = attributes(&svg[start + 4..open_end]).ok_or_else(|| not_a_picture.clone())?;
    let value = |key: &str| {
        attributes
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    };
    let pixels = |key: &str| {
        value(key)
            .map(|v| v.trim().trim_end_matches("px"))
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|v| v.is_finite() && *v > 0.0)
    };
    let (Some(width), Some(height)) = (pixels("width"), pixels("height")) else {
        return Err(not_a_picture);
    };
    let view_box = match value("viewBox") {
        Some(v) => {
            let numbers: Vec<f64> = v
                .split(|c: char| c.is_whitespace() || c == ',')
                .filter(|n| !n.is_empty())
                .map(str::parse)
                .collect::<Result<_, _>>()
                .map_err(|_| not_a_picture.clone())?;
            if numbers.len() != 4 || numbers.iter().any(|n| !n.is_finite()) {
                return Err(not_a_picture);
            }
            numbers
                .iter()
                .map(|&n| fmt(n))
                .collect::<Vec<_>>()
                .join(" ")
        }
        None => format!("0 0 {} {}", fmt(width), fmt(height)),
    };
    let prefix = format!("p{index}-");
    let body = prefix_ids(&svg[open_end + 1..close], &prefix);
    let fonts = smallest_fonts(svg);
    let attributes = attributes
        .into_iter()
        .filter(|(k, _)| !matches!(k.as_str(), "x" | "y" | "width" | "height" | "viewBox"))
        .map(|(k, v)| {
            let v = if k == "id" { format!("{prefix}{v}") } else { v };
            (k, v)
        })
        .collect();
    Ok(Nested {
        width,
        height,
        view_box,
        attributes,
        body,
        fonts,
    })
}

/// The attributes of a start tag (what lies between its name and its
/// `>`), values unescaped; `None` if they cannot be read.
fn attributes(tag: &str) -> Option<Vec<(String, String)>> {
    let mut out = Vec::new();
    let mut rest = tag.trim_start();
    while !rest.is_empty() {
        let equals = rest.find('=')?;
        let key = rest[..equals].trim();
        rest = rest[equals + 1..].trim_start();
        let quote = rest.chars().next().filter(|q| *q == '"' || *q == '\'')?;
        let end = rest[1..].find(quote)?;
        out.push((key.to_string(), unescape(&rest[1..1 + end])));
        rest = rest[end + 2..].trim_start();
    }
    Some(out)
}

/// The five entities the SVG writer escapes, back as characters.
fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// The markup with every id, and every reference to one, prefixed.
fn prefix_ids(markup: &str, prefix: &str) -> String {
    markup
        .replace(" id=\"", &format!(" id=\"{prefix}"))
        .replace("url(#", &format!("url(#{prefix}"))
        .replace("href=\"#", &format!("href=\"#{prefix}"))
}

/// The smallest font sizes the picture sets (`font-size="…"` attributes
/// and `font-size:` in styles, in px), those of `tspan`s apart.
fn smallest_fonts(svg: &str) -> Fonts {
    let mut fonts = Fonts::default();
    for (at, key) in svg.match_indices("font-size") {
        let rest = svg[at + key.len()..].trim_start();
        let Some(rest) = rest
            .strip_prefix('=')
            .map(|r| r.trim_start().trim_start_matches(['"', '\'']))
            .or_else(|| rest.strip_prefix(':').map(str::trim_start))
        else {
            continue;
        };
        let number: String = rest
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        let Some(size) = number.parse::<f64>().ok().filter(|f| *f > 0.0) else {
            continue;
        };
        // The element it belongs to: the last tag opened before it.
        let in_tspan = svg[..at]
            .rfind('<')
            .is_some_and(|open| svg[open + 1..].starts_with("tspan"));
        let least = if in_tspan {
            &mut fonts.script
        } else {
            &mut fonts.text
        };
        *least = Some(least.map_or(size, |l: f64| l.min(size)));
    }
    fonts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_picture_taken_apart() {
        let svg = r##"<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" width="300px" height="200" viewBox="0, 0, 600, 400">
<text id="t" font-size="13">a<tspan dy="2" font-size="7">2</tspan></text><g style="font-size: 9.5px"/><use href="#t"/>
</svg>
"##;
        let nested = nest(svg, 3).unwrap();
        assert_eq!((nested.width, nested.height), (300.0, 200.0));
        assert_eq!(nested.view_box, "0 0 600 400");
        assert_eq!(
            nested.attributes,
            [(
                "xmlns".to_string(),
                "http://www.w3.org/2000/svg".to_string()
            )]
        );
        assert!(nested.body.contains(r#"<text id="p3-t""#));
        assert!(nested.body.contains(r##"href="#p3-t""##));
        assert_eq!(
            nested.fonts,
            Fonts {
                text: Some(9.5),
                script: Some(7.0)
            }
        );
        for bad in [
            "no picture",
            r#"<svg width="10" height="10"/>"#,
            r#"<svg width="10cm" height="10"></svg>"#,
            r#"<svg height="10"></svg>"#,
            r#"<svg width="10" height="10" viewBox="0 0 10"></svg>"#,
        ] {
            assert!(nest(bad, 0).is_err(), "{bad}");
        }
    }
}

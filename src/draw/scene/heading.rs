//! The heading of a picture: a title and a subtitle under it, centred,
//! each wrapped at spaces to the picture's width.

use super::style;
use crate::draw::svg::{Writer, fmt};

/// The title's and the subtitle's font sizes.
pub(super) const TITLE_SIZE: f64 = 17.0;
pub(super) const SUBTITLE_SIZE: f64 = 13.0;
/// The baseline of the heading's first line.
const FIRST_BASELINE: f64 = style::MARGIN - 8.0;
/// What the text may not come nearer the picture's sides than.
const SIDE: f64 = 12.0;

/// The lines of a heading, wrapped, with their baselines.
#[derive(Clone, Debug, Default)]
pub(super) struct Heading {
    lines: Vec<Line>,
}

#[derive(Clone, Debug)]
struct Line {
    text: String,
    size: f64,
    class: &'static str,
    baseline: f64,
}

impl Heading {
    /// The title (if any) and the subtitle under it (if any), wrapped to
    /// a picture `width` pixels wide.
    pub(super) fn new(title: Option<&str>, subtitle: Option<&str>, width: f64) -> Heading {
        let room = width - 2.0 * SIDE;
        let mut lines = Vec::new();
        let mut baseline = FIRST_BASELINE;
        for (text, size, class) in [
            (title, TITLE_SIZE, "title"),
            (subtitle, SUBTITLE_SIZE, "subtitle"),
        ] {
            let Some(text) = text.filter(|t| !t.trim().is_empty()) else {
                continue;
            };
            for piece in wrap(text, size, room) {
                if !lines.is_empty() {
                    baseline += 1.25 * size;
                }
                lines.push(Line {
                    text: piece,
                    size,
                    class,
                    baseline,
                });
            }
        }
        Heading { lines }
    }

    /// The baseline of the last line, if there is a line.
    pub(super) fn bottom(&self) -> Option<f64> {
        self.lines.last().map(|line| line.baseline)
    }

    /// The smallest font size of the heading, if it has a line.
    pub(super) fn smallest_font(&self) -> Option<f64> {
        self.lines.iter().map(|line| line.size).reduce(f64::min)
    }

    /// Every line, centred in a picture `width` pixels wide.
    pub(super) fn draw(&self, w: &mut Writer, width: f64) {
        for line in &self.lines {
            w.open(
                "text",
                &[
                    ("class", line.class),
                    ("x", &fmt(width / 2.0)),
                    ("y", &fmt(line.baseline)),
                    ("text-anchor", "middle"),
                    ("font-family", style::FONT),
                    ("font-size", &fmt(line.size)),
                    ("fill", style::INK),
                ],
            );
            w.text(&line.text);
            w.close("text");
        }
    }
}

/// About how wide `text` is set upright in `style::FONT` at `size` px, on
/// the wide side (the font's advances rounded up: capitals 0.7 em, digits
/// 0.64 em, narrow letters and punctuation 0.3 to 0.38 em, m and w 0.9 em,
/// the rest 0.6 em).
pub(super) fn text_width(text: &str, size: f64) -> f64 {
    let ems: f64 = text
        .chars()
        .map(|c| match c {
            'i' | 'j' | 'l' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' => 0.3,
            ' ' | 'f' | 't' | 'r' | '(' | ')' | '[' | ']' | '/' | '-' => 0.38,
            'm' | 'w' | 'M' | 'W' | '%' | '—' => 0.9,
            '0'..='9' => 0.64,
            c if c.is_uppercase() => 0.7,
            _ => 0.6,
        })
        .sum();
    ems * size
}

/// `text` broken at spaces into lines no wider than `room` (a word wider
/// than that alone on its line).
fn wrap(text: &str, size: f64, room: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let longer = if line.is_empty() {
            word.to_string()
        } else {
            format!("{line} {word}")
        };
        if line.is_empty() || text_width(&longer, size) <= room {
            line = longer;
        } else {
            lines.push(std::mem::replace(&mut line, word.to_string()));
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_lines_wrap_at_spaces() {
        let text = "The best design of each tool at several poses with its coupler curve";
        let lines = wrap(text, 17.0, 300.0);
        assert!(lines.len() > 1);
        assert_eq!(lines.join(" "), text);
        assert!(lines.iter().all(|l| text_width(l, 17.0) <= 300.0));
        assert_eq!(wrap("short", 17.0, 300.0), ["short"]);
    }

    #[test]
    fn one_title_line_keeps_its_place() {
        let heading = Heading::new(Some("A four-bar"), None, 720.0);
        assert_eq!(heading.bottom(), Some(FIRST_BASELINE));
        assert!(Heading::new(None, None, 720.0).bottom().is_none());
        let both = Heading::new(Some("A four-bar"), Some("at 20°"), 720.0);
        assert_eq!(both.bottom(), Some(FIRST_BASELINE + 1.25 * SUBTITLE_SIZE));
    }
}

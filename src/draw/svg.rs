//! A small SVG writer: elements with escaped attributes and text, numbers
//! to a hundredth of a pixel.

use std::fmt::Write as _;

/// An SVG document being written.
pub(crate) struct Writer {
    out: String,
    depth: usize,
}

impl Writer {
    /// A document of `width` × `height` pixels.
    pub(crate) fn svg(width: f64, height: f64) -> Writer {
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#,
            w = fmt(width),
            h = fmt(height)
        );
        Writer { out, depth: 1 }
    }

    fn start(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.out.push_str(&"  ".repeat(self.depth));
        self.out.push('<');
        self.out.push_str(name);
        for (key, value) in attributes {
            let _ = write!(self.out, r#" {key}="{}""#, escape(value));
        }
    }

    /// `<name …/>`
    pub(crate) fn element(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.start(name, attributes);
        self.out.push_str("/>\n");
    }

    /// `<name …>`, to be closed by [`Writer::close`].
    pub(crate) fn open(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.start(name, attributes);
        self.out.push_str(">\n");
        self.depth += 1;
    }

    /// Text content, escaped.
    pub(crate) fn text(&mut self, text: &str) {
        self.out.push_str(&"  ".repeat(self.depth));
        self.out.push_str(&escape(text));
        self.out.push('\n');
    }

    /// `<text …>` with its runs on one line (so that no space comes
    /// between them): each run's text escaped, in a `tspan` when it moves
    /// the baseline by `dy` or has its own font size.
    pub(crate) fn text_runs(&mut self, attributes: &[(&str, &str)], runs: &[Run]) {
        self.start("text", attributes);
        self.out.push('>');
        for run in runs {
            if run.dy == 0.0 && run.size.is_none() {
                self.out.push_str(&escape(&run.text));
                continue;
            }
            self.out.push_str("<tspan");
            if run.dy != 0.0 {
                let _ = write!(self.out, r#" dy="{}""#, fmt(run.dy));
            }
            if let Some(size) = run.size {
                let _ = write!(self.out, r#" font-size="{}""#, fmt(size));
            }
            let _ = write!(self.out, ">{}</tspan>", escape(&run.text));
        }
        self.out.push_str("</text>\n");
    }

    /// Markup written as it is given: a whole element of another document
    /// (such as a picture nested in a sheet), already well-formed.
    pub(crate) fn verbatim(&mut self, markup: &str) {
        self.out.push_str(markup);
        if !markup.ends_with('\n') {
            self.out.push('\n');
        }
    }

    pub(crate) fn close(&mut self, name: &str) {
        self.depth = self.depth.saturating_sub(1);
        self.out.push_str(&"  ".repeat(self.depth));
        let _ = writeln!(self.out, "</{name}>");
    }

    pub(crate) fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A piece of a text: its characters, how far it moves the baseline down
/// from the previous run's, and its own font size if it has one.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Run {
    pub(crate) text: String,
    pub(crate) dy: f64,
    pub(crate) size: Option<f64>,
}

/// A coordinate to 0.01 px, without trailing zeros ("12.5", "-3", "0").
pub(crate) fn fmt(x: f64) -> String {
    let text = format!("{x:.2}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

/// The largest 1, 2 or 5 × 10ᵏ not above x (1 for anything not positive
/// and finite): arrow scales and scale-bar lengths a reader can use.
pub(crate) fn nice_below(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let decade = 10f64.powf(x.log10().floor());
    let mantissa = x / decade;
    let nice = if mantissa >= 5.0 {
        5.0
    } else if mantissa >= 2.0 {
        2.0
    } else {
        1.0
    };
    nice * decade
}

/// A scale bar `pixels` long from (x, y), with end ticks: `⊢——⊣`.
pub(crate) fn scale_bar(w: &mut Writer, x: f64, y: f64, pixels: f64) {
    w.element(
        "path",
        &[
            ("id", "scale-bar"),
            (
                "d",
                &format!("M{} {} v-4 v8 v-4 h{} v-4 v8", fmt(x), fmt(y), fmt(pixels)),
            ),
            ("fill", "none"),
            ("stroke", crate::draw::palette::INK),
            ("stroke-width", "1.4"),
        ],
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_escapes() {
        assert_eq!(fmt(12.3049), "12.3");
        assert_eq!(fmt(-0.001), "0");
        assert_eq!(fmt(5.0), "5");
        assert_eq!(fmt(-2.255), "-2.25");
        assert_eq!(escape(r#"a<b & "c""#), "a&lt;b &amp; &quot;c&quot;");
    }

    #[test]
    fn round_numbers_below() {
        assert_eq!(nice_below(0.0234), 0.02);
        assert_eq!(nice_below(0.00071), 0.0005);
        assert_eq!(nice_below(3.0), 2.0);
        assert_eq!(nice_below(1.0), 1.0);
        assert_eq!(nice_below(-1.0), 1.0);
    }
}

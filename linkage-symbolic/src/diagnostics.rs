//! Located mistakes in a file and their rendering as a compiler prints
//! them:
//!
//! ```text
//! error: unknown name `thta3`: not a coordinate, a point, a parameter of `FourBar` or a constant of `std::f64::consts`; did you mean `theta3`?
//!  --> fourbar.toml:7:34
//!   |
//! 7 |     l2 * theta2.cos() + l3 * thta3.cos() + l4 * theta4.cos() - l1,
//!   |                              ^^^^^
//! ```
//!
//! A [`Diagnostic`] is a message with, where it has one, the byte range of
//! the file it is about (the primary place), further labelled places
//! ("first `l3` is here") and notes. [`Diagnostics`] holds every mistake
//! of one file, in the order found. The run-time front end
//! ([`crate::text::build`]) makes them from the attribute's errors; a
//! reader of a whole file (the equations inside a TOML file, say) adds its
//! own with [`Diagnostic::error`] and renders all of them with one
//! [`Diagnostics::render`].
//!
//! The renderer is `codespan-reporting`, with its ASCII characters: it
//! draws rustc's layout (`-->`, the gutter, carets under the primary
//! place, dashes under the others, notes after `=`), depends on two small
//! crates only (`termcolor` for colour, `unicode-width` for columns) and
//! builds for `wasm32-unknown-unknown`. Of the alternatives, `ariadne`
//! draws its own, box-drawn layout, not a compiler's, and `miette` brings
//! a reporting framework (derives, hooks, a dozen dependencies) where one
//! function is needed.

use codespan_reporting::diagnostic as codespan;
use codespan_reporting::files::SimpleFile;
use codespan_reporting::term::{self, Chars, Config};
use std::fmt;
use std::ops::Range;

/// One mistake: a message, where it is (a byte range of the file, if the
/// mistake has a place), other places it names, and notes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    message: String,
    range: Option<Range<usize>>,
    labels: Vec<Label>,
    notes: Vec<String>,
}

/// A further place a [`Diagnostic`] names, with what to say of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Label {
    range: Range<usize>,
    message: String,
}

impl Label {
    /// The place: a byte range of the file.
    pub fn range(&self) -> Range<usize> {
        self.range.clone()
    }

    /// What is said of it.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl Diagnostic {
    /// An error about the bytes `range` of the file, or about the file as a
    /// whole (`None`: rendered without a snippet).
    pub fn error(message: impl Into<String>, range: Option<Range<usize>>) -> Diagnostic {
        Diagnostic {
            message: message.into(),
            range,
            labels: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// With a further place, `range`, and what to say of it.
    pub fn with_label(mut self, range: Range<usize>, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            range,
            message: message.into(),
        });
        self
    }

    /// With a note, printed after the snippet (`= note: ...`).
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// What is wrong.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// Where: a byte range of the file, `None` for the file as a whole.
    pub fn range(&self) -> Option<Range<usize>> {
        self.range.clone()
    }

    /// The further places named.
    pub fn labels(&self) -> &[Label] {
        &self.labels
    }

    /// The notes.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// Rendered alone, as [`Diagnostics::render`] renders each.
    pub fn render(&self, file_name: &str, file_text: &str, colour: bool) -> String {
        let file = SimpleFile::new(file_name, file_text);
        let diagnostic = self.to_codespan(file_text);
        let config = Config {
            chars: Chars::ascii(),
            ..Config::default()
        };
        let rendered = if colour {
            let mut buffer = term::termcolor::Buffer::ansi();
            let styles = term::Styles::default();
            let mut writer = term::StylesWriter::new(&mut buffer, &styles);
            term::emit_to_write_style(&mut writer, &config, &file, &diagnostic)
                .map(|()| String::from_utf8_lossy(buffer.as_slice()).into_owned())
        } else {
            term::emit_into_string(&config, &file, &diagnostic)
        };
        // The ranges are clamped to the text, so the renderer has nothing
        // to refuse; should it refuse all the same, the message stays.
        rendered.unwrap_or_else(|_| format!("error: {}\n", self.message))
    }

    /// The renderer's diagnostic, every range clamped to `text` and to its
    /// characters' boundaries (a range from another version of the file
    /// is drawn at the nearest place rather than refused).
    fn to_codespan(&self, text: &str) -> codespan::Diagnostic<()> {
        let mut labels: Vec<codespan::Label<()>> = Vec::new();
        if let Some(range) = &self.range {
            labels.push(codespan::Label::primary((), clamp(range, text)));
        }
        for label in &self.labels {
            labels.push(
                codespan::Label::secondary((), clamp(&label.range, text))
                    .with_message(&label.message),
            );
        }
        codespan::Diagnostic::error()
            .with_message(&self.message)
            .with_labels(labels)
            .with_notes(
                self.notes
                    .iter()
                    .map(|note| format!("note: {note}"))
                    .collect(),
            )
    }
}

/// `range` inside `text`, its ends moved back to characters' boundaries.
fn clamp(range: &Range<usize>, text: &str) -> Range<usize> {
    let boundary = |mut at: usize| {
        at = at.min(text.len());
        while !text.is_char_boundary(at) {
            at -= 1;
        }
        at
    };
    let start = boundary(range.start);
    start..boundary(range.end).max(start)
}

impl fmt::Display for Diagnostic {
    /// The message, and each further place with its byte range (without
    /// the file's text there are no lines and columns to give).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)?;
        if let Some(range) = &self.range {
            write!(f, " (bytes {}..{})", range.start, range.end)?;
        }
        for label in &self.labels {
            let Range { start, end } = label.range;
            write!(f, "; {} (bytes {start}..{end})", label.message)?;
        }
        for note in &self.notes {
            write!(f, "; note: {note}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Diagnostic {}

/// Every mistake of one file, in the order found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Diagnostics(Vec<Diagnostic>);

impl Diagnostics {
    pub fn new() -> Diagnostics {
        Diagnostics::default()
    }

    pub fn push(&mut self, diagnostic: Diagnostic) {
        self.0.push(diagnostic);
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    pub fn len(&self) -> usize {
        self.0.len()
    }

    pub fn iter(&self) -> std::slice::Iter<'_, Diagnostic> {
        self.0.iter()
    }

    /// Every mistake as a compiler prints it, `file_name` in each `-->`
    /// line, the snippets taken from `file_text` (the whole file the
    /// ranges are in); with ANSI colours if `colour`. Each mistake ends
    /// with a blank line.
    pub fn render(&self, file_name: &str, file_text: &str, colour: bool) -> String {
        (self.0.iter())
            .map(|diagnostic| diagnostic.render(file_name, file_text, colour))
            .collect()
    }
}

impl fmt::Display for Diagnostics {
    /// One mistake a line (see [`Diagnostic`]'s `Display`); to show them
    /// with the text they are in, [`Diagnostics::render`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, diagnostic) in self.0.iter().enumerate() {
            if k > 0 {
                writeln!(f)?;
            }
            write!(f, "error: {diagnostic}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Diagnostics {}

impl From<Diagnostic> for Diagnostics {
    fn from(diagnostic: Diagnostic) -> Diagnostics {
        Diagnostics(vec![diagnostic])
    }
}

impl Extend<Diagnostic> for Diagnostics {
    fn extend<I: IntoIterator<Item = Diagnostic>>(&mut self, iter: I) {
        self.0.extend(iter);
    }
}

impl FromIterator<Diagnostic> for Diagnostics {
    fn from_iter<I: IntoIterator<Item = Diagnostic>>(iter: I) -> Diagnostics {
        Diagnostics(iter.into_iter().collect())
    }
}

impl IntoIterator for Diagnostics {
    type Item = Diagnostic;
    type IntoIter = std::vec::IntoIter<Diagnostic>;

    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'a> IntoIterator for &'a Diagnostics {
    type Item = &'a Diagnostic;
    type IntoIter = std::slice::Iter<'a, Diagnostic>;

    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = "name = \"FourBar\"\nclosure = \"l2 * thta3\"\n";

    #[test]
    fn renders_like_a_compiler() {
        let at = FILE.find("thta3").unwrap();
        let d = Diagnostic::error("unknown name `thta3`", Some(at..at + 5));
        let text = d.render("fourbar.toml", FILE, false);
        assert_eq!(
            text,
            "error: unknown name `thta3`\n  \
             --> fourbar.toml:2:17\n  \
             |\n\
             2 | closure = \"l2 * thta3\"\n  \
             |                 ^^^^^\n\n"
        );
    }

    #[test]
    fn labels_and_notes_are_drawn() {
        let second = FILE.find("l2").unwrap();
        let d = Diagnostic::error("`l2` is listed twice", Some(second..second + 2))
            .with_label(0..4, "first `l2` is here")
            .with_note("a parameter is listed once");
        let text = d.render("m.toml", FILE, false);
        assert_eq!(
            text,
            "error: `l2` is listed twice\n  \
             --> m.toml:2:12\n  \
             |\n\
             1 | name = \"FourBar\"\n  \
             | ---- first `l2` is here\n\
             2 | closure = \"l2 * thta3\"\n  \
             |            ^^\n  \
             |\n  \
             = note: a parameter is listed once\n\n"
        );
        let coloured = d.render("m.toml", FILE, true);
        assert!(coloured.contains('\u{1b}'), "{coloured}");
    }

    /// A range past the end, or inside a character, is drawn at the
    /// nearest place; a diagnostic without a place has no snippet.
    #[test]
    fn any_range_renders() {
        let reversed = Range { start: 5, end: 3 };
        for range in [0..1000, 1000..2000, 1..2, reversed] {
            let d = Diagnostic::error("somewhere", Some(range));
            assert!(
                d.render("f", "αβγ\n", false)
                    .starts_with("error: somewhere\n")
            );
        }
        let d = Diagnostic::error("about the file", None);
        assert_eq!(d.render("f", FILE, false), "error: about the file\n\n");
    }

    #[test]
    fn displayed_without_the_text() {
        let mut all = Diagnostics::new();
        all.push(Diagnostic::error("one", Some(1..2)).with_label(3..4, "there"));
        all.push(Diagnostic::error("two", None));
        assert_eq!(
            all.to_string(),
            "error: one (bytes 1..2); there (bytes 3..4)\nerror: two"
        );
        assert_eq!(all.iter().count(), 2);
    }
}

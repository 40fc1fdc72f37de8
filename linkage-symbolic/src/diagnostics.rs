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
use codespan_reporting::files::{self, Files};
use codespan_reporting::term::{self, Chars, Config};
use std::fmt;
use std::ops::Range;

/// A line of a snippet longer than this (bytes) is shown cut to the part
/// around the places on it, with `...` where it is cut: a file of one long
/// line with many mistakes renders in time and space in proportion to the
/// mistakes, not to the mistakes times the line.
const LONG_LINE: usize = 160;
/// How much of a cut line is shown either side of its places (bytes).
const MARGIN: usize = 60;
/// The most mistakes [`Diagnostics::render`] draws; it counts the rest.
pub const MOST_RENDERED: usize = 100;

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
        let starts: Vec<usize> = files::line_starts(file_text).collect();
        self.render_with(file_name, file_text, &starts, colour)
    }

    /// Rendered against the lines of the file its places are on (`starts`:
    /// where each line of `file_text` starts), the long ones cut.
    fn render_with(
        &self,
        file_name: &str,
        file_text: &str,
        starts: &[usize],
        colour: bool,
    ) -> String {
        // Every range clamped to the text and to its characters'
        // boundaries: a range from another version of the file is drawn at
        // the nearest place rather than refused.
        let primary = self.range.as_ref().map(|r| clamp(r, file_text));
        let labels: Vec<Range<usize>> = (self.labels.iter())
            .map(|label| clamp(&label.range, file_text))
            .collect();
        let places: Vec<Range<usize>> = primary.iter().chain(&labels).cloned().collect();
        let excerpt = Excerpt::new(file_name, file_text, starts, &places);
        let diagnostic = self.to_codespan(
            primary.map(|r| excerpt.range(&r)),
            labels.iter().map(|r| excerpt.range(r)).collect(),
        );
        let config = Config {
            chars: Chars::ascii(),
            ..Config::default()
        };
        let rendered = if colour {
            let mut buffer = term::termcolor::Buffer::ansi();
            let styles = term::Styles::default();
            let mut writer = term::StylesWriter::new(&mut buffer, &styles);
            term::emit_to_write_style(&mut writer, &config, &excerpt, &diagnostic)
                .map(|()| String::from_utf8_lossy(buffer.as_slice()).into_owned())
        } else {
            term::emit_into_string(&config, &excerpt, &diagnostic)
        };
        // The ranges are clamped to the text, so the renderer has nothing
        // to refuse; should it refuse all the same, the message stays.
        rendered.unwrap_or_else(|_| format!("error: {}\n", self.message))
    }

    /// The renderer's diagnostic, its primary place and its labels' at
    /// `primary` and `labels` (ranges of the excerpt rendered).
    fn to_codespan(
        &self,
        primary: Option<Range<usize>>,
        labels: Vec<Range<usize>>,
    ) -> codespan::Diagnostic<()> {
        let mut drawn: Vec<codespan::Label<()>> = Vec::new();
        if let Some(range) = primary {
            drawn.push(codespan::Label::primary((), range));
        }
        for (label, range) in self.labels.iter().zip(labels) {
            drawn.push(codespan::Label::secondary((), range).with_message(&label.message));
        }
        let labels = drawn;
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
    let start = floor(text, range.start);
    start..floor(text, range.end).max(start)
}

/// The last character boundary of `text` at or before `at`.
fn floor(text: &str, at: usize) -> usize {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// The first character boundary of `text` at or after `at`.
fn ceil(text: &str, at: usize) -> usize {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at += 1;
    }
    at
}

/// One line of an [`Excerpt`].
struct ExcerptLine {
    /// Its bytes in the excerpt, without the newline.
    at: Range<usize>,
    /// The line in the file, without the newline.
    line: Range<usize>,
    /// The part of it shown...
    shown: Range<usize>,
    /// ... which starts here in the excerpt.
    shown_at: usize,
}

/// The lines of a file a diagnostic draws: those its places are on and
/// the few around them the renderer shows, each cut to the part around
/// its places if it is long; the other lines of the span empty. The
/// renderer reads it as the file: lines are numbered, and columns counted,
/// as in the file.
struct Excerpt<'t> {
    name: &'t str,
    text: &'t str,
    source: String,
    /// The index in the file of the excerpt's first line.
    first: usize,
    lines: Vec<ExcerptLine>,
}

impl<'t> Excerpt<'t> {
    fn new(name: &'t str, text: &'t str, starts: &[usize], places: &[Range<usize>]) -> Self {
        let line_of = |at: usize| starts.partition_point(|&s| s <= at).saturating_sub(1);
        let line_range = |k: usize| {
            let start = starts[k];
            let end = starts.get(k + 1).map_or(text.len(), |&next| next - 1);
            // A line ends before its newline (and a `\r` before it).
            let end = if text.as_bytes().get(end.wrapping_sub(1)) == Some(&b'\r') && end > start {
                end - 1
            } else {
                end
            };
            start..end.max(start)
        };
        let last_line = starts.len().saturating_sub(1);
        // The lines drawn: each place's first line and three after it, its
        // last and the one before, and a line either side (a gap of one
        // line is drawn, not elided).
        let mut shown: Vec<Range<usize>> = Vec::new();
        for place in places {
            let (a, b) = (line_of(place.start), line_of(place.end));
            shown.push(a.saturating_sub(1)..(a + 4).min(last_line));
            shown.push(b.saturating_sub(2)..(b + 1).min(last_line));
        }
        let first = shown.iter().map(|r| r.start).min().unwrap_or(0);
        let last = shown.iter().map(|r| r.end).max().unwrap_or(0);
        let mut source = String::new();
        let mut lines = Vec::new();
        for k in first..=last {
            let line = line_range(k);
            let start = source.len();
            let drawn = shown.iter().any(|r| r.contains(&k) || r.end == k);
            let points: Vec<usize> = (places.iter())
                .flat_map(|p| [p.start, p.end])
                .filter(|&p| line.start <= p && p <= line.end)
                .collect();
            let part = if !drawn {
                line.start..line.start
            } else if line.len() <= LONG_LINE {
                line.clone()
            } else if let (Some(&low), Some(&high)) = (points.iter().min(), points.iter().max()) {
                ceil(text, low.saturating_sub(MARGIN).max(line.start)).min(floor(text, low))
                    ..ceil(text, (high + MARGIN).min(line.end))
            } else {
                line.start..floor(text, line.start + LONG_LINE)
            };
            let part = part.start.max(line.start)..part.end.min(line.end).max(part.start);
            if drawn && part.start > line.start {
                source.push_str("...");
            }
            let shown_at = source.len();
            source.push_str(&text[part.clone()]);
            if drawn && part.end < line.end {
                source.push_str("...");
            }
            lines.push(ExcerptLine {
                at: start..source.len(),
                line,
                shown: part,
                shown_at,
            });
            source.push('\n');
        }
        Excerpt {
            name,
            text,
            source,
            first,
            lines,
        }
    }

    /// The excerpt's line of the file's line `k`.
    fn line(&self, k: usize) -> Option<&ExcerptLine> {
        self.lines.get(k.checked_sub(self.first)?)
    }

    /// Where the file's byte `at` is in the excerpt.
    fn offset(&self, at: usize) -> usize {
        let k = self
            .lines
            .partition_point(|l| l.line.start <= at)
            .saturating_sub(1);
        match self.lines.get(k) {
            Some(l) => {
                let within = at.clamp(l.shown.start, l.shown.end) - l.shown.start;
                l.shown_at + within
            }
            None => 0,
        }
    }

    /// A range of the file, in the excerpt.
    fn range(&self, range: &Range<usize>) -> Range<usize> {
        let start = self.offset(range.start);
        start..self.offset(range.end).max(start)
    }
}

impl<'a> Files<'a> for Excerpt<'_> {
    type FileId = ();
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(self.name)
    }

    fn source(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(&self.source)
    }

    /// The file's index of the line holding the excerpt's byte `at`.
    fn line_index(&'a self, (): (), at: usize) -> Result<usize, files::Error> {
        let k = self
            .lines
            .partition_point(|l| l.at.start <= at)
            .saturating_sub(1);
        Ok(self.first + k)
    }

    /// The file's column of the excerpt's byte `at`.
    fn column_number(&'a self, (): (), k: usize, at: usize) -> Result<usize, files::Error> {
        let Some(l) = self.line(k) else {
            return Ok(1);
        };
        let within = at.saturating_sub(l.shown_at).min(l.shown.len());
        Ok(files::column_index(self.text, l.line.clone(), l.shown.start + within) + 1)
    }

    fn line_range(&'a self, (): (), k: usize) -> Result<Range<usize>, files::Error> {
        let l = self.line(k).ok_or(files::Error::LineTooLarge {
            given: k,
            max: self.first + self.lines.len(),
        })?;
        Ok(l.at.start..l.at.end + 1)
    }
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
    /// with a blank line. The first [`MOST_RENDERED`] are drawn, and the
    /// others counted; a long line is shown cut to the part around the
    /// places on it.
    pub fn render(&self, file_name: &str, file_text: &str, colour: bool) -> String {
        let starts: Vec<usize> = files::line_starts(file_text).collect();
        let mut rendered: String = (self.0.iter().take(MOST_RENDERED))
            .map(|diagnostic| diagnostic.render_with(file_name, file_text, &starts, colour))
            .collect();
        if self.0.len() > MOST_RENDERED {
            rendered.push_str(&format!(
                "error: {} more mistakes, not drawn (the first {MOST_RENDERED} are)\n\n",
                self.0.len() - MOST_RENDERED
            ));
        }
        rendered
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

    /// A long line is shown cut to the part around the place, `...`
    /// where it is cut, at the file's line and column.
    #[test]
    fn a_long_line_is_cut_around_its_place() {
        let line = format!("x = [{}oops{}]", "a, ".repeat(2000), ", b".repeat(2000));
        let file = format!("first\n{line}\nlast\n");
        let at = file.find("oops").unwrap();
        let d = Diagnostic::error("no `oops`", Some(at..at + 4));
        let text = d.render("long.toml", &file, false);
        let column = line.find("oops").unwrap() + 1;
        assert!(
            text.contains(&format!("--> long.toml:2:{column}")),
            "{text}"
        );
        assert!(text.len() < 600, "{} bytes: {text}", text.len());
        let drawn = text.lines().find(|l| l.starts_with("2 |")).unwrap();
        assert!(
            drawn.starts_with("2 | ...") && drawn.ends_with("..."),
            "{drawn}"
        );
        let caret = text.lines().find(|l| l.contains('^')).unwrap();
        assert_eq!(caret.find('^'), drawn.find("oops"), "{text}");
        // The line before and after, short, as they are.
        let label = Diagnostic::error("no `oops`", Some(at..at + 4)).with_label(0..5, "here");
        let text = label.render("long.toml", &file, false);
        assert!(text.contains("1 | first"), "{text}");
        // Places far apart on one long line: shown from the first to the
        // last.
        let end = file.find("]\n").unwrap();
        let both = Diagnostic::error("wide", Some(at..at + 4)).with_label(end..end + 1, "end");
        let text = both.render("long.toml", &file, false);
        assert!(text.contains("oops") && text.contains("end"), "{text}");
    }

    /// Thousands of mistakes on one long line: the first hundred drawn,
    /// each cut, the rest counted.
    #[test]
    fn many_mistakes_render_in_proportion() {
        let text = "65536, ".repeat(3000);
        let all: Diagnostics = (0..3000)
            .map(|k| Diagnostic::error("no entry", Some(7 * k..7 * k + 5)))
            .collect();
        let rendered = all.render("many.toml", &text, false);
        assert_eq!(rendered.matches("error: no entry").count(), MOST_RENDERED);
        assert!(
            rendered.contains("error: 2900 more mistakes, not drawn"),
            "{rendered}"
        );
        assert!(rendered.len() < MOST_RENDERED * 500, "{}", rendered.len());
        assert!(rendered.contains("--> many.toml:1:694\n"), "{rendered}");
    }

    /// Lines ending in CRLF, a place at a line's end and past the text.
    #[test]
    fn places_at_the_ends_render() {
        let file = format!("a = 1\r\nb = {}\r\n", "2".repeat(400));
        for range in [5..7, 6..7, file.len() - 1..file.len(), 8..file.len()] {
            let d = Diagnostic::error("here", Some(range.clone()));
            let text = d.render("crlf.toml", &file, false);
            assert!(
                text.starts_with("error: here\n  --> crlf.toml:"),
                "{range:?}: {text}"
            );
        }
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

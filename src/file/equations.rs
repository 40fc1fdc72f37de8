//! The equations: the attribute's grammar as text, and where in the file it
//! starts.

use super::names::Name;
use super::reader::{Reader, Value};
use linkage_symbolic::text;
use toml::de::DeValue;

/// The equations as written (the inside of `#[linkage::linkage(...)]`:
/// `u = [...], v = [...], points = [...], closure = [...]`, optional
/// `params = [...]`), and the byte offset in the file where they start:
/// `text` is the file's `offset..offset + text.len()`, byte for byte, so a
/// place in the equations is a place in the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equations {
    pub text: String,
    pub offset: usize,
}

impl Reader<'_> {
    /// The equations from their value. They must be written as they are
    /// read (a literal string `'''…'''`, or a string without escapes), so
    /// that their bytes are the file's: an escape (`\n`, `\u03b8`, a
    /// backslash at a line's end) would shift every place after it.
    pub(super) fn equations(&mut self, value: &Value<'_>) -> Option<Equations> {
        let DeValue::String(text) = value.get_ref() else {
            self.wrong_type(
                "equations",
                "a string (the equations between ''' and ''')",
                value,
            );
            return None;
        };
        let span = value.span();
        let Some(inner) = self.verbatim(&span, text) else {
            self.error(
                span,
                "the equations use escapes (`\\`): write them as a literal string, between ''' and ''', so that a place in them is a place in the file",
            );
            return None;
        };
        if text.trim().is_empty() {
            self.error(
                span,
                "the equations are empty: write `u = [...], v = [...], closure = [...]` (and `points = [...]`) between ''' and '''",
            );
            return None;
        }
        Some(Equations {
            text: text.to_string(),
            offset: inner.start,
        })
    }
}

impl Reader<'_> {
    /// The equations' own mistakes, as the file's: what reading them as a
    /// mechanism would report, with `declared` the parameters.
    pub(super) fn check_equations(&mut self, name: &str, equations: &Equations, declared: &[Name]) {
        let parameters: Vec<text::Parameter<'_>> = (declared.iter())
            .map(|p| text::Parameter::declared_at(&p.text, p.span.clone()))
            .collect();
        let at = text::Equations::at(&equations.text, equations.offset);
        let Err(mistakes) = text::build(name, at, &parameters) else {
            return;
        };
        for mistake in mistakes.iter() {
            let at = mistake
                .range()
                .unwrap_or(equations.offset..equations.offset);
            let mut error = self.mistake(at, mistake.message());
            for label in mistake.labels() {
                error = error.label(label.range(), label.message());
            }
            for note in mistake.notes() {
                error = error.note(note);
            }
            self.push(error);
        }
    }
}

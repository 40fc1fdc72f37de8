//! The attribute's errors, which carry spans, as diagnostics, which carry
//! places in the file. A span is in one of three texts the lexer was given
//! during one build: the equations (their bytes, shifted by where they sit
//! in the file), the struct written for the mechanism (the place its
//! parameter is declared) or none (the call site, which is, in a compiler,
//! the whole attribute: here the whole text of the equations).

use super::Equations;
use super::declaration::Declaration;
use crate::diagnostics::Diagnostic;
use proc_macro2::Span;
use std::ops::Range;

/// What places the spans of one build.
pub(super) struct Places<'a> {
    pub equations: Equations<'a>,
    pub declaration: &'a Declaration,
    /// A span of the struct's text (any: a span joins only spans of its
    /// own text, which tells the texts apart).
    pub struct_span: Span,
}

impl Places<'_> {
    /// One error, with the further places it names (`syn::Error::combine`)
    /// as labels; a further place that has none in the file, as a note.
    pub fn diagnostic(&self, error: syn::Error) -> Diagnostic {
        let mut parts = error.into_iter();
        let Some(first) = parts.next() else {
            return Diagnostic::error("an error without a message", None);
        };
        let mut diagnostic = Diagnostic::error(first.to_string(), self.place(first.span()));
        for part in parts {
            diagnostic = match self.place(part.span()) {
                Some(range) => diagnostic.with_label(range, part.to_string()),
                None => diagnostic.with_note(part.to_string()),
            };
        }
        diagnostic
    }

    /// Where `span` is in the file, if anywhere.
    pub fn place(&self, span: Span) -> Option<Range<usize>> {
        if self.struct_span.join(span).is_some() {
            self.declaration.declared_at(span.byte_range())
        } else if Span::call_site().join(span).is_some() {
            Some(self.equations.whole())
        } else {
            Some(self.equations.in_file(span.byte_range()))
        }
    }
}

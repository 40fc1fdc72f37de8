//! Walking the TOML document by hand: each value taken by key, checked for
//! its type, every mistake recorded where it was written and the walk
//! carried on — so that all of a file's mistakes come out at once, each
//! once. (A derived deserializer stops at the first.)

use super::error::FileError;
use super::lines::Lines;
use super::suggest::did_you_mean;
use std::ops::Range;
use toml::Spanned;
use toml::de::{DeArray, DeTable, DeValue};

/// A value of the document, with its byte range.
pub(super) type Value<'i> = Spanned<DeValue<'i>>;

/// The walk's state: the file's text and the mistakes found so far.
pub(super) struct Reader<'t> {
    pub(super) text: &'t str,
    errors: Vec<FileError>,
    /// Where the text's lines start, once a mistake needs it.
    lines: std::cell::OnceCell<Lines<'t>>,
}

impl<'t> Reader<'t> {
    pub(super) fn new(text: &'t str) -> Reader<'t> {
        Reader {
            text,
            errors: Vec::new(),
            lines: std::cell::OnceCell::new(),
        }
    }

    /// Where the text's lines start.
    pub(super) fn lines(&self) -> &Lines<'t> {
        self.lines.get_or_init(|| Lines::new(self.text))
    }

    /// A mistake at `at` (to push, after labels if any).
    pub(super) fn mistake(&self, at: Range<usize>, message: impl Into<String>) -> FileError {
        let place = self.lines().line_col(at.start);
        FileError::at_line(at, place, message)
    }

    /// Records a mistake.
    pub(super) fn push(&mut self, error: FileError) {
        self.errors.push(error);
    }

    /// Records a mistake at `at`.
    pub(super) fn error(&mut self, at: Range<usize>, message: impl Into<String>) {
        let error = self.mistake(at, message);
        self.push(error);
    }

    /// Whether any mistake has been recorded.
    pub(super) fn failed(&self) -> bool {
        !self.errors.is_empty()
    }

    /// The mistakes, in the order of the file.
    pub(super) fn into_errors(self) -> Vec<FileError> {
        let mut errors = self.errors;
        errors.sort_by_key(|e| (e.at.start, e.at.end));
        errors
    }

    /// The range of a string value's text inside the file, if the file
    /// writes it as is (a literal string, or a basic one without escapes):
    /// then a byte of the string is a byte of the file. For a multi-line
    /// string, the newline right after the opening quotes (which TOML
    /// drops) is not part of it.
    pub(super) fn verbatim(&self, span: &Range<usize>, decoded: &str) -> Option<Range<usize>> {
        let raw = self.text.get(span.clone())?;
        let quotes = if raw.starts_with("'''") || raw.starts_with("\"\"\"") {
            3
        } else {
            1
        };
        if raw.len() < 2 * quotes {
            return None;
        }
        let mut start = span.start + quotes;
        let end = span.end - quotes;
        if quotes == 3 {
            let inner = self.text.get(start..end)?;
            if inner.starts_with("\r\n") {
                start += 2;
            } else if inner.starts_with('\n') {
                start += 1;
            }
        }
        (self.text.get(start..end)? == decoded).then_some(start..end)
    }

    /// A value's type, for a message ("a string", "an array").
    fn found(value: &DeValue<'_>) -> &'static str {
        match value {
            DeValue::String(_) => "a string",
            DeValue::Integer(_) => "an integer",
            DeValue::Float(_) => "a float",
            DeValue::Boolean(_) => "a boolean",
            DeValue::Datetime(_) => "a date",
            DeValue::Array(_) => "an array",
            DeValue::Table(_) => "a table",
        }
    }

    /// "`place` must be `expected`, not …", at the value.
    pub(super) fn wrong_type(&mut self, place: &str, expected: &str, value: &Value<'_>) {
        let found = Self::found(value.get_ref());
        self.error(
            value.span(),
            format!("`{place}` must be {expected}, not {found}"),
        );
    }

    /// A string value.
    pub(super) fn string<'v>(&mut self, place: &str, value: &'v Value<'_>) -> Option<&'v str> {
        match value.get_ref() {
            DeValue::String(s) => Some(s.as_ref()),
            _ => {
                self.wrong_type(place, "a string", value);
                None
            }
        }
    }

    /// An array value.
    pub(super) fn array<'v, 'i>(
        &mut self,
        place: &str,
        expected: &str,
        value: &'v Value<'i>,
    ) -> Option<&'v DeArray<'i>> {
        match value.get_ref() {
            DeValue::Array(a) => Some(a),
            _ => {
                self.wrong_type(place, expected, value);
                None
            }
        }
    }

    /// A table value, to take its keys from; `path` names it in messages
    /// (`drive.theta2`).
    pub(super) fn table<'v, 'i>(
        &mut self,
        path: &str,
        expected: &str,
        value: &'v Value<'i>,
    ) -> Option<Table<'v, 'i>> {
        match value.get_ref() {
            DeValue::Table(t) => Some(Table::new(t, path, value.span())),
            _ => {
                self.wrong_type(path, expected, value);
                None
            }
        }
    }

    /// A whole number from `least` to `most`.
    pub(super) fn count(
        &mut self,
        place: &str,
        value: &Value<'_>,
        least: u64,
        most: u64,
    ) -> Option<usize> {
        let range = format!("a whole number from {least} to {most}");
        let DeValue::Integer(integer) = value.get_ref() else {
            self.wrong_type(place, &range, value);
            return None;
        };
        let written = integer.as_str().replace('_', "");
        let parsed = i128::from_str_radix(&written, integer.radix()).ok();
        match parsed {
            Some(n) if (i128::from(least)..=i128::from(most)).contains(&n) => {
                usize::try_from(n).ok()
            }
            _ => {
                self.error(
                    value.span(),
                    format!("`{place}` must be {range}, not {}", integer.as_str()),
                );
                None
            }
        }
    }

    /// Each name of an array of names (strings), with its range.
    pub(super) fn names(
        &mut self,
        place: &str,
        value: &Value<'_>,
    ) -> Option<Vec<(String, Range<usize>)>> {
        let array = self.array(place, "an array of point names", value)?;
        let mut names = Vec::new();
        let mut ok = true;
        for (k, item) in array.iter().enumerate() {
            match item.get_ref() {
                DeValue::String(s) => names.push((s.to_string(), item.span())),
                _ => {
                    self.wrong_type(&format!("{place}[{k}]"), "a point's name", item);
                    ok = false;
                }
            }
        }
        ok.then_some(names)
    }
}

/// A table of the document whose keys are taken one by one; the keys left
/// at [`Table::finish`] are unknown, each an error with the closest known
/// key.
pub(super) struct Table<'v, 'i> {
    entries: &'v DeTable<'i>,
    path: String,
    span: Range<usize>,
    known: Vec<&'static str>,
}

impl<'v, 'i> Table<'v, 'i> {
    pub(super) fn new(entries: &'v DeTable<'i>, path: &str, span: Range<usize>) -> Table<'v, 'i> {
        Table {
            entries,
            path: path.to_owned(),
            span,
            known: Vec::new(),
        }
    }

    /// The table's name in messages: `[drive.theta2]`, or "the file" for
    /// the document itself.
    pub(super) fn describe(&self) -> String {
        if self.path.is_empty() {
            "the file".to_owned()
        } else {
            format!("`{}`", self.path)
        }
    }

    /// The dotted path of one of its keys (`drive.theta2.steps`).
    pub(super) fn place(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_owned()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    /// Where the table is written (its header or braces).
    pub(super) fn span(&self) -> Range<usize> {
        self.span.clone()
    }

    /// The value of `key`, if written (`key` is known from now on).
    pub(super) fn take(&mut self, key: &'static str) -> Option<&'v Value<'i>> {
        self.known.push(key);
        self.entries
            .iter()
            .find(|(k, _)| k.get_ref().as_ref() == key)
            .map(|(_, v)| v)
    }

    /// The value of `key`, or an error at the table that it is missing.
    pub(super) fn require(
        &mut self,
        reader: &mut Reader<'_>,
        key: &'static str,
        what: &str,
    ) -> Option<&'v Value<'i>> {
        let value = self.take(key);
        if value.is_none() {
            let message = format!("{} has no `{key}`: {what}", self.describe());
            reader.error(self.span(), message);
        }
        value
    }

    /// Every entry, in the order of the file: (key, the key's range, the
    /// value), for a table whose keys are names the file chooses.
    pub(super) fn all(&self) -> Vec<(&'v str, Range<usize>, &'v Value<'i>)> {
        let mut all: Vec<_> = self
            .entries
            .iter()
            .map(|(k, v)| (k.get_ref().as_ref(), k.span(), v))
            .collect();
        all.sort_by_key(|(_, span, _)| span.start);
        all
    }

    /// Reports every key not taken as unknown.
    pub(super) fn finish(self, reader: &mut Reader<'_>) {
        let mut unknown: Vec<_> = self
            .entries
            .iter()
            .filter(|(k, _)| !self.known.contains(&k.get_ref().as_ref()))
            .collect();
        unknown.sort_by_key(|(k, _)| k.span().start);
        for (key, _) in unknown {
            let name = key.get_ref().as_ref();
            let hint = did_you_mean(name, self.known.iter().copied());
            let keys = if hint.is_empty() {
                format!(" (its keys: {})", self.known.join(", "))
            } else {
                hint
            };
            reader.error(
                key.span(),
                format!("unknown key `{name}` in {}{keys}", self.describe()),
            );
        }
    }
}

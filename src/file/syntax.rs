//! The file as TOML: parsed, or its syntax errors, one per line.

use super::reader::Reader;
use toml::Spanned;
use toml::de::DeTable;

/// The document, or `None` with its syntax errors recorded. The parser
/// recovers and carries on, but one mistake can leave several errors: on
/// its line (an extra `=`, then the value it did not expect), of which the
/// first is kept; and after a table written twice, each of its keys again,
/// which are not reported.
pub(super) fn document<'t>(reader: &mut Reader<'t>) -> Option<Spanned<DeTable<'t>>> {
    let text = reader.text;
    let (document, mut errors) = DeTable::parse_recoverable(text);
    errors.sort_by_key(|e| e.span().map_or(0, |s| s.start));
    let mut lines = Vec::new();
    // The body of the last table written twice.
    let mut table_twice = 0..0;
    for error in &errors {
        let at = error.span().unwrap_or(0..0);
        let twice = error.message() == "duplicate key";
        if twice && table_twice.contains(&at.start) {
            continue;
        }
        if twice && is_header(line_of(text, at.start)) {
            table_twice = at.end..next_header(text, at.end);
        }
        let mistake = reader.mistake(at.clone(), message(text, error.message(), &at));
        if lines.contains(&mistake.line) {
            continue;
        }
        lines.push(mistake.line);
        reader.push(mistake);
    }
    errors.is_empty().then_some(document)
}

/// Whether a line is a table's header (`[drive.theta2]`).
fn is_header(line: &str) -> bool {
    line.trim_start().starts_with('[')
}

/// The offset of the first header after `offset` (or the text's end).
fn next_header(text: &str, offset: usize) -> usize {
    let mut at = text
        .get(offset..)
        .and_then(|rest| rest.find('\n'))
        .map_or(text.len(), |k| offset + k + 1);
    while at < text.len() {
        let line = line_of(text, at);
        if is_header(line) {
            return at;
        }
        at += line.len() + 1;
    }
    text.len()
}

/// The line of `text` that holds the byte `offset`.
fn line_of(text: &str, offset: usize) -> &str {
    let offset = offset.min(text.len());
    let start = text.as_bytes()[..offset]
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |k| k + 1);
    let end = text.as_bytes()[offset..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(text.len(), |k| offset + k);
    text.get(start..end).unwrap_or_default()
}

/// The parser's message, with the key named where it says "duplicate key".
fn message(text: &str, said: &str, at: &std::ops::Range<usize>) -> String {
    let key = text.get(at.clone()).unwrap_or_default();
    if said == "duplicate key" && !key.is_empty() {
        format!("`{key}` is defined twice: a key or a table is written once")
    } else {
        format!("TOML: {said}")
    }
}

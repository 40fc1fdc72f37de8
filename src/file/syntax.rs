//! The file as TOML: parsed, or its syntax errors, one per line.

use super::lines::Lines;
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
    // The line reported last: the errors are in the order of the text,
    // and one a line is kept (a line of thousands of mistakes is one
    // mistake, found in time in proportion to the file).
    let mut last_line = None;
    // The body of the last table written twice.
    let mut table_twice = 0..0;
    for error in &errors {
        let at = error.span().unwrap_or(0..0);
        let twice = error.message() == "duplicate key";
        if twice && table_twice.contains(&at.start) {
            continue;
        }
        let lines = reader.lines();
        let (line, _) = lines.line_col(at.start);
        if twice && is_header(lines.line_of(at.start)) {
            table_twice = at.end..next_header(lines, text.len(), at.end);
        }
        if last_line == Some(line) {
            continue;
        }
        last_line = Some(line);
        let mistake = reader.mistake(at.clone(), message(text, error.message(), &at));
        reader.push(mistake);
    }
    errors.is_empty().then_some(document)
}

/// Whether a line is a table's header (`[drive.theta2]`).
fn is_header(line: &str) -> bool {
    line.trim_start().starts_with('[')
}

/// The offset of the first header after the line of `offset` (or the
/// text's end, `end`).
fn next_header(lines: &Lines, end: usize, offset: usize) -> usize {
    let mut at = lines.next_line(offset);
    while at < end {
        if is_header(lines.line_of(at)) {
            return at;
        }
        at = lines.next_line(at);
    }
    end
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

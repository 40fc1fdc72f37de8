//! Where the lines of a text start, to place a byte offset by line and
//! column: built once per text, so that a file of many mistakes has each
//! placed in time in proportion to its line, not to the text before it.

/// The starts of the lines of a text.
pub(super) struct Lines<'t> {
    text: &'t str,
    /// The byte offset where each line starts; the first is 0.
    starts: Vec<usize>,
}

impl<'t> Lines<'t> {
    pub(super) fn new(text: &'t str) -> Lines<'t> {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(k, _)| k + 1))
            .collect();
        Lines { text, starts }
    }

    /// The line and column (from 1; the column in characters) of the byte
    /// `offset` (an offset inside a character, or past the end, counts
    /// from the character's start, or the end).
    pub(super) fn line_col(&self, offset: usize) -> (usize, usize) {
        let text = self.text;
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset);
        let start = self.starts[line - 1];
        (line, text[start..offset].chars().count() + 1)
    }

    /// The line that holds the byte `offset`, without its newline.
    pub(super) fn line_of(&self, offset: usize) -> &'t str {
        let text = self.text;
        let line = self
            .starts
            .partition_point(|&s| s <= offset.min(text.len()));
        let start = self.starts[line - 1];
        let end = self.starts.get(line).map_or(text.len(), |&next| next - 1);
        text.get(start..end).unwrap_or_default()
    }

    /// The offset where the line after the one holding `offset` starts
    /// (the text's end if it is the last).
    pub(super) fn next_line(&self, offset: usize) -> usize {
        let line = self
            .starts
            .partition_point(|&s| s <= offset.min(self.text.len()));
        self.starts.get(line).copied().unwrap_or(self.text.len())
    }
}

#[cfg(test)]
mod tests {
    use super::Lines;

    #[test]
    fn lines_and_columns_count_characters_from_one() {
        let text = "ab\nθ = 1\n";
        let lines = Lines::new(text);
        assert_eq!(lines.line_col(0), (1, 1));
        assert_eq!(lines.line_col(3), (2, 1));
        // After θ (two bytes): the second character.
        assert_eq!(lines.line_col(5), (2, 2));
        // Inside θ: its start; past the end: the end.
        assert_eq!(lines.line_col(4), (2, 1));
        assert_eq!(lines.line_col(999), (3, 1));
    }

    #[test]
    fn a_line_is_found_from_any_of_its_offsets() {
        let text = "ab\nθ = 1\n";
        let lines = Lines::new(text);
        assert_eq!(lines.line_of(0), "ab");
        assert_eq!(lines.line_of(2), "ab");
        assert_eq!(lines.line_of(4), "θ = 1");
        assert_eq!(lines.line_of(999), "");
        assert_eq!(lines.next_line(1), 3);
        assert_eq!(lines.next_line(4), 10);
        assert_eq!(lines.next_line(10), 10);
    }
}

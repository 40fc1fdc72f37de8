//! What is wrong with a mechanism file: each mistake a [`FileError`] at its
//! byte range in the file, all of a file's mistakes together in
//! [`FileErrors`], and [`ReadError`] for a file that cannot be read.

use super::lines::Lines;
use std::fmt;
use std::ops::Range;
use std::path::PathBuf;

/// One mistake in a mechanism file: what is wrong, where (a byte range of
/// the file's text), and other places that explain it (each a byte range
/// and a note), for a renderer that shows the file's lines with carets.
/// `Display` writes `line:column: message`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    /// What is wrong, and what would be right.
    pub message: String,
    /// Where: a byte range of the file (empty at a point).
    pub at: Range<usize>,
    /// Other places that explain it: a byte range and a note.
    pub labels: Vec<(Range<usize>, String)>,
    /// The line of `at`'s start, from 1.
    pub line: usize,
    /// The column of `at`'s start, from 1, in characters.
    pub column: usize,
    /// What else to know, at no place.
    pub notes: Vec<String>,
}

impl FileError {
    /// A mistake at `at` in `text`, without labels.
    pub(super) fn new(text: &str, at: Range<usize>, message: impl Into<String>) -> FileError {
        FileError::at_line(at.clone(), Lines::new(text).line_col(at.start), message)
    }

    /// A mistake at `at`, whose start is at `line` and `column`.
    pub(super) fn at_line(
        at: Range<usize>,
        (line, column): (usize, usize),
        message: impl Into<String>,
    ) -> FileError {
        FileError {
            message: message.into(),
            at,
            labels: Vec::new(),
            line,
            column,
            notes: Vec::new(),
        }
    }

    /// The same, with a note at another place.
    pub(super) fn label(mut self, at: Range<usize>, note: impl Into<String>) -> FileError {
        self.labels.push((at, note.into()));
        self
    }

    /// The same, with a note at no place.
    pub(super) fn note(mut self, note: impl Into<String>) -> FileError {
        self.notes.push(note.into());
        self
    }

    /// The line and column (from 1; the column in characters) of the
    /// error's start in `text`, the file it was found in.
    ///
    /// ```
    /// use linkage::file::MechanismFile;
    ///
    /// let text = "name = \"Bar\"\nequations = 'u = [x], v = [t], closure = [x - t],'\n\
    ///             [drive.t]\nfrom = 0\nto = 1\nsteps = 0\n";
    /// let errors = MechanismFile::parse(text).unwrap_err();
    /// assert_eq!(errors.errors[0].line_col(text), (6, 9));
    /// assert_eq!(
    ///     errors.to_string(),
    ///     "6:9: `drive.t.steps` must be a whole number from 1 to 1000000, not 0"
    /// );
    /// ```
    pub fn line_col(&self, text: &str) -> (usize, usize) {
        Lines::new(text).line_col(self.at.start)
    }
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.column, self.message)
    }
}

impl std::error::Error for FileError {}

/// Every mistake of a mechanism file, in the order of the file (one
/// mistake, one error: a mistake does not also report what follows from
/// it). Never empty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileErrors {
    pub errors: Vec<FileError>,
}

impl fmt::Display for FileErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, error) in self.errors.iter().enumerate() {
            if k > 0 {
                f.write_str("\n")?;
            }
            write!(f, "{error}")?;
        }
        Ok(())
    }
}

impl std::error::Error for FileErrors {}

/// A mechanism file that could not be read from disk, or whose text is
/// wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ReadError {
    /// The file could not be read.
    Io {
        path: PathBuf,
        error: std::io::Error,
    },
    /// The file's text has mistakes: its text (non-UTF-8 bytes replaced by
    /// U+FFFD), to show them in, and the mistakes.
    Invalid {
        path: PathBuf,
        text: String,
        errors: FileErrors,
    },
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io { path, error } => {
                write!(f, "cannot read {}: {error}", path.display())
            }
            ReadError::Invalid { path, errors, .. } => {
                for (k, error) in errors.errors.iter().enumerate() {
                    if k > 0 {
                        f.write_str("\n")?;
                    }
                    write!(f, "{}:{error}", path.display())?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Io { error, .. } => Some(error),
            ReadError::Invalid { errors, .. } => Some(errors),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_says_where_and_what() {
        let text = "x = 1\ny = 2\n";
        let error = FileError::new(text, 6..7, "unknown key `y`").label(0..1, "here");
        assert_eq!(error.to_string(), "2:1: unknown key `y`");
        let all = FileErrors {
            errors: vec![error.clone(), FileError::new(text, 0..1, "first")],
        };
        assert_eq!(all.to_string(), "2:1: unknown key `y`\n1:1: first");
        let read = ReadError::Invalid {
            path: "four_bar.toml".into(),
            text: text.into(),
            errors: FileErrors {
                errors: vec![error],
            },
        };
        assert_eq!(read.to_string(), "four_bar.toml:2:1: unknown key `y`");
    }
}

//! A mechanism file's text with new values of its parameters — a design
//! the page's synthesis found, dimensions edited — each written where the
//! old one stood, as a plain number in the units the mechanism computes in
//! (the file's length unit, radians), its comment and every other line as
//! they were. The text written is read back: each parameter must read as
//! the value asked, to the bit, or nothing is written.

use super::MechanismFile;
use std::ops::Range;
use toml::de::{DeTable, DeValue};

/// Why new values cannot be written into a file's text.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum RewriteError {
    /// The text is not a mechanism file that reads without mistakes.
    Unreadable,
    /// The file's `[parameters]` table has no such key (a topology file's
    /// parameters come from its joints, not from such a table).
    NotAParameter(String),
    /// A value is not finite.
    NotFinite { parameter: String, value: f64 },
    /// Written, the parameter would read as another value.
    ReadsOtherwise { parameter: String, value: f64 },
}

crate::error::error_impls! {
    RewriteError {
        Self::Unreadable => ("the text is not a mechanism file that reads without mistakes"),
        Self::NotAParameter(name) => ("`{name}` is not a key of the file's [parameters]: its value cannot be written into the text"),
        Self::NotFinite { parameter, value } => ("`{parameter}` = {value} is not finite"),
        Self::ReadsOtherwise { parameter, value } => ("`{parameter}` written as {value:?} would read otherwise"),
    }
    wraps {}
}

/// `text` with each parameter of `values` given its value.
pub fn with_parameters(text: &str, values: &[(&str, f64)]) -> Result<String, RewriteError> {
    MechanismFile::parse(text).map_err(|_| RewriteError::Unreadable)?;
    let document = DeTable::parse(text).map_err(|_| RewriteError::Unreadable)?;
    let table = (document.get_ref().iter())
        .find(|(k, _)| k.get_ref().as_ref() == "parameters")
        .and_then(|(_, v)| match v.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => None,
        });
    let mut edits: Vec<(Range<usize>, String)> = Vec::with_capacity(values.len());
    for &(name, value) in values {
        if !value.is_finite() {
            return Err(RewriteError::NotFinite {
                parameter: name.to_owned(),
                value,
            });
        }
        let span = (table.into_iter().flat_map(|t| t.iter()))
            .find(|(k, _)| k.get_ref().as_ref() == name)
            .map(|(_, v)| v.span())
            .ok_or_else(|| RewriteError::NotAParameter(name.to_owned()))?;
        edits.push((span, format!("{value:?}")));
    }
    edits.sort_by_key(|(span, _)| std::cmp::Reverse(span.start));
    let mut out = text.to_owned();
    for (span, number) in edits {
        out.replace_range(span, &number);
    }
    let read = MechanismFile::parse(&out).map_err(|_| RewriteError::Unreadable)?;
    for &(name, value) in values {
        if read.parameter(name).map(f64::to_bits) != Some(value.to_bits()) {
            return Err(RewriteError::ReadsOtherwise {
                parameter: name.to_owned(),
                value,
            });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FOUR_BAR: &str = include_str!("../../mechanisms/four_bar.toml");

    /// New values are written where the old stood, the comments kept, and
    /// read back to the bit; nothing else of the text changes.
    #[test]
    fn new_values_are_written_in_place() {
        let values = [("l2", 21.456_789_012_345_67), ("l4", -0.1 + 0.2)];
        let out = with_parameters(FOUR_BAR, &values).unwrap();
        let read = MechanismFile::parse(&out).unwrap();
        for (name, value) in values {
            assert_eq!(read.parameter(name).unwrap().to_bits(), value.to_bits());
        }
        assert_eq!(read.parameter("l1"), Some(80.0));
        assert!(
            out.contains("l2 = 21.45678901234567   # crank A–B"),
            "{out}"
        );
        let changed: Vec<(&str, &str)> = (FOUR_BAR.lines().zip(out.lines()))
            .filter(|(a, b)| a != b)
            .collect();
        assert_eq!(changed.len(), 2, "{changed:?}");
        assert_eq!(FOUR_BAR.lines().count(), out.lines().count());
    }

    /// A name the table lacks, a value not finite and a text that does not
    /// read are refused, nothing written.
    #[test]
    fn what_cannot_be_written_is_refused() {
        assert_eq!(
            with_parameters(FOUR_BAR, &[("x_D", 1.0)]),
            Err(RewriteError::NotAParameter("x_D".into()))
        );
        assert!(matches!(
            with_parameters(FOUR_BAR, &[("l2", f64::NAN)]),
            Err(RewriteError::NotFinite { .. })
        ));
        assert_eq!(
            with_parameters("name = 3", &[("l2", 1.0)]),
            Err(RewriteError::Unreadable)
        );
    }
}

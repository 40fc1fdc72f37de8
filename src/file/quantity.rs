//! A number of the file with its unit: a TOML number (in the engine's
//! units), or a string of a number and a unit (`"80 mm"`, `"400 rpm"`).

use super::reader::{Reader, Value};
use super::suggest::did_you_mean;
use super::units::{self, Kind, Unit};
use std::ops::Range;
use toml::de::DeValue;

/// A number read from the file: its value as the engine sees it (SI, with
/// lengths in the file's length unit), its unit as written, what it
/// measures, and where it is written.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantity {
    /// The value the engine sees: SI, lengths in the file's length unit.
    pub value: f64,
    /// The unit as written (`"mm"`), `None` for a bare number or a default.
    pub unit: Option<String>,
    /// What the unit measures ([`Kind::Number`] without one).
    pub kind: Kind,
    /// Where the value is written; `None` for a default the file did not
    /// write.
    pub span: Option<Range<usize>>,
}

impl Quantity {
    /// A default value, not written in the file.
    pub(super) fn default_of(value: f64) -> Quantity {
        Quantity {
            value,
            unit: None,
            kind: Kind::Number,
            span: None,
        }
    }
}

/// A string "number unit" split: the number's and the unit's text and
/// their offsets in the string.
struct Written<'s> {
    number: &'s str,
    number_at: Range<usize>,
    unit: &'s str,
    unit_at: Range<usize>,
}

/// Splits "80.5 mm" (the space optional, blanks around ignored) where the
/// number ends: at the first character that cannot continue it.
fn split(text: &str) -> Written<'_> {
    let start = text.len() - text.trim_start().len();
    let end = text.trim_end().len().max(start);
    let body = &text[start..end];
    let bytes = body.as_bytes();
    let mut k = 0;
    while k < bytes.len() {
        let b = bytes[k];
        let exponent_sign =
            (b == b'-' || b == b'+') && k > 0 && matches!(bytes[k - 1], b'e' | b'E');
        let exponent = (b == b'e' || b == b'E')
            && k > 0
            && bytes[k - 1].is_ascii_digit()
            && bytes
                .get(k + 1)
                .is_some_and(|c| c.is_ascii_digit() || *c == b'-' || *c == b'+');
        if b.is_ascii_digit()
            || b == b'.'
            || (k == 0 && (b == b'-' || b == b'+'))
            || exponent
            || exponent_sign
        {
            k += 1;
        } else {
            break;
        }
    }
    let number = &body[..k];
    let rest = &body[k..];
    let unit_start = k + (rest.len() - rest.trim_start().len());
    Written {
        number,
        number_at: start..start + k,
        unit: &body[unit_start..],
        unit_at: start + unit_start..end,
    }
}

/// What a place accepts: its kinds (a plain number is accepted
/// everywhere), and how a message names it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Accept {
    pub(super) kinds: &'static [Kind],
    pub(super) what: &'static str,
}

impl Accept {
    pub(super) const ANY: Accept = Accept {
        kinds: &[
            Kind::Length,
            Kind::Angle,
            Kind::Time,
            Kind::AngularRate,
            Kind::LinearRate,
            Kind::AngularAcceleration,
            Kind::LinearAcceleration,
            Kind::Mass,
            Kind::Force,
            Kind::Moment,
        ],
        what: "a number",
    };
    pub(super) const LENGTH: Accept = Accept {
        kinds: &[Kind::Length],
        what: "a length",
    };
    pub(super) const ANGLE: Accept = Accept {
        kinds: &[Kind::Angle],
        what: "an angle",
    };
    pub(super) const COORDINATE: Accept = Accept {
        kinds: &[Kind::Angle, Kind::Length],
        what: "an angle or a length",
    };
    pub(super) const RATE: Accept = Accept {
        kinds: &[Kind::AngularRate, Kind::LinearRate],
        what: "a rate",
    };
    pub(super) const ACCELERATION: Accept = Accept {
        kinds: &[Kind::AngularAcceleration, Kind::LinearAcceleration],
        what: "an acceleration",
    };

    /// The units it takes, for a message: "an angle: `rad`, `deg`, `rev`;
    /// or a length: `m`, …".
    fn which(&self) -> String {
        if self.kinds.is_empty() {
            "no unit: a plain number".to_owned()
        } else if self.kinds.len() == Accept::ANY.kinds.len() {
            "a unit of the table of `linkage::file::units`".to_owned()
        } else {
            self.kinds
                .iter()
                .map(|&k| format!("{k}: {}", units::of_kind(k)))
                .collect::<Vec<_>>()
                .join("; or ")
        }
    }
}

impl Reader<'_> {
    /// The quantity at `place`: a TOML number, or a string of a number and
    /// a unit that `accept` takes; lengths converted to `length`.
    pub(super) fn quantity(
        &mut self,
        place: &str,
        value: &Value<'_>,
        accept: Accept,
        length: Unit,
    ) -> Option<Quantity> {
        let span = value.span();
        let expected = format!("{} (a number, or a string such as \"80 mm\")", accept.what);
        let (number, unit) = match value.get_ref() {
            DeValue::Integer(integer) => {
                let written = integer.as_str().replace('_', "");
                let Some(n) = i128::from_str_radix(&written, integer.radix()).ok() else {
                    self.error(
                        span,
                        format!(
                            "`{place}`: {} is not a number this file can hold",
                            integer.as_str()
                        ),
                    );
                    return None;
                };
                (n as f64, None)
            }
            DeValue::Float(float) => {
                let x = float
                    .as_str()
                    .replace('_', "")
                    .parse::<f64>()
                    .unwrap_or(f64::NAN);
                (x, None)
            }
            DeValue::String(s) => return self.written_quantity(place, &span, s, accept, length),
            _ => {
                self.wrong_type(place, &expected, value);
                return None;
            }
        };
        self.finite(place, span.clone(), number)?;
        Some(Quantity {
            value: number,
            unit,
            kind: Kind::Number,
            span: Some(span),
        })
    }

    /// A string's quantity: "80 mm".
    fn written_quantity(
        &mut self,
        place: &str,
        span: &Range<usize>,
        text: &str,
        accept: Accept,
        length: Unit,
    ) -> Option<Quantity> {
        let written = split(text);
        // Offsets in the string are offsets in the file if the file writes
        // it as is; else the whole string is pointed at.
        let inner = self.verbatim(span, text);
        let at = |r: Range<usize>| match &inner {
            Some(inner) => inner.start + r.start..inner.start + r.end,
            None => span.clone(),
        };
        if written.number.is_empty() || !super::decimal::is_decimal(written.number) {
            self.error(
                at(written.number_at.start..written.unit_at.end.max(written.number_at.end)),
                format!(
                    "`{place}` must start with a number (such as \"80 mm\" or \"-1.5e3 mm\"), not `{text}`"
                ),
            );
            return None;
        }
        let (kind, value) = if written.unit.is_empty() {
            // A decimal number (checked above): never NaN.
            let value = super::decimal::scaled(written.number, 1, 1).unwrap_or(f64::NAN);
            (Kind::Number, value)
        } else {
            let Some(unit) = units::lookup(written.unit) else {
                let hint = did_you_mean(written.unit, units::spellings());
                let hint = if hint.is_empty() {
                    format!(" ({})", accept.which())
                } else {
                    hint
                };
                self.error(
                    at(written.unit_at.clone()),
                    format!("unknown unit `{}` in `{place}`{hint}", written.unit),
                );
                return None;
            };
            if !accept.kinds.contains(&unit.kind) {
                self.error(
                    at(written.unit_at.clone()),
                    format!(
                        "`{place}` is {} (`{}`), but {} belongs here ({})",
                        unit.kind,
                        written.unit,
                        accept.what,
                        accept.which()
                    ),
                );
                return None;
            }
            let value = unit.convert(written.number, length).unwrap_or(f64::NAN);
            (unit.kind, value)
        };
        self.finite(place, at(written.number_at.clone()), value)?;
        Some(Quantity {
            value,
            unit: (!written.unit.is_empty()).then(|| written.unit.to_owned()),
            kind,
            span: Some(span.clone()),
        })
    }

    /// The value, if finite; else an error.
    fn finite(&mut self, place: &str, at: Range<usize>, value: f64) -> Option<f64> {
        if value.is_finite() {
            Some(value)
        } else {
            self.error(
                at,
                format!(
                    "`{place}` must be a finite number: this one is {}",
                    if value.is_nan() {
                        "not a number"
                    } else {
                        "too large"
                    }
                ),
            );
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splits_a_number_from_its_unit() {
        let w = split(" 80.5 mm ");
        assert_eq!(
            (w.number, w.number_at, w.unit, w.unit_at),
            ("80.5", 1..5, "mm", 6..8)
        );
        let w = split("-1.5e3mm");
        assert_eq!((w.number, w.unit), ("-1.5e3", "mm"));
        let w = split("3 rad/s^2");
        assert_eq!((w.number, w.unit), ("3", "rad/s^2"));
        let w = split("2 m");
        assert_eq!((w.number, w.unit), ("2", "m"));
        // An e that starts a unit is not an exponent.
        let w = split("2 e");
        assert_eq!((w.number, w.unit), ("2", "e"));
        let w = split("mm");
        assert_eq!((w.number, w.unit, w.unit_at), ("", "mm", 0..2));
        let w = split("");
        assert_eq!((w.number, w.unit), ("", ""));
    }
}

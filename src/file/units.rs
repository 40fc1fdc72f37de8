//! The units a mechanism file may write, and their conversion to what the
//! engine sees.
//!
//! The table is small and explicit:
//!
//! | kind | units |
//! |---|---|
//! | length | `m`, `mm`, `cm`, `in`, `ft` |
//! | angle | `rad`, `deg` (`°`), `rev` (`turn`) |
//! | time | `s`, `min` |
//! | angular rate | `rad/s`, `deg/s`, `rpm` (`rev/min`), `rev/s` |
//! | linear rate | `m/s`, `mm/s` |
//! | angular acceleration | `rad/s^2`, `deg/s^2` |
//! | linear acceleration | `m/s^2`, `mm/s^2` |
//! | mass | `kg`, `g` |
//! | force | `N`, `kN` |
//! | moment | `N*m` (`N·m`) |
//!
//! (`²` may stand for `^2`.) A number without a unit is dimensionless, or
//! already in the engine's units.
//!
//! The engine sees SI: metres, radians, seconds, kilograms, newtons — but
//! for lengths, which are in the file's `length_unit` (metres unless the
//! file says otherwise), and so are the lengths inside linear rates,
//! accelerations and moments. What it prints is in the same units.
//!
//! Conversion rounds once: the decimal number as written is scaled
//! exactly and the result rounded to the nearest f64 — "80.3 mm" is the
//! f64 nearest 0.0803, not 80.3 × 0.001 (the product of two rounded
//! numbers); "5 mm" in a file of inches is the f64 nearest 5/25.4. The
//! units that carry π do the same with π to 250 digits: "30 deg" is the
//! f64 nearest π/6, "60 rpm" is [`std::f64::consts::TAU`]. (Rust code
//! rounds more than once: `30f64.to_radians()` and `PI / 6.0` are one ulp
//! below π/6's nearest f64, `73.0 * TAU / 60.0` one below 73 rpm's. A file
//! that must reproduce such a program's number to the bit writes it as a
//! bare number.)

use super::decimal;
use std::fmt;

/// What a quantity measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// A number without a unit: dimensionless, or in the engine's units.
    Number,
    Length,
    Angle,
    Time,
    AngularRate,
    LinearRate,
    AngularAcceleration,
    LinearAcceleration,
    Mass,
    Force,
    Moment,
}

impl Kind {
    /// Whether its unit has a length in it (converted to the file's
    /// length unit).
    fn has_length(self) -> bool {
        matches!(
            self,
            Kind::Length | Kind::LinearRate | Kind::LinearAcceleration | Kind::Moment
        )
    }
}

impl fmt::Display for Kind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Kind::Number => "a plain number",
            Kind::Length => "a length",
            Kind::Angle => "an angle",
            Kind::Time => "a time",
            Kind::AngularRate => "an angular rate",
            Kind::LinearRate => "a linear rate",
            Kind::AngularAcceleration => "an angular acceleration",
            Kind::LinearAcceleration => "a linear acceleration",
            Kind::Mass => "a mass",
            Kind::Force => "a force",
            Kind::Moment => "a moment",
        })
    }
}

/// How a unit's number becomes the engine's: times numerator /
/// denominator (and π), exactly, rounded once.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scale {
    Ratio(u64, u64),
    PiRatio(u64, u64),
}

/// Degrees: π/180.
const DEGREES: Scale = Scale::PiRatio(1, 180);
/// Turns: 2π.
const TURNS: Scale = Scale::PiRatio(2, 1);
/// Turns a minute: 2π/60.
const TURNS_PER_MINUTE: Scale = Scale::PiRatio(2, 60);

/// A unit of the table: its name as written, what it measures, and how it
/// converts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unit {
    /// The unit as the table writes it (`"mm"`, `"rad/s^2"`).
    pub name: &'static str,
    /// What it measures.
    pub kind: Kind,
    scale: Scale,
}

const fn unit(name: &'static str, kind: Kind, scale: Scale) -> Unit {
    Unit { name, kind, scale }
}

/// Every unit, each once; [`ALIASES`] gives the other spellings.
const UNITS: [Unit; 25] = [
    unit("m", Kind::Length, Scale::Ratio(1, 1)),
    unit("mm", Kind::Length, Scale::Ratio(1, 1000)),
    unit("cm", Kind::Length, Scale::Ratio(1, 100)),
    unit("in", Kind::Length, Scale::Ratio(254, 10000)),
    unit("ft", Kind::Length, Scale::Ratio(3048, 10000)),
    unit("rad", Kind::Angle, Scale::Ratio(1, 1)),
    unit("deg", Kind::Angle, DEGREES),
    unit("rev", Kind::Angle, TURNS),
    unit("s", Kind::Time, Scale::Ratio(1, 1)),
    unit("min", Kind::Time, Scale::Ratio(60, 1)),
    unit("rad/s", Kind::AngularRate, Scale::Ratio(1, 1)),
    unit("deg/s", Kind::AngularRate, DEGREES),
    unit("rpm", Kind::AngularRate, TURNS_PER_MINUTE),
    unit("rev/s", Kind::AngularRate, TURNS),
    unit("m/s", Kind::LinearRate, Scale::Ratio(1, 1)),
    unit("mm/s", Kind::LinearRate, Scale::Ratio(1, 1000)),
    unit("rad/s^2", Kind::AngularAcceleration, Scale::Ratio(1, 1)),
    unit("deg/s^2", Kind::AngularAcceleration, DEGREES),
    unit("m/s^2", Kind::LinearAcceleration, Scale::Ratio(1, 1)),
    unit("mm/s^2", Kind::LinearAcceleration, Scale::Ratio(1, 1000)),
    unit("kg", Kind::Mass, Scale::Ratio(1, 1)),
    unit("g", Kind::Mass, Scale::Ratio(1, 1000)),
    unit("N", Kind::Force, Scale::Ratio(1, 1)),
    unit("kN", Kind::Force, Scale::Ratio(1000, 1)),
    unit("N*m", Kind::Moment, Scale::Ratio(1, 1)),
];

/// Other spellings of a unit: (the spelling, the unit's name).
const ALIASES: [(&str, &str); 4] = [
    ("°", "deg"),
    ("turn", "rev"),
    ("rev/min", "rpm"),
    ("°/s", "deg/s"),
];

/// The unit written `text` (`²` for `^2`, `·` for `*` allowed), if the
/// table has it.
pub fn lookup(text: &str) -> Option<Unit> {
    let text = text.replace('²', "^2").replace('·', "*");
    let name = ALIASES
        .iter()
        .find(|(alias, _)| *alias == text)
        .map_or(text.as_str(), |(_, name)| name);
    UNITS.iter().find(|u| u.name == name).copied()
}

/// Every spelling of every unit (for suggestions).
pub(super) fn spellings() -> impl Iterator<Item = &'static str> {
    UNITS
        .iter()
        .map(|u| u.name)
        .chain(ALIASES.iter().map(|(alias, _)| *alias))
}

/// The units of one kind, as a list for a message ("`m`, `mm`, …").
pub(super) fn of_kind(kind: Kind) -> String {
    UNITS
        .iter()
        .filter(|u| u.kind == kind)
        .map(|u| format!("`{}`", u.name))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Unit {
    /// The decimal number `number`, in this unit, in the engine's units
    /// with lengths in `length` (which must be a length); `None` if
    /// `number` is not a decimal number.
    pub(super) fn convert(&self, number: &str, length: Unit) -> Option<f64> {
        match self.scale {
            Scale::Ratio(numerator, denominator) => {
                let (numerator, denominator) = match (self.kind.has_length(), length.scale) {
                    (true, Scale::Ratio(n, d)) => reduced(numerator * d, denominator * n),
                    _ => (numerator, denominator),
                };
                decimal::scaled(number, numerator, denominator)
            }
            Scale::PiRatio(numerator, denominator) => {
                decimal::scaled_by_pi(number, numerator, denominator)
            }
        }
    }
}

/// A ratio in lowest terms.
fn reduced(numerator: u64, denominator: u64) -> (u64, u64) {
    let (mut a, mut b) = (numerator, denominator);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    let divisor = a.max(1);
    (numerator / divisor, denominator / divisor)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn metres() -> Unit {
        lookup("m").unwrap()
    }

    fn convert(number: &str, unit: &str, length: &str) -> f64 {
        lookup(unit)
            .unwrap()
            .convert(number, lookup(length).unwrap())
            .unwrap()
    }

    #[test]
    fn every_spelling_is_found_and_every_name_is_unique() {
        for name in spellings() {
            assert!(lookup(name).is_some(), "{name}");
        }
        for (k, a) in UNITS.iter().enumerate() {
            assert!(
                UNITS[k + 1..].iter().all(|b| b.name != a.name),
                "{}",
                a.name
            );
        }
        assert_eq!(lookup("rad/s²"), lookup("rad/s^2"));
        assert_eq!(lookup("N·m").unwrap().name, "N*m");
        assert_eq!(lookup("°").unwrap().name, "deg");
        assert_eq!(lookup("furlong"), None);
        assert_eq!(lookup("MM"), None);
    }

    #[test]
    fn lengths_to_metres_round_once() {
        assert_eq!(convert("80", "mm", "m"), 0.08);
        assert_eq!(
            convert("80.3", "mm", "m"),
            "80.3e-3".parse::<f64>().unwrap()
        );
        assert_eq!(convert("12", "in", "m"), 0.3048);
        assert_eq!(convert("1", "ft", "m"), 0.3048);
        assert_eq!(convert("2.5", "cm", "m"), 0.025);
    }

    #[test]
    fn lengths_to_a_files_length_unit() {
        // Lengths in mm: mm stay as written, to the bit.
        assert_eq!(convert("41.5", "mm", "mm"), 41.5);
        assert_eq!(convert("0.08", "m", "mm"), 80.0);
        assert_eq!(convert("1", "in", "mm"), 25.4);
        assert_eq!(convert("1", "ft", "mm"), 304.8);
        assert_eq!(convert("5", "mm", "in"), 0.1968503937007874);
        // Rates and accelerations carry the length; angles do not.
        assert_eq!(convert("2", "m/s", "mm"), 2000.0);
        assert_eq!(convert("3", "m/s^2", "mm"), 3000.0);
        assert_eq!(convert("3", "N*m", "mm"), 3000.0);
        assert_eq!(convert("3", "N", "mm"), 3.0);
        assert_eq!(convert("3", "rad", "mm"), 3.0);
    }

    #[test]
    fn units_with_pi_round_once() {
        use std::f64::consts::{PI, TAU};
        // Where Rust's expressions are the nearest f64 too.
        assert_eq!(convert("20", "deg", "m"), 20f64.to_radians());
        assert_eq!(convert("-50", "°", "m"), (-50f64).to_radians());
        assert_eq!(convert("400", "rpm", "m"), 400.0 * TAU / 60.0);
        assert_eq!(convert("60", "rpm", "m"), TAU);
        assert_eq!(convert("1", "rev/s", "m"), TAU);
        assert_eq!(convert("0.5", "rev", "m"), PI);
        assert_eq!(convert("180", "deg/s", "m"), PI);
        assert_eq!(convert("180", "deg/s^2", "m"), PI);
        // Where they are not: π/3's nearest f64 (std's constant), one ulp
        // above.
        use std::f64::consts::FRAC_PI_3;
        assert_eq!(convert("60", "deg", "m"), FRAC_PI_3);
        assert_eq!(FRAC_PI_3.to_bits(), 60f64.to_radians().to_bits() + 1);
    }

    #[test]
    fn other_kinds_to_si() {
        assert_eq!(convert("1.5", "min", "m"), 90.0);
        assert_eq!(convert("250", "g", "m"), 0.25);
        assert_eq!(convert("2.2", "kN", "m"), 2200.0);
        assert_eq!(convert("9.81", "m/s^2", "m"), 9.81);
        assert_eq!(convert("120", "mm/s", "m"), 0.12);
    }

    #[test]
    fn not_a_number_is_none() {
        assert_eq!(lookup("mm").unwrap().convert("eighty", metres()), None);
        assert_eq!(lookup("deg").unwrap().convert("1..2", metres()), None);
    }

    #[test]
    fn the_lists_for_messages() {
        assert_eq!(of_kind(Kind::Length), "`m`, `mm`, `cm`, `in`, `ft`");
        assert_eq!(Kind::AngularRate.to_string(), "an angular rate");
    }
}

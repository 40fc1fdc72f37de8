//! Names: one table of Greek letters and the two ways the project writes a
//! name with it — in formulas (`theta3` → `θ3`) and in pictures (`theta3`
//! → `θ₃`, `G2` → `G₂`) — and the names of a model's symbols, in generated
//! code (`theta3_dot`) and in formulas (`θ̇3`).

use crate::dag::{Constant, Symbol};

/// The Greek letters, by the names an identifier spells them with.
const GREEK: [(&str, char); 24] = [
    ("alpha", 'α'),
    ("beta", 'β'),
    ("gamma", 'γ'),
    ("delta", 'δ'),
    ("epsilon", 'ε'),
    ("zeta", 'ζ'),
    ("eta", 'η'),
    ("theta", 'θ'),
    ("iota", 'ι'),
    ("kappa", 'κ'),
    ("lambda", 'λ'),
    ("mu", 'μ'),
    ("nu", 'ν'),
    ("xi", 'ξ'),
    ("omicron", 'ο'),
    ("pi", 'π'),
    ("rho", 'ρ'),
    ("sigma", 'σ'),
    ("tau", 'τ'),
    ("upsilon", 'υ'),
    ("phi", 'φ'),
    ("chi", 'χ'),
    ("psi", 'ψ'),
    ("omega", 'ω'),
];

/// The Greek letter a word spells: `theta` → θ; capitalised (`Phi`,
/// `PHI`), the capital letter Φ; `None` for any other word.
pub fn letter(word: &str) -> Option<char> {
    let capital = word.starts_with(|c: char| c.is_ascii_uppercase());
    GREEK.iter().find_map(|&(latin, letter)| {
        if word == latin {
            Some(letter)
        } else if capital && word.to_ascii_lowercase() == latin {
            letter.to_uppercase().next()
        } else {
            None
        }
    })
}

/// A name in a formula: a leading Greek word as its letter, the rest as
/// written — `theta3` → `θ3`, `phi_1` → `φ_1`, `Phi` → `Φ`, `l2` → `l2`.
pub fn greek(name: &str) -> String {
    let word_end = name
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(name.len());
    let (word, rest) = name.split_at(word_end);
    match letter(word) {
        Some(letter) => format!("{letter}{rest}"),
        None => name.to_owned(),
    }
}

/// A name in a picture: a Greek word as its letter and trailing digits as
/// subscripts — `theta3` → `θ₃`, `G2` → `G₂`, `phi_12` → `φ₁₂`, `s` → `s`.
pub fn textbook(name: &str) -> String {
    let stem_end = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    let (stem, digits) = name.split_at(stem_end);
    let stem = stem.strip_suffix('_').unwrap_or(stem);
    if stem.is_empty() {
        return name.to_owned();
    }
    match letter(stem) {
        Some(letter) => format!("{letter}{}", subscript(digits)),
        None => format!("{stem}{}", subscript(digits)),
    }
}

/// Decimal digits as subscripts: `12` → `₁₂`; other characters unchanged.
pub fn subscript(digits: &str) -> String {
    digits
        .chars()
        .map(|c| {
            c.to_digit(10)
                .and_then(|d| char::from_u32(0x2080 + d))
                .unwrap_or(c)
        })
        .collect()
}

/// The names of a model's symbols: its parameters (the struct's `f64`
/// fields, `Symbol::Param(k)`) and its coordinates (u then v,
/// `Symbol::Coord(k)`), with their velocities and accelerations.
#[derive(Clone, Debug)]
pub struct SymbolNames {
    fields: Vec<String>,
    coords: Vec<String>,
    /// How many coordinates are dependent (u); the rest are driving (v).
    m: usize,
    /// The parameters p differentiated by, as indices into `fields`.
    params: Vec<u16>,
}

impl SymbolNames {
    /// The names as written by the user (raw identifiers without `r#`).
    pub fn new(
        fields: Vec<String>,
        coords: Vec<String>,
        m: usize,
        params: Vec<u16>,
    ) -> SymbolNames {
        SymbolNames {
            fields,
            coords,
            m,
            params,
        }
    }

    /// The position in p of the parameter `Symbol::Param(k)`, if it is one
    /// of the parameters differentiated by.
    pub fn param_index(&self, k: u16) -> Option<usize> {
        self.params.iter().position(|&d| d == k)
    }

    /// The parameters differentiated by, in the order of p, as a formula
    /// writes them.
    pub fn params_display(&self) -> Vec<String> {
        self.params
            .iter()
            .map(|&k| greek(&self.fields[k as usize]))
            .collect()
    }

    /// The parameters differentiated by, in the order of p, as written.
    pub fn params_code(&self) -> Vec<String> {
        self.params
            .iter()
            .map(|&k| self.fields[k as usize].clone())
            .collect()
    }

    /// How many coordinates are dependent.
    pub fn m(&self) -> usize {
        self.m
    }

    /// A symbol's name in generated code: `l2`, `theta3`, `theta3_dot`,
    /// `theta3_ddot`, `pi`.
    pub fn code(&self, s: Symbol) -> String {
        match s {
            Symbol::Param(k) => self.fields[k as usize].clone(),
            Symbol::Coord(k) => self.coords[k as usize].clone(),
            Symbol::Vel(k) => format!("{}_dot", self.coords[k as usize]),
            Symbol::Acc(k) => format!("{}_ddot", self.coords[k as usize]),
            Symbol::Constant(c) => c.name().to_ascii_lowercase(),
        }
    }

    /// Every name a symbol can take in generated code: temporaries must
    /// avoid them.
    pub fn all_code(&self) -> impl Iterator<Item = String> + '_ {
        let n = self.coords.len() as u16;
        self.fields.iter().cloned().chain(
            (0..n).flat_map(|k| {
                [Symbol::Coord(k), Symbol::Vel(k), Symbol::Acc(k)].map(|s| self.code(s))
            }),
        )
    }

    /// A symbol's name in a formula: Greek letters spelled out in an
    /// identifier become Greek (`theta3` → `θ3`), velocities get a dot
    /// (`θ̇3`) and accelerations two (`θ̈3`).
    pub fn display(&self, s: Symbol) -> String {
        match s {
            Symbol::Param(k) => greek(&self.fields[k as usize]),
            Symbol::Coord(k) => greek(&self.coords[k as usize]),
            Symbol::Vel(k) => dotted(&greek(&self.coords[k as usize]), '\u{307}'),
            Symbol::Acc(k) => dotted(&greek(&self.coords[k as usize]), '\u{308}'),
            Symbol::Constant(c) => constant(c).to_owned(),
        }
    }

    /// A coordinate's name in a formula.
    pub fn coord(&self, k: usize) -> String {
        greek(&self.coords[k])
    }
}

/// A constant of `std::f64::consts` as a formula writes it.
fn constant(c: Constant) -> &'static str {
    use Constant::*;
    match c {
        Pi => "π",
        Tau => "τ",
        E => "e",
        FracPi2 => "π/2",
        FracPi3 => "π/3",
        FracPi4 => "π/4",
        FracPi6 => "π/6",
        FracPi8 => "π/8",
        Frac1Pi => "1/π",
        Frac2Pi => "2/π",
        Frac2SqrtPi => "2/√π",
        Sqrt2 => "√2",
        Frac1Sqrt2 => "1/√2",
        Ln2 => "ln 2",
        Ln10 => "ln 10",
        Log2E => "log₂e",
        Log10E => "log₁₀e",
        Log2_10 => "log₂10",
        Log10_2 => "log₁₀2",
    }
}

/// The name with a combining mark on its first character: `θ3` → `θ̇3`.
fn dotted(name: &str, mark: char) -> String {
    let mut chars = name.chars();
    match chars.next() {
        Some(first) => format!("{first}{mark}{}", chars.as_str()),
        None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_and_pictures() {
        assert_eq!(greek("theta3"), "θ3");
        assert_eq!(greek("phi_1"), "φ_1");
        assert_eq!(greek("Phi"), "Φ");
        assert_eq!(greek("l2"), "l2");
        assert_eq!(greek("thetas"), "thetas");
        assert_eq!(textbook("theta3"), "θ₃");
        assert_eq!(textbook("G2"), "G₂");
        assert_eq!(textbook("phi_12"), "φ₁₂");
        assert_eq!(textbook("s"), "s");
        assert_eq!(textbook("P"), "P");
        assert_eq!(textbook("42"), "42");
        assert_eq!(textbook("Omega2"), "Ω₂");
        assert_eq!(subscript("10"), "₁₀");
        assert_eq!(dotted("θ3", '\u{307}'), "θ\u{307}3");
    }
}

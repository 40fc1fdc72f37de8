//! Which names a file may give: the mechanism's (a Rust type's name, if it
//! is ever written as a struct) and its parameters' and coordinates' (the
//! equations' identifiers).

/// Rust's keywords, strict and reserved: none can name a struct or a field.
const KEYWORDS: [&str; 52] = [
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub",
    "ref", "return", "self", "Self", "static", "struct", "super", "trait", "true", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield", "try", "gen",
];

/// Why `name` cannot be an identifier of the equations, if it cannot: an
/// ASCII letter or `_` first, then letters, digits and `_`; not `_`
/// alone, not a Rust keyword.
pub(crate) fn not_an_identifier(name: &str) -> Option<String> {
    let mut chars = name.chars();
    let first_ok = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    let rest_ok = chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !first_ok || !rest_ok || name == "_" {
        Some(format!(
            "`{name}` is not a name the equations can use: a letter or `_` first, then letters, digits and `_` (ASCII)"
        ))
    } else if KEYWORDS.contains(&name) {
        Some(format!(
            "`{name}` is a Rust keyword, which cannot be a name"
        ))
    } else {
        None
    }
}

/// A name written in the file, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Name {
    /// The name.
    pub text: String,
    /// Where it is written: a key, or a string (quotes included).
    pub span: std::ops::Range<usize>,
}

impl Name {
    pub(super) fn new(text: &str, span: std::ops::Range<usize>) -> Name {
        Name {
            text: text.to_owned(),
            span,
        }
    }
}

impl super::reader::Reader<'_> {
    /// `name` as a [`Name`] if the equations can use it; else an error at
    /// it.
    pub(super) fn identifier(&mut self, name: &str, span: std::ops::Range<usize>) -> Option<Name> {
        match not_an_identifier(name) {
            None => Some(Name::new(name, span)),
            Some(why) => {
                self.error(span, why);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identifiers() {
        for good in ["l1", "theta2", "_x", "FourBar", "x_d"] {
            assert_eq!(not_an_identifier(good), None, "{good}");
        }
        for bad in ["", "1x", "l-1", "θ", "a b", "_", "type", "fn"] {
            assert!(not_an_identifier(bad).is_some(), "{bad}");
        }
    }
}

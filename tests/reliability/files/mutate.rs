//! Mutations of text, token by token: deletions, duplications, swaps,
//! replacements from a dictionary of the grammar's words and awkward
//! numbers, unicode, deep nesting and long inputs.

use super::random::Rng;

/// The text cut into tokens: runs of whitespace, words (letters, digits,
/// `_`), numbers (`1.5e-3`), and every other character alone.
pub(crate) fn tokens(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < chars.len() {
        let c = chars[k];
        let start = k;
        if c.is_whitespace() {
            while k < chars.len() && chars[k].is_whitespace() {
                k += 1;
            }
        } else if c.is_ascii_digit() {
            while k < chars.len() && (chars[k].is_ascii_alphanumeric() || chars[k] == '_') {
                k += 1;
            }
            if k + 1 < chars.len() && chars[k] == '.' && chars[k + 1].is_ascii_digit() {
                k += 1;
                while k < chars.len() && (chars[k].is_ascii_alphanumeric() || chars[k] == '_') {
                    k += 1;
                }
            }
            if k < chars.len() && matches!(chars[k], '+' | '-') && matches!(chars[k - 1], 'e' | 'E')
            {
                k += 1;
                while k < chars.len() && chars[k].is_ascii_digit() {
                    k += 1;
                }
            }
        } else if c.is_alphanumeric() || c == '_' {
            while k < chars.len() && (chars[k].is_alphanumeric() || chars[k] == '_') {
                k += 1;
            }
        } else {
            k += 1;
        }
        out.push(chars[start..k].iter().collect());
    }
    out
}

/// Words of the grammar and of Rust.
pub(crate) const WORDS: &[&str] = &[
    "u",
    "v",
    "points",
    "closure",
    "params",
    "x",
    "y",
    "theta2",
    "theta3",
    "theta4",
    "l1",
    "l2",
    "s",
    "B",
    "C",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "sinh",
    "cosh",
    "tanh",
    "hypot",
    "powi",
    "powf",
    "sqrt",
    "ln",
    "exp",
    "abs",
    "log",
    "f64",
    "std",
    "consts",
    "PI",
    "TAU",
    "E",
    "FRAC_PI_2",
    "NAN",
    "INFINITY",
    "MAX",
    "self",
    "Self",
    "struct",
    "fn",
    "let",
    "as",
    "if",
    "match",
    "_",
    "r#type",
    "r#u",
    "crate",
    "true",
    "include",
    "include_str",
    "env",
];

/// Numbers (and things that look like them) that are awkward to read.
pub(crate) const NUMBERS: &[&str] = &[
    "0",
    "1",
    "2",
    "0.5",
    "2.0",
    "-1.0",
    "1e308",
    "1e309",
    "-1e309",
    "1e-400",
    "5e-324",
    "1.7976931348623157e308",
    "0.0",
    "1_000.5",
    "0x1f",
    "0b101",
    "1u8",
    "2.0f32",
    "3f64",
    "65536",
    "65537",
    "-65536",
    "2147483648",
    "18446744073709551616",
    "340282366920938463463374607431768211456",
    "1e999f64",
    "1.",
    ".5",
    "1e",
    "NaN",
    "nan",
    "inf",
    "f64::NAN",
    "f64::INFINITY",
    "f64::MAX",
    "f64::MIN_POSITIVE",
    "std::f64::consts::PI",
    "(0.0 / 0.0)",
    "(1.0 / 0.0)",
    "(-1.0).sqrt()",
    "(0.0).ln()",
    "(2.0).acos()",
    "(1e308 * 10.0)",
    "'c'",
    "\"text\"",
    "b\"bytes\"",
];

/// Characters from outside ASCII, and ASCII's awkward ones.
pub(crate) const UNICODE: &[&str] = &[
    "θ", "é", "e\u{301}", "ñ", "Ω", "ｘ", "😀", "\u{200b}", "\u{202e}", "\u{feff}", "\u{2028}",
    "\u{85}", "\u{a0}", "\u{0}", "\u{1}", "\u{7f}", "\u{b}", "\r", "\r\n", "\t", "\\", "\\u{3b8}",
    "𝜃", "ᵢ", "²", "٣",
];

/// Every ASCII punctuation character.
const PUNCTUATION: &str = "!\"#$%&'()*+,-./:;<=>?@[\\]^_`{|}~";

/// One of the awkward numbers, or a long run of digits.
pub(crate) fn number(rng: &mut Rng) -> String {
    match rng.below(12) {
        0 => "9".repeat(rng.between(20, 2000)),
        1 => format!("0.{}1", "0".repeat(rng.between(300, 2000))),
        2 => format!("1e{}", rng.next() % 100_000),
        3 => format!("{:e}", f64::from_bits(rng.next())),
        4 => format!("{}", rng.unit() * 100.0),
        _ => rng.pick(NUMBERS).to_string(),
    }
}

/// An expression `inner` nested `depth` deep, one of several ways.
pub(crate) fn nested(rng: &mut Rng, inner: &str, depth: usize) -> String {
    match rng.below(7) {
        0 => format!("{}{inner}{}", "(".repeat(depth), ")".repeat(depth)),
        1 => format!("{inner}{}", ".sin()".repeat(depth)),
        2 => format!("{}{inner}", "-".repeat(depth)),
        3 => format!(
            "{}{inner}{}",
            "hypot(".repeat(depth),
            ", 1.0)".repeat(depth)
        ),
        4 => format!("{}{inner}{}", "(".repeat(depth), ").powi(2)".repeat(depth)),
        5 => format!(
            "{}{inner}{}",
            "(1.0 + ".repeat(depth),
            " * 2.0)".repeat(depth)
        ),
        _ => format!("{}{inner}{}", "atan2(".repeat(depth), ", x)".repeat(depth)),
    }
}

/// A depth about the limits: at them, just past them, far past.
pub(crate) fn depth(rng: &mut Rng) -> usize {
    *rng.pick(&[2, 8, 15, 16, 17, 31, 32, 33, 40, 64, 200, 1000, 5000])
}

/// A long chain of `term` joined by `op`.
pub(crate) fn long(rng: &mut Rng, term: &str) -> String {
    let n = *rng.pick(&[100, 255, 256, 257, 1000, 2047, 4096, 5000, 20_000]);
    let op = rng.pick(&[" + ", " * ", " - ", ", "]);
    vec![term; n].join(op)
}

/// The places of tokens that are not whitespace.
fn solid(tokens: &[String]) -> Vec<usize> {
    (0..tokens.len())
        .filter(|&k| !tokens[k].trim().is_empty())
        .collect()
}

/// A token to put somewhere: a word of the text, of the grammar, a
/// number, punctuation, unicode.
fn new_token(rng: &mut Rng, tokens: &[String]) -> String {
    match rng.below(6) {
        0 if !tokens.is_empty() => rng.pick(tokens).clone(),
        1 => rng.pick(WORDS).to_string(),
        2 => number(rng),
        3 => {
            let k = rng.below(PUNCTUATION.len());
            PUNCTUATION[k..k + 1].to_string()
        }
        4 => rng.pick(UNICODE).to_string(),
        _ => rng
            .pick(&["(", ")", "[", "]", ",", ".", "=", "*", "-"])
            .to_string(),
    }
}

/// One mutation of `text`, token by token.
pub(crate) fn mutate(rng: &mut Rng, text: &str) -> String {
    let mut t = tokens(text);
    let solid = solid(&t);
    if t.is_empty() || solid.is_empty() {
        return new_token(rng, &t);
    }
    let any = |rng: &mut Rng| solid[rng.below(solid.len())];
    match rng.below(16) {
        // Delete a token, or a run of them.
        0 | 1 => {
            let k = any(rng);
            let n = if rng.one_in(3) { rng.few(40) } else { 1 };
            t.drain(k..(k + n).min(t.len()));
        }
        // Duplicate a token or a run.
        2 | 3 => {
            let k = any(rng);
            let n = rng.few(20).min(t.len() - k);
            let copy: Vec<String> = t[k..k + n].to_vec();
            let at = if rng.one_in(2) {
                k + n
            } else {
                rng.below(t.len() + 1)
            };
            for (j, c) in copy.into_iter().enumerate() {
                t.insert(at + j, c);
            }
        }
        // Swap two tokens.
        4 | 5 => {
            let (a, b) = (any(rng), any(rng));
            t.swap(a, b);
        }
        // Replace a token.
        6..=8 => {
            let k = any(rng);
            t[k] = new_token(rng, &t);
        }
        // Replace a number by an awkward one.
        9 => {
            let numbers: Vec<usize> = solid
                .iter()
                .copied()
                .filter(|&k| t[k].starts_with(|c: char| c.is_ascii_digit()))
                .collect();
            let k = if numbers.is_empty() {
                any(rng)
            } else {
                *rng.pick(&numbers)
            };
            t[k] = number(rng);
        }
        // Insert a token.
        10 => {
            let at = rng.below(t.len() + 1);
            let token = new_token(rng, &t);
            t.insert(at, token);
        }
        // Nest a word or number deep.
        11 => {
            let k = any(rng);
            let d = depth(rng);
            t[k] = nested(rng, &t[k].clone(), d);
        }
        // Make a token a long chain.
        12 => {
            let k = any(rng);
            t[k] = long(rng, &t[k].clone());
        }
        // Unicode or a control character between two tokens.
        13 => {
            let at = rng.below(t.len() + 1);
            t.insert(at, rng.pick(UNICODE).to_string());
        }
        // Cut the text short.
        14 => {
            let k = rng.below(t.len());
            t.truncate(k);
        }
        // The whole text again, or padded out past the size limit.
        _ => {
            let whole: String = t.concat();
            return match rng.below(3) {
                0 => whole.repeat(rng.between(2, 40)),
                1 => format!("{whole}{}", " ".repeat(rng.between(60_000, 70_000))),
                _ => format!("{whole}// {}\n", "x".repeat(rng.between(100, 70_000))),
            };
        }
    }
    t.concat()
}

/// A few mutations in a row.
pub(crate) fn mutate_few(rng: &mut Rng, text: &str) -> String {
    let mut text = text.to_string();
    for _ in 0..rng.few(6) {
        text = capped(mutate(rng, &text));
    }
    text
}

/// A text cut to a few hundred kilobytes: past every limit, and quick to
/// mutate again.
pub(crate) fn capped(mut text: String) -> String {
    const MOST: usize = 200_000;
    if text.len() > MOST {
        let mut cut = MOST;
        while !text.is_char_boundary(cut) {
            cut -= 1;
        }
        text.truncate(cut);
    }
    text
}

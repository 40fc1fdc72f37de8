//! The words of a chart: subscripts (`_` starts one), numbers as a reader
//! writes them (a true minus sign, powers of ten as superscripts), and how
//! wide a text is drawn.

use crate::draw::svg::Run;

/// `text` (of a font `size` wide) in runs with its subscripts drawn: `_`
/// starts one, which runs to the next space, bracket, operator or `_` —
/// "J_II(φ)", "dJ_II/dφ", "ω_1". Digits and the letters that Unicode has
/// subscripts of become those (ω₁), as in the scenes' G₂; any other, a
/// smaller run lowered by a third of the font (which every SVG viewer
/// draws). A `_` with nothing after it, or written `\\_`, is the text's
/// own (`max\\_solutions`).
pub(crate) fn runs(text: &str, size: f64) -> Vec<Run> {
    let mut runs = subscripted(&text.replace("\\_", LITERAL), size);
    for run in &mut runs {
        run.text = run.text.replace(LITERAL, "_");
    }
    runs
}

/// What stands for an escaped `_` while the subscripts are found (a
/// private-use character).
const LITERAL: &str = "\u{E000}";

fn subscripted(text: &str, size: f64) -> Vec<Run> {
    let mut parts = text.split('_');
    let mut runs = vec![plain(parts.next().unwrap_or(""))];
    let drop = 0.3 * size;
    let mut lowered = false;
    for part in parts {
        let end = part
            .find(|c: char| c.is_whitespace() || "()[]{}/,;:=+−-·*^'&<>\"|…".contains(c))
            .unwrap_or(part.len());
        let (low, after) = part.split_at(end);
        let unicode: Option<String> = low.chars().map(unicode_subscript).collect();
        if low.is_empty() {
            push(&mut runs, &format!("_{part}"), lowered);
            continue;
        }
        match (lowered, unicode) {
            (false, Some(unicode)) => push(&mut runs, &unicode, false),
            _ => {
                let dy = if lowered { 0.0 } else { drop };
                runs.push(Run {
                    text: low.into(),
                    dy,
                    size: Some(0.75 * size),
                });
                lowered = true;
            }
        }
        if lowered && !after.is_empty() {
            // Spaces opening a tspan are dropped by some viewers (librsvg):
            // they go between the runs, at the text's own level.
            let rest = after.trim_start();
            let spaces = &after[..after.len() - rest.len()];
            if !spaces.is_empty() {
                runs.push(plain(spaces));
            }
            runs.push(Run {
                text: rest.into(),
                dy: -drop,
                size: None,
            });
            lowered = false;
        } else {
            push(&mut runs, after, lowered);
        }
    }
    runs.retain(|r| !r.text.is_empty() || r.dy != 0.0);
    runs
}

fn plain(text: &str) -> Run {
    Run {
        text: text.into(),
        dy: 0.0,
        size: None,
    }
}

/// `text` appended to the last run when it is at the same level.
fn push(runs: &mut Vec<Run>, text: &str, lowered: bool) {
    match runs.last_mut() {
        Some(last) if !lowered && last.size.is_none() => last.text.push_str(text),
        Some(last) if lowered => last.text.push_str(text),
        _ => runs.push(plain(text)),
    }
}

/// The Unicode subscript of `c`, if there is one (and fonts have it).
fn unicode_subscript(c: char) -> Option<char> {
    const FROM: &str = "0123456789aehijklmnoprstuvx";
    const TO: &str = "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ";
    FROM.chars()
        .position(|f| f == c)
        .and_then(|i| TO.chars().nth(i))
}

#[cfg(test)]
/// The characters as they are read (the subscript marks dropped).
pub(crate) fn shown(text: &str) -> String {
    runs(text, 10.0).into_iter().map(|r| r.text).collect()
}

/// How wide `text` is drawn in a sans-serif font `size` high: a rough
/// measure (an SVG writer cannot measure text), on the wide side.
pub(crate) fn width(text: &str, size: f64) -> f64 {
    runs(text, size)
        .iter()
        .map(|run| {
            let scale = run.size.map_or(1.0, |s| s / size);
            let em: f64 = run.text.chars().map(char_width).sum();
            em * size * scale
        })
        .sum()
}

/// A character's width in ems (DejaVu Sans, rounded up).
fn char_width(c: char) -> f64 {
    match c {
        'i' | 'j' | 'l' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' => 0.3,
        ' ' | 'f' | 't' | 'r' | '(' | ')' | '[' | ']' | '/' | '-' => 0.38,
        'm' | 'w' | 'M' | 'W' | '%' | '—' | 'Σ' => 0.9,
        '0'..='9' | '−' | '+' | '=' | '×' => 0.64,
        '⁰'..='⁹' | '¹' | '²' | '³' | '⁻' => 0.42,
        c if c.is_uppercase() => 0.7,
        _ => 0.6,
    }
}

/// `text` broken at spaces into lines at most `width` wide (a word wider
/// than that on a line of its own).
pub(crate) fn wrap(text: &str, size: f64, width: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if self::width(&format!("{line} {word}"), size) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// `x` written for a reader: a true minus sign, no `-0`.
pub(crate) fn minus(text: String) -> String {
    if text.starts_with('-') && text[1..].chars().all(|c| c == '0' || c == '.') {
        return text[1..].to_string();
    }
    text.replace('-', "−")
}

/// `n` in superscript digits (`⁻¹²`).
pub(crate) fn superscript(n: i32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits = n.unsigned_abs().to_string();
    let mut out = if n < 0 {
        "⁻".to_string()
    } else {
        String::new()
    };
    out.extend(digits.bytes().map(|b| DIGITS[usize::from(b - b'0')]));
    out
}

/// A tick label of a linear axis whose ticks are `step` apart: as many
/// decimals as the step needs, or a power of ten for very large or very
/// small numbers (`2.5×10⁻⁴`).
pub(crate) fn tick(x: f64, step: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let big = x.abs().max(step);
    if big >= 1e6 || step < 1e-4 {
        let exponent = x.abs().log10().floor() as i32;
        let mantissa = x / 10f64.powi(exponent);
        let digits = ((exponent as f64) - step.log10().floor()).clamp(0.0, 6.0) as usize;
        let m = format!("{mantissa:.digits$}");
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            m
        };
        return minus(format!("{m}×10{}", superscript(exponent)));
    }
    let decimals = (-(step.log10() + 1e-9).floor()).clamp(0.0, 10.0) as usize;
    minus(format!("{x:.decimals$}"))
}

/// The label of a power of ten on a log axis: `10⁻¹²`; or, on an axis
/// whose labels all lie from 0.01 to 100 (`plain`), the number as it is.
pub(crate) fn decade(exponent: i32, plain: bool) -> String {
    match (plain, exponent) {
        (true, -2..=0) => minus(format!("{}", 10f64.powi(exponent))),
        (true, 1 | 2) => format!("{}", 10i32.pow(exponent as u32)),
        _ => format!("10{}", superscript(exponent)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(runs: &[Run]) -> Vec<(&str, f64, Option<f64>)> {
        runs.iter()
            .map(|r| (r.text.as_str(), r.dy, r.size))
            .collect()
    }

    #[test]
    fn subscripts() {
        assert_eq!(
            text(&runs("ω_1 [rad/s]", 10.0)),
            [("ω₁ [rad/s]", 0.0, None)]
        );
        assert_eq!(
            text(&runs("J_II(φ)", 10.0)),
            [
                ("J", 0.0, None),
                ("II", 3.0, Some(7.5)),
                ("(φ)", -3.0, None)
            ]
        );
        assert_eq!(shown("a_b_c"), "abc");
        assert_eq!(text(&runs("x_ y", 10.0)), [("x_ y", 0.0, None)]);
        assert_eq!(shown("θ_4"), "θ₄");
        assert_eq!(shown("max\\_solutions 1"), "max_solutions 1");
        assert_eq!(
            text(&runs("F_y [N]", 10.0)),
            [
                ("F", 0.0, None),
                ("y", 3.0, Some(7.5)),
                (" ", 0.0, None),
                ("[N]", -3.0, None)
            ]
        );
        assert_eq!(wrap("a bb cc", 10.0, 30.0), ["a bb", "cc"]);
        assert_eq!(shown("l_1…l_4, |∂y/∂p_i| t_i"), "l₁…l₄, |∂y/∂pᵢ| tᵢ");
    }

    #[test]
    fn numbers() {
        assert_eq!(tick(-0.5, 0.5), "−0.5");
        assert_eq!(tick(150.0, 50.0), "150");
        assert_eq!(tick(0.25, 0.05), "0.25");
        assert_eq!(tick(3.0, 1.0), "3");
        assert_eq!(tick(0.3, 0.1), "0.3");
        assert_eq!(tick(2e6, 1e6), "2×10⁶");
        assert_eq!(tick(-2.5e-5, 5e-6), "−2.5×10⁻⁵");
        assert_eq!(decade(-12, false), "10⁻¹²");
        assert_eq!(decade(-1, true), "0.1");
        assert_eq!(decade(-1, false), "10⁻¹");
        assert_eq!(decade(2, true), "100");
        assert_eq!(minus("-0.0".into()), "0.0");
    }
}

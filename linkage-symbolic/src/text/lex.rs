//! The equations' text read into tokens, within bounds: proc-macro2's
//! lexer (the one the attribute's tokens come from outside a compiler),
//! a text it refuses described and located, and a text too large or too
//! deeply nested for the later stages (whose recursion follows the
//! expressions' depth) refused before they see it.

use super::Equations;
use crate::diagnostics::Diagnostic;
use proc_macro2::{Delimiter, Span, TokenStream, TokenTree};
use std::ops::Range;
use std::str::FromStr;

/// The longest text read, in bytes: a hundred times the largest mechanism
/// of the project's models (about 700 bytes).
pub const MAX_BYTES: usize = 64 * 1024;

/// The most tokens read: sixteen times the largest model's (about 250).
/// The derivatives' work grows with the square of the number of
/// coordinates, and as many tokens make at most about 130 coordinates,
/// under a second.
pub const MAX_TOKENS: usize = 4096;

/// The most tokens one entry of a list (an equation, a point) has, nested
/// ones counted: real equations have about forty. An expression is at
/// most as deep as its tokens are many, and the parser and the lowering
/// recurse that deep: 256 levels fit a 1 MiB stack, as WebAssembly has,
/// unoptimised.
pub const MAX_ENTRY_TOKENS: usize = 256;

/// The deepest nesting of brackets read: real equations nest four or five
/// deep.
pub const MAX_DEPTH: usize = 32;

impl Equations<'_> {
    /// The character at byte `at` of the text, in file coordinates (empty
    /// at the end).
    fn char_at(&self, at: usize) -> Range<usize> {
        let width = (self.text.get(at..))
            .and_then(|rest| rest.chars().next())
            .map_or(0, char::len_utf8);
        self.in_file(at..at + width)
    }
}

/// The tokens of `equations`, or why they cannot be read.
pub(super) fn lex(equations: Equations<'_>) -> Result<TokenStream, Diagnostic> {
    if equations.text.len() > MAX_BYTES {
        // From the character the limit falls in: a place on a character's
        // boundary, which a renderer can cut the text at.
        let start = (0..=MAX_BYTES)
            .rev()
            .find(|&k| equations.text.is_char_boundary(k))
            .unwrap_or(0);
        return Err(Diagnostic::error(
            format!(
                "the equations are {} bytes long; the most this reads is {MAX_BYTES}",
                equations.text.len()
            ),
            Some(equations.in_file(start..equations.text.len())),
        ));
    }
    let tokens = TokenStream::from_str(equations.text)
        .map_err(|e| refused(equations, e.span().byte_range().start))?;
    check_size(equations, &tokens)?;
    Ok(tokens)
}

/// Why the lexer stopped at byte `at`: a bracket never closed (the lexer
/// points at it), a closing bracket that closes nothing or the wrong
/// bracket, or a character that starts no token.
fn refused(equations: Equations<'_>, at: usize) -> Diagnostic {
    let here = equations.char_at(at);
    let Some(c) = equations
        .text
        .get(at..)
        .and_then(|rest| rest.chars().next())
    else {
        return Diagnostic::error("the equations end in the middle of a token", Some(here));
    };
    match c {
        '(' | '[' | '{' => Diagnostic::error(
            format!(
                "unclosed `{c}`: the equations end before the `{}` that closes it",
                closing(c)
            ),
            Some(here),
        ),
        ')' | ']' | '}' => match unclosed_before(equations, at) {
            Some((open, opened_at)) => Diagnostic::error(
                format!(
                    "mismatched `{c}`: the `{open}` still open is closed by `{}` first",
                    closing(open)
                ),
                Some(here),
            )
            .with_label(opened_at, format!("`{open}` opened here")),
            None => Diagnostic::error(
                format!("unexpected `{c}`: it closes no bracket"),
                Some(here),
            ),
        },
        '"' => Diagnostic::error("a string that is never closed", Some(here)),
        _ => Diagnostic::error(
            format!(
                "unexpected `{}`: an equation is written with numbers, names, operators, \
                 commas and brackets",
                c.escape_debug()
            ),
            Some(here),
        ),
    }
}

/// The innermost bracket open at byte `at`, and where: what the lexer
/// says of the text up to there (it read that far, so only an open bracket
/// can stop it).
fn unclosed_before(equations: Equations<'_>, at: usize) -> Option<(char, Range<usize>)> {
    let before = equations.text.get(..at)?;
    let opened = TokenStream::from_str(before)
        .err()?
        .span()
        .byte_range()
        .start;
    let open = before.get(opened..)?.chars().next()?;
    matches!(open, '(' | '[' | '{').then(|| (open, equations.char_at(opened)))
}

fn closing(open: char) -> char {
    match open {
        '(' => ')',
        '[' => ']',
        _ => '}',
    }
}

/// At most [`MAX_TOKENS`] tokens nested at most [`MAX_DEPTH`] deep, and
/// at most [`MAX_ENTRY_TOKENS`] between two commas inside brackets (walked
/// without recursion: the nesting is not known to be shallow yet).
fn check_size(equations: Equations<'_>, tokens: &TokenStream) -> Result<(), Diagnostic> {
    let mut count = 0;
    let mut pending: Vec<(TokenStream, usize)> = vec![(tokens.clone(), 0)];
    while let Some((stream, depth)) = pending.pop() {
        let mut entry: Option<(Span, usize)> = None;
        for tree in stream {
            count += 1;
            let span = tree.span();
            if count > MAX_TOKENS {
                return Err(Diagnostic::error(
                    format!(
                        "the equations have more than {MAX_TOKENS} tokens, the most this reads; \
                         this is the first one past it"
                    ),
                    Some(located(equations, span)),
                ));
            }
            if matches!(&tree, TokenTree::Punct(p) if p.as_char() == ',') {
                entry = None;
                continue;
            }
            // At the top, an entry is `key = [...]`, whose list's entries
            // are counted one by one below.
            let (start, size) = entry.get_or_insert((span, 0));
            *size += tokens_in(&tree);
            if depth > 0 && *size > MAX_ENTRY_TOKENS {
                let whole = start.join(span).unwrap_or(*start);
                return Err(Diagnostic::error(
                    format!(
                        "this entry has more than {MAX_ENTRY_TOKENS} tokens, the most one \
                         equation or point may have"
                    ),
                    Some(located(equations, whole)),
                ));
            }
            if let TokenTree::Group(group) = tree {
                if depth + 1 > MAX_DEPTH && group.delimiter() != Delimiter::None {
                    return Err(Diagnostic::error(
                        format!("brackets nested more than {MAX_DEPTH} deep, the most this reads"),
                        Some(located(equations, group.span_open())),
                    ));
                }
                pending.push((group.stream(), depth + 1));
            }
        }
    }
    Ok(())
}

/// The tokens of `tree`, itself and those it holds.
fn tokens_in(tree: &TokenTree) -> usize {
    let mut count = 1;
    let mut pending: Vec<TokenStream> = match tree {
        TokenTree::Group(group) => vec![group.stream()],
        _ => Vec::new(),
    };
    while let Some(stream) = pending.pop() {
        for tree in stream {
            count += 1;
            if let TokenTree::Group(group) = tree {
                pending.push(group.stream());
            }
        }
    }
    count
}

/// A span of the text's tokens, in file coordinates.
fn located(equations: Equations<'_>, span: Span) -> Range<usize> {
    equations.in_file(span.byte_range())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refusal(text: &str) -> Diagnostic {
        let equations = Equations::at(text, 100);
        lex(equations).expect_err(text)
    }

    #[test]
    fn an_unclosed_bracket_is_the_one_left_open() {
        let d = refusal("u = [a, b], v = [t, closure = [a - t]");
        assert_eq!(
            d.message(),
            "unclosed `[`: the equations end before the `]` that closes it"
        );
        assert_eq!(d.range(), Some(116..117));
    }

    #[test]
    fn a_mismatched_bracket_names_the_open_one() {
        let d = refusal("closure = [(a - t], u = [a]");
        assert_eq!(
            d.message(),
            "mismatched `]`: the `(` still open is closed by `)` first"
        );
        assert_eq!(d.range(), Some(117..118));
        assert_eq!(d.labels()[0].range(), 111..112);
        let d = refusal("u = [a]]");
        assert_eq!(d.message(), "unexpected `]`: it closes no bracket");
        assert_eq!(d.range(), Some(107..108));
    }

    #[test]
    fn a_stray_character_is_located() {
        let d = refusal("closure = [a → t]");
        assert!(d.message().starts_with("unexpected `→`"), "{}", d.message());
        assert_eq!(d.range(), Some(113..116));
        let d = refusal("u = [\"a]");
        assert_eq!(d.message(), "a string that is never closed");
    }

    #[test]
    fn too_large_or_too_deep_is_refused() {
        let long = "a + ".repeat(MAX_BYTES / 4 + 1);
        assert!(refusal(&long).message().contains("bytes long"));
        // The limit inside a character: the place starts at the
        // character, on a boundary of the text.
        let wide = format!("{}θθ", "a".repeat(MAX_BYTES - 1));
        let d = refusal(&wide);
        let at = d.range().unwrap().start - 100;
        assert_eq!(at, MAX_BYTES - 1);
        assert!(wide.is_char_boundary(at));
        let many = "a + a, ".repeat(MAX_TOKENS / 4 + 1);
        assert!(
            refusal(&many)
                .message()
                .starts_with("the equations have more than")
        );
        let entry = format!("closure = [{}a]", "- ".repeat(MAX_ENTRY_TOKENS));
        let d = refusal(&entry);
        assert!(d.message().starts_with("this entry has more than"));
        assert_eq!(d.range(), Some(111..111 + 2 * MAX_ENTRY_TOKENS + 1));
        let fine = format!(
            "closure = [{}a], v = [{}b]",
            "- ".repeat(255),
            "- ".repeat(255)
        );
        assert!(lex(Equations::new(&fine)).is_ok());
        let deep = format!(
            "{}a{}",
            "(".repeat(MAX_DEPTH + 1),
            ")".repeat(MAX_DEPTH + 1)
        );
        let d = refusal(&deep);
        assert!(d.message().starts_with("brackets nested"));
        assert_eq!(d.range(), Some(100 + MAX_DEPTH..101 + MAX_DEPTH));
        let fine = format!("{}a{}", "(".repeat(MAX_DEPTH), ")".repeat(MAX_DEPTH));
        assert!(lex(Equations::new(&fine)).is_ok());
    }
}

//! Mechanisms given as text at run time: the inside of
//! `#[linkage::linkage(...)]` — `u = [...], v = [...], points = [...],
//! closure = [...], params = [...]` — read from a string, with the names
//! of the mechanism's parameters, by the attribute's own parser, checks and
//! derivatives, and every mistake reported at once, each located in the
//! file the text came from.
//!
//! ```
//! use linkage_symbolic::text::{self, Equations, Parameter};
//!
//! let equations = "
//!     u = [theta3, theta4],
//!     v = [theta2],
//!     closure = [
//!         l2 * theta2.cos() + l3 * theta3.cos() - l4 * theta4.cos() - l1,
//!         l2 * theta2.sin() + l3 * theta3.sin() - l4 * theta4.sin(),
//!     ]";
//! let parameters = ["l1", "l2", "l3", "l4"].map(Parameter::new);
//! let built = text::build("FourBar", Equations::new(equations), &parameters)?;
//! assert_eq!((built.derivatives.m(), built.derivatives.f()), (2, 1));
//! assert_eq!(built.derivatives.k(), 4);
//! # Ok::<(), linkage_symbolic::diagnostics::Diagnostics>(())
//! ```
//!
//! A text with mistakes gives [`Diagnostics`], each at a byte range of
//! the file; [`Equations::offset`] says where the text sits in it (a TOML
//! file holding it in a string, say), and a parameter's
//! [`Parameter::declared_at`] where that parameter is declared. Rendered,
//! they read like the compiler's messages for the same attribute, with
//! "a parameter of `FourBar`" where the compiler says "a field":
//!
//! ```
//! use linkage_symbolic::text::{self, Equations, Parameter};
//!
//! let file = "name = \"Crank\"\nequations = \"u = [x], v = [t], closure = [x - l * t.sinn()]\"\n";
//! let start = file.find("u = ").unwrap();
//! let end = file.rfind('"').unwrap();
//! let equations = Equations::at(&file[start..end], start);
//! let Err(mistakes) = text::build("Crank", equations, &[Parameter::new("l")]) else {
//!     panic!("`sinn` is not a function");
//! };
//! assert_eq!(
//!     mistakes.render("crank.toml", file, false),
//!     "\
//! error: unsupported function `sinn`; supported functions: sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, tanh, sqrt, exp, ln, abs, hypot, powi (integer literal exponent), powf
//!   --> crank.toml:2:53
//!   |
//! 2 | equations = \"u = [x], v = [t], closure = [x - l * t.sinn()]\"
//!   |                                                     ^^^^
//!
//! "
//! );
//! ```
//!
//! How: the text is lexed by proc-macro2 with its `span-locations`
//! feature, which gives every token its byte range; a struct
//! `struct <name> { <parameter>: f64, ... }` is written and lexed beside
//! it; the pair goes through [`Input::parse_owned_by`] and
//! [`crate::build`] as an attribute and its struct would; and every
//! `syn::Error` recorded becomes a [`Diagnostic`] (`locate.rs`). What the
//! attribute's parser cannot see is checked here first: the names given
//! for the mechanism and its parameters (`declaration.rs`) and a text the
//! lexer refuses, or too large or too deeply nested to read (`lex.rs`:
//! [`MAX_BYTES`], [`MAX_TOKENS`], [`MAX_ENTRY_TOKENS`], [`MAX_DEPTH`]),
//! and equations nested too deep to differentiate in reasonable time
//! (`depth.rs`: [`MAX_NESTING`]).
//!
//! proc-macro2 keeps the text of every string it lexes, for the life of
//! the thread; [`build`] drops them when it is done
//! (`proc_macro2::extra::invalidate_current_thread_spans`), so a program
//! that builds a million mechanisms does not keep a million texts. The
//! spans inside a [`Built`] are then no longer places: its names and
//! expressions are for reading, not for locating (every place there is to
//! report is in the diagnostics). The same call ends the places of any
//! other span lexed on the thread; and [`build`] is for programs, not for
//! procedural macros, where proc-macro2's spans are the compiler's.

mod declaration;
mod depth;
mod lex;
mod locate;

pub use depth::MAX_NESTING;
pub use lex::{MAX_BYTES, MAX_DEPTH, MAX_ENTRY_TOKENS, MAX_TOKENS};

use crate::ast::Input;
use crate::derivatives::Derivatives;
use crate::diagnostics::{Diagnostic, Diagnostics};
use crate::errors::Errors;
use crate::owner::Owner;
use declaration::Declaration;
use locate::Places;
use proc_macro2::TokenStream;
use std::ops::Range;
use std::str::FromStr;

/// A parameter of a run-time mechanism: its name, as the equations write
/// it, and where it is declared, if known (a byte range of the file the
/// equations are in).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Parameter<'a> {
    pub name: &'a str,
    pub declared_at: Option<Range<usize>>,
}

impl<'a> Parameter<'a> {
    /// A parameter declared nowhere in particular.
    pub fn new(name: &'a str) -> Parameter<'a> {
        Parameter {
            name,
            declared_at: None,
        }
    }

    /// A parameter declared at the bytes `range` of the file.
    pub fn declared_at(name: &'a str, range: Range<usize>) -> Parameter<'a> {
        Parameter {
            name,
            declared_at: Some(range),
        }
    }
}

/// The equations' text and where it starts in its file (a byte offset), so
/// that the equations held in a string of a larger file are reported at
/// the file's lines and columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Equations<'a> {
    pub text: &'a str,
    pub offset: usize,
}

impl<'a> Equations<'a> {
    /// A text that is the whole file.
    pub fn new(text: &'a str) -> Equations<'a> {
        Equations { text, offset: 0 }
    }

    /// A text that starts at byte `offset` of its file.
    pub fn at(text: &'a str, offset: usize) -> Equations<'a> {
        Equations { text, offset }
    }

    /// The bytes `range` of the text, in file coordinates.
    fn in_file(&self, range: Range<usize>) -> Range<usize> {
        self.offset.saturating_add(range.start)..self.offset.saturating_add(range.end)
    }

    /// The whole text, in file coordinates.
    fn whole(&self) -> Range<usize> {
        self.in_file(0..self.text.len())
    }
}

/// A mechanism read, checked and differentiated: what the later stages
/// (an evaluator, a code generator) take.
pub struct Built {
    /// The equations parsed, as the attribute's are, with the struct
    /// written for the mechanism (its name and parameters as fields).
    pub input: Input,
    /// Every derivative.
    pub derivatives: Derivatives,
}

/// The mechanism `name` whose equations are `equations` and whose
/// parameters are `parameters`, read, checked and differentiated; or
/// every mistake found, each at its place in the file.
///
/// The parameters the equations may use are exactly `parameters`; which
/// of them are differentiated by is the attribute's rule (`params = [...]`,
/// or else every parameter the equations use).
pub fn build(
    name: &str,
    equations: Equations<'_>,
    parameters: &[Parameter<'_>],
) -> Result<Built, Diagnostics> {
    let built = build_with_spans(name, equations, parameters);
    proc_macro2::extra::invalidate_current_thread_spans();
    built
}

fn build_with_spans(
    name: &str,
    equations: Equations<'_>,
    parameters: &[Parameter<'_>],
) -> Result<Built, Diagnostics> {
    let mut diagnostics = Diagnostics::new();
    let declaration = Declaration::new(name, parameters, &mut diagnostics);
    let attr = match lex::lex(equations) {
        Ok(tokens) => tokens,
        Err(refused) => {
            diagnostics.push(refused);
            return Err(diagnostics);
        }
    };
    // Names checked and written as Rust identifiers: this lexes.
    let item = match TokenStream::from_str(&declaration.text) {
        Ok(item) => item,
        Err(_) => {
            diagnostics.push(Diagnostic::error(
                "the mechanism's name and parameters could not be read as a struct (an \
                 internal error: please report it with the names)",
                None,
            ));
            return Err(diagnostics);
        }
    };
    let struct_span = (item.clone().into_iter().next())
        .map(|token| token.span())
        .unwrap_or_else(proc_macro2::Span::call_site);
    let places = Places {
        equations,
        declaration: &declaration,
        struct_span,
    };
    let mut errors = Errors::default();
    let owner = |_: &syn::Ident| Owner::Mechanism(name.to_owned());
    let input = Input::parse_owned_by(attr, item, owner, &mut errors);
    let derivatives = (input.as_ref()).and_then(|input| match depth::too_deep(input) {
        Some(too_deep) => {
            errors.push(too_deep);
            None
        }
        None => crate::build(input, &mut errors).ok(),
    });
    diagnostics.extend(errors.into_iter().map(|error| places.diagnostic(error)));
    match (input, derivatives) {
        (Some(input), Some(derivatives)) if diagnostics.is_empty() => {
            Ok(Built { input, derivatives })
        }
        _ if !diagnostics.is_empty() => Err(diagnostics),
        // Every path that gives up records why; should one not, the
        // caller still gets an error rather than nothing.
        _ => Err(Diagnostic::error(
            "the equations could not be read (an internal error: please report it with \
             the equations)",
            Some(equations.whole()),
        )
        .into()),
    }
}

#[cfg(test)]
mod tests;

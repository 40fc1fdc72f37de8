//! The symbolic engine of `linkage`: the closure equations of a planar
//! mechanism, written as Rust expressions, turned into straight-line Rust
//! for Ψ, its Jacobians and every second-order term.
//!
//! The pipeline, one module per stage:
//!
//! 1. [`ast`]: the attribute and the struct, parsed with their spans;
//! 2. [`lower`]: names resolved, expressions lowered into the hash-consed
//!    DAG of [`dag`]; [`valid`]: counts and structural rank checked;
//!    [`params`]: the parameters to differentiate by;
//! 3. [`derivatives`]: every derivative built with the rules of [`diff`],
//!    the two acceleration methods compared in the normal form of
//!    [`normal`];
//! 4. [`emit`]: common subexpressions shared, temporaries named, Rust
//!    statements emitted;
//! 5. [`display`]: formulas as a textbook prints them, for documentation.
//!
//! [`build`] runs stages 1–3. [`generate`] assembles the emitted
//! statements into documented items, each f64 function from its [`plan`]:
//! the code of the `#[linkage::linkage(...)]` attribute (crate
//! `linkage-macros`, a thin shell around it), and of `linkage expand
//! --expanded`. A [`tape`] is the same statements compiled into a
//! register program that gives the compiled function's numbers without a
//! compiler (its interpreter needs no feature, its compiler `syntax`).
//!
//! Features: `syntax` (default) reads and emits Rust with syn and quote;
//! without it only the DAG, its derivative rules, its normal form, its
//! display and [`names`] remain. `eval` adds `interp`, an evaluator of the DAG on the dual
//! numbers of num-dual. `text` adds [`text`], the pipeline run on a
//! mechanism given as text at run time, and the [`diagnostics`] that
//! locate its mistakes.

#![forbid(unsafe_code)]
// Without `syntax` the pipeline's first stages are not compiled, and the
// links above to them have nothing to point at.
#![cfg_attr(not(feature = "syntax"), allow(rustdoc::broken_intra_doc_links))]

#[cfg(feature = "syntax")]
pub mod ast;
pub mod blocks;
pub mod dag;
#[cfg(feature = "syntax")]
pub mod derivatives;
#[cfg(feature = "text")]
pub mod diagnostics;
pub mod diff;
pub mod display;
#[cfg(feature = "syntax")]
pub mod emit;
#[cfg(feature = "syntax")]
pub mod errors;
#[cfg(feature = "syntax")]
pub mod generate;
mod hasher;
#[cfg(any(test, feature = "eval"))]
pub mod interp;
#[cfg(feature = "syntax")]
pub mod lower;
pub mod names;
pub mod normal;
#[cfg(feature = "syntax")]
pub mod owner;
#[cfg(feature = "syntax")]
pub mod params;
#[cfg(feature = "syntax")]
pub mod plan;
#[cfg(feature = "syntax")]
mod suggest;
pub mod tape;
#[cfg(feature = "text")]
pub mod text;
#[cfg(feature = "syntax")]
pub mod valid;

#[cfg(feature = "syntax")]
pub use pipeline::{Unbuilt, build};

#[cfg(feature = "syntax")]
mod pipeline {
    use crate::ast::Input;
    use crate::derivatives::Derivatives;
    use crate::errors::Errors;

    /// An attribute with mistakes, as far as [`build`] read it: what the
    /// items the struct still gets take their sizes from.
    #[derive(Debug, Default)]
    pub struct Unbuilt {
        /// The number of parameters p [`crate::params::resolve`] found,
        /// when the equations and the points were lowered.
        pub params: Option<usize>,
    }

    /// Stages 2 and 3 on a parsed attribute: names resolved, counts and
    /// structural rank checked, every derivative built. When the attribute
    /// has mistakes, every one of them is recorded in `errors` and the
    /// error is what was read of it.
    pub fn build(input: &Input, errors: &mut Errors) -> Result<Derivatives, Unbuilt> {
        if !input.complete {
            return Err(Unbuilt::default());
        }
        let shape_ok = crate::valid::check_shape(input, errors);
        let Some(mut lowered) = crate::lower::lower(input, errors) else {
            return Err(Unbuilt::default());
        };
        // The structure needs as many equations as coordinates of u; the
        // parameters do not.
        if shape_ok {
            crate::valid::check_structure(input, &mut lowered, errors);
        }
        crate::params::resolve(input, &mut lowered, errors);
        if !errors.is_empty() {
            return Err(Unbuilt {
                params: Some(lowered.params.len()),
            });
        }
        Ok(Derivatives::build(lowered))
    }
}

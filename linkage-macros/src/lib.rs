//! The `#[linkage::linkage(...)]` attribute: loop-closure equations of a
//! planar mechanism, differentiated symbolically at compile time into
//! straight-line Rust.
//!
//! The pipeline, one module per stage:
//!
//! 1. `ast`: the attribute and the struct, parsed with their spans;
//! 2. `lower`: names resolved, expressions lowered into the hash-consed
//!    DAG of `dag`; `valid`: counts and structural rank checked;
//! 3. `model`: every derivative built with the rules of `diff`;
//! 4. `emit`: common subexpressions shared, temporaries named;
//! 5. `expand`: the items assembled, documented with formulas from
//!    `display`.
//!
//! Use it through the `linkage` crate, which documents the attribute.

#![forbid(unsafe_code)]

mod ast;
mod dag;
mod diff;
mod display;
mod emit;
mod errors;
mod expand;
#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod interp;
mod lower;
mod model;
mod normal;
#[cfg(test)]
mod proptests;
#[cfg(test)]
mod run_emitted;
mod suggest;
mod valid;

use proc_macro::TokenStream;

/// Generates Ψ, its Jacobians, the second-order terms of both acceleration
/// methods, the points' kinematics and an implementation of
/// `linkage::Linkage` from closure equations. See the `linkage` crate.
#[proc_macro_attribute]
pub fn linkage(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::expand(attr.into(), item.into()).into()
}

//! The `#[linkage::linkage(...)]` attribute: loop-closure equations of a
//! planar mechanism, differentiated symbolically at compile time into
//! straight-line Rust.
//!
//! A thin shell around the symbolic engine, `linkage-symbolic` (parse,
//! DAG, derivatives, normal form, shared subexpressions, emitted
//! statements, and their assembly into documented items in its
//! `generate`).
//!
//! Use it through the `linkage` crate, which documents the attribute.

#![forbid(unsafe_code)]

#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod proptests;
#[cfg(test)]
mod run_emitted;

use proc_macro::TokenStream;

// Documented where users meet it, on the `linkage` crate's re-export
// (docs/attribute.md).
#[proc_macro_attribute]
pub fn linkage(attr: TokenStream, item: TokenStream) -> TokenStream {
    linkage_symbolic::generate::expand(attr.into(), item.into()).into()
}

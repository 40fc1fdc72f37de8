//! One f64 function of the table from its kernel's plan: the emitted
//! statements, the result matrices filled, the signature with the
//! arguments it reads.

use super::Generator;
use super::docs::doc_attributes;
use super::quantities::{Arg, Quantity};
use super::signature;
use crate::dag::{Id, Node, Symbol};
use crate::emit::{Body, Mode, Reads};
use crate::plan::{Kernel, free_name};
use crate::tape::{Form, Part};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// Whether a function's body reads an argument.
pub fn reads(r: &Reads, arg: Arg) -> bool {
    match arg {
        Arg::U => r.u,
        Arg::V => r.v,
        Arg::Udot => r.udot,
        Arg::Vdot => r.vdot,
        Arg::Uddot => r.uddot,
        Arg::Vddot => r.vddot,
        Arg::TrigU | Arg::TrigV => true,
        Arg::Params => r.p,
    }
}

impl Generator<'_> {
    /// The function of `q`, computing its kernel, documented by `doc`.
    pub(super) fn function(&self, q: &Quantity, doc: &[String], kernel: Kernel) -> TokenStream {
        let name = format_ident!("{}", q.name);
        let plan = kernel.plan(self.model);
        let parts: Vec<&Part> = plan.phases.iter().flatten().map(|p| &p.part).collect();
        // The result matrices' names, which temporaries avoid.
        let reserved: Vec<String> = parts
            .iter()
            .filter(|p| p.form == Form::Matrix)
            .map(|p| self.free_name(p.name))
            .collect();
        let phased = plan.emit(self.dag(), &self.names, &reserved, Mode::F64);
        let Body {
            statements,
            values,
            reads: read,
        } = phased.into_body();
        let mut values = values.iter();
        let mut result_names = reserved.iter();
        let mut stmts = Vec::new();
        let mut results = Vec::new();
        for part in &parts {
            match part.form {
                Form::Matrix => {
                    let name = result_names.next().map(String::as_str).unwrap_or("out");
                    let (s, value, _) = assemble(part, name, &mut values, quote!(f64));
                    stmts.extend(s);
                    results.push(value);
                }
                Form::Points => {
                    let vectors = (0..part.rows).map(|_| {
                        let x = values.next();
                        let y = values.next();
                        quote!(Vector2::new(#x, #y))
                    });
                    results.push(quote!([#(#vectors),*]));
                }
                Form::PointColumns => results.push(point_columns(part, &mut values)),
            }
        }
        let result = match results.as_slice() {
            [one] => quote!(#(#stmts)* #one),
            _ => quote!(#(#stmts)* (#(#results),*)),
        };
        let dims = self.dims();
        let args = signature::args(q, &dims, |a| reads(&read, a));
        let ret = signature::output_type(q, &dims, false);
        let doc = doc_attributes(doc);
        // No `#[inline]`: the kernels are compiled in the user's crate, where
        // LLVM chooses; the hint made a Newton step (Ψ and Ψ_u inlined into
        // the caller) slower (docs/performance.md, "Measurements behind the
        // code"). The trait's delegations carry it instead.
        quote! {
            #doc
            #[must_use]
            pub fn #name(&self, #(#args),*) -> #ret {
                #(#statements)*
                #result
            }
        }
    }

    /// `name`, unless a symbol already has it.
    pub(super) fn free_name(&self, name: &str) -> String {
        free_name(&self.names, name)
    }
}

/// The statements filling a result matrix from the emitted values (the
/// part's entries; every other entry zero), the expression naming it, and
/// its type.
pub fn assemble<'v>(
    part: &Part,
    name: &str,
    values: &mut impl Iterator<Item = &'v TokenStream>,
    scalar: TokenStream,
) -> (Vec<TokenStream>, TokenStream, TokenStream) {
    let (r, c) = (
        Literal::usize_unsuffixed(part.rows),
        Literal::usize_unsuffixed(part.cols),
    );
    let is_vector = part.cols == 1;
    let (ty, constructor) = if is_vector {
        (quote!(SVector<#scalar, #r>), quote!(SVector::<#scalar, #r>))
    } else {
        (
            quote!(SMatrix<#scalar, #r, #c>),
            quote!(SMatrix::<#scalar, #r, #c>),
        )
    };
    if part.entries.is_empty() {
        return (Vec::new(), quote!(#constructor::zeros()), ty);
    }
    let var = format_ident!("{}", name);
    let mut stmts = vec![quote!(let mut #var = #constructor::zeros();)];
    for &(i, j) in &part.entries {
        let value = values.next();
        let index = if is_vector {
            let i = Literal::usize_unsuffixed(i);
            quote!(#i)
        } else {
            let (i, j) = (Literal::usize_unsuffixed(i), Literal::usize_unsuffixed(j));
            quote!((#i, #j))
        };
        stmts.push(quote!(#var[#index] = #value;));
    }
    (stmts, quote!(#var), ty)
}

/// A part of points by columns, `[[Vector2::new(x, y), …], …]`: one array
/// of the points per column, its entries from the emitted values and
/// `0.0` where the part lists none.
pub fn point_columns<'v>(
    part: &Part,
    values: &mut impl Iterator<Item = &'v TokenStream>,
) -> TokenStream {
    let mut entries = part.entries.iter().peekable();
    let mut next = |row: usize, col: usize| {
        if entries.next_if(|&&e| e == (row, col)).is_some() {
            let value = values.next();
            quote!(#value)
        } else {
            quote!(0.0)
        }
    };
    let columns: Vec<TokenStream> = (0..part.cols)
        .map(|j| {
            let points: Vec<TokenStream> = (0..part.rows / 2)
                .map(|i| {
                    let x = next(2 * i, j);
                    let y = next(2 * i + 1, j);
                    quote!(Vector2::new(#x, #y))
                })
                .collect();
            quote!([#(#points),*])
        })
        .collect();
    quote!([#(#columns),*])
}

/// Whether any of `roots` depends on the symbol.
pub fn reaches(dag: &crate::dag::Dag, roots: &[Id], symbol: Symbol) -> bool {
    let mut seen = std::collections::HashSet::new();
    let mut stack: Vec<Id> = roots.to_vec();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        match dag.node(id) {
            Node::Sym(s) if *s == symbol => return true,
            node => stack.extend(crate::dag::children(node)),
        }
    }
    false
}

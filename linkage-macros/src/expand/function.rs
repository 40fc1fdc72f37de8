//! One f64 function of the table from its formulas: the emitted statements,
//! the result matrices filled, the signature with the arguments it reads.

use super::Generator;
use super::docs::doc_attributes;
use super::quantities::{Arg, Quantity};
use super::signature;
use linkage_symbolic::dag::{Dag, Id, Node, Symbol};
use linkage_symbolic::derivatives::Matrix;
use linkage_symbolic::emit::{Body, Mode, Reads, emit};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// What an f64 function returns, with the formulas behind it.
pub enum Output {
    /// One matrix (a vector if it has one column), named for the result.
    Matrix(&'static str, Matrix),
    /// A tuple of matrices.
    Tuple(Vec<(&'static str, Matrix)>),
    /// An array of 2-vectors, one per point, with names for the coordinates.
    Points(Vec<([Id; 2], [String; 2])>),
}

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
    /// The function of `q` returning `output`, documented by `doc`.
    pub(super) fn function(&self, q: &Quantity, doc: &[String], output: Output) -> TokenStream {
        let name = format_ident!("{}", q.name);
        let mut roots = Vec::new();
        let mut hints = Vec::new();
        let mut reserved: Vec<String> = Vec::new();
        match &output {
            Output::Matrix(result, matrix) => {
                roots.extend(matrix.entries.iter().copied().filter(|&e| e != Dag::ZERO));
                reserved.push(result.to_string());
            }
            Output::Tuple(parts) => {
                for (result, matrix) in parts {
                    roots.extend(matrix.entries.iter().copied().filter(|&e| e != Dag::ZERO));
                    reserved.push(result.to_string());
                }
            }
            Output::Points(points) => {
                for (ids, names) in points {
                    for c in 0..2 {
                        roots.push(ids[c]);
                        hints.push((ids[c], names[c].clone()));
                    }
                }
            }
        }
        let reserved: Vec<String> = reserved.into_iter().map(|r| self.free_name(&r)).collect();
        let body: Body = emit(
            self.dag(),
            &self.names,
            &roots,
            &hints,
            &reserved,
            Mode::F64,
        );
        let mut values = body.values.iter();
        let mut result_names = reserved.iter();
        let result = match &output {
            Output::Matrix(_, matrix) => {
                let name = result_names.next().map(String::as_str).unwrap_or("out");
                let (stmts, value, _) = assemble(matrix, name, &mut values, quote!(f64));
                quote!(#(#stmts)* #value)
            }
            Output::Tuple(parts) => {
                let mut stmts = Vec::new();
                let mut tuple = Vec::new();
                for (_, matrix) in parts {
                    let name = result_names.next().map(String::as_str).unwrap_or("out");
                    let (s, value, _) = assemble(matrix, name, &mut values, quote!(f64));
                    stmts.extend(s);
                    tuple.push(value);
                }
                quote!(#(#stmts)* (#(#tuple),*))
            }
            Output::Points(points) => {
                let vectors = points.iter().map(|_| {
                    let x = values.next();
                    let y = values.next();
                    quote!(Vector2::new(#x, #y))
                });
                quote!([#(#vectors),*])
            }
        };
        let dims = self.dims();
        let args = signature::args(q, &dims, |a| reads(&body.reads, a));
        let ret = signature::output_type(q, &dims, false);
        let doc = doc_attributes(doc);
        let statements = &body.statements;
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
        let taken: Vec<String> = self.names.all_code().collect();
        let mut candidate = name.to_owned();
        while taken.contains(&candidate) {
            candidate.push('_');
        }
        candidate
    }
}

/// The statements filling a result matrix from the emitted values (zero
/// entries left out), the expression naming it, and its type.
pub fn assemble<'v>(
    matrix: &Matrix,
    name: &str,
    values: &mut impl Iterator<Item = &'v TokenStream>,
    scalar: TokenStream,
) -> (Vec<TokenStream>, TokenStream, TokenStream) {
    let (r, c) = (
        Literal::usize_unsuffixed(matrix.rows),
        Literal::usize_unsuffixed(matrix.cols),
    );
    let is_vector = matrix.cols == 1;
    let (ty, constructor) = if is_vector {
        (quote!(SVector<#scalar, #r>), quote!(SVector::<#scalar, #r>))
    } else {
        (
            quote!(SMatrix<#scalar, #r, #c>),
            quote!(SMatrix::<#scalar, #r, #c>),
        )
    };
    let nonzero: Vec<usize> = (0..matrix.entries.len())
        .filter(|&k| matrix.entries[k] != Dag::ZERO)
        .collect();
    if nonzero.is_empty() {
        return (Vec::new(), quote!(#constructor::zeros()), ty);
    }
    let var = format_ident!("{}", name);
    let mut stmts = vec![quote!(let mut #var = #constructor::zeros();)];
    for k in nonzero {
        let value = values.next();
        let (i, j) = (k / matrix.cols, k % matrix.cols);
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

/// Whether any of `roots` depends on the symbol.
pub fn reaches(dag: &Dag, roots: &[Id], symbol: Symbol) -> bool {
    let mut seen = std::collections::HashSet::new();
    let mut stack: Vec<Id> = roots.to_vec();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        match dag.node(id) {
            Node::Sym(s) if *s == symbol => return true,
            node => stack.extend(linkage_symbolic::dag::children(node)),
        }
    }
    false
}

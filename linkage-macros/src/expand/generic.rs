//! The functions of the table on any dual number of num-dual: Ψ
//! (`psi_generic`) and the point positions (`point_positions_generic`), for
//! derivatives by automatic differentiation; with `_params`, the
//! parameters given as dual numbers too.

use super::Generator;
use super::docs::doc_attributes;
use super::function::{assemble, reads};
use super::quantities::{Arg, Quantity};
use super::signature;
use linkage_symbolic::dag::{Dag, Id};
use linkage_symbolic::derivatives::Matrix;
use linkage_symbolic::emit::{Body, Mode, emit};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

impl Generator<'_> {
    /// A matrix of formulas on dual numbers.
    pub(super) fn generic_formula(
        &self,
        q: &Quantity,
        doc: &[String],
        matrix: &Matrix,
    ) -> TokenStream {
        let result = self.free_name(
            q.name
                .trim_end_matches("_params")
                .trim_end_matches("_generic"),
        );
        let roots: Vec<Id> = matrix
            .entries
            .iter()
            .copied()
            .filter(|&e| e != Dag::ZERO)
            .collect();
        let body = emit(
            self.dag(),
            &self.names,
            &roots,
            &[],
            std::slice::from_ref(&result),
            mode(q),
        );
        let mut values = body.values.iter();
        let (stmts, value, _) = assemble(matrix, &result, &mut values, quote!(D));
        self.generic_function(q, doc, &body, quote!(#(#stmts)* #value))
    }

    /// The point positions on dual numbers.
    pub(super) fn generic_points(&self, q: &Quantity, doc: &[String]) -> TokenStream {
        let points = &self.model.points;
        let roots: Vec<Id> = points.iter().flat_map(|p| p.position).collect();
        let hints: Vec<(Id, String)> = points
            .iter()
            .flat_map(|p| {
                let l = p.name.to_lowercase();
                [
                    (p.position[0], format!("{l}_x")),
                    (p.position[1], format!("{l}_y")),
                ]
            })
            .collect();
        let body = emit(self.dag(), &self.names, &roots, &hints, &[], mode(q));
        let mut values = body.values.iter();
        let vectors = points.iter().map(|_| {
            let x = values.next();
            let y = values.next();
            quote!(Vector2::new(#x, #y))
        });
        let result = quote!([#(#vectors),*]);
        self.generic_function(q, doc, &body, result)
    }

    fn generic_function(
        &self,
        q: &Quantity,
        doc: &[String],
        body: &Body,
        result: TokenStream,
    ) -> TokenStream {
        let name = format_ident!("{}", q.name);
        let dims = self.dims();
        let generics = signature::generics(q);
        let args = signature::args(q, &dims, |a| reads(&body.reads, a));
        let ret = signature::output_type(q, &dims, false);
        let doc = doc_attributes(doc);
        let statements = &body.statements;
        quote! {
            #doc
            #[must_use]
            #[inline]
            pub fn #name #generics(&self, #(#args),*) -> #ret {
                #(#statements)*
                #result
            }
        }
    }
}

/// Generic code, reading the parameters from `params` if the function takes them.
fn mode(q: &Quantity) -> Mode {
    Mode::Generic {
        params_from_p: q.args.contains(&Arg::Params),
    }
}

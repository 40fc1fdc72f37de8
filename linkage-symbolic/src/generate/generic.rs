//! The functions of the table on any dual number of num-dual: Ψ
//! (`psi_generic`) and the point positions (`point_positions_generic`), for
//! derivatives by automatic differentiation; with `_params`, the
//! parameters given as dual numbers too.

use super::Generator;
use super::docs::doc_attributes;
use super::function::{assemble, reads};
use super::quantities::{Arg, Quantity};
use super::signature;
use crate::emit::{Body, Mode};
use crate::plan::{Formula, Kernel};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

impl Generator<'_> {
    /// A matrix of formulas on dual numbers.
    pub(super) fn generic_formula(
        &self,
        q: &Quantity,
        doc: &[String],
        formula: Formula,
    ) -> TokenStream {
        let result = self.free_name(
            q.name
                .trim_end_matches("_params")
                .trim_end_matches("_generic"),
        );
        let plan = Kernel::Formula(formula).plan(self.model);
        let phased = plan.emit(
            self.dag(),
            &self.names,
            std::slice::from_ref(&result),
            mode(q),
        );
        let body = phased.into_body();
        let mut values = body.values.iter();
        let mut stmts = Vec::new();
        let mut value = quote!();
        for part in plan.phases.iter().flatten() {
            let (s, v, _) = assemble(&part.part, &result, &mut values, quote!(D));
            stmts.extend(s);
            value = v;
        }
        self.generic_function(q, doc, &body, quote!(#(#stmts)* #value))
    }

    /// The point positions on dual numbers.
    pub(super) fn generic_points(&self, q: &Quantity, doc: &[String]) -> TokenStream {
        let plan = Kernel::Points(0).plan(self.model);
        let phased = plan.emit(self.dag(), &self.names, &[], mode(q));
        let body = phased.into_body();
        let mut values = body.values.iter();
        let vectors = self.model.points.iter().map(|_| {
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

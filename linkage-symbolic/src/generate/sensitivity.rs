//! `sensitivity_terms`: every derivative by u and by the parameters p that
//! the sensitivities need, in one function sharing each sine, cosine and
//! subexpression — Ψ_u, Ψ_p and their first and second time derivatives,
//! and the same of every point.

use super::Generator;
use super::constants::SENSITIVITY_TRIG;
use super::docs::doc_attributes;
use super::function::{assemble, point_columns, reads};
use super::quantities::Quantity;
use super::signature;
use crate::emit::Mode;
use crate::plan::{Kernel, Plan};
use crate::tape::{Form, Part};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

impl Generator<'_> {
    /// `sensitivity_terms`, or with `with_trig` `sensitivity_terms_with_trig`
    /// (the sines and cosines read from its arguments `trig_u` and `trig_v`)
    /// and the masks saying which it reads.
    pub(super) fn sensitivity_terms_function(
        &self,
        q: &Quantity,
        with_trig: bool,
        doc: &[String],
    ) -> TokenStream {
        let plan = Kernel::SensitivityTerms { with_trig }.plan(self.model);
        let parts: Vec<&Part> = plan.phases.iter().flatten().map(|p| &p.part).collect();
        // The matrices' names, which temporaries avoid, with the trig
        // arguments' (a coordinate may be called `trig_u`).
        let reserved: Vec<String> = parts
            .iter()
            .filter(|p| p.form == Form::Matrix)
            .map(|p| self.free_name(p.name))
            .collect();
        let trig_names = Plan::trig_names(&self.names);
        let mut names_taken = reserved.clone();
        names_taken.extend(trig_names.iter().cloned());
        let phased = plan.emit(self.dag(), &self.names, &names_taken, Mode::F64);
        let trig_coords = phased.trig_coords.clone();
        let reads_of = phased.reads;
        let body = phased.into_body();
        let (body_statements, body_values) = (body.statements, body.values);
        let mut values = body_values.iter();
        let mut statements = Vec::new();
        let mut fields = Vec::new();
        let mut names = reserved.iter();
        for part in &parts {
            let field = format_ident!("{}", part.name);
            match part.form {
                Form::Matrix => {
                    let name = names.next().map(String::as_str).unwrap_or(part.name);
                    let (stmts, value, _) = assemble(part, name, &mut values, quote!(f64));
                    statements.extend(stmts);
                    // `psi_u` rather than `psi_u: psi_u`.
                    let shorthand = field == value.to_string();
                    fields.push(if shorthand {
                        quote!(#field)
                    } else {
                        quote!(#field: #value)
                    });
                }
                Form::PointColumns | Form::Points => {
                    let columns = point_columns(part, &mut values);
                    fields.push(quote!(#field: #columns));
                }
            }
        }
        let name = format_ident!("{}", q.name);
        let dims = self.dims();
        let mut args = signature::args(q, &dims, |a| reads(&reads_of, a));
        let ret = signature::output_type(q, &dims, false);
        let doc = doc_attributes(doc);
        let masks = if with_trig {
            // The trig arguments under their free names (a coordinate may be
            // called `trig_u`), after u and v.
            let (m, f) = (self.m, self.f);
            let (ml, fl) = (Literal::usize_unsuffixed(m), Literal::usize_unsuffixed(f));
            let [trig_u, trig_v] = trig_names.map(|n| format_ident!("{}", n));
            args[2] = quote!(#trig_u: &[(f64, f64); #ml]);
            args[3] = quote!(#trig_v: &[(f64, f64); #fl]);
            let mask = |range: std::ops::Range<usize>| {
                let flags = range.map(|k| trig_coords.contains(&k));
                quote!([#(#flags),*])
            };
            let [u_const, v_const] = &SENSITIVITY_TRIG;
            let (mask_u, mask_v) = (mask(0..m), mask(m..m + f));
            let (mask_u, mask_v) = (
                u_const.declare(&dims, mask_u),
                v_const.declare(&dims, mask_v),
            );
            quote!(#mask_u #mask_v)
        } else {
            quote!()
        };
        // The kernel with the sines and cosines given is the runtime's (a
        // sweep's or an analysis's), not an entry point: out of the
        // documentation, as `linkage::SensitivityKernel` is.
        let hidden = with_trig.then(|| quote!(#[doc(hidden)]));
        // `#[inline(always)]`, unlike the kernels (see `function.rs`): the
        // terms are read once, by the solve that follows, and in line the
        // struct of them need not be written out (docs/performance.md,
        // "Measurements behind the code").
        quote! {
            #masks
            #doc
            #hidden
            #[must_use]
            #[inline(always)]
            #[allow(unused_variables, clippy::too_many_arguments)]
            pub fn #name(&self, #(#args),*) -> #ret {
                #(#body_statements)*
                #(#statements)*
                ::linkage::SensitivityTerms { #(#fields),* }
            }
        }
    }
}

//! `sensitivity_terms`: every derivative by u and by the parameters p that
//! the sensitivities need, in one function sharing each sine, cosine and
//! subexpression — Ψ_u, Ψ_p and their first and second time derivatives,
//! and the same of every point.

use super::Generator;
use super::constants::SENSITIVITY_TRIG;
use super::docs::doc_attributes;
use super::function::{assemble, reads};
use super::quantities::Quantity;
use super::signature;
use linkage_symbolic::dag::{Dag, Id};
use linkage_symbolic::derivatives::Matrix;
use linkage_symbolic::emit::{Mode, TrigSource, emit_phases};
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
        let model = self.model;
        let matrices: [(&str, &Matrix); 6] = [
            ("psi_u", &model.psi_u),
            ("psi_p", &model.psi_p),
            ("psi_u_dot", &model.psi_u_dot),
            ("psi_p_dot", &model.psi_p_dot),
            ("psi_u_ddot", &model.psi_u_ddot),
            ("psi_p_ddot", &model.psi_p_ddot),
        ];
        // The points' derivatives: [level][by u, by p], each a list of
        // columns, each column one (x, y) per point.
        let point_columns = |level: usize, by_params: bool| -> Vec<Vec<[Id; 2]>> {
            let cols = if by_params { self.k } else { self.m };
            (0..cols)
                .map(|j| {
                    model
                        .points
                        .iter()
                        .map(|p| {
                            let matrix = if by_params {
                                &p.by_p[level]
                            } else {
                                &p.by_u[level]
                            };
                            [matrix.get(0, j), matrix.get(1, j)]
                        })
                        .collect()
                })
                .collect()
        };
        let point_parts: Vec<(&str, Vec<Vec<[Id; 2]>>)> = vec![
            ("points_u", point_columns(0, false)),
            ("points_p", point_columns(0, true)),
            ("point_velocities_u", point_columns(1, false)),
            ("point_velocities_p", point_columns(1, true)),
            ("point_accelerations_u", point_columns(2, false)),
            ("point_accelerations_p", point_columns(2, true)),
        ];
        let mut roots: Vec<Id> = Vec::new();
        for (_, matrix) in &matrices {
            roots.extend(matrix.entries.iter().copied().filter(|&e| e != Dag::ZERO));
        }
        for (_, columns) in &point_parts {
            for column in columns {
                for xy in column {
                    roots.extend(xy.iter().copied().filter(|&e| e != Dag::ZERO));
                }
            }
        }
        let reserved: Vec<String> = matrices.iter().map(|(n, _)| self.free_name(n)).collect();
        let trig_names = [self.free_name("trig_u"), self.free_name("trig_v")];
        let source = TrigSource {
            u: format_ident!("{}", trig_names[0]),
            v: format_ident!("{}", trig_names[1]),
            m: self.m,
        };
        let mut names_taken = reserved.clone();
        names_taken.extend(trig_names.iter().cloned());
        let phased = emit_phases(
            self.dag(),
            &self.names,
            &[&roots],
            &[],
            &names_taken,
            Mode::F64,
            &[],
            with_trig.then_some(&source),
        );
        let (body_statements, body_values) = phased.phases.into_iter().next().unwrap_or_default();
        let mut values = body_values.iter();
        let mut statements = Vec::new();
        let mut fields = Vec::new();
        for ((field, matrix), name) in matrices.iter().zip(&reserved) {
            let (stmts, value, _) = assemble(matrix, name, &mut values, quote!(f64));
            statements.extend(stmts);
            let field = format_ident!("{}", field);
            // `psi_u` rather than `psi_u: psi_u`.
            let shorthand = field == value.to_string();
            fields.push(if shorthand {
                quote!(#field)
            } else {
                quote!(#field: #value)
            });
        }
        for (field, columns) in &point_parts {
            let columns = columns.iter().map(|column| {
                let points = column.iter().map(|xy| {
                    let [x, y] = xy.map(|e| {
                        if e == Dag::ZERO {
                            quote!(0.0)
                        } else {
                            let value = values.next();
                            quote!(#value)
                        }
                    });
                    quote!(Vector2::new(#x, #y))
                });
                quote!([#(#points),*])
            });
            let field = format_ident!("{}", field);
            fields.push(quote!(#field: [#(#columns),*]));
        }
        let name = format_ident!("{}", q.name);
        let dims = self.dims();
        let mut args = signature::args(q, &dims, |a| reads(&phased.reads, a));
        let ret = signature::output_type(q, &dims, false);
        let doc = doc_attributes(doc);
        let prologue = &phased.prologue;
        let masks = if with_trig {
            // The trig arguments under their free names (a coordinate may be
            // called `trig_u`), after u and v.
            let (m, f) = (self.m, self.f);
            let (ml, fl) = (Literal::usize_unsuffixed(m), Literal::usize_unsuffixed(f));
            let (trig_u, trig_v) = (&source.u, &source.v);
            args[2] = quote!(#trig_u: &[(f64, f64); #ml]);
            args[3] = quote!(#trig_v: &[(f64, f64); #fl]);
            let mask = |range: std::ops::Range<usize>| {
                let flags = range.map(|k| phased.trig_coords.contains(&k));
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
                #(#prologue)*
                #(#body_statements)*
                #(#statements)*
                ::linkage::SensitivityTerms { #(#fields),* }
            }
        }
    }
}

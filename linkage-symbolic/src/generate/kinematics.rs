//! `kinematics` and `kinematics_with_trig`: Ψ, Ψ_u, Ψ_v, the velocity
//! solve, γ and the acceleration solve in one pass of straight-line code.

use super::Generator;
use super::constants::{self, TRIG};
use super::docs::doc_attributes;
use super::function::{assemble, reaches};
use crate::dag::Symbol;
use crate::emit::Mode;
use crate::plan::{Kernel, Plan, PlannedPart};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// Above this many coordinates a mechanism's fused kernel with given sines
/// and cosines is emitted once, as `kinematics_with_trig_into`, written
/// over a result kept by its caller (a sweep's, an analysis's): its m × m
/// matrices cost more to move than to write in place.
/// `kinematics_with_trig` then returns it written over a fresh result. Up
/// to it the body returns its result by value, which stays in registers
/// and is faster.
pub(super) const IN_PLACE_ABOVE: usize = 4;

impl Generator<'_> {
    /// `PSI_U_BLOCKS`, the constant of Ψ_u's diagonal blocks in solve order
    /// that `kinematics` and the `Kernels` impl use, where Ψ_u has more than
    /// one block (nothing where it has one).
    pub(super) fn psi_u_blocks_constant(&self) -> TokenStream {
        let blocks = &self.model.blocks;
        if !blocks.is_triangular() {
            return quote!();
        }
        let order = blocks.order();
        let list = |v: &[usize]| {
            let v = v.iter().map(|&x| Literal::usize_unsuffixed(x));
            quote!(&[#(#v),*])
        };
        let (equations, coordinates, ends, reach) = (
            list(&order.equations),
            list(&order.coordinates),
            list(&order.ends),
            list(&order.reach),
        );
        let name = format_ident!("{}", constants::PSI_U_BLOCKS);
        let doc = format!(
            " {}. Its blocks' equations and coordinates in solve order, where each block ends, and where the coordinates its equations involve begin (`Kernels::psi_u_blocks`).",
            blocks
        );
        quote! {
            #[doc = #doc]
            pub const #name: ::linkage::PsiUBlocks<'static> =
                ::linkage::PsiUBlocks::new(#equations, #coordinates, #ends, #reach);
        }
    }

    /// `kinematics`: Ψ, Ψ_u, Ψ_v, the velocity solve and γ in one pass, every
    /// sine, cosine and common subexpression computed once.
    pub(super) fn kinematics_function(&self, with_trig: bool, doc: &[String]) -> TokenStream {
        let doc = doc_attributes(doc);
        let model = self.model;
        let (m, f) = (self.m, self.f);
        let (ml, fl) = (Literal::usize_unsuffixed(m), Literal::usize_unsuffixed(f));
        let plan = Kernel::Kinematics { with_trig }.plan(model);
        let locals = [
            "psi", "psi_u", "psi_v", "gamma", "factors", "rcond", "det", "udot", "uddot", "out",
        ];
        let local: Vec<String> = locals.iter().map(|n| self.free_name(n)).collect();
        let trig_names = Plan::trig_names(&self.names);
        let source = [&trig_names[0], &trig_names[1]].map(|n| format_ident!("{}", n));
        let mut reserved = local.clone();
        reserved.extend(trig_names.iter().cloned());
        let phased = plan.emit(self.dag(), &self.names, &reserved, Mode::F64);
        let [
            psi,
            psi_u,
            psi_v,
            gamma,
            factors,
            rcond,
            det,
            udot,
            uddot,
            out,
        ] = locals.map(|n| {
            let k = locals.iter().position(|x| *x == n).unwrap_or(0);
            format_ident!("{}", local[k])
        });
        let second = plan.roots().pop().unwrap_or_default();
        let mut phases = phased.phases.into_iter();
        let (first_statements, first_values) = phases.next().unwrap_or_default();
        let (second_statements, second_values) = phases.next().unwrap_or_default();
        // Each phase's parts filled from its values: Ψ, Ψ_u and Ψ_v, then γ.
        let phase_parts = |k: usize| plan.phases.get(k).map_or(&[][..], Vec::as_slice);
        let fill = |parts: &[PlannedPart],
                    k: usize,
                    name: &proc_macro2::Ident,
                    values: &mut std::slice::Iter<'_, TokenStream>| {
            parts.get(k).map_or_else(Vec::new, |p| {
                assemble(&p.part, &name.to_string(), values, quote!(f64)).0
            })
        };
        let mut values = first_values.iter();
        let psi_fill = fill(phase_parts(0), 0, &psi, &mut values);
        let psi_u_fill = fill(phase_parts(0), 1, &psi_u, &mut values);
        // In place: the same entries written over the result's own Ψ_u
        // (the statements after `assemble`'s declaration), its other
        // entries zeroed first by `_into`, or zero already for `_over`.
        let psi_u_entries: Vec<TokenStream> = psi_u_fill.iter().skip(1).cloned().collect();
        let psi_v_fill = fill(phase_parts(0), 2, &psi_v, &mut values);
        let mut values = second_values.iter();
        let gamma_fill = fill(phase_parts(1), 0, &gamma, &mut values);
        let bind = |name: &proc_macro2::Ident, fill: Vec<TokenStream>, ty: TokenStream| {
            if fill.is_empty() {
                quote!(let #name = #ty::zeros();)
            } else {
                quote!(#(#fill)*)
            }
        };
        let psi_bind = bind(&psi, psi_fill, quote!(SVector::<f64, #ml>));
        let psi_u_bind = bind(&psi_u, psi_u_fill, quote!(SMatrix::<f64, #ml, #ml>));
        let psi_v_bind = bind(&psi_v, psi_v_fill, quote!(SMatrix::<f64, #ml, #fl>));
        let gamma_bind = bind(&gamma, gamma_fill, quote!(SVector::<f64, #ml>));
        // The velocities u̇ that γ uses, read from the solved vector.
        let used: Vec<usize> = (0..m)
            .filter(|&k| reaches(self.dag(), &second, Symbol::Vel(k as u16)))
            .collect();
        let velocity_names: Vec<proc_macro2::Ident> = used
            .iter()
            .map(|&k| format_ident!("{}", format!("{}_dot", self.model.lowered.coord_name(k))))
            .collect();
        let indices = used.iter().map(|&k| Literal::usize_unsuffixed(k));
        let velocity_bind = match velocity_names.len() {
            0 => quote!(),
            1 => quote!(let #(#velocity_names)* = #(#udot[#indices])*;),
            _ => quote!(let (#(#velocity_names),*) = (#(#udot[#indices]),*);),
        };
        // `field` when the local has the field's name, `field: local` else.
        let field = |name: &str, local: &proc_macro2::Ident| {
            let f = format_ident!("{}", name);
            if *local == name {
                quote!(#f)
            } else {
                quote!(#f: #local)
            }
        };
        let fields = [
            ("psi", &psi),
            ("psi_u", &psi_u),
            ("psi_v", &psi_v),
            ("factors", &factors),
            ("rcond", &rcond),
            ("det", &det),
            ("udot", &udot),
            ("uddot", &uddot),
        ]
        .map(|(name, local)| field(name, local));
        // Block by block where Ψ_u has more than one block.
        let factor = if model.blocks.is_triangular() {
            let blocks = format_ident!("{}", constants::PSI_U_BLOCKS);
            quote!(::linkage::Factors::of(&#psi_u, Self::#blocks))
        } else {
            quote!(::linkage::Factors::whole(&#psi_u))
        };
        let factor_into = if model.blocks.is_triangular() {
            let blocks = format_ident!("{}", constants::PSI_U_BLOCKS);
            quote!(#out.factors.of_into(&#out.psi_u, Self::#blocks);)
        } else {
            quote!(#out.factors = ::linkage::Factors::whole(&#out.psi_u);)
        };
        let prologue = &phased.prologue;
        let reads = phased.reads;
        let arg = |used: bool, name: &str| {
            if used {
                format_ident!("{}", name)
            } else {
                format_ident!("_{}", name)
            }
        };
        let (u_arg, v_arg) = (arg(reads.u, "u"), arg(reads.v, "v"));
        // The body, the same with computed or carried sines and cosines
        // (the prologue reads them from wherever they come from).
        let body = quote! {
            #(#prologue)*
            #(#first_statements)*
            #psi_bind
            #psi_u_bind
            #psi_v_bind
            let #factors = #factor;
            let (#rcond, #det) = (#factors.rcond(), #factors.det());
            let #udot = -#factors.solve(&(#psi_v * vdot));
            #velocity_bind
            #(#second_statements)*
            #gamma_bind
            let #uddot = -#factors.solve(&(#psi_v * vddot + #gamma));
            ::linkage::Kinematics { #(#fields),* }
        };
        if with_trig {
            let [trig_u, trig_v] = &source;
            let mask = |range: std::ops::Range<usize>| {
                let flags = range.map(|k| phased.trig_coords.contains(&k));
                quote!([#(#flags),*])
            };
            let dims = self.dims();
            let [trig_u_const, trig_v_const] = &TRIG;
            let masks = [
                trig_u_const.declare(&dims, mask(0..m)),
                trig_v_const.declare(&dims, mask(m..m + f)),
            ];
            // The inputs of both forms, returned and in place.
            let inputs = [
                quote!(&self),
                quote!(#u_arg: &SVector<f64, #ml>),
                quote!(#v_arg: &SVector<f64, #fl>),
                quote!(#trig_u: &[(f64, f64); #ml]),
                quote!(#trig_v: &[(f64, f64); #fl]),
                quote!(vdot: &SVector<f64, #fl>),
                quote!(vddot: &SVector<f64, #fl>),
            ];
            // Above IN_PLACE_ABOVE the body is emitted once, in place, and
            // the result returned by value is that written over a fresh one.
            let returned = if m > IN_PLACE_ABOVE {
                quote! {
                    let mut #out = ::linkage::Kinematics::unevaluated();
                    self.kinematics_with_trig_into(#u_arg, #v_arg, #trig_u, #trig_v, vdot, vddot, &mut #out);
                    #out
                }
            } else {
                body.clone()
            };
            let in_place = if m > IN_PLACE_ABOVE {
                quote! {
                    /// [`Self::kinematics_with_trig`] written over `out`, whose
                    /// m × m matrices are then neither built elsewhere nor
                    /// moved: Ψ_u's entries are written into `out.psi_u` and
                    /// factored in `out.factors`. The same numbers, bit for
                    /// bit.
                    #[doc(hidden)]
                    #[inline(always)]
                    #[allow(unused_variables, clippy::too_many_arguments)]
                    pub fn kinematics_with_trig_into(
                        #(#inputs,)*
                        #out: &mut ::linkage::Kinematics<#ml, #fl>,
                    ) {
                        #out.psi_u.as_mut_slice().fill(0.0);
                        self.kinematics_with_trig_over(#u_arg, #v_arg, #trig_u, #trig_v, vdot, vddot, #out);
                    }
                    /// [`Self::kinematics_with_trig_into`] over an `out` whose
                    /// Ψ_u is zero wherever Ψ_u is zero at every pose (one this
                    /// kernel wrote, or `Kinematics::blank()`): only the
                    /// entries that can be nonzero are written.
                    #[doc(hidden)]
                    #[inline(always)]
                    #[allow(unused_variables, clippy::too_many_arguments)]
                    pub fn kinematics_with_trig_over(
                        #(#inputs,)*
                        #out: &mut ::linkage::Kinematics<#ml, #fl>,
                    ) {
                        #(#prologue)*
                        #(#first_statements)*
                        #psi_bind
                        #psi_v_bind
                        {
                            let #psi_u = &mut #out.psi_u;
                            #(#psi_u_entries)*
                        }
                        #factor_into
                        let (#rcond, #det) = (#out.factors.rcond(), #out.factors.det());
                        let #udot = -#out.factors.solve(&(#psi_v * vdot));
                        #velocity_bind
                        #(#second_statements)*
                        #gamma_bind
                        let #uddot = -#out.factors.solve(&(#psi_v * vddot + #gamma));
                        #out.psi = #psi;
                        #out.psi_v = #psi_v;
                        #out.rcond = #rcond;
                        #out.det = #det;
                        #out.udot = #udot;
                        #out.uddot = #uddot;
                    }
                }
            } else {
                quote!()
            };
            return quote! {
                #in_place
                #(#masks)*
                #doc
                #[doc(hidden)]
                #[must_use]
                #[inline(always)]
                #[allow(unused_variables, clippy::too_many_arguments)]
                pub fn kinematics_with_trig(
                    #(#inputs),*
                ) -> ::linkage::Kinematics<#ml, #fl> {
                    #returned
                }
            };
        }
        quote! {
            #doc
            #[must_use]
            #[inline]
            pub fn kinematics(
                &self,
                #u_arg: &SVector<f64, #ml>,
                #v_arg: &SVector<f64, #fl>,
                vdot: &SVector<f64, #fl>,
                vddot: &SVector<f64, #fl>,
            ) -> ::linkage::Kinematics<#ml, #fl> {
                #body
            }
        }
    }
}

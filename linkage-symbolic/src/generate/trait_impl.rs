//! The `Kernels`, `Linkage`, `SensitivityKernel` and `Sensitivities` impls:
//! every quantity of the table that the trait has, delegating to the
//! inherent function of the same name (`Linkage`'s impl is empty: its
//! methods, the analyses, are all provided).

use super::Generator;
use super::constants::{
    PARAM_NAMES, POINT_NAMES, PSI_U_BLOCKS, SENSITIVITY_TRIG, TRIG, U_NAMES, V_NAMES,
};
use super::kinematics::IN_PLACE_ABOVE;
use super::quantities::{QUANTITIES, Source, Trait};
use super::signature;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

impl Generator<'_> {
    pub(super) fn trait_impl(&self) -> TokenStream {
        let item = &self.input.item;
        let ty = &item.ident;
        let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
        let (m, f, np) = (
            Literal::usize_unsuffixed(self.m),
            Literal::usize_unsuffixed(self.f),
            Literal::usize_unsuffixed(self.np),
        );
        let k = Literal::usize_unsuffixed(self.k);
        let dims = self.dims();
        let functions = |which: Trait| {
            QUANTITIES
                .iter()
                .filter(move |q| q.in_trait == Some(which))
                .map(|q| {
                    let name = format_ident!("{}", q.name);
                    let generics = signature::generics(q);
                    let args = signature::args(q, &dims, |_| true);
                    let ret = signature::output_type(q, &dims, true);
                    let call = signature::delegate(q);
                    let prefix = match q.source {
                        Source::Kinematics { with_trig: false } => quote!(#[inline]),
                        Source::Kinematics { with_trig: true } => {
                            let flags = TRIG.iter().map(|c| c.trait_method(&dims, false));
                            quote! {
                                #(#flags)*
                                #[inline(always)]
                            }
                        }
                        Source::SensitivityTerms { with_trig: true } => {
                            let flags = SENSITIVITY_TRIG
                                .iter()
                                .map(|c| c.trait_method(&dims, false));
                            quote! {
                                #(#flags)*
                                #[inline(always)]
                            }
                        }
                        _ => quote!(#[inline]),
                    };
                    quote! {
                        #prefix
                        fn #name #generics(&self, #(#args),*) -> #ret {
                            #call
                        }
                    }
                })
                .collect::<Vec<_>>()
        };
        let (kinematics, kernel, sensitivities) = (
            functions(Trait::Kernels),
            functions(Trait::SensitivityKernel),
            functions(Trait::Sensitivities),
        );
        let names = [U_NAMES, V_NAMES, POINT_NAMES].map(|c| c.trait_method(&dims, false));
        let psi_u_blocks = if self.model.blocks.is_triangular() {
            let name = format_ident!("{}", PSI_U_BLOCKS);
            quote! {
                #[inline]
                fn psi_u_blocks(&self) -> ::linkage::PsiUBlocks<'_> {
                    Self::#name
                }
            }
        } else {
            quote!()
        };
        // The fused kernel in place where the generator emits it: the
        // trait's methods call the inherent ones of the same name.
        let in_place = if self.m > IN_PLACE_ABOVE {
            let written = ["kinematics_with_trig_into", "kinematics_with_trig_over"].map(|name| {
                let name = format_ident!("{}", name);
                quote! {
                    #[inline(always)]
                    fn #name(
                        &self,
                        u: &SVector<f64, #m>,
                        v: &SVector<f64, #f>,
                        trig_u: &[(f64, f64); #m],
                        trig_v: &[(f64, f64); #f],
                        vdot: &SVector<f64, #f>,
                        vddot: &SVector<f64, #f>,
                        out: &mut ::linkage::Kinematics<#m, #f>,
                    ) {
                        self.#name(u, v, trig_u, trig_v, vdot, vddot, out)
                    }
                }
            });
            quote! {
                #[inline(always)]
                fn evaluates_in_place(&self) -> bool {
                    true
                }
                #(#written)*
            }
        } else {
            quote!()
        };
        let param_names = PARAM_NAMES.trait_method(&dims, false);
        let lowered = &self.model.lowered;
        let param_idents: Vec<_> = lowered
            .params
            .iter()
            .map(|&k| &lowered.fields[k as usize])
            .collect();
        let indices = (0..param_idents.len()).map(Literal::usize_unsuffixed);
        quote! {
            #[automatically_derived]
            impl #impl_generics ::linkage::Kernels<#m, #f> for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                #(#names)*
                #psi_u_blocks
                #(#kinematics)*
                #in_place
            }

            #[automatically_derived]
            impl #impl_generics ::linkage::Linkage<#m, #f> for #ty #ty_generics #where_clause {}

            #[automatically_derived]
            impl #impl_generics ::linkage::SensitivityKernel<#m, #f, #k> for #ty #ty_generics #where_clause {
                #(#kernel)*
            }

            #[automatically_derived]
            impl #impl_generics ::linkage::Sensitivities<#m, #f, #k> for #ty #ty_generics #where_clause {
                #param_names
                #[inline]
                fn params(&self) -> SVector<f64, #k> {
                    SVector::<f64, #k>::from([#(self.#param_idents),*])
                }
                #[inline]
                fn set_params(&mut self, params: &SVector<f64, #k>) {
                    #(self.#param_idents = params[#indices];)*
                }
                #(#sensitivities)*
            }
        }
    }
}

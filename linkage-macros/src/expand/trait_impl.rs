//! The `Linkage` impl: every quantity of the table that the trait has,
//! delegating to the inherent function of the same name.

use super::Generator;
use super::quantities::{QUANTITIES, Source};
use super::signature::{self, Dims};
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
        let dims = Dims::known(self.m, self.f, self.np);
        let functions = QUANTITIES.iter().filter(|q| q.in_trait).map(|q| {
            let name = format_ident!("{}", q.name);
            let generics = signature::generics(q);
            let args = signature::args(q, &dims, |_| true);
            let ret = signature::output_type(q, &dims, true);
            let call = signature::delegate(q);
            let prefix = match q.source {
                Source::Kinematics { with_trig: false } => quote!(#[inline]),
                Source::Kinematics { with_trig: true } => quote! {
                    const TRIG_U: [bool; #m] = Self::TRIG_U;
                    const TRIG_V: [bool; #f] = Self::TRIG_V;
                    #[inline(always)]
                },
                _ => quote!(#[inline]),
            };
            quote! {
                #prefix
                fn #name #generics(&self, #(#args),*) -> #ret {
                    #call
                }
            }
        });
        quote! {
            #[automatically_derived]
            impl #impl_generics ::linkage::Linkage<#m, #f> for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                const U_NAMES: [&'static str; #m] = Self::U_NAMES;
                const V_NAMES: [&'static str; #f] = Self::V_NAMES;
                const POINT_NAMES: &'static [&'static str] = &Self::POINT_NAMES;
                const SYMBOLIC: ::linkage::SymbolicTable = Self::SYMBOLIC;
                #(#functions)*
            }
        }
    }
}

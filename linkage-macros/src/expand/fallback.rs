//! The error path: when the attribute has mistakes, the struct still gets
//! every generated item, with bodies that never run (the build fails on
//! the reported errors) and generic in the dimensions, so that whatever
//! sizes the user's other code passes it still type-checks and only the
//! attribute's real mistakes are reported — as thiserror's `fallback.rs`.
//!
//! The generic parameters have names no user identifier takes
//! (`__LINKAGE_M`, ...): a struct called `M` or `F` must not turn a
//! dimension into a type.

use super::quantities::{Arg, QUANTITIES, Quantity, Scalar, Shape, Trait};
use super::signature::{self, Dim, Dims};
use linkage_symbolic::ast::Input;
use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

/// The struct as written, followed by the fallback items.
pub fn fallback(input: &Input) -> TokenStream {
    let item = &input.item;
    let ty = &item.ident;
    let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
    let [m, f, n, k] = ["__LINKAGE_M", "__LINKAGE_F", "__LINKAGE_N", "__LINKAGE_K"]
        .map(|s| format_ident!("{}", s));
    let np = input.points.items.len();
    let dims = Dims {
        m: Dim::generic(&m),
        f: Dim::generic(&f),
        n: Dim::generic(&n),
        np: Dim::known(np),
        k: Dim::generic(&k),
    };
    let never = quote!(::core::unimplemented!(
        "#[linkage::linkage] on this struct has errors"
    ));
    let name = ty.to_string();
    let names: Vec<String> = input
        .points
        .items
        .iter()
        .map(|p| p.name.to_string())
        .collect();
    let point_indices = super::point_indices(names.iter().map(String::as_str));
    let inherent = QUANTITIES.iter().filter(|q| q.function).map(|q| {
        let fn_name = format_ident!("{}", q.name);
        let generics = function_generics(q, &m, &f, &n, &k);
        let args = signature::args(q, &dims, |_| false);
        let ret = signature::output_type(q, &dims, false);
        quote! {
            #[allow(clippy::too_many_arguments)]
            pub fn #fn_name #generics(&self, #(#args),*) -> #ret {
                #never
            }
        }
    });
    let in_trait = |which: Trait| {
        QUANTITIES
            .iter()
            .filter(move |q| q.in_trait == Some(which))
            .map(|q| {
                let fn_name = format_ident!("{}", q.name);
                let generics = signature::generics(q);
                let args = signature::args(q, &dims, |_| false);
                let ret = signature::output_type(q, &dims, false);
                let refines = (q.scalar == Scalar::Dual && q.shape == Shape::Points)
                    .then(|| quote!(#[allow(refining_impl_trait)]));
                quote! {
                    #refines
                    #[allow(clippy::too_many_arguments)]
                    fn #fn_name #generics(&self, #(#args),*) -> #ret {
                        #never
                    }
                }
            })
            .collect::<Vec<_>>()
    };
    let (kinematics, kernel, sensitivities) = (
        in_trait(Trait::Linkage),
        in_trait(Trait::SensitivityKernel),
        in_trait(Trait::Sensitivities),
    );
    let mut generics = item.generics.clone();
    generics.params.push(syn::parse_quote!(const #m: usize));
    generics.params.push(syn::parse_quote!(const #f: usize));
    let (trait_generics, _, _) = generics.split_for_impl();
    let mut generics_k = generics.clone();
    generics_k.params.push(syn::parse_quote!(const #k: usize));
    let (sensitivity_generics, _, _) = generics_k.split_for_impl();
    let np = proc_macro2::Literal::usize_unsuffixed(np);
    quote! {
        #item
        const _: () = {
            use ::linkage::nalgebra::{SMatrix, SVector, Vector2};
            #[allow(dead_code, unused_variables)]
            impl #impl_generics #ty #ty_generics #where_clause {
                pub const U_NAMES: &'static [&'static str] = &[];
                pub const V_NAMES: &'static [&'static str] = &[];
                pub const POINT_NAMES: &'static [&'static str] = &[];
                pub const PARAM_NAMES: &'static [&'static str] = &[];
                #point_indices
                pub const SYMBOLIC: ::linkage::SymbolicTable = ::linkage::SymbolicTable {
                    name: #name,
                    u: &[],
                    v: &[],
                    matrices: &[],
                    methods_agree: ::core::option::Option::None,
                };
                #(#inherent)*
            }
            #[allow(unused_variables)]
            impl #trait_generics ::linkage::Linkage<#m, #f> for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                const U_NAMES: [&'static str; #m] = [""; #m];
                const V_NAMES: [&'static str; #f] = [""; #f];
                const POINT_NAMES: &'static [&'static str] = &[];
                const SYMBOLIC: ::linkage::SymbolicTable = Self::SYMBOLIC;
                #(#kinematics)*
            }
            #[allow(unused_variables)]
            impl #sensitivity_generics ::linkage::SensitivityKernel<#m, #f, #k> for #ty #ty_generics #where_clause {
                #(#kernel)*
            }
            #[allow(unused_variables)]
            impl #sensitivity_generics ::linkage::Sensitivities<#m, #f, #k> for #ty #ty_generics #where_clause {
                const PARAM_NAMES: [&'static str; #k] = [""; #k];
                fn params(&self) -> SVector<f64, #k> {
                    #never
                }
                fn set_params(&mut self, params: &SVector<f64, #k>) {
                    #never
                }
                #(#sensitivities)*
            }
        };
    }
}

/// A fallback function's own generic parameters: the dual number type if
/// any, then the dimensions it uses.
fn function_generics(q: &Quantity, m: &Ident, f: &Ident, n: &Ident, k: &Ident) -> TokenStream {
    let dual = (q.scalar == Scalar::Dual).then(|| {
        let d = signature::dual();
        quote!(#d: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,)
    });
    let full = (q.shape == Shape::Full).then(|| quote!(, const #n: usize));
    let by_params = matches!(q.shape, Shape::ByParams | Shape::SensitivityTerms)
        || q.args.contains(&Arg::Params);
    let params = by_params.then(|| quote!(, const #k: usize));
    quote!(<#dual const #m: usize, const #f: usize #full #params>)
}

//! The error path: when the attribute has mistakes, the struct still gets
//! every generated item, with bodies that never run (the build fails on
//! the reported errors) and with the types it has without the mistakes,
//! so that the rest of the user's code still type-checks and only the
//! attribute's real mistakes are reported — as thiserror's `fallback.rs`.
//!
//! Every dimension the attribute gives, as far as it was read, is that
//! number: m from `u` (or else the number of closure equations), f from
//! `v`, the points from `points`, k from `params` or else the fields the
//! equations use (as the pipeline resolved them where it lowered the
//! equations), each list's entries as written (a malformed one
//! included, a name written twice counted once). A generic trait impl
//! would leave a call such as `bar.sensitivities_of(..)` ambiguous, and a
//! slice is not the array a user's code passes on
//! (`Tolerances::by_name(&Bar::PARAM_NAMES, ..)`). Only a dimension the
//! attribute does not give stays generic.
//!
//! The generic parameters have names no user identifier takes
//! (`__LINKAGE_M`, ...): a struct called `M` or `F` must not turn a
//! dimension into a type.

use super::constants;
use super::quantities::{QUANTITIES, Scalar, Shape, Trait};
use super::signature::{self, Dim, Dims};
use crate::Unbuilt;
use crate::ast::Input;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The dimensions as far as the attribute gives them.
fn dims(input: &Input, unbuilt: &Unbuilt) -> Dims {
    let [m, f, n, k_name] = ["__LINKAGE_M", "__LINKAGE_F", "__LINKAGE_N", "__LINKAGE_K"]
        .map(|s| format_ident!("{}", s));
    let given = |written: usize| (written > 0).then_some(written);
    let m = Dim::known_or_generic(
        given(input.u.meant(&[])).or(given(input.closure.written)),
        &m,
    );
    let f = Dim::known_or_generic(given(input.v.meant(&input.u.items)), &f);
    let n = Dim::known_or_generic(m.value().zip(f.value()).map(|(m, f)| m + f), &n);
    let k = crate::params::count_as_written(input, unbuilt.params);
    let k = Dim::known_or_generic(k, &k_name);
    Dims {
        m,
        f,
        n,
        np: Dim::known(input.points.written),
        k,
    }
}

/// The struct as written, followed by the fallback items.
pub fn fallback(input: &Input, unbuilt: &Unbuilt) -> TokenStream {
    let item = &input.item;
    let ty = &item.ident;
    let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
    let dims = dims(input, unbuilt);
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
    let consts = constants::all().map(|c| c.placeholder(&dims, false));
    let names = [
        constants::U_NAMES,
        constants::V_NAMES,
        constants::POINT_NAMES,
    ]
    .map(|c| c.trait_method(&dims, true));
    let param_names = constants::PARAM_NAMES.trait_method(&dims, true);
    let symbolic_name = format_ident!("{}", constants::SYMBOLIC);
    let inherent = QUANTITIES.iter().filter(|q| q.function).map(|q| {
        let fn_name = format_ident!("{}", q.name);
        let args = signature::args(q, &dims, |_| false);
        let ret = signature::output_type(q, &dims, false);
        let dual = (q.scalar == Scalar::Dual).then(|| {
            let d = signature::dual();
            quote!(#d: ::linkage::num_dual::DualNum<Primitive = f64> + Copy)
        });
        let generic_dims = dims.generic_params(&quote!(#(#args)* #ret));
        let generics: Vec<TokenStream> = dual.into_iter().chain(generic_dims).collect();
        let generics = (!generics.is_empty()).then(|| quote!(<#(#generics),*>));
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
        in_trait(Trait::Kernels),
        in_trait(Trait::SensitivityKernel),
        in_trait(Trait::Sensitivities),
    );
    let (m, f, k, np) = (
        &dims.m.tokens(),
        &dims.f.tokens(),
        &dims.k.tokens(),
        &dims.np.tokens(),
    );
    // Each trait impl generic in the dimensions it leaves open.
    let impl_generics_over = |trait_: &TokenStream| {
        let mut generics = item.generics.clone();
        for param in dims.generic_params(trait_) {
            generics.params.push(syn::parse_quote!(#param));
        }
        generics
    };
    let kernels = quote!(::linkage::Kernels<#m, #f>);
    let linkage = quote!(::linkage::Linkage<#m, #f>);
    let sensitivities_trait = quote!(::linkage::Sensitivities<#m, #f, #k>);
    let kernel_trait = quote!(::linkage::SensitivityKernel<#m, #f, #k>);
    let linkage_generics = impl_generics_over(&linkage);
    let sensitivity_generics = impl_generics_over(&sensitivities_trait);
    let (linkage_generics, _, _) = linkage_generics.split_for_impl();
    let (sensitivity_generics, _, _) = sensitivity_generics.split_for_impl();
    quote! {
        #item
        const _: () = {
            use ::linkage::nalgebra::{SMatrix, SVector, Vector2};
            #[allow(dead_code, unused_variables)]
            impl #impl_generics #ty #ty_generics #where_clause {
                #(#consts)*
                #point_indices
                pub const #symbolic_name: ::linkage::SymbolicTable = ::linkage::SymbolicTable {
                    name: #name,
                    u: &[],
                    v: &[],
                    matrices: &[],
                    methods_agree: ::core::option::Option::None,
                    structure: "",
                };
                #(#inherent)*
            }
            #[allow(unused_variables)]
            impl #linkage_generics #kernels for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                #(#names)*
                #(#kinematics)*
            }
            impl #linkage_generics #linkage for #ty #ty_generics #where_clause {}
            #[allow(unused_variables)]
            impl #sensitivity_generics #kernel_trait for #ty #ty_generics #where_clause {
                #(#kernel)*
            }
            #[allow(unused_variables)]
            impl #sensitivity_generics #sensitivities_trait for #ty #ty_generics #where_clause {
                #param_names
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

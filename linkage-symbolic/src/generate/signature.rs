//! The signatures of the generated functions, from the table of
//! quantities: one rule for every argument and result type, whether the
//! dimensions are the model's numbers (the items, the trait impl) or, on
//! the error path, the numbers the attribute gives as far as it was read
//! and generic parameters for the others (the fallback).

use super::quantities::{Arg, Length, Quantity, Scalar, Shape};
use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote};

/// A dimension: a number known to the macro, or a generic parameter.
#[derive(Clone)]
pub struct Dim {
    tokens: TokenStream,
    value: Option<usize>,
}

impl Dim {
    pub fn known(n: usize) -> Dim {
        let literal = Literal::usize_unsuffixed(n);
        Dim {
            tokens: quote!(#literal),
            value: Some(n),
        }
    }

    pub fn generic(name: &Ident) -> Dim {
        Dim {
            tokens: quote!(#name),
            value: None,
        }
    }

    /// The number if it is known, else the generic parameter `name`.
    pub fn known_or_generic(value: Option<usize>, name: &Ident) -> Dim {
        value.map_or_else(|| Dim::generic(name), Dim::known)
    }

    /// The number or the generic parameter, as written in a type.
    pub fn tokens(&self) -> TokenStream {
        self.tokens.clone()
    }

    /// The number, if known.
    pub fn value(&self) -> Option<usize> {
        self.value
    }

    /// The declaration `const NAME: usize` of this dimension if it is
    /// generic and `tokens` name it.
    fn generic_param_in(&self, tokens: &TokenStream) -> Option<TokenStream> {
        fn names(tokens: &TokenStream, name: &str) -> bool {
            tokens.clone().into_iter().any(|tt| match tt {
                proc_macro2::TokenTree::Ident(i) => i == name,
                proc_macro2::TokenTree::Group(g) => names(&g.stream(), name),
                _ => false,
            })
        }
        let name = &self.tokens;
        (self.value.is_none() && names(tokens, &name.to_string()))
            .then(|| quote!(const #name: usize))
    }
}

/// The dimensions of a model: m dependent coordinates, f driving ones, m +
/// f in all, np named points, k parameters.
#[derive(Clone)]
pub struct Dims {
    pub m: Dim,
    pub f: Dim,
    pub n: Dim,
    pub np: Dim,
    pub k: Dim,
}

impl Dims {
    /// The declarations of the generic dimensions that `tokens` (types, a
    /// signature) name, in the order m, f, n, np, k: an item generic in
    /// exactly the dimensions its types leave open.
    pub fn generic_params(&self, tokens: &TokenStream) -> Vec<TokenStream> {
        [&self.m, &self.f, &self.n, &self.np, &self.k]
            .into_iter()
            .filter_map(|d| d.generic_param_in(tokens))
            .collect()
    }

    pub fn known(m: usize, f: usize, np: usize, k: usize) -> Dims {
        Dims {
            m: Dim::known(m),
            f: Dim::known(f),
            n: Dim::known(m + f),
            np: Dim::known(np),
            k: Dim::known(k),
        }
    }
}

/// The name of the dual-number type parameter of the generic functions.
pub fn dual() -> Ident {
    format_ident!("D")
}

fn scalar(s: Scalar) -> TokenStream {
    match s {
        Scalar::F64 => quote!(f64),
        Scalar::Dual => {
            let d = dual();
            quote!(#d)
        }
    }
}

/// A `rows × cols` matrix of `s`: `SVector` when it has one column.
fn matrix(rows: &Dim, cols: &Dim, s: Scalar) -> TokenStream {
    let (r, c, s) = (&rows.tokens, &cols.tokens, scalar(s));
    if cols.value == Some(1) {
        quote!(SVector<#s, #r>)
    } else {
        quote!(SMatrix<#s, #r, #c>)
    }
}

/// The type of an argument.
pub fn arg_type(arg: Arg, dims: &Dims, s: Scalar) -> TokenStream {
    let dim = match arg.length() {
        Length::M => &dims.m,
        Length::F => &dims.f,
        Length::K => &dims.k,
    };
    let (d, s) = (&dim.tokens, scalar(s));
    match arg {
        Arg::TrigU | Arg::TrigV => quote!(&[(f64, f64); #d]),
        _ => quote!(&SVector<#s, #d>),
    }
}

/// The result type; `in_trait` asks for the trait's form of the dual
/// points (`impl AsRef<[Vector2<D>]>`).
pub fn output_type(q: &Quantity, dims: &Dims, in_trait: bool) -> TokenStream {
    let s = q.scalar;
    let one = Dim::known(1);
    match q.shape {
        Shape::Column => matrix(&dims.m, &one, s),
        Shape::Square => matrix(&dims.m, &dims.m, s),
        Shape::Wide => matrix(&dims.m, &dims.f, s),
        Shape::Full => matrix(&dims.m, &dims.n, s),
        Shape::ColumnAndSquare => {
            let (a, b) = (matrix(&dims.m, &one, s), matrix(&dims.m, &dims.m, s));
            quote!((#a, #b))
        }
        Shape::Points => {
            let (np, s) = (&dims.np.tokens, scalar(s));
            if in_trait && q.scalar == Scalar::Dual {
                quote!(impl AsRef<[Vector2<#s>]>)
            } else {
                quote!([Vector2<#s>; #np])
            }
        }
        Shape::Kinematics => {
            let (m, f) = (&dims.m.tokens, &dims.f.tokens);
            quote!(::linkage::Kinematics<#m, #f>)
        }
        Shape::ByParams => matrix(&dims.m, &dims.k, s),
        Shape::SensitivityTerms => {
            let (m, k, np) = (&dims.m.tokens, &dims.k.tokens, &dims.np.tokens);
            quote!(::linkage::SensitivityTerms<#m, #k, [Vector2<f64>; #np]>)
        }
    }
}

/// The generic parameters of a function: the dual number type, if any.
pub fn generics(q: &Quantity) -> TokenStream {
    match q.scalar {
        Scalar::F64 => quote!(),
        Scalar::Dual => {
            let d = dual();
            quote!(<#d: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>)
        }
    }
}

/// `name: type` for every argument; `used` says which are read (the others
/// get a leading underscore).
pub fn args(q: &Quantity, dims: &Dims, used: impl Fn(Arg) -> bool) -> Vec<TokenStream> {
    q.args
        .iter()
        .map(|&a| {
            let name = if used(a) {
                format_ident!("{}", a.name())
            } else {
                format_ident!("_{}", a.name())
            };
            let ty = arg_type(a, dims, q.scalar);
            quote!(#name: #ty)
        })
        .collect()
}

/// The call of the inherent function from the trait: `Self::name(self, u, v)`.
pub fn delegate(q: &Quantity) -> TokenStream {
    let name = format_ident!("{}", q.name);
    let args = q.args.iter().map(|a| format_ident!("{}", a.name()));
    quote!(Self::#name(self, #(#args),*))
}

//! The one table of the associated constants the attribute generates
//! beside the functions of the table of quantities: the items declare them
//! from it (`mod.rs`, `kinematics.rs`, `sensitivity.rs`), the fallback
//! gives each its placeholder from it, and a point gets no index constant
//! under a name taken here ([`taken`]).

use super::signature::{Dim, Dims};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// What a constant has one entry per.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Per {
    /// Dependent coordinate (m).
    U,
    /// Driving coordinate (f).
    V,
    /// Named point.
    Point,
    /// Parameter (k).
    Param,
}

/// What each entry is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// A name (`&'static str`).
    Name,
    /// Whether the coordinate appears under `sin`/`cos` (`bool`).
    Flag,
}

/// One generated constant: an array with an entry per coordinate, point or
/// parameter.
#[derive(Clone, Copy)]
pub struct Constant {
    pub name: &'static str,
    pub per: Per,
    pub entry: Entry,
    /// Its documentation, one line each.
    pub doc: &'static [&'static str],
    /// Whether it is hidden from the documentation (the runtime's, not an
    /// entry point).
    pub hidden: bool,
}

const fn names(name: &'static str, per: Per, doc: &'static [&'static str]) -> Constant {
    Constant {
        name,
        per,
        entry: Entry::Name,
        doc,
        hidden: false,
    }
}

pub const U_NAMES: Constant = names(
    "U_NAMES",
    Per::U,
    &[" The dependent coordinates u, in order."],
);
pub const V_NAMES: Constant = names(
    "V_NAMES",
    Per::V,
    &[" The driving coordinates v, in order."],
);
pub const POINT_NAMES: Constant =
    names("POINT_NAMES", Per::Point, &[" The named points, in order."]);
pub const PARAM_NAMES: Constant = names(
    "PARAM_NAMES",
    Per::Param,
    &[" The parameters p the sensitivities differentiate by, in order."],
);

/// The names of the coordinates, points and parameters, in this order
/// first among the inherent items.
pub const NAMES: [Constant; 4] = [U_NAMES, V_NAMES, POINT_NAMES, PARAM_NAMES];

/// Which coordinates `kinematics_with_trig` reads the sine and cosine of.
pub const TRIG: [Constant; 2] = [
    Constant {
        name: "TRIG_U",
        per: Per::U,
        entry: Entry::Flag,
        doc: &[
            " Which coordinates of u appear under `sin`/`cos` in",
            " [`Self::kinematics_with_trig`], which reads their sine and",
            " cosine from `trig_u` (the others' entries are not read).",
        ],
        hidden: true,
    },
    Constant {
        name: "TRIG_V",
        per: Per::V,
        entry: Entry::Flag,
        doc: &[
            " Which coordinates of v appear under `sin`/`cos`, read from",
            " `trig_v`.",
        ],
        hidden: true,
    },
];

/// Which coordinates `sensitivity_terms_with_trig` reads the sine and
/// cosine of.
pub const SENSITIVITY_TRIG: [Constant; 2] = [
    Constant {
        name: "SENSITIVITY_TRIG_U",
        per: Per::U,
        entry: Entry::Flag,
        doc: &[
            " Which coordinates of u appear under `sin`/`cos` in",
            " [`Self::sensitivity_terms_with_trig`], which reads their",
            " sine and cosine from `trig_u` (the others' entries are not",
            " read).",
        ],
        hidden: true,
    },
    Constant {
        name: "SENSITIVITY_TRIG_V",
        per: Per::V,
        entry: Entry::Flag,
        doc: &[
            " Which coordinates of v appear under `sin`/`cos`, read from",
            " `trig_v`.",
        ],
        hidden: true,
    },
];

/// The symbolic table, `Self::SYMBOLIC`: a constant of its own type.
pub const SYMBOLIC: &str = "SYMBOLIC";

/// Ψ_u's diagonal blocks, `Self::PSI_U_BLOCKS` (where it has more than one).
pub const PSI_U_BLOCKS: &str = "PSI_U_BLOCKS";

/// Every array constant of the table.
pub fn all() -> impl Iterator<Item = &'static Constant> {
    NAMES.iter().chain(&TRIG).chain(&SENSITIVITY_TRIG)
}

/// Whether a generated constant is called `name`.
pub fn taken(name: &str) -> bool {
    name == SYMBOLIC || name == PSI_U_BLOCKS || all().any(|c| c.name == name)
}

impl Constant {
    /// The number of entries.
    pub fn dim<'a>(&self, dims: &'a Dims) -> &'a Dim {
        match self.per {
            Per::U => &dims.m,
            Per::V => &dims.f,
            Per::Point => &dims.np,
            Per::Param => &dims.k,
        }
    }

    fn element(&self) -> TokenStream {
        match self.entry {
            Entry::Name => quote!(&'static str),
            Entry::Flag => quote!(bool),
        }
    }

    /// The inherent item, documented: `pub const NAME: [T; n] = value;`.
    pub fn declare(&self, dims: &Dims, value: TokenStream) -> TokenStream {
        let (name, element) = (format_ident!("{}", self.name), self.element());
        let n = self.dim(dims).tokens();
        let doc = self.doc;
        let hidden = self.hidden.then(|| quote!(#[doc(hidden)]));
        quote! {
            #(#[doc = #doc])*
            #hidden
            pub const #name: [#element; #n] = #value;
        }
    }

    /// The trait's method that answers with this constant:
    /// `fn u_names(&self) -> [&'static str; m] { Self::U_NAMES }` (the
    /// points' names as a slice), or in the fallback an array of `""` or
    /// `false` of the dimension's size (the points: none).
    pub fn trait_method(&self, dims: &Dims, placeholder: bool) -> TokenStream {
        let method = format_ident!("{}", self.name.to_lowercase());
        let (name, element) = (format_ident!("{}", self.name), self.element());
        let n = self.dim(dims).tokens();
        let hidden = self.hidden.then(|| quote!(#[doc(hidden)]));
        let empty = match self.entry {
            Entry::Name => quote!(""),
            Entry::Flag => quote!(false),
        };
        let (ty, value) = match (self.per, placeholder) {
            (Per::Point, false) => (quote!(&'static [#element]), quote!(&Self::#name)),
            (Per::Point, true) => (quote!(&'static [#element]), quote!(&[])),
            (_, false) => (quote!([#element; #n]), quote!(Self::#name)),
            (_, true) => (quote!([#element; #n]), quote!([#empty; #n])),
        };
        quote! {
            #hidden
            #[inline]
            fn #method(&self) -> #ty {
                #value
            }
        }
    }

    /// The fallback's item, every entry `""` or `false`: in a trait impl
    /// (generic in the dimensions it leaves open) an array of the
    /// dimension's size; in the inherent impl an array where the size is
    /// known, else an empty slice.
    pub fn placeholder(&self, dims: &Dims, in_trait: bool) -> TokenStream {
        let (name, element) = (format_ident!("{}", self.name), self.element());
        let value = match self.entry {
            Entry::Name => quote!(""),
            Entry::Flag => quote!(false),
        };
        let dim = self.dim(dims);
        let n = dim.tokens();
        match (in_trait, dim.value()) {
            (true, _) => quote!(const #name: [#element; #n] = [#value; #n];),
            (false, Some(_)) => quote!(pub const #name: [#element; #n] = [#value; #n];),
            (false, None) => quote!(pub const #name: &'static [#element] = &[];),
        }
    }
}

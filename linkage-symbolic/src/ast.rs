//! Stage 1: the attribute and the struct, parsed into an IR that keeps spans.
//!
//! The attribute is split at its top-level commas and each piece parsed on
//! its own, so that one malformed entry does not hide the errors of the
//! others.

use crate::errors::Errors;
use crate::owner::Owner;
use proc_macro2::{Delimiter, Span, TokenStream, TokenTree};
use syn::spanned::Spanned;
use syn::{Expr, Ident};

/// A named point: `B = (x, y)`.
pub struct PointDef {
    pub name: Ident,
    /// `(x, y)`; `None` when they are malformed (already reported): the
    /// point's name is still known, so its uses report nothing more.
    pub coords: Option<(Expr, Expr)>,
}

/// A field of the struct.
pub struct Field {
    pub ident: Ident,
    pub is_f64: bool,
    /// The type as written, for messages.
    pub ty: String,
}

/// A bracketed list as written, with the span of its brackets.
pub struct List<T> {
    /// The entries that parsed (a malformed one is reported and left out).
    pub items: Vec<T>,
    /// The number of entries written, malformed ones included: the size
    /// the list was meant to have (0 for a list not given).
    pub written: usize,
    pub span: Span,
}

impl<T> List<T> {
    fn empty() -> List<T> {
        List {
            items: Vec::new(),
            written: 0,
            span: Span::call_site(),
        }
    }
}

impl List<Ident> {
    /// The number of names the list was meant to hold: its entries as
    /// written, a name already in `earlier` or earlier in the list counted
    /// once.
    pub fn meant(&self, earlier: &[Ident]) -> usize {
        let mut seen: Vec<String> = earlier.iter().map(unraw).collect();
        let repeated = (self.items.iter().map(unraw))
            .filter(|name| {
                let repeated = seen.contains(name);
                seen.push(name.clone());
                repeated
            })
            .count();
        self.written - repeated
    }
}

/// The parsed attribute and struct.
pub struct Input {
    pub item: syn::ItemStruct,
    /// Who the parameters belong to, for messages: the struct, or the
    /// mechanism the struct stands for at run time.
    pub owner: Owner,
    pub fields: Vec<Field>,
    pub u: List<Ident>,
    pub v: List<Ident>,
    pub points: List<PointDef>,
    pub closure: List<Expr>,
    /// The parameters to differentiate by, as written (`None`: every `f64`
    /// field the equations use).
    pub params: Option<List<Ident>>,
    /// The bracketed lists of `points` and `closure` as written, malformed
    /// entries included: where [`crate::params::count_as_written`] looks
    /// for the fields the equations name when they could not be lowered.
    pub equation_tokens: TokenStream,
    /// Whether `u`, `v` and `closure` were all given and well-formed (if
    /// not, the errors say why and the lists above are empty).
    pub complete: bool,
}

const KEYS: [&str; 5] = ["u", "v", "points", "closure", "params"];

impl Input {
    /// Parses the attribute and the struct; every problem found is recorded
    /// in `errors`, and `None` returned only when nothing usable is left.
    pub fn parse(attr: TokenStream, item: TokenStream, errors: &mut Errors) -> Option<Input> {
        Input::parse_owned_by(attr, item, |ident| Owner::Struct(ident.to_string()), errors)
    }

    /// [`Input::parse`], the messages naming the parameters' owner as
    /// `owner` words it (given the struct's name): a mechanism read at run
    /// time, whose struct only carries its parameters, is an
    /// [`Owner::Mechanism`].
    pub fn parse_owned_by(
        attr: TokenStream,
        item: TokenStream,
        owner: impl FnOnce(&Ident) -> Owner,
        errors: &mut Errors,
    ) -> Option<Input> {
        let item: syn::ItemStruct = match syn::parse2(item) {
            Ok(item) => item,
            Err(e) => {
                errors.push(syn::Error::new(
                    e.span(),
                    "#[linkage::linkage(...)] goes on a struct whose `f64` fields are the \
                     mechanism's parameters, e.g. `struct FourBar { l1: f64, l2: f64 }`",
                ));
                return None;
            }
        };
        let fields = parse_fields(&item, errors);
        let owner = owner(&item.ident);
        let mut u = None;
        let mut v = None;
        let mut points = None;
        let mut closure = None;
        let mut params = None;
        let mut equation_tokens = TokenStream::new();
        let mut seen: Vec<(String, Span)> = Vec::new();
        // Keys written, even malformed, or suggested for a misspelt key: no
        // "missing" error for them, the error on the key itself says it all.
        let mut attempted: Vec<String> = Vec::new();
        for chunk in split_commas(attr) {
            if let Some(TokenTree::Ident(first)) = chunk.clone().into_iter().next() {
                let first = first.to_string();
                if !KEYS.contains(&first.as_str()) {
                    attempted.extend(
                        crate::suggest::closest(&first, KEYS.iter().copied()).map(str::to_owned),
                    );
                }
                attempted.push(first);
            }
            let Some((key, value)) = parse_entry(&chunk, errors) else {
                continue;
            };
            let name = key.to_string();
            if let Some((_, first)) = seen.iter().find(|(k, _)| *k == name) {
                let mut e = syn::Error::new(key.span(), format!("`{name}` is given twice"));
                e.combine(syn::Error::new(*first, format!("first `{name}` is here")));
                errors.push(e);
                continue;
            }
            seen.push((name.clone(), key.span()));
            // The equations' tokens kept, the names' dropped.
            let tokens = &mut equation_tokens;
            match name.as_str() {
                "u" | "v" => {
                    let list = parse_names(
                        &key,
                        value,
                        errors,
                        "a coordinate is a plain name, e.g. `theta3`",
                    );
                    if name == "u" { u = list } else { v = list }
                }
                "points" => {
                    points = parse_list(&key, value, errors, parse_point).map(|(list, written)| {
                        tokens.extend([written]);
                        list
                    })
                }
                "closure" => {
                    closure = parse_list(&key, value, errors, parse_expr).map(|(list, written)| {
                        tokens.extend([written]);
                        list
                    })
                }
                "params" => {
                    let message = format!(
                        "a parameter is the name of {}, e.g. `l2`",
                        owner.a_parameter_of_it()
                    );
                    params = parse_names(&key, value, errors, &message)
                }
                other => {
                    let hint = match crate::suggest::closest(other, KEYS.iter().copied()) {
                        Some(k) => format!("; did you mean `{k}`?"),
                        None => String::new(),
                    };
                    errors.push(syn::Error::new(
                        key.span(),
                        format!(
                            "unknown key `{other}`: {} takes `u = [...]`, `v = [...]`, \
                             `closure = [...]` and optionally `points = [...]` and `params = [...]`{hint}",
                            owner.reader()
                        ),
                    ));
                }
            }
        }
        let call_site = Span::call_site();
        let mut require = |missing: bool, what: &str, example: &str| {
            if missing && !attempted.iter().any(|k| k == what) {
                errors.push(syn::Error::new(
                    call_site,
                    format!(
                        "missing `{what} = [...]` in {}, e.g. `{example}`",
                        owner.where_written()
                    ),
                ));
            }
        };
        require(u.is_none(), "u", "u = [theta3, theta4]");
        require(v.is_none(), "v", "v = [theta2]");
        require(closure.is_none(), "closure", "closure = [expr, expr]");
        let points = points.unwrap_or_else(List::empty);
        let complete = u.is_some() && v.is_some() && closure.is_some();
        Some(Input {
            item,
            owner,
            fields,
            u: u.unwrap_or_else(List::empty),
            v: v.unwrap_or_else(List::empty),
            points,
            closure: closure.unwrap_or_else(List::empty),
            params,
            equation_tokens,
            complete,
        })
    }
}

fn parse_fields(item: &syn::ItemStruct, errors: &mut Errors) -> Vec<Field> {
    match &item.fields {
        syn::Fields::Named(named) => named
            .named
            .iter()
            .filter_map(|f| {
                let ident = f.ident.clone()?;
                let ty = &f.ty;
                let is_f64 =
                    matches!(ty, syn::Type::Path(p) if p.qself.is_none() && p.path.is_ident("f64"));
                Some(Field {
                    ident,
                    is_f64,
                    ty: quote::quote!(#ty).to_string(),
                })
            })
            .collect(),
        syn::Fields::Unit => Vec::new(),
        syn::Fields::Unnamed(unnamed) => {
            errors.push(syn::Error::new(
                unnamed.span(),
                "the parameters of a #[linkage] struct are named `f64` fields \
                 (`struct FourBar { l1: f64, ... }`); a tuple struct has no names to use in equations",
            ));
            Vec::new()
        }
    }
}

/// Splits a token stream at its top-level commas (groups are atomic, so
/// commas inside brackets and parentheses stay). Empty pieces are dropped.
pub fn split_commas(tokens: TokenStream) -> Vec<TokenStream> {
    let mut out = Vec::new();
    let mut current = Vec::new();
    for tt in tokens {
        match &tt {
            TokenTree::Punct(p) if p.as_char() == ',' => {
                if !current.is_empty() {
                    out.push(current.drain(..).collect());
                }
            }
            _ => current.push(tt),
        }
    }
    if !current.is_empty() {
        out.push(current.into_iter().collect());
    }
    out
}

/// `key = value`
fn parse_entry(chunk: &TokenStream, errors: &mut Errors) -> Option<(Ident, Vec<TokenTree>)> {
    let mut iter = chunk.clone().into_iter();
    let key = match iter.next() {
        Some(TokenTree::Ident(i)) => i,
        _ => {
            errors.push(syn::Error::new_spanned(
                chunk,
                "expected `key = [...]` with a key among `u`, `v`, `points`, `closure`, `params`",
            ));
            return None;
        }
    };
    match iter.next() {
        Some(TokenTree::Punct(p)) if p.as_char() == '=' => {}
        other => {
            let span = other.map(|t| t.span()).unwrap_or_else(|| key.span());
            errors.push(syn::Error::new(
                span,
                format!("expected `=` after `{key}`, as in `{key} = [...]`"),
            ));
            return None;
        }
    }
    Some((key, iter.collect()))
}

/// `[a, b, c]` of names (`u`, `v`, `params`), `not_a_name` the message for
/// an entry that is not one. A single name written without its brackets,
/// `v = theta2`, is reported and read as `[theta2]`, so that the
/// mechanism's sizes stay known and nothing else is reported.
fn parse_names(
    key: &Ident,
    value: Vec<TokenTree>,
    errors: &mut Errors,
    not_a_name: &str,
) -> Option<List<Ident>> {
    if let [TokenTree::Ident(name)] = value.as_slice() {
        errors.push(syn::Error::new(
            name.span(),
            format!("`{key}` takes a bracketed list: `{key} = [{name}]`"),
        ));
        return Some(List {
            items: vec![name.clone()],
            written: 1,
            span: name.span(),
        });
    }
    let parse_name =
        |chunk: TokenStream, errors: &mut Errors| match syn::parse2::<Ident>(chunk.clone()) {
            Ok(i) => Some(i),
            Err(_) => {
                errors.push(syn::Error::new_spanned(chunk, not_a_name));
                None
            }
        };
    parse_list(key, value, errors, parse_name).map(|(list, _)| list)
}

/// `[a, b, c]`, each element parsed by `parse_item`; with the list as
/// written.
fn parse_list<T>(
    key: &Ident,
    value: Vec<TokenTree>,
    errors: &mut Errors,
    parse_item: impl Fn(TokenStream, &mut Errors) -> Option<T>,
) -> Option<(List<T>, TokenTree)> {
    let group = match value.as_slice() {
        [TokenTree::Group(g)] if g.delimiter() == Delimiter::Bracket => g.clone(),
        _ => {
            let message = format!("`{key}` takes a bracketed list: `{key} = [...]`");
            errors.push(if value.is_empty() {
                syn::Error::new(key.span(), message)
            } else {
                syn::Error::new_spanned(value.iter().cloned().collect::<TokenStream>(), message)
            });
            return None;
        }
    };
    let chunks = split_commas(group.stream());
    let written = chunks.len();
    let items = chunks
        .into_iter()
        .filter_map(|chunk| parse_item(chunk, errors))
        .collect();
    let list = List {
        items,
        written,
        span: group.span(),
    };
    Some((list, TokenTree::Group(group)))
}

fn parse_expr(chunk: TokenStream, errors: &mut Errors) -> Option<Expr> {
    match syn::parse2::<Expr>(chunk) {
        Ok(e) => Some(e),
        Err(e) => {
            errors.push(e);
            None
        }
    }
}

/// `B = (x, y)`. A malformed entry whose name can be read is kept, without
/// coordinates, so that its uses elsewhere report nothing more.
fn parse_point(chunk: TokenStream, errors: &mut Errors) -> Option<PointDef> {
    let tokens: Vec<TokenTree> = chunk.clone().into_iter().collect();
    let shape_error = |errors: &mut Errors| {
        errors.push(syn::Error::new_spanned(
            chunk.clone(),
            "a point is written `Name = (x, y)`, e.g. `B = (l2 * theta2.cos(), l2 * theta2.sin())`",
        ));
    };
    let name = match tokens.as_slice() {
        [TokenTree::Ident(name), TokenTree::Punct(eq), ..] if eq.as_char() == '=' => name.clone(),
        _ => {
            shape_error(errors);
            return None;
        }
    };
    let malformed = |name: Ident| Some(PointDef { name, coords: None });
    let coords = match &tokens[2..] {
        [TokenTree::Group(g)] if g.delimiter() == Delimiter::Parenthesis => g.clone(),
        _ => {
            shape_error(errors);
            return malformed(name);
        }
    };
    let parts: [TokenStream; 2] = match split_commas(coords.stream()).try_into() {
        Ok(parts) => parts,
        Err(parts) => {
            errors.push(syn::Error::new(
                coords.span(),
                format!(
                    "point `{name}` needs two coordinates `(x, y)`, found {}",
                    parts.len()
                ),
            ));
            return malformed(name);
        }
    };
    let [x, y] = parts.map(|part| parse_expr(part, errors));
    Some(PointDef {
        name,
        coords: x.zip(y),
    })
}

/// The name of an identifier without a raw prefix (`r#type` is `type`).
pub fn unraw(ident: &Ident) -> String {
    let s = ident.to_string();
    s.strip_prefix("r#").map(str::to_owned).unwrap_or(s)
}

//! The parameters p a model is differentiated by: the `params = [...]` of
//! the attribute, checked against the struct and the equations, or by
//! default every `f64` field the closure equations or the points use.

use crate::ast::Input;
use crate::ast::unraw;
use crate::dag::{Dag, Symbol};
use crate::errors::Errors;
use crate::lower::Lowered;

/// Sets `lowered.params`; every mistake of `params` is recorded in
/// `errors` with the span of the name.
pub fn resolve(input: &Input, lowered: &mut Lowered, errors: &mut Errors) {
    let used = used_params(lowered);
    let Some(list) = &input.params else {
        lowered.params = (0..lowered.fields.len() as u16)
            .filter(|&k| used[k as usize])
            .collect();
        return;
    };
    let owner = &input.owner;
    let usable: Vec<String> = (0..lowered.fields.len())
        .filter(|&k| used[k])
        .map(|k| lowered.field_name(k))
        .collect();
    let listing = if usable.is_empty() {
        format!("none: the equations use no {}", owner.parameter_kind())
    } else {
        usable.join(", ")
    };
    let mut params: Vec<u16> = Vec::new();
    let mut seen: Vec<(String, proc_macro2::Span)> = Vec::new();
    for ident in &list.items {
        let name = unraw(ident);
        if let Some((_, first)) = seen.iter().find(|(n, _)| *n == name) {
            let mut e = syn::Error::new(
                ident.span(),
                format!("`{name}` is listed twice in `params`"),
            );
            e.combine(syn::Error::new(*first, format!("first `{name}` is here")));
            errors.push(e);
            continue;
        }
        seen.push((name.clone(), ident.span()));
        let param = (0..lowered.fields.len()).find(|&k| lowered.field_name(k) == name);
        let message = match param {
            Some(k) if used[k] => {
                params.push(k as u16);
                continue;
            }
            Some(_) => format!(
                "`{name}` is {} that neither the closure equations nor \
                 the points use, so every derivative by it is zero; the parameters the \
                 equations use: {listing}",
                owner.a_member()
            ),
            None => {
                let field = input.fields.iter().find(|f| unraw(&f.ident) == name);
                let coordinate = lowered.coords.iter().any(|c| unraw(c) == name);
                let point = lowered.points.iter().any(|(p, _, _)| unraw(p) == name);
                if let Some(field) = field {
                    format!(
                        "field `{name}` of `{}` has type `{}`; only `f64` fields are \
                         parameters (the ones the equations use: {listing})",
                        owner.name(),
                        field.ty
                    )
                } else if coordinate {
                    format!(
                        "`{name}` is a coordinate, not a parameter: `params` lists {} \
                         (the ones the equations use: {listing})",
                        owner.parameters()
                    )
                } else if point {
                    format!(
                        "`{name}` is a point, not a parameter: `params` lists {} \
                         (the ones the equations use: {listing})",
                        owner.parameters()
                    )
                } else {
                    let hint =
                        match crate::suggest::closest(&name, usable.iter().map(String::as_str)) {
                            Some(close) => format!("; did you mean `{close}`?"),
                            None => String::new(),
                        };
                    format!(
                        "`{name}` is not {}: `params` lists {} \
                         the equations use ({listing}){hint}",
                        owner.a_member(),
                        owner.parameters_kind()
                    )
                }
            }
        };
        errors.push(syn::Error::new(ident.span(), message));
    }
    lowered.params = params;
}

/// The number of parameters the attribute asks for, read from what is
/// written even when it has mistakes (the items of the error path have the
/// sizes they would have without them): the entries of `params`, a name
/// listed twice counted once; or else the parameters [`resolve`] found,
/// `resolved`, when every equation and point was read and lowered; or
/// else, only then read from the tokens, every `f64` field the closure
/// equations or the points name (where a use that cancels, `l1 - l1`,
/// counts, which `resolve` leaves out). `None` when no closure equation is
/// written.
pub fn count_as_written(input: &Input, resolved: Option<usize>) -> Option<usize> {
    if let Some(list) = &input.params {
        return Some(list.meant(&[]));
    }
    if input.closure.written == 0 {
        return None;
    }
    let all_read = input.closure.items.len() == input.closure.written
        && input.points.items.len() == input.points.written
        && input.points.items.iter().all(|p| p.coords.is_some());
    if let Some(k) = resolved.filter(|_| all_read) {
        return Some(k);
    }
    // A coordinate or a point of the same name hides a field.
    let declared: Vec<String> = (input.u.items.iter())
        .chain(&input.v.items)
        .chain(input.points.items.iter().map(|p| &p.name))
        .map(unraw)
        .collect();
    let fields: Vec<String> = (input.fields.iter())
        .filter(|f| f.is_f64)
        .map(|f| unraw(&f.ident))
        .filter(|name| !declared.contains(name))
        .collect();
    let mut named = Vec::new();
    names_in(input.equation_tokens.clone(), &fields, &mut named);
    Some(named.len())
}

/// Adds to `named` each of `fields` that `tokens` names as a variable (not
/// after `.` or `::`: `B.x`, `theta2.cos()`, `consts::PI` are not fields).
fn names_in(tokens: proc_macro2::TokenStream, fields: &[String], named: &mut Vec<String>) {
    use proc_macro2::TokenTree;
    let mut after_path_or_dot = false;
    for tt in tokens {
        match &tt {
            TokenTree::Group(g) => names_in(g.stream(), fields, named),
            TokenTree::Ident(ident) => {
                let name = unraw(ident);
                if !after_path_or_dot && fields.contains(&name) && !named.contains(&name) {
                    named.push(name);
                }
            }
            TokenTree::Punct(_) | TokenTree::Literal(_) => {}
        }
        after_path_or_dot = matches!(&tt, TokenTree::Punct(p) if matches!(p.as_char(), '.' | ':'));
    }
}

/// Which parameters the closure equations or a point depend on.
fn used_params(lowered: &mut Lowered) -> Vec<bool> {
    let roots: Vec<_> = lowered
        .closure
        .iter()
        .copied()
        .chain(lowered.points.iter().flat_map(|(_, x, y)| [*x, *y]))
        .collect();
    (0..lowered.fields.len() as u16)
        .map(|k| {
            roots
                .iter()
                .any(|&r| lowered.dag.diff(r, Symbol::Param(k)) != Dag::ZERO)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::count_as_written;
    use crate::ast::Input;
    use crate::errors::Errors;
    use quote::quote;

    fn count(attr: proc_macro2::TokenStream) -> Option<usize> {
        let item = quote!(
            struct Bar {
                l1: f64,
                l2: f64,
                l3: f64,
                mass: f64,
                x: f64,
                label: u32,
            }
        );
        // As the error path asks: after the pipeline, with what it found.
        let mut errors = Errors::default();
        let input = Input::parse(attr, item, &mut errors).unwrap();
        let resolved = crate::build(&input, &mut errors)
            .err()
            .and_then(|unbuilt| unbuilt.params);
        count_as_written(&input, resolved)
    }

    /// Without `params`, the `f64` fields the equations or the points
    /// name (`mass` as a receiver too), whatever their mistakes; not a
    /// point's coordinate, a constant's path, a coordinate of the same
    /// name, or a field that is not `f64`.
    #[test]
    fn by_default_the_fields_the_equations_name() {
        let n = count(quote!(
            u = [theta3],
            v = [theta2],
            points = [B = (l3 * thta2.cos(), label * 1.0)],
            closure = [l1 * theta2.cos() + B.x + mass.cos() + l2 / std::f64::consts::PI - tht]
        ));
        assert_eq!(n, Some(4));
        let coordinate = count(quote!(u = [l1], v = [theta2], closure = [l1 + l2 * theta2]));
        assert_eq!(coordinate, Some(1));
        assert_eq!(count(quote!(u = [theta3], v = [theta2])), None);
    }

    /// Where the equations were lowered, the parameters `resolve` found,
    /// whatever the mistakes elsewhere: a field whose uses cancel is not
    /// one (here one equation for two coordinates of u). A malformed entry
    /// leaves the equations unread, and then every field they name counts.
    #[test]
    fn where_lowered_the_parameters_resolve_found() {
        let n = count(quote!(
            u = [theta3, x4],
            v = [theta2],
            closure = [l2 * theta2.cos() + l3 * theta3.cos() + l1 - l1]
        ));
        assert_eq!(n, Some(2));
        let malformed = count(quote!(
            u = [theta3, x4],
            v = [theta2],
            closure = [l2 * theta2.cos() + l3 * theta3.cos() + l1 - l1, mass +]
        ));
        assert_eq!(malformed, Some(4));
    }

    /// With `params`, its entries as written: a misspelt or malformed one
    /// counts, a name listed twice counts once.
    #[test]
    fn with_params_its_entries() {
        let n = count(quote!(
            u = [theta3],
            v = [theta2],
            closure = [l1 * theta3 + l2 * theta2],
            params = [l1, l22, l1, 3.0]
        ));
        assert_eq!(n, Some(3));
    }
}

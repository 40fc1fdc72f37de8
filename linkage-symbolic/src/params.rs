//! The parameters p a model is differentiated by: the `params = [...]` of
//! the attribute, checked against the struct and the equations, or by
//! default every `f64` field the closure equations or the points use.

use crate::ast::Input;
use crate::dag::{Dag, Symbol};
use crate::errors::Errors;
use crate::lower::{Lowered, unraw};

/// Sets `lowered.design`; every mistake of `params` is recorded in
/// `errors` with the span of the name.
pub fn resolve(input: &Input, lowered: &mut Lowered, errors: &mut Errors) {
    let used = used_params(lowered);
    let Some(list) = &input.params else {
        lowered.design = (0..lowered.params.len() as u16)
            .filter(|&k| used[k as usize])
            .collect();
        return;
    };
    let struct_name = &input.item.ident;
    let usable: Vec<String> = (0..lowered.params.len())
        .filter(|&k| used[k])
        .map(|k| lowered.param_name(k))
        .collect();
    let listing = if usable.is_empty() {
        "none: the equations use no `f64` field".to_owned()
    } else {
        usable.join(", ")
    };
    let mut design: Vec<u16> = Vec::new();
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
        let param = (0..lowered.params.len()).find(|&k| lowered.param_name(k) == name);
        let message = match param {
            Some(k) if used[k] => {
                design.push(k as u16);
                continue;
            }
            Some(_) => format!(
                "`{name}` is a field of `{struct_name}` that neither the closure equations nor \
                 the points use, so every derivative by it is zero; the parameters the \
                 equations use: {listing}"
            ),
            None => {
                let field = input.fields.iter().find(|f| unraw(&f.ident) == name);
                let coordinate = lowered.coords.iter().any(|c| unraw(c) == name);
                let point = lowered.points.iter().any(|(p, _, _)| unraw(p) == name);
                if let Some(field) = field {
                    format!(
                        "field `{name}` of `{struct_name}` has type `{}`; only `f64` fields are \
                         parameters (the ones the equations use: {listing})",
                        field.ty
                    )
                } else if coordinate {
                    format!(
                        "`{name}` is a coordinate, not a parameter: `params` lists `f64` fields \
                         of `{struct_name}` (the ones the equations use: {listing})"
                    )
                } else if point {
                    format!(
                        "`{name}` is a point, not a parameter: `params` lists `f64` fields of \
                         `{struct_name}` (the ones the equations use: {listing})"
                    )
                } else {
                    let hint =
                        match crate::suggest::closest(&name, usable.iter().map(String::as_str)) {
                            Some(close) => format!("; did you mean `{close}`?"),
                            None => String::new(),
                        };
                    format!(
                        "`{name}` is not a field of `{struct_name}`: `params` lists `f64` fields \
                         the equations use ({listing}){hint}"
                    )
                }
            }
        };
        errors.push(syn::Error::new(ident.span(), message));
    }
    lowered.design = design;
}

/// Which parameters the closure equations or a point depend on.
fn used_params(lowered: &mut Lowered) -> Vec<bool> {
    let roots: Vec<_> = lowered
        .closure
        .iter()
        .copied()
        .chain(lowered.points.iter().flat_map(|(_, x, y)| [*x, *y]))
        .collect();
    (0..lowered.params.len() as u16)
        .map(|k| {
            roots
                .iter()
                .any(|&r| lowered.dag.diff(r, Symbol::Param(k)) != Dag::ZERO)
        })
        .collect()
}

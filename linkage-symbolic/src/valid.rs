//! Pure checks: the shape of the attribute (non-empty lists, one equation per
//! dependent coordinate) and the structural rank of Ψ_u.

use crate::ast::Input;
use crate::ast::unraw;
use crate::dag::{Dag, Symbol};
use crate::errors::Errors;
use crate::lower::Lowered;

/// Checks that do not need the equations' meaning. Returns whether the
/// shape is right (the structural check needs it).
pub fn check_shape(input: &Input, errors: &mut Errors) -> bool {
    let mut ok = true;
    for (list_empty, span, what, example) in [
        (
            input.u.items.is_empty(),
            input.u.span,
            "u",
            "the dependent coordinates, e.g. `u = [theta3, theta4]`",
        ),
        (
            input.v.items.is_empty(),
            input.v.span,
            "v",
            "the driving coordinates, e.g. `v = [theta2]`",
        ),
        (
            input.closure.items.is_empty(),
            input.closure.span,
            "closure",
            "one closure equation Ψᵢ(u, v) = 0 per coordinate of u, written as the expression Ψᵢ",
        ),
    ] {
        if list_empty {
            errors.push(syn::Error::new(
                span,
                format!("`{what}` is empty; it lists {example}"),
            ));
            ok = false;
        }
    }
    let (m, equations) = (input.u.items.len(), input.closure.items.len());
    if m > 0 && equations > 0 && m != equations {
        errors.push(syn::Error::new(
            input.closure.span,
            format!(
                "{equations} closure equation{} for {m} dependent coordinate{} in `u`: \
                 there must be exactly one equation per coordinate of `u` (Ψ_u must be square)",
                plural(equations),
                plural(m)
            ),
        ));
        ok = false;
    }
    ok
}

fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}

/// Structural rank of Ψ_u: every coordinate of u must appear in some
/// equation, every equation must involve some coordinate of u, and there
/// must be a perfect matching of equations to coordinates in the incidence
/// pattern of Ψ_u (else det Ψ_u ≡ 0 whatever the parameters).
#[allow(clippy::needless_range_loop)] // rows and columns of the incidence matrix
pub fn check_structure(input: &Input, lowered: &mut Lowered, errors: &mut Errors) {
    let m = lowered.m;
    let incidence: Vec<Vec<bool>> = (0..m)
        .map(|i| {
            (0..m)
                .map(|k| {
                    lowered
                        .dag
                        .diff(lowered.closure[i], Symbol::Coord(k as u16))
                        != Dag::ZERO
                })
                .collect()
        })
        .collect();
    let name = |k: usize| format!("`{}`", unraw(&input.u.items[k]));
    let mut found = false;
    for k in 0..m {
        if (0..m).all(|i| !incidence[i][k]) {
            errors.push(syn::Error::new(
                input.u.items[k].span(),
                format!(
                    "Ψ_u is structurally singular: the coordinate {} appears in no closure equation \
                     (∂Ψ/∂{} = 0), so it cannot be solved for; use it in an equation or remove it from `u`",
                    name(k),
                    unraw(&input.u.items[k])
                ),
            ));
            found = true;
        }
    }
    for i in 0..m {
        if incidence[i].iter().all(|&x| !x) {
            errors.push(syn::Error::new_spanned(
                &input.closure.items[i],
                format!(
                    "Ψ_u is structurally singular: closure equation {} involves no coordinate of `u`, \
                     so it does not constrain them",
                    i + 1
                ),
            ));
            found = true;
        }
    }
    if found {
        return;
    }
    if let Some((coords, equations)) = hall_violator(&incidence) {
        let coord_list = coords
            .iter()
            .map(|&k| name(k))
            .collect::<Vec<_>>()
            .join(", ");
        let eq_list = match equations.as_slice() {
            [one] => format!("equation {}", one + 1),
            more => format!(
                "equations {}",
                more.iter()
                    .map(|i| (i + 1).to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        errors.push(syn::Error::new(
            input.u.items[coords[0]].span(),
            format!(
                "Ψ_u is structurally singular: the coordinates {coord_list} appear only in {eq_list} \
                 of `closure` ({} coordinates, {} equation{}), so no pairing of one equation per \
                 coordinate exists and det Ψ_u ≡ 0 whatever the parameters; add an equation that \
                 involves them, or move one of them to `v`",
                coords.len(),
                equations.len(),
                plural(equations.len()),
            ),
        ));
    }
}

/// A maximum matching of equations (rows) to coordinates (columns) by
/// augmenting paths; if it is not perfect, a set S of coordinates with fewer
/// equations N(S) than coordinates (Hall's condition violated): both sorted.
fn hall_violator(incidence: &[Vec<bool>]) -> Option<(Vec<usize>, Vec<usize>)> {
    let m = incidence.len();
    let row_of_col = crate::blocks::maximum_matching(incidence);
    let unmatched = (0..m).find(|&c| row_of_col[c].is_none())?;
    // Alternating search from the unmatched column: column → its rows →
    // the columns those rows are matched to.
    let mut cols = vec![unmatched];
    let mut rows: Vec<usize> = Vec::new();
    let mut k = 0;
    while k < cols.len() {
        let c = cols[k];
        for (r, row) in incidence.iter().enumerate() {
            if row[c] && !rows.contains(&r) {
                rows.push(r);
                if let Some(c2) = (0..m).find(|&c2| row_of_col[c2] == Some(r)) {
                    if !cols.contains(&c2) {
                        cols.push(c2);
                    }
                }
            }
        }
        k += 1;
    }
    cols.sort_unstable();
    rows.sort_unstable();
    Some((cols, rows))
}

#[cfg(test)]
mod tests {
    use super::hall_violator;

    #[test]
    fn perfect_matching_exists() {
        let inc = vec![vec![true, true], vec![true, false]];
        assert_eq!(hall_violator(&inc), None);
    }

    #[test]
    fn two_coordinates_in_one_equation() {
        // x and y appear only in equation 0; equation 1 and 2 only have z.
        let inc = vec![
            vec![true, true, true],
            vec![false, false, true],
            vec![false, false, true],
        ];
        let (cols, rows) = hall_violator(&inc).unwrap();
        assert!(rows.len() < cols.len());
        let inc2 = vec![
            vec![true, true, false],
            vec![false, false, true],
            vec![false, false, true],
        ];
        let (cols, rows) = hall_violator(&inc2).unwrap();
        assert_eq!((cols, rows), (vec![0, 1], vec![0]));
    }
}

//! The expanded normal form: an expression multiplied out into a sum of
//! monomials `c·Π aᵢ^eᵢ`, where the atoms `aᵢ` are symbols and function
//! calls. Two expressions with the same normal form are the same polynomial
//! in their atoms; this is how the macro proves, at compile time, that the
//! two acceleration methods give the same γ. The emitted code never uses it:
//! multiplying out destroys sharing.

use crate::dag::{Dag, Id, Node};
use std::collections::HashMap;

/// Expansions larger than this many monomials are abandoned.
const LIMIT: usize = 20_000;

/// A polynomial: monomial → coefficient, sorted by monomial.
pub type Polynomial = Vec<(Id, f64)>;

/// The normal form of `id`, or `None` if it exceeds the size limit.
pub fn expand(dag: &mut Dag, id: Id) -> Option<Polynomial> {
    let mut memo = HashMap::new();
    let terms = terms(dag, id, &mut memo)?;
    Some(collect(terms))
}

/// `expand`, rebuilt into a node (the canonical sum of its monomials).
pub fn expand_node(dag: &mut Dag, id: Id) -> Option<Id> {
    let p = expand(dag, id)?;
    Some(dag.sum(p.into_iter().map(|(m, c)| (c, m))))
}

/// Whether two polynomials are equal, coefficient by coefficient, to within
/// a relative `1e-12` (coefficients come from exact small integers and
/// powers, so equality is in practice exact).
pub fn same(a: &Polynomial, b: &Polynomial) -> bool {
    let mut map: HashMap<Id, (f64, f64)> = HashMap::new();
    for &(m, c) in a {
        map.entry(m).or_default().0 += c;
    }
    for &(m, c) in b {
        map.entry(m).or_default().1 += c;
    }
    map.values()
        .all(|&(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(y.abs()))
}

fn collect(terms: Vec<(f64, Id)>) -> Polynomial {
    let mut map: HashMap<Id, f64> = HashMap::new();
    for (c, m) in terms {
        *map.entry(m).or_default() += c;
    }
    let scale = map.values().fold(0.0_f64, |a, c| a.max(c.abs()));
    let mut out: Polynomial = map
        .into_iter()
        .filter(|&(_, c)| c.abs() > 1e-14 * scale)
        .collect();
    out.sort_by_key(|&(m, _)| m);
    out
}

fn terms(dag: &mut Dag, id: Id, memo: &mut HashMap<Id, Vec<(f64, Id)>>) -> Option<Vec<(f64, Id)>> {
    if let Some(t) = memo.get(&id) {
        return Some(t.clone());
    }
    let out = match dag.node(id).clone() {
        Node::Const(c) => vec![(c.get(), Dag::ONE)],
        Node::Sym(_) | Node::Call(..) | Node::Call2(..) => vec![(1.0, id)],
        Node::Sum(ts) => {
            let mut out = Vec::new();
            for (c, t) in ts {
                for (ci, mi) in terms(dag, t, memo)? {
                    out.push((c.get() * ci, mi));
                }
            }
            out
        }
        Node::Prod(factors) => {
            let mut acc = vec![(1.0, Dag::ONE)];
            for (f, e) in factors {
                let factor = if e > 0 {
                    let base = terms(dag, f, memo)?;
                    power(dag, &base, e)?
                } else {
                    vec![(1.0, dag.powi(f, e))]
                };
                acc = multiply(dag, &acc, &factor)?;
            }
            acc
        }
    };
    if out.len() > LIMIT {
        return None;
    }
    memo.insert(id, out.clone());
    Some(out)
}

/// The product of two expanded polynomials, collected, or `None` past the
/// size limit.
fn multiply(dag: &mut Dag, a: &[(f64, Id)], b: &[(f64, Id)]) -> Option<Vec<(f64, Id)>> {
    if a.len() * b.len() > LIMIT {
        return None;
    }
    let mut next = Vec::with_capacity(a.len() * b.len());
    for &(ca, ma) in a {
        for &(cb, mb) in b {
            let product = dag.mul(ma, mb);
            let (c, m) = dag.split_coefficient(product);
            next.push((ca * cb * c, m));
        }
    }
    Some(collect(next).into_iter().map(|(m, c)| (c, m)).collect())
}

/// `base^e` for `e ≥ 1`, expanded: a monomial directly (`(c·m)^e =
/// c^e·m^e`, abandoned if `c^e` is not a finite nonzero number), a sum by
/// repeated multiplication — abandoned at once if `e` exceeds the size
/// limit, since a sum of two or more terms to the `e`-th power has at
/// least `e + 1` of them.
fn power(dag: &mut Dag, base: &[(f64, Id)], e: i32) -> Option<Vec<(f64, Id)>> {
    if let [(c, m)] = base {
        let coefficient = c.powi(e);
        if !coefficient.is_normal() {
            return None;
        }
        let raised = dag.powi(*m, e);
        let (k, monomial) = dag.split_coefficient(raised);
        return Some(vec![(coefficient * k, monomial)]);
    }
    if usize::try_from(e).ok()? > LIMIT {
        return None;
    }
    let mut acc = base.to_vec();
    for _ in 1..e {
        acc = multiply(dag, &acc, base)?;
    }
    Some(acc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dag::{Func, Symbol};

    #[test]
    fn multiplies_out() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        // (x + y)² and x² + 2xy + y²
        let s = dag.add(x, y);
        let sq = dag.powi(s, 2);
        let x2 = dag.powi(x, 2);
        let y2 = dag.powi(y, 2);
        let xy = dag.mul(x, y);
        let poly = dag.sum([(1.0, x2), (2.0, xy), (1.0, y2)]);
        let a = expand(&mut dag, sq).unwrap();
        let b = expand(&mut dag, poly).unwrap();
        assert!(same(&a, &b));
        assert_ne!(sq, poly);
    }

    #[test]
    fn huge_powers_are_immediate_or_abandoned() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        // (x^65536)^65536: the exponents overflow i32, the factor stays
        // nested, and its normal form is one monomial, found at once.
        let big = dag.powi(x, 65536);
        let bigger = dag.powi(big, 65536);
        let p = expand(&mut dag, bigger).unwrap();
        assert_eq!(p.len(), 1);
        // (x + y)^65536 has 65537 terms: past the limit, abandoned at once.
        let s = dag.add(x, y);
        let sp = dag.powi(s, 65536);
        assert!(expand(&mut dag, sp).is_none());
        // (x + y)^3 still multiplies out: x³ + 3x²y + 3xy² + y³.
        let cube = dag.powi(s, 3);
        let p = expand(&mut dag, cube).unwrap();
        let mut coefficients: Vec<f64> = p.iter().map(|&(_, c)| c).collect();
        coefficients.sort_by(f64::total_cmp);
        assert_eq!(coefficients, [1.0, 1.0, 3.0, 3.0]);
    }

    #[test]
    fn atoms_stay_atoms() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let s = dag.call(Func::Sin, x);
        let p = expand(&mut dag, s).unwrap();
        assert_eq!(p, vec![(s, 1.0)]);
    }
}

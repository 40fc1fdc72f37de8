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

/// The work an expansion may do, in monomials multiplied or copied: past
/// it, the expansion is abandoned. The size limit alone bounds each
/// product, not how many there are: `(x.sin() + y).powi(1024)` is 1023
/// products of up to a thousand terms each, and γ holds several such —
/// seconds (7 s for a run-time mechanism), for a proof that is then too
/// large to use. The 13 mechanism files each prove A = B with at most 534;
/// this much takes about 0.2 s.
pub const WORK: usize = 100_000;

/// What is left of the work an expansion (or several, sharing it) may do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget(pub usize);

impl Budget {
    /// Takes `n` units of work, or `None` if there is not that much left.
    fn spend(&mut self, n: usize) -> Option<()> {
        self.0 = self.0.checked_sub(n)?;
        Some(())
    }
}

impl Default for Budget {
    fn default() -> Budget {
        Budget(WORK)
    }
}

/// A polynomial: monomial → coefficient, sorted by monomial.
pub type Polynomial = Vec<(Id, f64)>;

/// The normal form of `id`, or `None` if it exceeds the size limit or the
/// work allowed.
pub fn expand(dag: &mut Dag, id: Id) -> Option<Polynomial> {
    expand_within(dag, id, &mut Budget::default())
}

/// [`expand`], the work taken from `budget` (shared by several
/// expansions: what they may do together).
pub fn expand_within(dag: &mut Dag, id: Id, budget: &mut Budget) -> Option<Polynomial> {
    let mut memo = HashMap::new();
    let terms = terms(dag, id, &mut memo, budget)?;
    collect(terms)
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

/// Like terms added up. A sum that cancels to within rounding of the
/// largest term that went into it (1e-14 of it) is dropped; a small
/// coefficient that did not cancel is kept, however small beside the
/// others. `None` if a sum overflows.
fn collect(terms: Vec<(f64, Id)>) -> Option<Polynomial> {
    let mut map: HashMap<Id, (f64, f64)> = HashMap::new();
    for (c, m) in terms {
        let entry = map.entry(m).or_default();
        entry.0 += c;
        entry.1 = entry.1.max(c.abs());
    }
    let mut out: Polynomial = Vec::with_capacity(map.len());
    for (m, (sum, largest)) in map {
        if !sum.is_finite() {
            return None;
        }
        if sum.abs() > 1e-14 * largest {
            out.push((m, sum));
        }
    }
    out.sort_by_key(|&(m, _)| m);
    Some(out)
}

fn terms(
    dag: &mut Dag,
    id: Id,
    memo: &mut HashMap<Id, Vec<(f64, Id)>>,
    budget: &mut Budget,
) -> Option<Vec<(f64, Id)>> {
    if let Some(t) = memo.get(&id) {
        budget.spend(t.len())?;
        return Some(t.clone());
    }
    let out = match dag.node(id).clone() {
        Node::Const(c) if c.get() == 0.0 => Vec::new(),
        Node::Const(c) => vec![(finite_coefficient(c.get())?, Dag::ONE)],
        Node::Sym(_) | Node::Call(..) | Node::Call2(..) => vec![(1.0, id)],
        Node::Sum(ts) => {
            let mut out = Vec::new();
            for (c, t) in ts {
                for (ci, mi) in terms(dag, t, memo, budget)? {
                    out.push((finite_coefficient(c.get() * ci)?, mi));
                }
            }
            out
        }
        Node::Prod(factors) => {
            let mut acc = vec![(1.0, Dag::ONE)];
            for (f, e) in factors {
                let factor = if e > 0 {
                    let base = terms(dag, f, memo, budget)?;
                    power(dag, &base, e, budget)?
                } else {
                    vec![(1.0, dag.powi(f, e))]
                };
                acc = multiply(dag, &acc, &factor, budget)?;
            }
            acc
        }
    };
    if out.len() > LIMIT {
        return None;
    }
    budget.spend(out.len())?;
    memo.insert(id, out.clone());
    Some(out)
}

/// The product of two expanded polynomials, collected, or `None` past the
/// size limit or the work left.
fn multiply(
    dag: &mut Dag,
    a: &[(f64, Id)],
    b: &[(f64, Id)],
    budget: &mut Budget,
) -> Option<Vec<(f64, Id)>> {
    if a.len() * b.len() > LIMIT {
        return None;
    }
    budget.spend(a.len() * b.len())?;
    let mut next = Vec::with_capacity(a.len() * b.len());
    for &(ca, ma) in a {
        for &(cb, mb) in b {
            let product = dag.mul(ma, mb);
            let (c, m) = dag.split_coefficient(product);
            next.push((finite_coefficient(ca * cb * c)?, m));
        }
    }
    Some(collect(next)?.into_iter().map(|(m, c)| (c, m)).collect())
}

/// A coefficient that is a finite, nonzero and normal number; anything else
/// (an overflow, or an underflow of nonzero factors) abandons the expansion,
/// which must never claim two different expressions equal.
fn finite_coefficient(c: f64) -> Option<f64> {
    c.is_normal().then_some(c)
}

/// `base^e` for `e ≥ 1`, expanded: a monomial directly (`(c·m)^e =
/// c^e·m^e`, abandoned if `c^e` is not a finite nonzero number), a sum by
/// repeated multiplication — abandoned at once if `e` exceeds the size
/// limit, since a sum of two or more terms to the `e`-th power has at
/// least `e + 1` of them.
fn power(dag: &mut Dag, base: &[(f64, Id)], e: i32, budget: &mut Budget) -> Option<Vec<(f64, Id)>> {
    if e < 1 {
        return None;
    }
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
        acc = multiply(dag, &acc, base, budget)?;
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
    fn overflowing_coefficients_abandon_instead_of_vanishing() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        let z = dag.sym(Symbol::Coord(2));
        // (x + y)^2000: binomial coefficients overflow f64.
        let s = dag.add(x, y);
        let big = dag.powi(s, 2000);
        assert!(expand(&mut dag, big).is_none());
        // (1e200·x + 1e200·y)² and (1e200·x + 1e200·z)² are not the same:
        // their coefficients overflow, and neither may expand to the zero
        // polynomial (which would call them equal); both are abandoned.
        let c = dag.num(1e200);
        let cx = dag.mul(c, x);
        let cy = dag.mul(c, y);
        let cz = dag.mul(c, z);
        let a = dag.add(cx, cy);
        let b = dag.add(cx, cz);
        let ab = dag.mul(a, a);
        let bb = dag.mul(b, b);
        assert!(expand(&mut dag, ab).is_none());
        assert!(expand(&mut dag, bb).is_none());
    }

    #[test]
    fn small_coefficients_that_did_not_cancel_stay() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        // (x + y)^50: x⁵⁰ has coefficient 1 beside C(50, 25) ≈ 1.3e14.
        let s = dag.add(x, y);
        let p50 = dag.powi(s, 50);
        let p = expand(&mut dag, p50).unwrap();
        assert_eq!(p.len(), 51);
        let x50 = dag.powi(x, 50);
        let ends = p.iter().find(|&&(m, _)| m == x50).map(|&(_, c)| c);
        assert_eq!(ends, Some(1.0));
    }

    /// Within the size limit but past the work: `(x + y)^1024` has 1025
    /// terms, and 1023 products to make them, half a million monomials;
    /// abandoned. A budget shared by two expansions is spent by the first.
    #[test]
    fn long_work_is_abandoned() {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        let s = dag.add(x, y);
        let long = dag.powi(s, 1024);
        assert!(expand(&mut dag, long).is_none());
        let mut budget = Budget(WORK);
        let p300 = dag.powi(s, 300);
        assert_eq!(
            expand_within(&mut dag, p300, &mut budget).map(|p| p.len()),
            Some(301)
        );
        assert!(budget.0 < WORK / 2);
        assert!(expand_within(&mut dag, p300, &mut budget).is_none());
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

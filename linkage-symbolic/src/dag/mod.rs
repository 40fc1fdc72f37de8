//! The hash-consed expression DAG and its simplifying constructors.
//!
//! Every distinct subexpression is stored once; a node is referred to by its
//! [`Id`], and children are always created before their parents, so `Id`
//! order is a topological order.
//!
//! The constructors keep expressions in a canonical form, which is what lets
//! hash-consing find shared subexpressions:
//!
//! * a sum is `Σ cᵢ·tᵢ` with numeric coefficients, terms sorted by id, like
//!   terms collected (`x − x` vanishes, `x + x = 2·x`) and the constant term
//!   stored as a coefficient of the node `1`;
//! * a product is `Π fᵢ^eᵢ` with integer exponents, factors sorted by id,
//!   equal bases merged; a numeric factor is pulled out as the coefficient of
//!   a one-term sum (`2·x·y` is the sum `2·(x·y)`);
//! * nested sums and products are flattened, constants folded, and `0`/`1`
//!   identities applied.
//!
//! Every rewrite is exact in floating point or changes a value by at most a
//! rounding: a sum is flattened into its parent only when its coefficient is a
//! power of two, because `0.1·(a − b)` and `0.1·a − 0.1·b` differ badly when
//! `a ≈ b`.

use crate::hasher::FastMap;

mod atoms;

pub use atoms::{Constant, Func, Func2, Id, Node, Num, Symbol};

/// The expression DAG: an arena of unique nodes.
#[derive(Clone, Default)]
pub struct Dag {
    nodes: Vec<Node>,
    index: FastMap<Node, Id>,
    derivatives: FastMap<(Id, Symbol), Id>,
}

impl Dag {
    /// The node `0`.
    pub const ZERO: Id = Id(0);
    /// The node `1`.
    pub const ONE: Id = Id(1);

    pub fn new() -> Dag {
        let mut dag = Dag::default();
        let zero = dag.intern(Node::Const(Num::new(0.0)));
        let one = dag.intern(Node::Const(Num::new(1.0)));
        debug_assert_eq!((zero, one), (Dag::ZERO, Dag::ONE));
        dag
    }

    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.index()]
    }

    /// How many distinct nodes the DAG holds.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the DAG holds no node (never, once built: it starts with
    /// the constants 0 and 1).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.index.get(&node) {
            return id;
        }
        let id = Id(u32::try_from(self.nodes.len()).expect("fewer than 2³² nodes"));
        self.nodes.push(node.clone());
        self.index.insert(node, id);
        id
    }

    /// The numeric value of a constant node.
    pub fn as_const(&self, id: Id) -> Option<f64> {
        match self.node(id) {
            Node::Const(c) => Some(c.get()),
            _ => None,
        }
    }

    /// A numeric constant. A non-finite value cannot be a node; callers fold
    /// only when the result is finite.
    pub fn num(&mut self, x: f64) -> Id {
        self.intern(Node::Const(Num::new(x)))
    }

    pub fn sym(&mut self, s: Symbol) -> Id {
        self.intern(Node::Sym(s))
    }

    /// Splits a node into its numeric coefficient and the rest:
    /// `c·x ↦ (c, x)`, `x ↦ (1, x)`.
    pub fn split_coefficient(&self, id: Id) -> (f64, Id) {
        match self.node(id) {
            Node::Sum(terms) if terms.len() == 1 => (terms[0].0.get(), terms[0].1),
            Node::Const(c) => (c.get(), Dag::ONE),
            _ => (1.0, id),
        }
    }

    /// `Σ cᵢ·tᵢ`, simplified.
    pub fn sum(&mut self, terms: impl IntoIterator<Item = (f64, Id)>) -> Id {
        let mut constant = 0.0;
        let mut flat: Vec<(f64, Id)> = Vec::new();
        let mut work: Vec<(f64, Id)> = terms.into_iter().collect();
        work.reverse();
        while let Some((c, id)) = work.pop() {
            if c == 0.0 {
                continue;
            }
            match self.node(id) {
                Node::Const(k) if (constant + c * k.get()).is_finite() => {
                    constant += c * k.get();
                }
                Node::Sum(inner)
                    if (inner.len() == 1 || is_exact_scale(c))
                        && inner
                            .iter()
                            .all(|&(ci, _)| scales_exactly_enough(c, ci.get())) =>
                {
                    for &(ci, ti) in inner.iter().rev() {
                        work.push((c * ci.get(), ti));
                    }
                }
                _ => flat.push((c, id)),
            }
        }
        flat.sort_by_key(|&(_, id)| id);
        let mut merged: Vec<(Num, Id)> = Vec::with_capacity(flat.len() + 1);
        let mut i = 0;
        while i < flat.len() {
            let id = flat[i].1;
            let mut c = 0.0;
            while i < flat.len() && flat[i].1 == id {
                c += flat[i].0;
                i += 1;
            }
            if c != 0.0 && c.is_finite() {
                merged.push((Num::new(c), id));
            } else if !c.is_finite() {
                // An overflowing coefficient is kept as two terms rather than
                // turned into infinity.
                for &(cj, _) in flat.iter().filter(|t| t.1 == id) {
                    merged.push((Num::new(cj), id));
                }
            }
        }
        if constant != 0.0 && constant.is_finite() {
            merged.push((Num::new(constant), Dag::ONE));
            merged.sort_by_key(|&(_, id)| id);
        }
        match merged.as_slice() {
            [] => Dag::ZERO,
            [(c, id)] if c.get() == 1.0 => *id,
            [(c, id)] if *id == Dag::ONE => self.num(c.get()),
            _ => self.intern(Node::Sum(merged)),
        }
    }

    pub fn add(&mut self, a: Id, b: Id) -> Id {
        self.sum([(1.0, a), (1.0, b)])
    }

    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        self.sum([(1.0, a), (-1.0, b)])
    }

    pub fn neg(&mut self, a: Id) -> Id {
        self.sum([(-1.0, a)])
    }

    pub fn scale(&mut self, c: f64, a: Id) -> Id {
        self.sum([(c, a)])
    }

    /// `Π fᵢ^eᵢ`, simplified; a numeric factor becomes a coefficient.
    pub fn product(&mut self, factors: impl IntoIterator<Item = (Id, i32)>) -> Id {
        let mut coefficient = 1.0_f64;
        let mut flat: Vec<(Id, i32)> = Vec::new();
        let mut work: Vec<(Id, i32)> = factors.into_iter().collect();
        work.reverse();
        while let Some((id, e)) = work.pop() {
            if e == 0 {
                continue;
            }
            match self.node(id) {
                Node::Const(k) => {
                    let k = k.get();
                    let p = coefficient * k.powi(e);
                    if p.is_finite() && (p != 0.0 || k == 0.0) {
                        coefficient = p;
                    } else {
                        // k^e over- or underflows: keep the factor symbolic.
                        flat.push((id, e));
                    }
                }
                Node::Prod(inner) => {
                    let inner = inner.clone();
                    for (fi, ei) in inner.into_iter().rev() {
                        match ei.checked_mul(e) {
                            Some(p) => work.push((fi, p)),
                            None => {
                                flat.push((id, e));
                                break;
                            }
                        }
                    }
                }
                Node::Sum(terms) if terms.len() == 1 && terms[0].1 != Dag::ONE => {
                    let (c, inner) = (terms[0].0.get(), terms[0].1);
                    let p = coefficient * c.powi(e);
                    if p.is_finite() && p != 0.0 {
                        coefficient = p;
                        work.push((inner, e));
                    } else {
                        flat.push((id, e));
                    }
                }
                _ => flat.push((id, e)),
            }
        }
        if coefficient == 0.0 {
            return Dag::ZERO;
        }
        flat.sort_by_key(|&(id, _)| id);
        let mut merged: Vec<(Id, i32)> = Vec::with_capacity(flat.len());
        let mut i = 0;
        while i < flat.len() {
            let id = flat[i].0;
            let mut e: i32 = 0;
            let start = i;
            let mut overflow = false;
            while i < flat.len() && flat[i].0 == id {
                match e.checked_add(flat[i].1) {
                    Some(s) => e = s,
                    None => overflow = true,
                }
                i += 1;
            }
            if overflow {
                merged.extend_from_slice(&flat[start..i]);
            } else if e != 0 {
                merged.push((id, e));
            }
        }
        let rest = match merged.as_slice() {
            [] => Dag::ONE,
            [(id, 1)] => *id,
            _ => self.intern(Node::Prod(merged)),
        };
        self.scale(coefficient, rest)
    }

    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        self.product([(a, 1), (b, 1)])
    }

    pub fn div(&mut self, a: Id, b: Id) -> Id {
        self.product([(a, 1), (b, -1)])
    }

    pub fn powi(&mut self, a: Id, n: i32) -> Id {
        if n == 0 {
            return Dag::ONE;
        }
        self.product([(a, n)])
    }

    /// `x = s·y` with `s = ±1` and `y` in a canonical sign: a one-term sum
    /// with a positive coefficient, or a sum whose first term is positive.
    fn split_sign(&mut self, x: Id) -> (bool, Id) {
        match self.node(x) {
            Node::Sum(terms) if terms[0].0.get() < 0.0 => {
                let negated = self.neg(x);
                (true, negated)
            }
            Node::Const(c) if c.get() < 0.0 => {
                let c = c.get();
                (true, self.num(-c))
            }
            _ => (false, x),
        }
    }

    /// `f(x)`, folded when `x` is a constant and the value is finite, and
    /// with the sign of `x` pulled out of odd and even functions.
    pub fn call(&mut self, f: Func, x: Id) -> Id {
        if let Some(c) = self.as_const(x) {
            let y = f.eval(c);
            if y.is_finite() {
                return self.num(y);
            }
        }
        if f.is_odd() || f.is_even() {
            let (negative, y) = self.split_sign(x);
            if negative {
                let fy = self.intern(Node::Call(f, y));
                return if f.is_odd() { self.neg(fy) } else { fy };
            }
        }
        if f == Func::Abs {
            // |c·y| = |c|·|y|
            let (c, y) = self.split_coefficient(x);
            if c != 1.0 && y != Dag::ONE {
                let fy = self.intern(Node::Call(f, y));
                return self.scale(c.abs(), fy);
            }
        }
        self.intern(Node::Call(f, x))
    }

    /// `f(a, b)`, folded for constants; `powf` with an integer constant
    /// exponent becomes a product.
    pub fn call2(&mut self, f: Func2, a: Id, b: Id) -> Id {
        if let (Some(x), Some(y)) = (self.as_const(a), self.as_const(b)) {
            let z = f.eval(x, y);
            if z.is_finite() {
                return self.num(z);
            }
        }
        if f == Func2::Powf {
            if let Some(e) = self.as_const(b) {
                if e == 0.0 {
                    return Dag::ONE;
                }
                if e.fract() == 0.0 && e.abs() <= 64.0 {
                    return self.powi(a, e as i32);
                }
            }
        }
        if f == Func2::Hypot {
            // hypot is even in both arguments and symmetric.
            let (_, a) = self.split_sign(a);
            let (_, b) = self.split_sign(b);
            let (a, b) = if a <= b { (a, b) } else { (b, a) };
            return self.intern(Node::Call2(f, a, b));
        }
        self.intern(Node::Call2(f, a, b))
    }
}

/// The children of a node, in order.
pub fn children(node: &Node) -> Vec<Id> {
    match node {
        Node::Const(_) | Node::Sym(_) => Vec::new(),
        Node::Sum(terms) => terms.iter().map(|t| t.1).collect(),
        Node::Prod(factors) => factors.iter().map(|f| f.0).collect(),
        Node::Call(_, x) => vec![*x],
        Node::Call2(_, a, b) => vec![*a, *b],
    }
}

/// `c·cᵢ` is a usable coefficient: finite, and not flushed to zero.
fn scales_exactly_enough(c: f64, ci: f64) -> bool {
    let p = c * ci;
    p.is_finite() && p != 0.0
}

/// Multiplying by `c` is exact: `c = ±2ᵏ`.
fn is_exact_scale(c: f64) -> bool {
    c.is_normal() && c.to_bits() & ((1u64 << 52) - 1) == 0
}

impl Dag {
    pub(crate) fn derivative_memo(&self, key: (Id, Symbol)) -> Option<Id> {
        self.derivatives.get(&key).copied()
    }

    pub(crate) fn remember_derivative(&mut self, key: (Id, Symbol), d: Id) {
        self.derivatives.insert(key, d);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup() -> (Dag, Id, Id) {
        let mut dag = Dag::new();
        let x = dag.sym(Symbol::Coord(0));
        let y = dag.sym(Symbol::Coord(1));
        (dag, x, y)
    }

    #[test]
    fn x_minus_x_is_zero() {
        let (mut dag, x, _) = setup();
        assert_eq!(dag.sub(x, x), Dag::ZERO);
    }

    #[test]
    fn like_terms_collect() {
        let (mut dag, x, y) = setup();
        let a = dag.add(x, y);
        let b = dag.add(a, x);
        let expected = dag.sum([(2.0, x), (1.0, y)]);
        assert_eq!(b, expected);
    }

    #[test]
    fn sums_and_products_commute() {
        let (mut dag, x, y) = setup();
        assert_eq!(dag.add(x, y), dag.add(y, x));
        assert_eq!(dag.mul(x, y), dag.mul(y, x));
    }

    #[test]
    fn identities_of_zero_and_one() {
        let (mut dag, x, _) = setup();
        assert_eq!(dag.add(x, Dag::ZERO), x);
        assert_eq!(dag.mul(x, Dag::ONE), x);
        assert_eq!(dag.mul(x, Dag::ZERO), Dag::ZERO);
        assert_eq!(dag.div(x, x), Dag::ONE);
        assert_eq!(dag.powi(x, 0), Dag::ONE);
    }

    #[test]
    fn numeric_factors_are_collected() {
        let (mut dag, x, y) = setup();
        let two = dag.num(2.0);
        let three = dag.num(3.0);
        let a = dag.mul(two, x);
        let b = dag.mul(three, y);
        let p = dag.mul(a, b);
        let xy = dag.mul(x, y);
        assert_eq!(p, dag.scale(6.0, xy));
    }

    #[test]
    fn constants_fold() {
        let mut dag = Dag::new();
        let a = dag.num(2.0);
        let b = dag.num(0.5);
        let s = dag.add(a, b);
        assert_eq!(dag.as_const(s), Some(2.5));
        let c = dag.call(Func::Cos, Dag::ZERO);
        assert_eq!(c, Dag::ONE);
        // sqrt(-1) is not finite: it stays a call.
        let m = dag.num(-1.0);
        let r = dag.call(Func::Sqrt, m);
        assert!(matches!(dag.node(r), Node::Call(Func::Sqrt, _)));
    }

    #[test]
    fn products_flatten_and_merge_powers() {
        let (mut dag, x, y) = setup();
        let xy = dag.mul(x, y);
        let p = dag.mul(xy, x);
        assert_eq!(p, dag.product([(x, 2), (y, 1)]));
        let q = dag.div(p, xy);
        assert_eq!(q, x);
    }

    #[test]
    fn inexact_scales_do_not_distribute() {
        let (mut dag, x, y) = setup();
        let d = dag.sub(x, y);
        let s = dag.scale(0.1, d);
        // 0.1·(x − y) stays a scaled sum: distributing would lose accuracy
        // when x ≈ y.
        assert_eq!(dag.split_coefficient(s), (0.1, d));
        let h = dag.scale(0.5, d);
        assert!(matches!(dag.node(h), Node::Sum(t) if t.len() == 2));
    }

    #[test]
    fn odd_and_even_functions_pull_out_the_sign() {
        let (mut dag, x, y) = setup();
        let mx = dag.neg(x);
        let sin_mx = dag.call(Func::Sin, mx);
        let sin_x = dag.call(Func::Sin, x);
        assert_eq!(sin_mx, dag.neg(sin_x));
        let cos_mx = dag.call(Func::Cos, mx);
        assert_eq!(cos_mx, dag.call(Func::Cos, x));
        let ymx = dag.sub(y, x);
        let xmy = dag.sub(x, y);
        let s1 = dag.call(Func::Sin, ymx);
        let s2 = dag.call(Func::Sin, xmy);
        assert_eq!(s1, dag.neg(s2));
    }

    #[test]
    fn powf_with_integer_exponent_is_a_power() {
        let (mut dag, x, _) = setup();
        let two = dag.num(2.0);
        let p = dag.call2(Func2::Powf, x, two);
        assert_eq!(p, dag.powi(x, 2));
    }
}

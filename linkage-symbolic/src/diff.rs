//! Symbolic differentiation: one rule per operation, memoised per
//! `(node, symbol)` so that shared subexpressions are differentiated once and
//! their derivatives are shared too.

use crate::dag::{Dag, Func, Func2, Id, Node, Symbol};

impl Dag {
    /// `∂x/∂s`, simplified.
    pub fn diff(&mut self, x: Id, s: Symbol) -> Id {
        if let Some(d) = self.derivative_memo((x, s)) {
            return d;
        }
        let d = self.diff_uncached(x, s);
        self.remember_derivative((x, s), d);
        d
    }

    /// The directional derivative `Σₖ ∂x/∂sₖ · dₖ`.
    pub fn directional(&mut self, x: Id, direction: &[(Symbol, Id)]) -> Id {
        let mut terms = Vec::with_capacity(direction.len());
        for &(s, d) in direction {
            let dx = self.diff(x, s);
            if dx != Dag::ZERO && d != Dag::ZERO {
                terms.push((1.0, self.mul(dx, d)));
            }
        }
        self.sum(terms)
    }

    fn diff_uncached(&mut self, x: Id, s: Symbol) -> Id {
        match self.node(x).clone() {
            Node::Const(_) => Dag::ZERO,
            Node::Sym(t) => {
                if t == s {
                    Dag::ONE
                } else {
                    Dag::ZERO
                }
            }
            // (Σ cᵢ tᵢ)' = Σ cᵢ tᵢ'
            Node::Sum(terms) => {
                let mut out = Vec::with_capacity(terms.len());
                for (c, t) in terms {
                    let dt = self.diff(t, s);
                    out.push((c.get(), dt));
                }
                self.sum(out)
            }
            // (Π fᵢ^eᵢ)' = Σᵢ eᵢ·fᵢ^(eᵢ−1)·fᵢ'·Πⱼ≠ᵢ fⱼ^eⱼ
            Node::Prod(factors) => {
                let mut out = Vec::new();
                for (i, &(f, e)) in factors.iter().enumerate() {
                    let df = self.diff(f, s);
                    if df == Dag::ZERO {
                        continue;
                    }
                    let mut term = factors.clone();
                    match e.checked_sub(1) {
                        Some(e1) => term[i].1 = e1,
                        None => term.push((f, -1)),
                    }
                    term.push((df, 1));
                    let t = self.product(term);
                    out.push((f64::from(e), t));
                }
                self.sum(out)
            }
            Node::Call(f, a) => {
                let da = self.diff(a, s);
                if da == Dag::ZERO {
                    return Dag::ZERO;
                }
                let outer = self.call_derivative(f, a);
                self.mul(outer, da)
            }
            Node::Call2(f, a, b) => {
                let da = self.diff(a, s);
                let db = self.diff(b, s);
                if da == Dag::ZERO && db == Dag::ZERO {
                    return Dag::ZERO;
                }
                self.call2_derivative(f, x, a, b, da, db)
            }
        }
    }

    /// `f′(a)` for a function of one argument.
    fn call_derivative(&mut self, f: Func, a: Id) -> Id {
        match f {
            // sin′ = cos
            Func::Sin => self.call(Func::Cos, a),
            // cos′ = −sin
            Func::Cos => {
                let sin = self.call(Func::Sin, a);
                self.neg(sin)
            }
            // tan′ = 1/cos²
            Func::Tan => {
                let cos = self.call(Func::Cos, a);
                self.powi(cos, -2)
            }
            // asin′ = 1/√(1 − a²)
            Func::Asin => {
                let root = self.one_minus_square_root(a);
                self.powi(root, -1)
            }
            // acos′ = −1/√(1 − a²)
            Func::Acos => {
                let root = self.one_minus_square_root(a);
                let inv = self.powi(root, -1);
                self.neg(inv)
            }
            // atan′ = 1/(1 + a²)
            Func::Atan => {
                let sq = self.powi(a, 2);
                let den = self.sum([(1.0, Dag::ONE), (1.0, sq)]);
                self.powi(den, -1)
            }
            // sinh′ = cosh
            Func::Sinh => self.call(Func::Cosh, a),
            // cosh′ = sinh
            Func::Cosh => self.call(Func::Sinh, a),
            // tanh′ = 1/cosh² (accurate where 1 − tanh² cancels)
            Func::Tanh => {
                let cosh = self.call(Func::Cosh, a);
                self.powi(cosh, -2)
            }
            // √′ = 1/(2√a)
            Func::Sqrt => {
                let root = self.call(Func::Sqrt, a);
                let inv = self.powi(root, -1);
                self.scale(0.5, inv)
            }
            // exp′ = exp
            Func::Exp => self.call(Func::Exp, a),
            // ln′ = 1/a
            Func::Ln => self.powi(a, -1),
            // |a|′ = signum(a)
            Func::Abs => self.call(Func::Signum, a),
            // signum′ = 0 (almost everywhere)
            Func::Signum => Dag::ZERO,
        }
    }

    /// `√(1 − a²)`
    fn one_minus_square_root(&mut self, a: Id) -> Id {
        let sq = self.powi(a, 2);
        let inner = self.sum([(1.0, Dag::ONE), (-1.0, sq)]);
        self.call(Func::Sqrt, inner)
    }

    /// The total derivative of `f(a, b)` (the node `fab`), given `a′` and `b′`.
    fn call2_derivative(&mut self, f: Func2, fab: Id, a: Id, b: Id, da: Id, db: Id) -> Id {
        match f {
            // atan2(a, b)′ = (b·a′ − a·b′)/(a² + b²)
            Func2::Atan2 => {
                let b_da = self.mul(b, da);
                let a_db = self.mul(a, db);
                let num = self.sub(b_da, a_db);
                let a2 = self.powi(a, 2);
                let b2 = self.powi(b, 2);
                let den = self.add(a2, b2);
                self.div(num, den)
            }
            // hypot(a, b)′ = (a·a′ + b·b′)/hypot(a, b)
            Func2::Hypot => {
                let a_da = self.mul(a, da);
                let b_db = self.mul(b, db);
                let num = self.add(a_da, b_db);
                self.div(num, fab)
            }
            Func2::Powf => match self.as_const(b) {
                // (a^c)′ = c·a^(c−1)·a′
                Some(c) => {
                    let c1 = self.num(c - 1.0);
                    let pow = self.call2(Func2::Powf, a, c1);
                    let t = self.mul(pow, da);
                    self.scale(c, t)
                }
                // (a^b)′ = a^b·(b′·ln a + b·a′/a)
                None => {
                    let ln_a = self.call(Func::Ln, a);
                    let t1 = self.mul(db, ln_a);
                    let t2 = self.product([(b, 1), (da, 1), (a, -1)]);
                    let inner = self.add(t1, t2);
                    self.mul(fab, inner)
                }
            },
        }
    }
}

#[cfg(test)]
mod tests {
    //! One test per derivative rule: the symbolic derivative, evaluated,
    //! against the derivative known in closed form.
    use super::*;
    use crate::interp::eval_f64;

    const X: Symbol = Symbol::Coord(0);
    const Y: Symbol = Symbol::Coord(1);

    /// Checks `d/dx f(x)` at `x0` against `expected(x0)`.
    fn check1(build: impl Fn(&mut Dag, Id) -> Id, expected: impl Fn(f64) -> f64, x0: f64) {
        let mut dag = Dag::new();
        let x = dag.sym(X);
        let f = build(&mut dag, x);
        let df = dag.diff(f, X);
        let got = eval_f64(&dag, df, &[x0, 0.0]);
        let want = expected(x0);
        assert!(
            (got - want).abs() <= 1e-14 * want.abs().max(1.0),
            "got {got}, want {want}"
        );
    }

    #[test]
    fn rule_sin() {
        check1(|d, x| d.call(Func::Sin, x), f64::cos, 0.7);
    }

    #[test]
    fn rule_cos() {
        check1(|d, x| d.call(Func::Cos, x), |x| -x.sin(), 0.7);
    }

    #[test]
    fn rule_tan() {
        check1(|d, x| d.call(Func::Tan, x), |x| 1.0 / x.cos().powi(2), 0.7);
    }

    #[test]
    fn rule_asin() {
        check1(
            |d, x| d.call(Func::Asin, x),
            |x| 1.0 / (1.0 - x * x).sqrt(),
            0.3,
        );
    }

    #[test]
    fn rule_acos() {
        check1(
            |d, x| d.call(Func::Acos, x),
            |x| -1.0 / (1.0 - x * x).sqrt(),
            0.3,
        );
    }

    #[test]
    fn rule_atan() {
        check1(|d, x| d.call(Func::Atan, x), |x| 1.0 / (1.0 + x * x), 0.3);
    }

    #[test]
    fn rule_sinh_cosh_tanh() {
        check1(|d, x| d.call(Func::Sinh, x), f64::cosh, 0.3);
        check1(|d, x| d.call(Func::Cosh, x), f64::sinh, 0.3);
        check1(
            |d, x| d.call(Func::Tanh, x),
            |x| 1.0 / x.cosh().powi(2),
            0.3,
        );
    }

    #[test]
    fn rule_sqrt_exp_ln() {
        check1(|d, x| d.call(Func::Sqrt, x), |x| 0.5 / x.sqrt(), 2.0);
        check1(|d, x| d.call(Func::Exp, x), f64::exp, 0.4);
        check1(|d, x| d.call(Func::Ln, x), |x| 1.0 / x, 2.5);
    }

    #[test]
    fn rule_abs() {
        check1(|d, x| d.call(Func::Abs, x), |_| -1.0, -2.0);
        check1(|d, x| d.call(Func::Abs, x), |_| 1.0, 2.0);
    }

    #[test]
    fn rule_powi_and_quotient() {
        check1(|d, x| d.powi(x, 5), |x| 5.0 * x.powi(4), 1.3);
        check1(|d, x| d.powi(x, -3), |x| -3.0 / x.powi(4), 1.3);
        check1(
            |d, x| {
                let s = d.call(Func::Sin, x);
                d.div(s, x)
            },
            |x| (x * x.cos() - x.sin()) / (x * x),
            1.3,
        );
    }

    #[test]
    fn rule_powf() {
        check1(
            |d, x| {
                let c = d.num(2.5);
                d.call2(Func2::Powf, x, c)
            },
            |x| 2.5 * x.powf(1.5),
            1.7,
        );
        // x^x: both base and exponent vary.
        check1(
            |d, x| d.call2(Func2::Powf, x, x),
            |x| x.powf(x) * (x.ln() + 1.0),
            1.7,
        );
    }

    /// Checks ∂/∂x and ∂/∂y of f(x, y) at (x0, y0).
    fn check2(
        build: impl Fn(&mut Dag, Id, Id) -> Id,
        expected: impl Fn(f64, f64) -> (f64, f64),
        p: (f64, f64),
    ) {
        let mut dag = Dag::new();
        let x = dag.sym(X);
        let y = dag.sym(Y);
        let f = build(&mut dag, x, y);
        let dfx = dag.diff(f, X);
        let dfy = dag.diff(f, Y);
        let got = (
            eval_f64(&dag, dfx, &[p.0, p.1]),
            eval_f64(&dag, dfy, &[p.0, p.1]),
        );
        let want = expected(p.0, p.1);
        assert!(
            (got.0 - want.0).abs() <= 1e-14 * want.0.abs().max(1.0),
            "{got:?} {want:?}"
        );
        assert!(
            (got.1 - want.1).abs() <= 1e-14 * want.1.abs().max(1.0),
            "{got:?} {want:?}"
        );
    }

    #[test]
    fn rule_atan2() {
        check2(
            |d, x, y| d.call2(Func2::Atan2, y, x),
            |x, y| (-y / (x * x + y * y), x / (x * x + y * y)),
            (0.8, -1.3),
        );
    }

    #[test]
    fn rule_hypot() {
        check2(
            |d, x, y| d.call2(Func2::Hypot, x, y),
            |x, y| (x / x.hypot(y), y / x.hypot(y)),
            (0.8, -1.3),
        );
    }

    #[test]
    fn rule_product_and_sum() {
        check2(
            |d, x, y| {
                let xy = d.mul(x, y);
                let x2 = d.powi(x, 2);
                let s = d.sum([(3.0, xy), (-2.0, x2), (1.0, y)]);
                d.mul(s, x)
            },
            |x, y| (6.0 * x * y - 6.0 * x * x + y, 3.0 * x * x + x),
            (0.8, -1.3),
        );
    }

    #[test]
    fn derivatives_are_shared() {
        let mut dag = Dag::new();
        let x = dag.sym(X);
        let s = dag.call(Func::Sin, x);
        let a = dag.diff(s, X);
        let n = dag.len();
        let b = dag.diff(s, X);
        assert_eq!(a, b);
        assert_eq!(n, dag.len());
    }

    #[test]
    fn mixed_second_derivatives_are_the_same_node() {
        let mut dag = Dag::new();
        let x = dag.sym(X);
        let y = dag.sym(Y);
        let xy = dag.mul(x, y);
        let f = dag.call(Func::Sin, xy);
        let fx = dag.diff(f, X);
        let fxy = dag.diff(fx, Y);
        let fy = dag.diff(f, Y);
        let fyx = dag.diff(fy, X);
        assert_eq!(fxy, fyx);
    }
}

//! An interpreter of the DAG over any `num_dual::DualNum`: the reference the
//! symbolic derivatives are tested against (test builds only).

use crate::dag::{Dag, Func, Func2, Id, Node, Symbol};
use num_dual::DualNum;

/// The value of `root`, with the leaves given by `leaf`.
pub fn eval<D: DualNum<Primitive = f64> + Copy>(
    dag: &Dag,
    root: Id,
    leaf: &dyn Fn(Symbol) -> D,
) -> D {
    let mut values: Vec<Option<D>> = vec![None; root.index() + 1];
    eval_rec(dag, root, leaf, &mut values)
}

/// The values of `roots`, with the leaves given by `leaf`, each shared
/// node evaluated once.
pub fn eval_many<D: DualNum<Primitive = f64> + Copy>(
    dag: &Dag,
    roots: &[Id],
    leaf: &dyn Fn(Symbol) -> D,
) -> Vec<D> {
    let size = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
    let mut values: Vec<Option<D>> = vec![None; size];
    roots
        .iter()
        .map(|&root| eval_rec(dag, root, leaf, &mut values))
        .collect()
}

fn eval_rec<D: DualNum<Primitive = f64> + Copy>(
    dag: &Dag,
    id: Id,
    leaf: &dyn Fn(Symbol) -> D,
    memo: &mut Vec<Option<D>>,
) -> D {
    if let Some(v) = memo[id.index()] {
        return v;
    }
    let v = match dag.node(id) {
        Node::Const(c) => D::from(c.get()),
        Node::Sym(Symbol::Constant(c)) => D::from(c.value()),
        Node::Sym(s) => leaf(*s),
        Node::Sum(terms) => {
            let mut acc = D::from(0.0);
            for &(c, t) in terms {
                acc += eval_rec(dag, t, leaf, memo) * c.get();
            }
            acc
        }
        Node::Prod(factors) => {
            let mut acc = D::from(1.0);
            for &(f, e) in factors {
                acc *= eval_rec(dag, f, leaf, memo).powi(e);
            }
            acc
        }
        Node::Call(f, a) => {
            let a = eval_rec(dag, *a, leaf, memo);
            match f {
                Func::Sin => a.sin(),
                Func::Cos => a.cos(),
                Func::Tan => a.tan(),
                Func::Asin => a.asin(),
                Func::Acos => a.acos(),
                Func::Atan => a.atan(),
                Func::Sinh => a.sinh(),
                Func::Cosh => a.cosh(),
                Func::Tanh => a.tanh(),
                Func::Sqrt => a.sqrt(),
                Func::Exp => a.exp(),
                Func::Ln => a.ln(),
                Func::Abs => num_traits::Signed::abs(&a),
                Func::Signum => num_traits::Signed::signum(&a),
            }
        }
        Node::Call2(f, a, b) => {
            let exponent = dag.as_const(*b);
            let (a, b) = (eval_rec(dag, *a, leaf, memo), eval_rec(dag, *b, leaf, memo));
            match (f, exponent) {
                (Func2::Atan2, _) => a.atan2(b),
                (Func2::Hypot, _) => (a * a + b * b).sqrt(),
                (Func2::Powf, Some(c)) => a.powf(c),
                (Func2::Powf, None) => a.powd(b),
            }
        }
    };
    memo[id.index()] = Some(v);
    v
}

/// The value of `root` in `f64`, with `coords[k]` for `q[k]` and every other
/// leaf zero.
pub fn eval_f64(dag: &Dag, root: Id, coords: &[f64]) -> f64 {
    eval::<f64>(dag, root, &|s| match s {
        Symbol::Coord(k) => coords[k as usize],
        _ => 0.0,
    })
}

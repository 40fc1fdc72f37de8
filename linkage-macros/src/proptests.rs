//! Property tests of the symbolic engine: random expression trees built
//! through the simplifying constructors, their symbolic first and second
//! derivatives evaluated by the interpreter, against num-dual's automatic
//! derivatives of the unsimplified tree.

use linkage_symbolic::dag::{Dag, Func, Func2, Id, Symbol};
use linkage_symbolic::interp::eval;
use num_dual::{Dual2_64, Dual64, DualNum, HyperDual64};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// A random expression over the coordinates x = q₀, y = q₁. Arguments of
/// functions with a restricted domain are wrapped so that every sample lies
/// away from the domain's edges.
#[derive(Clone, Debug)]
enum Tree {
    X,
    Y,
    Num(f64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    /// a / (c + b²)
    Div(Box<Tree>, Box<Tree>, f64),
    Neg(Box<Tree>),
    Powi(Box<Tree>, i32),
    /// f(a) for sin, cos, atan, sinh, cosh, tanh, exp(a/4), abs
    Free(Func, Box<Tree>),
    /// tan, asin, acos of 0.9·tanh(a)
    Bounded(Func, Box<Tree>),
    /// sqrt, ln of (c + a²)
    Positive(Func, Box<Tree>, f64),
    /// atan2(a, c + b²)
    Atan2(Box<Tree>, Box<Tree>, f64),
    Hypot(Box<Tree>, Box<Tree>),
    /// (c + a²)^p
    Powf(Box<Tree>, f64, f64),
    /// (c + a²)^(b/4)
    PowfVar(Box<Tree>, Box<Tree>, f64),
}

fn leaf() -> impl Strategy<Value = Tree> {
    prop_oneof![
        Just(Tree::X),
        Just(Tree::Y),
        (-3.0..3.0f64).prop_map(Tree::Num),
        (1i32..4).prop_map(|k| Tree::Num(f64::from(k))),
    ]
}

fn tree() -> impl Strategy<Value = Tree> {
    leaf().prop_recursive(6, 48, 2, |inner| {
        let c = 0.5..2.0f64;
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Add(a.into(), b.into())),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Sub(a.into(), b.into())),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Mul(a.into(), b.into())),
            (inner.clone(), inner.clone(), c.clone()).prop_map(|(a, b, c)| Tree::Div(
                a.into(),
                b.into(),
                c
            )),
            inner.clone().prop_map(|a| Tree::Neg(a.into())),
            (inner.clone(), -3i32..4).prop_map(|(a, n)| Tree::Powi(a.into(), n)),
            (
                prop_oneof![
                    Just(Func::Sin),
                    Just(Func::Cos),
                    Just(Func::Atan),
                    Just(Func::Sinh),
                    Just(Func::Cosh),
                    Just(Func::Tanh),
                    Just(Func::Exp),
                    Just(Func::Abs),
                ],
                inner.clone()
            )
                .prop_map(|(f, a)| Tree::Free(f, a.into())),
            (
                prop_oneof![Just(Func::Tan), Just(Func::Asin), Just(Func::Acos)],
                inner.clone()
            )
                .prop_map(|(f, a)| Tree::Bounded(f, a.into())),
            (
                prop_oneof![Just(Func::Sqrt), Just(Func::Ln)],
                inner.clone(),
                c.clone()
            )
                .prop_map(|(f, a, c)| Tree::Positive(f, a.into(), c)),
            (inner.clone(), inner.clone(), c.clone()).prop_map(|(a, b, c)| Tree::Atan2(
                a.into(),
                b.into(),
                c
            )),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Hypot(a.into(), b.into())),
            (inner.clone(), c.clone(), -2.5..2.5f64).prop_map(|(a, c, p)| Tree::Powf(
                a.into(),
                c,
                p
            )),
            (inner.clone(), inner, c).prop_map(|(a, b, c)| Tree::PowfVar(a.into(), b.into(), c)),
        ]
    })
}

/// Builds the tree in the DAG through the simplifying constructors.
fn build(dag: &mut Dag, t: &Tree) -> Id {
    match t {
        Tree::X => dag.sym(Symbol::Coord(0)),
        Tree::Y => dag.sym(Symbol::Coord(1)),
        Tree::Num(c) => dag.num(*c),
        Tree::Add(a, b) => {
            let (a, b) = (build(dag, a), build(dag, b));
            dag.add(a, b)
        }
        Tree::Sub(a, b) => {
            let (a, b) = (build(dag, a), build(dag, b));
            dag.sub(a, b)
        }
        Tree::Mul(a, b) => {
            let (a, b) = (build(dag, a), build(dag, b));
            dag.mul(a, b)
        }
        Tree::Div(a, b, c) => {
            let (a, b) = (build(dag, a), build(dag, b));
            let den = positive(dag, b, *c);
            dag.div(a, den)
        }
        Tree::Neg(a) => {
            let a = build(dag, a);
            dag.neg(a)
        }
        Tree::Powi(a, n) => {
            let a = build(dag, a);
            // Negative powers of a shifted square, to stay away from 0⁻ⁿ.
            if *n < 0 {
                let p = positive(dag, a, 1.0);
                dag.powi(p, *n)
            } else {
                dag.powi(a, *n)
            }
        }
        Tree::Free(f, a) => {
            let mut a = build(dag, a);
            if *f == Func::Exp || *f == Func::Sinh || *f == Func::Cosh {
                a = dag.scale(0.25, a);
            }
            if *f == Func::Sin || *f == Func::Cos {
                // 3·tanh(a/3): a sine of a huge argument is ill-conditioned,
                // whatever computes it.
                let inner = dag.scale(1.0 / 3.0, a);
                let t = dag.call(Func::Tanh, inner);
                a = dag.scale(3.0, t);
            }
            dag.call(*f, a)
        }
        Tree::Bounded(f, a) => {
            let a = build(dag, a);
            let t = dag.call(Func::Tanh, a);
            let s = dag.scale(0.9, t);
            dag.call(*f, s)
        }
        Tree::Positive(f, a, c) => {
            let a = build(dag, a);
            let p = positive(dag, a, *c);
            dag.call(*f, p)
        }
        Tree::Atan2(a, b, c) => {
            let (a, b) = (build(dag, a), build(dag, b));
            let x = positive(dag, b, *c);
            dag.call2(Func2::Atan2, a, x)
        }
        Tree::Hypot(a, b) => {
            let (a, b) = (build(dag, a), build(dag, b));
            let one = dag.num(1.0);
            let b1 = dag.add(b, one);
            let b1 = positive(dag, b1, 0.5);
            dag.call2(Func2::Hypot, a, b1)
        }
        Tree::Powf(a, c, p) => {
            let a = build(dag, a);
            let base = positive(dag, a, *c);
            let p = dag.num(*p);
            dag.call2(Func2::Powf, base, p)
        }
        Tree::PowfVar(a, b, c) => {
            let (a, b) = (build(dag, a), build(dag, b));
            let base = positive(dag, a, *c);
            let t = dag.call(Func::Tanh, b);
            dag.call2(Func2::Powf, base, t)
        }
    }
}

/// c + a²
fn positive(dag: &mut Dag, a: Id, c: f64) -> Id {
    let sq = dag.powi(a, 2);
    let c = dag.num(c);
    dag.add(c, sq)
}

/// tanh(a) = 1 − 2/(e^{2a} + 1): num-dual's `tanh` is sinh/cosh, whose
/// derivative cancels catastrophically for |a| ≳ 3; this form does not.
fn tanh<D: DualNum<Primitive = f64> + Copy>(a: D) -> D {
    -((a * 2.0).exp() + 1.0).recip() * 2.0 + 1.0
}

/// The same tree evaluated directly, without the DAG: the unsimplified
/// reference.
fn direct<D: DualNum<Primitive = f64> + Copy>(t: &Tree, x: D, y: D) -> D {
    let pos = |a: D, c: f64| a * a + c;
    match t {
        Tree::X => x,
        Tree::Y => y,
        Tree::Num(c) => D::from(*c),
        Tree::Add(a, b) => direct(a, x, y) + direct(b, x, y),
        Tree::Sub(a, b) => direct(a, x, y) - direct(b, x, y),
        Tree::Mul(a, b) => direct(a, x, y) * direct(b, x, y),
        Tree::Div(a, b, c) => direct(a, x, y) / pos(direct(b, x, y), *c),
        Tree::Neg(a) => -direct(a, x, y),
        Tree::Powi(a, n) => {
            let a = direct(a, x, y);
            if *n < 0 {
                pos(a, 1.0).powi(*n)
            } else {
                a.powi(*n)
            }
        }
        Tree::Free(f, a) => {
            let a = direct(a, x, y);
            match f {
                Func::Sin => (tanh(a * (1.0 / 3.0)) * 3.0).sin(),
                Func::Cos => (tanh(a * (1.0 / 3.0)) * 3.0).cos(),
                Func::Atan => a.atan(),
                Func::Sinh => (a * 0.25).sinh(),
                Func::Cosh => (a * 0.25).cosh(),
                Func::Tanh => tanh(a),
                Func::Exp => (a * 0.25).exp(),
                _ => num_traits::Signed::abs(&a),
            }
        }
        Tree::Bounded(f, a) => {
            let s = tanh(direct(a, x, y)) * 0.9;
            match f {
                Func::Tan => s.tan(),
                Func::Asin => s.asin(),
                _ => s.acos(),
            }
        }
        Tree::Positive(f, a, c) => {
            let p = pos(direct(a, x, y), *c);
            if *f == Func::Sqrt { p.sqrt() } else { p.ln() }
        }
        Tree::Atan2(a, b, c) => direct(a, x, y).atan2(pos(direct(b, x, y), *c)),
        Tree::Hypot(a, b) => {
            let a = direct(a, x, y);
            let b = pos(direct(b, x, y) + 1.0, 0.5);
            (a * a + b * b).sqrt()
        }
        Tree::Powf(a, c, p) => pos(direct(a, x, y), *c).powf(*p),
        Tree::PowfVar(a, b, c) => pos(direct(a, x, y), *c).powd(tanh(direct(b, x, y))),
    }
}

/// A fixed random state, so that CI runs the same cases every time; set
/// `PROPTEST_RNG_SEED` (a number) to explore others.
fn config(cases: u32) -> ProptestConfig {
    let mut config = ProptestConfig::with_cases(cases);
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x004c_494e_4b41_4745);
    }
    config
}

/// |a − b| relative to the size of the quantities involved.
fn relative(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(scale).max(1e-300)
}

const X: Symbol = Symbol::Coord(0);
const Y: Symbol = Symbol::Coord(1);

proptest! {
    #![proptest_config(config(2000))]

    /// Value, gradient and second derivatives of the simplified DAG agree
    /// with num-dual on the unsimplified tree.
    #[test]
    fn symbolic_derivatives_match_num_dual(t in tree(), x in -1.5..1.5f64, y in -1.5..1.5f64) {
        let mut dag = Dag::new();
        let f = build(&mut dag, &t);
        let fx = dag.diff(f, X);
        let fy = dag.diff(f, Y);
        let fxx = dag.diff(fx, X);
        let fxy = dag.diff(fx, Y);
        let leaf = |s: Symbol| match s { Symbol::Coord(0) => x, _ => y };
        let value = eval::<f64>(&dag, f, &leaf);
        let gx = eval::<f64>(&dag, fx, &leaf);
        let gy = eval::<f64>(&dag, fy, &leaf);
        let hxx = eval::<f64>(&dag, fxx, &leaf);
        let hxy = eval::<f64>(&dag, fxy, &leaf);

        let dx = direct(&t, Dual64::from(x).derivative(), Dual64::from(y));
        let dy = direct(&t, Dual64::from(x), Dual64::from(y).derivative());
        let d2 = direct(&t, Dual2_64::from(x).derivative(), Dual2_64::from(y));
        let hyper = direct(
            &t,
            HyperDual64::from(x).derivative1(),
            HyperDual64::from(y).derivative2(),
        );
        let reference_xy = hyper.eps1eps2;
        let all = [value, gx, gy, hxx, hxy, dx.re, dx.eps, dy.eps, d2.v2, reference_xy];
        prop_assume!(all.iter().all(|v| v.is_finite() && v.abs() < 1e8));
        // The tree's magnitudes bound the cancellation error of either side.
        // A derivative that cancels to almost nothing is measured against a
        // hundredth of the function's size.
        let scale = 1e-2 * value.abs().max(1.0);
        prop_assert!(relative(value, dx.re, 1e-2) < 1e-12, "value {} vs {}", value, dx.re);
        prop_assert!(relative(gx, dx.eps, scale) < 1e-12, "∂x {} vs {}", gx, dx.eps);
        prop_assert!(relative(gy, dy.eps, scale) < 1e-12, "∂y {} vs {}", gy, dy.eps);
        prop_assert!(relative(hxx, d2.v2, scale) < 1e-11, "∂xx {} vs {}", hxx, d2.v2);
        prop_assert!(relative(hxy, reference_xy, scale) < 1e-11, "∂xy {} vs {}", hxy, reference_xy);
    }
}

/// The tree as Rust source, in a mix of spellings: methods, free functions,
/// `f64::` paths, integer and float literals. `style` varies the spelling.
fn source(t: &Tree, style: &mut u32) -> String {
    *style = style.wrapping_mul(1_103_515_245).wrapping_add(12_345);
    let pick = (*style >> 16) % 3;
    let num = |c: f64| {
        if c.fract() == 0.0 && c.abs() < 100.0 && c >= 0.0 {
            format!("{}", c as i64)
        } else {
            format!("({c:?})")
        }
    };
    let call = |f: &str, a: String, pick: u32| match pick {
        0 => format!("({a}).{f}()"),
        1 => format!("{f}({a})"),
        _ => format!("f64::{f}({a})"),
    };
    match t {
        Tree::X => "x".to_owned(),
        Tree::Y => "y".to_owned(),
        Tree::Num(c) => num(*c),
        Tree::Add(a, b) => format!("({} + {})", source(a, style), source(b, style)),
        Tree::Sub(a, b) => format!("({} - {})", source(a, style), source(b, style)),
        Tree::Mul(a, b) => format!("({} * {})", source(a, style), source(b, style)),
        Tree::Div(a, b, c) => {
            let b = source(b, style);
            format!("({} / ({} + {b} * {b}))", source(a, style), num(*c))
        }
        Tree::Neg(a) => format!("(-{})", source(a, style)),
        Tree::Powi(a, n) => {
            let a = source(a, style);
            let base = if *n < 0 {
                format!("(1.0 + {a} * {a})")
            } else {
                a
            };
            match pick {
                0 => format!("{base}.powi({n})"),
                _ => format!("powi({base}, {n})"),
            }
        }
        Tree::Free(f, a) => {
            let a = source(a, style);
            let a = if matches!(f, Func::Exp | Func::Sinh | Func::Cosh) {
                format!("0.25 * {a}")
            } else if matches!(f, Func::Sin | Func::Cos) {
                format!("3.0 * {}", call("tanh", format!("{a} * (1.0 / 3.0)"), pick))
            } else {
                a
            };
            call(f.method(), a, pick)
        }
        Tree::Bounded(f, a) => {
            let inner = format!("0.9 * {}", call("tanh", source(a, style), pick));
            call(f.method(), inner, pick)
        }
        Tree::Positive(f, a, c) => {
            let a = source(a, style);
            call(f.method(), format!("{} + {a} * {a}", num(*c)), pick)
        }
        Tree::Atan2(a, b, c) => {
            let (a, b) = (source(a, style), source(b, style));
            match pick {
                0 => format!("({a}).atan2({} + {b} * {b})", num(*c)),
                _ => format!("atan2({a}, {} + {b} * {b})", num(*c)),
            }
        }
        Tree::Hypot(a, b) => {
            let (a, b) = (source(a, style), source(b, style));
            match pick {
                0 => format!("({a}).hypot(0.5 + ({b} + 1.0) * ({b} + 1.0))"),
                _ => format!("hypot({a}, 0.5 + ({b} + 1.0).powi(2))"),
            }
        }
        Tree::Powf(a, c, p) => {
            let a = source(a, style);
            format!("({} + {a} * {a}).powf({p:?})", num(*c))
        }
        Tree::PowfVar(a, b, c) => {
            let a = source(a, style);
            format!(
                "powf({} + {a} * {a}, ({}).tanh())",
                num(*c),
                source(b, style)
            )
        }
    }
}

proptest! {
    #![proptest_config(config(300))]

    /// The whole pipeline on random equations written as Rust source: the
    /// attribute is expanded, the emitted `psi`, `psi_v` and `gamma` are run
    /// by an interpreter of the emitted code, and compared with num-dual on
    /// the unsimplified tree: the value within a few ulps, first and second
    /// derivatives to 1e-12 and 1e-11 relative.
    #[test]
    fn emitted_code_matches_num_dual(
        t in tree(),
        style in 0u32..1000,
        x in -1.5..1.5f64,
        y in -1.5..1.5f64,
        a in -2.0..2.0f64,
        b in -2.0..2.0f64,
    ) {
        use crate::run_emitted::call;
        let mut style = style;
        let expr: syn::Expr = syn::parse_str(&source(&t, &mut style)).expect("the source parses");
        let attr = quote::quote!(u = [w], v = [x, y], closure = [w - k * (#expr)]);
        let item = quote::quote!(pub struct Random { pub k: f64 });
        let expansion = linkage_symbolic::generate::expand(attr, item);
        let file: syn::File = syn::parse2(expansion.clone()).expect("the expansion parses");
        prop_assume!(!expansion.to_string().contains("compile_error"));
        let fields = std::collections::HashMap::from([("k".to_owned(), 1.0)]);
        let (w, v, udot, vdot) = (vec![0.0], vec![x, y], vec![0.0], vec![a, b]);
        let psi = call(&file, "psi", &fields, &[w.clone(), v.clone()]).entries_row_major()[0];
        let psi_v = call(&file, "psi_v", &fields, &[w.clone(), v.clone()]).entries_row_major();
        let gamma = call(&file, "gamma", &fields, &[w, v, udot, vdot]).entries_row_major()[0];

        let d = direct(&t, Dual64::from(x), Dual64::from(y));
        let dx = direct(&t, Dual64::from(x).derivative(), Dual64::from(y)).eps;
        let dy = direct(&t, Dual64::from(x), Dual64::from(y).derivative()).eps;
        let second = direct(&t, Dual2_64::new(x, a, 0.0), Dual2_64::new(y, b, 0.0)).v2;
        let all = [psi, psi_v[0], psi_v[1], gamma, d.re, dx, dy, second];
        prop_assume!(all.iter().all(|v| v.is_finite() && v.abs() < 1e8));
        let scale = 1e-2 * d.re.abs().max(1.0);
        prop_assert!(relative(-psi, d.re, 1e-2) < 1e-13, "value {} vs {}", -psi, d.re);
        prop_assert!(relative(-psi_v[0], dx, scale) < 1e-12, "∂x {} vs {}", -psi_v[0], dx);
        prop_assert!(relative(-psi_v[1], dy, scale) < 1e-12, "∂y {} vs {}", -psi_v[1], dy);
        prop_assert!(relative(-gamma, second, scale) < 1e-11, "γ {} vs {}", -gamma, second);
    }
}

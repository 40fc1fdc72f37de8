//! An interpreter of the code the macro emits (test builds only): it runs
//! the straight-line bodies of the generated functions on `f64`, so that the
//! whole pipeline — parse, lower, differentiate, simplify, share, emit — can
//! be checked against automatic differentiation without a compiler.
//!
//! It understands exactly the forms `emit` and `expand` produce: `let`
//! bindings (names, tuples, `Self { .. } = *self`), indexing, `+ - * /`,
//! unary `-`, parentheses, method calls of `f64`, `SVector`/`SMatrix`
//! construction with `zeros()`, assignment to entries, tuples and arrays.

use std::collections::HashMap;
use syn::{BinOp, Expr, Lit, Pat, Stmt, UnOp};

/// A value of the interpreted code.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Num(f64),
    Tuple(Vec<Value>),
    /// Column-major entries and the number of rows.
    Matrix(Vec<f64>, usize),
}

impl Value {
    pub fn num(&self) -> f64 {
        match self {
            Value::Num(x) => *x,
            other => panic!("not a number: {other:?}"),
        }
    }

    /// The entries of a matrix or vector, row-major.
    pub fn entries_row_major(&self) -> Vec<f64> {
        match self {
            Value::Matrix(data, rows) => {
                let cols = data.len() / rows.max(&1);
                (0..*rows)
                    .flat_map(|i| (0..cols).map(move |j| data[j * rows + i]))
                    .collect()
            }
            Value::Num(x) => vec![*x],
            other => panic!("not a matrix: {other:?}"),
        }
    }
}

/// Finds the generated method `name` in an expansion and runs it with the
/// given fields of `self` and arguments (each a vector).
pub fn call(
    file: &syn::File,
    name: &str,
    fields: &HashMap<String, f64>,
    args: &[Vec<f64>],
) -> Value {
    let method = find(file, name).unwrap_or_else(|| panic!("no generated function `{name}`"));
    let mut env: HashMap<String, Value> = HashMap::new();
    for (input, value) in method.sig.inputs.iter().skip(1).zip(args) {
        let syn::FnArg::Typed(t) = input else {
            unreachable!()
        };
        let Pat::Ident(p) = &*t.pat else {
            unreachable!()
        };
        env.insert(
            p.ident.to_string(),
            Value::Matrix(value.clone(), value.len()),
        );
    }
    let mut machine = Machine { env, fields };
    let mut result = Value::Tuple(Vec::new());
    for stmt in &method.block.stmts {
        match stmt {
            Stmt::Local(local) => {
                let value = machine.eval(&local.init.as_ref().expect("an initialiser").expr);
                machine.bind(&local.pat, value);
            }
            Stmt::Expr(e, Some(_)) => {
                machine.eval(e);
            }
            Stmt::Expr(e, None) => result = machine.eval(e),
            other => panic!("unexpected statement {}", quote::quote!(#other)),
        }
    }
    result
}

fn find<'a>(file: &'a syn::File, name: &str) -> Option<&'a syn::ImplItemFn> {
    for item in &file.items {
        let syn::Item::Const(c) = item else { continue };
        let Expr::Block(block) = &*c.expr else {
            continue;
        };
        for stmt in &block.block.stmts {
            let Stmt::Item(syn::Item::Impl(imp)) = stmt else {
                continue;
            };
            if imp.trait_.is_some() {
                continue;
            }
            for it in &imp.items {
                if let syn::ImplItem::Fn(f) = it {
                    if f.sig.ident == name {
                        return Some(f);
                    }
                }
            }
        }
    }
    None
}

struct Machine<'a> {
    env: HashMap<String, Value>,
    fields: &'a HashMap<String, f64>,
}

impl Machine<'_> {
    fn bind(&mut self, pat: &Pat, value: Value) {
        match (pat, value) {
            (Pat::Ident(p), v) => {
                self.env.insert(p.ident.to_string(), v);
            }
            (Pat::Tuple(t), Value::Tuple(vs)) => {
                for (p, v) in t.elems.iter().zip(vs) {
                    self.bind(p, v);
                }
            }
            // let Self { a, b, .. } = *self;
            (Pat::Struct(s), _) => {
                for f in &s.fields {
                    let syn::Member::Named(name) = &f.member else {
                        unreachable!()
                    };
                    let value = self.fields[&name.to_string()];
                    self.env.insert(name.to_string(), Value::Num(value));
                }
            }
            (p, v) => panic!("cannot bind {} to {v:?}", quote::quote!(#p)),
        }
    }

    fn eval(&mut self, e: &Expr) -> Value {
        match e {
            Expr::Lit(l) => match &l.lit {
                Lit::Float(f) => Value::Num(f.base10_parse().unwrap()),
                Lit::Int(i) => Value::Num(i.base10_parse::<i64>().unwrap() as f64),
                other => panic!("literal {}", quote::quote!(#other)),
            },
            Expr::Paren(p) => self.eval(&p.expr),
            Expr::Group(g) => self.eval(&g.expr),
            Expr::Path(p) => {
                let segments: Vec<String> = p
                    .path
                    .segments
                    .iter()
                    .map(|s| s.ident.to_string())
                    .collect();
                if segments.len() == 1 {
                    return self
                        .env
                        .get(&segments[0])
                        .cloned()
                        .unwrap_or_else(|| panic!("unbound {}", segments[0]));
                }
                Value::Num(constant(segments.last().unwrap()))
            }
            Expr::Tuple(t) => Value::Tuple(t.elems.iter().map(|e| self.eval(e)).collect()),
            Expr::Array(a) => Value::Tuple(a.elems.iter().map(|e| self.eval(e)).collect()),
            Expr::Index(ix) => {
                let base = self.eval(&ix.expr);
                let (data, rows) = match base {
                    Value::Matrix(d, r) => (d, r),
                    other => panic!("indexing {other:?}"),
                };
                let k = self.index(&ix.index, rows);
                Value::Num(data[k])
            }
            Expr::Unary(u) => match u.op {
                UnOp::Neg(_) => Value::Num(-self.eval(&u.expr).num()),
                UnOp::Deref(_) => Value::Tuple(Vec::new()),
                _ => panic!("unary"),
            },
            Expr::Binary(b) => {
                let (l, r) = (self.eval(&b.left).num(), self.eval(&b.right).num());
                Value::Num(match b.op {
                    BinOp::Add(_) => l + r,
                    BinOp::Sub(_) => l - r,
                    BinOp::Mul(_) => l * r,
                    BinOp::Div(_) => l / r,
                    _ => panic!("operator"),
                })
            }
            Expr::Assign(a) => {
                let value = self.eval(&a.right).num();
                let Expr::Index(ix) = &*a.left else {
                    panic!("assignment")
                };
                let Expr::Path(p) = &*ix.expr else {
                    panic!("assignment")
                };
                let name = p.path.segments[0].ident.to_string();
                let rows = match &self.env[&name] {
                    Value::Matrix(_, r) => *r,
                    _ => panic!("assignment"),
                };
                let k = self.index(&ix.index, rows);
                if let Some(Value::Matrix(d, _)) = self.env.get_mut(&name) {
                    d[k] = value;
                }
                Value::Tuple(Vec::new())
            }
            // SVector::<f64, R>::zeros(), SMatrix::<f64, R, C>::zeros(), Vector2::new(x, y)
            Expr::Call(c) => {
                let Expr::Path(p) = &*c.func else {
                    panic!("call")
                };
                let last = p.path.segments.last().unwrap().ident.to_string();
                if last == "new" {
                    let entries: Vec<f64> = c.args.iter().map(|a| self.eval(a).num()).collect();
                    let n = entries.len();
                    return Value::Matrix(entries, n);
                }
                let dims: Vec<usize> = p
                    .path
                    .segments
                    .iter()
                    .flat_map(|s| match &s.arguments {
                        syn::PathArguments::AngleBracketed(a) => a
                            .args
                            .iter()
                            .filter_map(|g| match g {
                                syn::GenericArgument::Const(Expr::Lit(l)) => match &l.lit {
                                    Lit::Int(i) => i.base10_parse().ok(),
                                    _ => None,
                                },
                                _ => None,
                            })
                            .collect::<Vec<usize>>(),
                        _ => Vec::new(),
                    })
                    .collect();
                let (rows, cols) = (dims[0], dims.get(1).copied().unwrap_or(1));
                Value::Matrix(vec![0.0; rows * cols], rows)
            }
            Expr::MethodCall(m) => {
                let receiver = self.eval(&m.receiver).num();
                let args: Vec<f64> = m.args.iter().map(|a| self.eval(a).num()).collect();
                let name = m.method.to_string();
                if name == "sin_cos" {
                    let (s, c) = receiver.sin_cos();
                    return Value::Tuple(vec![Value::Num(s), Value::Num(c)]);
                }
                Value::Num(match (name.as_str(), args.as_slice()) {
                    ("sin", []) => receiver.sin(),
                    ("cos", []) => receiver.cos(),
                    ("tan", []) => receiver.tan(),
                    ("asin", []) => receiver.asin(),
                    ("acos", []) => receiver.acos(),
                    ("atan", []) => receiver.atan(),
                    ("sinh", []) => receiver.sinh(),
                    ("cosh", []) => receiver.cosh(),
                    ("tanh", []) => receiver.tanh(),
                    ("sqrt", []) => receiver.sqrt(),
                    ("exp", []) => receiver.exp(),
                    ("ln", []) => receiver.ln(),
                    ("abs", []) => receiver.abs(),
                    ("signum", []) => receiver.signum(),
                    ("powi", [n]) => receiver.powi(*n as i32),
                    ("powf", [y]) => receiver.powf(*y),
                    ("atan2", [x]) => receiver.atan2(*x),
                    ("hypot", [y]) => receiver.hypot(*y),
                    _ => panic!("method {name}"),
                })
            }
            other => panic!("unexpected expression {}", quote::quote!(#other)),
        }
    }

    /// `[k]` or `[(i, j)]` into column-major storage.
    fn index(&mut self, index: &Expr, rows: usize) -> usize {
        match index {
            Expr::Tuple(t) => {
                let i = self.eval(&t.elems[0]).num() as usize;
                let j = self.eval(&t.elems[1]).num() as usize;
                j * rows + i
            }
            e => self.eval(e).num() as usize,
        }
    }
}

fn constant(name: &str) -> f64 {
    use std::f64::consts::*;
    match name {
        "PI" => PI,
        "TAU" => TAU,
        "E" => E,
        "FRAC_PI_2" => FRAC_PI_2,
        "FRAC_PI_3" => FRAC_PI_3,
        "FRAC_PI_4" => FRAC_PI_4,
        "FRAC_PI_6" => FRAC_PI_6,
        "FRAC_PI_8" => FRAC_PI_8,
        "SQRT_2" => SQRT_2,
        "LN_2" => LN_2,
        "LN_10" => LN_10,
        other => panic!("constant {other}"),
    }
}

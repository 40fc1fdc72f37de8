//! Stage 2: names resolved and expressions lowered into the DAG.
//!
//! A name in an equation is, in this order of lookup, a coordinate, a point
//! (only as `P.x`/`P.y`), a parameter (an `f64` field of the struct) or a
//! constant of `core::f64::consts`. Every mistake is recorded with the span of
//! the offending token, and lowering continues so that all mistakes of one
//! attribute are reported together.
//!
//! One idea in a little over 600 lines: the lookup of every name and the
//! lowering of every expression form Rust allows in an equation belong
//! together, as each form's errors speak of the names around it.

use crate::ast::{Input, unraw};
use crate::dag::{Constant, Dag, Func, Func2, Id, Symbol};
use crate::errors::Errors;
use crate::owner::Owner;
use std::collections::HashMap;
use syn::{BinOp, Expr, Ident, Lit, Member, UnOp};

/// What a name refers to.
#[derive(Clone, Debug)]
enum Binding {
    Param(u16),
    /// A field that is not `f64`: named in messages, never usable.
    OtherField(String),
    Coord(u16),
    Point(usize),
}

/// Names of the generated functions' arguments, which a coordinate or a
/// point may not take.
const RESERVED: [&str; 8] = ["u", "v", "udot", "vdot", "uddot", "vddot", "params", "self"];

/// The supported functions, for messages.
pub const SUPPORTED: &str = "sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, tanh, sqrt, exp, ln, \
                             abs, hypot, powi (integer literal exponent), powf";

/// The mechanism after name resolution: the DAG and its roots.
pub struct Lowered {
    pub dag: Dag,
    /// The `f64` fields, in order: `Symbol::Param(k)` is `fields[k]`.
    pub fields: Vec<Ident>,
    /// The parameters p to differentiate by, as indices into `fields`
    /// (set by [`crate::params::resolve`]; empty until then).
    pub params: Vec<u16>,
    /// u then v: `Symbol::Coord(k)` is `coords[k]`.
    pub coords: Vec<Ident>,
    pub m: usize,
    pub f: usize,
    pub points: Vec<(Ident, Id, Id)>,
    pub closure: Vec<Id>,
}

struct Lowerer<'a> {
    dag: Dag,
    names: HashMap<String, Binding>,
    /// The lowered coordinates of the points defined so far.
    points: Vec<(Id, Id)>,
    point_names: Vec<Ident>,
    /// (point used, point being defined) pairs already reported.
    early_uses: std::collections::HashSet<(usize, usize)>,
    owner: &'a Owner,
    errors: &'a mut Errors,
}

/// Resolves every name of `input` and lowers its expressions.
pub fn lower(input: &Input, errors: &mut Errors) -> Option<Lowered> {
    let owner = &input.owner;
    let mut names: HashMap<String, Binding> = HashMap::new();
    let mut params = Vec::new();
    for field in &input.fields {
        let binding = if field.is_f64 {
            params.push(field.ident.clone());
            Binding::Param((params.len() - 1) as u16)
        } else {
            Binding::OtherField(field.ty.clone())
        };
        names.insert(unraw(&field.ident), binding);
    }

    let m = input.u.items.len();
    let f = input.v.items.len();
    let coords: Vec<Ident> = input
        .u
        .items
        .iter()
        .chain(&input.v.items)
        .cloned()
        .collect();
    let mut declared: HashMap<String, (&'static str, proc_macro2::Span)> = HashMap::new();
    let mut declare = |ident: &Ident,
                       kind: &'static str,
                       names: &mut HashMap<String, Binding>,
                       binding: Binding,
                       errors: &mut Errors| {
        let name = unraw(ident);
        if RESERVED.contains(&name.as_str()) {
            errors.push(syn::Error::new(
                ident.span(),
                format!(
                    "`{name}` is the name of an argument of the generated functions; \
                     choose another name for this {}",
                    kind.split(' ').next().unwrap_or(kind)
                ),
            ));
            return;
        }
        if let Some((first_kind, first_span)) = declared.get(&name) {
            let mut e = syn::Error::new(
                ident.span(),
                format!(
                    "`{name}` is declared twice: first as a {first_kind}, again as a {kind}; names must be unique"
                ),
            );
            e.combine(syn::Error::new(
                *first_span,
                format!("`{name}` is first declared here"),
            ));
            errors.push(e);
            return;
        }
        declared.insert(name.clone(), (kind, ident.span()));
        if let Some(Binding::Param(_) | Binding::OtherField(_)) = names.get(&name) {
            errors.push(syn::Error::new(
                ident.span(),
                format!(
                    "`{name}` is declared as a {kind} but is also {}; \
                     rename one of them so that every name in the equations means one thing",
                    owner.a_member()
                ),
            ));
            // The name is taken to mean the coordinate or point, as declared,
            // so that no follow-on error is reported.
        }
        names.insert(name, binding);
    };
    for (k, ident) in input.u.items.iter().enumerate() {
        declare(
            ident,
            "coordinate in `u`",
            &mut names,
            Binding::Coord(k as u16),
            errors,
        );
    }
    for (k, ident) in input.v.items.iter().enumerate() {
        declare(
            ident,
            "coordinate in `v`",
            &mut names,
            Binding::Coord((m + k) as u16),
            errors,
        );
    }
    for (k, p) in input.points.items.iter().enumerate() {
        declare(&p.name, "point", &mut names, Binding::Point(k), errors);
    }

    let mut lowerer = Lowerer {
        dag: Dag::new(),
        names,
        points: Vec::new(),
        point_names: input.points.items.iter().map(|p| p.name.clone()).collect(),
        early_uses: Default::default(),
        owner,
        errors,
    };
    let mut points = Vec::new();
    let mut ok = true;
    for p in &input.points.items {
        // Malformed coordinates were reported where they were read.
        let (x, y) = match &p.coords {
            Some((x, y)) => (lowerer.lower(x), lowerer.lower(y)),
            None => (None, None),
        };
        let (x, y) = match (x, y) {
            (Some(x), Some(y)) => (x, y),
            _ => {
                ok = false;
                (Dag::ZERO, Dag::ZERO)
            }
        };
        lowerer.points.push((x, y));
        points.push((p.name.clone(), x, y));
    }
    let mut closure = Vec::new();
    for e in &input.closure.items {
        match lowerer.lower(e) {
            Some(id) => closure.push(id),
            None => ok = false,
        }
    }
    if !ok {
        return None;
    }
    Some(Lowered {
        dag: lowerer.dag,
        fields: params,
        params: Vec::new(),
        coords,
        m,
        f,
        points,
        closure,
    })
}

impl Lowerer<'_> {
    fn error(
        &mut self,
        spanned: &dyn quote::ToTokens,
        message: impl std::fmt::Display,
    ) -> Option<Id> {
        self.errors.push(syn::Error::new_spanned(spanned, message));
        None
    }

    fn lower(&mut self, e: &Expr) -> Option<Id> {
        match e {
            Expr::Lit(lit) => self.literal(&lit.lit),
            Expr::Paren(p) => self.lower(&p.expr),
            Expr::Group(g) => self.lower(&g.expr),
            Expr::Path(p) => self.path(p),
            Expr::Field(field) => self.field(field),
            Expr::Unary(u) => match u.op {
                UnOp::Neg(_) => {
                    let x = self.lower(&u.expr)?;
                    Some(self.dag.neg(x))
                }
                _ => self.error(u, "only unary `-` is supported in an equation"),
            },
            Expr::Binary(b) => self.binary(b),
            Expr::MethodCall(call) => {
                let mut args = vec![&*call.receiver];
                args.extend(call.args.iter());
                if call.turbofish.is_some() {
                    return self.error(call, "type arguments are not supported in an equation");
                }
                self.function(&call.method, &args, call)
            }
            Expr::Call(call) => {
                let Expr::Path(path) = &*call.func else {
                    return self.error(
                        &call.func,
                        format!("not a function name; supported functions: {SUPPORTED}"),
                    );
                };
                let segments: Vec<String> = path
                    .path
                    .segments
                    .iter()
                    .map(|s| s.ident.to_string())
                    .collect();
                let is_plain = path.qself.is_none()
                    && path.path.segments.iter().all(|s| s.arguments.is_none())
                    && (segments.len() == 1 || (segments.len() == 2 && segments[0] == "f64"));
                if !is_plain {
                    return self.error(
                        path,
                        format!(
                            "unsupported function `{}`; supported functions: {SUPPORTED}",
                            quote::quote!(#path).to_string().replace(' ', "")
                        ),
                    );
                }
                let name = &path.path.segments.last()?.ident;
                let args: Vec<&Expr> = call.args.iter().collect();
                self.function(name, &args, call)
            }
            Expr::Cast(c) => self.error(
                c,
                "casts are not needed: every quantity in an equation is an `f64`",
            ),
            other => self.error(
                other,
                "unsupported expression; an equation uses numbers, names, `+ - * /`, unary `-`, \
                 parentheses and the functions "
                    .to_owned()
                    + SUPPORTED,
            ),
        }
    }

    fn literal(&mut self, lit: &Lit) -> Option<Id> {
        let value = match lit {
            Lit::Float(f) => match f.suffix() {
                "" | "f64" => f.base10_parse::<f64>().ok(),
                _ => return self.error(f, "only `f64` literals are supported"),
            },
            Lit::Int(i) => match i.suffix() {
                "" | "f64" => i.base10_digits().parse::<f64>().ok(),
                _ => {
                    return self.error(
                        i,
                        "integer literals in equations are `f64` numbers; drop the suffix",
                    );
                }
            },
            other => return self.error(other, "only numeric literals are supported"),
        };
        match value {
            Some(v) if v.is_finite() => Some(self.dag.num(v)),
            _ => self.error(lit, "this number is not a finite `f64`"),
        }
    }

    fn path(&mut self, p: &syn::ExprPath) -> Option<Id> {
        if p.qself.is_some() || p.path.segments.iter().any(|s| !s.arguments.is_none()) {
            return self.error(p, "unsupported path");
        }
        let segments: Vec<String> = p
            .path
            .segments
            .iter()
            .map(|s| s.ident.to_string())
            .collect();
        if segments.len() == 1 {
            let ident = &p.path.segments[0].ident;
            return self.name(ident);
        }
        // core::f64::consts::PI, std::f64::consts::PI, f64::consts::PI, consts::PI
        let last = segments.last()?;
        let prefix: Vec<&str> = segments[..segments.len() - 1]
            .iter()
            .map(String::as_str)
            .collect();
        let valid_prefix = match prefix.as_slice() {
            ["consts"] | ["f64", "consts"] => p.path.leading_colon.is_none(),
            ["std" | "core", "f64", "consts"] => true,
            _ => false,
        };
        match Constant::from_name(last) {
            Some(c) if valid_prefix => Some(self.dag.sym(Symbol::Constant(c))),
            _ => self.error(
                p,
                format!(
                    "unknown path `{}`; an equation may name the constants of `std::f64::consts` \
                     (e.g. `PI` or `std::f64::consts::PI`), {}, the coordinates \
                     and the points",
                    segments.join("::"),
                    self.owner.its_parameters()
                ),
            ),
        }
    }

    fn name(&mut self, ident: &Ident) -> Option<Id> {
        let name = unraw(ident);
        match self.names.get(&name).cloned() {
            Some(Binding::Param(k)) => Some(self.dag.sym(Symbol::Param(k))),
            Some(Binding::Coord(k)) => Some(self.dag.sym(Symbol::Coord(k))),
            Some(Binding::OtherField(ty)) => self.error(
                ident,
                format!(
                    "field `{name}` of `{}` has type `{ty}`; only `f64` fields are parameters \
                     that equations can use",
                    self.owner.name()
                ),
            ),
            Some(Binding::Point(_)) => self.error(
                ident,
                format!("`{name}` is a point; use its coordinates `{name}.x` and `{name}.y`"),
            ),
            None => {
                if let Some(c) = Constant::from_name(&name) {
                    return Some(self.dag.sym(Symbol::Constant(c)));
                }
                let constants = Constant::ALL.iter().map(|c| c.name());
                let known: Vec<&str> = self
                    .names
                    .keys()
                    .map(String::as_str)
                    .chain(constants)
                    .collect();
                let hint = match crate::suggest::closest(&name, known) {
                    Some(k) => format!("; did you mean `{k}`?"),
                    None => String::new(),
                };
                self.error(
                    ident,
                    format!(
                        "unknown name `{name}`: not a coordinate, a point, {} \
                         or a constant of `std::f64::consts`{hint}",
                        self.owner.a_parameter()
                    ),
                )
            }
        }
    }

    fn field(&mut self, field: &syn::ExprField) -> Option<Id> {
        let member = match &field.member {
            Member::Named(m) => m.to_string(),
            Member::Unnamed(i) => i.index.to_string(),
        };
        let base = match &*field.base {
            Expr::Path(p) if p.qself.is_none() && p.path.get_ident().is_some() => {
                p.path.get_ident()?
            }
            other => {
                return self.error(
                    other,
                    format!("`.{member}` can only follow the name of a point, as in `B.x`"),
                );
            }
        };
        let name = unraw(base);
        let index = match self.names.get(&name) {
            Some(Binding::Point(k)) => *k,
            Some(Binding::Coord(_)) => {
                return self.error(
                    field,
                    format!(
                        "`{name}` is a coordinate, not a point: only points have `.x` and `.y`"
                    ),
                );
            }
            Some(Binding::Param(_) | Binding::OtherField(_)) => {
                return self.error(
                    field,
                    format!(
                        "`{name}` is {}, not a point: only points have `.x` and `.y`",
                        self.owner.a_member()
                    ),
                );
            }
            None => {
                let known: Vec<String> = self.point_names.iter().map(unraw).collect();
                let hint = match crate::suggest::closest(&name, known.iter().map(String::as_str)) {
                    Some(k) => format!("; did you mean `{k}`?"),
                    None => String::new(),
                };
                return self.error(base, format!("unknown point `{name}`{hint}"));
            }
        };
        if index >= self.points.len() {
            // One error per point used too early, not one per use.
            if !self.early_uses.insert((index, self.points.len())) {
                return None;
            }
            let current = self
                .point_names
                .get(self.points.len())
                .map(unraw)
                .unwrap_or_default();
            let message = if index == self.points.len() {
                format!("point `{name}` cannot refer to itself")
            } else {
                format!(
                    "point `{name}` is used before it is defined: points are defined in order, \
                     so define `{name}` before `{current}`"
                )
            };
            return self.error(base, message);
        }
        let (x, y) = self.points[index];
        match member.as_str() {
            "x" => Some(x),
            "y" => Some(y),
            _ => self.error(
                &field.member,
                format!("a point has the coordinates `.x` and `.y`, not `.{member}`"),
            ),
        }
    }

    fn binary(&mut self, b: &syn::ExprBinary) -> Option<Id> {
        // Both sides first, so that their mistakes are reported too.
        let l = self.lower(&b.left);
        let r = self.lower(&b.right);
        let op = match b.op {
            BinOp::Add(_) | BinOp::Sub(_) | BinOp::Mul(_) | BinOp::Div(_) => b.op,
            BinOp::BitXor(_) => {
                return self.error(
                    &b.op,
                    "`^` is exclusive-or in Rust, not a power: write `x.powi(2)` or `x.powf(y)`",
                );
            }
            _ => return self.error(&b.op, "unsupported operator; an equation uses `+ - * /`"),
        };
        let (l, r) = (l?, r?);
        Some(match op {
            BinOp::Add(_) => self.dag.add(l, r),
            BinOp::Sub(_) => self.dag.sub(l, r),
            BinOp::Mul(_) => self.dag.mul(l, r),
            _ => self.dag.div(l, r),
        })
    }

    /// `name(args)` in either form: `x.sin()` has `args = [x]`.
    fn function(
        &mut self,
        name: &Ident,
        args: &[&Expr],
        whole: &dyn quote::ToTokens,
    ) -> Option<Id> {
        let n = name.to_string();
        let unary = match n.as_str() {
            "sin" => Some(Func::Sin),
            "cos" => Some(Func::Cos),
            "tan" => Some(Func::Tan),
            "asin" => Some(Func::Asin),
            "acos" => Some(Func::Acos),
            "atan" => Some(Func::Atan),
            "sinh" => Some(Func::Sinh),
            "cosh" => Some(Func::Cosh),
            "tanh" => Some(Func::Tanh),
            "sqrt" => Some(Func::Sqrt),
            "exp" => Some(Func::Exp),
            "ln" => Some(Func::Ln),
            "abs" => Some(Func::Abs),
            _ => None,
        };
        let binary = match n.as_str() {
            "atan2" => Some(Func2::Atan2),
            "hypot" => Some(Func2::Hypot),
            "powf" => Some(Func2::Powf),
            _ => None,
        };
        let arity = if unary.is_some() {
            1
        } else if binary.is_some() || n == "powi" {
            2
        } else {
            let hint = match n.as_str() {
                "log" | "log10" | "log2" => {
                    " (write `x.ln()`, dividing by `LN_10` or `LN_2` for other bases)".to_owned()
                }
                "sin_cos" => {
                    " (write `x.sin()` and `x.cos()`; the generated code shares them)".to_owned()
                }
                "pow" => " (write `x.powi(n)` or `x.powf(y)`)".to_owned(),
                "cbrt" => " (write `x.powf(1.0 / 3.0)` for x ≥ 0)".to_owned(),
                "sq" | "square" => " (write `x.powi(2)`)".to_owned(),
                _ => String::new(),
            };
            // The arguments' own mistakes are reported too.
            for a in args {
                self.lower(a);
            }
            return self.error(
                name,
                format!("unsupported function `{n}`{hint}; supported functions: {SUPPORTED}"),
            );
        };
        if args.len() != arity {
            let usage = match arity {
                1 => format!("`x.{n}()` or `{n}(x)`"),
                _ if n == "powi" => "`x.powi(2)` or `powi(x, 2)`".to_owned(),
                _ => format!("`a.{n}(b)` or `{n}(a, b)`"),
            };
            return self.error(
                whole,
                format!(
                    "`{n}` takes {arity} argument{}: {usage}",
                    if arity == 1 { "" } else { "s" }
                ),
            );
        }
        if n == "powi" {
            let base = self.lower(args[0]);
            let exponent = self.integer_literal(args[1]);
            let (base, exponent) = (base?, exponent?);
            return Some(self.dag.powi(base, exponent));
        }
        if let Some(func) = unary {
            let a = self.lower(args[0])?;
            return Some(self.dag.call(func, a));
        }
        let a = self.lower(args[0]);
        let b = self.lower(args[1]);
        let (a, b) = (a?, b?);
        Some(self.dag.call2(binary?, a, b))
    }

    /// The exponent of `powi`: an integer literal, possibly negated.
    fn integer_literal(&mut self, e: &Expr) -> Option<i32> {
        const LIMIT: i32 = 1 << 16;
        let value = match e {
            Expr::Lit(syn::ExprLit {
                lit: Lit::Int(i), ..
            }) => i.base10_parse::<i32>().ok(),
            Expr::Unary(syn::ExprUnary {
                op: UnOp::Neg(_),
                expr,
                ..
            }) => match &**expr {
                Expr::Lit(syn::ExprLit {
                    lit: Lit::Int(i), ..
                }) => i.base10_parse::<i32>().ok().map(|v| -v),
                _ => None,
            },
            Expr::Paren(p) => return self.integer_literal(&p.expr),
            Expr::Group(g) => return self.integer_literal(&g.expr),
            _ => {
                self.error(
                    e,
                    "`powi` takes an integer literal exponent, e.g. `x.powi(2)`; \
                     for an exponent that is not a literal use `x.powf(y)`",
                );
                return None;
            }
        };
        match value {
            Some(v) if v.abs() <= LIMIT => Some(v),
            _ => {
                self.error(e, format!("`powi` exponent out of range (|n| ≤ {LIMIT})"));
                None
            }
        }
    }
}

impl Lowered {
    /// The span-free name of a coordinate, for generated identifiers.
    pub fn coord_name(&self, k: usize) -> String {
        unraw(&self.coords[k])
    }

    /// The span-free name of the field `k` (`Symbol::Param(k)`).
    pub fn field_name(&self, k: usize) -> String {
        unraw(&self.fields[k])
    }

    /// The names of the symbols, for generated code and formulas.
    pub fn names(&self) -> crate::names::SymbolNames {
        crate::names::SymbolNames::new(
            (0..self.fields.len()).map(|k| self.field_name(k)).collect(),
            (0..self.coords.len()).map(|k| self.coord_name(k)).collect(),
            self.m,
            self.params.clone(),
        )
    }
}

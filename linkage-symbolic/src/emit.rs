//! Stage 4: straight-line Rust for a set of outputs of the DAG.
//!
//! Common-subexpression elimination works across all outputs of one
//! function: a node used more than once becomes a `let` with a name that
//! says what it is (`s_theta3`, `l3_c_theta3`), every angle's sine and cosine
//! come from one `sin_cos`, and everything used once is written inline.

use crate::dag::{Dag, Func, Func2, Id, Node, Symbol, children};
use crate::display::display_order;
use crate::names::SymbolNames;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::{HashMap, HashSet};

/// The number type of the emitted code.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// `f64`, with literals and methods of `f64`.
    F64,
    /// A generic `D: num_dual::DualNum<Primitive = f64> + Copy`.
    Generic,
}

/// The argument vectors a function reads.
#[derive(Clone, Copy, Default, Debug, PartialEq, Eq)]
pub struct Reads {
    pub u: bool,
    pub v: bool,
    pub udot: bool,
    pub vdot: bool,
    pub uddot: bool,
    pub vddot: bool,
}

/// The emitted body of one function.
pub struct Body {
    /// `let` statements: symbols from the arguments, then temporaries.
    pub statements: Vec<TokenStream>,
    /// One expression per requested root, referring to the temporaries.
    pub values: Vec<TokenStream>,
    pub reads: Reads,
}

/// An identifier for a generated name: names come from the user's
/// identifiers and are valid; anything else is sanitised rather than allowed
/// to panic.
fn ident(name: &str) -> proc_macro2::Ident {
    if let Ok(i) = syn::parse_str::<proc_macro2::Ident>(name) {
        return i;
    }
    let mut clean: String = name
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if clean.is_empty() || clean.starts_with(|c: char| c.is_ascii_digit()) {
        clean.insert_str(0, "t_");
    }
    syn::parse_str::<proc_macro2::Ident>(&clean)
        .or_else(|_| syn::parse_str::<proc_macro2::Ident>(&format!("r#{clean}")))
        .unwrap_or_else(|_| format_ident!("generated_value"))
}

/// Binding strength of an emitted expression.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum Prec {
    Sum,
    Product,
    Unary,
    Atom,
}

struct Emitter<'a> {
    dag: &'a Dag,
    names: &'a SymbolNames,
    mode: Mode,
    /// Temporaries by node.
    bound: HashMap<Id, String>,
}

/// Emits the straight-line code computing `roots`; `hints` names chosen
/// nodes (e.g. a point's coordinates) and always binds them.
pub fn emit(
    dag: &Dag,
    names: &SymbolNames,
    roots: &[Id],
    hints: &[(Id, String)],
    reserved: &[String],
    mode: Mode,
) -> Body {
    let phased = emit_phases(dag, names, &[roots], hints, reserved, mode, &[], None);
    let mut statements = phased.prologue;
    let mut phases = phased.phases.into_iter();
    let (phase_statements, values) = phases.next().unwrap_or_default();
    statements.extend(phase_statements);
    Body {
        statements,
        values,
        reads: phased.reads,
    }
}

/// Code in phases: the values of phase k may use everything computed in
/// phases before it, and the `late` symbols become available only from
/// phase 1 on (the caller binds them between the phases — e.g. the
/// velocities u̇, solved for after phase 0). Common subexpressions are
/// shared across all phases, each computed in the first phase that needs it.
pub struct Phased {
    /// Reading the (early) symbols from the arguments.
    pub prologue: Vec<TokenStream>,
    /// For each phase: its statements and the values of its roots.
    pub phases: Vec<(Vec<TokenStream>, Vec<TokenStream>)>,
    pub reads: Reads,
    /// The coordinates (indices into q = (u, v)) whose sine or cosine is read
    /// from the [`TrigSource`], ascending.
    pub trig_coords: Vec<usize>,
}

/// Sines and cosines of the coordinates given by the caller instead of
/// computed: `u[k]` is (sin, cos) of u's coordinate k, `v[k]` of v's.
pub struct TrigSource {
    pub u: proc_macro2::Ident,
    pub v: proc_macro2::Ident,
    pub m: usize,
}

#[allow(clippy::too_many_arguments)]
pub fn emit_phases(
    dag: &Dag,
    names: &SymbolNames,
    phases: &[&[Id]],
    hints: &[(Id, String)],
    reserved: &[String],
    mode: Mode,
    late: &[Symbol],
    trig_source: Option<&TrigSource>,
) -> Phased {
    // Reachable nodes, their use counts, and the first phase needing each.
    let mut uses: HashMap<Id, usize> = HashMap::new();
    let mut phase_of: HashMap<Id, usize> = HashMap::new();
    for (p, roots) in phases.iter().enumerate() {
        let mut stack: Vec<Id> = roots.to_vec();
        for &r in roots.iter() {
            *uses.entry(r).or_default() += 1;
        }
        while let Some(id) = stack.pop() {
            if phase_of.contains_key(&id) {
                continue;
            }
            phase_of.insert(id, p);
            for c in children(dag.node(id)) {
                if c != Dag::ONE {
                    *uses.entry(c).or_default() += 1;
                }
                stack.push(c);
            }
        }
    }
    let mut order: Vec<Id> = phase_of.keys().copied().collect();
    order.sort();

    let hint_of: HashMap<Id, &str> = hints
        .iter()
        .rev()
        .map(|(id, name)| (*id, name.as_str()))
        .collect();

    // Which nodes become temporaries.
    let is_trig = |id: Id| matches!(dag.node(id), Node::Call(Func::Sin | Func::Cos, _));
    let to_bind: Vec<Id> = order
        .iter()
        .copied()
        .filter(|&id| match dag.node(id) {
            Node::Const(_) | Node::Sym(_) => false,
            _ if hint_of.contains_key(&id) || is_trig(id) => true,
            Node::Sum(terms) if terms.len() == 1 => false,
            _ => uses.get(&id).copied().unwrap_or(0) >= 2,
        })
        .collect();

    let mut taken: HashSet<String> = names.all_code().collect();
    taken.extend(["u", "v", "udot", "vdot", "uddot", "vddot", "self", "D"].map(str::to_owned));
    taken.extend(reserved.iter().cloned());
    let mut emitter = Emitter {
        dag,
        names,
        mode,
        bound: HashMap::new(),
    };

    // Sine and cosine of the same angle share one sin_cos, in the first
    // phase that needs either.
    let mut trig_pairs: HashMap<Id, (Option<Id>, Option<Id>)> = HashMap::new();
    for &id in &to_bind {
        match dag.node(id) {
            Node::Call(Func::Sin, a) => trig_pairs.entry(*a).or_default().0 = Some(id),
            Node::Call(Func::Cos, a) => trig_pairs.entry(*a).or_default().1 = Some(id),
            _ => {}
        }
    }
    for (sin, cos) in trig_pairs.values() {
        if let (Some(sin), Some(cos)) = (sin, cos) {
            let first = phase_of[sin].min(phase_of[cos]);
            phase_of.insert(*sin, first);
            phase_of.insert(*cos, first);
        }
    }
    let mut angle_count = 0;
    for &id in &to_bind {
        if emitter.bound.contains_key(&id) {
            continue;
        }
        if let Node::Call(Func::Sin | Func::Cos, a) = dag.node(id) {
            let (sin, cos) = trig_pairs[a];
            let mut base = emitter.structural_name(*a);
            if base.len() > 24 {
                angle_count += 1;
                base = format!("angle{angle_count}");
            }
            for (node, prefix) in [(sin, "s"), (cos, "c")] {
                if let Some(node) = node {
                    let name = unique(format!("{prefix}_{base}"), &mut taken);
                    emitter.bound.insert(node, name);
                }
            }
            continue;
        }
        let name = match hint_of.get(&id) {
            Some(h) => h.to_string(),
            None => {
                let s = emitter.structural_name(id);
                if s.len() > 28 {
                    emitter.kind_name(id)
                } else {
                    s
                }
            }
        };
        let name = unique(name, &mut taken);
        emitter.bound.insert(id, name);
    }

    // The symbols read from the arguments (the late ones by the caller).
    let mut reads = Reads::default();
    let mut trig_coords = std::collections::BTreeSet::new();
    let mut symbols: Vec<Symbol> = order
        .iter()
        .filter_map(|&id| match dag.node(id) {
            Node::Sym(s) if !late.contains(s) => Some(*s),
            _ => None,
        })
        .collect();
    symbols.sort();
    let prologue = emitter.prologue(&symbols, &mut reads);

    // The temporaries of each phase, in topological order.
    let mut emitted_pairs: HashSet<Id> = HashSet::new();
    let mut out = Vec::with_capacity(phases.len());
    for (p, roots) in phases.iter().enumerate() {
        let mut statements = Vec::new();
        for &id in to_bind.iter().filter(|id| phase_of[id] == p) {
            let name = ident(&emitter.bound[&id]);
            if let Node::Call(f @ (Func::Sin | Func::Cos), a) = dag.node(id) {
                let (sin, cos) = trig_pairs[a];
                // A coordinate's sine and cosine from the caller.
                if let (Some(source), Node::Sym(Symbol::Coord(k))) = (trig_source, dag.node(*a)) {
                    let k = *k as usize;
                    trig_coords.insert(k);
                    let (array, index) = if k < source.m {
                        (&source.u, k)
                    } else {
                        (&source.v, k - source.m)
                    };
                    let index = Literal::usize_unsuffixed(index);
                    match (sin, cos) {
                        (Some(s), Some(c)) => {
                            if emitted_pairs.insert(*a) {
                                let (s, c) = (ident(&emitter.bound[&s]), ident(&emitter.bound[&c]));
                                statements.push(quote! { let (#s, #c) = #array[#index]; });
                            }
                        }
                        _ => {
                            let field = Literal::usize_unsuffixed(usize::from(*f == Func::Cos));
                            statements.push(quote! { let #name = #array[#index].#field; });
                        }
                    }
                    continue;
                }
                let arg = emitter.operand(*a, Prec::Atom);
                match (sin, cos) {
                    (Some(s), Some(c)) => {
                        if emitted_pairs.insert(*a) {
                            let (s, c) = (ident(&emitter.bound[&s]), ident(&emitter.bound[&c]));
                            statements.push(quote! { let (#s, #c) = #arg.sin_cos(); });
                        }
                    }
                    _ => {
                        let method = format_ident!("{}", f.method());
                        statements.push(quote! { let #name = #arg.#method(); });
                    }
                }
                continue;
            }
            let value = emitter.definition(id).0;
            statements.push(quote! { let #name = #value; });
        }
        let values = roots
            .iter()
            .map(|&r| emitter.operand(r, Prec::Sum))
            .collect();
        out.push((statements, values));
    }
    Phased {
        prologue,
        phases: out,
        reads,
        trig_coords: trig_coords.into_iter().collect(),
    }
}

/// `a * b * c`
fn join_products(factors: Vec<TokenStream>) -> TokenStream {
    let mut out = TokenStream::new();
    for (k, f) in factors.into_iter().enumerate() {
        if k > 0 {
            out.extend(quote!(*));
        }
        out.extend(f);
    }
    out
}

fn unique(name: String, taken: &mut HashSet<String>) -> String {
    let mut candidate = name.clone();
    let mut k = 2;
    while taken.contains(&candidate) {
        candidate = format!("{name}_{k}");
        k += 1;
    }
    taken.insert(candidate.clone());
    candidate
}

impl Emitter<'_> {
    /// `let Self { l2, .. } = *self;` and `let (theta3, theta4) = (u[0], u[1]);`
    fn prologue(&self, symbols: &[Symbol], reads: &mut Reads) -> Vec<TokenStream> {
        let mut out = Vec::new();
        let m = self.names.m();
        let mut params = Vec::new();
        let mut sources: [(Vec<TokenStream>, Vec<TokenStream>); 6] = Default::default();
        for &s in symbols {
            let name = ident(&self.names.code(s));
            let (source, k) = match s {
                Symbol::Param(_) => {
                    params.push(name);
                    continue;
                }
                Symbol::Constant(_) => continue,
                Symbol::Coord(k) => (0, k as usize),
                Symbol::Vel(k) => (2, k as usize),
                Symbol::Acc(k) => (4, k as usize),
            };
            let (source, index) = if k < m {
                (source, k)
            } else {
                (source + 1, k - m)
            };
            let vector = format_ident!("{}", ["u", "v", "udot", "vdot", "uddot", "vddot"][source]);
            let index = Literal::usize_unsuffixed(index);
            sources[source].0.push(quote!(#name));
            sources[source].1.push(quote!(#vector[#index]));
        }
        for (k, (names, values)) in sources.iter().enumerate() {
            if names.is_empty() {
                continue;
            }
            match k {
                0 => reads.u = true,
                1 => reads.v = true,
                2 => reads.udot = true,
                3 => reads.vdot = true,
                4 => reads.uddot = true,
                _ => reads.vddot = true,
            }
            if names.len() == 1 {
                let (n, v) = (&names[0], &values[0]);
                out.push(quote! { let #n = #v; });
            } else {
                out.push(quote! { let (#(#names),*) = (#(#values),*); });
            }
        }
        if !params.is_empty() {
            let line = match self.mode {
                Mode::F64 => quote! { let Self { #(#params,)* .. } = *self; },
                Mode::Generic => quote! { #(let #params = D::from(self.#params);)* },
            };
            out.insert(0, line);
        }
        out
    }

    /// A readable name built from the node's structure.
    fn structural_name(&self, id: Id) -> String {
        if let Some(name) = self.bound.get(&id) {
            return name.clone();
        }
        match self.dag.node(id) {
            Node::Const(c) => {
                let c = c.get();
                if c.fract() == 0.0 && c.abs() < 1e6 {
                    format!("{}{}", if c < 0.0 { "m" } else { "" }, c.abs() as i64)
                } else {
                    "k".to_owned()
                }
            }
            Node::Sym(s) => self.names.code(*s),
            Node::Call(f, a) => {
                let prefix = match f {
                    Func::Sin => "s",
                    Func::Cos => "c",
                    other => other.method(),
                };
                format!("{prefix}_{}", self.structural_name(*a))
            }
            Node::Call2(f, a, b) => {
                let prefix = match f {
                    Func2::Powf => "pow",
                    other => other.method(),
                };
                format!(
                    "{prefix}_{}_{}",
                    self.structural_name(*a),
                    self.structural_name(*b)
                )
            }
            Node::Sum(terms) if terms.len() == 1 => {
                let (c, t) = (terms[0].0.get(), terms[0].1);
                if c == -1.0 {
                    format!("neg_{}", self.structural_name(t))
                } else {
                    format!("k_{}", self.structural_name(t))
                }
            }
            Node::Sum(terms) => {
                let ordered =
                    display_order(self.dag, terms.iter().map(|&(c, t)| (c.get(), t)).collect());
                let mut s = String::new();
                for (k, (c, t)) in ordered.into_iter().enumerate() {
                    let part = if t == Dag::ONE {
                        "1".to_owned()
                    } else {
                        self.structural_name(t)
                    };
                    let joiner = match (k, c < 0.0) {
                        (0, false) => "",
                        (0, true) => "neg_",
                        (_, false) => "_plus_",
                        (_, true) => "_minus_",
                    };
                    s.push_str(joiner);
                    if c.abs() != 1.0 {
                        s.push_str("k_");
                    }
                    s.push_str(&part);
                }
                s
            }
            Node::Prod(factors) => {
                let mut num = Vec::new();
                let mut den = Vec::new();
                for (f, e) in crate::display::factor_order(self.dag, factors) {
                    let base = self.structural_name(f);
                    let text = match e.unsigned_abs() {
                        1 => base,
                        2 => format!("{base}_sq"),
                        3 => format!("{base}_cube"),
                        n => format!("{base}_pow{n}"),
                    };
                    if e > 0 {
                        num.push(text)
                    } else {
                        den.push(text)
                    }
                }
                match (num.is_empty(), den.is_empty()) {
                    (_, true) => num.join("_"),
                    (true, false) => format!("inv_{}", den.join("_")),
                    (false, false) => format!("{}_over_{}", num.join("_"), den.join("_")),
                }
            }
        }
    }

    /// A short name saying what kind of quantity a node is, when its
    /// structure is too long to spell out.
    fn kind_name(&self, id: Id) -> String {
        match self.dag.node(id) {
            Node::Sum(_) => "sum".to_owned(),
            Node::Prod(f) if f.iter().any(|&(_, e)| e < 0) => "ratio".to_owned(),
            Node::Prod(_) => "product".to_owned(),
            Node::Call(f, _) => f.method().to_owned(),
            Node::Call2(Func2::Powf, ..) => "power".to_owned(),
            Node::Call2(f, ..) => f.method().to_owned(),
            Node::Const(_) | Node::Sym(_) => "value".to_owned(),
        }
    }

    fn literal(&self, c: f64) -> (TokenStream, Prec) {
        let lit = Literal::f64_unsuffixed(c.abs());
        let tokens = match self.mode {
            Mode::F64 if c < 0.0 => quote!(-#lit),
            Mode::F64 => quote!(#lit),
            Mode::Generic if c < 0.0 => quote!(D::from(-#lit)),
            Mode::Generic => quote!(D::from(#lit)),
        };
        let prec = match self.mode {
            Mode::F64 if c < 0.0 => Prec::Unary,
            // A bare float literal cannot receive a method call.
            Mode::F64 => Prec::Product,
            Mode::Generic => Prec::Atom,
        };
        (tokens, prec)
    }

    /// The node as an operand that binds at least as tightly as `at_least`.
    fn operand(&self, id: Id, at_least: Prec) -> TokenStream {
        let (tokens, prec) = match self.bound.get(&id) {
            Some(name) => {
                let name = ident(name);
                (quote!(#name), Prec::Atom)
            }
            None => self.definition(id),
        };
        if prec < at_least {
            quote!((#tokens))
        } else {
            tokens
        }
    }

    /// The expression defining a node (its children by name if bound).
    fn definition(&self, id: Id) -> (TokenStream, Prec) {
        match self.dag.node(id) {
            Node::Const(c) => self.literal(c.get()),
            Node::Sym(Symbol::Constant(c)) => {
                let name = format_ident!("{}", c.name());
                match self.mode {
                    Mode::F64 => (quote!(::core::f64::consts::#name), Prec::Atom),
                    Mode::Generic => (quote!(D::from(::core::f64::consts::#name)), Prec::Atom),
                }
            }
            Node::Sym(s) => {
                let name = ident(&self.names.code(*s));
                (quote!(#name), Prec::Atom)
            }
            Node::Sum(terms) => self.sum(terms.iter().map(|&(c, t)| (c.get(), t)).collect()),
            Node::Prod(factors) => (self.product(1.0, factors), Prec::Product),
            Node::Call(f, a) => {
                let arg = self.operand(*a, Prec::Atom);
                let method = format_ident!("{}", f.method());
                (quote!(#arg.#method()), Prec::Atom)
            }
            Node::Call2(f, a, b) => {
                let x = self.operand(*a, Prec::Atom);
                let tokens = match (f, self.mode) {
                    (Func2::Atan2, _) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.atan2(#y))
                    }
                    (Func2::Hypot, Mode::F64) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.hypot(#y))
                    }
                    (Func2::Hypot, Mode::Generic) => {
                        let y = self.operand(*b, Prec::Atom);
                        quote!((#x.powi(2) + #y.powi(2)).sqrt())
                    }
                    (Func2::Powf, Mode::F64) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.powf(#y))
                    }
                    (Func2::Powf, Mode::Generic) => match self.dag.as_const(*b) {
                        Some(c) => {
                            let c = Literal::f64_unsuffixed(c.abs());
                            let c = if self.dag.as_const(*b).is_some_and(|c| c < 0.0) {
                                quote!(-#c)
                            } else {
                                quote!(#c)
                            };
                            quote!(#x.powf(#c))
                        }
                        None => {
                            let y = self.operand(*b, Prec::Sum);
                            quote!(#x.powd(#y))
                        }
                    },
                };
                (tokens, Prec::Atom)
            }
        }
    }

    /// `Σ cᵢ·tᵢ` in reading order.
    fn sum(&self, terms: Vec<(f64, Id)>) -> (TokenStream, Prec) {
        let single = terms.len() == 1;
        let ordered = display_order(self.dag, terms);
        let mut out = TokenStream::new();
        for (k, (c, t)) in ordered.into_iter().enumerate() {
            let magnitude = if t == Dag::ONE && k > 0 {
                // `x + 2.0` is valid for `f64` and for a dual number alike.
                let lit = Literal::f64_unsuffixed(c.abs());
                quote!(#lit)
            } else if t == Dag::ONE {
                self.literal(c.abs()).0
            } else {
                self.scaled(c.abs(), t)
            };
            match (k, c < 0.0) {
                (0, false) => out.extend(magnitude),
                (0, true) => out.extend(quote!(-#magnitude)),
                (_, false) => out.extend(quote!(+ #magnitude)),
                (_, true) => out.extend(quote!(- #magnitude)),
            }
        }
        let prec = if !single {
            Prec::Sum
        } else if out.to_string().starts_with('-') {
            Prec::Unary
        } else {
            Prec::Product
        };
        (out, prec)
    }

    /// `c·t` for `c > 0`, as a product chain.
    fn scaled(&self, c: f64, t: Id) -> TokenStream {
        if let (None, Node::Prod(factors)) = (self.bound.get(&t), self.dag.node(t)) {
            return self.product(c, factors);
        }
        let operand = self.operand(t, Prec::Product);
        if c == 1.0 {
            return operand;
        }
        let lit = Literal::f64_unsuffixed(c);
        match self.mode {
            Mode::F64 => quote!(#lit * #operand),
            Mode::Generic => quote!(#operand * #lit),
        }
    }

    /// `c·Π fᵢ^eᵢ` as `c * a * b / (d * e.powi(2))`.
    fn product(&self, c: f64, factors: &[(Id, i32)]) -> TokenStream {
        let power = |f: Id, e: u32| -> TokenStream {
            if e == 1 {
                self.operand(f, Prec::Unary)
            } else {
                let base = self.operand(f, Prec::Atom);
                let e = Literal::i32_unsuffixed(e as i32);
                quote!(#base.powi(#e))
            }
        };
        let factors = crate::display::factor_order(self.dag, factors);
        let numerator: Vec<TokenStream> = factors
            .iter()
            .filter(|f| f.1 > 0)
            .map(|&(f, e)| power(f, e.unsigned_abs()))
            .collect();
        let denominator: Vec<TokenStream> = factors
            .iter()
            .filter(|f| f.1 < 0)
            .map(|&(f, e)| power(f, e.unsigned_abs()))
            .collect();
        let lit = Literal::f64_unsuffixed(c);
        let numerator = join_products(numerator);
        let mut num = match (self.mode, numerator.is_empty(), c == 1.0) {
            (Mode::F64, true, _) => quote!(#lit),
            (Mode::F64, false, true) => numerator.clone(),
            (Mode::F64, false, false) => quote!(#lit * #numerator),
            (Mode::Generic, true, _) => quote!(D::from(#lit)),
            (Mode::Generic, false, _) => numerator.clone(),
        };
        match denominator.len() {
            0 => {}
            1 => {
                let d = &denominator[0];
                num = quote!(#num / #d);
            }
            _ => {
                let d = join_products(denominator);
                num = quote!(#num / (#d));
            }
        }
        if self.mode == Mode::Generic && c != 1.0 && !numerator.is_empty() {
            num = quote!(#num * #lit);
        }
        num
    }
}

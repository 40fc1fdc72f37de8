//! Stage 4: straight-line Rust for a set of outputs of the DAG.
//!
//! Common-subexpression elimination works across all outputs of one
//! function: a node used more than once becomes a `let` with a name that
//! says what it is (`s_theta3`, `l3_c_theta3`), every angle's sine and cosine
//! come from one `sin_cos`, and everything used once is written inline.

use crate::dag::{Dag, Func, Func2, Id, Node, Symbol, children};
use crate::display::display_order;
use crate::hasher::{FastMap, FastSet};
use crate::names::SymbolNames;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

mod expr;

/// The number type of the emitted code.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// `f64`, with literals and methods of `f64`.
    F64,
    /// A generic `D: num_dual::DualNum<Primitive = f64> + Copy`; the
    /// parameters differentiated by are read from the argument `params` if
    /// `params_from_p`, else every parameter from `self`.
    Generic { params_from_p: bool },
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
    /// The parameter vector `params` (generic functions of the parameters).
    pub p: bool,
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
    // The common case without tokenizing: what `syn` reads as an identifier.
    if is_plain_identifier(name) {
        return proc_macro2::Ident::new(name, proc_macro2::Span::call_site());
    }
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

/// An ASCII identifier that is not a keyword (nor `_`): one that
/// `syn::parse_str::<Ident>` accepts as it is.
fn is_plain_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    let first_ok = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    let keyword = matches!(
        name,
        "_" | "abstract"
            | "as"
            | "async"
            | "await"
            | "become"
            | "box"
            | "break"
            | "const"
            | "continue"
            | "crate"
            | "do"
            | "dyn"
            | "else"
            | "enum"
            | "extern"
            | "false"
            | "final"
            | "fn"
            | "for"
            | "if"
            | "impl"
            | "in"
            | "let"
            | "loop"
            | "macro"
            | "match"
            | "mod"
            | "move"
            | "mut"
            | "override"
            | "priv"
            | "pub"
            | "ref"
            | "return"
            | "Self"
            | "self"
            | "static"
            | "struct"
            | "super"
            | "trait"
            | "true"
            | "try"
            | "type"
            | "typeof"
            | "unsafe"
            | "unsized"
            | "use"
            | "virtual"
            | "where"
            | "while"
            | "yield"
    );
    first_ok && chars.all(|c| c.is_ascii_alphanumeric() || c == '_') && !keyword
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
    bound: FastMap<Id, String>,
    /// The bound products whose `let` is already written, which a later
    /// product containing their factors reuses, by their first factor (a
    /// product within another has its first factor there too, so only
    /// these few are candidates).
    products: FastMap<(Id, i32), Vec<Id>>,
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

impl Phased {
    /// Code in one phase as one body: the prologue's statements, then the
    /// phase's.
    pub fn into_body(self) -> Body {
        let mut statements = self.prologue;
        let (phase, values) = self.phases.into_iter().next().unwrap_or_default();
        statements.extend(phase);
        Body {
            statements,
            values,
            reads: self.reads,
        }
    }
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
    let mut uses: FastMap<Id, usize> = FastMap::default();
    let mut phase_of: FastMap<Id, usize> = FastMap::default();
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

    let hint_of: FastMap<Id, &str> = hints
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

    let mut taken: FastSet<String> = names.all_code().collect();
    taken.extend(
        [
            "u", "v", "udot", "vdot", "uddot", "vddot", "params", "self", "D",
        ]
        .map(str::to_owned),
    );
    taken.extend(reserved.iter().cloned());
    let mut emitter = Emitter {
        dag,
        names,
        mode,
        bound: FastMap::default(),
        products: FastMap::default(),
    };

    // Sine and cosine of the same angle share one sin_cos, in the first
    // phase that needs either.
    let mut trig_pairs: FastMap<Id, (Option<Id>, Option<Id>)> = FastMap::default();
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
    let mut emitted_pairs: FastSet<Id> = FastSet::default();
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
                let arg = emitter.receiver(*a);
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
            if let Node::Prod(factors) = dag.node(id)
                && let Some(&first) = factors.first()
            {
                emitter.products.entry(first).or_default().push(id);
            }
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

fn unique(name: String, taken: &mut FastSet<String>) -> String {
    let mut candidate = name.clone();
    let mut k = 2;
    while taken.contains(&candidate) {
        candidate = format!("{name}_{k}");
        k += 1;
    }
    taken.insert(candidate.clone());
    candidate
}

#[cfg(test)]
mod ident_tests {
    use super::{ident, is_plain_identifier};

    /// The fast path takes only what `syn` takes, as it is; the rest goes
    /// the way it went.
    #[test]
    fn a_plain_identifier_is_what_syn_reads() {
        for name in [
            "theta3",
            "l2_c_theta3",
            "_x",
            "Self",
            "self",
            "type",
            "_",
            "r#type",
            "3x",
            "θ3",
            "a-b",
            "",
            "trig_u",
            "gen",
            "union",
            "x9_",
        ] {
            let parsed = syn::parse_str::<proc_macro2::Ident>(name).ok();
            if is_plain_identifier(name) {
                assert_eq!(
                    parsed.as_ref().map(|i| i.to_string()),
                    Some(name.to_owned()),
                    "{name}"
                );
            }
            if let Some(parsed) = parsed {
                assert_eq!(ident(name), parsed, "{name}");
            }
        }
    }
}

//! Fuzzing the attribute: the parser and the expression engine fed
//! arbitrary and mutated token streams (one idea in 735 lines: five
//! campaigns sharing one corpus, one dictionary and one set of
//! properties). The properties:
//!
//! - `expand` never panics, whatever the tokens;
//! - it always gives either the generated items or at least one
//!   `syn::Error` (never neither, never an internal error), and every error
//!   has a message;
//! - whenever the item is a valid Rust item (the only kind the compiler
//!   hands an attribute), the output parses as Rust items, so the user sees
//!   our errors and not a cascade of syntax errors;
//! - an attribute built only from supported forms is either accepted or
//!   rejected for a structural reason (a coordinate in no equation, a
//!   singular Jacobian), never as "unsupported".
//!
//! Why not `cargo fuzz`: libFuzzer needs `-Zsanitizer`, a nightly-only
//! flag, and this project builds on stable; `afl` needs its own compiler
//! wrapper and a long-running fuzzer process, which CI cannot host. These
//! are proptest campaigns instead — a corpus of real attributes mutated
//! token by token (deleted, duplicated, swapped, replaced by tokens from a
//! dictionary of the attribute's words and Rust's awkward literals), plus
//! token soup and random expression trees — with a fixed random state so that a CI
//! failure reproduces, and shrinking to the smallest failing input.
//!
//! The number of cases per campaign is `LINKAGE_FUZZ_CASES` (default 1000,
//! what CI runs); the long run:
//!
//!     LINKAGE_FUZZ_CASES=1000000 cargo test --release -p linkage-macros fuzz -- --nocapture

use linkage_symbolic::generate::{expand, run};
use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::Cell;
use std::str::FromStr;
use std::time::Instant;

fn cases() -> u32 {
    std::env::var("LINKAGE_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000)
}

fn runner() -> TestRunner {
    let mut config = Config::with_cases(cases());
    config.failure_persistence = None;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x6675_7a7a_6c69_6e6b);
    }
    TestRunner::new(config)
}

/// Real attributes and their structs: the worksheet's four-bar with points, a
/// slider-crank, a two-loop six-bar and the shaper's mechanism, each one
/// accepted as written.
const CORPUS: &[(&str, &str)] = &[
    (
        "u = [theta3, theta4], v = [theta2],
         points = [
             B = (l2 * theta2.cos(), l2 * theta2.sin()),
             C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
             G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
         ],
         closure = [
             l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
             l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
         ],",
        "#[derive(Clone, Debug)] pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }",
    ),
    (
        "u = [theta3, s], v = [theta2],
         points = [P = (s, e)],
         closure = [
             r * theta2.cos() + l * theta3.cos() - s,
             r * theta2.sin() + l * theta3.sin() - e,
         ]",
        "struct SliderCrank { r: f64, l: f64, e: f64 }",
    ),
    (
        "u = [theta3, theta4, theta5, theta6], v = [theta2],
         points = [
             B = (l2 * theta2.cos(), l2 * theta2.sin()),
             E = (B.x + e * (theta3 + beta).cos(), B.y + e * (theta3 + beta).sin()),
         ],
         closure = [
             l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
             l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
             E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
             E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
         ]",
        "pub struct SixBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64, pub l5: f64,
             pub l6: f64, pub e: f64, pub beta: f64, pub gx: f64, pub gy: f64 }",
    ),
    (
        "u = [s3, phi4, s5], v = [phi2],
         points = [
             A = (r2 * phi2.cos(), r2 * phi2.sin()),
             D = (l4 * phi4.cos(), yd + l4 * phi4.sin()),
         ],
         closure = [
             s3 * phi4.cos() - r2 * phi2.cos(),
             s3 * phi4.sin() - yd - r2 * phi2.sin(),
             l4 * phi4.sin().powi(2) + hypot(s5, 1.0).ln() * 0.0 + (s5 - l4 * phi4.cos()) / 2.0,
         ]",
        "struct Shaper { r2: f64, l4: f64, yd: f64 }",
    ),
];

/// A token, flattened: a group's delimiters become `Open` and `Close`, so
/// that mutations can cut across groups and the stream is rebuilt balanced.
#[derive(Clone, Debug)]
enum Atom {
    Open(Delimiter),
    Close,
    Leaf(TokenTree),
}

fn flatten(tokens: TokenStream, out: &mut Vec<Atom>) {
    for tree in tokens {
        match tree {
            TokenTree::Group(g) => {
                out.push(Atom::Open(g.delimiter()));
                flatten(g.stream(), out);
                out.push(Atom::Close);
            }
            leaf => out.push(Atom::Leaf(leaf)),
        }
    }
}

/// The token stream of a list of atoms: an unmatched `Close` is dropped and
/// an unclosed `Open` closed at the end (a macro never sees unbalanced
/// delimiters).
fn rebuild(atoms: &[Atom]) -> TokenStream {
    let mut stack: Vec<(Delimiter, Vec<TokenTree>)> = vec![(Delimiter::None, Vec::new())];
    for atom in atoms {
        match atom {
            Atom::Open(d) => stack.push((*d, Vec::new())),
            Atom::Close if stack.len() > 1 => {
                let (d, trees) = stack.pop().expect("a group is open");
                let group = Group::new(d, trees.into_iter().collect());
                stack.last_mut().expect("the root").1.push(group.into());
            }
            Atom::Close => {}
            Atom::Leaf(t) => stack.last_mut().expect("the root").1.push(t.clone()),
        }
    }
    while stack.len() > 1 {
        let (d, trees) = stack.pop().expect("a group is open");
        let group = Group::new(d, trees.into_iter().collect());
        stack.last_mut().expect("the root").1.push(group.into());
    }
    stack.pop().expect("the root").1.into_iter().collect()
}

/// Words of the attribute and of Rust, literals that are awkward for a
/// parser of numbers, and every punctuation character.
fn dictionary_atom() -> BoxedStrategy<Atom> {
    const WORDS: &[&str] = &[
        "u", "v", "points", "closure", "theta2", "theta3", "theta4", "l1", "l2", "s", "B", "C",
        "x", "y", "z", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "hypot", "powi",
        "powf", "sqrt", "ln", "exp", "abs", "log", "f64", "f32", "i32", "std", "consts", "PI",
        "self", "Self", "struct", "pub", "fn", "let", "if", "else", "match", "as", "move", "_",
        "r#type", "r#u", "crate", "super", "async", "dyn", "impl", "where",
    ];
    const LITERALS: &[&str] = &[
        "0",
        "1",
        "2",
        "0.5",
        "2.0",
        "1e308",
        "1e309",
        "1e-400",
        "0.0",
        "-0.0",
        "1_000.5",
        "0x1f",
        "0b101",
        "0o17",
        "1u8",
        "2.0f32",
        "3f64",
        "4i32",
        "65536",
        "65537",
        "2147483648",
        "4294967296",
        "340282366920938463463374607431768211456",
        "1e999f64",
        "\"text\"",
        "'c'",
        "b'c'",
        "b\"bytes\"",
        "r\"raw\"",
        "c\"c\"",
        "true",
        "1.",
    ];
    const PUNCT: &[char] = &[
        '+', '-', '*', '/', '%', '^', '!', '&', '|', '=', '<', '>', '.', ',', ';', ':', '#', '@',
        '?', '$', '~',
    ];
    prop_oneof![
        4 => prop::sample::select(WORDS).prop_map(|w| {
            let ident = match w.strip_prefix("r#") {
                Some(raw) => Ident::new_raw(raw, Span::call_site()),
                None => Ident::new(w, Span::call_site()),
            };
            Atom::Leaf(ident.into())
        }),
        3 => prop::sample::select(LITERALS).prop_map(|l| {
            let tree: TokenTree = match Literal::from_str(l) {
                Ok(lit) => lit.into(),
                // `true` and the like are identifiers.
                Err(_) => Ident::new(l, Span::call_site()).into(),
            };
            Atom::Leaf(tree)
        }),
        1 => any::<f64>().prop_map(|x| Atom::Leaf(Literal::f64_suffixed(x.abs().min(f64::MAX)).into())),
        1 => any::<i64>().prop_map(|k| Atom::Leaf(Literal::i64_unsuffixed(k).into())),
        3 => (prop::sample::select(PUNCT), any::<bool>()).prop_map(|(c, joint)| {
            let spacing = if joint { Spacing::Joint } else { Spacing::Alone };
            Atom::Leaf(Punct::new(c, spacing).into())
        }),
        1 => prop::sample::select(&[
            Delimiter::Parenthesis,
            Delimiter::Bracket,
            Delimiter::Brace,
            Delimiter::None
        ][..])
        .prop_map(Atom::Open),
        1 => Just(Atom::Close),
    ]
    .boxed()
}

/// One edit of a flat token list; positions are fractions of its length.
#[derive(Clone, Debug)]
enum Edit {
    Delete(prop::sample::Index),
    Insert(prop::sample::Index, Atom),
    Replace(prop::sample::Index, Atom),
    /// Copies a run of up to 12 atoms to another place.
    Duplicate(prop::sample::Index, usize, prop::sample::Index),
    Swap(prop::sample::Index, prop::sample::Index),
    Truncate(prop::sample::Index),
}

fn edit() -> impl Strategy<Value = Edit> {
    use prop::sample::Index;
    prop_oneof![
        3 => any::<Index>().prop_map(Edit::Delete),
        3 => (any::<Index>(), dictionary_atom()).prop_map(|(i, a)| Edit::Insert(i, a)),
        3 => (any::<Index>(), dictionary_atom()).prop_map(|(i, a)| Edit::Replace(i, a)),
        1 => (any::<Index>(), 1usize..12, any::<Index>())
            .prop_map(|(i, n, j)| Edit::Duplicate(i, n, j)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Edit::Swap(i, j)),
        1 => any::<Index>().prop_map(Edit::Truncate),
    ]
}

fn apply(atoms: &mut Vec<Atom>, edit: &Edit) {
    if atoms.is_empty() {
        if let Edit::Insert(_, a) | Edit::Replace(_, a) = edit {
            atoms.push(a.clone());
        }
        return;
    }
    let n = atoms.len();
    match edit {
        Edit::Delete(i) => {
            atoms.remove(i.index(n));
        }
        Edit::Insert(i, a) => atoms.insert(i.index(n + 1), a.clone()),
        Edit::Replace(i, a) => atoms[i.index(n)] = a.clone(),
        Edit::Duplicate(i, len, j) => {
            let start = i.index(n);
            let run: Vec<Atom> = atoms[start..(start + len).min(n)].to_vec();
            let at = j.index(n + 1);
            atoms.splice(at..at, run);
        }
        Edit::Swap(i, j) => atoms.swap(i.index(n), j.index(n)),
        Edit::Truncate(i) => atoms.truncate(i.index(n)),
    }
}

/// What one run of the attribute showed; `Err` says which property failed.
fn check(attr: TokenStream, item: TokenStream) -> Result<Verdict, TestCaseError> {
    let item_is_rust = syn::parse2::<syn::Item>(item.clone()).is_ok();
    let result = run(attr.clone(), item.clone()).result;
    let verdict = match &result {
        Ok(_) => Verdict::Accepted,
        Err(error) => {
            for e in error.clone() {
                let message = e.to_string();
                prop_assert!(!message.trim().is_empty(), "an error without a message");
                prop_assert!(
                    !message.contains("internal error"),
                    "neither code nor an error: {message}"
                );
            }
            Verdict::Rejected(error.to_string())
        }
    };
    let output = expand(attr, item);
    if item_is_rust {
        if let Err(e) = syn::parse2::<syn::File>(output.clone()) {
            return Err(TestCaseError::fail(format!(
                "the output is not Rust items ({e}):\n{output}"
            )));
        }
    }
    Ok(verdict)
}

enum Verdict {
    Accepted,
    Rejected(String),
}

fn report(name: &str, runs: u32, accepted: u32, seconds: f64) {
    println!(
        "fuzz {name}: {runs} cases, {accepted} accepted, {} rejected with an error, \
         0 panics, 0 outputs that are not Rust, {seconds:.1} s",
        runs - accepted
    );
}

#[test]
fn corpus_is_accepted() {
    for (attr, item) in CORPUS {
        let attr = TokenStream::from_str(attr).expect("tokens");
        let item = TokenStream::from_str(item).expect("tokens");
        match run(attr, item).result {
            Ok(_) => {}
            Err(e) => panic!("a corpus entry is rejected: {e}"),
        }
    }
}

#[test]
fn rebuild_inverts_flatten() {
    for (attr, _) in CORPUS {
        let tokens = TokenStream::from_str(attr).expect("tokens");
        let mut atoms = Vec::new();
        flatten(tokens.clone(), &mut atoms);
        assert_eq!(rebuild(&atoms).to_string(), tokens.to_string());
    }
}

/// The corpus, mutated: the attribute, the struct or both, by up to eight
/// edits each.
#[test]
fn mutated_attributes_never_panic() {
    let strategy = (
        0..CORPUS.len(),
        prop::collection::vec(edit(), 0..8),
        prop::collection::vec(edit(), 0..3),
        any::<bool>(),
    );
    let (runs, accepted) = (Cell::new(0), Cell::new(0));
    let start = Instant::now();
    let mut runner = runner();
    let outcome = runner.run(&strategy, |(which, attr_edits, item_edits, edit_item)| {
        let (attr, item) = CORPUS[which];
        let mut attr_atoms = Vec::new();
        flatten(
            TokenStream::from_str(attr).expect("tokens"),
            &mut attr_atoms,
        );
        let mut item_atoms = Vec::new();
        flatten(
            TokenStream::from_str(item).expect("tokens"),
            &mut item_atoms,
        );
        for e in &attr_edits {
            apply(&mut attr_atoms, e);
        }
        if edit_item {
            for e in &item_edits {
                apply(&mut item_atoms, e);
            }
        }
        let verdict = check(rebuild(&attr_atoms), rebuild(&item_atoms))?;
        runs.set(runs.get() + 1);
        accepted.set(accepted.get() + u32::from(matches!(verdict, Verdict::Accepted)));
        Ok(())
    });
    if let Err(e) = outcome {
        panic!("{e}");
    }
    report(
        "mutated corpus",
        runs.get(),
        accepted.get(),
        start.elapsed().as_secs_f64(),
    );
}

/// Token soup: up to 64 atoms from the dictionary as the attribute, on a
/// valid struct.
#[test]
fn token_soup_never_panics() {
    let strategy = prop::collection::vec(dictionary_atom(), 0..64);
    let item = TokenStream::from_str(CORPUS[0].1).expect("tokens");
    let (runs, accepted) = (Cell::new(0), Cell::new(0));
    let start = Instant::now();
    let mut runner = runner();
    let outcome = runner.run(&strategy, |atoms| {
        let verdict = check(rebuild(&atoms), item.clone())?;
        runs.set(runs.get() + 1);
        accepted.set(accepted.get() + u32::from(matches!(verdict, Verdict::Accepted)));
        Ok(())
    });
    if let Err(e) = outcome {
        panic!("{e}");
    }
    report(
        "token soup",
        runs.get(),
        accepted.get(),
        start.elapsed().as_secs_f64(),
    );
}

/// A random expression: supported forms (numbers, the names in scope,
/// `+ - * /`, unary `-`, the supported functions as methods or calls, point
/// coordinates) and, when `wild`, forms the engine must reject.
#[derive(Clone, Debug)]
enum Expr {
    Num(f64),
    Name(&'static str),
    Point(&'static str, &'static str),
    Bin(char, Box<Expr>, Box<Expr>),
    Neg(Box<Expr>),
    Paren(Box<Expr>),
    Method(&'static str, Box<Expr>, Vec<Expr>),
    Call(&'static str, Vec<Expr>),
    Powi(Box<Expr>, i64),
    /// Text the engine does not support, around a supported expression.
    Wild(&'static str, Box<Expr>),
}

impl Expr {
    fn supported(&self) -> bool {
        match self {
            Expr::Num(_) | Expr::Name(_) | Expr::Point(..) => true,
            Expr::Bin(_, a, b) => a.supported() && b.supported(),
            Expr::Neg(a) | Expr::Paren(a) => a.supported(),
            Expr::Method(f, a, args) => {
                arity(f) == Some(args.len() + 1)
                    && a.supported()
                    && args.iter().all(Expr::supported)
            }
            Expr::Call(f, args) => arity(f) == Some(args.len()) && args.iter().all(Expr::supported),
            Expr::Powi(a, k) => k.abs() <= 1 << 16 && a.supported(),
            Expr::Wild(..) => false,
        }
    }

    /// The tree with every point outside `visible` replaced by a parameter.
    fn in_scope(&self, visible: &[&str]) -> Expr {
        let map = |a: &Expr| Box::new(a.in_scope(visible));
        match self {
            Expr::Point(p, _) if !visible.contains(p) => Expr::Name("q"),
            Expr::Num(_) | Expr::Name(_) | Expr::Point(..) => self.clone(),
            Expr::Bin(op, a, b) => Expr::Bin(*op, map(a), map(b)),
            Expr::Neg(a) => Expr::Neg(map(a)),
            Expr::Paren(a) => Expr::Paren(map(a)),
            Expr::Method(f, a, args) => Expr::Method(
                f,
                map(a),
                args.iter().map(|x| x.in_scope(visible)).collect(),
            ),
            Expr::Call(f, args) => {
                Expr::Call(f, args.iter().map(|x| x.in_scope(visible)).collect())
            }
            Expr::Powi(a, k) => Expr::Powi(map(a), *k),
            Expr::Wild(w, a) => Expr::Wild(w, map(a)),
        }
    }

    fn text(&self) -> String {
        match self {
            Expr::Num(x) => format!("{x:?}"),
            Expr::Name(n) => (*n).to_owned(),
            Expr::Point(p, c) => format!("{p}.{c}"),
            Expr::Bin(op, a, b) => format!("{} {op} {}", a.text(), b.text()),
            Expr::Neg(a) => format!("-{}", a.text()),
            Expr::Paren(a) => format!("({})", a.text()),
            Expr::Method(f, a, args) => format!("({}).{f}({})", a.text(), list(args)),
            Expr::Call(f, args) => format!("{f}({})", list(args)),
            Expr::Powi(a, k) => format!("({}).powi({k})", a.text()),
            Expr::Wild(w, a) => w.replace('@', &a.text()),
        }
    }
}

fn list(args: &[Expr]) -> String {
    args.iter().map(Expr::text).collect::<Vec<_>>().join(", ")
}

fn arity(f: &str) -> Option<usize> {
    match f {
        "sin" | "cos" | "tan" | "asin" | "acos" | "atan" | "sinh" | "cosh" | "tanh" | "sqrt"
        | "exp" | "ln" | "abs" => Some(1),
        "atan2" | "hypot" | "powf" => Some(2),
        _ => None,
    }
}

fn expression(wild: bool) -> BoxedStrategy<Expr> {
    const NAMES: &[&str] = &["a", "b", "c", "p", "q", "r", "PI", "TAU", "E"];
    const FUNCTIONS: &[&str] = &[
        "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "sqrt", "exp", "ln",
        "abs", "atan2", "hypot", "powf", "log", "cbrt", "max", "sin_cos", "floor",
    ];
    const WILD: &[&str] = &[
        "@ as f64",
        "&@",
        "!@",
        "*@",
        "@ % 2.0",
        "@ ^ 2.0",
        "@ == 1.0",
        "@ += 1.0",
        "[@][0]",
        "(@, 1.0)",
        "{ @ }",
        "if true { @ } else { 0.0 }",
        "|x: f64| @",
        "m!(@)",
        "@?",
        "@.0",
        "@.z",
        "Q.x + @",
        "@.powi(n)",
        "@.powi(2.5)",
        "@.powi(99999999)",
        "@.sin::<f64>()",
        "std::f64::sin(@)",
        "<f64>::sin(@)",
        "\"@\"",
        "@ + 1e999",
        "@ * 1.0f32",
        "@ - 2u8",
        "@..1.0",
        "loop { @ }",
        "unsafe { @ }",
        "async { @ }",
        "@ + self.a",
    ];
    let leaf = prop_oneof![
        1 => prop_oneof![
            (-1e3f64..1e3),
            Just(0.0),
            Just(1e300),
            Just(f64::MIN_POSITIVE),
            Just(5e-324)
        ]
        .prop_map(|x| Expr::Num(x.abs())),
        3 => prop::sample::select(NAMES).prop_map(Expr::Name),
        1 => (
            prop::sample::select(&["P", "R"][..]),
            prop::sample::select(&["x", "y"][..])
        )
            .prop_map(|(p, c)| Expr::Point(p, c)),
    ];
    leaf.prop_recursive(5, 40, 3, move |inner| {
        // Supported names with their arity, or (wild) any name with 0-2
        // arguments.
        let functions = if wild { FUNCTIONS } else { &FUNCTIONS[..16] };
        let call = (
            prop::sample::select(functions),
            inner.clone(),
            inner.clone(),
            0usize..3,
        )
            .prop_map(move |(f, a, b, n)| {
                let count = if wild { n } else { arity(f).unwrap_or(n) };
                (f, [a, b].into_iter().take(count).collect::<Vec<_>>())
            });
        let base = prop_oneof![
            4 => (
                prop::sample::select(&['+', '-', '*', '/'][..]),
                inner.clone(),
                inner.clone()
            )
                .prop_map(|(op, a, b)| Expr::Bin(op, a.into(), b.into())),
            1 => inner.clone().prop_map(|a| Expr::Neg(a.into())),
            1 => inner.clone().prop_map(|a| Expr::Paren(a.into())),
            2 => (call.clone(), inner.clone()).prop_map(|((f, mut args), receiver)| {
                match args.is_empty() {
                    true => Expr::Method(f, receiver.into(), args),
                    false => Expr::Method(f, args.remove(0).into(), args),
                }
            }),
            2 => call.prop_map(|(f, args)| Expr::Call(f, args)),
            1 => (inner.clone(), prop_oneof![-4i64..8, Just(65536), Just(-65537)])
                .prop_map(|(a, k)| Expr::Powi(a.into(), k)),
        ];
        if wild {
            prop_oneof![
                6 => base,
                1 => (prop::sample::select(WILD), inner).prop_map(|(w, a)| Expr::Wild(w, a.into())),
            ]
            .boxed()
        } else {
            base.boxed()
        }
    })
    .boxed()
}

/// Random closure equations in the coordinates a, b (driven by c) with
/// parameters p, q, r and points P, R: supported ones are accepted unless
/// structurally singular; wild ones are rejected with an error.
#[test]
fn random_equations_never_panic() {
    // Three cases in four are made of supported forms only, with points
    // read only where they are defined; equations are anchored on `a` and
    // `b` half the time, so that many are accepted.
    let trees = |wild| {
        (
            prop::collection::vec(expression(wild), 2),
            prop::collection::vec(expression(wild), 4),
            any::<[bool; 2]>(),
            Just(wild),
        )
    };
    let strategy = prop_oneof![3 => trees(false), 1 => trees(true)];
    let item = TokenStream::from_str("struct Random { p: f64, q: f64, r: f64 }").expect("tokens");
    let (runs, accepted) = (Cell::new(0), Cell::new(0));
    let start = Instant::now();
    let mut runner = runner();
    let outcome = runner.run(&strategy, |(closure, mut points, anchored, wild)| {
        if !wild {
            for (k, point) in points.iter_mut().enumerate() {
                *point = point.in_scope(if k < 2 { &[] } else { &["P"] });
            }
        }
        let equation = |k: usize| match (anchored[k], k) {
            (true, 0) => format!("a - ({})", closure[0].text()),
            (true, _) => format!("({}) * b + b", closure[1].text()),
            (false, _) => closure[k].text(),
        };
        let text = format!(
            "u = [a, b], v = [c], points = [P = ({}, {}), R = ({}, {})], closure = [{}, {}]",
            points[0].text(),
            points[1].text(),
            points[2].text(),
            points[3].text(),
            equation(0),
            equation(1),
        );
        // Wild text may not even be tokens (an unbalanced `"`): the
        // compiler rejects those before any macro runs.
        let Ok(attr) = TokenStream::from_str(&text) else {
            return Ok(());
        };
        let verdict = check(attr, item.clone())?;
        // Points defined later may not be used earlier: P may not read R.
        let order_ok = !points[0].text().contains("R.") && !points[1].text().contains("R.");
        let self_ok = (0..2).all(|k| !points[k].text().contains("P."))
            && (2..4).all(|k| !points[k].text().contains("R."));
        let all_supported = closure.iter().chain(&points).all(Expr::supported);
        if all_supported && order_ok && self_ok {
            if let Verdict::Rejected(message) = &verdict {
                prop_assert!(
                    message.contains("structurally singular"),
                    "supported equations rejected: {message}\n{text}"
                );
            }
        }
        if !all_supported {
            prop_assert!(
                matches!(verdict, Verdict::Rejected(_)),
                "unsupported equations accepted:\n{text}"
            );
        }
        runs.set(runs.get() + 1);
        accepted.set(accepted.get() + u32::from(matches!(verdict, Verdict::Accepted)));
        Ok(())
    });
    if let Err(e) = outcome {
        panic!("{e}");
    }
    report(
        "random equations",
        runs.get(),
        accepted.get(),
        start.elapsed().as_secs_f64(),
    );
}

/// Deep nesting: the recursive parts (parser, lowering, differentiation,
/// emission) on equations nested far deeper than anyone writes — a chain
/// of functions and products 32 deep (the time to expand it grows with the
/// cube of the depth, which is what bounds it here), and a sum of 1000
/// terms and 200 nested parentheses, on a thread with the 8 MiB stack of
/// rustc's main thread.
#[test]
fn deep_nesting_is_handled() {
    let mut chain = "a".to_owned();
    for k in 0..32 {
        chain = match k % 3 {
            0 => format!("({chain}).sin()"),
            1 => format!("({chain} * b + c)"),
            _ => format!("-({chain})"),
        };
    }
    let sum = (0..1000)
        .map(|k| format!("{k}.5 * a"))
        .collect::<Vec<_>>()
        .join(" + ");
    let parens = format!("{}a * b{}", "(".repeat(200), ")".repeat(200));
    for (name, e) in [("chain", chain), ("sum", sum), ("parentheses", parens)] {
        let text = format!("u = [a, b], v = [c], closure = [{e}, a - b + c]");
        // Tokens are not `Send`: they are made on the thread that reads them.
        let verdict = std::thread::Builder::new()
            .stack_size(8 << 20)
            .spawn(move || {
                let attr = TokenStream::from_str(&text).expect("tokens");
                let item = TokenStream::from_str("struct Deep { p: f64 }").expect("tokens");
                check(attr, item)
                    .map(|v| matches!(v, Verdict::Accepted))
                    .map_err(|e| e.to_string())
            })
            .expect("a thread")
            .join()
            .expect("no panic");
        assert!(matches!(verdict, Ok(true)), "{name}: {verdict:?}");
    }
}

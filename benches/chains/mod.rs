//! Chains of N four-bar loops, the benchmarks' mechanism that grows: the
//! crank of loop k keyed to the rocker of loop k − 1 at the angle `delta`,
//! its ground pivots shifted along x, a coupler point per loop; m = 2N.
//! `chain_text` writes one as the attribute's text, and the files beside
//! this one are the chains of 1, 2, 4, 8, 16 and 32 loops written out as a
//! user writes a mechanism; [`check_compiled`] holds each to the text.

use linkage::prelude::*;

// The mechanisms of the macro's cost examples; the chain is the one used here.
#[allow(dead_code)]
#[path = "../../linkage-macros/examples/common/cases.rs"]
mod cases;

/// Every loop the worksheet's crank-rocker, its coupler point 30 from B at
/// 0.5 rad, each crank keyed 0.3 rad past the previous rocker.
pub const PARAMETERS: [(&str, f64); 7] = [
    ("l1", 80.0),
    ("l2", 20.0),
    ("l3", 50.0),
    ("l4", 70.0),
    ("e", 30.0),
    ("beta", 0.5),
    ("delta", 0.3),
];

/// A compiled chain `$module::Chain` with [`PARAMETERS`] (one loop, `n1`,
/// has no `delta`).
#[macro_export]
macro_rules! chain {
    (n1) => {
        n1::Chain {
            l1: 80.0,
            l2: 20.0,
            l3: 50.0,
            l4: 70.0,
            e: 30.0,
            beta: 0.5,
        }
    };
    ($module:ident) => {
        $module::Chain {
            l1: 80.0,
            l2: 20.0,
            l3: 50.0,
            l4: 70.0,
            e: 30.0,
            beta: 0.5,
            delta: 0.3,
        }
    };
}

/// N four-bar loops in a chain, as the attribute's text: the chain whose
/// expansion cost `linkage-macros/examples/expansion_cost.rs` measures.
/// m = 2N.
pub fn chain_text(n: usize) -> String {
    cases::chain(n).attr
}

/// The text inside `#[...linkage(` … `)]` of the struct `name` in `source`.
pub fn attribute_of(source: &str, name: &str) -> String {
    let at = source
        .find(&format!("pub struct {name} "))
        .unwrap_or_else(|| panic!("no struct {name}"));
    let start = source[..at].rfind("linkage(").expect("an attribute") + "linkage(".len();
    let mut depth = 0;
    for (k, c) in source[start..at].char_indices() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' if depth == 0 => return source[start..start + k].to_owned(),
            ')' | ']' | '}' => depth -= 1,
            _ => {}
        }
    }
    panic!("the attribute of {name} does not end")
}

/// A text without its layout: no white space, no trailing commas.
pub fn tokens_of(text: &str) -> String {
    let bare: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    bare.replace(",]", "]")
        .replace(",)", ")")
        .trim_end_matches(',')
        .to_owned()
}

/// Panics unless the file `source` (the chain of `n` loops) writes out
/// `chain_text(n)`; gives its attribute's text.
pub fn check_compiled(source: &str, n: usize) -> String {
    let attribute = attribute_of(source, "Chain");
    assert_eq!(
        tokens_of(&attribute),
        tokens_of(&chain_text(n)),
        "the compiled chain of {n} loops is the generator's"
    );
    attribute
}

/// The chain's pose at crank angle `t`, loop by loop from the closed form
/// (the branch of the four-bar's benchmarks).
pub fn chain_pose<const M: usize>(t: f64) -> SVector<f64, M> {
    let value = |name: &str| {
        (PARAMETERS.iter())
            .find(|(n, _)| *n == name)
            .map(|(_, x)| *x)
            .expect("a parameter of the chain")
    };
    let four_bar = linkage::closed_form::FourBar {
        l1: value("l1"),
        l2: value("l2"),
        l3: value("l3"),
        l4: value("l4"),
    };
    let mut u = SVector::<f64, M>::zeros();
    let mut crank = t;
    for k in 0..M / 2 {
        let [a, b] = four_bar.position(crank, 1.0).expect("a crank-rocker turns");
        u[2 * k] = a;
        u[2 * k + 1] = b;
        crank = b + value("delta");
    }
    u
}

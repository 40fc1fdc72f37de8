//! The run-time front end as a whole: a mechanism built from text, its
//! mistakes located in the file, one build after another on the same
//! thread, and any text at all answered without a panic, accepted exactly
//! when the attribute's pipeline accepts it.

use super::*;
use crate::ast::Input;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};

const FOUR_BAR: &str = "
    u = [theta3, theta4],
    v = [theta2],
    points = [B = (l2 * theta2.cos(), l2 * theta2.sin())],
    closure = [
        B.x + l3 * theta3.cos() - l4 * theta4.cos() - l1,
        B.y + l3 * theta3.sin() - l4 * theta4.sin(),
    ]";

const FOUR_BAR_PARAMETERS: [&str; 4] = ["l1", "l2", "l3", "l4"];

fn parameters<'a>(names: &[&'a str]) -> Vec<Parameter<'a>> {
    names.iter().map(|name| Parameter::new(name)).collect()
}

/// The messages of `text` built as a mechanism, and their places.
fn mistakes(text: &str, offset: usize) -> Vec<(String, Option<Range<usize>>)> {
    let equations = Equations::at(text, offset);
    match build("FourBar", equations, &parameters(&FOUR_BAR_PARAMETERS)) {
        Ok(_) => Vec::new(),
        Err(diagnostics) => (diagnostics.iter())
            .map(|d| (d.message().to_owned(), d.range()))
            .collect(),
    }
}

#[test]
fn a_four_bar_from_text() {
    let built = build(
        "FourBar",
        Equations::new(FOUR_BAR),
        &parameters(&FOUR_BAR_PARAMETERS),
    )
    .unwrap_or_else(|d| panic!("{d}"));
    let d = &built.derivatives;
    assert_eq!((d.m(), d.f(), d.k()), (2, 1, 4));
    assert_eq!(d.points.len(), 1);
    assert_eq!(built.input.owner, Owner::Mechanism("FourBar".to_owned()));
    assert_eq!(built.input.item.ident, "FourBar");
}

/// A chain of 32 four-bar loops, each crank keyed to the rocker of the
/// loop before: Ψ_u splits into a 2×2 block per loop, solved loop by loop.
#[test]
fn a_chain_of_loops_splits_into_a_block_per_loop() {
    let loops = 32;
    let crank = |k: usize| match k {
        1 => "t".to_owned(),
        _ => format!("(b{} + d)", k - 1),
    };
    let u: Vec<String> = (1..=loops).map(|k| format!("a{k}, b{k}")).collect();
    let closure: Vec<String> = (1..=loops)
        .map(|k| {
            let c = crank(k);
            format!(
                "l2 * {c}.cos() + l3 * a{k}.cos() + l4 * b{k}.cos() - l1, \
                 l2 * {c}.sin() + l3 * a{k}.sin() + l4 * b{k}.sin()"
            )
        })
        .collect();
    let text = format!(
        "u = [{}], v = [t], closure = [{}]",
        u.join(", "),
        closure.join(", ")
    );
    let built = build(
        "Chain",
        Equations::new(&text),
        &parameters(&["l1", "l2", "l3", "l4", "d"]),
    )
    .unwrap_or_else(|d| panic!("{d}"));
    let blocks = &built.derivatives.blocks;
    assert_eq!(
        blocks.to_string(),
        "Ψ_u is block lower triangular: 32 blocks of 2×2"
    );
    for (l, block) in blocks.blocks().iter().enumerate() {
        assert_eq!(block.coordinates, [2 * l, 2 * l + 1]);
        assert_eq!(block.equations, [2 * l, 2 * l + 1]);
    }
}

/// proc-macro2's memory of the texts is dropped after every build; the
/// next build's places are its own, whatever came before.
#[test]
fn one_build_after_another_locates_its_own_text() {
    let misspelt = FOUR_BAR.replace("l3 * theta3.sin()", "l3 * thta3.sin()");
    let at = misspelt.find("thta3").unwrap();
    for round in 0..200 {
        let offset = round * 7;
        let found = mistakes(&misspelt, offset);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(
            found[0].1,
            Some(offset + at..offset + at + 5),
            "round {round}"
        );
        assert!(mistakes(FOUR_BAR, offset).is_empty());
    }
}

/// A mistake about the whole text (a list missing) is at the whole text;
/// an empty text misses all three lists, at its (empty) place.
#[test]
fn a_missing_list_is_the_whole_texts() {
    let text = "u = [theta3], closure = [theta3 - l1]";
    let found = mistakes(text, 10);
    assert_eq!(
        found,
        [(
            "missing `v = [...]` in the mechanism `FourBar`, e.g. `v = [theta2]`".to_owned(),
            Some(10..10 + text.len())
        )]
    );
    let empty = mistakes("", 3);
    assert_eq!(empty.len(), 3);
    assert!(empty.iter().all(|(_, at)| *at == Some(3..3)));
}

#[test]
fn a_text_the_lexer_refuses_is_located() {
    let found = mistakes("u = [theta3, v = [theta2]", 20);
    assert_eq!(found.len(), 1);
    assert!(found[0].0.starts_with("unclosed `[`"), "{found:?}");
    assert_eq!(found[0].1, Some(24..25));
}

/// Points that build on one another nest deeper than any single equation
/// is written: `P0` is 2 deep (a sine of a coordinate), `Pk` is `k + 2`.
#[test]
fn nesting_too_deep_is_refused_at_the_point() {
    let chain = |last: usize| {
        let mut points = vec!["P0 = (theta2.sin(), theta2.cos())".to_owned()];
        for k in 1..=last {
            points.push(format!("P{k} = (P{}.x.sin(), P{}.y)", k - 1, k - 1));
        }
        let points = points.join(", ");
        format!("u = [x], v = [theta2], points = [{points}], closure = [x - theta2]")
    };
    assert_eq!(mistakes(&chain(MAX_NESTING - 2), 0), []);
    let text = chain(MAX_NESTING - 1);
    let found = mistakes(&text, 0);
    assert_eq!(found.len(), 1, "{found:?}");
    let (message, at) = &found[0];
    let last = MAX_NESTING - 1;
    assert_eq!(
        *message,
        format!(
            "point `P{last}` nests {} operations deep (with the points it uses), the most this \
             reads is {MAX_NESTING}",
            MAX_NESTING + 1
        )
    );
    let at = at.clone().unwrap();
    assert_eq!(&text[at.clone()], format!("P{last}"));
    assert_eq!(text[at.end..].chars().next(), Some(' '));
}

/// What the attribute's pipeline says of `text` read as tokens with
/// `parameters` as a struct's fields, worded for a mechanism: its
/// messages and places (in the text), or `None` if the lexer refuses it.
fn pipeline(text: &str, parameters: &[&str]) -> Option<Vec<(String, Range<usize>)>> {
    let attr: proc_macro2::TokenStream = text.parse().ok()?;
    let fields = parameters
        .iter()
        .map(|p| format!("{p}: f64, "))
        .collect::<String>();
    let item: proc_macro2::TokenStream = format!("struct FourBar {{ {fields} }}").parse().ok()?;
    let mut errors = Errors::default();
    let owner = |_: &syn::Ident| Owner::Mechanism("FourBar".to_owned());
    if let Some(input) = Input::parse_owned_by(attr, item, owner, &mut errors) {
        let _ = crate::build(&input, &mut errors);
    }
    let whole = 0..text.len();
    let place = |span: proc_macro2::Span| {
        if proc_macro2::Span::call_site().join(span).is_some() {
            whole.clone()
        } else {
            span.byte_range()
        }
    };
    Some(
        errors
            .into_iter()
            .flat_map(|e| {
                e.into_iter()
                    .map(|part| (part.to_string(), place(part.span())))
            })
            .collect(),
    )
}

/// The run-time front end's answer to the same: its messages and places,
/// labels after their message.
fn run_time(text: &str, parameters: &[&str]) -> Result<(), Vec<(String, Range<usize>)>> {
    let given = self::parameters(parameters);
    match build("FourBar", Equations::new(text), &given) {
        Ok(_) => Ok(()),
        Err(diagnostics) => Err(diagnostics
            .iter()
            .flat_map(|d| {
                let primary = (d.message().to_owned(), d.range().unwrap_or(0..0));
                let labels = (d.labels().iter()).map(|l| (l.message().to_owned(), l.range()));
                std::iter::once(primary).chain(labels)
            })
            .collect()),
    }
}

/// The words texts are made of: the grammar's, names, operators, numbers,
/// and what a lexer or a parser refuses.
const WORDS: &[&str] = &[
    "u",
    "v",
    "closure",
    "points",
    "params",
    "=",
    "[",
    "]",
    "(",
    ")",
    "{",
    "}",
    ",",
    ",",
    " ",
    "\n",
    "theta2",
    "theta3",
    "theta4",
    "l1",
    "l2",
    "l3",
    "x",
    "B",
    "B.x",
    "B.y",
    ".",
    ".sin()",
    ".cos()",
    "sin",
    "atan2",
    "powi",
    "+",
    "-",
    "*",
    "/",
    "^",
    "2",
    "2.0",
    "1e400",
    "PI",
    "std::f64::consts::PI",
    "\"",
    "'",
    "#",
    "→",
    "r#type",
    "fn",
    "_",
    "::",
    ";",
    "/*",
    "//",
    "0x",
    "u = [theta3]",
    "v = [theta2]",
    "closure = [theta3 - l1 * theta2]",
    "params = [l1]",
];

/// A text from `WORDS` and stray characters, or the four-bar with a slice
/// replaced.
fn texts() -> impl Strategy<Value = String> {
    let word = prop_oneof![
        4 => proptest::sample::select(WORDS).prop_map(str::to_owned),
        1 => any::<char>().prop_map(String::from),
    ];
    let soup = proptest::collection::vec(word.clone(), 0..40).prop_map(|words| words.concat());
    let mutated = (
        0..FOUR_BAR.len(),
        0..12usize,
        proptest::collection::vec(word, 0..3),
    )
        .prop_map(|(at, cut, words)| {
            let end = (at + cut).min(FOUR_BAR.len());
            format!("{}{}{}", &FOUR_BAR[..at], words.concat(), &FOUR_BAR[end..])
        });
    prop_oneof![
        1 => Just(FOUR_BAR.to_owned()),
        3 => mutated,
        3 => soup,
    ]
}

/// Parameter names, good and bad: the four-bar's, alone or with others,
/// or any.
fn names() -> impl Strategy<Value = Vec<&'static str>> {
    let name = proptest::sample::select(
        &[
            "l1", "l2", "l3", "l4", "theta2", "B", "x", "2x", "fn", "", "r#type", "l 1",
        ][..],
    );
    let any = proptest::collection::vec(name, 0..6);
    let four_bar = FOUR_BAR_PARAMETERS.to_vec();
    prop_oneof![
        2 => Just(four_bar.clone()),
        1 => any.clone().prop_map(move |more| [four_bar.clone(), more].concat()),
        1 => any,
    ]
}

/// Any text and any parameters: no panic; the lexer's refusals and the
/// names' mistakes the front end's own; otherwise exactly the pipeline's
/// messages at the pipeline's places.
#[test]
fn any_text_is_answered_as_the_pipeline_answers_it() {
    // More with `LINKAGE_FUZZ_CASES`, as the attribute's fuzzing.
    let cases = std::env::var("LINKAGE_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok());
    let mut config = Config::with_cases(cases.unwrap_or(512));
    config.failure_persistence = None;
    config.rng_seed = RngSeed::Fixed(0x7465_7874_6672_6f6e);
    let mut runner = TestRunner::new(config);
    // How many texts were accepted, refused by the lexer, and refused by
    // the pipeline: each kind must have come up.
    let seen = std::cell::Cell::new([0usize; 3]);
    let count = |kind: usize| {
        let mut counts = seen.get();
        counts[kind] += 1;
        seen.set(counts);
    };
    runner
        .run(&(texts(), names()), |(text, names)| {
            let valid: Vec<&str> = (names.iter().copied())
                .filter(|name| syn::parse_str::<syn::Ident>(name).is_ok_and(|i| i == name))
                .fold(Vec::new(), |mut kept, name| {
                    let unraw = name.trim_start_matches("r#");
                    if !kept
                        .iter()
                        .any(|k: &&str| k.trim_start_matches("r#") == unraw)
                    {
                        kept.push(name);
                    }
                    kept
                });
            let expected = pipeline(&text, &valid);
            let actual = run_time(&text, &names);
            let names_wrong = valid.len() != names.len();
            match (expected, actual) {
                // The lexer refused the text: so does the front end, with
                // a place in it.
                (None, actual) => {
                    count(1);
                    let refused = actual.expect_err("a text the lexer refuses");
                    let (_, at) = refused.last().expect("a refusal");
                    prop_assert!(at.end <= text.len());
                }
                (Some(expected), Ok(())) => {
                    count(0);
                    prop_assert!(expected.is_empty(), "accepted: {expected:?}");
                    prop_assert!(!names_wrong);
                }
                (Some(expected), Err(actual)) => {
                    let limits = ["the most this reads", "the most one equation"];
                    if actual
                        .iter()
                        .any(|(m, _)| limits.iter().any(|l| m.contains(l)))
                    {
                        return Ok(());
                    }
                    count(2);
                    // The names' mistakes come first, one each (declared
                    // nowhere, they have no label), then the pipeline's.
                    let names_mistakes = names.len() - valid.len();
                    prop_assert!(actual.len() >= names_mistakes);
                    prop_assert_eq!(&actual[names_mistakes..], &expected[..]);
                    prop_assert!(names_wrong || !expected.is_empty());
                }
            }
            Ok(())
        })
        .unwrap();
    let [accepted, lexer, pipeline] = seen.get();
    assert!(
        accepted > 10 && lexer > 10 && pipeline > 10,
        "{:?}",
        seen.get()
    );
}

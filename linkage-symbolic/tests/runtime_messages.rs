//! The run-time front end says what the attribute says: for every case of
//! the compile-time diagnostics (`tests/ui/*.rs`, with rustc's rendering
//! in `*.stderr`), the attribute's text and the struct's fields are given
//! to `text::build`, the text at its place in the case's file and each
//! field as a parameter declared where the field is. Its messages must be
//! rustc's, the words naming the struct's fields put as a run-time
//! mechanism's parameters, in the same order and at the same lines and
//! columns of the file.
//!
//! Every case is listed below with how it is held equal; a case added to
//! `tests/ui` and not listed fails the test.

use linkage_symbolic::diagnostics::Diagnostics;
use linkage_symbolic::text::{self, Equations, Parameter};
use std::ops::Range;
use std::path::{Path, PathBuf};

/// How a compile-time case is held equal to its run-time counterpart.
enum Counterpart {
    /// The struct's fields, all `f64`, are the parameters; the messages
    /// are the compile-time ones with the owner's words mapped.
    Same,
    /// The struct also has fields that are not `f64`, which a run-time
    /// mechanism cannot have (its parameters are numbers): its `f64`
    /// fields are the parameters, and the message at each index given
    /// (counted as in the `.stderr`) is replaced by the run-time one, at
    /// the same place.
    NumbersOnly(&'static [(usize, &'static str)]),
    /// No run-time counterpart, for the reason given.
    None(&'static str),
}

const CASES: &[(&str, Counterpart)] = &[
    (
        "bad_params",
        Counterpart::NumbersOnly(&[(
            4,
            "`label` is not a parameter of `FourBar`: `params` lists parameters the equations \
             use (l1, l2, l3, l4)",
        )]),
    ),
    ("coordinate_in_no_equation", Counterpart::Same),
    ("duplicate_name", Counterpart::Same),
    ("empty_list", Counterpart::Same),
    ("equation_count", Counterpart::Same),
    ("malformed_key", Counterpart::Same),
    ("malformed_point", Counterpart::Same),
    ("missing_key", Counterpart::Same),
    ("mistake_in_closure", Counterpart::Same),
    ("mistake_in_params", Counterpart::Same),
    ("mistake_in_points", Counterpart::Same),
    ("mistake_in_u", Counterpart::Same),
    ("mistake_in_v", Counterpart::Same),
    (
        "non_f64_field",
        Counterpart::NumbersOnly(&[(
            0,
            "unknown name `teeth`: not a coordinate, a point, a parameter of `FourBar` or a \
             constant of `std::f64::consts`",
        )]),
    ),
    ("not_a_point_coordinate", Counterpart::Same),
    (
        "not_a_struct",
        Counterpart::None(
            "the attribute on an enum: a run-time mechanism has no Rust item, only a name and \
             parameters, whose mistakes (not an identifier, a keyword, declared twice) are \
             `names_that_are_not_names_are_located` below",
        ),
    ),
    ("point_before_definition", Counterpart::Same),
    // A point named like a generated constant is a mistake of the items
    // the attribute emits, not of the equations: at run time as at
    // compile time, only the misspelt name is reported.
    ("point_named_like_a_constant", Counterpart::Same),
    ("powi_not_a_literal", Counterpart::Same),
    ("shadows_a_field", Counterpart::Same),
    // A struct named like a generic parameter of the emitted items: at run
    // time the name `F` is as good as any, and only `v`'s mistake remains.
    ("struct_named_f", Counterpart::Same),
    ("structurally_singular", Counterpart::Same),
    ("unknown_name", Counterpart::Same),
    ("unsupported_function", Counterpart::Same),
    ("v_not_a_list", Counterpart::Same),
    ("xor_is_not_a_power", Counterpart::Same),
];

/// The compile-time words for the struct's fields and the attribute, and
/// the run-time words for the same (`{}` is the owner's name).
const WORDS: &[(&str, &str)] = &[
    (
        "an `f64` field of the struct",
        "a parameter of the mechanism",
    ),
    ("an `f64` field of `{}`", "a parameter of `{}`"),
    ("a field of `{}`", "a parameter of `{}`"),
    ("`f64` fields of `{}`", "parameters of `{}`"),
    ("lists `f64` fields the", "lists parameters the"),
    ("use no `f64` field", "use no parameter"),
    ("the struct's `f64` fields", "the mechanism's parameters"),
    ("in #[linkage::linkage(...)]", "in the mechanism `{}`"),
    ("the attribute takes", "a mechanism takes"),
];

fn ui() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/ui")
}

/// A message and where it is: a line and a column (from 1, in
/// characters), as rustc's `-->` gives them.
#[derive(Debug, PartialEq)]
struct Located {
    message: String,
    at: Option<(usize, usize)>,
}

/// rustc's messages in a `.stderr`, in order.
fn compile_time(stderr: &str) -> Vec<Located> {
    let mut out: Vec<Located> = Vec::new();
    for line in stderr.lines() {
        if let Some(message) = line.strip_prefix("error: ") {
            out.push(Located {
                message: message.to_owned(),
                at: None,
            });
        } else if let Some(place) = line.trim_start().strip_prefix("--> ") {
            let mut parts = place.rsplitn(3, ':');
            let column = parts.next().and_then(|c| c.parse().ok());
            let line = parts.next().and_then(|l| l.parse().ok());
            let last = out.last_mut().expect("a place after a message");
            if last.at.is_none() {
                last.at = line.zip(column);
            }
        }
    }
    out
}

/// The line and column (from 1) of byte `at` of `text`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at];
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}

/// A case's file read as the compiler reads it.
struct Case {
    file: String,
    name: String,
    /// The attribute's text: the bytes between `#[linkage::linkage(` and
    /// its `)]`.
    equations: Range<usize>,
    /// Where the attribute starts (its `#`), where rustc puts a mistake of
    /// the whole attribute.
    attribute_at: usize,
    /// The struct's `f64` fields, with the bytes of their names.
    numbers: Vec<(String, Range<usize>)>,
}

fn read_case(path: &Path) -> Option<Case> {
    let file = std::fs::read_to_string(path).expect("a case's file");
    let syntax = syn::parse_file(&file).expect("a case's file parses");
    let struct_ = syntax.items.iter().find_map(|item| match item {
        syn::Item::Struct(s) => Some(s),
        _ => None,
    })?;
    let attribute = (struct_.attrs.iter())
        .find(|a| a.path().segments.iter().any(|s| s.ident == "linkage"))
        .expect("the attribute");
    let syn::Meta::List(list) = &attribute.meta else {
        panic!("the attribute has a list");
    };
    let delimiters = match &list.delimiter {
        syn::MacroDelimiter::Paren(paren) => paren.span,
        _ => panic!("the attribute's list is in parentheses"),
    };
    let equations = delimiters.open().byte_range().end..delimiters.close().byte_range().start;
    let numbers = (struct_.fields.iter())
        .filter(|f| matches!(&f.ty, syn::Type::Path(p) if p.path.is_ident("f64")))
        .map(|f| {
            let ident = f.ident.as_ref().expect("named fields");
            (ident.to_string(), ident.span().byte_range())
        })
        .collect();
    Some(Case {
        name: struct_.ident.to_string(),
        equations,
        attribute_at: attribute.pound_token.span.byte_range().start,
        numbers,
        file,
    })
}

/// The run-time messages, each label after its message, and where.
fn run_time(case: &Case) -> (Vec<Located>, Diagnostics) {
    let parameters: Vec<Parameter<'_>> = (case.numbers.iter())
        .map(|(name, at)| Parameter::declared_at(name, at.clone()))
        .collect();
    let text = &case.file[case.equations.clone()];
    let equations = Equations::at(text, case.equations.start);
    let Err(diagnostics) = text::build(&case.name, equations, &parameters) else {
        panic!("the case has a mistake");
    };
    let place = |range: Range<usize>| {
        // A mistake of the whole text is where rustc puts a mistake of
        // the whole attribute.
        let at = if range == case.equations {
            case.attribute_at
        } else {
            range.start
        };
        Some(line_column(&case.file, at))
    };
    let mut out = Vec::new();
    for d in &diagnostics {
        out.push(Located {
            message: d.message().to_owned(),
            at: d.range().and_then(place),
        });
        for label in d.labels() {
            out.push(Located {
                message: label.message().to_owned(),
                at: place(label.range()),
            });
        }
        for note in d.notes() {
            out.push(Located {
                message: note.clone(),
                at: None,
            });
        }
    }
    (out, diagnostics)
}

fn worded_at_run_time(message: &str, owner: &str) -> String {
    let mut message = message.to_owned();
    for (compile_time, run_time) in WORDS {
        message = message.replace(
            &compile_time.replace("{}", owner),
            &run_time.replace("{}", owner),
        );
    }
    message
}

#[test]
fn every_case_is_listed() {
    let mut files: Vec<String> = std::fs::read_dir(ui())
        .expect("tests/ui")
        .map(|entry| entry.expect("an entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "rs"))
        .map(|path| path.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    files.sort();
    let listed: Vec<String> = CASES.iter().map(|(name, _)| name.to_string()).collect();
    assert_eq!(files, listed, "tests/ui and the cases listed here differ");
}

#[test]
fn run_time_messages_are_the_attributes() {
    let mut compared = 0;
    for (name, counterpart) in CASES {
        let path = ui().join(format!("{name}.rs"));
        let stderr = std::fs::read_to_string(path.with_extension("stderr")).expect("a .stderr");
        let case = read_case(&path);
        let replaced = match counterpart {
            Counterpart::None(reason) => {
                assert!(
                    case.is_none(),
                    "{name} has a counterpart after all ({reason})"
                );
                continue;
            }
            Counterpart::Same => &[][..],
            Counterpart::NumbersOnly(replaced) => replaced,
        };
        let case = case.unwrap_or_else(|| panic!("{name}: a struct under the attribute"));
        let mut expected = compile_time(&stderr);
        assert!(!expected.is_empty(), "{name}: no message in the .stderr");
        for located in &mut expected {
            located.message = worded_at_run_time(&located.message, &case.name);
        }
        for (index, message) in replaced.iter() {
            expected[*index].message = message.to_string();
        }
        let (actual, diagnostics) = run_time(&case);
        assert_eq!(
            actual,
            expected,
            "{name}: the run-time messages differ from the attribute's; rendered:\n{}",
            diagnostics.render(&format!("tests/ui/{name}.rs"), &case.file, false)
        );
        compared += 1;
    }
    assert_eq!(compared, CASES.len() - 1);
}

/// The counterpart of a struct's mistakes: names given for the mechanism
/// and its parameters that the equations could not write, each at the
/// place its parameter is declared, reported with the equations' own
/// mistakes.
#[test]
fn names_that_are_not_names_are_located() {
    let file = "[parameters]\n2x = 1.0\nfn = 2.0\nl1 = 3.0\nl1 = 4.0\n\
                equations = 'u = [x], v = [t], closure = [x - l1 * t + y]'\n";
    let declared = |name: &'static str, nth: usize| {
        let at = file
            .match_indices(&format!("\n{name} ="))
            .nth(nth)
            .unwrap()
            .0
            + 1;
        Parameter::declared_at(name, at..at + name.len())
    };
    let parameters = [
        declared("2x", 0),
        declared("fn", 0),
        declared("l1", 0),
        declared("l1", 1),
    ];
    let start = file.find("u = ").unwrap();
    let equations = Equations::at(&file[start..file.rfind('\'').unwrap()], start);
    let Err(diagnostics) = text::build("Four Bar", equations, &parameters) else {
        panic!("the names are mistakes");
    };
    let rendered = diagnostics.render("bar.toml", file, false);
    let messages: Vec<&str> = diagnostics.iter().map(|d| d.message()).collect();
    assert_eq!(messages.len(), 5, "{rendered}");
    assert!(
        messages[0].starts_with("`Four Bar` is not a name"),
        "{rendered}"
    );
    assert!(messages[1].starts_with("`2x` is not a name"), "{rendered}");
    assert!(
        messages[2].starts_with("`fn` is a keyword of Rust"),
        "{rendered}"
    );
    assert_eq!(messages[3], "the parameter `l1` is declared twice");
    assert!(
        messages[4]
            .starts_with("unknown name `y`: not a coordinate, a point, a parameter of `Four Bar`"),
        "{rendered}"
    );
    assert!(rendered.contains(" --> bar.toml:2:1\n"), "{rendered}");
    assert!(rendered.contains(" --> bar.toml:3:1\n"), "{rendered}");
    assert!(rendered.contains(" --> bar.toml:5:1\n"), "{rendered}");
    assert!(rendered.contains("first `l1` is here"), "{rendered}");
    assert!(rendered.contains(" --> bar.toml:6:56\n"), "{rendered}");
}

//! The loader: a whole file read, each kind of mistake located, and
//! mutated files that never panic.

use super::*;
use proptest::prelude::*;
use std::f64::consts::TAU;

/// A small complete file; the tests change one line of it.
const GOOD: &str = r#"name = "Bar"
title = "A bar"
length_unit = "mm"
equations = '''
u = [theta3, theta4],
v = [theta2],
closure = [
    l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
    l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
],
'''

[parameters]
l1 = "80 mm"
l2 = 20
l3 = "5 cm"
l4 = "0.07 m"

[drive.theta2]
from = "0 deg"
to = "360 deg"
steps = 36
rate = "400 rpm"
at = "20 deg"

[assembly]
near = { theta3 = "70 deg", theta4 = "-50 deg" }

[drawing]
ground = { A = [0, 0], D = ["80 mm", 0] }
links = [["A", "B"], ["B", "C"], ["C", "D"]]
velocities = ["B", "C"]
"#;

/// `GOOD` with `from` replaced by `to` (the first occurrence).
fn with(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "{from}");
    GOOD.replacen(from, to, 1)
}

/// The errors of a text, each as `line:col: message`.
fn errors(text: &str) -> Vec<String> {
    match MechanismFile::parse(text) {
        Ok(_) => Vec::new(),
        Err(e) => e.errors.iter().map(ToString::to_string).collect(),
    }
}

/// The one error of a text.
fn error(text: &str) -> String {
    let all = errors(text);
    assert_eq!(all.len(), 1, "{all:#?}");
    all[0].clone()
}

#[test]
fn a_whole_file_is_read_in_the_engines_units() {
    let file = MechanismFile::parse(GOOD).unwrap();
    assert_eq!(file.name.text, "Bar");
    assert_eq!(&GOOD[file.name.span.clone()], "\"Bar\"");
    assert_eq!(file.title.as_deref(), Some("A bar"));
    assert_eq!(file.length_unit, "mm");
    // The equations: the file's bytes from their offset on.
    let eq = &file.equations;
    assert!(eq.text.starts_with("u = [theta3"));
    assert_eq!(&GOOD[eq.offset..eq.offset + eq.text.len()], eq.text);
    // Parameters in the file's order, in mm.
    let values: Vec<(&str, f64)> = file
        .parameters
        .iter()
        .map(|p| (p.name.text.as_str(), p.quantity.value))
        .collect();
    assert_eq!(
        values,
        [("l1", 80.0), ("l2", 20.0), ("l3", 50.0), ("l4", 70.0)]
    );
    let l1 = &file.parameters[0];
    assert_eq!(&GOOD[l1.name.span.clone()], "l1");
    assert_eq!(l1.quantity.unit.as_deref(), Some("mm"));
    assert_eq!(l1.quantity.kind, Kind::Length);
    assert_eq!(&GOOD[l1.quantity.span.clone().unwrap()], "\"80 mm\"");
    assert_eq!(file.parameters[1].quantity.unit, None);
    assert_eq!(file.parameters[1].quantity.kind, Kind::Number);
    // The driver.
    let d = file.driver("theta2").unwrap();
    assert_eq!((d.from.value, d.to.value), (0.0, TAU));
    assert_eq!(d.steps, 36);
    assert_eq!(d.rate.value, 400.0 * TAU / 60.0);
    assert_eq!(d.acceleration, Quantity::default_of(0.0));
    assert_eq!(d.at.value, 20f64.to_radians());
    assert_eq!(&GOOD[d.name.span.clone()], "theta2");
    // The assembly and the drawing.
    let Some(AssemblyChoice::Near(near)) = &file.assembly else {
        panic!("{:?}", file.assembly)
    };
    assert_eq!(near[0].0.text, "theta3");
    assert_eq!(near[1].1.value, (-50f64).to_radians());
    let drawing = file.drawing.as_ref().unwrap();
    assert_eq!(drawing.ground[1].0.text, "D");
    assert_eq!(drawing.ground[1].1[0].value, 80.0);
    assert_eq!(drawing.links.len(), 3);
    assert_eq!(drawing.velocities[1].text, "C");
}

#[test]
fn defaults_are_filled_in_and_said_to_be_defaults() {
    let text = with("steps = 36\nrate = \"400 rpm\"\nat = \"20 deg\"\n", "");
    let file = MechanismFile::parse(&text).unwrap();
    let d = &file.drivers[0];
    assert_eq!((d.steps, d.steps_span.clone()), (DEFAULT_STEPS, None));
    assert_eq!(d.rate, Quantity::default_of(DEFAULT_RATE));
    assert_eq!(d.at.value, d.from.value);
    assert_eq!(d.at.span, None);
    // Without length_unit, lengths are in metres.
    let text = with("length_unit = \"mm\"\n", "");
    let file = MechanismFile::parse(&text).unwrap();
    assert_eq!(file.length_unit, "m");
    assert_eq!(file.parameter("l1"), Some(0.08));
    assert_eq!(file.parameter("l2"), Some(20.0));
}

#[test]
fn the_equations_offset_is_where_their_text_starts() {
    // No newline after the quotes, a CRLF file, a one-line literal string,
    // and a basic string without escapes.
    for (form, start) in [
        ("equations = '''u = [a],'''", "u = [a],"),
        ("equations = '''\r\nu = [a],\r\n'''", "u = [a],\r\n"),
        ("equations = 'u = [a],'", "u = [a],"),
        ("equations = \"u = [a],\"", "u = [a],"),
    ] {
        let text = GOOD.replacen(
            &GOOD[GOOD.find("equations").unwrap()..GOOD.find("[parameters]").unwrap() - 1],
            form,
            1,
        );
        let file = MechanismFile::parse(&text).unwrap_or_else(|e| panic!("{form}: {e}"));
        assert_eq!(file.equations.text, start);
        assert_eq!(
            &text[file.equations.offset..][..start.len()],
            start,
            "{form}"
        );
    }
}

#[test]
fn toml_syntax_errors_come_alone_one_per_line() {
    let text = with("title = \"A bar\"", "title = = \"A bar\"\nstray");
    assert_eq!(
        errors(&text),
        [
            "2:9: TOML: extra `=`, expected nothing",
            "3:6: TOML: key with no value, expected `=`"
        ]
    );
}

#[test]
fn a_table_written_twice_is_named() {
    let text = format!("{GOOD}\n[drive.theta2]\nfrom = 0\nto = 1\n");
    assert_eq!(
        error(&text),
        "34:8: `theta2` is defined twice: a key or a table is written once"
    );
}

#[test]
fn an_unknown_key_suggests_the_closest() {
    assert_eq!(
        error(&with("title", "titel")),
        "2:1: unknown key `titel` in the file; did you mean `title`?"
    );
    assert_eq!(
        error(&with("steps = 36", "stpes = 36")),
        "22:1: unknown key `stpes` in `drive.theta2`; did you mean `steps`?"
    );
    assert_eq!(
        error(&with("links", "bars")),
        "31:1: unknown key `bars` in `drawing` (its keys: ground, links, plates, sliders, velocities, accelerations, trace, velocity_scale, acceleration_scale)"
    );
}

#[test]
fn a_value_of_the_wrong_type_says_what_belongs() {
    assert_eq!(
        error(&with("name = \"Bar\"", "name = 3")),
        "1:8: `name` must be a string, not an integer"
    );
    assert_eq!(
        error(&with("steps = 36", "steps = \"36\"")),
        "22:9: `drive.theta2.steps` must be a whole number from 1 to 1000000, not a string"
    );
    assert_eq!(
        error(&with("l2 = 20", "l2 = true")),
        "15:6: `parameters.l2` must be a number (a number, or a string such as \"80 mm\"), not a boolean"
    );
}

#[test]
fn a_missing_key_is_located_at_its_table() {
    let text = with("equations = '''", "equation = '''");
    let all = errors(&text);
    assert_eq!(
        all,
        [
            "1:1: the file has no `equations`: the closure equations, between ''' and ''' (u = [...], v = [...], closure = [...])",
            "4:1: unknown key `equation` in the file; did you mean `equations`?",
        ]
    );
    assert_eq!(
        error(&with("from = \"0 deg\"\n", "")),
        "19:1: `drive.theta2` has no `from`: the sweep's range"
    );
}

#[test]
fn an_unknown_unit_is_pointed_at() {
    assert_eq!(
        error(&with("\"80 mm\"", "\"80 mn\"")),
        "14:10: unknown unit `mn` in `parameters.l1`; did you mean `mm`?"
    );
    assert_eq!(
        error(&with("\"400 rpm\"", "\"400 furlongs/fortnight\"")),
        "23:13: unknown unit `furlongs/fortnight` in `drive.theta2.rate` (an angular rate: `rad/s`, `deg/s`, `rpm`, `rev/s`; or a linear rate: `m/s`, `mm/s`)"
    );
}

#[test]
fn a_unit_of_the_wrong_kind_for_its_place() {
    assert_eq!(
        error(&with("\"400 rpm\"", "\"400 mm\"")),
        "23:13: `drive.theta2.rate` is a length (`mm`), but a rate belongs here (an angular rate: `rad/s`, `deg/s`, `rpm`, `rev/s`; or a linear rate: `m/s`, `mm/s`)"
    );
    assert_eq!(
        error(&with("D = [\"80 mm\", 0]", "D = [\"80 deg\", 0]")),
        "30:33: `drawing.ground.D[0]` is an angle (`deg`), but a length belongs here (a length: `m`, `mm`, `cm`, `in`, `ft`)"
    );
    // A driver moves an angle or a length, not both.
    assert_eq!(
        error(&with("to = \"360 deg\"", "to = \"360 mm\"")),
        "21:6: `drive.theta2` moves an angle (`deg`), but this is a length (`mm`)"
    );
    let text = with("to = \"360 deg\"", "to = \"360 mm\"");
    let e = MechanismFile::parse(&text).unwrap_err();
    assert_eq!(e.errors[0].labels.len(), 1);
    assert_eq!(&text[e.errors[0].labels[0].0.clone()], "\"0 deg\"");
    assert_eq!(
        error(&with("length_unit = \"mm\"", "length_unit = \"deg\"")),
        "3:15: `length_unit` must be a unit of length (`m`, `mm`, `cm`, `in`, `ft`), not `deg`"
    );
}

#[test]
fn a_number_must_be_finite_and_a_number() {
    assert_eq!(
        error(&with("l2 = 20", "l2 = nan")),
        "15:6: `parameters.l2` must be a finite number: this one is not a number"
    );
    assert_eq!(
        error(&with("l2 = 20", "l2 = -inf")),
        "15:6: `parameters.l2` must be a finite number: this one is too large"
    );
    assert_eq!(
        error(&with("\"80 mm\"", "\"1e400 mm\"")),
        "14:7: `parameters.l1` must be a finite number: this one is too large"
    );
    assert_eq!(
        error(&with("\"80 mm\"", "\"eighty mm\"")),
        "14:7: `parameters.l1` must start with a number (such as \"80 mm\" or \"-1.5e3 mm\"), not `eighty mm`"
    );
    assert_eq!(
        error(&with("\"80 mm\"", "\"80,5 mm\"")),
        "14:9: unknown unit `,5 mm` in `parameters.l1` (a unit of the table of `linkage::file::units`)"
    );
}

#[test]
fn steps_are_a_positive_count() {
    assert_eq!(
        error(&with("steps = 36", "steps = 0")),
        "22:9: `drive.theta2.steps` must be a whole number from 1 to 1000000, not 0"
    );
    assert_eq!(
        error(&with("steps = 36", "steps = 99999999999999999999999")),
        "22:9: `drive.theta2.steps` must be a whole number from 1 to 1000000, not 99999999999999999999999"
    );
}

#[test]
fn a_range_of_zero_length() {
    let text = with("to = \"360 deg\"", "to = \"0 rad\"");
    assert_eq!(
        error(&text),
        "21:6: the range of `drive.theta2` has zero length: `from` and `to` are both 0"
    );
}

#[test]
fn drivers_share_their_steps() {
    let text = format!("{GOOD}\n[drive.theta5]\nfrom = 0\nto = 1\nsteps = 10\n");
    assert_eq!(
        error(&text),
        "37:9: the drivers move together in a sweep, so their steps must agree: `theta2` has 36, `theta5` 10"
    );
    // One that says nothing takes the others'.
    let text = format!("{GOOD}\n[drive.theta5]\nfrom = 0\nto = 1\n");
    let file = MechanismFile::parse(&text).unwrap();
    assert_eq!(file.driver("theta5").unwrap().steps, 36);
}

#[test]
fn names_are_identifiers_and_one_thing_each() {
    assert_eq!(
        error(&with("name = \"Bar\"", "name = \"Four bar\"")),
        "1:8: `Four bar` is not a name the equations can use: a letter or `_` first, then letters, digits and `_` (ASCII)"
    );
    assert_eq!(
        error(&with("l2 = 20", "\"l 2\" = 20")),
        "15:1: `l 2` is not a name the equations can use: a letter or `_` first, then letters, digits and `_` (ASCII)"
    );
    assert_eq!(
        error(&with("l2 = 20", "fn = 20")),
        "15:1: `fn` is a Rust keyword, which cannot be a name"
    );
    assert_eq!(
        error(&with("l2 = 20", "theta2 = 20")),
        "15:1: `theta2` is both a parameter and a driver: a name is one or the other"
    );
    assert_eq!(
        error(&with("theta4 = \"-50 deg\"", "theta2 = \"-50 deg\"")),
        "27:29: `assembly.near` sketches the dependent coordinates, and `theta2` is a driver"
    );
}

#[test]
fn the_equations_are_written_as_they_are_read() {
    let text = GOOD.replacen(
        &GOOD[GOOD.find("equations").unwrap()..GOOD.find("[parameters]").unwrap() - 1],
        "equations = \"u = [a],\\nv = [b]\"",
        1,
    );
    assert_eq!(
        error(&text),
        "4:13: the equations use escapes (`\\`): write them as a literal string, between ''' and ''', so that a place in them is a place in the file"
    );
    let text = GOOD.replacen(
        &GOOD[GOOD.find("equations").unwrap()..GOOD.find("[parameters]").unwrap() - 1],
        "equations = '''\n  \n'''",
        1,
    );
    assert_eq!(
        error(&text),
        "4:13: the equations are empty: write `u = [...], v = [...], closure = [...]` (and `points = [...]`) between ''' and '''"
    );
}

#[test]
fn the_assembly_is_picked_one_way() {
    let text = with("[assembly]\n", "[assembly]\nindex = 1\n");
    let e = MechanismFile::parse(&text).unwrap_err();
    assert_eq!(
        e.to_string(),
        "28:8: `assembly` is picked one way: `index` or `near`, not both"
    );
    assert_eq!(&text[e.errors[0].labels[0].0.clone()], "1");
    assert_eq!(
        error(&with(
            "near = { theta3 = \"70 deg\", theta4 = \"-50 deg\" }",
            ""
        )),
        "26:1: `assembly` picks no assembly: give `index`, `near` or `points`"
    );
    let text = with(
        "near = { theta3 = \"70 deg\", theta4 = \"-50 deg\" }",
        "points = { C = [\"30 mm\"] }",
    );
    assert_eq!(
        error(&text),
        "27:16: `assembly.points.C` must be a position [x, y]: two lengths, not 1"
    );
    let text = with(
        "near = { theta3 = \"70 deg\", theta4 = \"-50 deg\" }",
        "index = -1",
    );
    assert_eq!(
        error(&text),
        "27:9: `assembly.index` must be a whole number from 0 to 65536, not -1"
    );
    let text = with(
        "near = { theta3 = \"70 deg\", theta4 = \"-50 deg\" }",
        "near = {}",
    );
    assert_eq!(
        error(&text),
        "27:8: `assembly.near` is empty: name at least one"
    );
}

#[test]
fn the_drawing_is_checked_for_what_the_file_alone_tells() {
    assert_eq!(
        error(&with("[\"A\", \"B\"], ", "[\"A\", \"B\", \"C\"], ")),
        "31:10: `drawing.links[0]` must join 2 points, not 3"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "velocities = [\"B\", \"B\"]"
        )),
        "32:20: `B` is listed twice in `drawing.velocities`"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "velocities = [\"B\", 3]"
        )),
        "32:20: `drawing.velocities[1]` must be a point's name, not an integer"
    );
    assert_eq!(
        error(&with("[\"A\", \"B\"], ", "[\"A\", \"A\"], ")),
        "31:16: `A` is listed twice in `drawing.links[0]`"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "sliders = [{ point = \"C\" }]"
        )),
        "32:12: a slider needs its guide: `angle` (a fixed guide), `along` (a link) or `slot` (a slot in a translating body)"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "sliders = [{ point = \"C\", angle = 0, slot = 0 }]"
        )),
        "32:45: a slider has one guide: `angle` or `slot`, not both"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "velocity_scale = \"0.02 s\""
        )),
        "32:24: `drawing.velocity_scale` is a time (`s`), but a positive plain number belongs here (no unit: a plain number)"
    );
    assert_eq!(
        error(&with("velocities = [\"B\", \"C\"]", "velocity_scale = -1")),
        "32:18: `drawing.velocity_scale` must be positive, not -1"
    );
    assert_eq!(
        error(&with(
            "velocities = [\"B\", \"C\"]",
            "plates = [[\"A\", \"B\"]]"
        )),
        "32:11: `drawing.plates[0]` must join 3 or more points, not 2"
    );
}

#[test]
fn every_mistake_at_once_and_each_once() {
    // A unit mistaken in `from`: no follow-on error about the range or
    // the driver's kind; a misspelt key elsewhere is still reported.
    let text = with("from = \"0 deg\"", "from = \"0 dge\"").replace("title", "titel");
    assert_eq!(
        errors(&text),
        [
            "2:1: unknown key `titel` in the file; did you mean `title`?",
            "20:11: unknown unit `dge` in `drive.theta2.from`; did you mean `deg`?",
        ]
    );
}

#[test]
fn a_file_is_read_from_disk_or_says_why_not() {
    let folder = std::env::temp_dir().join(format!("linkage-file-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let good = folder.join("good.toml");
    std::fs::write(&good, GOOD).unwrap();
    assert_eq!(MechanismFile::read(&good).unwrap().name.text, "Bar");
    let bad = folder.join("bad.toml");
    std::fs::write(&bad, with("steps = 36", "steps = 0")).unwrap();
    match MechanismFile::read(&bad) {
        Err(ReadError::Invalid { text, errors, .. }) => {
            assert!(text.contains("steps = 0"));
            assert_eq!(errors.errors.len(), 1);
        }
        other => panic!("{other:?}"),
    }
    let binary = folder.join("binary.toml");
    std::fs::write(&binary, b"name = \"\xff\"\n").unwrap();
    match MechanismFile::read(&binary) {
        Err(ReadError::Invalid { errors, .. }) => {
            assert_eq!(
                errors.to_string(),
                "1:9: the file is not UTF-8 text: a mechanism file is text in UTF-8"
            );
        }
        other => panic!("{other:?}"),
    }
    let missing = folder.join("missing.toml");
    assert!(matches!(
        MechanismFile::read(&missing),
        Err(ReadError::Io { .. })
    ));
    std::fs::remove_dir_all(&folder).unwrap();
}

/// What may be spliced into a file by the fuzzer.
const SNIPPETS: [&str; 16] = [
    "nan",
    "inf",
    "-inf",
    "1e999",
    "\"1e999 mm\"",
    "99999999999999999999999",
    "[[[[[[[[[[",
    "]]]]",
    "{",
    "'''",
    "\"",
    "\\u00",
    "=",
    "\n[drive.theta2]\n",
    "\"0 rad\"",
    "é",
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Random edits of a good file: a byte changed, a cut, a snippet
    /// spliced in, deep nesting. Never a panic; every error inside the
    /// text; a file read has its equations where it says.
    #[test]
    fn mutated_files_never_panic(
        edits in prop::collection::vec((0usize..2000, 0u8..=255, 0usize..SNIPPETS.len(), 0u8..4), 1..6),
        cut in prop::option::of(0usize..2000),
        nesting in prop::option::of(1usize..5000),
    ) {
        let mut bytes = GOOD.as_bytes().to_vec();
        for (at, byte, snippet, how) in edits {
            let at = at % (bytes.len() + 1);
            match how {
                0 if at < bytes.len() => bytes[at] = byte,
                1 => bytes.splice(at..at, SNIPPETS[snippet].bytes()).for_each(drop),
                2 if at < bytes.len() => { bytes.remove(at); }
                _ => bytes.insert(at, byte),
            }
        }
        if let Some(cut) = cut {
            bytes.truncate(cut.min(bytes.len()));
        }
        if let Some(depth) = nesting {
            bytes.extend_from_slice(b"\nx = ");
            bytes.extend(std::iter::repeat_n(b'[', depth));
            bytes.extend(std::iter::repeat_n(b']', depth));
        }
        let text = String::from_utf8_lossy(&bytes).into_owned();
        match MechanismFile::parse(&text) {
            Ok(file) => {
                let eq = &file.equations;
                prop_assert_eq!(text.get(eq.offset..eq.offset + eq.text.len()), Some(eq.text.as_str()));
                for p in &file.parameters {
                    prop_assert!(p.quantity.value.is_finite());
                }
            }
            Err(errors) => {
                prop_assert!(!errors.errors.is_empty());
                for e in &errors.errors {
                    prop_assert!(e.at.start <= e.at.end && e.at.end <= text.len(), "{:?}", e);
                    prop_assert_eq!(e.line_col(&text), (e.line, e.column));
                    for (at, _) in &e.labels {
                        prop_assert!(at.end <= text.len());
                    }
                }
            }
        }
    }

    /// Any value in any place: a number, a quantity string, or garbage.
    #[test]
    fn any_value_anywhere(
        place in 0usize..8,
        value in prop_oneof![
            any::<f64>().prop_map(|x| format!("{x:?}")),
            any::<i64>().prop_map(|x| x.to_string()),
            ("[-+]?[0-9.eE+-]{0,12}", "[ ]?", "(mm|m|deg|rad|rpm|rad/s|m/s\\^2|rad/s²|N·m|kN|g|x|)")
                .prop_map(|(n, s, u)| format!("\"{n}{s}{u}\"")),
            "\\PC{0,20}".prop_map(|s| format!("{s:?}")),
        ],
    ) {
        let key = ["l2 = 20", "steps = 36", "rate = \"400 rpm\"", "at = \"20 deg\"",
            "index = 0", "D = [\"80 mm\", 0]", "velocities = [\"B\", \"C\"]", "name = \"Bar\""][place];
        let text = match place {
            4 => with("near = { theta3 = \"70 deg\", theta4 = \"-50 deg\" }", &format!("index = {value}")),
            5 => with(key, &format!("D = [{value}, 0]")),
            _ => with(key, &format!("{} = {value}", key.split(" =").next().unwrap())),
        };
        if let Err(errors) = MechanismFile::parse(&text) {
            for e in &errors.errors {
                prop_assert!(e.at.end <= text.len());
            }
        }
    }
}

#[test]
fn the_modules_example_file_reads() {
    let doc: String = include_str!("mod.rs")
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .map(|l| format!("{}\n", l.strip_prefix(' ').unwrap_or(l)))
        .collect();
    let start = doc.find("```toml\n").unwrap() + "```toml\n".len();
    let end = start + doc[start..].find("```").unwrap();
    let file = MechanismFile::parse(&doc[start..end]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(file.name.text, "FourBar");
    assert_eq!(file.parameter("l3"), Some(50.0));
    assert_eq!(file.parameter("l4"), Some(70.0));
}

/// No key of a mechanism file is a path: the module reaches the file
/// system once, in `MechanismFile::read`, for the path it is given. (What
/// a file holds — a title, names, units, values, keys it does not know —
/// is read as text and never opened; `tests/files/paths.rs` runs files
/// whose every string is a path.)
#[test]
fn the_module_opens_no_path_but_the_one_it_is_given() {
    let sources = [
        ("assembly.rs", include_str!("assembly.rs")),
        ("decimal.rs", include_str!("decimal.rs")),
        ("drawing.rs", include_str!("drawing.rs")),
        ("drive.rs", include_str!("drive.rs")),
        ("drives.rs", include_str!("drives.rs")),
        ("equations.rs", include_str!("equations.rs")),
        ("error.rs", include_str!("error.rs")),
        ("lines.rs", include_str!("lines.rs")),
        ("mechanism.rs", include_str!("mechanism.rs")),
        ("mod.rs", include_str!("mod.rs")),
        ("names.rs", include_str!("names.rs")),
        ("parameters.rs", include_str!("parameters.rs")),
        ("quantity.rs", include_str!("quantity.rs")),
        ("reader.rs", include_str!("reader.rs")),
        ("rewrite.rs", include_str!("rewrite.rs")),
        ("scene.rs", include_str!("scene.rs")),
        ("suggest.rs", include_str!("suggest.rs")),
        ("syntax.rs", include_str!("syntax.rs")),
        ("topology.rs", include_str!("topology.rs")),
        ("units.rs", include_str!("units.rs")),
    ];
    // Every source of the module is read here.
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/file");
    for entry in std::fs::read_dir(folder).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".rs") && name != "tests.rs" {
            assert!(
                sources.iter().any(|(n, _)| *n == name),
                "{name} is not read here"
            );
        }
    }
    let reaches = [
        "std::fs",
        "fs::",
        "File::open",
        "File::create",
        "OpenOptions",
        "std::env",
        "std::process",
        "std::net",
    ];
    let mut found = Vec::new();
    for (name, source) in sources {
        for (k, line) in source.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            if reaches.iter().any(|r| code.contains(r)) {
                found.push(format!("{name}:{}: {}", k + 1, line.trim()));
            }
        }
    }
    assert_eq!(found.len(), 1, "{found:#?}");
    assert!(found[0].contains("std::fs::read(path)"), "{found:#?}");
}

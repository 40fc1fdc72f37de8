//! Fuzzing topologies: topology files (the library's of
//! `mechanisms/joints/`, mutated token by token; made up from joints and
//! links at random: pins, sliders and slots on random links, drivers of
//! random lines, lengths given), pyslvs's expressions (its 22 examples,
//! mutated) and pylinkage's JSON (its examples, mutated). Each is read
//! (a topology file's mistakes located in it), checked, its equations
//! generated, and the mechanism file they make run as the file campaign
//! runs one: assembled, analysed, swept, drawn.

use super::mutate;
use super::random::Rng;
use super::run::{self, Report, located};
use linkage::file::TopologyFile;
use linkage::mechanism::Diagnostics;
use linkage::topology::Topology;
use linkage::topology::pylinkage::from_pylinkage;
use linkage::topology::pyslvs::from_pyslvs;

/// The topology files of `mechanisms/joints/`.
const LIBRARY: &[&str] = &[
    include_str!("../../../mechanisms/joints/four_bar.toml"),
    include_str!("../../../mechanisms/joints/jansen_double.toml"),
    include_str!("../../../mechanisms/joints/quick_return.toml"),
    include_str!("../../../mechanisms/joints/shaper.toml"),
    include_str!("../../../mechanisms/joints/slider_crank.toml"),
];

/// pyslvs's examples' expressions and inputs.
fn pyslvs_examples() -> Vec<(String, Vec<(usize, usize)>)> {
    let data: serde_json::Value =
        serde_json::from_str(include_str!("../../data/pyslvs_examples.json")).unwrap();
    (data["examples"].as_array().unwrap().iter())
        .map(|e| {
            let inputs = (e["inputs"].as_array().unwrap().iter())
                .map(|p| {
                    (
                        p[0].as_u64().unwrap() as usize,
                        p[1].as_u64().unwrap() as usize,
                    )
                })
                .collect();
            (e["expression"].as_str().unwrap().to_owned(), inputs)
        })
        .collect()
}

const PYLINKAGE: &[&str] = &[
    include_str!("../../data/pylinkage/readme_fourbar.json"),
    include_str!("../../data/pylinkage/hoeken.json"),
    include_str!("../../data/pylinkage/mechanism_slider_crank.json"),
    include_str!("../../data/pylinkage/strider.json"),
    include_str!("../../data/pylinkage/stroke_engine.json"),
];

/// A case: what is read, and how.
#[derive(Debug)]
pub(crate) enum TopologyCase {
    File(String),
    Pyslvs(String, Vec<(usize, usize)>),
    Pylinkage(String),
}

/// A made-up topology: a few joints at random places (pins mostly,
/// sliders and slots now and then), links of two to four of them, a
/// driver or two of random lines, a length given now and then.
fn made(rng: &mut Rng) -> String {
    let joints = rng.between(2, 9);
    let mut text = String::from("name = \"Fuzz\"\nlength_unit = \"mm\"\n\n[joints]\n");
    for j in 0..joints {
        let (x, y) = (
            (rng.unit() * 200.0 - 100.0).round(),
            (rng.unit() * 200.0 - 100.0).round(),
        );
        let (x, y) = if rng.one_in(40) {
            (f64::NAN, y)
        } else {
            (x, y)
        };
        match rng.below(8) {
            0 => {
                text += &format!(
                    "J{j} = {{ at = [{x}, {y}], slider = \"{} deg\" }}\n",
                    rng.below(180)
                )
            }
            1 => {
                text += &format!(
                    "J{j} = {{ at = [{x}, {y}], slot = \"{} deg\" }}\n",
                    rng.below(180)
                )
            }
            _ => text += &format!("J{j} = [{x}, {y}]\n"),
        }
    }
    text += "\n[links]\n";
    let links = rng.between(1, 7);
    for l in 0..links {
        let name = if l == 0 {
            "ground".to_owned()
        } else {
            format!("L{l}")
        };
        let members: Vec<String> = (0..rng.between(1, 4))
            .map(|_| format!("\"J{}\"", rng.below(joints + 1)))
            .collect();
        text += &format!("{name} = [{}]\n", members.join(", "));
    }
    for _ in 0..rng.between(0, 2) {
        text += &format!(
            "\n[[drive]]\nangle = [\"J{}\", \"J{}\"]\n",
            rng.below(joints),
            rng.below(joints)
        );
        if rng.one_in(3) {
            text += &format!(
                "from = \"{} deg\"\nto = \"{} deg\"\n",
                rng.below(360),
                rng.below(720)
            );
        }
    }
    if rng.one_in(3) {
        text += &format!("\n[lengths]\nJ0-J1 = {}\n", rng.unit() * 100.0);
    }
    text
}

pub(crate) fn input(rng: &mut Rng) -> TopologyCase {
    match rng.below(10) {
        0..=3 => {
            let file = rng_pick(rng, LIBRARY);
            TopologyCase::File(mutate::mutate_few(rng, file))
        }
        4..=5 => TopologyCase::File(made(rng)),
        6..=7 => {
            let examples = pyslvs_examples();
            let (expression, own) = &examples[rng.below(examples.len())];
            let text = if rng.one_in(3) {
                expression.clone()
            } else {
                mutate::mutate_few(rng, expression)
            };
            let inputs = if rng.one_in(2) {
                own.clone()
            } else {
                (0..rng.between(0, 2))
                    .map(|_| (rng.below(12), rng.below(12)))
                    .collect()
            };
            TopologyCase::Pyslvs(text, inputs)
        }
        _ => {
            let json = rng_pick(rng, PYLINKAGE);
            TopologyCase::Pylinkage(mutate::mutate_few(rng, json))
        }
    }
}

fn rng_pick<'a>(rng: &mut Rng, xs: &[&'a str]) -> &'a str {
    xs[rng.below(xs.len())]
}

/// The mechanism file of a read topology, run as a file case; a file the
/// generator writes that does not read is its fault.
fn generated(report: &mut Report, topology: &Topology) {
    match topology.mechanism_text() {
        Err(errors) => {
            let _ = errors.to_string();
            if errors.errors.is_empty() {
                report
                    .internal
                    .push("a topology refused without a mistake".into());
            }
            if errors
                .errors
                .iter()
                .any(|e| matches!(e, linkage::topology::TopologyError::Generated { .. }))
            {
                report
                    .internal
                    .push(format!("the generated file does not read: {errors}"));
            }
            report.kind = "topology: refused".into();
        }
        Ok(text) => {
            let inner = run::file_case(&text);
            report.lies.extend(inner.lies);
            // A mistake in generated text is the generator's.
            report.internal.extend(
                inner
                    .unlocated
                    .into_iter()
                    .map(|u| format!("in the generated file: {u}")),
            );
            report.internal.extend(inner.internal);
            if inner.kind.starts_with("file:")
                || inner.kind.starts_with("build:") && !inner.kind.contains("Singular")
            {
                report.internal.push(format!(
                    "the generated file is refused: {}\n{text}",
                    inner.kind
                ));
            }
            report.kind = match inner.kind.strip_prefix("Ok") {
                Some(rest) => format!("Ok (generated){rest}"),
                None => format!("generated: {}", inner.kind),
            };
        }
    }
}

pub(crate) fn run(case: &TopologyCase) -> Report {
    let mut report = Report::default();
    match case {
        TopologyCase::File(text) => match TopologyFile::parse(text) {
            Err(errors) => {
                let _ = errors.to_string();
                let diagnostics = Diagnostics::from(&errors);
                located(&mut report, &diagnostics, text, &[]);
                if errors.errors.is_empty() {
                    report
                        .unlocated
                        .push("a file refused without a mistake".into());
                }
                report.kind = "topology file: refused".into();
            }
            Ok(file) => generated(&mut report, &file.topology),
        },
        TopologyCase::Pyslvs(text, inputs) => match from_pyslvs("Fuzz", text, inputs) {
            Err(e) => {
                let _ = e.to_string();
                report.kind = "pyslvs: refused".into();
            }
            Ok(topology) => generated(&mut report, &topology),
        },
        TopologyCase::Pylinkage(text) => match from_pylinkage(text) {
            Err(e) => {
                let _ = e.to_string();
                report.kind = "pylinkage: refused".into();
            }
            Ok((topology, _)) => generated(&mut report, &topology),
        },
    }
    report
}

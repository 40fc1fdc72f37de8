//! pylinkage's example linkages, read from pylinkage's own JSON
//! (`mechanism_to_dict`) and driven step by step as pylinkage drives them,
//! each joint held to pylinkage's simulation (tests/data/pylinkage/, made
//! by benches/peers/pylinkage_examples.py with pylinkage 1.3.0).
//!
//! pylinkage solves each step in closed form (circle–circle and
//! circle–line intersections, the root nearest the last position), exact
//! to ~1e-15, its crank angle re-read from the positions each step (a
//! drift of ~1e-14 over a turn): held here to 1e-11 of the drawing's size.

use linkage::assembly::Assemble;
use linkage::file::MechanismFile;
use linkage::mechanism::Fixed;
use linkage::prelude::*;
use linkage::topology::pylinkage::{from_pylinkage, to_pylinkage};
use linkage::topology::{Driven, TopologyError};
use serde_json::Value;

/// The examples whose JSON pylinkage itself re-simulates as the linkage
/// (the others lose a side of a fixed dyad or a line's anchors in it).
const FAITHFUL: [&str; 8] = [
    "readme_fourbar",
    "fourbar_linkage",
    "hoeken",
    "fourbar_from_lengths",
    "readme_path_synthesis",
    "readme_builder_fourbar",
    "mechanism_fourbar",
    "mechanism_slider_crank",
];

fn read(name: &str) -> (String, Value) {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pylinkage");
    let json = std::fs::read_to_string(dir.join(format!("{name}.json"))).unwrap();
    let positions = std::fs::read_to_string(dir.join(format!("{name}_positions.json"))).unwrap();
    (json, serde_json::from_str(&positions).unwrap())
}

/// The largest distance of a joint from pylinkage's, over every step.
fn worst<const M: usize>(
    name: &str,
    file: &MechanismFile,
    drawn: f64,
    ids: &[(String, String)],
    reference: &Value,
) -> (f64, usize) {
    let model: Fixed<M, 1> = file.mechanism().unwrap().fixed::<M, 1>().unwrap();
    let driver = &file.drivers[0];
    let Some(linkage::file::AssemblyChoice::Near(near)) = &file.assembly else {
        panic!("{name}: a sketch");
    };
    let u_names = model.u_names();
    let guess = SVector::<f64, M>::from_fn(|k, _| {
        near.iter()
            .find(|(n, _)| n.text == u_names[k])
            .unwrap()
            .1
            .value
    });
    let names: Vec<String> = (reference["joint_names"].as_array().unwrap().iter())
        .map(|n| n.as_str().unwrap().to_owned())
        .collect();
    let name_of = |id: &str| ids.iter().find(|(i, _)| i == id).unwrap().1.clone();
    let reference_steps = reference["steps"].as_array().unwrap();
    let steps = reference["iterations"].as_u64().unwrap() as usize;
    let dt = reference["dt"].as_f64().unwrap();
    let rate = driver.rate.value;
    assert!(
        (drawn - driver.at.value).abs() < 1e-12,
        "{name}: drawn at its initial angle"
    );
    // As drawn, where pylinkage starts its crank; or, where the drawing is
    // a change point (every pin on one line: the drawing picks no
    // branch, and linkage will not start there), from pylinkage's first
    // step, on the branch it took.
    let (first, start) = match model.solve_position(&guess, &vector![drawn], &Options::default()) {
        Ok(pose) => (0, pose.u),
        Err(linkage::Error::Singular { .. }) => {
            let point_names = model.point_names();
            let sketch = (names.iter().enumerate())
                .filter(|(_, id)| point_names.contains(&name_of(id).as_str()))
                .map(|(j, id)| {
                    let p = &reference_steps[0][j];
                    (
                        name_of(id),
                        Vector2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()),
                    )
                })
                .collect();
            let v = vector![driver.at.value + rate * dt];
            let mode = model
                .assemble(&v, &linkage::assembly::Pick::NearestPoints(sketch))
                .unwrap_or_else(|e| panic!("{name}: at the first step: {e}"));
            (1, mode.u)
        }
        Err(e) => panic!("{name}: as drawn: {e}"),
    };
    let drive = Drive::Line {
        from: vector![driver.at.value + rate * dt * first as f64],
        to: vector![driver.at.value + rate * dt * steps as f64],
        steps: steps - first,
    };
    let sweep = (model.sweep(&start, &drive, &SweepOptions::default()))
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(sweep.complete, "{name}: the drive stops");
    let point_names = model.point_names();
    let mut worst = 0.0_f64;
    let mut compared = 0;
    // Beyond a branch point (a change point: the parallelogram's pins in
    // one line) the branch is a choice: the sweep keeps the smooth
    // continuation, pylinkage's nearest root may cross over. Compared up
    // to there.
    let branch = (sweep.events.iter())
        .find(|e| e.kind == EventKind::BranchPoint)
        .map(|e| e.v[0]);
    let v_of = |k: usize| driver.at.value + rate * dt * (k + 1) as f64;
    for (k, step) in reference_steps.iter().enumerate().skip(first) {
        let v = v_of(k);
        if branch.is_some_and(|b| (v - b) * rate > 0.0) {
            break;
        }
        let Some(pose) = sweep.poses.iter().find(|p| (p.v[0] - v).abs() < 1e-9) else {
            continue;
        };
        let points = model.point_positions(&pose.u, &pose.v);
        compared += 1;
        for (j, id) in names.iter().enumerate() {
            let name = name_of(id);
            let theirs = Vector2::new(step[j][0].as_f64().unwrap(), step[j][1].as_f64().unwrap());
            let ours = match point_names.iter().position(|n| *n == name) {
                Some(p) => points.as_ref()[p],
                None => Vector2::new(
                    file.parameter(&format!("x_{name}")).unwrap(),
                    file.parameter(&format!("y_{name}")).unwrap(),
                ),
            };
            worst = worst.max((ours - theirs).amax());
        }
    }
    (worst, compared)
}

#[test]
fn pylinkages_examples_match_pylinkage_step_by_step() {
    let mut report = Vec::new();
    for name in FAITHFUL {
        let (json, reference) = read(name);
        let (topology, ids) = from_pylinkage(&json).unwrap_or_else(|e| panic!("{name}: {e}"));
        let file = topology
            .mechanism_file()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let m = file.mechanism().unwrap().m();
        // The crank's angle as drawn.
        let Driven::Angle { from, to } = &topology.drivers[0].driven else {
            panic!("{name}: a crank");
        };
        let at = |n: &str| topology.joints.iter().find(|j| j.name == n).unwrap().at;
        let (a, b) = (at(from), at(to));
        let drawn = (b[1] - a[1]).atan2(b[0] - a[0]);
        let (miss, compared) = match m {
            2 => worst::<2>(name, &file, drawn, &ids, &reference),
            3 => worst::<3>(name, &file, drawn, &ids, &reference),
            4 => worst::<4>(name, &file, drawn, &ids, &reference),
            5 => worst::<5>(name, &file, drawn, &ids, &reference),
            6 => worst::<6>(name, &file, drawn, &ids, &reference),
            7 => worst::<7>(name, &file, drawn, &ids, &reference),
            8 => worst::<8>(name, &file, drawn, &ids, &reference),
            10 => worst::<10>(name, &file, drawn, &ids, &reference),
            12 => worst::<12>(name, &file, drawn, &ids, &reference),
            other => panic!("{name}: m = {other}"),
        };
        report.push(format!("{name}: {miss:.1e} over {compared} steps"));
        let steps = reference["iterations"].as_u64().unwrap() as usize;
        // The parallelograms from their first step to their change point
        // (half a turn); the others every step.
        let expected = match name {
            "readme_fourbar" => 9,
            "fourbar_linkage" => 8,
            _ => steps,
        };
        assert_eq!(compared, expected, "{name}");
        assert!(
            miss < 1e-11,
            "{name}: {miss:e}\n{}",
            topology.mechanism_text().unwrap()
        );
    }
    eprintln!("{}", report.join("\n"));
}

/// The two examples whose JSON pylinkage itself does not re-simulate as
/// the linkage (3 and 4.2 apart): the stroke engine's line is written as
/// a link pinned to the frame twice, which linkage refuses, naming it; the
/// strider's positions are rough hints that its lengths are then read
/// from, which linkage takes as drawn: it assembles and turns.
#[test]
fn pylinkages_unfaithful_examples_are_refused_or_taken_as_drawn() {
    let (json, _) = read("stroke_engine");
    let (topology, _) = from_pylinkage(&json).unwrap();
    let errors = topology.check().unwrap_err().errors;
    assert!(
        matches!(&errors[..], [TopologyError::RigidPair { links, .. }] if links[1] == "Slider_guide"),
        "{errors:?}"
    );
    let (json, _) = read("strider");
    let (topology, _) = from_pylinkage(&json).unwrap();
    let file = topology.mechanism_file().unwrap();
    let model = file.mechanism().unwrap().fixed::<12, 1>().unwrap();
    let Some(linkage::file::AssemblyChoice::Near(near)) = &file.assembly else {
        panic!("a sketch");
    };
    let u_names = model.u_names();
    let guess = SVector::<f64, 12>::from_fn(|k, _| {
        near.iter()
            .find(|(n, _)| n.text == u_names[k])
            .unwrap()
            .1
            .value
    });
    let Driven::Angle { from, to } = &topology.drivers[0].driven else {
        panic!("a crank");
    };
    let at = |n: &str| topology.joints.iter().find(|j| j.name == n).unwrap().at;
    let (a, b) = (at(from), at(to));
    let drawn = (b[1] - a[1]).atan2(b[0] - a[0]);
    let start = model
        .solve_position(&guess, &vector![drawn], &Options::default())
        .unwrap();
    let turn = Drive::Line {
        from: vector![drawn],
        to: vector![drawn + std::f64::consts::TAU],
        steps: 360,
    };
    let sweep = model
        .sweep(&start.u, &turn, &SweepOptions::default())
        .unwrap();
    assert!(sweep.complete);
}

/// Written back as pylinkage's JSON and read again, each is the same
/// topology.
#[test]
fn every_example_reads_back_from_its_written_json() {
    for name in FAITHFUL {
        let (json, _) = read(name);
        let (topology, ids) = from_pylinkage(&json).unwrap();
        let written = to_pylinkage(&topology, &ids).unwrap();
        let (again, _) =
            from_pylinkage(&written).unwrap_or_else(|e| panic!("{name}: {e}\n{written}"));
        assert_eq!(again, topology, "{name}\n{written}");
    }
}

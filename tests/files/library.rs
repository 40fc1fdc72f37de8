//! Each file of `mechanisms/` against its compiled twin.

use crate::machine::{COURSE_PROJECT, synthesize};
use crate::models::{
    BOOM, Coupler, FIVE_BAR, JANSEN_LEG, QUICK_RETURN, SIX_BAR, SLIDER_CRANK, SLIDER_DRIVEN,
    STEPHENSON_THREE, TRAMMEL, WATT_SIX_BAR,
};
use crate::twins::{self, attribute};
use linkage::assembly::{Pick, Search, modes};
use linkage::file::{AssemblyChoice, MechanismFile};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use std::collections::BTreeSet;
use std::f64::consts::TAU;

/// Each file of the library, and the source of its compiled twin.
const LIBRARY: [(&str, &str); 13] = [
    ("four_bar.toml", include_str!("../../src/mechanisms.rs")),
    (
        "slider_crank.toml",
        include_str!("../models/slider_crank.rs"),
    ),
    (
        "slider_driven.toml",
        include_str!("../models/slider_driven.rs"),
    ),
    ("five_bar.toml", include_str!("../models/five_bar.rs")),
    ("boom.toml", include_str!("../models/boom.rs")),
    ("six_bar.toml", include_str!("../models/six_bar.rs")),
    (
        "watt_six_bar.toml",
        include_str!("../models/watt_six_bar.rs"),
    ),
    (
        "stephenson_three.toml",
        include_str!("../models/stephenson_three.rs"),
    ),
    ("coupler.toml", include_str!("../models/coupler.rs")),
    (
        "shaper.toml",
        include_str!("../../examples/shaper/machine.rs"),
    ),
    ("jansen_leg.toml", include_str!("../models/jansen_leg.rs")),
    (
        "quick_return.toml",
        include_str!("../models/quick_return.rs"),
    ),
    ("trammel.toml", include_str!("../models/trammel.rs")),
];

/// The file `mechanisms/<name>`: its text and what it says.
fn load(name: &str) -> (String, MechanismFile) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("mechanisms")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    let file = MechanismFile::read(&path).unwrap_or_else(|e| panic!("{e}"));
    (text, file)
}

/// Rust's tokens of a text, as a string: spacing, line breaks and comments
/// aside.
fn tokens(text: &str) -> String {
    text.parse::<proc_macro2::TokenStream>()
        .unwrap_or_else(|e| panic!("{e}: {text}"))
        .to_string()
}

#[test]
fn every_file_of_the_library_loads_and_says_what_it_is() {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("mechanisms");
    let on_disk: BTreeSet<String> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    let listed: BTreeSet<String> = LIBRARY.iter().map(|(f, _)| f.to_string()).collect();
    assert_eq!(
        on_disk, listed,
        "each file of mechanisms/ is listed with its twin"
    );
    for name in &on_disk {
        let (text, _) = load(name);
        // A comment header: what it is and where its numbers come from.
        let header: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
        assert!(header.len() >= 4, "{name}: its header");
        assert!(
            text.contains("Numbers:"),
            "{name}: where its numbers come from"
        );
    }
}

#[test]
fn the_equations_are_the_twins_token_for_token() {
    for (name, source) in LIBRARY {
        let (_, file) = load(name);
        let twin = attribute(source, &file.name.text);
        assert_eq!(
            tokens(&file.equations.text),
            tokens(twin),
            "{name}: the equations differ from {}'s",
            file.name.text
        );
    }
}

/// The file's parameters are the twin's (`params()`, named by
/// `PARAM_NAMES`), each to the bit, none missing, none more.
fn same_parameters<L: Sensitivities<M, F, K>, const M: usize, const F: usize, const K: usize>(
    name: &str,
    file: &MechanismFile,
    model: &L,
) {
    let values = model.params();
    for (k, param) in model.param_names().iter().enumerate() {
        let written = file
            .parameter(param)
            .unwrap_or_else(|| panic!("{name}: no parameter {param}"));
        assert_eq!(
            written.to_bits(),
            values[k].to_bits(),
            "{name}: {param} = {written} in the file, {} in the twin",
            values[k]
        );
    }
    assert_eq!(
        file.parameters.len(),
        K,
        "{name}: parameters the twin has not"
    );
}

/// The pick the file's assembly says, on the twin's coordinates.
fn pick<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    file: &MechanismFile,
) -> Pick<M> {
    let names = model.u_names();
    match &file.assembly {
        None => Pick::Index(0),
        Some(AssemblyChoice::Index { index, .. }) => Pick::Index(*index),
        Some(AssemblyChoice::Near(sketch)) => Pick::nearest(SVector::from_fn(|k, _| {
            let (_, q) = sketch
                .iter()
                .find(|(n, _)| n.text == names[k])
                .unwrap_or_else(|| panic!("the sketch has no {}", names[k]));
            q.value
        })),
        Some(AssemblyChoice::Points(sketch)) => Pick::NearestPoints(
            sketch
                .iter()
                .map(|(n, [x, y])| (n.text.clone(), vector![x.value, y.value]))
                .collect(),
        ),
        Some(other) => panic!("an assembly this test does not know: {other:?}"),
    }
}

/// One driver value of each of the twin's driving coordinates.
fn drive<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    file: &MechanismFile,
    of: impl Fn(&linkage::file::Driver) -> f64,
) -> SVector<f64, F> {
    let names = model.v_names();
    SVector::from_fn(|k, _| of(file.driver(names[k]).unwrap()))
}

/// The file's assembly, at its `at`, carried to `from`, then swept to
/// `to` on the twin: the whole range runs. The analysis at `at` draws the
/// file's picture.
fn runs<L: Linkage<M, F>, const M: usize, const F: usize>(
    name: &str,
    file: &MechanismFile,
    model: &L,
) {
    let names: BTreeSet<&str> = file.drivers.iter().map(|d| d.name.text.as_str()).collect();
    assert_eq!(
        names,
        model.v_names().into_iter().collect(),
        "{name}: the drivers"
    );
    let at = drive(model, file, |d| d.at.value);
    let from = drive(model, file, |d| d.from.value);
    let to = drive(model, file, |d| d.to.value);
    let found = modes(model, &at, &Search::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mode = found
        .pick(&pick(model, file))
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    let options = SweepOptions::default();
    let start = if at == from {
        mode.u
    } else {
        let back = Drive::Line {
            from: at,
            to: from,
            steps: 100,
        };
        let sweep = model.sweep(&mode.u, &back, &options).unwrap();
        assert!(sweep.complete, "{name}: from `at` back to `from`");
        sweep.poses.last().unwrap().u
    };
    let steps = file.drivers[0].steps;
    let whole = Drive::Line { from, to, steps };
    let sweep = model
        .sweep(&start, &whole, &options)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(
        sweep.complete,
        "{name}: the sweep stopped at {:?}",
        sweep.poses.last().map(|p| p.v)
    );
    #[cfg(feature = "draw")]
    if file.drawing.is_some() {
        use linkage::draw::scene::Frame;
        let rate = drive(model, file, |d| d.rate.value);
        let acceleration = drive(model, file, |d| d.acceleration.value);
        let analysis = model
            .analyze(&mode.u, &at, &rate, &acceleration, &Options::default())
            .unwrap();
        let frame = Frame::from_analysis(model, &analysis);
        let cycle: Vec<Frame> = sweep
            .poses
            .iter()
            .map(|p| Frame::from_sweep_pose(model, p))
            .collect();
        let svg = file
            .scene()
            .render(&frame, &cycle)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(svg.starts_with("<svg"));
    }
}

/// The file read at run time is its twin: every kernel and the
/// sensitivities at poses in motion, and the sweep over its drive range
/// from its assembly with the sensitivities of every pose, to the bit.
fn same_at_run_time<L, const M: usize, const F: usize, const K: usize>(
    name: &str,
    file: &MechanismFile,
    model: &L,
) where
    L: Linkage<M, F> + Sensitivities<M, F, K>,
{
    let mechanism = file.mechanism().unwrap_or_else(|e| panic!("{name}: {e}"));
    let run_time = mechanism
        .fixed::<M, F>()
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    // By the twin's parameters in the twin's order (a file may list them
    // in another).
    let sensitive = mechanism
        .differentiated_by::<M, F, 32, K>(&model.param_names())
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    for [u, v, udot, vdot, uddot, vddot] in twins::motions::<M, F>(40) {
        let (m, f) = (
            SVector::<f64, M>::from_column_slice,
            SVector::<f64, F>::from_column_slice,
        );
        let motion = Motion {
            u: m(&u),
            v: f(&v),
            udot: m(&udot),
            vdot: f(&vdot),
            uddot: m(&uddot),
            vddot: f(&vddot),
        };
        twins::every_kernel(
            model,
            &run_time,
            &motion.u,
            &motion.v,
            &motion.udot,
            &motion.vdot,
            &motion.uddot,
            &motion.vddot,
        );
        twins::every_sensitivity_kernel(model, &sensitive, &motion);
    }
    let at = drive(model, file, |d| d.at.value);
    let from = drive(model, file, |d| d.from.value);
    let to = drive(model, file, |d| d.to.value);
    let start = modes(model, &at, &Search::default())
        .and_then(|found| found.pick(&pick(model, file)).cloned())
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    let options = SweepOptions::default();
    let mut drives = Vec::new();
    if at != from {
        drives.push(Drive::Line {
            from: at,
            to: from,
            steps: 50,
        });
    }
    drives.push(Drive::Line {
        from,
        to,
        steps: file.drivers[0].steps,
    });
    for drive in drives {
        let compiled = model
            .sweep(&start.u, &drive, &options)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let read = run_time
            .sweep(&start.u, &drive, &options)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        twins::same_sweep(&compiled, &read);
        let mut expected = Vec::new();
        model
            .sweep_sensitivities_each(&start.u, &drive, &options, |_, s| expected.push(s))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut poses = 0;
        sensitive
            .sweep_sensitivities_each(&start.u, &drive, &options, |_, s| {
                twins::same_sensitivity(&expected[poses], &s);
                poses += 1;
            })
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            poses,
            expected.len(),
            "{name}: the poses with sensitivities"
        );
        // At analyses of every tenth pose: the positions' sensitivities
        // alone are the whole ones', the twins' the same to the bit.
        let accuracy = options.options;
        let mut analysed = 0;
        for pose in compiled.poses.iter().step_by(10) {
            let (vdot, vddot) = (SVector::repeat(1.0), SVector::repeat(0.5));
            let a = model.analyze(&pose.u, &pose.v, &vdot, &vddot, &accuracy);
            let b = sensitive.analyze(&pose.u, &pose.v, &vdot, &vddot, &accuracy);
            let (a, b) = match (a, b) {
                (Ok(a), Ok(b)) => (a, b),
                (Err(a), Err(b)) => {
                    assert_eq!(
                        format!("{a:?}"),
                        format!("{b:?}"),
                        "{name}: the twins' analyses"
                    );
                    continue;
                }
                (a, b) => panic!(
                    "{name}: one twin's analysis failed: {:?} {:?}",
                    a.err(),
                    b.err()
                ),
            };
            analysed += 1;
            let positions = model.position_sensitivities_of(&a, &accuracy);
            twins::same_positions(&model.sensitivities_of(&a, &accuracy), &positions);
            let read = sensitive.position_sensitivities_of(&b, &accuracy);
            twins::same_positions(&sensitive.sensitivities_of(&b, &accuracy), &read);
            match (&positions, &read) {
                (Ok(p), Ok(q)) => {
                    twins::same("positions.u", &p.u, &q.u);
                    for (x, y) in p.points.iter().zip(&q.points) {
                        twins::same_points("positions.points", x.as_ref(), y.as_ref());
                    }
                }
                (p, q) => assert_eq!(
                    format!("{:?}", p.as_ref().err()),
                    format!("{:?}", q.as_ref().err())
                ),
            }
        }
        assert!(analysed > 0, "{name}: no pose of the sweep analysed");
    }
    runs(name, file, &run_time);
}

/// Every check of one file against its twin.
pub(crate) fn twin<L, const M: usize, const F: usize, const K: usize>(name: &str, model: &L)
where
    L: Linkage<M, F> + Sensitivities<M, F, K>,
{
    let (_, file) = load(name);
    same_parameters(name, &file, model);
    runs(name, &file, model);
    same_at_run_time(name, &file, model);
}

#[test]
fn the_four_bar_is_the_worksheets() {
    twin("four_bar.toml", &FourBar::WORKSHEET);
    let (_, file) = load("four_bar.toml");
    let theta2 = file.driver("theta2").unwrap();
    assert_eq!(theta2.at.value.to_bits(), 20f64.to_radians().to_bits());
    assert_eq!(theta2.rate.value.to_bits(), (400.0 * TAU / 60.0).to_bits());
}

#[test]
fn the_slider_cranks_are_the_tests() {
    twin("slider_crank.toml", &SLIDER_CRANK);
    twin("slider_driven.toml", &SLIDER_DRIVEN);
}

#[test]
fn the_five_bar_and_the_boom_are_the_tests() {
    twin("five_bar.toml", &FIVE_BAR);
    twin("boom.toml", &BOOM);
}

#[test]
fn the_six_bars_are_the_tests() {
    twin("six_bar.toml", &SIX_BAR);
    twin("watt_six_bar.toml", &WATT_SIX_BAR);
    twin("stephenson_three.toml", &STEPHENSON_THREE);
}

#[test]
fn the_coupler_body_is_the_assembly_tests() {
    let coupler = Coupler {
        xa: 0.0,
        ya: 0.0,
        xd: 80.0,
        yd: 0.0,
        l2: 20.0,
        l4: 70.0,
        bx: -25.0,
        by: -10.0,
        cx: 25.0,
        cy: -10.0,
    };
    twin("coupler.toml", &coupler);
}

#[test]
fn the_shaper_is_the_course_projects() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    twin("shaper.toml", &shaper);
    let (_, file) = load("shaper.toml");
    let phi = file.driver("phi").unwrap();
    assert_eq!(phi.at.value.to_bits(), shaper.analysed_position().to_bits());
    assert_eq!(
        phi.rate.value.to_bits(),
        (TAU * COURSE_PROJECT.n1).to_bits()
    );
}

#[test]
fn the_new_mechanisms_are_their_twins() {
    twin("jansen_leg.toml", &JANSEN_LEG);
    twin("quick_return.toml", &QUICK_RETURN);
    twin("trammel.toml", &TRAMMEL);
}

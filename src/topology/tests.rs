use super::*;
use crate::assembly::Assemble;
use crate::file::MechanismFile;
use crate::mechanism::Fixed;
use crate::prelude::*;
use std::f64::consts::PI;

/// The pose of a mechanism file at its drivers' `at`, from its assembly,
/// with velocities at the drivers' rates.
fn pose<const M: usize, const F: usize>(
    file: &MechanismFile,
) -> (
    Fixed<M, F>,
    Analysis<M, F, <Fixed<M, F> as Kernels<M, F>>::Points>,
) {
    let model = file.mechanism().unwrap().fixed::<M, F>().unwrap();
    let names = model.v_names();
    let of = |f: &dyn Fn(&crate::file::Driver) -> f64| {
        SVector::<f64, F>::from_fn(|k, _| f(file.driver(names[k]).unwrap()))
    };
    let (at, rate) = (of(&|d| d.at.value), of(&|d| d.rate.value));
    let pick = file
        .assembly
        .as_ref()
        .unwrap()
        .pick::<M>(&model.u_names())
        .unwrap();
    let u = model.assemble(&at, &pick).unwrap().u;
    let analysis = model
        .analyze(&u, &at, &rate, &SVector::zeros(), &Options::default())
        .unwrap();
    (model, analysis)
}

fn point<const M: usize, const F: usize>(
    model: &Fixed<M, F>,
    analysis: &Analysis<M, F, <Fixed<M, F> as Kernels<M, F>>::Points>,
    name: &str,
) -> [Vector2<f64>; 2] {
    let k = model.point_names().iter().position(|n| *n == name).unwrap();
    [
        analysis.points.as_ref()[k],
        analysis.point_velocities.as_ref()[k],
    ]
}

fn close(a: Vector2<f64>, b: Vector2<f64>, scale: f64) {
    assert!((a - b).amax() <= 1e-12 * scale, "{a:?} ≠ {b:?}");
}

/// The worksheet's four-bar, sketched near its pose at θ2 = 20° with its
/// lengths given.
fn worksheet_four_bar() -> Topology {
    Topology::new("FourBar")
        .length_unit("mm")
        .revolute("A", [0.0, 0.0])
        .revolute("B", [18.8, 6.8])
        .revolute("C", [35.0, 54.0])
        .revolute("D", [80.0, 0.0])
        .link("ground", &["A", "D"])
        .link("crank", &["A", "B"])
        .link("coupler", &["B", "C"])
        .link("rocker", &["D", "C"])
        .length("A", "B", 20.0)
        .length("B", "C", 50.0)
        .length("D", "C", 70.0)
        .drive_angle("A", "B")
}

#[test]
fn the_worksheets_four_bar_from_its_topology_is_its_equation_files() {
    let mut topology = worksheet_four_bar();
    topology.drivers[0].at = Some(20f64.to_radians());
    let (model, analysis) = pose::<2, 1>(&topology.mechanism_file().unwrap());
    let equations = MechanismFile::parse(include_str!("../../mechanisms/four_bar.toml")).unwrap();
    let (twin, twin_analysis) = pose::<2, 1>(&equations);
    for name in ["B", "C"] {
        let [p, pv] = point(&model, &analysis, name);
        let [q, qv] = point(&twin, &twin_analysis, name);
        close(p, q, 80.0);
        // The file's rate is 400 rpm; the topology's 1 rad/s.
        close(pv * (400.0 * 2.0 * PI / 60.0), qv, 80.0 * 41.9);
    }
}

#[test]
fn an_offset_slider_crank_is_its_closed_form() {
    let (r, l, e): (f64, f64, f64) = (50.0, 200.0, 10.0);
    let topology = Topology::new("SliderCrank")
        .length_unit("mm")
        .revolute("A", [0.0, 0.0])
        .revolute("B", [r, 0.0])
        .revolute("C", [r + (l * l - e * e).sqrt(), e])
        .prismatic("S", [r + (l * l - e * e).sqrt(), e], 0.0)
        .link("ground", &["A", "S"])
        .link("crank", &["A", "B"])
        .link("rod", &["B", "C"])
        .link("block", &["S", "C"])
        .drive_angle("A", "B");
    let text = topology.mechanism_text().unwrap();
    let file = MechanismFile::parse(&text).unwrap();
    let model = file.mechanism().unwrap().fixed::<2, 1>().unwrap();
    let pick = file
        .assembly
        .as_ref()
        .unwrap()
        .pick::<2>(&model.u_names())
        .unwrap();
    let start = model.assemble(&vector![0.0], &pick).unwrap().u;
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![2.0 * PI],
        steps: 72,
    };
    let sweep = model
        .sweep(&start, &drive, &SweepOptions::default())
        .unwrap();
    assert!(sweep.complete);
    let c = model.point_names().iter().position(|n| *n == "C").unwrap();
    for pose in &sweep.poses {
        let theta = pose.v[0];
        let x = r * theta.cos() + (l * l - (r * theta.sin() - e).powi(2)).sqrt();
        let p = model.point_positions(&pose.u, &pose.v).as_ref()[c];
        close(p, vector![x, e], 250.0);
    }
}

/// A crank-and-slotted-lever quick return: the crank's pin runs in the
/// lever's slot; the ram slides on the frame.
#[test]
fn the_quick_return_from_its_topology_is_its_equation_files() {
    let equations =
        MechanismFile::parse(include_str!("../../mechanisms/quick_return.toml")).unwrap();
    let (twin, twin_analysis) = pose::<4, 1>(&equations);
    let at = |name: &str| {
        let [p, _] = point(&twin, &twin_analysis, name);
        [p.x, p.y]
    };
    let a = at("A");
    let slot = (a[1] + 240.0).atan2(a[0]);
    let mut topology = Topology::new("QuickReturn")
        .length_unit("mm")
        .revolute("O", [0.0, 0.0])
        .revolute("C", [0.0, -240.0])
        .pin_in_slot("A", a, slot)
        .revolute("P", at("P"))
        .revolute("R", at("R"))
        .prismatic("Ram", at("R"), 0.0)
        .link("ground", &["O", "C", "Ram"])
        .link("lever", &["C", "A", "P"])
        .link("crank", &["O", "A"])
        .link("rod", &["P", "R"])
        .link("ram", &["Ram", "R"])
        .drive_angle("O", "A");
    topology.drivers[0].rate = Some(2.0 * PI);
    let (model, analysis) = pose::<4, 1>(&topology.mechanism_file().unwrap());
    for name in ["A", "P", "R"] {
        let [p, pv] = point(&model, &analysis, name);
        let [q, qv] = point(&twin, &twin_analysis, name);
        close(p, q, 450.0);
        close(pv, qv, 450.0 * 2.0 * PI);
    }
}

fn errors(topology: &Topology) -> Vec<TopologyError> {
    topology.check().unwrap_err().errors
}

#[test]
fn each_bad_topology_gives_its_one_error() {
    let good = worksheet_four_bar();
    assert_eq!(good.check(), Ok(()));
    // A joint on no link.
    let t = good.clone().revolute("E", [1.0, 1.0]);
    assert_eq!(
        errors(&t),
        [TopologyError::JointOnNoLink { joint: "E".into() }]
    );
    // A link listing a joint that is not there.
    let t = good.clone().link("spare", &["C", "Q"]);
    assert_eq!(
        errors(&t),
        [TopologyError::UnknownJoint {
            link: "spare".into(),
            joint: "Q".into()
        }]
    );
    // Disconnected: a bar on its own.
    let t = good
        .clone()
        .revolute("E", [1.0, 1.0])
        .revolute("F", [2.0, 1.0])
        .revolute("G", [3.0, 2.0])
        .link("e", &["E", "F"])
        .link("f", &["F", "G"]);
    assert_eq!(
        errors(&t),
        [TopologyError::Disconnected {
            links: vec!["e".into(), "f".into()]
        }]
    );
    // No driver: one degree of freedom too many.
    let mut t = good.clone();
    t.drivers.clear();
    assert!(matches!(
        errors(&t)[..],
        [TopologyError::Mobility {
            mobility: 1,
            drivers: 0,
            ..
        }]
    ));
    // Two drivers of a one-degree-of-freedom mechanism.
    let t = good.clone().drive_angle("D", "C");
    assert!(matches!(
        errors(&t)[..],
        [TopologyError::Mobility {
            mobility: 1,
            drivers: 2,
            ..
        }]
    ));
    // Coincident pins.
    let mut t = good.clone();
    t.joints[2].at = t.joints[1].at;
    assert_eq!(
        errors(&t),
        [TopologyError::CoincidentPins {
            link: "coupler".into(),
            joints: ["B".into(), "C".into()]
        }]
    );
    // Two links pinned twice.
    let t = good.clone().link("coupler2", &["B", "C"]);
    assert!(errors(&t).contains(&TopologyError::RigidPair {
        links: ["coupler".into(), "coupler2".into()],
        joints: ["B".into(), "C".into()]
    }));
    // A driver too many once a brace makes the four-bar a truss.
    let t = good.clone().link("brace", &["A", "C"]);
    assert!(matches!(
        errors(&t)[..],
        [TopologyError::Mobility {
            mobility: 0,
            drivers: 1,
            ..
        }]
    ));
    // Braced twice: over-constrained, the links that cannot move named.
    let t = good
        .clone()
        .link("brace", &["A", "C"])
        .link("brace2", &["B", "D"]);
    let found = errors(&t);
    let [TopologyError::RigidLoop { links }] = &found[..] else {
        panic!("{found:?}");
    };
    // Braced once, the driven four-bar is already a truss: the smallest
    // such part, with one of the braces.
    assert!(links.len() < 6, "{links:?}");
    assert!(links.iter().any(|l| l.starts_with("brace")), "{links:?}");
    // A slider on three links.
    let t = good
        .clone()
        .prismatic("S", [10.0, 10.0], 0.0)
        .link("x", &["S"])
        .link("y", &["S"])
        .link("z", &["S"]);
    assert!(errors(&t).contains(&TopologyError::SliderLinks {
        joint: "S".into(),
        links: 3
    }));
    // A position that is not a number.
    let mut t = good.clone();
    t.joints[1].at[0] = f64::NAN;
    assert!(matches!(&errors(&t)[..], [TopologyError::NotFinite { .. }]));
    // A name the equations cannot use, a unit that is not a length.
    let t = good.clone().length_unit("s");
    assert_eq!(errors(&t), [TopologyError::BadUnit { unit: "s".into() }]);
    let mut t = good.clone();
    t.links[1].name = "fn".into();
    assert!(matches!(&errors(&t)[..], [TopologyError::BadName { .. }]));
    // No driver and no freedom: a structure.
    let t = Topology::new("Truss")
        .revolute("A", [0.0, 0.0])
        .revolute("B", [1.0, 0.0])
        .revolute("C", [0.5, 1.0])
        .link("ground", &["A", "B"])
        .link("left", &["A", "C"])
        .link("right", &["B", "C"]);
    assert_eq!(errors(&t), [TopologyError::NoDriver]);
    // A drive of zero length, or of no steps.
    let mut t = good.clone();
    t.drivers[0].range = Some([1.0, 1.0]);
    assert!(matches!(&errors(&t)[..], [TopologyError::BadDrive { .. }]));
    let mut t = good.clone();
    t.drivers[0].steps = Some(0);
    assert!(matches!(&errors(&t)[..], [TopologyError::BadDrive { .. }]));
    // The angle of a block that slides on the frame without turning.
    let block = Topology::new("Block")
        .prismatic("S", [0.0, 0.0], 0.0)
        .revolute("P", [1.0, 0.0])
        .link("ground", &["S"])
        .link("block", &["S", "P"])
        .drive_angle("S", "P");
    assert!(
        matches!(&errors(&block)[..], [TopologyError::DrivenLinkLocked { link, .. }, ..] if link == "block"),
        "{:?}",
        errors(&block)
    );
    // A lone crank: nothing left to solve for.
    let crank = Topology::new("Crank")
        .revolute("A", [0.0, 0.0])
        .revolute("B", [1.0, 0.0])
        .link("ground", &["A"])
        .link("crank", &["A", "B"])
        .drive_angle("A", "B");
    assert_eq!(
        crank.mechanism_text().unwrap_err().errors,
        [TopologyError::NothingDepends]
    );
    // A joint named as a generated parameter is.
    let t = good
        .clone()
        .revolute("l_A_B", [5.0, 5.0])
        .link("tag", &["B", "l_A_B"]);
    let t = {
        let mut t = t;
        t.links.pop();
        t.links[2].joints.push("l_A_B".into());
        t
    };
    assert_eq!(
        t.mechanism_text().unwrap_err().errors,
        [TopologyError::NameClash {
            name: "l_A_B".into()
        }]
    );
    // A point traced that is no joint.
    let t = good.clone().trace("Q");
    assert_eq!(
        errors(&t),
        [TopologyError::UnknownTrace { name: "Q".into() }]
    );
    // A link whose joints are all drawn at one place (a pin and a slot).
    let t = Topology::new("Bad")
        .revolute("A", [0.0, 0.0])
        .revolute("B", [1.0, 0.0])
        .pin_in_slot("S", [1.0, 0.0], 0.0)
        .link("ground", &["A", "S"])
        .link("crank", &["A", "B"])
        .link("rod", &["B", "S"])
        .guide("S", "ground")
        .drive_angle("A", "B");
    assert_eq!(
        errors(&t),
        [TopologyError::CoincidentPins {
            link: "rod".into(),
            joints: ["B".into(), "S".into()]
        }]
    );
    // A driver of joints no moving link carries together.
    let t = {
        let mut t = good.clone();
        t.drivers.clear();
        t.drive_angle("A", "C")
    };
    assert_eq!(
        errors(&t),
        [TopologyError::DriverNotOnOneLink {
            from: "A".into(),
            to: "C".into()
        }]
    );
}

/// Each topology file of `mechanisms/joints/` against its equation file:
/// the named points and their velocities at the drive's `at`.
#[test]
fn the_topology_files_are_their_equation_files() {
    use crate::file::TopologyFile;
    fn compare<const M: usize, const N: usize>(
        topology: &str,
        equations: &str,
        points: &[&str],
        scale: f64,
    ) {
        let (generated, _) = TopologyFile::parse(topology)
            .unwrap()
            .mechanism_file()
            .unwrap();
        let (model, analysis) = pose::<M, 1>(&generated);
        let (twin, twin_analysis) = pose::<N, 1>(&MechanismFile::parse(equations).unwrap());
        for name in points {
            let [p, pv] = point(&model, &analysis, name);
            let [q, qv] = point(&twin, &twin_analysis, name);
            close(p, q, scale);
            close(pv, qv, scale * 50.0);
        }
    }
    compare::<2, 2>(
        include_str!("../../mechanisms/joints/four_bar.toml"),
        include_str!("../../mechanisms/four_bar.toml"),
        &["B", "C"],
        80.0,
    );
    compare::<4, 3>(
        include_str!("../../mechanisms/joints/shaper.toml"),
        include_str!("../../mechanisms/shaper.toml"),
        &["A", "D", "S3", "S5", "K"],
        0.7,
    );
    compare::<4, 4>(
        include_str!("../../mechanisms/joints/quick_return.toml"),
        include_str!("../../mechanisms/quick_return.toml"),
        &["A", "P", "R"],
        450.0,
    );
}

/// A drawing closes every loop to rounding where it gives every length;
/// a length given that opens a loop is found at the joint that closes it.
#[test]
fn sketch_gaps_name_the_loop_that_given_lengths_open() {
    let drawn = worksheet_four_bar();
    let mut exact = drawn.clone();
    exact.lengths.clear();
    let gaps = exact.sketch_gaps().unwrap();
    assert_eq!(gaps.len(), 1);
    assert!(gaps[0].1 < 1e-12, "{gaps:?}");
    // The sketch is near the given lengths: a small gap.
    let near = drawn.sketch_gaps().unwrap();
    assert!(near[0].1 > 1e-3 && near[0].1 < 1.0, "{near:?}");
    // A rocker of 10 mm cannot reach: the loop at C misses by what the
    // drawing says, C reached from D along the drawn D→C and from B along
    // the drawn B→C.
    let mut open = drawn.clone();
    open.lengths[2].2 = 10.0;
    let gaps = open.sketch_gaps().unwrap();
    assert_eq!(gaps[0].0, "C");
    let at = |n: &str| open.joints.iter().find(|j| j.name == n).unwrap().at;
    let along = |from: [f64; 2], to: [f64; 2], length: f64| {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let norm = dx.hypot(dy);
        [from[0] + length * dx / norm, from[1] + length * dy / norm]
    };
    // B where the given crank puts it along the drawn A→B.
    let b = along(at("A"), at("B"), 20.0);
    let (c, d) = (at("C"), at("D"));
    let (by_rocker, by_coupler) = (
        along(d, c, 10.0),
        along(
            b,
            [b[0] + c[0] - at("B")[0], b[1] + c[1] - at("B")[1]],
            50.0,
        ),
    );
    let expected = (by_rocker[0] - by_coupler[0])
        .abs()
        .max((by_rocker[1] - by_coupler[1]).abs());
    assert!(
        (gaps[0].1 - expected).abs() < 1e-12,
        "{gaps:?} against {expected}"
    );
}

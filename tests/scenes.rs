//! Pictures: well-formed SVG (parsed by a real XML parser), drawn where the
//! kinematics say — the worksheet's points and arrow tips read back from
//! the drawing — and every bad input a typed error.

mod common;

use common::{FourBar, OMEGA2, SLIDER_CRANK, SliderCrank};
use linkage::closed_form;
use linkage::draw::diagrams::{DiagramError, Diagrams};
use linkage::draw::scene::{Frame, Scene, SceneError};
use linkage::error::{NameKind, UnknownName};
use linkage::prelude::*;
use std::f64::consts::TAU;

/// The worksheet's pose: θ2 = 20°, ω2 = 400 rpm, α2 = 0.
fn worksheet_pose() -> Analysis<2, 1, [Vector2<f64>; 5]> {
    FourBar::WORKSHEET
        .analyze(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &vector![20f64.to_radians()],
            &vector![OMEGA2],
            &vector![0.0],
            &Options::default(),
        )
        .unwrap()
}

fn worksheet_scene() -> Scene {
    Scene::new()
        .ground("A", [0.0, 0.0])
        .ground("D", [FourBar::WORKSHEET.l1, 0.0])
        .link(["A", "B"])
        .link(["B", "C"])
        .link(["C", "D"])
        .velocities(["G2", "G3", "G4"])
        .accelerations(["G2", "G3", "G4"])
        .velocity_scale(0.02)
        .acceleration_scale(0.0005)
        .trace(["G3"])
        .title("The four-bar at θ₂ = 20°")
}

/// A revolution of the worksheet's four-bar from the worksheet's pose.
fn revolution(steps: usize) -> (Sweep<2, 1>, Vec<Frame>) {
    let pose = worksheet_pose();
    let sweep = FourBar::WORKSHEET
        .sweep(
            &pose.u,
            &Drive::Line {
                from: vector![20f64.to_radians()],
                to: vector![20f64.to_radians() + TAU],
                steps,
            },
            &SweepOptions {
                speed: OMEGA2,
                ..SweepOptions::default()
            },
        )
        .unwrap();
    let frames = sweep
        .poses
        .iter()
        .map(|p| Frame::from_sweep_pose(&FourBar::WORKSHEET, p))
        .collect();
    (sweep, frames)
}

fn parse(svg: &str) -> roxmltree::Document<'_> {
    roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not well-formed XML: {e}"))
}

fn by_id<'a>(doc: &'a roxmltree::Document<'a>, id: &str) -> roxmltree::Node<'a, 'a> {
    doc.descendants()
        .find(|n| n.attribute("id") == Some(id))
        .unwrap_or_else(|| panic!("no element #{id}"))
}

fn number(node: roxmltree::Node, attribute: &str) -> f64 {
    node.attribute(attribute)
        .unwrap_or_else(|| panic!("no {attribute}"))
        .parse()
        .unwrap()
}

/// "x1,y1 x2,y2 …" → the points.
fn points(text: &str) -> Vec<Vector2<f64>> {
    text.split_whitespace()
        .map(|pair| {
            let (x, y) = pair.split_once(',').unwrap();
            Vector2::new(x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The drawing's map back to model coordinates, recovered from the two
/// ground pivots A (0, 0) and D (l1, 0) alone: the scale, and y up.
struct Readback {
    a: Vector2<f64>,
    scale: f64,
}

impl Readback {
    fn new(doc: &roxmltree::Document) -> Readback {
        let circle = |id| {
            let n = by_id(doc, id);
            Vector2::new(number(n, "cx"), number(n, "cy"))
        };
        let (a, d) = (circle("point-A"), circle("point-D"));
        assert!((a.y - d.y).abs() < 1e-9, "the ground line is level");
        Readback {
            a,
            scale: (d.x - a.x) / FourBar::WORKSHEET.l1,
        }
    }

    fn model(&self, p: Vector2<f64>) -> Vector2<f64> {
        Vector2::new((p.x - self.a.x) / self.scale, (self.a.y - p.y) / self.scale)
    }

    /// What a coordinate written to 0.01 px can be off by, in model units
    /// (the point's rounding and A's and D's).
    fn tolerance(&self) -> f64 {
        0.02 / self.scale
    }
}

#[test]
fn the_worksheet_scene_is_drawn_where_the_kinematics_say() {
    let pose = worksheet_pose();
    let (_, cycle) = revolution(72);
    let svg = worksheet_scene()
        .render(&Frame::from_analysis(&FourBar::WORKSHEET, &pose), &cycle)
        .unwrap();
    let doc = parse(&svg);
    let back = Readback::new(&doc);
    let tol = back.tolerance();
    assert!(tol < 0.01, "a usable scale: {} px/mm", back.scale);
    let index = |name| FourBar::point_index(name).unwrap();
    for name in ["B", "C", "G2", "G3", "G4"] {
        let n = by_id(&doc, &format!("point-{name}"));
        let drawn = back.model(Vector2::new(number(n, "cx"), number(n, "cy")));
        let exact = pose.points[index(name)];
        assert!(
            (drawn - exact).amax() <= tol,
            "{name}: drawn at {drawn:?}, computed {exact:?}"
        );
    }
    // The worksheet's numbers, to its printed digits: B, C.
    let b = back.model({
        let n = by_id(&doc, "point-B");
        Vector2::new(number(n, "cx"), number(n, "cy"))
    });
    assert!((b - Vector2::new(18.79385242, 6.840402866)).amax() <= tol);
    for (kind, scale, vectors) in [
        ("velocity", 0.02, &pose.point_velocities),
        ("acceleration", 0.0005, &pose.point_accelerations),
    ] {
        for name in ["G2", "G3", "G4"] {
            let group = by_id(&doc, &format!("{kind}-{name}"));
            let line = group.children().find(|n| n.has_tag_name("line")).unwrap();
            let head = group
                .children()
                .find(|n| n.has_tag_name("polygon"))
                .unwrap();
            let base = back.model(Vector2::new(number(line, "x1"), number(line, "y1")));
            // The head's apex is the arrow's tip.
            let tip = back.model(points(head.attribute("points").unwrap())[0]);
            let k = index(name);
            let expected_tip = pose.points[k] + vectors[k] * scale;
            assert!((base - pose.points[k]).amax() <= tol, "{kind} {name} base");
            assert!(
                (tip - expected_tip).amax() <= tol,
                "{kind} {name}: tip drawn at {tip:?}, expected {expected_tip:?}"
            );
            // The shaft runs from the base towards the tip.
            let neck = back.model(Vector2::new(number(line, "x2"), number(line, "y2")));
            assert!((neck - base).dot(&(expected_tip - base)) > 0.0);
        }
    }
    // The legend states the scales.
    assert!(svg.contains("scale 0.02: 1 mm drawn = 50 mm/s"));
    assert!(svg.contains("scale 0.0005: 1 mm drawn = 2000 mm/s²"));
    // The trace goes through G3 at every frame.
    let trace = by_id(&doc, "trace-G3").attribute("d").unwrap();
    assert_eq!(trace.matches('L').count() + 1, cycle.len());
}

#[test]
fn automatic_arrow_scales_fit_the_drawing() {
    let pose = worksheet_pose();
    let frame = Frame::from_analysis(&FourBar::WORKSHEET, &pose);
    let svg = Scene::new()
        .ground("A", [0.0, 0.0])
        .ground("D", [FourBar::WORKSHEET.l1, 0.0])
        .link(["A", "B"])
        .link(["B", "C"])
        .link(["C", "D"])
        .velocities(["B", "C"])
        .accelerations(["B", "C"])
        .render(&frame, &[])
        .unwrap();
    let doc = parse(&svg);
    let back = Readback::new(&doc);
    // The mechanism spans 80 mm (A to D) by C's height.
    let extent = 80f64.max(pose.points[1].y);
    for kind in ["velocity", "acceleration"] {
        let longest = ["B", "C"]
            .iter()
            .map(|name| {
                let group = by_id(&doc, &format!("{kind}-{name}"));
                let line = group.children().find(|n| n.has_tag_name("line")).unwrap();
                let head = group
                    .children()
                    .find(|n| n.has_tag_name("polygon"))
                    .unwrap();
                let base = back.model(Vector2::new(number(line, "x1"), number(line, "y1")));
                let tip = back.model(points(head.attribute("points").unwrap())[0]);
                (tip - base).norm()
            })
            .fold(0.0, f64::max);
        // 0.3 of the extent, rounded down to 1, 2 or 5 × 10ᵏ: not below
        // 0.4 of that.
        assert!(
            longest <= 0.3 * extent && longest >= 0.4 * 0.3 * extent,
            "{kind}: longest arrow {longest} for an extent of {extent}"
        );
    }
}

#[test]
fn the_animation_moves_every_part_through_every_frame() {
    let (_, cycle) = revolution(36);
    let svg = worksheet_scene().animate(&cycle, 3.0).unwrap();
    let doc = parse(&svg);
    let animations: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("animate"))
        .collect();
    assert!(!animations.is_empty());
    for a in &animations {
        assert_eq!(a.attribute("dur"), Some("3s"));
        assert_eq!(a.attribute("repeatCount"), Some("indefinite"));
        let values = a.attribute("values").unwrap().split(';').count();
        assert_eq!(values, cycle.len(), "one value per frame");
    }
    // B's circle follows B: read back every frame.
    let back = Readback::new(&doc);
    let b = by_id(&doc, "point-B");
    let track = |attribute: &str| -> Vec<f64> {
        b.children()
            .find(|n| n.attribute("attributeName") == Some(attribute))
            .unwrap()
            .attribute("values")
            .unwrap()
            .split(';')
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let (xs, ys) = (track("cx"), track("cy"));
    let k = FourBar::point_index("B").unwrap();
    for (i, frame) in cycle.iter().enumerate() {
        let drawn = back.model(Vector2::new(xs[i], ys[i]));
        assert!((drawn - frame.positions[k]).amax() <= back.tolerance());
    }
}

#[test]
fn a_slider_crank_scene_has_its_block_and_guide() {
    let crank = SliderCrank {
        r: 50.0,
        l: 200.0,
        e: 10.0,
    };
    let sweep = crank
        .sweep(
            &vector![-0.05, 250.0],
            &Drive::Line {
                from: vector![0.0],
                to: vector![TAU],
                steps: 60,
            },
            &SweepOptions {
                speed: 10.0,
                ..SweepOptions::default()
            },
        )
        .unwrap();
    let cycle: Vec<Frame> = sweep
        .poses
        .iter()
        .map(|p| Frame::from_sweep_pose(&crank, p))
        .collect();
    let scene = Scene::new()
        .ground("O", [0.0, 0.0])
        .link(["O", "B"])
        .link(["B", "P"])
        .slider("P", 0.0)
        .velocities(["P"])
        .accelerations(["B"])
        .trace(["G3"]);
    let svg = scene.render(&cycle[5], &cycle).unwrap();
    if let Ok(path) = std::env::var("LINKAGE_DUMP_SLIDER") {
        std::fs::write(path, &svg).unwrap();
    }
    let doc = parse(&svg);
    let block = by_id(&doc, "slider-P");
    let transform = block.attribute("transform").unwrap();
    let p = by_id(&doc, "point-P");
    assert_eq!(
        transform,
        format!(
            "translate({} {})",
            p.attribute("cx").unwrap(),
            p.attribute("cy").unwrap()
        )
    );
    let guide = by_id(&doc, "guide-P").attribute("d").unwrap();
    assert!(guide.starts_with('M'));
    // Animated, the block moves along the guide.
    let animated = scene.animate(&cycle, 2.0).unwrap();
    let doc = parse(&animated);
    let moves = by_id(&doc, "slider-P")
        .children()
        .find(|n| n.has_tag_name("animateTransform"))
        .unwrap();
    assert_eq!(moves.attribute("type"), Some("translate"));
    let ys: Vec<f64> = moves
        .attribute("values")
        .unwrap()
        .split(';')
        .map(|v| v.split(' ').nth(1).unwrap().parse().unwrap())
        .collect();
    assert!(
        ys.iter().all(|y| (y - ys[0]).abs() < 0.011),
        "the block stays on its level guide"
    );
    let _ = SLIDER_CRANK;
}

#[test]
fn bad_scenes_are_typed_errors() {
    let pose = worksheet_pose();
    let frame = Frame::from_analysis(&FourBar::WORKSHEET, &pose);
    let err = Scene::new()
        .link(["A", "Q"])
        .render(&frame, &[])
        .unwrap_err();
    assert!(
        matches!(&err, SceneError::UnknownName(UnknownName { kind: NameKind::Point, name, known, .. }) if name == "A" && known.contains("G3")),
        "{err}"
    );
    let positions_only =
        Frame::positions(&FourBar::WORKSHEET, &pose.u, &vector![20f64.to_radians()]);
    assert_eq!(
        Scene::new()
            .velocities(["B"])
            .render(&positions_only, &[])
            .unwrap_err(),
        SceneError::MissingKinematics { what: "velocities" }
    );
    assert!(matches!(
        Scene::new()
            .velocity_scale(-1.0)
            .velocities(["B"])
            .render(&frame, &[]),
        Err(SceneError::BadSetting { .. })
    ));
    assert_eq!(
        worksheet_scene()
            .animate(std::slice::from_ref(&frame), 1.0)
            .unwrap_err(),
        SceneError::TooFewFrames { frames: 1 }
    );
    let mut broken = frame.clone();
    broken.positions[0].x = f64::NAN;
    assert!(matches!(
        Scene::new()
            .link(["A", "B"])
            .ground("A", [0.0, 0.0])
            .render(&broken, &[]),
        Err(SceneError::NonFinite { .. })
    ));
    // Text is escaped.
    let svg = Scene::new()
        .ground("A", [0.0, 0.0])
        .link(["A", "B"])
        .title("<&\">")
        .render(&frame, &[])
        .unwrap();
    parse(&svg);
}

#[test]
fn motion_diagrams_are_well_formed_and_mark_the_limit_positions() {
    let (sweep, _) = revolution(90);
    let svg = Diagrams::new()
        .title("The worksheet's four-bar")
        .render(&FourBar::WORKSHEET, &sweep)
        .unwrap();
    let doc = parse(&svg);
    let text: String = doc
        .descendants()
        .filter(|n| n.is_text())
        .filter_map(|n| n.text())
        .collect();
    for label in [
        "angle [°]",
        "angular velocity [rad/s]",
        "angular acceleration [rad/s²]",
        "θ₂ [°]",
        "θ₃",
        "θ₄",
    ] {
        assert!(text.contains(label), "missing {label}");
    }
    assert!(!text.contains("limit position"));
    // A triple rocker rocks between two limit positions: both marked.
    let bar = FourBar {
        l2: 45.0,
        ..FourBar::WORKSHEET
    };
    let cf = closed_form::FourBar {
        l1: bar.l1,
        l2: bar.l2,
        l3: bar.l3,
        l4: bar.l4,
    };
    let start = cf.position(0.0, 1.0).unwrap();
    let limit = cf.collinear_crank_angles()[0];
    let rocking = bar
        .sweep(
            &vector![start[0], start[1]],
            &Drive::Rocking {
                from: vector![0.0],
                step: vector![limit / 50.3],
                max_steps: 1000,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    assert_eq!(rocking.events.len(), 2);
    let svg = Diagrams::new().render(&bar, &rocking).unwrap();
    let doc = parse(&svg);
    let marks = doc
        .descendants()
        .filter(|n| n.is_text() && n.text().map(str::trim) == Some("limit position"))
        .count();
    assert_eq!(marks, 2, "both limit positions marked");
    // A slider-crank has a length column.
    let crank = SliderCrank {
        r: 50.0,
        l: 200.0,
        e: 10.0,
    };
    let sweep = crank
        .sweep(
            &vector![-0.05, 250.0],
            &Drive::Line {
                from: vector![0.0],
                to: vector![TAU],
                steps: 90,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    let svg = Diagrams::new()
        .units("mm", "s")
        .render(&crank, &sweep)
        .unwrap();
    assert!(svg.contains("position [mm]") && svg.contains("acceleration [mm/s²]"));
    // Too short a sweep.
    let one = Sweep {
        poses: sweep.poses[..1].to_vec(),
        events: Vec::new(),
        complete: true,
    };
    assert_eq!(
        Diagrams::new().render(&crank, &one).unwrap_err(),
        DiagramError::TooFewPoses { poses: 1 }
    );
}

//! Pictures: well-formed SVG (parsed by a real XML parser), drawn where the
//! kinematics say — the worksheet's points and arrow tips read back from
//! the drawing — and every bad input a typed error.

use crate::common::{FourBar, OMEGA2};
use crate::models::{SLIDER_CRANK, SliderCrank};
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

pub(crate) fn parse(svg: &str) -> roxmltree::Document<'_> {
    roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not well-formed XML: {e}"))
}

pub(crate) fn by_id<'a>(doc: &'a roxmltree::Document<'a>, id: &str) -> roxmltree::Node<'a, 'a> {
    doc.descendants()
        .find(|n| n.attribute("id") == Some(id))
        .unwrap_or_else(|| panic!("no element #{id}"))
}

pub(crate) fn number(node: roxmltree::Node, attribute: &str) -> f64 {
    node.attribute(attribute)
        .unwrap_or_else(|| panic!("no {attribute}"))
        .parse()
        .unwrap()
}

/// "x1,y1 x2,y2 …" → the points.
pub(crate) fn points(text: &str) -> Vec<Vector2<f64>> {
    text.split_whitespace()
        .map(|pair| {
            let (x, y) = pair.split_once(',').unwrap();
            Vector2::new(x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// An arrow's base, neck (where the shaft meets the head) and tip, on the
/// screen: its shaft in the group `{kind}-{name}`, its head in
/// `{kind}-{name}-head`, the head's apex first.
fn arrow_ends(
    doc: &roxmltree::Document,
    kind: &str,
    name: &str,
) -> (Vector2<f64>, Vector2<f64>, Vector2<f64>) {
    let shaft = by_id(doc, &format!("{kind}-{name}"))
        .children()
        .find(|n| n.attribute("class") == Some("shaft"))
        .unwrap();
    let head = by_id(doc, &format!("{kind}-{name}-head"))
        .children()
        .find(|n| n.attribute("class") == Some("head"))
        .unwrap();
    (
        Vector2::new(number(shaft, "x1"), number(shaft, "y1")),
        Vector2::new(number(shaft, "x2"), number(shaft, "y2")),
        points(head.attribute("points").unwrap())[0],
    )
}

/// The drawing's map back to model coordinates, recovered from the two
/// ground pivots A (0, 0) and D (l1, 0) alone: the scale, and y up.
pub(crate) struct Readback {
    pub(crate) a: Vector2<f64>,
    pub(crate) scale: f64,
}

impl Readback {
    pub(crate) fn new(doc: &roxmltree::Document) -> Readback {
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

    pub(crate) fn model(&self, p: Vector2<f64>) -> Vector2<f64> {
        Vector2::new((p.x - self.a.x) / self.scale, (self.a.y - p.y) / self.scale)
    }

    /// What a coordinate written to 0.01 px can be off by, in model units
    /// (the point's rounding and A's and D's).
    pub(crate) fn tolerance(&self) -> f64 {
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
    let index = |name| FourBar::WORKSHEET.point_index(name).unwrap();
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
            let (base, neck, tip) = arrow_ends(&doc, kind, name);
            let (base, neck, tip) = (back.model(base), back.model(neck), back.model(tip));
            let k = index(name);
            let expected_tip = pose.points[k] + vectors[k] * scale;
            assert!((base - pose.points[k]).amax() <= tol, "{kind} {name} base");
            assert!(
                (tip - expected_tip).amax() <= tol,
                "{kind} {name}: tip drawn at {tip:?}, expected {expected_tip:?}"
            );
            // The shaft runs from the base towards the tip.
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
                let (base, _, tip) = arrow_ends(&doc, kind, name);
                (back.model(tip) - back.model(base)).norm()
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
    let k = FourBar::B;
    for (i, frame) in cycle.iter().enumerate() {
        let drawn = back.model(Vector2::new(xs[i], ys[i]));
        assert!((drawn - frame.positions[k]).amax() <= back.tolerance());
    }
}

/// A slider-crank (r = 50, l = 200, e = 10) over a revolution in 60 steps
/// at 10 rad/s.
fn slider_crank_cycle() -> Vec<Frame> {
    let crank = SliderCrank {
        r: 50.0,
        l: 200.0,
        e: 10.0,
    };
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 60,
    };
    let options = SweepOptions {
        speed: 10.0,
        ..SweepOptions::default()
    };
    let sweep = crank
        .sweep(&vector![-0.05, 250.0], &drive, &options)
        .unwrap();
    sweep
        .poses
        .iter()
        .map(|p| Frame::from_sweep_pose(&crank, p))
        .collect()
}

#[test]
fn a_slider_crank_scene_has_its_block_and_guide() {
    let cycle = slider_crank_cycle();
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
    assert_eq!(
        err.to_string(),
        "`scene` names the point `A`, which is not defined (the points: B, C, G2, G3, G4)"
    );
    // A ground pivot resolves where no frame point has its name; a name
    // that is neither fails with the same error.
    let grounded = Scene::new().ground("A", [0.0, 0.0]);
    assert!(
        grounded
            .clone()
            .link(["A", "B"])
            .render(&frame, &[])
            .is_ok()
    );
    assert_eq!(
        grounded.link(["A", "Q"]).render(&frame, &[]).unwrap_err(),
        SceneError::UnknownName(UnknownName {
            kind: NameKind::Point,
            owner: "scene".into(),
            name: "Q".into(),
            known: "B, C, G2, G3, G4".into(),
        })
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
    let cf = bar.closed_form();
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

// ---------------------------------------------------------------------
// Fit for a report: labels clear of what is drawn, arrows visible, the
// legend true to the drawing, the animation true to the still.
// ---------------------------------------------------------------------

/// The shaper of the course project at f (crank at 60°), drawn as its
/// example draws it: points in metres, the pose's arrows given as drawn
/// lengths (scales 1), and a cycle that moves the ram along its guide and
/// the crank pin round its circle.
fn shaper() -> (Scene, Frame, Vec<Frame>) {
    let names = ["O", "A", "C", "D", "F", "S5", "K", "S3"];
    // On the screen of the example's picture (px, y down), read back to
    // metres (y up).
    let at = |x: f64, y: f64| Vector2::new(x / 1000.0, -y / 1000.0);
    let positions = vec![
        at(282.48, 406.34),
        at(342.85, 301.77),
        at(282.48, 746.87),
        at(372.12, 86.05),
        at(372.12, 101.66),
        at(527.25, 101.66),
        at(527.25, 191.53),
        at(327.3, 416.46),
    ];
    let zero = Vector2::zeros();
    let velocities = vec![
        zero,
        at(79.96, 46.16),
        zero,
        at(125.68, 17.05),
        at(125.68, 0.0),
        at(125.68, 0.0),
        at(125.68, 0.0),
        at(62.84, 8.52),
    ];
    let accelerations = vec![
        zero,
        zero,
        zero,
        zero,
        at(-119.85, 0.0),
        at(-119.85, 0.0),
        at(-119.85, 0.0),
        at(-59.93, 52.73),
    ];
    let frame = Frame {
        names: names.iter().map(|s| s.to_string()).collect(),
        positions: positions.clone(),
        velocities: Some(velocities),
        accelerations: Some(accelerations),
    };
    let (o, a) = (positions[0], positions[1]);
    let crank = (a - o).norm();
    let cycle = (0..=36)
        .map(|k| {
            let phi = k as f64 * TAU / 36.0;
            let ram = Vector2::new(0.2 * phi.sin() - 0.1, 0.0);
            let mut p = positions.clone();
            p[1] = o + Vector2::new(phi.cos(), phi.sin()) * crank;
            // D, F, S5 and K ride on the ram.
            for q in &mut p[3..7] {
                *q += ram;
            }
            Frame {
                names: frame.names.clone(),
                positions: p,
                velocities: None,
                accelerations: None,
            }
        })
        .collect();
    let scene = Scene::new()
        .ground("O", [o.x, o.y])
        .ground("C", [positions[2].x, positions[2].y])
        .link(["O", "A"])
        .link(["C", "D"])
        .link(["D", "F"])
        .link(["F", "S5"])
        .link(["S5", "K"])
        .slider_on("A", ["C", "D"])
        .block("D", std::f64::consts::FRAC_PI_2)
        .slider("S5", 0.0)
        .velocities(["A", "D", "S3"])
        .accelerations(["S3", "S5"])
        .velocity_scale(1.0)
        .acceleration_scale(1.0)
        .trace(["A", "D"])
        .units("m", "s")
        .title("The shaper at f (crank at 60°)");
    (scene, frame, cycle)
}

/// The slider-crank of `a_slider_crank_scene_has_its_block_and_guide`,
/// its cycle, and a pose where P's velocity and acceleration point the
/// same way along the guide.
fn slider_crank() -> (Scene, Frame, Vec<Frame>) {
    let cycle = slider_crank_cycle();
    let k = SliderCrank::P;
    let same_way = cycle
        .iter()
        .max_by(|f, g| {
            let along = |f: &Frame| {
                let (v, a) = (
                    f.velocities.as_ref().unwrap()[k].x,
                    f.accelerations.as_ref().unwrap()[k].x,
                );
                if v * a > 0.0 {
                    v.abs().min(a.abs() / 30.0)
                } else {
                    0.0
                }
            };
            along(f).total_cmp(&along(g))
        })
        .unwrap()
        .clone();
    let scene = Scene::new()
        .ground("O", [0.0, 0.0])
        .link(["O", "B"])
        .link(["B", "P"])
        .slider("P", 0.0)
        .velocities(["B", "P"])
        .accelerations(["P"])
        .trace(["P", "G3"]);
    (scene, same_way, cycle)
}

/// A box on the screen.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Box2 {
    pub(crate) min: Vector2<f64>,
    pub(crate) max: Vector2<f64>,
}

/// A stroke on the screen: a segment and half its width.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stroke {
    pub(crate) a: Vector2<f64>,
    pub(crate) b: Vector2<f64>,
    pub(crate) half: f64,
}

/// Whether a stroke covers part of a box: its segment comes within half
/// its width of the box.
pub(crate) fn overlaps(s: &Stroke, r: &Box2) -> bool {
    let to_box = |p: Vector2<f64>| (r.min - p).sup(&(p - r.max)).sup(&Vector2::zeros()).norm();
    let to_segment = |p: Vector2<f64>| {
        let ab = s.b - s.a;
        let t = if ab.norm_squared() > 0.0 {
            ((p - s.a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (s.a + ab * t - p).norm()
    };
    // The segment enters the box (clipped to it, Liang–Barsky)?
    let d = s.b - s.a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, s.a.x - r.min.x),
        (d.x, r.max.x - s.a.x),
        (-d.y, s.a.y - r.min.y),
        (d.y, r.max.y - s.a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                t1 = -1.0;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    if t0 <= t1 {
        return true;
    }
    let corners = [
        r.min,
        Vector2::new(r.max.x, r.min.y),
        r.max,
        Vector2::new(r.min.x, r.max.y),
    ];
    let distance = corners
        .into_iter()
        .map(to_segment)
        .chain([to_box(s.a), to_box(s.b)])
        .fold(f64::INFINITY, f64::min);
    distance < s.half
}

/// The width of a label's text: DejaVu Sans oblique's advances, about —
/// capitals 0.75 em, digits 0.64 em, subscript digits 0.42 em, the rest
/// 0.6 em.
fn text_width(text: &str, size: f64) -> f64 {
    text.chars()
        .map(|c| match c {
            'A'..='Z' => 0.75,
            '0'..='9' => 0.64,
            '\u{2080}'..='\u{2089}' => 0.42,
            _ => 0.6,
        })
        .sum::<f64>()
        * size
}

/// Each label's name and box (the points' labels and the markers'):
/// anchored in its middle at (x, y), y the baseline; from the cap height
/// (0.72 em above) to below the subscripts (0.22 em).
pub(crate) fn label_boxes(doc: &roxmltree::Document) -> Vec<(String, Box2)> {
    doc.descendants()
        .filter(|n| {
            n.has_tag_name("text")
                && matches!(n.attribute("class"), Some("label") | Some("marker-label"))
        })
        .map(|n| {
            let text: String = n
                .children()
                .filter(|c| c.is_text())
                .filter_map(|c| c.text())
                .collect::<String>()
                .trim()
                .to_string();
            let size = number(n, "font-size");
            let (x, y) = (number(n, "x"), number(n, "y"));
            assert_eq!(n.attribute("text-anchor"), Some("middle"));
            let half = text_width(&text, size) / 2.0;
            let b = Box2 {
                min: Vector2::new(x - half, y - 0.72 * size),
                max: Vector2::new(x + half, y + 0.22 * size),
            };
            (text, b)
        })
        .collect()
}

/// The straight pieces of an SVG path (commands M, L, H, V, Z and their
/// relative forms, as the scenes write them).
pub(crate) fn path_segments(d: &str) -> Vec<(Vector2<f64>, Vector2<f64>)> {
    let mut tokens = Vec::new();
    let mut word = String::new();
    for c in d.chars() {
        if c.is_ascii_alphabetic() {
            if !word.is_empty() {
                tokens.push(std::mem::take(&mut word));
            }
            tokens.push(c.to_string());
        } else if c == ' ' || c == ',' {
            if !word.is_empty() {
                tokens.push(std::mem::take(&mut word));
            }
        } else {
            word.push(c);
        }
    }
    if !word.is_empty() {
        tokens.push(word);
    }
    let mut out = Vec::new();
    let (mut at, mut start) = (Vector2::zeros(), Vector2::zeros());
    let mut command = 'M';
    let mut i = 0;
    let value = |i: usize| -> f64 { tokens[i].parse().unwrap() };
    while i < tokens.len() {
        if tokens[i].chars().all(|c| c.is_ascii_alphabetic()) {
            command = tokens[i].chars().next().unwrap();
            i += 1;
            if command.eq_ignore_ascii_case(&'z') {
                out.push((at, start));
                at = start;
            }
            continue;
        }
        let next = match command {
            'M' | 'L' => {
                i += 2;
                Vector2::new(value(i - 2), value(i - 1))
            }
            'm' | 'l' => {
                i += 2;
                at + Vector2::new(value(i - 2), value(i - 1))
            }
            'H' => {
                i += 1;
                Vector2::new(value(i - 1), at.y)
            }
            'h' => {
                i += 1;
                at + Vector2::new(value(i - 1), 0.0)
            }
            'V' => {
                i += 1;
                Vector2::new(at.x, value(i - 1))
            }
            'v' => {
                i += 1;
                at + Vector2::new(0.0, value(i - 1))
            }
            other => panic!("path command {other}"),
        };
        if command.eq_ignore_ascii_case(&'m') {
            start = next;
            // Further pairs after a move are lines.
            command = if command == 'M' { 'L' } else { 'l' };
        } else {
            out.push((at, next));
        }
        at = next;
    }
    out
}

fn polygon_edges(points_text: &str) -> Vec<(Vector2<f64>, Vector2<f64>)> {
    let p = points(points_text);
    (0..p.len()).map(|i| (p[i], p[(i + 1) % p.len()])).collect()
}

/// Half an element's stroke width (inherited from its groups).
fn half_width(n: roxmltree::Node) -> f64 {
    n.ancestors()
        .find_map(|a| a.attribute("stroke-width"))
        .map_or(0.5, |w| w.parse::<f64>().unwrap() / 2.0)
}

/// The strokes of the links: bars and the edges of plates.
pub(crate) fn link_strokes(doc: &roxmltree::Document) -> Vec<Stroke> {
    let mut out = Vec::new();
    for n in doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("link"))
    {
        let half = half_width(n);
        if n.has_tag_name("line") {
            out.push(Stroke {
                a: Vector2::new(number(n, "x1"), number(n, "y1")),
                b: Vector2::new(number(n, "x2"), number(n, "y2")),
                half,
            });
        } else if n.has_tag_name("polygon") {
            for (a, b) in polygon_edges(n.attribute("points").unwrap()) {
                out.push(Stroke { a, b, half });
            }
        }
    }
    out
}

/// The strokes of the ground symbols and the hatched guides.
fn hatching_strokes(doc: &roxmltree::Document) -> Vec<Stroke> {
    doc.descendants()
        .filter(|n| {
            n.has_tag_name("path") && matches!(n.attribute("class"), Some("ground") | Some("guide"))
        })
        .flat_map(|n| {
            let half = half_width(n);
            path_segments(n.attribute("d").unwrap())
                .into_iter()
                .map(move |(a, b)| Stroke { a, b, half })
        })
        .collect()
}

/// The visible strokes of the arrows (their outlines left out): shafts
/// and the edges of heads.
fn arrow_strokes(doc: &roxmltree::Document) -> Vec<Stroke> {
    let in_arrow = |n: &roxmltree::Node| {
        n.ancestors().any(|a| {
            a.attribute("class")
                .is_some_and(|c| c.split(' ').any(|w| w.starts_with("arrow")))
        })
    };
    let mut out = Vec::new();
    for n in doc
        .descendants()
        .filter(|n| in_arrow(n) && n.attribute("class") != Some("halo"))
    {
        if n.has_tag_name("line") {
            out.push(Stroke {
                a: Vector2::new(number(n, "x1"), number(n, "y1")),
                b: Vector2::new(number(n, "x2"), number(n, "y2")),
                half: half_width(n),
            });
        } else if n.has_tag_name("polygon") {
            for (a, b) in polygon_edges(n.attribute("points").unwrap()) {
                out.push(Stroke { a, b, half: 1.0 });
            }
        }
    }
    out
}

/// Every label overlapping a link, hatching, an arrow or another label.
pub(crate) fn label_collisions(svg: &str) -> Vec<String> {
    let doc = parse(svg);
    let labels = label_boxes(&doc);
    let mut found = Vec::new();
    for (what, strokes) in [
        ("a link", link_strokes(&doc)),
        ("hatching", hatching_strokes(&doc)),
        ("an arrow", arrow_strokes(&doc)),
    ] {
        assert!(!strokes.is_empty() || what == "an arrow");
        for (name, b) in &labels {
            if strokes.iter().any(|s| overlaps(s, b)) {
                found.push(format!("{name} on {what}"));
            }
        }
    }
    for (i, (name, a)) in labels.iter().enumerate() {
        for (other, b) in &labels[i + 1..] {
            if a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y {
                found.push(format!("{name} on {other}"));
            }
        }
    }
    found
}

#[test]
fn labels_keep_clear_of_links_hatching_arrows_and_one_another() {
    let (shaper, at_f, turn) = shaper();
    let (crank, same_way, revolution_of_crank) = slider_crank();
    let pose = worksheet_pose();
    let (_, cycle) = revolution(72);
    for (what, svg) in [
        ("the shaper", shaper.render(&at_f, &turn).unwrap()),
        (
            "the slider-crank",
            crank.render(&same_way, &revolution_of_crank).unwrap(),
        ),
        (
            "the worksheet's four-bar",
            worksheet_scene()
                .render(&Frame::from_analysis(&FourBar::WORKSHEET, &pose), &cycle)
                .unwrap(),
        ),
    ] {
        let collisions = label_collisions(&svg);
        assert!(collisions.is_empty(), "{what}: {collisions:?}");
    }
}

/// Whether the element `later` comes after `earlier` in the document (is
/// painted over it).
pub(crate) fn painted_after(later: roxmltree::Node, earlier: roxmltree::Node) -> bool {
    later.range().start > earlier.range().start
}

#[test]
fn arrows_are_drawn_above_the_links_and_outlined() {
    let pose = worksheet_pose();
    let svg = worksheet_scene()
        .render(&Frame::from_analysis(&FourBar::WORKSHEET, &pose), &[])
        .unwrap();
    let (shaper, at_f, turn) = shaper();
    for svg in [svg, shaper.render(&at_f, &turn).unwrap()] {
        let doc = parse(&svg);
        let covers: Vec<_> = doc
            .descendants()
            .filter(|n| matches!(n.attribute("class"), Some("link") | Some("slider")))
            .collect();
        let shafts: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("line"))
            .filter(|n| {
                n.parent()
                    .and_then(|g| g.attribute("class"))
                    .is_some_and(|c| c.starts_with("arrow "))
            })
            .filter(|n| n.attribute("class") != Some("halo"))
            .collect();
        assert!(!shafts.is_empty());
        for shaft in shafts {
            let id = shaft.parent().unwrap().attribute("id").unwrap();
            for cover in &covers {
                assert!(
                    painted_after(shaft, *cover),
                    "{id} is drawn under {:?}",
                    cover.attribute("id")
                );
            }
            // Outlined: a white stroke under the shaft, wider than it,
            // along it.
            let width = 2.0 * half_width(shaft);
            let ends = |n: roxmltree::Node| {
                (
                    Vector2::new(number(n, "x1"), number(n, "y1")),
                    Vector2::new(number(n, "x2"), number(n, "y2")),
                )
            };
            let (a, b) = ends(shaft);
            let outlined = shaft.prev_sibling_element().is_some_and(|halo| {
                let (p, q) = ends(halo);
                halo.attribute("stroke") == Some("white")
                    && 2.0 * half_width(halo) >= width + 2.0
                    && (q - b).norm() < 0.02
                    && (p - a).norm() <= 8.0
            });
            assert!(outlined, "{id} has no outline");
        }
    }
}

/// The shafts of two arrows lie on one another: nearly parallel, closer
/// than a shaft's width plus a pixel over a stretch of their length.
fn shafts_on_one_another(a: &Stroke, b: &Stroke) -> bool {
    let (la, lb) = ((a.b - a.a).norm(), (b.b - b.a).norm());
    let u = (a.b - a.a) / la;
    let v = (b.b - b.a) / lb;
    if (u.x * v.y - u.y * v.x).abs() > 0.2 {
        return false;
    }
    let normal = Vector2::new(-u.y, u.x);
    let along = |p: Vector2<f64>| (p - a.a).dot(&u);
    let (s0, s1) = (along(b.a), along(b.b));
    let (lo, hi) = (s0.min(s1).max(0.0), s0.max(s1).min(la));
    if hi - lo < 4.0 {
        return false;
    }
    let off = |s: f64| (b.a + (b.b - b.a) * ((s - s0) / (s1 - s0)) - a.a).dot(&normal);
    let near = a.half + b.half + 1.0;
    off(lo).abs() < near || off(hi).abs() < near
}

#[test]
fn arrows_along_one_line_are_both_visible() {
    let (crank, same_way, cycle) = slider_crank();
    let (shaper, at_f, turn) = shaper();
    // The shaper with the ram's own velocity, along its acceleration.
    let ram = shaper.velocities(["S5"]);
    for (what, svg, expected) in [
        (
            "the slider-crank",
            crank.render(&same_way, &cycle).unwrap(),
            ["velocity-P", "acceleration-P"],
        ),
        (
            "the shaper's ram",
            ram.render(&at_f, &turn).unwrap(),
            ["velocity-S5", "acceleration-S5"],
        ),
    ] {
        let doc = parse(&svg);
        let shaft = |id: &str| {
            let n = by_id(&doc, id)
                .children()
                .find(|n| n.has_tag_name("line") && n.attribute("class") != Some("halo"))
                .unwrap();
            Stroke {
                a: Vector2::new(number(n, "x1"), number(n, "y1")),
                b: Vector2::new(number(n, "x2"), number(n, "y2")),
                half: half_width(n),
            }
        };
        let [v, a] = expected.map(shaft);
        if what == "the slider-crank" {
            // The pose is the one where they point the same way.
            assert!((v.b - v.a).dot(&(a.b - a.a)) > 0.0);
        }
        assert!(
            !shafts_on_one_another(&v, &a),
            "{what}: {v:?} and {a:?} lie on one another"
        );
        // Still drawn from the point: within its joint's circle.
        let point = by_id(&doc, &format!("point-{}", &expected[0][9..]));
        let at = Vector2::new(number(point, "cx"), number(point, "cy"));
        for s in [v, a] {
            assert!((s.a - at).norm() <= 4.5, "{what}: an arrow off its point");
        }
    }
}

#[test]
fn legend_swatches_are_drawn_as_what_they_describe() {
    let (shaper, at_f, turn) = shaper();
    let (crank, same_way, cycle) = slider_crank();
    for svg in [
        shaper.render(&at_f, &turn).unwrap(),
        crank.render(&same_way, &cycle).unwrap(),
    ] {
        let doc = parse(&svg);
        let entries: Vec<_> = doc
            .descendants()
            .filter(|n| n.attribute("class") == Some("legend-entry"))
            .collect();
        // Velocity, acceleration and two traced paths.
        assert_eq!(entries.len(), 4);
        let style = |n: roxmltree::Node| {
            let inherited = |key: &str| {
                n.ancestors()
                    .find_map(|a| a.attribute(key))
                    .map(str::to_string)
            };
            (
                inherited("stroke"),
                inherited("stroke-dasharray"),
                inherited("stroke-width"),
            )
        };
        let mut traces = Vec::new();
        for entry in entries {
            let describes = entry.attribute("data-for").unwrap();
            let swatch = entry
                .children()
                .find(|n| n.attribute("class") == Some("swatch"))
                .unwrap();
            let drawn: Vec<_> = if describes.starts_with("trace-") {
                let trace = by_id(&doc, describes);
                traces.push(style(trace));
                vec![trace]
            } else {
                // Every arrow's visible shaft.
                doc.descendants()
                    .filter(|n| {
                        n.parent().and_then(|g| g.attribute("class"))
                            == Some(&format!("arrow {describes}"))
                            && n.has_tag_name("line")
                            && n.attribute("class") != Some("halo")
                    })
                    .collect()
            };
            assert!(!drawn.is_empty(), "nothing drawn for {describes}");
            for element in drawn {
                assert_eq!(
                    style(swatch),
                    style(element),
                    "the swatch of {describes} is not drawn as it"
                );
            }
        }
        // Two traced paths are told apart by colour or dashes.
        assert_eq!(traces.len(), 2);
        assert_ne!(
            (&traces[0].0, &traces[0].1),
            (&traces[1].0, &traces[1].1),
            "two traced paths drawn alike"
        );
    }
}

#[test]
fn the_animation_has_the_stills_scales_and_names_no_pose() {
    let (_, cycle) = revolution(72);
    // The scales chosen automatically, the still at the pose of the
    // slowest arrows.
    let scene = Scene::new()
        .ground("A", [0.0, 0.0])
        .ground("D", [FourBar::WORKSHEET.l1, 0.0])
        .link(["A", "B"])
        .link(["B", "C"])
        .link(["C", "D"])
        .velocities(["G3", "G4"])
        .accelerations(["G3", "G4"])
        .title("The four-bar at θ₂ = 20°");
    let g4 = FourBar::G4;
    let slowest = cycle
        .iter()
        .min_by(|f, g| {
            let speed = |f: &Frame| f.velocities.as_ref().unwrap()[g4].norm();
            speed(f).total_cmp(&speed(g))
        })
        .unwrap();
    let still = scene.render(slowest, &cycle).unwrap();
    let animation = scene.animate(&cycle, 4.0).unwrap();
    let texts = |svg: &str| -> Vec<String> {
        parse(svg)
            .descendants()
            .filter(|n| n.is_text())
            .filter_map(|n| n.text())
            .map(|t| t.trim().to_string())
            .filter(|t| !t.is_empty())
            .collect()
    };
    let scales = |svg: &str| -> Vec<String> {
        texts(svg)
            .into_iter()
            .filter(|t| t.contains(", scale "))
            .collect()
    };
    assert_eq!(scales(&still).len(), 2);
    assert_eq!(scales(&still), scales(&animation));
    // The still's title names its pose; the animation does not carry it.
    assert!(texts(&still).iter().any(|t| t.contains("20°")));
    assert!(!texts(&animation).iter().any(|t| t.contains("20°")));
    let titled = scene
        .animation_title("A revolution of the crank")
        .animate(&cycle, 4.0)
        .unwrap();
    assert!(
        texts(&titled)
            .iter()
            .any(|t| t == "A revolution of the crank")
    );
}

/// A pivot named again is moved, not drawn twice.
#[test]
fn a_ground_pivot_named_again_is_moved() {
    let moved = Scene::new()
        .ground("A", [0.0, 0.0])
        .ground("D", [80.0, 0.0])
        .ground("A", [5.0, -2.0]);
    let written = Scene::new()
        .ground("A", [5.0, -2.0])
        .ground("D", [80.0, 0.0]);
    assert_eq!(moved, written);
}

/// A point's arrow asked for twice is drawn once.
#[test]
fn an_arrow_asked_for_twice_is_drawn_once() {
    let twice = Scene::new()
        .velocities(["B", "C"])
        .velocities(["C", "D"])
        .accelerations(["B"])
        .accelerations(["B"]);
    let once = Scene::new()
        .velocities(["B", "C", "D"])
        .accelerations(["B"]);
    assert_eq!(twice, once);
}

//! What a scene draws besides the pose: markers at fixed points, given
//! curves, ghost poses, notes, and the heading — each where its numbers
//! say, in the legend, clear of the labels, and every bad value a typed
//! error.

use crate::scenes::{
    Box2, Readback, Stroke, by_id, label_boxes, label_collisions, number, overlaps, painted_after,
    parse, path_segments,
};
use linkage::draw::scene::{Curve, Frame, MarkerShape, Markers, Scene, SceneError};
use linkage::error::{NameKind, UnknownName};
use linkage::mechanisms::CouplerFourBar;
use linkage::prelude::*;
use std::f64::consts::TAU;

/// The worksheet's four-bar with its coupler point off the coupler's
/// line: the curve a synthesis would have matched.
pub(crate) const DESIGN: CouplerFourBar = CouplerFourBar {
    px: 30.0,
    py: 18.0,
    ..CouplerFourBar::WORKSHEET
};

/// Another design on the same pivots, for a second curve.
const OTHER: CouplerFourBar = CouplerFourBar {
    l2: 22.0,
    px: 18.0,
    py: -14.0,
    ..CouplerFourBar::WORKSHEET
};

/// A turn of `model`'s crank from θ2 = 0, in `steps` steps.
pub(crate) fn turn(model: &CouplerFourBar, steps: usize) -> Vec<Frame> {
    let sweep = model
        .sweep(
            &vector![1.3, -0.8],
            &Drive::Line {
                from: vector![0.0],
                to: vector![TAU],
                steps,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    sweep
        .poses
        .iter()
        .map(|p| Frame::from_sweep_pose(model, p))
        .collect()
}

/// The coupler point's positions over a turn.
fn coupler_curve(frames: &[Frame]) -> Vec<Vector2<f64>> {
    let p = CouplerFourBar::P;
    frames.iter().map(|f| f.positions[p]).collect()
}

/// Five targets on the design's coupler curve, at θ2 = 0°, 72°, …
fn targets(cycle: &[Frame]) -> Vec<Vector2<f64>> {
    let curve = coupler_curve(cycle);
    (0..5).map(|k| curve[k * (cycle.len() - 1) / 5]).collect()
}

/// The design drawn as a synthesis figure draws it: at θ2 = 0 with three
/// ghost poses, its coupler curve traced, the five targets numbered, the
/// other design's curve, a note and a subtitle.
pub(crate) fn design_scene(cycle: &[Frame]) -> Scene {
    let quarter = (cycle.len() - 1) / 4;
    let ghosts: Vec<Frame> = (1..4).map(|k| cycle[k * quarter].clone()).collect();
    Scene::new()
        .ground("A", [0.0, 0.0])
        .ground("D", [80.0, 0.0])
        .link(["A", "B"])
        .plate(["B", "C", "P"])
        .link(["C", "D"])
        .trace(["P"])
        .markers(Markers::new("targets", targets(cycle)).numbered())
        .curve(
            Curve::new(
                "another design's coupler curve",
                coupler_curve(&turn(&OTHER, 180)),
            )
            .closed(true),
        )
        .ghosts(&ghosts)
        .note([40.0, -12.0], "ground link")
        .title("A design through five targets")
        .subtitle("error 0 mm (the targets lie on its curve); three other poses drawn faint")
}

/// Where the sample pictures go, if asked for (`LINKAGE_SCENE_LOOK`, a
/// folder): to look at them as a reader would.
pub(crate) fn keep_for_a_look(name: &str, svg: &str) {
    if let Ok(folder) = std::env::var("LINKAGE_SCENE_LOOK") {
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(std::path::Path::new(&folder).join(name), svg).unwrap();
    }
}

/// The centre of a group drawn `translate(x y)`.
fn translation(node: roxmltree::Node) -> Vector2<f64> {
    let transform = node.attribute("transform").unwrap();
    let inner = transform
        .strip_prefix("translate(")
        .and_then(|t| t.strip_suffix(')'))
        .unwrap();
    let (x, y) = inner.split_once(' ').unwrap();
    Vector2::new(x.parse().unwrap(), y.parse().unwrap())
}

/// The text of every `<text>` of class `class`.
fn texts_of(doc: &roxmltree::Document, class: &str) -> Vec<String> {
    doc.descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("class") == Some(class))
        .map(|n| n.text().unwrap_or("").trim().to_string())
        .collect()
}

fn legend_entry<'a>(doc: &'a roxmltree::Document<'a>, of: &str) -> roxmltree::Node<'a, 'a> {
    doc.descendants()
        .find(|n| {
            n.attribute("class") == Some("legend-entry") && n.attribute("data-for") == Some(of)
        })
        .unwrap_or_else(|| panic!("no legend entry for {of}"))
}

#[test]
fn markers_are_drawn_at_their_points_numbered_and_in_the_legend() {
    let cycle = turn(&DESIGN, 360);
    let points = targets(&cycle);
    let precision = [[10.0, 40.0], [60.0, 45.0]];
    let scene = design_scene(&cycle).markers(
        Markers::new("precision points", precision)
            .shape(MarkerShape::Diamond)
            .filled(true)
            .colour("#123456")
            .labels(["a", ""]),
    );
    let svg = scene.render(&cycle[0], &cycle).unwrap();
    keep_for_a_look("design.svg", &svg);
    let doc = parse(&svg);
    let back = Readback::new(&doc);
    let tolerance = back.tolerance();
    for (id, expected) in [
        ("markers-0", points.clone()),
        (
            "markers-1",
            precision.iter().map(|p| Vector2::new(p[0], p[1])).collect(),
        ),
    ] {
        let drawn: Vec<Vector2<f64>> = by_id(&doc, id)
            .children()
            .filter(|n| n.attribute("class") == Some("marker"))
            .map(|n| back.model(translation(n)))
            .collect();
        assert_eq!(drawn.len(), expected.len(), "{id}");
        for (d, e) in drawn.iter().zip(&expected) {
            assert!(
                (d - e).amax() <= tolerance,
                "{id}: drawn at {d:?}, given {e:?}"
            );
        }
    }
    // The targets numbered 1 to 5, each label nearer its own marker than
    // any other; the second set's one label, the empty one left out.
    let labels = texts_of(&doc, "marker-label");
    assert_eq!(labels, ["1", "2", "3", "4", "5", "a"]);
    let boxes: Vec<(String, Box2)> = label_boxes(&doc)
        .into_iter()
        .filter(|(text, _)| labels.contains(text))
        .collect();
    let to_box =
        |b: &Box2, p: Vector2<f64>| (b.min - p).sup(&(p - b.max)).sup(&Vector2::zeros()).norm();
    let screen: Vec<Vector2<f64>> = by_id(&doc, "markers-0")
        .children()
        .filter(|n| n.attribute("class") == Some("marker"))
        .map(translation)
        .collect();
    for (k, own) in screen.iter().enumerate() {
        let (_, b) = &boxes[k];
        let near = to_box(b, *own);
        // Within the farthest spot tried (40 px out).
        assert!(near <= 40.0, "label {} is {near} px from its marker", k + 1);
        for (j, other) in screen.iter().enumerate().filter(|(j, _)| *j != k) {
            assert!(
                to_box(b, *other) > near,
                "label {} nearer marker {}",
                k + 1,
                j + 1
            );
        }
    }
    // The sets' looks: the first chosen (open crosses), the second given.
    let look = |id: &str| {
        let shape = by_id(&doc, id)
            .descendants()
            .find(|n| n.has_tag_name("path") && n.attribute("class") != Some("halo"))
            .unwrap();
        (
            shape.attribute("stroke").unwrap().to_string(),
            shape.attribute("fill").unwrap().to_string(),
        )
    };
    let (first_colour, first_fill) = look("markers-0");
    assert_eq!(first_fill, "none");
    assert_eq!(
        look("markers-1"),
        ("#123456".to_string(), "#123456".to_string())
    );
    // Both in the legend under their names, their swatches drawn alike.
    for (set, name, colour) in [
        ("markers-0", "targets", first_colour.as_str()),
        ("markers-1", "precision points", "#123456"),
    ] {
        let entry = legend_entry(&doc, set);
        let text: String = entry.descendants().filter_map(|n| n.text()).collect();
        assert!(text.contains(name), "{set}: {text}");
        let swatch = entry
            .descendants()
            .find(|n| n.has_tag_name("path") && n.attribute("class") != Some("halo"))
            .unwrap();
        assert_eq!(swatch.attribute("stroke"), Some(colour));
    }
    // Five sets, their shapes and colours chosen: all told apart by both.
    let five = (0..5)
        .fold(Scene::new(), |scene, k| {
            scene.markers(Markers::new(&format!("set {k}"), [[k as f64, 0.0]]))
        })
        .render(&cycle[0], &[])
        .unwrap();
    let doc = parse(&five);
    let looks: Vec<(&str, &str)> = (0..5)
        .map(|k| {
            let shape = by_id(&doc, &format!("markers-{k}"))
                .descendants()
                .find(|n| n.has_tag_name("path") && n.attribute("class") != Some("halo"))
                .unwrap();
            (
                shape.attribute("stroke").unwrap(),
                shape.attribute("d").unwrap(),
            )
        })
        .collect();
    for (i, a) in looks.iter().enumerate() {
        for b in &looks[i + 1..] {
            assert!(a.0 != b.0 && a.1 != b.1, "{a:?} and {b:?}");
        }
    }
}

/// The points of a path written `M x y L x y … [Z]`.
fn path_points(d: &str) -> Vec<Vector2<f64>> {
    let numbers: Vec<f64> = d
        .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap())
        .collect();
    numbers
        .chunks(2)
        .map(|p| Vector2::new(p[0], p[1]))
        .collect()
}

#[test]
fn curves_go_through_their_points_in_styles_of_their_own() {
    let cycle = turn(&DESIGN, 360);
    let other = coupler_curve(&turn(&OTHER, 180));
    let open = [[0.0, 60.0], [40.0, 70.0], [80.0, 60.0]];
    let scene = design_scene(&cycle).curve(Curve::new("desired path", open));
    let svg = scene.render(&cycle[0], &cycle).unwrap();
    let doc = parse(&svg);
    let back = Readback::new(&doc);
    let closed = by_id(&doc, "curve-0").attribute("d").unwrap();
    assert!(closed.ends_with('Z'), "a closed curve closes");
    let drawn = path_points(closed);
    assert_eq!(drawn.len(), other.len());
    for (d, e) in drawn.iter().zip(&other) {
        assert!((back.model(*d) - e).amax() <= back.tolerance());
    }
    let open_d = by_id(&doc, "curve-1").attribute("d").unwrap();
    assert!(!open_d.contains('Z'));
    assert_eq!(path_segments(open_d).len(), 2);
    // Told apart from the traced path and from each other, by colour or
    // dashes; each in the legend, its swatch drawn as it.
    let style = |n: roxmltree::Node| {
        (
            n.attribute("stroke").unwrap().to_string(),
            n.attribute("stroke-dasharray").unwrap_or("").to_string(),
            n.attribute("stroke-width").unwrap().to_string(),
        )
    };
    let trace = style(by_id(&doc, "trace-P"));
    let curves = ["curve-0", "curve-1"].map(|id| style(by_id(&doc, id)));
    assert_ne!((&curves[0].0, &curves[0].1), (&trace.0, &trace.1));
    assert_ne!((&curves[1].0, &curves[1].1), (&trace.0, &trace.1));
    assert_ne!((&curves[0].0, &curves[0].1), (&curves[1].0, &curves[1].1));
    for (k, name) in [(0, "another design's coupler curve"), (1, "desired path")] {
        let entry = legend_entry(&doc, &format!("curve-{k}"));
        let swatch = entry
            .children()
            .find(|n| n.attribute("class") == Some("swatch"))
            .unwrap();
        assert_eq!(style(swatch), curves[k]);
        let text: String = entry.descendants().filter_map(|n| n.text()).collect();
        assert!(text.contains(name));
    }
    // A colour and dashes given are drawn; a curve without a name is not
    // in the legend.
    let svg = Scene::new()
        .curve(Curve::new("", open).colour("teal").dashes(&[5.0, 2.5]))
        .render(&cycle[0], &[])
        .unwrap();
    let doc = parse(&svg);
    let given = style(by_id(&doc, "curve-0"));
    assert_eq!((given.0.as_str(), given.1.as_str()), ("teal", "5 2.5"));
    assert!(!svg.contains(r#"data-for="curve-0""#));
}

#[test]
fn ghost_poses_are_drawn_faint_under_the_pose_without_labels_or_arrows() {
    let cycle = turn(&DESIGN, 360);
    let scene = design_scene(&cycle).velocities(["P"]);
    let svg = scene.render(&cycle[0], &cycle).unwrap();
    let doc = parse(&svg);
    let back = Readback::new(&doc);
    let ghosts: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("ghost"))
        .collect();
    assert_eq!(ghosts.len(), 3);
    // Each at its own pose: its joints where that frame puts B, C, P.
    let quarter = 90;
    for (k, ghost) in ghosts.iter().enumerate() {
        let frame = &cycle[(k + 1) * quarter];
        let joints: Vec<Vector2<f64>> = ghost
            .children()
            .filter(|n| n.attribute("class") == Some("ghost-joint"))
            .map(|n| back.model(Vector2::new(number(n, "cx"), number(n, "cy"))))
            .collect();
        for name in ["B", "C", "P"] {
            let at = frame.positions[CouplerFourBar::WORKSHEET.point_index(name).unwrap()];
            assert!(
                joints.iter().any(|j| (j - at).amax() <= back.tolerance()),
                "ghost {k}: no joint at {name}"
            );
        }
        // Its bars and plate, in light grey.
        let bodies: Vec<_> = ghost
            .children()
            .filter(|n| n.attribute("class") == Some("ghost-link"))
            .collect();
        assert_eq!(bodies.len(), 3);
        for body in bodies {
            assert_eq!(body.attribute("stroke"), Some("#c4ccd6"));
        }
        // No label, no arrow.
        assert!(ghost.descendants().all(|n| !n.has_tag_name("text")));
        assert!(
            ghost
                .descendants()
                .all(|n| !n.attribute("class").is_some_and(|c| c.contains("arrow")))
        );
    }
    // Every ghost under every link of the pose.
    let links: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("link"))
        .collect();
    assert_eq!(links.len(), 3);
    for ghost in &ghosts {
        for n in ghost.descendants().filter(|n| n.is_element()) {
            for link in &links {
                assert!(
                    painted_after(*link, n),
                    "a ghost drawn over {:?}",
                    link.attribute("id")
                );
            }
        }
    }
    // One label per point of the pose, none for the ghosts.
    assert_eq!(
        label_boxes(&doc).iter().filter(|(t, _)| t == "B").count(),
        1
    );
    // The animation keeps them still behind the moving pose.
    let animation = scene.animate(&cycle[..60], 2.0).unwrap();
    let doc = parse(&animation);
    let ghost = by_id(&doc, "ghosts");
    assert_eq!(ghost.children().filter(|n| n.is_element()).count(), 3);
    assert!(ghost.descendants().all(|n| !n.has_tag_name("animate")));
}

/// Named, the ghosts have a legend entry in their colour, and the legend
/// grows by a line for it; unnamed or absent, none.
#[test]
fn named_ghosts_have_a_legend_entry() {
    let cycle = turn(&DESIGN, 360);
    let entry = |scene: &Scene| {
        let svg = scene.render(&cycle[0], &cycle).unwrap();
        let doc = parse(&svg);
        let height: f64 = doc
            .root_element()
            .attribute("height")
            .unwrap()
            .parse()
            .unwrap();
        let text = (doc.descendants())
            .find(|n| n.attribute("data-for") == Some("ghosts"))
            .map(|n| {
                let swatch = n.children().find(|c| c.has_tag_name("line")).unwrap();
                let bar = (doc.descendants())
                    .find(|g| g.attribute("class") == Some("ghost-link"))
                    .unwrap();
                assert_eq!(swatch.attribute("stroke"), bar.attribute("stroke"));
                let text = n.descendants().find(|t| t.has_tag_name("text")).unwrap();
                text.text().unwrap_or_default().trim().to_owned()
            });
        (text, height)
    };
    let unnamed = entry(&design_scene(&cycle));
    assert_eq!(unnamed.0, None);
    let named = entry(&design_scene(&cycle).ghost_name("three other poses"));
    assert_eq!(named.0.as_deref(), Some("three other poses"));
    assert!(named.1 > unnamed.1, "{named:?} against {unnamed:?}");
    let no_ghosts = Scene::new()
        .ground("A", [0.0, 0.0])
        .link(["A", "B"])
        .ghost_name("none drawn");
    assert_eq!(entry(&no_ghosts).0, None);
}

/// The strokes of the curves and the markers (a disc round each marker).
fn overlay_strokes(doc: &roxmltree::Document) -> Vec<Stroke> {
    let mut strokes = Vec::new();
    for curve in doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("curve"))
    {
        let half = number(curve, "stroke-width") / 2.0;
        strokes.extend(
            path_segments(curve.attribute("d").unwrap())
                .into_iter()
                .map(|(a, b)| Stroke { a, b, half }),
        );
    }
    for marker in doc.descendants().filter(|n| {
        n.attribute("class") == Some("marker")
            && n.ancestors()
                .any(|a| a.attribute("class") == Some("markers"))
    }) {
        let at = translation(marker);
        strokes.push(Stroke {
            a: at,
            b: at,
            half: 6.5,
        });
    }
    strokes
}

#[test]
fn labels_keep_clear_of_markers_curves_notes_and_one_another() {
    let cycle = turn(&DESIGN, 360);
    let svg = design_scene(&cycle).render(&cycle[0], &cycle).unwrap();
    let collisions = label_collisions(&svg);
    assert!(collisions.is_empty(), "{collisions:?}");
    let doc = parse(&svg);
    let strokes = overlay_strokes(&doc);
    assert!(strokes.len() > 100);
    let notes: Vec<Box2> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("note"))
        .map(|n| {
            let (x, y, size) = (number(n, "x"), number(n, "y"), number(n, "font-size"));
            let half = 0.6 * size * n.text().unwrap().trim().chars().count() as f64 / 2.0;
            Box2 {
                min: Vector2::new(x - half, y - 0.72 * size),
                max: Vector2::new(x + half, y + 0.22 * size),
            }
        })
        .collect();
    assert_eq!(notes.len(), 1);
    for (text, b) in label_boxes(&doc) {
        assert!(
            !strokes.iter().any(|s| overlaps(s, &b)),
            "{text} on a curve or a marker"
        );
        for note in &notes {
            let apart = b.max.x < note.min.x
                || note.max.x < b.min.x
                || b.max.y < note.min.y
                || note.max.y < b.min.y;
            assert!(apart, "{text} on the note");
        }
    }
}

#[test]
fn the_heading_wraps_and_the_subtitle_sits_under_the_title() {
    let cycle = turn(&DESIGN, 72);
    let long = "The best design of each tool, at several poses, with its coupler curve through the targets";
    let svg = design_scene(&cycle)
        .title(long)
        .width(400.0)
        .render(&cycle[0], &cycle)
        .unwrap();
    let doc = parse(&svg);
    let lines = |class: &str| -> Vec<(String, f64)> {
        doc.descendants()
            .filter(|n| n.has_tag_name("text") && n.attribute("class") == Some(class))
            .map(|n| (n.text().unwrap().trim().to_string(), number(n, "y")))
            .collect()
    };
    let (title, subtitle) = (lines("title"), lines("subtitle"));
    assert!(title.len() >= 3, "{title:?}");
    let joined: Vec<&str> = title.iter().map(|(t, _)| t.as_str()).collect();
    assert_eq!(joined.join(" "), long);
    for (text, _) in &title {
        // 17-px text, at half an em a letter on average: within the
        // 400 px less a margin.
        assert!(0.5 * 17.0 * text.chars().count() as f64 <= 376.0, "{text}");
    }
    assert!(!subtitle.is_empty());
    let last_title = title.last().unwrap().1;
    assert!(subtitle.iter().all(|(_, y)| *y > last_title));
    // The drawing starts below the heading: every point's label and the
    // pivots under the subtitle's last line.
    let lowest_heading = subtitle.last().unwrap().1;
    for id in ["point-A", "point-B", "point-C", "point-P"] {
        assert!(
            number(by_id(&doc, id), "cy") > lowest_heading + 10.0,
            "{id}"
        );
    }
    // The note is written at its point.
    let back = Readback::new(&doc);
    let note = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("note"))
        .unwrap();
    assert_eq!(note.text().unwrap().trim(), "ground link");
    let at = back.model(Vector2::new(number(note, "x"), number(note, "y")));
    assert!((at.x - 40.0).abs() <= back.tolerance());
    // The baseline a little under the point, the text centred on it.
    assert!(at.y < -12.0 && at.y > -12.0 - 6.0 / back.scale);
}

#[test]
fn bad_markers_curves_notes_and_ghosts_are_typed_errors() {
    let cycle = turn(&DESIGN, 36);
    let frame = &cycle[0];
    let base = || {
        Scene::new()
            .ground("A", [0.0, 0.0])
            .ground("D", [80.0, 0.0])
            .link(["A", "B"])
            .link(["B", "C"])
            .link(["C", "D"])
    };
    let render = |scene: Scene| scene.render(frame, &[]).unwrap_err();
    let nan = f64::NAN;
    let cases: Vec<(Scene, SceneError)> = vec![
        (
            base().markers(Markers::new(
                "targets",
                [[0.0, 0.0], [1.0, 1.0], [nan, 2.0]],
            )),
            SceneError::NonFinitePoint {
                what: "set of markers",
                name: "targets".into(),
                index: 2,
            },
        ),
        (
            base().markers(Markers::new("targets", Vec::<[f64; 2]>::new())),
            SceneError::TooFewPoints {
                what: "set of markers",
                name: "targets".into(),
                points: 0,
                least: 1,
            },
        ),
        (
            base().markers(Markers::new("targets", [[0.0, 0.0], [1.0, 1.0]]).labels(["1"])),
            SceneError::LabelCount {
                name: "targets".into(),
                markers: 2,
                labels: 1,
            },
        ),
        (
            base().markers(Markers::new("targets", [[0.0, 0.0]]).colour("red; fill: url(#x)")),
            SceneError::BadColour {
                what: "a set of markers",
                colour: "red; fill: url(#x)".into(),
            },
        ),
        (
            base().markers(Markers::new("targets", [[0.0, 0.0]]).size(0.0)),
            SceneError::BadSetting {
                what: "a marker's size",
                must: "from 2 to 40 pixels",
                value: 0.0,
            },
        ),
        (
            base().curve(Curve::new("path", [[0.0, 0.0]])),
            SceneError::TooFewPoints {
                what: "curve",
                name: "path".into(),
                points: 1,
                least: 2,
            },
        ),
        (
            base().curve(Curve::new("path", [[0.0, 0.0], [f64::INFINITY, 1.0]])),
            SceneError::NonFinitePoint {
                what: "curve",
                name: "path".into(),
                index: 1,
            },
        ),
        (
            base().curve(Curve::new("path", [[0.0, 0.0], [1.0, 1.0]]).dashes(&[4.0, -1.0])),
            SceneError::BadSetting {
                what: "a curve's dash length",
                must: "positive and finite",
                value: -1.0,
            },
        ),
        (
            base().curve(Curve::new("path", [[0.0, 0.0], [1.0, 1.0]]).colour("")),
            SceneError::BadColour {
                what: "a curve",
                colour: String::new(),
            },
        ),
        (
            base().note([nan, 0.0], "dead centre"),
            SceneError::NonFinite {
                what: "position",
                name: "dead centre".into(),
            },
        ),
    ];
    for (scene, expected) in cases {
        let err = render(scene.clone());
        assert_eq!(err, expected, "{err}");
        // The animation refuses it alike.
        assert_eq!(scene.animate(&cycle, 1.0).unwrap_err(), expected);
        assert!(!err.to_string().is_empty());
    }
    assert_eq!(
        SceneError::NonFinitePoint {
            what: "set of markers",
            name: "targets".into(),
            index: 2
        }
        .to_string(),
        "point 2 (from 0) of the set of markers `targets` is not finite"
    );
    // A ghost pose of another model: its names are not the scene's.
    let other_model = Frame {
        names: vec!["Q".into()],
        positions: vec![Vector2::zeros()],
        velocities: None,
        accelerations: None,
    };
    assert_eq!(
        render(base().ghosts(&[other_model])),
        SceneError::UnknownName(UnknownName {
            kind: NameKind::Point,
            owner: "scene".into(),
            name: "B".into(),
            known: "Q".into(),
        })
    );
    let mut broken = cycle[3].clone();
    broken.positions[CouplerFourBar::C].y = nan;
    assert_eq!(
        render(base().ghosts(&[cycle[1].clone(), broken])),
        SceneError::NonFinite {
            what: "position",
            name: "C".into(),
        }
    );
    // Text is escaped wherever it is written.
    let svg = base()
        .markers(Markers::new("<&\">", [[0.0, 0.0]]).labels(["<1>"]))
        .curve(Curve::new("a & b", [[0.0, 0.0], [1.0, 1.0]]))
        .note([0.0, 0.0], "\"quoted\" <note>")
        .subtitle("<&>")
        .render(frame, &[])
        .unwrap();
    parse(&svg);
}

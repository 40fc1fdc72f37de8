//! The library's charts: log axes refuse what they cannot show, one scale
//! for both axes where asked, a legend that covers no curve, no two series
//! alike, bars from zero, sizes that keep their printed size.

use linkage::draw::chart::{Chart, DiagramError, Panel};
use roxmltree::Document;

fn ramp(n: usize) -> Vec<(f64, f64)> {
    (0..=n).map(|i| (i as f64, 1.0 + i as f64)).collect()
}

fn elements<'a>(doc: &'a Document<'a>, tag: &str) -> Vec<roxmltree::Node<'a, 'a>> {
    doc.descendants()
        .filter(|n| n.tag_name().name() == tag)
        .collect()
}

fn points(node: roxmltree::Node) -> Vec<(f64, f64)> {
    node.attribute("points")
        .unwrap_or("")
        .split_whitespace()
        .filter_map(|p| p.split_once(','))
        .map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap()))
        .collect()
}

#[test]
fn a_log_axis_refuses_values_not_positive() {
    let err = Chart::new("log", "x")
        .panel(
            Panel::new("y")
                .y_log()
                .line("zero at 3", vec![(1.0, 1.0), (2.0, 2.0), (3.0, 0.0)]),
        )
        .render()
        .unwrap_err();
    assert_eq!(
        err,
        DiagramError::NotPositive {
            what: "point",
            name: "zero at 3".into(),
            pose: 2
        }
    );
    assert!(err.to_string().contains("logarithmic"));
    let err = Chart::new("range", "x")
        .panel(Panel::new("y").line("a", ramp(3)).x_range(2.0, 1.0))
        .render()
        .unwrap_err();
    assert!(matches!(err, DiagramError::BadSetting { .. }), "{err:?}");
}

#[test]
fn equal_scales_give_one_unit_the_same_length_on_both_axes() {
    // A circle of radius 1 about (3, 0): as wide as it is high on the page.
    let circle: Vec<(f64, f64)> = (0..=72)
        .map(|i| {
            let a = f64::from(i) * 5f64.to_radians();
            (3.0 + a.cos(), a.sin())
        })
        .collect();
    let svg = Chart::new("circle", "x")
        .size(900, 300)
        .panel(Panel::new("y").equal_scales().line("circle", circle))
        .render()
        .unwrap();
    let doc = Document::parse(&svg).unwrap();
    let curve = points(elements(&doc, "polyline")[0]);
    let (x0, x1) = curve
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = curve
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
    assert!(
        ((x1 - x0) / (y1 - y0) - 1.0).abs() < 2e-3,
        "{} × {}",
        x1 - x0,
        y1 - y0
    );
}

#[test]
fn a_legend_covers_no_curve_when_there_is_room_to_make() {
    // Curves over the whole panel: the ordinate grows to make room.
    let wave = |phase: f64| -> Vec<(f64, f64)> {
        (0..=100)
            .map(|i| {
                let x = f64::from(i) / 10.0;
                (x, (x + phase).sin())
            })
            .collect()
    };
    let svg = Chart::new("crowded", "x")
        .panel(
            Panel::new("y")
                .line("first curve with a long name", wave(0.0))
                .line("second", wave(1.5))
                .levels("limits", &[1.0, -1.0]),
        )
        .render()
        .unwrap();
    let doc = Document::parse(&svg).unwrap();
    let legend = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("legend-box"))
        .expect("a legend box");
    let number = |name: &str| legend.attribute(name).unwrap().parse::<f64>().unwrap();
    let (x, y, w, h) = (number("x"), number("y"), number("width"), number("height"));
    for curve in elements(&doc, "polyline") {
        for (px, py) in points(curve) {
            assert!(
                !(x..=x + w).contains(&px) || !(y..=y + h).contains(&py),
                "({px}, {py}) under the legend"
            );
        }
    }
}

#[test]
fn no_two_series_look_alike() {
    let mut panel = Panel::new("y");
    for k in 0..20 {
        panel = panel.points(&format!("series {k}"), vec![(k as f64, 1.0)]);
    }
    let svg = Chart::new("twenty", "x").panel(panel).render().unwrap();
    let doc = Document::parse(&svg).unwrap();
    // Each marker: its colour and its shape (a circle, or a path's shape
    // relative to its first point).
    let mut looks: Vec<String> = Vec::new();
    for marker in doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("marker"))
        .filter(|n| n.parent().is_some_and(|p| p.tag_name().name() == "g"))
    {
        let colour = marker.attribute("stroke").unwrap_or("");
        let shape = match marker.tag_name().name() {
            "circle" => "circle".to_string(),
            _ => {
                let d = marker.attribute("d").unwrap();
                let numbers: Vec<f64> = d
                    .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                    .filter_map(|s| s.parse().ok())
                    .collect();
                let relative: Vec<i64> = numbers
                    .chunks(2)
                    .map(|p| {
                        ((p[0] - numbers[0]) * 10.0).round() as i64
                            + 1000 * ((p[1] - numbers[1]) * 10.0).round() as i64
                    })
                    .collect();
                format!("{relative:?}")
            }
        };
        looks.push(format!("{colour} {shape}"));
    }
    assert_eq!(looks.len(), 20);
    let mut distinct = looks.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), 20, "{looks:?}");
}

#[test]
fn bars_stand_on_zero_one_group_a_colour() {
    let svg = Chart::new("bars", "")
        .panel(
            Panel::bars("share [%]", &["a", "b", "c"])
                .group("first", &[10.0, 50.0, 40.0])
                .group("second", &[30.0, 30.0, 40.0]),
        )
        .render()
        .unwrap();
    let doc = Document::parse(&svg).unwrap();
    let bars: Vec<_> = elements(&doc, "rect")
        .into_iter()
        .filter(|r| r.parent().is_some_and(|p| p.tag_name().name() == "g"))
        .collect();
    assert_eq!(bars.len(), 6);
    let bottom = |r: &roxmltree::Node| {
        r.attribute("y").unwrap().parse::<f64>().unwrap()
            + r.attribute("height").unwrap().parse::<f64>().unwrap()
    };
    assert!(
        bars.iter()
            .all(|r| (bottom(r) - bottom(&bars[0])).abs() < 0.02)
    );
    let colours: Vec<&str> = bars.iter().map(|r| r.attribute("fill").unwrap()).collect();
    assert_eq!(&colours[..3], [colours[0]; 3]);
    assert_ne!(colours[0], colours[3]);
    // The categories are the ticks' labels.
    let labels: Vec<String> = elements(&doc, "text")
        .iter()
        .map(|t| t.text().unwrap_or("").to_string())
        .collect();
    assert!(
        ["a", "b", "c"]
            .iter()
            .all(|c| labels.iter().any(|l| l == c))
    );
}

#[test]
fn text_keeps_its_printed_size_at_any_width() {
    let size_at = |width: u32| {
        let svg = Chart::new("sizes", "x")
            .size(width, 300)
            .panel(Panel::new("y").line("a", ramp(3)))
            .render()
            .unwrap();
        let doc = Document::parse(&svg).unwrap();
        let tick = elements(&doc, "text")
            .into_iter()
            .find(|t| t.attribute("text-anchor") == Some("end"))
            .unwrap();
        tick.attribute("font-size").unwrap().parse::<f64>().unwrap() / f64::from(width)
    };
    assert!((size_at(600) / size_at(1500) - 1.0).abs() < 1e-3);
    // 8 pt when printed 16 cm wide.
    assert!((size_at(600) * 16.0 / 2.54 * 72.0 - 8.0).abs() < 0.01);
}

//! The charts' and diagrams' legends: every swatch is drawn in the style —
//! colour, dashes, width — of the curves it names, in its panel (or in
//! every panel, for a legend shown once for all); shared legends are drawn
//! once; subscripts are drawn as subscripts; a revolution is drawn over
//! 0…360°. The stability study's charts (`examples/stability`) are checked
//! the same way.

use crate::charts;
use crate::study;

use linkage::draw::chart::Dash;
use linkage::draw::chart::look::COLOURS;
use linkage::draw::diagrams::{Chart, Diagrams, Panel};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use roxmltree::{Document, Node};
use std::f64::consts::TAU;

/// A stroked line of the picture: a `<polyline>` or a `<line>`.
#[derive(Debug)]
struct Line<'a> {
    node: Node<'a, 'a>,
    points: Vec<(f64, f64)>,
}

impl Line<'_> {
    /// What identifies the curve: its colour and opacity.
    fn colour(&self) -> (&str, &str) {
        paint(self.node, "stroke")
    }

    /// What the swatch must share with its curve besides the colour.
    fn pattern(&self) -> (&str, &str) {
        (
            attribute(self.node, "stroke-dasharray"),
            attribute(self.node, "stroke-width"),
        )
    }

    /// A short horizontal stroke: what a swatch looks like.
    fn swatch_like(&self) -> bool {
        let [(x0, y0), (x1, y1)] = self.points[..] else {
            return false;
        };
        (y0 - y1).abs() < 0.5 && (10.0..=60.0).contains(&(x1 - x0))
    }
}

/// What a legend entry draws before its name.
#[derive(Debug)]
enum Entry<'a> {
    /// A stroke: the index of a line in [`Picture::lines`].
    Line(usize),
    /// A filled rectangle: a shaded region's swatch.
    Band(Node<'a, 'a>),
}

fn attribute<'a>(node: Node<'a, '_>, name: &str) -> &'a str {
    node.attribute(name).unwrap_or("")
}

/// A stroke's or a fill's colour (`key`), with its opacity.
fn paint<'a>(node: Node<'a, '_>, key: &str) -> (&'a str, &'a str) {
    (attribute(node, key), attribute(node, "opacity"))
}

fn number(node: Node, name: &str) -> f64 {
    attribute(node, name).parse().unwrap_or(f64::NAN)
}

/// A text's content, its `tspan`s (subscripts) included.
fn content(node: Node) -> String {
    node.descendants()
        .filter(|n| n.is_text())
        .filter_map(|n| n.text())
        .collect::<String>()
        .trim()
        .to_owned()
}

/// What the checks need of an SVG page.
struct Picture<'a> {
    lines: Vec<Line<'a>>,
    fills: Vec<Node<'a, 'a>>,
    texts: Vec<Node<'a, 'a>>,
}

impl<'a> Picture<'a> {
    fn of(doc: &'a Document<'a>) -> Picture<'a> {
        let mut picture = Picture {
            lines: Vec::new(),
            fills: Vec::new(),
            texts: Vec::new(),
        };
        for node in doc.descendants().filter(|n| n.is_element()) {
            match node.tag_name().name() {
                "polyline" => picture.lines.push(Line {
                    node,
                    points: attribute(node, "points")
                        .split_whitespace()
                        .filter_map(|p| p.split_once(','))
                        .map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap()))
                        .collect(),
                }),
                "line" => picture.lines.push(Line {
                    node,
                    points: vec![
                        (number(node, "x1"), number(node, "y1")),
                        (number(node, "x2"), number(node, "y2")),
                    ],
                }),
                "rect" if !matches!(attribute(node, "fill"), "none" | "") => {
                    picture.fills.push(node)
                }
                "text" => picture.texts.push(node),
                _ => {}
            }
        }
        picture
    }

    /// The legend entries: a name written just right of a short horizontal
    /// stroke or a small filled rectangle, on its line.
    fn legend(&self) -> Vec<(Entry<'a>, String)> {
        let mut entries = Vec::new();
        for text in self
            .texts
            .iter()
            .filter(|t| attribute(**t, "text-anchor") == "start")
        {
            let (x, y) = (number(*text, "x"), number(*text, "y"));
            let next_to = |right: f64, middle: f64| {
                (1.0..=16.0).contains(&(x - right)) && (y - middle).abs() <= 8.0
            };
            let line = self
                .lines
                .iter()
                .position(|l| l.swatch_like() && next_to(l.points[1].0, l.points[1].1));
            let band = self.fills.iter().find(|r| {
                let (rx, ry) = (number(**r, "x"), number(**r, "y"));
                let (w, h) = (number(**r, "width"), number(**r, "height"));
                (10.0..=60.0).contains(&w) && h <= 20.0 && next_to(rx + w, ry + h / 2.0)
            });
            let swatch = match (line, band) {
                (Some(i), _) => Entry::Line(i),
                (None, Some(r)) => Entry::Band(*r),
                (None, None) => continue,
            };
            entries.push((swatch, content(*text)));
        }
        entries
    }

    /// The plotting areas of the panels: each between a long vertical axis
    /// (the axes' dark grey) and the long horizontal axis from its foot.
    fn panels(&self) -> Vec<[f64; 4]> {
        let axes: Vec<&Line> = self
            .lines
            .iter()
            .filter(|l| l.colour() == ("#262626", "1") && l.points.len() == 2)
            .collect();
        let mut panels = Vec::new();
        for y_axis in &axes {
            let [(x, top), (x1, bottom)] = y_axis.points[..] else {
                continue;
            };
            if x != x1 || bottom - top < 40.0 {
                continue;
            }
            let foot = axes.iter().find_map(|a| {
                let [(ax0, ay0), (ax1, ay1)] = a.points[..] else {
                    return None;
                };
                let from_foot = (ax0 - x).abs() <= 2.0 && (ay0 - bottom).abs() <= 2.0;
                (from_foot && ay0 == ay1 && ax1 - ax0 > 40.0).then_some(ax1)
            });
            if let Some(right) = foot {
                panels.push([x, top, right, bottom]);
            }
        }
        panels
    }
}

/// Checks that every legend entry of `svg` has curves drawn in its colour,
/// in its panel (a legend outside the panels stands for all of them), and
/// that they are drawn with the swatch's dashes and width. The number of
/// entries, or what is wrong.
fn check_legends(svg: &str) -> Result<usize, String> {
    let doc = Document::parse(svg).map_err(|e| format!("not well-formed: {e}"))?;
    let picture = Picture::of(&doc);
    let entries = picture.legend();
    let panels = picture.panels();
    let swatches: Vec<usize> = entries
        .iter()
        .filter_map(|(s, _)| match s {
            Entry::Line(i) => Some(*i),
            Entry::Band(_) => None,
        })
        .collect();
    for (swatch, name) in &entries {
        match swatch {
            Entry::Line(i) => {
                let swatch = &picture.lines[*i];
                let (sx, sy) = swatch.points[0];
                let inside = |[x0, y0, x1, y1]: [f64; 4], (x, y): (f64, f64)| {
                    (x0..=x1).contains(&x) && (y0..=y1).contains(&y)
                };
                let panel = panels.iter().find(|p| inside(**p, (sx, sy)));
                let curves: Vec<&Line> = picture
                    .lines
                    .iter()
                    .enumerate()
                    .filter(|(k, l)| {
                        !swatches.contains(k)
                            && l.colour() == swatch.colour()
                            && panel.is_none_or(|p| inside(*p, l.points[0]))
                    })
                    .map(|(_, l)| l)
                    .collect();
                if curves.is_empty() {
                    return Err(format!(
                        "legend entry `{name}`: nothing drawn in its colour {:?}",
                        swatch.colour()
                    ));
                }
                for curve in curves {
                    if curve.pattern() != swatch.pattern() {
                        return Err(format!(
                            "legend entry `{name}`: swatch (dashes, width) {:?}, its curve {:?}",
                            swatch.pattern(),
                            curve.pattern()
                        ));
                    }
                }
            }
            Entry::Band(r) => {
                let shaded = picture
                    .fills
                    .iter()
                    .filter(|f| f.range() != r.range() && paint(**f, "fill") == paint(*r, "fill"))
                    .count();
                if shaded == 0 {
                    return Err(format!("legend entry `{name}`: nothing shaded like it"));
                }
            }
        }
    }
    Ok(entries.len())
}

/// An element's text without its `stroke-dasharray`.
fn without_dashes(element: &str) -> String {
    match element.find(" stroke-dasharray=\"") {
        Some(at) => {
            let value = at + " stroke-dasharray=\"".len();
            let end = value + element[value..].find('"').unwrap_or(0) + 1;
            format!("{}{}", &element[..at], &element[end..])
        }
        None => element.to_string(),
    }
}

/// `svg` with the element `node` (of `svg`) rewritten by `change`.
fn edited(svg: &str, node: Node, change: impl Fn(&str) -> String) -> String {
    let range = node.range();
    format!(
        "{}{}{}",
        &svg[..range.start],
        change(&svg[range.clone()]),
        &svg[range.end..]
    )
}

fn wave(phase: f64, size: f64) -> Vec<(f64, f64)> {
    (0..=120)
        .map(|i| {
            let x = f64::from(i) * 3.0;
            (x, size * (x.to_radians() + phase).sin())
        })
        .collect()
}

/// Two panels side by side whose curves share colours in different
/// styles: the first panel's blue is solid, the second's dashed.
fn two_panels() -> String {
    Chart::new("Two panels", "φ [°]")
        .columns(2)
        .panel(
            Panel::new("y [mm]")
                .line("a", wave(0.0, 1.0))
                .dashed("b", wave(1.0, 1.0))
                .levels("limit", &[1.2, -1.2]),
        )
        .panel(
            Panel::new("z [mm]")
                .dashed("c", wave(0.0, 2.0))
                .colour(COLOURS[0])
                .line("d", wave(2.0, 1.0))
                .dash(Dash::Solid),
        )
        .render()
        .unwrap()
}

fn revolution(from_degrees: f64) -> (FourBar, Sweep<2, 1>) {
    let bar = FourBar::WORKSHEET;
    let start = bar
        .solve_position(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &vector![from_degrees.to_radians()],
            &Options::default(),
        )
        .unwrap();
    let sweep = bar
        .sweep(
            &start.u,
            &Drive::Line {
                from: vector![from_degrees.to_radians()],
                to: vector![from_degrees.to_radians() + TAU],
                steps: 180,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    (bar, sweep)
}

#[test]
fn chart_legends_match_their_curves() {
    assert_eq!(check_legends(&two_panels()), Ok(5));
}

#[test]
fn the_legend_check_fails_on_a_swatch_unlike_its_curve() {
    let svg = two_panels();
    let doc = Document::parse(&svg).unwrap();
    let picture = Picture::of(&doc);
    let swatch = |name: &str| {
        picture
            .legend()
            .into_iter()
            .find_map(|(entry, n)| match entry {
                Entry::Line(i) if n == name => Some(picture.lines[i].node),
                _ => None,
            })
            .unwrap_or_else(|| panic!("no legend entry {name}"))
    };
    // The fault reported: a dashed curve with a solid swatch.
    let solid = edited(&svg, swatch("b"), without_dashes);
    assert_ne!(solid, svg);
    assert!(check_legends(&solid).unwrap_err().contains("`b`"));
    // A dashed swatch for a solid curve.
    let dashed = edited(&svg, swatch("d"), |e| {
        without_dashes(e).replace("stroke-width", "stroke-dasharray=\"7 4\" stroke-width")
    });
    assert!(check_legends(&dashed).unwrap_err().contains("`d`"));
    // A swatch thinner than its curve.
    let thin = edited(&svg, swatch("a"), |e| {
        e.replace("stroke-width=\"", "stroke-width=\"0")
    });
    assert!(check_legends(&thin).unwrap_err().contains("`a`"));
    // A swatch in a colour no curve has.
    let recoloured = edited(&svg, swatch("c"), |e| {
        e.replace("stroke=\"#", "stroke=\"#0")
    });
    assert!(check_legends(&recoloured).unwrap_err().contains("`c`"));
    // One of the two limits drawn solid: one swatch cannot match both.
    let limit = swatch("limit");
    let level = picture
        .lines
        .iter()
        .map(|l| l.node)
        .find(|&n| n != limit && paint(n, "stroke") == paint(limit, "stroke"))
        .unwrap();
    let two_styles = edited(&svg, level, without_dashes);
    assert!(check_legends(&two_styles).unwrap_err().contains("`limit`"));
}

#[test]
fn a_legend_every_panel_shares_is_drawn_once() {
    let panel = |label: &str| {
        Panel::new(label)
            .line("energy method", wave(0.0, 1.0))
            .dashed("real motion", wave(0.1, 1.0))
    };
    let svg = Chart::new("Shared", "φ [°]")
        .columns(3)
        .panel(panel("ω_1 [rad/s]"))
        .panel(panel("ε_1 [rad/s²]"))
        .panel(panel("x [m]"))
        .render()
        .unwrap();
    assert_eq!(check_legends(&svg), Ok(2));
    assert_eq!(svg.matches("real motion").count(), 1);
}

#[test]
fn motion_diagrams_legend_matches_their_curves() {
    let (bar, sweep) = revolution(20.0);
    let svg = Diagrams::new()
        .title("A revolution")
        .render(&bar, &sweep)
        .unwrap();
    assert_eq!(check_legends(&svg), Ok(2));
}

#[test]
fn a_revolution_is_drawn_over_one_period() {
    let (bar, sweep) = revolution(20.0);
    let svg = Diagrams::new().render(&bar, &sweep).unwrap();
    let doc = Document::parse(&svg).unwrap();
    // The abscissa's tick labels (centred under the axis).
    let ticks: Vec<f64> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "text" && attribute(*n, "text-anchor") == "middle")
        .filter_map(|n| content(n).parse().ok())
        .collect();
    let (low, high) = ticks
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    assert!(
        low == 0.0 && (300.0..=360.0).contains(&high),
        "ticks {ticks:?}"
    );
    // Each curve spans the whole axis, in one piece.
    let picture = Picture::of(&doc);
    let panel = picture.panels()[0];
    let curve = picture
        .lines
        .iter()
        .find(|l| l.colour().0 == "#0072B2" && l.points.len() > 100)
        .unwrap();
    let first = curve.points[0].0;
    let last = curve.points[curve.points.len() - 1].0;
    assert!((first - panel[0]).abs() <= 2.0 && (last - panel[2]).abs() <= 2.0);
}

#[test]
fn names_are_drawn_with_their_subscripts() {
    let svg = Chart::new("Subscripts", "φ [°]")
        .panel(
            Panel::new("J_II [kg·m²]")
                .line("J_II(φ)", wave(0.0, 1.0))
                .dashed("ω_1", wave(1.0, 1.0)),
        )
        .render()
        .unwrap();
    let doc = Document::parse(&svg).unwrap();
    let texts: Vec<String> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "text")
        .map(content)
        .collect();
    assert!(texts.iter().any(|t| t == "JII(φ)"), "{texts:?}");
    assert!(texts.iter().any(|t| t == "ω₁"), "{texts:?}");
    assert!(!svg.contains("J_II"));
    let lowered = doc
        .descendants()
        .find(|n| n.tag_name().name() == "tspan" && n.text() == Some("II"))
        .expect("II in a tspan");
    assert!(number(lowered, "dy") > 0.0);
}

#[test]
fn stability_charts_have_one_legend_matching_their_curves() {
    use study::{Case, run};
    let (limit, branch) = (run(Case::Limit), run(Case::Branch));
    let svg = charts::error_chart(Case::Limit, &limit).unwrap();
    // Five methods, the accuracy target and the shading: once.
    assert_eq!(check_legends(&svg), Ok(7));
    assert!(svg.contains("Error::Singular") && svg.contains("Options::accuracy = 1e-6"));
    assert_eq!(
        check_legends(&charts::error_chart(Case::Branch, &branch).unwrap()),
        Ok(7)
    );
    let svg = charts::iterations_chart(&limit, &branch).unwrap();
    assert_eq!(check_legends(&svg), Ok(4));
    let svg = charts::methods_chart(&study::methods_near_limit()).unwrap();
    assert_eq!(check_legends(&svg), Ok(5));
}

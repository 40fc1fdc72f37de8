//! Sheets: pictures side by side under one title, each nested whole at
//! its own size, and text that prints at 7 pt or more.

use crate::overlays::{DESIGN, design_scene, keep_for_a_look, turn};
use crate::scenes::{by_id, number, parse};
use linkage::draw::diagrams::Diagrams;
use linkage::draw::scene::{Scene, SceneError, Sheet};
use linkage::mechanisms::CouplerFourBar;
use linkage::prelude::*;
use std::f64::consts::TAU;

/// Four designs, each drawn 400 px wide: two to a row print legibly.
fn four_designs() -> Vec<String> {
    [(30.0, 18.0), (25.0, 0.0), (10.0, 25.0), (40.0, -10.0)]
        .iter()
        .enumerate()
        .map(|(k, &(px, py))| {
            let model = CouplerFourBar { px, py, ..DESIGN };
            let cycle = turn(&model, 180);
            design_scene(&cycle)
                .width(400.0)
                .title(&format!("Design {}", k + 1))
                .subtitle(&format!("coupler point at ({px}, {py}) mm"))
                .render(&cycle[0], &cycle)
                .unwrap()
        })
        .collect()
}

#[test]
fn a_sheet_nests_its_pictures_in_a_grid_at_their_own_size() {
    let pictures = four_designs();
    let sheet = pictures
        .iter()
        .fold(
            Sheet::new("Four designs through the same five targets").columns(2),
            |sheet, svg| sheet.picture(svg.as_str()),
        )
        .subtitle("each at θ2 = 0 with three other poses faint")
        .render()
        .unwrap();
    keep_for_a_look("sheet.svg", &sheet);
    let doc = parse(&sheet);
    let root = doc.root_element();
    let nested: Vec<_> = root.children().filter(|n| n.has_tag_name("svg")).collect();
    assert_eq!(nested.len(), 4);
    // The pictures' own sizes.
    let sizes: Vec<(f64, f64)> = pictures
        .iter()
        .map(|svg| {
            let doc = parse(svg);
            let r = doc.root_element();
            (number(r, "width"), number(r, "height"))
        })
        .collect();
    // Two columns of 400 px with 8 px round and between them.
    assert_eq!(number(root, "width"), 8.0 + 400.0 + 8.0 + 400.0 + 8.0);
    let row_heights = [sizes[0].1.max(sizes[1].1), sizes[2].1.max(sizes[3].1)];
    let top = number(nested[0], "y");
    assert!(top > 40.0, "under the heading");
    for (k, picture) in nested.iter().enumerate() {
        let (row, column) = (k / 2, k % 2);
        assert_eq!(
            picture.attribute("data-picture"),
            Some(k.to_string().as_str())
        );
        assert_eq!(number(*picture, "x"), 8.0 + 408.0 * column as f64);
        let y = top + row as f64 * (row_heights[0] + 8.0);
        assert!(
            (number(*picture, "y") - y).abs() <= 0.01,
            "picture {k} at y {y}"
        );
        // Not scaled: its viewport is its own size, its view box its own.
        assert_eq!(
            (number(*picture, "width"), number(*picture, "height")),
            sizes[k]
        );
        assert_eq!(
            picture.attribute("viewBox").unwrap(),
            format!("0 0 {} {}", sizes[k].0, sizes[k].1)
        );
        // Its whole content, ids prefixed: the coupler point where the
        // picture alone has it.
        let alone = parse(&pictures[k]);
        let (here, there) = (
            by_id(&doc, &format!("p{k}-point-P")),
            by_id(&alone, "point-P"),
        );
        assert_eq!(here.attribute("cx"), there.attribute("cx"));
        assert!(here.ancestors().any(|a| a == *picture));
        let count = |n: roxmltree::Node| n.descendants().filter(|d| d.is_element()).count();
        assert_eq!(count(*picture), count(alone.root_element()));
    }
    let mut ids: Vec<&str> = doc
        .descendants()
        .filter_map(|n| n.attribute("id"))
        .collect();
    let all = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), all, "ids unique across the sheet");
    let title = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("title"))
        .unwrap();
    assert!(
        title
            .ancestors()
            .all(|a| !a.has_tag_name("svg") || a == root)
    );
    assert_eq!(
        title.text().unwrap().trim(),
        "Four designs through the same five targets"
    );
}

#[test]
fn a_sheet_keeps_its_text_at_7_pt_printed_16_cm_wide() {
    let cycle = turn(&DESIGN, 72);
    let wide = design_scene(&cycle).render(&cycle[0], &cycle).unwrap();
    // Two pictures 720 px wide: 13-px text on a sheet 1464 px wide prints
    // at 13 × 453.5 / 1464 ≈ 4 pt.
    let err = Sheet::new("Too wide")
        .picture(wide.as_str())
        .picture(wide.as_str())
        .render()
        .unwrap_err();
    let SceneError::TextTooSmall {
        picture,
        font,
        width,
        printed,
        least,
    } = err
    else {
        panic!("{err}");
    };
    assert_eq!((picture, font, width, least), (Some(0), 13.0, 1464.0, 7.0));
    assert!((printed - 13.0 * 453.54 / 1464.0).abs() < 0.01);
    // Two side by side: up to 409 px each (a sheet 842 px wide, 7.003
    // pt), not 410 (844 px, 6.99 pt).
    let side_by_side = |width: f64| {
        let svg = design_scene(&cycle)
            .width(width)
            .render(&cycle[0], &cycle)
            .unwrap();
        Sheet::new("Side by side")
            .picture(svg.as_str())
            .picture(svg.as_str())
            .render()
    };
    assert!(side_by_side(409.0).is_ok());
    assert!(matches!(
        side_by_side(410.0),
        Err(SceneError::TextTooSmall {
            picture: Some(0),
            ..
        })
    ));
    // Subscripts (a tspan of its own size) may print down to 5.5 pt: on a
    // sheet 916 px wide, 11 px prints at 5.45 pt, 12 px at 5.94 pt.
    let subscripted = |size: f64| {
        let chart = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="900" height="300"><text font-size="15">θ<tspan dy="3" font-size="{size}">2</tspan></text></svg>"#
        );
        Sheet::new("").picture(chart).render()
    };
    assert!(subscripted(12.0).is_ok());
    assert!(matches!(
        subscripted(11.0),
        Err(SceneError::TextTooSmall {
            picture: Some(0),
            least: 5.5,
            ..
        })
    ));
    // One alone prints at 8 pt.
    assert!(Sheet::new("One").picture(wide.as_str()).render().is_ok());
    // A sheet with no title has none.
    let untitled = Sheet::new("").picture(wide.as_str()).render().unwrap();
    let doc = parse(&untitled);
    let root = doc.root_element();
    assert!(root.children().all(|n| !n.has_tag_name("text")));
    assert_eq!(
        number(
            root.children().find(|n| n.has_tag_name("svg")).unwrap(),
            "y"
        ),
        8.0
    );
}

#[test]
fn bad_sheets_are_typed_errors() {
    let cycle = turn(&DESIGN, 36);
    let picture = Scene::new()
        .link(["B", "C"])
        .width(300.0)
        .render(&cycle[0], &[])
        .unwrap();
    assert_eq!(
        Sheet::new("none").render().unwrap_err(),
        SceneError::EmptySheet
    );
    assert_eq!(
        Sheet::new("no columns")
            .columns(0)
            .picture(picture.as_str())
            .render()
            .unwrap_err(),
        SceneError::BadSetting {
            what: "the number of a sheet's columns",
            must: "at least 1",
            value: 0.0,
        }
    );
    for bad in [
        "",
        "<svg width=\"10\" height=\"10\">",
        "<svg width=\"50%\" height=\"10\"></svg>",
    ] {
        assert_eq!(
            Sheet::new("bad")
                .picture(picture.as_str())
                .picture(bad)
                .render()
                .unwrap_err(),
            SceneError::NotAPicture { index: 1 },
            "{bad}"
        );
    }
}

#[test]
fn a_chart_the_library_draws_nests_whole_in_a_sheet() {
    let sweep = DESIGN
        .sweep(
            &vector![1.3, -0.8],
            &Drive::Line {
                from: vector![0.0],
                to: vector![TAU],
                steps: 90,
            },
            &SweepOptions::default(),
        )
        .unwrap();
    let chart = Diagrams::new().render(&DESIGN, &sweep).unwrap();
    // The library's charts are fit to print, so one nests whole.
    let sheet = Sheet::new("A chart")
        .columns(1)
        .picture(chart.as_str())
        .render()
        .unwrap();
    let doc = parse(&sheet);
    let nested = doc
        .root_element()
        .children()
        .find(|n| n.has_tag_name("svg"))
        .unwrap();
    let alone = parse(&chart);
    assert_eq!(
        nested.attribute("width"),
        alone.root_element().attribute("width")
    );
    // Its references (clip paths) lead to its own elements, under
    // their prefixed ids.
    let ids: Vec<&str> = doc
        .descendants()
        .filter_map(|n| n.attribute("id"))
        .collect();
    let references: Vec<&str> = sheet
        .match_indices("url(#")
        .map(|(at, _)| {
            let rest = &sheet[at + 5..];
            &rest[..rest.find(')').unwrap()]
        })
        .collect();
    assert_eq!(references.len(), chart.matches("url(#").count());
    for reference in references {
        assert!(reference.starts_with("p0-"), "{reference}");
        assert!(ids.contains(&reference), "{reference} leads nowhere");
    }
}

//! Every committed figure is fit to print: printed 16 cm wide, no text
//! under 7 pt (subscripts under 5.5 pt), one font family, and curves
//! written to a hundredth of a pixel (not rounded to whole pixels, which
//! draws them stair-stepped).

use roxmltree::Document;
use std::path::{Path, PathBuf};

/// A column of 16 cm, in points.
const COLUMN: f64 = 16.0 / 2.54 * 72.0;

fn figures(folder: &Path, found: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(folder).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            figures(&path, found);
        } else if path.extension().is_some_and(|e| e == "svg") {
            found.push(path);
        }
    }
}

/// The committed figures: everything under docs/figures.
fn committed() -> Vec<PathBuf> {
    let mut found = Vec::new();
    figures(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures"),
        &mut found,
    );
    found.sort();
    found
}

/// What is wrong with `svg` in print, if anything.
fn print_faults(svg: &str) -> Vec<String> {
    let doc = Document::parse(svg).expect("well-formed SVG");
    let root = doc.root_element();
    let width: f64 = root
        .attribute("viewBox")
        .and_then(|v| v.split_whitespace().nth(2))
        .or(root.attribute("width"))
        .and_then(|w| w.parse().ok())
        .expect("a width");
    let printed = |size: f64| size * COLUMN / width;
    let mut faults = Vec::new();
    let mut families = Vec::new();
    for node in doc.descendants().filter(|n| n.is_element()) {
        if let Some(family) = node.attribute("font-family")
            && !families.contains(&family)
        {
            families.push(family);
        }
        let Some(size) = node
            .attribute("font-size")
            .and_then(|s| s.parse::<f64>().ok())
        else {
            continue;
        };
        let least = if node.tag_name().name() == "tspan" {
            5.5
        } else {
            7.0
        };
        if printed(size) < least - 1e-9 {
            let text: String = node.descendants().filter_map(|n| n.text()).collect();
            faults.push(format!("{:.1} pt < {least} pt: {text:?}", printed(size)));
        }
    }
    if families.len() > 1 {
        faults.push(format!("several font families: {families:?}"));
    }
    // Curves: the coordinates of every polyline and path of ten points or
    // more, of which no more than a quarter may be whole pixels.
    let (mut whole, mut all) = (0usize, 0usize);
    for node in doc.descendants().filter(|n| n.is_element()) {
        let data = match node.tag_name().name() {
            "polyline" | "polygon" => node.attribute("points"),
            "path" => node.attribute("d"),
            _ => None,
        };
        let Some(data) = data else { continue };
        let numbers: Vec<&str> = data
            .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
            .filter(|s| !s.is_empty() && s.parse::<f64>().is_ok())
            .collect();
        if numbers.len() >= 20 {
            all += numbers.len();
            whole += numbers.iter().filter(|s| !s.contains('.')).count();
        }
    }
    if all > 0 && whole * 4 > all {
        faults.push(format!(
            "{whole} of {all} curve coordinates are whole pixels"
        ));
    }
    faults
}

#[test]
fn every_committed_figure_is_fit_to_print() {
    let figures = committed();
    assert!(figures.len() >= 20, "{figures:?}");
    let mut faults = Vec::new();
    let mut families: Vec<String> = Vec::new();
    for path in &figures {
        let svg = std::fs::read_to_string(path).unwrap();
        for fault in print_faults(&svg) {
            faults.push(format!("{}: {fault}", path.display()));
        }
        let doc = Document::parse(&svg).unwrap();
        for family in doc.descendants().filter_map(|n| n.attribute("font-family")) {
            if !families.iter().any(|f| f == family) {
                families.push(family.to_string());
            }
        }
    }
    if families.len() > 1 {
        faults.push(format!(
            "the figures use several font families: {families:?}"
        ));
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

#[test]
fn the_print_check_finds_small_text_and_whole_pixel_curves() {
    let points: Vec<String> = (0..30).map(|i| format!("{i},{}", i * 2)).collect();
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="1200" height="300" viewBox="0 0 1200 300">
  <text x="1" y="2" font-size="12" font-family="A">small</text>
  <text x="1" y="2" font-size="30" font-family="B">big</text>
  <polyline points="{}"/>
</svg>"#,
        points.join(" ")
    );
    let faults = print_faults(&svg);
    assert_eq!(faults.len(), 3, "{faults:?}");
    assert!(faults[0].contains("4.5 pt < 7 pt"));
    assert!(faults[1].contains("font families"));
    assert!(faults[2].contains("60 of 60"));
}

//! The 50-digit reference (tests/data/shaper_cam_reference.csv) and the
//! course project's printed digits.

use std::collections::HashMap;

/// key → (exact value, the course project's printed text).
pub(crate) fn reference() -> HashMap<String, (f64, Option<String>)> {
    include_str!("../../data/shaper_cam_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("key,"))
        .map(|l| {
            let cols: Vec<&str> = l.split(',').collect();
            let value = cols[1].parse().unwrap_or(f64::NAN);
            let printed = (!cols[2].is_empty()).then(|| cols[2].to_string());
            (cols[0].to_string(), (value, printed))
        })
        .collect()
}

/// The printed digits of a value: "102.041" → (102.041, 0.0005).
pub(crate) fn printed(text: &str) -> (f64, f64) {
    let text = text.trim();
    let (mantissa, exponent) = match text.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    let value: f64 = text.parse().unwrap();
    (value, 0.5 * 10f64.powi(exponent - decimals))
}

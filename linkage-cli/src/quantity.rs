//! A quantity written on the command line: a coordinate (`theta4`), a
//! point's component (`C.x`), each with `'` for its velocity and `''` for
//! its acceleration (`C.x''`), or a point's deviation normal to its path
//! (`C.path`).

use linkage::watch::{Axis, Of};

/// What a quantity's text names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Quantity<'a> {
    Coordinate(&'a str, Of),
    Point(&'a str, Axis, Of),
    Path(&'a str),
}

/// Reads a quantity.
pub fn parse(text: &str) -> Result<Quantity<'_>, String> {
    let (name, of) = if let Some(name) = text.strip_suffix("''") {
        (name, Of::Acceleration)
    } else if let Some(name) = text.strip_suffix('\'') {
        (name, Of::Velocity)
    } else {
        (text, Of::Position)
    };
    match name.rsplit_once('.') {
        Some((point, "x")) => Ok(Quantity::Point(point, Axis::X, of)),
        Some((point, "y")) => Ok(Quantity::Point(point, Axis::Y, of)),
        Some((point, "path")) if of == Of::Position => Ok(Quantity::Path(point)),
        Some((_, other)) => Err(format!(
            "`{text}`: a point has the components `.x` and `.y` (and `.path`, its deviation \
             normal to its path), not `.{other}`{}",
            if other == "path" { " with primes" } else { "" }
        )),
        None => Ok(Quantity::Coordinate(name, of)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_reads() {
        assert_eq!(
            parse("theta4"),
            Ok(Quantity::Coordinate("theta4", Of::Position))
        );
        assert_eq!(
            parse("C.x'"),
            Ok(Quantity::Point("C", Axis::X, Of::Velocity))
        );
        assert_eq!(
            parse("C.y''"),
            Ok(Quantity::Point("C", Axis::Y, Of::Acceleration))
        );
        assert_eq!(parse("C.path"), Ok(Quantity::Path("C")));
        assert!(parse("C.z").unwrap_err().contains("not `.z`"));
        assert!(parse("C.path'").is_err());
    }
}

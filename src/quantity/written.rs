//! A quantity written as text — on the command line, from Python: a
//! coordinate (`theta4`), a point's component (`C.x`), each with `'` for
//! its velocity and `''` for its acceleration (`C.x''`), or a point's
//! deviation normal to its path (`C.path`).

use super::{Axis, Of};

/// What a quantity's text names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Written<'a> {
    Coordinate(&'a str, Of),
    Point(&'a str, Axis, Of),
    Path(&'a str),
}

/// Reads a quantity: the mistake in words if it is not one.
///
/// ```
/// use linkage::quantity::{Axis, Of, Written, written};
///
/// assert_eq!(written("C.x'"), Ok(Written::Point("C", Axis::X, Of::Velocity)));
/// ```
pub fn written(text: &str) -> Result<Written<'_>, String> {
    let (name, of) = if let Some(name) = text.strip_suffix("''") {
        (name, Of::Acceleration)
    } else if let Some(name) = text.strip_suffix('\'') {
        (name, Of::Velocity)
    } else {
        (text, Of::Position)
    };
    match name.rsplit_once('.') {
        Some((point, "x")) => Ok(Written::Point(point, Axis::X, of)),
        Some((point, "y")) => Ok(Written::Point(point, Axis::Y, of)),
        Some((point, "path")) if of == Of::Position => Ok(Written::Path(point)),
        Some((_, other)) => Err(format!(
            "`{text}`: a point has the components `.x` and `.y` (and `.path`, its deviation \
             normal to its path), not `.{other}`{}",
            if other == "path" { " with primes" } else { "" }
        )),
        None => Ok(Written::Coordinate(name, of)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_reads() {
        assert_eq!(
            written("theta4"),
            Ok(Written::Coordinate("theta4", Of::Position))
        );
        assert_eq!(
            written("C.x'"),
            Ok(Written::Point("C", Axis::X, Of::Velocity))
        );
        assert_eq!(
            written("C.y''"),
            Ok(Written::Point("C", Axis::Y, Of::Acceleration))
        );
        assert_eq!(written("C.path"), Ok(Written::Path("C")));
        assert!(written("C.z").unwrap_err().contains("not `.z`"));
        assert!(written("C.path'").is_err());
    }
}

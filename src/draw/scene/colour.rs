//! Colours given to a scene: checked to be ones SVG understands before
//! they are written into the picture.

use super::SceneError;

/// `colour` if SVG understands it — `#rgb`, `#rrggbb` (with or without
/// alpha), a colour's name such as `teal`, or `rgb(…)`/`rgba(…)`/`hsl(…)`/
/// `hsla(…)` of numbers — else the error naming `what` it colours.
pub(super) fn check_colour(what: &'static str, colour: &str) -> Result<(), SceneError> {
    if is_colour(colour) {
        Ok(())
    } else {
        Err(SceneError::BadColour {
            what,
            colour: colour.into(),
        })
    }
}

fn is_colour(colour: &str) -> bool {
    if let Some(hex) = colour.strip_prefix('#') {
        return matches!(hex.len(), 3 | 4 | 6 | 8) && hex.chars().all(|c| c.is_ascii_hexdigit());
    }
    if !colour.is_empty() && colour.chars().all(|c| c.is_ascii_alphabetic()) {
        return true;
    }
    ["rgb(", "rgba(", "hsl(", "hsla("].iter().any(|function| {
        colour
            .strip_prefix(function)
            .and_then(|rest| rest.strip_suffix(')'))
            .is_some_and(|arguments| {
                !arguments.trim().is_empty()
                    && arguments
                        .chars()
                        .all(|c| c.is_ascii_digit() || " ,.%/-".contains(c))
            })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_svg_understands() {
        for good in [
            "#c00",
            "#d55e00",
            "#d55e0080",
            "teal",
            "rgb(10, 20, 30)",
            "hsl(200 50% 40%)",
        ] {
            assert!(is_colour(good), "{good}");
        }
        for bad in [
            "",
            "#12",
            "#ggg",
            "red;",
            "rgb(1,2,3",
            "url(#x)",
            "light blue",
            "rgb()",
        ] {
            assert!(!is_colour(bad), "{bad}");
        }
    }
}

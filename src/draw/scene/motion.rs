//! The frames of an animation, and SMIL `<animate>` elements through them.

use super::layout::Placed;
use crate::draw::svg::{Writer, fmt};

/// The frames of an animation and its period.
pub(super) struct Motion<'a> {
    pub(super) frames: &'a [Placed],
    pub(super) seconds: f64,
}

impl Motion<'_> {
    /// An `<animate>` of `attribute` through the frames' values.
    pub(super) fn animate(
        &self,
        w: &mut Writer,
        attribute: &str,
        value: impl Fn(&Placed) -> String,
    ) {
        let values: Vec<String> = self.frames.iter().map(value).collect();
        animate_values(w, attribute, &values.join(";"), self.seconds);
    }
}

pub(super) fn animate_values(w: &mut Writer, attribute: &str, values: &str, seconds: f64) {
    w.element(
        "animate",
        &[
            ("attributeName", attribute),
            ("dur", &format!("{}s", fmt(seconds))),
            ("repeatCount", "indefinite"),
            ("calcMode", "linear"),
            ("values", values),
        ],
    );
}

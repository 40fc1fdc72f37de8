//! Pictures, as self-contained SVG: a mechanism's poses and animations
//! ([`scene`]), motion diagrams, charts and hodographs ([`diagrams`]); the
//! cam's drawing ([`crate::cam::Cam::drawing`]) uses the same writer. With
//! the `draw` feature (on by default).

pub mod diagrams;
pub(crate) mod palette;
pub mod scene;
pub(crate) mod svg;

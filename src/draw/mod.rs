//! Pictures, as self-contained SVG: a mechanism's poses and animations
//! ([`scene`]), charts fit to print ([`chart`]), motion diagrams and
//! hodographs drawn with them ([`diagrams`]); the
//! cam's drawing ([`crate::cam::Cam::drawing`]) uses the same writer. With
//! the `draw` feature (on by default).

pub mod chart;
pub mod diagrams;
pub(crate) mod palette;
pub mod scene;
pub(crate) mod svg;

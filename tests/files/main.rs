//! The library of mechanism files, `mechanisms/`: every file loads, its
//! equations are its compiled twin's token for token, its parameters the
//! twin's to the bit, its drive runs from its assembly over the whole range
//! on the twin, and its drawing draws.

#[path = "../../examples/shaper/machine.rs"]
mod machine;
#[path = "../models/mod.rs"]
mod models;
#[path = "../common/twins.rs"]
mod twins;

/// Where links pinned to the frame come to rest.
mod dead_centres;
/// The code `linkage expand --expanded` prints, compiled.
mod expanded;
mod library;
/// No string of a file is a path.
mod paths;

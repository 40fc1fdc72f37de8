//! `linkage expand --expanded`: the code the tool prints for a file (the
//! quick return's, under `expanded/`, which the tool's tests hold equal to
//! what it prints now), compiled here, is the file's mechanism — its
//! parameters, its drive from its assembly, and every kernel and
//! sensitivity at poses in motion, to the bit against the file read at run
//! time. (The four-bar's expansion is the generator's snapshot,
//! `linkage-symbolic/tests/snapshots/`.)

mod quick_return {
    include!("expanded/quick_return.rs");
}

use crate::library::twin;

#[test]
fn the_expanded_code_is_the_files_mechanism() {
    twin("quick_return.toml", &quick_return::QuickReturn::FILE);
}

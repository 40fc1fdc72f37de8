//! `linkage expand --expanded`: the code the tool prints for a file (the
//! files under `expanded/`, which the tool's tests hold equal to what it
//! prints now), compiled here, is the file's mechanism — its parameters,
//! its drive from its assembly, and every kernel and sensitivity at poses
//! in motion, to the bit against the file read at run time.

mod four_bar {
    include!("expanded/four_bar.rs");
}
mod quick_return {
    include!("expanded/quick_return.rs");
}

use crate::library::twin;

#[test]
fn the_expanded_code_is_the_files_mechanism() {
    twin("four_bar.toml", &four_bar::FourBar::FILE);
    twin("quick_return.toml", &quick_return::QuickReturn::FILE);
}

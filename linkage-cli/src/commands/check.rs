//! `linkage check FILE`: every mistake in the file, or what it describes.

use crate::cli::Input;
use crate::failure::Failure;
use crate::load::load;

pub fn run(input: &Input) -> Result<(), Failure> {
    let loaded = load(&input.file)?;
    let m = &loaded.mechanism;
    let agree = match m.methods_agree() {
        Some(true) => "the two acceleration methods expand to the same polynomial",
        Some(false) => "the two acceleration methods do NOT expand to the same polynomial",
        None => "the two acceleration methods are too large to expand and compare",
    };
    let text = format!(
        "{}: {} is a mechanism of m = {} dependent coordinates [{}], f = {} driving [{}], {} named points [{}] and {} parameters [{}]; {agree}\n",
        loaded.shown,
        m.name(),
        m.m(),
        m.u_names().join(", "),
        m.f(),
        m.v_names().join(", "),
        m.point_names().len(),
        m.point_names().join(", "),
        m.parameter_names().len(),
        m.parameter_names().join(", "),
    );
    super::emit(input.output.as_deref(), text.as_bytes())
}

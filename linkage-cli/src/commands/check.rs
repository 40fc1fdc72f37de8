//! `linkage check FILE`: every mistake in the file, or what it describes.

use crate::cli::Input;
use crate::failure::Failure;
use crate::load::load;

pub fn run(input: &Input) -> Result<(), Failure> {
    let loaded = load(&input.file)?;
    let m = loaded.mechanism();
    let agree = match m.methods_agree() {
        Some(true) => "the two acceleration methods expand to the same polynomial",
        Some(false) => "the two acceleration methods do NOT expand to the same polynomial",
        None => "the two acceleration methods are too large to expand and compare",
    };
    let listed = |names: &[&str], one: &str, many: &str| {
        let noun = if names.len() == 1 { one } else { many };
        format!("{} {noun} [{}]", names.len(), names.join(", "))
    };
    let u_names = m.u_names();
    let structure = m
        .blocks()
        .describe(|k| u_names.get(k).map_or("?", |n| n).to_owned());
    let text = format!(
        "{}: {} is a mechanism of m = {} dependent coordinates [{}], f = {} driving [{}], {} and {}; {agree}\n{structure}\n",
        loaded.shown(),
        m.name(),
        m.m(),
        m.u_names().join(", "),
        m.f(),
        m.v_names().join(", "),
        listed(m.point_names(), "named point", "named points"),
        listed(m.parameter_names(), "parameter", "parameters"),
    );
    super::emit(input.output.as_deref(), text.as_bytes())
}

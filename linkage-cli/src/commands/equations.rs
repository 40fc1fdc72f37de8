//! `linkage equations FILE`: the mechanism file a topology file generates.

use crate::cli::Input;
use crate::failure::Failure;
use crate::load::{generated, text_of};
use linkage::file::is_topology;

pub fn run(input: &Input) -> Result<(), Failure> {
    let (shown, text) = text_of(&input.file)?;
    if !is_topology(&text) {
        return Err(Failure::Malformed(format!(
            "{shown} is not a topology file (it has no [joints], or it has equations): `equations` writes the equations of joints and links"
        )));
    }
    let mechanism = generated(&shown, &text)?;
    super::emit(input.output.as_deref(), mechanism.as_bytes())
}

//! `linkage import pyslvs|pylinkage FILE`: another tool's mechanism as a
//! topology file.

use crate::cli::{ImportArgs, Peer};
use crate::failure::Failure;
use crate::load::text_of;
use linkage::topology::pylinkage::from_pylinkage;
use linkage::topology::pyslvs::from_pyslvs;

pub fn run(args: &ImportArgs) -> Result<(), Failure> {
    let (shown, text) = text_of(&args.input.file)?;
    let topology = match args.from {
        Peer::Pyslvs => from_pyslvs(&args.name, text.trim(), &args.inputs)
            .map_err(|e| Failure::Malformed(format!("{shown}: {e}")))?,
        Peer::Pylinkage => {
            if !args.inputs.is_empty() {
                return Err(Failure::Malformed(
                    "`--input` is pyslvs's: pylinkage's JSON names its drivers".to_owned(),
                ));
            }
            from_pylinkage(&text)
                .map_err(|e| Failure::Malformed(format!("{shown}: {e}")))?
                .0
        }
    };
    // What the topology cannot be, said now rather than by the next command.
    if let Err(errors) = topology.check() {
        return Err(Failure::Malformed(format!("{shown}: {errors}")));
    }
    super::emit(
        args.input.output.as_deref(),
        topology.topology_text().as_bytes(),
    )
}

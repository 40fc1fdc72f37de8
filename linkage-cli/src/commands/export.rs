//! `linkage export pyslvs|pylinkage FILE`: a topology file in another
//! tool's format.

use crate::cli::{ExportArgs, Peer};
use crate::failure::Failure;
use crate::load::{report, text_of};
use linkage::file::TopologyFile;
use linkage::mechanism::Diagnostics;
use linkage::topology::pylinkage::to_pylinkage;
use linkage::topology::pyslvs::to_pyslvs;

pub fn run(args: &ExportArgs) -> Result<(), Failure> {
    let (shown, text) = text_of(&args.input.file)?;
    let file = TopologyFile::parse(&text).map_err(|errors| {
        report(&Diagnostics::from(&errors), &shown, &text);
        Failure::Mistakes
    })?;
    let refused = |why: String| Failure::Malformed(format!("{shown}: {why}"));
    let written = match args.to {
        Peer::Pyslvs => {
            let (expression, inputs) =
                to_pyslvs(&file.topology).map_err(|e| refused(e.to_string()))?;
            let inputs: Vec<String> = inputs.iter().map(|(b, d)| format!("({b}, {d})")).collect();
            format!("{expression}\n# inputs: {}\n", inputs.join(", "))
        }
        Peer::Pylinkage => {
            to_pylinkage(&file.topology, &[]).map_err(|e| refused(e.to_string()))? + "\n"
        }
    };
    super::emit(args.input.output.as_deref(), written.as_bytes())
}

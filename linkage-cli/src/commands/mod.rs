//! The subcommands, one per file, and where their results go.

pub mod analyze;
pub mod check;
pub mod draw;
pub mod dxf;
pub mod equations;
pub mod expand;
pub mod export;
pub mod extremes;
pub mod import;
pub mod sensitivities;
pub mod serve;
pub mod sweep;
pub mod synthesize;
pub mod tolerance;

use crate::failure::Failure;
use std::io::Write;
use std::path::Path;

/// Writes `bytes` to the file `output`, or to standard output.
pub fn emit(output: Option<&Path>, bytes: &[u8]) -> Result<(), Failure> {
    match output {
        Some(path) => std::fs::write(path, bytes)
            .map_err(|e| Failure::Io(format!("cannot write {}: {e}", path.display()))),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)
                .and_then(|()| out.flush())
                .or_else(|e| match e.kind() {
                    // A reader that stopped reading (`| head`) is not a failure.
                    std::io::ErrorKind::BrokenPipe => Ok(()),
                    _ => Err(e),
                })
                .map_err(|e| Failure::Io(format!("cannot write to standard output: {e}")))
        }
    }
}

//! Where an example writes its pictures and tables: `out/<example>/` in the
//! repository, which git ignores, or the folder named by the environment
//! variable `LINKAGE_OUT`. `docs/refresh.sh` points it at `docs/figures/…`
//! and `benches/results/` to refresh the committed figures and tables.

use std::path::{Path, PathBuf};

/// The output folder of the example `name`, created if missing.
pub fn folder(name: &str) -> std::io::Result<PathBuf> {
    let folder = match std::env::var_os("LINKAGE_OUT") {
        Some(folder) => PathBuf::from(folder),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("out").join(name),
    };
    std::fs::create_dir_all(&folder)?;
    Ok(folder)
}

//! `linkage expand FILE`: the Rust that promotes the file to a compiled
//! mechanism — its equations in `#[linkage::linkage(...)]` on a struct of
//! its parameters, and a constant with the file's values (each written so
//! that it reads back to the same f64). The attribute then generates, at
//! compile time, the code the run-time mechanism evaluates as tapes.

use crate::cli::Input;
use crate::failure::Failure;
use crate::load::load;

pub fn run(input: &Input) -> Result<(), Failure> {
    let loaded = load(&input.file)?;
    let file = &loaded.file;
    let name = &file.name.text;
    let mut rust = String::new();
    let title = file.title.as_deref().unwrap_or(name);
    // The title and the path are text of the file's, inside comments:
    // each of their lines its own comment line, so that no line of them
    // is ever code.
    for line in title.lines() {
        rust.push_str(&format!("/// {}\n", line.replace('\r', " ")));
    }
    let shown = loaded.shown.replace(['\n', '\r'], " ");
    rust.push_str(&format!(
        "///\n/// Promoted from the mechanism file `{shown}`"
    ));
    rust.push_str(&format!(" (lengths in {}).\n", file.length_unit));
    rust.push_str("#[linkage::linkage(\n");
    for line in file.equations.text.trim_matches('\n').lines() {
        if line.trim().is_empty() {
            rust.push('\n');
        } else {
            rust.push_str(&format!("    {line}\n"));
        }
    }
    rust.push_str(")]\n#[derive(Clone, Copy, Debug, PartialEq)]\n");
    rust.push_str(&format!("pub struct {name} {{\n"));
    for p in &file.parameters {
        rust.push_str(&format!("    pub {}: f64,\n", p.name.text));
    }
    rust.push_str("}\n\n");
    rust.push_str(&format!(
        "impl {name} {{\n    /// The values of the mechanism file.\n"
    ));
    rust.push_str(&format!("    pub const FILE: {name} = {name} {{\n"));
    for p in &file.parameters {
        rust.push_str(&format!(
            "        {}: {:?},\n",
            p.name.text, p.quantity.value
        ));
    }
    rust.push_str("    };\n}\n");
    super::emit(input.output.as_deref(), rust.as_bytes())
}

//! `linkage expand FILE`: the Rust that promotes the file to a compiled
//! mechanism — its equations in `#[linkage::linkage(...)]` on a struct of
//! its parameters, and a constant with the file's values (each written so
//! that it reads back to the same f64). The attribute then generates, at
//! compile time, the code the run-time mechanism evaluates as tapes. With
//! `--expanded`, that generated code itself: the attribute's own generator
//! (`linkage_symbolic::generate`) run on the same struct, formatted.

use crate::cli::ExpandArgs;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use std::str::FromStr;

pub fn run(args: &ExpandArgs) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let rust = match args.expanded {
        false => format!("{}{}", attributed(&loaded), values(&loaded)),
        true => expanded(&loaded)?,
    };
    super::emit(args.input.output.as_deref(), rust.as_bytes())
}

/// The struct with its documentation, the attribute on it.
fn attributed(loaded: &Loaded) -> String {
    format!(
        "{}#[linkage::linkage(\n{})]\n{}",
        documentation(loaded),
        attribute(loaded),
        structure(loaded)
    )
}

/// The struct's documentation: the file's title and where it comes from.
fn documentation(loaded: &Loaded) -> String {
    let file = loaded.file();
    let mut rust = String::new();
    let title = file.title.as_deref().unwrap_or(&file.name.text);
    // The title and the path are text of the file's, inside comments:
    // each of their lines its own comment line, so that no line of them
    // is ever code.
    for line in title.lines() {
        rust.push_str(&format!("/// {}\n", line.replace('\r', " ")));
    }
    let shown = loaded.shown().replace(['\n', '\r'], " ");
    rust.push_str(&format!(
        "///\n/// Promoted from the mechanism file `{shown}` (lengths in {}).\n",
        file.length_unit
    ));
    rust
}

/// The attribute's arguments: the file's equations, indented.
fn attribute(loaded: &Loaded) -> String {
    let mut rust = String::new();
    for line in loaded.file().equations.text.trim_matches('\n').lines() {
        if line.trim().is_empty() {
            rust.push('\n');
        } else {
            rust.push_str(&format!("    {line}\n"));
        }
    }
    rust
}

/// The struct of the parameters, with its derives.
fn structure(loaded: &Loaded) -> String {
    let file = loaded.file();
    let mut rust = String::from("#[derive(Clone, Copy, Debug, PartialEq)]\n");
    rust.push_str(&format!("pub struct {} {{\n", file.name.text));
    for p in &file.parameters {
        rust.push_str(&format!("    pub {}: f64,\n", p.name.text));
    }
    rust.push_str("}\n");
    rust
}

/// The constant with the file's values.
fn values(loaded: &Loaded) -> String {
    let file = loaded.file();
    let name = &file.name.text;
    let mut rust = format!("\nimpl {name} {{\n    /// The values of the mechanism file.\n");
    rust.push_str(&format!("    pub const FILE: {name} = {name} {{\n"));
    for p in &file.parameters {
        rust.push_str(&format!(
            "        {}: {:?},\n",
            p.name.text, p.quantity.value
        ));
    }
    rust.push_str("    };\n}\n");
    rust
}

/// What the attribute generates for the file's struct (the struct, its
/// documentation, and every item the attribute adds), then the constant
/// of its values, formatted.
fn expanded(loaded: &Loaded) -> Result<String, Failure> {
    // The documentation's `///` lines read back as `#[doc = "…"]`.
    let item_text = format!("{}{}", documentation(loaded), structure(loaded));
    let tokens = |text: &str, what: &str| {
        proc_macro2::TokenStream::from_str(text)
            .map_err(|e| Failure::Analysis(format!("the {what} does not read as Rust: {e}")))
    };
    let attr = tokens(&attribute(loaded), "attribute")?;
    let item = tokens(&item_text, "struct")?;
    let mut generated = linkage_symbolic::generate::expand(attr, item);
    generated.extend(tokens(&values(loaded), "constant")?);
    let file: syn::File = syn::parse2(generated)
        .map_err(|e| Failure::Analysis(format!("the generated code does not parse: {e}")))?;
    Ok(prettyplease::unparse(&file))
}

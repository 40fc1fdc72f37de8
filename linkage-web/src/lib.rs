//! linkage in the browser: a mechanism file or topology read at run time
//! by the library's own front end, its analyses run by the library's own
//! code compiled to WebAssembly, for the page in `web/`. Results cross to
//! JavaScript as JSON text; mistakes as JSON too, each with its place in
//! the text (for the editor to underline) and the message the command-line
//! tool writes.

mod design;
mod library;
mod mechanism;

pub use design::WebDesign;
pub use mechanism::WebMechanism;

use linkage::file::{LoadError, Loaded};
use serde_json::{Value, json};
use wasm_bindgen::prelude::*;

/// The library of mechanisms: JSON `[{path, text}, …]`.
#[wasm_bindgen]
pub fn library() -> String {
    let files: Vec<Value> = (library::FILES.iter())
        .map(|(path, text)| json!({ "path": path, "text": text }))
        .collect();
    Value::Array(files).to_string()
}

/// A pyslvs expression (`M[J[R, …], …]`), driven by `inputs` (a JSON list
/// of pairs `[base, drive]` of joint numbers), as a topology file's text.
#[wasm_bindgen(js_name = importPyslvs)]
pub fn import_pyslvs(expression: &str, inputs: &str, name: &str) -> Result<String, JsError> {
    let pairs: Vec<[usize; 2]> = serde_json::from_str::<Value>(inputs)
        .ok()
        .and_then(|v| {
            (v.as_array()?.iter())
                .map(|p| {
                    let p = p.as_array()?;
                    Some([p.first()?.as_u64()? as usize, p.get(1)?.as_u64()? as usize])
                })
                .collect()
        })
        .ok_or_else(|| {
            JsError::new("the inputs are a list of pairs [base, drive] of joint numbers")
        })?;
    let inputs: Vec<(usize, usize)> = pairs.iter().map(|[b, d]| (*b, *d)).collect();
    let topology = linkage::topology::pyslvs::from_pyslvs(name, expression.trim(), &inputs)
        .map_err(|e| JsError::new(&e.to_string()))?;
    Ok(topology.topology_text())
}

/// pylinkage's JSON (`Linkage.to_dict()`), as a topology file's text.
#[wasm_bindgen(js_name = importPylinkage)]
pub fn import_pylinkage(json: &str) -> Result<String, JsError> {
    let (topology, _) = linkage::topology::pylinkage::from_pylinkage(json)
        .map_err(|e| JsError::new(&e.to_string()))?;
    Ok(topology.topology_text())
}

/// A mechanism file's `text` with new values of its parameters (JSON
/// `[[name, value], …]`), each written where the old one stood and read
/// back to the bit; an error for a name its `[parameters]` lacks (a
/// topology file's come from its joints).
#[wasm_bindgen(js_name = withParameters)]
pub fn with_parameters(text: &str, values: &str) -> Result<String, JsError> {
    let values: Vec<(String, f64)> = serde_json::from_str(values)
        .map_err(|_| JsError::new("the values are a list of [name, number]"))?;
    let values: Vec<(&str, f64)> = values.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    linkage::file::with_parameters(text, &values).map_err(|e| JsError::new(&e.to_string()))
}

/// The mistakes of a mechanism file's (or topology's) text, as JSON: `[]`
/// when it makes a mechanism, or `[{message, from, to, rendered}, …]`
/// with `from` and `to` the UTF-16 offsets of its place in `text` (for a
/// text area's selection), and `rendered` the whole report as the tool
/// writes it; a failure that is not located has `from` = `to` = null.
#[wasm_bindgen]
pub fn mistakes(text: &str, name: &str) -> String {
    match Loaded::from_text(name, text) {
        Ok(_) => "[]".to_owned(),
        Err(error) => located(&error, text).to_string(),
    }
}

/// A load error as JSON mistakes located in `text`.
pub(crate) fn located(error: &LoadError, text: &str) -> Value {
    let utf16 = |byte: usize| text.get(..byte).map(|s| s.encode_utf16().count());
    match error {
        LoadError::Mistakes(located) if located.text == text => {
            let rendered = located.render(false);
            let each: Vec<Value> = (located.diagnostics.iter())
                .map(|d| {
                    let range = d.range();
                    json!({
                        "message": d.message(),
                        "from": range.as_ref().and_then(|r| utf16(r.start)),
                        "to": range.as_ref().and_then(|r| utf16(r.end)),
                        "rendered": rendered,
                    })
                })
                .collect();
            Value::Array(each)
        }
        other => {
            json!([{ "message": other.to_string(), "from": null, "to": null, "rendered": other.to_string() }])
        }
    }
}

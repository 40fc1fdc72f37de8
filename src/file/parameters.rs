//! The parameters: every name the equations use besides the coordinates
//! and points, with its value.

use super::names::Name;
use super::quantity::{Accept, Quantity};
use super::reader::{Reader, Value};
use super::units::Unit;

/// A parameter: its name (where the key is written) and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    pub name: Name,
    pub quantity: Quantity,
}

impl Reader<'_> {
    /// The `[parameters]` table: name = value, in the file's order.
    pub(super) fn parameters(&mut self, value: &Value<'_>, length: Unit) -> Vec<Parameter> {
        let Some(table) = self.table("parameters", "a table of name = value", value) else {
            return Vec::new();
        };
        let mut parameters = Vec::new();
        for (key, span, value) in table.all() {
            let name = self.identifier(key, span);
            let place = table.place(key);
            let quantity = self.quantity(&place, value, Accept::ANY, length);
            if let (Some(name), Some(quantity)) = (name, quantity) {
                parameters.push(Parameter { name, quantity });
            }
        }
        parameters
    }
}

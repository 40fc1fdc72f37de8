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
    /// The `[parameters]` table: name = value, in the file's order; and
    /// every name declared, its value read or not (for the equations,
    /// which may be checked although a value is wrong), or `None` if a
    /// name is not one (then an equation's name may be unknown only
    /// because of it).
    pub(super) fn parameters(
        &mut self,
        value: &Value<'_>,
        length: Unit,
    ) -> (Vec<Parameter>, Option<Vec<Name>>) {
        let Some(table) = self.table("parameters", "a table of name = value", value) else {
            return (Vec::new(), None);
        };
        let mut names_read = true;
        let mut parameters = Vec::new();
        let mut declared = Vec::new();
        for (key, span, value) in table.all() {
            let name = self.identifier(key, span);
            let place = table.place(key);
            let quantity = self.quantity(&place, value, Accept::ANY, length);
            match &name {
                Some(name) => declared.push(name.clone()),
                None => names_read = false,
            }
            if let (Some(name), Some(quantity)) = (name, quantity) {
                parameters.push(Parameter { name, quantity });
            }
        }
        (parameters, names_read.then_some(declared))
    }
}

//! The struct the attribute's parser reads the parameters from, written
//! for a mechanism given at run time: `struct FourBar { l1: f64, ... }`,
//! its name and each parameter's checked first (each must be a name the
//! equations could write), with where in the file each parameter is
//! declared, to locate a mistake the parser finds on the struct.

use super::Parameter;
use crate::diagnostics::{Diagnostic, Diagnostics};
use std::ops::Range;

/// The struct's text and its fields' places.
pub(super) struct Declaration {
    pub text: String,
    /// Each field's name in `text`, and where its parameter is declared.
    fields: Vec<(Range<usize>, Option<Range<usize>>)>,
}

/// The name a struct gets when the mechanism's is not one (reported): it
/// only has to parse, the messages name the mechanism as given.
const STAND_IN: &str = "Mechanism";

impl Declaration {
    /// The struct of mechanism `name` with `parameters` as its `f64`
    /// fields. A name that is not one, and a parameter declared twice, is
    /// recorded in `diagnostics` and left out (no equation can name it, so
    /// leaving it out reports nothing more).
    pub fn new(name: &str, parameters: &[Parameter<'_>], diagnostics: &mut Diagnostics) -> Self {
        let name = match not_a_name(name, "a mechanism's name", "FourBar") {
            Some(message) => {
                diagnostics.push(Diagnostic::error(message, None));
                STAND_IN
            }
            None => name,
        };
        let mut text = format!("struct {name} {{ ");
        let mut fields = Vec::new();
        let mut declared: Vec<(&str, &Parameter<'_>)> = Vec::new();
        for parameter in parameters {
            if let Some(message) = not_a_name(parameter.name, "a parameter's name", "l2") {
                diagnostics.push(Diagnostic::error(message, parameter.declared_at.clone()));
                continue;
            }
            let unraw = parameter.name.strip_prefix("r#").unwrap_or(parameter.name);
            if let Some((_, first)) = declared.iter().find(|(seen, _)| *seen == unraw) {
                let mut d = Diagnostic::error(
                    format!("the parameter `{unraw}` is declared twice"),
                    parameter.declared_at.clone(),
                );
                if let Some(first) = &first.declared_at {
                    d = d.with_label(first.clone(), format!("first `{unraw}` is here"));
                }
                diagnostics.push(d);
                continue;
            }
            declared.push((unraw, parameter));
            fields.push((
                text.len()..text.len() + parameter.name.len(),
                parameter.declared_at.clone(),
            ));
            text.push_str(parameter.name);
            text.push_str(": f64, ");
        }
        text.push('}');
        Declaration { text, fields }
    }

    /// Where the parameter whose field covers the bytes `range` of the
    /// struct's text is declared in the file, if it says.
    pub fn declared_at(&self, range: Range<usize>) -> Option<Range<usize>> {
        (self.fields.iter())
            .find(|(field, _)| field.start <= range.start && range.end <= field.end)
            .and_then(|(_, declared_at)| declared_at.clone())
    }
}

/// What is wrong with `name` as `what` (an identifier that is not a
/// keyword, written as the equations would write it), if anything.
fn not_a_name(name: &str, what: &str, example: &str) -> Option<String> {
    let ident = syn::parse_str::<syn::Ident>(name);
    if matches!(&ident, Ok(ident) if *ident == name) {
        return None;
    }
    let shown = name.escape_debug();
    let any_ident =
        syn::parse::Parser::parse_str(<syn::Ident as syn::ext::IdentExt>::parse_any, name);
    let a_keyword = matches!(&any_ident, Ok(ident) if *ident == name);
    Some(if a_keyword {
        format!(
            "`{shown}` is a keyword of Rust, which the equations cannot use as a name; {what} \
             is another identifier, e.g. `{example}`"
        )
    } else {
        format!(
            "`{shown}` is not a name: {what} is an identifier (letters, digits and `_`, not \
             starting with a digit), e.g. `{example}`"
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn declare(name: &str, parameters: &[Parameter<'_>]) -> (Declaration, Vec<String>) {
        let mut diagnostics = Diagnostics::new();
        let declaration = Declaration::new(name, parameters, &mut diagnostics);
        let messages = diagnostics.iter().map(|d| d.message().to_owned()).collect();
        (declaration, messages)
    }

    #[test]
    fn the_struct_of_a_mechanism() {
        let parameters = [
            Parameter::declared_at("l1", 10..12),
            Parameter::new("r#type"),
        ];
        let (declaration, messages) = declare("FourBar", &parameters);
        assert!(messages.is_empty());
        assert_eq!(declaration.text, "struct FourBar { l1: f64, r#type: f64, }");
        assert_eq!(declaration.declared_at(17..19), Some(10..12));
        assert_eq!(declaration.declared_at(26..32), None);
        assert_eq!(declaration.declared_at(0..6), None);
    }

    #[test]
    fn names_that_are_not_identifiers() {
        let parameters = [
            Parameter::declared_at("2x", 3..5),
            Parameter::new("fn"),
            Parameter::new(""),
            Parameter::new(" l1"),
            Parameter::new("_"),
            Parameter::declared_at("l1", 7..9),
            Parameter::declared_at("r#l1", 11..15),
        ];
        let mut diagnostics = Diagnostics::new();
        let declaration = Declaration::new("Four Bar", &parameters, &mut diagnostics);
        assert_eq!(declaration.text, "struct Mechanism { l1: f64, }");
        let all: Vec<&Diagnostic> = diagnostics.iter().collect();
        assert_eq!(all.len(), 7, "{diagnostics}");
        assert!(
            all[0]
                .message()
                .starts_with("`Four Bar` is not a name: a mechanism's name")
        );
        assert_eq!(all[0].range(), None);
        assert!(all[1].message().starts_with("`2x` is not a name"));
        assert_eq!(all[1].range(), Some(3..5));
        assert!(all[2].message().starts_with("`fn` is a keyword"));
        assert!(all[3].message().starts_with("`` is not a name"));
        assert!(all[4].message().starts_with("` l1` is not a name"));
        assert!(all[5].message().starts_with("`_` is"));
        assert_eq!(all[6].message(), "the parameter `l1` is declared twice");
        assert_eq!(all[6].range(), Some(11..15));
        assert_eq!(all[6].labels()[0].range(), 7..9);
    }
}

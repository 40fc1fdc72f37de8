//! A mechanism file made into a run-time [`Mechanism`]: its equations read
//! by the attribute's front end at their place in the file, its parameters
//! declared where their keys are, so that every mistake is located in the
//! file; and a file's own mistakes as the same [`Diagnostics`], to render
//! one way.

use super::MechanismFile;
use super::error::{FileError, FileErrors};
use crate::mechanism::{Diagnostic, Diagnostics, Equations, Mechanism, MechanismError, Parameter};

impl MechanismFile {
    /// The mechanism the file describes, with its parameters' values; the
    /// mistakes of its equations located in the file.
    pub fn mechanism(&self) -> Result<Mechanism, MechanismError> {
        let parameters: Vec<Parameter<'_>> = (self.parameters.iter())
            .map(|p| Parameter::declared_at(&p.name.text, p.name.span.clone()))
            .collect();
        let values: Vec<f64> = self.parameters.iter().map(|p| p.quantity.value).collect();
        let equations = Equations::at(&self.equations.text, self.equations.offset);
        Mechanism::build(&self.name.text, equations, &parameters, &values)
    }
}

impl From<&FileError> for Diagnostic {
    fn from(error: &FileError) -> Diagnostic {
        let mut diagnostic = Diagnostic::error(error.message.clone(), Some(error.at.clone()));
        for (at, note) in &error.labels {
            diagnostic = diagnostic.with_label(at.clone(), note.clone());
        }
        for note in &error.notes {
            diagnostic = diagnostic.with_note(note.clone());
        }
        diagnostic
    }
}

impl From<&FileErrors> for Diagnostics {
    fn from(errors: &FileErrors) -> Diagnostics {
        errors.errors.iter().map(Diagnostic::from).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = "name = \"Crank\"\nequations = '''\nu = [x], v = [t],\nclosure = [x - l * t.sinn()],\n'''\n[parameters]\nl = 2\n[drive.t]\nfrom = 0\nto = 1\n";

    #[test]
    fn the_equations_mistakes_are_located_in_the_file() {
        let file = MechanismFile::parse(FILE).unwrap();
        let Err(MechanismError::Mistakes(mistakes)) = file.mechanism() else {
            panic!("`sinn` is no function");
        };
        let rendered = mistakes.render("crank.toml", FILE, false);
        assert!(rendered.contains("crank.toml:4:22"), "{rendered}");
        assert!(
            rendered.contains("unsupported function `sinn`"),
            "{rendered}"
        );
    }

    /// A file with a mistake of its own and one in its equations reports
    /// both, in the file's order; a parameter whose value is wrong is
    /// still declared (no follow-on `unknown name`).
    #[test]
    fn the_equations_are_checked_beside_the_files_mistakes() {
        let text = FILE.replace("l = 2", "l = \"2 furlong\"");
        let errors = MechanismFile::parse(&text).unwrap_err();
        let messages: Vec<String> = errors.errors.iter().map(|e| e.to_string()).collect();
        assert_eq!(messages.len(), 2, "{messages:?}");
        assert!(
            messages[0].starts_with("4:22: unsupported function `sinn`"),
            "{messages:?}"
        );
        assert!(
            messages[1].starts_with("7:") && messages[1].contains("furlong"),
            "{messages:?}"
        );
        // Only the file's mistake once the equations are right.
        let text = text.replace("sinn", "sin");
        assert_eq!(MechanismFile::parse(&text).unwrap_err().errors.len(), 1);
    }

    #[test]
    fn a_good_file_makes_its_mechanism() {
        let file = MechanismFile::parse(&FILE.replace("sinn", "sin")).unwrap();
        let mechanism = file.mechanism().unwrap();
        assert_eq!((mechanism.m(), mechanism.f()), (1, 1));
        assert_eq!(mechanism.parameters(), [2.0]);
    }

    #[test]
    fn a_files_own_mistakes_render_as_diagnostics() {
        let text = FILE.replace("to = 1", "to = \"1 furlong\"");
        let errors = MechanismFile::parse(&text).unwrap_err();
        let rendered = Diagnostics::from(&errors).render("crank.toml", &text, false);
        assert!(rendered.contains("furlong"), "{rendered}");
        assert!(rendered.contains("crank.toml:10:"), "{rendered}");
    }
}

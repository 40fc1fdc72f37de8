//! Mechanism files: a planar mechanism written as text, to keep in a
//! repository and to analyse at run time — its closure equations in the
//! attribute's grammar, its parameters with units, its drive, the assembly
//! to start from and what to draw.
//!
//! The file is TOML:
//!
//! ```toml
//! # The four-bar of the Maple worksheet.
//! name = "FourBar"
//! title = "The four-bar of the Maple worksheet"
//! length_unit = "mm"
//! equations = '''
//! u = [theta3, theta4],
//! v = [theta2],
//! points = [
//!     B = (l2 * theta2.cos(), l2 * theta2.sin()),
//!     C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
//! ],
//! closure = [
//!     l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
//!     l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
//! ],
//! '''
//!
//! [parameters]
//! l1 = "80 mm"
//! l2 = "20 mm"
//! l3 = "5 cm"
//! l4 = 70
//!
//! [drive.theta2]
//! from = "0 deg"
//! to = "360 deg"
//! steps = 360
//! rate = "400 rpm"
//! at = "20 deg"
//!
//! [assembly]
//! near = { theta3 = "70 deg", theta4 = "-50 deg" }
//!
//! [drawing]
//! ground = { A = [0, 0], D = ["80 mm", 0] }
//! links = [["A", "B"], ["B", "C"], ["C", "D"]]
//! velocities = ["B", "C"]
//! ```
//!
//! | key | what | |
//! |---|---|---|
//! | `name` | the mechanism's name: a Rust identifier (the struct's name, if the file is ever written as Rust) | required |
//! | `title` | free text, for pictures and tables | optional |
//! | `length_unit` | the unit of the engine's lengths: `m` (the default), `mm`, `cm`, `in` or `ft`; a bare number is a length in it | optional |
//! | `equations` | the inside of `#[linkage::linkage(...)]`: `u = [...], v = [...], points = [...], closure = [...]`, optional `params = [...]`, as one literal string `'''…'''` | required |
//! | `[parameters]` | `name = value` for every parameter the equations use | optional |
//! | `[drive.<v>]` | one table per coordinate of v: `from`, `to` (the sweep's range, not of zero length), `steps` (a sweep's equal steps, as `Drive::Line`'s: steps + 1 poses; 1 to 1 000 000; default 360; the drivers move together and share it), `rate` (v̇; default 1 rad/s or m/s, so that a sweep's rates are the kinematic coefficients du/dv, as with `SweepOptions::default()`), `acceleration` (v̈; default 0), `at` (the pose one analysis takes; default `from`) | required |
//! | `[assembly]` | the assembly to start from, among the modes at the drivers' `at`, one of: `index = k` (the k-th mode found, from 0), `near = { <u> = value, … }` (the mode nearest a sketch of every dependent coordinate), `points = { <point> = [x, y], … }` (the mode nearest a sketch of named points) | optional |
//! | `[drawing]` | `ground = { <pivot> = [x, y], … }`, `links = [["A", "B"], …]`, `plates = [["B", "C", "E"], …]`, `sliders = [{ point = "C", angle = "0 deg" }, …]` (or `along = ["C", "D"]`, a link the block slides on, or `slot = "90 deg"`, a slot in a translating body), `velocities`, `accelerations`, `trace` (lists of points), `velocity_scale`, `acceleration_scale` (drawn length per unit of velocity, of acceleration) | optional |
//!
//! A value is a TOML number, in the engine's units, or a string of a
//! number and a unit (`"80 mm"`, `"400 rpm"`, `"-60 deg"`, `"9.81 m/s^2"`),
//! converted to them: SI, lengths in the file's `length_unit` (see
//! [`units`] for the table and how each converts). SI is what the engine
//! sees and prints. A unit of the wrong kind for its place (a length as a
//! rate) is a mistake; a driver's range, pose, rate and acceleration agree
//! on whether it moves an angle or a length.
//!
//! The equations' text is the file's, byte for byte, from
//! [`Equations::offset`] on: a mistake the equations' front end finds in
//! them is located in the file. (Their escapes would shift every place
//! after them, so the equations must be written as they are read: a
//! literal string, or a string without `\`.) What only the equations can
//! tell — whether `theta2` is a coordinate of v, whether every parameter is
//! used — is the front end's to check; what the file alone tells (a key
//! or a driver twice, a name both a parameter and a driver, a unit
//! unknown or misplaced, a number not finite, `steps = 0`, a range of
//! zero length, an unknown key) is checked here.
//!
//! Every mistake is reported, each once, at its byte range in the file
//! ([`FileError`]), in the file's order; TOML syntax errors come alone (a
//! file that does not parse says nothing reliable about its keys).
//!
//! ```
//! use linkage::file::{AssemblyChoice, MechanismFile};
//!
//! let text = r#"
//! name = "Crank"
//! length_unit = "mm"
//! equations = '''
//! u = [x],
//! v = [theta],
//! closure = [x - r * theta.cos()],
//! '''
//! [parameters]
//! r = "2 cm"
//! [drive.theta]
//! from = "0 deg"
//! to = "1 rev"
//! rate = "60 rpm"
//! [assembly]
//! index = 0
//! "#;
//! let file = MechanismFile::parse(text)?;
//! assert_eq!(file.name.text, "Crank");
//! assert_eq!(file.parameter("r"), Some(20.0)); // mm
//! let theta = &file.drivers[0];
//! assert_eq!(theta.to.value, std::f64::consts::TAU);
//! assert_eq!(theta.rate.value, std::f64::consts::TAU);
//! assert_eq!(theta.steps, 360);
//! assert_eq!(&text[file.equations.offset..][..5], "u = [");
//! assert!(matches!(file.assembly, Some(AssemblyChoice::Index { index: 0, .. })));
//!
//! // Mistakes, all at once, each where it is written.
//! let wrong = text.replace("\"2 cm\"", "\"2 cn\"").replace("rate", "rat");
//! let errors = MechanismFile::parse(&wrong).unwrap_err();
//! let said: Vec<String> = errors.errors.iter().map(|e| e.to_string()).collect();
//! assert_eq!(said, [
//!     "10:8: unknown unit `cn` in `parameters.r`; did you mean `cm`?",
//!     "14:1: unknown key `rat` in `drive.theta`; did you mean `rate`?",
//! ]);
//! # Ok::<(), linkage::file::FileErrors>(())
//! ```

mod assembly;
mod decimal;
mod drawing;
mod drive;
mod drives;
mod equations;
mod error;
mod lines;
mod loaded;
mod mechanism;
mod names;
mod parameters;
mod quantity;
mod reader;
mod rewrite;
#[cfg(feature = "draw")]
mod scene;
mod suggest;
mod syntax;
mod topology;
pub mod units;

pub use assembly::AssemblyChoice;
pub use drawing::{DrawingSpec, Guide, SliderSpec};
pub use drive::{DEFAULT_RATE, DEFAULT_STEPS, Driver, MOST_STEPS};
pub use drives::Drives;
pub use equations::Equations;
pub use error::{FileError, FileErrors, ReadError};
pub use loaded::{
    Cause, DeadCentre, DeadCentreError, DxfChoice, DxfError, FixedAnalysis, FixedDrives, LoadError,
    Loaded, Located, Positions, Swept, at_text, read_text,
};
pub use names::Name;
pub(crate) use names::not_an_identifier;
pub use parameters::Parameter;
pub use quantity::Quantity;
pub use rewrite::{RewriteError, with_parameters};
pub use topology::{TopologyFile, is_topology};
pub use units::{Kind, Unit};

use reader::{Reader, Table};
use std::path::Path;

/// A mechanism file, read: every value converted to the engine's units
/// (SI, lengths in [`MechanismFile::length_unit`]), each with where it is
/// written. See the [module](self) for the format.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanismFile {
    /// `name`: a Rust identifier.
    pub name: Name,
    /// `title`, if written.
    pub title: Option<String>,
    /// The unit of the engine's lengths (`"m"` unless the file says).
    pub length_unit: String,
    /// The equations, and where they start in the file.
    pub equations: Equations,
    /// `[parameters]`, in the file's order.
    pub parameters: Vec<Parameter>,
    /// `[drive.<v>]`, in the file's order.
    pub drivers: Vec<Driver>,
    /// `[assembly]`, if written.
    pub assembly: Option<AssemblyChoice>,
    /// `[drawing]`, if written.
    pub drawing: Option<DrawingSpec>,
}

impl MechanismFile {
    /// Reads a mechanism file's text: the file, or every mistake in it.
    pub fn parse(text: &str) -> Result<MechanismFile, FileErrors> {
        let mut reader = Reader::new(text);
        let file = syntax::document(&mut reader).and_then(|root| {
            let root = Table::new(root.get_ref(), "", 0..0);
            reader.mechanism(root)
        });
        match file {
            Some(file) if !reader.failed() => Ok(file),
            _ => Err(FileErrors {
                errors: reader.into_errors(),
            }),
        }
    }

    /// Reads the mechanism file at `path`.
    pub fn read(path: impl AsRef<Path>) -> Result<MechanismFile, ReadError> {
        let path = path.as_ref();
        let bytes = std::fs::read(path).map_err(|error| ReadError::Io {
            path: path.to_owned(),
            error,
        })?;
        let invalid = |text: String, errors| ReadError::Invalid {
            path: path.to_owned(),
            text,
            errors,
        };
        match String::from_utf8(bytes) {
            Ok(text) => MechanismFile::parse(&text).map_err(|errors| invalid(text, errors)),
            Err(e) => {
                let at = e.utf8_error().valid_up_to();
                let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
                let error = FileError::new(
                    &text,
                    at..at + 1,
                    "the file is not UTF-8 text: a mechanism file is text in UTF-8",
                );
                Err(invalid(
                    text,
                    FileErrors {
                        errors: vec![error],
                    },
                ))
            }
        }
    }

    /// The value of the parameter `name` (in the engine's units), if the
    /// file gives it.
    pub fn parameter(&self, name: &str) -> Option<f64> {
        self.parameters
            .iter()
            .find(|p| p.name.text == name)
            .map(|p| p.quantity.value)
    }

    /// The driver of the coordinate `name`, if the file has it.
    pub fn driver(&self, name: &str) -> Option<&Driver> {
        self.drivers.iter().find(|d| d.name.text == name)
    }
}

impl Reader<'_> {
    /// The document's keys, into a mechanism file.
    fn mechanism(&mut self, mut root: Table<'_, '_>) -> Option<MechanismFile> {
        let length = root.take("length_unit");
        let name = root.require(
            self,
            "name",
            "the mechanism's name, such as name = \"FourBar\"",
        );
        let title = root.take("title");
        let equations = root.require(
            self,
            "equations",
            "the closure equations, between ''' and ''' (u = [...], v = [...], closure = [...])",
        );
        let parameters = root.take("parameters");
        let drive = root.require(
            self,
            "drive",
            "a [drive.<name>] table with `from` and `to` for each coordinate of v",
        );
        let assembly = root.take("assembly");
        let drawing = root.take("drawing");
        root.finish(self);

        let length = match length {
            Some(v) => self.length_unit(v),
            None => units::lookup("m"),
        };
        let name = name.and_then(|v| {
            let text = self.string("name", v)?;
            self.identifier(text, v.span())
        });
        let title = title.and_then(|v| self.string("title", v).map(str::to_owned));
        let equations = equations.and_then(|v| self.equations(v));
        let length = length?;
        let (parameters, declared) = match parameters {
            Some(v) => self.parameters(v, length),
            None => (Vec::new(), Some(Vec::new())),
        };
        let drivers = drive.map_or_else(Vec::new, |v| self.drive(v, length));
        let assembly = assembly.and_then(|v| self.assembly(v, length));
        let drawing = drawing.and_then(|v| self.drawing(v, length));
        self.names_apart(&parameters, &drivers, assembly.as_ref());
        // A file that will not make a mechanism has its equations' mistakes
        // reported with its own, all at once: the parameters those
        // declared (a wrong value declares its name). Not if a parameter's
        // name is wrong, or a driver's too: a name of the equations would
        // then be unknown only because of that one mistake.
        let clash = (parameters.iter()).any(|p| drivers.iter().any(|d| d.name.text == p.name.text));
        if let (true, false, Some(equations), Some(declared)) =
            (self.failed(), clash, &equations, &declared)
        {
            let shown = name.as_ref().map_or("Mechanism", |n| n.text.as_str());
            self.check_equations(shown, equations, declared);
        }
        Some(MechanismFile {
            name: name?,
            title,
            length_unit: length.name.to_owned(),
            equations: equations?,
            parameters,
            drivers,
            assembly,
            drawing,
        })
    }

    /// `length_unit`: one of the length units.
    fn length_unit(&mut self, value: &reader::Value<'_>) -> Option<Unit> {
        let text = self.string("length_unit", value)?;
        match units::lookup(text) {
            Some(unit) if unit.kind == Kind::Length => Some(unit),
            _ => {
                let message = format!(
                    "`length_unit` must be a unit of length ({}), not `{text}`",
                    units::of_kind(Kind::Length)
                );
                self.error(value.span(), message);
                None
            }
        }
    }

    /// A parameter is no driver, and the sketch of an assembly names
    /// dependent coordinates only.
    fn names_apart(
        &mut self,
        parameters: &[Parameter],
        drivers: &[Driver],
        assembly: Option<&AssemblyChoice>,
    ) {
        for p in parameters {
            if let Some(d) = drivers.iter().find(|d| d.name.text == p.name.text) {
                let message = format!(
                    "`{}` is both a parameter and a driver: a name is one or the other",
                    p.name.text
                );
                let error = self
                    .mistake(p.name.span.clone(), message)
                    .label(d.name.span.clone(), "the driver");
                self.push(error);
            }
        }
        if let Some(AssemblyChoice::Near(near)) = assembly {
            for (name, _) in near {
                let clash = drivers
                    .iter()
                    .map(|d| (&d.name, "a driver"))
                    .chain(parameters.iter().map(|p| (&p.name, "a parameter")))
                    .find(|(n, _)| n.text == name.text);
                if let Some((other, what)) = clash {
                    let message = format!(
                        "`assembly.near` sketches the dependent coordinates, and `{}` is {what}",
                        name.text
                    );
                    let error = self
                        .mistake(name.span.clone(), message)
                        .label(other.span.clone(), what.to_string());
                    self.push(error);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;

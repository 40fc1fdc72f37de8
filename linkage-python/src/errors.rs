//! The library's errors as the Python exceptions of `linkage.errors`: the
//! class says what failed, the message is the library's own.

use linkage::Error;
use linkage::assembly::AssemblyError;
use linkage::file::{Cause, LoadError};
use linkage::mechanism::MechanismError;
use linkage::mechanism::design::NoDesign;
use linkage::mechanism::sizes::SizeError;
use linkage::synthesis::SynthesisError;
use linkage::tolerance::ToleranceError;
use linkage::watch::WatchError;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyType;

/// Why a call failed.
#[derive(Debug)]
pub enum Failure {
    Load(LoadError),
    Mechanism(MechanismError),
    Analysis(Error),
    Assembly(AssemblyError),
    Size(SizeError),
    Synthesis(SynthesisError),
    NoDesign(NoDesign),
    Watch(WatchError),
    Tolerance(ToleranceError),
    /// An argument from Python is out of its range.
    BadInput(String),
    /// Another tool's format could not be read or represented.
    Format(String),
}

impl From<LoadError> for Failure {
    fn from(error: LoadError) -> Failure {
        Failure::Load(error)
    }
}

impl From<MechanismError> for Failure {
    fn from(error: MechanismError) -> Failure {
        Failure::Mechanism(error)
    }
}

impl From<Error> for Failure {
    fn from(error: Error) -> Failure {
        Failure::Analysis(error)
    }
}

impl From<AssemblyError> for Failure {
    fn from(error: AssemblyError) -> Failure {
        Failure::Assembly(error)
    }
}

impl From<SynthesisError> for Failure {
    fn from(error: SynthesisError) -> Failure {
        Failure::Synthesis(error)
    }
}

impl From<SizeError> for Failure {
    fn from(error: SizeError) -> Failure {
        Failure::Size(error)
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Load(e) => write!(f, "{e}"),
            Failure::Mechanism(e) => write!(f, "{e}"),
            Failure::Analysis(e) => write!(f, "{e}"),
            Failure::Assembly(e) => write!(f, "{e}"),
            Failure::Size(e) => write!(f, "{e}"),
            Failure::Synthesis(e) => write!(f, "{e}"),
            Failure::NoDesign(e) => write!(f, "{e}"),
            Failure::Watch(e) => write!(f, "{e}"),
            Failure::Tolerance(e) => write!(f, "{e}"),
            Failure::BadInput(why) | Failure::Format(why) => f.write_str(why),
        }
    }
}

/// The class of `linkage.errors` for an analysis's error.
fn of_analysis(error: &Error) -> &'static str {
    match error {
        Error::NonFiniteInput { .. } | Error::InvalidInput { .. } => "BadInputError",
        Error::NotConverged { .. } => "NotConvergedError",
        Error::Singular { .. } => "SingularPoseError",
        Error::CannotAssemble { .. } => "CannotAssembleError",
        _ => "AnalysisError",
    }
}

fn of_assembly(error: &AssemblyError) -> &'static str {
    match error {
        AssemblyError::Input(e) => of_analysis(e),
        AssemblyError::NoAssembly { .. } => "CannotAssembleError",
        AssemblyError::SingularEverywhere { .. } | AssemblyError::AtDeadCentre { .. } => {
            "SingularPoseError"
        }
        _ => "BadInputError",
    }
}

fn of_watch(error: &WatchError) -> &'static str {
    match error {
        WatchError::UnknownName(_) => "BadInputError",
        WatchError::Kinematics(e) => of_analysis(e),
        _ => "AnalysisError",
    }
}

fn of_synthesis(error: &SynthesisError) -> &'static str {
    match error {
        SynthesisError::Unreachable { .. } | SynthesisError::NoDesign { .. } => "NoDesignError",
        SynthesisError::Options(e) => of_analysis(e),
        _ => "BadInputError",
    }
}

fn of_mechanism(error: &MechanismError) -> &'static str {
    match error {
        MechanismError::Mistakes(_) => "MistakesError",
        MechanismError::Sizes { .. }
        | MechanismError::TooManyPoints { .. }
        | MechanismError::TooManyParameters { .. } => "SizeError",
        MechanismError::Internal { .. } => "LinkageError",
        _ => "BadInputError",
    }
}

impl Failure {
    /// The name of its class in `linkage.errors`.
    fn class(&self) -> &'static str {
        match self {
            Failure::Load(LoadError::Read { missing: true, .. }) => "FileMissingError",
            Failure::Load(LoadError::Read { .. } | LoadError::NotThisKind { .. }) => "FileError",
            Failure::Load(LoadError::Mistakes(_)) => "MistakesError",
            Failure::Load(LoadError::Mechanism(e)) | Failure::Mechanism(e) => of_mechanism(e),
            Failure::Load(LoadError::Analysis { cause, .. }) => match cause {
                Cause::Analysis(e) => of_analysis(e),
                Cause::Assembly(e) => of_assembly(e),
                _ => "AnalysisError",
            },
            Failure::Load(_) => "LinkageError",
            Failure::Analysis(e) => of_analysis(e),
            Failure::Assembly(e) => of_assembly(e),
            Failure::Size(SizeError::View(e)) => of_mechanism(e),
            Failure::Size(_) => "SizeError",
            Failure::Synthesis(e) => of_synthesis(e),
            Failure::NoDesign(_) => "NoDesignError",
            Failure::Watch(e) => of_watch(e),
            Failure::Tolerance(e) => match e {
                ToleranceError::UnknownName(_) | ToleranceError::BadTolerance { .. } => {
                    "BadInputError"
                }
                ToleranceError::Kinematics { error, .. } => of_analysis(error),
                ToleranceError::Watch(e) => of_watch(e),
                _ => "AnalysisError",
            },
            Failure::BadInput(_) => "BadInputError",
            Failure::Format(_) => "FormatError",
        }
    }
}

impl From<Failure> for PyErr {
    fn from(failure: Failure) -> PyErr {
        let message = failure.to_string();
        Python::attach(|py| {
            let class = py
                .import("linkage.errors")
                .and_then(|errors| errors.getattr(failure.class()))
                .and_then(|class| Ok(class.cast_into::<PyType>()?));
            match class {
                Ok(class) => PyErr::from_type(class, message),
                Err(_) => PyRuntimeError::new_err(message),
            }
        })
    }
}

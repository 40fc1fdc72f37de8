//! The library's dispatch of a run-time mechanism to the analyses at its
//! sizes (`linkage::mechanism::sizes`), and its refusals as the tool's
//! failures.

use crate::failure::Failure;
pub use linkage::mechanism::sizes::{
    DesignJob, Job, PARAMETERS, SensitivityJob, SizeError, run, run_design, run_sensitive,
};

impl From<SizeError> for Failure {
    fn from(error: SizeError) -> Failure {
        Failure::Analysis(error.to_string())
    }
}

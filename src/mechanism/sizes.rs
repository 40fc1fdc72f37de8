//! From a mechanism whose sizes are known at run time to the analyses,
//! which are compiled for sizes known at compile time: a job is run on the
//! mechanism seen at its own sizes, among the sizes listed here — one
//! dispatch for every front door that reads mechanisms at run time (the
//! command-line tool, and the bindings to come). Each size instantiates
//! every analysis a job runs once, in the crate that runs it, so the list
//! is what mechanisms are usually made of, not every size there is; a
//! mechanism of another size is promoted to Rust (`linkage expand`), where
//! the attribute compiles it at its own sizes.

use super::{Fixed, Mechanism, MechanismError};
use std::fmt;

/// Why a job could not be run at a mechanism's sizes.
#[derive(Debug)]
#[non_exhaustive]
pub enum SizeError {
    /// Its sizes are none of [`SIZES`].
    NotListed { m: usize, f: usize },
    /// More parameters asked for than [`PARAMETERS`].
    TooManyParameters { count: usize, freed: bool },
    /// A job of one driving coordinate, on a mechanism of `f`.
    NotOneDriver { f: usize },
    /// The view at its sizes refused (a parameter it does not have).
    View(MechanismError),
}

impl fmt::Display for SizeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SizeError::NotListed { m, f: drivers } => write!(
                f,
                "mechanisms read at run time are analysed at the sizes {}; this one has m = {m}, \
                 f = {drivers}: promote it to Rust with `linkage expand`",
                SIZES
                    .iter()
                    .map(|(m, f)| format!("({m}, {f})"))
                    .collect::<Vec<_>>()
                    .join(" ")
            ),
            SizeError::TooManyParameters {
                count,
                freed: false,
            } => write!(
                f,
                "the mechanism is differentiated by {count} parameters; at most {PARAMETERS} are \
                 taken at once: choose them (the command-line tool's `--param`, Python's `params=`)"
            ),
            SizeError::TooManyParameters { count, freed: true } => write!(
                f,
                "{count} parameters are free; at most {PARAMETERS} can be at once"
            ),
            SizeError::NotOneDriver { f: drivers } => write!(
                f,
                "the synthesis takes mechanisms of one driving coordinate; this one has f = {drivers}"
            ),
            SizeError::View(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SizeError {}

/// Work to do on a mechanism at its sizes.
pub trait Job {
    type Output;
    /// Its errors, which a size the list lacks is one of.
    type Error: From<SizeError>;
    fn run<const M: usize, const F: usize>(
        self,
        mechanism: Fixed<M, F>,
    ) -> Result<Self::Output, Self::Error>;
}

/// Work with the sensitivities of a mechanism at its sizes, by chosen
/// parameters: at most [`PARAMETERS`] of them, the columns after them
/// zero.
pub trait SensitivityJob {
    type Output;
    type Error: From<SizeError>;
    fn run<const M: usize, const F: usize>(
        self,
        mechanism: Fixed<M, F, 32, PARAMETERS>,
    ) -> Result<Self::Output, Self::Error>;
}

/// Work with the sensitivities of a mechanism of one driving coordinate
/// (the synthesis), at its m.
pub trait DesignJob {
    type Output;
    type Error: From<SizeError>;
    fn run<const M: usize>(
        self,
        mechanism: Fixed<M, 1, 32, PARAMETERS>,
    ) -> Result<Self::Output, Self::Error>;
}

/// The room for parameters of the sensitivities: one size for every
/// mechanism (each size instantiates the sensitivities, the tolerance
/// analyses and the synthesis once more), the columns of the parameters
/// not chosen zero.
pub const PARAMETERS: usize = 16;

/// The sizes (m, f) this tool is built for.
pub const SIZES: &[(usize, usize)] = &[
    (1, 1),
    (2, 1),
    (3, 1),
    (4, 1),
    (5, 1),
    (6, 1),
    (7, 1),
    (8, 1),
    (10, 1),
    (12, 1),
    (16, 1),
    (1, 2),
    (2, 2),
    (3, 2),
    (4, 2),
    (5, 2),
    (6, 2),
];

/// `$then!(args; sizes...)` with the list of [`SIZES`] (the test below
/// holds the two the same).
macro_rules! with_sizes {
    ($then:ident!($($args:tt)*)) => {
        $then!($($args)*;
            (1, 1), (2, 1), (3, 1), (4, 1), (5, 1), (6, 1), (7, 1), (8, 1), (10, 1), (12, 1), (16, 1),
            (1, 2), (2, 2), (3, 2), (4, 2), (5, 2), (6, 2))
    };
}

/// `$then!(args; m...)` with the m of the sizes of [`SIZES`] with f = 1.
macro_rules! with_one_driver {
    ($then:ident!($($args:tt)*)) => {
        $then!($($args)*; 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 16)
    };
}

/// `$job.run(view)` with the view `$view::<m, 1>$arguments` at the
/// mechanism's m.
macro_rules! at_m {
    ($mechanism:expr, $job:expr, $view:ident $arguments:tt; $($m:literal),*) => {
        match ($mechanism.m(), $mechanism.f()) {
            $(($m, 1) => $job.run($view::<$m, 1> $arguments ?),)*
            (_, f) if f != 1 => Err(SizeError::NotOneDriver { f }.into()),
            (m, f) => Err(SizeError::NotListed { m, f }.into()),
        }
    };
}

/// `$job.run(view)` with the view `$view::<m, f>$arguments` at the
/// mechanism's sizes.
macro_rules! at_sizes {
    ($mechanism:expr, $job:expr, $view:ident $arguments:tt; $(($m:literal, $f:literal)),*) => {
        match ($mechanism.m(), $mechanism.f()) {
            $(($m, $f) => $job.run($view::<$m, $f> $arguments ?),)*
            (m, f) => Err(SizeError::NotListed { m, f }.into()),
        }
    };
}

/// The mechanism at m = `M`, f = `F`.
fn fixed<const M: usize, const F: usize>(mechanism: &Mechanism) -> Result<Fixed<M, F>, SizeError> {
    mechanism.fixed::<M, F>().map_err(SizeError::View)
}

/// The mechanism at m = `M`, f = `F`, differentiated by `names`.
fn sensitive<const M: usize, const F: usize>(
    mechanism: &Mechanism,
    names: &[&str],
) -> Result<Fixed<M, F, 32, PARAMETERS>, SizeError> {
    mechanism
        .differentiated_by::<M, F, 32, PARAMETERS>(names)
        .map_err(SizeError::View)
}

/// Runs `job` on `mechanism` at its sizes.
pub fn run<J: Job>(mechanism: &Mechanism, job: J) -> Result<J::Output, J::Error> {
    with_sizes!(at_sizes!(mechanism, job, fixed(mechanism)))
}

/// Runs `job` on `mechanism` at its sizes, its sensitivities by the
/// parameters `names` (every one it is differentiated by if none is
/// named).
pub fn run_sensitive<J: SensitivityJob>(
    mechanism: &Mechanism,
    names: &[String],
    job: J,
) -> Result<J::Output, J::Error> {
    let all = mechanism.differentiated();
    let names: Vec<&str> = if names.is_empty() {
        all
    } else {
        names.iter().map(String::as_str).collect()
    };
    if names.len() > PARAMETERS {
        return Err(SizeError::TooManyParameters {
            count: names.len(),
            freed: false,
        }
        .into());
    }
    with_sizes!(at_sizes!(mechanism, job, sensitive(mechanism, &names)))
}

/// Runs `job` on `mechanism` of one driving coordinate at its m, its
/// sensitivities by the parameters `names`.
pub fn run_design<J: DesignJob>(
    mechanism: &Mechanism,
    names: &[&str],
    job: J,
) -> Result<J::Output, J::Error> {
    if names.len() > PARAMETERS {
        return Err(SizeError::TooManyParameters {
            count: names.len(),
            freed: true,
        }
        .into());
    }
    with_one_driver!(at_m!(mechanism, job, sensitive(mechanism, names)))
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Sizes;
    impl Job for Sizes {
        type Output = (usize, usize);
        type Error = SizeError;
        fn run<const M: usize, const F: usize>(
            self,
            _: Fixed<M, F>,
        ) -> Result<(usize, usize), SizeError> {
            Ok((M, F))
        }
    }

    /// The list says what the match does: every listed size dispatches to
    /// itself, and one more is refused with the list.
    #[test]
    fn every_listed_size_runs_at_its_size() {
        for &(m, f) in SIZES {
            let u: Vec<String> = (0..m).map(|k| format!("x{k}")).collect();
            let v: Vec<String> = (0..f).map(|k| format!("t{k}")).collect();
            let closure: Vec<String> = (0..m).map(|k| format!("x{k} - t0")).collect();
            let text = format!(
                "u = [{}], v = [{}], closure = [{}]",
                u.join(", "),
                v.join(", "),
                closure.join(", ")
            );
            let mechanism = Mechanism::from_text("Sizes", &text, &[]).unwrap();
            assert_eq!(run(&mechanism, Sizes).unwrap(), (m, f));
        }
        let text = "u = [x0, x1, x2, x3, x4, x5, x6, x7, x8], v = [t], closure = [x0 - t, x1, x2, x3, x4, x5, x6, x7, x8]";
        let nine = Mechanism::from_text("Nine", text, &[]).unwrap();
        let Err(error @ SizeError::NotListed { m: 9, f: 1 }) = run(&nine, Sizes) else {
            panic!("m = 9 is not a size of the tool");
        };
        assert!(error.to_string().contains("m = 9, f = 1"), "{error}");
    }

    struct Design;
    impl DesignJob for Design {
        type Output = usize;
        type Error = SizeError;
        fn run<const M: usize>(self, _: Fixed<M, 1, 32, PARAMETERS>) -> Result<usize, SizeError> {
            Ok(M)
        }
    }

    /// The synthesis's list is the sizes' with f = 1.
    #[test]
    fn every_size_of_one_driver_designs_at_its_m() {
        for &(m, f) in SIZES {
            let u: Vec<String> = (0..m).map(|k| format!("x{k}")).collect();
            let v: Vec<String> = (0..f).map(|k| format!("t{k}")).collect();
            let closure: Vec<String> = (0..m).map(|k| format!("x{k} - a * t0")).collect();
            let text = format!(
                "u = [{}], v = [{}], closure = [{}]",
                u.join(", "),
                v.join(", "),
                closure.join(", ")
            );
            let mechanism = Mechanism::from_text("Sizes", &text, &[("a", 1.0)]).unwrap();
            match run_design(&mechanism, &["a"], Design) {
                Ok(designed) => assert_eq!((designed, f), (m, 1)),
                Err(error @ SizeError::NotOneDriver { .. }) => {
                    assert_ne!(f, 1, "{error}");
                    assert!(
                        error.to_string().contains("one driving coordinate"),
                        "{error}"
                    );
                }
                Err(other) => panic!("{other}"),
            }
        }
    }
}

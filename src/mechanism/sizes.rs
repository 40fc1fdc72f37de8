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

/// Work to do on a mechanism at its sizes, with room for `P` named
/// points (one of [`ROOMS`]).
pub trait Job {
    type Output;
    /// Its errors, which a size the list lacks is one of.
    type Error: From<SizeError>;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        mechanism: Fixed<M, F, P>,
    ) -> Result<Self::Output, Self::Error>;
}

/// Work with the sensitivities of a mechanism at its sizes, by chosen
/// parameters: at most [`PARAMETERS`] of them, the columns after them
/// zero.
pub trait SensitivityJob {
    type Output;
    type Error: From<SizeError>;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        mechanism: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Self::Output, Self::Error>;
}

/// Work with the sensitivities of a mechanism of one driving coordinate
/// (the synthesis), at its m.
pub trait DesignJob {
    type Output;
    type Error: From<SizeError>;
    fn run<const M: usize, const P: usize>(
        self,
        mechanism: Fixed<M, 1, P, PARAMETERS>,
    ) -> Result<Self::Output, Self::Error>;
}

/// The room for parameters of the sensitivities: one size for every
/// mechanism (each size instantiates the sensitivities, the tolerance
/// analyses and the synthesis once more), the columns of the parameters
/// not chosen zero.
pub const PARAMETERS: usize = 16;

/// The room for named points a job's view has: the first that holds the
/// mechanism's points. A view copies its point sets whole at every pose
/// and sensitivity (`K` columns of them), so room for 32 where a
/// mechanism has 3 costs the synthesis of a four-bar 1.8× its time; each
/// room instantiates every job once more.
pub const ROOMS: [usize; 2] = [8, 32];

/// The most named points a mechanism may have here.
pub const POINTS: usize = ROOMS[ROOMS.len() - 1];

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
        match ($mechanism.m(), $mechanism.f(), room($mechanism)) {
            $(($m, 1, 8) => $job.run($view::<$m, 1, 8> $arguments ?),
              ($m, 1, _) => $job.run($view::<$m, 1, 32> $arguments ?),)*
            (_, f, _) if f != 1 => Err(SizeError::NotOneDriver { f }.into()),
            (m, f, _) => Err(SizeError::NotListed { m, f }.into()),
        }
    };
}

/// `$job.run(view)` with the view `$view::<m, f>$arguments` at the
/// mechanism's sizes.
macro_rules! at_sizes {
    ($mechanism:expr, $job:expr, $view:ident $arguments:tt; $(($m:literal, $f:literal)),*) => {
        match ($mechanism.m(), $mechanism.f(), room($mechanism)) {
            $(($m, $f, 8) => $job.run($view::<$m, $f, 8> $arguments ?),
              ($m, $f, _) => $job.run($view::<$m, $f, 32> $arguments ?),)*
            (m, f, _) => Err(SizeError::NotListed { m, f }.into()),
        }
    };
}

/// The room of [`ROOMS`] for the mechanism's named points (the largest
/// if none holds them: the view then says how many it has).
fn room(mechanism: &Mechanism) -> usize {
    let points = mechanism.point_names().len();
    (ROOMS.into_iter())
        .find(|&room| points <= room)
        .unwrap_or(POINTS)
}

/// The mechanism at m = `M`, f = `F`, with room for `P` points.
fn fixed<const M: usize, const F: usize, const P: usize>(
    mechanism: &Mechanism,
) -> Result<Fixed<M, F, P>, SizeError> {
    mechanism.fixed_with::<M, F, P>().map_err(SizeError::View)
}

/// The mechanism at m = `M`, f = `F`, with room for `P` points,
/// differentiated by `names`.
fn sensitive<const M: usize, const F: usize, const P: usize>(
    mechanism: &Mechanism,
    names: &[&str],
) -> Result<Fixed<M, F, P, PARAMETERS>, SizeError> {
    mechanism
        .differentiated_by::<M, F, P, PARAMETERS>(names)
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
        fn run<const M: usize, const F: usize, const P: usize>(
            self,
            _: Fixed<M, F, P>,
        ) -> Result<(usize, usize), SizeError> {
            Ok((M, F))
        }
    }

    struct Room;
    impl Job for Room {
        type Output = usize;
        type Error = SizeError;
        fn run<const M: usize, const F: usize, const P: usize>(
            self,
            _: Fixed<M, F, P>,
        ) -> Result<usize, SizeError> {
            Ok(P)
        }
    }

    /// A four-bar with `n` named points.
    fn with_points(n: usize) -> Mechanism {
        let points: Vec<String> = (0..n).map(|k| format!("P{k} = ({k} * l, 0)")).collect();
        let text = format!(
            "u = [x], v = [t], points = [{}], closure = [x - l * t]",
            points.join(", ")
        );
        Mechanism::from_text("Points", &text, &[("l", 1.0)]).unwrap()
    }

    /// The match's rooms are those of [`ROOMS`]: each mechanism runs in
    /// the first that holds its points, and one with more than the
    /// largest holds is refused by its view, saying how many it has.
    #[test]
    fn each_mechanism_runs_in_the_first_room_that_holds_its_points() {
        for n in [0, 1, 7, 8, 9, 31, 32] {
            let room = ROOMS.into_iter().find(|&r| n <= r).unwrap();
            assert_eq!(run(&with_points(n), Room).unwrap(), room, "{n} points");
        }
        let Err(SizeError::View(error)) = run(&with_points(POINTS + 1), Room) else {
            panic!("{} points have no room", POINTS + 1);
        };
        assert!(error.to_string().contains("33"), "{error}");
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
        fn run<const M: usize, const P: usize>(
            self,
            _: Fixed<M, 1, P, PARAMETERS>,
        ) -> Result<usize, SizeError> {
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

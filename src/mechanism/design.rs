//! A synthesis posed on a run-time mechanism by names and numbers — what
//! the command-line tool, the Python package and each shard of a
//! distributed search ask for — solved by the library's synthesis
//! ([`crate::synthesis`]).

use super::Fixed;
use super::sizes::PARAMETERS;
use crate::synthesis::{
    self, Problem, Range, Requirements, Search, Synthesis, SynthesisError, Timing,
};
use nalgebra::{SVector, Vector2};
use std::fmt;

/// What a design must match.
#[derive(Clone, Debug, PartialEq)]
pub enum Targets {
    /// Path generation: the point `point` passes through `points`, reached
    /// as `timing` says; certified over a revolution of the driver.
    Path {
        point: String,
        points: Vec<[f64; 2]>,
        timing: Timing,
    },
    /// Function generation: the coordinate `coordinate` takes each pair's
    /// value at its driver; certified over the targets' drivers.
    Function {
        coordinate: String,
        pairs: Vec<(f64, f64)>,
    },
}

/// A synthesis on a run-time mechanism: its targets, the parameters it
/// chooses within bounds (the others keep their values), and whether it
/// stops at precision points.
#[derive(Clone, Debug, PartialEq)]
pub struct DesignTask {
    pub targets: Targets,
    /// `(name, lower, upper)` of each free parameter.
    pub free: Vec<(String, f64, f64)>,
    pub precision_points: bool,
    /// The smallest transmission angle a design may have over its range
    /// (radians); `None`: the library's default
    /// ([`Requirements::new`]: 40° for a mechanism of two coordinates).
    pub min_transmission: Option<f64>,
}

/// The fixed view a synthesis runs on: one driver, room for `P` named
/// points, the sensitivities by the free parameters.
pub type DesignView<const M: usize, const P: usize> = Fixed<M, 1, P, PARAMETERS>;

/// A design task posed on a run-time mechanism: the problem and its
/// requirements, searched at once ([`Designing::search`]) or piece by
/// piece, each piece the starts that follow ([`Search::first`]), put
/// together by [`Synthesis::absorb`] (the page's search, which reports
/// and can stop between pieces).
pub struct Designing<const M: usize, const P: usize> {
    problem: Problem<DesignView<M, P>, M, PARAMETERS>,
    requirements: Requirements<'static, DesignView<M, P>, M>,
}

impl<const M: usize, const P: usize> Designing<M, P> {
    /// `task` posed on `model`, from the assembly `guess` (without one,
    /// each start's design is assembled by the search for its modes).
    pub fn new(
        model: &DesignView<M, P>,
        guess: Option<SVector<f64, M>>,
        task: &DesignTask,
    ) -> Result<Designing<M, P>, SynthesisError> {
        let (problem, over) = match &task.targets {
            Targets::Path {
                point,
                points,
                timing,
            } => {
                let points: Vec<Vector2<f64>> =
                    points.iter().map(|p| Vector2::new(p[0], p[1])).collect();
                let problem = Problem::path(model.clone(), point, &points, timing.clone())?;
                (problem, Range::Revolution)
            }
            Targets::Function { coordinate, pairs } => {
                let problem = Problem::function(model.clone(), coordinate, pairs)?;
                (problem, Range::Targets)
            }
        };
        let mut problem = match guess {
            Some(guess) => problem.guess(guess),
            None => problem,
        };
        for (name, lower, upper) in &task.free {
            problem = problem.free(name, *lower, *upper)?;
        }
        if task.precision_points {
            problem = problem.precision_points();
        }
        let mut requirements = Requirements::new(over);
        if let Some(angle) = task.min_transmission {
            if !(0.0..=std::f64::consts::FRAC_PI_2).contains(&angle) {
                return Err(SynthesisError::Options(crate::Error::InvalidInput {
                    argument: "min_transmission",
                    value: angle,
                    why: "a transmission angle is from 0 to π/2",
                }));
            }
            requirements.min_transmission = angle;
        }
        Ok(Designing {
            problem,
            requirements,
        })
    }

    /// The search `search`, calling `on_start` as each start ends and
    /// stopping once `cancelled` says so; every design returned is
    /// certified.
    pub fn search(
        &self,
        search: &Search,
        on_start: &(dyn Fn() + Sync),
        cancelled: &(dyn Fn() -> bool + Sync),
    ) -> Result<Synthesis<DesignView<M, P>, M>, SynthesisError> {
        synthesis::synthesize_cancellable(
            &self.problem,
            &self.requirements,
            search,
            on_start,
            cancelled,
        )
    }

    /// `later`, a piece of the search that follows `found`'s starts, put
    /// after it ([`Synthesis::absorb`]).
    pub fn absorb(
        &self,
        found: &mut Synthesis<DesignView<M, P>, M>,
        later: Synthesis<DesignView<M, P>, M>,
    ) {
        found.absorb(&self.problem, later);
    }
}

/// Solves `task` on `model` from the assembly `guess` (without one, each
/// start's design is assembled by the search for its modes), by `search`,
/// calling `on_start` as each start ends and stopping once `cancelled`
/// says so; every design returned is certified. No design found is not an
/// error here (a shard may find none): see [`NoDesign::of`].
pub fn design<const M: usize, const P: usize>(
    model: &DesignView<M, P>,
    guess: Option<SVector<f64, M>>,
    task: &DesignTask,
    search: &Search,
    on_start: &(dyn Fn() + Sync),
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Result<Synthesis<DesignView<M, P>, M>, SynthesisError> {
    Designing::new(model, guess, task)?.search(search, on_start, cancelled)
}

/// A search that certified no design: from how many starts, and why
/// (a target out of reach, or the closest candidate's defect).
#[derive(Clone, Debug, PartialEq)]
pub struct NoDesign {
    pub starts: usize,
    pub why: Option<SynthesisError>,
}

impl NoDesign {
    /// Why `found` has no design, if it has none.
    pub fn of<L, const M: usize>(found: &Synthesis<L, M>) -> Option<NoDesign> {
        found.designs.is_empty().then(|| NoDesign {
            starts: found.starts,
            why: found.best().err(),
        })
    }
}

impl fmt::Display for NoDesign {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "no design found from {} starts", self.starts)?;
        match &self.why {
            Some(why) => write!(f, ": {why}"),
            None => Ok(()),
        }
    }
}

impl std::error::Error for NoDesign {}

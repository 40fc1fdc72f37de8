//! Continuation sweeps: the mechanism driven along a path, pose after pose,
//! without ever jumping silently to another assembly branch, and with every
//! singular pose on the way located and classified.
//!
//! Between two requested driver values the sweep takes as many sub-steps as
//! it needs. Each sub-step predicts the next pose from the velocity ratios
//! (first order, u + u′Δt) and, by default, the second-order analog
//! (+ ½u″Δt²), then corrects it with Newton. A corrected pose is accepted
//! only if it lies close to the prediction (the continuity of u) and, when
//! it is regular, if det Ψ_u keeps the branch's sign and its velocity ratios
//! continue the last regular pose's (the continuity of u′). A pose next to a
//! singular one (rcond below 1e-6) is kept for its position only: within
//! about √ε of a branch point rounding alone decides which of the crossing
//! solutions Newton finds, so such a pose never decides the branch or
//! predicts the next one.
//!
//! Where the branch passes through a *branch point* (two branches cross,
//! [Ψ_u Ψ_v] loses rank: the change-point four-bar at its collinear pose),
//! det Ψ_u changes sign along it, and Newton near it may fall onto the
//! other branch, whose velocity ratios differ. Either mark sends the sweep
//! to locate the branch point to rounding, as the regular solution of an
//! extended system (`branch_point.rs`), to work out the tangents of the two
//! branches there, and to leave it along the smooth continuation of the
//! branch it arrived on — whether or not a grid pose falls on the branch
//! point or within a few ulps of it. A sign change with no branch point
//! between is a jump to the mirror branch: refused, the step halved.
//!
//! Where the driver cannot advance any further, the pose is a *limit
//! position*: it is located exactly as the solution of Ψ = 0, det Ψ_u = 0,
//! and, when the drive rocks, the sweep passes onto the other branch and
//! reverses the driver — the full rocking motion of a non-Grashof four-bar.
//!
//! Both kinds are located to rounding: within 1e-12·max(1, |v|) of the
//! exact driver value (the worst of the targeted campaign in
//! `tests/sweep/singular_grid/`, every step count from 50 to 5000 with a grid
//! pose on the singular one or a few ulps off, is 1.7e-15).

// The files, each using only those before it:
//   state         what a sweep knows of its path (State, Track, Passage, Progress)
//   tracker       the path, the corrector, one predictor–corrector sub-step
//   bordered      Ψ_u, Ψ_t along the path and the bordered Newton system
//   branch_point  branch points: located, the two branches, passed
//   limit         limit positions: located, and the mirror pose
//   substep       sub-stepping, and the judgement of each sub-step's pose
//   pose          the poses handed out, at the sweep's speed
//   trig          sines and cosines carried from pose to pose
//   fast_run      the fast run over a regular stretch
//   driver        the driver loop
mod bordered;
mod branch_point;
mod driver;
mod fast_run;
mod limit;
mod pose;
mod state;
mod substep;
mod tracker;

pub(crate) use driver::sweep;

use crate::runtime::error::Error;
use crate::runtime::options::Options;
use nalgebra::SVector;

/// How the driver moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Drive<const F: usize> {
    /// From `from` to `to` along a straight line of driver space, in `steps`
    /// equal steps: the k-th pose is at `from + k·((to − from)/steps)`,
    /// evaluated in that order. A limit position on the way ends the sweep
    /// (the path cannot be followed further).
    Line {
        from: SVector<f64, F>,
        to: SVector<f64, F>,
        steps: usize,
    },
    /// Steps of `step` from `from` (poses at `from + k·step` for integer k),
    /// reversing at every limit position, until
    /// the mechanism is back at `from` moving the way it started after two
    /// reversals (one full rocking cycle), or after `max_steps` steps.
    Rocking {
        from: SVector<f64, F>,
        step: SVector<f64, F>,
        max_steps: usize,
    },
}

/// The choices of a sweep. The defaults: [`Options::default`], `speed`
/// 1 (so the poses' `udot` and `uddot` are the kinematic analogs du/dv and
/// d²u/dv², not velocities: set `speed` to the driver's speed, e.g. ω2 in
/// rad/s, for velocities and accelerations), `second_order` true,
/// `continuity` 0.5, `min_substep` 1e-12, `max_move` 0.1, `max_substeps`
/// 100 000.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepOptions {
    /// Newton's tolerances and the other solver choices.
    pub options: Options,
    /// The driver's speed along the path (driver units per second): the
    /// poses' velocities and accelerations are for this speed with no
    /// driver acceleration. 1 gives the kinematic analogs du/dv, d²u/dv².
    pub speed: f64,
    /// Predict with the second-order analog as well as the first.
    pub second_order: bool,
    /// A corrected pose farther from its prediction than this fraction of
    /// the predicted step is taken for a jump to another branch.
    pub continuity: f64,
    /// The smallest sub-step, as a fraction of a driver step: where halving
    /// the sub-step below this still finds no acceptable pose, the sweep
    /// looks for the singular pose that stops it (a branch point to step
    /// over, or a limit position). The singular poses themselves are located
    /// to rounding whatever this is.
    pub min_substep: f64,
    /// The largest predicted change of u in one sub-step, relative to
    /// max(1, ‖u‖∞): near a singular pose the velocity ratios blow up, and
    /// this keeps the predictor from throwing Newton onto a far branch.
    pub max_move: f64,
    /// The most sub-steps one step of the drive may take (halvings at
    /// singular poses included): a drive too long for its number of steps
    /// (a crank turned through 10⁹ revolutions in ten steps) is an
    /// [`Error::SubstepLimit`] rather than an endless loop.
    pub max_substeps: usize,
}

impl SweepOptions {
    /// That every setting is in its range.
    pub fn check(&self) -> Result<(), Error> {
        self.options.check()?;
        let invalid = |argument, value, why| {
            Err(Error::InvalidInput {
                argument,
                value,
                why,
            })
        };
        if !self.speed.is_finite() {
            return invalid("speed", self.speed, "the driver's speed must be finite");
        }
        for (argument, value) in [
            ("continuity", self.continuity),
            ("min_substep", self.min_substep),
            ("max_move", self.max_move),
        ] {
            if !(value > 0.0 && value.is_finite()) {
                return invalid(argument, value, "must be positive and finite");
            }
        }
        if self.max_substeps == 0 {
            return invalid("max_substeps", 0.0, "a step needs at least one sub-step");
        }
        Ok(())
    }
}

impl Default for SweepOptions {
    fn default() -> Self {
        SweepOptions {
            options: Options::default(),
            speed: 1.0,
            second_order: true,
            continuity: 0.5,
            min_substep: 1e-12,
            max_move: 0.1,
            max_substeps: 100_000,
        }
    }
}

/// One pose of a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepPose<const M: usize, const F: usize> {
    /// The sequence number of the driver step that reached this pose (0 for
    /// the start).
    pub step: usize,
    pub v: SVector<f64, F>,
    pub u: SVector<f64, M>,
    /// Velocities for the driver moving at `speed` in its current direction.
    pub vdot: SVector<f64, F>,
    pub udot: SVector<f64, M>,
    pub uddot: SVector<f64, M>,
    /// det Ψ_u: its sign is the assembly branch.
    pub det: f64,
    /// The reciprocal condition number of Ψ_u.
    pub rcond: f64,
    /// Newton iterations of the last corrector.
    pub iterations: usize,
}

/// What kind of singular pose the sweep met.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// The driver cannot go further: det Ψ_u = 0 with [Ψ_u Ψ_v] of full
    /// rank; the mechanism must reverse (a dead centre for this driver).
    LimitPosition,
    /// Two branches cross: det Ψ_u = 0 and [Ψ_u Ψ_v] rank-deficient (the
    /// change-point linkage's collinear pose); the sweep went on along the smooth
    /// continuation of the branch it arrived on.
    BranchPoint,
}

/// A singular pose met by a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event<const M: usize, const F: usize> {
    pub kind: EventKind,
    /// The driver value, located to rounding (within 1e-12·max(1, |v|)).
    pub v: SVector<f64, F>,
    pub u: SVector<f64, M>,
    /// The path parameter t of the event (v = from + t·direction).
    pub t: f64,
    /// The number of poses recorded before the event.
    pub after: usize,
    /// The smallest singular value of [Ψ_u Ψ_v] relative to the largest:
    /// about 0 at a branch point.
    pub rank_measure: f64,
}

/// The poses and events of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep<const M: usize, const F: usize> {
    /// One pose per driver step, except where the velocities and
    /// accelerations would not keep [`Options::accuracy`] (at or next to a
    /// singular pose, which the events report) and, whatever the accuracy,
    /// a step that falls within rounding of a branch point, where the
    /// crossing branches cannot be told apart: `step` numbers them.
    pub poses: Vec<SweepPose<M, F>>,
    pub events: Vec<Event<M, F>>,
    /// Whether the whole drive was followed (false: a limit position ended
    /// a line, or `max_steps` ended a rocking drive before it closed).
    pub complete: bool,
}

/// The outcome of a streamed sweep ([`crate::runtime::Linkage::sweep_each`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSummary<const M: usize, const F: usize> {
    pub events: Vec<Event<M, F>>,
    /// As [`Sweep::complete`].
    pub complete: bool,
    /// The number of poses passed on.
    pub poses: usize,
}

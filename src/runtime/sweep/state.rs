//! What a sweep knows of its path: [`State`], [`Track`], [`Passage`] and [`Progress`].

use super::Event;
use nalgebra::SVector;

/// A solved state on the path: t is the path parameter.
#[derive(Clone, Copy, Debug)]
pub(super) struct State<const M: usize, const F: usize> {
    pub(super) t: f64,
    pub(super) u: SVector<f64, M>,
    /// du/dt and d²u/dt² (zero where they cannot be computed).
    pub(super) du: SVector<f64, M>,
    pub(super) ddu: SVector<f64, M>,
    pub(super) det: f64,
    pub(super) rcond: f64,
    pub(super) iterations: usize,
    /// False for a pose that Newton could not resolve because it lies within
    /// rounding of a branch point (its u is the smooth continuation's
    /// prediction): never recorded.
    pub(super) solved: bool,
    /// Whether `du` and `ddu` hold the analogs (zero where they could not
    /// be computed per unit of t: Ψ_u singular, or so long a step that
    /// they overflow).
    pub(super) analogs: bool,
}

impl<const M: usize, const F: usize> State<M, F> {
    /// A pose at a branch point that Newton cannot resolve, taken from the
    /// prediction `u`: no tangent, no conditioning.
    pub(super) fn unresolved(u: SVector<f64, M>, t: f64) -> State<M, F> {
        State {
            t,
            u,
            du: SVector::zeros(),
            ddu: SVector::zeros(),
            det: 0.0,
            rcond: 0.0,
            iterations: 0,
            solved: false,
            analogs: false,
        }
    }
}

/// Below this reciprocal condition number a state's tangent is not trusted
/// for prediction, nor its det's sign for the branch. Within about √ε of a
/// branch point rounding alone decides which of the crossing solutions
/// Newton finds, and rcond there is about 1e-8; a tangent computed at rcond
/// r is off by about ε/r² relative (2e-4 at this threshold), still a fine
/// predictor.
pub(super) const REGULAR_RCOND: f64 = 1e-6;

/// The current state, the last well-conditioned one (the predictor near
/// singular poses) and the sign of det Ψ_u on the branch: that of the last
/// well-conditioned state, flipped at each located branch-point crossing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Track<const M: usize, const F: usize> {
    pub(super) state: State<M, F>,
    pub(super) regular: State<M, F>,
    pub(super) sign: f64,
}

impl<const M: usize, const F: usize> Track<M, F> {
    pub(super) fn new(state: State<M, F>) -> Track<M, F> {
        Track {
            state,
            regular: state,
            sign: state.det.signum(),
        }
    }

    pub(super) fn accept(&mut self, next: State<M, F>) {
        self.state = next;
        if next.rcond >= REGULAR_RCOND {
            self.regular = next;
            self.sign = next.det.signum();
        }
    }

    /// Past a branch point: on the smooth continuation, the sign of the
    /// regular pose beyond it (which may lie ahead of the pose at the
    /// target, when the target is next to the branch point).
    pub(super) fn pass(&mut self, passage: &Passage<M, F>) {
        self.state = passage.at_target.unwrap_or(passage.beyond);
        self.regular = passage.beyond;
        self.sign = passage.beyond.det.signum();
    }

    /// Where to predict from.
    pub(super) fn source(&self) -> State<M, F> {
        if self.state.rcond >= REGULAR_RCOND {
            self.state
        } else {
            self.regular
        }
    }
}

/// A branch point passed: the event, a regular state after it on the smooth
/// continuation of the branch the sweep arrived on, and, when the sub-step's
/// target lies between the two, the state at the target.
pub(super) struct Passage<const M: usize, const F: usize> {
    pub(super) event: Event<M, F>,
    pub(super) beyond: State<M, F>,
    pub(super) at_target: Option<State<M, F>>,
}

/// Where a sweep stands.
pub(super) struct Progress<const M: usize, const F: usize> {
    pub(super) track: Track<M, F>,
    /// The grid index of the current state.
    pub(super) index: i64,
    /// The driver steps taken.
    pub(super) step: usize,
    /// The poses passed on.
    pub(super) recorded: usize,
    /// The states at the last two grid indices (the source of a mirror).
    pub(super) last_grid: State<M, F>,
    pub(super) previous_grid: State<M, F>,
}

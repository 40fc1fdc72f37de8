//! A synthesis problem: which parameters are free (within bounds), what is
//! matched (a point's path, a coordinate as a function of the driver, a
//! body's position and angle), at which targets, with the driver at each
//! target prescribed or free.

use super::SynthesisError;
use super::terms::Terms;
use crate::quantity::{self, Names};
use crate::runtime::{Linkage, Sensitivities};
use nalgebra::{SVector, Vector2};
use num_dual::DualSVec64;

/// When the mechanism reaches each target.
#[derive(Clone, Debug, PartialEq)]
pub enum Timing {
    /// At these driver values (one per target).
    Prescribed(Vec<f64>),
    /// At these driver values plus one free offset, the same for every
    /// target: the crank's rotations between the targets are prescribed,
    /// not where it starts (the classical timed path problem). The offset
    /// is one more unknown.
    Relative(Vec<f64>),
    /// Whenever it can: each target's driver is an unknown too (first
    /// guessed evenly spread over a revolution, or over the problem's
    /// driver range, in the targets' order; for a start whose driver
    /// cannot turn a revolution, over the arc it reaches).
    Free,
}

/// The smallest and the largest of `values`.
pub(crate) fn extent(values: &[f64]) -> (f64, f64) {
    values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        })
}

impl Timing {
    /// The prescribed drivers (absolute or relative), if any.
    pub(crate) fn given(&self) -> Option<&[f64]> {
        match self {
            Timing::Prescribed(d) | Timing::Relative(d) => Some(d),
            Timing::Free => None,
        }
    }
}

/// What is matched at the targets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Task {
    /// A point's position: two residuals per target.
    Path { point: usize },
    /// A coordinate of u: one residual per target.
    Function { coordinate: usize },
    /// A point's position and a coordinate (the body's angle), the angle's
    /// residual times `length` so that both are lengths: three per target.
    Motion {
        point: usize,
        angle: usize,
        length: f64,
    },
}

impl Task {
    /// Residuals per target.
    pub(crate) fn rows(&self) -> usize {
        match self {
            Task::Path { .. } => 2,
            Task::Function { .. } => 1,
            Task::Motion { .. } => 3,
        }
    }
}

/// A parameter the synthesis chooses, within its bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Free {
    pub index: usize,
    pub lower: f64,
    pub upper: f64,
}

/// A synthesis problem on the model `L` (its fields not freed keep their
/// values).
#[derive(Clone, Debug)]
pub struct Problem<L, const M: usize, const K: usize> {
    pub(crate) model: L,
    pub(crate) free: Vec<Free>,
    pub(crate) task: Task,
    /// Each target's values: (x, y), (y), or (x, y, angle).
    pub(crate) targets: Vec<[f64; 3]>,
    /// When each target is reached.
    pub(crate) timing: Timing,
    /// The task's driver range, from one end to the other, if stated.
    pub(crate) range: Option<(f64, f64)>,
    /// A guess of the pose at the first target, if given; without one
    /// each start assembles its design with [`crate::assembly`].
    pub(crate) guess: Option<SVector<f64, M>>,
    /// Whether every target must be met exactly (precision points).
    pub(crate) exact: bool,
    /// The designer's own terms, after the targets' residuals.
    pub(crate) terms: Terms<K>,
}

impl<L: Sensitivities<M, 1, K>, const M: usize, const K: usize> Problem<L, M, K> {
    /// Path generation: the point `point` through `targets`.
    pub fn path(
        model: L,
        point: &str,
        targets: &[Vector2<f64>],
        timing: Timing,
    ) -> Result<Self, SynthesisError> {
        let task = Task::Path {
            point: point_index(&model, point)?,
        };
        let values = targets.iter().map(|t| [t.x, t.y, 0.0]).collect();
        Problem::new(model, task, values, timing)
    }

    /// Path generation close to a closed curve: the point `point` through
    /// `samples` points spread evenly by arc length along the closed
    /// polyline `curve` (its last point joined to its first), the driver
    /// at each free ([`Timing::Free`], first guessed in the samples' order
    /// over a revolution, which the certificate then checks), fitted by
    /// least squares. Errors: fewer than three points or samples, or a
    /// curve of no length ([`SynthesisError::Curve`]); a point not finite.
    pub fn curve(
        model: L,
        point: &str,
        curve: &[Vector2<f64>],
        samples: usize,
    ) -> Result<Self, SynthesisError> {
        if curve.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
            return Err(SynthesisError::NonFiniteTarget);
        }
        if curve.len() < 3 || samples < 3 {
            return Err(SynthesisError::Curve(
                "a closed curve needs at least three points and three samples",
            ));
        }
        let n = curve.len();
        let edge = |i: usize| (curve[i], curve[(i + 1) % n]);
        let lengths: Vec<f64> = (0..n).map(|i| (edge(i).1 - edge(i).0).norm()).collect();
        let total: f64 = lengths.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            return Err(SynthesisError::Curve("the curve has no length"));
        }
        let mut targets = Vec::with_capacity(samples);
        let (mut i, mut walked) = (0, 0.0);
        for k in 0..samples {
            let at = total * k as f64 / samples as f64;
            while i + 1 < n && walked + lengths[i] < at {
                walked += lengths[i];
                i += 1;
            }
            let (a, b) = edge(i);
            let t = if lengths[i] > 0.0 {
                ((at - walked) / lengths[i]).clamp(0.0, 1.0)
            } else {
                0.0
            };
            targets.push(a + (b - a) * t);
        }
        Problem::path(model, point, &targets, Timing::Free)
    }

    /// Function generation: the coordinate `coordinate` (of u) takes the
    /// value y at the driver v, for each (v, y) of `targets`. The task's
    /// input interval, which a certificate over [`Range::Task`](super::Range::Task) sweeps
    /// whole, is stated with [`Problem::driver_range`].
    pub fn function(
        model: L,
        coordinate: &str,
        targets: &[(f64, f64)],
    ) -> Result<Self, SynthesisError> {
        let task = Task::Function {
            coordinate: coordinate_index(&model, coordinate)?,
        };
        let values = targets.iter().map(|t| [t.1, 0.0, 0.0]).collect();
        let drivers = targets.iter().map(|t| t.0).collect();
        Problem::new(model, task, values, Timing::Prescribed(drivers))
    }

    /// Function generation over a range, by least squares: the coordinate
    /// `coordinate` (of u) should follow y = `function(v)` for the driver v
    /// from `from` to `to`, fitted at `samples` evenly spaced drivers, both
    /// ends included (for precision points instead, [`Problem::function`]
    /// with the points chosen). Errors: fewer than two samples, a range
    /// empty or not finite ([`SynthesisError::FunctionRange`]); a value of
    /// the function not finite. The range is the problem's driver range
    /// ([`Problem::driver_range`]).
    pub fn function_over(
        model: L,
        coordinate: &str,
        (from, to): (f64, f64),
        samples: usize,
        function: impl Fn(f64) -> f64,
    ) -> Result<Self, SynthesisError> {
        if samples < 2 {
            return Err(SynthesisError::FunctionRange(
                "a range needs at least two samples",
            ));
        }
        if !(from.is_finite() && to.is_finite() && from != to) {
            return Err(SynthesisError::FunctionRange(
                "the range is empty or not finite",
            ));
        }
        let targets: Vec<(f64, f64)> = (0..samples)
            .map(|k| {
                let v = from + (to - from) * k as f64 / (samples - 1) as f64;
                (v, function(v))
            })
            .collect();
        Problem::function(model, coordinate, &targets)?.driver_range(from, to)
    }

    /// Motion generation: the body carrying the point `point`, whose angle
    /// is the coordinate `angle`, through the poses (position, angle) of
    /// `targets`. Angles are weighed against positions by the targets'
    /// spread (the largest distance between two of them).
    pub fn motion(
        model: L,
        point: &str,
        angle: &str,
        targets: &[(Vector2<f64>, f64)],
        timing: Timing,
    ) -> Result<Self, SynthesisError> {
        let spread = targets
            .iter()
            .flat_map(|a| targets.iter().map(move |b| (a.0 - b.0).norm()))
            .fold(0.0, f64::max);
        let task = Task::Motion {
            point: point_index(&model, point)?,
            angle: coordinate_index(&model, angle)?,
            length: if spread > 0.0 { spread } else { 1.0 },
        };
        let values = targets.iter().map(|t| [t.0.x, t.0.y, t.1]).collect();
        Problem::new(model, task, values, timing)
    }

    fn new(
        model: L,
        task: Task,
        targets: Vec<[f64; 3]>,
        timing: Timing,
    ) -> Result<Self, SynthesisError> {
        if targets.is_empty() {
            return Err(SynthesisError::NoTargets);
        }
        let rows = task.rows();
        if targets
            .iter()
            .any(|t| t[..rows].iter().any(|x| !x.is_finite()))
        {
            return Err(SynthesisError::NonFiniteTarget);
        }
        if let Some(drivers) = timing.given() {
            if drivers.len() != targets.len() {
                return Err(SynthesisError::Timing {
                    targets: targets.len(),
                    drivers: drivers.len(),
                });
            }
            if drivers.iter().any(|v| !v.is_finite()) {
                return Err(SynthesisError::NonFiniteTarget);
            }
        }
        Ok(Problem {
            model,
            free: Vec::new(),
            task,
            targets,
            timing,
            range: None,
            guess: None,
            exact: false,
            terms: Terms::default(),
        })
    }

    /// Frees the parameter `name`, within [lower, upper].
    pub fn free(mut self, name: &str, lower: f64, upper: f64) -> Result<Self, SynthesisError> {
        let index = quantity::parameter(&self.model.param_names(), OWNER, name)?;
        if !(lower.is_finite() && upper.is_finite() && lower < upper) {
            return Err(SynthesisError::EmptyBounds {
                parameter: name.to_owned(),
                lower,
                upper,
            });
        }
        self.free.retain(|f| f.index != index);
        self.free.push(Free {
            index,
            lower,
            upper,
        });
        Ok(self)
    }

    /// The task's driver range: the driver runs from `from` to `to` (either
    /// way), and every target lies within it. A certificate over
    /// [`Range::Task`](super::Range::Task) sweeps it whole, ends included; free drivers are
    /// bounded to it. Errors: a range empty or not finite
    /// ([`SynthesisError::EmptyRange`]); a prescribed driver outside it
    /// ([`SynthesisError::OutsideRange`]). With relative timing only the
    /// drivers' spread must fit; the offset is bounded so that all lie
    /// within it.
    pub fn driver_range(mut self, from: f64, to: f64) -> Result<Self, SynthesisError> {
        if !(from.is_finite() && to.is_finite() && from != to) {
            return Err(SynthesisError::EmptyRange { from, to });
        }
        let (low, high) = (from.min(to), from.max(to));
        match &self.timing {
            Timing::Prescribed(drivers) => {
                if let Some((target, &driver)) = drivers
                    .iter()
                    .enumerate()
                    .find(|(_, d)| !(low..=high).contains(*d))
                {
                    return Err(SynthesisError::OutsideRange {
                        target,
                        driver,
                        from,
                        to,
                    });
                }
            }
            Timing::Relative(drivers) => {
                let (least, most) = extent(drivers);
                if most - least > high - low {
                    return Err(SynthesisError::EmptyRange { from, to });
                }
            }
            Timing::Free => {}
        }
        self.range = Some((from, to));
        Ok(self)
    }

    /// The task's driver range, if stated ([`Problem::driver_range`]).
    pub fn range(&self) -> Option<(f64, f64)> {
        self.range
    }

    /// A guess of the pose at the first target (the other targets' poses
    /// follow from it by continuation): every start's design is solved
    /// there by Newton from it. Without a guess, each start finds its
    /// design's assemblies at the first target's driver
    /// ([`crate::assembly::modes`]) and follows the first of them that
    /// reaches every target, trying them in their order turned by the
    /// start's index (start k begins with mode k mod n), so that the
    /// starts spread over the branches.
    pub fn guess(mut self, u: SVector<f64, M>) -> Self {
        self.guess = Some(u);
        self
    }

    /// Every target must be met exactly (precision points): a design that
    /// misses a target by more than 1e-10 of the targets' size (their
    /// largest coordinate in absolute value; for an angle, at least 1 rad)
    /// is not returned. More equations than unknowns are allowed: a
    /// consistent over-determined set (points of a curve the mechanism
    /// traces) is met to rounding; an inconsistent one is refused with its
    /// closest miss.
    pub fn precision_points(mut self) -> Self {
        self.exact = true;
        self
    }

    /// Adds the designer's term `name` to the objective: the residual
    /// `residual(p)` (driven towards zero with the targets' residuals, in
    /// their units), p the model's parameters in `PARAM_NAMES` order as dual
    /// numbers, so that its exact gradient comes with it. With precision
    /// points each term is one more equation to meet.
    pub fn term(
        mut self,
        name: &str,
        residual: impl Fn(&SVector<DualSVec64<K>, K>) -> DualSVec64<K> + Send + Sync + 'static,
    ) -> Self {
        self.terms.push(name, residual);
        self
    }

    /// The residuals: one, two or three per target, then one per term
    /// ([`Problem::term`]).
    pub fn residuals(&self) -> usize {
        self.target_residuals() + self.terms.len()
    }

    /// The targets' residuals (the rows before the terms').
    pub(crate) fn target_residuals(&self) -> usize {
        self.task.rows() * self.targets.len()
    }

    /// Whether the targets are reached in a revolution of the driver at
    /// whatever drivers the design takes (free timing, no task range): a
    /// design must then turn one.
    pub(crate) fn over_a_revolution(&self) -> bool {
        self.timing == Timing::Free && self.range.is_none()
    }

    /// The unknowns: the free parameters and the free drivers.
    pub fn unknowns(&self) -> usize {
        self.free.len() + self.free_drivers()
    }

    /// The unknowns that are drivers: one per target with free timing,
    /// the offset with relative timing, none with prescribed timing.
    pub(crate) fn free_drivers(&self) -> usize {
        match self.timing {
            Timing::Prescribed(_) => 0,
            Timing::Relative(_) => 1,
            Timing::Free => self.targets.len(),
        }
    }

    /// The checks that need the whole problem: something free.
    pub(crate) fn check(&self) -> Result<(), SynthesisError> {
        if self.free.is_empty() {
            return Err(SynthesisError::NothingFree);
        }
        Ok(())
    }

    /// The size a precision point's miss is measured against: the targets'
    /// largest coordinate in absolute value, for an angle at least 1 rad.
    pub(crate) fn target_scale(&self) -> f64 {
        let rows = self.task.rows();
        let largest = self
            .targets
            .iter()
            .flat_map(|t| t[..rows].iter().map(|x| x.abs()))
            .fold(0.0, f64::max);
        let angle = match self.task {
            Task::Function { coordinate } => self.model.trig_u()[coordinate],
            Task::Path { .. } | Task::Motion { .. } => false,
        };
        if angle || largest == 0.0 {
            largest.max(1.0)
        } else {
            largest
        }
    }

    /// The model with the free parameters set from the unknowns `x`.
    pub(crate) fn model_at(&self, x: &[f64]) -> L
    where
        L: Clone,
    {
        let mut model = self.model.clone();
        let mut p = model.params();
        for (f, value) in self.free.iter().zip(x) {
            p[f.index] = *value;
        }
        model.set_params(&p);
        model
    }

    /// The driver at target `i` for the unknowns `x`.
    pub(crate) fn driver(&self, x: &[f64], i: usize) -> f64 {
        match &self.timing {
            Timing::Prescribed(drivers) => drivers[i],
            Timing::Relative(drivers) => x[self.free.len()] + drivers[i],
            Timing::Free => x[self.free.len() + i],
        }
    }

    /// The column of the driver unknown that moves target `i`'s driver,
    /// if any.
    pub(crate) fn driver_column(&self, i: usize) -> Option<usize> {
        match self.timing {
            Timing::Prescribed(_) => None,
            Timing::Relative(_) => Some(self.free.len()),
            Timing::Free => Some(self.free.len() + i),
        }
    }
}

/// Who names the points, coordinates and parameters of a synthesis.
const OWNER: &str = "the synthesis problem";

fn point_index<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    name: &str,
) -> Result<usize, SynthesisError> {
    Ok(Names::of(model).point(OWNER, name)?)
}

/// The index of a solved coordinate (of u).
fn coordinate_index<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    name: &str,
) -> Result<usize, SynthesisError> {
    Ok(Names::of(model).solved(OWNER, name)?)
}

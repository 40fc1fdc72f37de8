//! The residuals of a problem at a design and their exact Jacobian: at each
//! target the pose is solved (by Newton, from the target's last pose, on
//! the same assembly branch), and its sensitivities give the columns of
//! the free parameters; its velocity at unit driver speed gives the column
//! of a free driver.

use super::problem::{Problem, Task};
use crate::least_squares::Evaluation;
use crate::runtime::{Factors, Linkage, Options, Sensitivities};
use nalgebra::{DMatrix, DVector, SVector};
use std::f64::consts::TAU;

/// The poses at the targets, and the sign of det Ψ_u there (the assembly
/// branch the design is followed on).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Poses<const M: usize> {
    pub u: Vec<SVector<f64, M>>,
    pub branch: Vec<bool>,
}

/// The assembly branch of the pose `u` at the driver `v`: the sign of
/// det Ψ_u.
pub(crate) fn branch<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: f64,
) -> bool {
    Factors::of(&model.psi_u(u, &SVector::from([v])), model.psi_u_blocks()).det() > 0.0
}

/// Evaluates the problem's residuals and Jacobian at the unknowns `x`,
/// solving each target's pose from `from`; `None` where a target cannot be
/// assembled, is singular, or lies on another branch than before.
pub(crate) fn evaluate<L, const M: usize, const K: usize>(
    problem: &Problem<L, M, K>,
    x: &DVector<f64>,
    from: &Poses<M>,
    options: &Options,
) -> Option<Evaluation<Poses<M>>>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let model = problem.model_at(x.as_slice());
    let rows = problem.task.rows();
    let n = x.len();
    let mut residuals = DVector::zeros(problem.residuals());
    let mut jacobian = DMatrix::zeros(problem.residuals(), n);
    let mut poses = Poses {
        u: Vec::with_capacity(problem.targets.len()),
        branch: Vec::with_capacity(problem.targets.len()),
    };
    let (vdot, vddot) = (SVector::from([1.0]), SVector::from([0.0]));
    for (i, target) in problem.targets.iter().enumerate() {
        let v = SVector::from([problem.driver(x.as_slice(), i)]);
        // Matched on references: the results are large (a run-time
        // mechanism's point sets have room for more points than it has),
        // and taken out of their `Result`s by value they were copied.
        let analysis = model.analyze(&from.u[i], &v, &vdot, &vddot, options);
        let Ok(analysis) = &analysis else {
            return None;
        };
        let sensitivity = model.position_sensitivities_of(analysis, options);
        let Ok(sensitivity) = &sensitivity else {
            return None;
        };
        // The branch from the sensitivities' factors of Ψ_u at the pose
        // (what [`branch`] computes, without evaluating Ψ_u again).
        let branch = sensitivity.det > 0.0;
        if branch != from.branch[i] {
            return None;
        }
        // The matched values (and their rates along the driver), row by
        // row: at most three rows, the first `rows` of each array.
        let zero = SVector::<f64, K>::zeros();
        let (value, rate, by_p): ([f64; 3], [f64; 3], [SVector<f64, K>; 3]) = match problem.task {
            Task::Path { point } => {
                let (p, pv, pp) = (
                    analysis.points.as_ref()[point],
                    analysis.point_velocities.as_ref()[point],
                    sensitivity.point(point),
                );
                (
                    [p.x, p.y, 0.0],
                    [pv.x, pv.y, 0.0],
                    [pp.row(0).transpose(), pp.row(1).transpose(), zero],
                )
            }
            Task::Function { coordinate } => (
                [analysis.u[coordinate], 0.0, 0.0],
                [analysis.udot[coordinate], 0.0, 0.0],
                [sensitivity.u.row(coordinate).transpose(), zero, zero],
            ),
            Task::Motion {
                point,
                angle,
                length,
            } => {
                let (p, pv, pp) = (
                    analysis.points.as_ref()[point],
                    analysis.point_velocities.as_ref()[point],
                    sensitivity.point(point),
                );
                (
                    [p.x, p.y, length * analysis.u[angle]],
                    [pv.x, pv.y, length * analysis.udot[angle]],
                    [
                        pp.row(0).transpose(),
                        pp.row(1).transpose(),
                        sensitivity.u.row(angle).transpose() * length,
                    ],
                )
            }
        };
        for r in 0..rows {
            let row = rows * i + r;
            residuals[row] = match (problem.task, r) {
                // An angle meets its target modulo whole turns: the body's
                // orientation is what is matched, not how often it turned.
                (Task::Motion { length, .. }, 2) => {
                    let miss = (value[r] - length * target[2]) / length;
                    length * (miss - TAU * (miss / TAU).round())
                }
                _ => value[r] - target[r],
            };
            for (column, free) in problem.free.iter().enumerate() {
                jacobian[(row, column)] = by_p[r][free.index];
            }
            if let Some(column) = problem.driver_column(i) {
                jacobian[(row, column)] = rate[r];
            }
        }
        poses.u.push(analysis.u);
        poses.branch.push(branch);
    }
    problem.terms.write(
        &model.params(),
        problem.free.iter().map(|free| free.index),
        problem.target_residuals(),
        &mut residuals,
        &mut jacobian,
    );
    let finite = residuals
        .iter()
        .chain(jacobian.iter())
        .all(|x| x.is_finite());
    finite.then_some(Evaluation {
        residuals,
        jacobian,
        state: poses,
    })
}

/// The residuals, their Jacobian (a row per residual, a column per
/// unknown) and the poses at the targets.
pub type Evaluated<const M: usize> = (DVector<f64>, DMatrix<f64>, Vec<SVector<f64, M>>);

impl<L, const M: usize, const K: usize> Problem<L, M, K>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    /// The residuals and their exact Jacobian at the unknowns `x` (the free
    /// parameters in the order they were freed, then the free drivers),
    /// with the poses found: what the solver evaluates at each trial, for
    /// checks and benchmarks. Each target's pose is solved by Newton from
    /// its pose in `from` and kept on that pose's branch. `None` where a
    /// target cannot be assembled, is singular or changes branch, or if `x`
    /// or `from` has the wrong length.
    pub fn evaluate(
        &self,
        x: &[f64],
        from: &[SVector<f64, M>],
        options: &Options,
    ) -> Option<Evaluated<M>> {
        if x.len() != self.unknowns() || from.len() != self.targets.len() {
            return None;
        }
        let model = self.model_at(x);
        let branch = from
            .iter()
            .enumerate()
            .map(|(i, u)| branch(&model, u, self.driver(x, i)))
            .collect();
        let from = Poses {
            u: from.to_vec(),
            branch,
        };
        let found = evaluate(self, &DVector::from_column_slice(x), &from, options)?;
        Some((found.residuals, found.jacobian, found.state.u))
    }
}

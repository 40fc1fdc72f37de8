//! What the sensitivities take and return: a pose in motion, the generated
//! terms at it, and the derivatives of every result by the parameters.

use crate::runtime::results::Analysis;
use crate::runtime::sweep::SweepPose;
use nalgebra::{SMatrix, SVector, Vector2};

/// A pose in motion: every coordinate with its velocity and acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion<const M: usize, const F: usize> {
    pub u: SVector<f64, M>,
    pub v: SVector<f64, F>,
    pub udot: SVector<f64, M>,
    pub vdot: SVector<f64, F>,
    pub uddot: SVector<f64, M>,
    pub vddot: SVector<f64, F>,
}

impl<const M: usize, const F: usize> Motion<M, F> {
    /// The pose of an analysis, its drivers at the values the analysis was
    /// given.
    pub fn of_analysis<P>(analysis: &Analysis<M, F, P>) -> Motion<M, F> {
        Motion {
            u: analysis.u,
            v: analysis.v,
            udot: analysis.udot,
            vdot: analysis.vdot,
            uddot: analysis.uddot,
            vddot: analysis.vddot,
        }
    }

    /// A pose of a sweep (its drivers at constant speed: v̈ = 0).
    pub fn of_sweep_pose(pose: &SweepPose<M, F>) -> Motion<M, F> {
        Motion {
            u: pose.u,
            v: pose.v,
            udot: pose.udot,
            vdot: pose.vdot,
            uddot: pose.uddot,
            vddot: SVector::zeros(),
        }
    }
}

/// The generated terms of the sensitivities at a pose in motion
/// (`sensitivity_terms`): the explicit derivatives by u and by the
/// parameters p of Ψ, Ψ̇ = Ψ_q q̇ and Ψ̈ = Ψ_q q̈ + γ — which are Ψ_u, Ψ_p
/// and their first and second time derivatives — and the same of every
/// point's P, Ṗ and P̈. `P` holds one 2-vector per point; `[P; M]` one `P`
/// per coordinate of u, `[P; K]` one per parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensitivityTerms<const M: usize, const K: usize, P> {
    pub psi_u: SMatrix<f64, M, M>,
    pub psi_p: SMatrix<f64, M, K>,
    /// Ψ̇_u = (Ψ_q q̇)_u
    pub psi_u_dot: SMatrix<f64, M, M>,
    /// Ψ̇_p = (Ψ_q q̇)_p
    pub psi_p_dot: SMatrix<f64, M, K>,
    /// Ψ̈_u = (Ψ_q q̈ + γ)_u
    pub psi_u_ddot: SMatrix<f64, M, M>,
    /// Ψ̈_p = (Ψ_q q̈ + γ)_p
    pub psi_p_ddot: SMatrix<f64, M, K>,
    /// P_u, column by column.
    pub points_u: [P; M],
    /// P_p (explicit), column by column.
    pub points_p: [P; K],
    /// Ṗ_u = (P_q q̇)_u
    pub point_velocities_u: [P; M],
    /// Ṗ_p = (P_q q̇)_p (explicit)
    pub point_velocities_p: [P; K],
    /// P̈_u = (P_q q̈ + (P_q q̇)_q q̇)_u
    pub point_accelerations_u: [P; M],
    /// P̈_p (explicit)
    pub point_accelerations_p: [P; K],
}

/// The terms of the sensitivities of the positions alone (those of
/// [`SensitivityTerms`] that depend on no rate): Ψ_u, Ψ_p, P_u and P_p.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PositionTerms<const M: usize, const K: usize, P> {
    pub psi_u: SMatrix<f64, M, M>,
    pub psi_p: SMatrix<f64, M, K>,
    /// P_u, column by column.
    pub points_u: [P; M],
    /// P_p (explicit), column by column.
    pub points_p: [P; K],
}

impl<const M: usize, const K: usize, P: Copy> PositionTerms<M, K, P> {
    /// The position terms among all the terms.
    pub fn of(terms: &SensitivityTerms<M, K, P>) -> PositionTerms<M, K, P> {
        PositionTerms {
            psi_u: terms.psi_u,
            psi_p: terms.psi_p,
            points_u: terms.points_u,
            points_p: terms.points_p,
        }
    }
}

/// The sensitivities of the positions alone at a pose
/// ([`Sensitivities::position_sensitivities_of`](super::Sensitivities::position_sensitivities_of)):
/// the very numbers of [`Sensitivity`]'s `u`, `points` and `rcond`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PositionSensitivity<const M: usize, const K: usize, P> {
    /// u_p = −Ψ_u⁻¹Ψ_p
    pub u: SMatrix<f64, M, K>,
    /// dP/dp = P_u u_p + P_p, one set of points per parameter.
    pub points: [P; K],
    /// The reciprocal condition number of Ψ_u at the pose.
    pub rcond: f64,
    /// det Ψ_u at the pose: its sign tells the assembly branch.
    pub det: f64,
}

impl<const M: usize, const K: usize, P: AsRef<[Vector2<f64>]>> PositionSensitivity<M, K, P> {
    /// The derivatives of the position of point `index` by the parameters
    /// (2 × k: rows x and y). Panics if `index` is not a point's index.
    pub fn point(&self, index: usize) -> SMatrix<f64, 2, K> {
        gather(&self.points, index)
    }
}

/// The sensitivities of a pose in motion to the parameters p: the total
/// derivative of every result by each parameter, the driver's position,
/// velocity and acceleration held fixed.
///
/// Column (or entry) j is the derivative by `PARAM_NAMES[j]`: `u[(i, j)]` =
/// ∂uᵢ/∂pⱼ, `points[j][c]` = ∂P_c/∂pⱼ for the point of index c.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sensitivity<const M: usize, const K: usize, P> {
    /// u_p = −Ψ_u⁻¹Ψ_p
    pub u: SMatrix<f64, M, K>,
    /// u̇_p = −Ψ_u⁻¹(Ψ̇_u u_p + Ψ̇_p)
    pub udot: SMatrix<f64, M, K>,
    /// ü_p = −Ψ_u⁻¹(Ψ̈_u u_p + 2Ψ̇_u u̇_p + Ψ̈_p)
    pub uddot: SMatrix<f64, M, K>,
    /// dP/dp = P_u u_p + P_p, one set of points per parameter.
    pub points: [P; K],
    /// dṖ/dp = Ṗ_u u_p + P_u u̇_p + Ṗ_p
    pub point_velocities: [P; K],
    /// dP̈/dp = P̈_u u_p + 2Ṗ_u u̇_p + P_u ü_p + P̈_p
    pub point_accelerations: [P; K],
    /// The reciprocal condition number of Ψ_u at the pose.
    pub rcond: f64,
}

impl<const M: usize, const K: usize, P: AsRef<[Vector2<f64>]>> Sensitivity<M, K, P> {
    /// The derivatives of the position of point `index` by the parameters
    /// (2 × k: rows x and y). Panics if `index` is not a point's index.
    pub fn point(&self, index: usize) -> SMatrix<f64, 2, K> {
        gather(&self.points, index)
    }

    /// The derivatives of the velocity of point `index` (2 × k).
    pub fn point_velocity(&self, index: usize) -> SMatrix<f64, 2, K> {
        gather(&self.point_velocities, index)
    }

    /// The derivatives of the acceleration of point `index` (2 × k).
    pub fn point_acceleration(&self, index: usize) -> SMatrix<f64, 2, K> {
        gather(&self.point_accelerations, index)
    }
}

fn gather<const K: usize, P: AsRef<[Vector2<f64>]>>(
    columns: &[P; K],
    index: usize,
) -> SMatrix<f64, 2, K> {
    SMatrix::from_fn(|c, j| columns[j].as_ref()[index][c])
}

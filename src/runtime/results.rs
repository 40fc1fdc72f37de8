//! What the analyses return: a pose, a Newton iterate, velocities, the
//! one-pass kinematics, and the whole analysis of a pose.

use crate::runtime::factors::Factors;
use crate::runtime::trig::PoseTrig;
use nalgebra::{SMatrix, SVector};

/// An assembled pose found by Newton–Raphson.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Position<const M: usize> {
    pub u: SVector<f64, M>,
    /// Newton steps taken.
    pub iterations: usize,
    /// ‖Ψ(u, v)‖∞ at the solution.
    pub residual: f64,
    /// Ψ_u at the solution (reused by the velocity solve).
    pub psi_u: SMatrix<f64, M, M>,
}

/// One Newton–Raphson iterate, as reported to an observer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iterate<const M: usize> {
    /// 0 for the initial guess.
    pub iteration: usize,
    pub u: SVector<f64, M>,
    /// ‖Ψ(u, v)‖∞
    pub residual: f64,
    /// ‖Δu‖∞ of the step that led here (0 for the initial guess).
    pub step: f64,
}

/// The velocity solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Velocity<const M: usize, const F: usize> {
    /// u̇ = −R v̇
    pub udot: SVector<f64, M>,
    /// The velocity ratios R = Ψ_u⁻¹Ψ_v (the worksheet's `Rap`); for one
    /// degree of freedom, −R is the column of first kinematic analogs du/dv.
    pub ratios: SMatrix<f64, M, F>,
    /// The reciprocal condition number of Ψ_u.
    pub rcond: f64,
}

/// Everything at one pose, from one pass of generated code
/// ([`Kernels::kinematics`](crate::runtime::Kernels::kinematics)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics<const M: usize, const F: usize> {
    /// Ψ (the residual of the pose).
    pub psi: SVector<f64, M>,
    pub psi_u: SMatrix<f64, M, M>,
    pub psi_v: SMatrix<f64, M, F>,
    /// Ψ_u factored for solving with it, by its diagonal blocks where it
    /// has more than one, with no explicit inverse (meaningless if `rcond`
    /// is 0).
    pub factors: Factors<M>,
    /// The column-equilibrated reciprocal condition number of Ψ_u
    /// ([`Factors::rcond`]).
    pub rcond: f64,
    /// det Ψ_u
    pub det: f64,
    /// u̇ = −Ψ_u⁻¹Ψ_v v̇
    pub udot: SVector<f64, M>,
    /// ü = −Ψ_u⁻¹(Ψ_v v̈ + γ)
    pub uddot: SVector<f64, M>,
}

impl<const M: usize, const F: usize> Kinematics<M, F> {
    /// What a kernel gives when it could not run: not numbers, which the
    /// runtime's checks turn into a typed error (and a value to write
    /// evaluations over, as the generated fused kernel of a large
    /// mechanism does).
    #[doc(hidden)]
    #[inline(always)]
    pub fn unevaluated() -> Kinematics<M, F> {
        Kinematics {
            psi: SVector::repeat(f64::NAN),
            psi_u: SMatrix::repeat(f64::NAN),
            psi_v: SMatrix::repeat(f64::NAN),
            factors: Factors::unfactored(),
            rcond: f64::NAN,
            det: f64::NAN,
            udot: SVector::repeat(f64::NAN),
            uddot: SVector::repeat(f64::NAN),
        }
    }

    /// [`Kinematics::unevaluated`] with Ψ_u zero: a value that
    /// [`Kernels::kinematics_with_trig_over`](crate::runtime::Kernels::kinematics_with_trig_over)
    /// may write over from the first evaluation on.
    #[doc(hidden)]
    #[inline(always)]
    pub fn blank() -> Kinematics<M, F> {
        Kinematics {
            psi_u: SMatrix::zeros(),
            ..Kinematics::unevaluated()
        }
    }
}

/// Positions, velocities and accelerations of a pose, of the coordinates
/// and of the points.
///
/// Two analyses are equal when their public fields are and they were given
/// the same drivers (which [`crate::runtime::Motion::of_analysis`] reads); the sines
/// and cosines one may keep for [`crate::runtime::Sensitivities::sensitivities_of`]
/// change none of its numbers, and are not compared.
#[derive(Clone, Copy, Debug)]
pub struct Analysis<const M: usize, const F: usize, P> {
    pub u: SVector<f64, M>,
    pub udot: SVector<f64, M>,
    pub uddot: SVector<f64, M>,
    /// R = Ψ_u⁻¹Ψ_v
    pub ratios: SMatrix<f64, M, F>,
    pub points: P,
    pub point_velocities: P,
    pub point_accelerations: P,
    /// Newton steps taken.
    pub iterations: usize,
    /// ‖Ψ‖∞ at the solution.
    pub residual: f64,
    /// The reciprocal condition number of Ψ_u at the solution.
    pub rcond: f64,
    /// The drivers v, v̇, v̈ the analysis was given (read by
    /// [`crate::runtime::Motion::of_analysis`]), kept so that the sensitivities at
    /// the analysis need not be given them again.
    pub(crate) v: SVector<f64, F>,
    pub(crate) vdot: SVector<f64, F>,
    pub(crate) vddot: SVector<f64, F>,
    /// The sines and cosines the fused kernel computed at the pose (the
    /// default options' path; `None` on the others), which
    /// [`crate::runtime::Sensitivities::sensitivities_of`] uses.
    pub(crate) trig: Option<PoseTrig<M, F>>,
}

impl<const M: usize, const F: usize, P: PartialEq> PartialEq for Analysis<M, F, P> {
    fn eq(&self, other: &Self) -> bool {
        // Every field but `trig`, named so that a field added later is not
        // left out unseen.
        let Analysis {
            u,
            udot,
            uddot,
            ratios,
            points,
            point_velocities,
            point_accelerations,
            iterations,
            residual,
            rcond,
            v,
            vdot,
            vddot,
            trig: _,
        } = self;
        *u == other.u
            && *udot == other.udot
            && *uddot == other.uddot
            && *ratios == other.ratios
            && *points == other.points
            && *point_velocities == other.point_velocities
            && *point_accelerations == other.point_accelerations
            && *iterations == other.iterations
            && *residual == other.residual
            && *rcond == other.rcond
            && *v == other.v
            && *vdot == other.vdot
            && *vddot == other.vddot
    }
}

/// One pose of a batch of analyses ([`Linkage::analyze`](crate::runtime::Linkage::analyze)).
#[derive(Clone, Debug, PartialEq)]
pub struct AnalysisJob<L, const M: usize, const F: usize> {
    pub model: L,
    pub u_guess: SVector<f64, M>,
    pub v: SVector<f64, F>,
    pub vdot: SVector<f64, F>,
    pub vddot: SVector<f64, F>,
}

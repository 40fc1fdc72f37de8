//! The typed errors of the runtime: every failure says what happened, where,
//! and the figure that explains it.

use core::fmt;

/// The step of the analysis where an error arose.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Newton–Raphson on Ψ(u, v) = 0.
    Position,
    /// The velocity solve Ψ_u u̇ = −Ψ_v v̇.
    Velocity,
    /// The acceleration solve Ψ_u ü = −Ψ_v v̈ − γ.
    Acceleration,
    /// The points' kinematics.
    Points,
    /// The sensitivities to the parameters, Ψ_u u_p = −Ψ_p and its time
    /// derivatives.
    Sensitivity,
}

impl fmt::Display for Stage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Stage::Position => "position",
            Stage::Velocity => "velocity",
            Stage::Acceleration => "acceleration",
            Stage::Points => "points",
            Stage::Sensitivity => "sensitivity",
        })
    }
}

/// Why an analysis failed.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An argument holds a NaN or an infinity.
    NonFiniteInput {
        /// The argument (`"u"`, `"v"`, `"vdot"`, ...).
        argument: &'static str,
        index: usize,
        value: f64,
    },
    /// Newton–Raphson used its iterations without meeting the tolerances
    /// (from a guess far from every assembly, too: [`crate::assembly`]
    /// needs none).
    NotConverged {
        iterations: usize,
        /// ‖Ψ‖∞ at the last iterate.
        residual: f64,
        /// ‖Δu‖∞ of the last step.
        step: f64,
    },
    /// Ψ_u is singular or so ill-conditioned that a solve with it would be
    /// garbage: the mechanism is at (or next to) a dead-centre, limit or
    /// change-point pose, or the equations do not determine u. In a
    /// position solve the singular pose may be Newton's start or one of
    /// its iterates instead: a guess far from every assembly (all zeros,
    /// say) fails so; [`crate::assembly`] finds the assemblies without one.
    Singular {
        stage: Stage,
        /// 1/(‖Ψ_u‖₁‖Ψ_u⁻¹‖₁), 0 for an exactly singular matrix.
        rcond: f64,
        /// The threshold in force for this stage ([`crate::runtime::Options::min_rcond`]).
        min_rcond: f64,
    },
    /// The equations have no solution at this driver value: damped Newton
    /// reached a least-squares minimum of ‖Ψ‖ (Ψ_uᵀΨ ≈ 0, and no
    /// second-order step along the null vector of Ψ_u descends, so not a
    /// saddle) that is not a root. The mechanism cannot be assembled here;
    /// `residual` says by how much it fails to close, `closest` is the pose
    /// that comes closest. For one loop (a four-bar, a slider-crank) every
    /// such minimum is global; a mechanism of several loops can have local
    /// ones, which another initial guess may avoid.
    CannotAssemble {
        /// ‖Ψ‖∞ at the closest pose.
        residual: f64,
        /// The dependent coordinates of the closest pose.
        closest: Vec<f64>,
        /// ‖Ψ_uᵀΨ‖∞ / (‖Ψ_u‖∞‖Ψ‖∞) there.
        gradient: f64,
    },
    /// The numbers are so small that f64 holds them only as subnormal
    /// numbers, whose relative precision is lost: a column or a row of
    /// [Ψ_u Ψ_v] has no entry above 2⁻⁹⁷⁰ ≈ 1e-292, or a velocity or an
    /// acceleration (u̇, ü, or a sweep's at its speed) is nonzero but below
    /// 2⁻¹⁰²² ≈ 2.2e-308. No result could keep the requested accuracy;
    /// express the mechanism in other units.
    Underflow {
        stage: Stage,
        quantity: &'static str,
        scale: f64,
    },
    /// A sweep's step needed more sub-steps than
    /// [`crate::runtime::SweepOptions::max_substeps`]: the drive moves too far per
    /// step for the predictor's largest move (a crank turned through many
    /// revolutions between two recorded poses). Take more steps, or a
    /// shorter drive.
    SubstepLimit {
        /// The poses recorded before the step.
        step: usize,
        /// [`crate::runtime::SweepOptions::max_substeps`].
        limit: usize,
    },
    /// A setting or an argument is out of its range (other than not being
    /// finite): a negative tolerance, a drive that does not move.
    InvalidInput {
        argument: &'static str,
        value: f64,
        why: &'static str,
    },
    /// A generated quantity is NaN or infinite although the inputs are
    /// finite: the pose or the parameters are outside the domain of the
    /// equations (e.g. `sqrt` of a negative number), or a value overflows.
    NonFiniteValue {
        stage: Stage,
        /// The quantity, e.g. `"Ψ"` or `"ü"`.
        quantity: &'static str,
    },
}

/// What a position solve's failure may also mean.
const FAR_GUESS: &str = "; a guess far from every assembly fails so too \
    (`linkage::assembly` finds the assemblies without one)";

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NonFiniteInput {
                argument,
                index,
                value,
            } => write!(f, "non-finite input: {argument}[{index}] = {value}"),
            Self::NotConverged {
                iterations,
                residual,
                step,
            } => write!(
                f,
                "Newton–Raphson did not converge in {iterations} iterations: \
         ‖Ψ‖∞ = {residual:.3e}, last step ‖Δu‖∞ = {step:.3e}{FAR_GUESS}"
            ),
            Self::Singular {
                min_rcond,
                rcond,
                stage,
            } => {
                write!(
                    f,
                    "Ψ_u is singular in the {stage} solve: reciprocal condition number {rcond:.3e} \
         is below {min_rcond:.3e}, the least that keeps the requested accuracy (the pose \
         is at or near a singular configuration: dead centre, limit position or branch point)"
                )?;
                if *stage == Stage::Position {
                    f.write_str(FAR_GUESS)?;
                }
                Ok(())
            }
            Self::CannotAssemble {
                gradient, residual, ..
            } => write!(
                f,
                "the mechanism cannot be assembled here: the closest pose leaves ‖Ψ‖∞ = {residual:.6e} \
         (a least-squares minimum, relative gradient {gradient:.1e})"
            ),
            Self::Underflow {
                quantity,
                scale,
                stage,
            } => write!(
                f,
                "{quantity} underflows in the {stage} stage: its scale {scale:.3e} is below the normal range of f64 that keeps relative precision (express the mechanism in larger units)"
            ),
            Self::SubstepLimit { limit, step } => write!(
                f,
                "a step of the sweep, after {step} recorded poses, needs more than {limit} sub-steps: the drive moves too far per step (take more steps or a shorter drive)"
            ),
            Self::InvalidInput {
                argument,
                value,
                why,
            } => write!(f, "{argument} = {value} is out of range: {why}"),
            Self::NonFiniteValue { quantity, stage } => write!(
                f,
                "{quantity} is not finite in the {stage} stage: the pose or the parameters are outside the equations' domain"
            ),
        }
    }
}

impl std::error::Error for Error {}

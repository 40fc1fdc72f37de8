//! The poses a sweep hands out: scaled to its speed, checked for accuracy and range.

use super::SweepPose;
use super::state::State;
use super::tracker::Tracker;
use crate::runtime::checks::check_result;
use crate::runtime::error::{Error, Stage};
use crate::runtime::kernels::Kernels;
use crate::runtime::solve::acceleration_conditioning_with;
use crate::runtime::sources;

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// Whether the pose's velocities and accelerations keep the requested
    /// accuracy (see [`Options::accuracy`]).
    pub(super) fn keeps_accuracy(&self, state: &State<M, F>) -> bool {
        let options = &self.options.options;
        // An exactly singular pose has no velocities, whatever the accuracy.
        if !state.solved || state.rcond <= 0.0 || state.rcond < self.min_rcond_velocity {
            return false;
        }
        if state.rcond >= self.min_rcond_acceleration {
            return true;
        }
        // Near a singular pose: the finer test needs Ψ_u and Ψ_v.
        let (jacobian, v) = (options.jacobian, self.v(state.t));
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, &state.u, &v).1;
        let psi_v = sources::psi_v(self.model, jacobian, &state.u, &v);
        acceleration_conditioning_with(
            &psi_u,
            &psi_v,
            state.rcond,
            self.min_rcond_acceleration,
            options,
        )
        .is_ok()
    }

    /// The pose at the sweep's speed; an error if scaling to that speed
    /// overflows (an absurd speed for the step).
    #[inline(always)]
    pub(super) fn pose(
        &self,
        state: &State<M, F>,
        step: usize,
        direction: f64,
    ) -> Result<SweepPose<M, F>, Error> {
        if !state.analogs {
            return self.pose_at_unit_scale(state, step, direction);
        }
        let rate = self.rate * direction;
        let pose = SweepPose {
            step,
            v: self.v(state.t),
            u: state.u,
            vdot: self.dir * rate,
            udot: state.du * rate,
            uddot: state.ddu * rate * rate,
            det: state.det,
            rcond: state.rcond,
            iterations: state.iterations,
        };
        // x·0 is 0 for a finite x and NaN otherwise: one cheap test of every
        // entry, which finite values far apart cannot fool (their sum could
        // overflow).
        let probe = |x: &[f64]| x.iter().fold(0.0, |acc, &x| acc + x * 0.0);
        let probes = probe(pose.v.as_slice())
            + probe(pose.vdot.as_slice())
            + probe(pose.udot.as_slice())
            + probe(pose.uddot.as_slice());
        // A non-finite entry, or a tiny speed at which the velocities and
        // accelerations may fall below the normal range: the careful tests,
        // out of line.
        let unusual = (probes != 0.0) | ((rate != 0.0) & (rate.abs() < 1e-100));
        if unusual {
            Self::unusual_pose(state, rate, &pose)?;
        }
        Ok(pose)
    }

    /// [`Self::pose`] for a state whose analogs per unit of t could not be
    /// computed (they overflow for a step of 1e160): the analogs per unit
    /// of driver length instead, at the sweep's speed.
    #[cold]
    #[inline(never)]
    fn pose_at_unit_scale(
        &self,
        state: &State<M, F>,
        step: usize,
        direction: f64,
    ) -> Result<SweepPose<M, F>, Error> {
        let along = self.dir / self.step_length;
        let v = self.v(state.t);
        let (Some((du, ddu)), _, _) = self.motion(&state.u, &v, &along) else {
            return Err(Error::NonFiniteValue {
                stage: Stage::Velocity,
                quantity: "the sweep's analogs along its path",
            });
        };
        let speed = self.options.speed * direction;
        let pose = SweepPose {
            step,
            v,
            u: state.u,
            vdot: along * speed,
            udot: du * speed,
            uddot: ddu * (speed * speed),
            det: state.det,
            rcond: state.rcond,
            iterations: state.iterations,
        };
        let unit = State { du, ddu, ..*state };
        if speed != 0.0 {
            Self::unusual_pose(&unit, speed, &pose)?;
        }
        Ok(pose)
    }

    /// The careful tests of [`Self::pose`], for a pose with a non-finite
    /// entry or at a tiny speed.
    #[cold]
    #[inline(never)]
    pub(super) fn unusual_pose(
        state: &State<M, F>,
        rate: f64,
        pose: &SweepPose<M, F>,
    ) -> Result<(), Error> {
        let finite = |x: &[f64]| x.iter().all(|v| v.is_finite());
        if !(finite(pose.v.as_slice())
            && finite(pose.vdot.as_slice())
            && finite(pose.udot.as_slice())
            && finite(pose.uddot.as_slice()))
        {
            return Err(Error::NonFiniteValue {
                stage: if finite(pose.udot.as_slice()) {
                    Stage::Acceleration
                } else {
                    Stage::Velocity
                },
                quantity: "the sweep's velocities and accelerations at its speed",
            });
        }
        let log_rate = rate.abs().log2();
        check_result(
            Stage::Velocity,
            "the sweep's u̇ at its speed",
            state.du.amax().log2() + log_rate,
        )?;
        check_result(
            Stage::Acceleration,
            "the sweep's ü at its speed",
            state.ddu.amax().log2() + 2.0 * log_rate,
        )
    }
}

//! The flywheel by the energy method: ΔT_I(φ), the flywheel J_I for a
//! coefficient of speed fluctuation, and the resulting ω(φ), ε(φ).

use super::{Machine, MachineError};
use crate::numerics;
use crate::runtime::Linkage;
use std::f64::consts::TAU;

/// The flywheel by the energy method (Merkalov's, as in the course
/// project): the kinetic energy of the variable part, T_II(φ) = ½ J(φ)ω_m²,
/// is taken at the mean speed, so that the constant part's energy varies
/// by ΔT_I(φ) = A(φ) + M_D·φ − T_II(φ); the flywheel that keeps the speed
/// within ω_m(1 ± δ/2) is J_I = (max ΔT_I − min ΔT_I)/(δ ω_m²), and
///
/// ```text
/// ω(φ) = ω_m + (ΔT_I(φ) − ½(max ΔT_I + min ΔT_I)) / (J_I ω_m)
/// ε(φ) = (M(φ) + M_D)/(J_I + J(φ)) − ω(φ)² J′(φ) / (2 (J_I + J(φ)))
/// ```
pub struct EnergyMethod<'m, L, const M: usize> {
    pub(super) machine: &'m Machine<L, M>,
    pub omega_mean: f64,
    pub delta: f64,
    /// M_D = −A(2π)/2π
    pub driving_moment: f64,
    /// (φ, ΔT_I) at the minimum and the maximum of ΔT_I.
    pub minimum: (f64, f64),
    pub maximum: (f64, f64),
    /// J_I, the constant reduced inertia needed.
    pub flywheel: f64,
}

/// (φ, value) of an extremum.
pub type Extremum = (f64, f64);

impl<'m, L: Linkage<M, 1>, const M: usize> EnergyMethod<'m, L, M> {
    pub(super) fn new(
        machine: &'m Machine<L, M>,
        omega_mean: f64,
        delta: f64,
    ) -> Result<Self, MachineError> {
        if !(omega_mean.is_finite() && omega_mean > 0.0) {
            return Err(MachineError::BadSetting {
                what: "the mean speed",
                must: "positive and finite",
                value: omega_mean,
            });
        }
        // ω_min = ω_m(1 − δ/2) must stay positive.
        if !(delta > 0.0 && delta < 2.0) {
            return Err(MachineError::BadSetting {
                what: "the coefficient of speed fluctuation δ",
                must: "between 0 and 2, exclusive",
                value: delta,
            });
        }
        let mut method = EnergyMethod {
            machine,
            omega_mean,
            delta,
            driving_moment: machine.mean_driving_moment(),
            minimum: (0.0, 0.0),
            maximum: (0.0, 0.0),
            flywheel: 0.0,
        };
        let phis: Vec<f64> = machine.grid().collect();
        let work = machine.work_along(&phis)?;
        let values: Vec<f64> = phis
            .iter()
            .zip(&work)
            .map(|(&phi, &a)| {
                machine.reduced(phi).map(|r| {
                    a + method.driving_moment * phi - 0.5 * r.inertia * omega_mean * omega_mean
                })
            })
            .collect::<Result<_, _>>()?;
        let refine = |k: usize, sign: f64| -> Result<Extremum, MachineError> {
            let lo = phis[k.saturating_sub(1)];
            let hi = phis[(k + 1).min(phis.len() - 1)];
            let mut f = |phi: f64| method.delta_t(phi).map(|v| sign * v);
            let (x, fx) = numerics::minimize(&mut f, lo, hi, 1e-11)?;
            // ΔT_I′ = M + M_D − ½ J′ ω_m² is known analytically: its root
            // places a smooth extremum to the precision of f64 (values only
            // place it to about the square root of that).
            let mut slope = |phi: f64| {
                method.machine.reduced(phi).map(|r| {
                    r.moment + method.driving_moment
                        - 0.5 * r.inertia_derivative * omega_mean * omega_mean
                })
            };
            let h = 1e-6;
            let (a, b) = (x - h, x + h);
            if slope(a)? * slope(b)? < 0.0 {
                let root = numerics::root(&mut slope, a, b)?;
                return Ok((root, method.delta_t(root)?));
            }
            Ok((x, sign * fx))
        };
        let argmin = numerics::argmin(&values);
        let argmax = numerics::argmax(&values);
        let (minimum, maximum) = (refine(argmin, 1.0)?, refine(argmax, -1.0)?);
        method.minimum = minimum;
        method.maximum = maximum;
        method.flywheel = (method.maximum.1 - method.minimum.1) / (delta * omega_mean * omega_mean);
        if !method.flywheel.is_finite() {
            return Err(MachineError::BadSetting {
                what: "the mean speed",
                must: "large enough that the flywheel J_I = ΔT/(δ·ω_m²) stays finite",
                value: omega_mean,
            });
        }
        Ok(method)
    }

    /// ΔT_I(φ) = A(φ) + M_D·φ − ½ J(φ) ω_m², periodic (M_D balances the
    /// work of a cycle): evaluated on φ wrapped to [0, 2π), so that a φ of
    /// many cycles loses no digits to the cancellation of A and M_D·φ.
    pub fn delta_t(&self, phi: f64) -> Result<f64, MachineError> {
        let r = self.machine.reduced(phi)?;
        let phi = phi.rem_euclid(TAU);
        Ok(self.machine.work(phi)? + self.driving_moment * phi
            - 0.5 * r.inertia * self.omega_mean * self.omega_mean)
    }

    /// ω(φ) (see the type's documentation).
    pub fn omega(&self, phi: f64) -> Result<f64, MachineError> {
        let middle = 0.5 * (self.maximum.1 + self.minimum.1);
        Ok(self.omega_mean + (self.delta_t(phi)? - middle) / (self.flywheel * self.omega_mean))
    }

    /// ε(φ) (see the type's documentation).
    pub fn epsilon(&self, phi: f64) -> Result<f64, MachineError> {
        let r = self.machine.reduced(phi)?;
        let omega = self.omega(phi)?;
        let total = self.flywheel + r.inertia;
        Ok((r.moment + self.driving_moment) / total
            - omega * omega * r.inertia_derivative / (2.0 * total))
    }

    /// The extremes of ω: at the extremes of ΔT_I, ω_m(1 ∓ δ/2).
    pub fn omega_extremes(&self) -> (Extremum, Extremum) {
        let half = 0.5 * self.delta * self.omega_mean;
        (
            (self.minimum.0, self.omega_mean - half),
            (self.maximum.0, self.omega_mean + half),
        )
    }

    /// The extremes of ε over the cycle: ε jumps where the loads do, so
    /// each kink-free segment is searched separately.
    pub fn epsilon_extremes(&self) -> Result<(Extremum, Extremum), MachineError> {
        let breaks = self.machine.breaks();
        let mut best_min = (0.0, f64::INFINITY);
        let mut best_max = (0.0, f64::NEG_INFINITY);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            let xs = numerics::samples(a, b, 1e-9 * (b - a), 64);
            let ys: Vec<f64> = xs
                .iter()
                .map(|&x| self.epsilon(x))
                .collect::<Result<_, _>>()?;
            for (sign, best) in [(1.0, &mut best_min), (-1.0, &mut best_max)] {
                let signed: Vec<f64> = ys.iter().map(|y| sign * y).collect();
                let k = numerics::argmin(&signed);
                let mut f = |phi: f64| self.epsilon(phi).map(|v| sign * v);
                let (x, fx) = numerics::refine(&mut f, &xs, k, 1e-10)?;
                let value = sign * fx;
                if sign * value < sign * best.1 {
                    *best = (x, value);
                }
            }
        }
        Ok((best_min, best_max))
    }
}

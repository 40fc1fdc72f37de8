//! The machine's real periodic motion under a motor: Runge–Kutta in the
//! kinetic energy over a cycle, shot on ω(0) until it repeats.

use super::{Extremum, Machine, MachineError, Reduced};
use crate::numerics;
use crate::runtime::Linkage;
use std::f64::consts::TAU;

/// How the machine is driven.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motor {
    /// A constant reduced driving moment.
    Constant { moment: f64 },
    /// A linear characteristic, reduced to φ: M_D(ω) = moment − slope·(ω −
    /// speed) (an induction motor near its working point).
    Linear { moment: f64, speed: f64, slope: f64 },
}

impl Motor {
    /// Every number finite, the working speed positive.
    fn check(&self) -> Result<(), MachineError> {
        let bad = |what, must, value| Err(MachineError::BadSetting { what, must, value });
        match *self {
            Motor::Constant { moment } if !moment.is_finite() => {
                bad("the driving moment", "finite", moment)
            }
            Motor::Linear { moment, .. } if !moment.is_finite() => {
                bad("the driving moment", "finite", moment)
            }
            Motor::Linear { speed, .. } if !(speed.is_finite() && speed > 0.0) => {
                bad("the motor's working speed", "positive and finite", speed)
            }
            Motor::Linear { slope, .. } if !slope.is_finite() => {
                bad("the motor characteristic's slope", "finite", slope)
            }
            _ => Ok(()),
        }
    }

    fn moment(&self, omega: f64) -> f64 {
        match *self {
            Motor::Constant { moment } => moment,
            Motor::Linear {
                moment,
                speed,
                slope,
            } => moment - slope * (omega - speed),
        }
    }
}

/// The machine's real periodic motion: d/dφ[½(J_I + J(φ))ω²] = M(φ) +
/// M_D(ω), integrated over a cycle (classical Runge–Kutta in the kinetic
/// energy, restarted at every kink) and shot on ω(0) until ω(2π) = ω(0).
/// With a constant driving moment every start is periodic (the energy
/// balances over a cycle); the shooting then fixes the mean speed,
/// ½(ω_max + ω_min) = ω_m, instead. The extremes of ω are located between
/// the grid's nodes, where ε = 0, on the Runge–Kutta solution continued
/// from the node before (or at a kink, where ε jumps through zero).
#[derive(Clone, Debug, PartialEq)]
pub struct SteadyMotion {
    /// The integration grid: about the requested number of steps, every
    /// kink a node.
    pub phi: Vec<f64>,
    pub omega: Vec<f64>,
    pub epsilon: Vec<f64>,
    /// (φ, ω) at the smallest and the largest ω, located.
    pub omega_min: Extremum,
    pub omega_max: Extremum,
    /// (ω_max − ω_min)/ω_m, ω_m = ½(ω_max + ω_min): the fluctuation achieved.
    pub delta: f64,
    /// The time of a cycle.
    pub period: f64,
}

impl SteadyMotion {
    pub(super) fn find<L: Linkage<M, 1>, const M: usize>(
        machine: &Machine<L, M>,
        inertia: f64,
        motor: Motor,
        omega_mean: f64,
        steps: usize,
    ) -> Result<SteadyMotion, MachineError> {
        for (what, value) in [
            ("the constant inertia", inertia),
            ("the mean speed", omega_mean),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MachineError::BadSetting {
                    what,
                    must: "positive and finite",
                    value,
                });
            }
        }
        motor.check()?;
        if !(10..=1_000_000).contains(&steps) {
            return Err(MachineError::BadSetting {
                what: "the number of integration steps",
                must: "from 10 to 10⁶",
                value: steps as f64,
            });
        }
        // The integration grid: about `steps` steps, every kink a node.
        let mut phis = Vec::new();
        for w in machine.breaks().windows(2) {
            let n = ((w[1] - w[0]) / TAU * steps as f64).ceil().max(2.0) as usize;
            for i in 0..n {
                phis.push(w[0] + (w[1] - w[0]) * i as f64 / n as f64);
            }
        }
        phis.push(TAU);
        let reduced: Vec<Reduced> = phis
            .iter()
            .map(|&p| machine.reduced(p))
            .collect::<Result<_, _>>()?;
        let grid = Step::along(machine, &phis)?;
        let accelerate = |r: &Reduced, w: f64| {
            (r.moment + motor.moment(w) - 0.5 * r.inertia_derivative * w * w)
                / (inertia + r.inertia)
        };
        // The motion from ω(0) = omega0: ω and ε at the nodes, and the
        // located extremes of ω.
        let run = |omega0: f64| -> Result<(Vec<f64>, Vec<f64>, Extremum, Extremum), MachineError> {
            let omega = integrate_energy(&grid, &phis, inertia, motor, omega0)?;
            let epsilon: Vec<f64> = reduced
                .iter()
                .zip(&omega)
                .map(|(r, &w)| accelerate(r, w))
                .collect();
            // (ω, ε) at φ between the nodes k and k + 1: one Runge–Kutta
            // step from node k, by the rule that made the grid.
            let continued = |k: usize, phi: f64| -> Result<(f64, f64), MachineError> {
                let h = phi - phis[k];
                if h == 0.0 {
                    return Ok((omega[k], epsilon[k]));
                }
                let at = |x: f64| machine.reduced(x).map(|r| (r.inertia, r.moment));
                let step = Step {
                    h,
                    nodes: [grid[k].nodes[0], at(phis[k] + 0.5 * h)?, at(phi)?],
                };
                let w = integrate_energy(&[step], &phis[k..], inertia, motor, omega[k])?[1];
                Ok((w, accelerate(&machine.reduced(phi)?, w)))
            };
            // An extreme of ω where ε changes sign next to the nodes'
            // extreme (from + to − at a maximum: `sign` = 1); at the node
            // itself if it does not (a kink, where ε jumps through zero).
            let locate = |k: usize, sign: f64| -> Result<Extremum, MachineError> {
                let before = k.checked_sub(1);
                let after = (k + 1 < phis.len()).then_some(k);
                for j in [before, after].into_iter().flatten() {
                    if sign * epsilon[j] > 0.0 && sign * epsilon[j + 1] < 0.0 {
                        let mut g = |phi: f64| continued(j, phi).map(|(_, e)| e);
                        let root = numerics::root(&mut g, phis[j], phis[j + 1])?;
                        return Ok((root, continued(j, root)?.0));
                    }
                }
                Ok((phis[k], omega[k]))
            };
            let kmin = numerics::argmin(&omega);
            let kmax = numerics::argmax(&omega);
            let (lo, hi) = (locate(kmin, -1.0)?, locate(kmax, 1.0)?);
            Ok((omega, epsilon, lo, hi))
        };
        let omega0 = match motor {
            Motor::Constant { .. } => {
                // ½(ω_max + ω_min) = ω_m.
                let mut g = |w0: f64| -> Result<f64, MachineError> {
                    let (_, _, lo, hi) = run(w0)?;
                    Ok(0.5 * (lo.1 + hi.1) - omega_mean)
                };
                bracket_root(&mut g, omega_mean)?
            }
            Motor::Linear { .. } => {
                let mut g = |w0: f64| -> Result<f64, MachineError> {
                    let w = integrate_energy(&grid, &phis, inertia, motor, w0)?;
                    Ok(w[w.len() - 1] - w0)
                };
                bracket_root(&mut g, omega_mean)?
            }
        };
        let (omega, epsilon, omega_min, omega_max) = run(omega0)?;
        let mean = 0.5 * (omega_min.1 + omega_max.1);
        // t = ∫ dφ/ω, by the trapezoid rule on the fine grid.
        let period = phis
            .windows(2)
            .zip(omega.windows(2))
            .map(|(p, w)| 0.5 * (p[1] - p[0]) * (1.0 / w[0] + 1.0 / w[1]))
            .sum();
        Ok(SteadyMotion {
            phi: phis,
            omega,
            epsilon,
            omega_min,
            omega_max,
            delta: (omega_max.1 - omega_min.1) / mean,
            period,
        })
    }
}

/// (J(φ), M(φ)) at the three points of one Runge–Kutta step: its start
/// and end taken just inside the step where they are kinks (one-sided),
/// and its middle.
struct Step {
    h: f64,
    nodes: [(f64, f64); 3],
}

impl Step {
    fn along<L: Linkage<M, 1>, const M: usize>(
        machine: &Machine<L, M>,
        phis: &[f64],
    ) -> Result<Vec<Step>, MachineError> {
        let is_kink = |x: f64| machine.kinks.contains(&x);
        let at = |phi: f64| machine.reduced(phi).map(|r| (r.inertia, r.moment));
        phis.windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let h = b - a;
                let inside = 1e-12 * h;
                Ok(Step {
                    h,
                    nodes: [
                        at(if is_kink(a) { a + inside } else { a })?,
                        at(0.5 * (a + b))?,
                        at(if is_kink(b) { b - inside } else { b })?,
                    ],
                })
            })
            .collect()
    }
}

/// ω at the steps' ends from ω(0) = omega0: classical Runge–Kutta on the
/// kinetic energy T = ½(J_I + J)ω², dT/dφ = M(φ) + M_D(ω).
fn integrate_energy(
    steps: &[Step],
    phis: &[f64],
    inertia: f64,
    motor: Motor,
    omega0: f64,
) -> Result<Vec<f64>, MachineError> {
    let rate = |(j, m): (f64, f64), t: f64, phi: f64| -> Result<f64, MachineError> {
        if t <= 0.0 {
            return Err(MachineError::Stalls { phi });
        }
        Ok(m + motor.moment((2.0 * t / (inertia + j)).sqrt()))
    };
    let mut t = 0.5 * (inertia + steps[0].nodes[0].0) * omega0 * omega0;
    let mut omega = vec![omega0];
    for (k, step) in steps.iter().enumerate() {
        let (h, [a, mid, b]) = (step.h, step.nodes);
        let phi = phis[k];
        let k1 = rate(a, t, phi)?;
        let k2 = rate(mid, t + 0.5 * h * k1, phi)?;
        let k3 = rate(mid, t + 0.5 * h * k2, phi)?;
        let k4 = rate(b, t + h * k3, phi)?;
        t += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if t <= 0.0 {
            return Err(MachineError::Stalls { phi: phis[k + 1] });
        }
        omega.push((2.0 * t / (inertia + b.0)).sqrt());
    }
    Ok(omega)
}

/// A root of g near x0 (> 0): bracketed by widening steps, then refined.
fn bracket_root(
    g: &mut impl FnMut(f64) -> Result<f64, MachineError>,
    x0: f64,
) -> Result<f64, MachineError> {
    let mut step = 0.02 * x0;
    let g0 = g(x0)?;
    if g0 == 0.0 {
        return Ok(x0);
    }
    for _ in 0..40 {
        for x in [x0 + step, (x0 - step).max(1e-9 * x0)] {
            let gx = match g(x) {
                Ok(v) => v,
                Err(MachineError::Stalls { .. }) => continue,
                Err(e) => return Err(e),
            };
            if gx == 0.0 {
                return Ok(x);
            }
            if (gx > 0.0) != (g0 > 0.0) {
                return numerics::root(g, x0, x);
            }
        }
        step *= 1.6;
    }
    Err(MachineError::NoSteadyState {
        omega: x0,
        why: "no sign change of the periodicity condition within a wide bracket",
    })
}

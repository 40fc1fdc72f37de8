//! Newton's method on one block of the equations, the other coordinates
//! held: damped (a backtracking line search, Levenberg–Marquardt where the
//! Newton step fails), with the roots already found deflated, then
//! polished to full precision by plain Newton steps.
//!
//! Everything is scale-free: equation i is divided by its size sᵢ, and
//! coordinate j measured in its unit (radians for an angle, the box's
//! half-width for a length).
//!
//! Deflation (Farrell, Birkisson and Funke, 2015): Newton's method on
//! G(x) = m(x)·Ψ(x), m(x) = Πₖ (1/‖x − xₖ‖² + 1) over the known roots xₖ,
//! has the roots of Ψ but the xₖ, and its step is the plain Newton step
//! d scaled by 1/(1 − ∇ln m·d): a start in a known root's basin is pushed
//! away from it, towards another root if there is one.

use super::scale::{Scale, wrap};
use super::structure::Block;
use crate::runtime::Linkage;
use nalgebra::{DMatrix, DVector, SVector};

/// Damped steps before a run is given up.
const MAX_STEPS: usize = 50;
/// The scale-free residual at which the damped iteration hands over to
/// the polish.
const CLOSE: f64 = 1e-10;
/// The scale-free residual a root must have once polished.
pub(crate) const ROOT_RESIDUAL: f64 = 1e-12;
/// Plain Newton steps of the polish, at most: a regular root takes two or
/// three; a double root (a dead centre) halves its error each step.
const MAX_POLISH: usize = 64;
/// A run whose length coordinate leaves its box by this many half-widths
/// is given up: it is diverging.
const FAR: f64 = 16.0;

/// One block's equations at the driver `v`, the other coordinates held at
/// those of the pose a run starts from.
pub(crate) struct BlockSystem<'a, L: ?Sized, const M: usize, const F: usize> {
    pub model: &'a L,
    pub v: &'a SVector<f64, F>,
    pub block: &'a Block,
    pub scale: &'a Scale<M>,
}

/// What a run ended with.
pub(crate) struct Run<const M: usize> {
    /// The root, polished, its angles in [−π, π).
    pub root: Option<SVector<f64, M>>,
    /// The least scale-free residual met.
    pub least_residual: f64,
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> BlockSystem<'_, L, M, F> {
    fn size(&self) -> usize {
        self.block.coordinates.len()
    }

    /// The block's scale-free residuals Ψᵢ/sᵢ and their Jacobian by its
    /// coordinates in their units; `None` if not finite.
    pub fn evaluate(&self, u: &SVector<f64, M>) -> Option<(DVector<f64>, DMatrix<f64>)> {
        let (psi, psi_u) = self.model.psi_and_psi_u(u, self.v);
        let (rows, columns) = (&self.block.equations, &self.block.coordinates);
        let sizes = &self.scale.equations;
        let d = self.size();
        let r = DVector::from_fn(d, |a, _| psi[rows[a]] / sizes[rows[a]]);
        let j = DMatrix::from_fn(d, d, |a, b| {
            psi_u[(rows[a], columns[b])] * self.scale.unit(columns[b]) / sizes[rows[a]]
        });
        let finite = r.iter().chain(j.iter()).all(|x| x.is_finite());
        finite.then_some((r, j))
    }

    /// `u` moved by the step `d` (in the block's coordinates and units),
    /// its angles wrapped; `None` if a length leaves its box far behind.
    fn moved(&self, u: &SVector<f64, M>, d: &DVector<f64>) -> Option<SVector<f64, M>> {
        let mut next = *u;
        for (b, &j) in self.block.coordinates.iter().enumerate() {
            let unit = self.scale.unit(j);
            next[j] += d[b] * unit;
            if self.scale.angle[j] {
                next[j] = wrap(next[j]);
            } else {
                let centre = 0.5 * (self.scale.lower[j] + self.scale.upper[j]);
                let within = (next[j] - centre).abs() <= FAR * unit;
                if !within {
                    return None;
                }
            }
        }
        Some(next)
    }

    /// ∇ln m at `u` (in the block's units) and ln m, m the deflation of
    /// the known roots `deflated`.
    fn deflation(&self, u: &SVector<f64, M>, deflated: &[SVector<f64, M>]) -> (DVector<f64>, f64) {
        let d = self.size();
        let mut gradient = DVector::zeros(d);
        let mut log = 0.0;
        for root in deflated {
            let offset = DVector::from_fn(d, |b, _| {
                let j = self.block.coordinates[b];
                self.scale.difference(j, u[j], root[j])
            });
            let squared = offset.norm_squared();
            // ln(1/‖Δ‖² + 1) and its gradient −2Δ/(‖Δ‖²(1 + ‖Δ‖²)).
            log += (1.0 / squared).ln_1p();
            gradient -= offset * (2.0 / (squared * (1.0 + squared)));
        }
        (gradient, log)
    }

    /// ln of the merit ½‖m·Ψ‖² (up to a constant): 2 ln m + ln ‖Ψ‖².
    fn log_merit(&self, u: &SVector<f64, M>, deflated: &[SVector<f64, M>]) -> Option<f64> {
        let (r, _) = self.evaluate(u)?;
        let log_m = if deflated.is_empty() {
            0.0
        } else {
            self.deflation(u, deflated).1
        };
        let value = 2.0 * log_m + r.norm_squared().ln();
        (!value.is_nan()).then_some(value)
    }

    /// Newton's method from `start` on the block, the roots `deflated`
    /// deflated; a root it reaches is polished.
    pub fn solve(&self, start: &SVector<f64, M>, deflated: &[SVector<f64, M>]) -> Run<M> {
        let mut least = f64::INFINITY;
        let mut u = *start;
        let mut mu = 1e-6;
        for _ in 0..MAX_STEPS {
            let Some((r, j)) = self.evaluate(&u) else {
                break;
            };
            let residual = r.amax();
            least = least.min(residual);
            if residual <= CLOSE {
                return self.polish(u, least);
            }
            let Some(here) = self.log_merit(&u, deflated) else {
                break;
            };
            let step = self
                .newton_step(&u, &r, &j, deflated, here)
                .or_else(|| self.levenberg_marquardt_step(&u, &r, &j, deflated, here, &mut mu));
            match step {
                Some(next) => u = next,
                None => break,
            }
        }
        Run {
            root: None,
            least_residual: least,
        }
    }

    /// The (deflated) Newton step, shortened until the merit decreases.
    fn newton_step(
        &self,
        u: &SVector<f64, M>,
        r: &DVector<f64>,
        j: &DMatrix<f64>,
        deflated: &[SVector<f64, M>],
        here: f64,
    ) -> Option<SVector<f64, M>> {
        let mut d = -j.clone().lu().solve(r)?;
        if !deflated.is_empty() {
            let (gradient, _) = self.deflation(u, deflated);
            let denominator = 1.0 - gradient.dot(&d);
            let pushed = denominator.abs() > 1e-12; // false for NaN
            if !pushed {
                return None;
            }
            d /= denominator;
        }
        if !d.iter().all(|x| x.is_finite()) {
            return None;
        }
        let mut lambda = 1.0;
        while lambda >= 1.0 / 1024.0 {
            if let Some(next) = self.moved(u, &(&d * lambda)) {
                if self
                    .log_merit(&next, deflated)
                    .is_some_and(|there| there <= here + (1.0 - 1e-4 * lambda).ln())
                {
                    return Some(next);
                }
            }
            lambda *= 0.5;
        }
        None
    }

    /// A Levenberg–Marquardt step −(JᵀJ + μ·s·I)⁻¹JᵀΨ, μ raised until the
    /// merit decreases (and lowered after a success).
    fn levenberg_marquardt_step(
        &self,
        u: &SVector<f64, M>,
        r: &DVector<f64>,
        j: &DMatrix<f64>,
        deflated: &[SVector<f64, M>],
        here: f64,
        mu: &mut f64,
    ) -> Option<SVector<f64, M>> {
        let jtj = j.transpose() * j;
        let gradient = j.transpose() * r;
        let s = jtj.amax().max(f64::MIN_POSITIVE);
        let n = self.size();
        while *mu <= 1e6 {
            let a = &jtj + DMatrix::identity(n, n) * (*mu * s);
            if let Some(d) = a.lu().solve(&gradient) {
                if let Some(next) = self.moved(u, &(-d)) {
                    if self
                        .log_merit(&next, deflated)
                        .is_some_and(|there| there < here)
                    {
                        *mu = (*mu / 10.0).max(1e-12);
                        return Some(next);
                    }
                }
            }
            *mu *= 10.0;
        }
        None
    }

    /// Plain Newton steps from a pose close to a root, while they shrink
    /// the residual: the root to full precision, if its residual is small
    /// enough then.
    fn polish(&self, mut u: SVector<f64, M>, least: f64) -> Run<M> {
        let mut least = least;
        let Some((mut r, mut j)) = self.evaluate(&u) else {
            return Run {
                root: None,
                least_residual: least,
            };
        };
        for _ in 0..MAX_POLISH {
            let residual = r.amax();
            least = least.min(residual);
            if residual == 0.0 {
                break;
            }
            let Some(d) = j.clone().lu().solve(&r) else {
                break;
            };
            let Some(next) = self.moved(&u, &(-&d)) else {
                break;
            };
            let Some((r_next, j_next)) = self.evaluate(&next) else {
                break;
            };
            if r_next.amax() > residual {
                break;
            }
            let size = d.amax();
            (u, r, j) = (next, r_next, j_next);
            if size <= 4.0 * f64::EPSILON {
                break;
            }
        }
        let residual = r.amax();
        least = least.min(residual);
        Run {
            root: (residual <= ROOT_RESIDUAL).then_some(u),
            least_residual: least,
        }
    }
}

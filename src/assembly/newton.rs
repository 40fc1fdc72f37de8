//! Newton's method on one block of the equations, the other coordinates
//! held: damped (a backtracking line search, Levenberg–Marquardt where the
//! Newton step fails), with the roots already found deflated, then
//! polished to full precision by plain Newton steps.
//!
//! Everything is scale-free: equation i is divided by its size sᵢ, and
//! coordinate j measured in its unit (radians for an angle, the box's
//! half-width for a length). A block of d equations is carried in the
//! first d entries of m-vectors, its Jacobian padded with the identity to
//! m × m: no allocation, and the padding's steps are zero.
//!
//! Deflation (Farrell, Birkisson and Funke, 2015): Newton's method on
//! G(x) = m(x)·Ψ(x), m(x) = Πₖ (1/‖x − xₖ‖² + 1) over the known roots xₖ,
//! has the roots of Ψ but the xₖ, and its step is the plain Newton step
//! d scaled by 1/(1 − ∇ln m·d): a start in a known root's basin is pushed
//! away from it, towards another root if there is one.

use super::scale::{Scale, wrap};
use super::structure::Block;
use crate::runtime::Linkage;
use nalgebra::{SMatrix, SVector};

/// Damped steps before a run is given up...
const MAX_STEPS: usize = 50;
/// ... or, with roots deflated, this many: a root deflation leads to is
/// near, and once every root is known the run only wanders.
const MAX_DEFLATED_STEPS: usize = 20;
/// The scale-free residual at which the damped iteration hands over to
/// the polish.
const CLOSE: f64 = 1e-10;
/// The scale-free residual a root must have once polished.
const ROOT_RESIDUAL: f64 = 1e-12;
/// Plain Newton steps of the polish, at most: a regular root takes two or
/// three; a double root (a dead centre) halves its error each step.
const MAX_POLISH: usize = 64;
/// The relative gradient of ‖Ψ‖² below which a pose that is not a root
/// is a least-squares minimum (or another stationary point) of it.
const STATIONARY: f64 = 1e-6;
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

/// A pose of a run, the block evaluated there.
struct Point<const M: usize> {
    u: SVector<f64, M>,
    /// The scale-free residuals (the block's first, zeros after).
    r: SVector<f64, M>,
    /// Their Jacobian, padded with the identity.
    j: SMatrix<f64, M, M>,
    /// ln of the deflated merit.
    log_merit: f64,
}

/// What a run ended with.
pub(crate) struct Run<const M: usize> {
    /// The root, polished, its angles in [−π, π).
    pub root: Option<SVector<f64, M>>,
    /// The least scale-free residual met.
    pub least_residual: f64,
}

/// x solving a·x = b (LU with partial pivoting), if `a` is not singular
/// and x is finite.
fn solve<const M: usize>(a: &SMatrix<f64, M, M>, b: &SVector<f64, M>) -> Option<SVector<f64, M>> {
    let (mut a, mut x) = (*a, *b);
    for col in 0..M {
        let pivot = (col..M).max_by(|&i, &k| a[(i, col)].abs().total_cmp(&a[(k, col)].abs()))?;
        if a[(pivot, col)] == 0.0 {
            return None;
        }
        a.swap_rows(col, pivot);
        x.swap_rows(col, pivot);
        for i in col + 1..M {
            let factor = a[(i, col)] / a[(col, col)];
            if factor != 0.0 {
                for k in col..M {
                    a[(i, k)] -= factor * a[(col, k)];
                }
                x[i] -= factor * x[col];
            }
        }
    }
    for col in (0..M).rev() {
        let known: f64 = (col + 1..M).map(|k| a[(col, k)] * x[k]).sum();
        x[col] = (x[col] - known) / a[(col, col)];
    }
    x.iter().all(|x| x.is_finite()).then_some(x)
}

/// Whether a pose that is not a root is a stationary point of ‖Ψ‖²
/// (JᵀΨ ≈ 0): the largest |cos| of the angle between Ψ and a column of J
/// below [`STATIONARY`]. There the mechanism comes closest to closing
/// without closing, and the run ends.
fn stationary<const M: usize>(point: &Point<M>) -> bool {
    let r = point.r / point.r.amax();
    let worst = point
        .j
        .column_iter()
        .map(|c| {
            let norm = c.norm();
            if norm > 0.0 {
                c.dot(&r).abs() / norm
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max);
    worst <= STATIONARY * r.norm()
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> BlockSystem<'_, L, M, F> {
    fn size(&self) -> usize {
        self.block.coordinates.len()
    }

    /// The block's scale-free residuals Ψᵢ/sᵢ and their Jacobian by its
    /// coordinates in their units (padded); `None` if not finite.
    pub fn evaluate(&self, u: &SVector<f64, M>) -> Option<(SVector<f64, M>, SMatrix<f64, M, M>)> {
        let (psi, psi_u) = self.model.psi_and_psi_u(u, self.v);
        let (rows, columns) = (&self.block.equations, &self.block.coordinates);
        let sizes = &self.scale.equations;
        let d = self.size();
        let r = SVector::<f64, M>::from_fn(|a, _| {
            if a < d {
                psi[rows[a]] / sizes[rows[a]]
            } else {
                0.0
            }
        });
        let j = SMatrix::<f64, M, M>::from_fn(|a, b| match (a < d, b < d) {
            (true, true) => {
                psi_u[(rows[a], columns[b])] * self.scale.unit(columns[b]) / sizes[rows[a]]
            }
            _ => f64::from(u8::from(a == b)),
        });
        let finite = r.iter().chain(j.iter()).all(|x| x.is_finite());
        finite.then_some((r, j))
    }

    /// `u` moved by the step `d` (in the block's coordinates and units),
    /// its angles wrapped; `None` if a length leaves its box far behind.
    fn moved(&self, u: &SVector<f64, M>, d: &SVector<f64, M>) -> Option<SVector<f64, M>> {
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
    fn deflation(
        &self,
        u: &SVector<f64, M>,
        deflated: &[SVector<f64, M>],
    ) -> (SVector<f64, M>, f64) {
        let d = self.size();
        let mut gradient = SVector::<f64, M>::zeros();
        let mut log = 0.0;
        for root in deflated {
            let offset = SVector::<f64, M>::from_fn(|b, _| {
                if b < d {
                    let j = self.block.coordinates[b];
                    self.scale.difference(j, u[j], root[j])
                } else {
                    0.0
                }
            });
            let squared = offset.norm_squared();
            // ln(1/‖Δ‖² + 1) and its gradient −2Δ/(‖Δ‖²(1 + ‖Δ‖²)).
            log += (1.0 / squared).ln_1p();
            gradient -= offset * (2.0 / (squared * (1.0 + squared)));
        }
        (gradient, log)
    }

    /// The block evaluated at `u`, with the merit of the deflated system:
    /// `None` where it is not finite.
    fn point(&self, u: SVector<f64, M>, deflated: &[SVector<f64, M>]) -> Option<Point<M>> {
        let (r, j) = self.evaluate(&u)?;
        let log_m = if deflated.is_empty() {
            0.0
        } else {
            self.deflation(&u, deflated).1
        };
        // ln of the merit ½‖m·Ψ‖² (up to a constant): 2 ln m + ln ‖Ψ‖².
        let log_merit = 2.0 * log_m + r.norm_squared().ln();
        (!log_merit.is_nan()).then_some(Point { u, r, j, log_merit })
    }

    /// Newton's method from `start` on the block, the roots `deflated`
    /// deflated; a root it reaches is polished.
    pub fn solve(&self, start: &SVector<f64, M>, deflated: &[SVector<f64, M>]) -> Run<M> {
        let mut least = f64::INFINITY;
        let mut here = self.point(*start, deflated);
        let mut mu = 1e-6;
        let steps = if deflated.is_empty() {
            MAX_STEPS
        } else {
            MAX_DEFLATED_STEPS
        };
        for _ in 0..steps {
            let Some(point) = here else {
                break;
            };
            let residual = point.r.amax();
            least = least.min(residual);
            if residual <= CLOSE {
                return self.polish(point, least);
            }
            if stationary(&point) {
                break;
            }
            // With roots deflated, no fallback: where the deflated Newton
            // step fails the run only wanders.
            here = self.newton_step(&point, deflated).or_else(|| {
                deflated
                    .is_empty()
                    .then(|| self.levenberg_marquardt_step(&point, deflated, &mut mu))
                    .flatten()
            });
        }
        Run {
            root: None,
            least_residual: least,
        }
    }

    /// The (deflated) Newton step, shortened until the merit decreases.
    fn newton_step(&self, here: &Point<M>, deflated: &[SVector<f64, M>]) -> Option<Point<M>> {
        let mut d = -solve(&here.j, &here.r)?;
        if !deflated.is_empty() {
            let (gradient, _) = self.deflation(&here.u, deflated);
            let denominator = 1.0 - gradient.dot(&d);
            let pushed = denominator.abs() > 1e-12; // false for NaN
            if !pushed {
                return None;
            }
            d /= denominator;
        }
        let mut lambda = 1.0;
        while lambda >= 1.0 / 1024.0 {
            let next = self
                .moved(&here.u, &(d * lambda))
                .and_then(|u| self.point(u, deflated));
            if let Some(next) = next {
                if next.log_merit <= here.log_merit + (1.0 - 1e-4 * lambda).ln() {
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
        here: &Point<M>,
        deflated: &[SVector<f64, M>],
        mu: &mut f64,
    ) -> Option<Point<M>> {
        let jtj = here.j.transpose() * here.j;
        let gradient = here.j.transpose() * here.r;
        let s = jtj.amax().max(f64::MIN_POSITIVE);
        while *mu <= 1e6 {
            let a = jtj + SMatrix::<f64, M, M>::identity() * (*mu * s);
            let next = solve(&a, &gradient)
                .and_then(|d| self.moved(&here.u, &(-d)))
                .and_then(|u| self.point(u, deflated));
            if let Some(next) = next {
                if next.log_merit < here.log_merit {
                    *mu = (*mu / 10.0).max(1e-12);
                    return Some(next);
                }
            }
            *mu *= 10.0;
        }
        None
    }

    /// Plain Newton steps from a pose close to a root, while they shrink
    /// the residual: the root to full precision, if its residual is small
    /// enough then.
    fn polish(&self, close: Point<M>, least: f64) -> Run<M> {
        let mut least = least;
        let Point {
            mut u,
            mut r,
            mut j,
            ..
        } = close;
        for _ in 0..MAX_POLISH {
            let residual = r.amax();
            least = least.min(residual);
            if residual == 0.0 {
                break;
            }
            let Some(d) = solve(&j, &r) else {
                break;
            };
            let Some(next) = self.moved(&u, &(-d)) else {
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

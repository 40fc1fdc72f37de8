//! A Levenberg–Marquardt least-squares solver with bounds, driven by exact
//! Jacobians.
//!
//! Why our own: the `levenberg-marquardt` crate (the nalgebra-native one)
//! is built on nalgebra 0.34 while linkage is on 0.35 (num-dual's), so
//! every residual and Jacobian would cross between two nalgebras, and it
//! has no bounds; `argmin` has Gauss–Newton but no bounded
//! Levenberg–Marquardt. The problems here are small (tens of unknowns),
//! so a dense solver is the right tool.
//!
//! The method (Moré 1978, "The Levenberg–Marquardt algorithm:
//! implementation and theory", with Nielsen's damping update): minimise
//! ½‖r(x)‖² for lower ≤ x ≤ upper. At x, with J = ∂r/∂x and g = Jᵀr, the
//! unknowns held at a bound by the gradient (at the lower bound with
//! g > 0, at the upper with g < 0) are fixed; the others take the step
//! (JᵀJ + λ D) δ = −g, D the largest diagonal of JᵀJ seen (scale
//! invariance); the trial x + δ is projected onto the bounds and accepted
//! if the actual reduction is at least 1e-4 of the one the model predicts.
//! λ shrinks by max(1/3, 1 − (2ρ − 1)³) after a success and doubles
//! (doubling its factor) after a failure. A trial the model cannot be
//! evaluated at (a design that does not assemble) is a failure. After
//! twenty failures in a row the solver stops: no step, however short,
//! reduces the cost (a minimum at rounding level, or a fold of the
//! assembly the start cannot get past); after three in a row as soon as
//! each of them is a step that changes no unknown by more than 1e-10 of
//! its size, which only rounding keeps from reducing a smooth cost (a
//! minimum polished to rounding: more trials would only redraw the
//! rounding errors). It stops too after
//! [`Stopping::unevaluable`] trials in all that could not be evaluated:
//! steps that keep running into a fold while creeping along it.

use nalgebra::{DMatrix, DVector};

/// A least-squares problem that cannot be started.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum LeastSquaresError {
    /// The bounds of unknown `unknown` are empty or not finite, or the
    /// bounds and the start differ in length (NaN then stands for the
    /// missing bound).
    EmptyBounds {
        unknown: usize,
        lower: f64,
        upper: f64,
    },
    /// The residuals cannot be evaluated at the start (or are not finite,
    /// or of the wrong shape there).
    NotEvaluable,
}

crate::error::error_impls! {
    LeastSquaresError {
        Self::EmptyBounds { unknown, lower, upper } => ("the bounds [{lower}, {upper}] of unknown {unknown} are empty, not finite, or missing"),
        Self::NotEvaluable => ("the residuals cannot be evaluated at the start (or are not finite there)"),
    }
    wraps {}
}

/// Failed trials in a row after which the solver stops. Each failure
/// raises λ (by a factor that doubles each time), so by then the steps
/// tried have shrunk past any length at which the cost still decreases: x
/// sits at a minimum to rounding (above [`Stopping::cost`]), or against a
/// fold of the assembly its steps cannot cross.
pub(crate) const STALLED: usize = 20;

/// Failed trials in a row, each of a step that changes no unknown by more
/// than [`ROUNDING_STEP`] of its size, after which the solver stops: a
/// step that short reduces a smooth cost unless rounding decides the
/// comparison, so x is at a minimum to rounding (a zero of the residuals,
/// polished) and further trials only redraw the rounding errors.
const STALLED_AT_ROUNDING: usize = 3;

/// The step, relative to each unknown's size, below which a failed trial
/// counts towards [`STALLED_AT_ROUNDING`].
const ROUNDING_STEP: f64 = 1e-10;

/// The residuals and their Jacobian at a point, and whatever the
/// evaluation carries to the next (the poses, to start the next solves
/// from).
pub(crate) struct Evaluation<S> {
    pub residuals: DVector<f64>,
    pub jacobian: DMatrix<f64>,
    pub state: S,
}

/// When to stop. Every test but `cost` is free of the problem's scale: a
/// problem and the same problem in other units stop at the same point.
/// [`Stopping::default`]: `cost` 0, `gradient` 1e-13, `step` 1e-15, at
/// most 400 evaluations, of which at most 24 cannot be evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stopping {
    /// Stop when ½‖r‖² falls to this (absolute: 0, the default, stops
    /// only at an exact zero).
    pub cost: f64,
    /// Stop when no unknown free to move (not held at a bound by the
    /// gradient) can change the cost c = ½‖r‖² by more than this relative
    /// to c per relative change of itself: |∂c/∂xᵢ|·|xᵢ| ≤ `gradient`·c
    /// (|xᵢ| at least 1e-3 of the largest unknown's) — a minimum, in any
    /// units. (Where the residuals can vanish the ratio grows as they
    /// shrink, so the solver polishes on to rounding.)
    pub gradient: f64,
    /// Stop when a step changes no unknown by more than this relative to
    /// its size (at least 1e-3 of the largest unknown's, for one near
    /// zero). Near a solution Gauss–Newton's steps shrink quadratically,
    /// so the step that falls below this is the last one that changed
    /// anything.
    pub step: f64,
    /// The most evaluations.
    pub evaluations: usize,
    /// The most trials that cannot be evaluated (a design that does not
    /// assemble, or cannot be followed from the last one), in all. On
    /// pylinkage's README task (docs/performance.md) a synthesis's start
    /// that meets its targets runs into none in the median and never more
    /// than 9; one that ends away from them, pressed against a fold of the
    /// assembly, into 85 in the median, each one a follow that fails at
    /// the fold. Stopping at 24 gives those up at a third of their cost,
    /// and loses no certified design there nor on the 5- and 9-point
    /// tasks.
    pub unevaluable: usize,
}

impl Default for Stopping {
    fn default() -> Stopping {
        Stopping {
            cost: 0.0,
            gradient: 1e-13,
            step: 1e-15,
            evaluations: 400,
            unevaluable: 24,
        }
    }
}

/// What [`least_squares`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct LeastSquares {
    /// Where it stopped (within the bounds).
    pub x: DVector<f64>,
    /// r(x)
    pub residuals: DVector<f64>,
    /// The evaluations it took.
    pub evaluations: usize,
}

/// Minimises ½‖r(x)‖² for `lower` ≤ x ≤ `upper` from `x0` (projected onto
/// the bounds) by the bounded Levenberg–Marquardt method
/// [`synthesis`](crate::synthesis) uses (see the module's documentation): for objectives of one's own —
/// a design's cost with its exact gradient, say (a scalar cost c ≥ 0 as
/// the one residual √c, its Jacobian ∇c/(2√c)). `residuals` gives r(x)
/// and ∂r/∂x, or `None` where x cannot be evaluated (a trial there only
/// shortens the step). Typed errors: bounds of the wrong length, empty or
/// not finite ([`LeastSquaresError::EmptyBounds`]), and a start that
/// cannot be evaluated ([`LeastSquaresError::NotEvaluable`]).
pub fn least_squares(
    x0: DVector<f64>,
    lower: &DVector<f64>,
    upper: &DVector<f64>,
    stopping: &Stopping,
    mut residuals: impl FnMut(&DVector<f64>) -> Option<(DVector<f64>, DMatrix<f64>)>,
) -> Result<LeastSquares, LeastSquaresError> {
    let n = x0.len();
    for i in 0..n.max(lower.len()).max(upper.len()) {
        let (lo, hi) = (
            lower.get(i).copied().unwrap_or(f64::NAN),
            upper.get(i).copied().unwrap_or(f64::NAN),
        );
        if !(lo <= hi && lo.is_finite() && hi.is_finite()) || i >= n {
            return Err(LeastSquaresError::EmptyBounds {
                unknown: i,
                lower: lo,
                upper: hi,
            });
        }
    }
    let x0 = DVector::from_fn(n, |i, _| x0[i].clamp(lower[i], upper[i]));
    let mut evaluate = |x: &DVector<f64>, _: &()| {
        residuals(x).and_then(|(r, j)| {
            let usable = j.nrows() == r.len()
                && j.ncols() == n
                && r.iter().chain(j.iter()).all(|v| v.is_finite());
            usable.then_some(Evaluation {
                residuals: r,
                jacobian: j,
                state: (),
            })
        })
    };
    let Some(first) = evaluate(&x0, &()) else {
        return Err(LeastSquaresError::NotEvaluable);
    };
    let found = minimize(first, x0, lower, upper, stopping, evaluate);
    Ok(LeastSquares {
        x: found.x,
        residuals: found.residuals,
        evaluations: found.evaluations,
    })
}

/// Where the solver stopped.
pub(crate) struct Minimum<S> {
    pub x: DVector<f64>,
    pub residuals: DVector<f64>,
    pub state: S,
    pub evaluations: usize,
}

/// Minimises ½‖r(x)‖² within the bounds from `x0` (projected onto them),
/// whose evaluation is `first`; `None` if no evaluation succeeds.
pub(crate) fn minimize<S>(
    first: Evaluation<S>,
    x0: DVector<f64>,
    lower: &DVector<f64>,
    upper: &DVector<f64>,
    stopping: &Stopping,
    mut evaluate: impl FnMut(&DVector<f64>, &S) -> Option<Evaluation<S>>,
) -> Minimum<S> {
    let n = x0.len();
    let mut x = x0;
    let mut at = first;
    let mut cost = 0.5 * at.residuals.norm_squared();
    let mut scale = DVector::<f64>::zeros(n);
    let (mut lambda, mut growth) = (None::<f64>, 2.0);
    let mut evaluations = 1;
    let mut iterations = 0;
    let mut failures = 0;
    let mut failures_at_rounding = 0;
    let mut unevaluable = 0;
    // JᵀJ and g of the current point, kept while trials are rejected.
    let mut normal: Option<(DMatrix<f64>, DVector<f64>)> = None;
    while evaluations < stopping.evaluations
        && cost > stopping.cost
        && failures < STALLED
        && failures_at_rounding < STALLED_AT_ROUNDING
        && unevaluable < stopping.unevaluable
    {
        let (jtj, g) = normal.get_or_insert_with(|| {
            let j = &at.jacobian;
            (j.transpose() * j, j.transpose() * &at.residuals)
        });
        let (jtj, g) = (&*jtj, &*g);
        for i in 0..n {
            scale[i] = scale[i].max(jtj[(i, i)]).max(f64::MIN_POSITIVE);
        }
        // The projected gradient (zero where a bound holds the unknown
        // against the descent) against the cost. (Not x − clamp(x − g):
        // that subtracts the gradient from x, and in units where x is
        // large beside g it rounds to zero far from the minimum.)
        let held = |i: usize| (x[i] <= lower[i] && g[i] > 0.0) || (x[i] >= upper[i] && g[i] < 0.0);
        let size = x.amax();
        let stationary = (0..n).all(|i| {
            let scale = x[i].abs().max(1e-3 * size);
            held(i) || g[i] == 0.0 || scale > 0.0 && g[i].abs() * scale <= stopping.gradient * cost
        });
        if stationary {
            break;
        }
        let mut free: Vec<usize> = (0..n).filter(|&i| !held(i)).collect();
        let lam = *lambda.get_or_insert_with(|| 1e-3 * scale.max());
        // The step on the free unknowns; an unknown at a bound that the step
        // would push out is held too, and the step taken again without it.
        let step = loop {
            let Some(step) = damped_step(jtj, g, &scale, lam, &free, n) else {
                break None;
            };
            let before = free.len();
            free.retain(|&i| {
                !((x[i] <= lower[i] && step[i] < 0.0) || (x[i] >= upper[i] && step[i] > 0.0))
            });
            if free.len() == before {
                break Some(step);
            }
        };
        let Some(step) = step else {
            lambda = Some(lam * growth);
            growth *= 2.0;
            continue;
        };
        let promise = |s: &DVector<f64>| -(g.dot(s) + 0.5 * s.dot(&(jtj * s)));
        let s = within_bounds(&x, &step, lower, upper, &promise);
        let trial = &x + &s;
        let predicted = promise(&s);
        let within = |s: &DVector<f64>, relative: f64| {
            (0..n).all(|i| s[i].abs() <= relative * x[i].abs().max(1e-3 * size))
        };
        let small = |s: &DVector<f64>| within(s, stopping.step);
        // A step too small to change x, or one that promises no reduction:
        // converged, once λ is as small as it goes (a step is small because λ
        // is large only until λ drops). The reduction itself is computed
        // without cancellation (below), so tiny promises are still tested.
        if small(&s) || predicted <= 0.0 {
            if lam <= 1e-12 * scale.max() {
                break;
            }
            lambda = Some((lam * 1e-3).max(1e-12 * scale.max()));
            iterations += 1;
            if iterations > 4 * stopping.evaluations {
                break;
            }
            continue;
        }
        evaluations += 1;
        let trial_evaluation = evaluate(&trial, &at.state);
        unevaluable += usize::from(trial_evaluation.is_none());
        let accepted = trial_evaluation.and_then(|next| {
            let trial_cost = 0.5 * next.residuals.norm_squared();
            // ½(‖r‖² − ‖r₊‖²) as ½(r − r₊)·(r + r₊): the reduction without
            // the cancellation of two nearly equal costs.
            let reduction =
                0.5 * (&at.residuals - &next.residuals).dot(&(&at.residuals + &next.residuals));
            let rho = reduction / predicted;
            (predicted > 0.0 && rho > 1e-4 && trial_cost.is_finite())
                .then_some((next, trial_cost, rho))
        });
        match accepted {
            Some((next, trial_cost, rho)) => {
                failures = 0;
                failures_at_rounding = 0;
                x = trial;
                at = next;
                normal = None;
                cost = trial_cost;
                lambda = Some(lam * (1.0 / 3.0f64).max(1.0 - (2.0 * rho - 1.0).powi(3)));
                growth = 2.0;
            }
            None => {
                failures += 1;
                if within(&s, ROUNDING_STEP) {
                    failures_at_rounding += 1;
                } else {
                    failures_at_rounding = 0;
                }
                lambda = Some(lam * growth);
                growth *= 2.0;
            }
        }
    }
    Minimum {
        x,
        residuals: at.residuals,
        state: at.state,
        evaluations,
    }
}

/// The step kept within the bounds, projected onto them or cut short at
/// the first it meets, whichever the model promises more from (a projected
/// Gauss–Newton step can turn uphill where a bound cuts it; the cut-short
/// one stays on the step's descent direction).
fn within_bounds(
    x: &DVector<f64>,
    step: &DVector<f64>,
    lower: &DVector<f64>,
    upper: &DVector<f64>,
    promise: &impl Fn(&DVector<f64>) -> f64,
) -> DVector<f64> {
    let n = x.len();
    let projected = DVector::from_fn(n, |i, _| (x[i] + step[i]).clamp(lower[i], upper[i]) - x[i]);
    let fraction = (0..n)
        .map(|i| {
            let room = if step[i] > 0.0 {
                upper[i] - x[i]
            } else {
                lower[i] - x[i]
            };
            if step[i] != 0.0 {
                (room / step[i]).clamp(0.0, 1.0)
            } else {
                1.0
            }
        })
        .fold(1.0, f64::min);
    let cut = step * fraction;
    if promise(&cut) > promise(&projected) {
        cut
    } else {
        projected
    }
}

/// The step on the free unknowns: (JᵀJ + λD) δ = −g restricted to them,
/// zero on the held ones; `None` if the system is not positive definite.
fn damped_step(
    jtj: &DMatrix<f64>,
    g: &DVector<f64>,
    scale: &DVector<f64>,
    lambda: f64,
    free: &[usize],
    n: usize,
) -> Option<DVector<f64>> {
    let k = free.len();
    let system = DMatrix::from_fn(k, k, |a, b| {
        jtj[(free[a], free[b])] + if a == b { lambda * scale[free[a]] } else { 0.0 }
    });
    let rhs = DVector::from_fn(k, |a, _| -g[free[a]]);
    let solved = system.cholesky()?.solve(&rhs);
    let mut step = DVector::zeros(n);
    for (a, &i) in free.iter().enumerate() {
        step[i] = solved[a];
    }
    step.iter().all(|x| x.is_finite()).then_some(step)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock's function as least squares: r = (10(x₂ − x₁²), 1 − x₁).
    fn rosenbrock(x: &DVector<f64>, _: &()) -> Option<Evaluation<()>> {
        Some(Evaluation {
            residuals: DVector::from_vec(vec![10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]]),
            jacobian: DMatrix::from_row_slice(2, 2, &[-20.0 * x[0], 10.0, -1.0, 0.0]),
            state: (),
        })
    }

    /// Residuals with errors of their own: the solver polishes the cost
    /// down to those errors, then stops within a few trials (37 trials
    /// there when only twenty failures in a row stopped it, each redrawing
    /// the errors).
    #[test]
    fn a_minimum_at_rounding_ends_the_solve_within_a_few_trials() {
        // Two residuals of three unknowns: a curve of zeros, as a
        // synthesis with more unknowns than targets; each residual with an
        // error of up to 5e-13 that changes with x in every bit, as that of
        // a residual computed by an iterative solve (a synthesis's poses).
        let costs = std::cell::RefCell::new(Vec::new());
        let noise = |x: &DVector<f64>, k: u64| {
            let bits = x.iter().fold(k, |h, v| {
                (h ^ v.to_bits()).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            });
            1e-12 * ((bits >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
        };
        let residuals = |x: &DVector<f64>, _: &()| {
            let r = DVector::from_vec(vec![
                x[0] * x[0] + x[1] * x[1] - 2.0 + noise(x, 1),
                x[0] * x[2] - std::f64::consts::PI + noise(x, 2),
            ]);
            costs.borrow_mut().push(0.5 * r.norm_squared());
            Some(Evaluation {
                residuals: r,
                jacobian: DMatrix::from_row_slice(
                    2,
                    3,
                    &[2.0 * x[0], 2.0 * x[1], 0.0, x[2], 0.0, x[0]],
                ),
                state: (),
            })
        };
        let x0 = DVector::from_vec(vec![3.0, 0.5, -1.0]);
        let first = residuals(&x0, &()).unwrap();
        let bounds = DVector::from_element(3, 10.0);
        let found = minimize(
            first,
            x0,
            &-&bounds,
            &bounds,
            &Stopping::default(),
            residuals,
        );
        let costs = costs.into_inner();
        // Polished to the residuals' errors (a cost of about 1e-25), in
        // few evaluations there.
        let at_floor = costs.iter().filter(|&&c| c < 1e-20).count();
        assert!(found.residuals.amax() < 2e-12, "{:?}", found.residuals);
        assert_eq!(found.evaluations, costs.len());
        assert!(
            (1..=10).contains(&at_floor),
            "{at_floor} evaluations at the floor: {costs:?}"
        );
    }

    /// The public entry: the same minimum as the inner solver; bounds of
    /// the wrong length or empty, and a start that cannot be evaluated, are
    /// typed errors.
    #[test]
    fn least_squares_for_ones_own_objective() {
        let residuals = |x: &DVector<f64>| rosenbrock(x, &()).map(|e| (e.residuals, e.jacobian));
        let wide = DVector::from_element(2, 10.0);
        let found = least_squares(
            DVector::from_vec(vec![-1.2, 1.0]),
            &-&wide,
            &wide,
            &Stopping::default(),
            residuals,
        )
        .unwrap();
        assert!((&found.x - DVector::from_element(2, 1.0)).amax() < 1e-12);
        let empty = DVector::from_vec(vec![0.0, 1.0]);
        let three = DVector::from_element(3, 10.0);
        for (lower, upper) in [(&empty, &DVector::zeros(2)), (&-&wide, &three)] {
            let e = least_squares(
                DVector::zeros(2),
                lower,
                upper,
                &Stopping::default(),
                residuals,
            );
            assert!(
                matches!(e, Err(LeastSquaresError::EmptyBounds { .. })),
                "{e:?}"
            );
        }
        let never = |_: &DVector<f64>| None;
        let e = least_squares(
            DVector::zeros(2),
            &-&wide,
            &wide,
            &Stopping::default(),
            never,
        );
        assert_eq!(e, Err(LeastSquaresError::NotEvaluable));
    }

    /// A minimum past a wall the residuals cannot be evaluated beyond (r =
    /// x − 2, nothing for x > 1): the solver creeps up to the wall, each
    /// step that crosses it a trial that cannot be evaluated, and stops at
    /// the `unevaluable`-th of them, not before and not after.
    #[test]
    fn stops_after_as_many_unevaluable_trials_as_it_is_allowed() {
        let walls = std::cell::Cell::new(0);
        let beyond_the_wall = |x: &DVector<f64>, _: &()| {
            if x[0] > 1.0 {
                walls.set(walls.get() + 1);
                return None;
            }
            Some(Evaluation {
                residuals: DVector::from_element(1, x[0] - 2.0),
                jacobian: DMatrix::from_element(1, 1, 1.0),
                state: (),
            })
        };
        let wide = DVector::from_element(1, 10.0);
        for allowed in [3, 7] {
            walls.set(0);
            let x0 = DVector::from_element(1, 0.0);
            let first = beyond_the_wall(&x0, &()).unwrap();
            let stopping = Stopping {
                unevaluable: allowed,
                ..Stopping::default()
            };
            let found = minimize(first, x0, &-&wide, &wide, &stopping, beyond_the_wall);
            assert_eq!(walls.get(), allowed);
            assert!(found.x[0] <= 1.0, "{}", found.x);
            // Three trials are all the steps cut short before one lands
            // this side of the wall; seven let it move towards the wall.
            assert_eq!(found.x[0] > 0.0, allowed == 7, "{}", found.x);
        }
    }

    #[test]
    fn finds_rosenbrocks_minimum_from_the_classic_start() {
        let x0 = DVector::from_vec(vec![-1.2, 1.0]);
        let wide = DVector::from_element(2, 1e9);
        let first = rosenbrock(&x0, &()).unwrap();
        let found = minimize(first, x0, &-&wide, &wide, &Stopping::default(), rosenbrock);
        assert!(
            (found.x[0] - 1.0).abs() < 1e-12 && (found.x[1] - 1.0).abs() < 1e-12,
            "{}",
            found.x
        );
        assert!(found.evaluations < 100, "{}", found.evaluations);
    }

    #[test]
    fn stops_on_an_active_bound_at_the_constrained_minimum() {
        // With x₁ ≤ 0.5 the minimum is on the bound: x₁ = 0.5, x₂ = 0.25.
        let x0 = DVector::from_vec(vec![-1.2, 1.0]);
        let lower = DVector::from_element(2, -10.0);
        let upper = DVector::from_vec(vec![0.5, 10.0]);
        let first = rosenbrock(&x0, &()).unwrap();
        let found = minimize(first, x0, &lower, &upper, &Stopping::default(), rosenbrock);
        assert_eq!(found.x[0], 0.5);
        assert!(
            (found.x[1] - 0.25).abs() < 1e-12,
            "{} after {}",
            found.x,
            found.evaluations
        );
        assert!((0.5 * found.residuals.norm_squared() - 0.125).abs() < 1e-12);
    }

    #[test]
    fn stops_where_no_step_reduces_the_cost() {
        // r = x − 1 with a deterministic 1e-9 noise: the cost cannot fall
        // below ~1e-19 (far above Stopping::cost) nor its gradient to
        // 1e-14, yet the solver must stop near x = 1 without spending all
        // its evaluations there.
        let evaluate = |x: &DVector<f64>, _: &()| {
            let noise = (x[0].to_bits() % 1000) as f64 / 1000.0 - 0.5;
            Some(Evaluation {
                residuals: DVector::from_element(1, x[0] - 1.0 + 1e-9 * noise),
                jacobian: DMatrix::from_element(1, 1, 1.0),
                state: (),
            })
        };
        let x0 = DVector::from_element(1, 3.0);
        let wide = DVector::from_element(1, 1e9);
        let first = evaluate(&x0, &()).unwrap();
        let found = minimize(first, x0, &-&wide, &wide, &Stopping::default(), evaluate);
        assert!((found.x[0] - 1.0).abs() < 1e-8, "{}", found.x);
        assert!(found.evaluations < 100, "{}", found.evaluations);
    }

    #[test]
    fn a_trial_that_cannot_be_evaluated_only_shortens_the_step() {
        // The residual is undefined for x < 0.2 (a design that does not
        // assemble): the solver must still find the root x = 0.25 of x² − 1/16.
        let evaluate = |x: &DVector<f64>, _: &()| {
            (x[0] >= 0.2).then(|| Evaluation {
                residuals: DVector::from_element(1, x[0] * x[0] - 0.0625),
                jacobian: DMatrix::from_element(1, 1, 2.0 * x[0]),
                state: (),
            })
        };
        let x0 = DVector::from_element(1, 3.0);
        let wide = DVector::from_element(1, 1e9);
        let first = evaluate(&x0, &()).unwrap();
        let found = minimize(first, x0, &-&wide, &wide, &Stopping::default(), evaluate);
        assert!((found.x[0] - 0.25).abs() < 1e-14, "{}", found.x);
    }
}

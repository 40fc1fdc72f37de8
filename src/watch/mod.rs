//! Zeros and extrema of chosen quantities along a sweep, located in the
//! driver to rounding rather than to the sweep's grid: the dead centres of
//! a slider (zeros of its velocity), the stroke (extrema of its position),
//! the extreme transmission angle, the peak acceleration.
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::watch::{Of, Watch, locate};
//!
//! #[linkage::linkage(
//!     u = [theta3, s],
//!     v = [theta2],
//!     closure = [
//!         r * theta2.cos() + l * theta3.cos() - s,
//!         r * theta2.sin() + l * theta3.sin() - e,
//!     ],
//! )]
//! struct SliderCrank { r: f64, l: f64, e: f64 }
//!
//! let crank = SliderCrank { r: 0.05, l: 0.2, e: 0.01 };
//! let drive = Drive::Line { from: vector![0.0], to: vector![6.2], steps: 62 };
//! let sweep = crank.sweep(&vector![-0.05, 0.25], &drive, &SweepOptions::default())?;
//! // The dead centres: where the slider's velocity is zero.
//! let found = locate(&crank, &sweep, &[Watch::coordinate("s", Of::Velocity).zeros()], &Options::default())?;
//! let (r, l, e) = (0.05_f64, 0.2_f64, 0.01_f64);
//! let outer = ((l + r).powi(2) - e * e).sqrt(); // where s is largest
//! assert_eq!(found.len(), 2);
//! assert!((found[0].u[1] - outer).abs() < 1e-15);
//! assert!((found[0].v[0] - e.atan2(outer)).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! How, as an ODE solver locates events: the sweep's poses are the grid.
//! Every pose is given its derivatives along the drive (u′, u″, u‴ by
//! implicit differentiation on dual numbers, [`PathPose`]), so that a
//! watched quantity g is evaluated with its exact rate g′. Where g (for
//! zeros) or g′ (for extrema) changes sign between two neighbouring poses
//! of one branch moving one way, the root is bracketed, and a safeguarded
//! secant on the driver refines it; each trial pose is solved by Newton
//! from the Taylor expansion at the pose before. Two sign changes of one
//! quantity between neighbouring poses cancel and are not seen: sweep finer
//! than the quantity's features.

mod path;

pub use crate::quantity::{Axis, Of};
pub use path::PathPose;

use crate::error::UnknownName;
use crate::numerics::root;
use crate::quantity::{Names, Quantity, Resolved};
use crate::runtime::{Error, Factors, Linkage, Options, Stage, Sweep};
use nalgebra::SVector;
use num_dual::Dual64;

/// What to look for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Find {
    /// Where the quantity crosses zero.
    Zeros,
    /// Where its rate along the drive crosses zero: its maxima and minima.
    Extrema,
    /// Both.
    Both,
}

/// A function of a path pose, watched.
type PathFunction<'a, const M: usize, const F: usize> = Box<dyn Fn(&PathPose<M, F>) -> Dual64 + 'a>;

/// A watched quantity with its names resolved to indices.
type Watched<'w, const M: usize, const F: usize> = Resolved<&'w PathFunction<'w, M, F>>;

/// A quantity to watch along a sweep and what to find of it.
pub struct Watch<'a, const M: usize, const F: usize> {
    find: Find,
    quantity: Quantity<PathFunction<'a, M, F>>,
}

impl<'a, const M: usize, const F: usize> Watch<'a, M, F> {
    fn of(quantity: Quantity<PathFunction<'a, M, F>>) -> Self {
        Watch {
            find: Find::Both,
            quantity,
        }
    }

    /// A coordinate of u or v, by its name in the attribute.
    pub fn coordinate(name: &str, of: Of) -> Self {
        Watch::of(Quantity::coordinate(name, of))
    }

    /// A component of a named point.
    pub fn point(name: &str, axis: Axis, of: Of) -> Self {
        Watch::of(Quantity::point(name, axis, of))
    }

    /// A function of the pose, written on dual numbers so that it carries
    /// its rate along the drive (num-dual's `DualNum` gives `sin`, `cos`,
    /// `atan2`, `sqrt`, …): the transmission angle θ4 − θ3 of a four-bar is
    /// `|p| p.u[1] - p.u[0]`.
    pub fn function(name: &str, f: impl Fn(&PathPose<M, F>) -> Dual64 + 'a) -> Self {
        Watch::of(Quantity::function(name, Box::new(f)))
    }

    /// The same coordinate or point as a watch; `None` for a function.
    pub(crate) fn named<G>(quantity: &Quantity<G>) -> Option<Self> {
        quantity.named().map(Watch::of)
    }

    /// Only the zeros.
    pub fn zeros(self) -> Self {
        Watch {
            find: Find::Zeros,
            ..self
        }
    }

    /// Only the extrema.
    pub fn extrema(self) -> Self {
        Watch {
            find: Find::Extrema,
            ..self
        }
    }

    /// What it watches, for reports: "s", "velocity of s", "P.x", or the
    /// function's name.
    pub fn name(&self) -> &str {
        self.quantity.name()
    }
}

/// What was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FoundKind {
    /// The quantity crosses zero, rising or falling along the drive.
    Zero {
        rising: bool,
    },
    Maximum,
    Minimum,
}

/// A zero or an extremum of a watched quantity, located in the driver.
#[derive(Clone, Debug, PartialEq)]
pub struct Found<const M: usize, const F: usize> {
    /// The index of the watch in the slice given to [`locate`].
    pub watch: usize,
    pub kind: FoundKind,
    /// The driver where it is.
    pub v: SVector<f64, F>,
    /// The quantity there, and its rate along the drive (0 to rounding at
    /// an extremum).
    pub value: f64,
    pub rate: f64,
    /// The pose there, at the sweep's speed.
    pub u: SVector<f64, M>,
    pub udot: SVector<f64, M>,
    pub uddot: SVector<f64, M>,
    /// The neighbouring poses of the sweep that bracket it (indices into
    /// `Sweep::poses`).
    pub between: (usize, usize),
}

/// Why the watched quantities could not be followed.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum WatchError {
    /// A watch names a coordinate or point the model does not have.
    UnknownName(UnknownName),
    /// A pose between two of the sweep's could not be solved, or is
    /// singular (its velocities and accelerations would not keep the
    /// accuracy asked for).
    Kinematics(Error),
    /// A watched quantity is not finite at the driver `v` (first
    /// component).
    NonFinite { watch: String, v: f64 },
    /// Newton, started between two poses of one branch, landed on another.
    BranchJump { v: f64 },
}

crate::error::error_impls! {
    WatchError {
        Self::UnknownName(inner) => ("{inner}"),
        Self::Kinematics(inner) => ("kinematics: {inner}"),
        Self::NonFinite { watch, v } => ("the watched quantity `{watch}` is not finite at v = {v}"),
        Self::BranchJump { v } => ("between two poses of one branch, Newton found another branch at v = {v}; sweep with smaller steps"),
    }
    wraps { UnknownName(UnknownName), Kinematics(Error) }
}

/// One pose of the sweep with its path derivatives.
struct Node<const M: usize, const F: usize> {
    pose: PathPose<M, F>,
    u: SVector<f64, M>,
    v: SVector<f64, F>,
    direction: SVector<f64, F>,
    speed: f64,
    det: f64,
}

/// Every zero and extremum of the `watches` along `sweep` (of `model`),
/// in the order of the sweep, then of the watches. Intervals the sweep
/// does not follow smoothly (across a reversal at a limit position, or a
/// change of branch) are not searched; poses are solved with `options`.
pub fn locate<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    sweep: &Sweep<M, F>,
    watches: &[Watch<'_, M, F>],
    options: &Options,
) -> Result<Vec<Found<M, F>>, WatchError> {
    options.check()?;
    let names = Names::of(model);
    let resolved = watches
        .iter()
        .map(|w| w.quantity.resolve(&names))
        .collect::<Result<Vec<_>, _>>()?;
    let mut nodes = Vec::with_capacity(sweep.poses.len());
    for p in &sweep.poses {
        let speed = p.vdot.norm();
        let direction = if speed > 0.0 { p.vdot / speed } else { p.vdot };
        nodes.push(node(model, &p.u, &p.v, &direction, speed, options)?);
    }
    let mut found = Vec::new();
    for (k, pair) in nodes.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let smooth = a.speed > 0.0
            && a.speed == b.speed
            && a.direction == b.direction
            && (a.det > 0.0) == (b.det > 0.0);
        // In the order of time: from a to b when the drivers' rate points
        // from a to b, from b back to a when it points the other way (a
        // negative rate).
        let forward = (b.v - a.v).dot(&a.direction);
        let (a, b, length) = if forward < 0.0 {
            (b, a, -forward)
        } else {
            (a, b, forward)
        };
        if !smooth || length.is_nan() || length <= 0.0 {
            continue;
        }
        for (w, (watch, quantity)) in watches.iter().zip(&resolved).enumerate() {
            let (ga, gb) = (quantity.at(&a.pose), quantity.at(&b.pose));
            for (extremum, fa, fb) in [(false, ga.re, gb.re), (true, ga.eps, gb.eps)] {
                let wanted = match watch.find {
                    Find::Zeros => !extremum,
                    Find::Extrema => extremum,
                    Find::Both => true,
                };
                // Half-open intervals (a, b]: a root exactly at a pose is
                // found once, in the interval that ends there.
                if !wanted || !(fa * fb < 0.0 || (fb == 0.0 && fa != 0.0)) {
                    continue;
                }
                let at = refine(model, a, b.v, length, quantity, extremum, options)?;
                let g = quantity.at(&at.pose);
                if !(g.re.is_finite() && g.eps.is_finite()) {
                    return Err(WatchError::NonFinite {
                        watch: watch.name().to_owned(),
                        v: at.v[0],
                    });
                }
                let kind = match (extremum, fb > fa) {
                    (false, rising) => FoundKind::Zero { rising },
                    (true, true) => FoundKind::Minimum,
                    (true, false) => FoundKind::Maximum,
                };
                found.push(Found {
                    watch: w,
                    kind,
                    v: at.v,
                    value: g.re,
                    rate: g.eps,
                    u: at.u,
                    udot: at.pose.udot.map(|x| x.re),
                    uddot: at.pose.uddot.map(|x| x.re),
                    between: (k, k + 1),
                });
            }
        }
    }
    Ok(found)
}

/// The pose (u, v) with its path derivatives, or why it has none.
fn node<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    direction: &SVector<f64, F>,
    speed: f64,
    options: &Options,
) -> Result<Node<M, F>, WatchError> {
    let psi_u = model.psi_u(u, v);
    let factors = Factors::of(&psi_u, model.psi_u_blocks());
    if !options.keeps_accuracy(Stage::Acceleration, factors.rcond()) {
        return Err(WatchError::Kinematics(Error::Singular {
            stage: Stage::Acceleration,
            rcond: factors.rcond(),
            min_rcond: options.min_rcond(Stage::Acceleration),
        }));
    }
    let pose = path::path_pose(model, u, v, direction, speed, &factors);
    if !path::is_finite(&pose) {
        return Err(WatchError::NonFinite {
            watch: "the pose's path derivatives".into(),
            v: v[0],
        });
    }
    Ok(Node {
        pose,
        u: *u,
        v: *v,
        direction: *direction,
        speed,
        det: factors.det(),
    })
}

/// The root of g (or of g′ for an `extremum`) between the pose `a` and the
/// driver `to`, `length` along the drive from it.
fn refine<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    a: &Node<M, F>,
    to: SVector<f64, F>,
    length: f64,
    quantity: &Watched<'_, M, F>,
    extremum: bool,
    options: &Options,
) -> Result<Node<M, F>, WatchError> {
    // The driver as x = s₀ + τ along the drive, s₀ = v_a·e, so that the
    // root's tolerance is relative to the driver's own size.
    let start = a.v.dot(&a.direction);
    // u′ and u″ at a, from the path pose (u̇ = u′σ, so d/ds u̇ = u″σ).
    let (u1, u2) = (
        a.pose.u.map(|x| x.eps),
        a.pose.udot.map(|x| x.eps) / a.speed,
    );
    let at = |x: f64| -> Result<Node<M, F>, WatchError> {
        let tau = x - start;
        let v = if tau >= length {
            to
        } else {
            a.v + a.direction * tau
        };
        let guess = a.u + u1 * tau + u2 * (0.5 * tau * tau);
        let position = model.solve_position(&guess, &v, options)?;
        let b = node(model, &position.u, &v, &a.direction, a.speed, options)?;
        if (b.det > 0.0) != (a.det > 0.0) {
            return Err(WatchError::BranchJump { v: v[0] });
        }
        Ok(b)
    };
    // The last trial pose, which is usually the root's: not solved twice.
    let mut last: Option<(f64, Node<M, F>)> = None;
    let mut g = |x: f64| -> Result<f64, WatchError> {
        let node = at(x)?;
        let g = quantity.at(&node.pose);
        last = Some((x, node));
        Ok(if extremum { g.eps } else { g.re })
    };
    let x = root(&mut g, start, start + length)?;
    match last {
        Some((tried, node)) if tried == x => Ok(node),
        _ => at(x),
    }
}

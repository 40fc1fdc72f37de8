//! What the search found: the assembly modes, each with its branch signs,
//! the singular assemblies apart, and how the search went.

use super::grid::SINGULAR_RCOND;
use super::scale::Scale;
use super::structure::Block;
use crate::runtime::{Linkage, determinant, invert};
use nalgebra::{DMatrix, SMatrix, SVector, Vector2};
use std::cmp::Ordering;

/// The sign of a determinant.
///
/// ```
/// use linkage::assembly::Sign;
/// assert_eq!(Sign::of(-2.0), Sign::Negative);
/// assert_eq!(Sign::of(3.0).to_string(), "+");
/// assert!(Sign::Positive < Sign::Negative); // the modes' order
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sign {
    Positive,
    Negative,
}

impl Sign {
    /// The sign of `x` (`Positive` for +0, which a regular mode never has).
    pub fn of(x: f64) -> Sign {
        if x < 0.0 {
            Sign::Negative
        } else {
            Sign::Positive
        }
    }
}

impl std::fmt::Display for Sign {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Sign::Positive => "+",
            Sign::Negative => "−",
        })
    }
}

/// One assembly mode: a regular solution u of Ψ(u, v) = 0 (Ψ_u
/// non-singular), polished to full precision.
///
/// Its branch signs tell it from the others: `signs[b]` is the sign of the
/// determinant of the block `b` of Ψ_u ([`Modes::blocks`]: its equations'
/// rows and its coordinates' columns, each in ascending order). For a
/// four-bar written as the Maple worksheet's (one block, θ3 and θ4) it is
/// the sign of l3·l4·sin(θ4 − θ3): which side of the line BD the joint C
/// lies on, open or crossed. Where the loops decouple (a Watt six-bar:
/// the four-bar, then the loop hanging from its rocker) each loop has its
/// own sign and the signs name the modes; where they do not (a Stephenson
/// III six-bar: one block of four) up to six modes share two signs, and a
/// mode is told by its index, a point's side of a line or a sketch
/// ([`Pick`](super::Pick)).
///
/// ```
/// use linkage::assembly::{Search, Sign, modes};
/// use linkage::mechanisms::FourBar;
/// use linkage::prelude::*;
///
/// let found = modes(&FourBar::WORKSHEET, &vector![20f64.to_radians()], &Search::default())?;
/// for mode in &found.modes {
///     let (theta3, theta4) = (mode.u[0], mode.u[1]);
///     assert_eq!(mode.signs, [Sign::of((theta4 - theta3).sin())]);
///     assert!(mode.residual < 1e-12 && mode.rcond > 0.1);
///     let c = mode.points[FourBar::C];
///     assert!(((c - vector![80.0, 0.0]).norm() - 70.0).abs() < 1e-12); // the rocker's length
/// }
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Mode<const M: usize> {
    /// The dependent coordinates, angles in [−π, π).
    pub u: SVector<f64, M>,
    /// The named points there, in the order of `POINT_NAMES`.
    pub points: Vec<Vector2<f64>>,
    /// The sign of each block's determinant, in the order of
    /// [`Modes::blocks`].
    pub signs: Vec<Sign>,
    /// The sign of det Ψ_u.
    pub determinant: Sign,
    /// The reciprocal condition number of Ψ_u, its rows divided by the
    /// equations' sizes and its columns equilibrated
    /// ([`Inverse::rcond`](crate::Inverse::rcond)).
    pub rcond: f64,
    /// The scale-free residual max |Ψᵢ|/sᵢ (sᵢ: [`Modes::equation_sizes`]).
    pub residual: f64,
}

/// A singular solution of Ψ(u, v) = 0: Ψ_u singular (its scale-free
/// reciprocal condition number below 1e-6), the mechanism at (or within
/// about 1e-6 of) a dead centre, where two modes meet. Reported once, not
/// as two modes: the modes meeting there cannot be told apart in f64.
///
/// ```
/// use linkage::assembly::{Search, modes};
/// use linkage::mechanisms::FourBar;
/// use linkage::prelude::*;
///
/// // At θ2 = 0, |BD| = 60 = l3 + l4: coupler and rocker in line.
/// let folded = FourBar { l1: 80.0, l2: 20.0, l3: 25.0, l4: 35.0 };
/// let found = modes(&folded, &vector![0.0], &Search::default())?;
/// assert!(found.modes.is_empty());
/// assert_eq!(found.dead_centres.len(), 1);
/// assert!(found.dead_centres[0].u.amax() < 1e-6); // θ3 = θ4 = 0
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct DeadCentre<const M: usize> {
    /// The dependent coordinates, angles in [−π, π) (located to about
    /// 1e-8, as a double root is).
    pub u: SVector<f64, M>,
    /// The named points there.
    pub points: Vec<Vector2<f64>>,
    /// As [`Mode::rcond`].
    pub rcond: f64,
    /// As [`Mode::residual`].
    pub residual: f64,
}

/// Every assembly the search found at the driver `v`
/// ([`modes`](super::modes)): the regular modes in a fixed order —
/// by their signs (`+` before `−`, block by block), then by their
/// coordinates — and the dead centres apart.
///
/// ```
/// use linkage::assembly::{Search, modes};
/// use linkage::mechanisms::OffsetSliderCrank;
/// use linkage::prelude::*;
///
/// let crank = OffsetSliderCrank { r: 0.05, l: 0.2, e: 0.01 };
/// let found = modes(&crank, &vector![1.0], &Search::default())?;
/// assert_eq!(found.modes.len(), 2); // the slider either side of the crank
/// assert_eq!(found.angle, [true, false]); // θ3 an angle, s a length
/// assert!(found.stable && found.runs > 0);
/// // The box of s holds every assembly: |s| ≤ r + l.
/// assert!(found.upper[1] >= 0.25);
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Modes<const M: usize, const F: usize> {
    /// The driver.
    pub v: SVector<f64, F>,
    /// The regular assembly modes.
    pub modes: Vec<Mode<M>>,
    /// The singular assemblies.
    pub dead_centres: Vec<DeadCentre<M>>,
    /// The blocks of Ψ_u the search solved one after the other (each
    /// block's equations involve only its coordinates and earlier blocks'):
    /// the loops, where they decouple.
    pub blocks: Vec<Block>,
    /// Which coordinates are angles (searched over a turn, compared up to
    /// whole turns): those under a sine or cosine of which Ψ is
    /// 2π-periodic.
    pub angle: [bool; M],
    /// The box searched: −π and π for an angle, a length's bounds.
    pub lower: SVector<f64, M>,
    pub upper: SVector<f64, M>,
    /// Each equation's size sᵢ, against which its residual is judged: the
    /// largest over a few poses of |Ψᵢ| + Σ_(j angle) |∂Ψᵢ/∂uⱼ|.
    pub equation_sizes: SVector<f64, M>,
    /// Whether every grid's set of roots stood
    /// [`Search::confirmations`](super::Search::confirmations) refinements
    /// (false: a grid would have exceeded
    /// [`Search::max_cells`](super::Search::max_cells) first, or a block
    /// had more roots than a loop has — 64 from one pose, 256 in all — and
    /// the search was cut short).
    pub stable: bool,
    /// Newton's runs, all blocks together.
    pub runs: usize,
    /// The model's point names, for picks by a point.
    pub point_names: &'static [&'static str],
}

impl<const M: usize, const F: usize> Modes<M, F> {
    /// The unit of coordinate `j` in the search: 1 (a radian) for an
    /// angle, the half-width of its box for a length.
    ///
    /// ```
    /// use linkage::assembly::{Lengths, Search, modes};
    /// use linkage::mechanisms::OffsetSliderCrank;
    /// use linkage::prelude::*;
    ///
    /// let crank = OffsetSliderCrank { r: 0.05, l: 0.2, e: 0.01 };
    /// let search = Search { lengths: Lengths::Within(0.5), ..Search::default() };
    /// let found = modes(&crank, &vector![1.0], &search)?;
    /// assert_eq!((found.unit(0), found.unit(1)), (1.0, 0.5));
    /// # Ok::<(), linkage::assembly::AssemblyError>(())
    /// ```
    pub fn unit(&self, j: usize) -> f64 {
        if self.angle[j] {
            1.0
        } else {
            0.5 * (self.upper[j] - self.lower[j])
        }
    }
}

/// A root classified: a regular mode, or a dead centre.
pub(crate) enum Classified<const M: usize> {
    Mode(Mode<M>),
    DeadCentre(DeadCentre<M>),
}

/// The root `u` of `model` at `v` classified, with its signs on `blocks`.
pub(crate) fn classify<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    u: SVector<f64, M>,
    scale: &Scale<M>,
    blocks: &[Block],
) -> Classified<M> {
    let u = scale.wrapped(&u);
    let (psi, psi_u) = model.psi_and_psi_u(&u, v);
    let scaled = SMatrix::<f64, M, M>::from_fn(|i, j| psi_u[(i, j)] / scale.equations[i]);
    let rcond = invert(&scaled).rcond;
    let residual = scale.residual(&psi);
    let points = model.point_positions(&u, v).as_ref().to_vec();
    if rcond < SINGULAR_RCOND {
        return Classified::DeadCentre(DeadCentre {
            u,
            points,
            rcond,
            residual,
        });
    }
    let signs = blocks
        .iter()
        .map(|block| {
            let minor = DMatrix::from_fn(block.equations.len(), block.coordinates.len(), |a, b| {
                psi_u[(block.equations[a], block.coordinates[b])]
            });
            Sign::of(minor.determinant())
        })
        .collect();
    Classified::Mode(Mode {
        u,
        points,
        signs,
        determinant: Sign::of(determinant(&psi_u)),
        rcond,
        residual,
    })
}

/// The order of the modes: by their signs, then their coordinates.
pub(crate) fn mode_order<const M: usize>(a: &Mode<M>, b: &Mode<M>) -> Ordering {
    a.signs
        .cmp(&b.signs)
        .then_with(|| coordinate_order(&a.u, &b.u))
}

/// Coordinates compared one after the other.
pub(crate) fn coordinate_order<const M: usize>(
    a: &SVector<f64, M>,
    b: &SVector<f64, M>,
) -> Ordering {
    a.iter()
        .zip(b.iter())
        .map(|(x, y)| x.total_cmp(y))
        .find(|o| o.is_ne())
        .unwrap_or(Ordering::Equal)
}

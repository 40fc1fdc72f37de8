//! The mechanism's size, read from its equations at a few poses: which
//! coordinates are angles, how large each equation's terms are, and the
//! box the lengths are searched in.

use super::error::AssemblyError;
use super::settings::Lengths;
use crate::runtime::{Error, Linkage, Stage};
use nalgebra::{SMatrix, SVector};
use std::f64::consts::{PI, TAU};

/// The poses the size is read at.
const SAMPLES: usize = 8;
/// Ψ's change over a whole turn of a coordinate, relative to the
/// equations' sizes, below which the coordinate is an angle.
const PERIODIC: f64 = 1e-9;

/// What the search needs to know of a mechanism's size.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Scale<const M: usize> {
    /// Whether each coordinate is an angle: Ψ unchanged by a whole turn
    /// of it (checked at two poses; for a coordinate whose sine or cosine
    /// is not written, `TRIG_U`, Ψ finite and moving with it there).
    pub angle: [bool; M],
    /// Each equation's size sᵢ: its residual is judged as |Ψᵢ|/sᵢ.
    pub equations: SVector<f64, M>,
    /// The box searched: −π and π for an angle, a length's bounds.
    pub lower: SVector<f64, M>,
    pub upper: SVector<f64, M>,
}

impl<const M: usize> Scale<M> {
    /// The unit of coordinate `j` in the search: 1 for an angle (radians),
    /// the half-width of its box for a length.
    pub fn unit(&self, j: usize) -> f64 {
        if self.angle[j] {
            1.0
        } else {
            0.5 * (self.upper[j] - self.lower[j])
        }
    }

    /// The difference a − b of coordinate `j` in units of the search, an
    /// angle's brought within (−π, π] (up to whole turns).
    pub fn difference(&self, j: usize, a: f64, b: f64) -> f64 {
        let d = (a - b) / self.unit(j);
        if self.angle[j] { within_a_turn(d) } else { d }
    }

    /// The largest scale-free residual max |Ψᵢ|/sᵢ.
    pub fn residual(&self, psi: &SVector<f64, M>) -> f64 {
        psi.component_div(&self.equations).amax()
    }

    /// `u` with its angles brought into [−π, π).
    pub fn wrapped(&self, u: &SVector<f64, M>) -> SVector<f64, M> {
        SVector::from_fn(|j, _| if self.angle[j] { wrap(u[j]) } else { u[j] })
    }
}

/// An angle brought into [−π, π).
pub(crate) fn wrap(angle: f64) -> f64 {
    let wrapped = (angle + PI).rem_euclid(TAU) - PI;
    // rem_euclid may round up to TAU itself.
    if wrapped >= PI {
        wrapped - TAU
    } else {
        wrapped
    }
}

/// An angle's difference brought within (−π, π].
pub(crate) fn within_a_turn(d: f64) -> f64 {
    -wrap(-d)
}

/// Sample `s` of coordinate `k`: a quasi-random point of [0, 1), spread
/// evenly over the samples and shifted by the golden ratio from one
/// coordinate to the next, so that no two coordinates move together.
fn sample(s: usize, k: usize) -> f64 {
    ((s as f64 + 0.5) / SAMPLES as f64 + k as f64 * 0.618_033_988_749_894_9).fract()
}

/// The sample poses: angles over a turn, lengths at `length` times a
/// point of [−1, 1].
fn pose<const M: usize>(angle: &[bool; M], s: usize, length: f64) -> SVector<f64, M> {
    SVector::from_fn(|k, _| {
        let t = sample(s, k);
        if angle[k] {
            -PI + TAU * t
        } else {
            length * (2.0 * t - 1.0)
        }
    })
}

/// Ψ and Ψ_u at a pose, if finite.
fn evaluate<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> Option<(SVector<f64, M>, SMatrix<f64, M, M>)> {
    let (psi, psi_u) = model.psi_and_psi_u(u, v);
    let finite = psi.iter().chain(psi_u.iter()).all(|x| x.is_finite());
    finite.then_some((psi, psi_u))
}

/// Each equation's size: the largest over the sample poses (lengths 0) of
/// |Ψᵢ| + Σ_(j angle) |∂Ψᵢ/∂uⱼ|. For a vector loop's x row, whose terms
/// are a constant c, the drivers' and the lengths' terms and the rigid
/// vectors lₖ(cos θₖ, sin θₖ) turning with the angles, that is
/// |cₓ + Σ lₖ cos θₖ| + Σ |lₖ sin θₖ|: a few times the size of the loop. An
/// equation of size 0 (only lengths in it) is given the largest of the
/// others', or 1.
fn equation_sizes<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    angle: &[bool; M],
) -> Result<SVector<f64, M>, AssemblyError> {
    let mut sizes = SVector::<f64, M>::zeros();
    let mut evaluated = false;
    for s in 0..SAMPLES {
        let Some((psi, psi_u)) = evaluate(model, &pose(angle, s, 0.0), v) else {
            continue;
        };
        evaluated = true;
        for i in 0..M {
            let turning: f64 = (0..M)
                .filter(|&j| angle[j])
                .map(|j| psi_u[(i, j)].abs())
                .sum();
            sizes[i] = sizes[i].max(psi[i].abs() + turning);
        }
    }
    if !evaluated {
        return Err(AssemblyError::Input(Error::NonFiniteValue {
            stage: Stage::Position,
            quantity: "Ψ",
        }));
    }
    let largest = sizes.amax();
    let fallback = if largest > 0.0 { largest } else { 1.0 };
    Ok(sizes.map(|s| if s > 0.0 { s } else { fallback }))
}

/// Whether Ψ is unchanged by a whole turn of coordinate `k` at two
/// sample poses (lengths at the mechanism's size `length`). A pose where
/// Ψ is not finite says nothing (`unknown`: what it is taken for).
fn periodic<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    angle: &[bool; M],
    k: usize,
    sizes: &SVector<f64, M>,
    length: f64,
    unknown: bool,
) -> bool {
    (0..2).all(|s| {
        let u = pose(angle, s, length);
        let mut turned = u;
        turned[k] += TAU;
        let (Some((a, psi_u)), Some((b, _))) =
            (evaluate(model, &u, v), evaluate(model, &turned, v))
        else {
            return unknown;
        };
        // A coordinate Ψ does not move with here says nothing either.
        if psi_u.column(k).iter().all(|&x| x == 0.0) {
            return unknown;
        }
        ((a - b).component_div(sizes)).amax() <= PERIODIC
    })
}

/// The mechanism's [`Scale`] at the driver `v`, its lengths' box as
/// `lengths` says.
pub(crate) fn scale<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    lengths: &Lengths,
) -> Result<Scale<M>, AssemblyError> {
    let mut angle = model.trig_u();
    let mut sizes = equation_sizes(model, v, &angle)?;
    let size: f64 = sizes.sum();
    let candidates = angle;
    for (k, &candidate) in candidates.iter().enumerate() {
        angle[k] = if candidate {
            // Its sine or cosine written: an angle unless Ψ shows otherwise.
            periodic(model, v, &candidates, k, &sizes, size, true)
        } else {
            // Under a sine or cosine only in a sum or a product
            // (`(theta + beta).cos()`): an angle if Ψ shows it, finite
            // and moving with it at both poses. (Searched as a length, a
            // turning coordinate has a root every turn of its box.)
            periodic(model, v, &candidates, k, &sizes, size, false)
        };
    }
    if angle != candidates {
        sizes = equation_sizes(model, v, &angle)?;
    }
    let size: f64 = sizes.sum();
    let mut lower = SVector::<f64, M>::from_element(-PI);
    let mut upper = SVector::<f64, M>::from_element(PI);
    for j in (0..M).filter(|&j| !angle[j]) {
        let (low, high) = match lengths {
            Lengths::FromScale => {
                let half = 2.0 * size / coefficient(model, v, &angle, j, size);
                (-half, half)
            }
            Lengths::Within(half) => (-half, *half),
            Lengths::Bounds(bounds) => bounds[j],
        };
        if !(low.is_finite() && high.is_finite() && low < high) {
            return Err(AssemblyError::Input(Error::InvalidInput {
                argument: "the box of a length coordinate",
                value: high - low,
                why: "finite bounds, lower < upper (Lengths::Bounds, or equations of no size)",
            }));
        }
        (lower[j], upper[j]) = (low, high);
    }
    Ok(Scale {
        angle,
        equations: sizes,
        lower,
        upper,
    })
}

/// The size of the length coordinate `j`'s coefficient in the equations:
/// the largest |∂Ψᵢ/∂uⱼ| over the sample poses, lengths at 0 and at the
/// mechanism's size (1 if it is 0 everywhere).
fn coefficient<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    angle: &[bool; M],
    j: usize,
    size: f64,
) -> f64 {
    let largest = (0..SAMPLES)
        .flat_map(|s| [pose(angle, s, 0.0), pose(angle, s, size)])
        .filter_map(|u| evaluate(model, &u, v))
        .map(|(_, psi_u)| psi_u.column(j).amax())
        .fold(0.0, f64::max);
    if largest > 0.0 { largest } else { 1.0 }
}

/// Which coordinates each equation involves: `nonzero[i][j]` if
/// ∂Ψᵢ/∂uⱼ is not 0 at one of the sample poses (lengths spread over
/// their box), the pattern the blocks are read from.
pub(crate) fn pattern<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    scale: &Scale<M>,
) -> [[bool; M]; M] {
    let mut nonzero = [[false; M]; M];
    for s in 0..SAMPLES {
        let u = SVector::from_fn(|k, _| {
            let t = sample(s, k);
            scale.lower[k] + (scale.upper[k] - scale.lower[k]) * t
        });
        let (_, psi_u) = model.psi_and_psi_u(&u, v);
        for (i, row) in nonzero.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                // (A NaN counts: the equation involves the coordinate.)
                *entry |= psi_u[(i, j)] != 0.0;
            }
        }
    }
    nonzero
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_wrap_into_one_turn() {
        assert_eq!(wrap(0.5), 0.5);
        assert_eq!(wrap(PI), -PI);
        assert_eq!(wrap(-PI), -PI);
        assert!((wrap(TAU + 0.25) - 0.25).abs() < 1e-15);
        assert!((wrap(-TAU - 0.25) + 0.25).abs() < 1e-15);
        assert_eq!(within_a_turn(PI), PI);
        assert!((within_a_turn(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
    }
}

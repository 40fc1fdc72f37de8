//! The search itself: the mechanism's scale and blocks read from its
//! equations, each block's roots found for every root of the blocks
//! before it, each whole root classified and the modes ordered.

use super::error::AssemblyError;
use super::grid::MOST_ROOTS;
use super::modes::{Classified, Modes, classify, coordinate_order, mode_order};
use super::newton::BlockSystem;
use super::scale::{pattern, scale};
use super::settings::Search;
use super::structure::{blocks, perfect};
use crate::runtime::{Error, Linkage, Stage};
use nalgebra::SVector;

/// The most poses of the blocks solved so far the next block is searched
/// from: enough for eight loops of two assemblies each, and for 64 roots
/// of a block searched from four poses.
const MOST_POSES: usize = 4 * MOST_ROOTS;

/// Every real assembly of `model` at the driver `v` the search finds, each
/// regular one a [`Mode`](super::Mode) with its branch signs, the singular
/// ones apart ([`DeadCentre`](super::DeadCentre)); no guess needed.
///
/// Errors: [`AssemblyError::NoAssembly`] if there is none (the mechanism
/// cannot be assembled at `v`); [`AssemblyError::Input`] for a `v` not
/// finite, settings out of range, equations not finite at every pose
/// tried, or a named point not finite at an assembly found;
/// [`AssemblyError::SingularEverywhere`] if Ψ_u is singular at every pose
/// sampled (no assembly can be regular).
///
/// ```
/// use linkage::assembly::{Search, Sign, modes};
/// use linkage::mechanisms::FourBar;
/// use linkage::prelude::*;
///
/// let found = modes(&FourBar::WORKSHEET, &vector![20f64.to_radians()], &Search::default())?;
/// assert_eq!(found.modes.len(), 2); // open and crossed
/// assert_eq!(found.modes[1].signs, [Sign::Negative]);
/// // The worksheet's pose, θ3 = 70.55°, found without its guess.
/// assert!((found.modes[1].u[0].to_degrees() - 70.550_765_47).abs() < 1e-8);
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
pub fn modes<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    v: &SVector<f64, F>,
    search: &Search,
) -> Result<Modes<M, F>, AssemblyError> {
    if let Some((index, &value)) = v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
        return Err(AssemblyError::Input(Error::NonFiniteInput {
            argument: "v",
            index,
            value,
        }));
    }
    search.check::<M>()?;
    let scale = scale(model, v, &search.lengths)?;
    let nonzero = pattern(model, v, &scale);
    // Ψ_u singular wherever it was looked at (a link of length 0): every
    // root would be a dead centre, found, if at all, by searching a grid
    // of every coordinate at once to its largest size (a second for six
    // coordinates, for nothing).
    if !perfect(&nonzero) {
        let idle = (0..M)
            .filter(|&j| nonzero.iter().all(|row| !row[j]))
            .collect();
        return Err(AssemblyError::SingularEverywhere { idle });
    }
    let blocks = blocks(&nonzero);
    // The poses solved so far: the blocks before, the others at the box's
    // centre (no earlier block's equation involves them).
    let mut poses = vec![(scale.lower + scale.upper) * 0.5];
    let (mut stable, mut runs, mut least) = (true, 0, f64::INFINITY);
    for block in &blocks {
        let system = BlockSystem {
            model,
            v,
            block,
            scale: &scale,
        };
        let mut next = Vec::new();
        for held in &poses {
            let found = system.roots(held, search);
            stable &= found.stable;
            runs += found.runs;
            least = least.min(found.least_residual);
            next.extend(found.roots);
        }
        // Too many to search the next block from each: a search gone
        // wrong (see `MOST_ROOTS`), cut short and said to be unstable.
        if next.len() > MOST_POSES {
            next.truncate(MOST_POSES);
            stable = false;
        }
        poses = next;
        if poses.is_empty() {
            return Err(AssemblyError::NoAssembly {
                v: v.as_slice().to_vec(),
                lower: scale.lower.as_slice().to_vec(),
                upper: scale.upper.as_slice().to_vec(),
                least_residual: least,
                stable,
            });
        }
    }
    let mut modes = Vec::new();
    let mut dead_centres = Vec::new();
    for u in poses {
        match classify(model, v, u, &scale, &blocks) {
            Classified::Mode(mode) => modes.push(mode),
            Classified::DeadCentre(dead_centre) => dead_centres.push(dead_centre),
        }
    }
    // A named point not finite at an assembly (`(theta3 - 1.0).sqrt()`
    // where θ3 < 1): the points are outside their domain there, as an
    // analysis of that pose would find.
    let finite = |points: &[nalgebra::Vector2<f64>]| {
        points.iter().all(|p| p.x.is_finite() && p.y.is_finite())
    };
    if !(modes.iter().all(|m| finite(&m.points)) && dead_centres.iter().all(|d| finite(&d.points)))
    {
        return Err(AssemblyError::Input(Error::NonFiniteValue {
            stage: Stage::Points,
            quantity: "P",
        }));
    }
    modes.sort_by(mode_order);
    dead_centres.sort_by(|a, b| coordinate_order(&a.u, &b.u));
    Ok(Modes {
        v: *v,
        modes,
        dead_centres,
        blocks,
        angle: scale.angle,
        lower: scale.lower,
        upper: scale.upper,
        equation_sizes: scale.equations,
        stable,
        runs,
        point_names: model.point_names(),
    })
}

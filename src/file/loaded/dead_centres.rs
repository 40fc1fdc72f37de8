//! The dead centres of a file's mechanism over its drive range: the poses
//! where a link pinned to the frame comes to rest and turns back, or a
//! block on a fixed guide reaches an end of its stroke — where the
//! mechanism would lock were that link its driver (a four-bar's rocker
//! with the crank and the coupler in line, a slider-crank's slider at top
//! and bottom dead centre). Read from the file's `[drawing]`: its ground
//! pivots (where [`Loaded::pivots`] puts them), the links and plates on
//! them, its sliders on fixed guides; each
//! located in the driver to rounding ([`crate::watch::locate`]).

use super::{LoadError, Loaded};
use crate::file::drawing::{DrawingSpec, Guide};
use crate::mechanism::Fixed;
use crate::watch::{Watch, WatchError, locate};
use crate::{Kernels, Options, Sweep};
use nalgebra::SVector;
use num_dual::DualNum;

/// A dead centre of the mechanism.
#[derive(Clone, Debug, PartialEq)]
pub struct DeadCentre<const M: usize, const F: usize> {
    /// What comes to rest: a link pinned to the frame, as its moving
    /// point and its pivot (`C–D`), or a block on a fixed guide (`P`).
    pub what: String,
    /// The drivers there.
    pub v: SVector<f64, F>,
    /// The pose there.
    pub u: SVector<f64, M>,
}

/// Why the dead centres could not be found.
#[derive(Debug)]
#[non_exhaustive]
pub enum DeadCentreError {
    /// The pose at `at` or the sweep failed.
    Load(LoadError),
    /// A pose between two of the sweep's could not be followed.
    Watch(WatchError),
}

crate::error::error_impls! {
    DeadCentreError {
        Self::Load(inner) => ("{inner}"),
        Self::Watch(inner) => ("the dead centres: {inner}"),
    }
    wraps { Load(LoadError), Watch(WatchError) }
}

/// What may come to rest: a moving point turning about a ground pivot, or
/// a point sliding along a fixed line.
enum Rests {
    /// The point (by its index) and the pivot.
    Turning { point: usize, pivot: [f64; 2] },
    /// The point and the guide's direction.
    Sliding { point: usize, direction: [f64; 2] },
}

/// Each link or plate pinned to the frame at one pivot, with a named
/// point on it (its first), and each slider on a fixed guide: what the
/// drawing shows that may come to rest, named.
fn resting(
    drawing: &DrawingSpec,
    pivots: &[(String, [f64; 2])],
    points: &[&str],
) -> Vec<(String, Rests)> {
    let point = |name: &str| points.iter().position(|p| *p == name);
    let pivot = |name: &str| (pivots.iter()).find(|(n, _)| n == name).map(|(_, at)| *at);
    let mut found = Vec::new();
    let bodies =
        (drawing.links.iter().map(|l| &l[..])).chain(drawing.plates.iter().map(|p| &p[..]));
    for body in bodies {
        let pivots: Vec<(&str, [f64; 2])> = (body.iter())
            .filter_map(|n| Some((n.text.as_str(), pivot(&n.text)?)))
            .collect();
        let moving = (body.iter()).find_map(|n| Some((n.text.as_str(), point(&n.text)?)));
        if let ([(pivot_name, at)], Some((name, index))) = (&pivots[..], moving) {
            let rests = Rests::Turning {
                point: index,
                pivot: *at,
            };
            found.push((format!("{name}–{pivot_name}"), rests));
        }
    }
    for slider in &drawing.sliders {
        if let (Guide::Ground(angle), Some(index)) = (&slider.guide, point(&slider.point.text)) {
            let direction = [angle.value.cos(), angle.value.sin()];
            let rests = Rests::Sliding {
                point: index,
                direction,
            };
            found.push((slider.point.text.clone(), rests));
        }
    }
    found
}

impl Loaded {
    /// The dead centres over the file's drive range, in the order of the
    /// sweep (none for a file without `[drawing]`, whose bodies are not
    /// known): where a link pinned to the frame turns back (the angle of
    /// its point about its pivot is extreme) or a block on a fixed guide
    /// does (its travel along the guide is extreme).
    ///
    /// ```
    /// use linkage::file::Loaded;
    ///
    /// let text = std::fs::read_to_string("mechanisms/four_bar.toml")?;
    /// let loaded = Loaded::from_text("four_bar.toml", &text)?;
    /// let bar = loaded.mechanism().fixed::<2, 1>()?;
    /// let found = loaded.dead_centres(&bar)?;
    /// // The rocker C–D at rest, the crank and the coupler in line:
    /// // stretched out at θ2 = acos(4/7), folded at θ2 = 240°, each within
    /// // two units in the last place.
    /// assert_eq!(found.len(), 2);
    /// assert_eq!(found[0].what, "C–D");
    /// assert!((found[0].v[0] - (4.0f64 / 7.0).acos()).abs() < 2e-15);
    /// assert!((found[1].v[0] - 240f64.to_radians()).abs() < 2e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn dead_centres<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<Vec<DeadCentre<M, F>>, DeadCentreError> {
        let Some(drawing) = &self.file().drawing else {
            return Ok(Vec::new());
        };
        let rests = resting(drawing, &self.pivots(model), model.point_names());
        if rests.is_empty() {
            return Ok(Vec::new());
        }
        let watches: Vec<Watch<'_, M, F>> = (rests.iter())
            .map(|(name, rests)| match *rests {
                Rests::Turning { point, pivot } => Watch::function(name, move |p| {
                    let at = p.points[point];
                    (at.y - pivot[1]).atan2(at.x - pivot[0])
                }),
                Rests::Sliding { point, direction } => Watch::function(name, move |p| {
                    let at = p.points[point];
                    at.x * direction[0] + at.y * direction[1]
                }),
            })
            .map(Watch::extrema)
            .collect();
        let steps = self.drives(model)?.steps;
        let mut poses = Vec::new();
        let summary = self.sweep_each(model, steps, &mut |_, pose| poses.push(*pose))?;
        let sweep = Sweep {
            poses,
            events: summary.events,
            complete: summary.complete,
        };
        let found = locate(model, &sweep, &watches, &Options::default())?;
        Ok((found.into_iter())
            .map(|f| DeadCentre {
                what: rests[f.watch].0.clone(),
                v: f.v,
                u: f.u,
            })
            .collect())
    }
}

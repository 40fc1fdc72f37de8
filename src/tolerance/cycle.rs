//! The linear estimate over a cycle: every output's value, gradient and
//! spread at every pose of a sweep of the nominal design.

use super::limit::{LimitMargin, WorstPose};
use super::output::TolerancePose;
use super::{Output, Spread, ToleranceError, Tolerances, gradient};
use crate::runtime::{Drive, Motion, Sensitivities, SweepOptions, SweepSummary};
use nalgebra::SVector;

/// One output over the cycle, pose by pose.
#[derive(Clone, Debug, PartialEq)]
pub struct Band<const F: usize, const K: usize> {
    /// The output's name ([`Output::name`]).
    pub name: String,
    /// The driver at each pose.
    pub v: Vec<SVector<f64, F>>,
    /// The nominal value.
    pub value: Vec<f64>,
    /// Its gradient by the parameters; `None` where the sensitivities are
    /// refused (next to a singular pose) or the output is not defined (a
    /// path where its point stands still).
    pub gradient: Vec<Option<SVector<f64, K>>>,
    /// The spread under the tolerances, where the gradient is known.
    pub spread: Vec<Option<Spread>>,
}

impl<const F: usize, const K: usize> Band<F, K> {
    /// The pose (its index) of the largest worst-case spread, and that
    /// spread; `None` if no pose has one.
    pub fn largest(&self) -> Option<(usize, Spread)> {
        self.spread
            .iter()
            .enumerate()
            .filter_map(|(i, s)| s.map(|s| (i, s)))
            .max_by(|a, b| a.1.worst_case.total_cmp(&b.1.worst_case))
    }

    /// What each dimension adds to the worst case at its worst over the
    /// cycle: the largest |∂y/∂pᵢ| tᵢ over the poses. The bar chart of
    /// which dimension matters most.
    pub fn contributions(&self, tolerances: &Tolerances<K>) -> SVector<f64, K> {
        self.gradient
            .iter()
            .flatten()
            .map(|g| tolerances.contributions(g))
            .fold(SVector::zeros(), |most, c| most.sup(&c))
    }
}

/// The linear estimate over a cycle: the bands of `outputs` along the
/// sweep of `model` from `u0` along `drive`, the sweep's summary, and how
/// far the tolerance band is from a limit position.
#[derive(Clone, Debug, PartialEq)]
pub struct Cycle<const M: usize, const F: usize, const K: usize> {
    pub bands: Vec<Band<F, K>>,
    pub summary: SweepSummary<M, F>,
    /// The margin to the nearest limit position at the cycle's worst pose
    /// ([`limit_margin`](super::limit_margin)); `None` if the sweep has
    /// no pose. Where [`LimitMargin::reaches_limit`], the linear spreads
    /// do not describe the band: some of its designs do not run the cycle.
    pub limit: Option<LimitMargin<M, F, K>>,
}

impl<const M: usize, const F: usize, const K: usize> Cycle<M, F, K> {
    /// The band of the output named `name`.
    pub fn band(&self, name: &str) -> Option<&Band<F, K>> {
        self.bands.iter().find(|b| b.name == name)
    }
}

/// Sweeps `model` and gives, at every pose, each output with its gradient
/// by the parameters and its spread under `tolerances` (see the module's
/// documentation).
pub fn cycle<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    outputs: &[Output<'_, M, F, K>],
    tolerances: &Tolerances<K>,
) -> Result<Cycle<M, F, K>, ToleranceError>
where
    L: Sensitivities<M, F, K>,
{
    let resolved = outputs
        .iter()
        .map(|o| o.resolve(model))
        .collect::<Result<Vec<_>, _>>()?;
    let mut bands: Vec<Band<F, K>> = outputs
        .iter()
        .map(|o| Band {
            name: o.name().to_owned(),
            v: Vec::new(),
            value: Vec::new(),
            gradient: Vec::new(),
            spread: Vec::new(),
        })
        .collect();
    let mut worst = WorstPose::default();
    let summary = model.sweep_sensitivities_each(u0, drive, options, |pose, sensitivity| {
        // The margin to a limit position from the sweep's u_p where it has
        // them.
        let u_p = sensitivity.as_ref().ok().map(|s| &s.u);
        worst.push(model, &pose.u, &pose.v, u_p, tolerances);
        let motion = Motion::of_sweep_pose(pose);
        let pose = match &sensitivity {
            Ok(s) => TolerancePose::with_gradients(model, &motion, s),
            Err(_) => TolerancePose::plain(model, &motion),
        };
        for (band, output) in bands.iter_mut().zip(&resolved) {
            let y = output.at(&pose, &pose);
            let g = gradient(&y);
            let known = sensitivity.is_ok() && y.re.is_finite() && g.iter().all(|x| x.is_finite());
            band.v.push(pose.v.map(|x| x.re));
            band.value.push(y.re);
            band.gradient.push(known.then_some(g));
            band.spread.push(known.then(|| tolerances.spread(&g)));
        }
    })?;
    let limit = worst.refine(model, tolerances, &options.options);
    Ok(Cycle {
        bands,
        summary,
        limit,
    })
}

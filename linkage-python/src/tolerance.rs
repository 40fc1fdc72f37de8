//! Tolerance analysis from Python: `Mechanism.tolerance`, how far the
//! parameters' tolerances move quantities over a sweep — the worst case,
//! the root-sum-square and σ at every pose, each parameter's share where
//! the worst case is largest, and a Monte Carlo check.

use crate::errors::Failure;
use crate::source::Source;
use crate::sweep::DriveArgs;
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::{PARAMETERS, SensitivityJob};
use linkage::prelude::*;
use linkage::quantity::{Written, written};
use linkage::tolerance::{self, MonteCarlo, Output, Tolerance, Tolerances};

/// A quantity's band over the sweep.
pub struct Band {
    pub quantity: String,
    /// (poses, f) row by row.
    pub v: Vec<f64>,
    pub value: Vec<f64>,
    /// NaN at a pose with no spread.
    pub worst_case: Vec<f64>,
    pub rss: Vec<f64>,
    pub sigma: Vec<f64>,
    /// The pose where the worst case is largest, and each parameter's
    /// share of it there.
    pub largest: Option<usize>,
    pub shares: Vec<f64>,
    /// σ of the Monte Carlo samples at each pose (with samples).
    pub sigma_monte_carlo: Option<Vec<f64>>,
}

/// The bands of every quantity.
pub struct Spreads {
    pub parameters: Vec<String>,
    pub bands: Vec<Band>,
    /// Where, within the tolerances, the mechanism may reach a limit
    /// position (the linear spreads do not describe the band there).
    pub limit: Option<Vec<f64>>,
    pub failed_samples: usize,
}

pub struct Spread {
    pub source: Source,
    pub drive: DriveArgs,
    pub tolerances: Vec<(String, Tolerance)>,
    pub quantities: Vec<String>,
    pub samples: usize,
    pub random_state: u64,
}

/// A quantity written as text, as a tolerance output.
fn output<const M: usize, const F: usize, const K: usize>(
    text: &str,
) -> Result<Output<'static, M, F, K>, Failure> {
    Ok(match written(text).map_err(Failure::BadInput)? {
        Written::Coordinate(name, of) => Output::coordinate(name, of),
        Written::Point(name, axis, of) => Output::point(name, axis, of),
        Written::Path(name) => Output::path(name),
    })
}

impl SensitivityJob for Spread {
    type Output = Spreads;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Spreads, Failure> {
        let quantities: Vec<String> = if self.quantities.is_empty() {
            model.u_names().iter().map(|n| n.to_string()).collect()
        } else {
            self.quantities.clone()
        };
        let outputs = (quantities.iter())
            .map(|text| output::<M, F, PARAMETERS>(text))
            .collect::<Result<Vec<_>, _>>()?;
        let given: Vec<(&str, Tolerance)> = (self.tolerances.iter())
            .map(|(n, t)| (n.as_str(), *t))
            .collect();
        let names = model.param_names();
        let tolerances = Tolerances::by_name(&names, &given).map_err(Failure::Tolerance)?;
        let (start, drive, options) = self.drive.resolve(&self.source, &model)?;
        let cycle = tolerance::cycle(&model, &start, &drive, &options, &outputs, &tolerances)
            .map_err(Failure::Tolerance)?;
        let samples = (self.samples > 0)
            .then(|| {
                let run = MonteCarlo {
                    samples: self.samples,
                    random_state: self.random_state,
                };
                tolerance::monte_carlo_cycle(
                    &model,
                    &start,
                    &drive,
                    &options,
                    &outputs,
                    &tolerances,
                    &run,
                )
                .map_err(Failure::Tolerance)
            })
            .transpose()?;
        let chosen: Vec<usize> = (0..PARAMETERS).filter(|&j| !names[j].is_empty()).collect();
        let mut bands = Vec::new();
        for (o, (band, text)) in cycle.bands.iter().zip(&quantities).enumerate() {
            let spread = |f: fn(&tolerance::Spread) -> f64| -> Vec<f64> {
                (band.spread.iter())
                    .map(|s| s.as_ref().map_or(f64::NAN, f))
                    .collect()
            };
            let largest = band.largest().map(|(k, _)| k);
            let shares = largest
                .and_then(|k| band.gradient[k])
                .map(|g| tolerances.contributions(&g))
                .unwrap_or_else(SVector::zeros);
            bands.push(Band {
                quantity: text.clone(),
                v: band.v.iter().flat_map(|v| v.iter().copied()).collect(),
                value: band.value.clone(),
                worst_case: spread(|s| s.worst_case),
                rss: spread(|s| s.rss),
                sigma: spread(|s| s.sigma),
                largest,
                shares: chosen.iter().map(|&j| shares[j]).collect(),
                sigma_monte_carlo: samples.as_ref().map(|s| {
                    (0..band.value.len())
                        .map(|k| match s.statistics[o].get(k) {
                            // σ of fewer than two samples is not known.
                            Some(x) if x.count >= 2 => x.std(),
                            _ => f64::NAN,
                        })
                        .collect()
                }),
            });
        }
        Ok(Spreads {
            parameters: chosen.iter().map(|&j| names[j].to_owned()).collect(),
            bands,
            limit: (cycle.limit.as_ref())
                .filter(|l| l.reaches_limit())
                .map(|l| l.v.as_slice().to_vec()),
            failed_samples: samples.map_or(0, |s| s.failures.len()),
        })
    }
}

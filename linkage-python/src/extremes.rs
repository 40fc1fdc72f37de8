//! Extremes and zeros from Python: `Mechanism.extremes`, where quantities
//! are largest, smallest or zero over a sweep, located to rounding
//! between its poses.

use crate::errors::Failure;
use crate::source::Source;
use crate::sweep::DriveArgs;
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::Job;
use linkage::prelude::*;
use linkage::quantity::{Written, written};
use linkage::watch::{FoundKind, Watch, locate};

/// One extreme or zero found: the quantity as written, its kind, the
/// drivers there and its value.
pub struct Extreme {
    pub quantity: String,
    pub kind: &'static str,
    pub v: Vec<f64>,
    pub value: f64,
}

/// The extremes (and zeros, if asked) of `quantities` (default: every
/// dependent coordinate) over the sweep `drive` asks for.
pub struct Find {
    pub source: Source,
    pub drive: DriveArgs,
    pub quantities: Vec<String>,
    pub zeros: bool,
}

impl Job for Find {
    type Output = Vec<Extreme>;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Vec<Extreme>, Failure> {
        let quantities: Vec<String> = if self.quantities.is_empty() {
            model.u_names().iter().map(|n| n.to_string()).collect()
        } else {
            self.quantities.clone()
        };
        let mut watches = Vec::new();
        let mut watched: Vec<&str> = Vec::new();
        for text in &quantities {
            if self.zeros {
                watches.push(watch::<M, F>(text)?.zeros());
                watched.push(text);
            }
            watches.push(watch::<M, F>(text)?.extrema());
            watched.push(text);
        }
        let (u0, drive, options) = self.drive.resolve(&self.source, &model)?;
        let sweep = model.sweep(&u0, &drive, &options)?;
        let found =
            locate(&model, &sweep, &watches, &Options::default()).map_err(Failure::Watch)?;
        Ok(found
            .iter()
            .map(|f| Extreme {
                quantity: watched.get(f.watch).copied().unwrap_or_default().to_owned(),
                kind: match f.kind {
                    FoundKind::Maximum => "maximum",
                    FoundKind::Minimum => "minimum",
                    FoundKind::Zero { rising: true } => "zero, rising",
                    FoundKind::Zero { rising: false } => "zero, falling",
                },
                v: f.v.as_slice().to_vec(),
                value: f.value,
            })
            .collect())
    }
}

/// The watch of a quantity written as text.
fn watch<const M: usize, const F: usize>(text: &str) -> Result<Watch<'static, M, F>, Failure> {
    match written(text).map_err(Failure::BadInput)? {
        Written::Coordinate(name, of) => Ok(Watch::coordinate(name, of)),
        Written::Point(name, axis, of) => Ok(Watch::point(name, axis, of)),
        Written::Path(_) => Err(Failure::BadInput(format!(
            "`{text}`: a path's deviation is a quantity of the tolerance analysis, not one to watch"
        ))),
    }
}

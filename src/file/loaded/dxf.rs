//! A topology file's mechanism for CAD, as DXF: the joints at the file's
//! pose (and the frame's pivots), their paths over the drive range, and
//! the drawing's sizes — what `linkage dxf` and the page's export write.

use super::{LoadError, Loaded};
use crate::mechanism::Fixed;
use crate::runtime::Kernels;
use crate::topology::dxf::DxfOptions;
use nalgebra::Vector2;

/// Named positions: each joint (or point) and where it is.
pub type Positions = Vec<(String, [f64; 2])>;

/// How the DXF is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DxfChoice {
    /// Every moving link laid flat and labelled, not the pose.
    pub cut_sheet: bool,
    /// The links' width (the holes then 0.4 of it), if not chosen from
    /// the mechanism's size.
    pub width: Option<f64>,
    /// The pin holes' diameter, if not chosen from the width.
    pub hole: Option<f64>,
}

/// Why a DXF cannot be drawn.
#[derive(Debug)]
#[non_exhaustive]
pub enum DxfError {
    /// The mechanism was given by its equations: it has no links to draw.
    NotATopology,
    /// The width or the holes are not positive, or the holes are not
    /// narrower than the links.
    Sizes { width: f64, hole: f64 },
    /// The pose or the sweep failed.
    Load(LoadError),
}

crate::error::error_impls! {
    DxfError {
        Self::NotATopology => ("a DXF is drawn from joints and links: this mechanism is given by its equations"),
        Self::Sizes { width, hole } => ("the links' width ({width}) and the holes ({hole}) must be positive, the holes narrower than the links"),
        Self::Load(inner) => ("{inner}"),
    }
    wraps { Load(LoadError) }
}

impl Loaded {
    /// The joints' positions at the file's pose (the frame's pivots,
    /// `x_J` and `y_J`, among them), and at each pose of the sweep over
    /// the drive range.
    pub fn joint_positions<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<(Positions, Vec<Positions>), LoadError> {
        let (drives, pose) = self.analysed(model)?;
        let names = model.point_names();
        let file = self.file();
        let pivots: Positions = (file.parameters.iter())
            .filter_map(|p| {
                let joint = p.name.text.strip_prefix("x_")?;
                let y = file.parameter(&format!("y_{joint}"))?;
                Some((joint.to_owned(), [p.quantity.value, y]))
            })
            .collect();
        let with_pivots = |points: &[Vector2<f64>]| -> Positions {
            (names.iter().zip(points))
                .map(|(n, p)| ((*n).to_owned(), [p.x, p.y]))
                .chain(pivots.iter().cloned())
                .collect()
        };
        let positions = with_pivots(pose.points.as_ref());
        let mut cycle = Vec::new();
        self.sweep_each(model, drives.steps, &mut |_, p| {
            cycle.push(with_pivots(model.point_positions(&p.u, &p.v).as_ref()));
        })?;
        Ok((positions, cycle))
    }

    /// The file's mechanism as DXF (see [`DxfChoice`]), drawn from its
    /// topology.
    pub fn dxf<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        choice: &DxfChoice,
    ) -> Result<String, DxfError> {
        let topology = self.topology().ok_or(DxfError::NotATopology)?;
        let (positions, cycle) = self.joint_positions(model)?;
        let extent = |k: usize| {
            let values = positions.iter().map(|(_, p)| p[k]);
            let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                (l.min(x), h.max(x))
            });
            hi - lo
        };
        let mut options = DxfOptions::for_size(extent(0).max(extent(1)));
        if let Some(width) = choice.width {
            options.width = width;
            options.hole_diameter = 0.4 * width;
        }
        if let Some(hole) = choice.hole {
            options.hole_diameter = hole;
        }
        let positive = [options.width, options.hole_diameter]
            .iter()
            .all(|x| x.is_finite() && *x > 0.0);
        if !positive || options.hole_diameter >= options.width {
            return Err(DxfError::Sizes {
                width: options.width,
                hole: options.hole_diameter,
            });
        }
        Ok(if choice.cut_sheet {
            topology.cut_sheet_dxf(&positions, &cycle, &options)
        } else {
            topology.pose_dxf(&positions, &cycle, &options)
        })
    }
}

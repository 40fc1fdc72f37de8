//! `linkage dxf TOPOLOGY -o pose.dxf`: the pose at `at` for CAD, or with
//! `--cut-sheet` the links laid flat.

use crate::cli::DxfArgs;
use crate::failure::Failure;
use crate::load::{Loaded, load_topology};
use crate::sizes::{self, Job};
use linkage::file::TopologyFile;
use linkage::mechanism::Fixed;
use linkage::prelude::*;
use linkage::topology::dxf::DxfOptions;

/// The joints' positions at the pose (the frame's pivots where drawn),
/// and at each pose of a cycle over the drive range.
struct Pose<'a> {
    loaded: &'a Loaded,
}

type Positions = Vec<(String, [f64; 2])>;

impl Job for Pose<'_> {
    type Output = (Positions, Vec<Positions>);
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Self::Output, Failure> {
        let (drives, pose) = self.loaded.analysed(&model)?;
        let names = model.point_names();
        let file = &self.loaded.file();
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
        self.loaded.sweep_each(&model, drives.steps, &mut |_, p| {
            cycle.push(with_pivots(model.point_positions(&p.u, &p.v).as_ref()));
        })?;
        Ok((positions, cycle))
    }
}

pub fn run(args: &DxfArgs) -> Result<(), Failure> {
    let (topology, loaded): (TopologyFile, Loaded) = load_topology(&args.input.file)?;
    let topology = &topology.topology;
    let (positions, cycle) = sizes::run(loaded.mechanism(), Pose { loaded: &loaded })?;
    let size = {
        let extent = |k: usize| {
            let values = positions.iter().map(|(_, p)| p[k]);
            let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                (l.min(x), h.max(x))
            });
            hi - lo
        };
        extent(0).max(extent(1))
    };
    let mut options = DxfOptions::for_size(size);
    if let Some(width) = args.width {
        options.width = width;
        options.hole_diameter = 0.4 * width;
    }
    if let Some(hole) = args.hole {
        options.hole_diameter = hole;
    }
    let sizes_ok = [options.width, options.hole_diameter]
        .iter()
        .all(|x| x.is_finite() && *x > 0.0);
    if !sizes_ok || options.hole_diameter >= options.width {
        return Err(Failure::Malformed(
            "`--width` and `--hole` must be positive, the holes narrower than the links".to_owned(),
        ));
    }
    let dxf = if args.cut_sheet {
        topology.cut_sheet_dxf(&positions, &cycle, &options)
    } else {
        topology.pose_dxf(&positions, &cycle, &options)
    };
    super::emit(args.input.output.as_deref(), dxf.as_bytes())
}

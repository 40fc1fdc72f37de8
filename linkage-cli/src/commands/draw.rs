//! `linkage draw FILE -o pose.svg`: the mechanism at its `at` pose, drawn
//! as the file's `[drawing]` says, with the paths its points trace over
//! the drive range (without `[drawing]`, every named point's path).

use crate::cli::Draw;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::sizes::{self, Job};
use linkage::draw::scene::Frame;
use linkage::mechanism::Fixed;
use linkage::prelude::*;

struct Picture<'a> {
    loaded: &'a Loaded,
    width: f64,
}

impl Job for Picture<'_> {
    type Output = String;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<String, Failure> {
        let (drives, pose) = self.loaded.analysed(&model)?;
        let frame = Frame::from_analysis(&model, &pose);
        let mut cycle = Vec::new();
        self.loaded.sweep_each(&model, drives.steps, &mut |_, p| {
            cycle.push(Frame::from_sweep_pose(&model, p))
        })?;
        self.loaded
            .scene_of(&model)
            .width(self.width)
            .render(&frame, &cycle)
            .map_err(|e| Failure::Analysis(format!("the drawing: {e}")))
    }
}

pub fn run(args: &Draw) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    if !(args.width.is_finite() && args.width >= 100.0) {
        return Err(Failure::Analysis(
            "`--width` must be at least 100 pixels".into(),
        ));
    }
    let svg = sizes::run(
        loaded.mechanism(),
        Picture {
            loaded: &loaded,
            width: args.width,
        },
    )?;
    super::emit(args.input.output.as_deref(), svg.as_bytes())
}

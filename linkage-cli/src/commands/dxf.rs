//! `linkage dxf TOPOLOGY -o pose.dxf`: the pose at `at` for CAD, or with
//! `--cut-sheet` the links laid flat (drawn by the library's
//! [`Loaded::dxf`](linkage::file::Loaded::dxf), as the page draws it).

use crate::cli::DxfArgs;
use crate::failure::Failure;
use crate::load::{Loaded, load_topology};
use crate::sizes::{self, Job};
use linkage::file::{DxfChoice, DxfError};
use linkage::mechanism::Fixed;

/// The DXF of the file's mechanism.
struct Dxf<'a> {
    loaded: &'a Loaded,
    choice: DxfChoice,
}

impl Job for Dxf<'_> {
    type Output = String;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<String, Failure> {
        self.loaded
            .dxf(&model, &self.choice)
            .map_err(|error| match error {
                DxfError::Load(error) => error.into(),
                DxfError::Sizes { .. } => Failure::Malformed(
                    "`--width` and `--hole` must be positive, the holes narrower than the links"
                        .to_owned(),
                ),
                other => Failure::Malformed(other.to_string()),
            })
    }
}

pub fn run(args: &DxfArgs) -> Result<(), Failure> {
    let (_, loaded) = load_topology(&args.input.file)?;
    let choice = DxfChoice {
        cut_sheet: args.cut_sheet,
        width: args.width,
        hole: args.hole,
    };
    let dxf = sizes::run(
        loaded.mechanism(),
        Dxf {
            loaded: &loaded,
            choice,
        },
    )?;
    super::emit(args.input.output.as_deref(), dxf.as_bytes())
}

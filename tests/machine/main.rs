//! Machines: the Mathcad course project's shaping machine (synthesis,
//! kinematics, reduced dynamics, flywheel, joint reactions), its cam, and
//! the force analysis of a four-bar against a free-body solution.

#[path = "../common/mod.rs"]
mod common;
#[path = "../../examples/shaper/machine.rs"]
mod machine;
#[path = "../models/mod.rs"]
mod models;
#[path = "../../examples/shaper/redesign.rs"]
mod redesign;

mod cam;
mod kinetostatics;
mod shaper;

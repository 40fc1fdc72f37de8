//! The mechanisms of the integration tests, one per file, shared by every
//! test binary (the four-bars of the Maple worksheet and of path generation
//! come from `linkage::mechanisms`).
#![allow(dead_code, unused_imports)] // not every binary uses every model

mod boom;
mod coupler;
mod five_bar;
mod six_bar;
mod slider_crank;
mod slider_driven;
mod stephenson_three;
mod watt_six_bar;

pub use boom::{BOOM, Boom};
pub use coupler::Coupler;
pub use five_bar::{FIVE_BAR, FiveBar};
pub use six_bar::{SIX_BAR, SixBar};
pub use slider_crank::{SLIDER_CRANK, SliderCrank};
pub use slider_driven::{SLIDER_DRIVEN, SliderDriven};
pub use stephenson_three::{STEPHENSON_THREE, StephensonThree};
pub use watt_six_bar::{WATT_SIX_BAR, WattSixBar};

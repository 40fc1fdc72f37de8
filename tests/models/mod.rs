//! The mechanisms of the integration tests, one per file, shared by every
//! test binary (the four-bars of the Maple worksheet and of path generation
//! come from `linkage::mechanisms`).
#![allow(dead_code, unused_imports)] // not every binary uses every model

mod boom;
mod coupler;
mod five_bar;
mod jansen_leg;
mod quick_return;
mod six_bar;
mod slider_crank;
mod slider_driven;
mod stephenson_three;
mod trammel;
mod watt_six_bar;

pub use boom::{BOOM, Boom};
pub use coupler::Coupler;
pub use five_bar::{FIVE_BAR, FiveBar};
pub use jansen_leg::{JANSEN_LEG, JansenLeg};
pub use quick_return::{QUICK_RETURN, QuickReturn};
pub use six_bar::{SIX_BAR, SixBar};
pub use slider_crank::{SLIDER_CRANK, SliderCrank};
pub use slider_driven::{SLIDER_DRIVEN, SliderDriven};
pub use stephenson_three::{STEPHENSON_THREE, StephensonThree};
pub use trammel::{TRAMMEL, Trammel};
pub use watt_six_bar::{WATT_SIX_BAR, WattSixBar};

//! Positions, velocities, accelerations and sensitivities: the Maple
//! worksheet's four-bar number by number, both acceleration methods, five
//! more mechanisms (and those the library `mechanisms/` adds), the typed errors of bad input, batches, and assembly
//! without a guess.

#[path = "../common/mod.rs"]
mod common;
#[path = "../models/mod.rs"]
mod models;

mod acceleration_methods;
mod assembly;
mod batch;
mod errors;
mod fourbar_worksheet;
mod library;
mod mechanisms;
mod run_time;
mod sensitivities;

//! Sweeps: tracked over full cycles through singular poses, each method
//! near singular poses against the 50-digit reference, the zeros and
//! extrema located along them, and the grids of step sizes through branch
//! points (one binary: each links the whole library).

#[path = "../common/mod.rs"]
mod common;
#[path = "../models/mod.rs"]
mod models;
/// Grids of step sizes through branch points and limit positions.
mod singular_grid;
/// Near singular poses, each method against the 50-digit reference.
mod stability_near_singular;
/// Tracked sweeps over full cycles.
mod stability_sweeps;
/// Zeros and extrema along a sweep.
mod watch;

//! The targeted campaign: sweeps whose grid lands exactly on, and within a
//! few ulps of, every singular pose — the measure-zero case that random
//! campaigns never hit and a user with a round step count hits first.
//!
//! For every step count in a range, both assembly branches and both
//! directions, a start and a step are chosen so that one grid pose is the
//! singular pose's driver value exactly (or 1 or 3 ulps off it), for:
//! change-point four-bars of four proportions (branch point at θ2 = π or 0),
//! the parallelogram and the anti-parallelogram (branch points at 0 and π),
//! a kite and a deltoid, a slider-crank with r = l (branch points at ±π/2),
//! a two-loop six-bar whose second loop is a change-point four-bar, a triple
//! rocker rocked through its limit positions and driven into one, and a
//! slider-crank driven by its slider through its dead centres.
//!
//! Each run must report every branch point and limit position it passes, in
//! order and of the right kind, located to 1e-12 (relative to max(1, |v|));
//! every pose must be on the branch the closed form says (the smooth
//! continuation through a branch point, the other branch after a limit
//! position); and consecutive poses must not jump in their velocity ratios
//! farther than the step and the second-order analogs allow.
//!
//! The step counts are 50 to 5000, every 331st in CI; every one with
//!
//!     LINKAGE_GRID=full cargo test --release --test sweep singular_grid -- --nocapture
//!
//! (`LINKAGE_GRID=3119,4000` reruns just those step counts.)

mod four_bars;
mod grids;
mod harness;
mod limit_positions;
mod slider_crank_and_six_bar;

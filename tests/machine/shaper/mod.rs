//! The shaping machine of the course project, first half:
//! synthesis, kinematics, reduced dynamics, work, the flywheel by the energy
//! method, ω1 and ε1 — against the 50-digit reference
//! (tests/data/shaper_cam_reference.csv), and, with other inputs, against
//! the invariants of the method; and its two assembly modes, found without
//! a guess.

mod assembly;
mod bad_settings;
mod design;
mod first_half;
mod kinetostatics;
mod reference;
mod steady_motion;

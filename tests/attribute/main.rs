//! The attribute itself: every form of an equation it accepts, names that
//! never collide with the user's, the other sources of derivatives, every
//! generated item used as a user's code uses it, and the compile-time
//! diagnostics of its mistakes.

#[path = "../common/mod.rs"]
mod common;
#[path = "../models/mod.rs"]
mod models;

mod attribute_forms;
mod diagnostics;
mod every_item;
mod hygiene;
mod jacobian_sources;

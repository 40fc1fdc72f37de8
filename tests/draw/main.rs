//! Pictures: scenes read back from their SVG, and the legends of charts and
//! diagrams (the stability study's charts among them).

#[path = "../../examples/stability/charts.rs"]
mod charts;
#[path = "../common/mod.rs"]
mod common;
#[path = "../models/mod.rs"]
mod models;
#[path = "../../examples/stability/study.rs"]
mod study;

mod chart;
mod diagrams;
mod overlays;
mod print;
mod scenes;
mod sheets;

//! Run-time mechanisms against their compiled twins: the same attribute
//! text, compiled by the macro and read at run time into tapes, gives the
//! same numbers to the bit — every kernel at random poses and rates, and
//! the analyses (a pose, a sweep with its singular poses) built on them.

use crate::common::twins::{every_kernel, same, same_points};
use crate::models::{BOOM, FIVE_BAR, SIX_BAR, SLIDER_CRANK, STEPHENSON_THREE, WATT_SIX_BAR};
use linkage::mechanism::{Fixed, Mechanism};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use proptest::prelude::*;

/// The text inside `#[...linkage(` … `)]` of the struct `name` in `source`.
fn attribute_of(source: &str, name: &str) -> String {
    let at = source
        .find(&format!("pub struct {name} "))
        .unwrap_or_else(|| panic!("no struct {name}"));
    let start = source[..at].rfind("linkage(").expect("an attribute") + "linkage(".len();
    let mut depth = 0;
    for (k, c) in source[start..at].char_indices() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' if depth == 0 => return source[start..start + k].to_owned(),
            ')' | ']' | '}' => depth -= 1,
            _ => {}
        }
    }
    panic!("the attribute of {name} does not end")
}

/// The twin of a compiled mechanism: its attribute read at run time, with
/// the compiled mechanism's parameter values.
fn twin<L, const M: usize, const F: usize, const K: usize>(
    compiled: &L,
    source: &str,
    name: &str,
) -> Fixed<M, F>
where
    L: Sensitivities<M, F, K>,
{
    let values = compiled.params();
    let parameters: Vec<(&str, f64)> = (compiled.param_names().iter().copied())
        .zip(values.iter().copied())
        .collect();
    let mechanism = Mechanism::from_text(name, &attribute_of(source, name), &parameters)
        .unwrap_or_else(|e| panic!("{name} reads at run time: {e}"));
    mechanism.fixed::<M, F>().expect("the compiled sizes")
}

/// u, v, u̇, v̇, ü, v̈ as lists.
type Motion6 = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

/// A pose in motion: every coordinate and rate in [−4, 4).
fn motion<const M: usize, const F: usize>() -> impl Strategy<Value = Motion6> {
    let numbers = |n: usize| proptest::collection::vec(-4.0..4.0f64, n);
    (
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
    )
}

macro_rules! twins {
    ($($test:ident: $model:expr, $name:literal, $source:literal, $m:literal, $f:literal, $k:literal;)*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig { cases: 200, failure_persistence: None, ..ProptestConfig::default() })]
            #[test]
            fn $test((u, v, udot, vdot, uddot, vddot) in motion::<$m, $f>()) {
                let compiled = $model;
                let twin = twin::<_, $m, $f, $k>(&compiled, include_str!($source), $name);
                let vector = |x: &[f64]| SVector::<f64, $m>::from_column_slice(x);
                let driver = |x: &[f64]| SVector::<f64, $f>::from_column_slice(x);
                every_kernel(
                    &compiled, &twin,
                    &vector(&u), &driver(&v), &vector(&udot), &driver(&vdot), &vector(&uddot), &driver(&vddot),
                );
            }
        }
    )*};
}

twins! {
    the_worksheets_four_bar: FourBar::WORKSHEET, "FourBar", "../../src/mechanisms.rs", 2, 1, 4;
    the_slider_crank: SLIDER_CRANK, "SliderCrank", "../models/slider_crank.rs", 2, 1, 3;
    the_five_bar: FIVE_BAR, "FiveBar", "../models/five_bar.rs", 2, 2, 5;
    the_boom: BOOM, "Boom", "../models/boom.rs", 2, 1, 4;
    the_six_bar: SIX_BAR, "SixBar", "../models/six_bar.rs", 4, 1, 10;
    the_watt_six_bar: WATT_SIX_BAR, "WattSixBar", "../models/watt_six_bar.rs", 4, 1, 10;
    the_stephenson_three: STEPHENSON_THREE, "StephensonThree", "../models/stephenson_three.rs", 4, 1, 11;
}

/// The analyses on the two: a pose analysed, and a sweep through the
/// worksheet's whole turn, pose by pose the same to the bit.
#[test]
fn a_sweep_of_the_twin_is_the_compiled_sweep() {
    let compiled = FourBar::WORKSHEET;
    let twin = twin::<_, 2, 1, 4>(
        &compiled,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    let options = Options::default();
    let (u0, v0) = (vector![1.2, -0.9], vector![0.35]);
    let a = compiled
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    let b = twin
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    same("analysis.u", &a.u, &b.u);
    same("analysis.uddot", &a.uddot, &b.uddot);
    same_points("analysis.points", a.points.as_ref(), b.points.as_ref());
    let drive = Drive::Line {
        from: vector![0.35],
        to: vector![0.35 + std::f64::consts::TAU],
        steps: 720,
    };
    let sweep_options = SweepOptions::default();
    let a = compiled.sweep(&u0, &drive, &sweep_options).unwrap();
    let b = twin.sweep(&u0, &drive, &sweep_options).unwrap();
    assert_eq!(a.poses.len(), b.poses.len());
    for (p, q) in a.poses.iter().zip(&b.poses) {
        same("pose.v", &p.v, &q.v);
        same("pose.u", &p.u, &q.u);
        same("pose.udot", &p.udot, &q.udot);
        same("pose.uddot", &p.uddot, &q.uddot);
    }
    assert_eq!(a.events.len(), b.events.len());
    assert_eq!(a.complete, b.complete);
}

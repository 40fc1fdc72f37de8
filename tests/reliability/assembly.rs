//! Assembly without a guess on random mechanisms: random four-bars and
//! Watt six-bars (links over three orders of magnitude, any crank angle,
//! most built around a pose so that they assemble)
//! searched with `linkage::assembly`, every count and every mode against
//! the law of cosines (two circles meet in two points, one or none), loop
//! by loop. Worlds within 1e-6 (relative) of a dead centre, where the
//! count turns on rounding, are not judged; garbage lengths must give an
//! error, never a panic or a NaN.

use linkage::assembly::{AssemblyError, Modes, Search, modes};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};
use std::cell::RefCell;
use std::f64::consts::PI;

use crate::models::WattSixBar;

/// Random worlds, the same every run.
fn runner(cases: u32) -> TestRunner {
    let mut config = Config::with_cases(cases);
    config.failure_persistence = None;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x6173_7365_6d62_6c79);
    }
    TestRunner::new(config)
}

/// A length over three orders of magnitude.
fn length() -> BoxedStrategy<f64> {
    (-1.5f64..1.5).prop_map(|e| 10f64.powf(e)).boxed()
}

/// The points X with |X − P| = a and |X − Q| = b (the side of P→Q each
/// is on), and the margin from the nearest change of their count, relative
/// to a + b: negative where the circles do not meet.
fn circles(p: Vector2<f64>, a: f64, q: Vector2<f64>, b: f64) -> (Vec<Vector2<f64>>, f64) {
    let d = (q - p).norm();
    let margin = (d - (a - b).abs()).min(a + b - d) / (a + b);
    if margin < 0.0 {
        return (Vec::new(), margin);
    }
    let along = (a * a - b * b + d * d) / (2.0 * d);
    let across = (a * a - along * along).max(0.0).sqrt();
    let e = (q - p) / d;
    let n = Vector2::new(-e.y, e.x);
    let points = [1.0, -1.0]
        .iter()
        .map(|s| p + e * along + n * (s * across))
        .collect();
    (points, margin)
}

fn angle(v: Vector2<f64>) -> f64 {
    v.y.atan2(v.x)
}

/// Every mode is one of `expected` (angles up to whole turns, within
/// 1e-10 amplified by the mode's conditioning) and every one is found.
fn same_modes<const M: usize>(found: &Modes<M, 1>, expected: &[SVector<f64, M>]) -> bool {
    found.modes.len() == expected.len()
        && found.modes.iter().all(|mode| {
            expected.iter().any(|u| {
                let tolerance = 1e-10 / mode.rcond;
                (0..M).all(|j| {
                    let d = (mode.u[j] - u[j] + PI).rem_euclid(2.0 * PI) - PI;
                    d.abs() <= tolerance
                })
            })
        })
}

#[test]
fn random_four_bars_have_the_law_of_cosines_modes() {
    // Half the worlds built around a pose (the joint C anywhere, the
    // coupler and rocker reaching it), half of independent lengths.
    let world = (
        [length(), length(), length(), length()],
        -PI..PI,
        (any::<bool>(), -2.0f64..2.0, -2.0f64..2.0),
    );
    let judged = RefCell::new([0usize; 3]);
    runner(300)
        .run(
            &world,
            |([l1, l2, mut l3, mut l4], theta2, (built, cx, cy))| {
                let b = Vector2::new(l2 * theta2.cos(), l2 * theta2.sin());
                let d = Vector2::new(l1, 0.0);
                if built {
                    let c = Vector2::new(cx, cy) * l1.max(l2);
                    (l3, l4) = ((c - b).norm(), (d - c).norm());
                }
                let bar = FourBar { l1, l2, l3, l4 };
                let (joints, margin) = circles(b, l3, d, l4);
                let found = modes(&bar, &vector![theta2], &Search::default());
                if margin.abs() < 1e-6 {
                    return Ok(());
                }
                let expected: Vec<SVector<f64, 2>> = joints
                    .iter()
                    .map(|&c| vector![angle(c - b), angle(d - c)])
                    .collect();
                judged.borrow_mut()[expected.len()] += 1;
                match found {
                    Ok(found) => prop_assert!(
                        found.stable && same_modes(&found, &expected),
                        "{bar:?} at {theta2}: {:?}, expected {expected:?}",
                        found.modes
                    ),
                    Err(AssemblyError::NoAssembly { .. }) => {
                        prop_assert!(expected.is_empty(), "{bar:?} at {theta2}: none found")
                    }
                    Err(e) => prop_assert!(false, "{bar:?} at {theta2}: {e}"),
                }
                Ok(())
            },
        )
        .unwrap();
    let judged = judged.into_inner();
    eprintln!("four-bars judged with 0, 1, 2 modes: {judged:?}");
    assert!(judged[0] > 50 && judged[2] > 100, "{judged:?}");
}

#[test]
fn random_watt_six_bars_have_the_law_of_cosines_modes_loop_by_loop() {
    // Built around a pose: the joints C and F anywhere (in units of the
    // frame), the links reaching them; G where a random link from F ends.
    let world = (
        [length(), length(), length(), length()],
        (-PI..PI, -PI..PI),
        [-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0],
    );
    let judged = RefCell::new([0usize; 5]);
    runner(150)
        .run(
            &world,
            |([l1, l2, le, l6], (theta2, beta), [cx, cy, fx, fy])| {
                let unit = l1.max(l2);
                let b = Vector2::new(l2 * theta2.cos(), l2 * theta2.sin());
                let d = Vector2::new(l1, 0.0);
                let c = Vector2::new(cx, cy) * unit;
                let (l3, l4) = ((c - b).norm(), (d - c).norm());
                let theta4 = angle(d - c);
                let e = d + Vector2::new((theta4 + beta).cos(), (theta4 + beta).sin()) * le;
                let f = Vector2::new(fx, fy) * unit;
                let l5 = (f - e).norm();
                let g = f + Vector2::new(beta.sin(), beta.cos()) * l6;
                let watt = WattSixBar {
                    l1,
                    l2,
                    l3,
                    l4,
                    le,
                    beta,
                    l5,
                    l6,
                    gx: g.x,
                    gy: g.y,
                };
                let (joints, margin) = circles(b, l3, d, l4);
                let mut least = margin.abs();
                let mut expected: Vec<SVector<f64, 4>> = Vec::new();
                for c in joints {
                    let theta4 = angle(d - c);
                    let e = d + Vector2::new((theta4 + beta).cos(), (theta4 + beta).sin()) * le;
                    let (fs, margin) = circles(e, l5, g, l6);
                    least = least.min(margin.abs());
                    for f in fs {
                        expected.push(vector![angle(c - b), theta4, angle(f - e), angle(g - f)]);
                    }
                }
                if least < 1e-6 {
                    return Ok(());
                }
                judged.borrow_mut()[expected.len()] += 1;
                match modes(&watt, &vector![theta2], &Search::default()) {
                    Ok(found) => prop_assert!(
                        found.stable && same_modes(&found, &expected),
                        "{watt:?} at {theta2}: {:?}, expected {expected:?}",
                        found.modes
                    ),
                    Err(AssemblyError::NoAssembly { .. }) => {
                        prop_assert!(expected.is_empty(), "{watt:?} at {theta2}: none found")
                    }
                    Err(e) => prop_assert!(false, "{watt:?} at {theta2}: {e}"),
                }
                Ok(())
            },
        )
        .unwrap();
    let judged = judged.into_inner();
    eprintln!("Watt six-bars judged with 0 to 4 modes: {judged:?}");
    assert!(judged[2] > 20 && judged[4] > 20, "{judged:?}");
}

#[test]
fn garbage_lengths_are_errors_not_panics() {
    for l in [f64::NAN, f64::INFINITY, 0.0, -1.0, 1e300, 1e-300] {
        let bar = FourBar {
            l1: 80.0,
            l2: l,
            l3: 50.0,
            l4: 70.0,
        };
        match modes(&bar, &vector![0.3], &Search::default()) {
            Ok(found) => {
                for mode in &found.modes {
                    assert!(mode.u.iter().all(|x| x.is_finite()), "{l}: {mode:?}");
                    assert!(mode.residual <= 1e-12);
                }
            }
            Err(e) => {
                let _ = e.to_string();
            }
        }
    }
}

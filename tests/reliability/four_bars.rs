//! Random four-bars, at random poses and guesses, through every entry point.

use crate::common::FourBar;
use crate::harness::{
    Tally, Truth, check, four_bar_truth, length, moderate, number, report, runner,
};
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

#[test]
fn four_bars_never_lie() {
    let tally = RefCell::new(Tally::default());
    let start = Instant::now();
    // Mode 0: independent lengths; 1: a parallelogram (l3 = l1, l4 = l2);
    // 2: coincident pivots (l1 = 0); 3: all equal; 4–7: built around a pose
    // (C anywhere), guessed from near or far.
    let world = (
        0..8usize,
        [length(), length(), length(), length()],
        [number(10.0), number(10.0)],
        number(10.0),
        number(100.0),
        number(1e4),
        any::<bool>(),
        (-3.0f64..3.0, -3.0f64..3.0, -4.0f64..0.5),
    );
    runner()
        .run(
            &world,
            |(mode, mut l, [mut g3, mut g4], theta2, omega, alpha, damped, (cx, cy, noise))| {
                match mode {
                    1 => {
                        l[2] = l[0];
                        l[3] = l[1];
                    }
                    2 => l[0] = 0.0,
                    3 => l = [l[0]; 4],
                    4..=7 if l[0].is_finite() && l[1].is_finite() && theta2.is_finite() => {
                        // C at (cx, cy) in units of the frame: the pose exists.
                        let unit = l[0].abs().max(l[1].abs()).max(1e-3);
                        let b = Vector2::new(l[1] * theta2.cos(), l[1] * theta2.sin());
                        let c = Vector2::new(cx, cy) * unit;
                        let d = Vector2::new(l[0], 0.0);
                        l[2] = (c - b).norm();
                        l[3] = (d - c).norm();
                        let exact = [(c - b).y.atan2((c - b).x), (d - c).y.atan2((d - c).x)];
                        let off = 10f64.powf(noise);
                        g3 = exact[0] + off * (g3.is_finite() as u8 as f64) * g3.signum();
                        g4 = exact[1] - off * (g4.is_finite() as u8 as f64) * g4.signum();
                    }
                    _ => {}
                }
                // Damped Newton from within 0.01 rad of a pose clear of
                // every singular one, at moderate numbers, must succeed.
                let truth = four_bar_truth(l, theta2);
                let expect_ok = (4..=7).contains(&mode)
                    && noise < -2.0
                    && damped
                    && matches!(truth, Truth::Assembles { clear: true })
                    && l.iter().all(|&x| (1e-6..=1e6).contains(&x.abs()))
                    && [g3, g4, theta2, omega, alpha].iter().all(|&x| moderate(x));
                let bar = FourBar {
                    l1: l[0],
                    l2: l[1],
                    l3: l[2],
                    l4: l[3],
                };
                check(
                    &bar,
                    vector![g3, g4],
                    theta2,
                    omega,
                    alpha,
                    damped,
                    truth,
                    expect_ok,
                    &tally,
                )
            },
        )
        .unwrap();
    let tally = tally.into_inner();
    report("four-bars", &tally, start.elapsed().as_secs_f64());
    assert!(tally.ok > 0 && tally.errors.contains_key("CannotAssemble"));
}

//! Random slider-cranks, at random poses and guesses, through every entry
//! point.

use crate::harness::{Tally, Truth, check, length, moderate, number, report, runner, slider_truth};
use crate::models::SliderCrank;
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

#[test]
fn slider_cranks_never_lie() {
    let tally = RefCell::new(Tally::default());
    let start = Instant::now();
    let world = (
        [
            length(),
            length(),
            prop_oneof![3 => Just(0.0), 7 => length()].boxed(),
        ],
        [number(10.0), number(1e3)],
        number(10.0),
        number(100.0),
        number(1e4),
        any::<bool>(),
        (any::<bool>(), -1.5f64..1.5, -4.0f64..0.5),
    );
    runner()
        .run(
            &world,
            |(
                [r, l, mut e],
                [mut g3, mut gs],
                theta2,
                omega,
                alpha,
                damped,
                (built, theta3, noise),
            )| {
                if built && [r, l, theta2].iter().all(|x| x.is_finite()) {
                    // The rod at θ3: the offset that puts the slider there.
                    e = r * theta2.sin() + l * theta3.sin();
                    let s = r * theta2.cos() + l * theta3.cos();
                    let off = 10f64.powf(noise);
                    g3 = theta3 + off;
                    gs = s + off * l.abs();
                }
                let truth = slider_truth(r, l, e, theta2);
                let expect_ok = built
                    && noise < -2.0
                    && damped
                    && matches!(truth, Truth::Assembles { clear: true })
                    && [r, l].iter().all(|&x| (1e-6..=1e6).contains(&x.abs()))
                    && [e, g3, gs, theta2, omega, alpha]
                        .iter()
                        .all(|&x| moderate(x));
                let crank = SliderCrank { r, l, e };
                check(
                    &crank,
                    vector![g3, gs],
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
    report("slider-cranks", &tally, start.elapsed().as_secs_f64());
    assert!(tally.ok > 0);
}

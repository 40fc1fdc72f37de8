//! Random six-bars, both loops closed around a pose or not, through every
//! entry point.

use crate::harness::{Tally, Truth, check, length, number, report, runner};
use crate::models::SixBar;
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

#[test]
fn six_bars_never_lie() {
    let tally = RefCell::new(Tally::default());
    let start = Instant::now();
    let world = (
        [length(), length(), length(), length(), length(), length()],
        [number(3.0), number(100.0), number(100.0)],
        [number(10.0), number(10.0), number(10.0), number(10.0)],
        number(10.0),
        number(100.0),
        number(1e4),
        any::<bool>(),
        (
            any::<bool>(),
            [-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0],
            -4.0f64..0.5,
        ),
    );
    runner()
        .run(
            &world,
            |(
                [mut l1, l2, mut l3, mut l4, mut l5, mut l6],
                [beta, mut gx, mut gy],
                [mut g3, mut g4, mut g5, mut g6],
                theta2,
                omega,
                alpha,
                damped,
                (built, [cx, cy, fx, fy], noise),
            )| {
                if built && [l1, l2, beta, theta2].iter().all(|x| x.is_finite()) {
                    // Both loops closed around a pose: C and F anywhere,
                    // the ground pivot G from F by the angle of (fy, fx).
                    let unit = l1.abs().max(l2.abs()).max(1e-3);
                    let b = Vector2::new(l2 * theta2.cos(), l2 * theta2.sin());
                    let c = Vector2::new(cx, cy) * unit;
                    l1 = l1.abs();
                    let d = Vector2::new(l1, 0.0);
                    l3 = (c - b).norm();
                    l4 = (d - c).norm();
                    let t3 = (c - b).y.atan2((c - b).x);
                    let t4 = (d - c).y.atan2((d - c).x);
                    let e = 0.8 * l3;
                    let e_point = b + Vector2::new((t3 + beta).cos(), (t3 + beta).sin()) * e;
                    let f = e_point + Vector2::new(fx, fy) * unit;
                    l5 = (f - e_point).norm();
                    let t5 = (f - e_point).y.atan2((f - e_point).x);
                    l6 = unit * (1.0 + fx.abs());
                    let t6 = fy;
                    let g = f - Vector2::new(t6.cos(), t6.sin()) * l6;
                    (gx, gy) = (g.x, g.y);
                    let off = 10f64.powf(noise);
                    (g3, g4, g5, g6) = (t3 + off, t4 - off, t5 + off, t6 - off);
                }
                let six = SixBar {
                    l1,
                    l2,
                    l3,
                    l4,
                    e: 0.8 * l3,
                    beta,
                    l5,
                    l6,
                    gx,
                    gy,
                };
                check(
                    &six,
                    vector![g3, g4, g5, g6],
                    theta2,
                    omega,
                    alpha,
                    damped,
                    Truth::Unknown,
                    false,
                    &tally,
                )
            },
        )
        .unwrap();
    let tally = tally.into_inner();
    report("six-bars", &tally, start.elapsed().as_secs_f64());
    assert!(tally.ok > 0);
}

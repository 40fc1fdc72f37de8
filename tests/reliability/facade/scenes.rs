//! Scenes of the four-bar with awkward settings, frames and cycles, rendered
//! and animated.

use super::harness::{
    Numbers, Tally, awkward, case, cases, clean_svg, count, four_bar, outcome, runner,
};
use crate::common::FourBar;
use linkage::draw::scene::{Frame, Scene};
use linkage::ground::Ground;
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

/// A frame of the four-bar at an awkward state, or with awkward positions
/// written in.
fn frame(bar: &FourBar, n: &[u64; 8]) -> Frame {
    let x = |k: usize| awkward(n[k]);
    let mut frame = Frame::at(
        bar,
        &vector![x(0), x(1)],
        &vector![x(2)],
        &vector![x(3), x(4)],
        &vector![x(5)],
        &vector![x(6), x(7)],
        &vector![0.0],
    );
    if n[0] % 2 == 0 {
        // An ordinary pose, one position perhaps spoilt.
        let pose = bar
            .analyze(
                &vector![0.4, -1.2],
                &vector![0.3],
                &vector![1.0],
                &vector![0.0],
                &Options::default(),
            )
            .map(|a| Frame::from_analysis(bar, &a));
        if let Ok(mut ordinary) = pose {
            if n[1] % 3 == 0 {
                ordinary.positions[(n[2] % 5) as usize].x = x(3);
            }
            frame = ordinary;
        }
    }
    frame
}

#[test]
fn scenes_never_hang_panic_or_lie() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    let world = (
        any::<[u64; 4]>(),
        any::<[u64; 8]>(),
        any::<[u64; 8]>(),
        any::<[u64; 8]>(),
    );
    runner(cases())
        .run(&world, |(model_bits, n, m, s)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let settings = Numbers { bits: s };
                let ordinary = s[0] % 3 != 2;
                let bar = four_bar(&model_bits, ordinary || model_bits[0] % 2 == 0);
                let x = |k: usize, usual: f64| settings.get(k, usual);
                let mut scene = Scene::new()
                    .with_ground(&Ground::new().point("A", [0.0, x(0, 0.0)]))
                    .ground("D", [80.0, 0.0])
                    .link(["A", "B"])
                    .link(["B", "C"])
                    .link(["C", "D"])
                    .plate(["B", "C", "G3"])
                    .slider("G4", x(1, 0.3))
                    .block("G2", x(2, -0.2))
                    .slider_on("G3", ["B", "C"])
                    .velocities(["G2", "G3", "C"])
                    .accelerations(["G3", "B"])
                    .trace(["G3"])
                    .labels(s[3] % 2 == 0)
                    .width(x(4, 640.0));
                if s[5] % 2 == 0 {
                    scene = scene
                        .velocity_scale(x(5, 0.02))
                        .acceleration_scale(x(6, 0.0005));
                }
                // The cycle's frames: ordinary poses over a turn, or, in an
                // awkward world, frames of awkward states.
                let frames = if ordinary {
                    2 + s[7] as usize % 40
                } else {
                    count(s[7]).min(50)
                };
                let cycle: Vec<Frame> = (0..frames)
                    .map(|k| {
                        if ordinary {
                            let theta2 = k as f64 * std::f64::consts::TAU / frames as f64;
                            ordinary_frame(&bar, theta2).unwrap_or_else(|| frame(&bar, &m))
                        } else {
                            let mut bits = m;
                            bits[0] = bits[0].rotate_left(k as u32);
                            frame(&bar, &bits)
                        }
                    })
                    .collect();
                let now = if ordinary {
                    ordinary_frame(&bar, 0.3).unwrap_or_else(|| frame(&bar, &n))
                } else {
                    frame(&bar, &n)
                };
                outcome(
                    scene.render(&now, &cycle),
                    |svg| clean_svg(svg),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    scene.animate(&cycle, x(7, 4.0)),
                    |svg| clean_svg(svg),
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("scenes", started);
}

/// The four-bar's frame at θ2 by a damped analysis, if it assembles there.
fn ordinary_frame(bar: &FourBar, theta2: f64) -> Option<Frame> {
    let options = Options::damped();
    let a = bar
        .analyze(
            &vector![0.4, -1.2],
            &vector![theta2],
            &vector![1.0],
            &vector![0.0],
            &options,
        )
        .ok()?;
    Some(Frame::from_analysis(bar, &a))
}

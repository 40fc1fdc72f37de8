//! Diagrams, charts and hodographs of awkward sweeps, curves and sizes.

use super::harness::{
    Numbers, Tally, awkward, case, cases, clean_svg, count, four_bar, outcome, runner,
};
use linkage::draw::diagrams::{Chart, Diagrams, Hodographs, Kind, Panel};
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

#[test]
fn diagrams_never_hang_panic_or_lie() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    let world = (any::<[u64; 4]>(), any::<[u64; 12]>(), any::<[u64; 6]>());
    runner(cases())
        .run(&world, |(model_bits, n, sizes)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let numbers = Numbers { bits: n };
                let ordinary = n[0] % 3 != 2;
                let bar = four_bar(&model_bits, ordinary || model_bits[0] % 2 == 0);
                let x = |k: usize, usual: f64| numbers.get(k, usual);
                // Sizes ordinary in ordinary worlds, else any.
                let size = |b: u64, usual: u32| {
                    if ordinary {
                        return usual;
                    }
                    match b % 4 {
                        0 => usual,
                        1 => u32::MAX,
                        2 => 0,
                        _ => (b >> 8) as u32,
                    }
                };
                let columns = |b: u64| {
                    if ordinary {
                        1 + b as usize % 3
                    } else {
                        count(b)
                    }
                };
                // A sweep of the four-bar, one of its numbers perhaps spoilt.
                let sweep = bar.sweep(
                    &vector![0.4, -1.2],
                    &Drive::Line {
                        from: vector![0.3],
                        to: vector![x(0, 6.0)],
                        steps: if ordinary {
                            2 + n[1] as usize % 400
                        } else {
                            count(n[1]).min(400)
                        },
                    },
                    &SweepOptions::default(),
                );
                if let Ok(mut sweep) = sweep {
                    if n[2] % 3 == 0 && !sweep.poses.is_empty() {
                        let k = (n[3] as usize) % sweep.poses.len();
                        sweep.poses[k].udot[0] = x(4, 1.0);
                    }
                    let diagrams = Diagrams::new()
                        .kind("theta3", Kind::Angle)
                        .kind(
                            "theta4",
                            if n[5] % 2 == 0 {
                                Kind::Angle
                            } else {
                                Kind::Length
                            },
                        )
                        .size(size(sizes[0], 900), size(sizes[1], 230));
                    outcome(
                        diagrams.render(&bar, &sweep),
                        |svg| clean_svg(svg),
                        &mut fine,
                        &mut outcomes,
                    );
                }
                // Curves: ordinary ones with one value perhaps awkward, or
                // all awkward; some constant, some of tiny or huge spread.
                let points = |k: usize| -> Vec<(f64, f64)> {
                    let length = if ordinary {
                        n[k] as usize % 300
                    } else {
                        count(n[k]).min(300)
                    };
                    let spread = x(k + 1, 1.0);
                    (0..length)
                        .map(|i| {
                            let t = i as f64;
                            match n[k + 1] % 4 {
                                0 => (t, t.sin() * spread),
                                1 => (t, spread),
                                2 => (1e290 + t * 1e275, spread * t),
                                _ => (awkward(n[k].rotate_left(i as u32)), x(k + 1, t)),
                            }
                        })
                        .collect()
                };
                let chart = Chart::new("a chart", "x")
                    .panel(
                        Panel::new("y")
                            .line("one", points(6))
                            .dashed("two", points(7))
                            .mark(x(8, 3.0), "mark"),
                    )
                    .panel(Panel::new("z").line("three", points(8)))
                    .columns(columns(sizes[2]))
                    .size(size(sizes[3], 900), size(sizes[4], 240));
                outcome(
                    chart.render(),
                    |svg| clean_svg(svg),
                    &mut fine,
                    &mut outcomes,
                );
                let hodographs = Hodographs::new("forces", "N")
                    .panel("F", points(9), Some((x(10, 1.0), x(11, -2.0), "now")))
                    .panel("G", points(6), None)
                    .layout(columns(sizes[5]), size(sizes[5] >> 3, 420));
                outcome(
                    hodographs.render(),
                    |svg| clean_svg(svg),
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("diagrams", started);
}

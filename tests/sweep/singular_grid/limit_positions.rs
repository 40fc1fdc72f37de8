//! Limit positions on the grid: a triple rocker rocked through its limit
//! positions and driven into one, and a slider-crank driven by its slider
//! through its dead centres.

use super::grids::{OFFSETS, line_grid, line_through, miss, off, rocking_through};
use super::harness::{Run, Tally, campaign, report, step_counts};
use crate::models::{SLIDER_DRIVEN, SliderDriven};
use linkage::closed_form::circle_intersection;
use linkage::mechanisms::BareFourBar;
use linkage::prelude::*;
use std::time::Instant;

/// The triple rocker l2 = 45 rocked through its limit positions ±θ*
/// (BD = l3 + l4), the grid on +θ* or −θ* first, and driven straight into
/// one (the sweep ends there).
#[test]
fn triple_rocker_limit_on_the_grid() {
    let began = Instant::now();
    let bar = BareFourBar {
        l1: 80.0,
        l2: 45.0,
        l3: 50.0,
        l4: 70.0,
    };
    let closed = bar.closed_form();
    let limit = closed.collinear_crank_angles()[0];
    let counts = step_counts();
    let mut tally = Tally::default();
    for sigma in [1.0, -1.0] {
        let truth = move |v: f64, passed: usize| {
            closed.position(v, if passed % 2 == 0 { sigma } else { -sigma })
        };
        let mut runs = Vec::new();
        for &k in &counts {
            let offset = OFFSETS[k % OFFSETS.len()];
            for direction in [1.0, -1.0] {
                // Rocking: k steps from about 0 to the first limit.
                let first = direction * limit;
                let step = first / k as f64;
                let from = rocking_through(off(first, offset), k, step);
                runs.push(Run {
                    label: format!("triple rocker rocking, branch {sigma}, k = {k}, direction {direction}, offset {offset}"),
                    start: SVector::from(closed.position(from, sigma).unwrap()),
                    drive: Drive::Rocking {
                        from: vector![from],
                        step: vector![step],
                        max_steps: 8 * k + 8,
                    },
                    expected: vec![
                        (EventKind::LimitPosition, first),
                        (EventKind::LimitPosition, -first),
                    ],
                    complete: true,
                    miss: Some(miss(from + step * k as f64, first)),
                });
                // A line from inside the range through the limit at k.
                let h = direction * limit / k as f64;
                let (from, to) = line_through(off(first, offset), k, k + k / 2, h);
                runs.push(Run {
                    label: format!("triple rocker driven into its limit, branch {sigma}, k = {k}, direction {direction}, offset {offset}"),
                    start: SVector::from(closed.position(from, sigma).unwrap()),
                    drive: Drive::Line {
                        from: vector![from],
                        to: vector![to],
                        steps: k + k / 2,
                    },
                    expected: vec![(EventKind::LimitPosition, first)],
                    complete: false,
                    miss: Some(miss(line_grid(from, to, k + k / 2, k), first)),
                });
            }
        }
        tally.add(&campaign(&bar, &runs, &truth, [true, true]));
    }
    report("triple rocker, limit positions ±θ*", &tally, began);
}

/// Driven by its slider, the slider-crank rocks between its dead centres
/// s = √((l ± r)² − e²), both on the grid.
#[test]
fn slider_driven_dead_centres_on_the_grid() {
    let began = Instant::now();
    let SliderDriven { r, l, e } = SLIDER_DRIVEN;
    let s_max = ((l + r).powi(2) - e * e).sqrt();
    let s_min = ((l - r).powi(2) - e * e).sqrt();
    let closed = move |s: f64, sigma: f64| -> Option<[f64; 2]> {
        let b = circle_intersection(
            nalgebra::Vector2::zeros(),
            r,
            nalgebra::Vector2::new(s, e),
            l,
            sigma,
        )?;
        let bp = nalgebra::Vector2::new(s, e) - b;
        Some([b.y.atan2(b.x), bp.y.atan2(bp.x)])
    };
    let counts = step_counts();
    let mut tally = Tally::default();
    for sigma in [1.0, -1.0] {
        let truth =
            move |s: f64, passed: usize| closed(s, if passed % 2 == 0 { sigma } else { -sigma });
        let mut runs = Vec::new();
        for &k in &counts {
            let offset = OFFSETS[k % OFFSETS.len()];
            for direction in [1.0, -1.0] {
                let (first, second) = if direction > 0.0 {
                    (s_max, s_min)
                } else {
                    (s_min, s_max)
                };
                let step = (first - second) / (2 * k) as f64;
                let from = rocking_through(off(first, offset), k, step);
                runs.push(Run {
                    label: format!("slider-driven, branch {sigma}, k = {k}, direction {direction}, offset {offset}"),
                    start: SVector::from(closed(from, sigma).unwrap()),
                    drive: Drive::Rocking {
                        from: vector![from],
                        step: vector![step],
                        max_steps: 8 * k + 8,
                    },
                    expected: vec![
                        (EventKind::LimitPosition, first),
                        (EventKind::LimitPosition, second),
                    ],
                    complete: true,
                    miss: Some(miss(from + step * k as f64, first)),
                });
            }
        }
        tally.add(&campaign(&SLIDER_DRIVEN, &runs, &truth, [true, true]));
    }
    report("slider-driven slider-crank, dead centres", &tally, began);
}

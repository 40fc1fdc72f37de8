//! Branch points beyond the four-bar: a centred slider-crank with r = l,
//! and a Watt six-bar whose second loop is a change-point four-bar.

use super::harness::{Tally, campaign, full_turns, report, step_counts};
use crate::common::FourBar;
use crate::models::{SliderCrank, WattSixBar};
use linkage::closed_form::{self, circle_intersection};
use linkage::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};
use std::time::Instant;

/// r = l: the ordinary branch (θ3 = −θ2, s = 2r cos θ2) and the folded one
/// (θ3 = π + θ2, s = 0) cross at θ2 = ±π/2; each continues smoothly as
/// itself.
#[test]
fn slider_crank_with_rod_equal_to_crank() {
    let began = Instant::now();
    let model = SliderCrank {
        r: 50.0,
        l: 50.0,
        e: 0.0,
    };
    let counts = step_counts();
    let mut tally = Tally::default();
    for folded in [false, true] {
        let exact = move |v: f64| {
            if folded {
                [PI + v, 0.0]
            } else {
                [-v, 2.0 * model.r * v.cos()]
            }
        };
        let truth = move |v: f64, _passed: usize| Some(exact(v));
        let start = move |v: f64| Some(exact(v));
        let label = format!("slider-crank r = l, folded: {folded}");
        let runs = full_turns(&[FRAC_PI_2, -FRAC_PI_2], &start, &counts, &label);
        tally.add(&campaign(&model, &runs, &truth, [true, false]));
    }
    report("slider-crank r = l (±π/2)", &tally, began);
}

/// The six-bar's exact pose: the four-bar on its branch, E, and the dyad on
/// the side `side` of E→G.
fn six_bar_pose(m: &WattSixBar, v: f64, side: f64) -> Option<[f64; 4]> {
    let four = closed_form::FourBar {
        l1: m.l1,
        l2: m.l2,
        l3: m.l3,
        l4: m.l4,
    };
    let [t3, t4] = four.position(v, 1.0)?;
    let e = nalgebra::Vector2::new(m.l1, 0.0)
        + nalgebra::Vector2::new((t4 + m.beta).cos(), (t4 + m.beta).sin()) * m.le;
    let g = nalgebra::Vector2::new(m.gx, m.gy);
    let f = circle_intersection(e, m.l5, g, m.l6, side)?;
    let (ef, fg) = (f - e, g - f);
    Some([t3, t4, ef.y.atan2(ef.x), fg.y.atan2(fg.x)])
}

/// The second loop D-E-F-G is a change-point four-bar (le + |DG| = l5 + l6)
/// whose joints line up, E beyond D from G, when the rocker passes the
/// angle it has at θ2 = 2: at θ2 = 2 and at the other crank angle with the
/// same rocker angle.
#[test]
fn six_bar_with_a_change_point_dyad() {
    let began = Instant::now();
    let (l1, l2, l3, l4) = (
        FourBar::WORKSHEET.l1,
        FourBar::WORKSHEET.l2,
        FourBar::WORKSHEET.l3,
        FourBar::WORKSHEET.l4,
    );
    let four = closed_form::FourBar { l1, l2, l3, l4 };
    let theta2 = 2.0;
    let [_, theta4] = four.position(theta2, 1.0).unwrap();
    let (le, beta, l5, l6, lg) = (30.0, 0.5, 50.0, 40.0, 60.0);
    // G on the line through D and E, beyond D from E.
    let towards_g = theta4 + beta + PI;
    let model = WattSixBar {
        l1,
        l2,
        l3,
        l4,
        le,
        beta,
        l5,
        l6,
        gx: l1 + lg * towards_g.cos(),
        gy: lg * towards_g.sin(),
    };
    // The other crank angle with the same rocker: B from C on the other side.
    let c =
        nalgebra::Vector2::new(l1, 0.0) - nalgebra::Vector2::new(theta4.cos(), theta4.sin()) * l4;
    let b_here = four.b(theta2);
    let side_here = {
        let (ab, ac) = (b_here, c);
        (ac.x * ab.y - ac.y * ab.x).signum()
    };
    let b_other = circle_intersection(nalgebra::Vector2::zeros(), l2, c, l3, -side_here).unwrap();
    let theta2_other = b_other.y.atan2(b_other.x);
    assert!(
        (theta2_other - theta2).abs() > 0.1,
        "two distinct crank angles"
    );
    let counts = step_counts();
    let mut tally = Tally::default();
    for sigma in [1.0, -1.0] {
        let truth = move |v: f64, passed: usize| {
            six_bar_pose(&model, v, if passed % 2 == 0 { sigma } else { -sigma })
        };
        let start = move |v: f64| six_bar_pose(&model, v, sigma);
        let label = format!("six-bar, dyad branch {sigma}");
        let runs = full_turns(&[theta2, theta2_other], &start, &counts, &label);
        tally.add(&campaign(&model, &runs, &truth, [true; 4]));
    }
    report("six-bar, change-point dyad (2 and its twin)", &tally, began);
}

//! The mechanisms the library `mechanisms/` adds — Jansen's leg, the
//! crank-and-slotted-lever quick return, the elliptic trammel — as their
//! compiled twins: each assembles over its whole drive range (a sweep from
//! the files' assembly that runs through without a singular pose), and
//! matches the independent closed forms of
//! `benches/reference/mechanism_files.py` (`tests/data/`).

use crate::common::rel;
use crate::models::{JANSEN_LEG, JansenLeg, QUICK_RETURN, TRAMMEL, Trammel};
use linkage::prelude::*;
use std::f64::consts::{PI, TAU};

/// The rows of a reference CSV: a line of `#`, a header, numbers.
fn rows(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// The difference of two angles, up to whole turns.
fn turn_apart(a: f64, b: f64) -> f64 {
    ((a - b + PI).rem_euclid(TAU) - PI).abs()
}

/// Sweeps `model` from `u0` over `from..to` in `steps`, asserting that it
/// runs through: every pose, no event (no dead centre, no limit, no branch
/// point).
fn whole_range<L: Linkage<M, 1>, const M: usize>(
    name: &str,
    model: &L,
    u0: SVector<f64, M>,
    from: f64,
    to: f64,
    steps: usize,
) -> Sweep<M, 1> {
    let drive = Drive::Line {
        from: vector![from],
        to: vector![to],
        steps,
    };
    let sweep = model
        .sweep(&u0, &drive, &SweepOptions::default())
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(
        sweep.complete,
        "{name}: stopped at {:?}",
        sweep.poses.last().map(|p| p.v)
    );
    assert_eq!(sweep.poses.len(), steps + 1, "{name}");
    assert!(sweep.events.is_empty(), "{name}: {:?}", sweep.events);
    sweep
}

/// Solves `model` at each reference row's driver (its first column) from
/// the sweep's nearest pose, and compares u (angles up to whole turns, to
/// 1e-12; lengths relative to 1e-12) and the `points` named (their x and y,
/// the row's last columns).
fn matches_reference<L: Linkage<M, 1>, const M: usize>(
    name: &str,
    model: &L,
    sweep: &Sweep<M, 1>,
    reference: &[Vec<f64>],
    points: &[&str],
) {
    let angles = model.trig_u();
    let angle = |k: usize| angles[k];
    for row in reference {
        let v = vector![row[0]];
        let nearest = sweep
            .poses
            .iter()
            .min_by(|a, b| (a.v[0] - v[0]).abs().total_cmp(&(b.v[0] - v[0]).abs()))
            .unwrap();
        let u = model
            .solve_position(&nearest.u, &v, &Options::default())
            .unwrap_or_else(|e| panic!("{name} at {v:?}: {e}"))
            .u;
        for k in 0..M {
            let off = if angle(k) {
                turn_apart(u[k], row[1 + k])
            } else {
                rel(u[k], row[1 + k], 1.0)
            };
            assert!(
                off < 1e-12,
                "{name} at {}: {} = {} vs {}",
                row[0],
                model.u_names()[k],
                u[k],
                row[1 + k]
            );
        }
        let positions = model.point_positions(&u, &v);
        let positions = positions.as_ref();
        for (n, point) in points.iter().enumerate() {
            let index = model.point_names().iter().position(|p| p == point).unwrap();
            let at = positions[index];
            let (x, y) = (row[1 + M + 2 * n], row[2 + M + 2 * n]);
            assert!(
                rel(at.x, x, 1.0) < 1e-12 && rel(at.y, y, 1.0) < 1e-12,
                "{name} at {}: {point} = {at:?} vs ({x}, {y})",
                row[0]
            );
        }
    }
}

/// A whole turn of Jansen's leg in 360 steps, from the assembly near the
/// file's sketch at θ = 0 (mechanisms/jansen_leg.toml).
fn jansens_turn() -> Sweep<6, 1> {
    let sketch = vector![141.3, 70.3, -132.7, -73.7, -66.7, 151.6].map(f64::to_radians);
    let start = JANSEN_LEG
        .solve_position(&sketch, &vector![0.0], &Options::default())
        .unwrap()
        .u;
    whole_range("Jansen's leg", &JANSEN_LEG, start, 0.0, TAU, 360)
}

/// Jansen's leg has Ψ_u in three blocks of 2×2, solved by its factors
/// with no inverse: at every pose of a turn the structure fits, the solves
/// are the whole inverse's to rounding, and the estimated conditioning is
/// the exact one (to rounding) at every pose.
#[test]
fn jansens_leg_is_solved_in_blocks_as_the_whole_inverse_solves() {
    let sweep = jansens_turn();
    let blocks = JANSEN_LEG.psi_u_blocks();
    assert_eq!(blocks.len(), 3);
    for pose in &sweep.poses {
        let psi_u = JANSEN_LEG.psi_u(&pose.u, &pose.v);
        assert!(blocks.fits(&psi_u));
        let (factors, whole) = (
            linkage::Factors::of(&psi_u, blocks),
            linkage::invert(&psi_u),
        );
        assert!(factors.in_blocks() && whole.rcond > 0.0);
        let b = JANSEN_LEG.psi_v(&pose.u, &pose.v).column(0).into_owned();
        let tolerance = 1e-14 * whole.inverse.amax() * b.amax() / whole.rcond;
        assert!((factors.solve(&b) - whole.inverse * b).amax() <= tolerance);
        assert!((factors.det() - whole.det).abs() <= 1e-13 * whole.det.abs() / whole.rcond);
        let ratio = factors.rcond() / whole.rcond;
        assert!((ratio - 1.0).abs() <= 1e-12, "rcond ratio {ratio}");
    }
}

/// A mechanism of more than four coordinates evaluates its fused kernel
/// with given sines and cosines over a result its caller keeps (what a
/// sweep does): at every pose of a turn, written over the result of the
/// pose before (and over a result of NaN), it is bit for bit the kernel
/// that computes its own sines and cosines (`kinematics`, a body of its
/// own) and the one returned by value.
#[test]
fn jansens_leg_fused_kernel_in_place_is_the_returned_one_to_the_bit() {
    use linkage::Kernels;
    let sweep = jansens_turn();
    assert!(JANSEN_LEG.evaluates_in_place());
    let (vdot, vddot) = (vector![1.0], vector![0.5]);
    let mut kept = JANSEN_LEG.kinematics(&sweep.poses[0].u, &sweep.poses[0].v, &vdot, &vddot);
    kept.psi_u.fill(f64::NAN);
    kept.udot.fill(f64::NAN);
    let mut over = linkage::Kinematics::blank();
    for pose in &sweep.poses {
        let trig_u: [(f64, f64); 6] = std::array::from_fn(|k| pose.u[k].sin_cos());
        let trig_v: [(f64, f64); 1] = [pose.v[0].sin_cos()];
        let returned =
            JANSEN_LEG.kinematics_with_trig(&pose.u, &pose.v, &trig_u, &trig_v, &vdot, &vddot);
        // Through the trait, as the sweep asks for it.
        Kernels::kinematics_with_trig_into(
            &JANSEN_LEG,
            &pose.u,
            &pose.v,
            &trig_u,
            &trig_v,
            &vdot,
            &vddot,
            &mut kept,
        );
        assert_eq!(kept, returned, "at {:?}", pose.v);
        assert_eq!(kept, JANSEN_LEG.kinematics(&pose.u, &pose.v, &vdot, &vddot));
        assert!(kept.factors.in_blocks());
        // Over a blank result, then over the pose before's, as the sweep
        // does: Ψ_u's zeros are not written again, and kept.
        Kernels::kinematics_with_trig_over(
            &JANSEN_LEG,
            &pose.u,
            &pose.v,
            &trig_u,
            &trig_v,
            &vdot,
            &vddot,
            &mut over,
        );
        assert_eq!(over, returned, "over, at {:?}", pose.v);
    }
}

#[test]
fn jansens_leg_walks_a_whole_turn_and_puts_its_foot_where_the_closed_form_does() {
    let reference = rows(include_str!("../data/jansen_leg.csv"));
    let sweep = jansens_turn();
    matches_reference("Jansen's leg", &JANSEN_LEG, &sweep, &reference, &["Foot"]);
    // Its foot's lowest stretch is nearly flat, the linkage's feature: over
    // the third of the turn centred on its lowest point the foot's height
    // varies by about a tenth of its lift (2.3 of 22.5, by the script).
    let foot = JansenLeg::POINT_NAMES
        .iter()
        .position(|p| *p == "Foot")
        .unwrap();
    let heights: Vec<f64> = sweep.poses[..360]
        .iter()
        .map(|p| JANSEN_LEG.point_positions(&p.u, &p.v).as_ref()[foot].y)
        .collect();
    let lowest = (0..360)
        .min_by(|&a, &b| heights[a].total_cmp(&heights[b]))
        .unwrap();
    let highest = heights.iter().copied().fold(f64::MIN, f64::max);
    let lift = highest - heights[lowest];
    let stretch = (0..120).map(|k| heights[(lowest + 300 + k) % 360]);
    let spread = stretch.fold(f64::MIN, f64::max) - heights[lowest];
    assert!((lift - 22.457).abs() < 1e-3, "the foot's lift {lift}");
    assert!(
        spread < 0.11 * lift,
        "the foot's lowest third spreads {spread}"
    );
}

#[test]
fn the_quick_return_turns_a_whole_turn_and_returns_quicker() {
    let reference = rows(include_str!("../data/quick_return.csv"));
    let sketch = vector![63.4f64.to_radians(), 268.0, 7.5f64.to_radians(), 335.0];
    let start = QUICK_RETURN
        .solve_position(&sketch, &vector![0.0], &Options::default())
        .unwrap()
        .u;
    let sweep = whole_range("quick return", &QUICK_RETURN, start, 0.0, TAU, 360);
    matches_reference("quick return", &QUICK_RETURN, &sweep, &reference, &[]);
    // The ram's extremes: the crank turns 240° one way between them and
    // 120° the other (a time ratio of 2, 2·acos(r/d) = 120°).
    let x: Vec<f64> = sweep.poses.iter().map(|p| p.u[3]).collect();
    let right = (0..x.len()).max_by(|&a, &b| x[a].total_cmp(&x[b])).unwrap();
    let left = (0..x.len()).min_by(|&a, &b| x[a].total_cmp(&x[b])).unwrap();
    let apart = (left as i64 - right as i64).rem_euclid(360);
    assert!(
        apart.min(360 - apart) == 120,
        "the extremes {right}° and {left}°"
    );
}

#[test]
fn the_trammel_slides_its_range_and_traces_its_ellipse() {
    let reference = rows(include_str!("../data/trammel.csv"));
    let start = TRAMMEL
        .solve_position(&vector![0.6, 0.15], &vector![-0.2], &Options::default())
        .unwrap()
        .u;
    let sweep = whole_range("trammel", &TRAMMEL, start, -0.2, 0.2, 400);
    matches_reference("trammel", &TRAMMEL, &sweep, &reference, &["P"]);
    let p = Trammel::POINT_NAMES.iter().position(|n| *n == "P").unwrap();
    let (a, b) = (TRAMMEL.l - TRAMMEL.p, TRAMMEL.p);
    for pose in &sweep.poses {
        let at = TRAMMEL.point_positions(&pose.u, &pose.v).as_ref()[p];
        let ellipse = (at.x / a).powi(2) + (at.y / b).powi(2);
        assert!((ellipse - 1.0).abs() < 1e-14, "{at:?}: {ellipse}");
    }
}

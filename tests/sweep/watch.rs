//! Zeros and extrema along a sweep (`linkage::watch`), located in the
//! driver: against closed forms (the offset slider-crank's dead centres,
//! the four-bar's extreme transmission angles) and against the 50-digit
//! extrema of the Maple worksheet's four-bar over a revolution
//! (`tests/data/fourbar_extrema.csv`).

use crate::common::{FourBar, OMEGA2, rel};
use crate::models::{FIVE_BAR, SLIDER_CRANK};
use linkage::prelude::*;
use linkage::watch::{Axis, Found, FoundKind, Of, Watch, WatchError, locate};
use std::f64::consts::{PI, TAU};

fn sweep_of<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    u0: SVector<f64, M>,
    from: f64,
    to: f64,
    steps: usize,
    speed: f64,
) -> Sweep<M, 1> {
    let drive = Drive::Line {
        from: vector![from],
        to: vector![to],
        steps,
    };
    let options = SweepOptions {
        speed,
        ..SweepOptions::default()
    };
    model.sweep(&u0, &drive, &options).expect("the sweep")
}

/// The offset slider-crank's dead centres: the slider is farthest out at
/// s = √((l+r)² − e²) with the crank along the rod, θ2 = atan2(e, s), and
/// nearest in at s = √((l−r)² − e²) with the crank folded back on it,
/// θ2 = atan2(e, s) + π. Found three ways, as zeros of ṡ, as extrema of s
/// and as extrema of the point P's x, on a coarse grid of 36 steps.
#[test]
fn the_slider_cranks_dead_centres_are_located_at_their_closed_forms() {
    let c = SLIDER_CRANK;
    let outer = ((c.l + c.r).powi(2) - c.e * c.e).sqrt();
    let inner = ((c.l - c.r).powi(2) - c.e * c.e).sqrt();
    let expected = [
        (c.e.atan2(outer), outer, FoundKind::Maximum),
        (c.e.atan2(inner) + PI, inner, FoundKind::Minimum),
    ];
    let sweep = sweep_of(&c, vector![-0.05, 0.25], 0.0, TAU, 36, OMEGA2);
    let watches = [
        Watch::coordinate("s", Of::Velocity).zeros(),
        Watch::coordinate("s", Of::Position).extrema(),
        Watch::point("P", Axis::X, Of::Position).extrema(),
    ];
    let found = locate(&c, &sweep, &watches, &Options::default()).unwrap();
    assert_eq!(found.len(), 6, "{found:#?}");
    for (w, watch) in watches.iter().enumerate() {
        let of: Vec<&Found<2, 1>> = found.iter().filter(|f| f.watch == w).collect();
        assert_eq!(of.len(), 2, "{}", watch.name());
        for (f, (theta2, s, kind)) in of.iter().zip(expected) {
            let where_ = rel(f.v[0], theta2, 1.0);
            let value = rel(f.u[1], s, 1.0);
            assert!(
                where_ <= 1e-14 && value <= 1e-15,
                "{}: {where_:e} {value:e}",
                watch.name()
            );
            assert!(f.udot[1].abs() <= 1e-15 * OMEGA2 * c.r, "ṡ = {}", f.udot[1]);
            if w == 0 {
                let rising = kind == FoundKind::Minimum;
                assert_eq!(f.kind, FoundKind::Zero { rising });
            } else {
                assert_eq!(f.kind, kind);
            }
        }
    }
}

/// Driven backwards (a negative rate: time runs from the sweep's end to
/// its start), the same dead centres are found, of the same kinds: ṡ
/// changes sign with the rate, and time runs the other way along the
/// drive, so a zero of ṡ that rises forwards rises backwards too.
#[test]
fn a_sweep_driven_backwards_finds_the_same_extremes() {
    let c = SLIDER_CRANK;
    let forwards = sweep_of(&c, vector![-0.05, 0.25], 0.0, TAU, 36, OMEGA2);
    let backwards = sweep_of(&c, vector![-0.05, 0.25], 0.0, TAU, 36, -OMEGA2);
    let watches = [
        Watch::coordinate("s", Of::Position).extrema(),
        Watch::coordinate("s", Of::Velocity).zeros(),
    ];
    let ahead = locate(&c, &forwards, &watches, &Options::default()).unwrap();
    let back = locate(&c, &backwards, &watches, &Options::default()).unwrap();
    assert_eq!(ahead.len(), 4, "{ahead:#?}");
    assert_eq!(back.len(), 4, "{back:#?}");
    for (a, b) in ahead.iter().zip(&back) {
        assert_eq!(a.watch, b.watch);
        assert!(rel(a.v[0], b.v[0], 1.0) <= 1e-14, "{} {}", a.v[0], b.v[0]);
        assert!(rel(a.value.abs(), b.value.abs(), 1.0) <= 1e-12);
        assert_eq!(a.kind, b.kind);
    }
}

/// The four-bar's transmission angle γ (between coupler and rocker, cos γ
/// = −cos(θ4 − θ3)) is extreme where the crank lies along the frame,
/// θ2 = 0 and π, with cos γ = (l3² + l4² − (l1 ∓ l2)²)/(2 l3 l4).
#[test]
fn the_four_bars_extreme_transmission_angles_sit_where_the_crank_lies_along_the_frame() {
    let bar = FourBar::WORKSHEET;
    let (l1, l2, l3, l4) = (bar.l1, bar.l2, bar.l3, bar.l4);
    let start = bar
        .solve_position(
            &vector![80f64.to_radians(), -45f64.to_radians()],
            &vector![-0.5],
            &Options::default(),
        )
        .unwrap();
    let sweep = sweep_of(&bar, start.u, -0.5, TAU - 0.5, 72, 1.0);
    let watch = Watch::function("θ4 − θ3", |p| p.u[1] - p.u[0]).extrema();
    let found = locate(&bar, &sweep, &[watch], &Options::default()).unwrap();
    assert_eq!(found.len(), 2, "{found:#?}");
    let cos_gamma = |bd: f64| (l3 * l3 + l4 * l4 - bd * bd) / (2.0 * l3 * l4);
    for (f, (theta2, bd)) in found.iter().zip([(0.0, l1 - l2), (PI, l1 + l2)]) {
        assert!(
            (f.v[0] - theta2).abs() <= 1e-14,
            "{} against {theta2}",
            f.v[0]
        );
        assert!(rel(-f.value.cos(), cos_gamma(bd), 1.0) <= 1e-15);
        assert!(f.rate.abs() <= 1e-15, "rate {}", f.rate);
    }
    // θ4 − θ3 = −(180° − γ): least at θ2 = 0 (γ = 57.12°, the smallest),
    // greatest at π (γ = 111.80°).
    assert_eq!(found[0].kind, FoundKind::Minimum);
    assert_eq!(found[1].kind, FoundKind::Maximum);
}

/// The twelve extrema of θ3, θ4, ω3, ω4, α3, α4 over the worksheet's
/// revolution (ω2 = 400 rpm, 1° grid) against the 50-digit references:
/// where (θ2) and how much, to ≤ 1e-12 relative. Those of α need u‴, the
/// third derivative along the drive.
#[test]
fn the_worksheets_extrema_over_a_revolution_match_the_50_digit_references() {
    let bar = FourBar::WORKSHEET;
    let u0 = vector![
        78.463_040_967_f64.to_radians(),
        -44.415_308_597_f64.to_radians()
    ];
    let sweep = sweep_of(&bar, u0, 0.0, TAU, 360, OMEGA2);
    let mut checked = 0;
    for line in include_str!("../data/fourbar_extrema.csv").lines().skip(3) {
        let cells: Vec<&str> = line.split(',').collect();
        let (quantity, extremum) = (cells[0], cells[1]);
        let at: f64 = cells[2].parse().unwrap();
        let value: f64 = cells[3].parse().unwrap();
        let (name, of, degrees) = match quantity {
            "theta3_deg" => ("theta3", Of::Position, true),
            "theta4_deg" => ("theta4", Of::Position, true),
            "omega3" => ("theta3", Of::Velocity, false),
            "omega4" => ("theta4", Of::Velocity, false),
            "alpha3" => ("theta3", Of::Acceleration, false),
            "alpha4" => ("theta4", Of::Acceleration, false),
            other => panic!("unknown quantity {other}"),
        };
        let kind = if extremum == "min" {
            FoundKind::Minimum
        } else {
            FoundKind::Maximum
        };
        let watch = Watch::coordinate(name, of).extrema();
        let found = locate(&bar, &sweep, &[watch], &Options::default()).unwrap();
        // The reference is the extremum over the revolution: the least of
        // the minima, the greatest of the maxima.
        let sign = if kind == FoundKind::Minimum {
            1.0
        } else {
            -1.0
        };
        let f = found
            .iter()
            .filter(|f| f.kind == kind)
            .min_by(|a, b| (sign * a.value).total_cmp(&(sign * b.value)))
            .unwrap_or_else(|| panic!("no {extremum} of {quantity}: {found:?}"));
        let ours = if degrees {
            f.value.to_degrees()
        } else {
            f.value
        };
        let where_ = rel(f.v[0].to_degrees(), at, 1.0);
        let how_much = rel(ours, value, 1.0);
        assert!(
            where_ <= 1e-12 && how_much <= 1e-12,
            "{extremum} of {quantity}: at {} (ref {at}, {where_:e}), {ours} (ref {value}, {how_much:e})",
            f.v[0].to_degrees()
        );
        checked += 1;
    }
    assert_eq!(checked, 12);
}

/// Swept backwards, the same extrema are found at the same crank angles
/// (a maximum stays a maximum), and a zero's direction is along the drive.
#[test]
fn a_sweep_run_backwards_finds_the_same_extrema() {
    let c = SLIDER_CRANK;
    let u0 = c
        .solve_position(&vector![-0.05, 0.25], &vector![TAU], &Options::default())
        .unwrap()
        .u;
    let forwards = sweep_of(&c, vector![-0.05, 0.25], 0.0, TAU, 40, 1.0);
    let backwards = sweep_of(&c, u0, TAU, 0.0, 40, 1.0);
    let watch = || Watch::coordinate("s", Of::Position).extrema();
    let options = Options::default();
    let by_angle = |sweep: &Sweep<2, 1>| {
        let mut found = locate(&c, sweep, &[watch()], &options).unwrap();
        found.sort_by(|x, y| x.v[0].total_cmp(&y.v[0]));
        found
    };
    let (f, b) = (by_angle(&forwards), by_angle(&backwards));
    assert_eq!(f.len(), 2);
    assert_eq!(b.len(), 2);
    for (x, y) in f.iter().zip(&b) {
        assert_eq!(x.kind, y.kind);
        assert!((x.v[0] - y.v[0]).abs() <= 1e-14, "{} {}", x.v[0], y.v[0]);
    }
}

/// Along a straight line of a two-driver mechanism (the five-bar), an
/// extremum of θ3: its rate there is zero to rounding, and θ3 a little
/// before and after (solved independently) is on the same side of it.
#[test]
fn extrema_along_a_line_of_two_drivers_are_extrema() {
    let bar = FIVE_BAR;
    let (from, to) = (vector![0.3, 2.0], vector![0.3 + TAU, 2.0 + 1.0]);
    let u0 = bar
        .solve_position(&vector![1.2, 1.9], &from, &Options::default())
        .unwrap()
        .u;
    let drive = Drive::Line {
        from,
        to,
        steps: 120,
    };
    let sweep = bar.sweep(&u0, &drive, &SweepOptions::default()).unwrap();
    assert!(sweep.complete);
    let watch = Watch::coordinate("theta3", Of::Position).extrema();
    let found = locate(&bar, &sweep, &[watch], &Options::default()).unwrap();
    assert!(!found.is_empty());
    let direction = (to - from).normalize();
    for f in &found {
        assert!(f.rate.abs() <= 1e-13, "rate {}", f.rate);
        let side = |delta: f64| {
            let v = f.v + direction * delta;
            let u = bar.solve_position(&f.u, &v, &Options::default()).unwrap().u;
            u[0] - f.u[0]
        };
        let (before, after) = (side(-1e-4), side(1e-4));
        let expected = if f.kind == FoundKind::Maximum {
            -1.0
        } else {
            1.0
        };
        assert!(
            before * expected > 0.0 && after * expected > 0.0,
            "{f:?}: {before} {after}"
        );
    }
}

#[test]
fn an_unknown_name_is_an_error_that_lists_the_known_ones() {
    let c = SLIDER_CRANK;
    let sweep = sweep_of(&c, vector![-0.05, 0.25], 0.0, 1.0, 4, 1.0);
    let options = Options::default();
    for watch in [
        Watch::coordinate("x", Of::Position),
        Watch::point("Q", Axis::X, Of::Velocity),
    ] {
        let error = locate(&c, &sweep, &[watch], &options).unwrap_err();
        assert!(matches!(error, WatchError::UnknownName(_)), "{error:?}");
        let text = error.to_string();
        assert!(
            text.contains("theta3, s, theta2") || text.contains("B, P, G3"),
            "{text}"
        );
    }
}

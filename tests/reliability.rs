//! Reliability: random worlds and garbage, and the library never lies.
//!
//! Random four-bars, slider-cranks and six-bars — link lengths over six
//! orders of magnitude, zero-length links, coincident pivots, equal
//! lengths, negative and non-finite ones — at random driver values,
//! velocities and accelerations (NaN, ±∞, huge and subnormal included),
//! from random initial guesses, through every entry point of the runtime.
//! The properties:
//!
//! - nothing panics;
//! - no NaN or ∞ inside an `Ok`;
//! - an `Ok` is right: ‖Ψ‖∞ meets the tolerance, Ψ_u u̇ + Ψ_v v̇ = 0 and
//!   method A = method B to the accuracy promised, and a four-bar or
//!   slider-crank the law of cosines says cannot be assembled is never
//!   `Ok`;
//! - an `Err` is of the right kind: `NonFiniteInput` exactly when an input
//!   is not finite, `CannotAssemble` never where the closed form says the
//!   mechanism assembles.
//!
//! The number of cases per mechanism is `LINKAGE_CASES` (default 2000, what
//! CI runs); the long run, 10⁶ per mechanism:
//!
//!     LINKAGE_CASES=1000000 cargo test --release --test reliability -- --nocapture
//!
//! A failure is shrunk by proptest to the smallest world that shows it.

mod common;

use common::{FourBar, SEED, SixBar, SliderCrank};
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

fn cases() -> u32 {
    std::env::var("LINKAGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000)
}

fn runner() -> TestRunner {
    let mut config = Config::with_cases(cases());
    config.failure_persistence = None;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x7265_6c69_6162_6c65);
    }
    TestRunner::new(config)
}

/// Awkward numbers: NaN, ±∞, the extremes, subnormals, negative, and
/// arbitrary bit patterns.
fn special() -> BoxedStrategy<f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(f64::MAX),
        Just(-f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        Just(1e300),
        Just(-1e-300),
        Just(0.0),
        Just(-0.0),
        any::<u64>().prop_map(f64::from_bits),
    ]
    .boxed()
}

/// A link length: mostly 1e-3 … 1e3, sometimes zero, one, negative or
/// special.
fn length() -> BoxedStrategy<f64> {
    prop_oneof![
        12 => (-3.0f64..3.0).prop_map(|e| 10f64.powf(e)),
        1 => Just(0.0),
        1 => Just(1.0),
        1 => (-3.0f64..3.0).prop_map(|e| -(10f64.powf(e))),
        1 => special(),
    ]
    .boxed()
}

/// A driver value, velocity or acceleration: mostly moderate, sometimes
/// huge or special.
fn number(range: f64) -> BoxedStrategy<f64> {
    prop_oneof![
        14 => -range..range,
        1 => -1e12f64..1e12,
        1 => special(),
    ]
    .boxed()
}

/// What happened, by kind.
#[derive(Default, Debug)]
struct Tally {
    cases: usize,
    ok: usize,
    errors: BTreeMap<&'static str, usize>,
    checked_closed_form: usize,
    /// Cases where the closed form and a near guess demand an `Ok`.
    expected_ok: usize,
}

impl Tally {
    fn error(&mut self, e: &Error) {
        let kind = match e {
            Error::NonFiniteInput { .. } => "NonFiniteInput",
            Error::NotConverged { .. } => "NotConverged",
            Error::Singular { .. } => "Singular",
            Error::CannotAssemble { .. } => "CannotAssemble",
            Error::NonFiniteValue { .. } => "NonFiniteValue",
            Error::Underflow { .. } => "Underflow",
            Error::InvalidInput { .. } => "InvalidInput",
            Error::SubstepLimit { .. } => "SubstepLimit",
            _ => "other",
        };
        *self.errors.entry(kind).or_default() += 1;
    }
}

/// What the closed form says of an assembly: the distance to close, and the
/// interval it must fall in.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Truth {
    /// `clear`: at least 10⁻³ of the mechanism's size from either edge of
    /// the interval, so far from any singular pose (det Ψ_u ∝ sin of the
    /// angle between the links, or cos θ₃ for the slider-crank).
    Assembles {
        clear: bool,
    },
    Cannot,
    /// Too close to the edge (or not finite) to say.
    Unknown,
}

fn four_bar_truth(l: [f64; 4], theta2: f64) -> Truth {
    if !l.iter().all(|x| x.is_finite()) || !theta2.is_finite() || theta2.abs() > 1e6 {
        return Truth::Unknown;
    }
    let b = Vector2::new(l[1] * theta2.cos(), l[1] * theta2.sin());
    // hypot: no overflow for lengths near f64::MAX.
    let bd = (l[0] - b.x).hypot(b.y);
    let (l3, l4) = (l[2].abs(), l[3].abs());
    let scale = l.iter().map(|x| x.abs()).sum::<f64>();
    // Residual tolerance 1e-9 absolute: a gap below that is "assembled".
    let margin = (1e-6 * scale).max(1e-7);
    if bd > (l3 - l4).abs() + margin && bd < l3 + l4 - margin {
        let clearance = 1e-3 * scale;
        Truth::Assembles {
            clear: bd > (l3 - l4).abs() + clearance && bd < l3 + l4 - clearance,
        }
    } else if bd > l3 + l4 + margin || bd < (l3 - l4).abs() - margin {
        Truth::Cannot
    } else {
        Truth::Unknown
    }
}

fn slider_truth(r: f64, l: f64, e: f64, theta2: f64) -> Truth {
    if ![r, l, e, theta2].iter().all(|x| x.is_finite()) || theta2.abs() > 1e6 {
        return Truth::Unknown;
    }
    let gap = (r * theta2.sin() - e).abs();
    let margin = (1e-6 * (r.abs() + l.abs() + e.abs())).max(1e-7);
    if gap < l.abs() - margin {
        Truth::Assembles {
            clear: gap < l.abs() - 1e-3 * (r.abs() + l.abs() + e.abs()),
        }
    } else if gap > l.abs() + margin {
        Truth::Cannot
    } else {
        Truth::Unknown
    }
}

/// Zero, or a magnitude from 1e-6 to 1e6: numbers with which damped Newton
/// from a near guess must succeed.
fn moderate(x: f64) -> bool {
    x == 0.0 || (1e-6..=1e6).contains(&x.abs())
}

fn all_finite(xs: impl IntoIterator<Item = f64>) -> bool {
    xs.into_iter().all(f64::is_finite)
}

/// The properties of one analysis of one world.
#[allow(clippy::too_many_arguments)]
fn check<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    guess: SVector<f64, M>,
    v: f64,
    vdot: f64,
    vddot: f64,
    damped: bool,
    truth: Truth,
    expect_ok: bool,
    tally: &RefCell<Tally>,
) -> Result<(), TestCaseError> {
    let options = Options {
        damped,
        ..Options::default()
    };
    let (v, vdot, vddot) = (vector![v], vector![vdot], vector![vddot]);
    let inputs_finite = all_finite(guess.iter().chain(&v).chain(&vdot).chain(&vddot).copied());
    let result = catch_unwind(AssertUnwindSafe(|| {
        model.analyze(&guess, &v, &vdot, &vddot, &options)
    }))
    .map_err(|_| TestCaseError::fail("analyze panicked"))?;
    let mut t = tally.borrow_mut();
    t.cases += 1;
    if truth != Truth::Unknown {
        t.checked_closed_form += 1;
    }
    t.expected_ok += usize::from(expect_ok);
    match result {
        Ok(a) => {
            t.ok += 1;
            drop(t);
            prop_assert!(inputs_finite, "Ok from non-finite input");
            prop_assert!(
                truth != Truth::Cannot,
                "Ok where the mechanism cannot be assembled: {a:?}"
            );
            let values =
                a.u.iter()
                    .chain(&a.udot)
                    .chain(&a.uddot)
                    .chain(a.ratios.iter())
                    .copied()
                    .chain(
                        a.points
                            .as_ref()
                            .iter()
                            .chain(a.point_velocities.as_ref())
                            .chain(a.point_accelerations.as_ref())
                            .flat_map(|p| [p.x, p.y]),
                    )
                    .chain([a.residual, a.rcond]);
            prop_assert!(all_finite(values), "NaN or ∞ inside Ok: {a:?}");
            // The pose closes.
            let psi = catch_unwind(AssertUnwindSafe(|| model.psi(&a.u, &v)))
                .map_err(|_| TestCaseError::fail("psi panicked"))?;
            prop_assert!(
                psi.amax() <= options.residual_tol,
                "‖Ψ‖∞ = {} above the tolerance",
                psi.amax()
            );
            // The velocities solve their equation.
            let (psi_u, psi_v) = (model.psi_u(&a.u, &v), model.psi_v(&a.u, &v));
            let residual = (psi_u * a.udot + psi_v * vdot).amax();
            let scale = psi_u.amax() * a.udot.amax() + psi_v.amax() * vdot.amax();
            prop_assert!(
                residual <= options.accuracy * scale + 1e-300,
                "Ψ_u u̇ + Ψ_v v̇ = {residual} against {scale}"
            );
            // Method A = method B (and the fused γ).
            let with = |method| Options { method, ..options };
            let a_acc = model.acceleration(
                &a.u,
                &v,
                &a.udot,
                &vdot,
                &vddot,
                &with(AccelerationMethod::A),
            );
            let b_acc = model.acceleration(
                &a.u,
                &v,
                &a.udot,
                &vdot,
                &vddot,
                &with(AccelerationMethod::B),
            );
            // The size of the terms ü is made of, Ψ_u⁻¹(Ψ_v v̈ + γ), before
            // they cancel: γ's terms are method B's blocks times the
            // velocities (l·cos θ·θ̇² and the like), which may cancel to
            // much less than each.
            let (ud, vd) = (a.udot.amax(), vdot.amax());
            let gamma_terms = model.psi_u_udot_u(&a.u, &v, &a.udot).amax() * ud
                + model.psi_u_udot_v(&a.u, &v, &a.udot).amax() * vd
                + model.psi_v_vdot_u(&a.u, &v, &vdot).amax() * ud
                + model.psi_v_vdot_v(&a.u, &v, &vdot).amax() * vd;
            let inverse = linkage::invert(&psi_u).inverse;
            let terms = (M as f64) * inverse.amax() * ((psi_v * vddot).amax() + gamma_terms);
            match (a_acc, b_acc) {
                (Ok(x), Ok(y)) => {
                    let size = x.amax().max(y.amax()).max(a.uddot.amax()).max(terms);
                    prop_assert!(
                        (x - y).amax() <= options.accuracy * size + 1e-300,
                        "method A {x:?} ≠ method B {y:?}"
                    );
                    prop_assert!((x - a.uddot).amax() <= options.accuracy * size + 1e-300);
                }
                (x, y) => prop_assert!(false, "the methods disagree on success: {x:?} vs {y:?}"),
            }
        }
        Err(e) => {
            t.error(&e);
            drop(t);
            prop_assert!(
                !expect_ok,
                "Err for a pose clear of every singular one, guessed within 0.01 rad: {e}"
            );
            match &e {
                Error::NonFiniteInput { .. } => {
                    prop_assert!(!inputs_finite, "NonFiniteInput for finite input: {e}")
                }
                _ => prop_assert!(inputs_finite, "non-finite input reported as {e}"),
            }
            // Once the pose is found, a singular velocity or acceleration
            // solve means a pose near a singular one.
            if let Error::Singular { stage, .. } = &e {
                prop_assert!(
                    *stage == Stage::Position || !matches!(truth, Truth::Assembles { clear: true }),
                    "Singular far from any singular pose: {e}"
                );
            }
            if let Error::CannotAssemble { residual, .. } = &e {
                prop_assert!(
                    !matches!(truth, Truth::Assembles { .. }),
                    "CannotAssemble where the mechanism assembles: {e}"
                );
                prop_assert!(residual.is_finite() && *residual > 0.0);
            }
        }
    }
    // Every other entry point on the same world: no panic, no NaN in Ok.
    let u = guess;
    let entry = catch_unwind(AssertUnwindSafe(|| {
        let mut fine = true;
        if let Ok(p) = model.solve_position(&u, &v, &options) {
            fine &= all_finite(p.u.iter().copied()) && p.residual <= options.residual_tol;
        }
        if let Ok(vel) = model.velocity(&u, &v, &vdot, &options) {
            fine &= all_finite(vel.udot.iter().chain(vel.ratios.iter()).copied())
                && vel.rcond.is_finite();
        }
        let udot = SVector::<f64, M>::repeat(0.5);
        if let Ok(acc) = model.acceleration(&u, &v, &udot, &vdot, &vddot, &options) {
            fine &= all_finite(acc.iter().copied());
        }
        fine
    }))
    .map_err(|_| TestCaseError::fail("an entry point panicked"))?;
    prop_assert!(
        entry,
        "NaN or ∞ inside an Ok of solve_position, velocity or acceleration"
    );
    Ok(())
}

fn report(name: &str, tally: &Tally, seconds: f64) {
    eprintln!(
        "{name}: {} cases in {seconds:.1} s, {} Ok, errors {:?}, {} checked against the closed form, {} of them clear and guessed near so that only Ok will do; panics 0, NaN in Ok 0, wrong Ok 0, wrong Err 0",
        tally.cases, tally.ok, tally.errors, tally.checked_closed_form, tally.expected_ok
    );
}

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

/// What the four-bar sweeps found.
#[derive(Default)]
struct SweepTally {
    cases: usize,
    ok: usize,
    poses: usize,
    events: BTreeMap<&'static str, usize>,
    errors: BTreeMap<&'static str, usize>,
}

/// Four-bars of every Grashof class, the change points, parallelograms,
/// kites and deltoids among them, swept over random spans in random numbers
/// of steps from a random start on a random branch. Every pose is checked
/// against the closed form on the branch it must be on (the start's, flipped
/// at each branch point reported and at nothing else), every event against
/// the law of cosines (|BD| = l3 + l4 or |l3 − l4| there), every pair of
/// consecutive poses by the branch-continuity check, and a sweep that
/// reports the line complete must not have passed a driver value where the
/// mechanism cannot be assembled.
#[test]
fn four_bar_sweeps_never_lie() {
    let start = Instant::now();
    let tally = RefCell::new(SweepTally::default());
    let world = (
        0..6usize,
        [
            10.0f64..100.0,
            10.0f64..100.0,
            10.0f64..100.0,
            10.0f64..100.0,
        ],
        -3.0f64..3.0,
        any::<bool>(),
        -PI..PI,
        -4.0 * PI..4.0 * PI,
        1..1500usize,
    );
    runner()
        .run(
            &world,
            |(mode, [a, b, c, d], exponent, positive, from, span, steps)| {
                // Mode 0: any four lengths; 1, 2: change points (l1 + l2 =
                // l3 + l4, collinear at θ2 = π; l3 − l4 = l1 − l2, at 0);
                // 3: a parallelogram; 4: a kite (l1 = l2, l3 = l4); 5: a
                // deltoid (l2 = l3, l4 = l1).
                let scale = 10f64.powf(exponent);
                let (l1, l2, l3) = (a * scale, b * scale, c * scale);
                let l = match mode {
                    1 => {
                        let (l2, l1) = (l2.min(l1), l2.max(l1));
                        [l1, l2, (l1 + l2) * 0.4, (l1 + l2) * 0.6]
                    }
                    2 => [l1 + l2, l2, l3 + l1, l3],
                    3 => [l1, l2, l1, l2],
                    4 => [l1, l1, l3, l3],
                    5 => [l1, l2, l2, l1],
                    _ => [l1, l2, l3, d * scale],
                };
                let sigma = if positive { 1.0 } else { -1.0 };
                let closed = linkage::closed_form::FourBar {
                    l1: l[0],
                    l2: l[1],
                    l3: l[2],
                    l4: l[3],
                };
                // A start clear of every singular pose.
                if !matches!(four_bar_truth(l, from), Truth::Assembles { clear: true }) {
                    return Ok(());
                }
                let Some(u0) = closed.position(from, sigma) else {
                    return Ok(());
                };
                let bar = FourBar {
                    l1: l[0],
                    l2: l[1],
                    l3: l[2],
                    l4: l[3],
                };
                let to = from + span;
                let drive = Drive::Line {
                    from: vector![from],
                    to: vector![to],
                    steps,
                };
                let mut t = tally.borrow_mut();
                t.cases += 1;
                let sweep = match catch_unwind(AssertUnwindSafe(|| {
                    bar.sweep(&vector![u0[0], u0[1]], &drive, &SweepOptions::default())
                })) {
                    Err(_) => return Err(TestCaseError::fail("panicked")),
                    Ok(Err(e)) => {
                        let mut errors = Tally::default();
                        errors.error(&e);
                        for (kind, n) in errors.errors {
                            *t.errors.entry(kind).or_default() += n;
                        }
                        return Ok(());
                    }
                    Ok(Ok(sweep)) => sweep,
                };
                t.ok += 1;
                t.poses += sweep.poses.len();
                // Events where the law of cosines puts them.
                let bd = |theta2: f64| (l[0] - l[1] * theta2.cos()).hypot(l[1] * theta2.sin());
                for e in &sweep.events {
                    *t.events
                        .entry(match e.kind {
                            EventKind::BranchPoint => "branch points",
                            EventKind::LimitPosition => "limit positions",
                        })
                        .or_default() += 1;
                    let at = bd(e.v[0]);
                    let off = (at - (l[2] + l[3]))
                        .abs()
                        .min((at - (l[2] - l[3]).abs()).abs());
                    prop_assert!(
                        off <= 1e-9 * (l[2] + l[3]),
                        "{:?} at θ2 = {} where |BD| = {at}, l3 ± l4 = {}, {}",
                        e.kind,
                        e.v[0],
                        l[2] + l[3],
                        (l[2] - l[3]).abs()
                    );
                }
                // Every pose on its branch, continuous with the last.
                for (k, p) in sweep.poses.iter().enumerate() {
                    let flips = sweep
                        .events
                        .iter()
                        .filter(|e| e.after <= k && e.kind == EventKind::BranchPoint)
                        .count();
                    let side = if flips % 2 == 0 { sigma } else { -sigma };
                    let exact = closed.position(p.v[0], side);
                    let near_limit = sweep.events.iter().any(|e| {
                        e.kind == EventKind::LimitPosition && (e.v[0] - p.v[0]).abs() < 1e-6
                    });
                    let tolerance = if near_limit { 1e-7 } else { 1e-9 };
                    let error = exact.map_or(f64::INFINITY, |x| {
                        let wrap = |d: f64| {
                            let d = d.rem_euclid(2.0 * PI);
                            d.min(2.0 * PI - d)
                        };
                        wrap(p.u[0] - x[0]).max(wrap(p.u[1] - x[1]))
                    });
                    prop_assert!(
                        error <= tolerance,
                        "pose {k} at θ2 = {}: {:?}, closed form {exact:?} on branch {side}",
                        p.v[0],
                        p.u.as_slice()
                    );
                }
                for pair in sweep.poses.windows(2) {
                    let jump = common::branch_jump(&bar, &pair[0], &pair[1]);
                    prop_assert!(
                        jump.is_none(),
                        "velocity ratios jump: {jump:?} at θ2 = {}",
                        pair[1].v[0]
                    );
                }
                // A complete line passed no driver value where the
                // mechanism cannot be assembled.
                if sweep.complete {
                    let cannot = (0..=steps).any(|k| {
                        let theta2 = from + (to - from) / steps as f64 * k as f64;
                        four_bar_truth(l, theta2) == Truth::Cannot
                    });
                    prop_assert!(!cannot, "complete through a pose that cannot be assembled");
                }
                Ok(())
            },
        )
        .unwrap();
    let t = tally.into_inner();
    eprintln!(
        "four-bar sweeps: {} cases in {:.1} s, {} Ok ({} poses), events {:?}, errors {:?}; panics 0, wrong Ok 0, branch jumps 0",
        t.cases,
        start.elapsed().as_secs_f64(),
        t.ok,
        t.poses,
        t.events,
        t.errors
    );
    assert!(t.events.contains_key("branch points") && t.events.contains_key("limit positions"));
}

/// Fuzzing the runtime's public entry points with arbitrary f64 bit
/// patterns: every argument, every parameter, and sweeps over random
/// drives. No panic, and no NaN or ∞ in any `Ok`. (Their sweeps are not
/// held to the branch-continuity check: with an angle of 1e180 rad, whose
/// ulp is 1e164, velocity ratios are not resolved. The four-bar sweeps
/// above and `tests/singular_grid.rs` are.)
///
/// Every entry point of the runtime on one world of arbitrary numbers:
/// whether every `Ok` held only finite numbers (a panic propagates).
fn every_entry_point(
    [l1, l2, l3, l4]: [f64; 4],
    [g3, g4]: [f64; 2],
    [v, vdot, vddot, to]: [f64; 4],
    steps: usize,
) -> bool {
    let bar = FourBar { l1, l2, l3, l4 };
    let options = Options::default();
    let (u, v1, vd, vdd) = (vector![g3, g4], vector![v], vector![vdot], vector![vddot]);
    let mut fine = true;
    if let Ok(a) = bar.analyze(&u, &v1, &vd, &vdd, &options) {
        fine &= all_finite(a.u.iter().chain(&a.udot).chain(&a.uddot).copied());
    }
    if let Ok(p) = bar.solve_position(
        &u,
        &v1,
        &Options {
            damped: true,
            ..options
        },
    ) {
        fine &= all_finite(p.u.iter().copied());
    }
    if let Ok(vel) = bar.velocity(&u, &v1, &vd, &options) {
        fine &= all_finite(vel.udot.iter().chain(vel.ratios.iter()).copied());
    }
    for method in [AccelerationMethod::A, AccelerationMethod::B] {
        let with = Options { method, ..options };
        if let Ok(acc) = bar.acceleration(&u, &v1, &u, &vd, &vdd, &with) {
            fine &= all_finite(acc.iter().copied());
        }
    }
    let k = bar.kinematics(&u, &v1, &vd, &vdd);
    let _ = linkage::invert(&k.psi_u);
    let drive = Drive::Line {
        from: v1,
        to: vector![to],
        steps,
    };
    if let Ok(sweep) = bar.sweep(&u, &drive, &SweepOptions::default()) {
        for p in &sweep.poses {
            fine &= all_finite(p.u.iter().chain(&p.udot).chain(&p.uddot).copied());
        }
    }
    fine
}

#[test]
fn arbitrary_bit_patterns_never_panic() {
    let start = Instant::now();
    let bits = || any::<u64>().prop_map(f64::from_bits);
    let world = (
        [bits(), bits(), bits(), bits()],
        [bits(), bits()],
        [bits(), bits(), bits(), bits()],
        0..64usize,
    );
    let count = RefCell::new((0usize, 0usize));
    runner()
        .run(
            &world,
            |([l1, l2, l3, l4], [g3, g4], [v, vdot, vddot, to], steps)| {
                let fine = catch_unwind(AssertUnwindSafe(|| {
                    every_entry_point([l1, l2, l3, l4], [g3, g4], [v, vdot, vddot, to], steps)
                }))
                .map_err(|_| TestCaseError::fail("panicked"))?;
                let mut c = count.borrow_mut();
                c.0 += 1;
                c.1 += usize::from(fine);
                prop_assert!(fine, "NaN or ∞ inside an Ok");
                Ok(())
            },
        )
        .unwrap();
    let (cases, _) = count.into_inner();
    eprintln!(
        "bit patterns: {cases} cases in {:.1} s; panics 0, NaN in Ok 0",
        start.elapsed().as_secs_f64()
    );
}

/// A world of extreme numbers whose sweep reached nalgebra's SVD with
/// values it could not decompose; it panicked ("Singular value was NaN").
/// Decompositions are now scaled and checked.
#[test]
fn extreme_sweeps_do_not_reach_a_panicking_svd() {
    assert!(every_entry_point(
        [
            -0.0,
            -6.239251926006511e-124,
            1.5408458638653365e-308,
            1.0282578114192783e-217
        ],
        [0.0, -6.060628366580756e236],
        [0.0, 0.0, 0.0, -1.723164724210535e54],
        53,
    ));
}

/// Failures the long campaigns found, kept as fixed cases.
#[test]
fn regressions() {
    // All links 1, θ₂ = 187°: the pivots B and D are 1.9963 apart, just
    // inside the dyad's reach of 2. From θ₃ = θ₄ = 0 the iterates stay
    // symmetric and stall at the stretched dyad, a saddle of ½‖Ψ‖² with
    // ‖Ψ‖∞ = 3.7e-3; it was once reported as CannotAssemble.
    let bar = FourBar {
        l1: 1.0,
        l2: 1.0,
        l3: 1.0,
        l4: 1.0,
    };
    let options = Options {
        damped: true,
        ..Options::default()
    };
    let theta2 = -9.303165937741154;
    let pose = bar
        .solve_position(&vector![-1e-300, -1e-300], &vector![theta2], &options)
        .expect("the four-bar assembles");
    assert!(pose.residual <= options.residual_tol);
    assert!(matches!(
        four_bar_truth([1.0; 4], theta2),
        Truth::Assembles { .. }
    ));
}

/// A frame of 3e23 with a crank of 1.27 driven at θ̇₂ = −1e-300: the true
/// u̇ is about 1e-323, a subnormal number with no relative precision left.
/// It was once returned as `Ok` with u̇ = 0; now it is an `Underflow`.
/// A drive whose step is so long that its Euclidean norm overflowed in
/// the computing (|step|² > f64::MAX) made the sweep's rate 0: every pose
/// reported v̇ = 0 and u̇ = 0 for a moving driver. The step's length is now
/// taken at scale.
#[test]
fn huge_steps_keep_their_speed() {
    let from = 20f64.to_radians();
    let [t3, t4] = linkage::closed_form::FourBar {
        l1: SEED.l1,
        l2: SEED.l2,
        l3: SEED.l3,
        l4: SEED.l4,
    }
    .position(from, 1.0)
    .unwrap();
    for step in [1e160, -1e200] {
        // One pose only (the first step cannot be taken): the start, at the
        // sweep's speed.
        let summary = SEED.sweep_each(
            &vector![t3, t4],
            &Drive::Rocking {
                from: vector![from],
                step: vector![step],
                max_steps: 1,
            },
            &SweepOptions::default(),
            |pose| {
                assert_eq!(pose.vdot[0], step.signum(), "v̇ at speed 1");
                assert!(pose.udot.amax() > 0.1, "u̇ = {:?}", pose.udot);
            },
        );
        assert!(summary.is_err() || summary.unwrap().poses >= 1);
    }
}

#[test]
fn subnormal_velocities_are_underflow() {
    let (l1, l2, theta2): (f64, f64, f64) =
        (2.9847149370108802e23, 1.2736528197825383, 9.527996370732259);
    let b = Vector2::new(l2 * theta2.cos(), l2 * theta2.sin());
    let c = Vector2::new(2.9748600056257435, 0.2004409639425302) * l1;
    let d = Vector2::new(l1, 0.0);
    let bar = FourBar {
        l1,
        l2,
        l3: (c - b).norm(),
        l4: (d - c).norm(),
    };
    let guess = vector![(c - b).y.atan2((c - b).x), (d - c).y.atan2((d - c).x)];
    let options = Options::default();
    let result = bar.analyze(
        &guess,
        &vector![theta2],
        &vector![-1e-300],
        &vector![0.0],
        &options,
    );
    assert!(matches!(result, Err(Error::Underflow { .. })), "{result:?}");
    // The same mechanism at an ordinary speed is fine.
    let a = bar
        .analyze(
            &guess,
            &vector![theta2],
            &vector![-1.0],
            &vector![0.0],
            &options,
        )
        .expect("an ordinary speed");
    assert!(a.udot.amax() > 0.0);
}

/// A rhombus of unit links (all equal) at θ̇₂ = 88.75, θ̈₂ = 2.2e-308: γ's
/// terms, of size θ̇₂², cancel, and ü is tiny; that is no underflow (the
/// error is relative to the terms), and methods A and B must agree. Once
/// one said `Underflow` while the other said `Ok`.
#[test]
fn cancellation_is_not_underflow() {
    let bar = FourBar {
        l1: 1.0,
        l2: 1.0,
        l3: 1.0,
        l4: 1.0,
    };
    let options = Options {
        damped: true,
        ..Options::default()
    };
    let (v, vdot, vddot) = (
        vector![-6.793924208014447],
        vector![88.75085585176765],
        vector![2.2250738585072014e-308],
    );
    let a = bar
        .analyze(
            &vector![5.66924140171174, -1.3335562559465945],
            &v,
            &vdot,
            &vddot,
            &options,
        )
        .expect("the rhombus assembles");
    for method in [AccelerationMethod::A, AccelerationMethod::B] {
        let with = Options { method, ..options };
        let uddot = bar
            .acceleration(&a.u, &v, &a.udot, &vdot, &vddot, &with)
            .expect("no underflow");
        assert!((uddot - a.uddot).amax() <= 1e-13 * vdot[0] * vdot[0]);
    }
    // Rhombi of 26.4 at θ̇₂ = 20.6 and θ̈₂ = 5e-324: ü is subnormal, but the
    // terms it is made of are not; methods A and B cancel γ exactly and
    // once said `Underflow` where the fused γ said `Ok`.
    let bar = FourBar {
        l1: 26.382266724994903,
        l2: 26.382266724994903,
        l3: 26.382266724994903,
        l4: 26.382266724994903,
    };
    let options = Options::default();
    let (v, vdot, vddot) = (
        vector![-0.9480644196028856],
        vector![20.609772770627007],
        vector![5e-324],
    );
    let a = bar
        .analyze(
            &vector![4.218873701362285, 2.2040557835185792],
            &v,
            &vdot,
            &vddot,
            &options,
        )
        .expect("the rhombus assembles");
    for method in [AccelerationMethod::A, AccelerationMethod::B] {
        let with = Options { method, ..options };
        let uddot = bar
            .acceleration(&a.u, &v, &a.udot, &vdot, &vddot, &with)
            .expect("no underflow");
        assert!((uddot - a.uddot).amax() <= 1e-13 * vdot[0] * vdot[0]);
    }
}

/// The worksheet's crank-rocker turned through 10⁴ rad in two steps: with
/// at most 0.1 rad per sub-step that needs 5·10⁴ sub-steps a step. Once a
/// drive of 1e300 rad sub-stepped forever; now the budget stops it.
#[test]
fn endless_drives_hit_the_substep_limit() {
    let options = SweepOptions {
        max_substeps: 1000,
        ..SweepOptions::default()
    };
    let guess = vector![0.3, 1.5];
    let far = Drive::Line {
        from: vector![0.0],
        to: vector![1e4],
        steps: 2,
    };
    let result = SEED.sweep(&guess, &far, &options);
    assert!(
        matches!(
            result,
            Err(Error::SubstepLimit {
                step: 1,
                limit: 1000
            })
        ),
        "{:?}",
        result.map(|s| s.poses.len())
    );
    // One turn in 36 steps stays well within the same budget.
    let turn = Drive::Line {
        from: vector![0.0],
        to: vector![std::f64::consts::TAU],
        steps: 36,
    };
    let sweep = SEED.sweep(&guess, &turn, &options).expect("one turn");
    assert!(sweep.complete && sweep.poses.len() == 37);
}

/// Angles do not care about units: a mechanism scaled by k (and its
/// residual tolerance with it) has the same angles, angular velocities and
/// angular accelerations, whatever k. The
/// runtime must give them (or say `Underflow`, never a wrong `Ok`) for k
/// from 1e-250 to 1e250, at speeds from 1e-40 to 1e3, on the fused and the
/// separate paths and from the stretched-dyad saddle. A review found each
/// of these broken once: a tiny mechanism's γ underflowed inside `Ok`, the
/// fused kernel returned ü = 0, and the merit ½‖Ψ‖² underflowed so that a
/// saddle looked like a minimum.
#[test]
fn angles_are_scale_invariant() {
    let base = [1.0, 1.0, 1.0, 1.0];
    let theta2 = -9.303165937741154;
    let near = vector![0.9, -0.8];
    let saddle = vector![-1e-300, -1e-300];
    for k in [1e-250, 1e-170, 1e-60, 1.0, 1e60, 1e170, 1e250] {
        let bar = |l: [f64; 4]| FourBar {
            l1: l[0] * k,
            l2: l[1] * k,
            l3: l[2] * k,
            l4: l[3] * k,
        };
        let (unit, scaled) = (bar(base.map(|x| x / k)), bar(base));
        for omega in [1e-40, 1e-3, 1.0, 1e3] {
            for method in [
                AccelerationMethod::Fused,
                AccelerationMethod::A,
                AccelerationMethod::B,
            ] {
                for guess in [near, saddle] {
                    let options = Options {
                        damped: true,
                        method,
                        ..Options::default()
                    };
                    let (v, vdot, vddot) = (vector![theta2], vector![omega], vector![0.5 * omega]);
                    let truth = unit
                        .analyze(&guess, &v, &vdot, &vddot, &options)
                        .expect("the unit rhombus");
                    // The residual tolerance is in the mechanism's units.
                    let options = Options {
                        residual_tol: options.residual_tol * k,
                        ..options
                    };
                    match scaled.analyze(&guess, &v, &vdot, &vddot, &options) {
                        Ok(a) => {
                            // To rounding of the terms each is made of:
                            // angles of size 1, rates of ω, accelerations
                            // of ω² + θ̈₂.
                            let close = |x: &SVector<f64, 2>, y: &SVector<f64, 2>, size: f64| {
                                (x - y).amax() <= 1e-12 * size
                            };
                            assert!(
                                close(&a.u, &truth.u, 1.0)
                                    && close(&a.udot, &truth.udot, omega)
                                    && close(&a.uddot, &truth.uddot, omega * omega + vddot[0]),
                                "k = {k:e}, ω = {omega:e}, {method:?}: {:?} against {:?}",
                                (a.u, a.udot, a.uddot),
                                (truth.u, truth.udot, truth.uddot)
                            );
                        }
                        Err(Error::Underflow { .. }) => {}
                        Err(e) => panic!("k = {k:e}, ω = {omega:e}, {method:?}: {e}"),
                    }
                }
            }
        }
    }
}

/// Velocities below the normal range (1e-309) with an ordinary v̈: ü is
/// Ψ_u⁻¹Ψ_v v̈ to full precision, the vanishing γ notwithstanding. Once the
/// scaling of the velocities divided by zero here.
#[test]
fn subnormal_velocities_with_an_ordinary_acceleration() {
    let options = Options::default();
    let v = vector![20f64.to_radians()];
    let pose = SEED
        .solve_position(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &v,
            &options,
        )
        .expect("the worksheet's pose");
    let rest = SEED
        .acceleration(
            &pose.u,
            &v,
            &vector![0.0, 0.0],
            &vector![0.0],
            &vector![1.0],
            &options,
        )
        .expect("at rest");
    for method in [
        AccelerationMethod::A,
        AccelerationMethod::B,
        AccelerationMethod::Fused,
    ] {
        let with = Options { method, ..options };
        let udot = vector![1e-309, -2e-309];
        let uddot = SEED
            .acceleration(&pose.u, &v, &udot, &vector![1e-309], &vector![1.0], &with)
            .expect("γ ≈ 1e-618 is nothing beside Ψ_v v̈");
        assert!((uddot - rest).amax() <= 1e-15 * rest.amax(), "{method:?}");
    }
}

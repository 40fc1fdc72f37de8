//! What every campaign shares: the runner, the strategies for random and
//! awkward numbers, the tally, the closed-form truth of an assembly, and
//! the properties one analysis of one world must have.

use crate::common::sensitivity::{Column, term_sizes, try_by_dual};
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};

fn cases() -> u32 {
    std::env::var("LINKAGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000)
}

pub(crate) fn runner() -> TestRunner {
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
pub(crate) fn length() -> BoxedStrategy<f64> {
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
pub(crate) fn number(range: f64) -> BoxedStrategy<f64> {
    prop_oneof![
        14 => -range..range,
        1 => -1e12f64..1e12,
        1 => special(),
    ]
    .boxed()
}

/// What happened, by kind.
#[derive(Default, Debug)]
pub(crate) struct Tally {
    cases: usize,
    pub(crate) ok: usize,
    pub(crate) errors: BTreeMap<&'static str, usize>,
    checked_closed_form: usize,
    /// Cases where the closed form and a near guess demand an `Ok`.
    expected_ok: usize,
    /// Sensitivities returned `Ok`.
    sensitivities_ok: usize,
    /// Of those, checked against num-dual (every number within 10^±100).
    sensitivities_compared: usize,
    /// Sensitivities refused (`Err`) at an analysed pose.
    sensitivities_err: usize,
}

impl Tally {
    pub(crate) fn error(&mut self, e: &Error) {
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
pub(crate) enum Truth {
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

pub(crate) fn four_bar_truth(l: [f64; 4], theta2: f64) -> Truth {
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

pub(crate) fn slider_truth(r: f64, l: f64, e: f64, theta2: f64) -> Truth {
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
pub(crate) fn moderate(x: f64) -> bool {
    x == 0.0 || (1e-6..=1e6).contains(&x.abs())
}

pub(crate) fn all_finite(xs: impl IntoIterator<Item = f64>) -> bool {
    xs.into_iter().all(f64::is_finite)
}

/// The properties of one analysis of one world.
#[allow(clippy::too_many_arguments)]
pub(crate) fn check<L: Sensitivities<M, 1, K>, const M: usize, const K: usize>(
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
            check_sensitivities(model, &Motion::of_analysis(&a), tally)?;
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
        // At a pose that need not close, with made-up rates.
        let motion = Motion {
            u,
            v,
            udot,
            vdot,
            uddot: udot,
            vddot,
        };
        if let Ok(s) = model.sensitivities(&motion, &options) {
            fine &= (0..K).all(|j| Column::of(&s, j).is_finite()) && s.rcond.is_finite();
        }
        fine
    }))
    .map_err(|_| TestCaseError::fail("an entry point panicked"))?;
    prop_assert!(
        entry,
        "NaN or ∞ inside an Ok of solve_position, velocity, acceleration or sensitivities"
    );
    Ok(())
}

/// The sensitivities at an analysed pose: no panic, no NaN in `Ok`, and an
/// `Ok` agrees with num-dual (parameters as dual numbers) to the accuracy
/// promised, relative to the size of the terms each result is made of.
fn check_sensitivities<L: Sensitivities<M, 1, K>, const M: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, 1>,
    tally: &RefCell<Tally>,
) -> Result<(), TestCaseError> {
    let options = Options::default();
    let result = catch_unwind(AssertUnwindSafe(|| model.sensitivities(motion, &options)))
        .map_err(|_| TestCaseError::fail("sensitivities panicked"))?;
    let s = match result {
        Ok(s) => s,
        Err(e) => {
            tally.borrow_mut().sensitivities_err += 1;
            prop_assert!(
                matches!(e, Error::Singular { .. } | Error::NonFiniteValue { .. }),
                "sensitivities at an analysed pose: {e}"
            );
            return Ok(());
        }
    };
    tally.borrow_mut().sensitivities_ok += 1;
    // num-dual's products underflow or overflow in worlds of extreme scale
    // (1e300 lengths times 1e-300 rates) where the library's do not: it is
    // a reference only where every number is within 10^±100.
    let scale_ok = |x: f64| x == 0.0 || (1e-100..=1e100).contains(&x.abs());
    let params = model.params();
    let numbers = params.iter().copied().chain(
        motion
            .u
            .iter()
            .chain(&motion.v)
            .chain(&motion.udot)
            .chain(&motion.vdot)
            .chain(&motion.uddot)
            .chain(&motion.vddot)
            .copied(),
    );
    let comparable = numbers.into_iter().all(scale_ok);
    tally.borrow_mut().sensitivities_compared += usize::from(comparable);
    let terms = model.sensitivity_terms(
        &motion.u,
        &motion.v,
        &motion.udot,
        &motion.vdot,
        &motion.uddot,
        &motion.vddot,
    );
    for j in 0..K {
        let ours = Column::of(&s, j);
        prop_assert!(ours.is_finite(), "NaN or ∞ inside Ok: {s:?}");
        if !comparable {
            continue;
        }
        let dual = catch_unwind(AssertUnwindSafe(|| try_by_dual(model, motion, j)))
            .map_err(|_| TestCaseError::fail("num-dual's sensitivities panicked"))?;
        let Some(dual) = dual.filter(Column::is_finite) else {
            continue;
        };
        let sizes = term_sizes(&terms, &s, j);
        let distance = ours.distance(&dual);
        for g in 0..4 {
            prop_assert!(
                distance[g] <= options.accuracy * sizes[g] + 1e-300,
                "sensitivity group {g} by {}: ours {ours:?}, num-dual {dual:?} (terms {sizes:?})",
                model.param_names()[j]
            );
        }
    }
    Ok(())
}

pub(crate) fn report(name: &str, tally: &Tally, seconds: f64) {
    eprintln!(
        "{name}: {} cases in {seconds:.1} s, {} Ok, errors {:?}, {} checked against the closed form, {} of them clear and guessed near so that only Ok will do; sensitivities {} Ok ({} checked against num-dual), {} refused; panics 0, NaN in Ok 0, wrong Ok 0, wrong Err 0",
        tally.cases,
        tally.ok,
        tally.errors,
        tally.checked_closed_form,
        tally.expected_ok,
        tally.sensitivities_ok,
        tally.sensitivities_compared,
        tally.sensitivities_err
    );
}

//! Garbage into every public entry point of the facade's areas — cams,
//! machine dynamics, kinetostatics, scenes and diagrams — as
//! `tests/reliability.rs` does for the runtime.
//!
//! Every number is an awkward one: an arbitrary bit pattern, a special
//! value (NaN, ±∞, ±0, the extremes, subnormals), or an ordinary number
//! that may be negative or zero; counts range from 0 to usize::MAX. The
//! properties, for every case:
//!
//! - it ends within a time limit (a watchdog thread: no hang);
//! - it does not panic;
//! - an `Ok` holds no NaN or infinity (an SVG none written as "NaN" or
//!   "inf").
//!
//! The number of cases per area is `LINKAGE_CASES` (default 300, what CI
//! runs, a tenth of that for the sizing of cams and the machines' real
//! motion, which are slow when their inputs happen to be valid); the long
//! run:
//!
//!     LINKAGE_CASES=20000 cargo test --release --test facade_reliability -- --nocapture

mod common;

use common::FourBar;
use linkage::cam::{
    Cam, CamError, Follower, Law, Program, Rotation, Segment, smallest_rocker, smallest_translating,
};
use linkage::draw::diagrams::{Chart, Diagrams, Hodographs, Kind, Panel};
use linkage::draw::scene::{Frame, Scene};
use linkage::ground::Ground;
use linkage::machine::kinetostatics::Kinetostatics;
use linkage::machine::{Body, Load, Machine, Motor, Table, flywheel};
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::sync::mpsc;
use std::time::{Duration, Instant};

fn cases() -> u32 {
    std::env::var("LINKAGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

fn runner(cases: u32) -> TestRunner {
    let mut config = Config::with_cases(cases.max(1));
    config.failure_persistence = None;
    // A hang shrinks slowly: a minute of shrinking at most.
    config.max_shrink_time = 60_000;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x6661_6361_6465);
    }
    TestRunner::new(config)
}

/// The longest a case may take (`LINKAGE_TIME_LIMIT` seconds, default 120):
/// far beyond any legitimate one, even unoptimised, so that running out
/// means a hang.
fn time_limit() -> Duration {
    let seconds = std::env::var("LINKAGE_TIME_LIMIT")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(120);
    Duration::from_secs(seconds)
}

/// How a case ended.
enum Ended<T> {
    Done(T),
    Panicked(String),
    Hung,
}

/// Runs `f` on a thread of its own and waits at most [`time_limit`].
fn watched<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> Ended<T> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        let _ = send.send(outcome);
    });
    match receive.recv_timeout(time_limit()) {
        Ok(Ok(value)) => Ended::Done(value),
        Ok(Err(payload)) => Ended::Panicked(
            payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default(),
        ),
        Err(_) => Ended::Hung,
    }
}

/// An awkward number from 64 random bits: an arbitrary bit pattern, a
/// special value, or an ordinary number of either sign.
fn awkward(bits: u64) -> f64 {
    const SPECIAL: [f64; 12] = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        f64::MAX,
        -f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
        1e300,
        -1e-300,
        1.0,
    ];
    let pick = bits >> 60;
    let rest = bits & ((1 << 60) - 1);
    match pick {
        0..=3 => f64::from_bits(bits.rotate_left(7)),
        4..=6 => SPECIAL[(rest % SPECIAL.len() as u64) as usize],
        _ => {
            // ±10^(−3 … 3), some of them whole.
            let exponent = (rest % 6001) as f64 / 1000.0 - 3.0;
            let sign = if rest & (1 << 40) != 0 { -1.0 } else { 1.0 };
            let x = sign * 10f64.powf(exponent);
            if rest & (1 << 41) != 0 { x.round() } else { x }
        }
    }
}

/// A count: small ones mostly, some huge.
fn count(bits: u64) -> usize {
    match bits % 8 {
        0 => 0,
        1 => usize::MAX,
        2 => u32::MAX as usize,
        3 => (bits >> 8) as usize % 100_000,
        _ => (bits >> 8) as usize % 200,
    }
}

/// The numbers of one world: all ordinary (a third of the worlds), all
/// ordinary but one awkward (a third), or all awkward — so that the code
/// behind the checks of the settings is reached, with every awkward number
/// in every place.
struct Numbers<const N: usize> {
    bits: [u64; N],
}

impl<const N: usize> Numbers<N> {
    /// The k-th number, `usual` when ordinary.
    fn get(&self, k: usize, usual: f64) -> f64 {
        let mode = self.bits[0] % 3;
        let spoilt = (self.bits[0] >> 2) as usize % N;
        match mode {
            0 => usual,
            1 if k != spoilt => usual,
            _ => awkward(self.bits[k].rotate_left(11)),
        }
    }
}

fn finite(xs: impl IntoIterator<Item = f64>) -> bool {
    xs.into_iter().all(f64::is_finite)
}

/// An SVG without a non-finite number written into it.
fn clean_svg(svg: &str) -> bool {
    for word in ["NaN", "inf"] {
        if let Some(at) = svg.find(word) {
            let from = svg[..at].char_indices().rev().nth(80).map_or(0, |(i, _)| i);
            let to = svg[at..]
                .char_indices()
                .nth(40)
                .map_or(svg.len(), |(i, _)| at + i);
            eprintln!("a non-finite number in an SVG: …{:?}…", &svg[from..to]);
            return false;
        }
    }
    true
}

/// What a campaign found.
#[derive(Default)]
struct Tally {
    cases: usize,
    ok: usize,
    errors: BTreeMap<String, usize>,
    slowest: Duration,
}

impl Tally {
    fn error(&mut self, e: &dyn std::fmt::Debug) {
        let text = format!("{e:?}");
        let kind = text
            .split(|c: char| !c.is_alphanumeric())
            .find(|s| !s.is_empty())
            .unwrap_or("?")
            .to_string();
        *self.errors.entry(kind).or_default() += 1;
    }

    fn report(&self, name: &str, started: Instant) {
        eprintln!(
            "{name}: {} cases in {:.1} s (slowest {:.2} s), {} Ok, errors {:?}; panics 0, hangs 0, NaN in Ok 0",
            self.cases,
            started.elapsed().as_secs_f64(),
            self.slowest.as_secs_f64(),
            self.ok,
            self.errors
        );
    }
}

/// Runs one case under the watchdog, turning a panic or a hang into a
/// failure and tallying the outcome (`fine`: no NaN in an `Ok`).
fn case(
    tally: &RefCell<Tally>,
    f: impl FnOnce() -> (bool, Vec<Result<(), String>>) + Send + 'static,
) -> Result<(), TestCaseError> {
    let started = Instant::now();
    let ended = watched(f);
    let mut t = tally.borrow_mut();
    t.cases += 1;
    t.slowest = t.slowest.max(started.elapsed());
    match ended {
        Ended::Hung => Err(TestCaseError::fail(format!("hung for {:?}", time_limit()))),
        Ended::Panicked(message) => Err(TestCaseError::fail(format!("panicked: {message}"))),
        Ended::Done((fine, outcomes)) => {
            if !fine {
                let lies: Vec<&String> = outcomes
                    .iter()
                    .filter_map(|o| o.as_ref().err())
                    .filter(|e| e.starts_with("NaN or ∞"))
                    .collect();
                return Err(TestCaseError::fail(format!("{lies:?}")));
            }
            for outcome in outcomes {
                match outcome {
                    Ok(()) => t.ok += 1,
                    Err(kind) => t.error(&kind),
                }
            }
            Ok(())
        }
    }
}

/// The outcome of one call: its `Ok` checked by `good`, its `Err` named.
fn outcome<T, E: std::fmt::Debug>(
    result: Result<T, E>,
    good: impl FnOnce(&T) -> bool,
    fine: &mut bool,
    outcomes: &mut Vec<Result<(), String>>,
) -> Option<T> {
    match result {
        Ok(value) => {
            if !good(&value) {
                *fine = false;
                outcomes.push(Err(format!(
                    "NaN or ∞ inside an Ok<{}>",
                    std::any::type_name::<T>()
                )));
            }
            outcomes.push(Ok(()));
            Some(value)
        }
        Err(e) => {
            outcomes.push(Err(format!("{e:?}")));
            None
        }
    }
}

fn law(bits: u64) -> Law {
    match bits % 6 {
        0 => Law::ConstantAcceleration {
            k: awkward(bits >> 3),
        },
        1 => Law::Harmonic,
        2 => Law::Cycloidal,
        3 => Law::Polynomial345,
        4 => Law::ModifiedTrapezoid,
        _ => Law::ConstantAcceleration { k: 1.0 },
    }
}

fn segment(bits: u64, angle: f64) -> Segment {
    match bits % 3 {
        0 => Segment::Rise {
            angle,
            law: law(bits >> 2),
        },
        1 => Segment::Dwell { angle },
        _ => Segment::Return {
            angle,
            law: law(bits >> 2),
        },
    }
}

/// A program of awkward numbers, or, half the time, a reasonable one (so
/// that the cams behind it are reached).
fn program(bits: &[u64; 8]) -> Result<Program, CamError> {
    if bits[0] % 2 == 0 {
        let lift = awkward(bits[1]);
        let segments = (0..(bits[2] % 5) as usize)
            .map(|i| segment(bits[3 + i], awkward(bits[3 + i].rotate_left(17))))
            .collect();
        Program::new(lift, segments)
    } else {
        let angle = |b: u64| 0.2 + (b % 1000) as f64 / 1000.0;
        Program::new(
            0.01 + (bits[1] % 100) as f64 / 1000.0,
            vec![
                Segment::Rise {
                    angle: angle(bits[2]),
                    law: law(bits[3] | 1),
                },
                Segment::Dwell {
                    angle: angle(bits[4]) * 0.5,
                },
                Segment::Return {
                    angle: angle(bits[5]),
                    law: law(bits[6] | 1),
                },
            ],
        )
    }
}

fn follower(bits: &[u64; 5]) -> Follower {
    let ordinary = bits[0] % 3 == 0;
    let number = |b: u64, usual: f64| {
        if ordinary {
            usual * (0.5 + (b % 1000) as f64 / 1000.0)
        } else {
            awkward(b)
        }
    };
    if bits[0] % 2 == 0 {
        Follower::Rocker {
            arm: number(bits[1], 0.15),
            centre_distance: number(bits[2], 0.3),
            initial_angle: number(bits[3], 0.9),
            pivot_angle: number(bits[4], -1.5),
        }
    } else {
        Follower::Translating {
            offset: number(bits[1], 0.01),
            base: number(bits[2], 0.2),
            axis_angle: number(bits[3], 1.5),
        }
    }
}

#[test]
fn cams_never_hang_panic_or_lie() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    let world = (
        any::<[u64; 8]>(),
        any::<[u64; 5]>(),
        any::<[u64; 8]>(),
        any::<bool>(),
    );
    runner(cases())
        .run(&world, |(p, f, n, clockwise)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let rotation = if clockwise {
                    Rotation::Clockwise
                } else {
                    Rotation::CounterClockwise
                };
                let Some(program) = outcome(
                    program(&p),
                    |pr| finite([pr.lift()]),
                    &mut fine,
                    &mut outcomes,
                ) else {
                    return (fine, outcomes);
                };
                let phi = awkward(n[0]);
                outcome(
                    program.at(phi),
                    |(d, _)| finite(*d),
                    &mut fine,
                    &mut outcomes,
                );
                // A law at any x: finite where the law is valid and x a
                // number (clamped to [0, 1]), NaN otherwise.
                for &b in &n[..4] {
                    let (law, x) = (law(b), awkward(b.rotate_left(5)));
                    let d = law.at(x);
                    fine &= if law.is_valid() && !x.is_nan() {
                        finite(d)
                    } else {
                        d.iter().all(|v| v.is_nan())
                    };
                }
                let Some(cam) = outcome(
                    Cam::new(program.clone(), follower(&f), rotation),
                    |c| finite([c.base_radius()]),
                    &mut fine,
                    &mut outcomes,
                ) else {
                    return (fine, outcomes);
                };
                outcome(
                    cam.pitch(phi),
                    |p| finite(p.k.iter().chain(&p.dk).chain(&p.ddk).copied()),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.pressure_angle(phi),
                    |x| x.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.pitch_curvature(phi),
                    |x| x.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.pressure_extremes(),
                    |&((a, b), (c, d))| finite([a, b, c, d]),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.pressure_excess(awkward(n[1])),
                    |x| x.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.largest_roller(),
                    |&(a, b)| finite([a, b]),
                    &mut fine,
                    &mut outcomes,
                );
                let roller = awkward(n[2]);
                outcome(
                    cam.profile(roller, count(n[3])),
                    |points| {
                        points.iter().all(|q| {
                            finite([q.phi, q.curvature])
                                && finite(q.pitch.iter().chain(&q.profile).copied())
                        })
                    },
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    cam.drawing(roller, phi, "a cam", awkward(n[4])),
                    |svg| clean_svg(svg),
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("cams", started);
}

/// The sizing of cams: slow when its inputs are valid, so fewer cases.
#[test]
fn cam_sizing_never_hangs_panics_or_lies() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    let world = (any::<[u64; 8]>(), any::<[u64; 4]>(), any::<bool>());
    runner(cases() / 10)
        .run(&world, |(p, n, clockwise)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let rotation = if clockwise {
                    Rotation::Clockwise
                } else {
                    Rotation::CounterClockwise
                };
                let Ok(program) = program(&p) else {
                    return (fine, outcomes);
                };
                // An ordinary limit a third of the time.
                let limit = if n[3] % 3 == 0 {
                    0.3 + (n[3] % 500) as f64 / 1000.0
                } else {
                    awkward(n[3])
                };
                let arm = if n[0] % 2 == 0 { 0.15 } else { awkward(n[0]) };
                let good = |c: &Cam| finite([c.base_radius()]);
                outcome(
                    smallest_rocker(&program, arm, awkward(n[1]), rotation, limit),
                    good,
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    smallest_translating(&program, awkward(n[2]), rotation, limit),
                    good,
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("cam sizing", started);
}

/// The worksheet's four-bar with its midpoints, lengths scaled by `scale`
/// or replaced by awkward numbers.
fn four_bar(bits: &[u64; 4], ordinary: bool) -> FourBar {
    let l = |k: usize, usual: f64| {
        if ordinary { usual } else { awkward(bits[k]) }
    };
    FourBar {
        l1: l(0, 80.0),
        l2: l(1, 20.0),
        l3: l(2, 50.0),
        l4: l(3, 70.0),
    }
}

/// A machine of the four-bar with awkward bodies and loads, or ordinary
/// ones (so that the analyses behind are reached).
fn machine(world: &MachineWorld) -> Result<Machine<FourBar, 2>, linkage::machine::MachineError> {
    let (model_bits, body_bits, load_bits, grid_bits) = world;
    // Half the worlds ordinary throughout, so that the analyses behind the
    // checks are reached; the others awkward in a third of their numbers.
    let ordinary = model_bits[0] % 2 == 0;
    let bar = four_bar(model_bits, ordinary || model_bits[1] % 3 != 0);
    let number = |b: u64, usual: f64| {
        if ordinary || b % 3 != 0 {
            usual
        } else {
            awkward(b)
        }
    };
    let points = ["B", "C", "G2", "G3", "G4", "Q"];
    let coordinates = ["theta2", "theta3", "theta4", "psi"];
    let mut builder = Machine::new(bar, vector![0.4, -1.2]);
    for (k, &b) in body_bits.iter().enumerate() {
        let mut body = Body::new(&format!("body {k}"))
            .mass(number(b, 2.0))
            .inertia(number(b.rotate_left(13), 0.1));
        // The points and coordinates that exist, or now and then not.
        let pick = |names: &[&'static str], b: u64| {
            let known = names.len() - 1;
            let k = if ordinary || b % 11 != 0 {
                b as usize % known
            } else {
                known
            };
            names[k]
        };
        if b % 5 != 0 {
            body = body.at(pick(&points, b >> 4));
        }
        if b % 7 != 0 {
            body = body.angle_as(pick(&coordinates, b >> 8), number(b.rotate_left(29), 1.0));
        }
        builder = builder.body(body);
    }
    let direction = |b: u64| {
        if ordinary || b % 3 != 0 {
            nalgebra::Vector2::new(1.0, 0.0)
        } else {
            nalgebra::Vector2::new(awkward(b), awkward(b.rotate_left(23)))
        }
    };
    let point = |b: u64| points[(b >> 5) as usize % (points.len() - 1)];
    let l = load_bits;
    builder = builder.load(Load::gravity("gravity", direction(l[0]) * 9.81));
    if let Ok(table) = Table::new(vec![
        (0.0, 0.0),
        (number(l[1], 10.0), number(l[2], 100.0)),
        (number(l[3], 40.0), number(l[4], 100.0)),
    ]) {
        builder = builder.load(Load::process(
            "process",
            point(l[1]),
            direction(l[5]),
            table,
        ));
    }
    builder = builder.load(Load::friction(
        "friction",
        point(l[6]),
        direction(l[7]),
        number(l[8], 5.0),
    ));
    let (fx, m) = (number(l[9], 3.0), number(l[10], 0.5));
    builder = builder.load(Load::force("force", point(l[11]), move |_| {
        nalgebra::Vector2::new(fx, 0.0)
    }));
    builder = builder.load(
        Load::moment("moment", coordinates[l[12] as usize % 3], move |pose| {
            m * pose.phi.sin()
        })
        .kinks(move |_| vec![fx]),
    );
    let grid = match grid_bits % 4 {
        0 => usize::MAX,
        1 => (grid_bits >> 8) as usize % 8,
        _ => 16 + (grid_bits >> 8) as usize % 100,
    };
    builder.grid(grid).build()
}

type MachineWorld = ([u64; 4], [u64; 3], [u64; 13], u64);

fn machine_world() -> impl Strategy<Value = MachineWorld> {
    (
        any::<[u64; 4]>(),
        any::<[u64; 3]>(),
        any::<[u64; 13]>(),
        any::<u64>(),
    )
}

#[test]
fn machines_never_hang_panic_or_lie() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    runner(cases())
        .run(&(machine_world(), any::<[u64; 8]>()), |(world, n)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                // The flywheel's formulas and tables, on their own.
                let x = |k: usize| awkward(n[k]);
                outcome(
                    flywheel::from_md2(x(0)),
                    |v| v.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    flywheel::on_motor_shaft(x(1), x(2), x(3), x(4)),
                    |v| v.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    flywheel::Rim::course_rule(x(5)),
                    |r| finite([r.outer, r.inner, r.width, r.mass, r.inertia()]),
                    &mut fine,
                    &mut outcomes,
                );
                if let Some(table) = outcome(
                    Table::new(vec![(x(0), x(1)), (x(2), x(3)), (x(2), x(4)), (x(5), x(6))]),
                    |t| t.area().is_finite(),
                    &mut fine,
                    &mut outcomes,
                ) {
                    let _ = table.at(x(7));
                }
                let Some(m) = outcome(machine(&world), |_| true, &mut fine, &mut outcomes) else {
                    return (fine, outcomes);
                };
                let phi = x(6);
                outcome(
                    m.reduced(phi),
                    |r| finite([r.inertia, r.inertia_derivative, r.moment]),
                    &mut fine,
                    &mut outcomes,
                );
                outcome(m.work(phi), |w| w.is_finite(), &mut fine, &mut outcomes);
                fine &= finite([m.cycle_work(), m.mean_driving_moment()]);
                let energy = outcome(
                    m.energy_method(x(0), x(1)),
                    |e| finite([e.flywheel, e.driving_moment, e.minimum.1, e.maximum.1]),
                    &mut fine,
                    &mut outcomes,
                );
                if let Some(e) = energy {
                    outcome(e.omega(phi), |w| w.is_finite(), &mut fine, &mut outcomes);
                    outcome(e.epsilon(phi), |w| w.is_finite(), &mut fine, &mut outcomes);
                    outcome(
                        e.epsilon_extremes(),
                        |&((a, b), (c, d))| finite([a, b, c, d]),
                        &mut fine,
                        &mut outcomes,
                    );
                }
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("machines", started);
}

/// The real motion: slow when its inputs are valid, so fewer cases.
#[test]
fn real_motion_never_hangs_panics_or_lies() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    runner(cases() / 10)
        .run(&(machine_world(), any::<[u64; 6]>()), |(world, n)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let Ok(m) = machine(&world) else {
                    return (fine, outcomes);
                };
                let ordinary = n[0] % 2 == 0;
                let number = |b: u64, usual: f64| if ordinary { usual } else { awkward(b) };
                let motor = if n[1] % 2 == 0 {
                    Motor::Constant {
                        moment: number(n[2], m.mean_driving_moment()),
                    }
                } else {
                    Motor::Linear {
                        moment: number(n[2], m.mean_driving_moment()),
                        speed: number(n[3], 10.0),
                        slope: number(n[4], 1.0),
                    }
                };
                let steps = if ordinary { 200 } else { count(n[5]) };
                outcome(
                    m.steady_motion(number(n[3], 50.0), motor, number(n[4], 10.0), steps),
                    |s| {
                        finite(s.omega.iter().chain(&s.epsilon).copied())
                            && finite([s.omega_min.1, s.omega_max.1, s.delta, s.period])
                    },
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("real motion", started);
}

#[test]
fn kinetostatics_never_hang_panic_or_lie() {
    let started = Instant::now();
    let tally = RefCell::new(Tally::default());
    runner(cases())
        .run(&(machine_world(), any::<[u64; 8]>()), |(world, n)| {
            case(&tally, move || {
                let (mut fine, mut outcomes) = (true, Vec::new());
                let Ok(m) = machine(&world) else {
                    return (fine, outcomes);
                };
                let x = |k: usize| {
                    if n[k] % 3 == 0 {
                        [1.0, 80.0, 0.0, 2.0, 0.3, 1.0, 1.0, 0.0][k]
                    } else {
                        awkward(n[k])
                    }
                };
                let names = ["body 0", "body 1", "body 2"];
                let statics = Kinetostatics::new(&m)
                    .with_ground(&Ground::new().point("A", [0.0, x(2)]))
                    .ground_point("D", [x(1), 0.0])
                    .body(names[0])
                    .body(names[1])
                    .body(names[2])
                    .revolute("A", "body 0", "ground", "A")
                    .revolute("B", "body 0", "body 1", "B")
                    .revolute("C", "body 1", "body 2", "C")
                    .revolute("D", "body 2", "ground", "D")
                    .load_on("process", "body 1")
                    .load_on("friction", "body 1")
                    .load_on("force", "body 2")
                    .load_on("moment", "body 0")
                    .driver("body 0", x(0))
                    .rotor("body 0", x(3), x(4))
                    .build();
                let Some(statics) = outcome(statics, |_| true, &mut fine, &mut outcomes) else {
                    return (fine, outcomes);
                };
                let (phi, omega, epsilon) = (x(5), x(6), x(7));
                outcome(
                    statics.solve(phi, omega, epsilon),
                    |r| {
                        finite([r.driving_moment])
                            && r.joints
                                .iter()
                                .all(|j| finite(j.force.iter().copied()) && finite(j.moment))
                    },
                    &mut fine,
                    &mut outcomes,
                );
                outcome(
                    statics.power_balance(phi, omega, epsilon),
                    |v| v.is_finite(),
                    &mut fine,
                    &mut outcomes,
                );
                (fine, outcomes)
            })
        })
        .unwrap();
    tally.into_inner().report("kinetostatics", started);
}

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
            .map(|a| Frame::from_analysis::<FourBar, 2, 1>(&a));
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
    Some(Frame::from_analysis::<FourBar, 2, 1>(&a))
}

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

/// The inputs that once looped forever (a rocker arm of 0 or NaN: the
/// bracket widened from 0 to 0) end, with an error.
#[test]
fn the_cases_that_once_hung_end() {
    let program = Program::new(
        0.045,
        vec![
            Segment::Rise {
                angle: 0.6,
                law: Law::Cycloidal,
            },
            Segment::Return {
                angle: 0.8,
                law: Law::Cycloidal,
            },
        ],
    )
    .unwrap();
    for arm in [0.0, f64::NAN] {
        let program = program.clone();
        let ended =
            watched(move || smallest_rocker(&program, arm, 0.0, Rotation::Clockwise, 0.6).is_err());
        assert!(matches!(ended, Ended::Done(true)));
    }
}

//! What the tapes cost: the time from a mechanism's text to every tape of
//! it ready (parse, lower, differentiate, emit, compile), and one
//! evaluation of the worksheet's four-bar on its tapes against the
//! compiled functions — one lane, and per lane of 4 and 8 lanes.
//!
//! ```sh
//! cargo run --release -p linkage-macros --example tape_cost
//! ```
//!
//! `--build-only` measures the building alone. Every time is the fastest of
//! several runs (of batches of calls): on a shared machine, the least
//! disturbed one.

// Not every example reads every field of a case.
#[allow(dead_code)]
#[path = "common/cases.rs"]
mod cases;

use cases::{Case, chain, fourbar, sixbar};
use linkage::nalgebra::{SMatrix, SVector};
use linkage_symbolic::derivatives::Derivatives;
use linkage_symbolic::emit::Mode;
use linkage_symbolic::errors::Errors;
use linkage_symbolic::plan::Kernel;
use linkage_symbolic::tape::{Input, Part, Tape, Tapes};
use proc_macro2::TokenStream;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// The worksheet's four-bar compiled by the attribute, with the text it
/// was compiled from.
macro_rules! compiled {
    ($($attr:tt)*) => {
        #[linkage::linkage($($attr)*)]
        pub struct Mechanism {
            pub l1: f64,
            pub l2: f64,
            pub l3: f64,
            pub l4: f64,
        }
        const ATTR: &str = stringify!($($attr)*);
    };
}

compiled!(
    u = [theta3, theta4],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        G2 = (0.5 * B.x, 0.5 * B.y),
        G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
        G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ]
);

/// The fastest of several runs: on a shared machine, the least disturbed.
fn fastest(times: Vec<Duration>) -> Duration {
    times.into_iter().min().unwrap_or_default()
}

/// The model of a mechanism's text.
fn model(case: &Case) -> Derivatives {
    let attr: TokenStream = case.attr.parse().expect("the attribute's text");
    let item: TokenStream = case.item.parse().expect("the struct's text");
    let mut errors = Errors::default();
    let input = linkage_symbolic::ast::Input::parse(attr, item, &mut errors).expect("a struct");
    match linkage_symbolic::build(&input, &mut errors) {
        Ok(model) => model,
        Err(_) => panic!("{}: {:?}", case.name, errors.combined()),
    }
}

/// From text to tapes: the front end (parse, lower, differentiate), every
/// kernel's statements emitted, and all of it with the tapes compiled.
fn build_times(case: &Case, runs: usize) -> (Duration, Duration, Duration, usize) {
    let (mut front, mut emit, mut whole) = (Vec::new(), Vec::new(), Vec::new());
    let mut ops = 0;
    for _ in 0..runs {
        let start = Instant::now();
        let model = model(case);
        front.push(start.elapsed());
        let tapes = Tapes::build(&model).expect("every kernel compiles");
        whole.push(start.elapsed());
        ops = Kernel::ALL.iter().map(|&k| tapes.get(k).len()).sum();
        let names = model.lowered.names();
        let start = Instant::now();
        for kernel in Kernel::ALL {
            let plan = kernel.plan(&model);
            black_box(plan.emit(model.dag(), &names, &[], Mode::F64));
        }
        emit.push(start.elapsed());
    }
    (fastest(front), fastest(emit), fastest(whole), ops)
}

/// The time of one evaluation, in ns: the fastest of `batches` batches of
/// `calls` calls of `f` (given the call's index), each call doing `lanes`
/// evaluations.
fn ns_per_evaluation(lanes: usize, mut f: impl FnMut(usize)) -> f64 {
    let (calls, batches) = (20_000 / lanes, 101);
    let mut times = Vec::with_capacity(batches);
    for _ in 0..batches {
        let start = Instant::now();
        for i in 0..calls {
            f(i);
        }
        times.push(start.elapsed());
    }
    fastest(times).as_secs_f64() * 1e9 / (calls * lanes) as f64
}

/// The inputs of call i (slightly different from call to call).
fn inputs(i: usize, lane: usize) -> ([f64; 2], [f64; 1]) {
    let d = (i % 64) as f64 * 1e-3 + lane as f64 * 0.01;
    ([0.6 + d, 1.4 - d], [0.8 + d])
}

const FIELDS: [f64; 4] = [80.0, 20.0, 50.0, 70.0];

/// A matrix filled from a part's outputs.
fn fill<const R: usize, const C: usize>(part: &Part, values: &[f64]) -> SMatrix<f64, R, C> {
    let mut m = SMatrix::zeros();
    for (&(i, j), &x) in part.entries.iter().zip(values) {
        m[(i, j)] = x;
    }
    m
}

/// One evaluation of each kernel on a tape, one lane at a time.
fn single(psi_and_psi_u: &Tape, kinematics: &Tape) -> (f64, f64, f64) {
    let mut r = psi_and_psi_u.registers::<1>();
    r.set(Input::Fields, &FIELDS).unwrap();
    let mut out = vec![0.0; psi_and_psi_u.outputs(0)];
    let jacobian = ns_per_evaluation(1, |i| {
        let (u, v) = inputs(i, 0);
        r.set(Input::U, black_box(&u)).unwrap();
        r.set(Input::V, black_box(&v)).unwrap();
        psi_and_psi_u.run(0, &mut r, &mut out).unwrap();
        black_box(&out);
    });
    let mut r = kinematics.registers::<1>();
    r.set(Input::Fields, &FIELDS).unwrap();
    r.set(Input::Vdot, &[1.0]).unwrap();
    let mut first = vec![0.0; kinematics.outputs(0)];
    let mut second = vec![0.0; kinematics.outputs(1)];
    let phases = ns_per_evaluation(1, |i| {
        let (u, v) = inputs(i, 0);
        r.set(Input::U, black_box(&u)).unwrap();
        r.set(Input::V, black_box(&v)).unwrap();
        kinematics.run(0, &mut r, &mut first).unwrap();
        r.set(Input::Udot, black_box(&[0.3, -0.2])).unwrap();
        kinematics.run(1, &mut r, &mut second).unwrap();
        black_box((&first, &second));
    });
    // With the compiled kinematics' own solve between and after the phases.
    let parts = [kinematics.parts(0), kinematics.parts(1)];
    let (psi_u_at, psi_v_at) = (
        parts[0][0].entries.len(),
        parts[0][0].entries.len() + parts[0][1].entries.len(),
    );
    let vdot = SVector::<f64, 1>::new(1.0);
    let vddot = SVector::<f64, 1>::new(0.0);
    let solved = ns_per_evaluation(1, |i| {
        let (u, v) = inputs(i, 0);
        r.set(Input::U, black_box(&u)).unwrap();
        r.set(Input::V, black_box(&v)).unwrap();
        kinematics.run(0, &mut r, &mut first).unwrap();
        let psi_u: SMatrix<f64, 2, 2> = fill(&parts[0][1], &first[psi_u_at..]);
        let psi_v: SMatrix<f64, 2, 1> = fill(&parts[0][2], &first[psi_v_at..]);
        let inverse = linkage::invert(&psi_u);
        let udot = -(inverse.inverse * (psi_v * vdot));
        r.set(Input::Udot, udot.as_slice()).unwrap();
        kinematics.run(1, &mut r, &mut second).unwrap();
        let gamma: SVector<f64, 2> = fill(&parts[1][0], &second);
        black_box(-(inverse.inverse * (psi_v * vddot + gamma)));
    });
    (jacobian, phases, solved)
}

/// Per lane of L lanes: Ψ and Ψ_u, and the two phases of `kinematics`.
fn lanes<const L: usize>(psi_and_psi_u: &Tape, kinematics: &Tape) -> (f64, f64) {
    let mut r = psi_and_psi_u.registers::<L>();
    for lane in 0..L {
        r.set_lane(Input::Fields, lane, &FIELDS).unwrap();
    }
    let mut out = vec![[0.0; L]; psi_and_psi_u.outputs(0)];
    let jacobian = ns_per_evaluation(L, |i| {
        for lane in 0..L {
            let (u, v) = inputs(i, lane);
            r.set_lane(Input::U, lane, black_box(&u)).unwrap();
            r.set_lane(Input::V, lane, black_box(&v)).unwrap();
        }
        psi_and_psi_u.run_lanes(0, &mut r, &mut out).unwrap();
        black_box(&out);
    });
    let mut r = kinematics.registers::<L>();
    for lane in 0..L {
        r.set_lane(Input::Fields, lane, &FIELDS).unwrap();
        r.set_lane(Input::Vdot, lane, &[1.0]).unwrap();
    }
    let mut first = vec![[0.0; L]; kinematics.outputs(0)];
    let mut second = vec![[0.0; L]; kinematics.outputs(1)];
    let phases = ns_per_evaluation(L, |i| {
        for lane in 0..L {
            let (u, v) = inputs(i, lane);
            r.set_lane(Input::U, lane, black_box(&u)).unwrap();
            r.set_lane(Input::V, lane, black_box(&v)).unwrap();
        }
        kinematics.run_lanes(0, &mut r, &mut first).unwrap();
        for lane in 0..L {
            r.set_lane(Input::Udot, lane, black_box(&[0.3, -0.2]))
                .unwrap();
        }
        kinematics.run_lanes(1, &mut r, &mut second).unwrap();
        black_box((&first, &second));
    });
    (jacobian, phases)
}

fn main() {
    let case = fourbar();
    let same_text = |a: &str| a.parse::<TokenStream>().map(|t| t.to_string()).ok();
    assert_eq!(
        same_text(ATTR),
        same_text(&case.attr),
        "the compiled four-bar is the measured one"
    );

    println!("From text to every tape ready (fastest run):\n");
    println!("| mechanism | m | front end | emitting | all, tapes ready | operations |");
    println!("|---|---:|---:|---:|---:|---:|");
    let mut cases = vec![(fourbar(), 2, 31), (sixbar(), 4, 15)];
    cases.extend([(chain(1), 2, 15), (chain(8), 16, 7), (chain(32), 64, 5)]);
    for (case, m, runs) in &cases {
        let (front, emit, whole, ops) = build_times(case, *runs);
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        println!(
            "| {} | {m} | {:.2} ms | {:.2} ms | {:.2} ms | {ops} |",
            case.name,
            ms(front),
            ms(emit),
            ms(whole)
        );
    }

    if std::env::args().any(|a| a == "--build-only") {
        return;
    }
    let model = model(&case);
    let tapes = Tapes::build(&model).expect("every kernel compiles");
    let psi_and_psi_u = tapes.get(Kernel::PsiAndPsiU);
    let kinematics = tapes.get(Kernel::Kinematics { with_trig: false });
    let mech = Mechanism {
        l1: FIELDS[0],
        l2: FIELDS[1],
        l3: FIELDS[2],
        l4: FIELDS[3],
    };
    let vector = |x: &[f64]| SVector::<f64, 2>::from_column_slice(x);
    let compiled_jacobian = ns_per_evaluation(1, |i| {
        let (u, v) = inputs(i, 0);
        let (u, v) = (
            vector(black_box(&u)),
            SVector::<f64, 1>::new(black_box(v[0])),
        );
        black_box(mech.psi_and_psi_u(&u, &v));
    });
    let compiled_kinematics = ns_per_evaluation(1, |i| {
        let (u, v) = inputs(i, 0);
        let (u, v) = (
            vector(black_box(&u)),
            SVector::<f64, 1>::new(black_box(v[0])),
        );
        let (vdot, vddot) = (SVector::<f64, 1>::new(1.0), SVector::<f64, 1>::new(0.0));
        black_box(mech.kinematics(&u, &v, &vdot, &vddot));
    });
    let (tape_jacobian, tape_phases, tape_solved) = single(psi_and_psi_u, kinematics);
    let (jacobian4, phases4) = lanes::<4>(psi_and_psi_u, kinematics);
    let (jacobian8, phases8) = lanes::<8>(psi_and_psi_u, kinematics);
    println!(
        "\nThe worksheet's four-bar, ns per evaluation (fastest of 101 batches; \
         {} and {} operations on the tapes):\n",
        psi_and_psi_u.len(),
        kinematics.len()
    );
    println!("| kernel | compiled | tape | tape, 4 lanes (per lane) | tape, 8 lanes (per lane) |");
    println!("|---|---:|---:|---:|---:|");
    println!(
        "| psi_and_psi_u | {compiled_jacobian:.1} | {tape_jacobian:.1} | {jacobian4:.1} | {jacobian8:.1} |"
    );
    println!("| kinematics, phases 0 + 1 | — | {tape_phases:.1} | {phases4:.1} | {phases8:.1} |");
    println!(
        "| kinematics with its solves | {compiled_kinematics:.1} | {tape_solved:.1} | — | — |"
    );
}

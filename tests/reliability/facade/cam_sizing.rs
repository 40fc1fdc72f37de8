//! The sizing of cams (the smallest rocker and translating cams), and the
//! inputs that once made it loop forever.

use super::cams::program;
use super::harness::{Ended, Tally, awkward, case, cases, finite, outcome, runner, watched};
use linkage::cam::{Cam, Law, Program, Rotation, Segment, smallest_rocker, smallest_translating};
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

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

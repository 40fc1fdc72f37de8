//! The machines' real motion under awkward motors and step counts.

use super::harness::{Tally, awkward, case, cases, count, finite, outcome, runner};
use super::machines::{machine, machine_world};
use linkage::machine::Motor;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

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

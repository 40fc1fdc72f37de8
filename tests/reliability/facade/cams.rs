//! Cams: programs, laws and followers of awkward numbers, through every
//! query of a cam and its drawing.

use super::harness::{Tally, awkward, case, cases, clean_svg, count, finite, outcome, runner};
use linkage::cam::{Cam, CamError, Follower, Law, Program, Rotation, Segment};
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

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
pub(crate) fn program(bits: &[u64; 8]) -> Result<Program, CamError> {
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

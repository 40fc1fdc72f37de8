//! Fuzzing the runtime's public entry points with arbitrary f64 bit
//! patterns: every argument, every parameter, and sweeps over random
//! drives. No panic, and no NaN or ∞ in any `Ok`. (Their sweeps are not
//! held to the branch-continuity check: with an angle of 1e180 rad, whose
//! ulp is 1e164, velocity ratios are not resolved. The four-bar sweeps
//! (`four_bar_sweeps.rs`) and `tests/sweep/singular_grid/` are.)

use crate::common::FourBar;
use crate::harness::{all_finite, runner};
use linkage::prelude::*;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::cell::RefCell;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

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

//! Kinetostatics of the machines with awkward grounds, drivers, rotors and
//! states.

use super::harness::{Tally, awkward, case, cases, finite, outcome, runner};
use super::machines::{machine, machine_world};
use linkage::ground::Ground;
use linkage::machine::kinetostatics::Kinetostatics;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

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

//! Machines of the four-bar with awkward bodies, loads and grids, and the
//! flywheel's formulas and tables, through the reduced dynamics and the
//! energy method.

use super::harness::{Tally, awkward, case, cases, finite, four_bar, outcome, runner};
use crate::common::FourBar;
use linkage::machine::{Body, Load, Machine, Table, flywheel};
use linkage::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::time::Instant;

/// A machine of the four-bar with awkward bodies and loads, or ordinary
/// ones (so that the analyses behind are reached).
pub(crate) fn machine(
    world: &MachineWorld,
) -> Result<Machine<FourBar, 2>, linkage::machine::MachineError> {
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

pub(crate) type MachineWorld = ([u64; 4], [u64; 3], [u64; 13], u64);

pub(crate) fn machine_world() -> impl Strategy<Value = MachineWorld> {
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

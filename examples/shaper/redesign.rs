//! The shaping machine re-designed for the smallest flywheel: K_V and the
//! stroke H kept (the mechanism synthesised from them as in the course
//! project), free the pivot distance l_OC, the ram's guide height y_F and
//! the rocker's mass distribution — its centre of mass S3 = C + λ·(D − C)
//! and its moment of inertia I_S3 about it, its mass kept (the same bar
//! shifted along its axis through the pivot, its section redistributed) —
//! to minimise the energy method's J_PRI, with the exact gradient
//! (`Machine::design`, the envelope theorem) and the bounded
//! Levenberg–Marquardt solver on the one residual √J_PRI.
//!
//! Shared by `examples/shaper` and `tests/machine/shaper/`.

#![allow(dead_code)]

use crate::machine::{Data, Shaper, machine, synthesize};
use linkage::least_squares::{LeastSquaresError, Stopping, least_squares};
use linkage::machine::{MachineError, Motor};
use linkage::nalgebra::{DMatrix, DVector};
use std::f64::consts::TAU;

/// The free variables, in order, and their bounds.
pub const VARIABLES: [&str; 4] = ["l_OC", "y_F", "λ_S3", "I_S3"];

/// The designer's bounds on the variables: l_OC from 0.3 to 0.45 m, the
/// guide within 0.1 m of the course project's height, S3 anywhere from
/// half the rocker below the pivot to 0.8 of it above, I_S3 from 0.5 to
/// 2 kg·m² (a 20 kg bar of the rocker's length has about 0.8 about its
/// centre). `course` is the course project's design as the variables.
pub fn bounds(course: &DVector<f64>) -> (DVector<f64>, DVector<f64>) {
    let y_f = course[1];
    (
        DVector::from_vec(vec![0.3, y_f - 0.1, -0.5, 0.5]),
        DVector::from_vec(vec![0.45, y_f + 0.1, 0.8, 2.0]),
    )
}

/// The course project's design as the variables.
pub fn course_variables(course: &Data) -> Result<DVector<f64>, MachineError> {
    let shaper = synthesize(course)?;
    Ok(DVector::from_vec(vec![
        course.l_oc,
        shaper.y_f,
        course.lambda_s3,
        course.i3s,
    ]))
}

/// The machine's data and mechanism for the variables x.
pub fn design(course: &Data, x: &DVector<f64>) -> Result<(Shaper, Data), MachineError> {
    let data = Data {
        l_oc: x[0],
        lambda_s3: x[2],
        i3s: x[3],
        ..*course
    };
    let shaper = Shaper {
        y_f: x[1],
        ..synthesize(&data)?
    };
    Ok((shaper, data))
}

/// J_PRI of the design x alone.
pub fn flywheel_value(course: &Data, x: &DVector<f64>) -> Result<f64, MachineError> {
    let (shaper, data) = design(course, x)?;
    let m = machine(&shaper, &data)?;
    Ok(m.energy_method(TAU * data.n1, data.delta)?.flywheel)
}

/// J_PRI and its exact gradient by the variables: the machine's gradient
/// by its dimensions and bodies (`Machine::design`), through the synthesis
/// l_OA = l_OC·sin(β/2), y_C = −l_OC (β fixed by K_V) for l_OC.
pub fn flywheel(
    course: &Data,
    x: &DVector<f64>,
) -> Result<(f64, DVector<f64>), Box<dyn std::error::Error>> {
    let (shaper, data) = design(course, x)?;
    let m = machine(&shaper, &data)?;
    let energy = m.energy_method(TAU * data.n1, data.delta)?;
    let by_design = m.design()?;
    let gradient = by_design.flywheel(&energy)?;
    let of = |name: &str| {
        let k = by_design.names().iter().position(|n| n == name);
        k.map(|k| gradient[k])
            .ok_or_else(|| format!("the design has no `{name}`"))
    };
    let half_swing = 0.5 * shaper.beta();
    Ok((
        energy.flywheel,
        DVector::from_vec(vec![
            of("l_oa")? * half_swing.sin() - of("y_c")?,
            of("y_f")?,
            of("lambda_s3")?,
            of("inertia of rocker 3")?,
        ]),
    ))
}

/// The optimum: where the solver stopped, J_PRI there and its gradient,
/// and the evaluations it took.
pub struct Optimum {
    pub x: DVector<f64>,
    pub flywheel: f64,
    pub gradient: DVector<f64>,
    pub evaluations: usize,
}

/// J_PRI minimised within the bounds from the course project's design.
pub fn minimise(course: &Data) -> Result<Optimum, Box<dyn std::error::Error>> {
    let start = course_variables(course)?;
    let (lower, upper) = bounds(&start);
    let stopping = Stopping {
        cost: 0.0,
        // ∇J_PRI is known to ≈ 1e-7 of its size (J_PRI's extremes are
        // located to the precision of f64, the work integrated to ≈ 1e-13):
        // stop where a relative change of any variable free to move changes
        // J_PRI by at most 1e-8 of itself (for λ_S3 ≈ 0.05, ∂J_PRI/∂λ_S3
        // within 2e-7 of J_PRI: the gradient resolved, with room).
        gradient: 1e-8,
        step: 1e-10,
        evaluations: 100,
        ..Stopping::default()
    };
    let found = least_squares(start, &lower, &upper, &stopping, |x| {
        let (j, g) = flywheel(course, x).ok()?;
        let r = j.sqrt();
        Some((
            DVector::from_element(1, r),
            DMatrix::from_row_slice(1, g.len(), (g / (2.0 * r)).as_slice()),
        ))
    })
    .map_err(|e: LeastSquaresError| e.to_string())?;
    let (flywheel, gradient) = flywheel(course, &found.x)?;
    Ok(Optimum {
        x: found.x,
        flywheel,
        gradient,
        evaluations: found.evaluations,
    })
}

/// The speed fluctuation the true periodic motion achieves with the
/// flywheel J_PRI of the design x (a constant driving moment, the mean
/// speed the course project's).
pub fn true_fluctuation(
    course: &Data,
    x: &DVector<f64>,
    inertia: f64,
) -> Result<f64, MachineError> {
    let (shaper, data) = design(course, x)?;
    let m = machine(&shaper, &data)?;
    let motor = Motor::Constant {
        moment: m.mean_driving_moment(),
    };
    Ok(m.steady_motion(inertia, motor, TAU * data.n1, 4000)?.delta)
}

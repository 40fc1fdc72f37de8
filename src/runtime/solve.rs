//! The linear solves at an assembled pose: the velocities Ψ_u u̇ = −Ψ_v v̇,
//! the accelerations Ψ_u ü = −Ψ_v v̈ − γ (scaled so that nothing underflows
//! or overflows), the fused one-pass kernel where it serves, and the
//! conditioning each needs to keep [`Options::accuracy`].

use crate::runtime::checks::{check_input, check_result, check_scale, check_value};
use crate::runtime::error::{Error, Stage};
use crate::runtime::factors::{Factors, factor};
use crate::runtime::kernels::{FusedRequest, Kernels};
use crate::runtime::linalg::augmented_condition;
use crate::runtime::newton::Progress;
use crate::runtime::options::{AccelerationMethod, JacobianSource, Options};
use crate::runtime::powers_of_two::power_of_two_near;
use crate::runtime::results::{Analysis, AnalysisJob, Kinematics, Position, Velocity};
use crate::runtime::trig::PoseTrig;
use crate::runtime::{newton, sources};
use nalgebra::{SMatrix, SVector};

/// `Linkage::analyze`: Newton–Raphson, then the velocities and the
/// accelerations (by the fused kernel where it serves, else by the separate
/// solves), then the points. With the generated code, the fused γ and
/// plain Newton (the defaults), every Newton evaluation is the fused kernel
/// and the one that confirms convergence gives the kinematics
/// ([`newton::FusedNewton`], the evaluation kept here, not moved).
pub(crate) fn analyze<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u_guess: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<Analysis<M, F, L::Points>, Error> {
    let fused_serves = fused_serves(vdot, vddot, options)?;
    if fused_serves && !options.damped {
        let mut newton = newton::FusedNewton::start(model, u_guess, v, options)?;
        if model.evaluates_in_place() {
            // Each evaluation written over one kept for the analysis (a
            // large m's, or a run-time mechanism's): none is moved.
            let mut k = Kinematics::blank();
            loop {
                let (u, trig_u, trig_v) = newton.pose();
                model.kinematics_with_trig_over(u, v, trig_u, trig_v, vdot, vddot, &mut k);
                if let Progress::Done(ended) = newton.advance(model, &k, options) {
                    return finish_fused(model, ended?, &k, v, vdot, vddot, options);
                }
            }
        }
        loop {
            let (u, trig_u, trig_v) = newton.pose();
            let k = model.kinematics_with_trig(u, v, trig_u, trig_v, vdot, vddot);
            if let Progress::Done(ended) = newton.advance(model, &k, options) {
                return finish_fused(model, ended?, &k, v, vdot, vddot, options);
            }
        }
    }
    let position = newton::solve(model, u_guess, v, options, &mut |_| {})?;
    let fused = if fused_serves {
        let k = model.kinematics(&position.u, v, vdot, vddot);
        fused_kinematics(&k, vdot, vddot, options)?
    } else {
        None
    };
    finish(model, position, fused, None, v, vdot, vddot, options)
}

/// [`analyze`] of every job, in order, each result bit for bit the one it
/// gives alone, written to its slot of `results` (one per job; every slot
/// is written): the Newton iterations of the jobs on the fused kernel
/// (the defaults) run side by side, each round's evaluations asked for
/// together ([`Kernels::kinematics_with_trig_each`]: on a run-time
/// mechanism's lanes), each job ending when it would alone.
pub(crate) fn analyze_together<L: Kernels<M, F>, const M: usize, const F: usize>(
    jobs: &[AnalysisJob<L, M, F>],
    options: &Options,
    results: &mut [Result<Analysis<M, F, L::Points>, Error>],
) {
    // The iterations stay where they start; those still running are
    // named by their place there (no iteration moved as others end).
    let mut newtons = Vec::with_capacity(jobs.len());
    for (job, result) in jobs.iter().zip(results.iter_mut()) {
        let fused_serves = match fused_serves(&job.vdot, &job.vddot, options) {
            Ok(serves) => serves,
            Err(error) => {
                *result = Err(error);
                continue;
            }
        };
        if !fused_serves || options.damped {
            *result = analyze(
                &job.model,
                &job.u_guess,
                &job.v,
                &job.vdot,
                &job.vddot,
                options,
            );
            continue;
        }
        match newton::FusedNewton::start(&job.model, &job.u_guess, &job.v, options) {
            Ok(newton) => newtons.push((job, result, newton)),
            Err(error) => *result = Err(error),
        }
    }
    let mut running: Vec<usize> = (0..newtons.len()).collect();
    // Each round's evaluations, written over those of the round before
    // (the jobs still running are never more).
    let mut evaluations = Vec::new();
    while !running.is_empty() {
        let requests: Vec<FusedRequest<'_, L, M, F>> = (running.iter())
            .map(|&n| {
                let (job, _, newton) = &newtons[n];
                let (u, trig_u, trig_v) = newton.pose();
                FusedRequest {
                    model: &job.model,
                    u,
                    v: &job.v,
                    trig_u,
                    trig_v,
                    vdot: &job.vdot,
                    vddot: &job.vddot,
                    rates: newton.may_end(),
                }
            })
            .collect();
        evaluations.resize_with(requests.len(), Kinematics::unevaluated);
        L::kinematics_with_trig_each(&requests, &mut evaluations);
        drop(requests);
        let mut evaluated = evaluations.iter();
        running.retain(|&n| {
            let (job, result, newton) = &mut newtons[n];
            let Some(k) = evaluated.next() else {
                return true;
            };
            match newton.advance(&job.model, k, options) {
                Progress::Evaluate => true,
                Progress::Done(ended) => {
                    **result = ended.and_then(|converged| {
                        finish_fused(
                            &job.model, converged, k, &job.v, &job.vdot, &job.vddot, options,
                        )
                    });
                    false
                }
            }
        });
    }
}

/// Whether the fused kernel serves for these drivers' rates (its numbers
/// ordinary, with the generated Jacobians and the fused γ), the rates
/// checked.
fn fused_serves<const F: usize>(
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<bool, Error> {
    check_input("vdot", vdot.as_slice())?;
    check_input("vddot", vddot.as_slice())?;
    // The fused kernel where its numbers are ordinary; the separate
    // solves, which scale γ and check for underflow, at the extremes.
    Ok(options.jacobian == JacobianSource::Generated
        && options.method == AccelerationMethod::Fused
        && ordinary(vdot.amax(), true)
        && ordinary(vddot.amax(), true))
}

/// The analysis of a pose Newton found on the fused kernel: its
/// velocities and accelerations from the evaluation that confirmed it.
#[inline(always)]
fn finish_fused<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    (position, trig): newton::Converged<M, F>,
    k: &Kinematics<M, F>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<Analysis<M, F, L::Points>, Error> {
    let fused = fused_kinematics(k, vdot, vddot, options)?;
    finish(model, position, fused, Some(trig), v, vdot, vddot, options)
}

/// The analysis of a pose found: the velocities and accelerations (those
/// of the fused kernel, `fused`, or by the separate solves), then the
/// points.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn finish<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    position: Position<M>,
    fused: Option<(Velocity<M, F>, SVector<f64, M>)>,
    trig: Option<PoseTrig<M, F>>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<Analysis<M, F, L::Points>, Error> {
    let u = position.u;
    let (velocity, uddot) = if let Some(fused) = fused {
        fused
    } else {
        let velocity = velocity_with(model, &position.psi_u, &u, v, vdot, options)?;
        let uddot = acceleration_with(
            model,
            &position.psi_u,
            &u,
            v,
            &velocity.udot,
            vdot,
            vddot,
            options,
        )?;
        (velocity, uddot)
    };
    let udot = &velocity.udot;
    // The points in one pass on the sines and cosines the analysis
    // computed at this pose, where it has them; else level by level.
    let [points, point_velocities, point_accelerations] = match &trig {
        Some(pose) if pose.u == u => {
            let flags = (model.point_trig_u(), model.point_trig_v());
            let (trig_u, trig_v) = pose.completed(&u, v, flags, (model.trig_u(), model.trig_v()));
            model.point_motion_with_trig(&u, v, udot, vdot, &uddot, vddot, &trig_u, &trig_v)
        }
        _ => [
            model.point_positions(&u, v),
            model.point_velocities(&u, v, udot, vdot),
            model.point_accelerations(&u, v, udot, vdot, &uddot, vddot),
        ],
    };
    for (quantity, p) in [
        ("P", &points),
        ("Ṗ", &point_velocities),
        ("P̈", &point_accelerations),
    ] {
        if !p.as_ref().iter().all(|x| x.iter().all(|c| c.is_finite())) {
            return Err(Error::NonFiniteValue {
                stage: Stage::Points,
                quantity,
            });
        }
    }
    Ok(Analysis {
        u,
        udot: velocity.udot,
        uddot,
        ratios: velocity.ratios,
        points,
        point_velocities,
        point_accelerations,
        iterations: position.iterations,
        residual: position.residual,
        rcond: velocity.rcond,
        v: *v,
        vdot: *vdot,
        vddot: *vddot,
        trig,
    })
}

/// `Linkage::velocity`: the inputs checked, Ψ_u evaluated, then
/// [`velocity_with`].
pub(crate) fn velocity<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    options: &Options,
) -> Result<Velocity<M, F>, Error> {
    check_input("u", u.as_slice())?;
    check_input("v", v.as_slice())?;
    check_input("vdot", vdot.as_slice())?;
    options.check()?;
    let psi_u = sources::psi_and_psi_u(model, options.jacobian, u, v).1;
    velocity_with(model, &psi_u, u, v, vdot, options)
}

/// `Linkage::acceleration`: the inputs checked, Ψ_u evaluated, then
/// [`acceleration_with`].
#[allow(clippy::too_many_arguments)]
pub(crate) fn acceleration<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<SVector<f64, M>, Error> {
    for (name, values) in [("u", u.as_slice()), ("udot", udot.as_slice())] {
        check_input(name, values)?;
    }
    for (name, values) in [
        ("v", v.as_slice()),
        ("vdot", vdot.as_slice()),
        ("vddot", vddot.as_slice()),
    ] {
        check_input(name, values)?;
    }
    options.check()?;
    let psi_u = sources::psi_and_psi_u(model, options.jacobian, u, v).1;
    acceleration_with(model, &psi_u, u, v, udot, vdot, vddot, options)
}

fn velocity_with<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    psi_u: &SMatrix<f64, M, M>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    options: &Options,
) -> Result<Velocity<M, F>, Error> {
    let psi_v = sources::psi_v(model, options.jacobian, u, v);
    check_value(Stage::Velocity, "Ψ_v", psi_v.as_slice())?;
    check_scale(Stage::Velocity, psi_u, &psi_v)?;
    let factors = factor(psi_u, model.psi_u_blocks(), Stage::Velocity, options)?;
    let ratios = factors.solve_columns(&psi_v);
    let udot = -(ratios * vdot);
    check_value(Stage::Velocity, "u̇", udot.as_slice())?;
    // The size of the terms of u̇ = −R v̇, ‖R‖·|v̇| (as log₂, which cannot
    // underflow), must be a normal number.
    let terms = if ratios.amax() > 0.0 && vdot.amax() > 0.0 {
        ratios.amax().log2() + vdot.amax().log2()
    } else {
        f64::NEG_INFINITY
    };
    check_result(Stage::Velocity, "u̇", terms)?;
    Ok(Velocity {
        udot,
        ratios,
        rcond: factors.rcond(),
    })
}

/// A magnitude the fused kernel handles with full precision: within
/// 10^±60, or zero where `zero_ok`.
#[inline(always)]
fn ordinary(x: f64, zero_ok: bool) -> bool {
    (zero_ok && x == 0.0) || (1e-60..=1e60).contains(&x)
}

/// Velocities and accelerations from one fused generated evaluation `k`
/// at the solved pose, with the same conditioning checks as the separate
/// solves; `None` where the results are extreme (nonzero and outside
/// 10^±60), which the separate solves handle with their scaling and
/// underflow checks.
#[inline]
fn fused_kinematics<const M: usize, const F: usize>(
    k: &Kinematics<M, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<Option<(Velocity<M, F>, SVector<f64, M>)>, Error> {
    check_value(Stage::Velocity, "Ψ_v", k.psi_v.as_slice())?;
    let (smallest, largest) = check_scale(Stage::Velocity, &k.psi_u, &k.psi_v)?;
    options.require_accuracy(Stage::Velocity, k.rcond)?;
    check_value(Stage::Velocity, "u̇", k.udot.as_slice())?;
    acceleration_conditioning(&k.psi_u, &k.psi_v, k.rcond, options)?;
    check_value(Stage::Acceleration, "ü", k.uddot.as_slice())?;
    // Every row and column of [Ψ_u Ψ_v], and u̇ and ü, within 10^±60 (zero
    // only where the drivers are at rest): then no product in the kernel,
    // of at most a few such factors, comes near the subnormal range, and
    // the result keeps its precision. Anything else goes to the separate
    // solves, which scale and check.
    let at_rest = vdot.amax() == 0.0;
    let geometry = ordinary(smallest, false) && ordinary(largest, false);
    let still = at_rest && vddot.amax() == 0.0;
    if !(geometry && ordinary(k.udot.amax(), at_rest) && ordinary(k.uddot.amax(), still)) {
        return Ok(None);
    }
    let velocity = Velocity {
        udot: k.udot,
        ratios: k.factors.solve_columns(&k.psi_v),
        rcond: k.rcond,
    };
    Ok(Some((velocity, k.uddot)))
}

#[allow(clippy::too_many_arguments)]
fn acceleration_with<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    psi_u: &SMatrix<f64, M, M>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<SVector<f64, M>, Error> {
    let factors = Factors::of(psi_u, model.psi_u_blocks());
    let psi_v = sources::psi_v(model, options.jacobian, u, v);
    check_value(Stage::Acceleration, "Ψ_v", psi_v.as_slice())?;
    check_scale(Stage::Acceleration, psi_u, &psi_v)?;
    acceleration_conditioning(psi_u, &psi_v, factors.rcond(), options)?;
    // ü = −Ψ_u⁻¹Ψ_v v̈ − Ψ_u⁻¹γ, each part computed at unit scale and
    // scaled back by powers of two (exact): γ is quadratic in the
    // velocities, γ(q̇) = s²·γ(q̇/s), and the v̈ part linear in v̈, so that
    // no intermediate underflows or overflows however small or large the
    // velocities, the accelerations or the mechanism. In the normal range
    // every scaling is exact and the result is the plain formula's, bit for
    // bit up to the order of the sums.
    let s = power_of_two_near(udot.amax().max(vdot.amax()));
    let (udot, vdot) = (udot / s, vdot / s);
    let generated = || sources::generated_gamma(model, options.method, u, v, &udot, &vdot);
    let gamma_unit = sources::gamma(model, options.jacobian, generated, u, v, &udot, &vdot);
    check_value(Stage::Acceleration, "γ", gamma_unit.as_slice())?;
    let t = power_of_two_near(vddot.amax());
    let from_gamma = factors.solve(&gamma_unit);
    let from_vddot = factors.solve(&(psi_v * (vddot / t)));
    check_value(Stage::Acceleration, "ü", from_gamma.as_slice())?;
    check_value(Stage::Acceleration, "ü", from_vddot.as_slice())?;
    // The size of the terms ü is made of, as log₂ (no underflow): ‖Ψ_u⁻¹‖
    // times ‖Ψ_v‖·|v̈| and times γ's terms, second derivatives of Ψ (sized
    // by its first, ‖[Ψ_u Ψ_v]‖) times |q̇|². Not ü's own size: γ's terms
    // may cancel (a rhombus's do, exactly), and ü with them, to far less
    // than the precision they leave; what must be a normal number is the
    // scale of that precision.
    let inverse_log2 = factors.inverse_size().log2();
    let vddot_terms = if from_vddot.amax() > 0.0 {
        inverse_log2 + psi_v.amax().log2() + vddot.amax().log2()
    } else {
        f64::NEG_INFINITY
    };
    let gamma_terms = if udot.amax().max(vdot.amax()) > 0.0 {
        inverse_log2
            + psi_u.amax().max(psi_v.amax()).log2()
            + 2.0 * (udot.amax().max(vdot.amax()).log2() + s.log2())
    } else {
        f64::NEG_INFINITY
    };
    check_result(Stage::Acceleration, "ü", vddot_terms.max(gamma_terms))?;
    let uddot = -(from_vddot * t + from_gamma * s * s);
    check_value(Stage::Acceleration, "ü", uddot.as_slice())?;
    Ok(uddot)
}

/// Whether an acceleration solve keeps [`Options::accuracy`]. Far from
/// singular poses ε·κ³ ≤ accuracy settles it. Nearer, the amplification is
/// ε·κ²·κ_q, with κ_q the condition number of [Ψ_u Ψ_v]: about 1 at a limit
/// position (where accelerations stay accurate as long as velocities do)
/// and about κ at a branch point (where they degrade first).
pub(crate) fn acceleration_conditioning<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
    rcond: f64,
    options: &Options,
) -> Result<(), Error> {
    if options.keeps_accuracy(Stage::Acceleration, rcond) {
        return Ok(());
    }
    acceleration_conditioning_with(
        psi_u,
        psi_v,
        rcond,
        options.min_rcond(Stage::Acceleration),
        options,
    )
}

/// [`acceleration_conditioning`] with the threshold ε·κ³ ≤ accuracy already
/// worked out (`fast`).
pub(crate) fn acceleration_conditioning_with<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
    rcond: f64,
    fast: f64,
    options: &Options,
) -> Result<(), Error> {
    if rcond > 0.0 && rcond >= fast {
        return Ok(());
    }
    let needed = if rcond > 0.0 {
        (f64::EPSILON * augmented_condition(psi_u, psi_v) / options.accuracy)
            .sqrt()
            .min(fast)
    } else {
        fast
    };
    if rcond > 0.0 && rcond >= needed {
        Ok(())
    } else {
        Err(Error::Singular {
            stage: Stage::Acceleration,
            rcond,
            min_rcond: needed,
        })
    }
}

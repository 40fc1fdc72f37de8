//! Criterion benchmarks of the sensitivities to the parameters:
//! at one converged pose (θ2 = 20°, ω2 = 1, α2 = 0), side by side, the
//! fused kinematics kernel and a warm analysis for reference, then the
//! exact sensitivities of positions, velocities and accelerations and of
//! every point's (u_p, u̇_p, ü_p, dP/dp, dṖ/dp, dP̈/dp) three ways:
//!
//! - ours: `Sensitivities::sensitivities` (the generated `sensitivity_terms`
//!   and the solves with Ψ_u⁻¹), `sensitivities_of` at the analysis, which
//!   takes the pose's sines and cosines from it, and `sensitivity_terms`
//!   alone;
//! - num-dual with k dual directions: the parameters as `DualSVec64<K>`
//!   through the generated `psi_generic_params`, the derivative parts solved
//!   with Ψ_u⁻¹ order by order (positions on the vector duals, velocities on
//!   `Dual` over them, accelerations on `Dual2` over them: Ψ is linear in
//!   the highest derivative, so one evaluation and one solve per order),
//!   the points through `point_positions_generic_params` on `Dual2`;
//! - forward differences: k + 1 warm analyses (the nominal design and one
//!   per perturbed parameter, each from the nominal pose), differenced.
//!
//! for the worksheet's four-bar (k = 4: l1..l4; bare, as in the kernels
//! benchmark, and with its five named points) and the two-loop six-bar with
//! k = 9 of its dimensions (every length and the fixed pivot's position;
//! the angle β held fixed). The setup checks, outside the timed loops, that
//! num-dual agrees with ours to 1e-12 (relative to each group's size) and the
//! differences to their own truncation error, so that all three compute the
//! same thing.
//!
//!     cargo bench --bench sensitivities            # all
//!     cargo bench --bench sensitivities -- "k = 9"  # one group
//!
//! A last group times the sensitivities of every pose of a dense sweep of
//! the bare four-bar: from scratch at each pose, and by
//! `sweep_sensitivities_each`, which carries the poses' sines and cosines.
//!
//! The kernels themselves are `cargo bench --bench kernels`.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::num_dual::{Dual, Dual2, DualSVec64};
use linkage::prelude::*;
use std::hint::black_box;
use std::time::Duration;

#[path = "../examples/speed_accuracy/workloads.rs"]
mod workloads;
use workloads::FOUR_BAR;

/// The worksheet's four-bar with its named points (`linkage::mechanisms::
/// FourBar`, written here so that its generated code is compiled where it
/// is used, as the workloads' mechanisms are).
#[linkage::linkage(
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
    ],
)]
#[derive(Clone, Copy, Debug)]
struct PointedFourBar {
    l1: f64,
    l2: f64,
    l3: f64,
    l4: f64,
}

const POINTED_FOUR_BAR: PointedFourBar = PointedFourBar {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
};

/// The workloads' two-loop six-bar with nine parameters: every length and
/// the fixed pivot (gx, gy); the angle β of E on the coupler is not one.
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        E = (B.x + e * (theta3 + beta).cos(), B.y + e * (theta3 + beta).sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
        E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
    ],
    params = [l1, l2, l3, l4, e, l5, l6, gx, gy],
)]
#[derive(Clone, Copy, Debug)]
struct SixBar9 {
    l1: f64,
    l2: f64,
    l3: f64,
    l4: f64,
    e: f64,
    beta: f64,
    l5: f64,
    l6: f64,
    gx: f64,
    gy: f64,
}

/// The workloads' six-bar (`workloads::SIX_BAR`).
const SIX_BAR_9: SixBar9 = SixBar9 {
    l1: 80.0,
    l2: 20.0,
    l3: 50.0,
    l4: 70.0,
    e: 40.0,
    beta: std::f64::consts::PI / 6.0,
    l5: 60.0,
    l6: 50.0,
    gx: 20.0,
    gy: 90.0,
};

/// The converged pose at θ2 = 20° with ω2 = 1, α2 = 0 (from a sweep from
/// `u0` near θ2 = 0, so on the benchmarks' branch, then a warm analysis).
fn motion<L: Linkage<M, 1>, const M: usize>(model: &L, u0: SVector<f64, M>) -> Motion<M, 1> {
    let v = vector![20f64.to_radians()];
    let (vdot, vddot) = (vector![1.0], vector![0.0]);
    let drive = Drive::Line {
        from: vector![0.0],
        to: v,
        steps: 200,
    };
    let sweep = model
        .sweep(&u0, &drive, &SweepOptions::default())
        .expect("the benchmark mechanisms sweep");
    let u = sweep.poses.last().expect("poses").u;
    let analysis = model
        .analyze(&u, &v, &vdot, &vddot, &Options::default())
        .expect("regular pose");
    Motion::of_analysis(&analysis)
}

/// The derivative part of a vector dual number (zero when num-dual left it
/// out).
#[inline(always)]
fn eps<const K: usize>(x: &DualSVec64<K>) -> SVector<f64, K> {
    x.eps.0.unwrap_or_else(SVector::zeros)
}

/// A vector dual number with the value `re` and the derivative part `eps`.
#[inline(always)]
fn dual<const K: usize>(re: f64, eps: SVector<f64, K>) -> DualSVec64<K> {
    DualSVec64::new(re, linkage::num_dual::Derivative::some(eps))
}

/// The same sensitivities by num-dual, the parameters as vector dual
/// numbers in k directions (one per parameter), from the converged pose:
///
/// 1. Ψ(p + ε, u, v) on `DualSVec64<K>` gives Ψ_p; u_p = −Ψ_u⁻¹Ψ_p.
/// 2. Ψ on `Dual<DualSVec64<K>>` (time direction over the parameters'),
///    u = (u + u_p ε, u̇), gives the parameters' part of Ψ̇ with u̇_p = 0,
///    which is Ψ̇_u u_p + Ψ̇_p; u̇_p = −Ψ_u⁻¹ of it (Ψ̇ is linear in u̇
///    through Ψ_u).
/// 3. Ψ on `Dual2<DualSVec64<K>>`, u = (u + u_p ε, u̇ + u̇_p ε, ü), gives
///    the parameters' part of Ψ̈ with ü_p = 0; ü_p = −Ψ_u⁻¹ of it.
/// 4. P on `Dual2<DualSVec64<K>>`, u = (u + u_p ε, u̇ + u̇_p ε, ü + ü_p ε):
///    dP/dp, dṖ/dp and dP̈/dp are the parameters' parts of its value and
///    of its first and second time derivatives.
///
/// Ψ_u is the generated `psi_u` (f64) inverted once with `linkage::invert`:
/// num-dual only for what needs derivatives by p.
fn by_num_dual<L, const M: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, 1>,
) -> Sensitivity<M, K, L::Points>
where
    L: Sensitivities<M, 1, K>,
{
    type Vel<const K: usize> = Dual<DualSVec64<K>>;
    type Acc<const K: usize> = Dual2<DualSVec64<K>>;
    let zero = DualSVec64::<K>::from_re(0.0);
    let p = model.params();
    let pd = SVector::<DualSVec64<K>, K>::from_fn(|i, _| DualSVec64::from_re(p[i]).derivative(i));
    let inv = linkage::invert(&model.psi_u(&motion.u, &motion.v));
    let inverse = inv.inverse;
    // 1. Positions.
    let u0 = motion.u.map(DualSVec64::<K>::from_re);
    let v0 = motion.v.map(DualSVec64::<K>::from_re);
    let r = model.psi_generic_params(&pd, &u0, &v0);
    let psi_p = SMatrix::<f64, M, K>::from_fn(|i, j| eps(&r[i])[j]);
    let u_p = -(inverse * psi_p);
    let u1 = SVector::<DualSVec64<K>, M>::from_fn(|i, _| dual(motion.u[i], u_p.row(i).transpose()));
    // 2. Velocities.
    let pv = pd.map(|x| Vel::new(x, zero));
    let uv =
        SVector::<Vel<K>, M>::from_fn(|i, _| Vel::new(u1[i], DualSVec64::from_re(motion.udot[i])));
    let vv = SVector::<Vel<K>, 1>::from_fn(|i, _| {
        Vel::new(
            DualSVec64::from_re(motion.v[i]),
            DualSVec64::from_re(motion.vdot[i]),
        )
    });
    let r = model.psi_generic_params(&pv, &uv, &vv);
    let rhs = SMatrix::<f64, M, K>::from_fn(|i, j| eps(&r[i].eps)[j]);
    let udot_p = -(inverse * rhs);
    // 3. Accelerations.
    let pa = pd.map(|x| Acc::new(x, zero, zero));
    let va = SVector::<Acc<K>, 1>::from_fn(|i, _| {
        Acc::new(
            DualSVec64::from_re(motion.v[i]),
            DualSVec64::from_re(motion.vdot[i]),
            DualSVec64::from_re(motion.vddot[i]),
        )
    });
    let mut ua = SVector::<Acc<K>, M>::from_fn(|i, _| {
        Acc::new(
            u1[i],
            dual(motion.udot[i], udot_p.row(i).transpose()),
            DualSVec64::from_re(motion.uddot[i]),
        )
    });
    let r = model.psi_generic_params(&pa, &ua, &va);
    let rhs = SMatrix::<f64, M, K>::from_fn(|i, j| eps(&r[i].v2)[j]);
    let uddot_p = -(inverse * rhs);
    // 4. The points.
    for i in 0..M {
        ua[i].v2 = dual(motion.uddot[i], uddot_p.row(i).transpose());
    }
    let template = model.point_positions(&motion.u, &motion.v);
    let mut points = [template; K];
    let mut point_velocities = [template; K];
    let mut point_accelerations = [template; K];
    let jets = model.point_positions_generic_params(&pa, &ua, &va);
    for (c, q) in jets.as_ref().iter().enumerate() {
        let (x, y) = (&q.x, &q.y);
        let (px, py) = (eps(&x.re), eps(&y.re));
        let (vx, vy) = (eps(&x.v1), eps(&y.v1));
        let (ax, ay) = (eps(&x.v2), eps(&y.v2));
        for j in 0..K {
            points[j].as_mut()[c] = Vector2::new(px[j], py[j]);
            point_velocities[j].as_mut()[c] = Vector2::new(vx[j], vy[j]);
            point_accelerations[j].as_mut()[c] = Vector2::new(ax[j], ay[j]);
        }
    }
    Sensitivity {
        u: u_p,
        udot: udot_p,
        uddot: uddot_p,
        points,
        point_velocities,
        point_accelerations,
        rcond: inv.rcond,
    }
}

/// The same sensitivities by forward differences of k + 1 warm analyses:
/// the nominal design and each parameter moved by h = √ε·max(|pⱼ|, 1),
/// each from the nominal pose.
fn by_differences<L, const M: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, 1>,
    options: &Options,
) -> Sensitivity<M, K, L::Points>
where
    L: Sensitivities<M, 1, K> + Clone,
{
    let (u, v, vdot, vddot) = (&motion.u, &motion.v, &motion.vdot, &motion.vddot);
    let nominal = model
        .analyze(u, v, vdot, vddot, options)
        .expect("regular pose");
    let p = model.params();
    let mut su = SMatrix::<f64, M, K>::zeros();
    let mut sudot = SMatrix::<f64, M, K>::zeros();
    let mut suddot = SMatrix::<f64, M, K>::zeros();
    let mut points = [nominal.points; K];
    let mut point_velocities = [nominal.points; K];
    let mut point_accelerations = [nominal.points; K];
    let mut shifted = model.clone();
    for j in 0..K {
        let h = f64::EPSILON.sqrt() * p[j].abs().max(1.0);
        let mut q = p;
        q[j] += h;
        shifted.set_params(&q);
        let a = shifted
            .analyze(&nominal.u, v, vdot, vddot, options)
            .expect("the shifted design assembles");
        let step = q[j] - p[j];
        su.set_column(j, &((a.u - nominal.u) / step));
        sudot.set_column(j, &((a.udot - nominal.udot) / step));
        suddot.set_column(j, &((a.uddot - nominal.uddot) / step));
        let difference = |target: &mut L::Points, plus: &L::Points, base: &L::Points| {
            for ((t, x), y) in target
                .as_mut()
                .iter_mut()
                .zip(plus.as_ref())
                .zip(base.as_ref())
            {
                *t = (x - y) / step;
            }
        };
        difference(&mut points[j], &a.points, &nominal.points);
        difference(
            &mut point_velocities[j],
            &a.point_velocities,
            &nominal.point_velocities,
        );
        difference(
            &mut point_accelerations[j],
            &a.point_accelerations,
            &nominal.point_accelerations,
        );
    }
    Sensitivity {
        u: su,
        udot: sudot,
        uddot: suddot,
        points,
        point_velocities,
        point_accelerations,
        rcond: nominal.rcond,
    }
}

/// The worst difference of `other` from `ours` over the six groups (u_p,
/// u̇_p, ü_p, dP/dp, dṖ/dp, dP̈/dp), each relative to the group's largest
/// entry in `ours`.
fn worst_difference<const M: usize, const K: usize, P: AsRef<[Vector2<f64>]>>(
    ours: &Sensitivity<M, K, P>,
    other: &Sensitivity<M, K, P>,
) -> f64 {
    let relative = |a: Vec<f64>, b: Vec<f64>| -> f64 {
        let size = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let diff = a
            .iter()
            .zip(&b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        if size > 0.0 { diff / size } else { diff }
    };
    let flat = |columns: &[P; K]| -> Vec<f64> {
        columns
            .iter()
            .flat_map(|c| c.as_ref().iter().flat_map(|x| [x.x, x.y]))
            .collect()
    };
    let matrix = |m: &SMatrix<f64, M, K>| m.iter().copied().collect::<Vec<_>>();
    [
        relative(matrix(&ours.u), matrix(&other.u)),
        relative(matrix(&ours.udot), matrix(&other.udot)),
        relative(matrix(&ours.uddot), matrix(&other.uddot)),
        relative(flat(&ours.points), flat(&other.points)),
        relative(flat(&ours.point_velocities), flat(&other.point_velocities)),
        relative(
            flat(&ours.point_accelerations),
            flat(&other.point_accelerations),
        ),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

/// The benchmarks of one mechanism at its pose at θ2 = 20°; `u0` starts the
/// sweep to it near θ2 = 0.
fn mechanism<L, const M: usize, const K: usize>(
    c: &mut Criterion,
    name: &str,
    model: &L,
    u0: SVector<f64, M>,
) where
    L: Sensitivities<M, 1, K> + Clone,
{
    let m = motion(model, u0);
    let options = Options::default();
    // The three compute the same thing: checked once, outside the timing.
    let ours = model.sensitivities(&m, &options).expect("regular pose");
    let dual = by_num_dual(model, &m);
    let worst = worst_difference(&ours, &dual);
    assert!(
        worst <= 1e-12,
        "{name}: num-dual differs from ours by {worst:e}"
    );
    let differences = by_differences(model, &m, &options);
    let worst_fd = worst_difference(&ours, &differences);
    assert!(
        worst_fd <= 1e-5,
        "{name}: the differences differ from ours by {worst_fd:e}"
    );
    eprintln!(
        "{name}: num-dual agrees with ours to {worst:.1e}, forward differences to {worst_fd:.1e} (relative to each group's size)"
    );

    let (u, v, vdot, vddot) = (m.u, m.v, m.vdot, m.vddot);
    let mut group = c.benchmark_group(name);
    group.bench_function("kinematics (fused kernel)", |b| {
        b.iter(|| model.kinematics(black_box(&u), black_box(&v), &vdot, &vddot))
    });
    group.bench_function("analyze warm", |b| {
        b.iter(|| {
            model
                .analyze(black_box(&u), black_box(&v), &vdot, &vddot, &options)
                .expect("regular pose")
        })
    });
    group.bench_function("sensitivity_terms", |b| {
        b.iter(|| {
            model.sensitivity_terms(
                black_box(&u),
                black_box(&v),
                black_box(&m.udot),
                &vdot,
                black_box(&m.uddot),
                &vddot,
            )
        })
    });
    group.bench_function("sensitivities (ours)", |b| {
        b.iter(|| {
            model
                .sensitivities(black_box(&m), &options)
                .expect("regular pose")
        })
    });
    let analysis = model
        .analyze(&m.u, &m.v, &m.vdot, &m.vddot, &options)
        .expect("regular pose");
    group.bench_function("sensitivities_of (ours, at the analysis)", |b| {
        b.iter(|| {
            model
                .sensitivities_of(black_box(&analysis), &options)
                .expect("regular pose")
        })
    });
    group.bench_function("num-dual (k directions)", |b| {
        b.iter(|| by_num_dual(model, black_box(&m)))
    });
    group.bench_function("forward differences (k + 1 analyses)", |b| {
        b.iter(|| by_differences(model, black_box(&m), &options))
    });
    group.finish();
}

/// The sensitivities of every pose of a dense sweep (the workloads' grid,
/// 2π/1 008 000 per step, 2 000 steps from θ2 = 0.3): the sweep alone, the
/// sweep with each pose's sensitivities from scratch or by num-dual, and
/// `sweep_sensitivities_each`, which carries the poses' sines and cosines.
fn dense_sweep(c: &mut Criterion) {
    const STEPS: usize = 2_000;
    let model = FOUR_BAR;
    let step = std::f64::consts::TAU / 1_008_000.0;
    let drive = Drive::Line {
        from: vector![0.3],
        to: vector![0.3 + STEPS as f64 * step],
        steps: STEPS,
    };
    let options = SweepOptions::default();
    let u0 = vector![1.2, -0.9];
    let mut group = c.benchmark_group("k = 4 four-bar, dense sweep of 2 001 poses");
    group.bench_function("sweep_each alone", |b| {
        b.iter(|| {
            model
                .sweep_each(black_box(&u0), &drive, &options, |pose| {
                    black_box(pose);
                })
                .expect("the sweep runs")
        })
    });
    group.bench_function("sweep_each + sensitivities from scratch", |b| {
        b.iter(|| {
            model
                .sweep_each(black_box(&u0), &drive, &options, |pose| {
                    let motion = Motion::of_sweep_pose(pose);
                    black_box(
                        model
                            .sensitivities(&motion, &options.options)
                            .expect("regular"),
                    );
                })
                .expect("the sweep runs")
        })
    });
    group.bench_function("sweep_each + num-dual (k directions)", |b| {
        b.iter(|| {
            model
                .sweep_each(black_box(&u0), &drive, &options, |pose| {
                    black_box(by_num_dual(&model, &Motion::of_sweep_pose(pose)));
                })
                .expect("the sweep runs")
        })
    });
    group.bench_function(
        "sweep_sensitivities_each (carried sines and cosines)",
        |b| {
            b.iter(|| {
                model
                    .sweep_sensitivities_each(black_box(&u0), &drive, &options, |pose, s| {
                        black_box((pose, s.expect("regular")));
                    })
                    .expect("the sweep runs")
            })
        },
    );
    group.finish();
}

fn benches(c: &mut Criterion) {
    let four_bar = linkage::closed_form::FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    }
    .position(0.0, 1.0)
    .expect("assembles");
    let four_bar = vector![four_bar[0], four_bar[1]];
    mechanism(c, "k = 4 four-bar", &FOUR_BAR, four_bar);
    mechanism(
        c,
        "k = 4 four-bar with 5 points",
        &POINTED_FOUR_BAR,
        four_bar,
    );
    mechanism(
        c,
        "k = 9 six-bar",
        &SIX_BAR_9,
        vector![1.369_438_4, -0.775_193_4, 2.237_243_8, -3.043_485_2],
    );
    dense_sweep(c);
}

criterion_group! {
    name = sensitivities;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30);
    targets = benches
}
criterion_main!(sensitivities);

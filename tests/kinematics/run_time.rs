//! Run-time mechanisms against their compiled twins: the same attribute
//! text, compiled by the macro and read at run time into tapes, gives the
//! same numbers to the bit — every kernel at random poses and rates, and
//! the analyses (a pose, a sweep with its singular poses) built on them.

use crate::common::twins::{
    attribute, every_kernel, every_sensitivity_kernel, same, same_points, same_sensitivity,
};
use crate::models::{
    BOOM, FIVE_BAR, SIX_BAR, SLIDER_CRANK, STEPHENSON_THREE, SixBar, SliderCrank, StephensonThree,
    WATT_SIX_BAR, WattSixBar,
};
use linkage::mechanism::{Fixed, Mechanism, MechanismError};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use proptest::prelude::*;

/// The twin of a compiled mechanism: its attribute read at run time, with
/// the compiled mechanism's parameter values.
fn twin<L, const M: usize, const F: usize, const K: usize>(
    compiled: &L,
    source: &str,
    name: &str,
) -> Fixed<M, F>
where
    L: Sensitivities<M, F, K>,
{
    read::<L, M, F, K>(compiled, source, name)
        .fixed::<M, F>()
        .expect("the compiled sizes")
}

/// The twin read, before it is seen at sizes.
fn read<L, const M: usize, const F: usize, const K: usize>(
    compiled: &L,
    source: &str,
    name: &str,
) -> Mechanism
where
    L: Sensitivities<M, F, K>,
{
    let values = compiled.params();
    let parameters: Vec<(&str, f64)> = (compiled.param_names().iter().copied())
        .zip(values.iter().copied())
        .collect();
    Mechanism::from_text(name, attribute(source, name), &parameters)
        .unwrap_or_else(|e| panic!("{name} reads at run time: {e}"))
}

/// u, v, u̇, v̇, ü, v̈ as lists.
type Motion6 = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

/// A pose in motion: every coordinate and rate in [−4, 4).
fn motion<const M: usize, const F: usize>() -> impl Strategy<Value = Motion6> {
    let numbers = |n: usize| proptest::collection::vec(-4.0..4.0f64, n);
    (
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
        numbers(M),
        numbers(F),
    )
}

macro_rules! twins {
    ($($test:ident: $model:expr, $name:literal, $source:literal, $m:literal, $f:literal, $k:literal;)*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig { cases: 200, failure_persistence: None, ..ProptestConfig::default() })]
            #[test]
            fn $test((u, v, udot, vdot, uddot, vddot) in motion::<$m, $f>()) {
                let compiled = $model;
                let twin = twin::<_, $m, $f, $k>(&compiled, include_str!($source), $name);
                let vector = |x: &[f64]| SVector::<f64, $m>::from_column_slice(x);
                let driver = |x: &[f64]| SVector::<f64, $f>::from_column_slice(x);
                every_kernel(
                    &compiled, &twin,
                    &vector(&u), &driver(&v), &vector(&udot), &driver(&vdot), &vector(&uddot), &driver(&vddot),
                );
                let sensitive = read::<_, $m, $f, $k>(&compiled, include_str!($source), $name)
                    .sensitive::<$m, $f, $k>()
                    .expect("the compiled sizes");
                let motion = Motion {
                    u: vector(&u), v: driver(&v), udot: vector(&udot), vdot: driver(&vdot),
                    uddot: vector(&uddot), vddot: driver(&vddot),
                };
                every_sensitivity_kernel(&compiled, &sensitive, &motion);
            }
        }
    )*};
}

twins! {
    the_worksheets_four_bar: FourBar::WORKSHEET, "FourBar", "../../src/mechanisms.rs", 2, 1, 4;
    the_slider_crank: SLIDER_CRANK, "SliderCrank", "../models/slider_crank.rs", 2, 1, 3;
    the_five_bar: FIVE_BAR, "FiveBar", "../models/five_bar.rs", 2, 2, 5;
    the_boom: BOOM, "Boom", "../models/boom.rs", 2, 1, 4;
    the_six_bar: SIX_BAR, "SixBar", "../models/six_bar.rs", 4, 1, 10;
    the_watt_six_bar: WATT_SIX_BAR, "WattSixBar", "../models/watt_six_bar.rs", 4, 1, 10;
    the_stephenson_three: STEPHENSON_THREE, "StephensonThree", "../models/stephenson_three.rs", 4, 1, 11;
}

/// The analyses on the two: a pose analysed, and a sweep through the
/// worksheet's whole turn, pose by pose the same to the bit.
#[test]
fn a_sweep_of_the_twin_is_the_compiled_sweep() {
    let compiled = FourBar::WORKSHEET;
    let twin = twin::<_, 2, 1, 4>(
        &compiled,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    let options = Options::default();
    let (u0, v0) = (vector![1.2, -0.9], vector![0.35]);
    let a = compiled
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    let b = twin
        .analyze(&u0, &v0, &vector![41.9], &vector![0.0], &options)
        .unwrap();
    same("analysis.u", &a.u, &b.u);
    same("analysis.uddot", &a.uddot, &b.uddot);
    same_points("analysis.points", a.points.as_ref(), b.points.as_ref());
    let drive = Drive::Line {
        from: vector![0.35],
        to: vector![0.35 + std::f64::consts::TAU],
        steps: 720,
    };
    let sweep_options = SweepOptions::default();
    let a = compiled.sweep(&u0, &drive, &sweep_options).unwrap();
    let b = twin.sweep(&u0, &drive, &sweep_options).unwrap();
    assert_eq!(a.poses.len(), b.poses.len());
    for (p, q) in a.poses.iter().zip(&b.poses) {
        same("pose.v", &p.v, &q.v);
        same("pose.u", &p.u, &q.u);
        same("pose.udot", &p.udot, &q.udot);
        same("pose.uddot", &p.uddot, &q.uddot);
    }
    assert_eq!(a.events.len(), b.events.len());
    assert_eq!(a.complete, b.complete);
}

/// A batch of analyses of run-time mechanisms, whose Newton iterations
/// run side by side on the tapes' lanes: every result the job's own
/// `analyze`, to the bit, and the compiled twin's — designs of one
/// mechanism (couplers of 40 … 59, one that assembles nowhere) at poses
/// round the turn, a second mechanism's jobs between them (a run of
/// lanes ends there), rates so small the separate solves take over, a
/// guess not finite; plain and damped Newton.
#[test]
fn a_batch_on_lanes_is_each_job_alone() {
    use linkage::batch::{self, AnalysisJob};
    let compiled = FourBar::WORKSHEET;
    let read = read::<_, 2, 1, 4>(
        &compiled,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    let other = twin::<_, 2, 1, 3>(
        &SLIDER_CRANK,
        include_str!("../models/slider_crank.rs"),
        "SliderCrank",
    );
    let mut jobs = Vec::new();
    let mut twins = Vec::new();
    for k in 0..60 {
        let mut design = read.clone();
        let mut bar = compiled;
        bar.l3 = 40.0 + (k % 20) as f64;
        if k % 20 == 7 {
            bar.l2 = 500.0;
        }
        design.set_parameter("l3", bar.l3).unwrap();
        design.set_parameter("l2", bar.l2).unwrap();
        let model = design.fixed::<2, 1>().unwrap();
        let vdot = match k {
            13 => 1e-70,
            _ => 41.9,
        };
        let u_guess = match k {
            29 => vector![f64::INFINITY, 0.0],
            _ => vector![1.2, -0.8],
        };
        let v = vector![(7.0 * k as f64).to_radians()];
        twins.push(AnalysisJob {
            model: bar,
            u_guess,
            v,
            vdot: vector![vdot],
            vddot: vector![5.0],
        });
        jobs.push(AnalysisJob {
            model,
            u_guess,
            v,
            vdot: vector![vdot],
            vddot: vector![5.0],
        });
    }
    for options in [Options::default(), Options::damped()] {
        let batch = batch::analyses(&jobs, &options);
        let compiled = batch::analyses(&twins, &options);
        for (k, ((job, result), twin)) in jobs.iter().zip(&batch).zip(&compiled).enumerate() {
            let alone = job
                .model
                .analyze(&job.u_guess, &job.v, &job.vdot, &job.vddot, &options);
            assert_eq!(result, &alone, "job {k}");
            match (result, twin) {
                (Ok(a), Ok(b)) => {
                    same("u", &a.u, &b.u);
                    same("udot", &a.udot, &b.udot);
                    same("uddot", &a.uddot, &b.uddot);
                    same_points("points", a.points.as_ref(), b.points.as_ref());
                    assert_eq!(a.iterations, b.iterations);
                }
                (Err(a), Err(b)) => assert_eq!(a, b, "job {k}"),
                _ => panic!("job {k}: {result:?} at run time, {twin:?} compiled"),
            }
        }
        assert!(batch[7].is_err() && batch[29].is_err() && batch[0].is_ok() && batch[13].is_ok());
    }
    // Another mechanism's jobs between the four-bar's: every third job,
    // then ten in a row (on lanes: its Ψ_u has a structural zero).
    let mixed: Vec<_> = (0..40)
        .map(|k| match (k, k % 3) {
            (30.., _) | (_, 2) => AnalysisJob {
                model: other.clone(),
                u_guess: vector![0.3, 0.1],
                v: vector![0.7 * k as f64],
                vdot: vector![3.0],
                vddot: vector![0.0],
            },
            _ => jobs[k].clone(),
        })
        .collect();
    let options = Options::default();
    let batch = batch::analyses(&mixed, &options);
    for (k, (job, result)) in mixed.iter().zip(&batch).enumerate() {
        let alone = job
            .model
            .analyze(&job.u_guess, &job.v, &job.vdot, &job.vddot, &options);
        assert_eq!(result, &alone, "job {k}");
    }
    assert!(batch[2].is_ok() && batch[5].is_ok() && batch[30..].iter().all(Result::is_ok));
}

/// A view differentiated by some parameters only, in its own order, with
/// room for more: its columns are the full view's, to the bit, and the
/// rest zero; its sensitivities along a sweep are the compiled ones'.
#[test]
fn a_view_by_chosen_parameters_has_their_columns() {
    let compiled = FourBar::WORKSHEET;
    let mechanism = read::<_, 2, 1, 4>(
        &compiled,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    let full = mechanism.sensitive::<2, 1, 4>().unwrap();
    let chosen = mechanism
        .differentiated_by::<2, 1, 32, 6>(&["l3", "l1"])
        .unwrap();
    assert_eq!(chosen.param_names(), ["l3", "l1", "", "", "", ""]);
    same(
        "params",
        &chosen.params(),
        &vector![compiled.l3, compiled.l1, 0.0, 0.0, 0.0, 0.0],
    );
    let motion = Motion {
        u: vector![1.2, -0.9],
        v: vector![0.35],
        udot: vector![0.7, -0.2],
        vdot: vector![41.9],
        uddot: vector![3.0, 1.5],
        vddot: vector![0.0],
    };
    let options = Options::default();
    let a = full.sensitivities(&motion, &options).unwrap();
    let b = chosen.sensitivities(&motion, &options).unwrap();
    for (view, of_full) in [(0, 2), (1, 0)] {
        same(
            "u_p",
            &a.u.column(of_full).into_owned(),
            &b.u.column(view).into_owned(),
        );
        same(
            "ü_p",
            &a.uddot.column(of_full).into_owned(),
            &b.uddot.column(view).into_owned(),
        );
        same_points("dP/dp", a.points[of_full].as_ref(), b.points[view].as_ref());
    }
    for view in 2..6 {
        assert!(b.u.column(view).iter().all(|x| *x == 0.0));
        assert!(
            b.points[view]
                .as_ref()
                .iter()
                .all(|p| *p == Vector2::zeros())
        );
    }
    // Setting the parameters sets the chosen ones, in the view's order.
    let mut moved = chosen.clone();
    moved.set_params(&vector![0.5, 2.5, 9.0, 9.0, 9.0, 9.0]);
    assert_eq!(moved.params(), vector![0.5, 2.5, 0.0, 0.0, 0.0, 0.0]);
    let l = |name: &str| {
        let k = moved
            .parameter_names()
            .iter()
            .position(|n| *n == name)
            .unwrap();
        moved.parameters()[k]
    };
    assert_eq!(
        (l("l1"), l("l2"), l("l3"), l("l4")),
        (2.5, compiled.l2, 0.5, compiled.l4)
    );

    // Along a sweep, the sensitivities of every pose are the compiled ones.
    let drive = Drive::Line {
        from: vector![0.35],
        to: vector![0.35 + std::f64::consts::TAU],
        steps: 180,
    };
    let mut expected = Vec::new();
    compiled
        .sweep_sensitivities_each(
            &vector![1.2, -0.9],
            &drive,
            &SweepOptions::default(),
            |_, s| expected.push(s),
        )
        .unwrap();
    let mut poses = 0;
    full.sweep_sensitivities_each(
        &vector![1.2, -0.9],
        &drive,
        &SweepOptions::default(),
        |_, s| {
            same_sensitivity(&expected[poses], &s);
            poses += 1;
        },
    )
    .unwrap();
    assert_eq!(poses, expected.len());
}

/// Views the mechanism cannot give are typed errors that say why.
#[test]
fn views_by_parameters_refuse_what_the_mechanism_has_not() {
    let text = "u = [theta3, theta4], v = [theta2], params = [l2, l3],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() - l4 * theta4.cos() - l1,
            l2 * theta2.sin() + l3 * theta3.sin() - l4 * theta4.sin(),
        ]";
    let values = [("l1", 4.0), ("l2", 1.0), ("l3", 3.0), ("l4", 3.5)];
    let mechanism = Mechanism::from_text("Bar", text, &values).unwrap();
    let message = |r: Result<Fixed<2, 1, 32, 4>, MechanismError>| r.unwrap_err().to_string();
    assert_eq!(
        message(mechanism.differentiated_by(&["l4"])),
        "the mechanism is not differentiated by `l4` (it is not in its `params`); \
         it is differentiated by: l2, l3"
    );
    assert_eq!(
        message(mechanism.differentiated_by(&["l2", "l2"])),
        "the parameter `l2` is named twice"
    );
    assert!(
        message(mechanism.differentiated_by(&["l9"]))
            .starts_with("the mechanism has no parameter `l9`")
    );
    assert_eq!(
        mechanism
            .differentiated_by::<2, 1, 32, 1>(&["l2", "l3"])
            .unwrap_err()
            .to_string(),
        "2 parameters asked for; this view holds at most 1"
    );
    assert_eq!(
        mechanism.sensitive::<2, 1, 3>().unwrap_err().to_string(),
        "the mechanism is differentiated by 2 parameters, not 3"
    );
    assert!(mechanism.sensitive::<2, 1, 2>().is_ok());
}

/// Ψ_u's diagonal blocks, found from which entries are not identically
/// zero: the compiled table and the twin read from the same text say the
/// same, and a Watt six-bar is a four-bar driving a dyad (two blocks), a
/// Stephenson III one coupled block.
#[test]
fn psi_u_splits_into_the_same_blocks_compiled_and_at_run_time() {
    fn same_blocks<L: Sensitivities<M, F, K>, const M: usize, const F: usize, const K: usize>(
        compiled: &L,
        table: &SymbolicTable,
        source: &str,
        name: &str,
    ) -> String {
        let twin = read::<_, M, F, K>(compiled, source, name);
        let sentence = twin.blocks().to_string();
        assert!(
            table.structure.starts_with(&sentence),
            "{name}: `{}` against `{sentence}`",
            table.structure
        );
        // The order the analyses invert Ψ_u by: the generated constant and
        // the run-time program's, the same lists.
        let fixed = twin.fixed::<M, F>().expect("the compiled sizes");
        assert_eq!(compiled.psi_u_blocks(), fixed.psi_u_blocks(), "{name}");
        // Every entry the factors do not read is zero, at any pose.
        let u = SVector::<f64, M>::from_fn(|i, _| 0.3 + 0.7 * i as f64);
        let v = SVector::<f64, F>::repeat(0.9);
        assert!(
            compiled.psi_u_blocks().fits(&compiled.psi_u(&u, &v)),
            "{name}"
        );
        assert_eq!(
            compiled.psi_u_blocks().len(),
            twin.blocks().blocks().len().max(1),
            "{name}"
        );
        sentence
    }
    let four_bar = same_blocks::<_, 2, 1, 4>(
        &FourBar::WORKSHEET,
        &FourBar::SYMBOLIC,
        include_str!("../../src/mechanisms.rs"),
        "FourBar",
    );
    assert_eq!(four_bar, "Ψ_u is one dense block of 2×2");
    assert_eq!(
        FourBar::WORKSHEET.psi_u_blocks(),
        linkage::PsiUBlocks::DENSE
    );
    let slider = same_blocks::<_, 2, 1, 3>(
        &SLIDER_CRANK,
        &SliderCrank::SYMBOLIC,
        include_str!("../models/slider_crank.rs"),
        "SliderCrank",
    );
    assert_eq!(slider, "Ψ_u is block lower triangular: 2 blocks of 1×1");
    same_blocks::<_, 4, 1, 10>(
        &SIX_BAR,
        &SixBar::SYMBOLIC,
        include_str!("../models/six_bar.rs"),
        "SixBar",
    );
    same_blocks::<_, 4, 1, 10>(
        &WATT_SIX_BAR,
        &WattSixBar::SYMBOLIC,
        include_str!("../models/watt_six_bar.rs"),
        "WattSixBar",
    );
    assert_eq!(
        WattSixBar::SYMBOLIC.structure,
        "Ψ_u is block lower triangular: 2 blocks of 2×2, solved in the order [θ3, θ4], [θ5, θ6]."
    );
    let watt: Vec<_> = WattSixBar::PSI_U_BLOCKS.blocks().collect();
    assert_eq!(
        watt,
        [(&[0, 1][..], &[0, 1][..]), (&[2, 3][..], &[2, 3][..])]
    );
    let stephenson = same_blocks::<_, 4, 1, 11>(
        &STEPHENSON_THREE,
        &StephensonThree::SYMBOLIC,
        include_str!("../models/stephenson_three.rs"),
        "StephensonThree",
    );
    assert_eq!(stephenson, "Ψ_u is one dense block of 4×4");
}

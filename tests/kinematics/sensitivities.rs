//! The sensitivities to the parameters, against numbers computed elsewhere:
//! num-dual with the parameters as dual numbers, central finite
//! differences, and the 50-digit references of mpmath; the scaling
//! identity of the four-bar.

use crate::common::OMEGA2;
use crate::common::sensitivity::{Column, by_differences, by_dual};
use crate::common::twins::same_positions;
use crate::models::{BOOM, FIVE_BAR, SIX_BAR, SLIDER_CRANK};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;

/// The pose of `model` near `u_guess` at v with its motion, and its
/// sensitivities.
fn at<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u_guess: SVector<f64, M>,
    v: SVector<f64, F>,
    vdot: SVector<f64, F>,
    vddot: SVector<f64, F>,
) -> (Motion<M, F>, Sensitivity<M, K, L::Points>)
where
    L: Sensitivities<M, F, K>,
{
    let options = Options::default();
    let analysis = model
        .analyze(&u_guess, &v, &vdot, &vddot, &options)
        .expect("the pose assembles");
    let motion = Motion::of_analysis(&analysis);
    let s = model
        .sensitivities(&motion, &options)
        .expect("a regular pose has sensitivities");
    (motion, s)
}

/// Every column of the library's sensitivities against num-dual's, to
/// `tolerance` relative to each group's size.
fn agrees_with_dual<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, F>,
    s: &Sensitivity<M, K, L::Points>,
    tolerance: f64,
) where
    L: Sensitivities<M, F, K>,
{
    for j in 0..K {
        let ours = Column::of(s, j);
        let dual = by_dual(model, motion, j);
        let worst = ours.difference(&dual, 1e-300);
        assert!(
            worst.iter().all(|&d| d <= tolerance),
            "∂/∂{}: u, u̇, ü, points differ from num-dual by {worst:?}\nours {ours:?}\ndual {dual:?}",
            model.param_names()[j]
        );
    }
}

#[test]
fn the_worksheets_fourbar_agrees_with_num_dual_around_the_cycle() {
    let model = FourBar::WORKSHEET;
    let mut u = vector![1.2, -0.9];
    for step in 0..36 {
        let theta2 = step as f64 * 10f64.to_radians() + 0.05;
        let (motion, s) = at(&model, u, vector![theta2], vector![OMEGA2], vector![3.0]);
        u = motion.u;
        agrees_with_dual(&model, &motion, &s, 2e-14);
    }
}

#[test]
fn the_slider_crank_boom_six_bar_and_five_bar_agree_with_num_dual() {
    for step in 0..12 {
        let t = step as f64 * 0.5 + 0.1;
        let (motion, s) = at(
            &SLIDER_CRANK,
            vector![0.0, 0.24],
            vector![t],
            vector![OMEGA2],
            vector![-2.0],
        );
        agrees_with_dual(&SLIDER_CRANK, &motion, &s, 2e-14);
        let (motion, s) = at(
            &SIX_BAR,
            vector![1.2, -0.9, 0.5, -1.0],
            vector![0.35 + 0.1 * t],
            vector![1.0],
            vector![0.5],
        );
        agrees_with_dual(&SIX_BAR, &motion, &s, 2e-14);
        let (motion, s) = at(
            &FIVE_BAR,
            vector![1.0, 2.0],
            vector![1.4 + 0.05 * t, 1.6 - 0.05 * t],
            vector![1.0, -0.5],
            vector![0.3, 0.2],
        );
        agrees_with_dual(&FIVE_BAR, &motion, &s, 2e-14);
    }
    for length in [0.8, 1.0, 1.2, 1.4] {
        let (motion, s) = at(
            &BOOM,
            vector![1.0, 1.2],
            vector![length],
            vector![0.1],
            vector![0.02],
        );
        agrees_with_dual(&BOOM, &motion, &s, 2e-14);
    }
}

/// The pose's sines and cosines, where the masks ask for them.
fn trig_of<const N: usize>(x: &SVector<f64, N>, mask: &[bool; N]) -> [(f64, f64); N] {
    std::array::from_fn(|k| if mask[k] { x[k].sin_cos() } else { (0.0, 0.0) })
}

/// The terms with the pose's own sines and cosines handed over are the very
/// numbers of the terms that compute them (==), for a mechanism with points,
/// one with a slider, one with two loops and one with two drivers; the
/// masks say which are read.
#[test]
fn the_terms_with_the_poses_sines_and_cosines_given_are_the_same_numbers() {
    fn same<L, const M: usize, const F: usize, const K: usize>(model: &L, motion: &Motion<M, F>)
    where
        L: Sensitivities<M, F, K>,
    {
        let m = motion;
        let computed = model.sensitivity_terms(&m.u, &m.v, &m.udot, &m.vdot, &m.uddot, &m.vddot);
        let (trig_u, trig_v) = (
            trig_of(&m.u, &model.sensitivity_trig_u()),
            trig_of(&m.v, &model.sensitivity_trig_v()),
        );
        let given = model.sensitivity_terms_with_trig(
            &m.u, &m.v, &trig_u, &trig_v, &m.udot, &m.vdot, &m.uddot, &m.vddot,
        );
        assert_eq!(given, computed);
    }
    let four_bar = FourBar::WORKSHEET;
    let (motion, _) = at(
        &four_bar,
        vector![1.2, -0.9],
        vector![0.4],
        vector![OMEGA2],
        vector![3.0],
    );
    same(&four_bar, &motion);
    assert_eq!(FourBar::SENSITIVITY_TRIG_U, [true, true]);
    assert_eq!(FourBar::SENSITIVITY_TRIG_V, [true]);
    let (motion, _) = at(
        &SLIDER_CRANK,
        vector![0.0, 0.24],
        vector![0.6],
        vector![OMEGA2],
        vector![-2.0],
    );
    same(&SLIDER_CRANK, &motion);
    // The slider's position s is under no sine or cosine.
    assert_eq!(
        crate::models::SliderCrank::SENSITIVITY_TRIG_U,
        [true, false]
    );
    let (motion, _) = at(
        &SIX_BAR,
        vector![1.2, -0.9, 0.5, -1.0],
        vector![0.4],
        vector![1.0],
        vector![0.5],
    );
    same(&SIX_BAR, &motion);
    let (motion, _) = at(
        &FIVE_BAR,
        vector![1.0, 2.0],
        vector![1.45, 1.55],
        vector![1.0, -0.5],
        vector![0.3, 0.2],
    );
    same(&FIVE_BAR, &motion);
}

/// At an analysis, `sensitivities_of` takes the drivers the analysis was
/// given and gives the very numbers (==) of `sensitivities` at its motion,
/// at the pose the analysis found and at one its caller moved. That the
/// first reads the sines and cosines the analysis kept, and the second
/// computes them, is shown inside the runtime (`src/runtime/sensitivities/tests.rs`),
/// where the kept ones are visible: here both paths give the same numbers.
#[test]
fn at_an_analysis_the_sensitivities_are_those_of_its_motion() {
    fn same<L, const M: usize, const F: usize, const K: usize>(
        model: &L,
        u_guess: SVector<f64, M>,
        v: SVector<f64, F>,
        vdot: SVector<f64, F>,
        vddot: SVector<f64, F>,
    ) where
        L: Sensitivities<M, F, K>,
    {
        let options = Options::default();
        let analysis = model
            .analyze(&u_guess, &v, &vdot, &vddot, &options)
            .expect("the pose assembles");
        let motion = Motion::of_analysis(&analysis);
        assert_eq!(
            motion,
            Motion {
                u: analysis.u,
                v,
                udot: analysis.udot,
                vdot,
                uddot: analysis.uddot,
                vddot,
            }
        );
        let given = model
            .sensitivities_of(&analysis, &options)
            .expect("regular");
        assert_eq!(
            given,
            model.sensitivities(&motion, &options).expect("regular")
        );
        // Its pose moved (its fields are the caller's): the sines and
        // cosines of the pose it found are not those of this one.
        let mut moved = analysis;
        moved.u = analysis.u.map(|x| x + 1e-3);
        let at_moved = model.sensitivities_of(&moved, &options);
        assert_eq!(
            at_moved,
            model.sensitivities(&Motion::of_analysis(&moved), &options)
        );
        assert_ne!(at_moved, Ok(given));
        // The positions' alone are theirs, at both.
        let positions = model.position_sensitivities_of(&analysis, &options);
        same_positions(&Ok(given), &positions);
        // Their det Ψ_u is that of Ψ_u at the pose, factored, to the bit.
        let psi_u = model.psi_u(&analysis.u, &v);
        let det = linkage::Factors::of(&psi_u, model.psi_u_blocks()).det();
        assert_eq!(positions.expect("regular").det.to_bits(), det.to_bits());
        same_positions(
            &at_moved,
            &model.position_sensitivities_of(&moved, &options),
        );
    }
    same(
        &FourBar::WORKSHEET,
        vector![1.2, -0.9],
        vector![0.4],
        vector![OMEGA2],
        vector![3.0],
    );
    same(
        &SLIDER_CRANK,
        vector![0.0, 0.24],
        vector![0.6],
        vector![OMEGA2],
        vector![-2.0],
    );
    same(
        &SIX_BAR,
        vector![1.2, -0.9, 0.5, -1.0],
        vector![0.4],
        vector![1.0],
        vector![0.5],
    );
    same(
        &FIVE_BAR,
        vector![1.0, 2.0],
        vector![1.45, 1.55],
        vector![1.0, -0.5],
        vector![0.3, 0.2],
    );
}

/// A dense sweep carries its sines and cosines from pose to pose into the
/// sensitivities (`sweep_sensitivities_each`): every pose's agree with those
/// computed from scratch to a few ulps.
#[test]
fn a_dense_sweep_carries_its_sines_and_cosines_into_the_sensitivities() {
    let model = FourBar::WORKSHEET;
    let drive = Drive::Line {
        from: vector![0.3],
        to: vector![0.8],
        steps: 5_000,
    };
    let options = SweepOptions::default();
    let mut worst = [0.0f64; 4];
    let mut poses = 0;
    model
        .sweep_sensitivities_each(&vector![1.2, -0.9], &drive, &options, |pose, carried| {
            let carried = carried.expect("a regular pose has sensitivities");
            let motion = Motion::of_sweep_pose(pose);
            let computed = model
                .sensitivities(&motion, &options.options)
                .expect("a regular pose has sensitivities");
            for j in 0..4 {
                let d = Column::of(&carried, j).difference(&Column::of(&computed, j), 1e-300);
                for (w, d) in worst.iter_mut().zip(d) {
                    *w = w.max(d);
                }
            }
            poses += 1;
        })
        .expect("the sweep runs");
    assert_eq!(poses, 5_001);
    // Measured: 6.9e-16 (u_p), 1.7e-15 (u̇_p), 2.8e-15 (ü_p), 2.3e-15
    // (points), 2026-11-23: the carried sines and cosines are as accurate
    // as `sin_cos`, to a few ulps.
    assert!(
        worst.iter().all(|&d| d <= 5e-15),
        "carried against computed: {worst:?}"
    );
}

/// Central differences agree to what their step leaves (truncation h²
/// against rounding ε/h): 7e-11 to 7e-10 of the terms at h = 1e-5 (measured
/// 2026-11-23), 7e-5 to 7e-4 at h = 1e-2 — the digits exact derivatives
/// keep.
#[test]
fn central_differences_agree_to_their_own_error() {
    let model = FourBar::WORKSHEET;
    let (motion, s) = at(
        &model,
        vector![1.2, -0.9],
        vector![20f64.to_radians()],
        vector![OMEGA2],
        vector![0.0],
    );
    let mut best = [0.0f64; 4];
    let mut coarse = [0.0f64; 4];
    for j in 0..4 {
        let exact = Column::of(&s, j);
        let fine = by_differences(&model, &motion, j, 1e-5).difference(&exact, 1e-300);
        let rough = by_differences(&model, &motion, j, 1e-2).difference(&exact, 1e-300);
        for g in 0..4 {
            best[g] = best[g].max(fine[g]);
            coarse[g] = coarse[g].max(rough[g]);
        }
    }
    assert!(best.iter().all(|&d| d < 1e-7), "h = 1e-5: {best:?}");
    assert!(
        best.iter().all(|&d| d > 1e-14),
        "differences cannot be exact: {best:?}"
    );
    assert!(
        coarse.iter().all(|&d| d > 1e-7),
        "h = 1e-2 loses digits: {coarse:?}"
    );
}

/// Scaling every length of the four-bar by (1 + ε) leaves its angles, and
/// their rates, unchanged: Σ lᵢ ∂θ/∂lᵢ = 0, and likewise for ω and α,
/// while each point moves with the scale: Σ lᵢ ∂P/∂lᵢ = P.
#[test]
fn scaling_every_length_changes_no_angle() {
    let model = FourBar::WORKSHEET;
    let l = model.params();
    let mut u = vector![1.2, -0.9];
    for step in 0..24 {
        let theta2 = step as f64 * 15f64.to_radians() + 0.01;
        let options = Options::default();
        let a = model
            .analyze(
                &u,
                &vector![theta2],
                &vector![OMEGA2],
                &vector![2.0],
                &options,
            )
            .unwrap();
        u = a.u;
        let motion = Motion::of_analysis(&a);
        let s = model.sensitivities(&motion, &options).unwrap();
        for (name, matrix) in [("θ", s.u), ("ω", s.udot), ("α", s.uddot)] {
            let sum = matrix * l;
            // To rounding of the largest term lᵢ ∂θ/∂lᵢ (measured: at most
            // 3ε of it).
            let terms = (0..4)
                .map(|j| (matrix.column(j) * l[j]).amax())
                .fold(0.0, f64::max);
            assert!(
                sum.amax() <= 6.0 * f64::EPSILON * terms,
                "Σ l ∂{name}/∂l = {sum:?} at θ2 = {theta2} (terms {terms})"
            );
        }
        for c in 0..FourBar::POINT_NAMES.len() {
            let moved = s.point(c) * l;
            let p = a.points[c];
            assert!(
                (moved - p).amax() <= 1e-13 * 80.0,
                "Σ l ∂P/∂l = {moved:?}, P = {p:?}"
            );
        }
    }
}

/// One mechanism's rows of `tests/data/sensitivities.csv`: the driver's
/// position, speed and acceleration, and per (quantity, parameter) the
/// value, velocity and acceleration (parameter "-") or their derivatives.
struct Reference {
    driver: [f64; 3],
    rows: Vec<(String, String, [f64; 3])>,
}

fn reference(mechanism: &str) -> Reference {
    let text = include_str!("../data/sensitivities.csv");
    let mut driver = None;
    let mut rows = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let fields: Vec<&str> = line.split(',').collect();
        if fields[0] != mechanism {
            continue;
        }
        let values = [3, 4, 5].map(|k| fields[k].parse::<f64>().expect("a number"));
        if fields[1] == "driver" {
            driver = Some(values);
        } else {
            rows.push((fields[1].to_owned(), fields[2].to_owned(), values));
        }
    }
    Reference {
        driver: driver.expect("the mechanism's driver row"),
        rows,
    }
}

/// The library's sensitivities of `model` against the 50-digit references:
/// the pose first (so that the branch is the reference's), then every
/// derivative of every coordinate and point by every parameter, each to
/// 1e-13 of the largest term of its row (the quantity's derivatives by all
/// the parameters at that order; the accuracy table's policy is 1e-12, the
/// worst measured 1.8e-14). Returns the worst figure.
fn against_reference<L, const M: usize, const K: usize>(
    model: &L,
    mechanism: &str,
    u_guess: SVector<f64, M>,
) -> f64
where
    L: Sensitivities<M, 1, K>,
{
    let r = reference(mechanism);
    let [v, vdot, vddot] = r.driver;
    let (motion, s) = at(model, u_guess, vector![v], vector![vdot], vector![vddot]);
    let analysis = model
        .analyze(
            &u_guess,
            &vector![v],
            &vector![vdot],
            &vector![vddot],
            &Options::default(),
        )
        .unwrap();
    // Ours: (value, velocity, acceleration) and, per parameter, their derivatives.
    let ours = |quantity: &str, param: Option<usize>| -> [f64; 3] {
        if let Some(i) = model.u_names().iter().position(|n| *n == quantity) {
            return match param {
                None => [motion.u[i], motion.udot[i], motion.uddot[i]],
                Some(j) => [s.u[(i, j)], s.udot[(i, j)], s.uddot[(i, j)]],
            };
        }
        let (point, axis) = quantity.split_once('.').expect("a point coordinate");
        let c = model.point_index(point).expect("a point of the model");
        let a = usize::from(axis == "y");
        match param {
            None => [
                analysis.points.as_ref()[c][a],
                analysis.point_velocities.as_ref()[c][a],
                analysis.point_accelerations.as_ref()[c][a],
            ],
            Some(j) => [
                s.point(c)[(a, j)],
                s.point_velocity(c)[(a, j)],
                s.point_acceleration(c)[(a, j)],
            ],
        }
    };
    let mut worst = 0.0f64;
    let mut checked = 0;
    for (quantity, param, expected) in &r.rows {
        let j = (param != "-").then(|| {
            model
                .param_index(param)
                .unwrap_or_else(|| panic!("{mechanism} has no parameter {param}"))
        });
        let got = ours(quantity, j);
        // The row's scale: the largest of the quantity's terms at each order.
        let scale = |order: usize| {
            r.rows
                .iter()
                .filter(|(q, p, _)| q == quantity && (p == "-") == j.is_none())
                .map(|(_, _, x)| x[order].abs())
                .fold(f64::MIN_POSITIVE, f64::max)
        };
        for order in 0..3 {
            let error = (got[order] - expected[order]).abs() / scale(order);
            assert!(
                error <= 1e-13,
                "{mechanism}: {quantity} by {param}, order {order}: {} against {} ({error:.1e} of its terms)",
                got[order],
                expected[order]
            );
            worst = worst.max(error);
            checked += 1;
        }
    }
    assert_eq!(checked, 3 * r.rows.len());
    assert!(
        r.rows.len() > 3 * K,
        "{mechanism}: only {} rows",
        r.rows.len()
    );
    worst
}

#[test]
fn the_worksheets_fourbar_against_the_50_digit_references() {
    let worst = against_reference(&FourBar::WORKSHEET, "fourbar", vector![1.2, -0.9]);
    assert!(worst <= 1e-14, "{worst:e}");
}

#[test]
fn the_slider_crank_against_the_50_digit_references() {
    against_reference(&SLIDER_CRANK, "slider_crank", vector![0.0, 0.24]);
}

#[test]
fn the_actuator_driven_boom_against_the_50_digit_references() {
    against_reference(&BOOM, "boom", vector![1.0, 1.2]);
}

#[test]
fn the_two_loop_six_bar_against_the_50_digit_references() {
    // The dyad's branch of the references (σ = +1): F to the left of E→G.
    against_reference(&SIX_BAR, "six_bar", vector![1.2, -0.9, 2.4, 3.1]);
}

/// A NaN or an infinity in the pose is refused, naming the first argument
/// that holds one (in the order u, u̇, ü, v, v̇, v̈) and where.
#[test]
fn a_non_finite_pose_is_named() {
    let model = FourBar::WORKSHEET;
    let (motion, _) = at::<_, 2, 1, 4>(
        &model,
        vector![1.2, -0.9],
        vector![0.4],
        vector![OMEGA2],
        vector![3.0],
    );
    let options = Options::default();
    let names = ["u", "udot", "uddot", "v", "vdot", "vddot"];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (k, name) in names.iter().enumerate() {
            let mut m = motion;
            match k {
                0 => m.u[1] = bad,
                1 => m.udot[1] = bad,
                2 => m.uddot[1] = bad,
                3 => m.v[0] = bad,
                4 => m.vdot[0] = bad,
                _ => m.vddot[0] = bad,
            }
            // A later argument bad too: the first is named.
            if k < 5 {
                m.vddot[0] = f64::NAN;
            }
            let index = if k < 3 { 1 } else { 0 };
            match model.sensitivities(&m, &options) {
                Err(Error::NonFiniteInput {
                    argument,
                    index: i,
                    value,
                }) => {
                    assert_eq!((argument, i), (*name, index));
                    assert!(value.is_nan() == bad.is_nan() && !value.is_finite());
                }
                other => panic!("{name} = {bad}: {other:?}"),
            }
        }
    }
}

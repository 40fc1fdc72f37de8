//! The sensitivities to the parameters, against numbers computed elsewhere:
//! num-dual with the parameters as dual numbers, central finite
//! differences, and the 50-digit references of mpmath; the scaling
//! identity of the four-bar.

mod common;

use common::sensitivity::{Column, by_differences, by_dual};
use common::{BOOM, FIVE_BAR, OMEGA2, SIX_BAR, SLIDER_CRANK};
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
    let motion = Motion::of_analysis(&analysis, &v, &vdot, &vddot);
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
            L::PARAM_NAMES[j]
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
        agrees_with_dual(&model, &motion, &s, 1e-13);
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
        agrees_with_dual(&SLIDER_CRANK, &motion, &s, 1e-13);
        let (motion, s) = at(
            &SIX_BAR,
            vector![1.2, -0.9, 0.5, -1.0],
            vector![0.35 + 0.1 * t],
            vector![1.0],
            vector![0.5],
        );
        agrees_with_dual(&SIX_BAR, &motion, &s, 1e-13);
        let (motion, s) = at(
            &FIVE_BAR,
            vector![1.0, 2.0],
            vector![1.4 + 0.05 * t, 1.6 - 0.05 * t],
            vector![1.0, -0.5],
            vector![0.3, 0.2],
        );
        agrees_with_dual(&FIVE_BAR, &motion, &s, 1e-13);
    }
    for length in [0.8, 1.0, 1.2, 1.4] {
        let (motion, s) = at(
            &BOOM,
            vector![1.0, 1.2],
            vector![length],
            vector![0.1],
            vector![0.02],
        );
        agrees_with_dual(&BOOM, &motion, &s, 1e-13);
    }
}

/// Central differences agree to what their step leaves (truncation h²
/// against rounding ε/h): about 1e-9 of the term at h = 1e-5, and far
/// worse at a step too small or too large — the digits exact derivatives
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
        let motion = Motion::of_analysis(&a, &vector![theta2], &vector![OMEGA2], &vector![2.0]);
        let s = model.sensitivities(&motion, &options).unwrap();
        for (name, matrix, scale) in [
            ("θ", s.u, 1.0),
            ("ω", s.udot, OMEGA2),
            ("α", s.uddot, OMEGA2 * OMEGA2),
        ] {
            let sum = matrix * l;
            // Each term lᵢ ∂θ/∂lᵢ is of order one (per unit of the rate).
            let terms = (0..4)
                .map(|j| (matrix.column(j) * l[j]).amax())
                .fold(0.0, f64::max);
            assert!(
                sum.amax() <= 4.0 * f64::EPSILON * terms.max(scale),
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

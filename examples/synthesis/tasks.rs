//! The tasks both tools are given: path generation through points of the
//! Maple worksheet's coupler curve of G3, without prescribed timing, and
//! Freudenstein's three precision points for y = log10 x.

use linkage::mechanisms::{CouplerFourBar, FourBar};
use linkage::nalgebra::Matrix3;
use linkage::prelude::*;
use linkage::synthesis::{Problem, Range, Requirements, SynthesisError, Timing};
use std::f64::consts::{PI, TAU};

/// The worksheet's assembly: Newton's start at θ2 = 0 (C above the ground
/// line).
pub const WORKSHEET_GUESS: [f64; 2] = [1.3, -0.8];

/// G3 of the worksheet's four-bar (P of [`CouplerFourBar::WORKSHEET`]) at
/// θ2 = 360°·k/n, k = 0 … n − 1: an exact solution exists.
pub fn path_targets(n: usize) -> Result<Vec<Vector2<f64>>, linkage::Error> {
    let bar = CouplerFourBar::WORKSHEET;
    let mut u = SVector::from(WORKSHEET_GUESS);
    (0..n)
        .map(|k| {
            let v = vector![TAU * k as f64 / n as f64];
            u = bar.solve_position(&u, &v, &Options::default())?.u;
            Ok(bar.point_positions(&u, &v)[CouplerFourBar::P])
        })
        .collect()
}

/// The bounds of both tools, from the targets' box (centre c, diagonal d):
/// the ground pivots within 2d of c in each coordinate, the links from
/// 0.05d to 2d, the coupler point within 2d of B in each coordinate of the
/// coupler's frame. In the order of [`CouplerFourBar::PARAM_NAMES`].
pub fn path_bounds(targets: &[Vector2<f64>]) -> [(&'static str, f64, f64); 9] {
    let (lo, hi) = targets
        .iter()
        .fold((targets[0], targets[0]), |(lo, hi), t| {
            (lo.inf(t), hi.sup(t))
        });
    let (c, d) = ((lo + hi) / 2.0, (hi - lo).norm());
    [
        ("xa", c.x - 2.0 * d, c.x + 2.0 * d),
        ("ya", c.y - 2.0 * d, c.y + 2.0 * d),
        ("xd", c.x - 2.0 * d, c.x + 2.0 * d),
        ("yd", c.y - 2.0 * d, c.y + 2.0 * d),
        ("l2", 0.05 * d, 2.0 * d),
        ("l3", 0.05 * d, 2.0 * d),
        ("l4", 0.05 * d, 2.0 * d),
        ("px", -2.0 * d, 2.0 * d),
        ("py", -2.0 * d, 2.0 * d),
    ]
}

/// Path generation: P through `targets` in their order over a turn, every
/// dimension free within [`path_bounds`], the timing free, each design on
/// the assembly Newton finds from the worksheet's guess at its first
/// target; precision points.
pub fn path_problem(
    targets: &[Vector2<f64>],
) -> Result<Problem<CouplerFourBar, 2, 9>, SynthesisError> {
    let mut problem = Problem::path(CouplerFourBar::WORKSHEET, "P", targets, Timing::Free)?;
    for (name, lower, upper) in path_bounds(targets) {
        problem = problem.free(name, lower, upper)?;
    }
    Ok(problem
        .guess(SVector::from(WORKSHEET_GUESS))
        .precision_points())
}

/// Freudenstein's task: y = log10 x on 1 ≤ x ≤ 10, the crank θ2 from 0° to
/// 60° and the rocker φ (the direction D→C) from 90° to 180°, both
/// linear in x and y; the ground 1 long.
pub struct FunctionTask {
    /// θ2 and φ at the three precision points.
    pub targets: [(f64, f64); 3],
}

/// The crank's and rocker's ranges.
pub const CRANK: (f64, f64) = (0.0, 60.0);
pub const ROCKER: (f64, f64) = (90.0, 180.0);

impl FunctionTask {
    /// Chebyshev's spacing of three points on 1 ≤ x ≤ 10.
    pub fn log10() -> FunctionTask {
        let targets = [1.0, 2.0, 3.0].map(|j: f64| {
            let x = 5.5 - 4.5 * (PI * (2.0 * j - 1.0) / 6.0).cos();
            FunctionTask::angles(x)
        });
        FunctionTask { targets }
    }

    /// What a design of this task is certified for: the crank's range
    /// swept whole, and no smallest transmission angle — the task as
    /// Freudenstein states it; its closed form's own design falls to 11.3°
    /// at θ2 = 0, which the default 40° would refuse.
    pub fn requirements() -> Requirements<'static, FourBar, 2> {
        let mut requirements = Requirements::new(Range::Task);
        requirements.min_transmission = 0.0;
        requirements
    }

    /// The crank's range, from one end to the other (radians).
    pub fn crank_range() -> (f64, f64) {
        (CRANK.0.to_radians(), CRANK.1.to_radians())
    }

    /// θ2 and the wanted φ at x.
    pub fn angles(x: f64) -> (f64, f64) {
        let theta = CRANK.0 + (CRANK.1 - CRANK.0) * (x - 1.0) / 9.0;
        let phi = ROCKER.0 + (ROCKER.1 - ROCKER.0) * x.log10();
        (theta.to_radians(), phi.to_radians())
    }

    /// The closed form: K1 cos φ − K2 cos θ + K3 = cos(θ − φ), K1 = d/a,
    /// K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac), linear in K; the
    /// lengths (crank a, coupler b, rocker c) for d = 1.
    pub fn closed_form(&self) -> Option<[f64; 3]> {
        let t = &self.targets;
        let a = Matrix3::from_fn(|i, j| [t[i].1.cos(), -t[i].0.cos(), 1.0][j]);
        let rhs = Vector3::from_fn(|i, _| (t[i].0 - t[i].1).cos());
        let k = a.lu().solve(&rhs)?;
        let (crank, rocker) = (1.0 / k[0], 1.0 / k[1]);
        let coupler = (crank * crank + rocker * rocker + 1.0 - 2.0 * crank * rocker * k[2]).sqrt();
        Some([crank, coupler, rocker])
    }

    /// Our problem: θ4 (the direction C→D, φ − π) at the three crank angles,
    /// the ground kept at 1, the links free from 0.1 to 5; precision points.
    pub fn problem(&self) -> Result<Problem<FourBar, 2, 4>, SynthesisError> {
        let start = FourBar {
            l1: 1.0,
            l2: 1.0,
            l3: 2.0,
            l4: 2.0,
        };
        let targets: Vec<(f64, f64)> = self.targets.iter().map(|t| (t.0, t.1 - PI)).collect();
        Ok(Problem::function(start, "theta4", &targets)?
            .free("l2", 0.1, 5.0)?
            .free("l3", 0.1, 5.0)?
            .free("l4", 0.1, 5.0)?
            .guess(vector![1.0, self.targets[0].1 - PI])
            .driver_range(FunctionTask::crank_range().0, FunctionTask::crank_range().1)?
            .precision_points())
    }
}

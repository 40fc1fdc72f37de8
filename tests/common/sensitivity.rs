//! Sensitivities computed another way, for the tests: by num-dual with the
//! parameters as dual numbers through the generated generic functions
//! (`psi_generic_params`, `point_positions_generic_params`), and by central
//! finite differences of whole analyses.

use linkage::SensitivityTerms;
use linkage::num_dual::{Dual2, Dual64};
use linkage::prelude::*;

/// Every sensitivity of a pose to one parameter, as flat lists: u_p, u̇_p,
/// ü_p, then for each point (x, y) of P, Ṗ, P̈.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    pub u: Vec<f64>,
    pub udot: Vec<f64>,
    pub uddot: Vec<f64>,
    pub points: Vec<[f64; 6]>,
}

impl Column {
    /// The column `j` of the library's result.
    pub fn of<const M: usize, const K: usize, P: AsRef<[Vector2<f64>]>>(
        s: &Sensitivity<M, K, P>,
        j: usize,
    ) -> Column {
        let points = (0..s.points[j].as_ref().len())
            .map(|c| {
                let (p, v, a) = (
                    s.points[j].as_ref()[c],
                    s.point_velocities[j].as_ref()[c],
                    s.point_accelerations[j].as_ref()[c],
                );
                [p.x, p.y, v.x, v.y, a.x, a.y]
            })
            .collect();
        Column {
            u: s.u.column(j).iter().copied().collect(),
            udot: s.udot.column(j).iter().copied().collect(),
            uddot: s.uddot.column(j).iter().copied().collect(),
            points,
        }
    }

    /// The largest absolute difference from `other`, of each group (u, u̇,
    /// ü, points).
    pub fn distance(&self, other: &Column) -> [f64; 4] {
        let max = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        };
        let flat = |p: &[[f64; 6]]| -> Vec<f64> { p.iter().flatten().copied().collect() };
        [
            max(&self.u, &other.u),
            max(&self.udot, &other.udot),
            max(&self.uddot, &other.uddot),
            max(&flat(&self.points), &flat(&other.points)),
        ]
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.u
            .iter()
            .chain(&self.udot)
            .chain(&self.uddot)
            .chain(self.points.iter().flatten())
            .all(|x| x.is_finite())
    }

    /// The worst relative difference from `reference`, of each group (u,
    /// u̇, ü, points), each relative to the size of its group in the
    /// reference (with `floor`).
    pub fn difference(&self, reference: &Column, floor: f64) -> [f64; 4] {
        let flat = |p: &[[f64; 6]], k: usize| -> Vec<f64> {
            p.iter().flat_map(|x| [x[2 * k], x[2 * k + 1]]).collect()
        };
        let points = (0..3)
            .map(|k| super::rel_norm(&flat(&self.points, k), &flat(&reference.points, k), floor))
            .fold(0.0, f64::max);
        [
            super::rel_norm(&self.u, &reference.u, floor),
            super::rel_norm(&self.udot, &reference.udot, floor),
            super::rel_norm(&self.uddot, &reference.uddot, floor),
            points,
        ]
    }
}

type Jet = Dual2<Dual64>;

/// The sensitivities to parameter `j` by num-dual: the parameters dual in
/// direction j; the derivative parts of the pose solved on those numbers
/// (Newton steps with Ψ_u⁻¹ on the derivative parts, the values kept as
/// given: the derivatives at this pose, as the library's); then the
/// velocity and the acceleration as the first and second time derivatives
/// of Ψ along the motion, on second-order numbers whose parts are
/// themselves dual in p, each solved order by order (u̇ and ü enter the
/// residual linearly, through Ψ_u, so a few fixed-point steps with the f64
/// inverse are exact).
pub fn by_dual<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, F>,
    j: usize,
) -> Column
where
    L: Sensitivities<M, F, K>,
{
    try_by_dual(model, motion, j).expect("a regular pose")
}

/// [`by_dual`], `None` where Ψ_u has no inverse.
pub fn try_by_dual<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, F>,
    j: usize,
) -> Option<Column>
where
    L: Sensitivities<M, F, K>,
{
    let p = model.params();
    let pd = SVector::<Dual64, K>::from_fn(|i, _| {
        let x = Dual64::from(p[i]);
        if i == j { x.derivative() } else { x }
    });
    let inverse = model.psi_u(&motion.u, &motion.v).try_inverse()?;
    let lift = |x: &SVector<f64, M>| x.map(Dual64::from);
    let solve = |x: SVector<Dual64, M>| -> SVector<Dual64, M> {
        SVector::from_fn(|i, _| {
            (0..M).fold(Dual64::from(0.0), |acc, k| acc + x[k] * inverse[(i, k)])
        })
    };
    // Derivative parts solved, values kept: x.re stays the given value.
    let keep = |x: &mut SVector<Dual64, M>, values: &SVector<f64, M>| {
        for i in 0..M {
            x[i] = Dual64::new(values[i], x[i].eps);
        }
    };
    // The position's derivative part, exact after one step.
    let mut u = lift(&motion.u);
    let vd = motion.v.map(Dual64::from);
    for _ in 0..2 {
        let r = model.psi_generic_params(&pd, &u, &vd);
        u -= solve(r);
        keep(&mut u, &motion.u);
    }
    // The velocity and the acceleration, order by order.
    let mut udot = lift(&motion.udot);
    let mut uddot = lift(&motion.uddot);
    let jet = |u: &SVector<Dual64, M>, udot: &SVector<Dual64, M>, uddot: &SVector<Dual64, M>| {
        SVector::<Jet, M>::from_fn(|i, _| Jet::new(u[i], udot[i], uddot[i]))
    };
    let vj = SVector::<Jet, F>::from_fn(|i, _| {
        Jet::new(
            Dual64::from(motion.v[i]),
            Dual64::from(motion.vdot[i]),
            Dual64::from(motion.vddot[i]),
        )
    });
    let pj = pd.map(Jet::from_re);
    for order in 1..=2 {
        for _ in 0..3 {
            let r = model.psi_generic_params(&pj, &jet(&u, &udot, &uddot), &vj);
            if order == 1 {
                udot -= solve(r.map(|x| x.v1));
                keep(&mut udot, &motion.udot);
            } else {
                uddot -= solve(r.map(|x| x.v2));
                keep(&mut uddot, &motion.uddot);
            }
        }
    }
    let points = model
        .point_positions_generic_params(&pj, &jet(&u, &udot, &uddot), &vj)
        .as_ref()
        .iter()
        .map(|q| {
            [
                q.x.re.eps, q.y.re.eps, q.x.v1.eps, q.y.v1.eps, q.x.v2.eps, q.y.v2.eps,
            ]
        })
        .collect();
    Some(Column {
        u: u.iter().map(|x| x.eps).collect(),
        udot: udot.iter().map(|x| x.eps).collect(),
        uddot: uddot.iter().map(|x| x.eps).collect(),
        points,
    })
}

/// The size of the terms each group of sensitivities to parameter `j` is
/// made of, before they cancel (u, u̇, ü, points): ‖Ψ_u⁻¹‖ times the sizes
/// of the right-hand sides, and for the points the sizes of their sums.
pub fn term_sizes<const M: usize, const K: usize, P: AsRef<[Vector2<f64>]>>(
    terms: &SensitivityTerms<M, K, P>,
    s: &Sensitivity<M, K, P>,
    j: usize,
) -> [f64; 4] {
    let inverse = linkage::invert(&terms.psi_u).inverse.amax() * M as f64;
    let (u, udot, uddot) = (
        s.u.column(j).amax(),
        s.udot.column(j).amax(),
        s.uddot.column(j).amax(),
    );
    let size = |points: &[P]| -> f64 {
        points
            .iter()
            .flat_map(|p| p.as_ref().iter().map(|x| x.amax()))
            .fold(0.0, f64::max)
    };
    let by_u = |points: &[P; M]| size(points.as_slice()) * M as f64;
    let by_p = |points: &[P; K]| size(&points[j..j + 1]);
    [
        inverse * terms.psi_p.column(j).amax(),
        inverse * (terms.psi_u_dot.amax() * u + terms.psi_p_dot.column(j).amax()),
        inverse
            * (terms.psi_u_ddot.amax() * u
                + 2.0 * terms.psi_u_dot.amax() * udot
                + terms.psi_p_ddot.column(j).amax()),
        (by_u(&terms.points_u) * u + by_p(&terms.points_p))
            .max(
                by_u(&terms.point_velocities_u) * u
                    + by_u(&terms.points_u) * udot
                    + by_p(&terms.point_velocities_p),
            )
            .max(
                by_u(&terms.point_accelerations_u) * u
                    + 2.0 * by_u(&terms.point_velocities_u) * udot
                    + by_u(&terms.points_u) * uddot
                    + by_p(&terms.point_accelerations_p),
            ),
    ]
}

/// The sensitivities to parameter `j` by central finite differences of
/// whole analyses, with the relative step `h` (each side re-solved from the
/// pose).
pub fn by_differences<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    motion: &Motion<M, F>,
    j: usize,
    h: f64,
) -> Column
where
    L: Sensitivities<M, F, K> + Clone,
{
    let p = model.params();
    let step = h * p[j].abs().max(1.0);
    let analyse = |sign: f64| {
        let mut shifted = model.clone();
        let mut q = p;
        q[j] += sign * step;
        shifted.set_params(&q);
        shifted
            .analyze(
                &motion.u,
                &motion.v,
                &motion.vdot,
                &motion.vddot,
                &Options::default(),
            )
            .expect("the shifted design assembles")
    };
    let (plus, minus) = (analyse(1.0), analyse(-1.0));
    let d = |a: f64, b: f64| (a - b) / (2.0 * step);
    let dv = |a: &SVector<f64, M>, b: &SVector<f64, M>| -> Vec<f64> {
        (0..M).map(|i| d(a[i], b[i])).collect()
    };
    let points = (0..plus.points.as_ref().len())
        .map(|c| {
            let (pp, mp) = (&plus, &minus);
            let (a, b) = (pp.points.as_ref()[c], mp.points.as_ref()[c]);
            let (av, bv) = (
                pp.point_velocities.as_ref()[c],
                mp.point_velocities.as_ref()[c],
            );
            let (aa, ba) = (
                pp.point_accelerations.as_ref()[c],
                mp.point_accelerations.as_ref()[c],
            );
            [
                d(a.x, b.x),
                d(a.y, b.y),
                d(av.x, bv.x),
                d(av.y, bv.y),
                d(aa.x, ba.x),
                d(aa.y, ba.y),
            ]
        })
        .collect();
    Column {
        u: dv(&plus.u, &minus.u),
        udot: dv(&plus.udot, &minus.udot),
        uddot: dv(&plus.uddot, &minus.uddot),
        points,
    }
}

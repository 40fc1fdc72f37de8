//! Which sines and cosines [`Sensitivities::sensitivities_of`] reads: the
//! ones an analysis kept at its pose (the default options' path), or its
//! own. Seen from inside the crate, where the kept ones are visible, on a
//! mechanism written out by hand that records which entry of its kernel
//! was called and with what.

use super::*;
use crate::runtime::kernels::Kernels;
use crate::runtime::options::{AccelerationMethod, JacobianSource};
use crate::runtime::results::Kinematics;
use crate::runtime::trig::PoseTrig;
use core::cell::Cell;
use nalgebra::{Matrix1, vector};

/// Which entry of the sensitivity kernel was called last.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Called {
    /// `sensitivity_terms`, which computes its sines and cosines.
    Computing,
    /// `sensitivity_terms_with_trig`, with these (sin θ, cos θ).
    Given(SinCos<1>),
}

/// Two cranks whose tips are at the same height: one of length r (the
/// parameter) at the angle θ (u), one of unit length at the driven angle φ
/// (v). Ψ = r sin θ − sin φ; one point, the first crank's tip
/// (r cos θ, r sin θ).
struct Tips {
    r: f64,
    called: Cell<Option<Called>>,
}

type Points = [Vector2<f64>; 1];

impl Tips {
    fn new(r: f64) -> Tips {
        Tips {
            r,
            called: Cell::new(None),
        }
    }

    /// [`Kernels::kinematics`] on the given sines and cosines.
    fn kinematics_on(
        &self,
        (s, c): (f64, f64),
        (s_phi, c_phi): (f64, f64),
        vdot: &SVector<f64, 1>,
        vddot: &SVector<f64, 1>,
    ) -> Kinematics<1, 1> {
        let r = self.r;
        let psi = vector![r * s - s_phi];
        let psi_u = Matrix1::new(r * c);
        let psi_v = Matrix1::new(-c_phi);
        let factors = crate::runtime::Factors::whole(&psi_u);
        let (rcond, det) = (factors.rcond(), factors.det());
        let udot = -factors.solve(&(psi_v * vdot));
        let gamma = vector![-r * s * udot[0].powi(2) + s_phi * vdot[0].powi(2)];
        let uddot = -factors.solve(&(psi_v * vddot + gamma));
        Kinematics {
            psi,
            psi_u,
            psi_v,
            factors,
            rcond,
            det,
            udot,
            uddot,
        }
    }

    /// The sensitivity terms on the given (sin θ, cos θ).
    fn terms_on(
        &self,
        (s, c): (f64, f64),
        udot: &SVector<f64, 1>,
        uddot: &SVector<f64, 1>,
    ) -> SensitivityTerms<1, 1, Points> {
        let (r, w, a) = (self.r, udot[0], uddot[0]);
        SensitivityTerms {
            psi_u: Matrix1::new(r * c),
            psi_p: Matrix1::new(s),
            psi_u_dot: Matrix1::new(-r * s * w),
            psi_p_dot: Matrix1::new(c * w),
            psi_u_ddot: Matrix1::new(-r * s * a - r * c * w * w),
            psi_p_ddot: Matrix1::new(c * a - s * w * w),
            points_u: [[Vector2::new(-r * s, r * c)]],
            points_p: [[Vector2::new(c, s)]],
            point_velocities_u: [[Vector2::new(-r * c * w, -r * s * w)]],
            point_velocities_p: [[Vector2::new(-s * w, c * w)]],
            point_accelerations_u: [[Vector2::new(
                r * s * w * w - r * c * a,
                -r * c * w * w - r * s * a,
            )]],
            point_accelerations_p: [[Vector2::new(-c * w * w - s * a, -s * w * w + c * a)]],
        }
    }
}

impl Kernels<1, 1> for Tips {
    type Points = Points;
    fn u_names(&self) -> [&'static str; 1] {
        ["theta"]
    }
    fn v_names(&self) -> [&'static str; 1] {
        ["phi"]
    }
    fn point_names(&self) -> &'static [&'static str] {
        &["tip"]
    }

    fn psi(&self, u: &SVector<f64, 1>, v: &SVector<f64, 1>) -> SVector<f64, 1> {
        vector![self.r * u[0].sin() - v[0].sin()]
    }
    fn psi_u(&self, u: &SVector<f64, 1>, _v: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        Matrix1::new(self.r * u[0].cos())
    }
    fn psi_v(&self, _u: &SVector<f64, 1>, v: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        Matrix1::new(-v[0].cos())
    }
    fn psi_and_psi_u(
        &self,
        u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
    ) -> (SVector<f64, 1>, SMatrix<f64, 1, 1>) {
        (self.psi(u, v), self.psi_u(u, v))
    }
    fn psi_u_udot_u(
        &self,
        u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        Matrix1::new(-self.r * u[0].sin() * udot[0])
    }
    fn psi_u_udot_v(
        &self,
        _u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        _udot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        Matrix1::zeros()
    }
    fn psi_v_vdot_u(
        &self,
        _u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        Matrix1::zeros()
    }
    fn psi_v_vdot_v(
        &self,
        _u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
        vdot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        Matrix1::new(v[0].sin() * vdot[0])
    }
    fn psi_u_dot(
        &self,
        u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        self.psi_u_udot_u(u, v, udot)
    }
    fn psi_v_dot(
        &self,
        u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
        _udot: &SVector<f64, 1>,
        vdot: &SVector<f64, 1>,
    ) -> SMatrix<f64, 1, 1> {
        self.psi_v_vdot_v(u, v, vdot)
    }
    fn gamma(
        &self,
        u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
        vdot: &SVector<f64, 1>,
    ) -> SVector<f64, 1> {
        vector![-self.r * u[0].sin() * udot[0].powi(2) + v[0].sin() * vdot[0].powi(2)]
    }
    fn kinematics(
        &self,
        u: &SVector<f64, 1>,
        v: &SVector<f64, 1>,
        vdot: &SVector<f64, 1>,
        vddot: &SVector<f64, 1>,
    ) -> Kinematics<1, 1> {
        self.kinematics_on(u[0].sin_cos(), v[0].sin_cos(), vdot, vddot)
    }
    fn trig_u(&self) -> [bool; 1] {
        [true]
    }
    fn trig_v(&self) -> [bool; 1] {
        [true]
    }
    fn kinematics_with_trig(
        &self,
        _u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        trig_u: &SinCos<1>,
        trig_v: &SinCos<1>,
        vdot: &SVector<f64, 1>,
        vddot: &SVector<f64, 1>,
    ) -> Kinematics<1, 1> {
        self.kinematics_on(trig_u[0], trig_v[0], vdot, vddot)
    }
    fn point_positions(&self, u: &SVector<f64, 1>, _v: &SVector<f64, 1>) -> Points {
        let (s, c) = u[0].sin_cos();
        [Vector2::new(self.r * c, self.r * s)]
    }
    fn point_velocities(
        &self,
        u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
    ) -> Points {
        let (s, c) = u[0].sin_cos();
        let (r, w) = (self.r, udot[0]);
        [Vector2::new(-r * s * w, r * c * w)]
    }
    fn point_accelerations(
        &self,
        u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
        uddot: &SVector<f64, 1>,
        _vddot: &SVector<f64, 1>,
    ) -> Points {
        let (s, c) = u[0].sin_cos();
        let (r, w, a) = (self.r, udot[0], uddot[0]);
        [Vector2::new(
            -r * c * w * w - r * s * a,
            -r * s * w * w + r * c * a,
        )]
    }
    fn psi_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, 1>,
        v: &SVector<D, 1>,
    ) -> SVector<D, 1> {
        self.psi_generic_params(&vector![D::from(self.r)], u, v)
    }
    fn point_positions_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, 1>,
        _v: &SVector<D, 1>,
    ) -> impl AsRef<[Vector2<D>]> {
        let r = D::from(self.r);
        [Vector2::new(r * u[0].cos(), r * u[0].sin())]
    }
}

impl Linkage<1, 1> for Tips {}

impl SensitivityKernel<1, 1, 1> for Tips {
    fn sensitivity_trig_u(&self) -> [bool; 1] {
        [true]
    }
    fn sensitivity_terms(
        &self,
        u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        udot: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
        uddot: &SVector<f64, 1>,
        _vddot: &SVector<f64, 1>,
    ) -> SensitivityTerms<1, 1, Points> {
        self.called.set(Some(Called::Computing));
        self.terms_on(u[0].sin_cos(), udot, uddot)
    }
    fn sensitivity_terms_with_trig(
        &self,
        _u: &SVector<f64, 1>,
        _v: &SVector<f64, 1>,
        trig_u: &SinCos<1>,
        _trig_v: &SinCos<1>,
        udot: &SVector<f64, 1>,
        _vdot: &SVector<f64, 1>,
        uddot: &SVector<f64, 1>,
        _vddot: &SVector<f64, 1>,
    ) -> SensitivityTerms<1, 1, Points> {
        self.called.set(Some(Called::Given(*trig_u)));
        self.terms_on(trig_u[0], udot, uddot)
    }
}

impl Sensitivities<1, 1, 1> for Tips {
    fn param_names(&self) -> [&'static str; 1] {
        ["r"]
    }
    fn params(&self) -> SVector<f64, 1> {
        vector![self.r]
    }
    fn set_params(&mut self, params: &SVector<f64, 1>) {
        self.r = params[0];
    }
    fn psi_p(&self, u: &SVector<f64, 1>, _v: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        Matrix1::new(u[0].sin())
    }
    fn psi_generic_params<D: DualNum<Primitive = f64> + Copy>(
        &self,
        params: &SVector<D, 1>,
        u: &SVector<D, 1>,
        v: &SVector<D, 1>,
    ) -> SVector<D, 1> {
        vector![params[0] * u[0].sin() - v[0].sin()]
    }
    fn point_positions_generic_params<D: DualNum<Primitive = f64> + Copy>(
        &self,
        params: &SVector<D, 1>,
        u: &SVector<D, 1>,
        _v: &SVector<D, 1>,
    ) -> impl AsRef<[Vector2<D>]> {
        [Vector2::new(params[0] * u[0].cos(), params[0] * u[0].sin())]
    }
}

/// The pose every test analyses: φ = 0.7, θ near 0.44.
fn analyze(model: &Tips, options: &Options) -> Analysis<1, 1, Points> {
    model
        .analyze(
            &vector![0.4],
            &vector![0.7],
            &vector![2.0],
            &vector![-3.0],
            options,
        )
        .expect("the pose assembles")
}

/// On the default options an analysis keeps the sines and cosines of the
/// pose it found, of u and of its drivers, and `sensitivities_of` hands
/// those very numbers to the kernel: the numbers of `sensitivities`, which
/// computes its own. Kept ones made wrong change the result (they are read,
/// not recomputed); once the caller moves `u` they are left aside.
#[test]
fn sensitivities_of_takes_the_sines_and_cosines_the_analysis_kept() {
    let model = Tips::new(1.5);
    let options = Options::default();
    let analysis = analyze(&model, &options);
    // The model is the one it says: θ = asin(sin φ / r), and
    // dθ/dr = −tan θ / r.
    let theta = (0.7f64.sin() / 1.5).asin();
    assert!((analysis.u[0] - theta).abs() <= 4.0 * f64::EPSILON);
    let kept = analysis.trig.expect("the default options' path keeps them");
    assert_eq!(kept.u, analysis.u);
    assert_eq!(kept.sin_cos_u, [analysis.u[0].sin_cos()]);
    assert_eq!(kept.sin_cos_v, [0.7f64.sin_cos()]);

    model.called.set(None);
    let given = model
        .sensitivities_of(&analysis, &options)
        .expect("regular");
    assert_eq!(model.called.get(), Some(Called::Given(kept.sin_cos_u)));
    assert!((given.u[(0, 0)] + theta.tan() / 1.5).abs() <= 1e-15);
    model.called.set(None);
    let computed = model.sensitivities(&Motion::of_analysis(&analysis), &options);
    assert_eq!(model.called.get(), Some(Called::Computing));
    assert_eq!(computed, Ok(given));

    let (s, c) = kept.sin_cos_u[0];
    let mut wrong = analysis;
    wrong.trig = Some(PoseTrig {
        sin_cos_u: [(s * (1.0 + 1e-9), c)],
        ..kept
    });
    assert_ne!(model.sensitivities_of(&wrong, &options), Ok(given));

    let mut moved = analysis;
    moved.u[0] += 1e-3;
    model.called.set(None);
    let at_moved = model.sensitivities_of(&moved, &options);
    assert_eq!(model.called.get(), Some(Called::Computing));
    assert_eq!(
        at_moved,
        model.sensitivities(&Motion::of_analysis(&moved), &options)
    );
    assert_ne!(at_moved, Ok(given));
}

/// Off the fused kernel (Jacobians by num-dual or finite differences,
/// method A, damped Newton) an analysis keeps no sines and cosines, and
/// `sensitivities_of` computes them.
#[test]
fn off_the_fused_path_an_analysis_keeps_none() {
    let model = Tips::new(1.5);
    for options in [
        Options {
            jacobian: JacobianSource::Dual,
            ..Options::default()
        },
        Options {
            jacobian: JacobianSource::FiniteDifference,
            ..Options::default()
        },
        Options {
            method: AccelerationMethod::A,
            ..Options::default()
        },
        Options::damped(),
    ] {
        let analysis = analyze(&model, &options);
        assert!(analysis.trig.is_none(), "{options:?}");
        model.called.set(None);
        let at_analysis = model.sensitivities_of(&analysis, &options);
        assert_eq!(model.called.get(), Some(Called::Computing), "{options:?}");
        assert_eq!(
            at_analysis,
            model.sensitivities(&Motion::of_analysis(&analysis), &options)
        );
    }
}

/// Two analyses are equal whether or not they kept sines and cosines; the
/// drivers they were given count.
#[test]
fn equality_leaves_the_kept_sines_and_cosines_aside() {
    let model = Tips::new(1.5);
    let analysis = analyze(&model, &Options::default());
    assert!(analysis.trig.is_some());
    let mut without = analysis;
    without.trig = None;
    assert_eq!(without, analysis);
    let mut other_drivers = analysis;
    other_drivers.vddot[0] += 1.0;
    assert_ne!(other_drivers, analysis);
}

/// A crank-and-slotted-lever quick return
///
/// Promoted from the mechanism file `mechanisms/quick_return.toml` (lengths in mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuickReturn {
    pub r: f64,
    pub d: f64,
    pub lever: f64,
    pub rod: f64,
    pub y_r: f64,
}
const _: () = {
    use ::linkage::nalgebra::{SMatrix, SVector, Vector2};
    #[allow(dead_code)]
    impl QuickReturn {
        /// The dependent coordinates u, in order.
        pub const U_NAMES: [&'static str; 4] = ["phi3", "s", "phi4", "x_r"];
        /// The driving coordinates v, in order.
        pub const V_NAMES: [&'static str; 1] = ["theta"];
        /// The named points, in order.
        pub const POINT_NAMES: [&'static str; 3] = ["A", "P", "R"];
        /// The parameters p the sensitivities differentiate by, in order.
        pub const PARAM_NAMES: [&'static str; 5] = ["r", "d", "lever", "rod", "y_r"];
        /// The index of the point `A`: `pose.points[Self::A]`.
        #[allow(non_upper_case_globals)]
        pub const A: usize = 0usize;
        /// The index of the point `P`: `pose.points[Self::P]`.
        #[allow(non_upper_case_globals)]
        pub const P: usize = 1usize;
        /// The index of the point `R`: `pose.points[Self::R]`.
        #[allow(non_upper_case_globals)]
        pub const R: usize = 2usize;
        /// Ψ_u is block lower triangular: 3 blocks: 2×2, 1×1, 1×1. Its blocks' equations and coordinates in solve order, where each block ends, and where the coordinates its equations involve begin (`Kernels::psi_u_blocks`).
        pub const PSI_U_BLOCKS: ::linkage::PsiUBlocks<'static> = ::linkage::PsiUBlocks::new(
            &[0, 1, 3, 2],
            &[0, 1, 2, 3],
            &[2, 3, 4],
            &[0, 0, 0],
        );
        /// Ψ(u, v): the closure equations, zero at every assembled pose.
        ///
        /// ```text
        /// [  r·cos θ - s·cos φ3                  ]
        /// [  r·sin θ + d - s·sin φ3              ]
        /// [  lever·cos φ3 - x_r + rod·cos φ4     ]
        /// [ -d + lever·sin φ3 - y_r + rod·sin φ4 ]
        /// ```
        #[must_use]
        pub fn psi(&self, u: &SVector<f64, 4>, v: &SVector<f64, 1>) -> SVector<f64, 4> {
            let Self { r, d, lever, rod, y_r, .. } = *self;
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi = SVector::<f64, 4>::zeros();
            psi[0] = r * c_theta - s * c_phi3;
            psi[1] = r * s_theta + d - s * s_phi3;
            psi[2] = lever * c_phi3 - x_r + rod * c_phi4;
            psi[3] = -d + lever * s_phi3 - y_r + rod * s_phi4;
            psi
        }
        /// Ψ_q = ∂Ψ/∂q, the 4×5 Jacobian with columns q = [φ3, s, φ4, x_r, θ] (u first, then v).
        ///
        /// ```text
        /// [  s·sin φ3       -cos φ3    0             0   -r·sin θ ]
        /// [ -s·cos φ3       -sin φ3    0             0    r·cos θ ]
        /// [ -lever·sin φ3    0        -rod·sin φ4   -1    0       ]
        /// [  lever·cos φ3    0         rod·cos φ4    0    0       ]
        /// ```
        #[must_use]
        pub fn psi_q(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 5> {
            let Self { r, lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi_q = SMatrix::<f64, 4, 5>::zeros();
            psi_q[(0, 0)] = s * s_phi3;
            psi_q[(0, 1)] = -c_phi3;
            psi_q[(0, 4)] = -r * s_theta;
            psi_q[(1, 0)] = -s * c_phi3;
            psi_q[(1, 1)] = -s_phi3;
            psi_q[(1, 4)] = r * c_theta;
            psi_q[(2, 0)] = -lever * s_phi3;
            psi_q[(2, 2)] = -rod * s_phi4;
            psi_q[(2, 3)] = -1.0;
            psi_q[(3, 0)] = lever * c_phi3;
            psi_q[(3, 2)] = rod * c_phi4;
            psi_q
        }
        /// Ψ_u = ∂Ψ/∂u, the 4×4 Jacobian with respect to u = [φ3, s, φ4, x_r]. Ψ_u is block lower
        /// triangular: 3 blocks: 2×2, 1×1, 1×1, solved in the order [φ3, s], [φ4], [x_r].
        ///
        /// ```text
        /// [  s·sin φ3       -cos φ3    0             0 ]
        /// [ -s·cos φ3       -sin φ3    0             0 ]
        /// [ -lever·sin φ3    0        -rod·sin φ4   -1 ]
        /// [  lever·cos φ3    0         rod·cos φ4    0 ]
        /// ```
        #[must_use]
        pub fn psi_u(
            &self,
            u: &SVector<f64, 4>,
            _v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 4> {
            let Self { lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s * s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s * c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever * s_phi3;
            psi_u[(2, 2)] = -rod * s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever * c_phi3;
            psi_u[(3, 2)] = rod * c_phi4;
            psi_u
        }
        /// Ψ_v = ∂Ψ/∂v, the 4×1 Jacobian with respect to v = [θ].
        ///
        /// ```text
        /// [ -r·sin θ ]
        /// [  r·cos θ ]
        /// [  0       ]
        /// [  0       ]
        /// ```
        #[must_use]
        pub fn psi_v(
            &self,
            _u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            let Self { r, .. } = *self;
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let mut psi_v = SVector::<f64, 4>::zeros();
            psi_v[0] = -r * s_theta;
            psi_v[1] = r * c_theta;
            psi_v
        }
        /// Ψ and Ψ_u together, sharing every sine, cosine and common subexpression: one
        /// Newton–Raphson step's evaluation (see [`Self::psi`] and [`Self::psi_u`]).
        #[must_use]
        pub fn psi_and_psi_u(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> (SVector<f64, 4>, SMatrix<f64, 4, 4>) {
            let Self { r, d, lever, rod, y_r, .. } = *self;
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let lever_c_phi3 = lever * c_phi3;
            let lever_s_phi3 = lever * s_phi3;
            let s_c_phi3 = s * c_phi3;
            let s_s_phi3 = s * s_phi3;
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let rod_c_phi4 = rod * c_phi4;
            let rod_s_phi4 = rod * s_phi4;
            let mut psi = SVector::<f64, 4>::zeros();
            psi[0] = r * c_theta - s_c_phi3;
            psi[1] = r * s_theta + d - s_s_phi3;
            psi[2] = lever_c_phi3 - x_r + rod_c_phi4;
            psi[3] = -d + lever_s_phi3 - y_r + rod_s_phi4;
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s_s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s_c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever_s_phi3;
            psi_u[(2, 2)] = -rod_s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever_c_phi3;
            psi_u[(3, 2)] = rod_c_phi4;
            (psi, psi_u)
        }
        /// ([Ψ_u]u̇)_u, the 4×4 Jacobian of Ψ_u u̇ with respect to u: the first block of method B.
        ///
        /// ```text
        /// [  s·cos φ3·φ̇3 + sin φ3·ṡ    sin φ3·φ̇3    0               0 ]
        /// [  s·sin φ3·φ̇3 - cos φ3·ṡ   -cos φ3·φ̇3    0               0 ]
        /// [ -lever·cos φ3·φ̇3           0           -rod·cos φ4·φ̇4   0 ]
        /// [ -lever·sin φ3·φ̇3           0           -rod·sin φ4·φ̇4   0 ]
        /// ```
        #[must_use]
        pub fn psi_u_udot_u(
            &self,
            u: &SVector<f64, 4>,
            _v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
        ) -> SMatrix<f64, 4, 4> {
            let Self { lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi_u_udot_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u_udot_u[(0, 0)] = s * c_phi3 * phi3_dot + s_phi3 * s_dot;
            psi_u_udot_u[(0, 1)] = s_phi3 * phi3_dot;
            psi_u_udot_u[(1, 0)] = s * s_phi3 * phi3_dot - c_phi3 * s_dot;
            psi_u_udot_u[(1, 1)] = -c_phi3 * phi3_dot;
            psi_u_udot_u[(2, 0)] = -lever * c_phi3 * phi3_dot;
            psi_u_udot_u[(2, 2)] = -rod * c_phi4 * phi4_dot;
            psi_u_udot_u[(3, 0)] = -lever * s_phi3 * phi3_dot;
            psi_u_udot_u[(3, 2)] = -rod * s_phi4 * phi4_dot;
            psi_u_udot_u
        }
        /// ([Ψ_u]u̇)_v, the 4×1 Jacobian of Ψ_u u̇ with respect to v (non-zero when Ψ_u depends on
        /// v).
        ///
        /// ```text
        /// [ 0 ]
        /// [ 0 ]
        /// [ 0 ]
        /// [ 0 ]
        /// ```
        #[must_use]
        pub fn psi_u_udot_v(
            &self,
            _u: &SVector<f64, 4>,
            _v: &SVector<f64, 1>,
            _udot: &SVector<f64, 4>,
        ) -> SVector<f64, 4> {
            SVector::<f64, 4>::zeros()
        }
        /// ([Ψ_v]v̇)_u, the 4×4 Jacobian of Ψ_v v̇ with respect to u (non-zero when Ψ_v depends on
        /// u).
        ///
        /// ```text
        /// [ 0   0   0   0 ]
        /// [ 0   0   0   0 ]
        /// [ 0   0   0   0 ]
        /// [ 0   0   0   0 ]
        /// ```
        #[must_use]
        pub fn psi_v_vdot_u(
            &self,
            _u: &SVector<f64, 4>,
            _v: &SVector<f64, 1>,
            _vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 4> {
            SMatrix::<f64, 4, 4>::zeros()
        }
        /// ([Ψ_v]v̇)_v, the 4×1 Jacobian of Ψ_v v̇ with respect to v.
        ///
        /// ```text
        /// [ -r·cos θ·θ̇ ]
        /// [ -r·sin θ·θ̇ ]
        /// [  0         ]
        /// [  0         ]
        /// ```
        #[must_use]
        pub fn psi_v_vdot_v(
            &self,
            _u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            let Self { r, .. } = *self;
            let theta = v[0];
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let mut psi_v_vdot_v = SVector::<f64, 4>::zeros();
            psi_v_vdot_v[0] = -r * c_theta * theta_dot;
            psi_v_vdot_v[1] = -r * s_theta * theta_dot;
            psi_v_vdot_v
        }
        /// Ψ̇_u = Σₖ ∂Ψ_u/∂qₖ q̇ₖ, the time derivative of Ψ_u (4×4): method A.
        ///
        /// ```text
        /// [  s·cos φ3·φ̇3 + sin φ3·ṡ    sin φ3·φ̇3    0               0 ]
        /// [  s·sin φ3·φ̇3 - cos φ3·ṡ   -cos φ3·φ̇3    0               0 ]
        /// [ -lever·cos φ3·φ̇3           0           -rod·cos φ4·φ̇4   0 ]
        /// [ -lever·sin φ3·φ̇3           0           -rod·sin φ4·φ̇4   0 ]
        /// ```
        #[must_use]
        pub fn psi_u_dot(
            &self,
            u: &SVector<f64, 4>,
            _v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            _vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 4> {
            let Self { lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi_u_dot = SMatrix::<f64, 4, 4>::zeros();
            psi_u_dot[(0, 0)] = s * c_phi3 * phi3_dot + s_phi3 * s_dot;
            psi_u_dot[(0, 1)] = s_phi3 * phi3_dot;
            psi_u_dot[(1, 0)] = s * s_phi3 * phi3_dot - c_phi3 * s_dot;
            psi_u_dot[(1, 1)] = -c_phi3 * phi3_dot;
            psi_u_dot[(2, 0)] = -lever * c_phi3 * phi3_dot;
            psi_u_dot[(2, 2)] = -rod * c_phi4 * phi4_dot;
            psi_u_dot[(3, 0)] = -lever * s_phi3 * phi3_dot;
            psi_u_dot[(3, 2)] = -rod * s_phi4 * phi4_dot;
            psi_u_dot
        }
        /// Ψ̇_v = Σₖ ∂Ψ_v/∂qₖ q̇ₖ, the time derivative of Ψ_v (4×1): method A.
        ///
        /// ```text
        /// [ -r·cos θ·θ̇ ]
        /// [ -r·sin θ·θ̇ ]
        /// [  0         ]
        /// [  0         ]
        /// ```
        #[must_use]
        pub fn psi_v_dot(
            &self,
            _u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            _udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            let Self { r, .. } = *self;
            let theta = v[0];
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let mut psi_v_dot = SVector::<f64, 4>::zeros();
            psi_v_dot[0] = -r * c_theta * theta_dot;
            psi_v_dot[1] = -r * s_theta * theta_dot;
            psi_v_dot
        }
        /// γ = (Ψ_q q̇)_q q̇, the convective term of the acceleration equation Ψ_u ü = −Ψ_v v̈ − γ,
        /// in one fused evaluation.
        ///
        /// Expanded symbolically at compile time, γ by method A (Ψ̇_u u̇ + Ψ̇_v v̇), by method B (the
        /// four blocks) and this fused form are the same polynomial in q̇.
        ///
        /// ```text
        /// [  (s·cos φ3·φ̇3 + sin φ3·ṡ)·φ̇3 + sin φ3·φ̇3·ṡ - r·cos θ·θ̇² ]
        /// [  (s·sin φ3·φ̇3 - cos φ3·ṡ)·φ̇3 - cos φ3·φ̇3·ṡ - r·sin θ·θ̇² ]
        /// [ -lever·cos φ3·φ̇3² - rod·cos φ4·φ̇4²                      ]
        /// [ -lever·sin φ3·φ̇3² - rod·sin φ4·φ̇4²                      ]
        /// ```
        #[must_use]
        pub fn gamma(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            let Self { r, lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let theta = v[0];
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut gamma = SVector::<f64, 4>::zeros();
            gamma[0] = (s * c_phi3 * phi3_dot + s_phi3 * s_dot) * phi3_dot
                + s_phi3 * phi3_dot * s_dot - r * c_theta * theta_dot.powi(2);
            gamma[1] = (s * s_phi3 * phi3_dot - c_phi3 * s_dot) * phi3_dot
                - c_phi3 * phi3_dot * s_dot - r * s_theta * theta_dot.powi(2);
            gamma[2] = -lever * c_phi3 * phi3_dot.powi(2)
                - rod * c_phi4 * phi4_dot.powi(2);
            gamma[3] = -lever * s_phi3 * phi3_dot.powi(2)
                - rod * s_phi4 * phi4_dot.powi(2);
            gamma
        }
        /// The positions P(q) of the points [A, P, R].
        ///
        /// ```text
        /// A.x = r·cos θ
        /// A.y = r·sin θ
        /// P.x = lever·cos φ3
        /// P.y = -d + lever·sin φ3
        /// R.x = x_r
        /// R.y = y_r
        /// ```
        #[must_use]
        pub fn point_positions(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            let Self { r, d, lever, y_r, .. } = *self;
            let (phi3, x_r) = (u[0], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let a_x = r * c_theta;
            let a_y = r * s_theta;
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let p_x = lever * c_phi3;
            let p_y = -d + lever * s_phi3;
            [Vector2::new(a_x, a_y), Vector2::new(p_x, p_y), Vector2::new(x_r, y_r)]
        }
        /// The velocities Ṗ = P_q q̇ of the points [A, P, R].
        ///
        /// ```text
        /// A.x = -r·sin θ·θ̇
        /// A.y = r·cos θ·θ̇
        /// P.x = -lever·sin φ3·φ̇3
        /// P.y = lever·cos φ3·φ̇3
        /// R.x = ẋ_r
        /// R.y = 0
        /// ```
        #[must_use]
        pub fn point_velocities(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            let Self { r, lever, .. } = *self;
            let phi3 = u[0];
            let theta = v[0];
            let (phi3_dot, x_r_dot) = (udot[0], udot[3]);
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let p_x_dot = -lever * s_phi3 * phi3_dot;
            let p_y_dot = lever * c_phi3 * phi3_dot;
            let a_x_dot = -r * s_theta * theta_dot;
            let a_y_dot = r * c_theta * theta_dot;
            [
                Vector2::new(a_x_dot, a_y_dot),
                Vector2::new(p_x_dot, p_y_dot),
                Vector2::new(x_r_dot, 0.0),
            ]
        }
        /// The accelerations P̈ = P_q q̈ + (P_q q̇)_q q̇ of the points [A, P, R].
        ///
        /// ```text
        /// A.x = -r·(cos θ·θ̇² + sin θ·θ̈)
        /// A.y = -r·(sin θ·θ̇² - cos θ·θ̈)
        /// P.x = -lever·(cos φ3·φ̇3² + sin φ3·φ̈3)
        /// P.y = -lever·(sin φ3·φ̇3² - cos φ3·φ̈3)
        /// R.x = ẍ_r
        /// R.y = 0
        /// ```
        #[must_use]
        pub fn point_accelerations(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            let Self { r, lever, .. } = *self;
            let phi3 = u[0];
            let theta = v[0];
            let phi3_dot = udot[0];
            let theta_dot = vdot[0];
            let (phi3_ddot, x_r_ddot) = (uddot[0], uddot[3]);
            let theta_ddot = vddot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let p_x_ddot = -lever * c_phi3 * phi3_dot.powi(2)
                - lever * s_phi3 * phi3_ddot;
            let a_x_ddot = -r * c_theta * theta_dot.powi(2) - r * s_theta * theta_ddot;
            let a_y_ddot = -r * s_theta * theta_dot.powi(2) + r * c_theta * theta_ddot;
            let p_y_ddot = -lever * s_phi3 * phi3_dot.powi(2)
                + lever * c_phi3 * phi3_ddot;
            [
                Vector2::new(a_x_ddot, a_y_ddot),
                Vector2::new(p_x_ddot, p_y_ddot),
                Vector2::new(x_r_ddot, 0.0),
            ]
        }
        /// Everything at one pose in one pass: Ψ, Ψ_u and Ψ_v; the velocity u̇ = −Ψ_u⁻¹Ψ_v v̇; γ =
        /// (Ψ_q q̇)_q q̇ at that velocity; and the acceleration ü = −Ψ_u⁻¹(Ψ_v v̈ + γ). Each sine and
        /// cosine, and each subexpression shared between these, is computed once: the fast path of
        /// the runtime's analyses and sweeps.
        #[must_use]
        #[inline]
        pub fn kinematics(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<4, 1> {
            let Self { r, d, lever, rod, y_r, .. } = *self;
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let r_c_theta = r * c_theta;
            let r_s_theta = r * s_theta;
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let lever_c_phi3 = lever * c_phi3;
            let lever_s_phi3 = lever * s_phi3;
            let s_c_phi3 = s * c_phi3;
            let s_s_phi3 = s * s_phi3;
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let rod_c_phi4 = rod * c_phi4;
            let rod_s_phi4 = rod * s_phi4;
            let mut psi = SVector::<f64, 4>::zeros();
            psi[0] = r_c_theta - s_c_phi3;
            psi[1] = r_s_theta + d - s_s_phi3;
            psi[2] = lever_c_phi3 - x_r + rod_c_phi4;
            psi[3] = -d + lever_s_phi3 - y_r + rod_s_phi4;
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s_s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s_c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever_s_phi3;
            psi_u[(2, 2)] = -rod_s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever_c_phi3;
            psi_u[(3, 2)] = rod_c_phi4;
            let mut psi_v = SVector::<f64, 4>::zeros();
            psi_v[0] = -r_s_theta;
            psi_v[1] = r_c_theta;
            let factors = ::linkage::Factors::of(&psi_u, Self::PSI_U_BLOCKS);
            let (rcond, det) = (factors.rcond(), factors.det());
            let udot = -factors.solve(&(psi_v * vdot));
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let mut gamma = SVector::<f64, 4>::zeros();
            gamma[0] = (s_c_phi3 * phi3_dot + s_phi3 * s_dot) * phi3_dot
                + s_phi3 * phi3_dot * s_dot - r_c_theta * theta_dot.powi(2);
            gamma[1] = (s_s_phi3 * phi3_dot - c_phi3 * s_dot) * phi3_dot
                - c_phi3 * phi3_dot * s_dot - r_s_theta * theta_dot.powi(2);
            gamma[2] = -lever_c_phi3 * phi3_dot.powi(2) - rod_c_phi4 * phi4_dot.powi(2);
            gamma[3] = -lever_s_phi3 * phi3_dot.powi(2) - rod_s_phi4 * phi4_dot.powi(2);
            let uddot = -factors.solve(&(psi_v * vddot + gamma));
            ::linkage::Kinematics {
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
        /// Which coordinates of u appear under `sin`/`cos` in
        /// [`Self::kinematics_with_trig`], which reads their sine and
        /// cosine from `trig_u` (the others' entries are not read).
        #[doc(hidden)]
        pub const TRIG_U: [bool; 4] = [true, false, true, false];
        /// Which coordinates of v appear under `sin`/`cos`, read from
        /// `trig_v`.
        #[doc(hidden)]
        pub const TRIG_V: [bool; 1] = [true];
        /// [`Self::kinematics`] with the sines and cosines of the coordinates given (`trig_u[k]` =
        /// (sin uₖ, cos uₖ), likewise `trig_v`) instead of computed: a sweep carries them from pose
        /// to pose by the angle-addition formulas, which costs a few multiplications instead of a
        /// transcendental call.
        #[doc(hidden)]
        #[must_use]
        #[inline(always)]
        #[allow(unused_variables, clippy::too_many_arguments)]
        pub fn kinematics_with_trig(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 4],
            trig_v: &[(f64, f64); 1],
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<4, 1> {
            let Self { r, d, lever, rod, y_r, .. } = *self;
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let theta_dot = vdot[0];
            let (s_theta, c_theta) = trig_v[0];
            let r_c_theta = r * c_theta;
            let r_s_theta = r * s_theta;
            let (s_phi3, c_phi3) = trig_u[0];
            let lever_c_phi3 = lever * c_phi3;
            let lever_s_phi3 = lever * s_phi3;
            let s_c_phi3 = s * c_phi3;
            let s_s_phi3 = s * s_phi3;
            let (s_phi4, c_phi4) = trig_u[2];
            let rod_c_phi4 = rod * c_phi4;
            let rod_s_phi4 = rod * s_phi4;
            let mut psi = SVector::<f64, 4>::zeros();
            psi[0] = r_c_theta - s_c_phi3;
            psi[1] = r_s_theta + d - s_s_phi3;
            psi[2] = lever_c_phi3 - x_r + rod_c_phi4;
            psi[3] = -d + lever_s_phi3 - y_r + rod_s_phi4;
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s_s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s_c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever_s_phi3;
            psi_u[(2, 2)] = -rod_s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever_c_phi3;
            psi_u[(3, 2)] = rod_c_phi4;
            let mut psi_v = SVector::<f64, 4>::zeros();
            psi_v[0] = -r_s_theta;
            psi_v[1] = r_c_theta;
            let factors = ::linkage::Factors::of(&psi_u, Self::PSI_U_BLOCKS);
            let (rcond, det) = (factors.rcond(), factors.det());
            let udot = -factors.solve(&(psi_v * vdot));
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let mut gamma = SVector::<f64, 4>::zeros();
            gamma[0] = (s_c_phi3 * phi3_dot + s_phi3 * s_dot) * phi3_dot
                + s_phi3 * phi3_dot * s_dot - r_c_theta * theta_dot.powi(2);
            gamma[1] = (s_s_phi3 * phi3_dot - c_phi3 * s_dot) * phi3_dot
                - c_phi3 * phi3_dot * s_dot - r_s_theta * theta_dot.powi(2);
            gamma[2] = -lever_c_phi3 * phi3_dot.powi(2) - rod_c_phi4 * phi4_dot.powi(2);
            gamma[3] = -lever_s_phi3 * phi3_dot.powi(2) - rod_s_phi4 * phi4_dot.powi(2);
            let uddot = -factors.solve(&(psi_v * vddot + gamma));
            ::linkage::Kinematics {
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
        /// Ψ(u, v) on any dual number of `num_dual`: the same closure equations as [`Self::psi`], for
        /// derivatives by automatic differentiation (cross-checks, and the alternative Jacobian
        /// source of the runtime).
        ///
        /// ```text
        /// [  r·cos θ - s·cos φ3                  ]
        /// [  r·sin θ + d - s·sin φ3              ]
        /// [  lever·cos φ3 - x_r + rod·cos φ4     ]
        /// [ -d + lever·sin φ3 - y_r + rod·sin φ4 ]
        /// ```
        #[must_use]
        #[inline]
        pub fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 4> {
            let r = D::from(self.r);
            let d = D::from(self.d);
            let lever = D::from(self.lever);
            let rod = D::from(self.rod);
            let y_r = D::from(self.y_r);
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi = SVector::<D, 4>::zeros();
            psi[0] = r * c_theta - s * c_phi3;
            psi[1] = r * s_theta + d - s * s_phi3;
            psi[2] = lever * c_phi3 - x_r + rod * c_phi4;
            psi[3] = -d + lever * s_phi3 - y_r + rod * s_phi4;
            psi
        }
        /// The point positions P(q) on any dual number of `num_dual` (see [`Self::point_positions`]).
        #[must_use]
        #[inline]
        pub fn point_positions_generic<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(&self, u: &SVector<D, 4>, v: &SVector<D, 1>) -> [Vector2<D>; 3] {
            let r = D::from(self.r);
            let d = D::from(self.d);
            let lever = D::from(self.lever);
            let y_r = D::from(self.y_r);
            let (phi3, x_r) = (u[0], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let a_x = r * c_theta;
            let a_y = r * s_theta;
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let p_x = lever * c_phi3;
            let p_y = -d + lever * s_phi3;
            [Vector2::new(a_x, a_y), Vector2::new(p_x, p_y), Vector2::new(x_r, y_r)]
        }
        /// Ψ_p = ∂Ψ/∂p, the 4×5 Jacobian with respect to the parameters p = [r, d, lever, rod, y_r]:
        /// the position sensitivities are u_p = −Ψ_u⁻¹Ψ_p.
        ///
        /// ```text
        /// [ cos θ    0   0        0         0 ]
        /// [ sin θ    1   0        0         0 ]
        /// [ 0        0   cos φ3   cos φ4    0 ]
        /// [ 0       -1   sin φ3   sin φ4   -1 ]
        /// ```
        #[must_use]
        pub fn psi_p(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 5> {
            let (phi3, phi4) = (u[0], u[2]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi_p = SMatrix::<f64, 4, 5>::zeros();
            psi_p[(0, 0)] = c_theta;
            psi_p[(1, 0)] = s_theta;
            psi_p[(1, 1)] = 1.0;
            psi_p[(2, 2)] = c_phi3;
            psi_p[(2, 3)] = c_phi4;
            psi_p[(3, 1)] = -1.0;
            psi_p[(3, 2)] = s_phi3;
            psi_p[(3, 3)] = s_phi4;
            psi_p[(3, 4)] = -1.0;
            psi_p
        }
        /// Every term the sensitivities to the parameters p = [r, d, lever, rod, y_r] need, at a pose
        /// in motion, in one pass sharing each sine, cosine and subexpression: Ψ_u, Ψ_p, their first
        /// and second time derivatives Ψ̇_u = (Ψ_q q̇)_u, Ψ̇_p = (Ψ_q q̇)_p, Ψ̈_u = (Ψ_q q̈ + γ)_u,
        /// Ψ̈_p = (Ψ_q q̈ + γ)_p, and the same of every point (P_u, Ṗ_u, P̈_u and P_p, Ṗ_p, P̈_p, the
        /// explicit derivatives of P, Ṗ, P̈). Differentiating Ψ_u u_p + Ψ_p = 0 in time twice gives
        /// the sensitivities (see `linkage::Sensitivities`):
        ///
        /// ```text
        /// u_p = −Ψ_u⁻¹ Ψ_p
        /// u̇_p = −Ψ_u⁻¹ (Ψ̇_u u_p + Ψ̇_p)
        /// ü_p = −Ψ_u⁻¹ (Ψ̈_u u_p + 2 Ψ̇_u u̇_p + Ψ̈_p)
        /// ```
        #[must_use]
        #[inline(always)]
        #[allow(unused_variables, clippy::too_many_arguments)]
        pub fn sensitivity_terms(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<4, 5, [Vector2<f64>; 3]> {
            let Self { lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let theta = v[0];
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let theta_dot = vdot[0];
            let (phi3_ddot, s_ddot, phi4_ddot) = (uddot[0], uddot[1], uddot[2]);
            let theta_ddot = vddot[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let lever_c_phi3 = lever * c_phi3;
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let s_s_phi3_phi3_dot = s * s_phi3 * phi3_dot;
            let c_phi3_s_dot = c_phi3 * s_dot;
            let sum = s * c_phi3 * phi3_dot + s_phi3 * s_dot;
            let s_phi3_phi3_dot = s_phi3 * phi3_dot;
            let c_phi3_phi3_dot = c_phi3 * phi3_dot;
            let c_theta_theta_dot = c_theta * theta_dot;
            let c_phi3_phi3_dot_sq = c_phi3 * phi3_dot.powi(2);
            let s_phi3_phi3_ddot = s_phi3 * phi3_ddot;
            let s_phi3_phi3_dot_sq = s_phi3 * phi3_dot.powi(2);
            let c_phi3_phi3_ddot = c_phi3 * phi3_ddot;
            let sum_2 = s_phi3_phi3_dot_sq * lever - lever_c_phi3 * phi3_ddot;
            let sum_3 = -lever_c_phi3 * phi3_dot.powi(2) - s_phi3_phi3_ddot * lever;
            let sum_4 = -c_theta * theta_dot.powi(2) - s_theta * theta_ddot;
            let sum_5 = -s_theta * theta_dot.powi(2) + c_theta * theta_ddot;
            let sum_6 = -c_phi3_phi3_dot_sq - s_phi3_phi3_ddot;
            let sum_7 = -s_phi3_phi3_dot_sq + c_phi3_phi3_ddot;
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s * s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s * c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever * s_phi3;
            psi_u[(2, 2)] = -rod * s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever_c_phi3;
            psi_u[(3, 2)] = rod * c_phi4;
            let mut psi_p = SMatrix::<f64, 4, 5>::zeros();
            psi_p[(0, 0)] = c_theta;
            psi_p[(1, 0)] = s_theta;
            psi_p[(1, 1)] = 1.0;
            psi_p[(2, 2)] = c_phi3;
            psi_p[(2, 3)] = c_phi4;
            psi_p[(3, 1)] = -1.0;
            psi_p[(3, 2)] = s_phi3;
            psi_p[(3, 3)] = s_phi4;
            psi_p[(3, 4)] = -1.0;
            let mut psi_u_dot = SMatrix::<f64, 4, 4>::zeros();
            psi_u_dot[(0, 0)] = sum;
            psi_u_dot[(0, 1)] = s_phi3_phi3_dot;
            psi_u_dot[(1, 0)] = s_s_phi3_phi3_dot - c_phi3_s_dot;
            psi_u_dot[(1, 1)] = -c_phi3_phi3_dot;
            psi_u_dot[(2, 0)] = -lever_c_phi3 * phi3_dot;
            psi_u_dot[(2, 2)] = -rod * c_phi4 * phi4_dot;
            psi_u_dot[(3, 0)] = -s_phi3_phi3_dot * lever;
            psi_u_dot[(3, 2)] = -rod * s_phi4 * phi4_dot;
            let mut psi_p_dot = SMatrix::<f64, 4, 5>::zeros();
            psi_p_dot[(0, 0)] = -s_theta * theta_dot;
            psi_p_dot[(1, 0)] = c_theta_theta_dot;
            psi_p_dot[(2, 2)] = -s_phi3_phi3_dot;
            psi_p_dot[(2, 3)] = -s_phi4 * phi4_dot;
            psi_p_dot[(3, 2)] = c_phi3_phi3_dot;
            psi_p_dot[(3, 3)] = c_phi4 * phi4_dot;
            let mut psi_u_ddot = SMatrix::<f64, 4, 4>::zeros();
            psi_u_ddot[(0, 0)] = c_phi3_s_dot * phi3_dot + c_phi3_phi3_ddot * s
                + s_phi3 * s_ddot + (-s_s_phi3_phi3_dot + c_phi3_s_dot) * phi3_dot;
            psi_u_ddot[(0, 1)] = c_phi3_phi3_dot_sq + s_phi3_phi3_ddot;
            psi_u_ddot[(1, 0)] = sum * phi3_dot + s_phi3_phi3_dot * s_dot
                + s_phi3_phi3_ddot * s - c_phi3 * s_ddot;
            psi_u_ddot[(1, 1)] = s_phi3_phi3_dot_sq - c_phi3_phi3_ddot;
            psi_u_ddot[(2, 0)] = sum_2;
            psi_u_ddot[(2, 2)] = rod * s_phi4 * phi4_dot.powi(2)
                - rod * c_phi4 * phi4_ddot;
            psi_u_ddot[(3, 0)] = sum_3;
            psi_u_ddot[(3, 2)] = -rod * c_phi4 * phi4_dot.powi(2)
                - rod * s_phi4 * phi4_ddot;
            let mut psi_p_ddot = SMatrix::<f64, 4, 5>::zeros();
            psi_p_ddot[(0, 0)] = sum_4;
            psi_p_ddot[(1, 0)] = sum_5;
            psi_p_ddot[(2, 2)] = sum_6;
            psi_p_ddot[(2, 3)] = -c_phi4 * phi4_dot.powi(2) - s_phi4 * phi4_ddot;
            psi_p_ddot[(3, 2)] = sum_7;
            psi_p_ddot[(3, 3)] = -s_phi4 * phi4_dot.powi(2) + c_phi4 * phi4_ddot;
            ::linkage::SensitivityTerms {
                psi_u,
                psi_p,
                psi_u_dot,
                psi_p_dot,
                psi_u_ddot,
                psi_p_ddot,
                points_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-lever * s_phi3, lever_c_phi3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(1.0, 0.0),
                    ],
                ],
                points_p: [
                    [
                        Vector2::new(c_theta, s_theta),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, -1.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(c_phi3, s_phi3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 1.0),
                    ],
                ],
                point_velocities_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-lever_c_phi3 * phi3_dot, -s_phi3_phi3_dot * lever),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_velocities_p: [
                    [
                        Vector2::new(-s_theta * theta_dot, c_theta_theta_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-s_phi3_phi3_dot, c_phi3_phi3_dot),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_accelerations_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_2, sum_3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_accelerations_p: [
                    [
                        Vector2::new(sum_4, sum_5),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_6, sum_7),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
            }
        }
        /// Which coordinates of u appear under `sin`/`cos` in
        /// [`Self::sensitivity_terms_with_trig`], which reads their
        /// sine and cosine from `trig_u` (the others' entries are not
        /// read).
        #[doc(hidden)]
        pub const SENSITIVITY_TRIG_U: [bool; 4] = [true, false, true, false];
        /// Which coordinates of v appear under `sin`/`cos`, read from
        /// `trig_v`.
        #[doc(hidden)]
        pub const SENSITIVITY_TRIG_V: [bool; 1] = [true];
        /// [`Self::sensitivity_terms`] with the sines and cosines of the coordinates given
        /// (`trig_u[k]` = (sin uₖ, cos uₖ), likewise `trig_v`; those of [`Self::SENSITIVITY_TRIG_U`]
        /// and [`Self::SENSITIVITY_TRIG_V`] are read) instead of computed: a sweep carries them from
        /// pose to pose, as it does for [`Self::kinematics_with_trig`].
        #[doc(hidden)]
        #[must_use]
        #[inline(always)]
        #[allow(unused_variables, clippy::too_many_arguments)]
        pub fn sensitivity_terms_with_trig(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 4],
            trig_v: &[(f64, f64); 1],
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<4, 5, [Vector2<f64>; 3]> {
            let Self { lever, rod, .. } = *self;
            let (phi3, s, phi4) = (u[0], u[1], u[2]);
            let theta = v[0];
            let (phi3_dot, s_dot, phi4_dot) = (udot[0], udot[1], udot[2]);
            let theta_dot = vdot[0];
            let (phi3_ddot, s_ddot, phi4_ddot) = (uddot[0], uddot[1], uddot[2]);
            let theta_ddot = vddot[0];
            let (s_theta, c_theta) = trig_v[0];
            let (s_phi3, c_phi3) = trig_u[0];
            let lever_c_phi3 = lever * c_phi3;
            let (s_phi4, c_phi4) = trig_u[2];
            let s_s_phi3_phi3_dot = s * s_phi3 * phi3_dot;
            let c_phi3_s_dot = c_phi3 * s_dot;
            let sum = s * c_phi3 * phi3_dot + s_phi3 * s_dot;
            let s_phi3_phi3_dot = s_phi3 * phi3_dot;
            let c_phi3_phi3_dot = c_phi3 * phi3_dot;
            let c_theta_theta_dot = c_theta * theta_dot;
            let c_phi3_phi3_dot_sq = c_phi3 * phi3_dot.powi(2);
            let s_phi3_phi3_ddot = s_phi3 * phi3_ddot;
            let s_phi3_phi3_dot_sq = s_phi3 * phi3_dot.powi(2);
            let c_phi3_phi3_ddot = c_phi3 * phi3_ddot;
            let sum_2 = s_phi3_phi3_dot_sq * lever - lever_c_phi3 * phi3_ddot;
            let sum_3 = -lever_c_phi3 * phi3_dot.powi(2) - s_phi3_phi3_ddot * lever;
            let sum_4 = -c_theta * theta_dot.powi(2) - s_theta * theta_ddot;
            let sum_5 = -s_theta * theta_dot.powi(2) + c_theta * theta_ddot;
            let sum_6 = -c_phi3_phi3_dot_sq - s_phi3_phi3_ddot;
            let sum_7 = -s_phi3_phi3_dot_sq + c_phi3_phi3_ddot;
            let mut psi_u = SMatrix::<f64, 4, 4>::zeros();
            psi_u[(0, 0)] = s * s_phi3;
            psi_u[(0, 1)] = -c_phi3;
            psi_u[(1, 0)] = -s * c_phi3;
            psi_u[(1, 1)] = -s_phi3;
            psi_u[(2, 0)] = -lever * s_phi3;
            psi_u[(2, 2)] = -rod * s_phi4;
            psi_u[(2, 3)] = -1.0;
            psi_u[(3, 0)] = lever_c_phi3;
            psi_u[(3, 2)] = rod * c_phi4;
            let mut psi_p = SMatrix::<f64, 4, 5>::zeros();
            psi_p[(0, 0)] = c_theta;
            psi_p[(1, 0)] = s_theta;
            psi_p[(1, 1)] = 1.0;
            psi_p[(2, 2)] = c_phi3;
            psi_p[(2, 3)] = c_phi4;
            psi_p[(3, 1)] = -1.0;
            psi_p[(3, 2)] = s_phi3;
            psi_p[(3, 3)] = s_phi4;
            psi_p[(3, 4)] = -1.0;
            let mut psi_u_dot = SMatrix::<f64, 4, 4>::zeros();
            psi_u_dot[(0, 0)] = sum;
            psi_u_dot[(0, 1)] = s_phi3_phi3_dot;
            psi_u_dot[(1, 0)] = s_s_phi3_phi3_dot - c_phi3_s_dot;
            psi_u_dot[(1, 1)] = -c_phi3_phi3_dot;
            psi_u_dot[(2, 0)] = -lever_c_phi3 * phi3_dot;
            psi_u_dot[(2, 2)] = -rod * c_phi4 * phi4_dot;
            psi_u_dot[(3, 0)] = -s_phi3_phi3_dot * lever;
            psi_u_dot[(3, 2)] = -rod * s_phi4 * phi4_dot;
            let mut psi_p_dot = SMatrix::<f64, 4, 5>::zeros();
            psi_p_dot[(0, 0)] = -s_theta * theta_dot;
            psi_p_dot[(1, 0)] = c_theta_theta_dot;
            psi_p_dot[(2, 2)] = -s_phi3_phi3_dot;
            psi_p_dot[(2, 3)] = -s_phi4 * phi4_dot;
            psi_p_dot[(3, 2)] = c_phi3_phi3_dot;
            psi_p_dot[(3, 3)] = c_phi4 * phi4_dot;
            let mut psi_u_ddot = SMatrix::<f64, 4, 4>::zeros();
            psi_u_ddot[(0, 0)] = c_phi3_s_dot * phi3_dot + c_phi3_phi3_ddot * s
                + s_phi3 * s_ddot + (-s_s_phi3_phi3_dot + c_phi3_s_dot) * phi3_dot;
            psi_u_ddot[(0, 1)] = c_phi3_phi3_dot_sq + s_phi3_phi3_ddot;
            psi_u_ddot[(1, 0)] = sum * phi3_dot + s_phi3_phi3_dot * s_dot
                + s_phi3_phi3_ddot * s - c_phi3 * s_ddot;
            psi_u_ddot[(1, 1)] = s_phi3_phi3_dot_sq - c_phi3_phi3_ddot;
            psi_u_ddot[(2, 0)] = sum_2;
            psi_u_ddot[(2, 2)] = rod * s_phi4 * phi4_dot.powi(2)
                - rod * c_phi4 * phi4_ddot;
            psi_u_ddot[(3, 0)] = sum_3;
            psi_u_ddot[(3, 2)] = -rod * c_phi4 * phi4_dot.powi(2)
                - rod * s_phi4 * phi4_ddot;
            let mut psi_p_ddot = SMatrix::<f64, 4, 5>::zeros();
            psi_p_ddot[(0, 0)] = sum_4;
            psi_p_ddot[(1, 0)] = sum_5;
            psi_p_ddot[(2, 2)] = sum_6;
            psi_p_ddot[(2, 3)] = -c_phi4 * phi4_dot.powi(2) - s_phi4 * phi4_ddot;
            psi_p_ddot[(3, 2)] = sum_7;
            psi_p_ddot[(3, 3)] = -s_phi4 * phi4_dot.powi(2) + c_phi4 * phi4_ddot;
            ::linkage::SensitivityTerms {
                psi_u,
                psi_p,
                psi_u_dot,
                psi_p_dot,
                psi_u_ddot,
                psi_p_ddot,
                points_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-lever * s_phi3, lever_c_phi3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(1.0, 0.0),
                    ],
                ],
                points_p: [
                    [
                        Vector2::new(c_theta, s_theta),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, -1.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(c_phi3, s_phi3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 1.0),
                    ],
                ],
                point_velocities_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-lever_c_phi3 * phi3_dot, -s_phi3_phi3_dot * lever),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_velocities_p: [
                    [
                        Vector2::new(-s_theta * theta_dot, c_theta_theta_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-s_phi3_phi3_dot, c_phi3_phi3_dot),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_accelerations_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_2, sum_3),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
                point_accelerations_p: [
                    [
                        Vector2::new(sum_4, sum_5),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_6, sum_7),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                ],
            }
        }
        /// Ψ(u, v) on any dual number of `num_dual`, with the parameters p = [r, d, lever, rod, y_r]
        /// given as dual numbers too (`params`): derivatives by the parameters by automatic
        /// differentiation (see [`Self::psi_generic`]).
        ///
        /// ```text
        /// [  r·cos θ - s·cos φ3                  ]
        /// [  r·sin θ + d - s·sin φ3              ]
        /// [  lever·cos φ3 - x_r + rod·cos φ4     ]
        /// [ -d + lever·sin φ3 - y_r + rod·sin φ4 ]
        /// ```
        #[must_use]
        #[inline]
        pub fn psi_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 5>,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 4> {
            let r = params[0];
            let d = params[1];
            let lever = params[2];
            let rod = params[3];
            let y_r = params[4];
            let (phi3, s, phi4, x_r) = (u[0], u[1], u[2], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let (s_phi4, c_phi4) = phi4.sin_cos();
            let mut psi = SVector::<D, 4>::zeros();
            psi[0] = r * c_theta - s * c_phi3;
            psi[1] = r * s_theta + d - s * s_phi3;
            psi[2] = lever * c_phi3 - x_r + rod * c_phi4;
            psi[3] = -d + lever * s_phi3 - y_r + rod * s_phi4;
            psi
        }
        /// The point positions P(q) on any dual number of `num_dual`, with the parameters p = [r, d,
        /// lever, rod, y_r] given as dual numbers (see [`Self::point_positions`]).
        #[must_use]
        #[inline]
        pub fn point_positions_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 5>,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> [Vector2<D>; 3] {
            let r = params[0];
            let d = params[1];
            let lever = params[2];
            let y_r = params[4];
            let (phi3, x_r) = (u[0], u[3]);
            let theta = v[0];
            let (s_theta, c_theta) = theta.sin_cos();
            let a_x = r * c_theta;
            let a_y = r * s_theta;
            let (s_phi3, c_phi3) = phi3.sin_cos();
            let p_x = lever * c_phi3;
            let p_y = -d + lever * s_phi3;
            [Vector2::new(a_x, a_y), Vector2::new(p_x, p_y), Vector2::new(x_r, y_r)]
        }
        /// Every generated quantity as a readable formula, for printing.
        pub const SYMBOLIC: ::linkage::SymbolicTable = ::linkage::SymbolicTable {
            name: "QuickReturn",
            u: &["φ3", "s", "φ4", "x_r"],
            v: &["θ"],
            matrices: &[
                ::linkage::SymbolicMatrix {
                    key: "psi",
                    title: "Ψ",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &[""],
                    nonzero: &[
                        (0, 0, "r·cos θ - s·cos φ3"),
                        (1, 0, "r·sin θ + d - s·sin φ3"),
                        (2, 0, "lever·cos φ3 - x_r + rod·cos φ4"),
                        (3, 0, "-d + lever·sin φ3 - y_r + rod·sin φ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_q",
                    title: "Ψ_q",
                    rows: 4,
                    cols: 5,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r", "θ"],
                    nonzero: &[
                        (0, 0, "s·sin φ3"),
                        (0, 1, "-cos φ3"),
                        (0, 4, "-r·sin θ"),
                        (1, 0, "-s·cos φ3"),
                        (1, 1, "-sin φ3"),
                        (1, 4, "r·cos θ"),
                        (2, 0, "-lever·sin φ3"),
                        (2, 2, "-rod·sin φ4"),
                        (2, 3, "-1"),
                        (3, 0, "lever·cos φ3"),
                        (3, 2, "rod·cos φ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u",
                    title: "Ψ_u",
                    rows: 4,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r"],
                    nonzero: &[
                        (0, 0, "s·sin φ3"),
                        (0, 1, "-cos φ3"),
                        (1, 0, "-s·cos φ3"),
                        (1, 1, "-sin φ3"),
                        (2, 0, "-lever·sin φ3"),
                        (2, 2, "-rod·sin φ4"),
                        (2, 3, "-1"),
                        (3, 0, "lever·cos φ3"),
                        (3, 2, "rod·cos φ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v",
                    title: "Ψ_v",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["θ"],
                    nonzero: &[(0, 0, "-r·sin θ"), (1, 0, "r·cos θ")],
                },
                ::linkage::SymbolicMatrix {
                    key: "det_psi_u",
                    title: "det Ψ_u",
                    rows: 1,
                    cols: 1,
                    row_labels: &[""],
                    col_labels: &[""],
                    nonzero: &[(0, 0, "-rod·s·cos φ4·(sin(φ3)² + cos(φ3)²)")],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_udot_u",
                    title: "([Ψ_u]u\u{307})_u",
                    rows: 4,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r"],
                    nonzero: &[
                        (0, 0, "s·cos φ3·φ\u{307}3 + sin φ3·s\u{307}"),
                        (0, 1, "sin φ3·φ\u{307}3"),
                        (1, 0, "s·sin φ3·φ\u{307}3 - cos φ3·s\u{307}"),
                        (1, 1, "-cos φ3·φ\u{307}3"),
                        (2, 0, "-lever·cos φ3·φ\u{307}3"),
                        (2, 2, "-rod·cos φ4·φ\u{307}4"),
                        (3, 0, "-lever·sin φ3·φ\u{307}3"),
                        (3, 2, "-rod·sin φ4·φ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_udot_v",
                    title: "([Ψ_u]u\u{307})_v",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["θ"],
                    nonzero: &[],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_vdot_u",
                    title: "([Ψ_v]v\u{307})_u",
                    rows: 4,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r"],
                    nonzero: &[],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_vdot_v",
                    title: "([Ψ_v]v\u{307})_v",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["θ"],
                    nonzero: &[
                        (0, 0, "-r·cos θ·θ\u{307}"),
                        (1, 0, "-r·sin θ·θ\u{307}"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_dot",
                    title: "Ψ\u{307}_u",
                    rows: 4,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r"],
                    nonzero: &[
                        (0, 0, "s·cos φ3·φ\u{307}3 + sin φ3·s\u{307}"),
                        (0, 1, "sin φ3·φ\u{307}3"),
                        (1, 0, "s·sin φ3·φ\u{307}3 - cos φ3·s\u{307}"),
                        (1, 1, "-cos φ3·φ\u{307}3"),
                        (2, 0, "-lever·cos φ3·φ\u{307}3"),
                        (2, 2, "-rod·cos φ4·φ\u{307}4"),
                        (3, 0, "-lever·sin φ3·φ\u{307}3"),
                        (3, 2, "-rod·sin φ4·φ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_dot",
                    title: "Ψ\u{307}_v",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["θ"],
                    nonzero: &[
                        (0, 0, "-r·cos θ·θ\u{307}"),
                        (1, 0, "-r·sin θ·θ\u{307}"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "gamma",
                    title: "γ = (Ψ_q q\u{307})_q q\u{307}",
                    rows: 4,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &[""],
                    nonzero: &[
                        (
                            0,
                            0,
                            "(s·cos φ3·φ\u{307}3 + sin φ3·s\u{307})·φ\u{307}3 + sin φ3·φ\u{307}3·s\u{307} - r·cos θ·θ\u{307}²",
                        ),
                        (
                            1,
                            0,
                            "(s·sin φ3·φ\u{307}3 - cos φ3·s\u{307})·φ\u{307}3 - cos φ3·φ\u{307}3·s\u{307} - r·sin θ·θ\u{307}²",
                        ),
                        (
                            2,
                            0,
                            "-lever·cos φ3·φ\u{307}3² - rod·cos φ4·φ\u{307}4²",
                        ),
                        (
                            3,
                            0,
                            "-lever·sin φ3·φ\u{307}3² - rod·sin φ4·φ\u{307}4²",
                        ),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "points",
                    title: "P",
                    rows: 3,
                    cols: 2,
                    row_labels: &["A", "P", "R"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "r·cos θ"),
                        (0, 1, "r·sin θ"),
                        (1, 0, "lever·cos φ3"),
                        (1, 1, "-d + lever·sin φ3"),
                        (2, 0, "x_r"),
                        (2, 1, "y_r"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_velocities",
                    title: "Ṗ",
                    rows: 3,
                    cols: 2,
                    row_labels: &["A", "P", "R"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "-r·sin θ·θ\u{307}"),
                        (0, 1, "r·cos θ·θ\u{307}"),
                        (1, 0, "-lever·sin φ3·φ\u{307}3"),
                        (1, 1, "lever·cos φ3·φ\u{307}3"),
                        (2, 0, "x\u{307}_r"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_accelerations",
                    title: "P\u{308}",
                    rows: 3,
                    cols: 2,
                    row_labels: &["A", "P", "R"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "-r·(cos θ·θ\u{307}² + sin θ·θ\u{308})"),
                        (0, 1, "-r·(sin θ·θ\u{307}² - cos θ·θ\u{308})"),
                        (1, 0, "-lever·(cos φ3·φ\u{307}3² + sin φ3·φ\u{308}3)"),
                        (1, 1, "-lever·(sin φ3·φ\u{307}3² - cos φ3·φ\u{308}3)"),
                        (2, 0, "x\u{308}_r"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p",
                    title: "Ψ_p",
                    rows: 4,
                    cols: 5,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "cos θ"),
                        (1, 0, "sin θ"),
                        (1, 1, "1"),
                        (2, 2, "cos φ3"),
                        (2, 3, "cos φ4"),
                        (3, 1, "-1"),
                        (3, 2, "sin φ3"),
                        (3, 3, "sin φ4"),
                        (3, 4, "-1"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p_dot",
                    title: "Ψ\u{307}_p = (Ψ_q q\u{307})_p",
                    rows: 4,
                    cols: 5,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "-sin θ·θ\u{307}"),
                        (1, 0, "cos θ·θ\u{307}"),
                        (2, 2, "-sin φ3·φ\u{307}3"),
                        (2, 3, "-sin φ4·φ\u{307}4"),
                        (3, 2, "cos φ3·φ\u{307}3"),
                        (3, 3, "cos φ4·φ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_ddot",
                    title: "Ψ\u{308}_u = (Ψ_q q\u{308} + γ)_u",
                    rows: 4,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["φ3", "s", "φ4", "x_r"],
                    nonzero: &[
                        (
                            0,
                            0,
                            "cos φ3·φ\u{307}3·s\u{307} + s·cos φ3·φ\u{308}3 + sin φ3·s\u{308} + (-s·sin φ3·φ\u{307}3 + cos φ3·s\u{307})·φ\u{307}3",
                        ),
                        (0, 1, "cos φ3·φ\u{307}3² + sin φ3·φ\u{308}3"),
                        (
                            1,
                            0,
                            "(s·cos φ3·φ\u{307}3 + sin φ3·s\u{307})·φ\u{307}3 + sin φ3·φ\u{307}3·s\u{307} + s·sin φ3·φ\u{308}3 - cos φ3·s\u{308}",
                        ),
                        (1, 1, "sin φ3·φ\u{307}3² - cos φ3·φ\u{308}3"),
                        (2, 0, "lever·(sin φ3·φ\u{307}3² - cos φ3·φ\u{308}3)"),
                        (2, 2, "rod·(sin φ4·φ\u{307}4² - cos φ4·φ\u{308}4)"),
                        (3, 0, "-lever·(cos φ3·φ\u{307}3² + sin φ3·φ\u{308}3)"),
                        (3, 2, "-rod·(cos φ4·φ\u{307}4² + sin φ4·φ\u{308}4)"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p_ddot",
                    title: "Ψ\u{308}_p = (Ψ_q q\u{308} + γ)_p",
                    rows: 4,
                    cols: 5,
                    row_labels: &["Ψ₁", "Ψ₂", "Ψ₃", "Ψ₄"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "-cos θ·θ\u{307}² - sin θ·θ\u{308}"),
                        (1, 0, "-sin θ·θ\u{307}² + cos θ·θ\u{308}"),
                        (2, 2, "-cos φ3·φ\u{307}3² - sin φ3·φ\u{308}3"),
                        (2, 3, "-cos φ4·φ\u{307}4² - sin φ4·φ\u{308}4"),
                        (3, 2, "-sin φ3·φ\u{307}3² + cos φ3·φ\u{308}3"),
                        (3, 3, "-sin φ4·φ\u{307}4² + cos φ4·φ\u{308}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "points_p",
                    title: "P_p",
                    rows: 6,
                    cols: 5,
                    row_labels: &["A.x", "A.y", "P.x", "P.y", "R.x", "R.y"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "cos θ"),
                        (1, 0, "sin θ"),
                        (2, 2, "cos φ3"),
                        (3, 1, "-1"),
                        (3, 2, "sin φ3"),
                        (5, 4, "1"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_velocities_p",
                    title: "Ṗ_p",
                    rows: 6,
                    cols: 5,
                    row_labels: &["A.x", "A.y", "P.x", "P.y", "R.x", "R.y"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "-sin θ·θ\u{307}"),
                        (1, 0, "cos θ·θ\u{307}"),
                        (2, 2, "-sin φ3·φ\u{307}3"),
                        (3, 2, "cos φ3·φ\u{307}3"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_accelerations_p",
                    title: "P\u{308}_p",
                    rows: 6,
                    cols: 5,
                    row_labels: &["A.x", "A.y", "P.x", "P.y", "R.x", "R.y"],
                    col_labels: &["r", "d", "lever", "rod", "y_r"],
                    nonzero: &[
                        (0, 0, "-cos θ·θ\u{307}² - sin θ·θ\u{308}"),
                        (1, 0, "-sin θ·θ\u{307}² + cos θ·θ\u{308}"),
                        (2, 2, "-cos φ3·φ\u{307}3² - sin φ3·φ\u{308}3"),
                        (3, 2, "-sin φ3·φ\u{307}3² + cos φ3·φ\u{308}3"),
                    ],
                },
            ],
            methods_agree: ::core::option::Option::Some(true),
            structure: "Ψ_u is block lower triangular: 3 blocks: 2×2, 1×1, 1×1, solved in the order [φ3, s], [φ4], [x_r].",
        };
    }
    #[automatically_derived]
    impl ::linkage::Kernels<4, 1> for QuickReturn {
        type Points = [Vector2<f64>; 3];
        #[inline]
        fn u_names(&self) -> [&'static str; 4] {
            Self::U_NAMES
        }
        #[inline]
        fn v_names(&self) -> [&'static str; 1] {
            Self::V_NAMES
        }
        #[inline]
        fn point_names(&self) -> &'static [&'static str] {
            &Self::POINT_NAMES
        }
        #[inline]
        fn psi_u_blocks(&self) -> ::linkage::PsiUBlocks<'_> {
            Self::PSI_U_BLOCKS
        }
        #[inline]
        fn psi(&self, u: &SVector<f64, 4>, v: &SVector<f64, 1>) -> SVector<f64, 4> {
            Self::psi(self, u, v)
        }
        #[inline]
        fn psi_u(&self, u: &SVector<f64, 4>, v: &SVector<f64, 1>) -> SMatrix<f64, 4, 4> {
            Self::psi_u(self, u, v)
        }
        #[inline]
        fn psi_v(&self, u: &SVector<f64, 4>, v: &SVector<f64, 1>) -> SVector<f64, 4> {
            Self::psi_v(self, u, v)
        }
        #[inline]
        fn psi_and_psi_u(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> (SVector<f64, 4>, SMatrix<f64, 4, 4>) {
            Self::psi_and_psi_u(self, u, v)
        }
        #[inline]
        fn psi_u_udot_u(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
        ) -> SMatrix<f64, 4, 4> {
            Self::psi_u_udot_u(self, u, v, udot)
        }
        #[inline]
        fn psi_u_udot_v(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
        ) -> SVector<f64, 4> {
            Self::psi_u_udot_v(self, u, v, udot)
        }
        #[inline]
        fn psi_v_vdot_u(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 4> {
            Self::psi_v_vdot_u(self, u, v, vdot)
        }
        #[inline]
        fn psi_v_vdot_v(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            Self::psi_v_vdot_v(self, u, v, vdot)
        }
        #[inline]
        fn psi_u_dot(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 4, 4> {
            Self::psi_u_dot(self, u, v, udot, vdot)
        }
        #[inline]
        fn psi_v_dot(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            Self::psi_v_dot(self, u, v, udot, vdot)
        }
        #[inline]
        fn gamma(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 4> {
            Self::gamma(self, u, v, udot, vdot)
        }
        #[inline]
        fn point_positions(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            Self::point_positions(self, u, v)
        }
        #[inline]
        fn point_velocities(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            Self::point_velocities(self, u, v, udot, vdot)
        }
        #[inline]
        fn point_accelerations(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 3] {
            Self::point_accelerations(self, u, v, udot, vdot, uddot, vddot)
        }
        #[inline]
        fn kinematics(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<4, 1> {
            Self::kinematics(self, u, v, vdot, vddot)
        }
        #[doc(hidden)]
        #[inline]
        fn trig_u(&self) -> [bool; 4] {
            Self::TRIG_U
        }
        #[doc(hidden)]
        #[inline]
        fn trig_v(&self) -> [bool; 1] {
            Self::TRIG_V
        }
        #[inline(always)]
        fn kinematics_with_trig(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 4],
            trig_v: &[(f64, f64); 1],
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<4, 1> {
            Self::kinematics_with_trig(self, u, v, trig_u, trig_v, vdot, vddot)
        }
        #[inline]
        fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 4> {
            Self::psi_generic(self, u, v)
        }
        #[inline]
        fn point_positions_generic<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(&self, u: &SVector<D, 4>, v: &SVector<D, 1>) -> impl AsRef<[Vector2<D>]> {
            Self::point_positions_generic(self, u, v)
        }
    }
    #[automatically_derived]
    impl ::linkage::Linkage<4, 1> for QuickReturn {}
    #[automatically_derived]
    impl ::linkage::SensitivityKernel<4, 1, 5> for QuickReturn {
        #[inline]
        fn sensitivity_terms(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<4, 5, [Vector2<f64>; 3]> {
            Self::sensitivity_terms(self, u, v, udot, vdot, uddot, vddot)
        }
        #[doc(hidden)]
        #[inline]
        fn sensitivity_trig_u(&self) -> [bool; 4] {
            Self::SENSITIVITY_TRIG_U
        }
        #[doc(hidden)]
        #[inline]
        fn sensitivity_trig_v(&self) -> [bool; 1] {
            Self::SENSITIVITY_TRIG_V
        }
        #[inline(always)]
        fn sensitivity_terms_with_trig(
            &self,
            u: &SVector<f64, 4>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 4],
            trig_v: &[(f64, f64); 1],
            udot: &SVector<f64, 4>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 4>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<4, 5, [Vector2<f64>; 3]> {
            Self::sensitivity_terms_with_trig(
                self,
                u,
                v,
                trig_u,
                trig_v,
                udot,
                vdot,
                uddot,
                vddot,
            )
        }
    }
    #[automatically_derived]
    impl ::linkage::Sensitivities<4, 1, 5> for QuickReturn {
        #[inline]
        fn param_names(&self) -> [&'static str; 5] {
            Self::PARAM_NAMES
        }
        #[inline]
        fn params(&self) -> SVector<f64, 5> {
            SVector::<f64, 5>::from([self.r, self.d, self.lever, self.rod, self.y_r])
        }
        #[inline]
        fn set_params(&mut self, params: &SVector<f64, 5>) {
            self.r = params[0];
            self.d = params[1];
            self.lever = params[2];
            self.rod = params[3];
            self.y_r = params[4];
        }
        #[inline]
        fn psi_p(&self, u: &SVector<f64, 4>, v: &SVector<f64, 1>) -> SMatrix<f64, 4, 5> {
            Self::psi_p(self, u, v)
        }
        #[inline]
        fn psi_generic_params<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            params: &SVector<D, 5>,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 4> {
            Self::psi_generic_params(self, params, u, v)
        }
        #[inline]
        fn point_positions_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 5>,
            u: &SVector<D, 4>,
            v: &SVector<D, 1>,
        ) -> impl AsRef<[Vector2<D>]> {
            Self::point_positions_generic_params(self, params, u, v)
        }
    }
};
impl QuickReturn {
    /// The values of the mechanism file.
    pub const FILE: QuickReturn = QuickReturn {
        r: 120.0,
        d: 240.0,
        lever: 450.0,
        rod: 135.0,
        y_r: 180.0,
    };
}

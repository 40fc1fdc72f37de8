#[derive(Clone, Debug)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}
const _: () = {
    use ::linkage::nalgebra::{SMatrix, SVector, Vector2};
    #[allow(dead_code)]
    impl FourBar {
        /// The dependent coordinates u, in order.
        pub const U_NAMES: [&'static str; 2] = ["theta3", "theta4"];
        /// The driving coordinates v, in order.
        pub const V_NAMES: [&'static str; 1] = ["theta2"];
        /// The named points, in order.
        pub const POINT_NAMES: [&'static str; 5] = ["B", "C", "G2", "G3", "G4"];
        /// The parameters p the sensitivities differentiate by, in order.
        pub const PARAM_NAMES: [&'static str; 4] = ["l1", "l2", "l3", "l4"];
        /// The index of the point `B`: `pose.points[Self::B]`.
        #[allow(non_upper_case_globals)]
        pub const B: usize = 0usize;
        /// The index of the point `C`: `pose.points[Self::C]`.
        #[allow(non_upper_case_globals)]
        pub const C: usize = 1usize;
        /// The index of the point `G2`: `pose.points[Self::G2]`.
        #[allow(non_upper_case_globals)]
        pub const G2: usize = 2usize;
        /// The index of the point `G3`: `pose.points[Self::G3]`.
        #[allow(non_upper_case_globals)]
        pub const G3: usize = 3usize;
        /// The index of the point `G4`: `pose.points[Self::G4]`.
        #[allow(non_upper_case_globals)]
        pub const G4: usize = 4usize;
        /// Ψ(u, v): the closure equations, zero at every assembled pose.
        ///
        /// ```text
        /// [ l2·cos θ2 + l3·cos θ3 + l4·cos θ4 - l1 ]
        /// [ l2·sin θ2 + l3·sin θ3 + l4·sin θ4      ]
        /// ```
        #[must_use]
        pub fn psi(&self, u: &SVector<f64, 2>, v: &SVector<f64, 1>) -> SVector<f64, 2> {
            let Self { l1, l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi = SVector::<f64, 2>::zeros();
            psi[0] = l2 * c_theta2 + l3 * c_theta3 + l4 * c_theta4 - l1;
            psi[1] = l2 * s_theta2 + l3 * s_theta3 + l4 * s_theta4;
            psi
        }
        /// Ψ_q = ∂Ψ/∂q, the 2×3 Jacobian with columns q = [θ3, θ4, θ2] (u first, then v).
        ///
        /// ```text
        /// [ -l3·sin θ3   -l4·sin θ4   -l2·sin θ2 ]
        /// [  l3·cos θ3    l4·cos θ4    l2·cos θ2 ]
        /// ```
        #[must_use]
        pub fn psi_q(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 3> {
            let Self { l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi_q = SMatrix::<f64, 2, 3>::zeros();
            psi_q[(0, 0)] = -l3 * s_theta3;
            psi_q[(0, 1)] = -l4 * s_theta4;
            psi_q[(0, 2)] = -l2 * s_theta2;
            psi_q[(1, 0)] = l3 * c_theta3;
            psi_q[(1, 1)] = l4 * c_theta4;
            psi_q[(1, 2)] = l2 * c_theta2;
            psi_q
        }
        /// Ψ_u = ∂Ψ/∂u, the 2×2 Jacobian with respect to u = [θ3, θ4]. Ψ_u is one dense block of 2×2.
        ///
        /// ```text
        /// [ -l3·sin θ3   -l4·sin θ4 ]
        /// [  l3·cos θ3    l4·cos θ4 ]
        /// ```
        #[must_use]
        pub fn psi_u(
            &self,
            u: &SVector<f64, 2>,
            _v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 2> {
            let Self { l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3 * s_theta3;
            psi_u[(0, 1)] = -l4 * s_theta4;
            psi_u[(1, 0)] = l3 * c_theta3;
            psi_u[(1, 1)] = l4 * c_theta4;
            psi_u
        }
        /// Ψ_v = ∂Ψ/∂v, the 2×1 Jacobian with respect to v = [θ2].
        ///
        /// ```text
        /// [ -l2·sin θ2 ]
        /// [  l2·cos θ2 ]
        /// ```
        #[must_use]
        pub fn psi_v(
            &self,
            _u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            let Self { l2, .. } = *self;
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let mut psi_v = SVector::<f64, 2>::zeros();
            psi_v[0] = -l2 * s_theta2;
            psi_v[1] = l2 * c_theta2;
            psi_v
        }
        /// Ψ and Ψ_u together, sharing every sine, cosine and common subexpression: one
        /// Newton–Raphson step's evaluation (see [`Self::psi`] and [`Self::psi_u`]).
        #[must_use]
        pub fn psi_and_psi_u(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> (SVector<f64, 2>, SMatrix<f64, 2, 2>) {
            let Self { l1, l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let l4_c_theta4 = l4 * c_theta4;
            let l4_s_theta4 = l4 * s_theta4;
            let mut psi = SVector::<f64, 2>::zeros();
            psi[0] = l2 * c_theta2 + l3_c_theta3 + l4_c_theta4 - l1;
            psi[1] = l2 * s_theta2 + l3_s_theta3 + l4_s_theta4;
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3_s_theta3;
            psi_u[(0, 1)] = -l4_s_theta4;
            psi_u[(1, 0)] = l3_c_theta3;
            psi_u[(1, 1)] = l4_c_theta4;
            (psi, psi_u)
        }
        /// ([Ψ_u]u̇)_u, the 2×2 Jacobian of Ψ_u u̇ with respect to u: the first block of method B.
        ///
        /// ```text
        /// [ -l3·cos θ3·θ̇3   -l4·cos θ4·θ̇4 ]
        /// [ -l3·sin θ3·θ̇3   -l4·sin θ4·θ̇4 ]
        /// ```
        #[must_use]
        pub fn psi_u_udot_u(
            &self,
            u: &SVector<f64, 2>,
            _v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
        ) -> SMatrix<f64, 2, 2> {
            let Self { l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi_u_udot_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u_udot_u[(0, 0)] = -l3 * c_theta3 * theta3_dot;
            psi_u_udot_u[(0, 1)] = -l4 * c_theta4 * theta4_dot;
            psi_u_udot_u[(1, 0)] = -l3 * s_theta3 * theta3_dot;
            psi_u_udot_u[(1, 1)] = -l4 * s_theta4 * theta4_dot;
            psi_u_udot_u
        }
        /// ([Ψ_u]u̇)_v, the 2×1 Jacobian of Ψ_u u̇ with respect to v (non-zero when Ψ_u depends on
        /// v).
        ///
        /// ```text
        /// [ 0 ]
        /// [ 0 ]
        /// ```
        #[must_use]
        pub fn psi_u_udot_v(
            &self,
            _u: &SVector<f64, 2>,
            _v: &SVector<f64, 1>,
            _udot: &SVector<f64, 2>,
        ) -> SVector<f64, 2> {
            SVector::<f64, 2>::zeros()
        }
        /// ([Ψ_v]v̇)_u, the 2×2 Jacobian of Ψ_v v̇ with respect to u (non-zero when Ψ_v depends on
        /// u).
        ///
        /// ```text
        /// [ 0   0 ]
        /// [ 0   0 ]
        /// ```
        #[must_use]
        pub fn psi_v_vdot_u(
            &self,
            _u: &SVector<f64, 2>,
            _v: &SVector<f64, 1>,
            _vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 2> {
            SMatrix::<f64, 2, 2>::zeros()
        }
        /// ([Ψ_v]v̇)_v, the 2×1 Jacobian of Ψ_v v̇ with respect to v.
        ///
        /// ```text
        /// [ -l2·cos θ2·θ̇2 ]
        /// [ -l2·sin θ2·θ̇2 ]
        /// ```
        #[must_use]
        pub fn psi_v_vdot_v(
            &self,
            _u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            let Self { l2, .. } = *self;
            let theta2 = v[0];
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let mut psi_v_vdot_v = SVector::<f64, 2>::zeros();
            psi_v_vdot_v[0] = -l2 * c_theta2 * theta2_dot;
            psi_v_vdot_v[1] = -l2 * s_theta2 * theta2_dot;
            psi_v_vdot_v
        }
        /// Ψ̇_u = Σₖ ∂Ψ_u/∂qₖ q̇ₖ, the time derivative of Ψ_u (2×2): method A.
        ///
        /// ```text
        /// [ -l3·cos θ3·θ̇3   -l4·cos θ4·θ̇4 ]
        /// [ -l3·sin θ3·θ̇3   -l4·sin θ4·θ̇4 ]
        /// ```
        #[must_use]
        pub fn psi_u_dot(
            &self,
            u: &SVector<f64, 2>,
            _v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            _vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 2> {
            let Self { l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi_u_dot = SMatrix::<f64, 2, 2>::zeros();
            psi_u_dot[(0, 0)] = -l3 * c_theta3 * theta3_dot;
            psi_u_dot[(0, 1)] = -l4 * c_theta4 * theta4_dot;
            psi_u_dot[(1, 0)] = -l3 * s_theta3 * theta3_dot;
            psi_u_dot[(1, 1)] = -l4 * s_theta4 * theta4_dot;
            psi_u_dot
        }
        /// Ψ̇_v = Σₖ ∂Ψ_v/∂qₖ q̇ₖ, the time derivative of Ψ_v (2×1): method A.
        ///
        /// ```text
        /// [ -l2·cos θ2·θ̇2 ]
        /// [ -l2·sin θ2·θ̇2 ]
        /// ```
        #[must_use]
        pub fn psi_v_dot(
            &self,
            _u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            _udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            let Self { l2, .. } = *self;
            let theta2 = v[0];
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let mut psi_v_dot = SVector::<f64, 2>::zeros();
            psi_v_dot[0] = -l2 * c_theta2 * theta2_dot;
            psi_v_dot[1] = -l2 * s_theta2 * theta2_dot;
            psi_v_dot
        }
        /// γ = (Ψ_q q̇)_q q̇, the convective term of the acceleration equation Ψ_u ü = −Ψ_v v̈ − γ,
        /// in one fused evaluation.
        ///
        /// Expanded symbolically at compile time, γ by method A (Ψ̇_u u̇ + Ψ̇_v v̇), by method B (the
        /// four blocks) and this fused form are the same polynomial in q̇.
        ///
        /// ```text
        /// [ -l3·cos θ3·θ̇3² - l4·cos θ4·θ̇4² - l2·cos θ2·θ̇2² ]
        /// [ -l3·sin θ3·θ̇3² - l4·sin θ4·θ̇4² - l2·sin θ2·θ̇2² ]
        /// ```
        #[must_use]
        pub fn gamma(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            let Self { l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut gamma = SVector::<f64, 2>::zeros();
            gamma[0] = -l3 * c_theta3 * theta3_dot.powi(2)
                - l4 * c_theta4 * theta4_dot.powi(2)
                - l2 * c_theta2 * theta2_dot.powi(2);
            gamma[1] = -l3 * s_theta3 * theta3_dot.powi(2)
                - l4 * s_theta4 * theta4_dot.powi(2)
                - l2 * s_theta2 * theta2_dot.powi(2);
            gamma
        }
        /// The positions P(q) of the points [B, C, G2, G3, G4].
        ///
        /// ```text
        /// B.x = l2·cos θ2
        /// B.y = l2·sin θ2
        /// C.x = l2·cos θ2 + l3·cos θ3
        /// C.y = l2·sin θ2 + l3·sin θ3
        /// G2.x = 0.5·l2·cos θ2
        /// G2.y = 0.5·l2·sin θ2
        /// G3.x = l2·cos θ2 + 0.5·l3·cos θ3
        /// G3.y = l2·sin θ2 + 0.5·l3·sin θ3
        /// G4.x = l2·cos θ2 + l3·cos θ3 + 0.5·l4·cos θ4
        /// G4.y = l2·sin θ2 + l3·sin θ3 + 0.5·l4·sin θ4
        /// ```
        #[must_use]
        pub fn point_positions(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            let Self { l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let b_x = l2 * c_theta2;
            let b_y = l2 * s_theta2;
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let c_x = b_x + l3_c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let c_y = b_y + l3_s_theta3;
            let g2_x = 0.5 * b_x;
            let g2_y = 0.5 * b_y;
            let g3_x = b_x + 0.5 * l3_c_theta3;
            let g3_y = b_y + 0.5 * l3_s_theta3;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let g4_x = b_x + l3_c_theta3 + 0.5 * l4 * c_theta4;
            let g4_y = b_y + l3_s_theta3 + 0.5 * l4 * s_theta4;
            [
                Vector2::new(b_x, b_y),
                Vector2::new(c_x, c_y),
                Vector2::new(g2_x, g2_y),
                Vector2::new(g3_x, g3_y),
                Vector2::new(g4_x, g4_y),
            ]
        }
        /// The velocities Ṗ = P_q q̇ of the points [B, C, G2, G3, G4].
        ///
        /// ```text
        /// B.x = -l2·sin θ2·θ̇2
        /// B.y = l2·cos θ2·θ̇2
        /// C.x = -l3·sin θ3·θ̇3 - l2·sin θ2·θ̇2
        /// C.y = l3·cos θ3·θ̇3 + l2·cos θ2·θ̇2
        /// G2.x = -0.5·l2·sin θ2·θ̇2
        /// G2.y = 0.5·l2·cos θ2·θ̇2
        /// G3.x = -0.5·l3·sin θ3·θ̇3 - l2·sin θ2·θ̇2
        /// G3.y = 0.5·l3·cos θ3·θ̇3 + l2·cos θ2·θ̇2
        /// G4.x = -l3·sin θ3·θ̇3 - 0.5·l4·sin θ4·θ̇4 - l2·sin θ2·θ̇2
        /// G4.y = l3·cos θ3·θ̇3 + 0.5·l4·cos θ4·θ̇4 + l2·cos θ2·θ̇2
        /// ```
        #[must_use]
        pub fn point_velocities(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            let Self { l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let l3_s_theta3_theta3_dot = l3 * s_theta3 * theta3_dot;
            let l3_c_theta3_theta3_dot = l3 * c_theta3 * theta3_dot;
            let l2_s_theta2_theta2_dot = l2 * s_theta2 * theta2_dot;
            let b_x_dot = -l2_s_theta2_theta2_dot;
            let b_y_dot = l2 * c_theta2 * theta2_dot;
            let c_x_dot = -l3_s_theta3_theta3_dot - l2_s_theta2_theta2_dot;
            let c_y_dot = l3_c_theta3_theta3_dot + b_y_dot;
            let g2_x_dot = -0.5 * l2_s_theta2_theta2_dot;
            let g2_y_dot = 0.5 * b_y_dot;
            let g3_x_dot = -0.5 * l3_s_theta3_theta3_dot - l2_s_theta2_theta2_dot;
            let g3_y_dot = 0.5 * l3_c_theta3_theta3_dot + b_y_dot;
            let g4_x_dot = -l3_s_theta3_theta3_dot - 0.5 * l4 * s_theta4 * theta4_dot
                - l2_s_theta2_theta2_dot;
            let g4_y_dot = l3_c_theta3_theta3_dot + 0.5 * l4 * c_theta4 * theta4_dot
                + b_y_dot;
            [
                Vector2::new(b_x_dot, b_y_dot),
                Vector2::new(c_x_dot, c_y_dot),
                Vector2::new(g2_x_dot, g2_y_dot),
                Vector2::new(g3_x_dot, g3_y_dot),
                Vector2::new(g4_x_dot, g4_y_dot),
            ]
        }
        /// The accelerations P̈ = P_q q̈ + (P_q q̇)_q q̇ of the points [B, C, G2, G3, G4].
        ///
        /// ```text
        /// B.x = -l2·(cos θ2·θ̇2² + sin θ2·θ̈2)
        /// B.y = -l2·(sin θ2·θ̇2² - cos θ2·θ̈2)
        /// C.x = -l3·cos θ3·θ̇3² - l2·cos θ2·θ̇2² - l3·sin θ3·θ̈3 - l2·sin θ2·θ̈2
        /// C.y = -l3·sin θ3·θ̇3² - l2·sin θ2·θ̇2² + l3·cos θ3·θ̈3 + l2·cos θ2·θ̈2
        /// G2.x = -0.5·l2·(cos θ2·θ̇2² + sin θ2·θ̈2)
        /// G2.y = -0.5·l2·(sin θ2·θ̇2² - cos θ2·θ̈2)
        /// G3.x = -0.5·l3·cos θ3·θ̇3² - l2·cos θ2·θ̇2² - 0.5·l3·sin θ3·θ̈3 - l2·sin θ2·θ̈2
        /// G3.y = -0.5·l3·sin θ3·θ̇3² - l2·sin θ2·θ̇2² + 0.5·l3·cos θ3·θ̈3 + l2·cos θ2·θ̈2
        /// G4.x = -l3·cos θ3·θ̇3² - 0.5·l4·cos θ4·θ̇4² - l2·cos θ2·θ̇2² - l3·sin θ3·θ̈3 - 0.5·l4·sin θ4·θ̈4 - l2·sin θ2·θ̈2
        /// G4.y = -l3·sin θ3·θ̇3² - 0.5·l4·sin θ4·θ̇4² - l2·sin θ2·θ̇2² + l3·cos θ3·θ̈3 + 0.5·l4·cos θ4·θ̈4 + l2·cos θ2·θ̈2
        /// ```
        #[must_use]
        pub fn point_accelerations(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            let Self { l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let theta2_dot = vdot[0];
            let (theta3_ddot, theta4_ddot) = (uddot[0], uddot[1]);
            let theta2_ddot = vddot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let l3_c_theta3_theta3_dot_sq = l3 * c_theta3 * theta3_dot.powi(2);
            let l2_c_theta2_theta2_dot_sq = l2 * c_theta2 * theta2_dot.powi(2);
            let l3_s_theta3_theta3_dot_sq = l3 * s_theta3 * theta3_dot.powi(2);
            let l2_s_theta2_theta2_dot_sq = l2 * s_theta2 * theta2_dot.powi(2);
            let l3_s_theta3_theta3_ddot = l3 * s_theta3 * theta3_ddot;
            let l2_s_theta2_theta2_ddot = l2 * s_theta2 * theta2_ddot;
            let l3_c_theta3_theta3_ddot = l3 * c_theta3 * theta3_ddot;
            let l2_c_theta2_theta2_ddot = l2 * c_theta2 * theta2_ddot;
            let b_x_ddot = -l2_c_theta2_theta2_dot_sq - l2_s_theta2_theta2_ddot;
            let b_y_ddot = -l2_s_theta2_theta2_dot_sq + l2_c_theta2_theta2_ddot;
            let c_x_ddot = -l3_c_theta3_theta3_dot_sq - l2_c_theta2_theta2_dot_sq
                - l3_s_theta3_theta3_ddot - l2_s_theta2_theta2_ddot;
            let c_y_ddot = -l3_s_theta3_theta3_dot_sq - l2_s_theta2_theta2_dot_sq
                + l3_c_theta3_theta3_ddot + l2_c_theta2_theta2_ddot;
            let g2_x_ddot = -0.5 * l2_c_theta2_theta2_dot_sq
                - 0.5 * l2_s_theta2_theta2_ddot;
            let g2_y_ddot = -0.5 * l2_s_theta2_theta2_dot_sq
                + 0.5 * l2_c_theta2_theta2_ddot;
            let g3_x_ddot = -0.5 * l3_c_theta3_theta3_dot_sq - l2_c_theta2_theta2_dot_sq
                - 0.5 * l3_s_theta3_theta3_ddot - l2_s_theta2_theta2_ddot;
            let g3_y_ddot = -0.5 * l3_s_theta3_theta3_dot_sq - l2_s_theta2_theta2_dot_sq
                + 0.5 * l3_c_theta3_theta3_ddot + l2_c_theta2_theta2_ddot;
            let g4_x_ddot = -l3_c_theta3_theta3_dot_sq
                - 0.5 * l4 * c_theta4 * theta4_dot.powi(2) - l2_c_theta2_theta2_dot_sq
                - l3_s_theta3_theta3_ddot - 0.5 * l4 * s_theta4 * theta4_ddot
                - l2_s_theta2_theta2_ddot;
            let g4_y_ddot = -l3_s_theta3_theta3_dot_sq
                - 0.5 * l4 * s_theta4 * theta4_dot.powi(2) - l2_s_theta2_theta2_dot_sq
                + l3_c_theta3_theta3_ddot + 0.5 * l4 * c_theta4 * theta4_ddot
                + l2_c_theta2_theta2_ddot;
            [
                Vector2::new(b_x_ddot, b_y_ddot),
                Vector2::new(c_x_ddot, c_y_ddot),
                Vector2::new(g2_x_ddot, g2_y_ddot),
                Vector2::new(g3_x_ddot, g3_y_ddot),
                Vector2::new(g4_x_ddot, g4_y_ddot),
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<2, 1> {
            let Self { l1, l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let l2_c_theta2 = l2 * c_theta2;
            let l2_s_theta2 = l2 * s_theta2;
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let l4_c_theta4 = l4 * c_theta4;
            let l4_s_theta4 = l4 * s_theta4;
            let mut psi = SVector::<f64, 2>::zeros();
            psi[0] = l2_c_theta2 + l3_c_theta3 + l4_c_theta4 - l1;
            psi[1] = l2_s_theta2 + l3_s_theta3 + l4_s_theta4;
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3_s_theta3;
            psi_u[(0, 1)] = -l4_s_theta4;
            psi_u[(1, 0)] = l3_c_theta3;
            psi_u[(1, 1)] = l4_c_theta4;
            let mut psi_v = SVector::<f64, 2>::zeros();
            psi_v[0] = -l2_s_theta2;
            psi_v[1] = l2_c_theta2;
            let factors = ::linkage::Factors::whole(&psi_u);
            let (rcond, det) = (factors.rcond(), factors.det());
            let udot = -factors.solve(&(psi_v * vdot));
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let mut gamma = SVector::<f64, 2>::zeros();
            gamma[0] = -l3_c_theta3 * theta3_dot.powi(2)
                - l4_c_theta4 * theta4_dot.powi(2) - l2_c_theta2 * theta2_dot.powi(2);
            gamma[1] = -l3_s_theta3 * theta3_dot.powi(2)
                - l4_s_theta4 * theta4_dot.powi(2) - l2_s_theta2 * theta2_dot.powi(2);
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
        pub const TRIG_U: [bool; 2] = [true, true];
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 2],
            trig_v: &[(f64, f64); 1],
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<2, 1> {
            let Self { l1, l2, l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let theta2_dot = vdot[0];
            let (s_theta2, c_theta2) = trig_v[0];
            let l2_c_theta2 = l2 * c_theta2;
            let l2_s_theta2 = l2 * s_theta2;
            let (s_theta3, c_theta3) = trig_u[0];
            let l3_c_theta3 = l3 * c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let (s_theta4, c_theta4) = trig_u[1];
            let l4_c_theta4 = l4 * c_theta4;
            let l4_s_theta4 = l4 * s_theta4;
            let mut psi = SVector::<f64, 2>::zeros();
            psi[0] = l2_c_theta2 + l3_c_theta3 + l4_c_theta4 - l1;
            psi[1] = l2_s_theta2 + l3_s_theta3 + l4_s_theta4;
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3_s_theta3;
            psi_u[(0, 1)] = -l4_s_theta4;
            psi_u[(1, 0)] = l3_c_theta3;
            psi_u[(1, 1)] = l4_c_theta4;
            let mut psi_v = SVector::<f64, 2>::zeros();
            psi_v[0] = -l2_s_theta2;
            psi_v[1] = l2_c_theta2;
            let factors = ::linkage::Factors::whole(&psi_u);
            let (rcond, det) = (factors.rcond(), factors.det());
            let udot = -factors.solve(&(psi_v * vdot));
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let mut gamma = SVector::<f64, 2>::zeros();
            gamma[0] = -l3_c_theta3 * theta3_dot.powi(2)
                - l4_c_theta4 * theta4_dot.powi(2) - l2_c_theta2 * theta2_dot.powi(2);
            gamma[1] = -l3_s_theta3 * theta3_dot.powi(2)
                - l4_s_theta4 * theta4_dot.powi(2) - l2_s_theta2 * theta2_dot.powi(2);
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
        /// [ l2·cos θ2 + l3·cos θ3 + l4·cos θ4 - l1 ]
        /// [ l2·sin θ2 + l3·sin θ3 + l4·sin θ4      ]
        /// ```
        #[must_use]
        #[inline]
        pub fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 2> {
            let l1 = D::from(self.l1);
            let l2 = D::from(self.l2);
            let l3 = D::from(self.l3);
            let l4 = D::from(self.l4);
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi = SVector::<D, 2>::zeros();
            psi[0] = l2 * c_theta2 + l3 * c_theta3 + l4 * c_theta4 - l1;
            psi[1] = l2 * s_theta2 + l3 * s_theta3 + l4 * s_theta4;
            psi
        }
        /// The point positions P(q) on any dual number of `num_dual` (see [`Self::point_positions`]).
        #[must_use]
        #[inline]
        pub fn point_positions_generic<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(&self, u: &SVector<D, 2>, v: &SVector<D, 1>) -> [Vector2<D>; 5] {
            let l2 = D::from(self.l2);
            let l3 = D::from(self.l3);
            let l4 = D::from(self.l4);
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let b_x = l2 * c_theta2;
            let b_y = l2 * s_theta2;
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let c_x = b_x + l3_c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let c_y = b_y + l3_s_theta3;
            let g2_x = b_x * 0.5;
            let g2_y = b_y * 0.5;
            let g3_x = b_x + l3_c_theta3 * 0.5;
            let g3_y = b_y + l3_s_theta3 * 0.5;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let g4_x = b_x + l3_c_theta3 + l4 * c_theta4 * 0.5;
            let g4_y = b_y + l3_s_theta3 + l4 * s_theta4 * 0.5;
            [
                Vector2::new(b_x, b_y),
                Vector2::new(c_x, c_y),
                Vector2::new(g2_x, g2_y),
                Vector2::new(g3_x, g3_y),
                Vector2::new(g4_x, g4_y),
            ]
        }
        /// Ψ_p = ∂Ψ/∂p, the 2×4 Jacobian with respect to the parameters p = [l1, l2, l3, l4]: the
        /// position sensitivities are u_p = −Ψ_u⁻¹Ψ_p.
        ///
        /// ```text
        /// [ -1   cos θ2   cos θ3   cos θ4 ]
        /// [  0   sin θ2   sin θ3   sin θ4 ]
        /// ```
        #[must_use]
        pub fn psi_p(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 4> {
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi_p = SMatrix::<f64, 2, 4>::zeros();
            psi_p[(0, 0)] = -1.0;
            psi_p[(0, 1)] = c_theta2;
            psi_p[(0, 2)] = c_theta3;
            psi_p[(0, 3)] = c_theta4;
            psi_p[(1, 1)] = s_theta2;
            psi_p[(1, 2)] = s_theta3;
            psi_p[(1, 3)] = s_theta4;
            psi_p
        }
        /// Every term the sensitivities to the parameters p = [l1, l2, l3, l4] need, at a pose in
        /// motion, in one pass sharing each sine, cosine and subexpression: Ψ_u, Ψ_p, their first and
        /// second time derivatives Ψ̇_u = (Ψ_q q̇)_u, Ψ̇_p = (Ψ_q q̇)_p, Ψ̈_u = (Ψ_q q̈ + γ)_u, Ψ̈_p
        /// = (Ψ_q q̈ + γ)_p, and the same of every point (P_u, Ṗ_u, P̈_u and P_p, Ṗ_p, P̈_p, the
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<2, 4, [Vector2<f64>; 5]> {
            let Self { l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let theta2_dot = vdot[0];
            let (theta3_ddot, theta4_ddot) = (uddot[0], uddot[1]);
            let theta2_ddot = vddot[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let l4_c_theta4 = l4 * c_theta4;
            let l4_s_theta4 = l4 * s_theta4;
            let l3_s_theta3_theta3_dot = l3_s_theta3 * theta3_dot;
            let l4_s_theta4_theta4_dot = l4_s_theta4 * theta4_dot;
            let l3_c_theta3_theta3_dot = l3_c_theta3 * theta3_dot;
            let l4_c_theta4_theta4_dot = l4_c_theta4 * theta4_dot;
            let l3_c_theta3_theta3_dot_sq = l3_c_theta3 * theta3_dot.powi(2);
            let l4_c_theta4_theta4_dot_sq = l4_c_theta4 * theta4_dot.powi(2);
            let l3_s_theta3_theta3_dot_sq = l3_s_theta3 * theta3_dot.powi(2);
            let l4_s_theta4_theta4_dot_sq = l4_s_theta4 * theta4_dot.powi(2);
            let l3_s_theta3_theta3_ddot = l3_s_theta3 * theta3_ddot;
            let l4_s_theta4_theta4_ddot = l4_s_theta4 * theta4_ddot;
            let l3_c_theta3_theta3_ddot = l3_c_theta3 * theta3_ddot;
            let l4_c_theta4_theta4_ddot = l4_c_theta4 * theta4_ddot;
            let s_theta2_theta2_dot = s_theta2 * theta2_dot;
            let s_theta3_theta3_dot = s_theta3 * theta3_dot;
            let s_theta4_theta4_dot = s_theta4 * theta4_dot;
            let c_theta2_theta2_dot = c_theta2 * theta2_dot;
            let c_theta3_theta3_dot = c_theta3 * theta3_dot;
            let c_theta4_theta4_dot = c_theta4 * theta4_dot;
            let sum = l3_s_theta3_theta3_dot_sq - l3_c_theta3_theta3_ddot;
            let sum_2 = -l3_c_theta3_theta3_dot_sq - l3_s_theta3_theta3_ddot;
            let c_theta2_theta2_dot_sq = c_theta2 * theta2_dot.powi(2);
            let s_theta2_theta2_ddot = s_theta2 * theta2_ddot;
            let sum_3 = -c_theta2_theta2_dot_sq - s_theta2_theta2_ddot;
            let c_theta3_theta3_dot_sq = c_theta3 * theta3_dot.powi(2);
            let s_theta3_theta3_ddot = s_theta3 * theta3_ddot;
            let sum_4 = -c_theta3_theta3_dot_sq - s_theta3_theta3_ddot;
            let c_theta4_theta4_dot_sq = c_theta4 * theta4_dot.powi(2);
            let s_theta4_theta4_ddot = s_theta4 * theta4_ddot;
            let s_theta2_theta2_dot_sq = s_theta2 * theta2_dot.powi(2);
            let c_theta2_theta2_ddot = c_theta2 * theta2_ddot;
            let sum_5 = -s_theta2_theta2_dot_sq + c_theta2_theta2_ddot;
            let s_theta3_theta3_dot_sq = s_theta3 * theta3_dot.powi(2);
            let c_theta3_theta3_ddot = c_theta3 * theta3_ddot;
            let sum_6 = -s_theta3_theta3_dot_sq + c_theta3_theta3_ddot;
            let s_theta4_theta4_dot_sq = s_theta4 * theta4_dot.powi(2);
            let c_theta4_theta4_ddot = c_theta4 * theta4_ddot;
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3_s_theta3;
            psi_u[(0, 1)] = -l4_s_theta4;
            psi_u[(1, 0)] = l3_c_theta3;
            psi_u[(1, 1)] = l4_c_theta4;
            let mut psi_p = SMatrix::<f64, 2, 4>::zeros();
            psi_p[(0, 0)] = -1.0;
            psi_p[(0, 1)] = c_theta2;
            psi_p[(0, 2)] = c_theta3;
            psi_p[(0, 3)] = c_theta4;
            psi_p[(1, 1)] = s_theta2;
            psi_p[(1, 2)] = s_theta3;
            psi_p[(1, 3)] = s_theta4;
            let mut psi_u_dot = SMatrix::<f64, 2, 2>::zeros();
            psi_u_dot[(0, 0)] = -l3_c_theta3_theta3_dot;
            psi_u_dot[(0, 1)] = -l4_c_theta4_theta4_dot;
            psi_u_dot[(1, 0)] = -l3_s_theta3_theta3_dot;
            psi_u_dot[(1, 1)] = -l4_s_theta4_theta4_dot;
            let mut psi_p_dot = SMatrix::<f64, 2, 4>::zeros();
            psi_p_dot[(0, 1)] = -s_theta2_theta2_dot;
            psi_p_dot[(0, 2)] = -s_theta3_theta3_dot;
            psi_p_dot[(0, 3)] = -s_theta4_theta4_dot;
            psi_p_dot[(1, 1)] = c_theta2_theta2_dot;
            psi_p_dot[(1, 2)] = c_theta3_theta3_dot;
            psi_p_dot[(1, 3)] = c_theta4_theta4_dot;
            let mut psi_u_ddot = SMatrix::<f64, 2, 2>::zeros();
            psi_u_ddot[(0, 0)] = sum;
            psi_u_ddot[(0, 1)] = l4_s_theta4_theta4_dot_sq - l4_c_theta4_theta4_ddot;
            psi_u_ddot[(1, 0)] = sum_2;
            psi_u_ddot[(1, 1)] = -l4_c_theta4_theta4_dot_sq - l4_s_theta4_theta4_ddot;
            let mut psi_p_ddot = SMatrix::<f64, 2, 4>::zeros();
            psi_p_ddot[(0, 1)] = sum_3;
            psi_p_ddot[(0, 2)] = sum_4;
            psi_p_ddot[(0, 3)] = -c_theta4_theta4_dot_sq - s_theta4_theta4_ddot;
            psi_p_ddot[(1, 1)] = sum_5;
            psi_p_ddot[(1, 2)] = sum_6;
            psi_p_ddot[(1, 3)] = -s_theta4_theta4_dot_sq + c_theta4_theta4_ddot;
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
                        Vector2::new(-l3_s_theta3, l3_c_theta3),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-0.5 * l3_s_theta3, 0.5 * l3_c_theta3),
                        Vector2::new(-l3_s_theta3, l3_c_theta3),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-0.5 * l4_s_theta4, 0.5 * l4_c_theta4),
                    ],
                ],
                points_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(0.5 * c_theta2, 0.5 * s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(c_theta3, s_theta3),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.5 * c_theta3, 0.5 * s_theta3),
                        Vector2::new(c_theta3, s_theta3),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.5 * c_theta4, 0.5 * s_theta4),
                    ],
                ],
                point_velocities_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-l3_c_theta3_theta3_dot, -l3_s_theta3_theta3_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * l3_c_theta3_theta3_dot,
                            -0.5 * l3_s_theta3_theta3_dot,
                        ),
                        Vector2::new(-l3_c_theta3_theta3_dot, -l3_s_theta3_theta3_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * l4_c_theta4_theta4_dot,
                            -0.5 * l4_s_theta4_theta4_dot,
                        ),
                    ],
                ],
                point_velocities_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(
                            -0.5 * s_theta2_theta2_dot,
                            0.5 * c_theta2_theta2_dot,
                        ),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-s_theta3_theta3_dot, c_theta3_theta3_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * s_theta3_theta3_dot,
                            0.5 * c_theta3_theta3_dot,
                        ),
                        Vector2::new(-s_theta3_theta3_dot, c_theta3_theta3_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * s_theta4_theta4_dot,
                            0.5 * c_theta4_theta4_dot,
                        ),
                    ],
                ],
                point_accelerations_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum, sum_2),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            0.5 * l3_s_theta3_theta3_dot_sq
                                - 0.5 * l3_c_theta3_theta3_ddot,
                            -0.5 * l3_c_theta3_theta3_dot_sq
                                - 0.5 * l3_s_theta3_theta3_ddot,
                        ),
                        Vector2::new(sum, sum_2),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            0.5 * l4_s_theta4_theta4_dot_sq
                                - 0.5 * l4_c_theta4_theta4_ddot,
                            -0.5 * l4_c_theta4_theta4_dot_sq
                                - 0.5 * l4_s_theta4_theta4_ddot,
                        ),
                    ],
                ],
                point_accelerations_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(
                            -0.5 * c_theta2_theta2_dot_sq - 0.5 * s_theta2_theta2_ddot,
                            -0.5 * s_theta2_theta2_dot_sq + 0.5 * c_theta2_theta2_ddot,
                        ),
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(sum_3, sum_5),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_4, sum_6),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * c_theta3_theta3_dot_sq - 0.5 * s_theta3_theta3_ddot,
                            -0.5 * s_theta3_theta3_dot_sq + 0.5 * c_theta3_theta3_ddot,
                        ),
                        Vector2::new(sum_4, sum_6),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * c_theta4_theta4_dot_sq - 0.5 * s_theta4_theta4_ddot,
                            -0.5 * s_theta4_theta4_dot_sq + 0.5 * c_theta4_theta4_ddot,
                        ),
                    ],
                ],
            }
        }
        /// Which coordinates of u appear under `sin`/`cos` in
        /// [`Self::sensitivity_terms_with_trig`], which reads their
        /// sine and cosine from `trig_u` (the others' entries are not
        /// read).
        #[doc(hidden)]
        pub const SENSITIVITY_TRIG_U: [bool; 2] = [true, true];
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 2],
            trig_v: &[(f64, f64); 1],
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<2, 4, [Vector2<f64>; 5]> {
            let Self { l3, l4, .. } = *self;
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (theta3_dot, theta4_dot) = (udot[0], udot[1]);
            let theta2_dot = vdot[0];
            let (theta3_ddot, theta4_ddot) = (uddot[0], uddot[1]);
            let theta2_ddot = vddot[0];
            let (s_theta2, c_theta2) = trig_v[0];
            let (s_theta3, c_theta3) = trig_u[0];
            let l3_c_theta3 = l3 * c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let (s_theta4, c_theta4) = trig_u[1];
            let l4_c_theta4 = l4 * c_theta4;
            let l4_s_theta4 = l4 * s_theta4;
            let l3_s_theta3_theta3_dot = l3_s_theta3 * theta3_dot;
            let l4_s_theta4_theta4_dot = l4_s_theta4 * theta4_dot;
            let l3_c_theta3_theta3_dot = l3_c_theta3 * theta3_dot;
            let l4_c_theta4_theta4_dot = l4_c_theta4 * theta4_dot;
            let l3_c_theta3_theta3_dot_sq = l3_c_theta3 * theta3_dot.powi(2);
            let l4_c_theta4_theta4_dot_sq = l4_c_theta4 * theta4_dot.powi(2);
            let l3_s_theta3_theta3_dot_sq = l3_s_theta3 * theta3_dot.powi(2);
            let l4_s_theta4_theta4_dot_sq = l4_s_theta4 * theta4_dot.powi(2);
            let l3_s_theta3_theta3_ddot = l3_s_theta3 * theta3_ddot;
            let l4_s_theta4_theta4_ddot = l4_s_theta4 * theta4_ddot;
            let l3_c_theta3_theta3_ddot = l3_c_theta3 * theta3_ddot;
            let l4_c_theta4_theta4_ddot = l4_c_theta4 * theta4_ddot;
            let s_theta2_theta2_dot = s_theta2 * theta2_dot;
            let s_theta3_theta3_dot = s_theta3 * theta3_dot;
            let s_theta4_theta4_dot = s_theta4 * theta4_dot;
            let c_theta2_theta2_dot = c_theta2 * theta2_dot;
            let c_theta3_theta3_dot = c_theta3 * theta3_dot;
            let c_theta4_theta4_dot = c_theta4 * theta4_dot;
            let sum = l3_s_theta3_theta3_dot_sq - l3_c_theta3_theta3_ddot;
            let sum_2 = -l3_c_theta3_theta3_dot_sq - l3_s_theta3_theta3_ddot;
            let c_theta2_theta2_dot_sq = c_theta2 * theta2_dot.powi(2);
            let s_theta2_theta2_ddot = s_theta2 * theta2_ddot;
            let sum_3 = -c_theta2_theta2_dot_sq - s_theta2_theta2_ddot;
            let c_theta3_theta3_dot_sq = c_theta3 * theta3_dot.powi(2);
            let s_theta3_theta3_ddot = s_theta3 * theta3_ddot;
            let sum_4 = -c_theta3_theta3_dot_sq - s_theta3_theta3_ddot;
            let c_theta4_theta4_dot_sq = c_theta4 * theta4_dot.powi(2);
            let s_theta4_theta4_ddot = s_theta4 * theta4_ddot;
            let s_theta2_theta2_dot_sq = s_theta2 * theta2_dot.powi(2);
            let c_theta2_theta2_ddot = c_theta2 * theta2_ddot;
            let sum_5 = -s_theta2_theta2_dot_sq + c_theta2_theta2_ddot;
            let s_theta3_theta3_dot_sq = s_theta3 * theta3_dot.powi(2);
            let c_theta3_theta3_ddot = c_theta3 * theta3_ddot;
            let sum_6 = -s_theta3_theta3_dot_sq + c_theta3_theta3_ddot;
            let s_theta4_theta4_dot_sq = s_theta4 * theta4_dot.powi(2);
            let c_theta4_theta4_ddot = c_theta4 * theta4_ddot;
            let mut psi_u = SMatrix::<f64, 2, 2>::zeros();
            psi_u[(0, 0)] = -l3_s_theta3;
            psi_u[(0, 1)] = -l4_s_theta4;
            psi_u[(1, 0)] = l3_c_theta3;
            psi_u[(1, 1)] = l4_c_theta4;
            let mut psi_p = SMatrix::<f64, 2, 4>::zeros();
            psi_p[(0, 0)] = -1.0;
            psi_p[(0, 1)] = c_theta2;
            psi_p[(0, 2)] = c_theta3;
            psi_p[(0, 3)] = c_theta4;
            psi_p[(1, 1)] = s_theta2;
            psi_p[(1, 2)] = s_theta3;
            psi_p[(1, 3)] = s_theta4;
            let mut psi_u_dot = SMatrix::<f64, 2, 2>::zeros();
            psi_u_dot[(0, 0)] = -l3_c_theta3_theta3_dot;
            psi_u_dot[(0, 1)] = -l4_c_theta4_theta4_dot;
            psi_u_dot[(1, 0)] = -l3_s_theta3_theta3_dot;
            psi_u_dot[(1, 1)] = -l4_s_theta4_theta4_dot;
            let mut psi_p_dot = SMatrix::<f64, 2, 4>::zeros();
            psi_p_dot[(0, 1)] = -s_theta2_theta2_dot;
            psi_p_dot[(0, 2)] = -s_theta3_theta3_dot;
            psi_p_dot[(0, 3)] = -s_theta4_theta4_dot;
            psi_p_dot[(1, 1)] = c_theta2_theta2_dot;
            psi_p_dot[(1, 2)] = c_theta3_theta3_dot;
            psi_p_dot[(1, 3)] = c_theta4_theta4_dot;
            let mut psi_u_ddot = SMatrix::<f64, 2, 2>::zeros();
            psi_u_ddot[(0, 0)] = sum;
            psi_u_ddot[(0, 1)] = l4_s_theta4_theta4_dot_sq - l4_c_theta4_theta4_ddot;
            psi_u_ddot[(1, 0)] = sum_2;
            psi_u_ddot[(1, 1)] = -l4_c_theta4_theta4_dot_sq - l4_s_theta4_theta4_ddot;
            let mut psi_p_ddot = SMatrix::<f64, 2, 4>::zeros();
            psi_p_ddot[(0, 1)] = sum_3;
            psi_p_ddot[(0, 2)] = sum_4;
            psi_p_ddot[(0, 3)] = -c_theta4_theta4_dot_sq - s_theta4_theta4_ddot;
            psi_p_ddot[(1, 1)] = sum_5;
            psi_p_ddot[(1, 2)] = sum_6;
            psi_p_ddot[(1, 3)] = -s_theta4_theta4_dot_sq + c_theta4_theta4_ddot;
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
                        Vector2::new(-l3_s_theta3, l3_c_theta3),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-0.5 * l3_s_theta3, 0.5 * l3_c_theta3),
                        Vector2::new(-l3_s_theta3, l3_c_theta3),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-0.5 * l4_s_theta4, 0.5 * l4_c_theta4),
                    ],
                ],
                points_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(0.5 * c_theta2, 0.5 * s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                        Vector2::new(c_theta2, s_theta2),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(c_theta3, s_theta3),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.5 * c_theta3, 0.5 * s_theta3),
                        Vector2::new(c_theta3, s_theta3),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.5 * c_theta4, 0.5 * s_theta4),
                    ],
                ],
                point_velocities_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-l3_c_theta3_theta3_dot, -l3_s_theta3_theta3_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * l3_c_theta3_theta3_dot,
                            -0.5 * l3_s_theta3_theta3_dot,
                        ),
                        Vector2::new(-l3_c_theta3_theta3_dot, -l3_s_theta3_theta3_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * l4_c_theta4_theta4_dot,
                            -0.5 * l4_s_theta4_theta4_dot,
                        ),
                    ],
                ],
                point_velocities_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(
                            -0.5 * s_theta2_theta2_dot,
                            0.5 * c_theta2_theta2_dot,
                        ),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                        Vector2::new(-s_theta2_theta2_dot, c_theta2_theta2_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(-s_theta3_theta3_dot, c_theta3_theta3_dot),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * s_theta3_theta3_dot,
                            0.5 * c_theta3_theta3_dot,
                        ),
                        Vector2::new(-s_theta3_theta3_dot, c_theta3_theta3_dot),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * s_theta4_theta4_dot,
                            0.5 * c_theta4_theta4_dot,
                        ),
                    ],
                ],
                point_accelerations_u: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum, sum_2),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            0.5 * l3_s_theta3_theta3_dot_sq
                                - 0.5 * l3_c_theta3_theta3_ddot,
                            -0.5 * l3_c_theta3_theta3_dot_sq
                                - 0.5 * l3_s_theta3_theta3_ddot,
                        ),
                        Vector2::new(sum, sum_2),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            0.5 * l4_s_theta4_theta4_dot_sq
                                - 0.5 * l4_c_theta4_theta4_ddot,
                            -0.5 * l4_c_theta4_theta4_dot_sq
                                - 0.5 * l4_s_theta4_theta4_ddot,
                        ),
                    ],
                ],
                point_accelerations_p: [
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                    ],
                    [
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(
                            -0.5 * c_theta2_theta2_dot_sq - 0.5 * s_theta2_theta2_ddot,
                            -0.5 * s_theta2_theta2_dot_sq + 0.5 * c_theta2_theta2_ddot,
                        ),
                        Vector2::new(sum_3, sum_5),
                        Vector2::new(sum_3, sum_5),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(sum_4, sum_6),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * c_theta3_theta3_dot_sq - 0.5 * s_theta3_theta3_ddot,
                            -0.5 * s_theta3_theta3_dot_sq + 0.5 * c_theta3_theta3_ddot,
                        ),
                        Vector2::new(sum_4, sum_6),
                    ],
                    [
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, 0.0),
                        Vector2::new(
                            -0.5 * c_theta4_theta4_dot_sq - 0.5 * s_theta4_theta4_ddot,
                            -0.5 * s_theta4_theta4_dot_sq + 0.5 * c_theta4_theta4_ddot,
                        ),
                    ],
                ],
            }
        }
        /// Ψ(u, v) on any dual number of `num_dual`, with the parameters p = [l1, l2, l3, l4] given
        /// as dual numbers too (`params`): derivatives by the parameters by automatic differentiation
        /// (see [`Self::psi_generic`]).
        ///
        /// ```text
        /// [ l2·cos θ2 + l3·cos θ3 + l4·cos θ4 - l1 ]
        /// [ l2·sin θ2 + l3·sin θ3 + l4·sin θ4      ]
        /// ```
        #[must_use]
        #[inline]
        pub fn psi_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 4>,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 2> {
            let l1 = params[0];
            let l2 = params[1];
            let l3 = params[2];
            let l4 = params[3];
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let mut psi = SVector::<D, 2>::zeros();
            psi[0] = l2 * c_theta2 + l3 * c_theta3 + l4 * c_theta4 - l1;
            psi[1] = l2 * s_theta2 + l3 * s_theta3 + l4 * s_theta4;
            psi
        }
        /// The point positions P(q) on any dual number of `num_dual`, with the parameters p = [l1,
        /// l2, l3, l4] given as dual numbers (see [`Self::point_positions`]).
        #[must_use]
        #[inline]
        pub fn point_positions_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 4>,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> [Vector2<D>; 5] {
            let l2 = params[1];
            let l3 = params[2];
            let l4 = params[3];
            let (theta3, theta4) = (u[0], u[1]);
            let theta2 = v[0];
            let (s_theta2, c_theta2) = theta2.sin_cos();
            let b_x = l2 * c_theta2;
            let b_y = l2 * s_theta2;
            let (s_theta3, c_theta3) = theta3.sin_cos();
            let l3_c_theta3 = l3 * c_theta3;
            let c_x = b_x + l3_c_theta3;
            let l3_s_theta3 = l3 * s_theta3;
            let c_y = b_y + l3_s_theta3;
            let g2_x = b_x * 0.5;
            let g2_y = b_y * 0.5;
            let g3_x = b_x + l3_c_theta3 * 0.5;
            let g3_y = b_y + l3_s_theta3 * 0.5;
            let (s_theta4, c_theta4) = theta4.sin_cos();
            let g4_x = b_x + l3_c_theta3 + l4 * c_theta4 * 0.5;
            let g4_y = b_y + l3_s_theta3 + l4 * s_theta4 * 0.5;
            [
                Vector2::new(b_x, b_y),
                Vector2::new(c_x, c_y),
                Vector2::new(g2_x, g2_y),
                Vector2::new(g3_x, g3_y),
                Vector2::new(g4_x, g4_y),
            ]
        }
        /// Every generated quantity as a readable formula, for printing.
        pub const SYMBOLIC: ::linkage::SymbolicTable = ::linkage::SymbolicTable {
            name: "FourBar",
            u: &["θ3", "θ4"],
            v: &["θ2"],
            matrices: &[
                ::linkage::SymbolicMatrix {
                    key: "psi",
                    title: "Ψ",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &[""],
                    nonzero: &[
                        (0, 0, "l2·cos θ2 + l3·cos θ3 + l4·cos θ4 - l1"),
                        (1, 0, "l2·sin θ2 + l3·sin θ3 + l4·sin θ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_q",
                    title: "Ψ_q",
                    rows: 2,
                    cols: 3,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4", "θ2"],
                    nonzero: &[
                        (0, 0, "-l3·sin θ3"),
                        (0, 1, "-l4·sin θ4"),
                        (0, 2, "-l2·sin θ2"),
                        (1, 0, "l3·cos θ3"),
                        (1, 1, "l4·cos θ4"),
                        (1, 2, "l2·cos θ2"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u",
                    title: "Ψ_u",
                    rows: 2,
                    cols: 2,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4"],
                    nonzero: &[
                        (0, 0, "-l3·sin θ3"),
                        (0, 1, "-l4·sin θ4"),
                        (1, 0, "l3·cos θ3"),
                        (1, 1, "l4·cos θ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v",
                    title: "Ψ_v",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ2"],
                    nonzero: &[(0, 0, "-l2·sin θ2"), (1, 0, "l2·cos θ2")],
                },
                ::linkage::SymbolicMatrix {
                    key: "det_psi_u",
                    title: "det Ψ_u",
                    rows: 1,
                    cols: 1,
                    row_labels: &[""],
                    col_labels: &[""],
                    nonzero: &[(0, 0, "-l3·l4·(sin θ3·cos θ4 - cos θ3·sin θ4)")],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_udot_u",
                    title: "([Ψ_u]u\u{307})_u",
                    rows: 2,
                    cols: 2,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4"],
                    nonzero: &[
                        (0, 0, "-l3·cos θ3·θ\u{307}3"),
                        (0, 1, "-l4·cos θ4·θ\u{307}4"),
                        (1, 0, "-l3·sin θ3·θ\u{307}3"),
                        (1, 1, "-l4·sin θ4·θ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_udot_v",
                    title: "([Ψ_u]u\u{307})_v",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ2"],
                    nonzero: &[],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_vdot_u",
                    title: "([Ψ_v]v\u{307})_u",
                    rows: 2,
                    cols: 2,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4"],
                    nonzero: &[],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_vdot_v",
                    title: "([Ψ_v]v\u{307})_v",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ2"],
                    nonzero: &[
                        (0, 0, "-l2·cos θ2·θ\u{307}2"),
                        (1, 0, "-l2·sin θ2·θ\u{307}2"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_dot",
                    title: "Ψ\u{307}_u",
                    rows: 2,
                    cols: 2,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4"],
                    nonzero: &[
                        (0, 0, "-l3·cos θ3·θ\u{307}3"),
                        (0, 1, "-l4·cos θ4·θ\u{307}4"),
                        (1, 0, "-l3·sin θ3·θ\u{307}3"),
                        (1, 1, "-l4·sin θ4·θ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_v_dot",
                    title: "Ψ\u{307}_v",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ2"],
                    nonzero: &[
                        (0, 0, "-l2·cos θ2·θ\u{307}2"),
                        (1, 0, "-l2·sin θ2·θ\u{307}2"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "gamma",
                    title: "γ = (Ψ_q q\u{307})_q q\u{307}",
                    rows: 2,
                    cols: 1,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &[""],
                    nonzero: &[
                        (
                            0,
                            0,
                            "-l3·cos θ3·θ\u{307}3² - l4·cos θ4·θ\u{307}4² - l2·cos θ2·θ\u{307}2²",
                        ),
                        (
                            1,
                            0,
                            "-l3·sin θ3·θ\u{307}3² - l4·sin θ4·θ\u{307}4² - l2·sin θ2·θ\u{307}2²",
                        ),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "points",
                    title: "P",
                    rows: 5,
                    cols: 2,
                    row_labels: &["B", "C", "G2", "G3", "G4"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "l2·cos θ2"),
                        (0, 1, "l2·sin θ2"),
                        (1, 0, "l2·cos θ2 + l3·cos θ3"),
                        (1, 1, "l2·sin θ2 + l3·sin θ3"),
                        (2, 0, "0.5·l2·cos θ2"),
                        (2, 1, "0.5·l2·sin θ2"),
                        (3, 0, "l2·cos θ2 + 0.5·l3·cos θ3"),
                        (3, 1, "l2·sin θ2 + 0.5·l3·sin θ3"),
                        (4, 0, "l2·cos θ2 + l3·cos θ3 + 0.5·l4·cos θ4"),
                        (4, 1, "l2·sin θ2 + l3·sin θ3 + 0.5·l4·sin θ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_velocities",
                    title: "Ṗ",
                    rows: 5,
                    cols: 2,
                    row_labels: &["B", "C", "G2", "G3", "G4"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "-l2·sin θ2·θ\u{307}2"),
                        (0, 1, "l2·cos θ2·θ\u{307}2"),
                        (1, 0, "-l3·sin θ3·θ\u{307}3 - l2·sin θ2·θ\u{307}2"),
                        (1, 1, "l3·cos θ3·θ\u{307}3 + l2·cos θ2·θ\u{307}2"),
                        (2, 0, "-0.5·l2·sin θ2·θ\u{307}2"),
                        (2, 1, "0.5·l2·cos θ2·θ\u{307}2"),
                        (
                            3,
                            0,
                            "-0.5·l3·sin θ3·θ\u{307}3 - l2·sin θ2·θ\u{307}2",
                        ),
                        (3, 1, "0.5·l3·cos θ3·θ\u{307}3 + l2·cos θ2·θ\u{307}2"),
                        (
                            4,
                            0,
                            "-l3·sin θ3·θ\u{307}3 - 0.5·l4·sin θ4·θ\u{307}4 - l2·sin θ2·θ\u{307}2",
                        ),
                        (
                            4,
                            1,
                            "l3·cos θ3·θ\u{307}3 + 0.5·l4·cos θ4·θ\u{307}4 + l2·cos θ2·θ\u{307}2",
                        ),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_accelerations",
                    title: "P\u{308}",
                    rows: 5,
                    cols: 2,
                    row_labels: &["B", "C", "G2", "G3", "G4"],
                    col_labels: &["x", "y"],
                    nonzero: &[
                        (0, 0, "-l2·(cos θ2·θ\u{307}2² + sin θ2·θ\u{308}2)"),
                        (0, 1, "-l2·(sin θ2·θ\u{307}2² - cos θ2·θ\u{308}2)"),
                        (
                            1,
                            0,
                            "-l3·cos θ3·θ\u{307}3² - l2·cos θ2·θ\u{307}2² - l3·sin θ3·θ\u{308}3 - l2·sin θ2·θ\u{308}2",
                        ),
                        (
                            1,
                            1,
                            "-l3·sin θ3·θ\u{307}3² - l2·sin θ2·θ\u{307}2² + l3·cos θ3·θ\u{308}3 + l2·cos θ2·θ\u{308}2",
                        ),
                        (
                            2,
                            0,
                            "-0.5·l2·(cos θ2·θ\u{307}2² + sin θ2·θ\u{308}2)",
                        ),
                        (
                            2,
                            1,
                            "-0.5·l2·(sin θ2·θ\u{307}2² - cos θ2·θ\u{308}2)",
                        ),
                        (
                            3,
                            0,
                            "-0.5·l3·cos θ3·θ\u{307}3² - l2·cos θ2·θ\u{307}2² - 0.5·l3·sin θ3·θ\u{308}3 - l2·sin θ2·θ\u{308}2",
                        ),
                        (
                            3,
                            1,
                            "-0.5·l3·sin θ3·θ\u{307}3² - l2·sin θ2·θ\u{307}2² + 0.5·l3·cos θ3·θ\u{308}3 + l2·cos θ2·θ\u{308}2",
                        ),
                        (
                            4,
                            0,
                            "-l3·cos θ3·θ\u{307}3² - 0.5·l4·cos θ4·θ\u{307}4² - l2·cos θ2·θ\u{307}2² - l3·sin θ3·θ\u{308}3 - 0.5·l4·sin θ4·θ\u{308}4 - l2·sin θ2·θ\u{308}2",
                        ),
                        (
                            4,
                            1,
                            "-l3·sin θ3·θ\u{307}3² - 0.5·l4·sin θ4·θ\u{307}4² - l2·sin θ2·θ\u{307}2² + l3·cos θ3·θ\u{308}3 + 0.5·l4·cos θ4·θ\u{308}4 + l2·cos θ2·θ\u{308}2",
                        ),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p",
                    title: "Ψ_p",
                    rows: 2,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 0, "-1"),
                        (0, 1, "cos θ2"),
                        (0, 2, "cos θ3"),
                        (0, 3, "cos θ4"),
                        (1, 1, "sin θ2"),
                        (1, 2, "sin θ3"),
                        (1, 3, "sin θ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p_dot",
                    title: "Ψ\u{307}_p = (Ψ_q q\u{307})_p",
                    rows: 2,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 1, "-sin θ2·θ\u{307}2"),
                        (0, 2, "-sin θ3·θ\u{307}3"),
                        (0, 3, "-sin θ4·θ\u{307}4"),
                        (1, 1, "cos θ2·θ\u{307}2"),
                        (1, 2, "cos θ3·θ\u{307}3"),
                        (1, 3, "cos θ4·θ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_u_ddot",
                    title: "Ψ\u{308}_u = (Ψ_q q\u{308} + γ)_u",
                    rows: 2,
                    cols: 2,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["θ3", "θ4"],
                    nonzero: &[
                        (0, 0, "l3·(sin θ3·θ\u{307}3² - cos θ3·θ\u{308}3)"),
                        (0, 1, "l4·(sin θ4·θ\u{307}4² - cos θ4·θ\u{308}4)"),
                        (1, 0, "-l3·(cos θ3·θ\u{307}3² + sin θ3·θ\u{308}3)"),
                        (1, 1, "-l4·(cos θ4·θ\u{307}4² + sin θ4·θ\u{308}4)"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "psi_p_ddot",
                    title: "Ψ\u{308}_p = (Ψ_q q\u{308} + γ)_p",
                    rows: 2,
                    cols: 4,
                    row_labels: &["Ψ₁", "Ψ₂"],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 1, "-cos θ2·θ\u{307}2² - sin θ2·θ\u{308}2"),
                        (0, 2, "-cos θ3·θ\u{307}3² - sin θ3·θ\u{308}3"),
                        (0, 3, "-cos θ4·θ\u{307}4² - sin θ4·θ\u{308}4"),
                        (1, 1, "-sin θ2·θ\u{307}2² + cos θ2·θ\u{308}2"),
                        (1, 2, "-sin θ3·θ\u{307}3² + cos θ3·θ\u{308}3"),
                        (1, 3, "-sin θ4·θ\u{307}4² + cos θ4·θ\u{308}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "points_p",
                    title: "P_p",
                    rows: 10,
                    cols: 4,
                    row_labels: &[
                        "B.x",
                        "B.y",
                        "C.x",
                        "C.y",
                        "G2.x",
                        "G2.y",
                        "G3.x",
                        "G3.y",
                        "G4.x",
                        "G4.y",
                    ],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 1, "cos θ2"),
                        (1, 1, "sin θ2"),
                        (2, 1, "cos θ2"),
                        (2, 2, "cos θ3"),
                        (3, 1, "sin θ2"),
                        (3, 2, "sin θ3"),
                        (4, 1, "0.5·cos θ2"),
                        (5, 1, "0.5·sin θ2"),
                        (6, 1, "cos θ2"),
                        (6, 2, "0.5·cos θ3"),
                        (7, 1, "sin θ2"),
                        (7, 2, "0.5·sin θ3"),
                        (8, 1, "cos θ2"),
                        (8, 2, "cos θ3"),
                        (8, 3, "0.5·cos θ4"),
                        (9, 1, "sin θ2"),
                        (9, 2, "sin θ3"),
                        (9, 3, "0.5·sin θ4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_velocities_p",
                    title: "Ṗ_p",
                    rows: 10,
                    cols: 4,
                    row_labels: &[
                        "B.x",
                        "B.y",
                        "C.x",
                        "C.y",
                        "G2.x",
                        "G2.y",
                        "G3.x",
                        "G3.y",
                        "G4.x",
                        "G4.y",
                    ],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 1, "-sin θ2·θ\u{307}2"),
                        (1, 1, "cos θ2·θ\u{307}2"),
                        (2, 1, "-sin θ2·θ\u{307}2"),
                        (2, 2, "-sin θ3·θ\u{307}3"),
                        (3, 1, "cos θ2·θ\u{307}2"),
                        (3, 2, "cos θ3·θ\u{307}3"),
                        (4, 1, "-0.5·sin θ2·θ\u{307}2"),
                        (5, 1, "0.5·cos θ2·θ\u{307}2"),
                        (6, 1, "-sin θ2·θ\u{307}2"),
                        (6, 2, "-0.5·sin θ3·θ\u{307}3"),
                        (7, 1, "cos θ2·θ\u{307}2"),
                        (7, 2, "0.5·cos θ3·θ\u{307}3"),
                        (8, 1, "-sin θ2·θ\u{307}2"),
                        (8, 2, "-sin θ3·θ\u{307}3"),
                        (8, 3, "-0.5·sin θ4·θ\u{307}4"),
                        (9, 1, "cos θ2·θ\u{307}2"),
                        (9, 2, "cos θ3·θ\u{307}3"),
                        (9, 3, "0.5·cos θ4·θ\u{307}4"),
                    ],
                },
                ::linkage::SymbolicMatrix {
                    key: "point_accelerations_p",
                    title: "P\u{308}_p",
                    rows: 10,
                    cols: 4,
                    row_labels: &[
                        "B.x",
                        "B.y",
                        "C.x",
                        "C.y",
                        "G2.x",
                        "G2.y",
                        "G3.x",
                        "G3.y",
                        "G4.x",
                        "G4.y",
                    ],
                    col_labels: &["l1", "l2", "l3", "l4"],
                    nonzero: &[
                        (0, 1, "-cos θ2·θ\u{307}2² - sin θ2·θ\u{308}2"),
                        (1, 1, "-sin θ2·θ\u{307}2² + cos θ2·θ\u{308}2"),
                        (2, 1, "-cos θ2·θ\u{307}2² - sin θ2·θ\u{308}2"),
                        (2, 2, "-cos θ3·θ\u{307}3² - sin θ3·θ\u{308}3"),
                        (3, 1, "-sin θ2·θ\u{307}2² + cos θ2·θ\u{308}2"),
                        (3, 2, "-sin θ3·θ\u{307}3² + cos θ3·θ\u{308}3"),
                        (4, 1, "-0.5·cos θ2·θ\u{307}2² - 0.5·sin θ2·θ\u{308}2"),
                        (5, 1, "-0.5·sin θ2·θ\u{307}2² + 0.5·cos θ2·θ\u{308}2"),
                        (6, 1, "-cos θ2·θ\u{307}2² - sin θ2·θ\u{308}2"),
                        (6, 2, "-0.5·cos θ3·θ\u{307}3² - 0.5·sin θ3·θ\u{308}3"),
                        (7, 1, "-sin θ2·θ\u{307}2² + cos θ2·θ\u{308}2"),
                        (7, 2, "-0.5·sin θ3·θ\u{307}3² + 0.5·cos θ3·θ\u{308}3"),
                        (8, 1, "-cos θ2·θ\u{307}2² - sin θ2·θ\u{308}2"),
                        (8, 2, "-cos θ3·θ\u{307}3² - sin θ3·θ\u{308}3"),
                        (8, 3, "-0.5·cos θ4·θ\u{307}4² - 0.5·sin θ4·θ\u{308}4"),
                        (9, 1, "-sin θ2·θ\u{307}2² + cos θ2·θ\u{308}2"),
                        (9, 2, "-sin θ3·θ\u{307}3² + cos θ3·θ\u{308}3"),
                        (9, 3, "-0.5·sin θ4·θ\u{307}4² + 0.5·cos θ4·θ\u{308}4"),
                    ],
                },
            ],
            methods_agree: ::core::option::Option::Some(true),
            structure: "Ψ_u is one dense block of 2×2.",
        };
    }
    #[automatically_derived]
    impl ::linkage::Kernels<2, 1> for FourBar {
        type Points = [Vector2<f64>; 5];
        #[inline]
        fn u_names(&self) -> [&'static str; 2] {
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
        fn psi(&self, u: &SVector<f64, 2>, v: &SVector<f64, 1>) -> SVector<f64, 2> {
            Self::psi(self, u, v)
        }
        #[inline]
        fn psi_u(&self, u: &SVector<f64, 2>, v: &SVector<f64, 1>) -> SMatrix<f64, 2, 2> {
            Self::psi_u(self, u, v)
        }
        #[inline]
        fn psi_v(&self, u: &SVector<f64, 2>, v: &SVector<f64, 1>) -> SVector<f64, 2> {
            Self::psi_v(self, u, v)
        }
        #[inline]
        fn psi_and_psi_u(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> (SVector<f64, 2>, SMatrix<f64, 2, 2>) {
            Self::psi_and_psi_u(self, u, v)
        }
        #[inline]
        fn psi_u_udot_u(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
        ) -> SMatrix<f64, 2, 2> {
            Self::psi_u_udot_u(self, u, v, udot)
        }
        #[inline]
        fn psi_u_udot_v(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
        ) -> SVector<f64, 2> {
            Self::psi_u_udot_v(self, u, v, udot)
        }
        #[inline]
        fn psi_v_vdot_u(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 2> {
            Self::psi_v_vdot_u(self, u, v, vdot)
        }
        #[inline]
        fn psi_v_vdot_v(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            Self::psi_v_vdot_v(self, u, v, vdot)
        }
        #[inline]
        fn psi_u_dot(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> SMatrix<f64, 2, 2> {
            Self::psi_u_dot(self, u, v, udot, vdot)
        }
        #[inline]
        fn psi_v_dot(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            Self::psi_v_dot(self, u, v, udot, vdot)
        }
        #[inline]
        fn gamma(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> SVector<f64, 2> {
            Self::gamma(self, u, v, udot, vdot)
        }
        #[inline]
        fn point_positions(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            Self::point_positions(self, u, v)
        }
        #[inline]
        fn point_velocities(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            Self::point_velocities(self, u, v, udot, vdot)
        }
        #[inline]
        fn point_accelerations(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> [Vector2<f64>; 5] {
            Self::point_accelerations(self, u, v, udot, vdot, uddot, vddot)
        }
        #[inline]
        fn kinematics(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<2, 1> {
            Self::kinematics(self, u, v, vdot, vddot)
        }
        #[doc(hidden)]
        #[inline]
        fn trig_u(&self) -> [bool; 2] {
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 2],
            trig_v: &[(f64, f64); 1],
            vdot: &SVector<f64, 1>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::Kinematics<2, 1> {
            Self::kinematics_with_trig(self, u, v, trig_u, trig_v, vdot, vddot)
        }
        #[inline]
        fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 2> {
            Self::psi_generic(self, u, v)
        }
        #[inline]
        fn point_positions_generic<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(&self, u: &SVector<D, 2>, v: &SVector<D, 1>) -> impl AsRef<[Vector2<D>]> {
            Self::point_positions_generic(self, u, v)
        }
    }
    #[automatically_derived]
    impl ::linkage::Linkage<2, 1> for FourBar {}
    #[automatically_derived]
    impl ::linkage::SensitivityKernel<2, 1, 4> for FourBar {
        #[inline]
        fn sensitivity_terms(
            &self,
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<2, 4, [Vector2<f64>; 5]> {
            Self::sensitivity_terms(self, u, v, udot, vdot, uddot, vddot)
        }
        #[doc(hidden)]
        #[inline]
        fn sensitivity_trig_u(&self) -> [bool; 2] {
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
            u: &SVector<f64, 2>,
            v: &SVector<f64, 1>,
            trig_u: &[(f64, f64); 2],
            trig_v: &[(f64, f64); 1],
            udot: &SVector<f64, 2>,
            vdot: &SVector<f64, 1>,
            uddot: &SVector<f64, 2>,
            vddot: &SVector<f64, 1>,
        ) -> ::linkage::SensitivityTerms<2, 4, [Vector2<f64>; 5]> {
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
    impl ::linkage::Sensitivities<2, 1, 4> for FourBar {
        #[inline]
        fn param_names(&self) -> [&'static str; 4] {
            Self::PARAM_NAMES
        }
        #[inline]
        fn params(&self) -> SVector<f64, 4> {
            SVector::<f64, 4>::from([self.l1, self.l2, self.l3, self.l4])
        }
        #[inline]
        fn set_params(&mut self, params: &SVector<f64, 4>) {
            self.l1 = params[0];
            self.l2 = params[1];
            self.l3 = params[2];
            self.l4 = params[3];
        }
        #[inline]
        fn psi_p(&self, u: &SVector<f64, 2>, v: &SVector<f64, 1>) -> SMatrix<f64, 2, 4> {
            Self::psi_p(self, u, v)
        }
        #[inline]
        fn psi_generic_params<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
            &self,
            params: &SVector<D, 4>,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> SVector<D, 2> {
            Self::psi_generic_params(self, params, u, v)
        }
        #[inline]
        fn point_positions_generic_params<
            D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy,
        >(
            &self,
            params: &SVector<D, 4>,
            u: &SVector<D, 2>,
            v: &SVector<D, 1>,
        ) -> impl AsRef<[Vector2<D>]> {
            Self::point_positions_generic_params(self, params, u, v)
        }
    }
};

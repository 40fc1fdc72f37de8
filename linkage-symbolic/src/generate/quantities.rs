//! The one table of generated quantities. Each entry says what a generated
//! function is called, what it takes and returns, where its value comes
//! from and where it appears: the inherent items, the `Kernels` impl, the
//! error-path fallback and the symbolic table are all generated from this
//! table, so adding a quantity is one entry here (plus its formula in
//! `crate::derivatives`).

use crate::plan::{Formula, Kernel};

/// An argument of a generated function, after `&self`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arg {
    U,
    V,
    Udot,
    Vdot,
    Uddot,
    Vddot,
    /// (sin uₖ, cos uₖ) per dependent coordinate.
    TrigU,
    /// (sin vₖ, cos vₖ) per driving coordinate.
    TrigV,
    /// The parameters p, on dual numbers.
    Params,
}

/// How many entries an argument has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Length {
    /// One per dependent coordinate (m).
    M,
    /// One per driving coordinate (f).
    F,
    /// One per parameter (k).
    K,
}

impl Arg {
    pub fn name(self) -> &'static str {
        match self {
            Arg::U => "u",
            Arg::V => "v",
            Arg::Udot => "udot",
            Arg::Vdot => "vdot",
            Arg::Uddot => "uddot",
            Arg::Vddot => "vddot",
            Arg::TrigU => "trig_u",
            Arg::TrigV => "trig_v",
            Arg::Params => "params",
        }
    }

    /// How many entries the argument has.
    pub fn length(self) -> Length {
        match self {
            Arg::U | Arg::Udot | Arg::Uddot | Arg::TrigU => Length::M,
            Arg::V | Arg::Vdot | Arg::Vddot | Arg::TrigV => Length::F,
            Arg::Params => Length::K,
        }
    }
}

/// What a generated function returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// m rows (Ψ, γ).
    Column,
    /// m × m (Jacobians with respect to u).
    Square,
    /// m × f (Jacobians with respect to v).
    Wide,
    /// m × (m + f) (Ψ_q).
    Full,
    /// (Ψ, Ψ_u).
    ColumnAndSquare,
    /// One 2-vector per named point.
    Points,
    /// `linkage::Kinematics<m, f>`.
    Kinematics,
    /// m × k (Jacobians with respect to the parameters).
    ByParams,
    /// `linkage::SensitivityTerms<m, k, points>`.
    SensitivityTerms,
}

/// The trait a generated function belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trait {
    /// `linkage::Kernels<m, f>`: the kinematics (the trait under
    /// `linkage::Linkage<m, f>`, whose impl the macro emits empty: its
    /// methods, the analyses, are all provided).
    Kernels,
    /// `linkage::Sensitivities<m, f, k>`: the derivatives by the parameters.
    Sensitivities,
    /// `linkage::SensitivityKernel<m, f, k>`: the generated terms the
    /// sensitivities are solved from, which the runtime calls (hidden from
    /// the documentation: not an entry point).
    SensitivityKernel,
}

/// The number type of a function: `f64`, or any dual number of num-dual
/// (the function is then generic in `D`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scalar {
    F64,
    Dual,
}

/// Where a function's value comes from.
#[derive(Clone, Copy)]
pub enum Source {
    /// One matrix of formulas of the derivatives.
    Formula(Formula),
    /// Ψ and Ψ_u in one evaluation.
    PsiAndPsiU,
    /// The points' positions (0), velocities (1) or accelerations (2).
    Points(usize),
    /// Everything at a pose, the sines and cosines computed or given.
    Kinematics { with_trig: bool },
    /// det Ψ_u: in the symbolic table only.
    Determinant,
    /// Every derivative by u and p the sensitivities need, in one evaluation,
    /// the sines and cosines computed or given.
    SensitivityTerms { with_trig: bool },
    /// The points' explicit derivatives by the parameters: positions (0),
    /// velocities (1), accelerations (2); in the symbolic table only.
    PointsByParams(usize),
}

/// The text a quantity's documentation is written from.
pub struct DocContext {
    pub m: usize,
    pub f: usize,
    /// u, v and q = [u; v] as lists of formula names.
    pub u_list: String,
    pub v_list: String,
    pub q_list: String,
    pub point_list: String,
    /// The parameters p, as a list of formula names.
    pub p_list: String,
    pub k: usize,
    /// Whether the two acceleration methods expand to the same polynomial.
    pub agreement: String,
    /// Ψ_u's diagonal blocks (see [`crate::blocks::Blocks::describe`]).
    pub structure: String,
}

/// One generated quantity.
pub struct Quantity {
    /// The function's name (and its key in the symbolic table unless
    /// `key` says otherwise).
    pub name: &'static str,
    /// How a textbook writes it: the symbolic table's title.
    pub symbol: &'static str,
    pub args: &'static [Arg],
    pub shape: Shape,
    pub scalar: Scalar,
    pub source: Source,
    /// Whether the struct gets a function (false: a table entry only).
    pub function: bool,
    /// The trait that has it, if any.
    pub in_trait: Option<Trait>,
    /// Its key in the symbolic table, if it is listed there.
    pub key: Option<&'static str>,
    /// The first paragraph of its documentation (formulas follow).
    pub doc: fn(&DocContext) -> String,
}

impl Quantity {
    /// The kernel of straight-line f64 code behind its function, if it has
    /// one: what the function computes is the kernel's plan
    /// (`crate::plan`), which the tapes compile too.
    pub fn kernel(&self) -> Option<Kernel> {
        if !self.function || self.scalar != Scalar::F64 {
            return None;
        }
        match self.source {
            Source::Formula(f) => Some(Kernel::Formula(f)),
            Source::PsiAndPsiU => Some(Kernel::PsiAndPsiU),
            Source::Points(level) => Some(Kernel::Points(level)),
            Source::Kinematics { with_trig } => Some(Kernel::Kinematics { with_trig }),
            Source::SensitivityTerms { with_trig } => Some(Kernel::SensitivityTerms { with_trig }),
            Source::Determinant | Source::PointsByParams(_) => None,
        }
    }
}

const U_V: &[Arg] = &[Arg::U, Arg::V];
const U_V_UDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot];
const U_V_VDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Vdot];
const U_V_QDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot, Arg::Vdot];
const U_V_QDOT_QDDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot, Arg::Vdot, Arg::Uddot, Arg::Vddot];
const U_V_VDOT_VDDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Vdot, Arg::Vddot];
const P_U_V: &[Arg] = &[Arg::Params, Arg::U, Arg::V];
const U_V_TRIG_QDOT_QDDOT: &[Arg] = &[
    Arg::U,
    Arg::V,
    Arg::TrigU,
    Arg::TrigV,
    Arg::Udot,
    Arg::Vdot,
    Arg::Uddot,
    Arg::Vddot,
];
const U_V_TRIG_VDOT_VDDOT: &[Arg] = &[
    Arg::U,
    Arg::V,
    Arg::TrigU,
    Arg::TrigV,
    Arg::Vdot,
    Arg::Vddot,
];

/// An f64 function of one matrix of formulas, in the trait and the table.
const fn formula(
    name: &'static str,
    symbol: &'static str,
    args: &'static [Arg],
    shape: Shape,
    matrix: Formula,
    doc: fn(&DocContext) -> String,
) -> Quantity {
    Quantity {
        name,
        symbol,
        args,
        shape,
        scalar: Scalar::F64,
        source: Source::Formula(matrix),
        function: true,
        in_trait: Some(Trait::Kernels),
        key: Some(name),
        doc,
    }
}

/// Every generated quantity, in the order of the generated items.
pub const QUANTITIES: &[Quantity] = &[
    formula("psi", "Ψ", U_V, Shape::Column, Formula::Psi, |_| {
        "Ψ(u, v): the closure equations, zero at every assembled pose.".to_owned()
    }),
    Quantity {
        in_trait: None,
        ..formula("psi_q", "Ψ_q", U_V, Shape::Full, Formula::PsiQ, |c| {
            format!(
                "Ψ_q = ∂Ψ/∂q, the {}×{} Jacobian with columns q = [{}] (u first, then v).",
                c.m,
                c.m + c.f,
                c.q_list
            )
        })
    },
    formula("psi_u", "Ψ_u", U_V, Shape::Square, Formula::PsiU, |c| {
        format!(
            "Ψ_u = ∂Ψ/∂u, the {m}×{m} Jacobian with respect to u = [{}]. {}",
            c.u_list,
            c.structure,
            m = c.m
        )
    }),
    formula("psi_v", "Ψ_v", U_V, Shape::Wide, Formula::PsiV, |c| {
        format!(
            "Ψ_v = ∂Ψ/∂v, the {}×{} Jacobian with respect to v = [{}].",
            c.m, c.f, c.v_list
        )
    }),
    Quantity {
        name: "psi_and_psi_u",
        symbol: "(Ψ, Ψ_u)",
        args: U_V,
        shape: Shape::ColumnAndSquare,
        scalar: Scalar::F64,
        source: Source::PsiAndPsiU,
        function: true,
        in_trait: Some(Trait::Kernels),
        key: None,
        doc: |_| {
            "Ψ and Ψ_u together, sharing every sine, cosine and common subexpression: \
             one Newton–Raphson step's evaluation (see [`Self::psi`] and [`Self::psi_u`])."
                .to_owned()
        },
    },
    Quantity {
        name: "det_psi_u",
        symbol: "det Ψ_u",
        args: U_V,
        shape: Shape::Column,
        scalar: Scalar::F64,
        source: Source::Determinant,
        function: false,
        in_trait: None,
        key: Some("det_psi_u"),
        doc: |_| "det Ψ_u".to_owned(),
    },
    formula(
        "psi_u_udot_u",
        "([Ψ_u]u̇)_u",
        U_V_UDOT,
        Shape::Square,
        Formula::PsiUUdotU,
        |c| {
            format!(
                "([Ψ_u]u̇)_u, the {m}×{m} Jacobian of Ψ_u u̇ with respect to u: the first block of method B.",
                m = c.m
            )
        },
    ),
    formula(
        "psi_u_udot_v",
        "([Ψ_u]u̇)_v",
        U_V_UDOT,
        Shape::Wide,
        Formula::PsiUUdotV,
        |c| {
            format!(
                "([Ψ_u]u̇)_v, the {}×{} Jacobian of Ψ_u u̇ with respect to v (non-zero when Ψ_u depends on v).",
                c.m, c.f
            )
        },
    ),
    formula(
        "psi_v_vdot_u",
        "([Ψ_v]v̇)_u",
        U_V_VDOT,
        Shape::Square,
        Formula::PsiVVdotU,
        |c| {
            format!(
                "([Ψ_v]v̇)_u, the {m}×{m} Jacobian of Ψ_v v̇ with respect to u (non-zero when Ψ_v depends on u).",
                m = c.m
            )
        },
    ),
    formula(
        "psi_v_vdot_v",
        "([Ψ_v]v̇)_v",
        U_V_VDOT,
        Shape::Wide,
        Formula::PsiVVdotV,
        |c| {
            format!(
                "([Ψ_v]v̇)_v, the {}×{} Jacobian of Ψ_v v̇ with respect to v.",
                c.m, c.f
            )
        },
    ),
    formula(
        "psi_u_dot",
        "Ψ̇_u",
        U_V_QDOT,
        Shape::Square,
        Formula::PsiUDot,
        |c| {
            format!(
                "Ψ̇_u = Σₖ ∂Ψ_u/∂qₖ q̇ₖ, the time derivative of Ψ_u ({m}×{m}): method A.",
                m = c.m
            )
        },
    ),
    formula(
        "psi_v_dot",
        "Ψ̇_v",
        U_V_QDOT,
        Shape::Wide,
        Formula::PsiVDot,
        |c| {
            format!(
                "Ψ̇_v = Σₖ ∂Ψ_v/∂qₖ q̇ₖ, the time derivative of Ψ_v ({}×{}): method A.",
                c.m, c.f
            )
        },
    ),
    formula(
        "gamma",
        "γ = (Ψ_q q̇)_q q̇",
        U_V_QDOT,
        Shape::Column,
        Formula::Gamma,
        |c| {
            format!(
                "γ = (Ψ_q q̇)_q q̇, the convective term of the acceleration equation \
                 Ψ_u ü = −Ψ_v v̈ − γ, in one fused evaluation.\n\n{}",
                c.agreement
            )
        },
    ),
    points("point_positions", "points", "P", U_V, 0, |c| {
        format!("The positions P(q) of the points [{}].", c.point_list)
    }),
    points(
        "point_velocities",
        "point_velocities",
        "Ṗ",
        U_V_QDOT,
        1,
        |c| format!("The velocities Ṗ = P_q q̇ of the points [{}].", c.point_list),
    ),
    points(
        "point_accelerations",
        "point_accelerations",
        "P̈",
        U_V_QDOT_QDDOT,
        2,
        |c| {
            format!(
                "The accelerations P̈ = P_q q̈ + (P_q q̇)_q q̇ of the points [{}].",
                c.point_list
            )
        },
    ),
    Quantity {
        name: "kinematics",
        symbol: "Ψ, Ψ_u, Ψ_v, u̇, ü",
        args: U_V_VDOT_VDDOT,
        shape: Shape::Kinematics,
        scalar: Scalar::F64,
        source: Source::Kinematics { with_trig: false },
        function: true,
        in_trait: Some(Trait::Kernels),
        key: None,
        doc: |_| {
            "Everything at one pose in one pass: Ψ, Ψ_u and Ψ_v; the velocity \
             u̇ = −Ψ_u⁻¹Ψ_v v̇; γ = (Ψ_q q̇)_q q̇ at that velocity; and the \
             acceleration ü = −Ψ_u⁻¹(Ψ_v v̈ + γ). Each sine and cosine, and each \
             subexpression shared between these, is computed once: the fast path \
             of the runtime's analyses and sweeps."
                .to_owned()
        },
    },
    Quantity {
        name: "kinematics_with_trig",
        symbol: "Ψ, Ψ_u, Ψ_v, u̇, ü",
        args: U_V_TRIG_VDOT_VDDOT,
        shape: Shape::Kinematics,
        scalar: Scalar::F64,
        source: Source::Kinematics { with_trig: true },
        function: true,
        in_trait: Some(Trait::Kernels),
        key: None,
        doc: |_| {
            "[`Self::kinematics`] with the sines and cosines of the coordinates \
             given (`trig_u[k]` = (sin uₖ, cos uₖ), likewise `trig_v`) instead of \
             computed: a sweep carries them from pose to pose by the angle-addition \
             formulas, which costs a few multiplications instead of a transcendental \
             call."
                .to_owned()
        },
    },
    Quantity {
        name: "psi_generic",
        symbol: "Ψ",
        args: U_V,
        shape: Shape::Column,
        scalar: Scalar::Dual,
        source: Source::Formula(Formula::Psi),
        function: true,
        in_trait: Some(Trait::Kernels),
        key: None,
        doc: |_| {
            "Ψ(u, v) on any dual number of `num_dual`: the same closure equations as \
             [`Self::psi`], for derivatives by automatic differentiation (cross-checks, \
             and the alternative Jacobian source of the runtime)."
                .to_owned()
        },
    },
    Quantity {
        name: "point_positions_generic",
        symbol: "P",
        args: U_V,
        shape: Shape::Points,
        scalar: Scalar::Dual,
        source: Source::Points(0),
        function: true,
        in_trait: Some(Trait::Kernels),
        key: None,
        doc: |_| {
            "The point positions P(q) on any dual number of `num_dual` (see \
             [`Self::point_positions`])."
                .to_owned()
        },
    },
    Quantity {
        in_trait: Some(Trait::Sensitivities),
        ..formula("psi_p", "Ψ_p", U_V, Shape::ByParams, Formula::PsiP, |c| {
            format!(
                "Ψ_p = ∂Ψ/∂p, the {}×{} Jacobian with respect to the parameters p = [{}]: \
                     the position sensitivities are u_p = −Ψ_u⁻¹Ψ_p.",
                c.m, c.k, c.p_list
            )
        })
    },
    table_only(
        "psi_p_dot",
        "Ψ̇_p = (Ψ_q q̇)_p",
        Shape::ByParams,
        Formula::PsiPDot,
    ),
    table_only(
        "psi_u_ddot",
        "Ψ̈_u = (Ψ_q q̈ + γ)_u",
        Shape::Square,
        Formula::PsiUDdot,
    ),
    table_only(
        "psi_p_ddot",
        "Ψ̈_p = (Ψ_q q̈ + γ)_p",
        Shape::ByParams,
        Formula::PsiPDdot,
    ),
    points_by_params("points_p", "P_p", 0),
    points_by_params("point_velocities_p", "Ṗ_p", 1),
    points_by_params("point_accelerations_p", "P̈_p", 2),
    Quantity {
        name: "sensitivity_terms",
        symbol: "Ψ_u, Ψ_p, Ψ̇_u, Ψ̇_p, Ψ̈_u, Ψ̈_p, P_u, P_p, …",
        args: U_V_QDOT_QDDOT,
        shape: Shape::SensitivityTerms,
        scalar: Scalar::F64,
        source: Source::SensitivityTerms { with_trig: false },
        function: true,
        in_trait: Some(Trait::SensitivityKernel),
        key: None,
        doc: |c| {
            format!(
                "Every term the sensitivities to the parameters p = [{}] need, at a pose in \
                 motion, in one pass sharing each sine, cosine and subexpression: Ψ_u, Ψ_p, \
                 their first and second time derivatives Ψ̇_u = (Ψ_q q̇)_u, Ψ̇_p = (Ψ_q q̇)_p, \
                 Ψ̈_u = (Ψ_q q̈ + γ)_u, Ψ̈_p = (Ψ_q q̈ + γ)_p, and the same of every point \
                 (P_u, Ṗ_u, P̈_u and P_p, Ṗ_p, P̈_p, the explicit derivatives of P, Ṗ, P̈). \
                 Differentiating Ψ_u u_p + Ψ_p = 0 in time twice gives the sensitivities \
                 (see `linkage::Sensitivities`):\n\n\
                 ```text\n\
                 u_p = −Ψ_u⁻¹ Ψ_p\n\
                 u̇_p = −Ψ_u⁻¹ (Ψ̇_u u_p + Ψ̇_p)\n\
                 ü_p = −Ψ_u⁻¹ (Ψ̈_u u_p + 2 Ψ̇_u u̇_p + Ψ̈_p)\n\
                 ```",
                c.p_list
            )
        },
    },
    Quantity {
        name: "sensitivity_terms_with_trig",
        symbol: "Ψ_u, Ψ_p, Ψ̇_u, Ψ̇_p, Ψ̈_u, Ψ̈_p, P_u, P_p, …",
        args: U_V_TRIG_QDOT_QDDOT,
        shape: Shape::SensitivityTerms,
        scalar: Scalar::F64,
        source: Source::SensitivityTerms { with_trig: true },
        function: true,
        in_trait: Some(Trait::SensitivityKernel),
        key: None,
        doc: |_| {
            "[`Self::sensitivity_terms`] with the sines and cosines of the coordinates \
             given (`trig_u[k]` = (sin uₖ, cos uₖ), likewise `trig_v`; those of \
             [`Self::SENSITIVITY_TRIG_U`] and [`Self::SENSITIVITY_TRIG_V`] are read) \
             instead of computed: a sweep carries them from pose to pose, as it does \
             for [`Self::kinematics_with_trig`]."
                .to_owned()
        },
    },
    Quantity {
        name: "psi_generic_params",
        symbol: "Ψ",
        args: P_U_V,
        shape: Shape::Column,
        scalar: Scalar::Dual,
        source: Source::Formula(Formula::Psi),
        function: true,
        in_trait: Some(Trait::Sensitivities),
        key: None,
        doc: |c| {
            format!(
                "Ψ(u, v) on any dual number of `num_dual`, with the parameters p = [{}] given \
                 as dual numbers too (`params`): derivatives by the parameters by automatic \
                 differentiation (see [`Self::psi_generic`]).",
                c.p_list
            )
        },
    },
    Quantity {
        name: "point_positions_generic_params",
        symbol: "P",
        args: P_U_V,
        shape: Shape::Points,
        scalar: Scalar::Dual,
        source: Source::Points(0),
        function: true,
        in_trait: Some(Trait::Sensitivities),
        key: None,
        doc: |c| {
            format!(
                "The point positions P(q) on any dual number of `num_dual`, with the \
                 parameters p = [{}] given as dual numbers (see [`Self::point_positions`]).",
                c.p_list
            )
        },
    },
];

/// A matrix of formulas listed in the symbolic table only.
const fn table_only(
    key: &'static str,
    symbol: &'static str,
    shape: Shape,
    matrix: Formula,
) -> Quantity {
    Quantity {
        name: key,
        symbol,
        args: U_V_QDOT_QDDOT,
        shape,
        scalar: Scalar::F64,
        source: Source::Formula(matrix),
        function: false,
        in_trait: None,
        key: Some(key),
        doc: |_| String::new(),
    }
}

/// The points' explicit derivatives by the parameters, in the symbolic
/// table only.
const fn points_by_params(key: &'static str, symbol: &'static str, pick: usize) -> Quantity {
    Quantity {
        name: key,
        symbol,
        args: U_V_QDOT_QDDOT,
        shape: Shape::Points,
        scalar: Scalar::F64,
        source: Source::PointsByParams(pick),
        function: false,
        in_trait: None,
        key: Some(key),
        doc: |_| String::new(),
    }
}

/// An f64 function of the points, in the trait and the table.
const fn points(
    name: &'static str,
    key: &'static str,
    symbol: &'static str,
    args: &'static [Arg],
    pick: usize,
    doc: fn(&DocContext) -> String,
) -> Quantity {
    Quantity {
        name,
        symbol,
        args,
        shape: Shape::Points,
        scalar: Scalar::F64,
        source: Source::Points(pick),
        function: true,
        in_trait: Some(Trait::Kernels),
        key: Some(key),
        doc,
    }
}

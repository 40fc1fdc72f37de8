//! What each f64 function of straight-line code computes, in one place
//! for the attribute's generator (`linkage-macros`) and for the tapes
//! ([`crate::tape`]) that evaluate the same statements without a compiler:
//! which matrices' nonzero entries are its outputs and in what order, which
//! nodes it always names (hints), in how many phases it runs, which symbols
//! the caller binds between phases, and whether the sines and cosines of
//! the coordinates come from the caller.

use crate::dag::{Dag, Id, Symbol};
use crate::derivatives::{Derivatives, Matrix};
use crate::emit::{Mode, Phased, TrigSource, emit_phases};
use crate::names::SymbolNames;
use crate::tape::{Form, Part};
use quote::format_ident;

/// A matrix of formulas of the derivatives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Formula {
    Psi,
    PsiQ,
    PsiU,
    PsiV,
    PsiUUdotU,
    PsiUUdotV,
    PsiVVdotU,
    PsiVVdotV,
    PsiUDot,
    PsiVDot,
    Gamma,
    PsiP,
    PsiPDot,
    PsiUDdot,
    PsiPDdot,
}

impl Formula {
    /// The matrix of the model.
    pub fn of(self, d: &Derivatives) -> &Matrix {
        use Formula::*;
        match self {
            Psi => &d.psi,
            PsiQ => &d.psi_q,
            PsiU => &d.psi_u,
            PsiV => &d.psi_v,
            PsiUUdotU => &d.psi_u_udot_u,
            PsiUUdotV => &d.psi_u_udot_v,
            PsiVVdotU => &d.psi_v_vdot_u,
            PsiVVdotV => &d.psi_v_vdot_v,
            PsiUDot => &d.psi_u_dot,
            PsiVDot => &d.psi_v_dot,
            Gamma => &d.gamma,
            PsiP => &d.psi_p,
            PsiPDot => &d.psi_p_dot,
            PsiUDdot => &d.psi_u_ddot,
            PsiPDdot => &d.psi_p_ddot,
        }
    }

    /// Its name in generated code (the function's, the local's, the
    /// field's).
    pub fn name(self) -> &'static str {
        use Formula::*;
        match self {
            Psi => "psi",
            PsiQ => "psi_q",
            PsiU => "psi_u",
            PsiV => "psi_v",
            PsiUUdotU => "psi_u_udot_u",
            PsiUUdotV => "psi_u_udot_v",
            PsiVVdotU => "psi_v_vdot_u",
            PsiVVdotV => "psi_v_vdot_v",
            PsiUDot => "psi_u_dot",
            PsiVDot => "psi_v_dot",
            Gamma => "gamma",
            PsiP => "psi_p",
            PsiPDot => "psi_p_dot",
            PsiUDdot => "psi_u_ddot",
            PsiPDdot => "psi_p_ddot",
        }
    }
}

/// An f64 function of straight-line code the attribute generates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kernel {
    /// One matrix of formulas.
    Formula(Formula),
    /// Ψ and Ψ_u in one evaluation.
    PsiAndPsiU,
    /// The points' positions (0), velocities (1) or accelerations (2).
    Points(usize),
    /// Ψ, Ψ_u and Ψ_v (phase 0), then γ at the velocity u̇ the caller
    /// solved for in between (phase 1); the sines and cosines computed or
    /// given.
    Kinematics { with_trig: bool },
    /// Every derivative by u and by p the sensitivities need, in one
    /// evaluation; the sines and cosines computed or given.
    SensitivityTerms { with_trig: bool },
    /// Those of the positions alone — Ψ_u, Ψ_p and the points' derivatives
    /// by u and by p — the sines and cosines given: what the sensitivities
    /// of the positions need (a synthesis reads no more). Its plan is the
    /// whole terms' (given the sines and cosines), of which it outputs
    /// these parts ([`Kernel::kept_parts`]): the same operations, as far as
    /// these need them, so the same numbers to the bit. A run-time
    /// mechanism's alone: the attribute does not generate it (a compiled
    /// mechanism reads them from [`Kernel::SensitivityTerms`]).
    PositionSensitivityTerms,
    /// The points' positions, velocities and accelerations in one
    /// evaluation, the sines and cosines given: what an analysis reads at
    /// its pose, where it has them. Its plan is the three levels' plans in
    /// one phase: the same operations, each computed once, so the same
    /// numbers to the bit. A run-time mechanism's alone (a compiled
    /// mechanism's three functions compute their sines and cosines in
    /// line).
    PointMotion,
}

/// The sensitivities' matrices, in the order of their outputs.
const SENSITIVITY_MATRICES: [Formula; 6] = [
    Formula::PsiU,
    Formula::PsiP,
    Formula::PsiUDot,
    Formula::PsiPDot,
    Formula::PsiUDdot,
    Formula::PsiPDdot,
];

/// The position sensitivities' parts, of those of the sensitivities.
const POSITION_SENSITIVITY_PARTS: [&str; 4] = ["psi_u", "psi_p", "points_u", "points_p"];

/// The sensitivities' point derivatives after the matrices: their names,
/// level (position, velocity, acceleration) and whether by p (else by u).
const SENSITIVITY_POINTS: [(&str, usize, bool); 6] = [
    ("points_u", 0, false),
    ("points_p", 0, true),
    ("point_velocities_u", 1, false),
    ("point_velocities_p", 1, true),
    ("point_accelerations_u", 2, false),
    ("point_accelerations_p", 2, true),
];

impl Kernel {
    /// Every kernel, in the order of the generated items.
    pub const ALL: [Kernel; 20] = [
        Kernel::Formula(Formula::Psi),
        Kernel::Formula(Formula::PsiQ),
        Kernel::Formula(Formula::PsiU),
        Kernel::Formula(Formula::PsiV),
        Kernel::PsiAndPsiU,
        Kernel::Formula(Formula::PsiUUdotU),
        Kernel::Formula(Formula::PsiUUdotV),
        Kernel::Formula(Formula::PsiVVdotU),
        Kernel::Formula(Formula::PsiVVdotV),
        Kernel::Formula(Formula::PsiUDot),
        Kernel::Formula(Formula::PsiVDot),
        Kernel::Formula(Formula::Gamma),
        Kernel::Points(0),
        Kernel::Points(1),
        Kernel::Points(2),
        Kernel::Kinematics { with_trig: false },
        Kernel::Kinematics { with_trig: true },
        Kernel::Formula(Formula::PsiP),
        Kernel::SensitivityTerms { with_trig: false },
        Kernel::SensitivityTerms { with_trig: true },
    ];

    /// The kernels of run-time mechanisms alone, placed after
    /// [`Kernel::ALL`]'s.
    pub const RUN_TIME: [Kernel; 2] = [Kernel::PositionSensitivityTerms, Kernel::PointMotion];

    /// The parts of its plan it outputs, if not every part.
    pub fn kept_parts(self) -> Option<&'static [&'static str]> {
        match self {
            Kernel::PositionSensitivityTerms => Some(&POSITION_SENSITIVITY_PARTS),
            _ => None,
        }
    }

    /// Every kernel, in the order of their indices ([`Kernel::index`]):
    /// [`Kernel::ALL`], then [`Kernel::RUN_TIME`].
    pub fn every() -> impl Iterator<Item = Kernel> {
        Kernel::ALL.into_iter().chain(Kernel::RUN_TIME)
    }

    /// Its place in [`Kernel::ALL`] followed by [`Kernel::RUN_TIME`], without a search (`None` for a formula
    /// only the sensitivities' kernel computes, which has no function of
    /// its own).
    pub fn index(self) -> Option<usize> {
        let k = match self {
            Kernel::Formula(Formula::Psi) => 0,
            Kernel::Formula(Formula::PsiQ) => 1,
            Kernel::Formula(Formula::PsiU) => 2,
            Kernel::Formula(Formula::PsiV) => 3,
            Kernel::PsiAndPsiU => 4,
            Kernel::Formula(Formula::PsiUUdotU) => 5,
            Kernel::Formula(Formula::PsiUUdotV) => 6,
            Kernel::Formula(Formula::PsiVVdotU) => 7,
            Kernel::Formula(Formula::PsiVVdotV) => 8,
            Kernel::Formula(Formula::PsiUDot) => 9,
            Kernel::Formula(Formula::PsiVDot) => 10,
            Kernel::Formula(Formula::Gamma) => 11,
            Kernel::Points(0) => 12,
            Kernel::Points(1) => 13,
            Kernel::Points(_) => 14,
            Kernel::Kinematics { with_trig: false } => 15,
            Kernel::Kinematics { with_trig: true } => 16,
            Kernel::Formula(Formula::PsiP) => 17,
            Kernel::SensitivityTerms { with_trig: false } => 18,
            Kernel::SensitivityTerms { with_trig: true } => 19,
            Kernel::PositionSensitivityTerms => 20,
            Kernel::PointMotion => 21,
            Kernel::Formula(Formula::PsiPDot | Formula::PsiUDdot | Formula::PsiPDdot) => {
                return None;
            }
        };
        Some(k)
    }

    /// The generated function's name.
    pub fn name(self) -> &'static str {
        match self {
            Kernel::Formula(f) => f.name(),
            Kernel::PsiAndPsiU => "psi_and_psi_u",
            Kernel::Points(level) => {
                ["point_positions", "point_velocities", "point_accelerations"][level.min(2)]
            }
            Kernel::Kinematics { with_trig: false } => "kinematics",
            Kernel::Kinematics { with_trig: true } => "kinematics_with_trig",
            Kernel::SensitivityTerms { with_trig: false } => "sensitivity_terms",
            Kernel::SensitivityTerms { with_trig: true } => "sensitivity_terms_with_trig",
            Kernel::PositionSensitivityTerms => "position_sensitivity_terms",
            Kernel::PointMotion => "point_motion_with_trig",
        }
    }

    /// What the kernel computes for a model.
    pub fn plan(self, model: &Derivatives) -> Plan {
        match self {
            Kernel::Formula(f) => Plan::single(vec![matrix_part(f.name(), f.of(model))]),
            Kernel::PsiAndPsiU => Plan::single(vec![
                matrix_part("psi", &model.psi),
                matrix_part("psi_u", &model.psi_u),
            ]),
            Kernel::Points(level) => points_plan(model, level.min(2)),
            Kernel::Kinematics { with_trig } => {
                let first = [Formula::Psi, Formula::PsiU, Formula::PsiV]
                    .map(|f| matrix_part(f.name(), f.of(model)));
                let second = matrix_part("gamma", &model.gamma);
                Plan {
                    phases: vec![Vec::from(first), vec![second]],
                    hints: Vec::new(),
                    // The velocities u̇, solved for after phase 0.
                    late: (0..model.m()).map(|k| Symbol::Vel(k as u16)).collect(),
                    trig: with_trig,
                }
            }
            Kernel::SensitivityTerms { with_trig } => {
                let mut parts: Vec<PlannedPart> = SENSITIVITY_MATRICES
                    .iter()
                    .map(|f| matrix_part(f.name(), f.of(model)))
                    .collect();
                for (name, level, by_params) in SENSITIVITY_POINTS {
                    parts.push(point_columns_part(model, name, level, by_params));
                }
                Plan {
                    phases: vec![parts],
                    hints: Vec::new(),
                    late: Vec::new(),
                    trig: with_trig,
                }
            }
            Kernel::PositionSensitivityTerms => {
                Kernel::SensitivityTerms { with_trig: true }.plan(model)
            }
            Kernel::PointMotion => {
                let (mut parts, mut hints) = (Vec::new(), Vec::<(Id, String)>::new());
                for level in 0..3 {
                    let plan = points_plan(model, level);
                    parts.extend(plan.phases.into_iter().flatten());
                    // A node named at one level keeps its first name (a
                    // point at rest: its velocity and acceleration zero).
                    for (id, name) in plan.hints {
                        if hints.iter().all(|(named, _)| *named != id) {
                            hints.push((id, name));
                        }
                    }
                }
                Plan {
                    phases: vec![parts],
                    hints,
                    late: Vec::new(),
                    trig: true,
                }
            }
        }
    }
}

/// One output of a plan: a part of the result and the nodes filling its
/// entries, in the order of [`Part::entries`].
pub struct PlannedPart {
    pub part: Part,
    pub roots: Vec<Id>,
}

/// What one kernel computes: its phases, each a list of result parts.
pub struct Plan {
    /// The parts of each phase; the roots of a phase are its parts' roots
    /// in order. Each phase may use everything computed before it.
    pub phases: Vec<Vec<PlannedPart>>,
    /// Nodes always bound to a `let`, under these names (the points'
    /// coordinates).
    pub hints: Vec<(Id, String)>,
    /// The symbols the caller binds between phase 0 and phase 1 (the
    /// velocities u̇ of `kinematics`).
    pub late: Vec<Symbol>,
    /// Whether the sines and cosines of the coordinates are read from the
    /// arguments `trig_u` and `trig_v` instead of computed.
    pub trig: bool,
}

impl Plan {
    fn single(parts: Vec<PlannedPart>) -> Plan {
        Plan {
            phases: vec![parts],
            hints: Vec::new(),
            late: Vec::new(),
            trig: false,
        }
    }

    /// The roots of each phase, in the order of its outputs.
    pub fn roots(&self) -> Vec<Vec<Id>> {
        self.phases
            .iter()
            .map(|parts| parts.iter().flat_map(|p| p.roots.iter().copied()).collect())
            .collect()
    }

    /// The names of the arguments the sines and cosines are read from:
    /// `trig_u` and `trig_v`, unless a symbol has the name.
    pub fn trig_names(names: &SymbolNames) -> [String; 2] {
        [free_name(names, "trig_u"), free_name(names, "trig_v")]
    }

    /// The straight-line code of the plan: `reserved` are the names the
    /// function's own code binds, which temporaries avoid.
    pub fn emit(&self, dag: &Dag, names: &SymbolNames, reserved: &[String], mode: Mode) -> Phased {
        let roots = self.roots();
        let phases: Vec<&[Id]> = roots.iter().map(Vec::as_slice).collect();
        let [u, v] = Plan::trig_names(names);
        let source = TrigSource {
            u: format_ident!("{}", u),
            v: format_ident!("{}", v),
            m: names.m(),
        };
        emit_phases(
            dag,
            names,
            &phases,
            &self.hints,
            reserved,
            mode,
            &self.late,
            self.trig.then_some(&source),
        )
    }
}

/// `name`, unless a symbol already has it: then with `_` appended until
/// free.
pub fn free_name(names: &SymbolNames, name: &str) -> String {
    let taken: Vec<String> = names.all_code().collect();
    let mut candidate = name.to_owned();
    while taken.contains(&candidate) {
        candidate.push('_');
    }
    candidate
}

/// A matrix's nonzero entries, row by row.
fn matrix_part(name: &'static str, matrix: &Matrix) -> PlannedPart {
    let mut entries = Vec::new();
    let mut roots = Vec::new();
    for i in 0..matrix.rows {
        for j in 0..matrix.cols {
            let e = matrix.get(i, j);
            if e != Dag::ZERO {
                entries.push((i, j));
                roots.push(e);
            }
        }
    }
    PlannedPart {
        part: Part {
            name,
            form: Form::Matrix,
            rows: matrix.rows,
            cols: matrix.cols,
            entries,
        },
        roots,
    }
}

/// The points' positions, velocities or accelerations: every coordinate,
/// zero or not, each named after its point (`b_x`, `c_y_dot`).
fn points_plan(model: &Derivatives, level: usize) -> Plan {
    let suffix = ["", "_dot", "_ddot"][level];
    let mut entries = Vec::new();
    let mut roots = Vec::new();
    let mut hints = Vec::new();
    for (i, p) in model.points.iter().enumerate() {
        let l = p.name.to_lowercase();
        let ids = [p.position, p.velocity, p.acceleration][level];
        for (c, axis) in ["x", "y"].iter().enumerate() {
            entries.push((i, c));
            roots.push(ids[c]);
            hints.push((ids[c], format!("{l}_{axis}{suffix}")));
        }
    }
    let name = Kernel::Points(level).name();
    Plan {
        phases: vec![vec![PlannedPart {
            part: Part {
                name,
                form: Form::Points,
                rows: model.points.len(),
                cols: 2,
                entries,
            },
            roots,
        }]],
        hints,
        late: Vec::new(),
        trig: false,
    }
}

/// A level of the points' derivatives by u or by p: column by column, one
/// (x, y) per point, the nonzero ones.
fn point_columns_part(
    model: &Derivatives,
    name: &'static str,
    level: usize,
    by_params: bool,
) -> PlannedPart {
    let cols = if by_params { model.k() } else { model.m() };
    let mut entries = Vec::new();
    let mut roots = Vec::new();
    for j in 0..cols {
        for (i, p) in model.points.iter().enumerate() {
            let matrix = if by_params {
                &p.by_p[level]
            } else {
                &p.by_u[level]
            };
            for c in 0..2 {
                let e = matrix.get(c, j);
                if e != Dag::ZERO {
                    entries.push((2 * i + c, j));
                    roots.push(e);
                }
            }
        }
    }
    PlannedPart {
        part: Part {
            name,
            form: Form::PointColumns,
            rows: 2 * model.points.len(),
            cols,
            entries,
        },
        roots,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kernel_knows_its_place() {
        for (k, kernel) in Kernel::every().enumerate() {
            assert_eq!(kernel.index(), Some(k), "{}", kernel.name());
        }
        for inside in [Formula::PsiPDot, Formula::PsiUDdot, Formula::PsiPDdot] {
            assert_eq!(Kernel::Formula(inside).index(), None);
        }
    }

    /// The position sensitivities' kernel is the whole terms' (given the
    /// sines and cosines), of which it keeps four parts, all of them parts
    /// of the whole.
    #[cfg(feature = "text")]
    #[test]
    fn the_position_terms_are_parts_of_the_whole_terms() {
        use crate::text::{Equations, Parameter, build};
        let equations = "u = [t3, t4], v = [t2], \
            points = [B = (l2 * t2.cos(), l2 * t2.sin()), P = (B.x + a * t3.cos(), B.y + a * t3.sin())], \
            closure = [l2 * t2.cos() + l3 * t3.cos() + l4 * t4.cos() - l1, \
            l2 * t2.sin() + l3 * t3.sin() + l4 * t4.sin()]";
        let parameters = ["l1", "l2", "l3", "l4", "a"].map(Parameter::new);
        let model = build("FourBar", Equations::new(equations), &parameters)
            .expect("reads")
            .derivatives;
        let whole = Kernel::SensitivityTerms { with_trig: true }.plan(&model);
        let position = Kernel::PositionSensitivityTerms.plan(&model);
        assert!(position.trig);
        assert_eq!(position.roots(), whole.roots());
        let names: Vec<&str> = whole.phases[0].iter().map(|p| p.part.name).collect();
        let kept = Kernel::PositionSensitivityTerms.kept_parts().expect("some");
        assert_eq!(kept, ["psi_u", "psi_p", "points_u", "points_p"]);
        assert!(kept.iter().all(|k| names.contains(k)));
        assert_eq!(
            Kernel::SensitivityTerms { with_trig: true }.kept_parts(),
            None
        );
    }
}

//! Stage 3: every symbolic output, derived from the lowered closure
//! equations and points in one shared DAG.
//!
//! With q = [u; v] and q̇ = [u̇; v̇]:
//!
//! * Ψ_q = ∂Ψ/∂q, split into Ψ_u and Ψ_v;
//! * method B: the Jacobians of Ψ_u u̇ and Ψ_v v̇ with respect to u and v;
//! * method A: Ψ̇_u = Σₖ ∂Ψ_u/∂qₖ q̇ₖ and Ψ̇_v likewise;
//! * γ = (Ψ_q q̇)_q q̇, the fused second-order term;
//! * for each point P: P, Ṗ = P_q q̇ and P̈ = P_q q̈ + (P_q q̇)_q q̇;
//! * for the sensitivities to the parameters p: Ψ_p, and the explicit
//!   partial derivatives by u and by p of Ψ̇ = Ψ_q q̇ and Ψ̈ = Ψ_q q̈ + γ
//!   (which are the time derivatives of Ψ_u and Ψ_p: Ψ̇_u, Ψ̇_p, Ψ̈_u, Ψ̈_p),
//!   and likewise of every point's P, Ṗ and P̈.

use crate::blocks::Blocks;
use crate::dag::{Dag, Id, Symbol};
use crate::lower::Lowered;

/// A dense matrix of DAG nodes, row-major.
#[derive(Clone, Debug)]
pub struct Matrix {
    pub rows: usize,
    pub cols: usize,
    pub entries: Vec<Id>,
}

impl Matrix {
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> Id) -> Matrix {
        let mut entries = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                entries.push(f(i, j));
            }
        }
        Matrix {
            rows,
            cols,
            entries,
        }
    }

    pub fn column(entries: Vec<Id>) -> Matrix {
        Matrix {
            rows: entries.len(),
            cols: 1,
            entries,
        }
    }

    pub fn get(&self, i: usize, j: usize) -> Id {
        self.entries[i * self.cols + j]
    }
}

/// A point and its kinematics.
pub struct PointKinematics {
    pub name: String,
    pub position: [Id; 2],
    pub velocity: [Id; 2],
    pub acceleration: [Id; 2],
    /// P_u, Ṗ_u and P̈_u (2 × m, rows x and y): the explicit derivatives by
    /// u of the position, velocity and acceleration, which are P_u and its
    /// first and second time derivatives.
    pub by_u: [Matrix; 3],
    /// P_p, Ṗ_p and P̈_p (2 × k), likewise by the parameters.
    pub by_p: [Matrix; 3],
}

/// Every output of the macro, as DAG nodes.
pub struct Derivatives {
    pub lowered: Lowered,
    pub psi: Matrix,
    pub psi_q: Matrix,
    pub psi_u: Matrix,
    pub psi_v: Matrix,
    pub psi_u_udot_u: Matrix,
    pub psi_u_udot_v: Matrix,
    pub psi_v_vdot_u: Matrix,
    pub psi_v_vdot_v: Matrix,
    pub psi_u_dot: Matrix,
    pub psi_v_dot: Matrix,
    pub gamma: Matrix,
    /// Ψ_p (m × k).
    pub psi_p: Matrix,
    /// Ψ̇_p = (Ψ_q q̇)_p (m × k).
    pub psi_p_dot: Matrix,
    /// Ψ̈_u = (Ψ_q q̈ + γ)_u (m × m).
    pub psi_u_ddot: Matrix,
    /// Ψ̈_p = (Ψ_q q̈ + γ)_p (m × k).
    pub psi_p_ddot: Matrix,
    pub points: Vec<PointKinematics>,
    /// det Ψ_u, expanded symbolically for m ≤ 4 (for the text table).
    pub det_psi_u: Option<Id>,
    /// Whether γ by method A, by method B and the fused γ reduce to the same
    /// polynomial in q̇ (`None`: too large to expand).
    pub methods_agree: Option<bool>,
    /// The diagonal blocks of Ψ_u, in solve order.
    pub blocks: Blocks,
}

impl Derivatives {
    // Index loops over rows and columns read like the formulas they compute.
    #[allow(clippy::needless_range_loop)]
    pub fn build(mut lowered: Lowered) -> Derivatives {
        let (m, f) = (lowered.m, lowered.f);
        let n = m + f;
        let dag = &mut lowered.dag;
        let coord = |k: usize| Symbol::Coord(k as u16);
        let vel: Vec<Id> = (0..n).map(|k| dag.sym(Symbol::Vel(k as u16))).collect();
        let acc: Vec<Id> = (0..n).map(|k| dag.sym(Symbol::Acc(k as u16))).collect();
        let q_dot: Vec<(Symbol, Id)> = (0..n).map(|k| (coord(k), vel[k])).collect();
        let u_dot: Vec<(Symbol, Id)> = q_dot[..m].to_vec();
        let v_dot: Vec<(Symbol, Id)> = q_dot[m..].to_vec();
        let q_ddot: Vec<(Symbol, Id)> = (0..n).map(|k| (coord(k), acc[k])).collect();

        let psi = Matrix::column(lowered.closure.clone());
        let psi_q = Matrix::from_fn(m, n, |i, k| dag.diff(psi.entries[i], coord(k)));
        let psi_u = Matrix::from_fn(m, m, |i, j| psi_q.get(i, j));
        let psi_v = Matrix::from_fn(m, f, |i, l| psi_q.get(i, m + l));

        // Method B: Jacobians of Ψ_u u̇ and Ψ_v v̇.
        let hu: Vec<Id> = (0..m)
            .map(|i| dag.directional(psi.entries[i], &u_dot))
            .collect();
        let hv: Vec<Id> = (0..m)
            .map(|i| dag.directional(psi.entries[i], &v_dot))
            .collect();
        let psi_u_udot_u = Matrix::from_fn(m, m, |i, j| dag.diff(hu[i], coord(j)));
        let psi_u_udot_v = Matrix::from_fn(m, f, |i, l| dag.diff(hu[i], coord(m + l)));
        let psi_v_vdot_u = Matrix::from_fn(m, m, |i, j| dag.diff(hv[i], coord(j)));
        let psi_v_vdot_v = Matrix::from_fn(m, f, |i, l| dag.diff(hv[i], coord(m + l)));

        // Method A: time derivatives of Ψ_u and Ψ_v.
        let psi_u_dot = Matrix::from_fn(m, m, |i, j| dag.directional(psi_u.get(i, j), &q_dot));
        let psi_v_dot = Matrix::from_fn(m, f, |i, l| dag.directional(psi_v.get(i, l), &q_dot));

        // Fused γ = (Ψ_q q̇)_q q̇.
        let h: Vec<Id> = (0..m)
            .map(|i| dag.directional(psi.entries[i], &q_dot))
            .collect();
        let gamma = Matrix::column(h.iter().map(|&hi| dag.directional(hi, &q_dot)).collect());

        // The sensitivities' terms: the derivatives by u and by p of Ψ,
        // Ψ̇ = Ψ_q q̇ and Ψ̈ = Ψ_q q̈ + γ.
        let by_param: Vec<Symbol> = lowered.params.iter().map(|&k| Symbol::Param(k)).collect();
        let k = by_param.len();
        let second: Vec<Id> = (0..m)
            .map(|i| {
                let ddot = dag.directional(psi.entries[i], &q_ddot);
                dag.add(ddot, gamma.entries[i])
            })
            .collect();
        let psi_p = Matrix::from_fn(m, k, |i, j| dag.diff(psi.entries[i], by_param[j]));
        let psi_p_dot = Matrix::from_fn(m, k, |i, j| dag.diff(h[i], by_param[j]));
        let psi_u_ddot = Matrix::from_fn(m, m, |i, j| dag.diff(second[i], coord(j)));
        let psi_p_ddot = Matrix::from_fn(m, k, |i, j| dag.diff(second[i], by_param[j]));

        let mut points = Vec::new();
        for (name, x, y) in &lowered.points {
            let position = [*x, *y];
            let velocity = position.map(|p| dag.directional(p, &q_dot));
            let acceleration = [0, 1].map(|c| {
                let first = dag.directional(position[c], &q_ddot);
                let second = dag.directional(velocity[c], &q_dot);
                dag.add(first, second)
            });
            let levels = [position, velocity, acceleration];
            let by_u = levels.map(|e| Matrix::from_fn(2, m, |c, j| dag.diff(e[c], coord(j))));
            let by_p = levels.map(|e| Matrix::from_fn(2, k, |c, j| dag.diff(e[c], by_param[j])));
            points.push(PointKinematics {
                name: crate::ast::unraw(name),
                position,
                velocity,
                acceleration,
                by_u,
                by_p,
            });
        }

        let det_psi_u = (m <= 4).then(|| determinant(dag, &psi_u));
        let incidence: Vec<Vec<bool>> = (0..m)
            .map(|i| (0..m).map(|k| psi_u.get(i, k) != Dag::ZERO).collect())
            .collect();
        let blocks = Blocks::of(&incidence);

        let methods_agree = {
            let mut gamma_a = Vec::with_capacity(m);
            let mut gamma_b = Vec::with_capacity(m);
            for i in 0..m {
                let mut a = Vec::new();
                let mut b = Vec::new();
                for j in 0..m {
                    a.push((1.0, dag.mul(psi_u_dot.get(i, j), vel[j])));
                    b.push((1.0, dag.mul(psi_u_udot_u.get(i, j), vel[j])));
                    b.push((1.0, dag.mul(psi_v_vdot_u.get(i, j), vel[j])));
                }
                for l in 0..f {
                    a.push((1.0, dag.mul(psi_v_dot.get(i, l), vel[m + l])));
                    b.push((1.0, dag.mul(psi_u_udot_v.get(i, l), vel[m + l])));
                    b.push((1.0, dag.mul(psi_v_vdot_v.get(i, l), vel[m + l])));
                }
                gamma_a.push(dag.sum(a));
                gamma_b.push(dag.sum(b));
            }
            let mut agree = Some(true);
            // One budget for the whole proof: its time is bounded, however
            // many equations.
            let mut budget = crate::normal::Budget::default();
            for i in 0..m {
                let expanded = [gamma_a[i], gamma_b[i], gamma.entries[i]]
                    .map(|g| crate::normal::expand_within(dag, g, &mut budget));
                match expanded {
                    [Some(a), Some(b), Some(c)] => {
                        if !crate::normal::same(&a, &b) || !crate::normal::same(&a, &c) {
                            agree = Some(false);
                        }
                    }
                    _ => {
                        agree = None;
                        break;
                    }
                }
            }
            agree
        };

        Derivatives {
            lowered,
            psi,
            psi_q,
            psi_u,
            psi_v,
            psi_u_udot_u,
            psi_u_udot_v,
            psi_v_vdot_u,
            psi_v_vdot_v,
            psi_u_dot,
            psi_v_dot,
            gamma,
            psi_p,
            psi_p_dot,
            psi_u_ddot,
            psi_p_ddot,
            points,
            det_psi_u,
            methods_agree,
            blocks,
        }
    }

    pub fn m(&self) -> usize {
        self.lowered.m
    }

    pub fn f(&self) -> usize {
        self.lowered.f
    }

    /// The number of parameters differentiated by.
    pub fn k(&self) -> usize {
        self.lowered.params.len()
    }

    pub fn dag(&self) -> &Dag {
        &self.lowered.dag
    }
}

/// The determinant by Laplace expansion along the first row, skipping zero
/// entries (for small matrices only: the text table).
fn determinant(dag: &mut Dag, a: &Matrix) -> Id {
    let rows: Vec<usize> = (0..a.rows).collect();
    let cols: Vec<usize> = (0..a.cols).collect();
    minor(dag, a, &rows, &cols)
}

fn minor(dag: &mut Dag, a: &Matrix, rows: &[usize], cols: &[usize]) -> Id {
    match rows.len() {
        0 => Dag::ONE,
        1 => a.get(rows[0], cols[0]),
        _ => {
            let mut terms = Vec::new();
            for (k, &c) in cols.iter().enumerate() {
                let entry = a.get(rows[0], c);
                if entry == Dag::ZERO {
                    continue;
                }
                let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
                let sub = minor(dag, a, &rows[1..], &rest);
                if sub == Dag::ZERO {
                    continue;
                }
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                terms.push((sign, dag.mul(entry, sub)));
            }
            let s = dag.sum(terms);
            crate::normal::expand_node(dag, s).unwrap_or(s)
        }
    }
}

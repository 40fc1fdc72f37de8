//! What a run-time mechanism is made of once its text is read: its names,
//! the tapes of its kernels, the formulas its dual-number functions
//! evaluate, and which coordinates' sines and cosines its kernels read.
//! Shared by every copy of the mechanism (behind an `Arc`).

use crate::mechanism::error::MechanismError;
use crate::mechanism::interned;
use linkage_symbolic::dag::{Dag, Id, Symbol};
use linkage_symbolic::derivatives::Derivatives;
use linkage_symbolic::plan::Kernel;
use linkage_symbolic::tape::{Tape, Tapes};
use std::sync::atomic::{AtomicU64, Ordering};

static NEXT_ID: AtomicU64 = AtomicU64::new(0);

/// A mechanism read at run time, ready to evaluate.
pub(crate) struct Program {
    /// Tells the register files made for this program's tapes from others.
    pub(crate) id: u64,
    pub(crate) name: String,
    pub(crate) m: usize,
    pub(crate) f: usize,
    pub(crate) u_names: Vec<&'static str>,
    pub(crate) v_names: Vec<&'static str>,
    pub(crate) point_names: &'static [&'static str],
    /// Every parameter, in the order the tapes read them.
    pub(crate) field_names: Vec<&'static str>,
    /// The parameters p differentiated by: indices into `field_names`.
    pub(crate) params: Vec<usize>,
    tapes: Tapes,
    /// The formulas of Ψ and of the points' positions, for the functions
    /// on dual numbers.
    dag: Dag,
    psi: Vec<Id>,
    points: Vec<[Id; 2]>,
    /// Whether the two acceleration methods expand to the same polynomial.
    pub(crate) methods_agree: Option<bool>,
}

impl std::fmt::Debug for Program {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Program")
            .field("name", &self.name)
            .field("u", &self.u_names)
            .field("v", &self.v_names)
            .field("points", &self.point_names)
            .field("parameters", &self.field_names)
            .finish_non_exhaustive()
    }
}

impl Program {
    /// The program of a mechanism read and differentiated.
    pub(crate) fn new(name: &str, derivatives: &Derivatives) -> Result<Program, MechanismError> {
        let tapes = Tapes::build(derivatives).map_err(|e| MechanismError::Internal {
            what: format!(
                "the kernel `{}` could not be compiled: {}",
                e.kernel, e.message
            ),
        })?;
        let lowered = &derivatives.lowered;
        let coordinate = |k: usize| interned::name(&lowered.coords[k].to_string());
        let (m, f) = (derivatives.m(), derivatives.f());
        let point_names: Vec<String> = derivatives.points.iter().map(|p| p.name.clone()).collect();
        let point_names: Vec<&str> = point_names.iter().map(String::as_str).collect();
        Ok(Program {
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            name: name.to_owned(),
            m,
            f,
            u_names: (0..m).map(coordinate).collect(),
            v_names: (m..m + f).map(coordinate).collect(),
            point_names: interned::list(&point_names),
            field_names: (lowered.fields.iter())
                .map(|field| interned::name(&linkage_symbolic::ast::unraw(field)))
                .collect(),
            params: lowered.params.iter().map(|&k| k as usize).collect(),
            tapes,
            dag: derivatives.dag().clone(),
            psi: derivatives.psi.entries.clone(),
            points: derivatives.points.iter().map(|p| p.position).collect(),
            methods_agree: derivatives.methods_agree,
        })
    }

    /// The tape of a kernel, and the kernel's place in [`Kernel::ALL`]
    /// (the key of its register files).
    pub(crate) fn tape(&self, kernel: Kernel) -> (usize, &Tape) {
        let index = Kernel::ALL.iter().position(|&k| k == kernel).unwrap_or(0);
        (index, self.tapes.get(kernel))
    }

    /// The coordinates of u, then of v, whose sine and cosine the kernel
    /// compiled with them given reads.
    pub(crate) fn trig_flags(&self, kernel: Kernel) -> (Vec<bool>, Vec<bool>) {
        let mut u = vec![false; self.m];
        let mut v = vec![false; self.f];
        for &k in self.tape(kernel).1.trig_coords() {
            match k.checked_sub(self.m) {
                None => u[k] = true,
                Some(j) => v[j] = true,
            }
        }
        (u, v)
    }

    /// Ψ on any dual number, from its formulas.
    pub(crate) fn psi_dual<D>(&self, field: &dyn Fn(usize) -> D, q: &dyn Fn(usize) -> D) -> Vec<D>
    where
        D: num_dual::DualNum<Primitive = f64> + Copy,
    {
        self.evaluate(&self.psi, field, q)
    }

    /// The points' positions on any dual number, from their formulas.
    pub(crate) fn points_dual<D>(
        &self,
        field: &dyn Fn(usize) -> D,
        q: &dyn Fn(usize) -> D,
    ) -> Vec<[D; 2]>
    where
        D: num_dual::DualNum<Primitive = f64> + Copy,
    {
        let roots: Vec<Id> = self.points.iter().flatten().copied().collect();
        let values = self.evaluate(&roots, field, q);
        values.chunks_exact(2).map(|xy| [xy[0], xy[1]]).collect()
    }

    /// The formulas `roots`, each parameter's value `field(k)` and each
    /// coordinate's `q(k)`.
    fn evaluate<D>(
        &self,
        roots: &[Id],
        field: &dyn Fn(usize) -> D,
        q: &dyn Fn(usize) -> D,
    ) -> Vec<D>
    where
        D: num_dual::DualNum<Primitive = f64> + Copy,
    {
        let leaf = |s: Symbol| match s {
            Symbol::Coord(k) => q(k as usize),
            Symbol::Param(k) => field(k as usize),
            // Velocities and accelerations appear in no position formula.
            _ => D::from(f64::NAN),
        };
        linkage_symbolic::interp::eval_many(&self.dag, roots, &leaf)
    }
}

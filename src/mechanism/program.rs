//! What a run-time mechanism is made of once its text is read: its names,
//! the tapes of its kernels, the formulas its dual-number functions
//! evaluate, and which coordinates' sines and cosines its kernels read.
//! Shared by every copy of the mechanism (behind an `Arc`).
//!
//! The kernels the views run are compiled with the program. The others
//! (Ψ_q, Ψ_p and the sensitivities' terms, the costliest tapes of all) are
//! compiled on first use, from the text read again: the derivatives
//! cannot be kept, as they hold the front end's identifiers, which stay on
//! the thread that made them; the same text gives the same derivatives.

use crate::mechanism::error::MechanismError;
use crate::mechanism::interned;
use crate::mechanism::kernel_tape::KernelTape;
use crate::runtime::PsiUBlocksBuf;
use linkage_symbolic::blocks::Blocks;
use linkage_symbolic::dag::{Dag, Id, Symbol};
use linkage_symbolic::derivatives::Derivatives;
use linkage_symbolic::plan::{Formula, Kernel};
use linkage_symbolic::tape::{self, CompileError};
use linkage_symbolic::text::{self, Equations, Parameter};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

static NEXT_ID: AtomicU64 = AtomicU64::new(0);

/// The kernels compiled on first use: no view runs them.
const ON_FIRST_USE: [Kernel; 5] = [
    Kernel::Formula(Formula::PsiQ),
    Kernel::Formula(Formula::PsiP),
    Kernel::SensitivityTerms { with_trig: false },
    Kernel::SensitivityTerms { with_trig: true },
    Kernel::PositionSensitivityTerms,
];

/// The kernels whose results the views read part by part in order, and
/// the parts' names, phase by phase.
const READ_IN_ORDER: [(Kernel, &[&[&str]]); 3] = [
    (Kernel::PsiAndPsiU, &[&["psi", "psi_u"]]),
    (
        Kernel::Kinematics { with_trig: false },
        &[&["psi", "psi_u", "psi_v"], &["gamma"]],
    ),
    (
        Kernel::Kinematics { with_trig: true },
        &[&["psi", "psi_u", "psi_v"], &["gamma"]],
    ),
];

/// What a mechanism was read from, to read it again.
struct Source {
    name: String,
    equations: String,
    parameters: Vec<String>,
}

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
    /// Every kernel, by its index ([`Kernel::every`]): compiled with the
    /// program, or on first use ([`ON_FIRST_USE`]).
    kernels: Vec<OnceLock<Result<KernelTape, CompileError>>>,
    source: Source,
    /// The formulas of Ψ and of the points' positions, for the functions
    /// on dual numbers.
    dag: Dag,
    psi: Vec<Id>,
    points: Vec<[Id; 2]>,
    /// Whether the two acceleration methods expand to the same polynomial.
    pub(crate) methods_agree: Option<bool>,
    /// Ψ_u's diagonal blocks, in solve order.
    pub(crate) blocks: Blocks,
    /// The same as the runtime inverts Ψ_u by them.
    pub(crate) psi_u_blocks: PsiUBlocksBuf,
}

/// A kernel's tape, compiled.
fn compiled(derivatives: &Derivatives, kernel: Kernel) -> Result<KernelTape, CompileError> {
    let tape = tape::compile(derivatives, kernel)?;
    Ok(KernelTape::new(kernel.index().unwrap_or(0), tape))
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
    /// The program of a mechanism read and differentiated (`derivatives`)
    /// from `equations`, whose parameters are `parameters`.
    pub(crate) fn new(
        name: &str,
        equations: &str,
        parameters: &[Parameter<'_>],
        derivatives: &Derivatives,
    ) -> Result<Program, MechanismError> {
        let internal = |e: CompileError| MechanismError::Internal {
            what: format!(
                "the kernel `{}` could not be compiled: {}",
                e.kernel, e.message
            ),
        };
        let kernels: Vec<OnceLock<Result<KernelTape, CompileError>>> =
            Kernel::every().map(|_| OnceLock::new()).collect();
        for (kernel, slot) in Kernel::every().zip(&kernels) {
            if !ON_FIRST_USE.contains(&kernel) {
                let _ = slot.set(Ok(compiled(derivatives, kernel).map_err(internal)?));
            }
        }
        let lowered = &derivatives.lowered;
        let coordinate = |k: usize| interned::name(&lowered.coords[k].to_string());
        let (m, f) = (derivatives.m(), derivatives.f());
        let point_names: Vec<String> = derivatives.points.iter().map(|p| p.name.clone()).collect();
        let point_names: Vec<&str> = point_names.iter().map(String::as_str).collect();
        let program = Program {
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
            kernels,
            source: Source {
                name: name.to_owned(),
                equations: equations.to_owned(),
                parameters: parameters.iter().map(|p| p.name.to_owned()).collect(),
            },
            dag: derivatives.dag().clone(),
            psi: derivatives.psi.entries.clone(),
            points: derivatives.points.iter().map(|p| p.position).collect(),
            methods_agree: derivatives.methods_agree,
            blocks: derivatives.blocks.clone(),
            psi_u_blocks: {
                let order = derivatives.blocks.order();
                PsiUBlocksBuf::new(order.equations, order.coordinates, order.ends, order.reach)
            },
        };
        for (kernel, names) in READ_IN_ORDER {
            if !program.kernel(kernel).is_ok_and(|k| k.has_parts(names)) {
                return Err(MechanismError::Internal {
                    what: format!("the kernel `{}` has parts out of order", kernel.name()),
                });
            }
        }
        Ok(program)
    }

    /// A kernel ready to run, compiled now if this is its first use (an
    /// error if it cannot be: the emitter wrote a form the tape compiler
    /// does not know, an internal error).
    pub(crate) fn kernel(&self, kernel: Kernel) -> Result<&KernelTape, &CompileError> {
        let slot = &self.kernels[kernel.index().unwrap_or(0)];
        slot.get_or_init(|| self.compile_again(kernel)).as_ref()
    }

    /// A kernel compiled from the text read again.
    fn compile_again(&self, kernel: Kernel) -> Result<KernelTape, CompileError> {
        let source = &self.source;
        let parameters: Vec<Parameter<'_>> = (source.parameters.iter())
            .map(|name| Parameter::new(name))
            .collect();
        match text::build(&source.name, Equations::new(&source.equations), &parameters) {
            Ok(built) => compiled(&built.derivatives, kernel),
            Err(diagnostics) => Err(CompileError {
                kernel: kernel.name(),
                message: format!("the text no longer reads: {diagnostics:?}"),
            }),
        }
    }

    /// The coordinates of u, then of v, whose sine and cosine the kernel
    /// compiled with them given reads, at sizes `M` and `F` (the view's,
    /// which it checked are the program's): no allocation, for the calls
    /// made at every pose.
    pub(crate) fn trig_flags<const M: usize, const F: usize>(
        &self,
        kernel: Kernel,
    ) -> ([bool; M], [bool; F]) {
        let (mut u, mut v) = ([false; M], [false; F]);
        let coords = self
            .kernel(kernel)
            .map_or(&[][..], |k| k.tape.trig_coords());
        for &k in coords {
            let flag = match k.checked_sub(self.m) {
                None => u.get_mut(k),
                Some(j) => v.get_mut(j),
            };
            if let Some(flag) = flag {
                *flag = true;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernels compiled on first use, from the text read again, are
    /// those compiled from the derivatives the program was made from.
    #[test]
    fn a_kernel_compiled_on_first_use_is_the_one_compiled_at_once() {
        let equations = "u = [theta3, theta4], v = [theta2],
            points = [B = (l2 * theta2.cos(), l2 * theta2.sin())],
            closure = [
                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
            ]";
        let parameters = ["l1", "l2", "l3", "l4"].map(Parameter::new);
        let built = text::build("FourBar", Equations::new(equations), &parameters)
            .expect("the four-bar reads");
        let program = Program::new("FourBar", equations, &parameters, &built.derivatives)
            .expect("every kernel compiles");
        for kernel in ON_FIRST_USE {
            let now = tape::compile(&built.derivatives, kernel).expect("compiles");
            let later = &program.kernel(kernel).expect("compiles on first use").tape;
            assert_eq!(later.ops(), now.ops(), "{}", kernel.name());
            assert_eq!(later.constants(), now.constants(), "{}", kernel.name());
            for phase in 0..now.phases() {
                assert_eq!(later.phase(phase), now.phase(phase), "{}", kernel.name());
            }
        }
    }
}

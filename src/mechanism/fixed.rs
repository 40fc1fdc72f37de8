//! [`Fixed`]: a run-time mechanism seen at sizes fixed at compile time
//! (m, f and a capacity of named points), so that it implements
//! [`Kernels`] and [`Linkage`] and every analysis of the library takes it
//! as it takes a compiled mechanism: the same code, instantiated for its
//! sizes. Each kernel runs its tape on this thread's register file, then
//! does exactly what the generated function does with the result (the
//! same nalgebra operations in the same order), so that the numbers are
//! the compiled mechanism's, bit for bit.

use crate::mechanism::kernel_tape::KernelTape;
use crate::mechanism::point_set::PointSet;
use crate::mechanism::program::Program;
use crate::mechanism::scratch::{self, LANES};
use crate::mechanism::sensitive::Columns;
use crate::runtime::{Factors, FusedRequest, Kernels, Kinematics, Linkage, PsiUBlocks};
use linkage_symbolic::plan::{Formula, Kernel};
use linkage_symbolic::tape::{Input, Registers, Slots};
use nalgebra::{SMatrix, SVector, Vector2};
use num_dual::DualNum;
use std::sync::Arc;

/// A run-time mechanism at the sizes m = `M`, f = `F`, with room for `P`
/// named points: made by [`Mechanism::fixed`](super::Mechanism::fixed),
/// which checks the sizes. Cheap to clone (the tapes are shared).
#[derive(Clone, Debug)]
pub struct Fixed<const M: usize, const F: usize, const P: usize = 32, const K: usize = 0> {
    program: Arc<Program>,
    /// Every parameter's value, in the order the tapes read them.
    fields: Vec<f64>,
    /// The parameters differentiated by, column by column of the
    /// sensitivities (at most `K`; the columns after them are zero).
    columns: Columns,
    u_names: [&'static str; M],
    v_names: [&'static str; F],
    trig_u: [bool; M],
    trig_v: [bool; F],
    /// The coordinates whose sines and cosines the points' one-pass
    /// kernel reads.
    point_trig_u: [bool; M],
    point_trig_v: [bool; F],
}

/// The result of a kernel's phase 0, left in its registers: read as
/// matrices straight from them, or whole into a buffer.
pub(super) struct Output<'a> {
    /// The kernel and its registers, if its tape ran.
    ran: Option<(&'a KernelTape, &'a Registers)>,
    buffer: &'a mut Vec<f64>,
}

impl<'a> Output<'a> {
    /// The R × C matrix that starts at `start` (NaN if the tape did not
    /// run).
    #[inline(always)]
    pub(super) fn block<const R: usize, const C: usize>(&self, start: usize) -> SMatrix<f64, R, C> {
        match self.ran {
            Some((kernel, registers)) => kernel.block(registers, 0, start, 0),
            None => SMatrix::repeat(f64::NAN),
        }
    }

    /// The kernel, if its tape ran.
    pub(super) fn kernel(&self) -> Option<&'a KernelTape> {
        self.ran.map(|(kernel, _)| kernel)
    }

    /// The whole result, laid out by [`KernelTape`] (empty if the tape did
    /// not run).
    pub(super) fn entries(&mut self) -> &[f64] {
        let Some((kernel, registers)) = self.ran else {
            return &[];
        };
        self.buffer.resize(kernel.len(0), 0.0);
        kernel.read(registers, 0, 0, self.buffer);
        self.buffer
    }
}

/// The sines and cosines of u and of v given to a kernel.
type Given<'a, const M: usize, const F: usize> = (&'a [(f64, f64); M], &'a [(f64, f64); F]);

/// Pairs (sin, cos) flattened, as the tapes read them.
pub(super) fn flat<const N: usize>(pairs: &[(f64, f64); N]) -> [[f64; 2]; N] {
    pairs.map(|(s, c)| [s, c])
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Fixed<M, F, P, K> {
    /// Writes an input where the tapes of sizes m = `M` and f = `F` read
    /// it (the view's sizes, which it checked are its program's): at an
    /// offset known where the view is compiled, the input's length known
    /// where it is copied. A program's tapes have these sizes, so this
    /// cannot fail (a failure leaves the input as it was, and the runtime's
    /// checks report what comes of it).
    #[inline(always)]
    fn set(registers: &mut Registers, input: Input, values: &[f64]) {
        Self::set_lane(registers, input, 0, values);
    }

    /// [`Fixed::set`] on lane `lane` of a file of L lanes.
    #[inline(always)]
    fn set_lane<const L: usize>(
        registers: &mut Registers<L>,
        input: Input,
        lane: usize,
        values: &[f64],
    ) {
        // Where an input starts, and how long it is (but the fields), does
        // not depend on how many fields there are.
        let slots = Slots {
            m: M,
            f: F,
            fields: 0,
        };
        if input != Input::Fields && values.len() != slots.len(input) {
            return;
        }
        registers.set_at(slots.range(input).start, lane, values);
    }

    /// The view of `program` with these parameter values, differentiated
    /// by the parameters of `columns` (see [`Fixed::columns`]); the caller
    /// has checked the sizes.
    pub(crate) fn new(
        program: Arc<Program>,
        fields: Vec<f64>,
        columns: Columns,
    ) -> Fixed<M, F, P, K> {
        let array = |names: &[&'static str], k: usize| names.get(k).copied().unwrap_or("");
        let (trig_u, trig_v) = program.trig_flags(Kernel::Kinematics { with_trig: true });
        let (point_trig_u, point_trig_v) = program.trig_flags(Kernel::PointMotion);
        Fixed {
            u_names: std::array::from_fn(|k| array(&program.u_names, k)),
            v_names: std::array::from_fn(|k| array(&program.v_names, k)),
            trig_u,
            trig_v,
            point_trig_u,
            point_trig_v,
            program,
            fields,
            columns,
        }
    }

    /// The mechanism's name.
    pub fn name(&self) -> &str {
        &self.program.name
    }

    /// Every parameter's name, in order (not only those differentiated by).
    pub fn parameter_names(&self) -> &[&'static str] {
        &self.program.field_names
    }

    /// Every parameter's value, in the order of [`Fixed::parameter_names`].
    pub fn parameters(&self) -> &[f64] {
        &self.fields
    }

    /// The program the view runs.
    pub(super) fn program(&self) -> &Program {
        &self.program
    }

    /// The parameters of the sensitivities' columns.
    pub(super) fn columns(&self) -> &Columns {
        &self.columns
    }

    /// The number of named points.
    pub(super) fn point_count(&self) -> usize {
        self.program.point_names.len()
    }

    /// Sets the value of the parameter `k` (of [`Fixed::parameter_names`]).
    pub(super) fn set_field(&mut self, k: usize, value: f64) {
        if let Some(field) = self.fields.get_mut(k) {
            *field = value;
        }
    }

    /// Which coordinates of u and of v the sensitivities' kernel with the
    /// sines and cosines given reads them of.
    pub(super) fn sensitivity_trig(&self) -> ([bool; M], [bool; F]) {
        self.program
            .trig_flags(Kernel::SensitivityTerms { with_trig: true })
    }

    /// Runs one phase-0 kernel with the inputs `inputs` written, and hands
    /// its result to `read`.
    pub(super) fn run<R>(
        &self,
        kernel: Kernel,
        inputs: &[(Input, &[f64])],
        read: impl FnOnce(Output<'_>) -> R,
    ) -> R {
        let Ok(kernel) = self.program.kernel(kernel) else {
            return read(Output {
                ran: None,
                buffer: &mut Vec::new(),
            });
        };
        scratch::with_registers(self.program.id, kernel, |registers, buffer| {
            Self::set(registers, Input::Fields, &self.fields);
            for (input, values) in inputs {
                Self::set(registers, *input, values);
            }
            let ran = kernel.run(0, registers).is_ok();
            read(Output {
                ran: ran.then_some((kernel, &*registers)),
                buffer,
            })
        })
    }

    /// A kernel whose one part is a matrix.
    fn formula<const R: usize, const C: usize>(
        &self,
        formula: Formula,
        inputs: &[(Input, &[f64])],
    ) -> SMatrix<f64, R, C> {
        self.run(Kernel::Formula(formula), inputs, |result| result.block(0))
    }

    /// A kernel of the points (none to run if the mechanism has none).
    fn points(&self, level: usize, inputs: &[(Input, &[f64])]) -> PointSet<P> {
        // The view was made only if its capacity holds every point.
        let mut points = PointSet::<P>::clamped(self.program.point_names.len());
        if points.is_empty() {
            return points;
        }
        self.run(Kernel::Points(level), inputs, |result| {
            for (k, point) in points.as_mut().iter_mut().enumerate() {
                *point = result.block(2 * k);
            }
        });
        points
    }

    /// The points' positions, velocities and accelerations from their
    /// one-pass kernel (each level written over `empty`, room for every
    /// point), read part by part as [`Fixed::points`] reads each.
    fn point_levels(&self, empty: PointSet<P>, inputs: &[(Input, &[f64])]) -> [PointSet<P>; 3] {
        let mut levels = [empty; 3];
        self.run(Kernel::PointMotion, inputs, |result| {
            let starts = result
                .kernel()
                .map(|tape| [0, 1, 2].map(|part| tape.start(0, part)));
            for (level, points) in levels.iter_mut().enumerate() {
                // (NaN where the tape did not run, as `points` gives.)
                let start = starts.map_or(usize::MAX, |s| s[level]);
                for (k, point) in points.as_mut().iter_mut().enumerate() {
                    *point = result.block(start.saturating_add(2 * k));
                }
            }
        });
        levels
    }

    /// `kinematics`, the sines and cosines computed or given: phase 0
    /// gives Ψ, Ψ_u and Ψ_v; then, as the generated function does, the
    /// inverse and u̇ = −Ψ_u⁻¹(Ψ_v v̇); phase 1 gives γ at that u̇; and
    /// ü = −Ψ_u⁻¹(Ψ_v v̈ + γ). Written over `out`, from within the thread's
    /// registers: a result returned through the thread-local would be
    /// copied out whole.
    #[inline(always)]
    fn kinematics_into(
        &self,
        trig: Option<Given<'_, M, F>>,
        (u, v): (&SVector<f64, M>, &SVector<f64, F>),
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        out: &mut Kinematics<M, F>,
    ) {
        let kernel = Kernel::Kinematics {
            with_trig: trig.is_some(),
        };
        let Ok(kernel) = self.program.kernel(kernel) else {
            *out = Kinematics::unevaluated();
            return;
        };
        scratch::with_registers(self.program.id, kernel, |registers, _| {
            Self::set(registers, Input::Fields, &self.fields);
            Self::set(registers, Input::U, u.as_slice());
            Self::set(registers, Input::V, v.as_slice());
            Self::set(registers, Input::Vdot, vdot.as_slice());
            if let Some((trig_u, trig_v)) = trig {
                Self::set(registers, Input::TrigU, flat(trig_u).as_flattened());
                Self::set(registers, Input::TrigV, flat(trig_v).as_flattened());
            }
            if kernel.run(0, registers).is_err() {
                *out = Kinematics::unevaluated();
                return;
            }
            // The parts in the order the program checked: Ψ, Ψ_u, Ψ_v; γ.
            out.psi = kernel.block(registers, 0, kernel.start(0, 0), 0);
            out.psi_u = kernel.block(registers, 0, kernel.start(0, 1), 0);
            out.psi_v = kernel.block(registers, 0, kernel.start(0, 2), 0);
            out.factors = Factors::of(&out.psi_u, self.psi_u_blocks());
            (out.rcond, out.det) = (out.factors.rcond(), out.factors.det());
            out.udot = -out.factors.solve(&(out.psi_v * vdot));
            Self::set(registers, Input::Udot, out.udot.as_slice());
            let gamma: SVector<f64, M> = match kernel.run(1, registers) {
                Ok(()) => kernel.block(registers, 1, kernel.start(1, 0), 0),
                Err(_) => SVector::repeat(f64::NAN),
            };
            out.uddot = -out.factors.solve(&(out.psi_v * vddot + gamma));
        });
    }

    /// [`Fixed::kinematics_into`] returned.
    #[inline(always)]
    fn kinematics_of(
        &self,
        trig: Option<Given<'_, M, F>>,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
    ) -> Kinematics<M, F> {
        let mut out = Kinematics::unevaluated();
        self.kinematics_into(trig, (u, v), vdot, vddot, &mut out);
        out
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Fixed<M, F, P, K> {
    /// `kinematics_with_trig` of each request into `out`, those of one
    /// program in a row run together on [`LANES`] lanes (see
    /// [`Kernels::kinematics_with_trig_each`]).
    fn kinematics_each(requests: &[FusedRequest<'_, Self, M, F>], out: &mut [Kinematics<M, F>]) {
        let n = requests.len().min(out.len());
        let (requests, out) = (&requests[..n], &mut out[..n]);
        let mut start = 0;
        while let Some(first) = requests.get(start) {
            let program = &first.model.program;
            let same = (requests[start..].iter().take(LANES))
                .take_while(|r| Arc::ptr_eq(&r.model.program, program))
                .count();
            let (run, outs) = (
                &requests[start..start + same],
                &mut out[start..start + same],
            );
            if let ([one], [out]) = (run, &mut *outs) {
                let trig = Some((one.trig_u, one.trig_v));
                (one.model).kinematics_into(trig, (one.u, one.v), one.vdot, one.vddot, out);
            } else {
                Self::kinematics_on_lanes(run, outs);
            }
            start += same;
        }
    }

    /// `kinematics_into` with given sines and cosines, for up to [`LANES`]
    /// requests of one program at once, each into its `out`: each lane
    /// does what one does, the operations in the same order, so each
    /// result is its own evaluation's, bit for bit. The lanes after the
    /// requests' run on what they last held, and nothing reads them.
    fn kinematics_on_lanes(run: &[FusedRequest<'_, Self, M, F>], out: &mut [Kinematics<M, F>]) {
        let n = run.len().min(out.len()).min(LANES);
        let (run, out) = (&run[..n], &mut out[..n]);
        let Some(first) = run.first() else {
            return;
        };
        let program = &first.model.program;
        let Ok(kernel) = program.kernel(Kernel::Kinematics { with_trig: true }) else {
            out.fill(Kinematics::unevaluated());
            return;
        };
        let set_lane = Self::set_lane::<LANES>;
        scratch::with_lanes(program.id, kernel, |registers, _| {
            for (l, r) in run.iter().enumerate() {
                set_lane(registers, Input::Fields, l, &r.model.fields);
                set_lane(registers, Input::U, l, r.u.as_slice());
                set_lane(registers, Input::V, l, r.v.as_slice());
                set_lane(registers, Input::Vdot, l, r.vdot.as_slice());
                set_lane(registers, Input::TrigU, l, flat(r.trig_u).as_flattened());
                set_lane(registers, Input::TrigV, l, flat(r.trig_v).as_flattened());
            }
            if kernel.run(0, registers).is_err() {
                out.fill(Kinematics::unevaluated());
                return;
            }
            // The parts in the order the program checked: Ψ, Ψ_u, Ψ_v; γ
            // (held in ü until ü is solved for), each entry to every lane.
            let part = |phase, part, len| (phase, kernel.start(phase, part), len);
            kernel.each_entry(registers, part(0, 0, M), |e, lanes| {
                out.iter_mut().zip(lanes).for_each(|(o, &x)| o.psi[e] = x);
            });
            kernel.each_entry(registers, part(0, 1, M * M), |e, lanes| {
                out.iter_mut().zip(lanes).for_each(|(o, &x)| o.psi_u[e] = x);
            });
            kernel.each_entry(registers, part(0, 2, M * F), |e, lanes| {
                out.iter_mut().zip(lanes).for_each(|(o, &x)| o.psi_v[e] = x);
            });
            // Each lane as `kinematics_into` goes on: the inverse and u̇;
            // then γ on every lane; then ü. The rates only where asked
            // for (NaN elsewhere), γ's phase only if any lane asks.
            for (l, (o, r)) in out.iter_mut().zip(run).enumerate() {
                o.factors = Factors::of(&o.psi_u, r.model.psi_u_blocks());
                (o.rcond, o.det) = (o.factors.rcond(), o.factors.det());
                o.udot = match r.rates {
                    true => -o.factors.solve(&(o.psi_v * r.vdot)),
                    false => SVector::repeat(f64::NAN),
                };
                set_lane(registers, Input::Udot, l, o.udot.as_slice());
            }
            if !run.iter().any(|r| r.rates) {
                out.iter_mut().for_each(|o| o.uddot.fill(f64::NAN));
                return;
            }
            match kernel.run(1, registers) {
                Ok(()) => kernel.each_entry(registers, part(1, 0, M), |e, lanes| {
                    out.iter_mut().zip(lanes).for_each(|(o, &x)| o.uddot[e] = x);
                }),
                Err(_) => out.iter_mut().for_each(|o| o.uddot.fill(f64::NAN)),
            }
            for (o, r) in out.iter_mut().zip(run) {
                o.uddot = match r.rates {
                    true => -o.factors.solve(&(o.psi_v * r.vddot + o.uddot)),
                    false => SVector::repeat(f64::NAN),
                };
            }
        });
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Kernels<M, F>
    for Fixed<M, F, P, K>
{
    type Points = PointSet<P>;

    fn u_names(&self) -> [&'static str; M] {
        self.u_names
    }

    fn v_names(&self) -> [&'static str; F] {
        self.v_names
    }

    fn point_names(&self) -> &'static [&'static str] {
        self.program.point_names
    }

    fn psi_u_blocks(&self) -> PsiUBlocks<'_> {
        self.program.psi_u_blocks.borrow()
    }

    fn psi(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SVector<f64, M> {
        self.formula(
            Formula::Psi,
            &[(Input::U, u.as_slice()), (Input::V, v.as_slice())],
        )
    }

    fn psi_u(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SMatrix<f64, M, M> {
        self.formula(
            Formula::PsiU,
            &[(Input::U, u.as_slice()), (Input::V, v.as_slice())],
        )
    }

    fn psi_v(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SMatrix<f64, M, F> {
        self.formula(
            Formula::PsiV,
            &[(Input::U, u.as_slice()), (Input::V, v.as_slice())],
        )
    }

    fn psi_and_psi_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> (SVector<f64, M>, SMatrix<f64, M, M>) {
        let inputs = [(Input::U, u.as_slice()), (Input::V, v.as_slice())];
        // The parts in the order the program checked: Ψ, Ψ_u.
        self.run(Kernel::PsiAndPsiU, &inputs, |result| {
            (result.block(0), result.block(M))
        })
    }

    fn psi_u_udot_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
    ) -> SMatrix<f64, M, M> {
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::Udot, udot.as_slice()),
        ];
        self.formula(Formula::PsiUUdotU, &inputs)
    }

    fn psi_u_udot_v(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
    ) -> SMatrix<f64, M, F> {
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::Udot, udot.as_slice()),
        ];
        self.formula(Formula::PsiUUdotV, &inputs)
    }

    fn psi_v_vdot_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, M> {
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::Vdot, vdot.as_slice()),
        ];
        self.formula(Formula::PsiVVdotU, &inputs)
    }

    fn psi_v_vdot_v(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, F> {
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::Vdot, vdot.as_slice()),
        ];
        self.formula(Formula::PsiVVdotV, &inputs)
    }

    fn psi_u_dot(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, M> {
        self.formula(Formula::PsiUDot, &motion(u, v, udot, vdot))
    }

    fn psi_v_dot(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, F> {
        self.formula(Formula::PsiVDot, &motion(u, v, udot, vdot))
    }

    fn gamma(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SVector<f64, M> {
        self.formula(Formula::Gamma, &motion(u, v, udot, vdot))
    }

    fn kinematics(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
    ) -> Kinematics<M, F> {
        self.kinematics_of(None, u, v, vdot, vddot)
    }

    fn trig_u(&self) -> [bool; M] {
        self.trig_u
    }

    fn trig_v(&self) -> [bool; F] {
        self.trig_v
    }

    fn kinematics_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
    ) -> Kinematics<M, F> {
        self.kinematics_of(Some((trig_u, trig_v)), u, v, vdot, vddot)
    }

    fn evaluates_in_place(&self) -> bool {
        true
    }

    fn kinematics_with_trig_into(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        out: &mut Kinematics<M, F>,
    ) {
        self.kinematics_into(Some((trig_u, trig_v)), (u, v), vdot, vddot, out);
    }

    fn evaluates_together() -> bool {
        true
    }

    fn kinematics_with_trig_each(
        requests: &[FusedRequest<'_, Self, M, F>],
        out: &mut [Kinematics<M, F>],
    ) {
        Self::kinematics_each(requests, out);
    }

    fn point_trig_u(&self) -> [bool; M] {
        self.point_trig_u
    }

    fn point_trig_v(&self) -> [bool; F] {
        self.point_trig_v
    }

    fn point_motion_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
    ) -> [PointSet<P>; 3] {
        // (No points to compute: nothing to write.)
        let none = PointSet::<P>::clamped(self.program.point_names.len());
        if none.is_empty() {
            return [none; 3];
        }
        let (trig_u, trig_v) = (flat(trig_u), flat(trig_v));
        let [u, v, udot, vdot, uddot, vddot] = accelerating(u, v, udot, vdot, uddot, vddot);
        let inputs = [
            u,
            v,
            udot,
            vdot,
            uddot,
            vddot,
            (Input::TrigU, trig_u.as_flattened()),
            (Input::TrigV, trig_v.as_flattened()),
        ];
        self.point_levels(none, &inputs)
    }

    fn point_positions(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> PointSet<P> {
        self.points(0, &[(Input::U, u.as_slice()), (Input::V, v.as_slice())])
    }

    fn point_velocities(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> PointSet<P> {
        self.points(1, &motion(u, v, udot, vdot))
    }

    fn point_accelerations(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
    ) -> PointSet<P> {
        self.points(2, &accelerating(u, v, udot, vdot, uddot, vddot))
    }

    fn psi_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> SVector<D, M> {
        let q = |k: usize| if k < M { u[k] } else { v[k - M] };
        let field = |k: usize| D::from(self.fields.get(k).copied().unwrap_or(f64::NAN));
        let values = self.program.psi_dual(&field, &q);
        SVector::from_fn(|i, _| values.get(i).copied().unwrap_or(D::from(f64::NAN)))
    }

    fn point_positions_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> impl AsRef<[Vector2<D>]> {
        let q = |k: usize| if k < M { u[k] } else { v[k - M] };
        let field = |k: usize| D::from(self.fields.get(k).copied().unwrap_or(f64::NAN));
        let points = self.program.points_dual(&field, &q);
        points
            .into_iter()
            .map(|[x, y]| Vector2::new(x, y))
            .collect::<Vec<_>>()
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Linkage<M, F>
    for Fixed<M, F, P, K>
{
}

/// [`motion`] and the accelerations ü, v̈ as inputs.
fn accelerating<'a, const M: usize, const F: usize>(
    u: &'a SVector<f64, M>,
    v: &'a SVector<f64, F>,
    udot: &'a SVector<f64, M>,
    vdot: &'a SVector<f64, F>,
    uddot: &'a SVector<f64, M>,
    vddot: &'a SVector<f64, F>,
) -> [(Input, &'a [f64]); 6] {
    let [u, v, udot, vdot] = motion(u, v, udot, vdot);
    let uddot = (Input::Uddot, uddot.as_slice());
    [u, v, udot, vdot, uddot, (Input::Vddot, vddot.as_slice())]
}

/// The inputs of a kernel of a pose in motion.
fn motion<'a, const M: usize, const F: usize>(
    u: &'a SVector<f64, M>,
    v: &'a SVector<f64, F>,
    udot: &'a SVector<f64, M>,
    vdot: &'a SVector<f64, F>,
) -> [(Input, &'a [f64]); 4] {
    [
        (Input::U, u.as_slice()),
        (Input::V, v.as_slice()),
        (Input::Udot, udot.as_slice()),
        (Input::Vdot, vdot.as_slice()),
    ]
}

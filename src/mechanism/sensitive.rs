//! The sensitivities of a run-time mechanism: [`Fixed`] with room for `K`
//! parameters implements [`SensitivityKernel`] and [`Sensitivities`], so
//! that the sensitivities, the tolerance analyses and the synthesis take
//! it as they take a compiled mechanism. The tapes differentiate by every
//! parameter p of the mechanism; a view reads the columns of those it was
//! made for ([`Columns`]), in its order, and its columns after them are
//! zero.

use crate::mechanism::fixed::{Fixed, flat};
use crate::mechanism::point_set::PointSet;
use crate::runtime::{PositionTerms, Sensitivities, SensitivityKernel, SensitivityTerms};
use linkage_symbolic::plan::{Formula, Kernel};
use linkage_symbolic::tape::Input;
use nalgebra::{SMatrix, SVector, Vector2};
use num_dual::DualNum;

/// Which of the mechanism's differentiated parameters a view's columns
/// are, found once when the view is made.
#[derive(Clone, Debug, Default)]
pub(crate) struct Columns {
    /// Each view column's parameter: its index among the mechanism's
    /// parameters (its field).
    fields: Vec<usize>,
    /// Each column of the tapes' view column, if the view has it.
    of_tape: Vec<Option<usize>>,
    /// Each field's view column, if the view has it.
    of_field: Vec<Option<usize>>,
}

impl Columns {
    /// The columns `chosen` (columns of the tapes, in the view's order),
    /// of tapes that differentiate by the fields `by_tape` (in the tapes'
    /// order), of a mechanism with `field_count` parameters.
    pub(crate) fn new(chosen: &[usize], by_tape: &[usize], field_count: usize) -> Columns {
        let mut of_tape = vec![None; by_tape.len()];
        let mut of_field = vec![None; field_count];
        let mut fields = Vec::with_capacity(chosen.len());
        for (view, &tape) in chosen.iter().enumerate() {
            let Some(&field) = by_tape.get(tape) else {
                continue;
            };
            of_tape[tape] = Some(view);
            if let Some(slot) = of_field.get_mut(field) {
                *slot = Some(view);
            }
            fields.push(field);
        }
        Columns {
            fields,
            of_tape,
            of_field,
        }
    }

    /// The view column of a column of the tapes, if the view has it.
    fn view_of(&self, tape: usize) -> Option<usize> {
        self.of_tape.get(tape).copied().flatten()
    }
}

/// A matrix part differentiated by p (`rows` × the tapes' columns, column
/// by column from `start` in `result`) read into the view's columns (the
/// other parameters' columns dropped).
fn by_params<const R: usize, const K: usize>(
    columns: &Columns,
    result: &[f64],
    start: usize,
    rows: usize,
) -> SMatrix<f64, R, K> {
    let mut out = SMatrix::<f64, R, K>::zeros();
    for (j, c) in columns.of_tape.iter().enumerate() {
        let (Some(c), Some(column)) = (c, result.get(start + j * rows..start + (j + 1) * rows))
        else {
            continue;
        };
        if *c < K && rows == R {
            out.column_mut(*c).copy_from_slice(column);
        }
    }
    out
}

/// A matrix part differentiated by u (m × m from `start`), as it is.
fn by_u<const M: usize>(result: &[f64], start: usize) -> SMatrix<f64, M, M> {
    result
        .get(start..start + M * M)
        .map_or_else(SMatrix::zeros, SMatrix::from_column_slice)
}

/// A part of point columns (the 2n coordinates of the points, column by
/// column from `start`) into `out`, each column `column(j)` of it, or
/// none.
fn point_columns<const N: usize, const P: usize>(
    out: &mut [PointSet<P>; N],
    result: &[f64],
    start: usize,
    (points, cols): (usize, usize),
    column: impl Fn(usize) -> Option<usize>,
) {
    let rows = 2 * points;
    for j in 0..cols {
        let (Some(c), Some(values)) = (
            column(j).filter(|&c| c < N),
            result.get(start + j * rows..start + (j + 1) * rows),
        ) else {
            continue;
        };
        for (point, xy) in out[c].as_mut().iter_mut().zip(values.chunks_exact(2)) {
            *point = Vector2::new(xy[0], xy[1]);
        }
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Fixed<M, F, P, K> {
    /// The terms of the sensitivities: the tape's one phase run with the
    /// pose in motion (and the sines and cosines, if given) written, its
    /// parts read from their places into the view's columns.
    fn terms(
        &self,
        inputs: &[(Input, &[f64])],
        with_trig: bool,
    ) -> SensitivityTerms<M, K, PointSet<P>> {
        let columns = self.columns();
        let points = self.point_count();
        let kernel = Kernel::SensitivityTerms { with_trig };
        let mut terms = SensitivityTerms {
            psi_u: SMatrix::repeat(f64::NAN),
            psi_p: SMatrix::zeros(),
            psi_u_dot: SMatrix::zeros(),
            psi_p_dot: SMatrix::zeros(),
            psi_u_ddot: SMatrix::zeros(),
            psi_p_ddot: SMatrix::zeros(),
            points_u: [PointSet::clamped(points); M],
            points_p: [PointSet::clamped(points); K],
            point_velocities_u: [PointSet::clamped(points); M],
            point_velocities_p: [PointSet::clamped(points); K],
            point_accelerations_u: [PointSet::clamped(points); M],
            point_accelerations_p: [PointSet::clamped(points); K],
        };
        // Filled in place (the terms are large: returned from the
        // thread's register file, they were copied out whole). If the
        // tape could not run, Ψ_u stays NaN: not numbers, which the solve
        // turns into a typed error.
        self.run(kernel, inputs, |mut output| {
            let Some(tape) = output.kernel() else {
                return;
            };
            let result = output.entries();
            let view = |j: usize| columns.view_of(j);
            let same = |j: usize| Some(j);
            for (k, part) in tape.tape.parts(0).iter().enumerate() {
                let (start, rows, size) = (tape.start(0, k), part.rows, (points, part.cols));
                match part.name {
                    "psi_u" => terms.psi_u = by_u(result, start),
                    "psi_u_dot" => terms.psi_u_dot = by_u(result, start),
                    "psi_u_ddot" => terms.psi_u_ddot = by_u(result, start),
                    "psi_p" => terms.psi_p = by_params(columns, result, start, rows),
                    "psi_p_dot" => terms.psi_p_dot = by_params(columns, result, start, rows),
                    "psi_p_ddot" => terms.psi_p_ddot = by_params(columns, result, start, rows),
                    "points_u" => point_columns(&mut terms.points_u, result, start, size, same),
                    "points_p" => point_columns(&mut terms.points_p, result, start, size, view),
                    "point_velocities_u" => {
                        point_columns(&mut terms.point_velocities_u, result, start, size, same)
                    }
                    "point_velocities_p" => {
                        point_columns(&mut terms.point_velocities_p, result, start, size, view)
                    }
                    "point_accelerations_u" => {
                        point_columns(&mut terms.point_accelerations_u, result, start, size, same)
                    }
                    "point_accelerations_p" => {
                        point_columns(&mut terms.point_accelerations_p, result, start, size, view)
                    }
                    _ => {}
                }
            }
        });
        terms
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Fixed<M, F, P, K> {
    /// The terms of the positions' sensitivities alone, from their own
    /// kernel (the sines and cosines given), read as [`Fixed::terms`]
    /// reads the whole terms.
    fn position_terms(&self, inputs: &[(Input, &[f64])]) -> PositionTerms<M, K, PointSet<P>> {
        let columns = self.columns();
        let points = self.point_count();
        let mut terms = PositionTerms {
            psi_u: SMatrix::repeat(f64::NAN),
            psi_p: SMatrix::zeros(),
            points_u: [PointSet::clamped(points); M],
            points_p: [PointSet::clamped(points); K],
        };
        self.run(Kernel::PositionSensitivityTerms, inputs, |mut output| {
            let Some(tape) = output.kernel() else {
                return;
            };
            let result = output.entries();
            for (k, part) in tape.tape.parts(0).iter().enumerate() {
                let (start, rows, size) = (tape.start(0, k), part.rows, (points, part.cols));
                match part.name {
                    "psi_u" => terms.psi_u = by_u(result, start),
                    "psi_p" => terms.psi_p = by_params(columns, result, start, rows),
                    "points_u" => point_columns(&mut terms.points_u, result, start, size, Some),
                    "points_p" => point_columns(&mut terms.points_p, result, start, size, |j| {
                        columns.view_of(j)
                    }),
                    _ => {}
                }
            }
        });
        terms
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> SensitivityKernel<M, F, K>
    for Fixed<M, F, P, K>
{
    fn position_trig_u(&self) -> [bool; M] {
        self.program()
            .trig_flags::<M, F>(Kernel::PositionSensitivityTerms)
            .0
    }

    fn position_trig_v(&self) -> [bool; F] {
        self.program()
            .trig_flags::<M, F>(Kernel::PositionSensitivityTerms)
            .1
    }

    fn position_terms_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
    ) -> PositionTerms<M, K, PointSet<P>> {
        let (trig_u, trig_v) = (flat(trig_u), flat(trig_v));
        self.position_terms(&[
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::TrigU, trig_u.as_flattened()),
            (Input::TrigV, trig_v.as_flattened()),
        ])
    }

    fn sensitivity_trig_u(&self) -> [bool; M] {
        self.sensitivity_trig().0
    }

    fn sensitivity_trig_v(&self) -> [bool; F] {
        self.sensitivity_trig().1
    }

    fn sensitivity_terms(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
    ) -> SensitivityTerms<M, K, PointSet<P>> {
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::Udot, udot.as_slice()),
            (Input::Vdot, vdot.as_slice()),
            (Input::Uddot, uddot.as_slice()),
            (Input::Vddot, vddot.as_slice()),
        ];
        self.terms(&inputs, false)
    }

    fn sensitivity_terms_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
    ) -> SensitivityTerms<M, K, PointSet<P>> {
        let (trig_u, trig_v) = (flat(trig_u), flat(trig_v));
        let inputs = [
            (Input::U, u.as_slice()),
            (Input::V, v.as_slice()),
            (Input::TrigU, trig_u.as_flattened()),
            (Input::TrigV, trig_v.as_flattened()),
            (Input::Udot, udot.as_slice()),
            (Input::Vdot, vdot.as_slice()),
            (Input::Uddot, uddot.as_slice()),
            (Input::Vddot, vddot.as_slice()),
        ];
        self.terms(&inputs, true)
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Sensitivities<M, F, K>
    for Fixed<M, F, P, K>
{
    /// The parameters of the view's columns; a column after them is named
    /// `""`.
    fn param_names(&self) -> [&'static str; K] {
        let names = self.differentiated_names();
        std::array::from_fn(|c| names.get(c).copied().unwrap_or(""))
    }

    /// Their values; a column after them is 0.
    fn params(&self) -> SVector<f64, K> {
        let fields = self.differentiated_fields();
        SVector::from_fn(|c, _| fields.get(c).map_or(0.0, |&k| self.parameters()[k]))
    }

    /// Sets them (a column after them is ignored). The values are taken as
    /// they come, as a compiled mechanism's fields are: a value that is not
    /// finite reaches the analyses, which report it.
    fn set_params(&mut self, params: &SVector<f64, K>) {
        for c in 0..self.differentiated_fields().len().min(K) {
            let k = self.differentiated_fields()[c];
            self.set_field(k, params[c]);
        }
    }

    fn psi_p(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SMatrix<f64, M, K> {
        let columns = self.columns();
        let inputs = [(Input::U, u.as_slice()), (Input::V, v.as_slice())];
        self.run(Kernel::Formula(Formula::PsiP), &inputs, |mut output| {
            let result = output.entries();
            if result.is_empty() {
                return SMatrix::repeat(f64::NAN);
            }
            by_params(columns, result, 0, M)
        })
    }

    fn psi_generic_params<D: DualNum<Primitive = f64> + Copy>(
        &self,
        params: &SVector<D, K>,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> SVector<D, M> {
        let q = |k: usize| if k < M { u[k] } else { v[k - M] };
        let field = |k: usize| self.dual_field(k, params);
        let values = self.program().psi_dual(&field, &q);
        SVector::from_fn(|i, _| values.get(i).copied().unwrap_or(D::from(f64::NAN)))
    }

    fn point_positions_generic_params<D: DualNum<Primitive = f64> + Copy>(
        &self,
        params: &SVector<D, K>,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> impl AsRef<[Vector2<D>]> {
        let q = |k: usize| if k < M { u[k] } else { v[k - M] };
        let field = |k: usize| self.dual_field(k, params);
        let points = self.program().points_dual(&field, &q);
        points
            .into_iter()
            .map(|[x, y]| Vector2::new(x, y))
            .collect::<Vec<_>>()
    }
}

impl<const M: usize, const F: usize, const P: usize, const K: usize> Fixed<M, F, P, K> {
    /// The fields of the view's parameters, in its order.
    fn differentiated_fields(&self) -> &[usize] {
        &self.columns().fields
    }

    /// The names of the view's parameters, in its order.
    fn differentiated_names(&self) -> Vec<&'static str> {
        let names = self.parameter_names();
        (self.differentiated_fields().iter())
            .map(|&k| names[k])
            .collect()
    }

    /// A field's value on dual numbers: the view's parameter of its column
    /// if it is one, its value otherwise.
    fn dual_field<D: DualNum<Primitive = f64> + Copy>(
        &self,
        k: usize,
        params: &SVector<D, K>,
    ) -> D {
        match self.columns().of_field.get(k).copied().flatten() {
            Some(c) if c < K => params[c],
            _ => D::from(self.parameters().get(k).copied().unwrap_or(f64::NAN)),
        }
    }
}

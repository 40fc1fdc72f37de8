//! The designer's own terms in a synthesis objective: residuals that are
//! functions of the model's parameters, written once on dual numbers so
//! that their exact gradient comes with their value (num-dual, one dual
//! direction per parameter) — a preferred crank length, a ratio between
//! two links, a penalty of one's own.

use super::problem::Problem;
use linkage_runtime::Sensitivities;
use nalgebra::{DMatrix, DVector, SVector};
use num_dual::DualSVec64;
use std::sync::Arc;

/// A term: r(p) on the parameters as dual numbers.
pub(crate) type TermFn<const K: usize> =
    Arc<dyn Fn(&SVector<DualSVec64<K>, K>) -> DualSVec64<K> + Send + Sync>;

/// A named term of the objective.
#[derive(Clone)]
pub(crate) struct Term<const K: usize> {
    pub name: String,
    pub residual: TermFn<K>,
}

impl<const K: usize> std::fmt::Debug for Term<K> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Term {{ {} }}", self.name)
    }
}

impl<L: Sensitivities<M, 1, K>, const M: usize, const K: usize> Problem<L, M, K> {
    /// Adds the designer's term `name` to the objective: the residual
    /// `residual(p)` (driven towards zero with the targets' residuals, in
    /// their units), p the model's parameters in `PARAM_NAMES` order as dual
    /// numbers, so that its exact gradient comes with it. With precision
    /// points each term is one more equation to meet.
    pub fn term(
        mut self,
        name: &str,
        residual: impl Fn(&SVector<DualSVec64<K>, K>) -> DualSVec64<K> + Send + Sync + 'static,
    ) -> Self {
        self.terms.push(Term {
            name: name.to_owned(),
            residual: Arc::new(residual),
        });
        self
    }
}

impl<L: Sensitivities<M, 1, K> + Clone, const M: usize, const K: usize> Problem<L, M, K> {
    /// Writes the terms' residuals and their Jacobian (the free
    /// parameters' columns; a driver does not enter them) into the rows
    /// after the targets'.
    pub(crate) fn add_terms(
        &self,
        x: &[f64],
        residuals: &mut DVector<f64>,
        jacobian: &mut DMatrix<f64>,
    ) {
        if self.terms.is_empty() {
            return;
        }
        let p = self.model_at(x).params();
        let dual =
            SVector::<DualSVec64<K>, K>::from_fn(|i, _| DualSVec64::from_re(p[i]).derivative(i));
        let first = self.target_residuals();
        for (t, term) in self.terms.iter().enumerate() {
            let value = (term.residual)(&dual);
            residuals[first + t] = value.re;
            // (num-dual leaves out a derivative that is zero.)
            let gradient = value.eps.0.unwrap_or_else(SVector::zeros);
            for (column, free) in self.free.iter().enumerate() {
                jacobian[(first + t, column)] = gradient[free.index];
            }
        }
    }
}

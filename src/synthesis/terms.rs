//! The designer's own terms in a synthesis objective: residuals that are
//! functions of the model's parameters, written once on dual numbers so
//! that their exact gradient comes with their value (num-dual, one dual
//! direction per parameter) — a preferred crank length, a ratio between
//! two links, a penalty of one's own.

use nalgebra::{DMatrix, DVector, SVector};
use num_dual::DualSVec64;
use std::sync::Arc;

/// A term: r(p) on the parameters as dual numbers.
type TermFn<const K: usize> =
    Arc<dyn Fn(&SVector<DualSVec64<K>, K>) -> DualSVec64<K> + Send + Sync>;

/// A named term of the objective.
#[derive(Clone)]
struct Term<const K: usize> {
    name: String,
    residual: TermFn<K>,
}

/// The terms of an objective, in the order they were added.
#[derive(Clone, Default)]
pub(crate) struct Terms<const K: usize> {
    terms: Vec<Term<K>>,
}

impl<const K: usize> std::fmt::Debug for Terms<K> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list()
            .entries(self.terms.iter().map(|t| &t.name))
            .finish()
    }
}

impl<const K: usize> Terms<K> {
    pub(crate) fn push(
        &mut self,
        name: &str,
        residual: impl Fn(&SVector<DualSVec64<K>, K>) -> DualSVec64<K> + Send + Sync + 'static,
    ) {
        self.terms.push(Term {
            name: name.to_owned(),
            residual: Arc::new(residual),
        });
    }

    /// How many: one residual each.
    pub(crate) fn len(&self) -> usize {
        self.terms.len()
    }

    /// Writes the terms' residuals at the parameters `p` into
    /// `residuals[first..]`, and their gradients into the same rows of
    /// `jacobian`: its column j is the parameter `free[j]` (a driver does
    /// not enter a term).
    pub(crate) fn write(
        &self,
        p: &SVector<f64, K>,
        free: impl Iterator<Item = usize> + Clone,
        first: usize,
        residuals: &mut DVector<f64>,
        jacobian: &mut DMatrix<f64>,
    ) {
        if self.terms.is_empty() {
            return;
        }
        let dual =
            SVector::<DualSVec64<K>, K>::from_fn(|i, _| DualSVec64::from_re(p[i]).derivative(i));
        for (t, term) in self.terms.iter().enumerate() {
            let value = (term.residual)(&dual);
            residuals[first + t] = value.re;
            // (num-dual leaves out a derivative that is zero.)
            let gradient = value.eps.0.unwrap_or_else(SVector::zeros);
            for (column, index) in free.clone().enumerate() {
                jacobian[(first + t, column)] = gradient[index];
            }
        }
    }
}

//! Mechanisms given at run time: the attribute's text, read, checked and
//! differentiated by the attribute's own front end while the program runs,
//! and evaluated by tapes — the kernels the attribute would generate,
//! compiled into register programs — instead of by rustc.
//!
//! A [`Mechanism`] knows its sizes only at run time. Seen at sizes fixed
//! at compile time ([`Mechanism::fixed`], which checks them), it is a
//! [`Fixed`], which implements [`Kernels`](crate::Kernels) and
//! [`Linkage`](crate::Linkage): every analysis of the library takes it as
//! it takes a compiled mechanism, and gives the compiled mechanism's
//! numbers, bit for bit, where the tape runs the same operations in the
//! same order as the generated code.
//!
//! ```
//! use linkage::mechanism::Mechanism;
//! use linkage::prelude::*;
//!
//! let four_bar = Mechanism::from_text(
//!     "FourBar",
//!     "u = [theta3, theta4],
//!      v = [theta2],
//!      points = [B = (l2 * theta2.cos(), l2 * theta2.sin())],
//!      closure = [
//!          l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
//!          l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
//!      ]",
//!     &[("l1", 80.0), ("l2", 20.0), ("l3", 50.0), ("l4", 70.0)],
//! )?;
//! assert_eq!((four_bar.m(), four_bar.f()), (2, 1));
//! let bar = four_bar.fixed::<2, 1>()?;
//! let pose = bar.analyze(
//!     &vector![1.2, -0.9], &vector![0.3], &vector![1.0], &vector![0.0],
//!     &Options::default(),
//! )?;
//! assert!(pose.residual < 1e-12);
//! // The same numbers as the compiled four-bar: see `linkage::mechanisms::FourBar`.
//! assert_eq!(pose.points.as_ref().len(), 1);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A mechanism with mistakes gives every one of them at once, located in
//! its text (see [`linkage_symbolic::text`]), in [`MechanismError::Mistakes`].

pub mod design;
mod error;
mod fixed;
mod interned;
mod kernel_tape;
mod point_set;
mod program;
mod scratch;
mod sensitive;
pub mod sizes;

pub use error::MechanismError;
pub use fixed::Fixed;
pub use linkage_symbolic::blocks::{Block, Blocks};
pub use linkage_symbolic::diagnostics::{Diagnostic, Diagnostics};
pub use linkage_symbolic::text::{Equations, Parameter};
pub use point_set::PointSet;

use sensitive::Columns;

use program::Program;
use std::sync::Arc;

/// A mechanism given at run time: its equations read and differentiated,
/// its kernels compiled into tapes, its parameters' values. Cheap to
/// clone (the tapes are shared).
#[derive(Clone, Debug)]
pub struct Mechanism {
    program: Arc<Program>,
    /// Every parameter's value, in the order of [`Mechanism::parameter_names`].
    fields: Vec<f64>,
}

impl Mechanism {
    /// The mechanism `name` (an identifier) whose equations are `equations`
    /// (the inside of `#[linkage::linkage(...)]`) and whose parameters have
    /// the values `parameters`, in SI or any one consistent set of units.
    pub fn from_text(
        name: &str,
        equations: &str,
        parameters: &[(&str, f64)],
    ) -> Result<Mechanism, MechanismError> {
        let declared: Vec<Parameter<'_>> =
            parameters.iter().map(|(n, _)| Parameter::new(n)).collect();
        let values: Vec<f64> = parameters.iter().map(|(_, x)| *x).collect();
        Mechanism::build(name, Equations::new(equations), &declared, &values)
    }

    /// The mechanism `name` whose equations sit in a larger file
    /// (`equations`: the text and where it starts) and whose parameters are
    /// declared in it (`parameters`, with `values` in the same order): every
    /// mistake located in the file.
    pub fn build(
        name: &str,
        equations: Equations<'_>,
        parameters: &[Parameter<'_>],
        values: &[f64],
    ) -> Result<Mechanism, MechanismError> {
        let built = linkage_symbolic::text::build(name, equations, parameters)?;
        let program = Program::new(name, equations.text, parameters, &built.derivatives)?;
        if values.len() != program.field_names.len() {
            return Err(MechanismError::Internal {
                what: format!(
                    "{} values for {} parameters",
                    values.len(),
                    program.field_names.len()
                ),
            });
        }
        let mut mechanism = Mechanism {
            program: Arc::new(program),
            fields: vec![0.0; values.len()],
        };
        for (k, &value) in values.iter().enumerate() {
            let name = mechanism.program.field_names[k];
            mechanism.set_parameter(name, value)?;
        }
        Ok(mechanism)
    }

    /// Its name.
    pub fn name(&self) -> &str {
        &self.program.name
    }

    /// The number m of dependent coordinates u.
    pub fn m(&self) -> usize {
        self.program.m
    }

    /// The number f of driving coordinates v.
    pub fn f(&self) -> usize {
        self.program.f
    }

    /// The dependent coordinates u, in order.
    pub fn u_names(&self) -> &[&'static str] {
        &self.program.u_names
    }

    /// The driving coordinates v, in order.
    pub fn v_names(&self) -> &[&'static str] {
        &self.program.v_names
    }

    /// The named points, in order.
    pub fn point_names(&self) -> &'static [&'static str] {
        self.program.point_names
    }

    /// Every parameter, in order.
    pub fn parameter_names(&self) -> &[&'static str] {
        &self.program.field_names
    }

    /// Every parameter's value, in the order of
    /// [`Mechanism::parameter_names`].
    pub fn parameters(&self) -> &[f64] {
        &self.fields
    }

    /// The parameters p the sensitivities differentiate by (`params =
    /// [...]`, or every parameter the equations use), in order.
    pub fn differentiated(&self) -> Vec<&'static str> {
        (self.program.params.iter())
            .map(|&k| self.program.field_names[k])
            .collect()
    }

    /// Whether the two acceleration methods expand to the same polynomial
    /// in q̇ (`None`: too large to expand).
    pub fn methods_agree(&self) -> Option<bool> {
        self.program.methods_agree
    }

    /// Ψ_u's diagonal blocks in the order they are solved, found from which
    /// of its entries are not identically zero (its `Display` is the
    /// sentence of the compiled mechanism's symbolic table).
    pub fn blocks(&self) -> &Blocks {
        &self.program.blocks
    }

    /// Sets a parameter's value.
    pub fn set_parameter(&mut self, name: &str, value: f64) -> Result<(), MechanismError> {
        let Some(k) = self.program.field_names.iter().position(|n| *n == name) else {
            return Err(MechanismError::UnknownParameter {
                name: name.to_owned(),
                known: owned(&self.program.field_names),
            });
        };
        if !value.is_finite() {
            return Err(MechanismError::NotFinite {
                name: name.to_owned(),
                value,
            });
        }
        self.fields[k] = value;
        Ok(())
    }

    /// Ψ(u, v), the closure equations' residuals in their order, at a pose
    /// of any sizes (`u` of m coordinates, `v` of f): for a look at a pose
    /// without a view at fixed sizes (how far a sketch is from closing).
    pub fn residual(&self, u: &[f64], v: &[f64]) -> Result<Vec<f64>, MechanismError> {
        let (m, f) = (self.m(), self.f());
        if (u.len(), v.len()) != (m, f) {
            return Err(MechanismError::Sizes {
                asked: (u.len(), v.len()),
                has: (m, f),
            });
        }
        let field = |k: usize| self.fields[k];
        let q = |k: usize| if k < m { u[k] } else { v[k - m] };
        Ok(self.program.psi_dual(&field, &q))
    }

    /// The mechanism seen at m = `M`, f = `F`, with room for 32 named
    /// points: an error if those are not its sizes.
    pub fn fixed<const M: usize, const F: usize>(&self) -> Result<Fixed<M, F>, MechanismError> {
        self.fixed_with::<M, F, 32>()
    }

    /// [`Mechanism::fixed`] with room for `P` named points.
    pub fn fixed_with<const M: usize, const F: usize, const P: usize>(
        &self,
    ) -> Result<Fixed<M, F, P>, MechanismError> {
        self.view(&[])
    }

    /// The mechanism at m = `M`, f = `F`, with room for 32 named points and
    /// its sensitivities by every parameter it is differentiated by
    /// ([`Mechanism::differentiated`], in that order): `K` must be their
    /// number. The view implements [`Sensitivities`](crate::Sensitivities),
    /// so that the sensitivities, the tolerance analyses and the synthesis
    /// take it.
    pub fn sensitive<const M: usize, const F: usize, const K: usize>(
        &self,
    ) -> Result<Fixed<M, F, 32, K>, MechanismError> {
        let has = self.program.params.len();
        if has != K {
            return Err(MechanismError::Parameters { asked: K, has });
        }
        self.view(&(0..has).collect::<Vec<_>>())
    }

    /// [`Mechanism::sensitive`] by the parameters `names` only, in this
    /// order, with room for `K` ≥ `names.len()` of them and for `P` named
    /// points: the columns after the named parameters are zero and their
    /// names empty. (A caller that learns which parameters at run time, the
    /// command-line tool, compiles its analyses for a few `K` and takes the
    /// smallest that holds them; the zero columns change no other column's
    /// numbers.)
    pub fn differentiated_by<const M: usize, const F: usize, const P: usize, const K: usize>(
        &self,
        names: &[&str],
    ) -> Result<Fixed<M, F, P, K>, MechanismError> {
        if names.len() > K {
            return Err(MechanismError::TooManyParameters {
                parameters: names.len(),
                most: K,
            });
        }
        let mut chosen = Vec::with_capacity(names.len());
        for &name in names {
            let column =
                (self.program.params.iter()).position(|&k| self.program.field_names[k] == name);
            match column {
                Some(c) if chosen.contains(&c) => {
                    return Err(MechanismError::RepeatedParameter {
                        name: name.to_owned(),
                    });
                }
                Some(c) => chosen.push(c),
                None if self.program.field_names.contains(&name) => {
                    return Err(MechanismError::NotDifferentiated {
                        name: name.to_owned(),
                        differentiated: owned(&self.differentiated()),
                    });
                }
                None => {
                    return Err(MechanismError::UnknownParameter {
                        name: name.to_owned(),
                        known: owned(&self.program.field_names),
                    });
                }
            }
        }
        self.view(&chosen)
    }

    /// The view at the sizes asked for, checked, differentiated by the
    /// tapes' columns `chosen`.
    fn view<const M: usize, const F: usize, const P: usize, const K: usize>(
        &self,
        chosen: &[usize],
    ) -> Result<Fixed<M, F, P, K>, MechanismError> {
        if (M, F) != (self.m(), self.f()) {
            return Err(MechanismError::Sizes {
                asked: (M, F),
                has: (self.m(), self.f()),
            });
        }
        let points = self.point_names().len();
        if points > P {
            return Err(MechanismError::TooManyPoints { points, most: P });
        }
        let columns = Columns::new(chosen, &self.program.params, self.fields.len());
        Ok(Fixed::new(
            self.program.clone(),
            self.fields.clone(),
            columns,
        ))
    }
}

/// Names as owned strings, for an error.
fn owned(names: &[&str]) -> Vec<String> {
    names.iter().map(|n| n.to_string()).collect()
}

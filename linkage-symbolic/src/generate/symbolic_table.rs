//! The `SYMBOLIC` constant: every quantity of the table that has a key,
//! as formulas a program can print.

use super::Generator;
use super::quantities::{QUANTITIES, Shape, Source};
use crate::dag::{Dag, Id};
use crate::derivatives::Matrix;
use crate::names::subscript;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

impl Generator<'_> {
    /// The `SymbolicTable` constant: every generated quantity as text.
    pub(super) fn symbolic_table(&self) -> TokenStream {
        let model = self.model;
        let fmt = self.formatter();
        let (m, f) = (self.m, self.f);
        let eq_labels: Vec<String> = (1..=m)
            .map(|i| format!("Ψ{}", subscript(&i.to_string())))
            .collect();
        let u_labels: Vec<String> = (0..m).map(|k| self.names.coord(k)).collect();
        let v_labels: Vec<String> = (m..m + f).map(|k| self.names.coord(k)).collect();
        let q_labels: Vec<String> = (0..m + f).map(|k| self.names.coord(k)).collect();
        let point_labels: Vec<String> = model.points.iter().map(|p| p.name.clone()).collect();
        let p_labels = self.names.params_display();
        let point_xy_labels: Vec<String> = model
            .points
            .iter()
            .flat_map(|p| [format!("{}.x", p.name), format!("{}.y", p.name)])
            .collect();
        let xy = ["x".to_owned(), "y".to_owned()];
        let one = ["".to_owned()];
        let mut entries: Vec<TokenStream> = Vec::new();
        for q in QUANTITIES {
            let Some(key) = q.key else { continue };
            let matrix = match q.source {
                Source::Formula(matrix) => matrix.of(model).clone(),
                Source::Points(pick) => self.points_matrix(pick),
                Source::Determinant => match model.det_psi_u {
                    Some(det) => Matrix::column(vec![det]),
                    None => continue,
                },
                Source::PointsByParams(level) => self.points_by_params_matrix(level),
                Source::PsiAndPsiU
                | Source::Kinematics { .. }
                | Source::SensitivityTerms { .. } => {
                    continue;
                }
            };
            let (rows, cols): (&[String], &[String]) = match (q.source, q.shape) {
                (Source::Determinant, _) => (&one, &one),
                (_, Shape::Column) => (&eq_labels, &one),
                (_, Shape::Square) => (&eq_labels, &u_labels),
                (_, Shape::Wide) => (&eq_labels, &v_labels),
                (_, Shape::Full) => (&eq_labels, &q_labels),
                (_, Shape::ByParams) => (&eq_labels, &p_labels),
                (Source::PointsByParams(_), Shape::Points) => (&point_xy_labels, &p_labels),
                (_, Shape::Points) => (&point_labels, &xy),
                (_, Shape::ColumnAndSquare | Shape::Kinematics | Shape::SensitivityTerms) => {
                    continue;
                }
            };
            let nonzero = matrix
                .entries
                .iter()
                .enumerate()
                .filter(|(_, e)| **e != Dag::ZERO)
                .map(|(k, &e)| {
                    let (i, j) = (
                        Literal::usize_unsuffixed(k / matrix.cols),
                        Literal::usize_unsuffixed(k % matrix.cols),
                    );
                    let text = fmt.format(e);
                    quote!((#i, #j, #text))
                });
            let (r, c) = (
                Literal::usize_unsuffixed(matrix.rows),
                Literal::usize_unsuffixed(matrix.cols),
            );
            let title = q.symbol;
            entries.push(quote! {
                ::linkage::SymbolicMatrix {
                    key: #key,
                    title: #title,
                    rows: #r,
                    cols: #c,
                    row_labels: &[#(#rows),*],
                    col_labels: &[#(#cols),*],
                    nonzero: &[#(#nonzero),*],
                }
            });
        }
        let name = self.input.item.ident.to_string();
        let agree = match model.methods_agree {
            Some(b) => quote!(::core::option::Option::Some(#b)),
            None => quote!(::core::option::Option::None),
        };
        let structure = (model.blocks).describe(|k| u_labels[k].clone());
        quote! {
            ::linkage::SymbolicTable {
                name: #name,
                u: &[#(#u_labels),*],
                v: &[#(#v_labels),*],
                matrices: &[#(#entries),*],
                methods_agree: #agree,
                structure: #structure,
            }
        }
    }

    /// The explicit derivatives by the parameters of the points' positions
    /// (0), velocities (1) or accelerations (2): a row per coordinate (B.x,
    /// B.y, …), a column per parameter.
    fn points_by_params_matrix(&self, level: usize) -> Matrix {
        let points = &self.model.points;
        let entries: Vec<Id> = points
            .iter()
            .flat_map(|p| p.by_p[level].entries.iter().copied())
            .collect();
        Matrix {
            rows: 2 * points.len(),
            cols: self.k,
            entries,
        }
    }

    /// The points' positions (0), velocities (1) or accelerations (2) as a
    /// matrix with a row per point and columns x, y.
    fn points_matrix(&self, pick: usize) -> Matrix {
        let points = &self.model.points;
        let entries: Vec<Id> = points
            .iter()
            .flat_map(|p| [p.position, p.velocity, p.acceleration][pick])
            .collect();
        Matrix {
            rows: points.len(),
            cols: 2,
            entries,
        }
    }
}

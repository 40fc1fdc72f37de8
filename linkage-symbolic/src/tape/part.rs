//! Where a tape's outputs go: each phase's outputs fill consecutive parts
//! of the result, each a matrix with some entries listed and every other
//! entry zero.

/// How a part appears in the generated function's result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// An nalgebra matrix (a vector when it has one column), the nonzero
    /// entries listed row by row.
    Matrix,
    /// One (x, y) per point: row i is point i, column 0 its x and column 1
    /// its y; every entry listed, zero or not.
    Points,
    /// For each column (a coordinate of u or a parameter), one (x, y) per
    /// point: row 2i + c is coordinate c (x, y) of point i; the nonzero
    /// entries listed column by column.
    PointColumns,
}

/// A part of a result, filled by consecutive outputs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Part {
    /// Its name in generated code (`psi_u`, `points_p`).
    pub name: &'static str,
    pub form: Form,
    pub rows: usize,
    pub cols: usize,
    /// The (row, column) each output fills, in the order of the outputs.
    pub entries: Vec<(usize, usize)>,
}

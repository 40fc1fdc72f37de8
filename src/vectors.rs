//! `vector!` and `matrix!` that resolve through `linkage`, so that a crate
//! whose only dependency is linkage can write them: nalgebra's own macros
//! expand to paths that start with `nalgebra::`, which a crate without
//! nalgebra as a direct dependency cannot name.

/// A column vector of fixed size, as nalgebra's `vector!`:
/// `vector![a, b, c]` is an `SVector<T, 3>`.
///
/// ```
/// use linkage::prelude::*;
/// let v: SVector<f64, 3> = vector![1.0, 2.0, 3.0];
/// assert_eq!(v[2], 3.0);
/// ```
#[macro_export]
macro_rules! vector {
    ($($x:expr),+ $(,)?) => {
        $crate::nalgebra::SVector::from_array_storage(
            $crate::nalgebra::ArrayStorage([[$($x),+]]),
        )
    };
}

/// A matrix of fixed size, written by rows as nalgebra's `matrix!`:
/// `matrix![a, b; c, d]` is the `SMatrix<T, 2, 2>` with rows (a, b) and
/// (c, d).
///
/// ```
/// use linkage::prelude::*;
/// let a: SMatrix<f64, 2, 3> = matrix![1.0, 2.0, 3.0; 4.0, 5.0, 6.0];
/// assert_eq!(a[(1, 0)], 4.0);
/// assert_eq!(a[(0, 2)], 3.0);
/// ```
#[macro_export]
macro_rules! matrix {
    ($($($x:expr),+ $(,)?);+ $(;)?) => {
        // The rows as the columns of the transpose (nalgebra stores by
        // columns), then transposed: exact, and for the small matrices of
        // a mechanism as cheap as a copy.
        $crate::nalgebra::SMatrix::from_array_storage(
            $crate::nalgebra::ArrayStorage([$([$($x),+]),+]),
        )
        .transpose()
    };
}

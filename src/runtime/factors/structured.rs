//! Products by a matrix with Ψ_u's structure (Ψ̇_u and Ψ̈_u, whose entries
//! are zero wherever Ψ_u's are at every pose): only the entries inside the
//! blocks' reach are multiplied, so that a product costs what those
//! entries number (for a chain of loops, linearly in m) rather than m².

use super::Factors;
use nalgebra::SMatrix;

impl<const M: usize> Factors<M> {
    /// a·b for an `a` that is zero outside the reach of Ψ_u's blocks, each
    /// entry summed over the coordinates in their order as a dense product
    /// sums it: the same numbers (the terms left out are zeros, and a sum
    /// that starts from +0 is never −0), but that an infinity or a NaN in
    /// a row of b meets only the rows of `a` that can be nonzero in its
    /// column (its own block's among them). Dense when Ψ_u was inverted
    /// whole.
    pub(crate) fn structured_product<const K: usize>(
        &self,
        a: &SMatrix<f64, M, M>,
        b: &SMatrix<f64, M, K>,
    ) -> SMatrix<f64, M, K> {
        let mut out = SMatrix::<f64, M, K>::zeros();
        if self.is_whole() {
            for k in 0..M {
                add_column_times(&mut out, a, b, k, 0..M);
            }
            return out;
        }
        let order = &self.order;
        let blocks = order.blocks as usize;
        // Each coordinate's position in the solve order, and each
        // position's block.
        let mut position = [0usize; M];
        for (p, &c) in order.coordinates.iter().enumerate() {
            position[c as usize] = p;
        }
        let mut block_at = [0usize; M];
        for block in 0..blocks {
            let (start, end, _) = order.block(block);
            block_at[start..end].fill(block);
        }
        for (k, &p) in position.iter().enumerate() {
            // Column k can be nonzero on the equations of its own block
            // and of the later blocks whose reach begins at or before it.
            for block in block_at[p]..blocks {
                let (start, end, reach) = order.block(block);
                if reach <= p {
                    let rows = order.equations[start..end].iter().map(|&e| e as usize);
                    add_column_times(&mut out, a, b, k, rows);
                }
            }
        }
        out
    }
}

/// out[i, j] += a[i, k]·b[k, j] for the rows `rows` and every column j.
#[inline(always)]
fn add_column_times<const M: usize, const K: usize>(
    out: &mut SMatrix<f64, M, K>,
    a: &SMatrix<f64, M, M>,
    b: &SMatrix<f64, M, K>,
    k: usize,
    rows: impl Iterator<Item = usize> + Clone,
) {
    for j in 0..K {
        let scale = b[(k, j)];
        for i in rows.clone() {
            out[(i, j)] += a[(i, k)] * scale;
        }
    }
}

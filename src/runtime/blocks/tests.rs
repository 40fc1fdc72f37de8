//! The block-by-block inverse against the whole matrix's: random block
//! lower triangular matrices in shuffled orders, singular and non-finite
//! blocks, extreme scales, and orders that are no permutation.

use super::*;
use crate::runtime::linalg::determinant;

/// A small deterministic generator (xorshift), uniform in [−1, 1).
struct Numbers(u64);

impl Numbers {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    fn below(&mut self, n: usize) -> usize {
        (((self.next() + 1.0) / 2.0) * n as f64) as usize % n
    }
    fn shuffled(&mut self, n: usize) -> Vec<usize> {
        let mut order: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            order.swap(i, self.below(i + 1));
        }
        order
    }
}

/// A random matrix that is block lower triangular in a random order, its
/// order (equations, coordinates, ends) and its density of couplings.
fn random_case<const M: usize>(
    numbers: &mut Numbers,
) -> (SMatrix<f64, M, M>, Vec<usize>, Vec<usize>, Vec<usize>) {
    let mut ends = Vec::new();
    let mut end = 0;
    while end < M {
        end = (end + 1 + numbers.below(4)).min(M);
        ends.push(end);
    }
    let (equations, coordinates) = (numbers.shuffled(M), numbers.shuffled(M));
    let block_of = |position: usize| ends.iter().position(|&e| position < e).unwrap();
    let mut a = SMatrix::<f64, M, M>::zeros();
    for r in 0..M {
        for s in 0..M {
            let (br, bs) = (block_of(r), block_of(s));
            let value = if br == bs {
                // Diagonally heavy blocks: regular, moderately conditioned.
                numbers.next() + if r == s { 3.0 } else { 0.0 }
            } else if bs < br && numbers.next() > 0.0 {
                numbers.next() * 2.0
            } else {
                0.0
            };
            a[(equations[r], coordinates[s])] = value;
        }
    }
    (a, equations, coordinates, ends)
}

fn agrees<const M: usize>(a: &SMatrix<f64, M, M>, blocks: PsiUBlocks<'_>) {
    let by_blocks = invert_in_blocks(a, blocks);
    let whole = invert(a);
    assert!(whole.rcond > 0.0 && by_blocks.rcond > 0.0);
    let residual = (a * by_blocks.inverse - SMatrix::<f64, M, M>::identity()).amax();
    assert!(
        residual < 1e-13 / whole.rcond,
        "‖A·X − I‖ = {residual:e}, rcond {:e}",
        whole.rcond
    );
    let scale = whole.inverse.amax();
    assert!((by_blocks.inverse - whole.inverse).amax() <= 1e-13 * scale / whole.rcond);
    assert!(
        (by_blocks.det - whole.det).abs() <= 1e-12 * whole.det.abs(),
        "det {} by blocks, {} whole",
        by_blocks.det,
        whole.det
    );
    assert!(
        (by_blocks.rcond - whole.rcond).abs() <= 1e-12 * whole.rcond,
        "rcond {:e} by blocks, {:e} whole",
        by_blocks.rcond,
        whole.rcond
    );
}

#[test]
fn random_block_triangular_matrices_invert_as_whole_ones() {
    let mut numbers = Numbers(0x9e37_79b9_7f4a_7c15);
    for _ in 0..300 {
        let (a, equations, coordinates, ends) = random_case::<7>(&mut numbers);
        let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
        assert_eq!(blocks.len(), ends.len());
        agrees(&a, blocks);
        let (a, equations, coordinates, ends) = random_case::<12>(&mut numbers);
        agrees(&a, PsiUBlocks::new(&equations, &coordinates, &ends));
    }
}

#[test]
fn the_determinant_keeps_the_sign_of_the_orders() {
    // Anti-diagonal 6×6 in six 1×1 blocks, coordinates in reverse (an odd
    // permutation: 15 inversions), one coupling below: det = −2·3·…·7.
    let mut a = SMatrix::<f64, 6, 6>::zeros();
    for i in 0..6 {
        a[(i, 5 - i)] = (i + 2) as f64;
    }
    a[(2, 5)] = 1.0;
    let blocks = PsiUBlocks::new(
        &[0, 1, 2, 3, 4, 5],
        &[5, 4, 3, 2, 1, 0],
        &[1, 2, 3, 4, 5, 6],
    );
    let inverse = invert_in_blocks(&a, blocks);
    assert_eq!(inverse.det, -5040.0);
    assert!((determinant(&a) + 5040.0).abs() < 1e-9);
    agrees(&a, blocks);
}

#[test]
fn small_matrices_are_inverted_whole() {
    let mut numbers = Numbers(13);
    let (a, equations, coordinates, ends) = random_case::<4>(&mut numbers);
    let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
    let (by_blocks, whole) = (invert_in_blocks(&a, blocks), invert(&a));
    assert_eq!(by_blocks.inverse, whole.inverse);
    assert_eq!((by_blocks.rcond, by_blocks.det), (whole.rcond, whole.det));
}

#[test]
fn a_singular_block_gives_rcond_zero() {
    let mut numbers = Numbers(7);
    let (mut a, equations, coordinates, ends) = random_case::<7>(&mut numbers);
    let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
    // The last block's first equation made zero within the block: the
    // whole matrix is singular though that row is not zero.
    let (last_equations, last_coordinates) = blocks.blocks().last().unwrap();
    for &c in last_coordinates {
        a[(last_equations[0], c)] = 0.0;
    }
    assert_eq!(determinant(&a), 0.0);
    let inverse = invert_in_blocks(&a, blocks);
    assert_eq!((inverse.rcond, inverse.det), (0.0, 0.0));
    let mut nan = a;
    nan[(equations[0], coordinates[0])] = f64::NAN;
    assert_eq!(invert_in_blocks(&nan, blocks).rcond, 0.0);
    assert_eq!(
        invert_in_blocks(&SMatrix::<f64, 7, 7>::zeros(), blocks).rcond,
        0.0
    );
}

#[test]
fn extreme_scales_are_scaled_exactly() {
    let mut numbers = Numbers(11);
    let (a, equations, coordinates, ends) = random_case::<7>(&mut numbers);
    let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
    let ordinary = invert_in_blocks(&a, blocks);
    for p in [-1000, -600, 600, 1000] {
        let factor = 2f64.powi(p / 2) * 2f64.powi(p - p / 2);
        let scaled = invert_in_blocks(&(a * factor), blocks);
        assert_eq!(scaled.rcond, ordinary.rcond, "2^{p}");
        assert_eq!(scaled.det.signum(), ordinary.det.signum(), "2^{p}");
        // The inverse is scaled back by 1/2^p: exact where it stays normal.
        if p.abs() < 1000 {
            assert_eq!(scaled.inverse * factor, ordinary.inverse, "2^{p}");
        }
    }
}

#[test]
fn orders_that_are_no_permutation_are_dense() {
    assert_eq!(
        PsiUBlocks::new(&[0, 0], &[0, 1], &[1, 2]),
        PsiUBlocks::DENSE
    );
    assert_eq!(
        PsiUBlocks::new(&[0, 2], &[0, 1], &[1, 2]),
        PsiUBlocks::DENSE
    );
    assert_eq!(PsiUBlocks::new(&[0, 1], &[0], &[1, 2]), PsiUBlocks::DENSE);
    assert_eq!(
        PsiUBlocks::new(&[0, 1], &[0, 1], &[2, 1]),
        PsiUBlocks::DENSE
    );
    assert_eq!(PsiUBlocks::new(&[0, 1], &[0, 1], &[1]), PsiUBlocks::DENSE);
    assert_eq!(PsiUBlocks::new(&[1, 0], &[0, 1], &[2]), PsiUBlocks::DENSE);
    assert_eq!(
        PsiUBlocks::new(&[0, 1], &[0, 1], &[0, 2]),
        PsiUBlocks::DENSE
    );
    assert_eq!(PsiUBlocks::DENSE.len(), 1);
    // The dense order, and one of another size, invert whole.
    let a = SMatrix::<f64, 2, 2>::new(2.0, 1.0, -1.0, 3.0);
    assert_eq!(
        invert_in_blocks(&a, PsiUBlocks::DENSE).inverse,
        invert(&a).inverse
    );
    let three = PsiUBlocks::new(&[0, 1, 2], &[0, 1, 2], &[1, 3]);
    assert_eq!(invert_in_blocks(&a, three).inverse, invert(&a).inverse);
}

/// A 1×1 block, then one of N − 1, coupled to it.
fn one_then_large<const N: usize>(seed: u64) -> SMatrix<f64, N, N> {
    let mut numbers = Numbers(seed);
    SMatrix::<f64, N, N>::from_fn(|r, s| {
        if r == 0 && s > 0 {
            0.0
        } else {
            numbers.next() + if r == s { 3.0 } else { 0.0 }
        }
    })
}

#[test]
fn a_block_beyond_8x8_inverts_by_elimination_on_the_heap() {
    let a = one_then_large::<11>(17);
    let order: Vec<usize> = (0..11).collect();
    agrees(&a, PsiUBlocks::new(&order, &order, &[1, 11]));
}

#[test]
fn large_blocks_invert_by_elimination() {
    // One 5×5 block after a 1×1: Gauss–Jordan for the large block.
    let mut numbers = Numbers(3);
    let mut a = SMatrix::<f64, 6, 6>::zeros();
    for r in 0..6 {
        for s in 0..6 {
            if r == 0 && s > 0 {
                continue;
            }
            a[(r, s)] = numbers.next() + if r == s { 3.0 } else { 0.0 };
        }
    }
    let blocks = PsiUBlocks::new(&[0, 1, 2, 3, 4, 5], &[0, 1, 2, 3, 4, 5], &[1, 6]);
    agrees(&a, blocks);
}

#[test]
fn blocks_that_are_not_the_matrixs_invert_it_whole() {
    let mut numbers = Numbers(5);
    for _ in 0..50 {
        let (mut a, equations, coordinates, ends) = random_case::<7>(&mut numbers);
        let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
        // An entry of the first block's equation in the last block's
        // coordinate: no longer triangular in this order.
        let (first, _) = blocks.blocks().next().unwrap();
        let (_, last) = blocks.blocks().last().unwrap();
        a[(first[0], last[0])] = 0.5;
        let whole = invert(&a);
        let by_blocks = invert_in_blocks(&a, blocks);
        assert_eq!(by_blocks.inverse, whole.inverse);
        assert_eq!((by_blocks.rcond, by_blocks.det), (whole.rcond, whole.det));
        let huge = invert_in_blocks(&(a * 2f64.powi(700)), blocks);
        assert_eq!(huge.rcond, invert(&(a * 2f64.powi(700))).rcond);
    }
}

//! Factors in blocks against the whole matrix's inverse: random block lower
//! triangular matrices in shuffled orders, the transposed solve, the
//! estimate of the conditioning against the exact value, singular and
//! non-finite blocks, extreme scales, and orders that are no permutation.

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
    fn vector<const M: usize>(&mut self) -> SVector<f64, M> {
        SVector::<f64, M>::from_fn(|_, _| self.next())
    }
}

/// A block lower triangular matrix in a random order, and its order.
struct Case<const M: usize> {
    a: SMatrix<f64, M, M>,
    equations: Vec<usize>,
    coordinates: Vec<usize>,
    ends: Vec<usize>,
    reach: Vec<usize>,
}

impl<const M: usize> Case<M> {
    fn random(numbers: &mut Numbers) -> Case<M> {
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
        Case::with_reach(a, equations, coordinates, ends)
    }

    /// The case of `a` in this order, each block's reach read from `a`.
    fn with_reach(
        a: SMatrix<f64, M, M>,
        equations: Vec<usize>,
        coordinates: Vec<usize>,
        ends: Vec<usize>,
    ) -> Case<M> {
        let mut start = 0;
        let reach = (ends.iter())
            .map(|&end| {
                let first = (0..start)
                    .find(|&p| (start..end).any(|s| a[(equations[s], coordinates[p])] != 0.0))
                    .unwrap_or(start);
                start = end;
                first
            })
            .collect();
        Case {
            a,
            equations,
            coordinates,
            ends,
            reach,
        }
    }

    fn blocks(&self) -> PsiUBlocks<'_> {
        PsiUBlocks::new(&self.equations, &self.coordinates, &self.ends, &self.reach)
    }
}

/// The factors solve as the whole inverse does, both ways; det as the
/// whole matrix's (to rounding, which grows with the conditioning); the
/// estimated rcond never below the exact one, and within a factor of 3.5
/// of it (3.2 at worst on the random matrices below). Whether the
/// estimate was exact.
fn agrees<const M: usize>(a: &SMatrix<f64, M, M>, blocks: PsiUBlocks<'_>) -> bool {
    assert!(blocks.fits(a));
    let factors = Factors::of(a, blocks);
    assert!(factors.in_blocks());
    let whole = invert(a);
    assert!(whole.rcond > 0.0 && factors.rcond() > 0.0);
    let tolerance = 1e-13 * whole.inverse.amax() / whole.rcond;
    let mut numbers = Numbers(99);
    for _ in 0..3 {
        let b = numbers.vector::<M>();
        let x = factors.solve(&b);
        assert!((x - whole.inverse * b).amax() <= tolerance * b.amax());
        let y = factors.backward(&b);
        assert!((y - whole.inverse.transpose() * b).amax() <= tolerance * b.amax());
    }
    assert!((factors.inverse() - whole.inverse).amax() <= tolerance);
    let psi_v = SMatrix::<f64, M, 2>::from_fn(|_, _| numbers.next());
    assert!((factors.solve_columns(&psi_v) - whole.inverse * psi_v).amax() <= 2.0 * tolerance);
    assert!(
        (factors.det() - whole.det).abs() <= 1e-14 * whole.det.abs() / whole.rcond,
        "det {} by blocks, {} whole",
        factors.det(),
        whole.det
    );
    let (estimate, exact) = (factors.rcond(), whole.rcond);
    assert!(
        // (The exact value, from the whole inverse, is itself only as
        // accurate as the conditioning allows.)
        estimate >= exact * (1.0 - 1e-12) - 1e-15 && estimate <= 3.5 * exact,
        "rcond {estimate:e} estimated, {exact:e} exact"
    );
    (estimate - exact).abs() <= 1e-12 * exact
}

#[test]
fn random_block_triangular_matrices_solve_as_whole_ones() {
    let mut numbers = Numbers(0x9e37_79b9_7f4a_7c15);
    let mut exact = 0;
    for _ in 0..300 {
        let case = Case::<7>::random(&mut numbers);
        assert_eq!(case.blocks().len(), case.ends.len());
        exact += usize::from(agrees(&case.a, case.blocks()));
        let case = Case::<12>::random(&mut numbers);
        exact += usize::from(agrees(&case.a, case.blocks()));
    }
    // The estimate is the exact norm for more than half of these matrices
    // (354 of 600 when written; within a factor 3.2 for all).
    assert!(exact >= 350, "exact {exact} of 600");
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
    let case = Case::with_reach(
        a,
        (0..6).collect(),
        (0..6).rev().collect(),
        (1..7).collect(),
    );
    assert_eq!(case.reach, [0, 1, 0, 3, 4, 5]);
    assert_eq!(Factors::of(&a, case.blocks()).det(), -5040.0);
    assert!((determinant(&a) + 5040.0).abs() < 1e-9);
    agrees(&a, case.blocks());
}

#[test]
fn small_matrices_are_inverted_whole() {
    let mut numbers = Numbers(13);
    let case = Case::<4>::random(&mut numbers);
    let (factors, whole) = (Factors::of(&case.a, case.blocks()), invert(&case.a));
    assert!(!factors.in_blocks());
    assert_eq!(factors.inverse(), whole.inverse);
    assert_eq!((factors.rcond(), factors.det()), (whole.rcond, whole.det));
    let b = numbers.vector::<4>();
    assert_eq!(factors.solve(&b), whole.inverse * b);
}

#[test]
fn a_singular_block_gives_rcond_zero() {
    let mut numbers = Numbers(7);
    let case = Case::<7>::random(&mut numbers);
    let blocks = case.blocks();
    // The last block's first equation made zero within the block: the
    // whole matrix is singular though that row is not zero.
    let mut a = case.a;
    let (last_equations, last_coordinates) = blocks.blocks().last().unwrap();
    for &c in last_coordinates {
        a[(last_equations[0], c)] = 0.0;
    }
    assert_eq!(determinant(&a), 0.0);
    let factors = Factors::of(&a, blocks);
    assert_eq!((factors.rcond(), factors.det()), (0.0, 0.0));
    // A NaN in a diagonal block, and in a coupling.
    let mut nan = case.a;
    nan[(case.equations[0], case.coordinates[0])] = f64::NAN;
    assert_eq!(Factors::of(&nan, blocks).rcond(), 0.0);
    let coupling = (0..7)
        .flat_map(|e| (0..7).map(move |k| (e, k)))
        .find(|&(e, k)| {
            let position = |list: &[usize], x| list.iter().position(|&y| y == x).unwrap();
            let block = |p| case.ends.iter().position(|&end| p < end).unwrap();
            case.a[(e, k)] != 0.0
                && block(position(&case.equations, e)) != block(position(&case.coordinates, k))
        })
        .expect("a coupling");
    let mut nan = case.a;
    nan[coupling] = f64::NAN;
    assert_eq!(Factors::of(&nan, blocks).rcond(), 0.0);
    let mut infinite = case.a;
    infinite[coupling] = f64::INFINITY;
    assert_eq!(Factors::of(&infinite, blocks).rcond(), 0.0);
    assert_eq!(
        Factors::of(&SMatrix::<f64, 7, 7>::zeros(), blocks).rcond(),
        0.0
    );
}

#[test]
fn extreme_scales_are_scaled_exactly() {
    let mut numbers = Numbers(11);
    let case = Case::<7>::random(&mut numbers);
    let ordinary = Factors::of(&case.a, case.blocks());
    for p in [-1000, -600, 600, 1000] {
        let factor = 2f64.powi(p / 2) * 2f64.powi(p - p / 2);
        let scaled = Factors::of(&(case.a * factor), case.blocks());
        assert_eq!(scaled.rcond(), ordinary.rcond(), "2^{p}");
        assert_eq!(scaled.det().signum(), ordinary.det().signum(), "2^{p}");
        // The solves are scaled back by 1/2^p: exact where they stay normal.
        if p.abs() < 1000 {
            assert_eq!(scaled.inverse() * factor, ordinary.inverse(), "2^{p}");
        }
    }
}

#[test]
fn orders_that_are_no_permutation_are_dense() {
    let dense = |e: &[usize], c: &[usize], ends: &[usize], reach: &[usize]| {
        PsiUBlocks::new(e, c, ends, reach) == PsiUBlocks::DENSE
    };
    assert!(dense(&[0, 0], &[0, 1], &[1, 2], &[0, 0]));
    assert!(dense(&[0, 2], &[0, 1], &[1, 2], &[0, 0]));
    assert!(dense(&[0, 1], &[0], &[1, 2], &[0, 0]));
    assert!(dense(&[0, 1], &[0, 1], &[2, 1], &[0, 0]));
    assert!(dense(&[0, 1], &[0, 1], &[1], &[0]));
    assert!(dense(&[1, 0], &[0, 1], &[2], &[0]));
    assert!(dense(&[0, 1], &[0, 1], &[0, 2], &[0, 0]));
    // A reach after its block's start, missing, or not from 0 first.
    assert!(dense(&[0, 1], &[0, 1], &[1, 2], &[0, 2]));
    assert!(dense(&[0, 1], &[0, 1], &[1, 2], &[0]));
    assert!(dense(&[0, 1], &[0, 1], &[1, 2], &[1, 1]));
    assert!(!dense(&[0, 1], &[0, 1], &[1, 2], &[0, 1]));
    assert_eq!(PsiUBlocks::DENSE.len(), 1);
    // The dense order, and one of another size, invert whole.
    let a = SMatrix::<f64, 2, 2>::new(2.0, 1.0, -1.0, 3.0);
    assert_eq!(
        Factors::of(&a, PsiUBlocks::DENSE).inverse(),
        invert(&a).inverse
    );
    let three = PsiUBlocks::new(&[0, 1, 2], &[0, 1, 2], &[1, 3], &[0, 0]);
    assert_eq!(Factors::of(&a, three).inverse(), invert(&a).inverse);
    assert!(!three.fits(&a));
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
    let case = Case::with_reach(a, order.clone(), order, vec![1, 11]);
    agrees(&a, case.blocks());
}

#[test]
fn large_blocks_invert_by_elimination() {
    // One 5×5 block after a 1×1: Gauss–Jordan for the large block.
    let a = one_then_large::<6>(3);
    let order: Vec<usize> = (0..6).collect();
    let case = Case::with_reach(a, order.clone(), order, vec![1, 6]);
    agrees(&a, case.blocks());
}

#[test]
fn an_entry_outside_the_reach_does_not_fit() {
    let mut numbers = Numbers(5);
    for _ in 0..50 {
        let case = Case::<7>::random(&mut numbers);
        let blocks = case.blocks();
        assert!(blocks.fits(&case.a));
        // An entry of the first block's equation in the last block's
        // coordinate: no longer triangular in this order.
        let (first, _) = blocks.blocks().next().unwrap();
        let (_, last) = blocks.blocks().last().unwrap();
        let mut a = case.a;
        a[(first[0], last[0])] = 0.5;
        assert!(!blocks.fits(&a));
    }
}

/// The estimate on matrices built to be hard for it: a chain whose
/// couplings grow block after block (the inverse's largest column is the
/// first), and nearly singular blocks late in the order.
#[test]
fn the_estimate_holds_on_growing_chains_and_nearly_singular_blocks() {
    const M: usize = 16;
    let order: Vec<usize> = (0..M).collect();
    let ends: Vec<usize> = (1..=M / 2).map(|b| 2 * b).collect();
    for growth in [0.5, 1.0, 3.0, 10.0] {
        for nearly in [1.0, 1e-6, 1e-12] {
            let mut a = SMatrix::<f64, M, M>::zeros();
            for b in 0..M / 2 {
                let r = 2 * b;
                a[(r, r)] = 1.0;
                a[(r + 1, r + 1)] = if b == M / 2 - 2 { nearly } else { 1.0 };
                a[(r, r + 1)] = 0.3;
                if b > 0 {
                    a[(r, r - 1)] = growth;
                    a[(r + 1, r - 2)] = -growth;
                }
            }
            let case = Case::with_reach(a, order.clone(), order.clone(), ends.clone());
            agrees(&a, case.blocks());
        }
    }
}

/// With the inverse formed, rcond is read from it: the whole matrix's,
/// to rounding; singular blocks and extreme scales as in [`Factors::of`].
#[test]
fn the_inverse_formed_gives_the_exact_rcond() {
    let mut numbers = Numbers(23);
    for _ in 0..100 {
        let case = Case::<9>::random(&mut numbers);
        let (factors, inverse) = Factors::of_with_inverse(&case.a, case.blocks());
        let inverse = inverse.expect("formed in blocks");
        let whole = invert(&case.a);
        assert!(factors.in_blocks());
        assert!((factors.rcond() - whole.rcond).abs() <= 1e-12 * whole.rcond);
        assert!((inverse - whole.inverse).amax() <= 1e-13 * whole.inverse.amax() / whole.rcond);
        let scaled = Factors::of_with_inverse(&(case.a * 2f64.powi(700)), case.blocks()).0;
        assert_eq!(scaled.rcond(), Factors::of(&case.a, case.blocks()).rcond());
    }
    let small = Case::<4>::random(&mut numbers);
    let (factors, inverse) = Factors::of_with_inverse(&small.a, small.blocks());
    assert_eq!(inverse, None);
    assert_eq!(
        (factors.whole_inverse(), factors.rcond()),
        (Some(&invert(&small.a).inverse), invert(&small.a).rcond)
    );
    let mut singular = Case::<9>::random(&mut numbers);
    let (first_equations, first_coordinates) = {
        let blocks = singular.blocks();
        let (e, c) = blocks.blocks().next().unwrap();
        (e.to_vec(), c.to_vec())
    };
    for &c in &first_coordinates {
        singular.a[(first_equations[0], c)] = 0.0;
    }
    assert_eq!(
        Factors::of_with_inverse(&singular.a, singular.blocks())
            .0
            .rcond(),
        0.0
    );
}

/// The factors of an evaluation that could not run are those of a matrix
/// of NaN.
#[test]
fn unfactored_is_a_matrix_of_nan_inverted() {
    fn check<const M: usize>() {
        let (a, b) = (
            Factors::<M>::unfactored(),
            Factors::<M>::whole(&SMatrix::repeat(f64::NAN)),
        );
        assert_eq!(a.rcond().to_bits(), b.rcond().to_bits(), "m = {M}");
        assert_eq!(a.det().is_nan(), b.det().is_nan(), "m = {M}");
        assert_eq!(a.stored(), b.stored(), "m = {M}");
        assert_eq!(a.in_blocks(), b.in_blocks());
    }
    check::<1>();
    check::<2>();
    check::<3>();
    check::<5>();
}

/// Whether two factors are the same to the bit (NaN entries too), in the
/// part of the storage they take.
fn same_bits<const M: usize>(a: &Factors<M>, b: &Factors<M>) -> bool {
    let bits = |f: &Factors<M>| {
        (f.stored().iter().chain([&f.rcond, &f.det]))
            .map(|x| x.to_bits())
            .collect::<Vec<_>>()
    };
    bits(a) == bits(b) && a.order == b.order
}

/// Factored in place, over the factors of another matrix, Ψ_u gives the
/// very factors [`Factors::of`] returns: in blocks, singular, with a NaN,
/// at extreme scales, and inverted whole.
#[test]
fn factored_in_place_is_factored_to_the_bit() {
    let mut numbers = Numbers(23);
    let mut kept = Factors::<7>::unfactored();
    for round in 0..200 {
        let case = Case::<7>::random(&mut numbers);
        let blocks = case.blocks();
        let mut a = case.a;
        match round % 5 {
            1 => a[(case.equations[0], case.coordinates[0])] = f64::NAN,
            2 => a *= 2f64.powi(700),
            3 => {
                let (equations, coordinates) = blocks.blocks().last().unwrap();
                for &c in coordinates {
                    a[(equations[0], c)] = 0.0;
                }
            }
            _ => {}
        }
        kept.of_into(&a, blocks);
        assert!(same_bits(&kept, &Factors::of(&a, blocks)), "round {round}");
        kept.of_into(&a, PsiUBlocks::DENSE);
        assert!(
            same_bits(&kept, &Factors::of(&a, PsiUBlocks::DENSE)),
            "round {round}"
        );
    }
    let small =
        SMatrix::<f64, 3, 3>::from_fn(|i, j| (i + 2 * j) as f64 + f64::from(u8::from(i == j)));
    let mut kept = Factors::<3>::unfactored();
    kept.of_into(&small, PsiUBlocks::DENSE);
    assert!(same_bits(&kept, &Factors::of(&small, PsiUBlocks::DENSE)));
}

/// The blocks solved by unrolled code give the general loops' numbers to
/// the bit, forward and backward, at every size unrolled.
#[test]
fn unrolled_blocks_solve_as_the_general_loops_to_the_bit() {
    let mut numbers = Numbers(41);
    let mut sizes = Vec::new();
    macro_rules! collect {
        ($(($k:literal, $d:literal)),*) => { $(sizes.push(($k, $d));)* };
    }
    unrolled_sizes!(collect);
    assert_eq!(sizes.len(), 15);
    for (k, d) in sizes {
        let w = k + d;
        for _ in 0..20 {
            let entries: Vec<f64> = (0..k * w).map(|_| numbers.next()).collect();
            let b: Vec<f64> = (0..8).map(|_| numbers.next()).collect();
            let equations: Vec<u16> = (0..k).map(|_| numbers.below(8) as u16).collect();
            let known: Vec<f64> = (0..d).map(|_| numbers.next()).collect();
            let (mut unrolled, mut general) = (vec![0.0; k], vec![0.0; k]);
            forward_block::<8>(&entries, &b, &equations, &known, &mut unrolled);
            forward_general::<8>(&entries, &b, &equations, &known, &mut general);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(
                bits(&unrolled),
                bits(&general),
                "forward, {k}×{k} reaching {d}"
            );
            let left: Vec<f64> = (0..k).map(|_| numbers.next()).collect();
            let (mut reached_u, mut reached_g) = (known.clone(), known.clone());
            backward_block(&entries, &left, &mut unrolled, &mut reached_u);
            backward_general(&entries, &left, &mut general, &mut reached_g);
            assert_eq!(
                bits(&unrolled),
                bits(&general),
                "backward, {k}×{k} reaching {d}"
            );
            assert_eq!(
                bits(&reached_u),
                bits(&reached_g),
                "backward, {k}×{k} reaching {d}"
            );
        }
    }
}

/// A solve with a unit vector, started at its equation's block, gives the
/// solve from the first block to the bit (a wrong block would leave
/// coordinates out, or add in blocks that are not zero).
#[test]
fn a_unit_solve_from_its_block_is_the_whole_solve_to_the_bit() {
    let mut numbers = Numbers(59);
    for _ in 0..200 {
        let case = Case::<9>::random(&mut numbers);
        let factors = Factors::of(&case.a, case.blocks());
        for e in 0..9 {
            let unit = SVector::<f64, 9>::from_fn(|i, _| f64::from(u8::from(i == e)));
            let bits = |v: SVector<f64, 9>| v.map(f64::to_bits);
            assert_eq!(
                bits(factors.unit_forward(e)),
                bits(factors.forward(&unit)),
                "equation {e} of blocks ending at {:?}",
                case.ends
            );
        }
    }
}

/// A product by a matrix with the blocks' structure, over its reach only,
/// is the dense product summed in the same order, to the bit.
#[test]
fn a_structured_product_is_the_dense_one_to_the_bit() {
    let mut numbers = Numbers(67);
    for _ in 0..200 {
        let case = Case::<9>::random(&mut numbers);
        let factors = Factors::of(&case.a, case.blocks());
        // Another matrix of the same structure, as Ψ̇_u is of Ψ_u's.
        let a = case.a.map(|x| if x == 0.0 { 0.0 } else { numbers.next() });
        let b = SMatrix::<f64, 9, 3>::from_fn(|_, _| numbers.next());
        let mut dense = SMatrix::<f64, 9, 3>::zeros();
        for j in 0..3 {
            for k in 0..9 {
                for i in 0..9 {
                    dense[(i, j)] += a[(i, k)] * b[(k, j)];
                }
            }
        }
        let bits = |m: SMatrix<f64, 9, 3>| m.map(f64::to_bits);
        assert_eq!(
            bits(factors.structured_product(&a, &b)),
            bits(dense),
            "blocks ending at {:?}",
            case.ends
        );
    }
    // Inverted whole (no block order to follow): the dense product.
    let a = SMatrix::<f64, 3, 3>::from_fn(|_, _| numbers.next()) + SMatrix::identity() * 3.0;
    let b = SMatrix::<f64, 3, 2>::from_fn(|_, _| numbers.next());
    let factors = Factors::whole(&a);
    assert!(!factors.in_blocks());
    let mut dense = SMatrix::<f64, 3, 2>::zeros();
    for j in 0..2 {
        for k in 0..3 {
            for i in 0..3 {
                dense[(i, j)] += a[(i, k)] * b[(k, j)];
            }
        }
    }
    assert_eq!(
        factors.structured_product(&a, &b).map(f64::to_bits),
        dense.map(f64::to_bits)
    );
}

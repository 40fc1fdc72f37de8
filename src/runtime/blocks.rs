//! The structure of Ψ_u. The symbolic engine finds, from which entries of
//! Ψ_u are not identically zero, an order of its equations and coordinates
//! in which it is block lower triangular ([`PsiUBlocks`]): each block's
//! equations involve only its own coordinates and those of the blocks
//! before it — from its reach on, the first of them its equations involve.
//! [`Factors`](crate::Factors) solves with Ψ_u in that order.

use nalgebra::SMatrix;

/// Ψ_u's diagonal blocks in the order they are solved: `equations` and
/// `coordinates` list every equation and every coordinate, block after
/// block, `ends` where each block ends in both lists, and `reach` where
/// each block's reach begins: the first position in `coordinates` of a
/// coordinate its equations involve. The generated code has them as a
/// constant (`PSI_U_BLOCKS`) where Ψ_u has more than one block; a run-time
/// mechanism from its program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PsiUBlocks<'a> {
    equations: &'a [usize],
    coordinates: &'a [usize],
    ends: &'a [usize],
    reach: &'a [usize],
    /// The sign of the two orders as permutations: det Ψ_u is it times the
    /// product of the diagonal blocks' determinants.
    sign: f64,
}

impl PsiUBlocks<'static> {
    /// One block: Ψ_u is dense, inverted whole.
    pub const DENSE: PsiUBlocks<'static> = PsiUBlocks {
        equations: &[],
        coordinates: &[],
        ends: &[],
        reach: &[],
        sign: 1.0,
    };
}

impl<'a> PsiUBlocks<'a> {
    /// The blocks, if `equations` and `coordinates` both order 0 … n − 1,
    /// `ends` rises to n in more than one step and each block's reach is
    /// no later than its start; [`PsiUBlocks::DENSE`] otherwise (one block
    /// is the dense matrix).
    pub const fn new(
        equations: &'a [usize],
        coordinates: &'a [usize],
        ends: &'a [usize],
        reach: &'a [usize],
    ) -> Self {
        let n = equations.len();
        let mut rising = ends.len() > 1 && ends[ends.len() - 1] == n && ends[0] > 0;
        rising = rising && reach.len() == ends.len() && reach[0] == 0;
        let mut b = 1;
        while rising && b < ends.len() {
            rising &= ends[b] > ends[b - 1] && reach[b] <= ends[b - 1];
            b += 1;
        }
        if coordinates.len() != n || !rising {
            return PsiUBlocks::DENSE;
        }
        match (parity(equations), parity(coordinates)) {
            (Some(a), Some(b)) => PsiUBlocks {
                equations,
                coordinates,
                ends,
                reach,
                sign: if a == b { 1.0 } else { -1.0 },
            },
            _ => PsiUBlocks::DENSE,
        }
    }

    /// How many blocks (1 for [`PsiUBlocks::DENSE`]).
    pub fn len(&self) -> usize {
        self.ends.len().max(1)
    }

    /// Never: there is at least the one dense block.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The equations and the coordinates of each block, in solve order
    /// (nothing for [`PsiUBlocks::DENSE`]).
    pub fn blocks(&self) -> impl Iterator<Item = (&'a [usize], &'a [usize])> + 'a {
        let (equations, coordinates, ends) = (self.equations, self.coordinates, self.ends);
        (0..ends.len()).map(move |b| {
            let start = if b == 0 { 0 } else { ends[b - 1] };
            (&equations[start..ends[b]], &coordinates[start..ends[b]])
        })
    }

    /// How many equations (and coordinates) the blocks order: 0 for
    /// [`PsiUBlocks::DENSE`].
    pub(crate) fn positions(&self) -> usize {
        self.equations.len()
    }

    /// The four lists, as [`PsiUBlocks::new`] took them.
    pub(crate) fn lists(&self) -> (&'a [usize], &'a [usize], &'a [usize], &'a [usize]) {
        (self.equations, self.coordinates, self.ends, self.reach)
    }

    /// The sign of the two orders as permutations.
    pub(crate) fn sign(&self) -> f64 {
        self.sign
    }

    /// Whether `a` has this structure: every entry of a block's equations
    /// outside its reach (before it, or in the blocks after it) is zero.
    /// [`Factors`](crate::Factors) never reads those entries.
    pub fn fits<const M: usize>(&self, a: &SMatrix<f64, M, M>) -> bool {
        if *self == PsiUBlocks::DENSE {
            return true;
        }
        if self.equations.len() != M {
            return false;
        }
        let mut start = 0;
        for (b, (equations, _)) in self.blocks().enumerate() {
            let end = start + equations.len();
            let outside = (0..self.reach[b]).chain(end..M);
            let zero = |p: usize| {
                let q = self.coordinates[p];
                equations.iter().all(|&e| a[(e, q)] == 0.0)
            };
            if !outside.into_iter().all(zero) {
                return false;
            }
            start = end;
        }
        true
    }
}

/// [`PsiUBlocks`] that owns its lists: a run-time mechanism's, checked and
/// its sign found once, when its program is built.
#[cfg(feature = "files")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PsiUBlocksBuf {
    equations: Vec<usize>,
    coordinates: Vec<usize>,
    ends: Vec<usize>,
    reach: Vec<usize>,
    sign: f64,
}

#[cfg(feature = "files")]
impl PsiUBlocksBuf {
    /// The lists as [`PsiUBlocks::new`] takes them (dense where it would
    /// be).
    pub(crate) fn new(
        equations: Vec<usize>,
        coordinates: Vec<usize>,
        ends: Vec<usize>,
        reach: Vec<usize>,
    ) -> Self {
        let blocks = PsiUBlocks::new(&equations, &coordinates, &ends, &reach);
        let (dense, sign) = (blocks == PsiUBlocks::DENSE, blocks.sign);
        if dense {
            return PsiUBlocksBuf {
                equations: Vec::new(),
                coordinates: Vec::new(),
                ends: Vec::new(),
                reach: Vec::new(),
                sign,
            };
        }
        PsiUBlocksBuf {
            equations,
            coordinates,
            ends,
            reach,
            sign,
        }
    }

    pub(crate) fn borrow(&self) -> PsiUBlocks<'_> {
        PsiUBlocks {
            equations: &self.equations,
            coordinates: &self.coordinates,
            ends: &self.ends,
            reach: &self.reach,
            sign: self.sign,
        }
    }
}

/// Whether `order` is a permutation of 0 … n − 1 that is odd (`Some(true)`)
/// or even; `None` if it is no permutation. Counted by inversions: n² steps,
/// once per mechanism.
const fn parity(order: &[usize]) -> Option<bool> {
    let n = order.len();
    let mut odd = false;
    let mut i = 0;
    while i < n {
        if order[i] >= n {
            return None;
        }
        let mut j = i + 1;
        while j < n {
            if order[i] == order[j] {
                return None;
            }
            odd ^= order[i] > order[j];
            j += 1;
        }
        i += 1;
    }
    Some(odd)
}

//! The block lower triangular form of Ψ_u, found from its structure alone
//! (which entries are not identically zero): a perfect matching of
//! equations to coordinates puts a structurally nonzero entry on the
//! diagonal, and the strongly connected components of the graph "the
//! equation matched to coordinate k involves coordinate j" are the
//! diagonal blocks (the Dulmage–Mendelsohn fine decomposition of a square
//! matrix of full structural rank). In their order, each block's equations
//! involve only its own coordinates and those of the blocks before it, so
//! the blocks can be solved one after another, each as small as the
//! mechanism allows. The blocks do not depend on which perfect matching is
//! taken.

use std::fmt;

/// One diagonal block: the equations and the coordinates it solves for,
/// each ascending.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    pub equations: Vec<usize>,
    pub coordinates: Vec<usize>,
}

/// The diagonal blocks of Ψ_u in solve order (none if Ψ_u is structurally
/// singular).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Blocks {
    blocks: Vec<Block>,
    /// For each block, the first position in the solve order of the
    /// coordinates (the block's own start if it involves none before it)
    /// that its equations involve: everything Ψ_u has in the block's rows
    /// lies between it and the block's end.
    reach: Vec<usize>,
}

/// [`Blocks::order`]: the blocks' equations and coordinates in solve order,
/// the end of each block in both, and where each block's reach begins
/// (the first position of a coordinate its equations involve).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BlockOrder {
    pub equations: Vec<usize>,
    pub coordinates: Vec<usize>,
    pub ends: Vec<usize>,
    pub reach: Vec<usize>,
}

/// A maximum matching of equations (rows) to coordinates (columns): for
/// each column, the row matched to it, if any. Augmenting paths from each
/// row in turn (Kuhn's algorithm, without recursion).
pub(crate) fn maximum_matching(incidence: &[Vec<bool>]) -> Vec<Option<usize>> {
    let m = incidence.len();
    let columns = incidence.first().map_or(0, Vec::len);
    let mut row_of_col: Vec<Option<usize>> = vec![None; columns];
    for root in 0..m {
        let mut visited = vec![false; columns];
        // The path so far: (row, next column to try), and the column each
        // row on it was reached by.
        let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
        let mut reached_by: Vec<usize> = Vec::new();
        while let Some(&mut (row, ref mut next)) = stack.last_mut() {
            let Some(col) = (*next..columns).find(|&c| incidence[row][c] && !visited[c]) else {
                stack.pop();
                reached_by.pop();
                continue;
            };
            *next = col + 1;
            visited[col] = true;
            match row_of_col[col] {
                Some(owner) => {
                    reached_by.push(col);
                    stack.push((owner, 0));
                }
                None => {
                    // Flip the path: each row on it takes the column it
                    // reached the next row by; the last takes `col`.
                    let mut take = col;
                    while let Some((r, _)) = stack.pop() {
                        row_of_col[take] = Some(r);
                        match reached_by.pop() {
                            Some(c) => take = c,
                            None => break,
                        }
                    }
                    break;
                }
            }
        }
    }
    row_of_col
}

impl Blocks {
    /// The blocks of the square incidence pattern `incidence[i][k]`
    /// (equation i involves coordinate k); none if it has no perfect
    /// matching.
    pub fn of(incidence: &[Vec<bool>]) -> Blocks {
        let m = incidence.len();
        if incidence.iter().any(|row| row.len() != m) {
            return Blocks::default();
        }
        let row_of_col = maximum_matching(incidence);
        let Some(matched) = row_of_col.iter().copied().collect::<Option<Vec<usize>>>() else {
            return Blocks::default();
        };
        // Coordinate k depends on coordinate j when the equation matched
        // to k involves j.
        let depends = |k: usize| {
            let row = &incidence[matched[k]];
            (0..m).filter(move |&j| j != k && row[j])
        };
        let components = strongly_connected(m, depends);
        // Tarjan's algorithm finishes a component after every component it
        // depends on: its order is the solve order.
        let blocks: Vec<Block> = components
            .into_iter()
            .map(|mut coordinates| {
                coordinates.sort_unstable();
                let mut equations: Vec<usize> = coordinates.iter().map(|&k| matched[k]).collect();
                equations.sort_unstable();
                Block {
                    equations,
                    coordinates,
                }
            })
            .collect();
        let mut position = vec![0; m];
        for (p, &k) in blocks.iter().flat_map(|b| &b.coordinates).enumerate() {
            position[k] = p;
        }
        let mut start = 0;
        let reach = (blocks.iter())
            .map(|block| {
                let first = (block.equations.iter())
                    .flat_map(|&e| (0..m).filter(move |&k| incidence[e][k]))
                    .map(|k| position[k])
                    .min()
                    .unwrap_or(start)
                    .min(start);
                start += block.coordinates.len();
                first
            })
            .collect();
        Blocks { blocks, reach }
    }

    /// The blocks, in the order they are solved.
    pub fn blocks(&self) -> &[Block] {
        &self.blocks
    }

    /// The blocks flattened as the runtime takes them
    /// (`linkage::PsiUBlocks::new`): every equation and every coordinate,
    /// block after block, and where each block ends in both lists.
    pub fn order(&self) -> BlockOrder {
        let mut order = BlockOrder::default();
        for block in &self.blocks {
            order.equations.extend(&block.equations);
            order.coordinates.extend(&block.coordinates);
            order.ends.push(order.equations.len());
        }
        order.reach.clone_from(&self.reach);
        order
    }

    /// Whether Ψ_u has more than one block.
    pub fn is_triangular(&self) -> bool {
        self.blocks.len() > 1
    }

    /// The sentence of [`Display`](fmt::Display) and, for up to eight
    /// blocks, the coordinates of each in solve order, named by `name`:
    /// "Ψ_u is block lower triangular: 2 blocks of 2×2, solved in the order
    /// [θ3, θ4], [θ5, θ6]."
    pub fn describe(&self, name: impl Fn(usize) -> String) -> String {
        let mut text = self.to_string();
        if self.is_triangular() && self.blocks.len() <= 8 {
            let order: Vec<String> = (self.blocks.iter())
                .map(|b| {
                    let names: Vec<String> = b.coordinates.iter().map(|&k| name(k)).collect();
                    format!("[{}]", names.join(", "))
                })
                .collect();
            text.push_str(", solved in the order ");
            text.push_str(&order.join(", "));
        }
        text.push('.');
        text
    }
}

/// The strongly connected components of the graph on `n` nodes whose
/// edges leave node k for `next(k)`, each finished after every component
/// it reaches (Tarjan's algorithm, iterative).
fn strongly_connected<I: Iterator<Item = usize>>(
    n: usize,
    next: impl Fn(usize) -> I,
) -> Vec<Vec<usize>> {
    const UNSEEN: usize = usize::MAX;
    let mut index = vec![UNSEEN; n];
    let mut low = vec![0; n];
    let mut on_stack = vec![false; n];
    let mut stack: Vec<usize> = Vec::new();
    let mut components = Vec::new();
    let mut counter = 0;
    for root in 0..n {
        if index[root] != UNSEEN {
            continue;
        }
        // Each frame: a node and the successors it has yet to visit.
        let mut frames: Vec<(usize, I)> = Vec::new();
        index[root] = counter;
        low[root] = counter;
        counter += 1;
        stack.push(root);
        on_stack[root] = true;
        frames.push((root, next(root)));
        while let Some((node, successors)) = frames.last_mut() {
            let node = *node;
            match successors.next() {
                Some(w) if index[w] == UNSEEN => {
                    index[w] = counter;
                    low[w] = counter;
                    counter += 1;
                    stack.push(w);
                    on_stack[w] = true;
                    frames.push((w, next(w)));
                }
                Some(w) => {
                    if on_stack[w] {
                        low[node] = low[node].min(index[w]);
                    }
                }
                None => {
                    frames.pop();
                    if let Some((parent, _)) = frames.last() {
                        low[*parent] = low[*parent].min(low[node]);
                    }
                    if low[node] == index[node] {
                        let mut component = Vec::new();
                        while let Some(w) = stack.pop() {
                            on_stack[w] = false;
                            component.push(w);
                            if w == node {
                                break;
                            }
                        }
                        components.push(component);
                    }
                }
            }
        }
    }
    components
}

impl fmt::Display for Blocks {
    /// "Ψ_u is block lower triangular: 32 blocks of 2×2", "… 3 blocks:
    /// 2×2, 2×2, 1×1", or "Ψ_u is one dense block of 2×2".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sizes: Vec<usize> = self.blocks.iter().map(|b| b.coordinates.len()).collect();
        match sizes.as_slice() {
            [] => write!(f, "Ψ_u is structurally singular"),
            [one] => write!(f, "Ψ_u is one dense block of {one}×{one}"),
            [first, rest @ ..] if rest.iter().all(|s| s == first) => write!(
                f,
                "Ψ_u is block lower triangular: {} blocks of {first}×{first}",
                sizes.len()
            ),
            _ => {
                let list: Vec<String> = sizes.iter().map(|s| format!("{s}×{s}")).collect();
                write!(
                    f,
                    "Ψ_u is block lower triangular: {} blocks: {}",
                    sizes.len(),
                    list.join(", ")
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pattern(rows: &[&str]) -> Vec<Vec<bool>> {
        rows.iter()
            .map(|r| r.chars().map(|c| c == 'x').collect())
            .collect()
    }

    /// Every block's equations involve only its coordinates and those of
    /// the blocks before it; the blocks partition the equations and the
    /// coordinates; each block's reach is the first position in the solve
    /// order of a coordinate its equations involve.
    fn lower_triangular(incidence: &[Vec<bool>], blocks: &Blocks) -> bool {
        let m = incidence.len();
        let order = blocks.order();
        let mut start = 0;
        for (b, block) in blocks.blocks().iter().enumerate() {
            let first = (order.coordinates.iter())
                .position(|&k| block.equations.iter().any(|&e| incidence[e][k]));
            if Some(order.reach[b]) != first.map(|p| p.min(start)) {
                return false;
            }
            start += block.coordinates.len();
        }
        let mut solved = vec![false; m];
        let mut equations = vec![false; m];
        for block in blocks.blocks() {
            for &k in &block.coordinates {
                if solved[k] {
                    return false;
                }
                solved[k] = true;
            }
            for &i in &block.equations {
                if equations[i] || (0..m).any(|k| incidence[i][k] && !solved[k]) {
                    return false;
                }
                equations[i] = true;
            }
        }
        solved.iter().all(|&s| s) && equations.iter().all(|&e| e)
    }

    #[test]
    fn a_dense_pattern_is_one_block() {
        let incidence = pattern(&["xx", "xx"]);
        let blocks = Blocks::of(&incidence);
        assert_eq!(blocks.blocks().len(), 1);
        assert_eq!(blocks.to_string(), "Ψ_u is one dense block of 2×2");
        assert!(!blocks.is_triangular());
    }

    #[test]
    fn a_chain_of_loops_is_a_block_per_loop_in_order() {
        // Loop l's two equations involve its two angles and, from l = 1
        // on, one angle of loop l − 1; written in reverse order.
        let m = 6;
        let mut incidence = vec![vec![false; m]; m];
        for l in 0..3 {
            let (row, col) = (m - 2 - 2 * l, m - 2 - 2 * l);
            for i in 0..2 {
                for j in 0..2 {
                    incidence[row + i][col + j] = true;
                }
                if l > 0 {
                    incidence[row + i][col + 2] = true;
                }
            }
        }
        let blocks = Blocks::of(&incidence);
        assert_eq!(
            blocks.to_string(),
            "Ψ_u is block lower triangular: 3 blocks of 2×2"
        );
        assert!(lower_triangular(&incidence, &blocks));
        assert_eq!(blocks.order().reach, [0, 0, 2]);
        assert_eq!(blocks.blocks()[0].coordinates, [4, 5]);
        assert_eq!(blocks.blocks()[2].coordinates, [0, 1]);
        assert_eq!(
            blocks.describe(|k| format!("x{k}")),
            "Ψ_u is block lower triangular: 3 blocks of 2×2, solved in the order \
             [x4, x5], [x2, x3], [x0, x1]."
        );
    }

    #[test]
    fn mixed_sizes_are_listed() {
        // x0 alone; then (x1, x2) coupled and reading x0; then x3 from x2.
        let incidence = pattern(&["x...", "xxx.", ".xx.", "..xx"]);
        let blocks = Blocks::of(&incidence);
        assert_eq!(
            blocks.to_string(),
            "Ψ_u is block lower triangular: 3 blocks: 1×1, 2×2, 1×1"
        );
        assert!(lower_triangular(&incidence, &blocks));
        assert_eq!(blocks.order().reach, [0, 0, 2]);
    }

    #[test]
    fn a_matching_off_the_diagonal_is_found() {
        // Equation 0 involves only x1 and equation 1 only x0: two blocks
        // of 1×1, with the equations crossed.
        let incidence = pattern(&[".x", "x."]);
        let blocks = Blocks::of(&incidence);
        assert_eq!(blocks.blocks().len(), 2);
        assert!(lower_triangular(&incidence, &blocks));
        // A structurally singular pattern has no blocks.
        assert_eq!(Blocks::of(&pattern(&["xx", "..",])).blocks(), &[]);
        assert_eq!(
            Blocks::of(&pattern(&["x.", "x."])).to_string(),
            "Ψ_u is structurally singular"
        );
    }

    /// On random patterns: lower triangular, and each block irreducible
    /// (no finer split exists: within a block every coordinate reaches
    /// every other through the matched equations), checked by brute force.
    #[test]
    fn random_patterns_split_into_irreducible_blocks() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut random = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut checked = 0;
        for _ in 0..600 {
            let m = 1 + (random() % 9) as usize;
            let density = 2 + random() % 5;
            let incidence: Vec<Vec<bool>> = (0..m)
                .map(|_| (0..m).map(|_| random() % 10 < density).collect())
                .collect();
            let blocks = Blocks::of(&incidence);
            let row_of_col = maximum_matching(&incidence);
            let perfect = row_of_col.iter().all(Option::is_some);
            if !perfect {
                assert!(blocks.blocks().is_empty());
                continue;
            }
            checked += 1;
            assert!(lower_triangular(&incidence, &blocks), "{incidence:?}");
            for block in blocks.blocks() {
                // Reachability inside the block along "k's matched
                // equation involves j".
                for &start in &block.coordinates {
                    let mut seen = vec![start];
                    let mut k = 0;
                    while k < seen.len() {
                        let c = seen[k];
                        let row = row_of_col[c].unwrap();
                        for &j in &block.coordinates {
                            if incidence[row][j] && !seen.contains(&j) {
                                seen.push(j);
                            }
                        }
                        k += 1;
                    }
                    assert_eq!(seen.len(), block.coordinates.len(), "{incidence:?}");
                }
            }
        }
        assert!(checked > 200, "{checked} patterns with a perfect matching");
    }
}

//! The loops of a mechanism, read from the pattern of Ψ_u: its equations
//! and coordinates ordered block-triangularly, so that each block of
//! equations involves only its own coordinates and those of the blocks
//! before it (the Dulmage–Mendelsohn decomposition of a square, structurally
//! non-singular matrix). A Watt six-bar's two loops are two blocks — the
//! four-bar loop first, then the loop hanging from its rocker — solved one
//! after the other; a Stephenson III six-bar's two loops share two
//! unknowns and are one block of four.

/// A block of the decomposition: equations solved together for the
/// coordinates they introduce.
///
/// ```
/// use linkage::assembly::{Search, modes};
/// use linkage::prelude::*;
///
/// /// A four-bar (θ3, θ4) and a dyad (θ5, θ6) hanging from its rocker.
/// #[linkage::linkage(
///     u = [theta3, theta4, theta5, theta6],
///     v = [theta2],
///     closure = [
///         20.0 * theta2.cos() + 50.0 * theta3.cos() + 70.0 * theta4.cos() - 80.0,
///         20.0 * theta2.sin() + 50.0 * theta3.sin() + 70.0 * theta4.sin(),
///         80.0 + 40.0 * theta4.cos() + 60.0 * theta5.cos() + 50.0 * theta6.cos() - gx,
///         40.0 * theta4.sin() + 60.0 * theta5.sin() + 50.0 * theta6.sin() - gy,
///     ],
/// )]
/// struct Watt { gx: f64, gy: f64 }
///
/// let found = modes(&Watt { gx: 100.0, gy: 60.0 }, &vector![0.35], &Search::default())?;
/// assert_eq!(found.blocks.len(), 2);
/// assert_eq!(found.blocks[1].equations, [2, 3]);
/// assert_eq!(found.blocks[1].coordinates, [2, 3]);
/// assert_eq!(found.modes.len(), 4); // two signs, one per loop
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    /// The equations' indices in Ψ, ascending.
    pub equations: Vec<usize>,
    /// The coordinates' indices in u, ascending.
    pub coordinates: Vec<usize>,
}

/// The blocks of the square pattern `nonzero` (`nonzero[i][j]`: equation
/// i involves coordinate j), in an order where each block's equations
/// involve the coordinates of no later block; among the blocks that may
/// come next, the one with the first equation first. The pattern must
/// have a perfect matching (the attribute refuses equations that do not);
/// without one, everything is one block.
pub(crate) fn blocks<const M: usize>(nonzero: &[[bool; M]; M]) -> Vec<Block> {
    let everything = || {
        vec![Block {
            equations: (0..M).collect(),
            coordinates: (0..M).collect(),
        }]
    };
    let Some(column_of) = matching(nonzero) else {
        return everything();
    };
    // Equation i depends on equation k when it involves the coordinate
    // matched to k.
    let depends = |i: usize, k: usize| i != k && nonzero[i][column_of[k]];
    let component = strongly_connected(M, depends);
    let count = component.iter().max().map_or(0, |c| c + 1);
    let component = &component;
    let members = |c: usize| (0..M).filter(move |&i| component[i] == c);
    // Kahn's order on the components: a component is ready once every one
    // it depends on is placed.
    let mut placed = vec![false; count];
    let mut order = Vec::with_capacity(count);
    while order.len() < count {
        let ready = (0..count)
            .filter(|&c| !placed[c])
            .filter(|&c| {
                members(c).all(|i| {
                    (0..M)
                        .filter(|&k| depends(i, k))
                        .all(|k| component[k] == c || placed[component[k]])
                })
            })
            .min_by_key(|&c| members(c).next());
        let Some(c) = ready else {
            return everything();
        };
        placed[c] = true;
        order.push(c);
    }
    order
        .into_iter()
        .map(|c| {
            let equations: Vec<usize> = members(c).collect();
            let mut coordinates: Vec<usize> = equations.iter().map(|&i| column_of[i]).collect();
            coordinates.sort_unstable();
            Block {
                equations,
                coordinates,
            }
        })
        .collect()
}

/// A perfect matching of equations to coordinates (`column_of[i]` the
/// coordinate of equation i), by augmenting paths tried in index order;
/// `None` if there is none.
/// Whether the pattern has a perfect matching: whether a matrix of it can
/// be regular at all.
pub(crate) fn perfect<const M: usize>(nonzero: &[[bool; M]; M]) -> bool {
    matching(nonzero).is_some()
}

fn matching<const M: usize>(nonzero: &[[bool; M]; M]) -> Option<[usize; M]> {
    fn augment<const M: usize>(
        i: usize,
        nonzero: &[[bool; M]; M],
        row_of: &mut [Option<usize>; M],
        seen: &mut [bool; M],
    ) -> bool {
        for j in 0..M {
            if nonzero[i][j] && !seen[j] {
                seen[j] = true;
                let free = match row_of[j] {
                    None => true,
                    Some(k) => augment(k, nonzero, row_of, seen),
                };
                if free {
                    row_of[j] = Some(i);
                    return true;
                }
            }
        }
        false
    }
    let mut row_of = [None; M];
    for i in 0..M {
        if !augment(i, nonzero, &mut row_of, &mut [false; M]) {
            return None;
        }
    }
    let mut column_of = [0; M];
    for (j, row) in row_of.iter().enumerate() {
        column_of[(*row)?] = j;
    }
    Some(column_of)
}

/// The strongly connected components of the graph on `n` nodes with the
/// edges `edge(a, b)`, numbered from 0 (Tarjan's algorithm).
fn strongly_connected(n: usize, edge: impl Fn(usize, usize) -> bool) -> Vec<usize> {
    struct Tarjan<'a> {
        edge: &'a dyn Fn(usize, usize) -> bool,
        n: usize,
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on_stack: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        component: Vec<usize>,
        components: usize,
    }
    impl Tarjan<'_> {
        fn visit(&mut self, a: usize) {
            self.index[a] = Some(self.next);
            self.low[a] = self.next;
            self.next += 1;
            self.stack.push(a);
            self.on_stack[a] = true;
            for b in 0..self.n {
                if !(self.edge)(a, b) {
                    continue;
                }
                match self.index[b] {
                    None => {
                        self.visit(b);
                        self.low[a] = self.low[a].min(self.low[b]);
                    }
                    Some(index) if self.on_stack[b] => self.low[a] = self.low[a].min(index),
                    Some(_) => {}
                }
            }
            if Some(self.low[a]) == self.index[a] {
                while let Some(b) = self.stack.pop() {
                    self.on_stack[b] = false;
                    self.component[b] = self.components;
                    if b == a {
                        break;
                    }
                }
                self.components += 1;
            }
        }
    }
    let mut tarjan = Tarjan {
        edge: &edge,
        n,
        index: vec![None; n],
        low: vec![0; n],
        on_stack: vec![false; n],
        stack: Vec::new(),
        next: 0,
        component: vec![0; n],
        components: 0,
    };
    for a in 0..n {
        if tarjan.index[a].is_none() {
            tarjan.visit(a);
        }
    }
    tarjan.component
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(equations: &[usize], coordinates: &[usize]) -> Block {
        Block {
            equations: equations.to_vec(),
            coordinates: coordinates.to_vec(),
        }
    }

    #[test]
    fn a_four_bar_is_one_block() {
        let pattern = [[true, true], [true, true]];
        assert_eq!(blocks(&pattern), vec![block(&[0, 1], &[0, 1])]);
    }

    #[test]
    fn a_watt_six_bar_is_its_four_bar_then_the_loop_on_its_rocker() {
        // θ3, θ4 | θ4, θ5, θ6
        let t = true;
        let f = false;
        let pattern = [[t, t, f, f], [t, t, f, f], [f, t, t, t], [f, t, t, t]];
        assert_eq!(
            blocks(&pattern),
            vec![block(&[0, 1], &[0, 1]), block(&[2, 3], &[2, 3])]
        );
        // The loops written the other way round: the four-bar still first.
        let swapped = [[f, t, t, t], [f, t, t, t], [t, t, f, f], [t, t, f, f]];
        assert_eq!(
            blocks(&swapped),
            vec![block(&[2, 3], &[0, 1]), block(&[0, 1], &[2, 3])]
        );
    }

    #[test]
    fn a_stephenson_six_bar_is_one_block_and_a_shaper_two() {
        let pattern = [[true; 4]; 4];
        assert_eq!(blocks(&pattern), vec![block(&[0, 1, 2, 3], &[0, 1, 2, 3])]);
        // φ3, s | x_d: the ram follows the rocker.
        let (t, f) = (true, false);
        let shaper = [[t, t, f], [t, t, f], [t, f, t]];
        assert_eq!(
            blocks(&shaper),
            vec![block(&[0, 1], &[0, 1]), block(&[2], &[2])]
        );
    }

    #[test]
    fn a_pattern_without_a_matching_is_one_block() {
        let (t, f) = (true, false);
        let pattern = [[t, f], [t, f]];
        assert_eq!(blocks(&pattern), vec![block(&[0, 1], &[0, 1])]);
    }
}

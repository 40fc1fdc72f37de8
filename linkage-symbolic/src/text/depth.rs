//! The equations' depth bounded before they are differentiated: a
//! derivative's size grows with the square of the depth of what it
//! differentiates (a chain of n functions gives products of n factors,
//! whose own derivatives are sums of n such products), and the rules
//! recurse that deep. A point used by another adds its depth to the
//! other's, so a text short enough to read may still nest deep; the
//! lowered equations are measured, points included.

use crate::ast::Input;
use crate::dag::{Dag, Id, children};
use crate::errors::Errors;
use std::collections::HashMap;

/// The deepest lowered expression built: the project's models are four or
/// five deep (sums and products are flattened). At this depth a chain of
/// two-argument functions, the costliest, is differentiated in about 50 ms
/// (optimised); at twice it, in over a second.
pub const MAX_NESTING: usize = 16;

/// An error on the first point or closure equation deeper than
/// [`MAX_NESTING`], if there is one. The equations are lowered on their
/// own for this (their mistakes are the pipeline's to report: an
/// attribute that does not lower is not measured).
pub(super) fn too_deep(input: &Input) -> Option<syn::Error> {
    let lowered = crate::lower::lower(input, &mut Errors::default())?;
    let mut depths = HashMap::new();
    let deeper = |id: Id, depths: &mut HashMap<Id, usize>| {
        Some(depth(&lowered.dag, id, depths)).filter(|&d| d > MAX_NESTING)
    };
    for (k, (name, x, y)) in lowered.points.iter().enumerate() {
        if let Some(d) = deeper(*x, &mut depths).or_else(|| deeper(*y, &mut depths)) {
            let point = &input.points.items.get(k)?.name;
            return Some(syn::Error::new(
                point.span(),
                format!(
                    "point `{name}` nests {d} operations deep (with the points it uses), \
                     the most this reads is {MAX_NESTING}"
                ),
            ));
        }
    }
    for (i, root) in lowered.closure.iter().enumerate() {
        if let Some(d) = deeper(*root, &mut depths) {
            return Some(syn::Error::new_spanned(
                input.closure.items.get(i)?,
                format!(
                    "closure equation {} nests {d} operations deep (with the points it uses), \
                     the most this reads is {MAX_NESTING}",
                    i + 1
                ),
            ));
        }
    }
    None
}

/// The depth of `root` in `dag` (a leaf is 1), every node's depth kept in
/// `depths`; walked without recursion (the depth is not known yet).
fn depth(dag: &Dag, root: Id, depths: &mut HashMap<Id, usize>) -> usize {
    let mut pending = vec![(root, false)];
    while let Some((id, children_done)) = pending.pop() {
        if depths.contains_key(&id) {
            continue;
        }
        let below = children(dag.node(id));
        if children_done || below.is_empty() {
            let deepest = below.iter().filter_map(|c| depths.get(c)).max();
            depths.insert(id, 1 + deepest.copied().unwrap_or(0));
        } else {
            pending.push((id, true));
            pending.extend(below.into_iter().map(|c| (c, false)));
        }
    }
    depths.get(&root).copied().unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_of_a_chain() {
        let mut dag = Dag::new();
        let x = dag.sym(crate::dag::Symbol::Coord(0));
        let mut id = x;
        for _ in 0..10 {
            id = dag.call(crate::dag::Func::Sin, id);
        }
        let both = dag.add(id, x);
        let mut depths = HashMap::new();
        assert_eq!(depth(&dag, id, &mut depths), 11);
        assert_eq!(depth(&dag, both, &mut depths), 12);
        assert_eq!(depth(&dag, x, &mut depths), 1);
    }
}

//! Minimum-degree ordering with symbolic elimination, for sparse LU without pivoting.
//!
//! The models' Newton matrices are structurally (nearly) symmetric and strongly block
//! structured: in the DFN each particle's shells couple only to their own x-node's
//! unknowns, so eliminating the shells first and the 1-D electrolyte/potential chain last
//! leaves almost no fill. Exact minimum degree on the symmetrised graph finds that order
//! without any model-specific hint.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// An elimination order and the filled structure it produces.
pub struct Elimination {
    /// `order[i]` is the original index eliminated `i`-th.
    pub order: Vec<usize>,
    /// For each original index, the original indices of the neighbours still present when it
    /// was eliminated (the structure of its column of `L` and row of `U`).
    pub later: Vec<Vec<usize>>,
}

impl Elimination {
    /// The same elimination sorted by level in its elimination tree (leaves first; ties keep
    /// the original order). Any topological order of the tree gives the same filled structure
    /// (Liu 1990), so the fill is unchanged; but rows of one level never depend on each other,
    /// so consecutive rows of a triangular sweep (the DFN's 40 particles, shell by shell) are
    /// independent and the processor overlaps them instead of waiting on one chain.
    pub fn by_level(mut self) -> Self {
        let n = self.order.len();
        let mut pos = vec![0; n];
        for (i, &v) in self.order.iter().enumerate() {
            pos[v] = i;
        }
        let mut level = vec![0usize; n];
        for &v in &self.order {
            // The parent is the first of the later neighbours to be eliminated.
            if let Some(&parent) = self.later[v].iter().min_by_key(|&&w| pos[w]) {
                level[parent] = level[parent].max(level[v] + 1);
            }
        }
        self.order.sort_by_key(|&v| (level[v], pos[v]));
        self
    }
}

/// Exact minimum-degree elimination of the graph of `A + A^T` for the pattern `entries`
/// (`(row, col)` pairs of an `n x n` matrix; the diagonal is implied), the nodes `last` left
/// to the end in their given order (an unknown whose own pivot may be zero, as a voltage
/// hold's current, gets its pivot from the fill of its neighbours). Ties go to the lowest
/// index, so the result is deterministic.
pub fn minimum_degree(n: usize, entries: &[(usize, usize)], last: &[usize]) -> Elimination {
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); n];
    for &(r, c) in entries {
        if r != c {
            adj[r].push(c);
            adj[c].push(r);
        }
    }
    for a in adj.iter_mut() {
        a.sort_unstable();
        a.dedup();
    }
    let mut held = vec![false; n];
    for &v in last {
        held[v] = true;
    }
    let mut heap: BinaryHeap<Reverse<(usize, usize)>> = (0..n).filter(|&v| !held[v]).map(|v| Reverse((adj[v].len(), v))).collect();
    let mut eliminated = vec![false; n];
    // mark[w] == u + 1 while the neighbours of u are being merged
    let mut mark = vec![0usize; n];
    let mut order = Vec::with_capacity(n);
    let mut later = vec![Vec::new(); n];
    type Heap = BinaryHeap<Reverse<(usize, usize)>>;
    let mut eliminate = |v: usize, adj: &mut Vec<Vec<usize>>, heap: &mut Heap, eliminated: &mut [bool]| {
        eliminated[v] = true;
        order.push(v);
        let nbrs = std::mem::take(&mut adj[v]);
        for &u in &nbrs {
            let list = &mut adj[u];
            list.retain(|&w| w != v);
            for &w in list.iter() {
                mark[w] = u + 1;
            }
            for &w in &nbrs {
                if w != u && mark[w] != u + 1 {
                    list.push(w);
                }
            }
            if !held[u] {
                heap.push(Reverse((list.len(), u)));
            }
        }
        later[v] = nbrs;
    };
    while let Some(Reverse((deg, v))) = heap.pop() {
        if eliminated[v] || deg != adj[v].len() {
            continue;
        }
        eliminate(v, &mut adj, &mut heap, &mut eliminated);
    }
    for &v in last {
        eliminate(v, &mut adj, &mut heap, &mut eliminated);
    }
    Elimination { order, later }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrow_matrix_eliminates_the_hub_last_without_fill() {
        // Node 0 couples to every other node: eliminating it first would fill the matrix.
        let n = 6;
        let entries: Vec<(usize, usize)> = (1..n).flat_map(|i| [(0, i), (i, 0)]).collect();
        let e = minimum_degree(n, &entries, &[]);
        // The hub goes once a single leaf is left (a tie with that leaf).
        assert_eq!(e.order[n - 2], 0);
        let fill: usize = e.later.iter().map(Vec::len).sum();
        assert_eq!(fill, n - 1, "only the original off-diagonal couplings");
    }

    /// A chain 1-2-3-4-5 with a leaf 0 on node 3 (a voltage hold's current on one row): free,
    /// the leaf goes first (lowest degree and index); held, it goes last, and the elimination
    /// of the chain couples it to the node eliminated just before it (its pivot gets fill).
    #[test]
    fn held_nodes_go_last_and_collect_their_fill() {
        let mut entries: Vec<(usize, usize)> = (1..5).flat_map(|i| [(i, i + 1), (i + 1, i)]).collect();
        entries.extend([(3, 0), (0, 3)]);
        assert_eq!(minimum_degree(6, &entries, &[]).order[0], 0);
        let held = minimum_degree(6, &entries, &[0]);
        assert_eq!(held.order[5], 0);
        assert_eq!(held.later[held.order[4]], vec![0]);
    }

    /// Four 5-node chains hanging off a 3-node spine (particles on an electrolyte line): the
    /// level order keeps the fill and eliminates every node before its later neighbours, and
    /// the chains' nodes of one depth come out together.
    #[test]
    fn level_order_keeps_the_fill_and_interleaves_independent_chains() {
        let mut entries = vec![(0, 1), (1, 0), (1, 2), (2, 1)];
        for c in 0..4 {
            let first = 3 + 5 * c;
            for k in first..first + 4 {
                entries.extend([(k, k + 1), (k + 1, k)]);
            }
            entries.extend([(first + 4, c % 3), (c % 3, first + 4)]);
        }
        let plain = minimum_degree(23, &entries, &[]);
        let fill: Vec<usize> = plain.later.iter().map(Vec::len).collect();
        let levelled = minimum_degree(23, &entries, &[]).by_level();
        assert_eq!(levelled.later.iter().map(Vec::len).collect::<Vec<_>>(), fill);
        let mut pos = [0; 23];
        for (i, &v) in levelled.order.iter().enumerate() {
            pos[v] = i;
        }
        for (v, later) in levelled.later.iter().enumerate() {
            assert!(later.iter().all(|&w| pos[w] > pos[v]), "{v} must go before {later:?}");
        }
        // The four chain ends (leaves) are eliminated first, one after another.
        let mut leaves: Vec<usize> = levelled.order[..4].to_vec();
        leaves.sort_unstable();
        assert_eq!(leaves, [3, 8, 13, 18]);
    }
}

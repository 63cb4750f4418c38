//! What the two pointer-based octrees (seed 000 §4.3.2) share: a node is a leaf's byte or
//! 8 children, reached from the root. [`super::pointer`] allocates every child on its own,
//! [`super::pointer_block`] the 8 children of a node in one block; reading a cell, listing the
//! leaves and walking the surface are the same for both.

use super::cell;
use super::key::{self, Key};

/// A node of a pointer-based octree.
pub trait PointerNode {
    /// The byte of a leaf (0 / 255 homogeneous, or a deepest cell's case byte); None for an
    /// internal node.
    fn leaf(&self) -> Option<u8>;
    /// Child `c` (location code z·4 + y·2 + x, Fig. 4.1) of an internal node.
    ///
    /// # Panics
    /// On a leaf.
    fn child(&self, c: usize) -> &Self;
}

/// Nodes of a tree with `internal` internal nodes: the root and 8 per internal node.
pub fn node_count(internal: usize) -> usize {
    8 * internal + 1
}

/// The byte of cell (x, y, z), walking down from `root` (seed 000 §4.3.2); 0 outside the
/// grid of side 2^depth.
pub fn cell<N: PointerNode>(root: &N, depth: u32, x: u32, y: u32, z: u32) -> u8 {
    let side = 1u64 << depth;
    if [x, y, z].iter().any(|&c| u64::from(c) >= side) {
        return 0;
    }
    let mut n = root;
    for l in (0..depth).rev() {
        if let Some(v) = n.leaf() {
            return v;
        }
        let c = (x >> l & 1) | (y >> l & 1) << 1 | (z >> l & 1) << 2;
        n = n.child(c as usize);
    }
    n.leaf().unwrap_or(0)
}

/// Every leaf below `n` (key `k`) with its byte, depth first in location-code order.
pub fn leaves<N: PointerNode>(n: &N, k: Key, f: &mut dyn FnMut(Key, u8)) {
    match n.leaf() {
        Some(v) => f(k, v),
        None => {
            for c in 0..8 {
                leaves(n.child(c), key::child(k, c as u8), f);
            }
        }
    }
}

/// Every surface cell below `n` (at `level`, cell `p` in its level's units) of a tree of
/// `depth` levels, depth first in location-code order, with the cells past the far faces.
pub fn surface<N: PointerNode, F: FnMut([u32; 3], u8)>(
    n: &N,
    level: u32,
    p: [u32; 3],
    depth: u32,
    f: &mut F,
) {
    match n.leaf() {
        Some(v) => cell::tree_leaf(p, level, depth, v, f),
        None => {
            for c in 0..8 {
                surface(
                    n.child(c),
                    level + 1,
                    super::child_xyz(p, c as u32),
                    depth,
                    f,
                );
            }
        }
    }
}

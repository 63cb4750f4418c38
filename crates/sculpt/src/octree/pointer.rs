//! The pointer-based octree as seed 000 describes it (§4.3.2 and §4.2.2).
//!
//! Layout (§4.3.2): "each parent node must store the addresses of its eight children", and
//! the children are labelled full, empty or mixed. So every node is its own allocation, a
//! label and 8 child addresses ([`Node`], 72 bytes), as the textbook C++ node
//! `struct Node { Node* child[8]; char label; }` is.
//!
//! Construction (§4.2.2, bottom-up, which the thesis prefers to top-down §4.2.1 at high
//! resolution): "voxels are placed, in traversal order, into a tree created empty with all
//! its leaf nodes; then nodes are merged bottom-up as the sub-spaces are full, empty or
//! mixed", looking at 8 children at a time. Here every cell becomes a node (one allocation),
//! and a parent whose 8 children are homogeneous leaves of one value frees them and becomes
//! that leaf; the shared slice-by-slice [`super::build::Pyramid`] visits the same 2×2×2
//! blocks in order of z instead of the thesis's reverse-Z (Morton) order, so at most two
//! layers of a level are alive, not the whole tree of leaves. The node and allocation counts
//! are those of the description; [`super::pointer_block`] is the stronger variant (one block
//! per 8 children, no node for a run of homogeneous cells) over the same builder.

use super::build::Merge;
use super::key::{Key, ROOT};
use super::tree::{self, PointerNode};
use super::{Budget, Finish, StoreKind, SurfaceWalk, VoxelStore};
use crate::{Error, Result};

/// A node: its own allocation, a label (0 empty, 255 full, a cell's case byte, or mixed) and
/// the addresses of its 8 children when mixed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Node {
    /// A leaf: 0 empty, 255 full, or a deepest cell's case byte.
    Leaf(u8),
    /// An internal node: the addresses of its 8 children, by location code.
    Inner([Box<Node>; 8]),
}

/// The thesis's pointer-based octree.
#[derive(Clone, Debug)]
pub struct PointerOctree {
    depth: u32,
    root: Box<Node>,
    internal: usize,
}

/// Allocates every node while building (seed 000 §4.2.2).
pub struct Nodes {
    /// The nodes' bytes, the root's included.
    budget: Budget,
}

impl Nodes {
    /// Nothing built yet but the root, within `budget` bytes.
    pub fn new(budget: u64) -> Nodes {
        Nodes {
            budget: Budget::new(NODE_BYTES, budget),
        }
    }
}

/// Bytes of a node.
const NODE_BYTES: u64 = std::mem::size_of::<Node>() as u64;

/// A node being built: `None` only for a slot the pyramid has not filled yet.
pub type Slot = Option<Box<Node>>;

impl Merge for Nodes {
    type Node = Slot;
    /// §4.2.2: every cell is a leaf node of the tree before anything is merged.
    const EVERY_CELL: bool = true;

    fn leaf(&mut self, v: u8) -> Slot {
        Some(Box::new(Node::Leaf(v)))
    }

    fn leaf_value(n: &Slot) -> Option<u8> {
        n.as_deref().and_then(PointerNode::leaf)
    }

    /// Merging frees 7 children and keeps the first's allocation for the parent leaf (one
    /// allocator call fewer than freeing 8 and allocating the parent).
    fn merge_leaf(&mut self, v: u8, kids: [Slot; 8]) -> Slot {
        let [first, ..] = kids;
        first.map(|mut n| {
            *n = Node::Leaf(v);
            n
        })
    }

    fn internal(&mut self, _: Key, kids: [Slot; 8]) -> Result<Slot> {
        self.budget.charge(8 * NODE_BYTES)?;
        let kids = kids.map(|k| k.unwrap_or_else(|| Box::new(Node::Leaf(0))));
        Ok(Some(Box::new(Node::Inner(kids))))
    }
}

impl Finish for Nodes {
    type Store = PointerOctree;

    fn finish(self, root: Slot, internal: u64, depth: u32) -> Result<PointerOctree> {
        Ok(PointerOctree {
            depth,
            root: root.ok_or(Error::NoRoot)?,
            internal: internal as usize,
        })
    }
}

impl PointerOctree {
    /// The root node.
    pub fn root(&self) -> &Node {
        &self.root
    }
}

impl PointerNode for Node {
    fn leaf(&self) -> Option<u8> {
        match self {
            Node::Leaf(v) => Some(*v),
            Node::Inner(_) => None,
        }
    }

    fn child(&self, c: usize) -> &Node {
        match self {
            Node::Inner(ch) => &ch[c],
            Node::Leaf(_) => panic!("a leaf has no children"),
        }
    }
}

impl VoxelStore for PointerOctree {
    fn kind(&self) -> StoreKind {
        StoreKind::Pointer
    }

    fn depth(&self) -> u32 {
        self.depth
    }

    /// Walks down from the root (seed 000 §4.3.2).
    fn cell(&self, x: u32, y: u32, z: u32) -> u8 {
        tree::cell(&*self.root, self.depth, x, y, z)
    }

    /// Every node: the root and 8 per internal node.
    fn node_count(&self) -> usize {
        tree::node_count(self.internal)
    }

    fn internal_count(&self) -> usize {
        self.internal
    }

    /// The nodes themselves (72 bytes each; the allocator's own overhead not counted).
    fn bytes(&self) -> usize {
        self.node_count() * std::mem::size_of::<Node>()
    }

    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8)) {
        tree::leaves(&*self.root, ROOT, f);
    }
}

impl SurfaceWalk for PointerOctree {
    /// Depth first, children in location-code order.
    fn walk_surface<F: FnMut([u32; 3], u8)>(&self, mut f: F) {
        tree::surface(&*self.root, 0, [0; 3], self.depth, &mut f);
    }
}

// The tests every store passes.
#[cfg(test)]
super::suite::voxel_store_suite!(tests, super::StoreKind::Pointer);

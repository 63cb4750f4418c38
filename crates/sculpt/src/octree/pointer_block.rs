//! A pointer-based octree stronger than the thesis's (seed 000 §4.3.2): every internal node
//! points to one block of its 8 children (`Box<[_; 8]>`, the usual Rust layout) rather than to
//! 8 nodes allocated one by one, and it is built by the shared bottom-up builder
//! ([`super::build`]), which makes no node for a run of homogeneous cells. Nodes are full,
//! empty, mixed (internal) or, at the deepest level, a cell byte; reaching a cell walks down
//! from the root. [`super::pointer`] is the thesis's own construction and layout.

use super::build::Merge;
use super::key::{Key, ROOT};
use super::tree::{self, PointerNode};
use super::{Budget, Finish, StoreKind, SurfaceWalk, VoxelStore};
use crate::Result;

/// A node: a leaf's value (0 / 255 homogeneous, or a cell's byte) or 8 children.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PNode {
    /// A leaf: 0 empty, 255 full, or a deepest cell's case byte.
    Leaf(u8),
    /// An internal node: its 8 children in one block, by location code.
    Inner(Box<[PNode; 8]>),
}

impl Default for PNode {
    fn default() -> PNode {
        PNode::Leaf(0)
    }
}

/// The pointer-based octree with a block of children per internal node.
#[derive(Clone, Debug)]
pub struct BlockPointerOctree {
    depth: u32,
    root: PNode,
    internal: usize,
}

/// Links children to parents while building.
pub struct Links {
    /// The nodes' bytes, the root's included.
    budget: Budget,
}

impl Links {
    /// Nothing built yet but the root, within `budget` bytes.
    pub fn new(budget: u64) -> Links {
        Links {
            budget: Budget::new(NODE_BYTES, budget),
        }
    }
}

/// Bytes of a node.
const NODE_BYTES: u64 = std::mem::size_of::<PNode>() as u64;

impl Merge for Links {
    type Node = PNode;

    fn leaf(&mut self, v: u8) -> PNode {
        PNode::Leaf(v)
    }

    fn leaf_value(n: &PNode) -> Option<u8> {
        n.leaf()
    }

    fn internal(&mut self, _: Key, kids: [PNode; 8]) -> Result<PNode> {
        self.budget.charge(8 * NODE_BYTES)?;
        Ok(PNode::Inner(Box::new(kids)))
    }
}

impl Finish for Links {
    type Store = BlockPointerOctree;

    fn finish(self, root: PNode, internal: u64, depth: u32) -> Result<BlockPointerOctree> {
        Ok(BlockPointerOctree {
            depth,
            root,
            internal: internal as usize,
        })
    }
}

impl BlockPointerOctree {
    /// The root node.
    pub fn root(&self) -> &PNode {
        &self.root
    }
}

impl PointerNode for PNode {
    fn leaf(&self) -> Option<u8> {
        match self {
            PNode::Leaf(v) => Some(*v),
            PNode::Inner(_) => None,
        }
    }

    fn child(&self, c: usize) -> &PNode {
        match self {
            PNode::Inner(ch) => &ch[c],
            PNode::Leaf(_) => panic!("a leaf has no children"),
        }
    }
}

impl VoxelStore for BlockPointerOctree {
    fn kind(&self) -> StoreKind {
        StoreKind::PointerBlock
    }

    fn depth(&self) -> u32 {
        self.depth
    }

    /// Walks down from the root (seed 000 §4.3.2).
    fn cell(&self, x: u32, y: u32, z: u32) -> u8 {
        tree::cell(&self.root, self.depth, x, y, z)
    }

    /// Every node: the root and 8 per internal node.
    fn node_count(&self) -> usize {
        tree::node_count(self.internal)
    }

    fn internal_count(&self) -> usize {
        self.internal
    }

    /// The nodes themselves (16 bytes each; the allocator's own overhead not counted).
    fn bytes(&self) -> usize {
        self.node_count() * std::mem::size_of::<PNode>()
    }

    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8)) {
        tree::leaves(&self.root, ROOT, f);
    }
}

impl SurfaceWalk for BlockPointerOctree {
    /// Depth first, children in location-code order.
    fn walk_surface<F: FnMut([u32; 3], u8)>(&self, mut f: F) {
        tree::surface(&self.root, 0, [0; 3], self.depth, &mut f);
    }
}

// The tests every store passes.
#[cfg(test)]
super::suite::voxel_store_suite!(tests, super::StoreKind::PointerBlock);

//! A pointer-based octree stronger than the thesis's (seed 000 §4.3.2): every internal node
//! points to one block of its 8 children (`Box<[_; 8]>`, the usual Rust layout) rather than to
//! 8 nodes allocated one by one, and it is built by the shared bottom-up builder
//! ([`super::build`]), which makes no node for a run of homogeneous cells. Nodes are full,
//! empty, mixed (internal) or, at the deepest level, a cell byte; reaching a cell walks down
//! from the root. [`super::pointer`] is the thesis's own construction and layout.

use super::build::Merge;
use super::cell;
use super::key::{self, Key, ROOT};
use super::mc::Tri;
use super::{Finish, StoreKind, VoxelStore};

/// A node: a leaf's value (0 / 255 homogeneous, or a cell's byte) or 8 children.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PNode {
    Leaf(u8),
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
    nodes: u64,
    budget: u64,
}

impl Links {
    pub fn new(budget: u64) -> Links {
        Links { nodes: 1, budget }
    }
}

impl Merge for Links {
    type Node = PNode;

    fn cell(&mut self, v: u8) -> PNode {
        PNode::Leaf(v)
    }

    fn homogeneous(n: &PNode) -> Option<u8> {
        match n {
            PNode::Leaf(v) if *v == 0 || *v == 255 => Some(*v),
            _ => None,
        }
    }

    fn leaf(&mut self, v: u8) -> PNode {
        PNode::Leaf(v)
    }

    fn internal(&mut self, _: Key, kids: [PNode; 8]) -> Result<PNode, String> {
        self.nodes += 8;
        let need = self.nodes * std::mem::size_of::<PNode>() as u64;
        if need > self.budget {
            return Err(super::over_budget(need, self.budget));
        }
        Ok(PNode::Inner(Box::new(kids)))
    }
}

impl Finish for Links {
    type Store = BlockPointerOctree;

    fn finish(self, root: PNode, internal: u64, depth: u32) -> Result<BlockPointerOctree, String> {
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

    fn leaves(&self, n: &PNode, k: Key, f: &mut dyn FnMut(Key, u8)) {
        match n {
            PNode::Leaf(v) => f(k, *v),
            PNode::Inner(ch) => {
                for (c, n) in ch.iter().enumerate() {
                    self.leaves(n, key::child(k, c as u8), f);
                }
            }
        }
    }

    /// Every surface cell, walking the tree depth first (children in location-code order).
    fn surface<F: FnMut([u32; 3], u8)>(&self, n: &PNode, level: u32, p: [u32; 3], f: &mut F) {
        match n {
            PNode::Leaf(v) => cell::tree_leaf(p, level, self.depth, *v, f),
            PNode::Inner(ch) => {
                for (c, n) in ch.iter().enumerate() {
                    self.surface(n, level + 1, super::child_xyz(p, c as u32), f);
                }
            }
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
        let side = 1u64 << self.depth;
        if [x, y, z].iter().any(|&c| u64::from(c) >= side) {
            return 0;
        }
        let mut n = &self.root;
        for l in (0..self.depth).rev() {
            match n {
                PNode::Leaf(v) => return *v,
                PNode::Inner(ch) => {
                    let c = (x >> l & 1) | (y >> l & 1) << 1 | (z >> l & 1) << 2;
                    n = &ch[c as usize];
                }
            }
        }
        match n {
            PNode::Leaf(v) => *v,
            PNode::Inner(_) => 0,
        }
    }

    /// Every node: the root and 8 per internal node.
    fn node_count(&self) -> usize {
        8 * self.internal + 1
    }

    fn internal_count(&self) -> usize {
        self.internal
    }

    /// The nodes themselves (16 bytes each; the allocator's own overhead not counted).
    fn bytes(&self) -> usize {
        self.node_count() * std::mem::size_of::<PNode>()
    }

    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8)) {
        self.leaves(&self.root, ROOT, f);
    }

    fn for_each_surface_cell(&self, f: &mut dyn FnMut([u32; 3], u8)) {
        self.surface(&self.root, 0, [0; 3], &mut |p, v| f(p, v));
    }

    fn marching_cubes_into(&self, out: &mut Vec<Tri>) {
        out.clear();
        let t = super::mc::table();
        self.surface(&self.root, 0, [0; 3], &mut |p, v| t.emit(p, v, out));
    }
}

//! The optimized hash-based octree (seed 000 §4.3.4, §3.1.1.6): only leaves are stored.
//!
//! A leaf is a homogeneous node (every cell below it 0, or every cell 255) at any level, or a
//! deepest-level cell of any value. Internal nodes are never stored: a parent's key is its
//! child's key >> 3. The leaves are inserted level by level from the deepest, each appended to
//! its bucket's chain, so cells sit at the heads of the chains where the most frequent lookups
//! (cells) find them first. A cell is found by its key, or, when it was merged into a coarse
//! leaf, by stripping three bits at a time until a key is in the table (§5.1, Eq. 5.1).

use super::hashed;
use super::key::{self, Key, ROOT};
use super::table::{Entry, KeyTable};
use super::{Finish, StoreKind};
use crate::{CellProblem, Error, Result};

// Here before hashed.rs took it (both hashed builders use it): the public path stays.
pub use super::hashed::MIXED;

/// The optimized hash-based octree.
#[derive(Clone, Debug)]
pub struct OptimizedOctree {
    depth: u32,
    table: KeyTable,
    internal: usize,
}

/// The leaves of each level, collected while building (seed 000 §4.3.4 step 2: what is known
/// about homogeneous sub-spaces is kept only until the table is filled).
pub type Leaves = hashed::Collect<false>;

impl Finish for Leaves {
    type Store = OptimizedOctree;

    fn finish(mut self, root: u16, internal: u64, depth: u32) -> Result<OptimizedOctree> {
        if root != MIXED {
            self.0.level(0).push(Entry::new(ROOT, root as u8, false));
        }
        let table = self.0.into_table()?;
        Ok(OptimizedOctree {
            depth,
            table,
            internal: internal as usize,
        })
    }
}

impl OptimizedOctree {
    /// The optimized octree of a whole volume, fed slice by slice (for sculpting and tests;
    /// [`super::builder`] gives the same store boxed).
    pub fn from_volume(v: &csgpix_scene::grid::Volume, budget: u64) -> Result<Self> {
        let depth = super::checked_depth(StoreKind::Octree, v.dims, budget)?;
        super::build_tree(depth, v.dims[0], Leaves::new(depth, budget)).store_of(v)
    }

    /// The deepest key of cell (x, y, z), if it is in the grid.
    pub fn cell_key(&self, x: u32, y: u32, z: u32) -> Option<Key> {
        hashed::cell_key(self.depth, x, y, z)
    }

    /// The leaf holding cell (x, y, z): the cell's own key, or the nearest ancestor in the
    /// table (seed 000 §5.1 step 3, Eq. 5.1). None outside the grid.
    pub fn find(&self, x: u32, y: u32, z: u32) -> Option<(Key, u8)> {
        hashed::find(&self.table, self.depth, x, y, z)
    }

    /// Makes cell (x, y, z) a leaf of its own: the coarse leaf holding it is removed and,
    /// level by level down to the cell, the 8 children of the node on the path are inserted
    /// with its value, the one on the path split further (seed 000 §5.2 scenario 2, split
    /// along the path only). Returns the cell's key.
    pub fn split_to(&mut self, x: u32, y: u32, z: u32) -> Result<Key> {
        let target = self.cell_key(x, y, z).ok_or(Error::Cell {
            cell: [x, y, z],
            problem: CellProblem::Outside,
        })?;
        let (found, v) = self.find(x, y, z).ok_or(Error::Cell {
            cell: [x, y, z],
            problem: CellProblem::NoLeaf,
        })?;
        if found == target {
            return Ok(target);
        }
        self.table.remove(found);
        let (from, to) = (key::level(found), self.depth);
        for l in from..to {
            let on_path = target >> (3 * (to - l - 1));
            let node = key::parent(on_path);
            for c in 0..8 {
                let k = key::child(node, c);
                if k != on_path || l + 1 == to {
                    self.table.push(k, v, false)?;
                }
            }
        }
        Ok(target)
    }

    /// Sets cell (x, y, z)'s byte, splitting its coarse leaf first.
    pub fn set_cell(&mut self, x: u32, y: u32, z: u32, v: u8) -> Result<()> {
        let k = self.split_to(x, y, z)?;
        match self.table.get_mut(k) {
            Some(slot) => {
                *slot = v;
                Ok(())
            }
            None => Err(Error::Cell {
                cell: [x, y, z],
                problem: CellProblem::Vanished,
            }),
        }
    }

    /// Room for `more` nodes without reallocating (sculpting, seed 000 §5.2).
    pub fn reserve(&mut self, more: usize) {
        self.table.reserve(more);
    }

    /// The hash table (for its chain statistics).
    pub fn table(&self) -> &KeyTable {
        &self.table
    }
}

hashed::hashed_store!(OptimizedOctree, StoreKind::Octree);

/// A builder of the optimized octree over a volume of `dims`, fed slice by slice in order of
/// k ([`StoreBuilder::push`](super::StoreBuilder::push)) so that no dense volume is made
/// (seed 000 §4.3.4); `budget` bounds the leaves kept while building, in bytes.
/// [`finish_store`](super::TreeBuilder::finish_store) gives the octree.
pub fn builder(dims: [usize; 3], budget: u64) -> Result<super::TreeBuilder<Leaves>> {
    let depth = super::depth_for(dims)?;
    Ok(super::build_tree(
        depth,
        dims[0],
        Leaves::new(depth, budget),
    ))
}

// The tests every store passes.
#[cfg(test)]
super::suite::voxel_store_suite!(tests, super::StoreKind::Octree);

//! The optimized hash-based octree (seed 000 §4.3.4, §3.1.1.6): only leaves are stored.
//!
//! A leaf is a homogeneous node (every cell below it 0, or every cell 255) at any level, or a
//! deepest-level cell of any value. Internal nodes are never stored: a parent's key is its
//! child's key >> 3. The leaves are inserted level by level from the deepest, each appended to
//! its bucket's chain, so cells sit at the heads of the chains where the most frequent lookups
//! (cells) find them first. A cell is found by its key, or, when it was merged into a coarse
//! leaf, by stripping three bits at a time until a key is in the table (§5.1, Eq. 5.1).

use super::build::Merge;
use super::cell;
use super::key::{self, Key, ROOT};
use super::mc::{self, Tri};
use super::table::{Entry, KeyTable};
use super::{Finish, StoreKind, VoxelStore};

/// A node that has children, while building.
pub const MIXED: u16 = 256;

/// The optimized hash-based octree.
#[derive(Clone, Debug)]
pub struct OptimizedOctree {
    depth: u32,
    table: KeyTable,
    internal: usize,
}

/// The leaves of each level, collected while building (seed 000 §4.3.4 step 2: what is known
/// about homogeneous sub-spaces is kept only until the table is filled).
pub struct Leaves {
    lists: Vec<Vec<Entry>>,
    count: u64,
    budget: u64,
}

/// Bytes per leaf while building: its place in a level list and in the table, and a bucket.
const BUILD_BYTES: u64 = 16 + 16 + 8;

impl Leaves {
    pub fn new(depth: u32, budget: u64) -> Leaves {
        Leaves {
            lists: vec![Vec::new(); depth as usize + 1],
            count: 0,
            budget,
        }
    }
}

impl Merge for Leaves {
    type Node = u16;

    fn cell(&mut self, v: u8) -> u16 {
        v.into()
    }

    fn homogeneous(n: &u16) -> Option<u8> {
        (*n == 0 || *n == 255).then_some(*n as u8)
    }

    fn leaf(&mut self, v: u8) -> u16 {
        v.into()
    }

    fn internal(&mut self, k: Key, kids: [u16; 8]) -> Result<u16, String> {
        let list = &mut self.lists[key::level(k) as usize + 1];
        for (c, &n) in kids.iter().enumerate() {
            if n != MIXED {
                list.push(Entry::new(key::child(k, c as u8), n as u8, false));
                self.count += 1;
            }
        }
        let need = self.count * BUILD_BYTES;
        if need > self.budget {
            return Err(super::over_budget(need, self.budget));
        }
        Ok(MIXED)
    }
}

impl Finish for Leaves {
    type Store = OptimizedOctree;

    fn finish(mut self, root: u16, internal: u64, depth: u32) -> Result<OptimizedOctree, String> {
        if root != MIXED {
            self.lists[0].push(Entry::new(ROOT, root as u8, false));
        }
        // Deepest level first (§4.3.4 step 3): cells head their chains.
        let table = KeyTable::from_lists(self.lists.into_iter().rev().collect())?;
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
    pub fn from_volume(v: &csgpix_scene::grid::Volume, budget: u64) -> Result<Self, String> {
        use super::StoreBuilder;
        let need = super::memory_estimate(StoreKind::Octree, v.dims)?;
        if need > budget {
            return Err(super::over_budget(need, budget));
        }
        let depth = super::depth_for(v.dims)?;
        let mut b = super::build_tree(depth, v.dims[0], Leaves::new(depth, budget));
        let n = (v.dims[0] * v.dims[1]).max(1);
        for (k, s) in v.voxels.chunks(n).enumerate().take(v.dims[2]) {
            b.push(k, s)?;
        }
        b.finish_store()
    }

    /// The deepest key of cell (x, y, z), if it is in the grid.
    pub fn cell_key(&self, x: u32, y: u32, z: u32) -> Option<Key> {
        let side = 1u64 << self.depth;
        [x, y, z]
            .iter()
            .all(|&c| u64::from(c) < side)
            .then(|| key::key(x, y, z, self.depth))
    }

    /// The leaf holding cell (x, y, z): the cell's own key, or the nearest ancestor in the
    /// table (seed 000 §5.1 step 3, Eq. 5.1). None outside the grid.
    pub fn find(&self, x: u32, y: u32, z: u32) -> Option<(Key, u8)> {
        let mut k = self.cell_key(x, y, z)?;
        loop {
            if let Some(e) = self.table.get(k) {
                return Some((k, e.val));
            }
            if k <= ROOT {
                return None;
            }
            k = key::parent(k);
        }
    }

    /// Makes cell (x, y, z) a leaf of its own: the coarse leaf holding it is removed and,
    /// level by level down to the cell, the 8 children of the node on the path are inserted
    /// with its value, the one on the path split further (seed 000 §5.2 scenario 2, split
    /// along the path only). Returns the cell's key.
    pub fn split_to(&mut self, x: u32, y: u32, z: u32) -> Result<Key, String> {
        let target = self
            .cell_key(x, y, z)
            .ok_or_else(|| format!("cell ({x}, {y}, {z}) is outside the octree"))?;
        let (found, v) = self
            .find(x, y, z)
            .ok_or_else(|| format!("cell ({x}, {y}, {z}) has no leaf"))?;
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
    pub fn set_cell(&mut self, x: u32, y: u32, z: u32, v: u8) -> Result<(), String> {
        let k = self.split_to(x, y, z)?;
        match self.table.get_mut(k) {
            Some(slot) => {
                *slot = v;
                Ok(())
            }
            None => Err(format!("cell ({x}, {y}, {z}) vanished")),
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

impl VoxelStore for OptimizedOctree {
    fn kind(&self) -> StoreKind {
        StoreKind::Octree
    }

    fn depth(&self) -> u32 {
        self.depth
    }

    fn cell(&self, x: u32, y: u32, z: u32) -> u8 {
        self.find(x, y, z).map_or(0, |(_, v)| v)
    }

    fn node_count(&self) -> usize {
        self.table.len()
    }

    fn internal_count(&self) -> usize {
        self.internal
    }

    fn bytes(&self) -> usize {
        self.table.bytes()
    }

    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8)) {
        self.table.entries().iter().for_each(|e| f(e.key, e.val));
    }

    fn for_each_surface_cell(&self, f: &mut dyn FnMut([u32; 3], u8)) {
        self.surface(f);
    }

    fn marching_cubes_into(&self, out: &mut Vec<Tri>) {
        out.clear();
        let t = mc::table();
        self.surface(|p, v| t.emit(p, v, out));
    }
}

impl OptimizedOctree {
    /// Every surface cell: one linear pass over the table's entries (seed 000 §4.3.4: only
    /// leaves are stored, and a leaf with a byte other than 0 and 255 is a deepest cell),
    /// with the cells past the far faces that the non-empty leaves there border.
    fn surface<F: FnMut([u32; 3], u8)>(&self, mut f: F) {
        for e in self.table.entries() {
            cell::hashed_leaf(e.key, e.val, self.depth, &mut f);
        }
    }
}

/// A builder of the optimized octree over a volume of `dims`, fed slice by slice in order of
/// k ([`StoreBuilder::push`](super::StoreBuilder::push)) so that no dense volume is made
/// (seed 000 §4.3.4); `budget` bounds the leaves kept while building, in bytes.
/// [`finish_store`](super::TreeBuilder::finish_store) gives the octree.
pub fn builder(dims: [usize; 3], budget: u64) -> Result<super::TreeBuilder<Leaves>, String> {
    let depth = super::depth_for(dims)?;
    Ok(super::build_tree(
        depth,
        dims[0],
        Leaves::new(depth, budget),
    ))
}

//! What the two hash-based octrees share (seed 000 §4.3.3, §4.3.4): nodes collected level
//! by level while building and sealed into one [`KeyTable`] deepest level first, a cell found
//! by its key or its nearest stored ancestor (§5.1, Eq. 5.1), and the leaves and surface read
//! in one linear pass over the table. The optimized octree stores leaves only, the plain one
//! internal nodes as well, which every reading skips.

use super::build::Merge;
use super::cell;
use super::key::{self, Key, ROOT};
use super::table::{Entry, KeyTable};
use super::Budget;
use crate::Result;

/// A node that has children, while building; any other node is a leaf of that byte. The
/// node of both hashed builders ([`super::optimized::Leaves`], [`super::plain::All`]).
pub const MIXED: u16 = 256;

/// The byte of a hashed builder's leaf node (None for [`MIXED`]).
pub fn leaf_value(n: u16) -> Option<u8> {
    (n != MIXED).then_some(n as u8)
}

/// The builder of both hashed octrees ([`Merge`]): the nodes of each level collected while
/// building. `ALL`: every node, internal ones too (the plain octree, [`super::plain::All`]),
/// or the leaves alone (the optimized one, [`super::optimized::Leaves`]); the two differ in
/// nothing else while building, so the merge is written once.
pub struct Collect<const ALL: bool>(pub(super) Levels);

impl<const ALL: bool> Collect<ALL> {
    /// No node yet, for a tree of `depth` levels within `budget` bytes.
    pub fn new(depth: u32, budget: u64) -> Collect<ALL> {
        Collect(Levels::new(depth, budget))
    }
}

impl<const ALL: bool> Merge for Collect<ALL> {
    type Node = u16;

    fn leaf(&mut self, v: u8) -> u16 {
        v.into()
    }

    fn leaf_value(n: &u16) -> Option<u8> {
        leaf_value(*n)
    }

    /// Parent `k`'s children go to the next level's list: all 8 with `ALL` (an internal child
    /// flagged), else the leaves only, each charged to the budget; the parent itself is
    /// stored by its own parent, or as the root at the end.
    fn internal(&mut self, k: Key, kids: [u16; 8]) -> Result<u16> {
        let list = self.0.level(key::level(k) + 1);
        let before = list.len();
        for (c, &n) in kids.iter().enumerate() {
            if ALL || n != MIXED {
                list.push(Entry::new(
                    key::child(k, c as u8),
                    (n & 255) as u8,
                    n == MIXED,
                ));
            }
        }
        let added = list.len() - before;
        self.0.charge(added as u64)?;
        Ok(MIXED)
    }
}

/// Bytes per node while building: its place in a level list and in the table, and a bucket.
pub const BUILD_BYTES: u64 = 16 + 16 + 8;

/// The nodes of each level (0 the root's), collected while building (seed 000 §4.3.4 step
/// 2: what is known about homogeneous sub-spaces is kept only until the table is filled).
pub struct Levels {
    lists: Vec<Vec<Entry>>,
    budget: Budget,
}

impl Levels {
    /// No node yet, for a tree of `depth` levels within `budget` bytes.
    pub fn new(depth: u32, budget: u64) -> Levels {
        Levels {
            lists: vec![Vec::new(); depth as usize + 1],
            budget: Budget::new(0, budget),
        }
    }

    /// The nodes of `level` so far.
    pub fn level(&mut self, level: u32) -> &mut Vec<Entry> {
        &mut self.lists[level as usize]
    }

    /// Charge `nodes` more nodes of [`BUILD_BYTES`] against the budget.
    pub fn charge(&mut self, nodes: u64) -> Result<()> {
        self.budget.charge(nodes * BUILD_BYTES)
    }

    /// The table of every node, deepest level first (§4.3.4 step 3: cells head their
    /// chains).
    pub fn into_table(self) -> Result<KeyTable> {
        KeyTable::from_lists(self.lists.into_iter().rev().collect())
    }
}

/// The stored node holding cell (x, y, z) of a tree of `depth` levels: the cell's own key or
/// the nearest ancestor in `table` (seed 000 §5.1 step 3, Eq. 5.1). None outside the grid.
/// The first one found is a leaf: an internal ancestor would have its children stored.
pub fn find(table: &KeyTable, depth: u32, x: u32, y: u32, z: u32) -> Option<(Key, u8)> {
    let mut k = cell_key(depth, x, y, z)?;
    loop {
        if let Some(e) = table.get(k) {
            return Some((k, e.val));
        }
        if k <= ROOT {
            return None;
        }
        k = key::parent(k);
    }
}

/// The deepest key of cell (x, y, z), if it is in the grid of side 2^depth.
pub fn cell_key(depth: u32, x: u32, y: u32, z: u32) -> Option<Key> {
    let side = 1u64 << depth;
    [x, y, z]
        .iter()
        .all(|&c| u64::from(c) < side)
        .then(|| key::key(x, y, z, depth))
}

/// The leaves of `table`, internal nodes skipped.
pub fn leaves(table: &KeyTable) -> impl Iterator<Item = &Entry> {
    table.entries().iter().filter(|e| !e.internal)
}

/// Every surface cell of a tree of `depth` levels: one linear pass over the table's leaves
/// (a leaf with a byte other than 0 and 255 is a deepest cell), with the cells past the far
/// faces that the non-empty leaves there border.
pub fn walk_surface<F: FnMut([u32; 3], u8)>(table: &KeyTable, depth: u32, mut f: F) {
    for e in leaves(table) {
        cell::hashed_leaf(e.key, e.val, depth, &mut f);
    }
}

/// `VoxelStore` and `SurfaceWalk` of a hash-based octree (a type with `depth`, `table` and
/// `internal` fields): every reading goes through this module, so the two stores differ only
/// in their [`StoreKind`](super::StoreKind).
macro_rules! hashed_store {
    ($store:ty, $kind:expr) => {
        impl super::VoxelStore for $store {
            fn kind(&self) -> super::StoreKind {
                $kind
            }

            fn depth(&self) -> u32 {
                self.depth
            }

            fn cell(&self, x: u32, y: u32, z: u32) -> u8 {
                super::hashed::find(&self.table, self.depth, x, y, z).map_or(0, |(_, v)| v)
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

            fn for_each_leaf(&self, f: &mut dyn FnMut(super::key::Key, u8)) {
                super::hashed::leaves(&self.table).for_each(|e| f(e.key, e.val));
            }
        }

        impl super::SurfaceWalk for $store {
            /// One linear pass over the table's entries (internal nodes skipped).
            fn walk_surface<F: FnMut([u32; 3], u8)>(&self, f: F) {
                super::hashed::walk_surface(&self.table, self.depth, f);
            }
        }
    };
}
pub(crate) use hashed_store;

//! The plain hash-based octree (seed 000 §4.3.3, after Castro et al.): every node, internal
//! and leaf, in the hash table under its key. Built like the optimized one (bottom-up, level
//! by level from the deepest), with the internal nodes as well.

use super::hashed::{self, MIXED};
use super::key::{Key, ROOT};
use super::table::{Entry, KeyTable};
use super::{Finish, StoreKind};
use crate::Result;

/// The plain hash-based octree.
#[derive(Clone, Debug)]
pub struct PlainHashOctree {
    depth: u32,
    table: KeyTable,
    internal: usize,
}

/// Every node of each level (key, value, internal?), collected while building.
pub type All = hashed::Collect<true>;

impl Finish for All {
    type Store = PlainHashOctree;

    fn finish(mut self, root: u16, internal: u64, depth: u32) -> Result<PlainHashOctree> {
        self.0
            .level(0)
            .push(Entry::new(ROOT, (root & 255) as u8, root == MIXED));
        let table = self.0.into_table()?;
        Ok(PlainHashOctree {
            depth,
            table,
            internal: internal as usize,
        })
    }
}

impl PlainHashOctree {
    /// The leaf holding cell (x, y, z): its key or the nearest stored ancestor (the first one
    /// found is a leaf: an internal ancestor would have its children stored).
    pub fn find(&self, x: u32, y: u32, z: u32) -> Option<(Key, u8)> {
        hashed::find(&self.table, self.depth, x, y, z)
    }
}

hashed::hashed_store!(PlainHashOctree, StoreKind::Hash);

// The tests every store passes.
#[cfg(test)]
super::suite::voxel_store_suite!(tests, super::StoreKind::Hash);

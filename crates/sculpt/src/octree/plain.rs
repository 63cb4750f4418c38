//! The plain hash-based octree (seed 000 §4.3.3, after Castro et al.): every node, internal
//! and leaf, in the hash table under its key. Built like the optimized one (bottom-up, level
//! by level from the deepest), with the internal nodes as well.

use super::build::Merge;
use super::cell;
use super::key::{self, Key, ROOT};
use super::mc::{self, Tri};
use super::optimized::MIXED;
use super::table::{Entry, KeyTable};
use super::{Finish, StoreKind, VoxelStore};

/// The plain hash-based octree.
#[derive(Clone, Debug)]
pub struct PlainHashOctree {
    depth: u32,
    table: KeyTable,
    internal: usize,
}

/// Every node of each level (key, value, internal?), collected while building.
pub struct All {
    lists: Vec<Vec<Entry>>,
    count: u64,
    budget: u64,
}

/// Bytes per node while building: its place in a level list and in the table, and a bucket.
const BUILD_BYTES: u64 = 16 + 16 + 8;

impl All {
    pub fn new(depth: u32, budget: u64) -> All {
        All {
            lists: vec![Vec::new(); depth as usize + 1],
            count: 0,
            budget,
        }
    }
}

impl Merge for All {
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
            list.push(Entry::new(
                key::child(k, c as u8),
                (n & 255) as u8,
                n == MIXED,
            ));
        }
        self.count += 8;
        let need = self.count * BUILD_BYTES;
        if need > self.budget {
            return Err(super::over_budget(need, self.budget));
        }
        Ok(MIXED)
    }
}

impl Finish for All {
    type Store = PlainHashOctree;

    fn finish(mut self, root: u16, internal: u64, depth: u32) -> Result<PlainHashOctree, String> {
        self.lists[0].push(Entry::new(ROOT, (root & 255) as u8, root == MIXED));
        let table = KeyTable::from_lists(self.lists.into_iter().rev().collect())?;
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
        let side = 1u64 << self.depth;
        if [x, y, z].iter().any(|&c| u64::from(c) >= side) {
            return None;
        }
        let mut k = key::key(x, y, z, self.depth);
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
}

impl VoxelStore for PlainHashOctree {
    fn kind(&self) -> StoreKind {
        StoreKind::Hash
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
        for e in self.table.entries().iter().filter(|e| !e.internal) {
            f(e.key, e.val);
        }
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

impl PlainHashOctree {
    /// Every surface cell: one linear pass over the table's entries, internal nodes skipped.
    fn surface<F: FnMut([u32; 3], u8)>(&self, mut f: F) {
        for e in self.table.entries().iter().filter(|e| !e.internal) {
            cell::hashed_leaf(e.key, e.val, self.depth, &mut f);
        }
    }
}

//! What the stores hold, in bytes, from bounds of their nodes by level (docs/memory.md,
//! "Octree nodes"): [`csgpix_voxel::cells::cell_counts`] bounds them from a scene before it is
//! voxelized, [`volume_counts`] counts them in a volume in hand.
//!
//! Sizes are those of the types and of what the allocator and the standard collections make
//! of them: a `Vec` grown by pushes has at most twice the capacity it needs (at least 4), a
//! `HashMap` (hashbrown) has a power of two of buckets, at least 8/7 of its items, each with
//! a control byte, and holds its old table while it moves to one twice as large; glibc's
//! malloc takes 8 bytes a block and rounds it to 16.

use csgpix_scene::grid::Volume;
pub use csgpix_voxel::cells::{corner_code, CellCounts, Corner, CORNER_CODES};

use super::hashed::BUILD_BYTES;
use super::{depth_for, memory_estimate, StoreKind};
use crate::Result;

/// Bytes of a node table entry ([`super::table::Entry`]).
pub const ENTRY_BYTES: u64 = std::mem::size_of::<super::table::Entry>() as u64;

/// Bytes glibc's malloc takes for a block of `n` bytes.
pub fn malloc_block(n: u64) -> u64 {
    ((n + 8).div_ceil(16) * 16).max(32)
}

/// The capacity of a `Vec` grown from nothing to `len` items one push (or one extend no
/// longer than its capacity) at a time: it doubles from 4, so a power of two.
pub fn vec_capacity(len: u64) -> u64 {
    match len {
        0 => 0,
        n => n.checked_next_power_of_two().unwrap_or(u64::MAX).max(4),
    }
}

/// Buckets of a hashbrown table asked to hold `items` (`with_capacity`, `reserve`, or grown
/// to them one insert at a time).
pub fn map_buckets(items: u64) -> u64 {
    match items {
        0 => 0,
        1..=3 => 4,
        4..=7 => 8,
        n => (n.saturating_mul(8) / 7).next_power_of_two(),
    }
}

/// Bytes of a hashbrown table of `buckets` buckets of `entry` bytes.
pub fn map_bytes(buckets: u64, entry: u64) -> u64 {
    match buckets {
        0 => 0,
        b => b.saturating_mul(entry + 1).saturating_add(16),
    }
}

/// A store's build: what [`memory_estimate`] counts (cell layers, pyramid, the dense grid's
/// cells) and what its nodes hold at the build's peak.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StoreBytes {
    /// Cell layers, the pyramid, and the dense grid's cells.
    pub fixed: u64,
    /// The nodes at the peak of the build, at least what the build charges against its
    /// budget for them.
    pub nodes: u64,
}

impl StoreBytes {
    /// Both.
    pub fn total(&self) -> u64 {
        self.fixed.saturating_add(self.nodes)
    }
}

/// Entries of a hashed octree with `internal` internal nodes: its leaves (1 + 7 a node) for
/// the optimized octree, every node (1 + 8 a node) for the plain one.
pub fn hashed_entries(kind: StoreKind, internal: u64) -> u64 {
    let per = if kind == StoreKind::Hash { 8 } else { 7 };
    internal.saturating_mul(per).saturating_add(1)
}

/// Bytes of a sealed hashed octree of `entries` entries: the entries and a bucket head each
/// of its 2^n ≥ entries buckets ([`super::table::KeyTable::from_lists`]).
pub fn table_bytes(entries: u64) -> u64 {
    let buckets = entries.next_power_of_two().max(8);
    entries
        .saturating_mul(ENTRY_BYTES)
        .saturating_add(buckets.saturating_mul(4))
}

/// Bytes a build of `kind` over `dims` holds at its peak, its nodes bounded by `counts`:
///
/// - the hashed octrees: each level's list of entries (every child of an internal node of
///   the level above, at most twice the capacity it needs), then the table's entries copied
///   from them before they are freed, its radix sort's offsets and the bucket heads built
///   after; never less than [`BUILD_BYTES`] a node, what the build charges;
/// - the thesis's pointer octree: every node its own 72-byte block (80 with malloc's), the
///   root and 8 a node, and a block for every slot the pyramid holds (its two layers a level);
/// - the block pointer octree: a 128-byte block (144) of 8 children a node;
/// - the dense grid: nothing beyond its cells.
pub fn store_bytes(kind: StoreKind, dims: [usize; 3], counts: &CellCounts) -> Result<StoreBytes> {
    let fixed = memory_estimate(kind, dims)?;
    let depth = depth_for(dims)?;
    let internal = counts.internal();
    let nodes = match kind {
        StoreKind::Dense => 0,
        StoreKind::Octree | StoreKind::Hash => {
            let lists = counts.nonuniform[..depth as usize]
                .iter()
                .fold(0u64, |a, &n| {
                    a.saturating_add(vec_capacity(n.saturating_mul(8)))
                });
            let n = hashed_entries(kind, internal);
            let buckets = n.next_power_of_two().max(8);
            let low = buckets.trailing_zeros() / 2;
            let offsets = 8 * ((buckets >> low) + 1) + 4 * ((1 << low) + 1);
            let copy = lists
                .saturating_mul(ENTRY_BYTES)
                .saturating_add(n.saturating_mul(ENTRY_BYTES))
                .saturating_add(offsets);
            copy.max(table_bytes(n)).max(n.saturating_mul(BUILD_BYTES))
        }
        StoreKind::Pointer => {
            let node = malloc_block(std::mem::size_of::<super::pointer::Node>() as u64);
            let side = 1u64 << depth;
            let slots = 2 * side * side / 3 + 1;
            internal
                .saturating_mul(8)
                .saturating_add(1)
                .saturating_add(slots)
                .saturating_mul(node)
        }
        StoreKind::PointerBlock => {
            let block = std::mem::size_of::<[super::pointer_block::PNode; 8]>() as u64;
            internal.saturating_mul(malloc_block(block))
        }
    };
    Ok(StoreBytes { fixed, nodes })
}

/// The counts of `v`'s own octree, exactly: per level the internal nodes, at the deepest the
/// cells with a surface (the cells past the far faces included) and their corners.
pub fn volume_counts(v: &Volume) -> Result<CellCounts> {
    let depth = depth_for(v.dims)?;
    let side = 1usize << depth;
    let [nx, ny, nz] = v.dims;
    let kinds = row_kinds(v);
    let kind_at = |y: usize, z: usize| kinds[z * (ny + 2) + y];
    let row = |y: usize, z: usize| shifted_row(v, y, z);
    let mut tally = Tally::new(depth);
    for z in 0..=nz.min(side) {
        for y in 0..=ny.min(side) {
            let k = [
                kind_at(y, z),
                kind_at(y + 1, z),
                kind_at(y, z + 1),
                kind_at(y + 1, z + 1),
            ];
            if k == [0; 4] {
                continue;
            }
            let rows = [row(y, z), row(y + 1, z), row(y, z + 1), row(y + 1, z + 1)];
            let filled = |x: usize, r: usize| {
                x >= 1 && x <= nx && rows[r].is_some_and(|row| row[x - 1] != 0)
            };
            let corners_at =
                |x: usize| -> [bool; 8] { std::array::from_fn(|c| filled(x + (c & 1), c >> 1)) };
            if k == [1; 4] {
                // Full rows: only the cells at the row's two ends have an empty corner.
                for x in [0, nx.min(side)] {
                    tally.cell(x, y, z, corners_at(x));
                }
                continue;
            }
            for x in 0..=nx.min(side) {
                tally.cell(x, y, z, corners_at(x));
            }
        }
    }
    Ok(tally.finish())
}

/// Row (y, z) of `v`'s voxels, shifted by one (cells' corners are voxels x − 1 ..= x); None
/// outside the volume.
fn shifted_row(v: &Volume, y: usize, z: usize) -> Option<&[u8]> {
    let [nx, ny, nz] = v.dims;
    (y >= 1 && z >= 1 && y <= ny && z <= nz)
        .then(|| &v.voxels[((z - 1) * ny + (y - 1)) * nx..][..nx])
}

/// Per shifted row (y in 0..=ny + 1 fastest, z in 0..=nz + 1) whether it is empty (or
/// outside), full or neither: 0, 1 or 2.
fn row_kinds(v: &Volume) -> Vec<u8> {
    let [_, ny, nz] = v.dims;
    let kind = |r: Option<&[u8]>| match r {
        None => 0u8,
        Some(r) if r.iter().all(|&b| b == 0) => 0,
        Some(r) if r.iter().all(|&b| b != 0) => 1,
        Some(_) => 2,
    };
    (0..=nz + 1)
        .flat_map(|z| (0..=ny + 1).map(move |y| (y, z)))
        .map(|(y, z)| kind(shifted_row(v, y, z)))
        .collect()
}

/// The counts so far: the internal nodes of each level above the deepest (one bit each),
/// the cells with a surface and their corner codes.
struct Tally {
    depth: u32,
    side: usize,
    marks: Vec<Vec<u64>>,
    surface: u64,
    corners: Vec<u64>,
}

impl Tally {
    fn new(depth: u32) -> Tally {
        Tally {
            depth,
            side: 1usize << depth,
            marks: (0..depth)
                .map(|l| vec![0u64; (1usize << (3 * l)).div_ceil(64)])
                .collect(),
            surface: 0,
            corners: vec![0u64; CORNER_CODES],
        }
    }

    /// Cell (x, y, z) with corners `c` (in or out): when they differ, a surface cell, and
    /// (within the octree) its ancestors internal.
    fn cell(&mut self, x: usize, y: usize, z: usize, c: [bool; 8]) {
        if c.iter().all(|&b| b == c[0]) {
            return;
        }
        self.surface += 1;
        self.corners[corner_code(c.map(|b| if b { Corner::In } else { Corner::Out }))] += 1;
        let side = self.side;
        if x < side && y < side && z < side {
            for (l, m) in self.marks.iter_mut().enumerate() {
                let s = self.depth as usize - l;
                let at = ((z >> s) << (2 * l) | (y >> s) << l) | x >> s;
                m[at / 64] |= 1 << (at % 64);
            }
        }
    }

    /// Per level the internal nodes, at the deepest the surface cells; their corners.
    fn finish(self) -> CellCounts {
        let mut nonuniform: Vec<u64> = self
            .marks
            .iter()
            .map(|m| m.iter().map(|w| u64::from(w.count_ones())).sum())
            .collect();
        nonuniform.push(self.surface);
        CellCounts {
            depth: self.depth,
            nonuniform,
            corners: self.corners,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::octree::from_volume;

    fn ball(n: usize, r: f64) -> Volume {
        let c = n as f64 / 2.0 - 0.3;
        let voxels = (0..n * n * n)
            .map(|i| {
                let p = [i % n, i / n % n, i / (n * n)].map(|a| a as f64 - c);
                u8::from(p.iter().map(|a| a * a).sum::<f64>() <= r * r)
            })
            .collect();
        Volume {
            dims: [n, n, n],
            voxels,
        }
    }

    #[test]
    fn a_volumes_counts_are_its_stores_nodes() {
        for (n, r) in [(16, 5.5), (20, 9.7), (9, 4.0), (32, 20.0)] {
            let v = ball(n, r);
            let c = volume_counts(&v).unwrap();
            for kind in [StoreKind::Octree, StoreKind::Hash, StoreKind::Pointer] {
                let s = from_volume(kind, &v, u64::MAX).unwrap();
                assert_eq!(s.internal_count() as u64, c.internal(), "{kind:?} {n}");
            }
            let o = from_volume(StoreKind::Octree, &v, u64::MAX).unwrap();
            assert_eq!(
                o.node_count() as u64,
                hashed_entries(StoreKind::Octree, c.internal())
            );
            let mut cells = 0u64;
            o.for_each_surface_cell(&mut |_, _| cells += 1);
            assert_eq!(cells, c.surface_cells(), "{n}");
            assert_eq!(c.corners.iter().sum::<u64>(), cells);
            let tris = crate::octree::mc::marching_cubes(o.as_ref())
                .triangles
                .len() as u64;
            assert_eq!(crate::estimate::triangles(&c), tris, "{n}");
        }
    }

    #[test]
    fn collections_are_sized_as_the_standard_library_sizes_them() {
        let mut m = std::collections::HashMap::<u64, u64>::new();
        for i in 0..10_000u64 {
            m.insert(i, i);
            // hashbrown's capacity is 7/8 of its buckets.
            assert!(m.capacity() as u64 > i);
            assert!(map_buckets(i + 1) * 7 / 8 >= m.capacity() as u64, "{i}");
        }
        let mut v = Vec::<u64>::new();
        for i in 0..10_000u64 {
            v.push(i);
            assert!(v.capacity() as u64 <= vec_capacity(i + 1));
        }
        let mut t = Vec::<[[f32; 3]; 3]>::new();
        for i in 0..10_000usize {
            t.extend_from_slice(&vec![[[0.0; 3]; 3]; i % 6]);
            assert!(t.capacity() as u64 <= vec_capacity(t.len() as u64));
        }
        assert_eq!(malloc_block(72), 80);
        assert_eq!(malloc_block(128), 144);
    }
}

//! Voxel stores for sculpting (seed 000 Ch. 4): the optimized hash-based octree of §4.3.4 and
//! its baselines, the pointer-based octree (§4.3.2), the plain hash-based octree (§4.3.3)
//! and a dense grid, behind one trait so that the bench and sculpting can swap them.
//!
//! Every store holds cells, not voxels: cell (x, y, z) holds the Marching Cubes case byte of
//! its dual cell, whose corners are the voxels x−1..x, y−1..y, z−1..z ([`cell`], §3.1.1.5).
//! A voxel is bit 6 (corner V6 = (x, y, z)) of the cell with the same index. The cell grid is
//! a cube of side 2^depth ≥ the volume's largest side; voxels beyond the volume are empty.
//! Marching Cubes also meshes the cells just past the grid's far faces, so meshes are closed.
//!
//! The three octrees are built bottom-up, level by level, straight from voxel slices in
//! order of z ([`build`]); none of them, nor the dense grid's builder, needs the volume.
//! See `docs/octree.md`.

pub mod build;
pub mod cell;
pub mod dense;
pub mod estimate;
pub mod hashed;
pub mod key;
pub mod mc;
pub mod mc_tables;
pub mod optimized;
pub mod plain;
pub mod pointer;
pub mod pointer_block;
pub mod table;
pub mod tree;

/// The tests every store passes ([`suite::voxel_store_suite!`]), run in each store's module.
#[cfg(test)]
pub(crate) mod suite;

use crate::{Error, Result};
use csgpix_scene::grid::Volume;
use key::Key;

pub use dense::DenseGrid;
pub use optimized::OptimizedOctree;
pub use plain::PlainHashOctree;
pub use pointer::PointerOctree;
pub use pointer_block::BlockPointerOctree;

/// Which store.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum StoreKind {
    /// Leaves only, in a hash table (seed 000 §4.3.4).
    Octree,
    /// Nodes with child pointers, each node its own allocation, built as §4.2.2 describes
    /// (every cell a node, then merged) (§4.3.2).
    Pointer,
    /// Nodes with child pointers, 8 children in one block, built by the shared builder.
    #[serde(rename = "pointer-block")]
    PointerBlock,
    /// Every node, in a hash table (§4.3.3).
    Hash,
    /// One byte per cell.
    Dense,
}

impl StoreKind {
    /// Every store, in the order reports list them.
    pub const ALL: [StoreKind; 5] = [
        StoreKind::Octree,
        StoreKind::Pointer,
        StoreKind::PointerBlock,
        StoreKind::Hash,
        StoreKind::Dense,
    ];

    /// The store's name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            StoreKind::Octree => "octree",
            StoreKind::Pointer => "pointer",
            StoreKind::PointerBlock => "pointer-block",
            StoreKind::Hash => "hash",
            StoreKind::Dense => "dense",
        }
    }
}

/// A store of cells (seed 000 §3.1.1.5) that sculpting and Marching Cubes can use. Its
/// surface traversal and global Marching Cubes come from [`Surface`], which every
/// [`SurfaceWalk`] has.
pub trait VoxelStore: Send + Sync + Surface {
    /// Which store this is.
    fn kind(&self) -> StoreKind;
    /// Levels below the root: the cell grid has side 2^depth.
    fn depth(&self) -> u32;
    /// Cells per axis.
    fn side(&self) -> usize {
        1 << self.depth()
    }
    /// The case byte of cell (x, y, z); 0 outside the grid.
    fn cell(&self, x: u32, y: u32, z: u32) -> u8;
    /// Is voxel (x, y, z) filled (bit 6 of its cell)?
    fn get(&self, x: u32, y: u32, z: u32) -> bool {
        self.cell(x, y, z) >> cell::SELF_BIT & 1 == 1
    }
    /// Nodes stored: for the octrees every node the structure holds (the root included for
    /// the pointer and plain hash trees), for the dense grid its cells.
    fn node_count(&self) -> usize;
    /// Internal nodes of the octree (the root included when it has children); 0 for the
    /// dense grid.
    fn internal_count(&self) -> usize;
    /// Bytes allocated for the structure.
    fn bytes(&self) -> usize;
    /// Every leaf: its key and value (a coarse leaf's value is 0 or 255).
    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8));
}

/// A store's own surface traversal, generic in what it calls so that Marching Cubes emits
/// each cell's triangles without a call through a pointer: the one surface method a store
/// writes ([`Surface`] follows from it).
pub trait SurfaceWalk {
    /// Every cell with a surface (byte not 0 nor 255), with its coordinates, the cells just
    /// past the far faces included (a coordinate equal to the side: not stored, their bytes
    /// from the stored cells they border, [`cell::beyond_leaf`]), so that meshes close.
    fn walk_surface<F: FnMut([u32; 3], u8)>(&self, f: F);
}

/// The surface of a store, callable through `dyn` [`VoxelStore`]: what every
/// [`SurfaceWalk`] gives.
pub trait Surface {
    /// Every surface cell, as [`SurfaceWalk::walk_surface`] visits them.
    fn for_each_surface_cell(&self, f: &mut dyn FnMut([u32; 3], u8));
    /// Global Marching Cubes (seed 000 §3.1.2) into `out`, cleared first: every surface
    /// cell's triangles, in the store's own traversal order.
    fn marching_cubes_into(&self, out: &mut Vec<mc::Tri>);
}

impl<S: SurfaceWalk> Surface for S {
    fn for_each_surface_cell(&self, f: &mut dyn FnMut([u32; 3], u8)) {
        self.walk_surface(f);
    }

    fn marching_cubes_into(&self, out: &mut Vec<mc::Tri>) {
        out.clear();
        let t = mc::table();
        self.walk_surface(|p, v| t.emit(p, v, out));
    }
}

/// A building store's memory: bytes charged against a budget.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Bytes charged so far.
    pub used: u64,
    /// Bytes allowed.
    pub limit: u64,
}

impl Budget {
    /// `used` bytes charged against `limit`.
    pub fn new(used: u64, limit: u64) -> Budget {
        Budget { used, limit }
    }

    /// Charge `bytes` more; [`Error::OverBudget`] once past the limit.
    pub fn charge(&mut self, bytes: u64) -> Result<()> {
        self.used += bytes;
        check_budget(self.used, self.limit)
    }
}

/// [`Error::OverBudget`] when `need` bytes are more than `budget`.
pub fn check_budget(need: u64, budget: u64) -> Result<()> {
    if need > budget {
        return Err(Error::OverBudget { need, budget });
    }
    Ok(())
}

/// The coordinates of child `c` (location code z·4 + y·2 + x, Fig. 4.1) of the node at `p`.
pub fn child_xyz(p: [u32; 3], c: u32) -> [u32; 3] {
    [
        2 * p[0] + (c & 1),
        2 * p[1] + (c >> 1 & 1),
        2 * p[2] + (c >> 2),
    ]
}

/// Takes voxel slices in order of z and builds a store.
pub trait StoreBuilder {
    /// Voxel slice `k` (colour codes, 0 empty, X fastest, the volume's width per row).
    fn push(&mut self, k: usize, slice: &[u8]) -> Result<()>;
    /// The store, once every slice is in (missing slices up to the side are empty).
    fn finish(self: Box<Self>) -> Result<Box<dyn VoxelStore>>;
}

/// Levels of the octree over a volume of `dims`: the side is the next power of two.
pub fn depth_for(dims: [usize; 3]) -> Result<u32> {
    let side = dims.iter().copied().max().unwrap_or(1).max(1);
    let depth = side.next_power_of_two().trailing_zeros();
    if depth > key::MAX_DEPTH {
        return Err(Error::TooDeep {
            side,
            depth,
            max: key::MAX_DEPTH,
        });
    }
    Ok(depth)
}

/// Bytes a build needs before its nodes: the slice and cell layers, the pyramid, and for
/// the dense grid its cells. The octrees' nodes are counted as they are made, against the
/// budget given to [`builder`]; [`estimate::store_bytes`] bounds them before the build.
pub fn memory_estimate(kind: StoreKind, dims: [usize; 3]) -> Result<u64> {
    let depth = depth_for(dims)?;
    let side = 1u64 << depth;
    let layers = cell::CellLayers::bytes(side as usize);
    Ok(match kind {
        StoreKind::Dense => layers + side * side * side,
        StoreKind::Pointer => layers + build::Pyramid::<pointer::Nodes>::bytes(depth, 8),
        StoreKind::PointerBlock => {
            layers + build::Pyramid::<pointer_block::Links>::bytes(depth, 16)
        }
        StoreKind::Octree | StoreKind::Hash => {
            layers + build::Pyramid::<plain::All>::bytes(depth, 2)
        }
    })
}

/// A builder for a volume of `dims` that refuses to hold more than `budget` bytes.
pub fn builder(kind: StoreKind, dims: [usize; 3], budget: u64) -> Result<Box<dyn StoreBuilder>> {
    let depth = checked_depth(kind, dims, budget)?;
    Ok(match kind {
        StoreKind::Dense => Box::new(dense::Builder::new(depth, dims[0])),
        StoreKind::Octree => Box::new(build_tree(
            depth,
            dims[0],
            optimized::Leaves::new(depth, budget),
        )),
        StoreKind::Hash => Box::new(build_tree(depth, dims[0], plain::All::new(depth, budget))),
        StoreKind::Pointer => Box::new(build_tree(depth, dims[0], pointer::Nodes::new(budget))),
        StoreKind::PointerBlock => Box::new(build_tree(
            depth,
            dims[0],
            pointer_block::Links::new(budget),
        )),
    })
}

/// The depth of a store of `kind` over `dims`, once its [`memory_estimate`] fits `budget`.
fn checked_depth(kind: StoreKind, dims: [usize; 3], budget: u64) -> Result<u32> {
    check_budget(memory_estimate(kind, dims)?, budget)?;
    depth_for(dims)
}

/// A store built from a whole volume, slice by slice.
pub fn from_volume(kind: StoreKind, v: &Volume, budget: u64) -> Result<Box<dyn VoxelStore>> {
    let mut b = builder(kind, v.dims, budget)?;
    push_volume(b.as_mut(), v)?;
    b.finish()
}

/// Every slice of `v` into `b`, in order of z.
fn push_volume(b: &mut dyn StoreBuilder, v: &Volume) -> Result<()> {
    let n = (v.dims[0] * v.dims[1]).max(1);
    for (k, s) in v.voxels.chunks(n).enumerate().take(v.dims[2]) {
        b.push(k, s)?;
    }
    Ok(())
}

/// What turns a [`build::Pyramid`]'s result into a store.
pub trait Finish: build::Merge + Sized {
    /// The store built.
    type Store: VoxelStore + 'static;
    /// The store of a finished pyramid: its `root`, its `internal` node count and its `depth`.
    fn finish(self, root: Self::Node, internal: u64, depth: u32) -> Result<Self::Store>;
}

/// Voxel slices in order of z made cell layers (§3.1.1.5): what every builder does with a
/// slice before its store takes the layer.
pub struct Slices {
    cells: cell::CellLayers,
    width: usize,
    next: usize,
    depth: u32,
}

impl Slices {
    /// Slices `width` voxels wide for a cell grid of side 2^depth.
    pub fn new(depth: u32, width: usize) -> Slices {
        Slices {
            cells: cell::CellLayers::new(1 << depth),
            width,
            next: 0,
            depth,
        }
    }

    /// Levels below the root of the cell grid.
    pub fn depth(&self) -> u32 {
        self.depth
    }

    /// The cell layer slice `k` completes. Slices must come in order, and not past the side.
    pub fn push(&mut self, k: usize, slice: &[u8]) -> Result<&[u8]> {
        let next = self.next;
        if k != next {
            return Err(Error::SliceOrder {
                got: k,
                expected: next,
            });
        }
        if k >= 1 << self.depth {
            return Err(Error::SlicePastSide {
                slice: k,
                side: 1usize << self.depth,
            });
        }
        self.next += 1;
        Ok(self.cells.next(slice, self.width))
    }

    /// The cell layer of the next missing slice (empty) up to the side, None once every
    /// slice is in.
    pub fn pad(&mut self) -> Option<&[u8]> {
        if self.next >= 1 << self.depth {
            return None;
        }
        self.next += 1;
        Some(self.cells.next_empty())
    }
}

/// The octree builder: cell layers into a pyramid.
pub struct TreeBuilder<M: Finish> {
    slices: Slices,
    pyramid: build::Pyramid<M>,
}

/// An octree builder for a cell grid of side 2^depth from slices `width` voxels wide,
/// `merge` deciding what the store keeps.
pub fn build_tree<M: Finish>(depth: u32, width: usize, merge: M) -> TreeBuilder<M> {
    TreeBuilder {
        slices: Slices::new(depth, width),
        pyramid: build::Pyramid::new(depth, merge),
    }
}

impl<M: Finish> StoreBuilder for TreeBuilder<M> {
    fn push(&mut self, k: usize, slice: &[u8]) -> Result<()> {
        let layer = self.slices.push(k, slice)?;
        self.pyramid.push_cells(layer)
    }

    fn finish(self: Box<Self>) -> Result<Box<dyn VoxelStore>> {
        Ok(Box::new(self.finish_store()?))
    }
}

impl<M: Finish> TreeBuilder<M> {
    /// The store itself (not boxed), once every slice is in.
    pub fn finish_store(mut self) -> Result<M::Store> {
        while let Some(layer) = self.slices.pad() {
            self.pyramid.push_cells(layer)?;
        }
        let (merge, root, internal) = self.pyramid.finish()?;
        merge.finish(root, internal, self.slices.depth())
    }

    /// The store of a whole volume, slice by slice.
    pub fn store_of(mut self, v: &Volume) -> Result<M::Store> {
        push_volume(&mut self, v)?;
        self.finish_store()
    }
}

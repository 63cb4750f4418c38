#![warn(missing_docs)]

//! csgpix voxel volumes as OME-Zarr 0.5 stores (Zarr v3), written out of core: one chunk row
//! (the slabs of one chunk along Z, every chunk across X and Y) at a time, so a run holds a
//! chunk row and the voxelizer's batch, never the whole volume (docs/zarr.md).
//!
//! # Layout
//!
//! ```text
//! OUT.zarr/zarr.json        group: "ome" (OME-Zarr 0.5 multiscales, a dataset per level), "csgpix"
//! OUT.zarr/L/zarr.json      level L's array: uint8, shape (nz, ny, nx) halved L times (ceil),
//!                           fill 0; shards of S×S chunks (sharding_indexed, inner gzip)
//! OUT.zarr/L/c/R/SJ/SI      shard (R, SJ, SI) of chunk row R; absent when all 0
//! ```
//!
//! Level 0 is the grid; level L ([`plan`]) halves every axis of level L−1, rounding up, each
//! voxel the [`label_of`] its ≤ 8 voxels there (the most frequent non-zero value, ties to the
//! smallest, 0 when all are 0). Level L's chunks are level 0's with the depth halved L times,
//! so chunk row R of level 0 makes chunk row R of every level, and a row stays a unit of
//! work whatever the levels. A shard is one chunk deep and `S` chunks a side across Y and X
//! (cut to the level); with `S` = 1 the array is unsharded, one gzip file a chunk at
//! `L/c/R/J/I`.
//!
//! The array is indexed `[k, j, i]` for voxel (i, j, k): numpy's C order of the voxelizer's
//! slices (X fastest, then Y, then Z; [`csgpix_voxel::Volume`]), so a slice k is `arr[k]`.
//! Values are those of the NRRD output (`crates/scene/src/nrrd.rs`): colour codes, 0 empty
//! (or grey levels, as the `csgpix` attribute's `values` says). OME-Zarr places voxel centres
//! at `translation + index × scale` (<https://ngff.openmicroscopy.org/0.5/#trafo-md>), so
//! `translation` is the centre of voxel (0, 0, 0) and `scale` the voxel size, Z, Y, X: the
//! NRRD file's `space origin` and `space directions`.
//!
//! # Splitting a run
//!
//! [`ZarrVolume::create`] writes the metadata; then any process can
//! [`ZarrVolume::open`] the store and [`voxelize_rows`] any range of its
//! [`chunk_rows`](ZarrVolume::chunk_rows): rows are disjoint sets of files at every level,
//! and the voxelizer gives every slab the same slice whatever range it is computed in
//! ([`csgpix_voxel::voxelize_slabs`]), so the files are byte for byte those of one run over
//! every row (tested: `tests/zarr.rs`).
//!
//! # Empty chunks
//!
//! A chunk whose voxels are all 0 (the fill value) is not written: inside a shard its index
//! entry says so, and a shard with no such chunk has no file (an existing one is removed);
//! Zarr readers read both as the fill value. Which files exist, and their bytes, therefore
//! depend only on the voxels.
//!
//! # Example
//!
//! ```
//! use csgpix_voxel::{blist::BlistEval, Grid, Route, Slicer, SlicerOptions};
//! use csgpix_zarr::{voxelize_rows, Layout, VolumeAttrs, ZarrVolume};
//! use glam::DVec3;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let scene = csgpix_openscad::parse_csg("cube(size = [8, 8, 8]);", "cube.csg")?;
//! let grid = Grid::new([16, 16, 10], DVec3::ZERO, DVec3::splat(8.0))?;
//! let dir = tempfile::tempdir()?;
//! let path = dir.path().join("cube.zarr");
//! let attrs = VolumeAttrs::new("cube.csg", "uint8 colour codes, 0 empty");
//! let layout = Layout { levels: Some(3), ..Layout::new([4, 16, 16]) };
//! let volume = ZarrVolume::create(&path, &grid, &layout, &attrs)?;
//! assert_eq!(volume.chunk_rows(), [0..4, 4..8, 8..10]);
//! assert_eq!(volume.levels()[2].dims, [4, 4, 3]);
//! assert_eq!(volume.levels()[2].chunk, [1, 4, 4]);
//!
//! // Two "tasks", each opening the store: rows 0..2, then row 2.
//! let slicer = Slicer::new(&scene, grid, SlicerOptions::default())?;
//! let eval = BlistEval::new(&scene.root);
//! let set = rtl_model::Equations::Derived.set();
//! let mut filled = 0;
//! for rows in [0..2, 2..3] {
//!     let volume = ZarrVolume::open(&path)?;
//!     let work = voxelize_rows(&slicer, Route::Intervals, set.clone(), &eval, &|| {}, &volume, rows)?;
//!     filled += work.filled;
//! }
//! assert_eq!(filled, 16 * 16 * 10);
//! assert!(path.join("0/c/2/0/0").exists()); // level 0's shard of row 2
//! assert!(path.join("2/c/2/0/0").exists()); // level 2's, made from it
//! assert_eq!(volume_files(&path), 9); // 3 rows, 3 levels, one shard each
//! # fn volume_files(p: &std::path::Path) -> usize {
//! #     (0..3).map(|l| (0..3).filter(|r| p.join(format!("{l}/c/{r}/0/0")).is_file()).count()).sum()
//! # }
//! # Ok(())
//! # }
//! ```

mod error;
pub mod pyramid;
mod shard;

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::Arc;

use csgpix_output::staged_write;
use csgpix_scene::grid::Grid;
use csgpix_voxel::runs::BrickRuns;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{PixelBox, Route, Slicer, Work};
use glam::DVec3;
use rayon::prelude::*;
use rtl_model::EquationSet;
use serde_json::{json, Value};
use zarrs::array::codec::{BytesCodec, GzipCodec, ShardingCodecBuilder};
use zarrs::array::{Array, ArrayBuilder, ArrayMetadataOptions};
use zarrs::filesystem::FilesystemStore;
use zarrs::group::{Group, GroupBuilder};

pub use error::{Error, Result, StoreProblem};
pub use pyramid::{downsample, label_of};

/// The side of a cubic chunk when none is asked for: a chunk row of a 2048² grid is then
/// 256 MiB, and a chunk 256 KiB before compression (docs/zarr.md).
pub const DEFAULT_CHUNK: usize = 64;

/// Inner chunks per shard side (Y and X) when none is asked for: with 64³ chunks a shard is
/// 64 × 4096 × 4096 voxels, and a 16384³ store 6,400 files over 7 levels (docs/zarr.md has
/// the counts). A shard is never held whole (`shard`), so its size costs no memory.
pub const DEFAULT_SHARD: usize = 64;

/// The default pyramid stops at the first level whose largest side is at most this.
pub const PYRAMID_SIDE: usize = 256;

/// gzip's level for every chunk: zlib's default. On twelve.csg at 1024³ level 1 made a store
/// 2.6× as large (6.29 MB against 2.39) in the same wall time, since writing, not
/// compressing, is what a run waits on (docs/zarr.md has the figures).
pub const GZIP_LEVEL: u32 = 6;

/// Unsharded arrays (`shard` 1): chunks of a row written at once, each on its own thread,
/// apart from rayon's so that they wait on the filesystem without holding the voxelizer's
/// workers; each holds a chunk and its gzip stream. (They once waited on the disk too, when
/// every chunk file was synced as it was written: docs/zarr.md.)
pub const WRITERS: usize = 8;

/// Bytes of a deflate stream's own state (window, hash chains, pending output) per thread
/// compressing: zlib's is about 268 KiB at level 6; counted at twice that.
const DEFLATE_STATE: u64 = 512 << 10;

/// What the `csgpix` attribute says of a volume besides its grid.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VolumeAttrs {
    /// Where the volume comes from: the command line, as the NRRD comment has it.
    pub comment: String,
    /// What the voxel values mean (e.g. `uint8 colour codes, 0 empty`).
    pub values: String,
}

impl VolumeAttrs {
    /// Attributes from their two texts.
    pub fn new(comment: impl Into<String>, values: impl Into<String>) -> VolumeAttrs {
        VolumeAttrs {
            comment: comment.into(),
            values: values.into(),
        }
    }
}

/// How a store is cut: chunks, shards and pyramid levels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The chunk (a shard's inner chunk) of level 0, Z, Y, X, before [`chunk_shape`] cuts
    /// it to the grid.
    pub chunk: [usize; 3],
    /// Inner chunks per shard side across Y and X (a shard is one chunk deep); 1 writes no
    /// shards, one file per chunk.
    pub shard: usize,
    /// Multiscale levels, level 0 the grid itself; None: [`default_levels`], within what the
    /// chunk depth allows ([`max_levels`]).
    pub levels: Option<usize>,
}

impl Layout {
    /// Chunks `chunk`, shards of [`DEFAULT_SHARD`] chunks a side, the default levels.
    pub fn new(chunk: [usize; 3]) -> Layout {
        Layout {
            chunk,
            shard: DEFAULT_SHARD,
            levels: None,
        }
    }
}

impl Default for Layout {
    fn default() -> Layout {
        Layout::new([DEFAULT_CHUNK; 3])
    }
}

/// A run's chunks by what they hold ([`ZarrVolume::chunks_held`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ChunksHeld {
    /// All 0: skipped.
    pub empty: u64,
    /// One non-zero value throughout.
    pub uniform: u64,
    /// Anything else.
    pub mixed: u64,
}

/// One level of the pyramid as written: the array at `OUT.zarr/L`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Level {
    /// Voxels along X, Y and Z: level 0's halved `l` times, rounding up.
    pub dims: [usize; 3],
    /// The chunk (inner chunk when sharded), Z, Y, X: level 0's depth halved `l` times, so
    /// that every chunk row of level 0 makes exactly one of this level.
    pub chunk: [usize; 3],
    /// The shard, Z, Y, X (a whole number of chunks), or None when unsharded.
    pub shard: Option<[usize; 3]>,
}

impl Level {
    /// The array's chunk grid unit: the shard, or the chunk when unsharded.
    pub fn grid_unit(&self) -> [usize; 3] {
        self.shard.unwrap_or(self.chunk)
    }

    /// Files a chunk row of this level can have: shards (or chunks) across Y times across X.
    pub fn files_per_row(&self) -> usize {
        let [nx, ny, _] = self.dims;
        let [_, uy, ux] = self.grid_unit();
        ny.div_ceil(uy) * nx.div_ceil(ux)
    }
}

/// The chunk shape a store of `dims` (X, Y, Z) gets for `chunk` (Z, Y, X): each side at most
/// the grid's, so that a small grid is not padded out to a large chunk.
pub fn chunk_shape(dims: [usize; 3], chunk: [usize; 3]) -> Result<[usize; 3]> {
    if chunk.contains(&0) {
        return Err(Error::BadChunk { chunk });
    }
    let [nx, ny, nz] = dims;
    Ok([chunk[0].min(nz), chunk[1].min(ny), chunk[2].min(nx)])
}

/// Levels the default pyramid has on `dims`: level 0, then one more per halving until the
/// largest side is at most [`PYRAMID_SIDE`] (384³: 2 levels, 4096³: 5, 16384³: 7).
pub fn default_levels(dims: [usize; 3]) -> usize {
    let mut side = dims.into_iter().max().unwrap_or(1);
    let mut levels = 1;
    while side > PYRAMID_SIDE {
        side = side.div_ceil(2);
        levels += 1;
    }
    levels
}

/// The most levels a store of `dims` with chunks `chunk` (cut, Z first) can have: each
/// chunk row of level 0 makes one chunk row of every level, so when the grid has more than
/// one row the chunk depth must halve exactly, 2^(levels-1) dividing it (64: at most 7
/// levels); and no level past the first that is 1×1×1.
pub fn max_levels(dims: [usize; 3], chunk: [usize; 3]) -> usize {
    let mut side = dims.into_iter().max().unwrap_or(1);
    let mut levels = 1;
    while side > 1 {
        side = side.div_ceil(2);
        levels += 1;
    }
    let cz = chunk[0];
    if dims[2] > cz {
        levels = levels.min(1 + cz.trailing_zeros() as usize);
    }
    levels
}

/// The levels of a store of `dims` cut by `layout`.
pub fn plan(dims: [usize; 3], layout: &Layout) -> Result<Vec<Level>> {
    let chunk = chunk_shape(dims, layout.chunk)?;
    if layout.shard == 0 {
        return Err(Error::BadShard);
    }
    let max = max_levels(dims, chunk);
    let levels = match layout.levels {
        None => default_levels(dims).min(max),
        Some(l) if (1..=max).contains(&l) => l,
        Some(l) => {
            return Err(Error::BadLevels {
                levels: l,
                max,
                depth: chunk[0],
            })
        }
    };
    let [cz, cy, cx] = chunk;
    Ok((0..levels)
        .map(|l| {
            let dims = dims.map(|d| d.div_ceil(1 << l));
            let [nx, ny, _] = dims;
            let chunk = [cz.div_ceil(1 << l), cy.min(ny), cx.min(nx)];
            // Level l's shard is `shard >> l` chunks a side (at least 1), so that while the
            // chunk's sides stay, every level's shard covers the scene a level-0 shard does:
            // a brick of level-0 shards makes whole files at every level ([`tile`]).
            let per = (layout.shard >> l).max(1);
            let shard = (layout.shard > 1).then(|| {
                let across = |n: usize, c: usize| per.min(n.div_ceil(c)) * c;
                [chunk[0], across(ny, chunk[1]), across(nx, chunk[2])]
            });
            Level { dims, chunk, shard }
        })
        .collect())
}

/// The XY tile (level-0 voxels along X, then Y) of a brick: the least side that every
/// level's file (its shard, or chunk when unsharded), scaled back to level 0, divides, so a
/// brick of rows × tile makes whole files at every level and its downsampled levels start on
/// even voxels; the grid's side when that is larger. Tiles start at multiples of it.
pub fn tile(dims: [usize; 3], levels: &[Level]) -> [usize; 2] {
    let side = |axis: usize, n: usize| {
        let t = levels.iter().enumerate().fold(1usize, |t, (l, v)| {
            lcm(t, v.grid_unit()[axis].saturating_mul(1 << l))
        });
        t.min(n).max(1)
    };
    [side(2, dims[0]), side(1, dims[1])]
}

/// The tiles of a grid of `dims` cut every `tile` columns (X, Y), row-major: the columns of
/// each brick.
pub fn tile_boxes(dims: [usize; 3], [tx, ty]: [usize; 2]) -> Vec<PixelBox> {
    let [nx, ny, _] = dims;
    let (tx, ty) = (tx.max(1), ty.max(1));
    (0..ny.div_ceil(ty))
        .flat_map(|j| {
            (0..nx.div_ceil(tx)).map(move |i| {
                PixelBox::new(
                    i * tx,
                    j * ty,
                    ((i + 1) * tx).min(nx),
                    ((j + 1) * ty).min(ny),
                )
            })
        })
        .collect()
}

fn lcm(a: usize, b: usize) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    (a / gcd(a, b)).saturating_mul(b)
}

/// Bytes of chunk row slices a run holds per level: level 0's row (buffered by
/// [`voxelize_rows`]) and each coarser level's, made from it; of `xy` columns (X, Y) of
/// level 0 when a brick's.
fn rows_bytes(levels: &[Level], xy: Option<[usize; 2]>) -> u64 {
    levels
        .iter()
        .enumerate()
        .map(|(l, v)| {
            let [mut nx, mut ny, nz] = v.dims;
            if let Some([tx, ty]) = xy {
                (nx, ny) = (nx.min(tx.div_ceil(1 << l)), ny.min(ty.div_ceil(1 << l)));
            }
            (v.chunk[0].min(nz) as u64)
                .saturating_mul(ny as u64)
                .saturating_mul(nx as u64)
        })
        .fold(0u64, u64::saturating_add)
}

/// Bytes a run over a store of `layout` on `threads` threads holds besides the voxelizer's
/// own: one chunk row of slices per level, and while a row is written, the larger of
/// - sharded: per thread a chunk copied out of the row and its deflate state, and a batch
///   (`BATCH_PER_THREAD` per thread) of compressed chunks, each
///   at most zlib's bound; with a shard's index;
/// - unsharded: per writer ([`WRITERS`]) a chunk copied out of the row and its gzip stream
///   (at most the chunk and zlib's bound) and deflate state.
///
/// Level 0's chunk is the largest, and levels are written one after another.
pub fn writer_bytes(dims: [usize; 3], layout: &Layout, threads: usize) -> Result<u64> {
    writer_bytes_over(dims, layout, threads, false)
}

/// [`writer_bytes`] of a run by bricks ([`voxelize_bricks`]): a brick's rows, not a row's.
pub fn writer_bytes_bricks(dims: [usize; 3], layout: &Layout, threads: usize) -> Result<u64> {
    writer_bytes_over(dims, layout, threads, true)
}

fn writer_bytes_over(
    dims: [usize; 3],
    layout: &Layout,
    threads: usize,
    bricks: bool,
) -> Result<u64> {
    let levels = plan(dims, layout)?;
    let rows = rows_bytes(&levels, bricks.then(|| tile(dims, &levels)));
    let [cz, cy, cx] = levels[0].chunk.map(|c| c as u64);
    let chunk = cz.saturating_mul(cy).saturating_mul(cx);
    let bound = shard::gzip_bound(chunk);
    let threads = threads.max(1) as u64;
    let writing = match levels[0].shard {
        Some([_, sy, sx]) => {
            let index = ((sy / levels[0].chunk[1]) * (sx / levels[0].chunk[2])) as u64 * 16;
            let batch = shard::BATCH_PER_THREAD as u64 * threads;
            threads
                .saturating_mul(chunk.saturating_add(DEFLATE_STATE))
                .saturating_add(batch.saturating_mul(bound))
                .saturating_add(index.saturating_mul(2))
        }
        None => (WRITERS as u64)
            .saturating_mul(chunk.saturating_add(bound).saturating_add(DEFLATE_STATE)),
    };
    Ok(rows.saturating_add(writing))
}

/// An upper bound of the memory of a run into a store of `layout` (docs/memory.md): the
/// voxelizer's without a volume ([`csgpix_voxel::memory_estimate_rows`]) and
/// [`writer_bytes`].
pub fn memory_estimate(grid: &Grid, layout: &Layout, prims: usize, threads: usize) -> Result<u64> {
    let held = writer_bytes(grid.dims, layout, threads)?;
    Ok(csgpix_voxel::memory_estimate_rows(
        grid, prims, threads, held,
    ))
}

/// A level's array and what this process wrote into it.
struct LevelArray {
    level: Level,
    array: Array<FilesystemStore>,
    /// Shard (or chunk) files written by this `ZarrVolume`.
    written: AtomicU64,
}

/// A csgpix volume in a Zarr v3 store on the filesystem: the group, and a uint8 array per
/// level of its pyramid at `0`, `1`, …, shape (nz, ny, nx) halved per level, written a chunk
/// row at a time.
pub struct ZarrVolume {
    path: PathBuf,
    grid: Grid,
    /// Inner chunks per shard side (1: unsharded).
    shard: usize,
    levels: Vec<LevelArray>,
    /// Chunks of one value, compressed once.
    uniform: shard::UniformChunks,
}

impl std::fmt::Debug for ZarrVolume {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ZarrVolume")
            .field("path", &self.path)
            .field("grid", &self.grid)
            .field("shard", &self.shard)
            .field("levels", &self.levels())
            .finish()
    }
}

// A binding holds a store across threads (a Python class must be `Send`), and rows are
// written from several: checked when the crate compiles.
const _: fn() = || {
    fn shared<T: Send + Sync>() {}
    shared::<ZarrVolume>();
    shared::<Error>();
};

fn store_err(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> Error + '_ {
    move |e| Error::Store {
        path: path.to_path_buf(),
        message: StoreProblem::Zarrs(e.to_string()),
    }
}

/// The system's error on the store at `path`.
fn io_err(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |e| Error::Store {
        path: path.to_path_buf(),
        message: StoreProblem::Io(e.into()),
    }
}

/// X, Y, Z as Z, Y, X.
fn zyx(v: DVec3) -> [f64; 3] {
    [v.z, v.y, v.x]
}

/// The group's attributes: OME-Zarr 0.5's `ome` (<https://ngff.openmicroscopy.org/0.5/>,
/// "multiscales": axes, one dataset per level with exactly one scale then one translation)
/// and ours. Level l's voxel is 2^l of level 0's along each axis, and its voxel 0 covers
/// level 0's voxels 0..2^l: its centre is `(2^l − 1)/2` voxels of level 0 past theirs.
/// Keys are written in this order (serde_json keeps insertion order under zarrs), so the
/// bytes of `zarr.json` depend on the grid, the layout and the texts alone.
fn group_attributes(
    grid: &Grid,
    chunk: [usize; 3],
    shard: usize,
    levels: usize,
    attrs: &VolumeAttrs,
) -> serde_json::Map<String, Value> {
    let axis = |name: &str| json!({"name": name, "type": "space"});
    let origin = grid.centre(0, 0, 0);
    let spacing = grid.voxel();
    let datasets: Vec<Value> = (0..levels)
        .map(|l| {
            let f = (1u64 << l) as f64;
            json!({
                "path": l.to_string(),
                "coordinateTransformations": [
                    {"type": "scale", "scale": zyx(spacing * f)},
                    {"type": "translation", "translation": zyx(origin + spacing * ((f - 1.0) / 2.0))},
                ],
            })
        })
        .collect();
    let ome = json!({
        "version": "0.5",
        "multiscales": [{
            "name": "csgpix",
            "axes": [axis("z"), axis("y"), axis("x")],
            "datasets": datasets,
        }],
    });
    let ours = json!({
        "dims": grid.dims,
        "origin": origin.to_array(),
        "spacing": spacing.to_array(),
        "min": grid.min.to_array(),
        "max": grid.max.to_array(),
        "axes": "x, y, z above; the array is indexed [k, j, i] for voxel (i, j, k)",
        "comment": attrs.comment,
        "values": attrs.values,
        "chunk": chunk,
        "shard": shard,
        "levels": levels,
    });
    let mut m = serde_json::Map::new();
    m.insert("ome".into(), ome);
    m.insert("csgpix".into(), ours);
    m
}

/// Metadata without zarrs's own `_zarrs` attribute (its version): the bytes then depend on
/// the volume alone, not on the library that wrote them.
fn metadata_options() -> ArrayMetadataOptions {
    ArrayMetadataOptions::default().with_include_zarrs_metadata(false)
}

/// The layout the `csgpix` attribute `ours` records (chunk, shard and levels), or for a store
/// written before shards and levels, one level whose chunks are those of its array.
fn stored_layout(
    ours: &Value,
    store: &Arc<FilesystemStore>,
    bad: &dyn Fn(String) -> Error,
) -> Result<Layout> {
    let field = |key: &str| -> Result<Option<Value>> { Ok(ours.get(key).cloned()) };
    Ok(match (field("chunk")?, field("shard")?, field("levels")?) {
        (Some(c), Some(s), Some(l)) => {
            let parse = |v: Value, what: &str| bad(format!("attribute `csgpix`: `{what}`: {v}"));
            Layout {
                chunk: serde_json::from_value(c.clone()).map_err(|_| parse(c, "chunk"))?,
                shard: serde_json::from_value(s.clone()).map_err(|_| parse(s, "shard"))?,
                levels: Some(serde_json::from_value(l.clone()).map_err(|_| parse(l, "levels"))?),
            }
        }
        _ => {
            // Before shards and levels: one level, its chunks those of the array.
            let array =
                Array::open(store.clone(), &format!("/{}", 0)).map_err(|e| bad(e.to_string()))?;
            let chunk = array
                .chunk_shape_usize(&[0, 0, 0])
                .map_err(|e| bad(e.to_string()))?;
            Layout {
                chunk: chunk
                    .try_into()
                    .map_err(|_| bad("the array is not 3D".into()))?,
                shard: 1,
                levels: Some(1),
            }
        }
    })
}

/// Level `l`'s array in the store, checked against its `level` of the plan: its shape,
/// uint8 samples, and the chunks (or shards) and inner chunks the layout makes.
fn open_level(
    store: &Arc<FilesystemStore>,
    l: usize,
    level: Level,
    bad: &dyn Fn(String) -> Error,
) -> Result<LevelArray> {
    let bad = |what: String| bad(format!("level {l}: {what}"));
    let array = Array::open(store.clone(), &format!("/{l}")).map_err(|e| bad(e.to_string()))?;
    let [nx, ny, nz] = level.dims.map(|d| d as u64);
    if array.shape() != [nz, ny, nx] {
        return Err(bad(format!(
            "array shape {:?} is not (nz, ny, nx) of dims {:?}",
            array.shape(),
            level.dims
        )));
    }
    if array.data_type() != &zarrs::array::data_type::uint8() {
        return Err(bad("the array is not uint8".into()));
    }
    // Chunks (or shards) and inner chunks as the attribute's layout makes them.
    let want = array_builder(&level)
        .build_metadata()
        .map_err(|e| bad(e.to_string()))?;
    let have = serde_json::to_value(array.metadata()).map_err(|e| bad(e.to_string()))?;
    let want = serde_json::to_value(want).map_err(|e| bad(e.to_string()))?;
    for key in ["chunk_grid", "codecs"] {
        if have[key] != want[key] {
            return Err(bad(format!(
                "`{key}` is {}, not {} as the `csgpix` attribute's layout makes it",
                have[key], want[key]
            )));
        }
    }
    Ok(LevelArray {
        level,
        array,
        written: AtomicU64::new(0),
    })
}

/// The array of `level`: uint8, fill 0, dimension names z, y, x; gzip at [`GZIP_LEVEL`],
/// inside the `sharding_indexed` codec when sharded (index at the end, `bytes`
/// little-endian, no checksum).
fn array_builder(level: &Level) -> ArrayBuilder {
    let [nx, ny, nz] = level.dims.map(|d| d as u64);
    let u64s = |s: [usize; 3]| s.map(|c| c as u64).to_vec();
    let gzip = Arc::new(GzipCodec::new(GZIP_LEVEL).expect("GZIP_LEVEL is a gzip level (0 to 9)"));
    let uint8 = zarrs::array::data_type::uint8();
    let mut b = ArrayBuilder::new(
        vec![nz, ny, nx],
        u64s(level.grid_unit()),
        uint8.clone(),
        0u8,
    );
    match level.shard {
        Some(_) => {
            let inner = level
                .chunk
                .map(|c| std::num::NonZeroU64::new(c as u64).expect("chunk sides are > 0"))
                .to_vec();
            let sharding = ShardingCodecBuilder::new(inner, &uint8)
                .bytes_to_bytes_codecs(vec![gzip])
                .index_array_to_bytes_codec(Arc::new(BytesCodec::little()))
                .index_bytes_to_bytes_codecs(vec![])
                .build_arc();
            b.array_to_bytes_codec(sharding);
        }
        None => {
            b.bytes_to_bytes_codecs(vec![gzip]);
        }
    }
    b.dimension_names(Some(["z", "y", "x"]));
    b
}

impl ZarrVolume {
    /// Write the metadata of a volume on `grid` at `path` (a new or empty directory): the
    /// group's `zarr.json` with its OME-Zarr 0.5 and `csgpix` attributes, and each level's
    /// array at `path/L` ([`plan`]: uint8, shape (nz, ny, nx) halved per level, chunks
    /// `layout.chunk` (Z, Y, X) cut to the grid, in shards of `layout.shard` chunks a side,
    /// fill 0, gzip at [`GZIP_LEVEL`], dimension names z, y, x). No chunk is written: a
    /// volume nobody voxelizes reads as all 0.
    pub fn create(
        path: &Path,
        grid: &Grid,
        layout: &Layout,
        attrs: &VolumeAttrs,
    ) -> Result<ZarrVolume> {
        let levels = plan(grid.dims, layout)?;
        let err = store_err(path);
        let _writing = staged_write().ok_or(Error::Interrupted)?;
        match std::fs::read_dir(path) {
            Ok(entries) => {
                if entries.count() > 0 {
                    return Err(Error::NotEmpty { path: path.into() });
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                std::fs::create_dir_all(path).map_err(io_err(path))?
            }
            Err(_) if path.exists() => return Err(Error::NotEmpty { path: path.into() }),
            Err(e) => return Err(io_err(path)(e)),
        }
        let store = Arc::new(FilesystemStore::new(path).map_err(|e| err(&e))?);
        let group = GroupBuilder::new()
            .attributes(group_attributes(
                grid,
                levels[0].chunk,
                layout.shard,
                levels.len(),
                attrs,
            ))
            .build(store.clone(), "/")
            .map_err(|e| err(&e))?;
        group.store_metadata().map_err(|e| err(&e))?;
        let mut arrays = vec![];
        for (l, level) in levels.into_iter().enumerate() {
            let array = array_builder(&level)
                .build(store.clone(), &format!("/{l}"))
                .map_err(|e| err(&e))?;
            array
                .store_metadata_opt(&metadata_options())
                .map_err(|e| err(&e))?;
            arrays.push(LevelArray {
                level,
                array,
                written: AtomicU64::new(0),
            });
        }
        Ok(ZarrVolume {
            path: path.into(),
            grid: *grid,
            shard: layout.shard,
            levels: arrays,
            uniform: Default::default(),
        })
    }

    /// Open a volume [`create`](ZarrVolume::create) wrote (by this process or another): its
    /// grid and layout from the `csgpix` attribute, each level's array checked against them.
    /// A store of one unsharded level from before shards and levels (no `chunk`, `shard` or
    /// `levels` in the attribute) opens with its array's chunks.
    pub fn open(path: &Path) -> Result<ZarrVolume> {
        let err = store_err(path);
        let bad = |reason: String| Error::NotAVolume {
            path: path.into(),
            reason,
        };
        if !path.join("zarr.json").is_file() {
            return Err(bad("no zarr.json".into()));
        }
        let store = Arc::new(FilesystemStore::new(path).map_err(|e| err(&e))?);
        let group = Group::open(store.clone(), "/").map_err(|e| bad(e.to_string()))?;
        let ours = group
            .attributes()
            .get("csgpix")
            .ok_or_else(|| bad("no `csgpix` attribute".into()))?;
        let grid = grid_of(ours).map_err(|e| bad(format!("attribute `csgpix`: {e}")))?;
        let layout = stored_layout(ours, &store, &bad)?;
        let levels = plan(grid.dims, &layout).map_err(|e| bad(e.to_string()))?;
        let mut arrays = vec![];
        for (l, level) in levels.into_iter().enumerate() {
            arrays.push(open_level(&store, l, level, &bad)?);
        }
        Ok(ZarrVolume {
            path: path.into(),
            grid,
            shard: layout.shard,
            levels: arrays,
            uniform: Default::default(),
        })
    }

    /// The store's directory.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The grid the volume was created on.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Voxels along X, Y and Z.
    pub fn dims(&self) -> [usize; 3] {
        self.grid.dims
    }

    /// Level 0's chunk shape (a shard's inner chunk when sharded), Z, Y, X.
    pub fn chunk(&self) -> [usize; 3] {
        self.levels[0].level.chunk
    }

    /// Inner chunks per shard side (1: unsharded).
    pub fn shard(&self) -> usize {
        self.shard
    }

    /// The pyramid's levels, level 0 first.
    pub fn levels(&self) -> Vec<Level> {
        self.levels.iter().map(|v| v.level).collect()
    }

    /// The layout the store was created with (its levels given).
    pub fn layout(&self) -> Layout {
        Layout {
            chunk: self.chunk(),
            shard: self.shard,
            levels: Some(self.levels.len()),
        }
    }

    /// Shard files (chunk files when unsharded) this value has written, per level.
    pub fn files_written(&self) -> Vec<u64> {
        self.levels
            .iter()
            .map(|v| v.written.load(Ordering::Relaxed))
            .collect()
    }

    /// Chunks (inner chunks when sharded) of every level this value has been given, by what
    /// they hold: all 0 (skipped: no bytes), one non-zero value throughout (compressed once
    /// per value), anything else (compressed).
    pub fn chunks_held(&self) -> ChunksHeld {
        let [empty, uniform, mixed] = self
            .uniform
            .counts
            .each_ref()
            .map(|c| c.load(Ordering::Relaxed));
        ChunksHeld {
            empty,
            uniform,
            mixed,
        }
    }

    /// The slabs (k ranges) of each chunk row of level 0, in order: `cz` slabs each, the
    /// last fewer when `cz` does not divide nz. Row r of every coarser level is made from
    /// row r of level 0.
    pub fn chunk_rows(&self) -> Vec<Range<usize>> {
        let (nz, cz) = (self.grid.dims[2], self.chunk()[0]);
        (0..nz).step_by(cz).map(|a| a..(a + cz).min(nz)).collect()
    }

    /// Bytes of the largest chunk row's slices (what [`voxelize_rows`] buffers).
    pub fn row_bytes(&self) -> usize {
        let [nx, ny, nz] = self.grid.dims;
        self.chunk()[0].min(nz) * ny * nx
    }

    /// Level `l`'s whole array as zarrs reads it, C order (nz, ny, nx) of the level: for
    /// tests and small stores.
    pub fn read_level(&self, l: usize) -> Result<Vec<u8>> {
        let a = &self
            .levels
            .get(l)
            .ok_or(Error::LevelRange {
                level: l,
                levels: self.levels.len(),
            })?
            .array;
        a.retrieve_array_subset(&a.subset_all())
            .map_err(|e| store_err(&self.path)(&e))
    }

    /// Store chunk row `row` of every level: `slices` are level 0's slabs' slices in order
    /// of k, each nx × ny bytes, X fastest then Y (the voxelizer's); each coarser level's
    /// row is [`downsample`]d from the level below's. Each shard (or chunk) with a non-zero
    /// voxel is written; one all 0 is not, and a file left for it by an earlier write is
    /// removed. On an error the first one is returned, and files of the row may be written
    /// or not. The files are not synced to the disk: [`sync`](Self::sync) does it once for
    /// the store ([`voxelize_rows`] and [`voxelize_bricks`] do at their end).
    pub fn write_row(&self, row: usize, slices: &[u8]) -> Result<()> {
        let [nx, ny, _] = self.grid.dims;
        self.write_brick(row, PixelBox::new(0, 0, nx, ny), slices, None)
    }

    /// The XY tile of a brick ([`tile`]): a brick is a chunk row's columns of one tile.
    pub fn tile(&self) -> [usize; 2] {
        let levels: Vec<Level> = self.levels.iter().map(|v| v.level).collect();
        tile(self.grid.dims, &levels)
    }

    /// The tiles of the grid, row-major: the columns of each brick ([`tile_boxes`]).
    pub fn tiles(&self) -> Vec<PixelBox> {
        tile_boxes(self.grid.dims, self.tile())
    }

    /// Store the brick of chunk row `row` and the tile `columns` (one of [`tiles`](Self::tiles),
    /// or the whole grid) at every level, as [`write_row`](Self::write_row) stores a row:
    /// `slices` are the brick's slices, each `columns`' width × height. `known` says, where
    /// the caller knows it (from the runs), which of the brick's level-0 chunks hold one
    /// value throughout (row-major over the brick's chunks; see `RowCut`):
    /// those are written without looking at their voxels. The files depend on the voxels
    /// alone, so bricks written in any order, by any process, make the row's files.
    pub fn write_brick(
        &self,
        row: usize,
        columns: PixelBox,
        slices: &[u8],
        known: Option<&[Option<u8>]>,
    ) -> Result<()> {
        let slabs = self.brick_slabs(row, columns, slices.len())?;
        let [w, h] = [columns.width(), columns.height()];
        self.write_level_brick(0, row, columns, [w, h, slabs], slices, known)?;
        let mut below: Option<Vec<u8>> = None;
        let mut size = [w, h, slabs];
        for l in 1..self.levels.len() {
            let next = downsample(below.as_deref().unwrap_or(slices), size);
            size = size.map(|d| d.div_ceil(2));
            let b = PixelBox::new(
                columns.x0 >> l,
                columns.y0 >> l,
                (columns.x0 >> l) + size[0],
                (columns.y0 >> l) + size[1],
            );
            let known = known.map(|k| self.coarsen(k, columns, l));
            self.write_level_brick(l, row, b, size, &next, known.as_deref())?;
            below = Some(next);
        }
        Ok(())
    }

    /// Put every file of the store on the disk: once when the rows are written, not once
    /// per file (a store of small chunks is tens of thousands of files, and a `fsync` each
    /// took most of the run: docs/zarr.md). A store written in several calls by several
    /// processes is durable once each has synced after its last write.
    pub fn sync(&self) -> Result<()> {
        csgpix_output::sync_tree(&self.path).map_err(io_err(&self.path))
    }

    /// The slabs of row `row`, checking that `columns` is a brick and `len` its bytes.
    fn brick_slabs(&self, row: usize, columns: PixelBox, len: usize) -> Result<usize> {
        let rows = self.chunk_rows();
        let slabs = rows
            .get(row)
            .ok_or(Error::RowRange {
                row,
                rows: rows.len(),
            })?
            .len();
        let [nx, ny, _] = self.grid.dims;
        let [tx, ty] = self.tile();
        let whole = PixelBox::new(0, 0, nx, ny);
        let on_tile = columns.x0.is_multiple_of(tx)
            && columns.y0.is_multiple_of(ty)
            && columns.x1 == (columns.x0 + tx).min(nx)
            && columns.y1 == (columns.y0 + ty).min(ny);
        if columns != whole && !on_tile {
            return Err(Error::BadBrick {
                columns: format!("{columns:?}"),
                tile: [tx, ty],
            });
        }
        let (w, h) = (columns.width(), columns.height());
        if len != slabs * w * h {
            return Err(Error::RowLength {
                row,
                expected: slabs * w * h,
                got: len,
                slabs,
                nx: w,
                ny: h,
            });
        }
        Ok(slabs)
    }

    /// What level `l`'s chunks of the brick on `columns` hold, from its level-0 chunks'
    /// `known`: one value where every level-0 chunk it covers is known to hold that value.
    fn coarsen(&self, known: &[Option<u8>], columns: PixelBox, l: usize) -> Vec<Option<u8>> {
        let [_, cy0, cx0] = self.levels[0].level.chunk;
        let [_, cy, cx] = self.levels[l].level.chunk;
        let across0 = columns.width().div_ceil(cx0);
        let (w, h) = (columns.width(), columns.height());
        let (wl, hl) = (w.div_ceil(1 << l), h.div_ceil(1 << l));
        let mut out = vec![];
        for bj in 0..hl.div_ceil(cy) {
            for bi in 0..wl.div_ceil(cx) {
                // Level-0 voxels of the chunk, within the brick, then its level-0 chunks.
                let ys = (bj * cy) << l..(((bj + 1) * cy) << l).min(h);
                let xs = (bi * cx) << l..(((bi + 1) * cx) << l).min(w);
                let mut values = (ys.start / cy0..ys.end.div_ceil(cy0)).flat_map(|j| {
                    (xs.start / cx0..xs.end.div_ceil(cx0)).map(move |i| known[j * across0 + i])
                });
                let first = values.next().flatten();
                out.push(first.filter(|&v| values.all(|u| u == Some(v))));
            }
        }
        out
    }

    /// Level `l`'s part of a brick: the tile `b` of the level, `size` its voxels (X, Y,
    /// slabs).
    #[allow(clippy::too_many_arguments)]
    fn write_level_brick(
        &self,
        l: usize,
        row: usize,
        b: PixelBox,
        size: [usize; 3],
        slices: &[u8],
        known: Option<&[Option<u8>]>,
    ) -> Result<()> {
        let v = &self.levels[l];
        let [_, cy, cx] = v.level.chunk;
        let cut = shard::RowCut {
            slices,
            nx: size[0],
            ny: size[1],
            slabs: size[2],
            chunk: v.level.chunk,
            at: [b.y0 / cy, b.x0 / cx],
            known,
        };
        let written = match v.level.shard {
            Some([_, sy, sx]) => {
                let per = [sy / cy, sx / cx];
                let dir = self.path.join(l.to_string());
                shard::write_row(&dir, row, &cut, per, &self.uniform)?
            }
            None => self.write_chunks(l, row, &cut)?,
        };
        v.written.fetch_add(written, Ordering::Relaxed);
        Ok(())
    }

    /// Level `l`'s row when unsharded, one chunk file each, [`WRITERS`] at a time: gzipped
    /// as zarrs's gzip codec does (one value's chunks compressed once a run), at zarrs's key
    /// `L/c/K/J/I`. Written here, not by zarrs's store, which syncs every file it writes.
    fn write_chunks(&self, l: usize, row: usize, cut: &shard::RowCut) -> Result<u64> {
        let (down, across) = cut.grid();
        let chunks = down * across;
        let written = AtomicU64::new(0);
        let dir = self.path.join(l.to_string());
        let write = |c: usize| -> Result<()> {
            let (bj, bi) = (c / across, c % across);
            let (j, i) = (cut.at[0] + bj, cut.at[1] + bi);
            let path = dir.join(format!("c/{row}/{j}/{i}"));
            let packed = self.uniform.pack(cut, bj, bi).map_err(io_err(&path))?;
            match packed {
                Some(bytes) => {
                    written.fetch_add(1, Ordering::Relaxed);
                    shard::write_file(&path, &bytes)
                }
                None => shard::remove_stale(&path),
            }
        };
        // WRITERS threads take the row's chunks in turn, this one among them (a brick of a
        // few chunks spawns no thread); the first error stops them all.
        let (next, failed) = (AtomicUsize::new(0), AtomicBool::new(false));
        let writer = || -> Result<()> {
            loop {
                let c = next.fetch_add(1, Ordering::Relaxed);
                if c >= chunks || failed.load(Ordering::Relaxed) {
                    return Ok(());
                }
                write(c).inspect_err(|_| failed.store(true, Ordering::Relaxed))?;
            }
        };
        std::thread::scope(|scope| {
            let writers: Vec<_> = (1..WRITERS.min(chunks))
                .map(|_| scope.spawn(writer))
                .collect();
            let mut first = writer();
            for w in writers {
                let r = w.join().unwrap_or(Err(Error::Panicked {
                    thread: "a chunk writer",
                }));
                first = first.and(r);
            }
            first
        })?;
        Ok(written.into_inner())
    }
}

/// The grid the `csgpix` attribute describes.
fn grid_of(v: &Value) -> csgpix_scene::Result<Grid> {
    let field = |key: &str, e: serde_json::Error| {
        csgpix_scene::Error::invalid(e.to_string()).context(format_args!("`{key}`"))
    };
    let dims: [usize; 3] =
        serde_json::from_value(v["dims"].clone()).map_err(|e| field("dims", e))?;
    let corner = |key: &str| -> csgpix_scene::Result<DVec3> {
        let a: [f64; 3] = serde_json::from_value(v[key].clone()).map_err(|e| field(key, e))?;
        Ok(DVec3::from_array(a))
    };
    Grid::new(dims, corner("min")?, corner("max")?)
}

/// A grid in words, for [`Error::GridMismatch`].
fn grid_text(g: &Grid) -> String {
    let [nx, ny, nz] = g.dims;
    format!("{nx}x{ny}x{nz} over {} .. {}", g.min, g.max)
}

/// Voxelize chunk rows `rows` of `volume` (indices into [`ZarrVolume::chunk_rows`]) and
/// store them: [`csgpix_voxel::voxelize_slabs`] over their slabs, one chunk row buffered at a
/// time and written ([`ZarrVolume::write_row`]) as soon as its last slice arrives. Memory is
/// one chunk row and the voxelizer's batch, whatever the grid's depth ([`memory_estimate`]).
/// The returned [`Work`] counts these rows' slabs alone; runs over disjoint row ranges sum to
/// the run over all of them. The slicer's grid must be the volume's (dims and box, exactly).
pub fn voxelize_rows(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    volume: &ZarrVolume,
    rows: Range<usize>,
) -> Result<Work> {
    check_rows(slicer, volume, &rows)?;
    let all = volume.chunk_rows();
    if rows.is_empty() {
        return Ok(Work::default());
    }
    let slabs = all[rows.start].start..all[rows.end - 1].end;
    let mut row = rows.start;
    let mut buf: Vec<u8> = Vec::with_capacity(volume.row_bytes());
    csgpix_voxel::voxelize_slabs(slicer, route, set, eval, tick, slabs, &mut |k, s| {
        buf.extend_from_slice(s);
        if k + 1 == all[row].end {
            volume.write_row(row, &buf)?;
            buf.clear();
            row += 1;
        }
        Ok::<(), Error>(())
    })
    .and_then(|work| volume.sync().map(|()| work))
}

/// Voxelize the bricks of chunk rows `rows` × `tiles` (each one of [`ZarrVolume::tiles`]) of
/// `volume` by the run route and store them ([`ZarrVolume::write_brick`]): per tile, its
/// columns' runs (only its columns: [`csgpix_voxel::runs::Columns::brick`]), then per row the
/// brick's voxels, its chunks that one run fills (or leaves empty) known from the runs.
/// Memory is one tile's runs and one brick's rows, whatever the grid's width. `tick` once a
/// brick. The frames and clocks of a row (the array's, counted from the programs) go with
/// the brick of the tile at the grid's origin, so runs over disjoint bricks sum to the whole
/// run's [`Work`]. The run route must apply ([`csgpix_voxel::runs::applies`]).
#[allow(clippy::too_many_arguments)]
pub fn voxelize_bricks(
    slicer: &Slicer,
    float: bool,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    volume: &ZarrVolume,
    rows: Range<usize>,
    tiles: &[PixelBox],
) -> Result<Work> {
    check_rows(slicer, volume, &rows)?;
    if !csgpix_voxel::runs::applies(slicer) {
        return Err(Error::NoRunRoute);
    }
    let all = volume.chunk_rows();
    let columns = csgpix_voxel::runs::Columns::new(slicer, float)?;
    let mut work = Work::default();
    // One buffer for every brick: a fresh one a brick costs its pages' faults each time.
    let mut voxels: Vec<u8> = vec![];
    for &tile in tiles {
        let runs = columns.brick(eval, tile);
        work.ops += runs.ops;
        for row in rows.clone() {
            let slabs = all[row].clone();
            if tile.x0 == 0 && tile.y0 == 0 {
                let counted = csgpix_voxel::drive::counted_work(slicer, &set, slabs.len())?;
                work.frames += counted.frames;
                work.cycles += counted.cycles;
                work.full_pixel_clocks += counted.full_pixel_clocks;
            }
            work.filled += runs.filled(slabs.clone());
            let known = known_chunks(&runs, volume.chunk(), slabs.clone());
            voxels.clear();
            voxels.resize(tile.pixels() * slabs.len(), 0);
            runs.write(slabs, &mut voxels);
            volume.write_brick(row, tile, &voxels, Some(&known))?;
            tick();
        }
    }
    volume.sync()?;
    Ok(work)
}

/// What each level-0 chunk of a brick holds, from its runs (row-major over the brick's
/// chunks): one colour, or None where the runs change within it.
fn known_chunks(runs: &BrickRuns, [_, cy, cx]: [usize; 3], slabs: Range<usize>) -> Vec<Option<u8>> {
    let b = runs.columns;
    let boxes: Vec<PixelBox> = (b.y0..b.y1)
        .step_by(cy)
        .flat_map(|y| {
            (b.x0..b.x1)
                .step_by(cx)
                .map(move |x| PixelBox::new(x, y, (x + cx).min(b.x1), (y + cy).min(b.y1)))
        })
        .collect();
    boxes
        .into_par_iter()
        .map(|c| runs.uniform(c, slabs.clone()))
        .collect()
}

/// The slicer is on the volume's grid and `rows` are among its rows.
fn check_rows(slicer: &Slicer, volume: &ZarrVolume, rows: &Range<usize>) -> Result<()> {
    if slicer.grid != volume.grid {
        return Err(Error::GridMismatch {
            expected: grid_text(&volume.grid),
            found: grid_text(&slicer.grid),
        });
    }
    let n = volume.chunk_rows().len();
    if rows.start > rows.end || rows.end > n {
        return Err(Error::RowsRange {
            start: rows.start,
            end: rows.end,
            rows: n,
        });
    }
    Ok(())
}

/// What a volume's values mean, for the `csgpix` attribute's `values`: colour codes, with
/// `grey` datasets' grey levels beside them (§4.5), or with `blend` grey levels throughout
/// (§3.3). One text for every writer (the command line and the Python binding), so their
/// stores are byte-identical.
pub fn values_text(grey: bool, blend: bool) -> &'static str {
    if blend {
        "uint8 grey levels blended by §3.3's operators, 0 empty"
    } else if grey {
        "uint8: 1-15 colour codes (crates/draw/src/palette.rs), 16-255 grey levels of datasets, 0 empty"
    } else {
        "uint8 colour codes (crates/draw/src/palette.rs), 0 empty"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(dims: [usize; 3]) -> Grid {
        // Odd corners and sizes: their decimals must come back exactly.
        Grid::new(
            dims,
            DVec3::new(-1.1, 0.3, 2.0 / 3.0),
            DVec3::new(7.7, 9.1, 5.0),
        )
        .unwrap()
    }

    fn attrs() -> VolumeAttrs {
        VolumeAttrs::new("test", "codes")
    }

    fn unsharded(chunk: [usize; 3]) -> Layout {
        Layout {
            chunk,
            shard: 1,
            levels: Some(1),
        }
    }

    fn sharded(chunk: [usize; 3], shard: usize, levels: usize) -> Layout {
        Layout {
            chunk,
            shard,
            levels: Some(levels),
        }
    }

    proptest::proptest! {
        /// Every file (shard, or chunk when unsharded) of every level lies in one tile,
        /// scaled back to level 0, and tiles start on voxels even at every level.
        #[test]
        fn a_tile_holds_whole_files_of_every_level(
            dims in proptest::array::uniform3(1usize..600),
            chunk in proptest::array::uniform3(1usize..70),
            shard in 1usize..9,
            levels in 1usize..8,
        ) {
            let layout = Layout { chunk, shard, levels: None };
            let mut levels_of = plan(dims, &layout).unwrap();
            levels_of.truncate(levels);
            let [tx, ty] = tile(dims, &levels_of);
            for (l, v) in levels_of.iter().enumerate() {
                let [_, uy, ux] = v.grid_unit();
                for (t, u, n) in [(tx, ux, dims[0]), (ty, uy, dims[1])] {
                    // A tile is the whole side, or a whole number of the level's files.
                    proptest::prop_assert!(t == n || (t % (u << l) == 0), "{t} {u} {l} {n}");
                    proptest::prop_assert!(t == n || t % (1 << (levels_of.len() - 1)) == 0);
                }
            }
        }
    }

    #[test]
    fn shards_cover_the_same_scene_at_every_level() {
        let levels = plan([4096, 4096, 4096], &Layout::default()).unwrap();
        assert_eq!(levels.len(), 5);
        for (l, v) in levels.iter().enumerate() {
            let [_, sy, sx] = v.shard.unwrap();
            assert_eq!([sy << l, sx << l], [4096, 4096], "level {l}");
        }
        assert_eq!(tile([4096, 4096, 4096], &levels), [4096, 4096]);
        assert_eq!(
            tile(
                [16384, 16384, 16384],
                &plan([16384; 3], &Layout::default()).unwrap()
            ),
            [4096, 4096]
        );
        let small = Layout {
            shard: 8,
            ..Layout::default()
        };
        assert_eq!(
            tile([16384; 3], &plan([16384; 3], &small).unwrap()),
            [4096, 4096]
        );
        let small = Layout {
            shard: 8,
            levels: Some(4),
            ..Layout::default()
        };
        assert_eq!(
            tile([16384; 3], &plan([16384; 3], &small).unwrap()),
            [512, 512]
        );
    }

    #[test]
    fn chunks_are_cut_to_the_grid_and_rows_cover_every_slab_once() {
        assert_eq!(chunk_shape([10, 20, 30], [64, 8, 64]).unwrap(), [30, 8, 10]);
        assert_eq!(
            chunk_shape([10, 20, 30], [4, 0, 4]).unwrap_err(),
            Error::BadChunk { chunk: [4, 0, 4] }
        );
        let dir = tempfile::tempdir().unwrap();
        let v = ZarrVolume::create(
            &dir.path().join("a"),
            &grid([5, 6, 11]),
            &unsharded([4, 4, 4]),
            &attrs(),
        )
        .unwrap();
        assert_eq!(v.chunk(), [4, 4, 4]);
        assert_eq!(v.chunk_rows(), [0..4, 4..8, 8..11]);
        assert_eq!(v.row_bytes(), 4 * 6 * 5);
    }

    /// The levels and shards of the rule (docs/zarr.md): depth halved per level, sides cut
    /// to each level, shards a whole number of chunks, halved per level, cut to the level.
    #[test]
    fn the_plan_halves_levels_and_cuts_shards() {
        let p = plan([1000, 300, 130], &sharded([64, 64, 64], 4, 3)).unwrap();
        assert_eq!(
            p,
            [
                Level {
                    dims: [1000, 300, 130],
                    chunk: [64, 64, 64],
                    shard: Some([64, 256, 256])
                },
                Level {
                    dims: [500, 150, 65],
                    chunk: [32, 64, 64],
                    shard: Some([32, 128, 128])
                },
                Level {
                    dims: [250, 75, 33],
                    chunk: [16, 64, 64],
                    shard: Some([16, 64, 64])
                },
            ]
        );
        // Level l's shard is 4 >> l chunks a side: each covers a level-0 shard's scene.
        assert_eq!(p[0].files_per_row(), 2 * 4);
        assert_eq!(p[1].files_per_row(), 2 * 4);
        assert_eq!(p[2].files_per_row(), 2 * 4);
        // Defaults: levels until the largest side is at most 256, within the depth's halvings.
        assert_eq!(default_levels([384; 3]), 2);
        assert_eq!(default_levels([256, 10, 10]), 1);
        assert_eq!(default_levels([4096; 3]), 5);
        assert_eq!(default_levels([16384; 3]), 7);
        assert_eq!(default_levels([32768; 3]), 8);
        assert_eq!(max_levels([32768; 3], [64; 3]), 7);
        assert_eq!(max_levels([100, 100, 100], [12, 64, 64]), 3);
        // One row: any depth halves; no level past 1×1×1.
        assert_eq!(max_levels([5, 3, 7], [7, 3, 5]), 4);
        let one = plan([5, 3, 7], &sharded([64; 3], 2, 4)).unwrap();
        assert_eq!(one[3].dims, [1, 1, 1]);
        assert_eq!(one[3].chunk, [1, 1, 1]);
        assert_eq!(one[1].chunk, [4, 2, 3]);
        let l = plan([100, 100, 100], &Layout::new([12, 64, 64])).unwrap();
        assert_eq!(l.len(), 1, "100 ≤ 256: no pyramid by default");
        assert_eq!(
            plan([100, 100, 100], &sharded([12, 64, 64], 64, 4)).unwrap_err(),
            Error::BadLevels {
                levels: 4,
                max: 3,
                depth: 12
            }
        );
        assert_eq!(
            plan([9; 3], &sharded([3; 3], 0, 1)).unwrap_err(),
            Error::BadShard
        );
        assert!(plan([9; 3], &sharded([3; 3], 2, 0)).is_err());
        // Unsharded: no shard at any level.
        let u = plan(
            [300, 20, 20],
            &Layout {
                shard: 1,
                ..Layout::new([4; 3])
            },
        )
        .unwrap();
        assert_eq!(u.len(), 2);
        assert!(u.iter().all(|v| v.shard.is_none()));
    }

    /// Voxel (i, j, k) is element [k, j, i]; rows written in any order, edge chunks cut;
    /// sharded and not.
    #[test]
    fn a_row_lands_at_k_j_i() {
        let [nx, ny, nz] = [5, 6, 7];
        let value = |i: usize, j: usize, k: usize| (1 + i + 10 * j + 100 * k) as u8;
        for (layout, file) in [
            (unsharded([3, 4, 2]), "0/c/2/1/2"),     // 3 rows of 2 × 3 chunks
            (sharded([3, 4, 2], 2, 1), "0/c/2/0/1"), // shards of 2 × 2 chunks: 1 × 2
        ] {
            let dir = tempfile::tempdir().unwrap();
            let v = ZarrVolume::create(
                &dir.path().join("a"),
                &grid([nx, ny, nz]),
                &layout,
                &attrs(),
            )
            .unwrap();
            for (row, slabs) in v.chunk_rows().into_iter().enumerate().rev() {
                let mut slices = vec![];
                for k in slabs {
                    for j in 0..ny {
                        slices.extend((0..nx).map(|i| value(i, j, k)));
                    }
                }
                v.write_row(row, &slices).unwrap();
            }
            let all = v.read_level(0).unwrap();
            for k in 0..nz {
                for j in 0..ny {
                    for i in 0..nx {
                        assert_eq!(
                            all[(k * ny + j) * nx + i],
                            value(i, j, k),
                            "{layout:?} ({i}, {j}, {k})"
                        );
                    }
                }
            }
            assert!(dir.path().join("a").join(file).is_file(), "{layout:?}");
            let files = v.files_written();
            assert_eq!(
                files,
                [v.levels()[0].files_per_row() as u64 * 3],
                "{layout:?}"
            );
        }
    }

    /// A chunk that becomes all 0 loses its file (sharded: its index entry, then its shard's
    /// file); the rest read as 0 without one.
    #[test]
    fn all_zero_chunks_have_no_file() {
        for layout in [unsharded([2, 4, 2]), sharded([2, 4, 2], 2, 1)] {
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("a");
            let v = ZarrVolume::create(&path, &grid([4, 4, 4]), &layout, &attrs()).unwrap();
            let mut row = vec![0u8; 2 * 4 * 4];
            row[3] = 9; // voxel (3, 0, 0): chunk (0, 0, 1)
            v.write_row(0, &row).unwrap();
            let (kept, gone) = match layout.shard {
                1 => ("0/c/0/0/1", "0/c/0/0/0"),
                _ => ("0/c/0/0/0", "0/c/1/0/0"),
            };
            assert!(path.join(kept).is_file(), "{layout:?}");
            assert!(!path.join(gone).exists(), "{layout:?}");
            if layout.shard > 1 {
                // One inner chunk of two, and a 2-entry index: (offset 0, its length) and
                // (MAX, MAX) for the empty one.
                let bytes = std::fs::read(path.join(kept)).unwrap();
                let index: Vec<u64> = bytes[bytes.len() - 32..]
                    .chunks(8)
                    .map(|b| u64::from_le_bytes(b.try_into().unwrap()))
                    .collect();
                assert_eq!(index[..2], [u64::MAX, u64::MAX]);
                assert_eq!(index[2..], [0, bytes.len() as u64 - 32]);
            }
            assert_eq!(v.read_level(0).unwrap()[3], 9);
            v.write_row(0, &[0; 32]).unwrap();
            assert!(!path.join(kept).exists(), "{layout:?}");
            assert!(v.read_level(0).unwrap().iter().all(|&x| x == 0));
        }
    }

    /// Unsharded chunks, written here rather than by zarrs's store (which syncs each file),
    /// are the bytes zarrs's own chunk writer gives for the same chunks.
    #[test]
    fn unsharded_chunks_are_the_bytes_zarrs_writes() {
        let dir = tempfile::tempdir().unwrap();
        let layout = unsharded([2, 3, 2]);
        let (ours, theirs) = (dir.path().join("ours"), dir.path().join("theirs"));
        let v = ZarrVolume::create(&ours, &grid([5, 4, 2]), &layout, &attrs()).unwrap();
        let z = ZarrVolume::create(&theirs, &grid([5, 4, 2]), &layout, &attrs()).unwrap();
        // A mixed chunk, a chunk of one value, chunks cut by the grid's edges, empty ones.
        let row: Vec<u8> = (0..40u8)
            .map(|i| [0, 7, i % 3, 7][(i / 10) as usize])
            .collect();
        v.write_row(0, &row).unwrap();
        let cut = shard::RowCut {
            slices: &row,
            nx: 5,
            ny: 4,
            slabs: 2,
            chunk: [2, 3, 2],
            at: [0, 0],
            known: None,
        };
        let (down, across) = cut.grid();
        let mut files = 0;
        for (j, i) in (0..down).flat_map(|j| (0..across).map(move |i| (j, i))) {
            let key = format!("0/c/0/{j}/{i}");
            if cut.held(j, i) == shard::Held::Empty {
                assert!(!ours.join(&key).exists(), "{key}");
                continue;
            }
            let chunk = cut.copy(j, i);
            let options = zarrs::array::CodecOptions::default();
            let at = [0, j as u64, i as u64];
            z.levels[0]
                .array
                .store_chunk_opt(&at, chunk, &options)
                .unwrap();
            let (a, b) = (ours.join(&key), theirs.join(&key));
            assert_eq!(
                std::fs::read(a).unwrap(),
                std::fs::read(b).unwrap(),
                "{key}"
            );
            files += 1;
        }
        assert!(files >= 3, "{files}");
    }

    /// Each level read back is the downsample of the one below, and is placed at the centre
    /// of the voxels it covers.
    #[test]
    fn levels_are_downsamples_of_the_level_below() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a");
        let [nx, ny, nz] = [13, 9, 11];
        let g = grid([nx, ny, nz]);
        let v = ZarrVolume::create(&path, &g, &sharded([4, 4, 4], 2, 3), &attrs()).unwrap();
        assert_eq!(v.chunk_rows().len(), 3);
        let value = |i: usize, j: usize, k: usize| ((i * 7 + j * 3 + k) % 5) as u8;
        for (row, slabs) in v.chunk_rows().into_iter().enumerate() {
            let mut slices = vec![];
            for k in slabs {
                for j in 0..ny {
                    slices.extend((0..nx).map(|i| value(i, j, k)));
                }
            }
            v.write_row(row, &slices).unwrap();
        }
        let mut want = v.read_level(0).unwrap();
        let mut dims = [nx, ny, nz];
        for l in 1..3 {
            want = downsample(&want, dims);
            dims = dims.map(|d| d.div_ceil(2));
            assert_eq!(v.levels()[l].dims, dims);
            assert_eq!(v.read_level(l).unwrap(), want, "level {l}");
        }
        let group: Value =
            serde_json::from_slice(&std::fs::read(path.join("zarr.json")).unwrap()).unwrap();
        let ds = &group["attributes"]["ome"]["multiscales"][0]["datasets"];
        let t = &ds[2]["coordinateTransformations"];
        let (o, s) = (g.centre(0, 0, 0), g.voxel());
        assert_eq!(ds[2]["path"], "2");
        assert_eq!(t[0]["scale"], json!(zyx(s * 4.0)));
        // Level 2's voxel 0 covers level 0's 0..4: its centre is 1.5 voxels past theirs.
        assert_eq!(t[1]["translation"], json!(zyx(o + s * 1.5)));
        let reopened = ZarrVolume::open(&path).unwrap();
        assert_eq!(reopened.levels(), v.levels());
        assert_eq!(reopened.layout(), sharded([4, 4, 4], 2, 3));
    }

    #[test]
    fn open_gives_back_the_grid_exactly_and_refuses_other_stores() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a");
        let g = grid([9, 8, 7]);
        ZarrVolume::create(&path, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap();
        let v = ZarrVolume::open(&path).unwrap();
        assert_eq!((*v.grid(), v.chunk(), v.dims()), (g, [5, 5, 5], [9, 8, 7]));
        assert_eq!(v.shard(), DEFAULT_SHARD);

        // A Zarr group that is not ours.
        let foreign = dir.path().join("b");
        std::fs::create_dir(&foreign).unwrap();
        std::fs::write(
            foreign.join("zarr.json"),
            r#"{"zarr_format": 3, "node_type": "group", "attributes": {}}"#,
        )
        .unwrap();
        let e = ZarrVolume::open(&foreign).unwrap_err().to_string();
        assert!(
            e.ends_with("not a csgpix Zarr volume: no `csgpix` attribute"),
            "{e}"
        );
        // Ours with its array gone.
        std::fs::remove_file(path.join("0/zarr.json")).unwrap();
        let e = ZarrVolume::open(&path).unwrap_err().to_string();
        assert!(e.contains("not a csgpix Zarr volume"), "{e}");
        // create: only where nothing is.
        let e = ZarrVolume::create(&path, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap_err();
        assert_eq!(e, Error::NotEmpty { path: path.clone() });
        let file = dir.path().join("f");
        std::fs::write(&file, b"x").unwrap();
        let e = ZarrVolume::create(&file, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap_err();
        assert_eq!(e, Error::NotEmpty { path: file });

        // An array whose shards are not what the attribute says.
        let c = dir.path().join("c");
        ZarrVolume::create(&c, &g, &sharded([2, 2, 2], 2, 1), &attrs()).unwrap();
        let meta = c.join("0/zarr.json");
        let mut m: Value = serde_json::from_slice(&std::fs::read(&meta).unwrap()).unwrap();
        assert_eq!(
            m["chunk_grid"]["configuration"]["chunk_shape"],
            json!([2, 4, 4])
        );
        m["chunk_grid"]["configuration"]["chunk_shape"] = json!([2, 2, 4]);
        std::fs::write(&meta, m.to_string()).unwrap();
        let e = ZarrVolume::open(&c).unwrap_err().to_string();
        assert!(e.contains("level 0: `chunk_grid` is"), "{e}");
    }

    #[test]
    fn bad_rows_are_refused_in_one_line() {
        let dir = tempfile::tempdir().unwrap();
        let v = ZarrVolume::create(
            &dir.path().join("a"),
            &grid([2, 3, 5]),
            &Layout::new([4, 3, 2]),
            &attrs(),
        )
        .unwrap();
        assert_eq!(
            v.write_row(2, &[]).unwrap_err().to_string(),
            "chunk row 2: the volume has rows 0..2"
        );
        assert_eq!(
            v.write_row(1, &[1; 7]).unwrap_err().to_string(),
            "chunk row 1: expected 6 bytes (slabs 1 of 2x3), got 7"
        );
    }

    /// The writer's estimate grows with the rows and the chunk, not with the shard.
    #[test]
    fn the_writers_estimate() {
        let d = [2048, 2048, 2048];
        let s = |shard| {
            writer_bytes(
                d,
                &Layout {
                    shard,
                    ..Layout::default()
                },
                2,
            )
            .unwrap()
        };
        // A shard costs its index alone, 16 bytes a chunk (64 is cut to the grid's 32).
        assert_eq!(s(64) - s(16), 2 * 16 * (32 * 32 - 16 * 16));
        let row0 = 64 * 2048 * 2048u64;
        assert!(s(64) > row0 + row0 / 8 && s(64) < row0 + row0 / 7 + (8 << 20));
        assert!(s(1) > row0 + 8 * (64 << 12));
    }
}

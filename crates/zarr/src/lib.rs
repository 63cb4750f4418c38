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
mod layout;
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
pub use layout::*;
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
        csgpix_scene::Error::Json {
            reason: e.to_string(),
        }
        .context(format_args!("`{key}`"))
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
    let columns = csgpix_voxel::runs::Columns::new(slicer, float, &|| ())?;
    let mut work = Work::default();
    // One buffer for every brick: a fresh one a brick costs its pages' faults each time.
    let mut voxels: Vec<u8> = vec![];
    for &tile in tiles {
        let runs = columns.brick(eval, tile);
        work.ops += runs.ops;
        for row in rows.clone() {
            let slabs = all[row].clone();
            if tile.x0 == 0 && tile.y0 == 0 {
                let counted = csgpix_voxel::drive::counted_work(slicer, slabs.len())?;
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
mod tests;

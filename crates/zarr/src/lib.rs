#![warn(missing_docs)]

//! csgpix voxel volumes as OME-Zarr 0.5 stores (Zarr v3), written out of core: one chunk row
//! (the slabs of one chunk along Z, every chunk across X and Y) at a time, so a run holds a
//! chunk row and the voxelizer's batch, never the whole volume (docs/zarr.md).
//!
//! # Layout
//!
//! ```text
//! OUT.zarr/zarr.json      group: "ome" (OME-Zarr 0.5 multiscales, one level) and "csgpix"
//! OUT.zarr/0/zarr.json    array: uint8, shape (nz, ny, nx), chunks (cz, cy, cx), fill 0, gzip
//! OUT.zarr/0/c/K/J/I      chunk (K, J, I), gzip of its C-order bytes; absent when all 0
//! ```
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
//! [`chunk_rows`](ZarrVolume::chunk_rows): rows are disjoint sets of chunk files, and the
//! voxelizer gives every slab the same slice whatever range it is computed in
//! ([`csgpix_voxel::voxelize_slabs`]), so the files are byte for byte those of one run over
//! every row (tested: `tests/zarr.rs`).
//!
//! # Empty chunks
//!
//! A chunk whose voxels are all 0 (the fill value) is not written, and is removed if a file
//! for it exists: zarrs's default (`store_empty_chunks` off), which Zarr readers read as the
//! fill value. Which files exist therefore depends only on the voxels.
//!
//! # Example
//!
//! ```
//! use csgpix_voxel::{blist::BlistEval, Grid, Route, Slicer, SlicerOptions};
//! use csgpix_zarr::{voxelize_rows, VolumeAttrs, ZarrVolume};
//! use glam::DVec3;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let scene = csgpix_openscad::parse_csg("cube(size = [8, 8, 8]);", "cube.csg")?;
//! let grid = Grid::new([16, 16, 10], DVec3::ZERO, DVec3::splat(8.0))?;
//! let dir = tempfile::tempdir()?;
//! let path = dir.path().join("cube.zarr");
//! let attrs = VolumeAttrs::new("cube.csg", "uint8 colour codes, 0 empty");
//! let volume = ZarrVolume::create(&path, &grid, [4, 16, 16], &attrs)?;
//! assert_eq!(volume.chunk_rows(), [0..4, 4..8, 8..10]);
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
//! assert!(path.join("0/c/2/0/0").exists());
//! # Ok(())
//! # }
//! ```

mod error;

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

use csgpix_scene::grid::Grid;
use csgpix_scene::output::staged_write;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{Route, Slicer, Work};
use glam::DVec3;
use rtl_model::EquationSet;
use serde_json::{json, Value};
use zarrs::array::codec::GzipCodec;
use zarrs::array::{Array, ArrayBuilder, ArrayMetadataOptions, CodecOptions};
use zarrs::filesystem::FilesystemStore;
use zarrs::group::{Group, GroupBuilder};

pub use error::{Error, Result};

/// The side of a cubic chunk when none is asked for: a chunk row of a 2048² grid is then
/// 256 MiB, and a chunk 256 KiB before compression (docs/zarr.md).
pub const DEFAULT_CHUNK: usize = 64;

/// gzip's level for every chunk: zlib's default. On twelve.csg at 1024³ level 1 made a store
/// 2.6× as large (6.29 MB against 2.39) in the same wall time, since writing, not
/// compressing, is what a run waits on (docs/zarr.md has the figures).
pub const GZIP_LEVEL: u32 = 6;

/// Chunks of a row written at once, each on its own thread. zarrs's filesystem store syncs
/// every chunk file to the disk before it returns (`File::sync_all`), so a writer spends most
/// of its time waiting on the disk, not compressing: with 2 writers a 1024³ run spent 6.5 s
/// of its 21 s there (docs/zarr.md). Threads apart from rayon's, so that they wait without
/// holding the voxelizer's workers; each holds a chunk and its gzip stream.
pub const WRITERS: usize = 8;

/// The dataset path of the one multiscale level, under the group.
const LEVEL: &str = "0";

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

/// A csgpix volume in a Zarr v3 store on the filesystem: the group, and its uint8 array at
/// `0`, shape (nz, ny, nx), written a chunk row at a time.
pub struct ZarrVolume {
    path: PathBuf,
    array: Array<FilesystemStore>,
    grid: Grid,
    /// Chunk shape, Z, Y, X.
    chunk: [usize; 3],
}

impl std::fmt::Debug for ZarrVolume {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ZarrVolume")
            .field("path", &self.path)
            .field("grid", &self.grid)
            .field("chunk", &self.chunk)
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

/// The chunk shape a store of `dims` (X, Y, Z) gets for `chunk` (Z, Y, X): each side at most
/// the grid's, so that a small grid is not padded out to a large chunk.
pub fn chunk_shape(dims: [usize; 3], chunk: [usize; 3]) -> Result<[usize; 3]> {
    if chunk.contains(&0) {
        return Err(Error::BadChunk { chunk });
    }
    let [nx, ny, nz] = dims;
    Ok([chunk[0].min(nz), chunk[1].min(ny), chunk[2].min(nx)])
}

/// Bytes a run over a store of `chunk` holds besides the voxelizer's own: one chunk row of
/// slices, and per writer ([`WRITERS`]) a chunk copied out of it and its gzip stream (at
/// most the chunk and zlib's bound, `deflateBound`).
pub fn writer_bytes(dims: [usize; 3], chunk: [usize; 3]) -> Result<u64> {
    let [cz, cy, cx] = chunk_shape(dims, chunk)?.map(|c| c as u64);
    let [nx, ny, _] = dims.map(|d| d as u64);
    let row = cz.saturating_mul(ny).saturating_mul(nx);
    let chunk = cz.saturating_mul(cy).saturating_mul(cx);
    let per_writer = chunk.saturating_mul(2).saturating_add(chunk / 8 + 64);
    Ok(row.saturating_add((WRITERS as u64).saturating_mul(per_writer)))
}

/// An upper bound of the memory of a run into a store of `chunk` (docs/memory.md): the
/// voxelizer's without a volume ([`csgpix_voxel::memory_estimate_rows`]) and
/// [`writer_bytes`].
pub fn memory_estimate(
    grid: &Grid,
    chunk: [usize; 3],
    prims: usize,
    threads: usize,
) -> Result<u64> {
    let held = writer_bytes(grid.dims, chunk)?;
    Ok(csgpix_voxel::memory_estimate_rows(
        grid, prims, threads, held,
    ))
}

fn store_err(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> Error + '_ {
    move |e| Error::Store {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// X, Y, Z as Z, Y, X.
fn zyx(v: DVec3) -> [f64; 3] {
    [v.z, v.y, v.x]
}

/// The group's attributes: OME-Zarr 0.5's `ome` (<https://ngff.openmicroscopy.org/0.5/>,
/// "multiscales": axes, one dataset with exactly one scale then one translation) and ours.
/// Keys are written in this order (serde_json keeps insertion order under zarrs), so the
/// bytes of `zarr.json` depend on the grid and the texts alone.
fn group_attributes(grid: &Grid, attrs: &VolumeAttrs) -> serde_json::Map<String, Value> {
    let axis = |name: &str| json!({"name": name, "type": "space"});
    let origin = grid.centre(0, 0, 0);
    let spacing = grid.voxel();
    let ome = json!({
        "version": "0.5",
        "multiscales": [{
            "name": "csgpix",
            "axes": [axis("z"), axis("y"), axis("x")],
            "datasets": [{
                "path": LEVEL,
                "coordinateTransformations": [
                    {"type": "scale", "scale": zyx(spacing)},
                    {"type": "translation", "translation": zyx(origin)},
                ],
            }],
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

/// Chunks equal to the fill value are skipped, whatever the process's zarrs configuration.
fn codec_options() -> CodecOptions {
    CodecOptions::default().with_store_empty_chunks(false)
}

impl ZarrVolume {
    /// Write the metadata of a volume on `grid` at `path` (a new or empty directory): the
    /// group's `zarr.json` with its OME-Zarr 0.5 and `csgpix` attributes, and the array's at
    /// `path/0` (uint8, shape (nz, ny, nx), chunks `chunk` (Z, Y, X) cut to the grid by
    /// [`chunk_shape`], fill 0, gzip at [`GZIP_LEVEL`], dimension names z, y, x). No chunk is
    /// written: a volume nobody voxelizes reads as all 0.
    pub fn create(
        path: &Path,
        grid: &Grid,
        chunk: [usize; 3],
        attrs: &VolumeAttrs,
    ) -> Result<ZarrVolume> {
        let chunk = chunk_shape(grid.dims, chunk)?;
        let err = store_err(path);
        let _writing = staged_write().ok_or(Error::Interrupted)?;
        match std::fs::read_dir(path) {
            Ok(entries) => {
                if entries.count() > 0 {
                    return Err(Error::NotEmpty { path: path.into() });
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                std::fs::create_dir_all(path).map_err(|e| err(&e))?
            }
            Err(_) if path.exists() => return Err(Error::NotEmpty { path: path.into() }),
            Err(e) => return Err(err(&e)),
        }
        let store = Arc::new(FilesystemStore::new(path).map_err(|e| err(&e))?);
        let group = GroupBuilder::new()
            .attributes(group_attributes(grid, attrs))
            .build(store.clone(), "/")
            .map_err(|e| err(&e))?;
        group.store_metadata().map_err(|e| err(&e))?;
        let [nx, ny, nz] = grid.dims.map(|d| d as u64);
        let gzip = GzipCodec::new(GZIP_LEVEL).map_err(|e| err(&e))?;
        let array = ArrayBuilder::new(
            vec![nz, ny, nx],
            chunk.map(|c| c as u64).to_vec(),
            zarrs::array::data_type::uint8(),
            0u8,
        )
        .bytes_to_bytes_codecs(vec![Arc::new(gzip)])
        .dimension_names(Some(["z", "y", "x"]))
        .build(store, &format!("/{LEVEL}"))
        .map_err(|e| err(&e))?;
        array
            .store_metadata_opt(&metadata_options())
            .map_err(|e| err(&e))?;
        Ok(ZarrVolume {
            path: path.into(),
            array,
            grid: *grid,
            chunk,
        })
    }

    /// Open a volume [`create`](ZarrVolume::create) wrote (by this process or another):
    /// its grid from the `csgpix` attribute, its chunk shape from the array, both checked
    /// against each other.
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
        let array = Array::open(store, &format!("/{LEVEL}")).map_err(|e| bad(e.to_string()))?;
        let [nx, ny, nz] = grid.dims.map(|d| d as u64);
        if array.shape() != [nz, ny, nx] {
            return Err(bad(format!(
                "array shape {:?} is not (nz, ny, nx) of dims {:?}",
                array.shape(),
                grid.dims
            )));
        }
        if array.data_type() != &zarrs::array::data_type::uint8() {
            return Err(bad("the array is not uint8".into()));
        }
        let chunk = array
            .chunk_shape_usize(&[0, 0, 0])
            .map_err(|e| bad(e.to_string()))?;
        let chunk: [usize; 3] = chunk
            .try_into()
            .map_err(|_| bad("the array is not 3D".into()))?;
        // A regular grid: every chunk has the shape of the first.
        if chunk.contains(&0) {
            return Err(bad("a chunk side is 0".into()));
        }
        let [cz, cy, cx] = chunk.map(|c| c as u64);
        if array.chunk_grid_shape() != [nz.div_ceil(cz), ny.div_ceil(cy), nx.div_ceil(cx)] {
            return Err(bad("the chunk grid is not regular".into()));
        }
        Ok(ZarrVolume {
            path: path.into(),
            array,
            grid,
            chunk,
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

    /// The array's chunk shape, Z, Y, X.
    pub fn chunk(&self) -> [usize; 3] {
        self.chunk
    }

    /// The slabs (k ranges) of each chunk row, in order: `cz` slabs each, the last fewer
    /// when `cz` does not divide nz.
    pub fn chunk_rows(&self) -> Vec<Range<usize>> {
        let (nz, cz) = (self.grid.dims[2], self.chunk[0]);
        (0..nz).step_by(cz).map(|a| a..(a + cz).min(nz)).collect()
    }

    /// Bytes of the largest chunk row's slices (what [`voxelize_rows`] buffers).
    pub fn row_bytes(&self) -> usize {
        let [nx, ny, nz] = self.grid.dims;
        self.chunk[0].min(nz) * ny * nx
    }

    /// Store chunk row `row`: `slices` are its slabs' slices in order of k, each nx × ny
    /// bytes, X fastest then Y (the voxelizer's). Every chunk of the row is written (gzip),
    /// [`WRITERS`] at a time; a chunk all 0 is not written, and a file left for it by an
    /// earlier write is removed. On an error the first one is returned, and chunks of the
    /// row may be written or not.
    pub fn write_row(&self, row: usize, slices: &[u8]) -> Result<()> {
        let rows = self.chunk_rows();
        let slabs = rows
            .get(row)
            .ok_or(Error::RowRange {
                row,
                rows: rows.len(),
            })?
            .len();
        let [nx, ny, _] = self.grid.dims;
        if slices.len() != slabs * nx * ny {
            return Err(Error::RowLength {
                row,
                expected: slabs * nx * ny,
                got: slices.len(),
                slabs,
                nx,
                ny,
            });
        }
        let [cz, cy, cx] = self.chunk;
        let across = nx.div_ceil(cx);
        let chunks = ny.div_ceil(cy) * across;
        let options = codec_options();
        let write = |c: usize| -> Result<()> {
            let (bj, bi) = (c / across, c % across);
            let (j0, i0) = (bj * cy, bi * cx);
            let (h, w) = (cy.min(ny - j0), cx.min(nx - i0));
            // The chunk's C-order bytes; past the grid's edge (the last chunk of an axis
            // that `c` does not divide) the fill value, as the Zarr spec pads edge chunks.
            let mut chunk = vec![0u8; cz * cy * cx];
            for z in 0..slabs {
                for y in 0..h {
                    let src = (z * ny + j0 + y) * nx + i0;
                    let dst = (z * cy + y) * cx;
                    chunk[dst..dst + w].copy_from_slice(&slices[src..src + w]);
                }
            }
            let at = [row as u64, bj as u64, bi as u64];
            // The store makes the chunk's directories as it writes: never after a signal's
            // cleanup has removed a staged store (crates/scene/src/output.rs).
            let _writing = staged_write().ok_or(Error::Interrupted)?;
            self.array
                .store_chunk_opt(&at, chunk, &options)
                .map_err(|e| store_err(&self.path)(&e))
        };
        // WRITERS threads take the row's chunks in turn; the first error stops them all.
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
            let writers: Vec<_> = (0..WRITERS.min(chunks))
                .map(|_| scope.spawn(writer))
                .collect();
            let mut first = Ok(());
            for w in writers {
                let r = w
                    .join()
                    .unwrap_or_else(|_| Err(Error::Msg("a chunk writer panicked".into())));
                first = first.and(r);
            }
            first
        })
    }
}

/// The grid the `csgpix` attribute describes.
fn grid_of(v: &Value) -> Result<Grid, String> {
    let dims: [usize; 3] =
        serde_json::from_value(v["dims"].clone()).map_err(|e| format!("`dims`: {e}"))?;
    let corner = |key: &str| -> Result<DVec3, String> {
        let a: [f64; 3] =
            serde_json::from_value(v[key].clone()).map_err(|e| format!("`{key}`: {e}"))?;
        Ok(DVec3::from_array(a))
    };
    Grid::new(dims, corner("min")?, corner("max")?).map_err(|e| e.to_string())
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
    if slicer.grid != volume.grid {
        return Err(Error::GridMismatch {
            expected: grid_text(&volume.grid),
            found: grid_text(&slicer.grid),
        });
    }
    let all = volume.chunk_rows();
    if rows.start > rows.end || rows.end > all.len() {
        return Err(Error::RowsRange {
            start: rows.start,
            end: rows.end,
            rows: all.len(),
        });
    }
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

    /// The whole array as zarrs reads it, C order (nz, ny, nx).
    fn read_all(v: &ZarrVolume) -> Vec<u8> {
        v.array
            .retrieve_array_subset(&v.array.subset_all())
            .unwrap()
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
            [4, 4, 4],
            &attrs(),
        )
        .unwrap();
        assert_eq!(v.chunk(), [4, 4, 4]);
        assert_eq!(v.chunk_rows(), [0..4, 4..8, 8..11]);
        assert_eq!(v.row_bytes(), 4 * 6 * 5);
    }

    /// Voxel (i, j, k) is element [k, j, i]; rows written in any order, edge chunks cut.
    #[test]
    fn a_row_lands_at_k_j_i() {
        let dir = tempfile::tempdir().unwrap();
        let [nx, ny, nz] = [5, 6, 7];
        let v = ZarrVolume::create(
            &dir.path().join("a"),
            &grid([nx, ny, nz]),
            [3, 4, 2],
            &attrs(),
        )
        .unwrap();
        let value = |i: usize, j: usize, k: usize| (1 + i + 10 * j + 100 * k) as u8;
        for (row, slabs) in v.chunk_rows().into_iter().enumerate().rev() {
            let mut slices = vec![];
            for k in slabs {
                for j in 0..ny {
                    slices.extend((0..nx).map(|i| value(i, j, k)));
                }
            }
            v.write_row(row, &slices).unwrap();
        }
        let all = read_all(&v);
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    assert_eq!(
                        all[(k * ny + j) * nx + i],
                        value(i, j, k),
                        "({i}, {j}, {k})"
                    );
                }
            }
        }
        // 3 rows of 2 × 3 chunks.
        assert!(dir.path().join("a/0/c/2/1/2").is_file());
    }

    /// A chunk that becomes all 0 loses its file; the rest read as 0 without one.
    #[test]
    fn all_zero_chunks_have_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a");
        let v = ZarrVolume::create(&path, &grid([4, 4, 4]), [2, 4, 2], &attrs()).unwrap();
        let mut row = vec![0u8; 2 * 4 * 4];
        row[3] = 9; // voxel (3, 0, 0): chunk (0, 0, 1)
        v.write_row(0, &row).unwrap();
        assert!(path.join("0/c/0/0/1").is_file());
        assert!(!path.join("0/c/0/0/0").exists());
        v.write_row(0, &[0; 32]).unwrap();
        assert!(!path.join("0/c/0/0/1").exists());
        assert!(read_all(&v).iter().all(|&x| x == 0));
    }

    #[test]
    fn open_gives_back_the_grid_exactly_and_refuses_other_stores() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a");
        let g = grid([9, 8, 7]);
        ZarrVolume::create(&path, &g, [5, 5, 5], &attrs()).unwrap();
        let v = ZarrVolume::open(&path).unwrap();
        assert_eq!((*v.grid(), v.chunk(), v.dims()), (g, [5, 5, 5], [9, 8, 7]));

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
        let e = ZarrVolume::create(&path, &g, [5, 5, 5], &attrs()).unwrap_err();
        assert_eq!(e, Error::NotEmpty { path: path.clone() });
        let file = dir.path().join("f");
        std::fs::write(&file, b"x").unwrap();
        let e = ZarrVolume::create(&file, &g, [5, 5, 5], &attrs()).unwrap_err();
        assert_eq!(e, Error::NotEmpty { path: file });
    }

    #[test]
    fn bad_rows_are_refused_in_one_line() {
        let dir = tempfile::tempdir().unwrap();
        let v = ZarrVolume::create(&dir.path().join("a"), &grid([2, 3, 5]), [4, 3, 2], &attrs())
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
}

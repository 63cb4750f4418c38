//! Zarr volumes written a chunk row at a time (docs/zarr.md), in pieces any process can
//! take: `zarr_create` writes the store's metadata, `zarr_write_rows` voxelizes and stores a
//! range of its chunk rows, or their bricks of some XY tiles. `csgpix.distributed` runs the
//! second as Dask tasks.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use csgpix_voxel::Route;
use csgpix_zarr::{
    voxelize_bricks, voxelize_rows, Layout, VolumeAttrs, ZarrVolume, DEFAULT_CHUNK, DEFAULT_SHARD,
};
use rtl_model::Equations;

use crate::errors::{text, voxel};
use crate::voxel::{check_memory, GridOptions, RunOptions, Scene};
use csgpix_run::voxelize::zarr_rows_estimate;

/// A Zarr store's error, kept whole where it wraps a scene error.
fn zarr(e: csgpix_zarr::Error) -> PyErr {
    match e {
        csgpix_zarr::Error::Voxel(e) => voxel(e),
        e => text(e.to_string()),
    }
}

/// `chunk` as N or (X, Y, Z), as `res` is; held (Z, Y, X), the array's order.
fn chunk_shape(chunk: Option<&Bound<'_, PyAny>>) -> PyResult<[usize; 3]> {
    let Some(c) = chunk else {
        return Ok([DEFAULT_CHUNK; 3]);
    };
    if let Ok(n) = c.extract::<usize>() {
        return Ok([n; 3]);
    }
    let [x, y, z] = c
        .extract::<[usize; 3]>()
        .map_err(|_| text("chunk: an int N or a tuple (X, Y, Z)".into()))?;
    Ok([z, y, x])
}

/// `shard` as N chunks a side, "none" for no shards (1), or the default when not given.
fn shard_side(shard: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    let Some(s) = shard else {
        return Ok(DEFAULT_SHARD);
    };
    if s.extract::<String>().is_ok_and(|t| t == "none") {
        return Ok(1);
    }
    s.extract::<usize>()
        .map_err(|_| text("shard: an int N (chunks a shard side) or \"none\"".into()))
}

/// Write the metadata of the volume of `scene` on its grid at `path` (a new or empty
/// directory), as `csgpix voxelize --format zarr` does (`shard`: chunks a shard side, or
/// "none"; `levels`: the pyramid's, default as the command line's); returns `dims` (x, y,
/// z), `chunk` (z, y, x), `shard` (z, y, x, or None), `levels`, `rows`, the number of
/// chunk rows, `tile` (x, y) and `tiles`, the XY tiles of a brick, and `bricks`: whether
/// the run computes tiles apart (the run route, where it applies).
#[pyfunction]
#[pyo3(signature = (scene, path, res=None, *, voxel=None, pad=0, bounds=None, chunk=None,
    shard=None, levels=None, sampling="centre", model="word", route="runs", eval="blist",
    grey=false, blend=None, word="10/10/11"))]
#[allow(clippy::too_many_arguments)]
pub fn zarr_create<'py>(
    py: Python<'py>,
    scene: &Scene,
    path: PathBuf,
    res: Option<&Bound<'py, PyAny>>,
    voxel: Option<f64>,
    pad: usize,
    bounds: Option<([f64; 3], [f64; 3])>,
    chunk: Option<&Bound<'py, PyAny>>,
    shard: Option<&Bound<'py, PyAny>>,
    levels: Option<usize>,
    sampling: &str,
    model: &str,
    route: &str,
    eval: &str,
    grey: bool,
    blend: Option<&str>,
    word: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let grid = GridOptions::new(res, voxel, pad, bounds)?.grid(scene)?;
    // Checked here so that a bad option fails before any file is written.
    let opts = RunOptions::parse(sampling, model, route, eval, grey, blend, word)?;
    let slicer = opts.slicer(scene, grid)?;
    let bricks = matches!(opts.route(&slicer), Route::Runs { .. });
    drop(slicer);
    let values = csgpix_zarr::values_text(grey, blend.is_some());
    let attrs = VolumeAttrs::new(format!("csgpix voxelize {}", scene.name), values);
    let layout = Layout {
        chunk: chunk_shape(chunk)?,
        shard: shard_side(shard)?,
        levels,
    };
    let store = ZarrVolume::create(&path, &grid, &layout, &attrs).map_err(zarr)?;
    let d = PyDict::new(py);
    d.set_item("dims", store.dims())?;
    d.set_item("chunk", store.chunk())?;
    d.set_item("shard", store.levels()[0].shard)?;
    d.set_item("levels", store.levels().len())?;
    d.set_item("rows", store.chunk_rows().len())?;
    d.set_item("tile", store.tile())?;
    d.set_item("tiles", store.tiles().len())?;
    d.set_item("bricks", bricks)?;
    Ok(d)
}

/// Voxelize chunk rows `rows` (r0, r1) of the volume at `path` and store them; the grid is
/// the store's. `tiles` (t0, t1): only the bricks of those XY tiles (indices into the
/// store's tiles, row-major; default all), which the run route alone computes apart.
/// `threads`: the voxelizer's (default: every core). Returns the bricks' work, and
/// `files_written`: the shard (or chunk) files it wrote, every level.
#[pyfunction]
#[pyo3(signature = (scene, path, rows, *, tiles=None, sampling="centre", model="word",
    route="runs", eval="blist", grey=false, blend=None, word="10/10/11", threads=None,
    max_memory=None))]
#[allow(clippy::too_many_arguments)]
pub fn zarr_write_rows<'py>(
    py: Python<'py>,
    scene: &Scene,
    path: PathBuf,
    rows: (usize, usize),
    tiles: Option<(usize, usize)>,
    sampling: &str,
    model: &str,
    route: &str,
    eval: &str,
    grey: bool,
    blend: Option<&str>,
    word: &str,
    threads: Option<usize>,
    max_memory: Option<u64>,
) -> PyResult<Bound<'py, PyDict>> {
    let opts = RunOptions::parse(sampling, model, route, eval, grey, blend, word)?;
    let store = ZarrVolume::open(&path).map_err(zarr)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| text(e.to_string()))?;
    // Checked before anything is allocated: the store's grid and chunks are what its
    // zarr.json says, whoever wrote it.
    let grid = *store.grid();
    let slicer = opts.slicer(scene, grid)?;
    let eval = opts.evaluator(scene);
    let all = store.tiles();
    let route = opts.route(&slicer);
    let float = match route {
        Route::Runs { float } => Some(float),
        _ => None,
    };
    let (t0, t1) = tiles.unwrap_or((0, all.len()));
    if t0 > t1 || t1 > all.len() || (float.is_none() && (t0, t1) != (0, all.len())) {
        return Err(text(format!(
            "tiles ({t0}, {t1}): the store has tiles 0..{}, and only the run route voxelizes \
             some of them",
            all.len()
        )));
    }
    let threads = pool.current_num_threads();
    let need = zarr_rows_estimate(&slicer, route, eval.as_ref(), threads, &store).map_err(zarr)?;
    check_memory(need, max_memory)?;
    let set = Equations::Derived.set();
    let rows = rows.0..rows.1;
    let work = py
        .detach(|| {
            pool.install(|| match float {
                Some(float) => {
                    let tiles = &all[t0..t1];
                    voxelize_bricks(
                        &slicer,
                        float,
                        set,
                        eval.as_ref(),
                        &|| {},
                        &store,
                        rows,
                        tiles,
                    )
                }
                None => voxelize_rows(&slicer, route, set, eval.as_ref(), &|| {}, &store, rows),
            })
        })
        .map_err(zarr)?;
    let d = PyDict::new(py);
    d.set_item("filled", work.filled)?;
    d.set_item("frames", work.frames)?;
    d.set_item("cycles", work.cycles)?;
    d.set_item("simulated_pixel_clocks", work.simulated_pixel_clocks)?;
    d.set_item("full_pixel_clocks", work.full_pixel_clocks)?;
    d.set_item("files_written", store.files_written().iter().sum::<u64>())?;
    Ok(d)
}

//! Zarr volumes written a chunk row at a time (docs/zarr.md), in pieces any process can
//! take: `zarr_create` writes the store's metadata, `zarr_write_rows` voxelizes and stores a
//! range of its chunk rows, or their bricks of some XY tiles. `csgpix.distributed` runs the
//! second as Dask tasks.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use csgpix_run::grid::GridOptions;
use csgpix_run::voxelize::{parse_chunk, parse_shard};
use csgpix_zarr::{DEFAULT_CHUNK, DEFAULT_SHARD};

use crate::errors::{run, text};
use crate::voxel::{grid_options, Callback, Options, Scene};

/// `chunk` as N or (X, Y, Z), as `res` is, read as `--chunk` reads `N` or `XxYxZ`; held
/// (Z, Y, X), the array's order.
fn chunk_shape(chunk: Option<&Bound<'_, PyAny>>) -> PyResult<[usize; 3]> {
    let Some(c) = chunk else {
        return Ok([DEFAULT_CHUNK; 3]);
    };
    let flag = match c.extract::<usize>() {
        Ok(n) => n.to_string(),
        Err(_) => match c.extract::<[usize; 3]>() {
            Ok([x, y, z]) => format!("{x}x{y}x{z}"),
            Err(_) => return Err(text("chunk: an int N or a tuple (X, Y, Z)".into())),
        },
    };
    parse_chunk(&flag).map_err(|e| text(format!("chunk: {e}")))
}

/// `shard` as N chunks a side, "none" for no shards (1), or the default when not given;
/// read as `--shard` reads it.
fn shard_side(shard: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    let Some(s) = shard else {
        return Ok(DEFAULT_SHARD);
    };
    let flag = match (s.extract::<usize>(), s.extract::<String>()) {
        (Ok(n), _) => n.to_string(),
        (_, Ok(t)) if t == "none" => t,
        _ => {
            return Err(text(
                "shard: an int N (chunks a shard side) or \"none\"".into(),
            ))
        }
    };
    parse_shard(&flag).map_err(|e| text(format!("shard: {e}")))
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
    let grid = grid_options(res, voxel, pad, bounds)?;
    // Checked here so that a bad option fails before any file is written.
    let options = Options {
        sampling,
        model,
        route,
        eval,
        grey,
        blend,
        word,
    };
    let mut job = options.job(scene, grid, None)?;
    job.outputs.chunk = Some(chunk_shape(chunk)?);
    job.outputs.shard = Some(shard_side(shard)?);
    job.outputs.levels = levels;
    let (store, bricks) = job.create_zarr(&scene.loaded, &path).map_err(run)?;
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
/// `threads`: the voxelizer's (default: every core). `progress`: called as
/// `progress(done, total)` as bricks (or slices) are stored. Returns the bricks' work, and
/// `files_written`: the shard (or chunk) files it wrote, every level.
#[pyfunction]
#[pyo3(signature = (scene, path, rows, *, tiles=None, sampling="centre", model="word",
    route="runs", eval="blist", grey=false, blend=None, word="10/10/11", threads=None,
    max_memory=None, progress=None))]
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
    progress: Option<Py<PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let options = Options {
        sampling,
        model,
        route,
        eval,
        grey,
        blend,
        word,
    };
    // The grid is the store's: these options are never used.
    let mut job = options.job(scene, GridOptions::default(), max_memory)?;
    job.threads = threads;
    let (rows, tiles) = (rows.0..rows.1, tiles.map(|(t0, t1)| t0..t1));
    let sink = Callback::new(progress);
    let done = py.detach(|| job.write_zarr_rows(&scene.loaded, &path, (rows, tiles), &sink));
    sink.raise()?;
    let (work, files) = done.map_err(run)?;
    let d = PyDict::new(py);
    d.set_item("filled", work.filled)?;
    d.set_item("frames", work.frames)?;
    d.set_item("cycles", work.cycles)?;
    d.set_item("simulated_pixel_clocks", work.simulated_pixel_clocks)?;
    d.set_item("full_pixel_clocks", work.full_pixel_clocks)?;
    d.set_item("files_written", files)?;
    Ok(d)
}

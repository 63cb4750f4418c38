//! OME-Zarr stores of a voxelization (docs/zarr.md), the steps the job's `-o OUT.zarr` and
//! the Python binding (`zarr_create`, `zarr_write_rows`, run as Dask tasks by
//! `csgpix.distributed`) share: the store's metadata, the memory of writing its chunk rows,
//! and those rows (or their bricks of some XY tiles) voxelized (§4.4) and stored.

use std::ops::Range;
use std::path::Path;

use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{Grid, Route, Slicer, Work};
use csgpix_zarr::{voxelize_bricks, voxelize_rows, Layout, VolumeAttrs, ZarrVolume};
use rtl_model::EquationSet;

use serde::Serialize;

use super::plan::{by_bricks, zarr_estimate as estimate, Plan};
use super::VoxelizeJob;
use crate::progress::Progress;
use crate::Error;

/// The `--format zarr` figures of the JSON report.
#[derive(Serialize, Clone, Debug)]
pub struct ZarrReport {
    /// Level 0's chunk shape (a shard's inner chunk), Z, Y, X.
    pub chunk: [usize; 3],
    pub chunk_rows: usize,
    /// Level 0's shard shape, Z, Y, X; null when unsharded (--shard none).
    pub shard: Option<[usize; 3]>,
    /// Multiscale levels, level 0 included.
    pub levels: usize,
    /// Files written per level: shard files, or chunk files when unsharded (all-0 shards
    /// and chunks have none).
    pub files_written: Vec<u64>,
    /// A brick's columns, X, Y (the run route writes brick by brick; else null).
    pub tile: Option<[usize; 2]>,
    /// Bricks written (chunk rows × tiles), or null.
    pub bricks: Option<usize>,
    /// Chunks of every level by what they hold: `empty` (skipped), `uniform` (one value,
    /// compressed once), `mixed`.
    pub chunks: csgpix_zarr::ChunksHeld,
}

impl VoxelizeJob {
    /// The store's layout from the chunk, shard and levels options.
    pub fn zarr_layout(&self) -> Layout {
        let o = &self.outputs;
        Layout {
            chunk: o.chunk.unwrap_or([csgpix_zarr::DEFAULT_CHUNK; 3]),
            shard: o.shard.unwrap_or(csgpix_zarr::DEFAULT_SHARD),
            levels: o.levels,
        }
    }

    /// A Zarr store's error, naming `-o` where the library names the staging directory.
    pub fn zarr_message(&self, e: csgpix_zarr::Error) -> Error {
        use csgpix_zarr::Error as Z;
        match e {
            Z::Store { message, .. } => {
                let out = self.outputs.out.display();
                Error::options("-o", format!("-o {out}: {message}"))
            }
            Z::BadLevels { levels, max, depth } => Error::options(
                "--levels",
                format!(
                    "--levels {levels}: at most {max} here (with more than one chunk row, \
                     2^(levels-1) must divide the chunk depth, {depth}; and no level past a \
                     1x1x1 one)"
                ),
            ),
            e @ Z::BadChunk { .. } => Error::options("--chunk", format!("--chunk: {e}")),
            e => e.into(),
        }
    }

    /// The metadata of the job's volume on `grid` at `root` ([`create_store`]).
    pub fn create_store(&self, grid: &Grid, root: &Path) -> Result<ZarrVolume, csgpix_zarr::Error> {
        let (grey, blend) = (self.voxels.grey, self.voxels.blend.is_some());
        create_store(root, grid, &self.zarr_layout(), &self.name(), grey, blend)
    }

    /// The store of the job's volume of `loaded` at `path` (a new or empty directory): its
    /// metadata only, the chunk rows left to [`VoxelizeJob::write_zarr_rows`]; and whether
    /// the run goes by bricks, tiles apart (the run route, where it applies).
    pub fn create_zarr(&self, loaded: &Loaded, path: &Path) -> crate::Result<(ZarrVolume, bool)> {
        let grid = self.grid.grid(loaded)?;
        let slicer = self.voxels.slicer(loaded, grid, self.grid.sampling)?;
        let bricks = by_bricks(self.voxels.route(&slicer));
        Ok((self.create_store(&grid, path)?, bricks))
    }

    /// Voxelize chunk rows `rows` of the store at `path` (its grid is the store's) and store
    /// them: on the run route only the bricks of tiles `tiles` (None: all). The estimate is
    /// checked against the limit first. Returns the work and the files written, every level.
    pub fn write_zarr_rows(
        &self,
        loaded: &Loaded,
        path: &Path,
        (rows, tiles): (Range<usize>, Option<Range<usize>>),
        progress: &dyn Progress,
    ) -> crate::Result<(Work, u64)> {
        let store = ZarrVolume::open(path)?;
        // Checked before anything is allocated: the store's grid and chunks are what its
        // zarr.json says, whoever wrote it.
        let plan = self.plan_on(loaded, *store.grid())??;
        let layout = store.layout();
        // The estimate walks a dataset's columns to count its runs: on the task's threads.
        let need = plan.pool.install(|| {
            let e = plan.eval.as_ref();
            estimate(
                &plan.slicer,
                plan.route,
                e,
                plan.threads,
                (&layout, tiles.clone()),
            )
        })?;
        self.max_memory.check(need, "this run", self.memory_fix())?;
        let bricks = by_bricks(plan.route).then(|| {
            let n = tiles.as_ref().map_or(store.tiles().len(), |t| t.len());
            rows.len() * n
        });
        let slices = || (rows.len() * store.chunk()[0]).min(store.dims()[2]);
        match bricks {
            Some(n) => progress.stage("bricks", n as u64),
            None => progress.stage("slices", slices() as u64),
        }
        let work = plan.write_rows(self, &store, rows, tiles, progress)?;
        progress.finish();
        Ok((work, store.files_written().iter().sum()))
    }
}

impl Plan {
    /// Voxelize chunk rows `rows` of `store` ([`write_bricks`]) on the plan's threads.
    pub fn write_rows(
        &self,
        job: &VoxelizeJob,
        store: &ZarrVolume,
        rows: Range<usize>,
        tiles: Option<Range<usize>>,
        progress: &dyn Progress,
    ) -> crate::Result<Work> {
        let set = job.voxels.equations.set();
        let tick = || progress.advance(1);
        self.pool.install(|| {
            let e = self.eval.as_ref();
            write_bricks(&self.slicer, self.route, set, e, &tick, store, rows, tiles)
        })
    }
}

/// Write the metadata of the volume of the scene `name` (as messages name it: a path, or
/// `--expr "…"`) on `grid` at `root` (a new or empty directory), cut by `layout`: its
/// attributes say where it comes from and what its values are (colour codes, with `grey`
/// datasets' grey levels, or `blend`ed grey levels, §3.3).
pub fn create_store(
    root: &Path,
    grid: &Grid,
    layout: &Layout,
    name: &str,
    grey: bool,
    blend: bool,
) -> Result<ZarrVolume, csgpix_zarr::Error> {
    let values = csgpix_zarr::values_text(grey, blend);
    let attrs = VolumeAttrs::new(format!("csgpix voxelize {name}"), values);
    ZarrVolume::create(root, grid, layout, &attrs)
}

/// Voxelize chunk rows `rows` of `store` by `route` and store them: on the run route their
/// bricks of the tiles `tiles` (indices into [`ZarrVolume::tiles`], row-major; None: all),
/// else whole rows, which every tile must then be. `tick` once a brick, or once a slice.
/// The slicer's grid must be the store's.
#[allow(clippy::too_many_arguments)]
pub fn write_bricks(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    store: &ZarrVolume,
    rows: Range<usize>,
    tiles: Option<Range<usize>>,
) -> crate::Result<Work> {
    let all = store.tiles();
    let tiles = tiles.unwrap_or(0..all.len());
    check_tiles(route, &tiles, all.len())?;
    let work = match route {
        Route::Runs { float } => {
            let tiles = &all[tiles];
            voxelize_bricks(slicer, float, eval, tick, store, rows, tiles)
        }
        _ => voxelize_rows(slicer, route, set, eval, tick, store, rows),
    };
    Ok(work?)
}

/// Tiles `tiles` are among a store's `n`, and all of them unless the run goes by bricks.
fn check_tiles(route: Route, tiles: &Range<usize>, n: usize) -> crate::Result<()> {
    let among = tiles.start <= tiles.end && tiles.end <= n;
    if among && (by_bricks(route) || *tiles == (0..n)) {
        return Ok(());
    }
    Err(Error::Tiles {
        start: tiles.start,
        end: tiles.end,
        tiles: n,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn some_tiles_only_by_bricks() {
        let runs = Route::Runs { float: false };
        assert!(check_tiles(runs, &(1..3), 4).is_ok());
        assert!(check_tiles(Route::Intervals, &(0..4), 4).is_ok());
        let e = check_tiles(Route::Intervals, &(1..3), 4).unwrap_err();
        assert_eq!(
            e.to_string(),
            "tiles (1, 3): the store has tiles 0..4, and only the run route voxelizes some of them"
        );
    }

    #[test]
    fn tiles_past_the_store_or_reversed_are_refused() {
        let runs = Route::Runs { float: true };
        assert!(matches!(
            check_tiles(runs, &(0..5), 4),
            Err(Error::Tiles {
                start: 0,
                end: 5,
                tiles: 4
            })
        ));
        #[allow(clippy::reversed_empty_ranges)]
        let reversed = 3..2;
        assert!(check_tiles(runs, &reversed, 4).is_err());
    }
}

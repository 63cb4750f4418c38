//! OME-Zarr stores of a voxelization (docs/zarr.md), the steps `csgpix voxelize --format
//! zarr` and the Python binding (`zarr_create`, `zarr_write_rows`, run as Dask tasks by
//! `csgpix.distributed`) share: the store's metadata, the memory of writing its chunk rows,
//! and those rows (or their bricks of some XY tiles) voxelized (§4.4) and stored.

use std::ops::Range;
use std::path::Path;

use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{Grid, PixelBox, Route, Slicer, Work};
use csgpix_zarr::{voxelize_bricks, voxelize_rows, Layout, VolumeAttrs, ZarrVolume};
use rtl_model::EquationSet;

use crate::memory::imports_estimate;
use crate::Error;

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

/// Whether the store is written brick by brick (a chunk row of one XY tile: the run route)
/// rather than a whole chunk row at a time.
pub fn by_bricks(route: Route) -> bool {
    matches!(route, Route::Runs { .. })
}

/// The memory of voxelizing chunk rows of a store cut by `layout` on the slicer's grid with
/// `threads` threads (docs/memory.md): on the run route a tile's runs (of `tiles`, a task's
/// share of [`ZarrVolume::tiles`], or of any tile) and the writer's bricks, else the rows'
/// slabs, the writer's and the imports' samples.
pub fn estimate(
    slicer: &Slicer,
    route: Route,
    eval: &dyn SliceEval,
    threads: usize,
    (layout, tiles): (&Layout, Option<Range<usize>>),
) -> Result<u64, csgpix_zarr::Error> {
    let grid = &slicer.grid;
    if by_bricks(route) {
        let levels = csgpix_zarr::plan(grid.dims, layout)?;
        let tile = csgpix_zarr::tile(grid.dims, &levels);
        let writer = csgpix_zarr::writer_bytes_bricks(grid.dims, layout, threads)?;
        // A task's tiles: only their panels' datasets are walked to count their runs.
        let boxes = csgpix_zarr::tile_boxes(grid.dims, tile);
        let within = tiles.and_then(|t| boxes.get(t)).map(|b| {
            let all = b.iter().copied().reduce(PixelBox::union);
            all.unwrap_or(PixelBox::new(0, 0, 0, 0))
        });
        let runs = csgpix_voxel::runs::memory_estimate_bricks(slicer, eval, threads, tile, within);
        return Ok(runs.saturating_add(writer));
    }
    let prims = slicer.primitive_count();
    let rows = csgpix_zarr::memory_estimate(grid, layout, prims, threads)?;
    Ok(rows.saturating_add(imports_estimate(slicer)))
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
            voxelize_bricks(slicer, float, set, eval, tick, store, rows, tiles)
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

//! How a store is cut and what writing it holds in memory: the chunk, shard and level plan
//! of a grid, the tiles written at a time, and the bytes the writers hold.

use super::*;

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

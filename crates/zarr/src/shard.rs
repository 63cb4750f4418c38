//! Shard files of Zarr v3's `sharding_indexed` codec, written as a stream: each inner chunk
//! is gzipped and appended to its shard's file as soon as it is compressed, and the index
//! (an offset and a length per inner chunk, little-endian u64, C order; both `u64::MAX` for
//! an empty one) goes at the end (`index_location: "end"`). A shard is therefore never held
//! whole: a run holds a batch of compressed inner chunks, not a shard (docs/zarr.md says why
//! zarrs's own shard encoder is not used to write them; zarrs reads them back in the tests).
//!
//! <https://zarr-specs.readthedocs.io/en/latest/v3/codecs/sharding-indexed/index.html>

use std::collections::HashMap;
use std::fs::File;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use csgpix_output::staged_write;
use rayon::prelude::*;

use crate::pyramid::all_equal;
use crate::{Error, Result, StoreProblem, GZIP_LEVEL};

/// Inner chunks compressed at once per thread of the pool: the batch is held compressed
/// until it is appended, in order, to the shard files.
pub(crate) const BATCH_PER_THREAD: usize = 2;

/// zlib's worst case for `n` bytes in a gzip member (zarrs's `GzipCodec` bound): what a
/// compressed inner chunk can take.
pub(crate) fn gzip_bound(n: u64) -> u64 {
    n + 10 + 8 + n.div_ceil(8) + n.div_ceil(64) + 5
}

/// gzip of `data` at [`GZIP_LEVEL`], as zarrs's gzip codec writes it (header time 0).
pub(crate) fn gzip(data: &[u8]) -> std::io::Result<Vec<u8>> {
    let mut e = flate2::read::GzEncoder::new(data, flate2::Compression::new(GZIP_LEVEL));
    let mut out = Vec::with_capacity(gzip_bound(data.len() as u64) as usize);
    e.read_to_end(&mut out)?;
    Ok(out)
}

/// One level's chunk row, or a brick's part of it, as the writer sees it: the slices and
/// how the level is cut.
pub(crate) struct RowCut<'a> {
    /// The slabs' slices in order, each `nx × ny`, X fastest.
    pub slices: &'a [u8],
    /// The voxels along X and Y (the brick's at this level), and the row's slabs.
    pub nx: usize,
    pub ny: usize,
    pub slabs: usize,
    /// The inner chunk, Z, Y, X (Z: the row's depth at this level).
    pub chunk: [usize; 3],
    /// The level's chunk (j, i) the slices start at (0, 0 for a whole row).
    pub at: [usize; 2],
    /// What each chunk of the cut holds where the caller knows it (row-major, `ny / cy`
    /// rounded up by `nx / cx` rounded up): `Some(v)` when every voxel is `v`, None when
    /// unknown. Without it the writer looks at the voxels.
    pub known: Option<&'a [Option<u8>]>,
}

/// What an inner chunk holds, padded with 0 past the grid's edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Held {
    /// Every voxel 0: no chunk is written.
    Empty,
    /// Every voxel one non-zero value (a chunk inside a part).
    Uniform(u8),
    /// Anything else.
    Mixed,
}

impl RowCut<'_> {
    /// The chunks across X and Y of the cut.
    pub fn grid(&self) -> (usize, usize) {
        (
            self.ny.div_ceil(self.chunk[1]),
            self.nx.div_ceil(self.chunk[2]),
        )
    }

    /// The voxels of chunk (bj, bi) inside the grid, Y then X, and one of its lines.
    fn extent<'s>(
        &'s self,
        bj: usize,
        bi: usize,
    ) -> (usize, usize, impl Fn(usize, usize) -> &'s [u8]) {
        let [_, cy, cx] = self.chunk;
        let (j0, i0) = (bj * cy, bi * cx);
        let (h, w) = (cy.min(self.ny - j0), cx.min(self.nx - i0));
        let line = move |z: usize, y: usize| {
            let src = (z * self.ny + j0 + y) * self.nx + i0;
            &self.slices[src..src + w]
        };
        (h, w, line)
    }

    /// What chunk (bj, bi) of the cut holds: as the caller knows it, or from its voxels.
    pub fn held(&self, bj: usize, bi: usize) -> Held {
        let whole = |h: usize, w: usize| [self.slabs, h, w] == self.chunk;
        let (h, w, line) = self.extent(bj, bi);
        let known = self.known.and_then(|k| k[bj * self.grid().1 + bi]);
        let first = match known {
            Some(v) => v,
            None => {
                let first = line(0, 0)[0];
                let same = (0..self.slabs).all(|z| (0..h).all(|y| all_equal(line(z, y), first)));
                if !same {
                    return Held::Mixed;
                }
                first
            }
        };
        match first {
            0 => Held::Empty,
            // Padding past the grid's edge is 0: such a chunk is not one value.
            v if whole(h, w) => Held::Uniform(v),
            _ => Held::Mixed,
        }
    }

    /// Chunk (bj, bi) copied out, padded with 0.
    pub(crate) fn copy(&self, bj: usize, bi: usize) -> Vec<u8> {
        let [cz, cy, cx] = self.chunk;
        let (h, w, line) = self.extent(bj, bi);
        let mut chunk = vec![0u8; cz * cy * cx];
        for z in 0..self.slabs {
            for y in 0..h {
                let dst = (z * cy + y) * cx;
                chunk[dst..dst + w].copy_from_slice(line(z, y));
            }
        }
        chunk
    }
}

/// A compressed chunk, shared where it is one value's.
type Packed = Arc<Vec<u8>>;

/// Compressed chunks of one value throughout, by value and shape: most of a large volume's
/// chunks are inside or outside every part, and gzip gives the same bytes for the same
/// chunk, so each is compressed once per run.
/// It counts the chunks it is given by what they hold.
#[derive(Default)]
pub(crate) struct UniformChunks {
    cache: Mutex<HashMap<(u8, [usize; 3]), Packed>>,
    /// Chunks packed: empty (no bytes), one value (from the cache), mixed (compressed).
    pub counts: [AtomicU64; 3],
}

impl UniformChunks {
    fn get(&self, v: u8, chunk: [usize; 3]) -> std::io::Result<Arc<Vec<u8>>> {
        let mut map = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(c) = map.get(&(v, chunk)) {
            return Ok(c.clone());
        }
        let bytes = Arc::new(gzip(&vec![v; chunk.iter().product()])?);
        map.insert((v, chunk), bytes.clone());
        Ok(bytes)
    }

    /// One more chunk that holds `held`.
    pub fn count(&self, held: Held) {
        let i = match held {
            Held::Empty => 0,
            Held::Uniform(_) => 1,
            Held::Mixed => 2,
        };
        self.counts[i].fetch_add(1, Ordering::Relaxed);
    }

    /// Chunk (bj, bi) of `cut` compressed: None when empty, from the cache when one value.
    pub fn pack(
        &self,
        cut: &RowCut,
        bj: usize,
        bi: usize,
    ) -> std::io::Result<Option<Arc<Vec<u8>>>> {
        let held = cut.held(bj, bi);
        self.count(held);
        match held {
            Held::Empty => Ok(None),
            Held::Uniform(v) => self.get(v, cut.chunk).map(Some),
            Held::Mixed => gzip(&cut.copy(bj, bi)).map(|c| Some(Arc::new(c))),
        }
    }
}

/// The shard being written.
struct Open {
    /// Shard (sj, si) of the row.
    at: (usize, usize),
    path: PathBuf,
    file: Option<File>,
    /// Offset and length of each inner chunk, C order; `u64::MAX` for none.
    index: Vec<u64>,
    end: u64,
}

/// Write one level's chunk row `row` as shard files `dir/c/ROW/SJ/SI` of `per` (Y, X) inner
/// chunks each: every shard with a non-zero voxel, and no file (an existing one removed) for
/// the others. Inner chunks are compressed a batch at a time on rayon's pool and appended in
/// C order, so the bytes do not depend on the threads. The files are not synced: the store
/// is, once, when it is whole ([`crate::ZarrVolume::sync`]). Returns the shard files
/// written.
pub(crate) fn write_row(
    dir: &Path,
    row: usize,
    cut: &RowCut,
    per: [usize; 2],
    uniform: &UniformChunks,
) -> Result<u64> {
    let (gy, gx) = cut.grid();
    let (shy, shx) = (gy.div_ceil(per[0]), gx.div_ceil(per[1]));
    // The cut starts on a shard ([`crate::tile`]): its shards are the level's from here.
    debug_assert!(cut.at[0].is_multiple_of(per[0]) && cut.at[1].is_multiple_of(per[1]));
    let first = [cut.at[0] / per[0], cut.at[1] / per[1]];
    let io = |path: &Path, e: std::io::Error| Error::Store {
        path: path.to_path_buf(),
        message: StoreProblem::Io(e.into()),
    };
    // Every inner chunk of the row in the grid, shard by shard (row-major), each shard's in
    // its C order: (shard, index in the shard, chunk j, chunk i).
    let mut items = (0..shy * shx).flat_map(|s| {
        let (sj, si) = (s / shx, s % shx);
        (0..per[0] * per[1]).filter_map(move |q| {
            let (bj, bi) = (sj * per[0] + q / per[1], si * per[1] + q % per[1]);
            (bj < gy && bi < gx).then_some(((sj, si), q, bj, bi))
        })
    });
    let batch = BATCH_PER_THREAD * rayon::current_num_threads().max(1);
    let mut open: Option<Open> = None;
    let mut written = 0u64;
    loop {
        let todo: Vec<_> = items.by_ref().take(batch).collect();
        if todo.is_empty() {
            break;
        }
        let packed: Vec<Option<Arc<Vec<u8>>>> = todo
            .par_iter()
            .map(|&(_, _, bj, bi)| uniform.pack(cut, bj, bi))
            .collect::<std::io::Result<_>>()
            .map_err(|e| io(dir, e))?;
        for (&(at, q, _, _), bytes) in todo.iter().zip(packed) {
            if open.as_ref().is_none_or(|o| o.at != at) {
                if let Some(o) = open.take() {
                    finish(o)?;
                }
                open = Some(Open {
                    at,
                    path: dir.join(format!("c/{row}/{}/{}", first[0] + at.0, first[1] + at.1)),
                    file: None,
                    index: vec![u64::MAX; 2 * per[0] * per[1]],
                    end: 0,
                });
            }
            let (Some(o), Some(bytes)) = (open.as_mut(), bytes) else {
                continue;
            };
            if o.file.is_none() {
                // Directories are made, and the file created, never after a signal's cleanup
                // has removed a staged store (crates/output); once open, writes
                // land in the file whatever becomes of its name.
                let _writing = staged_write().ok_or(Error::Interrupted)?;
                if let Some(parent) = o.path.parent() {
                    std::fs::create_dir_all(parent).map_err(|e| io(parent, e))?;
                }
                o.file = Some(File::create(&o.path).map_err(|e| io(&o.path, e))?);
                written += 1;
            }
            let file = o.file.as_mut().expect("opened above");
            file.write_all(&bytes).map_err(|e| io(&o.path, e))?;
            o.index[2 * q] = o.end;
            o.index[2 * q + 1] = bytes.len() as u64;
            o.end += bytes.len() as u64;
        }
    }
    if let Some(o) = open.take() {
        finish(o)?;
    }
    Ok(written)
}

/// The shard's index appended, or its stale file removed when it has no inner chunk.
fn finish(o: Open) -> Result<()> {
    let io = |e: std::io::Error| Error::Store {
        path: o.path.clone(),
        message: StoreProblem::Io(e.into()),
    };
    let Some(mut file) = o.file else {
        return remove_stale(&o.path);
    };
    let index: Vec<u8> = o.index.iter().flat_map(|v| v.to_le_bytes()).collect();
    file.write_all(&index).map_err(io)
}

/// Remove the file an earlier write left at `path` for a chunk or shard now all 0.
pub(crate) fn remove_stale(path: &Path) -> Result<()> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(Error::Store {
            path: path.to_path_buf(),
            message: StoreProblem::Io(e.into()),
        }),
        _ => Ok(()),
    }
}

/// Write a chunk file whole at `path` (not synced: the store is, once, when it is whole),
/// its directories made first, never after a signal's cleanup has removed a staged store
/// (crates/output).
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    let io = |p: &Path, e: std::io::Error| Error::Store {
        path: p.to_path_buf(),
        message: StoreProblem::Io(e.into()),
    };
    let _writing = staged_write().ok_or(Error::Interrupted)?;
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| io(parent, e))?;
    }
    std::fs::write(path, bytes).map_err(|e| io(path, e))
}

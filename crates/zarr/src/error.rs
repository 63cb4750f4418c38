//! The error of `csgpix-zarr`: its own problems, one line each, and the voxelizer's, kept
//! whole. No message names a command-line flag: where a caller needs to tell a case apart
//! (to name its own flags), the error has a variant of its own.

use std::path::PathBuf;

/// An error of `csgpix-zarr`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// The voxelizer's error (with the scene's `FILE:LINE:COL` where it has one).
    #[error(transparent)]
    Voxel(#[from] csgpix_voxel::Error),
    /// A chunk shape with a side of 0.
    #[error("chunk shape {chunk:?} (z, y, x): every side needs at least one voxel")]
    BadChunk {
        /// The shape asked for, Z, Y, X.
        chunk: [usize; 3],
    },
    /// Shards of 0 chunks a side.
    #[error("shards of 0 chunks a side: give 1 (no shards) or more")]
    BadShard,
    /// More pyramid levels than the grid and the chunk depth allow ([`crate::max_levels`]).
    #[error(
        "{levels} levels: this grid and chunk depth {depth} allow 1 to {max} (each level \
         halves a chunk row, so 2^(levels-1) must divide the depth when the grid has more than \
         one row; no level past a 1x1x1 one)"
    )]
    BadLevels {
        /// Levels asked for.
        levels: usize,
        /// The most allowed.
        max: usize,
        /// Level 0's chunk depth (cut to the grid).
        depth: usize,
    },
    /// `create` was pointed at something other than a new or empty directory: it writes a
    /// whole store, and stale chunks of another would read as voxels.
    #[error("{}: exists and is not an empty directory", .path.display())]
    NotEmpty {
        /// The path.
        path: PathBuf,
    },
    /// The store at `path` is not a volume this crate wrote (or is damaged).
    #[error("{}: not a csgpix Zarr volume: {reason}", .path.display())]
    NotAVolume {
        /// The store's directory.
        path: PathBuf,
        /// What is missing or wrong.
        reason: String,
    },
    /// Reading or writing the store failed (the filesystem, or zarrs).
    #[error("{}: {message}", .path.display())]
    Store {
        /// The store's directory (or the file in it).
        path: PathBuf,
        /// The system's or zarrs's error.
        message: StoreProblem,
    },
    /// A chunk row index past the volume's rows.
    #[error("chunk row {row}: the volume has rows 0..{rows}")]
    RowRange {
        /// The row asked for.
        row: usize,
        /// How many rows the volume has.
        rows: usize,
    },
    /// A range of chunk rows that is reversed or runs past the volume's rows.
    #[error("chunk rows {start}..{end}: the volume has rows 0..{rows}")]
    RowsRange {
        /// First row asked for.
        start: usize,
        /// One past the last.
        end: usize,
        /// How many rows the volume has.
        rows: usize,
    },
    /// A chunk row's bytes are not its slabs' slices.
    #[error("chunk row {row}: expected {expected} bytes (slabs {slabs} of {nx}x{ny}), got {got}")]
    RowLength {
        /// The row.
        row: usize,
        /// Bytes it needs: slabs × nx × ny.
        expected: usize,
        /// Bytes given.
        got: usize,
        /// Slabs in the row.
        slabs: usize,
        /// Voxels along X.
        nx: usize,
        /// Voxels along Y.
        ny: usize,
    },
    /// Columns that are neither the whole grid nor one of the volume's tiles.
    #[error("columns {columns}: a brick is the whole grid or one tile of {tile:?} (X, Y) voxels")]
    BadBrick {
        /// The columns given.
        columns: String,
        /// The volume's tile.
        tile: [usize; 2],
    },
    /// The slicer's grid is not the one the volume was created for.
    #[error(
        "the grid {found} is not the volume's {expected}: voxelize on the grid it was created for"
    )]
    GridMismatch {
        /// The volume's grid (dims and box).
        expected: String,
        /// The slicer's.
        found: String,
    },
    /// A signal is stopping the run and removing its staged outputs: nothing more is
    /// written ([`csgpix_output::staged_write`]).
    #[error("interrupted: the run's outputs are being removed")]
    Interrupted,
    /// A pyramid level past the store's levels.
    #[error("level {level}: the store has {levels}")]
    LevelRange {
        /// The level asked for.
        level: usize,
        /// How many levels the store has.
        levels: usize,
    },
    /// Bricks were asked of a slicer the run route does not apply to.
    #[error("bricks take the run route, which does not apply to grey datasets or blends")]
    NoRunRoute,
    /// A writing thread panicked (its panic message went to standard error).
    #[error("{thread} panicked")]
    Panicked {
        /// Which thread: `a chunk writer`, `a sync thread`.
        thread: &'static str,
    },
}

/// Why reading or writing a store failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum StoreProblem {
    /// The system's error, with its kind (a missing directory, a full disk, ...).
    #[error(transparent)]
    Io(#[from] csgpix_scene::IoError),
    /// zarrs's error, as zarrs words it (its errors can be neither cloned nor compared).
    #[error("{0}")]
    Zarrs(String),
}

/// A `csgpix-zarr` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

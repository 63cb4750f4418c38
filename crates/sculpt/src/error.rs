//! The error of `csgpix-sculpt`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where the fix is a
//! setting ([`Error::OverBudget`], [`Error::BadTool`]) the error carries the figures and the
//! command line words it.

use csgpix_scene::{Location, OneLine};

/// An error of `csgpix-sculpt`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A scene error (a path file's `FILE:LINE:COL`, a volume's header).
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// A voxel store would hold more than its memory budget (bytes).
    #[error(
        "the voxel store needs more than {} MiB (limit {} MiB)",
        need >> 20,
        budget >> 20
    )]
    OverBudget {
        /// Bytes the store needs (at least).
        need: u64,
        /// Bytes it may hold.
        budget: u64,
    },
    /// A tool description that is not `sphere:R` with a radius in range.
    #[error("tool {spec:?}: {reason}")]
    BadTool {
        /// The description as given.
        spec: String,
        /// What is wrong with it.
        reason: ToolProblem,
    },
    /// A tool whose radius is out of range ([`ToolProblem::RadiusRange`]).
    #[error(transparent)]
    Tool(ToolProblem),
    /// A spring stiffness k (seed 000 §6, F = k·ΔX) that is negative or not finite.
    #[error("the stiffness must be a finite number >= 0")]
    BadStiffness,
    /// The voxelizer feeding a store failed (with the scene's `FILE:LINE:COL` where it has
    /// one).
    #[error(transparent)]
    Voxel(#[from] Box<csgpix_voxel::Error>),
    /// A grid side needs more octree levels than a key holds.
    #[error("a side of {side} voxels needs {depth} octree levels; at most {max} fit a key")]
    TooDeep {
        /// The grid's longest side, voxels.
        side: usize,
        /// Levels it needs.
        depth: u32,
        /// Levels a key holds.
        max: u32,
    },
    /// More octree nodes than a table indexes (2^32 - 1).
    #[error("more than 2^32 - 1 octree nodes")]
    TooManyNodes,
    /// A cell layer pushed past the octree's side or shorter than a layer.
    #[error("cell layer {layer} of {cells} cells: not a layer of this octree")]
    BadLayer {
        /// The layer's index.
        layer: usize,
        /// Cells given.
        cells: usize,
    },
    /// A pointer octree finished without a root node.
    #[error("the pointer octree has no root")]
    NoRoot,
    /// A build finished before all its cell layers came.
    #[error("the octree got {got} of {want} cell layers")]
    MissingLayers {
        /// Layers pushed.
        got: usize,
        /// Layers the octree has.
        want: usize,
    },
    /// A voxel slice came out of order.
    #[error("voxel slice {got} arrived, slice {expected} was expected")]
    SliceOrder {
        /// The slice that came.
        got: usize,
        /// The slice due.
        expected: usize,
    },
    /// A voxel slice past the octree's side.
    #[error("voxel slice {slice} is past the octree's side {side}")]
    SlicePastSide {
        /// The slice.
        slice: usize,
        /// The octree's side, voxels.
        side: usize,
    },
    /// A cell the octree does not hold as asked.
    #[error("cell ({}, {}, {}) {problem}", cell[0], cell[1], cell[2])]
    Cell {
        /// The cell, X, Y, Z.
        cell: [u32; 3],
        /// What is wrong.
        problem: CellProblem,
    },
    /// A tool path file without a position: `file` as given.
    #[error("{}: no tool positions: give one row x,y,z per step", OneLine(file))]
    NoToolPositions {
        /// The file.
        file: String,
    },
    /// A volume whose voxel steps are not positive and along the axes.
    #[error("space directions: sculpting needs positive axis-aligned voxel steps")]
    NotAxisAligned,
    /// A problem about `what` (e.g. the file it concerns): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns.
        what: String,
        /// The problem.
        source: Box<Error>,
    },
}

/// What is wrong with a tool description.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ToolProblem {
    /// It does not start with `sphere:`.
    #[error("expected sphere:R (R in voxels)")]
    NotSphere,
    /// The radius is not a number.
    #[error("radius: {0}")]
    Radius(std::num::ParseFloatError),
    /// The radius is not in (0, [`crate::MAX_RADIUS`]].
    #[error(
        "the sphere's radius must be more than 0 and at most {} voxels",
        crate::MAX_RADIUS
    )]
    RadiusRange,
}

/// What is wrong with a cell of an octree.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum CellProblem {
    /// It lies outside the octree.
    #[error("is outside the octree")]
    Outside,
    /// No leaf covers it.
    #[error("has no leaf")]
    NoLeaf,
    /// Its leaf went missing after a split.
    #[error("vanished")]
    Vanished,
}

impl From<csgpix_voxel::Error> for Error {
    fn from(e: csgpix_voxel::Error) -> Error {
        Error::Voxel(Box::new(e))
    }
}

/// A `csgpix-sculpt` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Where in its input the problem is, when it has a place there.
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::Scene(e) => e.location(),
            Error::Voxel(e) => e.location(),
            Error::Context { source, .. } => source.location(),
            _ => None,
        }
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns).
    pub fn context(self, what: impl std::fmt::Display) -> Self {
        match self {
            Error::Scene(e) => Error::Scene(e.context(what)),
            e => Error::Context {
                what: what.to_string(),
                source: Box::new(e),
            },
        }
    }
}

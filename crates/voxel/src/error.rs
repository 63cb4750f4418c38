//! The error of `csgpix-voxel`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where a caller needs to
//! tell a case apart (to name its own flags), the error has a variant of its own.

use std::path::PathBuf;

use csgpix_scene::Location;

/// An error of `csgpix-voxel`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Error {
    /// A scene error.
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// A drawing error.
    #[error(transparent)]
    Draw(#[from] csgpix_draw::Error),
    /// The scene has no primitive, so no box of its own: a grid over it needs bounds given.
    #[error("the scene has no primitives")]
    NeedsBounds,
    /// A CSG expression over named primitives (§4.3.2) could not be read: the reader's
    /// message, one line.
    #[error("the expression: {0}")]
    Expr(String),
    /// A primitive name of the expression is bound to no file.
    #[error("primitive `{name}` is bound to no file")]
    Unbound {
        /// The name.
        name: String,
    },
    /// A primitive name's binding to a file ([`crate::sampled::Binding`]) is wrong.
    #[error("primitive `{name}`: {problem}")]
    Binding {
        /// The name bound.
        name: String,
        /// What is wrong with it.
        problem: BindingProblem,
    },
    /// The slicer was given a different number of loaded imports than the scene names.
    #[error("the scene imports {named} files but {loaded} are loaded")]
    ImportsNotLoaded {
        /// Imports the scene names.
        named: usize,
        /// Imports given.
        loaded: usize,
    },
    /// A slab range that is empty-reversed or runs past the grid.
    #[error("slabs {start}..{end}: the grid has slabs 0..{slabs}")]
    SlabRange {
        /// First slab asked for.
        start: usize,
        /// One past the last.
        end: usize,
        /// The grid's slabs (NZ).
        slabs: usize,
    },
    /// A problem of this crate's own, one line.
    #[error("{0}")]
    Msg(String),
}

/// What is wrong with a primitive name's binding to a file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BindingProblem {
    /// The expression does not name the primitive.
    #[error("the expression has no such primitive")]
    NotInExpression,
    /// A threshold was given with a `.csg` scene.
    #[error("a threshold applies to datasets only")]
    ThresholdOnScene,
    /// A threshold was given with a mesh.
    #[error("a threshold applies to datasets (.nrrd) only")]
    ThresholdOnMesh,
    /// A dataset was given without its iso value.
    #[error("a dataset needs its iso value: NAME=FILE.nrrd,threshold=T")]
    NeedsThreshold,
    /// The file is of no format read here.
    #[error(
        "{}: csgpix reads .csg scenes, .stl and .obj meshes and .nrrd datasets \
         (PLY, OFF and others: convert to STL or OBJ)",
        .0.display()
    )]
    UnknownFormat(PathBuf),
    /// The file does not exist: `file` as given, `path` where it was looked for.
    #[error("`import(\"{file}\")`: no such file {}", .path.display())]
    NoSuchFile {
        /// The file as given.
        file: String,
        /// Where it was looked for.
        path: PathBuf,
    },
}

/// A `csgpix-voxel` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Where in its input the problem is, when it has a place there.
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::Scene(e) => e.location(),
            Error::Draw(e) => e.location(),
            _ => None,
        }
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns). Typed
    /// variants other than the wrapped errors become one-line messages.
    pub fn context(self, what: impl std::fmt::Display) -> Self {
        match self {
            Error::Scene(e) => Error::Scene(e.context(what)),
            Error::Draw(e) => Error::Draw(e.context(what)),
            e => Error::Msg(format!("{what}: {e}")),
        }
    }
}

csgpix_scene::message_conversions!(Error, Error::Msg);

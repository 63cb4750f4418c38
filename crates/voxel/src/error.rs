//! The error of `csgpix-voxel`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where a caller needs to
//! tell a case apart (to name its own flags), the error has a variant of its own.

use std::path::PathBuf;

use csgpix_scene::{Location, OneLine};

/// An error of `csgpix-voxel`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A scene error.
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// A drawing error.
    #[error(transparent)]
    Draw(#[from] csgpix_draw::Error),
    /// The volume's bytes could not be allocated: the system had less than the estimate
    /// said (another process took it, or a limit the estimate could not see).
    #[error("the volume: {0}")]
    OutOfMemory(#[from] csgpix_output::AllocFailed),
    /// The scene has no primitive, so no box of its own: a grid over it needs bounds given.
    #[error("the scene has no primitives")]
    NeedsBounds,
    /// A CSG expression over named primitives (§4.3.2) could not be read: its line (always
    /// 1) and column, and the reader's error.
    #[error("the expression: {0}")]
    Expr(ExprError),
    /// A primitive binding `NAME=FILE[,threshold=T]` that does not parse.
    #[error("{spec:?}: {problem}")]
    BadBinding {
        /// The binding as given.
        spec: String,
        /// What is wrong with it.
        problem: BindingSyntax,
    },
    /// A primitive name of the expression is bound to no file.
    #[error("primitive `{name}` is bound to no file")]
    Unbound {
        /// The name.
        name: String,
        /// Where the expression first names it: the column (1-based, in characters) of line 1.
        col: usize,
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
    /// A program the array refuses (a clipping stack too shallow for it, say).
    #[error(transparent)]
    Program(#[from] rtl_model::program::ProgramError),
    /// A plane of solid `solid` (0-based) does not fit the depth word.
    #[error("solid {}: {message}", solid + 1)]
    Plane {
        /// The solid.
        solid: usize,
        /// The plane's field at fault (0 Z0, 1 dZx, 2 dZy).
        field: usize,
        /// What is wrong, as the compiler words it.
        message: String,
    },
    /// A brick of columns and slabs that is not inside the grid.
    #[error("brick {columns:?} × slabs {slabs:?} is not inside the grid {}x{}x{}", dims[0], dims[1], dims[2])]
    BrickRange {
        /// The columns asked for.
        columns: crate::pixel_box::PixelBox,
        /// The slabs asked for.
        slabs: std::ops::Range<usize>,
        /// The grid's voxels, X, Y, Z.
        dims: [usize; 3],
    },
    /// More slices than the depth word can tell apart.
    #[error(
        "{slices} slices do not fit the depth word ({frac} fraction and {int} integer bits): \
         use fewer slices or a wider word (e.g. 10/11/12)"
    )]
    TooManySlices {
        /// Slices asked for.
        slices: usize,
        /// The word's fraction bits.
        frac: u32,
        /// The word's integer bits.
        int: u32,
    },
    /// A caller's slice sink failed to write: the system's error.
    #[error(transparent)]
    Sink(csgpix_scene::IoError),
    /// A problem about `what` (e.g. the primitive it concerns): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns.
        what: String,
        /// The problem.
        source: Box<Error>,
    },
}

/// Why a CSG expression over named primitives could not be read: `1:col: error` (the
/// expression is one line; the line is said all the same, as every located error says it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("1:{col}: {}", .error.problem())]
pub struct ExprError {
    /// The column (1-based, in characters) of the problem.
    pub col: usize,
    /// The reader's error, located in the expression.
    pub error: csgpix_scene::Error,
}

/// What is wrong with the text of a primitive binding.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BindingSyntax {
    /// There is no `=`.
    #[error("expected NAME=FILE[,threshold=T]")]
    NoEquals,
    /// The threshold is not a number.
    #[error("threshold {text:?}: {error}")]
    Threshold {
        /// The threshold as given.
        text: String,
        /// Why it does not parse.
        error: std::num::ParseFloatError,
    },
    /// The threshold is infinite or NaN.
    #[error("the threshold must be finite")]
    NotFinite,
    /// The name is not letters, digits and `_` starting with a letter.
    #[error("{name:?} is not a primitive name (letters, digits, _)")]
    BadName {
        /// The name given.
        name: String,
    },
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
        "{}: csgpix reads .csg scenes, .stl, .obj, .off, .amf and .3mf meshes and .nrrd \
         datasets (PLY and others: convert to STL or OBJ)",
        OneLine(.0.display())
    )]
    UnknownFormat(PathBuf),
    /// The file does not exist: `file` as given, `path` where it was looked for.
    #[error("`import(\"{}\")`: no such file {}", OneLine(file), OneLine(.path.display()))]
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
            Error::Context { source, .. } => source.location(),
            _ => None,
        }
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns): the
    /// wrapped errors take it in, the others are wrapped in [`Error::Context`].
    pub fn context(self, what: impl std::fmt::Display) -> Self {
        match self {
            Error::Scene(e) => Error::Scene(e.context(what)),
            Error::Draw(e) => Error::Draw(e.context(what)),
            e => Error::Context {
                what: what.to_string(),
                source: Box::new(e),
            },
        }
    }
}

//! The error of `csgpix-draw`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where the fix is a
//! setting, the error carries what to set ([`Error::DeeperThanMaxdepth`]) and the command
//! line words it.

use csgpix_scene::{Location, OneLine};
use rtl_model::WordFormat;

use crate::compile::CompileError;

/// An error of `csgpix-draw`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A scene error.
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// The projected scene reaches maxdepth (§2.4.1): `detail` says how deep it is on which
    /// array, `suggested` is the narrowest word (same fraction and overflow bits) whose
    /// maxdepth lies beyond it.
    #[error(
        "{detail}: use a {}/{}/{} depth word or a smaller array",
        suggested.frac, suggested.int, suggested.ovf
    )]
    DeeperThanMaxdepth {
        /// `the scene is D depth units deep on a WxH array, beyond maxdepth M`.
        detail: String,
        /// The word that would hold the scene.
        suggested: WordFormat,
    },
    /// Solid `solid` (0-based) of a scene does not compile (§5.2).
    #[error("solid {}: {error}", solid + 1)]
    Solid {
        /// Index of the solid (and of its display list).
        solid: usize,
        /// The plane and field at fault.
        error: CompileError,
    },
    /// The clipping function or tree does not compile as a whole (§5.2): what is wrong.
    #[error("{}", .0.msg)]
    Clip(CompileError),
    /// Binning a scene into panels would take more than `limit` panels of `panel` pixels
    /// (`cols` x `rows` of them).
    #[error(
        "{cols}x{rows} panels of {}x{}: more than {limit} to bin (use larger panels)",
        panel.0, panel.1
    )]
    TooManyPanels {
        /// Panels across.
        cols: usize,
        /// Panels down.
        rows: usize,
        /// One panel's width and height, pixels.
        panel: (usize, usize),
        /// The most panels binned.
        limit: usize,
    },
    /// A polygon was given fewer than 3 vertices.
    #[error("a polygon needs at least 3 vertices, got {got}")]
    TooFewVertices {
        /// How many were given.
        got: usize,
    },
    /// A program the array refuses (a clipping stack too shallow for it, say).
    #[error(transparent)]
    Program(#[from] rtl_model::program::ProgramError),
    /// A projected scene with no solids: nothing fixes its scale.
    #[error("the scene has no solids")]
    NoSolids,
    /// A polygon whose turns go both ways.
    #[error("the polygon is not convex: split it into convex pieces")]
    NotConvex,
    /// A polygon without area.
    #[error("the polygon has no area")]
    NoArea,
    /// A line with ends at one point or a width not positive.
    #[error("a line needs two distinct ends and a positive width")]
    BadLine,
    /// The cycle counter a caller gave to [`crate::panels`] failed: its message.
    #[error("{0}")]
    Counter(String),
    /// A problem about `what` (e.g. the primitive it concerns): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns.
        what: String,
        /// The problem.
        source: Box<Error>,
    },
}

/// A `csgpix-draw` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Where in its input the problem is, when it has a place there.
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::Scene(e) => e.location(),
            Error::Context { source, .. } => source.location(),
            _ => None,
        }
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns).
    pub fn context(self, what: impl std::fmt::Display) -> Self {
        match self {
            Error::Scene(e) => Error::Scene(e.context(what)),
            Error::DeeperThanMaxdepth { detail, suggested } => Error::DeeperThanMaxdepth {
                detail: format!("{what}: {detail}"),
                suggested,
            },
            e => Error::Context {
                what: what.to_string(),
                source: Box::new(e),
            },
        }
    }
}

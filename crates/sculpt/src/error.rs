//! The error of `csgpix-sculpt`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where the fix is a
//! setting ([`Error::OverBudget`], [`Error::BadTool`]) the error carries the figures and the
//! command line words it.

use csgpix_scene::Location;

/// An error of `csgpix-sculpt`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
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
        reason: String,
    },
    /// A spring stiffness k (seed 000 §6, F = k·ΔX) that is negative or not finite.
    #[error("the stiffness must be a finite number >= 0")]
    BadStiffness,
    /// A problem of this crate's own, one line.
    #[error("{0}")]
    Msg(String),
}

/// A `csgpix-sculpt` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Where in its input the problem is, when it has a place there.
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::Scene(e) => e.location(),
            _ => None,
        }
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns).
    pub fn context(self, what: impl std::fmt::Display) -> Self {
        match self {
            Error::Scene(e) => Error::Scene(e.context(what)),
            Error::Msg(m) => Error::Msg(format!("{what}: {m}")),
            e => Error::Msg(format!("{what}: {e}")),
        }
    }
}

csgpix_scene::message_conversions!(Error, Error::Msg);

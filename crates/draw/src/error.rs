//! The error of `csgpix-draw`:
//! its own problems, one line each, and those of the crates it builds on, kept whole (with their
//! `FILE:LINE:COL` location). No message names a command-line flag: where the fix is a
//! setting, the error carries what to set ([`Error::DeeperThanMaxdepth`]) and the command
//! line words it.

use csgpix_scene::Location;
use rtl_model::WordFormat;

use crate::compile::CompileError;

/// An error of `csgpix-draw`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
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
    /// A problem of this crate's own, one line.
    #[error("{0}")]
    Msg(String),
}

/// A `csgpix-draw` result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Where in its input the problem is, when it has a place there.
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::Scene(e) => e.location(),
            Error::DeeperThanMaxdepth { .. } | Error::Solid { .. } | Error::Msg(_) => None,
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
            e @ Error::Solid { .. } => Error::Msg(format!("{what}: {e}")),
            Error::Msg(m) => Error::Msg(format!("{what}: {m}")),
        }
    }
}

csgpix_scene::message_conversions!(Error, Error::Msg);

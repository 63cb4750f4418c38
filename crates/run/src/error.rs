//! The run layer's error: every way a command can refuse or fail, typed, each variant one
//! line as the command line prints it (`csgpix: MESSAGE`, exit status 2). The libraries'
//! errors are kept whole ([`Error::Scene`], [`Error::Voxel`], …) so a caller (the Python
//! binding) reads their fields, e.g. a scene error's file, line and column.

use std::path::PathBuf;

use csgpix_output::OneLine;

/// A command's error.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A scene reader's or writer's error (located in its input where it has a place).
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// The voxelizer's.
    #[error(transparent)]
    Voxel(#[from] csgpix_voxel::Error),
    /// Drawing a scene on the array.
    #[error(transparent)]
    Draw(#[from] csgpix_draw::Error),
    /// Loading a scene for drawing.
    #[error(transparent)]
    Load(#[from] csgpix_draw::scenes::LoadError),
    /// An output that cannot be named, staged or committed.
    #[error(transparent)]
    Output(#[from] csgpix_output::Error),
    /// A voxel store's or sculpting's.
    #[error(transparent)]
    Sculpt(#[from] csgpix_sculpt::Error),
    /// A Zarr store's.
    #[error(transparent)]
    #[cfg(feature = "zarr")]
    Zarr(#[from] csgpix_zarr::Error),
    /// A program the array cannot run (its stack, its windows).
    #[error(transparent)]
    Program(#[from] rtl_model::program::ProgramError),
    /// An array configuration the processor model refuses (`--size`, `--word`, the stack).
    #[error(transparent)]
    Config(#[from] rtl_model::state::ConfigError),
    /// A probe outside the array (`--probe`).
    #[error(transparent)]
    Probe(#[from] rtl_model::probe::ProbeOutside),
    /// Golden vectors that contradict one another (the derived equations' tables).
    #[error(transparent)]
    Table(#[from] rtl_model::select::vectors::TableConflict),
    /// Golden vectors of the Verilog twin that do not parse.
    #[error(transparent)]
    Golden(#[from] rtl_model::verilog::GoldenError),
    /// A program that does not compile for the array (the scene-wide compile errors of
    /// `requirements` and the study, which have no file place): the draw compiler's error,
    /// said of the solid it comes from; printed as `solid N: MESSAGE`, or the message alone
    /// where it is the whole program's.
    #[error("{}{}", solid_prefix(.solid), OneLine(&.error.msg))]
    Compile {
        /// The solid (0-based) whose plane the array cannot take; None for the whole
        /// program's (its clipping stack, a concave clipping volume).
        solid: Option<usize>,
        /// The compiler's error: the plane and field at fault, and what is wrong.
        error: csgpix_draw::compile::CompileError,
    },
    /// Tiles of a Zarr store's bricks (the Python binding's `tiles=(t0, t1)`) outside the
    /// store's, or not all of them where the run goes a chunk row at a time: only the run
    /// route voxelizes some tiles apart (docs/zarr.md).
    #[error(
        "tiles ({start}, {end}): the store has tiles 0..{tiles}, and only the run route \
         voxelizes some of them"
    )]
    Tiles {
        /// The first tile asked for.
        start: usize,
        /// One past the last.
        end: usize,
        /// The store's tiles.
        tiles: usize,
    },
    /// Golden vectors that do not fit the table they are checked against.
    #[error(transparent)]
    Vectors(#[from] rtl_model::select::verify::VectorError),
    /// A scene that does not read once the study sets its tessellation (`$fn`).
    #[error("{source} (with $fn = {fragments})")]
    Tessellation {
        /// The `$fn` the scene was read with.
        fragments: u32,
        /// The reader's error.
        source: csgpix_scene::Error,
    },
    /// A run refused before it allocated: over the memory limit.
    #[error(transparent)]
    Memory(#[from] crate::memory::OverMemory),
    /// Options the command cannot take together, or one it needs and was not given: `flag`
    /// names the option at fault, `message` says what to change (naming it).
    #[error("{}", OneLine(message))]
    Options {
        /// The option at fault, as the command line spells it (`--json`, `--probe`, `-o`).
        flag: &'static str,
        /// The whole line.
        message: String,
    },
    /// A file that could not be read or written.
    #[error("{}: {source}", OneLine(path.display()))]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// An error and what it happened to: an input's name, a flag (`what: source`).
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// The input or option it concerns.
        what: String,
        /// The error itself.
        source: Box<Error>,
    },
    /// A chart that could not be drawn.
    #[error(transparent)]
    Plot(#[from] crate::plot::PlotError),
    /// The worker threads could not be started.
    #[error(transparent)]
    Threads(#[from] rayon::ThreadPoolBuildError),
    /// A report that could not be written as JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
}

/// `solid N: ` of a compile error said of solid N − 1, else nothing.
fn solid_prefix(solid: &Option<usize>) -> String {
    solid.map_or_else(String::new, |i| format!("solid {}: ", i + 1))
}

/// A run's result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Options refused together or alone: `flag` the one at fault, `message` the line.
    pub fn options(flag: &'static str, message: impl Into<String>) -> Error {
        Error::Options {
            flag,
            message: message.into(),
        }
    }

    /// This error, said of `what` (an input's name, a flag).
    pub fn context(self, what: impl Into<String>) -> Error {
        Error::Context {
            what: what.into(),
            source: Box::new(self),
        }
    }

    /// The innermost scene error, where this error is one (or wraps one): its location is
    /// where the problem is in an input.
    pub fn scene(&self) -> Option<&csgpix_scene::Error> {
        match self {
            Error::Scene(e) => Some(e),
            Error::Voxel(csgpix_voxel::Error::Scene(e)) => Some(e),
            Error::Load(csgpix_draw::scenes::LoadError::Scene(e)) => Some(e),
            Error::Tessellation { source, .. } => Some(source),
            Error::Context { source, .. } => source.scene(),
            _ => None,
        }
    }

    /// The system's kind of failure, when a file could not be read or written (an input,
    /// through the scene's error, or an output), through any context.
    pub fn io_kind(&self) -> Option<std::io::ErrorKind> {
        match self {
            Error::Output(e) => e.io_kind(),
            Error::Io { source, .. } => Some(source.kind()),
            Error::Context { source, .. } => source.io_kind(),
            e => e.scene().and_then(csgpix_scene::Error::io_kind),
        }
    }
}

pub use crate::value::{BadValue, Parsed};

#[cfg(test)]
mod tests {
    use super::*;
    use csgpix_draw::compile::{CompileError, WHOLE_PROGRAM};

    /// A compile error prints as it did as text: `solid N: ` and the compiler's message (not
    /// its `plane N: ` form), or the message alone for the whole program's.
    #[test]
    fn a_compile_error_prints_its_solid_and_the_compilers_message() {
        let error = |field| CompileError {
            plane: 4,
            field,
            msg: "dZx: out of range".into(),
        };
        let of_solid = Error::Compile {
            solid: Some(2),
            error: error(1),
        };
        assert_eq!(of_solid.to_string(), "solid 3: dZx: out of range");
        let whole = Error::Compile {
            solid: None,
            error: error(WHOLE_PROGRAM),
        };
        assert_eq!(whole.to_string(), "dZx: out of range");
    }
}

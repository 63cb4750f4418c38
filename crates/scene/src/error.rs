//! The error of every scene reader and writer: one line, located in its input where it has a
//! place there (`FILE:LINE:COL: message`), never naming a command-line flag (the CLI adds
//! those). The place, the file that could not be read and the context are fields
//! ([`Error::location`], [`Error::io_kind`]), so a caller need not parse the message.

use std::fmt;

/// Where in an input a problem is: 1-based line and column (in characters). Binary inputs
/// are located by byte offset instead, as line 0 and column = offset + 1.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The input's name as the user gave it (a path, or a name such as `<expr>`).
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub col: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", OneLine(&self.file), self.line, self.col)
    }
}

pub use csgpix_output::{IoError, OneLine};

/// A scene error: what went wrong and, for bad input, where.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// Bad input at a place in it (a `.csg`, `.dl` or mesh file, an expression, an NRRD
    /// header): `at: problem`.
    #[error("{at}: {problem}")]
    At {
        /// Where.
        at: Location,
        /// What is wrong there.
        problem: Box<Error>,
    },
    /// A problem about `what` (a path, a primitive, an output's name): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns, as the user would name it.
        what: String,
        /// The problem.
        source: Box<Error>,
    },
    /// A file or directory could not be read, written or created: the system's error. The
    /// path is in an enclosing [`Error::Context`] (`path: system message`, see [`Error::io`])
    /// or [`Error::At`].
    #[error(transparent)]
    Io(IoError),
    /// A grid was asked over a scene with no solids, so it has no bounds of its own: the
    /// caller has to give a box.
    #[error("the scene has no solids: give the grid's bounds")]
    NeedsBounds,
    /// A grid resolution with a side of 0 voxels.
    #[error("resolution {dims:?}: every side needs at least one voxel")]
    EmptyResolution {
        /// The resolution asked for, X, Y, Z.
        dims: [usize; 3],
    },
    /// A grid (padding included) with more voxels along an axis than csgpix allows.
    #[error("a grid of {dims:?} voxels: at most {limit} per axis")]
    GridTooLarge {
        /// The grid's voxels, X, Y, Z.
        dims: [usize; 3],
        /// The most voxels along an axis ([`crate::grid::MAX_GRID_SIDE`]).
        limit: usize,
    },
    /// An output that cannot be written (a writer's path, refused or failed).
    #[error(transparent)]
    Output(#[from] csgpix_output::Error),
    /// A program csgpix runs (openscad) did not finish within its time limit: it was
    /// killed. The caller names the setting that raises the limit.
    #[error("{program} did not finish within {} s", Seconds(*limit))]
    TimedOut {
        /// The program.
        program: String,
        /// The limit it was given.
        limit: std::time::Duration,
    },
    /// Input whose content breaks its format's rules or a setting's range: what is wrong,
    /// one line (the place, when it has one, is in an enclosing [`Error::At`]).
    #[error("{}", OneLine(.0))]
    Invalid(String),
}

/// The cases of [`Error`] a caller may need to tell apart (to name its own option, say).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Kind {
    /// Any other problem: the message says it all.
    #[default]
    Other,
    /// A grid was asked over a scene with no solids ([`Error::NeedsBounds`]).
    NeedsBounds,
    /// A program did not finish within its time limit ([`Error::TimedOut`]).
    TimedOut,
}

/// A scene result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// A time limit in seconds: `300`, or `0.5` when not whole.
struct Seconds(std::time::Duration);

impl fmt::Display for Seconds {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.subsec_nanos() {
            0 => write!(f, "{}", self.0.as_secs()),
            _ => write!(f, "{}", self.0.as_secs_f64()),
        }
    }
}

impl Error {
    /// An error at `file:line:col`.
    ///
    /// ```
    /// use csgpix_scene::Error;
    ///
    /// let e = Error::at("a.dl", 3, 7, "expected a number");
    /// assert_eq!(e.to_string(), "a.dl:3:7: expected a number");
    /// assert_eq!(e.in_file("b.dl").to_string(), "b.dl:3:7: expected a number");
    /// ```
    pub fn at(
        file: impl Into<String>,
        line: usize,
        col: usize,
        message: impl Into<String>,
    ) -> Self {
        let file = file.into();
        Error::At {
            at: Location { file, line, col },
            problem: Box::new(Error::invalid(message)),
        }
    }

    /// This error at `file:line:col`.
    pub fn located(self, file: impl Into<String>, line: usize, col: usize) -> Self {
        let file = file.into();
        Error::At {
            at: Location { file, line, col },
            problem: Box::new(self),
        }
    }

    /// Invalid input with no place in it.
    pub fn invalid(message: impl Into<String>) -> Self {
        Error::Invalid(message.into())
    }

    /// A failure of the system on `path`: `path: system message`.
    pub fn io(path: impl fmt::Display, e: &std::io::Error) -> Self {
        Error::Io(e.into()).context(path)
    }

    /// Which case it is, for callers that word [`Kind::NeedsBounds`] or [`Kind::TimedOut`]
    /// their own way.
    pub fn kind(&self) -> Kind {
        match self {
            Error::NeedsBounds => Kind::NeedsBounds,
            Error::TimedOut { .. } => Kind::TimedOut,
            Error::Context { source: e, .. } | Error::At { problem: e, .. } => e.kind(),
            _ => Kind::Other,
        }
    }

    /// Where in its input the problem is, when it has a place there.
    ///
    /// ```
    /// use csgpix_scene::Error;
    ///
    /// let e = Error::at("a.dl", 3, 7, "expected a number").context("plane 2");
    /// assert_eq!(e.to_string(), "a.dl:3:7: plane 2: expected a number");
    /// assert_eq!(e.location().map(|l| l.line), Some(3));
    /// ```
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::At { at, .. } => Some(at),
            Error::Context { source, .. } => source.location(),
            _ => None,
        }
    }

    /// The problem without its place: for [`Error::At`] what is wrong there, else the whole
    /// error.
    pub fn problem(&self) -> &Error {
        match self {
            Error::At { problem, .. } => problem,
            e => e,
        }
    }

    /// The system's kind of failure, when a file could not be read or written.
    ///
    /// ```
    /// use csgpix_scene::Error;
    /// use std::io::ErrorKind;
    ///
    /// let e = csgpix_scene::input::read_text("no/such.csg".as_ref()).unwrap_err();
    /// assert_eq!(e.io_kind(), Some(ErrorKind::NotFound));
    /// assert!(e.to_string().starts_with("no/such.csg: "));
    /// ```
    pub fn io_kind(&self) -> Option<std::io::ErrorKind> {
        match self {
            Error::Io(e) => Some(e.kind),
            Error::Output(e) => e.io_kind(),
            Error::At { problem: e, .. } | Error::Context { source: e, .. } => e.io_kind(),
            _ => None,
        }
    }

    /// The same error located in `file` instead (the caller's name for the input, e.g. the
    /// option an expression came from); unchanged when it has no location.
    pub fn in_file(self, file: impl Into<String>) -> Self {
        match self {
            Error::At { mut at, problem } => {
                at.file = file.into();
                Error::At { at, problem }
            }
            Error::Context { what, source } => Error::Context {
                what,
                source: Box::new(source.in_file(file)),
            },
            e => e,
        }
    }

    /// The same error, its problem after `what: ` (e.g. the primitive it concerns), the
    /// place, if any, still first.
    pub fn context(self, what: impl fmt::Display) -> Self {
        match self {
            Error::At { at, problem } => Error::At {
                at,
                problem: Box::new(problem.context(what)),
            },
            e => Error::Context {
                what: what.to_string(),
                source: Box::new(e),
            },
        }
    }
}

impl From<Error> for String {
    fn from(e: Error) -> String {
        e.to_string()
    }
}

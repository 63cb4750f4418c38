//! The error of every scene reader and writer: one line, located in its input where it has a
//! place there (`FILE:LINE:COL: message`), never naming a command-line flag (the CLI adds
//! those).

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
        write!(f, "{}:{}:{}", self.file, self.line, self.col)
    }
}

/// A scene error: what went wrong and, for bad input, where.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub struct Error {
    /// Where in its input, when the problem has a place there.
    pub location: Option<Location>,
    /// What went wrong, one line.
    pub message: String,
    /// Which case it is, where a caller words or handles one differently.
    pub kind: Kind,
}

/// The cases of [`Error`] a caller may need to tell apart (to name its own option, say).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Kind {
    /// Any other problem: the message says it all.
    #[default]
    Other,
    /// A grid was asked over a scene with no solids, so it has no bounds of its own: the
    /// caller has to give a box.
    NeedsBounds,
}

/// A scene result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // One line always: a quoted name or literal may hold line breaks.
        let msg = self.message.replace('\r', "\\r").replace('\n', "\\n");
        match &self.location {
            Some(at) => write!(f, "{at}: {msg}"),
            None => f.write_str(&msg),
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
        Error {
            location: Some(Location { file, line, col }),
            message: message.into(),
            kind: Kind::Other,
        }
    }

    /// An error with no place in an input.
    pub fn msg(message: impl Into<String>) -> Self {
        Error {
            location: None,
            message: message.into(),
            kind: Kind::Other,
        }
    }

    /// An error of kind `kind`, with no place in an input.
    pub fn of_kind(kind: Kind, message: impl Into<String>) -> Self {
        Error {
            kind,
            ..Error::msg(message)
        }
    }

    /// The same error located in `file` instead (the caller's name for the input, e.g. the
    /// option an expression came from); unchanged when it has no location.
    pub fn in_file(mut self, file: impl Into<String>) -> Self {
        if let Some(at) = &mut self.location {
            at.file = file.into();
        }
        self
    }

    /// The same error, its message after `what: ` (e.g. the primitive it concerns).
    pub fn context(mut self, what: impl fmt::Display) -> Self {
        self.message = format!("{what}: {}", self.message);
        self
    }
}

/// The conversions every csgpix error type has: from a one-line message (`String`, `&str`)
/// through `$msg`, and to a `String` for callers that still speak in one-line strings (the
/// command line). `message_conversions!(Error, Error::Msg)` in the crate that defines `Error`.
#[macro_export]
macro_rules! message_conversions {
    ($err:ty, $msg:path) => {
        impl From<String> for $err {
            fn from(m: String) -> Self {
                $msg(m)
            }
        }

        impl From<&str> for $err {
            fn from(m: &str) -> Self {
                $msg(m.to_string())
            }
        }

        impl From<$err> for String {
            fn from(e: $err) -> String {
                e.to_string()
            }
        }
    };
}

message_conversions!(Error, Error::msg);

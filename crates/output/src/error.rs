//! The error of naming, staging and committing outputs: one line, the path or the option at
//! fault first (`-o v.png: is a directory`), the system's kind of failure a field
//! ([`Error::io_kind`]) so a caller need not parse the message.

use std::fmt;

/// A system error reading or writing a file: its kind, for a caller to tell a missing file
/// from a forbidden one, and the system's message.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct IoError {
    /// What kind of failure it is.
    pub kind: std::io::ErrorKind,
    /// The system's message (`No such file or directory (os error 2)`).
    pub message: String,
}

impl From<&std::io::Error> for IoError {
    fn from(e: &std::io::Error) -> IoError {
        IoError {
            kind: e.kind(),
            message: e.to_string(),
        }
    }
}

impl From<std::io::Error> for IoError {
    fn from(e: std::io::Error) -> IoError {
        IoError::from(&e)
    }
}

/// An output that cannot be written.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A problem about `what` (an option and its path, a path): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns, as the user would name it (`-o v.png`).
        what: String,
        /// The problem.
        source: Box<Error>,
    },
    /// The system refused to create, write or rename a file or directory. The path is in an
    /// enclosing [`Error::Context`] (see [`Error::io`]).
    #[error(transparent)]
    Io(IoError),
    /// An output's directory (or a parent of it) is a file.
    #[error("{} is not a directory", OneLine(path))]
    NotADirectory {
        /// The path, as shown.
        path: String,
    },
    /// A path csgpix will not write to, or outputs that cannot be written together.
    #[error(transparent)]
    Refused(#[from] Refusal),
}

/// Why a path is refused as an output, before anything is computed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Refusal {
    /// `-` given for a directory output.
    #[error("a directory of files cannot go to standard output")]
    DirectoryToStdout,
    /// A directory output's path names something else.
    #[error("exists and is not a directory")]
    ExistsNotDirectory,
    /// A directory output written as one file.
    #[error("is a directory output")]
    DirectoryOutput,
    /// A file output asked for its staging directory.
    #[error("{}: is not a directory output", OneLine(shown))]
    NotDirectoryOutput {
        /// The output's path, as named.
        shown: String,
    },
    /// A file of a directory output named with a path separator, a leading dot or nothing.
    #[error("{}: bad file name {}", OneLine(shown), OneLine(&format!("{name:?}")))]
    BadFileName {
        /// The directory output's path, as named.
        shown: String,
        /// The file name asked for.
        name: String,
    },
    /// `-` given for an output that is never standard output.
    #[error("{} -: this output cannot go to standard output", OneLine(flag))]
    NotToStdout {
        /// The option.
        flag: String,
    },
    /// Two outputs named `-`.
    #[error(
        "only one output can be - (standard output): {} and {}",
        OneLine(first),
        OneLine(second)
    )]
    TwoStdout {
        /// The first, as named.
        first: String,
        /// The second, as named.
        second: String,
    },
    /// Two outputs naming one file (after symlinks).
    #[error("{} and {} name the same file", OneLine(first), OneLine(second))]
    SameFile {
        /// The first, as named.
        first: String,
        /// The second, as named.
        second: String,
    },
    /// A directory written whole that would replace one csgpix did not write.
    #[error(
        "exists and holds no {}: only a directory csgpix could have written is replaced \
         (remove it first)",
        OneLine(marker)
    )]
    NotReplaceable {
        /// The file that marks a directory of the format (`zarr.json`).
        marker: String,
    },
    /// A series of files written whole (`--slices`) that would replace a directory holding
    /// something else.
    #[error(
        "exists and holds {}, which is not one of csgpix's {} files: only a directory csgpix \
         could have written is replaced (remove it first)",
        OneLine(entry),
        OneLine(series)
    )]
    NotSeries {
        /// The first entry found that is not a file of the series.
        entry: String,
        /// The series' names, the digits shown as `N` (`slice-N.png`).
        series: String,
    },
    /// A directory written whole named by `.`, `..` or `/`, which cannot be renamed.
    #[error("names no directory that can be replaced whole: give its name (not . or ..)")]
    NoName,
    /// More than 40 symbolic links in a row.
    #[error("too many levels of symbolic links")]
    SymlinkLoop,
    /// A file output's path is a directory.
    #[error("is a directory")]
    IsDirectory,
    /// A block device.
    #[error("is a block device: csgpix writes files, FIFOs and character devices")]
    BlockDevice,
    /// A socket or another special file.
    #[error("is a socket or other special file: csgpix writes files, FIFOs and character devices")]
    SpecialFile,
    /// Not a regular file (systems without FIFOs and devices).
    #[error("is not a regular file")]
    NotRegularFile,
    /// A name whose extension is not the format's.
    #[error(
        "the name must end in {}: the extension names the format written",
        Extensions(expected)
    )]
    Extension {
        /// The extensions the format takes, without their dot.
        expected: Vec<String>,
    },
}

/// A result of this crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Text shown on one line, as a terminal shows it: a name or an input's fragment echoed in an
/// error may hold line breaks or other control characters (NUL, VT, FF, NEL, U+2028), which
/// would break the one line, move the cursor or vanish. Each is written escaped, Rust style:
/// `\0`, `\t`, `\n`, `\r`, `\x0b` for the other C0 controls and DEL, `\u{85}` for the C1
/// controls and the Unicode line and paragraph separators. Everything else, backslashes
/// included, is written as it is, so escaping twice changes nothing.
///
/// ```
/// use csgpix_output::OneLine;
///
/// assert_eq!(OneLine("a\nb\0c\x0bd\u{85}e\u{2028}").to_string(), r"a\nb\0c\x0bd\u{85}e\u{2028}");
/// assert_eq!(OneLine(r"C:\dir\n").to_string(), r"C:\dir\n");
/// ```
pub struct OneLine<T>(pub T);

impl<T: fmt::Display> fmt::Display for OneLine<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = self.0.to_string();
        let mut rest = text.as_str();
        while let Some(at) = rest.find(needs_escape) {
            let c = rest[at..].chars().next().expect("found at a character");
            f.write_str(&rest[..at])?;
            write_escaped(f, c)?;
            rest = &rest[at + c.len_utf8()..];
        }
        f.write_str(rest)
    }
}

/// Control characters (C0, DEL, C1) and the Unicode line and paragraph separators.
fn needs_escape(c: char) -> bool {
    c.is_control() || matches!(c, '\u{2028}' | '\u{2029}')
}

fn write_escaped(f: &mut fmt::Formatter<'_>, c: char) -> fmt::Result {
    match c {
        '\0' => f.write_str("\\0"),
        '\t' => f.write_str("\\t"),
        '\n' => f.write_str("\\n"),
        '\r' => f.write_str("\\r"),
        c if c.is_ascii() => write!(f, "\\x{:02x}", u32::from(c)),
        c => write!(f, "\\u{{{:x}}}", u32::from(c)),
    }
}

/// `.a`, `.a or .b`, `.a, .b or .c`.
struct Extensions<'a>(&'a [String]);

impl fmt::Display for Extensions<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Some((last, rest)) = self.0.split_last() else {
            return Ok(());
        };
        for (i, e) in rest.iter().enumerate() {
            let sep = if i + 1 == rest.len() { " or " } else { ", " };
            write!(f, ".{}{sep}", OneLine(e))?;
        }
        write!(f, ".{}", OneLine(last))
    }
}

impl Error {
    /// A failure of the system on `path`: `path: system message`.
    pub fn io(path: impl fmt::Display, e: &std::io::Error) -> Self {
        Error::Io(e.into()).context(path)
    }

    /// This error about `what`: `what: self`.
    pub fn context(self, what: impl fmt::Display) -> Self {
        Error::Context {
            what: what.to_string(),
            source: Box::new(self),
        }
    }

    /// The system's kind of failure, if the system refused (a missing directory, a
    /// forbidden one), through any context.
    pub fn io_kind(&self) -> Option<std::io::ErrorKind> {
        match self {
            Error::Io(e) => Some(e.kind),
            Error::Context { source, .. } => source.io_kind(),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extensions_are_listed_as_a_sentence() {
        let ext = |v: &[&str]| {
            Refusal::Extension {
                expected: v.iter().map(|s| s.to_string()).collect(),
            }
            .to_string()
        };
        let tail = ": the extension names the format written";
        assert_eq!(ext(&["png"]), format!("the name must end in .png{tail}"));
        assert_eq!(
            ext(&["nrrd", "gz"]),
            format!("the name must end in .nrrd or .gz{tail}")
        );
        assert_eq!(
            ext(&["obj", "ply", "stl"]),
            format!("the name must end in .obj, .ply or .stl{tail}")
        );
    }

    #[test]
    fn context_keeps_the_kind_and_one_line() {
        let e = Error::io("a\nb", &std::io::Error::from(std::io::ErrorKind::NotFound));
        assert_eq!(e.io_kind(), Some(std::io::ErrorKind::NotFound));
        assert!(e.to_string().starts_with("a\\nb: "), "{e}");
        assert_eq!(Error::from(Refusal::IsDirectory).io_kind(), None);
    }
}

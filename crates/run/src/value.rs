//! An option's value that does not parse (`--res 0x1`, `res=(0, 1, 1)`): the error of every
//! value parser of the run layer, in a leaf module so that the modules whose flags parse values (memory, voxelize, …) and the
//! run layer's error (which wraps theirs) do not depend on each other.

/// An option's value that does not parse: the reason, one line, which the command line
/// prints after the flag and the value.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct BadValue(pub String);

impl From<&str> for BadValue {
    fn from(s: &str) -> BadValue {
        BadValue(s.into())
    }
}

impl From<String> for BadValue {
    fn from(s: String) -> BadValue {
        BadValue(s)
    }
}

/// `Result` of a flag's value parser.
pub type Parsed<T> = std::result::Result<T, BadValue>;

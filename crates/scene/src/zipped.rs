//! Zip archives holding a mesh (a 3MF package, a zipped AMF), read with the `zip` crate
//! (deflate and stored entries only) and bounded against zip bombs: the bytes inflated from one
//! archive may not pass [`inflate_limit`] of its size, whatever its headers claim.

use std::io::{Cursor, Read};

use zip::ZipArchive;

use crate::{Error, Result};

/// Deflate inflates at most about 1032:1; XML meshes compress some 3 to 10 times. An archive
/// may inflate to this many times its own size (or [`MIN_INFLATE`], for small ones) ...
pub(crate) const INFLATE_RATIO: u64 = 100;
/// ... at least this many bytes ...
pub(crate) const MIN_INFLATE: u64 = 16 << 20;
/// ... and never more than this (the XML is then parsed into a tree of about the same size
/// again, [`crate::meshfile::MAX_XML_NODES`]).
pub(crate) const MAX_INFLATE: u64 = 1 << 30;

/// The most bytes an archive of `len` bytes may inflate to.
pub(crate) fn inflate_limit(len: u64) -> u64 {
    len.saturating_mul(INFLATE_RATIO).clamp(MIN_INFLATE, MAX_INFLATE)
}

/// Whether `bytes` start as a zip archive does (a local file header).
pub(crate) fn is_zip(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04")
}

/// An open archive, `file` in its errors, with what is left of its inflate budget.
pub(crate) struct Archive<'a> {
    zip: ZipArchive<Cursor<&'a [u8]>>,
    file: &'a str,
    left: u64,
}

impl<'a> Archive<'a> {
    /// Reads the central directory; a truncated or damaged archive is one line.
    pub(crate) fn open(bytes: &'a [u8], file: &'a str) -> Result<Archive<'a>> {
        let zip = ZipArchive::new(Cursor::new(bytes)).map_err(|e| {
            Error::invalid(format!(
                "{file}: not a readable zip archive ({} bytes): {e}",
                bytes.len()
            ))
        })?;
        Ok(Archive {
            zip,
            file,
            left: inflate_limit(bytes.len() as u64),
        })
    }

    /// The entries' names, in the archive's order.
    pub(crate) fn names(&self) -> Vec<String> {
        self.zip.file_names().map(str::to_string).collect()
    }

    /// The bytes of entry `name`, `None` when there is none. Refused in one line, naming the
    /// entry and its byte offset: an entry that would pass the archive's inflate budget (its
    /// declared size checked first, then the bytes actually inflated), an unsupported
    /// compression, damaged data or a wrong checksum.
    pub(crate) fn read(&mut self, name: &str) -> Result<Option<Vec<u8>>> {
        let (file, left) = (self.file, self.left);
        let mut entry = match self.zip.by_name(name) {
            Ok(e) => e,
            Err(zip::result::ZipError::FileNotFound) => return Ok(None),
            Err(e) => {
                let msg = format!("{file}: zip entry `{name}`: {e}");
                return Err(Error::invalid(msg));
            }
        };
        let at = entry.header_start();
        let here = |msg: String| {
            Error::invalid(format!(
                "{file}: zip entry `{name}` (byte offset {at}): {msg}"
            ))
        };
        let bomb = || {
            here(format!(
                "inflates past {left} bytes, more than csgpix allows for an archive of this \
                 size ({INFLATE_RATIO} times, at least {MIN_INFLATE}, at most {MAX_INFLATE} \
                 bytes): a zip bomb or a damaged archive"
            ))
        };
        if entry.size() > left {
            return Err(bomb());
        }
        let mut out = Vec::new();
        (&mut entry)
            .take(left + 1)
            .read_to_end(&mut out)
            .map_err(|e| here(e.to_string()))?;
        // Fewer than `left + 1` bytes: the entry's end was reached (and its CRC checked).
        if out.len() as u64 > left {
            return Err(bomb());
        }
        self.left -= out.len() as u64;
        Ok(Some(out))
    }
}

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
    len.saturating_mul(INFLATE_RATIO)
        .clamp(MIN_INFLATE, MAX_INFLATE)
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
            let reason = e.to_string();
            Error::NotZip {
                bytes: bytes.len(),
                reason,
            }
            .context(file)
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
                let reason = e.to_string();
                let e = Error::ZipEntry { reason }.context(format_args!("zip entry `{name}`"));
                return Err(e.context(file));
            }
        };
        let at = entry.header_start();
        let here = |e: Error| {
            e.context(format_args!("zip entry `{name}` (byte offset {at})"))
                .context(file)
        };
        let bomb = || {
            here(Error::ZipBomb {
                left,
                ratio: INFLATE_RATIO,
                min: MIN_INFLATE,
                max: MAX_INFLATE,
            })
        };
        if entry.size() > left {
            return Err(bomb());
        }
        let mut out = Vec::new();
        (&mut entry)
            .take(left + 1)
            .read_to_end(&mut out)
            .map_err(|e| {
                here(Error::ZipEntry {
                    reason: e.to_string(),
                })
            })?;
        // Fewer than `left + 1` bytes: the entry's end was reached (and its CRC checked).
        if out.len() as u64 > left {
            return Err(bomb());
        }
        self.left -= out.len() as u64;
        Ok(Some(out))
    }
}

/// Zip archives for the readers' tests.
#[cfg(test)]
pub(crate) mod testing {
    use std::io::Write;

    use zip::write::SimpleFileOptions;
    use zip::{CompressionMethod, ZipWriter};

    /// An archive of `entries`, deflated.
    pub(crate) fn archive(entries: &[(&str, &[u8])]) -> Vec<u8> {
        let mut w = ZipWriter::new(std::io::Cursor::new(Vec::new()));
        let opts = SimpleFileOptions::default()
            .compression_method(CompressionMethod::Deflated)
            .large_file(false);
        for (name, bytes) in entries {
            w.start_file(*name, opts).unwrap();
            w.write_all(bytes).unwrap();
        }
        w.finish().unwrap().into_inner()
    }
}

#[cfg(test)]
mod tests {
    use super::testing::archive;
    use super::*;

    fn read(bytes: &[u8], name: &str) -> Result<Option<Vec<u8>>> {
        Archive::open(bytes, "t.zip")?.read(name)
    }

    #[test]
    fn entries_are_read_by_name() {
        let z = archive(&[("a/b.txt", b"hello"), ("c", b"")]);
        assert!(is_zip(&z));
        let mut a = Archive::open(&z, "t.zip").unwrap();
        assert_eq!(a.names(), ["a/b.txt", "c"]);
        assert_eq!(a.read("a/b.txt").unwrap().unwrap(), b"hello");
        assert_eq!(a.read("c").unwrap().unwrap(), b"");
        assert!(a.read("b.txt").unwrap().is_none());
    }

    #[test]
    fn a_zip_bomb_is_refused_in_one_line() {
        // 40 MiB of zeros deflate to some 40 KB: far past 100 times that (and past 16 MiB).
        let zeros = vec![0u8; 40 << 20];
        let z = archive(&[("bomb", &zeros)]);
        assert!(z.len() < 100_000, "{}", z.len());
        let e = read(&z, "bomb").unwrap_err().to_string();
        assert!(
            e.starts_with("t.zip: zip entry `bomb` (byte offset 0): inflates past 16777216 bytes"),
            "{e}"
        );
        assert_eq!(e.lines().count(), 1);
        // The same archive whose header understates the size: the inflated bytes are counted.
        let mut lying = z.clone();
        let cd = lying.windows(4).rposition(|w| w == b"PK\x01\x02").unwrap();
        lying[cd + 24..cd + 28].copy_from_slice(&5u32.to_le_bytes());
        lying[22..26].copy_from_slice(&5u32.to_le_bytes());
        let e = read(&lying, "bomb").unwrap_err().to_string();
        assert!(
            e.contains("inflates past") || e.contains("byte offset 0"),
            "{e}"
        );
        assert_eq!(e.lines().count(), 1);
        // Several entries share one budget.
        let half = vec![0u8; 10 << 20];
        let z = archive(&[("a", &half), ("b", &half)]);
        let mut a = Archive::open(&z, "t.zip").unwrap();
        a.read("a").unwrap();
        assert!(a
            .read("b")
            .unwrap_err()
            .to_string()
            .contains("inflates past 6291456 bytes"));
    }

    #[test]
    fn truncated_and_damaged_archives_are_one_line() {
        let z = archive(&[("m", &b"<model/>".repeat(1000))]);
        for cut in [0, 4, 30, z.len() / 2, z.len() - 1] {
            let e = match Archive::open(&z[..cut], "t.zip") {
                Err(e) => e.to_string(),
                Ok(mut a) => match a.read("m") {
                    Err(e) => e.to_string(),
                    Ok(_) => panic!("cut at {cut} read"),
                },
            };
            assert!(e.starts_with("t.zip: "), "{e}");
            assert_eq!(e.lines().count(), 1, "{e}");
        }
        // A flipped byte in the deflated data: a bad stream or a wrong checksum.
        let mut bad = z.clone();
        bad[40] ^= 0xff;
        let e = read(&bad, "m").unwrap_err().to_string();
        assert!(
            e.starts_with("t.zip: zip entry `m` (byte offset 0): "),
            "{e}"
        );
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}

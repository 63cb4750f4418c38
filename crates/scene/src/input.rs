//! Reading text inputs: invalid UTF-8 is reported where it is, `FILE:LINE:COL`.

use std::path::Path;

use crate::{Error, Result};

/// The text of `path`; its name in errors is `path` as given.
pub fn read_text(path: &Path) -> Result<String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| Error::io(&name, &e))?;
    text(bytes, &name)
}

/// `bytes` as text, or `FILE:LINE:COL: invalid UTF-8 …` at the first bad byte: LINE counts
/// from 1, COL is 1 + the characters before it on its line.
pub fn text(bytes: Vec<u8>, file: &str) -> Result<String> {
    String::from_utf8(bytes).map_err(|e| {
        let (line, col, problem) =
            bad_utf8(e.as_bytes()).expect("invalid UTF-8 has a first bad byte");
        Error::at(file, line, col, problem)
    })
}

/// Line, column and problem ([`Error::BadUtf8`]) of the first invalid UTF-8 byte of
/// `bytes`, if any.
pub fn bad_utf8(bytes: &[u8]) -> Option<(usize, usize, Error)> {
    let at = std::str::from_utf8(bytes).err()?.valid_up_to();
    let (line, col) = position(&bytes[..at]);
    Some((line, col, Error::BadUtf8 { byte: bytes[at] }))
}

/// Line and column just past `valid` (valid UTF-8 by construction).
fn position(valid: &[u8]) -> (usize, usize) {
    let line_start = valid.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
    let col = 1 + std::str::from_utf8(&valid[line_start..]).map_or(0, |s| s.chars().count());
    (line, col)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_bad_byte_is_located_by_line_and_character() {
        let e = text(b"cube();\n  \xc3\xa9x\xff;\n".to_vec(), "a.csg")
            .unwrap_err()
            .to_string();
        // Line 2: two spaces, é (one character, two bytes), x, then the bad byte.
        assert_eq!(
            e,
            "a.csg:2:5: invalid UTF-8 (byte 0xFF): text inputs are UTF-8"
        );
        let e = text(b"\x80".to_vec(), "b").unwrap_err().to_string();
        assert!(e.starts_with("b:1:1: "), "{e}");
        // A sequence cut short at the end.
        let e = text(b"ab\xe2\x82".to_vec(), "c").unwrap_err().to_string();
        assert!(e.starts_with("c:1:3: "), "{e}");
        assert_eq!(text(b"ok\n".to_vec(), "d").unwrap(), "ok\n");
    }
}

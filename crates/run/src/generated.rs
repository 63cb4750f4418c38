//! Files a job generates from the model (the golden select vectors, the Verilog twin):
//! written into a directory all or none, or only compared with what is there (`--check`).

use std::path::{Path, PathBuf};

use serde::Serialize;

/// What [`write_generated`] did: the files written, or with `check` the files that differ
/// from what would be written (none: the directory is up to date).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct GeneratedReport {
    /// Whether the files were only compared.
    pub checked: bool,
    /// The files written, in order (none when checked).
    pub written: Vec<PathBuf>,
    /// With `checked`: the files whose contents differ, or that are missing.
    pub differs: Vec<PathBuf>,
}

/// Write `files` (name, text) into directory `out`, all or none (the directory named
/// `--out`); with `check`, only compare them with the files there.
pub fn write_generated(
    files: &[(String, String)],
    out: &Path,
    check: bool,
) -> crate::Result<GeneratedReport> {
    if check {
        let differs = files
            .iter()
            .map(|(name, text)| (out.join(name), text))
            .filter(|(path, text)| std::fs::read_to_string(path).unwrap_or_default() != **text)
            .map(|(path, _)| path)
            .collect();
        return Ok(GeneratedReport {
            checked: true,
            written: vec![],
            differs,
        });
    }
    let mut outs = csgpix_output::Outputs::new();
    let dir = outs.dir("--out", out)?;
    for (name, text) in files {
        outs.write_in(dir, name, |w| w.write_all(text.as_bytes()))?;
    }
    outs.commit()?;
    Ok(GeneratedReport {
        checked: false,
        written: files.iter().map(|(name, _)| out.join(name)).collect(),
        differs: vec![],
    })
}

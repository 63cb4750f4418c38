//! The gen-vectors job: regenerate the golden select-logic vectors (Espresso PLA) and the
//! derived equations (`vectors/select/`) from the case tables (§2.3.3).

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::generated::{write_generated, GeneratedReport};
use crate::progress::Progress;

/// Write (or check) the PLA files and `derived.eqn`. `Default`: into `vectors/select`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct GenVectorsJob {
    /// The directory to write (or check) the files in (`-o`).
    pub out: PathBuf,
    /// Only compare with the files in the directory (`--check`).
    pub check: bool,
}

impl Default for GenVectorsJob {
    fn default() -> Self {
        GenVectorsJob {
            out: "vectors/select".into(),
            check: false,
        }
    }
}

impl GenVectorsJob {
    /// The memory plan: the files are a few kilobytes; nothing grows.
    pub fn estimate(&self) -> crate::Result<u64> {
        Ok(0)
    }

    /// Generate, then write or compare.
    pub fn run(&self, _: &dyn Progress) -> crate::Result<GeneratedReport> {
        let files = rtl_model::select::vectors::generate()?;
        write_generated(&files, &self.out, self.check)
    }
}

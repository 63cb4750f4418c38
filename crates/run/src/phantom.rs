//! The phantom job: the project's CT-head phantom as a NRRD dataset (Figure 5.6's stand-in;
//! docs/volume-scenes.md).

use std::path::PathBuf;

use csgpix_output::Outputs;
use csgpix_scene::dataset::phantom;
use csgpix_scene::nrrd::{nrrd_bytes, Encoding, Endian};
use serde::{Deserialize, Serialize};

use crate::memory::Limit;
use crate::progress::Progress;

named!(Encoding: "encoding" {
    Encoding::Gzip => "gzip": "One gzip member",
    Encoding::Raw => "raw": "Raw bytes",
});

/// The largest `size`.
pub const MAX_SIZE: u16 = 1024;

/// Write the phantom, `size` samples along each axis, to `out`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PhantomJob {
    /// Samples along each axis, 1 to [`MAX_SIZE`] (the phantom spans -10..10 scene units
    /// whatever the size).
    pub size: u16,
    /// Data encoding.
    #[serde(with = "crate::named::by_name")]
    pub encoding: Encoding,
    /// Output NRRD file (uint16; `-`: standard output).
    pub out: PathBuf,
    /// The memory limit in MiB (`--max-memory`); None: the memory available when it runs.
    pub max_memory: Option<u64>,
}

impl Default for PhantomJob {
    fn default() -> Self {
        PhantomJob {
            size: 48,
            encoding: Encoding::Gzip,
            out: PathBuf::new(),
            max_memory: None,
        }
    }
}

/// What was written.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PhantomReport {
    /// The file, as given (`-`: standard output).
    pub out: PathBuf,
    /// Samples along each axis.
    pub size: u16,
    /// Whether the volume went to standard output (the closing line then goes to standard
    /// error).
    #[serde(skip)]
    pub stdout: bool,
}

impl PhantomJob {
    /// An upper bound of the phantom's memory (docs/memory.md): the samples (f32, 4 bytes
    /// each), the uint16 data (2 each), the file's bytes (2 each: header and data joined, or
    /// gzip's output), a spare 2 for the encoder, the process.
    pub fn estimate(&self) -> crate::Result<u64> {
        Ok(u64::from(self.size).pow(3) * (4 + 2 + 2 + 2) + (16 << 20))
    }

    /// Sample the phantom and write it.
    pub fn run(&self, _: &dyn Progress) -> crate::Result<PhantomReport> {
        let mut outs = Outputs::new();
        let out = outs.file_or_stdout("-o", &self.out, &["nrrd"])?;
        if !(1..=MAX_SIZE).contains(&self.size) {
            let message = format!("--size {}: must be 1..={MAX_SIZE}", self.size);
            return Err(crate::Error::options("--size", message));
        }
        let n = self.size as usize;
        Limit::new(self.max_memory, "--max-memory").check(
            self.estimate()?,
            "this phantom",
            "lower --size",
        )?;
        let comment = format!(
            "csgpix phantom --size {n}: CT-head phantom after Figure 5.6 (skull 1000, tissue \
             400, ventricles 100, dense sphere 1200)"
        );
        let bytes = nrrd_bytes(&phantom(n), self.encoding, Endian::Little, &comment)?;
        outs.write(out, |w| w.write_all(&bytes))?;
        let stdout = outs.uses_stdout();
        outs.commit()?;
        Ok(PhantomReport {
            out: self.out.clone(),
            size: self.size,
            stdout,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress::Quiet;

    #[test]
    fn writes_the_phantom_and_refuses_a_size_out_of_range() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("h.nrrd");
        let job = PhantomJob {
            size: 8,
            encoding: Encoding::Raw,
            out: out.clone(),
            ..PhantomJob::default()
        };
        let r = job.run(&Quiet).unwrap();
        assert_eq!((r.size, r.stdout), (8, false));
        let bytes = std::fs::read(&out).unwrap();
        // The raw data, 2 bytes a sample, after the header.
        assert!(bytes.len() > 8 * 8 * 8 * 2);
        let zero = PhantomJob { size: 0, ..job };
        let e = zero.run(&Quiet).unwrap_err().to_string();
        assert_eq!(e, "--size 0: must be 1..=1024");
    }

    #[test]
    fn a_job_goes_through_json_unchanged() {
        let j = PhantomJob {
            encoding: Encoding::Raw,
            ..PhantomJob::default()
        };
        let text = serde_json::to_string(&j).unwrap();
        assert!(text.contains("\"encoding\":\"raw\""), "{text}");
        assert_eq!(serde_json::from_str::<PhantomJob>(&text).unwrap(), j);
    }
}

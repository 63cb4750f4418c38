//! `--max-memory`: the one memory limit every allocating command checks its estimate against
//! before it allocates (docs/memory.md).

pub use csgpix_scene::memory::{default_mib, MAX_MIB};

/// `--max-memory`, flattened into each command that allocates in proportion to its input.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct MaxMemory {
    /// Refuse a run whose memory estimate is over this many MiB, before allocating. The
    /// default is the memory available now (MemAvailable), capped by the address-space limit
    /// (`ulimit -v`) less an eighth for code and stacks; at most 2^43.
    #[arg(long = "max-memory", value_name = "MIB", default_value_t = default_mib(),
          value_parser = clap::value_parser!(u64).range(1..=MAX_MIB))]
    pub mib: u64,
}

impl MaxMemory {
    /// The limit in bytes (no wrap: at most 2^63).
    pub fn bytes(&self) -> u64 {
        self.mib << 20
    }

    /// Make the file readers refuse what would not fit: NRRD volumes are refused by their
    /// header's `sizes`, before their data (gzip or raw) is read.
    pub fn limit_readers(&self) {
        csgpix_scene::nrrd::limit_samples_to_memory(self.bytes(), "--max-memory");
    }

    /// Refuse `need` bytes of `what` when over the limit, saying how to lower it (`fix`).
    pub fn check(&self, need: u64, what: &str, fix: &str) -> Result<(), String> {
        if need <= self.bytes() {
            return Ok(());
        }
        Err(format!(
            "{what} needs about {} MiB, over --max-memory {}: {fix} or raise the limit",
            need.div_ceil(1 << 20),
            self.mib
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_in_bytes_cannot_wrap() {
        let m = MaxMemory { mib: MAX_MIB };
        assert_eq!(m.bytes(), 1 << 63);
        assert!(m.check(u64::MAX, "x", "y").is_err());
        assert!(m.check(1 << 63, "x", "y").is_ok());
    }
}

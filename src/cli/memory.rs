//! `--max-memory`: the one memory limit every allocating command checks its estimate against
//! before it allocates (docs/memory.md).

/// The largest limit accepted, in MiB: 2^43 MiB is 2^63 bytes, so the limit in bytes never
/// wraps.
pub const MAX_MIB: u64 = 1 << 43;

/// Used when the machine's available memory cannot be read.
const FALLBACK_MIB: u64 = 4096;

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
        csgpix::nrrd::limit_samples_to_memory(self.bytes(), "--max-memory");
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

/// The default limit: MemAvailable, capped by the address-space limit less an eighth.
pub fn default_mib() -> u64 {
    let available = mem_available_mib().unwrap_or(FALLBACK_MIB);
    let cap = address_space_mib().map_or(u64::MAX, |m| m - m / 8);
    available.min(cap).clamp(1, MAX_MIB)
}

/// MemAvailable of /proc/meminfo, in MiB.
fn mem_available_mib() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib >> 10)
}

/// The soft address-space limit (`ulimit -v`) of /proc/self/limits, in MiB; None if unlimited.
fn address_space_mib() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/limits").ok()?;
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    let soft = line
        .trim_start_matches("Max address space")
        .split_whitespace()
        .next()?;
    soft.parse::<u64>().ok().map(|b| b >> 20)
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

    #[test]
    fn the_default_is_at_least_one_mib_and_at_most_what_is_available() {
        let d = default_mib();
        assert!((1..=MAX_MIB).contains(&d));
        if let Some(avail) = mem_available_mib() {
            assert!(d <= avail.max(1));
        }
    }
}

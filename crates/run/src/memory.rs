//! The memory limit every allocating job checks its estimate against before it allocates
//! (docs/memory.md): `--max-memory` on the command line, `max_memory` in Python, one
//! [`Limit`] for both.

use csgpix_scene::nrrd::SampleLimit;

/// A memory limit, and the name its user gave it in messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limit {
    /// The limit in MiB, 1 to [`MAX_MIB`].
    pub mib: u64,
    /// How the caller names the limit: `--max-memory`, `max_memory`.
    pub name: &'static str,
}

/// A run refused before it allocated: its estimate is over the limit.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{what} needs about {need_mib} MiB, over {name} {limit_mib}: {fix} or raise the limit")]
pub struct OverMemory {
    /// What needs it (`this run`, `--mesh`, …).
    pub what: String,
    /// The estimate, MiB (rounded up).
    pub need_mib: u64,
    /// The limit's name and value, MiB.
    pub name: &'static str,
    /// The limit, MiB.
    pub limit_mib: u64,
    /// How to need less.
    pub fix: String,
}

impl Limit {
    /// `mib` MiB (clamped to 1..=[`MAX_MIB`]), or the default: the memory available now
    /// capped by the address-space limit ([`default_mib`]).
    pub fn new(mib: Option<u64>, name: &'static str) -> Limit {
        let mib = mib.unwrap_or_else(default_mib).clamp(1, MAX_MIB);
        Limit { mib, name }
    }

    /// The limit in bytes (no wrap: at most 2^63).
    pub fn bytes(&self) -> u64 {
        self.mib << 20
    }

    /// Refuse `need` bytes of `what` when over the limit, saying how to lower it (`fix`).
    pub fn check(&self, need: u64, what: &str, fix: &str) -> Result<(), OverMemory> {
        if need <= self.bytes() {
            return Ok(());
        }
        Err(OverMemory {
            what: what.into(),
            need_mib: need.div_ceil(1 << 20),
            name: self.name,
            limit_mib: self.mib,
            fix: fix.into(),
        })
    }

    /// The most samples a dataset may have under this limit, for the file readers: a NRRD
    /// volume is refused by its header's `sizes`, before its data (gzip or raw) is read.
    pub fn samples(&self) -> SampleLimit {
        SampleLimit::of_memory(self.bytes(), self.name)
    }
}

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
    /// The limit.
    pub fn limit(&self) -> Limit {
        Limit {
            mib: self.mib,
            name: "--max-memory",
        }
    }

    /// The limit in bytes (no wrap: at most 2^63).
    pub fn bytes(&self) -> u64 {
        self.limit().bytes()
    }

    /// The readers' sample limit ([`Limit::samples`]).
    pub fn samples(&self) -> SampleLimit {
        self.limit().samples()
    }

    /// Refuse `need` bytes of `what` when over the limit, saying how to lower it (`fix`).
    pub fn check(&self, need: u64, what: &str, fix: &str) -> Result<(), OverMemory> {
        self.limit().check(need, what, fix)
    }
}

// The memory a run may use by default: what the machine has available now.

/// The largest limit accepted, in MiB: 2^43 MiB is 2^63 bytes, so the limit in bytes never
/// wraps.
pub const MAX_MIB: u64 = 1 << 43;

/// Used when the machine's available memory cannot be read.
const FALLBACK_MIB: u64 = 4096;

/// The default limit in MiB: MemAvailable, capped by the address-space limit (`ulimit -v`)
/// less an eighth for code and stacks; 1 to [`MAX_MIB`].
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
mod probe_tests {
    use super::*;

    #[test]
    fn the_default_is_at_least_one_mib_and_at_most_what_is_available() {
        let d = default_mib();
        assert!((1..=MAX_MIB).contains(&d));
        if let Some(avail) = mem_available_mib() {
            assert!(d <= avail.max(1));
        }
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

    #[test]
    fn a_refusal_names_the_limit_as_its_caller_does() {
        let e = Limit::new(Some(16), "max_memory").check(17 << 20, "this run", "lower res");
        let e = e.unwrap_err();
        assert_eq!((e.need_mib, e.limit_mib), (17, 16));
        assert_eq!(
            e.to_string(),
            "this run needs about 17 MiB, over max_memory 16: lower res or raise the limit"
        );
    }
}

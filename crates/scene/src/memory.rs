//! The memory a run may use (docs/memory.md): what the machine has available now, the one
//! default every allocating command and the Python binding check their estimates against
//! before they allocate.

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
mod tests {
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

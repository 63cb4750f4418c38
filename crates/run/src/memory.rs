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

/// The default memory limit of a job: the memory available now, as `--max-memory` names it.
pub fn default_limit() -> Limit {
    Limit::new(None, "--max-memory")
}

impl Limit {
    /// `mib` MiB (clamped to 1..=[`MAX_MIB`] and to what the process may hold,
    /// [`Cap::probe`]), or the default: the memory available now within that cap
    /// ([`default_mib`]).
    pub fn new(mib: Option<u64>, name: &'static str) -> Limit {
        let cap = Cap::probe().map_or(MAX_MIB, |c| c.mib);
        let mib = mib
            .map_or_else(default_mib, |m| m.min(cap))
            .clamp(1, MAX_MIB);
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

/// A limit typed by the user (`--max-memory MIB`, Python's `max_memory`): 1 to [`MAX_MIB`]
/// MiB, lowered to what the process may hold ([`Cap`]), with the note that says so, so that a
/// limit above the address space cannot let a run start that the system will not let finish.
pub fn parse_mib(s: &str) -> crate::value::Parsed<(u64, Option<String>)> {
    let mib: u64 = s
        .parse()
        .map_err(|_| format!("{s:?} is not a whole number of MiB"))?;
    if !(1..=MAX_MIB).contains(&mib) {
        return Err(format!("{mib} is not in 1..={MAX_MIB}").into());
    }
    Ok(match Cap::probe() {
        Some(cap) if mib > cap.mib => {
            let note = format!(
                "--max-memory {mib} is above what this process may hold ({}): {} MiB used",
                cap.why, cap.mib
            );
            (cap.mib, Some(note))
        }
        _ => (mib, None),
    })
}

// The memory a run may use by default: what the machine has available now, within what the
// process may hold.

/// The largest limit accepted, in MiB: 2^43 MiB is 2^63 bytes, so the limit in bytes never
/// wraps.
pub const MAX_MIB: u64 = 1 << 43;

/// Used when the machine's available memory cannot be read.
const FALLBACK_MIB: u64 = 4096;

/// Address space the process takes besides a run's estimate, measured (docs/memory.md): the
/// binary and its libraries, the main stack, the allocator's own (one malloc arena under an
/// address-space limit, `csgpix_output::one_arena_under_address_limit`), with room to spare.
const PROCESS_MIB: u64 = 64;

/// Address space each thread adds: its stack (2 MiB) and its buffers, with room to spare.
const THREAD_MIB: u64 = 8;

/// The default limit in MiB: MemAvailable, within [`Cap::probe`]; 1 to [`MAX_MIB`].
pub fn default_mib() -> u64 {
    let available = mem_available_mib().unwrap_or(FALLBACK_MIB);
    let cap = Cap::probe().map_or(u64::MAX, |c| c.mib);
    available.min(cap).clamp(1, MAX_MIB)
}

/// The most a run may hold whatever the machine has free: the tightest of the address-space
/// limit, the data limit (each less the process's own `PROCESS_MIB` and `THREAD_MIB` a
/// thread) and the room left in the process's cgroup; and which one it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cap {
    /// MiB, at least 1.
    pub mib: u64,
    /// What sets it, as a user would look it up (`address space 1024 MiB, ulimit -v`).
    pub why: String,
}

impl Cap {
    /// The cap of this process now, None when nothing limits it.
    pub fn probe() -> Option<Cap> {
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u64;
        let own = PROCESS_MIB + THREAD_MIB * threads;
        let limits = proc_limits();
        let rlimit = |name: &str, shell: &str| {
            let mib = rlimit_mib(&limits, name)?;
            let why = format!("{} {mib} MiB, {shell}", name.to_ascii_lowercase());
            Some(Cap {
                mib: mib.saturating_sub(own).max(1),
                why,
            })
        };
        [
            rlimit("Max address space", "ulimit -v"),
            rlimit("Max data size", "ulimit -d"),
            cgroup_room_mib().map(|mib| Cap {
                mib: mib.max(1),
                why: format!("{mib} MiB left in the cgroup"),
            }),
        ]
        .into_iter()
        .flatten()
        .min_by_key(|c| c.mib)
    }
}

/// An upper bound of a slab route's memory over `grid` (the slicer's, or fewer slabs of it):
/// every primitive's per-pixel slab ranges and the threads' state
/// ([`csgpix_voxel::memory_estimate`]), and the imports' samples.
pub fn slab_route_estimate(
    slicer: &csgpix_voxel::Slicer,
    grid: &csgpix_voxel::Grid,
    threads: usize,
) -> u64 {
    csgpix_voxel::memory_estimate(grid, slicer.primitive_count(), threads)
        .saturating_add(imports_estimate(slicer))
}

/// Bytes the slab routes hold for the imports of `slicer` (datasets' samples, meshes' runs).
pub fn imports_estimate(slicer: &csgpix_voxel::Slicer) -> u64 {
    let each = slicer
        .sampled
        .iter()
        .map(|s| s.memory_estimate(&slicer.grid));
    each.fold(0, u64::saturating_add)
}

/// MemAvailable of /proc/meminfo, in MiB.
fn mem_available_mib() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib >> 10)
}

/// /proc/self/limits, or nothing where there is none.
fn proc_limits() -> String {
    std::fs::read_to_string("/proc/self/limits").unwrap_or_default()
}

/// The soft limit `name` (`Max address space`, `Max data size`) of /proc/self/limits, in
/// MiB; None if unlimited.
fn rlimit_mib(limits: &str, name: &str) -> Option<u64> {
    let line = limits.lines().find(|l| l.starts_with(name))?;
    let soft = line.trim_start_matches(name).split_whitespace().next()?;
    soft.parse::<u64>().ok().map(|b| b >> 20)
}

/// The memory the process's cgroup may still take, in MiB (its limit less its usage, the
/// tightest along its path), cgroup v2 or v1; None without a limit.
fn cgroup_room_mib() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    cgroup_room(&text, std::path::Path::new("/sys/fs/cgroup"), &|p| {
        std::fs::read_to_string(p).ok()
    })
}

/// [`cgroup_room_mib`] of a `/proc/self/cgroup` text, files read by `read` under `root`.
fn cgroup_room(
    text: &str,
    root: &std::path::Path,
    read: &dyn Fn(&std::path::Path) -> Option<String>,
) -> Option<u64> {
    let num = |p: std::path::PathBuf| read(&p)?.trim().parse::<u64>().ok();
    let mut rooms = vec![];
    for line in text.lines() {
        let mut f = line.splitn(3, ':');
        let (_, controllers, path) = (f.next()?, f.next()?, f.next()?);
        let (base, max, used) = match controllers {
            "" => (root.to_path_buf(), "memory.max", "memory.current"),
            c if c.split(',').any(|c| c == "memory") => (
                root.join("memory"),
                "memory.limit_in_bytes",
                "memory.usage_in_bytes",
            ),
            _ => continue,
        };
        // The cgroup and its ancestors: each one's limit holds.
        let mut dir = base.join(path.trim_start_matches('/'));
        loop {
            if let (Some(max), Some(used)) = (num(dir.join(max)), num(dir.join(used))) {
                // v1 says "no limit" with a number near 2^63.
                if max < 1 << 60 {
                    rooms.push(max.saturating_sub(used) >> 20);
                }
            }
            if dir == base || !dir.pop() {
                break;
            }
        }
    }
    rooms.into_iter().min()
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
    use std::path::{Path, PathBuf};

    /// `cgroup_room` over a map of files.
    fn room(text: &str, files: &[(&str, &str)]) -> Option<u64> {
        let files: Vec<(PathBuf, String)> = files
            .iter()
            .map(|(p, t)| (Path::new("/cg").join(p), t.to_string()))
            .collect();
        let read = |p: &Path| files.iter().find(|(q, _)| q == p).map(|(_, t)| t.clone());
        cgroup_room(text, Path::new("/cg"), &read)
    }

    #[test]
    fn the_cgroup_room_is_the_tightest_along_the_path() {
        let v2 = [
            ("a/memory.max", "max\n"),
            ("a/memory.current", "0\n"),
            ("a/b/memory.max", "1073741824\n"),
            ("a/b/memory.current", "268435456\n"),
        ];
        assert_eq!(room("0::/a/b\n", &v2), Some(768));
        let parent = [
            ("a/memory.max", "536870912"),
            ("a/memory.current", "0"),
            ("a/b/memory.max", "max"),
            ("a/b/memory.current", "1"),
        ];
        assert_eq!(room("0::/a/b", &parent), Some(512));
        let v1 = [
            ("memory/x/memory.limit_in_bytes", "2147483648"),
            ("memory/x/memory.usage_in_bytes", "1073741824"),
            ("memory/memory.limit_in_bytes", "9223372036854771712"),
            ("memory/memory.usage_in_bytes", "5"),
        ];
        assert_eq!(room("4:memory:/x\n1:cpu:/\n0::/", &v1), Some(1024));
        let unlimited = [
            ("memory/x/memory.limit_in_bytes", "9223372036854771712"),
            ("memory/x/memory.usage_in_bytes", "1"),
        ];
        assert_eq!(room("4:memory:/x", &unlimited), None);
        assert_eq!(room("", &[]), None);
    }

    #[test]
    fn rlimits_are_read_in_mib_and_unlimited_is_none() {
        let limits = "Limit                     Soft Limit           Hard Limit           Units\n\
                      Max data size             unlimited            unlimited            bytes\n\
                      Max address space         1073741824           unlimited            bytes\n";
        assert_eq!(rlimit_mib(limits, "Max address space"), Some(1024));
        assert_eq!(rlimit_mib(limits, "Max data size"), None);
    }

    #[test]
    fn an_explicit_limit_is_parsed_in_range() {
        assert!(parse_mib("0").is_err());
        assert!(parse_mib("x").is_err());
        assert!(parse_mib(&(MAX_MIB + 1).to_string()).is_err());
        let cap = Cap::probe().map_or(MAX_MIB, |c| c.mib);
        let (mib, note) = parse_mib(&MAX_MIB.to_string()).unwrap();
        assert_eq!(mib, cap);
        assert_eq!(note.is_some(), cap < MAX_MIB);
        assert_eq!(parse_mib("1").unwrap(), (1, None));
    }

    #[test]
    fn the_limit_in_bytes_cannot_wrap() {
        let m = Limit {
            mib: MAX_MIB,
            name: "--max-memory",
        };
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

//! What an interrupted run leaves beside its outputs, found and cleared by the next run that
//! names the same output.
//!
//! A run stages output `NAME` beside it as `.NAME.XXXXXX.csgpix-tmp` (six letters or
//! digits); a signal's cleanup renames a staging directory to `.NAME.XXXXXX.csgpix-rm`
//! before removing it; replacing a directory renames the old one to
//! `.NAME.XXXXXX.csgpix-old` until the new one is in. SIGINT, SIGTERM and SIGHUP remove all
//! of them, but SIGKILL (or a power cut) cannot be caught, and they stay. No user writes
//! such names, and only names of exactly this shape are touched.
//!
//! A live run holds an exclusive `flock` on each of its staging files and directories (and
//! on a directory it is renaming aside), and the kernel drops it when the process dies: an
//! entry that cannot be locked belongs to a run still going (two runs writing the same
//! output) and is left alone.

use std::fs::File;
use std::path::{Path, PathBuf};

/// The random part of a staging name: as many letters or digits as this.
pub(crate) const RANDOM: usize = 6;

/// The suffixes of csgpix's staging names.
const TMP: &str = "csgpix-tmp";
const OLD: &str = "csgpix-old";
const RM: &str = "csgpix-rm";

/// What a leftover was, by its suffix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Staged and never committed: incomplete, or complete and not renamed in.
    Tmp,
    /// A replaced directory renamed aside: the only copy if the new one never came in.
    Old,
    /// A staging directory a signal's cleanup was removing.
    Rm,
}

/// The kind of `entry` if it is a staging name of output `name`: `.NAME.`, six ASCII
/// letters or digits, `.` and one of the three suffixes, nothing else.
fn leftover_kind(entry: &str, name: &str) -> Option<Kind> {
    let rest = entry
        .strip_prefix('.')?
        .strip_prefix(name)?
        .strip_prefix('.')?;
    let (random, suffix) = rest.split_at_checked(RANDOM)?;
    if !random.bytes().all(|b| b.is_ascii_alphanumeric()) {
        return None;
    }
    match suffix.strip_prefix('.')? {
        TMP => Some(Kind::Tmp),
        OLD => Some(Kind::Old),
        RM => Some(Kind::Rm),
        _ => None,
    }
}

/// Take the lock that marks `file` (a staging file or directory) as a live run's: held
/// until the file is closed, or the process ends however it ends. False when another
/// process holds it.
#[cfg(unix)]
pub(crate) fn lock(file: &File) -> bool {
    use std::os::fd::AsRawFd;
    // SAFETY: flock(2) on a descriptor this File owns.
    unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) == 0 }
}

#[cfg(not(unix))]
pub(crate) fn lock(_: &File) -> bool {
    true
}

/// `path` opened (a file or a directory) and locked, when no live run holds it.
fn claim(path: &Path) -> Option<File> {
    let file = File::open(path).ok()?;
    lock(&file).then_some(file)
}

/// Clear the leftovers of output `name` in `dir` (see the module's doc), one line on
/// standard error for each. A `.csgpix-old` directory whose target is missing (the run was
/// killed between the two renames of a commit) is renamed back to `dir/name`; the newest
/// if there are several. Failures are ignored: the run goes on as it would without them.
pub(crate) fn clear(dir: &Path, name: &str) {
    if cfg!(not(unix)) {
        // No lock tells a live run's staging from a dead one's.
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut found: Vec<(PathBuf, Kind)> = entries
        .filter_map(|e| {
            let e = e.ok()?;
            let kind = leftover_kind(e.file_name().to_str()?, name)?;
            Some((e.path(), kind))
        })
        .collect();
    if found.is_empty() {
        return;
    }
    restore(dir, name, &mut found);
    for (path, _) in found {
        remove(&path);
    }
}

/// Rename the newest claimable `.csgpix-old` of `found` back to `dir/name` when nothing is
/// there, and take it out of `found`.
fn restore(dir: &Path, name: &str, found: &mut Vec<(PathBuf, Kind)>) {
    let target = dir.join(name);
    if std::fs::symlink_metadata(&target).is_ok() {
        return;
    }
    let modified = |p: &Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    let newest = found
        .iter()
        .enumerate()
        .filter(|(_, (_, kind))| *kind == Kind::Old)
        .max_by_key(|(_, (p, _))| modified(p))
        .map(|(i, _)| i);
    let Some(i) = newest else { return };
    let (old, _) = found.remove(i);
    let Some(_held) = claim(&old) else { return };
    if std::fs::rename(&old, &target).is_ok() {
        eprintln!(
            "csgpix: restored {} from {} of an interrupted run",
            target.display(),
            shown(&old)
        );
    }
}

/// Remove one leftover, file or directory, unless a live run holds it.
fn remove(path: &Path) {
    let Some(_held) = claim(path) else { return };
    let removed = match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_dir() => std::fs::remove_dir_all(path),
        Ok(_) => std::fs::remove_file(path),
        Err(e) => Err(e),
    };
    if removed.is_ok() {
        eprintln!(
            "csgpix: removed leftover {} of an interrupted run",
            shown(path)
        );
    }
}

/// A leftover's name as the messages give it (it is beside the output the user named).
fn shown(p: &Path) -> String {
    p.file_name()
        .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_staging_names_of_the_output_are_leftovers() {
        let k = |e| leftover_kind(e, "v.nrrd");
        assert_eq!(k(".v.nrrd.AbC123.csgpix-tmp"), Some(Kind::Tmp));
        assert_eq!(k(".v.nrrd.000000.csgpix-old"), Some(Kind::Old));
        assert_eq!(k(".v.nrrd.zzzzzz.csgpix-rm"), Some(Kind::Rm));
        for not in [
            "v.nrrd",
            ".v.nrrd",
            ".v.nrrd.AbC12.csgpix-tmp",
            ".v.nrrd.AbC1234.csgpix-tmp",
            ".v.nrrd.AbC-23.csgpix-tmp",
            ".v.nrrd.AbC123.csgpix-tmpx",
            ".v.nrrd.AbC123.csgpix-tmp.bak",
            ".v.nrrd.AbC123.tmp",
            "..v.nrrd.AbC123.csgpix-tmp",
            ".w.nrrd.AbC123.csgpix-tmp",
            ".v.nrrd.x.AbC123.csgpix-tmp",
            ".v.nrrd.ÄbC12.csgpix-tmp",
        ] {
            assert_eq!(k(not), None, "{not}");
        }
        // Another output whose name starts with this one's is not this one's.
        assert_eq!(leftover_kind(".v.nrrd.AbC123.csgpix-tmp", "v"), None);
    }
}

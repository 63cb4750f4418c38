//! What a run makes beside its outputs and must not leave behind when a signal ends it: scratch
//! files and directories (a `--fallback openscad` statement written beside the scene,
//! openscad's mesh in TMPDIR) and child processes (openscad itself). Each is registered for as
//! long as it lives ([`Scratch`], [`Child`]); the signal cleanup
//! ([`crate::install_signal_cleanup`]) ends the children's process groups and removes the
//! scratch paths, as it removes staged outputs.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

static PATHS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
static GROUPS: Mutex<Vec<i32>> = Mutex::new(Vec::new());

fn paths() -> MutexGuard<'static, Vec<PathBuf>> {
    PATHS.lock().unwrap_or_else(|e| e.into_inner())
}

fn groups() -> MutexGuard<'static, Vec<i32>> {
    GROUPS.lock().unwrap_or_else(|e| e.into_inner())
}

/// A scratch file or directory a signal removes while this lives; dropping it only forgets
/// the path (its owner, a `tempfile` handle, removes it on the normal path).
pub struct Scratch {
    path: PathBuf,
}

/// Registers `path` (a file or directory) for removal by a signal's cleanup.
pub fn scratch(path: &Path) -> Scratch {
    paths().push(path.to_path_buf());
    Scratch {
        path: path.to_path_buf(),
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let mut p = paths();
        if let Some(i) = p.iter().rposition(|q| *q == self.path) {
            p.swap_remove(i);
        }
    }
}

/// A child process that leads its own process group (spawned with `process_group(0)`), which
/// a signal's cleanup kills while this lives.
pub struct Child {
    group: i32,
}

/// Registers the process group `group` (the child's pid) to be killed by a signal's cleanup.
pub fn child(group: u32) -> Child {
    let group = group as i32;
    groups().push(group);
    Child { group }
}

impl Drop for Child {
    fn drop(&mut self) {
        let mut g = groups();
        if let Some(i) = g.iter().rposition(|&q| q == self.group) {
            g.swap_remove(i);
        }
    }
}

/// Kill every registered child's process group (SIGKILL: what they were making is about to be
/// removed), then remove every scratch path. Called by the signal cleanup only.
pub(crate) fn clear() {
    for &g in groups().iter() {
        if g > 0 {
            // SAFETY: kill(2) with a negative pid signals that process group; no memory is
            // touched.
            unsafe { libc::kill(-g, libc::SIGKILL) };
        }
    }
    for p in paths().drain(..) {
        let removed = match std::fs::symlink_metadata(&p) {
            Ok(m) if m.is_dir() => std::fs::remove_dir_all(&p),
            Ok(_) => std::fs::remove_file(&p),
            Err(_) => Ok(()),
        };
        let _ = removed;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scratch_paths_are_removed_by_clear_and_forgotten_when_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        std::fs::create_dir(&a).unwrap();
        std::fs::write(a.join("mesh.stl"), b"x").unwrap();
        std::fs::write(&b, b"x").unwrap();
        let kept = scratch(&b);
        drop(kept);
        let _held = scratch(&a);
        clear();
        assert!(!a.exists(), "a registered directory is removed");
        assert!(b.exists(), "a dropped registration is forgotten");
    }

    #[cfg(unix)]
    #[test]
    fn a_registered_child_group_is_killed() {
        use std::os::unix::process::CommandExt;
        let mut sh = std::process::Command::new("sh")
            .args(["-c", "sleep 30 & wait"])
            .process_group(0)
            .spawn()
            .unwrap();
        let _g = child(sh.id());
        let t0 = std::time::Instant::now();
        clear();
        let status = sh.wait().unwrap();
        assert!(!status.success());
        assert!(t0.elapsed().as_secs() < 10);
    }
}

//! An old output's blocks freed after the run, not during it.
//!
//! Replacing a file leaves the old one under the staged name ([`crate::replace`]), and
//! removing it is most of what a replacing run pays past its own work: at 1024³ the `unlink`
//! of the old 1 GiB volume took 0.16-0.27 s (`strace -T`, twelve.csg, ext4 mounted with
//! `discard`), about a third of it the page cache (0.15-0.16 s remained when
//! `posix_fadvise(DONTNEED)` had dropped that first) and the rest the extents. The name
//! goes at once; the blocks go when the last descriptor of the file is closed. So the
//! command line ([`release_after_exit`]) has a child hold one: the old file is opened,
//! unlinked, and given to a child of the `csgpix` binary ([`hold_if_asked`]) as its standard
//! output, with a pipe from this process as its standard input. The child reads that pipe
//! until it ends, which is when this process has ended (its write end closes with the
//! process, however it ends), then exits, and the system frees the file's blocks in the
//! child's exit. The directory is as before at every moment: the name is removed before the
//! run returns, and no file is left anywhere if either process is killed.
//!
//! Only the binary asks for it: a library caller (the Python module) may run for long, and
//! would keep the space of every file it replaced until it ends. Only a file of
//! [`WORTH_A_CHILD`] or more is held: below it, starting the child costs more than the
//! removal. Where the child cannot be started, or the old file cannot be opened, it is
//! removed at once, as without this.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::{Mutex, OnceLock};

/// The least space an old file takes (its allocated blocks) for a child to free it. A child
/// costs its start, 1-2 ms of the run's time here (a replacing `--res 64` run, 256 KiB:
/// 4.4 ms before, 6.2 ms with a child, least of 25 in alternation beside a build). Removing
/// a file costs about 0.07 ms a MiB of page cache, and where its blocks are on the disk and
/// the file system discards them, milliseconds more (an `unlink` after `sync`: 3.5-3.9 ms at
/// 4 MiB, 4.5-8.3 ms at 16 MiB, 16-20 ms at 64 MiB on this disk).
pub const WORTH_A_CHILD: u64 = 16 << 20;

/// The environment variable that makes the `csgpix` binary the holder of a released file:
/// [`hold_if_asked`] then waits for its standard input to end and exits.
pub const HOLD: &str = "CSGPIX_HOLD_RELEASED";

/// The program whose child holds a released file ([`release_after_exit`]).
static HOLDER: OnceLock<PathBuf> = OnceLock::new();

/// The write ends of the holders' pipes, open until this process ends.
static HELD: Mutex<Vec<ChildStdin>> = Mutex::new(Vec::new());

/// From now on, the old file a replaced output leaves is freed after this process ends, by a
/// child of `program` (this binary, which calls [`hold_if_asked`] first thing). Call once,
/// from `main`, in a process that ends when its run does.
pub fn release_after_exit(program: PathBuf) {
    let _ = HOLDER.set(program);
}

/// In a child started to hold a released file (the [`HOLD`] variable set): close every
/// descriptor but the standard three, wait until standard input ends, then exit with status
/// 0, closing the file on standard output. Otherwise return at once. Call first thing in
/// `main`.
pub fn hold_if_asked() {
    if std::env::var_os(HOLD).is_none() {
        return;
    }
    // Descriptors the run inherited from its own caller without close-on-exec (a pipe named
    // as `-o /dev/fd/3`) are not kept open past the run by this child.
    #[cfg(target_os = "linux")]
    // SAFETY: close_range(2) over every descriptor above the standard three; nothing in this
    // process has opened one yet (called first thing in `main`).
    unsafe {
        libc::syscall(libc::SYS_close_range, 3u32, u32::MAX, 0u32);
    }
    let _ = std::io::copy(&mut std::io::stdin().lock(), &mut std::io::sink());
    std::process::exit(0)
}

/// Remove the file at `path`: its name now, and its blocks now or, after
/// [`release_after_exit`] and where it takes [`WORTH_A_CHILD`] or more, once this process
/// has ended.
pub(crate) fn remove_file(path: &Path) {
    let held = HOLDER.get().and_then(|program| {
        let file = File::open(path).ok()?;
        if allocated(&file)? < WORTH_A_CHILD {
            return None;
        }
        std::fs::remove_file(path).ok()?;
        let (child, pipe) = hold(program, file).ok()?;
        HELD.lock().unwrap_or_else(|e| e.into_inner()).push(pipe);
        // Never waited for: it outlives this process by design, and the system's reaper
        // becomes its parent.
        drop(child);
        Some(())
    });
    if held.is_none() {
        // Not held (or the child not started, the file then closed here): removed now.
        let _ = std::fs::remove_file(path);
    }
}

/// The bytes of disk `file` takes (its length where the system does not say).
fn allocated(file: &File) -> Option<u64> {
    let meta = file.metadata().ok()?;
    #[cfg(unix)]
    let bytes = std::os::unix::fs::MetadataExt::blocks(&meta) * 512;
    #[cfg(not(unix))]
    let bytes = meta.len();
    Some(bytes)
}

/// Start a child of `program` holding `file` as its standard output until the returned
/// pipe, its standard input, is closed.
fn hold(program: &Path, file: File) -> std::io::Result<(Child, ChildStdin)> {
    let mut child = Command::new(program)
        .env(HOLD, "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::from(file))
        .stderr(Stdio::null())
        .spawn()?;
    let pipe = child.stdin.take().ok_or(std::io::ErrorKind::BrokenPipe)?;
    Ok((child, pipe))
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;
    use std::os::unix::fs::MetadataExt;
    use std::time::{Duration, Instant};

    /// The child holds the unlinked file, open on its standard output, for as long as its
    /// pipe is open, and ends when it closes. `cat` stands in for the binary's
    /// [`hold_if_asked`] (read standard input to its end, write nothing): the binary's own
    /// holder is tested in tests/outputs.rs.
    #[test]
    fn a_held_file_stays_open_in_the_child_until_the_pipe_closes() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("old.nrrd");
        std::fs::write(&path, vec![7u8; 1 << 16]).unwrap();
        let ino = std::fs::metadata(&path).unwrap().ino();
        let file = File::open(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        let (mut child, pipe) = hold(Path::new("cat"), file).unwrap();
        assert!(!path.exists(), "the name is gone at once");
        std::thread::sleep(Duration::from_millis(200));
        assert!(
            child.try_wait().unwrap().is_none(),
            "the child waits for its pipe"
        );
        let held = std::fs::metadata(format!("/proc/{}/fd/1", child.id())).unwrap();
        assert_eq!(
            (held.ino(), held.nlink()),
            (ino, 0),
            "the old file, unlinked"
        );
        assert_eq!(held.len(), 1 << 16, "its bytes not yet freed");
        drop(pipe);
        let start = Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break s;
            }
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "the child did not end"
            );
            std::thread::sleep(Duration::from_millis(10));
        };
        assert!(status.success());
    }

    /// Without [`release_after_exit`] (a library caller), the file is removed at once.
    #[test]
    fn without_a_holder_the_file_is_removed_at_once() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("old.nrrd");
        std::fs::write(&path, b"x").unwrap();
        assert!(HOLDER.get().is_none());
        remove_file(&path);
        assert!(!path.exists());
    }
}

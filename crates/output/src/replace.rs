//! Putting a staged file in place of its target without a flush the run did not ask for.
//!
//! ext4 (with its default `auto_da_alloc`) writes a file's data out before it returns from a
//! `rename` over an existing file, and on the `close` of a file that was truncated to zero:
//! both guard programs that neither sync nor stage against losing a file's content in a power
//! cut. A staged output needs neither guard while the machine runs (the target holds the old
//! file or the new one, whole), and at 1024³ they cost more than the voxelizer's own work:
//! 0.18 s for `close` of a new volume, 0.47 s for the rename over an old one (`strace -T`,
//! twelve.csg, docs/voxelize-bench.md). So a new staged file is never truncated
//! (`Outputs::emptied`), and an existing target is swapped with the staged file in one
//! atomic step (`renameat2(RENAME_EXCHANGE)`, which ext4 does not flush), the old file then
//! removed from the staged name (its blocks freed after the run where the binary asks:
//! [`crate::release`]).
//!
//! A run that must survive a power cut asks for it ([`sync_outputs`], `csgpix --sync`): every
//! staged file is then synced before it replaces anything and its directory after.

use std::fs::File;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// Whether outputs are put on the disk before they replace anything ([`sync_outputs`]).
static DURABLE: AtomicBool = AtomicBool::new(false);

/// From now on, sync every output file before it replaces its target, and the directory
/// that holds it after: outputs that survive a power cut, at the cost of waiting for the
/// disk. Off by default, where an output is whole or absent while the machine runs (the
/// system writes it out later). Directories written whole are synced either way
/// ([`sync_tree`](crate::sync_tree)).
pub fn sync_outputs(on: bool) {
    DURABLE.store(on, Ordering::SeqCst);
}

/// Whether [`sync_outputs`] is on.
pub(crate) fn durable() -> bool {
    DURABLE.load(Ordering::SeqCst)
}

/// Put the staged file at `staged` in place of `target`, whole: the target holds the old
/// file or the new one at every moment. `staged` no longer exists afterwards.
pub(crate) fn put_file(staged: &Path, target: &Path) -> std::io::Result<()> {
    if durable() {
        File::open(staged)?.sync_all()?;
    }
    match exchange(staged, target) {
        // The old file now has the staged name; were it left there (the system refusing to
        // remove it), the next run naming the output would clear it (`leftover`). Its blocks
        // may be freed after the run (`release`).
        Ok(()) => crate::release::remove_file(staged),
        // No target to swap with (or no exchange here): a rename, which flushes nothing
        // when it replaces nothing.
        Err(_) => std::fs::rename(staged, target)?,
    }
    if durable() {
        sync_parent(target)?;
    }
    Ok(())
}

/// Swap the files at `a` and `b` in one step; an error when either is missing or the system
/// cannot (not Linux, an old kernel, a filesystem without it).
#[cfg(target_os = "linux")]
fn exchange(a: &Path, b: &Path) -> std::io::Result<()> {
    use std::os::unix::ffi::OsStrExt;
    let c =
        |p: &Path| std::ffi::CString::new(p.as_os_str().as_bytes()).map_err(std::io::Error::other);
    let (a, b) = (c(a)?, c(b)?);
    // SAFETY: renameat2(2) through syscall(2), with NUL-terminated paths relative to the
    // working directory; glibc and musl do not both export a wrapper.
    let r = unsafe {
        libc::syscall(
            libc::SYS_renameat2,
            libc::AT_FDCWD,
            a.as_ptr(),
            libc::AT_FDCWD,
            b.as_ptr(),
            libc::RENAME_EXCHANGE,
        )
    };
    match r {
        0 => Ok(()),
        _ => Err(std::io::Error::last_os_error()),
    }
}

#[cfg(not(target_os = "linux"))]
fn exchange(_: &Path, _: &Path) -> std::io::Result<()> {
    Err(std::io::ErrorKind::Unsupported.into())
}

/// Sync the directory that holds `p`, so that its new entry survives a power cut.
pub(crate) fn sync_parent(p: &Path) -> std::io::Result<()> {
    sync_dir(&crate::split(p).0)
}

/// Sync directory `dir`'s entries to the disk.
pub(crate) fn sync_dir(dir: &Path) -> std::io::Result<()> {
    // Windows cannot open a directory as a file: its entries are written with the files.
    match File::open(dir) {
        Ok(d) => d.sync_all(),
        Err(_) if cfg!(windows) => Ok(()),
        Err(e) => Err(e),
    }
}

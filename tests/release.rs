//! The old file of a replaced output is freed by a child after the run (crates/output
//! `release`). A test binary of its own: it makes this process the reaper of the children its
//! `csgpix` runs leave (`PR_SET_CHILD_SUBREAPER`) and waits for any child, which would take
//! the exit statuses of other tests' runs in a shared binary.

#![cfg(target_os = "linux")]

use std::path::Path;
use std::time::{Duration, Instant};

/// The children left to this process that have ended within `wait`, with their statuses;
/// stops early when none is left.
fn reap(wait: Duration) -> Vec<i32> {
    let start = Instant::now();
    let mut statuses = Vec::new();
    loop {
        let mut status = 0;
        // SAFETY: waitpid(2) on any child, not blocking, with a status this frame owns.
        let pid = unsafe { libc::waitpid(-1, &mut status, libc::WNOHANG) };
        match pid {
            -1 => return statuses, // no child left
            0 if start.elapsed() >= wait => return statuses,
            0 => std::thread::sleep(Duration::from_millis(10)),
            _ => statuses.push(status),
        }
    }
}

fn run(out: &Path) {
    let r = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(["voxelize", "vectors/scenes/twelve.csg", "--res", "64", "-o"])
        .arg(out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(r.status.success(), "{r:?}");
}

/// A run that writes a new output starts no child; a run that replaces one starts one
/// holder, which ends with status 0 once the run has ended (its parent then this process).
#[test]
fn a_replacing_run_leaves_one_holder_that_ends_after_it() {
    // SAFETY: prctl(2) with a documented option; it changes only who reaps orphans.
    assert_eq!(
        unsafe { libc::prctl(libc::PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) },
        0
    );
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("v.nrrd");
    run(&out);
    assert_eq!(reap(Duration::from_millis(500)), [] as [i32; 0]);
    run(&out);
    let left = reap(Duration::from_secs(10));
    assert_eq!(left.len(), 1, "children left: {left:?}");
    assert!(libc::WIFEXITED(left[0]) && libc::WEXITSTATUS(left[0]) == 0);
}

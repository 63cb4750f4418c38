//! The old file of a replaced output of 16 MiB or more is freed by a child after the run
//! (crates/output `release`). A test binary of its own: it makes this process the reaper of
//! the children its `csgpix` runs leave (`PR_SET_CHILD_SUBREAPER`) and waits for any child,
//! which would take the exit statuses of other tests' runs in a shared binary.

#![cfg(target_os = "linux")]

use std::path::Path;
use std::time::{Duration, Instant};

use csgpix::output::WORTH_A_CHILD;

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

/// `csgpix voxelize SCENE --res RES -o OUT`, which must succeed.
fn run(scene: &Path, res: &str, out: &Path) {
    let r = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .arg("voxelize")
        .arg(scene)
        .args(["--res", res, "-o"])
        .arg(out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(r.status.success(), "{r:?}");
}

/// A run that writes a new output starts no child, nor one that replaces a small one; a run
/// that replaces an output of [`WORTH_A_CHILD`] or more starts one holder, which ends with
/// status 0 once the run has ended (its parent then this process).
#[test]
fn a_run_replacing_a_large_output_leaves_one_holder_that_ends_after_it() {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: prctl(2) with a documented option; it changes only who reaps orphans.
    assert_eq!(
        unsafe { libc::prctl(libc::PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) },
        0
    );
    let dir = tempfile::tempdir().unwrap();
    let twelve = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/scenes/twelve.csg");
    let small = dir.path().join("small.nrrd");
    run(&twelve, "64", &small);
    assert_eq!(reap(Duration::from_millis(300)), [] as [i32; 0]);
    run(&twelve, "64", &small);
    assert_eq!(reap(Duration::from_millis(300)), [] as [i32; 0]);
    // One cube filling the grid: 16 MiB of voxels, no hole.
    let cube = dir.path().join("cube.csg");
    std::fs::write(&cube, "cube([1, 1, 1]);\n").unwrap();
    let large = dir.path().join("large.nrrd");
    run(&cube, "256x256x256", &large);
    let taken = std::fs::metadata(&large).unwrap().blocks() * 512;
    assert!(taken >= WORTH_A_CHILD, "{taken} bytes on disk");
    assert_eq!(reap(Duration::from_millis(300)), [] as [i32; 0]);
    run(&cube, "256x256x256", &large);
    let left = reap(Duration::from_secs(10));
    assert_eq!(left.len(), 1, "children left: {left:?}");
    assert!(libc::WIFEXITED(left[0]) && libc::WEXITSTATUS(left[0]) == 0);
}

//! A failed allocation under `ExitOnOom` ends the process with one line and exit status 2,
//! its staged outputs removed, where Rust's default would abort and leave them. The test
//! runs itself as a child under an address-space limit (setrlimit) and allocates past it.

use std::path::Path;
use std::process::Command;

use csgpix_output::{ExitOnOom, Outputs};

#[global_allocator]
static ALLOC: ExitOnOom = ExitOnOom;

const CHILD: &str = "CSGPIX_OOM_CHILD_DIR";

/// In the child: stage an output, lower the address space to 256 MiB, ask for 1 GiB.
fn child(dir: &Path) -> ! {
    let mut outs = Outputs::new();
    let out = outs.file("-o", &dir.join("v.nrrd"), &["nrrd"]).unwrap();
    outs.write(out, |w| w.write_all(b"NRRD0004\n")).unwrap();
    let limit = libc::rlimit {
        rlim_cur: 256 << 20,
        rlim_max: libc::RLIM_INFINITY,
    };
    // SAFETY: setrlimit(2) on this process, with an initialised struct.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_AS, &limit) }, 0);
    let v: Vec<u8> = Vec::with_capacity(1 << 30);
    std::hint::black_box(&v);
    // Not reached: the allocation fails and the allocator ends the process.
    std::process::exit(0)
}

#[test]
fn a_failed_allocation_exits_2_in_one_line_and_removes_the_staged_outputs() {
    if let Some(dir) = std::env::var_os(CHILD) {
        child(Path::new(&dir));
    }
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "a_failed_allocation_exits_2_in_one_line_and_removes_the_staged_outputs",
            "--test-threads=1",
            "--nocapture",
        ])
        .env(CHILD, dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 1, "{err}");
    assert!(
        lines[0].starts_with("csgpix: out of memory: an allocation of 1024 MiB failed"),
        "{err}"
    );
    assert!(lines[0].contains("address-space limit 256 MiB"), "{err}");
    let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");
}

//! Output files through the CLI: symlinks, FIFOs and devices written through, `-o -`, output
//! names checked before the run, all outputs or none, nothing left behind by a signal
//! (crates/output), and what SIGKILL leaves cleared by the next run.

mod common;
use common::csgpix;

use std::path::Path;
use std::process::{Command, Stdio};

const CUBE: &str = "vectors/thesis/cube.dl";
const TWELVE: &str = "vectors/scenes/twelve.csg";

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every name in `dir`, sorted (hidden staging files included).
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn one_line_error(out: &std::process::Output) -> String {
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.starts_with("csgpix: "), "{err}");
    err
}

#[cfg(unix)]
#[test]
fn a_symlinked_output_replaces_the_file_it_names_and_stays_a_symlink() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.png");
    let link = dir.path().join("link.png");
    std::fs::write(&real, b"old").unwrap();
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let out = csgpix(&["render", CUBE, "-o", s(&link)]);
    assert!(out.status.success(), "{out:?}");
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read(&real).unwrap().starts_with(b"\x89PNG"));
    assert_eq!(names(dir.path()), ["link.png", "real.png"]);
}

#[cfg(unix)]
#[test]
fn a_fifo_is_written_through_not_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.nrrd");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let out = csgpix(&["voxelize", TWELVE, "--res", "16x16x16", "-o", s(&fifo)]);
    assert!(out.status.success(), "{out:?}");
    let bytes = reader.join().unwrap();
    let file = dir.path().join("file.nrrd");
    let out = csgpix(&["voxelize", TWELVE, "--res", "16x16x16", "-o", s(&file)]);
    assert!(out.status.success(), "{out:?}");
    assert_eq!(bytes, std::fs::read(&file).unwrap());
    let ft = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    assert!(ft.is_fifo());
}

#[cfg(unix)]
#[test]
fn dev_null_stays_a_device() {
    use std::os::unix::fs::FileTypeExt;
    let out = csgpix(&["render", CUBE, "-o", "/dev/null"]);
    assert!(out.status.success(), "{out:?}");
    let m = std::fs::symlink_metadata("/dev/null").unwrap();
    assert!(m.file_type().is_char_device());
}

#[test]
fn dash_writes_the_same_bytes_to_standard_output_and_reports_on_standard_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("cube.png");
    let to_file = csgpix(&["render", CUBE, "-o", s(&file)]);
    assert!(to_file.status.success(), "{to_file:?}");
    let to_stdout = csgpix(&["render", CUBE, "-o", "-"]);
    assert!(to_stdout.status.success(), "{to_stdout:?}");
    assert_eq!(to_stdout.stdout, std::fs::read(&file).unwrap());
    assert!(String::from_utf8_lossy(&to_stdout.stderr).contains("cycles"));
    // A NRRD volume too.
    let nrrd = dir.path().join("v.nrrd");
    let a = csgpix(&["voxelize", TWELVE, "--res", "12x12x12", "-o", s(&nrrd)]);
    let b = csgpix(&["voxelize", TWELVE, "--res", "12x12x12", "-o", "-"]);
    assert!(a.status.success() && b.status.success(), "{b:?}");
    assert_eq!(b.stdout, std::fs::read(&nrrd).unwrap());
}

#[test]
fn dash_is_refused_where_the_format_or_json_needs_standard_output() {
    let e = one_line_error(&csgpix(&["render", CUBE, "--json", "-o", "-"]));
    assert!(e.contains("--json"), "{e}");
    let e = one_line_error(&csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "8x8x8",
        "--mesh",
        "-",
        "-o",
        "/dev/null",
    ]));
    assert!(e.contains("--mesh"), "{e}");
    let e = one_line_error(&csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "8x8x8",
        "--preview",
        "-",
        "-o",
        "-",
    ]));
    assert!(e.contains("only one output"), "{e}");
}

#[test]
fn output_extensions_are_checked_before_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&[&str], &str); 5] = [
        (&["render", CUBE, "-o"], "x.jpg"),
        (&["voxelize", TWELVE, "--res", "8x8x8", "-o"], "x.raw"),
        (&["phantom", "--size", "4", "-o"], "x.nhdr"),
        (
            &[
                "voxelize",
                TWELVE,
                "--res",
                "8x8x8",
                "-o",
                "/dev/null",
                "--mesh",
            ],
            "x.off",
        ),
        (
            &[
                "voxelize",
                TWELVE,
                "--res",
                "8x8x8",
                "-o",
                "/dev/null",
                "--preview",
            ],
            "x.gif",
        ),
    ];
    for (args, name) in cases {
        let p = dir.path().join(name);
        let mut all = args.to_vec();
        all.push(s(&p));
        let e = one_line_error(&csgpix(&all));
        assert!(e.contains(name) && e.contains("must end in"), "{e}");
    }
    assert!(names(dir.path()).is_empty(), "{:?}", names(dir.path()));
}

#[test]
fn a_run_that_cannot_write_its_output_leaves_no_side_output() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "16x16x16",
        "--preview",
        s(&d.join("p.png")),
        "--mesh",
        s(&d.join("m.stl")),
        "--slices",
        s(&d.join("slices")),
        "-o",
        s(&d.join("missing-dir/o.nrrd")),
    ]);
    let e = one_line_error(&out);
    assert!(e.contains("missing-dir"), "{e}");
    assert!(names(d).is_empty(), "{:?}", names(d));
}

#[test]
fn a_run_that_fails_after_naming_its_outputs_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bad = d.join("bad.csg");
    std::fs::write(&bad, "cube(1);\nsphere(r = );\n").unwrap();
    let out = csgpix(&[
        "voxelize",
        s(&bad),
        "--res",
        "16x16x16",
        "--preview",
        s(&d.join("p.png")),
        "--slices",
        s(&d.join("slices")),
        "-o",
        s(&d.join("o.nrrd")),
    ]);
    one_line_error(&out);
    assert_eq!(names(d), ["bad.csg"]);
}

#[test]
fn every_output_of_a_run_is_written_together() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "16x16x16",
        "--preview",
        s(&d.join("p.png")),
        "--mesh",
        s(&d.join("m.ply")),
        "--slices",
        s(&d.join("a/slices")),
        "-o",
        s(&d.join("o.nrrd")),
    ]);
    assert!(out.status.success(), "{out:?}");
    assert_eq!(names(d), ["a", "m.ply", "o.nrrd", "p.png"]);
    assert_eq!(names(&d.join("a/slices")).len(), 16);
}

/// Start a long voxelization, wait until its outputs are staged, send `sig`, and check that
/// the process died of it leaving nothing behind.
#[cfg(unix)]
fn interrupted(sig: i32) {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args([
            "voxelize",
            TWELVE,
            "--res",
            "256x256x256",
            "--model",
            "cycle",
        ])
        .args([
            "--slices",
            s(&d.join("slices")),
            "--preview",
            s(&d.join("p.png")),
        ])
        .args(["-o", s(&d.join("o.nrrd"))])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let t0 = std::time::Instant::now();
    while names(d).len() < 3 {
        assert!(t0.elapsed().as_secs() < 60, "outputs never staged");
        assert!(
            child.try_wait().unwrap().is_none(),
            "finished before the signal"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(
        names(d).iter().all(|n| n.ends_with(".csgpix-tmp")),
        "{:?}",
        names(d)
    );
    std::thread::sleep(std::time::Duration::from_millis(300));
    // SAFETY: kill(2) on our own child's pid.
    assert_eq!(unsafe { libc::kill(child.id() as i32, sig) }, 0);
    let status = child.wait().unwrap();
    assert_eq!(status.signal(), Some(sig), "{status:?}");
    assert!(names(d).is_empty(), "{:?}", names(d));
}

#[cfg(unix)]
#[test]
fn sigterm_leaves_no_staged_output() {
    interrupted(libc::SIGTERM);
}

#[cfg(unix)]
#[test]
fn sigint_leaves_no_staged_output() {
    interrupted(libc::SIGINT);
}

/// A signal while the slices are being written, one file after another into their staging
/// directory: the directory goes, whatever file the run was creating in it.
#[cfg(unix)]
#[test]
fn a_signal_while_slices_are_written_leaves_no_staging_directory() {
    use std::os::unix::process::ExitStatusExt;
    for _ in 0..3 {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let mut child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["voxelize", TWELVE, "--res", "48x48x4000"])
            .args(["--slices", s(&d.join("slices")), "-o", s(&d.join("o.nrrd"))])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let staged_slices = || {
            let staging = names(d).into_iter().find(|n| n.starts_with(".slices."))?;
            std::fs::read_dir(d.join(staging)).ok().map(Iterator::count)
        };
        let t0 = std::time::Instant::now();
        while staged_slices().unwrap_or(0) < 20 {
            assert!(t0.elapsed().as_secs() < 60, "slices never staged");
            assert!(child.try_wait().unwrap().is_none(), "finished first");
            std::thread::yield_now();
        }
        // SAFETY: kill(2) on our own child's pid.
        assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(libc::SIGINT), "{status:?}");
        assert!(names(d).is_empty(), "{:?}", names(d));
    }
}

/// `-o /dev/fd/3` (or `/dev/stderr`, or a shell's `>(…)`) naming a pipe: written through.
#[cfg(unix)]
#[test]
fn a_pipe_named_through_dev_fd_is_written_through() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("cube.png");
    let to_file = csgpix(&["render", CUBE, "-o", s(&file)]);
    assert!(to_file.status.success(), "{to_file:?}");
    // fd 3 is the pipe this test reads as standard output; csgpix's own goes to /dev/null.
    let out = Command::new("sh")
        .arg("-c")
        .arg("exec \"$0\" render \"$1\" -o /dev/fd/3 3>&1 >/dev/null")
        .arg(env!("CARGO_BIN_EXE_csgpix"))
        .arg(CUBE)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert_eq!(out.stdout, std::fs::read(&file).unwrap());
}

/// Writing through to a FIFO nobody reads waits, as `cat > fifo` does, but a signal still
/// ends the run.
#[cfg(unix)]
#[test]
fn a_signal_ends_a_run_waiting_on_a_fifo_without_a_reader() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.png");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let mut child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["render", CUBE, "-o", s(&fifo)])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // The render takes milliseconds; then it waits to open the FIFO.
    std::thread::sleep(std::time::Duration::from_millis(700));
    assert!(
        child.try_wait().unwrap().is_none(),
        "did not wait for a reader"
    );
    // SAFETY: kill(2) on our own child's pid.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGTERM) }, 0);
    let t0 = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if t0.elapsed().as_secs() >= 10 {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!("SIGTERM did not end a run waiting on a FIFO");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    assert_eq!(status.signal(), Some(libc::SIGTERM), "{status:?}");
    assert_eq!(names(dir.path()), ["out.png"]);
}

/// A signal that comes once some outputs are in place ends the run as interrupted, and says
/// which outputs were already written whole: here the VCD is renamed into place, then the
/// render waits for a reader of its FIFO.
#[cfg(unix)]
#[test]
fn a_late_signal_says_which_outputs_are_already_whole() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.png");
    let vcd = dir.path().join("w.vcd");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let args = [
        "render",
        CUBE,
        "--probe",
        "0,0",
        "--vcd",
        s(&vcd),
        "-o",
        s(&fifo),
    ];
    let child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let t0 = std::time::Instant::now();
    while !vcd.exists() {
        assert!(
            t0.elapsed().as_secs() < 20,
            "the VCD was never put in place"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(200));
    // SAFETY: kill(2) on our own child's pid.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.signal(), Some(libc::SIGINT), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    let said = format!(
        "csgpix: interrupted by SIGINT; already written whole: {}\n",
        s(&vcd)
    );
    assert_eq!(err, said);
    assert!(std::fs::read_to_string(&vcd)
        .unwrap()
        .contains("$enddefinitions"));
    assert_eq!(names(dir.path()), ["out.png", "w.vcd"]);
}

/// `--vcd`, `--wave` and `--forces` are named with `-o` and go with it: a path that cannot
/// be written, whichever it is, leaves none of the others (nor their staging files).
#[test]
fn side_outputs_of_render_and_sculpt_go_with_the_output_or_not_at_all() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = |name: &str| s(&d.join(name)).to_string();
    let render = |vcd: &str, png: &str| {
        let probe = ["render", CUBE, "--probe", "0,0", "--vcd", vcd];
        csgpix(&[&probe[..], &["--wave", &p("w.svg"), "-o", png]].concat())
    };
    let sculpt = |forces: &str, mesh: &str| {
        let head = ["sculpt", TWELVE, "--res", "16x16x16", "--tool", "sphere:1"];
        let tail = [
            "--path",
            "vectors/paths/carve.csv",
            "--forces",
            forces,
            "-o",
            mesh,
        ];
        csgpix(&[&head[..], &tail[..]].concat())
    };
    let runs = [
        render(&p("w.vcd"), &p("missing/r.png")),
        render(&p("missing/w.vcd"), &p("r.png")),
        sculpt(&p("f.csv"), &p("missing/c.stl")),
        sculpt(&p("missing/f.csv"), &p("c.stl")),
    ];
    for out in runs {
        let e = one_line_error(&out);
        assert!(e.contains("missing"), "{e}");
        assert!(names(d).is_empty(), "{:?}", names(d));
    }
    // The same runs with every path writable write everything.
    assert!(render(&p("w.vcd"), &p("r.png")).status.success());
    assert!(sculpt(&p("f.csv"), &p("c.stl")).status.success());
    assert_eq!(names(d), ["c.stl", "f.csv", "r.png", "w.svg", "w.vcd"]);
}

/// `--slices` is written whole: a run at a lower resolution into the directory of an
/// earlier one leaves only its own slices, none of the earlier run's higher-numbered ones.
#[test]
fn slices_of_an_earlier_run_are_replaced_whole() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let run = |res: &str| {
        let slices = d.join("slices");
        let args = ["voxelize", TWELVE, "--res", res, "--slices", s(&slices)];
        let out = csgpix(&[&args[..], &["-o", s(&d.join("o.nrrd"))]].concat());
        assert!(out.status.success(), "{out:?}");
        names(&slices)
    };
    assert_eq!(run("16x16x16").len(), 16);
    let slices = run("8x8x8");
    let want: Vec<String> = (0..8).map(|k| format!("slice-{k:04}.png")).collect();
    assert_eq!(slices, want);
    assert_eq!(names(d), ["o.nrrd", "slices"]);
}

/// A `--slices` directory holding anything csgpix does not write there (another file, a
/// subdirectory, a symlink) is refused before the run, named, and kept as it is; an empty
/// one is used.
#[test]
fn a_slices_directory_of_other_files_is_refused_and_kept() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let slices = d.join("slices");
    std::fs::create_dir(&slices).unwrap();
    let run = || {
        let args = ["voxelize", TWELVE, "--res", "8x8x8", "--slices", s(&slices)];
        csgpix(&[&args[..], &["-o", s(&d.join("o.nrrd"))]].concat())
    };
    std::fs::write(slices.join("slice-0000.png"), b"old").unwrap();
    for (other, make) in [
        ("notes.txt", 0),
        ("slice-0001.png.bak", 0),
        ("slice-x.png", 0),
        ("slice-0002.png", 1),
    ] {
        let p = slices.join(other);
        match make {
            0 => std::fs::write(&p, b"mine").unwrap(),
            _ => std::fs::create_dir(&p).unwrap(),
        }
        let e = one_line_error(&run());
        assert!(e.contains(&format!("holds {other}")), "{e}");
        assert!(e.contains("slice-N.png"), "{e}");
        assert_eq!(names(d), ["slices"], "nothing written");
        assert!(names(&slices).contains(&other.to_string()));
        match make {
            0 => std::fs::remove_file(&p).unwrap(),
            _ => std::fs::remove_dir(&p).unwrap(),
        }
    }
    #[cfg(unix)]
    {
        let link = slices.join("slice-0003.png");
        std::os::unix::fs::symlink(d.join("elsewhere.png"), &link).unwrap();
        let e = one_line_error(&run());
        assert!(e.contains("holds slice-0003.png"), "{e}");
        std::fs::remove_file(&link).unwrap();
    }
    std::fs::remove_file(slices.join("slice-0000.png")).unwrap();
    assert!(run().status.success());
    assert_eq!(names(&slices).len(), 8);
}

/// What SIGKILL leaves beside an output (a staging file, a staging directory being
/// removed) is removed by the next run naming that output, one line each on stderr; names
/// of other outputs, and names that are not exactly csgpix's, are kept.
#[test]
fn leftovers_of_an_interrupted_run_are_removed_by_the_next() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let ours = [
        ".o.nrrd.AbC123.csgpix-tmp",
        ".slices.XyZ789.csgpix-rm",
        ".slices.000000.csgpix-tmp",
    ];
    let kept = [
        ".o.nrrd.AbC12.csgpix-tmp",
        ".o.nrrd.AbC123.csgpix-tmp.bak",
        ".o.nrrd.notes",
        ".other.nrrd.AbC123.csgpix-tmp",
        "o.nrrd.AbC123.csgpix-tmp",
    ];
    for n in ours.iter().chain(&kept) {
        if n.ends_with("-rm") {
            std::fs::create_dir_all(d.join(n).join("0/c")).unwrap();
            std::fs::write(d.join(n).join("0/c/0"), b"x").unwrap();
        } else {
            std::fs::write(d.join(n), b"x").unwrap();
        }
    }
    let args = ["voxelize", TWELVE, "--res", "8x8x8"];
    let (slices, nrrd) = (d.join("slices"), d.join("o.nrrd"));
    let outs = ["--slices", s(&slices), "-o", s(&nrrd)];
    let out = csgpix(&[&args[..], &outs[..]].concat());
    assert!(out.status.success(), "{out:?}");
    let mut lines: Vec<String> = String::from_utf8_lossy(&out.stderr)
        .lines()
        .map(String::from)
        .collect();
    lines.sort();
    let mut want: Vec<String> = ours
        .iter()
        .map(|n| format!("csgpix: removed leftover {n} of an interrupted run"))
        .collect();
    want.sort();
    assert_eq!(lines, want);
    let mut left: Vec<String> = kept.iter().map(|n| n.to_string()).collect();
    left.extend(["o.nrrd".into(), "slices".into()]);
    left.sort();
    assert_eq!(names(d), left);
}

/// SIGKILL between a commit's two renames leaves the replaced store renamed aside and the
/// new one staged, and no store: the next run naming it puts the old one back (here a run
/// that then fails, so the store stays as it was) and removes the staged one.
#[test]
fn a_store_renamed_aside_by_an_interrupted_commit_is_restored() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let old = d.join(".v.zarr.AbC123.csgpix-old");
    std::fs::create_dir_all(old.join("0")).unwrap();
    std::fs::write(old.join("zarr.json"), b"the old store").unwrap();
    let new = d.join(".v.zarr.XyZ789.csgpix-tmp");
    std::fs::create_dir_all(&new).unwrap();
    std::fs::write(new.join("zarr.json"), b"the new store").unwrap();
    let missing = d.join("missing.csg");
    let store = d.join("v.zarr");
    let out = csgpix(&["voxelize", s(&missing), "--res", "8", "-o", s(&store)]);
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(out.status.code(), Some(2), "{err}");
    let restored = format!(
        "csgpix: restored {} from .v.zarr.AbC123.csgpix-old of an interrupted run",
        store.display()
    );
    assert_eq!(lines[0], restored, "{err}");
    assert_eq!(
        lines[1],
        "csgpix: removed leftover .v.zarr.XyZ789.csgpix-tmp of an interrupted run"
    );
    assert!(lines[2].contains("missing.csg"), "{err}");
    assert_eq!(names(d), ["v.zarr"]);
    assert_eq!(
        std::fs::read(store.join("zarr.json")).unwrap(),
        b"the old store"
    );
}

/// A staging file another run is still writing (locked, as every live run's is) is not a
/// leftover: a second run naming the same output leaves it alone.
#[cfg(unix)]
#[test]
fn a_live_runs_staging_file_is_left_alone() {
    use std::os::fd::AsRawFd;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let live = d.join(".o.nrrd.AbC123.csgpix-tmp");
    let f = std::fs::File::create(&live).unwrap();
    // SAFETY: flock(2) on a descriptor this test owns.
    assert_eq!(unsafe { libc::flock(f.as_raw_fd(), libc::LOCK_EX) }, 0);
    let out = csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "8x8x8",
        "-o",
        s(&d.join("o.nrrd")),
    ]);
    assert!(out.status.success(), "{out:?}");
    assert!(out.stderr.is_empty(), "{out:?}");
    assert_eq!(names(d), [".o.nrrd.AbC123.csgpix-tmp", "o.nrrd"]);
    drop(f);
    let out = csgpix(&[
        "voxelize",
        TWELVE,
        "--res",
        "8x8x8",
        "-o",
        s(&d.join("o.nrrd")),
    ]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("removed leftover"));
    assert_eq!(names(d), ["o.nrrd"]);
}

/// A run killed by SIGKILL while it writes a store that replaces an earlier one: the
/// earlier store is still there, whole, beside the killed run's staging directory, which
/// the next run removes, reporting it, before it writes its own.
#[cfg(unix)]
#[test]
fn sigkill_leaves_the_old_store_and_a_leftover_the_next_run_removes() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let store = d.join("v.zarr");
    let small = ["voxelize", TWELVE, "--res", "8x8x8", "-o", s(&store)];
    assert!(csgpix(&small).status.success());
    let before = std::fs::read(store.join("zarr.json")).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["voxelize", TWELVE, "--res", "48x48x4000", "--chunk", "4"])
        .args(["--shard", "none", "-o", s(&store)])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let staged = || names(d).into_iter().find(|n| n.ends_with(".csgpix-tmp"));
    let t0 = std::time::Instant::now();
    while staged().is_none_or(|n| names(&d.join(n)).is_empty()) {
        assert!(t0.elapsed().as_secs() < 60, "never staged");
        assert!(child.try_wait().unwrap().is_none(), "finished first");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(200));
    // SAFETY: kill(2) on our own child's pid.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGKILL) }, 0);
    let status = child.wait().unwrap();
    assert_eq!(status.signal(), Some(libc::SIGKILL), "{status:?}");
    let leftover = staged().expect("SIGKILL leaves the staging directory");
    assert_eq!(std::fs::read(store.join("zarr.json")).unwrap(), before);
    let out = csgpix(&small);
    assert!(out.status.success(), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    let want = format!("csgpix: removed leftover {leftover} of an interrupted run\n");
    assert_eq!(err, want);
    assert_eq!(names(d), ["v.zarr"]);
}

/// Whether this file system leaves a block never written unallocated (ext4, xfs, tmpfs do).
#[cfg(unix)]
fn keeps_holes(dir: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    let probe = dir.join("probe");
    let f = std::fs::File::create(&probe).unwrap();
    f.set_len(1 << 20).unwrap();
    let blocks = std::fs::metadata(&probe).unwrap().blocks();
    std::fs::remove_file(&probe).unwrap();
    blocks * 512 < 1 << 20
}

/// A voxel file's runs of zeros of 1 MiB or more are holes (crates/output `Sparse`,
/// `VOLUME_HOLE`): it reads back as the same voxels as the gzip file of the same run, whether
/// the volume is streamed or held (`--preview` holds it), and takes fewer bytes on disk than
/// its length: two slabs 98 units apart at 256³ leave 250 empty slices of 64 KiB between
/// them (a 16 MiB hole; the file is 16.8 MB long and takes 0.5 MB here).
#[cfg(unix)]
#[test]
fn a_volume_file_leaves_its_empty_slices_as_holes() {
    use std::io::Read;
    use std::os::unix::fs::MetadataExt;
    let dir = tempfile::tempdir().unwrap();
    let p = |n: &str| dir.path().join(n);
    let scene = p("apart.csg");
    std::fs::write(
        &scene,
        "cube([10, 10, 1]);\nmultmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,99],[0,0,0,1]]) \
         cube([10, 10, 1]);\n",
    )
    .unwrap();
    let run = |extra: &[&str]| {
        let mut args = vec!["voxelize", s(&scene), "--res", "256x256x256"];
        args.extend_from_slice(extra);
        let out = csgpix(&args);
        assert!(out.status.success(), "{out:?}");
    };
    run(&["-o", s(&p("streamed.nrrd"))]);
    run(&["-o", s(&p("held.nrrd")), "--preview", s(&p("v.png"))]);
    run(&["-o", s(&p("gz.nrrd")), "--compress"]);
    let gz = std::fs::read(p("gz.nrrd")).unwrap();
    let split = gz.windows(2).position(|w| w == b"\n\n").unwrap() + 2;
    let mut voxels = Vec::new();
    flate2::read::GzDecoder::new(&gz[split..])
        .read_to_end(&mut voxels)
        .unwrap();
    assert!(voxels.iter().any(|&v| v != 0) && voxels.contains(&0));
    for name in ["streamed.nrrd", "held.nrrd"] {
        let bytes = std::fs::read(p(name)).unwrap();
        let (_, data) = csgpix::scene::nrrd::read(&bytes).unwrap();
        assert!(
            data == voxels,
            "{name}: the voxels differ from the gzip file's"
        );
        if keeps_holes(dir.path()) {
            let on_disk = std::fs::metadata(p(name)).unwrap().blocks() * 512;
            assert!(
                on_disk < bytes.len() as u64 / 4,
                "{name}: {on_disk} bytes on disk of {}",
                bytes.len()
            );
        }
    }
}

/// Every process's descriptor of the unlinked file with inode `ino` on device `dev`, as
/// `/proc/PID/fd/N` (the processes this user may read). Unlinked only: once the file is
/// freed, its inode number may name a new file of another test.
#[cfg(target_os = "linux")]
fn holders(dev: u64, ino: u64) -> Vec<String> {
    use std::os::unix::fs::MetadataExt;
    let mut found = Vec::new();
    for pid in std::fs::read_dir("/proc").unwrap().flatten() {
        let Ok(fds) = std::fs::read_dir(pid.path().join("fd")) else {
            continue;
        };
        for fd in fds.flatten() {
            let held = |m: std::fs::Metadata| (m.dev(), m.ino(), m.nlink()) == (dev, ino, 0);
            if std::fs::metadata(fd.path()).is_ok_and(held) {
                found.push(fd.path().display().to_string());
            }
        }
    }
    found
}

/// A replaced output's old file leaves the directory before the run returns, and its blocks
/// are freed after (crates/output/src/release.rs; a file of 16 MiB, so that a child holds
/// it): no process holds it for long once the run has ended. The new file is whole, and
/// nothing else is left beside it.
#[cfg(target_os = "linux")]
#[test]
fn a_replaced_outputs_old_file_is_gone_at_once_and_held_by_nothing_after_the_run() {
    use std::os::unix::fs::MetadataExt;
    use std::time::{Duration, Instant};
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("v.nrrd");
    let cube = dir.path().join("cube.csg");
    std::fs::write(&cube, "cube([1, 1, 1]);\n").unwrap();
    let run = || {
        let r = csgpix(&["voxelize", s(&cube), "--res", "256x256x256", "-o", s(&out)]);
        assert!(r.status.success(), "{r:?}");
    };
    run();
    let first = std::fs::read(&out).unwrap();
    let old = std::fs::metadata(&out).unwrap();
    assert!(old.blocks() * 512 >= csgpix::output::WORTH_A_CHILD);
    run();
    let new = std::fs::metadata(&out).unwrap();
    assert_ne!(
        new.ino(),
        old.ino(),
        "the output was replaced, not rewritten"
    );
    assert_eq!(std::fs::read(&out).unwrap(), first);
    assert_eq!(names(dir.path()), ["cube.csg", "v.nrrd"]);
    let start = Instant::now();
    loop {
        let held = holders(old.dev(), old.ino());
        if held.is_empty() {
            break;
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "the old file is still held 10 s after the run: {held:?}"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The binary as the holder of a released file ([`csgpix_output::HOLD`] set): it keeps the
/// file open on its standard output while its standard input is open, says nothing, and ends
/// with status 0 when its input ends. A pipe it inherited as descriptor 100 (as a run inherits
/// its caller's `-o /dev/fd/N`) it closes at once: the reader sees its end while the holder
/// still waits.
#[cfg(target_os = "linux")]
#[test]
fn the_binary_holds_a_released_file_until_its_input_ends() {
    use std::os::unix::fs::MetadataExt;
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("old.nrrd");
    std::fs::write(&path, [1u8; 4096]).unwrap();
    let file = std::fs::File::open(&path).unwrap();
    let ino = file.metadata().unwrap().ino();
    std::fs::remove_file(&path).unwrap();
    let mut fds = [0; 2];
    // SAFETY: pipe2(2) into an array this frame owns; close-on-exec, so that no other test's
    // child inherits it.
    assert_eq!(unsafe { libc::pipe2(fds.as_mut_ptr(), libc::O_CLOEXEC) }, 0);
    let [read_end, write_end] = fds;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_csgpix"));
    cmd.env(csgpix::output::HOLD, "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::from(file))
        .stderr(Stdio::piped());
    // SAFETY: dup2(2) and fcntl(2) between fork and exec, async-signal-safe: the write end
    // as descriptor 100, without close-on-exec (dup2 onto itself would keep the flag).
    unsafe {
        use std::os::unix::process::CommandExt;
        cmd.pre_exec(move || {
            let r = match write_end {
                100 => libc::fcntl(100, libc::F_SETFD, 0),
                _ => libc::dup2(write_end, 100),
            };
            match r {
                -1 => Err(std::io::Error::last_os_error()),
                _ => Ok(()),
            }
        });
    }
    let mut child = cmd.spawn().unwrap();
    // SAFETY: this process's copy of the write end, which it no longer uses; the read end is
    // owned from here by the File.
    let mut reader = unsafe {
        use std::os::fd::FromRawFd;
        libc::close(write_end);
        std::fs::File::from_raw_fd(read_end)
    };
    // The reader sees the pipe's end within 5 s: no process holds the write end any more.
    let mut ready = libc::pollfd {
        fd: read_end,
        events: libc::POLLIN,
        revents: 0,
    };
    // SAFETY: poll(2) on one descriptor this frame owns.
    assert_eq!(
        unsafe { libc::poll(&mut ready, 1, 5000) },
        1,
        "the pipe stays open"
    );
    let mut rest = Vec::new();
    std::io::Read::read_to_end(&mut reader, &mut rest).unwrap();
    assert!(rest.is_empty());
    std::thread::sleep(std::time::Duration::from_millis(300));
    assert!(
        child.try_wait().unwrap().is_none(),
        "it waits for its input"
    );
    let held = std::fs::metadata(format!("/proc/{}/fd/1", child.id())).unwrap();
    assert_eq!((held.ino(), held.nlink()), (ino, 0));
    drop(child.stdin.take());
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(out.stderr.is_empty(), "{out:?}");
}

/// A signal that ends a `--fallback openscad` run ends openscad with it (its process group:
/// here a stand-in script and its `sleep`) and removes the statement written beside the scene
/// and openscad's scratch directory in TMPDIR; they were left, and openscad kept running.
#[cfg(unix)]
#[test]
fn a_signal_ends_openscad_and_removes_its_scratch_files() {
    use std::os::unix::fs::PermissionsExt;
    use std::os::unix::process::ExitStatusExt;
    for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let (bin, tmp, scene) = (d.join("bin"), d.join("tmp"), d.join("scene"));
        for p in [&bin, &tmp, &scene] {
            std::fs::create_dir(p).unwrap();
        }
        // The stand-in writes a mesh into its -o path's directory and waits; its pid and its
        // child's are recorded.
        let fake = bin.join("openscad");
        let script = format!(
            "#!/bin/sh\necho $$ > {pids}\nprintf 'solid x\\nendsolid x\\n' > \"$2\"\n\
             sleep 60 &\necho $! >> {pids}\nwait\n",
            pids = d.join("pids").display()
        );
        std::fs::write(&fake, script).unwrap();
        std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
        // A DXF file csgpix refuses (a line over 64 KiB, which OpenSCAD reads): outlined by
        // openscad under the fallback.
        let statement = "linear_extrude(height = 1) import(file = \"h.dxf\");\ncube(1);\n";
        std::fs::write(scene.join("s.csg"), statement).unwrap();
        let dxf = format!("999\n{}\n0\nEOF\n", "x".repeat(70_000));
        std::fs::write(scene.join("h.dxf"), dxf).unwrap();
        let path = format!(
            "{}:{}",
            bin.display(),
            std::env::var("PATH").unwrap_or_default()
        );
        let mut child = Command::new(env!("CARGO_BIN_EXE_csgpix"))
            .current_dir(&scene)
            .env("PATH", path)
            .env("TMPDIR", &tmp)
            .args(["voxelize", "s.csg", "--res", "8", "--fallback", "openscad"])
            .args(["-o", s(&d.join("o.nrrd"))])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let t0 = std::time::Instant::now();
        let pids = || std::fs::read_to_string(d.join("pids")).unwrap_or_default();
        while pids().lines().count() < 2 {
            assert!(t0.elapsed().as_secs() < 30, "openscad never started");
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        assert!(
            names(&tmp).len() == 1,
            "openscad's scratch directory: {:?}",
            names(&tmp)
        );
        // SAFETY: kill(2) on our own child's pid.
        assert_eq!(unsafe { libc::kill(child.id() as i32, sig) }, 0);
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(sig), "{status:?}");
        assert!(names(&tmp).is_empty(), "left in TMPDIR: {:?}", names(&tmp));
        assert_eq!(names(&scene), ["h.dxf", "s.csg"]);
        assert!(!d.join("o.nrrd").exists());
        // Both processes are gone (kill(pid, 0) fails once a process is reaped or a zombie
        // of an exited parent; give init a moment to reap).
        for pid in pids().lines().map(|l| l.trim().parse::<i32>().unwrap()) {
            let t0 = std::time::Instant::now();
            // SAFETY: signal 0 only checks that the process exists.
            while unsafe { libc::kill(pid, 0) } == 0 {
                assert!(t0.elapsed().as_secs() < 10, "{pid} still running");
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
        }
    }
}

/// A report whose standard output has no reader (`| head` gone) or no room (`/dev/full`): one
/// line and exit status 2, naming the outputs already whole, for text and `--json` reports
/// (a panic, exit 101 with a backtrace, before).
#[cfg(unix)]
#[test]
fn a_closed_or_full_standard_output_is_one_line_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let nrrd = dir.path().join("v.nrrd");
    let voxelize = ["voxelize", TWELVE, "--res", "16", "-o", s(&nrrd)];
    let runs: Vec<Vec<&str>> = vec![
        vec!["throughput"],
        vec!["throughput", "--json"],
        vec!["verify-select"],
        voxelize.to_vec(),
        [&voxelize[..], &["--json"]].concat(),
    ];
    for args in &runs {
        for closed in [true, false] {
            let stdout: Stdio = if closed {
                // A pipe whose reading end is closed before csgpix starts: every write fails.
                let (reader, writer) = std::io::pipe().unwrap();
                drop(reader);
                writer.into()
            } else {
                let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
                full.unwrap().into()
            };
            let out = Command::new(env!("CARGO_BIN_EXE_csgpix"))
                .args(args)
                .current_dir(env!("CARGO_MANIFEST_DIR"))
                .stdout(stdout)
                .output()
                .unwrap();
            let err = one_line_error(&out);
            assert!(
                err.contains("cannot write to standard output"),
                "{args:?}: {err}"
            );
            let whole = err.contains(&format!("already written whole: {}", s(&nrrd)));
            assert_eq!(whole, args[0] == "voxelize", "{args:?}: {err}");
        }
    }
}

//! `--openscad-timeout`: every command that may run openscad stops it at the limit, in one
//! line, exit 2, nothing left behind. openscad is faked by a script earlier on PATH that
//! sleeps (and then writes a `.csg` where it was asked to), so these tests need no openscad.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// A fake `openscad` in `dir`: records its pid in `dir/pid`, sleeps `FAKE_SLEEP` seconds
/// (replaced by `sleep` when that is long, so killing it kills the sleep), then writes
/// `cube(1);` to the file after `-o`.
fn fake_openscad(dir: &Path) -> PathBuf {
    let bin = dir.join("bin");
    std::fs::create_dir(&bin).unwrap();
    let script = format!(
        "#!/bin/sh\necho $$ > '{}'\n\
         if [ \"$FAKE_SLEEP\" -gt 100 ]; then exec sleep \"$FAKE_SLEEP\"; fi\n\
         sleep \"$FAKE_SLEEP\"\n\
         while [ $# -gt 0 ]; do [ \"$1\" = -o ] && out=\"$2\"; shift; done\n\
         echo 'cube(1);' > \"$out\"\n",
        dir.join("pid").display()
    );
    let openscad = bin.join("openscad");
    std::fs::write(&openscad, script).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&openscad, std::fs::Permissions::from_mode(0o755)).unwrap();
    bin
}

fn run(bin: &Path, sleep: u32, args: &[&str]) -> (Output, Duration) {
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let t0 = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("PATH", path)
        .env("FAKE_SLEEP", sleep.to_string())
        .output()
        .unwrap();
    (out, t0.elapsed())
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// The fake's process is gone (killed and reaped, not left running).
fn gone(dir: &Path) {
    let pid = std::fs::read_to_string(dir.join("pid")).unwrap();
    let proc = PathBuf::from(format!("/proc/{}", pid.trim()));
    let t0 = Instant::now();
    while proc.exists() {
        assert!(
            t0.elapsed() < Duration::from_secs(5),
            "openscad left running"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Each command that reads `.scad` files: the limit kills openscad and the command says so
/// in one line, quickly, writing nothing.
#[test]
fn every_command_stops_openscad_at_its_time_limit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bin = fake_openscad(d);
    let scad = d.join("slow.scad");
    std::fs::write(&scad, "cube(1);\n").unwrap();
    let (scad, out) = (scad.to_str().unwrap(), d.join("out"));
    std::fs::create_dir(&out).unwrap();
    let o = |name: &str| out.join(name).to_str().unwrap().to_string();
    let carve = "vectors/paths/carve.csv";
    let commands: Vec<Vec<String>> = [
        vec!["voxelize", scad, "--res", "8", "-o", &o("v.nrrd")],
        vec!["voxelize", scad, "--res", "8", "-o", &o("v.zarr")],
        vec!["render", scad, "-o", &o("r.png")],
        vec!["requirements", scad],
        vec![
            "sculpt",
            scad,
            "--tool",
            "sphere:1",
            "--path",
            carve,
            "-o",
            &o("c.stl"),
        ],
        vec!["study", scad, "-o", &o("study")],
        vec!["throughput", "--scene", scad],
    ]
    .iter()
    .map(|c| c.iter().map(|s| s.to_string()).collect())
    .collect();
    for command in commands {
        let mut args: Vec<&str> = command.iter().map(String::as_str).collect();
        args.extend(["--openscad-timeout", "1"]);
        let (output, took) = run(&bin, 600, &args);
        let err = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
        let want =
            format!("csgpix: {scad}: openscad did not finish within 1 s (--openscad-timeout)\n");
        assert_eq!(err, want, "{args:?}");
        assert!(took < Duration::from_secs(20), "{args:?}: {took:?}");
        gone(d);
        assert!(names(&out).is_empty(), "{args:?}: {:?}", names(&out));
    }
}

/// `--fallback openscad`'s meshes have the same limit; the statement written beside the
/// scene for openscad is removed.
#[test]
fn a_fallback_mesh_is_stopped_at_the_limit_too() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bin = fake_openscad(d);
    let scene = d.join("scene");
    std::fs::create_dir(&scene).unwrap();
    let csg = scene.join("s.csg");
    // `roof`: a node of OpenSCAD releases after 2021.01, which csgpix does not read.
    std::fs::write(&csg, "cube(2);\nroof(method = \"straight\");\n").unwrap();
    let out = d.join("o.nrrd");
    let args = [
        "voxelize",
        csg.to_str().unwrap(),
        "--res",
        "8",
        "--fallback",
        "openscad",
        "--openscad-timeout",
        "1",
        "-o",
        out.to_str().unwrap(),
    ];
    let (output, _) = run(&bin, 600, &args);
    let err = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    let want = format!(
        "csgpix: {}:2:1: `roof` (--fallback openscad): openscad did not finish within 1 s \
         (--openscad-timeout)\n",
        csg.display()
    );
    assert_eq!(err, want);
    gone(d);
    assert_eq!(names(&scene), ["s.csg"]);
    assert!(!out.exists());
}

/// The limit is per run of openscad and 0 lifts it: an export of 2 s fails at 1 s, and
/// passes with 0 and with the default.
#[test]
fn zero_is_no_limit_and_the_default_is_minutes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bin = fake_openscad(d);
    let scad = d.join("two-seconds.scad");
    std::fs::write(&scad, "cube(1);\n").unwrap();
    let nrrd = d.join("o.nrrd");
    let args = |limit: &[&'static str]| -> Vec<String> {
        let mut a = vec!["requirements".to_string(), scad.display().to_string()];
        a.extend(limit.iter().map(|s| s.to_string()));
        a
    };
    for (limit, ok) in [
        (&["--openscad-timeout", "1"][..], false),
        (&["--openscad-timeout", "0"], true),
        (&[], true),
    ] {
        let a = args(limit);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let (output, took) = run(&bin, 2, &a);
        assert_eq!(output.status.success(), ok, "{a:?}: {output:?}");
        assert!(ok || took < Duration::from_millis(1900), "{took:?}");
    }
    assert!(!nrrd.exists());
    let help = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(["voxelize", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(help.contains("--openscad-timeout <SECONDS>"), "{help}");
    assert!(help.contains("[default: 300]"), "{help}");
}

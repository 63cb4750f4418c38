//! Malformed parts OpenSCAD 2021.01 warns about and renders the rest of the scene around
//! (`vectors/openscad/lenient/cases.txt`, made by its `generate.sh`): a colour out of range,
//! `polyhedron(points = undef)` and an index out of range, a negative `resize()`, a scale by
//! 0 in 3D and in 2D, imports of missing files and of `""`, infinite and NaN sizes and
//! translations, 2D children of 3D intersections and differences and the other way round.
//! Each case's CSG export is read by csgpix, which must warn and go on, and voxelized at 64³
//! against OpenSCAD's CGAL mesh of the same `.scad` (`NAME.off`; its warnings are in
//! `NAME.warnings`); with `strict` the first warning is the refusal instead.
//! `cargo test --release --test openscad_lenient -- --nocapture` prints the IoUs.

mod common;

use common::compare_with_off;

use std::path::{Path, PathBuf};

use csgpix::openscad::{parse_csg_with, ReadOptions};
use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/lenient")
}

fn cases() -> Vec<String> {
    let text = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split('\t').next().unwrap().to_string())
        .collect()
}

#[test]
fn malformed_parts_are_warned_about_and_the_rest_matches_openscad() {
    let mut failures = vec![];
    for name in cases() {
        match compare_with_off(&dir(), &name, Route::Array { cycle: false }) {
            Ok((float, word)) => {
                println!("{name:18} IoU float {float:.5}, word {word:.5}");
                if float < 0.999 || word < 0.99 {
                    failures.push(format!("{name}: float {float:.5}, word {word:.5}"));
                }
            }
            Err(e) => failures.push(format!("{name}: refused: {e}")),
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert_eq!(cases().len(), 9);
}

#[test]
fn each_case_warns_and_strict_refuses_at_the_first_warning() {
    for name in cases() {
        let file = format!("{name}.csg");
        let text = std::fs::read_to_string(dir().join(&file)).unwrap();
        let options = ReadOptions {
            dir: Some(dir()),
            ..Default::default()
        };
        let scene = parse_csg_with(&text, &file, &options).unwrap();
        assert!(!scene.warnings.is_empty(), "{name}: no warning");
        for w in &scene.warnings {
            let w = w.to_string();
            assert!(w.starts_with(&format!("{file}:")), "{name}: {w}");
        }
        let strict = ReadOptions {
            strict: true,
            ..options
        };
        let e = parse_csg_with(&text, &file, &strict).unwrap_err();
        assert_eq!(e.to_string(), scene.warnings[0].to_string(), "{name}");
    }
}

/// The command line: each warning one line on stderr, `csgpix: warning: FILE:LINE:COL: …`,
/// the same lines in `--json`; `--strict` exits 2 with the first as the one-line refusal and
/// writes nothing.
#[test]
fn the_command_line_prints_warnings_and_strict_writes_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let scene = dir().join("colour.csg");
    let out = tmp.path().join("o.nrrd");
    let args = |extra: &[&str]| {
        let mut a = vec![
            "voxelize".to_string(),
            scene.display().to_string(),
            "--res".into(),
            "8".into(),
            "-o".into(),
            out.display().to_string(),
        ];
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let run = |a: Vec<String>| {
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        common::csgpix(&a)
    };
    let o = run(args(&["--json"]));
    assert!(o.status.success());
    let stderr = String::from_utf8_lossy(&o.stderr);
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 4, "{stderr}");
    let want = format!("csgpix: warning: {}:1:8: color() expects", scene.display());
    assert!(lines[0].starts_with(&want), "{stderr}");
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let listed: Vec<String> = json["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| format!("csgpix: warning: {}", w.as_str().unwrap()))
        .collect();
    assert_eq!(listed, lines);
    std::fs::remove_file(&out).unwrap();
    let o = run(args(&["--strict"]));
    assert_eq!(o.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with(&format!("csgpix: {}:1:8: color()", scene.display())));
    assert!(!out.exists(), "nothing written under --strict");
    let o = run(args(&["--strict", "--fallback", "openscad"]));
    assert_eq!(o.status.code(), Some(2), "--strict refuses every warning");
}

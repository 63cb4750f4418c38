//! A scene's imports are read in parallel (`csgpix_voxel::sampled::load_imports_warned`) and
//! taken in order: the meshes in the order the scene names them, their warnings in that
//! order, and of several failing imports the first one's error, every time.

use std::path::Path;

use csgpix_testkit::box_stl;
use csgpix_voxel::sampled::{load_scene, Shape};

/// A scene in `dir` importing `files`, one a line from line 2, column 3.
fn scene(dir: &Path, files: &[String]) -> std::path::PathBuf {
    let lines: String = files
        .iter()
        .map(|f| format!("  import(file = \"{f}\");\n"))
        .collect();
    let path = dir.join("s.csg");
    std::fs::write(&path, format!("group() {{\n{lines}}}\n")).unwrap();
    path
}

#[test]
fn meshes_and_warnings_come_in_the_scenes_order() {
    let dir = tempfile::tempdir().unwrap();
    // Open and closed boxes of different sizes, alternating: only the open ones warn.
    let files: Vec<String> = (0..12).map(|k| format!("b{k}.stl")).collect();
    for (k, f) in files.iter().enumerate() {
        std::fs::write(dir.path().join(f), box_stl(1.0 + k as f32, k % 2 == 0)).unwrap();
    }
    let path = scene(dir.path(), &files);
    for _ in 0..8 {
        let l = load_scene(&path).unwrap();
        let names: Vec<&str> = l.sampled.iter().map(|s| s.file.as_str()).collect();
        assert_eq!(names, files.iter().map(String::as_str).collect::<Vec<_>>());
        for (k, s) in l.sampled.iter().enumerate() {
            let open = matches!(s.shape, Shape::OpenMesh(..));
            assert_eq!(open, k % 2 == 0, "{k}");
        }
        let warned: Vec<String> = l.scene.warnings.iter().map(|w| w.to_string()).collect();
        let expected: Vec<String> = (0..12)
            .step_by(2)
            .map(|k| format!("{}:{}:3: `b{k}.stl`", path.display(), k + 2))
            .collect();
        assert_eq!(warned.len(), expected.len(), "{warned:?}");
        for (w, e) in warned.iter().zip(&expected) {
            assert!(w.starts_with(e), "{w} / {e}");
        }
    }
}

#[test]
fn of_several_failing_imports_the_first_is_told() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("ok.stl"), box_stl(2.0, false)).unwrap();
    // Meshes that cannot be read, after a missing file (which OpenSCAD, and so the reader,
    // only warns of) and between good ones.
    for k in 1..=3 {
        let cut = "solid b\nfacet normal\n".repeat(k);
        std::fs::write(dir.path().join(format!("bad{k}.stl")), cut).unwrap();
    }
    let names = [
        "ok.stl", "gone.stl", "bad1.stl", "ok.stl", "bad2.stl", "bad3.stl",
    ];
    let files: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    let path = scene(dir.path(), &files);
    for _ in 0..8 {
        let e = load_scene(&path)
            .err()
            .expect("an unreadable import")
            .to_string();
        assert!(e.contains("bad1.stl"), "{e}");
    }
}

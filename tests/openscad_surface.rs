//! `surface()` against OpenSCAD's own geometry: each case of
//! `vectors/openscad/surface/cases.txt` (made by its `generate.sh` with openscad 2021.01) is a
//! `surface()` of a `.dat` grid (plain, with comments, blank lines, negative values and a
//! short row, cut short by an illegal value) or of a PNG image (8-bit grey, RGB, a palette
//! with an index past it, 16-bit grey), with `center` and `invert`, under a transform and in
//! a difference, read from OpenSCAD's CSG export by csgpix (module `surface` of
//! crates/openscad) and voxelized at 64³, against OpenSCAD's CGAL mesh of the same export
//! (`NAME.off`) voxelized on the same grid. The IoU must reach 0.999 on the float route and
//! 0.99 on the word route; `cargo test --release --test openscad_surface -- --nocapture`
//! prints them.

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/surface")
}

#[test]
fn surface_matches_openscads_mesh() {
    let compared =
        compare_cases(&dir(), Route::Array { cycle: false }).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 11);
}

fn read(text: &str, dir: &Path) -> csgpix::scene::Result<csgpix::scene::solid::CsgScene> {
    let options = csgpix::openscad::ReadOptions {
        dir: Some(dir.to_path_buf()),
        ..Default::default()
    };
    csgpix::openscad::parse_csg_with(text, "t.csg", &options)
}

/// Where OpenSCAD warns and goes on (an illegal value in a grid, a file it cannot open or
/// decode), csgpix records the warning at the node and draws what OpenSCAD draws.
#[test]
fn openscads_warnings_are_kept_at_the_node() {
    use csgpix::scene::solid::CsgNode;
    let text = std::fs::read_to_string(dir().join("illegal.csg")).unwrap();
    let scene = read(&text, &dir()).unwrap();
    let w: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].starts_with("t.csg:1:1: Illegal value in '"), "{w:?}");
    assert!(
        w[0].ends_with("illegal.dat:3:5: `x` is not a number; the rest of the file is ignored"),
        "{w:?}"
    );
    assert_eq!(scene.imports.len(), 1);

    let tmp = tempfile::tempdir().unwrap();
    std::fs::write(tmp.path().join("bad.png"), b"\x89PNG\r\n\x1a\nnot an image").unwrap();
    for (file, warning) in [
        ("missing.dat", "couldn't be opened."),
        ("", "couldn't be opened."),
        ("bad.png", "Can't read PNG image '"),
    ] {
        let text = format!("group() {{\n  surface(file = \"{file}\", center = false, invert = false, timestamp = 0);\n  cube(1);\n}}\n");
        let scene = read(&text, tmp.path()).unwrap();
        let w: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(w.len(), 1, "{file}: {w:?}");
        assert!(w[0].starts_with("t.csg:2:3: "), "{w:?}");
        assert!(w[0].contains(warning), "{w:?}");
        // The cube alone.
        assert_eq!(scene.root, CsgNode::Solid(0), "{file}");
        assert!(scene.imports.is_empty());
    }
}

/// What csgpix refuses (a height that is not finite, a grid past the vertex limit, a file
/// name that is not a string) is one line naming the node's place and the file's.
#[test]
fn refusals_are_one_line_at_the_node() {
    let tmp = tempfile::tempdir().unwrap();
    std::fs::write(tmp.path().join("inf.dat"), "1 2\n3 -inf\n").unwrap();
    std::fs::write(tmp.path().join("big.dat"), "1 2 3\n4 5 6\n").unwrap();
    let e = read("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n  surface(\"inf.dat\");\n", tmp.path())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("t.csg:2:3: "), "{e}");
    assert!(
        e.contains("inf.dat:2:3: `surface(\"inf.dat\")`: a height of `-inf`"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1);
    let options = csgpix::openscad::ReadOptions {
        dir: Some(tmp.path().to_path_buf()),
        max_vertices: Some(20),
        ..Default::default()
    };
    let e = csgpix::openscad::parse_csg_with("surface(\"big.dat\");", "t.csg", &options)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("t.csg:1:1: "), "{e}");
    assert!(e.contains("would pass the scene's vertex limit"), "{e}");
    let e = read("surface(file = 5);", tmp.path())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("t.csg:1:16: `file` must be a string"), "{e}");
}

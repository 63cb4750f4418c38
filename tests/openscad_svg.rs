//! `import()` of SVG files against OpenSCAD's own geometry: each case of
//! `vectors/openscad/svg/cases.txt` (made by its `generate.sh` with openscad 2021.01) is a
//! `linear_extrude` of an SVG drawing (rectangles rounded or not, circles and ellipses under
//! nested group transforms, paths of cubic and quadratic Béziers and arcs, holes by the
//! even-odd rule, open paths drawn as strokes, a viewBox in inches and pixels with
//! `preserveAspectRatio` and `center`, a page without viewBox at a given `dpi`), read from
//! OpenSCAD's CSG export by csgpix (module `svg` of crates/openscad) and voxelized at 64³,
//! against OpenSCAD's CGAL mesh of the same export (`NAME.off`) voxelized on the same grid.
//! The IoU must reach 0.999 on the float route and 0.99 on the word route;
//! `cargo test --release --test openscad_svg -- --nocapture` prints them.

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/svg")
}

#[test]
fn svg_import_matches_openscads_mesh() {
    let compared =
        compare_cases(&dir(), Route::Array { cycle: false }).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 7);
}

/// A bad SVG file is one line naming the import's place in the scene; a missing one is a
/// warning there, as OpenSCAD's.
#[test]
fn bad_svg_is_one_line_at_the_import() {
    let tmp = tempfile::tempdir().unwrap();
    std::fs::write(
        tmp.path().join("bad.svg"),
        "<svg><path d='M 0 0 L 1 1'></svg>",
    )
    .unwrap();
    std::fs::write(tmp.path().join("page.svg"), "<html/>").unwrap();
    let options = csgpix::openscad::ReadOptions {
        dir: Some(tmp.path().to_path_buf()),
        ..Default::default()
    };
    for (file, why) in [
        ("bad.svg", "not a valid SVG file"),
        ("page.svg", "not an SVG file"),
    ] {
        let text = format!("union() {{\n  linear_extrude(1)\n    import(file = \"{file}\");\n}}\n");
        let e = csgpix::openscad::parse_csg_with(&text, "t.csg", &options)
            .err()
            .unwrap_or_else(|| panic!("{file} accepted"))
            .to_string();
        assert!(e.starts_with("t.csg:3:5:"), "{e}");
        assert!(e.contains(why), "{e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
    // A missing file imports nothing with OpenSCAD's warning; `strict` refuses at it.
    let text =
        "union() {\n  linear_extrude(1)\n    import(file = \"missing.svg\");\n  cube(1);\n}\n";
    let s = csgpix::openscad::parse_csg_with(text, "t.csg", &options).unwrap();
    let w = s.warnings[0].to_string();
    assert!(
        w.starts_with("t.csg:3:5:") && w.contains("Can't open import file"),
        "{w}"
    );
    let strict = csgpix::openscad::ReadOptions {
        strict: true,
        ..options
    };
    let e = csgpix::openscad::parse_csg_with(text, "t.csg", &strict).unwrap_err();
    assert_eq!(e.to_string(), w);
}

//! `import()` of DXF files against OpenSCAD's own geometry: each case of
//! `vectors/openscad/dxf/cases.txt` (made by its `generate.sh` with openscad 2021.01) is a
//! `linear_extrude` of a hand-written DXF drawing (closed and open LWPOLYLINEs, bulges
//! ignored; POLYLINE/VERTEX/SEQEND and SPLINE, which draw nothing; loose LINEs joined into
//! loops; ARCs and CIRCLEs at the default resolution, `$fn` and `$fa`/`$fs`; holes by the
//! even-odd rule; whole and half ELLIPSEs; two layers and `layer`; `origin` and `scale`; a
//! block inserted moved, scaled and turned), read from OpenSCAD's CSG export by csgpix (module
//! `dxf` of crates/openscad) and voxelized at 64³, against OpenSCAD's CGAL mesh of the same
//! export (`NAME.off`) voxelized on the same grid. The IoU must reach 0.999 on the float
//! route and 0.99 on the word route;
//! `cargo test --release --test openscad_dxf -- --nocapture` prints them.

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/dxf")
}

#[test]
fn dxf_import_matches_openscads_mesh() {
    let compared =
        compare_cases(&dir(), Route::Array { cycle: false }).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 14);
}

/// A malformed DXF file is read as OpenSCAD 2021.01 reads it (checked with its binary: "Illegal
/// value 'x'", "Illegal ID 'X'", nothing for a file that ends after a group code, where csgpix notes that it draws nothing): warnings at
/// the import naming the file's line, the rest of the scene drawn; `--strict` refuses at the
/// first. A coordinate past csgpix's limit is still refused in one line.
#[test]
fn bad_dxf_is_a_warning_at_the_import() {
    let tmp = tempfile::tempdir().unwrap();
    let files = [
        ("bad.dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nx\n"),
        ("odd.dxf", "0\nSECTION\n2\n"),
        ("id.dxf", "0\nSECTION\n2\nENTITIES\nX\nY\n"),
        (
            "far.dxf",
            "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1e300\n20\n0\n11\n0\n21\n1\n0\nEOF\n",
        ),
    ];
    for (name, text) in files {
        std::fs::write(tmp.path().join(name), text).unwrap();
    }
    let options = csgpix::openscad::ReadOptions {
        dir: Some(tmp.path().to_path_buf()),
        ..Default::default()
    };
    let strict = csgpix::openscad::ReadOptions {
        strict: true,
        ..options.clone()
    };
    let scene = |file: &str| {
        format!("union() {{\n  linear_extrude(1)\n    import(file = \"{file}\");\n  cube(1);\n}}\n")
    };
    for (file, why) in [
        (
            "bad.dxf",
            Some("bad.dxf:8: Illegal value \"x\" for group code 10"),
        ),
        ("odd.dxf", None),
        ("id.dxf", Some("id.dxf:5: Illegal ID \"X\"")),
    ] {
        let s = csgpix::openscad::parse_csg_with(&scene(file), "t.csg", &options)
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(s.solids.len(), 1, "{file}: the cube drawn");
        let Some(why) = why else {
            // Only csgpix's note that the import draws nothing (OpenSCAD prints nothing).
            let draws_nothing = |w: &csgpix::scene::Error| w.to_string().contains("draws nothing");
            assert!(s.warnings.iter().all(draws_nothing), "{:?}", s.warnings);
            continue;
        };
        let w = s.warnings[0].to_string();
        assert!(w.starts_with("t.csg:3:5:") && w.contains(why), "{w}");
        let e = csgpix::openscad::parse_csg_with(&scene(file), "t.csg", &strict)
            .err()
            .unwrap_or_else(|| panic!("{file} accepted under strict"))
            .to_string();
        assert!(e.starts_with("t.csg:3:5:") && e.contains(why), "{e}");
    }
    let e = csgpix::openscad::parse_csg_with(&scene("far.dxf"), "t.csg", &options)
        .expect_err("a coordinate past the limit")
        .to_string();
    assert!(
        e.starts_with("t.csg:3:5:") && e.contains("coordinate limit"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1, "{e}");
    // A missing file imports nothing, with OpenSCAD's warning ("Can't open import file").
    let text = "union() {\n  linear_extrude(1)\n    import(file = \"missing.dxf\");\n}\n";
    let s = csgpix::openscad::parse_csg_with(text, "t.csg", &options).unwrap();
    let w = s.warnings[0].to_string();
    assert!(
        w.starts_with("t.csg:3:5:") && w.contains("Can't open import file"),
        "{w}"
    );
}

/// OpenSCAD's warnings on a DXF file (an unsupported entity) are the scene's, at the import.
#[test]
fn unsupported_entities_are_warnings_at_the_import() {
    let text = "linear_extrude(1)\n  import(file = \"polyline.dxf\");\n";
    let options = csgpix::openscad::ReadOptions {
        dir: Some(dir()),
        ..Default::default()
    };
    let scene = csgpix::openscad::parse_csg_with(text, "t.csg", &options).unwrap();
    let warnings: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
    for entity in ["POLYLINE", "VERTEX", "SEQEND", "SPLINE"] {
        let found = warnings
            .iter()
            .any(|w| w.starts_with("t.csg:2:3:") && w.contains(&format!("'{entity}'")));
        assert!(found, "{entity}: {warnings:?}");
    }
}

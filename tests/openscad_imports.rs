//! `import()` of OFF, AMF and 3MF meshes against OpenSCAD's own geometry: each case of
//! `vectors/openscad/imports/cases.txt` (made by its `generate.sh` with openscad 2021.01 and
//! lib3mf 1.8.1, on the meshes `make_inputs.py` wrote) imports one file: a cube and a
//! non-convex L-shaped prism in each format, OFF with polygons (the L's caps are hexagons whose
//! fan from the first vertex crosses the notch) and a `COFF` header, AMF with two overlapping
//! objects (OpenSCAD unites them), with two volumes sharing a face and zipped, 3MF with the
//! model part elsewhere than `3D/3dmodel.model`, in inches, and with two mesh objects, build
//! items under transforms and a component (OpenSCAD 2021.01 takes each mesh object once, as
//! defined, and unites them), also under a transform of the scene; and five operations that
//! take an imported mesh's geometry while the scene is read (so csgpix reads the file then):
//! `projection()`'s shadow (0.93 while the L's hexagons were fanned: a fan triangle lay in the
//! notch) and section, `hull`, `resize` and `minkowski`. csgpix reads OpenSCAD's
//! CSG export of the statement and voxelizes it at 64³, against OpenSCAD's mesh of the same
//! export (`NAME.off`) voxelized on the same grid. The IoU must reach 0.999 on the float route
//! and 0.99 on the word route; `cargo test --release --test openscad_imports -- --nocapture`
//! prints them.

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/imports")
}

#[test]
fn mesh_imports_match_openscads_mesh() {
    let compared =
        compare_cases(&dir(), Route::Array { cycle: false }).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 17);
}

/// The warnings of OpenSCAD's omissions reach the scene, each one located line.
#[test]
fn left_out_parts_of_a_file_are_warnings() {
    let loaded = csgpix::voxel::sampled::load_scene(&dir().join("two-items-3mf.csg")).unwrap();
    let w: Vec<String> = loaded
        .scene
        .warnings
        .iter()
        .map(|w| w.to_string())
        .collect();
    assert_eq!(w.len(), 2, "{w:#?}");
    assert!(w[0].contains("two-items.3mf[3D/3dmodel.model]:"), "{w:#?}");
    assert!(w[0].contains("components are not applied"), "{w:#?}");
    assert!(w[1].contains("transform is not applied"), "{w:#?}");
    let loaded = csgpix::voxel::sampled::load_scene(&dir().join("lshape-amf.csg")).unwrap();
    let w: Vec<String> = loaded
        .scene
        .warnings
        .iter()
        .map(|w| w.to_string())
        .collect();
    assert_eq!(w.len(), 1, "{w:#?}");
    assert!(
        w[0].contains("lshape.amf:2:1: unit \"inch\" is ignored"),
        "{w:#?}"
    );
    assert!(w.iter().all(|w| w.lines().count() == 1));
}

/// A bad mesh file is one line naming the file and the place in it.
#[test]
fn bad_mesh_files_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let cases: [(&str, &[u8], &str); 3] = [
        ("bad.off", b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "bad.off:6:7: facet 0 refers to vertex 3"),
        ("bad.amf", b"<amf><object><mesh><vertices>\n<vertex><coordinates><x>1</x></coordinates></vertex></vertices></mesh></object></amf>", "bad.amf:2:9: a vertex's <coordinates> has no <y>"),
        ("bad.3mf", b"PK\x03\x04 truncated", "bad.3mf: not a readable zip archive"),
    ];
    for (name, bytes, want) in cases {
        std::fs::write(tmp.path().join(name), bytes).unwrap();
        std::fs::write(
            tmp.path().join("t.csg"),
            format!("import(file = \"{name}\");\n"),
        )
        .unwrap();
        let e = match csgpix::voxel::sampled::load_scene(&tmp.path().join("t.csg")) {
            Ok(_) => panic!("{name} accepted"),
            Err(e) => e.to_string(),
        };
        assert!(e.contains(want), "{name}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}

//! `projection()` and `resize()` against OpenSCAD's own geometry: each case of
//! `vectors/openscad/projection/cases.txt` (made by its `generate.sh` with openscad 2021.01)
//! is read from OpenSCAD's CSG export by csgpix and voxelized, and OpenSCAD's CGAL mesh of
//! the same export (`NAME.off`) is voxelized on the same 64³ grid as a closed-mesh
//! primitive. The IoU must reach 0.999 on the float route and 0.99 on the default word route
//! (`cargo test --release --test openscad_projection -- --nocapture` prints them).
//!
//! A case whose solid needs the mesh boolean (the shadow or bounding box of a difference) is
//! reported and skipped while `csgpix_openscad::geom::mesh_of` is the stub without it.

mod common;

use common::compare_with_off;

use std::path::{Path, PathBuf};

use common::csgpix;
use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/projection")
}

#[test]
fn projection_and_resize_match_openscads_mesh() {
    let cases = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    let mut failures = vec![];
    let mut compared = 0;
    for line in cases.lines().filter(|l| !l.starts_with('#')) {
        let name = line.split('\t').next().unwrap();
        match compare_with_off(&dir(), name, Route::Array { cycle: false }) {
            Ok((float, word)) => {
                compared += 1;
                println!("{name}: IoU float {float:.5}, word {word:.5}");
                if float < 0.999 || word < 0.99 {
                    failures.push(format!("{name}: float {float:.5}, word {word:.5}"));
                }
            }
            Err(e) if e.contains("needs the mesh boolean") => {
                println!("{name}: skipped: {e}");
            }
            Err(e) => failures.push(format!("{name}: refused: {e}")),
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(compared >= 6, "only {compared} cases compared");
}

#[test]
fn the_binary_reads_a_projection() {
    let path = dir().join("shadow-cube-cylinder.csg");
    let out = tempfile::tempdir().unwrap();
    let o = csgpix(&[
        "voxelize",
        path.to_str().unwrap(),
        "--res",
        "16",
        "-o",
        out.path().join("v.nrrd").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

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

use common::compare_cases;

use std::path::{Path, PathBuf};

use common::csgpix;
use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/projection")
}

#[test]
fn projection_and_resize_match_openscads_mesh() {
    let compared =
        compare_cases(&dir(), Route::Array { cycle: false }).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 8);
}

#[test]
fn the_binary_reads_a_projection() {
    let path = dir().join("shadow-cube-cylinder.csg");
    let out = tempfile::tempdir().unwrap();
    let o = csgpix(&[
        "voxelize",
        path.to_str().unwrap(),
        "--res",
        "16x16x16",
        "-o",
        out.path().join("v.nrrd").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

//! `linear_extrude` of outlines csgpix once got wrong, against OpenSCAD's own geometry: each
//! case of `vectors/openscad/extrude/cases.txt` (made by its `generate.sh` with openscad
//! 2021.01) is read from OpenSCAD's CSG export by csgpix and voxelized at 64³, and OpenSCAD's
//! CGAL mesh of the same export (`NAME.off`) is voxelized on the same grid as a closed-mesh
//! primitive. The IoU must reach 0.999 on the float route and 0.99 on the word route
//! (intervals); `cargo test --release --test openscad_extrude -- --nocapture` prints them.
//!
//! The cases: a spike (an outline running out and straight back, whose cap earcut left
//! short) and two triangles meeting at a corner under a twist (one taken for a hole of
//! nothing), both refused before as "mesh is not closed"; a twisted fan of 40 triangles from
//! the origin (MCAD `trochoids.scad`'s `hypotrochoidLinear`, whose 2D union came out in
//! pieces: IoU 0.85), and a twisted square beside the origin (wall quads split along the
//! wrong diagonal: IoU 0.977). docs/volume-scenes.md has the causes.

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/extrude")
}

#[test]
fn extrusions_match_openscads_mesh() {
    let compared = compare_cases(&dir(), Route::Intervals).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 4);
}

//! `offset()` of any 2D region against OpenSCAD's own geometry: each case of
//! `vectors/openscad/offset/cases.txt` (made by its `generate.sh` with openscad 2021.01) is a
//! `linear_extrude` of an offset of a concave polygon, a difference, a union offset inward,
//! text, or a polygon under a scale (the distance is in the offset's own coordinates), read
//! from OpenSCAD's CSG export by csgpix (which offsets it as OpenSCAD's Clipper
//! does) and voxelized at 64³, and OpenSCAD's CGAL mesh of the same export (`NAME.off`) is
//! voxelized on the same grid as a closed-mesh primitive. The IoU must reach 0.999 on the
//! float route and 0.99 on the word route (intervals); `cargo test --release --test
//! openscad_offset -- --nocapture` prints them (docs/volume-scenes.md).

mod common;

use common::compare_cases;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/offset")
}

#[test]
fn offset_matches_openscads_mesh() {
    let compared = compare_cases(&dir(), Route::Intervals).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(compared, 9);
}

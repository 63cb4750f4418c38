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

use common::compare_with_off;

use std::path::{Path, PathBuf};

use csgpix::voxel::Route;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/offset")
}

#[test]
fn offset_matches_openscads_mesh() {
    let cases = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    let mut failures = vec![];
    let mut compared = 0;
    for line in cases.lines().filter(|l| !l.starts_with('#')) {
        let name = line.split('\t').next().unwrap();
        match compare_with_off(&dir(), name, Route::Intervals) {
            Ok((float, word)) => {
                compared += 1;
                println!("{name:16} IoU float {float:.5}, word (intervals) {word:.5}");
                if float < 0.999 || word < 0.99 {
                    failures.push(format!("{name}: float {float:.5}, word {word:.5}"));
                }
            }
            Err(e) => failures.push(format!("{name}: refused: {e}")),
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert_eq!(compared, 9);
}

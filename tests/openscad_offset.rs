//! `offset()` of any 2D region against OpenSCAD's own geometry: each case of
//! `vectors/openscad/offset/cases.txt` (made by its `generate.sh` with openscad 2021.01) is a
//! `linear_extrude` of an offset of a concave polygon, a difference, a union offset inward or
//! text, read from OpenSCAD's CSG export by csgpix (which offsets it as OpenSCAD's Clipper
//! does) and voxelized at 64³, and OpenSCAD's CGAL mesh of the same export (`NAME.off`) is
//! voxelized on the same grid as a closed-mesh primitive. The IoU must reach 0.999 on the
//! float route and 0.99 on the word route (intervals); `cargo test --release --test
//! openscad_offset -- --nocapture` prints them (docs/volume-scenes.md).

mod common;

use common::{iou, read_off, scene_occupancy};

use std::path::{Path, PathBuf};
use std::sync::Arc;

use csgpix::scad::parse_csg;
use csgpix::solid::{CsgNode, CsgScene, Import};
use csgpix::voxel::{Grid, Route};
use glam::DVec3;

const N: usize = 64;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openscad/offset")
}

/// (float IoU, word IoU) of csgpix's reading of `NAME.csg` against `NAME.off`; Err with
/// csgpix's message when it refuses the file.
fn compare(name: &str) -> Result<(f64, f64), String> {
    let text = std::fs::read_to_string(dir().join(format!("{name}.csg"))).unwrap();
    let ours = parse_csg(&text, &format!("{name}.csg")).map_err(|e| e.to_string())?;
    let tris = read_off(&dir().join(format!("{name}.off")));
    let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for p in tris.iter().flatten() {
        lo = lo.min(DVec3::from(*p));
        hi = hi.max(DVec3::from(*p));
    }
    // A margin of about two voxels round OpenSCAD's box, an odd fraction of the size so that
    // no voxel centre falls on the cases' round coordinates (a centre on a face is a tie the
    // two sides may break differently).
    let pad = (hi - lo) * 0.0371;
    let grid = Grid::new([N; 3], lo - pad, hi + pad).unwrap();
    let theirs = CsgScene {
        solids: vec![],
        imports: vec![Import {
            file: format!("{name}.off"),
            threshold: None,
            matrix: None,
            colour: None,
            line: 1,
            col: 1,
            mesh: Some(Arc::new(tris)),
        }],
        root: CsgNode::Solid(0),
        warnings: vec![],
    };
    let b = scene_occupancy(&theirs, &dir(), &grid, Route::Float).unwrap();
    let a = scene_occupancy(&ours, &dir(), &grid, Route::Float).unwrap();
    let float = iou(&a, &b);
    let word = iou(
        &scene_occupancy(&ours, &dir(), &grid, Route::Intervals).unwrap(),
        &b,
    );
    Ok((float, word))
}

#[test]
fn offset_matches_openscads_mesh() {
    let cases = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    let mut failures = vec![];
    let mut compared = 0;
    for line in cases.lines().filter(|l| !l.starts_with('#')) {
        let name = line.split('\t').next().unwrap();
        match compare(name) {
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
    assert_eq!(compared, 8);
}

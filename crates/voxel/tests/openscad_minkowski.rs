//! `minkowski()` and `hull()` of differences against OpenSCAD's own results, and against the
//! definitions.
//!
//! Each case of `vectors/openscad/minkowski/` (made by its `generate.sh` with openscad
//! 2021.01) is a CSG export (`NAME.csg`) and OpenSCAD's CGAL mesh of it (`NAME.stl`). csgpix
//! reads the `.csg` and voxelizes it at 64³, and the mesh is voxelized on the same grid as a
//! closed-mesh primitive: IoU ≥ 0.999 on the float route, ≥ 0.99 on the default word route
//! (intervals). `cargo test --release -p csgpix-voxel --test openscad_minkowski -- --nocapture` prints the
//! IoUs (docs/volume-scenes.md).
//!
//! The properties: minkowski of random convex polytopes is, voxel for voxel, the hull of the
//! pairwise sums; a random difference of two boxes ⊕ a random box is, voxel for voxel, the set
//! of centres p for which the box p − C meets X (decided exactly, box against boxes).

use csgpix_testkit::iou;

use std::path::{Path, PathBuf};

use csgpix_openscad::parse_csg;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::sampled::load_imports;
use csgpix_voxel::{voxelize, Grid, Route, Slicer, SlicerOptions};
use glam::DVec3;
use proptest::prelude::*;
use rtl_model::Equations;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn dir() -> PathBuf {
    Path::new(ROOT).join("vectors/openscad/minkowski")
}

fn voxels(text: &str, base: &Path, grid: &Grid, route: Route) -> Vec<bool> {
    let scene = parse_csg(text, "t.csg").unwrap_or_else(|e| panic!("{e}"));
    let sampled = load_imports(&scene, "t.csg", base).unwrap_or_else(|e| panic!("{e}"));
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&scene, *grid, opts).unwrap();
    let eval = BlistEval::new(&scene.root);
    let (v, _) = voxelize(&slicer, route, Equations::Derived.set(), &eval, &|| {}).unwrap();
    v.voxels.iter().map(|&c| c != 0).collect()
}

/// The bounds of an ASCII STL's vertices.
fn stl_bounds(text: &str) -> (DVec3, DVec3) {
    let mut lo = DVec3::INFINITY;
    let mut hi = DVec3::NEG_INFINITY;
    for line in text.lines() {
        let mut w = line.split_whitespace();
        if w.next() == Some("vertex") {
            let c: Vec<f64> = w.map(|s| s.parse().unwrap()).collect();
            let p = DVec3::new(c[0], c[1], c[2]);
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    (lo, hi)
}

#[test]
fn minkowski_and_hull_agree_with_openscad() {
    let cases = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    let mut n = 0;
    for line in cases.lines().filter(|l| !l.starts_with('#')) {
        let name = line.split('\t').next().unwrap();
        let csg = std::fs::read_to_string(dir().join(format!("{name}.csg"))).unwrap();
        let stl = std::fs::read_to_string(dir().join(format!("{name}.stl"))).unwrap();
        let (lo, hi) = stl_bounds(&stl);
        let pad = (hi - lo) * 0.05;
        let grid = Grid::new([64; 3], lo - pad, hi + pad).unwrap();
        let reference = format!("import(file = \"{name}.stl\");");
        let scene = parse_csg(&csg, "t.csg").unwrap();
        let mut ious = vec![];
        for (route, need) in [(Route::Float, 0.999), (Route::Intervals, 0.99)] {
            let a = voxels(&csg, &dir(), &grid, route);
            let b = voxels(&reference, &dir(), &grid, route);
            let v = iou(&a, &b);
            assert!(v >= need, "{name} {route:?}: IoU {v:.5} < {need}");
            ious.push(v);
        }
        println!(
            "{name:32} float IoU {:.5}  word (intervals) IoU {:.5}  ({} convex solids, {} meshes)",
            ious[0],
            ious[1],
            scene.solids.len(),
            scene.imports.len()
        );
        n += 1;
    }
    assert_eq!(n, 10);
}

/// A box's corners, `lo` and `hi` given.
fn corners(lo: [f64; 3], hi: [f64; 3]) -> Vec<DVec3> {
    (0..8)
        .map(|i| {
            DVec3::new(
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            )
        })
        .collect()
}

/// `cube` from `lo` to `hi`, placed by `m` (row-major 3×4).
fn cube_text(lo: [f64; 3], hi: [f64; 3], m: [[f64; 4]; 3]) -> String {
    let s = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    // Rotate about the origin after moving lo there: m · (lo + x).
    let t = [
        m[0][0] * lo[0] + m[0][1] * lo[1] + m[0][2] * lo[2] + m[0][3],
        m[1][0] * lo[0] + m[1][1] * lo[1] + m[1][2] * lo[2] + m[1][3],
        m[2][0] * lo[0] + m[2][1] * lo[1] + m[2][2] * lo[2] + m[2][3],
    ];
    format!(
        "multmatrix([[{}, {}, {}, {}], [{}, {}, {}, {}], [{}, {}, {}, {}], [0, 0, 0, 1]]) cube(size = [{}, {}, {}]);",
        m[0][0], m[0][1], m[0][2], t[0], m[1][0], m[1][1], m[1][2], t[1], m[2][0], m[2][1],
        m[2][2], t[2], s[0], s[1], s[2]
    )
}

fn apply(m: [[f64; 4]; 3], p: DVec3) -> DVec3 {
    DVec3::new(
        m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
        m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
        m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3],
    )
}

fn rot_z(a: f64) -> [[f64; 4]; 3] {
    let (s, c) = a.sin_cos();
    [[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]
}

fn translate(d: DVec3) -> [[f64; 4]; 3] {
    [
        [1.0, 0.0, 0.0, d.x],
        [0.0, 1.0, 0.0, d.y],
        [0.0, 0.0, 1.0, d.z],
    ]
}

fn a_box() -> impl Strategy<Value = ([f64; 3], [f64; 3])> {
    (
        prop::array::uniform3(-2.0..1.0f64),
        prop::array::uniform3(0.3..2.0f64),
    )
        .prop_map(|(lo, s)| (lo, [lo[0] + s[0], lo[1] + s[1], lo[2] + s[2]]))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// minkowski() { hull of boxes A; hull of rotated boxes B } = hull of the pairwise sums:
    /// hull() { A's boxes translated to every corner of B's boxes }.
    #[test]
    fn minkowski_of_convex_polytopes_is_the_hull_of_sums(
        a in prop::collection::vec(a_box(), 1..3),
        b in prop::collection::vec(a_box(), 1..3),
        angle in -3.0..3.0f64,
    ) {
        let r = rot_z(angle);
        let a_text: String = a.iter().map(|&(lo, hi)| cube_text(lo, hi, translate(DVec3::ZERO))).collect();
        let b_text: String = b.iter().map(|&(lo, hi)| cube_text(lo, hi, r)).collect();
        let text = format!("minkowski() {{ hull() {{ {a_text} }} hull() {{ {b_text} }} }}");
        let mut sums = String::new();
        for &(lo, hi) in &b {
            for c in corners(lo, hi) {
                let d = apply(r, c);
                for &(lo, hi) in &a {
                    sums.push_str(&cube_text(lo, hi, translate(d)));
                }
            }
        }
        let reference = format!("hull() {{ {sums} }}");
        let grid = Grid::new([40; 3], DVec3::splat(-8.1), DVec3::splat(8.3)).unwrap();
        let x = voxels(&text, Path::new("."), &grid, Route::Float);
        let y = voxels(&reference, Path::new("."), &grid, Route::Float);
        let diff = x.iter().zip(&y).filter(|(p, q)| p != q).count();
        prop_assert_eq!(diff, 0, "{} voxels differ\n{}\n{}", diff, text, reference);
        prop_assert!(x.iter().any(|&v| v));
    }

    /// (B1 − B2) ⊕ C by the boundary formula, against the exact test "the box p − C meets
    /// B1 − B2" at every voxel centre p; C alone where B1 − B2 is empty (OpenSCAD's rule).
    #[test]
    fn minkowski_of_a_difference_and_a_box_is_exact(
        b1 in a_box(),
        b2 in a_box(),
        c in a_box(),
    ) {
        let id = translate(DVec3::ZERO);
        let text = format!(
            "minkowski() {{ difference() {{ {} {} }} {} }}",
            cube_text(b1.0, b1.1, id),
            cube_text(b2.0, b2.1, id),
            cube_text(c.0, c.1, id)
        );
        let grid = Grid::new([40; 3], DVec3::splat(-4.13), DVec3::splat(4.21)).unwrap();
        let got = voxels(&text, Path::new("."), &grid, Route::Float);
        // B1 ⊆ B2 (as the scene places them: lo + (hi − lo)) leaves B1 − B2 empty, and
        // OpenSCAD leaves an empty operand out of the sum: the result is C alone (openscad
        // 2021.01 gives C's cube for such a case).
        let placed = |b: ([f64; 3], [f64; 3]), a: usize| b.0[a] + (b.1[a] - b.0[a]);
        let b1_in_b2 = (0..3).all(|a| b1.0[a] >= b2.0[a] && placed(b1, a) <= placed(b2, a));
        let mut want = vec![false; got.len()];
        for k in 0..40 {
            for j in 0..40 {
                for i in 0..40 {
                    let p = grid.centre(i, j, k).to_array();
                    if b1_in_b2 {
                        let in_c = (0..3).all(|a| p[a] >= c.0[a] && p[a] <= placed(c, a));
                        want[(k * 40 + j) * 40 + i] = in_c;
                        continue;
                    }
                    // Q = p − C, R = Q ∩ B1; inside iff R is not empty and not inside B2.
                    let mut lo = [0.0; 3];
                    let mut hi = [0.0; 3];
                    let mut empty = false;
                    for a in 0..3 {
                        lo[a] = (p[a] - c.1[a]).max(b1.0[a]);
                        hi[a] = (p[a] - c.0[a]).min(b1.1[a]);
                        empty |= lo[a] > hi[a];
                    }
                    let within_b2 = (0..3).all(|a| lo[a] >= b2.0[a] && hi[a] <= b2.1[a]);
                    want[(k * 40 + j) * 40 + i] = !empty && !within_b2;
                }
            }
        }
        let diff = got.iter().zip(&want).filter(|(p, q)| p != q).count();
        prop_assert_eq!(diff, 0, "{} voxels differ\n{}", diff, text);
    }
}

//! Helpers shared by csgpix's test suites (a dev-dependency of the crates that test with
//! random scenes): random `.csg` scenes of the subset every reader and evaluator takes, the
//! face planes direct evaluation checks slices against, the IoU of two occupancies, and the
//! centre IoU against a reference mesh that forgives ties on its surface ([`band`]), and an
//! ASCII STL of a box, closed or open ([`box_stl`]).
//!
//! The strategies draw their values in a fixed order: the `*.proptest-regressions` files of
//! the suites that use them keep their seeds' scenes only while that order stays.

pub mod band;

use csgpix_scene::solid::ConvexSolid;
use glam::DVec3;
use proptest::prelude::*;
use std::f64::consts::PI;

/// A box, sphere, cylinder or cone of the `.csg` subset, centred, with random sizes and
/// facet counts.
pub fn shape() -> impl Strategy<Value = String> {
    prop_oneof![
        (2.0..12.0f64, 2.0..12.0f64, 2.0..12.0f64)
            .prop_map(|(a, b, c)| format!("cube(size = [{a:.3}, {b:.3}, {c:.3}], center = true);")),
        (3usize..14, 1.0..6.0f64).prop_map(|(n, r)| format!("sphere($fn = {n}, r = {r:.3});")),
        (3usize..14, 2.0..10.0f64, 0.0..5.0f64, 1.0..5.0f64).prop_map(|(n, h, r1, r2)| format!(
            "cylinder($fn = {n}, h = {h:.3}, r1 = {r1:.3}, r2 = {r2:.3}, center = true);"
        )),
    ]
}

/// A primitive of the `.csg` subset, placed by a random rotation and shift.
pub fn primitive() -> impl Strategy<Value = String> {
    (
        shape(),
        -PI..PI,
        -PI..PI,
        prop::array::uniform3(-4.0..4.0f64),
    )
        .prop_map(|(shape, a, b, t)| placed(&shape, a, b, t))
}

/// [`primitive`], unturned half the time (its faces along the axes, where voxel centres
/// meet faces most often), else turned.
pub fn primitive_or_unturned() -> impl Strategy<Value = String> {
    let turn = prop_oneof![Just((0.0, 0.0)), (-PI..PI, -PI..PI)];
    (shape(), turn, prop::array::uniform3(-4.0..4.0f64))
        .prop_map(|(shape, (a, b), t)| placed(&shape, a, b, t))
}

/// `shape` under a `multmatrix`: a rotation about z by `a`, then about x by `b`, then a shift
/// by `t`.
pub fn placed(shape: &str, a: f64, b: f64, t: [f64; 3]) -> String {
    let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cos(), b.sin());
    let m = [
        [ca, -sa, 0.0, t[0]],
        [sa * cb, ca * cb, -sb, t[1]],
        [sa * sb, ca * sb, cb, t[2]],
    ];
    let row = |r: [f64; 4]| format!("[{:.6}, {:.6}, {:.6}, {:.6}]", r[0], r[1], r[2], r[3]);
    format!(
        "multmatrix([{}, {}, {}, [0, 0, 0, 1]]) {{ {shape} }}",
        row(m[0]),
        row(m[1]),
        row(m[2])
    )
}

/// A union, difference or intersection of one to three [`primitive`]s.
pub fn random_scene() -> impl Strategy<Value = String> {
    scene_of(primitive())
}

/// A union, difference or intersection of one to three of `primitive`'s.
pub fn scene_of(primitive: impl Strategy<Value = String>) -> impl Strategy<Value = String> {
    let op = prop_oneof![Just("union"), Just("difference"), Just("intersection")];
    (op, prop::collection::vec(primitive, 1..4))
        .prop_map(|(op, kids)| format!("{op}() {{\n{}\n}}\n", kids.join("\n")))
}

/// Outward face planes (unit normal, offset) of a convex solid, by Newell's method: the
/// geometry direct evaluation checks the slices against.
pub fn face_planes(s: &ConvexSolid) -> Vec<(DVec3, f64)> {
    s.faces
        .iter()
        .map(|f| {
            let v = |i: usize| DVec3::from(s.vertices[f[i % f.len()] as usize]);
            let n: DVec3 = (0..f.len()).map(|i| v(i).cross(v(i + 1))).sum();
            let n = n.normalize();
            let c: DVec3 = (0..f.len()).map(v).sum::<DVec3>() / f.len() as f64;
            (n, n.dot(c))
        })
        .collect()
}

/// Intersection over union of two occupancies (1 when both are empty).
pub fn iou(a: &[bool], b: &[bool]) -> f64 {
    let both = a.iter().zip(b).filter(|(x, y)| **x && **y).count();
    let either = a.iter().zip(b).filter(|(x, y)| **x || **y).count();
    if either == 0 {
        1.0
    } else {
        both as f64 / either as f64
    }
}

/// An ASCII STL of the box [0, `side`]³ as 12 triangles (two a face), its top face (z = side)
/// left out when `open`.
pub fn box_stl(side: f32, open: bool) -> String {
    let c = |i: usize| [0, 1, 2].map(|a| if i >> a & 1 == 1 { side } else { 0.0 });
    let quads = [
        [0, 2, 3, 1],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
        [4, 5, 7, 6],
    ];
    let facet = |t: [[f32; 3]; 3]| {
        let v: String = t
            .iter()
            .map(|p| format!("vertex {} {} {}\n", p[0], p[1], p[2]))
            .collect();
        format!("facet normal 0 0 0\nouter loop\n{v}endloop\nendfacet\n")
    };
    let faces = if open { &quads[..5] } else { &quads[..] };
    let body: String = faces
        .iter()
        .flat_map(|q| [[c(q[0]), c(q[1]), c(q[2])], [c(q[0]), c(q[2]), c(q[3])]])
        .map(facet)
        .collect();
    format!("solid b\n{body}endsolid b\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    #[test]
    fn a_placed_shape_is_a_multmatrix_of_a_rotation() {
        let text = placed("sphere(r = 1);", PI / 2.0, 0.0, [1.0, 2.0, 3.0]);
        assert_eq!(
            text,
            "multmatrix([[0.000000, -1.000000, 0.000000, 1.000000], \
             [1.000000, 0.000000, -0.000000, 2.000000], \
             [0.000000, 0.000000, 1.000000, 3.000000], [0, 0, 0, 1]]) { sphere(r = 1); }"
        );
    }

    #[test]
    fn random_scenes_are_one_operation_over_one_to_three_primitives() {
        let mut runner = TestRunner::deterministic();
        for _ in 0..64 {
            let s = random_scene().new_tree(&mut runner).unwrap().current();
            let op = s.split('(').next().unwrap();
            assert!(["union", "difference", "intersection"].contains(&op), "{s}");
            let kids = s.matches("multmatrix").count();
            assert!((1..4).contains(&kids), "{s}");
        }
    }

    #[test]
    fn iou_counts_both_over_either() {
        let (a, b) = ([true, true, false, false], [true, false, true, false]);
        assert_eq!(iou(&a, &b), 1.0 / 3.0);
        assert_eq!(iou(&[false; 3], &[false; 3]), 1.0);
    }

    #[test]
    fn a_box_has_six_outward_planes_through_its_faces() {
        // [-1, 1] × [-1, 2] × [-1, 3]; corner i at x bit 0, y bit 1, z bit 2.
        let hi = [1.0, 2.0, 3.0];
        let vertices = (0..8)
            .map(|i| [0, 1, 2].map(|a| if i >> a & 1 == 1 { hi[a] } else { -1.0 }))
            .collect();
        let faces = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let solid = ConvexSolid {
            vertices,
            faces: faces.iter().map(|f| f.to_vec()).collect(),
            colour: None,
            line: 1,
        };
        let planes = face_planes(&solid);
        let mut axes = vec![];
        for (n, d) in planes {
            let axis = (0..3).find(|&a| n[a].abs() == 1.0).expect("along an axis");
            // Outward: +1 at the high face (offset hi), −1 at the low one (offset 1).
            let want = if n[axis] > 0.0 { hi[axis] } else { 1.0 };
            assert_eq!(d, want, "{n} {d}");
            axes.push((axis, n[axis] > 0.0));
        }
        axes.sort();
        let every: Vec<_> = (0..3).flat_map(|a| [(a, false), (a, true)]).collect();
        assert_eq!(axes, every);
    }
}

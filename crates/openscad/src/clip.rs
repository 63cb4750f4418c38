//! An intersection of convex solids as one convex polytope, by clipping: the solid of most
//! faces is cut by every face plane of the others, one plane at a time, keeping its faces
//! (each cut face shortened, the cut closed by one new face). The intersection of convex
//! sets is convex, so no mesh boolean is needed where `minkowski()` or `hull()` takes such an
//! intersection whole: the boolean built two meshes' half-edge structures and colliders
//! for a result the planes give directly (grinder-glass-holder's cube ∩ a 3,900-vertex
//! sum, docs/voxelize-bench.md).
//!
//! The polytope returned is the hull of the clipped corners ([`hull3`]), as the mesh path
//! takes the hull of the boolean's corners ([`crate::geom::convex_hull_of`]): the same faces
//! up to the rounding of the new corners.

use std::collections::HashMap;

use glam::DVec3;

use crate::geom::{face_plane, Polytope};
use csgpix_scene::solid::{ConvexSolid, CsgNode, IMPORTED};

/// Relative distance (to the clipped solid's extent) within which a corner lies on a plane.
const ON_PLANE: f64 = 1e-12;

/// Most corner-plane tests one intersection may take; past them the mesh boolean is used.
const CLIP_TESTS: usize = 1 << 26;

/// What [`convex_intersection`] found.
#[derive(Debug)]
pub(crate) enum Clipped {
    /// Not an intersection of convex solids (or too large to clip): take its mesh.
    NotConvex,
    /// An intersection of nothing: the solids are apart, or meet only where a face plane of
    /// one has every corner left of the other on it or beyond.
    Empty,
    /// The intersection, a convex polytope.
    Convex(Polytope),
}

/// `node` as one convex polytope when it is an intersection (through nested intersections) of
/// convex solids.
pub(crate) fn convex_intersection(node: &CsgNode, solids: &[ConvexSolid]) -> Clipped {
    if !matches!(node, CsgNode::Intersection(_)) {
        return Clipped::NotConvex;
    }
    let mut leaves: Vec<&ConvexSolid> = vec![];
    let mut stack = vec![node];
    while let Some(n) = stack.pop() {
        match n {
            CsgNode::Intersection(c) => stack.extend(c.iter()),
            CsgNode::Empty => return Clipped::Empty,
            CsgNode::Solid(i) if *i < IMPORTED => match solids.get(*i) {
                Some(s) => leaves.push(s),
                None => return Clipped::NotConvex,
            },
            _ => return Clipped::NotConvex,
        }
    }
    let Some(big) = (0..leaves.len()).max_by_key(|&i| leaves[i].faces.len()) else {
        return Clipped::NotConvex;
    };
    let mut p = Polytope::of_solid(leaves[big]);
    let planes: Vec<(DVec3, f64)> = (leaves.iter().enumerate())
        .filter(|&(i, _)| i != big)
        .flat_map(|(_, s)| {
            let q = Polytope::of_solid(s);
            q.faces
                .iter()
                .map(|f| face_plane(&q.v, f))
                .collect::<Vec<_>>()
        })
        .collect();
    if planes.len().saturating_mul(p.v.len()) > CLIP_TESTS {
        return Clipped::NotConvex;
    }
    let eps = ON_PLANE * extent(&p.v);
    for (n, d) in planes {
        match p.clipped(n, d, eps) {
            Some(q) => p = q,
            None => return Clipped::Empty,
        }
    }
    // Corners left that span no volume (a sliver thinner than the hull's tolerance) go the
    // mesh path, as they went before: their sum with a solid has volume.
    match Polytope::hull(&p.v) {
        Ok(p) => Clipped::Convex(p),
        Err(_) => Clipped::NotConvex,
    }
}

/// The largest side of the points' bounding box.
fn extent(v: &[DVec3]) -> f64 {
    let (lo, hi) = v
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
            (a.min(p), b.max(p))
        });
    (hi - lo).max_element().max(0.0)
}

impl Polytope {
    /// The part on the inner side of plane n·x = d (n·x ≤ d), corners within `eps` of the
    /// plane counted on it; None when nothing of volume is left (every corner on or beyond
    /// the plane). Each face keeps its corners inside and gains the points where its edges
    /// cross; the points on the plane, in order around their centroid, close the cut.
    pub(crate) fn clipped(&self, n: DVec3, d: f64, eps: f64) -> Option<Polytope> {
        let dist: Vec<f64> = self.v.iter().map(|&v| n.dot(v) - d).collect();
        if dist.iter().all(|&s| s <= eps) {
            return Some(self.clone());
        }
        if dist.iter().all(|&s| s >= -eps) {
            return None;
        }
        let mut v: Vec<DVec3> = vec![];
        let kept: Vec<Option<usize>> = (self.v.iter().zip(&dist))
            .map(|(&p, &s)| {
                (s <= eps).then(|| {
                    v.push(p);
                    v.len() - 1
                })
            })
            .collect();
        let mut cap: Vec<usize> = (0..self.v.len())
            .filter(|&i| dist[i].abs() <= eps)
            .filter_map(|i| kept[i])
            .collect();
        let mut crossing: HashMap<(usize, usize), usize> = HashMap::new();
        let mut faces = Vec::with_capacity(self.faces.len() + 1);
        for f in &self.faces {
            let mut g = Vec::with_capacity(f.len() + 1);
            for (k, &a) in f.iter().enumerate() {
                let b = f[(k + 1) % f.len()];
                g.extend(kept[a]);
                let (da, db) = (dist[a], dist[b]);
                if (da < -eps && db > eps) || (da > eps && db < -eps) {
                    let key = (a.min(b), a.max(b));
                    let at = *crossing.entry(key).or_insert_with(|| {
                        let (p, q) = (self.v[key.0], self.v[key.1]);
                        let (dp, dq) = (dist[key.0], dist[key.1]);
                        v.push(p + (q - p) * (dp / (dp - dq)));
                        cap.push(v.len() - 1);
                        v.len() - 1
                    });
                    g.push(at);
                }
            }
            if g.len() >= 3 {
                faces.push(g);
            }
        }
        if cap.len() >= 3 {
            faces.push(around(&v, cap, n));
        }
        Some(Polytope { v, faces })
    }
}

/// Points `on` (indices into `v`, all on a plane of normal `n`, in convex position) in
/// counter-clockwise order seen from the side `n` points to.
fn around(v: &[DVec3], mut on: Vec<usize>, n: DVec3) -> Vec<usize> {
    let c = on.iter().map(|&i| v[i]).sum::<DVec3>() / on.len() as f64;
    let u = n.any_orthonormal_vector();
    let w = n.cross(u);
    let angle = |i: usize| {
        let r = v[i] - c;
        r.dot(w).atan2(r.dot(u))
    };
    on.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
    on
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::mesh_of;
    use proptest::prelude::*;

    fn volume(p: &Polytope) -> f64 {
        let c = p.v[0];
        let tri = |f: &Vec<usize>| {
            (1..f.len() - 1)
                .map(|i| (p.v[f[i]] - c).dot((p.v[f[i + 1]] - c).cross(p.v[f[0]] - c)))
                .sum::<f64>()
        };
        p.faces.iter().map(tri).sum::<f64>() / 6.0
    }

    fn mesh_volume(m: &[[DVec3; 3]]) -> f64 {
        m.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0
    }

    /// The clipped polytope against the mesh boolean of the same intersection: the same
    /// volume, every corner of each within the other's planes.
    fn agrees_with_the_boolean(src: &str) -> Result<(), TestCaseError> {
        let s = crate::parse_csg(src, "t.csg").unwrap();
        let mesh = mesh_of(&s.root, &s.solids, &[]).unwrap();
        match convex_intersection(&s.root, &s.solids) {
            Clipped::Convex(p) => {
                let (a, b) = (volume(&p), mesh_volume(&mesh));
                prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "{a} against {b}");
                let planes: Vec<_> = p.faces.iter().map(|f| face_plane(&p.v, f)).collect();
                let eps = 1e-9 * extent(&p.v);
                for q in mesh.iter().flatten() {
                    let out = planes
                        .iter()
                        .map(|(n, d)| n.dot(*q) - d)
                        .fold(f64::MIN, f64::max);
                    prop_assert!(out <= eps, "a corner of the boolean {out} outside");
                }
            }
            Clipped::Empty => prop_assert!(mesh_volume(&mesh) < 1e-9, "{}", mesh_volume(&mesh)),
            Clipped::NotConvex => prop_assert!(false, "not taken as convex: {src}"),
        }
        Ok(())
    }

    #[test]
    fn a_cube_cut_by_a_slab_is_the_box_between() {
        let s = crate::parse_csg(
            "intersection() { cube(size = [2, 2, 2]); \
             multmatrix([[1,0,0,0.5],[0,1,0,-1],[0,0,1,-1],[0,0,0,1]]) cube(size = [1, 4, 4]); }",
            "t.csg",
        )
        .unwrap();
        let Clipped::Convex(p) = convex_intersection(&s.root, &s.solids) else {
            panic!("not convex");
        };
        assert_eq!(p.v.len(), 8);
        assert_eq!(p.faces.len(), 6);
        assert!((volume(&p) - 4.0).abs() < 1e-12, "{}", volume(&p));
        let lo = p.v.iter().fold(DVec3::INFINITY, |a, &b| a.min(b));
        let hi = p.v.iter().fold(DVec3::NEG_INFINITY, |a, &b| a.max(b));
        assert_eq!(
            (lo, hi),
            (DVec3::new(0.5, 0.0, 0.0), DVec3::new(1.5, 2.0, 2.0))
        );
    }

    #[test]
    fn disjoint_or_touching_solids_meet_in_nothing_and_a_difference_is_not_convex() {
        let apart = "intersection() { cube(size = 1); \
             multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) sphere(r = 1); }";
        let touching = "intersection() { cube(size = 1); \
             multmatrix([[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(size = 1); }";
        for src in [apart, touching] {
            let s = crate::parse_csg(src, "t.csg").unwrap();
            assert!(
                matches!(convex_intersection(&s.root, &s.solids), Clipped::Empty),
                "{src}"
            );
        }
        let s =
            crate::parse_csg("difference() { cube(size = 2); sphere(r = 1); }", "t.csg").unwrap();
        assert!(matches!(
            convex_intersection(&s.root, &s.solids),
            Clipped::NotConvex
        ));
        let s = crate::parse_csg("sphere(r = 1);", "t.csg").unwrap();
        assert!(matches!(
            convex_intersection(&s.root, &s.solids),
            Clipped::NotConvex
        ));
    }

    #[test]
    fn a_cube_and_a_many_sided_sum_agree_with_the_boolean() {
        agrees_with_the_boolean(
            "intersection() { multmatrix([[1,0,0,0],[0,1,0,-30.5],[0,0,1,0],[0,0,0,1]]) \
             cube(size = [61, 61, 7], center = true); \
             minkowski() { cylinder($fn = 150, h = 3, r1 = 42.5, r2 = 42.5, center = true); \
             sphere($fn = 50, r = 3); } }",
        )
        .unwrap();
    }

    fn solid() -> impl Strategy<Value = String> {
        let shape = prop_oneof![
            (1.0..4.0f64, 1.0..4.0f64, 1.0..4.0f64)
                .prop_map(|(a, b, c)| format!("cube(size = [{a}, {b}, {c}], center = true);")),
            (0.5..3.0f64, 5..24u32).prop_map(|(r, n)| format!("sphere(r = {r}, $fn = {n});")),
            (0.5..3.0f64, 0.0..3.0f64, 1.0..4.0f64, 3..24u32).prop_map(|(r1, r2, h, n)| {
                format!("cylinder(r1 = {r1}, r2 = {r2}, h = {h}, center = true, $fn = {n});")
            }),
        ];
        (shape, -1.5..1.5f64, -1.5..1.5f64, -1.5..1.5f64, 0.0..6.3f64, 0.0..6.3f64).prop_map(
            |(s, x, y, z, a, b)| {
                let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cos(), b.sin());
                // A turn about z by a, then about x by b.
                format!(
                    "multmatrix([[{ca},{m},0,{x}],[{p},{q},{r},{y}],[{t},{u},{cb},{z}],[0,0,0,1]]) {s}",
                    m = -sa,
                    p = cb * sa,
                    q = cb * ca,
                    r = -sb,
                    t = sb * sa,
                    u = sb * ca,
                )
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn clipped_intersections_agree_with_the_boolean(
            solids in proptest::collection::vec(solid(), 2..4),
        ) {
            agrees_with_the_boolean(&format!("intersection() {{ {} }}", solids.join(" ")))?;
        }
    }
}

//! A planar polygon face (an OFF facet, a `polyhedron()` face) as triangles that cover exactly
//! the polygon, as OpenSCAD 2021.01 tessellates faces (`GeometryUtils::tessellatePolygon`).
//!
//! A fan from the first corner covers a concave polygon an odd number of times exactly inside
//! it, which is all the parity rule of [`crate::trimesh::TriMesh::crossings`] needs, but its
//! triangles also reach outside the polygon (cancelled there only by their orientation). A
//! shadow or section of the mesh (`projection()`), which unions triangles, would take those
//! too; so a concave face is ear-clipped in its plane instead. A convex face keeps its fan
//! (the triangles csgpix always made of it).

use glam::{DVec2, DVec3};

/// The triangles of the polygon `corners` (in order round the face), as indices into it, each
/// wound as the polygon runs. A convex polygon is fanned from its first corner; a concave one
/// is ear-clipped in the plane of its Newell normal. Where ear clipping does not cover the
/// polygon with `n - 2` triangles (a polygon that crosses itself, or with no area), the fan.
pub fn triangulate(corners: &[DVec3]) -> Vec<[usize; 3]> {
    let n = corners.len();
    let fan = || (1..n.saturating_sub(1)).map(|i| [0, i, i + 1]).collect();
    if n <= 3 {
        return fan();
    }
    let normal = newell(corners);
    if normal == DVec3::ZERO || is_convex(corners, normal) {
        return fan();
    }
    ear_clipped(corners, normal).unwrap_or_else(fan)
}

/// The polygon's Newell normal: twice its vector area.
fn newell(corners: &[DVec3]) -> DVec3 {
    let n = corners.len();
    (0..n).map(|i| corners[i].cross(corners[(i + 1) % n])).sum()
}

/// Every corner turns the same way about `normal` (none backwards).
fn is_convex(corners: &[DVec3], normal: DVec3) -> bool {
    let n = corners.len();
    (0..n).all(|i| {
        let (a, b, c) = (corners[i], corners[(i + 1) % n], corners[(i + 2) % n]);
        (b - a).cross(c - b).dot(normal) >= 0.0
    })
}

/// `corners` ear-clipped in the plane across `normal` (dropping its largest component), each
/// triangle wound as the polygon; None unless that gives `n - 2` triangles.
fn ear_clipped(corners: &[DVec3], normal: DVec3) -> Option<Vec<[usize; 3]>> {
    let a = normal.abs();
    let drop = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    let flat = |p: DVec3| match drop {
        0 => DVec2::new(p.y, p.z),
        1 => DVec2::new(p.z, p.x),
        _ => DVec2::new(p.x, p.y),
    };
    let pts: Vec<DVec2> = corners.iter().map(|&p| flat(p)).collect();
    let mut idx: Vec<usize> = vec![];
    earcut::Earcut::new().earcut(pts.iter().map(|p| p.to_array()), &[], &mut idx);
    if idx.len() != 3 * (corners.len() - 2) {
        return None;
    }
    let tris = idx
        .chunks_exact(3)
        .map(|t| {
            let t = [t[0], t[1], t[2]];
            let turn = (corners[t[1]] - corners[t[0]]).cross(corners[t[2]] - corners[t[0]]);
            if turn.dot(normal) < 0.0 {
                [t[0], t[2], t[1]]
            } else {
                t
            }
        })
        .collect();
    Some(tris)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(corners: &[DVec3], tris: &[[usize; 3]]) -> DVec3 {
        tris.iter()
            .map(|t| (corners[t[1]] - corners[t[0]]).cross(corners[t[2]] - corners[t[0]]))
            .sum()
    }

    /// The L of OFF facet `6 0 1 2 3 4 5` in vectors/openscad/imports/lshape.off, raised.
    fn ell(z: f64) -> Vec<DVec3> {
        [
            [10., 4.],
            [4., 4.],
            [4., 10.],
            [0., 10.],
            [0., 0.],
            [10., 0.],
        ]
        .map(|[x, y]| DVec3::new(x, y, z))
        .to_vec()
    }

    #[test]
    fn a_convex_face_is_its_fan() {
        let sq = [[0., 0.], [1., 0.], [1., 1.], [0., 1.]].map(|[x, y]| DVec3::new(x, y, 2.0));
        assert_eq!(triangulate(&sq), [[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn a_concave_face_is_covered_by_triangles_inside_it() {
        let l = ell(3.0);
        let tris = triangulate(&l);
        assert_eq!(tris.len(), 4);
        // Every triangle wound as the polygon (counter-clockwise): their areas add up to the
        // L's, 64 (no cancelling).
        for t in &tris {
            let turn = (l[t[1]] - l[t[0]]).cross(l[t[2]] - l[t[0]]);
            assert!(turn.z > 0.0, "{t:?}");
        }
        assert!((area(&l, &tris).z - 2.0 * 64.0).abs() < 1e-9);
        // The fan's first triangle, (10,4)-(4,4)-(4,10), lies in the notch, outside the L.
        assert!(!tris.contains(&[0, 1, 2]));
    }

    #[test]
    fn a_face_turned_any_way_is_clipped_in_its_plane() {
        let m = glam::DMat3::from_euler(glam::EulerRot::XYZ, 0.3, 1.2, -0.7);
        let l: Vec<DVec3> = ell(0.0).iter().map(|&p| m * p).collect();
        let tris = triangulate(&l);
        let normal = m * DVec3::Z;
        for t in &tris {
            let turn = (l[t[1]] - l[t[0]]).cross(l[t[2]] - l[t[0]]);
            assert!(turn.dot(normal) > 0.0, "{t:?}");
        }
        assert!((area(&l, &tris).length() - 128.0).abs() < 1e-9);
    }

    #[test]
    fn a_self_crossing_face_falls_back_to_the_fan() {
        let bow =
            [[0., 0.], [2., 2.], [2., 0.], [0., 2.], [-1., 1.]].map(|[x, y]| DVec3::new(x, y, 0.0));
        let tris = triangulate(&bow);
        assert_eq!(tris.len(), 3);
    }
}

//! Convex hulls: OpenSCAD's `hull()` of solids becomes one convex solid the array draws with
//! one plane per face (§5.2), and `hull()` of 2D shapes one convex polygon.
//!
//! The 3D hull is built incrementally (a tetrahedron, then every point outside a face replaces
//! the faces it sees by a fan from their horizon), with a tolerance relative to the points'
//! extent; coplanar triangles are then merged into one polygon face, so the hull of a cube has
//! six faces and the display list six planes.

use glam::{DVec2, DVec3};

use csgpix_scene::Result;

/// Relative tolerance: a point closer than this times the extent to a face's plane is on it.
const EPS: f64 = 1e-9;

/// The convex hull of `points` as (vertices, faces), faces counter-clockwise seen from
/// outside. Err when the points span no volume (fewer than four, or all on a plane).
pub fn hull3(points: &[DVec3]) -> Result<(Vec<DVec3>, Vec<Vec<usize>>)> {
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
            (a.min(p), b.max(p))
        });
    let extent = (hi - lo).max_element();
    if !(extent.is_finite() && extent > 0.0) {
        return Err("hull() of fewer than two distinct points".into());
    }
    let eps = EPS * extent;
    let tet = initial_tetrahedron(points, eps).ok_or("hull() of points on one plane: no volume")?;
    let mut faces: Vec<Face> = Vec::new();
    let centre = tet.iter().map(|&i| points[i]).sum::<DVec3>() / 4.0;
    for f in [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]] {
        faces.push(Face::outward(points, f.map(|k| tet[k]), centre));
    }
    for (i, &p) in points.iter().enumerate() {
        if tet.contains(&i) {
            continue;
        }
        let seen: Vec<bool> = faces.iter().map(|f| f.distance(p) > eps).collect();
        if !seen.contains(&true) {
            continue;
        }
        let horizon = horizon(&faces, &seen);
        // In place: a hull of tens of thousands of points (a Minkowski sum) adds nearly all.
        let mut k = 0;
        faces.retain(|_| {
            k += 1;
            !seen[k - 1]
        });
        for (a, b) in horizon {
            faces.push(Face::new(points, [a, b, i]));
        }
    }
    Ok(merge_coplanar(points, &faces, eps))
}

#[derive(Clone)]
struct Face {
    v: [usize; 3],
    n: DVec3,
    d: f64,
}

impl Face {
    fn new(points: &[DVec3], v: [usize; 3]) -> Face {
        let [a, b, c] = v.map(|i| points[i]);
        let n = (b - a).cross(c - a).normalize_or_zero();
        Face { v, n, d: n.dot(a) }
    }

    /// The face with its winding turned so that `inside` lies behind it.
    fn outward(points: &[DVec3], v: [usize; 3], inside: DVec3) -> Face {
        let f = Face::new(points, v);
        if f.distance(inside) > 0.0 {
            Face::new(points, [v[0], v[2], v[1]])
        } else {
            f
        }
    }

    fn distance(&self, p: DVec3) -> f64 {
        self.n.dot(p) - self.d
    }
}

/// Four points spanning a volume: the extremes along X, the farthest from their line, the
/// farthest from their plane.
fn initial_tetrahedron(points: &[DVec3], eps: f64) -> Option<[usize; 4]> {
    let by = |key: &dyn Fn(DVec3) -> f64| {
        (0..points.len()).max_by(|&a, &b| key(points[a]).total_cmp(&key(points[b])))
    };
    let a = by(&|p| -p.x)?;
    let b = by(&|p| (p - points[a]).length_squared())?;
    let ab = (points[b] - points[a]).normalize_or_zero();
    let c = by(&|p| (p - points[a]).cross(ab).length_squared())?;
    let n = (points[b] - points[a])
        .cross(points[c] - points[a])
        .normalize_or_zero();
    let d = by(&|p| n.dot(p - points[a]).abs())?;
    let spans = (points[b] - points[a]).length() > eps
        && (points[c] - points[a]).cross(ab).length() > eps
        && n.dot(points[d] - points[a]).abs() > eps;
    spans.then_some([a, b, c, d])
}

/// The edges bounding the seen faces, directed as the seen face had them.
fn horizon(faces: &[Face], seen: &[bool]) -> Vec<(usize, usize)> {
    let edges = |f: &Face| {
        let [a, b, c] = f.v;
        [(a, b), (b, c), (c, a)]
    };
    let visible: std::collections::HashSet<(usize, usize)> = faces
        .iter()
        .zip(seen)
        .filter(|(_, s)| **s)
        .flat_map(|(f, _)| edges(f))
        .collect();
    visible
        .iter()
        .filter(|&&(a, b)| !visible.contains(&(b, a)))
        .copied()
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect()
}

/// Triangles on one plane become one polygon (its vertices ordered around their centre), and
/// only the points faces use are kept.
fn merge_coplanar(points: &[DVec3], faces: &[Face], eps: f64) -> (Vec<DVec3>, Vec<Vec<usize>>) {
    let mut groups: Vec<(DVec3, f64, Vec<usize>)> = vec![];
    for f in faces {
        let g = groups
            .iter_mut()
            .find(|(n, d, _)| n.dot(f.n) > 1.0 - 1e-9 && (d - f.d).abs() <= eps);
        match g {
            Some((_, _, vs)) => vs.extend(f.v),
            None => groups.push((f.n, f.d, f.v.to_vec())),
        }
    }
    let mut index = vec![usize::MAX; points.len()];
    let mut vertices = vec![];
    let mut out = vec![];
    for (n, _, mut vs) in groups {
        vs.sort_unstable();
        vs.dedup();
        // The group's outline: the 2D hull in the face's plane (points inside the face or on
        // an edge between two corners are no corners, in either face that holds them).
        let u = n.any_orthonormal_vector();
        let w = n.cross(u);
        let flat: Vec<DVec2> = vs
            .iter()
            .map(|&i| DVec2::new(points[i].dot(u), points[i].dot(w)))
            .collect();
        let ring = hull2_indices(&flat);
        if ring.len() < 3 {
            continue;
        }
        let face = ring
            .into_iter()
            .map(|k| {
                let i = vs[k];
                if index[i] == usize::MAX {
                    index[i] = vertices.len();
                    vertices.push(points[i]);
                }
                index[i]
            })
            .collect();
        out.push(face);
    }
    (vertices, out)
}

/// The convex hull of 2D points, counter-clockwise, without collinear points (Andrew's
/// monotone chain). Fewer than three points when they span no area.
pub fn hull2(points: &[DVec2]) -> Vec<DVec2> {
    hull2_indices(points)
        .into_iter()
        .map(|i| points[i])
        .collect()
}

/// [`hull2`] as indices into `points`.
pub fn hull2_indices(points: &[DVec2]) -> Vec<usize> {
    let mut p: Vec<usize> = (0..points.len()).collect();
    let at = |i: usize| points[i];
    p.sort_by(|&a, &b| {
        at(a)
            .x
            .total_cmp(&at(b).x)
            .then(at(a).y.total_cmp(&at(b).y))
    });
    p.dedup_by(|a, b| at(*a) == at(*b));
    if p.len() < 3 {
        return p;
    }
    let cross = |o: usize, a: usize, b: usize| (at(a) - at(o)).perp_dot(at(b) - at(o));
    let mut h: Vec<usize> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let order: Vec<usize> = if pass == 0 {
            p.clone()
        } else {
            p.iter().rev().copied().collect()
        };
        for q in order {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube_points(lo: f64, hi: f64) -> Vec<DVec3> {
        (0..8)
            .map(|c| {
                DVec3::new(
                    if c & 1 == 0 { lo } else { hi },
                    if c & 2 == 0 { lo } else { hi },
                    if c & 4 == 0 { lo } else { hi },
                )
            })
            .collect()
    }

    fn volume(v: &[DVec3], faces: &[Vec<usize>]) -> f64 {
        faces
            .iter()
            .map(|f| {
                (1..f.len() - 1)
                    .map(|i| v[f[0]].dot(v[f[i]].cross(v[f[i + 1]])) / 6.0)
                    .sum::<f64>()
            })
            .sum()
    }

    #[test]
    fn two_cubes_hull_to_a_box_of_six_faces() {
        let mut p = cube_points(0.0, 1.0);
        p.extend(cube_points(0.0, 1.0).iter().map(|q| *q + DVec3::X * 3.0));
        p.push(DVec3::splat(0.5)); // inside
        let (v, f) = hull3(&p).unwrap();
        assert_eq!(f.len(), 6);
        assert_eq!(v.len(), 8);
        assert!((volume(&v, &f) - 4.0).abs() < 1e-12);
    }

    #[test]
    fn every_point_is_inside_every_face() {
        // Points on a sphere and inside it.
        let p: Vec<DVec3> = (0..200)
            .map(|i| {
                let (a, b) = (i as f64 * 2.399, (i as f64 * 0.61).sin());
                let r = if i % 3 == 0 { 0.5 } else { 1.0 };
                DVec3::new(
                    a.cos() * (1.0 - b * b).sqrt(),
                    a.sin() * (1.0 - b * b).sqrt(),
                    b,
                ) * r
            })
            .collect();
        let (v, f) = hull3(&p).unwrap();
        for face in &f {
            let [a, b, c] = [v[face[0]], v[face[1]], v[face[2]]];
            let n = (b - a).cross(c - a).normalize();
            assert!(p.iter().all(|q| n.dot(*q - a) <= 1e-9));
        }
        // Closed: every directed edge once, its reverse once.
        let mut edges = std::collections::HashMap::new();
        for face in &f {
            for k in 0..face.len() {
                *edges
                    .entry((face[k], face[(k + 1) % face.len()]))
                    .or_insert(0) += 1;
            }
        }
        assert!(edges
            .iter()
            .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1)));
    }

    #[test]
    fn flat_point_sets_are_refused() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(1.0, 1.0, 0.0)];
        assert!(hull3(&p).is_err());
        assert!(hull3(&[DVec3::ONE; 5]).is_err());
    }

    #[test]
    fn hull2_drops_inner_and_collinear_points() {
        let p = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
            DVec2::new(1.0, 1.0),
        ];
        let h = hull2(&p);
        assert_eq!(h.len(), 4);
        let area: f64 = (0..4).map(|i| h[i].perp_dot(h[(i + 1) % 4]) / 2.0).sum();
        assert_eq!(area, 4.0);
    }
}

//! `linear_extrude` meshes of unions of small polygons are closed, as `TriMesh::check_closed`
//! (which `csgpix voxelize` applies to every extruded mesh) requires: random polygons on a
//! coarse grid (so points coincide, fall on other outlines' edges, run back along a line, and
//! outlines touch at a corner or cross), extruded as the reader hands them over (each
//! polygon on its own when untwisted, several paths of one `polygon`, or a 2D union or
//! difference flattened first under a twist, as a twisted gear outline is). The caps must end
//! on the walls' edges; untwisted and flattened, the mesh must also hold, by the parity of
//! crossings, the points the shape holds by the even-odd rule.

use csgpix_openscad::extrude::{flatten, linear_mesh, Linear, Poly2, Region};
use csgpix_scene::trimesh::TriMesh;
use glam::{DVec2, DVec3};
use proptest::prelude::*;

fn sc(a: f64) -> (f64, f64) {
    a.to_radians().sin_cos()
}

fn linear(twist: f64) -> Linear {
    Linear {
        height: 2.0,
        center: false,
        twist,
        slices: 2,
        scale: [1.0, 1.0],
    }
}

/// The extrusion's mesh checked as `csgpix voxelize` checks it. Err with the check's message.
fn closed_mesh(p: &Poly2, twist: f64) -> Result<Vec<[DVec3; 3]>, TestCaseError> {
    let tris = linear_mesh(p, &linear(twist), &sc);
    if tris.is_empty() {
        // The reader draws nothing for it (a shape of no area).
        return Ok(tris);
    }
    let f: Vec<[[f64; 3]; 3]> = tris.iter().map(|t| t.map(|v| v.to_array())).collect();
    TriMesh::from_f64(&f)
        .check_closed("extrusion")
        .map_err(|e| TestCaseError::fail(format!("{e} for {:?}", p.paths)))?;
    Ok(tris)
}

/// Whether (x, y) is inside the shape by the even-odd rule over its outlines.
fn in_shape(p: &Poly2, q: DVec2) -> bool {
    let mut odd = false;
    for r in &p.paths {
        for i in 0..r.len() {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
                odd = !odd;
            }
        }
    }
    odd
}

/// Whether the vertical line through (x, y) crosses the triangles an odd number of times
/// below height z (the parity the voxelizer counts).
fn in_mesh(tris: &[[DVec3; 3]], q: DVec2, z: f64) -> bool {
    let hits = tris.iter().filter(|t| {
        let [a, b, c] = t.map(|v| v.truncate());
        let s = |u: DVec2, v: DVec2| (v - u).perp_dot(q - u);
        let (d1, d2, d3) = (s(a, b), s(b, c), s(c, a));
        let hit = (d1 > 0.0 && d2 > 0.0 && d3 > 0.0) || (d1 < 0.0 && d2 < 0.0 && d3 < 0.0);
        hit && (t[0].z * d2 + t[1].z * d3 + t[2].z * d1) / (d1 + d2 + d3) < z
    });
    hits.count() % 2 == 1
}

/// The untwisted mesh holds, at mid height, the points the shape does (a grid of points
/// off the outlines' half-unit grid).
fn same_inside(p: &Poly2, tris: &[[DVec3; 3]], half: f64) -> Result<(), TestCaseError> {
    for i in 0..40 {
        for j in 0..40 {
            let q = DVec2::new(i as f64 + 0.2371, j as f64 + 0.3113) * (2.0 * half / 40.0) - half;
            if in_shape(p, q) != in_mesh(tris, q, 1.0) {
                return Err(TestCaseError::fail(format!(
                    "{q} differs for {:?}",
                    p.paths
                )));
            }
        }
    }
    Ok(())
}

/// 3 to 6 points on the half-unit grid of [-2, 2]².
fn grid_polygon() -> impl Strategy<Value = Vec<DVec2>> {
    proptest::collection::vec((-4i32..5, -4i32..5), 3..7).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| DVec2::new(x as f64, y as f64) * 0.5)
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn grid_polygons_extrude_to_closed_meshes(
        polys in proptest::collection::vec(grid_polygon(), 1..6),
        how in 0..4,
        twist in prop_oneof![Just(0.0), -90.0f64..90.0],
    ) {
        let leaf = |p: &Vec<DVec2>| Region::Poly(Poly2 { paths: vec![p.clone()] });
        let shapes = match how {
            0 => polys.iter().map(|p| Poly2 { paths: vec![p.clone()] }).collect(),
            1 => vec![Poly2 { paths: polys.clone() }],
            _ => {
                let parts = polys.iter().map(leaf).collect();
                vec![flatten(&if how == 2 { Region::Union(parts) } else { Region::Difference(parts) })]
            }
        };
        for shape in &shapes {
            let tris = closed_mesh(shape, twist)?;
            if twist == 0.0 {
                same_inside(shape, &tris, 2.2)?;
            }
        }
    }
}

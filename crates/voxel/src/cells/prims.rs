//! The scene's primitives in voxel coordinates, as the walk classifies them: convex solids
//! by their planes, sampled shapes (meshes and datasets), and the grid itself.

use super::*;

/// The convex solid's supporting planes in voxel coordinates (`to_voxel` maps scene points),
/// each with how far it may be drawn from where it is.
pub(super) fn planes(
    s: &ConvexSolid,
    to_voxel: impl Fn(DVec3) -> DVec3,
    tol: &Tolerance,
) -> Vec<(DVec3, f64, f64)> {
    let v: Vec<DVec3> = s
        .vertices
        .iter()
        .map(|&p| to_voxel(DVec3::from(p)))
        .collect();
    if v.is_empty() {
        return vec![];
    }
    let mean = v.iter().copied().sum::<DVec3>() / v.len() as f64;
    let mut out = vec![];
    for f in &s.faces {
        let pts: Vec<DVec3> = f
            .iter()
            .filter_map(|&i| v.get(i as usize).copied())
            .collect();
        if pts.len() < 3 {
            continue;
        }
        // Newell's normal, outward for a face counter-clockwise seen from outside.
        let mut n = DVec3::ZERO;
        for (k, a) in pts.iter().enumerate() {
            let b = pts[(k + 1) % pts.len()];
            n += a.cross(b);
        }
        let Some(n) = n.try_normalize() else { continue };
        let centre = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
        let n = if n.dot(mean) > n.dot(centre) { -n } else { n };
        // A supporting plane: every vertex on its inner side.
        let d = v
            .iter()
            .map(|p| n.dot(*p))
            .fold(f64::NEG_INFINITY, f64::max);
        out.push((n, d, tol.plane(n)));
    }
    out
}

/// A sampled shape as a primitive in voxel coordinates (`to_voxel` maps scene points
/// there), with how far its boundary may move: a closed mesh by its triangles and box, one
/// that is not closed by its box, a dataset by the affine map from voxels to its lattice.
pub(super) fn sampled_prim<'a>(
    shape: &'a Shape,
    slicer: &Slicer,
    to_voxel: &impl Fn(DVec3) -> DVec3,
    tol: &Tolerance,
) -> (Prim<'a>, DVec3) {
    let grid = &slicer.grid;
    match shape {
        Shape::Mesh(m) => {
            let tris: Vec<[DVec3; 3]> = m
                .triangles
                .iter()
                .map(|t| t.map(|i| to_voxel(m.vertices[i as usize])))
                .collect();
            let lo = tris
                .iter()
                .flatten()
                .fold(DVec3::INFINITY, |a, &p| a.min(p));
            let hi = tris
                .iter()
                .flatten()
                .fold(DVec3::NEG_INFINITY, |a, &p| a.max(p));
            (Prim::Tris(tris, lo, hi), tol.mesh())
        }
        Shape::OpenMesh(m, _) => {
            let (lo, hi) = m.mesh().bounds();
            (Prim::Unknown(to_voxel(lo), to_voxel(hi)), tol.mesh())
        }
        Shape::Footprint(f) => {
            let (lo, hi) = f.bounds();
            (Prim::Unknown(to_voxel(lo), to_voxel(hi)), tol.mesh())
        }
        Shape::Dataset {
            data,
            threshold,
            to_file,
        } => {
            let voxel = grid.voxel();
            // Voxel → scene → file → lattice index, an affine map.
            let index = |v: DVec3| {
                let scene = grid.min + (v + DVec3::splat(0.5)) * voxel;
                data.index_of(to_file.transform_point3(scene))
            };
            let b = index(DVec3::ZERO);
            let a = DMat3::from_cols(
                index(DVec3::X) - b,
                index(DVec3::Y) - b,
                index(DVec3::Z) - b,
            );
            let graded = slicer.blend.is_some();
            let lattice = Lattice::new(a, b, data, *threshold, graded);
            (Prim::Lattice(lattice), DVec3::splat(1e-9))
        }
    }
}

/// The grid as a primitive: voxel centres 0..dims; any box between them and the next
/// centres out.
pub(super) fn grid_planes(dims: [usize; 3]) -> Prim<'static> {
    let dims = DVec3::from(dims.map(|d| d as f64));
    Prim::Planes(vec![
        (DVec3::NEG_X, 0.5, 0.0),
        (DVec3::NEG_Y, 0.5, 0.0),
        (DVec3::NEG_Z, 0.5, 0.0),
        (DVec3::X, dims.x - 0.5, 0.0),
        (DVec3::Y, dims.y - 0.5, 0.0),
        (DVec3::Z, dims.z - 0.5, 0.0),
    ])
}

//! Centre IoU against a reference mesh that forgives ties: a voxel whose centre lies on the
//! reference's surface (within [`BAND`] voxels) may round to either side in two meshes of the
//! same solid, so where the two occupancies differ there it counts as agreeing.

use csgpix_scene::grid::Grid;
use glam::DVec3;

/// How near (in voxels, along each axis) a centre must lie to the reference's surface to count
/// either way: far below the word's error, far above two meshes' rounding of the same face.
pub const BAND: f64 = 1e-3;

/// Triangles as three points each.
pub type Triangle = [[f64; 3]; 3];

/// The point of triangle `t` closest to `p` (Ericson, Real-Time Collision Detection, 5.1.5).
pub fn closest_on_triangle(p: DVec3, [a, b, c]: [DVec3; 3]) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = 1.0 / (va + vb + vc);
    a + ab * (vb * denom) + ac * (vc * denom)
}

/// Which of the voxels `asked` (indices, X fastest) have their centre within [`BAND`] voxels
/// of a triangle of `tris`, distances taken in voxel units (so a thousandth of a voxel along
/// each axis of a non-cubic voxel). The triangles are binned by their boxes into cells of
/// `CELL`³ voxels, so each centre meets only the triangles near it.
pub fn near_surface(tris: &[Triangle], grid: &Grid, asked: &[usize]) -> Vec<bool> {
    const CELL: usize = 4;
    let [nx, ny, _] = grid.dims;
    let cells = grid.dims.map(|d| d.div_ceil(CELL));
    let h = grid.voxel();
    // Voxel units: voxel (i, j, k)'s centre is the point (i, j, k).
    let to_voxel = |p: &[f64; 3]| (DVec3::from(*p) - grid.min) / h - 0.5;
    let mut bins: Vec<Vec<u32>> = vec![vec![]; cells.iter().product()];
    let cell_range = |lo: f64, hi: f64, n: usize| {
        let a = ((lo - BAND) / CELL as f64).floor().max(0.0) as usize;
        let b = ((hi + BAND) / CELL as f64).floor().max(0.0) as usize;
        a.min(n)..(b + 1).min(n)
    };
    for (t, tri) in tris.iter().enumerate() {
        let v = tri.map(|p| to_voxel(&p));
        let (lo, hi) = (v[0].min(v[1]).min(v[2]), v[0].max(v[1]).max(v[2]));
        for z in cell_range(lo.z, hi.z, cells[2]) {
            for y in cell_range(lo.y, hi.y, cells[1]) {
                for x in cell_range(lo.x, hi.x, cells[0]) {
                    bins[(z * cells[1] + y) * cells[0] + x].push(t as u32);
                }
            }
        }
    }
    asked
        .iter()
        .map(|&i| {
            let (x, y, z) = (i % nx, (i / nx) % ny, i / (nx * ny));
            let p = DVec3::new(x as f64, y as f64, z as f64);
            let cell = ((z / CELL) * cells[1] + y / CELL) * cells[0] + x / CELL;
            bins[cell].iter().any(|&t| {
                let v = tris[t as usize].map(|q| to_voxel(&q));
                closest_on_triangle(p, v).distance(p) <= BAND
            })
        })
        .collect()
}

/// `theirs` with every voxel where `ours` differs and whose centre lies within [`BAND`] voxels
/// of the reference's surface (`tris`) set to `ours`: the reference, forgiving ties.
pub fn forgive_ties(ours: &[bool], theirs: &[bool], tris: &[Triangle], grid: &Grid) -> Vec<bool> {
    let differ: Vec<usize> = (0..ours.len()).filter(|&i| ours[i] != theirs[i]).collect();
    let near = near_surface(tris, grid, &differ);
    let mut forgiven = theirs.to_vec();
    for (&i, &n) in differ.iter().zip(&near) {
        if n {
            forgiven[i] = ours[i];
        }
    }
    forgiven
}

/// Centre IoU of `ours` against the reference `theirs` (voxelized from `tris` on `grid`),
/// ties forgiven ([`forgive_ties`]).
pub fn centre_iou(ours: &[bool], theirs: &[bool], tris: &[Triangle], grid: &Grid) -> f64 {
    crate::iou(ours, &forgive_ties(ours, theirs, tris, grid))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The band: a voxel centre on the reference's surface may fall either way, one a hundredth of a
    /// voxel away may not.
    #[test]
    fn centre_iou_forgives_only_the_surface_band() {
        let grid = Grid::new([4, 4, 4], DVec3::ZERO, DVec3::splat(4.0)).unwrap();
        // A square in the plane x = 2.5 (voxel units: x = 2.0, the centres of column x = 2),
        // spanning the whole grid in y and z.
        let sq = |x: f64| {
            vec![
                [[x, -1.0, -1.0], [x, 5.0, -1.0], [x, 5.0, 5.0]],
                [[x, -1.0, -1.0], [x, 5.0, 5.0], [x, -1.0, 5.0]],
            ]
        };
        let inside = |lim: usize| (0..64).map(|i| i % 4 < lim).collect::<Vec<bool>>();
        // csgpix puts column 2 inside, the reference outside: forgiven on the plane...
        assert_eq!(centre_iou(&inside(3), &inside(2), &sq(2.5), &grid), 1.0);
        // ... a thousandth of a voxel off it still, a hundredth off not.
        assert_eq!(centre_iou(&inside(3), &inside(2), &sq(2.5009), &grid), 1.0);
        let off = centre_iou(&inside(3), &inside(2), &sq(2.51), &grid);
        assert!((off - 2.0 / 3.0).abs() < 1e-12, "{off}");
        // Voxel units: on a grid twice as long in x, a thousandth of a voxel is 0.002.
        let long = Grid::new([4, 4, 4], DVec3::ZERO, DVec3::new(8.0, 4.0, 4.0)).unwrap();
        assert_eq!(centre_iou(&inside(3), &inside(2), &sq(5.0018), &long), 1.0);
        assert!(centre_iou(&inside(3), &inside(2), &sq(5.0022), &long) < 1.0);
    }

    #[test]
    fn only_ties_are_forgiven() {
        let grid = Grid::new([4, 1, 1], DVec3::ZERO, DVec3::new(4.0, 1.0, 1.0)).unwrap();
        let tris = vec![
            [[1.5, -1.0, -1.0], [1.5, 2.0, -1.0], [1.5, 2.0, 2.0]],
            [[1.5, -1.0, -1.0], [1.5, 2.0, 2.0], [1.5, -1.0, 2.0]],
        ];
        let ours = [true, true, true, false];
        let theirs = [true, false, false, false];
        // Voxel 1 sits on the face and is forgiven; voxel 2 is a real difference.
        assert_eq!(
            forgive_ties(&ours, &theirs, &tris, &grid),
            [true, true, false, false]
        );
    }
}

//! Open and non-manifold meshes by their generalized winding number
//! (`csgpix_scene::winding`): the voxelizer's crossings-plus-boundary evaluation against the
//! direct sum over every triangle, and the inside test against closed forms (an open box, a
//! cube soup, two overlapping cubes), against the same mesh closed, and against the parity
//! of crossings on random closed meshes.

use std::f64::consts::PI;

use csgpix_scene::trimesh::{TriMesh, Window};
use csgpix_scene::winding::OpenMesh;
use glam::{DMat3, DVec3};
use proptest::prelude::*;

type Tri = [[f64; 3]; 3];

/// The 12 triangles of the box `[lo, hi]`, outward, two per face (the top face, +z, last).
fn cuboid(lo: [f64; 3], hi: [f64; 3]) -> Vec<Tri> {
    let c = |i: usize| {
        [
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ]
    };
    const QUADS: [[usize; 4]; 6] = [
        [0, 2, 3, 1],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
        [4, 5, 7, 6],
    ];
    QUADS
        .iter()
        .flat_map(|q| [[c(q[0]), c(q[1]), c(q[2])], [c(q[0]), c(q[2]), c(q[3])]])
        .collect()
}

/// A closed star-shaped surface around `c`: `rings` latitudes of `seg` points at radius
/// `r(i, j)`, and the two poles; outward.
fn star(c: DVec3, rings: usize, seg: usize, r: impl Fn(usize, usize) -> f64) -> Vec<Tri> {
    let point = |i: usize, j: usize| {
        let th = PI * (i + 1) as f64 / (rings + 1) as f64;
        let ph = 2.0 * PI * j as f64 / seg as f64;
        let d = DVec3::new(th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos());
        (c + d * r(i, j)).to_array()
    };
    let (north, south) = (
        (c + DVec3::Z * r(0, seg)).to_array(),
        (c - DVec3::Z * r(rings - 1, seg)).to_array(),
    );
    let mut t = vec![];
    for j in 0..seg {
        let k = (j + 1) % seg;
        t.push([north, point(0, j), point(0, k)]);
        t.push([south, point(rings - 1, k), point(rings - 1, j)]);
        for i in 0..rings - 1 {
            t.push([point(i, j), point(i + 1, j), point(i + 1, k)]);
            t.push([point(i, j), point(i + 1, k), point(i, k)]);
        }
    }
    t
}

/// An affine frame: `scale · (rot · p) + shift`, scene → (pixel x, pixel y, depth).
#[derive(Clone, Copy, Debug)]
struct Frame {
    rot: DMat3,
    scale: DVec3,
    shift: DVec3,
}

impl Frame {
    /// `[lo, hi]³` onto the voxel centres `0..n` on each axis (voxels of `(hi − lo) / n`).
    fn cube(lo: f64, hi: f64, n: usize) -> Frame {
        let s = n as f64 / (hi - lo);
        Frame {
            rot: DMat3::IDENTITY,
            scale: DVec3::splat(s),
            shift: DVec3::splat(-lo * s - 0.5),
        }
    }

    fn map(&self) -> impl Fn(DVec3) -> DVec3 + Copy + '_ {
        move |p| self.scale * (self.rot * p) + self.shift
    }

    fn scene(&self, f: DVec3) -> DVec3 {
        self.rot.transpose() * ((f - self.shift) / self.scale)
    }
}

/// Inside at every voxel centre `(x, y, k)` of an `n`³ grid, by the voxelizer's runs.
fn voxels(m: &OpenMesh, f: &Frame, n: usize) -> Vec<bool> {
    let depths: Vec<f64> = (0..n).map(|k| k as f64).collect();
    let win = Window {
        x0: 0,
        y0: 0,
        w: n,
        h: n,
    };
    let mut v = vec![false; n * n * n];
    for (i, runs) in m.inside_runs_in(f.map(), win, &depths).iter().enumerate() {
        for &(a, b) in runs {
            (a..=b).for_each(|k| v[i * n + k as usize] = true);
        }
    }
    v
}

/// Inside by the parity of crossings below each voxel centre, and whether the centre lies
/// within 1e-9 of a crossing (on the surface).
fn parity(m: &TriMesh, f: &Frame, n: usize) -> (Vec<bool>, Vec<bool>) {
    let mut inside = vec![false; n * n * n];
    let mut near = vec![false; n * n * n];
    for (i, c) in m.crossings(f.map(), n, n).iter().enumerate() {
        for k in 0..n {
            let z = k as f64;
            inside[i * n + k] = c.iter().filter(|&&d| d < z).count() % 2 == 1;
            near[i * n + k] = c.iter().any(|&d| (d - z).abs() <= 1e-9);
        }
    }
    (inside, near)
}

/// Voxels inside the box `[lo, hi]` by their centres, on the grid of [`Frame::cube`].
fn in_box(f: &Frame, n: usize, lo: [f64; 3], hi: [f64; 3]) -> Vec<bool> {
    let mut v = vec![false; n * n * n];
    for (i, c) in v.iter_mut().enumerate() {
        let p = f.scene(DVec3::new(
            (i / n % n) as f64,
            (i / n / n) as f64,
            (i % n) as f64,
        ));
        *c = (0..3).all(|a| lo[a] < p[a] && p[a] < hi[a]);
    }
    v
}

/// The solid angle of triangle `(a, b, c)` seen from the origin, by L'Huilier's theorem on
/// the spherical triangle's sides, signed by the orientation (independent of the crate's
/// van Oosterom–Strackee form).
fn solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (a, b, c) = (a.normalize(), b.normalize(), c.normalize());
    let side = |u: DVec3, v: DVec3| u.angle_between(v);
    let (x, y, z) = (side(b, c), side(c, a), side(a, b));
    let s = (x + y + z) / 2.0;
    let t = (s / 2.0).tan() * ((s - x) / 2.0).tan() * ((s - y) / 2.0).tan() * ((s - z) / 2.0).tan();
    4.0 * t.max(0.0).sqrt().atan() * a.dot(b.cross(c)).signum()
}

fn count(v: &[bool]) -> usize {
    v.iter().filter(|&&b| b).count()
}

#[test]
fn an_open_box_is_solid_inside_and_empty_far_outside() {
    let mut tris = cuboid([0.0; 3], [10.0; 3]);
    tris.truncate(10); // no top face
    let mesh = TriMesh::from_f64(&tris);
    assert!(mesh.check_closed("box").is_err());
    let m = OpenMesh::new(&mesh);
    assert_eq!(m.boundary_edges(), 4);
    // Five faces of a cube seen from its centre: 5/6.
    let w = m.winding_number(DVec3::splat(5.0));
    assert!((w - 5.0 / 6.0).abs() < 1e-12, "{w}");
    assert!(m.winding_number(DVec3::new(5.0, 5.0, 9.9)) > 0.5);
    assert!(m.winding_number(DVec3::new(5.0, 5.0, 10.1)).abs() < 0.5);
    assert!(m.winding_number(DVec3::splat(100.0)).abs() < 1e-3);
    // Every voxel centre inside the box is inside (the missing face is flat: from below it
    // subtends less than a hemisphere), none outside.
    let f = Frame::cube(-2.0, 12.0, 14);
    let got = voxels(&m, &f, 14);
    let want = in_box(&f, 14, [0.0; 3], [10.0; 3]);
    assert_eq!(count(&want), 10 * 10 * 10);
    assert_eq!(got, want);
}

#[test]
fn a_cube_soup_with_flipped_and_missing_triangles_is_the_cube() {
    let mut tris = cuboid([1.0; 3], [9.0; 3]);
    tris.remove(7);
    for k in [1, 4, 9] {
        tris[k].swap(1, 2);
    }
    // Unshared corners: every triangle its own three vertices.
    let soup = TriMesh {
        vertices: tris.iter().flatten().map(|&p| DVec3::from(p)).collect(),
        triangles: (0..tris.len() as u32)
            .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
            .collect(),
    };
    assert!(soup.check_closed("soup").is_err());
    let m = OpenMesh::new(&soup);
    assert_eq!(m.boundary_edges(), 3);
    let w = m.winding_number(DVec3::splat(5.0));
    assert!(w > 0.5 && w < 1.0, "{w}");
    let f = Frame::cube(0.0, 10.0, 10);
    assert_eq!(voxels(&m, &f, 10), in_box(&f, 10, [1.0; 3], [9.0; 3]));
    // The whole soup, all 12 triangles and some flipped, welds closed: parity takes it.
    let mut all = cuboid([1.0; 3], [9.0; 3]);
    all[3].swap(0, 1);
    TriMesh::from_f64(&all).check_closed("soup").unwrap();
}

#[test]
fn two_overlapping_cubes_count_twice_and_stay_inside() {
    let mut tris = cuboid([0.0; 3], [6.0; 3]);
    tris.extend(cuboid([3.0; 3], [9.0; 3]));
    let m = OpenMesh::new(&TriMesh::from_f64(&tris));
    assert_eq!(m.boundary_edges(), 0);
    assert!((m.winding_number(DVec3::splat(4.5)) - 2.0).abs() < 1e-9);
    assert!((m.winding_number(DVec3::splat(1.0)) - 1.0).abs() < 1e-9);
    assert!(m.winding_number(DVec3::new(1.0, 8.0, 1.0)).abs() < 1e-9);
    let f = Frame::cube(0.0, 9.0, 18);
    let a = in_box(&f, 18, [0.0; 3], [6.0; 3]);
    let b = in_box(&f, 18, [3.0; 3], [9.0; 3]);
    let union: Vec<bool> = a.iter().zip(&b).map(|(x, y)| x | y).collect();
    assert_eq!(voxels(&m, &f, 18), union);
}

/// A sphere of many triangles with a patch of `holes` triangles cut out, wound with every
/// seventh triangle the wrong way.
fn holey_sphere(holes: usize) -> Vec<Tri> {
    let mut t = star(DVec3::splat(10.0), 14, 28, |i, j| {
        7.0 + 0.6 * ((i * 3 + j) as f64 * 0.7).sin()
    });
    t.drain(100..100 + holes);
    for k in (0..t.len()).step_by(7) {
        t[k].swap(1, 2);
    }
    t
}

#[test]
fn a_sphere_with_a_hole_is_the_closed_sphere() {
    let closed = TriMesh::from_f64(&holey_sphere(0));
    closed.check_closed("sphere").unwrap();
    let f = Frame::cube(2.0, 18.0, 40);
    let (want, _) = parity(&closed, &f, 40);
    for holes in [1, 6] {
        let open = TriMesh::from_f64(&holey_sphere(holes));
        assert!(open.check_closed("holey").is_err());
        let got = voxels(&OpenMesh::new(&open), &f, 40);
        let both = got.iter().zip(&want).filter(|(a, b)| **a && **b).count();
        let either = got.iter().zip(&want).filter(|(a, b)| **a || **b).count();
        let iou = both as f64 / either as f64;
        assert!(iou >= 0.99, "{holes} holes: IoU {iou}");
        if holes == 1 {
            // The missing triangle is flat: exactly the closed sphere.
            assert_eq!(got, want);
        }
    }
}

/// A frame turned by `angles` (about z, then y, then x), scaled by `scale` per axis,
/// mirrored when `mirror`, with the mesh's box `[lo, hi]` inside voxel centres `0..n`.
fn turned(angles: [f64; 3], scale: [f64; 3], mirror: bool, lo: f64, hi: f64, n: usize) -> Frame {
    let rot = DMat3::from_rotation_x(angles[0])
        * DMat3::from_rotation_y(angles[1])
        * DMat3::from_rotation_z(angles[2]);
    let rot = if mirror {
        DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0)) * rot
    } else {
        rot
    };
    // The box's corners turned, fitted onto 0.5..n − 0.5 with the scale's proportions.
    let c = DVec3::splat((lo + hi) / 2.0);
    let r = (hi - lo) * 3f64.sqrt() / 2.0;
    let s = DVec3::from(scale);
    let s = s * ((n as f64 - 1.0) / 2.0 / r / s.max_element());
    Frame {
        rot,
        scale: s,
        shift: DVec3::splat((n as f64 - 1.0) / 2.0) - s * (rot * c),
    }
}

/// A sphere with 1 to 39 triangles cut out, its first 100-299 triangles lifted 1e-12 along
/// z or not (a seam: two boundary loops that all but cancel, module docs "Seams"), and up to
/// `loose − 1` loose triangles beside it, ready for the winding number.
fn holey_with_loose(loose: usize) -> impl Strategy<Value = OpenMesh> {
    let tri = prop::array::uniform3(prop::array::uniform3(4.0..16.0f64));
    let seam = prop::option::of(100usize..300);
    (1usize..40, seam, prop::collection::vec(tri, 0..loose)).prop_map(|(holes, seam, extra)| {
        let mut tris = holey_sphere(holes);
        for t in &mut tris[..seam.unwrap_or(0)] {
            t.iter_mut().for_each(|v| v[2] += 1e-12);
        }
        tris.extend(extra);
        OpenMesh::new(&TriMesh::from_f64(&tris))
    })
}

fn frame() -> impl Strategy<Value = ([f64; 3], [f64; 3], bool)> {
    (
        prop::array::uniform3(-3.2..3.2f64),
        prop::array::uniform3(0.5..2.0f64),
        any::<bool>(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The crossings-plus-boundary winding number is the direct sum over every triangle, at
    /// every voxel centre off the surface, whatever the frame's turn, scale and handedness.
    #[test]
    fn the_voxelizers_winding_number_is_the_direct_sum(
        (angles, scale, mirror) in frame(),
        m in holey_with_loose(6),
    ) {
        let n = 12;
        let f = turned(angles, scale, mirror, 2.0, 18.0, n);
        let depths: Vec<f64> = (0..n).map(|k| k as f64).collect();
        let crossings = m.mesh().crossings(f.map(), n, n);
        // The voxelizer's mesh: x and y snapped to 2^-16 pixel in the frame, wound as `m`.
        let snap = |c: f64| (c * 65536.0).round() / 65536.0;
        let snapped: Vec<DVec3> = m.mesh().vertices.iter().map(|&v| {
            let p = f.map()(v);
            f.scene(DVec3::new(snap(p.x), snap(p.y), p.z))
        }).collect();
        let direct_sum = |p: DVec3| -> f64 {
            let total: f64 = m.mesh().triangles.iter().map(|t| {
                let [a, b, c] = t.map(|i| snapped[i as usize] - p);
                solid_angle(a, b, c)
            }).sum();
            total / (4.0 * PI)
        };
        let mut checked = 0;
        for y in 0..n {
            for x in 0..n {
                let col = m.winding_on_column(f.map(), (x, y), &depths);
                for (k, w) in col.into_iter().enumerate() {
                    let Some(w) = w else { continue };
                    let z = k as f64;
                    if crossings[y * n + x].iter().any(|&d| (d - z).abs() < 1e-6) {
                        continue;
                    }
                    let p = f.scene(DVec3::new(x as f64, y as f64, z));
                    let direct = direct_sum(p);
                    prop_assert!((w - direct).abs() < 1e-9, "({x},{y},{k}): {w} vs {direct}");
                    checked += 1;
                }
            }
        }
        prop_assert!(checked > 20, "{checked}");
    }

    /// The voxelizer's runs, which take most samples by a bound on how fast the boundary's
    /// angles change along a column (module docs, "Skipping along a column"), are those of
    /// the full sum at every sample: not one sample on the other side of 1/2, on holey
    /// spheres with loose triangles, in turned, scaled and mirrored frames, at depths a
    /// quarter of a voxel apart.
    #[test]
    fn the_runs_are_the_full_sums_at_every_sample(
        (angles, scale, mirror) in frame(),
        m in holey_with_loose(4),
    ) {
        let n = 24;
        let f = turned(angles, scale, mirror, 2.0, 18.0, n);
        let depths: Vec<f64> = (0..4 * n).map(|k| k as f64 / 4.0).collect();
        let win = Window { x0: 0, y0: 0, w: n, h: n };
        let runs = m.inside_runs_in(f.map(), win, &depths);
        let (mut inside, mut outside) = (0, 0);
        for (i, got) in runs.iter().enumerate() {
            let mut want: Vec<(u32, u32)> = vec![];
            let col = m.winding_on_column(f.map(), (i % n, i / n), &depths);
            for (k, w) in col.into_iter().enumerate() {
                let k = k as u32;
                match w {
                    Some(w) if w >= 0.5 => {
                        inside += 1;
                        match want.last_mut() {
                            Some(r) if r.1 + 1 == k => r.1 = k,
                            _ => want.push((k, k)),
                        }
                    }
                    Some(_) => outside += 1,
                    None => {}
                }
            }
            prop_assert_eq!(got, &want, "column {}", i);
        }
        prop_assert!(inside > 50 && outside > 50, "{inside} inside, {outside} outside");
    }

    /// On closed meshes the winding number's inside test is the parity of crossings at every
    /// voxel centre not within 1e-9 of the surface.
    #[test]
    fn on_closed_meshes_the_winding_number_is_parity(
        (angles, scale, mirror) in frame(),
        radii in prop::collection::vec(3.0..8.0f64, 6 * 9 + 1),
        flip in any::<bool>(),
    ) {
        let mut tris = star(DVec3::splat(10.0), 6, 9, |i, j| radii[(i * 9 + j) % radii.len()]);
        if flip {
            tris.iter_mut().for_each(|t| t.swap(1, 2));
        }
        let mesh = TriMesh::from_f64(&tris);
        mesh.check_closed("star").unwrap();
        let n = 20;
        let f = turned(angles, scale, mirror, 2.0, 18.0, n);
        let (want, near) = parity(&mesh, &f, n);
        let got = voxels(&OpenMesh::new(&mesh), &f, n);
        let differ = (0..n * n * n).filter(|&i| !near[i] && got[i] != want[i]).count();
        prop_assert_eq!(differ, 0);
        prop_assert!(count(&want) > 10);
    }
}

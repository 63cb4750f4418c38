//! Triangle meshes in: STL (ASCII, binary) and OBJ read with one-line errors and no panics;
//! closedness checked; crossings exact where rays pass through edges and vertices (§4.4),
//! against closed forms on aligned solids and against the generalized winding number on
//! random closed meshes with frequent ties.

use csgpix_scene::mesh::Tri;
use csgpix_scene::trimesh::TriMesh;
use glam::DVec3;
use proptest::prelude::*;

// ---------------------------------------------------------------- solids

/// The 12 triangles of the box `[lo, hi]`, outward, each face split along a diagonal.
fn cuboid(lo: [f32; 3], hi: [f32; 3]) -> Vec<Tri> {
    let c = |i: usize| {
        [
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ]
    };
    hexahedron(std::array::from_fn(c))
}

/// A closed surface on 8 corners indexed by bits (x, y, z), outward for a box.
fn hexahedron(c: [[f32; 3]; 8]) -> Vec<Tri> {
    const QUADS: [[usize; 4]; 6] = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    QUADS
        .iter()
        .flat_map(|q| [[c[q[0]], c[q[1]], c[q[2]]], [c[q[0]], c[q[2]], c[q[3]]]])
        .collect()
}

/// The boundary of the tetrahedron `v` (consistently oriented whatever the points).
fn tetrahedron(v: [[f32; 3]; 4]) -> Vec<Tri> {
    [[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]]
        .iter()
        .map(|t| t.map(|i| v[i]))
        .collect()
}

/// The octahedron `|x-c| + |y-c| + |z-c| <= r` along the axes.
fn octahedron(c: [f32; 3], r: [f32; 3]) -> Vec<Tri> {
    let v = |axis: usize, s: f32| {
        let mut p = c;
        p[axis] += s * r[axis];
        p
    };
    let mut t = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0f32, 1.0] {
                let tri = [v(0, sx), v(1, sy), v(2, sz)];
                // Outward when the octant has an even number of negative signs.
                if sx * sy * sz > 0.0 {
                    t.push(tri);
                } else {
                    t.push([tri[0], tri[2], tri[1]]);
                }
            }
        }
    }
    t
}

fn reversed(t: Vec<Tri>) -> Vec<Tri> {
    t.into_iter().map(|[a, b, c]| [a, c, b]).collect()
}

/// A latitude-longitude sphere (closed once welded: the poles are shared).
fn sphere(c: [f32; 3], r: f32, n: usize) -> Vec<Tri> {
    let at = |i: usize, j: usize| {
        let (th, ph) = (
            std::f32::consts::PI * i as f32 / n as f32,
            std::f32::consts::TAU * (j % (2 * n)) as f32 / (2 * n) as f32,
        );
        if i == 0 || i == n {
            return [c[0], c[1], c[2] + if i == 0 { r } else { -r }];
        }
        [
            c[0] + r * th.sin() * ph.cos(),
            c[1] + r * th.sin() * ph.sin(),
            c[2] + r * th.cos(),
        ]
    };
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..2 * n {
            let (a, b, cc, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if i > 0 {
                t.push([a, b, d]);
            }
            if i + 1 < n {
                t.push([b, cc, d]);
            }
        }
    }
    t
}

// ---------------------------------------------------------------- references

/// The frame `(x + a·z + ox, y + b·z + oy, z)`: pixel x, pixel y, depth. Its rays are the
/// scene lines from `(X - ox, Y - oy, 0)` along `(-a, -b, 1)`, depth = parameter.
#[derive(Clone, Copy, Debug)]
struct Shear {
    a: f64,
    b: f64,
    o: (f64, f64),
}

impl Shear {
    fn map(self) -> impl Fn(DVec3) -> DVec3 {
        move |p| {
            DVec3::new(
                p.x + self.a * p.z + self.o.0,
                p.y + self.b * p.z + self.o.1,
                p.z,
            )
        }
    }
}

/// Depths where the ray of pixel `(x, y)` is inside the convex `{q : n·q <= d}`, as the
/// crossings expected: the ray is moved by `(2^-20, 2^-40)` pixel, the exact rule's
/// `(ε, ε²)`, to decide which rays along faces, edges and vertices hit; the depths are those
/// of the unmoved ray (the endpoints are continuous).
fn convex_crossings(planes: &[(DVec3, f64)], f: Shear, x: f64, y: f64) -> Vec<f64> {
    let clip = |x: f64, y: f64| {
        let (o, dir) = (
            DVec3::new(x - f.o.0, y - f.o.1, 0.0),
            DVec3::new(-f.a, -f.b, 1.0),
        );
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for &(n, d) in planes {
            let (s, r) = (n.dot(dir), d - n.dot(o));
            match s.partial_cmp(&0.0) {
                Some(std::cmp::Ordering::Greater) => hi = hi.min(r / s),
                Some(std::cmp::Ordering::Less) => lo = lo.max(r / s),
                _ if r < 0.0 => return None,
                _ => {}
            }
        }
        Some((lo, hi))
    };
    match clip(x + 2f64.powi(-20), y + 2f64.powi(-40)) {
        Some((lo, hi)) if lo < hi => {
            let (lo, hi) = clip(x, y).expect("the closure of a hit ray meets the solid");
            vec![lo, hi]
        }
        _ => vec![],
    }
}

fn box_planes(lo: f64, hi: f64) -> Vec<(DVec3, f64)> {
    [DVec3::X, DVec3::Y, DVec3::Z]
        .into_iter()
        .flat_map(|n| [(n, hi), (-n, -lo)])
        .collect()
}

fn octahedron_planes(c: f64, r: f64) -> Vec<(DVec3, f64)> {
    let mut p = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                let n = DVec3::new(sx, sy, sz);
                p.push((n, r + n.dot(DVec3::splat(c))));
            }
        }
    }
    p
}

/// Generalized winding number of the triangles at `p` (solid angles, van Oosterom and
/// Strackee): an integer off the surface, ±1 inside a simple closed surface.
fn winding(verts: &[DVec3], tris: &[[u32; 3]], p: DVec3) -> f64 {
    let mut sum = 0.0;
    for t in tris {
        let [a, b, c] = t.map(|i| verts[i as usize] - p);
        let (la, lb, lc) = (a.length(), b.length(), c.length());
        let num = a.dot(b.cross(c));
        let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        sum += 2.0 * num.atan2(den);
    }
    sum / (4.0 * std::f64::consts::PI)
}

fn assert_close(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-9, "{what}: got {got:?}, want {want:?}");
    }
}

/// Every pixel of `m` in frame `f` against the convex reference.
fn check_convex(m: &TriMesh, planes: &[(DVec3, f64)], f: Shear, w: usize, h: usize) {
    let got = m.crossings(f.map(), w, h);
    assert_eq!(got.len(), w * h);
    for y in 0..h {
        for x in 0..w {
            let want = convex_crossings(planes, f, x as f64, y as f64);
            assert_close(&got[y * w + x], &want, &format!("{f:?} pixel ({x}, {y})"));
        }
    }
}

const SHEARS: [(f64, f64, f64, f64); 7] = [
    (0.0, 0.0, 0.0, 0.0),
    (1.0, 0.0, 0.0, 0.0),
    (0.0, 1.0, 1.0, 0.0),
    (1.0, 1.0, 0.0, 0.0),
    (-1.0, 0.5, 8.0, 1.0),
    (0.5, -1.0, 2.0, 6.0),
    (-0.5, -0.5, 5.0, 5.0),
];

fn shears() -> impl Iterator<Item = Shear> {
    SHEARS
        .iter()
        .map(|&(a, b, ox, oy)| Shear { a, b, o: (ox, oy) })
}

// ---------------------------------------------------------------- crossings

#[test]
fn a_cube_with_ties_everywhere() {
    // Corners, edges and face diagonals all on pixel rays, in the view along z and in
    // sheared views where every face is seen at an angle.
    let m = TriMesh::from_tris(&cuboid([2.0; 3], [6.0; 3]));
    assert_eq!((m.vertices.len(), m.triangles.len()), (8, 12));
    for f in shears() {
        check_convex(&m, &box_planes(2.0, 6.0), f, 16, 16);
    }
    let got = m.crossings(|p| p, 8, 8);
    for y in 0..8 {
        for x in 0..8 {
            let inside = (2..6).contains(&x) && (2..6).contains(&y);
            let want: &[f64] = if inside { &[2.0, 6.0] } else { &[] };
            assert_close(&got[y * 8 + x], want, &format!("pixel ({x}, {y})"));
        }
    }
}

#[test]
fn a_hollow_cube_keeps_its_cavity() {
    let mut t = cuboid([0.0; 3], [6.0; 3]);
    t.extend(reversed(cuboid([2.0; 3], [4.0; 3])));
    let m = TriMesh::from_tris(&t);
    m.check_closed("hollow").unwrap();
    for f in shears() {
        let got = m.crossings(f.map(), 16, 16);
        for y in 0..16 {
            for x in 0..16 {
                let outer = convex_crossings(&box_planes(0.0, 6.0), f, x as f64, y as f64);
                let inner = convex_crossings(&box_planes(2.0, 4.0), f, x as f64, y as f64);
                let mut want: Vec<f64> = outer.into_iter().chain(inner).collect();
                want.sort_by(f64::total_cmp);
                assert_close(&got[y * 16 + x], &want, &format!("{f:?} ({x}, {y})"));
            }
        }
    }
    let got = m.crossings(|p| p, 8, 8);
    assert_close(&got[3 * 8 + 3], &[0.0, 2.0, 4.0, 6.0], "through the cavity");
    assert_close(
        &got[2 * 8 + 2],
        &[0.0, 2.0, 4.0, 6.0],
        "through the cavity's corner",
    );
    assert_close(&got[8 + 1], &[0.0, 6.0], "beside the cavity");
}

#[test]
fn an_octahedron_with_vertices_on_pixel_rays() {
    let m = TriMesh::from_tris(&octahedron([5.0; 3], [3.0; 3]));
    m.check_closed("octahedron").unwrap();
    for f in shears() {
        check_convex(&m, &octahedron_planes(5.0, 3.0), f, 16, 16);
    }
    let got = m.crossings(|p| p, 12, 12);
    // Through both poles: the surface passes, once each.
    assert_close(&got[5 * 12 + 5], &[2.0, 8.0], "through the poles");
    // Through an equatorial vertex: a silhouette, grazed.
    assert_eq!(got[5 * 12 + 8].len() % 2, 0);
}

#[test]
fn meshes_beyond_the_image() {
    let m = TriMesh::from_tris(&cuboid([-10.0, -3.0, 0.0], [5.0, 30.0, 2.0]));
    let got = m.crossings(|p| p, 8, 8);
    for y in 0..8 {
        for x in 0..8 {
            let want: &[f64] = if x < 5 { &[0.0, 2.0] } else { &[] };
            assert_close(&got[y * 8 + x], want, &format!("({x}, {y})"));
        }
    }
    // Entirely outside, on every side: nothing.
    for (lo, hi) in [
        ([-9.0, 0.0], [-1.0, 5.0]),
        ([8.0, 0.0], [12.0, 5.0]),
        ([0.0, 8.5], [7.0, 20.0]),
    ] {
        let m = TriMesh::from_tris(&cuboid([lo[0], lo[1], 0.0], [hi[0], hi[1], 1.0]));
        assert!(m.crossings(|p| p, 8, 8).iter().all(Vec::is_empty));
    }
    // Far beyond the clamp (±2^31 pixels): still covers the whole image.
    let m = TriMesh::from_tris(&cuboid([-1e12, -1e12, 1.0], [1e12, 1e12, 3.0]));
    for c in m.crossings(|p| p, 8, 8) {
        assert_close(&c, &[1.0, 3.0], "huge box");
    }
    assert!(m.crossings(|p| p, 0, 5).is_empty());
}

#[test]
fn crossings_do_not_depend_on_threads() {
    let mut t = sphere([20.0, 20.0, 20.0], 15.5, 40);
    t.extend(cuboid([3.0, 3.0, 0.0], [12.0, 9.0, 30.0]));
    let m = TriMesh::from_tris(&t);
    m.check_closed("sphere").unwrap();
    assert!(m.triangles.len() > 3000);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| m.crossings(|p| p, 40, 40))
    };
    let one = run(1);
    assert_eq!(one, run(2));
    assert!(one.iter().all(|c| c.len() % 2 == 0));
    let centre = &one[20 * 40 + 20];
    assert_eq!(centre.len(), 2);
    assert!((centre[0] - 4.5).abs() < 0.05 && (centre[1] - 35.5).abs() < 0.05);
}

/// A random closed mesh on a grid of half pixels (ties are frequent): tetrahedra, jittered
/// boxes and octahedra, possibly overlapping or flat.
fn grid_shape() -> impl Strategy<Value = Vec<Tri>> {
    let g = || (-4i32..28).prop_map(|k| k as f32 * 0.5);
    let pt = move || [g(), g(), g()];
    prop_oneof![
        [pt(), pt(), pt(), pt()].prop_map(tetrahedron),
        (
            pt(),
            prop::array::uniform8(prop::array::uniform3(-2i32..3)),
            1i32..12
        )
            .prop_map(|(lo, jitter, size)| {
                let c: [[f32; 3]; 8] = std::array::from_fn(|i| {
                    std::array::from_fn(|k| {
                        let bit = (i >> k) & 1;
                        lo[k] + (bit as i32 * size + jitter[i][k]) as f32 * 0.5
                    })
                });
                hexahedron(c)
            }),
        (pt(), [1i32..8, 1i32..8, 1i32..8])
            .prop_map(|(c, r)| octahedron(c, r.map(|k| k as f32 * 0.5))),
    ]
}

fn grid_frame() -> impl Strategy<Value = Shear> {
    let half = |k: i32| k as f64 * 0.5;
    (-2i32..3, -2i32..3, -4i32..5, -4i32..5).prop_map(move |(a, b, ox, oy)| Shear {
        a: half(a),
        b: half(b),
        o: (half(ox), half(oy)),
    })
}

/// Fixed-point x and y as the crossings snap them (2^-16 pixel).
fn snap(v: DVec3) -> (i64, i64) {
    (
        (v.x * 65536.0).round() as i64,
        (v.y * 65536.0).round() as i64,
    )
}

/// Whether the ray of pixel `(x, y)` lies in a triangle seen edge-on (zero snapped area):
/// along that face the surface is a segment of the ray, and the winding number there is
/// not an inside/outside answer.
fn along_a_face(snapped: &[(i64, i64)], tris: &[[u32; 3]], x: i64, y: i64) -> bool {
    let p = (x << 16, y << 16);
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| {
        i128::from(a.0 - o.0) * i128::from(b.1 - o.1)
            - i128::from(a.1 - o.1) * i128::from(b.0 - o.0)
    };
    let between = |a: i64, b: i64, c: i64| a.min(b) <= c && c <= a.max(b);
    tris.iter().any(|t| {
        let [a, b, c] = t.map(|i| snapped[i as usize]);
        cross(a, b, c) == 0
            && [(a, b), (b, c), (c, a)].iter().any(|&(u, v)| {
                cross(u, v, p) == 0 && between(u.0, v.0, p.0) && between(u.1, v.1, p.1)
            })
    })
}

/// Every pixel even, and, for the mesh as snapped, parity agrees with the winding number
/// (mod 2) at depths between and around the crossings and on a grid of depths. Points on
/// the surface are skipped: crossings (within 1e-9), grazing points (the winding number is
/// fractional there) and rays along an edge-on face (where it may not be), which the
/// closed-form tests cover. Returns the samples checked.
fn check_parity(m: &TriMesh, to_frame: impl Fn(DVec3) -> DVec3, w: usize, h: usize) -> usize {
    let got = m.crossings(&to_frame, w, h);
    let frame: Vec<DVec3> = m.vertices.iter().map(|&v| to_frame(v)).collect();
    let snapped: Vec<(i64, i64)> = frame.iter().map(|&v| snap(v)).collect();
    let verts: Vec<DVec3> = frame
        .iter()
        .zip(&snapped)
        .map(|(v, s)| DVec3::new(s.0 as f64 / 65536.0, s.1 as f64 / 65536.0, v.z))
        .collect();
    let (lo, hi) = verts
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, u), v| (l.min(v.z), u.max(v.z)));
    let mut checked = 0;
    for y in 0..h {
        for x in 0..w {
            let c = &got[y * w + x];
            assert_eq!(c.len() % 2, 0, "pixel ({x}, {y}): {c:?}");
            if along_a_face(&snapped, &m.triangles, x as i64, y as i64) {
                continue;
            }
            let mids = c.windows(2).map(|p| (p[0] + p[1]) / 2.0);
            let ends = c
                .first()
                .map(|d| d - 0.5)
                .into_iter()
                .chain(c.last().map(|d| d + 0.5));
            let grid = (0..)
                .map(|k| lo - 1.0 + 0.37 * k as f64)
                .take_while(|&d| d < hi + 1.0);
            for d in mids.chain(ends).chain(grid) {
                if c.iter().any(|e| (e - d).abs() < 1e-9) {
                    continue;
                }
                let wn = winding(&verts, &m.triangles, DVec3::new(x as f64, y as f64, d));
                if !wn.is_finite() || (wn - wn.round()).abs() >= 1e-6 {
                    continue; // on the surface where the ray grazes it (a silhouette)
                }
                let inside = (wn.round() as i64).rem_euclid(2) == 1;
                let odd = c.iter().filter(|&&e| e < d).count() % 2 == 1;
                assert_eq!(
                    odd, inside,
                    "pixel ({x}, {y}) depth {d}: {c:?}, winding {wn}"
                );
                checked += 1;
            }
        }
    }
    checked
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_grid_meshes_have_the_winding_numbers_parity(
        shapes in prop::collection::vec(grid_shape(), 1..4),
        f in grid_frame(),
    ) {
        let m = TriMesh::from_tris(&shapes.concat());
        let checked = check_parity(&m, f.map(), 14, 14);
        prop_assert!(checked > 14 * 14, "{} samples", checked);
    }

    #[test]
    fn random_rotations_have_the_winding_numbers_parity(
        shapes in prop::collection::vec(grid_shape(), 1..3),
        angles in [0.0..std::f64::consts::TAU, 0.0..std::f64::consts::TAU, 0.0..std::f64::consts::TAU],
    ) {
        let m = TriMesh::from_tris(&shapes.concat());
        let r = glam::DMat3::from_euler(glam::EulerRot::ZXY, angles[0], angles[1], angles[2]);
        let c = DVec3::splat(6.0);
        let checked = check_parity(&m, move |p| r * (p - c) + c, 14, 14);
        prop_assert!(checked > 14 * 14, "{} samples", checked);
    }
}

// ---------------------------------------------------------------- closedness

#[test]
fn closedness() {
    let cube = cuboid([0.0; 3], [1.0; 3]);
    TriMesh::from_tris(&cube).check_closed("cube.stl").unwrap();

    let e = TriMesh::from_tris(&cube[1..])
        .check_closed("open.stl")
        .unwrap_err()
        .to_string();
    assert!(!e.contains('\n'));
    assert!(
        e.starts_with(
            "open.stl: mesh is not closed: 3 edges belong to one triangle (first from (0,0,0) to"
        ),
        "{e}"
    );
    assert!(
        e.contains(", 0 to another odd number; close the holes"),
        "{e}"
    );

    // Two cubes sharing an edge: four triangles on it, an even number, so parity still
    // gives the inside (OpenSCAD writes such meshes).
    let mut two = cube.clone();
    two.extend(cuboid([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]));
    TriMesh::from_tris(&two).check_closed("two.stl").unwrap();

    // A fin on an edge of the cube: three triangles on it, two open edges.
    let mut fin = cube.clone();
    fin.push([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, -1.0, 0.5]]);
    let e = TriMesh::from_tris(&fin)
        .check_closed("fin.stl")
        .unwrap_err()
        .to_string();
    assert!(e.contains("not closed: 2 edges belong to one triangle (first from (1,0,0) to (0.5,-1,0.5)), 1 to another odd number;"), "{e}");

    // Degenerate triangles are dropped first; nothing left is refused.
    let mut degenerate = cube.clone();
    degenerate.push([[0.0; 3], [0.0; 3], [1.0; 3]]);
    TriMesh::from_tris(&degenerate)
        .check_closed("d.stl")
        .unwrap();
    let e = TriMesh::from_tris(&[[[0.0; 3], [0.0; 3], [1.0; 3]]])
        .check_closed("d.stl")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("d.stl: mesh has no triangles"), "{e}");
    assert!(TriMesh::default()
        .check_closed("e.stl")
        .unwrap_err()
        .to_string()
        .starts_with("e.stl: "));

    let bad = TriMesh {
        vertices: vec![DVec3::ZERO],
        triangles: vec![[0, 0, 9]],
    };
    assert!(bad
        .check_closed("b.stl")
        .unwrap_err()
        .to_string()
        .contains("refers to vertex 9"));
    assert!(bad.crossings(|p| p, 2, 2).iter().all(Vec::is_empty));
}

#[test]
fn bounds_and_transform() {
    let m = TriMesh::from_tris(&cuboid([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]));
    assert_eq!(
        m.bounds(),
        (DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0))
    );
    let t = m.transformed(
        glam::DMat4::from_translation(DVec3::X)
            * glam::DMat4::from_scale(DVec3::new(-1.0, 1.0, 2.0)),
    );
    assert_eq!(
        t.bounds(),
        (DVec3::new(-3.0, 2.0, 6.0), DVec3::new(0.0, 5.0, 12.0))
    );
    // Mirrored, the triangles are reversed so the enclosed volume stays positive.
    let volume = |m: &TriMesh| -> f64 {
        m.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| m.vertices[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    };
    assert!((volume(&m) - 27.0).abs() < 1e-9);
    assert!((volume(&t) - 54.0).abs() < 1e-9);
    assert_eq!(TriMesh::default().bounds().0, DVec3::INFINITY);
}

// ---------------------------------------------------------------- reading

const TETRA_STL: &str = "solid tetra made by hand
  facet normal 0 0 -1
    outer loop
      vertex 0 0 0
      vertex 0 1 0
      vertex 1 0 0
    endloop
  endfacet
  facet normal 0 -1 0
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 0 1
    endloop
  endfacet
  facet normal -1 0 0
    outer loop
      vertex 0 0 0
      vertex 0 0 1
      vertex 0 1 0
    endloop
  endfacet
  facet normal 0.577 0.577 0.577
    outer loop
      vertex 1 0 0
      vertex 0 1 0
      vertex 0 0 1.0e0
    endloop
  endfacet
endsolid tetra made by hand
";

fn binary_stl(header: &[u8], tris: &[Tri]) -> Vec<u8> {
    let mut b = vec![b' '; 80];
    b[..header.len()].copy_from_slice(header);
    b.extend((tris.len() as u32).to_le_bytes());
    for t in tris {
        b.extend([0u8; 12]);
        for c in t.iter().flatten() {
            b.extend(c.to_le_bytes());
        }
        b.extend([0u8; 2]);
    }
    b
}

const CUBE_OBJ: &str = "# a cube as quads, every face style
mtllib cube.mtl
o cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vn 0 0 1
g bottom
usemtl grey
s off
f 1/1/1 4/1/1 3/1/1 2/1/1
f 1//1 2//1 6//1 5//1  # vertices 5..8 are defined below: refused, see errors
";

#[test]
fn ascii_stl() {
    let m = TriMesh::parse(TETRA_STL.as_bytes(), "t.stl", false).unwrap();
    assert_eq!((m.vertices.len(), m.triangles.len()), (4, 4));
    m.check_closed("t.stl").unwrap();
    assert_eq!(m.bounds(), (DVec3::ZERO, DVec3::ONE));
    // Two solids in one file, empty solid, upper case keywords.
    let two = format!(
        "{TETRA_STL}{}",
        TETRA_STL.replace("vertex 0 0 0", "vertex 0 0 -1")
    );
    let m = TriMesh::parse(two.as_bytes(), "t.stl", false).unwrap();
    assert_eq!((m.vertices.len(), m.triangles.len()), (5, 8));
    let m = TriMesh::parse(b"solid\nendsolid\n", "e.stl", false).unwrap();
    assert!(m.triangles.is_empty());
    let upper = TETRA_STL.to_uppercase().replace("SOLID", "solid");
    assert_eq!(
        TriMesh::parse(upper.as_bytes(), "u.stl", false)
            .unwrap()
            .triangles
            .len(),
        4
    );
}

#[test]
fn binary_stl_even_with_a_solid_header() {
    let cube = cuboid([0.0; 3], [2.0, 1.0, 1.0]);
    let want = TriMesh::from_tris(&cube);
    for header in [&b"binary cube"[..], b"solid cube, but binary", b"  solid"] {
        let m = TriMesh::parse(&binary_stl(header, &cube), "c.stl", false).unwrap();
        assert_eq!(m, want);
        m.check_closed("c.stl").unwrap();
    }
    // Trailing bytes are ignored when the header does not say "solid".
    let mut b = binary_stl(b"x", &cube);
    b.extend([1, 2, 3]);
    assert_eq!(TriMesh::parse(&b, "c.stl", false).unwrap(), want);
}

#[test]
fn obj_with_slashes_negative_indices_and_polygons() {
    let text = CUBE_OBJ.replace(
        "f 1//1 2//1 6//1 5//1  # vertices 5..8 are defined below: refused, see errors\n",
        "v 0 0 1\nv 1 0 1 1.0\nv 1 1 1 0.5 0.5 0.5\nv 0 1 1\n\
         f -4 -3 -2 -1\n\
         f 1//1 2//1 6//1 5//1\n\
         f 2/2 3/2 7/2 6/2\r\n\
         f -5/1/1 -1/1/1 -2/1/1 -6/1/1 # trailing comment\n\
         f 4 1 5 8\n",
    );
    let m = TriMesh::parse(text.as_bytes(), "c.obj", true).unwrap();
    assert_eq!((m.vertices.len(), m.triangles.len()), (8, 12));
    m.check_closed("c.obj").unwrap();
    assert_eq!(m.bounds(), (DVec3::ZERO, DVec3::ONE));
    // A pentagon is fanned into three triangles; duplicate coordinates are welded.
    let penta = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nv 0 0 0\nf 1 2 3 4 5\nf 6 5 4\n";
    let m = TriMesh::parse(penta.as_bytes(), "p.obj", true).unwrap();
    assert_eq!((m.vertices.len(), m.triangles.len()), (5, 4));
    assert_eq!(m.triangles[..3], [[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
}

#[test]
fn read_picks_the_format_by_extension() {
    let dir = tempfile::tempdir().unwrap();
    let stl = dir.path().join("t.STL");
    std::fs::write(&stl, TETRA_STL).unwrap();
    assert_eq!(TriMesh::read(&stl).unwrap().triangles.len(), 4);
    let obj = dir.path().join("t.OBJ");
    std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    assert_eq!(TriMesh::read(&obj).unwrap().triangles.len(), 1);
    let missing = dir.path().join("none.stl");
    let e = TriMesh::read(&missing).unwrap_err().to_string();
    assert!(
        e.starts_with(&format!("{}: cannot read", missing.display())),
        "{e}"
    );
    // Any other extension is refused before the file is read (a PLY is not an STL).
    let ply = dir.path().join("t.ply");
    std::fs::write(&ply, "ply\nformat ascii 1.0\n").unwrap();
    let e = TriMesh::read(&ply).unwrap_err().to_string();
    assert!(e.contains(".stl, .obj, .off, .amf or .3mf"), "{e}");
    // OFF, AMF and 3MF by their extension, any case.
    let off = dir.path().join("t.Off");
    std::fs::write(&off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
    assert_eq!(TriMesh::read(&off).unwrap().triangles.len(), 1);
    let amf = dir.path().join("t.AMF");
    std::fs::write(&amf, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
    let e = TriMesh::read(&amf).unwrap_err().to_string();
    assert!(e.contains("t.AMF:1:1: not well-formed XML"), "{e}");
    let tmf = dir.path().join("t.3mf");
    std::fs::write(&tmf, TETRA_STL).unwrap();
    let e = TriMesh::read(&tmf).unwrap_err().to_string();
    assert!(e.contains("t.3mf: not a readable zip archive"), "{e}");
}

fn err(text: &str, file: &str, obj: bool) -> String {
    let e = TriMesh::parse(text.as_bytes(), file, obj)
        .unwrap_err()
        .to_string();
    assert!(!e.contains('\n'), "{e}");
    e
}

#[test]
fn text_errors_name_the_line_and_column() {
    let bad_number = TETRA_STL.replacen("vertex 0 1 0", "vertex 0 1,5 0", 1);
    let e = err(&bad_number, "t.stl", false);
    assert!(
        e.starts_with("t.stl:5:16: expected a finite number, found `1,5`"),
        "{e}"
    );
    let e = err(
        &TETRA_STL.replacen("vertex 0 0 0", "vertex 0 nan 0", 1),
        "t.stl",
        false,
    );
    assert!(e.starts_with("t.stl:4:16: "), "{e}");
    let quad = TETRA_STL.replacen(
        "      vertex 1 0 0\n",
        "      vertex 1 0 0\n      vertex 2 2 2\n",
        1,
    );
    let e = err(&quad, "t.stl", false);
    assert!(
        e.starts_with("t.stl:2:3: this facet has 4 vertices; an STL facet has 3"),
        "{e}"
    );
    let e = err(&TETRA_STL.replacen("endloop", "endlop", 1), "t.stl", false);
    assert!(
        e.starts_with("t.stl:7:5: expected `vertex` or `endloop`, found `endlop`"),
        "{e}"
    );
    let e = err(&TETRA_STL[..TETRA_STL.len() - 28], "t.stl", false);
    assert!(
        e.starts_with("t.stl:30:1: expected `facet` or `endsolid`, found the end"),
        "{e}"
    );

    let e = err(CUBE_OBJ, "c.obj", true);
    assert!(
        e.starts_with("c.obj:14:13: vertex index 6 is out of range: 4 vertices are defined so far"),
        "{e}"
    );
    let e = err("v 1 2 3\nv 1 2 x3\n", "c.obj", true);
    assert!(
        e.starts_with("c.obj:2:7: expected a finite number, found `x3`"),
        "{e}"
    );
    let e = err("v 1 2\n", "c.obj", true);
    assert!(
        e.starts_with("c.obj:1:6: a vertex needs 3 coordinates, found 2"),
        "{e}"
    );
    let e = err("v 0 0 0\nv 1 0 0\n  f 1 2\n", "c.obj", true);
    assert!(
        e.starts_with("c.obj:3:3: a face needs at least 3 vertices, found 2"),
        "{e}"
    );
    let e = err("v 0 0 0\nf 1 -2 1\n", "c.obj", true);
    assert!(
        e.starts_with("c.obj:2:5: vertex index -2 is out of range"),
        "{e}"
    );
    let e = err("v 0 0 0\nf 1 0 1\n", "c.obj", true);
    assert!(
        e.starts_with("c.obj:2:5: vertex index 0 is out of range"),
        "{e}"
    );
}

#[test]
fn binary_errors_name_the_byte_offset() {
    let cube = binary_stl(b"cube", &cuboid([0.0; 3], [1.0; 3]));
    let e = TriMesh::parse(&cube[..cube.len() - 7], "c.stl", false)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with(&format!(
            "c.stl: binary STL truncated at byte offset {}",
            cube.len() - 7
        )),
        "{e}"
    );
    assert!(e.contains("triangle 11 starts at byte offset 634"), "{e}");
    let e = TriMesh::parse(&cube[..50], "c.stl", false)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("c.stl: binary STL truncated at byte offset 50"),
        "{e}"
    );
    // A binary file with a "solid" header, truncated: the binary error, not an ASCII one.
    let solid = binary_stl(b"solid cube", &cuboid([0.0; 3], [1.0; 3]));
    let e = TriMesh::parse(&solid[..300], "s.stl", false)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("s.stl: binary STL truncated at byte offset 300"),
        "{e}"
    );
    let mut nan = cube.clone();
    nan[84 + 50 + 16..84 + 50 + 20].copy_from_slice(&f32::NAN.to_le_bytes());
    let e = TriMesh::parse(&nan, "n.stl", false)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("n.stl: binary STL: triangle 1 (byte offset 134) has a coordinate"),
        "{e}"
    );
}

/// Valid files of every kind, to mutate.
fn samples() -> Vec<(Vec<u8>, bool)> {
    let cube = cuboid([0.0; 3], [1.0; 3]);
    vec![
        (TETRA_STL.as_bytes().to_vec(), false),
        (binary_stl(b"solid x", &cube), false),
        (binary_stl(b"bin", &cube), false),
        (CUBE_OBJ.as_bytes().to_vec(), true),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400), obj: bool, solid: bool) {
        let mut b = if solid { b"solid ".to_vec() } else { Vec::new() };
        b.extend(bytes);
        if let Err(e) = TriMesh::parse(&b, "f", obj).map_err(|e| e.to_string()) {
            prop_assert!(e.starts_with("f:") && !e.contains('\n'), "{}", e);
        }
    }

    #[test]
    fn mutated_files_never_panic(
        which in 0usize..4,
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
        cut in any::<prop::sample::Index>(),
        truncate: bool,
    ) {
        let (mut b, obj) = samples().swap_remove(which);
        for (at, byte, how) in edits {
            let i = at.index(b.len());
            match how {
                0 => b[i] = byte,
                1 => b.insert(i, byte),
                _ => { b.remove(i); }
            }
        }
        if truncate {
            b.truncate(cut.index(b.len() + 1));
        }
        match TriMesh::parse(&b, "f", obj) {
            Ok(m) => {
                prop_assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.vertices.len()));
                let _ = m.check_closed("f");
                let c = m.crossings(|p| p * 4.0, 6, 6);
                prop_assert_eq!(c.len(), 36);
            }
            Err(e) => {
                let e = e.to_string();
                prop_assert!(e.starts_with("f:") && !e.contains('\n'), "{}", e)
            }
        }
    }
}

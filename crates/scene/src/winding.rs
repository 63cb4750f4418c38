//! Open and non-manifold triangle meshes as solids, by their generalized winding number
//! (Jacobson, Kavan and Sorkine-Hornung, "Robust inside-outside segmentation using
//! generalized winding numbers", SIGGRAPH 2013).
//!
//! A closed mesh bounds a solid and [`TriMesh::crossings`] finds it by the parity of ray
//! crossings. A mesh with holes, fins or loose triangles bounds nothing; its winding number
//! `w(p) = Σ Ω_t(p) / 4π` (the signed solid angles of its triangles seen from `p`) is still
//! defined, is the parity's 0 or 1 off the surface of a closed, consistently wound mesh, and
//! changes smoothly across a hole. csgpix takes `p` inside where `w(p) ≥ 1/2` and `p` lies in
//! the mesh's bounding box (in the voxelizer's frame). OpenSCAD 2021.01 has no counterpart:
//! its CGAL path (`createNefPolyhedronFromPolySet` in src/cgalutils.cc) stops at "The given mesh is
//! not closed! Unable to convert to CGAL_Nef_Polyhedron." and drops the object.
//!
//! # Winding by crossings and the boundary
//!
//! Summing every triangle at every voxel costs voxels × triangles. [`OpenMesh::inside_runs_in`]
//! instead uses, for a point `p` on a pixel's column (the frame's depth axis `ẑ`):
//!
//! `w(p) = X(p) + Σ_e m_e · Ω(a_e − p, b_e − p, ẑ) / 4π`
//!
//! where `X(p)` is the signed count of triangles the column crosses below `p` (+1 for a
//! triangle facing down, −1 facing up: the jump of `w` across it), and the sum runs over the
//! mesh's boundary chain: every directed edge `a → b` with net multiplicity `m ≠ 0` (the
//! triangles' edges, an edge and its reverse cancelling). Derivation: let `K` be the cone of
//! triangles `(a_e, b_e, q)` over the boundary to the point `q = p + sẑ` above `p`. Its
//! boundary is the mesh's, so `S − K` is closed and its winding number at `p` is the signed
//! count of crossings of any ray from `p`; the ray down from `p` misses `K` (every cone
//! triangle meets the column only at `q`), so it is `X(p)`. And `w_S = w_{S−K} + w_K`, with
//! `w_K(p)` the sum above (a solid angle depends on directions only, `q − p ∥ ẑ`). The cost
//! is the mesh's footprint columns × the voxels of its depth range × its boundary edges:
//! nothing beyond the crossings for a mesh with a small hole, and the direct sum's order
//! (three boundary edges per triangle) for a soup of loose triangles.
//!
//! The crossings are [`TriMesh::crossings`]' own, exact on shared edges and vertices. The
//! boundary term jumps by 1 where the column passes a boundary edge above which `p` lies,
//! exactly where `X` gains or loses the edge's triangle: the sign of that jump (the sign of
//! `Ω`'s numerator, the projected edge function) is taken from the same exact fixed-point
//! edge function at the same perturbed pixel centre, so the two stay in step; a boundary edge
//! seen end-on adds nothing, like its triangles. The denominator is evaluated in a form free
//! of cancellation for edges far below `p` (`boundary_angle`).
//!
//! # Orientation
//!
//! Solid angles are signed, so a triangle wound the wrong way cancels its neighbour.
//! [`OpenMesh::new`] turns triangles over to agree with their neighbours across every edge
//! two triangles share, then turns each connected piece so that the volume it encloses about
//! its box's centre is positive (outward). OpenSCAD 2021.01 refuses a polyhedron whose faces
//! disagree like this ("The given mesh is not closed!") unless every face is wound the other
//! way round; csgpix repairs them.

use std::collections::HashMap;
use std::f64::consts::PI;

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use crate::trimesh::{edges, Edge, Projected, Raster, TriMesh, Window, FRAC_BITS};

/// A mesh ready for the winding-number inside test: its proper triangles, each connected
/// piece wound consistently and outward, and its boundary chain.
#[derive(Clone, Debug, PartialEq)]
pub struct OpenMesh {
    mesh: TriMesh,
    /// Directed edges `[a, b]` with their net multiplicity (nonzero), sorted.
    boundary: Vec<([u32; 2], i32)>,
}

impl OpenMesh {
    /// The mesh with equal coordinates welded (a soup's repeated corners become shared),
    /// its degenerate triangles and those with an index past the vertices dropped, wound
    /// consistently (module docs, "Orientation").
    pub fn new(mesh: &TriMesh) -> OpenMesh {
        let n = mesh.vertices.len();
        let corners: Vec<[[f64; 3]; 3]> = mesh
            .triangles
            .iter()
            .filter(|t| t.iter().all(|&i| (i as usize) < n))
            .map(|t| t.map(|i| mesh.vertices[i as usize].to_array()))
            .collect();
        let mut welded = TriMesh::from_f64(&corners);
        welded
            .triangles
            .retain(|[a, b, c]| a != b && b != c && c != a);
        welded.triangles = orient(&welded.vertices, std::mem::take(&mut welded.triangles));
        let boundary = boundary(&welded.triangles);
        OpenMesh {
            mesh: welded,
            boundary,
        }
    }

    /// The triangles, as wound for the winding number.
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    /// The boundary chain's edges counted with their multiplicity.
    pub fn boundary_edges(&self) -> usize {
        self.boundary
            .iter()
            .map(|(_, m)| m.unsigned_abs() as usize)
            .sum()
    }

    /// The generalized winding number at `p`, summed over every triangle (van Oosterom and
    /// Strackee's solid angle): the reference [`OpenMesh::inside_runs_in`] is tested against.
    pub fn winding_number(&self, p: DVec3) -> f64 {
        let v = |i: u32| self.mesh.vertices[i as usize] - p;
        let sum: f64 = self
            .mesh
            .triangles
            .iter()
            .map(|&[a, b, c]| solid_angle(v(a), v(b), v(c)))
            .sum();
        sum / (4.0 * PI)
    }

    /// For each pixel of `win` (index `(y − y0)·w + (x − x0)`, as [`TriMesh::crossings_in`]),
    /// the runs `(first, last)` of the sample depths `depths` (ascending, frame depth units)
    /// whose points `(x, y, depth)` are inside: winding number at least 1/2 and within the
    /// mesh's box in the frame. `to_frame` maps scene points to (pixel x, pixel y, depth) and
    /// must be affine with orthogonal axes scaled separately (a [`crate`] user's frame is):
    /// the winding number is taken in the scene's proportions, not the frame's.
    pub fn inside_runs_in(
        &self,
        to_frame: impl Fn(DVec3) -> DVec3,
        win: Window,
        depths: &[f64],
    ) -> Vec<Vec<(u32, u32)>> {
        let mut out = vec![vec![]; win.w.saturating_mul(win.h)];
        if let Some((column, crossings)) = self.prepare(to_frame, win, depths) {
            out.par_iter_mut()
                .zip(crossings.par_iter())
                .enumerate()
                .for_each(|(i, (runs, crossed))| {
                    if let Some((px, py)) = column.centre(win, i) {
                        *runs = column.runs(px, py, crossed);
                    }
                });
        }
        out
    }

    /// The winding number at the points `(x, y, depth)` of the frame (as
    /// [`OpenMesh::inside_runs_in`]) for each of `depths`, computed as the voxelizer does
    /// (module docs, "Winding by crossings and the boundary"); `None` for points outside the
    /// mesh's box in the frame.
    pub fn winding_on_column(
        &self,
        to_frame: impl Fn(DVec3) -> DVec3,
        (x, y): (usize, usize),
        depths: &[f64],
    ) -> Vec<Option<f64>> {
        let mut out = vec![None; depths.len()];
        let win = Window {
            x0: x,
            y0: y,
            w: 1,
            h: 1,
        };
        if let Some((column, crossings)) = self.prepare(to_frame, win, depths) {
            if let Some((px, py)) = column.centre(win, 0) {
                let w = column.winding(px, py, &crossings[0]);
                for (k, w) in w.into_iter().enumerate() {
                    out[column.first as usize + k] = Some(w);
                }
            }
        }
        out
    }

    /// What every column of `win` shares, and each one's signed crossings; `None` when no
    /// sample lies in the mesh's depth range.
    fn prepare(
        &self,
        to_frame: impl Fn(DVec3) -> DVec3,
        win: Window,
        depths: &[f64],
    ) -> Option<(Column, Vec<Crossed>)> {
        if self.mesh.triangles.is_empty() || win.w.saturating_mul(win.h) == 0 {
            return None;
        }
        let iso = Iso::of(&to_frame, self.mesh.bounds());
        let projected: Vec<Projected> = self
            .mesh
            .vertices
            .iter()
            .map(|&v| Projected::of(to_frame(v)))
            .collect();
        let (lo, hi) = self.frame_box(&projected);
        let k0 = depths.partition_point(|&d| d < lo.z);
        let k1 = depths.partition_point(|&d| d <= hi.z);
        if k0 >= k1 {
            return None;
        }
        let boundary: Vec<Boundary> = self
            .boundary
            .iter()
            .map(|&([a, b], m)| Boundary::new(projected[a as usize], projected[b as usize], m))
            .collect();
        let column = Column {
            iso,
            boundary,
            zs: depths[k0..k1].to_vec(),
            first: k0 as u32,
            lo,
            hi,
        };
        Some((column, self.signed_crossings(&projected, win)))
    }

    /// The fixed-point x, y and the depth of the projected vertices' box.
    fn frame_box(&self, projected: &[Projected]) -> (DVec3, DVec3) {
        let used = self.mesh.triangles.iter().flatten();
        used.map(|&i| projected[i as usize]).fold(
            (DVec3::INFINITY, DVec3::NEG_INFINITY),
            |(lo, hi), p| {
                let v = DVec3::new(p.x as f64, p.y as f64, p.z);
                (lo.min(v), hi.max(v))
            },
        )
    }

    /// Per pixel of `win`, the depths where its column crosses a triangle and the jump of
    /// the winding number there (+1 where the triangle runs clockwise in the frame, facing
    /// down the depth axis), sorted by depth.
    fn signed_crossings(&self, projected: &[Projected], win: Window) -> Vec<Crossed> {
        let tris: Vec<Raster> = self
            .mesh
            .triangles
            .iter()
            .filter_map(|t| Raster::new(t, projected))
            .collect();
        let hits: Vec<Vec<(usize, f64, i32)>> = tris
            .par_chunks(256)
            .map(|chunk| {
                let (mut out, mut buf) = (Vec::new(), Vec::new());
                for t in chunk {
                    t.rasterize(win, &mut buf);
                    let jump = if t.flipped { 1 } else { -1 };
                    out.extend(buf.drain(..).map(|(i, d)| (i, d, jump)));
                }
                out
            })
            .collect();
        let mut pixels = vec![Vec::new(); win.w.saturating_mul(win.h)];
        for (i, d, s) in hits.into_iter().flatten() {
            pixels[i].push((d, s));
        }
        pixels
            .par_iter_mut()
            .for_each(|p| p.sort_unstable_by(|a, b| a.0.total_cmp(&b.0)));
        pixels
    }
}

/// One column's crossings: depth and the winding number's jump there, sorted by depth.
type Crossed = Vec<(f64, i32)>;

/// The frame's axes in scene proportions: frame coordinate i over `scale[i]` is a scene
/// length along an orthonormal basis whose handedness is `sign` times the scene's.
#[derive(Clone, Copy)]
struct Iso {
    scale: DVec3,
    sign: f64,
}

impl Iso {
    /// From the affine `to_frame`, by differences over the box `(lo, hi)`'s size.
    fn of(to_frame: &impl Fn(DVec3) -> DVec3, (lo, hi): (DVec3, DVec3)) -> Iso {
        let c = (lo + hi) / 2.0;
        let h = (hi - lo).max_element().max(1e-9);
        let at = to_frame(c);
        let l = DMat3::from_cols(
            (to_frame(c + DVec3::X * h) - at) / h,
            (to_frame(c + DVec3::Y * h) - at) / h,
            (to_frame(c + DVec3::Z * h) - at) / h,
        );
        let t = l.transpose();
        Iso {
            scale: DVec3::new(t.x_axis.length(), t.y_axis.length(), t.z_axis.length()),
            sign: if l.determinant() < 0.0 { -1.0 } else { 1.0 },
        }
    }
}

/// A boundary edge: its projected edge function, its ends' fixed-point x, y and depth, and
/// its multiplicity.
struct Boundary {
    edge: Edge,
    a: Projected,
    b: Projected,
    m: f64,
}

impl Boundary {
    fn new(a: Projected, b: Projected, m: i32) -> Boundary {
        Boundary {
            edge: Edge::new(a, b),
            a,
            b,
            m: f64::from(m),
        }
    }
}

/// What every column shares.
struct Column {
    iso: Iso,
    boundary: Vec<Boundary>,
    /// The sample depths within the mesh's depth range; the first is sample `first`.
    zs: Vec<f64>,
    first: u32,
    /// The mesh's box in the frame: fixed-point x and y, depth.
    lo: DVec3,
    hi: DVec3,
}

impl Column {
    /// The fixed-point centre of pixel `i` of `win`, if it lies in the mesh's box.
    fn centre(&self, win: Window, i: usize) -> Option<(i64, i64)> {
        let (x, y) = ((win.x0 + i % win.w) as i64, (win.y0 + i / win.w) as i64);
        let (px, py) = (x << FRAC_BITS, y << FRAC_BITS);
        let (fx, fy) = (px as f64, py as f64);
        let inside = self.lo.x <= fx && fx <= self.hi.x && self.lo.y <= fy && fy <= self.hi.y;
        inside.then_some((px, py))
    }

    /// The runs of inside samples on the column through fixed-point `(px, py)`, given its
    /// signed crossings.
    fn runs(&self, px: i64, py: i64, crossed: &[(f64, i32)]) -> Vec<(u32, u32)> {
        let mut runs: Vec<(u32, u32)> = vec![];
        for (k, w) in self.winding(px, py, crossed).into_iter().enumerate() {
            if w >= 0.5 {
                let k = self.first + k as u32;
                match runs.last_mut() {
                    Some(r) if r.1 + 1 == k => r.1 = k,
                    _ => runs.push((k, k)),
                }
            }
        }
        runs
    }

    /// The winding number at each sample of the column through fixed-point `(px, py)`,
    /// given its signed crossings: `X` plus the boundary's cone angles (module docs).
    fn winding(&self, px: i64, py: i64, crossed: &[(f64, i32)]) -> Vec<f64> {
        let mut omega = vec![0.0; self.zs.len()];
        for e in &self.boundary {
            self.add_boundary(e, px, py, &mut omega);
        }
        let (mut x, mut j) = (0i64, 0);
        let mut out = Vec::with_capacity(omega.len());
        for (&z, &o) in self.zs.iter().zip(&omega) {
            while j < crossed.len() && crossed[j].0 < z {
                x += i64::from(crossed[j].1);
                j += 1;
            }
            out.push(self.iso.sign * (x as f64 + o / (4.0 * PI)));
        }
        out
    }

    /// Adds edge `e`'s cone angle at every sample of the column to `omega`.
    fn add_boundary(&self, e: &Boundary, px: i64, py: i64, omega: &mut [f64]) {
        let side = e.edge.side(px, py);
        if side == 0 {
            // Seen end-on: its cone triangle meets the column only at its apex.
            return;
        }
        let s = self.iso.scale;
        let one = f64::from(1u32 << FRAC_BITS);
        let xy = |v: Projected| {
            let (dx, dy) = ((v.x - px) as f64 / one, (v.y - py) as f64 / one);
            (dx / s.x, dy / s.y)
        };
        let (a, b) = (xy(e.a), xy(e.b));
        let (az, bz) = (e.a.z / s.z, e.b.z / s.z);
        for (o, &z) in omega.iter_mut().zip(&self.zs) {
            let z = z / s.z;
            let u = DVec3::new(a.0, a.1, az - z);
            let v = DVec3::new(b.0, b.1, bz - z);
            *o += e.m * boundary_angle(u, v, side);
        }
    }
}

/// The signed solid angle of the triangle `(u, v, ∞·ẑ)` seen from the origin: van Oosterom
/// and Strackee's `tan(Ω/2) = u·(v × ẑ) / (|u||v| + u·v + u_z|v| + v_z|u|)`, divided by
/// `|u||v|` and with `1 + û_z` written `|u_xy|² / (|u|(|u| − u_z))` where `u_z < 0`, which
/// does not cancel for an edge far below. The numerator's sign is `side`, decided exactly.
fn boundary_angle(u: DVec3, v: DVec3, side: i32) -> f64 {
    let (lu, lv) = (u.length(), v.length());
    if lu == 0.0 || lv == 0.0 {
        return 0.0;
    }
    let up = |w: DVec3, l: f64| {
        if w.z >= 0.0 {
            1.0 + w.z / l
        } else {
            (w.x * w.x + w.y * w.y) / (l * (l - w.z))
        }
    };
    let n = ((u.x * v.y - u.y * v.x) / (lu * lv)).abs();
    let n = if side > 0 { n } else { -n };
    let d = up(u, lu) * up(v, lv) + (u.x * v.x + u.y * v.y) / (lu * lv);
    2.0 * n.atan2(d)
}

/// The signed solid angle of triangle `(a, b, c)` seen from the origin (van Oosterom and
/// Strackee 1983): positive when it runs counter-clockwise seen from the origin's far side.
fn solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let n = a.dot(b.cross(c));
    let d = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * n.atan2(d)
}

/// The triangles turned to agree with their neighbours across every edge exactly two of
/// them share, then each connected piece turned so that the volume it encloses about its
/// box's centre is not negative.
fn orient(vertices: &[DVec3], tris: Vec<[u32; 3]>) -> Vec<[u32; 3]> {
    let mut users: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(tris.len() * 3 / 2);
    for (k, t) in tris.iter().enumerate() {
        for (a, b) in edges(t) {
            users
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push(k as u32);
        }
    }
    let mut piece = vec![u32::MAX; tris.len()];
    let mut out = tris.clone();
    let mut pieces = 0u32;
    for seed in 0..tris.len() {
        if piece[seed] != u32::MAX {
            continue;
        }
        piece[seed] = pieces;
        let mut stack = vec![seed];
        while let Some(k) = stack.pop() {
            for (a, b) in edges(&out[k]) {
                let &[i, j] = users[&(a.min(b), a.max(b))].as_slice() else {
                    continue;
                };
                let other = if i as usize == k { j } else { i } as usize;
                if piece[other] != u32::MAX {
                    continue;
                }
                piece[other] = pieces;
                // The neighbour must run the shared edge b → a.
                if edges(&tris[other]).contains(&(a, b)) {
                    out[other] = [tris[other][0], tris[other][2], tris[other][1]];
                }
                stack.push(other);
            }
        }
        pieces += 1;
    }
    outward(vertices, &mut out, &piece, pieces as usize);
    out
}

/// Turns over every piece whose enclosed volume about its box's centre is negative.
fn outward(vertices: &[DVec3], tris: &mut [[u32; 3]], piece: &[u32], pieces: usize) {
    let mut boxes = vec![(DVec3::INFINITY, DVec3::NEG_INFINITY); pieces];
    for (t, &p) in tris.iter().zip(piece) {
        let b = &mut boxes[p as usize];
        for &i in t {
            *b = (b.0.min(vertices[i as usize]), b.1.max(vertices[i as usize]));
        }
    }
    let mut volume = vec![0.0; pieces];
    for (t, &p) in tris.iter().zip(piece) {
        let c = (boxes[p as usize].0 + boxes[p as usize].1) / 2.0;
        let [a, b, d] = t.map(|i| vertices[i as usize] - c);
        volume[p as usize] += a.dot(b.cross(d));
    }
    for (t, &p) in tris.iter_mut().zip(piece) {
        if volume[p as usize] < 0.0 {
            t.swap(1, 2);
        }
    }
}

/// The boundary chain: the triangles' directed edges, each edge less its reverse.
fn boundary(tris: &[[u32; 3]]) -> Vec<([u32; 2], i32)> {
    let mut net: HashMap<(u32, u32), i32> = HashMap::new();
    for (a, b) in tris.iter().flat_map(edges) {
        match a < b {
            true => *net.entry((a, b)).or_default() += 1,
            false => *net.entry((b, a)).or_default() -= 1,
        }
    }
    let mut out: Vec<([u32; 2], i32)> = net
        .into_iter()
        .filter(|&(_, m)| m != 0)
        .map(|((a, b), m)| ([a, b], m))
        .collect();
    out.sort_unstable();
    out
}

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
//! `w_K(p)` the sum above (a solid angle depends on directions only, `q − p ∥ ẑ`). Summed at
//! every sample, the cost would be the mesh's footprint columns × the voxels of its depth
//! range × its boundary edges; most samples are decided without the sum (below), so a mesh
//! with holes costs little beyond its crossings, and only a soup of loose triangles (three
//! boundary edges per triangle, every column near many) keeps the direct sum's order.
//!
//! The crossings are [`TriMesh::crossings`]' own, exact on shared edges and vertices. The
//! boundary term jumps by 1 where the column passes a boundary edge above which `p` lies,
//! exactly where `X` gains or loses the edge's triangle: the sign of that jump (the sign of
//! `Ω`'s numerator, the projected edge function) is taken from the same exact fixed-point
//! edge function at the same perturbed pixel centre, so the two stay in step; a boundary edge
//! seen end-on adds nothing, like its triangles. The denominator is evaluated in a form free
//! of cancellation for edges far below `p` (`boundary_angle`).
//!
//! # Skipping along a column
//!
//! Along one column the boundary term `B(z) = Σ_e m_e Ω_e(z) / 4π` is smooth: each cone
//! triangle is a vertical strip over its edge, which the column meets only where it passes
//! the edge (the crossings' business). Its rate is bounded: the gradient of a surface's solid
//! angle is the Biot–Savart integral round its boundary, `∇Ω = ∮ dl × r / |r|³` (`r` from the
//! point to the curve), and of a strip's boundary only the edge has a depth component (the
//! two vertical sides give `ẑ × r ⊥ ẑ`; the side at infinity nothing), so
//! `|dΩ_e/dz| ≤ ∫_e |dl_xy| |r_xy| / |r|³ ≤ ℓ_e / d_e²`, with `ℓ_e` the edge's length across
//! the depth axis and `d_e` its distance from the column there (scene proportions). Summed,
//! `|B(z) − B(z')| ≤ |z − z'| Σ_e |m_e| ℓ_e / d_e² / 4π`. Where that leaves too much room
//! over a column, each block of 16 samples takes its own bound, an edge whose depth range is
//! `h` away from the block's counted at `max_{ρ ≥ d_e} ρ / (ρ² + h²)^{3/2}` (the same integral
//! with `|r|² = ρ² + r_z²`, `r_z ≥ h`) instead of `1 / d_e²`; `h` is taken 1e-6 short, so
//! that an edge's angle turning where its computed denominator changes sign (near its own
//! depths, for a column just off its shadow) is always inside `h = 0`. An edge seen end-on
//! adds nothing at any depth and is left out. A sample whose winding number,
//! taken with `B` of the last sample where the boundary was summed (exact crossings of its
//! own), is farther from 1/2 than the bounds allow since then plus `SLACK` (1e-9, far above the
//! rounding of a sum of a few hundred angles) is on the same side of 1/2 as the full sum
//! would put it, so it is decided without the sum; any other sample is summed edge by edge in
//! the same order as before (the same bits) and becomes the next anchor. Far from the
//! boundary and from the level `w = 1/2` most samples are decided this way; near either, every
//! one is summed. The runs are those of the sum at every sample (a property test holds them
//! to it). The samples a bound decides are passed a block at a time: within a block the room
//! grows by its rate times the depth walked, so the last sample in reach is found by binary
//! search, and the next crossing ends a stretch (the count `X` changes there).
//!
//! # Seams
//!
//! A mesh made of pieces whose shared corners differ by rounding (1.8e-15 in a public
//! design's two polyhedra: BOSL2's `bosl2-ring-hook`) is closed in all but name: its
//! boundary is two loops over the same line, run opposite ways, whose cone angles cancel
//! to within the gap between them. The rate bound above adds their edges' terms instead,
//! twice an open loop's, and a column near such a seam summed nearly every sample. So two
//! boundary edges over the same projected segment whose chains cancel (opposite ways with
//! the same multiplicity, `Term::Two`) take one term: with the two short vertical
//! segments between their ends (which add nothing: a vertical edge's cone has no area) they
//! close a loop round the quadrilateral `Q` between them, so their summed angles are an
//! integer (fixed along a column that misses `Q`'s shadow) less `Ω_Q`, and
//! `|∇Ω_Q| ≤ ∫_Q |∇(n·r/|r|³)| dA ≤ ∫_Q 2/|r|³ dA ≤ 2 A_Q / D³`, `D` the distance from the
//! column's samples to `Q` (at least the column's distance from the segment less 1e-6, and
//! the depth gap as above). `A_Q ≤ (ℓ + |δb|)(|δa| + |δb|)/2` for depth gaps `δa`, `δb` at
//! the two ends. The term is the lesser of that and the two edges' own, so it never
//! loosens the bound. On `bosl2-ring-hook` (one polyhedron's 34 boundary edges are 17 such
//! pairs, 1.8e-15 apart) the whole 256³ voxelization took 0.13 s instead of 0.88-1.05 and
//! `csgpix print` 5.1-6.1 s instead of 19.3-20.9, every voxel and pixel the same; skipping
//! the decided samples a block at a time (`Column::skip`) then took them to 0.11 s and
//! 2.6 s.
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

use glam::{DMat3, DVec2, DVec3};
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
        self.inside_runs_ticking(to_frame, win, depths, &|| ())
    }

    /// [`OpenMesh::inside_runs_in`], calling `row` once for each row of `win` as it is done
    /// (`win.h` calls in all): a soup of loose triangles can take minutes, and a progress
    /// display counts these.
    pub fn inside_runs_ticking(
        &self,
        to_frame: impl Fn(DVec3) -> DVec3,
        win: Window,
        depths: &[f64],
        row: &(dyn Fn() + Sync),
    ) -> Vec<Vec<(u32, u32)>> {
        let mut out = vec![vec![]; win.w.saturating_mul(win.h)];
        let Some((column, crossings)) = self.prepare(to_frame, win, depths) else {
            (0..win.h).for_each(|_| row());
            return out;
        };
        out.par_chunks_mut(win.w)
            .zip(crossings.par_chunks(win.w))
            .enumerate()
            .for_each(|(y, (runs, crossed))| {
                for (x, (runs, crossed)) in runs.iter_mut().zip(crossed).enumerate() {
                    if let Some((px, py)) = column.centre(win, y * win.w + x) {
                        *runs = column.runs(px, py, crossed);
                    }
                }
                row();
            });
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
        let terms = terms(&boundary, iso);
        let column = Column {
            iso,
            terms,
            boundary,
            zs: depths[k0..k1].to_vec(),
            ts: depths[k0..k1].iter().map(|z| z / iso.scale.z).collect(),
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

/// How far from 1/2 a winding number taken by the bound must be (module docs, "Skipping along
/// a column"): far above the rounding of the summed angles, far below a voxel's worth.
const SLACK: f64 = 1e-9;

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
    /// Its ends' depths in scene proportions.
    fn depths(&self, iso: Iso) -> (f64, f64) {
        (self.a.z / iso.scale.z, self.b.z / iso.scale.z)
    }

    /// Whether the edge is seen end-on (no projected length), from every column.
    fn end_on(&self) -> bool {
        (self.a.x, self.a.y) == (self.b.x, self.b.y)
    }

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
    /// The terms of the rate bound, over the boundary's edges as every column sees them
    /// ([`Column::seen`]: all but those seen end-on, which are the same for every column).
    terms: Vec<Term>,
    /// The sample depths within the mesh's depth range; the first is sample `first`.
    zs: Vec<f64>,
    /// The same depths in scene proportions.
    ts: Vec<f64>,
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
    /// signed crossings: the samples where [`Column::winding`] is at least 1/2, found without
    /// evaluating the boundary at every sample (module docs, "Skipping along a column").
    fn runs(&self, px: i64, py: i64, crossed: &[(f64, i32)]) -> Vec<(u32, u32)> {
        let seen = self.seen(px, py);
        let rates = self.block_rates(&seen);
        if self.every_sample_summed(&rates) {
            // Summed edge by edge over the column, as the bound would have it at every sample.
            let w = self.winding_seen(&seen, crossed);
            return inside_runs(w.into_iter().map(|w| w >= 0.5), self.first);
        }
        // The last sample where the boundary's angles were summed: the sum, and the most
        // they can have changed since (radians).
        let mut anchor: Option<(f64, f64)> = None;
        let mut crossings = Crossings::new(crossed);
        let mut out = Ranges::new(self.first);
        let mut k = 0;
        while k < self.zs.len() {
            let x = crossings.below(self.zs[k]) as f64;
            let w = |o: f64| self.iso.sign * (x + o / (4.0 * PI));
            if let Some((o, room)) = anchor.as_mut() {
                let end = self.skip(k, room, w(*o), crossings.next(), &rates);
                if end > k {
                    out.push(k..end, w(*o) >= 0.5);
                    k = end;
                    continue;
                }
            }
            let o = self.omega_at(&seen, self.zs[k]);
            out.push(k..k + 1, w(o) >= 0.5);
            anchor = Some((o, 0.0));
            k += 1;
        }
        out.runs
    }

    /// From sample `k` (past an anchor, whose winding number with the crossings below `k` is
    /// `w`), the end of the samples the rate bounds `rates` decide as `w` is: each one's room
    /// (`room`, radians, accumulated sample by sample as the bound grows) at most
    /// `|w − 1/2|` less [`SLACK`], and none past the next crossing at depth `next` (where
    /// the crossings' count changes). Block by block: within one the room grows by the
    /// block's rate times the depth walked, so its last sample in reach is found by search.
    fn skip(&self, k: usize, room: &mut f64, w: f64, next: f64, rates: &[f64]) -> usize {
        let allowed = ((w - 0.5).abs() - SLACK) * 4.0 * PI;
        let (n, mut j) = (self.zs.len(), k);
        while j < n {
            let b = j / BLOCK;
            let end = ((b + 1) * BLOCK).min(n);
            let before = self.zs[j..end].partition_point(|&z| z <= next);
            // Samples i of the block with room + rate · (t(i) − t(j − 1)) below `allowed`
            // (a rate of 0 reaches every one, an infinite rate none).
            let from = self.ts[j - 1];
            let most = from + (allowed - *room) / rates[b];
            let reach = self.ts[j..j + before].partition_point(|&t| t < most);
            if reach > 0 {
                *room += rates[b] * (self.ts[j + reach - 1] - from);
            }
            let whole = reach == end - j;
            j += reach;
            if !whole {
                break;
            }
        }
        j
    }

    /// Whether the rate bounds `rates` leave more than a whole winding number of room
    /// between any two neighbouring samples (so every sample would be summed anyway).
    fn every_sample_summed(&self, rates: &[f64]) -> bool {
        let n = self.zs.len();
        if n < 2 {
            return false;
        }
        let step = (self.zs[n - 1] - self.zs[0]) / self.iso.scale.z / (n - 1) as f64;
        rates.iter().all(|r| r * step / (4.0 * PI) > 1.0)
    }

    /// The boundary edges as the column through fixed-point `(px, py)` sees them, in order,
    /// those seen end-on left out (their cone triangles add nothing there): those of no
    /// projected length ([`Boundary::end_on`]), the same for every column, so that
    /// [`Column::terms`] index this list.
    fn seen(&self, px: i64, py: i64) -> Vec<Seen> {
        let seen = self.boundary.iter().filter_map(|e| {
            let side = e.edge.side(px, py);
            let (a, b) = (self.across(e.a, px, py), self.across(e.b, px, py));
            let z = e.depths(self.iso);
            (side != 0).then(|| Seen {
                a,
                b,
                z,
                m: e.m,
                side,
                weight: e.m.abs() * (b - a).length(),
                d: segment_distance(a, b),
                span: (z.0.min(z.1), z.0.max(z.1)),
            })
        });
        seen.collect()
    }

    /// For each block of [`BLOCK`] samples, a bound on the rate of the boundary's summed
    /// angles (radians per unit of depth in scene proportions) from the sample before the
    /// block to its last. One bound for the whole column (every edge taken at its nearest)
    /// where that leaves less than [`SMALL`] of room over the column; otherwise one a block.
    fn block_rates(&self, seen: &[Seen]) -> Vec<f64> {
        let n = self.zs.len();
        let t = |k: usize| self.ts[k];
        let whole = rate(seen, &self.terms, None);
        let blocks = n.div_ceil(BLOCK);
        if n == 0 || whole * (t(n - 1) - t(0)) / (4.0 * PI) < SMALL {
            return vec![whole; blocks];
        }
        (0..blocks)
            .map(|b| {
                let (lo, hi) = ((b * BLOCK).saturating_sub(1), ((b + 1) * BLOCK).min(n) - 1);
                rate(seen, &self.terms, Some((t(lo), t(hi))))
            })
            .collect()
    }

    /// Vertex `v` seen from the column through fixed-point `(px, py)`, across the depth axis
    /// and in scene proportions.
    fn across(&self, v: Projected, px: i64, py: i64) -> DVec2 {
        let (s, one) = (self.iso.scale, f64::from(1u32 << FRAC_BITS));
        DVec2::new((v.x - px) as f64 / one / s.x, (v.y - py) as f64 / one / s.y)
    }

    /// The boundary's summed angles at the sample at depth `z` of the column that sees the
    /// boundary as `seen`: the sum [`Column::winding`] makes there, edge by edge in the same
    /// order, so the same bits.
    fn omega_at(&self, seen: &[Seen], z: f64) -> f64 {
        let z = z / self.iso.scale.z;
        seen.iter().fold(0.0, |o, e| o + e.m * e.angle(z))
    }

    /// The winding number at each sample of the column through fixed-point `(px, py)`,
    /// given its signed crossings: `X` plus the boundary's cone angles (module docs).
    fn winding(&self, px: i64, py: i64, crossed: &[(f64, i32)]) -> Vec<f64> {
        self.winding_seen(&self.seen(px, py), crossed)
    }

    /// [`Column::winding`] on the column that sees the boundary as `seen`: each edge's
    /// angles over the column in turn.
    fn winding_seen(&self, seen: &[Seen], crossed: &[(f64, i32)]) -> Vec<f64> {
        let mut omega = vec![0.0; self.zs.len()];
        for e in seen {
            for (o, &z) in omega.iter_mut().zip(&self.zs) {
                *o += e.m * e.angle(z / self.iso.scale.z);
            }
        }
        let mut crossings = Crossings::new(crossed);
        let w = self.zs.iter().zip(&omega);
        w.map(|(&z, &o)| self.iso.sign * (crossings.below(z) as f64 + o / (4.0 * PI)))
            .collect()
    }
}

/// A column's signed crossings, counted up the column: the samples' depths must ascend.
struct Crossings<'a> {
    crossed: &'a [(f64, i32)],
    next: usize,
    x: i64,
}

impl<'a> Crossings<'a> {
    fn new(crossed: &'a [(f64, i32)]) -> Self {
        Crossings {
            crossed,
            next: 0,
            x: 0,
        }
    }

    /// The depth of the next crossing not yet counted (infinite past the last).
    fn next(&self) -> f64 {
        self.crossed.get(self.next).map_or(f64::INFINITY, |c| c.0)
    }

    /// The signed count of crossings below depth `z` (no lower than the last asked).
    fn below(&mut self, z: f64) -> i64 {
        while let Some(&(_, s)) = self.crossed.get(self.next).filter(|c| c.0 < z) {
            self.x += i64::from(s);
            self.next += 1;
        }
        self.x
    }
}

/// The runs `(first, last)` of the true samples among `inside`, the first sample numbered
/// `first`.
fn inside_runs(inside: impl Iterator<Item = bool>, first: u32) -> Vec<(u32, u32)> {
    let mut out = Ranges::new(first);
    inside.enumerate().for_each(|(k, i)| out.push(k..k + 1, i));
    out.runs
}

/// Runs `(first, last)` of inside samples built from ranges of samples decided alike, the
/// first sample numbered `first`.
struct Ranges {
    first: u32,
    runs: Vec<(u32, u32)>,
}

impl Ranges {
    fn new(first: u32) -> Ranges {
        Ranges {
            first,
            runs: vec![],
        }
    }

    /// Samples `ks` (in order after those pushed before), inside or not.
    fn push(&mut self, ks: std::ops::Range<usize>, inside: bool) {
        if !inside || ks.is_empty() {
            return;
        }
        let (a, b) = (self.first + ks.start as u32, self.first + ks.end as u32 - 1);
        match self.runs.last_mut() {
            Some(r) if r.1 + 1 == a => r.1 = b,
            _ => self.runs.push((a, b)),
        }
    }
}

/// A boundary edge seen from a column, in scene proportions: its ends across the depth axis
/// from the column, their depths, its multiplicity and the exact sign of its cone angle's
/// numerator (never 0: an edge seen end-on is left out).
struct Seen {
    a: DVec2,
    b: DVec2,
    z: (f64, f64),
    m: f64,
    side: i32,
    /// `|m|` times the edge's length across the depth axis, its distance from the column
    /// there, and its depth range: what the rate bound needs ([`rate`]).
    weight: f64,
    d: f64,
    span: (f64, f64),
}

impl Seen {
    /// The edge's cone angle at depth `z` (scene proportions) on the column.
    fn angle(&self, z: f64) -> f64 {
        let u = DVec3::new(self.a.x, self.a.y, self.z.0 - z);
        let v = DVec3::new(self.b.x, self.b.y, self.z.1 - z);
        boundary_angle(u, v, self.side)
    }
}

/// Samples a rate bound covers on a column where one bound for the whole column is not enough.
const BLOCK: usize = 16;

/// The room (in winding number) below which one rate bound serves a whole column.
const SMALL: f64 = 0.05;

/// A bound on `|dΩ/dz|` of the cone triangles over `seen`, summed, for depths in `within`
/// (every depth where `None`): `Σ |m| ℓ · max_{ρ ≥ d} ρ / (ρ² + h²)^{3/2}`, `ℓ` an edge's
/// length across the depth axis, `d` its distance from the column there and `h` the gap
/// between `within` and its depth range less 1e-6 (module docs, "Skipping along a column").
/// Where `d ≥ h / √2` the maximum, at `ρ = d`, is bounded by `d / ((d² + h²) max(d, h))`,
/// which needs no square root.
fn rate(seen: &[Seen], terms: &[Term], within: Option<(f64, f64)>) -> f64 {
    let one = |e: &Seen| {
        let (d, h) = (e.d, gap(e.span, within));
        let (d2, h2) = (d * d, h * h);
        let most = match (h > 0.0, 2.0 * d2 >= h2) {
            (false, _) => 1.0 / d2,
            (true, true) => d / ((d2 + h2) * d.max(h)),
            // ρ / (ρ² + h²)^{3/2} is largest at ρ = h / √2.
            (true, false) => 2.0 / (3.0 * 3f64.sqrt() * h2),
        };
        e.weight * most
    };
    terms
        .iter()
        .map(|t| match *t {
            Term::One(k) => one(&seen[k]),
            Term::Two(k, l, q) => (one(&seen[k]) + one(&seen[l])).min(q.rate(seen[k].d, within)),
        })
        .sum()
}

/// The gap between the depths `within` (all of them where `None`) and the depth range
/// `span`, taken 1e-6 short and never below 0 (module docs, "Skipping along a column").
fn gap(span: (f64, f64), within: Option<(f64, f64)>) -> f64 {
    let gap = within.map_or(0.0, |(lo, hi)| (span.0 - hi).max(lo - span.1));
    (gap - 1e-6).max(0.0)
}

/// A term of the rate bound: one boundary edge (an index into [`Column::seen`]'s list), or
/// two whose chains all but cancel (module docs, "Seams").
#[derive(Clone, Copy, Debug)]
enum Term {
    One(usize),
    Two(usize, usize, Quad),
}

/// The quadrilateral between two boundary edges over the same line across the depth axis,
/// run opposite ways: its area bound (times 2 and the edges' multiplicity) and its depth range,
/// in scene proportions.
#[derive(Clone, Copy, Debug)]
struct Quad {
    area: f64,
    span: (f64, f64),
}

impl Quad {
    /// A bound on the rate of the two edges' summed cone angles on a column `d` across the
    /// depth axis from their projection, over the depths `within` (as [`rate`]): the solid
    /// angle of the quadrilateral, whose gradient is at most 2/r³ per unit of its area; none
    /// (infinite) within 1e-6 of the projection.
    fn rate(&self, d: f64, within: Option<(f64, f64)>) -> f64 {
        let (d, h) = (d - 1e-6, gap(self.span, within));
        match d > 0.0 {
            true => {
                let r2 = d * d + h * h;
                self.area / (r2 * r2.sqrt())
            }
            false => f64::INFINITY,
        }
    }
}

/// The terms of the rate bound over `boundary`'s edges as seen ([`Term`]): two edges over
/// the same projected segment whose chains cancel (run opposite ways with the same
/// multiplicity) make one term; any other edge seen makes its own.
fn terms(boundary: &[Boundary], iso: Iso) -> Vec<Term> {
    let seen: Vec<&Boundary> = boundary.iter().filter(|e| !e.end_on()).collect();
    let key = |e: &Boundary| {
        let (a, b) = ((e.a.x, e.a.y), (e.b.x, e.b.y));
        (a.min(b), a.max(b))
    };
    let mut open: HashMap<_, Vec<usize>> = HashMap::new();
    let mut partner = vec![None; seen.len()];
    for (l, e) in seen.iter().enumerate() {
        let waiting = open.entry(key(e)).or_default();
        match waiting.iter().position(|&k| cancels(seen[k], e)) {
            Some(at) => partner[waiting.swap_remove(at)] = Some(l),
            None => waiting.push(l),
        }
    }
    let mut out = vec![];
    let mut taken = vec![false; seen.len()];
    for k in 0..seen.len() {
        match (taken[k], partner[k]) {
            (true, _) => {}
            (false, Some(l)) => {
                taken[l] = true;
                out.push(Term::Two(k, l, quad(seen[k], seen[l], iso)));
            }
            (false, None) => out.push(Term::One(k)),
        }
    }
    out
}

/// Whether the chains of edges `e` and `f` (over the same projected segment) cancel.
fn cancels(e: &Boundary, f: &Boundary) -> bool {
    match same_way(e, f) {
        true => e.m == -f.m,
        false => e.m == f.m,
    }
}

/// Whether edges `e` and `f` over the same projected segment start at the same end of it.
fn same_way(e: &Boundary, f: &Boundary) -> bool {
    (e.a.x, e.a.y) == (f.a.x, f.a.y)
}

/// The [`Quad`] between edges `e` and `f` over the same projected segment: its corners are
/// their ends, each end of `e` above or below one of `f`'s, so its area is at most
/// `(ℓ + |δb|)(|δa| + |δb|) / 2`, `ℓ` the length of `e` and `δa`, `δb` the depth gaps at
/// its ends.
fn quad(e: &Boundary, f: &Boundary, iso: Iso) -> Quad {
    let (ez, fz) = (e.depths(iso), f.depths(iso));
    let fz = match same_way(e, f) {
        true => fz,
        false => (fz.1, fz.0),
    };
    let (one, s) = (f64::from(1u32 << FRAC_BITS), iso.scale);
    let across = DVec2::new(
        (e.b.x - e.a.x) as f64 / one / s.x,
        (e.b.y - e.a.y) as f64 / one / s.y,
    );
    let l = across.length().hypot(ez.1 - ez.0);
    let (da, db) = ((fz.0 - ez.0).abs(), (fz.1 - ez.1).abs());
    let lo = ez.0.min(ez.1).min(fz.0).min(fz.1);
    let hi = ez.0.max(ez.1).max(fz.0).max(fz.1);
    Quad {
        area: e.m.abs() * (l + db) * (da + db) * (1.0 + 1e-9),
        span: (lo, hi),
    }
}

/// The distance from the origin to the segment `ab`.
fn segment_distance(a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = match len2 > 0.0 {
        true => (-a.dot(ab) / len2).clamp(0.0, 1.0),
        false => 0.0,
    };
    (a + ab * t).length()
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A soup of small loose triangles packed into a corner of the box, all the way up
    /// (columns there pass near many boundary edges at every depth), in a closed tetrahedron
    /// reaching beyond it (inside samples on those columns and on others away from the soup), and one
    /// large loose triangle across the far corner.
    fn corner_soup() -> OpenMesh {
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut tris: Vec<[[f64; 3]; 3]> = (0..200)
            .map(|_| {
                let c = [0.6, 0.6, 3.6].map(|r| 0.2 + r * next());
                [0; 3].map(|_| [0, 1, 2].map(|a| c[a] + 0.3 * (next() - 0.5)))
            })
            .collect();
        tris.push([[1.5, 2.0, 0.5], [4.0, 2.5, 3.5], [2.0, 4.0, 2.0]]);
        let [a, b, c, d] = [
            [0.05, 0.05, 0.05],
            [3.8, 0.05, 0.05],
            [0.05, 1.5, 0.05],
            [0.3, 0.3, 3.9],
        ];
        tris.extend([[a, c, b], [a, b, d], [b, c, d], [c, a, d]]);
        OpenMesh::new(&TriMesh::from_f64(&tris))
    }

    /// A tetrahedron on the origin and the unit axes, all but its base lifted by `lift`
    /// along z: a seam of three pairs of boundary edges over the base's outline, run
    /// opposite ways.
    fn lifted_top(lift: f64) -> OpenMesh {
        let [o, x, y, z] = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let l = |p: [f64; 3]| [p[0], p[1], p[2] + lift];
        let tris = [
            [o, y, x],
            [l(o), l(x), l(z)],
            [l(o), l(z), l(y)],
            [l(x), l(y), l(z)],
        ];
        OpenMesh::new(&TriMesh::from_f64(&tris))
    }

    /// The frame of [`lifted_top`]'s tests: the unit box at pixels 8-16 of a 24-pixel
    /// window, and the column through pixel (4, 12), half a unit from the nearest edge.
    fn lifted_column(m: &OpenMesh) -> (Column, Vec<Seen>) {
        let to_frame = |p: DVec3| p * 8.0 + DVec3::new(8.0, 8.0, 8.0);
        let depths: Vec<f64> = (0..96).map(|k| k as f64 / 4.0).collect();
        let win = Window {
            x0: 0,
            y0: 0,
            w: 24,
            h: 24,
        };
        let (column, _) = m.prepare(to_frame, win, &depths).expect("samples in range");
        let seen = column.seen(4 << FRAC_BITS, 12 << FRAC_BITS);
        (column, seen)
    }

    /// A seam's edges pair up, and on a column away from it their rate bound is the
    /// quadrilateral's, far below the edges' own.
    #[test]
    fn a_seams_edges_pair_up_and_their_bound_is_the_gap_between_them() {
        let m = lifted_top(1e-12);
        assert_eq!(m.boundary_edges(), 6);
        let (column, seen) = lifted_column(&m);
        let pairs = column
            .terms
            .iter()
            .filter(|t| matches!(t, Term::Two(..)))
            .count();
        assert_eq!((pairs, column.terms.len()), (3, 3));
        let ones: Vec<Term> = (0..seen.len()).map(Term::One).collect();
        let (paired, alone) = (rate(&seen, &column.terms, None), rate(&seen, &ones, None));
        assert!(paired < 1e-9 && alone > 1.0, "{paired} against {alone}");
    }

    /// The quadrilateral's bound holds: the two edges' summed cone angles change no faster
    /// than [`Quad::rate`] between any two depths of the column, above, across and below the
    /// seam (lifted a fifth of a unit, so that the change is far above rounding).
    #[test]
    fn the_quadrilaterals_bound_holds_along_a_column() {
        let m = lifted_top(0.2);
        let (column, seen) = lifted_column(&m);
        let mut checked = 0;
        for t in &column.terms {
            let &Term::Two(k, l, q) = t else {
                panic!("every edge pairs")
            };
            let sum = |z: f64| seen[k].m * seen[k].angle(z) + seen[l].m * seen[l].angle(z);
            for (lo, hi) in [(-1.0, 0.5), (0.5, 1.1), (1.1, 3.0), (-1.0, 3.0)] {
                let zs: Vec<f64> = (0..=200)
                    .map(|i| lo + (hi - lo) * f64::from(i) / 200.0)
                    .collect();
                let bound = q.rate(seen[k].d, Some((lo, hi)));
                for w in zs.windows(2) {
                    let change = (sum(w[1]) - sum(w[0])).abs();
                    assert!(
                        change <= bound * (w[1] - w[0]) + 1e-12,
                        "{change} over {w:?}: {bound}"
                    );
                    checked += 1;
                }
                assert!(bound < rate(&seen, &[Term::One(k), Term::One(l)], Some((lo, hi))));
            }
        }
        assert_eq!(checked, 3 * 4 * 200);
    }

    /// Both of [`Column::runs`]' ways (samples decided by the rate bound, and a column the
    /// bound cannot skip summed whole) give the runs of the sum at every sample, and the
    /// mesh takes both.
    #[test]
    fn both_ways_give_the_runs_of_the_sums_at_every_sample() {
        let m = corner_soup();
        let n = 24;
        let to_frame = |p: DVec3| p * (n as f64 / 4.0);
        let depths: Vec<f64> = (0..2 * n).map(|k| k as f64 / 2.0).collect();
        let win = Window {
            x0: 0,
            y0: 0,
            w: n,
            h: n,
        };
        let (column, crossings) = m.prepare(to_frame, win, &depths).expect("samples in range");
        let (mut whole, mut skipped) = (0, 0);
        for (i, crossed) in crossings.iter().enumerate() {
            let Some((px, py)) = column.centre(win, i) else {
                continue;
            };
            let sums = column.winding(px, py, crossed).into_iter();
            let want = inside_runs(sums.map(|w| w >= 0.5), column.first);
            assert_eq!(column.runs(px, py, crossed), want, "column {i}");
            let rates = column.block_rates(&column.seen(px, py));
            match (column.every_sample_summed(&rates), want.is_empty()) {
                (true, false) => whole += 1,
                (false, false) => skipped += 1,
                (_, true) => {}
            }
        }
        // Columns with inside samples, each way.
        assert!(
            whole > 5 && skipped > 20,
            "{whole} summed whole, {skipped} skipped"
        );
    }
}

//! Closed triangle meshes as solid primitives: read from STL (binary or ASCII) or OBJ, checked
//! for closedness, and sliced along the view direction into per-pixel depth intervals.
//!
//! A mesh is a solid given only by its boundary, so its interior comes from parity: a ray
//! from a pixel enters the solid at its first crossing and leaves at the next (the XOR
//! slicing of §3.4.2, where the "0th slice" from `z = -∞` to the region's first plane makes
//! the parity right for objects that start before the region: here the crossings are listed
//! from `-∞`, so every pair is complete). Each triangle is, as in §5.3.1, its plane clipped
//! by the three planes through its edges perpendicular to the screen: the edge functions
//! decide coverage, the plane gives the depth.
//!
//! §4.4 warns that the parity rule fails "if vertex or some point on edge of surface
//! primitive happens to project to the exact center of a pixel". [`TriMesh::crossings`] is
//! exact in those cases: projected vertices are snapped to a fixed-point grid (each welded
//! vertex once, so shared vertices stay shared), edge functions are evaluated exactly in
//! integers, and points on an edge or vertex are decided by a symbolic perturbation of the
//! pixel centre (a top-left fill rule). Every pixel of a closed mesh therefore gets an even
//! number of crossings, counted once where the surface passes through an edge or vertex and
//! zero or two times where it only grazes a silhouette.

use std::collections::HashMap;

use glam::{DMat3, DMat4, DVec3};
use rayon::prelude::*;

use crate::mesh::Tri;
use crate::{Error, Result};

/// The extensions (lower case) of the mesh files [`TriMesh::read`] reads.
pub const READ_EXTENSIONS: [&str; 5] = ["stl", "obj", "off", "amf", "3mf"];

/// A triangle mesh with shared vertices. A solid when closed ([`TriMesh::check_closed`]);
/// the orientation of the triangles does not matter to [`TriMesh::crossings`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriMesh {
    /// The vertices, each once.
    pub vertices: Vec<DVec3>,
    /// Triangles as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
}

/// Shares vertices with equal coordinates (`-0.0` and `0.0` are one vertex).
#[derive(Default)]
struct Welder {
    at: HashMap<[u64; 3], u32, foldhash::fast::RandomState>,
    mesh: TriMesh,
}

impl Welder {
    fn vertex(&mut self, p: DVec3) -> Result<u32> {
        let key = p.to_array().map(|c| (c + 0.0).to_bits());
        if let Some(&i) = self.at.get(&key) {
            return Ok(i);
        }
        let i = u32::try_from(self.mesh.vertices.len()).map_err(|_| Error::TooManyVertices)?;
        self.mesh.vertices.push(p);
        self.at.insert(key, i);
        Ok(i)
    }

    fn triangle(&mut self, t: [DVec3; 3]) -> Result<()> {
        let t = [self.vertex(t[0])?, self.vertex(t[1])?, self.vertex(t[2])?];
        self.mesh.triangles.push(t);
        Ok(())
    }
}

impl TriMesh {
    /// Parses OBJ (`obj`) or STL. STL is ASCII when it starts with `solid` and parses as
    /// ASCII; otherwise binary, which also covers binary files whose header starts with
    /// `solid` (their length is `84 + 50·n`). OBJ reads `v x y z` and `f a b c …` (indices
    /// `a`, `a/t`, `a/t/n`, `a//n`, negative = relative to the vertices so far; polygons
    /// fan-triangulated) and ignores other statements. Equal coordinates are welded into one
    /// vertex, so an STL (which repeats vertices) comes out shared. Errors are one line:
    /// `FILE:LINE:COL: …` for text, `FILE: … byte offset …` for binary STL. Never panics.
    pub fn parse(bytes: &[u8], file: &str, obj: bool) -> Result<TriMesh> {
        if obj {
            obj::parse(bytes, file)
        } else {
            stl::parse(bytes, file)
        }
    }

    /// The mesh of `tris` ([`crate::mesh::Tri`]), equal coordinates welded.
    pub fn from_tris(tris: &[Tri]) -> TriMesh {
        let mut w = Welder::default();
        for t in tris {
            let t = t.map(|p| DVec3::from(p.map(f64::from)));
            // Fails only past 2^32 distinct vertices; the rest are dropped then.
            if w.triangle(t).is_err() {
                break;
            }
        }
        w.mesh
    }

    /// The mesh of triangles in f64, equal coordinates welded.
    pub fn from_f64(tris: &[[[f64; 3]; 3]]) -> TriMesh {
        let mut w = Welder::default();
        for t in tris {
            // Fails only past 2^32 distinct vertices; the rest are dropped then.
            if w.triangle(t.map(DVec3::from)).is_err() {
                break;
            }
        }
        w.mesh
    }

    /// Smallest and largest coordinates of the vertices; `(+∞, -∞)` for no vertices.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.vertices
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            })
    }

    /// The mesh under the affine map `m` (`transform_point3`). A mirroring `m` (negative
    /// determinant) also reverses every triangle so outward faces stay outward.
    pub fn transformed(&self, m: DMat4) -> TriMesh {
        let flip = DMat3::from_mat4(m).determinant() < 0.0;
        TriMesh {
            vertices: self
                .vertices
                .iter()
                .map(|&v| m.transform_point3(v))
                .collect(),
            triangles: self
                .triangles
                .iter()
                .map(|&[a, b, c]| if flip { [a, c, b] } else { [a, b, c] })
                .collect(),
        }
    }

    /// Ok when the mesh bounds a solid: every undirected edge belongs to an even number of
    /// triangles (two, or four where two solids touch along an edge, as OpenSCAD's own meshes
    /// often have: the parity of ray crossings is then still the inside), after dropping
    /// degenerate triangles (a repeated vertex index). Refuses an empty mesh and indices past
    /// the vertices. The error is one line starting `FILE:`.
    pub fn check_closed(&self, file: &str) -> Result<()> {
        let tris = self.proper_triangles(file)?;
        match self.open_edges(&tris) {
            None => Ok(()),
            Some(open) => Err(Error::NotClosed { open }.context(file)),
        }
    }

    /// What [`TriMesh::check_closed`] finds open, without its advice: `None` when closed,
    /// else `N edges belong to one triangle (first from (…) to (…)), M to another odd
    /// number`. Errors as [`TriMesh::check_closed`] for a mesh without proper triangles.
    pub fn open_edges_summary(&self, file: &str) -> Result<Option<String>> {
        let tris = self.proper_triangles(file)?;
        Ok(self.open_edges(&tris))
    }

    /// The open edges of `tris` (proper triangles of this mesh) in words, if any.
    fn open_edges(&self, tris: &[[u32; 3]]) -> Option<String> {
        // Each undirected edge with how many triangles use it, by sorting (not hashing) the
        // edges as one number each, in the order of (lower, higher) corner.
        let key = |(a, b): (u32, u32)| (u64::from(a) << 32) | u64::from(b);
        let mut all: Vec<u64> = tris
            .iter()
            .flat_map(edges)
            .map(|e| key(undirected(e)))
            .collect();
        all.sort_unstable();
        let mut uses: Vec<(u64, u32)> = Vec::with_capacity(all.len() / 2 + 1);
        for e in all {
            match uses.last_mut() {
                Some((last, n)) if *last == e => *n += 1,
                _ => uses.push((e, 1)),
            }
        }
        let uses_of = |e: (u32, u32)| {
            let k = key(e);
            uses.binary_search_by_key(&k, |u| u.0)
                .map_or(0, |i| uses[i].1)
        };
        let count = |f: fn(u32) -> bool| uses.iter().filter(|u| f(u.1)).count();
        let (open, many) = (count(|n| n == 1), count(|n| n > 2 && n % 2 == 1));
        if open == 0 && many == 0 {
            return None;
        }
        // The first offending edge in triangle order (deterministic), of the first kind found.
        let first = |f: fn(u32) -> bool| {
            let (a, b) = tris
                .iter()
                .flat_map(edges)
                .find(|&e| f(uses_of(undirected(e))))
                .unwrap_or_default();
            let (a, b) = (self.vertices[a as usize], self.vertices[b as usize]);
            format!(
                " (first from ({},{},{}) to ({},{},{}))",
                a.x, a.y, a.z, b.x, b.y, b.z
            )
        };
        let (first_open, first_many) = if open > 0 {
            (first(|n| n == 1), String::new())
        } else {
            (String::new(), first(|n| n > 2 && n % 2 == 1))
        };
        Some(format!(
            "{open} edges belong to one triangle{first_open}, {many} to another odd \
             number{first_many}"
        ))
    }

    /// The triangles without a repeated index; errors for an index past the vertices or
    /// when none is left.
    pub(crate) fn proper_triangles(&self, file: &str) -> Result<Vec<[u32; 3]>> {
        let n = self.vertices.len();
        if let Some((k, i)) = self
            .triangles
            .iter()
            .enumerate()
            .find_map(|(k, t)| t.iter().find(|&&i| i as usize >= n).map(|&i| (k, i)))
        {
            let e = Error::NoSuchVertex {
                triangle: k,
                vertex: i,
                count: n,
            };
            return Err(e.context(file));
        }
        let tris: Vec<[u32; 3]> = self
            .triangles
            .iter()
            .filter(|[a, b, c]| a != b && b != c && c != a)
            .copied()
            .collect();
        if tris.is_empty() {
            let degenerate = self.triangles.len();
            return Err(Error::NoTriangles { degenerate }.context(file));
        }
        Ok(tris)
    }

    /// For each pixel `(x, y)` of a `w`×`h` image (index `y·w + x`), the sorted depths at
    /// which the line `{(x, y, z)}` crosses the surface, in the coordinates `to_frame` maps
    /// scene points to (pixel x, pixel y, depth; called once per vertex). For a closed mesh
    /// each list has even length and its pairs `(d0,d1), (d2,d3), …` are the depth intervals
    /// inside the solid (§3.4.2: parity from `-∞`, so a solid that starts before the region
    /// needs no separate 0th slice).
    ///
    /// Exactness (§4.4): projected x and y are rounded to multiples of 2^-16 pixel (error at
    /// most 2^-17 pixel; coordinates beyond ±2^31 pixels are clamped there), and a pixel
    /// centre is covered by a triangle when the exact integer edge functions of the
    /// counter-clockwise projected triangle are positive at the centre moved by an
    /// infinitesimal `(ε, ε²)` (`Edge::covers`). The moved point lies on no projected edge,
    /// so a ray through a shared edge or vertex counts one crossing where the surface passes
    /// and zero or two where it grazes, triangles seen edge-on count nothing, and a ray along
    /// a face follows the half-open convention (a box `[x0, x1)` covers pixel `x0`, not
    /// `x1`). Depths interpolate the unsnapped depth of the vertices barycentrically.
    ///
    /// Cost: one `Vec` per pixel (24 bytes each, plus 8 per crossing, plus 16 per crossing
    /// while collecting; [`TriMesh::crossings_flat_in`] holds 8 a pixel instead); time proportional to the triangles' clamped pixel bounding boxes.
    /// Triangles are rasterized in parallel; the result does not depend on the threads.
    /// Triangles with an index past the vertices are skipped.
    pub fn crossings(
        &self,
        to_frame: impl Fn(DVec3) -> DVec3,
        w: usize,
        h: usize,
    ) -> Vec<Vec<f64>> {
        self.crossings_in(to_frame, Window { x0: 0, y0: 0, w, h })
    }

    /// [`TriMesh::crossings`] for the pixels of `win` only (index `(y − y0)·w + (x − x0)`):
    /// the same lists those pixels have in the whole image, so a primitive's crossings can be
    /// kept over its own footprint (`crates/voxel/src/runs.rs`).
    pub fn crossings_in(&self, to_frame: impl Fn(DVec3) -> DVec3, win: Window) -> Vec<Vec<f64>> {
        let flat = self.crossings_flat_in(to_frame, win);
        (0..flat.pixels()).map(|i| flat.pixel(i).to_vec()).collect()
    }

    /// [`TriMesh::crossings_in`] as one buffer: no `Vec` per pixel (8 bytes a pixel and 8 a
    /// crossing, plus 16 per crossing while collecting). The depths are placed by a counting
    /// sort whose cursors are the pixels' starts themselves, and put in order by chunks of
    /// pixels: nothing more a pixel, even for a moment.
    pub fn crossings_flat_in(&self, to_frame: impl Fn(DVec3) -> DVec3, win: Window) -> Crossings {
        let (w, h) = (win.w, win.h);
        let projected: Vec<Projected> = self
            .vertices
            .iter()
            .map(|&v| Projected::of(to_frame(v)))
            .collect();
        let tris: Vec<Raster> = self
            .triangles
            .iter()
            .filter_map(|t| Raster::new(t, &projected))
            .collect();
        let hits: Vec<Vec<(usize, f64)>> = tris
            .par_chunks(256)
            .map(|chunk| {
                let mut out = Vec::with_capacity(chunk.iter().map(|t| t.pixels_hint(win)).sum());
                for t in chunk {
                    t.rasterize(win, &mut out);
                }
                out
            })
            .collect();
        // A counting sort by pixel, then each pixel's depths in order.
        let n = w.saturating_mul(h);
        let mut start = vec![0usize; n + 1];
        for &(i, _) in hits.iter().flatten() {
            start[i + 1] += 1;
        }
        for i in 1..start.len() {
            start[i] += start[i - 1];
        }
        let mut depths = vec![0.0; start[n]];
        // `start[i]` is pixel i's cursor while the depths are placed: after, it is where
        // pixel i + 1 starts, and the list is shifted back one place.
        for &(i, d) in hits.iter().flatten() {
            depths[start[i]] = d;
            start[i] += 1;
        }
        drop(hits);
        start.copy_within(0..n, 1);
        start[0] = 0;
        sort_pixels(&start, &mut depths);
        let out = Crossings { start, depths };
        #[cfg(debug_assertions)]
        if self.check_closed("").is_ok() {
            debug_assert!((0..out.pixels()).all(|i| out.pixel(i).len().is_multiple_of(2)));
        }
        out
    }
}

/// Each pixel's depths in `depths` (pixel i's at `start[i]..start[i + 1]`) put in order, by
/// chunks of pixels in parallel. Most pixels hold two (a mesh's front and back).
fn sort_pixels(start: &[usize], depths: &mut [f64]) {
    const CHUNK: usize = 4096;
    let n = start.len() - 1;
    let mut pieces = Vec::with_capacity(n.div_ceil(CHUNK));
    let mut rest = depths;
    for c in (0..n).step_by(CHUNK) {
        let e = (c + CHUNK).min(n);
        let (this, tail) = rest.split_at_mut(start[e] - start[c]);
        pieces.push((c..e, this));
        rest = tail;
    }
    pieces.into_par_iter().for_each(|(pixels, piece)| {
        let base = start[pixels.start];
        for i in pixels {
            let p = &mut piece[start[i] - base..start[i + 1] - base];
            match p.len() {
                0 | 1 => {}
                2 => {
                    if p[0].total_cmp(&p[1]).is_gt() {
                        p.swap(0, 1);
                    }
                }
                _ => p.sort_unstable_by(f64::total_cmp),
            }
        }
    });
}

/// Per pixel of a window, the depths where its ray crosses a mesh, in order
/// ([`TriMesh::crossings_flat_in`]): pixel i's are `depths[start[i]..start[i + 1]]`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Crossings {
    start: Vec<usize>,
    depths: Vec<f64>,
}

impl Crossings {
    /// Pixels in the window.
    pub fn pixels(&self) -> usize {
        self.start.len().saturating_sub(1)
    }

    /// Pixel i's crossings, in order.
    pub fn pixel(&self, i: usize) -> &[f64] {
        &self.depths[self.start[i]..self.start[i + 1]]
    }
}

/// The three directed edges of a triangle.
pub(crate) fn edges(t: &[u32; 3]) -> [(u32, u32); 3] {
    [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
}

fn undirected((a, b): (u32, u32)) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Fixed-point fraction bits of projected x and y: multiples of 2^-16 pixel.
pub(crate) const FRAC_BITS: u32 = 16;
/// Projected x and y are clamped to ±2^31 pixels, so products of coordinate differences
/// (< 2^96) fit an `i128` with room.
const LIMIT: f64 = 2_147_483_648.0;

/// A vertex in the frame: x and y snapped to fixed point, depth as is.
#[derive(Clone, Copy)]
pub(crate) struct Projected {
    pub(crate) x: i64,
    pub(crate) y: i64,
    pub(crate) z: f64,
}

impl Projected {
    pub(crate) fn of(f: DVec3) -> Projected {
        // Scaling by 2^16 is exact; rounding errs by at most half a step (2^-17 pixel). A
        // NaN becomes 0 (`as` saturates), consistently for every triangle of the vertex.
        let snap = |c: f64| (c.clamp(-LIMIT, LIMIT) * f64::from(1u32 << FRAC_BITS)).round() as i64;
        Projected {
            x: snap(f.x),
            y: snap(f.y),
            z: f.z,
        }
    }
}

/// One edge of a counter-clockwise projected triangle, as its edge function
/// `E(p) = (b - a) × (p - a)`, positive inside (§5.3.1: the plane through the edge
/// perpendicular to the screen).
#[derive(Clone, Copy)]
pub(crate) struct Edge {
    ax: i64,
    ay: i64,
    dx: i64,
    dy: i64,
}

impl Edge {
    pub(crate) fn new(a: Projected, b: Projected) -> Edge {
        Edge {
            ax: a.x,
            ay: a.y,
            dx: b.x - a.x,
            dy: b.y - a.y,
        }
    }

    /// The exact edge function at `(px, py)`.
    pub(crate) fn at(&self, px: i64, py: i64) -> i128 {
        i128::from(self.dx) * i128::from(py - self.ay)
            - i128::from(self.dy) * i128::from(px - self.ax)
    }

    /// Whether `p + (ε, ε²)` is on the inner side for an infinitesimal ε > 0, given
    /// `e = E(p)`: `E(p + (ε, ε²)) = e - ε·dy + ε²·dx`, so on the edge the sign is that of
    /// `-dy`, or of `dx` for a horizontal edge (the top-left rule). Being the sign of the edge
    /// function at one perturbed point, it is consistent across edges and at vertices.
    fn covers(&self, e: i128) -> bool {
        e > 0 || (e == 0 && (self.dy < 0 || (self.dy == 0 && self.dx > 0)))
    }
}

impl Edge {
    /// The steps k (pixels along a row from a pixel where the edge function is `f`; it is
    /// f − k·`s` at step k, `s` = dy·2^16) that [`Edge::covers`] accepts, as an interval
    /// (empty when lo > hi). Covered means f − k·s ≥ t, with t = 0 where the top-left rule
    /// takes the edge itself and 1 where it does not: a bound by floor division.
    fn span(&self, f: i128, s: i128) -> (i128, i128) {
        let t = i128::from(!self.covers(0));
        match s.signum() {
            0 if f >= t => (i128::MIN, i128::MAX),
            0 => (1, 0),
            1 => (i128::MIN, (f - t).div_euclid(s)),
            _ => (-((f - t).div_euclid(-s)), i128::MAX),
        }
    }

    /// The sign (−1, 0 or 1) of the edge function at `p + (ε, ε²)`, the point
    /// [`Edge::covers`] decides: 0 only for an edge of no projected length.
    pub(crate) fn side(&self, px: i64, py: i64) -> i32 {
        let e = self.at(px, py);
        let s = match (e.signum(), self.dy.signum(), self.dx.signum()) {
            (0, 0, dx) => dx,
            (0, dy, _) => -dy,
            (e, _, _) => e as i64,
        };
        s as i32
    }
}

/// A triangle ready to rasterize: counter-clockwise, nonzero projected area.
pub(crate) struct Raster {
    edges: [Edge; 3],
    /// Whether the triangle as given ran clockwise in the frame (and was turned over).
    pub(crate) flipped: bool,
    /// Depths of the vertices opposite each edge (edge `i` is `v[i] → v[i+1]`, opposite
    /// `v[i+2]`).
    z: [f64; 3],
    area: f64,
    lo: (i64, i64),
    hi: (i64, i64),
}

impl Raster {
    /// `None` for an edge-on triangle (zero projected area) or an index past the vertices.
    pub(crate) fn new(t: &[u32; 3], p: &[Projected]) -> Option<Raster> {
        let v = |i: u32| p.get(i as usize).copied();
        let (a, mut b, mut c) = (v(t[0])?, v(t[1])?, v(t[2])?);
        let area = Edge::new(a, b).at(c.x, c.y);
        if area == 0 {
            return None;
        }
        if area < 0 {
            std::mem::swap(&mut b, &mut c);
        }
        Some(Raster {
            edges: [Edge::new(a, b), Edge::new(b, c), Edge::new(c, a)],
            flipped: area < 0,
            z: [c.z, a.z, b.z],
            area: area.unsigned_abs() as f64,
            lo: (a.x.min(b.x).min(c.x), a.y.min(b.y).min(c.y)),
            hi: (a.x.max(b.x).max(c.x), a.y.max(b.y).max(c.y)),
        })
    }

    /// About how many pixel centres of `win` the triangle covers, never many fewer: its
    /// area plus half its perimeter plus one, in pixels (a convex set holds at most that many
    /// lattice points), or its bounding box within `win` when that is smaller. A capacity for
    /// [`Raster::rasterize`]'s output, so the hits are not copied as they grow.
    pub(crate) fn pixels_hint(&self, win: Window) -> usize {
        let Some((x0, x1)) = pixel_span(self.lo.0, self.hi.0, win.x0, win.w) else {
            return 0;
        };
        let Some((y0, y1)) = pixel_span(self.lo.1, self.hi.1, win.y0, win.h) else {
            return 0;
        };
        let one = f64::from(1u32 << FRAC_BITS);
        let perimeter: f64 = self
            .edges
            .iter()
            .map(|e| (e.dx as f64).hypot(e.dy as f64))
            .sum();
        let bound = self.area / 2.0 / (one * one) + perimeter / one / 2.0 + 1.0;
        let bbox = (x1 - x0 + 1) as f64 * (y1 - y0 + 1) as f64;
        bound.min(bbox) as usize
    }

    /// Appends `(pixel index in win, depth)` for every covered pixel centre of `win`.
    ///
    /// Along a row each edge function falls by `dy` per pixel ([`Edge::at`] is linear), so
    /// the pixels an edge covers are an interval found by one division ([`Edge::span`]); a
    /// row visits only the pixels of all three intervals, and the values, the coverage and
    /// the depths are those of `depth_at` (the tests' reference) at every pixel.
    pub(crate) fn rasterize(&self, win: Window, out: &mut Vec<(usize, f64)>) {
        let Some((x0, x1)) = pixel_span(self.lo.0, self.hi.0, win.x0, win.w) else {
            return;
        };
        let Some((y0, y1)) = pixel_span(self.lo.1, self.hi.1, win.y0, win.h) else {
            return;
        };
        let (wx, wy) = (win.x0 as i64, win.y0 as i64);
        let step = self.edges.map(|e| i128::from(e.dy) << FRAC_BITS);
        for y in y0..=y1 {
            let f0 = self.edges.map(|e| e.at(x0 << FRAC_BITS, y << FRAC_BITS));
            let (mut a, mut b) = (0i128, i128::from(x1 - x0));
            for ((e, &f), &s) in self.edges.iter().zip(&f0).zip(&step) {
                let (lo, hi) = e.span(f, s);
                (a, b) = (a.max(lo), b.min(hi));
            }
            if a > b {
                continue;
            }
            // a and b lie in 0..=x1 - x0 here.
            let (a, b) = (a as i64, b as i64);
            let mut f = self
                .edges
                .map(|e| e.at((x0 + a) << FRAC_BITS, y << FRAC_BITS));
            let row = (y - wy) as usize * win.w;
            for x in x0 + a..=x0 + b {
                debug_assert!(self.edges.iter().zip(&f).all(|(e, &v)| e.covers(v)));
                out.push((row + (x - wx) as usize, self.depth_of(f)));
                for (v, s) in f.iter_mut().zip(&step) {
                    *v -= s;
                }
            }
        }
    }

    /// The depth of the triangle's plane where the edge functions are `f` (a covered point):
    /// the vertices' depths weighted by the barycentric weights f / area.
    fn depth_of(&self, f: [i128; 3]) -> f64 {
        let mut d = 0.0;
        for (&f, z) in f.iter().zip(self.z) {
            // Barycentric weight of the opposite vertex: in [0, 1] by construction.
            d += z * (to_f64(f) / self.area);
        }
        d
    }

    /// The depth of the triangle's plane at fixed-point `(px, py)` when the point is covered.
    #[cfg(test)]
    fn depth_at(&self, px: i64, py: i64) -> Option<f64> {
        let f = self.edges.map(|e| e.at(px, py));
        let covered = self.edges.iter().zip(&f).all(|(e, &v)| e.covers(v));
        covered.then(|| self.depth_of(f))
    }
}

/// `v` rounded to the nearest f64, as `v as f64`; through i64 where it fits, whose
/// conversion is one instruction and rounds the same value the same way. The wide case is
/// a call of its own: with both arms `as f64`, the optimiser sees them equal and makes the
/// whole match one call of the i128 conversion (`__floattidf`).
fn to_f64(v: i128) -> f64 {
    match i64::try_from(v) {
        Ok(v) => v as f64,
        Err(_) => wide_to_f64(v),
    }
}

#[cold]
#[inline(never)]
fn wide_to_f64(v: i128) -> f64 {
    v as f64
}

/// Pixel indices `[first, last]` within `0..n` whose centres lie in fixed-point `[lo, hi]`.
fn pixel_span(lo: i64, hi: i64, start: usize, n: usize) -> Option<(i64, i64)> {
    let one = 1i64 << FRAC_BITS;
    let start = i64::try_from(start).unwrap_or(i64::MAX);
    let end = start.saturating_add(i64::try_from(n).unwrap_or(i64::MAX));
    let first = (-((-lo).div_euclid(one))).max(start);
    let last = hi.div_euclid(one).min(end - 1);
    (first <= last).then_some((first, last))
}

/// A rectangle of pixels: columns `x0..x0 + w`, rows `y0..y0 + h`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// First column.
    pub x0: usize,
    /// First row.
    pub y0: usize,
    /// Columns.
    pub w: usize,
    /// Rows.
    pub h: usize,
}

/// Words of a text, with their 1-based line and column.
mod text {
    /// A whitespace-separated word and where it starts.
    #[derive(Clone, Copy)]
    pub struct Word<'a> {
        pub text: &'a [u8],
        pub line: usize,
        pub col: usize,
    }

    /// Words of one line, with 1-based byte columns.
    pub fn line_words(line: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
        let mut i = 0;
        std::iter::from_fn(move || {
            while line.get(i).is_some_and(u8::is_ascii_whitespace) {
                i += 1;
            }
            let start = i;
            while line.get(i).is_some_and(|b| !b.is_ascii_whitespace()) {
                i += 1;
            }
            (i > start).then(|| (start + 1, &line[start..i]))
        })
    }

    /// All words of `bytes`, line by line.
    pub fn words(bytes: &[u8]) -> impl Iterator<Item = Word<'_>> {
        bytes.split(|&b| b == b'\n').enumerate().flat_map(|(i, l)| {
            line_words(l).map(move |(col, text)| Word {
                text,
                line: i + 1,
                col,
            })
        })
    }

    /// A word for messages: lossy UTF-8, at most 40 characters.
    pub fn show(w: &[u8]) -> String {
        let s = String::from_utf8_lossy(w);
        match s.char_indices().nth(40) {
            Some((i, _)) => format!("{}…", &s[..i]),
            None => s.into_owned(),
        }
    }

    /// The number a word spells, if finite.
    pub fn finite(w: &[u8]) -> Option<f64> {
        std::str::from_utf8(w)
            .ok()?
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
    }
}

/// STL, binary and ASCII.
mod stl {
    use std::iter::Peekable;

    use glam::DVec3;

    use super::text::{finite, show, words, Word};
    use super::{TriMesh, Welder};
    use crate::{Error, Result};

    /// ASCII when it starts with `solid` and reads as ASCII, binary otherwise. A file that
    /// starts with `solid` and does not read as ASCII gets the ASCII error (with its line and
    /// column, a stray byte included) unless it looks binary: its length is exactly a binary
    /// STL's, 84 + 50·n for the count in its header, or it holds a NUL byte, which text never
    /// does and a binary STL's count and attribute words nearly always do (some binary headers
    /// start with `solid` too).
    pub fn parse(bytes: &[u8], file: &str) -> Result<TriMesh> {
        if bytes.trim_ascii_start().starts_with(b"solid") {
            match ascii(bytes, file) {
                Ok(m) => return Ok(m),
                Err(e) if !binary_length_fits(bytes) && !bytes.contains(&0) => return Err(e),
                Err(_) => {}
            }
        }
        binary(bytes, file)
    }

    /// The triangle count of the header, if there is a header.
    fn count(bytes: &[u8]) -> Option<u64> {
        let n: [u8; 4] = bytes.get(80..84)?.try_into().ok()?;
        Some(u64::from(u32::from_le_bytes(n)))
    }

    fn binary_length_fits(bytes: &[u8]) -> bool {
        count(bytes).is_some_and(|n| 84 + 50 * n == bytes.len() as u64)
    }

    /// 80-byte header, u32 count, then per triangle a normal, three vertices (f32 LE) and a
    /// 2-byte attribute. Bytes past the last triangle are ignored.
    fn binary(bytes: &[u8], file: &str) -> Result<TriMesh> {
        let len = bytes.len() as u64;
        let n = count(bytes).ok_or_else(|| Error::StlHeaderTruncated { len }.context(file))?;
        if len < 84 + 50 * n {
            let k = (len - 84) / 50;
            let e = Error::StlTruncated {
                len,
                triangles: n,
                needs: 84 + 50 * n,
                incomplete: k,
                offset: 84 + 50 * k,
            };
            return Err(e.context(file));
        }
        let mut w = Welder::default();
        for (k, rec) in bytes[84..].chunks_exact(50).take(n as usize).enumerate() {
            let t = [0, 1, 2].map(|i| vertex(&rec[12 + 12 * i..24 + 12 * i]));
            match t {
                [Some(a), Some(b), Some(c)] => w.triangle([a, b, c]),
                _ => Err(Error::NonFiniteTriangle {
                    triangle: k,
                    offset: 84 + 50 * k,
                }),
            }
            .map_err(|e| e.context("binary STL").context(file))?;
        }
        Ok(w.mesh)
    }

    /// Three little-endian f32 (12 bytes), if finite.
    fn vertex(b: &[u8]) -> Option<DVec3> {
        let c = |i: usize| -> Option<f64> {
            let v = f32::from_le_bytes(b.get(4 * i..4 * i + 4)?.try_into().ok()?);
            v.is_finite().then_some(f64::from(v))
        };
        Some(DVec3::new(c(0)?, c(1)?, c(2)?))
    }

    type Words<'a> = Peekable<Box<dyn Iterator<Item = Word<'a>> + 'a>>;

    /// Reads `solid name`, facets, `endsolid name`, possibly several solids.
    fn ascii(bytes: &[u8], file: &str) -> Result<TriMesh> {
        let mut p = Ascii {
            words: (Box::new(words(bytes)) as Box<dyn Iterator<Item = Word>>).peekable(),
            file,
            end: end_of(bytes),
            welder: Welder::default(),
        };
        p.solid()?;
        while let Some(w) = p.words.next() {
            match w.text.to_ascii_lowercase().as_slice() {
                b"facet" => p.facet(w)?,
                b"endsolid" => {
                    p.skip_line(w.line);
                    if p.words.peek().is_some() {
                        p.solid()?;
                    } else {
                        return Ok(p.welder.mesh);
                    }
                }
                _ => return Err(p.error(w, "`facet` or `endsolid`")),
            }
        }
        Err(p.at_end("`facet` or `endsolid`"))
    }

    /// Line and column just past the last byte.
    fn end_of(bytes: &[u8]) -> (usize, usize) {
        let line = bytes.iter().filter(|&&b| b == b'\n').count() + 1;
        let last = bytes.rsplit(|&b| b == b'\n').next().unwrap_or_default();
        (line, last.len() + 1)
    }

    struct Ascii<'a> {
        words: Words<'a>,
        file: &'a str,
        end: (usize, usize),
        welder: Welder,
    }

    /// `expected WHAT, found FOUND`.
    fn expected(what: &str, found: String) -> Error {
        Error::Expected {
            expected: what.to_string(),
            found,
        }
    }

    impl<'a> Ascii<'a> {
        fn error(&self, w: Word, what: &str) -> Error {
            let found = format!("`{}`", show(w.text));
            Error::at(self.file, w.line, w.col, expected(what, found))
        }

        fn at_end(&self, what: &str) -> Error {
            let (l, c) = self.end;
            let found = "the end of the file";
            Error::at(self.file, l, c, expected(what, found.to_string()))
        }

        fn next(&mut self, what: &str) -> Result<Word<'a>> {
            self.words.next().ok_or_else(|| self.at_end(what))
        }

        fn keyword(&mut self, k: &str) -> Result<Word<'a>> {
            let w = self.next(&format!("`{k}`"))?;
            if w.text.eq_ignore_ascii_case(k.as_bytes()) {
                Ok(w)
            } else {
                Err(self.error(w, &format!("`{k}`")))
            }
        }

        fn number(&mut self) -> Result<f64> {
            let w = self.next("a number")?;
            finite(w.text).ok_or_else(|| self.error(w, "a finite number"))
        }

        fn skip_line(&mut self, line: usize) {
            while self.words.next_if(|w| w.line == line).is_some() {}
        }

        /// `solid` and the rest of its line (the name).
        fn solid(&mut self) -> Result<()> {
            let w = self.keyword("solid")?;
            self.skip_line(w.line);
            Ok(())
        }

        /// `facet normal n n n outer loop (vertex x y z)×3 endloop endfacet`, after `facet`.
        fn facet(&mut self, facet: Word) -> Result<()> {
            self.keyword("normal")?;
            for _ in 0..3 {
                self.number()?;
            }
            self.keyword("outer")?;
            self.keyword("loop")?;
            let mut v = Vec::with_capacity(3);
            loop {
                let w = self.next("`vertex` or `endloop`")?;
                if w.text.eq_ignore_ascii_case(b"endloop") {
                    break;
                }
                if !w.text.eq_ignore_ascii_case(b"vertex") {
                    return Err(self.error(w, "`vertex` or `endloop`"));
                }
                v.push(DVec3::new(self.number()?, self.number()?, self.number()?));
            }
            let [a, b, c] = v[..] else {
                let vertices = v.len();
                let e = Error::FacetVertices { vertices };
                return Err(e.located(self.file, facet.line, facet.col));
            };
            self.keyword("endfacet")?;
            self.welder
                .triangle([a, b, c])
                .map_err(|e| e.located(self.file, facet.line, facet.col))
        }
    }
}

/// Wavefront OBJ: vertices and faces.
mod obj {
    use glam::DVec3;

    use super::text::{finite, line_words, show};
    use super::{TriMesh, Welder};
    use crate::{Error, Result};

    /// Reads `v` and `f` statements, ignoring the others; comments start with `#`.
    pub fn parse(bytes: &[u8], file: &str) -> Result<TriMesh> {
        let mut vs: Vec<DVec3> = Vec::new();
        let mut w = Welder::default();
        for (i, line) in bytes.split(|&b| b == b'\n').enumerate() {
            let line = line.split(|&b| b == b'#').next().unwrap_or_default();
            let mut words = line_words(line);
            let at = |col: usize, e: Error| e.located(file, i + 1, col);
            match words.next() {
                Some((_, b"v")) => {
                    vs.push(vertex(&mut words, line.len() + 1).map_err(|(c, e)| at(c, e))?)
                }
                Some((col, b"f")) => {
                    face(&mut words, col, &vs, &mut w).map_err(|(c, e)| at(c, e))?
                }
                _ => {}
            }
        }
        Ok(w.mesh)
    }

    type Located = (usize, Error);

    /// `x y z` (further numbers, such as w or a colour, are ignored).
    fn vertex<'a>(
        words: &mut impl Iterator<Item = (usize, &'a [u8])>,
        end: usize,
    ) -> Result<DVec3, Located> {
        let mut c = [0.0; 3];
        for (k, c) in c.iter_mut().enumerate() {
            let (col, w) = words.next().ok_or((
                end,
                Error::Needs {
                    what: "a vertex",
                    needs: "3 coordinates",
                    found: k,
                },
            ))?;
            *c = finite(w).ok_or_else(|| {
                (
                    col,
                    Error::Expected {
                        expected: "a finite number".into(),
                        found: format!("`{}`", show(w)),
                    },
                )
            })?;
        }
        Ok(DVec3::from(c))
    }

    /// A polygon of at least 3 vertex references, fan-triangulated from its first vertex.
    fn face<'a>(
        words: &mut impl Iterator<Item = (usize, &'a [u8])>,
        col: usize,
        vs: &[DVec3],
        w: &mut Welder,
    ) -> Result<(), Located> {
        let refs = words
            .map(|(c, r)| reference(r, vs.len()).map_err(|e| (c, e)))
            .collect::<Result<Vec<usize>, Located>>()?;
        if refs.len() < 3 {
            return Err((
                col,
                Error::Needs {
                    what: "a face",
                    needs: "at least 3 vertices",
                    found: refs.len(),
                },
            ));
        }
        for k in 1..refs.len() - 1 {
            let t = [refs[0], refs[k], refs[k + 1]].map(|r| vs[r]);
            w.triangle(t).map_err(|e| (col, e))?;
        }
        Ok(())
    }

    /// The 0-based vertex of `a`, `a/t`, `a/t/n` or `a//n`, given `n` vertices so far.
    pub(super) fn reference(r: &[u8], n: usize) -> Result<usize> {
        let a = r.split(|&b| b == b'/').next().unwrap_or_default();
        let i: i64 = std::str::from_utf8(a)
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| Error::Expected {
                expected: "a vertex index".into(),
                found: format!("`{}`", show(r)),
            })?;
        let k = match i {
            1.. => usize::try_from(i - 1).ok().filter(|&k| k < n),
            ..=-1 => usize::try_from(n as i64 + i).ok(),
            0 => None,
        };
        k.ok_or(Error::VertexIndex {
            index: i,
            defined: n,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: i64, y: i64) -> Projected {
        Projected {
            x: x << FRAC_BITS,
            y: y << FRAC_BITS,
            z: 0.0,
        }
    }

    /// `to_f64` rounds as `as f64` does, on both sides of the i64 range it takes the short
    /// way in.
    #[test]
    fn to_f64_rounds_as_the_i128_conversion() {
        let edge = [i128::from(i64::MAX), i128::from(i64::MIN)];
        let mut values = vec![0, 1, -1, (1 << 100) + 12345, -(1 << 90) - 7];
        values.extend([i128::MAX, i128::MIN, (1 << 53) + 1, -(1 << 60) - 3]);
        for e in edge {
            values.extend((-3..=3).map(|d| e + d));
        }
        for v in values {
            assert_eq!(to_f64(v).to_bits(), (v as f64).to_bits(), "{v}");
        }
    }

    proptest::proptest! {
        /// `rasterize`, which steps the edge functions along each row, gives at every pixel
        /// of the window what `depth_at` gives there from scratch: the same pixels, the same
        /// depths to the bit. Corners span small offsets to 2^30 pixels, so edge functions
        /// past i64 (the conversion's other path) are among them.
        #[test]
        fn rasterize_agrees_with_depth_at_at_every_pixel(
            c in proptest::collection::vec((-40.0f64..40.0, -40.0f64..40.0, -9.0f64..9.0), 3),
            scale in proptest::sample::select(vec![1.0, 1.0, 1e3, 1e8, 1.07e9]),
            win in (0usize..30, 0usize..30, 1usize..40, 1usize..40),
        ) {
            let v: Vec<Projected> =
                c.iter().map(|&(x, y, z)| Projected::of(DVec3::new(x * scale, y * scale, z))).collect();
            let Some(r) = Raster::new(&[0, 1, 2], &v) else { return Ok(()); };
            let win = Window { x0: win.0, y0: win.1, w: win.2, h: win.3 };
            let mut got = vec![];
            r.rasterize(win, &mut got);
            let mut want = vec![];
            for y in 0..win.h {
                for x in 0..win.w {
                    let (px, py) = ((x + win.x0) as i64, (y + win.y0) as i64);
                    if let Some(d) = r.depth_at(px << FRAC_BITS, py << FRAC_BITS) {
                        want.push((y * win.w + x, d.to_bits()));
                    }
                }
            }
            let got: Vec<(usize, u64)> = got.iter().map(|&(i, d)| (i, d.to_bits())).collect();
            proptest::prop_assert_eq!(got, want);
        }
    }

    /// How many of the triangles (given by their projected corners) cover the origin.
    fn covering(tris: &[[Projected; 3]]) -> usize {
        let verts: Vec<Projected> = tris.iter().flatten().copied().collect();
        (0..tris.len() as u32)
            .filter_map(|k| Raster::new(&[3 * k, 3 * k + 1, 3 * k + 2], &verts))
            .filter(|r| r.depth_at(0, 0).is_some())
            .count()
    }

    #[test]
    fn a_fan_around_a_vertex_covers_it_once() {
        // Eight triangles around the origin, both orientations mixed.
        let ring = [
            (1, 0),
            (1, 1),
            (0, 1),
            (-1, 1),
            (-1, 0),
            (-1, -1),
            (0, -1),
            (1, -1),
        ];
        let tris: Vec<[Projected; 3]> = (0..8)
            .map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % 8]);
                let t = [p(0, 0), p(a.0, a.1), p(b.0, b.1)];
                if i % 3 == 0 {
                    [t[0], t[2], t[1]]
                } else {
                    t
                }
            })
            .collect();
        assert_eq!(covering(&tris), 1);
        // A fold at the vertex (a silhouette): half the fan in front, the same half-plane
        // triangulated differently behind. Near the vertex both sheets cover the same
        // sector, so the count is 0 or 2 whichever the half.
        let q = |i: usize| p(ring[i % 8].0, ring[i % 8].1);
        for s in 0..8 {
            let mut fold: Vec<[Projected; 3]> = (s..s + 4).map(|i| tris[i % 8]).collect();
            fold.push([p(0, 0), q(s + 2), q(s)]);
            fold.push([p(0, 0), q(s + 4), q(s + 2)]);
            assert_eq!(covering(&fold) % 2, 0, "start {s}");
        }
    }

    #[test]
    fn a_shared_edge_through_the_centre_counts_once() {
        for (a, b) in [
            ((-2, 0), (2, 0)),
            ((0, -2), (0, 2)),
            ((-2, -2), (2, 2)),
            ((-1, 2), (1, -2)),
        ] {
            let (a, b) = (p(a.0, a.1), p(b.0, b.1));
            // Apexes on either side of the edge.
            let n = (b.y - a.y, a.x - b.x);
            let side = |s: i64| Projected {
                x: s * n.0,
                y: s * n.1,
                z: 0.0,
            };
            assert_eq!(covering(&[[a, b, side(1)], [b, a, side(-1)]]), 1);
            // Both on one side (a fold seen edge-first): even.
            assert_eq!(covering(&[[a, b, side(1)], [b, a, side(2)]]) % 2, 0);
        }
    }

    #[test]
    fn edge_on_triangles_count_nothing() {
        assert!(Raster::new(&[0, 1, 2], &[p(0, 0), p(1, 1), p(2, 2)]).is_none());
        assert!(Raster::new(&[0, 0, 1], &[p(0, 0), p(1, 1)]).is_none());
        assert!(Raster::new(&[0, 1, 7], &[p(0, 0), p(1, 1)]).is_none());
    }

    #[test]
    fn snapping_errs_at_most_half_a_step() {
        for c in [0.3, -7.123_456_789, 1e6 + 0.1, 123.999_999_9] {
            let s = Projected::of(DVec3::new(c, -c, 1.0));
            let step = 1.0 / f64::from(1u32 << FRAC_BITS);
            assert!((s.x as f64 * step - c).abs() <= step / 2.0);
            assert!((s.y as f64 * step + c).abs() <= step / 2.0);
        }
        let far = Projected::of(DVec3::new(f64::INFINITY, f64::NAN, 0.0));
        assert_eq!((far.x, far.y), ((LIMIT as i64) << FRAC_BITS, 0));
    }

    #[test]
    fn pixel_spans_round_inwards_and_clamp() {
        let one = 1i64 << FRAC_BITS;
        assert_eq!(pixel_span(one / 2, 3 * one, 0, 10), Some((1, 3)));
        assert_eq!(pixel_span(-5 * one, 20 * one, 0, 10), Some((0, 9)));
        assert_eq!(pixel_span(one + 1, 2 * one - 1, 0, 10), None);
        assert_eq!(pixel_span(0, 0, 0, 0), None);
        assert_eq!(pixel_span(-one, -1, 0, 10), None);
        assert_eq!(pixel_span(-5 * one, 20 * one, 4, 3), Some((4, 6)));
        assert_eq!(pixel_span(one / 2, 3 * one, 4, 3), None);
    }

    #[test]
    fn obj_references() {
        assert_eq!(obj::reference(b"3/1/2", 5).ok(), Some(2));
        assert_eq!(obj::reference(b"-1//4", 5).ok(), Some(4));
        assert_eq!(obj::reference(b"-5", 5).ok(), Some(0));
        assert!(obj::reference(b"-6", 5).is_err());
        assert!(obj::reference(b"0", 5).is_err());
        assert!(obj::reference(b"6", 5).is_err());
        assert!(obj::reference(b"x", 5).is_err());
        assert!(obj::reference(b"-9223372036854775808", 5).is_err());
    }

    proptest::proptest! {
        /// The open-edge words counted by sorting are those of counting every undirected
        /// edge's uses in a map: the same counts and the same first offending edge.
        #[test]
        fn open_edges_sorted_count_as_a_map_does(
            tris in proptest::collection::vec(proptest::array::uniform3(0u32..12), 1..60),
        ) {
            let mesh = TriMesh {
                vertices: (0..12).map(|i| DVec3::new(i as f64, (i * i) as f64, 0.5)).collect(),
                triangles: tris.clone(),
            };
            let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
            for e in tris.iter().flat_map(edges) {
                *uses.entry(undirected(e)).or_default() += 1;
            }
            let count = |f: fn(u32) -> bool| uses.values().filter(|&&n| f(n)).count();
            let (open, many) = (count(|n| n == 1), count(|n| n > 2 && n % 2 == 1));
            let got = mesh.open_edges(&tris);
            proptest::prop_assert_eq!(got.is_none(), open == 0 && many == 0);
            if let Some(words) = got {
                let kind: fn(u32) -> bool = match open > 0 {
                    true => |n| n == 1,
                    false => |n| n > 2 && n % 2 == 1,
                };
                let (a, b) = tris.iter().flat_map(edges).find(|&e| kind(uses[&undirected(e)])).unwrap();
                let (a, b) = (mesh.vertices[a as usize], mesh.vertices[b as usize]);
                let first = format!("(first from ({},{},{}) to ({},{},{}))", a.x, a.y, a.z, b.x, b.y, b.z);
                let lead = format!("{open} edges belong to one triangle");
                proptest::prop_assert!(words.starts_with(&lead));
                let odd = format!(", {many} to another odd");
                proptest::prop_assert!(words.contains(&odd));
                proptest::prop_assert!(words.contains(&first), "{} lacks {}", words, first);
            }
        }
    }
}

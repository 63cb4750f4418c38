//! The exact geometry of a CSG subtree, for the nodes that need more than its leaves:
//! `hull()` of a difference or intersection, `minkowski()` of a non-convex operand (and, on
//! branch `proj`, `projection()` and `resize()`). An intersection of convex solids is
//! clipped into one polytope instead ([`crate::clip`]); `minkowski()`'s operands are split
//! into pieces by [`crate::pieces`].
//!
//! [`mesh_of`] evaluates a subtree to one closed triangle mesh: a convex solid's faces are
//! fanned into triangles, a closed mesh primitive (an [`Import`] holding triangles) is taken as
//! it is, and unions, intersections and differences are computed by `boolmesh`, a pure-Rust
//! port of Manifold, the mesh-boolean engine of recent OpenSCAD. The tree is walked with an
//! explicit stack (trees can be [`crate::MAX_NESTING`] deep). A dataset or a mesh file
//! (`import("x.nrrd")`, `import("x.stl")`) has no triangles while a scene is read, and is
//! refused by name.
//!
//! Limits: boolmesh needs manifold operands. The caps of a concave outline's extrusion are
//! fans that overlap themselves (crates/openscad/src/extrude.rs: right under parity, not as a
//! manifold); their booleans can be wrong, and boolmesh may refuse them.
//!
//! # Minkowski sums
//!
//! [`minkowski3`] and [`minkowski2`] compute OpenSCAD's `minkowski()` of operands given as
//! pieces ([`Piece`], [`Piece2`]), unions being distributed first:
//! (A ∪ B) ⊕ C = (A ⊕ C) ∪ (B ⊕ C).
//!
//! * Convex ⊕ convex: the convex hull of the pairwise vertex sums (one convex solid the array
//!   draws; in 2D one convex polygon). In 3D only the sums p + q whose normal cones meet are
//!   hulled ([`Fan`]): the others are never vertices of the sum, and a sphere of a thousand
//!   vertices plus a 32-vertex hull is 33 000 sums of which about 1 500 are kept. A convex
//!   operand is a [`Polytope`] with its faces (a solid's own, or the hull's that made it), so
//!   its fan is read from them and the sum's solid keeps its hull's faces: no hull is taken
//!   twice.
//! * A non-convex X (a difference, an intersection, a closed mesh primitive) ⊕ a convex C:
//!
//!   X ⊕ C = (X + c0) ∪ ⋃_{triangles T of ∂X} hull(T ⊕ C), for any point c0 of C.
//!
//!   Proof: ⊇ is plain (X + c0 ⊂ X ⊕ C, and T ⊕ C ⊂ X ⊕ C is convex, so it is its hull).
//!   ⊆: let p = x + c with x ∈ X, c ∈ C. If p − c0 ∈ X, p ∈ X + c0. Otherwise follow
//!   q(t) = p − (c0 + t(c − c0)) for t from 0 to 1: q(0) = p − c0 ∉ X and q(1) = x ∈ X, so
//!   the path crosses ∂X at some t, q(t) ∈ T for a triangle T of ∂X, and
//!   p = q(t) + (c0 + t(c − c0)) with c0 + t(c − c0) ∈ C (C is convex): p ∈ T ⊕ C. ∎
//!
//!   The proof needs only convex parts of ∂X covering it, so coplanar neighbouring triangles
//!   whose union is convex are taken as one ([`convex_patches`]).
//!
//!   X + c0 is X's mesh translated (a closed mesh primitive), each hull(T ⊕ C) a convex
//!   solid: a mesh of n triangles becomes n convex solids of up to 3·|C| vertices each. That
//!   is exact but many primitives (a sphere minus a cylinder at `$fn = 12` has a few hundred
//!   triangles); the scene's vertex budget ([`crate::ReadOptions::max_vertices`]) refuses sums that
//!   would exceed it.
//! * Both non-convex: the same argument with a triangle T in the role of C (a triangle is
//!   convex) gives T ⊕ Y = (Y + t) ∪ ⋃_{T' of ∂Y} hull(T ⊕ T') for any point t of T, so
//!
//!   X ⊕ Y = (X + y0) ∪ ⋃_{vertices v of ∂X} (Y + v) ∪ ⋃_{T of ∂X, T' of ∂Y} hull(T ⊕ T'),
//!
//!   choosing for t a vertex of T. That is |∂X|·|∂Y| convex solids and one mesh per vertex
//!   of X: only small operands fit the budget. The flat hulls of parallel triangles are
//!   dropped, which changes nothing: X ⊕ Y is the union of the regular closed sets X + y, so
//!   each of its points is a limit of interior points, almost all of which (all but a
//!   finite union of planar polygons) lie in the remaining pieces, whose union is closed.
//!
//! In 2D the same formulas hold with the boundary edges of a polygon in place of triangles
//! (the path argument is unchanged); the pieces are joined by a 2D union.

use csgpix_scene::Error;
use glam::{DVec2, DVec3};

use boolmesh::prelude::{compute_boolean, Manifold, OpType};

use crate::extrude::{flatten, Poly2, Region};
use crate::hull::{hull2, hull3};
use csgpix_scene::solid::{ConvexSolid, CsgNode, Import, IMPORTED};

/// A closed triangle mesh, outward by the right-hand rule.
pub(crate) type Mesh = Vec<[DVec3; 3]>;

/// The exact geometry of `node` as a closed triangle mesh (empty for an empty result). Leaf
/// `Solid(i)` is `solids[i]` below [`IMPORTED`] and `imports[i - IMPORTED]` from it, as while
/// a scene is read.
///
/// Err names what cannot be evaluated: an import without triangles, a complement, a leaf out
/// of range, a boolean boolmesh refuses.
pub(crate) fn mesh_of(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
) -> csgpix_scene::Result<Vec<[DVec3; 3]>> {
    // Post-order with an explicit stack: a node is entered (its children pushed), then left
    // (its children's results, on `done`, combined).
    enum Step<'a> {
        Enter(&'a CsgNode),
        Leave(&'a CsgNode),
    }
    let mut stack = vec![Step::Enter(node)];
    // `None` is the empty set.
    let mut done: Vec<Option<Manifold>> = Vec::new();
    while let Some(step) = stack.pop() {
        match step {
            Step::Enter(n) => match n {
                CsgNode::Empty => done.push(None),
                CsgNode::Solid(i) => done.push(leaf_manifold(*i, solids, imports)?),
                CsgNode::Complement(_) => return Err(Error::UnboundedComplement),
                CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                    stack.push(Step::Leave(n));
                    // Reversed, so the first child is evaluated (and pushed on `done`) first.
                    stack.extend(c.iter().rev().map(Step::Enter));
                }
            },
            Step::Leave(n) => {
                let k = n.children().len();
                let parts = done.split_off(done.len() - k);
                done.push(combine(n, parts)?);
            }
        }
    }
    Ok(match done.pop().flatten() {
        None => vec![],
        Some(m) => triangles(&m),
    })
}

/// The children's results combined as `n` says.
fn combine(n: &CsgNode, parts: Vec<Option<Manifold>>) -> csgpix_scene::Result<Option<Manifold>> {
    let mut it = parts.into_iter();
    let mut acc = it.next().flatten();
    for part in it {
        acc = match n {
            CsgNode::Union(_) => match (acc, part) {
                (None, b) => b,
                (a, None) => a,
                (Some(a), Some(b)) => boolean(&a, &b, OpType::Add)?,
            },
            CsgNode::Intersection(_) => match (acc, part) {
                (Some(a), Some(b)) => boolean(&a, &b, OpType::Intersect)?,
                _ => None,
            },
            _ => match (acc, part) {
                (Some(a), Some(b)) => boolean(&a, &b, OpType::Subtract)?,
                (a, None) => a,
                (None, _) => None,
            },
        };
    }
    Ok(acc)
}

fn boolean(a: &Manifold, b: &Manifold, op: OpType) -> csgpix_scene::Result<Option<Manifold>> {
    match compute_boolean(a, b, op) {
        Ok(m) => Ok((m.nf > 0).then_some(m)),
        // boolmesh reports an empty result (disjoint operands of an intersection, a
        // difference removing everything) as an error without vertices.
        Err(e) if e.contains("empty") => Ok(None),
        Err(reason) => Err(Error::BooleanFailed { reason }),
    }
}

fn leaf_manifold(
    i: usize,
    solids: &[ConvexSolid],
    imports: &[Import],
) -> csgpix_scene::Result<Option<Manifold>> {
    let tris = leaf_mesh(i, solids, imports)?;
    manifold(&tris)
}

/// A leaf's triangles (a convex solid's faces fanned; an import's mesh in scene coordinates).
pub(crate) fn leaf_mesh(
    i: usize,
    solids: &[ConvexSolid],
    imports: &[Import],
) -> csgpix_scene::Result<Mesh> {
    if i < IMPORTED {
        let s = solids.get(i).ok_or(Error::NoPrimitive {
            kind: "solid",
            index: i,
        })?;
        return Ok(solid_triangles(s));
    }
    let import = imports.get(i - IMPORTED).ok_or(Error::NoPrimitive {
        kind: "import",
        index: i - IMPORTED,
    })?;
    let Some(mesh) = &import.mesh else {
        return Err(Error::ImportWithoutGeometry {
            file: import.file.clone(),
        });
    };
    let m = import.matrix;
    Ok(mesh
        .iter()
        .map(|t| {
            t.map(|v| match &m {
                None => DVec3::from(v),
                Some(m) => DVec3::new(
                    m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2] + m[0][3],
                    m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2] + m[1][3],
                    m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2] + m[2][3],
                ),
            })
        })
        .collect())
}

/// A convex solid's faces as fans of triangles.
pub(crate) fn solid_triangles(s: &ConvexSolid) -> Mesh {
    let v = |i: u32| DVec3::from(s.vertices[i as usize]);
    let mut out = Vec::new();
    for f in &s.faces {
        for k in 1..f.len().saturating_sub(1) {
            out.push([v(f[0]), v(f[k]), v(f[k + 1])]);
        }
    }
    out
}

/// A triangle soup welded (bit-equal corners) into a boolmesh manifold; `None` when empty.
fn manifold(tris: &[[DVec3; 3]]) -> csgpix_scene::Result<Option<Manifold>> {
    if tris.is_empty() {
        return Ok(None);
    }
    let pos: Vec<f64> = tris.iter().flatten().flat_map(|v| v.to_array()).collect();
    let idx: Vec<usize> = (0..tris.len() * 3).collect();
    Manifold::new(&pos, &idx)
        .map(Some)
        .map_err(|e| Error::NotManifold {
            reason: e.to_string(),
        })
}

fn triangles(m: &Manifold) -> Mesh {
    let p = |i: usize| {
        let q = m.ps[i];
        DVec3::new(q.x, q.y, q.z)
    };
    m.hs.chunks_exact(3)
        .map(|h| [p(h[0].tail), p(h[1].tail), p(h[2].tail)])
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Minkowski sums

/// An operand of a 3D Minkowski sum.
#[derive(Clone, Debug)]
pub(crate) enum Piece {
    /// A convex polytope.
    Convex(Polytope),
    /// A closed mesh, outward.
    Mesh(Mesh),
}

/// A convex polytope with its faces, each counter-clockwise seen from outside: a convex
/// solid's own, or a hull's as [`hull3`] made it. A sum's normal fans ([`Fan`]) are read from
/// the faces and a sum's solid keeps its hull's faces, so no hull is taken twice (a sphere of
/// 7,200 vertices took 7-9 ms to hull again, each time).
#[derive(Clone, Debug)]
pub(crate) struct Polytope {
    pub(crate) v: Vec<DVec3>,
    pub(crate) faces: Vec<Vec<usize>>,
}

impl Polytope {
    /// The hull of `points`.
    pub(crate) fn hull(points: &[DVec3]) -> csgpix_scene::Result<Polytope> {
        let (v, faces) = hull3(points)?;
        Ok(Polytope { v, faces })
    }

    /// A convex solid's corners and faces.
    pub(crate) fn of_solid(s: &ConvexSolid) -> Polytope {
        Polytope {
            v: s.vertices.iter().map(|&v| DVec3::from(v)).collect(),
            faces: s.faces.to_vecs(),
        }
    }

    /// As the solid the array draws.
    pub(crate) fn solid(self, colour: Option<[f64; 4]>, line: usize) -> ConvexSolid {
        ConvexSolid {
            vertices: self.v.iter().map(|v| v.to_array()).collect(),
            faces: self.faces.into(),
            colour,
            line,
        }
    }

    /// Whether its faces can give its normal fan as they stand: four or more, and every
    /// corner on three or more (a flat or degenerate solid's fan is made from a hull of its
    /// corners instead, which refuses it as [`Fan::of`] does).
    fn faces_hold_fan(&self) -> bool {
        let mut on = vec![0u32; self.v.len()];
        for f in &self.faces {
            for &i in f {
                on[i] += 1;
            }
        }
        self.faces.len() >= 4 && on.iter().all(|&n| n >= 3)
    }

    /// Its normal fan: from its faces ([`Self::faces_hold_fan`]), else as [`Fan::of`] makes it.
    fn fan(&self) -> Option<Fan> {
        match self.faces_hold_fan() {
            true => Some(Fan::polytope(self.v.clone(), &self.faces)),
            false => Fan::of(&self.v),
        }
    }
}

/// Most vertex-plane tests [`convex_hull_of`] makes; past them a mesh stays a mesh.
const CONVEX_TESTS: usize = 1 << 24;

/// The hull when closed mesh `m` is convex: every vertex of `m` on the hull's surface and
/// the volumes equal. The mesh lies within its hull, so equal volumes leave only
/// a difference of no volume, and a cavity or dent, however thin, has a vertex inside the hull.
/// Tolerances are relative, as the hull's ([`hull3`]).
pub(crate) fn convex_hull_of(m: &Mesh) -> Option<Polytope> {
    const EPS: f64 = 1e-9;
    let points = distinct(m.iter().flatten().copied());
    let (v, faces) = hull3(&points).ok()?;
    if points.len().saturating_mul(faces.len()) > CONVEX_TESTS {
        return None;
    }
    let planes: Vec<(DVec3, f64)> = faces.iter().map(|f| face_plane(&v, f)).collect();
    let extent = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
            (a.min(p), b.max(p))
        });
    let eps = EPS * (extent.1 - extent.0).max_element();
    let on_surface = |p: &DVec3| {
        planes
            .iter()
            .map(|(n, d)| n.dot(*p) - d)
            .fold(f64::NEG_INFINITY, f64::max)
            >= -eps
    };
    let vs = &v;
    let hull_volume: f64 = faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |i| [vs[f[0]], vs[f[i]], vs[f[i + 1]]]))
        .map(|t| t[0].dot(t[1].cross(t[2])) / 6.0)
        .sum();
    let mesh_volume: f64 = m.iter().map(|t| t[0].dot(t[1].cross(t[2])) / 6.0).sum();
    let same = (hull_volume - mesh_volume).abs() <= EPS * hull_volume;
    (same && points.iter().all(on_surface)).then_some(Polytope { v, faces })
}

/// A convex face's unit outward normal n and offset d (n·x = d on it), by Newell's method.
pub(crate) fn face_plane(v: &[DVec3], f: &[usize]) -> (DVec3, f64) {
    let n = (0..f.len())
        .map(|i| {
            let (a, b) = (v[f[i]], v[f[(i + 1) % f.len()]]);
            DVec3::new(
                (a.y - b.y) * (a.z + b.z),
                (a.z - b.z) * (a.x + b.x),
                (a.x - b.x) * (a.y + b.y),
            )
        })
        .sum::<DVec3>()
        .normalize_or_zero();
    (n, n.dot(v[f[0]]))
}

/// A 2D operand of `minkowski()` as a union of pieces: unions distributed, a convex outline
/// as itself, any other shape, difference or intersection as its computed outline.
pub(crate) fn pieces2(r: &Region) -> Vec<Piece2> {
    let mut out = vec![];
    let mut stack = vec![r];
    while let Some(r) = stack.pop() {
        match r {
            Region::Union(c) => stack.extend(c.iter()),
            Region::Poly(p) => match p.convex_outline() {
                Some(o) => out.push(Piece2::Convex(o)),
                None if !p.paths.is_empty() => out.push(Piece2::Shape(p.clone())),
                None => {}
            },
            _ => {
                let p = flatten(r);
                if !p.paths.is_empty() {
                    out.push(Piece2::Shape(p));
                }
            }
        }
    }
    out
}

/// The Minkowski sum of two unions of pieces, as a union of pieces (module documentation),
/// and the vertices it was counted to bring (what `budget` had to hold). `budget` is the
/// most vertices the result may have; Err("budget") past it. The pairs' sums are made in
/// parallel (a sphere's sum with each part of a union is a hull of its own) and kept in
/// order; an error is the one the pairs met first, in order, as if summed one after another.
pub(crate) fn minkowski3(
    a: &[Piece],
    b: &[Piece],
    budget: usize,
) -> csgpix_scene::Result<(Vec<Piece>, usize)> {
    use rayon::prelude::*;
    let pairs: Vec<(&Piece, &Piece)> = a
        .iter()
        .flat_map(|p| b.iter().map(move |q| (p, q)))
        .collect();
    // The pairs within the budget, the vertices each may bring counted before it is made.
    let counts: Vec<usize> = pairs.iter().map(|&(p, q)| pair_vertices(p, q)).collect();
    let need = counts.iter().fold(0usize, |n, &c| n.saturating_add(c));
    let mut spend = spender(budget);
    let within = counts
        .iter()
        .position(|&c| spend(c).is_err())
        .unwrap_or(pairs.len());
    let sums: Vec<csgpix_scene::Result<Vec<Piece>>> = pairs[..within]
        .par_iter()
        .map(|&(p, q)| pair_sum(p, q))
        .collect();
    let mut out = Vec::new();
    for s in sums {
        out.extend(s?);
    }
    match within < pairs.len() {
        true => Err(over_budget()),
        false => Ok((out, need)),
    }
}

/// The most vertices the sum of pieces `p` and `q` brings (the budget's count).
fn pair_vertices(p: &Piece, q: &Piece) -> usize {
    match (p, q) {
        (Piece::Convex(x), Piece::Convex(y)) => x.v.len().saturating_mul(y.v.len()),
        (Piece::Mesh(x), Piece::Convex(c)) | (Piece::Convex(c), Piece::Mesh(x)) => {
            x.len().saturating_mul(3 * c.v.len() + 3)
        }
        (Piece::Mesh(x), Piece::Mesh(y)) => {
            let verts = distinct(x.iter().flatten().copied());
            x.len()
                .saturating_mul(y.len())
                .saturating_mul(9)
                .saturating_add(verts.len().saturating_mul(3 * y.len()))
                .saturating_add(3 * x.len())
        }
    }
}

/// The sum of pieces `p` and `q`, as pieces.
fn pair_sum(p: &Piece, q: &Piece) -> csgpix_scene::Result<Vec<Piece>> {
    let mut out = vec![];
    match (p, q) {
        (Piece::Convex(x), Piece::Convex(y)) => out.push(convex_sum(x, y)?),
        (Piece::Mesh(x), Piece::Convex(c)) | (Piece::Convex(c), Piece::Mesh(x)) => {
            mesh_plus_convex(x, c, &mut out)?;
        }
        (Piece::Mesh(x), Piece::Mesh(y)) => {
            out.push(Piece::Mesh(translated(x, y[0][0])));
            for &v in &distinct(x.iter().flatten().copied()) {
                out.push(Piece::Mesh(translated(y, v)));
            }
            for t in x {
                for u in y {
                    // Parallel triangles sum to a flat hull: dropped (module docs).
                    if let Ok(p) = hull_piece(&sum_points(t, u, || (Fan::of(t), Fan::of(u)))) {
                        out.push(p);
                    }
                }
            }
        }
    }
    Ok(out)
}

/// What spends at most `budget` of the result's vertices: each call adds its count, an error
/// once they pass the budget.
fn spender(budget: usize) -> impl FnMut(usize) -> csgpix_scene::Result<()> {
    let mut used = 0usize;
    move |n| {
        used = used.saturating_add(n);
        match used > budget {
            true => Err(over_budget()),
            false => Ok(()),
        }
    }
}

pub(crate) fn over_budget() -> Error {
    Error::MinkowskiTooLarge
}

/// X ⊕ C = (X + c0) ∪ ⋃ hull(F ⊕ C), F the convex patches of ∂X ([`convex_patches`]).
fn mesh_plus_convex(x: &Mesh, c: &Polytope, out: &mut Vec<Piece>) -> csgpix_scene::Result<()> {
    use rayon::prelude::*;
    let Some(&c0) = c.v.first() else {
        return Ok(());
    };
    out.push(Piece::Mesh(translated(x, c0)));
    // C's normal fan once, for every patch; the patches' hulls in parallel, in order.
    let fan = c.fan();
    let hulls: Vec<csgpix_scene::Result<Piece>> = convex_patches(x)
        .par_iter()
        .map(|f| {
            let points = match (&fan, Fan::flat(f)) {
                (Some(fc), Some(ff)) => ff.sum_vertices(fc),
                _ => all_sums(f, &c.v),
            };
            hull_piece(&points)
        })
        .collect();
    for h in hulls {
        out.push(h?);
    }
    Ok(())
}

/// The triangles of `x` joined into convex polygons, in order: from each triangle not yet
/// taken, the neighbour across an edge of the polygon is added while it lies in the polygon's
/// plane (its far corner within 10⁻¹² of the extent) beyond that edge and the polygon stays
/// convex. Each polygon is then the union of its triangles, so a convex part of ∂X, and the
/// polygons cover ∂X: the path argument of the module documentation holds for them as for
/// triangles, and an extrusion's wall of two triangles is one hull instead of two (a flat
/// polygon ⊕ C has about as many vertices as a triangle ⊕ C: C's vertices shared out among
/// the corners' cones). Counter-clockwise seen from outside, as the triangles are.
fn convex_patches(x: &Mesh) -> Vec<Vec<DVec3>> {
    let key = |p: DVec3| p.to_array().map(f64::to_bits);
    let mut by_edge = std::collections::HashMap::with_capacity(3 * x.len());
    for (i, t) in x.iter().enumerate() {
        for k in 0..3 {
            by_edge.insert((key(t[k]), key(t[(k + 1) % 3])), i);
        }
    }
    let (lo, hi) = x
        .iter()
        .flatten()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let tol = 1e-12 * (hi - lo).max_element();
    let mut taken = vec![false; x.len()];
    let mut out = Vec::with_capacity(x.len());
    for (i, t) in x.iter().enumerate() {
        if taken[i] {
            continue;
        }
        taken[i] = true;
        let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        let mut poly = t.to_vec();
        let mut k = 0;
        while n != DVec3::ZERO && k < poly.len() {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            let grown = by_edge
                .get(&(key(b), key(a)))
                .filter(|&&j| !taken[j])
                .and_then(|&j| {
                    let c = x[j]
                        .into_iter()
                        .find(|&p| key(p) != key(a) && key(p) != key(b))?;
                    grows(&poly, k, c, n, tol).then_some((j, c))
                });
            match grown {
                Some((j, c)) => {
                    taken[j] = true;
                    poly.insert(k + 1, c);
                }
                None => k += 1,
            }
        }
        out.push(poly);
    }
    out
}

/// Whether convex polygon `poly` (counter-clockwise about `n`) with point `c` put after
/// corner `k` is a convex polygon in the same plane: `c` within `tol` of the plane, strictly
/// beyond edge k, and no corner turned the other way.
fn grows(poly: &[DVec3], k: usize, c: DVec3, n: DVec3, tol: f64) -> bool {
    let m = poly.len();
    let at = |i: usize| poly[(i + m) % m];
    let (a, b) = (at(k), at(k + 1));
    let turn = |p: DVec3, q: DVec3, r: DVec3| (q - p).cross(r - q).dot(n);
    (n.dot(c - a)).abs() <= tol
        && turn(a, c, b) > 0.0
        && turn(at(k + m - 1), a, c) >= 0.0
        && turn(c, b, at(k + 2)) >= 0.0
}

/// The hull of the pairwise sums of two convex polytopes.
fn convex_sum(x: &Polytope, y: &Polytope) -> csgpix_scene::Result<Piece> {
    hull_piece(&sum_points(&x.v, &y.v, || (x.fan(), y.fan())))
}

fn hull_piece(points: &[DVec3]) -> csgpix_scene::Result<Piece> {
    Polytope::hull(points).map(Piece::Convex)
}

/// Below this many pairwise sums the hull takes them all.
const FEW_SUMS: usize = 64;

/// Points whose convex hull is hull(x ⊕ y): every vertex of that hull among them. Large
/// operands go through their normal fans ([`Fan::sum_vertices`], the two `fans` makes);
/// small or flat ones (other than a triangle) give all pairwise sums.
fn sum_points(
    x: &[DVec3],
    y: &[DVec3],
    fans: impl FnOnce() -> (Option<Fan>, Option<Fan>),
) -> Vec<DVec3> {
    if x.len().saturating_mul(y.len()) <= FEW_SUMS {
        return all_sums(x, y);
    }
    match fans() {
        (Some(a), Some(b)) => a.sum_vertices(&b),
        _ => all_sums(x, y),
    }
}

fn all_sums(x: &[DVec3], y: &[DVec3]) -> Vec<DVec3> {
    x.iter()
        .flat_map(|&p| y.iter().map(move |&q| p + q))
        .collect()
}

/// Angular tolerance (radians, and for products of unit vectors) of the fan tests.
const FAN_EPS: f64 = 1e-9;

/// A convex polytope (or a triangle) with the normal cone of each vertex: the directions d
/// for which the vertex maximises d · x over the polytope.
///
/// p + q is a vertex of P ⊕ Q only where the cones of p and q share an open set of
/// directions (the sum's support in a direction is the sum of the supports), so
/// [`Fan::sum_vertices`] keeps the sums of the pairs whose cones meet: that is all the
/// hull's vertices among about as many points, instead of |P|·|Q|
/// (a 32-vertex hull ⊕ a sphere of 1035 vertices: about 1500 points in place of 33 000).
///
/// A cone is given twice: by its generators (unit vectors: the normals of the faces around
/// the vertex; for a triangle's corner, ±its normal and the outward normals of its two
/// edges), and by its faces, one per edge e of the vertex (the directions d with d · e ≤ 0,
/// e the unit vector along the edge). Two cones share no open set of directions when every
/// generator of one lies on the far side of a face plane of the other, or on that plane
/// ([`Fan::beyond_an_edge`]): the plane separates them. Such pairs are dropped; every other
/// pair is kept, a vertex of the sum or not (a pair apart by no face plane of either is
/// kept though its cones may be disjoint: extra points cost time only, never the hull).
/// Cones that only touch, along a ray or a plane, are so dropped: a 150-sided cylinder's
/// rims and a 50-fragment sphere's polar rings share the axis, and counting touching cones
/// as meeting gave 23,000 points for a hull of 3,900 (now 3,900). A plane "on" within
/// [`FAN_EPS`] drops pairs whose shared directions are thinner than that: their sum is
/// within that angle times an edge's length of the hull of the rest, below [`hull3`]'s own
/// tolerance (10⁻⁹ of the extent).
struct Fan {
    /// The vertices.
    v: Vec<DVec3>,
    /// Distinct generator directions, unit.
    dirs: Vec<DVec3>,
    /// Per vertex, its generators (indices into `dirs`).
    gens: Vec<Vec<usize>>,
    /// Per vertex, the unit vectors along its edges (to each neighbour): its cone is the
    /// directions d with d · e ≤ 0 for each.
    edges: Vec<Vec<DVec3>>,
    /// Per vertex, a cap holding its cone (unit centre, angular radius), None past 90°.
    caps: Vec<Option<(DVec3, f64)>>,
    /// The caps by latitude, built once: a fan is summed with many others (a mesh's
    /// triangles, each with the same convex operand).
    band: CapBand,
    /// Per vertex, the cosine and sine of its cap's radius ((0, 0) without a cap).
    trig: Vec<(f64, f64)>,
}

impl Fan {
    /// The fan of a triangle (three points) or of the hull of four or more points; None
    /// for degenerate (flat, collinear) sets other than a triangle.
    fn of(points: &[DVec3]) -> Option<Fan> {
        match points.len() {
            3 => Fan::flat(points),
            n if n >= 4 => {
                let (v, faces) = hull3(points).ok()?;
                Some(Fan::polytope(v, &faces))
            }
            _ => None,
        }
    }

    fn polytope(v: Vec<DVec3>, faces: &[Vec<usize>]) -> Fan {
        let mut dirs = Vec::with_capacity(faces.len());
        let mut gens = vec![vec![]; v.len()];
        for f in faces {
            // Newell's normal: outward for a counter-clockwise face.
            let n: DVec3 = (0..f.len())
                .map(|k| v[f[k]].cross(v[f[(k + 1) % f.len()]]))
                .sum();
            let n = n.normalize_or_zero();
            if n == DVec3::ZERO {
                continue;
            }
            for &i in f {
                gens[i].push(dirs.len());
            }
            dirs.push(n);
        }
        let mut next: Vec<Vec<usize>> = vec![vec![]; v.len()];
        for f in faces {
            for k in 0..f.len() {
                let (a, b) = (f[k], f[(k + 1) % f.len()]);
                next[a].push(b);
                next[b].push(a);
            }
        }
        let edges = next
            .iter_mut()
            .enumerate()
            .map(|(i, n)| {
                n.sort_unstable();
                n.dedup();
                n.iter()
                    .map(|&j| (v[j] - v[i]).normalize_or_zero())
                    .collect()
            })
            .collect();
        Fan::with_caps(v, dirs, gens, edges)
    }

    /// The fan of a flat convex polygon (a triangle, or a patch of [`convex_patches`]):
    /// each corner's cone is the wedge of ±the normal and the outward normals of its two
    /// edges. None when it has no area.
    fn flat(t: &[DVec3]) -> Option<Fan> {
        let m = t.len();
        let n = match m {
            3 => (t[1] - t[0]).cross(t[2] - t[0]),
            // Newell's normal.
            _ => (0..m).map(|k| t[k].cross(t[(k + 1) % m])).sum(),
        }
        .normalize_or_zero();
        if m < 3 || n == DVec3::ZERO {
            return None;
        }
        // A point inside, to turn each edge normal outward.
        let inner = match m {
            3 => None,
            _ => Some(t.iter().sum::<DVec3>() / m as f64),
        };
        // dirs: n, -n, then the outward in-plane normal of edge k (from t[k] to t[k+1]).
        let mut dirs = vec![n, -n];
        for k in 0..m {
            let (a, b) = (t[k], t[(k + 1) % m]);
            let c = inner.unwrap_or(t[(k + 2) % m]);
            let w = (b - a).cross(n).normalize_or_zero();
            dirs.push(if w.dot(c - a) > 0.0 { -w } else { w });
        }
        // Corner k touches edges k and k - 1 (the one ending at it).
        let gens: Vec<Vec<usize>> = (0..m)
            .map(|k| vec![0, 1, 2 + k, 2 + (k + m - 1) % m])
            .collect();
        let edges = (0..m)
            .map(|k| {
                let to = |j: usize| (t[(k + j) % m] - t[k]).normalize_or_zero();
                vec![to(1), to(m - 1)]
            })
            .collect();
        Some(Fan::with_caps(t.to_vec(), dirs, gens, edges))
    }

    fn with_caps(
        v: Vec<DVec3>,
        dirs: Vec<DVec3>,
        gens: Vec<Vec<usize>>,
        edges: Vec<Vec<DVec3>>,
    ) -> Fan {
        let caps: Vec<_> = gens
            .iter()
            .map(|g| {
                let c = g
                    .iter()
                    .map(|&k| dirs[k])
                    .sum::<DVec3>()
                    .normalize_or_zero();
                let cos = g.iter().map(|&k| c.dot(dirs[k])).fold(1.0, f64::min);
                (c != DVec3::ZERO && cos > 1e-3).then(|| (c, cos.clamp(-1.0, 1.0).acos()))
            })
            .collect();
        let band = CapBand::of(&caps);
        let trig = cap_trig(&caps, 0.0);
        Fan {
            v,
            dirs,
            gens,
            edges,
            caps,
            band,
            trig,
        }
    }

    /// The sums p + q of this fan's vertex p and `other`'s vertex q whose cones meet: all
    /// the vertices of hull(P ⊕ Q) among them (the type's documentation). Pairs whose caps
    /// lie more than their radii (and 10⁻⁶) apart are skipped unseen: for each p only the
    /// q of [`CapBand::candidates`] are tried, and the kept put in order.
    fn sum_vertices(&self, other: &Fan) -> Vec<DVec3> {
        // A large sum's vertices are found in parallel; a small one's (a mesh's triangle,
        // the triangles summed in parallel already) in turn.
        let parallel = self.v.len().saturating_mul(other.v.len()) >= PARALLEL_SUMS;
        self.sum_vertices_in(other, parallel)
    }

    /// [`Fan::sum_vertices`], each of this fan's vertices apart in parallel or all in turn:
    /// the same points in the same order.
    fn sum_vertices_in(&self, other: &Fan, parallel: bool) -> Vec<DVec3> {
        use rayon::prelude::*;
        // This fan's radii widened by the 10⁻⁶ slack: caps at angle a apart are disjoint
        // when a > r1 + r2 + 10⁻⁶, that is cos a < cos(r1' + r2).
        let meet = cap_trig(&self.caps, 1e-6);
        let (mut cand, mut out) = (vec![], vec![]);
        match parallel {
            true => (0..self.v.len())
                .into_par_iter()
                .map_init(Vec::new, |cand, i| {
                    let mut out = vec![];
                    self.sums_at(i, other, &meet, cand, &mut out);
                    out
                })
                .collect::<Vec<_>>()
                .concat(),
            false => {
                for i in 0..self.v.len() {
                    self.sums_at(i, other, &meet, &mut cand, &mut out);
                }
                out
            }
        }
    }

    /// The sums of this fan's vertex `i` with the vertices of `other` whose cones meet its
    /// own, in order, onto `out` ([`Fan::sum_vertices`]); `cand` is scratch.
    /// Whether `other`'s cone at its vertex `j` lies beyond the plane of one of the faces of
    /// this fan's cone at vertex `i` (every generator of it on that plane or past it, within
    /// [`FAN_EPS`]): then the two cones share no open set of directions.
    fn beyond_an_edge(&self, i: usize, other: &Fan, j: usize) -> bool {
        self.edges[i].iter().any(|e| {
            other.gens[j]
                .iter()
                .all(|&k| other.dirs[k].dot(*e) >= -FAN_EPS)
        })
    }

    fn sums_at(
        &self,
        i: usize,
        other: &Fan,
        trig_self: &[(f64, f64)],
        cand: &mut Vec<usize>,
        out: &mut Vec<DVec3>,
    ) {
        other.band.candidates(self.caps[i], cand);
        cand.retain(|&j| {
            if let (Some((c1, _)), Some((c2, _))) = (self.caps[i], other.caps[j]) {
                let ((cos1, sin1), (cos2, sin2)) = (trig_self[i], other.trig[j]);
                // Both radii are below 90°, so the sum is below 180° and cos decreases.
                if c1.dot(c2) < cos1 * cos2 - sin1 * sin2 {
                    return false;
                }
            }
            !(self.beyond_an_edge(i, other, j) || other.beyond_an_edge(j, self, i))
        });
        // In `other`'s order: the few kept sorted, not the many tried.
        cand.sort_unstable();
        out.extend(cand.iter().map(|&j| self.v[i] + other.v[j]));
    }
}

/// From this many pairs of vertices on, [`Fan::sum_vertices`] works in parallel.
const PARALLEL_SUMS: usize = 1 << 16;

/// The cosine and sine of each cap's radius plus `slack` ((0, 0) without a cap).
fn cap_trig(caps: &[Option<(DVec3, f64)>], slack: f64) -> Vec<(f64, f64)> {
    caps.iter()
        .map(|c| c.map_or((0.0, 0.0), |(_, r)| ((r + slack).cos(), (r + slack).sin())))
        .collect()
}

/// A fan's vertices by where their caps can be: those with a cap of radius at most
/// [`CapBand::NARROW`] sorted by the cap centre's z, the rest (wide or no cap) apart.
///
/// Caps within angle θ of each other have latitudes (asin z) within θ, so a cap of radius
/// r₁ centred at c can meet only the narrow caps whose z lies in the band of latitudes
/// asin(c.z) ± (r₁ + [`CapBand::NARROW`] + 10⁻⁶): on a sphere's many small caps a thin band.
struct CapBand {
    /// (z of the cap's centre, vertex), narrow caps only, by z.
    by_z: Vec<(f64, usize)>,
    /// The vertices with a wide cap or none: candidates for every query.
    wide: Vec<usize>,
}

impl CapBand {
    /// The widest cap kept in the band (radians); wider ones are tried with every vertex.
    const NARROW: f64 = 0.25;

    fn of(caps: &[Option<(DVec3, f64)>]) -> CapBand {
        let (mut by_z, mut wide) = (vec![], vec![]);
        for (j, cap) in caps.iter().enumerate() {
            match cap {
                Some((c, r)) if *r <= Self::NARROW => by_z.push((c.z, j)),
                _ => wide.push(j),
            }
        }
        by_z.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        CapBand { by_z, wide }
    }

    /// Into `out`, the wide first, then the narrow by latitude: the vertices whose caps may
    /// meet `cap` (every vertex when it is None).
    fn candidates(&self, cap: Option<(DVec3, f64)>, out: &mut Vec<usize>) {
        out.clear();
        out.extend_from_slice(&self.wide);
        let (lo, hi) = match cap {
            Some((c, r)) => {
                use std::f64::consts::FRAC_PI_2;
                // The margin covers asin's and sin's rounding.
                let theta = r + Self::NARROW + 1e-6 + 1e-9;
                let lat = c.z.clamp(-1.0, 1.0).asin();
                let lo = if lat - theta <= -FRAC_PI_2 {
                    f64::NEG_INFINITY
                } else {
                    (lat - theta).sin() - 1e-12
                };
                let hi = if lat + theta >= FRAC_PI_2 {
                    f64::INFINITY
                } else {
                    (lat + theta).sin() + 1e-12
                };
                (lo, hi)
            }
            None => (f64::NEG_INFINITY, f64::INFINITY),
        };
        let a = self.by_z.partition_point(|e| e.0 < lo);
        let b = self.by_z.partition_point(|e| e.0 <= hi);
        out.extend(self.by_z[a..b].iter().map(|e| e.1));
    }
}

fn translated(x: &Mesh, d: DVec3) -> Mesh {
    x.iter().map(|t| t.map(|v| v + d)).collect()
}

fn distinct(it: impl Iterator<Item = DVec3>) -> Vec<DVec3> {
    let mut seen = std::collections::HashSet::new();
    it.filter(|v| seen.insert(v.to_array().map(f64::to_bits)))
        .collect()
}

/// An operand of a 2D Minkowski sum.
#[derive(Clone, Debug)]
pub(crate) enum Piece2 {
    /// A convex polygon, counter-clockwise.
    Convex(Vec<DVec2>),
    /// A shape: outlines filled even-odd.
    Shape(Poly2),
}

/// The 2D Minkowski sum of two unions of pieces, as a union of pieces (module documentation,
/// edges in place of triangles). `budget` bounds the result's vertices.
pub(crate) fn minkowski2(
    a: &[Piece2],
    b: &[Piece2],
    budget: usize,
) -> csgpix_scene::Result<Vec<Piece2>> {
    let mut out = Vec::new();
    let mut spend = spender(budget);
    let sum = |x: &[DVec2], y: &[DVec2]| -> Option<Piece2> {
        let pts: Vec<DVec2> = x
            .iter()
            .flat_map(|&p| y.iter().map(move |&q| p + q))
            .collect();
        let h = hull2(&pts);
        (h.len() >= 3).then_some(Piece2::Convex(h))
    };
    for p in a {
        for q in b {
            match (p, q) {
                (Piece2::Convex(x), Piece2::Convex(y)) => {
                    spend(x.len() * y.len())?;
                    out.extend(sum(x, y));
                }
                (Piece2::Shape(x), Piece2::Convex(c)) | (Piece2::Convex(c), Piece2::Shape(x)) => {
                    let es = edges(x);
                    spend(es.len().saturating_mul(2 * c.len()) + x.points().count())?;
                    let Some(&c0) = c.first() else { continue };
                    out.push(Piece2::Shape(shifted(x, c0)));
                    for e in es {
                        out.extend(sum(&e, c));
                    }
                }
                (Piece2::Shape(x), Piece2::Shape(y)) => {
                    let (ex, ey) = (edges(x), edges(y));
                    let verts: Vec<DVec2> = x.points().collect();
                    let ny = y.points().count();
                    spend(
                        (ex.len() * ey.len())
                            .saturating_mul(4)
                            .saturating_add(verts.len().saturating_mul(ny))
                            .saturating_add(verts.len()),
                    )?;
                    let Some(y0) = y.points().next() else {
                        continue;
                    };
                    out.push(Piece2::Shape(shifted(x, y0)));
                    for &v in &verts {
                        out.push(Piece2::Shape(shifted(y, v)));
                    }
                    for e in &ex {
                        for f in &ey {
                            out.extend(sum(e, f));
                        }
                    }
                }
            }
        }
    }
    Ok(out)
}

fn edges(p: &Poly2) -> Vec<[DVec2; 2]> {
    p.paths
        .iter()
        .flat_map(|c| (0..c.len()).map(move |k| [c[k], c[(k + 1) % c.len()]]))
        .collect()
}

fn shifted(p: &Poly2, d: DVec2) -> Poly2 {
    Poly2 {
        paths: p
            .paths
            .iter()
            .map(|c| c.iter().map(|&v| v + d).collect())
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::memo::MeshMemo;
    use crate::pieces::pieces;

    fn cube(lo: [f64; 3], hi: [f64; 3]) -> ConvexSolid {
        let v = |i: usize| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        };
        ConvexSolid {
            vertices: (0..8).map(v).collect(),
            // Outward, counter-clockwise seen from outside.
            faces: vec![
                vec![0, 2, 3, 1],
                vec![4, 5, 7, 6],
                vec![0, 1, 5, 4],
                vec![2, 6, 7, 3],
                vec![0, 4, 6, 2],
                vec![1, 3, 7, 5],
            ]
            .into(),
            colour: None,
            line: 1,
        }
    }

    fn volume(m: &Mesh) -> f64 {
        m.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0
    }

    #[test]
    fn a_convex_cut_is_one_convex_piece_and_a_dent_is_not() {
        let s = [
            cube([0.0; 3], [2.0; 3]),
            cube([1.0, -1.0, -1.0], [3.0, 3.0, 3.0]), // cuts off a half: convex
            cube([1.0, 1.0, -1.0], [3.0, 3.0, 3.0]),  // cuts out a corner: an L
            cube([0.999, -1.0, 1.0], [1.001, 3.0, 3.0]), // a thin slot from the top
        ];
        let cut = |k| CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(k)]);
        let p = pieces(&cut(1), &s, &[], &mut MeshMemo::default()).unwrap();
        let [Piece::Convex(half)] = &p[..] else {
            panic!("a half cube is one convex piece")
        };
        assert_eq!(half.v.len(), 8);
        for k in [2, 3] {
            let p = pieces(&cut(k), &s, &[], &mut MeshMemo::default()).unwrap();
            assert!(matches!(&p[..], [Piece::Mesh(_)]), "cut {k} is not convex");
        }
        // Its sum with a cube is one hull: the box [0,1]x[0,2]x[0,2] grown by 1.
        let q = [Piece::Convex(Polytope::of_solid(&s[0]))];
        let (sum, _) = minkowski3(&p_half(&s), &q, 1 << 20).unwrap();
        let [Piece::Convex(sum)] = &sum[..] else {
            panic!("one hull")
        };
        let hi = sum.v.iter().fold(DVec3::NEG_INFINITY, |a, &b| a.max(b));
        assert_eq!(hi, DVec3::new(3.0, 4.0, 4.0));
    }

    fn p_half(s: &[ConvexSolid]) -> Vec<Piece> {
        let cut = CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(1)]);
        pieces(&cut, s, &[], &mut MeshMemo::default()).unwrap()
    }

    #[test]
    fn a_cube_has_its_volume() {
        let s = [cube([0.0; 3], [2.0, 3.0, 4.0])];
        let m = mesh_of(&CsgNode::Solid(0), &s, &[]).unwrap();
        assert!((volume(&m) - 24.0).abs() < 1e-9, "{}", volume(&m));
    }

    #[test]
    fn a_cube_minus_a_cube_has_the_right_volume() {
        let s = [
            cube([0.0; 3], [2.0; 3]),
            cube([1.0, 1.0, -1.0], [3.0, 3.0, 3.0]),
        ];
        let n = CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(1)]);
        let m = mesh_of(&n, &s, &[]).unwrap();
        assert!((volume(&m) - 6.0).abs() < 1e-9, "{}", volume(&m));
        let u = CsgNode::Union(vec![CsgNode::Solid(0), CsgNode::Solid(1)]);
        let m = mesh_of(&u, &s, &[]).unwrap();
        assert!((volume(&m) - 22.0).abs() < 1e-9, "{}", volume(&m));
        let i = CsgNode::Intersection(vec![CsgNode::Solid(0), CsgNode::Solid(1)]);
        let m = mesh_of(&i, &s, &[]).unwrap();
        assert!((volume(&m) - 2.0).abs() < 1e-9, "{}", volume(&m));
    }

    #[test]
    fn empty_parts() {
        let s = [cube([0.0; 3], [1.0; 3]), cube([5.0; 3], [6.0; 3])];
        let i = CsgNode::Intersection(vec![CsgNode::Solid(0), CsgNode::Solid(1)]);
        assert!(mesh_of(&i, &s, &[]).unwrap().is_empty());
        let d = CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Empty]);
        assert!((volume(&mesh_of(&d, &s, &[]).unwrap()) - 1.0).abs() < 1e-9);
        assert!(mesh_of(&CsgNode::Empty, &s, &[]).unwrap().is_empty());
    }

    #[test]
    fn a_deep_tree_is_walked_without_recursion() {
        let s = [cube([0.0; 3], [2.0; 3]), cube([1.0; 3], [3.0; 3])];
        let mut n = CsgNode::Solid(1);
        for _ in 0..5000 {
            n = CsgNode::Union(vec![n]);
        }
        let n = CsgNode::Difference(vec![CsgNode::Solid(0), n]);
        let m = mesh_of(&n, &s, &[]).unwrap();
        assert!((volume(&m) - 7.0).abs() < 1e-9);
    }

    #[test]
    fn an_import_with_a_mesh_is_used_and_one_without_is_refused() {
        let s = [cube([0.0; 3], [1.0; 3])];
        let imp = |mesh| Import {
            file: "part.stl".into(),
            threshold: None,
            matrix: Some([
                [1.0, 0.0, 0.0, 0.5],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ]),
            colour: None,
            line: 3,
            col: 1,
            mesh,
            footprint: None,
        };
        let tris: Vec<[[f64; 3]; 3]> = solid_triangles(&s[0])
            .iter()
            .map(|t| t.map(|v| v.to_array()))
            .collect();
        let with = [imp(Some(std::sync::Arc::new(tris)))];
        let n = CsgNode::Union(vec![CsgNode::Solid(0), CsgNode::Solid(IMPORTED)]);
        let m = mesh_of(&n, &s, &with).unwrap();
        assert!((volume(&m) - 1.5).abs() < 1e-9);
        let without = [imp(None)];
        let e = mesh_of(&n, &s, &without).unwrap_err();
        assert!(e.to_string().contains("part.stl"), "{e}");
    }

    #[test]
    fn mesh_plus_box_covers_the_sum() {
        // An L (a 2×2×1 slab minus its +x+y quarter) ⊕ a unit cube: volume of the sum of an
        // L-shaped prism and a cube = 3·... checked through mesh_of of the union of pieces.
        let s = [
            cube([0.0; 3], [2.0, 2.0, 1.0]),
            cube([1.0, 1.0, -1.0], [3.0, 3.0, 2.0]),
        ];
        let x = mesh_of(
            &CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(1)]),
            &s,
            &[],
        )
        .unwrap();
        let c = Polytope::of_solid(&cube([0.0; 3], [1.0; 3]));
        let (pieces, _) = minkowski3(&[Piece::Mesh(x)], &[Piece::Convex(c)], 1 << 20).unwrap();
        // The union of the pieces, through mesh_of: the L of arms 3 wide... = 3×3×2 minus
        // the 1×1×2 corner at [2,3]².
        let mut solids = vec![];
        let mut imports = vec![];
        let mut leaves = vec![];
        for p in &pieces {
            match p {
                Piece::Convex(p) => {
                    solids.push(p.clone().solid(None, 1));
                    leaves.push(CsgNode::Solid(solids.len() - 1));
                }
                Piece::Mesh(m) => {
                    imports.push(Import {
                        file: "m".into(),
                        threshold: None,
                        matrix: None,
                        colour: None,
                        line: 1,
                        col: 1,
                        footprint: None,
                        mesh: Some(std::sync::Arc::new(
                            m.iter().map(|t| t.map(|v| v.to_array())).collect(),
                        )),
                    });
                    leaves.push(CsgNode::Solid(IMPORTED + imports.len() - 1));
                }
            }
        }
        let m = mesh_of(&CsgNode::Union(leaves), &solids, &imports).unwrap();
        assert!((volume(&m) - 16.0).abs() < 1e-6, "{}", volume(&m));
    }

    // The hull of the fan-filtered sums against the hull of all pairwise sums.

    use crate::hull::tests::volume as hull_volume;

    /// hull(sum_points(x, y)) is hull(all_sums(x, y)): the same vertices, the same volume.
    fn same_sum(x: &[DVec3], y: &[DVec3]) {
        same_sum_of_fans(x, y, (Fan::of(x), Fan::of(y)));
    }

    /// [`same_sum`] with the two fans given.
    fn same_sum_of_fans(x: &[DVec3], y: &[DVec3], fans: (Option<Fan>, Option<Fan>)) {
        let all = all_sums(x, y);
        let Ok((v0, f0)) = hull3(&all) else {
            return;
        };
        let kept = match fans {
            (Some(a), Some(b)) => a.sum_vertices(&b),
            _ => return,
        };
        let (v1, f1) = hull3(&kept).unwrap();
        let scale = all
            .iter()
            .map(|p| p.abs().max_element())
            .fold(1.0, f64::max);
        let (a, b) = (hull_volume(&v0, &f0), hull_volume(&v1, &f1));
        assert!((a - b).abs() <= 1e-9 * scale.powi(3), "{a} vs {b}");
        // Every vertex of the full hull within the kept points' hull (the kept points are
        // sums, so inside the full hull): one hull.
        for p in &v0 {
            let out = f1
                .iter()
                .map(|f| {
                    let n: DVec3 = (0..f.len())
                        .map(|k| v1[f[k]].cross(v1[f[(k + 1) % f.len()]]))
                        .sum::<DVec3>()
                        .normalize();
                    n.dot(*p - v1[f[0]])
                })
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                out <= 1e-9 * scale,
                "vertex {p} of the sum is {out} outside ({} of {} points kept)",
                kept.len(),
                all.len()
            );
        }
    }

    fn sphere(r: f64, n: usize, centre: DVec3) -> Vec<DVec3> {
        // OpenSCAD's layout: n fragments, n / 2 rings off the poles.
        let rings = n.div_ceil(2);
        let mut out = vec![];
        for i in 0..rings {
            let phi = std::f64::consts::PI * (i as f64 + 0.5) / rings as f64;
            for k in 0..n {
                let th = std::f64::consts::TAU * k as f64 / n as f64;
                out.push(
                    centre + r * DVec3::new(phi.sin() * th.cos(), phi.sin() * th.sin(), phi.cos()),
                );
            }
        }
        out
    }

    fn corners(lo: DVec3, hi: DVec3) -> Vec<DVec3> {
        cube(lo.to_array(), hi.to_array())
            .vertices
            .iter()
            .map(|&v| DVec3::from(v))
            .collect()
    }

    #[test]
    fn fan_sums_keep_every_vertex_of_boxes_spheres_and_triangles() {
        let s = sphere(2.797, 45, DVec3::ZERO);
        let b = corners(DVec3::new(-1.0, 0.0, 2.0), DVec3::new(3.0, 0.5, 2.25));
        same_sum(&b, &s);
        same_sum(&s, &b);
        // Boxes: cones meeting only along their boundaries everywhere.
        same_sum(&b, &corners(DVec3::ZERO, DVec3::ONE));
        same_sum(&s, &sphere(1.0, 12, DVec3::new(5.0, 0.0, 1.0)));
        // Triangles: in a coordinate plane, along a sphere's ring, tilted.
        for t in [
            [DVec3::ZERO, DVec3::X, DVec3::Y],
            [DVec3::ZERO, DVec3::Z * 3.0, DVec3::new(1.0, 0.0, 0.0)],
            [
                DVec3::new(0.3, 0.1, 7.0),
                DVec3::new(2.0, -1.0, 6.5),
                DVec3::new(1.0, 4.0, 5.0),
            ],
        ] {
            same_sum(&t, &s);
            same_sum(&s, &t);
            same_sum(&t, &b);
        }
        // Fewer points than all sums.
        let kept = Fan::of(&b).unwrap().sum_vertices(&Fan::of(&s).unwrap());
        assert!(kept.len() * 4 < b.len() * s.len(), "{}", kept.len());
    }

    #[test]
    fn fan_sums_in_parallel_are_the_sums_in_turn() {
        let s = Fan::of(&sphere(2.797, 45, DVec3::ZERO)).unwrap();
        let t = Fan::of(&sphere(1.0, 12, DVec3::new(5.0, 0.0, 1.0))).unwrap();
        let b = Fan::of(&corners(DVec3::ZERO, DVec3::new(1.0, 2.0, 0.5))).unwrap();
        for (x, y) in [(&s, &t), (&t, &s), (&b, &s), (&s, &b)] {
            let bits = |v: Vec<DVec3>| v.iter().map(|p| p.to_array().map(f64::to_bits)).collect();
            let (a, c): (Vec<_>, Vec<_>) = (
                bits(x.sum_vertices_in(y, true)),
                bits(x.sum_vertices_in(y, false)),
            );
            assert!(a.len() > x.v.len().max(y.v.len()), "{}", a.len());
            assert_eq!(a, c);
        }
        // The sphere pair is past the size summed in parallel.
        assert!(s.v.len() * t.v.len() >= PARALLEL_SUMS);
    }

    #[test]
    fn a_mesh_plus_a_sphere_is_the_union_of_the_same_pieces() {
        // mesh_plus_convex through the fans against the hulls of all sums, patch by patch.
        let s = sphere(0.7, 20, DVec3::new(0.1, 0.0, 0.0));
        let x = solid_triangles(&cube([0.0; 3], [2.0, 3.0, 1.0]));
        let patches = convex_patches(&x);
        let mut out = vec![];
        mesh_plus_convex(&x, &Polytope::hull(&s).unwrap(), &mut out).unwrap();
        assert_eq!(out.len(), patches.len() + 1);
        for (f, p) in patches.iter().zip(&out[1..]) {
            let Piece::Convex(p) = p else { panic!() };
            let (v0, f0) = hull3(&all_sums(f, &s)).unwrap();
            let (v1, f1) = (&p.v, &p.faces);
            let (a, b) = (hull_volume(&v0, &f0), hull_volume(v1, f1));
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }

    /// Area of a flat polygon (Newell's normal's length, halved).
    fn area(f: &[DVec3]) -> f64 {
        let n: DVec3 = (0..f.len()).map(|k| f[k].cross(f[(k + 1) % f.len()])).sum();
        n.length() / 2.0
    }

    #[test]
    fn patches_are_convex_and_cover_the_triangles() {
        // A cube's twelve triangles are its six squares.
        let cube = solid_triangles(&cube([0.0; 3], [2.0, 3.0, 1.0]));
        let p = convex_patches(&cube);
        assert_eq!(p.iter().map(Vec::len).collect::<Vec<_>>(), [4; 6]);
        // An L-shaped prism (an extrusion of a concave outline, as the reader makes it):
        // each wall one rectangle, each cap convex pieces; every patch flat and convex
        // counter-clockwise about its triangles' normal, and the areas summed per plane
        // the triangles' own.
        let scene = crate::parse_csg(
            "linear_extrude(height = 2) polygon([[0,0],[3,0],[3,1],[1,1],[1,3],[0,3]]);",
            "t.csg",
        )
        .unwrap();
        let x: Mesh = match &scene.imports[..] {
            [i] => i
                .mesh
                .as_ref()
                .unwrap()
                .iter()
                .map(|t| t.map(DVec3::from))
                .collect(),
            _ => scene.solids.iter().flat_map(solid_triangles).collect(),
        };
        let mut p = convex_patches(&x);
        assert!(
            p.len() < x.len(),
            "{} patches of {} triangles",
            p.len(),
            x.len()
        );
        assert!(p.iter().filter(|f| f.len() == 4).count() >= 6);
        // A sphere's faces meet at angles of a few degrees, convex ones: each its own patch.
        let ball = crate::parse_csg("sphere(r = 1, $fn = 24);", "t.csg").unwrap();
        let ball = &ball.solids[0];
        let t = solid_triangles(ball);
        let q = convex_patches(&t);
        assert_eq!(q.len(), ball.faces.len());
        p.extend(q);
        let x: Mesh = x.into_iter().chain(t).collect();
        let plane = |n: DVec3| n.to_array().map(|c| (c * 1e6).round() as i64);
        let mut by_plane = std::collections::HashMap::new();
        for t in &x {
            let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize();
            *by_plane.entry(plane(n)).or_insert(0.0) += area(t);
        }
        for f in &p {
            let n = (f[1] - f[0]).cross(f[2] - f[0]).normalize();
            for k in 0..f.len() {
                let [a, b, c] = [0, 1, 2].map(|j| f[(k + j) % f.len()]);
                assert!((b - a).cross(c - b).dot(n) >= -1e-12, "a corner turns back");
                assert!(n.dot(f[k] - f[0]).abs() < 1e-12, "off the plane");
            }
            *by_plane.get_mut(&plane(n)).unwrap() -= area(f);
        }
        assert!(
            by_plane.values().all(|a: &f64| a.abs() < 1e-9),
            "{by_plane:?}"
        );
    }

    #[test]
    fn a_solids_own_faces_give_the_fan_of_its_hull() {
        // Primitives as the reader makes them, each fan read from the solid's faces: every
        // pair sums to the hull of all pairwise sums.
        let text = "sphere(r = 2, $fn = 24); cylinder(h = 3, r1 = 2, r2 = 0, $fn = 30); \
                    multmatrix([[0.6,0,0.8,1],[0,1,0,2],[-0.8,0,0.6,0],[0,0,0,1]]) \
                    cylinder(h = 5, r = 1, $fn = 40); cube([1, 2, 3]); \
                    polyhedron(points = [[0,0,0],[2,0,0],[0,2,0],[0,0,2]], \
                    faces = [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]);";
        let scene = crate::parse_csg(text, "t.csg").unwrap();
        let solids: Vec<Polytope> = scene.solids.iter().map(Polytope::of_solid).collect();
        assert_eq!(solids.len(), 5);
        for (i, x) in solids.iter().enumerate() {
            assert!(x.faces_hold_fan(), "solid {i}");
            for y in &solids {
                same_sum_of_fans(&x.v, &y.v, (x.fan(), y.fan()));
            }
        }
        // A flat polytope's faces do not: its fan is refused as the hull refuses it.
        let square = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let flat = Polytope {
            v: square.iter().map(|&p| DVec3::from(p)).collect(),
            faces: vec![vec![0, 1, 2, 3], vec![3, 2, 1, 0]],
        };
        assert!(!flat.faces_hold_fan());
        assert!(flat.fan().is_none());
    }

    #[test]
    fn cones_that_only_touch_are_not_summed() {
        // A cylinder's rim and a sphere's rings share the axis and the sphere's meridians
        // every third side: cones touching along a ray or a plane, not sums' vertices. The
        // fan keeps the hull's vertices alone (counting touching cones as meeting kept 6×).
        let text = "cylinder(h = 7, r = 30.5, center = true, $fn = 150); sphere(r = 2, $fn = 50);";
        let scene = crate::parse_csg(text, "t.csg").unwrap();
        let [x, y] = [0, 1].map(|k| Polytope::of_solid(&scene.solids[k]));
        let kept = x.fan().unwrap().sum_vertices(&y.fan().unwrap());
        let hull = Polytope::hull(&kept).unwrap();
        assert_eq!(hull.v.len(), 3900);
        assert!(kept.len() <= hull.v.len() + 100, "{} kept", kept.len());
        same_sum_of_fans(&x.v, &y.v, (x.fan(), y.fan()));
    }

    use proptest::prelude::*;

    fn point() -> impl Strategy<Value = DVec3> {
        // Coarse coordinates make coplanar faces and parallel edges common.
        prop_oneof![
            (-4i32..5, -4i32..5, -4i32..5)
                .prop_map(|(x, y, z)| DVec3::new(x as f64, y as f64, z as f64) * 0.5),
            (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z)),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        #[test]
        fn fan_sums_match_all_sums(
            x in prop::collection::vec(point(), 3..24),
            y in prop::collection::vec(point(), 3..40),
        ) {
            same_sum(&x, &y);
        }

        #[test]
        fn fan_sums_of_spheres_and_boxes_match_all_sums(
            n in 3usize..30,
            r in 0.1..5.0f64,
            c in point(),
            lo in point(),
            d in point(),
        ) {
            let s = sphere(r, n, c);
            let b = corners(lo, lo + d.abs() + DVec3::splat(0.01));
            same_sum(&b, &s);
            same_sum(&s, &b);
        }
    }
}

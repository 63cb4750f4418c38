//! The caps of an extrusion and the orientation of its mesh.
//!
//! An extrusion's outlines (outer ones and their holes, as OpenSCAD's even-odd cleanup leaves
//! them) are closed at the ends by a triangulation of the shape itself: each outer outline
//! with the holes directly inside it, ear-clipped (`earcut`, holes bridged in), so the cap
//! covers the shape and nothing else. A fan from one vertex would cover the outline's interior
//! only by parity (its triangles fold over concave corners), which the array's crossing count
//! accepts but a mesh boolean (`mesh_of`), a shadow or a Minkowski sum of the triangles does
//! not.
//!
//! [`outward`] then turns the triangles of each closed part so every shared edge is run in
//! opposite directions by its two triangles and the part encloses positive volume.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use crate::linalg::{signed_area, Tri3};

/// One outline of a shape: its points and how many other outlines it lies inside (even: an
/// outer outline, odd: a hole).
pub(crate) struct Ring {
    pub points: Vec<DVec2>,
    pub depth: usize,
}

impl Ring {
    /// Inside an odd number of other outlines.
    pub fn is_hole(&self) -> bool {
        !self.depth.is_multiple_of(2)
    }
}

/// A corner of a cap triangle: (outline, point of that outline).
pub(crate) type Corner = (usize, usize);

/// The triangles covering the shape the rings bound (even-odd), each counter-clockwise.
/// An outer outline whose ear clipping does not cover its area or does not end on its edges
/// (self-touching or degenerate input) is closed by a fan instead, which still bounds it by
/// parity. Every outline is capped once: a hole belongs to the first outer outline one level
/// up that encloses it, and a hole no such outline encloses (outlines crossing each other, as
/// a raw `polygon` with several `paths` may have) is capped on its own, which by parity is
/// the even-odd fill.
///
/// The outlines are matched with their holes in order first; the shapes are then
/// triangulated in parallel (a line of text has one per glyph, and more for its holes) and
/// their triangles joined in that order.
pub(crate) fn cap(rings: &[Ring]) -> Vec<[Corner; 3]> {
    use rayon::prelude::*;
    let shapes = shapes(rings);
    let each = |(o, holes): &(usize, Vec<usize>)| ear_clipped_or_fan(rings, *o, holes);
    // A shape or two of a few corners each (a square, a ring) is capped where it is.
    let corners: usize = rings.iter().map(|r| r.points.len()).sum();
    match shapes.len() > 1 && corners >= PARALLEL_CORNERS {
        true => shapes.par_iter().map(each).collect::<Vec<_>>().concat(),
        false => shapes.iter().flat_map(each).collect(),
    }
}

/// The shapes a cap triangulates, in order: each outer outline with the holes it takes,
/// then each hole no outline took, alone.
fn shapes(rings: &[Ring]) -> Vec<(usize, Vec<usize>)> {
    let mut shapes: Vec<(usize, Vec<usize>)> = vec![];
    let mut capped = vec![false; rings.len()];
    for (o, outer) in rings.iter().enumerate() {
        if outer.is_hole() {
            continue;
        }
        let near = grown_box(&outer.points);
        let holes: Vec<usize> = (0..rings.len())
            .filter(|&h| !capped[h] && rings[h].depth == outer.depth + 1)
            .filter(|&h| rings[h].points.first().is_some_and(|&p| near(p)))
            .filter(|&h| encloses(&outer.points, &rings[h].points))
            .collect();
        holes.iter().for_each(|&h| capped[h] = true);
        shapes.push((o, holes));
    }
    for h in (0..rings.len()).filter(|&h| rings[h].is_hole() && !capped[h]) {
        shapes.push((h, vec![]));
    }
    shapes
}

/// The fewest corners of a cap whose shapes are triangulated in parallel.
const PARALLEL_CORNERS: usize = 256;

/// The fewest edges [`neighbours`] sorts in parallel.
const PARALLEL_EDGES: usize = 1 << 14;

/// Outline `o` with `holes` ear-clipped, or as fans where that fails.
fn ear_clipped_or_fan(rings: &[Ring], o: usize, holes: &[usize]) -> Vec<[Corner; 3]> {
    ear_clipped(rings, o, holes).unwrap_or_else(|| {
        fan(rings, o)
            .chain(holes.iter().flat_map(|&h| fan(rings, h)))
            .collect()
    })
}

/// Outline `o` with `holes` ear-clipped, or None when the triangles' area is not the shape's
/// or they do not end on the outlines' edges ([`bounded_by`]).
fn ear_clipped(rings: &[Ring], o: usize, holes: &[usize]) -> Option<Vec<[Corner; 3]>> {
    let mut corners: Vec<Corner> = vec![];
    let mut starts: Vec<usize> = vec![];
    for &r in std::iter::once(&o).chain(holes) {
        if r != o {
            starts.push(corners.len());
        }
        corners.extend((0..rings[r].points.len()).map(|i| (r, i)));
    }
    let at = |c: Corner| rings[c.0].points[c.1];
    let mut idx: Vec<usize> = vec![];
    earcut::Earcut::new().earcut(corners.iter().map(|&c| at(c).to_array()), &starts, &mut idx);
    let mut tris: Vec<[Corner; 3]> = idx
        .chunks_exact(3)
        .map(|t| {
            let t = [corners[t[0]], corners[t[1]], corners[t[2]]];
            if (at(t[1]) - at(t[0])).perp_dot(at(t[2]) - at(t[0])) < 0.0 {
                [t[0], t[2], t[1]]
            } else {
                t
            }
        })
        .collect();
    split_at_dropped(rings, &corners, &mut tris);
    let area = |r: usize| signed_area(&rings[r].points).abs();
    let want = area(o) - holes.iter().map(|&h| area(h)).sum::<f64>();
    let got: f64 = tris
        .iter()
        .map(|t| 0.5 * (at(t[1]) - at(t[0])).perp_dot(at(t[2]) - at(t[0])))
        .sum();
    let covers = (got - want).abs() <= 1e-9 * area(o).max(f64::MIN_POSITIVE);
    (covers && bounded_by(rings, o, holes, &tris)).then_some(tris)
}

/// Whether the cap's triangles end exactly on the outlines' edges, as the walls do: every
/// segment (by its end points' coordinates) in an even number of cap triangles and outline
/// edges together. The area alone misses a cap whose edges are not the walls' (an outline
/// touching itself, a point of one outline on an edge of another, earcut's cure of a local
/// self-intersection): the mesh would then not be closed.
fn bounded_by(rings: &[Ring], o: usize, holes: &[usize], tris: &[[Corner; 3]]) -> bool {
    let key = |p: DVec2| p.to_array().map(|c| (c + 0.0).to_bits());
    let mut odd: std::collections::HashSet<([u64; 2], [u64; 2])> = Default::default();
    let mut flip = |a: DVec2, b: DVec2| {
        let (a, b) = (key(a), key(b));
        if a != b && !odd.remove(&(a.min(b), a.max(b))) {
            odd.insert((a.min(b), a.max(b)));
        }
    };
    let at = |c: Corner| rings[c.0].points[c.1];
    for t in tris {
        let [a, b, c] = t.map(at);
        // A triangle with two corners at one point is dropped from the mesh (`push`).
        if a != b && b != c && c != a {
            flip(a, b);
            flip(b, c);
            flip(c, a);
        }
    }
    for &r in std::iter::once(&o).chain(holes) {
        let p = &rings[r].points;
        (0..p.len()).for_each(|i| flip(p[i], p[(i + 1) % p.len()]));
    }
    odd.is_empty()
}

/// The triangles split where ear clipping left an outline's edge out: earcut drops a point on
/// the straight line between its neighbours (after bridging holes, neighbours may belong to
/// different outlines) and runs one edge past it, but the walls end at every point, so the cap
/// must too. Each end of an outline edge no triangle has cuts the triangles whose edge it lies
/// on in two.
fn split_at_dropped(rings: &[Ring], corners: &[Corner], tris: &mut Vec<[Corner; 3]>) {
    let at = |c: Corner| rings[c.0].points[c.1];
    let mut edges: std::collections::HashSet<(Corner, Corner)> = std::collections::HashSet::new();
    for t in tris.iter() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.insert((a.min(b), a.max(b)));
        }
    }
    let next = |c: Corner| (c.0, (c.1 + 1) % rings[c.0].points.len());
    let missing = |c: Corner| {
        let prev = (
            c.0,
            (c.1 + rings[c.0].points.len() - 1) % rings[c.0].points.len(),
        );
        [next(c), prev]
            .iter()
            .any(|&d| !edges.contains(&(c.min(d), c.max(d))))
    };
    let ends: Vec<Corner> = corners.iter().copied().filter(|&c| missing(c)).collect();
    for p in ends {
        let mut t = 0;
        while t < tris.len() {
            let tri = tris[t];
            let edge = (0..3).find(|&k| on_segment(at(p), at(tri[k]), at(tri[(k + 1) % 3])));
            if let Some(k) = edge {
                let (a, b, w) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
                tris[t] = [a, p, w];
                tris.push([p, b, w]);
            }
            t += 1;
        }
    }
}

/// The outline without its parts of zero width, as OpenSCAD 2021.01 extrudes it: it
/// sanitizes every 2D leaf first (`GeometryEvaluator::visit(const LeafNode &)` calls
/// `ClipperUtils::sanitize`, whose `toPolygon2d` runs Clipper's `CleanPolygon`), which drops
/// a repeated point and the tip of a spike. A tip is a point where the outline turns straight
/// back: on the line through its neighbours (zero area with them, as earcut's `area`) but not
/// between them. earcut's `filter_points` drops such a point too, and the cap then ran from
/// one neighbour straight to the other while the walls still went out to the tip and back:
/// three edges of each cap in one triangle only (a zero-area outline, all its points on one
/// line, lost its whole cap the same way). A point between its neighbours on a straight line
/// is kept (OpenSCAD's walls have it; [`split_at_dropped`] puts it back into the cap). Fewer
/// than three points left: the outline bounds nothing, and is dropped.
pub(crate) fn unfolded(points: &[DVec2]) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::with_capacity(points.len());
    for &p in points {
        out.push(p);
        settle(&mut out);
    }
    // The same across the seam: the last points against the first ones.
    let mut start = 0;
    while out.len() - start >= 3 {
        let (a, b) = (out[out.len() - 1], out[start]);
        if a == b || folds(out[out.len() - 2], a, b) {
            out.pop();
        } else if folds(a, b, out[start + 1]) {
            start += 1;
        } else {
            out.drain(..start);
            return out;
        }
    }
    vec![]
}

/// Drops the last point while it repeats the one before, and the last but one while it is a
/// spike's tip (the points before them have neither).
fn settle(out: &mut Vec<DVec2>) {
    loop {
        let n = out.len();
        if n >= 2 && out[n - 1] == out[n - 2] {
            out.pop();
        } else if n >= 3 && folds(out[n - 3], out[n - 2], out[n - 1]) {
            out.remove(n - 2);
        } else {
            return;
        }
    }
}

/// Whether an outline running a → p → b turns straight back at p.
fn folds(a: DVec2, p: DVec2, b: DVec2) -> bool {
    (p - a).perp_dot(b - p) == 0.0 && (p - a).dot(b - p) < 0.0
}

/// Whether p lies strictly between a and b on their segment (within rounding).
fn on_segment(p: DVec2, a: DVec2, b: DVec2) -> bool {
    let len2 = (b - a).length_squared();
    let t = (p - a).dot(b - a);
    (p - a).perp_dot(b - a).abs() <= 1e-9 * len2 && t > 0.0 && t < len2
}

/// Outline `r` as a fan from its first point, each triangle counter-clockwise for an outer
/// outline (clockwise for a hole: by parity, they cancel).
fn fan(rings: &[Ring], r: usize) -> impl Iterator<Item = [Corner; 3]> + '_ {
    let n = rings[r].points.len();
    let ccw = signed_area(&rings[r].points) > 0.0;
    let turn = ccw != rings[r].is_hole();
    (1..n.saturating_sub(1)).map(move |i| {
        if turn {
            [(r, 0), (r, i), (r, i + 1)]
        } else {
            [(r, 0), (r, i + 1), (r, i)]
        }
    })
}

/// Whether outline `inner` lies inside outline `outer`, decided at inner's first point off
/// outer's boundary (then, failing that, at the middle of its first edge off it): the outlines
/// of a shape do not cross, but they may touch (a 2D union leaves two shapes meeting at a
/// corner as two outlines sharing that point), and a point on the boundary answers either way.
/// Asked at one fixed point, the outline of one of two triangles touching at a corner counted
/// as inside the other, a hole by its depth; and, asked again at the first point of the turned
/// hole, as a hole of nothing, so no cap closed it. False when all of inner is on outer.
pub(crate) fn encloses(outer: &[DVec2], inner: &[DVec2]) -> bool {
    let n = inner.len();
    let middles = (0..n).map(|i| (inner[i] + inner[(i + 1) % n]) * 0.5);
    inner
        .iter()
        .copied()
        .chain(middles)
        .find(|&p| !on_boundary(outer, p))
        .is_some_and(|p| inside(outer, p))
}

/// Whether a point may lie on or inside the outline: within its box grown by a millionth of
/// its size. A point outside is neither on an edge (within [`on_segment`]'s rounding, a
/// billionth of the edge) nor inside, so [`encloses`], which asks at inner's first point when
/// that is off the boundary, is false for an outline whose first point is outside: the box
/// spares the point-in-polygon test for every other outline of the shape (quadratic in the
/// outlines: a 4,000-character text spent seconds there).
fn grown_box(outline: &[DVec2]) -> impl Fn(DVec2) -> bool {
    let lo = outline.iter().fold(DVec2::INFINITY, |a, &p| a.min(p));
    let hi = outline.iter().fold(DVec2::NEG_INFINITY, |a, &p| a.max(p));
    let grow = DVec2::splat((hi - lo).max_element() * 1e-6);
    let (lo, hi) = (lo - grow, hi + grow);
    move |p| p.cmpge(lo).all() && p.cmple(hi).all()
}

/// Whether p is a point of the outline or lies on one of its edges (within rounding).
fn on_boundary(poly: &[DVec2], p: DVec2) -> bool {
    (0..poly.len()).any(|i| {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        p == a || on_segment(p, a, b)
    })
}

/// Point in polygon by crossings (even-odd).
pub(crate) fn inside(poly: &[DVec2], p: DVec2) -> bool {
    let mut odd = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            odd = !odd;
        }
    }
    odd
}

/// A corner's key: its coordinates' bits (a mesh's triangles share corners bit for bit).
pub(crate) fn key(p: DVec3) -> [u64; 3] {
    p.to_array().map(f64::to_bits)
}

/// The triangles turned so that, in each edge-connected part, every edge shared by exactly two
/// triangles is run in opposite directions, and each part encloses positive volume (outward by
/// the right-hand rule). An edge in more than two triangles does not connect parts.
///
/// Corners are numbered once (equal bits, one number) and each triangle's neighbours found by
/// sorting its edges, so the walk touches a few words per triangle: a map from edge keys to
/// triangle lists, the first form, cost a cache miss per probe and most of a long text's
/// extrusion (1.6 million triangles).
pub(crate) fn outward(tris: &mut [Tri3]) {
    let ids = corner_ids(tris);
    let neighbours = neighbours(&ids);
    let mut order = ids.clone();
    let mut seen = vec![false; tris.len()];
    for start in 0..tris.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let part = consistent_part(&ids, &mut order, &neighbours, start, &mut seen);
        // The part's triangles as turned: `order` follows the swaps.
        for &t in &part {
            if order[t] != ids[t] {
                tris[t].swap(1, 2);
            }
        }
        let volume: f64 = part
            .iter()
            .map(|&t| tris[t][0].dot(tris[t][1].cross(tris[t][2])))
            .sum();
        if volume < 0.0 {
            part.iter().for_each(|&t| tris[t].swap(1, 2));
        }
    }
}

/// Each triangle's corners as numbers, equal for corners equal bit for bit ([`key`]).
fn corner_ids(tris: &[Tri3]) -> Vec<[u32; 3]> {
    let fast = foldhash::fast::RandomState::default();
    let mut number: HashMap<[u64; 3], u32, _> = HashMap::with_capacity_and_hasher(tris.len(), fast);
    tris.iter()
        .map(|t| {
            t.map(|p| {
                let next = number.len() as u32;
                *number.entry(key(p)).or_insert(next)
            })
        })
        .collect()
}

/// For each triangle and edge k (corners k, k + 1 as first given), the triangle across it when
/// exactly two triangles share that edge, else `u32::MAX`.
fn neighbours(ids: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let undirected = |a: u32, b: u32| (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
    let mut edges: Vec<(u64, u32)> = Vec::with_capacity(3 * ids.len());
    for (t, c) in ids.iter().enumerate() {
        for k in 0..3 {
            edges.push((undirected(c[k], c[(k + 1) % 3]), (3 * t + k) as u32));
        }
    }
    // Each entry is unique (its triangle and edge), so either sort gives the same order.
    match edges.len() >= PARALLEL_EDGES {
        true => rayon::slice::ParallelSliceMut::par_sort_unstable(&mut edges[..]),
        false => edges.sort_unstable(),
    }
    let mut out = vec![[u32::MAX; 3]; ids.len()];
    for run in edges.chunk_by(|x, y| x.0 == y.0) {
        if let [(_, s), (_, r)] = run {
            let (s, r) = (*s as usize, *r as usize);
            out[s / 3][s % 3] = (r / 3) as u32;
            out[r / 3][r % 3] = (s / 3) as u32;
        }
    }
    out
}

/// The part reached from triangle `start` through edges of two triangles, each neighbour
/// turned (its corners 1 and 2 swapped in `order`, which starts as `ids`) to run the shared
/// edge against its predecessor.
fn consistent_part(
    ids: &[[u32; 3]],
    order: &mut [[u32; 3]],
    neighbours: &[[u32; 3]],
    start: usize,
    seen: &mut [bool],
) -> Vec<usize> {
    let mut part = vec![start];
    let mut todo = vec![start];
    while let Some(t) = todo.pop() {
        for k in 0..3 {
            let n = neighbours[t][k];
            if n == u32::MAX || seen[n as usize] {
                continue;
            }
            let n = n as usize;
            seen[n] = true;
            // The shared edge as t now runs it: t's corners k and k + 1 of its first order.
            let edge = (ids[t][k], ids[t][(k + 1) % 3]);
            let (a, b) = edge_as_run(&order[t], edge);
            if runs(&order[n], a, b) {
                order[n].swap(1, 2);
            }
            part.push(n);
            todo.push(n);
        }
    }
    part
}

/// Corners `a`, `b` of triangle `t` in the direction `t` runs them.
fn edge_as_run(t: &[u32; 3], (a, b): (u32, u32)) -> (u32, u32) {
    if runs(t, a, b) {
        (a, b)
    } else {
        (b, a)
    }
}

/// Whether the triangle runs from corner `a` to corner `b` along one of its edges.
fn runs(t: &[u32; 3], a: u32, b: u32) -> bool {
    (0..3).any(|k| t[k] == a && t[(k + 1) % 3] == b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn ring(points: &[[f64; 2]], depth: usize) -> Ring {
        Ring {
            points: points.iter().map(|&p| DVec2::from(p)).collect(),
            depth,
        }
    }

    fn area(rings: &[Ring], tris: &[[Corner; 3]]) -> f64 {
        let at = |c: Corner| rings[c.0].points[c.1];
        tris.iter()
            .map(|t| 0.5 * (at(t[1]) - at(t[0])).perp_dot(at(t[2]) - at(t[0])))
            .sum()
    }

    /// A grid of `n`² square rings of `k` points a side, each with a square hole holding
    /// an island: enough corners for the shapes to be capped in parallel.
    fn plate(n: usize, k: usize) -> Vec<Ring> {
        let square = |c: DVec2, h: f64, depth: usize| {
            let side =
                |a: DVec2, b: DVec2| (0..k).map(move |i| a + (b - a) * (i as f64 / k as f64));
            let p = [(-h, -h), (h, -h), (h, h), (-h, h)].map(|(x, y)| c + DVec2::new(x, y));
            let mut points: Vec<DVec2> = (0..4).flat_map(|i| side(p[i], p[(i + 1) % 4])).collect();
            if depth % 2 == 1 {
                points.reverse();
            }
            Ring { points, depth }
        };
        let centres = (0..n * n).map(|i| DVec2::new((i % n) as f64, (i / n) as f64) * 10.0);
        centres
            .flat_map(|c| [square(c, 4.0, 0), square(c, 2.0, 1), square(c, 1.0, 2)])
            .collect()
    }

    #[test]
    fn shapes_capped_in_parallel_are_those_capped_in_order() {
        let rings = plate(6, 8);
        assert!(rings.iter().map(|r| r.points.len()).sum::<usize>() >= PARALLEL_CORNERS);
        let shapes = shapes(&rings);
        // Each outer square with its hole, each island alone: 72 shapes.
        assert_eq!(shapes.len(), 72);
        let in_order: Vec<[Corner; 3]> = shapes
            .iter()
            .flat_map(|(o, holes)| ear_clipped_or_fan(&rings, *o, holes))
            .collect();
        assert_eq!(cap(&rings), in_order);
        // 36 frames of area 64 - 16 and 36 islands of area 4.
        assert!((area(&rings, &in_order) - 36.0 * 52.0).abs() < 1e-9);
    }

    #[test]
    fn neighbours_sorted_in_parallel_are_each_edges_other_triangle() {
        // A strip of 2·m triangles over a row of m + 1 by 2 corners, closed into a band:
        // every edge but the band's two rims is shared by two triangles.
        let m = PARALLEL_EDGES;
        let at = |i: usize, top: bool| (2 * (i % m) + usize::from(top)) as u32;
        let ids: Vec<[u32; 3]> = (0..m)
            .flat_map(|i| {
                [
                    [at(i, false), at(i + 1, false), at(i + 1, true)],
                    [at(i, false), at(i + 1, true), at(i, true)],
                ]
            })
            .collect();
        assert!(3 * ids.len() >= PARALLEL_EDGES);
        let found = neighbours(&ids);
        // The reference: each undirected edge's triangles, from a map.
        let mut by_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
        for (t, c) in ids.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (c[k], c[(k + 1) % 3]);
                by_edge.entry((a.min(b), a.max(b))).or_default().push(t);
            }
        }
        let rims = found.iter().flatten().filter(|&&n| n == u32::MAX).count();
        assert_eq!(rims, 2 * m);
        for (t, n) in found.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (ids[t][k], ids[t][(k + 1) % 3]);
                let expected = match by_edge[&(a.min(b), a.max(b))][..] {
                    [u, v] => (if u == t { v } else { u }) as u32,
                    _ => u32::MAX,
                };
                assert_eq!(n[k], expected, "triangle {t} edge {k}");
            }
        }
    }

    #[test]
    fn a_concave_outline_is_covered_without_folds() {
        let l = [ring(
            &[[0., 0.], [5., 0.], [5., 5.], [4., 5.], [4., 1.], [0., 1.]],
            0,
        )];
        let tris = cap(&l);
        assert_eq!(tris.len(), 4);
        assert!((area(&l, &tris) - 9.0).abs() < 1e-12);
        let at = |c: Corner| l[0].points[c.1];
        for t in &tris {
            assert!((at(t[1]) - at(t[0])).perp_dot(at(t[2]) - at(t[0])) > 0.0);
        }
    }

    #[test]
    fn a_hole_is_left_open_and_an_island_in_it_is_capped() {
        let sq = |h: f64, d: usize| {
            let p = [[-h, -h], [h, -h], [h, h], [-h, h]];
            let mut r = ring(&p, d);
            if d % 2 == 1 {
                r.points.reverse();
            }
            r
        };
        let rings = [sq(3.0, 0), sq(2.0, 1), sq(1.0, 2)];
        let tris = cap(&rings);
        assert!((area(&rings, &tris) - (36.0 - 16.0 + 4.0)).abs() < 1e-12);
        assert!(tris
            .iter()
            .flatten()
            .all(|c| c.0 != 1 || rings[1].points.len() == 4));
    }

    fn cube_tris() -> Vec<Tri3> {
        let v = |i: usize| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64);
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        quads
            .iter()
            .flat_map(|q| [[v(q[0]), v(q[1]), v(q[2])], [v(q[0]), v(q[2]), v(q[3])]])
            .collect()
    }

    /// Every edge of a mesh run exactly once each way, and the volume it encloses.
    fn closed_volume(tris: &[Tri3]) -> Option<f64> {
        let mut runs: HashMap<([u64; 3], [u64; 3]), i32> = HashMap::new();
        for t in tris {
            for k in 0..3 {
                *runs.entry((key(t[k]), key(t[(k + 1) % 3]))).or_default() += 1;
            }
        }
        let closed = runs
            .iter()
            .all(|(&(a, b), &n)| n == 1 && runs.get(&(b, a)) == Some(&1));
        let vol = tris.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0;
        closed.then_some(vol)
    }

    /// A star outline of `k` points about `c`, radii alternating `r` and `r / 3`.
    fn star(c: DVec2, r: f64, k: usize, turn: f64) -> Vec<DVec2> {
        (0..2 * k)
            .map(|i| {
                let a = turn + std::f64::consts::PI * i as f64 / k as f64;
                let rr = if i % 2 == 0 { r } else { r / 3.0 };
                c + rr * DVec2::new(a.cos(), a.sin())
            })
            .collect()
    }

    #[test]
    fn a_part_turn_of_a_concave_outline_is_closed_and_outward() {
        let l = vec![
            DVec2::new(2.0, 0.0),
            DVec2::new(5.0, 0.0),
            DVec2::new(5.0, 3.0),
            DVec2::new(4.0, 3.0),
            DVec2::new(4.0, 1.0),
            DVec2::new(2.0, 1.0),
        ];
        let poly = crate::extrude::Poly2 { paths: vec![l] };
        let sc = |d: f64| d.to_radians().sin_cos();
        for angle in [90.0, -135.0, 360.0] {
            let tris = crate::extrude::rotate_mesh(&poly, angle, 24, &sc).unwrap();
            let vol = closed_volume(&tris).expect("closed");
            assert!(vol > 0.0, "{angle}: {vol}");
        }
    }

    proptest! {
        /// Any pattern of turned triangles of two cubes comes back outward: every edge run
        /// once each way, positive volume per cube.
        #[test]
        fn outward_undoes_any_turning(flips in proptest::collection::vec(any::<bool>(), 24)) {
            let mut tris = cube_tris();
            tris.extend(cube_tris().iter().map(|t| t.map(|p| p + DVec3::splat(3.0))));
            for (t, &f) in tris.iter_mut().zip(&flips) {
                if f {
                    t.swap(0, 1);
                }
            }
            outward(&mut tris);
            let vol: f64 = tris.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0;
            prop_assert!((vol - 2.0).abs() < 1e-12);
            let mut runs: HashMap<([u64; 3], [u64; 3]), i32> = HashMap::new();
            for t in &tris {
                for k in 0..3 {
                    *runs.entry((key(t[k]), key(t[(k + 1) % 3]))).or_default() += 1;
                }
            }
            prop_assert!(runs.iter().all(|(&(a, b), &n)| n == 1 && runs.get(&(b, a)) == Some(&1)));
        }

        /// A concave outline with holes and islands (stars in stars), extruded with any
        /// twist, scale and slices: closed, outward, and as large as its area times height.
        #[test]
        fn extrusions_are_closed_and_outward(
            k in 3usize..9,
            turn in 0.0f64..1.0,
            twist in prop_oneof![Just(0.0), -90.0f64..90.0],
            slices in 1usize..4,
            scale in 0.2f64..1.5,
            height in 0.5f64..3.0,
        ) {
            let outer = star(DVec2::ZERO, 10.0, k, turn);
            let mut hole = star(DVec2::ZERO, 3.0, k, turn + 0.3);
            hole.reverse();
            let island = star(DVec2::ZERO, 0.8, k, turn);
            let side = vec![DVec2::new(20.0, 0.0), DVec2::new(24.0, 0.0), DVec2::new(24.0, 1.0)];
            let poly = crate::extrude::Poly2 { paths: vec![outer.clone(), hole.clone(), island.clone(), side.clone()] };
            let l = crate::extrude::Linear { height, center: false, twist, slices, scale: [scale, scale] };
            let sc = |d: f64| d.to_radians().sin_cos();
            let tris = crate::extrude::linear_mesh(&poly, &l, &sc);
            let vol = closed_volume(&tris);
            prop_assert!(vol.is_some(), "not closed");
            let area = signed_area(&outer) - signed_area(&hole).abs() + signed_area(&island) + signed_area(&side);
            // A uniform scale s at the top: the area at height t is (1 + (s - 1) t)^2 times.
            let lift = (1.0 + scale + scale * scale) / 3.0;
            // Walls between twisted slices are not ruled by the interpolation: volume only
            // checked untwisted.
            let want = area * height * lift;
            let got = vol.unwrap();
            prop_assert!(got > 0.0);
            prop_assert!(twist != 0.0 || (got - want).abs() < 1e-9 * want, "{} vs {}", got, want);
        }
    }
}

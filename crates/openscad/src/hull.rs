//! Convex hulls: OpenSCAD's `hull()` of solids becomes one convex solid the array draws with
//! one plane per face (§5.2), and `hull()` of 2D shapes one convex polygon.
//!
//! The 3D hull is a quickhull with conflict lists: a tetrahedron whose faces each hold the
//! points outside them; the point farthest outside a face replaces the faces it sees (found by
//! a walk over face adjacency from that face) by a fan from their horizon, and the points the
//! removed faces held go to a new face they are outside of, or nowhere when now inside. A
//! point is so tested against the few faces near it rather than against every face, which
//! keeps the hull of a Minkowski sum's tens of thousands of points well under a second. The
//! tolerance is relative to the points' extent; a face the new point is all but on, that a
//! new face would fold back over, is removed too, so the surface stays convex. Coplanar
//! triangles are then merged into one polygon face (their outline), so the hull of a cube
//! has six faces and the display list six planes, and every edge is used once each way.

use csgpix_scene::Error;
use glam::{DVec2, DVec3};
use std::mem::take;

use csgpix_scene::Result;

/// Relative tolerance: a point closer than this times the extent to a face's plane is on it.
const EPS: f64 = 1e-9;

/// Most points of room a removed face's conflict list keeps for the face put in its slot.
const REUSED: usize = 16;

/// No face (an unset adjacency) or no point.
const NONE: usize = usize::MAX;

/// The convex hull of `points` as (vertices, faces), faces counter-clockwise seen from
/// outside. Err when the points span no volume (fewer than four, or all on a plane).
pub fn hull3(points: &[DVec3]) -> Result<(Vec<DVec3>, Vec<Vec<usize>>)> {
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
            (a.min(p), b.max(p))
        });
    let extent = (hi - lo).max_element();
    if !(extent.is_finite() && extent > 0.0) {
        return Err(Error::HullTooFewPoints);
    }
    let eps = EPS * extent;
    let tet = initial_tetrahedron(points, eps).ok_or(Error::FlatHull)?;
    let mut hull = Hull::new(points, eps, tet);
    hull.build();
    Ok(hull.merge_coplanar())
}

/// A triangle of the hull under construction.
struct Face {
    /// Corners, counter-clockwise seen from outside.
    v: [usize; 3],
    /// Unit outward normal and offset: the plane is `n·p = d`.
    n: DVec3,
    d: f64,
    /// `adj[k]` is the face across the edge `v[k] → v[k + 1]`.
    adj: [usize; 3],
    /// The conflict list: points outside this face that no other face holds.
    outside: Vec<usize>,
    /// False once removed (its slot is then reused).
    alive: bool,
    /// The pass that last found this face visible (or merged it), so that marks need no reset.
    mark: u32,
}

impl Face {
    fn new(points: &[DVec3], v: [usize; 3]) -> Face {
        let [a, b, c] = v.map(|i| points[i]);
        Face::with_normal(a, v, (b - a).cross(c - a).normalize_or_zero())
    }

    /// The face on corners `v`, the first at `a`, with unit normal `n` made as [`Face::new`]
    /// makes it.
    fn with_normal(a: DVec3, v: [usize; 3], n: DVec3) -> Face {
        Face {
            v,
            n,
            d: n.dot(a),
            adj: [NONE; 3],
            outside: vec![],
            alive: true,
            mark: 0,
        }
    }

    fn distance(&self, p: DVec3) -> f64 {
        self.n.dot(p) - self.d
    }

    /// The index k of the edge `a → b`, if the face has it.
    fn edge(&self, a: usize, b: usize) -> Option<usize> {
        (0..3).find(|&k| self.v[k] == a && self.v[(k + 1) % 3] == b)
    }
}

/// The hull under construction: its faces (dead ones kept as free slots) and scratch space.
struct Hull<'a> {
    points: &'a [DVec3],
    eps: f64,
    faces: Vec<Face>,
    free: Vec<usize>,
    /// The current pass, for [`Face::mark`].
    pass: u32,
    /// Per point: the new face whose horizon edge starts there, during one step.
    starts: Vec<usize>,
    /// One step's scratch, kept from step to step (a sum's hull adds thousands of points,
    /// nearly all of them vertices): the faces seen, their horizon, the faces a new face
    /// would fold over, the points handed on, the new faces.
    visible: Vec<usize>,
    horizon: Vec<(usize, usize, usize)>,
    folds: Vec<usize>,
    /// The unit normal of the new face each `horizon` edge would make ([`Self::folds`]).
    normals: Vec<DVec3>,
    moved: Vec<usize>,
    new: Vec<usize>,
}

impl<'a> Hull<'a> {
    /// The tetrahedron on `tet`, outward, with every other point in the conflict list of a
    /// face it is outside of.
    fn new(points: &'a [DVec3], eps: f64, tet: [usize; 4]) -> Hull<'a> {
        let mut hull = Hull {
            points,
            eps,
            faces: Vec::new(),
            free: Vec::new(),
            pass: 0,
            starts: vec![NONE; points.len()],
            visible: vec![],
            horizon: vec![],
            folds: vec![],
            normals: vec![],
            moved: vec![],
            new: vec![],
        };
        let centre = tet.iter().map(|&i| points[i]).sum::<DVec3>() / 4.0;
        for f in [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]] {
            let v = f.map(|k| tet[k]);
            let face = Face::new(points, v);
            let face = if face.distance(centre) > 0.0 {
                Face::new(points, [v[0], v[2], v[1]])
            } else {
                face
            };
            hull.faces.push(face);
        }
        for f in 0..4 {
            for k in 0..3 {
                let (a, b) = (hull.faces[f].v[k], hull.faces[f].v[(k + 1) % 3]);
                hull.faces[f].adj[k] = (0..4)
                    .find(|&g| hull.faces[g].edge(b, a).is_some())
                    .expect("a tetrahedron's faces share every edge");
            }
        }
        let rest = (0..points.len()).filter(|i| !tet.contains(i));
        hull.assign(rest, &[0, 1, 2, 3]);
        hull
    }

    /// Each point goes to the conflict list of the first of `faces` it is outside of.
    fn assign(&mut self, candidates: impl IntoIterator<Item = usize>, faces: &[usize]) {
        for i in candidates {
            let p = self.points[i];
            if let Some(&f) = faces
                .iter()
                .find(|&&f| self.faces[f].distance(p) > self.eps)
            {
                self.faces[f].outside.push(i);
            }
        }
    }

    /// The edges from the `visible` faces (marked `pass`) to the others, each with the face
    /// across it, into `horizon`.
    fn horizon(&self, visible: &[usize], pass: u32, horizon: &mut Vec<(usize, usize, usize)>) {
        horizon.clear();
        for &g in visible {
            let face = &self.faces[g];
            for k in 0..3 {
                let h = face.adj[k];
                if self.faces[h].mark != pass {
                    horizon.push((face.v[k], face.v[(k + 1) % 3], h));
                }
            }
        }
    }

    fn add_face(&mut self, face: Face) -> usize {
        match self.free.pop() {
            Some(f) => {
                // The slot's conflict list (emptied when its face was removed) keeps its
                // room for the new face's when small: at most REUSED points a slot, so the
                // room kept stays within a few times the faces' own.
                let outside = take(&mut self.faces[f].outside);
                self.faces[f] = match outside.capacity() <= REUSED {
                    true => Face { outside, ..face },
                    false => face,
                };
                f
            }
            None => {
                self.faces.push(face);
                self.faces.len() - 1
            }
        }
    }

    /// Adds points until no face has any outside it.
    fn build(&mut self) {
        let mut pending: Vec<usize> = (0..4).collect();
        while let Some(f) = pending.pop() {
            if !self.faces[f].alive || self.faces[f].outside.is_empty() {
                continue;
            }
            let far = self.farthest(f);
            match self.add_point(f, far) {
                true => pending.extend_from_slice(&self.new),
                false => {
                    // The faces it sees do not bound a disc, which only rounding among
                    // nearly coplanar faces could cause (no test meets it): the point is left
                    // out rather than the surface broken.
                    self.faces[f].outside.retain(|&i| i != far);
                    pending.push(f);
                }
            }
        }
    }

    /// The point of face `f`'s (non-empty) conflict list farthest outside it, the last of
    /// equals (as `Iterator::max_by`), each distance computed once.
    fn farthest(&self, f: usize) -> usize {
        let face = &self.faces[f];
        let mut best = (face.outside[0], face.distance(self.points[face.outside[0]]));
        for &i in &face.outside[1..] {
            let d = face.distance(self.points[i]);
            if best.1.total_cmp(&d) != std::cmp::Ordering::Greater {
                best = (i, d);
            }
        }
        best.0
    }

    /// Replaces the faces point `p` sees, starting from face `f`, by a fan from their horizon
    /// to `p`, the new faces in `self.new`; false when the horizon is not one loop (nothing
    /// changed).
    fn add_point(&mut self, f: usize, p: usize) -> bool {
        let (mut visible, mut horizon) = (take(&mut self.visible), take(&mut self.horizon));
        self.visible_region(f, self.points[p], &mut visible, &mut horizon);
        let simple = self.is_one_loop(&horizon);
        if simple {
            self.replace_by_fan(&visible, &horizon, p);
        }
        (self.visible, self.horizon) = (visible, horizon);
        simple
    }

    /// The faces point `at` sees from face `f` on (marked with a new pass), grown until no
    /// new face would fold over the faces beyond, into `visible`, with their horizon: the
    /// edges `(a, b, h)` to the unseen faces `h`.
    fn visible_region(
        &mut self,
        f: usize,
        at: DVec3,
        visible: &mut Vec<usize>,
        horizon: &mut Vec<(usize, usize, usize)>,
    ) {
        self.pass += 1;
        let pass = self.pass;
        self.faces[f].mark = pass;
        visible.clear();
        visible.push(f);
        let mut folds = take(&mut self.folds);
        let mut i = 0;
        loop {
            // The faces `at` is above (by more than the tolerance), over adjacency.
            while i < visible.len() {
                for g in self.faces[visible[i]].adj {
                    if self.faces[g].mark != pass && self.faces[g].distance(at) > self.eps {
                        self.faces[g].mark = pass;
                        visible.push(g);
                    }
                }
                i += 1;
            }
            self.horizon(visible, pass, horizon);
            self.folds(horizon, at, &mut folds);
            if folds.is_empty() {
                self.folds = folds;
                return;
            }
            for &h in &folds {
                if self.faces[h].mark != pass {
                    self.faces[h].mark = pass;
                    visible.push(h);
                }
            }
        }
    }

    /// The unseen faces of `horizon` a new face to `at` would fold back over: that face's
    /// third corner above it, or, `at` all but on that face's plane, facing the other way
    /// (`at` on the face's side of the edge). Those faces go too, into `folds`.
    fn folds(&mut self, horizon: &[(usize, usize, usize)], at: DVec3, folds: &mut Vec<usize>) {
        folds.clear();
        self.normals.clear();
        for &(a, b, h) in horizon {
            let [pa, pb] = [a, b].map(|i| self.points[i]);
            let face = &self.faces[h];
            // The new face's normal, as `Face::new` makes it for [a, b, at].
            let n = (pb - pa).cross(at - pa).normalize_or_zero();
            self.normals.push(n);
            let c = face.v.into_iter().find(|&i| i != a && i != b);
            if c.is_some_and(|c| n.dot(self.points[c] - pa) > self.eps)
                || (face.distance(at) > -self.eps && n.dot(face.n) < 0.0)
            {
                folds.push(h);
            }
        }
    }

    /// Whether `horizon` is one loop: every horizon vertex starts exactly one edge, and the
    /// walk along them from the first meets them all. When it is, `starts` holds each
    /// vertex's edge (to be cleared by the caller); else it is left clear.
    fn is_one_loop(&mut self, horizon: &[(usize, usize, usize)]) -> bool {
        let mut simple = !horizon.is_empty();
        for (n, &(a, _, _)) in horizon.iter().enumerate() {
            simple &= self.starts[a] == NONE;
            self.starts[a] = n;
        }
        if simple {
            let mut steps = 1;
            let mut v = horizon[0].1;
            while v != horizon[0].0 && steps <= horizon.len() {
                match self.starts[v] {
                    NONE => break,
                    k => v = horizon[k].1,
                }
                steps += 1;
            }
            simple = v == horizon[0].0 && steps == horizon.len();
        }
        if !simple {
            for &(a, _, _) in horizon {
                self.starts[a] = NONE;
            }
        }
        simple
    }

    /// The `visible` faces removed and a fan of new faces from each `horizon` edge to point
    /// `p` added, linked to each other (through `starts`, cleared after) and to the unseen
    /// faces; their outside points handed to the new faces. The new faces in `self.new`.
    fn replace_by_fan(&mut self, visible: &[usize], horizon: &[(usize, usize, usize)], p: usize) {
        let (mut moved, mut new) = (take(&mut self.moved), take(&mut self.new));
        moved.clear();
        for &g in visible {
            moved.append(&mut self.faces[g].outside);
            self.faces[g].alive = false;
            self.free.push(g);
        }
        new.clear();
        for (k, &(a, b, _)) in horizon.iter().enumerate() {
            let face = Face::with_normal(self.points[a], [a, b, p], self.normals[k]);
            new.push(self.add_face(face));
        }
        for (n, &(a, b, h)) in horizon.iter().enumerate() {
            let face = new[n];
            let k = self.faces[h]
                .edge(b, a)
                .expect("the unseen face shares the edge");
            self.faces[h].adj[k] = face;
            // The new face on the next horizon edge, b → c, shares the edge b → p.
            let next = new[self.starts[b]];
            self.faces[face].adj = [h, next, self.faces[face].adj[2]];
            self.faces[next].adj[2] = face;
        }
        for &(a, _, _) in horizon {
            self.starts[a] = NONE;
        }
        moved.retain(|&i| i != p);
        self.assign(moved.iter().copied(), &new);
        (self.moved, self.new) = (moved, new);
    }

    /// The faces left, the triangles of one plane merged into one polygon: the outline of the
    /// triangles, less the points on an edge between two corners (those only this face and
    /// its neighbour across that edge hold, so that both drop them). Only the points faces
    /// use are kept. Every edge of the result is so used once each way.
    fn merge_coplanar(&self) -> (Vec<DVec3>, Vec<Vec<usize>>) {
        let points = self.points;
        let (group_of, groups) = self.coplanar_groups();
        let outlines = self.group_outlines(&group_of, &groups);
        let holders = self.holders(&outlines, &groups);
        let keep = self.off_line_points(&outlines);
        let corner = |i: usize, keep: &[bool]| holders[i] != 2 || keep[i];
        // A face left with fewer than three corners keeps all its points.
        let keep = keep_three_corners(&outlines, keep, corner);
        let mut index = vec![NONE; points.len()];
        let mut vertices = vec![];
        let mut number = |i: usize| {
            if index[i] == NONE {
                index[i] = vertices.len();
                vertices.push(points[i]);
            }
            index[i]
        };
        let mut out = vec![];
        for (ring, group) in outlines.iter().zip(groups.iter()) {
            match ring.is_empty() {
                false => out.push(
                    ring.iter()
                        .filter(|&&i| corner(i, &keep))
                        .map(|&i| number(i))
                        .collect(),
                ),
                true => out.extend(
                    group
                        .iter()
                        .map(|&g| self.faces[g].v.iter().map(|&i| number(i)).collect()),
                ),
            }
        }
        (vertices, out)
    }

    /// The live faces grouped by plane: each seed's group the faces on its plane (their
    /// corners within the tolerance of it), over adjacency, as on a convex hull the
    /// triangles of one plane are connected. Each face's group, and the groups.
    fn coplanar_groups(&self) -> (Vec<usize>, Lists) {
        let (points, eps) = (self.points, self.eps);
        let mut group_of = vec![NONE; self.faces.len()];
        let mut groups = Lists::default();
        for seed in 0..self.faces.len() {
            if !self.faces[seed].alive || group_of[seed] != NONE {
                continue;
            }
            let (n, d) = (self.faces[seed].n, self.faces[seed].d);
            let id = groups.len();
            group_of[seed] = id;
            let mut i = groups.items.len();
            groups.items.push(seed);
            while i < groups.items.len() {
                for g in self.faces[groups.items[i]].adj {
                    let face = &self.faces[g];
                    if group_of[g] == NONE
                        && n.dot(face.n) > 0.0
                        && face.v.iter().all(|&i| (n.dot(points[i]) - d).abs() <= eps)
                    {
                        group_of[g] = id;
                        groups.items.push(g);
                    }
                }
                i += 1;
            }
            groups.close();
        }
        (group_of, groups)
    }

    /// Each group's outline, when its edges to other groups form one loop (else, only
    /// within the tolerance, its triangles stay apart: an empty outline).
    fn group_outlines(&self, group_of: &[usize], groups: &Lists) -> Lists {
        let mut outlines = Lists::default();
        let mut edges: Vec<(usize, usize)> = vec![];
        for (id, group) in groups.iter().enumerate() {
            edges.clear();
            edges.extend(group.iter().flat_map(|&g| {
                let face = &self.faces[g];
                (0..3)
                    .filter(|&k| group_of[face.adj[k]] != id)
                    .map(|k| (face.v[k], face.v[(k + 1) % 3]))
            }));
            edges.sort_unstable();
            one_loop(&edges, &mut outlines.items);
            outlines.close();
        }
        outlines
    }

    /// Per point, how many outlines hold it (saturating; the most for a point of a group
    /// left as triangles): a point two outlines hold and that lies on the line of its
    /// neighbours there is on the edge between the two faces.
    fn holders(&self, outlines: &Lists, groups: &Lists) -> Vec<u8> {
        let mut holders = vec![0u8; self.points.len()];
        for (ring, group) in outlines.iter().zip(groups.iter()) {
            match ring.is_empty() {
                false => ring
                    .iter()
                    .for_each(|&i| holders[i] = holders[i].saturating_add(1)),
                true => group
                    .iter()
                    .flat_map(|&g| self.faces[g].v)
                    .for_each(|i| holders[i] = u8::MAX),
            }
        }
        holders
    }

    /// The outline points off the line of their neighbours (by more than the tolerance).
    fn off_line_points(&self, outlines: &Lists) -> Vec<bool> {
        let points = self.points;
        let mut keep = vec![false; points.len()];
        for ring in outlines.iter() {
            for (k, &i) in ring.iter().enumerate() {
                let (u, w) = (
                    ring[(k + ring.len() - 1) % ring.len()],
                    ring[(k + 1) % ring.len()],
                );
                let line = points[w] - points[u];
                let off = (points[i] - points[u]).cross(line).length();
                if off.is_nan() || off > self.eps * line.length() {
                    keep[i] = true;
                }
            }
        }
        keep
    }
}

/// Lists of indices in one vector (a hull's thousands of groups and outlines without an
/// allocation each): list `i` is `items[ends[i - 1]..ends[i]]`, the first from 0.
#[derive(Default)]
struct Lists {
    items: Vec<usize>,
    ends: Vec<usize>,
}

impl Lists {
    fn len(&self) -> usize {
        self.ends.len()
    }

    /// Ends the list being built: the items pushed since the last one.
    fn close(&mut self) {
        self.ends.push(self.items.len());
    }

    fn iter(&self) -> impl Iterator<Item = &[usize]> {
        let starts = std::iter::once(0).chain(self.ends.iter().copied());
        starts.zip(&self.ends).map(|(a, &b)| &self.items[a..b])
    }
}

/// `keep` with every point of an outline that would be left with fewer than three corners
/// (by `corner`) kept, until no outline is.
fn keep_three_corners(
    outlines: &Lists,
    mut keep: Vec<bool>,
    corner: impl Fn(usize, &[bool]) -> bool,
) -> Vec<bool> {
    loop {
        let mut changed = false;
        for ring in outlines.iter().filter(|r| !r.is_empty()) {
            if ring.iter().filter(|&&i| corner(i, &keep)).count() < 3 {
                for &i in ring {
                    changed |= !keep[i];
                    keep[i] = true;
                }
            }
        }
        if !changed {
            return keep;
        }
    }
}

/// The points of directed `edges` (sorted) in order along them, pushed onto `ring`, when
/// they form one loop; else `ring` as it was.
fn one_loop(edges: &[(usize, usize)], ring: &mut Vec<usize>) {
    let start = ring.len();
    if !walk_loop(edges, ring) {
        ring.truncate(start);
    }
}

/// [`one_loop`]'s walk: whether it met every edge once, back where it started.
fn walk_loop(edges: &[(usize, usize)], ring: &mut Vec<usize>) -> bool {
    if edges.windows(2).any(|w| w[0].0 == w[1].0) {
        return false;
    }
    let Some(&(first, next)) = edges.first() else {
        return false;
    };
    let start = ring.len();
    ring.push(first);
    let mut at = next;
    while at != first {
        if ring.len() - start == edges.len() {
            return false;
        }
        ring.push(at);
        let Ok(k) = edges.binary_search_by_key(&at, |e| e.0) else {
            return false;
        };
        at = edges[k].1;
    }
    ring.len() - start == edges.len()
}

/// Four points spanning a volume: the extremes along X, the farthest from their line, the
/// farthest from their plane.
fn initial_tetrahedron(points: &[DVec3], eps: f64) -> Option<[usize; 4]> {
    let by = |key: &dyn Fn(DVec3) -> f64| {
        (0..points.len()).max_by(|&a, &b| key(points[a]).total_cmp(&key(points[b])))
    };
    let a = by(&|p| -p.x)?;
    let b = by(&|p| (p - points[a]).length_squared())?;
    let ab = (points[b] - points[a]).normalize_or_zero();
    let c = by(&|p| (p - points[a]).cross(ab).length_squared())?;
    let n = (points[b] - points[a])
        .cross(points[c] - points[a])
        .normalize_or_zero();
    let d = by(&|p| n.dot(p - points[a]).abs())?;
    let spans = (points[b] - points[a]).length() > eps
        && (points[c] - points[a]).cross(ab).length() > eps
        && n.dot(points[d] - points[a]).abs() > eps;
    spans.then_some([a, b, c, d])
}

/// The convex hull of 2D points, counter-clockwise, without collinear points (Andrew's
/// monotone chain). Fewer than three points when they span no area.
pub fn hull2(points: &[DVec2]) -> Vec<DVec2> {
    hull2_indices(points)
        .into_iter()
        .map(|i| points[i])
        .collect()
}

/// [`hull2`] as indices into `points`.
pub fn hull2_indices(points: &[DVec2]) -> Vec<usize> {
    let mut p: Vec<usize> = (0..points.len()).collect();
    let at = |i: usize| points[i];
    p.sort_by(|&a, &b| {
        at(a)
            .x
            .total_cmp(&at(b).x)
            .then(at(a).y.total_cmp(&at(b).y))
    });
    p.dedup_by(|a, b| at(*a) == at(*b));
    if p.len() < 3 {
        return p;
    }
    let cross = |o: usize, a: usize, b: usize| (at(a) - at(o)).perp_dot(at(b) - at(o));
    let mut h: Vec<usize> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let order: Vec<usize> = if pass == 0 {
            p.clone()
        } else {
            p.iter().rev().copied().collect()
        };
        for q in order {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    fn cube_points(lo: f64, hi: f64) -> Vec<DVec3> {
        (0..8)
            .map(|c| {
                DVec3::new(
                    if c & 1 == 0 { lo } else { hi },
                    if c & 2 == 0 { lo } else { hi },
                    if c & 4 == 0 { lo } else { hi },
                )
            })
            .collect()
    }

    /// The volume a closed polygon mesh encloses (faces counter-clockwise from outside).
    pub(crate) fn volume(v: &[DVec3], faces: &[Vec<usize>]) -> f64 {
        faces
            .iter()
            .map(|f| {
                (1..f.len() - 1)
                    .map(|i| v[f[0]].dot(v[f[i]].cross(v[f[i + 1]])) / 6.0)
                    .sum::<f64>()
            })
            .sum()
    }

    /// Every directed edge of the faces used once, and its reverse once.
    pub(super) fn closed(faces: &[Vec<usize>]) -> bool {
        let mut edges = std::collections::HashMap::new();
        for face in faces {
            for k in 0..face.len() {
                *edges
                    .entry((face[k], face[(k + 1) % face.len()]))
                    .or_insert(0) += 1;
            }
        }
        edges
            .iter()
            .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
    }

    #[test]
    fn two_cubes_hull_to_a_box_of_six_faces() {
        let mut p = cube_points(0.0, 1.0);
        p.extend(cube_points(0.0, 1.0).iter().map(|q| *q + DVec3::X * 3.0));
        p.push(DVec3::splat(0.5)); // inside
        let (v, f) = hull3(&p).unwrap();
        assert_eq!(f.len(), 6);
        assert_eq!(v.len(), 8);
        assert!((volume(&v, &f) - 4.0).abs() < 1e-12);
    }

    #[test]
    fn every_point_is_inside_every_face() {
        // Points on a sphere and inside it.
        let p: Vec<DVec3> = (0..200)
            .map(|i| {
                let (a, b) = (i as f64 * 2.399, (i as f64 * 0.61).sin());
                let r = if i % 3 == 0 { 0.5 } else { 1.0 };
                DVec3::new(
                    a.cos() * (1.0 - b * b).sqrt(),
                    a.sin() * (1.0 - b * b).sqrt(),
                    b,
                ) * r
            })
            .collect();
        let (v, f) = hull3(&p).unwrap();
        for face in &f {
            let [a, b, c] = [v[face[0]], v[face[1]], v[face[2]]];
            let n = (b - a).cross(c - a).normalize();
            assert!(p.iter().all(|q| n.dot(*q - a) <= 1e-9));
        }
        // Closed: every directed edge once, its reverse once.
        assert!(closed(&f));
    }

    #[test]
    fn flat_point_sets_are_refused() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(1.0, 1.0, 0.0)];
        assert!(hull3(&p).is_err());
        assert!(hull3(&[DVec3::ONE; 5]).is_err());
    }

    #[test]
    fn hull2_drops_inner_and_collinear_points() {
        let p = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
            DVec2::new(1.0, 1.0),
        ];
        let h = hull2(&p);
        assert_eq!(h.len(), 4);
        let area: f64 = (0..4).map(|i| h[i].perp_dot(h[(i + 1) % 4]) / 2.0).sum();
        assert_eq!(area, 4.0);
    }
}

/// Random point sets, near-degenerate ones among them, against the former incremental hull.
#[cfg(test)]
mod properties {
    use std::collections::HashSet;

    use proptest::prelude::*;

    use super::tests::{closed, volume};
    use super::*;

    /// The former algorithm, every point tested against every face, as the reference: the
    /// triangles it ends with before merging.
    fn incremental(points: &[DVec3], eps: f64) -> Vec<[usize; 3]> {
        let tet = initial_tetrahedron(points, eps).expect("spans a volume");
        let centre = tet.iter().map(|&i| points[i]).sum::<DVec3>() / 4.0;
        let mut faces: Vec<Face> = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
            .into_iter()
            .map(|f| {
                let v = f.map(|k| tet[k]);
                match Face::new(points, v) {
                    f if f.distance(centre) > 0.0 => Face::new(points, [v[0], v[2], v[1]]),
                    f => f,
                }
            })
            .collect();
        for (i, &p) in points.iter().enumerate() {
            if tet.contains(&i) {
                continue;
            }
            let seen: Vec<bool> = faces.iter().map(|f| f.distance(p) > eps).collect();
            if !seen.contains(&true) {
                continue;
            }
            let edges: HashSet<(usize, usize)> = faces
                .iter()
                .zip(&seen)
                .filter(|(_, s)| **s)
                .flat_map(|(f, _)| (0..3).map(|k| (f.v[k], f.v[(k + 1) % 3])))
                .collect();
            let mut kept: Vec<Face> = faces
                .into_iter()
                .zip(&seen)
                .filter(|(_, s)| !**s)
                .map(|(f, _)| f)
                .collect();
            for &(a, b) in &edges {
                if !edges.contains(&(b, a)) {
                    kept.push(Face::new(points, [a, b, i]));
                }
            }
            faces = kept;
        }
        faces.iter().map(|f| f.v).collect()
    }

    fn extent(points: &[DVec3]) -> f64 {
        let (lo, hi) = points
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
                (a.min(p), b.max(p))
            });
        (hi - lo).max_element()
    }

    /// Every property the hull must have, against `points`; Err names the first that fails.
    fn check(points: &[DVec3]) -> Result<(), String> {
        let Ok((v, faces)) = hull3(points) else {
            return match initial_tetrahedron(points, EPS * extent(points)) {
                None => Ok(()),
                Some(_) => Err(String::from("refused points that span a volume")),
            };
        };
        let size = extent(points);
        let inputs: HashSet<[u64; 3]> = points
            .iter()
            .map(|p| p.to_array().map(f64::to_bits))
            .collect();
        if !v
            .iter()
            .all(|p| inputs.contains(&p.to_array().map(f64::to_bits)))
        {
            return Err(String::from("a vertex is no input point"));
        }
        if faces.len() < 4 || faces.iter().any(|f| f.len() < 3) {
            return Err(format!("{} faces, or a face of fewer than 3", faces.len()));
        }
        if !closed(&faces) {
            return Err(String::from("not closed: an edge not used once each way"));
        }
        let used: HashSet<usize> = faces.iter().flatten().copied().collect();
        if used.len() != v.len() {
            return Err(String::from("a vertex no face uses"));
        }
        let tol = 1e-8 * size;
        for f in &faces {
            // Newell's normal: the polygon's area vector, outward for a counter-clockwise face.
            let n = (0..f.len())
                .map(|k| v[f[k]].cross(v[f[(k + 1) % f.len()]]))
                .sum::<DVec3>()
                .normalize();
            let c = f.iter().map(|&i| v[i]).sum::<DVec3>() / f.len() as f64;
            if let Some(q) = points.iter().find(|q| n.dot(**q - c) > tol) {
                let fv: Vec<DVec3> = f.iter().map(|&i| v[i]).collect();
                return Err(format!(
                    "{q} is {} outside a face {fv:?} n {n}",
                    n.dot(*q - c)
                ));
            }
        }
        let got = volume(&v, &faces);
        let reference = incremental(points, EPS * size);
        let want: f64 = reference
            .iter()
            .map(|t| points[t[0]].dot(points[t[1]].cross(points[t[2]])) / 6.0)
            .sum();
        if !(got > 0.0 && (got - want).abs() <= 1e-9 * size.powi(3)) {
            return Err(format!("volume {got}, the incremental hull's {want}"));
        }
        Ok(())
    }

    fn vec3(r: f64) -> impl Strategy<Value = DVec3> {
        (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
    }

    /// Point sets: uniform; on a sphere (and inside it); on a cube's faces; from a few points
    /// with repeats; on an integer grid; a Minkowski sum of a box and a sphere's rings.
    fn point_sets() -> impl Strategy<Value = Vec<DVec3>> {
        let uniform = prop::collection::vec(vec3(1.0), 4..120);
        let sphere = prop::collection::vec((0.0..6.3f64, -1.0..1.0f64, prop::bool::ANY), 4..150)
            .prop_map(|v| {
                v.into_iter()
                    .map(|(a, z, inner)| {
                        let r = (1.0 - z * z).sqrt();
                        DVec3::new(r * a.cos(), r * a.sin(), z) * if inner { 0.7 } else { 1.0 }
                    })
                    .collect()
            });
        let cube_faces = prop::collection::vec((vec3(1.0), 0..7usize), 4..150).prop_map(|v| {
            v.into_iter()
                .map(|(p, k)| match k {
                    0..=5 => {
                        let mut a = p.to_array();
                        a[k % 3] = if k < 3 { -1.0 } else { 1.0 };
                        DVec3::from_array(a)
                    }
                    _ => p,
                })
                .collect()
        });
        let repeats = (
            prop::collection::vec(vec3(1.0), 4..10),
            prop::collection::vec(0..10usize, 4..60),
        )
            .prop_map(|(base, picks)| picks.iter().map(|&i| base[i % base.len()]).collect());
        let grid = (
            prop::collection::vec((0..4i32, 0..4i32, 0..3i32), 4..64),
            0.01..100.0f64,
        )
            .prop_map(|(v, s)| {
                v.into_iter()
                    .map(|(x, y, z)| DVec3::new(x as f64, y as f64, z as f64) * s)
                    .collect()
            });
        let rounded_box = (vec3(3.0), 3..16usize, 0.05..1.0f64).prop_map(|(size, n, r)| {
            let rings = n.div_ceil(2);
            let sphere: Vec<DVec3> = (0..rings)
                .flat_map(|i| {
                    let phi = std::f64::consts::PI * (i as f64 + 0.5) / rings as f64;
                    (0..n).map(move |j| {
                        let t = std::f64::consts::TAU * j as f64 / n as f64;
                        DVec3::new(phi.sin() * t.cos(), phi.sin() * t.sin(), phi.cos()) * r
                    })
                })
                .collect();
            let corners = (0..8).map(move |c| {
                DVec3::new(
                    if c & 1 == 0 { 0.0 } else { size.x.abs() },
                    if c & 2 == 0 { 0.0 } else { size.y.abs() },
                    if c & 4 == 0 { 0.0 } else { size.z.abs() },
                )
            });
            corners
                .flat_map(|c| sphere.iter().map(move |&s| c + s).collect::<Vec<_>>())
                .collect()
        });
        prop_oneof![uniform, sphere, cube_faces, repeats, grid, rounded_box]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(600))]

        #[test]
        fn hull_is_closed_convex_and_of_the_reference_volume(points in point_sets()) {
            if let Err(e) = check(&points) {
                prop_assert!(false, "{e}");
            }
        }
    }

    /// The design that made the hull a quickhull: a box ⊕ a `$fn = 120` sphere, 57,600
    /// points, most of them corners.
    #[test]
    fn hull_of_a_rounded_box_of_57600_points() {
        let (n, rings) = (120, 60);
        let mut points = vec![];
        for c in 0..8 {
            let corner = DVec3::new(
                if c & 1 == 0 { 0.0 } else { 46.0 },
                if c & 2 == 0 { 0.0 } else { 246.0 },
                if c & 4 == 0 { 0.0 } else { 51.0 },
            );
            for i in 0..rings {
                let phi = std::f64::consts::PI * (i as f64 + 0.5) / rings as f64;
                for j in 0..n {
                    let t = std::f64::consts::TAU * j as f64 / n as f64;
                    points.push(corner + DVec3::new(t.cos(), t.sin(), 0.0) * 2.0 * phi.sin());
                    points.last_mut().unwrap().z += 2.0 * phi.cos();
                }
            }
        }
        let start = std::time::Instant::now();
        let (v, f) = hull3(&points).unwrap();
        eprintln!(
            "{} points: {} vertices, {} faces, {:?}",
            points.len(),
            v.len(),
            f.len(),
            start.elapsed()
        );
        assert!(closed(&f));
        // The volume of a box ⊕ a convex S: abc, plus the box's faces times S's widths, plus
        // its edges times S's shadows, plus S. S's rings are regular 120-gons with a corner
        // on +X (and so on ±X, ±Y): width 2·R (the widest ring's radius) along X and Y, the
        // outer rings' spread along Z; S is a stack of frusta between rings, each
        // h/6 · (A0 + 4·Am + A1) with Am the area of the mean ring.
        let (a, b, c) = (46.0, 246.0, 51.0);
        let ring = |i: usize| {
            let phi = std::f64::consts::PI * (i as f64 + 0.5) / rings as f64;
            (2.0 * phi.sin(), 2.0 * phi.cos())
        };
        let area = |r: f64| n as f64 / 2.0 * r * r * (std::f64::consts::TAU / n as f64).sin();
        let s_volume: f64 = (0..rings - 1)
            .map(|i| {
                let ((r0, z0), (r1, z1)) = (ring(i), ring(i + 1));
                (z0 - z1) / 6.0 * (area(r0) + 4.0 * area((r0 + r1) / 2.0) + area(r1))
            })
            .sum();
        let wide = ring(rings / 2).0;
        let (wx, wz) = (2.0 * wide, ring(0).1 - ring(rings - 1).1);
        // The shadow along X (or Y): the outline of (±r_i, z_i).
        let outline: Vec<DVec2> = (0..rings)
            .map(|i| DVec2::new(ring(i).0, ring(i).1))
            .chain((0..rings).rev().map(|i| DVec2::new(-ring(i).0, ring(i).1)))
            .collect();
        let side: f64 = (0..outline.len())
            .map(|k| outline[k].perp_dot(outline[(k + 1) % outline.len()]) / 2.0)
            .sum::<f64>()
            .abs();
        let want = a * b * c
            + a * b * wz
            + (b * c + c * a) * wx
            + (a + b) * side
            + c * area(wide)
            + s_volume;
        let got = volume(&v, &f);
        eprintln!("volume {got}, expected {want}");
        assert!((got - want).abs() < 1e-9 * want, "{got} against {want}");
        let t = std::time::Instant::now();
        for face in &f {
            let n = (0..face.len())
                .map(|k| v[face[k]].cross(v[face[(k + 1) % face.len()]]))
                .sum::<DVec3>()
                .normalize();
            let c = face.iter().map(|&i| v[i]).sum::<DVec3>() / face.len() as f64;
            let worst = points
                .iter()
                .map(|q| n.dot(*q - c))
                .fold(f64::MIN, f64::max);
            assert!(worst <= 1e-8 * 250.0, "{worst}");
        }
        eprintln!("inside {:?}", t.elapsed());
    }
}

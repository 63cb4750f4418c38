//! `projection(cut)` and `resize(newsize, auto)`, after OpenSCAD 2021.01
//! (`GeometryEvaluator::visit(ProjectionNode)`, `CGALUtils::project` in
//! `src/cgalutils-project.cc`, `PolysetUtils::project`; `CgaladvNode` RESIZE with
//! `PolySet::resize`, `CGAL_Nef_polyhedron::resize` and `Polygon2d::resize`).
//!
//! * `projection(cut = true)`: the section of the children at z = 0. OpenSCAD intersects the
//!   CGAL Nef polyhedron with the plane. Its Nef booleans are not regularized: a union or
//!   intersection of closed solids is closed, but a difference removes the subtracted solid
//!   with its boundary. So a face lying in z = 0 is in the section when it belongs to a solid
//!   (`cube(10)` gives its bottom face), not when the subtraction made it. Sections of closed
//!   sets commute with those set operations, so csgpix sections every leaf as a closed set
//!   (a convex solid: the hull of its points at z = 0; a closed mesh: the loops its triangles
//!   cut from the plane, taken just above and just below the plane when a vertex lies in it)
//!   and keeps the tree as a 2D tree, whose booleans agree with OpenSCAD's up to sets of no
//!   area.
//! * `projection(cut = false)`: the shadow on z = 0. OpenSCAD projects every triangle of each
//!   child's rendered mesh and unions them (Clipper, non-zero). csgpix unions shadows through
//!   unions, takes a convex solid's shadow as the 2D hull of its vertices, a mesh's as the
//!   union of its triangles (one `i_overlay` sweep, non-zero), and asks
//!   [`crate::geom::mesh_of`] for the mesh of a difference or intersection.
//! * `resize`: a scale about the origin from the exact bounding box (see [`resize_scale`]).
//!
//! An imported mesh file below either has been read by then (the reader reads the files
//! below `projection`, `hull`, `minkowski` and `resize` from the scene's folder); only a scene
//! given as text, with no folder, leaves it a file, which is refused here.

use csgpix_scene::{CsgError, Error};
use glam::{DVec2, DVec3};

use crate::cap::key;
use crate::extrude::{flatten, map_region, Poly2, Region};
use crate::hull::hull2;
use crate::memo::MeshMemo;
use crate::{frame::*, lex::*, linalg::*, node::*, primitives::*, tree::*};
use csgpix_scene::solid::{ConvexSolid, CsgNode, Import, IMPORTED};

/// A leaf of the tree being read.
enum Leaf<'a> {
    Convex(&'a ConvexSolid),
    Mesh(&'a [[[f64; 3]; 3]]),
    File(&'a Import),
}

fn leaf<'a>(i: usize, solids: &'a [ConvexSolid], imports: &'a [Import]) -> Leaf<'a> {
    if i < IMPORTED {
        return Leaf::Convex(&solids[i]);
    }
    let import = &imports[i - IMPORTED];
    match &import.mesh {
        Some(m) => Leaf::Mesh(m.as_slice()),
        None => Leaf::File(import),
    }
}

fn file_refused(what: &'static str, import: &Import) -> Error {
    Error::ImportNotSupported {
        operation: what,
        file: import.file.clone(),
    }
}

fn empty() -> Region {
    Region::Union(vec![])
}

// ---------------------------------------------------------------------------------------------
// Sections

/// The section of `node` by the plane z = 0, as a 2D tree (see the module documentation).
pub(crate) fn section(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
) -> csgpix_scene::Result<Region> {
    let parts = |c: &[CsgNode]| -> csgpix_scene::Result<Vec<Region>> {
        c.iter().map(|c| section(c, solids, imports)).collect()
    };
    Ok(match node {
        CsgNode::Empty => empty(),
        CsgNode::Union(c) => Region::Union(parts(c)?),
        CsgNode::Intersection(c) => Region::Intersection(parts(c)?),
        CsgNode::Difference(c) => Region::Difference(parts(c)?),
        CsgNode::Complement(_) => return Err(Error::Internal("a complement in a file")),
        CsgNode::Solid(i) => match leaf(*i, solids, imports) {
            Leaf::Convex(s) => {
                convex_section(s).map_or_else(empty, |p| Region::Poly(Poly2 { paths: vec![p] }))
            }
            Leaf::Mesh(m) => mesh_section(m),
            Leaf::File(f) => return Err(file_refused("projection(cut = true)", f)),
        },
    })
}

/// A convex solid's closed section at z = 0 (its face there, when it has one): the hull of its
/// vertices in the plane and of its edges' crossings; None when it has no area.
pub(crate) fn convex_section(s: &ConvexSolid) -> Option<Vec<DVec2>> {
    let v = |k: u32| DVec3::from(s.vertices[k as usize]);
    let mut pts: Vec<DVec2> = s
        .vertices
        .iter()
        .filter(|p| p[2] == 0.0)
        .map(|p| DVec2::new(p[0], p[1]))
        .collect();
    for f in &s.faces {
        for k in 0..f.len() {
            let (a, b) = (v(f[k]), v(f[(k + 1) % f.len()]));
            if (a.z < 0.0 && b.z > 0.0) || (a.z > 0.0 && b.z < 0.0) {
                pts.push(crossing(a, b));
            }
        }
    }
    let h = hull2(&pts);
    (h.len() >= 3).then_some(h)
}

/// Where segment a–b (one end below, one above) crosses z = 0, computed from its lower-sorted
/// end so both triangles of an edge agree bit for bit.
fn crossing(a: DVec3, b: DVec3) -> DVec2 {
    let (a, b) = if key(a) <= key(b) { (a, b) } else { (b, a) };
    let t = a.z / (a.z - b.z);
    DVec2::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
}

/// A closed mesh's closed section at z = 0: the loops its triangles cut from the plane, filled
/// even-odd. With a vertex in the plane, the sections just above and just below (vertices in
/// the plane counted below, then above) are taken together.
pub(crate) fn mesh_section(tris: &[[[f64; 3]; 3]]) -> Region {
    let on_plane = tris.iter().flatten().any(|p| p[2] == 0.0);
    let above = mesh_loops(tris, |z| z > 0.0);
    if !on_plane {
        return Region::Poly(above);
    }
    let below = mesh_loops(tris, |z| z >= 0.0);
    Region::Union(vec![Region::Poly(above), Region::Poly(below)])
}

type EdgeKey = ([u64; 3], [u64; 3]);

/// The loops where the triangles cross between the two sides `up` tells apart, chained
/// through the edges they cross (an edge of a closed mesh is in two triangles).
fn mesh_loops(tris: &[[[f64; 3]; 3]], up: impl Fn(f64) -> bool) -> Poly2 {
    use std::collections::HashMap;
    type Fast = foldhash::fast::RandomState;
    let mut ends: Vec<[EdgeKey; 2]> = vec![];
    let mut points: HashMap<EdgeKey, DVec2, Fast> = HashMap::default();
    for t in tris {
        let t = t.map(DVec3::from);
        let mut cut = vec![];
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if up(a.z) != up(b.z) {
                let e = if key(a) <= key(b) {
                    (key(a), key(b))
                } else {
                    (key(b), key(a))
                };
                points.entry(e).or_insert_with(|| crossing(a, b));
                cut.push(e);
            }
        }
        if let [e0, e1] = cut[..] {
            ends.push([e0, e1]);
        }
    }
    let mut at: HashMap<EdgeKey, Vec<usize>, Fast> = HashMap::default();
    for (s, e) in ends.iter().enumerate() {
        at.entry(e[0]).or_default().push(s);
        at.entry(e[1]).or_default().push(s);
    }
    let mut used = vec![false; ends.len()];
    let mut paths = vec![];
    for s0 in 0..ends.len() {
        if used[s0] {
            continue;
        }
        used[s0] = true;
        let start = ends[s0][0];
        let mut path = vec![points[&start]];
        let mut cur = ends[s0][1];
        while cur != start {
            path.push(points[&cur]);
            let Some(&s) = at[&cur].iter().find(|&&s| !used[s]) else {
                break;
            };
            used[s] = true;
            cur = if ends[s][0] == cur {
                ends[s][1]
            } else {
                ends[s][0]
            };
        }
        if path.len() >= 3 {
            paths.push(path);
        }
    }
    Poly2 { paths }
}

// ---------------------------------------------------------------------------------------------
// Shadows

/// The shadow of `node` on z = 0 (see the module documentation).
pub(crate) fn shadow(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
    memo: &mut MeshMemo,
) -> csgpix_scene::Result<Region> {
    Ok(match node {
        CsgNode::Empty => empty(),
        CsgNode::Union(c) => Region::Union(
            c.iter()
                .map(|c| shadow(c, solids, imports, memo))
                .collect::<Result<_, _>>()?,
        ),
        CsgNode::Solid(i) => match leaf(*i, solids, imports) {
            Leaf::Convex(s) => {
                let pts: Vec<DVec2> = s.vertices.iter().map(|p| DVec2::new(p[0], p[1])).collect();
                let h = hull2(&pts);
                if h.len() < 3 {
                    empty()
                } else {
                    Region::Poly(Poly2 { paths: vec![h] })
                }
            }
            Leaf::Mesh(m) => Region::Poly(triangles_shadow(m.iter().map(|t| t.map(DVec3::from)))),
            Leaf::File(f) => return Err(file_refused("projection()", f)),
        },
        _ => {
            let tris = memo.mesh_of(node, solids, imports)?;
            Region::Poly(triangles_shadow(tris.into_iter()))
        }
    })
}

/// The union of the triangles' shadows: every triangle turned counter-clockwise, all filled
/// non-zero in one `i_overlay` sweep. Triangles without area, or with less than 1e-12 of the
/// square of the shadow's extent (slivers of walls seen edge-on), are dropped: the overlay
/// snaps to an integer grid about 1e-9 of the extent fine, where slivers break its result into
/// thousands of fragments, and what they cover is below that grid.
///
/// A closed surface's shadow is covered by the triangles that face up alone (a vertical line
/// through the solid leaves it through one of them; or by those facing down, whichever way
/// it is wound), so of a closed mesh ([`closed`]) only the triangles turned counter-clockwise
/// go to the sweep: the others cover the same ground with outlines along the same lines,
/// which the sweep splits pair by pair (openscad-geb's letters seen from two sides: 62 and
/// 36 ms, now 0.5 ms each).
pub(crate) fn triangles_shadow(tris: impl Iterator<Item = [DVec3; 3]>) -> Poly2 {
    let tris: Vec<[DVec3; 3]> = tris.collect();
    shadow_of(&tris, closed(&tris))
}

/// The union of the shadows of `tris`' triangles, or of those turned counter-clockwise alone
/// when `one_side` ([`triangles_shadow`]).
fn shadow_of(tris: &[[DVec3; 3]], one_side: bool) -> Poly2 {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::single::SingleFloatOverlay;
    let flat: Vec<[DVec2; 3]> = tris
        .iter()
        .map(|t| t.map(|p| DVec2::new(p.x, p.y)))
        .collect();
    let (lo, hi) = flat
        .iter()
        .flatten()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let least = 1e-12 * (hi - lo).max_element().powi(2);
    let mut subj: Vec<Vec<[f64; 2]>> = vec![];
    for [a, b, c] in flat {
        let area = 0.5 * (b - a).perp_dot(c - a);
        if area > least {
            subj.push(vec![a.to_array(), b.to_array(), c.to_array()]);
        } else if area < -least && !one_side {
            subj.push(vec![a.to_array(), c.to_array(), b.to_array()]);
        }
    }
    let none: Vec<Vec<[f64; 2]>> = vec![];
    let shapes = subj.overlay(&none, OverlayRule::Subject, FillRule::NonZero);
    Poly2 {
        paths: shapes
            .into_iter()
            .flatten()
            .map(|c| c.into_iter().map(DVec2::from).collect())
            .collect(),
    }
}

/// Whether every edge of `tris` is run as often one way as the other (corners equal bit for
/// bit): a closed surface.
fn closed(tris: &[[DVec3; 3]]) -> bool {
    let key = |p: DVec3| p.to_array().map(|c| (c + 0.0).to_bits());
    let mut runs: std::collections::HashMap<_, i64, _> =
        std::collections::HashMap::with_capacity_and_hasher(
            3 * tris.len(),
            foldhash::fast::RandomState::default(),
        );
    for t in tris {
        for k in 0..3 {
            let (a, b) = (key(t[k]), key(t[(k + 1) % 3]));
            match a.cmp(&b) {
                std::cmp::Ordering::Less => *runs.entry((a, b)).or_default() += 1,
                std::cmp::Ordering::Greater => *runs.entry((b, a)).or_default() -= 1,
                std::cmp::Ordering::Equal => {}
            }
        }
    }
    runs.values().all(|&n| n == 0)
}

// ---------------------------------------------------------------------------------------------
// Bounding boxes and resize

/// A box, lowest and highest corner.
pub(crate) type Box3 = (DVec3, DVec3);

fn join(a: Option<Box3>, b: Option<Box3>) -> Option<Box3> {
    match (a, b) {
        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
        (a, None) => a,
        (None, b) => b,
    }
}

fn box_of(points: impl Iterator<Item = DVec3>) -> Option<Box3> {
    points.fold(None, |acc, p| join(acc, Some((p, p))))
}

/// The exact bounding box of `node`'s solid: through unions the leaves' boxes, of a
/// difference or intersection that of [`mesh_of`]. None when it is empty.
pub(crate) fn bbox3(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
    memo: &mut MeshMemo,
) -> csgpix_scene::Result<Option<Box3>> {
    match node {
        CsgNode::Empty => Ok(None),
        CsgNode::Union(c) => c.iter().try_fold(None, |acc, c| {
            Ok(join(acc, bbox3(c, solids, imports, memo)?))
        }),
        CsgNode::Solid(i) => match leaf(*i, solids, imports) {
            Leaf::Convex(s) => Ok(box_of(s.vertices.iter().map(|&p| DVec3::from(p)))),
            Leaf::Mesh(m) => Ok(box_of(m.iter().flatten().map(|&p| DVec3::from(p)))),
            Leaf::File(f) => Err(file_refused("resize()", f)),
        },
        _ => Ok(box_of(
            memo.mesh_of(node, solids, imports)?.into_iter().flatten(),
        )),
    }
}

/// The bounding box of a 2D tree (its booleans taken in the plane where they are not unions).
pub(crate) fn bbox2(r: &Region) -> Option<(DVec2, DVec2)> {
    let of = |pts: &mut dyn Iterator<Item = DVec2>| {
        pts.fold(None, |acc: Option<(DVec2, DVec2)>, p| {
            Some(acc.map_or((p, p), |(lo, hi)| (lo.min(p), hi.max(p))))
        })
    };
    match r {
        Region::Poly(p) => of(&mut p.points()),
        Region::Union(c) => c
            .iter()
            .filter_map(bbox2)
            .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))),
        _ => of(&mut flatten(r).points()),
    }
}

/// OpenSCAD 2021.01's resize factors for a box of `size` (the first `dims` axes): an axis with
/// a positive new size scales to it; another keeps its size, or with `auto` takes the factor of
/// the axis with the largest new size (the first of equals; 1 when no size is positive). None
/// when an axis to be resized has no extent (OpenSCAD warns and leaves the object as it is).
pub fn resize_scale(
    newsize: [f64; 3],
    auto: [bool; 3],
    size: [f64; 3],
    dims: usize,
) -> Option<[f64; 3]> {
    let mut scale = [1.0; 3];
    let mut max = 0;
    for i in 0..dims {
        if newsize[i] > newsize[max] {
            max = i;
        }
        if newsize[i] > 0.0 {
            if size[i] <= 0.0 {
                return None;
            }
            scale[i] = newsize[i] / size[i];
        }
    }
    let autoscale = scale[max];
    for i in 0..dims {
        if auto[i] && newsize[i] <= 0.0 {
            scale[i] = autoscale;
        }
    }
    Some(scale)
}

/// `CGAL_Nef_polyhedron::resize` (OpenSCAD 2021.01), the rule for a boolean's result: as
/// [`resize_scale`] but every nonzero entry scales its axis, a negative one too (a mirror
/// about the origin's plane, as OpenSCAD renders it); `None` where an axis to scale has no
/// extent (OpenSCAD leaves the object unchanged).
pub fn nef_resize_scale(
    newsize: [f64; 3],
    auto: [bool; 3],
    size: [f64; 3],
    dims: usize,
) -> Option<[f64; 3]> {
    let mut scale = [1.0; 3];
    let mut max = 0;
    for i in 0..dims {
        if newsize[i] != 0.0 {
            if size[i] == 0.0 {
                return None;
            }
            scale[i] = newsize[i] / size[i];
            if newsize[i] > newsize[max] {
                max = i;
            }
        }
    }
    let autoscale = match newsize[max] {
        0.0 => 1.0,
        n => n / size[max],
    };
    for i in 0..dims {
        if auto[i] && newsize[i] == 0.0 {
            scale[i] = autoscale;
        }
    }
    Some(scale)
}

/// The leaves of a tree.
pub(crate) fn leaves(n: &CsgNode) -> Vec<usize> {
    let mut out = vec![];
    let mut stack = vec![n];
    while let Some(n) = stack.pop() {
        match n {
            CsgNode::Solid(i) => out.push(*i),
            _ => stack.extend(n.children()),
        }
    }
    out
}

/// A finished `projection(cut)`: the section or shadow of its children, placed by the
/// transform above it; and the children's tree, whose leaves leave the scene.
pub(crate) fn projection(
    frame: Frame,
    solids: &[ConvexSolid],
    imports: &[Import],
    memo: &mut MeshMemo,
) -> Result<(Item, CsgNode), Fail> {
    let pos = frame.pos;
    if !frame.flats.is_empty() {
        let node = "projection";
        return fail(pos, CsgError::ChildDimension { node, flat: false });
    }
    let cut = match frame.spec {
        Spec::Projection { cut } => cut,
        _ => return fail(pos, Error::Internal("a projection without its parameters")),
    };
    let node = combine(Op::Union, frame.children);
    let region = if cut {
        section(&node, solids, imports)
    } else {
        shadow(&node, solids, imports, memo)
    }
    .map_err(|problem| Fail { pos, problem })?;
    let m = plane_part(frame.placement.as_ref());
    let region = map_region(region, &|p| p.transformed(m));
    Ok((Item::Flat(region, pos), node))
}

/// A finished `resize(newsize, auto)`: its children scaled about the origin from their
/// exact bounding box, then placed by the transform above it. The solids and imports below
/// it are moved in place.
pub(crate) fn resize(
    frame: Frame,
    solids: &mut [ConvexSolid],
    imports: &mut [Import],
    memo: &mut MeshMemo,
) -> Result<Item, Fail> {
    let pos = frame.pos;
    let Spec::Resize { newsize, auto } = frame.spec else {
        return fail(pos, Error::Internal("a resize without its parameters"));
    };
    if !frame.flats.is_empty() {
        return Ok(resize_flat(frame, newsize, auto));
    }
    let node = combine(Op::Union, frame.children);
    let bbox = bbox3(&node, solids, imports, memo).map_err(|problem| Fail { pos, problem })?;
    // OpenSCAD resizes one primitive's mesh (a PolySet) and a boolean's result (a Nef
    // polyhedron) by different rules, which differ only for a negative entry.
    let rule = match node {
        CsgNode::Solid(_) => resize_scale,
        _ => nef_resize_scale,
    };
    let s = match bbox {
        Some((lo, hi)) => rule(newsize, auto, (hi - lo).to_array(), 3).unwrap_or([1.0; 3]),
        None => [1.0; 3],
    };
    let mut m = [
        [s[0], 0.0, 0.0, 0.0],
        [0.0, s[1], 0.0, 0.0],
        [0.0, 0.0, s[2], 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    if let Some(outer) = &frame.placement {
        m = mat_mul(outer, &m);
    }
    move_leaves(&node, solids, imports, &m, (pos, RESIZED_PAST_LIMIT))?;
    Ok(Item::Solid(node))
}

/// A `resize` of 2D children: the union scaled about the origin from its exact bounding box
/// in x and y, then placed in the plane.
fn resize_flat(frame: Frame, newsize: [f64; 3], auto: [bool; 3]) -> Item {
    let pos = frame.pos;
    let at = frame.first_flat.unwrap_or(pos);
    let region = crate::flat::region_of(Op::Union, frame.flats);
    let s = match bbox2(&region) {
        Some((lo, hi)) => {
            let size = hi - lo;
            resize_scale(newsize, auto, [size.x, size.y, 0.0], 2).unwrap_or([1.0; 3])
        }
        None => [1.0; 3],
    };
    let m = plane_part(frame.placement.as_ref());
    let region = map_region(region, &|p| {
        p.transformed([[s[0], 0.0, 0.0], [0.0, s[1], 0.0]])
            .transformed(m)
    });
    Item::Flat(region, at)
}

/// A coordinate a `resize` takes past the limit.
const RESIZED_PAST_LIMIT: CsgError = CsgError::CoordinateLimit {
    what: "a coordinate",
    resized: true,
};

/// The solids and imports under `node` moved by `m` in place (faces reversed when `m`
/// mirrors); `past_limit` when a coordinate then passes the limit.
pub(crate) fn move_leaves(
    node: &CsgNode,
    solids: &mut [ConvexSolid],
    imports: &mut [Import],
    m: &Mat4,
    (pos, past_limit): (Pos, CsgError),
) -> Result<(), Fail> {
    let flip = det3(m) < 0.0;
    for i in leaves(node) {
        if i < IMPORTED {
            let solid = &mut solids[i];
            for v in &mut solid.vertices {
                *v = transform_point(m, *v);
            }
            if flip {
                solid.faces.reverse_each();
            }
            if solid.vertices.iter().flatten().any(|&c| too_large(c)) {
                return fail(pos, past_limit);
            }
            continue;
        }
        let import = &mut imports[i - IMPORTED];
        match &mut import.mesh {
            Some(mesh) => {
                let tris = std::sync::Arc::make_mut(mesh);
                for t in tris.iter_mut() {
                    *t = t.map(|v| transform_point(m, v));
                    if flip {
                        t.swap(1, 2);
                    }
                }
                if tris.iter().flatten().flatten().any(|&c| too_large(c)) {
                    return fail(pos, past_limit);
                }
            }
            None => {
                import.matrix = Some(match &import.matrix {
                    Some(inner) => mat_mul(m, inner),
                    None => *m,
                })
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extrude::signed_area;
    use crate::geom::mesh_of;
    use crate::{parse_csg, parse_csg_with, ReadOptions};
    use csgpix_scene::solid::CsgScene;

    fn strict() -> ReadOptions {
        ReadOptions {
            strict: true,
            ..Default::default()
        }
    }

    fn scene(text: &str) -> csgpix_scene::solid::CsgScene {
        parse_csg(text, "t.csg").unwrap_or_else(|e| panic!("{e}"))
    }

    /// The area a 2D tree covers (its booleans taken by `i_overlay`, whose outlines run
    /// counter-clockwise and holes clockwise).
    fn area(r: &Region) -> f64 {
        flatten(r).paths.iter().map(|p| signed_area(p)).sum()
    }

    type TreeToRegion = fn(&CsgNode, &[ConvexSolid], &[Import]) -> csgpix_scene::Result<Region>;

    /// The region of the file's tree, its imports renumbered from IMPORTED as while reading.
    fn tree_region(text: &str, f: TreeToRegion) -> csgpix_scene::Result<Region> {
        let s = scene(text);
        let mut root = s.root.clone();
        let first = s.solids.len();
        root.for_each_leaf_mut(|n| {
            if let CsgNode::Solid(i) = n {
                if *i >= first {
                    *i = IMPORTED + *i - first;
                }
            }
        });
        f(&root, &s.solids, &s.imports)
    }

    #[test]
    fn section_of_a_cube() {
        let r = tree_region("cube(size = [2, 4, 6], center = true);", section).unwrap();
        assert!((area(&r) - 8.0).abs() < 1e-12);
        // A face in the plane is in the section, from above and from below.
        let r = tree_region("cube(size = [2, 4, 6]);", section).unwrap();
        assert!((area(&r) - 8.0).abs() < 1e-12);
        let below =
            "multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,-6],[0,0,0,1]]) cube(size = [2, 4, 6]);";
        assert!((area(&tree_region(below, section).unwrap()) - 8.0).abs() < 1e-12);
        // Off the plane: nothing.
        let off = "multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,1],[0,0,0,1]]) cube(size = [2, 4, 6]);";
        assert_eq!(area(&tree_region(off, section).unwrap()), 0.0);
    }

    #[test]
    fn section_of_a_sphere_mesh_is_that_of_the_convex_sphere() {
        let s = scene("multmatrix([[1,0,0,0],[0,0.8,-0.6,0],[0,0.6,0.8,0.3],[0,0,0,1]]) sphere(r = 5, $fn = 16);");
        let convex = convex_section(&s.solids[0]).unwrap();
        let tris: Vec<[[f64; 3]; 3]> = mesh_of(&s.root, &s.solids, &[])
            .unwrap()
            .iter()
            .map(|t| t.map(|v| v.to_array()))
            .collect();
        let mesh = mesh_section(&tris);
        let a = signed_area(&convex);
        assert!(a > 60.0, "{a}");
        assert!((area(&mesh) - a).abs() < 1e-9 * a, "{} {a}", area(&mesh));
        // A mesh with vertices in the plane (a cube standing on it) gives its bottom face.
        let s = scene("cube(size = [2, 4, 6]);");
        let tris: Vec<[[f64; 3]; 3]> = mesh_of(&s.root, &s.solids, &[])
            .unwrap()
            .iter()
            .map(|t| t.map(|v| v.to_array()))
            .collect();
        assert!((area(&mesh_section(&tris)) - 8.0).abs() < 1e-12);
    }

    #[test]
    fn section_of_a_difference_follows_openscad() {
        // A 10×10 square minus a circle of 8 fragments, radius 3 (area 18·√2).
        let text = "difference() { cube(size = 10, center = true); \
                    cylinder(h = 20, r = 3, center = true, $fn = 8); }";
        let r = tree_region(text, section).unwrap();
        assert!(
            (area(&r) - (100.0 - 18.0 * 2f64.sqrt())).abs() < 1e-6,
            "{}",
            area(&r)
        );
        // A face the subtraction makes in the plane is not in the section (OpenSCAD's Nef
        // difference removes the subtracted solid's boundary), one an intersection makes is.
        let minus = "difference() { cube(size = 10, center = true); \
                     multmatrix([[1,0,0,-10],[0,1,0,-10],[0,0,1,0],[0,0,0,1]]) cube(size = 20); }";
        assert!(area(&tree_region(minus, section).unwrap()).abs() < 1e-12);
        let and = minus.replace("difference", "intersection");
        assert!((area(&tree_region(&and, section).unwrap()) - 100.0).abs() < 1e-12);
    }

    #[test]
    fn shadow_of_a_rotated_cube() {
        // 45° about x: the shadow is 2 wide and 2·√2 deep.
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let text = format!(
            "multmatrix([[1,0,0,0],[0,{c},-{c},0],[0,{c},{c},0],[0,0,0,1]]) cube(size = 2, center = true);"
        );
        let r = tree_region(&text, |n, s, i| shadow(n, s, i, &mut MeshMemo::default())).unwrap();
        assert!((area(&r) - 4.0 * 2f64.sqrt()).abs() < 1e-6, "{}", area(&r));
        // The same cube as a mesh: the union of its triangles' shadows.
        let s = scene(&text);
        let tris = mesh_of(&s.root, &s.solids, &[]).unwrap();
        let p = triangles_shadow(tris.into_iter());
        assert!((area(&Region::Poly(p)) - 4.0 * 2f64.sqrt()).abs() < 1e-6);
    }

    #[test]
    fn a_closed_meshs_shadow_is_that_of_its_triangles_facing_one_way() {
        // Overhangs (a wide cap on a stem, a notch from below), a rotation, either winding:
        // the shadow of the counter-clockwise triangles alone is that of all of them.
        let texts = [
            "union() { cylinder(h = 4, r = 1, $fn = 12); \
             multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]) cylinder(h = 1, r = 3, $fn = 12); }",
            "multmatrix([[0.6,0,0.8,0],[0,1,0,0],[-0.8,0,0.6,0],[0,0,0,1]]) difference() { \
             cube(size = [4, 3, 2]); multmatrix([[1,0,0,1],[0,1,0,-1],[0,0,1,-1],[0,0,0,1]]) \
             cube(size = [1, 5, 2]); }",
        ];
        for text in texts {
            let s = scene(text);
            let tris = mesh_of(&s.root, &s.solids, &[]).unwrap();
            assert!(closed(&tris));
            let all = area(&Region::Poly(shadow_of(&tris, false)));
            let up = area(&Region::Poly(shadow_of(&tris, true)));
            let turned: Vec<_> = tris.iter().map(|&[a, b, c]| [a, c, b]).collect();
            let down = area(&Region::Poly(shadow_of(&turned, true)));
            assert!(all > 1.0 && (up - all).abs() < 1e-9 && (down - all).abs() < 1e-9);
            // Without a triangle it is open: every triangle counts.
            assert!(!closed(&tris[1..]));
        }
    }

    #[test]
    fn projection_reads_and_consumes_its_children() {
        let s = scene(
            "cube(1); linear_extrude(height = 1) projection(cut = false, convexity = 0) \
             { sphere(r = 2, $fn = 8); }",
        );
        // The cube, and the shadow's prism; the sphere left the scene.
        assert_eq!(s.solids.len(), 2);
        let e = parse_csg("projection(cut = true) cube(1);", "t.csg").unwrap_err();
        assert!(e.to_string().contains("2D shape outside"), "{e}");
    }

    #[test]
    fn resize_rules() {
        let size = [2.0, 4.0, 5.0];
        // A zero entry keeps its axis, or with auto takes the largest new size's factor.
        assert_eq!(
            resize_scale([10.0, 0.0, 0.0], [false; 3], size, 3),
            Some([5.0, 1.0, 1.0])
        );
        assert_eq!(
            resize_scale([10.0, 0.0, 0.0], [true, false, true], size, 3),
            Some([5.0, 1.0, 5.0])
        );
        assert_eq!(
            resize_scale([1.0, 8.0, 0.0], [true; 3], size, 3),
            Some([0.5, 2.0, 2.0])
        );
        // No positive size: auto scales by 1.
        assert_eq!(resize_scale([0.0; 3], [true; 3], size, 3), Some([1.0; 3]));
        // A flat axis cannot be resized.
        assert_eq!(
            resize_scale([1.0, 0.0, 0.0], [false; 3], [0.0, 1.0, 1.0], 3),
            None
        );
        let s = scene(
            "resize(newsize = [10, 0, 0], auto = [1, 0, 1], convexity = 0) cube(size = [2, 4, 5]);",
        );
        let hi = s.solids[0].vertices.iter().fold([0.0f64; 3], |m, v| {
            [m[0].max(v[0]), m[1].max(v[1]), m[2].max(v[2])]
        });
        assert_eq!(hi, [10.0, 4.0, 25.0]);
        // Placed by the transform above it, after the resize.
        let s = scene(
            "multmatrix([[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) resize([4, 0, 0], true) cube(size = 2);",
        );
        let lo = s.solids[0]
            .vertices
            .iter()
            .fold(f64::MAX, |m, v| m.min(v[0]));
        let hz = s.solids[0]
            .vertices
            .iter()
            .fold(f64::MIN, |m, v| m.max(v[2]));
        assert_eq!((lo, hz), (1.0, 4.0));
        // A negative entry, with OpenSCAD 2021.01's boxes (its CGAL meshes of the same
        // scenes): ignored for one primitive, a mirror for a boolean's result.
        let bounds = |s: &CsgScene| {
            let mut b = [[f64::MAX, f64::MIN]; 3];
            for v in s.solids.iter().flat_map(|s| &s.vertices) {
                for i in 0..3 {
                    b[i] = [b[i][0].min(v[i]), b[i][1].max(v[i])];
                }
            }
            b
        };
        let s = parse_csg("resize([-2, 2, 2]) cube(1);", "t.csg").unwrap();
        assert_eq!(bounds(&s), [[0.0, 1.0], [0.0, 2.0], [0.0, 2.0]]);
        assert!(s.warnings[0].to_string().contains("negative size"));
        let text = "resize([-3, 2, 0]) union() { cube(1); \
                    multmatrix([[1,0,0,0.5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(1); }";
        let s = parse_csg(text, "t.csg").unwrap();
        assert_eq!(bounds(&s), [[-3.0, 0.0], [0.0, 2.0], [0.0, 1.0]]);
        assert!(parse_csg_with(text, "t.csg", &strict()).is_err());
        // 2D: a circle of radius 2 (8 fragments, 4 across) to 8 across, auto: 8 high too.
        let s = scene("linear_extrude(height = 1) resize(newsize = [8, 0, 0], auto = true) circle(r = 2, $fn = 8);");
        let ys = s.solids[0]
            .vertices
            .iter()
            .fold(f64::MIN, |m, v| m.max(v[1]));
        assert!((ys - 4.0).abs() < 1e-12, "{ys}");
    }

    #[test]
    fn bbox_of_a_difference() {
        // A 10-cube with its half x > 5 cut away: x spans 0..5.
        let text = "difference() { cube(size = 10); \
                    multmatrix([[1,0,0,5],[0,1,0,-1],[0,0,1,-1],[0,0,0,1]]) cube(size = 12); }";
        let s = scene(text);
        let (lo, hi) = bbox3(&s.root, &s.solids, &s.imports, &mut MeshMemo::default())
            .unwrap()
            .unwrap();
        assert!((lo - DVec3::ZERO).abs().max_element() < 1e-9);
        assert!((hi - DVec3::new(5.0, 10.0, 10.0)).abs().max_element() < 1e-9);
        // Through unions, the leaves' boxes.
        let s = scene("cube(1); multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) sphere(r = 1, $fn = 4);");
        let (lo, hi) = bbox3(&s.root, &s.solids, &s.imports, &mut MeshMemo::default())
            .unwrap()
            .unwrap();
        assert_eq!(lo.x, 0.0);
        assert!((hi.x - (3.0 + 0.5f64.sqrt())).abs() < 1e-12, "{hi}");
    }
}

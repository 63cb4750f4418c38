//! `cube`, `sphere`, `cylinder` and `polyhedron`, tessellated as OpenSCAD does.

use csgpix_scene::error::{CsgError, Rule};
use csgpix_scene::Error;
use glam::DVec3;
use std::collections::HashMap;
use std::f64::consts::PI;

use crate::{consts_::*, frame::*, lex::*, linalg::*, node::*, value::*};
use csgpix_scene::solid::{ConvexSolid, Faces};

// ---------------------------------------------------------------------------------------------
// Primitives

/// A convex solid in its own coordinates, faces counter-clockwise seen from outside.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Shape {
    pub(crate) vertices: Vec<Vec3>,
    pub(crate) faces: Faces,
}

/// Moves a shape into the scene: transform, keep faces outward, colour.
pub(crate) fn place(shape: Shape, ctx: &Ctx, pos: Pos) -> Result<ConvexSolid, Fail> {
    let Shape {
        mut vertices,
        mut faces,
    } = shape;
    if let Some(m) = &ctx.matrix {
        for v in &mut vertices {
            *v = transform_point(m, *v);
        }
        if det3(m) < 0.0 {
            faces.reverse_each();
        }
    }
    if vertices.iter().flatten().any(|&c| too_large(c)) {
        return fail(pos, coordinate_too_large(None));
    }
    if let Some(problem) = degenerate_extent(vertices.iter().copied()) {
        return fail(pos, problem);
    }
    Ok(ConvexSolid {
        vertices,
        faces,
        colour: ctx.colour,
        line: pos.line,
    })
}

/// `degenerate extent: …` when the box around `points` has a side that is positive but below
/// [`MIN_EXTENT`].
pub(crate) fn degenerate_extent(points: impl Iterator<Item = [f64; 3]>) -> Option<CsgError> {
    let (lo, hi) = points.fold(
        ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]),
        |(lo, hi), p| {
            (
                std::array::from_fn(|i| lo[i].min(p[i])),
                std::array::from_fn(|i| hi[i].max(p[i])),
            )
        },
    );
    let (axis, side) = ["x", "y", "z"]
        .into_iter()
        .zip((0..3).map(|i| hi[i] - lo[i]))
        .find(|&(_, side)| side > 0.0 && side < MIN_EXTENT)?;
    Some(CsgError::ThinSolid {
        side,
        axis,
        min: MIN_EXTENT,
        max: MAX_COORDINATE,
    })
}

/// A coordinate past [`MAX_COORDINATE`], shown when given.
pub(crate) fn coordinate_too_large(value: Option<f64>) -> CsgError {
    CsgError::CoordinateTooLarge {
        value,
        limit: MAX_COORDINATE,
    }
}

/// `fragments` past [`MAX_FRAGMENTS`] (`resolution`: counted from `$fn`, `$fa`, `$fs`).
pub(crate) fn too_many_fragments(fragments: f64, resolution: bool) -> CsgError {
    CsgError::TooManyFragments {
        fragments,
        limit: MAX_FRAGMENTS,
        resolution,
    }
}

/// Beyond [`MAX_COORDINATE`], or not a number at all.
pub(crate) fn too_large(c: f64) -> bool {
    c.is_nan() || c.abs() > MAX_COORDINATE
}

/// Refuses `vertices` more when only `budget` are left of the scene's limit
/// ([`crate::ReadOptions::max_vertices`]).
pub(crate) fn check_budget(vertices: usize, budget: usize, pos: Pos) -> Result<(), Fail> {
    if vertices > budget {
        let left = budget;
        return fail(pos, CsgError::VertexLimit { vertices, left });
    }
    Ok(())
}

/// `cube(size, center)`: size a number or `[x, y, z]`, default 1. Vertex `i` is at
/// `(i&1 ? x2 : x1, i&2 ? y2 : y1, i&4 ? z2 : z1)` and the faces are those of
/// `CubeNode::createGeometry`.
pub(crate) fn cube(params: &Params) -> Result<Option<Shape>, Fail> {
    let size = match params.get("size") {
        None => [1.0; 3],
        Some(v) => {
            let size = match v.kind {
                Kind::Num(s) => [s; 3],
                _ => v.vec3("`size`")?,
            };
            if size.iter().any(|&s| !(s > 0.0 && s.is_finite())) {
                return Ok(None);
            }
            size
        }
    };
    let (lo, hi) = if params.boolean("center")? {
        (size.map(|s| -s / 2.0), size.map(|s| s / 2.0))
    } else {
        ([0.0; 3], size)
    };
    let vertices = (0..8)
        .map(|i| {
            let pick = |bit: usize, axis: usize| if i & bit != 0 { hi[axis] } else { lo[axis] };
            [pick(1, 0), pick(2, 1), pick(4, 2)]
        })
        .collect();
    let faces = [
        [4, 5, 7, 6], // top
        [2, 3, 1, 0], // bottom
        [0, 1, 5, 4], // front
        [1, 3, 7, 5], // right
        [3, 2, 6, 7], // back
        [2, 0, 4, 6], // left
    ];
    let mut out = Faces::with_capacity(6, 24);
    out.extend(faces.iter().map(|f| f.iter().copied()));
    Ok(Some(Shape {
        vertices,
        faces: out,
    }))
}

/// `$fn`, `$fa`, `$fs` of a sphere or cylinder.
pub(crate) struct Resolution {
    pub(crate) fn_: f64,
    pub(crate) fa: f64,
    pub(crate) fs: f64,
}

impl Resolution {
    /// OpenSCAD's defaults are `$fn = 0, $fa = 12, $fs = 2`; `set_fragments` clamps `$fa` and
    /// `$fs` up to 0.01. Negative values are refused.
    pub(crate) fn read(params: &Params) -> Result<Self, Fail> {
        let get = |name: &str, default: f64| match params.number(name)? {
            None => Ok(default),
            Some((v, pos)) if v < 0.0 => fail(pos, must(&format!("`{name}`"), Rule::NotNegative)),
            Some((v, _)) => Ok(v),
        };
        Ok(Resolution {
            fn_: get("$fn", 0.0)?,
            fa: get("$fa", 12.0)?.max(F_MINIMUM),
            fs: get("$fs", 2.0)?.max(F_MINIMUM),
        })
    }

    /// OpenSCAD's `Calc::get_fragments_from_r` (`src/utils/calc.cc`), as a float so a huge
    /// count can be refused before it is converted.
    pub(crate) fn fragments_from_r(&self, r: f64) -> f64 {
        if r < GRID_FINE {
            return 3.0;
        }
        if self.fn_ > 0.0 {
            return if self.fn_ >= 3.0 {
                self.fn_.trunc()
            } else {
                3.0
            };
        }
        (360.0 / self.fa)
            .min(r * 2.0 * PI / self.fs)
            .max(5.0)
            .ceil()
    }

    pub(crate) fn fragments(&self, r: f64, pos: Pos) -> Result<usize, Fail> {
        let n = self.fragments_from_r(r);
        if n > MAX_FRAGMENTS as f64 {
            return fail(pos, too_many_fragments(n, true));
        }
        Ok(n as usize)
    }
}

/// A radius given as a diameter `d` or a radius `r`; the diameter wins, as in OpenSCAD's
/// `lookup_radius`.
pub(crate) fn radius(params: &Params, d: &str, r: &str) -> Result<Option<(f64, Pos)>, Fail> {
    if let Some((diameter, pos)) = params.number(d)? {
        return Ok(Some((diameter / 2.0, pos)));
    }
    params.number(r)
}

/// `sphere(r | d, $fn, $fa, $fs)` as `SphereNode::createGeometry`: `(fragments + 1) / 2` rings
/// at polar angles `180 (i + 0.5) / rings`, ring 0 at the top, each a circle of `fragments`
/// points; the top and bottom rings are polygon faces and neighbouring rings are joined by
/// quads.
pub(crate) fn sphere(params: &Params, budget: usize) -> Result<Option<Shape>, Fail> {
    let r = match radius(params, "d", "r")? {
        Some((r, _)) if !(r > 0.0 && r.is_finite()) => return Ok(None),
        Some((r, _)) => r,
        None => 1.0,
    };
    let fragments = Resolution::read(params)?.fragments(r, params.pos)?;
    let rings = fragments.div_ceil(2); // OpenSCAD's (fragments + 1) / 2
    check_budget(rings * fragments, budget, params.pos)?;
    let mut vertices = Vec::with_capacity(rings * fragments);
    for i in 0..rings {
        let phi = (180.0 * (i as f64 + 0.5)) / rings as f64;
        circle(
            &mut vertices,
            r * sin_degrees(phi),
            r * cos_degrees(phi),
            fragments,
        );
    }
    let at = |ring: usize, j: usize| ring * fragments + j % fragments;
    // Straight into one vector of indices, sized once: a sphere at the vertex limit has
    // 20 million faces, which as a heap vector each held 1.3 GB more while it was made.
    let quads = (rings - 1) * fragments;
    let mut faces = Faces::with_capacity(2 + quads, 2 * fragments + 4 * quads);
    faces.push(0..fragments);
    for i in 0..rings - 1 {
        for j in 0..fragments {
            faces.push([at(i, j + 1), at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
        }
    }
    faces.push((0..fragments).map(|j| rings * fragments - j - 1));
    Ok(Some(Shape { vertices, faces }))
}

/// `cylinder(h, r1, r2, center, r, d, d1, d2, $fn, $fa, $fs)` as `CylinderNode::createGeometry`:
/// defaults `h = 1, r = 1`; `r` sets both radii, `r1`/`r2` override it, diameters override
/// radii. A zero radius makes that end a single apex vertex.
pub(crate) fn cylinder(params: &Params, budget: usize) -> Result<Option<Shape>, Fail> {
    let h = match params.number("h")? {
        Some((h, _)) if !(h > 0.0 && h.is_finite()) => return Ok(None),
        Some((h, _)) => h,
        None => 1.0,
    };
    let (mut r1, mut r2) = ((1.0, params.pos), (1.0, params.pos));
    if let Some(r) = radius(params, "d", "r")? {
        (r1, r2) = (r, r);
    }
    if let Some(r) = radius(params, "d1", "r1")? {
        r1 = r;
    }
    if let Some(r) = radius(params, "d2", "r2")? {
        r2 = r;
    }
    let (r1, r2) = (r1.0, r2.0);
    if !(r1 >= 0.0 && r2 >= 0.0 && r1.is_finite() && r2.is_finite()) || (r1 == 0.0 && r2 == 0.0) {
        return Ok(None);
    }
    let fragments = Resolution::read(params)?.fragments(r1.max(r2), params.pos)?;
    check_budget(2 * fragments, budget, params.pos)?;
    let (z1, z2) = if params.boolean("center")? {
        (-h / 2.0, h / 2.0)
    } else {
        (0.0, h)
    };
    Ok(Some(cylinder_shape(r1, r2, z1, z2, fragments)))
}

pub(crate) fn cylinder_shape(r1: f64, r2: f64, z1: f64, z2: f64, n: usize) -> Shape {
    let cone = r2 == 0.0;
    let inverted_cone = r1 == 0.0;
    let mut vertices = Vec::with_capacity(2 * n);
    if inverted_cone {
        vertices.push([0.0, 0.0, z1]);
    } else {
        circle(&mut vertices, r1, z1, n);
    }
    if cone {
        vertices.push([0.0, 0.0, z2]);
    } else {
        circle(&mut vertices, r2, z2, n);
    }
    let mut faces: Vec<Vec<usize>> = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            if cone {
                vec![i, j, n]
            } else if inverted_cone {
                vec![0, j + 1, i + 1]
            } else {
                vec![i, j, j + n, i + n]
            }
        })
        .collect();
    if !inverted_cone {
        faces.push((0..n).rev().collect());
    }
    if !cone {
        let offset = if inverted_cone { 1 } else { n };
        faces.push((offset..offset + n).collect());
    }
    Shape {
        vertices,
        faces: faces.into(),
    }
}

/// OpenSCAD's `generate_circle`: point `i` at angle `360 i / fragments`, counter-clockwise from
/// +x seen from +z.
pub(crate) fn circle(out: &mut Vec<Vec3>, r: f64, z: f64, fragments: usize) {
    for i in 0..fragments {
        let phi = (360.0 * i as f64) / fragments as f64;
        out.push([r * cos_degrees(phi), r * sin_degrees(phi), z]);
    }
}

/// What a polyhedron becomes: a convex solid the array draws, or (not convex, too large to
/// check, or not closed) a mesh primitive of its faces as triangles
/// (`csgpix_scene::facet::triangulate`: a convex face fanned, a concave one ear-clipped, so
/// that a shadow or section of the mesh has no triangle outside a face).
pub(crate) enum Polyhedron {
    /// Closed, convex, faces counter-clockwise seen from outside.
    Convex(Shape),
    /// Its triangles, in the file's coordinates: closed or not
    /// (`csgpix_scene::winding`; the reader warns of one that is not, from the same
    /// triangles on the points welded, [`welded`]).
    Mesh(Vec<[Vec3; 3]>, csgpix_scene::trimesh::TriMesh),
}

/// `polyhedron(points, faces | triangles)` as OpenSCAD takes it: faces listed clockwise seen
/// from outside (`PolyhedronNode::createGeometry` reverses them) or all the other way round
/// (OpenSCAD renders those too: csgpix turns them over); convex ones become convex solids,
/// the others mesh primitives. Points no face uses are dropped. A surface that is not closed,
/// or closed only with some faces wound against their neighbours, OpenSCAD 2021.01's render
/// drops ("The given mesh is not closed! Unable to convert to CGAL_Nef_Polyhedron.",
/// `createNefPolyhedronFromPolySet`, src/cgalutils.cc); csgpix voxelizes it as a mesh.
///
/// Where `PolyhedronNode::createGeometry` (src/primitives.cc) logs a problem and goes on, so
/// does this, with the warning in `warnings`: `points` that are not a list of finite
/// `[x, y, z]` make the polyhedron empty (`Ok(None)`), an index out of range is left out of
/// its face, and a polyhedron with no face of 3 distinct points is empty.
pub(crate) fn polyhedron(
    params: &Params,
    budget: usize,
    warnings: &mut Vec<(Pos, String)>,
) -> Result<Option<Polyhedron>, Fail> {
    let Some(points) = points_of(params, warnings)? else {
        return Ok(None);
    };
    check_budget(points.len(), budget, params.pos)?;
    if let Some(&p) = points.iter().flatten().find(|&&c| too_large(c)) {
        return fail(params.pos, coordinate_too_large(Some(p)));
    }
    let faces = match params.get("faces") {
        Some(faces) => faces,
        None => params.require("triangles", "faces = [[i, j, k, …], …]")?,
    };
    let faces = faces
        .list("`faces`")?
        .iter()
        .map(|f| face_indices(f, points.len(), warnings))
        .collect::<Result<Vec<_>, _>>()?;
    // A face of fewer than 3 distinct corners encloses nothing: OpenSCAD drops it too.
    let faces: Vec<Vec<usize>> = faces.into_iter().filter(|f| f.len() >= 3).collect();
    if faces.is_empty() {
        let msg = "polyhedron: no face has 3 distinct points: it is empty";
        warnings.push((params.pos, msg.to_string()));
        return Ok(None);
    }
    let mut faces = faces;
    if enclosed_volume(&points, &faces) < 0.0 {
        faces.iter_mut().for_each(|f| f.reverse());
    }
    let small = points.len() <= MAX_POLYHEDRON_POINTS;
    if small && check_convex_closed(&points, &faces).is_ok() {
        return Ok(Some(Polyhedron::Convex(compact(points, faces))));
    }
    let (mut tris, mut indices) = (Vec::new(), Vec::new());
    for f in &faces {
        // A triangle is its own ([`csgpix_scene::facet::triangulate`]'s fan of three).
        if let [a, b, c] = f[..] {
            tris.push([a, b, c].map(|i| points[i]));
            indices.push([a, b, c]);
            continue;
        }
        let corners: Vec<DVec3> = f.iter().map(|&i| DVec3::from(points[i])).collect();
        for t in csgpix_scene::facet::triangulate(&corners) {
            tris.push(t.map(|j| points[f[j]]));
            indices.push(t.map(|j| f[j]));
        }
    }
    Ok(Some(Polyhedron::Mesh(tris, welded(&points, &indices))))
}

/// Triangles `indices` into `points` as the mesh `TriMesh::from_f64` welds from their
/// corners (equal coordinates one vertex, `-0.0` as `0.0`, numbered as first met, with the
/// coordinates first met), each point looked up once rather than every corner.
pub(crate) fn welded(points: &[Vec3], indices: &[[usize; 3]]) -> csgpix_scene::trimesh::TriMesh {
    let mut at: HashMap<[u64; 3], u32, _> =
        HashMap::with_capacity_and_hasher(points.len(), foldhash::fast::RandomState::default());
    let (mut vertices, mut id) = (Vec::new(), vec![u32::MAX; points.len()]);
    let mut vertex = |i: usize| {
        if id[i] == u32::MAX {
            let key = points[i].map(|c| (c + 0.0).to_bits());
            id[i] = *at.entry(key).or_insert_with(|| {
                vertices.push(DVec3::from(points[i]));
                (vertices.len() - 1) as u32
            });
        }
        id[i]
    };
    let triangles = indices.iter().map(|t| t.map(&mut vertex)).collect();
    csgpix_scene::trimesh::TriMesh {
        vertices,
        triangles,
    }
}

/// `points` as finite `[x, y, z]`s, or `None` (with OpenSCAD's words) where
/// `PolyhedronNode::createGeometry` gives an empty polyhedron: `points` not a list ("Unable to
/// convert points = … to a vector of coordinates"), or one point not three finite numbers.
fn points_of(
    params: &Params,
    warnings: &mut Vec<(Pos, String)>,
) -> Result<Option<Vec<Vec3>>, Fail> {
    let msg = "Unable to convert points to a vector of coordinates: the polyhedron is empty";
    let items = match params.get("points") {
        Some(Value {
            kind: Kind::List(items),
            ..
        }) => items,
        other => {
            let at = other.map_or(params.pos, |v| v.pos);
            warnings.push((at, msg.to_string()));
            return Ok(None);
        }
    };
    let mut points = Vec::with_capacity(items.len());
    for (i, p) in items.iter().enumerate() {
        match p.vec3("a point") {
            Ok(v) if v.iter().all(|c| c.is_finite()) => points.push(v),
            _ => {
                let msg = format!(
                    "Unable to convert points[{i}] to a vec3 of numbers: the polyhedron is empty"
                );
                warnings.push((p.pos, msg));
                return Ok(None);
            }
        }
    }
    Ok(Some(points))
}

/// The signed volume the faces enclose (positive when they run counter-clockwise seen from
/// outside), by the divergence theorem over fans.
fn enclosed_volume(points: &[Vec3], faces: &[Vec<usize>]) -> f64 {
    let mut v = 0.0;
    for f in faces {
        for i in 1..f.len() - 1 {
            let (a, b, c) = (points[f[0]], points[f[i]], points[f[i + 1]]);
            v += dot(a, cross(b, c)) / 6.0;
        }
    }
    v
}

/// One face's point indices, reversed to counter-clockwise.
/// An index out of range is left out, with OpenSCAD's warning ("Point index … is out of
/// bounds"); a face left with fewer than 3 points is dropped by the caller.
pub(crate) fn face_indices(
    face: &Value,
    points: usize,
    warnings: &mut Vec<(Pos, String)>,
) -> Result<Vec<usize>, Fail> {
    let items = face.list("a face")?;
    let mut indices = Vec::with_capacity(items.len());
    for item in items.iter().rev() {
        let v = item.number("a point index")?;
        if v.fract() != 0.0 || v < 0.0 || v >= points as f64 {
            let msg = format!("Point index {v} is out of bounds (of {points} points): left out");
            warnings.push((item.pos, msg));
            continue;
        }
        let i = v as usize;
        // A point repeated at once is one corner (OpenSCAD takes such faces too).
        if indices.last() != Some(&i) {
            indices.push(i);
        }
    }
    if indices.len() > 1 && indices.first() == indices.last() {
        indices.pop();
    }
    Ok(indices)
}

/// Keeps only the points some face uses, in their order.
pub(crate) fn compact(points: Vec<Vec3>, mut faces: Vec<Vec<usize>>) -> Shape {
    let mut used = vec![false; points.len()];
    faces.iter().flatten().for_each(|&i| used[i] = true);
    let mut new_index = vec![0; points.len()];
    let mut vertices = Vec::with_capacity(points.len());
    for (i, point) in points.into_iter().enumerate() {
        if used[i] {
            new_index[i] = vertices.len();
            vertices.push(point);
        }
    }
    faces.iter_mut().flatten().for_each(|i| *i = new_index[*i]);
    Shape {
        vertices,
        faces: faces.into(),
    }
}

// ---------------------------------------------------------------------------------------------
// Checks of polyhedra

/// Checks that faces (counter-clockwise seen from outside) close a convex solid: every
/// directed edge once and its reverse once, no degenerate face, positive volume, and no used
/// point outside any face plane by more than [`CONVEXITY_TOLERANCE`]. The edges are checked
/// last: a large concave polyhedron (a thread) fails at its first faces' planes, before
/// the edges of every face are hashed.
pub(crate) fn check_convex_closed(
    vertices: &[Vec3],
    faces: &[Vec<usize>],
) -> csgpix_scene::Result<()> {
    check_convex(vertices, faces)?;
    check_closed(faces)
}

/// [`check_convex_closed`] but the edges.
fn check_convex(vertices: &[Vec3], faces: &[Vec<usize>]) -> csgpix_scene::Result<()> {
    let used = used_points(vertices.len(), faces);
    let (extent, magnitude) = scale(vertices, &used);
    let tolerance = CONVEXITY_TOLERANCE * magnitude;
    // Each face's plane as it is met, tested first against the corners of the next faces
    // (in a file, mostly the face's neighbours): a concave polyhedron is found out there,
    // in a pass over some of its faces, before every plane is made or the volume summed.
    // The same test as the last pass, so the same answer.
    const NEAR: usize = 4;
    // Each face's unit normal with its plane.
    let mut planes: Vec<(Vec3, Plane)> = Vec::with_capacity(faces.len());
    for (k, face) in faces.iter().enumerate() {
        let p = face_plane(vertices, face, extent).ok_or(Error::FaceWithoutArea { face: k })?;
        planes.push((p.normal.map(|c| c / norm(p.normal)), p));
        for f in (1..=NEAR).map(|j| &faces[(k + j) % faces.len()]) {
            f.iter()
                .try_for_each(|&i| outside(vertices, &planes[k], tolerance, k, i))?;
        }
    }
    let volume: f64 = planes
        .iter()
        .map(|(_, p)| dot(p.centre, p.normal) / 6.0)
        .sum();
    let has_volume = volume > 1e-12 * extent * extent * extent;
    if !has_volume {
        return Err(Error::WrongWinding);
    }
    for (k, plane) in planes.iter().enumerate() {
        used.iter()
            .try_for_each(|&i| outside(vertices, plane, tolerance, k, i))?;
    }
    Ok(())
}

/// The points some face uses, in order.
fn used_points(points: usize, faces: &[Vec<usize>]) -> Vec<usize> {
    let mut used = vec![false; points];
    faces.iter().flatten().for_each(|&i| used[i] = true);
    (0..points).filter(|&i| used[i]).collect()
}

/// Err when point `i` lies outside face `k` (its unit normal and plane) by more than
/// `tolerance`.
fn outside(
    vertices: &[Vec3],
    (unit, plane): &(Vec3, Plane),
    tolerance: f64,
    k: usize,
    i: usize,
) -> csgpix_scene::Result<()> {
    let d = dot(*unit, sub(vertices[i], plane.centre));
    match d > tolerance {
        true => Err(Error::NotConvex {
            point: i,
            distance: d,
            face: k,
        }),
        false => Ok(()),
    }
}

/// A face's Newell normal (twice its area long) and its centroid.
pub(crate) struct Plane {
    pub(crate) normal: Vec3,
    pub(crate) centre: Vec3,
}

/// A face's plane; None when it has no area (relative to `extent`).
fn face_plane(vertices: &[Vec3], face: &[usize], extent: f64) -> Option<Plane> {
    let normal = newell(vertices, face);
    let has_area = norm(normal) > 1e-12 * extent * extent;
    has_area.then(|| Plane {
        normal,
        centre: centroid(vertices, face),
    })
}

pub(crate) fn check_closed(faces: &[Vec<usize>]) -> csgpix_scene::Result<()> {
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    for (k, face) in faces.iter().enumerate() {
        for edge in ring_edges(face) {
            if let Some(j) = edges.insert(edge, k) {
                return Err(Error::EdgeTwice {
                    first: j,
                    second: k,
                    from: edge.1,
                    to: edge.0,
                });
            }
        }
    }
    for (k, face) in faces.iter().enumerate() {
        for (a, b) in ring_edges(face) {
            if !edges.contains_key(&(b, a)) {
                return Err(Error::OpenEdge { a, b, face: k });
            }
        }
    }
    Ok(())
}

/// The directed edges of a face, closing the loop.
pub(crate) fn ring_edges(face: &[usize]) -> impl Iterator<Item = (usize, usize)> + '_ {
    face.iter()
        .zip(face.iter().cycle().skip(1))
        .map(|(&a, &b)| (a, b))
}

/// The bounding-box diagonal and the largest absolute coordinate of the used points.
pub(crate) fn scale(vertices: &[Vec3], used: &[usize]) -> (f64, f64) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut magnitude = 0.0_f64;
    for &i in used {
        for axis in 0..3 {
            let c = vertices[i][axis];
            lo[axis] = lo[axis].min(c);
            hi[axis] = hi[axis].max(c);
            magnitude = magnitude.max(c.abs());
        }
    }
    (norm(sub(hi, lo)), magnitude)
}

/// Newell's normal: the polygon's unit normal (right-hand rule) times twice its area.
pub(crate) fn newell(vertices: &[Vec3], face: &[usize]) -> Vec3 {
    let mut n = [0.0; 3];
    for (a, b) in ring_edges(face) {
        let (a, b) = (vertices[a], vertices[b]);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    n
}

pub(crate) fn centroid(vertices: &[Vec3], face: &[usize]) -> Vec3 {
    let mut c = [0.0; 3];
    for &i in face {
        for axis in 0..3 {
            c[axis] += vertices[i][axis];
        }
    }
    c.map(|v| v / face.len() as f64)
}

// ---------------------------------------------------------------------------------------------
// Trigonometry in degrees, as OpenSCAD's `src/utils/degree_trig.cc`

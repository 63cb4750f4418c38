//! OpenSCAD's 2D shapes and their extrusions (`linear_extrude`, `rotate_extrude`), `offset`,
//! in the vertex layout of OpenSCAD 2021.01, as the `.csg` reader hands them to the array.
//!
//! The array draws convex solids (§5.2); everything else reaches it as a closed mesh
//! primitive whose slices are the parity of ray crossings (§3.4.2, [`csgpix_scene::trimesh`]):
//!
//! * a 2D boolean is never computed as a polygon: an extrusion maps each height (or angle) of
//!   the plane one to one, so the extrusion of A − B is the extrusion of A minus that of B,
//!   and the reader emits that CSG tree over the extruded leaves;
//! * a `linear_extrude` of one convex outline without twist and with a uniform scale is convex
//!   ([`convex_prism`]): the hull of its bottom and scaled top outlines;
//! * every other extrusion is a closed triangle mesh ([`linear_mesh`], [`rotate_mesh`]): each
//!   outline's side walls between consecutive slices (or angles), and its caps (module `cap`:
//!   the shape ear-clipped, or a fan from the outline's first vertex where that fails, which
//!   crossings counted by parity still read as the outline's interior); every edge is in an
//!   even number of triangles.

use glam::{DVec2, DVec3};

use csgpix_scene::solid::Faces;
use csgpix_scene::{Error, Result};

use crate::cap;
pub use crate::linalg::{signed_area, Tri3};

/// A 2D shape: closed outlines, filled by the even-odd rule (OpenSCAD's `polygon` with
/// `paths`: an outline inside another is a hole).
#[derive(Clone, Debug, PartialEq)]
pub struct Poly2 {
    /// The outlines, each a closed polygon (the last point joins the first).
    pub paths: Vec<Vec<DVec2>>,
}

/// A 2D CSG tree over shapes, as the `.csg` file writes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Region {
    /// A shape.
    Poly(Poly2),
    /// Everything in any child.
    Union(Vec<Region>),
    /// Everything in every child.
    Intersection(Vec<Region>),
    /// The first minus the others.
    Difference(Vec<Region>),
}

impl Poly2 {
    /// `square(size, center)`: counter-clockwise from the corner nearest −∞.
    pub fn square(w: f64, h: f64, center: bool) -> Poly2 {
        let (x0, y0) = if center {
            (-w / 2.0, -h / 2.0)
        } else {
            (0.0, 0.0)
        };
        let p = |x, y| DVec2::new(x, y);
        Poly2 {
            paths: vec![vec![
                p(x0, y0),
                p(x0 + w, y0),
                p(x0 + w, y0 + h),
                p(x0, y0 + h),
            ]],
        }
    }

    /// `circle(r)` with `fragments` points, point i at 360·i/fragments degrees (OpenSCAD's
    /// `generate_circle`), from the exact-at-30°-and-45° sine and cosine `sincos`.
    pub fn circle(r: f64, fragments: usize, sincos: impl Fn(f64) -> (f64, f64)) -> Poly2 {
        let unit: Vec<(f64, f64)> = (0..fragments)
            .map(|i| sincos(360.0 * i as f64 / fragments as f64))
            .collect();
        Poly2::circle_of(r, &unit)
    }

    /// [`Poly2::circle`] from its angles' sines and cosines, `unit[i]` = sincos(360°·i/n).
    pub fn circle_of(r: f64, unit: &[(f64, f64)]) -> Poly2 {
        let path = unit
            .iter()
            .map(|&(s, c)| DVec2::new(r * c, r * s))
            .collect();
        Poly2 { paths: vec![path] }
    }

    /// Every outline under the plane's affine map `m` (row-major 2×3: `x' = m[0]·(x, y, 1)`).
    pub fn transformed(&self, m: [[f64; 3]; 2]) -> Poly2 {
        let map = |p: DVec2| {
            DVec2::new(
                m[0][0] * p.x + m[0][1] * p.y + m[0][2],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2],
            )
        };
        Poly2 {
            paths: self
                .paths
                .iter()
                .map(|path| path.iter().map(|&p| map(p)).collect())
                .collect(),
        }
    }

    /// The one outline, counter-clockwise, when the shape is a single convex outline (repeated
    /// points dropped; collinear points kept). None otherwise.
    pub fn convex_outline(&self) -> Option<Vec<DVec2>> {
        let [path] = self.paths.as_slice() else {
            return None;
        };
        let mut p: Vec<DVec2> = path.clone();
        p.dedup();
        while p.len() > 1 && p.first() == p.last() {
            p.pop();
        }
        if p.len() < 3 {
            return None;
        }
        if signed_area(&p) < 0.0 {
            p.reverse();
        }
        let n = p.len();
        let scale = p.iter().map(|q| q.abs().max_element()).fold(0.0, f64::max);
        let tol = 1e-12 * scale * scale;
        let mut turns = 0.0;
        for i in 0..n {
            let (a, b, c) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
            let cross = (b - a).perp_dot(c - b);
            if cross < -tol {
                return None;
            }
            turns += (b - a).angle_to(c - b);
        }
        // One turn round, not a star winding several times.
        ((turns - std::f64::consts::TAU).abs() < 1e-6).then_some(p)
    }

    /// Every vertex.
    pub fn points(&self) -> impl Iterator<Item = DVec2> + '_ {
        self.paths.iter().flatten().copied()
    }
}

/// `linear_extrude`'s parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Linear {
    /// Height along +Z.
    pub height: f64,
    /// Centred on z = 0 rather than standing on it.
    pub center: bool,
    /// Degrees; positive twists clockwise seen from +Z, as OpenSCAD's.
    pub twist: f64,
    /// Layers from bottom to top (at least 1).
    pub slices: usize,
    /// X and Y scale of the top against the bottom.
    pub scale: [f64; 2],
}

impl Linear {
    /// Bottom and top heights.
    pub(crate) fn z(&self) -> (f64, f64) {
        if self.center {
            (-self.height / 2.0, self.height / 2.0)
        } else {
            (0.0, self.height)
        }
    }

    /// Whether the solid of one convex outline is convex: no twist, one scale for X and Y.
    pub fn keeps_convex(&self) -> bool {
        self.twist == 0.0 && self.scale[0] == self.scale[1]
    }

    /// Point `p` of the outline at slice j of n.
    fn at(&self, p: DVec2, j: usize, sincos: &dyn Fn(f64) -> (f64, f64)) -> DVec3 {
        let t = j as f64 / self.slices as f64;
        let (z0, z1) = self.z();
        let s = DVec2::new(
            1.0 + (self.scale[0] - 1.0) * t,
            1.0 + (self.scale[1] - 1.0) * t,
        );
        // Turned, then scaled (OpenSCAD's Scaling · Rotation2D).
        let (sn, cs) = sincos(-self.twist * t);
        let q = DVec2::new(p.x * cs - p.y * sn, p.x * sn + p.y * cs) * s;
        DVec3::new(q.x, q.y, z0 + (z1 - z0) * t)
    }
}

/// OpenSCAD 2021.01's slice count when `slices` is not given (`Calc::get_helix_slices`,
/// `get_conical_helix_slices`, `get_diagonal_slices`): with a twist, enough that no slice
/// turns more than `$fa` or runs longer than `$fs` along the outermost point's helix (or
/// `$fn` per turn), at least one per 120°; with a non-uniform scale, one per `$fs` along the
/// longest diagonal (or `$fn`); otherwise 1. `r_max` is the outline's largest radius.
pub fn default_slices(l: &Linear, r_max: f64, fn_: f64, fa: f64, fs: f64, max_delta: f64) -> f64 {
    let twist = l.twist.abs();
    if twist > 0.0 {
        let min_slices = (twist / 120.0).ceil().max(1.0);
        if r_max < 1e-6 || !fn_.is_finite() {
            return min_slices;
        }
        if fn_ > 0.0 {
            return (twist / 360.0 * fn_).ceil().max(min_slices);
        }
        let fa_slices = (twist / fa).ceil();
        let fs_slices = (helix_length(l, r_max) / fs).ceil();
        return fa_slices.min(fs_slices).max(min_slices);
    }
    if l.scale[0] != l.scale[1] {
        if max_delta < 1e-6 || !fn_.is_finite() {
            return 1.0;
        }
        if fn_ > 0.0 {
            return fn_.trunc().max(1.0);
        }
        return ((max_delta * max_delta + l.height * l.height).sqrt() / fs)
            .ceil()
            .max(1.0);
    }
    1.0
}

/// Length of the path of a point at radius r along the twisted, scaled extrusion, as
/// OpenSCAD measures it: the planar spiral's length (Simpson's rule on 64 intervals) and the
/// height as the legs of a right triangle.
fn helix_length(l: &Linear, r: f64) -> f64 {
    let s = (l.scale[0] + l.scale[1]) / 2.0;
    let w = l.twist.abs().to_radians();
    let dr = r * (s - 1.0);
    let speed = |t: f64| {
        let radius = r * (1.0 + (s - 1.0) * t);
        (dr * dr + (radius * w).powi(2)).sqrt()
    };
    let n = 64;
    let h = 1.0 / n as f64;
    let sum: f64 = (0..=n)
        .map(|i| {
            let k = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            k * speed(i as f64 * h)
        })
        .sum();
    let planar = sum * h / 3.0;
    (planar * planar + l.height * l.height).sqrt()
}

/// The convex solid of `linear_extrude` over one convex outline (counter-clockwise), no
/// twist, scale `s` for both axes: vertices and faces counter-clockwise seen from outside.
/// A zero scale makes the top a single apex.
pub fn convex_prism(outline: &[DVec2], l: &Linear) -> (Vec<[f64; 3]>, Faces) {
    let n = outline.len();
    let (z0, z1) = l.z();
    let s = l.scale[0];
    // Sized once: a circle of many fragments is thousands of faces.
    let mut v: Vec<[f64; 3]> = Vec::with_capacity(2 * n);
    v.extend(outline.iter().map(|p| [p.x, p.y, z0]));
    let mut faces = Faces::with_capacity(n + 2, 6 * n);
    faces.push((0..n).rev());
    if s == 0.0 {
        v.push([0.0, 0.0, z1]);
        (0..n).for_each(|i| faces.push([i, (i + 1) % n, n]));
    } else {
        v.extend(outline.iter().map(|p| [p.x * s, p.y * s, z1]));
        faces.push(n..2 * n);
        for i in 0..n {
            let j = (i + 1) % n;
            faces.push([i, j, n + j, n + i]);
        }
    }
    (v, faces)
}

/// `linear_extrude` as a closed mesh, outward: every outline's walls between consecutive
/// slices, and the shape's caps (`cap::cap`) at the bottom and, unless the top is scaled to a
/// point, at the top. Outlines run as OpenSCAD's even-odd cleanup leaves them (outer ones
/// counter-clockwise, holes clockwise). Each wall quad is split along the diagonal OpenSCAD
/// 2021.01 picks (`openscad_split`).
pub fn linear_mesh(poly: &Poly2, l: &Linear, sincos: &dyn Fn(f64) -> (f64, f64)) -> Vec<Tri3> {
    let rings = oriented(poly);
    let level = |j: usize| -> Vec<Vec<DVec3>> {
        rings
            .iter()
            .map(|r| r.points.iter().map(|&p| l.at(p, j, sincos)).collect())
            .collect()
    };
    let mut out = vec![];
    let caps = cap::cap(&rings);
    let mut lower = level(0);
    lid(&caps, &lower, &mut out);
    for j in 1..=l.slices {
        let upper = level(j);
        let any_zero = j == l.slices && l.scale.contains(&0.0);
        for (r, ring) in rings.iter().enumerate() {
            // OpenSCAD's `flip`: a negative (clockwise) outline, xor a twist that is not positive.
            let flip = ring.is_hole() != (l.twist <= 0.0);
            let split = |li, lk, ui, uk| openscad_split([li, lk, ui, uk], flip, any_zero);
            walls(&lower[r], &upper[r], split, &mut out);
        }
        lower = upper;
    }
    lid(&caps, &lower, &mut out);
    cap::outward(&mut out);
    out
}

/// The cap's triangles on one level's rings.
fn lid(caps: &[[cap::Corner; 3]], level: &[Vec<DVec3>], out: &mut Vec<Tri3>) {
    for t in caps {
        push(out, t.map(|(r, i)| level[r][i]));
    }
}

/// The quads between two rings, each as two triangles split along lower i – upper i + 1 when
/// `rising(lower i, lower i + 1, upper i, upper i + 1)`, else along upper i – lower i + 1.
fn walls(
    lower: &[DVec3],
    upper: &[DVec3],
    rising: impl Fn(DVec3, DVec3, DVec3, DVec3) -> bool,
    out: &mut Vec<Tri3>,
) {
    let n = lower.len();
    for i in 0..n {
        let k = (i + 1) % n;
        if rising(lower[i], lower[k], upper[i], upper[k]) {
            push(out, [lower[i], upper[k], lower[k]]);
            push(out, [lower[i], upper[i], upper[k]]);
        } else {
            push(out, [lower[i], upper[i], lower[k]]);
            push(out, [upper[i], upper[k], lower[k]]);
        }
    }
}

/// Whether OpenSCAD 2021.01 splits the wall quad of corners `[lower i, lower i + 1, upper i,
/// upper i + 1]` along lower i – upper i + 1 (`add_slice` in `src/GeometryEvaluator.cc`): along
/// the diagonal shorter in the plane, where lengths within 10 ppm are equal (`sgn_vdiff`) and
/// the tie goes to that diagonal unless `flip`; the other diagonal at a top scaled to zero on
/// an axis (`any_zero`). For a twist alone that is lower i – upper i + 1 when the edge runs
/// counter-clockwise about the origin and the twist is positive (or clockwise and negative),
/// the other diagonal otherwise: csgpix once took the first for every edge of an outer
/// outline, which bulged the walls of edges running the other way (a square beside the
/// origin, twisted 90°: IoU 0.977 against OpenSCAD's mesh).
fn openscad_split(q: [DVec3; 4], flip: bool, any_zero: bool) -> bool {
    let [li, lk, ui, uk] = q.map(|p| p.truncate());
    let (d1, d2) = ((li - uk).length(), (lk - ui).length());
    let shorter_first = if 2.0 * (d1 - d2).abs() * 1e5 > d1 + d2 {
        d1 < d2
    } else {
        !flip
    };
    shorter_first != any_zero
}

/// The outlines as OpenSCAD's even-odd cleanup orients them: an outline inside an odd number
/// of others is a hole, run clockwise; the others counter-clockwise. Each with its depth (the
/// number of outlines it lies inside).
fn oriented(poly: &Poly2) -> Vec<cap::Ring> {
    let unfolded: Vec<Vec<DVec2>> = poly.paths.iter().map(|p| cap::unfolded(p)).collect();
    let paths: Vec<&Vec<DVec2>> = unfolded.iter().filter(|p| p.len() >= 3).collect();
    // Each outline's box, so the point-in-outline test runs only where it can succeed.
    let boxes: Vec<(DVec2, DVec2)> = paths
        .iter()
        .map(|p| {
            p.iter()
                .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &q| {
                    (lo.min(q), hi.max(q))
                })
        })
        .collect();
    // Outline i can lie inside outline j only when its box does.
    let in_box = |i: usize, j: usize| {
        boxes[i].0.cmpge(boxes[j].0).all() && boxes[i].1.cmple(boxes[j].1).all()
    };
    paths
        .iter()
        .enumerate()
        .map(|(i, path)| {
            let depth = (0..paths.len())
                .filter(|&j| j != i && in_box(i, j) && cap::encloses(paths[j], path))
                .count();
            let mut ring = cap::Ring {
                points: (*path).clone(),
                depth,
            };
            if (signed_area(&ring.points) > 0.0) == ring.is_hole() {
                ring.points.reverse();
            }
            ring
        })
        .collect()
}

/// `rotate_extrude` over `angle` degrees in `fragments` steps as a closed mesh: each outline
/// (x the radius, y the height) swept about Z. A full turn starts at 180° (OpenSCAD's "start on
/// the −X axis") and closes on itself; a part turn runs from +X counter-clockwise (clockwise
/// for a negative angle) and is capped at both ends. Err when the outline has points on both
/// sides of the axis.
pub fn rotate_mesh(
    poly: &Poly2,
    angle: f64,
    fragments: usize,
    sincos: &dyn Fn(f64) -> (f64, f64),
) -> Result<Vec<Tri3>> {
    let (lo, hi) = poly
        .points()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.x), b.max(p.x))
        });
    if lo < 0.0 && hi > 0.0 {
        return Err(Error::MixedXSign);
    }
    let full = angle.abs() >= 360.0;
    let at = |j: usize| {
        if full {
            180.0 + 360.0 * j as f64 / fragments as f64
        } else {
            angle * j as f64 / fragments as f64
        }
    };
    // OpenSCAD's rings run clockwise on a full turn and reversed where it flips faces: the
    // diagonal it splits each quad along is then the other one.
    let flip = (lo >= 0.0 && angle > 0.0 && !full) || (lo < 0.0 && (angle < 0.0 || full));
    let rings = oriented(poly);
    let turned = |a: f64| -> Vec<Vec<DVec3>> {
        let (s, c) = sincos(a);
        rings
            .iter()
            .map(|r| {
                r.points
                    .iter()
                    .map(|p| DVec3::new(p.x * c, p.x * s, p.y))
                    .collect()
            })
            .collect()
    };
    let mut out = vec![];
    let first = turned(at(0));
    let mut lower = first.clone();
    for j in 1..=fragments {
        let upper = if full && j == fragments {
            first.clone()
        } else {
            turned(at(j))
        };
        for r in 0..rings.len() {
            walls(&lower[r], &upper[r], |_, _, _, _| full == flip, &mut out);
        }
        lower = upper;
    }
    if !full {
        let caps = cap::cap(&rings);
        lid(&caps, &first, &mut out);
        lid(&caps, &lower, &mut out);
    }
    cap::outward(&mut out);
    Ok(out)
}

/// A triangle unless two of its corners coincide (a ring on the axis, a top scaled to a point).
fn push(out: &mut Vec<Tri3>, t: Tri3) {
    if t[0] != t[1] && t[1] != t[2] && t[2] != t[0] {
        out.push(t);
    }
}

/// How `offset` moves edges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Offset {
    /// `r`: round corners, `fragments` steps to a full turn (Clipper's round join).
    Round {
        /// Distance, outward when positive.
        r: f64,
        /// Steps to a full turn of a round corner.
        fragments: usize,
    },
    /// `delta`: sharp (mitred) corners, or cut corners with `chamfer`.
    Delta {
        /// Distance, outward when positive.
        delta: f64,
        /// Cut the corners instead of mitring them.
        chamfer: bool,
    },
}

impl Offset {
    fn amount(&self) -> f64 {
        match *self {
            Offset::Round { r, .. } => r,
            Offset::Delta { delta, .. } => delta,
        }
    }
}

/// `offset` of a region. A single convex outline by any amount, and a union of them by a
/// positive amount (a Minkowski sum distributes over union), are offset exactly
/// (`offset_convex`); every other region as OpenSCAD 2021.01 does it ([`clipper_offset`]).
pub fn offset(region: &Region, o: Offset, sincos: &dyn Fn(f64) -> (f64, f64)) -> Result<Region> {
    if let Some(r) = offset_exact(region, o, sincos) {
        return Ok(r);
    }
    Ok(Region::Poly(clipper_offset(&flatten(region), o, sincos)))
}

/// The exact path: None unless every shape is one convex outline (and, under a union, the
/// offset is outward).
fn offset_exact(region: &Region, o: Offset, sincos: &dyn Fn(f64) -> (f64, f64)) -> Option<Region> {
    match region {
        Region::Union(parts) if o.amount() >= 0.0 => Some(Region::Union(
            parts
                .iter()
                .map(|p| offset_exact(p, o, sincos))
                .collect::<Option<_>>()?,
        )),
        Region::Poly(p) => {
            let outline = p.convex_outline()?;
            Some(Region::Poly(Poly2 {
                paths: vec![offset_convex(&outline, o, sincos)],
            }))
        }
        _ => None,
    }
}

/// OpenSCAD 2021.01's fixed Clipper scale (`CLIPPER_SCALE` in `src/clipper-utils.h`).
const CLIPPER_SCALE: f64 = 65536.0;

/// Clipper's `Round`: half away from zero.
fn cround(v: f64) -> f64 {
    if v < 0.0 {
        (v - 0.5).trunc()
    } else {
        (v + 0.5).trunc()
    }
}

/// OpenSCAD 2021.01's `offset` of a flattened shape (outer outlines and holes, even-odd):
/// `ClipperUtils::applyOffset`, that is Clipper 6.4's `ClipperOffset` on the outlines scaled by
/// 2¹⁶ and truncated to integers, outer outlines counter-clockwise and holes clockwise, with
/// `jtRound` for `r` (the arc tolerance `|r|·(1 − cos(180°/fragments))`), `jtMiter` with miter
/// limit 10⁶ for `delta`, `jtSquare` for `chamfer`; then the union of the offset outlines by the
/// positive winding rule (Clipper's clean-up of the corners), here with `i_overlay`.
pub fn clipper_offset(shape: &Poly2, o: Offset, sincos: &dyn Fn(f64) -> (f64, f64)) -> Poly2 {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::single::SingleFloatOverlay;
    let src = clipper_paths(shape);
    let delta = o.amount() * CLIPPER_SCALE;
    let dest: Vec<Vec<[f64; 2]>> = if delta.abs() < 1e-20 {
        src.iter()
            .map(|p| p.iter().map(|v| v.to_array()).collect())
            .collect()
    } else {
        let offset = ClosedOffset::new(o, delta, sincos);
        src.iter()
            .filter(|p| !(delta <= 0.0 && p.len() < 3))
            .map(|p| offset.outline(p))
            .collect()
    };
    let none: Vec<Vec<[f64; 2]>> = vec![];
    let shapes = dest.overlay(&none, OverlayRule::Subject, FillRule::Positive);
    Poly2 {
        paths: shapes
            .into_iter()
            .flatten()
            .filter(|c| c.len() >= 3)
            .map(|c| {
                c.into_iter()
                    .map(|v| DVec2::from(v) / CLIPPER_SCALE)
                    .collect()
            })
            .collect(),
    }
}

/// The outlines of `shape` as Clipper's `AddPath` keeps them: integer points, repeats
/// dropped, fewer than three points skipped; then oriented as OpenSCAD's sanitized polygons
/// are, outer outlines counter-clockwise and holes (by even-odd nesting) clockwise.
fn clipper_paths(shape: &Poly2) -> Vec<Vec<DVec2>> {
    // `flatten` gives each shape's outer outline first.
    let mut src: Vec<Vec<DVec2>> = vec![];
    for path in &shape.paths {
        let mut p: Vec<DVec2> = path.iter().map(|v| (*v * CLIPPER_SCALE).trunc()).collect();
        p.dedup();
        while p.len() > 1 && p.first() == p.last() {
            p.pop();
        }
        if p.len() >= 3 {
            src.push(p);
        }
    }
    let inside_count = |i: usize| {
        let q = src[i][0];
        src.iter()
            .enumerate()
            .filter(|&(j, p)| j != i && cap::inside(p, q))
            .count()
    };
    let holes: Vec<bool> = (0..src.len()).map(|i| inside_count(i) % 2 == 1).collect();
    for (p, &hole) in src.iter_mut().zip(&holes) {
        if (signed_area(p) < 0.0) != hole {
            p.reverse();
        }
    }
    src
}

/// Clipper's `Round` of a point onto the integer grid, appended to `out`.
fn put_rounded(out: &mut Vec<[f64; 2]>, v: DVec2) {
    out.push([cround(v.x), cround(v.y)]);
}

/// Clipper 6.4's `ClipperOffset::DoOffset` for closed outlines: the join kind, the offset
/// `delta` (scaled) and the arc steps its set-up derives.
struct ClosedOffset {
    o: Offset,
    delta: f64,
    miter_lim: f64,
    steps_per_rad: f64,
    /// The sine (negated for an inward offset) and cosine of one arc step.
    m_sin: f64,
    m_cos: f64,
}

impl ClosedOffset {
    /// `DoOffset`'s set-up: miter limit 10⁶, and the arc steps from OpenSCAD's arc
    /// tolerance `|r|·(1 − cos(180°/fragments))` (0.25 when 0, at most `|delta|/4`).
    fn new(o: Offset, delta: f64, sincos: &dyn Fn(f64) -> (f64, f64)) -> Self {
        let miter_lim = 2.0 / (1e6 * 1e6);
        let arc_tolerance = match o {
            Offset::Round { r, fragments } => {
                let (_, c) = sincos(180.0 / fragments as f64);
                r.abs() * (1.0 - c) * CLIPPER_SCALE
            }
            // OpenSCAD computes it for every join type; only jtRound uses it.
            Offset::Delta { .. } => 0.0,
        };
        let y = if arc_tolerance <= 0.0 {
            0.25
        } else if arc_tolerance > delta.abs() * 0.25 {
            delta.abs() * 0.25
        } else {
            arc_tolerance
        };
        let mut steps = std::f64::consts::PI / (1.0 - y / delta.abs()).acos();
        if steps > delta.abs() * std::f64::consts::PI {
            steps = delta.abs() * std::f64::consts::PI;
        }
        let two_pi = 2.0 * std::f64::consts::PI;
        let (mut m_sin, m_cos) = ((two_pi / steps).sin(), (two_pi / steps).cos());
        if delta < 0.0 {
            m_sin = -m_sin;
        }
        ClosedOffset {
            o,
            delta,
            miter_lim,
            steps_per_rad: steps / two_pi,
            m_sin,
            m_cos,
        }
    }

    /// One closed outline offset: its edge normals, then each point's join.
    fn outline(&self, p: &[DVec2]) -> Vec<[f64; 2]> {
        let len = p.len();
        let normals: Vec<DVec2> = (0..len)
            .map(|j| {
                let d = p[(j + 1) % len] - p[j];
                if d == DVec2::ZERO {
                    DVec2::ZERO
                } else {
                    let f = 1.0 / (d.x * d.x + d.y * d.y).sqrt();
                    DVec2::new(d.y * f, -d.x * f)
                }
            })
            .collect();
        let mut out: Vec<[f64; 2]> = vec![];
        let mut k = len - 1;
        for j in 0..len {
            if self.offset_point(&mut out, normals[k], normals[j], p[j]) {
                k = j;
            }
        }
        out
    }

    /// Clipper's `OffsetPoint`: the join at `pj` between the edges with normals `nk` (in)
    /// and `nj` (out); false when the point is skipped (the edges nearly parallel).
    fn offset_point(&self, out: &mut Vec<[f64; 2]>, nk: DVec2, nj: DVec2, pj: DVec2) -> bool {
        let delta = self.delta;
        let mut sin_a = nk.x * nj.y - nj.x * nk.y;
        let cos_a = nk.x * nj.x + nj.y * nk.y;
        if (sin_a * delta).abs() < 1.0 {
            if cos_a > 0.0 {
                put_rounded(out, pj + nk * delta);
                return false;
            }
        } else {
            sin_a = sin_a.clamp(-1.0, 1.0);
        }
        if sin_a * delta < 0.0 {
            put_rounded(out, pj + nk * delta);
            put_rounded(out, pj);
            put_rounded(out, pj + nj * delta);
            return true;
        }
        match self.o {
            Offset::Delta { chamfer: false, .. } => {
                let r = 1.0 + (nj.x * nk.x + nj.y * nk.y);
                if r >= self.miter_lim {
                    let q = delta / r;
                    put_rounded(out, pj + (nk + nj) * q);
                } else {
                    self.do_square(out, nk, nj, pj, sin_a, cos_a);
                }
            }
            Offset::Delta { chamfer: true, .. } => self.do_square(out, nk, nj, pj, sin_a, cos_a),
            Offset::Round { .. } => self.do_round(out, nk, nj, pj, sin_a, cos_a),
        }
        true
    }

    /// Clipper's `DoSquare`: the corner at `pj` cut square at distance `delta`.
    fn do_square(
        &self,
        out: &mut Vec<[f64; 2]>,
        nk: DVec2,
        nj: DVec2,
        pj: DVec2,
        sin_a: f64,
        cos_a: f64,
    ) {
        let dx = (sin_a.atan2(cos_a) / 4.0).tan();
        put_rounded(
            out,
            pj + DVec2::new(nk.x - nk.y * dx, nk.y + nk.x * dx) * self.delta,
        );
        put_rounded(
            out,
            pj + DVec2::new(nj.x + nj.y * dx, nj.y - nj.x * dx) * self.delta,
        );
    }

    /// Clipper's `DoRound`: an arc around `pj` from normal `nk` to normal `nj`.
    fn do_round(
        &self,
        out: &mut Vec<[f64; 2]>,
        nk: DVec2,
        nj: DVec2,
        pj: DVec2,
        sin_a: f64,
        cos_a: f64,
    ) {
        let a = sin_a.atan2(cos_a);
        let n = (cround(self.steps_per_rad * a.abs()) as i64).max(1);
        let (mut x, mut y) = (nk.x, nk.y);
        for _ in 0..n {
            put_rounded(out, pj + DVec2::new(x, y) * self.delta);
            let x2 = x;
            x = x * self.m_cos - self.m_sin * y;
            y = x2 * self.m_sin + y * self.m_cos;
        }
        put_rounded(out, pj + nj * self.delta);
    }
}

/// A convex counter-clockwise outline offset: outward with round, mitred or chamfered
/// corners; inward as the outline clipped by every edge moved in (all three agree there).
fn offset_convex(p: &[DVec2], o: Offset, sincos: &dyn Fn(f64) -> (f64, f64)) -> Vec<DVec2> {
    let n = p.len();
    let normal = |i: usize| {
        let e = p[(i + 1) % n] - p[i];
        DVec2::new(e.y, -e.x).normalize_or_zero()
    };
    let d = o.amount();
    if d < 0.0 {
        return (0..n).fold(p.to_vec(), |poly, i| {
            clip(&poly, normal(i), normal(i).dot(p[i]) + d)
        });
    }
    let mut out = vec![];
    for (i, &corner) in p.iter().enumerate() {
        let (n0, n1) = (normal((i + n - 1) % n), normal(i));
        match o {
            Offset::Delta { chamfer: false, .. } => {
                let bis = (n0 + n1).normalize_or_zero();
                out.push(corner + bis * (d / bis.dot(n1).max(1e-12)));
            }
            Offset::Delta { chamfer: true, .. } => {
                // Clipper's square join: the corner cut square to its bisector at distance d.
                let dx = (n0.perp_dot(n1).atan2(n0.dot(n1)) / 4.0).tan();
                out.push(corner + (n0 + n0.perp() * dx) * d);
                out.push(corner + (n1 - n1.perp() * dx) * d);
            }
            Offset::Round { fragments, .. } => {
                let (a0, a1) = (n0.y.atan2(n0.x), n1.y.atan2(n1.x));
                let mut turn = (a1 - a0).to_degrees();
                if turn < 0.0 {
                    turn += 360.0;
                }
                // Clipper's round join as OpenSCAD sets it up (arc tolerance from the circle's
                // fragments): round(fragments · turn / 360) points a fragment's angle apart
                // from the first edge's normal, then the second edge's.
                let steps = ((turn / 360.0) * fragments as f64).round().max(1.0) as usize;
                for k in 0..steps {
                    let (s, c) = sincos(a0.to_degrees() + 360.0 * k as f64 / fragments as f64);
                    out.push(corner + DVec2::new(c, s) * d);
                }
                out.push(corner + n1 * d);
            }
        }
    }
    out.dedup();
    out
}

/// The part of a convex polygon where n·x ≤ c (Sutherland-Hodgman against one half-plane).
fn clip(poly: &[DVec2], n: DVec2, c: f64) -> Vec<DVec2> {
    let mut out = vec![];
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let (da, db) = (n.dot(a) - c, n.dot(b) - c);
        if da <= 0.0 {
            out.push(a);
        }
        if (da < 0.0) != (db < 0.0) && da != db {
            out.push(a + (b - a) * (da / (da - db)));
        }
    }
    out
}

/// The shape a 2D tree covers, its booleans computed in the plane (the even-odd outlines of
/// its parts combined by `i_overlay`, as OpenSCAD combines them with Clipper): for the
/// extrusions that do not commute with booleans, those whose walls are triangulated between
/// slices (a twist, a scale differing between X and Y).
pub fn flatten(r: &Region) -> Poly2 {
    use i_overlay::i_float::float::rect::FloatRect;
    let mut pts: Vec<[f64; 2]> = vec![];
    let mut stack = vec![r];
    while let Some(r) = stack.pop() {
        match r {
            Region::Poly(p) => pts.extend(p.points().map(|q| q.to_array())),
            Region::Union(c) | Region::Intersection(c) | Region::Difference(c) => {
                stack.extend(c.iter())
            }
        }
    }
    let rect = FloatRect::with_iter(pts.iter()).unwrap_or(FloatRect::zero());
    let grid = Grid::new(rect);
    Poly2 {
        paths: contours(r, &grid)
            .into_iter()
            .flatten()
            .map(|c| c.into_iter().map(DVec2::from).collect())
            .collect(),
    }
}

/// The one integer grid every `i_overlay` run of a [`flatten`] snaps to, as OpenSCAD 2021.01
/// scales every Clipper run by the one `CLIPPER_SCALE`: fine enough for the whole tree's box
/// (`i_overlay`'s own choice for that box). `i_overlay`'s float API otherwise picks a grid
/// per run from that run's box (centred on it, truncating), so a point two parts share (the
/// centre of a fan of wedges) landed on different floats in the runs that sanitized each
/// part: the parts no longer met edge to edge, their union stayed several outlines meeting
/// along nearly shared edges, and, twisted, the walls of two outlines on one edge split its
/// quads along different diagonals (each from its own lower first corner), leaving the
/// sliver between them outside by parity (MCAD's `trochoids.scad`, `hypotrochoidLinear`: 40
/// triangles from the origin, IoU 0.85 against OpenSCAD's mesh).
type Grid = i_overlay::i_float::adapter::FloatPointAdapter<[f64; 2], f64>;

/// One `i_overlay` run on `grid`.
fn run(
    grid: &Grid,
    subject: &[Vec<[f64; 2]>],
    clip: &[Vec<[f64; 2]>],
    rule: i_overlay::core::overlay_rule::OverlayRule,
    fill: i_overlay::core::fill_rule::FillRule,
) -> Vec<Vec<Vec<[f64; 2]>>> {
    use i_overlay::core::overlay::ShapeType;
    use i_overlay::float::overlay::FloatOverlay;
    let n = subject.iter().chain(clip).map(Vec::len).sum();
    // Every point lies in the grid's box: the tree's points, and what runs on them make.
    FloatOverlay::with_adapter(grid.clone(), n)
        .unsafe_add_source(subject, ShapeType::Subject)
        .unsafe_add_source(clip, ShapeType::Clip)
        .overlay(rule, fill)
}

/// Shapes (outer outline, then holes) of a 2D tree. A union or difference takes all its
/// parts in one run, as OpenSCAD 2021.01 does (`ClipperUtils::apply`, nonzero fill over
/// sanitized children): each part's outlines come from `i_overlay` outer counter-clockwise and
/// holes clockwise, so nonzero winding fills what any part fills. An intersection runs
/// part by part, as OpenSCAD's.
fn contours(r: &Region, grid: &Grid) -> Vec<Vec<Vec<[f64; 2]>>> {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    let none: Vec<Vec<[f64; 2]>> = vec![];
    let paths =
        |s: Vec<Vec<Vec<[f64; 2]>>>| -> Vec<Vec<[f64; 2]>> { s.into_iter().flatten().collect() };
    let (rule, parts) = match r {
        Region::Poly(p) => {
            let subj: Vec<Vec<[f64; 2]>> = p
                .paths
                .iter()
                .map(|c| c.iter().map(|v| v.to_array()).collect())
                .collect();
            return run(grid, &subj, &none, OverlayRule::Subject, FillRule::EvenOdd);
        }
        Region::Union(c) => (OverlayRule::Union, c),
        Region::Intersection(c) => (OverlayRule::Intersect, c),
        Region::Difference(c) => (OverlayRule::Difference, c),
    };
    let mut it = parts.iter();
    let Some(first) = it.next() else {
        return vec![];
    };
    let mut acc = paths(contours(first, grid));
    if !matches!(rule, OverlayRule::Intersect) {
        let others: Vec<_> = it.flat_map(|p| paths(contours(p, grid))).collect();
        return run(grid, &acc, &others, rule, FillRule::NonZero);
    }
    for part in it {
        let other = paths(contours(part, grid));
        // An intersection with nothing is nothing.
        acc = paths(run(grid, &acc, &other, rule, FillRule::EvenOdd));
    }
    run(grid, &acc, &none, OverlayRule::Subject, FillRule::EvenOdd)
}

/// Every vertex of a region's shapes, for `hull()`: of the shapes under unions, and of the
/// computed outline of a difference or intersection ([`flatten`]: the hull of a difference
/// is the hull of what remains, not of its operands).
pub fn region_points(r: &Region, out: &mut Vec<DVec2>) -> Result<()> {
    let mut stack = vec![r];
    while let Some(r) = stack.pop() {
        match r {
            Region::Poly(p) => out.extend(p.points()),
            Region::Union(parts) => stack.extend(parts.iter()),
            _ => out.extend(flatten(r).points()),
        }
    }
    Ok(())
}

/// A heap block of `bytes`, with an allocator's 16 bytes.
fn block(bytes: usize) -> u64 {
    bytes as u64 + 16
}

/// The heap bytes a shape's outlines hold (each outline's points and vector, and its list
/// of outlines), as [`region_bytes`] counts them.
pub(crate) fn poly_bytes(p: &Poly2) -> u64 {
    let outlines: u64 = p.paths.iter().map(|c| block(c.capacity() * 16)).sum();
    block(p.paths.capacity() * 24) + outlines
}

/// The heap bytes a 2D tree's outlines hold (each outline's points and vector, each shape's
/// list of outlines, with an allocator's 16 bytes a block), walked without recursion.
pub(crate) fn region_bytes(r: &Region) -> u64 {
    let (mut total, mut stack) = (0u64, vec![r]);
    while let Some(r) = stack.pop() {
        match r {
            Region::Poly(p) => total += poly_bytes(p),
            Region::Union(c) | Region::Intersection(c) | Region::Difference(c) => {
                total += block(c.capacity() * std::mem::size_of::<Region>());
                stack.extend(c.iter());
            }
        }
    }
    total
}

/// Every shape of a 2D tree through `f`.
pub(crate) fn map_region(r: Region, f: &dyn Fn(Poly2) -> Poly2) -> Region {
    match r {
        Region::Poly(p) => Region::Poly(f(p)),
        Region::Union(c) => Region::Union(c.into_iter().map(|c| map_region(c, f)).collect()),
        Region::Intersection(c) => {
            Region::Intersection(c.into_iter().map(|c| map_region(c, f)).collect())
        }
        Region::Difference(c) => {
            Region::Difference(c.into_iter().map(|c| map_region(c, f)).collect())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sc(a: f64) -> (f64, f64) {
        a.to_radians().sin_cos()
    }

    fn closed(tris: &[Tri3]) -> bool {
        let key = |p: DVec3| p.to_array().map(f64::to_bits);
        let mut edges = std::collections::HashMap::new();
        for t in tris {
            for k in 0..3 {
                let (a, b) = (key(t[k]), key(t[(k + 1) % 3]));
                let e = if a < b { (a, b) } else { (b, a) };
                *edges.entry(e).or_insert(0) += 1;
            }
        }
        edges.values().all(|&n| n == 2)
    }

    /// Parity of the crossings of the ray from (x, y, z) towards +Z with the triangles.
    fn inside(tris: &[Tri3], x: f64, y: f64, z: f64) -> bool {
        let p = DVec2::new(x, y);
        tris.iter()
            .filter(|t| {
                let [a, b, c] = t.map(|v| v.truncate());
                let s = |u: DVec2, v: DVec2| (v - u).perp_dot(p - u);
                let (d1, d2, d3) = (s(a, b), s(b, c), s(c, a));
                let area = d1 + d2 + d3;
                let hit = (d1 > 0.0 && d2 > 0.0 && d3 > 0.0) || (d1 < 0.0 && d2 < 0.0 && d3 < 0.0);
                // Barycentric depth of the crossing.
                hit && (t[0].z * d2 + t[1].z * d3 + t[2].z * d1) / area > z
            })
            .count()
            % 2
            == 1
    }

    #[test]
    fn a_square_with_a_hole_extrudes_to_a_closed_mesh_with_the_hole() {
        let mut p = Poly2::square(10.0, 10.0, true);
        p.paths.extend(Poly2::square(4.0, 4.0, true).paths);
        let l = Linear {
            height: 5.0,
            center: false,
            twist: 0.0,
            slices: 1,
            scale: [1.0, 1.0],
        };
        let m = linear_mesh(&p, &l, &sc);
        assert!(closed(&m));
        assert!(inside(&m, 4.0, 0.5, 2.5));
        assert!(!inside(&m, 0.5, 0.3, 2.5), "the hole");
        assert!(!inside(&m, 6.0, 0.0, 2.5));
        assert!(!inside(&m, 4.0, 0.5, -1.0), "below");
    }

    #[test]
    fn a_concave_outline_extrudes_by_parity() {
        // An L: the notch at (3, 3) is outside.
        let l_shape = Poly2 {
            paths: vec![[(0., 0.), (4., 0.), (4., 2.), (2., 2.), (2., 4.), (0., 4.)]
                .map(|(x, y)| DVec2::new(x, y))
                .to_vec()],
        };
        assert!(l_shape.convex_outline().is_none());
        let l = Linear {
            height: 1.0,
            center: true,
            twist: 45.0,
            slices: 3,
            scale: [1.0, 0.5],
        };
        let m = linear_mesh(&l_shape, &l, &sc);
        assert!(closed(&m));
        // Near the bottom the outline has barely turned or shrunk.
        assert!(inside(&m, 0.5, 0.5, -0.49) && inside(&m, 3.0, 0.2, -0.49));
        assert!(!inside(&m, 3.0, 3.0, -0.49), "the notch");
    }

    #[test]
    fn a_torus_is_closed_with_fragments_times_points_vertices() {
        let c = Poly2::circle(1.0, 8, sc).transformed([[1.0, 0.0, 3.0], [0.0, 1.0, 0.0]]);
        let m = rotate_mesh(&c, 360.0, 12, &sc).unwrap();
        assert!(closed(&m));
        assert_eq!(m.len(), 2 * 8 * 12);
        let mut v: Vec<_> = m
            .iter()
            .flatten()
            .map(|p| p.to_array().map(f64::to_bits))
            .collect();
        v.sort_unstable();
        v.dedup();
        assert_eq!(v.len(), 8 * 12);
        // A part turn is capped; a profile touching the axis closes at it.
        let half = rotate_mesh(&Poly2::square(2.0, 1.0, false), 90.0, 3, &sc).unwrap();
        assert!(closed(&half));
        assert!(rotate_mesh(&Poly2::square(2.0, 1.0, true), 360.0, 6, &sc).is_err());
    }

    #[test]
    fn offsets_of_a_square() {
        let sq = Region::Poly(Poly2::square(2.0, 2.0, false));
        let area = |r: &Region| match r {
            Region::Poly(p) => signed_area(&p.paths[0]),
            _ => f64::NAN,
        };
        let mitre = offset(
            &sq,
            Offset::Delta {
                delta: 1.0,
                chamfer: false,
            },
            &sc,
        )
        .unwrap();
        assert!((area(&mitre) - 16.0).abs() < 1e-12);
        let chamfer = offset(
            &sq,
            Offset::Delta {
                delta: 1.0,
                chamfer: true,
            },
            &sc,
        )
        .unwrap();
        // Clipper's square join (OpenSCAD's chamfer): each corner cut square to its bisector
        // at distance 1, a right isosceles triangle of height √2 − 1 off the mitred square.
        let h = 2.0_f64.sqrt() - 1.0;
        assert!((area(&chamfer) - (16.0 - 4.0 * h * h)).abs() < 1e-12);
        let round = offset(
            &sq,
            Offset::Round {
                r: 1.0,
                fragments: 360,
            },
            &sc,
        )
        .unwrap();
        assert!((area(&round) - (4.0 + 8.0 + std::f64::consts::PI)).abs() < 1e-3);
        let inward = offset(
            &sq,
            Offset::Round {
                r: -0.5,
                fragments: 8,
            },
            &sc,
        )
        .unwrap();
        assert!((area(&inward) - 1.0).abs() < 1e-12);
        // A square minus itself is empty, and so is its offset.
        let diff = Region::Difference(vec![sq.clone(), sq.clone()]);
        let empty = offset(
            &diff,
            Offset::Delta {
                delta: 1.0,
                chamfer: false,
            },
            &sc,
        )
        .unwrap();
        assert_eq!(region_area(&empty), 0.0);
    }

    /// Even-odd area of a region flattened.
    fn region_area(r: &Region) -> f64 {
        flatten(r)
            .paths
            .iter()
            .map(|p| signed_area(p))
            .sum::<f64>()
            .abs()
    }

    /// An L: the 4×4 square minus its 2×2 top-right quarter (area 12, perimeter 16, one
    /// reflex corner).
    fn ell() -> Region {
        let p = |x, y| DVec2::new(x, y);
        Region::Poly(Poly2 {
            paths: vec![vec![
                p(0.0, 0.0),
                p(4.0, 0.0),
                p(4.0, 2.0),
                p(2.0, 2.0),
                p(2.0, 4.0),
                p(0.0, 4.0),
            ]],
        })
    }

    fn round(r: f64, fragments: usize) -> Offset {
        Offset::Round { r, fragments }
    }

    fn delta(delta: f64, chamfer: bool) -> Offset {
        Offset::Delta { delta, chamfer }
    }

    #[test]
    fn an_l_offset_outward_and_inward() {
        let tol = 1e-6;
        // Round outward: A + P·r, plus a quarter disc at each of the five convex corners
        // (the fragment polygon's, 360 fragments), minus the r×r square where the two strips
        // along the reflex corner's edges overlap.
        let r = 0.5;
        let n = 360.0_f64;
        let poly_circle = 0.5 * n * r * r * (2.0 * std::f64::consts::PI / n).sin();
        let a = region_area(&offset(&ell(), round(r, 360), &sc).unwrap());
        assert!(
            (a - (12.0 + 16.0 * r + 1.25 * poly_circle - r * r)).abs() < 1e-4,
            "{a}"
        );
        // Mitred outward: [−0.5, 4.5]² minus the corner [2.5, 4.5]².
        let a = region_area(&offset(&ell(), delta(0.5, false), &sc).unwrap());
        assert!((a - (25.0 - 4.0)).abs() < tol, "{a}");
        // Mitred inward: the L shrunk by 0.5: [0.5, 3.5]×[0.5, 1.5] ∪ [0.5, 1.5]×[0.5, 3.5].
        let a = region_area(&offset(&ell(), delta(-0.5, false), &sc).unwrap());
        assert!((a - (3.0 + 3.0 - 1.0)).abs() < tol, "{a}");
        // Round inward equals mitred inward away from the reflex corner, which becomes an arc
        // of radius 0.5 around (2, 2): the quarter disc's corner square minus the quarter disc.
        let a = region_area(&offset(&ell(), round(-0.5, 360), &sc).unwrap());
        let corner = 0.25 - std::f64::consts::PI * 0.25 / 4.0;
        assert!((a - (5.0 + corner)).abs() < 1e-3, "{a}");
        // Chamfer outward (Clipper's square join: the corner cut square to its bisector at
        // distance 0.5 from the corner): each of the five convex corners loses, from the
        // mitred offset, a right isosceles triangle of height 0.5·(√2 − 1).
        let a = region_area(&offset(&ell(), delta(0.5, true), &sc).unwrap());
        let h = 0.5 * (2.0_f64.sqrt() - 1.0);
        assert!((a - (21.0 - 5.0 * h * h)).abs() < 1e-4, "{a}");
    }

    #[test]
    fn a_square_with_a_hole_offset_inward_and_outward() {
        // [0, 10]² minus [4, 6]²: area 96.
        let holed = Region::Difference(vec![
            Region::Poly(Poly2::square(10.0, 10.0, false)),
            Region::Poly(
                Poly2::square(2.0, 2.0, false).transformed([[1.0, 0.0, 4.0], [0.0, 1.0, 4.0]]),
            ),
        ]);
        let a = region_area(&offset(&holed, delta(-1.0, false), &sc).unwrap());
        assert!((a - (64.0 - 16.0)).abs() < 1e-6, "{a}");
        let a = region_area(&offset(&holed, delta(1.0, false), &sc).unwrap());
        assert!((a - 144.0).abs() < 1e-6, "{a}");
        // Outward by 1.5 the hole closes.
        let a = region_area(&offset(&holed, delta(1.5, false), &sc).unwrap());
        assert!((a - 169.0).abs() < 1e-6, "{a}");
        // The inward offset of a union of two touching squares is one rectangle shrunk.
        let two = Region::Union(vec![
            Region::Poly(Poly2::square(2.0, 2.0, false)),
            Region::Poly(
                Poly2::square(2.0, 2.0, false).transformed([[1.0, 0.0, 2.0], [0.0, 1.0, 0.0]]),
            ),
        ]);
        let a = region_area(&offset(&two, round(-0.5, 36), &sc).unwrap());
        assert!((a - 3.0).abs() < 1e-6, "{a}");
    }

    #[test]
    fn a_convex_prism_is_the_square_extruded() {
        let sq = Poly2::square(2.0, 3.0, false).convex_outline().unwrap();
        let l = Linear {
            height: 4.0,
            center: false,
            twist: 0.0,
            slices: 1,
            scale: [0.5, 0.5],
        };
        let (v, f) = convex_prism(&sq, &l);
        assert_eq!((v.len(), f.len()), (8, 6));
        assert_eq!(v[6], [1.0, 1.5, 4.0]);
    }

    #[test]
    fn helix_slices_follow_openscad() {
        // Measured with OpenSCAD 2021.01 on square([5, 3]) moved to x = 2 (r² = 58).
        let l = |h: f64, twist: f64, s: f64| Linear {
            height: h,
            center: false,
            twist,
            slices: 0,
            scale: [s, s],
        };
        let r = 58f64.sqrt();
        assert_eq!(
            default_slices(&l(10.0, 90.0, 1.0), r, 0.0, 12.0, 2.0, 0.0),
            8.0
        );
        assert_eq!(
            default_slices(&l(10.0, 360.0, 1.0), r, 0.0, 12.0, 2.0, 0.0),
            25.0
        );
        assert_eq!(
            default_slices(&l(30.0, 90.0, 1.0), r, 0.0, 12.0, 2.0, 0.0),
            8.0
        );
        assert_eq!(
            default_slices(&l(10.0, 90.0, 1.0), r, 16.0, 12.0, 2.0, 0.0),
            4.0
        );
        assert_eq!(
            default_slices(&l(10.0, 90.0, 0.5), r, 0.0, 12.0, 2.0, 0.0),
            7.0
        );
    }
}

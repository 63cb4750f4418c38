//! Projection: a CSG scene of convex solids, seen orthographically, becomes display lists
//! (one per solid, §5.2) and a clipping function over them (§5.2.1).
//!
//! The view maps scene coordinates to (u, v, w): u to the right, v down the screen, w into
//! the screen. The scene's bounds are scaled uniformly to fill the array, one depth unit per
//! pixel, with the nearest point of the scene at depth [`DEPTH_MARGIN`]. A face with outward
//! normal n and plane n·p = d has depth `w(u, v) = (d − n_u·u − n_v·v) / n_w`, so per pixel
//! `Z0`, `dZx = −n_u/n_w`, `dZy = −n_v/n_w`; it is a front face (H = 1) when n_w < 0 (it faces
//! the viewer).
//!
//! Near-perpendicular faces: as n_w → 0 the slopes grow without bound. A face whose slope
//! exceeds [`max_slope`] is drawn as a perpendicular plane (Y = 1) with `K` = the signed
//! distance in pixels from its trace (K ≥ 0 inside). The limit is maxdepth per pixel (such a
//! face crosses the whole depth range within one pixel, so its silhouette moves by less than
//! one pixel), lowered on large arrays so that no coefficient and no DEPGEN sum anywhere on
//! the array leaves the word: a face whose depth is in [0, maxdepth] somewhere on the array has
//! |Z0 + x·dZx + y·dZy| ≤ maxdepth + slope·(W + H) at every pixel (docs/rendering.md).

use glam::{DMat3, DVec3};

use csgpix_scene::clip_expr::Clip;
use csgpix_scene::display_list::{DisplayList, DlPlane};
use csgpix_scene::solid::{ConvexSolid, CsgNode, CsgScene};
use rtl_model::WordFormat;

use crate::{Error, Result};

/// Depth of the scene's nearest point, in depth units (pixels).
pub const DEPTH_MARGIN: f64 = 4.0;

/// A named view direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum View {
    /// Looking down the scene's −Z axis (x right, y up the screen).
    Top,
    /// Looking along +Y (x right, z up).
    Front,
    /// Isometric from (+1, −1, +1) towards the origin.
    #[default]
    Iso,
}

impl View {
    /// Rows: the scene directions of screen u (right), v (down) and w (into the screen).
    fn basis(self) -> DMat3 {
        let (u, v, w) = match self {
            View::Top => (DVec3::X, DVec3::NEG_Y, DVec3::NEG_Z),
            View::Front => (DVec3::X, DVec3::NEG_Z, DVec3::Y),
            View::Iso => {
                let w = DVec3::new(-1.0, 1.0, -1.0).normalize();
                let u = DVec3::new(1.0, 1.0, 0.0).normalize();
                (u, w.cross(u).normalize(), w)
            }
        };
        DMat3::from_cols(u, v, w).transpose()
    }
}

/// The largest |dZx|, |dZy| drawn as a sloped plane on a `width`×`height` array: maxdepth
/// depth units per pixel, or less where the word could not hold maxdepth + slope·(W + H).
pub fn max_slope(fmt: &WordFormat, width: usize, height: usize) -> f64 {
    let maxdepth = fmt.to_real(fmt.maxdepth());
    let headroom = fmt.to_real(fmt.max_word()) - maxdepth;
    maxdepth.min(headroom / (width + height) as f64).max(0.0)
}

/// Where the scene lands on the array.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Rows: the scene directions of screen u (right), v (down) and w (into the screen).
    pub basis: DMat3,
    /// Minimum (u, v, w) of the scene in view coordinates.
    pub min: DVec3,
    /// Pixels (x, y) and depth units (z) per scene unit along u, v, w.
    pub scale: DVec3,
    /// Added after scaling: pixel coordinates and depth of `min`.
    pub offset: DVec3,
}

impl Frame {
    /// Fit `scene` into a `width`×`height` array.
    pub fn fit(scene: &CsgScene, view: View, width: usize, height: usize) -> Result<Frame> {
        let basis = view.basis();
        let pts = scene
            .solids
            .iter()
            .flat_map(|s| s.vertices.iter())
            .map(|p| basis * DVec3::from(*p));
        let (min, max) = pts.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), p| {
            (a.min(p), b.max(p))
        });
        if !min.is_finite() {
            return Err(Error::NoSolids);
        }
        let ext = (max - min).max(DVec3::splat(1e-9));
        let scale = ((width.max(2) - 1) as f64 / ext.x).min((height.max(2) - 1) as f64 / ext.y);
        Ok(Frame {
            basis,
            min,
            scale: DVec3::splat(scale),
            offset: DVec3::new(0.0, 0.0, DEPTH_MARGIN),
        })
    }

    /// The greatest depth of any vertex of the scene, in depth units.
    pub fn deepest(&self, scene: &CsgScene) -> f64 {
        scene
            .solids
            .iter()
            .flat_map(|s| s.vertices.iter())
            .map(|p| self.to_pixel(DVec3::from(*p)).z)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Pixel coordinates (x, y) and depth of a scene point.
    pub fn to_pixel(&self, p: DVec3) -> DVec3 {
        (self.basis * p - self.min) * self.scale + self.offset
    }
}

/// The display-list plane of one face, its corners `p` in pixels and depth.
fn face_plane(p: &[DVec3], colour: u32, slope_limit: f64) -> Option<DlPlane> {
    // Newell's normal: robust for any planar polygon; outward for counter-clockwise faces.
    let mut n = DVec3::ZERO;
    for (a, b) in p.iter().zip(p.iter().cycle().skip(1)) {
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    // Every view basis is a rotation (det +1) and every scale positive, so counter-clockwise
    // still means outward.
    if n.length() < 1e-12 {
        return None;
    }
    let c = p.iter().copied().sum::<DVec3>() / p.len() as f64;
    let d = n.dot(c);
    let plane = |z0: f64, dzx: f64, dzy: f64, h: bool, y: bool| DlPlane {
        z0,
        dzx,
        dzy,
        colour,
        h,
        y,
        l: false,
    };
    let (nu, nv, nw) = (n.x, n.y, n.z);
    if nu.abs().max(nv.abs()) > slope_limit * nw.abs() {
        let len = (nu * nu + nv * nv).sqrt();
        return Some(plane(d / len, -nu / len, -nv / len, false, true));
    }
    Some(plane(d / nw, -nu / nw, -nv / nw, nw < 0.0, false))
}

/// Perpendicular planes (Y = 1) along the solid's silhouette: one per edge of the convex hull
/// of its projected vertices, K the signed distance in pixels from the edge, K ≥ 0 inside
/// (the polygon edges of §5.3.1). They change nothing inside the silhouette; outside it they
/// keep the solid out even where one of its back planes lies in front of the screen, which the
/// row "A < 0 ≤ B: Put 1" of §2.3.3 would otherwise turn into a solid reaching to maxdepth
/// (docs/voxelization.md). None when the solid projects to less than an area.
pub fn silhouette_planes(frame: &Frame, s: &ConvexSolid, colour: u32) -> Vec<DlPlane> {
    outline_planes(&pixels(frame, s), colour, |_, _| true)
}

/// Solid `s`'s vertices in `frame`'s pixels and depth, in its order: projected once for all
/// the faces that share them (three on a prism's side) and for its outline.
pub fn pixels(frame: &Frame, s: &ConvexSolid) -> Vec<DVec3> {
    (s.vertices.iter())
        .map(|v| frame.to_pixel(DVec3::from(*v)))
        .collect()
}

/// [`silhouette_planes`] of the edges `keep` keeps.
fn outline_planes(
    pixels: &[DVec3],
    colour: u32,
    keep: impl Fn(glam::DVec2, glam::DVec2) -> bool,
) -> Vec<DlPlane> {
    // A prism along the view (its bottom's corners, then its top's) projects each top corner
    // onto the bottom one, bit for bit: those repeats are left out before the hull's sort,
    // whose dedup would drop them anyway, so the hull is the same and the sort half as long.
    let half = pixels.len() / 2;
    let repeats = |j: usize, p: &DVec3| {
        let q = j.checked_sub(half).map(|i| pixels[i]);
        q.is_some_and(|q| p.x.to_bits() == q.x.to_bits() && p.y.to_bits() == q.y.to_bits())
    };
    let pts = (pixels.iter().enumerate())
        .filter(|&(j, p)| !repeats(j, p))
        .map(|(_, p)| p.truncate());
    let hull = convex_hull(pts.collect());
    if hull.len() < 3 {
        return vec![];
    }
    let mut planes = Vec::with_capacity(hull.len());
    for (a, b) in hull.iter().zip(hull.iter().cycle().skip(1)) {
        let e = *b - *a;
        let len = e.length();
        if len < 1e-12 || !keep(*a, *b) {
            continue;
        }
        // K(p) = e × (p − a) / |e|: positive to the left of a → b, inside a counter-clockwise hull.
        planes.push(DlPlane {
            z0: (e.y * a.x - e.x * a.y) / len,
            dzx: -e.y / len,
            dzy: e.x / len,
            colour,
            h: false,
            y: true,
            l: false,
        });
    }
    planes
}

/// The factor a perpendicular plane's K is multiplied by before it is quantized for a
/// `width`×`height` array: the largest power of two (at least 1) that keeps |K| at every
/// pixel, and each of K0, dKx, dKy, within half the largest word.
///
/// The array reads only the sign of K (§2.3.3, §2.3.4: K < 0 outside, K ≥ 0 inside), so any
/// positive multiple of the distance is the same plane to it; but each of K0, dKx, dKy is
/// rounded to 2^-(F+1), so K in pixels (|dKx|, |dKy| ≤ 1) puts the trace up to
/// 2^-(F+1)·(1 + x + y) pixels off: 0.06 pixel at the far corner of 64×64 with the thesis's
/// word, enough to move pixel columns near a face in and out of a solid (docs/depth-word.md).
/// Scaled by s the trace is off by that over s. A plane whose trace crosses the window has
/// |K| ≤ width + height pixels at its corners, so s ≥ (largest word)/(4·(width + height)):
/// 4096 at 64×64, 1024 at 256×256 with the thesis's word. A power of two scales every f64
/// sum of the exact model exactly, so `float` draws the same pixels either way.
pub fn perpendicular_scale(p: &DlPlane, fmt: &WordFormat, width: usize, height: usize) -> f64 {
    let (xm, ym) = (
        width.saturating_sub(1) as f64,
        height.saturating_sub(1) as f64,
    );
    // The coefficients are words too: on an array one pixel wide or high the corners do not
    // bound dKx or dKy (a thin scene, `cube([50, 1, 1])` at 32 voxels across, overflowed).
    let largest = [(0.0, 0.0), (xm, 0.0), (0.0, ym), (xm, ym)]
        .iter()
        .map(|&(x, y)| (p.z0 + x * p.dzx + y * p.dzy).abs())
        .chain([p.z0.abs(), p.dzx.abs(), p.dzy.abs()])
        .fold(0.0, f64::max);
    let room = fmt.to_real(fmt.max_word()) / 2.0;
    if !(largest > 0.0 && largest.is_finite()) || largest >= room {
        return 1.0;
    }
    // 2^k with 2^k·largest <= room; k < 64 keeps every product exact and finite.
    let k = (room / largest).log2().floor().clamp(0.0, 63.0) as i32;
    let s = 2f64.powi(k);
    if s * largest > room {
        s / 2.0
    } else {
        s
    }
}

/// Multiply every perpendicular plane's K0, dKx, dKy in `dl` by its [`perpendicular_scale`].
pub fn scale_perpendicular(dl: &mut DisplayList, fmt: &WordFormat, width: usize, height: usize) {
    for p in dl.planes.iter_mut().filter(|p| p.y) {
        let s = perpendicular_scale(p, fmt, width, height);
        (p.z0, p.dzx, p.dzy) = (p.z0 * s, p.dzx * s, p.dzy * s);
    }
}

/// Convex hull, counter-clockwise (positive signed area), without collinear points
/// (Andrew's monotone chain).
fn convex_hull(mut pts: Vec<glam::DVec2>) -> Vec<glam::DVec2> {
    // Equal keys are equal points, bit for bit: a stable sort would give the same order.
    pts.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: glam::DVec2, a: glam::DVec2, b: glam::DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<glam::DVec2> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = hull.len();
        for i in 0..pts.len() {
            let p = pts[if pass == 0 { i } else { pts.len() - 1 - i }];
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Nearest palette code (1..=15) to an RGBA colour.
pub fn colour_code(rgba: [f64; 4]) -> u32 {
    (1..16u32)
        .min_by(|&a, &b| {
            let dist = |c: u32| {
                let p = crate::palette::rgb(c);
                (0..3)
                    .map(|k| (p[k] as f64 / 255.0 - rgba[k]).powi(2))
                    .sum::<f64>()
            };
            dist(a).total_cmp(&dist(b))
        })
        .unwrap_or(7)
}

/// One display list per solid; solids without a colour take codes 1..6 in turn. `slope_limit`
/// is [`max_slope`] for the array the lists are for.
pub fn display_lists(scene: &CsgScene, frame: &Frame, slope_limit: f64) -> Vec<DisplayList> {
    scene
        .solids
        .iter()
        .enumerate()
        .map(|(i, s)| display_list(frame, i, s, slope_limit))
        .collect()
}

/// [`display_list`] closed along the solid's silhouette (§5.3.1, in the list's colour): the
/// list a slice draws, whatever the screen rule would do. A silhouette edge along which a
/// face of the solid already stands perpendicular to the screen (a side of an extrusion
/// along the view) has that face's plane in the list, the same line; it gets no second one
/// (found as `face_list` makes the list): a prism of 1,080 sides had 2,162 planes, now 1,082.
pub fn closed_list(frame: &Frame, i: usize, s: &ConvexSolid, slope_limit: f64) -> DisplayList {
    closed_list_at(&pixels(frame, s), i, s, slope_limit)
}

/// [`closed_list`] from the solid's vertices already projected ([`pixels`]).
pub fn closed_list_at(
    pixels: &[DVec3],
    i: usize,
    s: &ConvexSolid,
    slope_limit: f64,
) -> DisplayList {
    let mut sides = vec![];
    let mut dl = face_list(pixels, i, s, slope_limit, Some(&mut sides));
    let colour = dl.planes.first().map_or(1, |p| p.colour);
    sides.sort_unstable();
    let open = |a, b| sides.binary_search(&segment_key(a, b)).is_err();
    dl.planes.extend(outline_planes(pixels, colour, open));
    dl
}

/// A segment's two ends, bit for bit, in either order.
fn segment_key(a: glam::DVec2, b: glam::DVec2) -> [u64; 4] {
    let (a, b) = match a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)) {
        std::cmp::Ordering::Greater => (b, a),
        _ => (a, b),
    };
    [a.x, a.y, b.x, b.y].map(f64::to_bits)
}

/// [`display_lists`]' list of solid `s`, the scene's `i`-th.
pub fn display_list(frame: &Frame, i: usize, s: &ConvexSolid, slope_limit: f64) -> DisplayList {
    face_list(&pixels(frame, s), i, s, slope_limit, None)
}

/// [`display_list`], and into `sides` the segment each face perpendicular to the screen
/// projects to, when it projects to one exactly: all its corners on two points, bit for bit
/// (the same vertices' projections). Such a face's Newell normal has a depth part of exactly
/// 0 (its terms cancel in pairs), so [`face_plane`] makes it a perpendicular plane: the line
/// through the two points.
fn face_list(
    pixels: &[DVec3],
    i: usize,
    s: &ConvexSolid,
    slope_limit: f64,
    mut sides: Option<&mut Vec<[u64; 4]>>,
) -> DisplayList {
    let colour = s.colour.map_or(1 + (i % 6) as u32, colour_code);
    let mut p: Vec<DVec3> = vec![];
    let mut planes: Vec<DlPlane> = Vec::with_capacity(s.faces.len());
    for f in &s.faces {
        p.clear();
        p.extend(f.iter().map(|&v| pixels[v as usize]));
        let Some(plane) = face_plane(&p, colour, slope_limit) else {
            continue;
        };
        if let (Some(sides), true) = (sides.as_deref_mut(), plane.y) {
            sides.extend(segment(&p).map(|(a, b)| segment_key(a, b)));
        }
        planes.push(plane);
    }
    if planes.is_empty() {
        // Every face is degenerate at this scale (a solid far smaller than a pixel): a list
        // without planes would be all of space to the float model and to the clipping stack,
        // and nothing to the array. Say "nothing" to all three: one perpendicular plane with
        // K = -1 everywhere (outside).
        planes.push(DlPlane {
            z0: -1.0,
            dzx: 0.0,
            dzy: 0.0,
            colour,
            h: false,
            y: true,
            l: false,
        });
    }
    DisplayList {
        planes,
        terminator: 1234,
    }
}

/// The two points a face's corners all project to, if they do.
fn segment(p: &[DVec3]) -> Option<(glam::DVec2, glam::DVec2)> {
    let a = p.first()?.truncate();
    let b = p.iter().map(|q| q.truncate()).find(|&q| q != a)?;
    p.iter()
        .all(|q| q.truncate() == a || q.truncate() == b)
        .then_some((a, b))
}

/// A scene projected for one array: a display list per solid and the clipping function of
/// its tree (None when the tree is empty: nothing is drawn).
#[derive(Clone, Debug)]
pub struct Projected {
    /// One display list per solid, in scene order (§5.2).
    pub lists: Vec<DisplayList>,
    /// The clipping function of the CSG tree (§5.2.1), None when nothing is drawn.
    pub clip: Option<Clip>,
}

/// Project `scene` in `view` onto a `width`×`height` array with word format `fmt`: the bounds
/// fill the array, and the scene must fit in depth (nearest point at [`DEPTH_MARGIN`], deepest
/// under maxdepth). A clipping function of more products than the compiler takes is refused
/// first ([`crate::compile::check_clip_size`]), before any solid is projected.
pub fn project(
    scene: &CsgScene,
    view: View,
    width: usize,
    height: usize,
    fmt: &WordFormat,
) -> Result<Projected> {
    let clip = clip_of(&scene.root);
    let Some(expr) = clip.as_ref().filter(|_| !scene.solids.is_empty()) else {
        return Ok(Projected {
            lists: vec![],
            clip: None,
        });
    };
    // A function too big to compile is refused before thousands of solids are projected.
    crate::compile::check_clip_size(expr).map_err(Error::Clip)?;
    let frame = Frame::fit(scene, view, width, height)?;
    let maxdepth = fmt.to_real(fmt.maxdepth());
    let deepest = frame.deepest(scene);
    if deepest >= maxdepth {
        // The fewest integer bits whose maxdepth (2^I) is beyond the deepest point.
        let int = (deepest.log2().floor() as u32 + 1).max(fmt.int + 1);
        return Err(Error::DeeperThanMaxdepth {
            detail: format!(
                "the scene is {deepest:.0} depth units deep on a {width}x{height} array, \
                 beyond maxdepth {maxdepth}"
            ),
            suggested: WordFormat { int, ..*fmt },
        });
    }
    let mut lists = display_lists(scene, &frame, max_slope(fmt, width, height));
    // A back face in front of the screen meets the row "A < 0 <= B: Put 1" of §2.3.3, which
    // can draw the solid where it has none (docs/stability.md: a steep face of a solid that
    // does not fill the array). Close the silhouette with perpendicular planes for the solids
    // where that happens on this array, as voxelizing does for all.
    for (dl, solid) in lists.iter_mut().zip(&scene.solids) {
        if drawn_by_screen_rule(dl, width, height, maxdepth) {
            let colour = dl.planes[0].colour;
            dl.planes.extend(silhouette_planes(&frame, solid, colour));
        }
    }
    Ok(Projected { lists, clip })
}

/// Does the thesis's rule for back planes in front of the screen (a negative back plane puts
/// maxdepth into B) draw convex list `dl` at some pixel of a `width`×`height` array where its
/// exact half-space intersection shows nothing? (The rule of `float::ScreenRule::Thesis`.)
///
/// Only a pixel where some back plane is at or in front of the screen can differ (elsewhere
/// the rule's B is the exact one), so each row is tried at a superset of those pixels: the
/// ends of the row that back planes reach ([`Row::candidates`]), inside every perpendicular
/// plane. A sphere's 80,000 planes then cost rows × planes, not pixels × planes.
fn drawn_by_screen_rule(dl: &DisplayList, width: usize, height: usize, maxdepth: f64) -> bool {
    if !dl.planes.iter().any(|p| !p.h && !p.y) || width == 0 || height == 0 {
        return false;
    }
    let span = (width as f64, height as f64);
    if behind_the_screen(dl, width, height, span) {
        return false;
    }
    (0..height).any(|y| {
        Row::of(dl, y as f64, width, span)
            .candidates()
            .any(|x| drawn_at(dl, x as f64, y as f64, maxdepth))
    })
}

/// Whether every back plane of `dl` is behind the screen (v > 0) at every pixel of a
/// `width`×`height` array, by a margin beyond the rounding of [`drawn_at`]'s sum: v is
/// linear, so its least value over the array is at a corner. Then the rule's B is the exact
/// one everywhere, and a list is checked in its planes' count, not rows × planes (a prism of
/// 1,080 sides on a 512-row screen: 1,080 · 4 sums instead of 1,080 · 512 row crossings).
fn behind_the_screen(dl: &DisplayList, width: usize, height: usize, span: (f64, f64)) -> bool {
    let (x1, y1) = ((width - 1) as f64, (height - 1) as f64);
    dl.planes.iter().filter(|p| !p.h && !p.y).all(|p| {
        let tol = 8.0 * f64::EPSILON * (p.z0.abs() + span.0 * p.dzx.abs() + span.1 * p.dzy.abs());
        let least = p.z0 + (x1 * p.dzx).min(0.0) + (y1 * p.dzy).min(0.0);
        least > 2.0 * tol
    })
}

/// Whether the rule draws `dl` at pixel (x, y) where the exact intersection does not.
fn drawn_at(dl: &DisplayList, x: f64, y: f64, maxdepth: f64) -> bool {
    let (mut lo, mut hi, mut hi_rule) = (f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY);
    for p in &dl.planes {
        let v = p.z0 + x * p.dzx + y * p.dzy;
        if p.y {
            if v < 0.0 {
                return false;
            }
        } else if p.h {
            lo = lo.max(v);
        } else {
            hi = hi.min(v);
            hi_rule = if v < 0.0 {
                f64::INFINITY
            } else {
                hi_rule.min(v)
            };
        }
    }
    let exact = lo < hi && hi > 0.0;
    !exact && lo < hi_rule && lo.max(0.0) < maxdepth
}

/// One row of the array seen from the planes of a list: the pixels worth trying, as whole
/// pixel bounds that hold each plane's sign test with a margin for rounding.
struct Row {
    width: i64,
    /// Back planes reach 0 at x ≤ `prefix` …
    prefix: i64,
    /// … and at x ≥ `suffix` (so with `prefix + 1 >= suffix` the whole row).
    suffix: i64,
    /// Every perpendicular plane is non-negative only within `inside.0 ..= inside.1`.
    inside: (i64, i64),
}

impl Row {
    fn of(dl: &DisplayList, y: f64, width: usize, span: (f64, f64)) -> Row {
        let w = width as i64;
        let mut row = Row {
            width: w,
            prefix: -1,
            suffix: w,
            inside: (0, w - 1),
        };
        for p in dl.planes.iter().filter(|p| !p.h) {
            // v(x) = c + b·x along the row. The exact test computes it in another order, so
            // both tests below hold `tol` more than the rounding either can make.
            let (c, b) = (p.z0 + y * p.dzy, p.dzx);
            let tol = 8.0 * f64::EPSILON * (p.z0.abs() + span.0 * b.abs() + span.1 * p.dzy.abs());
            if p.y {
                // Inside: v ≥ 0, so at least v ≥ -tol.
                let (lo, hi) = half_line(c + tol, b, true, w);
                row.inside = (row.inside.0.max(lo), row.inside.1.min(hi));
            } else {
                // In front of the screen: v < 0 (or 0), so at most v ≤ tol.
                let (lo, hi) = half_line(c - tol, b, false, w);
                if lo <= 0 {
                    row.prefix = row.prefix.max(hi);
                }
                if hi >= w - 1 {
                    row.suffix = row.suffix.min(lo);
                }
            }
        }
        row
    }

    /// The pixels to try, left to right, within `inside`.
    fn candidates(self) -> impl Iterator<Item = i64> {
        let (lo, hi) = self.inside;
        let left = lo..=hi.min(self.prefix);
        let right = lo.max(self.suffix.max(self.prefix + 1))..=hi;
        let width = self.width;
        left.chain(right).filter(move |&x| x >= 0 && x < width)
    }
}

/// The pixels of a row of `w` where c + b·x ≥ 0 (`above`) or ≤ 0, as `(lo, hi)` widened by a
/// pixel; `(0, -1)`-like empty ranges when none, `(-1, w)` when every pixel.
fn half_line(c: f64, b: f64, above: bool, w: i64) -> (i64, i64) {
    let all = (-1, w);
    let none = (w, -1);
    if b == 0.0 || !c.is_finite() || !b.is_finite() {
        let holds = if above { c >= 0.0 } else { c <= 0.0 };
        return if holds || !c.is_finite() { all } else { none };
    }
    // The crossing, clamped so the conversion to whole pixels stays in range.
    let x0 = (-c / b).clamp(-2.0, w as f64 + 2.0);
    if (b > 0.0) == above {
        // Holds for x ≥ x0.
        (x0.floor() as i64 - 1, w)
    } else {
        // Holds for x ≤ x0.
        (-1, x0.ceil() as i64 + 1)
    }
}

/// The scene's CSG tree as a clipping function over the solids (None for an empty scene).
/// Walks with an explicit stack, so deep trees cannot overflow it.
pub fn clip_of(root: &CsgNode) -> Option<Clip> {
    enum Task<'a> {
        Visit(&'a CsgNode),
        Build(&'a CsgNode, usize),
    }
    let mut tasks = vec![Task::Visit(root)];
    let mut out: Vec<Option<Clip>> = vec![];
    while let Some(t) = tasks.pop() {
        match t {
            Task::Visit(n) => match n {
                CsgNode::Solid(i) => out.push(Some(Clip::Obj(*i))),
                CsgNode::Empty => out.push(None),
                _ => {
                    let c = n.children();
                    tasks.push(Task::Build(n, c.len()));
                    tasks.extend(c.iter().rev().map(Task::Visit));
                }
            },
            Task::Build(n, k) => {
                let kids = out.split_off(out.len() - k);
                out.push(combine(n, kids));
            }
        }
    }
    out.pop().flatten()
}

fn combine(n: &CsgNode, kids: Vec<Option<Clip>>) -> Option<Clip> {
    let and = |a: Clip, b: Clip| Clip::And(Box::new(a), Box::new(b));
    match n {
        CsgNode::Union(_) => kids
            .into_iter()
            .flatten()
            .reduce(|a, b| Clip::Or(Box::new(a), Box::new(b))),
        // An empty operand makes an intersection empty.
        CsgNode::Intersection(_) => kids
            .into_iter()
            .collect::<Option<Vec<_>>>()?
            .into_iter()
            .reduce(and),
        CsgNode::Difference(_) => {
            let mut it = kids.into_iter();
            let first = it.next().flatten()?;
            Some(
                it.flatten()
                    .fold(first, |a, b| and(a, Clip::Not(Box::new(b)))),
            )
        }
        // The complement of nothing is everything, which no display list can draw.
        CsgNode::Complement(_) => Some(Clip::Not(Box::new(kids.into_iter().next()??))),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn cube(lo: f64, hi: f64) -> ConvexSolid {
        let v = |x: bool, y: bool, z: bool| {
            [
                [lo, hi][x as usize],
                [lo, hi][y as usize],
                [lo, hi][z as usize],
            ]
        };
        let vertices: Vec<[f64; 3]> = (0..8)
            .map(|i| v(i & 1 == 1, i & 2 == 2, i & 4 == 4))
            .collect();
        // Counter-clockwise seen from outside.
        let faces = vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ];
        ConvexSolid {
            vertices,
            faces: faces.into(),
            colour: None,
            line: 1,
        }
    }

    #[test]
    fn top_view_of_a_cube_has_one_front_one_back_and_four_perpendicular_faces() {
        let scene = CsgScene::convex(vec![cube(0.0, 10.0)], CsgNode::Solid(0));
        let frame = Frame::fit(&scene, View::Top, 11, 11).unwrap();
        let dl = &display_lists(&scene, &frame, 1024.0)[0];
        let fronts: Vec<&DlPlane> = dl.planes.iter().filter(|p| p.h && !p.y).collect();
        let backs: Vec<&DlPlane> = dl.planes.iter().filter(|p| !p.h && !p.y).collect();
        assert_eq!((fronts.len(), backs.len()), (1, 1));
        assert_eq!(dl.planes.iter().filter(|p| p.y).count(), 4);
        assert!((fronts[0].z0 - DEPTH_MARGIN).abs() < 1e-9, "{dl:?}");
        assert!(fronts[0].dzx.abs() < 1e-12 && fronts[0].dzy.abs() < 1e-12);
        assert!((backs[0].z0 - DEPTH_MARGIN - 10.0).abs() < 1e-9);
        // Every perpendicular plane is non-negative at the centre pixel (inside).
        for p in dl.planes.iter().filter(|p| p.y) {
            assert!(p.z0 + 5.0 * p.dzx + 5.0 * p.dzy > 0.0, "{p:?}");
        }
    }

    /// An n-sided prism from z = 0 to `h` over `outline` (counter-clockwise), its top moved
    /// by `shear`.
    fn prism(outline: &[glam::DVec2], h: f64, shear: glam::DVec2) -> ConvexSolid {
        let n = outline.len();
        let vertices = [(0.0, glam::DVec2::ZERO), (h, shear)]
            .iter()
            .flat_map(|&(z, d)| outline.iter().map(move |p| [p.x + d.x, p.y + d.y, z]))
            .collect();
        let mut faces = vec![(0..n).rev().collect(), (n..2 * n).collect()];
        faces.extend((0..n).map(|i| vec![i, (i + 1) % n, n + (i + 1) % n, n + i]));
        ConvexSolid {
            vertices,
            faces: faces.into(),
            colour: None,
            line: 1,
        }
    }

    fn polygon(n: usize, r: f64, c: glam::DVec2) -> Vec<glam::DVec2> {
        (0..n)
            .map(|i| {
                let (s, co) = (std::f64::consts::TAU * i as f64 / n as f64).sin_cos();
                c + r * glam::DVec2::new(co, s)
            })
            .collect()
    }

    /// The slicer's frame: the scene's axes, a pixel per unit, depth along z.
    fn slicer_frame() -> Frame {
        Frame {
            basis: DMat3::IDENTITY,
            min: DVec3::ZERO,
            scale: DVec3::ONE,
            offset: DVec3::new(-0.5, -0.5, DEPTH_MARGIN),
        }
    }

    /// Inside every plane of `dl` at pixel (x, y) and depth z, in f64.
    fn inside(dl: &DisplayList, x: f64, y: f64, z: f64) -> bool {
        dl.planes.iter().all(|p| {
            let v = p.z0 + x * p.dzx + y * p.dzy;
            match (p.y, p.h) {
                (true, _) => v >= 0.0,
                (false, true) => z >= v,
                (false, false) => z <= v,
            }
        })
    }

    #[test]
    fn a_prism_along_the_view_gets_no_second_plane_per_side() {
        let frame = slicer_frame();
        let outline = polygon(1080, 20.0, glam::DVec2::new(30.0, 30.0));
        let s = prism(&outline, 7.0, glam::DVec2::ZERO);
        let open = display_list(&frame, 0, &s, 1024.0);
        assert_eq!(open.planes.iter().filter(|p| p.y).count(), 1080);
        let closed = closed_list(&frame, 0, &s, 1024.0);
        assert!(closed.planes.len() <= 1082 + 8, "{}", closed.planes.len());
        // Sheared a little, its sides are steep (perpendicular planes in the list) but not
        // perpendicular: every silhouette plane stays.
        let s = prism(&outline, 7.0, glam::DVec2::new(1e-5, 0.0));
        let open = display_list(&frame, 0, &s, 1024.0);
        assert_eq!(open.planes.iter().filter(|p| p.y).count(), 1080);
        let with_all = open.planes.len() + silhouette_planes(&frame, &s, 1).len();
        assert_eq!(closed_list(&frame, 0, &s, 1024.0).planes.len(), with_all);
        // Seen from the side its caps are steep faces, not segments: the silhouette planes
        // stay (a cube in the iso view has no face perpendicular to the screen).
        let c = cube(0.0, 10.0);
        let scene = CsgScene::convex(vec![c.clone()], CsgNode::Solid(0));
        let iso = Frame::fit(&scene, View::Iso, 64, 64).unwrap();
        let with_all =
            display_list(&iso, 0, &c, 1024.0).planes.len() + silhouette_planes(&iso, &c, 1).len();
        assert_eq!(closed_list(&iso, 0, &c, 1024.0).planes.len(), with_all);
    }

    proptest! {
        /// A list closed without the planes its sides already give decides every point as
        /// the list with every silhouette plane does, but within 1e-9 pixel of an edge (where
        /// the two planes of one line, rounded apart, may disagree): random prisms along the
        /// view (some sheared off it), of 3 to 300 sides, at random sample points.
        #[test]
        fn closing_a_prism_by_its_sides_decides_as_all_silhouette_planes(
            n in 3usize..300,
            r in 0.01f64..40.0,
            cx in -50.0f64..50.0,
            cy in -50.0f64..50.0,
            h in 0.01f64..20.0,
            shear in prop_oneof![Just((0.0, 0.0)), (-1e-3f64..1e-3, -1e-3f64..1e-3)],
            pts in proptest::collection::vec((-100.0f64..100.0, -100.0f64..100.0, -1.0f64..30.0), 64),
        ) {
            let frame = slicer_frame();
            let s = prism(&polygon(n, r, glam::DVec2::new(cx, cy)), h, shear.into());
            let closed = closed_list(&frame, 0, &s, 1024.0);
            let mut all = display_list(&frame, 0, &s, 1024.0);
            all.planes.extend(silhouette_planes(&frame, &s, 1));
            let near_edge = |x: f64, y: f64| all.planes.iter().filter(|p| p.y).any(|p| {
                (p.z0 + x * p.dzx + y * p.dzy).abs() < 1e-9
            });
            // And points a millionth of the radius inside and outside the corners.
            let corners = polygon(n, r, glam::DVec2::new(cx, cy));
            let close = corners.iter().step_by(n.div_ceil(16)).flat_map(|&v| {
                let c = glam::DVec2::new(cx, cy);
                [1.0 - 1e-6, 1.0 + 1e-6].map(|k| c + (v - c) * k)
            });
            let close: Vec<(f64, f64, f64)> = close.map(|p| (p.x, p.y, h / 2.0)).collect();
            for (x, y, z) in pts.into_iter().chain(close) {
                if !near_edge(x, y) {
                    prop_assert_eq!(inside(&closed, x, y, z), inside(&all, x, y, z), "({}, {}, {})", x, y, z);
                }
            }
        }
    }

    #[test]
    fn iso_view_faces_split_three_and_three() {
        let scene = CsgScene::convex(vec![cube(-1.0, 1.0)], CsgNode::Solid(0));
        let frame = Frame::fit(&scene, View::Iso, 64, 64).unwrap();
        let dl = &display_lists(&scene, &frame, 1024.0)[0];
        assert_eq!(dl.planes.iter().filter(|p| p.h).count(), 3);
        assert_eq!(dl.planes.iter().filter(|p| !p.h && !p.y).count(), 3);
    }

    #[test]
    fn slope_limit_keeps_every_sum_in_the_word() {
        let thesis = WordFormat::THESIS;
        assert_eq!(max_slope(&thesis, 250, 250), 1024.0);
        for (w, h) in [(1024, 1024), (4096, 4096), (65536, 1)] {
            let s = max_slope(&thesis, w, h);
            let worst = 1024.0 + s * (w + h) as f64;
            assert!(
                s > 0.0 && worst <= thesis.to_real(thesis.max_word()),
                "{w}x{h}: {s}"
            );
        }
        // One overflow bit leaves about maxdepth of headroom: about 2 units per pixel.
        let one_overflow_bit = WordFormat::new(10, 10, 1).unwrap();
        let s = max_slope(&one_overflow_bit, 250, 250);
        assert!(s > 2.0 && s < 2.1, "{s}");
    }

    #[test]
    fn perpendicular_planes_scale_to_the_word_and_keep_their_sign() {
        let fmt = WordFormat::THESIS;
        let room = fmt.to_real(fmt.max_word()) / 2.0;
        // A wall at 7° through (20.3, 11.7) on a 64×64 array, K in pixels.
        let (c, s) = (7f64.to_radians().cos(), 7f64.to_radians().sin());
        let k = DlPlane {
            z0: 20.3 * c + 11.7 * s,
            dzx: -c,
            dzy: -s,
            colour: 1,
            h: false,
            y: true,
            l: false,
        };
        let scale = perpendicular_scale(&k, &fmt, 64, 64);
        // |K| is largest at (63, 63), 48.6 pixels: 2^14·48.6 within 2^20, half the word.
        assert_eq!(scale, 16384.0);
        assert_eq!(scale.log2().fract(), 0.0);
        let mut dl = DisplayList {
            planes: vec![k.clone()],
            terminator: 1234,
        };
        scale_perpendicular(&mut dl, &fmt, 64, 64);
        let scaled = &dl.planes[0];
        crate::compile::check_window(std::slice::from_ref(&dl), &fmt, 64, 64).unwrap();
        let q = crate::compile::coeffs(&fmt, scaled.z0, scaled.dzx, scaled.dzy).unwrap();
        let unscaled = crate::compile::coeffs(&fmt, k.z0, k.dzx, k.dzy).unwrap();
        let (mut worst, mut worst_unscaled) = (0f64, 0f64);
        for y in 0..64i64 {
            for x in 0..64i64 {
                let exact = k.z0 + x as f64 * k.dzx + y as f64 * k.dzy;
                let v = scaled.z0 + x as f64 * scaled.dzx + y as f64 * scaled.dzy;
                // A power of two scales the f64 sum exactly: the float model is unchanged.
                assert_eq!(v, exact * scale);
                assert!(v.abs() <= room);
                let word = fmt.to_real(q.c0 + x * q.dx + y * q.dy) / scale;
                worst = worst.max((word - exact).abs());
                let word = fmt.to_real(unscaled.c0 + x * unscaled.dx + y * unscaled.dy);
                worst_unscaled = worst_unscaled.max((word - exact).abs());
            }
        }
        // The trace: within 2^-11·127 pixels unscaled, that over 16384 scaled.
        let e = 127.0 / 2048.0;
        assert!(worst <= e / scale, "{worst}");
        assert!(worst_unscaled > 100.0 * worst, "{worst_unscaled} {worst}");
        // Never shrunk, and a plane already too large for the word is left alone.
        let far = DlPlane {
            z0: 3.0e6,
            ..k.clone()
        };
        assert_eq!(perpendicular_scale(&far, &fmt, 64, 64), 1.0);
    }

    /// On an array one pixel high the corners do not bound dKy: a wall along X 0.32 pixel
    /// from the row (a 1-unit-thin cube at 1.5625 units a voxel) was scaled until dKy = 2^21,
    /// one past the word, and the thin scene refused. Every coefficient now fits.
    #[test]
    fn a_perpendicular_plane_fits_the_word_on_a_one_pixel_array() {
        let fmt = WordFormat::THESIS;
        let room = fmt.to_real(fmt.max_word()) / 2.0;
        let wall = DlPlane {
            z0: 0.32,
            dzx: 0.0,
            dzy: -1.0,
            colour: 1,
            h: false,
            y: true,
            l: false,
        };
        for (w, h) in [(32, 1), (1, 32), (1, 1), (2, 1)] {
            let mut dl = DisplayList {
                planes: vec![wall.clone()],
                terminator: 1,
            };
            scale_perpendicular(&mut dl, &fmt, w, h);
            let p = &dl.planes[0];
            assert!(
                [p.z0, p.dzx, p.dzy].iter().all(|c| c.abs() <= room),
                "{w}x{h}"
            );
            crate::compile::coeffs(&fmt, p.z0, p.dzx, p.dzy).unwrap();
            crate::compile::check_window(std::slice::from_ref(&dl), &fmt, w, h).unwrap();
            // Still scaled far up: the trace's rounding is shrunk as on any array.
            assert!(p.z0 / wall.z0 >= 1024.0, "{w}x{h}");
        }
    }

    #[test]
    fn steep_faces_compile_on_a_large_array() {
        let fmt = WordFormat::THESIS;
        // A thin wedge seen almost edge-on: slopes of thousands of depth units per pixel.
        let mut s = cube(0.0, 10.0);
        for v in &mut s.vertices {
            v[2] += v[0] * 400.0;
        }
        let scene = CsgScene::convex(vec![s], CsgNode::Solid(0));
        for size in [250, 1024, 2048] {
            let frame = Frame::fit(&scene, View::Front, size, size).unwrap();
            let dl = &display_lists(&scene, &frame, max_slope(&fmt, size, size))[0];
            for p in &dl.planes {
                crate::compile::coeffs(&fmt, p.z0, p.dzx, p.dzy).unwrap();
            }
        }
    }

    #[test]
    fn csg_tree_becomes_a_clipping_function() {
        let t = CsgNode::Difference(vec![
            CsgNode::Union(vec![CsgNode::Solid(0), CsgNode::Solid(1)]),
            CsgNode::Solid(2),
            CsgNode::Empty,
        ]);
        let e = clip_of(&t).unwrap();
        let prods = e.products().unwrap();
        assert_eq!(
            prods,
            vec![vec![(0, false), (2, true)], vec![(1, false), (2, true)]]
        );
        assert_eq!(
            clip_of(&CsgNode::Intersection(vec![
                CsgNode::Solid(0),
                CsgNode::Empty
            ])),
            None
        );
        let mut deep = CsgNode::Solid(0);
        for _ in 0..100_000 {
            deep = CsgNode::Union(vec![deep]);
        }
        assert_eq!(clip_of(&deep), Some(Clip::Obj(0)));
    }

    /// The whole-array scan [`drawn_by_screen_rule`] narrows: every pixel tried.
    fn drawn_anywhere(dl: &DisplayList, width: usize, height: usize, maxdepth: f64) -> bool {
        dl.planes.iter().any(|p| !p.h && !p.y)
            && (0..height).any(|y| (0..width).any(|x| drawn_at(dl, x as f64, y as f64, maxdepth)))
    }

    /// A coefficient: often a small integer or a half (so a plane meets 0 exactly at a pixel
    /// centre), sometimes any value, sometimes far beyond the array.
    fn coefficient(scale: f64) -> impl Strategy<Value = f64> {
        prop_oneof![
            (-8i32..=8).prop_map(f64::from),
            (-16i32..=16).prop_map(|k| f64::from(k) / 2.0),
            -scale..scale,
            (-1e9f64..1e9),
        ]
    }

    fn plane() -> impl Strategy<Value = DlPlane> {
        (
            coefficient(60.0),
            coefficient(6.0),
            coefficient(6.0),
            0u8..3,
        )
            .prop_map(|(z0, dzx, dzy, kind)| DlPlane {
                z0,
                dzx,
                dzy,
                colour: 1,
                h: kind == 0,
                y: kind == 2,
                l: false,
            })
    }

    proptest! {
        /// The narrowed check agrees with trying every pixel, and tries every pixel the rule
        /// draws, for random lists of front, back and perpendicular planes on small arrays.
        #[test]
        fn the_screen_rule_check_agrees_with_every_pixel(
            planes in proptest::collection::vec(plane(), 1..8),
            width in 1usize..24,
            height in 1usize..24,
            maxdepth in prop_oneof![Just(1024.0), 1.0f64..200.0],
        ) {
            let dl = DisplayList { planes, terminator: 1234 };
            prop_assert_eq!(
                drawn_by_screen_rule(&dl, width, height, maxdepth),
                drawn_anywhere(&dl, width, height, maxdepth)
            );
            // Stronger: every pixel the rule draws is among its row's candidates.
            let span = (width as f64, height as f64);
            for y in 0..height {
                let tried: Vec<i64> = Row::of(&dl, y as f64, width, span).candidates().collect();
                for x in 0..width {
                    if drawn_at(&dl, x as f64, y as f64, maxdepth) {
                        prop_assert!(tried.contains(&(x as i64)), "({x}, {y}) not tried");
                    }
                }
            }
        }
    }

    /// A back plane that crosses the screen where no front plane covers: drawn by the rule
    /// at the left of the array only, and found there.
    #[test]
    fn the_screen_rule_check_finds_a_single_column() {
        let back = |z0: f64, dzx: f64| DlPlane {
            z0,
            dzx,
            dzy: 0.0,
            colour: 1,
            h: false,
            y: false,
            l: false,
        };
        // Back plane 1 is negative at x = 0 only; back plane 2 is below the front there.
        let front = DlPlane {
            z0: 5.0,
            h: true,
            ..back(0.0, 0.0)
        };
        let dl = DisplayList {
            planes: vec![back(3.0, 1.0), front, back(-0.5, 1.0)],
            terminator: 1234,
        };
        assert!(drawn_at(&dl, 0.0, 0.0, 1024.0));
        assert!(!(1..64).any(|x| drawn_at(&dl, x as f64, 0.0, 1024.0)));
        assert!(drawn_by_screen_rule(&dl, 64, 64, 1024.0));
        assert!(drawn_anywhere(&dl, 64, 64, 1024.0));
    }
}

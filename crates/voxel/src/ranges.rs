//! The interval routes to slab masks: the array's plane words, or exact f64, reduced once
//! per pixel to the slabs a primitive meets.

use csgpix_scene::footprint::Footprint;
use csgpix_scene::trimesh::{TriMesh, Window};
use csgpix_scene::winding::OpenMesh;
use glam::DVec2;

use crate::error::Result;
use crate::pixel_box::PixelBox;
use crate::slicer::Slicer;
// Here before crate::slabs took them: the public paths stay.
use crate::sampled::Shape;
use crate::slabs::SlabRuns;
pub use crate::slabs::{toggle_run, SlabRanges};

/// The slabs whose window ([`Slicer::window`]) a depth interval [lo, hi] (in raw word units)
/// meets, both ends closed.
pub(crate) fn slabs_of(slicer: &Slicer, lo: i128, hi: i128) -> (u32, u32) {
    const EMPTY: (u32, u32) = (1, 0);
    if lo > hi {
        return EMPTY;
    }
    // Depths past ±2^62 meet the same slabs as ±2^62 (every slab window lies within the word,
    // far inside that): clamped, the arithmetic fits an i64.
    const FAR: i128 = 1 << 62;
    let (lo, hi) = (lo.clamp(-FAR, FAR) as i64, hi.clamp(-FAR, FAR) as i64);
    let (z0, s) = (slicer.z_plane(0), slicer.slab_raw);
    let (a, b) = slicer.window();
    let last_slab = slicer.grid.dims[2] as i64 - 1;
    // Slab k's window is [z0 + k·s + a, z0 + k·s + b] in raw units: it meets [lo, hi] when
    // z0 + k·s + a <= hi and z0 + k·s + b >= lo, i.e. k <= ⌊(hi − z0 − a) / s⌋ and
    // k >= ⌈(lo − z0 − b) / s⌉.
    let last = (hi - z0 - a).div_euclid(s).min(last_slab);
    let first = (lo - z0 - b + s - 1).div_euclid(s).max(0);
    if first > last || last < 0 || first > last_slab {
        return EMPTY;
    }
    (first as u32, last as u32)
}

/// Pixels of a row [`WordPlanes::row_slabs`] reduces together.
const ROW_CHUNK: usize = 8;

/// A solid's planes as the array's depth generator holds them: Z0, dZx, dZy (or K0, dKx,
/// dKy) in raw words, with each plane's Y and H flags (§2.3).
pub(crate) struct WordPlanes(Vec<(rtl_model::Coeffs, bool, bool)>);

// The slicer's estimate counts RUN_PLANE_BYTES a plane: a word's and an f64's must fit.
const _: () = {
    let word = std::mem::size_of::<(rtl_model::Coeffs, bool, bool)>();
    let float = std::mem::size_of::<(f64, f64, f64, bool, bool)>();
    assert!(word <= crate::slicer::RUN_PLANE_BYTES && float <= crate::slicer::RUN_PLANE_BYTES);
};

impl WordPlanes {
    /// Planes held.
    pub(crate) fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether every plane held is level (dZx = dZy = 0): the same values, so the same
    /// slabs, at every pixel.
    pub(crate) fn level(&self) -> bool {
        self.0.iter().all(|(c, _, _)| c.dx == 0 && c.dy == 0)
    }

    /// Solid `prim`'s planes in the slicer's word; an error names a plane that does not fit.
    pub(crate) fn of(slicer: &Slicer, prim: usize) -> Result<WordPlanes> {
        let fmt = &slicer.fmt;
        let planes = slicer.lists[prim]
            .planes
            .iter()
            .map(|p| {
                csgpix_draw::compile::coeffs(fmt, p.z0, p.dzx, p.dzy)
                    .map(|c| (c, p.y, p.h))
                    .map_err(|(field, message)| crate::Error::Plane {
                        solid: prim,
                        field,
                        message,
                    })
            })
            .collect::<Result<_, _>>()?;
        Ok(WordPlanes(planes))
    }

    /// The planes that decide the solid's interval somewhere in panel `b`, or None when the
    /// solid is nowhere in it: the depth generator's planes pruned as the thesis's panels
    /// draw only the planes that reach them (§2.5). A plane's value is linear over the panel
    /// and, where none of its corner values wraps, lies between its corner values, so:
    ///
    /// * a perpendicular plane (Y) non-negative at every corner never refuses a pixel: dropped;
    ///   negative at every corner, it refuses them all: None;
    /// * a front plane whose largest corner value is below the largest of the front planes'
    ///   smallest corner values, M, is everywhere below the plane that has M: it never sets
    ///   the interval's start (ties kept), and so for back planes and the end;
    /// * the interval starts at M or later and ends at the back planes' m or sooner at every
    ///   pixel, so when [M, m] meets no slab the solid fills nothing in the panel: None.
    ///
    /// Planes whose value wraps at a corner are kept and take no part. [`WordPlanes::slabs`] of
    /// the pruned planes is that of all of them at every pixel of `b` (tested).
    pub(crate) fn in_panel(&self, slicer: &Slicer, b: PixelBox) -> Option<WordPlanes> {
        let fmt = &slicer.fmt;
        let corners = |c: &rtl_model::Coeffs| -> Option<(i64, i64)> {
            let (x1, y1) = (b.x1 as i64 - 1, b.y1 as i64 - 1);
            let v = [
                (b.x0 as i64, b.y0 as i64),
                (x1, b.y0 as i64),
                (b.x0 as i64, y1),
                (x1, y1),
            ]
            .map(|(x, y)| c.c0 + x * c.dx + y * c.dy);
            let fits = v.iter().all(|&v| fmt.wrap(v) == v);
            fits.then(|| (*v.iter().min().unwrap_or(&0), *v.iter().max().unwrap_or(&0)))
        };
        let ext: Vec<_> = self
            .0
            .iter()
            .map(|(c, y, h)| ((*y, *h), corners(c)))
            .collect();
        let d = decisive(&self.0, &ext)?;
        let (lo, hi) = (
            d.lo.map_or(i128::MIN, i128::from),
            d.hi.map_or(i128::MAX, i128::from),
        );
        let (first, last) = slabs_of(slicer, lo, hi);
        (first <= last).then_some(WordPlanes(d.kept))
    }

    /// The slabs the solid fills along pixel (x, y)'s ray: DEPGEN's Z0 + x·dZx + y·dZy
    /// wrapped to the word, reduced to the interval inside every plane.
    pub(crate) fn slabs(&self, slicer: &Slicer, x: i64, y: i64) -> (u32, u32) {
        let (lo, hi) = self.interval(&slicer.fmt, x, y).unwrap_or((1, 0));
        slabs_of(slicer, lo, hi)
    }

    /// [`WordPlanes::slabs`] of pixels `xs` of row `y`, pushed onto `out` in order: the same
    /// values (Z0 + y·dZy + x·dZx is Z0 + x·dZx + y·dZy modulo 2^64, then wrapped to the
    /// word) reduced a plane at a time over up to [`ROW_CHUNK`] pixels, so the same slabs,
    /// without a branch on each plane's kind at every pixel.
    pub(crate) fn row_slabs(
        &self,
        slicer: &Slicer,
        y: i64,
        xs: std::ops::Range<usize>,
        out: &mut Vec<(u32, u32)>,
    ) {
        let fmt = &slicer.fmt;
        for x0 in xs.clone().step_by(ROW_CHUNK) {
            let n = (xs.end - x0).min(ROW_CHUNK);
            let (mut lo, mut hi) = ([i64::MIN; ROW_CHUNK], [i64::MAX; ROW_CHUNK]);
            let mut refused = [false; ROW_CHUNK];
            for (c, perpendicular, front) in &self.0 {
                let row = c.c0.wrapping_add(y.wrapping_mul(c.dy));
                let value = |i: usize| fmt.wrap(row.wrapping_add((x0 + i) as i64 * c.dx));
                match (perpendicular, front) {
                    (true, _) => (0..n).for_each(|i| refused[i] |= value(i) < 0),
                    (false, true) => (0..n).for_each(|i| lo[i] = lo[i].max(value(i))),
                    (false, false) => (0..n).for_each(|i| hi[i] = hi[i].min(value(i))),
                }
            }
            // As `ray_interval`'s None, an empty interval meets no slab.
            out.extend((0..n).map(|i| match refused[i] || lo[i] > hi[i] {
                true => (1, 0),
                false => slabs_of(slicer, lo[i].into(), hi[i].into()),
            }));
        }
    }

    /// The depths (raw words) inside the solid along pixel (x, y)'s ray; None when none are.
    fn interval(&self, fmt: &rtl_model::WordFormat, x: i64, y: i64) -> Option<(i128, i128)> {
        let values = self
            .0
            .iter()
            .map(|(c, py, ph)| (fmt.wrap(c.c0 + x * c.dx + y * c.dy) as i128, *py, *ph));
        ray_interval(values, i128::MIN, i128::MAX)
    }
}

/// [`Route::Intervals`](crate::Route::Intervals): the array's own plane words (DEPGEN's
/// Z0 + x·dZx + y·dZy, wrapped to the word) reduced to the interval of depths inside P:
/// behind every front plane, before every back plane, K ≥ 0 on every perpendicular plane.
pub fn word_ranges(slicer: &Slicer, prim: usize) -> Result<SlabRanges> {
    let planes = WordPlanes::of(slicer, prim)?;
    Ok(by_panel(
        slicer,
        |b| planes.in_panel(slicer, b),
        |p, x, y| p.slabs(slicer, x as i64, y as i64),
    ))
}

/// Side of the panels [`by_panel`] prunes the planes for.
const PANEL: usize = 16;

/// Every pixel's slabs, panel by panel: the planes pruned to those that decide a panel
/// (`prune`, None when the solid is nowhere in it), then each pixel's slabs of those
/// (`slabs`), as the thesis's panels draw only the planes that reach them (§2.5). A sphere's
/// thousands of planes shrink to the few near each panel's patch of its surface; the slabs
/// are those of all the planes ([`WordPlanes::in_panel`], tested).
fn by_panel<P>(
    slicer: &Slicer,
    prune: impl Fn(PixelBox) -> Option<P>,
    slabs: impl Fn(&P, usize, usize) -> (u32, u32),
) -> SlabRanges {
    let (w, h) = (slicer.grid.dims[0], slicer.grid.dims[1]);
    // slabs_of's one empty run.
    let mut out = vec![(1, 0); w * h];
    for y0 in (0..h).step_by(PANEL) {
        for x0 in (0..w).step_by(PANEL) {
            let b = PixelBox::new(x0, y0, (x0 + PANEL).min(w), (y0 + PANEL).min(h));
            let Some(planes) = prune(b) else { continue };
            for y in b.y0..b.y1 {
                for x in b.x0..b.x1 {
                    out[y * w + x] = slabs(&planes, x, y);
                }
            }
        }
    }
    SlabRanges(out)
}

/// A plane's (Y, H) flags and its smallest and largest value over a panel, if known.
type PlaneRange<T> = ((bool, bool), Option<(T, T)>);

/// The planes of `all` that can decide a pixel of a panel, from each plane's (Y, H) flags and
/// its smallest and largest value over the panel (`planes`; None: not known, kept); None when
/// a perpendicular plane is negative all over it, so the solid is nowhere there. See
/// [`WordPlanes::in_panel`] for the argument.
fn decisive<P: Copy, T: PartialOrd + Copy + Default>(
    all: &[P],
    planes: &[PlaneRange<T>],
) -> Option<Decisive<P, T>> {
    // The front plane with the largest minimum, the back plane with the smallest maximum.
    let mut front: Option<(T, usize)> = None;
    let mut back: Option<(T, usize)> = None;
    for (i, &((y, h), e)) in planes.iter().enumerate() {
        match (e, y, h) {
            (Some((lo, _)), false, true) if front.is_none_or(|(m, _)| lo > m) => {
                front = Some((lo, i))
            }
            (Some((_, hi)), false, false) if back.is_none_or(|(m, _)| hi < m) => {
                back = Some((hi, i))
            }
            _ => {}
        }
    }
    let zero = T::default();
    let mut kept = Vec::with_capacity(all.len());
    for (i, (&p, &((y, h), e))) in all.iter().zip(planes).enumerate() {
        let keep = match (e, y, h) {
            (None, _, _) => true,
            (Some((_, hi)), true, _) if hi < zero => return None,
            (Some((lo, _)), true, _) => lo < zero,
            (Some((_, hi)), false, true) => front.is_none_or(|(m, g)| i == g || hi >= m),
            (Some((lo, _)), false, false) => back.is_none_or(|(m, g)| i == g || lo <= m),
        };
        if keep {
            kept.push(p);
        }
    }
    // Sized to what is kept, not to all: a panel's tiles each keep a few of its planes.
    kept.shrink_to_fit();
    Some(Decisive {
        kept,
        lo: front.map(|(m, _)| m),
        hi: back.map(|(m, _)| m),
    })
}

/// The planes that decide a panel, and bounds of the interval inside them at every pixel of
/// it: it starts at `lo` or later and ends at `hi` or sooner (None: no such bound known). A
/// panel whose bounds meet no slab holds nothing of the solid.
struct Decisive<P, T> {
    kept: Vec<P>,
    lo: Option<T>,
    hi: Option<T>,
}

/// A solid's planes as f64 (Z0, dZx, dZy, Y, H), for [`Route::Float`](crate::Route::Float)'s
/// depths: the same values [`float_interval`] computes, in the same order.
pub(crate) struct FloatPlanes(Vec<(f64, f64, f64, bool, bool)>);

impl FloatPlanes {
    /// Planes held.
    pub(crate) fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether every plane held is level (dZx = dZy = 0): Z0 + x·0 + y·0 is Z0 at every
    /// pixel, so the slabs are the same at every pixel.
    pub(crate) fn level(&self) -> bool {
        self.0
            .iter()
            .all(|&(_, dx, dy, _, _)| dx == 0.0 && dy == 0.0)
    }

    /// Solid `prim`'s planes.
    pub(crate) fn of(slicer: &Slicer, prim: usize) -> FloatPlanes {
        let planes = slicer.lists[prim].planes.iter();
        FloatPlanes(planes.map(|p| (p.z0, p.dzx, p.dzy, p.y, p.h)).collect())
    }

    /// [`WordPlanes::in_panel`] in f64: (Z0 + x·dZx) + y·dZy rounded at each step is monotone
    /// in x and in y (rounding is monotone), so over a panel it lies between its corner values
    /// as the exact plane does; planes with a corner value not finite are kept.
    pub(crate) fn in_panel(&self, slicer: &Slicer, b: PixelBox) -> Option<FloatPlanes> {
        let (x0, y0, x1, y1) = (
            b.x0 as f64,
            b.y0 as f64,
            (b.x1 - 1) as f64,
            (b.y1 - 1) as f64,
        );
        let ext: Vec<_> = self
            .0
            .iter()
            .map(|&(z0, dx, dy, y, h)| {
                let v = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].map(|(x, y)| z0 + x * dx + y * dy);
                let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                ((y, h), v.iter().all(|v| v.is_finite()).then_some((lo, hi)))
            })
            .collect();
        let d = decisive(&self.0, &ext)?;
        let lo = d.lo.map_or(i128::MIN, |v| raw_depth(slicer, v, true));
        let hi = d.hi.map_or(i128::MAX, |v| raw_depth(slicer, v, false));
        let (first, last) = slabs_of(slicer, lo, hi);
        (first <= last).then_some(FloatPlanes(d.kept))
    }

    /// The exact depths inside the solid along pixel (x, y)'s ray ([`float_interval`]).
    fn interval(&self, x: usize, y: usize) -> Option<(f64, f64)> {
        let (x, y) = (x as f64, y as f64);
        let values = self
            .0
            .iter()
            .map(|&(z0, dx, dy, py, ph)| (z0 + x * dx + y * dy, py, ph));
        ray_interval(values, f64::NEG_INFINITY, f64::INFINITY)
    }

    /// The slabs the solid fills along pixel (x, y)'s ray, from its exact interval.
    pub(crate) fn slabs(&self, slicer: &Slicer, x: usize, y: usize) -> (u32, u32) {
        match self.interval(x, y) {
            Some((lo, hi)) => slabs_of(
                slicer,
                raw_depth(slicer, lo, true),
                raw_depth(slicer, hi, false),
            ),
            None => (1, 0),
        }
    }
}

/// The exact depth interval [lo, hi] of primitive `prim` along pixel (x, y)'s ray, in depth
/// units (None when the ray misses it; lo or hi infinite when no plane bounds that side).
pub fn float_interval(slicer: &Slicer, prim: usize, x: usize, y: usize) -> Option<(f64, f64)> {
    let values = slicer.lists[prim]
        .planes
        .iter()
        .map(|p| (p.z0 + x as f64 * p.dzx + y as f64 * p.dzy, p.y, p.h));
    ray_interval(values, f64::NEG_INFINITY, f64::INFINITY)
}

/// The depths inside a convex solid along one ray, from its planes' values there as
/// (value, Y, H): behind every front plane (H), before every back plane, and none at all where
/// a perpendicular plane (Y) is negative (K < 0, §2.3.3). Starts from [lo, hi]; None when
/// empty.
pub fn ray_interval<T: PartialOrd + Copy + Default>(
    planes: impl IntoIterator<Item = (T, bool, bool)>,
    mut lo: T,
    mut hi: T,
) -> Option<(T, T)> {
    for (v, y, h) in planes {
        match (y, h) {
            (true, _) if v < T::default() => return None,
            (true, _) => {}
            (false, true) if v > lo => lo = v,
            (false, false) if v < hi => hi = v,
            _ => {}
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// A depth (real units) in raw word units, rounded up or down. Slab planes are whole raw
/// units: z <= hi exactly when z <= floor(hi), z >= lo exactly when z >= ceil(lo).
fn raw_depth(slicer: &Slicer, v: f64, up: bool) -> i128 {
    let one = (1u64 << slicer.fmt.frac) as f64;
    let r = if up {
        (v * one).ceil()
    } else {
        (v * one).floor()
    };
    // A whole number below 2^62 in size converts exactly through i64, in one instruction;
    // the wide case is a call of its own so that the optimiser keeps the two apart (as one
    // `as i128` the whole of it would be a call of `__fixdfti`).
    match r.abs() < (1u64 << 62) as f64 {
        true => i128::from(r as i64),
        false => wide_raw(r),
    }
}

#[cold]
#[inline(never)]
fn wide_raw(r: f64) -> i128 {
    r.clamp(-1e30, 1e30) as i128
}

/// [`Route::Float`](crate::Route::Float): the same slabs from the exact intervals.
pub fn float_ranges(slicer: &Slicer, prim: usize) -> SlabRanges {
    let planes = FloatPlanes::of(slicer, prim);
    by_panel(
        slicer,
        |b| planes.in_panel(slicer, b),
        |p, x, y| p.slabs(slicer, x, y),
    )
}

/// Per pixel, the slabs a closed mesh fills: the crossings of the pixel's ray with its
/// triangles (§5.3.1), paired by parity (§3.4.2), each inside interval reduced to slabs as
/// [`float_ranges`] reduces a convex solid's.
pub fn mesh_runs(slicer: &Slicer, mesh: &TriMesh) -> SlabRuns {
    let [w, h, _] = slicer.grid.dims;
    mesh_runs_in(slicer, mesh, Window { x0: 0, y0: 0, w, h })
}

/// The runs of a sampled primitive that is a surface or a footprint over the pixels of `win`
/// (as [`mesh_runs_in`]): a closed mesh's, an open mesh's or a footprint's; None for a
/// dataset, which is sampled voxel by voxel. An open mesh calls `row` once a row of `win`
/// ([`open_mesh_runs_in`]); the others never.
pub fn sampled_runs_in(
    slicer: &Slicer,
    shape: &Shape,
    win: Window,
    row: &(dyn Fn() + Sync),
) -> Option<SlabRuns> {
    match shape {
        Shape::Mesh(m) => Some(mesh_runs_in(slicer, m, win)),
        Shape::OpenMesh(m, _) => Some(open_mesh_runs_in(slicer, m, win, row)),
        Shape::Footprint(f) => Some(footprint_runs_in(slicer, f, win)),
        Shape::Dataset { .. } => None,
    }
}

/// [`mesh_runs`] on the pixels of `win` only (index `(y − y0)·w + (x − x0)`): the same runs
/// those pixels have over the whole array.
pub fn mesh_runs_in(slicer: &Slicer, mesh: &TriMesh, win: Window) -> SlabRuns {
    let raw = |v, up| raw_depth(slicer, v, up);
    let crossings = mesh.crossings_flat_in(|p| slicer.frame.to_pixel(p), win);
    SlabRuns::merged(crossings.pixels(), |i| {
        crossings
            .pixel(i)
            .chunks_exact(2)
            .map(move |p| slabs_of(slicer, raw(p[0], true), raw(p[1], false)))
    })
}

/// Per pixel of `win` (as [`mesh_runs_in`]), the slabs a mesh that is not closed fills: those
/// whose voxel centre has winding number at least 1/2 and lies in the mesh's box
/// ([`OpenMesh::inside_runs_in`]). The centre of slab k is the depth word Z-plane(k) + half a
/// slab, the point centre sampling classifies; slab sampling takes the same points here (a
/// winding number has no segment to meet), so both routes and both samplings read one set.
/// `row` is called once a row of `win` as it is done.
pub fn open_mesh_runs_in(
    slicer: &Slicer,
    mesh: &OpenMesh,
    win: Window,
    row: &(dyn Fn() + Sync),
) -> SlabRuns {
    let depths: Vec<f64> = (0..slicer.grid.dims[2])
        .map(|k| slicer.fmt.to_real(slicer.z_plane(k) + slicer.slab_raw / 2))
        .collect();
    let to_pixel = |p| slicer.frame.to_pixel(p);
    SlabRuns::of_pixels(mesh.inside_runs_ticking(to_pixel, win, &depths, row))
}

/// Per pixel of `win` (as [`mesh_runs_in`]), the slabs a footprint fills: its depth range,
/// rounded as a mesh's crossings are, where its 2D tree holds the pixel's centre
/// ([`Footprint::mask_in`]). The footprint's placement keeps the Z axis and the slicer looks
/// along it, so a pixel's depth range is the same everywhere.
pub fn footprint_runs_in(slicer: &Slicer, f: &Footprint, win: Window) -> SlabRuns {
    let m = f.to_scene();
    let at = |p: DVec2, z: f64| slicer.frame.to_pixel(m.transform_point3(p.extend(z)));
    debug_assert!(at(DVec2::ZERO, f.z[0])
        .truncate()
        .abs_diff_eq(at(DVec2::ZERO, f.z[1]).truncate(), 1e-6));
    // Plane → pixels is affine: its origin and two axes, for every outline point.
    let o = at(DVec2::ZERO, f.z[0]).truncate();
    let (ex, ey) = (
        at(DVec2::X, f.z[0]).truncate() - o,
        at(DVec2::Y, f.z[0]).truncate() - o,
    );
    let mask = f.mask_in(|p| o + ex * p.x + ey * p.y, win);
    let (a, b) = (at(DVec2::ZERO, f.z[0]).z, at(DVec2::ZERO, f.z[1]).z);
    let run = slabs_of(
        slicer,
        raw_depth(slicer, a.min(b), true),
        raw_depth(slicer, a.max(b), false),
    );
    SlabRuns::merged(mask.len(), |i| mask[i].then_some(run).into_iter())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::slicer::SlicerOptions;
    use csgpix_scene::grid::Grid;
    use proptest::prelude::*;

    /// A sphere or cone of many faces, turned and placed anywhere on the grid.
    pub(crate) fn solid() -> impl Strategy<Value = String> {
        let shape = prop_oneof![
            (6usize..40, 2.0..9.0f64).prop_map(|(n, r)| format!("sphere($fn = {n}, r = {r:.3});")),
            (3usize..40, 2.0..12.0f64, 0.0..6.0f64).prop_map(|(n, h, r)| format!(
                "cylinder($fn = {n}, h = {h:.3}, r1 = {r:.3}, r2 = 1, center = true);"
            )),
        ];
        (shape, -3.0..3.0f64, prop::array::uniform3(-6.0..6.0f64)).prop_map(|(s, a, t)| {
            let (c, si) = (a.cos(), a.sin());
            format!(
                "multmatrix([[{c}, 0, {si}, {}], [0, 1, 0, {}], [{}, 0, {c}, {}], [0, 0, 0, 1]]) {{ {s} }}",
                t[0], t[1], -si, t[2]
            )
        })
    }

    /// A slicer of scene `text` on an n³ grid over [-12, 12]³, and the box of up to `size`
    /// pixels at `at` (wrapped onto the grid), cut by the grid's edge.
    pub(crate) fn slicer_and_box(
        text: &str,
        n: usize,
        at: [usize; 2],
        size: [usize; 2],
    ) -> (Slicer, PixelBox) {
        let scene = csgpix_openscad::parse_csg(text, "s.csg").unwrap();
        let lo = glam::DVec3::splat(-12.0);
        let grid = Grid::new([n, n, n], lo, -lo).unwrap();
        let slicer = Slicer::new(&scene, grid, SlicerOptions::default()).unwrap();
        let (x0, y0) = (at[0] % n, at[1] % n);
        let b = PixelBox::new(x0, y0, (x0 + size[0]).min(n), (y0 + size[1]).min(n));
        (slicer, b)
    }

    /// An empty run of slabs.
    fn empty((first, last): (u32, u32)) -> bool {
        first > last
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// The planes kept for a panel give every pixel of it the slabs all the planes give.
        #[test]
        fn planes_pruned_to_a_panel_decide_as_all_do(
            text in solid(),
            n in 8usize..80,
            at in prop::array::uniform2(0usize..80),
            size in prop::array::uniform2(1usize..24),
        ) {
            let (slicer, b) = slicer_and_box(&text, n, at, size);
            let all = WordPlanes::of(&slicer, 0).unwrap();
            let kept = all.in_panel(&slicer, b);
            for y in b.y0..b.y1 {
                for x in b.x0..b.x1 {
                    let (x, y) = (x as i64, y as i64);
                    let want = all.interval(&slicer.fmt, x, y);
                    match &kept {
                        Some(k) => prop_assert_eq!(k.interval(&slicer.fmt, x, y), want),
                        None => prop_assert!(empty(all.slabs(&slicer, x, y))),
                    }
                }
            }
            if let Some(k) = kept {
                prop_assert!(k.0.len() <= all.0.len());
            }
            // The routes' ranges, panel by panel, are every pixel's slabs of all the planes.
            let ranges = word_ranges(&slicer, 0).unwrap();
            let floats = float_ranges(&slicer, 0);
            let all_f = FloatPlanes::of(&slicer, 0);
            for i in 0..n * n {
                let (x, y) = (i % n, i / n);
                prop_assert_eq!(ranges.0[i], all.slabs(&slicer, x as i64, y as i64));
                prop_assert_eq!(floats.0[i], all_f.slabs(&slicer, x, y));
            }
            let all = FloatPlanes::of(&slicer, 0);
            let kept = all.in_panel(&slicer, b);
            for y in b.y0..b.y1 {
                for x in b.x0..b.x1 {
                    let want = all.interval(x, y);
                    prop_assert_eq!(want, float_interval(&slicer, 0, x, y));
                    match &kept {
                        Some(k) => prop_assert_eq!(k.interval(x, y), want),
                        None => prop_assert!(empty(all.slabs(&slicer, x, y))),
                    }
                }
            }
        }
    }
}

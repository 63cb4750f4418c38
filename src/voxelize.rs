//! Voxelizing slice by slice (§4.4; DESIGN.md, "From images to voxels").
//!
//! The grid's X and Y map to the array's pixels and its Z to depth: slab k lies between
//! Z-plane(k) and Z-plane(k + 1). The slice of primitive P is what the array shows for P·Vz,
//! drawn the thesis way (§5.2.1): @(P)·Vz + @(Vz)·P, P's own surface inside the slab or the
//! slab's front plane inside P, composed by the second stage. A pixel shows something exactly
//! when P meets the slab along the pixel's ray.
//!
//! # Sampling conventions ([`Sampling`])
//!
//! * `centre` (the default): voxel (i, j, k) is inside primitive P when its centre is inside
//!   P. Pixel (i, j) samples the ray at the centre's X and Y; Vz is one least unit of the
//!   depth word thick, at the centre's depth. Point membership commutes with CSG, so the
//!   volume is the point membership of the CSG solid at every centre.
//! * `slab` (the thesis's §4.4 slab): voxel (i, j, k) is inside P when the segment through
//!   the voxel's centre parallel to Z, from its front face up to (not including) its back
//!   face, meets P. The slab's clipping planes are the voxel's front face and a plane one least
//!   unit of the depth word before its back face, so every depth word belongs to exactly one
//!   slab. CSG over such classifications dilates every subtracted solid by up to a voxel.
//!
//! # Routes to the same masks
//!
//! * [`Route::Array`]: the processor itself (`cycle` or `word`), one frame per primitive per
//!   slab; the reference, and the only route that reports clocks.
//! * [`Route::Intervals`]: the same plane words the array computes (Z0 + x·dZx + y·dZy in the
//!   depth word, §2.3.1), reduced once per pixel to the interval of depths where P lies, then
//!   intersected with every slab. Tests prove it gives the processor's masks voxel for voxel.
//! * [`Route::Float`]: the same intervals in exact f64 arithmetic: the reference geometry.

use glam::{DMat3, DVec3};

use rtl_model::array::check_program;
use rtl_model::program::CReg;
use rtl_model::{Array, ArrayConfig, CycleArray, EquationSet, WordArray, WordFormat};

use crate::blend::BlendEval;
use crate::clip_expr::Clip;
use crate::compile::clip_scene_ops;
use crate::display_list::{DisplayList, DlPlane};
use crate::project::{display_lists, max_slope, silhouette_planes, Frame, DEPTH_MARGIN};
use crate::requirements::{Footprint, PixelBox};
use crate::sampled::{Sampled, Shape, SlabRuns};
use crate::slice::{Mask, OpCounts, SliceEval};
use crate::solid::CsgScene;

/// The voxel grid: `dims` voxels spanning the box `min`..`max` in scene units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub dims: [usize; 3],
    pub min: DVec3,
    pub max: DVec3,
}

impl Grid {
    /// A grid over the scene's bounds (every solid's vertices, so subtracted solids count).
    pub fn of_scene(scene: &CsgScene, dims: [usize; 3]) -> Result<Grid, String> {
        let pts = scene.solids.iter().flat_map(|s| s.vertices.iter());
        let (min, max) = pts.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), p| {
            (a.min(DVec3::from(*p)), b.max(DVec3::from(*p)))
        });
        if !min.is_finite() {
            return Err("the scene has no solids: give --bounds".into());
        }
        Grid::new(dims, min, max)
    }

    /// A grid over an explicit box.
    pub fn new(dims: [usize; 3], min: DVec3, max: DVec3) -> Result<Grid, String> {
        if dims.contains(&0) {
            return Err(format!(
                "resolution {dims:?}: every side needs at least one voxel"
            ));
        }
        if !(min.is_finite() && max.is_finite()) || (max - min).min_element() <= 0.0 {
            return Err(format!(
                "bounds {min} .. {max} must be finite with every side positive"
            ));
        }
        Ok(Grid { dims, min, max })
    }

    /// Size of one voxel in scene units.
    pub fn voxel(&self) -> DVec3 {
        (self.max - self.min)
            / DVec3::new(
                self.dims[0] as f64,
                self.dims[1] as f64,
                self.dims[2] as f64,
            )
    }

    /// Centre of voxel (i, j, k) in scene units.
    pub fn centre(&self, i: usize, j: usize, k: usize) -> DVec3 {
        self.min + (DVec3::new(i as f64, j as f64, k as f64) + 0.5) * self.voxel()
    }

    /// Voxels in one slice.
    pub fn slice_len(&self) -> usize {
        self.dims[0] * self.dims[1]
    }
}

/// Most voxels a grid may have along one axis (a `--voxel` size far below the scene's extent
/// is refused here rather than by the memory estimate's arithmetic).
pub const MAX_GRID_SIDE: usize = 1 << 20;

/// How a grid is laid over a region: voxels per axis (`res`) or a cubic voxel size
/// (`voxel`, the grid centred on the region with whole voxels covering it), then `pad`
/// empty voxels added on every side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridSpec {
    pub res: Option<[usize; 3]>,
    pub voxel: Option<f64>,
    pub pad: usize,
}

impl GridSpec {
    /// The grid over the box `lo`..`hi`.
    pub fn grid(&self, lo: DVec3, hi: DVec3) -> Result<Grid, String> {
        let inner = match (self.res, self.voxel) {
            (Some(dims), None) => Grid::new(dims, lo, hi)?,
            (None, Some(size)) => Self::cubic(size, lo, hi)?,
            _ => return Err("give the grid as a resolution or a voxel size, not both".into()),
        };
        let v = inner.voxel();
        let pad = self.pad.min(MAX_GRID_SIDE);
        let dims = inner.dims.map(|d| d.saturating_add(2 * pad));
        if dims.iter().any(|&d| d > MAX_GRID_SIDE) {
            return Err(format!(
                "a grid of {dims:?} voxels: at most {MAX_GRID_SIDE} per axis"
            ));
        }
        let margin = v * pad as f64;
        Grid::new(dims, inner.min - margin, inner.max + margin)
    }

    /// Cubic voxels of side `size`: as many as cover each side of the box, centred on it.
    fn cubic(size: f64, lo: DVec3, hi: DVec3) -> Result<Grid, String> {
        if !(size.is_finite() && size > 0.0) {
            return Err(format!("voxel size {size}: must be a positive number"));
        }
        let extent = hi - lo;
        let mut dims = [0usize; 3];
        for (d, e) in dims.iter_mut().zip(extent.to_array()) {
            // A side that is a whole number of voxels (to rounding) gets exactly that many.
            let n = (e / size * (1.0 - 1e-12)).ceil().max(1.0);
            if n.is_nan() || n > MAX_GRID_SIDE as f64 {
                return Err(format!(
                    "voxel size {size} over an extent of {e}: more than {MAX_GRID_SIDE} voxels per axis"
                ));
            }
            *d = n as usize;
        }
        let side = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64) * size;
        let centre = (lo + hi) / 2.0;
        Grid::new(dims, centre - side / 2.0, centre + side / 2.0)
    }
}

/// How slab masks are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// The processor, clock by clock (`cycle`) or word by word (`word`).
    Array { cycle: bool },
    /// The array's plane words reduced to per-pixel depth intervals.
    Intervals,
    /// Exact f64 intervals.
    Float,
}

/// Which depths of a voxel's ray classify it against a primitive (docs/voxelization.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Sampling {
    /// The voxel's centre: Vz one least unit of the depth word thick, at the centre's depth.
    #[default]
    Centre,
    /// The thesis's slab (§4.4): the segment through the centre from the voxel's front face
    /// up to one least unit before its back face.
    Slab,
}

/// The slope limit of centre sampling: every face whose slope the word can carry across the
/// array stays a sloped plane. Rendering caps slopes at maxdepth per pixel ([`max_slope`]),
/// which moves a steep face by up to a pixel; here a face in the depth range at some pixel of
/// the array stays within the word at every pixel (|Z| ≤ maxdepth + slope·(W + H + 2) ≤ the
/// largest word, the 2 for the half pixel the grid's corners lie beyond the outer pixel
/// centres), so the perpendicular approximation moves a face by at most
/// maxdepth / slope pixels: with the thesis's word 1/16 of a pixel at 64×64, 1/4 at 256×256.
pub fn voxel_slope(fmt: &WordFormat, width: usize, height: usize) -> f64 {
    let maxdepth = fmt.to_real(fmt.maxdepth());
    let headroom = fmt.to_real(fmt.max_word()) - maxdepth;
    (headroom / (width + height + 2) as f64).max(max_slope(fmt, width, height))
}

/// Panel size the array route prunes to by default. Any size gives the same voxels; smaller
/// panels simulate fewer pixels around small primitives (docs/requirements.md).
pub const DEFAULT_PANEL: [usize; 2] = [32, 32];

/// A scene set up for slicing: its display lists in the grid's frame and the slabs.
pub struct Slicer {
    pub grid: Grid,
    pub fmt: WordFormat,
    /// One display list per solid (§5.2), in the frame of [`Slicer::frame`].
    pub lists: Vec<DisplayList>,
    /// Raw depth-word units per slab (a whole number, so slab planes are exact words; even
    /// under centre sampling, so the voxel centres are exact words too).
    pub slab_raw: i64,
    /// Which depths of each slab classify its voxels ([`Slicer::window`]).
    pub sampling: Sampling,
    /// Faces steeper than this (depth units per pixel) are drawn as perpendicular planes
    /// through their trace at depth 0 ([`crate::project`]), moving them by at most
    /// maxdepth / slope_limit pixels inside the depth range.
    pub slope_limit: f64,
    /// Colour code of each solid (its display list's colour).
    pub colours: Vec<u8>,
    /// Panels of this many pixels: the array route simulates, for each primitive, only the
    /// panels and slabs its footprint touches ([`crate::requirements`]). None simulates the
    /// whole array for every frame. Either way the voxels are the same (tested).
    pub panel: Option<[usize; 2]>,
    /// Where the grid lies on the array: scene point → (pixel x, pixel y, depth).
    pub frame: Frame,
    /// Imported primitives (datasets, meshes), after the solids: primitive
    /// `lists.len() + j` ([`crate::sampled`]). Must match the scene's imports.
    pub sampled: Vec<Sampled>,
    /// Imports the scene names (checked against `sampled` before a run).
    pub imports: usize,
    /// Voxels won by a dataset take its grey value (§4.5), not its colour code.
    pub grey: bool,
    /// Grey-valued output by the blending operators of §3.3 instead of labels.
    pub blend: Option<BlendEval>,
}

impl Slicer {
    /// Lay the grid on the array under centre sampling ([`Slicer::with_sampling`] for the
    /// other): X, Y to pixels (voxel centres at integer pixel coordinates), Z to depth, slab k
    /// at DEPTH_MARGIN + k·q depth units, q as large as the word's depth range allows.
    pub fn new(scene: &CsgScene, grid: Grid, fmt: WordFormat) -> Result<Slicer, String> {
        Slicer::with_sampling(scene, grid, fmt, Sampling::Centre)
    }

    /// [`Slicer::new`] under the given sampling convention. Centre sampling needs an even
    /// number of raw units per slab (so the voxel centre is a word), at least 2.
    pub fn with_sampling(
        scene: &CsgScene,
        grid: Grid,
        fmt: WordFormat,
        sampling: Sampling,
    ) -> Result<Slicer, String> {
        let one = 1i64 << fmt.frac;
        let margin_raw = DEPTH_MARGIN as i64 * one;
        let room = fmt.maxdepth() - 2 * margin_raw;
        let mut slab_raw = room / grid.dims[2] as i64;
        if sampling == Sampling::Centre {
            slab_raw &= !1;
        }
        if slab_raw < 1 {
            return Err(format!(
                "{} slices do not fit the depth word ({} fraction and {} integer bits): \
                 use fewer slices or a wider word (e.g. 10/11/12)",
                grid.dims[2], fmt.frac, fmt.int
            ));
        }
        let frame = Self::frame_of(&grid, fmt.to_real(slab_raw));
        let (w, h) = (grid.dims[0], grid.dims[1]);
        let slope_limit = match sampling {
            Sampling::Slab => max_slope(&fmt, w, h),
            Sampling::Centre => voxel_slope(&fmt, w, h),
        };
        let mut lists = display_lists(scene, &frame, slope_limit);
        for (dl, solid) in lists.iter_mut().zip(&scene.solids) {
            let colour = dl.planes.first().map_or(1, |p| p.colour);
            dl.planes.extend(silhouette_planes(&frame, solid, colour));
        }
        let colours = lists
            .iter()
            .map(|dl| dl.planes.first().map_or(1, |p| p.colour.min(255) as u8))
            .collect();
        Ok(Slicer {
            grid,
            fmt,
            lists,
            slab_raw,
            sampling,
            slope_limit,
            colours,
            panel: Some(DEFAULT_PANEL),
            frame,
            sampled: vec![],
            imports: scene.imports.len(),
            grey: false,
            blend: None,
        })
    }

    /// Add the scene's loaded imports (in the scene's order), with their colours.
    pub fn with_sampled(mut self, sampled: Vec<Sampled>) -> Slicer {
        self.colours.extend(sampled.iter().map(|s| s.colour));
        self.sampled = sampled;
        self
    }

    /// Primitives of every kind.
    pub fn primitive_count(&self) -> usize {
        self.lists.len() + self.sampled.len()
    }

    /// Primitive p when it is an imported dataset.
    pub fn dataset(&self, p: usize) -> Option<&Sampled> {
        let j = p.checked_sub(self.lists.len())?;
        self.sampled.get(j).filter(|s| s.is_dataset())
    }

    /// Every import the scene names is loaded ([`Slicer::with_sampled`]).
    fn check_imports(&self) -> Result<(), String> {
        if self.sampled.len() != self.imports {
            return Err(format!(
                "the scene imports {} files but {} are loaded",
                self.imports,
                self.sampled.len()
            ));
        }
        Ok(())
    }

    fn frame_of(grid: &Grid, q: f64) -> Frame {
        let v = grid.voxel();
        Frame {
            basis: DMat3::IDENTITY,
            min: grid.min,
            scale: DVec3::new(1.0 / v.x, 1.0 / v.y, q / v.z),
            offset: DVec3::new(-0.5, -0.5, DEPTH_MARGIN),
        }
    }

    /// Depth (raw word) of Z-plane(k), the front of slab k.
    pub fn z_plane(&self, k: usize) -> i64 {
        ((DEPTH_MARGIN as i64) << self.fmt.frac) + k as i64 * self.slab_raw
    }

    /// The depths (raw words, both ends included) that classify slab k's voxels, as offsets
    /// from Z-plane(k): the whole slab up to one raw unit before Z-plane(k + 1) (`slab`), or
    /// the voxel centre's word and the next (`centre`: Vz one least unit thick; the array
    /// shows nothing between a front and a back clipping plane at the same word).
    pub fn window(&self) -> (i64, i64) {
        match self.sampling {
            Sampling::Slab => (0, self.slab_raw - 1),
            Sampling::Centre => (self.slab_raw / 2, self.slab_raw / 2 + 1),
        }
    }

    /// Vz of slab k as a display list: its front and back clipping planes at the two ends
    /// of [`Slicer::window`] (one least unit apart under centre sampling).
    pub fn slab_list(&self, k: usize, colour: u32) -> DisplayList {
        let z = |raw: i64| self.fmt.to_real(raw);
        let (a, b) = self.window();
        let z0 = self.z_plane(k);
        DisplayList::slab(z(z0 + a), z(z0 + b), colour)
    }

    /// The array configuration slices run on.
    pub fn config(&self) -> ArrayConfig {
        ArrayConfig {
            fmt: self.fmt,
            ..ArrayConfig::new(self.grid.dims[0], self.grid.dims[1])
        }
    }
}

/// What the processor shows for P·Vz, as a mask (pixels with a colour), and the clocks taken,
/// simulating the whole array.
pub fn array_mask(
    slicer: &Slicer,
    prim: usize,
    k: usize,
    cycle: bool,
    set: EquationSet,
) -> Result<(Mask, u64), String> {
    let [w, h] = [slicer.grid.dims[0], slicer.grid.dims[1]];
    let all = PixelBox {
        x0: 0,
        y0: 0,
        x1: w,
        y1: h,
    };
    array_mask_in(slicer, prim, k, cycle, set, all)
}

/// [`array_mask`] simulating only the pixels of `bx`, as an array of that size whose DEPGEN
/// starts at the box's corner: every plane's Z0 becomes Z0 + x0·dZx + y0·dZy, modulo 2^N_D as
/// DEPGEN's sums are, so every simulated pixel receives the very word the whole array would
/// give it (pixels share nothing else). Pixels outside the box are left empty: the caller
/// knows from the footprint that P·Vz shows nothing there. The clocks are those of the
/// smaller array (its DEPGEN tree is shorter).
pub fn array_mask_in(
    slicer: &Slicer,
    prim: usize,
    k: usize,
    cycle: bool,
    set: EquationSet,
    bx: PixelBox,
) -> Result<(Mask, u64), String> {
    let mut ops = slice_ops(slicer, prim, k)?;
    rtl_model::program::translate(&mut ops, bx.x0, bx.y0);
    let full = slicer.config();
    let cfg = ArrayConfig {
        width: bx.width(),
        height: bx.height(),
        // Only the clipping-stack levels the frame uses (its unused levels would hold 0).
        stack_depth: check_program(&ops, full.stack_depth).map_err(|e| e.to_string())?,
        ..full
    };
    let mut arr: Box<dyn Array> = if cycle {
        Box::new(CycleArray::new(cfg, set))
    } else {
        Box::new(WordArray::new(cfg, set))
    };
    arr.run(&ops).map_err(|e| e.to_string())?;
    let w = slicer.grid.dims[0];
    let mut mask = Mask::new(slicer.grid.slice_len());
    for y in 0..bx.height() {
        for x in 0..bx.width() {
            if arr.pixel(x, y).creg(CReg::G) != 0 {
                mask.set((bx.y0 + y) * w + bx.x0 + x, true);
            }
        }
    }
    Ok((mask, arr.cycles()))
}

/// Per pixel, the slabs primitive P meets: `first..=last` (empty when first > last).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SlabRanges(pub Vec<(u32, u32)>);

impl SlabRanges {
    /// Per slab k, the pixels whose membership differs between slab k − 1 and slab k: those
    /// whose range starts at k or ended at k − 1 (slab 0: none).
    pub fn toggles(&self, slabs: usize) -> Vec<Vec<u32>> {
        let mut t = vec![vec![]; slabs];
        for (i, &run) in self.0.iter().enumerate() {
            toggle_run(&mut t, i, run);
        }
        t
    }

    /// The mask of slab k.
    pub fn mask(&self, k: usize) -> Mask {
        let k = k as u32;
        Mask::from_fn(self.0.len(), |i| {
            let (a, b) = self.0[i];
            a <= k && k <= b
        })
    }
}

/// The slabs whose window ([`Slicer::window`]) a depth interval [lo, hi] (in raw word units)
/// meets, both ends closed.
fn slabs_of(slicer: &Slicer, lo: i128, hi: i128) -> (u32, u32) {
    const EMPTY: (u32, u32) = (1, 0);
    let (z0, s) = (slicer.z_plane(0) as i128, slicer.slab_raw as i128);
    let (a, b) = slicer.window();
    let (a, b) = (a as i128, b as i128);
    let last_slab = slicer.grid.dims[2] as i128 - 1;
    if lo > hi {
        return EMPTY;
    }
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

/// [`Route::Intervals`]: the array's own plane words (DEPGEN's Z0 + x·dZx + y·dZy, wrapped to
/// the word) reduced to the interval of depths inside P: behind every front plane, before
/// every back plane, K ≥ 0 on every perpendicular plane.
pub fn word_ranges(slicer: &Slicer, prim: usize) -> Result<SlabRanges, String> {
    let fmt = &slicer.fmt;
    let coeffs: Vec<(rtl_model::Coeffs, &DlPlane)> = slicer.lists[prim]
        .planes
        .iter()
        .map(|p| {
            crate::compile::coeffs(fmt, p.z0, p.dzx, p.dzy)
                .map(|c| (c, p))
                .map_err(|(_, msg)| format!("solid {}: {msg}", prim + 1))
        })
        .collect::<Result<_, _>>()?;
    let (w, h) = (slicer.grid.dims[0], slicer.grid.dims[1]);
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h as i64 {
        for x in 0..w as i64 {
            let values = coeffs
                .iter()
                .map(|(c, p)| (fmt.wrap(c.c0 + x * c.dx + y * c.dy) as i128, p.y, p.h));
            let (lo, hi) = ray_interval(values, i128::MIN, i128::MAX).unwrap_or((1, 0));
            out.push(slabs_of(slicer, lo, hi));
        }
    }
    Ok(SlabRanges(out))
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
    r.clamp(-1e30, 1e30) as i128
}

/// Record that pixel i enters slab `first` and leaves after slab `last` (an empty run,
/// first > last, records nothing): the flips [`SlabRanges::toggles`] and
/// [`SlabRuns::toggles`] list per slab.
pub fn toggle_run(t: &mut [Vec<u32>], i: usize, (first, last): (u32, u32)) {
    if first > last {
        return;
    }
    if first > 0 && (first as usize) < t.len() {
        t[first as usize].push(i as u32);
    }
    if (last as usize) + 1 < t.len() {
        t[last as usize + 1].push(i as u32);
    }
}

/// [`Route::Float`]: the same slabs from the exact intervals.
pub fn float_ranges(slicer: &Slicer, prim: usize) -> SlabRanges {
    let raw = |v, up| raw_depth(slicer, v, up);
    let (w, h) = (slicer.grid.dims[0], slicer.grid.dims[1]);
    let out = (0..w * h)
        .map(|i| match float_interval(slicer, prim, i % w, i / w) {
            Some((lo, hi)) => slabs_of(slicer, raw(lo, true), raw(hi, false)),
            None => (1, 0),
        })
        .collect();
    SlabRanges(out)
}

/// The P·Vz program of primitive `prim` and slab `k` (§5.2.1: @(P)·Vz + @(Vz)·P).
pub fn slice_ops(slicer: &Slicer, prim: usize, k: usize) -> Result<Vec<rtl_model::Op>, String> {
    let p = &slicer.lists[prim];
    let lists = [p.clone(), slicer.slab_list(k, slicer.colours[prim] as u32)];
    let expr = Clip::And(Box::new(Clip::Obj(0)), Box::new(Clip::Obj(1)));
    let cfg = slicer.config();
    clip_scene_ops(&lists, &expr, &cfg.fmt, cfg.colour_bits)
        .map_err(|(_, e)| format!("solid {}: {e}", prim + 1))
}

/// A voxelized scene: colour codes, X fastest, then Y, then Z; 0 is empty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Volume {
    pub dims: [usize; 3],
    pub voxels: Vec<u8>,
}

/// What a run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Work {
    /// Voxels inside the scene.
    pub filled: usize,
    /// Array clocks for every P·Vz frame (simulated on the array route, counted from the
    /// programs on the others: the same number either way).
    pub cycles: u64,
    /// P·Vz frames drawn (primitives × slabs).
    pub frames: u64,
    /// The evaluator's operations (§5.5).
    pub ops: OpCounts,
    /// Pixel-clocks the simulator ran (array route: Σ over simulated frames of pixels ×
    /// clocks; 0 on the other routes, which simulate no pixel).
    pub simulated_pixel_clocks: u64,
    /// Pixel-clocks of every frame on the whole array: what simulating everything costs.
    pub full_pixel_clocks: u64,
}

/// Per-slice masks of every primitive: the solids' by route, then the imports'.
struct Source {
    convex: ConvexSource,
    sampled: Vec<SampledSource>,
}

/// Where an import's slab masks come from.
enum SampledSource {
    /// A mesh: its slab runs per pixel and, per slab, the pixels that flip there.
    Runs(SlabRuns, Vec<Vec<u32>>),
    /// A dataset (import j): sampled slab by slab.
    Dataset(usize),
}

impl SampledSource {
    fn mask(&self, slicer: &Slicer, k: usize) -> Mask {
        match self {
            SampledSource::Runs(r, _) => r.mask(k),
            SampledSource::Dataset(j) => slicer.sampled[*j].dataset_mask(&slicer.grid, k),
        }
    }

    /// The mask of slab k from that of slab k − 1.
    fn advance(&self, slicer: &Slicer, k: usize, m: &mut Mask) {
        match self {
            SampledSource::Runs(_, toggles) => {
                toggles[k].iter().for_each(|&i| m.toggle(i as usize))
            }
            SampledSource::Dataset(_) => *m = self.mask(slicer, k),
        }
    }
}

/// Per-slice masks of the convex solids, by route.
enum ConvexSource {
    /// Slab ranges of every primitive and, per slab, the pixels whose membership flips there.
    Ranges(Vec<(SlabRanges, Vec<Vec<u32>>)>),
    Array {
        cycle: bool,
        set: EquationSet,
        /// Per primitive, where it is (when the slicer prunes to panels).
        footprints: Option<Vec<Footprint>>,
    },
}

impl ConvexSource {
    fn ranges(r: Vec<SlabRanges>, slabs: usize) -> ConvexSource {
        ConvexSource::Ranges(
            r.into_iter()
                .map(|r| {
                    let t = r.toggles(slabs);
                    (r, t)
                })
                .collect(),
        )
    }

    /// The masks of slabs `a..b`, each handed to `f` in order. From ranges, slab a is built
    /// pixel by pixel and every later one by flipping the pixels whose membership changes.
    fn sweep_convex(
        &self,
        slicer: &Slicer,
        a: usize,
        b: usize,
        simulated: &mut u64,
        f: &mut dyn FnMut(usize, &[Mask]),
    ) -> Result<(), String> {
        match self {
            ConvexSource::Ranges(r) => {
                let mut masks: Vec<Mask> = r.iter().map(|(r, _)| r.mask(a)).collect();
                for k in a..b {
                    if k > a {
                        for ((_, toggles), m) in r.iter().zip(&mut masks) {
                            toggles[k].iter().for_each(|&i| m.toggle(i as usize));
                        }
                    }
                    f(k, &masks);
                }
            }
            ConvexSource::Array {
                cycle,
                set,
                footprints,
            } => {
                for k in a..b {
                    let masks = (0..slicer.lists.len())
                        .map(|p| {
                            let fp = footprints.as_ref().map(|f| &f[p]);
                            let (m, px_clocks) = frame_mask(slicer, p, k, *cycle, set, fp)?;
                            *simulated += px_clocks;
                            Ok(m)
                        })
                        .collect::<Result<Vec<_>, String>>()?;
                    f(k, &masks);
                }
            }
        }
        Ok(())
    }
}

impl Source {
    /// Every primitive's masks of slabs `a..b` (solids, then imports), handed to `f` in order.
    fn sweep(
        &self,
        slicer: &Slicer,
        a: usize,
        b: usize,
        simulated: &mut u64,
        f: &mut dyn FnMut(usize, &[Mask]),
    ) -> Result<(), String> {
        if self.sampled.is_empty() {
            return self.convex.sweep_convex(slicer, a, b, simulated, f);
        }
        let mut imported: Vec<Mask> = vec![];
        let mut all: Vec<Mask> = vec![];
        self.convex
            .sweep_convex(slicer, a, b, simulated, &mut |k, convex| {
                if k == a {
                    imported = self.sampled.iter().map(|s| s.mask(slicer, k)).collect();
                } else {
                    for (s, m) in self.sampled.iter().zip(&mut imported) {
                        s.advance(slicer, k, m);
                    }
                }
                all.clear();
                all.extend_from_slice(convex);
                all.extend_from_slice(&imported);
                f(k, &all);
            })
    }
}

/// A run of consecutive slabs: each slab's colour codes and evaluator counts, and the
/// pixel-clocks simulated for them.
type Chunk = (Vec<(Vec<u8>, OpCounts)>, u64);

/// The mask of P·Vz on the array route and the pixel-clocks simulated for it: the whole array,
/// or with a footprint only the panels it touches, and nothing in a slab it misses.
fn frame_mask(
    slicer: &Slicer,
    p: usize,
    k: usize,
    cycle: bool,
    set: &EquationSet,
    fp: Option<&Footprint>,
) -> Result<(Mask, u64), String> {
    let [w, h] = [slicer.grid.dims[0], slicer.grid.dims[1]];
    let bx = match (fp, slicer.panel) {
        (None, _) | (_, None) => PixelBox {
            x0: 0,
            y0: 0,
            x1: w,
            y1: h,
        },
        (Some(fp), Some(panel)) => match fp.pixels {
            Some(b) if fp.holds(k) => b.to_panels(panel, w, h),
            _ => return Ok((Mask::new(w * h), 0)),
        },
    };
    let (m, clocks) = array_mask_in(slicer, p, k, cycle, set.clone(), bx)?;
    Ok((m, clocks * bx.pixels() as u64))
}

/// Voxelize: every slab's primitive masks by `route`, evaluated by `eval`, slabs in
/// parallel; the result does not depend on the number of threads. `tick` is called once per
/// finished slab (for a progress bar).
pub fn voxelize(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
) -> Result<(Volume, Work), String> {
    use rayon::prelude::*;
    let source = source_for(slicer, route, &set)?;
    let mut work = counted_work(slicer, &set)?;
    let [nx, ny, nz] = slicer.grid.dims;
    // Chunks of consecutive slabs, a few per thread, so masks can be swept forward; each
    // chunk's slices go straight into their place in the volume (one volume held, not two).
    let chunk = (nz / (4 * rayon::current_num_threads())).max(1);
    let mut voxels = vec![0u8; nx * ny * nz];
    let counted: Vec<(u64, OpCounts)> = voxels
        .par_chunks_mut(chunk * nx * ny)
        .enumerate()
        .map(|(c, place)| {
            let a = c * chunk;
            let (slices, simulated) =
                slab_chunk(slicer, &source, eval, tick, a, (a + chunk).min(nz))?;
            let mut ops = OpCounts::default();
            for ((colours, counts), into) in slices.into_iter().zip(place.chunks_mut(nx * ny)) {
                into.copy_from_slice(&colours);
                ops += counts;
            }
            Ok((simulated, ops))
        })
        .collect::<Result<_, String>>()?;
    for (simulated, ops) in counted {
        work.simulated_pixel_clocks += simulated;
        work.ops += ops;
    }
    work.filled = voxels.iter().filter(|&&v| v != 0).count();
    Ok((
        Volume {
            dims: slicer.grid.dims,
            voxels,
        },
        work,
    ))
}

/// An upper bound of a run's memory (docs/memory.md): the volume, the per-pixel slab ranges
/// of every primitive, per thread a slab's masks and labels and the slices of the chunk in
/// hand (an eighth of the volume at most, [`voxelize`]), and the process itself.
pub fn memory_estimate(grid: &Grid, prims: usize, threads: usize) -> u64 {
    let [nx, ny, nz] = grid.dims.map(|d| d as u64);
    let pixels = nx.saturating_mul(ny);
    let (prims, threads) = (prims as u64, threads as u64);
    let volume = pixels.saturating_mul(nz);
    let chunk = (nz / (4 * threads.max(1))).max(1);
    let per_thread = pixels.saturating_mul((prims / 8 + 1 + 8).saturating_add(chunk));
    volume
        .saturating_add(prims.saturating_mul(pixels).saturating_mul(8))
        .saturating_add(threads.saturating_mul(per_thread))
        .saturating_add(PROCESS_BYTES)
}

/// Filled voxels with an empty face neighbour (or on the grid's faces): where Marching Cubes
/// puts triangles, so what a mesh's size follows.
pub fn surface_voxels(v: &Volume) -> u64 {
    let [nx, ny, nz] = v.dims;
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * ny + j) * nx + i] != 0;
    let open = |i: usize, j: usize, k: usize| {
        i == 0 || j == 0 || k == 0 || i + 1 == nx || j + 1 == ny || k + 1 == nz || {
            !(at(i - 1, j, k)
                && at(i + 1, j, k)
                && at(i, j - 1, k)
                && at(i, j + 1, k)
                && at(i, j, k - 1)
                && at(i, j, k + 1))
        }
    };
    let mut n = 0;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                n += u64::from(at(i, j, k) && open(i, j, k));
            }
        }
    }
    n
}

/// The process before any voxel: code, libraries, the scene.
pub const PROCESS_BYTES: u64 = 16 << 20;

/// Receives slice k's colour codes ([`voxelize_streaming`]); an error stops the run.
pub type SliceSink<'a> = dyn FnMut(usize, &[u8]) -> Result<(), String> + 'a;

/// [`voxelize`] handing each slice's colour codes to `sink` in order of k (0, 1, …) instead of
/// assembling a volume, for stores built slice by slice (seed 000 §4.3.4; `src/octree`).
/// Slabs are voxelized in parallel a batch at a time (a few slabs per thread), so at most a
/// batch of slices is held; the slices, and the returned [`Work`], are those of [`voxelize`]
/// (tested). `sink` may stop the run with an error.
pub fn voxelize_streaming(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    sink: &mut SliceSink,
) -> Result<Work, String> {
    use rayon::prelude::*;
    let source = source_for(slicer, route, &set)?;
    let mut work = counted_work(slicer, &set)?;
    let nz = slicer.grid.dims[2];
    let threads = rayon::current_num_threads();
    let chunk = (nz / (4 * threads)).clamp(1, 8);
    let batch = chunk * threads;
    for start in (0..nz).step_by(batch) {
        let end = (start + batch).min(nz);
        let chunks: Vec<Chunk> = (start..end)
            .step_by(chunk)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|a| slab_chunk(slicer, &source, eval, tick, a, (a + chunk).min(end)))
            .collect::<Result<_, String>>()?;
        let slices = chunks.into_iter().flat_map(|(s, sim)| {
            work.simulated_pixel_clocks += sim;
            s
        });
        for (k, (colours, counts)) in (start..).zip(slices) {
            work.ops += counts;
            work.filled += colours.iter().filter(|&&v| v != 0).count();
            sink(k, &colours)?;
        }
    }
    Ok(work)
}

/// Where a run's per-slab masks come from, by route.
fn source_for(slicer: &Slicer, route: Route, set: &EquationSet) -> Result<Source, String> {
    slicer.check_imports()?;
    let nz = slicer.grid.dims[2];
    let sampled = slicer
        .sampled
        .iter()
        .enumerate()
        .map(|(j, s)| match &s.shape {
            Shape::Mesh(m) => {
                let runs = mesh_runs(slicer, m);
                let toggles = runs.toggles(nz);
                SampledSource::Runs(runs, toggles)
            }
            Shape::Dataset { .. } => SampledSource::Dataset(j),
        })
        .collect();
    Ok(Source {
        convex: convex_source(slicer, route, set)?,
        sampled,
    })
}

/// Per pixel, the slabs a closed mesh fills: the crossings of the pixel's ray with its
/// triangles (§5.3.1), paired by parity (§3.4.2), each inside interval reduced to slabs as
/// [`float_ranges`] reduces a convex solid's.
pub fn mesh_runs(slicer: &Slicer, mesh: &crate::trimesh::TriMesh) -> SlabRuns {
    let [w, h, _] = slicer.grid.dims;
    let raw = |v, up| raw_depth(slicer, v, up);
    let crossings = mesh.crossings(|p| slicer.frame.to_pixel(p), w, h);
    SlabRuns::merged(
        crossings
            .iter()
            .map(|c| {
                c.chunks_exact(2)
                    .map(|p| slabs_of(slicer, raw(p[0], true), raw(p[1], false)))
                    .collect()
            })
            .collect(),
    )
}

fn convex_source(slicer: &Slicer, route: Route, set: &EquationSet) -> Result<ConvexSource, String> {
    use rayon::prelude::*;
    let (prims, nz) = (slicer.lists.len(), slicer.grid.dims[2]);
    Ok(match route {
        Route::Array { cycle } => ConvexSource::Array {
            cycle,
            set: set.clone(),
            footprints: match slicer.panel {
                Some(_) => Some(crate::requirements::footprints(slicer)?),
                None => None,
            },
        },
        Route::Intervals => ConvexSource::ranges(
            (0..prims)
                .into_par_iter()
                .map(|p| word_ranges(slicer, p))
                .collect::<Result<_, _>>()?,
            nz,
        ),
        Route::Float => ConvexSource::ranges(
            (0..prims)
                .into_par_iter()
                .map(|p| float_ranges(slicer, p))
                .collect(),
            nz,
        ),
    })
}

/// The clocks and frames of a run, counted from the programs: the same on every route.
fn counted_work(slicer: &Slicer, set: &EquationSet) -> Result<Work, String> {
    let cfg = slicer.config();
    let [nx, ny, nz] = slicer.grid.dims;
    let prims = slicer.lists.len();
    let mut cycles = 0;
    for p in 0..prims {
        cycles +=
            rtl_model::array::program_cycles(&cfg, set, &slice_ops(slicer, p, 0)?) * nz as u64;
    }
    Ok(Work {
        cycles,
        frames: (prims * nz) as u64,
        full_pixel_clocks: cycles * (nx * ny) as u64,
        ..Work::default()
    })
}

/// A slice's colour codes from its labels: the winner's colour code, or with
/// [`Slicer::grey`] a winning dataset's grey value at the voxel (§4.5), as [`grey_code`].
fn label_colours(slicer: &Slicer, k: usize, labels: &[u32]) -> Vec<u8> {
    let nx = slicer.grid.dims[0];
    labels
        .iter()
        .enumerate()
        .map(|(i, &l)| match l {
            0 => 0,
            l => {
                let p = l as usize - 1;
                let grey = match slicer.dataset(p) {
                    Some(s) if slicer.grey => {
                        s.grey(slicer.grid.centre(i % nx, i / nx, k)).map(grey_code)
                    }
                    _ => None,
                };
                grey.unwrap_or(slicer.colours[p])
            }
        })
        .collect()
}

/// First value `--grey` gives a dataset's grey levels: 1..=15 stay the palette's codes.
pub const GREY_BASE: u8 = 16;

/// A grey level 1..=255 as a voxel value GREY_BASE..=255 beside the colour codes.
pub fn grey_code(g: u8) -> u8 {
    let span = (255 - GREY_BASE) as u32;
    GREY_BASE + ((g.max(1) - 1) as u32 * span / 254) as u8
}

/// Every primitive's grey slice for the blending operators ([`crate::blend`]): 0 outside;
/// inside, a dataset's grey value, a solid's or mesh's [`crate::blend::SOLID`].
fn grey_slices(slicer: &Slicer, k: usize, masks: &[Mask]) -> Vec<Vec<u8>> {
    let nx = slicer.grid.dims[0];
    masks
        .iter()
        .enumerate()
        .map(|(p, m)| {
            let level = crate::blend::SOLID;
            let dataset = slicer.dataset(p);
            (0..m.len())
                .map(|i| match (m.get(i), dataset) {
                    (false, _) => 0,
                    (true, Some(s)) => s
                        .grey(slicer.grid.centre(i % nx, i / nx, k))
                        .unwrap_or(level),
                    (true, None) => level,
                })
                .collect()
        })
        .collect()
}

/// Slabs a..b: colour codes and counts of each, and the pixel-clocks simulated.
fn slab_chunk(
    slicer: &Slicer,
    source: &Source,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    a: usize,
    b: usize,
) -> Result<Chunk, String> {
    let (mut out, mut simulated) = (vec![], 0);
    source.sweep(slicer, a, b, &mut simulated, &mut |k, masks| {
        let mut counts = OpCounts::default();
        let colours = match &slicer.blend {
            Some(b) => b.blend(&grey_slices(slicer, k, masks), slicer.grid.slice_len()),
            None => label_colours(slicer, k, &eval.eval(masks, &mut counts)),
        };
        tick();
        out.push((colours, counts));
    })?;
    Ok((out, simulated))
}

#[cfg(test)]
mod grid_tests {
    use super::*;

    fn spec(res: Option<[usize; 3]>, voxel: Option<f64>, pad: usize) -> GridSpec {
        GridSpec { res, voxel, pad }
    }

    #[test]
    fn cubic_voxels_cover_the_bounds_centred() {
        let g = spec(None, Some(0.5), 0)
            .grid(DVec3::new(1.0, 2.0, 3.0), DVec3::new(63.0, 3.2, 4.0))
            .unwrap();
        // 62 / 0.5 = 124 exactly; 1.2 / 0.5 = 2.4 → 3 voxels, centred; 1 / 0.5 = 2.
        assert_eq!(g.dims, [124, 3, 2]);
        assert_eq!(g.voxel(), DVec3::splat(0.5));
        assert_eq!(g.min.x, 1.0);
        assert!((g.min.y - (2.6 - 0.75)).abs() < 1e-12);
        assert_eq!(g.max.z, 4.0);
    }

    #[test]
    fn padding_adds_empty_voxels_of_the_same_size() {
        let g = spec(Some([10, 20, 5]), None, 2)
            .grid(DVec3::ZERO, DVec3::new(10.0, 10.0, 10.0))
            .unwrap();
        assert_eq!(g.dims, [14, 24, 9]);
        assert_eq!(g.voxel(), DVec3::new(1.0, 0.5, 2.0));
        assert_eq!(g.min, DVec3::new(-2.0, -1.0, -4.0));
        assert_eq!(g.max, DVec3::new(12.0, 11.0, 14.0));
    }

    #[test]
    fn bad_grids_are_refused() {
        let (lo, hi) = (DVec3::ZERO, DVec3::ONE);
        assert!(spec(None, Some(0.0), 0).grid(lo, hi).is_err());
        assert!(spec(None, Some(f64::NAN), 0).grid(lo, hi).is_err());
        assert!(spec(None, Some(1e-9), 0).grid(lo, hi).is_err());
        assert!(spec(None, None, 0).grid(lo, hi).is_err());
        assert!(spec(Some([4; 3]), None, usize::MAX).grid(lo, hi).is_err());
    }
}

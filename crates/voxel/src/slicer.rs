//! A scene set up for slicing (§4.4): the grid laid on the array, the display lists in its
//! frame, the slabs and the sampling convention.

use glam::{DMat3, DVec3};
use rtl_model::{ArrayConfig, WordFormat};

use csgpix_draw::project::{
    closed_list_at, max_slope, pixels, scale_perpendicular, Frame, DEPTH_MARGIN,
};
use csgpix_scene::display_list::{DisplayList, DlPlane};
use csgpix_scene::grid::Grid;
use csgpix_scene::solid::CsgScene;

use crate::blend::BlendEval;
use crate::error::{Error, Result};
use crate::pixel_box::PixelBox;
use crate::sampled::Sampled;

/// How slab masks are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// The processor, clock by clock (`cycle`) or word by word (`word`).
    Array {
        /// The clock-by-clock model; false for the word-by-word one.
        cycle: bool,
    },
    /// The array's plane words reduced to per-pixel depth intervals.
    Intervals,
    /// Exact f64 intervals.
    Float,
    /// Column by column ([`crate::runs`]): each primitive's slabs along every pixel's ray
    /// from the same depths as [`Route::Intervals`] (`float: false`) or [`Route::Float`]
    /// (`float: true`), merged into runs of constant membership, the tree evaluated once per
    /// run. The same voxels as the route it takes its depths from (tested).
    Runs {
        /// Exact f64 depths (the float model) instead of the array's plane words.
        float: bool,
    },
}

impl Route {
    /// The slab-by-slab route that gives the same voxels: [`Route::Intervals`] or
    /// [`Route::Float`] for [`Route::Runs`], itself otherwise.
    pub fn by_slab(self) -> Route {
        match self {
            Route::Runs { float: false } => Route::Intervals,
            Route::Runs { float: true } => Route::Float,
            r => r,
        }
    }
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

/// How to slice a scene: everything [`Slicer::new`] takes beside the scene and the grid.
pub struct SlicerOptions {
    /// The depth word (§2.3.1).
    pub fmt: WordFormat,
    /// Which depths of a voxel's ray classify it.
    pub sampling: Sampling,
    /// Panels the array route prunes to ([`Slicer::panel`]); None simulates the whole array.
    pub panel: Option<[usize; 2]>,
    /// Voxels won by a dataset take its grey value (§4.5), not its colour code.
    pub grey: bool,
    /// Grey-valued output by the blending operators of §3.3 instead of labels.
    pub blend: Option<BlendEval>,
    /// The scene's imports, loaded, in the scene's order ([`crate::sampled::load_imports`]):
    /// as many as the scene names.
    pub sampled: Vec<Sampled>,
}

impl Default for SlicerOptions {
    /// The thesis's word, centre sampling, [`DEFAULT_PANEL`] panels, colour codes, no imports.
    fn default() -> Self {
        SlicerOptions {
            fmt: WordFormat::THESIS,
            sampling: Sampling::Centre,
            panel: Some(DEFAULT_PANEL),
            grey: false,
            blend: None,
            sampled: vec![],
        }
    }
}

/// A scene set up for slicing: its display lists in the grid's frame and the slabs. Built
/// whole by [`Slicer::new`]; its fields are there to be read.
pub struct Slicer {
    /// The voxel grid: X, Y on the array's pixels, Z on the slabs.
    pub grid: Grid,
    /// The depth word (§2.3.1).
    pub fmt: WordFormat,
    /// One display list per solid (§5.2), in the frame of [`Slicer::frame`], with its
    /// silhouette planes; every perpendicular plane's K is scaled to the word
    /// (`csgpix_draw::project::scale_perpendicular`), so it is a multiple of the distance in
    /// pixels, not the distance.
    pub lists: Vec<DisplayList>,
    /// Raw depth-word units per slab (a whole number, so slab planes are exact words; even
    /// under centre sampling, so the voxel centres are exact words too).
    pub slab_raw: i64,
    /// Which depths of each slab classify its voxels ([`Slicer::window`]).
    pub sampling: Sampling,
    /// Faces steeper than this (depth units per pixel) are drawn as perpendicular planes
    /// through their trace at depth 0 (`csgpix_draw::project`), moving them by at most
    /// maxdepth / slope_limit pixels inside the depth range.
    pub slope_limit: f64,
    /// Colour code of each primitive: a solid's display-list colour, then each import's.
    pub colours: Vec<u8>,
    /// Panels of this many pixels: the array route simulates, for each primitive, only the
    /// panels and slabs its footprint touches ([`crate::requirements`]). None simulates the
    /// whole array for every frame. Either way the voxels are the same (tested).
    pub panel: Option<[usize; 2]>,
    /// Where the grid lies on the array: scene point → (pixel x, pixel y, depth).
    pub frame: Frame,
    /// Imported primitives (datasets, meshes), after the solids: primitive
    /// `lists.len() + j` ([`crate::sampled`]), one per import of the scene.
    pub sampled: Vec<Sampled>,
    /// Voxels won by a dataset take its grey value (§4.5), not its colour code.
    pub grey: bool,
    /// Grey-valued output by the blending operators of §3.3 instead of labels.
    pub blend: Option<BlendEval>,
    /// Per primitive, the pixels whose rays can meet it: its vertices' (or box's) projection
    /// grown by [`OUTLINE_MARGIN`] pixels, within the array (None: nowhere on it). The run
    /// route visits a primitive only on these columns.
    pub outlines: Vec<Option<PixelBox>>,
}

/// Panels a solid's outline may meet before the run route holds its planes for the whole
/// run ([`Slicer::holds_planes`]).
pub const HELD_PANELS: usize = 4;

/// Pixels an outline box is grown by beyond the projected vertices: silhouette planes are
/// exact to 1.5e-5 pixel (`solid_lists`), so one pixel is room enough; two for margin.
pub const OUTLINE_MARGIN: f64 = 2.0;

/// Bytes of one plane as the run route holds it (`ranges`: a word's coefficients or an f64's,
/// and the Y and H flags), for [`Slicer::planes_bytes`]; `ranges` checks that both fit.
pub(crate) const RUN_PLANE_BYTES: usize = 32;

impl Slicer {
    /// Lay the grid on the array (§4.4): X, Y to pixels (voxel centres at integer pixel
    /// coordinates), Z to depth, slab k at DEPTH_MARGIN + k·q depth units, q as large as the
    /// word's depth range allows (even under centre sampling, so the voxel centre is a word;
    /// at least 1). Fails when the slabs do not fit the word, or when `opts.sampled` does not
    /// hold one loaded import per import the scene names ([`Error::ImportsNotLoaded`]).
    ///
    /// ```
    /// use csgpix_voxel::{Error, Grid, Sampling, Slicer, SlicerOptions};
    /// use glam::DVec3;
    ///
    /// let scene = csgpix_openscad::parse_csg("cube(size = [2, 2, 2]);", "c.csg").unwrap();
    /// let grid = Grid::new([8, 8, 4], DVec3::ZERO, DVec3::splat(2.0)).unwrap();
    /// let opts = SlicerOptions { sampling: Sampling::Slab, ..SlicerOptions::default() };
    /// let s = Slicer::new(&scene, grid, opts).unwrap();
    /// // Slab k starts at Z-plane(k): the slabs share the word's depth range evenly.
    /// assert_eq!(s.z_plane(1) - s.z_plane(0), s.slab_raw);
    /// assert_eq!(s.window(), (0, s.slab_raw - 1));
    ///
    /// // A scene naming a file needs it loaded.
    /// let imports = csgpix_openscad::parse_csg("import(\"part.stl\");", "i.csg").unwrap();
    /// let err = Slicer::new(&imports, grid, SlicerOptions::default()).err();
    /// assert_eq!(err, Some(Error::ImportsNotLoaded { named: 1, loaded: 0 }));
    /// ```
    pub fn new(scene: &CsgScene, grid: Grid, opts: SlicerOptions) -> Result<Slicer> {
        let SlicerOptions {
            fmt,
            sampling,
            panel,
            grey,
            blend,
            sampled,
        } = opts;
        let slab_raw = slab_raw(&grid, &fmt, sampling)?;
        if sampled.len() != scene.imports.len() {
            return Err(Error::ImportsNotLoaded {
                named: scene.imports.len(),
                loaded: sampled.len(),
            });
        }
        let frame = Self::frame_of(&grid, fmt.to_real(slab_raw));
        let (w, h) = (grid.dims[0], grid.dims[1]);
        let slope_limit = match sampling {
            Sampling::Slab => max_slope(&fmt, w, h),
            Sampling::Centre => voxel_slope(&fmt, w, h),
        };
        let (lists, mut outlines) = solid_lists(scene, &frame, slope_limit, &fmt, w, h);
        outlines.extend(sampled.iter().map(|s| {
            let (lo, hi) = s.bounds();
            let corners = crate::sampled::corners(lo, hi).map(|p| frame.to_pixel(p));
            outline(corners, w, h)
        }));
        let colours = lists
            .iter()
            .map(|dl| dl.planes.first().map_or(1, |p| p.colour.min(255) as u8))
            .chain(sampled.iter().map(|s| s.colour))
            .collect();
        Ok(Slicer {
            grid,
            fmt,
            lists,
            slab_raw,
            sampling,
            slope_limit,
            colours,
            panel,
            frame,
            sampled,
            grey,
            blend,
            outlines,
        })
    }

    /// The bytes a run holds for the scene's solids whatever its route (docs/memory.md,
    /// "Planes held"): `scene`'s vertices and faces, the display lists, with `runs` the run
    /// route's planes as words (or f64) for the solids it holds them of
    /// ([`Slicer::holds_planes`]) and per thread one solid's, and per thread one solid's
    /// program while its clocks are counted. A scene of millions of planes (thousands of
    /// circles of many fragments) holds them twice, as faces and in the lists; a scene of a
    /// few solids, next to nothing.
    pub fn planes_bytes(&self, scene: &CsgScene, runs: bool, threads: usize) -> u64 {
        use std::mem::size_of;
        let solids: u64 = scene
            .solids
            .iter()
            .map(|s| {
                let [index, ends] = s.faces.capacity_bytes();
                heap(s.vertices.capacity() * 24) + heap(index) + heap(ends)
            })
            .sum();
        // The display lists' bytes, the planes the run route holds, the most planes of one.
        let (lists, held, most) = self
            .lists
            .iter()
            .enumerate()
            .fold((0, 0, 0), |acc, (p, l)| {
                let (b, n, m) = acc;
                let len = l.planes.len() as u64;
                let bytes = heap(l.planes.capacity() * size_of::<DlPlane>());
                (b + bytes, n + len * self.holds_planes(p) as u64, m.max(len))
            });
        // The run route's held planes, and per thread one solid's compiled as it meets a panel.
        let words = match runs {
            true => (held + most * threads as u64) * RUN_PLANE_BYTES as u64,
            false => 0,
        };
        // counted_work: a copy of the list, and the program of its planes and the slab's.
        let most = most + 8;
        let program = most * (size_of::<DlPlane>() + size_of::<rtl_model::Op>()) as u64 * 2;
        solids + lists + words + program * threads as u64
    }

    /// Whether the run route holds solid `p`'s planes (as words or f64) for the whole run:
    /// when its outline meets more than [`HELD_PANELS`] of the route's panels. A smaller
    /// solid's are made again from its display list in each panel it meets, so a scene of
    /// thousands of small many-sided solids holds its planes once (the lists), not twice;
    /// a large one is not compiled again panel after panel.
    pub fn holds_planes(&self, p: usize) -> bool {
        let [pw, ph] = self.panel.unwrap_or(DEFAULT_PANEL).map(|n| n.max(1));
        self.outlines[p].is_some_and(|o| {
            let across = (o.x1 - 1) / pw - o.x0 / pw + 1;
            let down = (o.y1 - 1) / ph - o.y0 / ph + 1;
            across * down > HELD_PANELS
        })
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

/// Raw depth-word units per slab: as many as the word's depth range allows between its
/// margins, even under centre sampling (so the voxel centre is a word).
fn slab_raw(grid: &Grid, fmt: &WordFormat, sampling: Sampling) -> Result<i64> {
    let one = 1i64 << fmt.frac;
    let margin_raw = DEPTH_MARGIN as i64 * one;
    let room = fmt.maxdepth() - 2 * margin_raw;
    let mut slab_raw = room / grid.dims[2] as i64;
    if sampling == Sampling::Centre {
        slab_raw &= !1;
    }
    if slab_raw < 1 {
        return Err(Error::TooManySlices {
            slices: grid.dims[2],
            frac: fmt.frac,
            int: fmt.int,
        });
    }
    Ok(slab_raw)
}

/// One display list per solid in `frame` (§5.2), its silhouette planes added so that it
/// shows nothing outside its outline at any depth, every perpendicular plane's K scaled to
/// the word on a `w`×`h` array ([`scale_perpendicular`]: the array reads only K's sign, and
/// the scale s takes the rounding of K0, dKx, dKy from up to 2^-(F+1)·(1 + x + y) pixels off
/// the trace to that over s, s ≥ 4096 at 64×64 with the thesis's word: 1.5e-5 pixel); and
/// each solid's [`outline`], from the same projected vertices.
fn solid_lists(
    scene: &CsgScene,
    frame: &Frame,
    slope_limit: f64,
    fmt: &WordFormat,
    w: usize,
    h: usize,
) -> (Vec<DisplayList>, Vec<Option<PixelBox>>) {
    use rayon::prelude::*;
    scene
        .solids
        .par_iter()
        .enumerate()
        .map(|(i, solid)| {
            let pixels = pixels(frame, solid);
            let mut dl = closed_list_at(&pixels, i, solid, slope_limit);
            scale_perpendicular(&mut dl, fmt, w, h);
            (dl, outline(pixels.into_iter(), w, h))
        })
        .unzip()
}

/// The pixels of a `w`×`h` array whose rays can meet the convex hull of points projected
/// to pixels and depth (`Frame::to_pixel`): their box grown by [`OUTLINE_MARGIN`] (None when
/// it misses the array or there are no points, or a point is not finite).
fn outline(pts: impl Iterator<Item = DVec3>, w: usize, h: usize) -> Option<PixelBox> {
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for q in pts {
        (lo, hi) = (lo.min(q), hi.max(q));
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let first = |v: f64| (v - OUTLINE_MARGIN).ceil().max(0.0);
    let end = |v: f64, n: usize| ((v + OUTLINE_MARGIN).floor() + 1.0).min(n as f64);
    let b = PixelBox {
        x0: first(lo.x) as usize,
        y0: first(lo.y) as usize,
        x1: end(hi.x, w).max(0.0) as usize,
        y1: end(hi.y, h).max(0.0) as usize,
    };
    (b.x0 < b.x1 && b.y0 < b.y1).then_some(b)
}

/// Heap bytes of an allocation of `bytes` (glibc: an 8-byte header, 16-byte chunks of at least
/// 32); nothing for an empty one.
fn heap(bytes: usize) -> u64 {
    match bytes {
        0 => 0,
        b => ((b + 8).div_ceil(16) * 16).max(32) as u64,
    }
}

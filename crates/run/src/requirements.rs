//! The requirements job: what a scene needs of the hardware (panels, slabs, word, stack,
//! label; §2.5, §4.3.2, §5.5) and the clocks each costs, from the same analysis the
//! simulator prunes with.

use crate::memory::Limit;
use crate::Error;
use std::path::PathBuf;

use csgpix_draw::compile::clip_scene_ops;
use csgpix_draw::project::{project, Projected, View};
use csgpix_scene::solid::CsgScene;
use csgpix_voxel::blist::BlistTable;
use csgpix_voxel::requirements::DepthLayout;
use csgpix_voxel::{footprints, touched_panels, Footprint, PixelBox};
use csgpix_voxel::{slice_ops, Grid, Sampling, Slicer, SlicerOptions};
use rtl_model::array::{check_program, program_cycles};
use rtl_model::{ArrayConfig, WordFormat};
use serde::{Deserialize, Serialize};

use crate::grid::Resolution;
use crate::memory::default_limit;
use crate::progress::{warn_all, Progress};
use crate::read::ReadSettings;

/// Analyse a `.csg` scene for the hardware. `Default` is the documented defaults: a 128
/// grid over the scene's bounds, 32x32 panels, centre sampling, precision 0.01, the thesis
/// word, the iso view on a 250x250 screen.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RequirementsJob {
    /// The OpenSCAD `.csg` scene.
    pub scene: PathBuf,
    /// The voxel grid the scene is sliced on (`--res`).
    #[serde(with = "crate::named::by_text")]
    pub res: Resolution,
    /// The region, X0,Y0,Z0 and X1,Y1,Z1 (`--bounds`; None: the scene's bounds).
    pub bounds: Option<([f64; 3], [f64; 3])>,
    /// Panel size in pixels (`--panel`; None: the whole array).
    pub panel: Option<[usize; 2]>,
    /// The sampling convention of the voxelize run described (`--sampling`).
    #[serde(with = "crate::named::by_name")]
    pub sampling: Sampling,
    /// Depth precision wanted, scene units along Z (`--precision`).
    pub precision: f64,
    /// The depth word the scene is sliced with (`--word`).
    #[serde(with = "crate::array_args::word_text")]
    pub word: WordFormat,
    /// View of the render program whose clipping stack is measured (`--view`).
    #[serde(with = "crate::named::by_name")]
    pub view: View,
    /// Screen of the render program, width and height (`--screen`).
    pub screen: (usize, usize),
    /// The memory limit (`--max-memory`); not serialized: it is the machine's.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
    /// How the scene is read.
    pub read: ReadSettings,
}

impl Default for RequirementsJob {
    fn default() -> Self {
        RequirementsJob {
            scene: PathBuf::new(),
            res: Resolution::Longest(128),
            bounds: None,
            panel: Some([32, 32]),
            sampling: Sampling::Centre,
            precision: 0.01,
            word: WordFormat::THESIS,
            view: View::Iso,
            screen: (250, 250),
            max_memory: default_limit(),
            read: ReadSettings::default(),
        }
    }
}

/// Bytes per pixel of a slice the analysis holds (footprints and the slicer's per-pixel
/// state): measured 12.6-16 on three scenes at 4096², docs/memory.md.
const BYTES_PER_PIXEL: u64 = 20;

/// An upper bound of the analysis's memory: per pixel of a slice, and the process.
fn memory_estimate(dims: [usize; 3]) -> u64 {
    let pixels = (dims[0] as u64).saturating_mul(dims[1] as u64);
    pixels
        .saturating_mul(BYTES_PER_PIXEL)
        .saturating_add(16 << 20)
}

/// One solid's footprint and frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Solid {
    /// 1-based, in file order.
    pub solid: usize,
    pub pixels: Option<PixelBox>,
    pub slabs: Option<(u32, u32)>,
    pub panels: usize,
    /// Clocks of one P·Vz frame on the whole array.
    pub frame_clocks: u64,
}

/// What the scene needs (`--json` prints these fields, in this order).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RequirementsReport {
    pub dims: [usize; 3],
    pub panel: Option<[usize; 2]>,
    pub panels_total: usize,
    pub panels_touched: usize,
    /// Slabs `first..=last` that hold any geometry.
    pub slabs_with_geometry: Option<(u32, u32)>,
    /// Clipping-stack levels: one P·Vz frame, and the scene's render program.
    pub stack_levels_slice: usize,
    pub stack_levels_render: usize,
    /// The Blist label register and table.
    pub label_bits: u32,
    pub blist_rows: usize,
    /// The word asked for and its worst plane-word error (scene units), and the narrowest word
    /// reaching `precision`.
    pub word: String,
    pub word_error: Option<f64>,
    pub precision: f64,
    pub word_needed: Option<String>,
    pub word_needed_error: Option<f64>,
    /// Clocks: every solid in every slab (as §5.5 counts), only the slabs each solid meets,
    /// and the render program.
    pub cycles_all_frames: u64,
    pub cycles_needed_frames: u64,
    pub cycles_render: u64,
    /// Pixel-clocks the array route simulates against the whole array's.
    pub simulated_pixel_clocks: u64,
    pub full_pixel_clocks: u64,
    pub solids: Vec<Solid>,
}

impl RequirementsJob {
    /// The memory plan: per pixel of a slice of the grid over the scene's bounds (or
    /// `bounds`), and the process; the scene is read to know its bounds.
    pub fn estimate(&self) -> crate::Result<u64> {
        let scene = csgpix_openscad::read_scene_with(
            &self.scene,
            &self.read.read_options().for_the_array(),
        )?;
        Ok(memory_estimate(self.grid(&scene)?.dims))
    }

    /// Read the scene, check the estimate, analyse.
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<RequirementsReport> {
        let at = |e: Error| e.context(self.scene.display().to_string());
        let scene = csgpix_openscad::read_scene_with(
            &self.scene,
            &self.read.read_options().for_the_array(),
        )?;
        warn_all(progress, &scene.warnings);
        scene.require_convex(&self.scene.display().to_string(), "`requirements`")?;
        if !(self.precision > 0.0 && self.precision.is_finite()) {
            let message = format!("--precision {}: must be a positive number", self.precision);
            return Err(Error::options("--precision", message));
        }
        let grid = self.grid(&scene)?;
        self.max_memory
            .check(memory_estimate(grid.dims), "this analysis", "lower --res")?;
        let opts = SlicerOptions {
            fmt: self.word,
            sampling: self.sampling,
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&scene, grid, opts).map_err(|e| at(e.into()))?;
        analyse(self, &scene, &slicer).map_err(at)
    }

    /// The grid over `bounds` or the scene's bounds.
    fn grid(&self, scene: &CsgScene) -> crate::Result<Grid> {
        let at = |e: Error| e.context(self.scene.display().to_string());
        let spec = self.res.spec();
        match self.bounds {
            Some((lo, hi)) => spec.grid(lo.into(), hi.into()),
            None => Grid::scene_bounds(scene).and_then(|(lo, hi)| spec.grid(lo, hi)),
        }
        .map_err(|e| match e.kind() {
            csgpix_scene::Kind::NeedsBounds => at(Error::options(
                "--bounds",
                "the scene has no solids: give --bounds",
            )),
            _ => at(e.into()),
        })
    }
}

fn analyse(
    a: &RequirementsJob,
    scene: &CsgScene,
    slicer: &Slicer,
) -> crate::Result<RequirementsReport> {
    let [w, h, nz] = slicer.grid.dims;
    let panel = a.panel.unwrap_or([w, h]);
    // The render program first: it refuses a scene too big to draw before the slices' work.
    let (render_levels, render_cycles) = render_program(a, scene)?;
    let fps = footprints(slicer)?;
    let cfg = slicer.config();
    let mut solids = vec![];
    let (mut all, mut needed, mut simulated, mut levels) = (0, 0, 0, 0);
    for (p, fp) in fps.iter().enumerate() {
        let ops = slice_ops(slicer, p, 0)?;
        levels = levels.max(check_program(&ops, cfg.stack_depth)?);
        let frame_clocks = program_cycles(&cfg, &ops);
        all += frame_clocks * nz as u64;
        needed += frame_clocks * fp.slab_count() as u64;
        simulated += pruned_pixel_clocks(&cfg, &ops, fp, panel, fp.slab_count());
        solids.push(Solid {
            solid: p + 1,
            pixels: fp.pixels,
            slabs: fp.slabs,
            panels: fp.pixels.map_or(0, |b| {
                touched_panels(&[b], panel, w, h)
                    .iter()
                    .filter(|&&t| t)
                    .count()
            }),
            frame_clocks,
        });
    }
    let boxes: Vec<PixelBox> = fps.iter().filter_map(|f| f.pixels).collect();
    let touched = touched_panels(&boxes, panel, w, h);
    let layout = DepthLayout {
        extent: slicer.grid.max.z - slicer.grid.min.z,
        slabs: nz,
        w,
        h,
    };
    let needed_word = layout.word_for(a.precision, a.word);
    let table = BlistTable::compile(&scene.root);
    Ok(RequirementsReport {
        dims: slicer.grid.dims,
        panel: a.panel,
        panels_total: touched.len(),
        panels_touched: touched.iter().filter(|&&t| t).count(),
        slabs_with_geometry: slab_union(&fps),
        stack_levels_slice: levels,
        stack_levels_render: render_levels,
        label_bits: table.label_bits,
        blist_rows: table.rows.len(),
        word: word_name(&a.word),
        word_error: layout.error(&a.word),
        precision: a.precision,
        word_needed: needed_word.as_ref().map(word_name),
        word_needed_error: needed_word.and_then(|f| layout.error(&f)),
        cycles_all_frames: all,
        cycles_needed_frames: needed,
        cycles_render: render_cycles,
        simulated_pixel_clocks: simulated,
        full_pixel_clocks: all * (w * h) as u64,
        solids,
    })
}

/// Pixel-clocks of simulating `slabs` frames of a solid on the panels of its footprint only.
fn pruned_pixel_clocks(
    cfg: &ArrayConfig,
    ops: &[rtl_model::Op],
    fp: &Footprint,
    panel: [usize; 2],
    slabs: usize,
) -> u64 {
    let Some(b) = fp.pixels.map(|b| b.to_panels(panel, cfg.width, cfg.height)) else {
        return 0;
    };
    let sub = ArrayConfig {
        width: b.width(),
        height: b.height(),
        ..*cfg
    };
    program_cycles(&sub, ops) * b.pixels() as u64 * slabs as u64
}

fn slab_union(fps: &[Footprint]) -> Option<(u32, u32)> {
    fps.iter()
        .filter_map(|f| f.slabs)
        .reduce(|(a, b), (c, d)| (a.min(c), b.max(d)))
}

/// Stack levels and clocks of the scene's render program (the scene's tree as a clipping
/// function, §5.2.1) on the `--screen` array.
fn render_program(a: &RequirementsJob, scene: &CsgScene) -> crate::Result<(usize, u64)> {
    let (w, h) = a.screen;
    let cfg = ArrayConfig {
        fmt: a.word,
        ..ArrayConfig::new(w, h)
    };
    let Projected { lists, clip } =
        project(scene, a.view, w, h, &cfg.fmt).map_err(super::lib_errors::draw)?;
    let Some(clip) = clip else {
        return Ok((0, 0));
    };
    let ops = clip_scene_ops(&lists, &clip, &cfg.fmt, cfg.colour_bits).map_err(|(i, e)| {
        let whole = e.field == csgpix_draw::compile::WHOLE_PROGRAM;
        Error::Compile {
            solid: (!whole).then_some(i),
            error: e,
        }
    })?;
    let levels = check_program(&ops, 64)?;
    Ok((levels, program_cycles(&cfg, &ops)))
}

fn word_name(f: &WordFormat) -> String {
    format!("{}/{}/{} (N_D = {})", f.frac, f.int, f.ovf, f.bits())
}

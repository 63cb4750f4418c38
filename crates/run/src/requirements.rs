//! `csgpix requirements`: what a scene needs of the hardware (panels, slabs, word, stack,
//! label) and the clocks each costs, from the same analysis the simulator prunes with.

use crate::Error;
use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::compile::clip_scene_ops;
use csgpix_draw::project::{project, Projected};
use csgpix_scene::solid::CsgScene;
use csgpix_voxel::blist::BlistTable;
use csgpix_voxel::requirements::DepthLayout;
use csgpix_voxel::{footprints, touched_panels, Footprint, PixelBox};
use csgpix_voxel::{slice_ops, Grid, Slicer, SlicerOptions};
use glam::DVec3;
use rtl_model::array::{check_program, program_cycles};
use rtl_model::{ArrayConfig, Equations, WordFormat};
use serde::Serialize;

use super::array_args::{parse_size, parse_word};
use super::voxelize::{parse_bounds, parse_panel, parse_res, PanelArg, Resolution, SamplingArg};
use super::ViewArg;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix requirements vectors/scenes/twelve.csg --res 128\n  \
    csgpix requirements vectors/scenes/figure-5.2.csg --res 64 --panel 16x16 --precision 0.001 --json")]
pub struct Args {
    /// OpenSCAD `.csg` scene.
    scene: PathBuf,
    /// Voxel grid the scene is sliced on: N for a cube, or NXxNYxNZ.
    #[arg(long, value_parser = parse_res, default_value = "128")]
    res: Resolution,
    /// Region, X0,Y0,Z0,X1,Y1,Z1 in scene units (default: the scene's bounds).
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    bounds: Option<(DVec3, DVec3)>,
    /// Panel size in pixels (NXxNY).
    #[arg(long, default_value = "32x32", value_parser = parse_panel)]
    panel: PanelArg,
    /// The sampling convention of the voxelize run described (docs/voxelization.md).
    #[arg(long, value_enum, default_value_t)]
    sampling: SamplingArg,
    /// Depth precision wanted, in scene units along Z: the narrowest word that keeps every
    /// plane word within it on the whole array.
    #[arg(long, default_value_t = 0.01)]
    precision: f64,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits the scene is sliced with.
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    word: WordFormat,
    /// View of the render program whose clipping stack is measured.
    #[arg(long, value_enum, default_value_t)]
    view: ViewArg,
    /// Screen of the render program, WxH.
    #[arg(long, default_value = "250x250", value_parser = parse_size)]
    screen: (usize, usize),
    /// Print as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
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

#[derive(Serialize)]
struct Solid {
    /// 1-based, in file order.
    solid: usize,
    pixels: Option<PixelBox>,
    slabs: Option<(u32, u32)>,
    panels: usize,
    /// Clocks of one P·Vz frame on the whole array.
    frame_clocks: u64,
}

#[derive(Serialize)]
struct Report {
    dims: [usize; 3],
    panel: Option<[usize; 2]>,
    panels_total: usize,
    panels_touched: usize,
    /// Slabs `first..=last` that hold any geometry.
    slabs_with_geometry: Option<(u32, u32)>,
    /// Clipping-stack levels: one P·Vz frame, and the scene's render program.
    stack_levels_slice: usize,
    stack_levels_render: usize,
    /// The Blist label register and table.
    label_bits: u32,
    blist_rows: usize,
    /// The word asked for and its worst plane-word error (scene units), and the narrowest word
    /// reaching `precision`.
    word: String,
    word_error: Option<f64>,
    precision: f64,
    word_needed: Option<String>,
    word_needed_error: Option<f64>,
    /// Clocks: every solid in every slab (as §5.5 counts), only the slabs each solid meets,
    /// and the render program.
    cycles_all_frames: u64,
    cycles_needed_frames: u64,
    cycles_render: u64,
    /// Pixel-clocks the array route simulates against the whole array's.
    simulated_pixel_clocks: u64,
    full_pixel_clocks: u64,
    solids: Vec<Solid>,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let at = |e: Error| e.context(a.scene.display().to_string());
    let scene = csgpix_openscad::read_scene_with(&a.scene, &a.openscad.read_options())?;
    crate::read_args::print_warnings(&scene.warnings);
    scene.require_convex(&a.scene.display().to_string(), "`requirements`")?;
    if !(a.precision > 0.0 && a.precision.is_finite()) {
        let message = format!("--precision {}: must be a positive number", a.precision);
        return Err(Error::options("--precision", message));
    }
    let grid = match a.bounds {
        Some((lo, hi)) => a.res.spec().grid(lo, hi),
        None => Grid::scene_bounds(&scene).and_then(|(lo, hi)| a.res.spec().grid(lo, hi)),
    }
    .map_err(|e| match e.kind() {
        csgpix_scene::Kind::NeedsBounds => at(Error::options(
            "--bounds",
            "the scene has no solids: give --bounds",
        )),
        _ => at(e.into()),
    })?;
    a.mem
        .check(memory_estimate(grid.dims), "this analysis", "lower --res")?;
    let opts = SlicerOptions {
        fmt: a.word,
        sampling: a.sampling.sampling(),
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&scene, grid, opts).map_err(|e| at(e.into()))?;
    let report = analyse(&a, &scene, &slicer).map_err(at)?;
    if a.json {
        let text = serde_json::to_string_pretty(&report)?;
        println!("{text}");
    } else {
        print_text(&report);
    }
    Ok(ExitCode::SUCCESS)
}

fn analyse(a: &Args, scene: &CsgScene, slicer: &Slicer) -> crate::Result<Report> {
    let [w, h, nz] = slicer.grid.dims;
    let panel = a.panel.0.unwrap_or([w, h]);
    let fps = footprints(slicer)?;
    let set = Equations::Derived.set();
    let cfg = slicer.config();
    let mut solids = vec![];
    let (mut all, mut needed, mut simulated, mut levels) = (0, 0, 0, 0);
    for (p, fp) in fps.iter().enumerate() {
        let ops = slice_ops(slicer, p, 0)?;
        levels = levels.max(check_program(&ops, cfg.stack_depth)?);
        let frame_clocks = program_cycles(&cfg, &set, &ops);
        all += frame_clocks * nz as u64;
        needed += frame_clocks * fp.slab_count() as u64;
        simulated += pruned_pixel_clocks(&cfg, &set, &ops, fp, panel, fp.slab_count());
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
    let (render_levels, render_cycles) = render_program(a, scene)?;
    let table = BlistTable::compile(&scene.root);
    Ok(Report {
        dims: slicer.grid.dims,
        panel: a.panel.0,
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
    set: &rtl_model::EquationSet,
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
    program_cycles(&sub, set, ops) * b.pixels() as u64 * slabs as u64
}

fn slab_union(fps: &[Footprint]) -> Option<(u32, u32)> {
    fps.iter()
        .filter_map(|f| f.slabs)
        .reduce(|(a, b), (c, d)| (a.min(c), b.max(d)))
}

/// Stack levels and clocks of the scene's render program (the scene's tree as a clipping
/// function, §5.2.1) on the `--screen` array.
fn render_program(a: &Args, scene: &CsgScene) -> crate::Result<(usize, u64)> {
    let (w, h) = a.screen;
    let cfg = ArrayConfig {
        fmt: a.word,
        ..ArrayConfig::new(w, h)
    };
    let Projected { lists, clip } =
        project(scene, a.view.into(), w, h, &cfg.fmt).map_err(super::lib_errors::draw)?;
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
    Ok((
        levels,
        program_cycles(&cfg, &Equations::Derived.set(), &ops),
    ))
}

fn word_name(f: &WordFormat) -> String {
    format!("{}/{}/{} (N_D = {})", f.frac, f.int, f.ovf, f.bits())
}

fn print_text(r: &Report) {
    let pct = |a: u64, b: u64| 100.0 * a as f64 / b.max(1) as f64;
    println!("grid {}x{}x{}", r.dims[0], r.dims[1], r.dims[2]);
    println!(
        "panels: {} of {} touched ({})",
        r.panels_touched,
        r.panels_total,
        r.panel.map_or("whole array".into(), |p| format!(
            "{}x{} pixels",
            p[0], p[1]
        ))
    );
    match r.slabs_with_geometry {
        Some((f, l)) => println!("slabs with geometry: {f}..={l} of 0..={}", r.dims[2] - 1),
        None => println!("slabs with geometry: none"),
    }
    println!(
        "clipping stack: {} levels per slice, {} for the render program",
        r.stack_levels_slice, r.stack_levels_render
    );
    println!(
        "Blist: {} rows, label register {} bits",
        r.blist_rows, r.label_bits
    );
    println!(
        "word {}: worst plane-word error {} scene units",
        r.word,
        r.word_error
            .map_or("- (slabs do not fit)".into(), |e| format!("{e:.3e}"))
    );
    match (&r.word_needed, r.word_needed_error) {
        (Some(w), Some(e)) => println!("word for precision {}: {w}, error {e:.3e}", r.precision),
        _ => println!("word for precision {}: none up to 62 bits", r.precision),
    }
    println!(
        "clocks: {} for every solid in every slab, {} for the slabs each meets ({:.1}%); render {}",
        r.cycles_all_frames,
        r.cycles_needed_frames,
        pct(r.cycles_needed_frames, r.cycles_all_frames),
        r.cycles_render
    );
    println!(
        "simulated pixel-clocks on the array route: {} of {} ({:.1}%)",
        r.simulated_pixel_clocks,
        r.full_pixel_clocks,
        pct(r.simulated_pixel_clocks, r.full_pixel_clocks)
    );
}

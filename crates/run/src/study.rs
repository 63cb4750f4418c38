//! `csgpix study`: sweep the knobs that trade speed for accuracy when voxelizing a scene
//! through the array (depth-word fraction bits §2.3.1/§2.5, tessellation, slabs §4.4/§5.5,
//! model), and write the figures as CSV and PNG charts.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_output::{Out, Outputs};
use std::time::Instant;

use super::voxelize::SamplingArg;
use crate::sweep::{charts, csv, prepare, Model, Point, Prepared, Sweep};
use csgpix_voxel::memory_estimate;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Writes DIR/study.csv (one row per point) and the charts DIR/bits.png, \
    DIR/fragments.png, DIR/depth.png, DIR/wall.png. See docs/tradeoffs.md for the columns.\n\n\
    Examples:\n  \
    csgpix study vectors/scenes/cube-minus-cylinder.csg --models cycle,word,float -o study/cmc\n  \
    csgpix study vectors/scenes/csg-logo.csg --bits 4,8,12 --fragments 16,32 --slabs 32 -o logo\n  \
    csgpix study vectors/scenes/figure-5.2.csg --res 64 --json -o fig52 > fig52.json\n  \
    csgpix study scene.csg --bits 10 --int-bits 8 --ovf-bits 4 --slabs 16,32,64,128 -o out"
)]
pub struct Args {
    /// OpenSCAD `.csg` scene.
    scene: PathBuf,
    /// Output directory (created if missing; files are written only when the whole sweep
    /// succeeded).
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// Fraction bits F of the depth word to sweep (N_D = F + I + O + 1 clocks per plane).
    #[arg(long, value_delimiter = ',', default_values_t = [4u32, 6, 8, 10, 12, 16])]
    bits: Vec<u32>,
    /// `$fn` of every sphere and cylinder to sweep (the scene's own `$fn` is overridden).
    #[arg(long, value_delimiter = ',', default_values_t = [8u32, 16, 32, 64])]
    fragments: Vec<u32>,
    /// Slabs along Z to sweep (voxel resolution along Z).
    #[arg(long, value_delimiter = ',', default_values_t = [16usize, 32, 64, 128])]
    slabs: Vec<usize>,
    /// Models to run: `cycle` (every frame clock by clock: the same voxels and clocks as
    /// `word`, at 20 to 300 times its wall time, so not run unless asked), `word` (the array's
    /// plane words), `float` (exact, not hardware).
    #[arg(long, value_parser = super::model_parser(), value_delimiter = ',', default_value = "word,float")]
    models: Vec<Model>,
    /// Voxels along X and Y (the array is RES×RES pixels).
    #[arg(long, default_value_t = 32)]
    res: usize,
    /// Integer bits I of the depth word, fixed during the sweep.
    #[arg(long, default_value_t = 10)]
    int_bits: u32,
    /// Overflow bits O of the depth word, fixed during the sweep.
    #[arg(long, default_value_t = 11)]
    ovf_bits: u32,
    /// The sampling convention of every voxelization (docs/voxelization.md).
    #[arg(long, value_enum, default_value_t)]
    sampling: SamplingArg,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
    /// Print every point as JSON.
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Report<'a> {
    scene: String,
    sweep: &'a Sweep,
    /// The grid box shared by every point, scene units.
    bounds: [[f64; 3]; 2],
    points: &'a [Point],
    wall_seconds: f64,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let file = a.scene.display().to_string();
    let text = csgpix_openscad::scene_text_with(&a.scene, a.openscad.limit())?;
    let sweep = Sweep {
        bits: a.bits.clone(),
        fragments: a.fragments.clone(),
        slabs: a.slabs.clone(),
        models: a.models.clone(),
        res: a.res,
        int_bits: a.int_bits,
        ovf_bits: a.ovf_bits,
        sampling: a.sampling.sampling(),
    };
    let mut outs = Outputs::new();
    let dir = outs.dir("-o", &a.out)?;
    let prep = prepare(&text, &file, sweep)?;
    check_memory(&prep, a.mem)?;
    let t0 = Instant::now();
    let bar = progress(prep.sweep.len());
    let points = prep.run(&|| bar.inc(1))?;
    bar.finish_and_clear();
    let wall = t0.elapsed().as_secs_f64();
    let name = a
        .scene
        .file_name()
        .map_or(file.clone(), |n| n.to_string_lossy().into());
    write_outputs(&mut outs, dir, &points, &name)?;
    outs.commit()?;
    report(&a, &prep, &points, &name, wall)
}

/// The largest grid's voxelization, and the reference and float volumes kept beside it.
fn check_memory(prep: &Prepared, mem: super::memory::MaxMemory) -> crate::Result<()> {
    let slabs = prep.sweep.slabs.iter().copied().max().unwrap_or(1);
    let grid = prep.grid(slabs)?;
    let solids = prep
        .scenes
        .iter()
        .map(|(_, s)| s.solids.len())
        .max()
        .unwrap_or(0);
    let need = memory_estimate(&grid, solids, rayon::current_num_threads()).saturating_mul(3);
    Ok(mem.check(need, "this sweep", "lower --res or --slabs")?)
}

fn progress(points: usize) -> ProgressBar {
    let bar = ProgressBar::new(points as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} points")
    {
        bar.set_style(style);
    }
    bar
}

/// Stage study.csv and the charts as the files of directory output `dir`.
fn write_outputs(outs: &mut Outputs, dir: Out, points: &[Point], scene: &str) -> crate::Result<()> {
    let table = csv(points);
    outs.write_in(dir, "study.csv", |w| w.write_all(table.as_bytes()))?;
    for (name, chart) in charts(points, scene) {
        chart.write_png(&outs.stage_path(dir, name)?, 800, 560)?;
    }
    Ok(())
}

fn report(
    a: &Args,
    prep: &Prepared,
    points: &[Point],
    scene: &str,
    wall: f64,
) -> crate::Result<ExitCode> {
    if a.json {
        let r = Report {
            scene: scene.into(),
            sweep: &prep.sweep,
            bounds: [prep.min.to_array(), prep.max.to_array()],
            points,
            wall_seconds: wall,
        };
        let text = serde_json::to_string_pretty(&r)?;
        println!("{text}");
    } else {
        let worst = points.iter().map(|p| p.diff_ref).max().unwrap_or(0);
        println!(
            "{}: {scene}, {} points, at most {worst} voxels differ from the reference; \
             charts beside it; {wall:.2} s wall",
            a.out.join("study.csv").display(),
            points.len(),
        );
    }
    Ok(ExitCode::SUCCESS)
}

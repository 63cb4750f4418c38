//! `csgpix requirements`: flags to a [`RequirementsJob`], its report as text or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::project::View;
use csgpix_run::array_args::{parse_size, parse_word};
use csgpix_run::grid::{parse_bounds, parse_res, Resolution};
use csgpix_run::requirements::{RequirementsJob, RequirementsReport};
use csgpix_run::voxelize::{parse_panel, PanelArg};
use csgpix_voxel::Sampling;
use glam::DVec3;
use rtl_model::WordFormat;

use super::common::{named, MaxMemory, ReadArgs};
use super::progress::Bars;

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
    #[arg(long, value_parser = named::<Sampling>(), default_value = "centre")]
    sampling: Sampling,
    /// Depth precision wanted, in scene units along Z: the narrowest word that keeps every
    /// plane word within it on the whole array.
    #[arg(long, default_value_t = 0.01)]
    precision: f64,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits the scene is sliced with.
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    word: WordFormat,
    /// View of the render program whose clipping stack is measured.
    #[arg(long, value_parser = named::<View>(), default_value = "iso")]
    view: View,
    /// Screen of the render program, WxH.
    #[arg(long, default_value = "250x250", value_parser = parse_size)]
    screen: (usize, usize),
    /// Print as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
}

impl Args {
    fn job(&self) -> RequirementsJob {
        RequirementsJob {
            scene: self.scene.clone(),
            res: self.res,
            bounds: self.bounds.map(|(a, b)| (a.to_array(), b.to_array())),
            panel: self.panel.0,
            sampling: self.sampling,
            precision: self.precision,
            word: self.word,
            view: self.view,
            screen: self.screen,
            max_memory: self.mem.limit(),
            read: self.openscad.into(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    super::print(a.json, &report, print_text)
}

fn print_text(r: &RequirementsReport) {
    outln!("grid {}x{}x{}", r.dims[0], r.dims[1], r.dims[2]);
    outln!(
        "panels: {} of {} touched ({})",
        r.panels_touched,
        r.panels_total,
        r.panel.map_or("whole array".into(), |p| format!(
            "{}x{} pixels",
            p[0], p[1]
        ))
    );
    match r.slabs_with_geometry {
        Some((f, l)) => outln!("slabs with geometry: {f}..={l} of 0..={}", r.dims[2] - 1),
        None => outln!("slabs with geometry: none"),
    }
    outln!(
        "clipping stack: {} levels per slice, {} for the render program",
        r.stack_levels_slice,
        r.stack_levels_render
    );
    outln!(
        "Blist: {} rows, label register {} bits",
        r.blist_rows,
        r.label_bits
    );
    print_words(r);
    print_clocks(r);
}

/// The word asked for and the word the precision needs.
fn print_words(r: &RequirementsReport) {
    outln!(
        "word {}: worst plane-word error {} scene units",
        r.word,
        r.word_error
            .map_or("- (slabs do not fit)".into(), |e| format!("{e:.3e}"))
    );
    match (&r.word_needed, r.word_needed_error) {
        (Some(w), Some(e)) => outln!("word for precision {}: {w}, error {e:.3e}", r.precision),
        _ => outln!("word for precision {}: none up to 62 bits", r.precision),
    }
}

/// The clocks of every frame against the pruned ones.
fn print_clocks(r: &RequirementsReport) {
    let pct = |a: u64, b: u64| 100.0 * a as f64 / b.max(1) as f64;
    outln!(
        "clocks: {} for every solid in every slab, {} for the slabs each meets ({:.1}%); render {}",
        r.cycles_all_frames,
        r.cycles_needed_frames,
        pct(r.cycles_needed_frames, r.cycles_all_frames),
        r.cycles_render
    );
    outln!(
        "simulated pixel-clocks on the array route: {} of {} ({:.1}%)",
        r.simulated_pixel_clocks,
        r.full_pixel_clocks,
        pct(r.simulated_pixel_clocks, r.full_pixel_clocks)
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit is the
    /// machine's, read once by each).
    #[test]
    fn flags_make_the_default_job() {
        let argv = ["csgpix", "requirements", "a.csg"];
        let a = parsed!(Requirements, argv);
        let want = RequirementsJob {
            scene: "a.csg".into(),
            max_memory: a.mem.limit(),
            ..RequirementsJob::default()
        };
        assert_eq!(a.job(), want);
    }
}

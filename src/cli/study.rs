//! `csgpix study`: flags to a [`StudyJob`], run with the charts drawn by plotters
//! ([`super::plot::Plotters`]); its report as one line or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::Model;
use csgpix_run::study::{StudyJob, StudyReport};
use csgpix_run::sweep::Sweep;
use csgpix_voxel::Sampling;

use super::common::{named, MaxMemory, ReadArgs};
use super::plot::Plotters;
use super::progress::Bars;

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
    #[arg(long, value_parser = named::<Model>(), value_delimiter = ',', default_value = "word,float")]
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
    #[arg(long, value_parser = named::<Sampling>(), default_value = "centre")]
    sampling: Sampling,
    #[command(flatten)]
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
    /// Print every point as JSON.
    #[arg(long)]
    json: bool,
}

impl Args {
    fn job(&self) -> StudyJob {
        StudyJob {
            scene: self.scene.clone(),
            out: self.out.clone(),
            sweep: Sweep {
                bits: self.bits.clone(),
                fragments: self.fragments.clone(),
                slabs: self.slabs.clone(),
                models: self.models.clone(),
                res: self.res,
                int_bits: self.int_bits,
                ovf_bits: self.ovf_bits,
                sampling: self.sampling,
            },
            max_memory: Some(self.mem.mib),
            read: self.openscad.into(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run_with_charts(&Plotters, &Bars::default())?;
    super::print(a.json, &report, print_text)
}

fn print_text(r: &StudyReport) {
    let worst = r.points.iter().map(|p| p.diff_ref).max().unwrap_or(0);
    outln!(
        "{}: {}, {} points, at most {worst} voxels differ from the reference; \
         charts beside it; {:.2} s wall",
        r.csv.display(),
        r.scene,
        r.points.len(),
        r.wall_seconds,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit aside: its
    /// default is the memory available when the flags are parsed).
    #[test]
    fn flags_make_the_default_job() {
        let argv = ["csgpix", "study", "s.csg", "-o", "out"];
        let a = parsed!(Study, argv);
        let job = a.job();
        let want = StudyJob {
            scene: "s.csg".into(),
            out: "out".into(),
            max_memory: job.max_memory,
            ..StudyJob::default()
        };
        assert_eq!(job, want);
        assert!(job.max_memory.is_some());
    }
}

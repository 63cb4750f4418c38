//! `csgpix sculpt`: flags to a [`SculptJob`]; its report as two lines or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_run::grid::{parse_res, Resolution};
use csgpix_run::sculpt::{finite, parse_tool, SculptJob, SculptReport};

use super::common::{GridArgs, MaxMemory, ReadArgs};
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix sculpt vectors/scenes/twelve.csg --res 128 --bounds=-15,-15,-15,15,15,15 --tool sphere:4 --path vectors/paths/carve.csv -o carved.stl\n  \
    csgpix sculpt vectors/scenes/twelve.csg --res 256 --bounds=-15,-15,-15,15,15,15 --tool sphere:8 --path vectors/paths/carve.csv --json --forces f.csv -o carved.ply\n  \
    csgpix sculpt part.nrrd --tool sphere:3 --add --path path.csv --stiffness 0.5 -o grown.obj\n\n\
    PATH.csv: columns x,y,z in scene units, one tool centre per row; a header row, blank\n  \
    lines and # comments are allowed. Each row is one haptic step: collision by key lookup,\n  \
    removal (or --add) of every voxel whose centre is inside the sphere, the changed cells'\n  \
    case bytes rewritten and re-meshed, and the spring force F = k·(P_s − P_c), P_s where the\n  \
    contact began (seed 000 §6; docs/sculpting.md).")]
pub struct Args {
    /// A `.csg` scene (voxelized as by `voxelize`) or a `.nrrd` volume: one `voxelize`
    /// wrote, or a dataset with `--threshold`.
    input: PathBuf,
    /// For a `.nrrd` input: a voxel is filled where its sample is at or above this value
    /// (default: where it is not 0).
    #[arg(long, value_parser = finite)]
    threshold: Option<f64>,
    /// Voxels along X, Y, Z for a `.csg` scene: N or NXxNYxNZ (default 128).
    #[arg(long, value_parser = parse_res)]
    res: Option<Resolution>,
    #[command(flatten)]
    grid: GridArgs,
    /// The tool: sphere:R, R in voxels (0 < R <= 128).
    #[arg(long, value_parser = parse_tool)]
    tool: f64,
    /// Add material instead of removing it.
    #[arg(long)]
    add: bool,
    /// Tool positions, CSV x,y,z in scene units.
    #[arg(long)]
    path: PathBuf,
    /// k of F = k·ΔX (force per scene unit).
    #[arg(long, default_value_t = 1.0)]
    stiffness: f64,
    /// Output mesh: .stl (binary), .obj or .ply (binary).
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
    /// Write each step's contact, displacement and force to this CSV.
    #[arg(long)]
    forces: Option<PathBuf>,
    #[command(flatten)]
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
}

impl Args {
    fn job(&self) -> SculptJob {
        SculptJob {
            input: self.input.clone(),
            threshold: self.threshold,
            grid: self.grid.options(self.res),
            tool: self.tool,
            add: self.add,
            path: self.path.clone(),
            stiffness: self.stiffness,
            out: self.out.clone(),
            forces: self.forces.clone(),
            max_memory: Some(self.mem.mib),
            read: self.openscad.into(),
            stdout_taken: self.json,
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    super::print(a.json, &report, |r| print_text(&a, r))
}

fn print_text(a: &Args, r: &SculptReport) {
    let say = |line: String| super::report_line(&line, r.stdout);
    say(format!(
        "{}: {} steps ({} in contact), {} voxels {}, {} cells re-meshed; {} -> {} triangles",
        a.out.display(),
        r.steps,
        r.contact_steps,
        r.voxels_changed,
        if a.add { "added" } else { "removed" },
        r.cells_remeshed,
        r.triangles_before,
        r.triangles_after
    ));
    say(format!(
        "{} open edges; octree {} -> {} nodes (+{} from splits); step median {:.1} us, p99 {:.1} us, max {:.1} us",
        r.open_edges,
        r.nodes_before,
        r.nodes_after,
        r.nodes_added,
        r.latency.median_us,
        r.latency.p99_us,
        r.latency.max_us
    ));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit aside: its
    /// default is the memory available when the flags are parsed).
    #[test]
    fn flags_make_the_default_job() {
        let argv = [
            "csgpix", "sculpt", "s.csg", "--tool", "sphere:3", "--path", "p.csv", "-o", "m.stl",
        ];
        let a = parsed!(Sculpt, argv);
        let job = a.job();
        let want = SculptJob {
            input: "s.csg".into(),
            tool: 3.0,
            path: "p.csv".into(),
            out: "m.stl".into(),
            max_memory: job.max_memory,
            ..SculptJob::default()
        };
        assert_eq!(job, want);
    }
}

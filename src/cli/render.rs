//! `csgpix render`: flags to a [`RenderJob`], its report as one line or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::project::View;
use csgpix_run::render::{RenderJob, RenderReport};
use csgpix_run::voxelize::{parse_panel, PanelArg};

use super::array::ArrayArgs;
use super::common::{named, ReadArgs};
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix render vectors/thesis/cube.dl -o cube.png\n  \
    csgpix render vectors/scenes/cube-minus-cylinder.csg --view iso --shade -o scene.png\n  \
    csgpix render vectors/scenes/twelve.csg --panel 32x32 --json -o twelve.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --model word --json -o boxes.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --clip 'A.!B' -o fig5-1e.png\n  \
    csgpix render vectors/thesis/cube.dl --vcd cube.vcd --probe '120,100;10,10' -o cube.png\n  \
    csgpix render vectors/thesis/cube.dl --probe 120,100 --wave cube.svg --wave-clocks 0..120 -o cube.png")]
pub struct Args {
    /// Display-list files (thesis §5.2), composed by the second stage; or one OpenSCAD `.csg`
    /// file, projected onto the array, its tree evaluated as a clipping function.
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// View direction for a `.csg` scene (the scene's bounds fill the array).
    #[arg(long, value_parser = named::<View>(), default_value = "iso")]
    view: View,
    /// Output PNG (`-`: standard output).
    #[arg(short = 'o', long)]
    out: PathBuf,
    #[command(flatten)]
    array: ArrayArgs,
    /// Clipping function over the objects, named A, B, … in the order given (§5.2.1), e.g.
    /// "A.!B"; each literal is drawn, clipped by the rest of its product and composed.
    #[arg(long)]
    clip: Option<String>,
    /// For a `.csg` scene: draw on panels of NXxNY pixels (§2.5), each running only the solids
    /// whose footprint touches it; panels no solid touches are not simulated. Same image.
    #[arg(long, value_parser = parse_panel)]
    panel: Option<PanelArg>,
    /// Shade by depth (C): nearest drawn depth at full colour, farthest at 45%.
    #[arg(long)]
    shade: bool,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    openscad: ReadArgs,
}

impl Args {
    fn job(&self) -> RenderJob {
        RenderJob {
            scenes: self.scenes.clone(),
            view: self.view,
            out: self.out.clone(),
            array: self.array.options(),
            clip: self.clip.clone(),
            panel: self.panel.as_ref().and_then(|p| p.0),
            shade: self.shade,
            read: self.openscad.into(),
            report_on_stdout: self.json,
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    super::print(a.json, &report, |r| print_line(&a, r))
}

fn print_line(a: &Args, r: &RenderReport) {
    let line = format!(
        "{}: {} objects, {} planes, {} cycles ({:.1} us at 10 MHz), {:.3} s wall",
        a.out.display(),
        r.objects,
        r.planes,
        r.cycles,
        r.hardware_seconds * 1e6,
        r.wall_seconds
    );
    super::report_line(&line, r.to_stdout);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit is the
    /// machine's, read once by each).
    #[test]
    fn flags_make_the_default_job() {
        let argv = ["csgpix", "render", "a.dl", "-o", "a.png"];
        let a = parsed!(Render, argv);
        let mut want = RenderJob {
            scenes: vec!["a.dl".into()],
            out: "a.png".into(),
            ..RenderJob::default()
        };
        want.array.max_memory = a.array.mem.limit();
        assert_eq!(a.job(), want);
    }
}

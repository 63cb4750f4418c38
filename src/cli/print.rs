//! `csgpix print`: flags to a [`PrintJob`]: a printer profile, overridden flag by flag.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_run::printer::{PrintJob, PrintReport, Printer, PROFILES};

use super::common::{MaxMemory, ReadArgs, SweepArgs};
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix print vectors/designs/meshes/hex-driver-handle.csg -o handle.sl1\n  \
    csgpix print part.csg --printer sl1s --aa 4 -o part.sl1s\n  \
    csgpix print part.csg --printer mono-4k --layer-height 0.03 -o layers/   # PNGs + print.json\n  \
    csgpix print part.csg --printer sl1 --position 20,-10 --exposure 6 -o part.sl1\n\n\
Printers: sl1 (Original Prusa SL1), sl1s (SL1S SPEED), mono-4k (6.1-inch 3840x2400),\n\
mono-8k (10-inch 7680x4320). docs/printer.md has their figures.")]
pub struct Args {
    /// OpenSCAD `.csg` or `.scad` scene, in mm.
    scene: PathBuf,
    /// `*.sl1` or `*.sl1s`: Prusa's archive (config.ini, prusaslicer.ini, layer PNGs,
    /// thumbnails); anything else: a directory of `layer-NNNNN.png` with `print.json`.
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// Printer profile (default: sl1s for `*.sl1s`, else sl1).
    #[arg(long, value_parser = printer)]
    printer: Option<Printer>,
    /// Samples per pixel side: a pixel's grey is the share of its AA×AA samples inside
    /// the part (1: inside or not).
    #[arg(long, default_value_t = 1)]
    aa: u32,
    /// Layer height, mm.
    #[arg(long)]
    layer_height: Option<f64>,
    /// First layer's height, mm.
    #[arg(long)]
    initial_layer_height: Option<f64>,
    /// Display size WxH, mm, along the bed's X and Y.
    #[arg(long, value_parser = pair::<f64>)]
    display: Option<[f64; 2]>,
    /// Display pixels NXxNY.
    #[arg(long, value_parser = pair::<u32>)]
    pixels: Option<[u32; 2]>,
    /// `portrait` turns the layer images a quarter turn, `landscape` does not.
    #[arg(long, value_parser = ["portrait", "landscape"])]
    orientation: Option<String>,
    /// Mirror the images: `x`, `y`, `xy` or `none`.
    #[arg(long, value_parser = ["x", "y", "xy", "none"])]
    mirror: Option<String>,
    /// Exposure of the layers after the faded ones, s.
    #[arg(long)]
    exposure: Option<f64>,
    /// Exposure of the first layer, s.
    #[arg(long)]
    initial_exposure: Option<f64>,
    /// The part's centre X,Y, mm from the display's centre (default 0,0: centred).
    #[arg(long, value_parser = pair::<f64>, allow_hyphen_values = true)]
    position: Option<[f64; 2]>,
    #[command(flatten)]
    sweep: SweepArgs,
    #[command(flatten)]
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
}

/// `--printer`: a bundled profile.
fn printer(s: &str) -> Result<Printer, String> {
    Printer::named(s).ok_or_else(|| {
        let names: Vec<&str> = PROFILES.iter().map(|p| &*p.id).collect();
        format!("{s:?}: not a printer; one of {}", names.join(", "))
    })
}

/// `AxB` or `A,B`.
fn pair<T: std::str::FromStr>(s: &str) -> Result<[T; 2], String>
where
    T::Err: std::fmt::Display,
{
    let parts: Vec<&str> = s.split(['x', ',']).collect();
    let [a, b] = parts[..] else {
        return Err(format!("{s:?}: expected two values, AxB or A,B"));
    };
    let n = |v: &str| v.trim().parse::<T>().map_err(|e| format!("{v:?}: {e}"));
    Ok([n(a)?, n(b)?])
}

impl Args {
    /// The profile with every override the flags give: the `--printer`'s, else `sl1s` for an
    /// `*.sl1s` output, else the job's default.
    fn printer(&self) -> Printer {
        let by_ext = self
            .out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("sl1s"));
        let base = if by_ext { "sl1s" } else { "sl1" };
        let mut p = self
            .printer
            .clone()
            .or_else(|| Printer::named(base))
            .unwrap_or(PROFILES[0].clone());
        p.layer_height = self.layer_height.unwrap_or(p.layer_height);
        p.initial_layer_height = self.initial_layer_height.unwrap_or(p.initial_layer_height);
        p.size = self.display.unwrap_or(p.size);
        p.pixels = self.pixels.unwrap_or(p.pixels);
        if let Some(o) = &self.orientation {
            p.portrait = o == "portrait";
        }
        if let Some(m) = &self.mirror {
            p.mirror = [m.contains('x'), m.contains('y')];
        }
        p.exposure = self.exposure.unwrap_or(p.exposure);
        p.initial_exposure = self.initial_exposure.unwrap_or(p.initial_exposure);
        p
    }

    fn job(&self) -> PrintJob {
        PrintJob {
            scene: self.scene.clone(),
            out: self.out.clone(),
            printer: self.printer(),
            aa: self.aa,
            centre: self.position.unwrap_or([0.0, 0.0]),
            threads: self.sweep.threads(),
            max_memory: self.mem.limit(),
            read: self.sweep.reading(self.openscad.into()),
            fallback: self.sweep.fallback,
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    super::print(a.json, &report, print_text)
}

/// The summary line; the reader's warnings were told as the scene was read (`--json` carries
/// them too).
fn print_text(r: &PrintReport) {
    let line = format!(
        "{}: {} layers of {}x{} ({}, part {}x{} pixels, aa {}); {:.2} ml, print {:.0} min; {:.3} s wall",
        r.out.display(),
        r.layers,
        r.image[0],
        r.image[1],
        r.printer,
        r.part_pixels[0],
        r.part_pixels[1],
        r.aa,
        r.material_ml,
        r.print_seconds / 60.0,
        r.wall_seconds
    );
    super::report_line(&line, false);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The required flags alone make the default job (the memory limit aside: its default
    /// is the memory available when the flags are parsed).
    #[test]
    fn flags_make_the_default_job() {
        let argv = ["csgpix", "print", "part.csg", "-o", "part.sl1"];
        let a = parsed!(Print, argv);
        let job = a.job();
        let want = PrintJob {
            scene: "part.csg".into(),
            out: "part.sl1".into(),
            max_memory: job.max_memory,
            ..PrintJob::default()
        };
        assert_eq!(job, want);
    }
}

//! `csgpix export-verilog`: flags to an [`ExportVerilogJob`]; the files written (and how to
//! run `tb_array` on a scene's), or with `--check` those that differ (exit 1).

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_run::array_args::{parse_size, parse_word};
use csgpix_run::export_verilog::{parse_origin, ExportVerilogJob, ExportVerilogReport, SceneFiles};
use rtl_model::verilog::stimulus;
use rtl_model::WordFormat;

use super::common::MaxMemory;
use super::gen_vectors::print_generated;
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Examples:\n  csgpix export-verilog                 # rewrite rtl-model/verilog/\n  \
    csgpix export-verilog -o out/         # write elsewhere\n  \
    csgpix export-verilog --check         # exit 1 if the checked-in files differ\n  \
    csgpix export-verilog --scene vectors/thesis/cube.dl --origin 56,90 -o cube/\n  \
    sh cube/run.sh                        # tb_array on the cube's 16x16 window, Icarus\n  \
    sh cube/run.sh verilator              # the same under Verilator\n  \
    csgpix export-verilog --scene vectors/thesis/box1.dl --scene vectors/thesis/box2.dl \
    --clip 'A.!B' --origin 112,148 -o boxes/"
)]
pub struct Args {
    /// Directory to write (or check) the files in: rtl-model/verilog when not given; with
    /// --scene it must be given.
    #[arg(short = 'o', long)]
    out: Option<PathBuf>,
    /// Only compare with the files in the directory; exit 1 on any difference.
    #[arg(long, conflicts_with = "scene")]
    check: bool,
    /// A display list (thesis §5.2) to run on the array; repeat for more objects (A, B, …);
    /// or one OpenSCAD .csg/.scad scene, projected onto the --size array.
    /// Writes tb_array's stimulus (control.hex), the state it must see after every clock
    /// (expected.hex), the image (expected.png), the Verilog it is built from and run.sh.
    #[arg(long, value_name = "FILE.dl")]
    scene: Vec<PathBuf>,
    /// Clipping function over the objects, as for `render` (§5.2.1), e.g. "A.!B".
    #[arg(long, requires = "scene")]
    clip: Option<String>,
    /// Array size WIDTHxHEIGHT; pixel_array.v and tb_array.v are generated for it.
    #[arg(long, default_value = "16x16", value_parser = parse_size, requires = "scene")]
    size: (usize, usize),
    /// The screen pixel X,Y the array's pixel (0, 0) shows: the window of the scene drawn.
    #[arg(long, default_value = "0,0", value_parser = parse_origin, requires = "scene")]
    origin: (usize, usize),
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (thesis 10/10/11).
    #[arg(long, default_value = "10/10/11", value_parser = parse_word, requires = "scene")]
    word: WordFormat,
    #[command(flatten)]
    mem: MaxMemory,
}

impl Args {
    fn job(&self) -> ExportVerilogJob {
        ExportVerilogJob {
            out: self.out.clone(),
            check: self.check,
            scene: self.scene.clone(),
            clip: self.clip.clone(),
            size: self.size,
            origin: self.origin,
            word: self.word,
            max_memory: self.mem.limit(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    Ok(match a.job().run(&Bars::default())? {
        ExportVerilogReport::Generated(r) => print_generated(&r),
        ExportVerilogReport::Scene(s) => {
            print_scene(&s);
            ExitCode::SUCCESS
        }
    })
}

/// What was written and how to run it: the command lines `run.sh` holds, from the directory.
fn print_scene(s: &SceneFiles) {
    let dir = &s.dir;
    for name in &s.files {
        outln!("wrote {}", dir.join(name).display());
    }
    let mib = s.expected_bytes as f64 / (1 << 20) as f64;
    let (w, h) = s.size;
    outln!(
        "wrote {} ({} clocks x {} pixels, {mib:.1} MiB)",
        dir.join("expected.hex").display(),
        s.clocks,
        w * h
    );
    outln!(
        "wrote {} ({w}x{h}, G after the last clock)",
        dir.join("expected.png").display(),
    );
    let d = shell_word(&dir.display().to_string());
    outln!("run tb_array; it must print \"{}\":", s.summary);
    outln!("  icarus:    cd {d} && {}", stimulus::ICARUS);
    outln!("  verilator: cd {d} && {}", stimulus::VERILATOR);
    outln!("  or:        sh {d}/run.sh [icarus|verilator]   (exit 0 only on that line)");
    outln!("run tb_machine (the controller reads program.hex; every word and register checked):");
    outln!("  icarus:    cd {d} && {}", stimulus::MACHINE_ICARUS);
    outln!("  verilator: cd {d} && {}", stimulus::MACHINE_VERILATOR);
}

/// `s` as one shell word: as it is when it needs no quoting, else in single quotes.
fn shell_word(s: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "/._-+,:@%=".contains(c);
    if !s.is_empty() && s.chars().all(plain) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit is the
    /// machine's, read once by each).
    #[test]
    fn flags_make_the_default_job() {
        let a = parsed!(ExportVerilog, ["csgpix", "export-verilog"]);
        let want = ExportVerilogJob {
            max_memory: a.mem.limit(),
            ..ExportVerilogJob::default()
        };
        assert_eq!(a.job(), want);
    }

    #[test]
    fn a_path_is_quoted_only_when_the_shell_needs_it() {
        assert_eq!(shell_word("out/cube"), "out/cube");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
    }
}

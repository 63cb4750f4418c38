//! The command line of csgpix: clap's flags become a job of the run layer (`csgpix-run`),
//! the job runs with progress bars ([`progress::Bars`]), and its report (data) is printed
//! as text or `--json`. Nothing of a pipeline is assembled here: every command module holds
//! its flags (`Args`), their conversion to the job, and the printing of the report.

/// The `Args` of the command line `argv` (program name included), which must parse as
/// command `$cmd`: for each command's test that its flags' defaults are its job's.
#[cfg(test)]
macro_rules! parsed {
    ($cmd:ident, $argv:expr) => {{
        use clap::Parser;
        match crate::cli::Cli::try_parse_from($argv).unwrap().cmd {
            crate::cli::Cmd::$cmd(a) => a,
            other => panic!("parsed as {other:?}"),
        }
    }};
}

/// `println!` for what a command prints on standard output: a failed write (a reader gone,
/// `| head`; a full disk) is one line on standard error and exit status 2 ([`out_line`]),
/// not a panic.
macro_rules! outln {
    () => {
        $crate::cli::out_line(format_args!(""))
    };
    ($($t:tt)*) => {
        $crate::cli::out_line(format_args!($($t)*))
    };
}

pub mod args_utf8;
mod array;
mod blist;
mod common;
mod completions;
mod export_verilog;
mod gen_vectors;
mod man;
mod phantom;
mod plot;
mod print;
pub mod progress;
mod render;
mod requirements;
mod sculpt;
mod study;
mod throughput;
mod verify_select;
mod voxelize;

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use csgpix_run as run;

#[derive(Parser, Debug)]
#[command(
    name = "csgpix",
    version,
    about = "Cycle-accurate simulator of the 2D CSG pixel-processor array (2005 thesis, Ch. 2)",
    after_help = "Examples:\n  \
        csgpix render vectors/thesis/cube.dl -o cube.png\n  \
        csgpix verify-select --equations printed\n  \
        csgpix gen-vectors --check\n  \
        csgpix completions bash > ~/.local/share/bash-completion/completions/csgpix\n  \
        csgpix man | man -l -"
)]
pub struct Cli {
    #[command(subcommand)]
    pub cmd: Cmd,
    /// Put every output file on the disk (fsync) before it replaces the old one, and its
    /// directory after, so that outputs survive a power cut; without it an output is whole or
    /// absent while the machine runs and the system writes it out in its own time
    #[arg(long, global = true)]
    pub sync: bool,
}

#[derive(Subcommand, Debug)]
pub enum Cmd {
    /// Write the golden select-logic vectors (Espresso PLA) and the derived equations.
    GenVectors(gen_vectors::Args),
    /// Check an equation set against every row of the golden vectors.
    VerifySelect(verify_select::Args),
    /// Write the Verilog twin of SGENE, its testbenches and Yosys scripts (docs/verilog.md).
    ExportVerilog(export_verilog::Args),
    /// Run display lists through the array and write the image.
    Render(render::Args),
    /// Voxelize a CSG scene slice by slice through the array; write a NRRD volume or an OME-Zarr store.
    Voxelize(voxelize::Args),
    /// Carve (or add) with a spherical tool along a path in the hashed octree; write the mesh.
    Sculpt(sculpt::Args),
    /// Compile a CSG expression to its Blist table (§4.3.2); trace one voxel through it.
    Blist(blist::Args),
    /// What a scene needs of the hardware: panels, slabs, word, stack, label, and the clocks.
    Requirements(requirements::Args),
    /// Throughput: eq. 2.3-2.5 and 5.1, Table 2.1, and a scene's frame rate on panels (§2.5).
    Throughput(throughput::Args),
    /// Sweep depth-word bits, tessellation, slabs and model; error against cost as CSV and PNG.
    Study(study::Args),
    /// Slice a CSG scene onto a resin printer's display: Prusa SL1/SL1S archives or PNG layers
    Print(print::Args),
    /// Write the project's CT-head phantom (Figure 5.6's dataset) as NRRD.
    Phantom(phantom::Args),
    /// Print the completion script of a shell (bash, zsh, fish, elvish, powershell).
    Completions(completions::Args),
    /// Print the manual page (roff).
    Man(man::Args),
}

/// Run the command `cli` names: its exit code, or the error that stopped it.
pub fn run(cli: Cli) -> run::Result<ExitCode> {
    csgpix_output::sync_outputs(cli.sync);
    let result = match cli.cmd {
        Cmd::GenVectors(a) => gen_vectors::run(a),
        Cmd::Phantom(a) => phantom::run(a),
        Cmd::VerifySelect(a) => verify_select::run(a),
        Cmd::ExportVerilog(a) => export_verilog::run(a),
        Cmd::Render(a) => render::run(a),
        Cmd::Voxelize(a) => voxelize::run(a),
        Cmd::Print(a) => print::run(a),
        Cmd::Sculpt(a) => sculpt::run(a),
        Cmd::Blist(a) => blist::run(a),
        Cmd::Requirements(a) => requirements::run(a),
        Cmd::Throughput(a) => throughput::run(a),
        Cmd::Study(a) => study::run(a),
        Cmd::Completions(a) => completions::run(a),
        Cmd::Man(a) => man::run(a),
    };
    result.map_err(openscad_timeout)
}

/// openscad killed at its time limit, in any command: the option that sets the limit named
/// after the message (`FILE.scad: openscad did not finish within 300 s (--openscad-timeout)`).
fn openscad_timeout(e: run::Error) -> run::Error {
    match e.scene().map(csgpix_scene::Error::kind) {
        Some(csgpix_scene::Kind::TimedOut) => {
            run::Error::options("--openscad-timeout", format!("{e} (--openscad-timeout)"))
        }
        _ => e,
    }
}

/// A command's closing line: on standard output, or on standard error when an output goes
/// to standard output (`-o -`).
pub fn report_line(line: &str, to_stderr: bool) {
    if to_stderr {
        eprintln!("{line}");
    } else {
        outln!("{line}");
    }
}

/// A report as `--json` prints it (pretty, one object) or as its text lines (`text`).
pub fn print<T: serde::Serialize>(
    json: bool,
    report: &T,
    text: impl FnOnce(&T),
) -> run::Result<ExitCode> {
    if json {
        print_json(report)?;
    } else {
        text(report);
    }
    Ok(ExitCode::SUCCESS)
}

/// A report as `--json` prints it: pretty, one object, streamed (a panel-by-panel report can
/// be hundreds of megabytes of text).
pub fn print_json<T: serde::Serialize>(report: &T) -> run::Result<()> {
    use std::io::Write;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = serde_json::to_writer_pretty(&mut out, report)
        .map_err(std::io::Error::from)
        .and_then(|()| writeln!(out))
        .and_then(|()| out.flush());
    if let Err(e) = written {
        csgpix_output::stdout_failed(&e);
    }
    Ok(())
}

/// One line of a report on standard output (see `outln!`).
pub fn out_line(line: std::fmt::Arguments) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(line).and_then(|()| out.write_all(b"\n")) {
        csgpix_output::stdout_failed(&e);
    }
}

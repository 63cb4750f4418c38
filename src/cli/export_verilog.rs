//! `csgpix export-verilog`: the Verilog twin of SGENE and its checks (docs/verilog.md).

use std::path::PathBuf;
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Examples:\n  csgpix export-verilog                 # rewrite rtl-model/verilog/\n  \
    csgpix export-verilog -o out/         # write elsewhere\n  \
    csgpix export-verilog --check         # exit 1 if the checked-in files differ"
)]
pub struct Args {
    /// Directory to write (or check) the Verilog files and Yosys scripts in.
    #[arg(short = 'o', long, default_value = "rtl-model/verilog")]
    out: PathBuf,
    /// Only compare with the files in the directory; exit 1 on any difference.
    #[arg(long)]
    check: bool,
}

pub fn run(a: Args) -> Result<ExitCode, String> {
    super::write_generated(&rtl_model::verilog::files()?, &a.out, a.check)
}

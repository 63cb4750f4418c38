//! `csgpix export-verilog`: the Verilog twin of SGENE and its checks (docs/verilog.md).

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix::output::write_atomic;

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
    let files = rtl_model::verilog::files()?;
    if !a.check {
        std::fs::create_dir_all(&a.out).map_err(|e| format!("{}: {e}", a.out.display()))?;
    }
    let mut stale = 0;
    for (name, text) in &files {
        let path = a.out.join(name);
        if a.check {
            let old = std::fs::read_to_string(&path).unwrap_or_default();
            if &old != text {
                println!("differs: {}", path.display());
                stale += 1;
            }
        } else {
            write_atomic(&path, |w| w.write_all(text.as_bytes()))?;
            println!("wrote {}", path.display());
        }
    }
    Ok(if stale == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

//! `csgpix gen-vectors`: regenerate `vectors/select/` from the case tables.

use std::path::PathBuf;
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Examples:\n  csgpix gen-vectors            # rewrite vectors/select/\n  \
    csgpix gen-vectors --check    # exit 1 if the checked-in files differ"
)]
pub struct Args {
    /// Directory to write (or check) the PLA files and derived.eqn in.
    #[arg(short = 'o', long, default_value = "vectors/select")]
    out: PathBuf,
    /// Only compare with the files in the directory; exit 1 on any difference.
    #[arg(long)]
    check: bool,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let files = rtl_model::select::vectors::generate()?;
    super::write_generated(&files, &a.out, a.check)
}

//! `csgpix gen-vectors`: regenerate `vectors/select/` from the case tables.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix::output::write_atomic;

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

pub fn run(a: Args) -> Result<ExitCode, String> {
    let files = rtl_model::select::vectors::generate()?;
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

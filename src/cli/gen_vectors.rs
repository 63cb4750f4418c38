//! `csgpix gen-vectors`: flags to a [`GenVectorsJob`]; the files written, or with `--check`
//! those that differ (exit 1).

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_run::gen_vectors::GenVectorsJob;
use csgpix_run::generated::GeneratedReport;

use super::progress::Bars;

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

impl Args {
    fn job(&self) -> GenVectorsJob {
        GenVectorsJob {
            out: self.out.clone(),
            check: self.check,
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    Ok(print_generated(&a.job().run(&Bars::default())?))
}

/// `differs: FILE` for each file a check found different (exit 1 when any), or `wrote FILE`
/// for each file written.
pub fn print_generated(r: &GeneratedReport) -> ExitCode {
    for path in &r.differs {
        outln!("differs: {}", path.display());
    }
    for path in &r.written {
        outln!("wrote {}", path.display());
    }
    if r.differs.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults.
    #[test]
    fn flags_make_the_default_job() {
        let a = parsed!(GenVectors, ["csgpix", "gen-vectors"]);
        assert_eq!(a.job(), GenVectorsJob::default());
    }
}

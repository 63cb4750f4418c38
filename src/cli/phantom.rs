//! `csgpix phantom`: flags to a [`PhantomJob`]; its closing line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use csgpix_run::named::Named;
use csgpix_run::phantom::{PhantomJob, MAX_SIZE};
use csgpix_scene::nrrd::Encoding;

use super::common::MaxMemory;
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix phantom -o vectors/scenes/phantom.nrrd          # the file figure-5.6.csg imports\n  \
    csgpix phantom --size 128 --encoding raw -o head.nrrd")]
pub struct Args {
    /// Samples along each axis (the phantom spans -10..10 scene units whatever the size).
    #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u16).range(1..=i64::from(MAX_SIZE)))]
    size: u16,
    /// Data encoding.
    #[arg(long, value_parser = encoding(), default_value = "gzip")]
    encoding: Encoding,
    /// Output NRRD file (uint16; `-`: standard output).
    #[arg(short = 'o', long)]
    out: PathBuf,
    #[command(flatten)]
    mem: MaxMemory,
}

/// `--encoding`: the names alone, as `--help` has always listed them (no line each).
fn encoding() -> impl TypedValueParser<Value = Encoding> {
    PossibleValuesParser::new(Encoding::VALUES.iter().map(|v| v.1))
        .map(|s| csgpix_run::named::parse::<Encoding>(&s).expect("a possible value"))
}

impl Args {
    fn job(&self) -> PhantomJob {
        PhantomJob {
            size: self.size,
            encoding: self.encoding,
            out: self.out.clone(),
            max_memory: Some(self.mem.mib),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let r = a.job().run(&Bars::default())?;
    let n = r.size;
    let line = format!("wrote {} ({n}x{n}x{n} uint16)", r.out.display());
    super::report_line(&line, r.stdout);
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit aside: its
    /// default is the memory available when the flags are parsed).
    #[test]
    fn flags_make_the_default_job() {
        let argv = ["csgpix", "phantom", "-o", "h.nrrd"];
        let a = parsed!(Phantom, argv);
        let job = a.job();
        let want = PhantomJob {
            out: "h.nrrd".into(),
            max_memory: job.max_memory,
            ..PhantomJob::default()
        };
        assert_eq!(job, want);
    }
}

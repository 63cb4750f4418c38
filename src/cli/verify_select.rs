//! `csgpix verify-select`: flags to a [`VerifySelectJob`], its verdicts as text or `--json`;
//! exit 1 on any mismatch.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_run::verify_select::{VerifySelectJob, VerifySelectReport};
use rtl_model::Equations;

use super::common::named;
use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Exit status: 0 when every care row matches, 1 on any mismatch, 2 on bad input.\n\n\
    Examples:\n  csgpix verify-select\n  csgpix verify-select --equations printed --json"
)]
pub struct Args {
    /// Equation set to check.
    #[arg(long, value_parser = named::<Equations>(), default_value = "derived")]
    equations: Equations,
    /// Read the PLA files from this directory instead of the built-in golden vectors.
    #[arg(long)]
    vectors: Option<PathBuf>,
    /// Print a JSON array of {signal, rows, mismatches}.
    #[arg(long)]
    json: bool,
}

impl Args {
    fn job(&self) -> VerifySelectJob {
        VerifySelectJob {
            equations: self.equations,
            vectors: self.vectors.clone(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    if a.json {
        super::print_json(&report.signals)?;
    } else {
        print_text(&report);
    }
    Ok(if report.mismatches() == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn print_text(report: &VerifySelectReport) {
    outln!("equation set: {}", report.equations.name());
    for r in &report.signals {
        let verdict = if r.mismatches.is_empty() {
            "ok"
        } else {
            "MISMATCH"
        };
        outln!(
            "{:<10} {:>4} rows  {:>3} mismatches  {verdict}",
            r.signal,
            r.rows,
            r.mismatches.len()
        );
        for m in &r.mismatches {
            outln!(
                "    {}  expected {} got {}   [{}]",
                m.inputs,
                m.expected as u8,
                m.got as u8,
                m.case
            );
        }
    }
    let rows: usize = report.signals.iter().map(|r| r.rows).sum();
    outln!(
        "{} signals, {rows} rows checked, {} mismatches",
        report.signals.len(),
        report.mismatches()
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults.
    #[test]
    fn flags_make_the_default_job() {
        let a = parsed!(VerifySelect, ["csgpix", "verify-select"]);
        assert_eq!(a.job(), VerifySelectJob::default());
    }
}

//! `csgpix blist`: flags to a [`BlistJob`], its report as a table or `--json`.

use std::process::ExitCode;

use csgpix_run::blist::{BlistJob, BlistReport};

use super::progress::Bars;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix blist '(A+B)-((C+(D-E)).(F+G))'                   # Figure 4.4: Table 4.1\n  \
    csgpix blist '(A+B)-((C+(D-E)).(F+G))' --trace 0100110   # Table 4.2\n  \
    csgpix blist '(A+B+C)-(D+E)' --json                      # Table 5.1\n  \
    csgpix blist '(cube1+cube2)-(cylinder1+cylinder2)'")]
pub struct Args {
    /// CSG expression over named primitives: `+` union, `.` intersection, `-` difference, `!`
    /// complement, parentheses; `!` binds tightest, then `.`, then `+` and `-`.
    #[arg(allow_hyphen_values = true)]
    expr: String,
    /// Print the table (and trace) as JSON.
    #[arg(long)]
    json: bool,
    /// Classify one voxel: one bit per primitive (1 = inside), in order of first appearance in
    /// EXPR; prints the label after each row and the result.
    #[arg(long, value_name = "BITS")]
    trace: Option<String>,
}

impl Args {
    fn job(&self) -> BlistJob {
        BlistJob {
            expr: self.expr.clone(),
            trace: self.trace.clone(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    if a.json {
        outln!("{}", serde_json::to_string(&report)?);
    } else {
        print_text(&report);
    }
    Ok(ExitCode::SUCCESS)
}

fn print_text(r: &BlistReport) {
    let width = r
        .rows
        .iter()
        .map(|r| r.reference.len())
        .max()
        .unwrap_or(0)
        .max(9);
    let mut head = format!(
        "{:>3}  {:>4}  {:>4}  {:<width$}  {:>5}",
        "p", "name", "sign", "reference", "stamp"
    );
    if r.trace.is_some() {
        head.push_str("  class  label");
    }
    outln!("{head}");
    for (k, b) in r.rows.iter().enumerate() {
        let mut line = format!(
            "{:>3}  {:>4}  {:>4}  {:<width$}  {:>5}",
            b.p, b.name, b.sign, b.reference, b.stamp
        );
        if let (Some(class), Some(labels)) = (b.class, &r.trace) {
            line.push_str(&format!("  {:>5}  {:>5}", u8::from(class), labels[k]));
        }
        outln!("{line}");
    }
    let plural = if r.label_bits == 1 { "" } else { "s" };
    outln!(
        "IN name {}; label register {} bit{plural}",
        r.in_name,
        r.label_bits
    );
    if let Some(inside) = r.inside {
        outln!("{}", if inside { "inside" } else { "outside" });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults.
    #[test]
    fn flags_make_the_default_job() {
        let a = parsed!(Blist, ["csgpix", "blist", "A+B"]);
        let want = BlistJob {
            expr: "A+B".into(),
            ..BlistJob::default()
        };
        assert_eq!(a.job(), want);
    }
}

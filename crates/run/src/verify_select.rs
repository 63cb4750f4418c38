//! `csgpix verify-select`: every equation on every golden vector row.

use std::path::PathBuf;
use std::process::ExitCode;

use rtl_model::select::verify::{verify_table, SignalReport, VectorFile};
use rtl_model::select::{Table, GOLDEN};
use rtl_model::Equations;

use super::EquationsArg;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Exit status: 0 when every care row matches, 1 on any mismatch, 2 on bad input.\n\n\
    Examples:\n  csgpix verify-select\n  csgpix verify-select --equations printed --json"
)]
pub struct Args {
    /// Equation set to check.
    #[arg(long, value_enum, default_value_t)]
    equations: EquationsArg,
    /// Read the PLA files from this directory instead of the built-in golden vectors.
    #[arg(long)]
    vectors: Option<PathBuf>,
    /// Print a JSON array of {signal, rows, mismatches}.
    #[arg(long)]
    json: bool,
}

fn load(dir: &Option<PathBuf>, t: Table, builtin: &str) -> crate::Result<VectorFile> {
    let (name, text) = match dir {
        Some(d) => {
            let p = d.join(format!("{}.pla", t.name()));
            let text = csgpix_scene::input::read_text(&p)?;
            (p.display().to_string(), text)
        }
        None => (
            format!("vectors/select/{}.pla", t.name()),
            builtin.to_string(),
        ),
    };
    let file = VectorFile::parse(name.as_str(), &text);
    file.map_err(|e| {
        csgpix_scene::Error::at(name, e.line, e.col, csgpix_scene::Error::invalid(e.msg)).into()
    })
}

/// Every signal of `eq` checked on every care row of the golden vectors (§2.3.3): the
/// built-in ones, or the `.pla` files of directory `vectors`.
pub fn verify(eq: Equations, vectors: &Option<PathBuf>) -> crate::Result<Vec<SignalReport>> {
    let set = eq.set();
    let mut reports: Vec<SignalReport> = vec![];
    for (t, text) in GOLDEN {
        let file = load(vectors, t, text)?;
        reports.extend(verify_table(&set, t, &file)?);
    }
    Ok(reports)
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let eq: Equations = a.equations.into();
    let reports = verify(eq, &a.vectors)?;
    let bad: usize = reports.iter().map(|r| r.mismatches.len()).sum();
    if a.json {
        println!("{}", serde_json::to_string_pretty(&reports)?);
    } else {
        print_text(eq, &reports);
    }
    Ok(if bad == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn print_text(eq: Equations, reports: &[SignalReport]) {
    println!("equation set: {}", eq.name());
    for r in reports {
        let verdict = if r.mismatches.is_empty() {
            "ok"
        } else {
            "MISMATCH"
        };
        println!(
            "{:<10} {:>4} rows  {:>3} mismatches  {verdict}",
            r.signal,
            r.rows,
            r.mismatches.len()
        );
        for m in &r.mismatches {
            println!(
                "    {}  expected {} got {}   [{}]",
                m.inputs, m.expected as u8, m.got as u8, m.case
            );
        }
    }
    let bad: usize = reports.iter().map(|r| r.mismatches.len()).sum();
    let rows: usize = reports.iter().map(|r| r.rows).sum();
    println!(
        "{} signals, {rows} rows checked, {bad} mismatches",
        reports.len()
    );
}

//! `csgpix blist`: the Blist table of a CSG expression (§4.3.2) and, with `--trace`, one voxel's
//! classification through it (§4.3.3, Table 4.2).

use std::process::ExitCode;

use csgpix_scene::csg_expr::{self, CsgExpr};
use csgpix_voxel::blist::BlistTable;
use serde::Serialize;

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

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let e = csg_expr::parse(&a.expr).map_err(|e| e.in_file("EXPR"))?;
    let table = BlistTable::compile(&e.root);
    let bits = a.trace.as_deref().map(|b| trace_bits(b, &e)).transpose()?;
    let trace = bits.as_ref().map(|bits| {
        let mut labels = vec![];
        let inside = table.classify(|p| bits[p], Some(&mut labels));
        (labels, inside)
    });
    if a.json {
        println!("{}", report_json(&table, &e, trace.as_ref())?);
    } else {
        print_text(&table, &e, bits.as_deref(), trace.as_ref());
    }
    Ok(ExitCode::SUCCESS)
}

/// `--trace` as one classification per primitive.
fn trace_bits(text: &str, e: &CsgExpr) -> crate::Result<Vec<bool>> {
    let bits: Vec<bool> = text
        .chars()
        .enumerate()
        .map(|(i, c)| match c {
            '0' => Ok(false),
            '1' => Ok(true),
            c => Err(csgpix_scene::Error::at(
                "--trace",
                1,
                i + 1,
                format!("expected 0 or 1, found {c:?}"),
            )),
        })
        .collect::<Result<_, _>>()?;
    if bits.len() != e.names.len() {
        let message = format!(
            "expected {} bits, one per primitive ({}), found {}",
            e.names.len(),
            e.names.join(", "),
            bits.len()
        );
        return Err(csgpix_scene::Error::at("--trace", 1, 1, message).into());
    }
    Ok(bits)
}

fn sign(s: bool) -> &'static str {
    if s {
        "+"
    } else {
        "-"
    }
}

/// `--json`'s report. Fields in alphabetical order, as the JSON map of the first versions
/// printed them (`tests/identity.rs`): serde_json keeps insertion order in this build (zarrs
/// turns on its `preserve_order`), so the order is fixed here, by the struct.
#[derive(Serialize)]
struct Report<'a> {
    in_name: u32,
    #[serde(skip_serializing_if = "Option::is_none")]
    inside: Option<bool>,
    label_bits: u32,
    rows: Vec<RowReport<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    trace: Option<&'a [u32]>,
}

/// One row of the table, fields in alphabetical order ([`Report`]).
#[derive(Serialize)]
struct RowReport<'a> {
    name: u32,
    p: usize,
    reference: &'a str,
    sign: &'static str,
    stamp: u32,
}

fn report_json(
    table: &BlistTable,
    e: &CsgExpr,
    trace: Option<&(Vec<u32>, bool)>,
) -> crate::Result<String> {
    let rows = table
        .rows
        .iter()
        .enumerate()
        .map(|(k, r)| RowReport {
            name: r.name,
            p: k + 1,
            reference: &e.names[r.prim],
            sign: sign(r.sign),
            stamp: r.stamp,
        })
        .collect();
    let report = Report {
        in_name: table.in_name,
        inside: trace.map(|t| t.1),
        label_bits: table.label_bits,
        rows,
        trace: trace.map(|t| &t.0[..]),
    };
    Ok(serde_json::to_string(&report)?)
}

fn print_text(
    table: &BlistTable,
    e: &CsgExpr,
    bits: Option<&[bool]>,
    trace: Option<&(Vec<u32>, bool)>,
) {
    let width = e.names.iter().map(String::len).max().unwrap_or(0).max(9);
    let mut head = format!(
        "{:>3}  {:>4}  {:>4}  {:<width$}  {:>5}",
        "p", "name", "sign", "reference", "stamp"
    );
    if trace.is_some() {
        head.push_str("  class  label");
    }
    println!("{head}");
    for (k, r) in table.rows.iter().enumerate() {
        let mut line = format!(
            "{:>3}  {:>4}  {:>4}  {:<width$}  {:>5}",
            k + 1,
            r.name,
            sign(r.sign),
            e.names[r.prim],
            r.stamp
        );
        if let (Some(bits), Some((labels, _))) = (bits, trace) {
            line.push_str(&format!(
                "  {:>5}  {:>5}",
                u8::from(bits[r.prim]),
                labels[k]
            ));
        }
        println!("{line}");
    }
    println!(
        "IN name {}; label register {} bit{}",
        table.in_name,
        table.label_bits,
        if table.label_bits == 1 { "" } else { "s" }
    );
    if let Some((_, inside)) = trace {
        println!("{}", if *inside { "inside" } else { "outside" });
    }
}

//! The select-logic verifier: every equation of a set on every row of the golden vectors.

use serde::Serialize;

use super::pla::{expand, Out, Pla};
use super::sop::Var;
use super::{EquationSet, Signal, Table};

/// One row where an equation disagrees with the vectors.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Mismatch {
    /// Inputs as `NAME=0|1`, in PLA column order.
    pub inputs: String,
    /// The output the vectors require.
    pub expected: bool,
    /// The output the equation gives.
    pub got: bool,
    /// The thesis case row the vector came from (the PLA comment above it).
    pub case: String,
}

/// The verdict on one signal.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SignalReport {
    /// The signal's name, `table.NAME`.
    pub signal: String,
    /// Care rows checked (rows whose expected output is 0 or 1).
    pub rows: usize,
    /// The care rows where the equation disagrees with the vectors.
    pub mismatches: Vec<Mismatch>,
}

/// Why a vector file cannot be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorError(pub String);

impl std::fmt::Display for VectorError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for VectorError {}

/// Check `set` against the PLA of `table`.
pub fn verify_table(
    set: &EquationSet,
    table: Table,
    pla: &Pla,
) -> Result<Vec<SignalReport>, VectorError> {
    let vars: Vec<Var> = pla
        .inputs
        .iter()
        .map(|n| {
            let mut c = n.chars();
            match (c.next().and_then(Var::from_name), c.next()) {
                (Some(v), None) => Ok(v),
                _ => Err(VectorError(format!(
                    "{}.pla: unknown input {n:?}",
                    table.name()
                ))),
            }
        })
        .collect::<Result<_, _>>()?;
    let mut reports = Vec::new();
    for s in table.signals() {
        let j = pla
            .outputs
            .iter()
            .position(|o| o == s.short())
            .ok_or_else(|| VectorError(format!("{}.pla: no output {}", table.name(), s.short())))?;
        reports.push(verify_signal(set, *s, &vars, pla, j));
    }
    Ok(reports)
}

fn verify_signal(set: &EquationSet, s: Signal, vars: &[Var], pla: &Pla, j: usize) -> SignalReport {
    let mut rep = SignalReport {
        signal: s.name().into(),
        rows: 0,
        mismatches: vec![],
    };
    let mut case = String::new();
    for row in &pla.rows {
        if let Some(c) = row.comments.last() {
            case = c.clone();
        }
        let expected = match row.outputs[j] {
            Out::One => true,
            Out::Zero => false,
            Out::DontCare => continue,
        };
        rep.rows += 1;
        // A '-' input in a care row means both values: check each.
        for m in expand(&row.inputs) {
            let mut env = [false; 10];
            for (i, v) in vars.iter().enumerate() {
                env[*v as usize] = m >> i & 1 == 1;
            }
            let got = set.sop(s).eval_bits(&env);
            if got != expected {
                let inputs = vars
                    .iter()
                    .map(|v| format!("{}={}", v.name(), env[*v as usize] as u8))
                    .collect::<Vec<_>>()
                    .join(" ");
                rep.mismatches.push(Mismatch {
                    inputs,
                    expected,
                    got,
                    case: case.clone(),
                });
            }
        }
    }
    rep
}

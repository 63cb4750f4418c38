//! The select-logic verifier: every equation of a set on every row of the golden vectors.

use serde::Serialize;

use super::pla::{expand, Out, Pla, PlaError, Places};
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

/// A golden-vector file as read: its name (as the user gave it), its table and where it names
/// its inputs and outputs, for errors found after parsing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorFile {
    /// The file's name in errors (a path, or `vectors/select/TABLE.pla` for the built-in ones).
    pub name: String,
    /// The table.
    pub pla: Pla,
    /// Where it names its inputs and outputs.
    pub places: Places,
}

impl VectorFile {
    /// Parse `text`, named `name` in errors.
    ///
    /// # Errors
    ///
    /// The parser's, with its line and column (the caller adds the file's name).
    pub fn parse(name: impl Into<String>, text: &str) -> Result<VectorFile, PlaError> {
        let (pla, places) = Pla::parse_with_places(text)?;
        Ok(VectorFile {
            name: name.into(),
            pla,
            places,
        })
    }

    fn error(&self, (line, col): (usize, usize), problem: VectorProblem) -> VectorError {
        let file = self.name.clone();
        VectorError {
            at: Location { file, line, col },
            problem,
        }
    }
}

/// Where in a vector file: `FILE:LINE:COL`, 1-based, the column in characters.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file, as the user named it.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub col: usize,
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // A name with a line break or another control character would break the one line.
        for c in self.file.chars() {
            match c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') {
                true => write!(f, "{}", c.escape_debug())?,
                false => write!(f, "{c}")?,
            }
        }
        write!(f, ":{}:{}", self.line, self.col)
    }
}

/// What makes a vector file unusable for its table, though it parses.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VectorProblem {
    /// An input name that is not one select-logic variable (`L`, `S`, `Y`, `N`, …).
    UnknownInput {
        /// The name, as the file gives it.
        name: String,
    },
    /// An output of the table that the file's `.ob` does not list.
    NoOutput {
        /// The output's name (`S1`, `LL`, …).
        signal: &'static str,
    },
}

/// Why a vector file cannot be used: `FILE:LINE:COL: problem`, at the name at fault (an
/// input's in `.ilb`) or at the list that lacks one (`.ob`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorError {
    /// Where.
    pub at: Location,
    /// What is wrong there.
    pub problem: VectorProblem,
}

impl std::fmt::Display for VectorProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            VectorProblem::UnknownInput { name } => write!(f, "unknown input {name:?}"),
            VectorProblem::NoOutput { signal } => write!(f, "no output {signal}"),
        }
    }
}

impl std::fmt::Display for VectorError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.at, self.problem)
    }
}

impl std::error::Error for VectorError {}

/// Check `set` against the vector file of `table`.
///
/// # Errors
///
/// An input name that is no variable, or an output of the table the file does not list,
/// located in the file.
pub fn verify_table(
    set: &EquationSet,
    table: Table,
    file: &VectorFile,
) -> Result<Vec<SignalReport>, VectorError> {
    let pla = &file.pla;
    let vars: Vec<Var> = pla
        .inputs
        .iter()
        .zip(&file.places.inputs)
        .map(|(name, &at)| {
            let mut c = name.chars();
            match (c.next().and_then(Var::from_name), c.next()) {
                (Some(v), None) => Ok(v),
                _ => Err(file.error(at, VectorProblem::UnknownInput { name: name.clone() })),
            }
        })
        .collect::<Result<_, _>>()?;
    let mut reports = Vec::new();
    for s in table.signals() {
        let j = pla
            .outputs
            .iter()
            .position(|o| o == s.short())
            .ok_or_else(|| {
                let signal = s.short();
                file.error(file.places.outputs, VectorProblem::NoOutput { signal })
            })?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::select::GOLDEN;
    use crate::Equations;

    fn verify(text: &str) -> Result<Vec<SignalReport>, VectorError> {
        let file = VectorFile::parse("dir/second.pla", text).unwrap();
        verify_table(&Equations::Derived.set(), Table::Second, &file)
    }

    #[test]
    fn names_the_logic_does_not_know_are_located_in_the_file() {
        let golden = GOLDEN[4].1;
        assert!(verify(golden).is_ok());
        let e = verify(&golden.replace(".ilb P N J T M", ".ilb P N J\tx0 M")).unwrap_err();
        let problem = VectorProblem::UnknownInput { name: "x0".into() };
        assert_eq!((e.at.line, e.at.col, &e.problem), (7, 12, &problem));
        assert_eq!(e.to_string(), "dir/second.pla:7:12: unknown input \"x0\"");
        let e = verify(&golden.replace(".ob S3 S4", ".ob S4 S")).unwrap_err();
        assert_eq!(e.problem, VectorProblem::NoOutput { signal: "S3" });
        assert_eq!(e.to_string(), "dir/second.pla:8:1: no output S3");
    }

    #[test]
    fn a_file_name_with_control_characters_stays_on_one_line() {
        let text = GOLDEN[4].1.replace(".ob S3 S4", ".ob S3 Q");
        let file = VectorFile::parse("a\nb\u{85}\0.pla", &text).unwrap();
        let e = verify_table(&Equations::Derived.set(), Table::Second, &file).unwrap_err();
        assert_eq!(e.to_string(), "a\\nb\\u{85}\\0.pla:8:1: no output S4");
    }
}

//! The verify-select job: every select equation on every golden vector row (§2.3.3).

use std::path::PathBuf;

use rtl_model::select::verify::{verify_table, SignalReport, VectorFile};
use rtl_model::select::{Table, GOLDEN};
use rtl_model::Equations;
use serde::{Deserialize, Serialize};

use crate::progress::Progress;

/// Check an equation set against the golden vectors. `Default`: the derived equations, the
/// built-in vectors.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct VerifySelectJob {
    /// The equation set to check (`--equations`).
    #[serde(with = "crate::named::by_name")]
    pub equations: Equations,
    /// A directory of PLA files to read instead of the built-in golden vectors (`--vectors`).
    pub vectors: Option<PathBuf>,
}

/// The verdict on every signal (`--json` prints `signals`, an array).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VerifySelectReport {
    /// The equation set checked.
    #[serde(skip)]
    pub equations: Equations,
    /// One verdict per signal, table by table.
    pub signals: Vec<SignalReport>,
}

impl VerifySelectReport {
    /// The care rows where an equation disagrees, over all signals.
    pub fn mismatches(&self) -> usize {
        self.signals.iter().map(|r| r.mismatches.len()).sum()
    }
}

impl VerifySelectJob {
    /// The memory plan: the vectors are a few kilobytes; nothing grows.
    pub fn estimate(&self) -> crate::Result<u64> {
        Ok(0)
    }

    /// Check every signal.
    pub fn run(&self, _: &dyn Progress) -> crate::Result<VerifySelectReport> {
        Ok(VerifySelectReport {
            equations: self.equations,
            signals: verify(self.equations, &self.vectors)?,
        })
    }
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
        let problem = csgpix_scene::Error::Pla { reason: e.msg };
        csgpix_scene::Error::at(name, e.line, e.col, problem).into()
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

//! The Blist job: the Blist table of a CSG expression (§4.3.2) and, with a trace, one
//! voxel's classification through it (§4.3.3, Table 4.2).

use csgpix_scene::csg_expr::{self, CsgExpr};
use csgpix_voxel::blist::BlistTable;
use serde::{Deserialize, Serialize};

use crate::progress::Progress;

/// Compile `expr` to its Blist table; with `trace`, classify one voxel through it.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct BlistJob {
    /// CSG expression over named primitives: `+` union, `.` intersection, `-` difference,
    /// `!` complement, parentheses.
    pub expr: String,
    /// One bit per primitive (1 = inside), in order of first appearance in `expr`.
    pub trace: Option<String>,
}

/// The table (and trace). Fields in alphabetical order, as the JSON map of the first
/// versions printed them (`tests/identity.rs`): serde_json keeps insertion order in this
/// build (zarrs turns on its `preserve_order`), so the order is fixed here, by the struct.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BlistReport {
    /// The name a voxel inside the whole expression ends with.
    pub in_name: u32,
    /// With a trace: whether the voxel is inside.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inside: Option<bool>,
    /// Bits of the label register.
    pub label_bits: u32,
    /// The table's rows, in order.
    pub rows: Vec<BlistRow>,
    /// With a trace: the label after each row.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trace: Option<Vec<u32>>,
}

/// One row of the table, fields in alphabetical order ([`BlistReport`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BlistRow {
    /// The row's name (label).
    pub name: u32,
    /// The row's position, 1-based.
    pub p: usize,
    /// The primitive it tests, by name.
    pub reference: String,
    /// `+` or `-`.
    pub sign: &'static str,
    /// The stamp written when it decides.
    pub stamp: u32,
    /// With a trace: whether the voxel is inside the row's primitive (text only).
    #[serde(skip)]
    pub class: Option<bool>,
}

impl BlistJob {
    /// The memory plan: the table is a few bytes a primitive, allocated from the expression
    /// the user typed; nothing to bound.
    pub fn estimate(&self) -> crate::Result<u64> {
        Ok(0)
    }

    /// Compile, and trace when asked.
    pub fn run(&self, _: &dyn Progress) -> crate::Result<BlistReport> {
        let e = csg_expr::parse(&self.expr).map_err(|e| e.in_file("EXPR"))?;
        let table = BlistTable::compile(&e.root);
        let bits = self
            .trace
            .as_deref()
            .map(|b| trace_bits(b, &e))
            .transpose()?;
        let trace = bits.as_ref().map(|bits| {
            let mut labels = vec![];
            let inside = table.classify(|p| bits[p], Some(&mut labels));
            (labels, inside)
        });
        let rows = table
            .rows
            .iter()
            .enumerate()
            .map(|(k, r)| BlistRow {
                name: r.name,
                p: k + 1,
                reference: e.names[r.prim].clone(),
                sign: if r.sign { "+" } else { "-" },
                stamp: r.stamp,
                class: bits.as_ref().map(|b| b[r.prim]),
            })
            .collect();
        Ok(BlistReport {
            in_name: table.in_name,
            inside: trace.as_ref().map(|t| t.1),
            label_bits: table.label_bits,
            rows,
            trace: trace.map(|t| t.0),
        })
    }
}

/// The trace as one classification per primitive.
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
                csgpix_scene::Error::Expected {
                    expected: "0 or 1".into(),
                    found: format!("{c:?}"),
                },
            )),
        })
        .collect::<Result<_, _>>()?;
    if bits.len() != e.names.len() {
        let message = csgpix_scene::Error::Expected {
            expected: format!(
                "{} bits, one per primitive ({})",
                e.names.len(),
                e.names.join(", ")
            ),
            found: bits.len().to_string(),
        };
        return Err(csgpix_scene::Error::at("--trace", 1, 1, message).into());
    }
    Ok(bits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress::Quiet;

    /// Figure 4.4's expression traced with Table 4.2's voxel: inside, as the table says.
    #[test]
    fn figure_4_4_traced() {
        let job = BlistJob {
            expr: "(A+B)-((C+(D-E)).(F+G))".into(),
            trace: Some("0100110".into()),
        };
        let r = job.run(&Quiet).unwrap();
        assert_eq!(r.rows.len(), 7);
        assert_eq!(r.trace.as_ref().map(Vec::len), Some(7));
        assert_eq!(r.rows[1].class, Some(true));
        assert_eq!(r.inside, Some(r.trace.unwrap()[6] == r.in_name));
    }

    #[test]
    fn a_trace_of_the_wrong_length_is_refused_at_its_place() {
        let job = BlistJob {
            expr: "A+B".into(),
            trace: Some("1".into()),
        };
        let e = job.run(&Quiet).unwrap_err().to_string();
        assert!(e.starts_with("--trace:1:1: expected 2 bits"), "{e}");
    }
}

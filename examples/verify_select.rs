//! Verify the select logic (SGENE, §2.3.3-2.3.5) against the golden vectors: both equation
//! sets, the derived one and the thesis's printed one, on every care row of every table.
//!
//! `cargo run --release --example verify_select`

use rtl_model::select::verify::{verify_table, VectorFile};
use rtl_model::select::GOLDEN;
use rtl_model::Equations;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    for eq in [Equations::Derived, Equations::Printed] {
        let set = eq.set();
        let (mut rows, mut bad) = (0, 0);
        for (table, text) in GOLDEN {
            let file = VectorFile::parse(format!("vectors/select/{}.pla", table.name()), text)?;
            for report in verify_table(&set, table, &file)? {
                rows += report.rows;
                bad += report.mismatches.len();
            }
        }
        println!("{eq:?} equations: {bad} of {rows} care rows mismatch");
    }
    Ok(())
}

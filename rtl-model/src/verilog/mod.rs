//! A Verilog-2005 twin of the select logic (SGENE, seed 001 §2.3.3-2.3.5), written from the
//! same equation sets the Rust models evaluate, the bit-serial comparator, one pixel processor
//! and an array of them with DEPGEN's adder trees (§2.4, [`depgen`]) driven by a per-clock
//! control stream ([`pixel`]), and the files that check them; [`stimulus`] is what the array's
//! testbench runs and must see for a program (`csgpix export-verilog --scene`).
//!
//! [`files`] is everything `csgpix export-verilog` writes (checked in under
//! `rtl-model/verilog/`); docs/verilog.md says how each file is used.

pub mod check;
pub mod comparator;
pub mod controller;
pub mod depgen;
pub mod pixel;
pub mod sgene;
pub mod stimulus;

use crate::select::pla::Pla;
use crate::select::{Equations, Table, GOLDEN};

/// The golden vectors, parsed.
pub fn golden() -> Result<Vec<(Table, Pla)>, GoldenError> {
    GOLDEN
        .iter()
        .map(|&(table, text)| {
            Pla::parse(text)
                .map(|p| (table, p))
                .map_err(|error| GoldenError { table, error })
        })
        .collect()
}

/// A golden vector file that does not parse: `vectors/select/TABLE.pla:LINE:COL: message`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GoldenError {
    /// The table whose file it is.
    pub table: Table,
    /// The parser's error, with its line and column.
    pub error: crate::select::pla::PlaError,
}

impl std::fmt::Display for GoldenError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "vectors/select/{}.pla:{}", self.table.name(), self.error)
    }
}

impl std::error::Error for GoldenError {}

/// The Yosys cost script: generic gates, then 4- and 6-input LUTs, for each set's SGENE and
/// for the whole pixel; generic gates and LUT4s for the comparator and for one DEPGEN tree.
fn cost_script() -> String {
    let mut v = String::from(
        "# Cost of SGENE (generic cells, LUT4, LUT6) and of the comparator (generic, LUT4).\n\
         # Run in this directory: yosys -s cost.ys (the figures are in docs/verilog.md)\n",
    );
    for eq in [Equations::Derived, Equations::Printed] {
        let m = format!("sgene_{}", eq.name());
        for (label, flow) in [
            ("generic", format!("synth -top {m}")),
            ("lut4", format!("synth -top {m} -lut 4")),
            ("lut6", format!("synth -top {m}\nabc -lut 6\nopt_clean")),
        ] {
            v +=
                &format!("design -reset\nread_verilog {m}.v\n{flow}\nlog COST {m} {label}\nstat\n");
        }
    }
    v += "design -reset\nread_verilog comparator.v\nsynth -top comparator\nlog COST comparator generic\nstat\n";
    v += "design -reset\nread_verilog comparator.v\nsynth -top comparator -lut 4\nlog COST comparator lut4\nstat\n";
    let px = "design -reset\nread_verilog pixel.v comparator.v sgene_derived.v\n";
    v += &format!("{px}synth -top pixel -flatten\nlog COST pixel generic\nstat\n");
    v += &format!("{px}synth -top pixel -flatten -lut 4\nlog COST pixel lut4\nstat\n");
    v += &format!(
        "{px}synth -top pixel -flatten\nabc -lut 6\nopt_clean\nlog COST pixel lut6\nstat\n"
    );
    // One DEPGEN tree of the 16×16 array (16 lines, 4 levels); an array has two.
    let dg = "design -reset\nread_verilog depgen.v\nchparam -set N 16 -set LEVELS 4 depgen\n";
    v += &format!("{dg}synth -top depgen\nlog COST depgen generic\nstat\n");
    v += &format!("{dg}synth -top depgen -lut 4\nlog COST depgen lut4\nstat\n");
    v
}

/// Bits, LSB first, as hex digits, most significant first.
pub(crate) fn hex(bits: &[bool]) -> String {
    (0..bits.len().div_ceil(4))
        .rev()
        .map(|d| {
            let v = (0..4)
                .filter(|b| bits.get(d * 4 + b) == Some(&true))
                .fold(0, |a, b| a | 1 << b);
            char::from_digit(v, 16).unwrap()
        })
        .collect()
}

/// The synthesizable sources of `pixel_array`, leaves first, one a line: a filelist for
/// `verilator -f`, `iverilog -c` and synthesis scripts.
pub fn filelist() -> String {
    let srcs = [
        "sgene_derived.v",
        "comparator.v",
        "depgen.v",
        "pixel.v",
        "pixel_array.v",
    ];
    srcs.iter().map(|f| format!("{f}\n")).collect()
}

/// Every generated file, `(name, text)`, in a fixed order.
pub fn files() -> Result<Vec<(String, String)>, GoldenError> {
    let golden = golden()?;
    let mut out = vec![("select_spec.v".to_string(), check::spec_modules(&golden))];
    for eq in [Equations::Derived, Equations::Printed] {
        let set = eq.set();
        let n = eq.name();
        out.push((format!("sgene_{n}.v"), sgene::module(&set)));
        out.push((format!("tb_sgene_{n}.v"), check::testbench(n, &golden)));
        out.push((format!("miter_{n}.v"), check::miters(n, &golden)));
        let verify = eq == Equations::Derived;
        out.push((
            format!("equiv_{n}.ys"),
            check::equiv_script(n, &golden, verify),
        ));
    }
    let fmt = crate::WordFormat::default();
    out.push(("comparator.v".to_string(), comparator::module(&fmt)));
    out.push((
        "tb_comparator.v".to_string(),
        comparator::testbench(&fmt, 2000),
    ));
    let cfg = crate::ArrayConfig::new(16, 16);
    let derived = Equations::Derived.set();
    out.push(("pixel.v".to_string(), pixel::pixel_module(&cfg, &derived)));
    out.push(("depgen.v".to_string(), depgen::module()));
    out.push(("pixel_array.v".to_string(), pixel::array_module(&cfg)));
    out.push(("tb_array.v".to_string(), pixel::testbench(&cfg)));
    out.push(("pixel_array.f".to_string(), filelist()));
    out.push(("controller.v".to_string(), controller::module(&cfg)));
    out.push((
        "machine.v".to_string(),
        controller::machine_module(&cfg, controller::ADDR_BITS),
    ));
    out.push((
        "tb_machine.v".to_string(),
        controller::testbench(&cfg, controller::ADDR_BITS),
    ));
    out.push(("machine.f".to_string(), controller::filelist()));
    out.push(("panel.v".to_string(), controller::panel_module(&cfg)));
    out.push(("tb_panel.v".to_string(), controller::panel_testbench(&cfg)));
    out.push(("cost.ys".to_string(), cost_script()));
    Ok(out)
}

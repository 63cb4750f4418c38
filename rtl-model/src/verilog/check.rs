//! What the Verilog SGENE is checked against: the golden vectors (`vectors/select/*.pla`),
//! written as Verilog. Nothing here reads an equation set: the expected values come only from
//! the PLA rows, so a testbench or a miter can fail.
//!
//! * [`spec_modules`]: one module per table, `care_O`/`val_O` per output, from the rows.
//! * [`testbench`]: applies every care row to `sgene_SET` and counts mismatches per signal.
//! * [`miters`]: per table, `ok_O = ~care_O | (sgene == val_O)`, for Yosys `sat -prove`.
//! * [`equiv_script`]: the Yosys script proving (or refuting, with every counterexample) each
//!   signal of a set against the care set.

use crate::select::pla::{expand, Out, Pla};
use crate::select::{Signal, Table};

use super::sgene::port;

/// The Verilog inputs of a table, in PLA column order: `L, S, Y, N, J, T, M`.
fn inputs(t: Table) -> Vec<String> {
    t.inputs().iter().map(|v| v.name().to_string()).collect()
}

/// A row's input pattern as a `casez` label: `7'b01?0011` (input 0 is the leftmost bit).
fn pattern(row: &[Option<bool>]) -> String {
    let bits: String = row
        .iter()
        .map(|b| match b {
            Some(true) => '1',
            Some(false) => '0',
            None => '?',
        })
        .collect();
    format!("{}'b{bits}", row.len())
}

/// `spec_TABLE`: for each output O, `care_O` (the row gives 0 or 1) and `val_O`.
fn spec_module(t: Table, pla: &Pla) -> String {
    let ins = inputs(t);
    let outs: Vec<String> = pla
        .outputs
        .iter()
        .flat_map(|o| [format!("care_{o}"), format!("val_{o}")])
        .collect();
    let mut v = format!(
        "// {}.pla as a function: care_O = 1 on a care row, val_O its expected value.\n",
        t.name()
    );
    v += &format!(
        "module spec_{}(\n    input wire {},\n    output reg {}\n);\n",
        t.name(),
        ins.join(", "),
        outs.join(", ")
    );
    v += "    always @* begin\n";
    v += &format!("        {{{}}} = {}'b0;\n", outs.join(", "), outs.len());
    v += &format!("        casez ({{{}}})\n", ins.join(", "));
    for row in &pla.rows {
        let sets: Vec<String> = pla
            .outputs
            .iter()
            .zip(&row.outputs)
            .filter(|(_, o)| **o != Out::DontCare)
            .map(|(name, o)| format!("care_{name} = 1'b1; val_{name} = {};", bit(*o)))
            .collect();
        if !sets.is_empty() {
            v += &format!(
                "            {}: begin {} end\n",
                pattern(&row.inputs),
                sets.join(" ")
            );
        }
    }
    v += "            default: ;\n        endcase\n    end\nendmodule\n";
    v
}

fn bit(o: Out) -> &'static str {
    match o {
        Out::One => "1'b1",
        _ => "1'b0",
    }
}

/// Every table's spec module, one file.
pub fn spec_modules(golden: &[(Table, Pla)]) -> String {
    let mut v = String::from(
        "// The golden select vectors (vectors/select/*.pla, seed 001 §2.3.3-2.3.5) as Verilog.\n\n",
    );
    for (t, pla) in golden {
        v += &spec_module(*t, pla);
        v += "\n";
    }
    v
}

/// The statements applying one minterm and checking every care output of its row.
fn bench_row(t: Table, pla: &Pla, m: u32, outs: &[Out]) -> String {
    let vars = t.inputs();
    let assign: Vec<String> = vars
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{} = 1'b{};", v.name(), m >> i & 1))
        .collect();
    let shown: Vec<String> = vars
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{}={}", v.name(), m >> i & 1))
        .collect();
    let mut v = format!("        clear; {}\n        #1;\n", assign.join(" "));
    for (name, o) in pla.outputs.iter().zip(outs) {
        let Some(s) = t.signals().iter().find(|s| s.short() == name) else {
            continue;
        };
        if *o == Out::DontCare {
            continue;
        }
        let k = Signal::ALL.iter().position(|g| g == s).unwrap();
        v += &format!(
            "        rows[{k}] = rows[{k}] + 1;\n        if ({p} !== {e}) begin bad[{k}] = bad[{k}] + 1; \
             $display(\"MISMATCH {n} {shown} expected {x} got %b\", {p}); end\n",
            p = port(*s),
            e = bit(*o),
            n = s.name(),
            shown = shown.join(" "),
            x = u8::from(*o == Out::One),
        );
    }
    v
}

/// `tb_sgene_SET`: every care row of every table through `sgene_SET`, then one line per
/// signal, `SIGNAL name rows R mismatches B`, and `TOTAL`.
pub fn testbench(set: &str, golden: &[(Table, Pla)]) -> String {
    let vars = "L, S, H, Y, X, P, N, J, T, M";
    let outs: Vec<String> = Signal::ALL.iter().map(|s| port(*s)).collect();
    let mut v = format!(
        "// Applies every care row of vectors/select/*.pla to sgene_{set}; generated, do not edit.\n\
         module tb_sgene_{set};\n    reg {vars};\n    wire {};\n    \
         integer rows [0:8];\n    integer bad [0:8];\n    integer k, total;\n",
        outs.join(", ")
    );
    let conns: Vec<String> = vars
        .split(", ")
        .map(String::from)
        .chain(outs.iter().cloned())
        .map(|p| format!(".{p}({p})"))
        .collect();
    v += &format!("    sgene_{set} dut({});\n", conns.join(", "));
    v += &format!("    task clear; begin {{{vars}}} = 10'b0; end endtask\n");
    v += "    initial begin\n        for (k = 0; k < 9; k = k + 1) begin rows[k] = 0; bad[k] = 0; end\n";
    for (t, pla) in golden {
        for row in pla
            .rows
            .iter()
            .filter(|r| r.outputs.iter().any(|o| *o != Out::DontCare))
        {
            for m in expand(&row.inputs) {
                v += &bench_row(*t, pla, m, &row.outputs);
            }
        }
    }
    v += "        total = 0;\n";
    for (k, s) in Signal::ALL.iter().enumerate() {
        v += &format!(
            "        $display(\"SIGNAL {} rows %0d mismatches %0d\", rows[{k}], bad[{k}]); total = total + bad[{k}];\n",
            s.name()
        );
    }
    v += "        $display(\"TOTAL mismatches %0d\", total);\n        $finish;\n    end\nendmodule\n";
    v
}

/// `miter_SET_TABLE`: the table's inputs drive `sgene_SET` (other externals 0) and
/// `spec_TABLE`; `ok_O` is 1 unless O is a care output that SGENE gets wrong.
fn miter(set: &str, t: Table, pla: &Pla) -> String {
    let ins = inputs(t);
    let oks: Vec<String> = pla.outputs.iter().map(|o| format!("ok_{o}")).collect();
    let mut v = format!(
        "module miter_{set}_{}(\n    input wire {},\n    output wire {}\n);\n",
        t.name(),
        ins.join(", "),
        oks.join(", ")
    );
    let mut conns: Vec<String> = crate::select::sop::Var::ALL
        .iter()
        .map(|var| {
            let n = var.name().to_string();
            let drive = if ins.contains(&n) {
                n.clone()
            } else {
                "1'b0".into()
            };
            format!(".{n}({drive})")
        })
        .collect();
    for s in t.signals() {
        v += &format!("    wire {};\n", port(*s));
        conns.push(format!(".{p}({p})", p = port(*s)));
    }
    v += &format!("    sgene_{set} dut({});\n", conns.join(", "));
    for o in &pla.outputs {
        v += &format!("    wire care_{o}, val_{o};\n");
    }
    let spec: Vec<String> = ins
        .iter()
        .map(|n| format!(".{n}({n})"))
        .chain(
            pla.outputs
                .iter()
                .flat_map(|o| [format!(".care_{o}(care_{o})"), format!(".val_{o}(val_{o})")]),
        )
        .collect();
    v += &format!("    spec_{} spec({});\n", t.name(), spec.join(", "));
    for s in t.signals() {
        let o = s.short();
        v += &format!(
            "    assign ok_{o} = ~care_{o} | ({} == val_{o});\n",
            port(*s)
        );
    }
    v += "endmodule\n";
    v
}

/// Every table's miter against `sgene_SET`, one file.
pub fn miters(set: &str, golden: &[(Table, Pla)]) -> String {
    let mut v =
        format!("// sgene_{set} against the golden vectors' care set; generated, do not edit.\n\n");
    for (t, pla) in golden {
        v += &miter(set, *t, pla);
        v += "\n";
    }
    v
}

/// The Yosys script: for each signal, `sat -prove ok_O 1` (exits non-zero on the first
/// failure when `verify`); otherwise `sat -set ok_O 0 -all` lists every failing input.
pub fn equiv_script(set: &str, golden: &[(Table, Pla)], verify: bool) -> String {
    let mut v = format!(
        "# Equivalence of sgene_{set} with the golden vectors' care set.\n\
         # Run in this directory: yosys -q -s equiv_{set}.ys\n\
         read_verilog sgene_{set}.v select_spec.v miter_{set}.v\n"
    );
    for (t, pla) in golden {
        v += &format!(
            "design -push-copy\nhierarchy -top miter_{set}_{t}\nproc -norom\nflatten\nopt_clean\n",
            t = t.name()
        );
        for o in &pla.outputs {
            v += &format!("log CHECK {}.{o}\n", t.name());
            if verify {
                v += &format!("sat -prove ok_{o} 1 -verify\n");
            } else {
                v += &format!("sat -set ok_{o} 0 -all -show-inputs\n");
            }
        }
        v += "design -pop\n";
    }
    v
}

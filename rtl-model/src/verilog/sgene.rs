//! SGENE as a Verilog module, written from an [`EquationSet`] (§2.3.3-2.3.5).
//!
//! Every signal is the same two-level sum of products the Rust models evaluate
//! ([`Sop::eval`]): one `assign` per signal, an OR of AND terms, complemented when the thesis
//! prints the primed name. No equation is re-derived here, so the module and the models cannot
//! drift apart.

use crate::select::sop::{Cube, Sop, Var};
use crate::select::{EquationSet, Signal};

/// The Verilog port name of a signal: `front.S1` → `front_S1`.
pub fn port(s: Signal) -> String {
    s.name().replace('.', "_")
}

/// The Verilog module name of the SGENE built from `set`.
pub fn module_name(set: &EquationSet) -> String {
    format!("sgene_{}", set.name)
}

/// One product term: `L & ~S & N`; the empty term is `1'b1`.
fn term(c: &Cube) -> String {
    let lits: Vec<String> = Var::ALL
        .iter()
        .filter(|v| c.care & v.bit() != 0)
        .map(|v| {
            let neg = if c.value & v.bit() != 0 { "" } else { "~" };
            format!("{neg}{}", v.name())
        })
        .collect();
    if lits.is_empty() {
        "1'b1".into()
    } else {
        lits.join(" & ")
    }
}

/// The right-hand side of one `assign`: the OR of the terms, complemented when primed.
pub fn expr(sop: &Sop) -> String {
    let sum = if sop.cubes.is_empty() {
        "1'b0".to_string()
    } else {
        sop.cubes
            .iter()
            .map(|c| format!("({})", term(c)))
            .collect::<Vec<_>>()
            .join(" | ")
    };
    if sop.primed {
        format!("~({sum})")
    } else {
        sum
    }
}

/// The whole module: inputs L S H Y X P N J T M, one output per [`Signal`].
pub fn module(set: &EquationSet) -> String {
    let ins: Vec<String> = Var::ALL.iter().map(|v| v.name().to_string()).collect();
    let outs: Vec<String> = Signal::ALL.iter().map(|s| port(*s)).collect();
    let mut v = String::new();
    v += &format!(
        "// SGENE, the select logic of seed 001 §2.3.3-2.3.5, `{}` equation set.\n",
        set.name
    );
    v += "// Externals L S H Y X P (§2.3.2), comparator flags N J T M (§2.4.2).\n";
    v += &format!(
        "module {}(\n    input wire {},\n    output wire {}\n);\n",
        module_name(set),
        ins.join(", "),
        outs.join(", ")
    );
    for s in Signal::ALL {
        let sop = set.sop(s);
        let prime = if sop.primed { "'" } else { "" };
        v += &format!("    // {}{prime} = {}\n", s.name(), sop.to_text());
        v += &format!("    assign {} = {};\n", port(s), expr(sop));
    }
    v += "endmodule\n";
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terms_keep_polarity_and_constants() {
        let sop = |t: &str, primed| Sop {
            cubes: crate::select::sop::parse_sop(t, &[]).unwrap(),
            primed,
        };
        assert_eq!(expr(&sop("L'SN", false)), "(~L & S & N)");
        assert_eq!(expr(&sop("P' + J", true)), "~((~P) | (J))");
        assert_eq!(expr(&sop("1", false)), "(1'b1)");
        assert_eq!(
            expr(&Sop {
                cubes: vec![],
                primed: false
            }),
            "1'b0"
        );
    }
}

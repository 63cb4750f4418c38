//! SGENE: the select logic of §2.3.3-2.3.5 and its golden vectors.
//!
//! The behavioural case tables ([`cases`]) are the specification. [`vectors`] turns them into
//! Espresso PLA truth tables over the reachable comparator flags; [`qm`] minimizes those into
//! the `derived` equation set; the `printed` set is the thesis text, parsed as written. Both
//! sets are [`EquationSet`]s, evaluated by the same code on 64 pixels at a time, and both
//! models of the array use whichever set they are given.

pub mod cases;
pub mod pla;
pub mod qm;
pub mod sop;
pub mod vectors;
pub mod verify;

use sop::{parse_sop, Cube, Sop, Var};

/// One truth table, one PLA file: which signals it defines and over which inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Table {
    /// Stage position 1, front or perpendicular plane: S1, S2 (Sel1).
    Front,
    /// Stage position 2, back plane: S1, S2 (Sel2).
    Back,
    /// Stage position 3, B against F: S1, S2 (same TRANSD code as Sel1).
    Close,
    /// Clipping plane: LL (§2.3.4).
    Clip,
    /// Stage position 4, F against C: S3, S4 (§2.3.5).
    Second,
}

impl Table {
    /// Every table, in PLA file order.
    pub const ALL: [Table; 5] = [
        Table::Front,
        Table::Back,
        Table::Close,
        Table::Clip,
        Table::Second,
    ];

    /// Short name, also the PLA file stem.
    pub fn name(self) -> &'static str {
        match self {
            Table::Front => "front",
            Table::Back => "back",
            Table::Close => "close",
            Table::Clip => "clip",
            Table::Second => "second",
        }
    }

    /// The externals this table depends on; the internals N J T M follow them.
    pub fn externals(self) -> &'static [Var] {
        match self {
            Table::Front => &[Var::L, Var::S, Var::Y],
            Table::Back => &[Var::L, Var::S],
            Table::Close => &[Var::L],
            Table::Clip => &[Var::H, Var::Y, Var::X],
            Table::Second => &[Var::P],
        }
    }

    /// All inputs in PLA column order.
    pub fn inputs(self) -> Vec<Var> {
        let mut v = self.externals().to_vec();
        v.extend([Var::N, Var::J, Var::T, Var::M]);
        v
    }

    /// The signals (PLA outputs) of this table.
    pub fn signals(self) -> &'static [Signal] {
        match self {
            Table::Front => &[Signal::FrontS1, Signal::FrontS2],
            Table::Back => &[Signal::BackS1, Signal::BackS2],
            Table::Close => &[Signal::CloseS1, Signal::CloseS2],
            Table::Clip => &[Signal::LL],
            Table::Second => &[Signal::S3, Signal::S4],
        }
    }
}

/// One select signal of SGENE.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Signal {
    /// S1 of a front or perpendicular plane, stage position 1 (§2.3.3).
    FrontS1,
    /// S2 of a front or perpendicular plane, stage position 1 (§2.3.3).
    FrontS2,
    /// S1 of a back plane, stage position 2 (§2.3.3).
    BackS1,
    /// S2 of a back plane, stage position 2 (§2.3.3).
    BackS2,
    /// S1 when closing the object, stage position 3 (B against F).
    CloseS1,
    /// S2 when closing the object, stage position 3 (B against F).
    CloseS2,
    /// LL, the partial inside/outside answer of a clipping plane (§2.3.4).
    LL,
    /// S3 of the second stage, stage position 4 (§2.3.5).
    S3,
    /// S4 of the second stage, stage position 4 (§2.3.5).
    S4,
}

impl Signal {
    /// Every signal, in equation-file order (also the index into an [`EquationSet`]).
    pub const ALL: [Signal; 9] = [
        Signal::FrontS1,
        Signal::FrontS2,
        Signal::BackS1,
        Signal::BackS2,
        Signal::CloseS1,
        Signal::CloseS2,
        Signal::LL,
        Signal::S3,
        Signal::S4,
    ];

    /// `table.NAME`, as in the equation files and the verifier's report.
    pub fn name(self) -> &'static str {
        match self {
            Signal::FrontS1 => "front.S1",
            Signal::FrontS2 => "front.S2",
            Signal::BackS1 => "back.S1",
            Signal::BackS2 => "back.S2",
            Signal::CloseS1 => "close.S1",
            Signal::CloseS2 => "close.S2",
            Signal::LL => "clip.LL",
            Signal::S3 => "second.S3",
            Signal::S4 => "second.S4",
        }
    }

    /// The PLA output name (the part after the dot).
    pub fn short(self) -> &'static str {
        &self.name()[self.name().find('.').unwrap() + 1..]
    }

    /// The signal named `table.NAME` (as [`Signal::name`] spells it), if any.
    pub fn from_name(s: &str) -> Option<Signal> {
        Signal::ALL.into_iter().find(|g| g.name() == s)
    }

    /// The table (PLA file) that specifies this signal.
    pub fn table(self) -> Table {
        *Table::ALL
            .iter()
            .find(|t| t.signals().contains(&self))
            .unwrap()
    }
}

/// Which equations SGENE is built from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Equations {
    /// Minimized from the golden vectors (the default).
    #[default]
    Derived,
    /// Exactly the thesis text, faults included.
    Printed,
}

impl Equations {
    /// `derived` or `printed`, as on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Equations::Derived => "derived",
            Equations::Printed => "printed",
        }
    }

    /// The equation set.
    pub fn set(self) -> EquationSet {
        match self {
            Equations::Derived => EquationSet::derived(),
            Equations::Printed => EquationSet::printed(),
        }
    }
}

/// A full set of SGENE equations, one [`Sop`] per [`Signal`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EquationSet {
    /// Name of the set (`derived`, `printed`, or the name given to [`EquationSet::parse`]).
    pub name: String,
    sops: Vec<Sop>,
}

/// An equation file that could not be read, with 1-based line and column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EquationError {
    /// 1-based line of the error (0 when no line is at fault, e.g. a missing equation).
    pub line: usize,
    /// 1-based column of the error (0 when no line is at fault).
    pub col: usize,
    /// What is wrong.
    pub msg: String,
}

impl std::fmt::Display for EquationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.col, self.msg)
    }
}

impl std::error::Error for EquationError {}

/// The thesis text of the select equations, as printed (§2.3.3-2.3.5).
pub const PRINTED_TEXT: &str = include_str!("printed.eqn");

/// The equations minimized from the golden vectors by `csgpix gen-vectors`.
pub const DERIVED_TEXT: &str = include_str!("../../vectors/select/derived.eqn");

/// Undefined letters in the printed text and what they are read as (docs/select-logic.md).
pub const PRINTED_ALIASES: &[(char, Var)] = &[('K', Var::N)];

impl EquationSet {
    /// Exactly the thesis text. It has no equation for stage position 3 (closing the object),
    /// so those two signals come from the derived set.
    pub fn printed() -> EquationSet {
        let mut set = parse_partial(PRINTED_TEXT, PRINTED_ALIASES).expect("printed.eqn parses");
        let derived = EquationSet::derived();
        for s in [Signal::CloseS1, Signal::CloseS2] {
            set[s as usize].get_or_insert_with(|| derived.sop(s).clone());
        }
        EquationSet::complete("printed", set).expect("printed set complete")
    }

    /// The set minimized from the vectors and checked in as `vectors/select/derived.eqn`.
    pub fn derived() -> EquationSet {
        EquationSet::parse("derived", DERIVED_TEXT).expect("derived.eqn parses")
    }

    /// Parse an equation file: lines `table.NAME = SOP` or `table.NAME' = SOP`, `#` comments.
    pub fn parse(name: &str, text: &str) -> Result<EquationSet, EquationError> {
        let set = parse_partial(text, &[])?;
        EquationSet::complete(name, set)
    }

    fn complete(name: &str, set: [Option<Sop>; 9]) -> Result<EquationSet, EquationError> {
        let mut sops = Vec::new();
        for (i, s) in set.into_iter().enumerate() {
            sops.push(s.ok_or_else(|| EquationError {
                line: 0,
                col: 0,
                msg: format!("no equation for {}", Signal::ALL[i].name()),
            })?);
        }
        Ok(EquationSet {
            name: name.into(),
            sops,
        })
    }

    /// Build from minimized cubes (positive polarity), one list per signal.
    pub fn from_cubes(name: &str, cubes: Vec<Vec<Cube>>) -> EquationSet {
        let sops = cubes
            .into_iter()
            .map(|cubes| Sop {
                cubes,
                primed: false,
            })
            .collect();
        EquationSet {
            name: name.into(),
            sops,
        }
    }

    /// The equation of signal `s`.
    pub fn sop(&self, s: Signal) -> &Sop {
        &self.sops[s as usize]
    }

    /// The file text, one equation a line in [`Signal::ALL`] order, after `header` comments.
    pub fn to_text(&self, header: &[String]) -> String {
        let mut out: String = header.iter().map(|h| format!("# {h}\n")).collect();
        for s in Signal::ALL {
            let sop = self.sop(s);
            let prime = if sop.primed { "'" } else { "" };
            out += &format!("{}{} = {}\n", s.name(), prime, sop.to_text());
        }
        out
    }
}

fn parse_partial(text: &str, alias: &[(char, Var)]) -> Result<[Option<Sop>; 9], EquationError> {
    let mut set: [Option<Sop>; 9] = Default::default();
    for (i, line) in text.lines().enumerate() {
        let err = |col: usize, msg: String| EquationError {
            line: i + 1,
            col,
            msg,
        };
        let body = line.trim_start();
        if body.is_empty() || body.starts_with('#') {
            continue;
        }
        let eq = line
            .find('=')
            .ok_or_else(|| err(1, "expected NAME = SOP".into()))?;
        let lhs = line[..eq].trim();
        let (lhs, primed) = match lhs.strip_suffix('\'') {
            Some(l) => (l, true),
            None => (lhs, false),
        };
        let sig = Signal::from_name(lhs)
            .ok_or_else(|| err(1, format!("expected a signal name, found {lhs:?}")))?;
        let cubes = parse_sop(&line[eq + 1..], alias)
            .map_err(|e| err(line[..eq + 1].chars().count() + e.col, e.msg))?;
        if set[sig as usize].is_some() {
            return Err(err(1, format!("{} defined twice", sig.name())));
        }
        set[sig as usize] = Some(Sop { cubes, primed });
    }
    Ok(set)
}

/// The checked-in golden vectors, `vectors/select/*.pla`, as built into the binary. The files
/// live in this crate (`rtl-model/vectors/select`, where `vectors/select` links to), so that
/// the crate builds from its published package; there is one copy.
pub const GOLDEN: [(Table, &str); 5] = [
    (Table::Front, include_str!("../../vectors/select/front.pla")),
    (Table::Back, include_str!("../../vectors/select/back.pla")),
    (Table::Close, include_str!("../../vectors/select/close.pla")),
    (Table::Clip, include_str!("../../vectors/select/clip.pla")),
    (
        Table::Second,
        include_str!("../../vectors/select/second.pla"),
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printed_text_parses_and_keeps_every_thesis_term() {
        let p = EquationSet::printed();
        // Term counts as printed in §2.3.3-2.3.5.
        assert_eq!(p.sop(Signal::FrontS1).cubes.len(), 5);
        assert_eq!(p.sop(Signal::FrontS2).cubes.len(), 7);
        assert_eq!(p.sop(Signal::BackS1).cubes.len(), 4);
        assert_eq!(p.sop(Signal::BackS2).cubes.len(), 3);
        assert_eq!(p.sop(Signal::LL).cubes.len(), 9);
        assert_eq!(p.sop(Signal::S3).to_text(), "J'P'".replace("J'P'", "P'J'"));
        assert!(p.sop(Signal::FrontS1).primed && !p.sop(Signal::LL).primed);
    }

    #[test]
    fn equation_file_errors_name_line_and_column() {
        let e = EquationSet::parse("t", "# c\nfront.S1 = L Q\n").unwrap_err();
        assert_eq!((e.line, e.col), (2, 14));
        let e = EquationSet::parse("t", "bogus = L\n").unwrap_err();
        assert_eq!(e.line, 1);
        let e = EquationSet::parse("t", "front.S1 = L\n").unwrap_err();
        assert!(e.msg.contains("no equation for front.S2"));
    }
}

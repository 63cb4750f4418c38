//! Golden vectors: the case tables of [`super::cases`] as Espresso PLA truth tables.
//!
//! Which flag combinations can occur is found, not assumed: the register contents that the
//! case tables can ever produce are computed as a fixed point (start from the reset word, apply
//! every action to every candidate word), then every pair (A-side word, register word) is
//! streamed through the bit-serial comparator ([`compare_serial`]) to get its N, J, T, M.
//! Flag combinations no pair produces are don't-care rows; ties the thesis leaves to the user
//! are don't-care outputs; everything else is a care row. Two flag-identical pairs that the
//! tables treat differently would be a contradiction and stop the generator.

use std::collections::{BTreeMap, BTreeSet};

use super::cases::{self, Action, Compose, Verdict};
use super::pla::{Out, Pla, Row};
use super::qm::minimize;
use super::sop::Cube;
use super::{EquationSet, Signal, Table};
use crate::comparator::compare_serial;
use crate::depth_word::WordFormat;

/// The words a register can hold, found by applying the case tables until nothing new appears.
#[derive(Clone, Debug)]
pub struct Reachable {
    /// The depth word format the words belong to.
    pub fmt: WordFormat,
    /// Candidate words on the A side (anything DEPGEN can deliver).
    pub words: Vec<i64>,
    /// Words F can hold: from the Put-1 reset word, by front planes, stage 3 and clipping.
    pub f: BTreeSet<i64>,
    /// Words B can hold: from the Put-1 reset word, by back planes.
    pub b: BTreeSet<i64>,
    /// Words C can hold: from the Put-1 reset word, by the second stage composing F.
    pub c: BTreeSet<i64>,
}

fn bools(n: usize) -> impl Iterator<Item = Vec<bool>> {
    (0..1u32 << n).map(move |m| (0..n).map(|i| m >> (n - 1 - i) & 1 == 1).collect())
}

fn apply(act: Action, fmt: &WordFormat, a: i64, r: i64) -> i64 {
    match act {
        Action::PutA => a,
        Action::Put0 => 0,
        Action::Keep => r,
        Action::Put1 => fmt.max_word(),
    }
}

fn choices<T: Copy>(v: Verdict<T>) -> Vec<T> {
    std::iter::once(v.choices.0).chain(v.choices.1).collect()
}

/// Close `start` under `step(word, reg) -> new words`, for every candidate word.
fn fixpoint(words: &[i64], start: i64, step: impl Fn(i64, i64) -> Vec<i64>) -> BTreeSet<i64> {
    let mut set = BTreeSet::from([start]);
    let mut todo = vec![start];
    while let Some(r) = todo.pop() {
        for &a in words {
            for v in step(a, r) {
                if set.insert(v) {
                    todo.push(v);
                }
            }
        }
    }
    set
}

impl Reachable {
    /// Reachable register contents for `fmt`, drawing A-side words from `words`.
    pub fn compute(fmt: WordFormat, words: Vec<i64>) -> Reachable {
        let front_step = |a: i64, r: i64| {
            let mut out = vec![];
            for e in bools(3) {
                let ext = cases::FrontExt {
                    l: e[0],
                    s: e[1],
                    y: e[2],
                };
                for act in choices(cases::front(&fmt, ext, a, r)) {
                    out.push(apply(act, &fmt, a, r));
                }
            }
            // Stage 3 and the clipping result only keep F or put 1.
            out.push(fmt.max_word());
            out
        };
        let back_step = |a: i64, r: i64| {
            let mut out = vec![];
            for e in bools(2) {
                let ext = cases::BackExt { l: e[0], s: e[1] };
                for act in choices(cases::back(&fmt, ext, a, r)) {
                    out.push(apply(act, &fmt, a, r));
                }
            }
            out
        };
        let f = fixpoint(&words, fmt.max_word(), front_step);
        let b = fixpoint(&words, fmt.max_word(), back_step);
        let f_words: Vec<i64> = f.iter().copied().collect();
        let c = fixpoint(&f_words, fmt.max_word(), |fv, c| {
            [true, false]
                .into_iter()
                .flat_map(|p| choices(cases::second(p, fv, c)))
                .map(|act| match act {
                    Compose::Put1 => fmt.max_word(),
                    Compose::PutF => fv,
                    Compose::KeepC => c,
                })
                .collect()
        });
        Reachable {
            fmt,
            words,
            f,
            b,
            c,
        }
    }

    /// Every word of a small format: the exhaustive check.
    pub fn exhaustive(fmt: WordFormat) -> Reachable {
        Reachable::compute(fmt, (fmt.min_word()..=fmt.max_word()).collect())
    }

    /// Boundary words of a (large) format: negative extremes, 0, around maxdepth, the top.
    pub fn boundary(fmt: WordFormat) -> Reachable {
        let md = fmt.maxdepth();
        let (lo, hi) = (fmt.min_word(), fmt.max_word());
        let mut w = vec![
            lo,
            lo + 1,
            -md - 1,
            -md,
            -2,
            -1,
            0,
            1,
            2,
            md / 2,
            md - 2,
            md - 1,
        ];
        w.extend([md, md + 1, 2 * md, hi - 2, hi - 1, hi]);
        w.sort();
        w.dedup();
        Reachable::compute(fmt, w)
    }

    /// The (A-side, register) pairs a table sees.
    fn pairs(&self, t: Table) -> Vec<(i64, i64)> {
        let (a_side, reg): (Vec<i64>, &BTreeSet<i64>) = match t {
            Table::Front | Table::Clip => (self.words.clone(), &self.f),
            Table::Back => (self.words.clone(), &self.b),
            Table::Close => (self.b.iter().copied().collect(), &self.f),
            Table::Second => (self.f.iter().copied().collect(), &self.c),
        };
        a_side
            .iter()
            .flat_map(|&a| reg.iter().map(move |&r| (a, r)))
            .collect()
    }
}

/// A table's specified rows: minterm (bit i = input i of [`Table::inputs`]) to outputs and the
/// thesis row that gave them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TruthTable {
    /// The table (PLA file) these rows specify.
    pub table: Table,
    /// Minterm to (one output per signal of the table, the deciding thesis row).
    pub rows: BTreeMap<u32, (Vec<Out>, &'static str)>,
}

fn action_outs(v: Verdict<Action>) -> Vec<Out> {
    let code = |a: Action| [a.code().0, a.code().1];
    let first = code(v.choices.0);
    let other = v.choices.1.map(code).unwrap_or(first);
    (0..2).map(|i| out_of(first[i], other[i])).collect()
}

fn out_of(a: bool, b: bool) -> Out {
    match (a, b) {
        (true, true) => Out::One,
        (false, false) => Out::Zero,
        _ => Out::DontCare,
    }
}

fn verdict_outs(
    t: Table,
    fmt: &WordFormat,
    ext: &[bool],
    a: i64,
    r: i64,
) -> (Vec<Out>, &'static str) {
    match t {
        Table::Front => {
            let e = cases::FrontExt {
                l: ext[0],
                s: ext[1],
                y: ext[2],
            };
            let v = cases::front(fmt, e, a, r);
            (action_outs(v), v.row)
        }
        Table::Back => {
            let v = cases::back(
                fmt,
                cases::BackExt {
                    l: ext[0],
                    s: ext[1],
                },
                a,
                r,
            );
            (action_outs(v), v.row)
        }
        Table::Close => {
            let v = cases::close(ext[0], a, r);
            (action_outs(v), v.row)
        }
        Table::Clip => {
            let e = cases::ClipExt {
                h: ext[0],
                y: ext[1],
                x: ext[2],
            };
            let v = cases::clip(fmt, e, a, r);
            let ll = v.choices.0;
            (vec![out_of(ll, v.choices.1.unwrap_or(ll))], v.row)
        }
        Table::Second => {
            let v = cases::second(ext[0], a, r);
            let outs = match v.choices.0 {
                Compose::Put1 => vec![Out::Zero, Out::Zero],
                Compose::PutF => vec![Out::Zero, Out::One],
                Compose::KeepC => vec![Out::One, Out::DontCare],
            };
            (outs, v.row)
        }
    }
}

/// Two register pairs of a table give the same flags but different outputs
/// ([`TruthTable::build`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TableConflict {
    /// The table.
    pub table: Table,
    /// The flags (inputs) both give, bit i = input i.
    pub flags: u32,
    /// The outputs first found for them and why.
    pub first: (Vec<Out>, &'static str),
    /// The other outputs and why.
    pub second: (Vec<Out>, &'static str),
    /// The register values (A, R) of the second.
    pub pair: (i64, i64),
}

impl std::fmt::Display for TableConflict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (a, reg) = self.pair;
        write!(
            f,
            "{}: flags {:#b} give {:?} ({}) and {:?} ({}) (A={a}, R={reg})",
            self.table.name(),
            self.flags,
            self.first.0,
            self.first.1,
            self.second.0,
            self.second.1
        )
    }
}

impl std::error::Error for TableConflict {}

impl TruthTable {
    /// Build a table from the reachable pairs of one or more formats.
    pub fn build(t: Table, reach: &[Reachable]) -> Result<TruthTable, TableConflict> {
        let ne = t.externals().len();
        let mut rows: BTreeMap<u32, (Vec<Out>, &'static str)> = BTreeMap::new();
        for r in reach {
            let pairs = r.pairs(t);
            for ext in bools(ne) {
                for &(a, reg) in &pairs {
                    let fl = compare_serial(&r.fmt, a, reg);
                    let mut m = 0u32;
                    for (i, b) in ext.iter().chain(&[fl.n, fl.j, fl.t, fl.m]).enumerate() {
                        m |= (*b as u32) << i;
                    }
                    let spec = verdict_outs(t, &r.fmt, &ext, a, reg);
                    if let Some(old) = rows.get(&m) {
                        if old.0 != spec.0 {
                            return Err(TableConflict {
                                table: t,
                                flags: m,
                                first: old.clone(),
                                second: spec,
                                pair: (a, reg),
                            });
                        }
                    } else {
                        rows.insert(m, spec);
                    }
                }
            }
        }
        Ok(TruthTable { table: t, rows })
    }

    /// The table as a PLA file: every minterm, unreachable ones with don't-care outputs.
    pub fn to_pla(&self) -> Pla {
        let inputs = self.table.inputs();
        let n = inputs.len();
        let n_out = self.table.signals().len();
        let unreachable = "unreachable: no pair of register values gives these flags";
        let mut rows = Vec::new();
        let mut last = "";
        let (mut care, mut ties) = (0, 0);
        for bits in bools(n) {
            let m = bits
                .iter()
                .enumerate()
                .fold(0u32, |m, (i, b)| m | (*b as u32) << i);
            let (outs, why) = match self.rows.get(&m) {
                Some((o, why)) => (o.clone(), *why),
                None => (vec![Out::DontCare; n_out], unreachable),
            };
            if why != unreachable {
                care += 1;
                ties += outs.contains(&Out::DontCare) as usize;
            }
            let comments = if why != last {
                vec![why.to_string()]
            } else {
                vec![]
            };
            last = why;
            rows.push(Row {
                comments,
                inputs: bits.into_iter().map(Some).collect(),
                outputs: outs,
            });
        }
        Pla {
            header: self.header(care, ties, (1 << n) - care),
            inputs: inputs.iter().map(|v| v.name().to_string()).collect(),
            outputs: self
                .table
                .signals()
                .iter()
                .map(|s| s.short().to_string())
                .collect(),
            rows,
            trailer: vec![],
        }
    }

    fn header(&self, care: usize, ties: usize, unreachable: usize) -> Vec<String> {
        let what = match self.table {
            Table::Front => "front/perpendicular plane, Sel1 (§2.3.3): 00 Put A, 10 Put 0, 01 Keep F, 11 Put 1",
            Table::Back => "back plane, Sel2 (§2.3.3): 00 Put A, 01 Keep B, 11 Put 1",
            Table::Close => "closing the object, stage position 3, B against F (§2.3.3, §2.4): 01 Keep F, 11 Put 1",
            Table::Clip => "clipping plane, partial inside/outside answer LL (§2.3.4)",
            Table::Second => "second stage, F against C (§2.3.5): 00 Put 1, 01 Put F, 1- Keep C",
        };
        vec![
            format!("csgpix golden vectors: {what}"),
            "generated by `csgpix gen-vectors` from rtl-model/src/select/cases.rs; do not edit".into(),
            "inputs: externals, then N J T M from the bit-serial comparator".into(),
            format!("{care} reachable rows ({ties} with a tie left to the user: '-' outputs), {unreachable} unreachable rows (all '-')"),
        ]
    }

    /// On-set and don't-care set of output `j`, for the minimizer.
    pub fn sets(&self, j: usize) -> (Vec<u32>, Vec<u32>) {
        let n = self.table.inputs().len();
        let (mut on, mut dc) = (vec![], vec![]);
        for m in 0..1u32 << n {
            match self.rows.get(&m).map(|r| r.0[j]) {
                Some(Out::One) => on.push(m),
                Some(Out::Zero) => {}
                Some(Out::DontCare) | None => dc.push(m),
            }
        }
        (on, dc)
    }
}

/// The reachable sets the generator uses: the small format 1/2/2 exhaustively and the thesis
/// format on its boundary words.
pub fn standard_reach() -> Vec<Reachable> {
    vec![
        Reachable::exhaustive(WordFormat::new(1, 2, 2).unwrap()),
        Reachable::boundary(WordFormat::THESIS),
    ]
}

/// Every table, built from [`standard_reach`].
pub fn all_tables() -> Result<Vec<TruthTable>, TableConflict> {
    let reach = standard_reach();
    Table::ALL
        .iter()
        .map(|&t| TruthTable::build(t, &reach))
        .collect()
}

/// Map a cube over a table's inputs (bit i = input i) to one over [`Var`] bits.
fn to_vars(t: Table, c: Cube) -> Cube {
    let mut out = Cube { care: 0, value: 0 };
    for (i, v) in t.inputs().into_iter().enumerate() {
        if c.care >> i & 1 == 1 {
            out.care |= v.bit();
            out.value |= (c.value >> i & 1) * v.bit();
        }
    }
    out
}

/// Minimize every signal of every table: the `derived` equation set.
pub fn derive(tables: &[TruthTable]) -> EquationSet {
    let mut cubes = Vec::new();
    for s in Signal::ALL {
        let tt = tables.iter().find(|t| t.table == s.table()).expect("table");
        let j = s.table().signals().iter().position(|x| *x == s).unwrap();
        let (on, dc) = tt.sets(j);
        let n = s.table().inputs().len();
        cubes.push(
            minimize(n, &on, &dc)
                .into_iter()
                .map(|c| to_vars(s.table(), c))
                .collect(),
        );
    }
    EquationSet::from_cubes("derived", cubes)
}

/// How the derived equations settle the ties §2.3.3 leaves "up to the user" (A = F on front
/// planes, A = B on back planes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Ties {
    /// Whatever the minimum cover does with the don't-cares (the checked-in `derived.eqn`).
    #[default]
    Minimal,
    /// Keep the register (and colour): the earlier plane wins.
    Keep,
    /// Put A (and D): the later plane wins.
    Put,
}

/// The derived equations with the user's ties fixed: the tie rows become care rows with the
/// chosen action's code and the tables are minimized again.
pub fn derive_with_ties(ties: Ties) -> Result<EquationSet, TableConflict> {
    let mut tables = all_tables()?;
    let code = match ties {
        Ties::Minimal => return Ok(EquationSet::derived()),
        Ties::Keep => Action::Keep.code(),
        Ties::Put => Action::PutA.code(),
    };
    for t in tables
        .iter_mut()
        .filter(|t| matches!(t.table, Table::Front | Table::Back))
    {
        for (outs, why) in t.rows.values_mut() {
            if why.ends_with("(user)") {
                *outs = vec![out_of(code.0, code.0), out_of(code.1, code.1)];
            }
        }
    }
    let mut set = derive(&tables);
    set.name = format!(
        "derived, ties {}",
        if ties == Ties::Keep { "keep" } else { "put" }
    );
    Ok(set)
}

/// The files `gen-vectors` writes, as (file name, text).
pub fn generate() -> Result<Vec<(String, String)>, TableConflict> {
    let tables = all_tables()?;
    let mut files: Vec<(String, String)> = tables
        .iter()
        .map(|t| (format!("{}.pla", t.table.name()), t.to_pla().to_text()))
        .collect();
    let header = [
        "The `derived` select equations: Quine-McCluskey minimum covers of vectors/select/*.pla"
            .to_string(),
        "(don't-care rows used freely). Generated by `csgpix gen-vectors`; do not edit."
            .to_string(),
    ];
    files.push(("derived.eqn".into(), derive(&tables).to_text(&header)));
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn register_contents_are_what_the_thesis_implies() {
        let r = Reachable::exhaustive(WordFormat::new(1, 2, 2).unwrap());
        let md = r.fmt.maxdepth();
        let f_expect: BTreeSet<i64> = (0..md).chain([r.fmt.max_word()]).collect();
        assert_eq!(r.f, f_expect, "F holds [0, maxdepth) or the Put-1 word");
        assert_eq!(r.c, f_expect, "C holds what F held");
        let b_expect: BTreeSet<i64> = (0..=r.fmt.max_word()).collect();
        assert_eq!(
            r.b, b_expect,
            "a first back plane puts any non-negative Z into B"
        );
    }

    #[test]
    fn small_exhaustive_and_thesis_boundary_give_the_same_tables() {
        let small = [Reachable::exhaustive(WordFormat::new(1, 2, 2).unwrap())];
        let big = [Reachable::boundary(WordFormat::THESIS)];
        for t in Table::ALL {
            let a = TruthTable::build(t, &small).unwrap();
            let b = TruthTable::build(t, &big).unwrap();
            let strip = |x: &TruthTable| -> Vec<(u32, Vec<Out>)> {
                x.rows.iter().map(|(m, r)| (*m, r.0.clone())).collect()
            };
            assert_eq!(strip(&a), strip(&b), "table {}", t.name());
        }
    }

    #[test]
    fn front_table_has_seven_reachable_flag_combinations_per_external() {
        let tables = all_tables().unwrap();
        let front = &tables[0];
        // A anything, F in [0, maxdepth) or the Put-1 word: N=1 forces J=1 T=0 M=0;
        // N=0 M=0 and N=0 M=1 each allow (J,T) in {00, 10, 11}.
        assert_eq!(front.rows.len(), 8 * 7);
    }

    #[test]
    fn tie_policies_decide_the_tie_rows_and_nothing_else() {
        let tables = all_tables().unwrap();
        for (ties, want) in [(Ties::Keep, Action::Keep), (Ties::Put, Action::PutA)] {
            let set = derive_with_ties(ties).unwrap();
            for tt in tables
                .iter()
                .filter(|t| matches!(t.table, Table::Front | Table::Back))
            {
                let sig = tt.table.signals();
                let mut ties_seen = 0;
                for (m, (outs, why)) in &tt.rows {
                    let mut vars = [false; 10];
                    for (i, v) in tt.table.inputs().into_iter().enumerate() {
                        vars[v as usize] = m >> i & 1 == 1;
                    }
                    let got = (
                        set.sop(sig[0]).eval_bits(&vars),
                        set.sop(sig[1]).eval_bits(&vars),
                    );
                    if why.ends_with("(user)") {
                        ties_seen += 1;
                        assert_eq!(Action::from_code(got.0, got.1), want, "{why}");
                    } else {
                        let code = [got.0, got.1];
                        for j in 0..2 {
                            assert!(
                                outs[j] == Out::DontCare || (outs[j] == Out::One) == code[j],
                                "{why}"
                            );
                        }
                    }
                }
                assert!(ties_seen > 0, "{}", tt.table.name());
            }
        }
    }

    #[test]
    fn derived_equations_reproduce_every_care_row() {
        let tables = all_tables().unwrap();
        let set = derive(&tables);
        for tt in &tables {
            for (m, (outs, why)) in &tt.rows {
                let mut vars = [false; 10];
                for (i, v) in tt.table.inputs().into_iter().enumerate() {
                    vars[v as usize] = m >> i & 1 == 1;
                }
                for (j, s) in tt.table.signals().iter().enumerate() {
                    let got = set.sop(*s).eval_bits(&vars);
                    match outs[j] {
                        Out::One => assert!(got, "{} row {m:b} ({why})", s.name()),
                        Out::Zero => assert!(!got, "{} row {m:b} ({why})", s.name()),
                        Out::DontCare => {}
                    }
                }
            }
        }
    }
}

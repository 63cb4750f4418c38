//! Berkeley Espresso PLA files (`.type fd`) for the select-logic truth tables.
//!
//! A PLA file lists a multi-output truth table as rows of input and output characters:
//!
//! ```text
//! # header comment
//! .i 3
//! .o 1
//! .ilb L S Y
//! .ob S1
//! .type fd
//! .p 2
//! 1-0 1
//! 011 -
//! .e
//! ```
//!
//! Input characters are `0`, `1` and `-` (either value); output characters are `0`, `1` and
//! `-` (don't care), with `~` read as `0` and `2` as `-`. [`Pla::to_text`] writes one
//! canonical form, byte for byte; [`Pla::parse`] reads that and the usual variations, and
//! names the line and column of anything it refuses. Columns count characters, from 1.

use std::fmt;

/// One output entry of a row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Out {
    /// `0` (also read from `~`).
    Zero,
    /// `1`.
    One,
    /// `-` (also read from `2`).
    DontCare,
}

/// One row of the table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// Text of the `#` comment lines just before the row, without the leading `"# "`.
    pub comments: Vec<String>,
    /// One entry per input: `Some(value)` or `None` for `-`.
    pub inputs: Vec<Option<bool>>,
    /// One entry per output.
    pub outputs: Vec<Out>,
}

/// A whole PLA file.
///
/// Comment texts must not contain line breaks and names must be non-empty without
/// whitespace, or the written text will not read back the same.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pla {
    /// Comment lines before the first directive.
    pub header: Vec<String>,
    /// Input names (`.ilb`); input 0 is the leftmost character of a row.
    pub inputs: Vec<String>,
    /// Output names (`.ob`).
    pub outputs: Vec<String>,
    /// The rows, in file order.
    pub rows: Vec<Row>,
    /// Comment lines after the last row (before `.e`).
    pub trailer: Vec<String>,
}

/// Where a parsed file names its inputs and outputs, as 1-based line and column (in
/// characters): for errors about the names found after parsing (a name the select logic does
/// not know, an output it needs and the file does not list).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Places {
    /// Each input's name in `.ilb`, or the `.i` count for every input when there is no `.ilb`
    /// (the default names `x0`, `x1`, …).
    pub inputs: Vec<(usize, usize)>,
    /// The `.ob` directive, or the `.o` count when there is none.
    pub outputs: (usize, usize),
}

/// Why a text is not a PLA file: the message and where, as 1-based line and column.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlaError {
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub col: usize,
    /// What is wrong.
    pub msg: String,
}

impl fmt::Display for PlaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.col, self.msg)
    }
}

impl std::error::Error for PlaError {}

/// Shorthand for an error result.
fn fail<T>(line: usize, col: usize, msg: impl Into<String>) -> Result<T, PlaError> {
    Err(PlaError {
        line,
        col,
        msg: msg.into(),
    })
}

/// The most inputs a minterm (`u32`) can hold.
const MAX_INPUTS: usize = 32;

impl Out {
    fn to_char(self) -> char {
        match self {
            Out::Zero => '0',
            Out::One => '1',
            Out::DontCare => '-',
        }
    }

    fn from_char(c: char) -> Option<Out> {
        match c {
            '0' | '~' => Some(Out::Zero),
            '1' => Some(Out::One),
            '-' | '2' => Some(Out::DontCare),
            _ => None,
        }
    }
}

fn input_char(v: Option<bool>) -> char {
    match v {
        Some(false) => '0',
        Some(true) => '1',
        None => '-',
    }
}

fn input_from_char(c: char) -> Option<Option<bool>> {
    match c {
        '0' => Some(Some(false)),
        '1' => Some(Some(true)),
        '-' => Some(None),
        _ => None,
    }
}

/// Append `# text` (just `#` for empty text) and a line break.
fn push_comment(out: &mut String, text: &str) {
    out.push('#');
    if !text.is_empty() {
        out.push(' ');
        out.push_str(text);
    }
    out.push('\n');
}

impl Pla {
    /// The canonical text: header comments, `.i .o .ilb .ob .type fd .p`, the rows (each
    /// after its comments, inputs and outputs separated by one space), trailer comments and
    /// `.e`, every line ending in `'\n'`.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        self.header.iter().for_each(|c| push_comment(&mut out, c));
        out.push_str(&format!(
            ".i {}\n.o {}\n",
            self.inputs.len(),
            self.outputs.len()
        ));
        out.push_str(&format!(".ilb {}\n", self.inputs.join(" ")));
        out.push_str(&format!(".ob {}\n", self.outputs.join(" ")));
        out.push_str(&format!(".type fd\n.p {}\n", self.rows.len()));
        for row in &self.rows {
            row.comments.iter().for_each(|c| push_comment(&mut out, c));
            out.extend(row.inputs.iter().map(|&v| input_char(v)));
            out.push(' ');
            out.extend(row.outputs.iter().map(|o| o.to_char()));
            out.push('\n');
        }
        self.trailer.iter().for_each(|c| push_comment(&mut out, c));
        out.push_str(".e\n");
        out
    }

    /// Read a PLA file of `.type fd`.
    ///
    /// Besides the canonical form this accepts blank lines, the directives in any order
    /// before the first row, no `.ilb`/`.ob` (names `x0..`/`y0..`), no `.type`, no `.p`,
    /// rows with the input and output fields separated by any whitespace or none, and `.e`,
    /// `.end` or nothing at the end. At most 32 inputs. Comments between directives join
    /// the header; comments after `.e` join the trailer.
    ///
    /// # Errors
    ///
    /// Anything else, with its line and column: an unknown or repeated directive, a bad
    /// count, a `.type` other than `fd`, names not matching `.i`/`.o`, a row before `.i` and
    /// `.o`, a bad character or length in a row, a `.p` not matching the rows, or anything
    /// but comments after `.e`.
    pub fn parse(text: &str) -> Result<Pla, PlaError> {
        Pla::parse_with_places(text).map(|(pla, _)| pla)
    }

    /// [`Pla::parse`], and where the file names its inputs and outputs.
    ///
    /// # Errors
    ///
    /// As [`Pla::parse`].
    pub fn parse_with_places(text: &str) -> Result<(Pla, Places), PlaError> {
        let mut parser = Parser::default();
        let mut lines = 0;
        for (i, line) in text.lines().enumerate() {
            parser.line(i + 1, line)?;
            lines = i + 1;
        }
        parser.finish(lines + 1)
    }

    /// Expand `-` inputs: every (minterm, outputs) pair the rows specify, row by row, each
    /// row's minterms ascending. Minterm bit `i` is input `i` (input 0 is the first `.ilb`
    /// name, the leftmost character of a row). Inputs past the 32nd are ignored.
    pub fn minterms(&self) -> Vec<(u32, Vec<Out>)> {
        self.rows
            .iter()
            .flat_map(|row| expand(&row.inputs).map(move |m| (m, row.outputs.clone())))
            .collect()
    }
}

/// The minterms of one input pattern, ascending (bit i = input i).
pub fn expand(inputs: &[Option<bool>]) -> impl Iterator<Item = u32> {
    let bits = inputs.iter().take(MAX_INPUTS).enumerate();
    let fixed: u32 = bits
        .clone()
        .filter(|(_, v)| **v == Some(true))
        .map(|(i, _)| 1 << i)
        .sum();
    let free: Vec<u32> = bits
        .filter(|(_, v)| v.is_none())
        .map(|(i, _)| 1 << i)
        .collect();
    (0..1u64 << free.len()).map(move |s| {
        let spread = free.iter().enumerate().filter(|(k, _)| s >> k & 1 == 1);
        fixed | spread.map(|(_, &bit)| bit).sum::<u32>()
    })
}

/// The whitespace-separated words of a line, each with its 1-based column.
fn words(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = None;
    for (col, (byte, ch)) in line.char_indices().enumerate() {
        match (ch.is_whitespace(), start) {
            (true, Some((c, b))) => {
                out.push((c, &line[b..byte]));
                start = None;
            }
            (false, None) => start = Some((col + 1, byte)),
            _ => {}
        }
    }
    if let Some((c, b)) = start {
        out.push((c, &line[b..]));
    }
    out
}

/// The column just past the end of a line.
fn end_col(line: &str) -> usize {
    line.chars().count() + 1
}

/// An `.ilb` or `.ob` line, checked against `.i`/`.o` when the rows begin.
struct Names {
    line: usize,
    /// Column of the directive.
    col: usize,
    end_col: usize,
    names: Vec<(usize, String)>,
}

/// A `.i`, `.o` or `.p` count and where its value stands.
#[derive(Clone, Copy)]
struct Count {
    line: usize,
    col: usize,
    value: usize,
}

/// Parser state, fed one line at a time.
#[derive(Default)]
struct Parser {
    pla: Pla,
    inputs: Option<Count>,
    outputs: Option<Count>,
    ilb: Option<Names>,
    ob: Option<Names>,
    type_line: Option<usize>,
    p: Option<Count>,
    /// Comments not yet attached to the header, a row or the trailer.
    pending: Vec<String>,
    /// Whether any directive has been seen.
    started: bool,
    /// The input and output counts, once the first row has been seen.
    dims: Option<(usize, usize)>,
    /// Line of the `.e` or `.end`.
    end: Option<usize>,
    /// Where the names stand, once the first row (or the end) settled them.
    places: Places,
}

impl Parser {
    fn line(&mut self, ln: usize, line: &str) -> Result<(), PlaError> {
        let text = line.trim_start();
        if text.trim_end().is_empty() {
            return Ok(());
        }
        if let Some(comment) = text.strip_prefix('#') {
            let comment = comment.strip_prefix(' ').unwrap_or(comment).to_string();
            if self.started {
                self.pending.push(comment);
            } else {
                self.pla.header.push(comment);
            }
            return Ok(());
        }
        let col = end_col(line) - text.chars().count();
        if let Some(end) = self.end {
            return fail(
                ln,
                col,
                format!("only comments may follow the end (line {end})"),
            );
        }
        if text.starts_with('.') {
            self.directive(ln, line)
        } else {
            self.row(ln, line, col)
        }
    }

    fn directive(&mut self, ln: usize, line: &str) -> Result<(), PlaError> {
        let d = Directive::new(ln, line);
        let is_end = d.name == ".e" || d.name == ".end";
        if self.dims.is_some() && !is_end {
            return d.fail(d.col, format!("{} after the first row", d.name));
        }
        if !is_end {
            self.pla.header.append(&mut self.pending);
        }
        self.started = true;
        match d.name {
            ".i" => self.inputs = Some(d.count(self.inputs, 1)?),
            ".o" => self.outputs = Some(d.count(self.outputs, 1)?),
            ".p" => self.p = Some(d.count(self.p, 0)?),
            ".ilb" => self.ilb = Some(d.names(self.ilb.as_ref())?),
            ".ob" => self.ob = Some(d.names(self.ob.as_ref())?),
            ".type" => {
                d.file_type(self.type_line)?;
                self.type_line = Some(ln);
            }
            _ if is_end => {
                d.no_args()?;
                self.end = Some(ln);
            }
            _ => return d.fail(d.col, format!("unknown directive {}", d.name)),
        }
        Ok(())
    }

    fn row(&mut self, ln: usize, line: &str, col: usize) -> Result<(), PlaError> {
        let (ni, no) = match self.dims {
            Some(dims) => dims,
            None => self.begin_rows(ln, col, "the first row")?,
        };
        let mut row = parse_row(ln, line, ni, no, &self.pla)?;
        row.comments = std::mem::take(&mut self.pending);
        self.pla.rows.push(row);
        Ok(())
    }

    /// Check the directives once they are complete (at the first row, or at `what` when
    /// there is none) and settle the names.
    fn begin_rows(
        &mut self,
        ln: usize,
        col: usize,
        what: &str,
    ) -> Result<(usize, usize), PlaError> {
        let Some(ni) = self.inputs else {
            return fail(ln, col, format!("missing .i before {what}"));
        };
        let Some(no) = self.outputs else {
            return fail(ln, col, format!("missing .o before {what}"));
        };
        self.pla.inputs = settle(self.ilb.as_ref(), ni, ".ilb", ".i", 'x')?;
        self.pla.outputs = settle(self.ob.as_ref(), no, ".ob", ".o", 'y')?;
        self.places = Places {
            inputs: match &self.ilb {
                Some(names) => names.names.iter().map(|n| (names.line, n.0)).collect(),
                None => vec![(ni.line, ni.col); ni.value],
            },
            outputs: self
                .ob
                .as_ref()
                .map_or((no.line, no.col), |n| (n.line, n.col)),
        };
        self.dims = Some((ni.value, no.value));
        Ok((ni.value, no.value))
    }

    fn finish(mut self, eof_line: usize) -> Result<(Pla, Places), PlaError> {
        if self.dims.is_none() {
            self.begin_rows(self.end.unwrap_or(eof_line), 1, "the end")?;
        }
        if let Some(p) = self.p {
            let found = self.pla.rows.len();
            if p.value != found {
                let msg = format!(".p says {} rows, found {found}", p.value);
                return fail(p.line, p.col, msg);
            }
        }
        self.pla.trailer = self.pending;
        Ok((self.pla, self.places))
    }
}

/// A directive line split into words.
struct Directive<'a> {
    line: usize,
    /// Column of the name.
    col: usize,
    name: &'a str,
    args: Vec<(usize, &'a str)>,
    end_col: usize,
}

impl<'a> Directive<'a> {
    /// Split line number `ln`, which starts (after blanks) with `.`.
    fn new(ln: usize, text: &'a str) -> Directive<'a> {
        let mut words = words(text);
        let (col, name) = words.remove(0);
        Directive {
            line: ln,
            col,
            name,
            args: words,
            end_col: end_col(text),
        }
    }

    fn fail<T>(&self, col: usize, msg: impl Into<String>) -> Result<T, PlaError> {
        fail(self.line, col, msg)
    }

    /// The column just past the name.
    fn after(&self) -> usize {
        self.col + self.name.chars().count()
    }

    /// Refuse a second occurrence; `first` is the line of the first.
    fn once(&self, first: Option<usize>) -> Result<(), PlaError> {
        match first {
            Some(line) => self.fail(
                self.col,
                format!("second {} (first on line {line})", self.name),
            ),
            None => Ok(()),
        }
    }

    /// Refuse any words after the name.
    fn no_args(&self) -> Result<(), PlaError> {
        match self.args.first() {
            Some(&(col, word)) => {
                self.fail(col, format!("unexpected {word:?} after {}", self.name))
            }
            None => Ok(()),
        }
    }

    /// The single argument, if there is exactly one.
    fn arg(&self, what: &str) -> Result<(usize, &'a str), PlaError> {
        match self.args[..] {
            [] => self.fail(self.after(), format!("expected {what} after {}", self.name)),
            [arg] => Ok(arg),
            [_, (col, word), ..] => {
                self.fail(col, format!("unexpected {word:?} after {}", self.name))
            }
        }
    }

    /// The value of `.i`, `.o` or `.p`, at least `min`; `seen` is an earlier one.
    fn count(&self, seen: Option<Count>, min: usize) -> Result<Count, PlaError> {
        self.once(seen.map(|c| c.line))?;
        let (col, word) = self.arg("a number")?;
        let Ok(value) = word.parse::<usize>() else {
            return self.fail(col, format!("expected a number, found {word:?}"));
        };
        if value < min {
            return self.fail(col, format!("{} must be at least {min}", self.name));
        }
        if self.name == ".i" && value > MAX_INPUTS {
            return self.fail(col, format!(".i is at most {MAX_INPUTS}"));
        }
        Ok(Count {
            line: self.line,
            col,
            value,
        })
    }

    /// The names of `.ilb` or `.ob`; `seen` is an earlier line of the same.
    fn names(&self, seen: Option<&Names>) -> Result<Names, PlaError> {
        self.once(seen.map(|n| n.line))?;
        Ok(Names {
            line: self.line,
            col: self.col,
            end_col: self.end_col,
            names: self.args.iter().map(|&(c, w)| (c, w.to_string())).collect(),
        })
    }

    /// Check `.type fd`; `seen` is the line of an earlier `.type`.
    fn file_type(&self, seen: Option<usize>) -> Result<(), PlaError> {
        self.once(seen)?;
        if let Some(&(col, value)) = self.args.first().filter(|a| a.1 != "fd") {
            return self.fail(col, format!("only .type fd is supported, found {value:?}"));
        }
        self.arg("a type").map(drop)
    }
}

/// The names for `count` inputs or outputs: from the `.ilb`/`.ob` line if any, which must
/// give exactly that many, else `x0, x1, ..` (or `y0, ..`).
fn settle(
    names: Option<&Names>,
    count: Count,
    directive: &str,
    count_directive: &str,
    prefix: char,
) -> Result<Vec<String>, PlaError> {
    let want = count.value;
    let Some(names) = names else {
        return Ok((0..want).map(|i| format!("{prefix}{i}")).collect());
    };
    let found = names.names.len();
    if found != want {
        let col = names.names.get(want).map_or(names.end_col, |n| n.0);
        let msg = format!(
            "{directive} gives {found} names but {count_directive} is {want} (line {})",
            count.line
        );
        return fail(names.line, col, msg);
    }
    Ok(names.names.iter().map(|n| n.1.clone()).collect())
}

/// One row of `ni` input and `no` output characters. When the row is two words, the first
/// must be exactly the inputs; otherwise all non-blank characters are split by count.
fn parse_row(ln: usize, line: &str, ni: usize, no: usize, pla: &Pla) -> Result<Row, PlaError> {
    if let [(col, field), _] = words(line)[..] {
        let len = field.chars().count();
        if len != ni {
            let msg = format!("input field has {len} characters but .i is {ni}");
            return fail(ln, col + len.min(ni), msg);
        }
    }
    let mut row = Row {
        comments: Vec::new(),
        inputs: Vec::with_capacity(ni),
        outputs: Vec::with_capacity(no),
    };
    let chars = line.chars().enumerate().filter(|(_, c)| !c.is_whitespace());
    for (k, (i, ch)) in chars.enumerate() {
        let col = i + 1;
        if k < ni {
            let Some(v) = input_from_char(ch) else {
                let msg = format!(
                    "expected 0, 1 or - for input {}, found {ch:?}",
                    pla.inputs[k]
                );
                return fail(ln, col, msg);
            };
            row.inputs.push(v);
        } else if k < ni + no {
            let Some(o) = Out::from_char(ch) else {
                let name = &pla.outputs[k - ni];
                let msg = format!("expected 0, 1, -, ~ or 2 for output {name}, found {ch:?}");
                return fail(ln, col, msg);
            };
            row.outputs.push(o);
        } else {
            return fail(
                ln,
                col,
                format!("row longer than {ni} inputs and {no} outputs"),
            );
        }
    }
    if row.outputs.len() < no {
        let found = row.inputs.len() + row.outputs.len();
        let msg = format!("row has {found} characters, expected {ni} inputs and {no} outputs");
        return fail(ln, end_col(line), msg);
    }
    Ok(row)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const SAMPLE: &str = "\
# select logic, S1 and S2
#
#  indented comment
.i 7
.o 2
.ilb L S Y N J T M
.ob S1 S2
.type fd
.p 3
# first row
0-10101 1-
1111111 00
# two comments
#
------- -1
# trailer
.e
";

    fn err(text: &str) -> (usize, usize) {
        let e = Pla::parse(text).unwrap_err();
        (e.line, e.col)
    }

    #[test]
    fn sample_round_trips_byte_for_byte() {
        let pla = Pla::parse(SAMPLE).unwrap();
        assert_eq!(
            pla.header,
            ["select logic, S1 and S2", "", " indented comment"]
        );
        assert_eq!(pla.inputs, ["L", "S", "Y", "N", "J", "T", "M"]);
        assert_eq!(pla.outputs, ["S1", "S2"]);
        assert_eq!(pla.rows.len(), 3);
        assert_eq!(pla.rows[0].comments, ["first row"]);
        assert_eq!(pla.rows[1].comments, Vec::<String>::new());
        assert_eq!(pla.rows[2].comments, ["two comments", ""]);
        assert_eq!(pla.rows[0].inputs[..3], [Some(false), None, Some(true)]);
        assert_eq!(pla.rows[0].outputs, [Out::One, Out::DontCare]);
        assert_eq!(pla.trailer, ["trailer"]);
        assert_eq!(pla.to_text(), SAMPLE);
    }

    #[test]
    fn lenient_forms_read_the_same() {
        let text = "\r\n# hdr\r\n.o 2\r\n\r\n.i 3\r\n# before\r\n1-0\t\t1~\r\n   0112-\r\n.end\r\n";
        let pla = Pla::parse(text).unwrap();
        let want = "\
# hdr
.i 3
.o 2
.ilb x0 x1 x2
.ob y0 y1
.type fd
.p 2
# before
1-0 10
011 --
.e
";
        assert_eq!(pla.to_text(), want);
        assert_eq!(Pla::parse(want).unwrap(), pla);
    }

    #[test]
    fn directives_in_any_order_and_optional_end() {
        let pla = Pla::parse(".ob f\n.ilb a b\n.type fd\n.o 1\n.i 2\n1- 1\n").unwrap();
        assert_eq!(pla.inputs, ["a", "b"]);
        assert_eq!(pla.outputs, ["f"]);
        assert_eq!(pla.rows.len(), 1);
        let empty = Pla::parse(".i 1\n.o 1\n# note\n.e\n# after\n").unwrap();
        assert!(empty.rows.is_empty());
        assert_eq!(empty.trailer, ["note", "after"]);
    }

    #[test]
    fn errors_name_line_and_column() {
        let head = ".i 3\n.o 2\n";
        // Bad input and output characters.
        assert_eq!(err(&format!("{head}1x0 10\n")), (3, 2));
        assert_eq!(err(&format!("{head}1-0 1x\n")), (3, 6));
        assert_eq!(err(&format!("{head}  1-0\t1x\n")), (3, 8));
        // Field lengths.
        assert_eq!(err(&format!("{head}10 10\n")), (3, 3));
        assert_eq!(err(&format!("{head}1000 10\n")), (3, 4));
        assert_eq!(err(&format!("{head}100 101\n")), (3, 7));
        assert_eq!(err(&format!("{head}100 1\n")), (3, 6));
        assert_eq!(err(&format!("{head}1001\n")), (3, 5));
        // Names.
        assert_eq!(err(&format!("{head}.ilb a b c d\n100 10\n")), (3, 12));
        assert_eq!(err(&format!("{head}.ilb a b\n100 10\n")), (3, 9));
        assert_eq!(err(&format!("{head}.ob s\n")), (3, 6));
        // Missing counts.
        assert_eq!(err(".o 2\n\n  100 10\n"), (3, 3));
        assert_eq!(err(".i 3\n100 10\n"), (2, 1));
        assert_eq!(err(".i 3\n.e\n"), (2, 1));
        assert_eq!(err(""), (1, 1));
        // Directives.
        assert_eq!(err(&format!("{head}.type fr\n")), (3, 7));
        assert_eq!(err(&format!("{head}.type\n")), (3, 6));
        assert_eq!(err(&format!("{head}.p 2\n100 10\n")), (3, 4));
        assert_eq!(err(&format!("{head}.phase 01\n")), (3, 1));
        assert_eq!(err(&format!("{head}.i 4\n")), (3, 1));
        assert_eq!(err(".i x\n"), (1, 4));
        assert_eq!(err(".i\n"), (1, 3));
        assert_eq!(err(".i 3 4\n"), (1, 6));
        assert_eq!(err(".i 0\n"), (1, 4));
        assert_eq!(err(".i 33\n"), (1, 4));
        assert_eq!(err(&format!("{head}100 10\n.p 1\n")), (4, 1));
        // After the end.
        assert_eq!(err(&format!("{head}.e\n# fine\n\n 100 10\n")), (6, 2));
        assert_eq!(err(&format!("{head}.e now\n")), (3, 4));
    }

    #[test]
    fn places_say_where_the_names_stand() {
        let text = ".i 2\n.o 1\n.ilb a  b\n.ob f\n10 1\n";
        let (_, places) = Pla::parse_with_places(text).unwrap();
        assert_eq!(places.inputs, [(3, 6), (3, 9)]);
        assert_eq!(places.outputs, (4, 1));
        // The default names stand at the counts.
        let (_, places) = Pla::parse_with_places(" .i 2\n.o 1\n").unwrap();
        assert_eq!(places.inputs, [(1, 5), (1, 5)]);
        assert_eq!(places.outputs, (2, 4));
    }

    #[test]
    fn error_display_is_line_colon_column() {
        let e = Pla::parse(".i 3\n.o 2\n.type fr\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "3:7: only .type fd is supported, found \"fr\""
        );
    }

    #[test]
    fn minterms_expand_dashes_with_input_0_as_bit_0() {
        let pla = Pla::parse(".i 3\n.o 1\n1-0 1\n--1 -\n").unwrap();
        let got: Vec<(u32, Out)> = pla.minterms().into_iter().map(|(m, o)| (m, o[0])).collect();
        let one = Out::One;
        let dc = Out::DontCare;
        assert_eq!(
            got,
            [(1, one), (3, one), (4, dc), (5, dc), (6, dc), (7, dc)]
        );
    }

    fn arb_pla() -> impl Strategy<Value = Pla> {
        let comment = || prop::collection::vec("[ -~]{0,12}", 0..3);
        let name = "[A-Za-z_][A-Za-z0-9_]{0,5}";
        (1usize..=9, 1usize..=3).prop_flat_map(move |(ni, no)| {
            let out = prop_oneof![Just(Out::Zero), Just(Out::One), Just(Out::DontCare)];
            let row = (
                comment(),
                prop::collection::vec(prop::option::of(any::<bool>()), ni),
                prop::collection::vec(out, no),
            )
                .prop_map(|(comments, inputs, outputs)| Row {
                    comments,
                    inputs,
                    outputs,
                });
            (
                comment(),
                prop::collection::vec(name, ni),
                prop::collection::vec(name, no),
                prop::collection::vec(row, 0..6),
                comment(),
            )
                .prop_map(|(header, inputs, outputs, rows, trailer)| Pla {
                    header,
                    inputs,
                    outputs,
                    rows,
                    trailer,
                })
        })
    }

    proptest! {
        #[test]
        fn random_plas_round_trip(pla in arb_pla()) {
            let text = pla.to_text();
            let back = Pla::parse(&text).map_err(|e| TestCaseError::fail(e.to_string()))?;
            prop_assert_eq!(&back, &pla);
            prop_assert_eq!(back.to_text(), text);
        }
    }
}

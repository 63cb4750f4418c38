//! Display-list text format of the 2D CSG display processor (thesis §5.2).
//!
//! A display list describes one object primitive as a list of planes. Each
//! plane takes two rows of whitespace-separated fields (§5.2):
//!
//! ```text
//! Z0  dZx  dZy  colour      depth at the window origin, increments, colour code
//! H   Y    L                front surface, perpendicular to the screen, concave
//! ```
//!
//! For a plane perpendicular to the screen (`Y = 1`) the three numbers are
//! `K0 dKx dKy` instead (§2.3.1, eq. 2.2); the syntax is the same.
//!
//! The list ends with a dummy first row whose colour is greater than 1000
//! (the thesis uses `0 0 0 1234`). Fields are separated by any mix of spaces
//! and tabs; blank lines and whole-line `#` comments may appear anywhere.

use std::fmt::{self, Display};
use std::path::Path;

use crate::{Error, Result};
use std::vec;

/// Largest colour code of a real plane; a greater colour marks the dummy
/// terminating entry of the list (§5.2).
pub const MAX_PLANE_COLOUR: u32 = 1000;

/// One plane of a display list (§5.2): depth (or K) coefficients, colour
/// code, externals.
#[derive(Clone, Debug, PartialEq)]
pub struct DlPlane {
    /// Depth at the origin of the display window (`K0` when `y`).
    pub z0: f64,
    /// Depth increment in the X direction (`dKx` when `y`).
    pub dzx: f64,
    /// Depth increment in the Y direction (`dKy` when `y`).
    pub dzy: f64,
    /// Colour code of the plane, at most [`MAX_PLANE_COLOUR`]; 0 is the
    /// background.
    pub colour: u32,
    /// `H = 1`: front surface.
    pub h: bool,
    /// `Y = 1`: plane perpendicular to the screen.
    pub y: bool,
    /// `L = 1`: plane of a concave object.
    pub l: bool,
}

/// A parsed display list (§5.2): the planes of one object primitive.
#[derive(Clone, Debug, PartialEq)]
pub struct DisplayList {
    /// The planes, in file order.
    pub planes: Vec<DlPlane>,
    /// Colour of the dummy terminating entry, greater than
    /// [`MAX_PLANE_COLOUR`] (the thesis uses 1234).
    pub terminator: u32,
}

/// 1-based (line, column) of field `field` (0-based) of the first row of plane `plane`
/// (0-based) in display-list text: each plane is two data rows, blank and `#` lines skipped.
pub fn field_position(text: &str, plane: usize, field: usize) -> Option<(usize, usize)> {
    let (line_no, line) = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .nth(2 * plane)?;
    let mut in_field = false;
    let mut n = 0;
    for (col, ch) in line.chars().enumerate() {
        if ch.is_whitespace() {
            in_field = false;
        } else if !in_field {
            if n == field {
                return Some((line_no + 1, col + 1));
            }
            in_field = true;
            n += 1;
        }
    }
    None
}

impl DisplayList {
    /// A slab between two depths (§4.4): a front plane at `front` and a back plane at `back`,
    /// both parallel to the screen, in colour `colour`.
    pub fn slab(front: f64, back: f64, colour: u32) -> DisplayList {
        let plane = |z0: f64, h: bool| DlPlane {
            z0,
            dzx: 0.0,
            dzy: 0.0,
            colour,
            h,
            y: false,
            l: false,
        };
        DisplayList {
            planes: vec![plane(front, true), plane(back, false)],
            terminator: 1234,
        }
    }

    /// Parses the §5.2 text format; `file` only names the source in errors.
    ///
    /// # Errors
    ///
    /// Returns the first syntax error, located by line and column.
    ///
    /// # Examples
    ///
    /// A slab between depths 10 and 20 in colour 5: its front plane, its back plane, the
    /// terminator.
    ///
    /// ```
    /// use csgpix_scene::display_list::DisplayList;
    ///
    /// let text = "10 0 0 5\n1 0 0\n20 0 0 5\n0 0 0\n0 0 0 1234\n";
    /// let list = DisplayList::parse(text, "slab.dl")?;
    /// assert_eq!(list, DisplayList::slab(10.0, 20.0, 5));
    /// assert!(list.planes[0].h && !list.planes[1].h);
    ///
    /// let err = DisplayList::parse("10 0 0 5\n1 0 x\n", "bad.dl").unwrap_err();
    /// assert_eq!(err.location().unwrap().to_string(), "bad.dl:2:5");
    /// # Ok::<(), csgpix_scene::Error>(())
    /// ```
    pub fn parse(text: &str, file: &str) -> Result<DisplayList> {
        Parser::new(text)
            .parse()
            .map_err(|spot| spot.into_error(file))
    }

    /// Reads and parses a display-list file (§5.2).
    ///
    /// # Errors
    ///
    /// Returns a syntax error, or an I/O error reported at line 0, column 0.
    pub fn read(path: &Path) -> Result<DisplayList> {
        let file = path.display().to_string();
        let bytes = match std::fs::read(path) {
            Ok(bytes) => bytes,
            Err(err) => return Err(Error::Io(err.into()).located(&file, 0, 0)),
        };
        if let Some((line, col, problem)) = crate::input::bad_utf8(&bytes) {
            return Err(problem.located(&file, line, col));
        }
        Self::parse(&String::from_utf8_lossy(&bytes), &file)
    }

    /// Writes the canonical text form: two tab-separated rows per plane,
    /// numbers in shortest round-trip form, then `0 0 0 terminator`.
    pub fn to_text(&self) -> String {
        self.to_string()
    }

    /// True if any plane has `L = 1` (the object is concave).
    pub fn is_concave(&self) -> bool {
        self.planes.iter().any(|plane| plane.l)
    }
}

impl Display for DisplayList {
    /// Canonical text form, see [`DisplayList::to_text`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for p in &self.planes {
            writeln!(f, "{}\t{}\t{}\t{}", p.z0, p.dzx, p.dzy, p.colour)?;
            writeln!(f, "{}\t{}\t{}", u8::from(p.h), u8::from(p.y), u8::from(p.l))?;
        }
        writeln!(f, "0\t0\t0\t{}", self.terminator)
    }
}

/// An error position and problem, before the file name is attached.
#[derive(Debug)]
struct Spot {
    line: usize,
    col: usize,
    problem: Error,
}

impl Spot {
    fn new(line: usize, col: usize, problem: Error) -> Spot {
        Spot { line, col, problem }
    }

    fn into_error(self, file: &str) -> Error {
        Error::at(file, self.line, self.col, self.problem)
    }
}

/// `expected WHAT, found FOUND`.
fn expected(what: impl Into<String>, found: impl Into<String>) -> Error {
    Error::Expected {
        expected: what.into(),
        found: found.into(),
    }
}

/// One whitespace-separated field of a row.
struct Field<'a> {
    text: &'a str,
    line: usize,
    col: usize,
}

impl Field<'_> {
    fn error(&self, problem: Error) -> Spot {
        Spot::new(self.line, self.col, problem)
    }

    /// `expected WHAT, found `FIELD``, at the field.
    fn expected(&self, what: impl Into<String>) -> Spot {
        self.error(expected(what, format!("`{}`", self.text)))
    }

    /// A real number (Z0, dZx, dZy or K0, dKx, dKy); must be finite.
    fn number(&self, name: &str) -> Result<f64, Spot> {
        match self.text.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            _ => Err(self.expected(format!("a finite number for {name}"))),
        }
    }

    /// An unsigned integer colour code.
    fn colour(&self) -> Result<u32, Spot> {
        if self.text.is_empty() || !self.text.bytes().all(|b| b.is_ascii_digit()) {
            return Err(self.expected("an unsigned integer colour"));
        }
        self.text.parse().map_err(|_| {
            let text = self.text.to_string();
            self.error(Error::ColourOutOfRange { text })
        })
    }

    /// An external variable H, Y or L: exactly `0` or `1`.
    fn flag(&self, name: &str) -> Result<bool, Spot> {
        match self.text {
            "0" => Ok(false),
            "1" => Ok(true),
            _ => Err(self.expected(format!("0 or 1 for {name}"))),
        }
    }
}

/// The fields of one non-blank, non-comment line, consumed left to right.
struct Row<'a> {
    line: usize,
    end_col: usize,
    fields: vec::IntoIter<Field<'a>>,
}

impl<'a> Row<'a> {
    fn new(line: usize, text: &'a str) -> Row<'a> {
        Row {
            line,
            end_col: text.chars().count() + 1,
            fields: split_fields(line, text).into_iter(),
        }
    }

    /// The next field, or an error at end of line naming what was expected.
    fn field(&mut self, what: &str) -> Result<Field<'a>, Spot> {
        let (line, col) = (self.line, self.end_col);
        self.fields
            .next()
            .ok_or_else(|| Spot::new(line, col, expected(what, "end of line")))
    }

    /// Checks that no field is left, else points at the first extra one.
    fn finish(mut self) -> Result<(), Spot> {
        match self.fields.next() {
            None => Ok(()),
            Some(f) => Err(f.expected("end of line")),
        }
    }
}

fn is_separator(c: char) -> bool {
    c == ' ' || c == '\t'
}

/// Splits a line at spaces and tabs, recording 1-based character columns. The column is
/// carried from piece to piece, never recounted from the line's start: a line of n fields
/// costs its length, not n times it (a 1 MB line took seconds to refuse otherwise).
fn split_fields(line: usize, text: &str) -> Vec<Field<'_>> {
    let mut fields = Vec::new();
    let mut col = 1;
    for piece in text.split(is_separator) {
        if !piece.is_empty() {
            fields.push(Field {
                text: piece,
                line,
                col,
            });
        }
        col += piece.chars().count() + 1; // a separator is one character
    }
    fields
}

/// Blank lines and whole-line `#` comments carry no data.
fn is_significant(text: &str) -> bool {
    let trimmed = text.trim_start_matches(is_separator);
    !trimmed.is_empty() && !trimmed.starts_with('#')
}

/// Line-oriented parser over the significant rows of a display list.
struct Parser<'a> {
    rows: Box<dyn Iterator<Item = Row<'a>> + 'a>,
    eof: (usize, usize),
    planes: Vec<DlPlane>,
    /// Line of the first plane's L field, for the shared-L check.
    first_l_line: usize,
}

impl<'a> Parser<'a> {
    fn new(text: &'a str) -> Parser<'a> {
        let rows = text
            .lines()
            .enumerate()
            .filter(|(_, line)| is_significant(line))
            .map(|(index, line)| Row::new(index + 1, line));
        Parser {
            rows: Box::new(rows),
            eof: end_of_text(text),
            planes: Vec::new(),
            first_l_line: 0,
        }
    }

    fn at_eof(&self, problem: Error) -> Spot {
        Spot::new(self.eof.0, self.eof.1, problem)
    }

    /// Parses planes until the terminating entry, then checks nothing follows.
    fn parse(mut self) -> Result<DisplayList, Spot> {
        loop {
            let Some(mut row) = self.rows.next() else {
                return Err(self.at_eof(self.missing_terminator()));
            };
            let (z0, dzx, dzy) = coefficients(&mut row)?;
            let colour_field = row.field("colour")?;
            let colour = colour_field.colour()?;
            row.finish()?;
            if colour > MAX_PLANE_COLOUR {
                return self.terminate(&colour_field, colour);
            }
            let plane = self.externals(z0, dzx, dzy, colour)?;
            self.planes.push(plane);
        }
    }

    fn missing_terminator(&self) -> Error {
        if self.planes.is_empty() {
            expected("a plane", "end of file").context("empty display list")
        } else {
            expected("a terminating entry with colour > 1000", "end of file")
        }
    }

    /// Handles the dummy entry of colour `terminator` (§5.2).
    fn terminate(mut self, field: &Field, terminator: u32) -> Result<DisplayList, Spot> {
        if self.planes.is_empty() {
            let e = Error::TerminatorFirst.context("empty display list");
            return Err(field.error(e));
        }
        // A significant row always holds at least one field.
        if let Some(extra) = self.rows.next().and_then(|mut row| row.fields.next()) {
            return Err(extra.expected("nothing after the terminating entry"));
        }
        Ok(DisplayList {
            planes: self.planes,
            terminator,
        })
    }

    /// Parses the `H Y L` row completing a plane whose first row is given.
    fn externals(&mut self, z0: f64, dzx: f64, dzy: f64, colour: u32) -> Result<DlPlane, Spot> {
        let Some(mut row) = self.rows.next() else {
            return Err(self.at_eof(expected("an H Y L row", "end of file")));
        };
        let h = row.field("H")?.flag("H")?;
        let y = row.field("Y")?.flag("Y")?;
        let l_field = row.field("L")?;
        let l = l_field.flag("L")?;
        row.finish()?;
        self.check_shared_l(&l_field, l)?;
        Ok(DlPlane {
            z0,
            dzx,
            dzy,
            colour,
            h,
            y,
            l,
        })
    }

    /// All planes of one object share L: it is convex or concave.
    fn check_shared_l(&mut self, field: &Field, l: bool) -> Result<(), Spot> {
        match self.planes.first() {
            None => {
                self.first_l_line = field.line;
                Ok(())
            }
            Some(first) if first.l == l => Ok(()),
            Some(first) => Err(field.expected(format!(
                "L={} as on line {} (all planes of an object share L)",
                u8::from(first.l),
                self.first_l_line,
            ))),
        }
    }
}

/// Parses the three real coefficients `Z0 dZx dZy` (or `K0 dKx dKy`).
fn coefficients(row: &mut Row) -> Result<(f64, f64, f64), Spot> {
    let z0 = row.field("Z0")?.number("Z0")?;
    let dzx = row.field("dZx")?.number("dZx")?;
    let dzy = row.field("dZy")?.number("dZy")?;
    Ok((z0, dzx, dzy))
}

/// The 1-based (line, column) just past the last character of `text`.
fn end_of_text(text: &str) -> (usize, usize) {
    let line = text.matches('\n').count() + 1;
    let last = text.rsplit('\n').next().unwrap_or("");
    (line, last.chars().count() + 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const CUBE: &str = include_str!("../../../vectors/thesis/cube.dl");
    const BOX1: &str = include_str!("../../../vectors/thesis/box1.dl");
    const BOX2: &str = include_str!("../../../vectors/thesis/box2.dl");

    fn parse(text: &str) -> Result<DisplayList> {
        DisplayList::parse(text, "t.dl")
    }

    /// Parses `text`, expecting an error at `line:col` whose message
    /// contains `needle`.
    fn assert_error(text: &str, line: usize, col: usize, needle: &str) {
        let err = parse(text).expect_err("parse should fail");
        let at = err.location().expect("a located error");
        assert_eq!((at.line, at.col), (line, col), "{err}");
        let problem = err.problem().to_string();
        assert!(problem.contains(needle), "`{problem}` lacks `{needle}`");
    }

    fn plane(z0: f64, dzx: f64, dzy: f64, colour: u32, hyl: [bool; 3]) -> DlPlane {
        let [h, y, l] = hyl;
        DlPlane {
            z0,
            dzx,
            dzy,
            colour,
            h,
            y,
            l,
        }
    }

    fn assert_round_trip(list: &DisplayList) {
        assert_eq!(&parse(&list.to_text()).unwrap(), list);
    }

    #[test]
    fn thesis_cube() {
        let cube = parse(CUBE).unwrap();
        assert_eq!(cube.planes.len(), 6);
        assert_eq!(cube.terminator, 1234);
        let front = [true, false, false];
        let back = [false, false, false];
        assert_eq!(cube.planes[0], plane(46.06, -1.0, 1.18, 2, front));
        assert_eq!(cube.planes[1], plane(38.28, 1.0, 0.0, 1, back));
        assert_eq!(cube.planes[3], plane(328.24, -1.0, -1.68, 3, front));
        assert_eq!(cube.planes[5], plane(193.75, -1.0, 1.18, 4, back));
        assert!(!cube.is_concave());
        assert_round_trip(&cube);
    }

    #[test]
    fn thesis_box1() {
        let box1 = parse(BOX1).unwrap();
        assert_eq!(box1.planes.len(), 6);
        assert_eq!(box1.terminator, 1234);
        let colours: Vec<u32> = box1.planes.iter().map(|p| p.colour).collect();
        assert_eq!(colours, [5, 6, 3, 4, 1, 2]);
        // As printed: the 501.42 plane has H=1 although its parallel
        // partner 281.42 is also a front plane (box2 has H=0 there), so
        // box1 has four front planes and two back planes.
        let fronts: Vec<bool> = box1.planes.iter().map(|p| p.h).collect();
        assert_eq!(fronts, [true, false, true, true, true, false]);
        assert_eq!(box1.planes[2].z0, -127.27);
        assert_eq!(
            box1.planes[4],
            plane(501.42, -1.0, -1.41, 1, [true, false, false])
        );
        assert!(box1.planes.iter().all(|p| !p.y && !p.l));
        assert_round_trip(&box1);
    }

    #[test]
    fn thesis_box2() {
        let box2 = parse(BOX2).unwrap();
        assert_eq!(box2.planes.len(), 6);
        assert_eq!(box2.terminator, 1234);
        let colours: Vec<u32> = box2.planes.iter().map(|p| p.colour).collect();
        assert_eq!(colours, [2, 5, 6, 1, 3, 5]);
        let fronts: Vec<bool> = box2.planes.iter().map(|p| p.h).collect();
        assert_eq!(fronts, [true, false, true, true, false, false]);
        assert_eq!(box2.planes[1].z0, 14.14);
        assert_eq!(box2.planes[5], plane(258.57, -1.0, 1.41, 5, [false; 3]));
        assert!(!box2.is_concave());
        assert_round_trip(&box2);
    }

    #[test]
    fn ocr_layout_is_accepted() {
        // The thesis' box1 has a blank line inside a plane; the cube mixes
        // runs of spaces; comments may appear anywhere.
        let text = "# c\n\n58.57 \t -1.0  1.41\t5\n\n  # x\n1\t0\t0\t\n0 0 0 1234\n\n# end\n";
        let list = parse(text).unwrap();
        assert_eq!(
            list.planes,
            [plane(58.57, -1.0, 1.41, 5, [true, false, false])]
        );
    }

    #[test]
    fn canonical_text() {
        let list = DisplayList {
            planes: vec![plane(-0.5, 1.0, 1e-7, 0, [false, true, true])],
            terminator: 1001,
        };
        assert_eq!(
            list.to_text(),
            "-0.5\t1\t0.0000001\t0\n0\t1\t1\n0\t0\t0\t1001\n"
        );
        assert!(list.is_concave());
    }

    #[test]
    fn error_display() {
        let err = parse("1 2 x 4\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "t.dl:1:5: expected a finite number for dZy, found `x`"
        );
    }

    #[test]
    fn rejects_non_finite_numbers() {
        assert_error("nan 0 0 1\n1 0 0\n0 0 0 1234\n", 1, 1, "found `nan`");
        assert_error(
            "0 inf 0 1\n1 0 0\n0 0 0 1234\n",
            1,
            3,
            "finite number for dZx",
        );
        assert_error("0 0 1e999 1\n1 0 0\n0 0 0 1234\n", 1, 5, "found `1e999`");
        assert_error("0 0 0x1 1\n1 0 0\n0 0 0 1234\n", 1, 5, "found `0x1`");
    }

    #[test]
    fn rejects_bad_colours() {
        assert_error(
            "0 0 0 2.5\n1 0 0\n0 0 0 1234\n",
            1,
            7,
            "unsigned integer colour",
        );
        assert_error("0 0 0 -1\n1 0 0\n0 0 0 1234\n", 1, 7, "found `-1`");
        assert_error("0 0 0 99999999999\n", 1, 7, "out of range");
        assert_error("0 0 0 1\n1 0 0\n0 0 0 +1234\n", 3, 7, "found `+1234`");
    }

    #[test]
    fn accepts_background_colour() {
        assert_eq!(
            parse("0 0 0 0\n1 0 0\n0 0 0 1234\n").unwrap().planes[0].colour,
            0
        );
    }

    #[test]
    fn rejects_bad_flags() {
        assert_error(
            "0 0 0 1\n2 0 0\n0 0 0 1234\n",
            2,
            1,
            "0 or 1 for H, found `2`",
        );
        assert_error("0 0 0 1\n1 0.0 0\n0 0 0 1234\n", 2, 3, "0 or 1 for Y");
        assert_error("0 0 0 1\n1 0 01\n0 0 0 1234\n", 2, 5, "0 or 1 for L");
    }

    #[test]
    fn rejects_missing_fields() {
        assert_error("0 0\n", 1, 4, "expected dZy, found end of line");
        assert_error("0 0 0 \n", 1, 7, "expected colour, found end of line");
        assert_error(
            "0 0 0 1\n1\t0\n0 0 0 1234\n",
            2,
            4,
            "expected L, found end of line",
        );
    }

    #[test]
    fn rejects_extra_fields() {
        assert_error("0 0 0 1 7 8\n", 1, 9, "expected end of line, found `7`");
        assert_error("0 0 0 1\n1 0 0  0\n0 0 0 1234\n", 2, 8, "found `0`");
        assert_error("0 0 0 1\n1 0 0\n0 0 0 1234 5\n", 3, 12, "found `5`");
    }

    #[test]
    fn rejects_missing_terminator() {
        let msg = "expected a terminating entry with colour > 1000";
        assert_error("0 0 0 1\n1 0 0\n", 3, 1, msg);
        assert_error("0 0 0 1\n1 0 0\n\n# x", 4, 4, msg);
        assert_error("0 0 0 1\n1 0 0\n0 0 0 1000\n1 0 0", 4, 6, msg);
        assert_error(
            "0 0 0 1\n",
            2,
            1,
            "expected an H Y L row, found end of file",
        );
    }

    #[test]
    fn rejects_trailing_data() {
        assert_error(
            "0 0 0 1\n1 0 0\n0 0 0 1234\n0 0 0\n",
            4,
            1,
            "after the terminating",
        );
        assert_error("0 0 0 1\n1 0 0\n0 0 0 1234\n\n  x # y\n", 5, 3, "found `x`");
        assert!(parse("0 0 0 1\n1 0 0\n0 0 0 1234\n\n# fin\n").is_ok());
    }

    #[test]
    fn rejects_empty_list() {
        assert_error("", 1, 1, "empty display list");
        assert_error("# nothing\n\n", 3, 1, "empty display list");
        assert_error("\n0 0 0 1234\n", 2, 7, "empty display list");
    }

    #[test]
    fn rejects_mixed_concavity() {
        let text = "0 0 0 1\n1 0 1\n0 0 0 2\n0 0 1\n0 0 0 3\n0 0 0\n0 0 0 1234\n";
        assert_error(text, 6, 5, "expected L=1 as on line 2");
    }

    #[test]
    fn columns_count_characters() {
        assert_error("é\t0 0 1\n", 1, 1, "found `é`");
        assert_error("0 é 0 1\n", 1, 3, "found `é`");
        assert_error("é 0 0 1 ü\n", 1, 1, "Z0");
        assert_error("0 0 0 1 ü\n", 1, 9, "found `ü`");
    }

    #[test]
    fn read_reports_io_errors() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing.dl");
        let err = DisplayList::read(&path).unwrap_err();
        let at = err.location().expect("a located error");
        assert_eq!((at.line, at.col), (0, 0));
        assert!(at.file.ends_with("missing.dl"));
        std::fs::write(&path, CUBE).unwrap();
        assert_eq!(DisplayList::read(&path).unwrap(), parse(CUBE).unwrap());
    }

    fn finite() -> impl Strategy<Value = f64> {
        prop_oneof![
            any::<f64>().prop_filter("finite", |v| v.is_finite()),
            (-100_000i32..100_000).prop_map(|n| f64::from(n) / 100.0),
        ]
    }

    fn list_strategy() -> impl Strategy<Value = DisplayList> {
        let fields = (
            finite(),
            finite(),
            finite(),
            0..=MAX_PLANE_COLOUR,
            any::<[bool; 2]>(),
        );
        (
            prop::collection::vec(fields, 1..12),
            any::<bool>(),
            MAX_PLANE_COLOUR + 1..=u32::MAX,
        )
            .prop_map(|(planes, l, terminator)| DisplayList {
                planes: planes
                    .into_iter()
                    .map(|(z0, dzx, dzy, colour, [h, y])| plane(z0, dzx, dzy, colour, [h, y, l]))
                    .collect(),
                terminator,
            })
    }

    /// One byte-level edit: insert, delete or replace at a position.
    fn mutate(bytes: &mut Vec<u8>, (kind, at, byte): (u8, usize, u8)) {
        if bytes.is_empty() {
            bytes.push(byte);
            return;
        }
        let at = at % bytes.len();
        match kind % 3 {
            0 => bytes.insert(at, byte),
            1 => {
                bytes.remove(at);
            }
            _ => bytes[at] = byte,
        }
    }

    proptest! {
        #[test]
        fn round_trips(list in list_strategy()) {
            prop_assert_eq!(parse(&list.to_text()).unwrap(), list);
        }

        #[test]
        fn random_text_never_panics(text in "[ \t\r\n0-9.#e+-]{0,80}|(?s).{0,200}") {
            let _ = parse(&text);
        }

        #[test]
        fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
            let _ = parse(&String::from_utf8_lossy(&bytes));
        }

        #[test]
        fn mutated_thesis_files_never_panic(
            which in 0..3usize,
            edits in prop::collection::vec(
                (any::<u8>(), any::<usize>(), prop::sample::select(b" \t\n\r#0123456789.-+e1".to_vec())),
                1..8,
            ),
        ) {
            let mut bytes = [CUBE, BOX1, BOX2][which].as_bytes().to_vec();
            for edit in edits {
                mutate(&mut bytes, edit);
            }
            if let Err(err) = parse(&String::from_utf8_lossy(&bytes)) {
                let at = err.location().expect("a located error");
                prop_assert!(at.line >= 1 && at.col >= 1);
            }
        }
    }
}

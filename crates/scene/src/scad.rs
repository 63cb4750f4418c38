//! Reader for the OpenSCAD `.csg` subset csgpix draws and voxelizes: solids, 2D shapes under
//! extrusions, hulls and offsets under CSG operations, as OpenSCAD writes them with File →
//! Export → Export as CSG.
//!
//! # What is read
//!
//! Statements `name(args);`, `name(args) child` and `name(args) { children }`, `//` and `/* */`
//! comments, numbers, `true`, `false`, `undef`, strings and (nested) vectors, positional and
//! named arguments (`$fn = 0`). The nodes:
//!
//! * `group()`, `union()` → [`CsgNode::Union`]; `render(convexity = …)` is read as a group
//!   (it only asks OpenSCAD to cache the geometry, so ignoring it is harmless).
//! * `intersection()` → [`CsgNode::Intersection`], `difference()` → [`CsgNode::Difference`]
//!   (the first child minus the others).
//! * `multmatrix(m = 4×4)` transforms the solids below it (nested transforms compose). As in
//!   OpenSCAD's `multmatrix` module (`src/core/TransformNode.cc`) a matrix whose `m[3][3]` is
//!   not 1 is divided by it; a projective or singular matrix is refused. A matrix with a
//!   negative determinant (a mirror) reverses the winding of every face so faces stay outward.
//! * `color([r, g, b, a])` / `color(c = [r, g, b], alpha = a)` colours the solids below it,
//!   the innermost colour winning. Named and hex colours (`color("red")`) are refused: the CSG
//!   export always writes the vector form.
//! * `cube`, `sphere`, `cylinder` are tessellated exactly as OpenSCAD does (see below), and
//!   `polyhedron` is accepted when it is closed and convex.
//! * The modifiers `%` (background) and `*` (disable) drop the statement, as OpenSCAD leaves
//!   such nodes out of the rendered result; `#` (highlight) is ignored; `!` is refused.
//! * `import(file = "x.stl" | "x.obj" | "x.nrrd", threshold = t)` names a mesh or a dataset
//!   primitive ([`crate::solid::Import`], loaded by `csgpix_voxel::sampled`); `threshold` (ours, not
//!   OpenSCAD's) is a dataset's iso value.
//!
//! * 2D shapes `square`, `circle`, `polygon(points, paths)` (several paths filled even-odd:
//!   holes) under 2D `multmatrix`/`color`/`group`/`union`/`difference`/`intersection`, inside
//!   `linear_extrude(height, center, twist, slices, scale)` or `rotate_extrude(angle)`; a 2D
//!   shape outside an extrusion, or an operation mixing 2D and 3D children, is refused.
//!   Extrusions follow OpenSCAD 2021.01's layout ([`crate::extrude`]): an untwisted, evenly
//!   scaled extrusion of one convex outline is a convex solid; anything else is a closed mesh
//!   primitive (an [`Import`] holding its triangles), and a 2D boolean becomes the same boolean
//!   of the extruded shapes, except under a twist or uneven scale, where it is taken in the
//!   plane first.
//! * `hull()` of solids (one convex solid over their vertices; the solids leave the scene) or
//!   of 2D shapes (a convex outline); not of a difference or intersection.
//! * `offset(r | delta, chamfer)` of one convex outline, or outward of a union of them.
//!
//! Anything else (`minkowski`, `projection`, `text`, `surface`, 2D imports, …) is refused with
//! an error naming the node, its line and column. [`scene_text`] turns a `.scad` file into
//! this CSG text by running `openscad`.
//!
//! The tree is simplified without changing the solid it describes: a union or group with one
//! child is that child, unions inside unions (and intersections inside intersections) are
//! flattened, empty children are dropped from unions and from the subtracted part of a
//! difference, and an intersection with an empty child, or a difference whose first child is
//! empty, is [`CsgNode::Empty`]. This is the meaning OpenSCAD gives empty children when it
//! renders (F6); its preview (F5) skips empty children of an intersection instead.
//!
//! # Following OpenSCAD
//!
//! The tessellation follows OpenSCAD's source (read, not copied):
//!
//! * fragment count: `Calc::get_fragments_from_r` in `src/utils/calc.cc`, with `GRID_FINE`
//!   from `src/geometry/Grid.h` and the clamping of `$fa`/`$fs` to `F_MINIMUM = 0.01` from
//!   `set_fragments` in `src/core/primitives.cc`;
//! * vertex and face layout: `CubeNode::createGeometry`, `SphereNode::createGeometry`,
//!   `CylinderNode::createGeometry` and `generate_circle` in `src/core/primitives.cc` (the
//!   current layout with quads between sphere rings and a single apex for cones);
//! * angles: `sin_degrees`/`cos_degrees` in `src/utils/degree_trig.cc`, which are exact at
//!   multiples of 30° and 45°.
//!
//! OpenSCAD versions differ in details, and this reader picks one:
//!
//! * a fractional `$fn` is truncated (`get_fragments_from_r`, release 2021.01); the newer
//!   `CurveDiscretizer::getCircularSegmentCount` (`src/core/CurveDiscretizer.cc`) rounds it
//!   up instead;
//! * release 2021.01 splits the band between two sphere rings into triangles where newer
//!   versions use one quad per fragment, as here; the vertices are the same;
//! * away from multiples of 30° and 45°, angles are converted as `x * (π / 180)`; 2021.01
//!   computes `x * π / 180`, which can differ in the last bit.
//!
//! # Limits
//!
//! Every error names the line and column (1-based, counted in characters) of the offending
//! token. Statements nest at most [`MAX_NESTING`] deep and vectors [`MAX_VECTOR_NESTING`]
//! deep, so neither the reader nor code walking the tree recursively can overflow the stack;
//! a circle has at most [`MAX_FRAGMENTS`] fragments, a polyhedron at most
//! [`MAX_POLYHEDRON_POINTS`] points, a scene at most [`MAX_SCENE_VERTICES`] vertices, and no
//! coordinate may exceed [`MAX_COORDINATE`] in size.

use std::collections::{HashMap, VecDeque};
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::fmt;

use glam::{DVec2, DVec3};

use crate::extrude::{
    convex_prism, default_slices, flatten, linear_mesh, offset, region_points, rotate_mesh, Linear,
    Offset, Poly2, Region,
};
use crate::hull::hull3;
use crate::solid::{ConvexSolid, CsgNode, CsgScene, Import, IMPORTED};
use crate::Error;

/// Deepest nesting of statements accepted: a top-level statement is at depth 1, so a cube may
/// sit inside at most 999 groups.
pub const MAX_NESTING: usize = 1_000;

/// Deepest nesting of vectors accepted (matrices, points and faces need 2).
pub const MAX_VECTOR_NESTING: usize = 64;

/// Most fragments (points on a circle) a sphere or cylinder may have.
pub const MAX_FRAGMENTS: usize = 10_000;

/// Most vertices a whole scene may have (a sphere with `$fn = 1414` alone has about that).
pub const MAX_SCENE_VERTICES: usize = 1_000_000;

/// Most points a polyhedron may have (its convexity check takes points × faces steps).
pub const MAX_POLYHEDRON_POINTS: usize = 10_000;

/// Largest absolute coordinate of a placed solid, so that areas and volumes stay finite.
pub const MAX_COORDINATE: f64 = 1e12;

/// OpenSCAD's `GRID_FINE` (`src/geometry/Grid.h`): below this radius a circle has 3 fragments.
const GRID_FINE: f64 = 0.000_000_953_674_316_406_25;

/// OpenSCAD's `F_MINIMUM` (`src/core/primitives.cc`): `$fa` and `$fs` are clamped up to it.
const F_MINIMUM: f64 = 0.01;

/// How far (relative to the largest coordinate) a polyhedron point may lie outside a face
/// plane. OpenSCAD writes polyhedron coordinates with 6 significant digits, so faces of a
/// convex polyhedron can be that far from flat in an exported file.
const CONVEXITY_TOLERANCE: f64 = 1e-5;

/// The `.csg` text of a scene file: a `.csg` file as it is; a `.scad` file exported to CSG by
/// OpenSCAD (`openscad -o scene.csg FILE.scad` into a temporary directory, removed after),
/// when `openscad` is on PATH. Errors are one line naming the file.
pub fn scene_text(path: &std::path::Path) -> crate::Result<String> {
    let name = path.display();
    let scad = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("scad"));
    if !scad {
        return crate::input::read_text(path);
    }
    if !path.is_file() {
        return Err(Error::msg(format!("{name}: no such file")));
    }
    let dir = tempfile::tempdir()
        .map_err(|e| Error::msg(format!("{name}: a temporary directory: {e}")))?;
    let out = dir.path().join("scene.csg");
    let run = std::process::Command::new("openscad")
        .arg("-o")
        .arg(&out)
        .arg(path)
        .stdin(std::process::Stdio::null())
        .output();
    let run = match run {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(Error::msg(format!(
                "{name}: reading .scad needs openscad on PATH (Debian: apt-get install openscad); \
                 or export File → Export → Export as CSG and give the .csg"
            )))
        }
        Err(e) => return Err(Error::msg(format!("{name}: running openscad: {e}"))),
        Ok(run) => run,
    };
    let text = std::fs::read_to_string(&out)
        .ok()
        .filter(|_| run.status.success());
    text.ok_or_else(|| {
        let stderr = String::from_utf8_lossy(&run.stderr);
        let line = stderr
            .lines()
            .find(|l| l.contains("ERROR"))
            .or_else(|| stderr.lines().rfind(|l| !l.trim().is_empty()))
            .unwrap_or("no output");
        Error::msg(format!(
            "{name}: openscad could not export it: {}",
            line.trim()
        ))
    })
}

/// Reads a `.csg` file's text into a scene; `file` is only used in error messages.
///
/// # Errors
///
/// The first problem, at its line and column in `file`.
///
/// # Examples
///
/// ```
/// use csgpix_scene::scad::parse_csg;
/// use csgpix_scene::solid::CsgNode;
///
/// let text = "difference() {\n  cube(size = [2, 2, 2], center = true);\n  \
///             sphere($fn = 8, r = 1.2);\n}\n";
/// let scene = parse_csg(text, "scene.csg")?;
/// assert_eq!(scene.solids.len(), 2);
/// assert!(matches!(scene.root, CsgNode::Difference(ref c) if c.len() == 2));
///
/// let err = parse_csg("cube(size = [1, 1]);", "bad.csg").unwrap_err();
/// assert!(err.to_string().starts_with("bad.csg:1:"));
/// # Ok::<(), csgpix_scene::Error>(())
/// ```
pub fn parse_csg(text: &str, file: &str) -> crate::Result<CsgScene> {
    Reader::new(text)
        .run()
        .map_err(|fail| Error::at(file, fail.pos.line, fail.pos.col, fail.msg))
}

// ---------------------------------------------------------------------------------------------
// Tokens

/// A 1-based line and column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Pos {
    line: usize,
    col: usize,
}

impl fmt::Display for Pos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.col)
    }
}

/// An error before the file name is attached.
#[derive(Debug)]
struct Fail {
    pos: Pos,
    msg: String,
}

fn fail<T>(pos: Pos, msg: impl Into<String>) -> Result<T, Fail> {
    Err(Fail {
        pos,
        msg: msg.into(),
    })
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Num(f64),
    Str(String),
    /// One of `( ) [ ] { } , ; = - + % # ! *`.
    Sym(u8),
    Eof,
}

impl Tok {
    fn describe(&self) -> String {
        match self {
            Tok::Ident(name) => format!("`{name}`"),
            Tok::Num(_) => "a number".to_string(),
            Tok::Str(_) => "a string".to_string(),
            Tok::Sym(c) => format!("'{}'", *c as char),
            Tok::Eof => "end of file".to_string(),
        }
    }
}

#[derive(Clone, Debug)]
struct Token {
    tok: Tok,
    pos: Pos,
}

/// Splits the text into tokens, skipping white space and comments.
struct Lexer<'a> {
    text: &'a str,
    at: usize,
    pos: Pos,
}

impl<'a> Lexer<'a> {
    fn new(text: &'a str) -> Self {
        let at = if text.starts_with('\u{feff}') { 3 } else { 0 };
        Lexer {
            text,
            at,
            pos: Pos { line: 1, col: 1 },
        }
    }

    fn byte(&self, ahead: usize) -> Option<u8> {
        self.text.as_bytes().get(self.at + ahead).copied()
    }

    /// Moves past one byte; columns count characters, not UTF-8 continuation bytes.
    fn bump(&mut self) {
        if let Some(b) = self.byte(0) {
            self.at += 1;
            if b == b'\n' {
                self.pos.line += 1;
                self.pos.col = 1;
            } else if b & 0xC0 != 0x80 {
                self.pos.col += 1;
            }
        }
    }

    fn bump_while(&mut self, pred: impl Fn(u8) -> bool) -> usize {
        let start = self.at;
        while self.byte(0).is_some_and(&pred) {
            self.bump();
        }
        self.at - start
    }

    fn next_token(&mut self) -> Result<Token, Fail> {
        self.skip_trivia()?;
        let pos = self.pos;
        let tok = match self.byte(0) {
            None => Tok::Eof,
            Some(b) if b.is_ascii_alphabetic() || b == b'_' || b == b'$' => self.ident(),
            Some(b) if b.is_ascii_digit() => self.number(pos)?,
            Some(b'.') if self.byte(1).is_some_and(|b| b.is_ascii_digit()) => self.number(pos)?,
            Some(b'"') => self.string(pos)?,
            Some(b) if b"()[]{},;=-+%#!*".contains(&b) => {
                self.bump();
                Tok::Sym(b)
            }
            Some(_) => {
                let c = self.text.get(self.at..).and_then(|s| s.chars().next());
                return fail(pos, format!("unexpected character {:?}", c.unwrap_or('?')));
            }
        };
        Ok(Token { tok, pos })
    }

    fn skip_trivia(&mut self) -> Result<(), Fail> {
        loop {
            match (self.byte(0), self.byte(1)) {
                (Some(b' ' | b'\t' | b'\r' | b'\n' | 0x0c), _) => self.bump(),
                (Some(b'/'), Some(b'/')) => {
                    self.bump_while(|b| b != b'\n');
                }
                (Some(b'/'), Some(b'*')) => self.block_comment()?,
                _ => return Ok(()),
            }
        }
    }

    fn block_comment(&mut self) -> Result<(), Fail> {
        let start = self.pos;
        self.bump();
        self.bump();
        loop {
            match (self.byte(0), self.byte(1)) {
                (Some(b'*'), Some(b'/')) => {
                    self.bump();
                    self.bump();
                    return Ok(());
                }
                (Some(_), _) => self.bump(),
                (None, _) => return fail(start, "unterminated comment (missing `*/`)"),
            }
        }
    }

    fn ident(&mut self) -> Tok {
        let start = self.at;
        self.bump();
        self.bump_while(|b| b.is_ascii_alphanumeric() || b == b'_');
        Tok::Ident(self.text[start..self.at].to_string())
    }

    /// `12`, `-` is a separate token, `1.5`, `.5`, `5.`, `1e-3`, `2.5E+10`.
    fn number(&mut self, pos: Pos) -> Result<Tok, Fail> {
        let start = self.at;
        self.bump_while(|b| b.is_ascii_digit());
        if self.byte(0) == Some(b'.') {
            self.bump();
            self.bump_while(|b| b.is_ascii_digit());
        }
        if matches!(self.byte(0), Some(b'e' | b'E')) {
            self.bump();
            if matches!(self.byte(0), Some(b'+' | b'-')) {
                self.bump();
            }
            if self.bump_while(|b| b.is_ascii_digit()) == 0 {
                return self.bad_number(start, pos);
            }
        }
        if self.byte(0).is_some_and(continues_number) {
            return self.bad_number(start, pos);
        }
        let text = &self.text[start..self.at];
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Tok::Num(v)),
            Ok(_) => fail(pos, format!("number `{text}` is out of range")),
            Err(_) => self.bad_number(start, pos),
        }
    }

    fn bad_number(&mut self, start: usize, pos: Pos) -> Result<Tok, Fail> {
        self.bump_while(continues_number);
        fail(
            pos,
            format!("malformed number `{}`", &self.text[start..self.at]),
        )
    }

    fn string(&mut self, pos: Pos) -> Result<Tok, Fail> {
        self.bump();
        let mut bytes = Vec::new();
        loop {
            let Some(b) = self.byte(0) else {
                return fail(pos, "unterminated string (missing `\"`)");
            };
            self.bump();
            match b {
                b'"' => return Ok(Tok::Str(String::from_utf8_lossy(&bytes).into_owned())),
                b'\\' => {
                    let escaped = self.byte(0).unwrap_or(b'\\');
                    self.bump();
                    bytes.push(match escaped {
                        b'n' => b'\n',
                        b't' => b'\t',
                        b'r' => b'\r',
                        other => other,
                    });
                }
                other => bytes.push(other),
            }
        }
    }
}

fn continues_number(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'_' | b'.' | b'$')
}

// ---------------------------------------------------------------------------------------------
// Values and arguments

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Num(f64),
    Bool(bool),
    Undef,
    Str(String),
    List(Vec<Value>),
}

/// A value and where it starts.
#[derive(Clone, Debug, PartialEq)]
struct Value {
    kind: Kind,
    pos: Pos,
}

impl Value {
    fn number(&self, what: &str) -> Result<f64, Fail> {
        match self.kind {
            Kind::Num(v) => Ok(v),
            _ => fail(self.pos, format!("{what} must be a number")),
        }
    }

    fn list(&self, what: &str) -> Result<&[Value], Fail> {
        match &self.kind {
            Kind::List(items) => Ok(items),
            _ => fail(self.pos, format!("{what} must be a vector")),
        }
    }

    /// A number for both, or `[x, y]` (`scale`, a square's `size`).
    fn pair(&self, what: &str) -> Result<[f64; 2], Fail> {
        match &self.kind {
            Kind::Num(s) => Ok([*s, *s]),
            _ => match self.list(what)? {
                [x, y] => Ok([x.number(what)?, y.number(what)?]),
                _ => fail(self.pos, format!("{what} must be a number or [x, y]")),
            },
        }
    }

    fn vec3(&self, what: &str) -> Result<Vec3, Fail> {
        match self.list(what)? {
            [x, y, z] => Ok([x.number(what)?, y.number(what)?, z.number(what)?]),
            _ => fail(self.pos, format!("{what} must be [x, y, z]")),
        }
    }
}

/// One argument of a node: `name = value` or a positional value.
struct Arg {
    name: Option<(String, Pos)>,
    value: Value,
}

/// Tokens with look-ahead, and the values and argument lists made of them.
struct Parser<'a> {
    lexer: Lexer<'a>,
    ahead: VecDeque<Token>,
}

impl<'a> Parser<'a> {
    fn new(text: &'a str) -> Self {
        Parser {
            lexer: Lexer::new(text),
            ahead: VecDeque::new(),
        }
    }

    fn peek_nth(&mut self, n: usize) -> Result<&Token, Fail> {
        while self.ahead.len() <= n {
            let token = self.lexer.next_token()?;
            self.ahead.push_back(token);
        }
        Ok(&self.ahead[n])
    }

    fn peek(&mut self) -> Result<&Token, Fail> {
        self.peek_nth(0)
    }

    fn next(&mut self) -> Result<Token, Fail> {
        match self.ahead.pop_front() {
            Some(token) => Ok(token),
            None => self.lexer.next_token(),
        }
    }

    fn at_sym(&mut self, c: u8) -> Result<bool, Fail> {
        Ok(self.peek()?.tok == Tok::Sym(c))
    }

    /// Consumes the symbol `c` if it comes next; returns its position.
    fn eat_sym(&mut self, c: u8) -> Result<Option<Pos>, Fail> {
        if self.at_sym(c)? {
            Ok(Some(self.next()?.pos))
        } else {
            Ok(None)
        }
    }

    fn expect_sym(&mut self, c: u8, context: &str) -> Result<Pos, Fail> {
        let token = self.next()?;
        if token.tok == Tok::Sym(c) {
            Ok(token.pos)
        } else {
            let found = token.tok.describe();
            fail(
                token.pos,
                format!("expected '{}' {context}, found {found}", c as char),
            )
        }
    }

    /// `( [name =] value, … )`
    fn args(&mut self, node: &str) -> Result<Vec<Arg>, Fail> {
        self.expect_sym(b'(', &format!("after `{node}`"))?;
        let mut args = Vec::new();
        loop {
            if self.eat_sym(b')')?.is_some() {
                return Ok(args);
            }
            let name = self.arg_name()?;
            let value = self.value()?;
            args.push(Arg { name, value });
            let token = self.next()?;
            match token.tok {
                Tok::Sym(b',') => {}
                Tok::Sym(b')') => return Ok(args),
                other => {
                    let msg = format!(
                        "expected ',' or ')' in the arguments of `{node}`, found {}",
                        other.describe()
                    );
                    return fail(token.pos, msg);
                }
            }
        }
    }

    /// The `name =` of a named argument, if the next two tokens are one.
    fn arg_name(&mut self) -> Result<Option<(String, Pos)>, Fail> {
        let Tok::Ident(name) = &self.peek()?.tok else {
            return Ok(None);
        };
        let name = name.clone();
        if self.peek_nth(1)?.tok != Tok::Sym(b'=') {
            return Ok(None);
        }
        let pos = self.next()?.pos;
        self.next()?;
        Ok(Some((name, pos)))
    }

    /// A value, vectors included; nested vectors are read with an explicit stack.
    fn value(&mut self) -> Result<Value, Fail> {
        let mut open: Vec<(Pos, Vec<Value>)> = Vec::new();
        loop {
            let token = self.next()?;
            if token.tok == Tok::Sym(b'[') && !self.at_sym(b']')? {
                if open.len() >= MAX_VECTOR_NESTING {
                    let msg = format!("vectors nested deeper than {MAX_VECTOR_NESTING} levels");
                    return fail(token.pos, msg);
                }
                open.push((token.pos, Vec::new()));
                continue;
            }
            let element = self.scalar_or_empty(token)?;
            if let Some(value) = self.attach(&mut open, element)? {
                return Ok(value);
            }
        }
    }

    /// Adds a finished element to the innermost open vector, closing the vectors that end after
    /// it; returns the whole value once nothing is left open.
    fn attach(
        &mut self,
        open: &mut Vec<(Pos, Vec<Value>)>,
        mut done: Value,
    ) -> Result<Option<Value>, Fail> {
        while let Some((pos, mut items)) = open.pop() {
            items.push(done);
            let token = self.next()?;
            let closed = match token.tok {
                Tok::Sym(b',') => self.eat_sym(b']')?.is_some(),
                Tok::Sym(b']') => true,
                other => {
                    let found = other.describe();
                    let msg = format!("expected ',' or ']' in a vector, found {found}");
                    return fail(token.pos, msg);
                }
            };
            if !closed {
                open.push((pos, items));
                return Ok(None);
            }
            done = Value {
                kind: Kind::List(items),
                pos,
            };
        }
        Ok(Some(done))
    }

    /// A number, boolean, `undef`, string or `[]`, starting with `token`.
    fn scalar_or_empty(&mut self, token: Token) -> Result<Value, Fail> {
        let pos = token.pos;
        let kind = match token.tok {
            Tok::Num(v) => Kind::Num(v),
            Tok::Str(s) => Kind::Str(s),
            Tok::Sym(b'[') => {
                self.next()?; // the ']'
                Kind::List(Vec::new())
            }
            Tok::Sym(sign @ (b'-' | b'+')) => {
                let token = self.next()?;
                match token.tok {
                    Tok::Num(v) if sign == b'-' => Kind::Num(-v),
                    Tok::Num(v) => Kind::Num(v),
                    other => {
                        let msg = format!(
                            "expected a number after '{}', found {}",
                            sign as char,
                            other.describe()
                        );
                        return fail(token.pos, msg);
                    }
                }
            }
            Tok::Ident(name) => match name.as_str() {
                "true" => Kind::Bool(true),
                "false" => Kind::Bool(false),
                "undef" => Kind::Undef,
                "inf" | "nan" => {
                    return fail(pos, format!("numbers must be finite, found `{name}`"))
                }
                _ => {
                    let msg = format!(
                        "expected a value, found `{name}` (csgpix reads numbers, true, false, \
                         undef, strings and vectors, not expressions)"
                    );
                    return fail(pos, msg);
                }
            },
            other => return fail(pos, format!("expected a value, found {}", other.describe())),
        };
        Ok(Value { kind, pos })
    }
}

// ---------------------------------------------------------------------------------------------
// Nodes and their parameters

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum NodeKind {
    Group,
    Union,
    Difference,
    Intersection,
    Render,
    Multmatrix,
    Color,
    Cube,
    Sphere,
    Cylinder,
    Polyhedron,
    Import,
    Square,
    Circle,
    Polygon,
    LinearExtrude,
    RotateExtrude,
    Hull,
    Offset,
}

/// How the children of an operation combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Op {
    Union,
    Intersection,
    Difference,
}

/// Every node this reader understands, by name.
const NODES: [(&str, NodeKind); 19] = [
    ("group", NodeKind::Group),
    ("union", NodeKind::Union),
    ("difference", NodeKind::Difference),
    ("intersection", NodeKind::Intersection),
    ("multmatrix", NodeKind::Multmatrix),
    ("color", NodeKind::Color),
    ("render", NodeKind::Render),
    ("cube", NodeKind::Cube),
    ("sphere", NodeKind::Sphere),
    ("cylinder", NodeKind::Cylinder),
    ("polyhedron", NodeKind::Polyhedron),
    ("import", NodeKind::Import),
    ("square", NodeKind::Square),
    ("circle", NodeKind::Circle),
    ("polygon", NodeKind::Polygon),
    ("linear_extrude", NodeKind::LinearExtrude),
    ("rotate_extrude", NodeKind::RotateExtrude),
    ("hull", NodeKind::Hull),
    ("offset", NodeKind::Offset),
];

impl NodeKind {
    fn from_name(name: &str) -> Option<Self> {
        NODES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, kind)| kind)
    }

    fn name(self) -> &'static str {
        NODES
            .iter()
            .find(|(_, kind)| *kind == self)
            .map_or("?", |(name, _)| name)
    }

    /// Parameters taken by position (in OpenSCAD's order), then those taken only by name.
    fn parameters(self) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            NodeKind::Group
            | NodeKind::Union
            | NodeKind::Difference
            | NodeKind::Intersection
            | NodeKind::Hull => (&[], &[]),
            NodeKind::Square => (&["size", "center"], &[]),
            NodeKind::Circle => (&["r"], &["d", "$fn", "$fa", "$fs"]),
            NodeKind::Polygon => (&["points", "paths", "convexity"], &[]),
            NodeKind::LinearExtrude => (
                &["height", "center", "convexity", "twist", "slices", "scale"],
                &["v", "$fn", "$fa", "$fs"],
            ),
            NodeKind::RotateExtrude => (&["angle", "convexity"], &["$fn", "$fa", "$fs"]),
            NodeKind::Offset => (&["r"], &["delta", "chamfer", "$fn", "$fa", "$fs"]),
            NodeKind::Render => (&["convexity"], &[]),
            NodeKind::Multmatrix => (&["m"], &[]),
            NodeKind::Color => (&["c", "alpha"], &[]),
            NodeKind::Cube => (&["size", "center"], &[]),
            NodeKind::Sphere => (&["r"], &["d", "$fn", "$fa", "$fs"]),
            NodeKind::Cylinder => (
                &["h", "r1", "r2", "center"],
                &["r", "d", "d1", "d2", "$fn", "$fa", "$fs"],
            ),
            NodeKind::Polyhedron => (&["points", "faces", "convexity"], &["triangles"]),
            // OpenSCAD's own parameters (read and ignored: they concern 2D files), and ours.
            NodeKind::Import => (
                &["file", "layer", "convexity"],
                &[
                    "origin",
                    "scale",
                    "center",
                    "dpi",
                    "id",
                    "timestamp",
                    "$fn",
                    "$fa",
                    "$fs",
                    "threshold",
                ],
            ),
        }
    }

    fn is_leaf(self) -> bool {
        matches!(
            self,
            NodeKind::Cube
                | NodeKind::Sphere
                | NodeKind::Cylinder
                | NodeKind::Polyhedron
                | NodeKind::Import
                | NodeKind::Square
                | NodeKind::Circle
                | NodeKind::Polygon
        )
    }

    /// Leaves of the plane (2D shapes).
    fn is_flat(self) -> bool {
        matches!(
            self,
            NodeKind::Square | NodeKind::Circle | NodeKind::Polygon
        )
    }

    fn op(self) -> Op {
        match self {
            NodeKind::Difference => Op::Difference,
            NodeKind::Intersection => Op::Intersection,
            _ => Op::Union,
        }
    }
}

/// A node's arguments bound to its parameter names.
struct Params {
    node: NodeKind,
    pos: Pos,
    values: Vec<(&'static str, Value)>,
}

impl Params {
    /// Binds arguments as OpenSCAD's `Parameters::parse` does: positional ones in order,
    /// named ones by name; unknown names and repeated parameters are refused.
    fn bind(node: NodeKind, pos: Pos, args: Vec<Arg>) -> Result<Self, Fail> {
        let (positional, named) = node.parameters();
        let mut values: Vec<(&'static str, Value)> = Vec::new();
        let mut next_positional = positional.iter();
        for arg in args {
            let (name, at) = match &arg.name {
                Some((name, at)) => {
                    let known = positional.iter().chain(named).find(|p| **p == name);
                    let Some(&known) = known else {
                        return fail(*at, Self::unknown(node, name));
                    };
                    (known, *at)
                }
                None => match next_positional.next() {
                    Some(&name) => (name, arg.value.pos),
                    None => {
                        let msg = format!("too many positional arguments for `{}`", node.name());
                        return fail(arg.value.pos, msg);
                    }
                },
            };
            if values.iter().any(|(n, _)| *n == name) {
                return fail(at, format!("argument `{name}` given twice"));
            }
            values.push((name, arg.value));
        }
        Ok(Params { node, pos, values })
    }

    fn unknown(node: NodeKind, name: &str) -> String {
        let (positional, named) = node.parameters();
        let all: Vec<&str> = positional.iter().chain(named).copied().collect();
        if all.is_empty() {
            format!("`{}` takes no arguments, found `{name}`", node.name())
        } else {
            let list = all.join(", ");
            format!(
                "`{}` has no parameter `{name}` (it takes {list})",
                node.name()
            )
        }
    }

    /// The value of a parameter; `undef` counts as not given.
    fn get(&self, name: &str) -> Option<&Value> {
        self.values
            .iter()
            .find(|(n, v)| *n == name && v.kind != Kind::Undef)
            .map(|(_, v)| v)
    }

    fn number(&self, name: &str) -> Result<Option<(f64, Pos)>, Fail> {
        match self.get(name) {
            None => Ok(None),
            Some(v) => Ok(Some((v.number(&format!("`{name}`"))?, v.pos))),
        }
    }

    fn boolean(&self, name: &str) -> Result<bool, Fail> {
        match self.get(name) {
            None => Ok(false),
            Some(Value {
                kind: Kind::Bool(b),
                ..
            }) => Ok(*b),
            Some(v) => fail(v.pos, format!("`{name}` must be true or false")),
        }
    }

    fn require(&self, name: &str, usage: &str) -> Result<&Value, Fail> {
        self.get(name).ok_or_else(|| Fail {
            pos: self.pos,
            msg: format!("`{}` needs {usage}", self.node.name()),
        })
    }
}

/// A statement up to its children: modifiers, node name and arguments.
struct Head {
    kind: NodeKind,
    pos: Pos,
    params: Params,
    /// `%` or `*`: the statement is left out of the result.
    skip: bool,
}

// ---------------------------------------------------------------------------------------------
// Statements, read with an explicit stack of open nodes

/// What the solids below a node inherit.
#[derive(Clone, Debug, Default)]
struct Ctx {
    /// `None` is the identity.
    matrix: Option<Mat4>,
    colour: Option<[f64; 4]>,
    skip: bool,
}

/// How an open operation's children end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Closer {
    /// `{ … }`, opened at this position.
    Brace(Pos),
    /// A single child statement: `multmatrix(…) cube(…);`
    Single,
}

/// An operation whose children are being read.
struct Frame {
    kind: NodeKind,
    closer: Closer,
    ctx: Ctx,
    children: Vec<CsgNode>,
    /// 2D children (shapes in the plane of the nearest extrusion), and where the first
    /// 2D shape among them stands.
    flats: Vec<Region>,
    first_flat: Option<Pos>,
    /// Where the node stands, for messages.
    pos: Pos,
    /// An extrusion's or offset's parameters, read when it opened.
    spec: Spec,
    /// The transform above an extrusion (its children start from the identity).
    placement: Option<Mat4>,
}

/// What a finished statement gives its parent: a solid's tree or a 2D region.
enum Item {
    Solid(CsgNode),
    Flat(Region, Pos),
}

/// The parameters of the nodes that act on 2D children.
#[derive(Clone, Copy, Debug)]
enum Spec {
    None,
    Linear(LinearArgs),
    Rotate { angle: f64, res: (f64, f64, f64) },
    Offset(Offset),
}

/// `linear_extrude` as read: the slices may be left to OpenSCAD's rule.
#[derive(Clone, Copy, Debug)]
struct LinearArgs {
    linear: Linear,
    slices: Option<usize>,
    res: (f64, f64, f64),
}

/// What comes next at a statement position.
enum Next {
    Eof,
    CloseBrace,
    Semicolon,
    Statement,
}

struct Reader<'a> {
    parser: Parser<'a>,
    solids: Vec<ConvexSolid>,
    /// Leaves `Solid(IMPORTED + j)` until the end, when they become `Solid(solids + j)`.
    imports: Vec<Import>,
    vertices: usize,
    open: Vec<Frame>,
    top: Vec<CsgNode>,
    /// Solids and imports a `hull()` took in: they leave the scene at the end.
    consumed_solids: Vec<usize>,
    consumed_imports: Vec<usize>,
}

impl<'a> Reader<'a> {
    fn new(text: &'a str) -> Self {
        Reader {
            parser: Parser::new(text),
            solids: Vec::new(),
            imports: Vec::new(),
            vertices: 0,
            open: Vec::new(),
            top: Vec::new(),
            consumed_solids: Vec::new(),
            consumed_imports: Vec::new(),
        }
    }

    fn run(mut self) -> Result<CsgScene, Fail> {
        loop {
            let token = self.parser.peek()?;
            let pos = token.pos;
            let next = match token.tok {
                Tok::Eof => Next::Eof,
                Tok::Sym(b'}') => Next::CloseBrace,
                Tok::Sym(b';') => Next::Semicolon,
                _ => Next::Statement,
            };
            match next {
                Next::Eof => return self.end(pos),
                Next::CloseBrace => self.close_brace(pos)?,
                Next::Semicolon => {
                    self.parser.next()?;
                    self.empty_statement()?;
                }
                Next::Statement => self.statement(pos)?,
            }
        }
    }

    fn end(mut self, pos: Pos) -> Result<CsgScene, Fail> {
        match self.open.pop() {
            None => {
                let mut root = combine(Op::Union, std::mem::take(&mut self.top));
                let (solids, imports) = self.drop_consumed(&mut root);
                root.number_imports_after(solids.len());
                Ok(CsgScene {
                    solids,
                    imports,
                    root,
                })
            }
            Some(frame) => fail(pos, unclosed(&frame, "end of file")),
        }
    }

    fn close_brace(&mut self, pos: Pos) -> Result<(), Fail> {
        match self.open.last() {
            None => fail(pos, "unexpected '}' (no '{' is open)"),
            Some(frame) if frame.closer == Closer::Single => fail(pos, unclosed(frame, "'}'")),
            Some(_) => {
                self.parser.next()?;
                let node = self.pop_and_finish()?;
                self.deliver(node)
            }
        }
    }

    /// A lone `;`: nothing inside braces, no children after `group()`.
    fn empty_statement(&mut self) -> Result<(), Fail> {
        if self.open.last().is_some_and(|f| f.closer == Closer::Single) {
            let node = self.pop_and_finish()?;
            self.deliver(node)?;
        }
        Ok(())
    }

    fn statement(&mut self, pos: Pos) -> Result<(), Fail> {
        if self.open.len() >= MAX_NESTING {
            return fail(
                pos,
                format!("statements nested deeper than {MAX_NESTING} levels"),
            );
        }
        let head = self.head()?;
        let parent = self.open.last().map(|f| f.ctx.clone()).unwrap_or_default();
        let ctx = child_ctx(&parent, &head)?;
        if head.kind.is_leaf() {
            let context = format!("after `{}(…)` (it takes no children)", head.kind.name());
            self.parser.expect_sym(b';', &context)?;
            let node = self.leaf(&head, &ctx)?;
            return self.deliver(node);
        }
        let closer = match self.parser.eat_sym(b'{')? {
            Some(brace) => Closer::Brace(brace),
            None => Closer::Single,
        };
        let spec = flat_spec(&head)?;
        let mut ctx = ctx;
        let placement = match head.kind {
            NodeKind::LinearExtrude | NodeKind::RotateExtrude => ctx.matrix.take(),
            _ => None,
        };
        self.open.push(Frame {
            kind: head.kind,
            closer,
            ctx,
            children: Vec::new(),
            flats: Vec::new(),
            first_flat: None,
            pos: head.pos,
            spec,
            placement,
        });
        Ok(())
    }

    /// Modifiers, name and arguments of a statement.
    fn head(&mut self) -> Result<Head, Fail> {
        let mut skip = false;
        let token = loop {
            let token = self.parser.next()?;
            match token.tok {
                Tok::Sym(b'%' | b'*') => skip = true,
                Tok::Sym(b'#') => {}
                Tok::Sym(b'!') => return fail(token.pos, "the root modifier '!' is not supported"),
                _ => break token,
            }
        };
        let Tok::Ident(name) = &token.tok else {
            let found = token.tok.describe();
            return fail(
                token.pos,
                format!("expected a statement such as `group() {{`, found {found}"),
            );
        };
        let Some(kind) = NodeKind::from_name(name) else {
            return fail(token.pos, unsupported(name));
        };
        let args = self.parser.args(name)?;
        let params = Params::bind(kind, token.pos, args)?;
        Ok(Head {
            kind,
            pos: token.pos,
            params,
            skip,
        })
    }

    /// Hands a finished node (or nothing, for a skipped one) to the open operation, closing
    /// the single-child operations it completes. A 2D shape outside every extrusion is
    /// refused where it stands.
    fn deliver(&mut self, mut node: Option<Item>) -> Result<(), Fail> {
        loop {
            let Some(frame) = self.open.last_mut() else {
                return match node {
                    Some(Item::Flat(_, pos)) => fail(
                        pos,
                        "a 2D shape outside linear_extrude or rotate_extrude: csgpix voxelizes solids",
                    ),
                    Some(Item::Solid(n)) => {
                        self.top.push(n);
                        Ok(())
                    }
                    None => Ok(()),
                };
            };
            match node {
                Some(Item::Solid(n)) => frame.children.push(n),
                Some(Item::Flat(r, at)) => {
                    frame.flats.push(r);
                    frame.first_flat.get_or_insert(at);
                }
                None => {}
            }
            if frame.closer != Closer::Single {
                return Ok(());
            }
            node = self.pop_and_finish()?;
        }
    }

    /// Closes the innermost open operation: what it gives its parent (nothing when skipped).
    fn pop_and_finish(&mut self) -> Result<Option<Item>, Fail> {
        let Some(frame) = self.open.pop() else {
            return Ok(None);
        };
        if frame.ctx.skip {
            return Ok(None);
        }
        let (kind, pos) = (frame.kind, frame.pos);
        let mixed = !frame.children.is_empty() && !frame.flats.is_empty();
        if mixed {
            return fail(pos, format!("`{}` mixes 2D and 3D children", kind.name()));
        }
        let flat_at = frame.first_flat.unwrap_or(pos);
        match kind {
            NodeKind::LinearExtrude | NodeKind::RotateExtrude if !frame.children.is_empty() => {
                fail(
                    pos,
                    format!("`{}` takes 2D children, found a solid", kind.name()),
                )
            }
            NodeKind::LinearExtrude | NodeKind::RotateExtrude => self.extrude(frame).map(Some),
            NodeKind::Hull if frame.flats.is_empty() => self.hull3(frame).map(Some),
            NodeKind::Hull => hull_flat(frame),
            NodeKind::Offset => offset_flat(frame),
            _ if !frame.flats.is_empty() => {
                Ok(Some(Item::Flat(region_of(kind.op(), frame.flats), flat_at)))
            }
            _ => Ok(Some(Item::Solid(combine(kind.op(), frame.children)))),
        }
    }

    fn leaf(&mut self, head: &Head, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        if head.kind == NodeKind::Import {
            let import = import(head, ctx)?;
            if ctx.skip {
                return Ok(None);
            }
            self.imports.push(import);
            return Ok(Some(Item::Solid(CsgNode::Solid(
                IMPORTED + self.imports.len() - 1,
            ))));
        }
        let budget = MAX_SCENE_VERTICES.saturating_sub(self.vertices);
        if head.kind.is_flat() {
            let poly = flat_shape(&head.params, budget)?;
            let n = poly.points().count();
            check_budget(n, budget, head.pos)?;
            if ctx.skip {
                return Ok(None);
            }
            self.vertices += n;
            let poly = poly.transformed(plane_part(ctx.matrix.as_ref()));
            return Ok(Some(Item::Flat(Region::Poly(poly), head.pos)));
        }
        let shape = match head.kind {
            NodeKind::Cube => cube(&head.params)?,
            NodeKind::Sphere => sphere(&head.params, budget)?,
            NodeKind::Cylinder => cylinder(&head.params, budget)?,
            _ => polyhedron(&head.params, budget)?,
        };
        check_budget(shape.vertices.len(), budget, head.pos)?;
        if ctx.skip {
            return Ok(None);
        }
        let solid = place(shape, ctx, head.pos)?;
        self.vertices += solid.vertices.len();
        self.solids.push(solid);
        Ok(Some(Item::Solid(CsgNode::Solid(self.solids.len() - 1))))
    }

    /// A finished `linear_extrude` or `rotate_extrude`: the CSG tree of its 2D children's
    /// tree, each shape extruded (module [`crate::extrude`]).
    fn extrude(&mut self, frame: Frame) -> Result<Item, Fail> {
        let pos = frame.pos;
        if frame.flats.is_empty() {
            return Ok(Item::Solid(CsgNode::Empty));
        }
        let mut region = region_of(Op::Union, frame.flats);
        // Twisted or unevenly scaled walls are triangulated between slices, which does not
        // commute with booleans: those take the booleans in the plane first, as OpenSCAD.
        let triangulated = matches!(frame.spec, Spec::Linear(a) if !a.linear.keeps_convex());
        if triangulated && !matches!(region, Region::Poly(_)) {
            region = Region::Poly(flatten(&region));
        }
        let mut pts = vec![];
        collect_points(&region, &mut pts);
        let how = match frame.spec {
            Spec::Linear(a) => Extrusion::Linear(linear_slices(a, &pts)),
            Spec::Rotate { angle, res } => {
                let r = pts.iter().map(|p| p.x.abs()).fold(0.0, f64::max);
                let res = Resolution {
                    fn_: res.0,
                    fa: res.1,
                    fs: res.2,
                };
                let f = (res.fragments_from_r(r) * angle.abs() / 360.0).max(1.0);
                if f > MAX_FRAGMENTS as f64 {
                    let msg =
                        format!("{f} fragments is more than the {MAX_FRAGMENTS} csgpix accepts");
                    return fail(pos, msg);
                }
                Extrusion::Rotate {
                    angle,
                    fragments: f as usize,
                }
            }
            _ => return fail(pos, "internal: an extrusion without its parameters"),
        };
        let to = Placement {
            matrix: frame.placement,
            colour: frame.ctx.colour,
            pos,
            name: frame.kind.name(),
        };
        let node = self.extrude_region(&region, &how, &to)?;
        Ok(Item::Solid(node))
    }

    /// One 2D tree extruded: its operations kept, its shapes extruded.
    fn extrude_region(
        &mut self,
        r: &Region,
        how: &Extrusion,
        to: &Placement,
    ) -> Result<CsgNode, Fail> {
        let (op, parts) = match r {
            Region::Poly(p) => return self.extrude_shape(p, how, to),
            Region::Union(c) => (Op::Union, c),
            Region::Intersection(c) => (Op::Intersection, c),
            Region::Difference(c) => (Op::Difference, c),
        };
        let nodes = parts
            .iter()
            .map(|c| self.extrude_region(c, how, to))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(combine(op, nodes))
    }

    /// One shape extruded: a convex solid when it stays convex, else a closed mesh primitive.
    fn extrude_shape(
        &mut self,
        p: &Poly2,
        how: &Extrusion,
        to: &Placement,
    ) -> Result<CsgNode, Fail> {
        let budget = MAX_SCENE_VERTICES.saturating_sub(self.vertices);
        let n = p.points().count();
        if let Extrusion::Linear(l) = how {
            if let Some(outline) = p.convex_outline().filter(|_| l.keeps_convex()) {
                let (vertices, faces) = convex_prism(&outline, l);
                let ctx = Ctx {
                    matrix: to.matrix,
                    colour: to.colour,
                    skip: false,
                };
                let solid = place(Shape { vertices, faces }, &ctx, to.pos)?;
                self.vertices += solid.vertices.len();
                self.solids.push(solid);
                return Ok(CsgNode::Solid(self.solids.len() - 1));
            }
        }
        let rings = match how {
            Extrusion::Linear(l) => l.slices + 1,
            Extrusion::Rotate { fragments, .. } => fragments + 1,
        };
        check_budget(n.saturating_mul(rings), budget, to.pos)?;
        let tris = match how {
            Extrusion::Linear(l) => linear_mesh(p, l, &sin_cos_degrees),
            Extrusion::Rotate { angle, fragments } => {
                rotate_mesh(p, *angle, *fragments, &sin_cos_degrees).map_err(|e| Fail {
                    pos: to.pos,
                    msg: e.message,
                })?
            }
        };
        if tris.is_empty() {
            return Ok(CsgNode::Empty);
        }
        self.vertices += n * rings;
        let m = to.matrix.unwrap_or(IDENTITY);
        let tris: Vec<[Vec3; 3]> = tris
            .iter()
            .map(|t| t.map(|v| transform_point(&m, v.to_array())))
            .collect();
        if tris.iter().flatten().flatten().any(|&c| too_large(c)) {
            let msg = format!("a coordinate exceeds {MAX_COORDINATE:e} in size");
            return fail(to.pos, msg);
        }
        self.imports.push(Import {
            file: format!("{} at {}", to.name, to.pos),
            threshold: None,
            matrix: None,
            colour: to.colour,
            line: to.pos.line,
            col: to.pos.col,
            mesh: Some(std::sync::Arc::new(tris)),
        });
        Ok(CsgNode::Solid(IMPORTED + self.imports.len() - 1))
    }

    /// The solids and imports, less those a `hull()` took in, and the tree's leaves renumbered
    /// to match (imports still counted from [`IMPORTED`]).
    fn drop_consumed(&mut self, root: &mut CsgNode) -> (Vec<ConvexSolid>, Vec<Import>) {
        let keep = |n: usize, gone: &[usize]| -> (Vec<bool>, Vec<usize>) {
            let mut k = vec![true; n];
            gone.iter().for_each(|&i| k[i] = false);
            let mut next = 0;
            let map = k
                .iter()
                .map(|&kept| {
                    next += usize::from(kept);
                    next - usize::from(kept)
                })
                .collect();
            (k, map)
        };
        let (ks, ms) = keep(self.solids.len(), &self.consumed_solids);
        let (ki, mi) = keep(self.imports.len(), &self.consumed_imports);
        root.for_each_leaf_mut(|n| {
            if let CsgNode::Solid(i) = n {
                *i = if *i >= IMPORTED {
                    IMPORTED + mi[*i - IMPORTED]
                } else {
                    ms[*i]
                };
            }
        });
        let solids = std::mem::take(&mut self.solids);
        let imports = std::mem::take(&mut self.imports);
        (
            solids
                .into_iter()
                .zip(ks)
                .filter(|(_, k)| *k)
                .map(|(s, _)| s)
                .collect(),
            imports
                .into_iter()
                .zip(ki)
                .filter(|(_, k)| *k)
                .map(|(s, _)| s)
                .collect(),
        )
    }

    /// A finished `hull()` of solids: one convex solid over every vertex of the solids and
    /// generated meshes below it, which leave the scene.
    fn hull3(&mut self, frame: Frame) -> Result<Item, Fail> {
        let pos = frame.pos;
        let mut leaves = vec![];
        for c in &frame.children {
            hull_leaves(c, &mut leaves).map_err(|msg| Fail { pos, msg })?;
        }
        let mut pts: Vec<DVec3> = vec![];
        for &leaf in &leaves {
            if leaf < IMPORTED {
                pts.extend(self.solids[leaf].vertices.iter().map(|&v| DVec3::from(v)));
                self.consumed_solids.push(leaf);
                continue;
            }
            let import = &self.imports[leaf - IMPORTED];
            let Some(mesh) = &import.mesh else {
                let msg = format!("hull() of `import(\"{}\")` is not supported", import.file);
                return fail(pos, msg);
            };
            pts.extend(mesh.iter().flatten().map(|&v| DVec3::from(v)));
            self.consumed_imports.push(leaf - IMPORTED);
        }
        if pts.is_empty() {
            return Ok(Item::Solid(CsgNode::Empty));
        }
        let (vertices, faces) = hull3(&pts).map_err(|e| Fail {
            pos,
            msg: e.message,
        })?;
        let solid = ConvexSolid {
            vertices: vertices.iter().map(|v| v.to_array()).collect(),
            faces,
            colour: frame.ctx.colour,
            line: pos.line,
        };
        self.vertices += solid.vertices.len();
        self.solids.push(solid);
        Ok(Item::Solid(CsgNode::Solid(self.solids.len() - 1)))
    }
}

/// Where an extrusion's solids go: the transform above it, its colour, for messages its
/// position and name.
struct Placement {
    matrix: Option<Mat4>,
    colour: Option<[f64; 4]>,
    pos: Pos,
    name: &'static str,
}

/// An extrusion, its slice or fragment count settled.
enum Extrusion {
    Linear(Linear),
    Rotate { angle: f64, fragments: usize },
}

/// The leaves under a `hull()`: through unions only (the hull of a difference is not the hull
/// of its operands' vertices).
fn hull_leaves(n: &CsgNode, out: &mut Vec<usize>) -> Result<(), String> {
    let mut stack = vec![n];
    while let Some(n) = stack.pop() {
        match n {
            CsgNode::Solid(i) => out.push(*i),
            CsgNode::Empty => {}
            CsgNode::Union(c) => stack.extend(c.iter()),
            _ => {
                return Err(
                    "hull() of a difference or intersection is not supported (csgpix takes the hull of its children's vertices)"
                        .into(),
                )
            }
        }
    }
    Ok(())
}

/// A finished `hull()` of 2D shapes: the convex hull of their vertices.
fn hull_flat(frame: Frame) -> Result<Option<Item>, Fail> {
    let pos = frame.pos;
    let at = frame.first_flat.unwrap_or(pos);
    let mut pts = vec![];
    for r in &frame.flats {
        region_points(r, &mut pts).map_err(|e| Fail {
            pos,
            msg: e.message,
        })?;
    }
    let h = crate::hull::hull2(&pts);
    if h.len() < 3 {
        return Ok(None);
    }
    Ok(Some(Item::Flat(Region::Poly(Poly2 { paths: vec![h] }), at)))
}

/// A finished `offset()`.
fn offset_flat(frame: Frame) -> Result<Option<Item>, Fail> {
    let pos = frame.pos;
    if !frame.children.is_empty() {
        return fail(pos, "`offset` takes 2D children, found a solid");
    }
    if frame.flats.is_empty() {
        return Ok(None);
    }
    let Spec::Offset(o) = frame.spec else {
        return fail(pos, "internal: an offset without its parameters");
    };
    let at = frame.first_flat.unwrap_or(pos);
    let region = region_of(Op::Union, frame.flats);
    let r = offset(&region, o, &sin_cos_degrees).map_err(|e| Fail {
        pos,
        msg: e.message,
    })?;
    Ok(Some(Item::Flat(r, at)))
}

/// The 2D tree an operation makes of its 2D children.
fn region_of(op: Op, mut parts: Vec<Region>) -> Region {
    if parts.len() == 1 && op == Op::Union {
        return parts.pop().unwrap_or(Region::Union(vec![]));
    }
    match op {
        Op::Union => Region::Union(parts),
        Op::Intersection => Region::Intersection(parts),
        Op::Difference => Region::Difference(parts),
    }
}

/// Every vertex of every shape of a 2D tree (for the slice and fragment counts).
fn collect_points(r: &Region, out: &mut Vec<DVec2>) {
    match r {
        Region::Poly(p) => out.extend(p.points()),
        Region::Union(c) | Region::Intersection(c) | Region::Difference(c) => {
            c.iter().for_each(|c| collect_points(c, out))
        }
    }
}

/// `linear_extrude`'s slices: as given, or OpenSCAD 2021.01's count from the outlines.
fn linear_slices(a: LinearArgs, pts: &[DVec2]) -> Linear {
    let mut l = a.linear;
    l.slices = match a.slices {
        Some(n) => n,
        None => {
            let r = pts.iter().map(|p| p.length()).fold(0.0, f64::max);
            let ds = DVec2::new(l.scale[0] - 1.0, l.scale[1] - 1.0);
            let delta = pts.iter().map(|p| (*p * ds).length()).fold(0.0, f64::max);
            let (fn_, fa, fs) = a.res;
            default_slices(&l, r, fn_, fa, fs, delta).min(MAX_FRAGMENTS as f64) as usize
        }
    };
    l
}

/// The plane part (x, y) of a transform, for 2D shapes.
fn plane_part(m: Option<&Mat4>) -> [[f64; 3]; 2] {
    let m = m.unwrap_or(&IDENTITY);
    [[m[0][0], m[0][1], m[0][3]], [m[1][0], m[1][1], m[1][3]]]
}

/// `sin_degrees` and `cos_degrees` of an angle.
fn sin_cos_degrees(a: f64) -> (f64, f64) {
    (sin_degrees(a), cos_degrees(a))
}

/// The parameters of an extrusion or offset, read when the statement opens.
fn flat_spec(head: &Head) -> Result<Spec, Fail> {
    let p = &head.params;
    let res = || -> Result<(f64, f64, f64), Fail> {
        let r = Resolution::read(p)?;
        Ok((r.fn_, r.fa, r.fs))
    };
    Ok(match head.kind {
        NodeKind::LinearExtrude => Spec::Linear(linear_args(p, res()?)?),
        NodeKind::RotateExtrude => {
            let mut angle = p.number("angle")?.map_or(360.0, |a| a.0);
            // OpenSCAD 2021.01: an angle outside (-360, 360] is a full turn.
            if !(angle > -360.0 && angle <= 360.0) {
                angle = 360.0;
            }
            if angle == 0.0 {
                return fail(head.pos, "`rotate_extrude` needs a nonzero `angle`");
            }
            Spec::Rotate { angle, res: res()? }
        }
        NodeKind::Offset => {
            let r = Resolution::read(p)?;
            let o = match (p.number("r")?, p.number("delta")?) {
                (Some((r_, at)), _) => {
                    finite(r_, at, "`r`")?;
                    Offset::Round {
                        r: r_,
                        fragments: r.fragments(r_.abs(), at)?,
                    }
                }
                (None, Some((d, at))) => Offset::Delta {
                    delta: finite(d, at, "`delta`")?,
                    chamfer: p.boolean("chamfer")?,
                },
                (None, None) => Offset::Delta {
                    delta: 1.0,
                    chamfer: p.boolean("chamfer")?,
                },
            };
            Spec::Offset(o)
        }
        _ => Spec::None,
    })
}

fn finite(v: f64, at: Pos, what: &str) -> Result<f64, Fail> {
    if v.is_finite() && v.abs() <= MAX_COORDINATE {
        Ok(v)
    } else {
        fail(at, format!("{what} must be a finite number"))
    }
}

/// `linear_extrude(height, center, convexity, twist, slices, scale)`.
fn linear_args(p: &Params, res: (f64, f64, f64)) -> Result<LinearArgs, Fail> {
    let height = match p.number("height")? {
        Some((h, at)) => finite(h, at, "`height`")?,
        None => 100.0,
    };
    let twist = match p.number("twist")? {
        Some((t, at)) => finite(t, at, "`twist`")?,
        None => 0.0,
    };
    let slices = match p.number("slices")? {
        Some((n, at)) => {
            if !(n.is_finite() && n < MAX_FRAGMENTS as f64) {
                return fail(at, format!("`slices` must be below {MAX_FRAGMENTS}"));
            }
            Some((n.max(1.0)) as usize)
        }
        None => None,
    };
    let scale = match p.get("scale") {
        None => [1.0, 1.0],
        Some(v) => {
            let s = v.pair("`scale`")?;
            if s.iter().any(|c| !(c.is_finite() && *c >= 0.0)) {
                return fail(v.pos, "`scale` must not be negative");
            }
            s
        }
    };
    Ok(LinearArgs {
        linear: Linear {
            height,
            center: p.boolean("center")?,
            twist,
            slices: 1,
            scale,
        },
        slices,
        res,
    })
}

/// `square`, `circle` or `polygon` as a shape in its own plane.
fn flat_shape(p: &Params, budget: usize) -> Result<Poly2, Fail> {
    match p.node {
        NodeKind::Square => {
            let size = match p.get("size") {
                None => [1.0, 1.0],
                Some(v) => {
                    let s = v.pair("`size`")?;
                    if s.iter().any(|c| !(*c > 0.0 && *c <= MAX_COORDINATE)) {
                        return fail(v.pos, "`size` must be positive");
                    }
                    s
                }
            };
            Ok(Poly2::square(size[0], size[1], p.boolean("center")?))
        }
        NodeKind::Circle => {
            let r = match radius(p, "d", "r")? {
                Some(r) => positive(r, "the radius")?,
                None => 1.0,
            };
            let n = Resolution::read(p)?.fragments(r, p.pos)?;
            check_budget(n, budget, p.pos)?;
            Ok(Poly2::circle(r, n, sin_cos_degrees))
        }
        _ => polygon(p, budget),
    }
}

/// `polygon(points, paths)`: one outline of all points, or one per path (even-odd fill).
fn polygon(p: &Params, budget: usize) -> Result<Poly2, Fail> {
    let pts = p.require("points", "points = [[x, y], …]")?;
    let pts = pts
        .list("`points`")?
        .iter()
        .map(|v| match v.list("a point")? {
            [x, y] | [x, y, _] => {
                let q = DVec2::new(x.number("a point")?, y.number("a point")?);
                if q.abs().max_element() > MAX_COORDINATE || !q.is_finite() {
                    return fail(v.pos, "a point exceeds the coordinate limit");
                }
                Ok(q)
            }
            _ => fail(v.pos, "a point must be [x, y]"),
        })
        .collect::<Result<Vec<_>, _>>()?;
    check_budget(pts.len(), budget, p.pos)?;
    let paths = match p.get("paths") {
        None => vec![pts],
        Some(v) => v
            .list("`paths`")?
            .iter()
            .map(|path| {
                path.list("a path")?
                    .iter()
                    .map(|i| {
                        let k = i.number("a point index")?;
                        if k.fract() != 0.0 || k < 0.0 || k >= pts.len() as f64 {
                            let msg =
                                format!("point index {k} is not one of the {} points", pts.len());
                            return fail(i.pos, msg);
                        }
                        Ok(pts[k as usize])
                    })
                    .collect::<Result<Vec<_>, _>>()
            })
            .collect::<Result<Vec<_>, _>>()?,
    };
    Ok(Poly2 {
        paths: paths.into_iter().filter(|p| p.len() >= 3).collect(),
    })
}

/// `import(file = "x.stl" | "x.obj" | "x.nrrd", threshold = t)`: a mesh or a dataset named by
/// the scene, loaded later (`csgpix_voxel::sampled`). A dataset needs `threshold`; a mesh must not
/// have one. `scale` other than 1 is refused (OpenSCAD applies it to 2D files only).
fn import(head: &Head, ctx: &Ctx) -> Result<Import, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name, e.g. import(\"part.stl\")")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, "`file` must be a string");
    };
    let threshold = p.number("threshold")?;
    let lower = name.to_ascii_lowercase();
    let dataset = lower.ends_with(".nrrd") || lower.ends_with(".nhdr");
    if !(dataset || lower.ends_with(".stl") || lower.ends_with(".obj")) {
        return fail(
            file.pos,
            format!("`import(\"{name}\")`: csgpix imports .stl and .obj meshes and .nrrd datasets (not 2D files such as .dxf or .svg)"),
        );
    }
    match (dataset, threshold) {
        (true, None) => {
            return fail(
                head.pos,
                format!("`import(\"{name}\")` is a dataset: give its iso value, `threshold = t`"),
            )
        }
        (false, Some((_, at))) => return fail(at, "`threshold` applies to datasets (.nrrd) only"),
        _ => {}
    }
    if let Some((s, at)) = p.number("scale")? {
        if s != 1.0 {
            return fail(
                at,
                "`scale` is not supported for 3D imports (use multmatrix)",
            );
        }
    }
    if let Some((t, at)) = threshold {
        if !t.is_finite() {
            return fail(at, "`threshold` must be a finite number");
        }
    }
    Ok(Import {
        file: name.clone(),
        threshold: threshold.map(|t| t.0),
        matrix: ctx.matrix,
        colour: ctx.colour,
        line: head.pos.line,
        col: head.pos.col,
        mesh: None,
    })
}

fn unsupported(name: &str) -> String {
    let known: Vec<&str> = NODES.iter().map(|(n, _)| *n).collect();
    format!(
        "unsupported node `{name}` (csgpix reads {})",
        known.join(", ")
    )
}

fn unclosed(frame: &Frame, found: &str) -> String {
    let name = frame.kind.name();
    match frame.closer {
        Closer::Brace(at) => {
            format!("expected '}}' to close `{name}` opened at {at}, found {found}")
        }
        Closer::Single => {
            format!("expected a child statement or ';' after `{name}(…)`, found {found}")
        }
    }
}

/// The context of the children of `head` (or of `head` itself, for a leaf).
fn child_ctx(parent: &Ctx, head: &Head) -> Result<Ctx, Fail> {
    let mut ctx = parent.clone();
    ctx.skip |= head.skip;
    match head.kind {
        NodeKind::Multmatrix => {
            if let Some(m) = matrix(&head.params)? {
                ctx.matrix = Some(match &parent.matrix {
                    Some(outer) => mat_mul(outer, &m),
                    None => m,
                });
            }
        }
        NodeKind::Color => ctx.colour = Some(colour(&head.params)?),
        _ => {}
    }
    Ok(ctx)
}

// ---------------------------------------------------------------------------------------------
// CSG tree

/// The node an operation makes of its children, simplified as the module documentation says.
fn combine(op: Op, children: Vec<CsgNode>) -> CsgNode {
    match op {
        Op::Union => union(children),
        Op::Intersection => intersection(children),
        Op::Difference => difference(children),
    }
}

/// Empty children dropped, unions flattened.
fn union(children: Vec<CsgNode>) -> CsgNode {
    let mut parts = Vec::with_capacity(children.len());
    for mut child in children {
        match &mut child {
            CsgNode::Empty => {}
            CsgNode::Union(inner) => parts.append(inner),
            _ => parts.push(child),
        }
    }
    one_or(parts, CsgNode::Union)
}

/// Empty if any child is, intersections flattened.
fn intersection(children: Vec<CsgNode>) -> CsgNode {
    if children.iter().any(|c| matches!(c, CsgNode::Empty)) {
        return CsgNode::Empty;
    }
    let mut parts = Vec::with_capacity(children.len());
    for mut child in children {
        match &mut child {
            CsgNode::Intersection(inner) => parts.append(inner),
            _ => parts.push(child),
        }
    }
    one_or(parts, CsgNode::Intersection)
}

/// Empty if the first child is; empty subtracted children dropped.
fn difference(children: Vec<CsgNode>) -> CsgNode {
    let mut children = children.into_iter();
    let first = match children.next() {
        None | Some(CsgNode::Empty) => return CsgNode::Empty,
        Some(first) => first,
    };
    let mut parts = vec![first];
    parts.extend(children.filter(|c| !matches!(c, CsgNode::Empty)));
    one_or(parts, CsgNode::Difference)
}

/// No part is empty, one part is itself, more make a `many` node.
fn one_or(mut parts: Vec<CsgNode>, many: fn(Vec<CsgNode>) -> CsgNode) -> CsgNode {
    match parts.len() {
        0 => CsgNode::Empty,
        1 => parts.pop().unwrap_or(CsgNode::Empty),
        _ => many(parts),
    }
}

// ---------------------------------------------------------------------------------------------
// Transforms and colours

type Vec3 = [f64; 3];
type Mat4 = [[f64; 4]; 4];

const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// `multmatrix(m)`: 3 or 4 rows of 4 numbers, the last row `[0, 0, 0, w]` with the matrix
/// divided by `w` as OpenSCAD does; a singular linear part is refused.
fn matrix(params: &Params) -> Result<Option<Mat4>, Fail> {
    let Some(value) = params.get("m") else {
        return Ok(None);
    };
    let rows = value.list("`m`")?;
    if !(3..=4).contains(&rows.len()) {
        return fail(value.pos, "`m` must have 4 rows of 4 numbers");
    }
    let mut m = IDENTITY;
    for (row, cells) in m.iter_mut().zip(rows) {
        let [a, b, c, d] = cells.list("a row of `m`")? else {
            return fail(cells.pos, "a row of `m` must have 4 numbers");
        };
        let entry = "an entry of `m`";
        *row = [
            a.number(entry)?,
            b.number(entry)?,
            c.number(entry)?,
            d.number(entry)?,
        ];
    }
    normalise(m, value.pos).map(Some)
}

/// Divides by `m[3][3]` and checks the matrix is affine and invertible.
fn normalise(mut m: Mat4, pos: Pos) -> Result<Mat4, Fail> {
    if m[3][..3].iter().any(|&v| v != 0.0) {
        return fail(
            pos,
            "projective matrices are not supported: the last row of `m` must be [0, 0, 0, w]",
        );
    }
    let w = m[3][3];
    if w == 0.0 {
        return fail(pos, "the last entry of `m` must not be 0");
    }
    if w != 1.0 {
        m = m.map(|row| row.map(|v| v / w));
    }
    let size = m[..3]
        .iter()
        .flat_map(|row| &row[..3])
        .fold(0.0_f64, |a, v| a.max(v.abs()));
    let det = det3(&m);
    let invertible = det.abs() > 1e-12 * size * size * size;
    if !invertible {
        return fail(
            pos,
            format!("singular matrix (determinant {det:e}): it flattens the solids"),
        );
    }
    Ok(m)
}

fn mat_mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    out
}

fn det3(m: &Mat4) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

fn transform_point(m: &Mat4, p: Vec3) -> Vec3 {
    let row = |r: &[f64; 4]| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3];
    [row(&m[0]), row(&m[1]), row(&m[2])]
}

/// `color(c, alpha)`: `c` is `[r, g, b]` or `[r, g, b, a]` (alpha 1 if missing, as in
/// OpenSCAD's `builtin_color`), components in 0..1; `alpha` overrides the fourth.
fn colour(params: &Params) -> Result<[f64; 4], Fail> {
    let c = params.require("c", "a colour [r, g, b, a]")?;
    let items = match &c.kind {
        Kind::Str(name) => {
            let msg = format!(
                "colour \"{name}\" is not supported: give it as color([r, g, b, a]), \
                 as OpenSCAD's CSG export writes it"
            );
            return fail(c.pos, msg);
        }
        Kind::List(items) if (3..=4).contains(&items.len()) => items,
        _ => return fail(c.pos, "`c` must be [r, g, b] or [r, g, b, a]"),
    };
    let mut rgba = [1.0; 4];
    for (slot, item) in rgba.iter_mut().zip(items) {
        *slot = unit(item.number("a colour component")?, item.pos)?;
    }
    if let Some((alpha, pos)) = params.number("alpha")? {
        rgba[3] = unit(alpha, pos)?;
    }
    Ok(rgba)
}

fn unit(v: f64, pos: Pos) -> Result<f64, Fail> {
    if (0.0..=1.0).contains(&v) {
        Ok(v)
    } else {
        fail(
            pos,
            format!("colour components must be between 0 and 1, found {v}"),
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Primitives

/// A convex solid in its own coordinates, faces counter-clockwise seen from outside.
#[derive(Clone, Debug, PartialEq)]
struct Shape {
    vertices: Vec<Vec3>,
    faces: Vec<Vec<usize>>,
}

/// Moves a shape into the scene: transform, keep faces outward, colour.
fn place(shape: Shape, ctx: &Ctx, pos: Pos) -> Result<ConvexSolid, Fail> {
    let Shape {
        mut vertices,
        mut faces,
    } = shape;
    if let Some(m) = &ctx.matrix {
        for v in &mut vertices {
            *v = transform_point(m, *v);
        }
        if det3(m) < 0.0 {
            faces.iter_mut().for_each(|f| f.reverse());
        }
    }
    if vertices.iter().flatten().any(|&c| too_large(c)) {
        let msg = format!("a coordinate exceeds {MAX_COORDINATE:e} in size");
        return fail(pos, msg);
    }
    Ok(ConvexSolid {
        vertices,
        faces,
        colour: ctx.colour,
        line: pos.line,
    })
}

/// Beyond [`MAX_COORDINATE`], or not a number at all.
fn too_large(c: f64) -> bool {
    c.is_nan() || c.abs() > MAX_COORDINATE
}

fn check_budget(vertices: usize, budget: usize, pos: Pos) -> Result<(), Fail> {
    if vertices > budget {
        let msg = format!("the scene would have more than {MAX_SCENE_VERTICES} vertices");
        return fail(pos, msg);
    }
    Ok(())
}

fn positive((v, pos): (f64, Pos), what: &str) -> Result<f64, Fail> {
    if v > 0.0 {
        Ok(v)
    } else {
        fail(pos, format!("{what} must be positive, found {v}"))
    }
}

/// `cube(size, center)`: size a number or `[x, y, z]`, default 1. Vertex `i` is at
/// `(i&1 ? x2 : x1, i&2 ? y2 : y1, i&4 ? z2 : z1)` and the faces are those of
/// `CubeNode::createGeometry`.
fn cube(params: &Params) -> Result<Shape, Fail> {
    let size = match params.get("size") {
        None => [1.0; 3],
        Some(v) => {
            let size = match v.kind {
                Kind::Num(s) => [s; 3],
                _ => v.vec3("`size`")?,
            };
            if size.iter().any(|&s| s <= 0.0) {
                return fail(v.pos, "`size` must be positive");
            }
            size
        }
    };
    let (lo, hi) = if params.boolean("center")? {
        (size.map(|s| -s / 2.0), size.map(|s| s / 2.0))
    } else {
        ([0.0; 3], size)
    };
    let vertices = (0..8)
        .map(|i| {
            let pick = |bit: usize, axis: usize| if i & bit != 0 { hi[axis] } else { lo[axis] };
            [pick(1, 0), pick(2, 1), pick(4, 2)]
        })
        .collect();
    let faces = [
        [4, 5, 7, 6], // top
        [2, 3, 1, 0], // bottom
        [0, 1, 5, 4], // front
        [1, 3, 7, 5], // right
        [3, 2, 6, 7], // back
        [2, 0, 4, 6], // left
    ];
    Ok(Shape {
        vertices,
        faces: faces.iter().map(|f| f.to_vec()).collect(),
    })
}

/// `$fn`, `$fa`, `$fs` of a sphere or cylinder.
struct Resolution {
    fn_: f64,
    fa: f64,
    fs: f64,
}

impl Resolution {
    /// OpenSCAD's defaults are `$fn = 0, $fa = 12, $fs = 2`; `set_fragments` clamps `$fa` and
    /// `$fs` up to 0.01. Negative values are refused.
    fn read(params: &Params) -> Result<Self, Fail> {
        let get = |name: &str, default: f64| match params.number(name)? {
            None => Ok(default),
            Some((v, pos)) if v < 0.0 => fail(pos, format!("`{name}` must not be negative")),
            Some((v, _)) => Ok(v),
        };
        Ok(Resolution {
            fn_: get("$fn", 0.0)?,
            fa: get("$fa", 12.0)?.max(F_MINIMUM),
            fs: get("$fs", 2.0)?.max(F_MINIMUM),
        })
    }

    /// OpenSCAD's `Calc::get_fragments_from_r` (`src/utils/calc.cc`), as a float so a huge
    /// count can be refused before it is converted.
    fn fragments_from_r(&self, r: f64) -> f64 {
        if r < GRID_FINE {
            return 3.0;
        }
        if self.fn_ > 0.0 {
            return if self.fn_ >= 3.0 {
                self.fn_.trunc()
            } else {
                3.0
            };
        }
        (360.0 / self.fa)
            .min(r * 2.0 * PI / self.fs)
            .max(5.0)
            .ceil()
    }

    fn fragments(&self, r: f64, pos: Pos) -> Result<usize, Fail> {
        let n = self.fragments_from_r(r);
        if n > MAX_FRAGMENTS as f64 {
            let msg = format!(
                "{n} fragments (from $fn, $fa, $fs) is more than the {MAX_FRAGMENTS} csgpix accepts"
            );
            return fail(pos, msg);
        }
        Ok(n as usize)
    }
}

/// A radius given as a diameter `d` or a radius `r`; the diameter wins, as in OpenSCAD's
/// `lookup_radius`.
fn radius(params: &Params, d: &str, r: &str) -> Result<Option<(f64, Pos)>, Fail> {
    if let Some((diameter, pos)) = params.number(d)? {
        return Ok(Some((diameter / 2.0, pos)));
    }
    params.number(r)
}

/// `sphere(r | d, $fn, $fa, $fs)` as `SphereNode::createGeometry`: `(fragments + 1) / 2` rings
/// at polar angles `180 (i + 0.5) / rings`, ring 0 at the top, each a circle of `fragments`
/// points; the top and bottom rings are polygon faces and neighbouring rings are joined by
/// quads.
fn sphere(params: &Params, budget: usize) -> Result<Shape, Fail> {
    let r = match radius(params, "d", "r")? {
        Some(r) => positive(r, "the radius")?,
        None => 1.0,
    };
    let fragments = Resolution::read(params)?.fragments(r, params.pos)?;
    let rings = fragments.div_ceil(2); // OpenSCAD's (fragments + 1) / 2
    check_budget(rings * fragments, budget, params.pos)?;
    let mut vertices = Vec::with_capacity(rings * fragments);
    for i in 0..rings {
        let phi = (180.0 * (i as f64 + 0.5)) / rings as f64;
        circle(
            &mut vertices,
            r * sin_degrees(phi),
            r * cos_degrees(phi),
            fragments,
        );
    }
    let at = |ring: usize, j: usize| ring * fragments + j % fragments;
    let mut faces = Vec::with_capacity(2 + (rings - 1) * fragments);
    faces.push((0..fragments).collect());
    for i in 0..rings - 1 {
        for j in 0..fragments {
            faces.push(vec![at(i, j + 1), at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
        }
    }
    faces.push((0..fragments).map(|j| rings * fragments - j - 1).collect());
    Ok(Shape { vertices, faces })
}

/// `cylinder(h, r1, r2, center, r, d, d1, d2, $fn, $fa, $fs)` as `CylinderNode::createGeometry`:
/// defaults `h = 1, r = 1`; `r` sets both radii, `r1`/`r2` override it, diameters override
/// radii. A zero radius makes that end a single apex vertex.
fn cylinder(params: &Params, budget: usize) -> Result<Shape, Fail> {
    let h = match params.number("h")? {
        Some(h) => positive(h, "`h`")?,
        None => 1.0,
    };
    let (mut r1, mut r2) = ((1.0, params.pos), (1.0, params.pos));
    if let Some(r) = radius(params, "d", "r")? {
        (r1, r2) = (r, r);
    }
    if let Some(r) = radius(params, "d1", "r1")? {
        r1 = r;
    }
    if let Some(r) = radius(params, "d2", "r2")? {
        r2 = r;
    }
    for (r, pos) in [r1, r2] {
        if r < 0.0 {
            return fail(
                pos,
                format!("a cylinder radius must not be negative, found {r}"),
            );
        }
    }
    let (r1, r2) = (r1.0, r2.0);
    if r1 == 0.0 && r2 == 0.0 {
        return fail(
            params.pos,
            "a cylinder needs a positive radius at one end at least",
        );
    }
    let fragments = Resolution::read(params)?.fragments(r1.max(r2), params.pos)?;
    check_budget(2 * fragments, budget, params.pos)?;
    let (z1, z2) = if params.boolean("center")? {
        (-h / 2.0, h / 2.0)
    } else {
        (0.0, h)
    };
    Ok(cylinder_shape(r1, r2, z1, z2, fragments))
}

fn cylinder_shape(r1: f64, r2: f64, z1: f64, z2: f64, n: usize) -> Shape {
    let cone = r2 == 0.0;
    let inverted_cone = r1 == 0.0;
    let mut vertices = Vec::with_capacity(2 * n);
    if inverted_cone {
        vertices.push([0.0, 0.0, z1]);
    } else {
        circle(&mut vertices, r1, z1, n);
    }
    if cone {
        vertices.push([0.0, 0.0, z2]);
    } else {
        circle(&mut vertices, r2, z2, n);
    }
    let mut faces: Vec<Vec<usize>> = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            if cone {
                vec![i, j, n]
            } else if inverted_cone {
                vec![0, j + 1, i + 1]
            } else {
                vec![i, j, j + n, i + n]
            }
        })
        .collect();
    if !inverted_cone {
        faces.push((0..n).rev().collect());
    }
    if !cone {
        let offset = if inverted_cone { 1 } else { n };
        faces.push((offset..offset + n).collect());
    }
    Shape { vertices, faces }
}

/// OpenSCAD's `generate_circle`: point `i` at angle `360 i / fragments`, counter-clockwise from
/// +x seen from +z.
fn circle(out: &mut Vec<Vec3>, r: f64, z: f64, fragments: usize) {
    for i in 0..fragments {
        let phi = (360.0 * i as f64) / fragments as f64;
        out.push([r * cos_degrees(phi), r * sin_degrees(phi), z]);
    }
}

/// `polyhedron(points, faces | triangles)`. OpenSCAD lists each face clockwise seen from
/// outside and `PolyhedronNode::createGeometry` reverses them; so does this. The result must
/// be closed (every edge shared by two faces, once in each direction) and convex. Points no
/// face uses are dropped.
fn polyhedron(params: &Params, budget: usize) -> Result<Shape, Fail> {
    let points = params.require("points", "points = [[x, y, z], …]")?;
    let points = points
        .list("`points`")?
        .iter()
        .map(|p| p.vec3("a point"))
        .collect::<Result<Vec<_>, _>>()?;
    check_budget(points.len(), budget, params.pos)?;
    if points.len() > MAX_POLYHEDRON_POINTS {
        let msg = format!("a polyhedron may have at most {MAX_POLYHEDRON_POINTS} points");
        return fail(params.pos, msg);
    }
    if let Some(p) = points.iter().flatten().find(|&&c| too_large(c)) {
        let msg = format!("coordinate {p} exceeds {MAX_COORDINATE:e} in size");
        return fail(params.pos, msg);
    }
    let faces = match params.get("faces") {
        Some(faces) => faces,
        None => params.require("triangles", "faces = [[i, j, k, …], …]")?,
    };
    let faces = faces
        .list("`faces`")?
        .iter()
        .map(|f| face_indices(f, points.len()))
        .collect::<Result<Vec<_>, _>>()?;
    check_convex_closed(&points, &faces).map_err(|msg| Fail {
        pos: params.pos,
        msg: format!("polyhedron refused: {msg}"),
    })?;
    Ok(compact(points, faces))
}

/// One face's point indices, reversed to counter-clockwise.
fn face_indices(face: &Value, points: usize) -> Result<Vec<usize>, Fail> {
    let items = face.list("a face")?;
    if items.len() < 3 {
        return fail(face.pos, "a face needs 3 points at least");
    }
    let mut indices = Vec::with_capacity(items.len());
    for item in items.iter().rev() {
        let v = item.number("a point index")?;
        if v.fract() != 0.0 || v < 0.0 || v >= points as f64 {
            let msg = format!("point index {v} is not one of the {points} points");
            return fail(item.pos, msg);
        }
        let i = v as usize;
        if indices.contains(&i) {
            return fail(item.pos, format!("point {i} appears twice in one face"));
        }
        indices.push(i);
    }
    Ok(indices)
}

/// Keeps only the points some face uses, in their order.
fn compact(points: Vec<Vec3>, mut faces: Vec<Vec<usize>>) -> Shape {
    let mut used = vec![false; points.len()];
    faces.iter().flatten().for_each(|&i| used[i] = true);
    let mut new_index = vec![0; points.len()];
    let mut vertices = Vec::with_capacity(points.len());
    for (i, point) in points.into_iter().enumerate() {
        if used[i] {
            new_index[i] = vertices.len();
            vertices.push(point);
        }
    }
    faces.iter_mut().flatten().for_each(|i| *i = new_index[*i]);
    Shape { vertices, faces }
}

// ---------------------------------------------------------------------------------------------
// Checks of polyhedra

/// Checks that faces (counter-clockwise seen from outside) close a convex solid: every
/// directed edge once and its reverse once, no degenerate face, positive volume, and no used
/// point outside any face plane by more than [`CONVEXITY_TOLERANCE`].
fn check_convex_closed(vertices: &[Vec3], faces: &[Vec<usize>]) -> Result<(), String> {
    check_closed(faces)?;
    let mut used: Vec<usize> = faces.iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    let (extent, magnitude) = scale(vertices, &used);
    let planes = face_planes(vertices, faces, extent)?;
    let volume: f64 = planes.iter().map(|p| dot(p.centre, p.normal) / 6.0).sum();
    let has_volume = volume > 1e-12 * extent * extent * extent;
    if !has_volume {
        return Err(
            "the faces wind the wrong way round (OpenSCAD lists each face clockwise \
                    seen from outside) or enclose no volume"
                .to_string(),
        );
    }
    let tolerance = CONVEXITY_TOLERANCE * magnitude;
    for (k, plane) in planes.iter().enumerate() {
        let unit = plane.normal.map(|c| c / norm(plane.normal));
        for &i in &used {
            let d = dot(unit, sub(vertices[i], plane.centre));
            if d > tolerance {
                return Err(format!(
                    "not convex: point {i} lies {d:.3e} outside the plane of face {k}"
                ));
            }
        }
    }
    Ok(())
}

/// A face's Newell normal (twice its area long) and its centroid.
struct Plane {
    normal: Vec3,
    centre: Vec3,
}

fn face_planes(vertices: &[Vec3], faces: &[Vec<usize>], extent: f64) -> Result<Vec<Plane>, String> {
    faces
        .iter()
        .enumerate()
        .map(|(k, face)| {
            let normal = newell(vertices, face);
            let has_area = norm(normal) > 1e-12 * extent * extent;
            if !has_area {
                return Err(format!("face {k} has no area"));
            }
            let centre = centroid(vertices, face);
            Ok(Plane { normal, centre })
        })
        .collect()
}

fn check_closed(faces: &[Vec<usize>]) -> Result<(), String> {
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    for (k, face) in faces.iter().enumerate() {
        for edge in ring_edges(face) {
            if let Some(j) = edges.insert(edge, k) {
                return Err(format!(
                    "faces {j} and {k} both run from point {} to point {} (the surface \
                     is not closed and consistently wound)",
                    edge.1, edge.0
                ));
            }
        }
    }
    for (k, face) in faces.iter().enumerate() {
        for (a, b) in ring_edges(face) {
            if !edges.contains_key(&(b, a)) {
                return Err(format!(
                    "not closed: the edge between points {a} and {b} of face {k} has no \
                     neighbouring face"
                ));
            }
        }
    }
    Ok(())
}

/// The directed edges of a face, closing the loop.
fn ring_edges(face: &[usize]) -> impl Iterator<Item = (usize, usize)> + '_ {
    face.iter()
        .zip(face.iter().cycle().skip(1))
        .map(|(&a, &b)| (a, b))
}

/// The bounding-box diagonal and the largest absolute coordinate of the used points.
fn scale(vertices: &[Vec3], used: &[usize]) -> (f64, f64) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut magnitude = 0.0_f64;
    for &i in used {
        for axis in 0..3 {
            let c = vertices[i][axis];
            lo[axis] = lo[axis].min(c);
            hi[axis] = hi[axis].max(c);
            magnitude = magnitude.max(c.abs());
        }
    }
    (norm(sub(hi, lo)), magnitude)
}

/// Newell's normal: the polygon's unit normal (right-hand rule) times twice its area.
fn newell(vertices: &[Vec3], face: &[usize]) -> Vec3 {
    let mut n = [0.0; 3];
    for (a, b) in ring_edges(face) {
        let (a, b) = (vertices[a], vertices[b]);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    n
}

fn centroid(vertices: &[Vec3], face: &[usize]) -> Vec3 {
    let mut c = [0.0; 3];
    for &i in face {
        for axis in 0..3 {
            c[axis] += vertices[i][axis];
        }
    }
    c.map(|v| v / face.len() as f64)
}

fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: Vec3) -> f64 {
    dot(a, a).sqrt()
}

// ---------------------------------------------------------------------------------------------
// Trigonometry in degrees, as OpenSCAD's `src/utils/degree_trig.cc`

/// `sqrt(3) / 2`, OpenSCAD's `M_SQRT3_4`.
const SQRT3_4: f64 = 0.866_025_403_784_438_6;

/// Reduces to `[0, 360)`.
fn reduce_degrees(x: f64) -> f64 {
    if (0.0..360.0).contains(&x) {
        x
    } else {
        x - 360.0 * (x / 360.0).floor()
    }
}

/// `sin_degrees`: exact at multiples of 30° and 45°.
fn sin_degrees(x: f64) -> f64 {
    let mut x = reduce_degrees(x);
    let oppose = x >= 180.0;
    if oppose {
        x -= 180.0;
    }
    if x > 90.0 {
        x = 180.0 - x;
    }
    let s = if x < 45.0 {
        if x == 30.0 {
            0.5
        } else {
            x.to_radians().sin()
        }
    } else if x == 45.0 {
        FRAC_1_SQRT_2
    } else if x == 60.0 {
        SQRT3_4
    } else {
        (90.0 - x).to_radians().cos()
    };
    if oppose {
        -s
    } else {
        s
    }
}

/// `cos_degrees`: exact at multiples of 30° and 45°.
fn cos_degrees(x: f64) -> f64 {
    let mut x = reduce_degrees(x);
    let mut oppose = x >= 180.0;
    if oppose {
        x -= 180.0;
    }
    if x > 90.0 {
        x = 180.0 - x;
        oppose = !oppose;
    }
    let c = if x > 45.0 {
        if x == 60.0 {
            0.5
        } else {
            (90.0 - x).to_radians().sin()
        }
    } else if x == 45.0 {
        FRAC_1_SQRT_2
    } else if x == 30.0 {
        SQRT3_4
    } else {
        x.to_radians().cos()
    };
    if oppose {
        -c
    } else {
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const EXAMPLE: &str = include_str!("../../../vectors/scenes/cube-minus-cylinder.csg");

    /// Every node kind, for the mutation fuzzing.
    const ALL_NODES: &str = "group() {\n\
        \tunion() { cube(size = [1, 2, 3], center = false); sphere($fn = 6, r = 2); }\n\
        \tintersection() {\n\
        \t\tmultmatrix([[-1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]) {\n\
        \t\t\tcolor(c = [0, 0.5, 1], alpha = 0.5) cylinder(h = 2, r1 = 1, r2 = 0, $fn = 5);\n\
        \t\t}\n\
        \t\trender(convexity = 2) %cube(2);\n\
        \t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
        faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);\n\
        \t}\n\
        \tdifference() { cube(1); /* c */ cylinder(h = 1, d = 1, center = true); } // end\n\
        }\n";

    fn parse(text: &str) -> CsgScene {
        parse_csg(text, "test.csg").unwrap_or_else(|e| panic!("{e}"))
    }

    /// Checks the error's position and that its message contains `part`.
    fn assert_err(text: &str, line: usize, col: usize, part: &str) {
        let e = parse_csg(text, "test.csg").expect_err("should be refused");
        let at = e.location.as_ref().expect("a located error");
        assert_eq!((at.line, at.col), (line, col), "{e}");
        assert!(e.message.contains(part), "{e}");
    }

    fn only_solid(text: &str) -> ConvexSolid {
        let scene = parse(text);
        assert_eq!(scene.root, CsgNode::Solid(0));
        assert_eq!(scene.solids.len(), 1);
        scene.solids.into_iter().next().unwrap()
    }

    /// Closed, convex, and every face normal points away from the centroid.
    fn assert_outward(solid: &ConvexSolid) {
        let n = solid.vertices.len() as f64;
        let centre = solid
            .vertices
            .iter()
            .fold([0.0; 3], |c, v| [c[0] + v[0], c[1] + v[1], c[2] + v[2]])
            .map(|c| c / n);
        for face in &solid.faces {
            let normal = newell(&solid.vertices, face);
            let out = sub(centroid(&solid.vertices, face), centre);
            assert!(dot(normal, out) > 0.0, "face {face:?} points inward");
        }
        check_convex_closed(&solid.vertices, &solid.faces).unwrap();
    }

    fn bounds(solid: &ConvexSolid) -> [[f64; 2]; 3] {
        let mut b = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
        for v in &solid.vertices {
            for axis in 0..3 {
                b[axis] = [b[axis][0].min(v[axis]), b[axis][1].max(v[axis])];
            }
        }
        b
    }

    fn close(a: Vec3, b: Vec3) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    // --- primitives ---

    #[test]
    fn cube_uncentred() {
        let cube = only_solid("cube(size = [1, 2, 3], center = false);");
        assert_eq!((cube.vertices.len(), cube.faces.len()), (8, 6));
        assert!(cube.faces.iter().all(|f| f.len() == 4));
        assert_eq!(bounds(&cube), [[0.0, 1.0], [0.0, 2.0], [0.0, 3.0]]);
        assert_eq!(cube.vertices[6], [0.0, 2.0, 3.0]);
        assert_outward(&cube);
        let scalar = only_solid("cube(2);");
        assert_eq!(bounds(&scalar), [[0.0, 2.0]; 3]);
    }

    #[test]
    fn cube_centred() {
        let cube = only_solid("cube(size = [20, 20, 20], center = true);");
        assert_eq!((cube.vertices.len(), cube.faces.len()), (8, 6));
        assert_eq!(bounds(&cube), [[-10.0, 10.0]; 3]);
        assert_outward(&cube);
        assert_eq!(only_solid("cube();").vertices[7], [1.0; 3]);
    }

    #[test]
    fn sphere_fn_8() {
        let sphere = only_solid("sphere($fn = 8, $fa = 12, $fs = 2, r = 10);");
        // 8 fragments, (8 + 1) / 2 = 4 rings at 22.5°, 67.5°, 112.5°, 157.5°.
        assert_eq!(sphere.vertices.len(), 8 * 4);
        assert_eq!(sphere.faces.len(), 2 + 3 * 8);
        let (radius, z) = (
            10.0 * 22.5_f64.to_radians().sin(),
            10.0 * 22.5_f64.to_radians().cos(),
        );
        assert!(close(sphere.vertices[0], [radius, 0.0, z]));
        // 90° is exact in OpenSCAD's degree trigonometry: x is 0, not 6e-17.
        assert_eq!(sphere.vertices[2][0], 0.0);
        assert!(close(sphere.vertices[2], [0.0, radius, z]));
        assert!(close(sphere.vertices[4], [-radius, 0.0, z]));
        assert!(close(
            sphere.vertices[31],
            [radius * 0.5_f64.sqrt(), -radius * 0.5_f64.sqrt(), -z]
        ));
        assert_eq!(sphere.faces[0], (0..8).collect::<Vec<_>>());
        assert_outward(&sphere);
    }

    #[test]
    fn sphere_fa_fs() {
        let sphere = only_solid("sphere($fn = 0, $fa = 12, $fs = 2, r = 10);");
        // ceil(max(min(360 / 12, 10 * 2π / 2), 5)) = 30 fragments, 15 rings.
        assert_eq!(sphere.vertices.len(), 30 * 15);
        assert_eq!(sphere.faces.len(), 2 + 14 * 30);
        // Ring 7 is at exactly 90°: the equator, exact in OpenSCAD's degree trigonometry.
        assert_eq!(sphere.vertices[7 * 30], [10.0, 0.0, 0.0]);
        assert_eq!(sphere.vertices[7 * 30 + 5], [5.0, 10.0 * SQRT3_4, 0.0]);
        let phi = 180.0 * 0.5 / 15.0_f64;
        let top = [
            10.0 * phi.to_radians().sin(),
            0.0,
            10.0 * phi.to_radians().cos(),
        ];
        assert!(close(sphere.vertices[0], top));
        assert_outward(&sphere);
    }

    #[test]
    fn fragment_rules() {
        let count = |text: &str| only_solid(text).vertices.len();
        // Small radius: at least 5 fragments (3 rings).
        assert_eq!(count("sphere(r = 1);"), 5 * 3);
        // $fn below 3 means 3; a fractional $fn is truncated; d is a diameter.
        assert_eq!(count("sphere(d = 4, $fn = 2);"), 3 * 2);
        assert_eq!(count("sphere(r = 1, $fn = 7.9);"), 7 * 4);
        // $fa and $fs are clamped up to 0.01: 360 / 0.01 = 36000 > 10 * 2π / 0.05.
        assert_eq!(count("cylinder(r = 10, $fa = 0, $fs = 0.05);"), 2 * 1257);
        // A cylinder's fragments come from its larger radius.
        assert_eq!(count("cylinder(h = 1, r1 = 1, r2 = 10);"), 2 * 30);
        assert_eq!(
            Resolution {
                fn_: 0.0,
                fa: 12.0,
                fs: 2.0
            }
            .fragments_from_r(1e-7),
            3.0
        );
    }

    #[test]
    fn cylinder_fn_6_centred() {
        let cyl = only_solid(
            "cylinder($fn = 6, $fa = 12, $fs = 2, h = 10, r1 = 3, r2 = 3, center = true);",
        );
        assert_eq!((cyl.vertices.len(), cyl.faces.len()), (12, 8));
        assert_eq!(bounds(&cyl)[2], [-5.0, 5.0]);
        assert_eq!(cyl.vertices[1], [1.5, 3.0 * SQRT3_4, -5.0]);
        assert_eq!(cyl.vertices[10], [-1.5, -3.0 * SQRT3_4, 5.0]);
        assert_outward(&cyl);
    }

    #[test]
    fn cones_have_one_apex() {
        let cone = only_solid("cylinder($fn = 6, h = 10, r1 = 3, r2 = 0, center = true);");
        assert_eq!((cone.vertices.len(), cone.faces.len()), (7, 7));
        assert_eq!(cone.vertices[6], [0.0, 0.0, 5.0]);
        assert_eq!(cone.faces.iter().filter(|f| f.len() == 3).count(), 6);
        assert_outward(&cone);
        let inverted = only_solid("cylinder($fn = 6, h = 10, r1 = 0, r2 = 3, center = true);");
        assert_eq!((inverted.vertices.len(), inverted.faces.len()), (7, 7));
        assert_eq!(inverted.vertices[0], [0.0, 0.0, -5.0]);
        assert_outward(&inverted);
        let frustum = only_solid("cylinder(h = 2, d1 = 4, r2 = 1, $fn = 5);");
        assert_eq!(bounds(&frustum)[0][1], 2.0);
        assert_outward(&frustum);
    }

    const TETRAHEDRON: &str = "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
                               faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);";

    #[test]
    fn polyhedron_clockwise_tetrahedron() {
        let tet = only_solid(TETRAHEDRON);
        assert_eq!(tet.faces[0], vec![2, 1, 0]);
        assert_outward(&tet);
        let old = only_solid(&TETRAHEDRON.replace("faces", "triangles"));
        assert_eq!(old, tet);
    }

    #[test]
    fn polyhedron_refusals() {
        let dented = "\n  polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.2, 0.2, 0.2]], \
                      faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [4, 2, 1], [4, 3, 2], [4, 1, 3]]);";
        assert_err(dented, 2, 3, "not convex");
        let open = "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
                    faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);";
        assert_err(open, 1, 1, "not closed");
        let ccw = TETRAHEDRON.replace(
            "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]",
            "[[2, 1, 0], [1, 3, 0], [3, 2, 0], [2, 3, 1]]",
        );
        assert_err(&ccw, 1, 1, "wrong way round");
        let bad_index = TETRAHEDRON.replace("[1, 3, 2]]", "[1, 3, 4]]");
        assert_err(&bad_index, 1, 116, "point index 4");
    }

    #[test]
    fn polyhedron_drops_unused_points() {
        let text = TETRAHEDRON.replace("[0, 0, 1]]", "[0, 0, 1], [9, 9, 9]]");
        assert_eq!(only_solid(&text).vertices.len(), 4);
    }

    // --- imports ---

    #[test]
    fn imports_follow_the_solids_in_leaf_numbers() {
        let scene = parse(
            "union() {\n  import(\"a.stl\");\n  cube(1);\n  \
             multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) \
             import(file = \"h.nrrd\", threshold = 300);\n}\n",
        );
        assert_eq!((scene.solids.len(), scene.imports.len()), (1, 2));
        assert_eq!(
            scene.root,
            CsgNode::Union(vec![
                CsgNode::Solid(1),
                CsgNode::Solid(0),
                CsgNode::Solid(2)
            ])
        );
        let (a, h) = (&scene.imports[0], &scene.imports[1]);
        assert_eq!(
            (a.file.as_str(), a.threshold, a.line, a.col),
            ("a.stl", None, 2, 3)
        );
        assert_eq!((h.file.as_str(), h.threshold), ("h.nrrd", Some(300.0)));
        assert_eq!(h.matrix.map(|m| m[0][3]), Some(5.0));
    }

    #[test]
    fn import_refusals() {
        assert_err("import(\"h.nrrd\");", 1, 1, "threshold");
        assert_err("import(\"a.stl\", threshold = 3);", 1, 29, "datasets");
        assert_err("import(\"a.stl\", scale = 2);", 1, 25, "scale");
        assert_err("import(3);", 1, 8, "string");
        assert_err("import();", 1, 1, "file name");
    }

    // --- transforms and colours ---

    #[test]
    fn multmatrix_translation() {
        let cube = only_solid(
            "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, -2], [0, 0, 0, 1]]) cube(1);",
        );
        assert_eq!(bounds(&cube), [[5.0, 6.0], [0.0, 1.0], [-2.0, -1.0]]);
        assert_outward(&cube);
    }

    #[test]
    fn multmatrix_mirror_keeps_faces_outward() {
        let plain = only_solid("cylinder(h = 3, r1 = 2, r2 = 1, $fn = 7);");
        let mirrored = only_solid(
            "multmatrix(m = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\
             \tcylinder(h = 3, r1 = 2, r2 = 1, $fn = 7);\n}",
        );
        assert_eq!(mirrored.vertices[0], [-2.0, 0.0, 0.0]);
        let reversed: Vec<Vec<usize>> = plain
            .faces
            .iter()
            .map(|f| f.iter().rev().copied().collect())
            .collect();
        assert_eq!(mirrored.faces, reversed);
        assert_outward(&mirrored);
    }

    #[test]
    fn nested_multmatrix_composes() {
        let cube = only_solid(
            "multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n\
             multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]) cube(1);",
        );
        assert_eq!(bounds(&cube), [[1.0, 3.0], [0.0, 2.0], [0.0, 2.0]]);
        // m[3][3] = 2 divides the matrix, as OpenSCAD does.
        let halved = only_solid(
            "multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 2]]) cube(1);",
        );
        assert_eq!(bounds(&halved), [[0.0, 1.0]; 3]);
    }

    #[test]
    fn multmatrix_refusals() {
        assert_err(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) cube(1);",
            1,
            12,
            "singular",
        );
        assert_err(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1]]) cube(1);",
            1,
            12,
            "projective",
        );
        assert_err(
            "multmatrix([[1, 0, 0], [0, 1, 0], [0, 0, 1]]) cube(1);",
            1,
            13,
            "4 numbers",
        );
    }

    #[test]
    fn colours_innermost_wins() {
        let scene = parse(
            "color([1, 0, 0, 1]) {\n\tcube(1);\n\tcolor([0, 0, 1, 0.5]) sphere(1);\n}\ncube(3);",
        );
        assert_eq!(scene.solids[0].colour, Some([1.0, 0.0, 0.0, 1.0]));
        assert_eq!(scene.solids[1].colour, Some([0.0, 0.0, 1.0, 0.5]));
        assert_eq!(scene.solids[2].colour, None);
        assert_eq!(
            scene.solids.iter().map(|s| s.line).collect::<Vec<_>>(),
            [2, 3, 5]
        );
        let named_args = only_solid("color(c = [0, 1, 0], alpha = 0.25) cube(1);");
        assert_eq!(named_args.colour, Some([0.0, 1.0, 0.0, 0.25]));
        assert_err(
            "color(\"red\") cube(1);",
            1,
            7,
            "colour \"red\" is not supported",
        );
        assert_err("color([2, 0, 0]) cube(1);", 1, 8, "between 0 and 1");
    }

    // --- tree shapes ---

    #[test]
    fn tree_shapes() {
        use CsgNode::{Difference, Empty, Intersection, Solid, Union};
        let root = |text: &str| parse(text).root;
        assert_eq!(
            root("difference() { cube(1); sphere(1); cylinder(h = 1, r = 1); }"),
            Difference(vec![Solid(0), Solid(1), Solid(2)])
        );
        assert_eq!(
            root("intersection() { cube(1); sphere(1); }"),
            Intersection(vec![Solid(0), Solid(1)])
        );
        assert_eq!(
            root("union() { cube(1); sphere(1); }"),
            Union(vec![Solid(0), Solid(1)])
        );
        assert_eq!(root("cube(1); sphere(1);"), Union(vec![Solid(0), Solid(1)]));
        assert_eq!(root("group() { cube(1); }"), Solid(0));
        assert_eq!(root("render(convexity = 2) { cube(1); }"), Solid(0));
        assert_eq!(
            root("group() { group() { cube(1); cube(2); } cube(3); }"),
            Union(vec![Solid(0), Solid(1), Solid(2)])
        );
        assert_eq!(
            root("group() { difference() { cube(1); sphere(1); } cube(3); }"),
            Union(vec![Difference(vec![Solid(0), Solid(1)]), Solid(2)])
        );
        for empty in [
            "",
            "// nothing\n/* at all */",
            "group();",
            "group() {}",
            "union() { group(); }",
            "difference() { group(); cube(1); }",
            "intersection() { cube(1); group(); }",
        ] {
            assert_eq!(root(empty), Empty, "{empty}");
        }
        assert_eq!(root("difference() { cube(1); group(); }"), Solid(0));
    }

    #[test]
    fn modifiers() {
        use CsgNode::{Difference, Solid};
        let scene = parse("difference() { %cube(1); #sphere(1); *group() { cube(5); } cube(2); }");
        assert_eq!(scene.root, Difference(vec![Solid(0), Solid(1)]));
        assert_eq!(scene.solids.len(), 2);
        assert_eq!(scene.solids[1].vertices[7], [2.0; 3]);
        assert_err("!cube(1);", 1, 1, "root modifier");
    }

    #[test]
    fn example_scene() {
        let scene = parse(EXAMPLE);
        assert_eq!(
            scene.root,
            CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(1)])
        );
        let [cube, cylinder] = &scene.solids[..] else {
            panic!("two solids")
        };
        assert_eq!((cube.vertices.len(), cube.colour, cube.line), (8, None, 2));
        assert_eq!(cylinder.vertices.len(), 48);
        assert_eq!(cylinder.colour, Some([1.0, 0.0, 0.0, 1.0]));
        assert_eq!(bounds(cylinder)[2], [-15.0, 15.0]);
        assert_outward(cube);
        assert_outward(cylinder);
    }

    // --- syntax and errors ---

    #[test]
    fn syntax_accepted() {
        let text = "/* header */ group() { // a comment\n\
                    \tcube(size = [.5, 5., 1e-1], center = false) ;\n\
                    \tsphere(r = +2.5E+0, $fn = 0, $fa = 12, $fs = 2,);\n\
                    \tcylinder(h = 1, r1 = 1, r2 = undef, center = false);\n}\n";
        let scene = parse(text);
        assert_eq!(scene.solids.len(), 3);
        assert_eq!(
            bounds(&scene.solids[0]),
            [[0.0, 0.5], [0.0, 5.0], [0.0, 0.1]]
        );
        // r2 = undef falls back to the default radius of 1, like OpenSCAD.
        assert_eq!(bounds(&scene.solids[2])[0][1], 1.0);
    }

    #[test]
    fn errors_name_line_and_column() {
        assert_err(
            "group() {\n  minkowski() { cube(1); sphere(1); }\n}",
            2,
            3,
            "unsupported node `minkowski` (csgpix reads group",
        );
        assert_err(
            "projection() cube(1);",
            1,
            1,
            "unsupported node `projection`",
        );
        assert_err("cube(size = 1.2.3);", 1, 13, "malformed number `1.2.3`");
        assert_err("cube(size = 1e);", 1, 13, "malformed number `1e`");
        assert_err("cube(size = 1e999);", 1, 13, "out of range");
        assert_err("cube(size = inf);", 1, 13, "finite");
        assert_err("cube(size = 1;\n", 1, 14, "expected ',' or ')'");
        assert_err(
            "group() {\n\tcube(1);\n",
            3,
            1,
            "expected '}' to close `group` opened at 1:9",
        );
        assert_err(
            "group() {\n  cube(1)\n}",
            3,
            1,
            "expected ';' after `cube(…)`",
        );
        assert_err("cube(1) sphere(1);", 1, 9, "expected ';' after `cube(…)`");
        assert_err(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
            1,
            69,
            "child statement or ';'",
        );
        assert_err("cube(1);\n}", 2, 1, "unexpected '}'");
        assert_err("cube(sise = 1);", 1, 6, "no parameter `sise`");
        assert_err("cube(1, true, 3);", 1, 15, "too many positional");
        assert_err("cube(size = 1, size = 2);", 1, 16, "given twice");
        assert_err("sphere(r = -1);", 1, 12, "must be positive");
        assert_err("cylinder(h = 0, r = 1);", 1, 14, "must be positive");
        assert_err("cylinder(h = 1, r1 = 0, r2 = 0);", 1, 1, "positive radius");
        assert_err("sphere($fn = -3, r = 1);", 1, 14, "must not be negative");
        assert_err("sphere($fn = 20000, r = 1);", 1, 1, "more than the 10000");
        assert_err("sphere($fn = 2000, r = 1);", 1, 1, "vertices");
        assert_err("cube(size = [1, 2]);", 1, 13, "[x, y, z]");
        assert_err("cube(center = 1);", 1, 15, "true or false");
        assert_err("cube(size = [1, 2 3]);", 1, 19, "expected ',' or ']'");
        assert_err("/* é */ foo();", 1, 9, "unsupported node `foo`");
        assert_err("cube(1); /* open", 1, 10, "unterminated comment");
        assert_err("color(\"red) cube(1);", 1, 7, "unterminated string");
        assert_err("cube(1) @", 1, 9, "unexpected character '@'");
        assert_err("x = 3;", 1, 1, "unsupported node `x`");
    }

    #[test]
    fn display_format() {
        let e = parse_csg("cube(size = 1.2.3);", "dir/a.csg").unwrap_err();
        assert_eq!(e.to_string(), "dir/a.csg:1:13: malformed number `1.2.3`");
    }

    // --- robustness ---

    #[test]
    fn deep_nesting_is_refused_not_a_crash() {
        let text = "group() {\n".repeat(100_000) + "cube(1);" + &"}".repeat(100_000);
        assert_err(&text, MAX_NESTING + 1, 1, "nested deeper than 1000");
        let single = "group() ".repeat(100_000) + "cube(1);";
        assert_err(&single, 1, 8 * MAX_NESTING + 1, "nested deeper");
        let vectors = "cube(size = ".to_string() + &"[".repeat(100_000);
        assert_err(
            &vectors,
            1,
            13 + MAX_VECTOR_NESTING,
            "vectors nested deeper than 64",
        );
    }

    #[test]
    fn size_limits() {
        assert_err("cube(1e13);", 1, 1, "exceeds");
        let far =
            "multmatrix([[1, 0, 0, 1e12], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(1);";
        assert_err(far, 1, 73, "exceeds");
        assert_err(
            &TETRAHEDRON.replace("[0, 0, 1]]", "[0, 0, 1e13]]"),
            1,
            1,
            "exceeds",
        );
        let cubes = "cube(1);".repeat(MAX_SCENE_VERTICES / 8 + 1);
        assert_err(&cubes, 1, 8 * (MAX_SCENE_VERTICES / 8) + 1, "vertices");
    }

    #[test]
    fn all_nodes_seed_parses() {
        let scene = parse(ALL_NODES);
        assert_eq!(scene.solids.len(), 6); // the `%cube` is left out
        scene.solids.iter().for_each(assert_outward);
    }

    #[test]
    fn deepest_accepted_nesting() {
        let groups =
            "group() {\n".repeat(MAX_NESTING - 1) + "cube(1);" + &"}".repeat(MAX_NESTING - 1);
        assert_eq!(parse(&groups).root, CsgNode::Solid(0));
        // A tree as deep as the limit allows, built and dropped on a test thread's stack.
        let deep = "difference() { cube(1);\n".repeat(MAX_NESTING - 1)
            + "cube(1);"
            + &"}".repeat(MAX_NESTING - 1);
        let scene = parse(&deep);
        assert_eq!(scene.solids.len(), MAX_NESTING);
        drop(scene);
    }

    /// Ok scenes are well formed; errors point inside the text.
    fn check_outcome(text: &str) {
        match parse_csg(text, "fuzz.csg") {
            Ok(scene) => {
                let mut pending = vec![&scene.root];
                while let Some(node) = pending.pop() {
                    match node {
                        CsgNode::Solid(i) => assert!(*i < scene.solids.len()),
                        CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                            pending.extend(c)
                        }
                        CsgNode::Complement(c) => pending.push(c),
                        CsgNode::Empty => {}
                    }
                }
                scene.solids.iter().for_each(assert_outward);
            }
            Err(e) => {
                let at = e.location.as_ref().expect("a located error");
                assert!(at.line >= 1 && at.col >= 1, "{e}");
                assert!(at.line <= text.lines().count() + 1, "{e}");
            }
        }
    }

    proptest! {
        #[test]
        fn random_text_never_panics(text in "\\PC{0,300}") {
            check_outcome(&text);
        }

        #[test]
        fn csg_like_text_never_panics(text in "[a-z$ (){}\\[\\];,=0-9.e+\\-\"/*%#\n]{0,300}") {
            check_outcome(&text);
        }

        #[test]
        fn mutated_files_never_panic(
            seed in prop::sample::select(vec![EXAMPLE, ALL_NODES]),
            edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0..3u8), 1..6)
        ) {
            let mut bytes = seed.as_bytes().to_vec();
            for (at, byte, how) in edits {
                let i = at.index(bytes.len() + 1);
                match how {
                    0 if i < bytes.len() => bytes[i] = byte,
                    1 if i < bytes.len() => { bytes.remove(i); }
                    _ => bytes.insert(i, byte),
                }
            }
            check_outcome(&String::from_utf8_lossy(&bytes));
        }
    }
}

//! `import("x.dxf")`: a DXF drawing read as OpenSCAD 2021.01 reads it (`DxfData::DxfData` in
//! `src/dxfdata.cc`, then `DxfData::toPolygon2d` and `ClipperUtils::sanitize`), into one 2D
//! shape. OpenSCAD's rules, quirks included:
//!
//! * the file is pairs of lines, a group code and its value; only the `ENTITIES` and `BLOCKS`
//!   sections draw. The entities drawn are `LINE`, `LWPOLYLINE` (its vertices joined, closed
//!   when flag 1 of code 70 is set; bulges, code 42, are ignored), `CIRCLE`, `ARC` (degrees,
//!   counter-clockwise from code 50 to 51), `ELLIPSE` (radians, the major axis end code 11/21
//!   shifted by `origin` and the ratio code 40 multiplied by `scale`, as OpenSCAD does) and
//!   `INSERT` of a block defined earlier (its lines scaled by codes 41/42, turned by 50, times
//!   `scale`, moved to the insertion point). Every other entity (`POLYLINE`, `VERTEX`,
//!   `SEQEND`, `SPLINE`, `TEXT`, …) draws nothing and is counted in OpenSCAD's warning
//!   "Unsupported DXF Entity";
//! * `layer` keeps the entities of that layer only (blocks are read whatever their layer),
//!   `origin` is subtracted from and `scale` multiplies the coordinates of the entities
//!   section; `$INSUNITS` and the header are not read;
//! * circles and arcs have OpenSCAD's fragment count from `$fn`, `$fa`, `$fs` for their radius
//!   (an arc its share of it, rounded up), an ellipse that of its major radius;
//! * every entity becomes line segments whose ends are snapped to a grid of 1/1024
//!   (`Grid2d` of `src/grid.h`, `GRID_COARSE`, with its snap to a neighbouring cell already
//!   used); segments meeting in a cell are joined into paths: first the open ones, from a free
//!   end, then the closed ones. Open paths are closed by a straight line ("We don't support
//!   open paths"), and all paths are filled together by the even-odd rule.
//!
//! Where OpenSCAD warns and goes on (an unsupported entity, an entity short of coordinates),
//! csgpix does the same to the geometry and records the warning: a group code that is not a
//! number stops the reading ("Illegal ID"; what was drawn before stays), a value that does not
//! parse is skipped ("Illegal value"), a group code without its value line (an odd number of
//! lines) has an empty value. A coordinate past [`MAX_COORDINATE`] is refused, one line naming
//! the file and line. The file is read line by line
//! (lines of at most [`MAX_LINE`] bytes) and its segments count against the scene's vertex
//! budget (two vertices each) as they are made, so memory stays bounded; the joining of
//! segments is linear in their number, up to a heap's logarithm.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BinaryHeap, HashMap};
use std::io::BufRead;
use std::path::Path;

use csgpix_scene::Error;
use glam::DVec2;

use crate::consts_::MAX_COORDINATE;
use crate::extrude::{flatten, Poly2, Region};
use crate::linalg::{cos_degrees, sin_degrees};
use crate::primitives::Resolution;

/// Longest line accepted, in bytes (DXF lines are short: a text value is at most 2049 bytes).
pub const MAX_LINE: usize = 1 << 16;

/// OpenSCAD's `GRID_COARSE` (`src/grid.h`): segment ends are snapped to it.
const GRID: f64 = 0.000_976_562_5;

/// Most turns an arc's end angle may be below its start (OpenSCAD adds a turn at a time).
const MAX_TURNS: f64 = 1e6;

/// The import's arguments that shape the drawing.
pub(crate) struct Settings {
    /// Only this layer's entities, or all when empty.
    pub(crate) layer: String,
    pub(crate) origin: [f64; 2],
    pub(crate) scale: f64,
    pub(crate) res: Resolution,
}

/// What a DXF file draws, and the warnings OpenSCAD gives on it.
pub(crate) struct Drawing {
    pub(crate) shape: Poly2,
    pub(crate) warnings: Vec<String>,
}

/// The DXF file at `path`, called `name` in messages; at most `budget` vertices.
pub(crate) fn read(
    path: &Path,
    name: &str,
    settings: &Settings,
    budget: usize,
) -> csgpix_scene::Result<Drawing> {
    let file = std::fs::File::open(path).map_err(|e| Error::io("cannot read it", &e))?;
    parse(std::io::BufReader::new(file), name, settings, budget)
}

/// [`read`] of the file's bytes.
pub(crate) fn parse(
    input: impl BufRead,
    name: &str,
    settings: &Settings,
    budget: usize,
) -> csgpix_scene::Result<Drawing> {
    let mut lines = Lines {
        input,
        name,
        line: 0,
        buf: Vec::new(),
    };
    let mut r = Dxf::new(name, settings, budget);
    while let Some(id) = lines.next()? {
        let id = id.to_vec();
        if id.is_empty() && lines.rest_is_blank()? {
            break;
        }
        let id_line = lines.line;
        // A group code without its value line (an odd number of lines) has an empty value, as
        // `std::getline` at the end of the stream gives.
        let value = lines.next()?.map(<[u8]>::to_vec);
        let code = std::str::from_utf8(&id)
            .ok()
            .and_then(|s| s.parse::<i32>().ok());
        let Some(code) = code else {
            // OpenSCAD stops reading here, warning unless the file has ended.
            if value.is_some() {
                let msg = format!(
                    "{name}:{id_line}: Illegal ID \"{}\" (a group code is a number): the rest \
                     of the file is not read",
                    shown(&id)
                );
                r.warnings.push(msg);
            }
            break;
        };
        r.pair(code, &value.unwrap_or_default(), lines.line)?;
    }
    r.finish()
}

/// The file's lines, trimmed of white space as `boost::trim` does, numbered from 1.
struct Lines<'n, R> {
    input: R,
    name: &'n str,
    line: usize,
    buf: Vec<u8>,
}

impl<R: BufRead> Lines<'_, R> {
    fn next(&mut self) -> csgpix_scene::Result<Option<&[u8]>> {
        use std::io::Read;
        self.buf.clear();
        let at = self.line + 1;
        let n = (&mut self.input)
            .take(MAX_LINE as u64 + 1)
            .read_until(b'\n', &mut self.buf)
            .map_err(|e| {
                Error::io("cannot read it", &e).context(format_args!("{}:{at}", self.name))
            })?;
        if n == 0 {
            return Ok(None);
        }
        if self.buf.len() > MAX_LINE {
            let e = Error::LineTooLong {
                limit: MAX_LINE,
                format: Some("DXF"),
            };
            return Err(e.context(format_args!("{}:{at}", self.name)));
        }
        self.line = at;
        Ok(Some(trim(&self.buf)))
    }

    /// Whether only blank lines are left (OpenSCAD stops quietly at a blank last line).
    fn rest_is_blank(&mut self) -> csgpix_scene::Result<bool> {
        while let Some(l) = self.next()? {
            if !l.is_empty() {
                return Ok(false);
            }
        }
        Ok(true)
    }
}

fn trim(s: &[u8]) -> &[u8] {
    let space = |b: &u8| matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c);
    let start = s.iter().position(|b| !space(b)).unwrap_or(s.len());
    let end = s.iter().rposition(|b| !space(b)).map_or(start, |e| e + 1);
    &s[start..end]
}

/// A value as it may be shown in a message: at most 40 characters of it.
fn shown(s: &[u8]) -> String {
    String::from_utf8_lossy(s).chars().take(40).collect()
}

/// One segment of the entities section: its ends (snapped) and their grid cells.
#[derive(Clone, Copy)]
struct Segment {
    p: [DVec2; 2],
    cell: [usize; 2],
}

/// OpenSCAD's `Grid2d` (`src/grid.h`): cells of side [`GRID`] holding the segments whose ends
/// were snapped into them.
#[derive(Default)]
struct Grid {
    index: HashMap<(i64, i64), usize>,
    /// For each cell, the segments registered there, in order. A block's segment registers
    /// the number of entity segments at that time, as OpenSCAD does (`lines.size()`).
    cells: Vec<Vec<usize>>,
}

impl Grid {
    /// `Grid2d::align`: the cell of `p`, or of the nearest (Manhattan) occupied neighbour
    /// when its own is empty, the loop bounds moving with the best cell as in OpenSCAD; the
    /// cell is created. Returns the cell and the snapped point.
    fn align(&mut self, p: DVec2) -> (usize, DVec2) {
        let mut ix = (p.x / GRID).round() as i64;
        let mut iy = (p.y / GRID).round() as i64;
        if !self.index.contains_key(&(ix, iy)) {
            let mut dist = 10;
            let mut jx = ix - 1;
            while jx <= ix + 1 {
                let mut jy = iy - 1;
                while jy <= iy + 1 {
                    if self.index.contains_key(&(jx, jy)) {
                        let d = (ix - jx).abs() + (iy - jy).abs();
                        if d < dist {
                            dist = d;
                            ix = jx;
                            iy = jy;
                        }
                    }
                    jy += 1;
                }
                jx += 1;
            }
        }
        let next = self.cells.len();
        let cell = *self.index.entry((ix, iy)).or_insert(next);
        if cell == next {
            self.cells.push(Vec::new());
        }
        (cell, DVec2::new(ix as f64 * GRID, iy as f64 * GRID))
    }
}

/// An entity too short of coordinates: OpenSCAD's `std::out_of_range`, caught with the
/// warning "Not enough input values".
struct Short;

/// Why an entity could not be finished.
enum Stop {
    Short,
    Fail(Error),
}

impl From<Short> for Stop {
    fn from(_: Short) -> Stop {
        Stop::Short
    }
}

impl From<Error> for Stop {
    fn from(e: Error) -> Stop {
        Stop::Fail(e)
    }
}

/// `v.at(i)`.
fn at(v: &[f64], i: usize) -> Result<f64, Short> {
    v.get(i).copied().ok_or(Short)
}

/// `DxfData::DxfData`'s state while it reads: the entity being read (`mode`, started at
/// line `mode_line`) and what was drawn.
struct Dxf<'s> {
    name: &'s str,
    s: &'s Settings,
    /// Vertices left: two per segment.
    budget: usize,
    in_entities: bool,
    in_blocks: bool,
    current_block: Option<usize>,
    mode: Vec<u8>,
    mode_line: usize,
    layer: Vec<u8>,
    iddata: Vec<u8>,
    dimtype: i32,
    xverts: Vec<f64>,
    yverts: Vec<f64>,
    radius: f64,
    arc_start: f64,
    arc_stop: f64,
    ellipse_start: f64,
    ellipse_stop: f64,
    grid: Grid,
    lines: Vec<Segment>,
    block_names: HashMap<Vec<u8>, usize>,
    blocks: Vec<Vec<[DVec2; 2]>>,
    unsupported: BTreeMap<Vec<u8>, usize>,
    warnings: Vec<String>,
}

impl<'s> Dxf<'s> {
    fn new(name: &'s str, s: &'s Settings, budget: usize) -> Self {
        Dxf {
            name,
            s,
            budget,
            in_entities: false,
            in_blocks: false,
            current_block: None,
            mode: Vec::new(),
            mode_line: 0,
            layer: Vec::new(),
            iddata: Vec::new(),
            dimtype: 0,
            xverts: Vec::new(),
            yverts: Vec::new(),
            radius: 0.0,
            arc_start: 0.0,
            arc_stop: 0.0,
            ellipse_start: 0.0,
            ellipse_stop: 0.0,
            grid: Grid::default(),
            lines: Vec::new(),
            block_names: HashMap::new(),
            blocks: Vec::new(),
            unsupported: BTreeMap::new(),
            warnings: Vec::new(),
        }
    }

    fn fail(&self, line: usize, problem: Error) -> Error {
        problem.context(format_args!("{}:{line}", self.name))
    }

    /// A number as `boost::lexical_cast<double>` reads it, or None with OpenSCAD's warning
    /// ("Illegal value"), the value skipped. csgpix skips `inf` and `nan` too, which OpenSCAD
    /// reads into coordinates that draw nothing usable.
    fn number(&mut self, code: i32, value: &[u8], line: usize) -> Option<f64> {
        let v = std::str::from_utf8(value)
            .ok()
            .and_then(|s| s.parse::<f64>().ok())
            .filter(|v| v.is_finite());
        if v.is_none() {
            self.illegal_value(code, value, line);
        }
        v
    }

    /// `DxfData::DxfData`'s warning on a value that does not parse: the value is skipped.
    fn illegal_value(&mut self, code: i32, value: &[u8], line: usize) {
        let msg = format!(
            "{}:{line}: Illegal value \"{}\" for group code {code}: skipped",
            self.name,
            shown(value)
        );
        self.warnings.push(msg);
    }

    /// A coordinate of the entities section (shifted by `origin`, times `scale`) or of a
    /// block (as written).
    fn coordinate(&self, v: f64, origin: f64) -> f64 {
        if self.in_blocks {
            v
        } else {
            (v - origin) * self.s.scale
        }
    }

    /// One group code and its value (at `line`), as the loop body of `DxfData::DxfData`: a
    /// number that does not parse is skipped with a warning, once.
    fn pair(&mut self, code: i32, value: &[u8], line: usize) -> csgpix_scene::Result<()> {
        let numeric = matches!(code, 10..=16 | 20..=26 | 40..=42 | 50 | 51);
        let v = if numeric {
            // 12-16 and 22-26 are parsed for dimensions, which draw nothing.
            match self.number(code, value, line) {
                Some(v) => v,
                None => return Ok(()),
            }
        } else {
            0.0
        };
        match code {
            0 => return self.end_entity(value, line),
            2 => self.iddata = value.to_vec(),
            8 => self.layer = value.to_vec(),
            10 | 11 => {
                let v = self.coordinate(v, self.s.origin[0]);
                self.xverts.push(v);
            }
            20 | 21 => {
                let v = self.coordinate(v, self.s.origin[1]);
                self.yverts.push(v);
            }
            40 => self.radius = if self.in_blocks { v } else { v * self.s.scale },
            41 => self.ellipse_start = v,
            42 => self.ellipse_stop = v,
            50 => self.arc_start = v,
            51 => self.arc_stop = v,
            70 => {
                let n = std::str::from_utf8(value)
                    .ok()
                    .and_then(|s| s.parse::<i32>().ok());
                match n {
                    Some(n) => self.dimtype = n,
                    None => self.illegal_value(code, value, line),
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// Code 0: the entity read so far is drawn, and `value` starts the next one. When the
    /// entity lacks coordinates OpenSCAD warns and keeps its state (the next entity's codes
    /// add to it), as here.
    fn end_entity(&mut self, value: &[u8], line: usize) -> csgpix_scene::Result<()> {
        match self.draw() {
            Ok(()) => {}
            Err(Stop::Short) => {
                let msg = format!(
                    "{}:{}: Not enough input values for {}",
                    self.name,
                    self.mode_line,
                    shown(&self.mode)
                );
                self.warnings.push(msg);
                return Ok(());
            }
            Err(Stop::Fail(e)) => return Err(e),
        }
        self.mode = value.to_vec();
        self.mode_line = line;
        self.layer.clear();
        self.iddata.clear();
        self.dimtype = 0;
        self.xverts.clear();
        self.yverts.clear();
        self.radius = 0.0;
        self.arc_start = 0.0;
        self.arc_stop = 0.0;
        let insert = self.mode == b"INSERT";
        self.ellipse_start = if insert { 1.0 } else { 0.0 };
        self.ellipse_stop = self.ellipse_start;
        Ok(())
    }

    fn layer_kept(&self) -> bool {
        self.s.layer.is_empty() || self.s.layer.as_bytes() == self.layer
    }

    /// The entity `mode` with what was read of it.
    fn draw(&mut self) -> Result<(), Stop> {
        match self.mode.as_slice() {
            b"SECTION" => {
                self.in_entities = self.iddata == b"ENTITIES";
                self.in_blocks = self.iddata == b"BLOCKS";
            }
            b"LINE" => {
                let (x, y) = (&self.xverts, &self.yverts);
                let (a, b) = (
                    DVec2::new(at(x, 0)?, at(y, 0)?),
                    DVec2::new(at(x, 1)?, at(y, 1)?),
                );
                self.add_line(a, b)?;
            }
            b"LWPOLYLINE" => self.lwpolyline()?,
            b"CIRCLE" => self.circle()?,
            b"ARC" => self.arc()?,
            b"ELLIPSE" => self.ellipse()?,
            b"INSERT" => self.insert()?,
            b"DIMENSION" if self.layer_kept() => {}
            b"BLOCK" => {
                let next = self.blocks.len();
                let i = *self.block_names.entry(self.iddata.clone()).or_insert(next);
                if i == next {
                    self.blocks.push(Vec::new());
                }
                // OpenSCAD's `current_block` is a name: an empty one collects nothing.
                self.current_block = (!self.iddata.is_empty()).then_some(i);
            }
            b"ENDBLK" => self.current_block = None,
            b"ENDSEC" => {}
            _ => {
                if self.in_blocks || (self.in_entities && self.layer_kept()) {
                    *self.unsupported.entry(self.mode.clone()).or_default() += 1;
                }
            }
        }
        Ok(())
    }

    fn lwpolyline(&mut self) -> Result<(), Stop> {
        let n = self.xverts.len().max(self.yverts.len());
        for i in 1..n {
            let (x, y) = (&self.xverts, &self.yverts);
            let a = DVec2::new(at(x, i - 1)?, at(y, i - 1)?);
            let b = DVec2::new(at(x, i)?, at(y, i)?);
            self.add_line(a, b)?;
        }
        if self.dimtype & 1 != 0 {
            let (x, y) = (&self.xverts, &self.yverts);
            let last = n.checked_sub(1).ok_or(Short)?;
            let a = DVec2::new(at(x, last)?, at(y, last)?);
            let b = DVec2::new(at(x, 0)?, at(y, 0)?);
            self.add_line(a, b)?;
        }
        Ok(())
    }

    /// A fragment count, refused when it would pass the budget before it is made.
    fn count(&self, n: f64) -> Result<usize, Stop> {
        if n.is_nan() || n > (self.budget / 2) as f64 {
            return Err(Stop::Fail(self.over_budget()));
        }
        Ok(n.max(0.0) as usize)
    }

    fn over_budget(&self) -> Error {
        self.fail(
            self.mode_line,
            Error::DxfVertexLimit {
                entity: shown(&self.mode),
                left: self.budget,
            },
        )
    }

    fn circle(&mut self) -> Result<(), Stop> {
        let r = self.radius;
        let n = self.count(self.s.res.fragments_from_r(r))?;
        let c = DVec2::new(at(&self.xverts, 0)?, at(&self.yverts, 0)?);
        let point = |a: f64| DVec2::new(cos_degrees(a) * r + c.x, sin_degrees(a) * r + c.y);
        for i in 0..n {
            let a1 = (360.0 * i as f64) / n as f64;
            let a2 = (360.0 * (i + 1) as f64) / n as f64;
            self.add_line(point(a1), point(a2))?;
        }
        Ok(())
    }

    fn arc(&mut self) -> Result<(), Stop> {
        let c = DVec2::new(at(&self.xverts, 0)?, at(&self.yverts, 0)?);
        let r = self.radius;
        let n = self.s.res.fragments_from_r(r);
        self.arc_stop = self.unwrap_angle(self.arc_start, self.arc_stop, 360.0)?;
        let (start, angle) = (self.arc_start, self.arc_stop - self.arc_start);
        let n = self.count((n * angle / 360.0).ceil())?;
        let point = |a: f64| DVec2::new(cos_degrees(a) * r + c.x, sin_degrees(a) * r + c.y);
        for i in 0..n {
            let a1 = start + angle * i as f64 / n as f64;
            let a2 = start + angle * (i + 1) as f64 / n as f64;
            self.add_line(point(a1), point(a2))?;
        }
        Ok(())
    }

    /// `stop` raised by whole turns until it is not below `start`, as OpenSCAD's loop does,
    /// refused past [`MAX_TURNS`] turns (OpenSCAD would loop that long).
    fn unwrap_angle(&self, start: f64, mut stop: f64, turn: f64) -> Result<f64, Stop> {
        let mut turns = 0.0;
        while start > stop {
            stop += turn;
            turns += 1.0;
            if turns > MAX_TURNS {
                let msg = Error::DxfAngleTurns {
                    entity: shown(&self.mode),
                    turns: MAX_TURNS,
                };
                return Err(Stop::Fail(self.fail(self.mode_line, msg)));
            }
        }
        Ok(stop)
    }

    /// OpenSCAD's ellipse: the major axis `ce` (codes 11/21, read as coordinates), the ratio
    /// in `radius`, angles in radians, `n` fragments of the major radius per turn.
    fn ellipse(&mut self) -> Result<(), Stop> {
        use std::f64::consts::PI;
        self.ellipse_stop = self.unwrap_angle(self.ellipse_start, self.ellipse_stop, 2.0 * PI)?;
        let c = DVec2::new(at(&self.xverts, 0)?, at(&self.yverts, 0)?);
        let ce = DVec2::new(at(&self.xverts, 1)?, at(&self.yverts, 1)?);
        let r_major = (ce.x * ce.x + ce.y * ce.y).sqrt();
        let mut rot = (ce.x / r_major).clamp(-1.0, 1.0).acos();
        if ce.y < 0.0 {
            rot = 2.0 * PI - rot;
        }
        let r_minor = r_major * self.radius;
        let (start, sweep) = (self.ellipse_start, self.ellipse_stop - self.ellipse_start);
        let n = self.s.res.fragments_from_r(r_major);
        let n = self.count((n * sweep / (2.0 * PI)).ceil())?;
        let mut p1 = DVec2::ZERO;
        for i in 0..=n {
            let a = start + sweep * i as f64 / n as f64;
            let p2 = DVec2::new(a.cos() * r_major, a.sin() * r_minor);
            let p2 = DVec2::new(
                rot.cos() * p2.x - rot.sin() * p2.y + c.x,
                rot.sin() * p2.x + rot.cos() * p2.y + c.y,
            );
            if i > 0 {
                self.add_line(p1, p2)?;
            }
            p1 = p2;
        }
        Ok(())
    }

    /// A block's segments placed: scaled by codes 41/42 (in `ellipse_start`/`ellipse_stop`,
    /// as OpenSCAD stores them), turned by code 50 (`arc_start`), times `scale`, moved.
    fn insert(&mut self) -> Result<(), Stop> {
        let Some(&b) = self.block_names.get(&self.iddata) else {
            return Ok(());
        };
        let n = self.blocks[b].len();
        let (a, sx, sy, scale) = (
            self.arc_start,
            self.ellipse_start,
            self.ellipse_stop,
            self.s.scale,
        );
        let (sin, cos) = (sin_degrees(a), cos_degrees(a));
        for i in 0..n {
            let seg = self.blocks[b][i];
            let o = DVec2::new(at(&self.xverts, 0)?, at(&self.yverts, 0)?);
            let place = |p: DVec2| {
                let (lx, ly) = (p.x * sx, p.y * sy);
                DVec2::new(
                    (cos * lx - sin * ly) * scale + o.x,
                    (sin * lx + cos * ly) * scale + o.y,
                )
            };
            self.add_line(place(seg[0]), place(seg[1]))?;
        }
        Ok(())
    }

    /// OpenSCAD's `ADD_LINE`: a segment of the entities section (of the layer asked for) or
    /// of a block, its ends snapped to the grid.
    fn add_line(&mut self, a: DVec2, b: DVec2) -> csgpix_scene::Result<()> {
        if !self.in_entities && !self.in_blocks {
            return Ok(());
        }
        if self.in_entities && !self.layer_kept() {
            return Ok(());
        }
        if [a, b]
            .iter()
            .any(|p| !p.is_finite() || p.abs().max_element() > MAX_COORDINATE)
        {
            let msg = Error::DxfCoordinateLimit {
                entity: shown(&self.mode),
                limit: MAX_COORDINATE,
            };
            return Err(self.fail(self.mode_line, msg));
        }
        if self.budget < 2 {
            return Err(self.over_budget());
        }
        self.budget -= 2;
        let (ca, a) = self.grid.align(a);
        let (cb, b) = self.grid.align(b);
        let index = self.lines.len();
        self.grid.cells[ca].push(index);
        self.grid.cells[cb].push(index);
        if self.in_entities {
            self.lines.push(Segment {
                p: [a, b],
                cell: [ca, cb],
            });
        }
        if let (true, Some(block)) = (self.in_blocks, self.current_block) {
            self.blocks[block].push([a, b]);
        }
        Ok(())
    }

    /// The end of the file: OpenSCAD's warnings, the segments joined into paths, filled.
    fn finish(mut self) -> csgpix_scene::Result<Drawing> {
        for (mode, count) in &self.unsupported {
            // OpenSCAD prints the count in hexadecimal.
            let msg = if self.s.layer.is_empty() {
                format!(
                    "Unsupported DXF Entity '{}' ({count:x}) in \"{}\".",
                    shown(mode),
                    self.name
                )
            } else {
                format!(
                    "Unsupported DXF Entity '{}' ({count:x}) in layer '{}' of {}",
                    shown(mode),
                    self.s.layer,
                    self.name
                )
            };
            self.warnings.push(msg);
        }
        let paths = Paths::new(&self.lines, &self.grid.cells).extract();
        let poly = Poly2 {
            paths: odd_edges(&paths),
        };
        Ok(Drawing {
            shape: flatten(&Region::Poly(poly)),
            warnings: self.warnings,
        })
    }
}

/// The edges of closed `paths` (of snapped points) that appear an odd number of times, either
/// way round, linked again into closed outlines. An edge crosses a ray as often as its copy, so
/// the even-odd region is the same (Clipper's fill of the paths), without the coincident
/// copies of an arc drawn over many turns, which the 2D booleans are slow on.
fn odd_edges(paths: &[Vec<DVec2>]) -> Vec<Vec<DVec2>> {
    type Key = (i64, i64);
    let key = |p: DVec2| ((p.x / GRID).round() as i64, (p.y / GRID).round() as i64);
    let mut odd: BTreeMap<(Key, Key), bool> = BTreeMap::new();
    for path in paths {
        for (i, &p) in path.iter().enumerate() {
            let (a, b) = (key(p), key(path[(i + 1) % path.len()]));
            if a != b {
                let flip = odd.entry((a.min(b), a.max(b))).or_insert(false);
                *flip = !*flip;
            }
        }
    }
    let edges: Vec<(Key, Key)> = odd.into_iter().filter(|e| e.1).map(|e| e.0).collect();
    let mut at: BTreeMap<Key, Vec<usize>> = BTreeMap::new();
    for (i, &(a, b)) in edges.iter().enumerate() {
        at.entry(a).or_default().push(i);
        at.entry(b).or_default().push(i);
    }
    let point = |k: Key| DVec2::new(k.0 as f64 * GRID, k.1 as f64 * GRID);
    let mut used = vec![false; edges.len()];
    let mut out = vec![];
    for (i, &(start, _)) in edges.iter().enumerate() {
        if used[i] {
            continue;
        }
        // Every vertex has an even degree, so a walk from `start` ends there.
        let (mut cur, mut cycle) = (start, vec![]);
        while let Some(e) = at.get_mut(&cur).and_then(|l| l.pop()) {
            if used[e] {
                continue;
            }
            used[e] = true;
            cycle.push(point(cur));
            cur = if edges[e].0 == cur {
                edges[e].1
            } else {
                edges[e].0
            };
            if cur == start {
                break;
            }
        }
        out.push(cycle);
    }
    out
}

/// The joining of segments into paths (the end of `DxfData::DxfData`), with bookkeeping that
/// makes OpenSCAD's rescans unnecessary while keeping its choices: the open paths start,
/// one after another, at the first segment (by index) with a free end (its end 0 before its
/// end 1), a free end being one whose cell holds no other enabled segment; a path goes on
/// through the first enabled segment registered in the cell it reached. Then the closed
/// paths start at the first enabled segment, end 0.
struct Paths<'l> {
    lines: &'l [Segment],
    disabled: Vec<bool>,
    /// Per cell, the segments of OpenSCAD's cell list that have an end in it, in order (the
    /// others, a block's registrations, are never followed), and how many are disabled at
    /// its start.
    walk: Vec<Vec<usize>>,
    skip: Vec<usize>,
    /// Per cell, the distinct segments registered there (a block's registration counts, as
    /// in OpenSCAD's test of a free end), and how many of them are enabled.
    distinct: Vec<Vec<usize>>,
    live: Vec<usize>,
    /// Per segment, the cells that list it.
    listed_in: Vec<Vec<usize>>,
    /// Segments that may have a free end, smallest first.
    heap: BinaryHeap<Reverse<usize>>,
}

impl<'l> Paths<'l> {
    fn new(lines: &'l [Segment], cells: &[Vec<usize>]) -> Self {
        let n = lines.len();
        let mut walk = Vec::with_capacity(cells.len());
        let mut distinct = Vec::with_capacity(cells.len());
        let mut listed_in = vec![Vec::new(); n];
        for (c, list) in cells.iter().enumerate() {
            // A registration past the last entity segment would be read out of bounds by
            // OpenSCAD; here it is no segment.
            let valid = list.iter().copied().filter(|&k| k < n);
            walk.push(
                valid
                    .clone()
                    .filter(|&k| lines[k].cell.contains(&c))
                    .collect(),
            );
            let mut d: Vec<usize> = valid.collect();
            d.sort_unstable();
            d.dedup();
            for &k in &d {
                listed_in[k].push(c);
            }
            distinct.push(d);
        }
        let live = distinct.iter().map(Vec::len).collect();
        let mut p = Paths {
            lines,
            disabled: vec![false; n],
            skip: vec![0; cells.len()],
            walk,
            distinct,
            live,
            listed_in,
            heap: BinaryHeap::new(),
        };
        p.heap = (0..n)
            .filter(|&i| p.free_end(i).is_some())
            .map(Reverse)
            .collect();
        p
    }

    /// The first free end of an enabled segment: the only enabled segment in its cell.
    fn free_end(&self, i: usize) -> Option<usize> {
        (0..2).find(|&j| self.live[self.lines[i].cell[j]] == 1)
    }

    fn disable(&mut self, i: usize) {
        self.disabled[i] = true;
        for &c in &self.listed_in[i] {
            self.live[c] -= 1;
            if self.live[c] == 1 {
                // The segment left alone there may have a free end now.
                if let Some(&k) = self.distinct[c].iter().find(|&&k| !self.disabled[k]) {
                    self.heap.push(Reverse(k));
                }
            }
        }
    }

    /// The paths: each its points in order, open ones first; a closed one without its first
    /// point (it repeats the last), as `toPolygon2d` takes them.
    fn extract(mut self) -> Vec<Vec<DVec2>> {
        let mut paths = vec![];
        while let Some(Reverse(i)) = self.heap.pop() {
            if self.disabled[i] {
                continue;
            }
            if let Some(j) = self.free_end(i) {
                paths.push(self.follow(i, j));
            }
        }
        for i in 0..self.lines.len() {
            if !self.disabled[i] {
                let mut path = self.follow(i, 0);
                path.remove(0);
                paths.push(path);
            }
        }
        paths
    }

    /// The path from end `j` of segment `i`, as far as segments join.
    fn follow(&mut self, mut i: usize, mut j: usize) -> Vec<DVec2> {
        let mut path = vec![self.lines[i].p[j]];
        loop {
            let seg = self.lines[i];
            path.push(seg.p[1 - j]);
            let c = seg.cell[1 - j];
            self.disable(i);
            let list = &self.walk[c];
            while self.skip[c] < list.len() && self.disabled[list[self.skip[c]]] {
                self.skip[c] += 1;
            }
            let Some(&k) = list.get(self.skip[c]) else {
                return path;
            };
            i = k;
            j = if self.lines[k].cell[0] == c { 0 } else { 1 };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings() -> Settings {
        Settings {
            layer: String::new(),
            origin: [0.0, 0.0],
            scale: 1.0,
            res: Resolution {
                fn_: 0.0,
                fa: 12.0,
                fs: 2.0,
            },
        }
    }

    fn drawing(text: &str) -> csgpix_scene::Result<Drawing> {
        parse(text.as_bytes(), "t.dxf", &settings(), 1_000_000)
    }

    fn area(p: &Poly2) -> f64 {
        p.paths.iter().map(|c| crate::linalg::signed_area(c)).sum()
    }

    fn entities(body: &str) -> String {
        format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n")
    }

    fn line(a: (f64, f64), b: (f64, f64)) -> String {
        format!(
            "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
            a.0, a.1, b.0, b.1
        )
    }

    /// Where `DxfData::DxfData` warns and goes on, so does csgpix: each case's warnings at
    /// their lines, and the drawing what is left.
    #[test]
    fn malformed_values_are_warnings_at_their_line() {
        let tri = |k: f64| {
            let p = [(k, k), (k + 2.0, k), (k + 2.0, k + 2.0)];
            (0..3)
                .map(|i| line(p[i], p[(i + 1) % 3]))
                .collect::<String>()
        };
        let short = "Not enough input values for LINE";
        for (text, warned, area_) in [
            // A value line missing at the end: the group code's value is empty.
            (format!("{}999", entities(&tri(0.0))), vec![], Some(2.0)),
            // A group code that is not a number: the rest (a second triangle) is not read.
            (
                format!("0\nSECTION\n2\nENTITIES\n{}X\nY\n{}", tri(0.0), tri(5.0)),
                vec![("t.dxf:41:", "Illegal ID \"X\"")],
                Some(2.0),
            ),
            // A coordinate that does not parse, or is not finite: skipped, so its LINE is
            // short of coordinates and keeps them for the next (OpenSCAD's state).
            (
                entities(&tri(0.0).replacen("10\n0\n", "10\n0.0.1\n", 1)),
                vec![
                    ("t.dxf:10:", "Illegal value \"0.0.1\" for group code 10"),
                    ("t.dxf:6:", short),
                ],
                None,
            ),
            (
                entities(&tri(0.0).replacen("\n2\n", "\n1e999\n", 1)),
                vec![
                    ("t.dxf:14:", "Illegal value \"1e999\""),
                    ("t.dxf:6:", short),
                ],
                None,
            ),
            // An integer that does not parse: skipped, the LINE drawn.
            (
                entities(&tri(0.0).replacen("8\n0\n", "8\n0\n70\n1.5\n", 1)),
                vec![("t.dxf:10:", "Illegal value \"1.5\" for group code 70")],
                Some(2.0),
            ),
        ] {
            let d = drawing(&text).unwrap_or_else(|e| panic!("{warned:?}: {e}"));
            assert_eq!(d.warnings.len(), warned.len(), "{:?}", d.warnings);
            for (w, (at, why)) in d.warnings.iter().zip(&warned) {
                assert!(w.starts_with(at) && w.contains(why), "{w}");
            }
            if let Some(a) = area_ {
                assert!((area(&d.shape).abs() - a).abs() < 1e-9, "{warned:?}");
            }
        }
    }

    #[test]
    fn loose_lines_join_into_a_closed_square() {
        let body: String = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]
            .windows(2)
            .map(|w| line(w[0], w[1]))
            .chain([line((0.0, 0.0), (0.0, 2.0))])
            .collect();
        let d = drawing(&entities(&body)).unwrap();
        assert!((area(&d.shape).abs() - 4.0).abs() < 1e-9);
        assert!(d.warnings.is_empty());
    }

    /// Segment ends a thousandth apart fall in one grid cell (or a neighbour's): joined.
    #[test]
    fn nearly_meeting_ends_join() {
        let body: String = [
            line((0.0, 0.0), (1.0, 0.0)),
            line((1.0008, -0.0008), (1.0, 1.0)),
            line((1.0, 1.0), (0.0, 0.0)),
        ]
        .concat();
        let d = drawing(&entities(&body)).unwrap();
        assert!((area(&d.shape).abs() - 0.5).abs() < 1e-3);
        // Three corners: (1.0008, -0.0008), in a neighbouring cell, was snapped onto (1, 0).
        assert_eq!(d.shape.points().count(), 3, "{:?}", d.shape.paths);
    }

    /// POLYLINE, VERTEX, SEQEND and SPLINE draw nothing in 2021.01, with its warning; an
    /// open LWPOLYLINE is closed; bulges are ignored.
    #[test]
    fn unsupported_entities_warn_and_open_paths_close() {
        let body = "0\nPOLYLINE\n8\n0\n70\n1\n0\nVERTEX\n8\n0\n10\n0\n20\n0\n0\nVERTEX\n\
                    8\n0\n10\n5\n20\n0\n0\nSEQEND\n0\nSPLINE\n8\n0\n\
                    0\nLWPOLYLINE\n8\n0\n90\n3\n70\n0\n10\n0\n20\n0\n42\n1\n10\n4\n20\n0\n\
                    10\n4\n20\n3\n";
        let d = drawing(&entities(body)).unwrap();
        assert!(
            (area(&d.shape).abs() - 6.0).abs() < 1e-9,
            "{}",
            area(&d.shape)
        );
        let w = d.warnings.join("\n");
        for e in [
            "'POLYLINE' (1)",
            "'VERTEX' (2)",
            "'SEQEND' (1)",
            "'SPLINE' (1)",
        ] {
            assert!(w.contains(e), "{w}");
        }
    }

    /// A LINE with one point: OpenSCAD's "Not enough input values", its state kept so the
    /// next LINE's points add to it (a segment from the first point to the next one's start).
    #[test]
    fn short_entity_warns_and_keeps_its_values() {
        let body = format!(
            "0\nLINE\n8\n0\n10\n0\n20\n0\n{}{}",
            line((3.0, 0.0), (3.0, 3.0)),
            line((3.0, 3.0), (0.0, 0.0))
        );
        let d = drawing(&entities(&body)).unwrap();
        assert_eq!(d.warnings.len(), 1, "{:?}", d.warnings);
        assert!(d.warnings[0].starts_with("t.dxf:6: Not enough input values for LINE"));
        assert!(
            (area(&d.shape).abs() - 4.5).abs() < 1e-9,
            "{}",
            area(&d.shape)
        );
    }

    #[test]
    fn segments_count_against_the_budget() {
        let circle = entities("0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n100\n");
        let e = parse(circle.as_bytes(), "t.dxf", &settings(), 40)
            .err()
            .unwrap()
            .to_string();
        assert!(
            e.starts_with("t.dxf:6: the CIRCLE entity would pass"),
            "{e}"
        );
        assert!(parse(circle.as_bytes(), "t.dxf", &settings(), 60).is_ok());
    }

    /// A circle drawn twice cancels by the even-odd rule, an arc over 101 whole turns is one
    /// circle (OpenSCAD 2021.01 draws the same: a 16-gon of radius 5 and a 30-gon of
    /// radius 10), and the turns' coincident copies are dropped before the fill.
    #[test]
    fn coincident_copies_cancel_by_parity() {
        let circle = |x: f64, r: f64| format!("0\nCIRCLE\n8\n0\n10\n{x}\n20\n0\n40\n{r}\n");
        let arc = "0\nARC\n8\n0\n10\n60\n20\n0\n40\n10\n50\n0\n51\n36360\n";
        let body = [
            circle(0.0, 10.0),
            circle(0.0, 10.0),
            circle(30.0, 5.0),
            arc.into(),
        ];
        let d = drawing(&entities(&body.concat())).unwrap();
        assert_eq!(d.shape.points().count(), 16 + 30);
        let polygon = |n: f64, r: f64| n / 2.0 * r * r * (2.0 * std::f64::consts::PI / n).sin();
        let want = polygon(16.0, 5.0) + polygon(30.0, 10.0);
        // The corners are snapped to the 1/1024 grid.
        assert!(
            (area(&d.shape).abs() - want).abs() < 1e-4 * want,
            "{}",
            area(&d.shape)
        );
    }
}

//! `surface(file, center, invert, convexity)`: a height map read from a `.dat` text grid or a
//! PNG image, closed below into a solid, as OpenSCAD 2021.01 does it (`src/surface.cc`).
//!
//! * [`read`] follows `SurfaceNode::read_png_or_dat`: a file starting with the PNG signature is
//!   an image ([`read_png`], OpenSCAD's `read_png_data`/`convert_image`), anything else a
//!   `.dat` grid ([`read_dat`], OpenSCAD's `read_dat`). A file that cannot be opened and a PNG
//!   that cannot be decoded give no heights and OpenSCAD's warning; so does an illegal value in
//!   a grid, which ends the grid there.
//! * [`mesh`] follows `SurfaceNode::createGeometry`: each cell of four heights is four
//!   triangles meeting at its centre (at their mean height), the walls go down from the outer
//!   heights to the floor, one below the lowest height and never above 0, and the floor closes
//!   the solid. `center` moves the grid's middle to x = y = 0.
//!
//! csgpix adds limits OpenSCAD has not: the grid is checked against the scene's vertex budget
//! before anything of its size is allocated (an image's size is in its header), a `.dat` line
//! may hold at most [`MAX_DAT_LINE`] bytes (comment lines excepted), and a height that is not
//! finite (`inf`, `nan`, which OpenSCAD takes in and meshes into nonsense) is refused, at its
//! line and column.

use std::io::{BufRead, Read, Seek, SeekFrom};
use std::path::Path;

use csgpix_scene::error::Rule;
use csgpix_scene::Error;
use glam::DVec3;

use crate::{lex::*, node::*, value::*};

/// The longest `.dat` line csgpix holds, in bytes: a guard on memory (a comment line may be
/// longer: it is skipped without being held).
pub const MAX_DAT_LINE: usize = 1 << 26;

/// The PNG signature OpenSCAD's `SurfaceNode::is_png` looks for.
const PNG_SIGNATURE: [u8; 8] = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

/// Heights on a grid, OpenSCAD's `img_data_t`: `rows[r][c]` is the height at x = c, y = r.
/// Rows of a `.dat` file may be ragged: a missing entry is 0 in the mesh (OpenSCAD's map
/// default) but takes no part in the floor.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Heights {
    /// The rows, the first at y = 0.
    pub rows: Vec<Vec<f64>>,
}

impl Heights {
    /// The number of rows (OpenSCAD's `lines`).
    pub fn lines(&self) -> usize {
        self.rows.len()
    }

    /// The longest row's length (OpenSCAD's `columns`).
    pub fn columns(&self) -> usize {
        self.rows.iter().map(Vec::len).max().unwrap_or(0)
    }

    /// The height at row `r`, column `c`; 0 where the row is short.
    fn at(&self, r: usize, c: usize) -> f64 {
        self.rows[r].get(c).copied().unwrap_or(0.0)
    }

    /// The floor's height: the lowest given height less 1, and at most 0 (`min_val` of
    /// `createGeometry`).
    pub fn floor(&self) -> f64 {
        self.rows
            .iter()
            .flatten()
            .fold(0.0, |m, &v| f64::min(v - 1.0, m))
    }
}

/// What a surface file gives: its heights (none, when OpenSCAD draws nothing) and OpenSCAD's
/// warnings about it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Surface {
    /// The heights.
    pub heights: Heights,
    /// OpenSCAD's warnings, in its words, each one line.
    pub warnings: Vec<String>,
}

/// The vertices (three per triangle) of the mesh [`mesh`] makes of a grid of `lines` ×
/// `columns`: what it costs of the scene's vertex budget.
pub fn mesh_vertices(lines: usize, columns: usize) -> usize {
    let (l, c) = (lines.saturating_sub(1), columns.saturating_sub(1));
    let top = l.saturating_mul(c).saturating_mul(4);
    let sides = l.saturating_add(c).saturating_mul(6);
    top.saturating_add(sides).saturating_mul(3)
}

/// The refusal of a grid of `lines` × `columns` that passes the `budget`.
fn over_budget(lines: usize, columns: usize, budget: usize) -> Option<Error> {
    let n = mesh_vertices(lines, columns);
    (n > budget).then_some(Error::SurfaceTooLarge {
        lines,
        columns,
        vertices: n,
        left: budget,
    })
}

/// The heights of the file at `path` (`SurfaceNode::read_png_or_dat`), `name` in messages. A
/// file that cannot be opened or read gives OpenSCAD's warning and no heights.
///
/// # Errors
///
/// A grid past the vertex `budget`, a `.dat` line over [`MAX_DAT_LINE`] bytes, a height that
/// is not finite: one line located in the file.
pub fn read(path: &Path, invert: bool, budget: usize) -> csgpix_scene::Result<Surface> {
    let name = path.display().to_string();
    let file = match std::fs::File::open(path) {
        Ok(f) => f,
        Err(_) => return Ok(cannot_open(&name)),
    };
    let got = read_from(std::io::BufReader::new(file), &name, invert, budget);
    match got {
        // Reading failed part way (a directory, a device): the file could not be loaded.
        Err(e) if e.io_kind().is_some() => Ok(cannot_open(&name)),
        got => got,
    }
}

/// OpenSCAD's warning for a file `lodepng::load_file` cannot open.
fn cannot_open(name: &str) -> Surface {
    Surface {
        heights: Heights::default(),
        warnings: vec![format!("The file '{name}' couldn't be opened.")],
    }
}

/// [`read`] from an open file (or bytes: a `std::io::Cursor`), `name` in messages.
///
/// # Errors
///
/// As [`read`]; a failure to read is an [`Error::Io`].
pub fn read_from<R: BufRead + Seek>(
    mut r: R,
    name: &str,
    invert: bool,
    budget: usize,
) -> csgpix_scene::Result<Surface> {
    let io = |e: std::io::Error| Error::io(name, &e);
    let mut head = Vec::with_capacity(8);
    r.by_ref().take(8).read_to_end(&mut head).map_err(io)?;
    r.seek(SeekFrom::Start(0)).map_err(io)?;
    if head == PNG_SIGNATURE {
        read_png(r, name, invert, budget)
    } else {
        read_dat(r, name, budget)
    }
}

/// The bytes C's `isspace` takes as white space: `boost::trim` removes them.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | 0x0b | 0x0c | b'\r')
}

/// `line` without the white space at either end, and where it starts in `line`.
fn trim(line: &[u8]) -> (usize, &[u8]) {
    let start = line
        .iter()
        .position(|&b| !is_space(b))
        .unwrap_or(line.len());
    let end = line
        .iter()
        .rposition(|&b| !is_space(b))
        .map_or(start, |e| e + 1);
    (start, &line[start..end])
}

/// One line as `std::getline` gives it, into `buf` without its `'\n'`: whether the file ended
/// before a `'\n'` (the stream's eof after the call), and whether the line was too long to
/// hold whole (only its first [`MAX_DAT_LINE`] bytes are in `buf`).
fn next_line<R: BufRead>(r: &mut R, buf: &mut Vec<u8>) -> std::io::Result<(bool, bool)> {
    buf.clear();
    let mut long = false;
    loop {
        let chunk = r.fill_buf()?;
        if chunk.is_empty() {
            return Ok((true, long));
        }
        let (part, used, done) = match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => (&chunk[..i], i + 1, true),
            None => (chunk, chunk.len(), false),
        };
        let room = MAX_DAT_LINE.saturating_sub(buf.len());
        long |= part.len() > room;
        buf.extend_from_slice(&part[..part.len().min(room)]);
        r.consume(used);
        if done {
            return Ok((false, long));
        }
    }
}

/// A `.dat` value as `boost::lexical_cast<double>` reads it: a decimal number, `inf`,
/// `infinity` or `nan` (any case, signed), `nan(…)`; `None` for anything else, a number beyond
/// the doubles among them.
fn dat_value(token: &[u8]) -> Option<f64> {
    let s = std::str::from_utf8(token).ok()?;
    let lower = s.to_ascii_lowercase();
    let unsigned = lower.strip_prefix(['+', '-']).unwrap_or(&lower);
    if unsigned.starts_with("nan(") && unsigned.ends_with(')') {
        return Some(f64::NAN);
    }
    let v: f64 = s.parse().ok()?;
    let spelled_infinite = unsigned == "inf" || unsigned == "infinity";
    (!v.is_infinite() || spelled_infinite).then_some(v)
}

/// The 1-based column, in characters, of byte `at` of `line`.
fn column(line: &[u8], at: usize) -> usize {
    1 + line[..at].iter().filter(|&&b| b & 0xc0 != 0x80).count()
}

/// A `.dat` grid as OpenSCAD's `SurfaceNode::read_dat` reads it: lines of numbers separated
/// by spaces and tabs, white space at either end of a line ignored, blank lines and lines
/// starting with `#` skipped. An illegal value ends the grid (the values before it on its
/// line stay) with OpenSCAD's warning, unless it is on a last line without a newline (where
/// OpenSCAD's stream is at its end and it says nothing).
///
/// # Errors
///
/// The grid passes the vertex `budget`; a line is over [`MAX_DAT_LINE`] bytes; a height is
/// `inf` or `nan`; a failure to read.
pub fn read_dat<R: BufRead>(mut r: R, name: &str, budget: usize) -> csgpix_scene::Result<Surface> {
    let mut out = Surface::default();
    let (mut buf, mut number, mut columns) = (Vec::new(), 0, 0);
    loop {
        let (eof, long) = next_line(&mut r, &mut buf).map_err(|e| Error::io(name, &e))?;
        number += 1;
        let (start, line) = trim(&buf);
        // A line held in part is a comment when its start says so; else it is refused.
        if long && line.first() != Some(&b'#') {
            let e = Error::LineTooLong {
                limit: MAX_DAT_LINE,
                format: None,
            };
            return Err(Error::at(name, number, 1, e));
        }
        if line.first().is_none_or(|&b| b == b'#') {
            // A comment at the end without a newline: OpenSCAD reads it as values and stops at
            // the `#` without a word.
            if eof {
                break;
            }
            continue;
        }
        let mut row = Vec::new();
        let mut illegal = None;
        let mut at = start;
        for token in line.split(|&b| b == b' ' || b == b'\t') {
            let col = at;
            at += token.len() + 1;
            if token.is_empty() {
                continue;
            }
            let Some(v) = dat_value(token) else {
                illegal = Some((col, token));
                break;
            };
            if !v.is_finite() {
                let tok = String::from_utf8_lossy(token);
                let e = Error::NonFiniteHeight {
                    token: tok.into_owned(),
                };
                return Err(Error::at(name, number, column(&buf, col), e));
            }
            row.push(v);
            columns = columns.max(row.len());
            if let Some(msg) = over_budget(out.heights.lines() + 1, columns, budget) {
                return Err(Error::at(name, number, column(&buf, col), msg));
            }
        }
        if !row.is_empty() {
            out.heights.rows.push(row);
        }
        if let Some((col, token)) = illegal {
            if !eof {
                // A token may hold a CR or a form feed: shown escaped, the warning one line.
                let tok = String::from_utf8_lossy(token).escape_debug().to_string();
                let col = column(&buf, col);
                out.warnings.push(format!(
                    "Illegal value in '{name}': {name}:{number}:{col}: `{tok}` is not a \
                     number; the rest of the file is ignored"
                ));
            }
            break;
        }
        if eof {
            break;
        }
    }
    Ok(out)
}

/// A PNG image as OpenSCAD's `read_png_data` and `convert_image` read it: decoded to RGBA with
/// 8 bits a channel as `lodepng::decode` does (a palette looked up, an index past it black,
/// grey of 1, 2 or 4 bits scaled to 0..=255, 16-bit samples cut to their high byte), each
/// pixel's grey `0.2126 r + 0.7152 g + 0.0722 b` scaled by 100/255 (with `invert`, of
/// `1 - grey`: OpenSCAD 2021.01 subtracts from 1, not 255), the image's top row at the top
/// (the last row of the grid). A file the decoder refuses gives OpenSCAD's warning and no
/// heights.
///
/// # Errors
///
/// The image passes the vertex `budget` (located at its width, byte 16); the decoder needs more
/// memory than its limit (64 MiB beside the pixels).
pub fn read_png<R: BufRead + Seek>(
    r: R,
    name: &str,
    invert: bool,
    budget: usize,
) -> csgpix_scene::Result<Surface> {
    let cant = || Surface {
        heights: Heights::default(),
        warnings: vec![format!("Can't read PNG image '{name}'")],
    };
    let mut decoder = png::Decoder::new(r);
    decoder.set_transformations(png::Transformations::EXPAND);
    decoder.set_ignore_text_chunk(true);
    decoder.set_ignore_iccp_chunk(true);
    let Ok(info) = decoder.read_header_info() else {
        return Ok(cant());
    };
    let (width, height) = info.size();
    let (w, h) = (width as usize, height as usize);
    if let Some(msg) = over_budget(h, w, budget) {
        let e = Error::ImageSize {
            width: w,
            height: h,
            problem: Box::new(msg),
        };
        return Err(Error::at(name, 0, 17, e));
    }
    let limits = |e: &png::DecodingError| matches!(e, png::DecodingError::LimitsExceeded);
    let refused = |e: png::DecodingError| {
        Error::at(
            name,
            0,
            1,
            Error::Png {
                reason: e.to_string(),
            },
        )
    };
    let mut reader = match decoder.read_info() {
        Ok(reader) => reader,
        Err(e) if limits(&e) => return Err(refused(e)),
        Err(_) => return Ok(cant()),
    };
    // A palette of a broken number of entries: lodepng refuses it (its error 38), and the
    // png crate's palette expansion panics on one that is not whole RGB triples.
    let palette = reader.info().palette.as_deref().map(<[u8]>::len);
    if palette.is_some_and(|n| n == 0 || n % 3 != 0 || n > 3 * 256) {
        return Ok(cant());
    }
    let Some(size) = reader.output_buffer_size() else {
        return Ok(cant());
    };
    let mut pixels = vec![0; size];
    let frame = reader.next_frame(&mut pixels).and_then(|f| {
        reader.finish()?;
        Ok(f)
    });
    let frame = match frame {
        Ok(frame) => frame,
        Err(e) if limits(&e) => return Err(refused(e)),
        Err(_) => return Ok(cant()),
    };
    let heights = grey_heights(&pixels, &frame, invert);
    Ok(Surface {
        heights,
        warnings: vec![],
    })
}

/// The heights of decoded pixels (grey or RGB, with or without alpha, 8 or 16 bits: the
/// decoder's output after `EXPAND`), OpenSCAD's `convert_image`.
fn grey_heights(pixels: &[u8], frame: &png::OutputInfo, invert: bool) -> Heights {
    use png::ColorType::*;
    let channels = match frame.color_type {
        Grayscale => 1,
        GrayscaleAlpha => 2,
        Rgb => 3,
        Rgba => 4,
        // `EXPAND` turns a palette into RGB(A).
        Indexed => 1,
    };
    let bytes = if frame.bit_depth == png::BitDepth::Sixteen {
        2
    } else {
        1
    };
    let (w, h) = (frame.width as usize, frame.height as usize);
    let mut rows = vec![Vec::new(); h];
    for (y, line) in pixels.chunks(frame.line_size).take(h).enumerate() {
        // Big-endian samples: the first byte of each is the high one lodepng keeps.
        let sample = |x: usize, k: usize| f64::from(line[(x * channels + k) * bytes]);
        let row = (0..w).map(|x| {
            let (r, g, b) = if channels < 3 {
                (sample(x, 0), sample(x, 0), sample(x, 0))
            } else {
                (sample(x, 0), sample(x, 1), sample(x, 2))
            };
            let grey = 0.2126 * r + 0.7152 * g + 0.0722 * b;
            100.0 / 255.0 * if invert { 1.0 - grey } else { grey }
        });
        rows[h - 1 - y] = row.collect();
    }
    Heights { rows }
}

/// The closed mesh of `SurfaceNode::createGeometry`, outward-facing triangles: each cell four
/// triangles round its centre, the four walls (quads from the floor to the outer heights, each
/// two triangles), and the floor as a fan round its centre (OpenSCAD's one polygon through
/// every point of the floor's rim, which its tessellation splits the same way up to
/// triangulation). Triangles of no area (a wall where a missing height of 0 meets a floor at
/// 0) are left out. Fewer than 2 rows or columns enclose nothing: no triangles.
pub fn mesh(h: &Heights, center: bool) -> Vec<[DVec3; 3]> {
    let (lines, columns) = (h.lines(), h.columns());
    if lines < 2 || columns < 2 {
        return vec![];
    }
    let floor = h.floor();
    // OpenSCAD writes `ox + j-1`: (ox + j) - 1, kept in that order.
    let ox = if center {
        -((columns - 1) as f64) / 2.0
    } else {
        0.0
    };
    let oy = if center {
        -((lines - 1) as f64) / 2.0
    } else {
        0.0
    };
    let p = |c: usize, r: usize, z: f64| DVec3::new(ox + c as f64, oy + r as f64, z);
    let mut tris = Vec::with_capacity(mesh_vertices(lines, columns) / 3);
    for i in 1..lines {
        for j in 1..columns {
            let (v1, v2) = (h.at(i - 1, j - 1), h.at(i - 1, j));
            let (v3, v4) = (h.at(i, j - 1), h.at(i, j));
            let vx = (v1 + v2 + v3 + v4) / 4.0;
            let mid = DVec3::new(ox + j as f64 - 0.5, oy + i as f64 - 0.5, vx);
            let (a, b) = (p(j - 1, i - 1, v1), p(j, i - 1, v2));
            let (c, d) = (p(j - 1, i, v3), p(j, i, v4));
            tris.extend([[a, b, mid], [b, d, mid], [d, c, mid], [c, a, mid]]);
        }
    }
    let mut quad = |q: [DVec3; 4]| tris.extend([[q[0], q[1], q[2]], [q[0], q[2], q[3]]]);
    let (last_c, last_r) = (columns - 1, lines - 1);
    for i in 1..lines {
        let (lo, hi) = (i - 1, i);
        quad([
            p(0, lo, floor),
            p(0, lo, h.at(lo, 0)),
            p(0, hi, h.at(hi, 0)),
            p(0, hi, floor),
        ]);
        let (zl, zh) = (h.at(lo, last_c), h.at(hi, last_c));
        quad([
            p(last_c, hi, floor),
            p(last_c, hi, zh),
            p(last_c, lo, zl),
            p(last_c, lo, floor),
        ]);
    }
    for i in 1..columns {
        let (lo, hi) = (i - 1, i);
        quad([
            p(hi, 0, floor),
            p(hi, 0, h.at(0, hi)),
            p(lo, 0, h.at(0, lo)),
            p(lo, 0, floor),
        ]);
        let (zl, zh) = (h.at(last_r, lo), h.at(last_r, hi));
        quad([
            p(lo, last_r, floor),
            p(lo, last_r, zl),
            p(hi, last_r, zh),
            p(hi, last_r, floor),
        ]);
    }
    floor_fan(&mut tris, &p, columns, lines, floor);
    tris.retain(|t| (t[1] - t[0]).cross(t[2] - t[0]) != DVec3::ZERO);
    tris
}

/// The floor: the rim's points counter-clockwise seen from above (as OpenSCAD lists them
/// before reversing them), each edge a triangle with the floor's centre, facing down.
fn floor_fan(
    tris: &mut Vec<[DVec3; 3]>,
    p: &impl Fn(usize, usize, f64) -> DVec3,
    columns: usize,
    lines: usize,
    floor: f64,
) {
    let (c, r) = (columns - 1, lines - 1);
    let rim: Vec<DVec3> = (0..c)
        .map(|i| p(i, 0, floor))
        .chain((0..r).map(|i| p(c, i, floor)))
        .chain((1..=c).rev().map(|i| p(i, r, floor)))
        .chain((1..=r).rev().map(|i| p(0, i, floor)))
        .collect();
    let centre = (p(0, 0, floor) + p(c, r, floor)) / 2.0;
    for (k, &a) in rim.iter().enumerate() {
        let b = rim[(k + 1) % rim.len()];
        tris.push([centre, b, a]);
    }
}

/// `surface(file, center, convexity, invert)` as OpenSCAD 2021.01's `SurfaceModule::instantiate`
/// takes it: `center` and `invert` count only when true or false (anything else is false),
/// `convexity` and the CSG export's `timestamp` are ignored, a missing `file` is the empty name
/// (which cannot be opened).
pub(crate) struct SurfaceArgs {
    pub(crate) file: String,
    pub(crate) center: bool,
    pub(crate) invert: bool,
}

pub(crate) fn surface_args(head: &Head) -> Result<SurfaceArgs, Fail> {
    let p = &head.params;
    let file = match p.get("file") {
        None => String::new(),
        Some(Value {
            kind: Kind::Str(s), ..
        }) => s.clone(),
        Some(v) => return fail(v.pos, must("`file`", Rule::Text)),
    };
    let flag = |name: &str| matches!(p.get(name).map(|v| &v.kind), Some(Kind::Bool(true)));
    Ok(SurfaceArgs {
        file,
        center: flag("center"),
        invert: flag("invert"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    const BIG: usize = usize::MAX;

    fn dat(text: &str) -> Surface {
        read_from(Cursor::new(text.as_bytes()), "h.dat", false, BIG).unwrap()
    }

    fn dat_err(text: &str) -> String {
        read_from(Cursor::new(text.as_bytes()), "h.dat", false, BIG)
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn dat_rows_comments_blank_lines_and_white_space() {
        // Each case was checked against openscad 2021.01's mesh of it.
        let want = vec![vec![1.0, 2.0], vec![3.0, 4.0]];
        for text in [
            "1 2\n3 4\n",
            "1 2\r\n\r\n3 4\r\n",
            "\x0c1 2\x0b\n3 4",
            "# heights\n  1 2\n\n\t# more\n3\t\t4\n# end",
        ] {
            let s = dat(text);
            assert_eq!(s.heights.rows, want, "{text:?}");
            assert!(s.warnings.is_empty(), "{text:?}");
        }
        // Values as boost::lexical_cast reads them; 1e-400 is 0.
        let s = dat("+1 .5 1. 1e1 1E+1 00012 -3 1e-400\n");
        assert_eq!(
            s.heights.rows,
            [[1.0, 0.5, 1.0, 10.0, 10.0, 12.0, -3.0, 0.0]]
        );
        assert_eq!(s.heights.floor(), -4.0);
        // Ragged rows: the longest row sets the columns; a missing entry is 0 in the mesh.
        let s = dat("1 2 3\n4 5\n7 8 9 10\n");
        assert_eq!((s.heights.lines(), s.heights.columns()), (3, 4));
        assert_eq!(s.heights.at(1, 2), 0.0);
        // All heights of at least 1: the floor is at 0.
        assert_eq!(s.heights.floor(), 0.0);
    }

    #[test]
    fn an_illegal_dat_value_ends_the_grid_with_openscads_warning() {
        for (text, rows) in [
            ("1 2\n3 x\n5 6\n", vec![vec![1.0, 2.0], vec![3.0]]),
            ("1 2\n3 4 # c\n", vec![vec![1.0, 2.0], vec![3.0, 4.0]]),
            ("1 2\n0x10 3\n", vec![vec![1.0, 2.0]]),
            ("1 2\n1e400 3\n", vec![vec![1.0, 2.0]]),
            ("1 2\n1,5 3\n", vec![vec![1.0, 2.0]]),
            ("1 2\n3\x0b4\n", vec![vec![1.0, 2.0]]),
            ("1 2\n\u{663} 4\n", vec![vec![1.0, 2.0]]),
            ("1 2\n\u{e9}\u{e9} x\n", vec![vec![1.0, 2.0]]),
        ] {
            let s = dat(text);
            assert_eq!(s.heights.rows, rows, "{text:?}");
            assert_eq!(s.warnings.len(), 1, "{text:?}");
            assert!(
                s.warnings[0].starts_with("Illegal value in 'h.dat': h.dat:2:"),
                "{s:?}"
            );
        }
        let s = dat("1 2\n\u{e9}\u{e9} x\n");
        assert!(
            s.warnings[0].contains("h.dat:2:1: `éé` is not a number"),
            "{s:?}"
        );
        let s = dat("1 2\n 3 x\n");
        assert!(s.warnings[0].contains("h.dat:2:4: `x`"), "{s:?}");
        // On a last line without a newline OpenSCAD's stream is at its end: no warning.
        let s = dat("1 2\n3 x");
        assert_eq!(s.heights.rows, [vec![1.0, 2.0], vec![3.0]]);
        assert!(s.warnings.is_empty());
    }

    #[test]
    fn non_finite_heights_are_refused_at_their_place() {
        for (text, at) in [
            ("inf 1\n1 1\n", "h.dat:1:1: a height of `inf`"),
            ("1 1\n1  -Infinity\n", "h.dat:2:4: a height of `-Infinity`"),
            ("1 NaN\n", "h.dat:1:3: a height of `NaN`"),
            ("1 1\n1 nan(x)", "h.dat:2:3: a height of `nan(x)`"),
        ] {
            let e = dat_err(text);
            assert!(e.starts_with(at), "{e}");
            assert_eq!(e.lines().count(), 1);
        }
    }

    #[test]
    fn a_grid_past_the_budget_is_refused_before_it_is_held() {
        // 3 × 3 heights: 4 cells of 4 triangles, 4 sides of 2 quads, a floor of 8: 40 triangles.
        assert_eq!(mesh_vertices(3, 3), 40 * 3);
        let text = "1 1 1\n1 1 1\n1 1 1\n";
        let ok = read_from(Cursor::new(text), "h.dat", false, 120).unwrap();
        assert_eq!(ok.heights.lines(), 3);
        let e = read_from(Cursor::new(text), "h.dat", false, 119)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("h.dat:3:1: a grid of 3 × 3 heights would pass"),
            "{e}"
        );
        // One line of a million values past a small budget: refused at the value that passes.
        let line = "1 ".repeat(1_000_000);
        let e = read_from(Cursor::new(format!("1\n{line}")), "h.dat", false, 1000)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("h.dat:2:"), "{e}");
    }

    /// A PNG of `w` × `h` pixels of `color` and `depth` from its samples.
    fn png_bytes(
        w: u32,
        h: u32,
        color: png::ColorType,
        depth: png::BitDepth,
        palette: Option<&[u8]>,
        data: &[u8],
    ) -> Vec<u8> {
        let mut out = Vec::new();
        let mut e = png::Encoder::new(&mut out, w, h);
        e.set_color(color);
        e.set_depth(depth);
        if let Some(p) = palette {
            e.set_palette(p.to_vec());
        }
        let mut writer = e.write_header().unwrap();
        writer.write_image_data(data).unwrap();
        writer.finish().unwrap();
        out
    }

    fn png_heights(bytes: &[u8], invert: bool) -> Surface {
        read_from(Cursor::new(bytes), "i.png", invert, BIG).unwrap()
    }

    #[test]
    fn png_pixels_become_heights_as_lodepng_and_convert_image_give_them() {
        use png::{BitDepth::*, ColorType::*};
        let scale = 100.0 / 255.0;
        let grey = |r: f64, g: f64, b: f64| scale * (0.2126 * r + 0.7152 * g + 0.0722 * b);
        // 2 × 2 grey: the image's top row is the grid's last.
        let s = png_heights(
            &png_bytes(2, 2, Grayscale, Eight, None, &[0, 51, 102, 255]),
            false,
        );
        let g = |v: f64| grey(v, v, v);
        assert_eq!(s.heights.rows, [[g(102.0), g(255.0)], [0.0, g(51.0)]]);
        // RGB: 0.2126 r + 0.7152 g + 0.0722 b.
        let rgb = [255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30];
        let s = png_heights(&png_bytes(2, 2, Rgb, Eight, None, &rgb), false);
        assert_eq!(
            s.heights.rows[1],
            [grey(255.0, 0.0, 0.0), grey(0.0, 255.0, 0.0)]
        );
        assert_eq!(
            s.heights.rows[0],
            [grey(0.0, 0.0, 255.0), grey(10.0, 20.0, 30.0)]
        );
        // invert: OpenSCAD 2021.01 takes 1 - grey (not 255 - grey).
        let s = png_heights(&png_bytes(1, 2, Grayscale, Eight, None, &[0, 255]), true);
        let lum = |v: f64| 0.2126 * v + 0.7152 * v + 0.0722 * v;
        assert_eq!(
            s.heights.rows,
            [[scale * (1.0 - lum(255.0))], [scale * 1.0]]
        );
        // 16 bits: the high byte of each sample; alpha is ignored.
        let s = png_heights(
            &png_bytes(1, 1, GrayscaleAlpha, Sixteen, None, &[200, 255, 9, 9]),
            false,
        );
        assert_eq!(s.heights.rows, [[g(200.0)]]);
        let s = png_heights(
            &png_bytes(1, 1, Rgba, Sixteen, None, &[1, 2, 3, 4, 5, 6, 7, 8]),
            false,
        );
        assert_eq!(s.heights.rows, [[grey(1.0, 3.0, 5.0)]]);
        // 2-bit grey scaled by 255 / 3; a palette looked up, an index past it black.
        let s = png_heights(
            &png_bytes(4, 1, Grayscale, Two, None, &[0b00_01_10_11]),
            false,
        );
        assert_eq!(s.heights.rows, [[0.0, g(85.0), g(170.0), g(255.0)]]);
        let pal = [10, 20, 30, 255, 255, 255];
        let s = png_heights(
            &png_bytes(3, 1, Indexed, Eight, Some(&pal), &[1, 0, 7]),
            false,
        );
        assert_eq!(s.heights.rows, [[g(255.0), grey(10.0, 20.0, 30.0), 0.0]]);
    }

    #[test]
    fn a_png_openscad_cannot_read_is_empty_with_its_warning() {
        let good = png_bytes(
            3,
            3,
            png::ColorType::Grayscale,
            png::BitDepth::Eight,
            None,
            &[7; 9],
        );
        let mut crc = good.clone();
        crc[40] ^= 1;
        for bad in [&good[..good.len() - 20], &good[..12], &crc[..]] {
            let s = png_heights(bad, false);
            assert_eq!(s.heights, Heights::default());
            assert_eq!(s.warnings, ["Can't read PNG image 'i.png'"]);
        }
        // Eight bytes or fewer that are not the signature: a .dat grid.
        assert_eq!(dat("\u{89}PN").warnings.len(), 0);
        // A palette of 16 bytes (not whole RGB triples), found by the fuzzer: the png crate's
        // palette expansion panicked; lodepng refuses it.
        let root = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../fuzz/regressions/surface"
        );
        let bad = std::fs::read(format!("{root}/png-palette-of-16-bytes")).unwrap();
        let s = png_heights(&bad, false);
        assert_eq!(s.warnings, ["Can't read PNG image 'i.png'"]);
    }

    #[test]
    fn a_png_past_the_budget_is_refused_from_its_header() {
        let mut bytes = png_bytes(
            2,
            2,
            png::ColorType::Grayscale,
            png::BitDepth::Eight,
            None,
            &[0; 4],
        );
        // Claim 60000 × 60000 pixels (the header's CRC mended): refused before decoding.
        bytes[16..24].copy_from_slice(&[0, 0, 0xea, 0x60, 0, 0, 0xea, 0x60]);
        let crc = crc32(&bytes[12..29]);
        bytes[29..33].copy_from_slice(&crc.to_be_bytes());
        let e = read_from(Cursor::new(&bytes), "i.png", false, 20_000_000)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("i.png:0:17: a 60000×60000 image: a grid of"),
            "{e}"
        );
    }

    /// The PNG chunk CRC (ISO 3309), bit by bit.
    fn crc32(bytes: &[u8]) -> u32 {
        let mut c = !0u32;
        for &b in bytes {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    0xedb8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
        }
        !c
    }

    /// The signed volume of a triangle mesh (the divergence theorem).
    fn volume(tris: &[[DVec3; 3]]) -> f64 {
        tris.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0
    }

    #[test]
    fn the_mesh_is_closed_outward_and_holds_the_volume_under_the_heights() {
        let s = dat("3 1 4 1\n5 -9 2 6\n5 3 5\n");
        let h = &s.heights;
        for center in [false, true] {
            let tris = mesh(h, center);
            // Every edge is met once each way: closed and consistently wound.
            let key = |v: DVec3| v.to_array().map(f64::to_bits);
            let mut edges = std::collections::HashMap::new();
            for t in &tris {
                for k in 0..3 {
                    *edges.entry((key(t[k]), key(t[(k + 1) % 3]))).or_insert(0) += 1;
                }
            }
            for (&(a, b), &n) in &edges {
                assert_eq!(Some(&n), edges.get(&(b, a)), "edge {a:?} {b:?}");
            }
            // Each cell's four triangles hold the mean of its corners above the floor.
            let floor = h.floor();
            assert_eq!(floor, -10.0);
            let mut want = 0.0;
            for i in 1..h.lines() {
                for j in 1..h.columns() {
                    let corners = h.at(i - 1, j - 1) + h.at(i - 1, j) + h.at(i, j - 1) + h.at(i, j);
                    want += corners / 4.0 - floor;
                }
            }
            assert!(
                (volume(&tris) - want).abs() < 1e-9,
                "{} {want}",
                volume(&tris)
            );
            let xs = tris.iter().flatten().map(|v| v.x);
            let lo = xs.clone().fold(f64::MAX, f64::min);
            assert_eq!(lo, if center { -1.5 } else { 0.0 });
        }
        // Fewer than 2 rows or columns: nothing.
        assert!(mesh(&dat("1 2 3\n").heights, false).is_empty());
        assert!(mesh(&dat("1\n2\n").heights, false).is_empty());
    }
}

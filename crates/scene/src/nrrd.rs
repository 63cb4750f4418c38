//! NRRD volumes: a text header and raw samples, placed in space with `space origin` (the
//! centre of the first sample) and `space directions` (one sample step per axis), so ParaView
//! and 3D Slicer show the volume exactly on the scene.
//!
//! Two halves:
//!
//! * [`header`], [`write()`], [`read`]: our own `uint8` voxelizer output (format version 4).
//! * [`parse_nrrd`], [`read_nrrd`], [`write_nrrd`]: general 3D scalar volumes ([`Nrrd`]), for
//!   dataset primitives; the reader follows the NRRD format spec
//!   (<https://teem.sourceforge.net/nrrd/format.html>, magics `NRRD0001` to `NRRD0005`)
//!   for one attached or detached data file, raw or gzip encoded.

use std::collections::BTreeMap;
use std::fmt::Display;
use std::io::{BufRead, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

use glam::{DMat3, DVec3};

use crate::grid::Grid;
use crate::{Error, Result};
use csgpix_output::write_atomic;

/// The `space` of a volume that no dataset placed in an anatomical frame: scene axes,
/// right-handed, in scene units.
pub const NEUTRAL_SPACE: &str = "3D-right-handed";

/// How a voxelizer volume is written: its `space` and its data's `encoding`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VolumeFormat {
    /// The `space:` field ([`NEUTRAL_SPACE`], or a dataset's own).
    pub space: String,
    /// Raw bytes, or one gzip member.
    pub encoding: Encoding,
}

impl Default for VolumeFormat {
    fn default() -> VolumeFormat {
        VolumeFormat {
            space: NEUTRAL_SPACE.into(),
            encoding: Encoding::Raw,
        }
    }
}

/// The header for `grid`, raw, in the neutral space ([`header_as`]).
pub fn header(grid: &Grid, comment: &str) -> String {
    header_as(grid, comment, &VolumeFormat::default())
}

/// The header for `grid` as `format` says: axis 0 is X (fastest), 1 is Y, 2 is Z, in scene
/// units.
pub fn header_as(grid: &Grid, comment: &str, format: &VolumeFormat) -> String {
    let [nx, ny, nz] = grid.dims;
    let v = grid.voxel();
    let o = grid.centre(0, 0, 0);
    let mut h = String::from("NRRD0004\n");
    for line in comment.lines() {
        h += &format!("# {line}\n");
    }
    h += "type: uint8\n";
    h += "dimension: 3\n";
    h += &format!("space: {}\n", format.space);
    h += &format!("sizes: {nx} {ny} {nz}\n");
    h += &format!(
        "space directions: ({},0,0) (0,{},0) (0,0,{})\n",
        v.x, v.y, v.z
    );
    h += "kinds: domain domain domain\n";
    h += match format.encoding {
        Encoding::Raw => "encoding: raw\n",
        Encoding::Gzip => "encoding: gzip\n",
    };
    h += &format!("space origin: ({},{},{})\n", o.x, o.y, o.z);
    h += "\n";
    h
}

/// Write the volume (X fastest, then Y, then Z) whole or not at all.
pub fn write(path: &Path, grid: &Grid, voxels: &[u8], comment: &str) -> Result<()> {
    Ok(write_atomic(path, |w| {
        write_volume(w, grid, voxels, comment)
    })?)
}

/// The NRRD file of the volume (X fastest, then Y, then Z), into `w`: raw, neutral space.
pub fn write_volume(
    w: &mut dyn Write,
    grid: &Grid,
    voxels: &[u8],
    comment: &str,
) -> std::io::Result<()> {
    write_volume_as(w, grid, voxels, comment, &VolumeFormat::default())
}

/// The NRRD file of the volume as `format` says, into `w`.
pub fn write_volume_as(
    w: &mut dyn Write,
    grid: &Grid,
    voxels: &[u8],
    comment: &str,
    format: &VolumeFormat,
) -> std::io::Result<()> {
    w.write_all(header_as(grid, comment, format).as_bytes())?;
    let mut data = data_writer(w, format.encoding);
    data.write_all(voxels)?;
    data.finish()
}

/// Where a volume's data bytes go after its header: `w` itself, or a gzip member into it.
pub fn data_writer(w: &mut dyn Write, encoding: Encoding) -> DataWriter<'_> {
    match encoding {
        Encoding::Raw => DataWriter::Raw(w),
        // Level 6, zlib's default: most of the gain of 9 at a fraction of its time.
        Encoding::Gzip => DataWriter::Gzip(flate2::write::GzEncoder::new(
            w,
            flate2::Compression::default(),
        )),
    }
}

/// A volume's data stream ([`data_writer`]); [`DataWriter::finish`] ends the gzip member.
pub enum DataWriter<'a> {
    /// Raw bytes.
    Raw(&'a mut dyn Write),
    /// One gzip member.
    Gzip(flate2::write::GzEncoder<&'a mut dyn Write>),
}

impl Write for DataWriter<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        match self {
            DataWriter::Raw(w) => w.write(buf),
            DataWriter::Gzip(g) => g.write(buf),
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        match self {
            DataWriter::Raw(w) => w.flush(),
            DataWriter::Gzip(g) => g.flush(),
        }
    }
}

impl DataWriter<'_> {
    /// Write what remains (the gzip trailer).
    pub fn finish(self) -> std::io::Result<()> {
        match self {
            DataWriter::Raw(_) => Ok(()),
            DataWriter::Gzip(g) => g.finish().map(drop),
        }
    }
}

/// Read back a volume this module wrote: the sizes and the voxels (for tests and tools).
pub fn read(bytes: &[u8]) -> Result<([usize; 3], Vec<u8>)> {
    let split = bytes
        .windows(2)
        .position(|w| w == b"\n\n")
        .ok_or(Error::NoNrrdHeaderEnd)?;
    let head = std::str::from_utf8(&bytes[..split]).map_err(|reason| Error::Utf8 { reason })?;
    if !head.starts_with("NRRD000") {
        return Err(Error::NotNrrd);
    }
    let sizes = head
        .lines()
        .find_map(|l| l.strip_prefix("sizes: "))
        .ok_or(Error::MissingField { field: "sizes" })?;
    let dims: Vec<usize> = sizes
        .split_whitespace()
        .map(|s| {
            s.parse()
                .map_err(|reason| Error::BadInteger { reason }.context("sizes"))
        })
        .collect::<Result<_>>()?;
    let [nx, ny, nz] = dims[..] else {
        let e = Error::Expected {
            expected: "3".into(),
            found: dims.len().to_string(),
        };
        return Err(e.context("sizes"));
    };
    let data = bytes[split + 2..].to_vec();
    if data.len() != nx * ny * nz {
        return Err(Error::DataLength {
            bytes: data.len(),
            sizes: [nx, ny, nz],
        });
    }
    Ok(([nx, ny, nz], data))
}

// ---------------------------------------------------------------------------------------------
// General 3D scalar volumes (NRRD format spec, <https://teem.sourceforge.net/nrrd/format.html>).

/// The most samples [`parse_nrrd`] accepts (1024³; 4 GiB once held as `f32`). Larger `sizes`
/// are refused before anything is allocated; [`parse_nrrd_limited`] takes a lower limit.
pub const MAX_SAMPLES: usize = 1 << 30;

/// Bytes a sample may cost a reader and its caller: the data as stored (at most 8), the
/// `f32` sample (4), and as much again for a dataset built from it.
pub const BYTES_PER_SAMPLE: u64 = 16;

/// The most samples a reader takes of one volume, and what sets that limit (named in the
/// refusal): given by the caller, from its memory limit, so that a gzip member that would
/// inflate past it is refused by its header's `sizes`, before a byte is decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SampleLimit {
    /// Samples at most.
    pub samples: usize,
    /// What set it (e.g. `--max-memory`); empty for [`SampleLimit::NONE`].
    pub source: &'static str,
}

impl SampleLimit {
    /// No limit but [`MAX_SAMPLES`].
    pub const NONE: SampleLimit = SampleLimit {
        samples: MAX_SAMPLES,
        source: "",
    };

    /// The samples `bytes` of memory hold ([`BYTES_PER_SAMPLE`] each), at most
    /// [`MAX_SAMPLES`]; `source` names the limit.
    pub fn of_memory(bytes: u64, source: &'static str) -> SampleLimit {
        let samples = (bytes / BYTES_PER_SAMPLE).min(MAX_SAMPLES as u64) as usize;
        SampleLimit { samples, source }
    }
}

impl Default for SampleLimit {
    fn default() -> SampleLimit {
        SampleLimit::NONE
    }
}

/// A 3D scalar volume: samples on the lattice `origin + directions · (i, j, k)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Nrrd {
    /// Samples along index axes 0 (X, fastest), 1 and 2.
    pub sizes: [usize; 3],
    /// Every sample as `f32`, axis 0 fastest: sample (i, j, k) is at `i + nx·(j + ny·k)`.
    pub samples: Vec<f32>,
    /// Scene position of sample (0, 0, 0) (`space origin`).
    pub origin: DVec3,
    /// Column i is the scene step for index axis i (`space directions`, or `spacings`).
    pub directions: DMat3,
    /// The type the samples were stored as (and are written back as).
    pub sample_type: SampleType,
    /// The least and the greatest sample.
    pub range: (f32, f32),
    /// The `space` the file declared (e.g. `right-anterior-superior`), if any other than
    /// [`NEUTRAL_SPACE`] (None, which is written as that): coordinates are scene units
    /// whatever it is; a voxelization of the dataset keeps it.
    pub space: Option<String>,
}

impl Nrrd {
    /// A volume from its parts; the samples must fill `sizes` exactly and be finite.
    pub fn new(
        sizes: [usize; 3],
        samples: Vec<f32>,
        origin: DVec3,
        directions: DMat3,
        sample_type: SampleType,
    ) -> Result<Nrrd> {
        let count = sizes.iter().try_fold(1usize, |a, &n| a.checked_mul(n));
        if count != Some(samples.len()) || samples.is_empty() {
            return Err(Error::SampleCount {
                samples: samples.len(),
                sizes,
            });
        }
        if let Some(i) = samples.iter().position(|v| !v.is_finite()) {
            return Err(Error::NonFiniteSample {
                index: i,
                value: samples[i],
            });
        }
        let range = samples
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            });
        Ok(Nrrd {
            sizes,
            samples,
            origin,
            directions,
            sample_type,
            range,
            space: None,
        })
    }

    /// Sample (i, j, k); panics outside `sizes`.
    pub fn at(&self, i: usize, j: usize, k: usize) -> f32 {
        self.samples[i + self.sizes[0] * (j + self.sizes[1] * k)]
    }
}

/// The scalar types of the NRRD format spec (§5 `type`), all but 64-bit integers and `block`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SampleType {
    /// `int8`.
    Int8,
    /// `uint8`.
    Uint8,
    /// `int16`.
    Int16,
    /// `uint16`.
    Uint16,
    /// `int32`.
    Int32,
    /// `uint32`.
    Uint32,
    /// `float` (32-bit).
    Float,
    /// `double` (64-bit).
    Double,
}

impl SampleType {
    /// Every supported type.
    pub const ALL: [SampleType; 8] = [
        SampleType::Int8,
        SampleType::Uint8,
        SampleType::Int16,
        SampleType::Uint16,
        SampleType::Int32,
        SampleType::Uint32,
        SampleType::Float,
        SampleType::Double,
    ];

    /// The type named by a `type:` value, in any of the spec's spellings ("unsigned short",
    /// "ushort", "uint16", "uint16_t", ...), case and repeated spaces aside.
    pub fn parse(name: &str) -> Option<SampleType> {
        use SampleType::*;
        let name = name.split_whitespace().collect::<Vec<_>>().join(" ");
        let t = match name.to_ascii_lowercase().as_str() {
            "signed char" | "int8" | "int8_t" => Int8,
            "uchar" | "unsigned char" | "uint8" | "uint8_t" => Uint8,
            "short" | "short int" | "signed short" | "signed short int" | "int16" | "int16_t" => {
                Int16
            }
            "ushort" | "unsigned short" | "unsigned short int" | "uint16" | "uint16_t" => Uint16,
            "int" | "signed int" | "int32" | "int32_t" => Int32,
            "uint" | "unsigned int" | "uint32" | "uint32_t" => Uint32,
            "float" => Float,
            "double" => Double,
            _ => return None,
        };
        Some(t)
    }

    /// The spec's canonical name, as written in headers.
    pub fn name(self) -> &'static str {
        use SampleType::*;
        match self {
            Int8 => "int8",
            Uint8 => "uint8",
            Int16 => "int16",
            Uint16 => "uint16",
            Int32 => "int32",
            Uint32 => "uint32",
            Float => "float",
            Double => "double",
        }
    }

    /// Bytes per sample.
    pub fn size(self) -> usize {
        use SampleType::*;
        match self {
            Int8 | Uint8 => 1,
            Int16 | Uint16 => 2,
            Int32 | Uint32 | Float => 4,
            Double => 8,
        }
    }

    /// The sample stored in `b` (exactly [`SampleType::size`] bytes).
    fn decode(self, b: &[u8], big: bool) -> f64 {
        use SampleType::*;
        match self {
            Int8 => f64::from(b[0] as i8),
            Uint8 => f64::from(b[0]),
            Int16 => f64::from(i16::from_le_bytes(ordered(b, big))),
            Uint16 => f64::from(u16::from_le_bytes(ordered(b, big))),
            Int32 => f64::from(i32::from_le_bytes(ordered(b, big))),
            Uint32 => f64::from(u32::from_le_bytes(ordered(b, big))),
            Float => f64::from(f32::from_le_bytes(ordered(b, big))),
            Double => f64::from_le_bytes(ordered(b, big)),
        }
    }

    /// Append `v` in this type: integers rounded to nearest and clamped to the type's range.
    fn encode(self, v: f32, big: bool, out: &mut Vec<u8>) {
        use SampleType::*;
        let v = f64::from(v);
        let int = |lo: f64, hi: f64| v.round().clamp(lo, hi);
        match self {
            Int8 => put(out, (int(-128.0, 127.0) as i8).to_le_bytes(), big),
            Uint8 => put(out, (int(0.0, 255.0) as u8).to_le_bytes(), big),
            Int16 => put(out, (int(-32768.0, 32767.0) as i16).to_le_bytes(), big),
            Uint16 => put(out, (int(0.0, 65535.0) as u16).to_le_bytes(), big),
            Int32 => put(
                out,
                (int(-2147483648.0, 2147483647.0) as i32).to_le_bytes(),
                big,
            ),
            Uint32 => put(out, (int(0.0, 4294967295.0) as u32).to_le_bytes(), big),
            Float => put(out, (v as f32).to_le_bytes(), big),
            Double => put(out, v.to_le_bytes(), big),
        }
    }
}

/// `b` as a little-endian array of N bytes.
fn ordered<const N: usize>(b: &[u8], big: bool) -> [u8; N] {
    let mut a = [0u8; N];
    a.copy_from_slice(&b[..N]);
    if big {
        a.reverse();
    }
    a
}

/// Append little-endian bytes `le` in the byte order asked for.
fn put<const N: usize>(out: &mut Vec<u8>, mut le: [u8; N], big: bool) {
    if big {
        le.reverse();
    }
    out.extend_from_slice(&le);
}

/// How the data bytes are stored (`encoding:`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// The bytes as they are.
    Raw,
    /// One gzip member holding the bytes.
    Gzip,
}

/// Byte order of multi-byte samples (`endian:`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Endian {
    /// Least significant byte first.
    Little,
    /// Most significant byte first.
    Big,
}

/// Whether the axis steps span 3D: every column finite and non-zero, and the determinant not
/// negligible against the product of the column lengths.
pub(crate) fn invertible(d: &DMat3) -> bool {
    let lengths = [d.x_axis.length(), d.y_axis.length(), d.z_axis.length()];
    let scale: f64 = lengths.iter().product();
    d.is_finite() && scale > 0.0 && scale.is_finite() && d.determinant().abs() > 1e-12 * scale
}

// --- Reading -----------------------------------------------------------------------------------

/// Read a NRRD file of at most [`MAX_SAMPLES`] samples ([`read_nrrd_limited`]).
pub fn read_nrrd(path: &Path) -> Result<Nrrd> {
    read_nrrd_limited(path, SampleLimit::NONE)
}

/// Read a NRRD file of at most `limit` samples; a detached `data file:` is found relative to
/// the file's directory.
pub fn read_nrrd_limited(path: &Path, limit: SampleLimit) -> Result<Nrrd> {
    let name = path.display().to_string();
    let len = std::fs::metadata(path)
        .map_err(|e| Error::io(&name, &e))?
        .len();
    let cap = MAX_SAMPLES as u64 * 8 + (1 << 20);
    if len > cap {
        let e = Error::VolumeFileTooLarge {
            len,
            limit: MAX_SAMPLES,
        };
        return Err(e.context(&name));
    }
    let bytes = std::fs::read(path).map_err(|e| Error::io(&name, &e))?;
    parse_nrrd_limited(&bytes, &name, path.parent(), limit)
}

/// Parse a NRRD file's bytes (NRRD format spec, magics `NRRD0001` to `NRRD0005`), of at most
/// [`MAX_SAMPLES`] samples. `file` names the file in errors; `dir` is where a detached
/// `data file:` is looked for (the current directory when `None`).
///
/// Every error is one line, `FILE:LINE:COL: what was expected`, at the offending header field
/// or value; problems with the samples themselves read `FILE: data: ...`.
pub fn parse_nrrd(bytes: &[u8], file: &str, dir: Option<&Path>) -> Result<Nrrd> {
    parse_nrrd_limited(bytes, file, dir, SampleLimit::NONE)
}

/// [`parse_nrrd`] with another limit on the number of samples.
pub fn parse_nrrd_limited(
    bytes: &[u8],
    file: &str,
    dir: Option<&Path>,
    limit: SampleLimit,
) -> Result<Nrrd> {
    let h = split_header(bytes, file)?;
    let plan = plan(&h, limit)?;
    let (origin, directions) = geometry(&h)?;
    let raw = fetch(&h, &plan, bytes, dir)?;
    let samples = raw
        .chunks_exact(plan.ty.size())
        .map(|b| plan.ty.decode(b, plan.big) as f32)
        .collect();
    let mut nrrd = Nrrd::new(plan.sizes, samples, origin, directions, plan.ty)
        .map_err(|e| e.context("data").context(file))?;
    // The neutral frame is no frame of the dataset's own (None writes it back).
    nrrd.space = h
        .get("space")
        .map(|f| f.value.trim().to_string())
        .filter(|s| s != NEUTRAL_SPACE);
    Ok(nrrd)
}

/// `FILE:LINE:COL: message`.
fn at(file: &str, line: usize, col: usize, problem: Error) -> Error {
    Error::at(file, line, col, problem)
}

/// `expected what, found `found``.
fn expected(what: &str, found: impl Display) -> Error {
    Error::Expected {
        expected: what.into(),
        found: format!("`{found}`"),
    }
}

/// `expected what`.
fn expected_here(what: impl Into<String>) -> Error {
    Error::ExpectedHere {
        expected: what.into(),
    }
}

/// One `field: value` line: where its value starts (1-based) and the value.
#[derive(Clone, Copy, Debug)]
struct Field<'a> {
    line: usize,
    col: usize,
    value: &'a str,
}

/// The header's fields by canonical name.
struct Header<'a> {
    file: &'a str,
    fields: BTreeMap<&'static str, Field<'a>>,
    /// The line that ends the header: the blank line, or one past the last line.
    end: usize,
    /// Where attached data starts: just after the blank line.
    data: Option<usize>,
}

impl<'a> Header<'a> {
    fn get(&self, name: &str) -> Option<Field<'a>> {
        self.fields.get(name).copied()
    }

    fn need(&self, name: &str) -> Result<Field<'a>> {
        self.get(name).ok_or_else(|| {
            let msg = expected_here(format!("a `{name}:` field before the end of the header"));
            at(self.file, self.end, 1, msg)
        })
    }

    /// An error `offset` bytes into field `f`'s value.
    fn err(&self, f: Field, offset: usize, msg: Error) -> Error {
        at(self.file, f.line, f.col + offset, msg)
    }

    /// Record line `line`, `text`: a field, a `key:=value` pair (ignored) or a comment.
    fn add(&mut self, line: usize, text: &'a str) -> Result<()> {
        if text.starts_with('#') {
            return Ok(());
        }
        let sep = match (text.find(": "), text.find(":=")) {
            (Some(f), None) => f,
            (Some(f), Some(k)) if f < k => f,
            (_, Some(_)) => return Ok(()),
            (None, None) => {
                let msg = expected_here("`field: value`, `key:=value` or `# comment`");
                return Err(at(self.file, line, 1, msg));
            }
        };
        let name = &text[..sep];
        let Some(canon) = canonical(name) else {
            let name = name.to_string();
            return Err(at(self.file, line, 1, Error::UnknownField { name }));
        };
        let value = text[sep + 2..].trim_end();
        let f = Field {
            line,
            col: sep + 3,
            value,
        };
        match self.fields.insert(canon, f) {
            Some(old) => {
                let msg = Error::DuplicateField {
                    name: name.to_string(),
                    first_line: old.line,
                };
                Err(at(self.file, line, 1, msg))
            }
            None => Ok(()),
        }
    }
}

/// The spec's field names (and their old spellings), by canonical name.
fn canonical(name: &str) -> Option<&'static str> {
    const FIELDS: [(&str, &str); 41] = [
        ("dimension", "dimension"),
        ("type", "type"),
        ("block size", "block size"),
        ("blocksize", "block size"),
        ("encoding", "encoding"),
        ("endian", "endian"),
        ("content", "content"),
        ("min", "min"),
        ("max", "max"),
        ("old min", "old min"),
        ("oldmin", "old min"),
        ("old max", "old max"),
        ("oldmax", "old max"),
        ("data file", "data file"),
        ("datafile", "data file"),
        ("line skip", "line skip"),
        ("lineskip", "line skip"),
        ("byte skip", "byte skip"),
        ("byteskip", "byte skip"),
        ("number", "number"),
        ("sample units", "sample units"),
        ("sampleunits", "sample units"),
        ("sizes", "sizes"),
        ("spacings", "spacings"),
        ("thicknesses", "thicknesses"),
        ("axis mins", "axis mins"),
        ("axismins", "axis mins"),
        ("axis maxs", "axis maxs"),
        ("axismaxs", "axis maxs"),
        ("centers", "centerings"),
        ("centerings", "centerings"),
        ("labels", "labels"),
        ("units", "units"),
        ("kinds", "kinds"),
        ("space", "space"),
        ("space dimension", "space dimension"),
        ("space units", "space units"),
        ("space origin", "space origin"),
        ("space directions", "space directions"),
        ("measurement frame", "measurement frame"),
        ("thickness", "thicknesses"),
    ];
    FIELDS.iter().find(|(n, _)| *n == name).map(|&(_, c)| c)
}

/// The header's lines up to the blank line (or the end of the bytes).
fn split_header<'a>(bytes: &'a [u8], file: &'a str) -> Result<Header<'a>> {
    let mut h = Header {
        file,
        fields: BTreeMap::new(),
        end: 1,
        data: None,
    };
    let (mut pos, mut line) = (0, 0);
    while pos < bytes.len() {
        line += 1;
        let end = bytes[pos..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |e| pos + e);
        let raw = &bytes[pos..end];
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        pos = end + 1;
        let text = std::str::from_utf8(raw).map_err(|e| {
            let msg = expected_here("header text (is the blank line ending the header missing?)");
            at(file, line, e.valid_up_to() + 1, msg)
        })?;
        if line == 1 {
            check_magic(text, file)?;
        } else if text.is_empty() {
            h.end = line;
            h.data = Some(pos.min(bytes.len()));
            return Ok(h);
        } else {
            h.add(line, text)?;
        }
    }
    if line == 0 {
        check_magic("", file)?;
    }
    h.end = line + 1;
    Ok(h)
}

fn check_magic(text: &str, file: &str) -> Result<()> {
    match text.strip_prefix("NRRD000") {
        Some("1" | "2" | "3" | "4" | "5") => Ok(()),
        _ => Err(at(
            file,
            1,
            1,
            expected_here("the magic `NRRD0001` to `NRRD0005`"),
        )),
    }
}

/// Whitespace-separated words of a value, each with its byte offset.
fn words(s: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in s.char_indices() {
        match (c.is_whitespace(), start) {
            (true, Some(s0)) => {
                out.push((s0, &s[s0..i]));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    if let Some(s0) = start {
        out.push((s0, &s[s0..]));
    }
    out
}

/// What the header asks for, checked before any data is touched.
struct Plan {
    ty: SampleType,
    sizes: [usize; 3],
    /// Data bytes needed: samples × sample size.
    bytes: usize,
    encoding: Encoding,
    big: bool,
    line_skip: usize,
    /// Bytes to skip (after decompression for gzip); `None` for `byte skip: -1`.
    byte_skip: Option<u64>,
}

fn plan(h: &Header, limit: SampleLimit) -> Result<Plan> {
    dimension(h)?;
    let ty = sample_type(h)?;
    let sizes = sizes(h)?;
    let bytes = data_bytes(h, sizes, ty, limit)?;
    let encoding = encoding(h)?;
    let big = big_endian(h, ty)?;
    let (line_skip, byte_skip) = skips(h, encoding)?;
    Ok(Plan {
        ty,
        sizes,
        bytes,
        encoding,
        big,
        line_skip,
        byte_skip,
    })
}

fn dimension(h: &Header) -> Result<()> {
    let f = h.need("dimension")?;
    match f.value.trim() {
        "3" => Ok(()),
        v => Err(h.err(f, 0, expected("dimension 3 (a volume)", v))),
    }
}

fn sample_type(h: &Header) -> Result<SampleType> {
    let f = h.need("type")?;
    SampleType::parse(f.value).ok_or_else(|| {
        let msg = expected(
            "a sample type (int8, uint8, int16, uint16, int32, uint32, float, double, or a C \
             spelling like `unsigned short`)",
            f.value,
        );
        h.err(f, 0, msg)
    })
}

fn sizes(h: &Header) -> Result<[usize; 3]> {
    let f = h.need("sizes")?;
    let w = words(f.value);
    if w.len() != 3 {
        let msg = Error::Expected {
            expected: "3 sizes".into(),
            found: w.len().to_string(),
        };
        return Err(h.err(f, 0, msg));
    }
    let mut sizes = [0; 3];
    for (s, &(off, word)) in sizes.iter_mut().zip(&w) {
        *s = match word.parse::<usize>() {
            Ok(n) if n >= 1 => n,
            _ => return Err(h.err(f, off, expected("a size ≥ 1", word))),
        };
    }
    Ok(sizes)
}

/// The data bytes `sizes` need, refused past `limit`.
fn data_bytes(h: &Header, sizes: [usize; 3], ty: SampleType, limit: SampleLimit) -> Result<usize> {
    let max = limit.samples;
    let count = sizes.iter().try_fold(1usize, |a, &n| a.checked_mul(n));
    let bytes = count.and_then(|c| c.checked_mul(ty.size()));
    match (count, bytes) {
        (Some(c), Some(b)) if c <= max => Ok(b),
        _ => {
            let set_by = match max < MAX_SAMPLES && !limit.source.is_empty() {
                true => Some(limit.source),
                false => None,
            };
            let msg = Error::TooManySamples {
                sizes,
                limit: max,
                set_by,
            };
            Err(h.err(h.need("sizes")?, 0, msg))
        }
    }
}

fn encoding(h: &Header) -> Result<Encoding> {
    let f = h.need("encoding")?;
    match f.value.trim().to_ascii_lowercase().as_str() {
        "raw" => Ok(Encoding::Raw),
        "gzip" | "gz" => Ok(Encoding::Gzip),
        v @ ("ascii" | "text" | "txt" | "hex" | "bzip2" | "bz2") => {
            let msg = Error::UnsupportedEncoding {
                encoding: v.to_string(),
            };
            Err(h.err(f, 0, msg))
        }
        v => Err(h.err(f, 0, expected("encoding raw or gzip", v))),
    }
}

/// Whether samples are big-endian; the spec requires `endian:` for multi-byte types.
fn big_endian(h: &Header, ty: SampleType) -> Result<bool> {
    match (h.get("endian"), ty.size()) {
        (None, 1) => Ok(false),
        (None, n) => {
            let msg = Error::NeedsEndian {
                bytes: n,
                ty: ty.name(),
            };
            Err(h.err(h.need("type")?, 0, msg))
        }
        (Some(f), _) => match f.value.trim() {
            "little" => Ok(false),
            "big" => Ok(true),
            v => Err(h.err(f, 0, expected("`little` or `big`", v))),
        },
    }
}

/// `line skip` and `byte skip` (-1: the data are the file's last bytes, raw encoding only).
fn skips(h: &Header, encoding: Encoding) -> Result<(usize, Option<u64>)> {
    let lines = match h.get("line skip") {
        None => 0,
        Some(f) => f
            .value
            .trim()
            .parse::<usize>()
            .map_err(|_| h.err(f, 0, expected("a line count ≥ 0", f.value)))?,
    };
    let bytes = match h.get("byte skip") {
        None => Some(0),
        Some(f) => match (f.value.trim().parse::<i64>(), encoding) {
            (Ok(-1), Encoding::Raw) => None,
            (Ok(-1), Encoding::Gzip) => {
                let msg = expected_here("a byte count ≥ 0 (-1 is for raw data only)");
                return Err(h.err(f, 0, msg));
            }
            (Ok(n), _) if n >= 0 => Some(n as u64),
            _ => {
                let msg = expected("a byte count ≥ 0 or -1", f.value);
                return Err(h.err(f, 0, msg));
            }
        },
    };
    Ok((lines, bytes))
}

// --- Geometry ----------------------------------------------------------------------------------

/// `space origin` (default 0) and the axis steps: `space directions`, else `spacings`
/// (diagonal), else unit steps. Coordinates are taken as scene units whatever the `space`.
fn geometry(h: &Header) -> Result<(DVec3, DMat3)> {
    check_space(h)?;
    let origin = match h.get("space origin") {
        Some(f) => origin(h, f)?,
        None => DVec3::ZERO,
    };
    let (dirs, field) = match (h.get("space directions"), h.get("spacings")) {
        (Some(_), Some(s)) => {
            let msg = expected_here("`spacings` or `space directions`, not both");
            return Err(h.err(s, 0, msg));
        }
        (Some(f), None) => (directions(h, f)?, f),
        (None, Some(f)) => (spacings(h, f)?, f),
        (None, None) => return Ok((origin, DMat3::IDENTITY)),
    };
    if !invertible(&dirs) {
        let msg = expected_here("3 independent axis steps (these are singular)");
        return Err(h.err(field, 0, msg));
    }
    Ok((origin, dirs))
}

/// The space must be 3D: `space dimension: 3`, and no `space` with a time axis.
fn check_space(h: &Header) -> Result<()> {
    if let Some(f) = h.get("space dimension") {
        if f.value.trim() != "3" {
            let msg = expected("space dimension 3", f.value);
            return Err(h.err(f, 0, msg));
        }
    }
    if let Some(f) = h.get("space") {
        let s = f.value.trim().to_ascii_lowercase();
        if s.ends_with("-time") || matches!(s.as_str(), "rast" | "last" | "lpst") {
            let msg = Error::Expected {
                expected: "a 3D space".into(),
                found: format!("`{}` (4D)", f.value),
            };
            return Err(h.err(f, 0, msg));
        }
    }
    Ok(())
}

fn origin(h: &Header, f: Field) -> Result<DVec3> {
    match vectors(h, f)?[..] {
        [(_, Some(v))] => Ok(v),
        _ => Err(h.err(f, 0, expected_here("one vector `(x,y,z)`"))),
    }
}

fn directions(h: &Header, f: Field) -> Result<DMat3> {
    let list = vectors(h, f)?;
    if list.len() != 3 {
        let msg = Error::Expected {
            expected: "3 vectors (one per axis)".into(),
            found: list.len().to_string(),
        };
        return Err(h.err(f, 0, msg));
    }
    let mut cols = [DVec3::ZERO; 3];
    for (axis, (c, &(off, v))) in cols.iter_mut().zip(&list).enumerate() {
        *c = v.ok_or_else(|| {
            let msg = expected(&format!("axis {axis} to be spatial"), "none");
            h.err(f, off, msg)
        })?;
    }
    Ok(DMat3::from_cols(cols[0], cols[1], cols[2]))
}

fn spacings(h: &Header, f: Field) -> Result<DMat3> {
    let w = words(f.value);
    if w.len() != 3 {
        let msg = Error::Expected {
            expected: "3 spacings".into(),
            found: w.len().to_string(),
        };
        return Err(h.err(f, 0, msg));
    }
    let mut d = [0.0; 3];
    for (s, &(off, word)) in d.iter_mut().zip(&w) {
        *s = number(word).ok_or_else(|| h.err(f, off, expected("a finite spacing", word)))?;
    }
    Ok(DMat3::from_diagonal(DVec3::from(d)))
}

/// A finite number.
fn number(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The `(x,y,z)` vectors and `none`s of a value, each with its byte offset.
fn vectors(h: &Header, f: Field) -> Result<Vec<(usize, Option<DVec3>)>> {
    let s = f.value;
    let mut out = Vec::new();
    let mut i = 0;
    loop {
        i += s[i..].len() - s[i..].trim_start().len();
        let rest = &s[i..];
        if rest.is_empty() {
            return Ok(out);
        }
        if rest.starts_with("none") {
            out.push((i, None));
            i += 4;
        } else if let (Some(inner), Some(close)) = (rest.strip_prefix('('), rest.find(')')) {
            out.push((i, Some(vector(h, f, i + 1, &inner[..close - 1])?)));
            i += close + 1;
        } else {
            return Err(h.err(f, i, expected_here("`(x,y,z)` or `none`")));
        }
    }
}

/// The three components of `inner`, found `off` bytes into `f`'s value.
fn vector(h: &Header, f: Field, off: usize, inner: &str) -> Result<DVec3> {
    let parts: Vec<&str> = inner.split(',').collect();
    if parts.len() != 3 {
        let msg = Error::Expected {
            expected: "3 components".into(),
            found: parts.len().to_string(),
        };
        return Err(h.err(f, off - 1, msg));
    }
    let mut v = [0.0; 3];
    let mut o = off;
    for (c, part) in v.iter_mut().zip(parts) {
        let lead = part.len() - part.trim_start().len();
        *c = number(part)
            .ok_or_else(|| h.err(f, o + lead, expected("a finite number", part.trim())))?;
        o += part.len() + 1;
    }
    Ok(DVec3::from(v))
}

// --- Data --------------------------------------------------------------------------------------

/// Why the data could not be read.
enum Fault {
    Io(std::io::Error),
    /// Fewer lines than `line skip`.
    Lines,
    /// Fewer bytes than `byte skip`.
    Skip,
    /// This many bytes instead of the needed ones.
    Short(u64),
    /// More bytes than needed.
    Excess,
}

/// The data bytes, exactly as many as the plan needs: from `data file:` or after the header.
fn fetch(h: &Header, plan: &Plan, bytes: &[u8], dir: Option<&Path>) -> Result<Vec<u8>> {
    let got = match h.get("data file") {
        Some(f) => {
            let path = data_path(h, f, dir)?;
            // Looked at before it is opened: opening a FIFO would wait for a writer.
            let open = |p: &Path| match std::fs::metadata(p)?.is_file() {
                true => std::fs::File::open(p),
                false => Err(std::io::Error::other("not a regular file")),
            };
            let file = open(&path).map_err(|e| {
                let what = format_args!("expected a readable data file {}", path.display());
                Error::io(what, &e).located(h.file, f.line, f.col)
            })?;
            read_data(std::io::BufReader::new(file), plan)
        }
        None => {
            let start = h.data.ok_or_else(|| {
                let msg = expected_here("a blank line and then the data, or a `data file:` field");
                at(h.file, h.end, 1, msg)
            })?;
            read_data(std::io::Cursor::new(&bytes[start..]), plan)
        }
    };
    got.map_err(|e| fault(h, plan, e))
}

/// The one data file named; lists and numbered series (`LIST`, `%d`) are not supported.
fn data_path(h: &Header, f: Field, dir: Option<&Path>) -> Result<PathBuf> {
    let v = f.value.trim();
    if v.starts_with("LIST") || (v.contains('%') && words(v).len() >= 4) || v.is_empty() {
        let msg = expected_here("one data file name (lists and numbered series are not supported)");
        return Err(h.err(f, 0, msg));
    }
    let p = Path::new(v);
    Ok(match dir {
        Some(d) if p.is_relative() => d.join(p),
        _ => p.to_path_buf(),
    })
}

/// Skip lines, then bytes (counted after decompression), then read the needed bytes and
/// one more to detect excess; or, for `byte skip: -1`, the stream's last bytes.
fn read_data<R: BufRead + Seek>(mut r: R, plan: &Plan) -> Result<Vec<u8>, Fault> {
    let Some(skip) = plan.byte_skip else {
        return tail(r, plan.bytes);
    };
    skip_lines(&mut r, plan.line_skip)?;
    match plan.encoding {
        Encoding::Raw => exact(r, skip, plan.bytes),
        Encoding::Gzip => exact(flate2::bufread::GzDecoder::new(r), skip, plan.bytes),
    }
}

fn skip_lines<R: BufRead>(r: &mut R, n: usize) -> Result<(), Fault> {
    for _ in 0..n {
        loop {
            let buf = r.fill_buf().map_err(Fault::Io)?;
            if buf.is_empty() {
                return Err(Fault::Lines);
            }
            match buf.iter().position(|&b| b == b'\n') {
                Some(i) => {
                    r.consume(i + 1);
                    break;
                }
                None => {
                    let len = buf.len();
                    r.consume(len);
                }
            }
        }
    }
    Ok(())
}

/// Skip `skip` bytes, then read exactly `n`.
fn exact<R: Read>(mut r: R, skip: u64, n: usize) -> Result<Vec<u8>, Fault> {
    let skipped = std::io::copy(&mut (&mut r).take(skip), &mut std::io::sink());
    if skipped.map_err(Fault::Io)? < skip {
        return Err(Fault::Skip);
    }
    let mut buf = Vec::new();
    r.take(n as u64 + 1)
        .read_to_end(&mut buf)
        .map_err(Fault::Io)?;
    match buf.len().cmp(&n) {
        std::cmp::Ordering::Less => Err(Fault::Short(buf.len() as u64)),
        std::cmp::Ordering::Greater => Err(Fault::Excess),
        std::cmp::Ordering::Equal => Ok(buf),
    }
}

/// The last `n` bytes of the stream.
fn tail<R: Read + Seek>(mut r: R, n: usize) -> Result<Vec<u8>, Fault> {
    let len = r.seek(SeekFrom::End(0)).map_err(Fault::Io)?;
    if len < n as u64 {
        return Err(Fault::Short(len));
    }
    r.seek(SeekFrom::Start(len - n as u64)).map_err(Fault::Io)?;
    exact(r, 0, n)
}

/// The error for `e`, at the header field that asked for what was not there.
fn fault(h: &Header, plan: &Plan, e: Fault) -> Error {
    let field = |name: &str| h.get(name).ok_or_else(|| format!("{}: data", h.file));
    let gz = plan.encoding == Encoding::Gzip;
    let place = match &e {
        Fault::Io(_) if gz => field("encoding"),
        Fault::Io(_) => field("data file"),
        Fault::Lines => field("line skip"),
        Fault::Skip => field("byte skip"),
        Fault::Short(_) | Fault::Excess => field("sizes"),
    };
    let bytes = |found| Error::DataBytes {
        sizes: plan.sizes,
        ty: plan.ty.name(),
        bytes: plan.bytes,
        gzip: gz,
        found,
    };
    let msg = match e {
        Fault::Io(e) => Error::UnreadableData {
            gzip: gz,
            reason: e.to_string(),
        },
        Fault::Lines => expected_here(format!(
            "{} lines to skip; the data ended first",
            plan.line_skip
        )),
        Fault::Skip => expected_here("the bytes to skip; the data ended first"),
        Fault::Short(got) => bytes(Some(got)),
        Fault::Excess => bytes(None),
    };
    match place {
        Ok(f) => h.err(f, 0, msg),
        Err(prefix) => msg.context(prefix),
    }
}

// --- Writing -----------------------------------------------------------------------------------

/// Write `nrrd` as an attached-header NRRD (format version 4) in its own sample type,
/// little-endian, whole or not at all. Gzip output is deterministic (no name, mtime 0).
pub fn write_nrrd(path: &Path, nrrd: &Nrrd, encoding: Encoding, comment: &str) -> Result<()> {
    let bytes = nrrd_bytes(nrrd, encoding, Endian::Little, comment)
        .map_err(|e| e.context(path.display()))?;
    Ok(write_atomic(path, |w| w.write_all(&bytes))?)
}

/// The bytes of an attached-header NRRD file for `nrrd`: the header (`space origin`,
/// `space directions` in shortest round-trip decimals), then the samples in `nrrd.sample_type`
/// (integers rounded and clamped), in `endian` order, raw or in one gzip member.
pub fn nrrd_bytes(
    nrrd: &Nrrd,
    encoding: Encoding,
    endian: Endian,
    comment: &str,
) -> Result<Vec<u8>> {
    let d = nrrd.directions;
    if !nrrd.origin.is_finite() || !d.is_finite() {
        return Err(Error::NonFiniteFrame);
    }
    if Some(nrrd.samples.len()) != nrrd.sizes.iter().try_fold(1usize, |a, &n| a.checked_mul(n)) {
        return Err(Error::WriteSampleCount {
            samples: nrrd.samples.len(),
            sizes: nrrd.sizes,
        });
    }
    let big = endian == Endian::Big;
    let ty = nrrd.sample_type;
    let mut data = Vec::with_capacity(nrrd.samples.len() * ty.size());
    for &v in &nrrd.samples {
        ty.encode(v, big, &mut data);
    }
    let head = general_header(nrrd, encoding, endian, comment);
    match encoding {
        Encoding::Raw => Ok([head.into_bytes(), data].concat()),
        Encoding::Gzip => gzip(head.into_bytes(), &data).map_err(|e| Error::Io(e.into())),
    }
}

/// `out` followed by `data` in one gzip member with a fixed header.
fn gzip(out: Vec<u8>, data: &[u8]) -> std::io::Result<Vec<u8>> {
    let mut z = flate2::GzBuilder::new()
        .mtime(0)
        .operating_system(255)
        .write(out, flate2::Compression::default());
    z.write_all(data)?;
    z.finish()
}

fn general_header(nrrd: &Nrrd, encoding: Encoding, endian: Endian, comment: &str) -> String {
    let [nx, ny, nz] = nrrd.sizes;
    let v = |v: DVec3| format!("({},{},{})", v.x, v.y, v.z);
    let d = nrrd.directions;
    let mut h = String::from("NRRD0004\n");
    for line in comment.lines() {
        h += &format!("# {line}\n");
    }
    h += &format!("type: {}\n", nrrd.sample_type.name());
    h += "dimension: 3\n";
    h += &format!(
        "space: {}\n",
        nrrd.space.as_deref().unwrap_or(NEUTRAL_SPACE)
    );
    h += &format!("sizes: {nx} {ny} {nz}\n");
    let dirs = [v(d.x_axis), v(d.y_axis), v(d.z_axis)].join(" ");
    h += &format!("space directions: {dirs}\n");
    h += "kinds: domain domain domain\n";
    if nrrd.sample_type.size() > 1 {
        let e = if endian == Endian::Big {
            "big"
        } else {
            "little"
        };
        h += &format!("endian: {e}\n");
    }
    h += if encoding == Encoding::Gzip {
        "encoding: gzip\n"
    } else {
        "encoding: raw\n"
    };
    h += &format!("space origin: {}\n\n", v(nrrd.origin));
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn header_places_voxel_centres() {
        let g = Grid::new(
            [2, 3, 4],
            DVec3::new(-1.0, 0.0, 2.0),
            DVec3::new(1.0, 3.0, 6.0),
        )
        .unwrap();
        let h = header(&g, "test");
        assert!(h.contains("sizes: 2 3 4\n"), "{h}");
        assert!(
            h.contains("space directions: (1,0,0) (0,1,0) (0,0,1)\n"),
            "{h}"
        );
        assert!(h.contains("space origin: (-0.5,0.5,2.5)\n"), "{h}");
        assert!(h.starts_with("NRRD0004\n# test\n") && h.ends_with("\n\n"));
    }

    #[test]
    fn round_trip() {
        let g = Grid::new([2, 2, 2], DVec3::ZERO, DVec3::ONE).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("v.nrrd");
        let v: Vec<u8> = (0..8).collect();
        write(&p, &g, &v, "x").unwrap();
        let (dims, data) = read(&std::fs::read(&p).unwrap()).unwrap();
        assert_eq!((dims, data), ([2, 2, 2], v));
    }

    // --- The general reader and writer (NRRD format spec) ---

    use proptest::prelude::*;

    const F: &str = "f.nrrd";

    fn parse(bytes: &[u8]) -> Result<Nrrd> {
        parse_nrrd(bytes, F, None)
    }

    /// The error for `bytes`, checked to be one line.
    fn error(bytes: &[u8]) -> String {
        let e = parse(bytes).unwrap_err().to_string();
        assert!(!e.contains('\n'), "{e}");
        e
    }

    fn file(header: &str, data: &[u8]) -> Vec<u8> {
        [header.as_bytes(), data].concat()
    }

    /// Twelve values each type holds exactly, its extremes among them.
    fn values(ty: SampleType) -> Vec<f32> {
        use SampleType::*;
        let ends: [f32; 2] = match ty {
            Int8 => [-128.0, 127.0],
            Uint8 => [0.0, 255.0],
            Int16 => [-32768.0, 32767.0],
            Uint16 => [0.0, 65535.0],
            Int32 => [-2147483648.0, 2147483520.0],
            Uint32 => [0.0, 4294967040.0],
            Float => [-3.25e20, 1.5e-7],
            Double => [f32::MIN, f32::MAX],
        };
        let frac = if matches!(ty, Float | Double) {
            0.1
        } else {
            0.0
        };
        let mut v: Vec<f32> = (0..10).map(|i| i as f32 * 7.0 + frac).collect();
        v.extend(ends);
        v
    }

    fn volume(ty: SampleType) -> Nrrd {
        let dirs = DMat3::from_cols(
            DVec3::new(0.8, 0.3, -0.2),
            DVec3::new(-0.25, 1.1, 0.4),
            DVec3::new(0.1, -0.3, 0.9),
        );
        let origin = DVec3::new(1.5, -2.0, 0.1);
        Nrrd::new([3, 2, 2], values(ty), origin, dirs, ty).unwrap()
    }

    #[test]
    fn every_type_encoding_and_endian_round_trips() {
        for ty in SampleType::ALL {
            for enc in [Encoding::Raw, Encoding::Gzip] {
                for endian in [Endian::Little, Endian::Big] {
                    let n = volume(ty);
                    let bytes = nrrd_bytes(&n, enc, endian, "round\ntrip").unwrap();
                    let back = parse(&bytes).unwrap_or_else(|e| panic!("{ty:?} {enc:?}: {e}"));
                    assert_eq!(back, n, "{ty:?} {enc:?} {endian:?}");
                }
            }
        }
    }

    #[test]
    fn every_spelling_of_every_type() {
        let spellings = [
            ("signed char|int8|int8_t", SampleType::Int8),
            ("uchar|unsigned char|uint8|uint8_t", SampleType::Uint8),
            (
                "short|short int|signed short|signed short int|int16|int16_t",
                SampleType::Int16,
            ),
            (
                "ushort|unsigned short|unsigned short int|uint16|uint16_t",
                SampleType::Uint16,
            ),
            ("int|signed int|int32|int32_t", SampleType::Int32),
            ("uint|unsigned int|uint32|uint32_t", SampleType::Uint32),
            ("float", SampleType::Float),
            ("double", SampleType::Double),
        ];
        for (names, ty) in spellings {
            for name in names.split('|') {
                assert_eq!(SampleType::parse(name), Some(ty), "{name}");
            }
        }
        assert_eq!(
            SampleType::parse("unsigned   short"),
            Some(SampleType::Uint16)
        );
        assert_eq!(SampleType::parse("UCHAR"), Some(SampleType::Uint8));
        assert_eq!(SampleType::parse("int64"), None);
        assert_eq!(SampleType::parse("block"), None);
    }

    #[test]
    fn write_and_read_a_file_gzip_deterministic() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.nrrd"), dir.path().join("b.nrrd"));
        let n = volume(SampleType::Uint16);
        write_nrrd(&a, &n, Encoding::Gzip, "x").unwrap();
        write_nrrd(&b, &n, Encoding::Gzip, "x").unwrap();
        let bytes = std::fs::read(&a).unwrap();
        assert_eq!(bytes, std::fs::read(&b).unwrap());
        let gz = bytes.windows(2).position(|w| w == b"\n\n").unwrap() + 2;
        assert_eq!(&bytes[gz..gz + 10], &[0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 255]);
        assert_eq!(read_nrrd(&a).unwrap(), n);
        let head = String::from_utf8_lossy(&bytes[..gz]);
        assert!(head.contains("type: uint16\n") && head.contains("endian: little\n"));
    }

    #[test]
    fn spacings_without_directions() {
        let h = "NRRD0001\ntype: unsigned char\ndimension: 3\nsizes: 2 1 2\nspacings: 0.5 2 3\n\
                 encoding: raw\n\n";
        let n = parse(&file(h, &[1, 2, 3, 4])).unwrap();
        assert_eq!(
            n.directions,
            DMat3::from_diagonal(DVec3::new(0.5, 2.0, 3.0))
        );
        assert_eq!(
            (n.origin, n.samples, n.range),
            (DVec3::ZERO, vec![1., 2., 3., 4.], (1., 4.))
        );
        let plain = "NRRD0001\ntype: uchar\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n";
        assert_eq!(
            parse(&file(plain, &[9])).unwrap().directions,
            DMat3::IDENTITY
        );
    }

    #[test]
    fn detached_data_file_with_line_skip() {
        let dir = tempfile::tempdir().unwrap();
        let mut raw = b"P5\n# a PGM-like header\n".to_vec();
        raw.extend([10u8, 20, 30, 40, 50, 60, 70, 80]);
        std::fs::write(dir.path().join("vol.raw"), &raw).unwrap();
        for name in ["vol.raw", "./vol.raw"] {
            let h = format!(
                "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\
                 data file: {name}\nline skip: 2\n"
            );
            let path = dir.path().join("vol.nhdr");
            std::fs::write(&path, &h).unwrap();
            let n = read_nrrd(&path).unwrap();
            assert_eq!(n.samples, [10., 20., 30., 40., 50., 60., 70., 80.]);
        }
        let h = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\
                 data file: nowhere.raw\n";
        let e = parse_nrrd(h.as_bytes(), F, Some(dir.path()))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("f.nrrd:6:12: expected a readable data file"),
            "{e}"
        );
    }

    #[test]
    fn byte_skip_minus_one_takes_the_last_bytes() {
        let h =
            "NRRD0005\ntype: uint8\ndimension: 3\nsizes: 2 1 1\nencoding: raw\nbyte skip: -1\n\n";
        let n = parse(&file(h, b"junk junk\x07\x08")).unwrap();
        assert_eq!(n.samples, [7.0, 8.0]);
        let e = error(&file(h, b"\x07"));
        assert!(
            e.starts_with("f.nrrd:4:8: sizes 2×1×1 of uint8 need 2 data bytes, found only 1"),
            "{e}"
        );
    }

    #[test]
    fn line_skip_and_byte_skip_attached_and_gzip() {
        let h = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 2\nencoding: raw\nline skip: 2\n\
                 byte skip: 3\n\n";
        let n = parse(&file(h, b"one\ntwo\nxyz\x05\x06")).unwrap();
        assert_eq!(n.samples, [5.0, 6.0]);
        let z = gzip(Vec::new(), b"abc\x05\x06").unwrap();
        let h = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 2\nencoding: gz\nbyte skip: 3\n\n";
        assert_eq!(parse(&file(h, &z)).unwrap().samples, [5.0, 6.0]);
    }

    #[test]
    fn big_endian_int16_by_hand() {
        let h = "NRRD0004\n# hand made\ntype: signed short\ndimension: 3\nsizes: 2 1 1\n\
                 endian: big\nencoding: raw\nkinds: domain domain domain\ncenterings: cell cell cell\n\
                 space: left-posterior-superior\nspace origin: ( 1, 2.5 ,-3 )\n\
                 space directions: (0,2,0) (1,0,0) (0,0,-1.5)\nmodality:=CT\n\n";
        let n = parse(&file(h, &[0x01, 0x02, 0xff, 0xfe])).unwrap();
        assert_eq!(n.samples, [258.0, -2.0]);
        assert_eq!(n.sample_type, SampleType::Int16);
        assert_eq!(n.origin, DVec3::new(1.0, 2.5, -3.0));
        assert_eq!(n.directions.x_axis, DVec3::new(0.0, 2.0, 0.0));
        assert_eq!(n.directions.z_axis, DVec3::new(0.0, 0.0, -1.5));
        let crlf = h.replace('\n', "\r\n");
        assert_eq!(parse(&file(&crlf, &[0x01, 0x02, 0xff, 0xfe])).unwrap(), n);
    }

    /// `header` with data `data` fails with an error starting `f.nrrd:LINE:COL: `, saying `what`.
    fn fails(header: &str, data: &[u8], place: &str, what: &str) {
        let e = error(&file(header, data));
        assert!(e.starts_with(&format!("{F}:{place}: ")), "{place}: {e}");
        assert!(e.contains(what), "{what}: {e}");
    }

    const U8: &str = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n";

    #[test]
    fn header_errors_point_at_the_field() {
        fails(
            "NRRD0004\ntype: uint8\ndimension: 3\nencoding: raw\n\n",
            &[0],
            "5:1",
            "`sizes:`",
        );
        fails(
            "NRRD0004\ntype: complex\ndimension: 3\n",
            &[],
            "2:7",
            "expected a sample type",
        );
        fails(
            "NRRD0004\ntype: int64\ndimension: 3\n\n",
            &[],
            "2:7",
            "found `int64`",
        );
        fails("NRRD0009\n", &[], "1:1", "magic");
        fails("", &[], "1:1", "magic");
        fails(
            "NRRD0004\nsize: 2 2 2\n",
            &[],
            "2:1",
            "unknown field `size`",
        );
        fails(
            "NRRD0004\ntype: uint8\ntype: uint8\n",
            &[],
            "3:1",
            "first on line 2",
        );
        fails(
            "NRRD0004\njust words\n",
            &[],
            "2:1",
            "expected `field: value`",
        );
        fails(
            "NRRD0004\ntype: uint8\ndimension: 2\n\n",
            &[],
            "3:12",
            "dimension 3",
        );
        fails(
            "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 0 2\n\n",
            &[],
            "4:10",
            "size ≥ 1",
        );
        fails(
            "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2\n\n",
            &[],
            "4:8",
            "3 sizes",
        );
    }

    #[test]
    fn encoding_data_and_space_errors_point_at_the_field() {
        let h = "NRRD0004\ntype: float\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n";
        fails(h, &[0; 4], "2:7", "needs an `endian:` field");
        fails(&format!("{U8}encoding: raw\n"), &[], "6:1", "given twice");
        let h = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: bzip2\n\n";
        fails(h, &[], "5:11", "not supported");
        fails(&format!("{U8}byte skip: -2\n\n"), &[], "6:12", "byte count");
        let h =
            "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\nbyte skip: -1\n\n";
        fails(h, &[], "6:12", "raw data only");
        fails(
            &format!("{U8}space dimension: 4\n\n"),
            &[0; 8],
            "6:18",
            "space dimension 3",
        );
        fails(&format!("{U8}space: RAST\n\n"), &[0; 8], "6:8", "3D space");
        fails(
            &format!("{U8}data file: LIST\n\n"),
            &[0; 8],
            "6:12",
            "one data file",
        );
        fails(U8, &[], "6:1", "blank line");
    }

    #[test]
    fn geometry_errors_point_at_the_value() {
        let dirs = |d: &str| format!("{U8}space: RAS\nspace directions: {d}\n\n");
        fails(
            &dirs("(1,0,0) none (0,0,1)"),
            &[0; 8],
            "7:27",
            "axis 1 to be spatial",
        );
        fails(
            &dirs("(1,0,0) (0,1,0)"),
            &[0; 8],
            "7:19",
            "expected 3 vectors",
        );
        fails(
            &dirs("(1,0,0) (0,1) (0,0,1)"),
            &[0; 8],
            "7:27",
            "3 components",
        );
        fails(
            &dirs("(1,0,0) (0,x,0) (0,0,1)"),
            &[0; 8],
            "7:30",
            "finite number, found `x`",
        );
        fails(
            &dirs("(1,0,0) (0,nan,0) (0,0,1)"),
            &[0; 8],
            "7:30",
            "found `nan`",
        );
        fails(
            &dirs("(1,0,0) [0,1,0] (0,0,1)"),
            &[0; 8],
            "7:27",
            "`(x,y,z)` or `none`",
        );
        fails(
            &dirs("(1,0,0) (2,0,0) (0,0,1)"),
            &[0; 8],
            "7:19",
            "singular",
        );
        fails(
            &dirs("(1,0,0) (0,1,0) (0,0,0)"),
            &[0; 8],
            "7:19",
            "singular",
        );
        fails(
            &format!("{U8}spacings: 1 nan 1\n\n"),
            &[0; 8],
            "6:13",
            "finite spacing",
        );
        fails(
            &format!("{U8}spacings: 1 0 1\n\n"),
            &[0; 8],
            "6:11",
            "singular",
        );
        let both = format!("{U8}spacings: 1 1 1\nspace directions: (1,0,0) (0,1,0) (0,0,1)\n\n");
        fails(&both, &[0; 8], "6:11", "not both");
        fails(
            &format!("{U8}space origin: (1,2,3) (4,5,6)\n\n"),
            &[0; 8],
            "6:15",
            "one vector",
        );
        fails(
            &format!("{U8}space origin: (1,2,3\n\n"),
            &[0; 8],
            "6:15",
            "`(x,y,z)`",
        );
    }

    #[test]
    fn data_errors_point_at_sizes_or_encoding() {
        let h = format!("{U8}\n");
        fails(&h, &[0; 7], "4:8", "need 8 data bytes, found only 7");
        fails(&h, &[0; 9], "4:8", "need 8 data bytes, found more");
        let gz = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\n\n";
        fails(gz, b"definitely not gzip", "5:11", "expected gzip data");
        let z = gzip(Vec::new(), &[1; 8]).unwrap();
        fails(gz, &z[..z.len() - 12], "5:11", "expected gzip data");
        let z7 = gzip(Vec::new(), &[1; 7]).unwrap();
        fails(gz, &z7, "4:8", "after decompression, found only 7");
        let z9 = gzip(Vec::new(), &[1; 9]).unwrap();
        fails(gz, &z9, "4:8", "found more");
        let mut bad_crc = z.clone();
        let n = bad_crc.len();
        bad_crc[n - 8] ^= 1;
        fails(gz, &bad_crc, "5:11", "expected gzip data");
        let skip = format!("{U8}line skip: 3\n\n");
        fails(&skip, b"a\nb\n", "6:12", "3 lines to skip");
        let skip = format!("{U8}byte skip: 30\n\n");
        fails(&skip, &[0; 20], "6:12", "bytes to skip");
        let h =
            "NRRD0004\ntype: float\nendian: little\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n";
        let e = error(&file(h, &f32::NAN.to_le_bytes()));
        assert!(e.starts_with("f.nrrd: data: sample 0 is NaN"), "{e}");
    }

    #[test]
    fn sizes_over_the_limit_are_refused_before_reading() {
        let h = "NRRD0004\ntype: uint16\nendian: little\ndimension: 3\nsizes: 2000 2000 1000\n\
                 encoding: raw\n\n";
        fails(h, &[], "5:8", "exceed the limit of 1073741824 samples");
        let huge =
            "NRRD0004\ntype: double\ndimension: 3\nsizes: 4294967296 4294967296 4294967296\n\n";
        fails(huge, &[], "4:8", "exceed the limit");
        let small = parse_nrrd_limited(
            &file(&format!("{U8}\n"), &[0; 8]),
            F,
            None,
            SampleLimit {
                samples: 7,
                source: "",
            },
        );
        assert!(small
            .unwrap_err()
            .to_string()
            .starts_with("f.nrrd:4:8: sizes 2×2×2 exceed the limit of 7"));
    }

    /// Small valid files to mutate: raw and gzip, with geometry.
    fn seeds() -> Vec<Vec<u8>> {
        let mut out = Vec::new();
        for ty in [SampleType::Uint8, SampleType::Int16, SampleType::Float] {
            for enc in [Encoding::Raw, Encoding::Gzip] {
                out.push(nrrd_bytes(&volume(ty), enc, Endian::Big, "seed").unwrap());
            }
        }
        out
    }

    fn check(bytes: &[u8]) {
        if let Err(e) =
            parse_nrrd(bytes, F, Some(Path::new("/nonexistent-dir"))).map_err(|e| e.to_string())
        {
            assert!(!e.contains('\n') && !e.is_empty(), "{e}");
        }
    }

    proptest! {
        #[test]
        fn parse_never_panics_on_mutated_bytes(
            seed in 0usize..6,
            flips in prop::collection::vec((any::<usize>(), any::<u8>()), 0..6),
            cut in any::<Option<usize>>(),
        ) {
            let mut bytes = seeds().swap_remove(seed);
            for (at, b) in flips {
                let n = bytes.len();
                bytes[at % n] = b;
            }
            if let Some(c) = cut {
                bytes.truncate(c % (bytes.len() + 1));
            }
            check(&bytes);
        }

        #[test]
        fn parse_never_panics_on_mutated_headers(
            seed in 0usize..6,
            line in 1usize..12,
            value in "[ -~]{0,24}",
            extra in prop::sample::select(vec![
                "", "byte skip: -1\n", "line skip: 99\n", "spacings: 1 1 1\n",
                "data file: x.raw\n", "space dimension: 3\n", "endian: big\n", "k:=v\n",
                "sizes: 1 1 1\n", "byte skip: 100\n",
            ]),
        ) {
            let bytes = seeds().swap_remove(seed);
            let split = bytes.windows(2).position(|w| w == b"\n\n").unwrap() + 1;
            let head = String::from_utf8(bytes[..split].to_vec()).unwrap();
            let mut lines: Vec<String> = head.lines().map(str::to_string).collect();
            let i = line % lines.len();
            if let Some(colon) = lines[i].find(": ") {
                lines[i] = format!("{}: {value}", &lines[i][..colon]);
            } else {
                lines[i] = value.clone();
            }
            let text = format!("{}\n{extra}\n", lines.join("\n"));
            check(&[text.as_bytes(), &bytes[split + 1..]].concat());
        }
    }
}

//! Speed against accuracy: a sweep of the knobs a user trades when voxelizing a scene through
//! the array: users trade speed for accuracy, so every knob that does so is measured.
//!
//! The knobs:
//!
//! * **fraction bits F** of the depth word (§2.3.1, §2.4.1). They set the rounding of the plane
//!   coefficients Z0, dZx, dZy and, through N_D = F + I + O + 1, the clocks per plane window:
//!   the hardware renders P = 1 / (N_D·T_C) surfaces per second (§2.5, eq. 2.3);
//! * **fragments** of curved primitives (OpenSCAD's `$fn`), re-tessellated by rewriting the
//!   scene text ([`with_fragments`]): more faces, more planes per P·Vz frame;
//! * **slabs** along Z (§4.4): one P·Vz frame per primitive per slab, so slices per second
//!   P_sp = P_R / N_s (§5.5, eq. 5.1);
//! * **model** `cycle`, `word` or `float` (one processor, three models, docs/rendering.md):
//!   the same voxels from `cycle` and `word`, at very different simulator cost.
//!
//! # What is measured, per point
//!
//! The grid is the same for every point of a given slab count: `res × res × slabs` voxels over
//! the union of the bounds of every tessellation swept, so that voxel (i, j, k) is the same box
//! of space at every point and volumes compare voxel for voxel.
//!
//! * `diff_ref`: voxels whose membership (filled or empty) differs from the **reference**, the
//!   `float` model of the finest tessellation swept with the most fraction bits swept, on the
//!   same grid. It counts tessellation and depth-word error together.
//! * `diff_float`: voxels differing from `float` at the same tessellation, bits and grid: the
//!   depth word's error alone (0 for `float`).
//! * `depth_err`: the largest |word depth − float depth| of a primitive's interval ends
//!   ([`depth_error`]), in scene units; `depth_bound` the proven bound on it.
//! * `cycles`: array clocks for every P·Vz frame (absent for `float`, which is not hardware),
//!   and `hardware_s` = cycles at 10 MHz.
//! * `wall_s`: the simulator's own time for the point's voxelization.

use crate::Error;
use std::time::Instant;

use glam::DVec3;
use rtl_model::{Equations, WordFormat};
use serde::{Deserialize, Serialize};

use crate::plot::{Chart, Series};
use csgpix_draw::compile::CompileError;
use csgpix_draw::float::rounding_bound;
use csgpix_openscad::{parse_csg_with, ReadOptions};
use csgpix_scene::solid::CsgScene;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::{
    float_interval, voxelize, Grid, Route, Sampling, Slicer, SlicerOptions, Volume,
};

/// The thesis's clock, 10 MHz (§2.5).
pub const CLOCK_HZ: f64 = 1e7;

pub use csgpix_draw::Model;

/// How a study runs a model's frames: `cycle` every P·Vz frame on the bit-serial array,
/// `word` the array's plane words reduced to depth intervals (proven equal to the word array
/// voxel for voxel), `float` exact intervals of the same planes.
fn route(model: Model) -> Route {
    match model {
        Model::Cycle => Route::Array { cycle: true },
        Model::Word => Route::Intervals,
        Model::Float => Route::Float,
    }
}

/// The ranges swept. Every list is sorted and without repeats ([`Sweep::normalized`]).
/// `Default` is the documented defaults (`csgpix study --help`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Sweep {
    /// Fraction bits F of the depth word.
    pub bits: Vec<u32>,
    /// `$fn` of every sphere and cylinder.
    pub fragments: Vec<u32>,
    /// Slabs along Z.
    pub slabs: Vec<usize>,
    /// Models run at every point.
    #[serde(with = "models_by_name")]
    pub models: Vec<Model>,
    /// Voxels along X and Y (array pixels per side).
    pub res: usize,
    /// Integer bits I of the depth word (fixed during the sweep).
    pub int_bits: u32,
    /// Overflow bits O of the depth word (fixed during the sweep).
    pub ovf_bits: u32,
    /// The sampling convention of every run (docs/voxelization.md).
    #[serde(with = "crate::named::by_name")]
    pub sampling: Sampling,
}

impl Default for Sweep {
    fn default() -> Self {
        Sweep {
            bits: vec![4, 6, 8, 10, 12, 16],
            fragments: vec![8, 16, 32, 64],
            slabs: vec![16, 32, 64, 128],
            models: vec![Model::Word, Model::Float],
            res: 32,
            int_bits: 10,
            ovf_bits: 11,
            sampling: Sampling::Centre,
        }
    }
}

/// serde of the models by name (`["word", "float"]`).
mod models_by_name {
    use super::Model;

    pub fn serialize<S: serde::Serializer>(v: &[Model], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(|m| m.name()))
    }

    pub fn deserialize<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Vec<Model>, D::Error> {
        use serde::Deserialize;
        let names = <Vec<std::borrow::Cow<'de, str>>>::deserialize(d)?;
        names
            .iter()
            .map(|n| crate::named::parse(n).map_err(serde::de::Error::custom))
            .collect()
    }
}

impl Sweep {
    /// The lists sorted and deduplicated, so the points come in one order.
    pub fn normalized(mut self) -> Sweep {
        self.bits.sort_unstable();
        self.bits.dedup();
        self.fragments.sort_unstable();
        self.fragments.dedup();
        self.slabs.sort_unstable();
        self.slabs.dedup();
        self.models.sort_unstable();
        self.models.dedup();
        self
    }

    /// Refuse empty lists and values no run could use.
    pub fn check(&self) -> crate::Result<()> {
        if self.bits.is_empty()
            || self.fragments.is_empty()
            || self.slabs.is_empty()
            || self.models.is_empty()
        {
            let message = "--bits, --fragments, --slabs and --models each need a value";
            return Err(Error::options("--bits", message));
        }
        if let Some(f) = self.fragments.iter().find(|&&f| f < 3) {
            let message = format!("--fragments {f}: a circle needs at least 3");
            return Err(Error::options("--fragments", message));
        }
        if self.slabs.contains(&0) || self.res == 0 {
            return Err(Error::options(
                "--slabs",
                "--slabs and --res must be at least 1",
            ));
        }
        for &b in &self.bits {
            self.word(b)?;
        }
        Ok(())
    }

    /// The depth word with `frac` fraction bits.
    pub fn word(&self, frac: u32) -> crate::Result<WordFormat> {
        WordFormat::new(frac, self.int_bits, self.ovf_bits).map_err(|e| {
            let message = format!(
                "--bits {frac} with {}/{}: {e}",
                self.int_bits, self.ovf_bits
            );
            Error::options("--bits", message)
        })
    }

    /// Points in the sweep.
    pub fn len(&self) -> usize {
        self.bits.len() * self.fragments.len() * self.slabs.len() * self.models.len()
    }

    /// Whether the sweep has no point.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One point of the sweep and what it measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The processor model run.
    pub model: Model,
    /// Fraction bits F.
    pub frac_bits: u32,
    /// Bits per depth word = clocks per plane window (§2.5).
    pub n_d: u32,
    /// `$fn` of every sphere and cylinder.
    pub fragments: u32,
    /// Voxels along X and Y.
    pub res: usize,
    /// Slabs along Z.
    pub slabs: usize,
    /// Voxels in the grid.
    pub voxels: usize,
    /// Voxels filled.
    pub filled: usize,
    /// FNV-1a digest of the volume's membership (filled or empty per voxel), in hex: equal
    /// digests mark the same voxels (`cycle` and `word` always give the same).
    pub digest: String,
    /// Voxels differing from the reference (float, finest tessellation and bits, same grid).
    pub diff_ref: usize,
    /// Voxels differing from float at the same tessellation, bits and grid.
    pub diff_float: usize,
    /// Largest |word − float| interval end, scene units ([`depth_error`]); 0 for float.
    pub depth_err: f64,
    /// The proven bound on `depth_err`, scene units.
    pub depth_bound: f64,
    /// Array clocks (None for float, which is not hardware).
    pub cycles: Option<u64>,
    /// `cycles` at 10 MHz.
    pub hardware_s: Option<f64>,
    /// The simulator's time for this point's voxelization.
    pub wall_s: f64,
}

/// Rewrite the `$fn` argument of every `sphere(...)` and `cylinder(...)` call in `.csg` text
/// to `n`, adding it where absent. Comments and strings are copied untouched. `$fn > 0`
/// overrides `$fa` and `$fs` (OpenSCAD's `get_fragments_from_r`), so the rewritten scene has
/// exactly `n` fragments per circle. Line numbers do not change.
pub fn with_fragments(text: &str, n: u32) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len() + 64);
    let mut i = 0;
    while i < b.len() {
        let skip = trivia_len(b, i);
        if skip > 0 {
            out.push_str(&text[i..i + skip]);
            i += skip;
        } else if b[i].is_ascii_alphabetic() || b[i] == b'_' || b[i] == b'$' {
            let end = i + ident_len(&b[i..]);
            out.push_str(&text[i..end]);
            let name = &text[i..end];
            i = end;
            if name == "sphere" || name == "cylinder" {
                i = rewrite_call(text, i, n, &mut out);
            }
        } else {
            let c = text[i..].chars().next().map_or(1, char::len_utf8);
            out.push_str(&text[i..i + c]);
            i += c;
        }
    }
    out
}

/// Length of a comment or string starting at `i` (0 if none starts there).
fn trivia_len(b: &[u8], i: usize) -> usize {
    let rest = &b[i..];
    if rest.starts_with(b"//") {
        rest.iter().position(|&c| c == b'\n').unwrap_or(rest.len())
    } else if rest.starts_with(b"/*") {
        rest.windows(2)
            .skip(2)
            .position(|w| w == b"*/")
            .map_or(rest.len(), |p| p + 4)
    } else if rest.first() == Some(&b'"') {
        let mut j = 1;
        while j < rest.len() && rest[j] != b'"' {
            j += if rest[j] == b'\\' { 2 } else { 1 };
        }
        (j + 1).min(rest.len())
    } else {
        0
    }
}

fn ident_len(b: &[u8]) -> usize {
    b.iter()
        .position(|&c| !(c.is_ascii_alphanumeric() || c == b'_' || c == b'$'))
        .unwrap_or(b.len())
}

/// After a `sphere`/`cylinder` name at `i`: copy white space, then the argument list with its
/// `$fn` replaced or added. Returns where copying stopped (the caller goes on from there).
fn rewrite_call(text: &str, mut i: usize, n: u32, out: &mut String) -> usize {
    let b = text.as_bytes();
    while i < b.len() && b[i].is_ascii_whitespace() {
        out.push(b[i] as char);
        i += 1;
    }
    if b.get(i) != Some(&b'(') {
        return i;
    }
    let Some(close) = matching_paren(b, i) else {
        return i;
    };
    let args = split_args(b, i + 1, close);
    let fn_arg = args.iter().find(|&&(s, e)| is_fn_arg(&text[s..e]));
    out.push('(');
    match fn_arg {
        Some(&(s, e)) => {
            out.push_str(&text[i + 1..s]);
            out.push_str(&format!("$fn = {n}"));
            out.push_str(&text[e..close]);
        }
        None if text[i + 1..close].trim().is_empty() => out.push_str(&format!("$fn = {n}")),
        None => {
            out.push_str(&format!("$fn = {n}, "));
            out.push_str(&text[i + 1..close]);
        }
    }
    out.push(')');
    close + 1
}

/// The index of the `)` closing the `(` at `open`, skipping comments, strings and nested
/// brackets.
fn matching_paren(b: &[u8], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut i = open;
    while i < b.len() {
        let skip = trivia_len(b, i);
        if skip > 0 {
            i += skip;
            continue;
        }
        match b[i] {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => {
                depth -= 1;
                if depth == 0 {
                    return (b[i] == b')').then_some(i);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The top-level arguments between `start` and `end` as byte ranges, trimmed of white space.
fn split_args(b: &[u8], start: usize, end: usize) -> Vec<(usize, usize)> {
    let (mut out, mut depth, mut from, mut i) = (vec![], 0usize, start, start);
    while i < end {
        let skip = trivia_len(b, i);
        if skip > 0 {
            i += skip;
            continue;
        }
        match b[i] {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            b',' if depth == 0 => {
                out.push(trim(b, from, i));
                from = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    out.push(trim(b, from, end));
    out
}

fn trim(b: &[u8], mut s: usize, mut e: usize) -> (usize, usize) {
    while s < e && b[s].is_ascii_whitespace() {
        s += 1;
    }
    while e > s && b[e - 1].is_ascii_whitespace() {
        e -= 1;
    }
    (s, e)
}

/// `$fn = value` (any spacing).
fn is_fn_arg(arg: &str) -> bool {
    arg.strip_prefix("$fn")
        .is_some_and(|rest| rest.trim_start().starts_with('='))
}

/// A scene read once per tessellation swept, and the grid box common to all of them.
pub struct Prepared {
    /// The sweep, normalized.
    pub sweep: Sweep,
    /// `(fragments, scene)`, in the sweep's order of fragments.
    pub scenes: Vec<(u32, CsgScene)>,
    /// The grid box's low corner, common to every tessellation.
    pub min: DVec3,
    /// The grid box's high corner.
    pub max: DVec3,
}

/// A study's scene as the array draws it: every extrusion as prisms and meshes.
fn parse_csg(text: &str, file: &str) -> csgpix_scene::Result<csgpix_scene::solid::CsgScene> {
    parse_csg_with(text, file, &ReadOptions::default().for_the_array())
}

/// Read every tessellation of the scene and lay every grid and word on it, so that any bad
/// input is refused before a point runs. `file` names the scene in messages.
pub fn prepare(text: &str, file: &str, sweep: Sweep) -> crate::Result<Prepared> {
    let sweep = sweep.normalized();
    sweep.check()?;
    parse_csg(text, file)?.require_convex(file, "`study`")?;
    let mut scenes = vec![];
    for &f in &sweep.fragments {
        let scene =
            parse_csg(&with_fragments(text, f), file).map_err(|source| Error::Tessellation {
                fragments: f,
                source,
            })?;
        scenes.push((f, scene));
    }
    let (mut min, mut max) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for (_, s) in &scenes {
        let g = Grid::of_scene(s, [1, 1, 1]).map_err(|e| bounds_hint(e).context(file))?;
        (min, max) = (min.min(g.min), max.max(g.max));
    }
    let p = Prepared {
        sweep,
        scenes,
        min,
        max,
    };
    for &slabs in &p.sweep.slabs {
        for &bits in &p.sweep.bits {
            for (_, s) in &p.scenes {
                p.slicer(s, bits, slabs).map_err(|e| e.context(file))?;
            }
        }
    }
    Ok(p)
}

/// A grid error as the command line words it: a scene without solids needs `--bounds`.
fn bounds_hint(e: csgpix_scene::Error) -> Error {
    match e.kind() {
        csgpix_scene::Kind::NeedsBounds => {
            Error::options("--bounds", "the scene has no solids: give --bounds")
        }
        _ => e.into(),
    }
}

impl Prepared {
    /// The grid of `slabs` slabs: the same box for every tessellation and word.
    pub fn grid(&self, slabs: usize) -> crate::Result<Grid> {
        Ok(Grid::new(
            [self.sweep.res, self.sweep.res, slabs],
            self.min,
            self.max,
        )?)
    }

    fn slicer(&self, scene: &CsgScene, bits: u32, slabs: usize) -> crate::Result<Slicer> {
        let (grid, word) = (self.grid(slabs)?, self.sweep.word(bits)?);
        let opts = SlicerOptions {
            fmt: word,
            sampling: self.sweep.sampling,
            ..SlicerOptions::default()
        };
        Ok(Slicer::new(scene, grid, opts)?)
    }

    /// Every point, slabs outermost, then fragments, bits and models (each ascending).
    /// `tick` is called after every point.
    pub fn run(&self, tick: &dyn Fn()) -> crate::Result<Vec<Point>> {
        let mut points = Vec::with_capacity(self.sweep.len());
        for &slabs in &self.sweep.slabs {
            let reference = self.reference(slabs)?;
            for (f, scene) in &self.scenes {
                for &bits in &self.sweep.bits {
                    let slicer = self.slicer(scene, bits, slabs)?;
                    points.extend(self.run_at(&slicer, scene, *f, &reference, tick)?);
                }
            }
        }
        Ok(points)
    }

    /// The reference of a grid: `float`, finest tessellation, most fraction bits.
    fn reference(&self, slabs: usize) -> crate::Result<Volume> {
        let none = |flag| Error::options(flag, format!("{flag}: nothing to sweep"));
        let (_, scene) = self.scenes.last().ok_or_else(|| none("--fragments"))?;
        let bits = *self.sweep.bits.last().ok_or_else(|| none("--bits"))?;
        let slicer = self.slicer(scene, bits, slabs)?;
        Ok(run_model(&slicer, scene, Model::Float)?.0)
    }

    /// The points of every model at one tessellation, word and grid.
    fn run_at(
        &self,
        slicer: &Slicer,
        scene: &CsgScene,
        fragments: u32,
        reference: &Volume,
        tick: &dyn Fn(),
    ) -> crate::Result<Vec<Point>> {
        let (float, _, _) = run_model(slicer, scene, Model::Float)?;
        let err = depth_error(slicer)?;
        let scale = depth_to_scene(slicer);
        let (w, h) = (slicer.grid.dims[0], slicer.grid.dims[1]);
        let bound = rounding_bound(&slicer.fmt, w - 1, h - 1) * scale;
        let mut out = vec![];
        for &model in &self.sweep.models {
            let (vol, cycles, wall) = run_model(slicer, scene, model)?;
            let hw = model != Model::Float;
            out.push(Point {
                model,
                frac_bits: slicer.fmt.frac,
                n_d: slicer.fmt.bits(),
                fragments,
                res: w,
                slabs: slicer.grid.dims[2],
                voxels: vol.voxels.len(),
                filled: vol.voxels.iter().filter(|&&v| v != 0).count(),
                digest: digest(&vol),
                diff_ref: differing(&vol, reference),
                diff_float: differing(&vol, &float),
                depth_err: if hw { err * scale } else { 0.0 },
                depth_bound: if hw { bound } else { 0.0 },
                cycles: hw.then_some(cycles),
                hardware_s: hw.then_some(cycles as f64 / CLOCK_HZ),
                wall_s: wall,
            });
            tick();
        }
        Ok(out)
    }
}

/// One voxelization: the volume, the array clocks and the wall time. The Blist evaluator
/// (§4.5) and the derived select equations, as `csgpix voxelize` by default.
fn run_model(slicer: &Slicer, scene: &CsgScene, model: Model) -> crate::Result<(Volume, u64, f64)> {
    let eval = BlistEval::new(&scene.root);
    let t0 = Instant::now();
    let (vol, work) = voxelize(
        slicer,
        route(model),
        Equations::Derived.set(),
        &eval,
        &|| {},
    )?;
    Ok((vol, work.cycles, t0.elapsed().as_secs_f64()))
}

/// Voxels filled in one volume and empty in the other (colour codes are not compared).
pub fn differing(a: &Volume, b: &Volume) -> usize {
    a.voxels
        .iter()
        .zip(&b.voxels)
        .filter(|(x, y)| (**x != 0) != (**y != 0))
        .count()
}

/// FNV-1a (64 bits) over the volume's membership bytes (1 filled, 0 empty), as 16 hex digits.
pub fn digest(v: &Volume) -> String {
    let h = v.voxels.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &x| {
        (h ^ u64::from(x != 0)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{h:016x}")
}

/// Scene units of Z per depth unit: a slab is q depth units and one voxel deep.
pub fn depth_to_scene(slicer: &Slicer) -> f64 {
    slicer.grid.voxel().z / slicer.fmt.to_real(slicer.slab_raw)
}

/// The largest depth error of the word, in depth units: over every primitive and every pixel
/// where both the word and the exact planes see the primitive, the larger of |lo_w − lo_f| and
/// |hi_w − hi_f|, where [lo, hi] is the primitive's depth interval along the pixel's ray
/// (behind every front plane, before every back plane) as the array's plane words give it
/// (DEPGEN's Z0 + x·dZx + y·dZy, §2.3.1) and as exact f64 planes give it, both ends clamped
/// to the grid's depth range [Z-plane(0), Z-plane(slabs)]. These ends are what decide the
/// slab masks (§4.4). Each plane word is within 2^-(F+1)·(1 + x + y) of the exact plane
/// (docs/depth-word.md) and max, min and clamping do not enlarge a difference, so the result
/// is at most that bound at the far corner.
pub fn depth_error(slicer: &Slicer) -> crate::Result<f64> {
    let fmt = &slicer.fmt;
    let (lo_z, hi_z) = (
        fmt.to_real(slicer.z_plane(0)),
        fmt.to_real(slicer.z_plane(slicer.grid.dims[2])),
    );
    let clamp = |v: f64| v.clamp(lo_z, hi_z);
    let (w, h) = (slicer.grid.dims[0], slicer.grid.dims[1]);
    let mut worst = 0.0f64;
    for prim in 0..slicer.lists.len() {
        let planes = plane_words(slicer, prim)?;
        for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
            let word = word_interval(fmt, &planes, x as i64, y as i64);
            if let (Some((lw, hw)), Some((lf, hf))) = (word, float_interval(slicer, prim, x, y)) {
                let e = (clamp(lw) - clamp(lf))
                    .abs()
                    .max((clamp(hw) - clamp(hf)).abs());
                worst = worst.max(e);
            }
        }
    }
    Ok(worst)
}

/// A plane as the array holds it: quantized coefficients, perpendicular (Y) and front (H).
struct PlaneWord {
    c: rtl_model::Coeffs,
    y: bool,
    h: bool,
}

fn plane_words(slicer: &Slicer, prim: usize) -> crate::Result<Vec<PlaneWord>> {
    slicer.lists[prim]
        .planes
        .iter()
        .enumerate()
        .map(|(plane, p)| {
            csgpix_draw::compile::coeffs(&slicer.fmt, p.z0, p.dzx, p.dzy)
                .map(|c| PlaneWord { c, y: p.y, h: p.h })
                .map_err(|(field, msg)| Error::Compile {
                    solid: Some(prim),
                    error: CompileError { plane, field, msg },
                })
        })
        .collect()
}

/// The word interval [lo, hi] in depth units (None where a perpendicular plane is negative or
/// the interval is empty), ends infinite where no plane bounds them.
fn word_interval(fmt: &WordFormat, planes: &[PlaneWord], x: i64, y: i64) -> Option<(f64, f64)> {
    let values = planes.iter().map(|p| {
        (
            fmt.to_real(fmt.wrap(p.c.c0 + x * p.c.dx + y * p.c.dy)),
            p.y,
            p.h,
        )
    });
    csgpix_voxel::ray_interval(values, f64::NEG_INFINITY, f64::INFINITY)
}

/// The CSV header; `wall_s` is last so runs compare without it.
pub const CSV_HEADER: &str = "model,frac_bits,n_d,fragments,res,slabs,voxels,filled,digest,\
diff_ref,diff_float,depth_err,depth_bound,cycles,hardware_s,wall_s";

/// One row per point, in the order given, with a header line. Empty fields for `float`'s
/// cycles and hardware time.
pub fn csv(points: &[Point]) -> String {
    let opt = |v: Option<String>| v.unwrap_or_default();
    let mut s = format!("{CSV_HEADER}\n");
    for p in points {
        s.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{:e},{:e},{},{},{}\n",
            p.model.name(),
            p.frac_bits,
            p.n_d,
            p.fragments,
            p.res,
            p.slabs,
            p.voxels,
            p.filled,
            p.digest,
            p.diff_ref,
            p.diff_float,
            p.depth_err,
            p.depth_bound,
            opt(p.cycles.map(|c| c.to_string())),
            opt(p.hardware_s.map(|t| format!("{t:e}"))),
            p.wall_s,
        ));
    }
    s
}

/// The charts of a sweep, `(file name, chart)`: error against cost for each knob, and the
/// simulator's cost per model. `scene` names the scene in titles.
pub fn charts(points: &[Point], scene: &str) -> Vec<(&'static str, Chart)> {
    let finest_f = points.iter().map(|p| p.fragments).max().unwrap_or(0);
    let most_bits = points.iter().map(|p| p.frac_bits).max().unwrap_or(0);
    let word = |p: &&Point| p.model == Model::Word;
    vec![
        (
            "bits.png",
            error_chart(
                scene,
                "fraction bits F",
                points
                    .iter()
                    .filter(word)
                    .filter(|p| p.fragments == finest_f),
            ),
        ),
        (
            "fragments.png",
            error_chart(
                scene,
                "fragments ($fn)",
                points
                    .iter()
                    .filter(word)
                    .filter(|p| p.frac_bits == most_bits),
            ),
        ),
        ("depth.png", depth_chart(points, scene, finest_f)),
        ("wall.png", wall_chart(points, scene)),
    ]
}

fn slab_counts<'a>(points: impl Iterator<Item = &'a Point>) -> Vec<usize> {
    let mut s: Vec<usize> = points.map(|p| p.slabs).collect();
    s.sort_unstable();
    s.dedup();
    s
}

/// Voxels differing from the reference (percent of the grid) against hardware time, one
/// curve per slab count, one point per value of the knob.
fn error_chart<'a>(scene: &str, knob: &str, pts: impl Iterator<Item = &'a Point>) -> Chart {
    let pts: Vec<&Point> = pts.collect();
    let series = slab_counts(pts.iter().copied())
        .into_iter()
        .map(|s| {
            let mut xy: Vec<(f64, f64)> = pts
                .iter()
                .filter(|p| p.slabs == s)
                .filter_map(|p| {
                    let pct = 100.0 * p.diff_ref as f64 / p.voxels as f64;
                    p.hardware_s.map(|t| (t * 1e3, pct))
                })
                .collect();
            xy.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series {
                label: format!("{s} slabs"),
                points: xy,
            }
        })
        .collect::<Vec<Series>>();
    let (lo, hi) = series
        .iter()
        .flat_map(|s: &Series| s.points.iter().map(|p| p.0))
        .fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    Chart {
        title: format!("{scene}: {knob}, word model"),
        x_label: "hardware time at 10 MHz (ms)".into(),
        y_label: "voxels differing from reference (%)".into(),
        log_x: hi > 20.0 * lo,
        log_y: false,
        series,
    }
}

/// Largest depth error (scene units) against N_D, the largest over slab counts (they differ
/// by a fraction of a percent: a slab is q depth units and one voxel deep), with the bound.
fn depth_chart(points: &[Point], scene: &str, fragments: u32) -> Chart {
    let pts: Vec<&Point> = points
        .iter()
        .filter(|p| p.model != Model::Float && p.fragments == fragments)
        .collect();
    let curve = |label: &str, f: fn(&Point) -> f64| {
        let mut nd: Vec<u32> = pts.iter().map(|p| p.n_d).collect();
        nd.sort_unstable();
        nd.dedup();
        let points = nd
            .into_iter()
            .map(|n| {
                let y = pts.iter().filter(|p| p.n_d == n).map(|p| f(p));
                (n as f64, y.fold(0.0, f64::max))
            })
            .filter(|&(_, y)| y > 0.0)
            .collect();
        Series {
            label: label.into(),
            points,
        }
    };
    Chart {
        title: format!("{scene}: depth error of the word, {fragments} fragments"),
        x_label: "N_D = clocks per plane".into(),
        y_label: "largest |word - float| depth (scene units)".into(),
        log_x: false,
        log_y: true,
        series: vec![
            curve("measured", |p| p.depth_err),
            curve("bound 2^-(F+1)(1+x+y)", |p| p.depth_bound),
        ],
    }
}

/// The simulator's wall time against the hardware time of the same job, per model; each
/// point sums the bit counts of one (fragments, slabs) pair, which smooths the timer's noise.
fn wall_chart(points: &[Point], scene: &str) -> Chart {
    let job = |p: &Point| {
        points
            .iter()
            .find(|q| q.hardware_s.is_some() && same_job(p, q))
            .and_then(|q| q.hardware_s)
    };
    let mut models: Vec<Model> = points.iter().map(|p| p.model).collect();
    models.sort_unstable();
    models.dedup();
    let series = models
        .into_iter()
        .map(|m| {
            let mut groups: Vec<((u32, usize), f64, f64)> = vec![];
            for p in points.iter().filter(|p| p.model == m) {
                let Some(t) = job(p) else { continue };
                match groups.iter_mut().find(|g| g.0 == (p.fragments, p.slabs)) {
                    Some(g) => (g.1, g.2) = (g.1 + t, g.2 + p.wall_s),
                    None => groups.push(((p.fragments, p.slabs), t, p.wall_s)),
                }
            }
            let mut xy: Vec<(f64, f64)> = groups
                .into_iter()
                .map(|(_, t, w)| (t * 1e3, w.max(1e-6) * 1e3))
                .collect();
            xy.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series {
                label: m.name().into(),
                points: xy,
            }
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    Chart {
        title: format!("{scene}: simulator cost per model (sums over bits)"),
        x_label: "hardware time of the jobs at 10 MHz (ms)".into(),
        y_label: "simulator wall time (ms)".into(),
        log_x: true,
        log_y: true,
        series,
    }
}

fn same_job(p: &Point, q: &Point) -> bool {
    (q.frac_bits, q.fragments, q.slabs) == (p.frac_bits, p.fragments, p.slabs)
}
